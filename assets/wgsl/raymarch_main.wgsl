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
    var phi_1902_: bool;
    var phi_1917_: bool;
    var phi_777_: vec2<f32>;
    var phi_808_: vec3<f32>;
    var phi_1012_: type_28;
    var phi_1047_: u32;
    var phi_1050_: f32;
    var phi_1202_: u32;
    var phi_1205_: f32;
    var phi_1207_: bool;
    var phi_1209_: bool;
    var phi_1211_: f32;
    var phi_1213_: f32;
    var phi_2000_: bool;
    var phi_2015_: bool;
    var phi_1976_: vec2<f32>;
    var phi_1573_: u32;
    var phi_1575_: u32;
    var phi_1576_: f32;
    var phi_1577_: bool;
    var phi_1578_: bool;
    var phi_1579_: f32;
    var phi_1582_: bool;
    var phi_1583_: bool;
    var phi_1203_: u32;
    var phi_1206_: f32;
    var phi_1208_: bool;
    var phi_1210_: bool;
    var phi_1212_: f32;
    var phi_1214_: f32;
    var phi_1587_: bool;
    var phi_1589_: bool;
    var phi_1590_: bool;
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
    var phi_1630_: f32;
    var phi_1048_: u32;
    var phi_1051_: f32;
    var phi_2029_: bool;
    var local_10: f32;
    var phi_1701_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e60 = id_1;
            let _e62 = arrayLength((&kernel.member));
            let _e73 = params.member.member.member[0u];
            let _e78 = select(select(u32(_e73), 0u, (_e73 < 0f)), 4294967295u, (_e73 > 4294967000f));
            let _e83 = params.member.member.member[1u];
            let _e88 = select(select(u32(_e83), 0u, (_e83 < 0f)), 4294967295u, (_e83 > 4294967000f));
            if (_e60.x >= _e78) {
            } else {
                if (_e60.y >= _e88) {
                } else {
                    let _e94 = ((_e60.y * _e78) + _e60.x);
                    let _e97 = depth.member[_e94];
                    let _e101 = params.member.member.member_3;
                    let _e104 = select(false, (_e97 < _e101), (_e97 > 0f));
                    let _e105 = select(_e101, _e97, _e104);
                    let _e106 = bitcast<i32>(_e60.x);
                    let _e107 = (_e106 + -1i);
                    let _e109 = select(0i, _e107, (0i < _e107));
                    let _e111 = (bitcast<i32>(_e78) - 1i);
                    let _e115 = bitcast<i32>(_e60.y);
                    let _e117 = select(0i, _e115, (0i < _e115));
                    let _e119 = (bitcast<i32>(_e88) - 1i);
                    let _e123 = (bitcast<u32>(select(_e117, _e119, (_e119 < _e117))) * _e78);
                    let _e127 = depth.member[(_e123 + bitcast<u32>(select(_e109, _e111, (_e111 < _e109))))];
                    let _e132 = (_e106 + 1i);
                    let _e134 = select(0i, _e132, (0i < _e132));
                    let _e141 = depth.member[(_e123 + bitcast<u32>(select(_e134, _e111, (_e111 < _e134))))];
                    let _e147 = select(0i, _e106, (0i < _e106));
                    let _e150 = bitcast<u32>(select(_e147, _e111, (_e111 < _e147)));
                    let _e151 = (_e115 + -1i);
                    let _e153 = select(0i, _e151, (0i < _e151));
                    let _e161 = depth.member[((bitcast<u32>(select(_e153, _e119, (_e119 < _e153))) * _e78) + _e150)];
                    let _e166 = (_e115 + 1i);
                    let _e168 = select(0i, _e166, (0i < _e166));
                    let _e176 = depth.member[((bitcast<u32>(select(_e168, _e119, (_e119 < _e168))) * _e78) + _e150)];
                    let _e181 = (select(_e101, _e127, select(false, (_e127 < _e101), (_e127 > 0f))) - _e105);
                    let _e182 = (select(_e101, _e141, select(false, (_e141 < _e101), (_e141 > 0f))) - _e105);
                    let _e183 = (select(_e101, _e161, select(false, (_e161 < _e101), (_e161 > 0f))) - _e105);
                    let _e184 = (select(_e101, _e176, select(false, (_e176 < _e101), (_e176 > 0f))) - _e105);
                    let _e186 = ((_e182 - _e181) * 0.5f);
                    let _e188 = ((_e184 - _e183) * 0.5f);
                    let _e189 = (_e105 * 0.011f);
                    let _e191 = abs(_e181);
                    let _e192 = abs((_e181 + _e186));
                    let _e198 = (1.25f - (select(_e192, _e191, ((_e191 < _e192) || (_e192 != _e192))) / _e189));
                    let _e202 = select(0f, select(1f, _e198, (_e198 < 1f)), (_e198 > 0f));
                    let _e204 = abs(_e182);
                    let _e205 = abs((_e182 - _e186));
                    let _e211 = (1.25f - (select(_e205, _e204, ((_e204 < _e205) || (_e205 != _e205))) / _e189));
                    let _e215 = select(0f, select(1f, _e211, (_e211 < 1f)), (_e211 > 0f));
                    let _e217 = abs(_e183);
                    let _e218 = abs((_e183 + _e188));
                    let _e224 = (1.25f - (select(_e218, _e217, ((_e217 < _e218) || (_e218 != _e218))) / _e189));
                    let _e228 = select(0f, select(1f, _e224, (_e224 < 1f)), (_e224 > 0f));
                    let _e230 = abs(_e184);
                    let _e231 = abs((_e184 - _e188));
                    let _e237 = (1.25f - (select(_e231, _e230, ((_e230 < _e231) || (_e231 != _e231))) / _e189));
                    let _e241 = select(0f, select(1f, _e237, (_e237 < 1f)), (_e237 > 0f));
                    let _e246 = (select(0f, select(1f, _e202, (_e202 < 1f)), (_e202 > 0f)) * 2.9f);
                    let _e248 = floor((_e246 + 0.5f));
                    let _e257 = select(_e248, (_e248 - 1f), (((_e248 - _e246) == 0.5f) && ((floor((_e248 * 0.5f)) * 2f) != _e248)));
                    let _e259 = select(0f, _e257, (_e257 > 0f));
                    let _e268 = (select(0f, select(1f, _e215, (_e215 < 1f)), (_e215 > 0f)) * 2.9f);
                    let _e270 = floor((_e268 + 0.5f));
                    let _e279 = select(_e270, (_e270 - 1f), (((_e270 - _e268) == 0.5f) && ((floor((_e270 * 0.5f)) * 2f) != _e270)));
                    let _e281 = select(0f, _e279, (_e279 > 0f));
                    let _e291 = (select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f)) * 2.9f);
                    let _e293 = floor((_e291 + 0.5f));
                    let _e302 = select(_e293, (_e293 - 1f), (((_e293 - _e291) == 0.5f) && ((floor((_e293 * 0.5f)) * 2f) != _e293)));
                    let _e304 = select(0f, _e302, (_e302 > 0f));
                    let _e314 = (select(0f, select(1f, _e241, (_e241 < 1f)), (_e241 > 0f)) * 2.9f);
                    let _e316 = floor((_e314 + 0.5f));
                    let _e325 = select(_e316, (_e316 - 1f), (((_e316 - _e314) == 0.5f) && ((floor((_e316 * 0.5f)) * 2f) != _e316)));
                    let _e327 = select(0f, _e325, (_e325 > 0f));
                    let _e331 = ((((64u * u32(select(3f, _e259, (_e259 < 3f)))) + (16u * u32(select(3f, _e281, (_e281 < 3f))))) + (4u * u32(select(3f, _e304, (_e304 < 3f))))) + u32(select(3f, _e327, (_e327 < 3f))));
                    if _e104 {
                        let _e344 = params.member.member.member_1[0u];
                        let _e346 = ((((((f32(_e60.x) + 0.5f) / _e73) * 2f) - 1f) * _e344) * _e97);
                        let _e353 = params.member.member.member_1[1u];
                        let _e355 = ((((((f32(_e60.y) + 0.5f) / _e83) * -2f) + 1f) * _e353) * _e97);
                        let _e359 = normals.member[_e94];
                        let _e367 = (f32((bitcast<i32>(((_e359 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e367 != _e367) {
                            phi_1902_ = true;
                        } else {
                            phi_1902_ = (-1f >= _e367);
                        }
                        let _e371 = phi_1902_;
                        let _e372 = select(_e367, -1f, _e371);
                        let _e382 = (f32((bitcast<i32>((((_e359 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e382 != _e382) {
                            phi_1917_ = true;
                        } else {
                            phi_1917_ = (-1f >= _e382);
                        }
                        let _e386 = phi_1917_;
                        let _e387 = select(_e382, -1f, _e386);
                        let _e390 = (1f - abs(_e372));
                        let _e391 = abs(_e387);
                        let _e392 = (_e390 - _e391);
                        if (_e392 < 0f) {
                            phi_777_ = vec2<f32>(((1f - _e391) * select(1f, -1f, (_e372 < 0f))), (_e390 * select(1f, -1f, (_e387 < 0f))));
                        } else {
                            phi_777_ = vec2<f32>(_e372, _e387);
                        }
                        let _e403 = phi_777_;
                        let _e412 = (1f / sqrt((((_e403.x * _e403.x) + (_e403.y * _e403.y)) + (_e392 * _e392))));
                        let _e413 = (_e403.x * _e412);
                        let _e414 = (_e403.y * _e412);
                        let _e415 = (_e392 * _e412);
                        let _e416 = -(_e415);
                        if ((((_e413 * -(_e346)) + (_e414 * -(_e355))) + (_e416 * -(_e97))) < 0f) {
                            phi_808_ = vec3<f32>(-(_e413), -(_e414), _e415);
                        } else {
                            phi_808_ = vec3<f32>(_e413, _e414, _e416);
                        }
                        let _e431 = phi_808_;
                        let _e434 = params.member.member_8;
                        let _e435 = (_e60.x & 63u);
                        let _e436 = (_e60.y & 63u);
                        let _e439 = select(0u, 1u, ((_e435 & 32u) != 0u));
                        let _e442 = select(0u, 1u, ((_e436 & 32u) != 0u));
                        let _e446 = (_e442 == 0u);
                        let _e448 = (_e446 && (_e439 == 1u));
                        let _e451 = select(_e435, (63u - _e435), _e448);
                        let _e452 = select(_e436, (63u - _e436), _e448);
                        let _e453 = select(_e451, _e452, _e446);
                        let _e454 = select(_e452, _e451, _e446);
                        let _e457 = select(0u, 1u, ((_e453 & 16u) != 0u));
                        let _e460 = select(0u, 1u, ((_e454 & 16u) != 0u));
                        let _e465 = (_e460 == 0u);
                        let _e467 = (_e465 && (_e457 == 1u));
                        let _e470 = select(_e453, (63u - _e453), _e467);
                        let _e471 = select(_e454, (63u - _e454), _e467);
                        let _e472 = select(_e470, _e471, _e465);
                        let _e473 = select(_e471, _e470, _e465);
                        let _e476 = select(0u, 1u, ((_e472 & 8u) != 0u));
                        let _e479 = select(0u, 1u, ((_e473 & 8u) != 0u));
                        let _e484 = (_e479 == 0u);
                        let _e486 = (_e484 && (_e476 == 1u));
                        let _e489 = select(_e472, (63u - _e472), _e486);
                        let _e490 = select(_e473, (63u - _e473), _e486);
                        let _e491 = select(_e489, _e490, _e484);
                        let _e492 = select(_e490, _e489, _e484);
                        let _e495 = select(0u, 1u, ((_e491 & 4u) != 0u));
                        let _e498 = select(0u, 1u, ((_e492 & 4u) != 0u));
                        let _e503 = (_e498 == 0u);
                        let _e505 = (_e503 && (_e495 == 1u));
                        let _e508 = select(_e491, (63u - _e491), _e505);
                        let _e509 = select(_e492, (63u - _e492), _e505);
                        let _e510 = select(_e508, _e509, _e503);
                        let _e511 = select(_e509, _e508, _e503);
                        let _e514 = select(0u, 1u, ((_e510 & 2u) != 0u));
                        let _e517 = select(0u, 1u, ((_e511 & 2u) != 0u));
                        let _e522 = (_e517 == 0u);
                        let _e524 = (_e522 && (_e514 == 1u));
                        let _e527 = select(_e510, (63u - _e510), _e524);
                        let _e528 = select(_e511, (63u - _e511), _e524);
                        let _e543 = f32((((((((1024u * ((3u * _e439) ^ _e442)) + (256u * ((3u * _e457) ^ _e460))) + (64u * ((3u * _e476) ^ _e479))) + (16u * ((3u * _e495) ^ _e498))) + (4u * ((3u * _e514) ^ _e517))) + ((3u * select(0u, 1u, ((select(_e527, _e528, _e522) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e528, _e527, _e522) & 1u) != 0u)))) + (288u * (_e434 % 64u))));
                        let _e545 = (0.5f + (_e543 * 0.7548777f));
                        let _e549 = (0.5f + (_e543 * 0.5698403f));
                        let _e552 = (6.2831855f * (_e545 - floor(_e545)));
                        phi_1012_ = type_28(_e331, type_27(1u, type_26(vec2<u32>(_e60.x, _e60.y), vec3<f32>(_e346, _e355, _e97), _e431, sin(_e552), cos(_e552), (_e549 - floor(_e549)))));
                    } else {
                        phi_1012_ = type_28(_e331, type_27(0u, type_27().member_1));
                    }
                    let _e564 = phi_1012_;
                    if (bitcast<i32>(_e564.member_1.member) != 0i) {
                        let _e573 = params.member.member_5;
                        let _e575 = select(_e573, 64u, (64u < _e573));
                        let _e577 = select(_e575, _e62, (_e62 < _e575));
                        let _e579 = select(1u, _e577, (1u < _e577));
                        let _e582 = params.member.member_6;
                        let _e584 = select(1u, _e582, (1u < _e582));
                        phi_1047_ = 0u;
                        phi_1050_ = 0f;
                        loop {
                            let _e586 = phi_1047_;
                            let _e588 = phi_1050_;
                            local_10 = _e588;
                            let _e589 = (_e586 < _e579);
                            if _e589 {
                                if (_e586 < _e62) {
                                } else {
                                    phi_2029_ = true;
                                    break;
                                }
                                let _e594 = kernel.member[_e586][0u];
                                let _e598 = kernel.member[_e586][1u];
                                let _e603 = ((_e564.member_1.member_1.member_4 * _e594) - (_e564.member_1.member_1.member_3 * _e598));
                                let _e606 = ((_e564.member_1.member_1.member_3 * _e594) + (_e564.member_1.member_1.member_4 * _e598));
                                let _e611 = ((1f - (_e603 * _e603)) - (_e606 * _e606));
                                let _e615 = sqrt(select(0f, _e611, ((_e611 > 0f) || false)));
                                let _e616 = -(_e615);
                                let _e620 = (-1f * _e564.member_1.member_1.member_2.z);
                                let _e621 = (-1f * _e564.member_1.member_1.member_2.x);
                                let _e623 = (1f / (_e620 + 1f));
                                let _e624 = (_e623 * _e564.member_1.member_1.member_2.y);
                                let _e628 = (_e624 * _e621);
                                let _e648 = (_e620 > 0.9997f);
                                let _e649 = (_e620 < -0.9997f);
                                let _e659 = params.member.member_1;
                                let _e663 = params.member.member_3;
                                let _e666 = params.member.member_4;
                                phi_1202_ = 1u;
                                phi_1205_ = _e659;
                                phi_1207_ = false;
                                phi_1209_ = true;
                                phi_1211_ = 0f;
                                phi_1213_ = 0f;
                                loop {
                                    let _e672 = phi_1202_;
                                    let _e674 = phi_1205_;
                                    let _e676 = phi_1207_;
                                    let _e678 = phi_1209_;
                                    let _e680 = phi_1211_;
                                    let _e682 = phi_1213_;
                                    local_4 = _e674;
                                    local_6 = _e676;
                                    local_8 = _e674;
                                    local_9 = _e676;
                                    let _e683 = (_e672 <= _e584);
                                    if _e683 {
                                        let _e689 = (((-(_e564.member_1.member_1.member_5) + f32(_e672)) * _e659) / f32(_e584));
                                        let _e694 = (_e564.member_1.member_1.member_1.x + (select(select(((((_e620 + (_e624 * _e564.member_1.member_1.member_2.y)) * _e603) + (_e628 * _e606)) + (_e621 * _e616)), _e603, _e649), _e603, _e648) * _e689));
                                        let _e696 = (_e564.member_1.member_1.member_1.y + (select(select((((_e628 * _e603) + ((_e620 + ((_e623 * _e621) * _e621)) * _e606)) + (-(_e564.member_1.member_1.member_2.y) * _e616)), -(_e606), _e649), _e606, _e648) * _e689));
                                        let _e698 = (_e564.member_1.member_1.member_1.z + (select(select((((_e564.member_1.member_1.member_2.x * _e603) + (_e564.member_1.member_1.member_2.y * _e606)) + (_e620 * _e616)), _e615, _e649), _e616, _e648) * _e689));
                                        let _e704 = params.member.member.member_1[0u];
                                        let _e707 = (((_e694 * 0.5f) / (_e698 * _e704)) + 0.5f);
                                        let _e713 = params.member.member.member_1[1u];
                                        let _e716 = (0.5f - ((_e696 * 0.5f) / (_e698 * _e713)));
                                        let _e726 = select(false, select(false, select(false, select(false, (_e716 <= 1f), (_e716 >= 0f)), select(false, (_e707 <= 1f), (_e707 >= 0f))), (_e698 > 0f)), _e678);
                                        if _e726 {
                                            let _e727 = (_e707 * _e73);
                                            let _e729 = f32((_e78 - 1u));
                                            let _e731 = select(0f, _e727, (_e727 > 0f));
                                            let _e735 = (_e716 * _e83);
                                            let _e737 = f32((_e88 - 1u));
                                            let _e739 = select(0f, _e735, (_e735 > 0f));
                                            let _e747 = depth.member[((u32(select(_e737, _e739, (_e739 < _e737))) * _e78) + u32(select(_e729, _e731, (_e731 < _e729))))];
                                            let _e751 = select(_e101, _e747, select(false, (_e747 < _e101), (_e747 > 0f)));
                                            let _e754 = (((_e707 * 2f) - 1f) * _e704);
                                            let _e758 = (((_e716 * -2f) + 1f) * _e713);
                                            let _e760 = (_e694 - (_e754 * _e751));
                                            let _e761 = (_e696 - (_e758 * _e751));
                                            let _e762 = (_e698 - _e751);
                                            let _e768 = sqrt((((_e760 * _e760) + (_e761 * _e761)) + (_e762 * _e762)));
                                            let _e773 = (select(0f, select(1f, _e707, (_e707 < 1f)), (_e707 > 0f)) * _e73);
                                            let _e775 = select(0f, _e773, (_e773 > 0f));
                                            let _e778 = u32(select(_e729, _e775, (_e775 < _e729)));
                                            let _e783 = (select(0f, select(1f, _e716, (_e716 < 1f)), (_e716 > 0f)) * _e83);
                                            let _e785 = select(0f, _e783, (_e783 > 0f));
                                            let _e788 = u32(select(_e737, _e785, (_e785 < _e737)));
                                            let _e809 = normals.member[((_e788 * _e78) + _e778)];
                                            let _e817 = (f32((bitcast<i32>(((_e809 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e817 != _e817) {
                                                phi_2000_ = true;
                                            } else {
                                                phi_2000_ = (-1f >= _e817);
                                            }
                                            let _e821 = phi_2000_;
                                            let _e822 = select(_e817, -1f, _e821);
                                            let _e832 = (f32((bitcast<i32>((((_e809 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e832 != _e832) {
                                                phi_2015_ = true;
                                            } else {
                                                phi_2015_ = (-1f >= _e832);
                                            }
                                            let _e836 = phi_2015_;
                                            let _e837 = select(_e832, -1f, _e836);
                                            let _e840 = (1f - abs(_e822));
                                            let _e841 = abs(_e837);
                                            let _e842 = (_e840 - _e841);
                                            if (_e842 < 0f) {
                                                phi_1976_ = vec2<f32>(((1f - _e841) * select(1f, -1f, (_e822 < 0f))), (_e840 * select(1f, -1f, (_e837 < 0f))));
                                            } else {
                                                phi_1976_ = vec2<f32>(_e822, _e837);
                                            }
                                            let _e853 = phi_1976_;
                                            let _e862 = (1f / sqrt((((_e853.x * _e853.x) + (_e853.y * _e853.y)) + (_e842 * _e842))));
                                            let _e863 = (_e853.x * _e862);
                                            let _e864 = (_e853.y * _e862);
                                            let _e866 = -((_e842 * _e862));
                                            let _e870 = (((_e863 * _e754) + (_e864 * _e758)) + _e866);
                                            let _e879 = select(((((_e863 * ((((((f32(_e778) + 0.5f) * (1f / _e73)) * 2f) - 1f) * _e704) * _e751)) + (_e864 * ((((((f32(_e788) + 0.5f) * (1f / _e83)) * -2f) + 1f) * _e713) * _e751))) + (_e866 * _e751)) / _e870), _e751, (abs(_e870) < 0.001f));
                                            let _e889 = select(select(((_e698 - _e879) > _e666), true, (_e698 < (_e879 * (1f + _e663)))), true, select(false, (_e788 == _e564.member_1.member_1.member.y), (_e778 == _e564.member_1.member_1.member.x)));
                                            let _e891 = select(false, !(_e889), _e726);
                                            let _e892 = (_e680 + _e768);
                                            let _e901 = select(false, _e889, _e726);
                                            if _e901 {
                                                phi_1573_ = (_e672 + 1u);
                                            } else {
                                                phi_1573_ = u32();
                                            }
                                            let _e904 = phi_1573_;
                                            phi_1575_ = _e904;
                                            phi_1576_ = select(_e674, select((_e682 + ((_e680 * (_e689 - _e682)) / _e892)), _e682, (_e892 < 0.000001f)), _e891);
                                            phi_1577_ = select(_e891, true, _e676);
                                            phi_1578_ = _e901;
                                            phi_1579_ = _e768;
                                            phi_1582_ = _e901;
                                            phi_1583_ = select(true, false, _e901);
                                        } else {
                                            phi_1575_ = u32();
                                            phi_1576_ = f32();
                                            phi_1577_ = bool();
                                            phi_1578_ = bool();
                                            phi_1579_ = f32();
                                            phi_1582_ = false;
                                            phi_1583_ = false;
                                        }
                                        let _e907 = phi_1575_;
                                        let _e909 = phi_1576_;
                                        let _e911 = phi_1577_;
                                        let _e913 = phi_1578_;
                                        let _e915 = phi_1579_;
                                        let _e917 = phi_1582_;
                                        let _e919 = phi_1583_;
                                        phi_1203_ = _e907;
                                        phi_1206_ = _e909;
                                        phi_1208_ = _e911;
                                        phi_1210_ = _e913;
                                        phi_1212_ = _e915;
                                        phi_1214_ = _e689;
                                        phi_1587_ = _e917;
                                        phi_1589_ = _e919;
                                        phi_1590_ = select(true, false, _e726);
                                    } else {
                                        phi_1203_ = u32();
                                        phi_1206_ = f32();
                                        phi_1208_ = bool();
                                        phi_1210_ = bool();
                                        phi_1212_ = f32();
                                        phi_1214_ = f32();
                                        phi_1587_ = false;
                                        phi_1589_ = false;
                                        phi_1590_ = false;
                                    }
                                    let _e922 = phi_1203_;
                                    let _e924 = phi_1206_;
                                    let _e926 = phi_1208_;
                                    let _e928 = phi_1210_;
                                    let _e930 = phi_1212_;
                                    let _e932 = phi_1214_;
                                    let _e934 = phi_1587_;
                                    let _e936 = phi_1589_;
                                    let _e938 = phi_1590_;
                                    let _e939 = select(true, false, _e683);
                                    local = _e939;
                                    local_1 = _e936;
                                    local_2 = _e939;
                                    local_3 = _e938;
                                    local_5 = _e924;
                                    local_7 = _e926;
                                    continue;
                                    continuing {
                                        phi_1202_ = _e922;
                                        phi_1205_ = _e924;
                                        phi_1207_ = _e926;
                                        phi_1209_ = _e928;
                                        phi_1211_ = _e930;
                                        phi_1213_ = _e932;
                                        break if !(_e934);
                                    }
                                }
                                let _e942 = local;
                                let _e944 = local_1;
                                let _e945 = select(_e944, false, _e942);
                                let _e947 = local_2;
                                let _e949 = local_3;
                                let _e951 = select(select(_e949, false, _e947), false, _e945);
                                let _e953 = local_4;
                                let _e955 = local_5;
                                let _e958 = local_6;
                                let _e960 = local_7;
                                let _e962 = select(_e945, true, _e951);
                                let _e964 = local_8;
                                let _e967 = local_9;
                                let _e971 = params.member.member_7;
                                if (_e971 == 1u) {
                                    phi_1630_ = 0f;
                                } else {
                                    let _e973 = (select(_e964, select(_e955, _e953, _e951), _e962) / _e659);
                                    phi_1630_ = select(0f, select(1f, _e973, (_e973 < 1f)), (_e973 > 0f));
                                }
                                let _e979 = phi_1630_;
                                phi_1048_ = (_e586 + 1u);
                                phi_1051_ = (_e588 + select(1f, _e979, select(_e967, select(_e960, _e958, _e951), _e962)));
                            } else {
                                phi_1048_ = u32();
                                phi_1051_ = f32();
                            }
                            let _e984 = phi_1048_;
                            let _e986 = phi_1051_;
                            continue;
                            continuing {
                                phi_1047_ = _e984;
                                phi_1050_ = _e986;
                                phi_2029_ = false;
                                break if !(_e589);
                            }
                        }
                        let _e989 = phi_2029_;
                        if _e989 {
                            break;
                        }
                        let _e992 = local_10;
                        let _e996 = params.member.member_2;
                        let _e997 = pow((_e992 / f32(_e579)), _e996);
                        let _e998 = (_e997 * 0.6666667f);
                        let _e1004 = ((select(0f, select(1f, _e998, (_e998 < 1f)), (_e998 > 0f)) * 255f) + 0.5f);
                        phi_1701_ = type_29(_e997, select(select(u32(_e1004), 0u, (_e1004 < 0f)), 4294967295u, (_e1004 > 4294967000f)), _e564.member);
                    } else {
                        phi_1701_ = type_29(1f, 170u, _e564.member);
                    }
                    let _e1013 = phi_1701_;
                    if (_e94 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e94] = _e1013.member;
                    if (_e94 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e94] = _e1013.member_1;
                    if (_e94 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e94] = _e1013.member_2;
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
