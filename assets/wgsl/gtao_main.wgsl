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
    member: type_20,
}

struct type_23 {
    member: f32,
    member_1: vec3<f32>,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(4) 
var<uniform> params: type_21;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_293_: i32;
    var phi_312_: i32;
    var phi_353_: i32;
    var phi_372_: i32;
    var phi_413_: i32;
    var phi_432_: i32;
    var phi_473_: i32;
    var phi_492_: i32;
    var phi_2119_: bool;
    var phi_2134_: bool;
    var phi_2149_: bool;
    var phi_2164_: bool;
    var phi_2195_: f32;
    var phi_2199_: f32;
    var phi_2200_: bool;
    var phi_2222_: u32;
    var phi_2249_: f32;
    var phi_2253_: f32;
    var phi_2254_: bool;
    var phi_2276_: u32;
    var phi_2303_: f32;
    var phi_2307_: f32;
    var phi_2308_: bool;
    var phi_2330_: u32;
    var phi_2357_: f32;
    var phi_2361_: f32;
    var phi_2362_: bool;
    var phi_2384_: u32;
    var phi_2464_: bool;
    var phi_2479_: bool;
    var phi_2439_: vec2<f32>;
    var phi_2496_: u32;
    var phi_2497_: u32;
    var phi_2498_: u32;
    var phi_2499_: u32;
    var phi_2522_: u32;
    var phi_2523_: u32;
    var phi_2526_: u32;
    var phi_2527_: u32;
    var phi_2531_: u32;
    var phi_2532_: u32;
    var phi_2533_: u32;
    var phi_2534_: u32;
    var local: u32;
    var phi_2868_: bool;
    var phi_767_: u32;
    var phi_770_: vec3<f32>;
    var phi_772_: f32;
    var phi_943_: u32;
    var phi_946_: f32;
    var phi_948_: f32;
    var phi_1002_: f32;
    var phi_1047_: f32;
    var phi_1049_: f32;
    var phi_1050_: bool;
    var phi_1073_: f32;
    var phi_1075_: f32;
    var phi_1076_: bool;
    var phi_1109_: u32;
    var phi_1112_: f32;
    var phi_1114_: f32;
    var phi_1116_: u32;
    var phi_1118_: u32;
    var phi_1120_: u32;
    var phi_1153_: u32;
    var phi_1156_: u32;
    var phi_1154_: u32;
    var phi_1157_: u32;
    var local_1: u32;
    var phi_1110_: u32;
    var phi_1113_: f32;
    var phi_1115_: f32;
    var phi_1117_: u32;
    var phi_1119_: u32;
    var phi_1121_: u32;
    var local_2: f32;
    var local_3: u32;
    var phi_1214_: u32;
    var local_4: f32;
    var local_5: u32;
    var phi_1233_: u32;
    var local_6: u32;
    var local_7: u32;
    var phi_1277_: u32;
    var phi_1280_: f32;
    var phi_1282_: f32;
    var phi_1284_: u32;
    var phi_1286_: u32;
    var phi_1288_: u32;
    var phi_1321_: u32;
    var phi_1324_: u32;
    var phi_1322_: u32;
    var phi_1325_: u32;
    var local_8: u32;
    var phi_1278_: u32;
    var phi_1281_: f32;
    var phi_1283_: f32;
    var phi_1285_: u32;
    var phi_1287_: u32;
    var phi_1289_: u32;
    var local_9: f32;
    var local_10: u32;
    var phi_1382_: u32;
    var local_11: f32;
    var local_12: u32;
    var phi_1401_: u32;
    var local_13: u32;
    var local_14: u32;
    var phi_1484_: f32;
    var phi_1544_: f32;
    var phi_2568_: bool;
    var phi_2583_: bool;
    var phi_944_: u32;
    var phi_947_: f32;
    var phi_949_: f32;
    var phi_2800_: bool;
    var local_15: f32;
    var local_16: f32;
    var local_17: f32;
    var local_18: f32;
    var phi_1763_: vec3<f32>;
    var phi_2950_: bool;
    var phi_768_: u32;
    var phi_771_: vec3<f32>;
    var phi_773_: f32;
    var phi_2949_: bool;
    var local_19: f32;
    var local_20: vec3<f32>;
    var phi_1769_: type_23;
    var phi_2610_: bool;
    var phi_1824_: vec3<f32>;
    var phi_1845_: u32;
    var phi_1890_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e84 = id_1;
            let _e87 = arrayLength((&mips.member));
            let _e98 = params.member.member.member[0u];
            let _e103 = select(select(u32(_e98), 0u, (_e98 < 0f)), 4294967295u, (_e98 > 4294967000f));
            let _e108 = params.member.member.member[1u];
            let _e113 = select(select(u32(_e108), 0u, (_e108 < 0f)), 4294967295u, (_e108 > 4294967000f));
            if (_e84.x >= _e103) {
            } else {
                if (_e84.y >= _e113) {
                } else {
                    let _e119 = ((_e84.y * _e103) + _e84.x);
                    if (_e119 < _e87) {
                    } else {
                        break;
                    }
                    let _e122 = mips.member[_e119];
                    let _e123 = bitcast<i32>(_e84.x);
                    let _e124 = (_e123 + -1i);
                    let _e126 = (bitcast<i32>(_e103) - 1i);
                    let _e127 = (0i <= _e126);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e124 < 0i) {
                        phi_293_ = 0i;
                    } else {
                        phi_293_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_293_;
                    let _e134 = bitcast<i32>(_e84.y);
                    let _e136 = (bitcast<i32>(_e113) - 1i);
                    let _e137 = (0i <= _e136);
                    if _e137 {
                    } else {
                        break;
                    }
                    let _e138 = (_e134 < 0i);
                    if _e138 {
                        phi_312_ = 0i;
                    } else {
                        phi_312_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e142 = phi_312_;
                    let _e145 = ((bitcast<u32>(_e142) * _e103) + bitcast<u32>(_e132));
                    if (_e145 < _e87) {
                    } else {
                        break;
                    }
                    let _e148 = mips.member[_e145];
                    let _e149 = (_e123 + 1i);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e149 < 0i) {
                        phi_353_ = 0i;
                    } else {
                        phi_353_ = select(_e149, _e126, (_e149 > _e126));
                    }
                    let _e154 = phi_353_;
                    if _e137 {
                    } else {
                        break;
                    }
                    if _e138 {
                        phi_372_ = 0i;
                    } else {
                        phi_372_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e159 = phi_372_;
                    let _e162 = ((bitcast<u32>(_e159) * _e103) + bitcast<u32>(_e154));
                    if (_e162 < _e87) {
                    } else {
                        break;
                    }
                    let _e165 = mips.member[_e162];
                    if _e127 {
                    } else {
                        break;
                    }
                    let _e166 = (_e123 < 0i);
                    if _e166 {
                        phi_413_ = 0i;
                    } else {
                        phi_413_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e170 = phi_413_;
                    let _e172 = (_e134 + -1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e172 < 0i) {
                        phi_432_ = 0i;
                    } else {
                        phi_432_ = select(_e172, _e136, (_e172 > _e136));
                    }
                    let _e177 = phi_432_;
                    let _e180 = ((bitcast<u32>(_e177) * _e103) + bitcast<u32>(_e170));
                    if (_e180 < _e87) {
                    } else {
                        break;
                    }
                    let _e183 = mips.member[_e180];
                    if _e127 {
                    } else {
                        break;
                    }
                    if _e166 {
                        phi_473_ = 0i;
                    } else {
                        phi_473_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e187 = phi_473_;
                    let _e189 = (_e134 + 1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e189 < 0i) {
                        phi_492_ = 0i;
                    } else {
                        phi_492_ = select(_e189, _e136, (_e189 > _e136));
                    }
                    let _e194 = phi_492_;
                    let _e197 = ((bitcast<u32>(_e194) * _e103) + bitcast<u32>(_e187));
                    if (_e197 < _e87) {
                    } else {
                        break;
                    }
                    let _e200 = mips.member[_e197];
                    let _e201 = (_e148 - _e122);
                    let _e202 = (_e165 - _e122);
                    let _e203 = (_e183 - _e122);
                    let _e204 = (_e200 - _e122);
                    let _e206 = ((_e202 - _e201) * 0.5f);
                    let _e208 = ((_e204 - _e203) * 0.5f);
                    let _e209 = (_e122 * 0.011f);
                    let _e211 = abs(_e201);
                    let _e212 = abs((_e201 + _e206));
                    if (_e211 != _e211) {
                        phi_2119_ = true;
                    } else {
                        phi_2119_ = (_e212 <= _e211);
                    }
                    let _e216 = phi_2119_;
                    let _e219 = (1.25f - (select(_e211, _e212, _e216) / _e209));
                    let _e223 = select(0f, select(1f, _e219, (_e219 < 1f)), (_e219 > 0f));
                    let _e225 = abs(_e202);
                    let _e226 = abs((_e202 - _e206));
                    if (_e225 != _e225) {
                        phi_2134_ = true;
                    } else {
                        phi_2134_ = (_e226 <= _e225);
                    }
                    let _e230 = phi_2134_;
                    let _e233 = (1.25f - (select(_e225, _e226, _e230) / _e209));
                    let _e237 = select(0f, select(1f, _e233, (_e233 < 1f)), (_e233 > 0f));
                    let _e239 = abs(_e203);
                    let _e240 = abs((_e203 + _e208));
                    if (_e239 != _e239) {
                        phi_2149_ = true;
                    } else {
                        phi_2149_ = (_e240 <= _e239);
                    }
                    let _e244 = phi_2149_;
                    let _e247 = (1.25f - (select(_e239, _e240, _e244) / _e209));
                    let _e251 = select(0f, select(1f, _e247, (_e247 < 1f)), (_e247 > 0f));
                    let _e253 = abs(_e204);
                    let _e254 = abs((_e204 - _e208));
                    if (_e253 != _e253) {
                        phi_2164_ = true;
                    } else {
                        phi_2164_ = (_e254 <= _e253);
                    }
                    let _e258 = phi_2164_;
                    let _e261 = (1.25f - (select(_e253, _e254, _e258) / _e209));
                    let _e265 = select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f));
                    let _e270 = (select(0f, select(1f, _e223, (_e223 < 1f)), (_e223 > 0f)) * 2.9f);
                    let _e272 = floor((_e270 + 0.5f));
                    if ((_e272 - _e270) == 0.5f) {
                        let _e278 = ((floor((_e272 * 0.5f)) * 2f) != _e272);
                        if _e278 {
                            phi_2195_ = (_e272 - 1f);
                        } else {
                            phi_2195_ = f32();
                        }
                        let _e281 = phi_2195_;
                        phi_2199_ = _e281;
                        phi_2200_ = select(true, false, _e278);
                    } else {
                        phi_2199_ = f32();
                        phi_2200_ = true;
                    }
                    let _e284 = phi_2199_;
                    let _e286 = phi_2200_;
                    let _e287 = select(_e284, _e272, _e286);
                    if (_e287 > 0f) {
                        let _e293 = select(select(u32(_e287), 0u, (_e287 < 0f)), 4294967295u, (_e287 > 4294967000f));
                        phi_2222_ = select(_e293, 3u, (3u < _e293));
                    } else {
                        phi_2222_ = 0u;
                    }
                    let _e297 = phi_2222_;
                    let _e303 = (select(0f, select(1f, _e237, (_e237 < 1f)), (_e237 > 0f)) * 2.9f);
                    let _e305 = floor((_e303 + 0.5f));
                    if ((_e305 - _e303) == 0.5f) {
                        let _e311 = ((floor((_e305 * 0.5f)) * 2f) != _e305);
                        if _e311 {
                            phi_2249_ = (_e305 - 1f);
                        } else {
                            phi_2249_ = f32();
                        }
                        let _e314 = phi_2249_;
                        phi_2253_ = _e314;
                        phi_2254_ = select(true, false, _e311);
                    } else {
                        phi_2253_ = f32();
                        phi_2254_ = true;
                    }
                    let _e317 = phi_2253_;
                    let _e319 = phi_2254_;
                    let _e320 = select(_e317, _e305, _e319);
                    if (_e320 > 0f) {
                        let _e326 = select(select(u32(_e320), 0u, (_e320 < 0f)), 4294967295u, (_e320 > 4294967000f));
                        phi_2276_ = select(_e326, 3u, (3u < _e326));
                    } else {
                        phi_2276_ = 0u;
                    }
                    let _e330 = phi_2276_;
                    let _e337 = (select(0f, select(1f, _e251, (_e251 < 1f)), (_e251 > 0f)) * 2.9f);
                    let _e339 = floor((_e337 + 0.5f));
                    if ((_e339 - _e337) == 0.5f) {
                        let _e345 = ((floor((_e339 * 0.5f)) * 2f) != _e339);
                        if _e345 {
                            phi_2303_ = (_e339 - 1f);
                        } else {
                            phi_2303_ = f32();
                        }
                        let _e348 = phi_2303_;
                        phi_2307_ = _e348;
                        phi_2308_ = select(true, false, _e345);
                    } else {
                        phi_2307_ = f32();
                        phi_2308_ = true;
                    }
                    let _e351 = phi_2307_;
                    let _e353 = phi_2308_;
                    let _e354 = select(_e351, _e339, _e353);
                    if (_e354 > 0f) {
                        let _e360 = select(select(u32(_e354), 0u, (_e354 < 0f)), 4294967295u, (_e354 > 4294967000f));
                        phi_2330_ = select(_e360, 3u, (3u < _e360));
                    } else {
                        phi_2330_ = 0u;
                    }
                    let _e364 = phi_2330_;
                    let _e371 = (select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f)) * 2.9f);
                    let _e373 = floor((_e371 + 0.5f));
                    if ((_e373 - _e371) == 0.5f) {
                        let _e379 = ((floor((_e373 * 0.5f)) * 2f) != _e373);
                        if _e379 {
                            phi_2357_ = (_e373 - 1f);
                        } else {
                            phi_2357_ = f32();
                        }
                        let _e382 = phi_2357_;
                        phi_2361_ = _e382;
                        phi_2362_ = select(true, false, _e379);
                    } else {
                        phi_2361_ = f32();
                        phi_2362_ = true;
                    }
                    let _e385 = phi_2361_;
                    let _e387 = phi_2362_;
                    let _e388 = select(_e385, _e373, _e387);
                    if (_e388 > 0f) {
                        let _e394 = select(select(u32(_e388), 0u, (_e388 < 0f)), 4294967295u, (_e388 > 4294967000f));
                        phi_2384_ = select(_e394, 3u, (3u < _e394));
                    } else {
                        phi_2384_ = 0u;
                    }
                    let _e398 = phi_2384_;
                    let _e402 = ((f32(_e84.x) + 0.5f) / _e98);
                    let _e405 = ((f32(_e84.y) + 0.5f) / _e108);
                    let _e406 = (_e122 * 0.99999f);
                    let _e413 = params.member.member.member_1[0u];
                    let _e415 = ((((_e402 * 2f) - 1f) * _e413) * _e406);
                    let _e422 = params.member.member.member_1[1u];
                    let _e424 = ((((_e405 * -2f) + 1f) * _e422) * _e406);
                    let _e425 = -(_e415);
                    let _e426 = -(_e424);
                    let _e427 = (_e122 * -0.99999f);
                    let _e434 = (1f / sqrt((((_e425 * _e425) + (_e426 * _e426)) + (_e427 * _e427))));
                    let _e435 = (_e425 * _e434);
                    let _e436 = (_e426 * _e434);
                    let _e437 = (_e427 * _e434);
                    if (_e119 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e441 = normals.member[_e119];
                    let _e449 = (f32((bitcast<i32>(((_e441 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e449 != _e449) {
                        phi_2464_ = true;
                    } else {
                        phi_2464_ = (-1f >= _e449);
                    }
                    let _e453 = phi_2464_;
                    let _e454 = select(_e449, -1f, _e453);
                    let _e464 = (f32((bitcast<i32>((((_e441 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e464 != _e464) {
                        phi_2479_ = true;
                    } else {
                        phi_2479_ = (-1f >= _e464);
                    }
                    let _e468 = phi_2479_;
                    let _e469 = select(_e464, -1f, _e468);
                    let _e472 = (1f - abs(_e454));
                    let _e473 = abs(_e469);
                    let _e474 = (_e472 - _e473);
                    if (_e474 < 0f) {
                        phi_2439_ = vec2<f32>(((1f - _e473) * select(1f, -1f, (_e454 < 0f))), (_e472 * select(1f, -1f, (_e469 < 0f))));
                    } else {
                        phi_2439_ = vec2<f32>(_e454, _e469);
                    }
                    let _e485 = phi_2439_;
                    let _e494 = (1f / sqrt((((_e485.x * _e485.x) + (_e485.y * _e485.y)) + (_e474 * _e474))));
                    let _e495 = (_e485.x * _e494);
                    let _e496 = (_e485.y * _e494);
                    let _e497 = (_e474 * _e494);
                    let _e498 = -(_e497);
                    let _e504 = ((((_e495 * _e435) + (_e496 * _e436)) + (_e498 * _e437)) < 0f);
                    let _e506 = select(_e495, -(_e495), _e504);
                    let _e508 = select(_e496, -(_e496), _e504);
                    let _e509 = select(_e498, _e497, _e504);
                    let _e513 = params.member.member_1;
                    let _e516 = params.member.member_2;
                    let _e517 = (_e513 * _e516);
                    let _e521 = (_e517 / (((_e122 * 1.99998f) * _e413) / _e98));
                    let _e525 = params.member.member_11;
                    phi_2496_ = (_e84.y & 63u);
                    phi_2497_ = (_e84.x & 63u);
                    phi_2498_ = 32u;
                    phi_2499_ = 0u;
                    loop {
                        let _e529 = phi_2496_;
                        let _e531 = phi_2497_;
                        let _e533 = phi_2498_;
                        let _e535 = phi_2499_;
                        local = _e535;
                        let _e536 = (_e533 > 0u);
                        if _e536 {
                            let _e539 = select(0u, 1u, ((_e531 & _e533) != 0u));
                            let _e542 = select(0u, 1u, ((_e529 & _e533) != 0u));
                            if (_e542 == 0u) {
                                if (_e539 == 1u) {
                                    phi_2522_ = (63u - _e529);
                                    phi_2523_ = (63u - _e531);
                                } else {
                                    phi_2522_ = _e529;
                                    phi_2523_ = _e531;
                                }
                                let _e553 = phi_2522_;
                                let _e555 = phi_2523_;
                                phi_2526_ = _e555;
                                phi_2527_ = _e553;
                            } else {
                                phi_2526_ = _e529;
                                phi_2527_ = _e531;
                            }
                            let _e557 = phi_2526_;
                            let _e559 = phi_2527_;
                            phi_2531_ = _e557;
                            phi_2532_ = _e559;
                            phi_2533_ = (_e533 / 2u);
                            phi_2534_ = (_e535 + ((_e533 * _e533) * ((3u * _e539) ^ _e542)));
                        } else {
                            phi_2531_ = u32();
                            phi_2532_ = u32();
                            phi_2533_ = u32();
                            phi_2534_ = u32();
                        }
                        let _e562 = phi_2531_;
                        let _e564 = phi_2532_;
                        let _e566 = phi_2533_;
                        let _e568 = phi_2534_;
                        continue;
                        continuing {
                            phi_2496_ = _e562;
                            phi_2497_ = _e564;
                            phi_2498_ = _e566;
                            phi_2499_ = _e568;
                            break if !(_e536);
                        }
                    }
                    let _e573 = local;
                    let _e575 = f32((_e573 + (288u * (_e525 % 64u))));
                    let _e577 = (0.5f + (_e575 * 0.7548777f));
                    let _e581 = (0.5f + (_e575 * 0.5698403f));
                    let _e587 = params.member.member.member_3;
                    let _e590 = select(false, (_e122 < _e587), (_e122 > 0f));
                    if _e590 {
                        let _e593 = params.member.member_3;
                        let _e594 = (_e593 * _e517);
                        let _e596 = ((10f - _e521) * 0.01f);
                        let _e604 = params.member.member_8;
                        let _e606 = select(1u, _e604, (1u < _e604));
                        phi_2868_ = false;
                        phi_767_ = 0u;
                        phi_770_ = vec3<f32>(0f, 0f, 0f);
                        phi_772_ = (select(0f, select(1f, _e596, (_e596 < 1f)), (_e596 > 0f)) * 0.5f);
                        loop {
                            let _e608 = phi_2868_;
                            let _e610 = phi_767_;
                            let _e612 = phi_770_;
                            let _e614 = phi_772_;
                            local_19 = _e614;
                            local_20 = _e612;
                            let _e615 = (_e610 < _e606);
                            if _e615 {
                                let _e620 = ((((_e577 - floor(_e577)) + f32(_e610)) * 3.1415927f) / f32(_e606));
                                let _e621 = sin(_e620);
                                let _e622 = cos(_e620);
                                let _e628 = ((_e622 * _e435) + (_e621 * _e436));
                                let _e632 = (_e622 - (_e435 * _e628));
                                let _e633 = (_e621 - (_e436 * _e628));
                                let _e634 = -((_e437 * _e628));
                                let _e637 = ((_e633 * _e437) - (_e436 * _e634));
                                let _e640 = ((_e634 * _e435) - (_e437 * _e632));
                                let _e643 = ((_e632 * _e436) - (_e435 * _e633));
                                let _e650 = (1f / sqrt((((_e637 * _e637) + (_e640 * _e640)) + (_e643 * _e643))));
                                let _e651 = (_e637 * _e650);
                                let _e652 = (_e640 * _e650);
                                let _e653 = (_e643 * _e650);
                                let _e658 = (((_e506 * _e651) + (_e508 * _e652)) + (_e509 * _e653));
                                let _e662 = (_e506 - (_e651 * _e658));
                                let _e663 = (_e508 - (_e652 * _e658));
                                let _e664 = (_e509 - (_e653 * _e658));
                                let _e670 = sqrt((((_e662 * _e662) + (_e663 * _e663)) + (_e664 * _e664)));
                                let _e675 = (((_e632 * _e662) + (_e633 * _e663)) + (_e634 * _e664));
                                let _e685 = ((((_e662 * _e435) + (_e663 * _e436)) + (_e664 * _e437)) / _e670);
                                let _e689 = select(0f, select(1f, _e685, (_e685 < 1f)), (_e685 > 0f));
                                let _e690 = abs(_e689);
                                let _e701 = (((_e690 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e690))) >> bitcast<u32>(1i))))));
                                let _e705 = (select(select(0f, -1f, (_e675 < 0f)), 1f, (_e675 > 0f)) * select((3.141593f - _e701), _e701, (_e689 >= 0f)));
                                let _e708 = params.member.member_9;
                                let _e710 = select(1u, _e708, (1u < _e708));
                                let _e712 = cos((_e705 + 1.5707964f));
                                let _e714 = cos((_e705 - 1.5707964f));
                                let _e717 = params.member.member_5;
                                phi_943_ = 0u;
                                phi_946_ = _e714;
                                phi_948_ = _e712;
                                loop {
                                    let _e719 = phi_943_;
                                    let _e721 = phi_946_;
                                    let _e723 = phi_948_;
                                    local_15 = _e721;
                                    local_16 = _e721;
                                    local_17 = _e723;
                                    local_18 = _e723;
                                    let _e724 = (_e719 < _e710);
                                    if _e724 {
                                        let _e729 = ((_e581 - floor(_e581)) + (f32((_e610 + (_e719 * _e710))) * 0.618034f));
                                        let _e735 = (((_e729 - floor(_e729)) + f32(_e719)) / f32(_e710));
                                        let _e738 = params.member.member_4;
                                        if (_e738 == 2f) {
                                            phi_1002_ = (_e735 * _e735);
                                        } else {
                                            phi_1002_ = pow(_e735, _e738);
                                        }
                                        let _e743 = phi_1002_;
                                        let _e744 = (_e743 + (1.3f / _e521));
                                        let _e745 = ((_e622 * _e521) * _e744);
                                        let _e746 = ((-(_e621) * _e521) * _e744);
                                        let _e754 = params.member.member_7;
                                        let _e755 = (log2(sqrt(((_e745 * _e745) + (_e746 * _e746)))) - _e754);
                                        let _e762 = (-1f - floor((-0.5f - select(0f, select(5f, _e755, (_e755 < 5f)), (_e755 > 0f)))));
                                        let _e764 = floor((_e745 + 0.5f));
                                        if ((_e764 - _e745) == 0.5f) {
                                            let _e770 = ((floor((_e764 * 0.5f)) * 2f) != _e764);
                                            if _e770 {
                                                phi_1047_ = (_e764 - 1f);
                                            } else {
                                                phi_1047_ = f32();
                                            }
                                            let _e773 = phi_1047_;
                                            phi_1049_ = _e773;
                                            phi_1050_ = select(true, false, _e770);
                                        } else {
                                            phi_1049_ = f32();
                                            phi_1050_ = true;
                                        }
                                        let _e776 = phi_1049_;
                                        let _e778 = phi_1050_;
                                        let _e780 = (select(_e776, _e764, _e778) / _e98);
                                        let _e782 = floor((_e746 + 0.5f));
                                        if ((_e782 - _e746) == 0.5f) {
                                            let _e788 = ((floor((_e782 * 0.5f)) * 2f) != _e782);
                                            if _e788 {
                                                phi_1073_ = (_e782 - 1f);
                                            } else {
                                                phi_1073_ = f32();
                                            }
                                            let _e791 = phi_1073_;
                                            phi_1075_ = _e791;
                                            phi_1076_ = select(true, false, _e788);
                                        } else {
                                            phi_1075_ = f32();
                                            phi_1076_ = true;
                                        }
                                        let _e794 = phi_1075_;
                                        let _e796 = phi_1076_;
                                        let _e798 = (select(_e794, _e782, _e796) / _e108);
                                        let _e799 = (_e402 + _e780);
                                        let _e800 = (_e405 + _e798);
                                        let _e801 = (_e402 - _e780);
                                        let _e802 = (_e405 - _e798);
                                        let _e804 = select(1u, _e103, (1u < _e103));
                                        let _e806 = select(1u, _e113, (1u < _e113));
                                        let _e807 = f32(_e804);
                                        let _e808 = f32(_e806);
                                        phi_1109_ = 1u;
                                        phi_1112_ = _e808;
                                        phi_1114_ = _e807;
                                        phi_1116_ = 0u;
                                        phi_1118_ = _e806;
                                        phi_1120_ = _e804;
                                        loop {
                                            let _e810 = phi_1109_;
                                            let _e812 = phi_1112_;
                                            let _e814 = phi_1114_;
                                            let _e816 = phi_1116_;
                                            let _e818 = phi_1118_;
                                            let _e820 = phi_1120_;
                                            local_2 = _e814;
                                            local_3 = _e820;
                                            local_4 = _e812;
                                            local_5 = _e818;
                                            local_6 = _e820;
                                            local_7 = _e816;
                                            let _e821 = (_e810 < 5u);
                                            if _e821 {
                                                let _e823 = (_e762 >= f32(_e810));
                                                let _e824 = (_e810 & 31u);
                                                let _e826 = (_e103 >> bitcast<u32>(_e824));
                                                let _e828 = select(1u, _e826, (1u < _e826));
                                                let _e830 = (_e113 >> bitcast<u32>(_e824));
                                                let _e832 = select(1u, _e830, (1u < _e830));
                                                phi_1153_ = 0u;
                                                phi_1156_ = 0u;
                                                loop {
                                                    let _e836 = phi_1153_;
                                                    let _e838 = phi_1156_;
                                                    local_1 = _e838;
                                                    let _e839 = (_e836 < _e810);
                                                    if _e839 {
                                                        let _e840 = (_e836 & 31u);
                                                        let _e842 = (_e103 >> bitcast<u32>(_e840));
                                                        let _e846 = (_e113 >> bitcast<u32>(_e840));
                                                        phi_1154_ = (_e836 + 1u);
                                                        phi_1157_ = (_e838 + (select(1u, _e842, (1u < _e842)) * select(1u, _e846, (1u < _e846))));
                                                    } else {
                                                        phi_1154_ = u32();
                                                        phi_1157_ = u32();
                                                    }
                                                    let _e853 = phi_1154_;
                                                    let _e855 = phi_1157_;
                                                    continue;
                                                    continuing {
                                                        phi_1153_ = _e853;
                                                        phi_1156_ = _e855;
                                                        break if !(_e839);
                                                    }
                                                }
                                                let _e858 = local_1;
                                                phi_1110_ = (_e810 + 1u);
                                                phi_1113_ = select(_e812, f32(_e832), _e823);
                                                phi_1115_ = select(_e814, f32(_e828), _e823);
                                                phi_1117_ = select(_e816, _e858, _e823);
                                                phi_1119_ = select(_e818, _e832, _e823);
                                                phi_1121_ = select(_e820, _e828, _e823);
                                            } else {
                                                phi_1110_ = u32();
                                                phi_1113_ = f32();
                                                phi_1115_ = f32();
                                                phi_1117_ = u32();
                                                phi_1119_ = u32();
                                                phi_1121_ = u32();
                                            }
                                            let _e866 = phi_1110_;
                                            let _e868 = phi_1113_;
                                            let _e870 = phi_1115_;
                                            let _e872 = phi_1117_;
                                            let _e874 = phi_1119_;
                                            let _e876 = phi_1121_;
                                            continue;
                                            continuing {
                                                phi_1109_ = _e866;
                                                phi_1112_ = _e868;
                                                phi_1114_ = _e870;
                                                phi_1116_ = _e872;
                                                phi_1118_ = _e874;
                                                phi_1120_ = _e876;
                                                break if !(_e821);
                                            }
                                        }
                                        let _e879 = local_2;
                                        let _e880 = (_e799 * _e879);
                                        if (_e880 > 0f) {
                                            let _e886 = select(select(u32(_e880), 0u, (_e880 < 0f)), 4294967295u, (_e880 > 4294967000f));
                                            let _e888 = local_3;
                                            let _e889 = (_e888 - 1u);
                                            phi_1214_ = select(_e886, _e889, (_e889 < _e886));
                                        } else {
                                            phi_1214_ = 0u;
                                        }
                                        let _e893 = phi_1214_;
                                        let _e895 = local_4;
                                        let _e896 = (_e800 * _e895);
                                        if (_e896 > 0f) {
                                            let _e902 = select(select(u32(_e896), 0u, (_e896 < 0f)), 4294967295u, (_e896 > 4294967000f));
                                            let _e904 = local_5;
                                            let _e905 = (_e904 - 1u);
                                            phi_1233_ = select(_e902, _e905, (_e905 < _e902));
                                        } else {
                                            phi_1233_ = 0u;
                                        }
                                        let _e909 = phi_1233_;
                                        let _e911 = local_6;
                                        let _e914 = local_7;
                                        let _e916 = ((_e914 + (_e909 * _e911)) + _e893);
                                        if (_e916 < _e87) {
                                        } else {
                                            phi_2800_ = true;
                                            break;
                                        }
                                        let _e920 = mips.member[_e916];
                                        phi_1277_ = 1u;
                                        phi_1280_ = _e808;
                                        phi_1282_ = _e807;
                                        phi_1284_ = 0u;
                                        phi_1286_ = _e806;
                                        phi_1288_ = _e804;
                                        loop {
                                            let _e930 = phi_1277_;
                                            let _e932 = phi_1280_;
                                            let _e934 = phi_1282_;
                                            let _e936 = phi_1284_;
                                            let _e938 = phi_1286_;
                                            let _e940 = phi_1288_;
                                            local_9 = _e934;
                                            local_10 = _e940;
                                            local_11 = _e932;
                                            local_12 = _e938;
                                            local_13 = _e940;
                                            local_14 = _e936;
                                            let _e941 = (_e930 < 5u);
                                            if _e941 {
                                                let _e943 = (_e762 >= f32(_e930));
                                                let _e944 = (_e930 & 31u);
                                                let _e946 = (_e103 >> bitcast<u32>(_e944));
                                                let _e948 = select(1u, _e946, (1u < _e946));
                                                let _e950 = (_e113 >> bitcast<u32>(_e944));
                                                let _e952 = select(1u, _e950, (1u < _e950));
                                                phi_1321_ = 0u;
                                                phi_1324_ = 0u;
                                                loop {
                                                    let _e956 = phi_1321_;
                                                    let _e958 = phi_1324_;
                                                    local_8 = _e958;
                                                    let _e959 = (_e956 < _e930);
                                                    if _e959 {
                                                        let _e960 = (_e956 & 31u);
                                                        let _e962 = (_e103 >> bitcast<u32>(_e960));
                                                        let _e966 = (_e113 >> bitcast<u32>(_e960));
                                                        phi_1322_ = (_e956 + 1u);
                                                        phi_1325_ = (_e958 + (select(1u, _e962, (1u < _e962)) * select(1u, _e966, (1u < _e966))));
                                                    } else {
                                                        phi_1322_ = u32();
                                                        phi_1325_ = u32();
                                                    }
                                                    let _e973 = phi_1322_;
                                                    let _e975 = phi_1325_;
                                                    continue;
                                                    continuing {
                                                        phi_1321_ = _e973;
                                                        phi_1324_ = _e975;
                                                        break if !(_e959);
                                                    }
                                                }
                                                let _e978 = local_8;
                                                phi_1278_ = (_e930 + 1u);
                                                phi_1281_ = select(_e932, f32(_e952), _e943);
                                                phi_1283_ = select(_e934, f32(_e948), _e943);
                                                phi_1285_ = select(_e936, _e978, _e943);
                                                phi_1287_ = select(_e938, _e952, _e943);
                                                phi_1289_ = select(_e940, _e948, _e943);
                                            } else {
                                                phi_1278_ = u32();
                                                phi_1281_ = f32();
                                                phi_1283_ = f32();
                                                phi_1285_ = u32();
                                                phi_1287_ = u32();
                                                phi_1289_ = u32();
                                            }
                                            let _e986 = phi_1278_;
                                            let _e988 = phi_1281_;
                                            let _e990 = phi_1283_;
                                            let _e992 = phi_1285_;
                                            let _e994 = phi_1287_;
                                            let _e996 = phi_1289_;
                                            continue;
                                            continuing {
                                                phi_1277_ = _e986;
                                                phi_1280_ = _e988;
                                                phi_1282_ = _e990;
                                                phi_1284_ = _e992;
                                                phi_1286_ = _e994;
                                                phi_1288_ = _e996;
                                                break if !(_e941);
                                            }
                                        }
                                        let _e999 = local_9;
                                        let _e1000 = (_e801 * _e999);
                                        if (_e1000 > 0f) {
                                            let _e1006 = select(select(u32(_e1000), 0u, (_e1000 < 0f)), 4294967295u, (_e1000 > 4294967000f));
                                            let _e1008 = local_10;
                                            let _e1009 = (_e1008 - 1u);
                                            phi_1382_ = select(_e1006, _e1009, (_e1009 < _e1006));
                                        } else {
                                            phi_1382_ = 0u;
                                        }
                                        let _e1013 = phi_1382_;
                                        let _e1015 = local_11;
                                        let _e1016 = (_e802 * _e1015);
                                        if (_e1016 > 0f) {
                                            let _e1022 = select(select(u32(_e1016), 0u, (_e1016 < 0f)), 4294967295u, (_e1016 > 4294967000f));
                                            let _e1024 = local_12;
                                            let _e1025 = (_e1024 - 1u);
                                            phi_1401_ = select(_e1022, _e1025, (_e1025 < _e1022));
                                        } else {
                                            phi_1401_ = 0u;
                                        }
                                        let _e1029 = phi_1401_;
                                        let _e1031 = local_13;
                                        let _e1034 = local_14;
                                        let _e1036 = ((_e1034 + (_e1029 * _e1031)) + _e1013);
                                        if (_e1036 < _e87) {
                                        } else {
                                            phi_2800_ = true;
                                            break;
                                        }
                                        let _e1040 = mips.member[_e1036];
                                        let _e1049 = (((((_e799 * 2f) - 1f) * _e413) * _e920) - _e415);
                                        let _e1050 = (((((_e800 * -2f) + 1f) * _e422) * _e920) - _e424);
                                        let _e1051 = (_e920 - _e406);
                                        let _e1054 = ((_e1049 * _e1049) + (_e1050 * _e1050));
                                        let _e1057 = sqrt((_e1054 + (_e1051 * _e1051)));
                                        let _e1066 = (1f + _e717);
                                        let _e1067 = (_e1051 * _e1066);
                                        let _e1070 = sqrt((_e1054 + (_e1067 * _e1067)));
                                        let _e1071 = (_e594 > 0f);
                                        if _e1071 {
                                            let _e1074 = ((-(_e1070) + _e517) / _e594);
                                            phi_1484_ = select(0f, select(1f, _e1074, (_e1074 < 1f)), (_e1074 > 0f));
                                        } else {
                                            phi_1484_ = select(0f, 1f, (_e1070 <= _e517));
                                        }
                                        let _e1082 = phi_1484_;
                                        let _e1085 = (_e712 + ((((((_e1049 / _e1057) * _e435) + ((_e1050 / _e1057) * _e436)) + ((_e1051 / _e1057) * _e437)) - _e712) * _e1082));
                                        let _e1086 = (((((_e801 * 2f) - 1f) * _e413) * _e1040) - _e415);
                                        let _e1087 = (((((_e802 * -2f) + 1f) * _e422) * _e1040) - _e424);
                                        let _e1088 = (_e1040 - _e406);
                                        let _e1091 = ((_e1086 * _e1086) + (_e1087 * _e1087));
                                        let _e1094 = sqrt((_e1091 + (_e1088 * _e1088)));
                                        let _e1103 = (_e1088 * _e1066);
                                        let _e1106 = sqrt((_e1091 + (_e1103 * _e1103)));
                                        if _e1071 {
                                            let _e1109 = ((-(_e1106) + _e517) / _e594);
                                            phi_1544_ = select(0f, select(1f, _e1109, (_e1109 < 1f)), (_e1109 > 0f));
                                        } else {
                                            phi_1544_ = select(0f, 1f, (_e1106 <= _e517));
                                        }
                                        let _e1117 = phi_1544_;
                                        let _e1120 = (_e714 + ((((((_e1086 / _e1094) * _e435) + ((_e1087 / _e1094) * _e436)) + ((_e1088 / _e1094) * _e437)) - _e714) * _e1117));
                                        if (_e723 != _e723) {
                                            phi_2568_ = true;
                                        } else {
                                            phi_2568_ = (_e1085 >= _e723);
                                        }
                                        let _e1124 = phi_2568_;
                                        if (_e721 != _e721) {
                                            phi_2583_ = true;
                                        } else {
                                            phi_2583_ = (_e1120 >= _e721);
                                        }
                                        let _e1129 = phi_2583_;
                                        phi_944_ = (_e719 + 1u);
                                        phi_947_ = select(_e721, _e1120, _e1129);
                                        phi_949_ = select(_e723, _e1085, _e1124);
                                    } else {
                                        phi_944_ = u32();
                                        phi_947_ = f32();
                                        phi_949_ = f32();
                                    }
                                    let _e1133 = phi_944_;
                                    let _e1135 = phi_947_;
                                    let _e1137 = phi_949_;
                                    continue;
                                    continuing {
                                        phi_943_ = _e1133;
                                        phi_946_ = _e1135;
                                        phi_948_ = _e1137;
                                        phi_2800_ = _e608;
                                        break if !(_e724);
                                    }
                                }
                                let _e1140 = phi_2800_;
                                phi_2949_ = _e1140;
                                if _e1140 {
                                    break;
                                }
                                let _e1142 = local_15;
                                let _e1143 = abs(_e1142);
                                let _e1154 = (((_e1143 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1143))) >> bitcast<u32>(1i))))));
                                let _e1156 = local_16;
                                let _e1159 = select((3.141593f - _e1154), _e1154, (_e1156 >= 0f));
                                let _e1160 = -(_e1159);
                                let _e1162 = local_17;
                                let _e1163 = abs(_e1162);
                                let _e1174 = (((_e1163 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1163))) >> bitcast<u32>(1i))))));
                                let _e1176 = local_18;
                                let _e1179 = select((3.141593f - _e1174), _e1174, (_e1176 >= 0f));
                                let _e1182 = (_e670 + ((1f - _e670) * 0.05f));
                                let _e1183 = (_e1159 * -2f);
                                let _e1184 = sin(_e705);
                                let _e1190 = (_e1179 * 2f);
                                let _e1202 = params.member.member_13;
                                if (_e1202 == 0u) {
                                    phi_1763_ = _e612;
                                } else {
                                    let _e1208 = ((_e1159 * -3f) - _e705);
                                    let _e1216 = ((_e1179 * 3f) - _e705);
                                    let _e1221 = (_e1160 + _e705);
                                    let _e1223 = (_e1179 + _e705);
                                    let _e1228 = (((((((sin((_e1160 - _e705)) * 6f) - sin(_e1208)) + (sin((_e1179 - _e705)) * 6f)) - sin(_e1216)) + (_e1184 * 16f)) - ((sin(_e1221) + sin(_e1223)) * 3f)) * 0.083333336f);
                                    let _e1240 = (((-(cos(_e1208)) - cos(_e1216)) + (cos(_e705) * 8f)) - ((cos(_e1221) + cos(_e1223)) * 3f));
                                    let _e1241 = (_e622 * _e1228);
                                    let _e1242 = (_e621 * _e1228);
                                    let _e1243 = (_e1240 * -0.083333336f);
                                    let _e1244 = (-1f * _e437);
                                    let _e1245 = (-1f * _e435);
                                    let _e1247 = (1f / (_e1244 + 1f));
                                    let _e1248 = (_e1247 * _e436);
                                    let _e1252 = (_e1248 * _e1245);
                                    let _e1273 = (_e1244 > 0.9997f);
                                    let _e1274 = (_e1244 < -0.9997f);
                                    phi_1763_ = (_e612 + vec3<f32>((select(select(((((_e1244 + (_e1248 * _e436)) * _e1241) + (_e1252 * _e1242)) + (_e1245 * _e1243)), _e1241, _e1274), _e1241, _e1273) * _e1182), (select(select((((_e1252 * _e1241) + ((_e1244 + ((_e1247 * _e1245) * _e1245)) * _e1242)) + (-(_e436) * _e1243)), -(_e1242), _e1274), _e1242, _e1273) * _e1182), (select(select((((_e435 * _e1241) + (_e436 * _e1242)) + (_e1244 * _e1243)), (_e1240 * 0.083333336f), _e1274), _e1243, _e1273) * _e1182)));
                                }
                                let _e1287 = phi_1763_;
                                phi_2950_ = _e1140;
                                phi_768_ = (_e610 + 1u);
                                phi_771_ = _e1287;
                                phi_773_ = (_e614 + ((0.25f * (((_e689 + (_e1183 * _e1184)) - cos((_e1183 - _e705))) + ((_e689 + (_e1190 * _e1184)) - cos((_e1190 - _e705))))) * _e1182));
                            } else {
                                phi_2950_ = _e608;
                                phi_768_ = u32();
                                phi_771_ = vec3<f32>();
                                phi_773_ = f32();
                            }
                            let _e1290 = phi_2950_;
                            let _e1292 = phi_768_;
                            let _e1294 = phi_771_;
                            let _e1296 = phi_773_;
                            continue;
                            continuing {
                                phi_2868_ = _e1290;
                                phi_767_ = _e1292;
                                phi_770_ = _e1294;
                                phi_772_ = _e1296;
                                phi_2949_ = _e1290;
                                break if !(_e615);
                            }
                        }
                        let _e1299 = phi_2949_;
                        if _e1299 {
                            break;
                        }
                        let _e1302 = local_19;
                        let _e1305 = local_20;
                        phi_1769_ = type_23((_e1302 / f32(_e606)), _e1305);
                    } else {
                        phi_1769_ = type_23(1f, vec3<f32>(0f, 0f, 0f));
                    }
                    let _e1308 = phi_1769_;
                    if _e590 {
                        let _e1313 = params.member.member_6;
                        let _e1314 = pow(_e1308.member, _e1313);
                        if (_e1314 != _e1314) {
                            phi_2610_ = true;
                        } else {
                            phi_2610_ = (0.03f >= _e1314);
                        }
                        let _e1318 = phi_2610_;
                        let _e1319 = select(_e1314, 0.03f, _e1318);
                        let _e1322 = params.member.member_13;
                        if (_e1322 == 0u) {
                            let _e1324 = (_e1319 * 0.6666667f);
                            let _e1330 = ((select(0f, select(1f, _e1324, (_e1324 < 1f)), (_e1324 > 0f)) * 255f) + 0.5f);
                            phi_1845_ = select(select(u32(_e1330), 0u, (_e1330 < 0f)), 4294967295u, (_e1330 > 4294967000f));
                        } else {
                            let _e1344 = sqrt((((_e1308.member_1.x * _e1308.member_1.x) + (_e1308.member_1.y * _e1308.member_1.y)) + (_e1308.member_1.z * _e1308.member_1.z)));
                            if (_e1344 > 0f) {
                                phi_1824_ = (_e1308.member_1 / vec3(_e1344));
                            } else {
                                phi_1824_ = vec3<f32>(_e506, _e508, _e509);
                            }
                            let _e1349 = phi_1824_;
                            let _e1350 = (_e1319 * 0.6666667f);
                            let _e1357 = ((_e1349.x * 0.5f) + 0.5f);
                            let _e1358 = ((_e1349.y * 0.5f) + 0.5f);
                            let _e1359 = ((_e1349.z * 0.5f) + 0.5f);
                            let _e1365 = ((select(0f, select(1f, _e1357, (_e1357 < 1f)), (_e1357 > 0f)) * 255f) + 0.5f);
                            let _e1376 = ((select(0f, select(1f, _e1358, (_e1358 < 1f)), (_e1358 > 0f)) * 255f) + 0.5f);
                            let _e1390 = ((select(0f, select(1f, _e1359, (_e1359 < 1f)), (_e1359 > 0f)) * 255f) + 0.5f);
                            let _e1404 = ((select(0f, select(1f, _e1350, (_e1350 < 1f)), (_e1350 > 0f)) * 255f) + 0.5f);
                            phi_1845_ = (((select(select(u32(_e1365), 0u, (_e1365 < 0f)), 4294967295u, (_e1365 > 4294967000f)) | (select(select(u32(_e1376), 0u, (_e1376 < 0f)), 4294967295u, (_e1376 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1390), 0u, (_e1390 < 0f)), 4294967295u, (_e1390 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1404), 0u, (_e1404 < 0f)), 4294967295u, (_e1404 > 4294967000f)) << bitcast<u32>(24i)));
                        }
                        let _e1414 = phi_1845_;
                        phi_1890_ = _e1414;
                    } else {
                        let _e1417 = params.member.member_13;
                        phi_1890_ = select(2852159616u, 170u, (_e1417 == 0u));
                    }
                    let _e1421 = phi_1890_;
                    if (_e119 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e119] = _e1421;
                    if (_e119 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e119] = ((((64u * _e297) + (16u * _e330)) + (4u * _e364)) + _e398);
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
