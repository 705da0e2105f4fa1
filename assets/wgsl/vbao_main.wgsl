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
    var phi_483_: i32;
    var phi_502_: i32;
    var phi_543_: i32;
    var phi_562_: i32;
    var phi_603_: i32;
    var phi_622_: i32;
    var phi_663_: i32;
    var phi_682_: i32;
    var phi_2431_: bool;
    var phi_2446_: bool;
    var phi_2461_: bool;
    var phi_2476_: bool;
    var phi_2507_: f32;
    var phi_2511_: f32;
    var phi_2512_: bool;
    var phi_2534_: u32;
    var phi_2561_: f32;
    var phi_2565_: f32;
    var phi_2566_: bool;
    var phi_2588_: u32;
    var phi_2615_: f32;
    var phi_2619_: f32;
    var phi_2620_: bool;
    var phi_2642_: u32;
    var phi_2669_: f32;
    var phi_2673_: f32;
    var phi_2674_: bool;
    var phi_2696_: u32;
    var phi_2775_: bool;
    var phi_2790_: bool;
    var phi_2751_: vec2<f32>;
    var phi_2807_: u32;
    var phi_2808_: u32;
    var phi_2809_: u32;
    var phi_2810_: u32;
    var phi_2833_: u32;
    var phi_2834_: u32;
    var phi_2837_: u32;
    var phi_2838_: u32;
    var phi_2842_: u32;
    var phi_2843_: u32;
    var phi_2844_: u32;
    var phi_2845_: u32;
    var local_1: u32;
    var phi_3185_: bool;
    var phi_934_: u32;
    var phi_937_: f32;
    var phi_939_: f32;
    var phi_1109_: u32;
    var phi_1112_: u32;
    var phi_1166_: f32;
    var phi_1211_: f32;
    var phi_1213_: f32;
    var phi_1214_: bool;
    var phi_1237_: f32;
    var phi_1239_: f32;
    var phi_1240_: bool;
    var phi_1273_: u32;
    var phi_1289_: u32;
    var phi_1292_: u32;
    var phi_1290_: u32;
    var phi_1293_: u32;
    var phi_1337_: u32;
    var phi_1356_: u32;
    var local_2: u32;
    var phi_1400_: u32;
    var phi_1416_: u32;
    var phi_1419_: u32;
    var phi_1417_: u32;
    var phi_1420_: u32;
    var phi_1464_: u32;
    var phi_1483_: u32;
    var local_3: u32;
    var phi_1532_: bool;
    var phi_2879_: bool;
    var phi_2894_: bool;
    var phi_2909_: bool;
    var phi_2924_: bool;
    var phi_2939_: bool;
    var phi_1778_: f32;
    var phi_1796_: u32;
    var phi_1814_: u32;
    var phi_1830_: u32;
    var phi_1833_: u32;
    var phi_1834_: u32;
    var phi_1835_: bool;
    var phi_1849_: u32;
    var phi_1873_: bool;
    var phi_2954_: bool;
    var phi_2969_: bool;
    var phi_2984_: bool;
    var phi_2999_: bool;
    var phi_3014_: bool;
    var phi_2119_: f32;
    var phi_2137_: u32;
    var phi_2155_: u32;
    var phi_2171_: u32;
    var phi_2174_: u32;
    var phi_2175_: u32;
    var phi_2176_: bool;
    var phi_2190_: u32;
    var phi_1110_: u32;
    var phi_1113_: u32;
    var phi_3073_: bool;
    var local_4: u32;
    var phi_2274_: u32;
    var phi_2277_: f32;
    var local_5: u32;
    var phi_2275_: u32;
    var phi_2278_: f32;
    var phi_3266_: bool;
    var local_6: f32;
    var phi_3277_: bool;
    var phi_2327_: f32;
    var phi_2328_: f32;
    var phi_2221_: u32;
    var phi_2224_: f32;
    var phi_2226_: f32;
    var local_7: u32;
    var phi_2222_: u32;
    var phi_2225_: f32;
    var phi_2227_: f32;
    var local_8: f32;
    var phi_3271_: bool;
    var phi_2329_: f32;
    var phi_2330_: f32;
    var phi_3270_: bool;
    var phi_935_: u32;
    var phi_938_: f32;
    var phi_940_: f32;
    var phi_3269_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var phi_2338_: f32;
    var phi_3047_: bool;
    var phi_2387_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e84 = id_1;
            let _e87 = arrayLength((&mips.member));
            let _e99 = params.member.member_4.member.member[0u];
            let _e104 = select(select(u32(_e99), 0u, (_e99 < 0f)), 4294967295u, (_e99 > 4294967000f));
            let _e110 = params.member.member_4.member.member[1u];
            let _e115 = select(select(u32(_e110), 0u, (_e110 < 0f)), 4294967295u, (_e110 > 4294967000f));
            if (_e84.x >= _e104) {
            } else {
                if (_e84.y >= _e115) {
                } else {
                    let _e121 = ((_e84.y * _e104) + _e84.x);
                    if (_e121 < _e87) {
                    } else {
                        break;
                    }
                    let _e124 = mips.member[_e121];
                    let _e125 = bitcast<i32>(_e84.x);
                    let _e126 = (_e125 + -1i);
                    let _e128 = (bitcast<i32>(_e104) - 1i);
                    let _e129 = (0i <= _e128);
                    if _e129 {
                    } else {
                        break;
                    }
                    if (_e126 < 0i) {
                        phi_483_ = 0i;
                    } else {
                        phi_483_ = select(_e126, _e128, (_e126 > _e128));
                    }
                    let _e134 = phi_483_;
                    let _e136 = bitcast<i32>(_e84.y);
                    let _e138 = (bitcast<i32>(_e115) - 1i);
                    let _e139 = (0i <= _e138);
                    if _e139 {
                    } else {
                        break;
                    }
                    let _e140 = (_e136 < 0i);
                    if _e140 {
                        phi_502_ = 0i;
                    } else {
                        phi_502_ = select(_e136, _e138, (_e136 > _e138));
                    }
                    let _e144 = phi_502_;
                    let _e147 = ((bitcast<u32>(_e144) * _e104) + bitcast<u32>(_e134));
                    if (_e147 < _e87) {
                    } else {
                        break;
                    }
                    let _e150 = mips.member[_e147];
                    let _e151 = (_e125 + 1i);
                    if _e129 {
                    } else {
                        break;
                    }
                    if (_e151 < 0i) {
                        phi_543_ = 0i;
                    } else {
                        phi_543_ = select(_e151, _e128, (_e151 > _e128));
                    }
                    let _e156 = phi_543_;
                    if _e139 {
                    } else {
                        break;
                    }
                    if _e140 {
                        phi_562_ = 0i;
                    } else {
                        phi_562_ = select(_e136, _e138, (_e136 > _e138));
                    }
                    let _e161 = phi_562_;
                    let _e164 = ((bitcast<u32>(_e161) * _e104) + bitcast<u32>(_e156));
                    if (_e164 < _e87) {
                    } else {
                        break;
                    }
                    let _e167 = mips.member[_e164];
                    if _e129 {
                    } else {
                        break;
                    }
                    let _e168 = (_e125 < 0i);
                    if _e168 {
                        phi_603_ = 0i;
                    } else {
                        phi_603_ = select(_e125, _e128, (_e125 > _e128));
                    }
                    let _e172 = phi_603_;
                    let _e174 = (_e136 + -1i);
                    if _e139 {
                    } else {
                        break;
                    }
                    if (_e174 < 0i) {
                        phi_622_ = 0i;
                    } else {
                        phi_622_ = select(_e174, _e138, (_e174 > _e138));
                    }
                    let _e179 = phi_622_;
                    let _e182 = ((bitcast<u32>(_e179) * _e104) + bitcast<u32>(_e172));
                    if (_e182 < _e87) {
                    } else {
                        break;
                    }
                    let _e185 = mips.member[_e182];
                    if _e129 {
                    } else {
                        break;
                    }
                    if _e168 {
                        phi_663_ = 0i;
                    } else {
                        phi_663_ = select(_e125, _e128, (_e125 > _e128));
                    }
                    let _e189 = phi_663_;
                    let _e191 = (_e136 + 1i);
                    if _e139 {
                    } else {
                        break;
                    }
                    if (_e191 < 0i) {
                        phi_682_ = 0i;
                    } else {
                        phi_682_ = select(_e191, _e138, (_e191 > _e138));
                    }
                    let _e196 = phi_682_;
                    let _e199 = ((bitcast<u32>(_e196) * _e104) + bitcast<u32>(_e189));
                    if (_e199 < _e87) {
                    } else {
                        break;
                    }
                    let _e202 = mips.member[_e199];
                    let _e203 = (_e150 - _e124);
                    let _e204 = (_e167 - _e124);
                    let _e205 = (_e185 - _e124);
                    let _e206 = (_e202 - _e124);
                    let _e208 = ((_e204 - _e203) * 0.5f);
                    let _e210 = ((_e206 - _e205) * 0.5f);
                    let _e211 = (_e124 * 0.011f);
                    let _e213 = abs(_e203);
                    let _e214 = abs((_e203 + _e208));
                    if (_e213 != _e213) {
                        phi_2431_ = true;
                    } else {
                        phi_2431_ = (_e214 <= _e213);
                    }
                    let _e218 = phi_2431_;
                    let _e221 = (1.25f - (select(_e213, _e214, _e218) / _e211));
                    let _e225 = select(0f, select(1f, _e221, (_e221 < 1f)), (_e221 > 0f));
                    let _e227 = abs(_e204);
                    let _e228 = abs((_e204 - _e208));
                    if (_e227 != _e227) {
                        phi_2446_ = true;
                    } else {
                        phi_2446_ = (_e228 <= _e227);
                    }
                    let _e232 = phi_2446_;
                    let _e235 = (1.25f - (select(_e227, _e228, _e232) / _e211));
                    let _e239 = select(0f, select(1f, _e235, (_e235 < 1f)), (_e235 > 0f));
                    let _e241 = abs(_e205);
                    let _e242 = abs((_e205 + _e210));
                    if (_e241 != _e241) {
                        phi_2461_ = true;
                    } else {
                        phi_2461_ = (_e242 <= _e241);
                    }
                    let _e246 = phi_2461_;
                    let _e249 = (1.25f - (select(_e241, _e242, _e246) / _e211));
                    let _e253 = select(0f, select(1f, _e249, (_e249 < 1f)), (_e249 > 0f));
                    let _e255 = abs(_e206);
                    let _e256 = abs((_e206 - _e210));
                    if (_e255 != _e255) {
                        phi_2476_ = true;
                    } else {
                        phi_2476_ = (_e256 <= _e255);
                    }
                    let _e260 = phi_2476_;
                    let _e263 = (1.25f - (select(_e255, _e256, _e260) / _e211));
                    let _e267 = select(0f, select(1f, _e263, (_e263 < 1f)), (_e263 > 0f));
                    let _e272 = (select(0f, select(1f, _e225, (_e225 < 1f)), (_e225 > 0f)) * 2.9f);
                    let _e274 = floor((_e272 + 0.5f));
                    if ((_e274 - _e272) == 0.5f) {
                        let _e280 = ((floor((_e274 * 0.5f)) * 2f) != _e274);
                        if _e280 {
                            phi_2507_ = (_e274 - 1f);
                        } else {
                            phi_2507_ = f32();
                        }
                        let _e283 = phi_2507_;
                        phi_2511_ = _e283;
                        phi_2512_ = select(true, false, _e280);
                    } else {
                        phi_2511_ = f32();
                        phi_2512_ = true;
                    }
                    let _e286 = phi_2511_;
                    let _e288 = phi_2512_;
                    let _e289 = select(_e286, _e274, _e288);
                    if (_e289 > 0f) {
                        let _e295 = select(select(u32(_e289), 0u, (_e289 < 0f)), 4294967295u, (_e289 > 4294967000f));
                        phi_2534_ = select(_e295, 3u, (3u < _e295));
                    } else {
                        phi_2534_ = 0u;
                    }
                    let _e299 = phi_2534_;
                    let _e305 = (select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f)) * 2.9f);
                    let _e307 = floor((_e305 + 0.5f));
                    if ((_e307 - _e305) == 0.5f) {
                        let _e313 = ((floor((_e307 * 0.5f)) * 2f) != _e307);
                        if _e313 {
                            phi_2561_ = (_e307 - 1f);
                        } else {
                            phi_2561_ = f32();
                        }
                        let _e316 = phi_2561_;
                        phi_2565_ = _e316;
                        phi_2566_ = select(true, false, _e313);
                    } else {
                        phi_2565_ = f32();
                        phi_2566_ = true;
                    }
                    let _e319 = phi_2565_;
                    let _e321 = phi_2566_;
                    let _e322 = select(_e319, _e307, _e321);
                    if (_e322 > 0f) {
                        let _e328 = select(select(u32(_e322), 0u, (_e322 < 0f)), 4294967295u, (_e322 > 4294967000f));
                        phi_2588_ = select(_e328, 3u, (3u < _e328));
                    } else {
                        phi_2588_ = 0u;
                    }
                    let _e332 = phi_2588_;
                    let _e339 = (select(0f, select(1f, _e253, (_e253 < 1f)), (_e253 > 0f)) * 2.9f);
                    let _e341 = floor((_e339 + 0.5f));
                    if ((_e341 - _e339) == 0.5f) {
                        let _e347 = ((floor((_e341 * 0.5f)) * 2f) != _e341);
                        if _e347 {
                            phi_2615_ = (_e341 - 1f);
                        } else {
                            phi_2615_ = f32();
                        }
                        let _e350 = phi_2615_;
                        phi_2619_ = _e350;
                        phi_2620_ = select(true, false, _e347);
                    } else {
                        phi_2619_ = f32();
                        phi_2620_ = true;
                    }
                    let _e353 = phi_2619_;
                    let _e355 = phi_2620_;
                    let _e356 = select(_e353, _e341, _e355);
                    if (_e356 > 0f) {
                        let _e362 = select(select(u32(_e356), 0u, (_e356 < 0f)), 4294967295u, (_e356 > 4294967000f));
                        phi_2642_ = select(_e362, 3u, (3u < _e362));
                    } else {
                        phi_2642_ = 0u;
                    }
                    let _e366 = phi_2642_;
                    let _e373 = (select(0f, select(1f, _e267, (_e267 < 1f)), (_e267 > 0f)) * 2.9f);
                    let _e375 = floor((_e373 + 0.5f));
                    if ((_e375 - _e373) == 0.5f) {
                        let _e381 = ((floor((_e375 * 0.5f)) * 2f) != _e375);
                        if _e381 {
                            phi_2669_ = (_e375 - 1f);
                        } else {
                            phi_2669_ = f32();
                        }
                        let _e384 = phi_2669_;
                        phi_2673_ = _e384;
                        phi_2674_ = select(true, false, _e381);
                    } else {
                        phi_2673_ = f32();
                        phi_2674_ = true;
                    }
                    let _e387 = phi_2673_;
                    let _e389 = phi_2674_;
                    let _e390 = select(_e387, _e375, _e389);
                    if (_e390 > 0f) {
                        let _e396 = select(select(u32(_e390), 0u, (_e390 < 0f)), 4294967295u, (_e390 > 4294967000f));
                        phi_2696_ = select(_e396, 3u, (3u < _e396));
                    } else {
                        phi_2696_ = 0u;
                    }
                    let _e400 = phi_2696_;
                    let _e404 = ((f32(_e84.x) + 0.5f) / _e99);
                    let _e407 = ((f32(_e84.y) + 0.5f) / _e110);
                    let _e408 = (_e124 * 0.99999f);
                    let _e416 = params.member.member_4.member.member_1[0u];
                    let _e418 = ((((_e404 * 2f) - 1f) * _e416) * _e408);
                    let _e426 = params.member.member_4.member.member_1[1u];
                    let _e428 = ((((_e407 * -2f) + 1f) * _e426) * _e408);
                    let _e429 = -(_e418);
                    let _e430 = -(_e428);
                    let _e431 = (_e124 * -0.99999f);
                    let _e438 = (1f / sqrt((((_e429 * _e429) + (_e430 * _e430)) + (_e431 * _e431))));
                    let _e439 = (_e429 * _e438);
                    let _e440 = (_e430 * _e438);
                    let _e441 = (_e431 * _e438);
                    if (_e121 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e445 = normals.member[_e121];
                    let _e453 = (f32((bitcast<i32>(((_e445 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e453 != _e453) {
                        phi_2775_ = true;
                    } else {
                        phi_2775_ = (-1f >= _e453);
                    }
                    let _e457 = phi_2775_;
                    let _e458 = select(_e453, -1f, _e457);
                    let _e468 = (f32((bitcast<i32>((((_e445 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e468 != _e468) {
                        phi_2790_ = true;
                    } else {
                        phi_2790_ = (-1f >= _e468);
                    }
                    let _e472 = phi_2790_;
                    let _e473 = select(_e468, -1f, _e472);
                    let _e476 = (1f - abs(_e458));
                    let _e477 = abs(_e473);
                    let _e478 = (_e476 - _e477);
                    if (_e478 < 0f) {
                        phi_2751_ = vec2<f32>(((1f - _e477) * select(1f, -1f, (_e458 < 0f))), (_e476 * select(1f, -1f, (_e473 < 0f))));
                    } else {
                        phi_2751_ = vec2<f32>(_e458, _e473);
                    }
                    let _e489 = phi_2751_;
                    let _e498 = (1f / sqrt((((_e489.x * _e489.x) + (_e489.y * _e489.y)) + (_e478 * _e478))));
                    let _e499 = (_e489.x * _e498);
                    let _e500 = (_e489.y * _e498);
                    let _e501 = (_e478 * _e498);
                    let _e502 = -(_e501);
                    let _e508 = ((((_e499 * _e439) + (_e500 * _e440)) + (_e502 * _e441)) < 0f);
                    let _e511 = select(_e499, -(_e499), _e508);
                    let _e512 = select(_e500, -(_e500), _e508);
                    let _e513 = select(_e502, _e501, _e508);
                    let _e517 = params.member.member_4.member_1;
                    let _e521 = params.member.member_4.member_2;
                    let _e526 = ((_e517 * _e521) / (((_e124 * 1.99998f) * _e416) / _e99));
                    let _e531 = params.member.member_4.member_11;
                    phi_2807_ = (_e84.y & 63u);
                    phi_2808_ = (_e84.x & 63u);
                    phi_2809_ = 32u;
                    phi_2810_ = 0u;
                    loop {
                        let _e535 = phi_2807_;
                        let _e537 = phi_2808_;
                        let _e539 = phi_2809_;
                        let _e541 = phi_2810_;
                        local_1 = _e541;
                        let _e542 = (_e539 > 0u);
                        if _e542 {
                            let _e545 = select(0u, 1u, ((_e537 & _e539) != 0u));
                            let _e548 = select(0u, 1u, ((_e535 & _e539) != 0u));
                            if (_e548 == 0u) {
                                if (_e545 == 1u) {
                                    phi_2833_ = (63u - _e535);
                                    phi_2834_ = (63u - _e537);
                                } else {
                                    phi_2833_ = _e535;
                                    phi_2834_ = _e537;
                                }
                                let _e559 = phi_2833_;
                                let _e561 = phi_2834_;
                                phi_2837_ = _e561;
                                phi_2838_ = _e559;
                            } else {
                                phi_2837_ = _e535;
                                phi_2838_ = _e537;
                            }
                            let _e563 = phi_2837_;
                            let _e565 = phi_2838_;
                            phi_2842_ = _e563;
                            phi_2843_ = _e565;
                            phi_2844_ = (_e539 / 2u);
                            phi_2845_ = (_e541 + ((_e539 * _e539) * ((3u * _e545) ^ _e548)));
                        } else {
                            phi_2842_ = u32();
                            phi_2843_ = u32();
                            phi_2844_ = u32();
                            phi_2845_ = u32();
                        }
                        let _e568 = phi_2842_;
                        let _e570 = phi_2843_;
                        let _e572 = phi_2844_;
                        let _e574 = phi_2845_;
                        continue;
                        continuing {
                            phi_2807_ = _e568;
                            phi_2808_ = _e570;
                            phi_2809_ = _e572;
                            phi_2810_ = _e574;
                            break if !(_e542);
                        }
                    }
                    let _e579 = local_1;
                    let _e581 = f32((_e579 + (288u * (_e531 % 64u))));
                    let _e583 = (0.5f + (_e581 * 0.7548777f));
                    let _e587 = (0.5f + (_e581 * 0.5698403f));
                    let _e594 = params.member.member_4.member.member_3;
                    let _e597 = select(false, (_e124 < _e594), (_e124 > 0f));
                    if _e597 {
                        let _e601 = params.member.member_4.member_8;
                        let _e603 = select(1u, _e601, (1u < _e601));
                        phi_3185_ = false;
                        phi_934_ = 0u;
                        phi_937_ = 0f;
                        phi_939_ = 0f;
                        loop {
                            let _e605 = phi_3185_;
                            let _e607 = phi_934_;
                            let _e609 = phi_937_;
                            let _e611 = phi_939_;
                            local_9 = _e609;
                            local_10 = _e611;
                            local_11 = _e609;
                            let _e612 = (_e607 < _e603);
                            if _e612 {
                                let _e617 = ((((_e583 - floor(_e583)) + f32(_e607)) * 3.1415927f) / f32(_e603));
                                let _e618 = sin(_e617);
                                let _e619 = cos(_e617);
                                let _e625 = ((_e619 * _e439) + (_e618 * _e440));
                                let _e629 = (_e619 - (_e439 * _e625));
                                let _e630 = (_e618 - (_e440 * _e625));
                                let _e631 = -((_e441 * _e625));
                                let _e634 = ((_e630 * _e441) - (_e440 * _e631));
                                let _e637 = ((_e631 * _e439) - (_e441 * _e629));
                                let _e640 = ((_e629 * _e440) - (_e439 * _e630));
                                let _e647 = (1f / sqrt((((_e634 * _e634) + (_e637 * _e637)) + (_e640 * _e640))));
                                let _e648 = (_e634 * _e647);
                                let _e649 = (_e637 * _e647);
                                let _e650 = (_e640 * _e647);
                                let _e655 = (((_e511 * _e648) + (_e512 * _e649)) + (_e513 * _e650));
                                let _e659 = (_e511 - (_e648 * _e655));
                                let _e660 = (_e512 - (_e649 * _e655));
                                let _e661 = (_e513 - (_e650 * _e655));
                                let _e667 = sqrt((((_e659 * _e659) + (_e660 * _e660)) + (_e661 * _e661)));
                                let _e672 = (((_e629 * _e659) + (_e630 * _e660)) + (_e631 * _e661));
                                let _e682 = ((((_e659 * _e439) + (_e660 * _e440)) + (_e661 * _e441)) / _e667);
                                let _e686 = select(0f, select(1f, _e682, (_e682 < 1f)), (_e682 > 0f));
                                let _e688 = (select(select(0f, -1f, (_e672 < 0f)), 1f, (_e672 > 0f)) * acos(_e686));
                                let _e692 = params.member.member_4.member_9;
                                let _e694 = select(1u, _e692, (1u < _e692));
                                phi_1109_ = 0u;
                                phi_1112_ = 0u;
                                loop {
                                    let _e696 = phi_1109_;
                                    let _e698 = phi_1112_;
                                    local_4 = _e698;
                                    local_5 = _e698;
                                    local_7 = _e698;
                                    let _e699 = (_e696 < _e694);
                                    if _e699 {
                                        let _e704 = ((_e587 - floor(_e587)) + (f32((_e607 + (_e696 * _e694))) * 0.618034f));
                                        let _e710 = (((_e704 - floor(_e704)) + f32(_e696)) / f32(_e694));
                                        let _e714 = params.member.member_4.member_4;
                                        if (_e714 == 2f) {
                                            phi_1166_ = (_e710 * _e710);
                                        } else {
                                            phi_1166_ = pow(_e710, _e714);
                                        }
                                        let _e719 = phi_1166_;
                                        let _e720 = (_e719 + (1.3f / _e526));
                                        let _e721 = ((_e619 * _e526) * _e720);
                                        let _e722 = ((-(_e618) * _e526) * _e720);
                                        let _e731 = params.member.member_4.member_7;
                                        let _e732 = (log2(sqrt(((_e721 * _e721) + (_e722 * _e722)))) - _e731);
                                        let _e739 = (-1f - floor((-0.5f - select(0f, select(5f, _e732, (_e732 < 5f)), (_e732 > 0f)))));
                                        let _e741 = floor((_e721 + 0.5f));
                                        if ((_e741 - _e721) == 0.5f) {
                                            let _e747 = ((floor((_e741 * 0.5f)) * 2f) != _e741);
                                            if _e747 {
                                                phi_1211_ = (_e741 - 1f);
                                            } else {
                                                phi_1211_ = f32();
                                            }
                                            let _e750 = phi_1211_;
                                            phi_1213_ = _e750;
                                            phi_1214_ = select(true, false, _e747);
                                        } else {
                                            phi_1213_ = f32();
                                            phi_1214_ = true;
                                        }
                                        let _e753 = phi_1213_;
                                        let _e755 = phi_1214_;
                                        let _e757 = (select(_e753, _e741, _e755) / _e99);
                                        let _e759 = floor((_e722 + 0.5f));
                                        if ((_e759 - _e722) == 0.5f) {
                                            let _e765 = ((floor((_e759 * 0.5f)) * 2f) != _e759);
                                            if _e765 {
                                                phi_1237_ = (_e759 - 1f);
                                            } else {
                                                phi_1237_ = f32();
                                            }
                                            let _e768 = phi_1237_;
                                            phi_1239_ = _e768;
                                            phi_1240_ = select(true, false, _e765);
                                        } else {
                                            phi_1239_ = f32();
                                            phi_1240_ = true;
                                        }
                                        let _e771 = phi_1239_;
                                        let _e773 = phi_1240_;
                                        let _e775 = (select(_e771, _e759, _e773) / _e110);
                                        let _e776 = (_e404 + _e757);
                                        let _e777 = (_e407 + _e775);
                                        let _e778 = (_e404 - _e757);
                                        let _e779 = (_e407 - _e775);
                                        let _e780 = (_e739 > 0f);
                                        if _e780 {
                                            let _e785 = select(select(u32(_e739), 0u, (_e739 < 0f)), 4294967295u, (_e739 > 4294967000f));
                                            phi_1273_ = select(_e785, 4u, (4u < _e785));
                                        } else {
                                            phi_1273_ = 0u;
                                        }
                                        let _e789 = phi_1273_;
                                        let _e790 = (_e789 & 31u);
                                        let _e792 = (_e104 >> bitcast<u32>(_e790));
                                        let _e794 = select(1u, _e792, (1u < _e792));
                                        let _e796 = (_e115 >> bitcast<u32>(_e790));
                                        let _e798 = select(1u, _e796, (1u < _e796));
                                        phi_1289_ = 0u;
                                        phi_1292_ = 0u;
                                        loop {
                                            let _e800 = phi_1289_;
                                            let _e802 = phi_1292_;
                                            local_2 = _e802;
                                            let _e803 = (_e800 < _e789);
                                            if _e803 {
                                                let _e804 = (_e800 & 31u);
                                                let _e806 = (_e104 >> bitcast<u32>(_e804));
                                                let _e810 = (_e115 >> bitcast<u32>(_e804));
                                                phi_1290_ = (_e800 + 1u);
                                                phi_1293_ = (_e802 + (select(1u, _e806, (1u < _e806)) * select(1u, _e810, (1u < _e810))));
                                            } else {
                                                phi_1290_ = u32();
                                                phi_1293_ = u32();
                                            }
                                            let _e817 = phi_1290_;
                                            let _e819 = phi_1293_;
                                            continue;
                                            continuing {
                                                phi_1289_ = _e817;
                                                phi_1292_ = _e819;
                                                break if !(_e803);
                                            }
                                        }
                                        let _e823 = (_e776 * f32(_e794));
                                        if (_e823 > 0f) {
                                            let _e829 = select(select(u32(_e823), 0u, (_e823 < 0f)), 4294967295u, (_e823 > 4294967000f));
                                            let _e830 = (_e794 - 1u);
                                            phi_1337_ = select(_e829, _e830, (_e830 < _e829));
                                        } else {
                                            phi_1337_ = 0u;
                                        }
                                        let _e834 = phi_1337_;
                                        let _e835 = (_e777 * f32(_e798));
                                        if (_e835 > 0f) {
                                            let _e841 = select(select(u32(_e835), 0u, (_e835 < 0f)), 4294967295u, (_e835 > 4294967000f));
                                            let _e842 = (_e798 - 1u);
                                            phi_1356_ = select(_e841, _e842, (_e842 < _e841));
                                        } else {
                                            phi_1356_ = 0u;
                                        }
                                        let _e846 = phi_1356_;
                                        let _e849 = local_2;
                                        let _e851 = ((_e849 + (_e846 * _e794)) + _e834);
                                        if (_e851 < _e87) {
                                        } else {
                                            phi_3073_ = true;
                                            break;
                                        }
                                        let _e855 = mips.member[_e851];
                                        if _e780 {
                                            let _e868 = select(select(u32(_e739), 0u, (_e739 < 0f)), 4294967295u, (_e739 > 4294967000f));
                                            phi_1400_ = select(_e868, 4u, (4u < _e868));
                                        } else {
                                            phi_1400_ = 0u;
                                        }
                                        let _e872 = phi_1400_;
                                        let _e873 = (_e872 & 31u);
                                        let _e875 = (_e104 >> bitcast<u32>(_e873));
                                        let _e877 = select(1u, _e875, (1u < _e875));
                                        let _e879 = (_e115 >> bitcast<u32>(_e873));
                                        let _e881 = select(1u, _e879, (1u < _e879));
                                        phi_1416_ = 0u;
                                        phi_1419_ = 0u;
                                        loop {
                                            let _e883 = phi_1416_;
                                            let _e885 = phi_1419_;
                                            local_3 = _e885;
                                            let _e886 = (_e883 < _e872);
                                            if _e886 {
                                                let _e887 = (_e883 & 31u);
                                                let _e889 = (_e104 >> bitcast<u32>(_e887));
                                                let _e893 = (_e115 >> bitcast<u32>(_e887));
                                                phi_1417_ = (_e883 + 1u);
                                                phi_1420_ = (_e885 + (select(1u, _e889, (1u < _e889)) * select(1u, _e893, (1u < _e893))));
                                            } else {
                                                phi_1417_ = u32();
                                                phi_1420_ = u32();
                                            }
                                            let _e900 = phi_1417_;
                                            let _e902 = phi_1420_;
                                            continue;
                                            continuing {
                                                phi_1416_ = _e900;
                                                phi_1419_ = _e902;
                                                break if !(_e886);
                                            }
                                        }
                                        let _e906 = (_e778 * f32(_e877));
                                        if (_e906 > 0f) {
                                            let _e912 = select(select(u32(_e906), 0u, (_e906 < 0f)), 4294967295u, (_e906 > 4294967000f));
                                            let _e913 = (_e877 - 1u);
                                            phi_1464_ = select(_e912, _e913, (_e913 < _e912));
                                        } else {
                                            phi_1464_ = 0u;
                                        }
                                        let _e917 = phi_1464_;
                                        let _e918 = (_e779 * f32(_e881));
                                        if (_e918 > 0f) {
                                            let _e924 = select(select(u32(_e918), 0u, (_e918 < 0f)), 4294967295u, (_e918 > 4294967000f));
                                            let _e925 = (_e881 - 1u);
                                            phi_1483_ = select(_e924, _e925, (_e925 < _e924));
                                        } else {
                                            phi_1483_ = 0u;
                                        }
                                        let _e929 = phi_1483_;
                                        let _e932 = local_3;
                                        let _e934 = ((_e932 + (_e929 * _e877)) + _e917);
                                        if (_e934 < _e87) {
                                        } else {
                                            phi_3073_ = true;
                                            break;
                                        }
                                        let _e938 = mips.member[_e934];
                                        let _e947 = (((((_e776 * 2f) - 1f) * _e416) * _e855) - _e418);
                                        let _e948 = (((((_e777 * -2f) + 1f) * _e426) * _e855) - _e428);
                                        let _e949 = (_e855 - _e408);
                                        let _e952 = params.member.member_1;
                                        let _e953 = (_e952 > 0f);
                                        if _e953 {
                                            phi_1532_ = (sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))) > _e952);
                                        } else {
                                            phi_1532_ = false;
                                        }
                                        let _e962 = phi_1532_;
                                        if !(_e962) {
                                            let _e966 = params.member.member;
                                            let _e969 = params.member.member_3;
                                            let _e974 = (((_e947 * _e439) + (_e948 * _e440)) + (_e949 * _e441));
                                            let _e978 = (_e947 - (_e439 * _e974));
                                            let _e979 = (_e948 - (_e440 * _e974));
                                            let _e980 = (_e949 - (_e441 * _e974));
                                            let _e989 = ((_e979 * _e441) - (_e440 * _e980));
                                            let _e992 = ((_e980 * _e439) - (_e441 * _e978));
                                            let _e995 = ((_e978 * _e440) - (_e439 * _e979));
                                            let _e1002 = (1f / sqrt((((_e989 * _e989) + (_e992 * _e992)) + (_e995 * _e995))));
                                            let _e1003 = (_e989 * _e1002);
                                            let _e1004 = (_e992 * _e1002);
                                            let _e1005 = (_e995 * _e1002);
                                            let _e1010 = (((_e511 * _e1003) + (_e512 * _e1004)) + (_e513 * _e1005));
                                            let _e1014 = (_e511 - (_e1003 * _e1010));
                                            let _e1015 = (_e512 - (_e1004 * _e1010));
                                            let _e1016 = (_e513 - (_e1005 * _e1010));
                                            let _e1022 = sqrt((((_e1014 * _e1014) + (_e1015 * _e1015)) + (_e1016 * _e1016)));
                                            let _e1028 = ((((_e1014 * _e439) + (_e1015 * _e440)) + (_e1016 * _e441)) / _e1022);
                                            let _e1033 = acos(select(0f, select(1f, _e1028, (_e1028 < 1f)), (_e1028 > 0f)));
                                            let _e1041 = select(_e1033, -(_e1033), ((((_e978 * _e1014) + (_e979 * _e1015)) + (_e980 * _e1016)) < 0f));
                                            let _e1042 = (0.02f / _e1022);
                                            if (_e1042 != _e1042) {
                                                phi_2879_ = true;
                                            } else {
                                                phi_2879_ = (0.19634955f <= _e1042);
                                            }
                                            let _e1046 = phi_2879_;
                                            let _e1047 = select(_e1042, 0.19634955f, _e1046);
                                            let _e1051 = (_e947 - (_e439 * _e966));
                                            let _e1052 = (_e948 - (_e440 * _e966));
                                            let _e1053 = (_e949 - (_e441 * _e966));
                                            let _e1060 = (1f / sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))));
                                            let _e1068 = ((((_e947 * _e1060) * _e439) + ((_e948 * _e1060) * _e440)) + ((_e949 * _e1060) * _e441));
                                            let _e1077 = ((((acos(select(-1f, select(1f, _e1068, (_e1068 < 1f)), (_e1068 > -1f))) + _e1047) - _e1041) + 1.5707964f) * 0.31830987f);
                                            let _e1081 = select(0f, select(1f, _e1077, (_e1077 < 1f)), (_e1077 > 0f));
                                            let _e1088 = (1f / sqrt((((_e1051 * _e1051) + (_e1052 * _e1052)) + (_e1053 * _e1053))));
                                            let _e1096 = ((((_e1051 * _e1088) * _e439) + ((_e1052 * _e1088) * _e440)) + ((_e1053 * _e1088) * _e441));
                                            let _e1105 = ((((acos(select(-1f, select(1f, _e1096, (_e1096 < 1f)), (_e1096 > -1f))) + _e1047) - _e1041) + 1.5707964f) * 0.31830987f);
                                            let _e1109 = select(0f, select(1f, _e1105, (_e1105 < 1f)), (_e1105 > 0f));
                                            let _e1110 = (_e1081 != _e1081);
                                            if _e1110 {
                                                phi_2894_ = true;
                                            } else {
                                                phi_2894_ = (_e1109 <= _e1081);
                                            }
                                            let _e1113 = phi_2894_;
                                            let _e1114 = select(_e1081, _e1109, _e1113);
                                            if _e1110 {
                                                phi_2909_ = true;
                                            } else {
                                                phi_2909_ = (_e1109 >= _e1081);
                                            }
                                            let _e1117 = phi_2909_;
                                            let _e1118 = select(_e1081, _e1109, _e1117);
                                            let _e1120 = floor((_e1114 * 32f));
                                            if (_e969 == 1u) {
                                                let _e1128 = -(floor((_e1118 * -32f)));
                                                if (_e1128 != _e1128) {
                                                    phi_2924_ = true;
                                                } else {
                                                    phi_2924_ = (32f <= _e1128);
                                                }
                                                let _e1132 = phi_2924_;
                                                let _e1135 = (select(_e1128, 32f, _e1132) - _e1120);
                                                if (_e1135 != _e1135) {
                                                    phi_2939_ = true;
                                                } else {
                                                    phi_2939_ = (0f >= _e1135);
                                                }
                                                let _e1139 = phi_2939_;
                                                phi_1778_ = select(select(_e1135, 0f, _e1139), 0f, (_e1118 <= _e1114));
                                            } else {
                                                phi_1778_ = -(floor(((_e1118 - _e1114) * -32f)));
                                            }
                                            let _e1143 = phi_1778_;
                                            if (_e1120 > 0f) {
                                                let _e1149 = select(select(u32(_e1120), 0u, (_e1120 < 0f)), 4294967295u, (_e1120 > 4294967000f));
                                                phi_1796_ = select(_e1149, 32u, (32u < _e1149));
                                            } else {
                                                phi_1796_ = 0u;
                                            }
                                            let _e1153 = phi_1796_;
                                            if (_e1143 > 0f) {
                                                let _e1159 = select(select(u32(_e1143), 0u, (_e1143 < 0f)), 4294967295u, (_e1143 > 4294967000f));
                                                phi_1814_ = select(_e1159, 32u, (32u < _e1159));
                                            } else {
                                                phi_1814_ = 0u;
                                            }
                                            let _e1163 = phi_1814_;
                                            if (_e1153 >= 32u) {
                                                phi_1834_ = u32();
                                                phi_1835_ = true;
                                            } else {
                                                let _e1165 = (_e1163 == 0u);
                                                if _e1165 {
                                                    phi_1833_ = u32();
                                                } else {
                                                    if (_e1163 >= 32u) {
                                                        phi_1830_ = 4294967295u;
                                                    } else {
                                                        phi_1830_ = ((1u << bitcast<u32>((_e1163 & 31u))) - 1u);
                                                    }
                                                    let _e1172 = phi_1830_;
                                                    phi_1833_ = (_e1172 << bitcast<u32>((_e1153 & 31u)));
                                                }
                                                let _e1177 = phi_1833_;
                                                phi_1834_ = _e1177;
                                                phi_1835_ = _e1165;
                                            }
                                            let _e1179 = phi_1834_;
                                            let _e1181 = phi_1835_;
                                            phi_1849_ = select(select(select(_e1179, 0u, _e1181), 0u, (sqrt((((_e978 * _e978) + (_e979 * _e979)) + (_e980 * _e980))) <= 0f)), 0u, _e962);
                                        } else {
                                            phi_1849_ = 0u;
                                        }
                                        let _e1187 = phi_1849_;
                                        let _e1189 = (((((_e778 * 2f) - 1f) * _e416) * _e938) - _e418);
                                        let _e1190 = (((((_e779 * -2f) + 1f) * _e426) * _e938) - _e428);
                                        let _e1191 = (_e938 - _e408);
                                        if _e953 {
                                            phi_1873_ = (sqrt((((_e1189 * _e1189) + (_e1190 * _e1190)) + (_e1191 * _e1191))) > _e952);
                                        } else {
                                            phi_1873_ = false;
                                        }
                                        let _e1200 = phi_1873_;
                                        if !(_e1200) {
                                            let _e1204 = params.member.member;
                                            let _e1207 = params.member.member_3;
                                            let _e1212 = (((_e1189 * _e439) + (_e1190 * _e440)) + (_e1191 * _e441));
                                            let _e1216 = (_e1189 - (_e439 * _e1212));
                                            let _e1217 = (_e1190 - (_e440 * _e1212));
                                            let _e1218 = (_e1191 - (_e441 * _e1212));
                                            let _e1227 = ((_e1217 * _e441) - (_e440 * _e1218));
                                            let _e1230 = ((_e1218 * _e439) - (_e441 * _e1216));
                                            let _e1233 = ((_e1216 * _e440) - (_e439 * _e1217));
                                            let _e1240 = (1f / sqrt((((_e1227 * _e1227) + (_e1230 * _e1230)) + (_e1233 * _e1233))));
                                            let _e1241 = (_e1227 * _e1240);
                                            let _e1242 = (_e1230 * _e1240);
                                            let _e1243 = (_e1233 * _e1240);
                                            let _e1248 = (((_e511 * _e1241) + (_e512 * _e1242)) + (_e513 * _e1243));
                                            let _e1252 = (_e511 - (_e1241 * _e1248));
                                            let _e1253 = (_e512 - (_e1242 * _e1248));
                                            let _e1254 = (_e513 - (_e1243 * _e1248));
                                            let _e1260 = sqrt((((_e1252 * _e1252) + (_e1253 * _e1253)) + (_e1254 * _e1254)));
                                            let _e1266 = ((((_e1252 * _e439) + (_e1253 * _e440)) + (_e1254 * _e441)) / _e1260);
                                            let _e1271 = acos(select(0f, select(1f, _e1266, (_e1266 < 1f)), (_e1266 > 0f)));
                                            let _e1279 = select(_e1271, -(_e1271), ((((_e1216 * _e1252) + (_e1217 * _e1253)) + (_e1218 * _e1254)) < 0f));
                                            let _e1280 = (0.02f / _e1260);
                                            if (_e1280 != _e1280) {
                                                phi_2954_ = true;
                                            } else {
                                                phi_2954_ = (0.19634955f <= _e1280);
                                            }
                                            let _e1284 = phi_2954_;
                                            let _e1285 = select(_e1280, 0.19634955f, _e1284);
                                            let _e1289 = (_e1189 - (_e439 * _e1204));
                                            let _e1290 = (_e1190 - (_e440 * _e1204));
                                            let _e1291 = (_e1191 - (_e441 * _e1204));
                                            let _e1298 = (1f / sqrt((((_e1189 * _e1189) + (_e1190 * _e1190)) + (_e1191 * _e1191))));
                                            let _e1306 = ((((_e1189 * _e1298) * _e439) + ((_e1190 * _e1298) * _e440)) + ((_e1191 * _e1298) * _e441));
                                            let _e1315 = ((((acos(select(-1f, select(1f, _e1306, (_e1306 < 1f)), (_e1306 > -1f))) + _e1285) - _e1279) + 1.5707964f) * 0.31830987f);
                                            let _e1326 = (1f / sqrt((((_e1289 * _e1289) + (_e1290 * _e1290)) + (_e1291 * _e1291))));
                                            let _e1334 = ((((_e1289 * _e1326) * _e439) + ((_e1290 * _e1326) * _e440)) + ((_e1291 * _e1326) * _e441));
                                            let _e1343 = ((((acos(select(-1f, select(1f, _e1334, (_e1334 < 1f)), (_e1334 > -1f))) + _e1285) - _e1279) + 1.5707964f) * 0.31830987f);
                                            let _e1348 = (1f - select(0f, select(1f, _e1315, (_e1315 < 1f)), (_e1315 > 0f)));
                                            let _e1349 = (1f - select(0f, select(1f, _e1343, (_e1343 < 1f)), (_e1343 > 0f)));
                                            let _e1350 = (_e1348 != _e1348);
                                            if _e1350 {
                                                phi_2969_ = true;
                                            } else {
                                                phi_2969_ = (_e1349 <= _e1348);
                                            }
                                            let _e1353 = phi_2969_;
                                            let _e1354 = select(_e1348, _e1349, _e1353);
                                            if _e1350 {
                                                phi_2984_ = true;
                                            } else {
                                                phi_2984_ = (_e1349 >= _e1348);
                                            }
                                            let _e1357 = phi_2984_;
                                            let _e1358 = select(_e1348, _e1349, _e1357);
                                            let _e1360 = floor((_e1354 * 32f));
                                            if (_e1207 == 1u) {
                                                let _e1368 = -(floor((_e1358 * -32f)));
                                                if (_e1368 != _e1368) {
                                                    phi_2999_ = true;
                                                } else {
                                                    phi_2999_ = (32f <= _e1368);
                                                }
                                                let _e1372 = phi_2999_;
                                                let _e1375 = (select(_e1368, 32f, _e1372) - _e1360);
                                                if (_e1375 != _e1375) {
                                                    phi_3014_ = true;
                                                } else {
                                                    phi_3014_ = (0f >= _e1375);
                                                }
                                                let _e1379 = phi_3014_;
                                                phi_2119_ = select(select(_e1375, 0f, _e1379), 0f, (_e1358 <= _e1354));
                                            } else {
                                                phi_2119_ = -(floor(((_e1358 - _e1354) * -32f)));
                                            }
                                            let _e1383 = phi_2119_;
                                            if (_e1360 > 0f) {
                                                let _e1389 = select(select(u32(_e1360), 0u, (_e1360 < 0f)), 4294967295u, (_e1360 > 4294967000f));
                                                phi_2137_ = select(_e1389, 32u, (32u < _e1389));
                                            } else {
                                                phi_2137_ = 0u;
                                            }
                                            let _e1393 = phi_2137_;
                                            if (_e1383 > 0f) {
                                                let _e1399 = select(select(u32(_e1383), 0u, (_e1383 < 0f)), 4294967295u, (_e1383 > 4294967000f));
                                                phi_2155_ = select(_e1399, 32u, (32u < _e1399));
                                            } else {
                                                phi_2155_ = 0u;
                                            }
                                            let _e1403 = phi_2155_;
                                            if (_e1393 >= 32u) {
                                                phi_2175_ = u32();
                                                phi_2176_ = true;
                                            } else {
                                                let _e1405 = (_e1403 == 0u);
                                                if _e1405 {
                                                    phi_2174_ = u32();
                                                } else {
                                                    if (_e1403 >= 32u) {
                                                        phi_2171_ = 4294967295u;
                                                    } else {
                                                        phi_2171_ = ((1u << bitcast<u32>((_e1403 & 31u))) - 1u);
                                                    }
                                                    let _e1412 = phi_2171_;
                                                    phi_2174_ = (_e1412 << bitcast<u32>((_e1393 & 31u)));
                                                }
                                                let _e1417 = phi_2174_;
                                                phi_2175_ = _e1417;
                                                phi_2176_ = _e1405;
                                            }
                                            let _e1419 = phi_2175_;
                                            let _e1421 = phi_2176_;
                                            phi_2190_ = select(select(select(_e1419, 0u, _e1421), 0u, (sqrt((((_e1216 * _e1216) + (_e1217 * _e1217)) + (_e1218 * _e1218))) <= 0f)), 0u, _e1200);
                                        } else {
                                            phi_2190_ = 0u;
                                        }
                                        let _e1427 = phi_2190_;
                                        phi_1110_ = (_e696 + 1u);
                                        phi_1113_ = ((_e698 | _e1187) | _e1427);
                                    } else {
                                        phi_1110_ = u32();
                                        phi_1113_ = u32();
                                    }
                                    let _e1431 = phi_1110_;
                                    let _e1433 = phi_1113_;
                                    continue;
                                    continuing {
                                        phi_1109_ = _e1431;
                                        phi_1112_ = _e1433;
                                        phi_3073_ = _e605;
                                        break if !(_e699);
                                    }
                                }
                                let _e1436 = phi_3073_;
                                phi_3269_ = _e1436;
                                if _e1436 {
                                    break;
                                }
                                let _e1439 = params.member.member_2;
                                if (_e1439 == 2u) {
                                    let _e1496 = (_e688 - 1.5707964f);
                                    let _e1497 = (_e1496 * 2f);
                                    let _e1498 = sin(_e688);
                                    let _e1503 = ((_e686 + (_e1497 * _e1498)) - cos((_e1497 - _e688)));
                                    phi_2221_ = 0u;
                                    phi_2224_ = select((_e1503 * 0.25f), (_e1503 * -0.25f), (_e1496 < 0f));
                                    phi_2226_ = 0f;
                                    loop {
                                        let _e1509 = phi_2221_;
                                        let _e1511 = phi_2224_;
                                        let _e1513 = phi_2226_;
                                        local_8 = _e1513;
                                        let _e1514 = (_e1509 < 32u);
                                        if _e1514 {
                                            let _e1515 = (_e1509 + 1u);
                                            let _e1518 = (_e1496 + (f32(_e1515) * 0.09817477f));
                                            let _e1519 = (_e1518 * 2f);
                                            let _e1524 = ((_e686 + (_e1519 * _e1498)) - cos((_e1519 - _e688)));
                                            let _e1528 = select((_e1524 * 0.25f), (_e1524 * -0.25f), (_e1518 < 0f));
                                            let _e1531 = local_7;
                                            phi_2222_ = _e1515;
                                            phi_2225_ = _e1528;
                                            phi_2227_ = select(_e1513, (_e1513 + (_e1528 - _e1511)), (((_e1531 >> bitcast<u32>((_e1509 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2222_ = u32();
                                            phi_2225_ = f32();
                                            phi_2227_ = f32();
                                        }
                                        let _e1540 = phi_2222_;
                                        let _e1542 = phi_2225_;
                                        let _e1544 = phi_2227_;
                                        continue;
                                        continuing {
                                            phi_2221_ = _e1540;
                                            phi_2224_ = _e1542;
                                            phi_2226_ = _e1544;
                                            break if !(_e1514);
                                        }
                                    }
                                    let _e1547 = local_8;
                                    phi_3271_ = _e1436;
                                    phi_2329_ = (_e609 + 1f);
                                    phi_2330_ = (_e611 + ((_e667 + ((1f - _e667) * 0.05f)) * _e1547));
                                } else {
                                    if (_e1439 == 1u) {
                                        phi_2274_ = 0u;
                                        phi_2277_ = 0f;
                                        loop {
                                            let _e1452 = phi_2274_;
                                            let _e1454 = phi_2277_;
                                            local_6 = _e1454;
                                            let _e1455 = (_e1452 < 4u);
                                            if _e1455 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1455 {
                                                } else {
                                                    phi_3266_ = true;
                                                    break;
                                                }
                                                let _e1458 = local[_e1452].member;
                                                let _e1461 = local[_e1452].member_1;
                                                let _e1463 = local_5;
                                                phi_2275_ = (_e1452 + 1u);
                                                phi_2278_ = (_e1454 + (f32(countOneBits((_e1463 & _e1458))) * _e1461));
                                            } else {
                                                phi_2275_ = u32();
                                                phi_2278_ = f32();
                                            }
                                            let _e1471 = phi_2275_;
                                            let _e1473 = phi_2278_;
                                            continue;
                                            continuing {
                                                phi_2274_ = _e1471;
                                                phi_2277_ = _e1473;
                                                phi_3266_ = _e1436;
                                                break if !(_e1455);
                                            }
                                        }
                                        let _e1476 = phi_3266_;
                                        phi_3269_ = _e1476;
                                        if _e1476 {
                                            break;
                                        }
                                        let _e1478 = local_6;
                                        let _e1479 = (1f - _e1478);
                                        phi_3277_ = _e1476;
                                        phi_2327_ = (_e609 + _e667);
                                        phi_2328_ = (_e611 + (_e667 * select(0f, select(1f, _e1479, (_e1479 < 1f)), (_e1479 > 0f))));
                                    } else {
                                        let _e1443 = local_4;
                                        phi_3277_ = _e1436;
                                        phi_2327_ = (_e609 + 1f);
                                        phi_2328_ = (_e611 + ((f32(countOneBits((_e1443 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1488 = phi_3277_;
                                    let _e1490 = phi_2327_;
                                    let _e1492 = phi_2328_;
                                    phi_3271_ = _e1488;
                                    phi_2329_ = _e1490;
                                    phi_2330_ = _e1492;
                                }
                                let _e1552 = phi_3271_;
                                let _e1554 = phi_2329_;
                                let _e1556 = phi_2330_;
                                phi_3270_ = _e1552;
                                phi_935_ = (_e607 + 1u);
                                phi_938_ = _e1554;
                                phi_940_ = _e1556;
                            } else {
                                phi_3270_ = _e605;
                                phi_935_ = u32();
                                phi_938_ = f32();
                                phi_940_ = f32();
                            }
                            let _e1559 = phi_3270_;
                            let _e1561 = phi_935_;
                            let _e1563 = phi_938_;
                            let _e1565 = phi_940_;
                            continue;
                            continuing {
                                phi_3185_ = _e1559;
                                phi_934_ = _e1561;
                                phi_937_ = _e1563;
                                phi_939_ = _e1565;
                                phi_3269_ = _e1559;
                                break if !(_e612);
                            }
                        }
                        let _e1568 = phi_3269_;
                        if _e1568 {
                            break;
                        }
                        let _e1570 = local_9;
                        let _e1573 = local_10;
                        let _e1575 = local_11;
                        phi_2338_ = select(1f, (_e1573 / _e1575), (_e1570 > 0f));
                    } else {
                        phi_2338_ = 1f;
                    }
                    let _e1579 = phi_2338_;
                    if _e597 {
                        let _e1583 = params.member.member_4.member_6;
                        let _e1584 = pow(_e1579, _e1583);
                        if (_e1584 != _e1584) {
                            phi_3047_ = true;
                        } else {
                            phi_3047_ = (0.03f >= _e1584);
                        }
                        let _e1588 = phi_3047_;
                        let _e1590 = (select(_e1584, 0.03f, _e1588) * 0.6666667f);
                        let _e1596 = ((select(0f, select(1f, _e1590, (_e1590 < 1f)), (_e1590 > 0f)) * 255f) + 0.5f);
                        phi_2387_ = select(select(u32(_e1596), 0u, (_e1596 < 0f)), 4294967295u, (_e1596 > 4294967000f));
                    } else {
                        phi_2387_ = 170u;
                    }
                    let _e1603 = phi_2387_;
                    if (_e121 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e121] = _e1603;
                    if (_e121 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e121] = ((((64u * _e299) + (16u * _e332)) + (4u * _e366)) + _e400);
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
