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

struct type_21 {
    member: u32,
    member_1: u32,
}

struct type_22 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_20,
}

struct type_23 {
    member: type_22,
}

struct type_25 {
    member: u32,
    member_1: f32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;
@group(0) @binding(4) 
var<uniform> params: type_23;

fn function_() {
    var local: array<type_25, 4>;
    var phi_303_: i32;
    var phi_322_: i32;
    var phi_362_: i32;
    var phi_381_: i32;
    var phi_421_: i32;
    var phi_440_: i32;
    var phi_480_: i32;
    var phi_499_: i32;
    var phi_579_: f32;
    var phi_590_: f32;
    var phi_601_: f32;
    var phi_612_: f32;
    var phi_2307_: f32;
    var phi_2322_: f32;
    var phi_2326_: f32;
    var phi_2327_: bool;
    var phi_2350_: f32;
    var phi_2365_: f32;
    var phi_2369_: f32;
    var phi_2370_: bool;
    var phi_2393_: f32;
    var phi_2408_: f32;
    var phi_2412_: f32;
    var phi_2413_: bool;
    var phi_2436_: f32;
    var phi_2451_: f32;
    var phi_2455_: f32;
    var phi_2456_: bool;
    var phi_2478_: bool;
    var phi_2493_: bool;
    var phi_715_: vec2<f32>;
    var phi_743_: vec3<f32>;
    var phi_764_: u32;
    var phi_767_: u32;
    var phi_769_: u32;
    var phi_771_: u32;
    var phi_800_: u32;
    var phi_801_: u32;
    var phi_802_: u32;
    var phi_803_: u32;
    var phi_765_: u32;
    var phi_768_: u32;
    var phi_770_: u32;
    var phi_772_: u32;
    var local_1: u32;
    var phi_826_: bool;
    var phi_2652_: bool;
    var phi_849_: u32;
    var phi_852_: f32;
    var phi_854_: f32;
    var phi_971_: f32;
    var phi_991_: f32;
    var phi_1030_: u32;
    var phi_1033_: u32;
    var phi_1087_: f32;
    var phi_1111_: f32;
    var phi_1134_: u32;
    var phi_1150_: f32;
    var phi_1152_: f32;
    var phi_1153_: bool;
    var phi_1173_: f32;
    var phi_1175_: f32;
    var phi_1176_: bool;
    var phi_1228_: u32;
    var phi_1248_: u32;
    var phi_1250_: u32;
    var phi_1253_: u32;
    var phi_1251_: u32;
    var phi_1254_: u32;
    var local_2: u32;
    var phi_1336_: u32;
    var phi_1356_: u32;
    var phi_1358_: u32;
    var phi_1361_: u32;
    var phi_1359_: u32;
    var phi_1362_: u32;
    var local_3: u32;
    var phi_1437_: bool;
    var phi_1540_: f32;
    var phi_1553_: f32;
    var phi_2508_: bool;
    var phi_1592_: f32;
    var phi_1607_: f32;
    var phi_1635_: f32;
    var phi_1650_: f32;
    var phi_2523_: bool;
    var phi_2538_: bool;
    var phi_1698_: u32;
    var phi_1699_: u32;
    var phi_1711_: u32;
    var phi_1712_: bool;
    var phi_1731_: u32;
    var phi_1734_: u32;
    var phi_1735_: u32;
    var phi_1736_: bool;
    var phi_1741_: u32;
    var phi_1742_: u32;
    var phi_1743_: u32;
    var phi_1771_: bool;
    var phi_1874_: f32;
    var phi_1887_: f32;
    var phi_2553_: bool;
    var phi_1926_: f32;
    var phi_1941_: f32;
    var phi_1969_: f32;
    var phi_1984_: f32;
    var phi_2568_: bool;
    var phi_2583_: bool;
    var phi_2032_: u32;
    var phi_2033_: u32;
    var phi_2045_: u32;
    var phi_2046_: bool;
    var phi_2065_: u32;
    var phi_2068_: u32;
    var phi_2069_: u32;
    var phi_2070_: bool;
    var phi_2075_: u32;
    var phi_2076_: u32;
    var phi_2077_: u32;
    var phi_1031_: u32;
    var phi_1034_: u32;
    var phi_2603_: bool;
    var local_4: u32;
    var phi_2161_: u32;
    var phi_2164_: f32;
    var local_5: u32;
    var phi_2162_: u32;
    var phi_2165_: f32;
    var phi_2770_: bool;
    var local_6: f32;
    var phi_2200_: f32;
    var phi_2781_: bool;
    var phi_2211_: f32;
    var phi_2212_: f32;
    var phi_2106_: f32;
    var phi_2108_: u32;
    var phi_2111_: f32;
    var phi_2113_: f32;
    var phi_2139_: f32;
    var local_7: u32;
    var phi_2149_: f32;
    var phi_2109_: u32;
    var phi_2112_: f32;
    var phi_2114_: f32;
    var local_8: f32;
    var phi_2775_: bool;
    var phi_2213_: f32;
    var phi_2214_: f32;
    var phi_2774_: bool;
    var phi_850_: u32;
    var phi_853_: f32;
    var phi_855_: f32;
    var phi_2773_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var phi_2221_: f32;
    var phi_2598_: bool;
    var phi_2237_: f32;
    var phi_2269_: type_21;

    switch bitcast<i32>(0u) {
        default: {
            let _e82 = id_1;
            let _e84 = arrayLength((&mips.member));
            let _e96 = params.member.member_4.member.member[0u];
            let _e101 = select(select(u32(_e96), 0u, (_e96 < 0f)), 4294967295u, (_e96 > 4294967000f));
            let _e107 = params.member.member_4.member.member[1u];
            let _e112 = select(select(u32(_e107), 0u, (_e107 < 0f)), 4294967295u, (_e107 > 4294967000f));
            if (_e82.x >= _e101) {
            } else {
                if (_e82.y >= _e112) {
                } else {
                    let _e118 = ((_e82.y * _e101) + _e82.x);
                    if (_e118 < _e84) {
                    } else {
                        break;
                    }
                    let _e122 = mips.member[_e118];
                    let _e123 = bitcast<i32>(_e82.x);
                    let _e124 = (_e123 + -1i);
                    let _e126 = (bitcast<i32>(_e101) - 1i);
                    let _e127 = (0i <= _e126);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e124 < 0i) {
                        phi_303_ = 0i;
                    } else {
                        phi_303_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_303_;
                    let _e134 = bitcast<i32>(_e82.y);
                    let _e136 = (bitcast<i32>(_e112) - 1i);
                    let _e137 = (0i <= _e136);
                    if _e137 {
                    } else {
                        break;
                    }
                    let _e138 = (_e134 < 0i);
                    if _e138 {
                        phi_322_ = 0i;
                    } else {
                        phi_322_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e142 = phi_322_;
                    let _e145 = ((bitcast<u32>(_e142) * _e101) + bitcast<u32>(_e132));
                    if (_e145 < _e84) {
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
                        phi_362_ = 0i;
                    } else {
                        phi_362_ = select(_e150, _e126, (_e150 > _e126));
                    }
                    let _e155 = phi_362_;
                    if _e137 {
                    } else {
                        break;
                    }
                    if _e138 {
                        phi_381_ = 0i;
                    } else {
                        phi_381_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e160 = phi_381_;
                    let _e163 = ((bitcast<u32>(_e160) * _e101) + bitcast<u32>(_e155));
                    if (_e163 < _e84) {
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
                        phi_421_ = 0i;
                    } else {
                        phi_421_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e172 = phi_421_;
                    let _e174 = (_e134 + -1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e174 < 0i) {
                        phi_440_ = 0i;
                    } else {
                        phi_440_ = select(_e174, _e136, (_e174 > _e136));
                    }
                    let _e179 = phi_440_;
                    let _e182 = ((bitcast<u32>(_e179) * _e101) + bitcast<u32>(_e172));
                    if (_e182 < _e84) {
                    } else {
                        break;
                    }
                    let _e186 = mips.member[_e182];
                    if _e127 {
                    } else {
                        break;
                    }
                    if _e168 {
                        phi_480_ = 0i;
                    } else {
                        phi_480_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e190 = phi_480_;
                    let _e192 = (_e134 + 1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e192 < 0i) {
                        phi_499_ = 0i;
                    } else {
                        phi_499_ = select(_e192, _e136, (_e192 > _e136));
                    }
                    let _e197 = phi_499_;
                    let _e200 = ((bitcast<u32>(_e197) * _e101) + bitcast<u32>(_e190));
                    if (_e200 < _e84) {
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
                    if (_e240 > 0f) {
                        phi_579_ = select(1f, _e240, (_e240 < 1f));
                    } else {
                        phi_579_ = 0f;
                    }
                    let _e245 = phi_579_;
                    let _e246 = (1.25f - (select(_e224, _e220, (_e220 < _e224)) / _e235));
                    if (_e246 > 0f) {
                        phi_590_ = select(1f, _e246, (_e246 < 1f));
                    } else {
                        phi_590_ = 0f;
                    }
                    let _e251 = phi_590_;
                    let _e252 = (1.25f - (select(_e225, _e221, (_e221 < _e225)) / _e235));
                    if (_e252 > 0f) {
                        phi_601_ = select(1f, _e252, (_e252 < 1f));
                    } else {
                        phi_601_ = 0f;
                    }
                    let _e257 = phi_601_;
                    let _e258 = (1.25f - (select(_e226, _e222, (_e222 < _e226)) / _e235));
                    if (_e258 > 0f) {
                        phi_612_ = select(1f, _e258, (_e258 < 1f));
                    } else {
                        phi_612_ = 0f;
                    }
                    let _e263 = phi_612_;
                    if (_e245 > 0f) {
                        phi_2307_ = select(1f, _e245, (_e245 < 1f));
                    } else {
                        phi_2307_ = 0f;
                    }
                    let _e268 = phi_2307_;
                    let _e269 = (_e268 * 2.9f);
                    let _e271 = floor((_e269 + 0.5f));
                    if ((_e271 - _e269) == 0.5f) {
                        let _e277 = ((floor((_e271 * 0.5f)) * 2f) != _e271);
                        if _e277 {
                            phi_2322_ = (_e271 - 1f);
                        } else {
                            phi_2322_ = f32();
                        }
                        let _e280 = phi_2322_;
                        phi_2326_ = _e280;
                        phi_2327_ = select(true, false, _e277);
                    } else {
                        phi_2326_ = f32();
                        phi_2327_ = true;
                    }
                    let _e283 = phi_2326_;
                    let _e285 = phi_2327_;
                    let _e286 = select(_e283, _e271, _e285);
                    if (_e251 > 0f) {
                        phi_2350_ = select(1f, _e251, (_e251 < 1f));
                    } else {
                        phi_2350_ = 0f;
                    }
                    let _e297 = phi_2350_;
                    let _e298 = (_e297 * 2.9f);
                    let _e300 = floor((_e298 + 0.5f));
                    if ((_e300 - _e298) == 0.5f) {
                        let _e306 = ((floor((_e300 * 0.5f)) * 2f) != _e300);
                        if _e306 {
                            phi_2365_ = (_e300 - 1f);
                        } else {
                            phi_2365_ = f32();
                        }
                        let _e309 = phi_2365_;
                        phi_2369_ = _e309;
                        phi_2370_ = select(true, false, _e306);
                    } else {
                        phi_2369_ = f32();
                        phi_2370_ = true;
                    }
                    let _e312 = phi_2369_;
                    let _e314 = phi_2370_;
                    let _e315 = select(_e312, _e300, _e314);
                    if (_e257 > 0f) {
                        phi_2393_ = select(1f, _e257, (_e257 < 1f));
                    } else {
                        phi_2393_ = 0f;
                    }
                    let _e327 = phi_2393_;
                    let _e328 = (_e327 * 2.9f);
                    let _e330 = floor((_e328 + 0.5f));
                    if ((_e330 - _e328) == 0.5f) {
                        let _e336 = ((floor((_e330 * 0.5f)) * 2f) != _e330);
                        if _e336 {
                            phi_2408_ = (_e330 - 1f);
                        } else {
                            phi_2408_ = f32();
                        }
                        let _e339 = phi_2408_;
                        phi_2412_ = _e339;
                        phi_2413_ = select(true, false, _e336);
                    } else {
                        phi_2412_ = f32();
                        phi_2413_ = true;
                    }
                    let _e342 = phi_2412_;
                    let _e344 = phi_2413_;
                    let _e345 = select(_e342, _e330, _e344);
                    if (_e263 > 0f) {
                        phi_2436_ = select(1f, _e263, (_e263 < 1f));
                    } else {
                        phi_2436_ = 0f;
                    }
                    let _e357 = phi_2436_;
                    let _e358 = (_e357 * 2.9f);
                    let _e360 = floor((_e358 + 0.5f));
                    if ((_e360 - _e358) == 0.5f) {
                        let _e366 = ((floor((_e360 * 0.5f)) * 2f) != _e360);
                        if _e366 {
                            phi_2451_ = (_e360 - 1f);
                        } else {
                            phi_2451_ = f32();
                        }
                        let _e369 = phi_2451_;
                        phi_2455_ = _e369;
                        phi_2456_ = select(true, false, _e366);
                    } else {
                        phi_2455_ = f32();
                        phi_2456_ = true;
                    }
                    let _e372 = phi_2455_;
                    let _e374 = phi_2456_;
                    let _e375 = select(_e372, _e360, _e374);
                    let _e381 = ((((64u * select(select(u32(_e286), 0u, (_e286 < 0f)), 4294967295u, (_e286 > 4294967000f))) + (16u * select(select(u32(_e315), 0u, (_e315 < 0f)), 4294967295u, (_e315 > 4294967000f)))) + (4u * select(select(u32(_e345), 0u, (_e345 < 0f)), 4294967295u, (_e345 > 4294967000f)))) + select(select(u32(_e375), 0u, (_e375 < 0f)), 4294967295u, (_e375 > 4294967000f)));
                    let _e386 = ((f32(_e82.x) + 0.5f) / _e96);
                    let _e387 = ((f32(_e82.y) + 0.5f) / _e107);
                    let _e388 = (_e122 * 0.99999f);
                    let _e396 = params.member.member_4.member.member_1[0u];
                    let _e398 = ((((2f * _e386) - 1f) * _e396) * _e388);
                    let _e406 = params.member.member_4.member.member_1[1u];
                    let _e408 = (((1f - (2f * _e387)) * _e406) * _e388);
                    let _e409 = -(_e398);
                    let _e410 = -(_e408);
                    let _e411 = (_e122 * -0.99999f);
                    let _e418 = (1f / sqrt((((_e409 * _e409) + (_e410 * _e410)) + (_e411 * _e411))));
                    let _e419 = (_e409 * _e418);
                    let _e420 = (_e410 * _e418);
                    let _e421 = (_e411 * _e418);
                    if (_e118 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e425 = normals.member[_e118];
                    let _e433 = (f32((bitcast<i32>(((_e425 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e433 != _e433) {
                        phi_2478_ = true;
                    } else {
                        phi_2478_ = (-1f >= _e433);
                    }
                    let _e437 = phi_2478_;
                    let _e438 = select(_e433, -1f, _e437);
                    let _e448 = (f32((bitcast<i32>((((_e425 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e448 != _e448) {
                        phi_2493_ = true;
                    } else {
                        phi_2493_ = (-1f >= _e448);
                    }
                    let _e452 = phi_2493_;
                    let _e453 = select(_e448, -1f, _e452);
                    let _e456 = (1f - abs(_e438));
                    let _e457 = abs(_e453);
                    let _e458 = (_e456 - _e457);
                    if (_e458 < 0f) {
                        phi_715_ = vec2<f32>(((1f - _e457) * select(1f, -1f, (_e438 < 0f))), (_e456 * select(1f, -1f, (_e453 < 0f))));
                    } else {
                        phi_715_ = vec2<f32>(_e438, _e453);
                    }
                    let _e469 = phi_715_;
                    let _e478 = (1f / sqrt((((_e469.x * _e469.x) + (_e469.y * _e469.y)) + (_e458 * _e458))));
                    let _e479 = (_e469.x * _e478);
                    let _e480 = (_e469.y * _e478);
                    let _e481 = (_e458 * _e478);
                    let _e482 = -(_e481);
                    if ((((_e479 * _e419) + (_e480 * _e420)) + (_e482 * _e421)) < 0f) {
                        phi_743_ = vec3<f32>(-(_e479), -(_e480), _e481);
                    } else {
                        phi_743_ = vec3<f32>(_e479, _e480, _e482);
                    }
                    let _e494 = phi_743_;
                    let _e498 = params.member.member_4.member_1;
                    let _e502 = params.member.member_4.member_2;
                    let _e507 = ((_e498 * _e502) / (((_e122 * 1.99998f) * _e396) / _e96));
                    let _e512 = params.member.member_4.member_11;
                    phi_764_ = (_e82.y & 63u);
                    phi_767_ = (_e82.x & 63u);
                    phi_769_ = 32u;
                    phi_771_ = 0u;
                    loop {
                        let _e516 = phi_764_;
                        let _e518 = phi_767_;
                        let _e520 = phi_769_;
                        let _e522 = phi_771_;
                        local_1 = _e522;
                        let _e523 = (_e520 > 0u);
                        if _e523 {
                            let _e526 = select(0u, 1u, ((_e518 & _e520) != 0u));
                            let _e529 = select(0u, 1u, ((_e516 & _e520) != 0u));
                            if (_e529 == 0u) {
                                if (_e526 == 1u) {
                                    phi_800_ = (63u - _e516);
                                    phi_801_ = (63u - _e518);
                                } else {
                                    phi_800_ = _e516;
                                    phi_801_ = _e518;
                                }
                                let _e540 = phi_800_;
                                let _e542 = phi_801_;
                                phi_802_ = _e542;
                                phi_803_ = _e540;
                            } else {
                                phi_802_ = _e516;
                                phi_803_ = _e518;
                            }
                            let _e544 = phi_802_;
                            let _e546 = phi_803_;
                            phi_765_ = _e544;
                            phi_768_ = _e546;
                            phi_770_ = (_e520 / 2u);
                            phi_772_ = (_e522 + ((_e520 * _e520) * ((3u * _e526) ^ _e529)));
                        } else {
                            phi_765_ = u32();
                            phi_768_ = u32();
                            phi_770_ = u32();
                            phi_772_ = u32();
                        }
                        let _e549 = phi_765_;
                        let _e551 = phi_768_;
                        let _e553 = phi_770_;
                        let _e555 = phi_772_;
                        continue;
                        continuing {
                            phi_764_ = _e549;
                            phi_767_ = _e551;
                            phi_769_ = _e553;
                            phi_771_ = _e555;
                            break if !(_e523);
                        }
                    }
                    let _e560 = local_1;
                    let _e562 = f32((_e560 + (288u * (_e512 % 64u))));
                    let _e564 = (0.5f + (_e562 * 0.7548777f));
                    let _e568 = (0.5f + (_e562 * 0.5698403f));
                    let _e575 = params.member.member_4.member.member_3;
                    if (_e122 > 0f) {
                        phi_826_ = (_e122 < _e575);
                    } else {
                        phi_826_ = false;
                    }
                    let _e579 = phi_826_;
                    if _e579 {
                        let _e584 = params.member.member_4.member_8;
                        let _e586 = select(1u, _e584, (1u < _e584));
                        phi_2652_ = false;
                        phi_849_ = 0u;
                        phi_852_ = 0f;
                        phi_854_ = 0f;
                        loop {
                            let _e588 = phi_2652_;
                            let _e590 = phi_849_;
                            let _e592 = phi_852_;
                            let _e594 = phi_854_;
                            local_9 = _e592;
                            local_10 = _e594;
                            local_11 = _e592;
                            let _e595 = (_e590 < _e586);
                            if _e595 {
                                let _e600 = ((3.1415927f * (f32(_e590) + (_e564 - floor(_e564)))) / f32(_e586));
                                let _e601 = sin(_e600);
                                let _e602 = cos(_e600);
                                let _e608 = ((_e602 * _e419) + (_e601 * _e420));
                                let _e612 = (_e602 - (_e419 * _e608));
                                let _e613 = (_e601 - (_e420 * _e608));
                                let _e614 = -((_e421 * _e608));
                                let _e617 = ((_e613 * _e421) - (_e420 * _e614));
                                let _e620 = ((_e614 * _e419) - (_e421 * _e612));
                                let _e623 = ((_e612 * _e420) - (_e419 * _e613));
                                let _e630 = (1f / sqrt((((_e617 * _e617) + (_e620 * _e620)) + (_e623 * _e623))));
                                let _e631 = (_e617 * _e630);
                                let _e632 = (_e620 * _e630);
                                let _e633 = (_e623 * _e630);
                                let _e641 = (((_e494.x * _e631) + (_e494.y * _e632)) + (_e494.z * _e633));
                                let _e645 = (_e494.x - (_e631 * _e641));
                                let _e646 = (_e494.y - (_e632 * _e641));
                                let _e647 = (_e494.z - (_e633 * _e641));
                                let _e653 = sqrt((((_e645 * _e645) + (_e646 * _e646)) + (_e647 * _e647)));
                                let _e658 = (((_e612 * _e645) + (_e613 * _e646)) + (_e614 * _e647));
                                if (_e658 > 0f) {
                                    phi_971_ = 1f;
                                } else {
                                    phi_971_ = select(0f, -1f, (_e658 < 0f));
                                }
                                let _e663 = phi_971_;
                                let _e669 = ((((_e645 * _e419) + (_e646 * _e420)) + (_e647 * _e421)) / _e653);
                                if (_e669 > 0f) {
                                    phi_991_ = select(1f, _e669, (_e669 < 1f));
                                } else {
                                    phi_991_ = 0f;
                                }
                                let _e674 = phi_991_;
                                let _e676 = (_e663 * acos(_e674));
                                let _e680 = params.member.member_4.member_9;
                                let _e682 = select(1u, _e680, (1u < _e680));
                                phi_1030_ = 0u;
                                phi_1033_ = 0u;
                                loop {
                                    let _e684 = phi_1030_;
                                    let _e686 = phi_1033_;
                                    local_4 = _e686;
                                    local_5 = _e686;
                                    local_7 = _e686;
                                    let _e687 = (_e684 < _e682);
                                    if _e687 {
                                        let _e692 = ((_e568 - floor(_e568)) + (f32((_e590 + (_e684 * _e682))) * 0.618034f));
                                        let _e698 = ((f32(_e684) + (_e692 - floor(_e692))) / f32(_e682));
                                        let _e702 = params.member.member_4.member_4;
                                        if (_e702 == 2f) {
                                            phi_1087_ = (_e698 * _e698);
                                        } else {
                                            phi_1087_ = pow(_e698, _e702);
                                        }
                                        let _e707 = phi_1087_;
                                        let _e708 = (_e707 + (1.3f / _e507));
                                        let _e709 = ((_e602 * _e507) * _e708);
                                        let _e710 = ((-(_e601) * _e507) * _e708);
                                        let _e719 = params.member.member_4.member_7;
                                        let _e720 = (log2(sqrt(((_e709 * _e709) + (_e710 * _e710)))) - _e719);
                                        if (_e720 > 0f) {
                                            phi_1111_ = select(5f, _e720, (_e720 < 5f));
                                        } else {
                                            phi_1111_ = 0f;
                                        }
                                        let _e725 = phi_1111_;
                                        let _e728 = (-1f - floor((-0.5f - _e725)));
                                        if (_e728 > 0f) {
                                            let _e734 = select(select(u32(_e728), 0u, (_e728 < 0f)), 4294967295u, (_e728 > 4294967000f));
                                            phi_1134_ = select(_e734, 4u, (4u < _e734));
                                        } else {
                                            phi_1134_ = 0u;
                                        }
                                        let _e738 = phi_1134_;
                                        let _e740 = floor((_e709 + 0.5f));
                                        if ((_e740 - _e709) == 0.5f) {
                                            let _e746 = ((floor((_e740 * 0.5f)) * 2f) != _e740);
                                            if _e746 {
                                                phi_1150_ = (_e740 - 1f);
                                            } else {
                                                phi_1150_ = f32();
                                            }
                                            let _e749 = phi_1150_;
                                            phi_1152_ = _e749;
                                            phi_1153_ = select(true, false, _e746);
                                        } else {
                                            phi_1152_ = f32();
                                            phi_1153_ = true;
                                        }
                                        let _e752 = phi_1152_;
                                        let _e754 = phi_1153_;
                                        let _e757 = floor((_e710 + 0.5f));
                                        if ((_e757 - _e710) == 0.5f) {
                                            let _e763 = ((floor((_e757 * 0.5f)) * 2f) != _e757);
                                            if _e763 {
                                                phi_1173_ = (_e757 - 1f);
                                            } else {
                                                phi_1173_ = f32();
                                            }
                                            let _e766 = phi_1173_;
                                            phi_1175_ = _e766;
                                            phi_1176_ = select(true, false, _e763);
                                        } else {
                                            phi_1175_ = f32();
                                            phi_1176_ = true;
                                        }
                                        let _e769 = phi_1175_;
                                        let _e771 = phi_1176_;
                                        let _e773 = (select(_e752, _e740, _e754) / _e96);
                                        let _e774 = (select(_e769, _e757, _e771) / _e107);
                                        let _e775 = (_e386 + _e773);
                                        let _e776 = (_e387 + _e774);
                                        let _e777 = (_e386 - _e773);
                                        let _e778 = (_e387 - _e774);
                                        let _e779 = (_e738 & 31u);
                                        let _e781 = (_e101 >> bitcast<u32>(_e779));
                                        let _e783 = select(1u, _e781, (1u < _e781));
                                        let _e785 = (_e112 >> bitcast<u32>(_e779));
                                        let _e787 = select(1u, _e785, (1u < _e785));
                                        let _e788 = f32(_e783);
                                        let _e789 = (_e775 * _e788);
                                        if (_e789 > 0f) {
                                            let _e795 = select(select(u32(_e789), 0u, (_e789 < 0f)), 4294967295u, (_e789 > 4294967000f));
                                            let _e796 = (_e783 - 1u);
                                            phi_1228_ = select(_e795, _e796, (_e796 < _e795));
                                        } else {
                                            phi_1228_ = 0u;
                                        }
                                        let _e800 = phi_1228_;
                                        let _e801 = f32(_e787);
                                        let _e802 = (_e776 * _e801);
                                        if (_e802 > 0f) {
                                            let _e808 = select(select(u32(_e802), 0u, (_e802 < 0f)), 4294967295u, (_e802 > 4294967000f));
                                            let _e809 = (_e787 - 1u);
                                            phi_1248_ = select(_e808, _e809, (_e809 < _e808));
                                        } else {
                                            phi_1248_ = 0u;
                                        }
                                        let _e813 = phi_1248_;
                                        phi_1250_ = 0u;
                                        phi_1253_ = 0u;
                                        loop {
                                            let _e815 = phi_1250_;
                                            let _e817 = phi_1253_;
                                            local_2 = _e817;
                                            let _e818 = (_e815 < _e738);
                                            if _e818 {
                                                let _e819 = (_e815 & 31u);
                                                let _e821 = (_e101 >> bitcast<u32>(_e819));
                                                let _e825 = (_e112 >> bitcast<u32>(_e819));
                                                phi_1251_ = (_e815 + 1u);
                                                phi_1254_ = (_e817 + (select(1u, _e821, (1u < _e821)) * select(1u, _e825, (1u < _e825))));
                                            } else {
                                                phi_1251_ = u32();
                                                phi_1254_ = u32();
                                            }
                                            let _e832 = phi_1251_;
                                            let _e834 = phi_1254_;
                                            continue;
                                            continuing {
                                                phi_1250_ = _e832;
                                                phi_1253_ = _e834;
                                                break if !(_e818);
                                            }
                                        }
                                        let _e839 = local_2;
                                        let _e840 = (_e839 + ((_e813 * _e783) + _e800));
                                        if (_e840 < _e84) {
                                        } else {
                                            phi_2603_ = true;
                                            break;
                                        }
                                        let _e844 = mips.member[_e840];
                                        let _e853 = (_e777 * _e788);
                                        if (_e853 > 0f) {
                                            let _e859 = select(select(u32(_e853), 0u, (_e853 < 0f)), 4294967295u, (_e853 > 4294967000f));
                                            let _e860 = (_e783 - 1u);
                                            phi_1336_ = select(_e859, _e860, (_e860 < _e859));
                                        } else {
                                            phi_1336_ = 0u;
                                        }
                                        let _e864 = phi_1336_;
                                        let _e865 = (_e778 * _e801);
                                        if (_e865 > 0f) {
                                            let _e871 = select(select(u32(_e865), 0u, (_e865 < 0f)), 4294967295u, (_e865 > 4294967000f));
                                            let _e872 = (_e787 - 1u);
                                            phi_1356_ = select(_e871, _e872, (_e872 < _e871));
                                        } else {
                                            phi_1356_ = 0u;
                                        }
                                        let _e876 = phi_1356_;
                                        phi_1358_ = 0u;
                                        phi_1361_ = 0u;
                                        loop {
                                            let _e878 = phi_1358_;
                                            let _e880 = phi_1361_;
                                            local_3 = _e880;
                                            let _e881 = (_e878 < _e738);
                                            if _e881 {
                                                let _e882 = (_e878 & 31u);
                                                let _e884 = (_e101 >> bitcast<u32>(_e882));
                                                let _e888 = (_e112 >> bitcast<u32>(_e882));
                                                phi_1359_ = (_e878 + 1u);
                                                phi_1362_ = (_e880 + (select(1u, _e884, (1u < _e884)) * select(1u, _e888, (1u < _e888))));
                                            } else {
                                                phi_1359_ = u32();
                                                phi_1362_ = u32();
                                            }
                                            let _e895 = phi_1359_;
                                            let _e897 = phi_1362_;
                                            continue;
                                            continuing {
                                                phi_1358_ = _e895;
                                                phi_1361_ = _e897;
                                                break if !(_e881);
                                            }
                                        }
                                        let _e902 = local_3;
                                        let _e903 = (_e902 + ((_e876 * _e783) + _e864));
                                        if (_e903 < _e84) {
                                        } else {
                                            phi_2603_ = true;
                                            break;
                                        }
                                        let _e907 = mips.member[_e903];
                                        let _e916 = (((((2f * _e775) - 1f) * _e396) * _e844) - _e398);
                                        let _e917 = ((((1f - (2f * _e776)) * _e406) * _e844) - _e408);
                                        let _e918 = (_e844 - _e388);
                                        let _e921 = params.member.member_1;
                                        let _e922 = (_e921 > 0f);
                                        if _e922 {
                                            phi_1437_ = select(true, false, (sqrt((((_e916 * _e916) + (_e917 * _e917)) + (_e918 * _e918))) > _e921));
                                        } else {
                                            phi_1437_ = true;
                                        }
                                        let _e932 = phi_1437_;
                                        if _e932 {
                                            let _e935 = params.member.member;
                                            let _e938 = params.member.member_3;
                                            let _e943 = (((_e916 * _e419) + (_e917 * _e420)) + (_e918 * _e421));
                                            let _e947 = (_e916 - (_e419 * _e943));
                                            let _e948 = (_e917 - (_e420 * _e943));
                                            let _e949 = (_e918 - (_e421 * _e943));
                                            if (sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))) <= 0f) {
                                                phi_1742_ = 0u;
                                            } else {
                                                let _e959 = ((_e948 * _e421) - (_e420 * _e949));
                                                let _e962 = ((_e949 * _e419) - (_e421 * _e947));
                                                let _e965 = ((_e947 * _e420) - (_e419 * _e948));
                                                let _e972 = (1f / sqrt((((_e959 * _e959) + (_e962 * _e962)) + (_e965 * _e965))));
                                                let _e973 = (_e959 * _e972);
                                                let _e974 = (_e962 * _e972);
                                                let _e975 = (_e965 * _e972);
                                                let _e980 = (((_e494.x * _e973) + (_e494.y * _e974)) + (_e494.z * _e975));
                                                let _e984 = (_e494.x - (_e973 * _e980));
                                                let _e985 = (_e494.y - (_e974 * _e980));
                                                let _e986 = (_e494.z - (_e975 * _e980));
                                                let _e992 = sqrt((((_e984 * _e984) + (_e985 * _e985)) + (_e986 * _e986)));
                                                let _e998 = ((((_e984 * _e419) + (_e985 * _e420)) + (_e986 * _e421)) / _e992);
                                                if (_e998 > 0f) {
                                                    phi_1540_ = select(1f, _e998, (_e998 < 1f));
                                                } else {
                                                    phi_1540_ = 0f;
                                                }
                                                let _e1003 = phi_1540_;
                                                if ((((_e947 * _e984) + (_e948 * _e985)) + (_e949 * _e986)) < 0f) {
                                                    phi_1553_ = -(acos(_e1003));
                                                } else {
                                                    phi_1553_ = acos(_e1003);
                                                }
                                                let _e1014 = phi_1553_;
                                                let _e1015 = (0.02f / _e992);
                                                if (_e1015 != _e1015) {
                                                    phi_2508_ = true;
                                                } else {
                                                    phi_2508_ = (0.19634955f <= _e1015);
                                                }
                                                let _e1019 = phi_2508_;
                                                let _e1020 = select(_e1015, 0.19634955f, _e1019);
                                                let _e1024 = (_e916 - (_e419 * _e935));
                                                let _e1025 = (_e917 - (_e420 * _e935));
                                                let _e1026 = (_e918 - (_e421 * _e935));
                                                let _e1033 = (1f / sqrt((((_e916 * _e916) + (_e917 * _e917)) + (_e918 * _e918))));
                                                let _e1041 = ((((_e916 * _e1033) * _e419) + ((_e917 * _e1033) * _e420)) + ((_e918 * _e1033) * _e421));
                                                if (_e1041 > -1f) {
                                                    phi_1592_ = select(1f, _e1041, (_e1041 < 1f));
                                                } else {
                                                    phi_1592_ = -1f;
                                                }
                                                let _e1046 = phi_1592_;
                                                let _e1051 = ((((acos(_e1046) + _e1020) - _e1014) + 1.5707964f) * 0.31830987f);
                                                if (_e1051 > 0f) {
                                                    phi_1607_ = select(1f, _e1051, (_e1051 < 1f));
                                                } else {
                                                    phi_1607_ = 0f;
                                                }
                                                let _e1056 = phi_1607_;
                                                let _e1063 = (1f / sqrt((((_e1024 * _e1024) + (_e1025 * _e1025)) + (_e1026 * _e1026))));
                                                let _e1071 = ((((_e1024 * _e1063) * _e419) + ((_e1025 * _e1063) * _e420)) + ((_e1026 * _e1063) * _e421));
                                                if (_e1071 > -1f) {
                                                    phi_1635_ = select(1f, _e1071, (_e1071 < 1f));
                                                } else {
                                                    phi_1635_ = -1f;
                                                }
                                                let _e1076 = phi_1635_;
                                                let _e1081 = ((((acos(_e1076) + _e1020) - _e1014) + 1.5707964f) * 0.31830987f);
                                                if (_e1081 > 0f) {
                                                    phi_1650_ = select(1f, _e1081, (_e1081 < 1f));
                                                } else {
                                                    phi_1650_ = 0f;
                                                }
                                                let _e1086 = phi_1650_;
                                                let _e1087 = (_e1056 != _e1056);
                                                if _e1087 {
                                                    phi_2523_ = true;
                                                } else {
                                                    phi_2523_ = (_e1086 <= _e1056);
                                                }
                                                let _e1090 = phi_2523_;
                                                let _e1091 = select(_e1056, _e1086, _e1090);
                                                if _e1087 {
                                                    phi_2538_ = true;
                                                } else {
                                                    phi_2538_ = (_e1086 >= _e1056);
                                                }
                                                let _e1094 = phi_2538_;
                                                let _e1095 = select(_e1056, _e1086, _e1094);
                                                let _e1097 = floor((32f * _e1091));
                                                let _e1102 = select(select(u32(_e1097), 0u, (_e1097 < 0f)), 4294967295u, (_e1097 > 4294967000f));
                                                if (_e938 == 1u) {
                                                    let _e1112 = (_e1095 <= _e1091);
                                                    if _e1112 {
                                                        phi_1699_ = u32();
                                                    } else {
                                                        let _e1114 = ceil((32f * _e1095));
                                                        let _e1119 = select(select(u32(_e1114), 0u, (_e1114 < 0f)), 4294967295u, (_e1114 > 4294967000f));
                                                        let _e1121 = select(_e1119, 32u, (32u < _e1119));
                                                        if (_e1121 > _e1102) {
                                                            phi_1698_ = (_e1121 - _e1102);
                                                        } else {
                                                            phi_1698_ = 0u;
                                                        }
                                                        let _e1125 = phi_1698_;
                                                        phi_1699_ = _e1125;
                                                    }
                                                    let _e1127 = phi_1699_;
                                                    phi_1711_ = _e1127;
                                                    phi_1712_ = select(true, false, _e1112);
                                                } else {
                                                    let _e1106 = ceil((32f * (_e1095 - _e1091)));
                                                    phi_1711_ = select(select(u32(_e1106), 0u, (_e1106 < 0f)), 4294967295u, (_e1106 > 4294967000f));
                                                    phi_1712_ = true;
                                                }
                                                let _e1130 = phi_1711_;
                                                let _e1132 = phi_1712_;
                                                if _e1132 {
                                                    if (_e1102 >= 32u) {
                                                        phi_1735_ = u32();
                                                        phi_1736_ = true;
                                                    } else {
                                                        let _e1134 = (_e1130 == 0u);
                                                        if _e1134 {
                                                            phi_1734_ = u32();
                                                        } else {
                                                            if (_e1130 >= 32u) {
                                                                phi_1731_ = 4294967295u;
                                                            } else {
                                                                phi_1731_ = ((1u << bitcast<u32>((_e1130 & 31u))) - 1u);
                                                            }
                                                            let _e1141 = phi_1731_;
                                                            phi_1734_ = (_e1141 << bitcast<u32>((_e1102 & 31u)));
                                                        }
                                                        let _e1146 = phi_1734_;
                                                        phi_1735_ = _e1146;
                                                        phi_1736_ = _e1134;
                                                    }
                                                    let _e1148 = phi_1735_;
                                                    let _e1150 = phi_1736_;
                                                    phi_1741_ = select(_e1148, 0u, _e1150);
                                                } else {
                                                    phi_1741_ = 0u;
                                                }
                                                let _e1153 = phi_1741_;
                                                phi_1742_ = _e1153;
                                            }
                                            let _e1155 = phi_1742_;
                                            phi_1743_ = _e1155;
                                        } else {
                                            phi_1743_ = 0u;
                                        }
                                        let _e1157 = phi_1743_;
                                        let _e1159 = (((((2f * _e777) - 1f) * _e396) * _e907) - _e398);
                                        let _e1160 = ((((1f - (2f * _e778)) * _e406) * _e907) - _e408);
                                        let _e1161 = (_e907 - _e388);
                                        if _e922 {
                                            phi_1771_ = select(true, false, (sqrt((((_e1159 * _e1159) + (_e1160 * _e1160)) + (_e1161 * _e1161))) > _e921));
                                        } else {
                                            phi_1771_ = true;
                                        }
                                        let _e1171 = phi_1771_;
                                        if _e1171 {
                                            let _e1174 = params.member.member;
                                            let _e1177 = params.member.member_3;
                                            let _e1182 = (((_e1159 * _e419) + (_e1160 * _e420)) + (_e1161 * _e421));
                                            let _e1186 = (_e1159 - (_e419 * _e1182));
                                            let _e1187 = (_e1160 - (_e420 * _e1182));
                                            let _e1188 = (_e1161 - (_e421 * _e1182));
                                            if (sqrt((((_e1186 * _e1186) + (_e1187 * _e1187)) + (_e1188 * _e1188))) <= 0f) {
                                                phi_2076_ = 0u;
                                            } else {
                                                let _e1198 = ((_e1187 * _e421) - (_e420 * _e1188));
                                                let _e1201 = ((_e1188 * _e419) - (_e421 * _e1186));
                                                let _e1204 = ((_e1186 * _e420) - (_e419 * _e1187));
                                                let _e1211 = (1f / sqrt((((_e1198 * _e1198) + (_e1201 * _e1201)) + (_e1204 * _e1204))));
                                                let _e1212 = (_e1198 * _e1211);
                                                let _e1213 = (_e1201 * _e1211);
                                                let _e1214 = (_e1204 * _e1211);
                                                let _e1219 = (((_e494.x * _e1212) + (_e494.y * _e1213)) + (_e494.z * _e1214));
                                                let _e1223 = (_e494.x - (_e1212 * _e1219));
                                                let _e1224 = (_e494.y - (_e1213 * _e1219));
                                                let _e1225 = (_e494.z - (_e1214 * _e1219));
                                                let _e1231 = sqrt((((_e1223 * _e1223) + (_e1224 * _e1224)) + (_e1225 * _e1225)));
                                                let _e1237 = ((((_e1223 * _e419) + (_e1224 * _e420)) + (_e1225 * _e421)) / _e1231);
                                                if (_e1237 > 0f) {
                                                    phi_1874_ = select(1f, _e1237, (_e1237 < 1f));
                                                } else {
                                                    phi_1874_ = 0f;
                                                }
                                                let _e1242 = phi_1874_;
                                                if ((((_e1186 * _e1223) + (_e1187 * _e1224)) + (_e1188 * _e1225)) < 0f) {
                                                    phi_1887_ = -(acos(_e1242));
                                                } else {
                                                    phi_1887_ = acos(_e1242);
                                                }
                                                let _e1253 = phi_1887_;
                                                let _e1254 = (0.02f / _e1231);
                                                if (_e1254 != _e1254) {
                                                    phi_2553_ = true;
                                                } else {
                                                    phi_2553_ = (0.19634955f <= _e1254);
                                                }
                                                let _e1258 = phi_2553_;
                                                let _e1259 = select(_e1254, 0.19634955f, _e1258);
                                                let _e1263 = (_e1159 - (_e419 * _e1174));
                                                let _e1264 = (_e1160 - (_e420 * _e1174));
                                                let _e1265 = (_e1161 - (_e421 * _e1174));
                                                let _e1272 = (1f / sqrt((((_e1159 * _e1159) + (_e1160 * _e1160)) + (_e1161 * _e1161))));
                                                let _e1280 = ((((_e1159 * _e1272) * _e419) + ((_e1160 * _e1272) * _e420)) + ((_e1161 * _e1272) * _e421));
                                                if (_e1280 > -1f) {
                                                    phi_1926_ = select(1f, _e1280, (_e1280 < 1f));
                                                } else {
                                                    phi_1926_ = -1f;
                                                }
                                                let _e1285 = phi_1926_;
                                                let _e1290 = ((((acos(_e1285) + _e1259) - _e1253) + 1.5707964f) * 0.31830987f);
                                                if (_e1290 > 0f) {
                                                    phi_1941_ = select(1f, _e1290, (_e1290 < 1f));
                                                } else {
                                                    phi_1941_ = 0f;
                                                }
                                                let _e1295 = phi_1941_;
                                                let _e1302 = (1f / sqrt((((_e1263 * _e1263) + (_e1264 * _e1264)) + (_e1265 * _e1265))));
                                                let _e1310 = ((((_e1263 * _e1302) * _e419) + ((_e1264 * _e1302) * _e420)) + ((_e1265 * _e1302) * _e421));
                                                if (_e1310 > -1f) {
                                                    phi_1969_ = select(1f, _e1310, (_e1310 < 1f));
                                                } else {
                                                    phi_1969_ = -1f;
                                                }
                                                let _e1315 = phi_1969_;
                                                let _e1320 = ((((acos(_e1315) + _e1259) - _e1253) + 1.5707964f) * 0.31830987f);
                                                if (_e1320 > 0f) {
                                                    phi_1984_ = select(1f, _e1320, (_e1320 < 1f));
                                                } else {
                                                    phi_1984_ = 0f;
                                                }
                                                let _e1325 = phi_1984_;
                                                let _e1326 = (1f - _e1295);
                                                let _e1327 = (1f - _e1325);
                                                let _e1328 = (_e1326 != _e1326);
                                                if _e1328 {
                                                    phi_2568_ = true;
                                                } else {
                                                    phi_2568_ = (_e1327 <= _e1326);
                                                }
                                                let _e1331 = phi_2568_;
                                                let _e1332 = select(_e1326, _e1327, _e1331);
                                                if _e1328 {
                                                    phi_2583_ = true;
                                                } else {
                                                    phi_2583_ = (_e1327 >= _e1326);
                                                }
                                                let _e1335 = phi_2583_;
                                                let _e1336 = select(_e1326, _e1327, _e1335);
                                                let _e1338 = floor((32f * _e1332));
                                                let _e1343 = select(select(u32(_e1338), 0u, (_e1338 < 0f)), 4294967295u, (_e1338 > 4294967000f));
                                                if (_e1177 == 1u) {
                                                    let _e1353 = (_e1336 <= _e1332);
                                                    if _e1353 {
                                                        phi_2033_ = u32();
                                                    } else {
                                                        let _e1355 = ceil((32f * _e1336));
                                                        let _e1360 = select(select(u32(_e1355), 0u, (_e1355 < 0f)), 4294967295u, (_e1355 > 4294967000f));
                                                        let _e1362 = select(_e1360, 32u, (32u < _e1360));
                                                        if (_e1362 > _e1343) {
                                                            phi_2032_ = (_e1362 - _e1343);
                                                        } else {
                                                            phi_2032_ = 0u;
                                                        }
                                                        let _e1366 = phi_2032_;
                                                        phi_2033_ = _e1366;
                                                    }
                                                    let _e1368 = phi_2033_;
                                                    phi_2045_ = _e1368;
                                                    phi_2046_ = select(true, false, _e1353);
                                                } else {
                                                    let _e1347 = ceil((32f * (_e1336 - _e1332)));
                                                    phi_2045_ = select(select(u32(_e1347), 0u, (_e1347 < 0f)), 4294967295u, (_e1347 > 4294967000f));
                                                    phi_2046_ = true;
                                                }
                                                let _e1371 = phi_2045_;
                                                let _e1373 = phi_2046_;
                                                if _e1373 {
                                                    if (_e1343 >= 32u) {
                                                        phi_2069_ = u32();
                                                        phi_2070_ = true;
                                                    } else {
                                                        let _e1375 = (_e1371 == 0u);
                                                        if _e1375 {
                                                            phi_2068_ = u32();
                                                        } else {
                                                            if (_e1371 >= 32u) {
                                                                phi_2065_ = 4294967295u;
                                                            } else {
                                                                phi_2065_ = ((1u << bitcast<u32>((_e1371 & 31u))) - 1u);
                                                            }
                                                            let _e1382 = phi_2065_;
                                                            phi_2068_ = (_e1382 << bitcast<u32>((_e1343 & 31u)));
                                                        }
                                                        let _e1387 = phi_2068_;
                                                        phi_2069_ = _e1387;
                                                        phi_2070_ = _e1375;
                                                    }
                                                    let _e1389 = phi_2069_;
                                                    let _e1391 = phi_2070_;
                                                    phi_2075_ = select(_e1389, 0u, _e1391);
                                                } else {
                                                    phi_2075_ = 0u;
                                                }
                                                let _e1394 = phi_2075_;
                                                phi_2076_ = _e1394;
                                            }
                                            let _e1396 = phi_2076_;
                                            phi_2077_ = _e1396;
                                        } else {
                                            phi_2077_ = 0u;
                                        }
                                        let _e1398 = phi_2077_;
                                        phi_1031_ = (_e684 + 1u);
                                        phi_1034_ = ((_e686 | _e1157) | _e1398);
                                    } else {
                                        phi_1031_ = u32();
                                        phi_1034_ = u32();
                                    }
                                    let _e1402 = phi_1031_;
                                    let _e1404 = phi_1034_;
                                    continue;
                                    continuing {
                                        phi_1030_ = _e1402;
                                        phi_1033_ = _e1404;
                                        phi_2603_ = _e588;
                                        break if !(_e687);
                                    }
                                }
                                let _e1407 = phi_2603_;
                                phi_2773_ = _e1407;
                                if _e1407 {
                                    break;
                                }
                                let _e1410 = params.member.member_2;
                                if (_e1410 == 2u) {
                                    let _e1467 = (_e676 - 1.5707964f);
                                    let _e1468 = (2f * _e1467);
                                    let _e1469 = sin(_e676);
                                    let _e1474 = ((_e674 + (_e1468 * _e1469)) - cos((_e1468 - _e676)));
                                    if (_e1467 < 0f) {
                                        phi_2106_ = (_e1474 * -0.25f);
                                    } else {
                                        phi_2106_ = (_e1474 * 0.25f);
                                    }
                                    let _e1479 = phi_2106_;
                                    phi_2108_ = 0u;
                                    phi_2111_ = _e1479;
                                    phi_2113_ = 0f;
                                    loop {
                                        let _e1481 = phi_2108_;
                                        let _e1483 = phi_2111_;
                                        let _e1485 = phi_2113_;
                                        local_8 = _e1485;
                                        let _e1486 = (_e1481 < 32u);
                                        if _e1486 {
                                            let _e1487 = (_e1481 + 1u);
                                            let _e1490 = (_e1467 + (f32(_e1487) * 0.09817477f));
                                            let _e1491 = (2f * _e1490);
                                            let _e1496 = ((_e674 + (_e1491 * _e1469)) - cos((_e1491 - _e676)));
                                            if (_e1490 < 0f) {
                                                phi_2139_ = (_e1496 * -0.25f);
                                            } else {
                                                phi_2139_ = (_e1496 * 0.25f);
                                            }
                                            let _e1501 = phi_2139_;
                                            let _e1504 = local_7;
                                            if (((_e1504 >> bitcast<u32>((_e1481 & 31u))) & 1u) == 0u) {
                                                phi_2149_ = (_e1485 + (_e1501 - _e1483));
                                            } else {
                                                phi_2149_ = _e1485;
                                            }
                                            let _e1512 = phi_2149_;
                                            phi_2109_ = _e1487;
                                            phi_2112_ = _e1501;
                                            phi_2114_ = _e1512;
                                        } else {
                                            phi_2109_ = u32();
                                            phi_2112_ = f32();
                                            phi_2114_ = f32();
                                        }
                                        let _e1514 = phi_2109_;
                                        let _e1516 = phi_2112_;
                                        let _e1518 = phi_2114_;
                                        continue;
                                        continuing {
                                            phi_2108_ = _e1514;
                                            phi_2111_ = _e1516;
                                            phi_2113_ = _e1518;
                                            break if !(_e1486);
                                        }
                                    }
                                    let _e1521 = local_8;
                                    phi_2775_ = _e1407;
                                    phi_2213_ = (_e592 + 1f);
                                    phi_2214_ = (_e594 + ((_e653 + ((1f - _e653) * 0.05f)) * _e1521));
                                } else {
                                    if (_e1410 == 1u) {
                                        phi_2161_ = 0u;
                                        phi_2164_ = 0f;
                                        loop {
                                            let _e1422 = phi_2161_;
                                            let _e1424 = phi_2164_;
                                            local_6 = _e1424;
                                            let _e1425 = (_e1422 < 4u);
                                            if _e1425 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1425 {
                                                } else {
                                                    phi_2770_ = true;
                                                    break;
                                                }
                                                let _e1428 = local[_e1422].member;
                                                let _e1431 = local[_e1422].member_1;
                                                let _e1433 = local_5;
                                                phi_2162_ = (_e1422 + 1u);
                                                phi_2165_ = (_e1424 + (f32(countOneBits((_e1433 & _e1428))) * _e1431));
                                            } else {
                                                phi_2162_ = u32();
                                                phi_2165_ = f32();
                                            }
                                            let _e1441 = phi_2162_;
                                            let _e1443 = phi_2165_;
                                            continue;
                                            continuing {
                                                phi_2161_ = _e1441;
                                                phi_2164_ = _e1443;
                                                phi_2770_ = _e1407;
                                                break if !(_e1425);
                                            }
                                        }
                                        let _e1446 = phi_2770_;
                                        phi_2773_ = _e1446;
                                        if _e1446 {
                                            break;
                                        }
                                        let _e1448 = local_6;
                                        let _e1449 = (1f - _e1448);
                                        if (_e1449 > 0f) {
                                            phi_2200_ = select(1f, _e1449, (_e1449 < 1f));
                                        } else {
                                            phi_2200_ = 0f;
                                        }
                                        let _e1454 = phi_2200_;
                                        phi_2781_ = _e1446;
                                        phi_2211_ = (_e592 + _e653);
                                        phi_2212_ = (_e594 + (_e653 * _e1454));
                                    } else {
                                        let _e1414 = local_4;
                                        phi_2781_ = _e1407;
                                        phi_2211_ = (_e592 + 1f);
                                        phi_2212_ = (_e594 + (1f - (f32(countOneBits(_e1414)) * 0.03125f)));
                                    }
                                    let _e1459 = phi_2781_;
                                    let _e1461 = phi_2211_;
                                    let _e1463 = phi_2212_;
                                    phi_2775_ = _e1459;
                                    phi_2213_ = _e1461;
                                    phi_2214_ = _e1463;
                                }
                                let _e1526 = phi_2775_;
                                let _e1528 = phi_2213_;
                                let _e1530 = phi_2214_;
                                phi_2774_ = _e1526;
                                phi_850_ = (_e590 + 1u);
                                phi_853_ = _e1528;
                                phi_855_ = _e1530;
                            } else {
                                phi_2774_ = _e588;
                                phi_850_ = u32();
                                phi_853_ = f32();
                                phi_855_ = f32();
                            }
                            let _e1533 = phi_2774_;
                            let _e1535 = phi_850_;
                            let _e1537 = phi_853_;
                            let _e1539 = phi_855_;
                            continue;
                            continuing {
                                phi_2652_ = _e1533;
                                phi_849_ = _e1535;
                                phi_852_ = _e1537;
                                phi_854_ = _e1539;
                                phi_2773_ = _e1533;
                                break if !(_e595);
                            }
                        }
                        let _e1542 = phi_2773_;
                        if _e1542 {
                            break;
                        }
                        let _e1544 = local_9;
                        if (_e1544 > 0f) {
                            let _e1547 = local_10;
                            let _e1549 = local_11;
                            phi_2221_ = (_e1547 / _e1549);
                        } else {
                            phi_2221_ = 1f;
                        }
                        let _e1552 = phi_2221_;
                        let _e1556 = params.member.member_4.member_6;
                        let _e1557 = pow(_e1552, _e1556);
                        if (_e1557 != _e1557) {
                            phi_2598_ = true;
                        } else {
                            phi_2598_ = (0.03f >= _e1557);
                        }
                        let _e1561 = phi_2598_;
                        let _e1563 = (select(_e1557, 0.03f, _e1561) * 0.6666667f);
                        if (_e1563 > 0f) {
                            phi_2237_ = select(1f, _e1563, (_e1563 < 1f));
                        } else {
                            phi_2237_ = 0f;
                        }
                        let _e1568 = phi_2237_;
                        let _e1570 = ((_e1568 * 255f) + 0.5f);
                        phi_2269_ = type_21(select(select(u32(_e1570), 0u, (_e1570 < 0f)), 4294967295u, (_e1570 > 4294967000f)), _e381);
                    } else {
                        phi_2269_ = type_21(170u, _e381);
                    }
                    let _e1578 = phi_2269_;
                    if (_e118 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e118] = _e1578.member;
                    if (_e118 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e118] = _e1578.member_1;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vbao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
