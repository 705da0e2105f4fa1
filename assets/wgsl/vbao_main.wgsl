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
    var phi_322_: i32;
    var phi_341_: i32;
    var phi_381_: i32;
    var phi_400_: i32;
    var phi_440_: i32;
    var phi_459_: i32;
    var phi_499_: i32;
    var phi_518_: i32;
    var phi_2384_: f32;
    var phi_2388_: f32;
    var phi_2389_: bool;
    var phi_2427_: f32;
    var phi_2431_: f32;
    var phi_2432_: bool;
    var phi_2470_: f32;
    var phi_2474_: f32;
    var phi_2475_: bool;
    var phi_2513_: f32;
    var phi_2517_: f32;
    var phi_2518_: bool;
    var phi_2540_: bool;
    var phi_2555_: bool;
    var phi_735_: vec2<f32>;
    var phi_763_: vec3<f32>;
    var phi_784_: u32;
    var phi_787_: u32;
    var phi_789_: u32;
    var phi_791_: u32;
    var phi_820_: u32;
    var phi_821_: u32;
    var phi_822_: u32;
    var phi_823_: u32;
    var phi_785_: u32;
    var phi_788_: u32;
    var phi_790_: u32;
    var phi_792_: u32;
    var local_1: u32;
    var phi_2963_: bool;
    var phi_870_: u32;
    var phi_873_: f32;
    var phi_875_: f32;
    var phi_1045_: u32;
    var phi_1048_: u32;
    var phi_1102_: f32;
    var phi_1147_: f32;
    var phi_1149_: f32;
    var phi_1150_: bool;
    var phi_1173_: f32;
    var phi_1175_: f32;
    var phi_1176_: bool;
    var phi_1209_: u32;
    var phi_1212_: f32;
    var phi_1214_: f32;
    var phi_1216_: u32;
    var phi_1218_: u32;
    var phi_1220_: u32;
    var phi_1253_: u32;
    var phi_1256_: u32;
    var phi_1254_: u32;
    var phi_1257_: u32;
    var local_2: u32;
    var phi_1210_: u32;
    var phi_1213_: f32;
    var phi_1215_: f32;
    var phi_1217_: u32;
    var phi_1219_: u32;
    var phi_1221_: u32;
    var local_3: f32;
    var local_4: u32;
    var phi_1314_: u32;
    var local_5: f32;
    var local_6: u32;
    var phi_1333_: u32;
    var local_7: u32;
    var local_8: u32;
    var phi_1377_: u32;
    var phi_1380_: f32;
    var phi_1382_: f32;
    var phi_1384_: u32;
    var phi_1386_: u32;
    var phi_1388_: u32;
    var phi_1421_: u32;
    var phi_1424_: u32;
    var phi_1422_: u32;
    var phi_1425_: u32;
    var local_9: u32;
    var phi_1378_: u32;
    var phi_1381_: f32;
    var phi_1383_: f32;
    var phi_1385_: u32;
    var phi_1387_: u32;
    var phi_1389_: u32;
    var local_10: f32;
    var local_11: u32;
    var phi_1482_: u32;
    var local_12: f32;
    var local_13: u32;
    var phi_1501_: u32;
    var local_14: u32;
    var local_15: u32;
    var phi_2576_: bool;
    var phi_2591_: bool;
    var phi_2606_: bool;
    var phi_2621_: bool;
    var phi_2636_: bool;
    var phi_1776_: f32;
    var phi_2674_: u32;
    var phi_2678_: u32;
    var phi_2680_: u32;
    var phi_2681_: bool;
    var phi_1804_: u32;
    var phi_2696_: bool;
    var phi_2711_: bool;
    var phi_2726_: bool;
    var phi_2741_: bool;
    var phi_2756_: bool;
    var phi_2054_: f32;
    var phi_2794_: u32;
    var phi_2798_: u32;
    var phi_2800_: u32;
    var phi_2801_: bool;
    var phi_2082_: u32;
    var phi_1046_: u32;
    var phi_1049_: u32;
    var phi_2847_: bool;
    var local_16: u32;
    var phi_2166_: u32;
    var phi_2169_: f32;
    var local_17: u32;
    var phi_2167_: u32;
    var phi_2170_: f32;
    var phi_3030_: bool;
    var local_18: f32;
    var phi_3041_: bool;
    var phi_2219_: f32;
    var phi_2220_: f32;
    var phi_2113_: u32;
    var phi_2116_: f32;
    var phi_2118_: f32;
    var local_19: u32;
    var phi_2114_: u32;
    var phi_2117_: f32;
    var phi_2119_: f32;
    var local_20: f32;
    var phi_3035_: bool;
    var phi_2221_: f32;
    var phi_2222_: f32;
    var phi_3034_: bool;
    var phi_871_: u32;
    var phi_874_: f32;
    var phi_876_: f32;
    var phi_3033_: bool;
    var local_21: f32;
    var local_22: f32;
    var local_23: f32;
    var phi_2230_: f32;
    var phi_2834_: bool;
    var phi_2279_: u32;

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
                        phi_322_ = 0i;
                    } else {
                        phi_322_ = select(_e127, _e129, (_e127 > _e129));
                    }
                    let _e135 = phi_322_;
                    let _e137 = bitcast<i32>(_e85.y);
                    let _e139 = (bitcast<i32>(_e115) - 1i);
                    let _e140 = (0i <= _e139);
                    if _e140 {
                    } else {
                        break;
                    }
                    let _e141 = (_e137 < 0i);
                    if _e141 {
                        phi_341_ = 0i;
                    } else {
                        phi_341_ = select(_e137, _e139, (_e137 > _e139));
                    }
                    let _e145 = phi_341_;
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
                        phi_381_ = 0i;
                    } else {
                        phi_381_ = select(_e153, _e129, (_e153 > _e129));
                    }
                    let _e158 = phi_381_;
                    if _e140 {
                    } else {
                        break;
                    }
                    if _e141 {
                        phi_400_ = 0i;
                    } else {
                        phi_400_ = select(_e137, _e139, (_e137 > _e139));
                    }
                    let _e163 = phi_400_;
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
                        phi_440_ = 0i;
                    } else {
                        phi_440_ = select(_e126, _e129, (_e126 > _e129));
                    }
                    let _e175 = phi_440_;
                    let _e177 = (_e137 + -1i);
                    if _e140 {
                    } else {
                        break;
                    }
                    if (_e177 < 0i) {
                        phi_459_ = 0i;
                    } else {
                        phi_459_ = select(_e177, _e139, (_e177 > _e139));
                    }
                    let _e182 = phi_459_;
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
                        phi_499_ = 0i;
                    } else {
                        phi_499_ = select(_e126, _e129, (_e126 > _e129));
                    }
                    let _e193 = phi_499_;
                    let _e195 = (_e137 + 1i);
                    if _e140 {
                    } else {
                        break;
                    }
                    if (_e195 < 0i) {
                        phi_518_ = 0i;
                    } else {
                        phi_518_ = select(_e195, _e139, (_e195 > _e139));
                    }
                    let _e200 = phi_518_;
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
                            phi_2384_ = (_e269 - 1f);
                        } else {
                            phi_2384_ = f32();
                        }
                        let _e278 = phi_2384_;
                        phi_2388_ = _e278;
                        phi_2389_ = select(true, false, _e275);
                    } else {
                        phi_2388_ = f32();
                        phi_2389_ = true;
                    }
                    let _e281 = phi_2388_;
                    let _e283 = phi_2389_;
                    let _e284 = select(_e281, _e269, _e283);
                    let _e295 = (select(0f, select(1f, _e252, (_e252 < 1f)), (_e252 > 0f)) * 2.9f);
                    let _e297 = floor((_e295 + 0.5f));
                    if ((_e297 - _e295) == 0.5f) {
                        let _e303 = ((floor((_e297 * 0.5f)) * 2f) != _e297);
                        if _e303 {
                            phi_2427_ = (_e297 - 1f);
                        } else {
                            phi_2427_ = f32();
                        }
                        let _e306 = phi_2427_;
                        phi_2431_ = _e306;
                        phi_2432_ = select(true, false, _e303);
                    } else {
                        phi_2431_ = f32();
                        phi_2432_ = true;
                    }
                    let _e309 = phi_2431_;
                    let _e311 = phi_2432_;
                    let _e312 = select(_e309, _e297, _e311);
                    let _e324 = (select(0f, select(1f, _e257, (_e257 < 1f)), (_e257 > 0f)) * 2.9f);
                    let _e326 = floor((_e324 + 0.5f));
                    if ((_e326 - _e324) == 0.5f) {
                        let _e332 = ((floor((_e326 * 0.5f)) * 2f) != _e326);
                        if _e332 {
                            phi_2470_ = (_e326 - 1f);
                        } else {
                            phi_2470_ = f32();
                        }
                        let _e335 = phi_2470_;
                        phi_2474_ = _e335;
                        phi_2475_ = select(true, false, _e332);
                    } else {
                        phi_2474_ = f32();
                        phi_2475_ = true;
                    }
                    let _e338 = phi_2474_;
                    let _e340 = phi_2475_;
                    let _e341 = select(_e338, _e326, _e340);
                    let _e353 = (select(0f, select(1f, _e262, (_e262 < 1f)), (_e262 > 0f)) * 2.9f);
                    let _e355 = floor((_e353 + 0.5f));
                    if ((_e355 - _e353) == 0.5f) {
                        let _e361 = ((floor((_e355 * 0.5f)) * 2f) != _e355);
                        if _e361 {
                            phi_2513_ = (_e355 - 1f);
                        } else {
                            phi_2513_ = f32();
                        }
                        let _e364 = phi_2513_;
                        phi_2517_ = _e364;
                        phi_2518_ = select(true, false, _e361);
                    } else {
                        phi_2517_ = f32();
                        phi_2518_ = true;
                    }
                    let _e367 = phi_2517_;
                    let _e369 = phi_2518_;
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
                        phi_2540_ = true;
                    } else {
                        phi_2540_ = (-1f >= _e428);
                    }
                    let _e432 = phi_2540_;
                    let _e433 = select(_e428, -1f, _e432);
                    let _e443 = (f32((bitcast<i32>((((_e420 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e443 != _e443) {
                        phi_2555_ = true;
                    } else {
                        phi_2555_ = (-1f >= _e443);
                    }
                    let _e447 = phi_2555_;
                    let _e448 = select(_e443, -1f, _e447);
                    let _e451 = (1f - abs(_e433));
                    let _e452 = abs(_e448);
                    let _e453 = (_e451 - _e452);
                    if (_e453 < 0f) {
                        phi_735_ = vec2<f32>(((1f - _e452) * select(1f, -1f, (_e433 < 0f))), (_e451 * select(1f, -1f, (_e448 < 0f))));
                    } else {
                        phi_735_ = vec2<f32>(_e433, _e448);
                    }
                    let _e464 = phi_735_;
                    let _e473 = (1f / sqrt((((_e464.x * _e464.x) + (_e464.y * _e464.y)) + (_e453 * _e453))));
                    let _e474 = (_e464.x * _e473);
                    let _e475 = (_e464.y * _e473);
                    let _e476 = (_e453 * _e473);
                    let _e477 = -(_e476);
                    if ((((_e474 * _e414) + (_e475 * _e415)) + (_e477 * _e416)) < 0f) {
                        phi_763_ = vec3<f32>(-(_e474), -(_e475), _e476);
                    } else {
                        phi_763_ = vec3<f32>(_e474, _e475, _e477);
                    }
                    let _e489 = phi_763_;
                    let _e493 = params.member.member_4.member_1;
                    let _e497 = params.member.member_4.member_2;
                    let _e502 = ((_e493 * _e497) / (((_e125 * 1.99998f) * _e391) / _e99));
                    let _e507 = params.member.member_4.member_11;
                    phi_784_ = (_e85.y & 63u);
                    phi_787_ = (_e85.x & 63u);
                    phi_789_ = 32u;
                    phi_791_ = 0u;
                    loop {
                        let _e511 = phi_784_;
                        let _e513 = phi_787_;
                        let _e515 = phi_789_;
                        let _e517 = phi_791_;
                        local_1 = _e517;
                        let _e518 = (_e515 > 0u);
                        if _e518 {
                            let _e521 = select(0u, 1u, ((_e513 & _e515) != 0u));
                            let _e524 = select(0u, 1u, ((_e511 & _e515) != 0u));
                            if (_e524 == 0u) {
                                if (_e521 == 1u) {
                                    phi_820_ = (63u - _e511);
                                    phi_821_ = (63u - _e513);
                                } else {
                                    phi_820_ = _e511;
                                    phi_821_ = _e513;
                                }
                                let _e535 = phi_820_;
                                let _e537 = phi_821_;
                                phi_822_ = _e537;
                                phi_823_ = _e535;
                            } else {
                                phi_822_ = _e511;
                                phi_823_ = _e513;
                            }
                            let _e539 = phi_822_;
                            let _e541 = phi_823_;
                            phi_785_ = _e539;
                            phi_788_ = _e541;
                            phi_790_ = (_e515 / 2u);
                            phi_792_ = (_e517 + ((_e515 * _e515) * ((3u * _e521) ^ _e524)));
                        } else {
                            phi_785_ = u32();
                            phi_788_ = u32();
                            phi_790_ = u32();
                            phi_792_ = u32();
                        }
                        let _e544 = phi_785_;
                        let _e546 = phi_788_;
                        let _e548 = phi_790_;
                        let _e550 = phi_792_;
                        continue;
                        continuing {
                            phi_784_ = _e544;
                            phi_787_ = _e546;
                            phi_789_ = _e548;
                            phi_791_ = _e550;
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
                        phi_2963_ = false;
                        phi_870_ = 0u;
                        phi_873_ = 0f;
                        phi_875_ = 0f;
                        loop {
                            let _e581 = phi_2963_;
                            let _e583 = phi_870_;
                            let _e585 = phi_873_;
                            let _e587 = phi_875_;
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
                                phi_1045_ = 0u;
                                phi_1048_ = 0u;
                                loop {
                                    let _e675 = phi_1045_;
                                    let _e677 = phi_1048_;
                                    local_16 = _e677;
                                    local_17 = _e677;
                                    local_19 = _e677;
                                    let _e678 = (_e675 < _e673);
                                    if _e678 {
                                        let _e683 = ((_e563 - floor(_e563)) + (f32((_e583 + (_e675 * _e673))) * 0.618034f));
                                        let _e689 = (((_e683 - floor(_e683)) + f32(_e675)) / f32(_e673));
                                        let _e693 = params.member.member_4.member_4;
                                        if (_e693 == 2f) {
                                            phi_1102_ = (_e689 * _e689);
                                        } else {
                                            phi_1102_ = pow(_e689, _e693);
                                        }
                                        let _e698 = phi_1102_;
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
                                                phi_1147_ = (_e720 - 1f);
                                            } else {
                                                phi_1147_ = f32();
                                            }
                                            let _e729 = phi_1147_;
                                            phi_1149_ = _e729;
                                            phi_1150_ = select(true, false, _e726);
                                        } else {
                                            phi_1149_ = f32();
                                            phi_1150_ = true;
                                        }
                                        let _e732 = phi_1149_;
                                        let _e734 = phi_1150_;
                                        let _e736 = (select(_e732, _e720, _e734) / _e99);
                                        let _e738 = floor((_e701 + 0.5f));
                                        if ((_e738 - _e701) == 0.5f) {
                                            let _e744 = ((floor((_e738 * 0.5f)) * 2f) != _e738);
                                            if _e744 {
                                                phi_1173_ = (_e738 - 1f);
                                            } else {
                                                phi_1173_ = f32();
                                            }
                                            let _e747 = phi_1173_;
                                            phi_1175_ = _e747;
                                            phi_1176_ = select(true, false, _e744);
                                        } else {
                                            phi_1175_ = f32();
                                            phi_1176_ = true;
                                        }
                                        let _e750 = phi_1175_;
                                        let _e752 = phi_1176_;
                                        let _e754 = (select(_e750, _e738, _e752) / _e110);
                                        let _e755 = (_e379 + _e736);
                                        let _e756 = (_e382 + _e754);
                                        let _e757 = (_e379 - _e736);
                                        let _e758 = (_e382 - _e754);
                                        let _e760 = select(1u, _e104, (1u < _e104));
                                        let _e762 = select(1u, _e115, (1u < _e115));
                                        let _e763 = f32(_e760);
                                        let _e764 = f32(_e762);
                                        phi_1209_ = 1u;
                                        phi_1212_ = _e764;
                                        phi_1214_ = _e763;
                                        phi_1216_ = 0u;
                                        phi_1218_ = _e762;
                                        phi_1220_ = _e760;
                                        loop {
                                            let _e766 = phi_1209_;
                                            let _e768 = phi_1212_;
                                            let _e770 = phi_1214_;
                                            let _e772 = phi_1216_;
                                            let _e774 = phi_1218_;
                                            let _e776 = phi_1220_;
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
                                                phi_1253_ = 0u;
                                                phi_1256_ = 0u;
                                                loop {
                                                    let _e792 = phi_1253_;
                                                    let _e794 = phi_1256_;
                                                    local_2 = _e794;
                                                    let _e795 = (_e792 < _e766);
                                                    if _e795 {
                                                        let _e796 = (_e792 & 31u);
                                                        let _e798 = (_e104 >> bitcast<u32>(_e796));
                                                        let _e802 = (_e115 >> bitcast<u32>(_e796));
                                                        phi_1254_ = (_e792 + 1u);
                                                        phi_1257_ = (_e794 + (select(1u, _e798, (1u < _e798)) * select(1u, _e802, (1u < _e802))));
                                                    } else {
                                                        phi_1254_ = u32();
                                                        phi_1257_ = u32();
                                                    }
                                                    let _e809 = phi_1254_;
                                                    let _e811 = phi_1257_;
                                                    continue;
                                                    continuing {
                                                        phi_1253_ = _e809;
                                                        phi_1256_ = _e811;
                                                        break if !(_e795);
                                                    }
                                                }
                                                let _e814 = local_2;
                                                phi_1210_ = (_e766 + 1u);
                                                phi_1213_ = select(_e768, f32(_e788), _e779);
                                                phi_1215_ = select(_e770, f32(_e784), _e779);
                                                phi_1217_ = select(_e772, _e814, _e779);
                                                phi_1219_ = select(_e774, _e788, _e779);
                                                phi_1221_ = select(_e776, _e784, _e779);
                                            } else {
                                                phi_1210_ = u32();
                                                phi_1213_ = f32();
                                                phi_1215_ = f32();
                                                phi_1217_ = u32();
                                                phi_1219_ = u32();
                                                phi_1221_ = u32();
                                            }
                                            let _e822 = phi_1210_;
                                            let _e824 = phi_1213_;
                                            let _e826 = phi_1215_;
                                            let _e828 = phi_1217_;
                                            let _e830 = phi_1219_;
                                            let _e832 = phi_1221_;
                                            continue;
                                            continuing {
                                                phi_1209_ = _e822;
                                                phi_1212_ = _e824;
                                                phi_1214_ = _e826;
                                                phi_1216_ = _e828;
                                                phi_1218_ = _e830;
                                                phi_1220_ = _e832;
                                                break if !(_e777);
                                            }
                                        }
                                        let _e835 = local_3;
                                        let _e836 = (_e755 * _e835);
                                        if (_e836 > 0f) {
                                            let _e842 = select(select(u32(_e836), 0u, (_e836 < 0f)), 4294967295u, (_e836 > 4294967000f));
                                            let _e844 = local_4;
                                            let _e845 = (_e844 - 1u);
                                            phi_1314_ = select(_e842, _e845, (_e845 < _e842));
                                        } else {
                                            phi_1314_ = 0u;
                                        }
                                        let _e849 = phi_1314_;
                                        let _e851 = local_5;
                                        let _e852 = (_e756 * _e851);
                                        if (_e852 > 0f) {
                                            let _e858 = select(select(u32(_e852), 0u, (_e852 < 0f)), 4294967295u, (_e852 > 4294967000f));
                                            let _e860 = local_6;
                                            let _e861 = (_e860 - 1u);
                                            phi_1333_ = select(_e858, _e861, (_e861 < _e858));
                                        } else {
                                            phi_1333_ = 0u;
                                        }
                                        let _e865 = phi_1333_;
                                        let _e867 = local_7;
                                        let _e870 = local_8;
                                        let _e872 = ((_e870 + (_e865 * _e867)) + _e849);
                                        if (_e872 < _e87) {
                                        } else {
                                            phi_2847_ = true;
                                            break;
                                        }
                                        let _e876 = mips.member[_e872];
                                        phi_1377_ = 1u;
                                        phi_1380_ = _e764;
                                        phi_1382_ = _e763;
                                        phi_1384_ = 0u;
                                        phi_1386_ = _e762;
                                        phi_1388_ = _e760;
                                        loop {
                                            let _e886 = phi_1377_;
                                            let _e888 = phi_1380_;
                                            let _e890 = phi_1382_;
                                            let _e892 = phi_1384_;
                                            let _e894 = phi_1386_;
                                            let _e896 = phi_1388_;
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
                                                phi_1421_ = 0u;
                                                phi_1424_ = 0u;
                                                loop {
                                                    let _e912 = phi_1421_;
                                                    let _e914 = phi_1424_;
                                                    local_9 = _e914;
                                                    let _e915 = (_e912 < _e886);
                                                    if _e915 {
                                                        let _e916 = (_e912 & 31u);
                                                        let _e918 = (_e104 >> bitcast<u32>(_e916));
                                                        let _e922 = (_e115 >> bitcast<u32>(_e916));
                                                        phi_1422_ = (_e912 + 1u);
                                                        phi_1425_ = (_e914 + (select(1u, _e918, (1u < _e918)) * select(1u, _e922, (1u < _e922))));
                                                    } else {
                                                        phi_1422_ = u32();
                                                        phi_1425_ = u32();
                                                    }
                                                    let _e929 = phi_1422_;
                                                    let _e931 = phi_1425_;
                                                    continue;
                                                    continuing {
                                                        phi_1421_ = _e929;
                                                        phi_1424_ = _e931;
                                                        break if !(_e915);
                                                    }
                                                }
                                                let _e934 = local_9;
                                                phi_1378_ = (_e886 + 1u);
                                                phi_1381_ = select(_e888, f32(_e908), _e899);
                                                phi_1383_ = select(_e890, f32(_e904), _e899);
                                                phi_1385_ = select(_e892, _e934, _e899);
                                                phi_1387_ = select(_e894, _e908, _e899);
                                                phi_1389_ = select(_e896, _e904, _e899);
                                            } else {
                                                phi_1378_ = u32();
                                                phi_1381_ = f32();
                                                phi_1383_ = f32();
                                                phi_1385_ = u32();
                                                phi_1387_ = u32();
                                                phi_1389_ = u32();
                                            }
                                            let _e942 = phi_1378_;
                                            let _e944 = phi_1381_;
                                            let _e946 = phi_1383_;
                                            let _e948 = phi_1385_;
                                            let _e950 = phi_1387_;
                                            let _e952 = phi_1389_;
                                            continue;
                                            continuing {
                                                phi_1377_ = _e942;
                                                phi_1380_ = _e944;
                                                phi_1382_ = _e946;
                                                phi_1384_ = _e948;
                                                phi_1386_ = _e950;
                                                phi_1388_ = _e952;
                                                break if !(_e897);
                                            }
                                        }
                                        let _e955 = local_10;
                                        let _e956 = (_e757 * _e955);
                                        if (_e956 > 0f) {
                                            let _e962 = select(select(u32(_e956), 0u, (_e956 < 0f)), 4294967295u, (_e956 > 4294967000f));
                                            let _e964 = local_11;
                                            let _e965 = (_e964 - 1u);
                                            phi_1482_ = select(_e962, _e965, (_e965 < _e962));
                                        } else {
                                            phi_1482_ = 0u;
                                        }
                                        let _e969 = phi_1482_;
                                        let _e971 = local_12;
                                        let _e972 = (_e758 * _e971);
                                        if (_e972 > 0f) {
                                            let _e978 = select(select(u32(_e972), 0u, (_e972 < 0f)), 4294967295u, (_e972 > 4294967000f));
                                            let _e980 = local_13;
                                            let _e981 = (_e980 - 1u);
                                            phi_1501_ = select(_e978, _e981, (_e981 < _e978));
                                        } else {
                                            phi_1501_ = 0u;
                                        }
                                        let _e985 = phi_1501_;
                                        let _e987 = local_14;
                                        let _e990 = local_15;
                                        let _e992 = ((_e990 + (_e985 * _e987)) + _e969);
                                        if (_e992 < _e87) {
                                        } else {
                                            phi_2847_ = true;
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
                                            phi_2576_ = true;
                                        } else {
                                            phi_2576_ = (0.19634955f <= _e1086);
                                        }
                                        let _e1090 = phi_2576_;
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
                                            phi_2591_ = true;
                                        } else {
                                            phi_2591_ = (_e1153 <= _e1125);
                                        }
                                        let _e1157 = phi_2591_;
                                        let _e1158 = select(_e1125, _e1153, _e1157);
                                        if _e1154 {
                                            phi_2606_ = true;
                                        } else {
                                            phi_2606_ = (_e1153 >= _e1125);
                                        }
                                        let _e1161 = phi_2606_;
                                        let _e1162 = select(_e1125, _e1153, _e1161);
                                        let _e1164 = floor((_e1158 * 32f));
                                        let _e1165 = (_e1013 == 1u);
                                        if _e1165 {
                                            let _e1172 = -(floor((_e1162 * -32f)));
                                            if (_e1172 != _e1172) {
                                                phi_2621_ = true;
                                            } else {
                                                phi_2621_ = (32f <= _e1172);
                                            }
                                            let _e1176 = phi_2621_;
                                            let _e1179 = (select(_e1172, 32f, _e1176) - _e1164);
                                            if (_e1179 != _e1179) {
                                                phi_2636_ = true;
                                            } else {
                                                phi_2636_ = (0f >= _e1179);
                                            }
                                            let _e1183 = phi_2636_;
                                            phi_1776_ = select(select(_e1179, 0f, _e1183), 0f, (_e1162 <= _e1158));
                                        } else {
                                            phi_1776_ = -(floor(((_e1162 - _e1158) * -32f)));
                                        }
                                        let _e1187 = phi_1776_;
                                        let _e1192 = select(select(u32(_e1164), 0u, (_e1164 < 0f)), 4294967295u, (_e1164 > 4294967000f));
                                        let _e1197 = select(select(u32(_e1187), 0u, (_e1187 < 0f)), 4294967295u, (_e1187 > 4294967000f));
                                        if (_e1192 >= 32u) {
                                            phi_2680_ = u32();
                                            phi_2681_ = true;
                                        } else {
                                            let _e1199 = (_e1197 == 0u);
                                            if _e1199 {
                                                phi_2678_ = u32();
                                            } else {
                                                if (_e1197 >= 32u) {
                                                    phi_2674_ = 4294967295u;
                                                } else {
                                                    phi_2674_ = ((1u << bitcast<u32>((_e1197 & 31u))) - 1u);
                                                }
                                                let _e1206 = phi_2674_;
                                                phi_2678_ = (_e1206 << bitcast<u32>((_e1192 & 31u)));
                                            }
                                            let _e1211 = phi_2678_;
                                            phi_2680_ = _e1211;
                                            phi_2681_ = _e1199;
                                        }
                                        let _e1213 = phi_2680_;
                                        let _e1215 = phi_2681_;
                                        let _e1218 = select(select(_e1213, 0u, _e1215), 0u, (sqrt((((_e1022 * _e1022) + (_e1023 * _e1023)) + (_e1024 * _e1024))) <= 0f));
                                        let _e1221 = params.member.member_1;
                                        let _e1222 = (_e1221 > 0f);
                                        if _e1222 {
                                            phi_1804_ = select(_e1218, 0u, (_e1103 > _e1221));
                                        } else {
                                            phi_1804_ = _e1218;
                                        }
                                        let _e1226 = phi_1804_;
                                        let _e1228 = (((((_e757 * 2f) - 1f) * _e391) * _e996) - _e393);
                                        let _e1229 = (((((_e758 * -2f) + 1f) * _e401) * _e996) - _e403);
                                        let _e1230 = (_e996 - _e383);
                                        let _e1235 = (((_e1228 * _e414) + (_e1229 * _e415)) + (_e1230 * _e416));
                                        let _e1239 = (_e1228 - (_e414 * _e1235));
                                        let _e1240 = (_e1229 - (_e415 * _e1235));
                                        let _e1241 = (_e1230 - (_e416 * _e1235));
                                        let _e1250 = ((_e1240 * _e416) - (_e415 * _e1241));
                                        let _e1253 = ((_e1241 * _e414) - (_e416 * _e1239));
                                        let _e1256 = ((_e1239 * _e415) - (_e414 * _e1240));
                                        let _e1263 = (1f / sqrt((((_e1250 * _e1250) + (_e1253 * _e1253)) + (_e1256 * _e1256))));
                                        let _e1264 = (_e1250 * _e1263);
                                        let _e1265 = (_e1253 * _e1263);
                                        let _e1266 = (_e1256 * _e1263);
                                        let _e1271 = (((_e489.x * _e1264) + (_e489.y * _e1265)) + (_e489.z * _e1266));
                                        let _e1275 = (_e489.x - (_e1264 * _e1271));
                                        let _e1276 = (_e489.y - (_e1265 * _e1271));
                                        let _e1277 = (_e489.z - (_e1266 * _e1271));
                                        let _e1283 = sqrt((((_e1275 * _e1275) + (_e1276 * _e1276)) + (_e1277 * _e1277)));
                                        let _e1289 = ((((_e1275 * _e414) + (_e1276 * _e415)) + (_e1277 * _e416)) / _e1283);
                                        let _e1294 = acos(select(0f, select(1f, _e1289, (_e1289 < 1f)), (_e1289 > 0f)));
                                        let _e1302 = select(_e1294, -(_e1294), ((((_e1239 * _e1275) + (_e1240 * _e1276)) + (_e1241 * _e1277)) < 0f));
                                        let _e1303 = (0.02f / _e1283);
                                        if (_e1303 != _e1303) {
                                            phi_2696_ = true;
                                        } else {
                                            phi_2696_ = (0.19634955f <= _e1303);
                                        }
                                        let _e1307 = phi_2696_;
                                        let _e1308 = select(_e1303, 0.19634955f, _e1307);
                                        let _e1309 = (_e1228 - _e1092);
                                        let _e1310 = (_e1229 - _e1093);
                                        let _e1311 = (_e1230 - _e1094);
                                        let _e1317 = sqrt((((_e1228 * _e1228) + (_e1229 * _e1229)) + (_e1230 * _e1230)));
                                        let _e1318 = (1f / _e1317);
                                        let _e1326 = ((((_e1228 * _e1318) * _e414) + ((_e1229 * _e1318) * _e415)) + ((_e1230 * _e1318) * _e416));
                                        let _e1335 = ((((acos(select(-1f, select(1f, _e1326, (_e1326 < 1f)), (_e1326 > -1f))) + _e1308) - _e1302) + 1.5707964f) * 0.31830987f);
                                        let _e1346 = (1f / sqrt((((_e1309 * _e1309) + (_e1310 * _e1310)) + (_e1311 * _e1311))));
                                        let _e1354 = ((((_e1309 * _e1346) * _e414) + ((_e1310 * _e1346) * _e415)) + ((_e1311 * _e1346) * _e416));
                                        let _e1363 = ((((acos(select(-1f, select(1f, _e1354, (_e1354 < 1f)), (_e1354 > -1f))) + _e1308) - _e1302) + 1.5707964f) * 0.31830987f);
                                        let _e1368 = (1f - select(0f, select(1f, _e1335, (_e1335 < 1f)), (_e1335 > 0f)));
                                        let _e1369 = (1f - select(0f, select(1f, _e1363, (_e1363 < 1f)), (_e1363 > 0f)));
                                        let _e1370 = (_e1368 != _e1368);
                                        if _e1370 {
                                            phi_2711_ = true;
                                        } else {
                                            phi_2711_ = (_e1369 <= _e1368);
                                        }
                                        let _e1373 = phi_2711_;
                                        let _e1374 = select(_e1368, _e1369, _e1373);
                                        if _e1370 {
                                            phi_2726_ = true;
                                        } else {
                                            phi_2726_ = (_e1369 >= _e1368);
                                        }
                                        let _e1377 = phi_2726_;
                                        let _e1378 = select(_e1368, _e1369, _e1377);
                                        let _e1380 = floor((_e1374 * 32f));
                                        if _e1165 {
                                            let _e1387 = -(floor((_e1378 * -32f)));
                                            if (_e1387 != _e1387) {
                                                phi_2741_ = true;
                                            } else {
                                                phi_2741_ = (32f <= _e1387);
                                            }
                                            let _e1391 = phi_2741_;
                                            let _e1394 = (select(_e1387, 32f, _e1391) - _e1380);
                                            if (_e1394 != _e1394) {
                                                phi_2756_ = true;
                                            } else {
                                                phi_2756_ = (0f >= _e1394);
                                            }
                                            let _e1398 = phi_2756_;
                                            phi_2054_ = select(select(_e1394, 0f, _e1398), 0f, (_e1378 <= _e1374));
                                        } else {
                                            phi_2054_ = -(floor(((_e1378 - _e1374) * -32f)));
                                        }
                                        let _e1402 = phi_2054_;
                                        let _e1407 = select(select(u32(_e1380), 0u, (_e1380 < 0f)), 4294967295u, (_e1380 > 4294967000f));
                                        let _e1412 = select(select(u32(_e1402), 0u, (_e1402 < 0f)), 4294967295u, (_e1402 > 4294967000f));
                                        if (_e1407 >= 32u) {
                                            phi_2800_ = u32();
                                            phi_2801_ = true;
                                        } else {
                                            let _e1414 = (_e1412 == 0u);
                                            if _e1414 {
                                                phi_2798_ = u32();
                                            } else {
                                                if (_e1412 >= 32u) {
                                                    phi_2794_ = 4294967295u;
                                                } else {
                                                    phi_2794_ = ((1u << bitcast<u32>((_e1412 & 31u))) - 1u);
                                                }
                                                let _e1421 = phi_2794_;
                                                phi_2798_ = (_e1421 << bitcast<u32>((_e1407 & 31u)));
                                            }
                                            let _e1426 = phi_2798_;
                                            phi_2800_ = _e1426;
                                            phi_2801_ = _e1414;
                                        }
                                        let _e1428 = phi_2800_;
                                        let _e1430 = phi_2801_;
                                        let _e1433 = select(select(_e1428, 0u, _e1430), 0u, (sqrt((((_e1239 * _e1239) + (_e1240 * _e1240)) + (_e1241 * _e1241))) <= 0f));
                                        if _e1222 {
                                            phi_2082_ = select(_e1433, 0u, (_e1317 > _e1221));
                                        } else {
                                            phi_2082_ = _e1433;
                                        }
                                        let _e1437 = phi_2082_;
                                        phi_1046_ = (_e675 + 1u);
                                        phi_1049_ = ((_e677 | _e1226) | _e1437);
                                    } else {
                                        phi_1046_ = u32();
                                        phi_1049_ = u32();
                                    }
                                    let _e1441 = phi_1046_;
                                    let _e1443 = phi_1049_;
                                    continue;
                                    continuing {
                                        phi_1045_ = _e1441;
                                        phi_1048_ = _e1443;
                                        phi_2847_ = _e581;
                                        break if !(_e678);
                                    }
                                }
                                let _e1446 = phi_2847_;
                                phi_3033_ = _e1446;
                                if _e1446 {
                                    break;
                                }
                                let _e1449 = params.member.member_2;
                                if (_e1449 == 2u) {
                                    let _e1506 = (_e667 - 1.5707964f);
                                    let _e1507 = (_e1506 * 2f);
                                    let _e1508 = sin(_e667);
                                    let _e1513 = ((_e665 + (_e1507 * _e1508)) - cos((_e1507 - _e667)));
                                    phi_2113_ = 0u;
                                    phi_2116_ = select((_e1513 * 0.25f), (_e1513 * -0.25f), (_e1506 < 0f));
                                    phi_2118_ = 0f;
                                    loop {
                                        let _e1519 = phi_2113_;
                                        let _e1521 = phi_2116_;
                                        let _e1523 = phi_2118_;
                                        local_20 = _e1523;
                                        let _e1524 = (_e1519 < 32u);
                                        if _e1524 {
                                            let _e1525 = (_e1519 + 1u);
                                            let _e1528 = (_e1506 + (f32(_e1525) * 0.09817477f));
                                            let _e1529 = (_e1528 * 2f);
                                            let _e1534 = ((_e665 + (_e1529 * _e1508)) - cos((_e1529 - _e667)));
                                            let _e1538 = select((_e1534 * 0.25f), (_e1534 * -0.25f), (_e1528 < 0f));
                                            let _e1541 = local_19;
                                            phi_2114_ = _e1525;
                                            phi_2117_ = _e1538;
                                            phi_2119_ = select(_e1523, (_e1523 + (_e1538 - _e1521)), (((_e1541 >> bitcast<u32>((_e1519 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2114_ = u32();
                                            phi_2117_ = f32();
                                            phi_2119_ = f32();
                                        }
                                        let _e1550 = phi_2114_;
                                        let _e1552 = phi_2117_;
                                        let _e1554 = phi_2119_;
                                        continue;
                                        continuing {
                                            phi_2113_ = _e1550;
                                            phi_2116_ = _e1552;
                                            phi_2118_ = _e1554;
                                            break if !(_e1524);
                                        }
                                    }
                                    let _e1557 = local_20;
                                    phi_3035_ = _e1446;
                                    phi_2221_ = (_e585 + 1f);
                                    phi_2222_ = (_e587 + ((_e646 + ((1f - _e646) * 0.05f)) * _e1557));
                                } else {
                                    if (_e1449 == 1u) {
                                        phi_2166_ = 0u;
                                        phi_2169_ = 0f;
                                        loop {
                                            let _e1462 = phi_2166_;
                                            let _e1464 = phi_2169_;
                                            local_18 = _e1464;
                                            let _e1465 = (_e1462 < 4u);
                                            if _e1465 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1465 {
                                                } else {
                                                    phi_3030_ = true;
                                                    break;
                                                }
                                                let _e1468 = local[_e1462].member;
                                                let _e1471 = local[_e1462].member_1;
                                                let _e1473 = local_17;
                                                phi_2167_ = (_e1462 + 1u);
                                                phi_2170_ = (_e1464 + (f32(countOneBits((_e1473 & _e1468))) * _e1471));
                                            } else {
                                                phi_2167_ = u32();
                                                phi_2170_ = f32();
                                            }
                                            let _e1481 = phi_2167_;
                                            let _e1483 = phi_2170_;
                                            continue;
                                            continuing {
                                                phi_2166_ = _e1481;
                                                phi_2169_ = _e1483;
                                                phi_3030_ = _e1446;
                                                break if !(_e1465);
                                            }
                                        }
                                        let _e1486 = phi_3030_;
                                        phi_3033_ = _e1486;
                                        if _e1486 {
                                            break;
                                        }
                                        let _e1488 = local_18;
                                        let _e1489 = (1f - _e1488);
                                        phi_3041_ = _e1486;
                                        phi_2219_ = (_e585 + _e646);
                                        phi_2220_ = (_e587 + (_e646 * select(0f, select(1f, _e1489, (_e1489 < 1f)), (_e1489 > 0f))));
                                    } else {
                                        let _e1453 = local_16;
                                        phi_3041_ = _e1446;
                                        phi_2219_ = (_e585 + 1f);
                                        phi_2220_ = (_e587 + ((f32(countOneBits((_e1453 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1498 = phi_3041_;
                                    let _e1500 = phi_2219_;
                                    let _e1502 = phi_2220_;
                                    phi_3035_ = _e1498;
                                    phi_2221_ = _e1500;
                                    phi_2222_ = _e1502;
                                }
                                let _e1562 = phi_3035_;
                                let _e1564 = phi_2221_;
                                let _e1566 = phi_2222_;
                                phi_3034_ = _e1562;
                                phi_871_ = (_e583 + 1u);
                                phi_874_ = _e1564;
                                phi_876_ = _e1566;
                            } else {
                                phi_3034_ = _e581;
                                phi_871_ = u32();
                                phi_874_ = f32();
                                phi_876_ = f32();
                            }
                            let _e1569 = phi_3034_;
                            let _e1571 = phi_871_;
                            let _e1573 = phi_874_;
                            let _e1575 = phi_876_;
                            continue;
                            continuing {
                                phi_2963_ = _e1569;
                                phi_870_ = _e1571;
                                phi_873_ = _e1573;
                                phi_875_ = _e1575;
                                phi_3033_ = _e1569;
                                break if !(_e588);
                            }
                        }
                        let _e1578 = phi_3033_;
                        if _e1578 {
                            break;
                        }
                        let _e1580 = local_21;
                        let _e1583 = local_22;
                        let _e1585 = local_23;
                        phi_2230_ = select(1f, (_e1583 / _e1585), (_e1580 > 0f));
                    } else {
                        phi_2230_ = 1f;
                    }
                    let _e1589 = phi_2230_;
                    if _e573 {
                        let _e1593 = params.member.member_4.member_6;
                        let _e1594 = pow(_e1589, _e1593);
                        if (_e1594 != _e1594) {
                            phi_2834_ = true;
                        } else {
                            phi_2834_ = (0.03f >= _e1594);
                        }
                        let _e1598 = phi_2834_;
                        let _e1600 = (select(_e1594, 0.03f, _e1598) * 0.6666667f);
                        let _e1606 = ((select(0f, select(1f, _e1600, (_e1600 < 1f)), (_e1600 > 0f)) * 255f) + 0.5f);
                        phi_2279_ = select(select(u32(_e1606), 0u, (_e1606 < 0f)), 4294967295u, (_e1606 > 4294967000f));
                    } else {
                        phi_2279_ = 170u;
                    }
                    let _e1613 = phi_2279_;
                    if (_e121 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e121] = _e1613;
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
