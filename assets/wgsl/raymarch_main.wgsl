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
    var phi_1874_: bool;
    var phi_1889_: bool;
    var phi_772_: vec2<f32>;
    var phi_803_: vec3<f32>;
    var phi_1008_: type_28;
    var phi_1043_: u32;
    var phi_1046_: f32;
    var phi_1198_: u32;
    var phi_1201_: f32;
    var phi_1203_: bool;
    var phi_1205_: bool;
    var phi_1207_: f32;
    var phi_1209_: f32;
    var phi_1972_: bool;
    var phi_1987_: bool;
    var phi_1948_: vec2<f32>;
    var phi_1587_: u32;
    var phi_1589_: u32;
    var phi_1590_: f32;
    var phi_1591_: bool;
    var phi_1592_: bool;
    var phi_1593_: f32;
    var phi_1596_: bool;
    var phi_1597_: bool;
    var phi_1199_: u32;
    var phi_1202_: f32;
    var phi_1204_: bool;
    var phi_1206_: bool;
    var phi_1208_: f32;
    var phi_1210_: f32;
    var phi_1601_: bool;
    var phi_1603_: bool;
    var phi_1604_: bool;
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
    var phi_1644_: f32;
    var phi_1044_: u32;
    var phi_1047_: f32;
    var phi_2001_: bool;
    var local_10: f32;
    var phi_1709_: type_29;

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
                    let _e251 = select(0f, _e249, (_e249 > 0f));
                    let _e264 = round((select(0f, select(1f, _e217, (_e217 < 1f)), (_e217 > 0f)) * 2.9f));
                    let _e266 = select(0f, _e264, (_e264 > 0f));
                    let _e280 = round((select(0f, select(1f, _e230, (_e230 < 1f)), (_e230 > 0f)) * 2.9f));
                    let _e282 = select(0f, _e280, (_e280 > 0f));
                    let _e296 = round((select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f)) * 2.9f));
                    let _e298 = select(0f, _e296, (_e296 > 0f));
                    let _e305 = ((((64u * (bitcast<u32>((floor(select(3f, _e251, (_e251 < 3f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(3f, _e266, (_e266 < 3f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(3f, _e282, (_e282 < 3f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(3f, _e298, (_e298 < 3f))) + 8388608f)) - 1258291200u));
                    if _e106 {
                        let _e318 = params.member.member.member_1[0u];
                        let _e320 = ((((((f32(_e108) + 0.5f) / _e75) * 2f) - 1f) * _e318) * _e99);
                        let _e327 = params.member.member.member_1[1u];
                        let _e329 = ((((((f32(_e117) + 0.5f) / _e85) * -2f) + 1f) * _e327) * _e99);
                        let _e333 = normals.member[_e96];
                        let _e341 = (f32((bitcast<i32>(((_e333 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e341 != _e341) {
                            phi_1874_ = true;
                        } else {
                            phi_1874_ = (-1f >= _e341);
                        }
                        let _e345 = phi_1874_;
                        let _e346 = select(_e341, -1f, _e345);
                        let _e356 = (f32((bitcast<i32>((((_e333 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e356 != _e356) {
                            phi_1889_ = true;
                        } else {
                            phi_1889_ = (-1f >= _e356);
                        }
                        let _e360 = phi_1889_;
                        let _e361 = select(_e356, -1f, _e360);
                        let _e364 = (1f - abs(_e346));
                        let _e365 = abs(_e361);
                        let _e366 = (_e364 - _e365);
                        if (_e366 < 0f) {
                            phi_772_ = vec2<f32>(((1f - _e365) * select(1f, -1f, (_e346 < 0f))), (_e364 * select(1f, -1f, (_e361 < 0f))));
                        } else {
                            phi_772_ = vec2<f32>(_e346, _e361);
                        }
                        let _e377 = phi_772_;
                        let _e386 = (1f / sqrt((((_e377.x * _e377.x) + (_e377.y * _e377.y)) + (_e366 * _e366))));
                        let _e387 = (_e377.x * _e386);
                        let _e388 = (_e377.y * _e386);
                        let _e389 = (_e366 * _e386);
                        let _e390 = -(_e389);
                        if ((((_e387 * -(_e320)) + (_e388 * -(_e329))) + (_e390 * -(_e99))) < 0f) {
                            phi_803_ = vec3<f32>(-(_e387), -(_e388), _e389);
                        } else {
                            phi_803_ = vec3<f32>(_e387, _e388, _e390);
                        }
                        let _e405 = phi_803_;
                        let _e408 = params.member.member_8;
                        let _e409 = (_e62.x & 63u);
                        let _e410 = (_e62.y & 63u);
                        let _e413 = select(0u, 1u, ((_e409 & 32u) != 0u));
                        let _e416 = select(0u, 1u, ((_e410 & 32u) != 0u));
                        let _e420 = (_e416 == 0u);
                        let _e422 = (_e420 && (_e413 == 1u));
                        let _e425 = select(_e409, (63u - _e409), _e422);
                        let _e426 = select(_e410, (63u - _e410), _e422);
                        let _e427 = select(_e425, _e426, _e420);
                        let _e428 = select(_e426, _e425, _e420);
                        let _e431 = select(0u, 1u, ((_e427 & 16u) != 0u));
                        let _e434 = select(0u, 1u, ((_e428 & 16u) != 0u));
                        let _e439 = (_e434 == 0u);
                        let _e441 = (_e439 && (_e431 == 1u));
                        let _e444 = select(_e427, (63u - _e427), _e441);
                        let _e445 = select(_e428, (63u - _e428), _e441);
                        let _e446 = select(_e444, _e445, _e439);
                        let _e447 = select(_e445, _e444, _e439);
                        let _e450 = select(0u, 1u, ((_e446 & 8u) != 0u));
                        let _e453 = select(0u, 1u, ((_e447 & 8u) != 0u));
                        let _e458 = (_e453 == 0u);
                        let _e460 = (_e458 && (_e450 == 1u));
                        let _e463 = select(_e446, (63u - _e446), _e460);
                        let _e464 = select(_e447, (63u - _e447), _e460);
                        let _e465 = select(_e463, _e464, _e458);
                        let _e466 = select(_e464, _e463, _e458);
                        let _e469 = select(0u, 1u, ((_e465 & 4u) != 0u));
                        let _e472 = select(0u, 1u, ((_e466 & 4u) != 0u));
                        let _e477 = (_e472 == 0u);
                        let _e479 = (_e477 && (_e469 == 1u));
                        let _e482 = select(_e465, (63u - _e465), _e479);
                        let _e483 = select(_e466, (63u - _e466), _e479);
                        let _e484 = select(_e482, _e483, _e477);
                        let _e485 = select(_e483, _e482, _e477);
                        let _e488 = select(0u, 1u, ((_e484 & 2u) != 0u));
                        let _e491 = select(0u, 1u, ((_e485 & 2u) != 0u));
                        let _e496 = (_e491 == 0u);
                        let _e498 = (_e496 && (_e488 == 1u));
                        let _e501 = select(_e484, (63u - _e484), _e498);
                        let _e502 = select(_e485, (63u - _e485), _e498);
                        let _e518 = f32(bitcast<i32>((((((((1024u * ((3u * _e413) ^ _e416)) + (256u * ((3u * _e431) ^ _e434))) + (64u * ((3u * _e450) ^ _e453))) + (16u * ((3u * _e469) ^ _e472))) + (4u * ((3u * _e488) ^ _e491))) + ((3u * select(0u, 1u, ((select(_e501, _e502, _e496) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e502, _e501, _e496) & 1u) != 0u)))) + (288u * (_e408 % 64u)))));
                        let _e520 = (0.5f + (_e518 * 0.7548777f));
                        let _e524 = (0.5f + (_e518 * 0.5698403f));
                        let _e527 = (6.2831855f * (_e520 - floor(_e520)));
                        phi_1008_ = type_28(_e305, type_27(1u, type_26(vec2<u32>(_e62.x, _e62.y), vec3<f32>(_e320, _e329, _e99), _e405, sin(_e527), cos(_e527), (_e524 - floor(_e524)))));
                    } else {
                        phi_1008_ = type_28(_e305, type_27(0u, type_27().member_1));
                    }
                    let _e539 = phi_1008_;
                    if (bitcast<i32>(_e539.member_1.member) != 0i) {
                        let _e548 = params.member.member_5;
                        let _e550 = select(_e548, 64u, (64u < _e548));
                        let _e552 = select(_e550, _e64, (_e64 < _e550));
                        let _e554 = select(1u, _e552, (1u < _e552));
                        let _e557 = params.member.member_6;
                        let _e559 = select(1u, _e557, (1u < _e557));
                        phi_1043_ = 0u;
                        phi_1046_ = 0f;
                        loop {
                            let _e561 = phi_1043_;
                            let _e563 = phi_1046_;
                            local_10 = _e563;
                            let _e564 = (_e561 < _e554);
                            if _e564 {
                                if (_e561 < _e64) {
                                } else {
                                    phi_2001_ = true;
                                    break;
                                }
                                let _e569 = kernel.member[_e561][0u];
                                let _e573 = kernel.member[_e561][1u];
                                let _e578 = ((_e539.member_1.member_1.member_4 * _e569) - (_e539.member_1.member_1.member_3 * _e573));
                                let _e581 = ((_e539.member_1.member_1.member_3 * _e569) + (_e539.member_1.member_1.member_4 * _e573));
                                let _e586 = ((1f - (_e578 * _e578)) - (_e581 * _e581));
                                let _e590 = sqrt(select(0f, _e586, ((_e586 > 0f) || false)));
                                let _e591 = -(_e590);
                                let _e595 = (-1f * _e539.member_1.member_1.member_2.z);
                                let _e596 = (-1f * _e539.member_1.member_1.member_2.x);
                                let _e598 = (1f / (_e595 + 1f));
                                let _e599 = (_e598 * _e539.member_1.member_1.member_2.y);
                                let _e603 = (_e599 * _e596);
                                let _e623 = (_e595 > 0.9997f);
                                let _e624 = (_e595 < -0.9997f);
                                let _e634 = params.member.member_1;
                                let _e638 = params.member.member_3;
                                let _e641 = params.member.member_4;
                                phi_1198_ = 1u;
                                phi_1201_ = _e634;
                                phi_1203_ = false;
                                phi_1205_ = true;
                                phi_1207_ = 0f;
                                phi_1209_ = 0f;
                                loop {
                                    let _e647 = phi_1198_;
                                    let _e649 = phi_1201_;
                                    let _e651 = phi_1203_;
                                    let _e653 = phi_1205_;
                                    let _e655 = phi_1207_;
                                    let _e657 = phi_1209_;
                                    local_4 = _e649;
                                    local_6 = _e651;
                                    local_8 = _e649;
                                    local_9 = _e651;
                                    let _e658 = (_e647 <= _e559);
                                    if _e658 {
                                        let _e664 = (((-(_e539.member_1.member_1.member_5) + f32(_e647)) * _e634) / f32(_e559));
                                        let _e669 = (_e539.member_1.member_1.member_1.x + (select(select(((((_e595 + (_e599 * _e539.member_1.member_1.member_2.y)) * _e578) + (_e603 * _e581)) + (_e596 * _e591)), _e578, _e624), _e578, _e623) * _e664));
                                        let _e671 = (_e539.member_1.member_1.member_1.y + (select(select((((_e603 * _e578) + ((_e595 + ((_e598 * _e596) * _e596)) * _e581)) + (-(_e539.member_1.member_1.member_2.y) * _e591)), -(_e581), _e624), _e581, _e623) * _e664));
                                        let _e673 = (_e539.member_1.member_1.member_1.z + (select(select((((_e539.member_1.member_1.member_2.x * _e578) + (_e539.member_1.member_1.member_2.y * _e581)) + (_e595 * _e591)), _e590, _e624), _e591, _e623) * _e664));
                                        let _e679 = params.member.member.member_1[0u];
                                        let _e682 = (((_e669 * 0.5f) / (_e673 * _e679)) + 0.5f);
                                        let _e688 = params.member.member.member_1[1u];
                                        let _e691 = (0.5f - ((_e671 * 0.5f) / (_e673 * _e688)));
                                        let _e701 = select(false, select(false, select(false, select(false, (_e691 <= 1f), (_e691 >= 0f)), select(false, (_e682 <= 1f), (_e682 >= 0f))), (_e673 > 0f)), _e653);
                                        if _e701 {
                                            let _e702 = (_e682 * _e75);
                                            let _e705 = f32(bitcast<i32>((_e80 - 1u)));
                                            let _e707 = select(0f, _e702, (_e702 > 0f));
                                            let _e714 = (_e691 * _e85);
                                            let _e717 = f32(bitcast<i32>((_e90 - 1u)));
                                            let _e719 = select(0f, _e714, (_e714 > 0f));
                                            let _e730 = depth.member[(((bitcast<u32>((floor(select(_e717, _e719, (_e719 < _e717))) + 8388608f)) - 1258291200u) * _e80) + (bitcast<u32>((floor(select(_e705, _e707, (_e707 < _e705))) + 8388608f)) - 1258291200u))];
                                            let _e734 = select(_e103, _e730, select(false, (_e730 < _e103), (_e730 > 0f)));
                                            let _e737 = (((_e682 * 2f) - 1f) * _e679);
                                            let _e741 = (((_e691 * -2f) + 1f) * _e688);
                                            let _e743 = (_e669 - (_e737 * _e734));
                                            let _e744 = (_e671 - (_e741 * _e734));
                                            let _e745 = (_e673 - _e734);
                                            let _e751 = sqrt((((_e743 * _e743) + (_e744 * _e744)) + (_e745 * _e745)));
                                            let _e756 = (select(0f, select(1f, _e682, (_e682 < 1f)), (_e682 > 0f)) * _e75);
                                            let _e758 = select(0f, _e756, (_e756 > 0f));
                                            let _e764 = (bitcast<u32>((floor(select(_e705, _e758, (_e758 < _e705))) + 8388608f)) - 1258291200u);
                                            let _e769 = (select(0f, select(1f, _e691, (_e691 < 1f)), (_e691 > 0f)) * _e85);
                                            let _e771 = select(0f, _e769, (_e769 > 0f));
                                            let _e777 = (bitcast<u32>((floor(select(_e717, _e771, (_e771 < _e717))) + 8388608f)) - 1258291200u);
                                            let _e800 = normals.member[((_e777 * _e80) + _e764)];
                                            let _e808 = (f32((bitcast<i32>(((_e800 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e808 != _e808) {
                                                phi_1972_ = true;
                                            } else {
                                                phi_1972_ = (-1f >= _e808);
                                            }
                                            let _e812 = phi_1972_;
                                            let _e813 = select(_e808, -1f, _e812);
                                            let _e823 = (f32((bitcast<i32>((((_e800 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e823 != _e823) {
                                                phi_1987_ = true;
                                            } else {
                                                phi_1987_ = (-1f >= _e823);
                                            }
                                            let _e827 = phi_1987_;
                                            let _e828 = select(_e823, -1f, _e827);
                                            let _e831 = (1f - abs(_e813));
                                            let _e832 = abs(_e828);
                                            let _e833 = (_e831 - _e832);
                                            if (_e833 < 0f) {
                                                phi_1948_ = vec2<f32>(((1f - _e832) * select(1f, -1f, (_e813 < 0f))), (_e831 * select(1f, -1f, (_e828 < 0f))));
                                            } else {
                                                phi_1948_ = vec2<f32>(_e813, _e828);
                                            }
                                            let _e844 = phi_1948_;
                                            let _e853 = (1f / sqrt((((_e844.x * _e844.x) + (_e844.y * _e844.y)) + (_e833 * _e833))));
                                            let _e854 = (_e844.x * _e853);
                                            let _e855 = (_e844.y * _e853);
                                            let _e857 = -((_e833 * _e853));
                                            let _e861 = (((_e854 * _e737) + (_e855 * _e741)) + _e857);
                                            let _e870 = select(((((_e854 * ((((((f32(bitcast<i32>(_e764)) + 0.5f) * (1f / _e75)) * 2f) - 1f) * _e679) * _e734)) + (_e855 * ((((((f32(bitcast<i32>(_e777)) + 0.5f) * (1f / _e85)) * -2f) + 1f) * _e688) * _e734))) + (_e857 * _e734)) / _e861), _e734, (abs(_e861) < 0.001f));
                                            let _e880 = select(select(((_e673 - _e870) > _e641), true, (_e673 < (_e870 * (1f + _e638)))), true, select(false, (_e777 == _e539.member_1.member_1.member.y), (_e764 == _e539.member_1.member_1.member.x)));
                                            let _e882 = select(false, !(_e880), _e701);
                                            let _e883 = (_e655 + _e751);
                                            let _e892 = select(false, _e880, _e701);
                                            if _e892 {
                                                phi_1587_ = (_e647 + 1u);
                                            } else {
                                                phi_1587_ = u32();
                                            }
                                            let _e895 = phi_1587_;
                                            phi_1589_ = _e895;
                                            phi_1590_ = select(_e649, select((_e657 + ((_e655 * (_e664 - _e657)) / _e883)), _e657, (_e883 < 0.000001f)), _e882);
                                            phi_1591_ = select(_e882, true, _e651);
                                            phi_1592_ = _e892;
                                            phi_1593_ = _e751;
                                            phi_1596_ = _e892;
                                            phi_1597_ = select(true, false, _e892);
                                        } else {
                                            phi_1589_ = u32();
                                            phi_1590_ = f32();
                                            phi_1591_ = bool();
                                            phi_1592_ = bool();
                                            phi_1593_ = f32();
                                            phi_1596_ = false;
                                            phi_1597_ = false;
                                        }
                                        let _e898 = phi_1589_;
                                        let _e900 = phi_1590_;
                                        let _e902 = phi_1591_;
                                        let _e904 = phi_1592_;
                                        let _e906 = phi_1593_;
                                        let _e908 = phi_1596_;
                                        let _e910 = phi_1597_;
                                        phi_1199_ = _e898;
                                        phi_1202_ = _e900;
                                        phi_1204_ = _e902;
                                        phi_1206_ = _e904;
                                        phi_1208_ = _e906;
                                        phi_1210_ = _e664;
                                        phi_1601_ = _e908;
                                        phi_1603_ = _e910;
                                        phi_1604_ = select(true, false, _e701);
                                    } else {
                                        phi_1199_ = u32();
                                        phi_1202_ = f32();
                                        phi_1204_ = bool();
                                        phi_1206_ = bool();
                                        phi_1208_ = f32();
                                        phi_1210_ = f32();
                                        phi_1601_ = false;
                                        phi_1603_ = false;
                                        phi_1604_ = false;
                                    }
                                    let _e913 = phi_1199_;
                                    let _e915 = phi_1202_;
                                    let _e917 = phi_1204_;
                                    let _e919 = phi_1206_;
                                    let _e921 = phi_1208_;
                                    let _e923 = phi_1210_;
                                    let _e925 = phi_1601_;
                                    let _e927 = phi_1603_;
                                    let _e929 = phi_1604_;
                                    let _e930 = select(true, false, _e658);
                                    local = _e930;
                                    local_1 = _e927;
                                    local_2 = _e930;
                                    local_3 = _e929;
                                    local_5 = _e915;
                                    local_7 = _e917;
                                    continue;
                                    continuing {
                                        phi_1198_ = _e913;
                                        phi_1201_ = _e915;
                                        phi_1203_ = _e917;
                                        phi_1205_ = _e919;
                                        phi_1207_ = _e921;
                                        phi_1209_ = _e923;
                                        break if !(_e925);
                                    }
                                }
                                let _e933 = local;
                                let _e935 = local_1;
                                let _e936 = select(_e935, false, _e933);
                                let _e938 = local_2;
                                let _e940 = local_3;
                                let _e942 = select(select(_e940, false, _e938), false, _e936);
                                let _e944 = local_4;
                                let _e946 = local_5;
                                let _e949 = local_6;
                                let _e951 = local_7;
                                let _e953 = select(_e936, true, _e942);
                                let _e955 = local_8;
                                let _e958 = local_9;
                                let _e962 = params.member.member_7;
                                if (_e962 == 1u) {
                                    phi_1644_ = 0f;
                                } else {
                                    let _e964 = (select(_e955, select(_e946, _e944, _e942), _e953) / _e634);
                                    phi_1644_ = select(0f, select(1f, _e964, (_e964 < 1f)), (_e964 > 0f));
                                }
                                let _e970 = phi_1644_;
                                phi_1044_ = (_e561 + 1u);
                                phi_1047_ = (_e563 + select(1f, _e970, select(_e958, select(_e951, _e949, _e942), _e953)));
                            } else {
                                phi_1044_ = u32();
                                phi_1047_ = f32();
                            }
                            let _e975 = phi_1044_;
                            let _e977 = phi_1047_;
                            continue;
                            continuing {
                                phi_1043_ = _e975;
                                phi_1046_ = _e977;
                                phi_2001_ = false;
                                break if !(_e564);
                            }
                        }
                        let _e980 = phi_2001_;
                        if _e980 {
                            break;
                        }
                        let _e983 = local_10;
                        let _e987 = params.member.member_2;
                        let _e988 = pow((_e983 / f32(_e554)), _e987);
                        let _e989 = (_e988 * 0.6666667f);
                        phi_1709_ = type_29(_e988, (bitcast<u32>((floor(((select(0f, select(1f, _e989, (_e989 < 1f)), (_e989 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u), _e539.member);
                    } else {
                        phi_1709_ = type_29(1f, (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u), _e539.member);
                    }
                    let _e1007 = phi_1709_;
                    if (_e96 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e96] = _e1007.member;
                    if (_e96 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e96] = _e1007.member_1;
                    if (_e96 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e96] = _e1007.member_2;
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
