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

struct type_28 {
    member: u32,
    member_1: u32,
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
    var phi_443_: i32;
    var phi_462_: i32;
    var phi_502_: i32;
    var phi_521_: i32;
    var phi_561_: i32;
    var phi_580_: i32;
    var phi_620_: i32;
    var phi_639_: i32;
    var phi_2289_: f32;
    var phi_2293_: f32;
    var phi_2294_: bool;
    var phi_2332_: f32;
    var phi_2336_: f32;
    var phi_2337_: bool;
    var phi_2375_: f32;
    var phi_2379_: f32;
    var phi_2380_: bool;
    var phi_2418_: f32;
    var phi_2422_: f32;
    var phi_2423_: bool;
    var phi_2445_: bool;
    var phi_2460_: bool;
    var phi_856_: vec2<f32>;
    var phi_884_: vec3<f32>;
    var phi_905_: u32;
    var phi_908_: u32;
    var phi_910_: u32;
    var phi_912_: u32;
    var phi_941_: u32;
    var phi_942_: u32;
    var phi_943_: u32;
    var phi_944_: u32;
    var phi_906_: u32;
    var phi_909_: u32;
    var phi_911_: u32;
    var phi_913_: u32;
    var local_1: u32;
    var phi_967_: bool;
    var phi_2897_: bool;
    var phi_990_: u32;
    var phi_993_: f32;
    var phi_995_: f32;
    var phi_1165_: u32;
    var phi_1168_: u32;
    var phi_1222_: f32;
    var phi_1267_: f32;
    var phi_1269_: f32;
    var phi_1270_: bool;
    var phi_1293_: f32;
    var phi_1295_: f32;
    var phi_1296_: bool;
    var phi_2492_: u32;
    var phi_2540_: u32;
    var phi_2560_: u32;
    var phi_2562_: u32;
    var phi_2563_: u32;
    var phi_2586_: u32;
    var phi_2587_: u32;
    var local_2: u32;
    var phi_2614_: u32;
    var phi_2662_: u32;
    var phi_2682_: u32;
    var phi_2684_: u32;
    var phi_2685_: u32;
    var phi_2708_: u32;
    var phi_2709_: u32;
    var local_3: u32;
    var phi_1404_: bool;
    var phi_1520_: f32;
    var phi_2725_: bool;
    var phi_2740_: bool;
    var phi_2755_: bool;
    var phi_1665_: u32;
    var phi_1666_: u32;
    var phi_1678_: u32;
    var phi_1679_: bool;
    var phi_1698_: u32;
    var phi_1701_: u32;
    var phi_1702_: u32;
    var phi_1703_: bool;
    var phi_1708_: u32;
    var phi_1709_: u32;
    var phi_1710_: u32;
    var phi_1738_: bool;
    var phi_1854_: f32;
    var phi_2770_: bool;
    var phi_2785_: bool;
    var phi_2800_: bool;
    var phi_1999_: u32;
    var phi_2000_: u32;
    var phi_2012_: u32;
    var phi_2013_: bool;
    var phi_2032_: u32;
    var phi_2035_: u32;
    var phi_2036_: u32;
    var phi_2037_: bool;
    var phi_2042_: u32;
    var phi_2043_: u32;
    var phi_2044_: u32;
    var phi_1166_: u32;
    var phi_1169_: u32;
    var phi_2845_: bool;
    var local_4: u32;
    var phi_2128_: u32;
    var phi_2131_: f32;
    var local_5: u32;
    var phi_2129_: u32;
    var phi_2132_: f32;
    var phi_3014_: bool;
    var local_6: f32;
    var phi_3025_: bool;
    var phi_2178_: f32;
    var phi_2179_: f32;
    var phi_2073_: f32;
    var phi_2075_: u32;
    var phi_2078_: f32;
    var phi_2080_: f32;
    var phi_2106_: f32;
    var local_7: u32;
    var phi_2116_: f32;
    var phi_2076_: u32;
    var phi_2079_: f32;
    var phi_2081_: f32;
    var local_8: f32;
    var phi_3019_: bool;
    var phi_2180_: f32;
    var phi_2181_: f32;
    var phi_3018_: bool;
    var phi_991_: u32;
    var phi_994_: f32;
    var phi_996_: f32;
    var phi_3017_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var phi_2188_: f32;
    var phi_2815_: bool;
    var phi_2236_: type_28;

