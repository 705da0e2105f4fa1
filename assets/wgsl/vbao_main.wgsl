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
                    if select(false, (_e123 < _e568), (_e123 > 0f)) {
                        let _e576 = params.member.member_4.member_8;
                        let _e578 = select(1u, _e576, (1u < _e576));
                        phi_2897_ = false;
                        phi_990_ = 0u;
                        phi_993_ = 0f;
                        phi_995_ = 0f;
                        loop {
                            let _e580 = phi_2897_;
                            let _e582 = phi_990_;
                            let _e584 = phi_993_;
                            let _e586 = phi_995_;
                            local_9 = _e584;
                            local_10 = _e586;
                            local_11 = _e584;
                            let _e587 = (_e582 < _e578);
                            if _e587 {
                                let _e592 = ((((_e557 - floor(_e557)) + f32(_e582)) * 3.1415927f) / f32(_e578));
                                let _e593 = sin(_e592);
                                let _e594 = cos(_e592);
                                let _e600 = ((_e594 * _e412) + (_e593 * _e413));
                                let _e604 = (_e594 - (_e412 * _e600));
                                let _e605 = (_e593 - (_e413 * _e600));
                                let _e606 = -((_e414 * _e600));
                                let _e609 = ((_e605 * _e414) - (_e413 * _e606));
                                let _e612 = ((_e606 * _e412) - (_e414 * _e604));
                                let _e615 = ((_e604 * _e413) - (_e412 * _e605));
                                let _e622 = (1f / sqrt((((_e609 * _e609) + (_e612 * _e612)) + (_e615 * _e615))));
                                let _e623 = (_e609 * _e622);
                                let _e624 = (_e612 * _e622);
                                let _e625 = (_e615 * _e622);
                                let _e633 = (((_e487.x * _e623) + (_e487.y * _e624)) + (_e487.z * _e625));
                                let _e637 = (_e487.x - (_e623 * _e633));
                                let _e638 = (_e487.y - (_e624 * _e633));
                                let _e639 = (_e487.z - (_e625 * _e633));
                                let _e645 = sqrt((((_e637 * _e637) + (_e638 * _e638)) + (_e639 * _e639)));
                                let _e650 = (((_e604 * _e637) + (_e605 * _e638)) + (_e606 * _e639));
                                let _e660 = ((((_e637 * _e412) + (_e638 * _e413)) + (_e639 * _e414)) / _e645);
                                let _e664 = select(0f, select(1f, _e660, (_e660 < 1f)), (_e660 > 0f));
                                let _e666 = (select(select(0f, -1f, (_e650 < 0f)), 1f, (_e650 > 0f)) * acos(_e664));
                                let _e670 = params.member.member_4.member_9;
                                let _e672 = select(1u, _e670, (1u < _e670));
                                phi_1165_ = 0u;
                                phi_1168_ = 0u;
                                loop {
                                    let _e674 = phi_1165_;
                                    let _e676 = phi_1168_;
                                    local_4 = _e676;
                                    local_5 = _e676;
                                    local_7 = _e676;
                                    let _e677 = (_e674 < _e672);
                                    if _e677 {
                                        let _e682 = ((_e561 - floor(_e561)) + (f32((_e582 + (_e674 * _e672))) * 0.618034f));
                                        let _e688 = (((_e682 - floor(_e682)) + f32(_e674)) / f32(_e672));
                                        let _e692 = params.member.member_4.member_4;
                                        if (_e692 == 2f) {
                                            phi_1222_ = (_e688 * _e688);
                                        } else {
                                            phi_1222_ = pow(_e688, _e692);
                                        }
                                        let _e697 = phi_1222_;
                                        let _e698 = (_e697 + (1.3f / _e500));
                                        let _e699 = ((_e594 * _e500) * _e698);
                                        let _e700 = ((-(_e593) * _e500) * _e698);
                                        let _e709 = params.member.member_4.member_7;
                                        let _e710 = (log2(sqrt(((_e699 * _e699) + (_e700 * _e700)))) - _e709);
                                        let _e717 = (-1f - floor((-0.5f - select(0f, select(5f, _e710, (_e710 < 5f)), (_e710 > 0f)))));
                                        let _e719 = floor((_e699 + 0.5f));
                                        if ((_e719 - _e699) == 0.5f) {
                                            let _e725 = ((floor((_e719 * 0.5f)) * 2f) != _e719);
                                            if _e725 {
                                                phi_1267_ = (_e719 - 1f);
                                            } else {
                                                phi_1267_ = f32();
                                            }
                                            let _e728 = phi_1267_;
                                            phi_1269_ = _e728;
                                            phi_1270_ = select(true, false, _e725);
                                        } else {
                                            phi_1269_ = f32();
                                            phi_1270_ = true;
                                        }
                                        let _e731 = phi_1269_;
                                        let _e733 = phi_1270_;
                                        let _e735 = (select(_e731, _e719, _e733) / _e97);
                                        let _e737 = floor((_e700 + 0.5f));
                                        if ((_e737 - _e700) == 0.5f) {
                                            let _e743 = ((floor((_e737 * 0.5f)) * 2f) != _e737);
                                            if _e743 {
                                                phi_1293_ = (_e737 - 1f);
                                            } else {
                                                phi_1293_ = f32();
                                            }
                                            let _e746 = phi_1293_;
                                            phi_1295_ = _e746;
                                            phi_1296_ = select(true, false, _e743);
                                        } else {
                                            phi_1295_ = f32();
                                            phi_1296_ = true;
                                        }
                                        let _e749 = phi_1295_;
                                        let _e751 = phi_1296_;
                                        let _e753 = (select(_e749, _e737, _e751) / _e108);
                                        let _e754 = (_e379 + _e735);
                                        let _e755 = (_e380 + _e753);
                                        let _e756 = (_e379 - _e735);
                                        let _e757 = (_e380 - _e753);
                                        let _e758 = (_e717 > 0f);
                                        if _e758 {
                                            let _e763 = select(select(u32(_e717), 0u, (_e717 < 0f)), 4294967295u, (_e717 > 4294967000f));
                                            phi_2492_ = select(_e763, 4u, (4u < _e763));
                                        } else {
                                            phi_2492_ = 0u;
                                        }
                                        let _e767 = phi_2492_;
                                        let _e768 = (_e767 & 31u);
                                        let _e770 = (_e102 >> bitcast<u32>(_e768));
                                        let _e772 = select(1u, _e770, (1u < _e770));
                                        let _e774 = (_e113 >> bitcast<u32>(_e768));
                                        let _e776 = select(1u, _e774, (1u < _e774));
                                        let _e778 = (_e754 * f32(_e772));
                                        if (_e778 > 0f) {
                                            let _e784 = select(select(u32(_e778), 0u, (_e778 < 0f)), 4294967295u, (_e778 > 4294967000f));
                                            let _e785 = (_e772 - 1u);
                                            phi_2540_ = select(_e784, _e785, (_e785 < _e784));
                                        } else {
                                            phi_2540_ = 0u;
                                        }
                                        let _e789 = phi_2540_;
                                        let _e791 = (_e755 * f32(_e776));
                                        if (_e791 > 0f) {
                                            let _e797 = select(select(u32(_e791), 0u, (_e791 < 0f)), 4294967295u, (_e791 > 4294967000f));
                                            let _e798 = (_e776 - 1u);
                                            phi_2560_ = select(_e797, _e798, (_e798 < _e797));
                                        } else {
                                            phi_2560_ = 0u;
                                        }
                                        let _e802 = phi_2560_;
                                        phi_2562_ = 0u;
                                        phi_2563_ = 0u;
                                        loop {
                                            let _e804 = phi_2562_;
                                            let _e806 = phi_2563_;
                                            local_2 = _e806;
                                            let _e807 = (_e804 < _e767);
                                            if _e807 {
                                                let _e808 = (_e804 & 31u);
                                                let _e810 = (_e102 >> bitcast<u32>(_e808));
                                                let _e814 = (_e113 >> bitcast<u32>(_e808));
                                                phi_2586_ = (_e804 + 1u);
                                                phi_2587_ = (_e806 + (select(1u, _e810, (1u < _e810)) * select(1u, _e814, (1u < _e814))));
                                            } else {
                                                phi_2586_ = u32();
                                                phi_2587_ = u32();
                                            }
                                            let _e821 = phi_2586_;
                                            let _e823 = phi_2587_;
                                            continue;
                                            continuing {
                                                phi_2562_ = _e821;
                                                phi_2563_ = _e823;
                                                break if !(_e807);
                                            }
                                        }
                                        let _e828 = local_2;
                                        let _e829 = (_e828 + ((_e802 * _e772) + _e789));
                                        if (_e829 < _e85) {
                                        } else {
                                            phi_2845_ = true;
                                            break;
                                        }
                                        let _e833 = mips.member[_e829];
                                        if _e758 {
                                            let _e846 = select(select(u32(_e717), 0u, (_e717 < 0f)), 4294967295u, (_e717 > 4294967000f));
                                            phi_2614_ = select(_e846, 4u, (4u < _e846));
                                        } else {
                                            phi_2614_ = 0u;
                                        }
                                        let _e850 = phi_2614_;
                                        let _e851 = (_e850 & 31u);
                                        let _e853 = (_e102 >> bitcast<u32>(_e851));
                                        let _e855 = select(1u, _e853, (1u < _e853));
                                        let _e857 = (_e113 >> bitcast<u32>(_e851));
                                        let _e859 = select(1u, _e857, (1u < _e857));
                                        let _e861 = (_e756 * f32(_e855));
                                        if (_e861 > 0f) {
                                            let _e867 = select(select(u32(_e861), 0u, (_e861 < 0f)), 4294967295u, (_e861 > 4294967000f));
                                            let _e868 = (_e855 - 1u);
                                            phi_2662_ = select(_e867, _e868, (_e868 < _e867));
                                        } else {
                                            phi_2662_ = 0u;
                                        }
                                        let _e872 = phi_2662_;
                                        let _e874 = (_e757 * f32(_e859));
                                        if (_e874 > 0f) {
                                            let _e880 = select(select(u32(_e874), 0u, (_e874 < 0f)), 4294967295u, (_e874 > 4294967000f));
                                            let _e881 = (_e859 - 1u);
                                            phi_2682_ = select(_e880, _e881, (_e881 < _e880));
                                        } else {
                                            phi_2682_ = 0u;
                                        }
                                        let _e885 = phi_2682_;
                                        phi_2684_ = 0u;
                                        phi_2685_ = 0u;
                                        loop {
                                            let _e887 = phi_2684_;
                                            let _e889 = phi_2685_;
                                            local_3 = _e889;
                                            let _e890 = (_e887 < _e850);
                                            if _e890 {
                                                let _e891 = (_e887 & 31u);
                                                let _e893 = (_e102 >> bitcast<u32>(_e891));
                                                let _e897 = (_e113 >> bitcast<u32>(_e891));
                                                phi_2708_ = (_e887 + 1u);
                                                phi_2709_ = (_e889 + (select(1u, _e893, (1u < _e893)) * select(1u, _e897, (1u < _e897))));
                                            } else {
                                                phi_2708_ = u32();
                                                phi_2709_ = u32();
                                            }
                                            let _e904 = phi_2708_;
                                            let _e906 = phi_2709_;
                                            continue;
                                            continuing {
                                                phi_2684_ = _e904;
                                                phi_2685_ = _e906;
                                                break if !(_e890);
                                            }
                                        }
                                        let _e911 = local_3;
                                        let _e912 = (_e911 + ((_e885 * _e855) + _e872));
                                        if (_e912 < _e85) {
                                        } else {
                                            phi_2845_ = true;
                                            break;
                                        }
                                        let _e916 = mips.member[_e912];
                                        let _e925 = (((((_e754 * 2f) - 1f) * _e389) * _e833) - _e391);
                                        let _e926 = (((((_e755 * -2f) + 1f) * _e399) * _e833) - _e401);
                                        let _e927 = (_e833 - _e381);
                                        let _e930 = params.member.member_1;
                                        let _e931 = (_e930 > 0f);
                                        if _e931 {
                                            phi_1404_ = select(true, false, (sqrt((((_e925 * _e925) + (_e926 * _e926)) + (_e927 * _e927))) > _e930));
                                        } else {
                                            phi_1404_ = true;
                                        }
                                        let _e941 = phi_1404_;
                                        if _e941 {
                                            let _e944 = params.member.member;
                                            let _e947 = params.member.member_3;
                                            let _e952 = (((_e925 * _e412) + (_e926 * _e413)) + (_e927 * _e414));
                                            let _e956 = (_e925 - (_e412 * _e952));
                                            let _e957 = (_e926 - (_e413 * _e952));
                                            let _e958 = (_e927 - (_e414 * _e952));
                                            if (sqrt((((_e956 * _e956) + (_e957 * _e957)) + (_e958 * _e958))) <= 0f) {
                                                phi_1709_ = 0u;
                                            } else {
                                                let _e968 = ((_e957 * _e414) - (_e413 * _e958));
                                                let _e971 = ((_e958 * _e412) - (_e414 * _e956));
                                                let _e974 = ((_e956 * _e413) - (_e412 * _e957));
                                                let _e981 = (1f / sqrt((((_e968 * _e968) + (_e971 * _e971)) + (_e974 * _e974))));
                                                let _e982 = (_e968 * _e981);
                                                let _e983 = (_e971 * _e981);
                                                let _e984 = (_e974 * _e981);
                                                let _e989 = (((_e487.x * _e982) + (_e487.y * _e983)) + (_e487.z * _e984));
                                                let _e993 = (_e487.x - (_e982 * _e989));
                                                let _e994 = (_e487.y - (_e983 * _e989));
                                                let _e995 = (_e487.z - (_e984 * _e989));
                                                let _e1001 = sqrt((((_e993 * _e993) + (_e994 * _e994)) + (_e995 * _e995)));
                                                let _e1007 = ((((_e993 * _e412) + (_e994 * _e413)) + (_e995 * _e414)) / _e1001);
                                                let _e1011 = select(0f, select(1f, _e1007, (_e1007 < 1f)), (_e1007 > 0f));
                                                if ((((_e956 * _e993) + (_e957 * _e994)) + (_e958 * _e995)) < 0f) {
                                                    phi_1520_ = -(acos(_e1011));
                                                } else {
                                                    phi_1520_ = acos(_e1011);
                                                }
                                                let _e1022 = phi_1520_;
                                                let _e1023 = (0.02f / _e1001);
                                                if (_e1023 != _e1023) {
                                                    phi_2725_ = true;
                                                } else {
                                                    phi_2725_ = (0.19634955f <= _e1023);
                                                }
                                                let _e1027 = phi_2725_;
                                                let _e1028 = select(_e1023, 0.19634955f, _e1027);
                                                let _e1032 = (_e925 - (_e412 * _e944));
                                                let _e1033 = (_e926 - (_e413 * _e944));
                                                let _e1034 = (_e927 - (_e414 * _e944));
                                                let _e1041 = (1f / sqrt((((_e925 * _e925) + (_e926 * _e926)) + (_e927 * _e927))));
                                                let _e1049 = ((((_e925 * _e1041) * _e412) + ((_e926 * _e1041) * _e413)) + ((_e927 * _e1041) * _e414));
                                                let _e1058 = ((((acos(select(-1f, select(1f, _e1049, (_e1049 < 1f)), (_e1049 > -1f))) + _e1028) - _e1022) + 1.5707964f) * 0.31830987f);
                                                let _e1062 = select(0f, select(1f, _e1058, (_e1058 < 1f)), (_e1058 > 0f));
                                                let _e1069 = (1f / sqrt((((_e1032 * _e1032) + (_e1033 * _e1033)) + (_e1034 * _e1034))));
                                                let _e1077 = ((((_e1032 * _e1069) * _e412) + ((_e1033 * _e1069) * _e413)) + ((_e1034 * _e1069) * _e414));
                                                let _e1086 = ((((acos(select(-1f, select(1f, _e1077, (_e1077 < 1f)), (_e1077 > -1f))) + _e1028) - _e1022) + 1.5707964f) * 0.31830987f);
                                                let _e1090 = select(0f, select(1f, _e1086, (_e1086 < 1f)), (_e1086 > 0f));
                                                let _e1091 = (_e1062 != _e1062);
                                                if _e1091 {
                                                    phi_2740_ = true;
                                                } else {
                                                    phi_2740_ = (_e1090 <= _e1062);
                                                }
                                                let _e1094 = phi_2740_;
                                                let _e1095 = select(_e1062, _e1090, _e1094);
                                                if _e1091 {
                                                    phi_2755_ = true;
                                                } else {
                                                    phi_2755_ = (_e1090 >= _e1062);
                                                }
                                                let _e1098 = phi_2755_;
                                                let _e1099 = select(_e1062, _e1090, _e1098);
                                                let _e1101 = floor((32f * _e1095));
                                                let _e1106 = select(select(u32(_e1101), 0u, (_e1101 < 0f)), 4294967295u, (_e1101 > 4294967000f));
                                                if (_e947 == 1u) {
                                                    let _e1116 = (_e1099 <= _e1095);
                                                    if _e1116 {
                                                        phi_1666_ = u32();
                                                    } else {
                                                        let _e1118 = ceil((32f * _e1099));
                                                        let _e1123 = select(select(u32(_e1118), 0u, (_e1118 < 0f)), 4294967295u, (_e1118 > 4294967000f));
                                                        let _e1125 = select(_e1123, 32u, (32u < _e1123));
                                                        if (_e1125 > _e1106) {
                                                            phi_1665_ = (_e1125 - _e1106);
                                                        } else {
                                                            phi_1665_ = 0u;
                                                        }
                                                        let _e1129 = phi_1665_;
                                                        phi_1666_ = _e1129;
                                                    }
                                                    let _e1131 = phi_1666_;
                                                    phi_1678_ = _e1131;
                                                    phi_1679_ = select(true, false, _e1116);
                                                } else {
                                                    let _e1110 = ceil((32f * (_e1099 - _e1095)));
                                                    phi_1678_ = select(select(u32(_e1110), 0u, (_e1110 < 0f)), 4294967295u, (_e1110 > 4294967000f));
                                                    phi_1679_ = true;
                                                }
                                                let _e1134 = phi_1678_;
                                                let _e1136 = phi_1679_;
                                                if _e1136 {
                                                    if (_e1106 >= 32u) {
                                                        phi_1702_ = u32();
                                                        phi_1703_ = true;
                                                    } else {
                                                        let _e1138 = (_e1134 == 0u);
                                                        if _e1138 {
                                                            phi_1701_ = u32();
                                                        } else {
                                                            if (_e1134 >= 32u) {
                                                                phi_1698_ = 4294967295u;
                                                            } else {
                                                                phi_1698_ = ((1u << bitcast<u32>((_e1134 & 31u))) - 1u);
                                                            }
                                                            let _e1145 = phi_1698_;
                                                            phi_1701_ = (_e1145 << bitcast<u32>((_e1106 & 31u)));
                                                        }
                                                        let _e1150 = phi_1701_;
                                                        phi_1702_ = _e1150;
                                                        phi_1703_ = _e1138;
                                                    }
                                                    let _e1152 = phi_1702_;
                                                    let _e1154 = phi_1703_;
                                                    phi_1708_ = select(_e1152, 0u, _e1154);
                                                } else {
                                                    phi_1708_ = 0u;
                                                }
                                                let _e1157 = phi_1708_;
                                                phi_1709_ = _e1157;
                                            }
                                            let _e1159 = phi_1709_;
                                            phi_1710_ = _e1159;
                                        } else {
                                            phi_1710_ = 0u;
                                        }
                                        let _e1161 = phi_1710_;
                                        let _e1163 = (((((_e756 * 2f) - 1f) * _e389) * _e916) - _e391);
                                        let _e1164 = (((((_e757 * -2f) + 1f) * _e399) * _e916) - _e401);
                                        let _e1165 = (_e916 - _e381);
                                        if _e931 {
                                            phi_1738_ = select(true, false, (sqrt((((_e1163 * _e1163) + (_e1164 * _e1164)) + (_e1165 * _e1165))) > _e930));
                                        } else {
                                            phi_1738_ = true;
                                        }
                                        let _e1175 = phi_1738_;
                                        if _e1175 {
                                            let _e1178 = params.member.member;
                                            let _e1181 = params.member.member_3;
                                            let _e1186 = (((_e1163 * _e412) + (_e1164 * _e413)) + (_e1165 * _e414));
                                            let _e1190 = (_e1163 - (_e412 * _e1186));
                                            let _e1191 = (_e1164 - (_e413 * _e1186));
                                            let _e1192 = (_e1165 - (_e414 * _e1186));
                                            if (sqrt((((_e1190 * _e1190) + (_e1191 * _e1191)) + (_e1192 * _e1192))) <= 0f) {
                                                phi_2043_ = 0u;
                                            } else {
                                                let _e1202 = ((_e1191 * _e414) - (_e413 * _e1192));
                                                let _e1205 = ((_e1192 * _e412) - (_e414 * _e1190));
                                                let _e1208 = ((_e1190 * _e413) - (_e412 * _e1191));
                                                let _e1215 = (1f / sqrt((((_e1202 * _e1202) + (_e1205 * _e1205)) + (_e1208 * _e1208))));
                                                let _e1216 = (_e1202 * _e1215);
                                                let _e1217 = (_e1205 * _e1215);
                                                let _e1218 = (_e1208 * _e1215);
                                                let _e1223 = (((_e487.x * _e1216) + (_e487.y * _e1217)) + (_e487.z * _e1218));
                                                let _e1227 = (_e487.x - (_e1216 * _e1223));
                                                let _e1228 = (_e487.y - (_e1217 * _e1223));
                                                let _e1229 = (_e487.z - (_e1218 * _e1223));
                                                let _e1235 = sqrt((((_e1227 * _e1227) + (_e1228 * _e1228)) + (_e1229 * _e1229)));
                                                let _e1241 = ((((_e1227 * _e412) + (_e1228 * _e413)) + (_e1229 * _e414)) / _e1235);
                                                let _e1245 = select(0f, select(1f, _e1241, (_e1241 < 1f)), (_e1241 > 0f));
                                                if ((((_e1190 * _e1227) + (_e1191 * _e1228)) + (_e1192 * _e1229)) < 0f) {
                                                    phi_1854_ = -(acos(_e1245));
                                                } else {
                                                    phi_1854_ = acos(_e1245);
                                                }
                                                let _e1256 = phi_1854_;
                                                let _e1257 = (0.02f / _e1235);
                                                if (_e1257 != _e1257) {
                                                    phi_2770_ = true;
                                                } else {
                                                    phi_2770_ = (0.19634955f <= _e1257);
                                                }
                                                let _e1261 = phi_2770_;
                                                let _e1262 = select(_e1257, 0.19634955f, _e1261);
                                                let _e1266 = (_e1163 - (_e412 * _e1178));
                                                let _e1267 = (_e1164 - (_e413 * _e1178));
                                                let _e1268 = (_e1165 - (_e414 * _e1178));
                                                let _e1275 = (1f / sqrt((((_e1163 * _e1163) + (_e1164 * _e1164)) + (_e1165 * _e1165))));
                                                let _e1283 = ((((_e1163 * _e1275) * _e412) + ((_e1164 * _e1275) * _e413)) + ((_e1165 * _e1275) * _e414));
                                                let _e1292 = ((((acos(select(-1f, select(1f, _e1283, (_e1283 < 1f)), (_e1283 > -1f))) + _e1262) - _e1256) + 1.5707964f) * 0.31830987f);
                                                let _e1303 = (1f / sqrt((((_e1266 * _e1266) + (_e1267 * _e1267)) + (_e1268 * _e1268))));
                                                let _e1311 = ((((_e1266 * _e1303) * _e412) + ((_e1267 * _e1303) * _e413)) + ((_e1268 * _e1303) * _e414));
                                                let _e1320 = ((((acos(select(-1f, select(1f, _e1311, (_e1311 < 1f)), (_e1311 > -1f))) + _e1262) - _e1256) + 1.5707964f) * 0.31830987f);
                                                let _e1325 = (1f - select(0f, select(1f, _e1292, (_e1292 < 1f)), (_e1292 > 0f)));
                                                let _e1326 = (1f - select(0f, select(1f, _e1320, (_e1320 < 1f)), (_e1320 > 0f)));
                                                let _e1327 = (_e1325 != _e1325);
                                                if _e1327 {
                                                    phi_2785_ = true;
                                                } else {
                                                    phi_2785_ = (_e1326 <= _e1325);
                                                }
                                                let _e1330 = phi_2785_;
                                                let _e1331 = select(_e1325, _e1326, _e1330);
                                                if _e1327 {
                                                    phi_2800_ = true;
                                                } else {
                                                    phi_2800_ = (_e1326 >= _e1325);
                                                }
                                                let _e1334 = phi_2800_;
                                                let _e1335 = select(_e1325, _e1326, _e1334);
                                                let _e1337 = floor((32f * _e1331));
                                                let _e1342 = select(select(u32(_e1337), 0u, (_e1337 < 0f)), 4294967295u, (_e1337 > 4294967000f));
                                                if (_e1181 == 1u) {
                                                    let _e1352 = (_e1335 <= _e1331);
                                                    if _e1352 {
                                                        phi_2000_ = u32();
                                                    } else {
                                                        let _e1354 = ceil((32f * _e1335));
                                                        let _e1359 = select(select(u32(_e1354), 0u, (_e1354 < 0f)), 4294967295u, (_e1354 > 4294967000f));
                                                        let _e1361 = select(_e1359, 32u, (32u < _e1359));
                                                        if (_e1361 > _e1342) {
                                                            phi_1999_ = (_e1361 - _e1342);
                                                        } else {
                                                            phi_1999_ = 0u;
                                                        }
                                                        let _e1365 = phi_1999_;
                                                        phi_2000_ = _e1365;
                                                    }
                                                    let _e1367 = phi_2000_;
                                                    phi_2012_ = _e1367;
                                                    phi_2013_ = select(true, false, _e1352);
                                                } else {
                                                    let _e1346 = ceil((32f * (_e1335 - _e1331)));
                                                    phi_2012_ = select(select(u32(_e1346), 0u, (_e1346 < 0f)), 4294967295u, (_e1346 > 4294967000f));
                                                    phi_2013_ = true;
                                                }
                                                let _e1370 = phi_2012_;
                                                let _e1372 = phi_2013_;
                                                if _e1372 {
                                                    if (_e1342 >= 32u) {
                                                        phi_2036_ = u32();
                                                        phi_2037_ = true;
                                                    } else {
                                                        let _e1374 = (_e1370 == 0u);
                                                        if _e1374 {
                                                            phi_2035_ = u32();
                                                        } else {
                                                            if (_e1370 >= 32u) {
                                                                phi_2032_ = 4294967295u;
                                                            } else {
                                                                phi_2032_ = ((1u << bitcast<u32>((_e1370 & 31u))) - 1u);
                                                            }
                                                            let _e1381 = phi_2032_;
                                                            phi_2035_ = (_e1381 << bitcast<u32>((_e1342 & 31u)));
                                                        }
                                                        let _e1386 = phi_2035_;
                                                        phi_2036_ = _e1386;
                                                        phi_2037_ = _e1374;
                                                    }
                                                    let _e1388 = phi_2036_;
                                                    let _e1390 = phi_2037_;
                                                    phi_2042_ = select(_e1388, 0u, _e1390);
                                                } else {
                                                    phi_2042_ = 0u;
                                                }
                                                let _e1393 = phi_2042_;
                                                phi_2043_ = _e1393;
                                            }
                                            let _e1395 = phi_2043_;
                                            phi_2044_ = _e1395;
                                        } else {
                                            phi_2044_ = 0u;
                                        }
                                        let _e1397 = phi_2044_;
                                        phi_1166_ = (_e674 + 1u);
                                        phi_1169_ = ((_e676 | _e1161) | _e1397);
                                    } else {
                                        phi_1166_ = u32();
                                        phi_1169_ = u32();
                                    }
                                    let _e1401 = phi_1166_;
                                    let _e1403 = phi_1169_;
                                    continue;
                                    continuing {
                                        phi_1165_ = _e1401;
                                        phi_1168_ = _e1403;
                                        phi_2845_ = _e580;
                                        break if !(_e677);
                                    }
                                }
                                let _e1406 = phi_2845_;
                                phi_3017_ = _e1406;
                                if _e1406 {
                                    break;
                                }
                                let _e1409 = params.member.member_2;
                                if (_e1409 == 2u) {
                                    let _e1465 = (_e666 - 1.5707964f);
                                    let _e1466 = (_e1465 * 2f);
                                    let _e1467 = sin(_e666);
                                    let _e1472 = ((_e664 + (_e1466 * _e1467)) - cos((_e1466 - _e666)));
                                    if (_e1465 < 0f) {
                                        phi_2073_ = (_e1472 * -0.25f);
                                    } else {
                                        phi_2073_ = (_e1472 * 0.25f);
                                    }
                                    let _e1477 = phi_2073_;
                                    phi_2075_ = 0u;
                                    phi_2078_ = _e1477;
                                    phi_2080_ = 0f;
                                    loop {
                                        let _e1479 = phi_2075_;
                                        let _e1481 = phi_2078_;
                                        let _e1483 = phi_2080_;
                                        local_8 = _e1483;
                                        let _e1484 = (_e1479 < 32u);
                                        if _e1484 {
                                            let _e1485 = (_e1479 + 1u);
                                            let _e1488 = (_e1465 + (f32(_e1485) * 0.09817477f));
                                            let _e1489 = (_e1488 * 2f);
                                            let _e1494 = ((_e664 + (_e1489 * _e1467)) - cos((_e1489 - _e666)));
                                            if (_e1488 < 0f) {
                                                phi_2106_ = (_e1494 * -0.25f);
                                            } else {
                                                phi_2106_ = (_e1494 * 0.25f);
                                            }
                                            let _e1499 = phi_2106_;
                                            let _e1502 = local_7;
                                            if (((_e1502 >> bitcast<u32>((_e1479 & 31u))) & 1u) == 0u) {
                                                phi_2116_ = (_e1483 + (_e1499 - _e1481));
                                            } else {
                                                phi_2116_ = _e1483;
                                            }
                                            let _e1510 = phi_2116_;
                                            phi_2076_ = _e1485;
                                            phi_2079_ = _e1499;
                                            phi_2081_ = _e1510;
                                        } else {
                                            phi_2076_ = u32();
                                            phi_2079_ = f32();
                                            phi_2081_ = f32();
                                        }
                                        let _e1512 = phi_2076_;
                                        let _e1514 = phi_2079_;
                                        let _e1516 = phi_2081_;
                                        continue;
                                        continuing {
                                            phi_2075_ = _e1512;
                                            phi_2078_ = _e1514;
                                            phi_2080_ = _e1516;
                                            break if !(_e1484);
                                        }
                                    }
                                    let _e1519 = local_8;
                                    phi_3019_ = _e1406;
                                    phi_2180_ = (_e584 + 1f);
                                    phi_2181_ = (_e586 + ((_e645 + ((1f - _e645) * 0.05f)) * _e1519));
                                } else {
                                    if (_e1409 == 1u) {
                                        phi_2128_ = 0u;
                                        phi_2131_ = 0f;
                                        loop {
                                            let _e1421 = phi_2128_;
                                            let _e1423 = phi_2131_;
                                            local_6 = _e1423;
                                            let _e1424 = (_e1421 < 4u);
                                            if _e1424 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1424 {
                                                } else {
                                                    phi_3014_ = true;
                                                    break;
                                                }
                                                let _e1427 = local[_e1421].member;
                                                let _e1430 = local[_e1421].member_1;
                                                let _e1432 = local_5;
                                                phi_2129_ = (_e1421 + 1u);
                                                phi_2132_ = (_e1423 + (f32(countOneBits((_e1432 & _e1427))) * _e1430));
                                            } else {
                                                phi_2129_ = u32();
                                                phi_2132_ = f32();
                                            }
                                            let _e1440 = phi_2129_;
                                            let _e1442 = phi_2132_;
                                            continue;
                                            continuing {
                                                phi_2128_ = _e1440;
                                                phi_2131_ = _e1442;
                                                phi_3014_ = _e1406;
                                                break if !(_e1424);
                                            }
                                        }
                                        let _e1445 = phi_3014_;
                                        phi_3017_ = _e1445;
                                        if _e1445 {
                                            break;
                                        }
                                        let _e1447 = local_6;
                                        let _e1448 = (1f - _e1447);
                                        phi_3025_ = _e1445;
                                        phi_2178_ = (_e584 + _e645);
                                        phi_2179_ = (_e586 + (_e645 * select(0f, select(1f, _e1448, (_e1448 < 1f)), (_e1448 > 0f))));
                                    } else {
                                        let _e1413 = local_4;
                                        phi_3025_ = _e1406;
                                        phi_2178_ = (_e584 + 1f);
                                        phi_2179_ = (_e586 + (1f - (f32(countOneBits(_e1413)) * 0.03125f)));
                                    }
                                    let _e1457 = phi_3025_;
                                    let _e1459 = phi_2178_;
                                    let _e1461 = phi_2179_;
                                    phi_3019_ = _e1457;
                                    phi_2180_ = _e1459;
                                    phi_2181_ = _e1461;
                                }
                                let _e1524 = phi_3019_;
                                let _e1526 = phi_2180_;
                                let _e1528 = phi_2181_;
                                phi_3018_ = _e1524;
                                phi_991_ = (_e582 + 1u);
                                phi_994_ = _e1526;
                                phi_996_ = _e1528;
                            } else {
                                phi_3018_ = _e580;
                                phi_991_ = u32();
                                phi_994_ = f32();
                                phi_996_ = f32();
                            }
                            let _e1531 = phi_3018_;
                            let _e1533 = phi_991_;
                            let _e1535 = phi_994_;
                            let _e1537 = phi_996_;
                            continue;
                            continuing {
                                phi_2897_ = _e1531;
                                phi_990_ = _e1533;
                                phi_993_ = _e1535;
                                phi_995_ = _e1537;
                                phi_3017_ = _e1531;
                                break if !(_e587);
                            }
                        }
                        let _e1540 = phi_3017_;
                        if _e1540 {
                            break;
                        }
                        let _e1542 = local_9;
                        if (_e1542 > 0f) {
                            let _e1545 = local_10;
                            let _e1547 = local_11;
                            phi_2188_ = (_e1545 / _e1547);
                        } else {
                            phi_2188_ = 1f;
                        }
                        let _e1550 = phi_2188_;
                        let _e1554 = params.member.member_4.member_6;
                        let _e1555 = pow(_e1550, _e1554);
                        if (_e1555 != _e1555) {
                            phi_2815_ = true;
                        } else {
                            phi_2815_ = (0.03f >= _e1555);
                        }
                        let _e1559 = phi_2815_;
                        let _e1561 = (select(_e1555, 0.03f, _e1559) * 0.6666667f);
                        let _e1567 = ((select(0f, select(1f, _e1561, (_e1561 < 1f)), (_e1561 > 0f)) * 255f) + 0.5f);
                        phi_2236_ = type_28(select(select(u32(_e1567), 0u, (_e1567 < 0f)), 4294967295u, (_e1567 > 4294967000f)), _e374);
                    } else {
                        phi_2236_ = type_28(170u, _e374);
                    }
                    let _e1575 = phi_2236_;
                    if (_e119 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e119] = _e1575.member;
                    if (_e119 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e119] = _e1575.member_1;
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
