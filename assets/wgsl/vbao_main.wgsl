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

struct type_21 {
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

struct type_22 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
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
    var phi_484_: i32;
    var phi_503_: i32;
    var phi_544_: i32;
    var phi_563_: i32;
    var phi_604_: i32;
    var phi_623_: i32;
    var phi_664_: i32;
    var phi_683_: i32;
    var phi_2509_: bool;
    var phi_2524_: bool;
    var phi_2539_: bool;
    var phi_2554_: bool;
    var phi_2585_: f32;
    var phi_2589_: f32;
    var phi_2590_: bool;
    var phi_2612_: u32;
    var phi_2639_: f32;
    var phi_2643_: f32;
    var phi_2644_: bool;
    var phi_2666_: u32;
    var phi_2693_: f32;
    var phi_2697_: f32;
    var phi_2698_: bool;
    var phi_2720_: u32;
    var phi_2747_: f32;
    var phi_2751_: f32;
    var phi_2752_: bool;
    var phi_2774_: u32;
    var phi_2854_: bool;
    var phi_2869_: bool;
    var phi_2829_: vec2<f32>;
    var phi_2886_: u32;
    var phi_2887_: u32;
    var phi_2888_: u32;
    var phi_2889_: u32;
    var phi_2912_: u32;
    var phi_2913_: u32;
    var phi_2916_: u32;
    var phi_2917_: u32;
    var phi_2921_: u32;
    var phi_2922_: u32;
    var phi_2923_: u32;
    var phi_2924_: u32;
    var local_1: u32;
    var phi_3276_: bool;
    var phi_940_: u32;
    var phi_943_: f32;
    var phi_945_: f32;
    var phi_1115_: u32;
    var phi_1118_: u32;
    var phi_1172_: f32;
    var phi_1217_: f32;
    var phi_1219_: f32;
    var phi_1220_: bool;
    var phi_1243_: f32;
    var phi_1245_: f32;
    var phi_1246_: bool;
    var phi_1279_: u32;
    var phi_1282_: f32;
    var phi_1284_: f32;
    var phi_1286_: u32;
    var phi_1288_: u32;
    var phi_1290_: u32;
    var phi_1323_: u32;
    var phi_1326_: u32;
    var phi_1324_: u32;
    var phi_1327_: u32;
    var local_2: u32;
    var phi_1280_: u32;
    var phi_1283_: f32;
    var phi_1285_: f32;
    var phi_1287_: u32;
    var phi_1289_: u32;
    var phi_1291_: u32;
    var local_3: f32;
    var local_4: u32;
    var phi_1384_: u32;
    var local_5: f32;
    var local_6: u32;
    var phi_1403_: u32;
    var local_7: u32;
    var local_8: u32;
    var phi_1447_: u32;
    var phi_1450_: f32;
    var phi_1452_: f32;
    var phi_1454_: u32;
    var phi_1456_: u32;
    var phi_1458_: u32;
    var phi_1491_: u32;
    var phi_1494_: u32;
    var phi_1492_: u32;
    var phi_1495_: u32;
    var local_9: u32;
    var phi_1448_: u32;
    var phi_1451_: f32;
    var phi_1453_: f32;
    var phi_1455_: u32;
    var phi_1457_: u32;
    var phi_1459_: u32;
    var local_10: f32;
    var local_11: u32;
    var phi_1552_: u32;
    var local_12: f32;
    var local_13: u32;
    var phi_1571_: u32;
    var local_14: u32;
    var local_15: u32;
    var phi_2958_: bool;
    var phi_2973_: bool;
    var phi_2988_: bool;
    var phi_3003_: bool;
    var phi_3018_: bool;
    var phi_1846_: f32;
    var phi_1864_: u32;
    var phi_1882_: u32;
    var phi_1898_: u32;
    var phi_1901_: u32;
    var phi_1902_: u32;
    var phi_1903_: bool;
    var phi_1932_: u32;
    var phi_3033_: bool;
    var phi_3048_: bool;
    var phi_3063_: bool;
    var phi_3078_: bool;
    var phi_3093_: bool;
    var phi_2182_: f32;
    var phi_2200_: u32;
    var phi_2218_: u32;
    var phi_2234_: u32;
    var phi_2237_: u32;
    var phi_2238_: u32;
    var phi_2239_: bool;
    var phi_2268_: u32;
    var phi_1116_: u32;
    var phi_1119_: u32;
    var phi_3152_: bool;
    var local_16: u32;
    var phi_2352_: u32;
    var phi_2355_: f32;
    var local_17: u32;
    var phi_2353_: u32;
    var phi_2356_: f32;
    var phi_3357_: bool;
    var local_18: f32;
    var phi_3368_: bool;
    var phi_2405_: f32;
    var phi_2406_: f32;
    var phi_2299_: u32;
    var phi_2302_: f32;
    var phi_2304_: f32;
    var local_19: u32;
    var phi_2300_: u32;
    var phi_2303_: f32;
    var phi_2305_: f32;
    var local_20: f32;
    var phi_3362_: bool;
    var phi_2407_: f32;
    var phi_2408_: f32;
    var phi_3361_: bool;
    var phi_941_: u32;
    var phi_944_: f32;
    var phi_946_: f32;
    var phi_3360_: bool;
    var local_21: f32;
    var local_22: f32;
    var local_23: f32;
    var phi_2416_: f32;
    var phi_3126_: bool;
    var phi_2465_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e85 = id_1;
            let _e88 = arrayLength((&mips.member));
            let _e100 = params.member.member_4.member.member[0u];
            let _e105 = select(select(u32(_e100), 0u, (_e100 < 0f)), 4294967295u, (_e100 > 4294967000f));
            let _e111 = params.member.member_4.member.member[1u];
            let _e116 = select(select(u32(_e111), 0u, (_e111 < 0f)), 4294967295u, (_e111 > 4294967000f));
            if (_e85.x >= _e105) {
            } else {
                if (_e85.y >= _e116) {
                } else {
                    let _e122 = ((_e85.y * _e105) + _e85.x);
                    if (_e122 < _e88) {
                    } else {
                        break;
                    }
                    let _e125 = mips.member[_e122];
                    let _e126 = bitcast<i32>(_e85.x);
                    let _e127 = (_e126 + -1i);
                    let _e129 = (bitcast<i32>(_e105) - 1i);
                    let _e130 = (0i <= _e129);
                    if _e130 {
                    } else {
                        break;
                    }
                    if (_e127 < 0i) {
                        phi_484_ = 0i;
                    } else {
                        phi_484_ = select(_e127, _e129, (_e127 > _e129));
                    }
                    let _e135 = phi_484_;
                    let _e137 = bitcast<i32>(_e85.y);
                    let _e139 = (bitcast<i32>(_e116) - 1i);
                    let _e140 = (0i <= _e139);
                    if _e140 {
                    } else {
                        break;
                    }
                    let _e141 = (_e137 < 0i);
                    if _e141 {
                        phi_503_ = 0i;
                    } else {
                        phi_503_ = select(_e137, _e139, (_e137 > _e139));
                    }
                    let _e145 = phi_503_;
                    let _e148 = ((bitcast<u32>(_e145) * _e105) + bitcast<u32>(_e135));
                    if (_e148 < _e88) {
                    } else {
                        break;
                    }
                    let _e151 = mips.member[_e148];
                    let _e152 = (_e126 + 1i);
                    if _e130 {
                    } else {
                        break;
                    }
                    if (_e152 < 0i) {
                        phi_544_ = 0i;
                    } else {
                        phi_544_ = select(_e152, _e129, (_e152 > _e129));
                    }
                    let _e157 = phi_544_;
                    if _e140 {
                    } else {
                        break;
                    }
                    if _e141 {
                        phi_563_ = 0i;
                    } else {
                        phi_563_ = select(_e137, _e139, (_e137 > _e139));
                    }
                    let _e162 = phi_563_;
                    let _e165 = ((bitcast<u32>(_e162) * _e105) + bitcast<u32>(_e157));
                    if (_e165 < _e88) {
                    } else {
                        break;
                    }
                    let _e168 = mips.member[_e165];
                    if _e130 {
                    } else {
                        break;
                    }
                    let _e169 = (_e126 < 0i);
                    if _e169 {
                        phi_604_ = 0i;
                    } else {
                        phi_604_ = select(_e126, _e129, (_e126 > _e129));
                    }
                    let _e173 = phi_604_;
                    let _e175 = (_e137 + -1i);
                    if _e140 {
                    } else {
                        break;
                    }
                    if (_e175 < 0i) {
                        phi_623_ = 0i;
                    } else {
                        phi_623_ = select(_e175, _e139, (_e175 > _e139));
                    }
                    let _e180 = phi_623_;
                    let _e183 = ((bitcast<u32>(_e180) * _e105) + bitcast<u32>(_e173));
                    if (_e183 < _e88) {
                    } else {
                        break;
                    }
                    let _e186 = mips.member[_e183];
                    if _e130 {
                    } else {
                        break;
                    }
                    if _e169 {
                        phi_664_ = 0i;
                    } else {
                        phi_664_ = select(_e126, _e129, (_e126 > _e129));
                    }
                    let _e190 = phi_664_;
                    let _e192 = (_e137 + 1i);
                    if _e140 {
                    } else {
                        break;
                    }
                    if (_e192 < 0i) {
                        phi_683_ = 0i;
                    } else {
                        phi_683_ = select(_e192, _e139, (_e192 > _e139));
                    }
                    let _e197 = phi_683_;
                    let _e200 = ((bitcast<u32>(_e197) * _e105) + bitcast<u32>(_e190));
                    if (_e200 < _e88) {
                    } else {
                        break;
                    }
                    let _e203 = mips.member[_e200];
                    let _e204 = (_e151 - _e125);
                    let _e205 = (_e168 - _e125);
                    let _e206 = (_e186 - _e125);
                    let _e207 = (_e203 - _e125);
                    let _e209 = ((_e205 - _e204) * 0.5f);
                    let _e211 = ((_e207 - _e206) * 0.5f);
                    let _e212 = (_e125 * 0.011f);
                    let _e214 = abs(_e204);
                    let _e215 = abs((_e204 + _e209));
                    if (_e214 != _e214) {
                        phi_2509_ = true;
                    } else {
                        phi_2509_ = (_e215 <= _e214);
                    }
                    let _e219 = phi_2509_;
                    let _e222 = (1.25f - (select(_e214, _e215, _e219) / _e212));
                    let _e226 = select(0f, select(1f, _e222, (_e222 < 1f)), (_e222 > 0f));
                    let _e228 = abs(_e205);
                    let _e229 = abs((_e205 - _e209));
                    if (_e228 != _e228) {
                        phi_2524_ = true;
                    } else {
                        phi_2524_ = (_e229 <= _e228);
                    }
                    let _e233 = phi_2524_;
                    let _e236 = (1.25f - (select(_e228, _e229, _e233) / _e212));
                    let _e240 = select(0f, select(1f, _e236, (_e236 < 1f)), (_e236 > 0f));
                    let _e242 = abs(_e206);
                    let _e243 = abs((_e206 + _e211));
                    if (_e242 != _e242) {
                        phi_2539_ = true;
                    } else {
                        phi_2539_ = (_e243 <= _e242);
                    }
                    let _e247 = phi_2539_;
                    let _e250 = (1.25f - (select(_e242, _e243, _e247) / _e212));
                    let _e254 = select(0f, select(1f, _e250, (_e250 < 1f)), (_e250 > 0f));
                    let _e256 = abs(_e207);
                    let _e257 = abs((_e207 - _e211));
                    if (_e256 != _e256) {
                        phi_2554_ = true;
                    } else {
                        phi_2554_ = (_e257 <= _e256);
                    }
                    let _e261 = phi_2554_;
                    let _e264 = (1.25f - (select(_e256, _e257, _e261) / _e212));
                    let _e268 = select(0f, select(1f, _e264, (_e264 < 1f)), (_e264 > 0f));
                    let _e273 = (select(0f, select(1f, _e226, (_e226 < 1f)), (_e226 > 0f)) * 2.9f);
                    let _e275 = floor((_e273 + 0.5f));
                    if ((_e275 - _e273) == 0.5f) {
                        let _e281 = ((floor((_e275 * 0.5f)) * 2f) != _e275);
                        if _e281 {
                            phi_2585_ = (_e275 - 1f);
                        } else {
                            phi_2585_ = f32();
                        }
                        let _e284 = phi_2585_;
                        phi_2589_ = _e284;
                        phi_2590_ = select(true, false, _e281);
                    } else {
                        phi_2589_ = f32();
                        phi_2590_ = true;
                    }
                    let _e287 = phi_2589_;
                    let _e289 = phi_2590_;
                    let _e290 = select(_e287, _e275, _e289);
                    if (_e290 > 0f) {
                        let _e296 = select(select(u32(_e290), 0u, (_e290 < 0f)), 4294967295u, (_e290 > 4294967000f));
                        phi_2612_ = select(_e296, 3u, (3u < _e296));
                    } else {
                        phi_2612_ = 0u;
                    }
                    let _e300 = phi_2612_;
                    let _e306 = (select(0f, select(1f, _e240, (_e240 < 1f)), (_e240 > 0f)) * 2.9f);
                    let _e308 = floor((_e306 + 0.5f));
                    if ((_e308 - _e306) == 0.5f) {
                        let _e314 = ((floor((_e308 * 0.5f)) * 2f) != _e308);
                        if _e314 {
                            phi_2639_ = (_e308 - 1f);
                        } else {
                            phi_2639_ = f32();
                        }
                        let _e317 = phi_2639_;
                        phi_2643_ = _e317;
                        phi_2644_ = select(true, false, _e314);
                    } else {
                        phi_2643_ = f32();
                        phi_2644_ = true;
                    }
                    let _e320 = phi_2643_;
                    let _e322 = phi_2644_;
                    let _e323 = select(_e320, _e308, _e322);
                    if (_e323 > 0f) {
                        let _e329 = select(select(u32(_e323), 0u, (_e323 < 0f)), 4294967295u, (_e323 > 4294967000f));
                        phi_2666_ = select(_e329, 3u, (3u < _e329));
                    } else {
                        phi_2666_ = 0u;
                    }
                    let _e333 = phi_2666_;
                    let _e340 = (select(0f, select(1f, _e254, (_e254 < 1f)), (_e254 > 0f)) * 2.9f);
                    let _e342 = floor((_e340 + 0.5f));
                    if ((_e342 - _e340) == 0.5f) {
                        let _e348 = ((floor((_e342 * 0.5f)) * 2f) != _e342);
                        if _e348 {
                            phi_2693_ = (_e342 - 1f);
                        } else {
                            phi_2693_ = f32();
                        }
                        let _e351 = phi_2693_;
                        phi_2697_ = _e351;
                        phi_2698_ = select(true, false, _e348);
                    } else {
                        phi_2697_ = f32();
                        phi_2698_ = true;
                    }
                    let _e354 = phi_2697_;
                    let _e356 = phi_2698_;
                    let _e357 = select(_e354, _e342, _e356);
                    if (_e357 > 0f) {
                        let _e363 = select(select(u32(_e357), 0u, (_e357 < 0f)), 4294967295u, (_e357 > 4294967000f));
                        phi_2720_ = select(_e363, 3u, (3u < _e363));
                    } else {
                        phi_2720_ = 0u;
                    }
                    let _e367 = phi_2720_;
                    let _e374 = (select(0f, select(1f, _e268, (_e268 < 1f)), (_e268 > 0f)) * 2.9f);
                    let _e376 = floor((_e374 + 0.5f));
                    if ((_e376 - _e374) == 0.5f) {
                        let _e382 = ((floor((_e376 * 0.5f)) * 2f) != _e376);
                        if _e382 {
                            phi_2747_ = (_e376 - 1f);
                        } else {
                            phi_2747_ = f32();
                        }
                        let _e385 = phi_2747_;
                        phi_2751_ = _e385;
                        phi_2752_ = select(true, false, _e382);
                    } else {
                        phi_2751_ = f32();
                        phi_2752_ = true;
                    }
                    let _e388 = phi_2751_;
                    let _e390 = phi_2752_;
                    let _e391 = select(_e388, _e376, _e390);
                    if (_e391 > 0f) {
                        let _e397 = select(select(u32(_e391), 0u, (_e391 < 0f)), 4294967295u, (_e391 > 4294967000f));
                        phi_2774_ = select(_e397, 3u, (3u < _e397));
                    } else {
                        phi_2774_ = 0u;
                    }
                    let _e401 = phi_2774_;
                    let _e405 = ((f32(_e85.x) + 0.5f) / _e100);
                    let _e408 = ((f32(_e85.y) + 0.5f) / _e111);
                    let _e409 = (_e125 * 0.99999f);
                    let _e417 = params.member.member_4.member.member_1[0u];
                    let _e419 = ((((_e405 * 2f) - 1f) * _e417) * _e409);
                    let _e427 = params.member.member_4.member.member_1[1u];
                    let _e429 = ((((_e408 * -2f) + 1f) * _e427) * _e409);
                    let _e430 = -(_e419);
                    let _e431 = -(_e429);
                    let _e432 = (_e125 * -0.99999f);
                    let _e439 = (1f / sqrt((((_e430 * _e430) + (_e431 * _e431)) + (_e432 * _e432))));
                    let _e440 = (_e430 * _e439);
                    let _e441 = (_e431 * _e439);
                    let _e442 = (_e432 * _e439);
                    if (_e122 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e446 = normals.member[_e122];
                    let _e454 = (f32((bitcast<i32>(((_e446 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e454 != _e454) {
                        phi_2854_ = true;
                    } else {
                        phi_2854_ = (-1f >= _e454);
                    }
                    let _e458 = phi_2854_;
                    let _e459 = select(_e454, -1f, _e458);
                    let _e469 = (f32((bitcast<i32>((((_e446 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e469 != _e469) {
                        phi_2869_ = true;
                    } else {
                        phi_2869_ = (-1f >= _e469);
                    }
                    let _e473 = phi_2869_;
                    let _e474 = select(_e469, -1f, _e473);
                    let _e477 = (1f - abs(_e459));
                    let _e478 = abs(_e474);
                    let _e479 = (_e477 - _e478);
                    if (_e479 < 0f) {
                        phi_2829_ = vec2<f32>(((1f - _e478) * select(1f, -1f, (_e459 < 0f))), (_e477 * select(1f, -1f, (_e474 < 0f))));
                    } else {
                        phi_2829_ = vec2<f32>(_e459, _e474);
                    }
                    let _e490 = phi_2829_;
                    let _e499 = (1f / sqrt((((_e490.x * _e490.x) + (_e490.y * _e490.y)) + (_e479 * _e479))));
                    let _e500 = (_e490.x * _e499);
                    let _e501 = (_e490.y * _e499);
                    let _e502 = (_e479 * _e499);
                    let _e503 = -(_e502);
                    let _e509 = ((((_e500 * _e440) + (_e501 * _e441)) + (_e503 * _e442)) < 0f);
                    let _e511 = select(_e500, -(_e500), _e509);
                    let _e513 = select(_e501, -(_e501), _e509);
                    let _e514 = select(_e503, _e502, _e509);
                    let _e518 = params.member.member_4.member_1;
                    let _e522 = params.member.member_4.member_2;
                    let _e527 = ((_e518 * _e522) / (((_e125 * 1.99998f) * _e417) / _e100));
                    let _e532 = params.member.member_4.member_11;
                    phi_2886_ = (_e85.y & 63u);
                    phi_2887_ = (_e85.x & 63u);
                    phi_2888_ = 32u;
                    phi_2889_ = 0u;
                    loop {
                        let _e536 = phi_2886_;
                        let _e538 = phi_2887_;
                        let _e540 = phi_2888_;
                        let _e542 = phi_2889_;
                        local_1 = _e542;
                        let _e543 = (_e540 > 0u);
                        if _e543 {
                            let _e546 = select(0u, 1u, ((_e538 & _e540) != 0u));
                            let _e549 = select(0u, 1u, ((_e536 & _e540) != 0u));
                            if (_e549 == 0u) {
                                if (_e546 == 1u) {
                                    phi_2912_ = (63u - _e536);
                                    phi_2913_ = (63u - _e538);
                                } else {
                                    phi_2912_ = _e536;
                                    phi_2913_ = _e538;
                                }
                                let _e560 = phi_2912_;
                                let _e562 = phi_2913_;
                                phi_2916_ = _e562;
                                phi_2917_ = _e560;
                            } else {
                                phi_2916_ = _e536;
                                phi_2917_ = _e538;
                            }
                            let _e564 = phi_2916_;
                            let _e566 = phi_2917_;
                            phi_2921_ = _e564;
                            phi_2922_ = _e566;
                            phi_2923_ = (_e540 / 2u);
                            phi_2924_ = (_e542 + ((_e540 * _e540) * ((3u * _e546) ^ _e549)));
                        } else {
                            phi_2921_ = u32();
                            phi_2922_ = u32();
                            phi_2923_ = u32();
                            phi_2924_ = u32();
                        }
                        let _e569 = phi_2921_;
                        let _e571 = phi_2922_;
                        let _e573 = phi_2923_;
                        let _e575 = phi_2924_;
                        continue;
                        continuing {
                            phi_2886_ = _e569;
                            phi_2887_ = _e571;
                            phi_2888_ = _e573;
                            phi_2889_ = _e575;
                            break if !(_e543);
                        }
                    }
                    let _e580 = local_1;
                    let _e582 = f32((_e580 + (288u * (_e532 % 64u))));
                    let _e584 = (0.5f + (_e582 * 0.7548777f));
                    let _e588 = (0.5f + (_e582 * 0.5698403f));
                    let _e595 = params.member.member_4.member.member_3;
                    let _e598 = select(false, (_e125 < _e595), (_e125 > 0f));
                    if _e598 {
                        let _e602 = params.member.member_4.member_8;
                        let _e604 = select(1u, _e602, (1u < _e602));
                        phi_3276_ = false;
                        phi_940_ = 0u;
                        phi_943_ = 0f;
                        phi_945_ = 0f;
                        loop {
                            let _e606 = phi_3276_;
                            let _e608 = phi_940_;
                            let _e610 = phi_943_;
                            let _e612 = phi_945_;
                            local_21 = _e610;
                            local_22 = _e612;
                            local_23 = _e610;
                            let _e613 = (_e608 < _e604);
                            if _e613 {
                                let _e618 = ((((_e584 - floor(_e584)) + f32(_e608)) * 3.1415927f) / f32(_e604));
                                let _e619 = sin(_e618);
                                let _e620 = cos(_e618);
                                let _e626 = ((_e620 * _e440) + (_e619 * _e441));
                                let _e630 = (_e620 - (_e440 * _e626));
                                let _e631 = (_e619 - (_e441 * _e626));
                                let _e632 = -((_e442 * _e626));
                                let _e635 = ((_e631 * _e442) - (_e441 * _e632));
                                let _e638 = ((_e632 * _e440) - (_e442 * _e630));
                                let _e641 = ((_e630 * _e441) - (_e440 * _e631));
                                let _e648 = (1f / sqrt((((_e635 * _e635) + (_e638 * _e638)) + (_e641 * _e641))));
                                let _e649 = (_e635 * _e648);
                                let _e650 = (_e638 * _e648);
                                let _e651 = (_e641 * _e648);
                                let _e656 = (((_e511 * _e649) + (_e513 * _e650)) + (_e514 * _e651));
                                let _e660 = (_e511 - (_e649 * _e656));
                                let _e661 = (_e513 - (_e650 * _e656));
                                let _e662 = (_e514 - (_e651 * _e656));
                                let _e668 = sqrt((((_e660 * _e660) + (_e661 * _e661)) + (_e662 * _e662)));
                                let _e673 = (((_e630 * _e660) + (_e631 * _e661)) + (_e632 * _e662));
                                let _e683 = ((((_e660 * _e440) + (_e661 * _e441)) + (_e662 * _e442)) / _e668);
                                let _e687 = select(0f, select(1f, _e683, (_e683 < 1f)), (_e683 > 0f));
                                let _e689 = (select(select(0f, -1f, (_e673 < 0f)), 1f, (_e673 > 0f)) * acos(_e687));
                                let _e693 = params.member.member_4.member_9;
                                let _e695 = select(1u, _e693, (1u < _e693));
                                phi_1115_ = 0u;
                                phi_1118_ = 0u;
                                loop {
                                    let _e697 = phi_1115_;
                                    let _e699 = phi_1118_;
                                    local_16 = _e699;
                                    local_17 = _e699;
                                    local_19 = _e699;
                                    let _e700 = (_e697 < _e695);
                                    if _e700 {
                                        let _e705 = ((_e588 - floor(_e588)) + (f32((_e608 + (_e697 * _e695))) * 0.618034f));
                                        let _e711 = (((_e705 - floor(_e705)) + f32(_e697)) / f32(_e695));
                                        let _e715 = params.member.member_4.member_4;
                                        if (_e715 == 2f) {
                                            phi_1172_ = (_e711 * _e711);
                                        } else {
                                            phi_1172_ = pow(_e711, _e715);
                                        }
                                        let _e720 = phi_1172_;
                                        let _e721 = (_e720 + (1.3f / _e527));
                                        let _e722 = ((_e620 * _e527) * _e721);
                                        let _e723 = ((-(_e619) * _e527) * _e721);
                                        let _e732 = params.member.member_4.member_7;
                                        let _e733 = (log2(sqrt(((_e722 * _e722) + (_e723 * _e723)))) - _e732);
                                        let _e740 = (-1f - floor((-0.5f - select(0f, select(5f, _e733, (_e733 < 5f)), (_e733 > 0f)))));
                                        let _e742 = floor((_e722 + 0.5f));
                                        if ((_e742 - _e722) == 0.5f) {
                                            let _e748 = ((floor((_e742 * 0.5f)) * 2f) != _e742);
                                            if _e748 {
                                                phi_1217_ = (_e742 - 1f);
                                            } else {
                                                phi_1217_ = f32();
                                            }
                                            let _e751 = phi_1217_;
                                            phi_1219_ = _e751;
                                            phi_1220_ = select(true, false, _e748);
                                        } else {
                                            phi_1219_ = f32();
                                            phi_1220_ = true;
                                        }
                                        let _e754 = phi_1219_;
                                        let _e756 = phi_1220_;
                                        let _e758 = (select(_e754, _e742, _e756) / _e100);
                                        let _e760 = floor((_e723 + 0.5f));
                                        if ((_e760 - _e723) == 0.5f) {
                                            let _e766 = ((floor((_e760 * 0.5f)) * 2f) != _e760);
                                            if _e766 {
                                                phi_1243_ = (_e760 - 1f);
                                            } else {
                                                phi_1243_ = f32();
                                            }
                                            let _e769 = phi_1243_;
                                            phi_1245_ = _e769;
                                            phi_1246_ = select(true, false, _e766);
                                        } else {
                                            phi_1245_ = f32();
                                            phi_1246_ = true;
                                        }
                                        let _e772 = phi_1245_;
                                        let _e774 = phi_1246_;
                                        let _e776 = (select(_e772, _e760, _e774) / _e111);
                                        let _e777 = (_e405 + _e758);
                                        let _e778 = (_e408 + _e776);
                                        let _e779 = (_e405 - _e758);
                                        let _e780 = (_e408 - _e776);
                                        let _e782 = select(1u, _e105, (1u < _e105));
                                        let _e784 = select(1u, _e116, (1u < _e116));
                                        let _e785 = f32(_e782);
                                        let _e786 = f32(_e784);
                                        phi_1279_ = 1u;
                                        phi_1282_ = _e786;
                                        phi_1284_ = _e785;
                                        phi_1286_ = 0u;
                                        phi_1288_ = _e784;
                                        phi_1290_ = _e782;
                                        loop {
                                            let _e788 = phi_1279_;
                                            let _e790 = phi_1282_;
                                            let _e792 = phi_1284_;
                                            let _e794 = phi_1286_;
                                            let _e796 = phi_1288_;
                                            let _e798 = phi_1290_;
                                            local_3 = _e792;
                                            local_4 = _e798;
                                            local_5 = _e790;
                                            local_6 = _e796;
                                            local_7 = _e798;
                                            local_8 = _e794;
                                            let _e799 = (_e788 < 5u);
                                            if _e799 {
                                                let _e801 = (_e740 >= f32(_e788));
                                                let _e802 = (_e788 & 31u);
                                                let _e804 = (_e105 >> bitcast<u32>(_e802));
                                                let _e806 = select(1u, _e804, (1u < _e804));
                                                let _e808 = (_e116 >> bitcast<u32>(_e802));
                                                let _e810 = select(1u, _e808, (1u < _e808));
                                                phi_1323_ = 0u;
                                                phi_1326_ = 0u;
                                                loop {
                                                    let _e814 = phi_1323_;
                                                    let _e816 = phi_1326_;
                                                    local_2 = _e816;
                                                    let _e817 = (_e814 < _e788);
                                                    if _e817 {
                                                        let _e818 = (_e814 & 31u);
                                                        let _e820 = (_e105 >> bitcast<u32>(_e818));
                                                        let _e824 = (_e116 >> bitcast<u32>(_e818));
                                                        phi_1324_ = (_e814 + 1u);
                                                        phi_1327_ = (_e816 + (select(1u, _e820, (1u < _e820)) * select(1u, _e824, (1u < _e824))));
                                                    } else {
                                                        phi_1324_ = u32();
                                                        phi_1327_ = u32();
                                                    }
                                                    let _e831 = phi_1324_;
                                                    let _e833 = phi_1327_;
                                                    continue;
                                                    continuing {
                                                        phi_1323_ = _e831;
                                                        phi_1326_ = _e833;
                                                        break if !(_e817);
                                                    }
                                                }
                                                let _e836 = local_2;
                                                phi_1280_ = (_e788 + 1u);
                                                phi_1283_ = select(_e790, f32(_e810), _e801);
                                                phi_1285_ = select(_e792, f32(_e806), _e801);
                                                phi_1287_ = select(_e794, _e836, _e801);
                                                phi_1289_ = select(_e796, _e810, _e801);
                                                phi_1291_ = select(_e798, _e806, _e801);
                                            } else {
                                                phi_1280_ = u32();
                                                phi_1283_ = f32();
                                                phi_1285_ = f32();
                                                phi_1287_ = u32();
                                                phi_1289_ = u32();
                                                phi_1291_ = u32();
                                            }
                                            let _e844 = phi_1280_;
                                            let _e846 = phi_1283_;
                                            let _e848 = phi_1285_;
                                            let _e850 = phi_1287_;
                                            let _e852 = phi_1289_;
                                            let _e854 = phi_1291_;
                                            continue;
                                            continuing {
                                                phi_1279_ = _e844;
                                                phi_1282_ = _e846;
                                                phi_1284_ = _e848;
                                                phi_1286_ = _e850;
                                                phi_1288_ = _e852;
                                                phi_1290_ = _e854;
                                                break if !(_e799);
                                            }
                                        }
                                        let _e857 = local_3;
                                        let _e858 = (_e777 * _e857);
                                        if (_e858 > 0f) {
                                            let _e864 = select(select(u32(_e858), 0u, (_e858 < 0f)), 4294967295u, (_e858 > 4294967000f));
                                            let _e866 = local_4;
                                            let _e867 = (_e866 - 1u);
                                            phi_1384_ = select(_e864, _e867, (_e867 < _e864));
                                        } else {
                                            phi_1384_ = 0u;
                                        }
                                        let _e871 = phi_1384_;
                                        let _e873 = local_5;
                                        let _e874 = (_e778 * _e873);
                                        if (_e874 > 0f) {
                                            let _e880 = select(select(u32(_e874), 0u, (_e874 < 0f)), 4294967295u, (_e874 > 4294967000f));
                                            let _e882 = local_6;
                                            let _e883 = (_e882 - 1u);
                                            phi_1403_ = select(_e880, _e883, (_e883 < _e880));
                                        } else {
                                            phi_1403_ = 0u;
                                        }
                                        let _e887 = phi_1403_;
                                        let _e889 = local_7;
                                        let _e892 = local_8;
                                        let _e894 = ((_e892 + (_e887 * _e889)) + _e871);
                                        if (_e894 < _e88) {
                                        } else {
                                            phi_3152_ = true;
                                            break;
                                        }
                                        let _e898 = mips.member[_e894];
                                        phi_1447_ = 1u;
                                        phi_1450_ = _e786;
                                        phi_1452_ = _e785;
                                        phi_1454_ = 0u;
                                        phi_1456_ = _e784;
                                        phi_1458_ = _e782;
                                        loop {
                                            let _e908 = phi_1447_;
                                            let _e910 = phi_1450_;
                                            let _e912 = phi_1452_;
                                            let _e914 = phi_1454_;
                                            let _e916 = phi_1456_;
                                            let _e918 = phi_1458_;
                                            local_10 = _e912;
                                            local_11 = _e918;
                                            local_12 = _e910;
                                            local_13 = _e916;
                                            local_14 = _e918;
                                            local_15 = _e914;
                                            let _e919 = (_e908 < 5u);
                                            if _e919 {
                                                let _e921 = (_e740 >= f32(_e908));
                                                let _e922 = (_e908 & 31u);
                                                let _e924 = (_e105 >> bitcast<u32>(_e922));
                                                let _e926 = select(1u, _e924, (1u < _e924));
                                                let _e928 = (_e116 >> bitcast<u32>(_e922));
                                                let _e930 = select(1u, _e928, (1u < _e928));
                                                phi_1491_ = 0u;
                                                phi_1494_ = 0u;
                                                loop {
                                                    let _e934 = phi_1491_;
                                                    let _e936 = phi_1494_;
                                                    local_9 = _e936;
                                                    let _e937 = (_e934 < _e908);
                                                    if _e937 {
                                                        let _e938 = (_e934 & 31u);
                                                        let _e940 = (_e105 >> bitcast<u32>(_e938));
                                                        let _e944 = (_e116 >> bitcast<u32>(_e938));
                                                        phi_1492_ = (_e934 + 1u);
                                                        phi_1495_ = (_e936 + (select(1u, _e940, (1u < _e940)) * select(1u, _e944, (1u < _e944))));
                                                    } else {
                                                        phi_1492_ = u32();
                                                        phi_1495_ = u32();
                                                    }
                                                    let _e951 = phi_1492_;
                                                    let _e953 = phi_1495_;
                                                    continue;
                                                    continuing {
                                                        phi_1491_ = _e951;
                                                        phi_1494_ = _e953;
                                                        break if !(_e937);
                                                    }
                                                }
                                                let _e956 = local_9;
                                                phi_1448_ = (_e908 + 1u);
                                                phi_1451_ = select(_e910, f32(_e930), _e921);
                                                phi_1453_ = select(_e912, f32(_e926), _e921);
                                                phi_1455_ = select(_e914, _e956, _e921);
                                                phi_1457_ = select(_e916, _e930, _e921);
                                                phi_1459_ = select(_e918, _e926, _e921);
                                            } else {
                                                phi_1448_ = u32();
                                                phi_1451_ = f32();
                                                phi_1453_ = f32();
                                                phi_1455_ = u32();
                                                phi_1457_ = u32();
                                                phi_1459_ = u32();
                                            }
                                            let _e964 = phi_1448_;
                                            let _e966 = phi_1451_;
                                            let _e968 = phi_1453_;
                                            let _e970 = phi_1455_;
                                            let _e972 = phi_1457_;
                                            let _e974 = phi_1459_;
                                            continue;
                                            continuing {
                                                phi_1447_ = _e964;
                                                phi_1450_ = _e966;
                                                phi_1452_ = _e968;
                                                phi_1454_ = _e970;
                                                phi_1456_ = _e972;
                                                phi_1458_ = _e974;
                                                break if !(_e919);
                                            }
                                        }
                                        let _e977 = local_10;
                                        let _e978 = (_e779 * _e977);
                                        if (_e978 > 0f) {
                                            let _e984 = select(select(u32(_e978), 0u, (_e978 < 0f)), 4294967295u, (_e978 > 4294967000f));
                                            let _e986 = local_11;
                                            let _e987 = (_e986 - 1u);
                                            phi_1552_ = select(_e984, _e987, (_e987 < _e984));
                                        } else {
                                            phi_1552_ = 0u;
                                        }
                                        let _e991 = phi_1552_;
                                        let _e993 = local_12;
                                        let _e994 = (_e780 * _e993);
                                        if (_e994 > 0f) {
                                            let _e1000 = select(select(u32(_e994), 0u, (_e994 < 0f)), 4294967295u, (_e994 > 4294967000f));
                                            let _e1002 = local_13;
                                            let _e1003 = (_e1002 - 1u);
                                            phi_1571_ = select(_e1000, _e1003, (_e1003 < _e1000));
                                        } else {
                                            phi_1571_ = 0u;
                                        }
                                        let _e1007 = phi_1571_;
                                        let _e1009 = local_14;
                                        let _e1012 = local_15;
                                        let _e1014 = ((_e1012 + (_e1007 * _e1009)) + _e991);
                                        if (_e1014 < _e88) {
                                        } else {
                                            phi_3152_ = true;
                                            break;
                                        }
                                        let _e1018 = mips.member[_e1014];
                                        let _e1027 = (((((_e777 * 2f) - 1f) * _e417) * _e898) - _e419);
                                        let _e1028 = (((((_e778 * -2f) + 1f) * _e427) * _e898) - _e429);
                                        let _e1029 = (_e898 - _e409);
                                        let _e1032 = params.member.member;
                                        let _e1035 = params.member.member_3;
                                        let _e1040 = (((_e1027 * _e440) + (_e1028 * _e441)) + (_e1029 * _e442));
                                        let _e1044 = (_e1027 - (_e440 * _e1040));
                                        let _e1045 = (_e1028 - (_e441 * _e1040));
                                        let _e1046 = (_e1029 - (_e442 * _e1040));
                                        let _e1055 = ((_e1045 * _e442) - (_e441 * _e1046));
                                        let _e1058 = ((_e1046 * _e440) - (_e442 * _e1044));
                                        let _e1061 = ((_e1044 * _e441) - (_e440 * _e1045));
                                        let _e1068 = (1f / sqrt((((_e1055 * _e1055) + (_e1058 * _e1058)) + (_e1061 * _e1061))));
                                        let _e1069 = (_e1055 * _e1068);
                                        let _e1070 = (_e1058 * _e1068);
                                        let _e1071 = (_e1061 * _e1068);
                                        let _e1076 = (((_e511 * _e1069) + (_e513 * _e1070)) + (_e514 * _e1071));
                                        let _e1080 = (_e511 - (_e1069 * _e1076));
                                        let _e1081 = (_e513 - (_e1070 * _e1076));
                                        let _e1082 = (_e514 - (_e1071 * _e1076));
                                        let _e1088 = sqrt((((_e1080 * _e1080) + (_e1081 * _e1081)) + (_e1082 * _e1082)));
                                        let _e1094 = ((((_e1080 * _e440) + (_e1081 * _e441)) + (_e1082 * _e442)) / _e1088);
                                        let _e1099 = acos(select(0f, select(1f, _e1094, (_e1094 < 1f)), (_e1094 > 0f)));
                                        let _e1107 = select(_e1099, -(_e1099), ((((_e1044 * _e1080) + (_e1045 * _e1081)) + (_e1046 * _e1082)) < 0f));
                                        let _e1108 = (0.02f / _e1088);
                                        if (_e1108 != _e1108) {
                                            phi_2958_ = true;
                                        } else {
                                            phi_2958_ = (0.19634955f <= _e1108);
                                        }
                                        let _e1112 = phi_2958_;
                                        let _e1113 = select(_e1108, 0.19634955f, _e1112);
                                        let _e1114 = (_e440 * _e1032);
                                        let _e1115 = (_e441 * _e1032);
                                        let _e1116 = (_e442 * _e1032);
                                        let _e1117 = (_e1027 - _e1114);
                                        let _e1118 = (_e1028 - _e1115);
                                        let _e1119 = (_e1029 - _e1116);
                                        let _e1125 = sqrt((((_e1027 * _e1027) + (_e1028 * _e1028)) + (_e1029 * _e1029)));
                                        let _e1126 = (1f / _e1125);
                                        let _e1134 = ((((_e1027 * _e1126) * _e440) + ((_e1028 * _e1126) * _e441)) + ((_e1029 * _e1126) * _e442));
                                        let _e1143 = ((((acos(select(-1f, select(1f, _e1134, (_e1134 < 1f)), (_e1134 > -1f))) + _e1113) - _e1107) + 1.5707964f) * 0.31830987f);
                                        let _e1147 = select(0f, select(1f, _e1143, (_e1143 < 1f)), (_e1143 > 0f));
                                        let _e1154 = (1f / sqrt((((_e1117 * _e1117) + (_e1118 * _e1118)) + (_e1119 * _e1119))));
                                        let _e1162 = ((((_e1117 * _e1154) * _e440) + ((_e1118 * _e1154) * _e441)) + ((_e1119 * _e1154) * _e442));
                                        let _e1171 = ((((acos(select(-1f, select(1f, _e1162, (_e1162 < 1f)), (_e1162 > -1f))) + _e1113) - _e1107) + 1.5707964f) * 0.31830987f);
                                        let _e1175 = select(0f, select(1f, _e1171, (_e1171 < 1f)), (_e1171 > 0f));
                                        let _e1176 = (_e1147 != _e1147);
                                        if _e1176 {
                                            phi_2973_ = true;
                                        } else {
                                            phi_2973_ = (_e1175 <= _e1147);
                                        }
                                        let _e1179 = phi_2973_;
                                        let _e1180 = select(_e1147, _e1175, _e1179);
                                        if _e1176 {
                                            phi_2988_ = true;
                                        } else {
                                            phi_2988_ = (_e1175 >= _e1147);
                                        }
                                        let _e1183 = phi_2988_;
                                        let _e1184 = select(_e1147, _e1175, _e1183);
                                        let _e1186 = floor((_e1180 * 32f));
                                        let _e1187 = (_e1035 == 1u);
                                        if _e1187 {
                                            let _e1194 = -(floor((_e1184 * -32f)));
                                            if (_e1194 != _e1194) {
                                                phi_3003_ = true;
                                            } else {
                                                phi_3003_ = (32f <= _e1194);
                                            }
                                            let _e1198 = phi_3003_;
                                            let _e1201 = (select(_e1194, 32f, _e1198) - _e1186);
                                            if (_e1201 != _e1201) {
                                                phi_3018_ = true;
                                            } else {
                                                phi_3018_ = (0f >= _e1201);
                                            }
                                            let _e1205 = phi_3018_;
                                            phi_1846_ = select(select(_e1201, 0f, _e1205), 0f, (_e1184 <= _e1180));
                                        } else {
                                            phi_1846_ = -(floor(((_e1184 - _e1180) * -32f)));
                                        }
                                        let _e1209 = phi_1846_;
                                        if (_e1186 > 0f) {
                                            let _e1215 = select(select(u32(_e1186), 0u, (_e1186 < 0f)), 4294967295u, (_e1186 > 4294967000f));
                                            phi_1864_ = select(_e1215, 32u, (32u < _e1215));
                                        } else {
                                            phi_1864_ = 0u;
                                        }
                                        let _e1219 = phi_1864_;
                                        if (_e1209 > 0f) {
                                            let _e1225 = select(select(u32(_e1209), 0u, (_e1209 < 0f)), 4294967295u, (_e1209 > 4294967000f));
                                            phi_1882_ = select(_e1225, 32u, (32u < _e1225));
                                        } else {
                                            phi_1882_ = 0u;
                                        }
                                        let _e1229 = phi_1882_;
                                        if (_e1219 >= 32u) {
                                            phi_1902_ = u32();
                                            phi_1903_ = true;
                                        } else {
                                            let _e1231 = (_e1229 == 0u);
                                            if _e1231 {
                                                phi_1901_ = u32();
                                            } else {
                                                if (_e1229 >= 32u) {
                                                    phi_1898_ = 4294967295u;
                                                } else {
                                                    phi_1898_ = ((1u << bitcast<u32>((_e1229 & 31u))) - 1u);
                                                }
                                                let _e1238 = phi_1898_;
                                                phi_1901_ = (_e1238 << bitcast<u32>((_e1219 & 31u)));
                                            }
                                            let _e1243 = phi_1901_;
                                            phi_1902_ = _e1243;
                                            phi_1903_ = _e1231;
                                        }
                                        let _e1245 = phi_1902_;
                                        let _e1247 = phi_1903_;
                                        let _e1250 = select(select(_e1245, 0u, _e1247), 0u, (sqrt((((_e1044 * _e1044) + (_e1045 * _e1045)) + (_e1046 * _e1046))) <= 0f));
                                        let _e1253 = params.member.member_1;
                                        let _e1254 = (_e1253 > 0f);
                                        if _e1254 {
                                            phi_1932_ = select(_e1250, 0u, (_e1125 > _e1253));
                                        } else {
                                            phi_1932_ = _e1250;
                                        }
                                        let _e1258 = phi_1932_;
                                        let _e1260 = (((((_e779 * 2f) - 1f) * _e417) * _e1018) - _e419);
                                        let _e1261 = (((((_e780 * -2f) + 1f) * _e427) * _e1018) - _e429);
                                        let _e1262 = (_e1018 - _e409);
                                        let _e1267 = (((_e1260 * _e440) + (_e1261 * _e441)) + (_e1262 * _e442));
                                        let _e1271 = (_e1260 - (_e440 * _e1267));
                                        let _e1272 = (_e1261 - (_e441 * _e1267));
                                        let _e1273 = (_e1262 - (_e442 * _e1267));
                                        let _e1282 = ((_e1272 * _e442) - (_e441 * _e1273));
                                        let _e1285 = ((_e1273 * _e440) - (_e442 * _e1271));
                                        let _e1288 = ((_e1271 * _e441) - (_e440 * _e1272));
                                        let _e1295 = (1f / sqrt((((_e1282 * _e1282) + (_e1285 * _e1285)) + (_e1288 * _e1288))));
                                        let _e1296 = (_e1282 * _e1295);
                                        let _e1297 = (_e1285 * _e1295);
                                        let _e1298 = (_e1288 * _e1295);
                                        let _e1303 = (((_e511 * _e1296) + (_e513 * _e1297)) + (_e514 * _e1298));
                                        let _e1307 = (_e511 - (_e1296 * _e1303));
                                        let _e1308 = (_e513 - (_e1297 * _e1303));
                                        let _e1309 = (_e514 - (_e1298 * _e1303));
                                        let _e1315 = sqrt((((_e1307 * _e1307) + (_e1308 * _e1308)) + (_e1309 * _e1309)));
                                        let _e1321 = ((((_e1307 * _e440) + (_e1308 * _e441)) + (_e1309 * _e442)) / _e1315);
                                        let _e1326 = acos(select(0f, select(1f, _e1321, (_e1321 < 1f)), (_e1321 > 0f)));
                                        let _e1334 = select(_e1326, -(_e1326), ((((_e1271 * _e1307) + (_e1272 * _e1308)) + (_e1273 * _e1309)) < 0f));
                                        let _e1335 = (0.02f / _e1315);
                                        if (_e1335 != _e1335) {
                                            phi_3033_ = true;
                                        } else {
                                            phi_3033_ = (0.19634955f <= _e1335);
                                        }
                                        let _e1339 = phi_3033_;
                                        let _e1340 = select(_e1335, 0.19634955f, _e1339);
                                        let _e1341 = (_e1260 - _e1114);
                                        let _e1342 = (_e1261 - _e1115);
                                        let _e1343 = (_e1262 - _e1116);
                                        let _e1349 = sqrt((((_e1260 * _e1260) + (_e1261 * _e1261)) + (_e1262 * _e1262)));
                                        let _e1350 = (1f / _e1349);
                                        let _e1358 = ((((_e1260 * _e1350) * _e440) + ((_e1261 * _e1350) * _e441)) + ((_e1262 * _e1350) * _e442));
                                        let _e1367 = ((((acos(select(-1f, select(1f, _e1358, (_e1358 < 1f)), (_e1358 > -1f))) + _e1340) - _e1334) + 1.5707964f) * 0.31830987f);
                                        let _e1378 = (1f / sqrt((((_e1341 * _e1341) + (_e1342 * _e1342)) + (_e1343 * _e1343))));
                                        let _e1386 = ((((_e1341 * _e1378) * _e440) + ((_e1342 * _e1378) * _e441)) + ((_e1343 * _e1378) * _e442));
                                        let _e1395 = ((((acos(select(-1f, select(1f, _e1386, (_e1386 < 1f)), (_e1386 > -1f))) + _e1340) - _e1334) + 1.5707964f) * 0.31830987f);
                                        let _e1400 = (1f - select(0f, select(1f, _e1367, (_e1367 < 1f)), (_e1367 > 0f)));
                                        let _e1401 = (1f - select(0f, select(1f, _e1395, (_e1395 < 1f)), (_e1395 > 0f)));
                                        let _e1402 = (_e1400 != _e1400);
                                        if _e1402 {
                                            phi_3048_ = true;
                                        } else {
                                            phi_3048_ = (_e1401 <= _e1400);
                                        }
                                        let _e1405 = phi_3048_;
                                        let _e1406 = select(_e1400, _e1401, _e1405);
                                        if _e1402 {
                                            phi_3063_ = true;
                                        } else {
                                            phi_3063_ = (_e1401 >= _e1400);
                                        }
                                        let _e1409 = phi_3063_;
                                        let _e1410 = select(_e1400, _e1401, _e1409);
                                        let _e1412 = floor((_e1406 * 32f));
                                        if _e1187 {
                                            let _e1419 = -(floor((_e1410 * -32f)));
                                            if (_e1419 != _e1419) {
                                                phi_3078_ = true;
                                            } else {
                                                phi_3078_ = (32f <= _e1419);
                                            }
                                            let _e1423 = phi_3078_;
                                            let _e1426 = (select(_e1419, 32f, _e1423) - _e1412);
                                            if (_e1426 != _e1426) {
                                                phi_3093_ = true;
                                            } else {
                                                phi_3093_ = (0f >= _e1426);
                                            }
                                            let _e1430 = phi_3093_;
                                            phi_2182_ = select(select(_e1426, 0f, _e1430), 0f, (_e1410 <= _e1406));
                                        } else {
                                            phi_2182_ = -(floor(((_e1410 - _e1406) * -32f)));
                                        }
                                        let _e1434 = phi_2182_;
                                        if (_e1412 > 0f) {
                                            let _e1440 = select(select(u32(_e1412), 0u, (_e1412 < 0f)), 4294967295u, (_e1412 > 4294967000f));
                                            phi_2200_ = select(_e1440, 32u, (32u < _e1440));
                                        } else {
                                            phi_2200_ = 0u;
                                        }
                                        let _e1444 = phi_2200_;
                                        if (_e1434 > 0f) {
                                            let _e1450 = select(select(u32(_e1434), 0u, (_e1434 < 0f)), 4294967295u, (_e1434 > 4294967000f));
                                            phi_2218_ = select(_e1450, 32u, (32u < _e1450));
                                        } else {
                                            phi_2218_ = 0u;
                                        }
                                        let _e1454 = phi_2218_;
                                        if (_e1444 >= 32u) {
                                            phi_2238_ = u32();
                                            phi_2239_ = true;
                                        } else {
                                            let _e1456 = (_e1454 == 0u);
                                            if _e1456 {
                                                phi_2237_ = u32();
                                            } else {
                                                if (_e1454 >= 32u) {
                                                    phi_2234_ = 4294967295u;
                                                } else {
                                                    phi_2234_ = ((1u << bitcast<u32>((_e1454 & 31u))) - 1u);
                                                }
                                                let _e1463 = phi_2234_;
                                                phi_2237_ = (_e1463 << bitcast<u32>((_e1444 & 31u)));
                                            }
                                            let _e1468 = phi_2237_;
                                            phi_2238_ = _e1468;
                                            phi_2239_ = _e1456;
                                        }
                                        let _e1470 = phi_2238_;
                                        let _e1472 = phi_2239_;
                                        let _e1475 = select(select(_e1470, 0u, _e1472), 0u, (sqrt((((_e1271 * _e1271) + (_e1272 * _e1272)) + (_e1273 * _e1273))) <= 0f));
                                        if _e1254 {
                                            phi_2268_ = select(_e1475, 0u, (_e1349 > _e1253));
                                        } else {
                                            phi_2268_ = _e1475;
                                        }
                                        let _e1479 = phi_2268_;
                                        phi_1116_ = (_e697 + 1u);
                                        phi_1119_ = ((_e699 | _e1258) | _e1479);
                                    } else {
                                        phi_1116_ = u32();
                                        phi_1119_ = u32();
                                    }
                                    let _e1483 = phi_1116_;
                                    let _e1485 = phi_1119_;
                                    continue;
                                    continuing {
                                        phi_1115_ = _e1483;
                                        phi_1118_ = _e1485;
                                        phi_3152_ = _e606;
                                        break if !(_e700);
                                    }
                                }
                                let _e1488 = phi_3152_;
                                phi_3360_ = _e1488;
                                if _e1488 {
                                    break;
                                }
                                let _e1491 = params.member.member_2;
                                if (_e1491 == 2u) {
                                    let _e1548 = (_e689 - 1.5707964f);
                                    let _e1549 = (_e1548 * 2f);
                                    let _e1550 = sin(_e689);
                                    let _e1555 = ((_e687 + (_e1549 * _e1550)) - cos((_e1549 - _e689)));
                                    phi_2299_ = 0u;
                                    phi_2302_ = select((_e1555 * 0.25f), (_e1555 * -0.25f), (_e1548 < 0f));
                                    phi_2304_ = 0f;
                                    loop {
                                        let _e1561 = phi_2299_;
                                        let _e1563 = phi_2302_;
                                        let _e1565 = phi_2304_;
                                        local_20 = _e1565;
                                        let _e1566 = (_e1561 < 32u);
                                        if _e1566 {
                                            let _e1567 = (_e1561 + 1u);
                                            let _e1570 = (_e1548 + (f32(_e1567) * 0.09817477f));
                                            let _e1571 = (_e1570 * 2f);
                                            let _e1576 = ((_e687 + (_e1571 * _e1550)) - cos((_e1571 - _e689)));
                                            let _e1580 = select((_e1576 * 0.25f), (_e1576 * -0.25f), (_e1570 < 0f));
                                            let _e1583 = local_19;
                                            phi_2300_ = _e1567;
                                            phi_2303_ = _e1580;
                                            phi_2305_ = select(_e1565, (_e1565 + (_e1580 - _e1563)), (((_e1583 >> bitcast<u32>((_e1561 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2300_ = u32();
                                            phi_2303_ = f32();
                                            phi_2305_ = f32();
                                        }
                                        let _e1592 = phi_2300_;
                                        let _e1594 = phi_2303_;
                                        let _e1596 = phi_2305_;
                                        continue;
                                        continuing {
                                            phi_2299_ = _e1592;
                                            phi_2302_ = _e1594;
                                            phi_2304_ = _e1596;
                                            break if !(_e1566);
                                        }
                                    }
                                    let _e1599 = local_20;
                                    phi_3362_ = _e1488;
                                    phi_2407_ = (_e610 + 1f);
                                    phi_2408_ = (_e612 + ((_e668 + ((1f - _e668) * 0.05f)) * _e1599));
                                } else {
                                    if (_e1491 == 1u) {
                                        phi_2352_ = 0u;
                                        phi_2355_ = 0f;
                                        loop {
                                            let _e1504 = phi_2352_;
                                            let _e1506 = phi_2355_;
                                            local_18 = _e1506;
                                            let _e1507 = (_e1504 < 4u);
                                            if _e1507 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1507 {
                                                } else {
                                                    phi_3357_ = true;
                                                    break;
                                                }
                                                let _e1510 = local[_e1504].member;
                                                let _e1513 = local[_e1504].member_1;
                                                let _e1515 = local_17;
                                                phi_2353_ = (_e1504 + 1u);
                                                phi_2356_ = (_e1506 + (f32(countOneBits((_e1515 & _e1510))) * _e1513));
                                            } else {
                                                phi_2353_ = u32();
                                                phi_2356_ = f32();
                                            }
                                            let _e1523 = phi_2353_;
                                            let _e1525 = phi_2356_;
                                            continue;
                                            continuing {
                                                phi_2352_ = _e1523;
                                                phi_2355_ = _e1525;
                                                phi_3357_ = _e1488;
                                                break if !(_e1507);
                                            }
                                        }
                                        let _e1528 = phi_3357_;
                                        phi_3360_ = _e1528;
                                        if _e1528 {
                                            break;
                                        }
                                        let _e1530 = local_18;
                                        let _e1531 = (1f - _e1530);
                                        phi_3368_ = _e1528;
                                        phi_2405_ = (_e610 + _e668);
                                        phi_2406_ = (_e612 + (_e668 * select(0f, select(1f, _e1531, (_e1531 < 1f)), (_e1531 > 0f))));
                                    } else {
                                        let _e1495 = local_16;
                                        phi_3368_ = _e1488;
                                        phi_2405_ = (_e610 + 1f);
                                        phi_2406_ = (_e612 + ((f32(countOneBits((_e1495 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1540 = phi_3368_;
                                    let _e1542 = phi_2405_;
                                    let _e1544 = phi_2406_;
                                    phi_3362_ = _e1540;
                                    phi_2407_ = _e1542;
                                    phi_2408_ = _e1544;
                                }
                                let _e1604 = phi_3362_;
                                let _e1606 = phi_2407_;
                                let _e1608 = phi_2408_;
                                phi_3361_ = _e1604;
                                phi_941_ = (_e608 + 1u);
                                phi_944_ = _e1606;
                                phi_946_ = _e1608;
                            } else {
                                phi_3361_ = _e606;
                                phi_941_ = u32();
                                phi_944_ = f32();
                                phi_946_ = f32();
                            }
                            let _e1611 = phi_3361_;
                            let _e1613 = phi_941_;
                            let _e1615 = phi_944_;
                            let _e1617 = phi_946_;
                            continue;
                            continuing {
                                phi_3276_ = _e1611;
                                phi_940_ = _e1613;
                                phi_943_ = _e1615;
                                phi_945_ = _e1617;
                                phi_3360_ = _e1611;
                                break if !(_e613);
                            }
                        }
                        let _e1620 = phi_3360_;
                        if _e1620 {
                            break;
                        }
                        let _e1622 = local_21;
                        let _e1625 = local_22;
                        let _e1627 = local_23;
                        phi_2416_ = select(1f, (_e1625 / _e1627), (_e1622 > 0f));
                    } else {
                        phi_2416_ = 1f;
                    }
                    let _e1631 = phi_2416_;
                    if _e598 {
                        let _e1635 = params.member.member_4.member_6;
                        let _e1636 = pow(_e1631, _e1635);
                        if (_e1636 != _e1636) {
                            phi_3126_ = true;
                        } else {
                            phi_3126_ = (0.03f >= _e1636);
                        }
                        let _e1640 = phi_3126_;
                        let _e1642 = (select(_e1636, 0.03f, _e1640) * 0.6666667f);
                        let _e1648 = ((select(0f, select(1f, _e1642, (_e1642 < 1f)), (_e1642 > 0f)) * 255f) + 0.5f);
                        phi_2465_ = select(select(u32(_e1648), 0u, (_e1648 < 0f)), 4294967295u, (_e1648 > 4294967000f));
                    } else {
                        phi_2465_ = 170u;
                    }
                    let _e1655 = phi_2465_;
                    if (_e122 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e122] = _e1655;
                    if (_e122 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e122] = ((((64u * _e300) + (16u * _e333)) + (4u * _e367)) + _e401);
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