    switch bitcast<i32>(0u) {
        default: {
            let _e83 = id_1;
            let _e85 = arrayLength((&mips.member));
            let _e97 = params.member.member_4.member.member[0u];
            let _e102 = select(select(u32(_e97), 0u, (_e97 < 0f)), 4294967295u, (_e97 > 4294967000f));
            let _e108 = params.member.member_4.member.member[1u];
            let _e113 = select(select(u32(_e108), 0u, (_e108 < 0f)), 4294967295u, (_e108 > 4294967000f));
            if (_e83.x >= _e102) {
            } else {
                if (_e83.y >= _e113) {
                } else {
                    let _e119 = ((_e83.y * _e102) + _e83.x);
                    if (_e119 < _e85) {
                    } else {
                        break;
                    }
                    let _e123 = mips.member[_e119];
                    let _e124 = bitcast<i32>(_e83.x);
                    let _e125 = (_e124 + -1i);
                    let _e127 = (bitcast<i32>(_e102) - 1i);
                    let _e128 = (0i <= _e127);
                    if _e128 {
                    } else {
                        break;
                    }
                    if (_e125 < 0i) {
                        phi_443_ = 0i;
                    } else {
                        phi_443_ = select(_e125, _e127, (_e125 > _e127));
                    }
                    let _e133 = phi_443_;
                    let _e135 = bitcast<i32>(_e83.y);
                    let _e137 = (bitcast<i32>(_e113) - 1i);
                    let _e138 = (0i <= _e137);
                    if _e138 {
                    } else {
                        break;
                    }
                    let _e139 = (_e135 < 0i);
                    if _e139 {
                        phi_462_ = 0i;
                    } else {
                        phi_462_ = select(_e135, _e137, (_e135 > _e137));
                    }
                    let _e143 = phi_462_;
                    let _e146 = ((bitcast<u32>(_e143) * _e102) + bitcast<u32>(_e133));
                    if (_e146 < _e85) {
                    } else {
                        break;
                    }
                    let _e150 = mips.member[_e146];
                    let _e151 = (_e124 + 1i);
                    if _e128 {
                    } else {
                        break;
                    }
                    if (_e151 < 0i) {
                        phi_502_ = 0i;
                    } else {
                        phi_502_ = select(_e151, _e127, (_e151 > _e127));
                    }
                    let _e156 = phi_502_;
                    if _e138 {
                    } else {
                        break;
                    }
                    if _e139 {
                        phi_521_ = 0i;
                    } else {
                        phi_521_ = select(_e135, _e137, (_e135 > _e137));
                    }
                    let _e161 = phi_521_;
                    let _e164 = ((bitcast<u32>(_e161) * _e102) + bitcast<u32>(_e156));
                    if (_e164 < _e85) {
                    } else {
                        break;
                    }
                    let _e168 = mips.member[_e164];
                    if _e128 {
                    } else {
                        break;
                    }
                    let _e169 = (_e124 < 0i);
                    if _e169 {
                        phi_561_ = 0i;
                    } else {
                        phi_561_ = select(_e124, _e127, (_e124 > _e127));
                    }
                    let _e173 = phi_561_;
                    let _e175 = (_e135 + -1i);
                    if _e138 {
                    } else {
                        break;
                    }
                    if (_e175 < 0i) {
                        phi_580_ = 0i;
                    } else {
                        phi_580_ = select(_e175, _e137, (_e175 > _e137));
                    }
                    let _e180 = phi_580_;
                    let _e183 = ((bitcast<u32>(_e180) * _e102) + bitcast<u32>(_e173));
                    if (_e183 < _e85) {
                    } else {
                        break;
                    }
                    let _e187 = mips.member[_e183];
                    if _e128 {
                    } else {
                        break;
                    }
                    if _e169 {
                        phi_620_ = 0i;
                    } else {
                        phi_620_ = select(_e124, _e127, (_e124 > _e127));
                    }
                    let _e191 = phi_620_;
                    let _e193 = (_e135 + 1i);
                    if _e138 {
                    } else {
                        break;
                    }
                    if (_e193 < 0i) {
                        phi_639_ = 0i;
                    } else {
                        phi_639_ = select(_e193, _e137, (_e193 > _e137));
                    }
                    let _e198 = phi_639_;
                    let _e201 = ((bitcast<u32>(_e198) * _e102) + bitcast<u32>(_e191));
                    if (_e201 < _e85) {
                    } else {
                        break;
                    }
                    let _e205 = mips.member[_e201];
                    let _e206 = (_e150 - _e123);
                    let _e207 = (_e168 - _e123);
                    let _e208 = (_e187 - _e123);
                    let _e209 = (_e205 - _e123);
                    let _e210 = (_e207 - _e206);
                    let _e212 = (_e209 - _e208);
                    let _e220 = abs(_e206);
                    let _e221 = abs(_e207);
                    let _e222 = abs(_e208);
                    let _e223 = abs(_e209);
                    let _e224 = abs((_e206 + (_e210 * 0.5f)));
                    let _e225 = abs((_e207 + (_e210 * -0.5f)));
                    let _e226 = abs((_e208 + (_e212 * 0.5f)));
                    let _e227 = abs((_e209 + (_e212 * -0.5f)));
                    let _e236 = (_e123 * 0.011f);
                    let _e241 = (1.25f - (select(_e224, _e220, (_e220 < _e224)) / _e236));
                    let _e245 = select(0f, select(1f, _e241, (_e241 < 1f)), (_e241 > 0f));
                    let _e246 = (1.25f - (select(_e225, _e221, (_e221 < _e225)) / _e236));
                    let _e250 = select(0f, select(1f, _e246, (_e246 < 1f)), (_e246 > 0f));
                    let _e251 = (1.25f - (select(_e226, _e222, (_e222 < _e226)) / _e236));
                    let _e255 = select(0f, select(1f, _e251, (_e251 < 1f)), (_e251 > 0f));
                    let _e256 = (1.25f - (select(_e227, _e223, (_e223 < _e227)) / _e236));
                    let _e260 = select(0f, select(1f, _e256, (_e256 < 1f)), (_e256 > 0f));
                    let _e265 = (select(0f, select(1f, _e245, (_e245 < 1f)), (_e245 > 0f)) * 2.9f);
                    let _e267 = floor((_e265 + 0.5f));
                    if ((_e267 - _e265) == 0.5f) {
                        let _e273 = ((floor((_e267 * 0.5f)) * 2f) != _e267);
                        if _e273 {
                            phi_2289_ = (_e267 - 1f);
                        } else {
                            phi_2289_ = f32();
                        }
                        let _e276 = phi_2289_;
                        phi_2293_ = _e276;
                        phi_2294_ = select(true, false, _e273);
                    } else {
                        phi_2293_ = f32();
                        phi_2294_ = true;
                    }
                    let _e279 = phi_2293_;
                    let _e281 = phi_2294_;
                    let _e282 = select(_e279, _e267, _e281);
                    let _e293 = (select(0f, select(1f, _e250, (_e250 < 1f)), (_e250 > 0f)) * 2.9f);
                    let _e295 = floor((_e293 + 0.5f));
                    if ((_e295 - _e293) == 0.5f) {
                        let _e301 = ((floor((_e295 * 0.5f)) * 2f) != _e295);
                        if _e301 {
                            phi_2332_ = (_e295 - 1f);
                        } else {
                            phi_2332_ = f32();
                        }
                        let _e304 = phi_2332_;
                        phi_2336_ = _e304;
                        phi_2337_ = select(true, false, _e301);
                    } else {
                        phi_2336_ = f32();
                        phi_2337_ = true;
                    }
                    let _e307 = phi_2336_;
                    let _e309 = phi_2337_;
                    let _e310 = select(_e307, _e295, _e309);
                    let _e322 = (select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f)) * 2.9f);
                    let _e324 = floor((_e322 + 0.5f));
                    if ((_e324 - _e322) == 0.5f) {
                        let _e330 = ((floor((_e324 * 0.5f)) * 2f) != _e324);
                        if _e330 {
                            phi_2375_ = (_e324 - 1f);
                        } else {
                            phi_2375_ = f32();
                        }
                        let _e333 = phi_2375_;
                        phi_2379_ = _e333;
                        phi_2380_ = select(true, false, _e330);
                    } else {
                        phi_2379_ = f32();
                        phi_2380_ = true;
                    }
                    let _e336 = phi_2379_;
                    let _e338 = phi_2380_;
                    let _e339 = select(_e336, _e324, _e338);
                    let _e351 = (select(0f, select(1f, _e260, (_e260 < 1f)), (_e260 > 0f)) * 2.9f);
                    let _e353 = floor((_e351 + 0.5f));
                    if ((_e353 - _e351) == 0.5f) {
                        let _e359 = ((floor((_e353 * 0.5f)) * 2f) != _e353);
                        if _e359 {
                            phi_2418_ = (_e353 - 1f);
                        } else {
                            phi_2418_ = f32();
                        }
                        let _e362 = phi_2418_;
                        phi_2422_ = _e362;
                        phi_2423_ = select(true, false, _e359);
                    } else {
                        phi_2422_ = f32();
                        phi_2423_ = true;
                    }
                    let _e365 = phi_2422_;
                    let _e367 = phi_2423_;
                    let _e368 = select(_e365, _e353, _e367);
                    let _e374 = ((((64u * select(select(u32(_e282), 0u, (_e282 < 0f)), 4294967295u, (_e282 > 4294967000f))) + (16u * select(select(u32(_e310), 0u, (_e310 < 0f)), 4294967295u, (_e310 > 4294967000f)))) + (4u * select(select(u32(_e339), 0u, (_e339 < 0f)), 4294967295u, (_e339 > 4294967000f)))) + select(select(u32(_e368), 0u, (_e368 < 0f)), 4294967295u, (_e368 > 4294967000f)));
                    let _e379 = ((f32(_e83.x) + 0.5f) / _e97);
                    let _e380 = ((f32(_e83.y) + 0.5f) / _e108);
                    let _e381 = (_e123 * 0.99999f);
                    let _e389 = params.member.member_4.member.member_1[0u];
                    let _e391 = ((((_e379 * 2f) - 1f) * _e389) * _e381);
                    let _e399 = params.member.member_4.member.member_1[1u];
                    let _e401 = ((((_e380 * -2f) + 1f) * _e399) * _e381);
                    let _e402 = -(_e391);
                    let _e403 = -(_e401);
                    let _e404 = (_e123 * -0.99999f);
                    let _e411 = (1f / sqrt((((_e402 * _e402) + (_e403 * _e403)) + (_e404 * _e404))));
                    let _e412 = (_e402 * _e411);
                    let _e413 = (_e403 * _e411);
                    let _e414 = (_e404 * _e411);
                    if (_e119 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e418 = normals.member[_e119];
                    let _e426 = (f32((bitcast<i32>(((_e418 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e426 != _e426) {
                        phi_2445_ = true;
                    } else {
                        phi_2445_ = (-1f >= _e426);
                    }
                    let _e430 = phi_2445_;
                    let _e431 = select(_e426, -1f, _e430);
                    let _e441 = (f32((bitcast<i32>((((_e418 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e441 != _e441) {
                        phi_2460_ = true;
                    } else {
                        phi_2460_ = (-1f >= _e441);
                    }
                    let _e445 = phi_2460_;
                    let _e446 = select(_e441, -1f, _e445);
                    let _e449 = (1f - abs(_e431));
                    let _e450 = abs(_e446);
                    let _e451 = (_e449 - _e450);
                    if (_e451 < 0f) {
                        phi_856_ = vec2<f32>(((1f - _e450) * select(1f, -1f, (_e431 < 0f))), (_e449 * select(1f, -1f, (_e446 < 0f))));
                    } else {
                        phi_856_ = vec2<f32>(_e431, _e446);
                    }
                    let _e462 = phi_856_;
                    let _e471 = (1f / sqrt((((_e462.x * _e462.x) + (_e462.y * _e462.y)) + (_e451 * _e451))));
                    let _e472 = (_e462.x * _e471);
                    let _e473 = (_e462.y * _e471);
                    let _e474 = (_e451 * _e471);
                    let _e475 = -(_e474);
                    if ((((_e472 * _e412) + (_e473 * _e413)) + (_e475 * _e414)) < 0f) {
                        phi_884_ = vec3<f32>(-(_e472), -(_e473), _e474);
                    } else {
                        phi_884_ = vec3<f32>(_e472, _e473, _e475);
                    }
                    let _e487 = phi_884_;
                    let _e491 = params.member.member_4.member_1;
                    let _e495 = params.member.member_4.member_2;
                    let _e500 = ((_e491 * _e495) / (((_e123 * 1.99998f) * _e389) / _e97));
                    let _e505 = params.member.member_4.member_11;
                    phi_905_ = (_e83.y & 63u);
                    phi_908_ = (_e83.x & 63u);
                    phi_910_ = 32u;
                    phi_912_ = 0u;
                    loop {
                        let _e509 = phi_905_;
                        let _e511 = phi_908_;
                        let _e513 = phi_910_;
                        let _e515 = phi_912_;
                        local_1 = _e515;
                        let _e516 = (_e513 > 0u);
                        if _e516 {
                            let _e519 = select(0u, 1u, ((_e511 & _e513) != 0u));
                            let _e522 = select(0u, 1u, ((_e509 & _e513) != 0u));
                            if (_e522 == 0u) {
                                if (_e519 == 1u) {
                                    phi_941_ = (63u - _e509);
                                    phi_942_ = (63u - _e511);
                                } else {
                                    phi_941_ = _e509;
                                    phi_942_ = _e511;
                                }
                                let _e533 = phi_941_;
                                let _e535 = phi_942_;
                                phi_943_ = _e535;
                                phi_944_ = _e533;
                            } else {
                                phi_943_ = _e509;
                                phi_944_ = _e511;
                            }
                            let _e537 = phi_943_;
                            let _e539 = phi_944_;
                            phi_906_ = _e537;
                            phi_909_ = _e539;
                            phi_911_ = (_e513 / 2u);
                            phi_913_ = (_e515 + ((_e513 * _e513) * ((3u * _e519) ^ _e522)));
                        } else {
                            phi_906_ = u32();
                            phi_909_ = u32();
                            phi_911_ = u32();
                            phi_913_ = u32();
                        }
                        let _e542 = phi_906_;
                        let _e544 = phi_909_;
                        let _e546 = phi_911_;
                        let _e548 = phi_913_;
                        continue;
                        continuing {
                            phi_905_ = _e542;
                            phi_908_ = _e544;
                            phi_910_ = _e546;
                            phi_912_ = _e548;
                            break if !(_e516);
                        }
                    }
                    let _e553 = local_1;
                    let _e555 = f32((_e553 + (288u * (_e505 % 64u))));
                    let _e557 = (0.5f + (_e555 * 0.7548777f));
                    let _e561 = (0.5f + (_e555 * 0.5698403f));
                    let _e568 = params.member.member_4.member.member_3;
                    if (_e123 > 0f) {
                        phi_967_ = (_e123 < _e568);
                    } else {
                        phi_967_ = false;
                    }
                    let _e572 = phi_967_;
                    if _e572 {
                        let _e577 = params.member.member_4.member_8;
                        let _e579 = select(1u, _e577, (1u < _e577));
                        phi_2897_ = false;
                        phi_990_ = 0u;
                        phi_993_ = 0f;
                        phi_995_ = 0f;
                        loop {
                            let _e581 = phi_2897_;
                            let _e583 = phi_990_;
                            let _e585 = phi_993_;
                            let _e587 = phi_995_;
                            local_9 = _e585;
                            local_10 = _e587;
                            local_11 = _e585;
                            let _e588 = (_e583 < _e579);
                            if _e588 {
                                let _e593 = ((((_e557 - floor(_e557)) + f32(_e583)) * 3.1415927f) / f32(_e579));
                                let _e594 = sin(_e593);
                                let _e595 = cos(_e593);
                                let _e601 = ((_e595 * _e412) + (_e594 * _e413));
                                let _e605 = (_e595 - (_e412 * _e601));
                                let _e606 = (_e594 - (_e413 * _e601));
                                let _e607 = -((_e414 * _e601));
                                let _e610 = ((_e606 * _e414) - (_e413 * _e607));
                                let _e613 = ((_e607 * _e412) - (_e414 * _e605));
                                let _e616 = ((_e605 * _e413) - (_e412 * _e606));
                                let _e623 = (1f / sqrt((((_e610 * _e610) + (_e613 * _e613)) + (_e616 * _e616))));
                                let _e624 = (_e610 * _e623);
                                let _e625 = (_e613 * _e623);
                                let _e626 = (_e616 * _e623);
                                let _e634 = (((_e487.x * _e624) + (_e487.y * _e625)) + (_e487.z * _e626));
                                let _e638 = (_e487.x - (_e624 * _e634));
                                let _e639 = (_e487.y - (_e625 * _e634));
                                let _e640 = (_e487.z - (_e626 * _e634));
                                let _e646 = sqrt((((_e638 * _e638) + (_e639 * _e639)) + (_e640 * _e640)));
                                let _e651 = (((_e605 * _e638) + (_e606 * _e639)) + (_e607 * _e640));
                                let _e661 = ((((_e638 * _e412) + (_e639 * _e413)) + (_e640 * _e414)) / _e646);
                                let _e665 = select(0f, select(1f, _e661, (_e661 < 1f)), (_e661 > 0f));
                                let _e667 = (select(select(0f, -1f, (_e651 < 0f)), 1f, (_e651 > 0f)) * acos(_e665));
                                let _e671 = params.member.member_4.member_9;
                                let _e673 = select(1u, _e671, (1u < _e671));
                                phi_1165_ = 0u;
                                phi_1168_ = 0u;
                                loop {
                                    let _e675 = phi_1165_;
                                    let _e677 = phi_1168_;
                                    local_4 = _e677;
                                    local_5 = _e677;
                                    local_7 = _e677;
                                    let _e678 = (_e675 < _e673);
                                    if _e678 {
                                        let _e683 = ((_e561 - floor(_e561)) + (f32((_e583 + (_e675 * _e673))) * 0.618034f));
                                        let _e689 = (((_e683 - floor(_e683)) + f32(_e675)) / f32(_e673));
                                        let _e693 = params.member.member_4.member_4;
                                        if (_e693 == 2f) {
                                            phi_1222_ = (_e689 * _e689);
                                        } else {
                                            phi_1222_ = pow(_e689, _e693);
                                        }
                                        let _e698 = phi_1222_;
                                        let _e699 = (_e698 + (1.3f / _e500));
                                        let _e700 = ((_e595 * _e500) * _e699);
                                        let _e701 = ((-(_e594) * _e500) * _e699);
                                        let _e710 = params.member.member_4.member_7;
                                        let _e711 = (log2(sqrt(((_e700 * _e700) + (_e701 * _e701)))) - _e710);
                                        let _e718 = (-1f - floor((-0.5f - select(0f, select(5f, _e711, (_e711 < 5f)), (_e711 > 0f)))));
                                        let _e720 = floor((_e700 + 0.5f));
                                        if ((_e720 - _e700) == 0.5f) {
                                            let _e726 = ((floor((_e720 * 0.5f)) * 2f) != _e720);
                                            if _e726 {
                                                phi_1267_ = (_e720 - 1f);
                                            } else {
                                                phi_1267_ = f32();
                                            }
                                            let _e729 = phi_1267_;
                                            phi_1269_ = _e729;
                                            phi_1270_ = select(true, false, _e726);
                                        } else {
                                            phi_1269_ = f32();
                                            phi_1270_ = true;
                                        }
                                        let _e732 = phi_1269_;
                                        let _e734 = phi_1270_;
                                        let _e736 = (select(_e732, _e720, _e734) / _e97);
                                        let _e738 = floor((_e701 + 0.5f));
                                        if ((_e738 - _e701) == 0.5f) {
                                            let _e744 = ((floor((_e738 * 0.5f)) * 2f) != _e738);
                                            if _e744 {
                                                phi_1293_ = (_e738 - 1f);
                                            } else {
                                                phi_1293_ = f32();
                                            }
                                            let _e747 = phi_1293_;
                                            phi_1295_ = _e747;
                                            phi_1296_ = select(true, false, _e744);
                                        } else {
                                            phi_1295_ = f32();
                                            phi_1296_ = true;
                                        }
                                        let _e750 = phi_1295_;
                                        let _e752 = phi_1296_;
                                        let _e754 = (select(_e750, _e738, _e752) / _e108);
                                        let _e755 = (_e379 + _e736);
                                        let _e756 = (_e380 + _e754);
                                        let _e757 = (_e379 - _e736);
                                        let _e758 = (_e380 - _e754);
                                        let _e759 = (_e718 > 0f);
                                        if _e759 {
                                            let _e764 = select(select(u32(_e718), 0u, (_e718 < 0f)), 4294967295u, (_e718 > 4294967000f));
                                            phi_2492_ = select(_e764, 4u, (4u < _e764));
                                        } else {
                                            phi_2492_ = 0u;
                                        }
                                        let _e768 = phi_2492_;
                                        let _e769 = (_e768 & 31u);
                                        let _e771 = (_e102 >> bitcast<u32>(_e769));
                                        let _e773 = select(1u, _e771, (1u < _e771));
                                        let _e775 = (_e113 >> bitcast<u32>(_e769));
                                        let _e777 = select(1u, _e775, (1u < _e775));
                                        let _e779 = (_e755 * f32(_e773));
                                        if (_e779 > 0f) {
                                            let _e785 = select(select(u32(_e779), 0u, (_e779 < 0f)), 4294967295u, (_e779 > 4294967000f));
                                            let _e786 = (_e773 - 1u);
                                            phi_2540_ = select(_e785, _e786, (_e786 < _e785));
                                        } else {
                                            phi_2540_ = 0u;
                                        }
                                        let _e790 = phi_2540_;
                                        let _e792 = (_e756 * f32(_e777));
                                        if (_e792 > 0f) {
                                            let _e798 = select(select(u32(_e792), 0u, (_e792 < 0f)), 4294967295u, (_e792 > 4294967000f));
                                            let _e799 = (_e777 - 1u);
                                            phi_2560_ = select(_e798, _e799, (_e799 < _e798));
                                        } else {
                                            phi_2560_ = 0u;
                                        }
                                        let _e803 = phi_2560_;
                                        phi_2562_ = 0u;
                                        phi_2563_ = 0u;
                                        loop {
                                            let _e805 = phi_2562_;
                                            let _e807 = phi_2563_;
                                            local_2 = _e807;
                                            let _e808 = (_e805 < _e768);
                                            if _e808 {
                                                let _e809 = (_e805 & 31u);
                                                let _e811 = (_e102 >> bitcast<u32>(_e809));
                                                let _e815 = (_e113 >> bitcast<u32>(_e809));
                                                phi_2586_ = (_e805 + 1u);
                                                phi_2587_ = (_e807 + (select(1u, _e811, (1u < _e811)) * select(1u, _e815, (1u < _e815))));
                                            } else {
                                                phi_2586_ = u32();
                                                phi_2587_ = u32();
                                            }
                                            let _e822 = phi_2586_;
                                            let _e824 = phi_2587_;
                                            continue;
                                            continuing {
                                                phi_2562_ = _e822;
                                                phi_2563_ = _e824;
                                                break if !(_e808);
                                            }
                                        }
                                        let _e829 = local_2;
                                        let _e830 = (_e829 + ((_e803 * _e773) + _e790));
                                        if (_e830 < _e85) {
                                        } else {
                                            phi_2845_ = true;
                                            break;
                                        }
                                        let _e834 = mips.member[_e830];
                                        if _e759 {
                                            let _e847 = select(select(u32(_e718), 0u, (_e718 < 0f)), 4294967295u, (_e718 > 4294967000f));
                                            phi_2614_ = select(_e847, 4u, (4u < _e847));
                                        } else {
                                            phi_2614_ = 0u;
                                        }
                                        let _e851 = phi_2614_;
                                        let _e852 = (_e851 & 31u);
                                        let _e854 = (_e102 >> bitcast<u32>(_e852));
                                        let _e856 = select(1u, _e854, (1u < _e854));
                                        let _e858 = (_e113 >> bitcast<u32>(_e852));
                                        let _e860 = select(1u, _e858, (1u < _e858));
                                        let _e862 = (_e757 * f32(_e856));
                                        if (_e862 > 0f) {
                                            let _e868 = select(select(u32(_e862), 0u, (_e862 < 0f)), 4294967295u, (_e862 > 4294967000f));
                                            let _e869 = (_e856 - 1u);
                                            phi_2662_ = select(_e868, _e869, (_e869 < _e868));
                                        } else {
                                            phi_2662_ = 0u;
                                        }
                                        let _e873 = phi_2662_;
                                        let _e875 = (_e758 * f32(_e860));
                                        if (_e875 > 0f) {
                                            let _e881 = select(select(u32(_e875), 0u, (_e875 < 0f)), 4294967295u, (_e875 > 4294967000f));
                                            let _e882 = (_e860 - 1u);
                                            phi_2682_ = select(_e881, _e882, (_e882 < _e881));
                                        } else {
                                            phi_2682_ = 0u;
                                        }
                                        let _e886 = phi_2682_;
                                        phi_2684_ = 0u;
                                        phi_2685_ = 0u;
                                        loop {
                                            let _e888 = phi_2684_;
                                            let _e890 = phi_2685_;
                                            local_3 = _e890;
                                            let _e891 = (_e888 < _e851);
                                            if _e891 {
                                                let _e892 = (_e888 & 31u);
                                                let _e894 = (_e102 >> bitcast<u32>(_e892));
                                                let _e898 = (_e113 >> bitcast<u32>(_e892));
                                                phi_2708_ = (_e888 + 1u);
                                                phi_2709_ = (_e890 + (select(1u, _e894, (1u < _e894)) * select(1u, _e898, (1u < _e898))));
                                            } else {
                                                phi_2708_ = u32();
                                                phi_2709_ = u32();
                                            }
                                            let _e905 = phi_2708_;
                                            let _e907 = phi_2709_;
                                            continue;
                                            continuing {
                                                phi_2684_ = _e905;
                                                phi_2685_ = _e907;
                                                break if !(_e891);
                                            }
                                        }
                                        let _e912 = local_3;
                                        let _e913 = (_e912 + ((_e886 * _e856) + _e873));
                                        if (_e913 < _e85) {
                                        } else {
                                            phi_2845_ = true;
                                            break;
                                        }
                                        let _e917 = mips.member[_e913];
                                        let _e926 = (((((_e755 * 2f) - 1f) * _e389) * _e834) - _e391);
                                        let _e927 = (((((_e756 * -2f) + 1f) * _e399) * _e834) - _e401);
                                        let _e928 = (_e834 - _e381);
                                        let _e931 = params.member.member_1;
                                        let _e932 = (_e931 > 0f);
                                        if _e932 {
                                            phi_1404_ = select(true, false, (sqrt((((_e926 * _e926) + (_e927 * _e927)) + (_e928 * _e928))) > _e931));
                                        } else {
                                            phi_1404_ = true;
                                        }
                                        let _e942 = phi_1404_;
                                        if _e942 {
                                            let _e945 = params.member.member;
                                            let _e948 = params.member.member_3;
                                            let _e953 = (((_e926 * _e412) + (_e927 * _e413)) + (_e928 * _e414));
                                            let _e957 = (_e926 - (_e412 * _e953));
                                            let _e958 = (_e927 - (_e413 * _e953));
                                            let _e959 = (_e928 - (_e414 * _e953));
                                            if (sqrt((((_e957 * _e957) + (_e958 * _e958)) + (_e959 * _e959))) <= 0f) {
                                                phi_1709_ = 0u;
                                            } else {
                                                let _e969 = ((_e958 * _e414) - (_e413 * _e959));
                                                let _e972 = ((_e959 * _e412) - (_e414 * _e957));
                                                let _e975 = ((_e957 * _e413) - (_e412 * _e958));
                                                let _e982 = (1f / sqrt((((_e969 * _e969) + (_e972 * _e972)) + (_e975 * _e975))));
                                                let _e983 = (_e969 * _e982);
                                                let _e984 = (_e972 * _e982);
                                                let _e985 = (_e975 * _e982);
                                                let _e990 = (((_e487.x * _e983) + (_e487.y * _e984)) + (_e487.z * _e985));
                                                let _e994 = (_e487.x - (_e983 * _e990));
                                                let _e995 = (_e487.y - (_e984 * _e990));
                                                let _e996 = (_e487.z - (_e985 * _e990));
                                                let _e1002 = sqrt((((_e994 * _e994) + (_e995 * _e995)) + (_e996 * _e996)));
                                                let _e1008 = ((((_e994 * _e412) + (_e995 * _e413)) + (_e996 * _e414)) / _e1002);
                                                let _e1012 = select(0f, select(1f, _e1008, (_e1008 < 1f)), (_e1008 > 0f));
                                                if ((((_e957 * _e994) + (_e958 * _e995)) + (_e959 * _e996)) < 0f) {
                                                    phi_1520_ = -(acos(_e1012));
                                                } else {
                                                    phi_1520_ = acos(_e1012);
                                                }
                                                let _e1023 = phi_1520_;
                                                let _e1024 = (0.02f / _e1002);
                                                if (_e1024 != _e1024) {
                                                    phi_2725_ = true;
                                                } else {
                                                    phi_2725_ = (0.19634955f <= _e1024);
                                                }
                                                let _e1028 = phi_2725_;
                                                let _e1029 = select(_e1024, 0.19634955f, _e1028);
                                                let _e1033 = (_e926 - (_e412 * _e945));
                                                let _e1034 = (_e927 - (_e413 * _e945));
                                                let _e1035 = (_e928 - (_e414 * _e945));
                                                let _e1042 = (1f / sqrt((((_e926 * _e926) + (_e927 * _e927)) + (_e928 * _e928))));
                                                let _e1050 = ((((_e926 * _e1042) * _e412) + ((_e927 * _e1042) * _e413)) + ((_e928 * _e1042) * _e414));
                                                let _e1059 = ((((acos(select(-1f, select(1f, _e1050, (_e1050 < 1f)), (_e1050 > -1f))) + _e1029) - _e1023) + 1.5707964f) * 0.31830987f);
                                                let _e1063 = select(0f, select(1f, _e1059, (_e1059 < 1f)), (_e1059 > 0f));
                                                let _e1070 = (1f / sqrt((((_e1033 * _e1033) + (_e1034 * _e1034)) + (_e1035 * _e1035))));
                                                let _e1078 = ((((_e1033 * _e1070) * _e412) + ((_e1034 * _e1070) * _e413)) + ((_e1035 * _e1070) * _e414));
                                                let _e1087 = ((((acos(select(-1f, select(1f, _e1078, (_e1078 < 1f)), (_e1078 > -1f))) + _e1029) - _e1023) + 1.5707964f) * 0.31830987f);
                                                let _e1091 = select(0f, select(1f, _e1087, (_e1087 < 1f)), (_e1087 > 0f));
                                                let _e1092 = (_e1063 != _e1063);
                                                if _e1092 {
                                                    phi_2740_ = true;
                                                } else {
                                                    phi_2740_ = (_e1091 <= _e1063);
                                                }
                                                let _e1095 = phi_2740_;
                                                let _e1096 = select(_e1063, _e1091, _e1095);
                                                if _e1092 {
                                                    phi_2755_ = true;
                                                } else {
                                                    phi_2755_ = (_e1091 >= _e1063);
                                                }
                                                let _e1099 = phi_2755_;
                                                let _e1100 = select(_e1063, _e1091, _e1099);
                                                let _e1102 = floor((32f * _e1096));
                                                let _e1107 = select(select(u32(_e1102), 0u, (_e1102 < 0f)), 4294967295u, (_e1102 > 4294967000f));
                                                if (_e948 == 1u) {
                                                    let _e1117 = (_e1100 <= _e1096);
                                                    if _e1117 {
                                                        phi_1666_ = u32();
                                                    } else {
                                                        let _e1119 = ceil((32f * _e1100));
                                                        let _e1124 = select(select(u32(_e1119), 0u, (_e1119 < 0f)), 4294967295u, (_e1119 > 4294967000f));
                                                        let _e1126 = select(_e1124, 32u, (32u < _e1124));
                                                        if (_e1126 > _e1107) {
                                                            phi_1665_ = (_e1126 - _e1107);
                                                        } else {
                                                            phi_1665_ = 0u;
                                                        }
                                                        let _e1130 = phi_1665_;
                                                        phi_1666_ = _e1130;
                                                    }
                                                    let _e1132 = phi_1666_;
                                                    phi_1678_ = _e1132;
                                                    phi_1679_ = select(true, false, _e1117);
                                                } else {
                                                    let _e1111 = ceil((32f * (_e1100 - _e1096)));
                                                    phi_1678_ = select(select(u32(_e1111), 0u, (_e1111 < 0f)), 4294967295u, (_e1111 > 4294967000f));
                                                    phi_1679_ = true;
                                                }
                                                let _e1135 = phi_1678_;
                                                let _e1137 = phi_1679_;
                                                if _e1137 {
                                                    if (_e1107 >= 32u) {
                                                        phi_1702_ = u32();
                                                        phi_1703_ = true;
                                                    } else {
                                                        let _e1139 = (_e1135 == 0u);
                                                        if _e1139 {
                                                            phi_1701_ = u32();
                                                        } else {
                                                            if (_e1135 >= 32u) {
                                                                phi_1698_ = 4294967295u;
                                                            } else {
                                                                phi_1698_ = ((1u << bitcast<u32>((_e1135 & 31u))) - 1u);
                                                            }
                                                            let _e1146 = phi_1698_;
                                                            phi_1701_ = (_e1146 << bitcast<u32>((_e1107 & 31u)));
                                                        }
                                                        let _e1151 = phi_1701_;
                                                        phi_1702_ = _e1151;
                                                        phi_1703_ = _e1139;
                                                    }
                                                    let _e1153 = phi_1702_;
                                                    let _e1155 = phi_1703_;
                                                    phi_1708_ = select(_e1153, 0u, _e1155);
                                                } else {
                                                    phi_1708_ = 0u;
                                                }
                                                let _e1158 = phi_1708_;
                                                phi_1709_ = _e1158;
                                            }
                                            let _e1160 = phi_1709_;
                                            phi_1710_ = _e1160;
                                        } else {
                                            phi_1710_ = 0u;
                                        }
                                        let _e1162 = phi_1710_;
                                        let _e1164 = (((((_e757 * 2f) - 1f) * _e389) * _e917) - _e391);
                                        let _e1165 = (((((_e758 * -2f) + 1f) * _e399) * _e917) - _e401);
                                        let _e1166 = (_e917 - _e381);
                                        if _e932 {
                                            phi_1738_ = select(true, false, (sqrt((((_e1164 * _e1164) + (_e1165 * _e1165)) + (_e1166 * _e1166))) > _e931));
                                        } else {
                                            phi_1738_ = true;
                                        }
                                        let _e1176 = phi_1738_;
                                        if _e1176 {
                                            let _e1179 = params.member.member;
                                            let _e1182 = params.member.member_3;
                                            let _e1187 = (((_e1164 * _e412) + (_e1165 * _e413)) + (_e1166 * _e414));
                                            let _e1191 = (_e1164 - (_e412 * _e1187));
                                            let _e1192 = (_e1165 - (_e413 * _e1187));
                                            let _e1193 = (_e1166 - (_e414 * _e1187));
                                            if (sqrt((((_e1191 * _e1191) + (_e1192 * _e1192)) + (_e1193 * _e1193))) <= 0f) {
                                                phi_2043_ = 0u;
                                            } else {
                                                let _e1203 = ((_e1192 * _e414) - (_e413 * _e1193));
                                                let _e1206 = ((_e1193 * _e412) - (_e414 * _e1191));
                                                let _e1209 = ((_e1191 * _e413) - (_e412 * _e1192));
                                                let _e1216 = (1f / sqrt((((_e1203 * _e1203) + (_e1206 * _e1206)) + (_e1209 * _e1209))));
                                                let _e1217 = (_e1203 * _e1216);
                                                let _e1218 = (_e1206 * _e1216);
                                                let _e1219 = (_e1209 * _e1216);
                                                let _e1224 = (((_e487.x * _e1217) + (_e487.y * _e1218)) + (_e487.z * _e1219));
                                                let _e1228 = (_e487.x - (_e1217 * _e1224));
                                                let _e1229 = (_e487.y - (_e1218 * _e1224));
                                                let _e1230 = (_e487.z - (_e1219 * _e1224));
                                                let _e1236 = sqrt((((_e1228 * _e1228) + (_e1229 * _e1229)) + (_e1230 * _e1230)));
                                                let _e1242 = ((((_e1228 * _e412) + (_e1229 * _e413)) + (_e1230 * _e414)) / _e1236);
                                                let _e1246 = select(0f, select(1f, _e1242, (_e1242 < 1f)), (_e1242 > 0f));
                                                if ((((_e1191 * _e1228) + (_e1192 * _e1229)) + (_e1193 * _e1230)) < 0f) {
                                                    phi_1854_ = -(acos(_e1246));
                                                } else {
                                                    phi_1854_ = acos(_e1246);
                                                }
                                                let _e1257 = phi_1854_;
                                                let _e1258 = (0.02f / _e1236);
                                                if (_e1258 != _e1258) {
                                                    phi_2770_ = true;
                                                } else {
                                                    phi_2770_ = (0.19634955f <= _e1258);
                                                }
                                                let _e1262 = phi_2770_;
                                                let _e1263 = select(_e1258, 0.19634955f, _e1262);
                                                let _e1267 = (_e1164 - (_e412 * _e1179));
                                                let _e1268 = (_e1165 - (_e413 * _e1179));
                                                let _e1269 = (_e1166 - (_e414 * _e1179));
                                                let _e1276 = (1f / sqrt((((_e1164 * _e1164) + (_e1165 * _e1165)) + (_e1166 * _e1166))));
                                                let _e1284 = ((((_e1164 * _e1276) * _e412) + ((_e1165 * _e1276) * _e413)) + ((_e1166 * _e1276) * _e414));
                                                let _e1293 = ((((acos(select(-1f, select(1f, _e1284, (_e1284 < 1f)), (_e1284 > -1f))) + _e1263) - _e1257) + 1.5707964f) * 0.31830987f);
                                                let _e1304 = (1f / sqrt((((_e1267 * _e1267) + (_e1268 * _e1268)) + (_e1269 * _e1269))));
                                                let _e1312 = ((((_e1267 * _e1304) * _e412) + ((_e1268 * _e1304) * _e413)) + ((_e1269 * _e1304) * _e414));
                                                let _e1321 = ((((acos(select(-1f, select(1f, _e1312, (_e1312 < 1f)), (_e1312 > -1f))) + _e1263) - _e1257) + 1.5707964f) * 0.31830987f);
                                                let _e1326 = (1f - select(0f, select(1f, _e1293, (_e1293 < 1f)), (_e1293 > 0f)));
                                                let _e1327 = (1f - select(0f, select(1f, _e1321, (_e1321 < 1f)), (_e1321 > 0f)));
                                                let _e1328 = (_e1326 != _e1326);
                                                if _e1328 {
                                                    phi_2785_ = true;
                                                } else {
                                                    phi_2785_ = (_e1327 <= _e1326);
                                                }
                                                let _e1331 = phi_2785_;
                                                let _e1332 = select(_e1326, _e1327, _e1331);
                                                if _e1328 {
                                                    phi_2800_ = true;
                                                } else {
                                                    phi_2800_ = (_e1327 >= _e1326);
                                                }
                                                let _e1335 = phi_2800_;
                                                let _e1336 = select(_e1326, _e1327, _e1335);
                                                let _e1338 = floor((32f * _e1332));
                                                let _e1343 = select(select(u32(_e1338), 0u, (_e1338 < 0f)), 4294967295u, (_e1338 > 4294967000f));
                                                if (_e1182 == 1u) {
                                                    let _e1353 = (_e1336 <= _e1332);
                                                    if _e1353 {
                                                        phi_2000_ = u32();
                                                    } else {
                                                        let _e1355 = ceil((32f * _e1336));
                                                        let _e1360 = select(select(u32(_e1355), 0u, (_e1355 < 0f)), 4294967295u, (_e1355 > 4294967000f));
                                                        let _e1362 = select(_e1360, 32u, (32u < _e1360));
                                                        if (_e1362 > _e1343) {
                                                            phi_1999_ = (_e1362 - _e1343);
                                                        } else {
                                                            phi_1999_ = 0u;
                                                        }
                                                        let _e1366 = phi_1999_;
                                                        phi_2000_ = _e1366;
                                                    }
                                                    let _e1368 = phi_2000_;
                                                    phi_2012_ = _e1368;
                                                    phi_2013_ = select(true, false, _e1353);
                                                } else {
                                                    let _e1347 = ceil((32f * (_e1336 - _e1332)));
                                                    phi_2012_ = select(select(u32(_e1347), 0u, (_e1347 < 0f)), 4294967295u, (_e1347 > 4294967000f));
                                                    phi_2013_ = true;
                                                }
                                                let _e1371 = phi_2012_;
                                                let _e1373 = phi_2013_;
                                                if _e1373 {
                                                    if (_e1343 >= 32u) {
                                                        phi_2036_ = u32();
                                                        phi_2037_ = true;
                                                    } else {
                                                        let _e1375 = (_e1371 == 0u);
                                                        if _e1375 {
                                                            phi_2035_ = u32();
                                                        } else {
                                                            if (_e1371 >= 32u) {
                                                                phi_2032_ = 4294967295u;
                                                            } else {
                                                                phi_2032_ = ((1u << bitcast<u32>((_e1371 & 31u))) - 1u);
                                                            }
                                                            let _e1382 = phi_2032_;
                                                            phi_2035_ = (_e1382 << bitcast<u32>((_e1343 & 31u)));
                                                        }
                                                        let _e1387 = phi_2035_;
                                                        phi_2036_ = _e1387;
                                                        phi_2037_ = _e1375;
                                                    }
                                                    let _e1389 = phi_2036_;
                                                    let _e1391 = phi_2037_;
                                                    phi_2042_ = select(_e1389, 0u, _e1391);
                                                } else {
                                                    phi_2042_ = 0u;
                                                }
                                                let _e1394 = phi_2042_;
                                                phi_2043_ = _e1394;
                                            }
                                            let _e1396 = phi_2043_;
                                            phi_2044_ = _e1396;
                                        } else {
                                            phi_2044_ = 0u;
                                        }
                                        let _e1398 = phi_2044_;
                                        phi_1166_ = (_e675 + 1u);
                                        phi_1169_ = ((_e677 | _e1162) | _e1398);
                                    } else {
                                        phi_1166_ = u32();
                                        phi_1169_ = u32();
                                    }
                                    let _e1402 = phi_1166_;
                                    let _e1404 = phi_1169_;
                                    continue;
                                    continuing {
                                        phi_1165_ = _e1402;
                                        phi_1168_ = _e1404;
                                        phi_2845_ = _e581;
                                        break if !(_e678);
                                    }
                                }
                                let _e1407 = phi_2845_;
                                phi_3017_ = _e1407;
                                if _e1407 {
                                    break;
                                }
                                let _e1410 = params.member.member_2;
                                if (_e1410 == 2u) {
                                    let _e1466 = (_e667 - 1.5707964f);
                                    let _e1467 = (_e1466 * 2f);
                                    let _e1468 = sin(_e667);
                                    let _e1473 = ((_e665 + (_e1467 * _e1468)) - cos((_e1467 - _e667)));
                                    if (_e1466 < 0f) {
                                        phi_2073_ = (_e1473 * -0.25f);
                                    } else {
                                        phi_2073_ = (_e1473 * 0.25f);
                                    }
                                    let _e1478 = phi_2073_;
                                    phi_2075_ = 0u;
                                    phi_2078_ = _e1478;
                                    phi_2080_ = 0f;
                                    loop {
                                        let _e1480 = phi_2075_;
                                        let _e1482 = phi_2078_;
                                        let _e1484 = phi_2080_;
                                        local_8 = _e1484;
                                        let _e1485 = (_e1480 < 32u);
                                        if _e1485 {
                                            let _e1486 = (_e1480 + 1u);
                                            let _e1489 = (_e1466 + (f32(_e1486) * 0.09817477f));
                                            let _e1490 = (_e1489 * 2f);
                                            let _e1495 = ((_e665 + (_e1490 * _e1468)) - cos((_e1490 - _e667)));
                                            if (_e1489 < 0f) {
                                                phi_2106_ = (_e1495 * -0.25f);
                                            } else {
                                                phi_2106_ = (_e1495 * 0.25f);
                                            }
                                            let _e1500 = phi_2106_;
                                            let _e1503 = local_7;
                                            if (((_e1503 >> bitcast<u32>((_e1480 & 31u))) & 1u) == 0u) {
                                                phi_2116_ = (_e1484 + (_e1500 - _e1482));
                                            } else {
                                                phi_2116_ = _e1484;
                                            }
                                            let _e1511 = phi_2116_;
                                            phi_2076_ = _e1486;
                                            phi_2079_ = _e1500;
                                            phi_2081_ = _e1511;
                                        } else {
                                            phi_2076_ = u32();
                                            phi_2079_ = f32();
                                            phi_2081_ = f32();
                                        }
                                        let _e1513 = phi_2076_;
                                        let _e1515 = phi_2079_;
                                        let _e1517 = phi_2081_;
                                        continue;
                                        continuing {
                                            phi_2075_ = _e1513;
                                            phi_2078_ = _e1515;
                                            phi_2080_ = _e1517;
                                            break if !(_e1485);
                                        }
                                    }
                                    let _e1520 = local_8;
                                    phi_3019_ = _e1407;
                                    phi_2180_ = (_e585 + 1f);
                                    phi_2181_ = (_e587 + ((_e646 + ((1f - _e646) * 0.05f)) * _e1520));
                                } else {
                                    if (_e1410 == 1u) {
                                        phi_2128_ = 0u;
                                        phi_2131_ = 0f;
                                        loop {
                                            let _e1422 = phi_2128_;
                                            let _e1424 = phi_2131_;
                                            local_6 = _e1424;
                                            let _e1425 = (_e1422 < 4u);
                                            if _e1425 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1425 {
                                                } else {
                                                    phi_3014_ = true;
                                                    break;
                                                }
                                                let _e1428 = local[_e1422].member;
                                                let _e1431 = local[_e1422].member_1;
                                                let _e1433 = local_5;
                                                phi_2129_ = (_e1422 + 1u);
                                                phi_2132_ = (_e1424 + (f32(countOneBits((_e1433 & _e1428))) * _e1431));
                                            } else {
                                                phi_2129_ = u32();
                                                phi_2132_ = f32();
                                            }
                                            let _e1441 = phi_2129_;
                                            let _e1443 = phi_2132_;
                                            continue;
                                            continuing {
                                                phi_2128_ = _e1441;
                                                phi_2131_ = _e1443;
                                                phi_3014_ = _e1407;
                                                break if !(_e1425);
                                            }
                                        }
                                        let _e1446 = phi_3014_;
                                        phi_3017_ = _e1446;
                                        if _e1446 {
                                            break;
                                        }
                                        let _e1448 = local_6;
                                        let _e1449 = (1f - _e1448);
                                        phi_3025_ = _e1446;
                                        phi_2178_ = (_e585 + _e646);
                                        phi_2179_ = (_e587 + (_e646 * select(0f, select(1f, _e1449, (_e1449 < 1f)), (_e1449 > 0f))));
                                    } else {
                                        let _e1414 = local_4;
                                        phi_3025_ = _e1407;
                                        phi_2178_ = (_e585 + 1f);
                                        phi_2179_ = (_e587 + (1f - (f32(countOneBits(_e1414)) * 0.03125f)));
                                    }
                                    let _e1458 = phi_3025_;
                                    let _e1460 = phi_2178_;
                                    let _e1462 = phi_2179_;
                                    phi_3019_ = _e1458;
                                    phi_2180_ = _e1460;
                                    phi_2181_ = _e1462;
                                }
                                let _e1525 = phi_3019_;
                                let _e1527 = phi_2180_;
                                let _e1529 = phi_2181_;
                                phi_3018_ = _e1525;
                                phi_991_ = (_e583 + 1u);
                                phi_994_ = _e1527;
                                phi_996_ = _e1529;
                            } else {
                                phi_3018_ = _e581;
                                phi_991_ = u32();
                                phi_994_ = f32();
                                phi_996_ = f32();
                            }
                            let _e1532 = phi_3018_;
                            let _e1534 = phi_991_;
                            let _e1536 = phi_994_;
                            let _e1538 = phi_996_;
                            continue;
                            continuing {
                                phi_2897_ = _e1532;
                                phi_990_ = _e1534;
                                phi_993_ = _e1536;
                                phi_995_ = _e1538;
                                phi_3017_ = _e1532;
                                break if !(_e588);
                            }
                        }
                        let _e1541 = phi_3017_;
                        if _e1541 {
                            break;
                        }
                        let _e1543 = local_9;
                        if (_e1543 > 0f) {
                            let _e1546 = local_10;
                            let _e1548 = local_11;
                            phi_2188_ = (_e1546 / _e1548);
                        } else {
                            phi_2188_ = 1f;
                        }
                        let _e1551 = phi_2188_;
                        let _e1555 = params.member.member_4.member_6;
                        let _e1556 = pow(_e1551, _e1555);
                        if (_e1556 != _e1556) {
                            phi_2815_ = true;
                        } else {
                            phi_2815_ = (0.03f >= _e1556);
                        }
                        let _e1560 = phi_2815_;
                        let _e1562 = (select(_e1556, 0.03f, _e1560) * 0.6666667f);
                        let _e1568 = ((select(0f, select(1f, _e1562, (_e1562 < 1f)), (_e1562 > 0f)) * 255f) + 0.5f);
                        phi_2236_ = type_28(select(select(u32(_e1568), 0u, (_e1568 < 0f)), 4294967295u, (_e1568 > 4294967000f)), _e374);
                    } else {
                        phi_2236_ = type_28(170u, _e374);
                    }
                    let _e1576 = phi_2236_;
                    if (_e119 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e119] = _e1576.member;
                    if (_e119 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e119] = _e1576.member_1;
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
