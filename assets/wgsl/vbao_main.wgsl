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
    var phi_2437_: bool;
    var phi_2452_: bool;
    var phi_2467_: bool;
    var phi_2482_: bool;
    var phi_2513_: f32;
    var phi_2517_: f32;
    var phi_2518_: bool;
    var phi_2540_: u32;
    var phi_2567_: f32;
    var phi_2571_: f32;
    var phi_2572_: bool;
    var phi_2594_: u32;
    var phi_2621_: f32;
    var phi_2625_: f32;
    var phi_2626_: bool;
    var phi_2648_: u32;
    var phi_2675_: f32;
    var phi_2679_: f32;
    var phi_2680_: bool;
    var phi_2702_: u32;
    var phi_2782_: bool;
    var phi_2797_: bool;
    var phi_2757_: vec2<f32>;
    var phi_2814_: u32;
    var phi_2815_: u32;
    var phi_2816_: u32;
    var phi_2817_: u32;
    var phi_2840_: u32;
    var phi_2841_: u32;
    var phi_2844_: u32;
    var phi_2845_: u32;
    var phi_2849_: u32;
    var phi_2850_: u32;
    var phi_2851_: u32;
    var phi_2852_: u32;
    var local_1: u32;
    var phi_3192_: bool;
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
    var phi_1295_: u32;
    var phi_1298_: u32;
    var phi_1296_: u32;
    var phi_1299_: u32;
    var phi_1343_: u32;
    var phi_1362_: u32;
    var local_2: u32;
    var phi_1406_: u32;
    var phi_1422_: u32;
    var phi_1425_: u32;
    var phi_1423_: u32;
    var phi_1426_: u32;
    var phi_1470_: u32;
    var phi_1489_: u32;
    var local_3: u32;
    var phi_1538_: bool;
    var phi_2886_: bool;
    var phi_2901_: bool;
    var phi_2916_: bool;
    var phi_2931_: bool;
    var phi_2946_: bool;
    var phi_1784_: f32;
    var phi_1802_: u32;
    var phi_1820_: u32;
    var phi_1836_: u32;
    var phi_1839_: u32;
    var phi_1840_: u32;
    var phi_1841_: bool;
    var phi_1855_: u32;
    var phi_1879_: bool;
    var phi_2961_: bool;
    var phi_2976_: bool;
    var phi_2991_: bool;
    var phi_3006_: bool;
    var phi_3021_: bool;
    var phi_2125_: f32;
    var phi_2143_: u32;
    var phi_2161_: u32;
    var phi_2177_: u32;
    var phi_2180_: u32;
    var phi_2181_: u32;
    var phi_2182_: bool;
    var phi_2196_: u32;
    var phi_1116_: u32;
    var phi_1119_: u32;
    var phi_3080_: bool;
    var local_4: u32;
    var phi_2280_: u32;
    var phi_2283_: f32;
    var local_5: u32;
    var phi_2281_: u32;
    var phi_2284_: f32;
    var phi_3273_: bool;
    var local_6: f32;
    var phi_3284_: bool;
    var phi_2333_: f32;
    var phi_2334_: f32;
    var phi_2227_: u32;
    var phi_2230_: f32;
    var phi_2232_: f32;
    var local_7: u32;
    var phi_2228_: u32;
    var phi_2231_: f32;
    var phi_2233_: f32;
    var local_8: f32;
    var phi_3278_: bool;
    var phi_2335_: f32;
    var phi_2336_: f32;
    var phi_3277_: bool;
    var phi_941_: u32;
    var phi_944_: f32;
    var phi_946_: f32;
    var phi_3276_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var phi_2344_: f32;
    var phi_3054_: bool;
    var phi_2393_: u32;

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
                        phi_484_ = 0i;
                    } else {
                        phi_484_ = select(_e126, _e128, (_e126 > _e128));
                    }
                    let _e134 = phi_484_;
                    let _e136 = bitcast<i32>(_e84.y);
                    let _e138 = (bitcast<i32>(_e115) - 1i);
                    let _e139 = (0i <= _e138);
                    if _e139 {
                    } else {
                        break;
                    }
                    let _e140 = (_e136 < 0i);
                    if _e140 {
                        phi_503_ = 0i;
                    } else {
                        phi_503_ = select(_e136, _e138, (_e136 > _e138));
                    }
                    let _e144 = phi_503_;
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
                        phi_544_ = 0i;
                    } else {
                        phi_544_ = select(_e151, _e128, (_e151 > _e128));
                    }
                    let _e156 = phi_544_;
                    if _e139 {
                    } else {
                        break;
                    }
                    if _e140 {
                        phi_563_ = 0i;
                    } else {
                        phi_563_ = select(_e136, _e138, (_e136 > _e138));
                    }
                    let _e161 = phi_563_;
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
                        phi_604_ = 0i;
                    } else {
                        phi_604_ = select(_e125, _e128, (_e125 > _e128));
                    }
                    let _e172 = phi_604_;
                    let _e174 = (_e136 + -1i);
                    if _e139 {
                    } else {
                        break;
                    }
                    if (_e174 < 0i) {
                        phi_623_ = 0i;
                    } else {
                        phi_623_ = select(_e174, _e138, (_e174 > _e138));
                    }
                    let _e179 = phi_623_;
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
                        phi_664_ = 0i;
                    } else {
                        phi_664_ = select(_e125, _e128, (_e125 > _e128));
                    }
                    let _e189 = phi_664_;
                    let _e191 = (_e136 + 1i);
                    if _e139 {
                    } else {
                        break;
                    }
                    if (_e191 < 0i) {
                        phi_683_ = 0i;
                    } else {
                        phi_683_ = select(_e191, _e138, (_e191 > _e138));
                    }
                    let _e196 = phi_683_;
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
                        phi_2437_ = true;
                    } else {
                        phi_2437_ = (_e214 <= _e213);
                    }
                    let _e218 = phi_2437_;
                    let _e221 = (1.25f - (select(_e213, _e214, _e218) / _e211));
                    let _e225 = select(0f, select(1f, _e221, (_e221 < 1f)), (_e221 > 0f));
                    let _e227 = abs(_e204);
                    let _e228 = abs((_e204 - _e208));
                    if (_e227 != _e227) {
                        phi_2452_ = true;
                    } else {
                        phi_2452_ = (_e228 <= _e227);
                    }
                    let _e232 = phi_2452_;
                    let _e235 = (1.25f - (select(_e227, _e228, _e232) / _e211));
                    let _e239 = select(0f, select(1f, _e235, (_e235 < 1f)), (_e235 > 0f));
                    let _e241 = abs(_e205);
                    let _e242 = abs((_e205 + _e210));
                    if (_e241 != _e241) {
                        phi_2467_ = true;
                    } else {
                        phi_2467_ = (_e242 <= _e241);
                    }
                    let _e246 = phi_2467_;
                    let _e249 = (1.25f - (select(_e241, _e242, _e246) / _e211));
                    let _e253 = select(0f, select(1f, _e249, (_e249 < 1f)), (_e249 > 0f));
                    let _e255 = abs(_e206);
                    let _e256 = abs((_e206 - _e210));
                    if (_e255 != _e255) {
                        phi_2482_ = true;
                    } else {
                        phi_2482_ = (_e256 <= _e255);
                    }
                    let _e260 = phi_2482_;
                    let _e263 = (1.25f - (select(_e255, _e256, _e260) / _e211));
                    let _e267 = select(0f, select(1f, _e263, (_e263 < 1f)), (_e263 > 0f));
                    let _e272 = (select(0f, select(1f, _e225, (_e225 < 1f)), (_e225 > 0f)) * 2.9f);
                    let _e274 = floor((_e272 + 0.5f));
                    if ((_e274 - _e272) == 0.5f) {
                        let _e280 = ((floor((_e274 * 0.5f)) * 2f) != _e274);
                        if _e280 {
                            phi_2513_ = (_e274 - 1f);
                        } else {
                            phi_2513_ = f32();
                        }
                        let _e283 = phi_2513_;
                        phi_2517_ = _e283;
                        phi_2518_ = select(true, false, _e280);
                    } else {
                        phi_2517_ = f32();
                        phi_2518_ = true;
                    }
                    let _e286 = phi_2517_;
                    let _e288 = phi_2518_;
                    let _e289 = select(_e286, _e274, _e288);
                    if (_e289 > 0f) {
                        let _e295 = select(select(u32(_e289), 0u, (_e289 < 0f)), 4294967295u, (_e289 > 4294967000f));
                        phi_2540_ = select(_e295, 3u, (3u < _e295));
                    } else {
                        phi_2540_ = 0u;
                    }
                    let _e299 = phi_2540_;
                    let _e305 = (select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f)) * 2.9f);
                    let _e307 = floor((_e305 + 0.5f));
                    if ((_e307 - _e305) == 0.5f) {
                        let _e313 = ((floor((_e307 * 0.5f)) * 2f) != _e307);
                        if _e313 {
                            phi_2567_ = (_e307 - 1f);
                        } else {
                            phi_2567_ = f32();
                        }
                        let _e316 = phi_2567_;
                        phi_2571_ = _e316;
                        phi_2572_ = select(true, false, _e313);
                    } else {
                        phi_2571_ = f32();
                        phi_2572_ = true;
                    }
                    let _e319 = phi_2571_;
                    let _e321 = phi_2572_;
                    let _e322 = select(_e319, _e307, _e321);
                    if (_e322 > 0f) {
                        let _e328 = select(select(u32(_e322), 0u, (_e322 < 0f)), 4294967295u, (_e322 > 4294967000f));
                        phi_2594_ = select(_e328, 3u, (3u < _e328));
                    } else {
                        phi_2594_ = 0u;
                    }
                    let _e332 = phi_2594_;
                    let _e339 = (select(0f, select(1f, _e253, (_e253 < 1f)), (_e253 > 0f)) * 2.9f);
                    let _e341 = floor((_e339 + 0.5f));
                    if ((_e341 - _e339) == 0.5f) {
                        let _e347 = ((floor((_e341 * 0.5f)) * 2f) != _e341);
                        if _e347 {
                            phi_2621_ = (_e341 - 1f);
                        } else {
                            phi_2621_ = f32();
                        }
                        let _e350 = phi_2621_;
                        phi_2625_ = _e350;
                        phi_2626_ = select(true, false, _e347);
                    } else {
                        phi_2625_ = f32();
                        phi_2626_ = true;
                    }
                    let _e353 = phi_2625_;
                    let _e355 = phi_2626_;
                    let _e356 = select(_e353, _e341, _e355);
                    if (_e356 > 0f) {
                        let _e362 = select(select(u32(_e356), 0u, (_e356 < 0f)), 4294967295u, (_e356 > 4294967000f));
                        phi_2648_ = select(_e362, 3u, (3u < _e362));
                    } else {
                        phi_2648_ = 0u;
                    }
                    let _e366 = phi_2648_;
                    let _e373 = (select(0f, select(1f, _e267, (_e267 < 1f)), (_e267 > 0f)) * 2.9f);
                    let _e375 = floor((_e373 + 0.5f));
                    if ((_e375 - _e373) == 0.5f) {
                        let _e381 = ((floor((_e375 * 0.5f)) * 2f) != _e375);
                        if _e381 {
                            phi_2675_ = (_e375 - 1f);
                        } else {
                            phi_2675_ = f32();
                        }
                        let _e384 = phi_2675_;
                        phi_2679_ = _e384;
                        phi_2680_ = select(true, false, _e381);
                    } else {
                        phi_2679_ = f32();
                        phi_2680_ = true;
                    }
                    let _e387 = phi_2679_;
                    let _e389 = phi_2680_;
                    let _e390 = select(_e387, _e375, _e389);
                    if (_e390 > 0f) {
                        let _e396 = select(select(u32(_e390), 0u, (_e390 < 0f)), 4294967295u, (_e390 > 4294967000f));
                        phi_2702_ = select(_e396, 3u, (3u < _e396));
                    } else {
                        phi_2702_ = 0u;
                    }
                    let _e400 = phi_2702_;
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
                        phi_2782_ = true;
                    } else {
                        phi_2782_ = (-1f >= _e453);
                    }
                    let _e457 = phi_2782_;
                    let _e458 = select(_e453, -1f, _e457);
                    let _e468 = (f32((bitcast<i32>((((_e445 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e468 != _e468) {
                        phi_2797_ = true;
                    } else {
                        phi_2797_ = (-1f >= _e468);
                    }
                    let _e472 = phi_2797_;
                    let _e473 = select(_e468, -1f, _e472);
                    let _e476 = (1f - abs(_e458));
                    let _e477 = abs(_e473);
                    let _e478 = (_e476 - _e477);
                    if (_e478 < 0f) {
                        phi_2757_ = vec2<f32>(((1f - _e477) * select(1f, -1f, (_e458 < 0f))), (_e476 * select(1f, -1f, (_e473 < 0f))));
                    } else {
                        phi_2757_ = vec2<f32>(_e458, _e473);
                    }
                    let _e489 = phi_2757_;
                    let _e498 = (1f / sqrt((((_e489.x * _e489.x) + (_e489.y * _e489.y)) + (_e478 * _e478))));
                    let _e499 = (_e489.x * _e498);
                    let _e500 = (_e489.y * _e498);
                    let _e501 = (_e478 * _e498);
                    let _e502 = -(_e501);
                    let _e508 = ((((_e499 * _e439) + (_e500 * _e440)) + (_e502 * _e441)) < 0f);
                    let _e510 = select(_e499, -(_e499), _e508);
                    let _e512 = select(_e500, -(_e500), _e508);
                    let _e513 = select(_e502, _e501, _e508);
                    let _e517 = params.member.member_4.member_1;
                    let _e521 = params.member.member_4.member_2;
                    let _e526 = ((_e517 * _e521) / (((_e124 * 1.99998f) * _e416) / _e99));
                    let _e531 = params.member.member_4.member_11;
                    phi_2814_ = (_e84.y & 63u);
                    phi_2815_ = (_e84.x & 63u);
                    phi_2816_ = 32u;
                    phi_2817_ = 0u;
                    loop {
                        let _e535 = phi_2814_;
                        let _e537 = phi_2815_;
                        let _e539 = phi_2816_;
                        let _e541 = phi_2817_;
                        local_1 = _e541;
                        let _e542 = (_e539 > 0u);
                        if _e542 {
                            let _e545 = select(0u, 1u, ((_e537 & _e539) != 0u));
                            let _e548 = select(0u, 1u, ((_e535 & _e539) != 0u));
                            if (_e548 == 0u) {
                                if (_e545 == 1u) {
                                    phi_2840_ = (63u - _e535);
                                    phi_2841_ = (63u - _e537);
                                } else {
                                    phi_2840_ = _e535;
                                    phi_2841_ = _e537;
                                }
                                let _e559 = phi_2840_;
                                let _e561 = phi_2841_;
                                phi_2844_ = _e561;
                                phi_2845_ = _e559;
                            } else {
                                phi_2844_ = _e535;
                                phi_2845_ = _e537;
                            }
                            let _e563 = phi_2844_;
                            let _e565 = phi_2845_;
                            phi_2849_ = _e563;
                            phi_2850_ = _e565;
                            phi_2851_ = (_e539 / 2u);
                            phi_2852_ = (_e541 + ((_e539 * _e539) * ((3u * _e545) ^ _e548)));
                        } else {
                            phi_2849_ = u32();
                            phi_2850_ = u32();
                            phi_2851_ = u32();
                            phi_2852_ = u32();
                        }
                        let _e568 = phi_2849_;
                        let _e570 = phi_2850_;
                        let _e572 = phi_2851_;
                        let _e574 = phi_2852_;
                        continue;
                        continuing {
                            phi_2814_ = _e568;
                            phi_2815_ = _e570;
                            phi_2816_ = _e572;
                            phi_2817_ = _e574;
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
                        phi_3192_ = false;
                        phi_940_ = 0u;
                        phi_943_ = 0f;
                        phi_945_ = 0f;
                        loop {
                            let _e605 = phi_3192_;
                            let _e607 = phi_940_;
                            let _e609 = phi_943_;
                            let _e611 = phi_945_;
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
                                let _e655 = (((_e510 * _e648) + (_e512 * _e649)) + (_e513 * _e650));
                                let _e659 = (_e510 - (_e648 * _e655));
                                let _e660 = (_e512 - (_e649 * _e655));
                                let _e661 = (_e513 - (_e650 * _e655));
                                let _e667 = sqrt((((_e659 * _e659) + (_e660 * _e660)) + (_e661 * _e661)));
                                let _e672 = (((_e629 * _e659) + (_e630 * _e660)) + (_e631 * _e661));
                                let _e682 = ((((_e659 * _e439) + (_e660 * _e440)) + (_e661 * _e441)) / _e667);
                                let _e686 = select(0f, select(1f, _e682, (_e682 < 1f)), (_e682 > 0f));
                                let _e688 = (select(select(0f, -1f, (_e672 < 0f)), 1f, (_e672 > 0f)) * acos(_e686));
                                let _e692 = params.member.member_4.member_9;
                                let _e694 = select(1u, _e692, (1u < _e692));
                                phi_1115_ = 0u;
                                phi_1118_ = 0u;
                                loop {
                                    let _e696 = phi_1115_;
                                    let _e698 = phi_1118_;
                                    local_4 = _e698;
                                    local_5 = _e698;
                                    local_7 = _e698;
                                    let _e699 = (_e696 < _e694);
                                    if _e699 {
                                        let _e704 = ((_e587 - floor(_e587)) + (f32((_e607 + (_e696 * _e694))) * 0.618034f));
                                        let _e710 = (((_e704 - floor(_e704)) + f32(_e696)) / f32(_e694));
                                        let _e714 = params.member.member_4.member_4;
                                        if (_e714 == 2f) {
                                            phi_1172_ = (_e710 * _e710);
                                        } else {
                                            phi_1172_ = pow(_e710, _e714);
                                        }
                                        let _e719 = phi_1172_;
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
                                                phi_1217_ = (_e741 - 1f);
                                            } else {
                                                phi_1217_ = f32();
                                            }
                                            let _e750 = phi_1217_;
                                            phi_1219_ = _e750;
                                            phi_1220_ = select(true, false, _e747);
                                        } else {
                                            phi_1219_ = f32();
                                            phi_1220_ = true;
                                        }
                                        let _e753 = phi_1219_;
                                        let _e755 = phi_1220_;
                                        let _e757 = (select(_e753, _e741, _e755) / _e99);
                                        let _e759 = floor((_e722 + 0.5f));
                                        if ((_e759 - _e722) == 0.5f) {
                                            let _e765 = ((floor((_e759 * 0.5f)) * 2f) != _e759);
                                            if _e765 {
                                                phi_1243_ = (_e759 - 1f);
                                            } else {
                                                phi_1243_ = f32();
                                            }
                                            let _e768 = phi_1243_;
                                            phi_1245_ = _e768;
                                            phi_1246_ = select(true, false, _e765);
                                        } else {
                                            phi_1245_ = f32();
                                            phi_1246_ = true;
                                        }
                                        let _e771 = phi_1245_;
                                        let _e773 = phi_1246_;
                                        let _e775 = (select(_e771, _e759, _e773) / _e110);
                                        let _e776 = (_e404 + _e757);
                                        let _e777 = (_e407 + _e775);
                                        let _e778 = (_e404 - _e757);
                                        let _e779 = (_e407 - _e775);
                                        let _e780 = (_e739 > 0f);
                                        if _e780 {
                                            let _e785 = select(select(u32(_e739), 0u, (_e739 < 0f)), 4294967295u, (_e739 > 4294967000f));
                                            phi_1279_ = select(_e785, 4u, (4u < _e785));
                                        } else {
                                            phi_1279_ = 0u;
                                        }
                                        let _e789 = phi_1279_;
                                        let _e790 = (_e789 & 31u);
                                        let _e792 = (_e104 >> bitcast<u32>(_e790));
                                        let _e794 = select(1u, _e792, (1u < _e792));
                                        let _e796 = (_e115 >> bitcast<u32>(_e790));
                                        let _e798 = select(1u, _e796, (1u < _e796));
                                        phi_1295_ = 0u;
                                        phi_1298_ = 0u;
                                        loop {
                                            let _e800 = phi_1295_;
                                            let _e802 = phi_1298_;
                                            local_2 = _e802;
                                            let _e803 = (_e800 < _e789);
                                            if _e803 {
                                                let _e804 = (_e800 & 31u);
                                                let _e806 = (_e104 >> bitcast<u32>(_e804));
                                                let _e810 = (_e115 >> bitcast<u32>(_e804));
                                                phi_1296_ = (_e800 + 1u);
                                                phi_1299_ = (_e802 + (select(1u, _e806, (1u < _e806)) * select(1u, _e810, (1u < _e810))));
                                            } else {
                                                phi_1296_ = u32();
                                                phi_1299_ = u32();
                                            }
                                            let _e817 = phi_1296_;
                                            let _e819 = phi_1299_;
                                            continue;
                                            continuing {
                                                phi_1295_ = _e817;
                                                phi_1298_ = _e819;
                                                break if !(_e803);
                                            }
                                        }
                                        let _e823 = (_e776 * f32(_e794));
                                        if (_e823 > 0f) {
                                            let _e829 = select(select(u32(_e823), 0u, (_e823 < 0f)), 4294967295u, (_e823 > 4294967000f));
                                            let _e830 = (_e794 - 1u);
                                            phi_1343_ = select(_e829, _e830, (_e830 < _e829));
                                        } else {
                                            phi_1343_ = 0u;
                                        }
                                        let _e834 = phi_1343_;
                                        let _e835 = (_e777 * f32(_e798));
                                        if (_e835 > 0f) {
                                            let _e841 = select(select(u32(_e835), 0u, (_e835 < 0f)), 4294967295u, (_e835 > 4294967000f));
                                            let _e842 = (_e798 - 1u);
                                            phi_1362_ = select(_e841, _e842, (_e842 < _e841));
                                        } else {
                                            phi_1362_ = 0u;
                                        }
                                        let _e846 = phi_1362_;
                                        let _e849 = local_2;
                                        let _e851 = ((_e849 + (_e846 * _e794)) + _e834);
                                        if (_e851 < _e87) {
                                        } else {
                                            phi_3080_ = true;
                                            break;
                                        }
                                        let _e855 = mips.member[_e851];
                                        if _e780 {
                                            let _e868 = select(select(u32(_e739), 0u, (_e739 < 0f)), 4294967295u, (_e739 > 4294967000f));
                                            phi_1406_ = select(_e868, 4u, (4u < _e868));
                                        } else {
                                            phi_1406_ = 0u;
                                        }
                                        let _e872 = phi_1406_;
                                        let _e873 = (_e872 & 31u);
                                        let _e875 = (_e104 >> bitcast<u32>(_e873));
                                        let _e877 = select(1u, _e875, (1u < _e875));
                                        let _e879 = (_e115 >> bitcast<u32>(_e873));
                                        let _e881 = select(1u, _e879, (1u < _e879));
                                        phi_1422_ = 0u;
                                        phi_1425_ = 0u;
                                        loop {
                                            let _e883 = phi_1422_;
                                            let _e885 = phi_1425_;
                                            local_3 = _e885;
                                            let _e886 = (_e883 < _e872);
                                            if _e886 {
                                                let _e887 = (_e883 & 31u);
                                                let _e889 = (_e104 >> bitcast<u32>(_e887));
                                                let _e893 = (_e115 >> bitcast<u32>(_e887));
                                                phi_1423_ = (_e883 + 1u);
                                                phi_1426_ = (_e885 + (select(1u, _e889, (1u < _e889)) * select(1u, _e893, (1u < _e893))));
                                            } else {
                                                phi_1423_ = u32();
                                                phi_1426_ = u32();
                                            }
                                            let _e900 = phi_1423_;
                                            let _e902 = phi_1426_;
                                            continue;
                                            continuing {
                                                phi_1422_ = _e900;
                                                phi_1425_ = _e902;
                                                break if !(_e886);
                                            }
                                        }
                                        let _e906 = (_e778 * f32(_e877));
                                        if (_e906 > 0f) {
                                            let _e912 = select(select(u32(_e906), 0u, (_e906 < 0f)), 4294967295u, (_e906 > 4294967000f));
                                            let _e913 = (_e877 - 1u);
                                            phi_1470_ = select(_e912, _e913, (_e913 < _e912));
                                        } else {
                                            phi_1470_ = 0u;
                                        }
                                        let _e917 = phi_1470_;
                                        let _e918 = (_e779 * f32(_e881));
                                        if (_e918 > 0f) {
                                            let _e924 = select(select(u32(_e918), 0u, (_e918 < 0f)), 4294967295u, (_e918 > 4294967000f));
                                            let _e925 = (_e881 - 1u);
                                            phi_1489_ = select(_e924, _e925, (_e925 < _e924));
                                        } else {
                                            phi_1489_ = 0u;
                                        }
                                        let _e929 = phi_1489_;
                                        let _e932 = local_3;
                                        let _e934 = ((_e932 + (_e929 * _e877)) + _e917);
                                        if (_e934 < _e87) {
                                        } else {
                                            phi_3080_ = true;
                                            break;
                                        }
                                        let _e938 = mips.member[_e934];
                                        let _e947 = (((((_e776 * 2f) - 1f) * _e416) * _e855) - _e418);
                                        let _e948 = (((((_e777 * -2f) + 1f) * _e426) * _e855) - _e428);
                                        let _e949 = (_e855 - _e408);
                                        let _e952 = params.member.member_1;
                                        let _e953 = (_e952 > 0f);
                                        if _e953 {
                                            phi_1538_ = (sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))) > _e952);
                                        } else {
                                            phi_1538_ = false;
                                        }
                                        let _e962 = phi_1538_;
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
                                            let _e1010 = (((_e510 * _e1003) + (_e512 * _e1004)) + (_e513 * _e1005));
                                            let _e1014 = (_e510 - (_e1003 * _e1010));
                                            let _e1015 = (_e512 - (_e1004 * _e1010));
                                            let _e1016 = (_e513 - (_e1005 * _e1010));
                                            let _e1022 = sqrt((((_e1014 * _e1014) + (_e1015 * _e1015)) + (_e1016 * _e1016)));
                                            let _e1028 = ((((_e1014 * _e439) + (_e1015 * _e440)) + (_e1016 * _e441)) / _e1022);
                                            let _e1033 = acos(select(0f, select(1f, _e1028, (_e1028 < 1f)), (_e1028 > 0f)));
                                            let _e1041 = select(_e1033, -(_e1033), ((((_e978 * _e1014) + (_e979 * _e1015)) + (_e980 * _e1016)) < 0f));
                                            let _e1042 = (0.02f / _e1022);
                                            if (_e1042 != _e1042) {
                                                phi_2886_ = true;
                                            } else {
                                                phi_2886_ = (0.19634955f <= _e1042);
                                            }
                                            let _e1046 = phi_2886_;
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
                                                phi_2901_ = true;
                                            } else {
                                                phi_2901_ = (_e1109 <= _e1081);
                                            }
                                            let _e1113 = phi_2901_;
                                            let _e1114 = select(_e1081, _e1109, _e1113);
                                            if _e1110 {
                                                phi_2916_ = true;
                                            } else {
                                                phi_2916_ = (_e1109 >= _e1081);
                                            }
                                            let _e1117 = phi_2916_;
                                            let _e1118 = select(_e1081, _e1109, _e1117);
                                            let _e1120 = floor((_e1114 * 32f));
                                            if (_e969 == 1u) {
                                                let _e1128 = -(floor((_e1118 * -32f)));
                                                if (_e1128 != _e1128) {
                                                    phi_2931_ = true;
                                                } else {
                                                    phi_2931_ = (32f <= _e1128);
                                                }
                                                let _e1132 = phi_2931_;
                                                let _e1135 = (select(_e1128, 32f, _e1132) - _e1120);
                                                if (_e1135 != _e1135) {
                                                    phi_2946_ = true;
                                                } else {
                                                    phi_2946_ = (0f >= _e1135);
                                                }
                                                let _e1139 = phi_2946_;
                                                phi_1784_ = select(select(_e1135, 0f, _e1139), 0f, (_e1118 <= _e1114));
                                            } else {
                                                phi_1784_ = -(floor(((_e1118 - _e1114) * -32f)));
                                            }
                                            let _e1143 = phi_1784_;
                                            if (_e1120 > 0f) {
                                                let _e1149 = select(select(u32(_e1120), 0u, (_e1120 < 0f)), 4294967295u, (_e1120 > 4294967000f));
                                                phi_1802_ = select(_e1149, 32u, (32u < _e1149));
                                            } else {
                                                phi_1802_ = 0u;
                                            }
                                            let _e1153 = phi_1802_;
                                            if (_e1143 > 0f) {
                                                let _e1159 = select(select(u32(_e1143), 0u, (_e1143 < 0f)), 4294967295u, (_e1143 > 4294967000f));
                                                phi_1820_ = select(_e1159, 32u, (32u < _e1159));
                                            } else {
                                                phi_1820_ = 0u;
                                            }
                                            let _e1163 = phi_1820_;
                                            if (_e1153 >= 32u) {
                                                phi_1840_ = u32();
                                                phi_1841_ = true;
                                            } else {
                                                let _e1165 = (_e1163 == 0u);
                                                if _e1165 {
                                                    phi_1839_ = u32();
                                                } else {
                                                    if (_e1163 >= 32u) {
                                                        phi_1836_ = 4294967295u;
                                                    } else {
                                                        phi_1836_ = ((1u << bitcast<u32>((_e1163 & 31u))) - 1u);
                                                    }
                                                    let _e1172 = phi_1836_;
                                                    phi_1839_ = (_e1172 << bitcast<u32>((_e1153 & 31u)));
                                                }
                                                let _e1177 = phi_1839_;
                                                phi_1840_ = _e1177;
                                                phi_1841_ = _e1165;
                                            }
                                            let _e1179 = phi_1840_;
                                            let _e1181 = phi_1841_;
                                            phi_1855_ = select(select(select(_e1179, 0u, _e1181), 0u, (sqrt((((_e978 * _e978) + (_e979 * _e979)) + (_e980 * _e980))) <= 0f)), 0u, _e962);
                                        } else {
                                            phi_1855_ = 0u;
                                        }
                                        let _e1187 = phi_1855_;
                                        let _e1189 = (((((_e778 * 2f) - 1f) * _e416) * _e938) - _e418);
                                        let _e1190 = (((((_e779 * -2f) + 1f) * _e426) * _e938) - _e428);
                                        let _e1191 = (_e938 - _e408);
                                        if _e953 {
                                            phi_1879_ = (sqrt((((_e1189 * _e1189) + (_e1190 * _e1190)) + (_e1191 * _e1191))) > _e952);
                                        } else {
                                            phi_1879_ = false;
                                        }
                                        let _e1200 = phi_1879_;
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
                                            let _e1248 = (((_e510 * _e1241) + (_e512 * _e1242)) + (_e513 * _e1243));
                                            let _e1252 = (_e510 - (_e1241 * _e1248));
                                            let _e1253 = (_e512 - (_e1242 * _e1248));
                                            let _e1254 = (_e513 - (_e1243 * _e1248));
                                            let _e1260 = sqrt((((_e1252 * _e1252) + (_e1253 * _e1253)) + (_e1254 * _e1254)));
                                            let _e1266 = ((((_e1252 * _e439) + (_e1253 * _e440)) + (_e1254 * _e441)) / _e1260);
                                            let _e1271 = acos(select(0f, select(1f, _e1266, (_e1266 < 1f)), (_e1266 > 0f)));
                                            let _e1279 = select(_e1271, -(_e1271), ((((_e1216 * _e1252) + (_e1217 * _e1253)) + (_e1218 * _e1254)) < 0f));
                                            let _e1280 = (0.02f / _e1260);
                                            if (_e1280 != _e1280) {
                                                phi_2961_ = true;
                                            } else {
                                                phi_2961_ = (0.19634955f <= _e1280);
                                            }
                                            let _e1284 = phi_2961_;
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
                                                phi_2976_ = true;
                                            } else {
                                                phi_2976_ = (_e1349 <= _e1348);
                                            }
                                            let _e1353 = phi_2976_;
                                            let _e1354 = select(_e1348, _e1349, _e1353);
                                            if _e1350 {
                                                phi_2991_ = true;
                                            } else {
                                                phi_2991_ = (_e1349 >= _e1348);
                                            }
                                            let _e1357 = phi_2991_;
                                            let _e1358 = select(_e1348, _e1349, _e1357);
                                            let _e1360 = floor((_e1354 * 32f));
                                            if (_e1207 == 1u) {
                                                let _e1368 = -(floor((_e1358 * -32f)));
                                                if (_e1368 != _e1368) {
                                                    phi_3006_ = true;
                                                } else {
                                                    phi_3006_ = (32f <= _e1368);
                                                }
                                                let _e1372 = phi_3006_;
                                                let _e1375 = (select(_e1368, 32f, _e1372) - _e1360);
                                                if (_e1375 != _e1375) {
                                                    phi_3021_ = true;
                                                } else {
                                                    phi_3021_ = (0f >= _e1375);
                                                }
                                                let _e1379 = phi_3021_;
                                                phi_2125_ = select(select(_e1375, 0f, _e1379), 0f, (_e1358 <= _e1354));
                                            } else {
                                                phi_2125_ = -(floor(((_e1358 - _e1354) * -32f)));
                                            }
                                            let _e1383 = phi_2125_;
                                            if (_e1360 > 0f) {
                                                let _e1389 = select(select(u32(_e1360), 0u, (_e1360 < 0f)), 4294967295u, (_e1360 > 4294967000f));
                                                phi_2143_ = select(_e1389, 32u, (32u < _e1389));
                                            } else {
                                                phi_2143_ = 0u;
                                            }
                                            let _e1393 = phi_2143_;
                                            if (_e1383 > 0f) {
                                                let _e1399 = select(select(u32(_e1383), 0u, (_e1383 < 0f)), 4294967295u, (_e1383 > 4294967000f));
                                                phi_2161_ = select(_e1399, 32u, (32u < _e1399));
                                            } else {
                                                phi_2161_ = 0u;
                                            }
                                            let _e1403 = phi_2161_;
                                            if (_e1393 >= 32u) {
                                                phi_2181_ = u32();
                                                phi_2182_ = true;
                                            } else {
                                                let _e1405 = (_e1403 == 0u);
                                                if _e1405 {
                                                    phi_2180_ = u32();
                                                } else {
                                                    if (_e1403 >= 32u) {
                                                        phi_2177_ = 4294967295u;
                                                    } else {
                                                        phi_2177_ = ((1u << bitcast<u32>((_e1403 & 31u))) - 1u);
                                                    }
                                                    let _e1412 = phi_2177_;
                                                    phi_2180_ = (_e1412 << bitcast<u32>((_e1393 & 31u)));
                                                }
                                                let _e1417 = phi_2180_;
                                                phi_2181_ = _e1417;
                                                phi_2182_ = _e1405;
                                            }
                                            let _e1419 = phi_2181_;
                                            let _e1421 = phi_2182_;
                                            phi_2196_ = select(select(select(_e1419, 0u, _e1421), 0u, (sqrt((((_e1216 * _e1216) + (_e1217 * _e1217)) + (_e1218 * _e1218))) <= 0f)), 0u, _e1200);
                                        } else {
                                            phi_2196_ = 0u;
                                        }
                                        let _e1427 = phi_2196_;
                                        phi_1116_ = (_e696 + 1u);
                                        phi_1119_ = ((_e698 | _e1187) | _e1427);
                                    } else {
                                        phi_1116_ = u32();
                                        phi_1119_ = u32();
                                    }
                                    let _e1431 = phi_1116_;
                                    let _e1433 = phi_1119_;
                                    continue;
                                    continuing {
                                        phi_1115_ = _e1431;
                                        phi_1118_ = _e1433;
                                        phi_3080_ = _e605;
                                        break if !(_e699);
                                    }
                                }
                                let _e1436 = phi_3080_;
                                phi_3276_ = _e1436;
                                if _e1436 {
                                    break;
                                }
                                let _e1439 = params.member.member_2;
                                if (_e1439 == 2u) {
                                    let _e1496 = (_e688 - 1.5707964f);
                                    let _e1497 = (_e1496 * 2f);
                                    let _e1498 = sin(_e688);
                                    let _e1503 = ((_e686 + (_e1497 * _e1498)) - cos((_e1497 - _e688)));
                                    phi_2227_ = 0u;
                                    phi_2230_ = select((_e1503 * 0.25f), (_e1503 * -0.25f), (_e1496 < 0f));
                                    phi_2232_ = 0f;
                                    loop {
                                        let _e1509 = phi_2227_;
                                        let _e1511 = phi_2230_;
                                        let _e1513 = phi_2232_;
                                        local_8 = _e1513;
                                        let _e1514 = (_e1509 < 32u);
                                        if _e1514 {
                                            let _e1515 = (_e1509 + 1u);
                                            let _e1518 = (_e1496 + (f32(_e1515) * 0.09817477f));
                                            let _e1519 = (_e1518 * 2f);
                                            let _e1524 = ((_e686 + (_e1519 * _e1498)) - cos((_e1519 - _e688)));
                                            let _e1528 = select((_e1524 * 0.25f), (_e1524 * -0.25f), (_e1518 < 0f));
                                            let _e1531 = local_7;
                                            phi_2228_ = _e1515;
                                            phi_2231_ = _e1528;
                                            phi_2233_ = select(_e1513, (_e1513 + (_e1528 - _e1511)), (((_e1531 >> bitcast<u32>((_e1509 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2228_ = u32();
                                            phi_2231_ = f32();
                                            phi_2233_ = f32();
                                        }
                                        let _e1540 = phi_2228_;
                                        let _e1542 = phi_2231_;
                                        let _e1544 = phi_2233_;
                                        continue;
                                        continuing {
                                            phi_2227_ = _e1540;
                                            phi_2230_ = _e1542;
                                            phi_2232_ = _e1544;
                                            break if !(_e1514);
                                        }
                                    }
                                    let _e1547 = local_8;
                                    phi_3278_ = _e1436;
                                    phi_2335_ = (_e609 + 1f);
                                    phi_2336_ = (_e611 + ((_e667 + ((1f - _e667) * 0.05f)) * _e1547));
                                } else {
                                    if (_e1439 == 1u) {
                                        phi_2280_ = 0u;
                                        phi_2283_ = 0f;
                                        loop {
                                            let _e1452 = phi_2280_;
                                            let _e1454 = phi_2283_;
                                            local_6 = _e1454;
                                            let _e1455 = (_e1452 < 4u);
                                            if _e1455 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1455 {
                                                } else {
                                                    phi_3273_ = true;
                                                    break;
                                                }
                                                let _e1458 = local[_e1452].member;
                                                let _e1461 = local[_e1452].member_1;
                                                let _e1463 = local_5;
                                                phi_2281_ = (_e1452 + 1u);
                                                phi_2284_ = (_e1454 + (f32(countOneBits((_e1463 & _e1458))) * _e1461));
                                            } else {
                                                phi_2281_ = u32();
                                                phi_2284_ = f32();
                                            }
                                            let _e1471 = phi_2281_;
                                            let _e1473 = phi_2284_;
                                            continue;
                                            continuing {
                                                phi_2280_ = _e1471;
                                                phi_2283_ = _e1473;
                                                phi_3273_ = _e1436;
                                                break if !(_e1455);
                                            }
                                        }
                                        let _e1476 = phi_3273_;
                                        phi_3276_ = _e1476;
                                        if _e1476 {
                                            break;
                                        }
                                        let _e1478 = local_6;
                                        let _e1479 = (1f - _e1478);
                                        phi_3284_ = _e1476;
                                        phi_2333_ = (_e609 + _e667);
                                        phi_2334_ = (_e611 + (_e667 * select(0f, select(1f, _e1479, (_e1479 < 1f)), (_e1479 > 0f))));
                                    } else {
                                        let _e1443 = local_4;
                                        phi_3284_ = _e1436;
                                        phi_2333_ = (_e609 + 1f);
                                        phi_2334_ = (_e611 + ((f32(countOneBits((_e1443 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1488 = phi_3284_;
                                    let _e1490 = phi_2333_;
                                    let _e1492 = phi_2334_;
                                    phi_3278_ = _e1488;
                                    phi_2335_ = _e1490;
                                    phi_2336_ = _e1492;
                                }
                                let _e1552 = phi_3278_;
                                let _e1554 = phi_2335_;
                                let _e1556 = phi_2336_;
                                phi_3277_ = _e1552;
                                phi_941_ = (_e607 + 1u);
                                phi_944_ = _e1554;
                                phi_946_ = _e1556;
                            } else {
                                phi_3277_ = _e605;
                                phi_941_ = u32();
                                phi_944_ = f32();
                                phi_946_ = f32();
                            }
                            let _e1559 = phi_3277_;
                            let _e1561 = phi_941_;
                            let _e1563 = phi_944_;
                            let _e1565 = phi_946_;
                            continue;
                            continuing {
                                phi_3192_ = _e1559;
                                phi_940_ = _e1561;
                                phi_943_ = _e1563;
                                phi_945_ = _e1565;
                                phi_3276_ = _e1559;
                                break if !(_e612);
                            }
                        }
                        let _e1568 = phi_3276_;
                        if _e1568 {
                            break;
                        }
                        let _e1570 = local_9;
                        let _e1573 = local_10;
                        let _e1575 = local_11;
                        phi_2344_ = select(1f, (_e1573 / _e1575), (_e1570 > 0f));
                    } else {
                        phi_2344_ = 1f;
                    }
                    let _e1579 = phi_2344_;
                    if _e597 {
                        let _e1583 = params.member.member_4.member_6;
                        let _e1584 = pow(_e1579, _e1583);
                        if (_e1584 != _e1584) {
                            phi_3054_ = true;
                        } else {
                            phi_3054_ = (0.03f >= _e1584);
                        }
                        let _e1588 = phi_3054_;
                        let _e1590 = (select(_e1584, 0.03f, _e1588) * 0.6666667f);
                        let _e1596 = ((select(0f, select(1f, _e1590, (_e1590 < 1f)), (_e1590 > 0f)) * 255f) + 0.5f);
                        phi_2393_ = select(select(u32(_e1596), 0u, (_e1596 < 0f)), 4294967295u, (_e1596 > 4294967000f));
                    } else {
                        phi_2393_ = 170u;
                    }
                    let _e1603 = phi_2393_;
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
