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
    var phi_311_: i32;
    var phi_330_: i32;
    var phi_370_: i32;
    var phi_389_: i32;
    var phi_429_: i32;
    var phi_448_: i32;
    var phi_488_: i32;
    var phi_507_: i32;
    var phi_2427_: f32;
    var phi_2431_: f32;
    var phi_2432_: bool;
    var phi_2470_: f32;
    var phi_2474_: f32;
    var phi_2475_: bool;
    var phi_2513_: f32;
    var phi_2517_: f32;
    var phi_2518_: bool;
    var phi_2556_: f32;
    var phi_2560_: f32;
    var phi_2561_: bool;
    var phi_2583_: bool;
    var phi_2598_: bool;
    var phi_724_: vec2<f32>;
    var phi_752_: vec3<f32>;
    var phi_773_: u32;
    var phi_776_: u32;
    var phi_778_: u32;
    var phi_780_: u32;
    var phi_809_: u32;
    var phi_810_: u32;
    var phi_811_: u32;
    var phi_812_: u32;
    var phi_774_: u32;
    var phi_777_: u32;
    var phi_779_: u32;
    var phi_781_: u32;
    var local_1: u32;
    var phi_2780_: bool;
    var phi_858_: u32;
    var phi_861_: f32;
    var phi_863_: f32;
    var phi_1033_: u32;
    var phi_1036_: u32;
    var phi_1090_: f32;
    var phi_1135_: f32;
    var phi_1137_: f32;
    var phi_1138_: bool;
    var phi_1161_: f32;
    var phi_1163_: f32;
    var phi_1164_: bool;
    var phi_1197_: u32;
    var phi_1200_: f32;
    var phi_1202_: f32;
    var phi_1204_: u32;
    var phi_1206_: u32;
    var phi_1208_: u32;
    var phi_1241_: u32;
    var phi_1244_: u32;
    var phi_1242_: u32;
    var phi_1245_: u32;
    var local_2: u32;
    var phi_1198_: u32;
    var phi_1201_: f32;
    var phi_1203_: f32;
    var phi_1205_: u32;
    var phi_1207_: u32;
    var phi_1209_: u32;
    var local_3: f32;
    var local_4: u32;
    var phi_1302_: u32;
    var local_5: f32;
    var local_6: u32;
    var phi_1321_: u32;
    var local_7: u32;
    var local_8: u32;
    var phi_1365_: u32;
    var phi_1368_: f32;
    var phi_1370_: f32;
    var phi_1372_: u32;
    var phi_1374_: u32;
    var phi_1376_: u32;
    var phi_1409_: u32;
    var phi_1412_: u32;
    var phi_1410_: u32;
    var phi_1413_: u32;
    var local_9: u32;
    var phi_1366_: u32;
    var phi_1369_: f32;
    var phi_1371_: f32;
    var phi_1373_: u32;
    var phi_1375_: u32;
    var phi_1377_: u32;
    var local_10: f32;
    var local_11: u32;
    var phi_1470_: u32;
    var local_12: f32;
    var local_13: u32;
    var phi_1489_: u32;
    var local_14: u32;
    var local_15: u32;
    var phi_1542_: bool;
    var phi_1658_: f32;
    var phi_2619_: bool;
    var phi_2634_: bool;
    var phi_2649_: bool;
    var phi_1803_: u32;
    var phi_1804_: u32;
    var phi_1816_: u32;
    var phi_1817_: bool;
    var phi_1836_: u32;
    var phi_1839_: u32;
    var phi_1840_: u32;
    var phi_1841_: bool;
    var phi_1846_: u32;
    var phi_1847_: u32;
    var phi_1848_: u32;
    var phi_1876_: bool;
    var phi_1992_: f32;
    var phi_2664_: bool;
    var phi_2679_: bool;
    var phi_2694_: bool;
    var phi_2137_: u32;
    var phi_2138_: u32;
    var phi_2150_: u32;
    var phi_2151_: bool;
    var phi_2170_: u32;
    var phi_2173_: u32;
    var phi_2174_: u32;
    var phi_2175_: bool;
    var phi_2180_: u32;
    var phi_2181_: u32;
    var phi_2182_: u32;
    var phi_1034_: u32;
    var phi_1037_: u32;
    var phi_2714_: bool;
    var local_16: u32;
    var phi_2266_: u32;
    var phi_2269_: f32;
    var local_17: u32;
    var phi_2267_: u32;
    var phi_2270_: f32;
    var phi_2897_: bool;
    var local_18: f32;
    var phi_2908_: bool;
    var phi_2316_: f32;
    var phi_2317_: f32;
    var phi_2211_: f32;
    var phi_2213_: u32;
    var phi_2216_: f32;
    var phi_2218_: f32;
    var phi_2244_: f32;
    var local_19: u32;
    var phi_2254_: f32;
    var phi_2214_: u32;
    var phi_2217_: f32;
    var phi_2219_: f32;
    var local_20: f32;
    var phi_2902_: bool;
    var phi_2318_: f32;
    var phi_2319_: f32;
    var phi_2901_: bool;
    var phi_859_: u32;
    var phi_862_: f32;
    var phi_864_: f32;
    var phi_2900_: bool;
    var local_21: f32;
    var local_22: f32;
    var local_23: f32;
    var phi_2326_: f32;
    var phi_2709_: bool;
    var phi_2374_: type_28;

    switch bitcast<i32>(0u) {
        default: {
            let _e84 = id_1;
            let _e86 = arrayLength((&mips.member));
            let _e98 = params.member.member_4.member.member[0u];
            let _e103 = select(select(u32(_e98), 0u, (_e98 < 0f)), 4294967295u, (_e98 > 4294967000f));
            let _e109 = params.member.member_4.member.member[1u];
            let _e114 = select(select(u32(_e109), 0u, (_e109 < 0f)), 4294967295u, (_e109 > 4294967000f));
            if (_e84.x >= _e103) {
            } else {
                if (_e84.y >= _e114) {
                } else {
                    let _e120 = ((_e84.y * _e103) + _e84.x);
                    if (_e120 < _e86) {
                    } else {
                        break;
                    }
                    let _e124 = mips.member[_e120];
                    let _e125 = bitcast<i32>(_e84.x);
                    let _e126 = (_e125 + -1i);
                    let _e128 = (bitcast<i32>(_e103) - 1i);
                    let _e129 = (0i <= _e128);
                    if _e129 {
                    } else {
                        break;
                    }
                    if (_e126 < 0i) {
                        phi_311_ = 0i;
                    } else {
                        phi_311_ = select(_e126, _e128, (_e126 > _e128));
                    }
                    let _e134 = phi_311_;
                    let _e136 = bitcast<i32>(_e84.y);
                    let _e138 = (bitcast<i32>(_e114) - 1i);
                    let _e139 = (0i <= _e138);
                    if _e139 {
                    } else {
                        break;
                    }
                    let _e140 = (_e136 < 0i);
                    if _e140 {
                        phi_330_ = 0i;
                    } else {
                        phi_330_ = select(_e136, _e138, (_e136 > _e138));
                    }
                    let _e144 = phi_330_;
                    let _e147 = ((bitcast<u32>(_e144) * _e103) + bitcast<u32>(_e134));
                    if (_e147 < _e86) {
                    } else {
                        break;
                    }
                    let _e151 = mips.member[_e147];
                    let _e152 = (_e125 + 1i);
                    if _e129 {
                    } else {
                        break;
                    }
                    if (_e152 < 0i) {
                        phi_370_ = 0i;
                    } else {
                        phi_370_ = select(_e152, _e128, (_e152 > _e128));
                    }
                    let _e157 = phi_370_;
                    if _e139 {
                    } else {
                        break;
                    }
                    if _e140 {
                        phi_389_ = 0i;
                    } else {
                        phi_389_ = select(_e136, _e138, (_e136 > _e138));
                    }
                    let _e162 = phi_389_;
                    let _e165 = ((bitcast<u32>(_e162) * _e103) + bitcast<u32>(_e157));
                    if (_e165 < _e86) {
                    } else {
                        break;
                    }
                    let _e169 = mips.member[_e165];
                    if _e129 {
                    } else {
                        break;
                    }
                    let _e170 = (_e125 < 0i);
                    if _e170 {
                        phi_429_ = 0i;
                    } else {
                        phi_429_ = select(_e125, _e128, (_e125 > _e128));
                    }
                    let _e174 = phi_429_;
                    let _e176 = (_e136 + -1i);
                    if _e139 {
                    } else {
                        break;
                    }
                    if (_e176 < 0i) {
                        phi_448_ = 0i;
                    } else {
                        phi_448_ = select(_e176, _e138, (_e176 > _e138));
                    }
                    let _e181 = phi_448_;
                    let _e184 = ((bitcast<u32>(_e181) * _e103) + bitcast<u32>(_e174));
                    if (_e184 < _e86) {
                    } else {
                        break;
                    }
                    let _e188 = mips.member[_e184];
                    if _e129 {
                    } else {
                        break;
                    }
                    if _e170 {
                        phi_488_ = 0i;
                    } else {
                        phi_488_ = select(_e125, _e128, (_e125 > _e128));
                    }
                    let _e192 = phi_488_;
                    let _e194 = (_e136 + 1i);
                    if _e139 {
                    } else {
                        break;
                    }
                    if (_e194 < 0i) {
                        phi_507_ = 0i;
                    } else {
                        phi_507_ = select(_e194, _e138, (_e194 > _e138));
                    }
                    let _e199 = phi_507_;
                    let _e202 = ((bitcast<u32>(_e199) * _e103) + bitcast<u32>(_e192));
                    if (_e202 < _e86) {
                    } else {
                        break;
                    }
                    let _e206 = mips.member[_e202];
                    let _e207 = (_e151 - _e124);
                    let _e208 = (_e169 - _e124);
                    let _e209 = (_e188 - _e124);
                    let _e210 = (_e206 - _e124);
                    let _e211 = (_e208 - _e207);
                    let _e213 = (_e210 - _e209);
                    let _e221 = abs(_e207);
                    let _e222 = abs(_e208);
                    let _e223 = abs(_e209);
                    let _e224 = abs(_e210);
                    let _e225 = abs((_e207 + (_e211 * 0.5f)));
                    let _e226 = abs((_e208 + (_e211 * -0.5f)));
                    let _e227 = abs((_e209 + (_e213 * 0.5f)));
                    let _e228 = abs((_e210 + (_e213 * -0.5f)));
                    let _e237 = (_e124 * 0.011f);
                    let _e242 = (1.25f - (select(_e225, _e221, (_e221 < _e225)) / _e237));
                    let _e246 = select(0f, select(1f, _e242, (_e242 < 1f)), (_e242 > 0f));
                    let _e247 = (1.25f - (select(_e226, _e222, (_e222 < _e226)) / _e237));
                    let _e251 = select(0f, select(1f, _e247, (_e247 < 1f)), (_e247 > 0f));
                    let _e252 = (1.25f - (select(_e227, _e223, (_e223 < _e227)) / _e237));
                    let _e256 = select(0f, select(1f, _e252, (_e252 < 1f)), (_e252 > 0f));
                    let _e257 = (1.25f - (select(_e228, _e224, (_e224 < _e228)) / _e237));
                    let _e261 = select(0f, select(1f, _e257, (_e257 < 1f)), (_e257 > 0f));
                    let _e266 = (select(0f, select(1f, _e246, (_e246 < 1f)), (_e246 > 0f)) * 2.9f);
                    let _e268 = floor((_e266 + 0.5f));
                    if ((_e268 - _e266) == 0.5f) {
                        let _e274 = ((floor((_e268 * 0.5f)) * 2f) != _e268);
                        if _e274 {
                            phi_2427_ = (_e268 - 1f);
                        } else {
                            phi_2427_ = f32();
                        }
                        let _e277 = phi_2427_;
                        phi_2431_ = _e277;
                        phi_2432_ = select(true, false, _e274);
                    } else {
                        phi_2431_ = f32();
                        phi_2432_ = true;
                    }
                    let _e280 = phi_2431_;
                    let _e282 = phi_2432_;
                    let _e283 = select(_e280, _e268, _e282);
                    let _e294 = (select(0f, select(1f, _e251, (_e251 < 1f)), (_e251 > 0f)) * 2.9f);
                    let _e296 = floor((_e294 + 0.5f));
                    if ((_e296 - _e294) == 0.5f) {
                        let _e302 = ((floor((_e296 * 0.5f)) * 2f) != _e296);
                        if _e302 {
                            phi_2470_ = (_e296 - 1f);
                        } else {
                            phi_2470_ = f32();
                        }
                        let _e305 = phi_2470_;
                        phi_2474_ = _e305;
                        phi_2475_ = select(true, false, _e302);
                    } else {
                        phi_2474_ = f32();
                        phi_2475_ = true;
                    }
                    let _e308 = phi_2474_;
                    let _e310 = phi_2475_;
                    let _e311 = select(_e308, _e296, _e310);
                    let _e323 = (select(0f, select(1f, _e256, (_e256 < 1f)), (_e256 > 0f)) * 2.9f);
                    let _e325 = floor((_e323 + 0.5f));
                    if ((_e325 - _e323) == 0.5f) {
                        let _e331 = ((floor((_e325 * 0.5f)) * 2f) != _e325);
                        if _e331 {
                            phi_2513_ = (_e325 - 1f);
                        } else {
                            phi_2513_ = f32();
                        }
                        let _e334 = phi_2513_;
                        phi_2517_ = _e334;
                        phi_2518_ = select(true, false, _e331);
                    } else {
                        phi_2517_ = f32();
                        phi_2518_ = true;
                    }
                    let _e337 = phi_2517_;
                    let _e339 = phi_2518_;
                    let _e340 = select(_e337, _e325, _e339);
                    let _e352 = (select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f)) * 2.9f);
                    let _e354 = floor((_e352 + 0.5f));
                    if ((_e354 - _e352) == 0.5f) {
                        let _e360 = ((floor((_e354 * 0.5f)) * 2f) != _e354);
                        if _e360 {
                            phi_2556_ = (_e354 - 1f);
                        } else {
                            phi_2556_ = f32();
                        }
                        let _e363 = phi_2556_;
                        phi_2560_ = _e363;
                        phi_2561_ = select(true, false, _e360);
                    } else {
                        phi_2560_ = f32();
                        phi_2561_ = true;
                    }
                    let _e366 = phi_2560_;
                    let _e368 = phi_2561_;
                    let _e369 = select(_e366, _e354, _e368);
                    let _e375 = ((((64u * select(select(u32(_e283), 0u, (_e283 < 0f)), 4294967295u, (_e283 > 4294967000f))) + (16u * select(select(u32(_e311), 0u, (_e311 < 0f)), 4294967295u, (_e311 > 4294967000f)))) + (4u * select(select(u32(_e340), 0u, (_e340 < 0f)), 4294967295u, (_e340 > 4294967000f)))) + select(select(u32(_e369), 0u, (_e369 < 0f)), 4294967295u, (_e369 > 4294967000f)));
                    let _e378 = ((f32(_e84.x) + 0.5f) / _e98);
                    let _e381 = ((f32(_e84.y) + 0.5f) / _e109);
                    let _e382 = (_e124 * 0.99999f);
                    let _e390 = params.member.member_4.member.member_1[0u];
                    let _e392 = ((((_e378 * 2f) - 1f) * _e390) * _e382);
                    let _e400 = params.member.member_4.member.member_1[1u];
                    let _e402 = ((((_e381 * -2f) + 1f) * _e400) * _e382);
                    let _e403 = -(_e392);
                    let _e404 = -(_e402);
                    let _e405 = (_e124 * -0.99999f);
                    let _e412 = (1f / sqrt((((_e403 * _e403) + (_e404 * _e404)) + (_e405 * _e405))));
                    let _e413 = (_e403 * _e412);
                    let _e414 = (_e404 * _e412);
                    let _e415 = (_e405 * _e412);
                    if (_e120 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e419 = normals.member[_e120];
                    let _e427 = (f32((bitcast<i32>(((_e419 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e427 != _e427) {
                        phi_2583_ = true;
                    } else {
                        phi_2583_ = (-1f >= _e427);
                    }
                    let _e431 = phi_2583_;
                    let _e432 = select(_e427, -1f, _e431);
                    let _e442 = (f32((bitcast<i32>((((_e419 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e442 != _e442) {
                        phi_2598_ = true;
                    } else {
                        phi_2598_ = (-1f >= _e442);
                    }
                    let _e446 = phi_2598_;
                    let _e447 = select(_e442, -1f, _e446);
                    let _e450 = (1f - abs(_e432));
                    let _e451 = abs(_e447);
                    let _e452 = (_e450 - _e451);
                    if (_e452 < 0f) {
                        phi_724_ = vec2<f32>(((1f - _e451) * select(1f, -1f, (_e432 < 0f))), (_e450 * select(1f, -1f, (_e447 < 0f))));
                    } else {
                        phi_724_ = vec2<f32>(_e432, _e447);
                    }
                    let _e463 = phi_724_;
                    let _e472 = (1f / sqrt((((_e463.x * _e463.x) + (_e463.y * _e463.y)) + (_e452 * _e452))));
                    let _e473 = (_e463.x * _e472);
                    let _e474 = (_e463.y * _e472);
                    let _e475 = (_e452 * _e472);
                    let _e476 = -(_e475);
                    if ((((_e473 * _e413) + (_e474 * _e414)) + (_e476 * _e415)) < 0f) {
                        phi_752_ = vec3<f32>(-(_e473), -(_e474), _e475);
                    } else {
                        phi_752_ = vec3<f32>(_e473, _e474, _e476);
                    }
                    let _e488 = phi_752_;
                    let _e492 = params.member.member_4.member_1;
                    let _e496 = params.member.member_4.member_2;
                    let _e501 = ((_e492 * _e496) / (((_e124 * 1.99998f) * _e390) / _e98));
                    let _e506 = params.member.member_4.member_11;
                    phi_773_ = (_e84.y & 63u);
                    phi_776_ = (_e84.x & 63u);
                    phi_778_ = 32u;
                    phi_780_ = 0u;
                    loop {
                        let _e510 = phi_773_;
                        let _e512 = phi_776_;
                        let _e514 = phi_778_;
                        let _e516 = phi_780_;
                        local_1 = _e516;
                        let _e517 = (_e514 > 0u);
                        if _e517 {
                            let _e520 = select(0u, 1u, ((_e512 & _e514) != 0u));
                            let _e523 = select(0u, 1u, ((_e510 & _e514) != 0u));
                            if (_e523 == 0u) {
                                if (_e520 == 1u) {
                                    phi_809_ = (63u - _e510);
                                    phi_810_ = (63u - _e512);
                                } else {
                                    phi_809_ = _e510;
                                    phi_810_ = _e512;
                                }
                                let _e534 = phi_809_;
                                let _e536 = phi_810_;
                                phi_811_ = _e536;
                                phi_812_ = _e534;
                            } else {
                                phi_811_ = _e510;
                                phi_812_ = _e512;
                            }
                            let _e538 = phi_811_;
                            let _e540 = phi_812_;
                            phi_774_ = _e538;
                            phi_777_ = _e540;
                            phi_779_ = (_e514 / 2u);
                            phi_781_ = (_e516 + ((_e514 * _e514) * ((3u * _e520) ^ _e523)));
                        } else {
                            phi_774_ = u32();
                            phi_777_ = u32();
                            phi_779_ = u32();
                            phi_781_ = u32();
                        }
                        let _e543 = phi_774_;
                        let _e545 = phi_777_;
                        let _e547 = phi_779_;
                        let _e549 = phi_781_;
                        continue;
                        continuing {
                            phi_773_ = _e543;
                            phi_776_ = _e545;
                            phi_778_ = _e547;
                            phi_780_ = _e549;
                            break if !(_e517);
                        }
                    }
                    let _e554 = local_1;
                    let _e556 = f32((_e554 + (288u * (_e506 % 64u))));
                    let _e558 = (0.5f + (_e556 * 0.7548777f));
                    let _e562 = (0.5f + (_e556 * 0.5698403f));
                    let _e569 = params.member.member_4.member.member_3;
                    if select(false, (_e124 < _e569), (_e124 > 0f)) {
                        let _e577 = params.member.member_4.member_8;
                        let _e579 = select(1u, _e577, (1u < _e577));
                        phi_2780_ = false;
                        phi_858_ = 0u;
                        phi_861_ = 0f;
                        phi_863_ = 0f;
                        loop {
                            let _e581 = phi_2780_;
                            let _e583 = phi_858_;
                            let _e585 = phi_861_;
                            let _e587 = phi_863_;
                            local_21 = _e585;
                            local_22 = _e587;
                            local_23 = _e585;
                            let _e588 = (_e583 < _e579);
                            if _e588 {
                                let _e593 = ((((_e558 - floor(_e558)) + f32(_e583)) * 3.1415927f) / f32(_e579));
                                let _e594 = sin(_e593);
                                let _e595 = cos(_e593);
                                let _e601 = ((_e595 * _e413) + (_e594 * _e414));
                                let _e605 = (_e595 - (_e413 * _e601));
                                let _e606 = (_e594 - (_e414 * _e601));
                                let _e607 = -((_e415 * _e601));
                                let _e610 = ((_e606 * _e415) - (_e414 * _e607));
                                let _e613 = ((_e607 * _e413) - (_e415 * _e605));
                                let _e616 = ((_e605 * _e414) - (_e413 * _e606));
                                let _e623 = (1f / sqrt((((_e610 * _e610) + (_e613 * _e613)) + (_e616 * _e616))));
                                let _e624 = (_e610 * _e623);
                                let _e625 = (_e613 * _e623);
                                let _e626 = (_e616 * _e623);
                                let _e634 = (((_e488.x * _e624) + (_e488.y * _e625)) + (_e488.z * _e626));
                                let _e638 = (_e488.x - (_e624 * _e634));
                                let _e639 = (_e488.y - (_e625 * _e634));
                                let _e640 = (_e488.z - (_e626 * _e634));
                                let _e646 = sqrt((((_e638 * _e638) + (_e639 * _e639)) + (_e640 * _e640)));
                                let _e651 = (((_e605 * _e638) + (_e606 * _e639)) + (_e607 * _e640));
                                let _e661 = ((((_e638 * _e413) + (_e639 * _e414)) + (_e640 * _e415)) / _e646);
                                let _e665 = select(0f, select(1f, _e661, (_e661 < 1f)), (_e661 > 0f));
                                let _e667 = (select(select(0f, -1f, (_e651 < 0f)), 1f, (_e651 > 0f)) * acos(_e665));
                                let _e671 = params.member.member_4.member_9;
                                let _e673 = select(1u, _e671, (1u < _e671));
                                phi_1033_ = 0u;
                                phi_1036_ = 0u;
                                loop {
                                    let _e675 = phi_1033_;
                                    let _e677 = phi_1036_;
                                    local_16 = _e677;
                                    local_17 = _e677;
                                    local_19 = _e677;
                                    let _e678 = (_e675 < _e673);
                                    if _e678 {
                                        let _e683 = ((_e562 - floor(_e562)) + (f32((_e583 + (_e675 * _e673))) * 0.618034f));
                                        let _e689 = (((_e683 - floor(_e683)) + f32(_e675)) / f32(_e673));
                                        let _e693 = params.member.member_4.member_4;
                                        if (_e693 == 2f) {
                                            phi_1090_ = (_e689 * _e689);
                                        } else {
                                            phi_1090_ = pow(_e689, _e693);
                                        }
                                        let _e698 = phi_1090_;
                                        let _e699 = (_e698 + (1.3f / _e501));
                                        let _e700 = ((_e595 * _e501) * _e699);
                                        let _e701 = ((-(_e594) * _e501) * _e699);
                                        let _e710 = params.member.member_4.member_7;
                                        let _e711 = (log2(sqrt(((_e700 * _e700) + (_e701 * _e701)))) - _e710);
                                        let _e718 = (-1f - floor((-0.5f - select(0f, select(5f, _e711, (_e711 < 5f)), (_e711 > 0f)))));
                                        let _e720 = floor((_e700 + 0.5f));
                                        if ((_e720 - _e700) == 0.5f) {
                                            let _e726 = ((floor((_e720 * 0.5f)) * 2f) != _e720);
                                            if _e726 {
                                                phi_1135_ = (_e720 - 1f);
                                            } else {
                                                phi_1135_ = f32();
                                            }
                                            let _e729 = phi_1135_;
                                            phi_1137_ = _e729;
                                            phi_1138_ = select(true, false, _e726);
                                        } else {
                                            phi_1137_ = f32();
                                            phi_1138_ = true;
                                        }
                                        let _e732 = phi_1137_;
                                        let _e734 = phi_1138_;
                                        let _e736 = (select(_e732, _e720, _e734) / _e98);
                                        let _e738 = floor((_e701 + 0.5f));
                                        if ((_e738 - _e701) == 0.5f) {
                                            let _e744 = ((floor((_e738 * 0.5f)) * 2f) != _e738);
                                            if _e744 {
                                                phi_1161_ = (_e738 - 1f);
                                            } else {
                                                phi_1161_ = f32();
                                            }
                                            let _e747 = phi_1161_;
                                            phi_1163_ = _e747;
                                            phi_1164_ = select(true, false, _e744);
                                        } else {
                                            phi_1163_ = f32();
                                            phi_1164_ = true;
                                        }
                                        let _e750 = phi_1163_;
                                        let _e752 = phi_1164_;
                                        let _e754 = (select(_e750, _e738, _e752) / _e109);
                                        let _e755 = (_e378 + _e736);
                                        let _e756 = (_e381 + _e754);
                                        let _e757 = (_e378 - _e736);
                                        let _e758 = (_e381 - _e754);
                                        let _e760 = select(1u, _e103, (1u < _e103));
                                        let _e762 = select(1u, _e114, (1u < _e114));
                                        let _e763 = f32(_e760);
                                        let _e764 = f32(_e762);
                                        phi_1197_ = 1u;
                                        phi_1200_ = _e764;
                                        phi_1202_ = _e763;
                                        phi_1204_ = 0u;
                                        phi_1206_ = _e762;
                                        phi_1208_ = _e760;
                                        loop {
                                            let _e766 = phi_1197_;
                                            let _e768 = phi_1200_;
                                            let _e770 = phi_1202_;
                                            let _e772 = phi_1204_;
                                            let _e774 = phi_1206_;
                                            let _e776 = phi_1208_;
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
                                                let _e782 = (_e103 >> bitcast<u32>(_e780));
                                                let _e784 = select(1u, _e782, (1u < _e782));
                                                let _e786 = (_e114 >> bitcast<u32>(_e780));
                                                let _e788 = select(1u, _e786, (1u < _e786));
                                                phi_1241_ = 0u;
                                                phi_1244_ = 0u;
                                                loop {
                                                    let _e792 = phi_1241_;
                                                    let _e794 = phi_1244_;
                                                    local_2 = _e794;
                                                    let _e795 = (_e792 < _e766);
                                                    if _e795 {
                                                        let _e796 = (_e792 & 31u);
                                                        let _e798 = (_e103 >> bitcast<u32>(_e796));
                                                        let _e802 = (_e114 >> bitcast<u32>(_e796));
                                                        phi_1242_ = (_e792 + 1u);
                                                        phi_1245_ = (_e794 + (select(1u, _e798, (1u < _e798)) * select(1u, _e802, (1u < _e802))));
                                                    } else {
                                                        phi_1242_ = u32();
                                                        phi_1245_ = u32();
                                                    }
                                                    let _e809 = phi_1242_;
                                                    let _e811 = phi_1245_;
                                                    continue;
                                                    continuing {
                                                        phi_1241_ = _e809;
                                                        phi_1244_ = _e811;
                                                        break if !(_e795);
                                                    }
                                                }
                                                let _e814 = local_2;
                                                phi_1198_ = (_e766 + 1u);
                                                phi_1201_ = select(_e768, f32(_e788), _e779);
                                                phi_1203_ = select(_e770, f32(_e784), _e779);
                                                phi_1205_ = select(_e772, _e814, _e779);
                                                phi_1207_ = select(_e774, _e788, _e779);
                                                phi_1209_ = select(_e776, _e784, _e779);
                                            } else {
                                                phi_1198_ = u32();
                                                phi_1201_ = f32();
                                                phi_1203_ = f32();
                                                phi_1205_ = u32();
                                                phi_1207_ = u32();
                                                phi_1209_ = u32();
                                            }
                                            let _e822 = phi_1198_;
                                            let _e824 = phi_1201_;
                                            let _e826 = phi_1203_;
                                            let _e828 = phi_1205_;
                                            let _e830 = phi_1207_;
                                            let _e832 = phi_1209_;
                                            continue;
                                            continuing {
                                                phi_1197_ = _e822;
                                                phi_1200_ = _e824;
                                                phi_1202_ = _e826;
                                                phi_1204_ = _e828;
                                                phi_1206_ = _e830;
                                                phi_1208_ = _e832;
                                                break if !(_e777);
                                            }
                                        }
                                        let _e835 = local_3;
                                        let _e836 = (_e755 * _e835);
                                        if (_e836 > 0f) {
                                            let _e842 = select(select(u32(_e836), 0u, (_e836 < 0f)), 4294967295u, (_e836 > 4294967000f));
                                            let _e844 = local_4;
                                            let _e845 = (_e844 - 1u);
                                            phi_1302_ = select(_e842, _e845, (_e845 < _e842));
                                        } else {
                                            phi_1302_ = 0u;
                                        }
                                        let _e849 = phi_1302_;
                                        let _e851 = local_5;
                                        let _e852 = (_e756 * _e851);
                                        if (_e852 > 0f) {
                                            let _e858 = select(select(u32(_e852), 0u, (_e852 < 0f)), 4294967295u, (_e852 > 4294967000f));
                                            let _e860 = local_6;
                                            let _e861 = (_e860 - 1u);
                                            phi_1321_ = select(_e858, _e861, (_e861 < _e858));
                                        } else {
                                            phi_1321_ = 0u;
                                        }
                                        let _e865 = phi_1321_;
                                        let _e867 = local_7;
                                        let _e870 = local_8;
                                        let _e872 = ((_e870 + (_e865 * _e867)) + _e849);
                                        if (_e872 < _e86) {
                                        } else {
                                            phi_2714_ = true;
                                            break;
                                        }
                                        let _e876 = mips.member[_e872];
                                        phi_1365_ = 1u;
                                        phi_1368_ = _e764;
                                        phi_1370_ = _e763;
                                        phi_1372_ = 0u;
                                        phi_1374_ = _e762;
                                        phi_1376_ = _e760;
                                        loop {
                                            let _e886 = phi_1365_;
                                            let _e888 = phi_1368_;
                                            let _e890 = phi_1370_;
                                            let _e892 = phi_1372_;
                                            let _e894 = phi_1374_;
                                            let _e896 = phi_1376_;
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
                                                let _e902 = (_e103 >> bitcast<u32>(_e900));
                                                let _e904 = select(1u, _e902, (1u < _e902));
                                                let _e906 = (_e114 >> bitcast<u32>(_e900));
                                                let _e908 = select(1u, _e906, (1u < _e906));
                                                phi_1409_ = 0u;
                                                phi_1412_ = 0u;
                                                loop {
                                                    let _e912 = phi_1409_;
                                                    let _e914 = phi_1412_;
                                                    local_9 = _e914;
                                                    let _e915 = (_e912 < _e886);
                                                    if _e915 {
                                                        let _e916 = (_e912 & 31u);
                                                        let _e918 = (_e103 >> bitcast<u32>(_e916));
                                                        let _e922 = (_e114 >> bitcast<u32>(_e916));
                                                        phi_1410_ = (_e912 + 1u);
                                                        phi_1413_ = (_e914 + (select(1u, _e918, (1u < _e918)) * select(1u, _e922, (1u < _e922))));
                                                    } else {
                                                        phi_1410_ = u32();
                                                        phi_1413_ = u32();
                                                    }
                                                    let _e929 = phi_1410_;
                                                    let _e931 = phi_1413_;
                                                    continue;
                                                    continuing {
                                                        phi_1409_ = _e929;
                                                        phi_1412_ = _e931;
                                                        break if !(_e915);
                                                    }
                                                }
                                                let _e934 = local_9;
                                                phi_1366_ = (_e886 + 1u);
                                                phi_1369_ = select(_e888, f32(_e908), _e899);
                                                phi_1371_ = select(_e890, f32(_e904), _e899);
                                                phi_1373_ = select(_e892, _e934, _e899);
                                                phi_1375_ = select(_e894, _e908, _e899);
                                                phi_1377_ = select(_e896, _e904, _e899);
                                            } else {
                                                phi_1366_ = u32();
                                                phi_1369_ = f32();
                                                phi_1371_ = f32();
                                                phi_1373_ = u32();
                                                phi_1375_ = u32();
                                                phi_1377_ = u32();
                                            }
                                            let _e942 = phi_1366_;
                                            let _e944 = phi_1369_;
                                            let _e946 = phi_1371_;
                                            let _e948 = phi_1373_;
                                            let _e950 = phi_1375_;
                                            let _e952 = phi_1377_;
                                            continue;
                                            continuing {
                                                phi_1365_ = _e942;
                                                phi_1368_ = _e944;
                                                phi_1370_ = _e946;
                                                phi_1372_ = _e948;
                                                phi_1374_ = _e950;
                                                phi_1376_ = _e952;
                                                break if !(_e897);
                                            }
                                        }
                                        let _e955 = local_10;
                                        let _e956 = (_e757 * _e955);
                                        if (_e956 > 0f) {
                                            let _e962 = select(select(u32(_e956), 0u, (_e956 < 0f)), 4294967295u, (_e956 > 4294967000f));
                                            let _e964 = local_11;
                                            let _e965 = (_e964 - 1u);
                                            phi_1470_ = select(_e962, _e965, (_e965 < _e962));
                                        } else {
                                            phi_1470_ = 0u;
                                        }
                                        let _e969 = phi_1470_;
                                        let _e971 = local_12;
                                        let _e972 = (_e758 * _e971);
                                        if (_e972 > 0f) {
                                            let _e978 = select(select(u32(_e972), 0u, (_e972 < 0f)), 4294967295u, (_e972 > 4294967000f));
                                            let _e980 = local_13;
                                            let _e981 = (_e980 - 1u);
                                            phi_1489_ = select(_e978, _e981, (_e981 < _e978));
                                        } else {
                                            phi_1489_ = 0u;
                                        }
                                        let _e985 = phi_1489_;
                                        let _e987 = local_14;
                                        let _e990 = local_15;
                                        let _e992 = ((_e990 + (_e985 * _e987)) + _e969);
                                        if (_e992 < _e86) {
                                        } else {
                                            phi_2714_ = true;
                                            break;
                                        }
                                        let _e996 = mips.member[_e992];
                                        let _e1005 = (((((_e755 * 2f) - 1f) * _e390) * _e876) - _e392);
                                        let _e1006 = (((((_e756 * -2f) + 1f) * _e400) * _e876) - _e402);
                                        let _e1007 = (_e876 - _e382);
                                        let _e1010 = params.member.member_1;
                                        let _e1011 = (_e1010 > 0f);
                                        if _e1011 {
                                            phi_1542_ = select(true, false, (sqrt((((_e1005 * _e1005) + (_e1006 * _e1006)) + (_e1007 * _e1007))) > _e1010));
                                        } else {
                                            phi_1542_ = true;
                                        }
                                        let _e1021 = phi_1542_;
                                        if _e1021 {
                                            let _e1024 = params.member.member;
                                            let _e1027 = params.member.member_3;
                                            let _e1032 = (((_e1005 * _e413) + (_e1006 * _e414)) + (_e1007 * _e415));
                                            let _e1036 = (_e1005 - (_e413 * _e1032));
                                            let _e1037 = (_e1006 - (_e414 * _e1032));
                                            let _e1038 = (_e1007 - (_e415 * _e1032));
                                            if (sqrt((((_e1036 * _e1036) + (_e1037 * _e1037)) + (_e1038 * _e1038))) <= 0f) {
                                                phi_1847_ = 0u;
                                            } else {
                                                let _e1048 = ((_e1037 * _e415) - (_e414 * _e1038));
                                                let _e1051 = ((_e1038 * _e413) - (_e415 * _e1036));
                                                let _e1054 = ((_e1036 * _e414) - (_e413 * _e1037));
                                                let _e1061 = (1f / sqrt((((_e1048 * _e1048) + (_e1051 * _e1051)) + (_e1054 * _e1054))));
                                                let _e1062 = (_e1048 * _e1061);
                                                let _e1063 = (_e1051 * _e1061);
                                                let _e1064 = (_e1054 * _e1061);
                                                let _e1069 = (((_e488.x * _e1062) + (_e488.y * _e1063)) + (_e488.z * _e1064));
                                                let _e1073 = (_e488.x - (_e1062 * _e1069));
                                                let _e1074 = (_e488.y - (_e1063 * _e1069));
                                                let _e1075 = (_e488.z - (_e1064 * _e1069));
                                                let _e1081 = sqrt((((_e1073 * _e1073) + (_e1074 * _e1074)) + (_e1075 * _e1075)));
                                                let _e1087 = ((((_e1073 * _e413) + (_e1074 * _e414)) + (_e1075 * _e415)) / _e1081);
                                                let _e1091 = select(0f, select(1f, _e1087, (_e1087 < 1f)), (_e1087 > 0f));
                                                if ((((_e1036 * _e1073) + (_e1037 * _e1074)) + (_e1038 * _e1075)) < 0f) {
                                                    phi_1658_ = -(acos(_e1091));
                                                } else {
                                                    phi_1658_ = acos(_e1091);
                                                }
                                                let _e1102 = phi_1658_;
                                                let _e1103 = (0.02f / _e1081);
                                                if (_e1103 != _e1103) {
                                                    phi_2619_ = true;
                                                } else {
                                                    phi_2619_ = (0.19634955f <= _e1103);
                                                }
                                                let _e1107 = phi_2619_;
                                                let _e1108 = select(_e1103, 0.19634955f, _e1107);
                                                let _e1112 = (_e1005 - (_e413 * _e1024));
                                                let _e1113 = (_e1006 - (_e414 * _e1024));
                                                let _e1114 = (_e1007 - (_e415 * _e1024));
                                                let _e1121 = (1f / sqrt((((_e1005 * _e1005) + (_e1006 * _e1006)) + (_e1007 * _e1007))));
                                                let _e1129 = ((((_e1005 * _e1121) * _e413) + ((_e1006 * _e1121) * _e414)) + ((_e1007 * _e1121) * _e415));
                                                let _e1138 = ((((acos(select(-1f, select(1f, _e1129, (_e1129 < 1f)), (_e1129 > -1f))) + _e1108) - _e1102) + 1.5707964f) * 0.31830987f);
                                                let _e1142 = select(0f, select(1f, _e1138, (_e1138 < 1f)), (_e1138 > 0f));
                                                let _e1149 = (1f / sqrt((((_e1112 * _e1112) + (_e1113 * _e1113)) + (_e1114 * _e1114))));
                                                let _e1157 = ((((_e1112 * _e1149) * _e413) + ((_e1113 * _e1149) * _e414)) + ((_e1114 * _e1149) * _e415));
                                                let _e1166 = ((((acos(select(-1f, select(1f, _e1157, (_e1157 < 1f)), (_e1157 > -1f))) + _e1108) - _e1102) + 1.5707964f) * 0.31830987f);
                                                let _e1170 = select(0f, select(1f, _e1166, (_e1166 < 1f)), (_e1166 > 0f));
                                                let _e1171 = (_e1142 != _e1142);
                                                if _e1171 {
                                                    phi_2634_ = true;
                                                } else {
                                                    phi_2634_ = (_e1170 <= _e1142);
                                                }
                                                let _e1174 = phi_2634_;
                                                let _e1175 = select(_e1142, _e1170, _e1174);
                                                if _e1171 {
                                                    phi_2649_ = true;
                                                } else {
                                                    phi_2649_ = (_e1170 >= _e1142);
                                                }
                                                let _e1178 = phi_2649_;
                                                let _e1179 = select(_e1142, _e1170, _e1178);
                                                let _e1181 = floor((32f * _e1175));
                                                let _e1186 = select(select(u32(_e1181), 0u, (_e1181 < 0f)), 4294967295u, (_e1181 > 4294967000f));
                                                if (_e1027 == 1u) {
                                                    let _e1196 = (_e1179 <= _e1175);
                                                    if _e1196 {
                                                        phi_1804_ = u32();
                                                    } else {
                                                        let _e1198 = ceil((32f * _e1179));
                                                        let _e1203 = select(select(u32(_e1198), 0u, (_e1198 < 0f)), 4294967295u, (_e1198 > 4294967000f));
                                                        let _e1205 = select(_e1203, 32u, (32u < _e1203));
                                                        if (_e1205 > _e1186) {
                                                            phi_1803_ = (_e1205 - _e1186);
                                                        } else {
                                                            phi_1803_ = 0u;
                                                        }
                                                        let _e1209 = phi_1803_;
                                                        phi_1804_ = _e1209;
                                                    }
                                                    let _e1211 = phi_1804_;
                                                    phi_1816_ = _e1211;
                                                    phi_1817_ = select(true, false, _e1196);
                                                } else {
                                                    let _e1190 = ceil((32f * (_e1179 - _e1175)));
                                                    phi_1816_ = select(select(u32(_e1190), 0u, (_e1190 < 0f)), 4294967295u, (_e1190 > 4294967000f));
                                                    phi_1817_ = true;
                                                }
                                                let _e1214 = phi_1816_;
                                                let _e1216 = phi_1817_;
                                                if _e1216 {
                                                    if (_e1186 >= 32u) {
                                                        phi_1840_ = u32();
                                                        phi_1841_ = true;
                                                    } else {
                                                        let _e1218 = (_e1214 == 0u);
                                                        if _e1218 {
                                                            phi_1839_ = u32();
                                                        } else {
                                                            if (_e1214 >= 32u) {
                                                                phi_1836_ = 4294967295u;
                                                            } else {
                                                                phi_1836_ = ((1u << bitcast<u32>((_e1214 & 31u))) - 1u);
                                                            }
                                                            let _e1225 = phi_1836_;
                                                            phi_1839_ = (_e1225 << bitcast<u32>((_e1186 & 31u)));
                                                        }
                                                        let _e1230 = phi_1839_;
                                                        phi_1840_ = _e1230;
                                                        phi_1841_ = _e1218;
                                                    }
                                                    let _e1232 = phi_1840_;
                                                    let _e1234 = phi_1841_;
                                                    phi_1846_ = select(_e1232, 0u, _e1234);
                                                } else {
                                                    phi_1846_ = 0u;
                                                }
                                                let _e1237 = phi_1846_;
                                                phi_1847_ = _e1237;
                                            }
                                            let _e1239 = phi_1847_;
                                            phi_1848_ = _e1239;
                                        } else {
                                            phi_1848_ = 0u;
                                        }
                                        let _e1241 = phi_1848_;
                                        let _e1243 = (((((_e757 * 2f) - 1f) * _e390) * _e996) - _e392);
                                        let _e1244 = (((((_e758 * -2f) + 1f) * _e400) * _e996) - _e402);
                                        let _e1245 = (_e996 - _e382);
                                        if _e1011 {
                                            phi_1876_ = select(true, false, (sqrt((((_e1243 * _e1243) + (_e1244 * _e1244)) + (_e1245 * _e1245))) > _e1010));
                                        } else {
                                            phi_1876_ = true;
                                        }
                                        let _e1255 = phi_1876_;
                                        if _e1255 {
                                            let _e1258 = params.member.member;
                                            let _e1261 = params.member.member_3;
                                            let _e1266 = (((_e1243 * _e413) + (_e1244 * _e414)) + (_e1245 * _e415));
                                            let _e1270 = (_e1243 - (_e413 * _e1266));
                                            let _e1271 = (_e1244 - (_e414 * _e1266));
                                            let _e1272 = (_e1245 - (_e415 * _e1266));
                                            if (sqrt((((_e1270 * _e1270) + (_e1271 * _e1271)) + (_e1272 * _e1272))) <= 0f) {
                                                phi_2181_ = 0u;
                                            } else {
                                                let _e1282 = ((_e1271 * _e415) - (_e414 * _e1272));
                                                let _e1285 = ((_e1272 * _e413) - (_e415 * _e1270));
                                                let _e1288 = ((_e1270 * _e414) - (_e413 * _e1271));
                                                let _e1295 = (1f / sqrt((((_e1282 * _e1282) + (_e1285 * _e1285)) + (_e1288 * _e1288))));
                                                let _e1296 = (_e1282 * _e1295);
                                                let _e1297 = (_e1285 * _e1295);
                                                let _e1298 = (_e1288 * _e1295);
                                                let _e1303 = (((_e488.x * _e1296) + (_e488.y * _e1297)) + (_e488.z * _e1298));
                                                let _e1307 = (_e488.x - (_e1296 * _e1303));
                                                let _e1308 = (_e488.y - (_e1297 * _e1303));
                                                let _e1309 = (_e488.z - (_e1298 * _e1303));
                                                let _e1315 = sqrt((((_e1307 * _e1307) + (_e1308 * _e1308)) + (_e1309 * _e1309)));
                                                let _e1321 = ((((_e1307 * _e413) + (_e1308 * _e414)) + (_e1309 * _e415)) / _e1315);
                                                let _e1325 = select(0f, select(1f, _e1321, (_e1321 < 1f)), (_e1321 > 0f));
                                                if ((((_e1270 * _e1307) + (_e1271 * _e1308)) + (_e1272 * _e1309)) < 0f) {
                                                    phi_1992_ = -(acos(_e1325));
                                                } else {
                                                    phi_1992_ = acos(_e1325);
                                                }
                                                let _e1336 = phi_1992_;
                                                let _e1337 = (0.02f / _e1315);
                                                if (_e1337 != _e1337) {
                                                    phi_2664_ = true;
                                                } else {
                                                    phi_2664_ = (0.19634955f <= _e1337);
                                                }
                                                let _e1341 = phi_2664_;
                                                let _e1342 = select(_e1337, 0.19634955f, _e1341);
                                                let _e1346 = (_e1243 - (_e413 * _e1258));
                                                let _e1347 = (_e1244 - (_e414 * _e1258));
                                                let _e1348 = (_e1245 - (_e415 * _e1258));
                                                let _e1355 = (1f / sqrt((((_e1243 * _e1243) + (_e1244 * _e1244)) + (_e1245 * _e1245))));
                                                let _e1363 = ((((_e1243 * _e1355) * _e413) + ((_e1244 * _e1355) * _e414)) + ((_e1245 * _e1355) * _e415));
                                                let _e1372 = ((((acos(select(-1f, select(1f, _e1363, (_e1363 < 1f)), (_e1363 > -1f))) + _e1342) - _e1336) + 1.5707964f) * 0.31830987f);
                                                let _e1383 = (1f / sqrt((((_e1346 * _e1346) + (_e1347 * _e1347)) + (_e1348 * _e1348))));
                                                let _e1391 = ((((_e1346 * _e1383) * _e413) + ((_e1347 * _e1383) * _e414)) + ((_e1348 * _e1383) * _e415));
                                                let _e1400 = ((((acos(select(-1f, select(1f, _e1391, (_e1391 < 1f)), (_e1391 > -1f))) + _e1342) - _e1336) + 1.5707964f) * 0.31830987f);
                                                let _e1405 = (1f - select(0f, select(1f, _e1372, (_e1372 < 1f)), (_e1372 > 0f)));
                                                let _e1406 = (1f - select(0f, select(1f, _e1400, (_e1400 < 1f)), (_e1400 > 0f)));
                                                let _e1407 = (_e1405 != _e1405);
                                                if _e1407 {
                                                    phi_2679_ = true;
                                                } else {
                                                    phi_2679_ = (_e1406 <= _e1405);
                                                }
                                                let _e1410 = phi_2679_;
                                                let _e1411 = select(_e1405, _e1406, _e1410);
                                                if _e1407 {
                                                    phi_2694_ = true;
                                                } else {
                                                    phi_2694_ = (_e1406 >= _e1405);
                                                }
                                                let _e1414 = phi_2694_;
                                                let _e1415 = select(_e1405, _e1406, _e1414);
                                                let _e1417 = floor((32f * _e1411));
                                                let _e1422 = select(select(u32(_e1417), 0u, (_e1417 < 0f)), 4294967295u, (_e1417 > 4294967000f));
                                                if (_e1261 == 1u) {
                                                    let _e1432 = (_e1415 <= _e1411);
                                                    if _e1432 {
                                                        phi_2138_ = u32();
                                                    } else {
                                                        let _e1434 = ceil((32f * _e1415));
                                                        let _e1439 = select(select(u32(_e1434), 0u, (_e1434 < 0f)), 4294967295u, (_e1434 > 4294967000f));
                                                        let _e1441 = select(_e1439, 32u, (32u < _e1439));
                                                        if (_e1441 > _e1422) {
                                                            phi_2137_ = (_e1441 - _e1422);
                                                        } else {
                                                            phi_2137_ = 0u;
                                                        }
                                                        let _e1445 = phi_2137_;
                                                        phi_2138_ = _e1445;
                                                    }
                                                    let _e1447 = phi_2138_;
                                                    phi_2150_ = _e1447;
                                                    phi_2151_ = select(true, false, _e1432);
                                                } else {
                                                    let _e1426 = ceil((32f * (_e1415 - _e1411)));
                                                    phi_2150_ = select(select(u32(_e1426), 0u, (_e1426 < 0f)), 4294967295u, (_e1426 > 4294967000f));
                                                    phi_2151_ = true;
                                                }
                                                let _e1450 = phi_2150_;
                                                let _e1452 = phi_2151_;
                                                if _e1452 {
                                                    if (_e1422 >= 32u) {
                                                        phi_2174_ = u32();
                                                        phi_2175_ = true;
                                                    } else {
                                                        let _e1454 = (_e1450 == 0u);
                                                        if _e1454 {
                                                            phi_2173_ = u32();
                                                        } else {
                                                            if (_e1450 >= 32u) {
                                                                phi_2170_ = 4294967295u;
                                                            } else {
                                                                phi_2170_ = ((1u << bitcast<u32>((_e1450 & 31u))) - 1u);
                                                            }
                                                            let _e1461 = phi_2170_;
                                                            phi_2173_ = (_e1461 << bitcast<u32>((_e1422 & 31u)));
                                                        }
                                                        let _e1466 = phi_2173_;
                                                        phi_2174_ = _e1466;
                                                        phi_2175_ = _e1454;
                                                    }
                                                    let _e1468 = phi_2174_;
                                                    let _e1470 = phi_2175_;
                                                    phi_2180_ = select(_e1468, 0u, _e1470);
                                                } else {
                                                    phi_2180_ = 0u;
                                                }
                                                let _e1473 = phi_2180_;
                                                phi_2181_ = _e1473;
                                            }
                                            let _e1475 = phi_2181_;
                                            phi_2182_ = _e1475;
                                        } else {
                                            phi_2182_ = 0u;
                                        }
                                        let _e1477 = phi_2182_;
                                        phi_1034_ = (_e675 + 1u);
                                        phi_1037_ = ((_e677 | _e1241) | _e1477);
                                    } else {
                                        phi_1034_ = u32();
                                        phi_1037_ = u32();
                                    }
                                    let _e1481 = phi_1034_;
                                    let _e1483 = phi_1037_;
                                    continue;
                                    continuing {
                                        phi_1033_ = _e1481;
                                        phi_1036_ = _e1483;
                                        phi_2714_ = _e581;
                                        break if !(_e678);
                                    }
                                }
                                let _e1486 = phi_2714_;
                                phi_2900_ = _e1486;
                                if _e1486 {
                                    break;
                                }
                                let _e1489 = params.member.member_2;
                                if (_e1489 == 2u) {
                                    let _e1545 = (_e667 - 1.5707964f);
                                    let _e1546 = (_e1545 * 2f);
                                    let _e1547 = sin(_e667);
                                    let _e1552 = ((_e665 + (_e1546 * _e1547)) - cos((_e1546 - _e667)));
                                    if (_e1545 < 0f) {
                                        phi_2211_ = (_e1552 * -0.25f);
                                    } else {
                                        phi_2211_ = (_e1552 * 0.25f);
                                    }
                                    let _e1557 = phi_2211_;
                                    phi_2213_ = 0u;
                                    phi_2216_ = _e1557;
                                    phi_2218_ = 0f;
                                    loop {
                                        let _e1559 = phi_2213_;
                                        let _e1561 = phi_2216_;
                                        let _e1563 = phi_2218_;
                                        local_20 = _e1563;
                                        let _e1564 = (_e1559 < 32u);
                                        if _e1564 {
                                            let _e1565 = (_e1559 + 1u);
                                            let _e1568 = (_e1545 + (f32(_e1565) * 0.09817477f));
                                            let _e1569 = (_e1568 * 2f);
                                            let _e1574 = ((_e665 + (_e1569 * _e1547)) - cos((_e1569 - _e667)));
                                            if (_e1568 < 0f) {
                                                phi_2244_ = (_e1574 * -0.25f);
                                            } else {
                                                phi_2244_ = (_e1574 * 0.25f);
                                            }
                                            let _e1579 = phi_2244_;
                                            let _e1582 = local_19;
                                            if (((_e1582 >> bitcast<u32>((_e1559 & 31u))) & 1u) == 0u) {
                                                phi_2254_ = (_e1563 + (_e1579 - _e1561));
                                            } else {
                                                phi_2254_ = _e1563;
                                            }
                                            let _e1590 = phi_2254_;
                                            phi_2214_ = _e1565;
                                            phi_2217_ = _e1579;
                                            phi_2219_ = _e1590;
                                        } else {
                                            phi_2214_ = u32();
                                            phi_2217_ = f32();
                                            phi_2219_ = f32();
                                        }
                                        let _e1592 = phi_2214_;
                                        let _e1594 = phi_2217_;
                                        let _e1596 = phi_2219_;
                                        continue;
                                        continuing {
                                            phi_2213_ = _e1592;
                                            phi_2216_ = _e1594;
                                            phi_2218_ = _e1596;
                                            break if !(_e1564);
                                        }
                                    }
                                    let _e1599 = local_20;
                                    phi_2902_ = _e1486;
                                    phi_2318_ = (_e585 + 1f);
                                    phi_2319_ = (_e587 + ((_e646 + ((1f - _e646) * 0.05f)) * _e1599));
                                } else {
                                    if (_e1489 == 1u) {
                                        phi_2266_ = 0u;
                                        phi_2269_ = 0f;
                                        loop {
                                            let _e1501 = phi_2266_;
                                            let _e1503 = phi_2269_;
                                            local_18 = _e1503;
                                            let _e1504 = (_e1501 < 4u);
                                            if _e1504 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1504 {
                                                } else {
                                                    phi_2897_ = true;
                                                    break;
                                                }
                                                let _e1507 = local[_e1501].member;
                                                let _e1510 = local[_e1501].member_1;
                                                let _e1512 = local_17;
                                                phi_2267_ = (_e1501 + 1u);
                                                phi_2270_ = (_e1503 + (f32(countOneBits((_e1512 & _e1507))) * _e1510));
                                            } else {
                                                phi_2267_ = u32();
                                                phi_2270_ = f32();
                                            }
                                            let _e1520 = phi_2267_;
                                            let _e1522 = phi_2270_;
                                            continue;
                                            continuing {
                                                phi_2266_ = _e1520;
                                                phi_2269_ = _e1522;
                                                phi_2897_ = _e1486;
                                                break if !(_e1504);
                                            }
                                        }
                                        let _e1525 = phi_2897_;
                                        phi_2900_ = _e1525;
                                        if _e1525 {
                                            break;
                                        }
                                        let _e1527 = local_18;
                                        let _e1528 = (1f - _e1527);
                                        phi_2908_ = _e1525;
                                        phi_2316_ = (_e585 + _e646);
                                        phi_2317_ = (_e587 + (_e646 * select(0f, select(1f, _e1528, (_e1528 < 1f)), (_e1528 > 0f))));
                                    } else {
                                        let _e1493 = local_16;
                                        phi_2908_ = _e1486;
                                        phi_2316_ = (_e585 + 1f);
                                        phi_2317_ = (_e587 + (1f - (f32(countOneBits(_e1493)) * 0.03125f)));
                                    }
                                    let _e1537 = phi_2908_;
                                    let _e1539 = phi_2316_;
                                    let _e1541 = phi_2317_;
                                    phi_2902_ = _e1537;
                                    phi_2318_ = _e1539;
                                    phi_2319_ = _e1541;
                                }
                                let _e1604 = phi_2902_;
                                let _e1606 = phi_2318_;
                                let _e1608 = phi_2319_;
                                phi_2901_ = _e1604;
                                phi_859_ = (_e583 + 1u);
                                phi_862_ = _e1606;
                                phi_864_ = _e1608;
                            } else {
                                phi_2901_ = _e581;
                                phi_859_ = u32();
                                phi_862_ = f32();
                                phi_864_ = f32();
                            }
                            let _e1611 = phi_2901_;
                            let _e1613 = phi_859_;
                            let _e1615 = phi_862_;
                            let _e1617 = phi_864_;
                            continue;
                            continuing {
                                phi_2780_ = _e1611;
                                phi_858_ = _e1613;
                                phi_861_ = _e1615;
                                phi_863_ = _e1617;
                                phi_2900_ = _e1611;
                                break if !(_e588);
                            }
                        }
                        let _e1620 = phi_2900_;
                        if _e1620 {
                            break;
                        }
                        let _e1622 = local_21;
                        if (_e1622 > 0f) {
                            let _e1625 = local_22;
                            let _e1627 = local_23;
                            phi_2326_ = (_e1625 / _e1627);
                        } else {
                            phi_2326_ = 1f;
                        }
                        let _e1630 = phi_2326_;
                        let _e1634 = params.member.member_4.member_6;
                        let _e1635 = pow(_e1630, _e1634);
                        if (_e1635 != _e1635) {
                            phi_2709_ = true;
                        } else {
                            phi_2709_ = (0.03f >= _e1635);
                        }
                        let _e1639 = phi_2709_;
                        let _e1641 = (select(_e1635, 0.03f, _e1639) * 0.6666667f);
                        let _e1647 = ((select(0f, select(1f, _e1641, (_e1641 < 1f)), (_e1641 > 0f)) * 255f) + 0.5f);
                        phi_2374_ = type_28(select(select(u32(_e1647), 0u, (_e1647 < 0f)), 4294967295u, (_e1647 > 4294967000f)), _e375);
                    } else {
                        phi_2374_ = type_28(170u, _e375);
                    }
                    let _e1655 = phi_2374_;
                    if (_e120 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e120] = _e1655.member;
                    if (_e120 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e120] = _e1655.member_1;
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
