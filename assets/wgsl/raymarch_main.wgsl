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
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;
@group(0) @binding(6) 
var<uniform> params: type_21;
@group(0) @binding(2) 
var<storage> kernel: type_24;

fn function_() {
    var phi_734_: vec3<f32>;
    var phi_874_: type_28;
    var phi_909_: u32;
    var phi_912_: f32;
    var phi_1064_: u32;
    var phi_1067_: f32;
    var phi_1069_: bool;
    var phi_1071_: bool;
    var phi_1073_: f32;
    var phi_1075_: f32;
    var phi_1524_: u32;
    var phi_1526_: u32;
    var phi_1527_: f32;
    var phi_1528_: bool;
    var phi_1529_: bool;
    var phi_1530_: f32;
    var phi_1533_: bool;
    var phi_1534_: bool;
    var phi_1065_: u32;
    var phi_1068_: f32;
    var phi_1070_: bool;
    var phi_1072_: bool;
    var phi_1074_: f32;
    var phi_1076_: f32;
    var phi_1538_: bool;
    var phi_1540_: bool;
    var phi_1541_: bool;
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
    var phi_1581_: f32;
    var phi_910_: u32;
    var phi_913_: f32;
    var phi_1801_: bool;
    var local_10: f32;
    var phi_1646_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e61 = id_1;
            let _e63 = arrayLength((&kernel.member));
            let _e74 = params.member.member.member[0u];
            let _e79 = select(select(u32(_e74), 0u, (_e74 < 0f)), 4294967295u, (_e74 > 4294967000f));
            let _e84 = params.member.member.member[1u];
            let _e89 = select(select(u32(_e84), 0u, (_e84 < 0f)), 4294967295u, (_e84 > 4294967000f));
            if (_e61.x >= _e79) {
            } else {
                if (_e61.y >= _e89) {
                } else {
                    let _e95 = ((_e61.y * _e79) + _e61.x);
                    let _e98 = depth.member[_e95];
                    let _e102 = params.member.member.member_3;
                    let _e105 = select(false, (_e98 < _e102), (_e98 > 0f));
                    let _e106 = select(_e102, _e98, _e105);
                    let _e107 = bitcast<i32>(_e61.x);
                    let _e108 = (_e107 + -1i);
                    let _e110 = select(0i, _e108, (0i < _e108));
                    let _e112 = (bitcast<i32>(_e79) - 1i);
                    let _e116 = bitcast<i32>(_e61.y);
                    let _e118 = select(0i, _e116, (0i < _e116));
                    let _e120 = (bitcast<i32>(_e89) - 1i);
                    let _e124 = (bitcast<u32>(select(_e118, _e120, (_e120 < _e118))) * _e79);
                    let _e128 = depth.member[(_e124 + bitcast<u32>(select(_e110, _e112, (_e112 < _e110))))];
                    let _e133 = (_e107 + 1i);
                    let _e135 = select(0i, _e133, (0i < _e133));
                    let _e142 = depth.member[(_e124 + bitcast<u32>(select(_e135, _e112, (_e112 < _e135))))];
                    let _e148 = select(0i, _e107, (0i < _e107));
                    let _e151 = bitcast<u32>(select(_e148, _e112, (_e112 < _e148)));
                    let _e152 = (_e116 + -1i);
                    let _e154 = select(0i, _e152, (0i < _e152));
                    let _e162 = depth.member[((bitcast<u32>(select(_e154, _e120, (_e120 < _e154))) * _e79) + _e151)];
                    let _e167 = (_e116 + 1i);
                    let _e169 = select(0i, _e167, (0i < _e167));
                    let _e177 = depth.member[((bitcast<u32>(select(_e169, _e120, (_e120 < _e169))) * _e79) + _e151)];
                    let _e182 = (select(_e102, _e128, select(false, (_e128 < _e102), (_e128 > 0f))) - _e106);
                    let _e183 = (select(_e102, _e142, select(false, (_e142 < _e102), (_e142 > 0f))) - _e106);
                    let _e184 = (select(_e102, _e162, select(false, (_e162 < _e102), (_e162 > 0f))) - _e106);
                    let _e185 = (select(_e102, _e177, select(false, (_e177 < _e102), (_e177 > 0f))) - _e106);
                    let _e187 = ((_e183 - _e182) * 0.5f);
                    let _e189 = ((_e185 - _e184) * 0.5f);
                    let _e190 = (_e106 * 0.011f);
                    let _e192 = abs(_e182);
                    let _e193 = abs((_e182 + _e187));
                    let _e199 = (1.25f - (select(_e193, _e192, ((_e192 < _e193) || (_e193 != _e193))) / _e190));
                    let _e203 = select(0f, select(1f, _e199, (_e199 < 1f)), (_e199 > 0f));
                    let _e205 = abs(_e183);
                    let _e206 = abs((_e183 - _e187));
                    let _e212 = (1.25f - (select(_e206, _e205, ((_e205 < _e206) || (_e206 != _e206))) / _e190));
                    let _e216 = select(0f, select(1f, _e212, (_e212 < 1f)), (_e212 > 0f));
                    let _e218 = abs(_e184);
                    let _e219 = abs((_e184 + _e189));
                    let _e225 = (1.25f - (select(_e219, _e218, ((_e218 < _e219) || (_e219 != _e219))) / _e190));
                    let _e229 = select(0f, select(1f, _e225, (_e225 < 1f)), (_e225 > 0f));
                    let _e231 = abs(_e185);
                    let _e232 = abs((_e185 - _e189));
                    let _e238 = (1.25f - (select(_e232, _e231, ((_e231 < _e232) || (_e232 != _e232))) / _e190));
                    let _e242 = select(0f, select(1f, _e238, (_e238 < 1f)), (_e238 > 0f));
                    let _e248 = round((select(0f, select(1f, _e203, (_e203 < 1f)), (_e203 > 0f)) * 2.9f));
                    let _e263 = round((select(0f, select(1f, _e216, (_e216 < 1f)), (_e216 > 0f)) * 2.9f));
                    let _e279 = round((select(0f, select(1f, _e229, (_e229 < 1f)), (_e229 > 0f)) * 2.9f));
                    let _e295 = round((select(0f, select(1f, _e242, (_e242 < 1f)), (_e242 > 0f)) * 2.9f));
                    let _e304 = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e248, (_e248 < 3f)), (_e248 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e263, (_e263 < 3f)), (_e263 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e279, (_e279 < 3f)), (_e279 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e295, (_e295 < 3f)), (_e295 > 0f))) + 8388608f)) - 1258291200u));
                    if _e105 {
                        let _e317 = params.member.member.member_1[0u];
                        let _e319 = ((((((f32(_e107) + 0.5f) / _e74) * 2f) - 1f) * _e317) * _e98);
                        let _e326 = params.member.member.member_1[1u];
                        let _e328 = ((((((f32(_e116) + 0.5f) / _e84) * -2f) + 1f) * _e326) * _e98);
                        let _e332 = normals.member[_e95];
                        let _e335 = f32(bitcast<i32>((_e332 & 255u)));
                        let _e339 = (select(_e335, (_e335 - 256f), (_e335 >= 128f)) * 0.007874016f);
                        let _e342 = select(-1f, _e339, ((_e339 > -1f) || false));
                        let _e347 = f32(bitcast<i32>(((_e332 >> bitcast<u32>(8u)) & 255u)));
                        let _e351 = (select(_e347, (_e347 - 256f), (_e347 >= 128f)) * 0.007874016f);
                        let _e354 = select(-1f, _e351, ((_e351 > -1f) || false));
                        let _e356 = (1f - abs(_e342));
                        let _e357 = abs(_e354);
                        let _e358 = (_e356 - _e357);
                        let _e359 = (_e358 < 0f);
                        let _e367 = select(_e342, ((1f - _e357) * select(1f, -1f, (_e342 < 0f))), _e359);
                        let _e368 = select(_e354, (_e356 * select(1f, -1f, (_e354 < 0f))), _e359);
                        let _e375 = (1f / sqrt((((_e367 * _e367) + (_e368 * _e368)) + (_e358 * _e358))));
                        let _e376 = (_e367 * _e375);
                        let _e377 = (_e368 * _e375);
                        let _e378 = (_e358 * _e375);
                        let _e379 = -(_e378);
                        if ((((_e376 * -(_e319)) + (_e377 * -(_e328))) + (_e379 * -(_e98))) < 0f) {
                            phi_734_ = vec3<f32>(-(_e376), -(_e377), _e378);
                        } else {
                            phi_734_ = vec3<f32>(_e376, _e377, _e379);
                        }
                        let _e394 = phi_734_;
                        let _e397 = params.member.member_8;
                        let _e398 = (_e61.x & 63u);
                        let _e399 = (_e61.y & 63u);
                        let _e402 = ((_e398 >> bitcast<u32>(5u)) & 1u);
                        let _e405 = ((_e399 >> bitcast<u32>(5u)) & 1u);
                        let _e409 = (_e405 ^ 1u);
                        let _e411 = ((_e402 & _e409) * 63u);
                        let _e412 = (_e398 ^ _e411);
                        let _e413 = (_e399 ^ _e411);
                        let _e415 = ((_e412 ^ _e413) * _e409);
                        let _e416 = (_e412 ^ _e415);
                        let _e417 = (_e413 ^ _e415);
                        let _e420 = ((_e416 >> bitcast<u32>(4u)) & 1u);
                        let _e423 = ((_e417 >> bitcast<u32>(4u)) & 1u);
                        let _e428 = (_e423 ^ 1u);
                        let _e430 = ((_e420 & _e428) * 63u);
                        let _e431 = (_e416 ^ _e430);
                        let _e432 = (_e417 ^ _e430);
                        let _e434 = ((_e431 ^ _e432) * _e428);
                        let _e435 = (_e431 ^ _e434);
                        let _e436 = (_e432 ^ _e434);
                        let _e439 = ((_e435 >> bitcast<u32>(3u)) & 1u);
                        let _e442 = ((_e436 >> bitcast<u32>(3u)) & 1u);
                        let _e447 = (_e442 ^ 1u);
                        let _e449 = ((_e439 & _e447) * 63u);
                        let _e450 = (_e435 ^ _e449);
                        let _e451 = (_e436 ^ _e449);
                        let _e453 = ((_e450 ^ _e451) * _e447);
                        let _e454 = (_e450 ^ _e453);
                        let _e455 = (_e451 ^ _e453);
                        let _e458 = ((_e454 >> bitcast<u32>(2u)) & 1u);
                        let _e461 = ((_e455 >> bitcast<u32>(2u)) & 1u);
                        let _e466 = (_e461 ^ 1u);
                        let _e468 = ((_e458 & _e466) * 63u);
                        let _e469 = (_e454 ^ _e468);
                        let _e470 = (_e455 ^ _e468);
                        let _e472 = ((_e469 ^ _e470) * _e466);
                        let _e473 = (_e469 ^ _e472);
                        let _e474 = (_e470 ^ _e472);
                        let _e477 = ((_e473 >> bitcast<u32>(1u)) & 1u);
                        let _e480 = ((_e474 >> bitcast<u32>(1u)) & 1u);
                        let _e485 = (_e480 ^ 1u);
                        let _e487 = ((_e477 & _e485) * 63u);
                        let _e488 = (_e473 ^ _e487);
                        let _e489 = (_e474 ^ _e487);
                        let _e491 = ((_e488 ^ _e489) * _e485);
                        let _e503 = f32(bitcast<i32>((((((((((_e402 * 3u) ^ _e405) * 1024u) + (((_e420 * 3u) ^ _e423) * 256u)) + (((_e439 * 3u) ^ _e442) * 64u)) + (((_e458 * 3u) ^ _e461) * 16u)) + (((_e477 * 3u) ^ _e480) * 4u)) + ((((_e488 ^ _e491) & 1u) * 3u) ^ ((_e489 ^ _e491) & 1u))) + (288u * (_e397 % 64u)))));
                        let _e505 = ((_e503 * 0.7548777f) + 0.5f);
                        let _e509 = ((_e503 * 0.5698403f) + 0.5f);
                        let _e512 = (6.2831855f * (_e505 - floor(_e505)));
                        phi_874_ = type_28(_e304, type_27(1u, type_26(vec2<u32>(_e61.x, _e61.y), vec3<f32>(_e319, _e328, _e98), _e394, sin(_e512), cos(_e512), (_e509 - floor(_e509)))));
                    } else {
                        phi_874_ = type_28(_e304, type_27(0u, type_27().member_1));
                    }
                    let _e524 = phi_874_;
                    if (bitcast<i32>(_e524.member_1.member) != 0i) {
                        let _e533 = params.member.member_5;
                        let _e535 = select(_e533, 64u, (64u < _e533));
                        let _e537 = select(_e535, _e63, (_e63 < _e535));
                        let _e539 = select(1u, _e537, (1u < _e537));
                        let _e542 = params.member.member_6;
                        let _e544 = select(1u, _e542, (1u < _e542));
                        phi_909_ = 0u;
                        phi_912_ = 0f;
                        loop {
                            let _e546 = phi_909_;
                            let _e548 = phi_912_;
                            local_10 = _e548;
                            let _e549 = (_e546 < _e539);
                            if _e549 {
                                if (_e546 < _e63) {
                                } else {
                                    phi_1801_ = true;
                                    break;
                                }
                                let _e554 = kernel.member[_e546][0u];
                                let _e558 = kernel.member[_e546][1u];
                                let _e563 = ((_e524.member_1.member_1.member_4 * _e554) - (_e524.member_1.member_1.member_3 * _e558));
                                let _e566 = ((_e524.member_1.member_1.member_3 * _e554) + (_e524.member_1.member_1.member_4 * _e558));
                                let _e571 = ((1f - (_e563 * _e563)) - (_e566 * _e566));
                                let _e575 = sqrt(select(0f, _e571, ((_e571 > 0f) || false)));
                                let _e576 = -(_e575);
                                let _e580 = (-1f * _e524.member_1.member_1.member_2.z);
                                let _e581 = (-1f * _e524.member_1.member_1.member_2.x);
                                let _e583 = (1f / (_e580 + 1f));
                                let _e584 = (_e583 * _e524.member_1.member_1.member_2.y);
                                let _e588 = (_e584 * _e581);
                                let _e608 = (_e580 > 0.9997f);
                                let _e609 = (_e580 < -0.9997f);
                                let _e619 = params.member.member_1;
                                let _e623 = params.member.member_3;
                                let _e626 = params.member.member_4;
                                phi_1064_ = 1u;
                                phi_1067_ = _e619;
                                phi_1069_ = false;
                                phi_1071_ = true;
                                phi_1073_ = 0f;
                                phi_1075_ = 0f;
                                loop {
                                    let _e632 = phi_1064_;
                                    let _e634 = phi_1067_;
                                    let _e636 = phi_1069_;
                                    let _e638 = phi_1071_;
                                    let _e640 = phi_1073_;
                                    let _e642 = phi_1075_;
                                    local_4 = _e634;
                                    local_6 = _e636;
                                    local_8 = _e634;
                                    local_9 = _e636;
                                    let _e643 = (_e632 <= _e544);
                                    if _e643 {
                                        let _e649 = (((-(_e524.member_1.member_1.member_5) + f32(_e632)) * _e619) / f32(_e544));
                                        let _e654 = (_e524.member_1.member_1.member_1.x + (select(select(((((_e580 + (_e584 * _e524.member_1.member_1.member_2.y)) * _e563) + (_e588 * _e566)) + (_e581 * _e576)), _e563, _e609), _e563, _e608) * _e649));
                                        let _e656 = (_e524.member_1.member_1.member_1.y + (select(select((((_e588 * _e563) + ((_e580 + ((_e583 * _e581) * _e581)) * _e566)) + (-(_e524.member_1.member_1.member_2.y) * _e576)), -(_e566), _e609), _e566, _e608) * _e649));
                                        let _e658 = (_e524.member_1.member_1.member_1.z + (select(select((((_e524.member_1.member_1.member_2.x * _e563) + (_e524.member_1.member_1.member_2.y * _e566)) + (_e580 * _e576)), _e575, _e609), _e576, _e608) * _e649));
                                        let _e664 = params.member.member.member_1[0u];
                                        let _e667 = (((_e654 * 0.5f) / (_e658 * _e664)) + 0.5f);
                                        let _e673 = params.member.member.member_1[1u];
                                        let _e676 = (0.5f - ((_e656 * 0.5f) / (_e658 * _e673)));
                                        let _e686 = select(false, select(false, select(false, select(false, (_e676 <= 1f), (_e676 >= 0f)), select(false, (_e667 <= 1f), (_e667 >= 0f))), (_e658 > 0f)), _e638);
                                        if _e686 {
                                            let _e687 = (_e667 * _e74);
                                            let _e690 = f32(bitcast<i32>((_e79 - 1u)));
                                            let _e699 = (_e676 * _e84);
                                            let _e702 = f32(bitcast<i32>((_e89 - 1u)));
                                            let _e715 = depth.member[(((bitcast<u32>((floor(select(0f, select(_e702, _e699, (_e699 < _e702)), (_e699 > 0f))) + 8388608f)) - 1258291200u) * _e79) + (bitcast<u32>((floor(select(0f, select(_e690, _e687, (_e687 < _e690)), (_e687 > 0f))) + 8388608f)) - 1258291200u))];
                                            let _e719 = select(_e102, _e715, select(false, (_e715 < _e102), (_e715 > 0f)));
                                            let _e722 = (((_e667 * 2f) - 1f) * _e664);
                                            let _e726 = (((_e676 * -2f) + 1f) * _e673);
                                            let _e728 = (_e654 - (_e722 * _e719));
                                            let _e729 = (_e656 - (_e726 * _e719));
                                            let _e730 = (_e658 - _e719);
                                            let _e736 = sqrt((((_e728 * _e728) + (_e729 * _e729)) + (_e730 * _e730)));
                                            let _e741 = (select(0f, select(1f, _e667, (_e667 < 1f)), (_e667 > 0f)) * _e74);
                                            let _e749 = (bitcast<u32>((floor(select(0f, select(_e690, _e741, (_e741 < _e690)), (_e741 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e754 = (select(0f, select(1f, _e676, (_e676 < 1f)), (_e676 > 0f)) * _e84);
                                            let _e762 = (bitcast<u32>((floor(select(0f, select(_e702, _e754, (_e754 < _e702)), (_e754 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e785 = normals.member[((_e762 * _e79) + _e749)];
                                            let _e788 = f32(bitcast<i32>((_e785 & 255u)));
                                            let _e792 = (select(_e788, (_e788 - 256f), (_e788 >= 128f)) * 0.007874016f);
                                            let _e795 = select(-1f, _e792, ((_e792 > -1f) || false));
                                            let _e800 = f32(bitcast<i32>(((_e785 >> bitcast<u32>(8u)) & 255u)));
                                            let _e804 = (select(_e800, (_e800 - 256f), (_e800 >= 128f)) * 0.007874016f);
                                            let _e807 = select(-1f, _e804, ((_e804 > -1f) || false));
                                            let _e809 = (1f - abs(_e795));
                                            let _e810 = abs(_e807);
                                            let _e811 = (_e809 - _e810);
                                            let _e812 = (_e811 < 0f);
                                            let _e820 = select(_e795, ((1f - _e810) * select(1f, -1f, (_e795 < 0f))), _e812);
                                            let _e821 = select(_e807, (_e809 * select(1f, -1f, (_e807 < 0f))), _e812);
                                            let _e828 = (1f / sqrt((((_e820 * _e820) + (_e821 * _e821)) + (_e811 * _e811))));
                                            let _e829 = (_e820 * _e828);
                                            let _e830 = (_e821 * _e828);
                                            let _e832 = -((_e811 * _e828));
                                            let _e836 = (((_e829 * _e722) + (_e830 * _e726)) + _e832);
                                            let _e845 = select(((((_e829 * ((((((f32(bitcast<i32>(_e749)) + 0.5f) * (1f / _e74)) * 2f) - 1f) * _e664) * _e719)) + (_e830 * ((((((f32(bitcast<i32>(_e762)) + 0.5f) * (1f / _e84)) * -2f) + 1f) * _e673) * _e719))) + (_e832 * _e719)) / _e836), _e719, (abs(_e836) < 0.001f));
                                            let _e855 = select(select(((_e658 - _e845) > _e626), true, (_e658 < (_e845 * (1f + _e623)))), true, select(false, (_e762 == _e524.member_1.member_1.member.y), (_e749 == _e524.member_1.member_1.member.x)));
                                            let _e857 = select(false, !(_e855), _e686);
                                            let _e858 = (_e640 + _e736);
                                            let _e867 = select(false, _e855, _e686);
                                            if _e867 {
                                                phi_1524_ = (_e632 + 1u);
                                            } else {
                                                phi_1524_ = u32();
                                            }
                                            let _e870 = phi_1524_;
                                            phi_1526_ = _e870;
                                            phi_1527_ = select(_e634, select((_e642 + ((_e640 * (_e649 - _e642)) / _e858)), _e642, (_e858 < 0.000001f)), _e857);
                                            phi_1528_ = select(_e857, true, _e636);
                                            phi_1529_ = _e867;
                                            phi_1530_ = _e736;
                                            phi_1533_ = _e867;
                                            phi_1534_ = select(true, false, _e867);
                                        } else {
                                            phi_1526_ = u32();
                                            phi_1527_ = f32();
                                            phi_1528_ = bool();
                                            phi_1529_ = bool();
                                            phi_1530_ = f32();
                                            phi_1533_ = false;
                                            phi_1534_ = false;
                                        }
                                        let _e873 = phi_1526_;
                                        let _e875 = phi_1527_;
                                        let _e877 = phi_1528_;
                                        let _e879 = phi_1529_;
                                        let _e881 = phi_1530_;
                                        let _e883 = phi_1533_;
                                        let _e885 = phi_1534_;
                                        phi_1065_ = _e873;
                                        phi_1068_ = _e875;
                                        phi_1070_ = _e877;
                                        phi_1072_ = _e879;
                                        phi_1074_ = _e881;
                                        phi_1076_ = _e649;
                                        phi_1538_ = _e883;
                                        phi_1540_ = _e885;
                                        phi_1541_ = select(true, false, _e686);
                                    } else {
                                        phi_1065_ = u32();
                                        phi_1068_ = f32();
                                        phi_1070_ = bool();
                                        phi_1072_ = bool();
                                        phi_1074_ = f32();
                                        phi_1076_ = f32();
                                        phi_1538_ = false;
                                        phi_1540_ = false;
                                        phi_1541_ = false;
                                    }
                                    let _e888 = phi_1065_;
                                    let _e890 = phi_1068_;
                                    let _e892 = phi_1070_;
                                    let _e894 = phi_1072_;
                                    let _e896 = phi_1074_;
                                    let _e898 = phi_1076_;
                                    let _e900 = phi_1538_;
                                    let _e902 = phi_1540_;
                                    let _e904 = phi_1541_;
                                    let _e905 = select(true, false, _e643);
                                    local = _e905;
                                    local_1 = _e902;
                                    local_2 = _e905;
                                    local_3 = _e904;
                                    local_5 = _e890;
                                    local_7 = _e892;
                                    continue;
                                    continuing {
                                        phi_1064_ = _e888;
                                        phi_1067_ = _e890;
                                        phi_1069_ = _e892;
                                        phi_1071_ = _e894;
                                        phi_1073_ = _e896;
                                        phi_1075_ = _e898;
                                        break if !(_e900);
                                    }
                                }
                                let _e908 = local;
                                let _e910 = local_1;
                                let _e911 = select(_e910, false, _e908);
                                let _e913 = local_2;
                                let _e915 = local_3;
                                let _e917 = select(select(_e915, false, _e913), false, _e911);
                                let _e919 = local_4;
                                let _e921 = local_5;
                                let _e924 = local_6;
                                let _e926 = local_7;
                                let _e928 = select(_e911, true, _e917);
                                let _e930 = local_8;
                                let _e933 = local_9;
                                let _e937 = params.member.member_7;
                                if (_e937 == 1u) {
                                    phi_1581_ = 0f;
                                } else {
                                    let _e939 = (select(_e930, select(_e921, _e919, _e917), _e928) / _e619);
                                    phi_1581_ = select(0f, select(1f, _e939, (_e939 < 1f)), (_e939 > 0f));
                                }
                                let _e945 = phi_1581_;
                                phi_910_ = (_e546 + 1u);
                                phi_913_ = (_e548 + select(1f, _e945, select(_e933, select(_e926, _e924, _e917), _e928)));
                            } else {
                                phi_910_ = u32();
                                phi_913_ = f32();
                            }
                            let _e950 = phi_910_;
                            let _e952 = phi_913_;
                            continue;
                            continuing {
                                phi_909_ = _e950;
                                phi_912_ = _e952;
                                phi_1801_ = false;
                                break if !(_e549);
                            }
                        }
                        let _e955 = phi_1801_;
                        if _e955 {
                            break;
                        }
                        let _e958 = local_10;
                        let _e962 = params.member.member_2;
                        let _e963 = pow((_e958 / f32(_e539)), _e962);
                        let _e964 = (_e963 * 0.6666667f);
                        phi_1646_ = type_29(_e963, (bitcast<u32>((floor(((select(0f, select(1f, _e964, (_e964 < 1f)), (_e964 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u), _e524.member);
                    } else {
                        phi_1646_ = type_29(1f, (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u), _e524.member);
                    }
                    let _e982 = phi_1646_;
                    if (_e95 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e95] = _e982.member;
                    if (_e95 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e95] = _e982.member_1;
                    if (_e95 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e95] = _e982.member_2;
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
