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
    var phi_790_: bool;
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
                    if (_e122 > 0f) {
                        phi_790_ = (_e122 < _e561);
                    } else {
                        phi_790_ = false;
                    }
                    let _e565 = phi_790_;
                    if _e565 {
                        let _e568 = params.member.member_3;
                        let _e569 = (_e568 * _e491);
                        let _e571 = ((10f - _e495) * 0.01f);
                        let _e579 = params.member.member_8;
                        let _e581 = select(1u, _e579, (1u < _e579));
                        phi_2635_ = false;
                        phi_832_ = 0u;
                        phi_835_ = vec3<f32>(0f, 0f, 0f);
                        phi_837_ = (select(0f, select(1f, _e571, (_e571 < 1f)), (_e571 > 0f)) * 0.5f);
                        loop {
                            let _e583 = phi_2635_;
                            let _e585 = phi_832_;
                            let _e587 = phi_835_;
                            let _e589 = phi_837_;
                            local_7 = _e589;
                            local_8 = _e587;
                            let _e590 = (_e585 < _e581);
                            if _e590 {
                                let _e595 = ((((_e551 - floor(_e551)) + f32(_e585)) * 3.1415927f) / f32(_e581));
                                let _e596 = sin(_e595);
                                let _e597 = cos(_e595);
                                let _e603 = ((_e597 * _e409) + (_e596 * _e410));
                                let _e607 = (_e597 - (_e409 * _e603));
                                let _e608 = (_e596 - (_e410 * _e603));
                                let _e609 = -((_e411 * _e603));
                                let _e612 = ((_e608 * _e411) - (_e410 * _e609));
                                let _e615 = ((_e609 * _e409) - (_e411 * _e607));
                                let _e618 = ((_e607 * _e410) - (_e409 * _e608));
                                let _e625 = (1f / sqrt((((_e612 * _e612) + (_e615 * _e615)) + (_e618 * _e618))));
                                let _e626 = (_e612 * _e625);
                                let _e627 = (_e615 * _e625);
                                let _e628 = (_e618 * _e625);
                                let _e636 = (((_e484.x * _e626) + (_e484.y * _e627)) + (_e484.z * _e628));
                                let _e640 = (_e484.x - (_e626 * _e636));
                                let _e641 = (_e484.y - (_e627 * _e636));
                                let _e642 = (_e484.z - (_e628 * _e636));
                                let _e648 = sqrt((((_e640 * _e640) + (_e641 * _e641)) + (_e642 * _e642)));
                                let _e653 = (((_e607 * _e640) + (_e608 * _e641)) + (_e609 * _e642));
                                let _e663 = ((((_e640 * _e409) + (_e641 * _e410)) + (_e642 * _e411)) / _e648);
                                let _e667 = select(0f, select(1f, _e663, (_e663 < 1f)), (_e663 > 0f));
                                let _e668 = abs(_e667);
                                let _e679 = (((_e668 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e668))) >> bitcast<u32>(1i))))));
                                let _e683 = (select(select(0f, -1f, (_e653 < 0f)), 1f, (_e653 > 0f)) * select((3.141593f - _e679), _e679, (_e667 >= 0f)));
                                let _e686 = params.member.member_9;
                                let _e688 = select(1u, _e686, (1u < _e686));
                                let _e690 = cos((_e683 + 1.5707964f));
                                let _e692 = cos((_e683 - 1.5707964f));
                                let _e695 = params.member.member_5;
                                phi_1008_ = 0u;
                                phi_1011_ = _e692;
                                phi_1013_ = _e690;
                                loop {
                                    let _e697 = phi_1008_;
                                    let _e699 = phi_1011_;
                                    let _e701 = phi_1013_;
                                    local_3 = _e699;
                                    local_4 = _e699;
                                    local_5 = _e701;
                                    local_6 = _e701;
                                    let _e702 = (_e697 < _e688);
                                    if _e702 {
                                        let _e707 = ((_e555 - floor(_e555)) + (f32((_e585 + (_e697 * _e688))) * 0.618034f));
                                        let _e713 = (((_e707 - floor(_e707)) + f32(_e697)) / f32(_e688));
                                        let _e716 = params.member.member_4;
                                        if (_e716 == 2f) {
                                            phi_1067_ = (_e713 * _e713);
                                        } else {
                                            phi_1067_ = pow(_e713, _e716);
                                        }
                                        let _e721 = phi_1067_;
                                        let _e722 = (_e721 + (1.3f / _e495));
                                        let _e723 = ((_e597 * _e495) * _e722);
                                        let _e724 = ((-(_e596) * _e495) * _e722);
                                        let _e732 = params.member.member_7;
                                        let _e733 = (log2(sqrt(((_e723 * _e723) + (_e724 * _e724)))) - _e732);
                                        let _e740 = (-1f - floor((-0.5f - select(0f, select(5f, _e733, (_e733 < 5f)), (_e733 > 0f)))));
                                        let _e742 = floor((_e723 + 0.5f));
                                        if ((_e742 - _e723) == 0.5f) {
                                            let _e748 = ((floor((_e742 * 0.5f)) * 2f) != _e742);
                                            if _e748 {
                                                phi_1112_ = (_e742 - 1f);
                                            } else {
                                                phi_1112_ = f32();
                                            }
                                            let _e751 = phi_1112_;
                                            phi_1114_ = _e751;
                                            phi_1115_ = select(true, false, _e748);
                                        } else {
                                            phi_1114_ = f32();
                                            phi_1115_ = true;
                                        }
                                        let _e754 = phi_1114_;
                                        let _e756 = phi_1115_;
                                        let _e758 = (select(_e754, _e742, _e756) / _e97);
                                        let _e760 = floor((_e724 + 0.5f));
                                        if ((_e760 - _e724) == 0.5f) {
                                            let _e766 = ((floor((_e760 * 0.5f)) * 2f) != _e760);
                                            if _e766 {
                                                phi_1138_ = (_e760 - 1f);
                                            } else {
                                                phi_1138_ = f32();
                                            }
                                            let _e769 = phi_1138_;
                                            phi_1140_ = _e769;
                                            phi_1141_ = select(true, false, _e766);
                                        } else {
                                            phi_1140_ = f32();
                                            phi_1141_ = true;
                                        }
                                        let _e772 = phi_1140_;
                                        let _e774 = phi_1141_;
                                        let _e776 = (select(_e772, _e760, _e774) / _e107);
                                        let _e777 = (_e378 + _e758);
                                        let _e778 = (_e379 + _e776);
                                        let _e779 = (_e378 - _e758);
                                        let _e780 = (_e379 - _e776);
                                        let _e781 = (_e740 > 0f);
                                        if _e781 {
                                            let _e786 = select(select(u32(_e740), 0u, (_e740 < 0f)), 4294967295u, (_e740 > 4294967000f));
                                            phi_2108_ = select(_e786, 4u, (4u < _e786));
                                        } else {
                                            phi_2108_ = 0u;
                                        }
                                        let _e790 = phi_2108_;
                                        let _e791 = (_e790 & 31u);
                                        let _e793 = (_e102 >> bitcast<u32>(_e791));
                                        let _e795 = select(1u, _e793, (1u < _e793));
                                        let _e797 = (_e112 >> bitcast<u32>(_e791));
                                        let _e799 = select(1u, _e797, (1u < _e797));
                                        let _e801 = (_e777 * f32(_e795));
                                        if (_e801 > 0f) {
                                            let _e807 = select(select(u32(_e801), 0u, (_e801 < 0f)), 4294967295u, (_e801 > 4294967000f));
                                            let _e808 = (_e795 - 1u);
                                            phi_2156_ = select(_e807, _e808, (_e808 < _e807));
                                        } else {
                                            phi_2156_ = 0u;
                                        }
                                        let _e812 = phi_2156_;
                                        let _e814 = (_e778 * f32(_e799));
                                        if (_e814 > 0f) {
                                            let _e820 = select(select(u32(_e814), 0u, (_e814 < 0f)), 4294967295u, (_e814 > 4294967000f));
                                            let _e821 = (_e799 - 1u);
                                            phi_2176_ = select(_e820, _e821, (_e821 < _e820));
                                        } else {
                                            phi_2176_ = 0u;
                                        }
                                        let _e825 = phi_2176_;
                                        phi_2178_ = 0u;
                                        phi_2179_ = 0u;
                                        loop {
                                            let _e827 = phi_2178_;
                                            let _e829 = phi_2179_;
                                            local_1 = _e829;
                                            let _e830 = (_e827 < _e790);
                                            if _e830 {
                                                let _e831 = (_e827 & 31u);
                                                let _e833 = (_e102 >> bitcast<u32>(_e831));
                                                let _e837 = (_e112 >> bitcast<u32>(_e831));
                                                phi_2202_ = (_e827 + 1u);
                                                phi_2203_ = (_e829 + (select(1u, _e833, (1u < _e833)) * select(1u, _e837, (1u < _e837))));
                                            } else {
                                                phi_2202_ = u32();
                                                phi_2203_ = u32();
                                            }
                                            let _e844 = phi_2202_;
                                            let _e846 = phi_2203_;
                                            continue;
                                            continuing {
                                                phi_2178_ = _e844;
                                                phi_2179_ = _e846;
                                                break if !(_e830);
                                            }
                                        }
                                        let _e851 = local_1;
                                        let _e852 = (_e851 + ((_e825 * _e795) + _e812));
                                        if (_e852 < _e86) {
                                        } else {
                                            phi_2581_ = true;
                                            break;
                                        }
                                        let _e856 = mips.member[_e852];
                                        if _e781 {
                                            let _e869 = select(select(u32(_e740), 0u, (_e740 < 0f)), 4294967295u, (_e740 > 4294967000f));
                                            phi_2230_ = select(_e869, 4u, (4u < _e869));
                                        } else {
                                            phi_2230_ = 0u;
                                        }
                                        let _e873 = phi_2230_;
                                        let _e874 = (_e873 & 31u);
                                        let _e876 = (_e102 >> bitcast<u32>(_e874));
                                        let _e878 = select(1u, _e876, (1u < _e876));
                                        let _e880 = (_e112 >> bitcast<u32>(_e874));
                                        let _e882 = select(1u, _e880, (1u < _e880));
                                        let _e884 = (_e779 * f32(_e878));
                                        if (_e884 > 0f) {
                                            let _e890 = select(select(u32(_e884), 0u, (_e884 < 0f)), 4294967295u, (_e884 > 4294967000f));
                                            let _e891 = (_e878 - 1u);
                                            phi_2278_ = select(_e890, _e891, (_e891 < _e890));
                                        } else {
                                            phi_2278_ = 0u;
                                        }
                                        let _e895 = phi_2278_;
                                        let _e897 = (_e780 * f32(_e882));
                                        if (_e897 > 0f) {
                                            let _e903 = select(select(u32(_e897), 0u, (_e897 < 0f)), 4294967295u, (_e897 > 4294967000f));
                                            let _e904 = (_e882 - 1u);
                                            phi_2298_ = select(_e903, _e904, (_e904 < _e903));
                                        } else {
                                            phi_2298_ = 0u;
                                        }
                                        let _e908 = phi_2298_;
                                        phi_2300_ = 0u;
                                        phi_2301_ = 0u;
                                        loop {
                                            let _e910 = phi_2300_;
                                            let _e912 = phi_2301_;
                                            local_2 = _e912;
                                            let _e913 = (_e910 < _e873);
                                            if _e913 {
                                                let _e914 = (_e910 & 31u);
                                                let _e916 = (_e102 >> bitcast<u32>(_e914));
                                                let _e920 = (_e112 >> bitcast<u32>(_e914));
                                                phi_2324_ = (_e910 + 1u);
                                                phi_2325_ = (_e912 + (select(1u, _e916, (1u < _e916)) * select(1u, _e920, (1u < _e920))));
                                            } else {
                                                phi_2324_ = u32();
                                                phi_2325_ = u32();
                                            }
                                            let _e927 = phi_2324_;
                                            let _e929 = phi_2325_;
                                            continue;
                                            continuing {
                                                phi_2300_ = _e927;
                                                phi_2301_ = _e929;
                                                break if !(_e913);
                                            }
                                        }
                                        let _e934 = local_2;
                                        let _e935 = (_e934 + ((_e908 * _e878) + _e895));
                                        if (_e935 < _e86) {
                                        } else {
                                            phi_2581_ = true;
                                            break;
                                        }
                                        let _e939 = mips.member[_e935];
                                        let _e948 = (((((_e777 * 2f) - 1f) * _e387) * _e856) - _e389);
                                        let _e949 = (((((_e778 * -2f) + 1f) * _e396) * _e856) - _e398);
                                        let _e950 = (_e856 - _e380);
                                        let _e953 = ((_e948 * _e948) + (_e949 * _e949));
                                        let _e956 = sqrt((_e953 + (_e950 * _e950)));
                                        let _e965 = (1f + _e695);
                                        let _e966 = (_e950 * _e965);
                                        let _e969 = sqrt((_e953 + (_e966 * _e966)));
                                        let _e970 = (_e569 > 0f);
                                        if _e970 {
                                            let _e973 = ((-(_e969) + _e491) / _e569);
                                            phi_1279_ = select(0f, select(1f, _e973, (_e973 < 1f)), (_e973 > 0f));
                                        } else {
                                            phi_1279_ = select(0f, 1f, (_e969 <= _e491));
                                        }
                                        let _e981 = phi_1279_;
                                        let _e984 = (_e690 + ((((((_e948 / _e956) * _e409) + ((_e949 / _e956) * _e410)) + ((_e950 / _e956) * _e411)) - _e690) * _e981));
                                        let _e985 = (((((_e779 * 2f) - 1f) * _e387) * _e939) - _e389);
                                        let _e986 = (((((_e780 * -2f) + 1f) * _e396) * _e939) - _e398);
                                        let _e987 = (_e939 - _e380);
                                        let _e990 = ((_e985 * _e985) + (_e986 * _e986));
                                        let _e993 = sqrt((_e990 + (_e987 * _e987)));
                                        let _e1002 = (_e987 * _e965);
                                        let _e1005 = sqrt((_e990 + (_e1002 * _e1002)));
                                        if _e970 {
                                            let _e1008 = ((-(_e1005) + _e491) / _e569);
                                            phi_1339_ = select(0f, select(1f, _e1008, (_e1008 < 1f)), (_e1008 > 0f));
                                        } else {
                                            phi_1339_ = select(0f, 1f, (_e1005 <= _e491));
                                        }
                                        let _e1016 = phi_1339_;
                                        let _e1019 = (_e692 + ((((((_e985 / _e993) * _e409) + ((_e986 / _e993) * _e410)) + ((_e987 / _e993) * _e411)) - _e692) * _e1016));
                                        if (_e701 != _e701) {
                                            phi_2341_ = true;
                                        } else {
                                            phi_2341_ = (_e984 >= _e701);
                                        }
                                        let _e1023 = phi_2341_;
                                        if (_e699 != _e699) {
                                            phi_2356_ = true;
                                        } else {
                                            phi_2356_ = (_e1019 >= _e699);
                                        }
                                        let _e1028 = phi_2356_;
                                        phi_1009_ = (_e697 + 1u);
                                        phi_1012_ = select(_e699, _e1019, _e1028);
                                        phi_1014_ = select(_e701, _e984, _e1023);
                                    } else {
                                        phi_1009_ = u32();
                                        phi_1012_ = f32();
                                        phi_1014_ = f32();
                                    }
                                    let _e1032 = phi_1009_;
                                    let _e1034 = phi_1012_;
                                    let _e1036 = phi_1014_;
                                    continue;
                                    continuing {
                                        phi_1008_ = _e1032;
                                        phi_1011_ = _e1034;
                                        phi_1013_ = _e1036;
                                        phi_2581_ = _e583;
                                        break if !(_e702);
                                    }
                                }
                                let _e1039 = phi_2581_;
                                phi_2702_ = _e1039;
                                if _e1039 {
                                    break;
                                }
                                let _e1041 = local_3;
                                let _e1042 = abs(_e1041);
                                let _e1053 = (((_e1042 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1042))) >> bitcast<u32>(1i))))));
                                let _e1055 = local_4;
                                let _e1058 = select((3.141593f - _e1053), _e1053, (_e1055 >= 0f));
                                let _e1059 = -(_e1058);
                                let _e1061 = local_5;
                                let _e1062 = abs(_e1061);
                                let _e1073 = (((_e1062 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1062))) >> bitcast<u32>(1i))))));
                                let _e1075 = local_6;
                                let _e1078 = select((3.141593f - _e1073), _e1073, (_e1075 >= 0f));
                                let _e1081 = (_e648 + ((1f - _e648) * 0.05f));
                                let _e1082 = (_e1058 * -2f);
                                let _e1083 = sin(_e683);
                                let _e1089 = (_e1078 * 2f);
                                let _e1101 = params.member.member_13;
                                if (_e1101 == 0u) {
                                    phi_1558_ = _e587;
                                } else {
                                    let _e1107 = ((_e1058 * -3f) - _e683);
                                    let _e1115 = ((_e1078 * 3f) - _e683);
                                    let _e1120 = (_e1059 + _e683);
                                    let _e1122 = (_e1078 + _e683);
                                    let _e1127 = (((((((sin((_e1059 - _e683)) * 6f) - sin(_e1107)) + (sin((_e1078 - _e683)) * 6f)) - sin(_e1115)) + (_e1083 * 16f)) - ((sin(_e1120) + sin(_e1122)) * 3f)) * 0.083333336f);
                                    let _e1139 = (((-(cos(_e1107)) - cos(_e1115)) + (cos(_e683) * 8f)) - ((cos(_e1120) + cos(_e1122)) * 3f));
                                    let _e1140 = (_e597 * _e1127);
                                    let _e1141 = (_e596 * _e1127);
                                    let _e1142 = (_e1139 * -0.083333336f);
                                    let _e1143 = (-1f * _e411);
                                    let _e1144 = (-1f * _e409);
                                    let _e1146 = (1f / (_e1143 + 1f));
                                    let _e1147 = (_e1146 * _e410);
                                    let _e1151 = (_e1147 * _e1144);
                                    let _e1172 = (_e1143 > 0.9997f);
                                    let _e1173 = (_e1143 < -0.9997f);
                                    phi_1558_ = (_e587 + vec3<f32>((select(select(((((_e1143 + (_e1147 * _e410)) * _e1140) + (_e1151 * _e1141)) + (_e1144 * _e1142)), _e1140, _e1173), _e1140, _e1172) * _e1081), (select(select((((_e1151 * _e1140) + ((_e1143 + ((_e1146 * _e1144) * _e1144)) * _e1141)) + (-(_e410) * _e1142)), -(_e1141), _e1173), _e1141, _e1172) * _e1081), (select(select((((_e409 * _e1140) + (_e410 * _e1141)) + (_e1143 * _e1142)), (_e1139 * 0.083333336f), _e1173), _e1142, _e1172) * _e1081)));
                                }
                                let _e1186 = phi_1558_;
                                phi_2703_ = _e1039;
                                phi_833_ = (_e585 + 1u);
                                phi_836_ = _e1186;
                                phi_838_ = (_e589 + ((0.25f * (((_e667 + (_e1082 * _e1083)) - cos((_e1082 - _e683))) + ((_e667 + (_e1089 * _e1083)) - cos((_e1089 - _e683))))) * _e1081));
                            } else {
                                phi_2703_ = _e583;
                                phi_833_ = u32();
                                phi_836_ = vec3<f32>();
                                phi_838_ = f32();
                            }
                            let _e1189 = phi_2703_;
                            let _e1191 = phi_833_;
                            let _e1193 = phi_836_;
                            let _e1195 = phi_838_;
                            continue;
                            continuing {
                                phi_2635_ = _e1189;
                                phi_832_ = _e1191;
                                phi_835_ = _e1193;
                                phi_837_ = _e1195;
                                phi_2702_ = _e1189;
                                break if !(_e590);
                            }
                        }
                        let _e1198 = phi_2702_;
                        if _e1198 {
                            break;
                        }
                        let _e1201 = local_7;
                        let _e1204 = local_8;
                        phi_1564_ = type_22((_e1201 / f32(_e581)), _e1204);
                    } else {
                        phi_1564_ = type_22(1f, vec3<f32>(0f, 0f, 0f));
                    }
                    let _e1207 = phi_1564_;
                    if _e565 {
                        let _e1212 = params.member.member_6;
                        let _e1213 = pow(_e1207.member, _e1212);
                        if (_e1213 != _e1213) {
                            phi_2383_ = true;
                        } else {
                            phi_2383_ = (0.03f >= _e1213);
                        }
                        let _e1217 = phi_2383_;
                        let _e1218 = select(_e1213, 0.03f, _e1217);
                        let _e1221 = params.member.member_13;
                        if (_e1221 == 0u) {
                            let _e1223 = (_e1218 * 0.6666667f);
                            let _e1229 = ((select(0f, select(1f, _e1223, (_e1223 < 1f)), (_e1223 > 0f)) * 255f) + 0.5f);
                            phi_1640_ = select(select(u32(_e1229), 0u, (_e1229 < 0f)), 4294967295u, (_e1229 > 4294967000f));
                        } else {
                            let _e1243 = sqrt((((_e1207.member_1.x * _e1207.member_1.x) + (_e1207.member_1.y * _e1207.member_1.y)) + (_e1207.member_1.z * _e1207.member_1.z)));
                            if (_e1243 > 0f) {
                                phi_1619_ = (_e1207.member_1 / vec3(_e1243));
                            } else {
                                phi_1619_ = _e484;
                            }
                            let _e1248 = phi_1619_;
                            let _e1249 = (_e1218 * 0.6666667f);
                            let _e1256 = ((_e1248.x * 0.5f) + 0.5f);
                            let _e1257 = ((_e1248.y * 0.5f) + 0.5f);
                            let _e1258 = ((_e1248.z * 0.5f) + 0.5f);
                            let _e1264 = ((select(0f, select(1f, _e1256, (_e1256 < 1f)), (_e1256 > 0f)) * 255f) + 0.5f);
                            let _e1275 = ((select(0f, select(1f, _e1257, (_e1257 < 1f)), (_e1257 > 0f)) * 255f) + 0.5f);
                            let _e1289 = ((select(0f, select(1f, _e1258, (_e1258 < 1f)), (_e1258 > 0f)) * 255f) + 0.5f);
                            let _e1303 = ((select(0f, select(1f, _e1249, (_e1249 < 1f)), (_e1249 > 0f)) * 255f) + 0.5f);
                            phi_1640_ = (((select(select(u32(_e1264), 0u, (_e1264 < 0f)), 4294967295u, (_e1264 > 4294967000f)) | (select(select(u32(_e1275), 0u, (_e1275 < 0f)), 4294967295u, (_e1275 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1289), 0u, (_e1289 < 0f)), 4294967295u, (_e1289 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1303), 0u, (_e1303 < 0f)), 4294967295u, (_e1303 > 4294967000f)) << bitcast<u32>(24i)));
                        }
                        let _e1313 = phi_1640_;
                        phi_1685_ = _e1313;
                    } else {
                        let _e1316 = params.member.member_13;
                        phi_1685_ = select(2852159616u, 170u, (_e1316 == 0u));
                    }
                    let _e1320 = phi_1685_;
                    if (_e118 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e118] = _e1320;
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
