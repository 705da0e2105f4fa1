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
    var phi_317_: i32;
    var phi_336_: i32;
    var phi_376_: i32;
    var phi_395_: i32;
    var phi_435_: i32;
    var phi_454_: i32;
    var phi_494_: i32;
    var phi_513_: i32;
    var phi_2450_: f32;
    var phi_2454_: f32;
    var phi_2455_: bool;
    var phi_2493_: f32;
    var phi_2497_: f32;
    var phi_2498_: bool;
    var phi_2536_: f32;
    var phi_2540_: f32;
    var phi_2541_: bool;
    var phi_2579_: f32;
    var phi_2583_: f32;
    var phi_2584_: bool;
    var phi_2606_: bool;
    var phi_2621_: bool;
    var phi_730_: vec2<f32>;
    var phi_758_: vec3<f32>;
    var phi_779_: u32;
    var phi_782_: u32;
    var phi_784_: u32;
    var phi_786_: u32;
    var phi_815_: u32;
    var phi_816_: u32;
    var phi_817_: u32;
    var phi_818_: u32;
    var phi_780_: u32;
    var phi_783_: u32;
    var phi_785_: u32;
    var phi_787_: u32;
    var local_1: u32;
    var phi_2943_: bool;
    var phi_865_: u32;
    var phi_868_: f32;
    var phi_870_: f32;
    var phi_1040_: u32;
    var phi_1043_: u32;
    var phi_1097_: f32;
    var phi_1142_: f32;
    var phi_1144_: f32;
    var phi_1145_: bool;
    var phi_1168_: f32;
    var phi_1170_: f32;
    var phi_1171_: bool;
    var phi_1204_: u32;
    var phi_1207_: f32;
    var phi_1209_: f32;
    var phi_1211_: u32;
    var phi_1213_: u32;
    var phi_1215_: u32;
    var phi_1248_: u32;
    var phi_1251_: u32;
    var phi_1249_: u32;
    var phi_1252_: u32;
    var local_2: u32;
    var phi_1205_: u32;
    var phi_1208_: f32;
    var phi_1210_: f32;
    var phi_1212_: u32;
    var phi_1214_: u32;
    var phi_1216_: u32;
    var local_3: f32;
    var local_4: u32;
    var phi_1309_: u32;
    var local_5: f32;
    var local_6: u32;
    var phi_1328_: u32;
    var local_7: u32;
    var local_8: u32;
    var phi_1372_: u32;
    var phi_1375_: f32;
    var phi_1377_: f32;
    var phi_1379_: u32;
    var phi_1381_: u32;
    var phi_1383_: u32;
    var phi_1416_: u32;
    var phi_1419_: u32;
    var phi_1417_: u32;
    var phi_1420_: u32;
    var local_9: u32;
    var phi_1373_: u32;
    var phi_1376_: f32;
    var phi_1378_: f32;
    var phi_1380_: u32;
    var phi_1382_: u32;
    var phi_1384_: u32;
    var local_10: f32;
    var local_11: u32;
    var phi_1477_: u32;
    var local_12: f32;
    var local_13: u32;
    var phi_1496_: u32;
    var local_14: u32;
    var local_15: u32;
    var phi_2642_: bool;
    var phi_2657_: bool;
    var phi_2672_: bool;
    var phi_2687_: bool;
    var phi_2702_: bool;
    var phi_1771_: f32;
    var phi_1789_: u32;
    var phi_1807_: u32;
    var phi_1823_: u32;
    var phi_1826_: u32;
    var phi_1827_: u32;
    var phi_1828_: bool;
    var phi_1857_: u32;
    var phi_2717_: bool;
    var phi_2732_: bool;
    var phi_2747_: bool;
    var phi_2762_: bool;
    var phi_2777_: bool;
    var phi_2107_: f32;
    var phi_2125_: u32;
    var phi_2143_: u32;
    var phi_2159_: u32;
    var phi_2162_: u32;
    var phi_2163_: u32;
    var phi_2164_: bool;
    var phi_2193_: u32;
    var phi_1041_: u32;
    var phi_1044_: u32;
    var phi_2819_: bool;
    var local_16: u32;
    var phi_2277_: u32;
    var phi_2280_: f32;
    var local_17: u32;
    var phi_2278_: u32;
    var phi_2281_: f32;
    var phi_3010_: bool;
    var local_18: f32;
    var phi_3021_: bool;
    var phi_2330_: f32;
    var phi_2331_: f32;
    var phi_2224_: u32;
    var phi_2227_: f32;
    var phi_2229_: f32;
    var local_19: u32;
    var phi_2225_: u32;
    var phi_2228_: f32;
    var phi_2230_: f32;
    var local_20: f32;
    var phi_3015_: bool;
    var phi_2332_: f32;
    var phi_2333_: f32;
    var phi_3014_: bool;
    var phi_866_: u32;
    var phi_869_: f32;
    var phi_871_: f32;
    var phi_3013_: bool;
    var local_21: f32;
    var local_22: f32;
    var local_23: f32;
    var phi_2341_: f32;
    var phi_2810_: bool;
    var phi_2390_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e85 = id_1;
            let _e87 = arrayLength((&mips.member));
            let _e99 = params.member.member_4.member.member[0u];
            let _e104 = select(select(u32(_e99), 0u, (_e99 < 0f)), 4294967295u, (_e99 > 4294967000f));
            let _e110 = params.member.member_4.member.member[1u];
            let _e115 = select(select(u32(_e110), 0u, (_e110 < 0f)), 4294967295u, (_e110 > 4294967000f));
            if (_e85.x >= _e104) {
            } else {
                if (_e85.y >= _e115) {
                } else {
                    let _e121 = ((_e85.y * _e104) + _e85.x);
                    if (_e121 < _e87) {
                    } else {
                        break;
                    }
                    let _e125 = mips.member[_e121];
                    let _e126 = bitcast<i32>(_e85.x);
                    let _e127 = (_e126 + -1i);
                    let _e129 = (bitcast<i32>(_e104) - 1i);
                    let _e130 = (0i <= _e129);
                    if _e130 {
                    } else {
                        break;
                    }
                    if (_e127 < 0i) {
                        phi_317_ = 0i;
                    } else {
                        phi_317_ = select(_e127, _e129, (_e127 > _e129));
                    }
                    let _e135 = phi_317_;
                    let _e137 = bitcast<i32>(_e85.y);
                    let _e139 = (bitcast<i32>(_e115) - 1i);
                    let _e140 = (0i <= _e139);
                    if _e140 {
                    } else {
                        break;
                    }
                    let _e141 = (_e137 < 0i);
                    if _e141 {
                        phi_336_ = 0i;
                    } else {
                        phi_336_ = select(_e137, _e139, (_e137 > _e139));
                    }
                    let _e145 = phi_336_;
                    let _e148 = ((bitcast<u32>(_e145) * _e104) + bitcast<u32>(_e135));
                    if (_e148 < _e87) {
                    } else {
                        break;
                    }
                    let _e152 = mips.member[_e148];
                    let _e153 = (_e126 + 1i);
                    if _e130 {
                    } else {
                        break;
                    }
                    if (_e153 < 0i) {
                        phi_376_ = 0i;
                    } else {
                        phi_376_ = select(_e153, _e129, (_e153 > _e129));
                    }
                    let _e158 = phi_376_;
                    if _e140 {
                    } else {
                        break;
                    }
                    if _e141 {
                        phi_395_ = 0i;
                    } else {
                        phi_395_ = select(_e137, _e139, (_e137 > _e139));
                    }
                    let _e163 = phi_395_;
                    let _e166 = ((bitcast<u32>(_e163) * _e104) + bitcast<u32>(_e158));
                    if (_e166 < _e87) {
                    } else {
                        break;
                    }
                    let _e170 = mips.member[_e166];
                    if _e130 {
                    } else {
                        break;
                    }
                    let _e171 = (_e126 < 0i);
                    if _e171 {
                        phi_435_ = 0i;
                    } else {
                        phi_435_ = select(_e126, _e129, (_e126 > _e129));
                    }
                    let _e175 = phi_435_;
                    let _e177 = (_e137 + -1i);
                    if _e140 {
                    } else {
                        break;
                    }
                    if (_e177 < 0i) {
                        phi_454_ = 0i;
                    } else {
                        phi_454_ = select(_e177, _e139, (_e177 > _e139));
                    }
                    let _e182 = phi_454_;
                    let _e185 = ((bitcast<u32>(_e182) * _e104) + bitcast<u32>(_e175));
                    if (_e185 < _e87) {
                    } else {
                        break;
                    }
                    let _e189 = mips.member[_e185];
                    if _e130 {
                    } else {
                        break;
                    }
                    if _e171 {
                        phi_494_ = 0i;
                    } else {
                        phi_494_ = select(_e126, _e129, (_e126 > _e129));
                    }
                    let _e193 = phi_494_;
                    let _e195 = (_e137 + 1i);
                    if _e140 {
                    } else {
                        break;
                    }
                    if (_e195 < 0i) {
                        phi_513_ = 0i;
                    } else {
                        phi_513_ = select(_e195, _e139, (_e195 > _e139));
                    }
                    let _e200 = phi_513_;
                    let _e203 = ((bitcast<u32>(_e200) * _e104) + bitcast<u32>(_e193));
                    if (_e203 < _e87) {
                    } else {
                        break;
                    }
                    let _e207 = mips.member[_e203];
                    let _e208 = (_e152 - _e125);
                    let _e209 = (_e170 - _e125);
                    let _e210 = (_e189 - _e125);
                    let _e211 = (_e207 - _e125);
                    let _e212 = (_e209 - _e208);
                    let _e214 = (_e211 - _e210);
                    let _e222 = abs(_e208);
                    let _e223 = abs(_e209);
                    let _e224 = abs(_e210);
                    let _e225 = abs(_e211);
                    let _e226 = abs((_e208 + (_e212 * 0.5f)));
                    let _e227 = abs((_e209 + (_e212 * -0.5f)));
                    let _e228 = abs((_e210 + (_e214 * 0.5f)));
                    let _e229 = abs((_e211 + (_e214 * -0.5f)));
                    let _e238 = (_e125 * 0.011f);
                    let _e243 = (1.25f - (select(_e226, _e222, (_e222 < _e226)) / _e238));
                    let _e247 = select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f));
                    let _e248 = (1.25f - (select(_e227, _e223, (_e223 < _e227)) / _e238));
                    let _e252 = select(0f, select(1f, _e248, (_e248 < 1f)), (_e248 > 0f));
                    let _e253 = (1.25f - (select(_e228, _e224, (_e224 < _e228)) / _e238));
                    let _e257 = select(0f, select(1f, _e253, (_e253 < 1f)), (_e253 > 0f));
                    let _e258 = (1.25f - (select(_e229, _e225, (_e225 < _e229)) / _e238));
                    let _e262 = select(0f, select(1f, _e258, (_e258 < 1f)), (_e258 > 0f));
                    let _e267 = (select(0f, select(1f, _e247, (_e247 < 1f)), (_e247 > 0f)) * 2.9f);
                    let _e269 = floor((_e267 + 0.5f));
                    if ((_e269 - _e267) == 0.5f) {
                        let _e275 = ((floor((_e269 * 0.5f)) * 2f) != _e269);
                        if _e275 {
                            phi_2450_ = (_e269 - 1f);
                        } else {
                            phi_2450_ = f32();
                        }
                        let _e278 = phi_2450_;
                        phi_2454_ = _e278;
                        phi_2455_ = select(true, false, _e275);
                    } else {
                        phi_2454_ = f32();
                        phi_2455_ = true;
                    }
                    let _e281 = phi_2454_;
                    let _e283 = phi_2455_;
                    let _e284 = select(_e281, _e269, _e283);
                    let _e295 = (select(0f, select(1f, _e252, (_e252 < 1f)), (_e252 > 0f)) * 2.9f);
                    let _e297 = floor((_e295 + 0.5f));
                    if ((_e297 - _e295) == 0.5f) {
                        let _e303 = ((floor((_e297 * 0.5f)) * 2f) != _e297);
                        if _e303 {
                            phi_2493_ = (_e297 - 1f);
                        } else {
                            phi_2493_ = f32();
                        }
                        let _e306 = phi_2493_;
                        phi_2497_ = _e306;
                        phi_2498_ = select(true, false, _e303);
                    } else {
                        phi_2497_ = f32();
                        phi_2498_ = true;
                    }
                    let _e309 = phi_2497_;
                    let _e311 = phi_2498_;
                    let _e312 = select(_e309, _e297, _e311);
                    let _e324 = (select(0f, select(1f, _e257, (_e257 < 1f)), (_e257 > 0f)) * 2.9f);
                    let _e326 = floor((_e324 + 0.5f));
                    if ((_e326 - _e324) == 0.5f) {
                        let _e332 = ((floor((_e326 * 0.5f)) * 2f) != _e326);
                        if _e332 {
                            phi_2536_ = (_e326 - 1f);
                        } else {
                            phi_2536_ = f32();
                        }
                        let _e335 = phi_2536_;
                        phi_2540_ = _e335;
                        phi_2541_ = select(true, false, _e332);
                    } else {
                        phi_2540_ = f32();
                        phi_2541_ = true;
                    }
                    let _e338 = phi_2540_;
                    let _e340 = phi_2541_;
                    let _e341 = select(_e338, _e326, _e340);
                    let _e353 = (select(0f, select(1f, _e262, (_e262 < 1f)), (_e262 > 0f)) * 2.9f);
                    let _e355 = floor((_e353 + 0.5f));
                    if ((_e355 - _e353) == 0.5f) {
                        let _e361 = ((floor((_e355 * 0.5f)) * 2f) != _e355);
                        if _e361 {
                            phi_2579_ = (_e355 - 1f);
                        } else {
                            phi_2579_ = f32();
                        }
                        let _e364 = phi_2579_;
                        phi_2583_ = _e364;
                        phi_2584_ = select(true, false, _e361);
                    } else {
                        phi_2583_ = f32();
                        phi_2584_ = true;
                    }
                    let _e367 = phi_2583_;
                    let _e369 = phi_2584_;
                    let _e370 = select(_e367, _e355, _e369);
                    let _e379 = ((f32(_e85.x) + 0.5f) / _e99);
                    let _e382 = ((f32(_e85.y) + 0.5f) / _e110);
                    let _e383 = (_e125 * 0.99999f);
                    let _e391 = params.member.member_4.member.member_1[0u];
                    let _e393 = ((((_e379 * 2f) - 1f) * _e391) * _e383);
                    let _e401 = params.member.member_4.member.member_1[1u];
                    let _e403 = ((((_e382 * -2f) + 1f) * _e401) * _e383);
                    let _e404 = -(_e393);
                    let _e405 = -(_e403);
                    let _e406 = (_e125 * -0.99999f);
                    let _e413 = (1f / sqrt((((_e404 * _e404) + (_e405 * _e405)) + (_e406 * _e406))));
                    let _e414 = (_e404 * _e413);
                    let _e415 = (_e405 * _e413);
                    let _e416 = (_e406 * _e413);
                    if (_e121 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e420 = normals.member[_e121];
                    let _e428 = (f32((bitcast<i32>(((_e420 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e428 != _e428) {
                        phi_2606_ = true;
                    } else {
                        phi_2606_ = (-1f >= _e428);
                    }
                    let _e432 = phi_2606_;
                    let _e433 = select(_e428, -1f, _e432);
                    let _e443 = (f32((bitcast<i32>((((_e420 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e443 != _e443) {
                        phi_2621_ = true;
                    } else {
                        phi_2621_ = (-1f >= _e443);
                    }
                    let _e447 = phi_2621_;
                    let _e448 = select(_e443, -1f, _e447);
                    let _e451 = (1f - abs(_e433));
                    let _e452 = abs(_e448);
                    let _e453 = (_e451 - _e452);
                    if (_e453 < 0f) {
                        phi_730_ = vec2<f32>(((1f - _e452) * select(1f, -1f, (_e433 < 0f))), (_e451 * select(1f, -1f, (_e448 < 0f))));
                    } else {
                        phi_730_ = vec2<f32>(_e433, _e448);
                    }
                    let _e464 = phi_730_;
                    let _e473 = (1f / sqrt((((_e464.x * _e464.x) + (_e464.y * _e464.y)) + (_e453 * _e453))));
                    let _e474 = (_e464.x * _e473);
                    let _e475 = (_e464.y * _e473);
                    let _e476 = (_e453 * _e473);
                    let _e477 = -(_e476);
                    if ((((_e474 * _e414) + (_e475 * _e415)) + (_e477 * _e416)) < 0f) {
                        phi_758_ = vec3<f32>(-(_e474), -(_e475), _e476);
                    } else {
                        phi_758_ = vec3<f32>(_e474, _e475, _e477);
                    }
                    let _e489 = phi_758_;
                    let _e493 = params.member.member_4.member_1;
                    let _e497 = params.member.member_4.member_2;
                    let _e502 = ((_e493 * _e497) / (((_e125 * 1.99998f) * _e391) / _e99));
                    let _e507 = params.member.member_4.member_11;
                    phi_779_ = (_e85.y & 63u);
                    phi_782_ = (_e85.x & 63u);
                    phi_784_ = 32u;
                    phi_786_ = 0u;
                    loop {
                        let _e511 = phi_779_;
                        let _e513 = phi_782_;
                        let _e515 = phi_784_;
                        let _e517 = phi_786_;
                        local_1 = _e517;
                        let _e518 = (_e515 > 0u);
                        if _e518 {
                            let _e521 = select(0u, 1u, ((_e513 & _e515) != 0u));
                            let _e524 = select(0u, 1u, ((_e511 & _e515) != 0u));
                            if (_e524 == 0u) {
                                if (_e521 == 1u) {
                                    phi_815_ = (63u - _e511);
                                    phi_816_ = (63u - _e513);
                                } else {
                                    phi_815_ = _e511;
                                    phi_816_ = _e513;
                                }
                                let _e535 = phi_815_;
                                let _e537 = phi_816_;
                                phi_817_ = _e537;
                                phi_818_ = _e535;
                            } else {
                                phi_817_ = _e511;
                                phi_818_ = _e513;
                            }
                            let _e539 = phi_817_;
                            let _e541 = phi_818_;
                            phi_780_ = _e539;
                            phi_783_ = _e541;
                            phi_785_ = (_e515 / 2u);
                            phi_787_ = (_e517 + ((_e515 * _e515) * ((3u * _e521) ^ _e524)));
                        } else {
                            phi_780_ = u32();
                            phi_783_ = u32();
                            phi_785_ = u32();
                            phi_787_ = u32();
                        }
                        let _e544 = phi_780_;
                        let _e546 = phi_783_;
                        let _e548 = phi_785_;
                        let _e550 = phi_787_;
                        continue;
                        continuing {
                            phi_779_ = _e544;
                            phi_782_ = _e546;
                            phi_784_ = _e548;
                            phi_786_ = _e550;
                            break if !(_e518);
                        }
                    }
                    let _e555 = local_1;
                    let _e557 = f32((_e555 + (288u * (_e507 % 64u))));
                    let _e559 = (0.5f + (_e557 * 0.7548777f));
                    let _e563 = (0.5f + (_e557 * 0.5698403f));
                    let _e570 = params.member.member_4.member.member_3;
                    let _e573 = select(false, (_e125 < _e570), (_e125 > 0f));
                    if _e573 {
                        let _e577 = params.member.member_4.member_8;
                        let _e579 = select(1u, _e577, (1u < _e577));
                        phi_2943_ = false;
                        phi_865_ = 0u;
                        phi_868_ = 0f;
                        phi_870_ = 0f;
                        loop {
                            let _e581 = phi_2943_;
                            let _e583 = phi_865_;
                            let _e585 = phi_868_;
                            let _e587 = phi_870_;
                            local_21 = _e585;
                            local_22 = _e587;
                            local_23 = _e585;
                            let _e588 = (_e583 < _e579);
                            if _e588 {
                                let _e593 = ((((_e559 - floor(_e559)) + f32(_e583)) * 3.1415927f) / f32(_e579));
                                let _e594 = sin(_e593);
                                let _e595 = cos(_e593);
                                let _e601 = ((_e595 * _e414) + (_e594 * _e415));
                                let _e605 = (_e595 - (_e414 * _e601));
                                let _e606 = (_e594 - (_e415 * _e601));
                                let _e607 = -((_e416 * _e601));
                                let _e610 = ((_e606 * _e416) - (_e415 * _e607));
                                let _e613 = ((_e607 * _e414) - (_e416 * _e605));
                                let _e616 = ((_e605 * _e415) - (_e414 * _e606));
                                let _e623 = (1f / sqrt((((_e610 * _e610) + (_e613 * _e613)) + (_e616 * _e616))));
                                let _e624 = (_e610 * _e623);
                                let _e625 = (_e613 * _e623);
                                let _e626 = (_e616 * _e623);
                                let _e634 = (((_e489.x * _e624) + (_e489.y * _e625)) + (_e489.z * _e626));
                                let _e638 = (_e489.x - (_e624 * _e634));
                                let _e639 = (_e489.y - (_e625 * _e634));
                                let _e640 = (_e489.z - (_e626 * _e634));
                                let _e646 = sqrt((((_e638 * _e638) + (_e639 * _e639)) + (_e640 * _e640)));
                                let _e651 = (((_e605 * _e638) + (_e606 * _e639)) + (_e607 * _e640));
                                let _e661 = ((((_e638 * _e414) + (_e639 * _e415)) + (_e640 * _e416)) / _e646);
                                let _e665 = select(0f, select(1f, _e661, (_e661 < 1f)), (_e661 > 0f));
                                let _e667 = (select(select(0f, -1f, (_e651 < 0f)), 1f, (_e651 > 0f)) * acos(_e665));
                                let _e671 = params.member.member_4.member_9;
                                let _e673 = select(1u, _e671, (1u < _e671));
                                phi_1040_ = 0u;
                                phi_1043_ = 0u;
                                loop {
                                    let _e675 = phi_1040_;
                                    let _e677 = phi_1043_;
                                    local_16 = _e677;
                                    local_17 = _e677;
                                    local_19 = _e677;
                                    let _e678 = (_e675 < _e673);
                                    if _e678 {
                                        let _e683 = ((_e563 - floor(_e563)) + (f32((_e583 + (_e675 * _e673))) * 0.618034f));
                                        let _e689 = (((_e683 - floor(_e683)) + f32(_e675)) / f32(_e673));
                                        let _e693 = params.member.member_4.member_4;
                                        if (_e693 == 2f) {
                                            phi_1097_ = (_e689 * _e689);
                                        } else {
                                            phi_1097_ = pow(_e689, _e693);
                                        }
                                        let _e698 = phi_1097_;
                                        let _e699 = (_e698 + (1.3f / _e502));
                                        let _e700 = ((_e595 * _e502) * _e699);
                                        let _e701 = ((-(_e594) * _e502) * _e699);
                                        let _e710 = params.member.member_4.member_7;
                                        let _e711 = (log2(sqrt(((_e700 * _e700) + (_e701 * _e701)))) - _e710);
                                        let _e718 = (-1f - floor((-0.5f - select(0f, select(5f, _e711, (_e711 < 5f)), (_e711 > 0f)))));
                                        let _e720 = floor((_e700 + 0.5f));
                                        if ((_e720 - _e700) == 0.5f) {
                                            let _e726 = ((floor((_e720 * 0.5f)) * 2f) != _e720);
                                            if _e726 {
                                                phi_1142_ = (_e720 - 1f);
                                            } else {
                                                phi_1142_ = f32();
                                            }
                                            let _e729 = phi_1142_;
                                            phi_1144_ = _e729;
                                            phi_1145_ = select(true, false, _e726);
                                        } else {
                                            phi_1144_ = f32();
                                            phi_1145_ = true;
                                        }
                                        let _e732 = phi_1144_;
                                        let _e734 = phi_1145_;
                                        let _e736 = (select(_e732, _e720, _e734) / _e99);
                                        let _e738 = floor((_e701 + 0.5f));
                                        if ((_e738 - _e701) == 0.5f) {
                                            let _e744 = ((floor((_e738 * 0.5f)) * 2f) != _e738);
                                            if _e744 {
                                                phi_1168_ = (_e738 - 1f);
                                            } else {
                                                phi_1168_ = f32();
                                            }
                                            let _e747 = phi_1168_;
                                            phi_1170_ = _e747;
                                            phi_1171_ = select(true, false, _e744);
                                        } else {
                                            phi_1170_ = f32();
                                            phi_1171_ = true;
                                        }
                                        let _e750 = phi_1170_;
                                        let _e752 = phi_1171_;
                                        let _e754 = (select(_e750, _e738, _e752) / _e110);
                                        let _e755 = (_e379 + _e736);
                                        let _e756 = (_e382 + _e754);
                                        let _e757 = (_e379 - _e736);
                                        let _e758 = (_e382 - _e754);
                                        let _e760 = select(1u, _e104, (1u < _e104));
                                        let _e762 = select(1u, _e115, (1u < _e115));
                                        let _e763 = f32(_e760);
                                        let _e764 = f32(_e762);
                                        phi_1204_ = 1u;
                                        phi_1207_ = _e764;
                                        phi_1209_ = _e763;
                                        phi_1211_ = 0u;
                                        phi_1213_ = _e762;
                                        phi_1215_ = _e760;
                                        loop {
                                            let _e766 = phi_1204_;
                                            let _e768 = phi_1207_;
                                            let _e770 = phi_1209_;
                                            let _e772 = phi_1211_;
                                            let _e774 = phi_1213_;
                                            let _e776 = phi_1215_;
                                            local_3 = _e770;
                                            local_4 = _e776;
                                            local_5 = _e768;
                                            local_6 = _e774;
                                            local_7 = _e776;
                                            local_8 = _e772;
                                            let _e777 = (_e766 < 5u);
                                            if _e777 {
                                                let _e779 = (_e718 >= f32(_e766));
                                                let _e780 = (_e766 & 31u);
                                                let _e782 = (_e104 >> bitcast<u32>(_e780));
                                                let _e784 = select(1u, _e782, (1u < _e782));
                                                let _e786 = (_e115 >> bitcast<u32>(_e780));
                                                let _e788 = select(1u, _e786, (1u < _e786));
                                                phi_1248_ = 0u;
                                                phi_1251_ = 0u;
                                                loop {
                                                    let _e792 = phi_1248_;
                                                    let _e794 = phi_1251_;
                                                    local_2 = _e794;
                                                    let _e795 = (_e792 < _e766);
                                                    if _e795 {
                                                        let _e796 = (_e792 & 31u);
                                                        let _e798 = (_e104 >> bitcast<u32>(_e796));
                                                        let _e802 = (_e115 >> bitcast<u32>(_e796));
                                                        phi_1249_ = (_e792 + 1u);
                                                        phi_1252_ = (_e794 + (select(1u, _e798, (1u < _e798)) * select(1u, _e802, (1u < _e802))));
                                                    } else {
                                                        phi_1249_ = u32();
                                                        phi_1252_ = u32();
                                                    }
                                                    let _e809 = phi_1249_;
                                                    let _e811 = phi_1252_;
                                                    continue;
                                                    continuing {
                                                        phi_1248_ = _e809;
                                                        phi_1251_ = _e811;
                                                        break if !(_e795);
                                                    }
                                                }
                                                let _e814 = local_2;
                                                phi_1205_ = (_e766 + 1u);
                                                phi_1208_ = select(_e768, f32(_e788), _e779);
                                                phi_1210_ = select(_e770, f32(_e784), _e779);
                                                phi_1212_ = select(_e772, _e814, _e779);
                                                phi_1214_ = select(_e774, _e788, _e779);
                                                phi_1216_ = select(_e776, _e784, _e779);
                                            } else {
                                                phi_1205_ = u32();
                                                phi_1208_ = f32();
                                                phi_1210_ = f32();
                                                phi_1212_ = u32();
                                                phi_1214_ = u32();
                                                phi_1216_ = u32();
                                            }
                                            let _e822 = phi_1205_;
                                            let _e824 = phi_1208_;
                                            let _e826 = phi_1210_;
                                            let _e828 = phi_1212_;
                                            let _e830 = phi_1214_;
                                            let _e832 = phi_1216_;
                                            continue;
                                            continuing {
                                                phi_1204_ = _e822;
                                                phi_1207_ = _e824;
                                                phi_1209_ = _e826;
                                                phi_1211_ = _e828;
                                                phi_1213_ = _e830;
                                                phi_1215_ = _e832;
                                                break if !(_e777);
                                            }
                                        }
                                        let _e835 = local_3;
                                        let _e836 = (_e755 * _e835);
                                        if (_e836 > 0f) {
                                            let _e842 = select(select(u32(_e836), 0u, (_e836 < 0f)), 4294967295u, (_e836 > 4294967000f));
                                            let _e844 = local_4;
                                            let _e845 = (_e844 - 1u);
                                            phi_1309_ = select(_e842, _e845, (_e845 < _e842));
                                        } else {
                                            phi_1309_ = 0u;
                                        }
                                        let _e849 = phi_1309_;
                                        let _e851 = local_5;
                                        let _e852 = (_e756 * _e851);
                                        if (_e852 > 0f) {
                                            let _e858 = select(select(u32(_e852), 0u, (_e852 < 0f)), 4294967295u, (_e852 > 4294967000f));
                                            let _e860 = local_6;
                                            let _e861 = (_e860 - 1u);
                                            phi_1328_ = select(_e858, _e861, (_e861 < _e858));
                                        } else {
                                            phi_1328_ = 0u;
                                        }
                                        let _e865 = phi_1328_;
                                        let _e867 = local_7;
                                        let _e870 = local_8;
                                        let _e872 = ((_e870 + (_e865 * _e867)) + _e849);
                                        if (_e872 < _e87) {
                                        } else {
                                            phi_2819_ = true;
                                            break;
                                        }
                                        let _e876 = mips.member[_e872];
                                        phi_1372_ = 1u;
                                        phi_1375_ = _e764;
                                        phi_1377_ = _e763;
                                        phi_1379_ = 0u;
                                        phi_1381_ = _e762;
                                        phi_1383_ = _e760;
                                        loop {
                                            let _e886 = phi_1372_;
                                            let _e888 = phi_1375_;
                                            let _e890 = phi_1377_;
                                            let _e892 = phi_1379_;
                                            let _e894 = phi_1381_;
                                            let _e896 = phi_1383_;
                                            local_10 = _e890;
                                            local_11 = _e896;
                                            local_12 = _e888;
                                            local_13 = _e894;
                                            local_14 = _e896;
                                            local_15 = _e892;
                                            let _e897 = (_e886 < 5u);
                                            if _e897 {
                                                let _e899 = (_e718 >= f32(_e886));
                                                let _e900 = (_e886 & 31u);
                                                let _e902 = (_e104 >> bitcast<u32>(_e900));
                                                let _e904 = select(1u, _e902, (1u < _e902));
                                                let _e906 = (_e115 >> bitcast<u32>(_e900));
                                                let _e908 = select(1u, _e906, (1u < _e906));
                                                phi_1416_ = 0u;
                                                phi_1419_ = 0u;
                                                loop {
                                                    let _e912 = phi_1416_;
                                                    let _e914 = phi_1419_;
                                                    local_9 = _e914;
                                                    let _e915 = (_e912 < _e886);
                                                    if _e915 {
                                                        let _e916 = (_e912 & 31u);
                                                        let _e918 = (_e104 >> bitcast<u32>(_e916));
                                                        let _e922 = (_e115 >> bitcast<u32>(_e916));
                                                        phi_1417_ = (_e912 + 1u);
                                                        phi_1420_ = (_e914 + (select(1u, _e918, (1u < _e918)) * select(1u, _e922, (1u < _e922))));
                                                    } else {
                                                        phi_1417_ = u32();
                                                        phi_1420_ = u32();
                                                    }
                                                    let _e929 = phi_1417_;
                                                    let _e931 = phi_1420_;
                                                    continue;
                                                    continuing {
                                                        phi_1416_ = _e929;
                                                        phi_1419_ = _e931;
                                                        break if !(_e915);
                                                    }
                                                }
                                                let _e934 = local_9;
                                                phi_1373_ = (_e886 + 1u);
                                                phi_1376_ = select(_e888, f32(_e908), _e899);
                                                phi_1378_ = select(_e890, f32(_e904), _e899);
                                                phi_1380_ = select(_e892, _e934, _e899);
                                                phi_1382_ = select(_e894, _e908, _e899);
                                                phi_1384_ = select(_e896, _e904, _e899);
                                            } else {
                                                phi_1373_ = u32();
                                                phi_1376_ = f32();
                                                phi_1378_ = f32();
                                                phi_1380_ = u32();
                                                phi_1382_ = u32();
                                                phi_1384_ = u32();
                                            }
                                            let _e942 = phi_1373_;
                                            let _e944 = phi_1376_;
                                            let _e946 = phi_1378_;
                                            let _e948 = phi_1380_;
                                            let _e950 = phi_1382_;
                                            let _e952 = phi_1384_;
                                            continue;
                                            continuing {
                                                phi_1372_ = _e942;
                                                phi_1375_ = _e944;
                                                phi_1377_ = _e946;
                                                phi_1379_ = _e948;
                                                phi_1381_ = _e950;
                                                phi_1383_ = _e952;
                                                break if !(_e897);
                                            }
                                        }
                                        let _e955 = local_10;
                                        let _e956 = (_e757 * _e955);
                                        if (_e956 > 0f) {
                                            let _e962 = select(select(u32(_e956), 0u, (_e956 < 0f)), 4294967295u, (_e956 > 4294967000f));
                                            let _e964 = local_11;
                                            let _e965 = (_e964 - 1u);
                                            phi_1477_ = select(_e962, _e965, (_e965 < _e962));
                                        } else {
                                            phi_1477_ = 0u;
                                        }
                                        let _e969 = phi_1477_;
                                        let _e971 = local_12;
                                        let _e972 = (_e758 * _e971);
                                        if (_e972 > 0f) {
                                            let _e978 = select(select(u32(_e972), 0u, (_e972 < 0f)), 4294967295u, (_e972 > 4294967000f));
                                            let _e980 = local_13;
                                            let _e981 = (_e980 - 1u);
                                            phi_1496_ = select(_e978, _e981, (_e981 < _e978));
                                        } else {
                                            phi_1496_ = 0u;
                                        }
                                        let _e985 = phi_1496_;
                                        let _e987 = local_14;
                                        let _e990 = local_15;
                                        let _e992 = ((_e990 + (_e985 * _e987)) + _e969);
                                        if (_e992 < _e87) {
                                        } else {
                                            phi_2819_ = true;
                                            break;
                                        }
                                        let _e996 = mips.member[_e992];
                                        let _e1005 = (((((_e755 * 2f) - 1f) * _e391) * _e876) - _e393);
                                        let _e1006 = (((((_e756 * -2f) + 1f) * _e401) * _e876) - _e403);
                                        let _e1007 = (_e876 - _e383);
                                        let _e1010 = params.member.member;
                                        let _e1013 = params.member.member_3;
                                        let _e1018 = (((_e1005 * _e414) + (_e1006 * _e415)) + (_e1007 * _e416));
                                        let _e1022 = (_e1005 - (_e414 * _e1018));
                                        let _e1023 = (_e1006 - (_e415 * _e1018));
                                        let _e1024 = (_e1007 - (_e416 * _e1018));
                                        let _e1033 = ((_e1023 * _e416) - (_e415 * _e1024));
                                        let _e1036 = ((_e1024 * _e414) - (_e416 * _e1022));
                                        let _e1039 = ((_e1022 * _e415) - (_e414 * _e1023));
                                        let _e1046 = (1f / sqrt((((_e1033 * _e1033) + (_e1036 * _e1036)) + (_e1039 * _e1039))));
                                        let _e1047 = (_e1033 * _e1046);
                                        let _e1048 = (_e1036 * _e1046);
                                        let _e1049 = (_e1039 * _e1046);
                                        let _e1054 = (((_e489.x * _e1047) + (_e489.y * _e1048)) + (_e489.z * _e1049));
                                        let _e1058 = (_e489.x - (_e1047 * _e1054));
                                        let _e1059 = (_e489.y - (_e1048 * _e1054));
                                        let _e1060 = (_e489.z - (_e1049 * _e1054));
                                        let _e1066 = sqrt((((_e1058 * _e1058) + (_e1059 * _e1059)) + (_e1060 * _e1060)));
                                        let _e1072 = ((((_e1058 * _e414) + (_e1059 * _e415)) + (_e1060 * _e416)) / _e1066);
                                        let _e1077 = acos(select(0f, select(1f, _e1072, (_e1072 < 1f)), (_e1072 > 0f)));
                                        let _e1085 = select(_e1077, -(_e1077), ((((_e1022 * _e1058) + (_e1023 * _e1059)) + (_e1024 * _e1060)) < 0f));
                                        let _e1086 = (0.02f / _e1066);
                                        if (_e1086 != _e1086) {
                                            phi_2642_ = true;
                                        } else {
                                            phi_2642_ = (0.19634955f <= _e1086);
                                        }
                                        let _e1090 = phi_2642_;
                                        let _e1091 = select(_e1086, 0.19634955f, _e1090);
                                        let _e1092 = (_e414 * _e1010);
                                        let _e1093 = (_e415 * _e1010);
                                        let _e1094 = (_e416 * _e1010);
                                        let _e1095 = (_e1005 - _e1092);
                                        let _e1096 = (_e1006 - _e1093);
                                        let _e1097 = (_e1007 - _e1094);
                                        let _e1103 = sqrt((((_e1005 * _e1005) + (_e1006 * _e1006)) + (_e1007 * _e1007)));
                                        let _e1104 = (1f / _e1103);
                                        let _e1112 = ((((_e1005 * _e1104) * _e414) + ((_e1006 * _e1104) * _e415)) + ((_e1007 * _e1104) * _e416));
                                        let _e1121 = ((((acos(select(-1f, select(1f, _e1112, (_e1112 < 1f)), (_e1112 > -1f))) + _e1091) - _e1085) + 1.5707964f) * 0.31830987f);
                                        let _e1125 = select(0f, select(1f, _e1121, (_e1121 < 1f)), (_e1121 > 0f));
                                        let _e1132 = (1f / sqrt((((_e1095 * _e1095) + (_e1096 * _e1096)) + (_e1097 * _e1097))));
                                        let _e1140 = ((((_e1095 * _e1132) * _e414) + ((_e1096 * _e1132) * _e415)) + ((_e1097 * _e1132) * _e416));
                                        let _e1149 = ((((acos(select(-1f, select(1f, _e1140, (_e1140 < 1f)), (_e1140 > -1f))) + _e1091) - _e1085) + 1.5707964f) * 0.31830987f);
                                        let _e1153 = select(0f, select(1f, _e1149, (_e1149 < 1f)), (_e1149 > 0f));
                                        let _e1154 = (_e1125 != _e1125);
                                        if _e1154 {
                                            phi_2657_ = true;
                                        } else {
                                            phi_2657_ = (_e1153 <= _e1125);
                                        }
                                        let _e1157 = phi_2657_;
                                        let _e1158 = select(_e1125, _e1153, _e1157);
                                        if _e1154 {
                                            phi_2672_ = true;
                                        } else {
                                            phi_2672_ = (_e1153 >= _e1125);
                                        }
                                        let _e1161 = phi_2672_;
                                        let _e1162 = select(_e1125, _e1153, _e1161);
                                        let _e1164 = floor((_e1158 * 32f));
                                        let _e1165 = (_e1013 == 1u);
                                        if _e1165 {
                                            let _e1172 = -(floor((_e1162 * -32f)));
                                            if (_e1172 != _e1172) {
                                                phi_2687_ = true;
                                            } else {
                                                phi_2687_ = (32f <= _e1172);
                                            }
                                            let _e1176 = phi_2687_;
                                            let _e1179 = (select(_e1172, 32f, _e1176) - _e1164);
                                            if (_e1179 != _e1179) {
                                                phi_2702_ = true;
                                            } else {
                                                phi_2702_ = (0f >= _e1179);
                                            }
                                            let _e1183 = phi_2702_;
                                            phi_1771_ = select(select(_e1179, 0f, _e1183), 0f, (_e1162 <= _e1158));
                                        } else {
                                            phi_1771_ = -(floor(((_e1162 - _e1158) * -32f)));
                                        }
                                        let _e1187 = phi_1771_;
                                        if (_e1164 > 0f) {
                                            let _e1193 = select(select(u32(_e1164), 0u, (_e1164 < 0f)), 4294967295u, (_e1164 > 4294967000f));
                                            phi_1789_ = select(_e1193, 32u, (32u < _e1193));
                                        } else {
                                            phi_1789_ = 0u;
                                        }
                                        let _e1197 = phi_1789_;
                                        if (_e1187 > 0f) {
                                            let _e1203 = select(select(u32(_e1187), 0u, (_e1187 < 0f)), 4294967295u, (_e1187 > 4294967000f));
                                            phi_1807_ = select(_e1203, 32u, (32u < _e1203));
                                        } else {
                                            phi_1807_ = 0u;
                                        }
                                        let _e1207 = phi_1807_;
                                        if (_e1197 >= 32u) {
                                            phi_1827_ = u32();
                                            phi_1828_ = true;
                                        } else {
                                            let _e1209 = (_e1207 == 0u);
                                            if _e1209 {
                                                phi_1826_ = u32();
                                            } else {
                                                if (_e1207 >= 32u) {
                                                    phi_1823_ = 4294967295u;
                                                } else {
                                                    phi_1823_ = ((1u << bitcast<u32>((_e1207 & 31u))) - 1u);
                                                }
                                                let _e1216 = phi_1823_;
                                                phi_1826_ = (_e1216 << bitcast<u32>((_e1197 & 31u)));
                                            }
                                            let _e1221 = phi_1826_;
                                            phi_1827_ = _e1221;
                                            phi_1828_ = _e1209;
                                        }
                                        let _e1223 = phi_1827_;
                                        let _e1225 = phi_1828_;
                                        let _e1228 = select(select(_e1223, 0u, _e1225), 0u, (sqrt((((_e1022 * _e1022) + (_e1023 * _e1023)) + (_e1024 * _e1024))) <= 0f));
                                        let _e1231 = params.member.member_1;
                                        let _e1232 = (_e1231 > 0f);
                                        if _e1232 {
                                            phi_1857_ = select(_e1228, 0u, (_e1103 > _e1231));
                                        } else {
                                            phi_1857_ = _e1228;
                                        }
                                        let _e1236 = phi_1857_;
                                        let _e1238 = (((((_e757 * 2f) - 1f) * _e391) * _e996) - _e393);
                                        let _e1239 = (((((_e758 * -2f) + 1f) * _e401) * _e996) - _e403);
                                        let _e1240 = (_e996 - _e383);
                                        let _e1245 = (((_e1238 * _e414) + (_e1239 * _e415)) + (_e1240 * _e416));
                                        let _e1249 = (_e1238 - (_e414 * _e1245));
                                        let _e1250 = (_e1239 - (_e415 * _e1245));
                                        let _e1251 = (_e1240 - (_e416 * _e1245));
                                        let _e1260 = ((_e1250 * _e416) - (_e415 * _e1251));
                                        let _e1263 = ((_e1251 * _e414) - (_e416 * _e1249));
                                        let _e1266 = ((_e1249 * _e415) - (_e414 * _e1250));
                                        let _e1273 = (1f / sqrt((((_e1260 * _e1260) + (_e1263 * _e1263)) + (_e1266 * _e1266))));
                                        let _e1274 = (_e1260 * _e1273);
                                        let _e1275 = (_e1263 * _e1273);
                                        let _e1276 = (_e1266 * _e1273);
                                        let _e1281 = (((_e489.x * _e1274) + (_e489.y * _e1275)) + (_e489.z * _e1276));
                                        let _e1285 = (_e489.x - (_e1274 * _e1281));
                                        let _e1286 = (_e489.y - (_e1275 * _e1281));
                                        let _e1287 = (_e489.z - (_e1276 * _e1281));
                                        let _e1293 = sqrt((((_e1285 * _e1285) + (_e1286 * _e1286)) + (_e1287 * _e1287)));
                                        let _e1299 = ((((_e1285 * _e414) + (_e1286 * _e415)) + (_e1287 * _e416)) / _e1293);
                                        let _e1304 = acos(select(0f, select(1f, _e1299, (_e1299 < 1f)), (_e1299 > 0f)));
                                        let _e1312 = select(_e1304, -(_e1304), ((((_e1249 * _e1285) + (_e1250 * _e1286)) + (_e1251 * _e1287)) < 0f));
                                        let _e1313 = (0.02f / _e1293);
                                        if (_e1313 != _e1313) {
                                            phi_2717_ = true;
                                        } else {
                                            phi_2717_ = (0.19634955f <= _e1313);
                                        }
                                        let _e1317 = phi_2717_;
                                        let _e1318 = select(_e1313, 0.19634955f, _e1317);
                                        let _e1319 = (_e1238 - _e1092);
                                        let _e1320 = (_e1239 - _e1093);
                                        let _e1321 = (_e1240 - _e1094);
                                        let _e1327 = sqrt((((_e1238 * _e1238) + (_e1239 * _e1239)) + (_e1240 * _e1240)));
                                        let _e1328 = (1f / _e1327);
                                        let _e1336 = ((((_e1238 * _e1328) * _e414) + ((_e1239 * _e1328) * _e415)) + ((_e1240 * _e1328) * _e416));
                                        let _e1345 = ((((acos(select(-1f, select(1f, _e1336, (_e1336 < 1f)), (_e1336 > -1f))) + _e1318) - _e1312) + 1.5707964f) * 0.31830987f);
                                        let _e1356 = (1f / sqrt((((_e1319 * _e1319) + (_e1320 * _e1320)) + (_e1321 * _e1321))));
                                        let _e1364 = ((((_e1319 * _e1356) * _e414) + ((_e1320 * _e1356) * _e415)) + ((_e1321 * _e1356) * _e416));
                                        let _e1373 = ((((acos(select(-1f, select(1f, _e1364, (_e1364 < 1f)), (_e1364 > -1f))) + _e1318) - _e1312) + 1.5707964f) * 0.31830987f);
                                        let _e1378 = (1f - select(0f, select(1f, _e1345, (_e1345 < 1f)), (_e1345 > 0f)));
                                        let _e1379 = (1f - select(0f, select(1f, _e1373, (_e1373 < 1f)), (_e1373 > 0f)));
                                        let _e1380 = (_e1378 != _e1378);
                                        if _e1380 {
                                            phi_2732_ = true;
                                        } else {
                                            phi_2732_ = (_e1379 <= _e1378);
                                        }
                                        let _e1383 = phi_2732_;
                                        let _e1384 = select(_e1378, _e1379, _e1383);
                                        if _e1380 {
                                            phi_2747_ = true;
                                        } else {
                                            phi_2747_ = (_e1379 >= _e1378);
                                        }
                                        let _e1387 = phi_2747_;
                                        let _e1388 = select(_e1378, _e1379, _e1387);
                                        let _e1390 = floor((_e1384 * 32f));
                                        if _e1165 {
                                            let _e1397 = -(floor((_e1388 * -32f)));
                                            if (_e1397 != _e1397) {
                                                phi_2762_ = true;
                                            } else {
                                                phi_2762_ = (32f <= _e1397);
                                            }
                                            let _e1401 = phi_2762_;
                                            let _e1404 = (select(_e1397, 32f, _e1401) - _e1390);
                                            if (_e1404 != _e1404) {
                                                phi_2777_ = true;
                                            } else {
                                                phi_2777_ = (0f >= _e1404);
                                            }
                                            let _e1408 = phi_2777_;
                                            phi_2107_ = select(select(_e1404, 0f, _e1408), 0f, (_e1388 <= _e1384));
                                        } else {
                                            phi_2107_ = -(floor(((_e1388 - _e1384) * -32f)));
                                        }
                                        let _e1412 = phi_2107_;
                                        if (_e1390 > 0f) {
                                            let _e1418 = select(select(u32(_e1390), 0u, (_e1390 < 0f)), 4294967295u, (_e1390 > 4294967000f));
                                            phi_2125_ = select(_e1418, 32u, (32u < _e1418));
                                        } else {
                                            phi_2125_ = 0u;
                                        }
                                        let _e1422 = phi_2125_;
                                        if (_e1412 > 0f) {
                                            let _e1428 = select(select(u32(_e1412), 0u, (_e1412 < 0f)), 4294967295u, (_e1412 > 4294967000f));
                                            phi_2143_ = select(_e1428, 32u, (32u < _e1428));
                                        } else {
                                            phi_2143_ = 0u;
                                        }
                                        let _e1432 = phi_2143_;
                                        if (_e1422 >= 32u) {
                                            phi_2163_ = u32();
                                            phi_2164_ = true;
                                        } else {
                                            let _e1434 = (_e1432 == 0u);
                                            if _e1434 {
                                                phi_2162_ = u32();
                                            } else {
                                                if (_e1432 >= 32u) {
                                                    phi_2159_ = 4294967295u;
                                                } else {
                                                    phi_2159_ = ((1u << bitcast<u32>((_e1432 & 31u))) - 1u);
                                                }
                                                let _e1441 = phi_2159_;
                                                phi_2162_ = (_e1441 << bitcast<u32>((_e1422 & 31u)));
                                            }
                                            let _e1446 = phi_2162_;
                                            phi_2163_ = _e1446;
                                            phi_2164_ = _e1434;
                                        }
                                        let _e1448 = phi_2163_;
                                        let _e1450 = phi_2164_;
                                        let _e1453 = select(select(_e1448, 0u, _e1450), 0u, (sqrt((((_e1249 * _e1249) + (_e1250 * _e1250)) + (_e1251 * _e1251))) <= 0f));
                                        if _e1232 {
                                            phi_2193_ = select(_e1453, 0u, (_e1327 > _e1231));
                                        } else {
                                            phi_2193_ = _e1453;
                                        }
                                        let _e1457 = phi_2193_;
                                        phi_1041_ = (_e675 + 1u);
                                        phi_1044_ = ((_e677 | _e1236) | _e1457);
                                    } else {
                                        phi_1041_ = u32();
                                        phi_1044_ = u32();
                                    }
                                    let _e1461 = phi_1041_;
                                    let _e1463 = phi_1044_;
                                    continue;
                                    continuing {
                                        phi_1040_ = _e1461;
                                        phi_1043_ = _e1463;
                                        phi_2819_ = _e581;
                                        break if !(_e678);
                                    }
                                }
                                let _e1466 = phi_2819_;
                                phi_3013_ = _e1466;
                                if _e1466 {
                                    break;
                                }
                                let _e1469 = params.member.member_2;
                                if (_e1469 == 2u) {
                                    let _e1526 = (_e667 - 1.5707964f);
                                    let _e1527 = (_e1526 * 2f);
                                    let _e1528 = sin(_e667);
                                    let _e1533 = ((_e665 + (_e1527 * _e1528)) - cos((_e1527 - _e667)));
                                    phi_2224_ = 0u;
                                    phi_2227_ = select((_e1533 * 0.25f), (_e1533 * -0.25f), (_e1526 < 0f));
                                    phi_2229_ = 0f;
                                    loop {
                                        let _e1539 = phi_2224_;
                                        let _e1541 = phi_2227_;
                                        let _e1543 = phi_2229_;
                                        local_20 = _e1543;
                                        let _e1544 = (_e1539 < 32u);
                                        if _e1544 {
                                            let _e1545 = (_e1539 + 1u);
                                            let _e1548 = (_e1526 + (f32(_e1545) * 0.09817477f));
                                            let _e1549 = (_e1548 * 2f);
                                            let _e1554 = ((_e665 + (_e1549 * _e1528)) - cos((_e1549 - _e667)));
                                            let _e1558 = select((_e1554 * 0.25f), (_e1554 * -0.25f), (_e1548 < 0f));
                                            let _e1561 = local_19;
                                            phi_2225_ = _e1545;
                                            phi_2228_ = _e1558;
                                            phi_2230_ = select(_e1543, (_e1543 + (_e1558 - _e1541)), (((_e1561 >> bitcast<u32>((_e1539 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2225_ = u32();
                                            phi_2228_ = f32();
                                            phi_2230_ = f32();
                                        }
                                        let _e1570 = phi_2225_;
                                        let _e1572 = phi_2228_;
                                        let _e1574 = phi_2230_;
                                        continue;
                                        continuing {
                                            phi_2224_ = _e1570;
                                            phi_2227_ = _e1572;
                                            phi_2229_ = _e1574;
                                            break if !(_e1544);
                                        }
                                    }
                                    let _e1577 = local_20;
                                    phi_3015_ = _e1466;
                                    phi_2332_ = (_e585 + 1f);
                                    phi_2333_ = (_e587 + ((_e646 + ((1f - _e646) * 0.05f)) * _e1577));
                                } else {
                                    if (_e1469 == 1u) {
                                        phi_2277_ = 0u;
                                        phi_2280_ = 0f;
                                        loop {
                                            let _e1482 = phi_2277_;
                                            let _e1484 = phi_2280_;
                                            local_18 = _e1484;
                                            let _e1485 = (_e1482 < 4u);
                                            if _e1485 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1485 {
                                                } else {
                                                    phi_3010_ = true;
                                                    break;
                                                }
                                                let _e1488 = local[_e1482].member;
                                                let _e1491 = local[_e1482].member_1;
                                                let _e1493 = local_17;
                                                phi_2278_ = (_e1482 + 1u);
                                                phi_2281_ = (_e1484 + (f32(countOneBits((_e1493 & _e1488))) * _e1491));
                                            } else {
                                                phi_2278_ = u32();
                                                phi_2281_ = f32();
                                            }
                                            let _e1501 = phi_2278_;
                                            let _e1503 = phi_2281_;
                                            continue;
                                            continuing {
                                                phi_2277_ = _e1501;
                                                phi_2280_ = _e1503;
                                                phi_3010_ = _e1466;
                                                break if !(_e1485);
                                            }
                                        }
                                        let _e1506 = phi_3010_;
                                        phi_3013_ = _e1506;
                                        if _e1506 {
                                            break;
                                        }
                                        let _e1508 = local_18;
                                        let _e1509 = (1f - _e1508);
                                        phi_3021_ = _e1506;
                                        phi_2330_ = (_e585 + _e646);
                                        phi_2331_ = (_e587 + (_e646 * select(0f, select(1f, _e1509, (_e1509 < 1f)), (_e1509 > 0f))));
                                    } else {
                                        let _e1473 = local_16;
                                        phi_3021_ = _e1466;
                                        phi_2330_ = (_e585 + 1f);
                                        phi_2331_ = (_e587 + ((f32(countOneBits((_e1473 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1518 = phi_3021_;
                                    let _e1520 = phi_2330_;
                                    let _e1522 = phi_2331_;
                                    phi_3015_ = _e1518;
                                    phi_2332_ = _e1520;
                                    phi_2333_ = _e1522;
                                }
                                let _e1582 = phi_3015_;
                                let _e1584 = phi_2332_;
                                let _e1586 = phi_2333_;
                                phi_3014_ = _e1582;
                                phi_866_ = (_e583 + 1u);
                                phi_869_ = _e1584;
                                phi_871_ = _e1586;
                            } else {
                                phi_3014_ = _e581;
                                phi_866_ = u32();
                                phi_869_ = f32();
                                phi_871_ = f32();
                            }
                            let _e1589 = phi_3014_;
                            let _e1591 = phi_866_;
                            let _e1593 = phi_869_;
                            let _e1595 = phi_871_;
                            continue;
                            continuing {
                                phi_2943_ = _e1589;
                                phi_865_ = _e1591;
                                phi_868_ = _e1593;
                                phi_870_ = _e1595;
                                phi_3013_ = _e1589;
                                break if !(_e588);
                            }
                        }
                        let _e1598 = phi_3013_;
                        if _e1598 {
                            break;
                        }
                        let _e1600 = local_21;
                        let _e1603 = local_22;
                        let _e1605 = local_23;
                        phi_2341_ = select(1f, (_e1603 / _e1605), (_e1600 > 0f));
                    } else {
                        phi_2341_ = 1f;
                    }
                    let _e1609 = phi_2341_;
                    if _e573 {
                        let _e1613 = params.member.member_4.member_6;
                        let _e1614 = pow(_e1609, _e1613);
                        if (_e1614 != _e1614) {
                            phi_2810_ = true;
                        } else {
                            phi_2810_ = (0.03f >= _e1614);
                        }
                        let _e1618 = phi_2810_;
                        let _e1620 = (select(_e1614, 0.03f, _e1618) * 0.6666667f);
                        let _e1626 = ((select(0f, select(1f, _e1620, (_e1620 < 1f)), (_e1620 > 0f)) * 255f) + 0.5f);
                        phi_2390_ = select(select(u32(_e1626), 0u, (_e1626 < 0f)), 4294967295u, (_e1626 > 4294967000f));
                    } else {
                        phi_2390_ = 170u;
                    }
                    let _e1633 = phi_2390_;
                    if (_e121 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e121] = _e1633;
                    if (_e121 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e121] = ((((64u * select(select(u32(_e284), 0u, (_e284 < 0f)), 4294967295u, (_e284 > 4294967000f))) + (16u * select(select(u32(_e312), 0u, (_e312 < 0f)), 4294967295u, (_e312 > 4294967000f)))) + (4u * select(select(u32(_e341), 0u, (_e341 < 0f)), 4294967295u, (_e341 > 4294967000f)))) + select(select(u32(_e370), 0u, (_e370 < 0f)), 4294967295u, (_e370 > 4294967000f)));
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
