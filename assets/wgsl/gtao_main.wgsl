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
    var phi_254_: i32;
    var phi_273_: i32;
    var phi_313_: i32;
    var phi_332_: i32;
    var phi_372_: i32;
    var phi_391_: i32;
    var phi_431_: i32;
    var phi_450_: i32;
    var phi_2042_: f32;
    var phi_2046_: f32;
    var phi_2047_: bool;
    var phi_2085_: f32;
    var phi_2089_: f32;
    var phi_2090_: bool;
    var phi_2128_: f32;
    var phi_2132_: f32;
    var phi_2133_: bool;
    var phi_2171_: f32;
    var phi_2175_: f32;
    var phi_2176_: bool;
    var phi_2199_: bool;
    var phi_2214_: bool;
    var phi_667_: vec2<f32>;
    var phi_695_: vec3<f32>;
    var phi_716_: u32;
    var phi_719_: u32;
    var phi_721_: u32;
    var phi_723_: u32;
    var phi_752_: u32;
    var phi_753_: u32;
    var phi_754_: u32;
    var phi_755_: u32;
    var phi_717_: u32;
    var phi_720_: u32;
    var phi_722_: u32;
    var phi_724_: u32;
    var local: u32;
    var phi_2518_: bool;
    var phi_820_: u32;
    var phi_823_: vec3<f32>;
    var phi_825_: f32;
    var phi_996_: u32;
    var phi_999_: f32;
    var phi_1001_: f32;
    var phi_1055_: f32;
    var phi_1100_: f32;
    var phi_1102_: f32;
    var phi_1103_: bool;
    var phi_1126_: f32;
    var phi_1128_: f32;
    var phi_1129_: bool;
    var phi_1162_: u32;
    var phi_1165_: f32;
    var phi_1167_: f32;
    var phi_1169_: u32;
    var phi_1171_: u32;
    var phi_1173_: u32;
    var phi_1206_: u32;
    var phi_1209_: u32;
    var phi_1207_: u32;
    var phi_1210_: u32;
    var local_1: u32;
    var phi_1163_: u32;
    var phi_1166_: f32;
    var phi_1168_: f32;
    var phi_1170_: u32;
    var phi_1172_: u32;
    var phi_1174_: u32;
    var local_2: f32;
    var local_3: u32;
    var phi_1267_: u32;
    var local_4: f32;
    var local_5: u32;
    var phi_1286_: u32;
    var local_6: u32;
    var local_7: u32;
    var phi_1330_: u32;
    var phi_1333_: f32;
    var phi_1335_: f32;
    var phi_1337_: u32;
    var phi_1339_: u32;
    var phi_1341_: u32;
    var phi_1374_: u32;
    var phi_1377_: u32;
    var phi_1375_: u32;
    var phi_1378_: u32;
    var local_8: u32;
    var phi_1331_: u32;
    var phi_1334_: f32;
    var phi_1336_: f32;
    var phi_1338_: u32;
    var phi_1340_: u32;
    var phi_1342_: u32;
    var local_9: f32;
    var local_10: u32;
    var phi_1435_: u32;
    var local_11: f32;
    var local_12: u32;
    var phi_1454_: u32;
    var local_13: u32;
    var local_14: u32;
    var phi_1537_: f32;
    var phi_1597_: f32;
    var phi_2235_: bool;
    var phi_2250_: bool;
    var phi_997_: u32;
    var phi_1000_: f32;
    var phi_1002_: f32;
    var phi_2450_: bool;
    var local_15: f32;
    var local_16: f32;
    var local_17: f32;
    var local_18: f32;
    var phi_1816_: vec3<f32>;
    var phi_2586_: bool;
    var phi_821_: u32;
    var phi_824_: vec3<f32>;
    var phi_826_: f32;
    var phi_2585_: bool;
    var local_19: f32;
    var local_20: vec3<f32>;
    var phi_1822_: type_22;
    var phi_2277_: bool;
    var phi_1877_: vec3<f32>;
    var phi_1898_: u32;
    var phi_1943_: u32;

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
                        phi_254_ = 0i;
                    } else {
                        phi_254_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_254_;
                    let _e134 = bitcast<i32>(_e84.y);
                    let _e136 = (bitcast<i32>(_e112) - 1i);
                    let _e137 = (0i <= _e136);
                    if _e137 {
                    } else {
                        break;
                    }
                    let _e138 = (_e134 < 0i);
                    if _e138 {
                        phi_273_ = 0i;
                    } else {
                        phi_273_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e142 = phi_273_;
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
                        phi_313_ = 0i;
                    } else {
                        phi_313_ = select(_e150, _e126, (_e150 > _e126));
                    }
                    let _e155 = phi_313_;
                    if _e137 {
                    } else {
                        break;
                    }
                    if _e138 {
                        phi_332_ = 0i;
                    } else {
                        phi_332_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e160 = phi_332_;
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
                        phi_372_ = 0i;
                    } else {
                        phi_372_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e172 = phi_372_;
                    let _e174 = (_e134 + -1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e174 < 0i) {
                        phi_391_ = 0i;
                    } else {
                        phi_391_ = select(_e174, _e136, (_e174 > _e136));
                    }
                    let _e179 = phi_391_;
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
                        phi_431_ = 0i;
                    } else {
                        phi_431_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e190 = phi_431_;
                    let _e192 = (_e134 + 1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e192 < 0i) {
                        phi_450_ = 0i;
                    } else {
                        phi_450_ = select(_e192, _e136, (_e192 > _e136));
                    }
                    let _e197 = phi_450_;
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
                            phi_2042_ = (_e266 - 1f);
                        } else {
                            phi_2042_ = f32();
                        }
                        let _e275 = phi_2042_;
                        phi_2046_ = _e275;
                        phi_2047_ = select(true, false, _e272);
                    } else {
                        phi_2046_ = f32();
                        phi_2047_ = true;
                    }
                    let _e278 = phi_2046_;
                    let _e280 = phi_2047_;
                    let _e281 = select(_e278, _e266, _e280);
                    let _e292 = (select(0f, select(1f, _e249, (_e249 < 1f)), (_e249 > 0f)) * 2.9f);
                    let _e294 = floor((_e292 + 0.5f));
                    if ((_e294 - _e292) == 0.5f) {
                        let _e300 = ((floor((_e294 * 0.5f)) * 2f) != _e294);
                        if _e300 {
                            phi_2085_ = (_e294 - 1f);
                        } else {
                            phi_2085_ = f32();
                        }
                        let _e303 = phi_2085_;
                        phi_2089_ = _e303;
                        phi_2090_ = select(true, false, _e300);
                    } else {
                        phi_2089_ = f32();
                        phi_2090_ = true;
                    }
                    let _e306 = phi_2089_;
                    let _e308 = phi_2090_;
                    let _e309 = select(_e306, _e294, _e308);
                    let _e321 = (select(0f, select(1f, _e254, (_e254 < 1f)), (_e254 > 0f)) * 2.9f);
                    let _e323 = floor((_e321 + 0.5f));
                    if ((_e323 - _e321) == 0.5f) {
                        let _e329 = ((floor((_e323 * 0.5f)) * 2f) != _e323);
                        if _e329 {
                            phi_2128_ = (_e323 - 1f);
                        } else {
                            phi_2128_ = f32();
                        }
                        let _e332 = phi_2128_;
                        phi_2132_ = _e332;
                        phi_2133_ = select(true, false, _e329);
                    } else {
                        phi_2132_ = f32();
                        phi_2133_ = true;
                    }
                    let _e335 = phi_2132_;
                    let _e337 = phi_2133_;
                    let _e338 = select(_e335, _e323, _e337);
                    let _e350 = (select(0f, select(1f, _e259, (_e259 < 1f)), (_e259 > 0f)) * 2.9f);
                    let _e352 = floor((_e350 + 0.5f));
                    if ((_e352 - _e350) == 0.5f) {
                        let _e358 = ((floor((_e352 * 0.5f)) * 2f) != _e352);
                        if _e358 {
                            phi_2171_ = (_e352 - 1f);
                        } else {
                            phi_2171_ = f32();
                        }
                        let _e361 = phi_2171_;
                        phi_2175_ = _e361;
                        phi_2176_ = select(true, false, _e358);
                    } else {
                        phi_2175_ = f32();
                        phi_2176_ = true;
                    }
                    let _e364 = phi_2175_;
                    let _e366 = phi_2176_;
                    let _e367 = select(_e364, _e352, _e366);
                    let _e376 = ((f32(_e84.x) + 0.5f) / _e97);
                    let _e379 = ((f32(_e84.y) + 0.5f) / _e107);
                    let _e380 = (_e122 * 0.99999f);
                    let _e387 = params.member.member.member_1[0u];
                    let _e389 = ((((_e376 * 2f) - 1f) * _e387) * _e380);
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
                        phi_2199_ = true;
                    } else {
                        phi_2199_ = (-1f >= _e423);
                    }
                    let _e427 = phi_2199_;
                    let _e428 = select(_e423, -1f, _e427);
                    let _e438 = (f32((bitcast<i32>((((_e415 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e438 != _e438) {
                        phi_2214_ = true;
                    } else {
                        phi_2214_ = (-1f >= _e438);
                    }
                    let _e442 = phi_2214_;
                    let _e443 = select(_e438, -1f, _e442);
                    let _e446 = (1f - abs(_e428));
                    let _e447 = abs(_e443);
                    let _e448 = (_e446 - _e447);
                    if (_e448 < 0f) {
                        phi_667_ = vec2<f32>(((1f - _e447) * select(1f, -1f, (_e428 < 0f))), (_e446 * select(1f, -1f, (_e443 < 0f))));
                    } else {
                        phi_667_ = vec2<f32>(_e428, _e443);
                    }
                    let _e459 = phi_667_;
                    let _e468 = (1f / sqrt((((_e459.x * _e459.x) + (_e459.y * _e459.y)) + (_e448 * _e448))));
                    let _e469 = (_e459.x * _e468);
                    let _e470 = (_e459.y * _e468);
                    let _e471 = (_e448 * _e468);
                    let _e472 = -(_e471);
                    if ((((_e469 * _e409) + (_e470 * _e410)) + (_e472 * _e411)) < 0f) {
                        phi_695_ = vec3<f32>(-(_e469), -(_e470), _e471);
                    } else {
                        phi_695_ = vec3<f32>(_e469, _e470, _e472);
                    }
                    let _e484 = phi_695_;
                    let _e487 = params.member.member_1;
                    let _e490 = params.member.member_2;
                    let _e491 = (_e487 * _e490);
                    let _e495 = (_e491 / (((_e122 * 1.99998f) * _e387) / _e97));
                    let _e499 = params.member.member_11;
                    phi_716_ = (_e84.y & 63u);
                    phi_719_ = (_e84.x & 63u);
                    phi_721_ = 32u;
                    phi_723_ = 0u;
                    loop {
                        let _e503 = phi_716_;
                        let _e505 = phi_719_;
                        let _e507 = phi_721_;
                        let _e509 = phi_723_;
                        local = _e509;
                        let _e510 = (_e507 > 0u);
                        if _e510 {
                            let _e513 = select(0u, 1u, ((_e505 & _e507) != 0u));
                            let _e516 = select(0u, 1u, ((_e503 & _e507) != 0u));
                            if (_e516 == 0u) {
                                if (_e513 == 1u) {
                                    phi_752_ = (63u - _e503);
                                    phi_753_ = (63u - _e505);
                                } else {
                                    phi_752_ = _e503;
                                    phi_753_ = _e505;
                                }
                                let _e527 = phi_752_;
                                let _e529 = phi_753_;
                                phi_754_ = _e529;
                                phi_755_ = _e527;
                            } else {
                                phi_754_ = _e503;
                                phi_755_ = _e505;
                            }
                            let _e531 = phi_754_;
                            let _e533 = phi_755_;
                            phi_717_ = _e531;
                            phi_720_ = _e533;
                            phi_722_ = (_e507 / 2u);
                            phi_724_ = (_e509 + ((_e507 * _e507) * ((3u * _e513) ^ _e516)));
                        } else {
                            phi_717_ = u32();
                            phi_720_ = u32();
                            phi_722_ = u32();
                            phi_724_ = u32();
                        }
                        let _e536 = phi_717_;
                        let _e538 = phi_720_;
                        let _e540 = phi_722_;
                        let _e542 = phi_724_;
                        continue;
                        continuing {
                            phi_716_ = _e536;
                            phi_719_ = _e538;
                            phi_721_ = _e540;
                            phi_723_ = _e542;
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
                        phi_2518_ = false;
                        phi_820_ = 0u;
                        phi_823_ = vec3<f32>(0f, 0f, 0f);
                        phi_825_ = (select(0f, select(1f, _e570, (_e570 < 1f)), (_e570 > 0f)) * 0.5f);
                        loop {
                            let _e582 = phi_2518_;
                            let _e584 = phi_820_;
                            let _e586 = phi_823_;
                            let _e588 = phi_825_;
                            local_19 = _e588;
                            local_20 = _e586;
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
                                phi_996_ = 0u;
                                phi_999_ = _e691;
                                phi_1001_ = _e689;
                                loop {
                                    let _e696 = phi_996_;
                                    let _e698 = phi_999_;
                                    let _e700 = phi_1001_;
                                    local_15 = _e698;
                                    local_16 = _e698;
                                    local_17 = _e700;
                                    local_18 = _e700;
                                    let _e701 = (_e696 < _e687);
                                    if _e701 {
                                        let _e706 = ((_e555 - floor(_e555)) + (f32((_e584 + (_e696 * _e687))) * 0.618034f));
                                        let _e712 = (((_e706 - floor(_e706)) + f32(_e696)) / f32(_e687));
                                        let _e715 = params.member.member_4;
                                        if (_e715 == 2f) {
                                            phi_1055_ = (_e712 * _e712);
                                        } else {
                                            phi_1055_ = pow(_e712, _e715);
                                        }
                                        let _e720 = phi_1055_;
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
                                                phi_1100_ = (_e741 - 1f);
                                            } else {
                                                phi_1100_ = f32();
                                            }
                                            let _e750 = phi_1100_;
                                            phi_1102_ = _e750;
                                            phi_1103_ = select(true, false, _e747);
                                        } else {
                                            phi_1102_ = f32();
                                            phi_1103_ = true;
                                        }
                                        let _e753 = phi_1102_;
                                        let _e755 = phi_1103_;
                                        let _e757 = (select(_e753, _e741, _e755) / _e97);
                                        let _e759 = floor((_e723 + 0.5f));
                                        if ((_e759 - _e723) == 0.5f) {
                                            let _e765 = ((floor((_e759 * 0.5f)) * 2f) != _e759);
                                            if _e765 {
                                                phi_1126_ = (_e759 - 1f);
                                            } else {
                                                phi_1126_ = f32();
                                            }
                                            let _e768 = phi_1126_;
                                            phi_1128_ = _e768;
                                            phi_1129_ = select(true, false, _e765);
                                        } else {
                                            phi_1128_ = f32();
                                            phi_1129_ = true;
                                        }
                                        let _e771 = phi_1128_;
                                        let _e773 = phi_1129_;
                                        let _e775 = (select(_e771, _e759, _e773) / _e107);
                                        let _e776 = (_e376 + _e757);
                                        let _e777 = (_e379 + _e775);
                                        let _e778 = (_e376 - _e757);
                                        let _e779 = (_e379 - _e775);
                                        let _e781 = select(1u, _e102, (1u < _e102));
                                        let _e783 = select(1u, _e112, (1u < _e112));
                                        let _e784 = f32(_e781);
                                        let _e785 = f32(_e783);
                                        phi_1162_ = 1u;
                                        phi_1165_ = _e785;
                                        phi_1167_ = _e784;
                                        phi_1169_ = 0u;
                                        phi_1171_ = _e783;
                                        phi_1173_ = _e781;
                                        loop {
                                            let _e787 = phi_1162_;
                                            let _e789 = phi_1165_;
                                            let _e791 = phi_1167_;
                                            let _e793 = phi_1169_;
                                            let _e795 = phi_1171_;
                                            let _e797 = phi_1173_;
                                            local_2 = _e791;
                                            local_3 = _e797;
                                            local_4 = _e789;
                                            local_5 = _e795;
                                            local_6 = _e797;
                                            local_7 = _e793;
                                            let _e798 = (_e787 < 5u);
                                            if _e798 {
                                                let _e800 = (_e739 >= f32(_e787));
                                                let _e801 = (_e787 & 31u);
                                                let _e803 = (_e102 >> bitcast<u32>(_e801));
                                                let _e805 = select(1u, _e803, (1u < _e803));
                                                let _e807 = (_e112 >> bitcast<u32>(_e801));
                                                let _e809 = select(1u, _e807, (1u < _e807));
                                                phi_1206_ = 0u;
                                                phi_1209_ = 0u;
                                                loop {
                                                    let _e813 = phi_1206_;
                                                    let _e815 = phi_1209_;
                                                    local_1 = _e815;
                                                    let _e816 = (_e813 < _e787);
                                                    if _e816 {
                                                        let _e817 = (_e813 & 31u);
                                                        let _e819 = (_e102 >> bitcast<u32>(_e817));
                                                        let _e823 = (_e112 >> bitcast<u32>(_e817));
                                                        phi_1207_ = (_e813 + 1u);
                                                        phi_1210_ = (_e815 + (select(1u, _e819, (1u < _e819)) * select(1u, _e823, (1u < _e823))));
                                                    } else {
                                                        phi_1207_ = u32();
                                                        phi_1210_ = u32();
                                                    }
                                                    let _e830 = phi_1207_;
                                                    let _e832 = phi_1210_;
                                                    continue;
                                                    continuing {
                                                        phi_1206_ = _e830;
                                                        phi_1209_ = _e832;
                                                        break if !(_e816);
                                                    }
                                                }
                                                let _e835 = local_1;
                                                phi_1163_ = (_e787 + 1u);
                                                phi_1166_ = select(_e789, f32(_e809), _e800);
                                                phi_1168_ = select(_e791, f32(_e805), _e800);
                                                phi_1170_ = select(_e793, _e835, _e800);
                                                phi_1172_ = select(_e795, _e809, _e800);
                                                phi_1174_ = select(_e797, _e805, _e800);
                                            } else {
                                                phi_1163_ = u32();
                                                phi_1166_ = f32();
                                                phi_1168_ = f32();
                                                phi_1170_ = u32();
                                                phi_1172_ = u32();
                                                phi_1174_ = u32();
                                            }
                                            let _e843 = phi_1163_;
                                            let _e845 = phi_1166_;
                                            let _e847 = phi_1168_;
                                            let _e849 = phi_1170_;
                                            let _e851 = phi_1172_;
                                            let _e853 = phi_1174_;
                                            continue;
                                            continuing {
                                                phi_1162_ = _e843;
                                                phi_1165_ = _e845;
                                                phi_1167_ = _e847;
                                                phi_1169_ = _e849;
                                                phi_1171_ = _e851;
                                                phi_1173_ = _e853;
                                                break if !(_e798);
                                            }
                                        }
                                        let _e856 = local_2;
                                        let _e857 = (_e776 * _e856);
                                        if (_e857 > 0f) {
                                            let _e863 = select(select(u32(_e857), 0u, (_e857 < 0f)), 4294967295u, (_e857 > 4294967000f));
                                            let _e865 = local_3;
                                            let _e866 = (_e865 - 1u);
                                            phi_1267_ = select(_e863, _e866, (_e866 < _e863));
                                        } else {
                                            phi_1267_ = 0u;
                                        }
                                        let _e870 = phi_1267_;
                                        let _e872 = local_4;
                                        let _e873 = (_e777 * _e872);
                                        if (_e873 > 0f) {
                                            let _e879 = select(select(u32(_e873), 0u, (_e873 < 0f)), 4294967295u, (_e873 > 4294967000f));
                                            let _e881 = local_5;
                                            let _e882 = (_e881 - 1u);
                                            phi_1286_ = select(_e879, _e882, (_e882 < _e879));
                                        } else {
                                            phi_1286_ = 0u;
                                        }
                                        let _e886 = phi_1286_;
                                        let _e888 = local_6;
                                        let _e891 = local_7;
                                        let _e893 = ((_e891 + (_e886 * _e888)) + _e870);
                                        if (_e893 < _e86) {
                                        } else {
                                            phi_2450_ = true;
                                            break;
                                        }
                                        let _e897 = mips.member[_e893];
                                        phi_1330_ = 1u;
                                        phi_1333_ = _e785;
                                        phi_1335_ = _e784;
                                        phi_1337_ = 0u;
                                        phi_1339_ = _e783;
                                        phi_1341_ = _e781;
                                        loop {
                                            let _e907 = phi_1330_;
                                            let _e909 = phi_1333_;
                                            let _e911 = phi_1335_;
                                            let _e913 = phi_1337_;
                                            let _e915 = phi_1339_;
                                            let _e917 = phi_1341_;
                                            local_9 = _e911;
                                            local_10 = _e917;
                                            local_11 = _e909;
                                            local_12 = _e915;
                                            local_13 = _e917;
                                            local_14 = _e913;
                                            let _e918 = (_e907 < 5u);
                                            if _e918 {
                                                let _e920 = (_e739 >= f32(_e907));
                                                let _e921 = (_e907 & 31u);
                                                let _e923 = (_e102 >> bitcast<u32>(_e921));
                                                let _e925 = select(1u, _e923, (1u < _e923));
                                                let _e927 = (_e112 >> bitcast<u32>(_e921));
                                                let _e929 = select(1u, _e927, (1u < _e927));
                                                phi_1374_ = 0u;
                                                phi_1377_ = 0u;
                                                loop {
                                                    let _e933 = phi_1374_;
                                                    let _e935 = phi_1377_;
                                                    local_8 = _e935;
                                                    let _e936 = (_e933 < _e907);
                                                    if _e936 {
                                                        let _e937 = (_e933 & 31u);
                                                        let _e939 = (_e102 >> bitcast<u32>(_e937));
                                                        let _e943 = (_e112 >> bitcast<u32>(_e937));
                                                        phi_1375_ = (_e933 + 1u);
                                                        phi_1378_ = (_e935 + (select(1u, _e939, (1u < _e939)) * select(1u, _e943, (1u < _e943))));
                                                    } else {
                                                        phi_1375_ = u32();
                                                        phi_1378_ = u32();
                                                    }
                                                    let _e950 = phi_1375_;
                                                    let _e952 = phi_1378_;
                                                    continue;
                                                    continuing {
                                                        phi_1374_ = _e950;
                                                        phi_1377_ = _e952;
                                                        break if !(_e936);
                                                    }
                                                }
                                                let _e955 = local_8;
                                                phi_1331_ = (_e907 + 1u);
                                                phi_1334_ = select(_e909, f32(_e929), _e920);
                                                phi_1336_ = select(_e911, f32(_e925), _e920);
                                                phi_1338_ = select(_e913, _e955, _e920);
                                                phi_1340_ = select(_e915, _e929, _e920);
                                                phi_1342_ = select(_e917, _e925, _e920);
                                            } else {
                                                phi_1331_ = u32();
                                                phi_1334_ = f32();
                                                phi_1336_ = f32();
                                                phi_1338_ = u32();
                                                phi_1340_ = u32();
                                                phi_1342_ = u32();
                                            }
                                            let _e963 = phi_1331_;
                                            let _e965 = phi_1334_;
                                            let _e967 = phi_1336_;
                                            let _e969 = phi_1338_;
                                            let _e971 = phi_1340_;
                                            let _e973 = phi_1342_;
                                            continue;
                                            continuing {
                                                phi_1330_ = _e963;
                                                phi_1333_ = _e965;
                                                phi_1335_ = _e967;
                                                phi_1337_ = _e969;
                                                phi_1339_ = _e971;
                                                phi_1341_ = _e973;
                                                break if !(_e918);
                                            }
                                        }
                                        let _e976 = local_9;
                                        let _e977 = (_e778 * _e976);
                                        if (_e977 > 0f) {
                                            let _e983 = select(select(u32(_e977), 0u, (_e977 < 0f)), 4294967295u, (_e977 > 4294967000f));
                                            let _e985 = local_10;
                                            let _e986 = (_e985 - 1u);
                                            phi_1435_ = select(_e983, _e986, (_e986 < _e983));
                                        } else {
                                            phi_1435_ = 0u;
                                        }
                                        let _e990 = phi_1435_;
                                        let _e992 = local_11;
                                        let _e993 = (_e779 * _e992);
                                        if (_e993 > 0f) {
                                            let _e999 = select(select(u32(_e993), 0u, (_e993 < 0f)), 4294967295u, (_e993 > 4294967000f));
                                            let _e1001 = local_12;
                                            let _e1002 = (_e1001 - 1u);
                                            phi_1454_ = select(_e999, _e1002, (_e1002 < _e999));
                                        } else {
                                            phi_1454_ = 0u;
                                        }
                                        let _e1006 = phi_1454_;
                                        let _e1008 = local_13;
                                        let _e1011 = local_14;
                                        let _e1013 = ((_e1011 + (_e1006 * _e1008)) + _e990);
                                        if (_e1013 < _e86) {
                                        } else {
                                            phi_2450_ = true;
                                            break;
                                        }
                                        let _e1017 = mips.member[_e1013];
                                        let _e1026 = (((((_e776 * 2f) - 1f) * _e387) * _e897) - _e389);
                                        let _e1027 = (((((_e777 * -2f) + 1f) * _e396) * _e897) - _e398);
                                        let _e1028 = (_e897 - _e380);
                                        let _e1031 = ((_e1026 * _e1026) + (_e1027 * _e1027));
                                        let _e1034 = sqrt((_e1031 + (_e1028 * _e1028)));
                                        let _e1043 = (1f + _e694);
                                        let _e1044 = (_e1028 * _e1043);
                                        let _e1047 = sqrt((_e1031 + (_e1044 * _e1044)));
                                        let _e1048 = (_e568 > 0f);
                                        if _e1048 {
                                            let _e1051 = ((-(_e1047) + _e491) / _e568);
                                            phi_1537_ = select(0f, select(1f, _e1051, (_e1051 < 1f)), (_e1051 > 0f));
                                        } else {
                                            phi_1537_ = select(0f, 1f, (_e1047 <= _e491));
                                        }
                                        let _e1059 = phi_1537_;
                                        let _e1062 = (_e689 + ((((((_e1026 / _e1034) * _e409) + ((_e1027 / _e1034) * _e410)) + ((_e1028 / _e1034) * _e411)) - _e689) * _e1059));
                                        let _e1063 = (((((_e778 * 2f) - 1f) * _e387) * _e1017) - _e389);
                                        let _e1064 = (((((_e779 * -2f) + 1f) * _e396) * _e1017) - _e398);
                                        let _e1065 = (_e1017 - _e380);
                                        let _e1068 = ((_e1063 * _e1063) + (_e1064 * _e1064));
                                        let _e1071 = sqrt((_e1068 + (_e1065 * _e1065)));
                                        let _e1080 = (_e1065 * _e1043);
                                        let _e1083 = sqrt((_e1068 + (_e1080 * _e1080)));
                                        if _e1048 {
                                            let _e1086 = ((-(_e1083) + _e491) / _e568);
                                            phi_1597_ = select(0f, select(1f, _e1086, (_e1086 < 1f)), (_e1086 > 0f));
                                        } else {
                                            phi_1597_ = select(0f, 1f, (_e1083 <= _e491));
                                        }
                                        let _e1094 = phi_1597_;
                                        let _e1097 = (_e691 + ((((((_e1063 / _e1071) * _e409) + ((_e1064 / _e1071) * _e410)) + ((_e1065 / _e1071) * _e411)) - _e691) * _e1094));
                                        if (_e700 != _e700) {
                                            phi_2235_ = true;
                                        } else {
                                            phi_2235_ = (_e1062 >= _e700);
                                        }
                                        let _e1101 = phi_2235_;
                                        if (_e698 != _e698) {
                                            phi_2250_ = true;
                                        } else {
                                            phi_2250_ = (_e1097 >= _e698);
                                        }
                                        let _e1106 = phi_2250_;
                                        phi_997_ = (_e696 + 1u);
                                        phi_1000_ = select(_e698, _e1097, _e1106);
                                        phi_1002_ = select(_e700, _e1062, _e1101);
                                    } else {
                                        phi_997_ = u32();
                                        phi_1000_ = f32();
                                        phi_1002_ = f32();
                                    }
                                    let _e1110 = phi_997_;
                                    let _e1112 = phi_1000_;
                                    let _e1114 = phi_1002_;
                                    continue;
                                    continuing {
                                        phi_996_ = _e1110;
                                        phi_999_ = _e1112;
                                        phi_1001_ = _e1114;
                                        phi_2450_ = _e582;
                                        break if !(_e701);
                                    }
                                }
                                let _e1117 = phi_2450_;
                                phi_2585_ = _e1117;
                                if _e1117 {
                                    break;
                                }
                                let _e1119 = local_15;
                                let _e1120 = abs(_e1119);
                                let _e1131 = (((_e1120 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1120))) >> bitcast<u32>(1i))))));
                                let _e1133 = local_16;
                                let _e1136 = select((3.141593f - _e1131), _e1131, (_e1133 >= 0f));
                                let _e1137 = -(_e1136);
                                let _e1139 = local_17;
                                let _e1140 = abs(_e1139);
                                let _e1151 = (((_e1140 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1140))) >> bitcast<u32>(1i))))));
                                let _e1153 = local_18;
                                let _e1156 = select((3.141593f - _e1151), _e1151, (_e1153 >= 0f));
                                let _e1159 = (_e647 + ((1f - _e647) * 0.05f));
                                let _e1160 = (_e1136 * -2f);
                                let _e1161 = sin(_e682);
                                let _e1167 = (_e1156 * 2f);
                                let _e1179 = params.member.member_13;
                                if (_e1179 == 0u) {
                                    phi_1816_ = _e586;
                                } else {
                                    let _e1185 = ((_e1136 * -3f) - _e682);
                                    let _e1193 = ((_e1156 * 3f) - _e682);
                                    let _e1198 = (_e1137 + _e682);
                                    let _e1200 = (_e1156 + _e682);
                                    let _e1205 = (((((((sin((_e1137 - _e682)) * 6f) - sin(_e1185)) + (sin((_e1156 - _e682)) * 6f)) - sin(_e1193)) + (_e1161 * 16f)) - ((sin(_e1198) + sin(_e1200)) * 3f)) * 0.083333336f);
                                    let _e1217 = (((-(cos(_e1185)) - cos(_e1193)) + (cos(_e682) * 8f)) - ((cos(_e1198) + cos(_e1200)) * 3f));
                                    let _e1218 = (_e596 * _e1205);
                                    let _e1219 = (_e595 * _e1205);
                                    let _e1220 = (_e1217 * -0.083333336f);
                                    let _e1221 = (-1f * _e411);
                                    let _e1222 = (-1f * _e409);
                                    let _e1224 = (1f / (_e1221 + 1f));
                                    let _e1225 = (_e1224 * _e410);
                                    let _e1229 = (_e1225 * _e1222);
                                    let _e1250 = (_e1221 > 0.9997f);
                                    let _e1251 = (_e1221 < -0.9997f);
                                    phi_1816_ = (_e586 + vec3<f32>((select(select(((((_e1221 + (_e1225 * _e410)) * _e1218) + (_e1229 * _e1219)) + (_e1222 * _e1220)), _e1218, _e1251), _e1218, _e1250) * _e1159), (select(select((((_e1229 * _e1218) + ((_e1221 + ((_e1224 * _e1222) * _e1222)) * _e1219)) + (-(_e410) * _e1220)), -(_e1219), _e1251), _e1219, _e1250) * _e1159), (select(select((((_e409 * _e1218) + (_e410 * _e1219)) + (_e1221 * _e1220)), (_e1217 * 0.083333336f), _e1251), _e1220, _e1250) * _e1159)));
                                }
                                let _e1264 = phi_1816_;
                                phi_2586_ = _e1117;
                                phi_821_ = (_e584 + 1u);
                                phi_824_ = _e1264;
                                phi_826_ = (_e588 + ((0.25f * (((_e666 + (_e1160 * _e1161)) - cos((_e1160 - _e682))) + ((_e666 + (_e1167 * _e1161)) - cos((_e1167 - _e682))))) * _e1159));
                            } else {
                                phi_2586_ = _e582;
                                phi_821_ = u32();
                                phi_824_ = vec3<f32>();
                                phi_826_ = f32();
                            }
                            let _e1267 = phi_2586_;
                            let _e1269 = phi_821_;
                            let _e1271 = phi_824_;
                            let _e1273 = phi_826_;
                            continue;
                            continuing {
                                phi_2518_ = _e1267;
                                phi_820_ = _e1269;
                                phi_823_ = _e1271;
                                phi_825_ = _e1273;
                                phi_2585_ = _e1267;
                                break if !(_e589);
                            }
                        }
                        let _e1276 = phi_2585_;
                        if _e1276 {
                            break;
                        }
                        let _e1279 = local_19;
                        let _e1282 = local_20;
                        phi_1822_ = type_22((_e1279 / f32(_e580)), _e1282);
                    } else {
                        phi_1822_ = type_22(1f, vec3<f32>(0f, 0f, 0f));
                    }
                    let _e1285 = phi_1822_;
                    if _e564 {
                        let _e1290 = params.member.member_6;
                        let _e1291 = pow(_e1285.member, _e1290);
                        if (_e1291 != _e1291) {
                            phi_2277_ = true;
                        } else {
                            phi_2277_ = (0.03f >= _e1291);
                        }
                        let _e1295 = phi_2277_;
                        let _e1296 = select(_e1291, 0.03f, _e1295);
                        let _e1299 = params.member.member_13;
                        if (_e1299 == 0u) {
                            let _e1301 = (_e1296 * 0.6666667f);
                            let _e1307 = ((select(0f, select(1f, _e1301, (_e1301 < 1f)), (_e1301 > 0f)) * 255f) + 0.5f);
                            phi_1898_ = select(select(u32(_e1307), 0u, (_e1307 < 0f)), 4294967295u, (_e1307 > 4294967000f));
                        } else {
                            let _e1321 = sqrt((((_e1285.member_1.x * _e1285.member_1.x) + (_e1285.member_1.y * _e1285.member_1.y)) + (_e1285.member_1.z * _e1285.member_1.z)));
                            if (_e1321 > 0f) {
                                phi_1877_ = (_e1285.member_1 / vec3(_e1321));
                            } else {
                                phi_1877_ = _e484;
                            }
                            let _e1326 = phi_1877_;
                            let _e1327 = (_e1296 * 0.6666667f);
                            let _e1334 = ((_e1326.x * 0.5f) + 0.5f);
                            let _e1335 = ((_e1326.y * 0.5f) + 0.5f);
                            let _e1336 = ((_e1326.z * 0.5f) + 0.5f);
                            let _e1342 = ((select(0f, select(1f, _e1334, (_e1334 < 1f)), (_e1334 > 0f)) * 255f) + 0.5f);
                            let _e1353 = ((select(0f, select(1f, _e1335, (_e1335 < 1f)), (_e1335 > 0f)) * 255f) + 0.5f);
                            let _e1367 = ((select(0f, select(1f, _e1336, (_e1336 < 1f)), (_e1336 > 0f)) * 255f) + 0.5f);
                            let _e1381 = ((select(0f, select(1f, _e1327, (_e1327 < 1f)), (_e1327 > 0f)) * 255f) + 0.5f);
                            phi_1898_ = (((select(select(u32(_e1342), 0u, (_e1342 < 0f)), 4294967295u, (_e1342 > 4294967000f)) | (select(select(u32(_e1353), 0u, (_e1353 < 0f)), 4294967295u, (_e1353 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1367), 0u, (_e1367 < 0f)), 4294967295u, (_e1367 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1381), 0u, (_e1381 < 0f)), 4294967295u, (_e1381 > 4294967000f)) << bitcast<u32>(24i)));
                        }
                        let _e1391 = phi_1898_;
                        phi_1943_ = _e1391;
                    } else {
                        let _e1394 = params.member.member_13;
                        phi_1943_ = select(2852159616u, 170u, (_e1394 == 0u));
                    }
                    let _e1398 = phi_1943_;
                    if (_e118 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e118] = _e1398;
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
