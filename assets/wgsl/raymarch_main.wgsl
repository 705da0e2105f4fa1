struct type_5 {
    member: vec2<f32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_7 {
    member: array<f32>,
}

struct type_10 {
    member: array<u32>,
}

struct type_20 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
}

struct type_21 {
    member: type_20,
}

struct type_24 {
    member: array<vec2<f32>>,
}

struct type_26 {
    member: vec2<u32>,
    member_1: vec3<f32>,
    member_2: vec3<f32>,
    member_3: f32,
    member_4: f32,
    member_5: f32,
}

struct type_27 {
    member: u32,
    member_1: type_26,
}

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_29 {
    member: f32,
    member_1: u32,
    member_2: u32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;
@group(0) @binding(6) 
var<uniform> params: type_21;
@group(0) @binding(2) 
var<storage> kernel: type_24;
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_735_: vec3<f32>;
    var phi_940_: type_28;
    var phi_975_: u32;
    var phi_978_: f32;
    var phi_1130_: u32;
    var phi_1133_: f32;
    var phi_1135_: bool;
    var phi_1137_: bool;
    var phi_1139_: f32;
    var phi_1141_: f32;
    var phi_1590_: u32;
    var phi_1592_: u32;
    var phi_1593_: f32;
    var phi_1594_: bool;
    var phi_1595_: bool;
    var phi_1596_: f32;
    var phi_1599_: bool;
    var phi_1600_: bool;
    var phi_1131_: u32;
    var phi_1134_: f32;
    var phi_1136_: bool;
    var phi_1138_: bool;
    var phi_1140_: f32;
    var phi_1142_: f32;
    var phi_1604_: bool;
    var phi_1606_: bool;
    var phi_1607_: bool;
    var local: bool;
    var local_1: bool;
    var local_2: bool;
    var local_3: bool;
    var local_4: f32;
    var local_5: f32;
    var local_6: bool;
    var local_7: bool;
    var local_8: f32;
    var local_9: bool;
    var phi_1647_: f32;
    var phi_976_: u32;
    var phi_979_: f32;
    var phi_1867_: bool;
    var local_10: f32;
    var phi_1712_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e62 = id_1;
            let _e64 = arrayLength((&kernel.member));
            let _e75 = params.member.member.member[0u];
            let _e80 = select(select(u32(_e75), 0u, (_e75 < 0f)), 4294967295u, (_e75 > 4294967000f));
            let _e85 = params.member.member.member[1u];
            let _e90 = select(select(u32(_e85), 0u, (_e85 < 0f)), 4294967295u, (_e85 > 4294967000f));
            if (_e62.x >= _e80) {
            } else {
                if (_e62.y >= _e90) {
                } else {
                    let _e96 = ((_e62.y * _e80) + _e62.x);
                    let _e99 = depth.member[_e96];
                    let _e103 = params.member.member.member_3;
                    let _e106 = select(false, (_e99 < _e103), (_e99 > 0f));
                    let _e107 = select(_e103, _e99, _e106);
                    let _e108 = bitcast<i32>(_e62.x);
                    let _e109 = (_e108 + -1i);
                    let _e111 = select(0i, _e109, (0i < _e109));
                    let _e113 = (bitcast<i32>(_e80) - 1i);
                    let _e117 = bitcast<i32>(_e62.y);
                    let _e119 = select(0i, _e117, (0i < _e117));
                    let _e121 = (bitcast<i32>(_e90) - 1i);
                    let _e125 = (bitcast<u32>(select(_e119, _e121, (_e121 < _e119))) * _e80);
                    let _e129 = depth.member[(_e125 + bitcast<u32>(select(_e111, _e113, (_e113 < _e111))))];
                    let _e134 = (_e108 + 1i);
                    let _e136 = select(0i, _e134, (0i < _e134));
                    let _e143 = depth.member[(_e125 + bitcast<u32>(select(_e136, _e113, (_e113 < _e136))))];
                    let _e149 = select(0i, _e108, (0i < _e108));
                    let _e152 = bitcast<u32>(select(_e149, _e113, (_e113 < _e149)));
                    let _e153 = (_e117 + -1i);
                    let _e155 = select(0i, _e153, (0i < _e153));
                    let _e163 = depth.member[((bitcast<u32>(select(_e155, _e121, (_e121 < _e155))) * _e80) + _e152)];
                    let _e168 = (_e117 + 1i);
                    let _e170 = select(0i, _e168, (0i < _e168));
                    let _e178 = depth.member[((bitcast<u32>(select(_e170, _e121, (_e121 < _e170))) * _e80) + _e152)];
                    let _e183 = (select(_e103, _e129, select(false, (_e129 < _e103), (_e129 > 0f))) - _e107);
                    let _e184 = (select(_e103, _e143, select(false, (_e143 < _e103), (_e143 > 0f))) - _e107);
                    let _e185 = (select(_e103, _e163, select(false, (_e163 < _e103), (_e163 > 0f))) - _e107);
                    let _e186 = (select(_e103, _e178, select(false, (_e178 < _e103), (_e178 > 0f))) - _e107);
                    let _e188 = ((_e184 - _e183) * 0.5f);
                    let _e190 = ((_e186 - _e185) * 0.5f);
                    let _e191 = (_e107 * 0.011f);
                    let _e193 = abs(_e183);
                    let _e194 = abs((_e183 + _e188));
                    let _e200 = (1.25f - (select(_e194, _e193, ((_e193 < _e194) || (_e194 != _e194))) / _e191));
                    let _e204 = select(0f, select(1f, _e200, (_e200 < 1f)), (_e200 > 0f));
                    let _e206 = abs(_e184);
                    let _e207 = abs((_e184 - _e188));
                    let _e213 = (1.25f - (select(_e207, _e206, ((_e206 < _e207) || (_e207 != _e207))) / _e191));
                    let _e217 = select(0f, select(1f, _e213, (_e213 < 1f)), (_e213 > 0f));
                    let _e219 = abs(_e185);
                    let _e220 = abs((_e185 + _e190));
                    let _e226 = (1.25f - (select(_e220, _e219, ((_e219 < _e220) || (_e220 != _e220))) / _e191));
                    let _e230 = select(0f, select(1f, _e226, (_e226 < 1f)), (_e226 > 0f));
                    let _e232 = abs(_e186);
                    let _e233 = abs((_e186 - _e190));
                    let _e239 = (1.25f - (select(_e233, _e232, ((_e232 < _e233) || (_e233 != _e233))) / _e191));
                    let _e243 = select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f));
                    let _e249 = round((select(0f, select(1f, _e204, (_e204 < 1f)), (_e204 > 0f)) * 2.9f));
                    let _e264 = round((select(0f, select(1f, _e217, (_e217 < 1f)), (_e217 > 0f)) * 2.9f));
                    let _e280 = round((select(0f, select(1f, _e230, (_e230 < 1f)), (_e230 > 0f)) * 2.9f));
                    let _e296 = round((select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f)) * 2.9f));
                    let _e305 = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e249, (_e249 < 3f)), (_e249 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e264, (_e264 < 3f)), (_e264 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e280, (_e280 < 3f)), (_e280 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e296, (_e296 < 3f)), (_e296 > 0f))) + 8388608f)) - 1258291200u));
                    if _e106 {
                        let _e318 = params.member.member.member_1[0u];
                        let _e320 = ((((((f32(_e108) + 0.5f) / _e75) * 2f) - 1f) * _e318) * _e99);
                        let _e327 = params.member.member.member_1[1u];
                        let _e329 = ((((((f32(_e117) + 0.5f) / _e85) * -2f) + 1f) * _e327) * _e99);
                        let _e333 = normals.member[_e96];
                        let _e336 = f32(bitcast<i32>((_e333 & 255u)));
                        let _e340 = (select(_e336, (_e336 - 256f), (_e336 >= 128f)) * 0.007874016f);
                        let _e343 = select(-1f, _e340, ((_e340 > -1f) || false));
                        let _e348 = f32(bitcast<i32>(((_e333 >> bitcast<u32>(8u)) & 255u)));
                        let _e352 = (select(_e348, (_e348 - 256f), (_e348 >= 128f)) * 0.007874016f);
                        let _e355 = select(-1f, _e352, ((_e352 > -1f) || false));
                        let _e357 = (1f - abs(_e343));
                        let _e358 = abs(_e355);
                        let _e359 = (_e357 - _e358);
                        let _e360 = (_e359 < 0f);
                        let _e368 = select(_e343, ((1f - _e358) * select(1f, -1f, (_e343 < 0f))), _e360);
                        let _e369 = select(_e355, (_e357 * select(1f, -1f, (_e355 < 0f))), _e360);
                        let _e376 = (1f / sqrt((((_e368 * _e368) + (_e369 * _e369)) + (_e359 * _e359))));
                        let _e377 = (_e368 * _e376);
                        let _e378 = (_e369 * _e376);
                        let _e379 = (_e359 * _e376);
                        let _e380 = -(_e379);
                        if ((((_e377 * -(_e320)) + (_e378 * -(_e329))) + (_e380 * -(_e99))) < 0f) {
                            phi_735_ = vec3<f32>(-(_e377), -(_e378), _e379);
                        } else {
                            phi_735_ = vec3<f32>(_e377, _e378, _e380);
                        }
                        let _e395 = phi_735_;
                        let _e398 = params.member.member_8;
                        let _e399 = (_e62.x & 63u);
                        let _e400 = (_e62.y & 63u);
                        let _e403 = select(0u, 1u, ((_e399 & 32u) != 0u));
                        let _e406 = select(0u, 1u, ((_e400 & 32u) != 0u));
                        let _e410 = (_e406 == 0u);
                        let _e412 = (_e410 && (_e403 == 1u));
                        let _e415 = select(_e399, (63u - _e399), _e412);
                        let _e416 = select(_e400, (63u - _e400), _e412);
                        let _e417 = select(_e415, _e416, _e410);
                        let _e418 = select(_e416, _e415, _e410);
                        let _e421 = select(0u, 1u, ((_e417 & 16u) != 0u));
                        let _e424 = select(0u, 1u, ((_e418 & 16u) != 0u));
                        let _e429 = (_e424 == 0u);
                        let _e431 = (_e429 && (_e421 == 1u));
                        let _e434 = select(_e417, (63u - _e417), _e431);
                        let _e435 = select(_e418, (63u - _e418), _e431);
                        let _e436 = select(_e434, _e435, _e429);
                        let _e437 = select(_e435, _e434, _e429);
                        let _e440 = select(0u, 1u, ((_e436 & 8u) != 0u));
                        let _e443 = select(0u, 1u, ((_e437 & 8u) != 0u));
                        let _e448 = (_e443 == 0u);
                        let _e450 = (_e448 && (_e440 == 1u));
                        let _e453 = select(_e436, (63u - _e436), _e450);
                        let _e454 = select(_e437, (63u - _e437), _e450);
                        let _e455 = select(_e453, _e454, _e448);
                        let _e456 = select(_e454, _e453, _e448);
                        let _e459 = select(0u, 1u, ((_e455 & 4u) != 0u));
                        let _e462 = select(0u, 1u, ((_e456 & 4u) != 0u));
                        let _e467 = (_e462 == 0u);
                        let _e469 = (_e467 && (_e459 == 1u));
                        let _e472 = select(_e455, (63u - _e455), _e469);
                        let _e473 = select(_e456, (63u - _e456), _e469);
                        let _e474 = select(_e472, _e473, _e467);
                        let _e475 = select(_e473, _e472, _e467);
                        let _e478 = select(0u, 1u, ((_e474 & 2u) != 0u));
                        let _e481 = select(0u, 1u, ((_e475 & 2u) != 0u));
                        let _e486 = (_e481 == 0u);
                        let _e488 = (_e486 && (_e478 == 1u));
                        let _e491 = select(_e474, (63u - _e474), _e488);
                        let _e492 = select(_e475, (63u - _e475), _e488);
                        let _e508 = f32(bitcast<i32>((((((((1024u * ((3u * _e403) ^ _e406)) + (256u * ((3u * _e421) ^ _e424))) + (64u * ((3u * _e440) ^ _e443))) + (16u * ((3u * _e459) ^ _e462))) + (4u * ((3u * _e478) ^ _e481))) + ((3u * select(0u, 1u, ((select(_e491, _e492, _e486) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e492, _e491, _e486) & 1u) != 0u)))) + (288u * (_e398 % 64u)))));
                        let _e510 = (0.5f + (_e508 * 0.7548777f));
                        let _e514 = (0.5f + (_e508 * 0.5698403f));
                        let _e517 = (6.2831855f * (_e510 - floor(_e510)));
                        phi_940_ = type_28(_e305, type_27(1u, type_26(vec2<u32>(_e62.x, _e62.y), vec3<f32>(_e320, _e329, _e99), _e395, sin(_e517), cos(_e517), (_e514 - floor(_e514)))));
                    } else {
                        phi_940_ = type_28(_e305, type_27(0u, type_27().member_1));
                    }
                    let _e529 = phi_940_;
                    if (bitcast<i32>(_e529.member_1.member) != 0i) {
                        let _e538 = params.member.member_5;
                        let _e540 = select(_e538, 64u, (64u < _e538));
                        let _e542 = select(_e540, _e64, (_e64 < _e540));
                        let _e544 = select(1u, _e542, (1u < _e542));
                        let _e547 = params.member.member_6;
                        let _e549 = select(1u, _e547, (1u < _e547));
                        phi_975_ = 0u;
                        phi_978_ = 0f;
                        loop {
                            let _e551 = phi_975_;
                            let _e553 = phi_978_;
                            local_10 = _e553;
                            let _e554 = (_e551 < _e544);
                            if _e554 {
                                if (_e551 < _e64) {
                                } else {
                                    phi_1867_ = true;
                                    break;
                                }
                                let _e559 = kernel.member[_e551][0u];
                                let _e563 = kernel.member[_e551][1u];
                                let _e568 = ((_e529.member_1.member_1.member_4 * _e559) - (_e529.member_1.member_1.member_3 * _e563));
                                let _e571 = ((_e529.member_1.member_1.member_3 * _e559) + (_e529.member_1.member_1.member_4 * _e563));
                                let _e576 = ((1f - (_e568 * _e568)) - (_e571 * _e571));
                                let _e580 = sqrt(select(0f, _e576, ((_e576 > 0f) || false)));
                                let _e581 = -(_e580);
                                let _e585 = (-1f * _e529.member_1.member_1.member_2.z);
                                let _e586 = (-1f * _e529.member_1.member_1.member_2.x);
                                let _e588 = (1f / (_e585 + 1f));
                                let _e589 = (_e588 * _e529.member_1.member_1.member_2.y);
                                let _e593 = (_e589 * _e586);
                                let _e613 = (_e585 > 0.9997f);
                                let _e614 = (_e585 < -0.9997f);
                                let _e624 = params.member.member_1;
                                let _e628 = params.member.member_3;
                                let _e631 = params.member.member_4;
                                phi_1130_ = 1u;
                                phi_1133_ = _e624;
                                phi_1135_ = false;
                                phi_1137_ = true;
                                phi_1139_ = 0f;
                                phi_1141_ = 0f;
                                loop {
                                    let _e637 = phi_1130_;
                                    let _e639 = phi_1133_;
                                    let _e641 = phi_1135_;
                                    let _e643 = phi_1137_;
                                    let _e645 = phi_1139_;
                                    let _e647 = phi_1141_;
                                    local_4 = _e639;
                                    local_6 = _e641;
                                    local_8 = _e639;
                                    local_9 = _e641;
                                    let _e648 = (_e637 <= _e549);
                                    if _e648 {
                                        let _e654 = (((-(_e529.member_1.member_1.member_5) + f32(_e637)) * _e624) / f32(_e549));
                                        let _e659 = (_e529.member_1.member_1.member_1.x + (select(select(((((_e585 + (_e589 * _e529.member_1.member_1.member_2.y)) * _e568) + (_e593 * _e571)) + (_e586 * _e581)), _e568, _e614), _e568, _e613) * _e654));
                                        let _e661 = (_e529.member_1.member_1.member_1.y + (select(select((((_e593 * _e568) + ((_e585 + ((_e588 * _e586) * _e586)) * _e571)) + (-(_e529.member_1.member_1.member_2.y) * _e581)), -(_e571), _e614), _e571, _e613) * _e654));
                                        let _e663 = (_e529.member_1.member_1.member_1.z + (select(select((((_e529.member_1.member_1.member_2.x * _e568) + (_e529.member_1.member_1.member_2.y * _e571)) + (_e585 * _e581)), _e580, _e614), _e581, _e613) * _e654));
                                        let _e669 = params.member.member.member_1[0u];
                                        let _e672 = (((_e659 * 0.5f) / (_e663 * _e669)) + 0.5f);
                                        let _e678 = params.member.member.member_1[1u];
                                        let _e681 = (0.5f - ((_e661 * 0.5f) / (_e663 * _e678)));
                                        let _e691 = select(false, select(false, select(false, select(false, (_e681 <= 1f), (_e681 >= 0f)), select(false, (_e672 <= 1f), (_e672 >= 0f))), (_e663 > 0f)), _e643);
                                        if _e691 {
                                            let _e692 = (_e672 * _e75);
                                            let _e695 = f32(bitcast<i32>((_e80 - 1u)));
                                            let _e704 = (_e681 * _e85);
                                            let _e707 = f32(bitcast<i32>((_e90 - 1u)));
                                            let _e720 = depth.member[(((bitcast<u32>((floor(select(0f, select(_e707, _e704, (_e704 < _e707)), (_e704 > 0f))) + 8388608f)) - 1258291200u) * _e80) + (bitcast<u32>((floor(select(0f, select(_e695, _e692, (_e692 < _e695)), (_e692 > 0f))) + 8388608f)) - 1258291200u))];
                                            let _e724 = select(_e103, _e720, select(false, (_e720 < _e103), (_e720 > 0f)));
                                            let _e727 = (((_e672 * 2f) - 1f) * _e669);
                                            let _e731 = (((_e681 * -2f) + 1f) * _e678);
                                            let _e733 = (_e659 - (_e727 * _e724));
                                            let _e734 = (_e661 - (_e731 * _e724));
                                            let _e735 = (_e663 - _e724);
                                            let _e741 = sqrt((((_e733 * _e733) + (_e734 * _e734)) + (_e735 * _e735)));
                                            let _e746 = (select(0f, select(1f, _e672, (_e672 < 1f)), (_e672 > 0f)) * _e75);
                                            let _e754 = (bitcast<u32>((floor(select(0f, select(_e695, _e746, (_e746 < _e695)), (_e746 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e759 = (select(0f, select(1f, _e681, (_e681 < 1f)), (_e681 > 0f)) * _e85);
                                            let _e767 = (bitcast<u32>((floor(select(0f, select(_e707, _e759, (_e759 < _e707)), (_e759 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e790 = normals.member[((_e767 * _e80) + _e754)];
                                            let _e793 = f32(bitcast<i32>((_e790 & 255u)));
                                            let _e797 = (select(_e793, (_e793 - 256f), (_e793 >= 128f)) * 0.007874016f);
                                            let _e800 = select(-1f, _e797, ((_e797 > -1f) || false));
                                            let _e805 = f32(bitcast<i32>(((_e790 >> bitcast<u32>(8u)) & 255u)));
                                            let _e809 = (select(_e805, (_e805 - 256f), (_e805 >= 128f)) * 0.007874016f);
                                            let _e812 = select(-1f, _e809, ((_e809 > -1f) || false));
                                            let _e814 = (1f - abs(_e800));
                                            let _e815 = abs(_e812);
                                            let _e816 = (_e814 - _e815);
                                            let _e817 = (_e816 < 0f);
                                            let _e825 = select(_e800, ((1f - _e815) * select(1f, -1f, (_e800 < 0f))), _e817);
                                            let _e826 = select(_e812, (_e814 * select(1f, -1f, (_e812 < 0f))), _e817);
                                            let _e833 = (1f / sqrt((((_e825 * _e825) + (_e826 * _e826)) + (_e816 * _e816))));
                                            let _e834 = (_e825 * _e833);
                                            let _e835 = (_e826 * _e833);
                                            let _e837 = -((_e816 * _e833));
                                            let _e841 = (((_e834 * _e727) + (_e835 * _e731)) + _e837);
                                            let _e850 = select(((((_e834 * ((((((f32(bitcast<i32>(_e754)) + 0.5f) * (1f / _e75)) * 2f) - 1f) * _e669) * _e724)) + (_e835 * ((((((f32(bitcast<i32>(_e767)) + 0.5f) * (1f / _e85)) * -2f) + 1f) * _e678) * _e724))) + (_e837 * _e724)) / _e841), _e724, (abs(_e841) < 0.001f));
                                            let _e860 = select(select(((_e663 - _e850) > _e631), true, (_e663 < (_e850 * (1f + _e628)))), true, select(false, (_e767 == _e529.member_1.member_1.member.y), (_e754 == _e529.member_1.member_1.member.x)));
                                            let _e862 = select(false, !(_e860), _e691);
                                            let _e863 = (_e645 + _e741);
                                            let _e872 = select(false, _e860, _e691);
                                            if _e872 {
                                                phi_1590_ = (_e637 + 1u);
                                            } else {
                                                phi_1590_ = u32();
                                            }
                                            let _e875 = phi_1590_;
                                            phi_1592_ = _e875;
                                            phi_1593_ = select(_e639, select((_e647 + ((_e645 * (_e654 - _e647)) / _e863)), _e647, (_e863 < 0.000001f)), _e862);
                                            phi_1594_ = select(_e862, true, _e641);
                                            phi_1595_ = _e872;
                                            phi_1596_ = _e741;
                                            phi_1599_ = _e872;
                                            phi_1600_ = select(true, false, _e872);
                                        } else {
                                            phi_1592_ = u32();
                                            phi_1593_ = f32();
                                            phi_1594_ = bool();
                                            phi_1595_ = bool();
                                            phi_1596_ = f32();
                                            phi_1599_ = false;
                                            phi_1600_ = false;
                                        }
                                        let _e878 = phi_1592_;
                                        let _e880 = phi_1593_;
                                        let _e882 = phi_1594_;
                                        let _e884 = phi_1595_;
                                        let _e886 = phi_1596_;
                                        let _e888 = phi_1599_;
                                        let _e890 = phi_1600_;
                                        phi_1131_ = _e878;
                                        phi_1134_ = _e880;
                                        phi_1136_ = _e882;
                                        phi_1138_ = _e884;
                                        phi_1140_ = _e886;
                                        phi_1142_ = _e654;
                                        phi_1604_ = _e888;
                                        phi_1606_ = _e890;
                                        phi_1607_ = select(true, false, _e691);
                                    } else {
                                        phi_1131_ = u32();
                                        phi_1134_ = f32();
                                        phi_1136_ = bool();
                                        phi_1138_ = bool();
                                        phi_1140_ = f32();
                                        phi_1142_ = f32();
                                        phi_1604_ = false;
                                        phi_1606_ = false;
                                        phi_1607_ = false;
                                    }
                                    let _e893 = phi_1131_;
                                    let _e895 = phi_1134_;
                                    let _e897 = phi_1136_;
                                    let _e899 = phi_1138_;
                                    let _e901 = phi_1140_;
                                    let _e903 = phi_1142_;
                                    let _e905 = phi_1604_;
                                    let _e907 = phi_1606_;
                                    let _e909 = phi_1607_;
                                    let _e910 = select(true, false, _e648);
                                    local = _e910;
                                    local_1 = _e907;
                                    local_2 = _e910;
                                    local_3 = _e909;
                                    local_5 = _e895;
                                    local_7 = _e897;
                                    continue;
                                    continuing {
                                        phi_1130_ = _e893;
                                        phi_1133_ = _e895;
                                        phi_1135_ = _e897;
                                        phi_1137_ = _e899;
                                        phi_1139_ = _e901;
                                        phi_1141_ = _e903;
                                        break if !(_e905);
                                    }
                                }
                                let _e913 = local;
                                let _e915 = local_1;
                                let _e916 = select(_e915, false, _e913);
                                let _e918 = local_2;
                                let _e920 = local_3;
                                let _e922 = select(select(_e920, false, _e918), false, _e916);
                                let _e924 = local_4;
                                let _e926 = local_5;
                                let _e929 = local_6;
                                let _e931 = local_7;
                                let _e933 = select(_e916, true, _e922);
                                let _e935 = local_8;
                                let _e938 = local_9;
                                let _e942 = params.member.member_7;
                                if (_e942 == 1u) {
                                    phi_1647_ = 0f;
                                } else {
                                    let _e944 = (select(_e935, select(_e926, _e924, _e922), _e933) / _e624);
                                    phi_1647_ = select(0f, select(1f, _e944, (_e944 < 1f)), (_e944 > 0f));
                                }
                                let _e950 = phi_1647_;
                                phi_976_ = (_e551 + 1u);
                                phi_979_ = (_e553 + select(1f, _e950, select(_e938, select(_e931, _e929, _e922), _e933)));
                            } else {
                                phi_976_ = u32();
                                phi_979_ = f32();
                            }
                            let _e955 = phi_976_;
                            let _e957 = phi_979_;
                            continue;
                            continuing {
                                phi_975_ = _e955;
                                phi_978_ = _e957;
                                phi_1867_ = false;
                                break if !(_e554);
                            }
                        }
                        let _e960 = phi_1867_;
                        if _e960 {
                            break;
                        }
                        let _e963 = local_10;
                        let _e967 = params.member.member_2;
                        let _e968 = pow((_e963 / f32(_e544)), _e967);
                        let _e969 = (_e968 * 0.6666667f);
                        phi_1712_ = type_29(_e968, (bitcast<u32>((floor(((select(0f, select(1f, _e969, (_e969 < 1f)), (_e969 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u), _e529.member);
                    } else {
                        phi_1712_ = type_29(1f, (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u), _e529.member);
                    }
                    let _e987 = phi_1712_;
                    if (_e96 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e96] = _e987.member;
                    if (_e96 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e96] = _e987.member_1;
                    if (_e96 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e96] = _e987.member_2;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn raymarch_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
