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

struct type_19 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: u32,
    member_12: u32,
    member_13: u32,
    member_14: u32,
}

struct type_20 {
    member: type_19,
}

struct type_22 {
    member: f32,
    member_1: vec3<f32>,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(4) 
var<uniform> params: type_20;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_266_: i32;
    var phi_285_: i32;
    var phi_325_: i32;
    var phi_344_: i32;
    var phi_384_: i32;
    var phi_403_: i32;
    var phi_443_: i32;
    var phi_462_: i32;
    var phi_1905_: f32;
    var phi_1909_: f32;
    var phi_1910_: bool;
    var phi_1948_: f32;
    var phi_1952_: f32;
    var phi_1953_: bool;
    var phi_1991_: f32;
    var phi_1995_: f32;
    var phi_1996_: bool;
    var phi_2034_: f32;
    var phi_2038_: f32;
    var phi_2039_: bool;
    var phi_2061_: bool;
    var phi_2076_: bool;
    var phi_679_: vec2<f32>;
    var phi_707_: vec3<f32>;
    var phi_728_: u32;
    var phi_731_: u32;
    var phi_733_: u32;
    var phi_735_: u32;
    var phi_764_: u32;
    var phi_765_: u32;
    var phi_766_: u32;
    var phi_767_: u32;
    var phi_729_: u32;
    var phi_732_: u32;
    var phi_734_: u32;
    var phi_736_: u32;
    var local: u32;
    var phi_2635_: bool;
    var phi_832_: u32;
    var phi_835_: vec3<f32>;
    var phi_837_: f32;
    var phi_1008_: u32;
    var phi_1011_: f32;
    var phi_1013_: f32;
    var phi_1067_: f32;
    var phi_1112_: f32;
    var phi_1114_: f32;
    var phi_1115_: bool;
    var phi_1138_: f32;
    var phi_1140_: f32;
    var phi_1141_: bool;
    var phi_2108_: u32;
    var phi_2156_: u32;
    var phi_2176_: u32;
    var phi_2178_: u32;
    var phi_2179_: u32;
    var phi_2202_: u32;
    var phi_2203_: u32;
    var local_1: u32;
    var phi_2230_: u32;
    var phi_2278_: u32;
    var phi_2298_: u32;
    var phi_2300_: u32;
    var phi_2301_: u32;
    var phi_2324_: u32;
    var phi_2325_: u32;
    var local_2: u32;
    var phi_1279_: f32;
    var phi_1339_: f32;
    var phi_2341_: bool;
    var phi_2356_: bool;
    var phi_1009_: u32;
    var phi_1012_: f32;
    var phi_1014_: f32;
    var phi_2581_: bool;
    var local_3: f32;
    var local_4: f32;
    var local_5: f32;
    var local_6: f32;
    var phi_1558_: vec3<f32>;
    var phi_2703_: bool;
    var phi_833_: u32;
    var phi_836_: vec3<f32>;
    var phi_838_: f32;
    var phi_2702_: bool;
    var local_7: f32;
    var local_8: vec3<f32>;
    var phi_1564_: type_22;
    var phi_2383_: bool;
    var phi_1619_: vec3<f32>;
    var phi_1640_: u32;
    var phi_1685_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e84 = id_1;
            let _e86 = arrayLength((&mips.member));
            let _e97 = params.member.member.member[0u];
            let _e102 = select(select(u32(_e97), 0u, (_e97 < 0f)), 4294967295u, (_e97 > 4294967000f));
            let _e107 = params.member.member.member[1u];
            let _e112 = select(select(u32(_e107), 0u, (_e107 < 0f)), 4294967295u, (_e107 > 4294967000f));
            if (_e84.x >= _e102) {
            } else {
                if (_e84.y >= _e112) {
                } else {
                    let _e118 = ((_e84.y * _e102) + _e84.x);
                    if (_e118 < _e86) {
                    } else {
                        break;
                    }
                    let _e122 = mips.member[_e118];
                    let _e123 = bitcast<i32>(_e84.x);
                    let _e124 = (_e123 + -1i);
                    let _e126 = (bitcast<i32>(_e102) - 1i);
                    let _e127 = (0i <= _e126);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e124 < 0i) {
                        phi_266_ = 0i;
                    } else {
                        phi_266_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_266_;
                    let _e134 = bitcast<i32>(_e84.y);
                    let _e136 = (bitcast<i32>(_e112) - 1i);
                    let _e137 = (0i <= _e136);
                    if _e137 {
                    } else {
                        break;
                    }
                    let _e138 = (_e134 < 0i);
                    if _e138 {
                        phi_285_ = 0i;
                    } else {
                        phi_285_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e142 = phi_285_;
                    let _e145 = ((bitcast<u32>(_e142) * _e102) + bitcast<u32>(_e132));
                    if (_e145 < _e86) {
                    } else {
                        break;
                    }
                    let _e149 = mips.member[_e145];
                    let _e150 = (_e123 + 1i);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e150 < 0i) {
                        phi_325_ = 0i;
                    } else {
                        phi_325_ = select(_e150, _e126, (_e150 > _e126));
                    }
                    let _e155 = phi_325_;
                    if _e137 {
                    } else {
                        break;
                    }
                    if _e138 {
                        phi_344_ = 0i;
                    } else {
                        phi_344_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e160 = phi_344_;
                    let _e163 = ((bitcast<u32>(_e160) * _e102) + bitcast<u32>(_e155));
                    if (_e163 < _e86) {
                    } else {
                        break;
                    }
                    let _e167 = mips.member[_e163];
                    if _e127 {
                    } else {
                        break;
                    }
                    let _e168 = (_e123 < 0i);
                    if _e168 {
                        phi_384_ = 0i;
                    } else {
                        phi_384_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e172 = phi_384_;
                    let _e174 = (_e134 + -1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e174 < 0i) {
                        phi_403_ = 0i;
                    } else {
                        phi_403_ = select(_e174, _e136, (_e174 > _e136));
                    }
                    let _e179 = phi_403_;
                    let _e182 = ((bitcast<u32>(_e179) * _e102) + bitcast<u32>(_e172));
                    if (_e182 < _e86) {
                    } else {
                        break;
                    }
                    let _e186 = mips.member[_e182];
                    if _e127 {
                    } else {
                        break;
                    }
                    if _e168 {
                        phi_443_ = 0i;
                    } else {
                        phi_443_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e190 = phi_443_;
                    let _e192 = (_e134 + 1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e192 < 0i) {
                        phi_462_ = 0i;
                    } else {
                        phi_462_ = select(_e192, _e136, (_e192 > _e136));
                    }
                    let _e197 = phi_462_;
                    let _e200 = ((bitcast<u32>(_e197) * _e102) + bitcast<u32>(_e190));
                    if (_e200 < _e86) {
                    } else {
                        break;
                    }
                    let _e204 = mips.member[_e200];
                    let _e205 = (_e149 - _e122);
                    let _e206 = (_e167 - _e122);
                    let _e207 = (_e186 - _e122);
                    let _e208 = (_e204 - _e122);
                    let _e209 = (_e206 - _e205);
                    let _e211 = (_e208 - _e207);
                    let _e219 = abs(_e205);
                    let _e220 = abs(_e206);
                    let _e221 = abs(_e207);
                    let _e222 = abs(_e208);
                    let _e223 = abs((_e205 + (_e209 * 0.5f)));
                    let _e224 = abs((_e206 + (_e209 * -0.5f)));
                    let _e225 = abs((_e207 + (_e211 * 0.5f)));
                    let _e226 = abs((_e208 + (_e211 * -0.5f)));
                    let _e235 = (_e122 * 0.011f);
                    let _e240 = (1.25f - (select(_e223, _e219, (_e219 < _e223)) / _e235));
                    let _e244 = select(0f, select(1f, _e240, (_e240 < 1f)), (_e240 > 0f));
                    let _e245 = (1.25f - (select(_e224, _e220, (_e220 < _e224)) / _e235));
                    let _e249 = select(0f, select(1f, _e245, (_e245 < 1f)), (_e245 > 0f));
                    let _e250 = (1.25f - (select(_e225, _e221, (_e221 < _e225)) / _e235));
                    let _e254 = select(0f, select(1f, _e250, (_e250 < 1f)), (_e250 > 0f));
                    let _e255 = (1.25f - (select(_e226, _e222, (_e222 < _e226)) / _e235));
                    let _e259 = select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f));
                    let _e264 = (select(0f, select(1f, _e244, (_e244 < 1f)), (_e244 > 0f)) * 2.9f);
                    let _e266 = floor((_e264 + 0.5f));
                    if ((_e266 - _e264) == 0.5f) {
                        let _e272 = ((floor((_e266 * 0.5f)) * 2f) != _e266);
                        if _e272 {
                            phi_1905_ = (_e266 - 1f);
                        } else {
                            phi_1905_ = f32();
                        }
                        let _e275 = phi_1905_;
                        phi_1909_ = _e275;
                        phi_1910_ = select(true, false, _e272);
                    } else {
                        phi_1909_ = f32();
                        phi_1910_ = true;
                    }
                    let _e278 = phi_1909_;
                    let _e280 = phi_1910_;
                    let _e281 = select(_e278, _e266, _e280);
                    let _e292 = (select(0f, select(1f, _e249, (_e249 < 1f)), (_e249 > 0f)) * 2.9f);
                    let _e294 = floor((_e292 + 0.5f));
                    if ((_e294 - _e292) == 0.5f) {
                        let _e300 = ((floor((_e294 * 0.5f)) * 2f) != _e294);
                        if _e300 {
                            phi_1948_ = (_e294 - 1f);
                        } else {
                            phi_1948_ = f32();
                        }
                        let _e303 = phi_1948_;
                        phi_1952_ = _e303;
                        phi_1953_ = select(true, false, _e300);
                    } else {
                        phi_1952_ = f32();
                        phi_1953_ = true;
                    }
                    let _e306 = phi_1952_;
                    let _e308 = phi_1953_;
                    let _e309 = select(_e306, _e294, _e308);
                    let _e321 = (select(0f, select(1f, _e254, (_e254 < 1f)), (_e254 > 0f)) * 2.9f);
                    let _e323 = floor((_e321 + 0.5f));
                    if ((_e323 - _e321) == 0.5f) {
                        let _e329 = ((floor((_e323 * 0.5f)) * 2f) != _e323);
                        if _e329 {
                            phi_1991_ = (_e323 - 1f);
                        } else {
                            phi_1991_ = f32();
                        }
                        let _e332 = phi_1991_;
                        phi_1995_ = _e332;
                        phi_1996_ = select(true, false, _e329);
                    } else {
                        phi_1995_ = f32();
                        phi_1996_ = true;
                    }
                    let _e335 = phi_1995_;
                    let _e337 = phi_1996_;
                    let _e338 = select(_e335, _e323, _e337);
                    let _e350 = (select(0f, select(1f, _e259, (_e259 < 1f)), (_e259 > 0f)) * 2.9f);
                    let _e352 = floor((_e350 + 0.5f));
                    if ((_e352 - _e350) == 0.5f) {
                        let _e358 = ((floor((_e352 * 0.5f)) * 2f) != _e352);
                        if _e358 {
                            phi_2034_ = (_e352 - 1f);
                        } else {
                            phi_2034_ = f32();
                        }
                        let _e361 = phi_2034_;
                        phi_2038_ = _e361;
                        phi_2039_ = select(true, false, _e358);
                    } else {
                        phi_2038_ = f32();
                        phi_2039_ = true;
                    }
                    let _e364 = phi_2038_;
                    let _e366 = phi_2039_;
                    let _e367 = select(_e364, _e352, _e366);
                    let _e378 = ((f32(_e84.x) + 0.5f) / _e97);
                    let _e379 = ((f32(_e84.y) + 0.5f) / _e107);
                    let _e380 = (_e122 * 0.99999f);
                    let _e387 = params.member.member.member_1[0u];
                    let _e389 = ((((_e378 * 2f) - 1f) * _e387) * _e380);
                    let _e396 = params.member.member.member_1[1u];
                    let _e398 = ((((_e379 * -2f) + 1f) * _e396) * _e380);
                    let _e399 = -(_e389);
                    let _e400 = -(_e398);
                    let _e401 = (_e122 * -0.99999f);
                    let _e408 = (1f / sqrt((((_e399 * _e399) + (_e400 * _e400)) + (_e401 * _e401))));
                    let _e409 = (_e399 * _e408);
                    let _e410 = (_e400 * _e408);
                    let _e411 = (_e401 * _e408);
                    if (_e118 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e415 = normals.member[_e118];
                    let _e423 = (f32((bitcast<i32>(((_e415 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e423 != _e423) {
                        phi_2061_ = true;
                    } else {
                        phi_2061_ = (-1f >= _e423);
                    }
                    let _e427 = phi_2061_;
                    let _e428 = select(_e423, -1f, _e427);
                    let _e438 = (f32((bitcast<i32>((((_e415 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e438 != _e438) {
                        phi_2076_ = true;
                    } else {
                        phi_2076_ = (-1f >= _e438);
                    }
                    let _e442 = phi_2076_;
                    let _e443 = select(_e438, -1f, _e442);
                    let _e446 = (1f - abs(_e428));
                    let _e447 = abs(_e443);
                    let _e448 = (_e446 - _e447);
                    if (_e448 < 0f) {
                        phi_679_ = vec2<f32>(((1f - _e447) * select(1f, -1f, (_e428 < 0f))), (_e446 * select(1f, -1f, (_e443 < 0f))));
                    } else {
                        phi_679_ = vec2<f32>(_e428, _e443);
                    }
                    let _e459 = phi_679_;
                    let _e468 = (1f / sqrt((((_e459.x * _e459.x) + (_e459.y * _e459.y)) + (_e448 * _e448))));
                    let _e469 = (_e459.x * _e468);
                    let _e470 = (_e459.y * _e468);
                    let _e471 = (_e448 * _e468);
                    let _e472 = -(_e471);
                    if ((((_e469 * _e409) + (_e470 * _e410)) + (_e472 * _e411)) < 0f) {
                        phi_707_ = vec3<f32>(-(_e469), -(_e470), _e471);
                    } else {
                        phi_707_ = vec3<f32>(_e469, _e470, _e472);
                    }
                    let _e484 = phi_707_;
                    let _e487 = params.member.member_1;
                    let _e490 = params.member.member_2;
                    let _e491 = (_e487 * _e490);
                    let _e495 = (_e491 / (((_e122 * 1.99998f) * _e387) / _e97));
                    let _e499 = params.member.member_11;
                    phi_728_ = (_e84.y & 63u);
                    phi_731_ = (_e84.x & 63u);
                    phi_733_ = 32u;
                    phi_735_ = 0u;
                    loop {
                        let _e503 = phi_728_;
                        let _e505 = phi_731_;
                        let _e507 = phi_733_;
                        let _e509 = phi_735_;
                        local = _e509;
                        let _e510 = (_e507 > 0u);
                        if _e510 {
                            let _e513 = select(0u, 1u, ((_e505 & _e507) != 0u));
                            let _e516 = select(0u, 1u, ((_e503 & _e507) != 0u));
                            if (_e516 == 0u) {
                                if (_e513 == 1u) {
                                    phi_764_ = (63u - _e503);
                                    phi_765_ = (63u - _e505);
                                } else {
                                    phi_764_ = _e503;
                                    phi_765_ = _e505;
                                }
                                let _e527 = phi_764_;
                                let _e529 = phi_765_;
                                phi_766_ = _e529;
                                phi_767_ = _e527;
                            } else {
                                phi_766_ = _e503;
                                phi_767_ = _e505;
                            }
                            let _e531 = phi_766_;
                            let _e533 = phi_767_;
                            phi_729_ = _e531;
                            phi_732_ = _e533;
                            phi_734_ = (_e507 / 2u);
                            phi_736_ = (_e509 + ((_e507 * _e507) * ((3u * _e513) ^ _e516)));
                        } else {
                            phi_729_ = u32();
                            phi_732_ = u32();
                            phi_734_ = u32();
                            phi_736_ = u32();
                        }
                        let _e536 = phi_729_;
                        let _e538 = phi_732_;
                        let _e540 = phi_734_;
                        let _e542 = phi_736_;
                        continue;
                        continuing {
                            phi_728_ = _e536;
                            phi_731_ = _e538;
                            phi_733_ = _e540;
                            phi_735_ = _e542;
                            break if !(_e510);
                        }
                    }
                    let _e547 = local;
                    let _e549 = f32((_e547 + (288u * (_e499 % 64u))));
                    let _e551 = (0.5f + (_e549 * 0.7548777f));
                    let _e555 = (0.5f + (_e549 * 0.5698403f));
                    let _e561 = params.member.member.member_3;
                    let _e564 = select(false, (_e122 < _e561), (_e122 > 0f));
                    if _e564 {
                        let _e567 = params.member.member_3;
                        let _e568 = (_e567 * _e491);
                        let _e570 = ((10f - _e495) * 0.01f);
                        let _e578 = params.member.member_8;
                        let _e580 = select(1u, _e578, (1u < _e578));
                        phi_2635_ = false;
                        phi_832_ = 0u;
                        phi_835_ = vec3<f32>(0f, 0f, 0f);
                        phi_837_ = (select(0f, select(1f, _e570, (_e570 < 1f)), (_e570 > 0f)) * 0.5f);
                        loop {
                            let _e582 = phi_2635_;
                            let _e584 = phi_832_;
                            let _e586 = phi_835_;
                            let _e588 = phi_837_;
                            local_7 = _e588;
                            local_8 = _e586;
                            let _e589 = (_e584 < _e580);
                            if _e589 {
                                let _e594 = ((((_e551 - floor(_e551)) + f32(_e584)) * 3.1415927f) / f32(_e580));
                                let _e595 = sin(_e594);
                                let _e596 = cos(_e594);
                                let _e602 = ((_e596 * _e409) + (_e595 * _e410));
                                let _e606 = (_e596 - (_e409 * _e602));
                                let _e607 = (_e595 - (_e410 * _e602));
                                let _e608 = -((_e411 * _e602));
                                let _e611 = ((_e607 * _e411) - (_e410 * _e608));
                                let _e614 = ((_e608 * _e409) - (_e411 * _e606));
                                let _e617 = ((_e606 * _e410) - (_e409 * _e607));
                                let _e624 = (1f / sqrt((((_e611 * _e611) + (_e614 * _e614)) + (_e617 * _e617))));
                                let _e625 = (_e611 * _e624);
                                let _e626 = (_e614 * _e624);
                                let _e627 = (_e617 * _e624);
                                let _e635 = (((_e484.x * _e625) + (_e484.y * _e626)) + (_e484.z * _e627));
                                let _e639 = (_e484.x - (_e625 * _e635));
                                let _e640 = (_e484.y - (_e626 * _e635));
                                let _e641 = (_e484.z - (_e627 * _e635));
                                let _e647 = sqrt((((_e639 * _e639) + (_e640 * _e640)) + (_e641 * _e641)));
                                let _e652 = (((_e606 * _e639) + (_e607 * _e640)) + (_e608 * _e641));
                                let _e662 = ((((_e639 * _e409) + (_e640 * _e410)) + (_e641 * _e411)) / _e647);
                                let _e666 = select(0f, select(1f, _e662, (_e662 < 1f)), (_e662 > 0f));
                                let _e667 = abs(_e666);
                                let _e678 = (((_e667 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e667))) >> bitcast<u32>(1i))))));
                                let _e682 = (select(select(0f, -1f, (_e652 < 0f)), 1f, (_e652 > 0f)) * select((3.141593f - _e678), _e678, (_e666 >= 0f)));
                                let _e685 = params.member.member_9;
                                let _e687 = select(1u, _e685, (1u < _e685));
                                let _e689 = cos((_e682 + 1.5707964f));
                                let _e691 = cos((_e682 - 1.5707964f));
                                let _e694 = params.member.member_5;
                                phi_1008_ = 0u;
                                phi_1011_ = _e691;
                                phi_1013_ = _e689;
                                loop {
                                    let _e696 = phi_1008_;
                                    let _e698 = phi_1011_;
                                    let _e700 = phi_1013_;
                                    local_3 = _e698;
                                    local_4 = _e698;
                                    local_5 = _e700;
                                    local_6 = _e700;
                                    let _e701 = (_e696 < _e687);
                                    if _e701 {
                                        let _e706 = ((_e555 - floor(_e555)) + (f32((_e584 + (_e696 * _e687))) * 0.618034f));
                                        let _e712 = (((_e706 - floor(_e706)) + f32(_e696)) / f32(_e687));
                                        let _e715 = params.member.member_4;
                                        if (_e715 == 2f) {
                                            phi_1067_ = (_e712 * _e712);
                                        } else {
                                            phi_1067_ = pow(_e712, _e715);
                                        }
                                        let _e720 = phi_1067_;
                                        let _e721 = (_e720 + (1.3f / _e495));
                                        let _e722 = ((_e596 * _e495) * _e721);
                                        let _e723 = ((-(_e595) * _e495) * _e721);
                                        let _e731 = params.member.member_7;
                                        let _e732 = (log2(sqrt(((_e722 * _e722) + (_e723 * _e723)))) - _e731);
                                        let _e739 = (-1f - floor((-0.5f - select(0f, select(5f, _e732, (_e732 < 5f)), (_e732 > 0f)))));
                                        let _e741 = floor((_e722 + 0.5f));
                                        if ((_e741 - _e722) == 0.5f) {
                                            let _e747 = ((floor((_e741 * 0.5f)) * 2f) != _e741);
                                            if _e747 {
                                                phi_1112_ = (_e741 - 1f);
                                            } else {
                                                phi_1112_ = f32();
                                            }
                                            let _e750 = phi_1112_;
                                            phi_1114_ = _e750;
                                            phi_1115_ = select(true, false, _e747);
                                        } else {
                                            phi_1114_ = f32();
                                            phi_1115_ = true;
                                        }
                                        let _e753 = phi_1114_;
                                        let _e755 = phi_1115_;
                                        let _e757 = (select(_e753, _e741, _e755) / _e97);
                                        let _e759 = floor((_e723 + 0.5f));
                                        if ((_e759 - _e723) == 0.5f) {
                                            let _e765 = ((floor((_e759 * 0.5f)) * 2f) != _e759);
                                            if _e765 {
                                                phi_1138_ = (_e759 - 1f);
                                            } else {
                                                phi_1138_ = f32();
                                            }
                                            let _e768 = phi_1138_;
                                            phi_1140_ = _e768;
                                            phi_1141_ = select(true, false, _e765);
                                        } else {
                                            phi_1140_ = f32();
                                            phi_1141_ = true;
                                        }
                                        let _e771 = phi_1140_;
                                        let _e773 = phi_1141_;
                                        let _e775 = (select(_e771, _e759, _e773) / _e107);
                                        let _e776 = (_e378 + _e757);
                                        let _e777 = (_e379 + _e775);
                                        let _e778 = (_e378 - _e757);
                                        let _e779 = (_e379 - _e775);
                                        let _e780 = (_e739 > 0f);
                                        if _e780 {
                                            let _e785 = select(select(u32(_e739), 0u, (_e739 < 0f)), 4294967295u, (_e739 > 4294967000f));
                                            phi_2108_ = select(_e785, 4u, (4u < _e785));
                                        } else {
                                            phi_2108_ = 0u;
                                        }
                                        let _e789 = phi_2108_;
                                        let _e790 = (_e789 & 31u);
                                        let _e792 = (_e102 >> bitcast<u32>(_e790));
                                        let _e794 = select(1u, _e792, (1u < _e792));
                                        let _e796 = (_e112 >> bitcast<u32>(_e790));
                                        let _e798 = select(1u, _e796, (1u < _e796));
                                        let _e800 = (_e776 * f32(_e794));
                                        if (_e800 > 0f) {
                                            let _e806 = select(select(u32(_e800), 0u, (_e800 < 0f)), 4294967295u, (_e800 > 4294967000f));
                                            let _e807 = (_e794 - 1u);
                                            phi_2156_ = select(_e806, _e807, (_e807 < _e806));
                                        } else {
                                            phi_2156_ = 0u;
                                        }
                                        let _e811 = phi_2156_;
                                        let _e813 = (_e777 * f32(_e798));
                                        if (_e813 > 0f) {
                                            let _e819 = select(select(u32(_e813), 0u, (_e813 < 0f)), 4294967295u, (_e813 > 4294967000f));
                                            let _e820 = (_e798 - 1u);
                                            phi_2176_ = select(_e819, _e820, (_e820 < _e819));
                                        } else {
                                            phi_2176_ = 0u;
                                        }
                                        let _e824 = phi_2176_;
                                        phi_2178_ = 0u;
                                        phi_2179_ = 0u;
                                        loop {
                                            let _e826 = phi_2178_;
                                            let _e828 = phi_2179_;
                                            local_1 = _e828;
                                            let _e829 = (_e826 < _e789);
                                            if _e829 {
                                                let _e830 = (_e826 & 31u);
                                                let _e832 = (_e102 >> bitcast<u32>(_e830));
                                                let _e836 = (_e112 >> bitcast<u32>(_e830));
                                                phi_2202_ = (_e826 + 1u);
                                                phi_2203_ = (_e828 + (select(1u, _e832, (1u < _e832)) * select(1u, _e836, (1u < _e836))));
                                            } else {
                                                phi_2202_ = u32();
                                                phi_2203_ = u32();
                                            }
                                            let _e843 = phi_2202_;
                                            let _e845 = phi_2203_;
                                            continue;
                                            continuing {
                                                phi_2178_ = _e843;
                                                phi_2179_ = _e845;
                                                break if !(_e829);
                                            }
                                        }
                                        let _e850 = local_1;
                                        let _e851 = (_e850 + ((_e824 * _e794) + _e811));
                                        if (_e851 < _e86) {
                                        } else {
                                            phi_2581_ = true;
                                            break;
                                        }
                                        let _e855 = mips.member[_e851];
                                        if _e780 {
                                            let _e868 = select(select(u32(_e739), 0u, (_e739 < 0f)), 4294967295u, (_e739 > 4294967000f));
                                            phi_2230_ = select(_e868, 4u, (4u < _e868));
                                        } else {
                                            phi_2230_ = 0u;
                                        }
                                        let _e872 = phi_2230_;
                                        let _e873 = (_e872 & 31u);
                                        let _e875 = (_e102 >> bitcast<u32>(_e873));
                                        let _e877 = select(1u, _e875, (1u < _e875));
                                        let _e879 = (_e112 >> bitcast<u32>(_e873));
                                        let _e881 = select(1u, _e879, (1u < _e879));
                                        let _e883 = (_e778 * f32(_e877));
                                        if (_e883 > 0f) {
                                            let _e889 = select(select(u32(_e883), 0u, (_e883 < 0f)), 4294967295u, (_e883 > 4294967000f));
                                            let _e890 = (_e877 - 1u);
                                            phi_2278_ = select(_e889, _e890, (_e890 < _e889));
                                        } else {
                                            phi_2278_ = 0u;
                                        }
                                        let _e894 = phi_2278_;
                                        let _e896 = (_e779 * f32(_e881));
                                        if (_e896 > 0f) {
                                            let _e902 = select(select(u32(_e896), 0u, (_e896 < 0f)), 4294967295u, (_e896 > 4294967000f));
                                            let _e903 = (_e881 - 1u);
                                            phi_2298_ = select(_e902, _e903, (_e903 < _e902));
                                        } else {
                                            phi_2298_ = 0u;
                                        }
                                        let _e907 = phi_2298_;
                                        phi_2300_ = 0u;
                                        phi_2301_ = 0u;
                                        loop {
                                            let _e909 = phi_2300_;
                                            let _e911 = phi_2301_;
                                            local_2 = _e911;
                                            let _e912 = (_e909 < _e872);
                                            if _e912 {
                                                let _e913 = (_e909 & 31u);
                                                let _e915 = (_e102 >> bitcast<u32>(_e913));
                                                let _e919 = (_e112 >> bitcast<u32>(_e913));
                                                phi_2324_ = (_e909 + 1u);
                                                phi_2325_ = (_e911 + (select(1u, _e915, (1u < _e915)) * select(1u, _e919, (1u < _e919))));
                                            } else {
                                                phi_2324_ = u32();
                                                phi_2325_ = u32();
                                            }
                                            let _e926 = phi_2324_;
                                            let _e928 = phi_2325_;
                                            continue;
                                            continuing {
                                                phi_2300_ = _e926;
                                                phi_2301_ = _e928;
                                                break if !(_e912);
                                            }
                                        }
                                        let _e933 = local_2;
                                        let _e934 = (_e933 + ((_e907 * _e877) + _e894));
                                        if (_e934 < _e86) {
                                        } else {
                                            phi_2581_ = true;
                                            break;
                                        }
                                        let _e938 = mips.member[_e934];
                                        let _e947 = (((((_e776 * 2f) - 1f) * _e387) * _e855) - _e389);
                                        let _e948 = (((((_e777 * -2f) + 1f) * _e396) * _e855) - _e398);
                                        let _e949 = (_e855 - _e380);
                                        let _e952 = ((_e947 * _e947) + (_e948 * _e948));
                                        let _e955 = sqrt((_e952 + (_e949 * _e949)));
                                        let _e964 = (1f + _e694);
                                        let _e965 = (_e949 * _e964);
                                        let _e968 = sqrt((_e952 + (_e965 * _e965)));
                                        let _e969 = (_e568 > 0f);
                                        if _e969 {
                                            let _e972 = ((-(_e968) + _e491) / _e568);
                                            phi_1279_ = select(0f, select(1f, _e972, (_e972 < 1f)), (_e972 > 0f));
                                        } else {
                                            phi_1279_ = select(0f, 1f, (_e968 <= _e491));
                                        }
                                        let _e980 = phi_1279_;
                                        let _e983 = (_e689 + ((((((_e947 / _e955) * _e409) + ((_e948 / _e955) * _e410)) + ((_e949 / _e955) * _e411)) - _e689) * _e980));
                                        let _e984 = (((((_e778 * 2f) - 1f) * _e387) * _e938) - _e389);
                                        let _e985 = (((((_e779 * -2f) + 1f) * _e396) * _e938) - _e398);
                                        let _e986 = (_e938 - _e380);
                                        let _e989 = ((_e984 * _e984) + (_e985 * _e985));
                                        let _e992 = sqrt((_e989 + (_e986 * _e986)));
                                        let _e1001 = (_e986 * _e964);
                                        let _e1004 = sqrt((_e989 + (_e1001 * _e1001)));
                                        if _e969 {
                                            let _e1007 = ((-(_e1004) + _e491) / _e568);
                                            phi_1339_ = select(0f, select(1f, _e1007, (_e1007 < 1f)), (_e1007 > 0f));
                                        } else {
                                            phi_1339_ = select(0f, 1f, (_e1004 <= _e491));
                                        }
                                        let _e1015 = phi_1339_;
                                        let _e1018 = (_e691 + ((((((_e984 / _e992) * _e409) + ((_e985 / _e992) * _e410)) + ((_e986 / _e992) * _e411)) - _e691) * _e1015));
                                        if (_e700 != _e700) {
                                            phi_2341_ = true;
                                        } else {
                                            phi_2341_ = (_e983 >= _e700);
                                        }
                                        let _e1022 = phi_2341_;
                                        if (_e698 != _e698) {
                                            phi_2356_ = true;
                                        } else {
                                            phi_2356_ = (_e1018 >= _e698);
                                        }
                                        let _e1027 = phi_2356_;
                                        phi_1009_ = (_e696 + 1u);
                                        phi_1012_ = select(_e698, _e1018, _e1027);
                                        phi_1014_ = select(_e700, _e983, _e1022);
                                    } else {
                                        phi_1009_ = u32();
                                        phi_1012_ = f32();
                                        phi_1014_ = f32();
                                    }
                                    let _e1031 = phi_1009_;
                                    let _e1033 = phi_1012_;
                                    let _e1035 = phi_1014_;
                                    continue;
                                    continuing {
                                        phi_1008_ = _e1031;
                                        phi_1011_ = _e1033;
                                        phi_1013_ = _e1035;
                                        phi_2581_ = _e582;
                                        break if !(_e701);
                                    }
                                }
                                let _e1038 = phi_2581_;
                                phi_2702_ = _e1038;
                                if _e1038 {
                                    break;
                                }
                                let _e1040 = local_3;
                                let _e1041 = abs(_e1040);
                                let _e1052 = (((_e1041 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1041))) >> bitcast<u32>(1i))))));
                                let _e1054 = local_4;
                                let _e1057 = select((3.141593f - _e1052), _e1052, (_e1054 >= 0f));
                                let _e1058 = -(_e1057);
                                let _e1060 = local_5;
                                let _e1061 = abs(_e1060);
                                let _e1072 = (((_e1061 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1061))) >> bitcast<u32>(1i))))));
                                let _e1074 = local_6;
                                let _e1077 = select((3.141593f - _e1072), _e1072, (_e1074 >= 0f));
                                let _e1080 = (_e647 + ((1f - _e647) * 0.05f));
                                let _e1081 = (_e1057 * -2f);
                                let _e1082 = sin(_e682);
                                let _e1088 = (_e1077 * 2f);
                                let _e1100 = params.member.member_13;
                                if (_e1100 == 0u) {
                                    phi_1558_ = _e586;
                                } else {
                                    let _e1106 = ((_e1057 * -3f) - _e682);
                                    let _e1114 = ((_e1077 * 3f) - _e682);
                                    let _e1119 = (_e1058 + _e682);
                                    let _e1121 = (_e1077 + _e682);
                                    let _e1126 = (((((((sin((_e1058 - _e682)) * 6f) - sin(_e1106)) + (sin((_e1077 - _e682)) * 6f)) - sin(_e1114)) + (_e1082 * 16f)) - ((sin(_e1119) + sin(_e1121)) * 3f)) * 0.083333336f);
                                    let _e1138 = (((-(cos(_e1106)) - cos(_e1114)) + (cos(_e682) * 8f)) - ((cos(_e1119) + cos(_e1121)) * 3f));
                                    let _e1139 = (_e596 * _e1126);
                                    let _e1140 = (_e595 * _e1126);
                                    let _e1141 = (_e1138 * -0.083333336f);
                                    let _e1142 = (-1f * _e411);
                                    let _e1143 = (-1f * _e409);
                                    let _e1145 = (1f / (_e1142 + 1f));
                                    let _e1146 = (_e1145 * _e410);
                                    let _e1150 = (_e1146 * _e1143);
                                    let _e1171 = (_e1142 > 0.9997f);
                                    let _e1172 = (_e1142 < -0.9997f);
                                    phi_1558_ = (_e586 + vec3<f32>((select(select(((((_e1142 + (_e1146 * _e410)) * _e1139) + (_e1150 * _e1140)) + (_e1143 * _e1141)), _e1139, _e1172), _e1139, _e1171) * _e1080), (select(select((((_e1150 * _e1139) + ((_e1142 + ((_e1145 * _e1143) * _e1143)) * _e1140)) + (-(_e410) * _e1141)), -(_e1140), _e1172), _e1140, _e1171) * _e1080), (select(select((((_e409 * _e1139) + (_e410 * _e1140)) + (_e1142 * _e1141)), (_e1138 * 0.083333336f), _e1172), _e1141, _e1171) * _e1080)));
                                }
                                let _e1185 = phi_1558_;
                                phi_2703_ = _e1038;
                                phi_833_ = (_e584 + 1u);
                                phi_836_ = _e1185;
                                phi_838_ = (_e588 + ((0.25f * (((_e666 + (_e1081 * _e1082)) - cos((_e1081 - _e682))) + ((_e666 + (_e1088 * _e1082)) - cos((_e1088 - _e682))))) * _e1080));
                            } else {
                                phi_2703_ = _e582;
                                phi_833_ = u32();
                                phi_836_ = vec3<f32>();
                                phi_838_ = f32();
                            }
                            let _e1188 = phi_2703_;
                            let _e1190 = phi_833_;
                            let _e1192 = phi_836_;
                            let _e1194 = phi_838_;
                            continue;
                            continuing {
                                phi_2635_ = _e1188;
                                phi_832_ = _e1190;
                                phi_835_ = _e1192;
                                phi_837_ = _e1194;
                                phi_2702_ = _e1188;
                                break if !(_e589);
                            }
                        }
                        let _e1197 = phi_2702_;
                        if _e1197 {
                            break;
                        }
                        let _e1200 = local_7;
                        let _e1203 = local_8;
                        phi_1564_ = type_22((_e1200 / f32(_e580)), _e1203);
                    } else {
                        phi_1564_ = type_22(1f, vec3<f32>(0f, 0f, 0f));
                    }
                    let _e1206 = phi_1564_;
                    if _e564 {
                        let _e1211 = params.member.member_6;
                        let _e1212 = pow(_e1206.member, _e1211);
                        if (_e1212 != _e1212) {
                            phi_2383_ = true;
                        } else {
                            phi_2383_ = (0.03f >= _e1212);
                        }
                        let _e1216 = phi_2383_;
                        let _e1217 = select(_e1212, 0.03f, _e1216);
                        let _e1220 = params.member.member_13;
                        if (_e1220 == 0u) {
                            let _e1222 = (_e1217 * 0.6666667f);
                            let _e1228 = ((select(0f, select(1f, _e1222, (_e1222 < 1f)), (_e1222 > 0f)) * 255f) + 0.5f);
                            phi_1640_ = select(select(u32(_e1228), 0u, (_e1228 < 0f)), 4294967295u, (_e1228 > 4294967000f));
                        } else {
                            let _e1242 = sqrt((((_e1206.member_1.x * _e1206.member_1.x) + (_e1206.member_1.y * _e1206.member_1.y)) + (_e1206.member_1.z * _e1206.member_1.z)));
                            if (_e1242 > 0f) {
                                phi_1619_ = (_e1206.member_1 / vec3(_e1242));
                            } else {
                                phi_1619_ = _e484;
                            }
                            let _e1247 = phi_1619_;
                            let _e1248 = (_e1217 * 0.6666667f);
                            let _e1255 = ((_e1247.x * 0.5f) + 0.5f);
                            let _e1256 = ((_e1247.y * 0.5f) + 0.5f);
                            let _e1257 = ((_e1247.z * 0.5f) + 0.5f);
                            let _e1263 = ((select(0f, select(1f, _e1255, (_e1255 < 1f)), (_e1255 > 0f)) * 255f) + 0.5f);
                            let _e1274 = ((select(0f, select(1f, _e1256, (_e1256 < 1f)), (_e1256 > 0f)) * 255f) + 0.5f);
                            let _e1288 = ((select(0f, select(1f, _e1257, (_e1257 < 1f)), (_e1257 > 0f)) * 255f) + 0.5f);
                            let _e1302 = ((select(0f, select(1f, _e1248, (_e1248 < 1f)), (_e1248 > 0f)) * 255f) + 0.5f);
                            phi_1640_ = (((select(select(u32(_e1263), 0u, (_e1263 < 0f)), 4294967295u, (_e1263 > 4294967000f)) | (select(select(u32(_e1274), 0u, (_e1274 < 0f)), 4294967295u, (_e1274 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1288), 0u, (_e1288 < 0f)), 4294967295u, (_e1288 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1302), 0u, (_e1302 < 0f)), 4294967295u, (_e1302 > 4294967000f)) << bitcast<u32>(24i)));
                        }
                        let _e1312 = phi_1640_;
                        phi_1685_ = _e1312;
                    } else {
                        let _e1315 = params.member.member_13;
                        phi_1685_ = select(2852159616u, 170u, (_e1315 == 0u));
                    }
                    let _e1319 = phi_1685_;
                    if (_e118 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e118] = _e1319;
                    if (_e118 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e118] = ((((64u * select(select(u32(_e281), 0u, (_e281 < 0f)), 4294967295u, (_e281 > 4294967000f))) + (16u * select(select(u32(_e309), 0u, (_e309 < 0f)), 4294967295u, (_e309 > 4294967000f)))) + (4u * select(select(u32(_e338), 0u, (_e338 < 0f)), 4294967295u, (_e338 > 4294967000f)))) + select(select(u32(_e367), 0u, (_e367 < 0f)), 4294967295u, (_e367 > 4294967000f)));
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
