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
    var phi_360_: i32;
    var phi_379_: i32;
    var phi_420_: i32;
    var phi_439_: i32;
    var phi_480_: i32;
    var phi_499_: i32;
    var phi_540_: i32;
    var phi_559_: i32;
    var phi_2031_: bool;
    var phi_2046_: bool;
    var phi_2061_: bool;
    var phi_2076_: bool;
    var phi_2107_: f32;
    var phi_2111_: f32;
    var phi_2112_: bool;
    var phi_2134_: u32;
    var phi_2161_: f32;
    var phi_2165_: f32;
    var phi_2166_: bool;
    var phi_2188_: u32;
    var phi_2215_: f32;
    var phi_2219_: f32;
    var phi_2220_: bool;
    var phi_2242_: u32;
    var phi_2269_: f32;
    var phi_2273_: f32;
    var phi_2274_: bool;
    var phi_2296_: u32;
    var phi_2375_: bool;
    var phi_2390_: bool;
    var phi_2351_: vec2<f32>;
    var phi_2407_: u32;
    var phi_2408_: u32;
    var phi_2409_: u32;
    var phi_2410_: u32;
    var phi_2433_: u32;
    var phi_2434_: u32;
    var phi_2437_: u32;
    var phi_2438_: u32;
    var phi_2442_: u32;
    var phi_2443_: u32;
    var phi_2444_: u32;
    var phi_2445_: u32;
    var local: u32;
    var phi_2765_: bool;
    var phi_829_: u32;
    var phi_832_: vec3<f32>;
    var phi_834_: f32;
    var phi_1005_: u32;
    var phi_1008_: f32;
    var phi_1010_: f32;
    var phi_1064_: f32;
    var phi_1109_: f32;
    var phi_1111_: f32;
    var phi_1112_: bool;
    var phi_1135_: f32;
    var phi_1137_: f32;
    var phi_1138_: bool;
    var phi_1171_: u32;
    var phi_1187_: u32;
    var phi_1190_: u32;
    var phi_1188_: u32;
    var phi_1191_: u32;
    var phi_1235_: u32;
    var phi_1254_: u32;
    var local_1: u32;
    var phi_1298_: u32;
    var phi_1314_: u32;
    var phi_1317_: u32;
    var phi_1315_: u32;
    var phi_1318_: u32;
    var phi_1362_: u32;
    var phi_1381_: u32;
    var local_2: u32;
    var phi_1464_: f32;
    var phi_1524_: f32;
    var phi_2479_: bool;
    var phi_2494_: bool;
    var phi_1006_: u32;
    var phi_1009_: f32;
    var phi_1011_: f32;
    var phi_2711_: bool;
    var local_3: f32;
    var local_4: f32;
    var local_5: f32;
    var local_6: f32;
    var phi_1743_: vec3<f32>;
    var phi_2847_: bool;
    var phi_830_: u32;
    var phi_833_: vec3<f32>;
    var phi_835_: f32;
    var phi_2846_: bool;
    var local_7: f32;
    var local_8: vec3<f32>;
    var phi_1749_: type_23;
    var phi_2521_: bool;
    var phi_1804_: vec3<f32>;
    var phi_1825_: u32;
    var phi_1870_: u32;

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
                        phi_360_ = 0i;
                    } else {
                        phi_360_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_360_;
                    let _e134 = bitcast<i32>(_e84.y);
                    let _e136 = (bitcast<i32>(_e113) - 1i);
                    let _e137 = (0i <= _e136);
                    if _e137 {
                    } else {
                        break;
                    }
                    let _e138 = (_e134 < 0i);
                    if _e138 {
                        phi_379_ = 0i;
                    } else {
                        phi_379_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e142 = phi_379_;
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
                        phi_420_ = 0i;
                    } else {
                        phi_420_ = select(_e149, _e126, (_e149 > _e126));
                    }
                    let _e154 = phi_420_;
                    if _e137 {
                    } else {
                        break;
                    }
                    if _e138 {
                        phi_439_ = 0i;
                    } else {
                        phi_439_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e159 = phi_439_;
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
                        phi_480_ = 0i;
                    } else {
                        phi_480_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e170 = phi_480_;
                    let _e172 = (_e134 + -1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e172 < 0i) {
                        phi_499_ = 0i;
                    } else {
                        phi_499_ = select(_e172, _e136, (_e172 > _e136));
                    }
                    let _e177 = phi_499_;
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
                        phi_540_ = 0i;
                    } else {
                        phi_540_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e187 = phi_540_;
                    let _e189 = (_e134 + 1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e189 < 0i) {
                        phi_559_ = 0i;
                    } else {
                        phi_559_ = select(_e189, _e136, (_e189 > _e136));
                    }
                    let _e194 = phi_559_;
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
                        phi_2031_ = true;
                    } else {
                        phi_2031_ = (_e212 <= _e211);
                    }
                    let _e216 = phi_2031_;
                    let _e219 = (1.25f - (select(_e211, _e212, _e216) / _e209));
                    let _e223 = select(0f, select(1f, _e219, (_e219 < 1f)), (_e219 > 0f));
                    let _e225 = abs(_e202);
                    let _e226 = abs((_e202 - _e206));
                    if (_e225 != _e225) {
                        phi_2046_ = true;
                    } else {
                        phi_2046_ = (_e226 <= _e225);
                    }
                    let _e230 = phi_2046_;
                    let _e233 = (1.25f - (select(_e225, _e226, _e230) / _e209));
                    let _e237 = select(0f, select(1f, _e233, (_e233 < 1f)), (_e233 > 0f));
                    let _e239 = abs(_e203);
                    let _e240 = abs((_e203 + _e208));
                    if (_e239 != _e239) {
                        phi_2061_ = true;
                    } else {
                        phi_2061_ = (_e240 <= _e239);
                    }
                    let _e244 = phi_2061_;
                    let _e247 = (1.25f - (select(_e239, _e240, _e244) / _e209));
                    let _e251 = select(0f, select(1f, _e247, (_e247 < 1f)), (_e247 > 0f));
                    let _e253 = abs(_e204);
                    let _e254 = abs((_e204 - _e208));
                    if (_e253 != _e253) {
                        phi_2076_ = true;
                    } else {
                        phi_2076_ = (_e254 <= _e253);
                    }
                    let _e258 = phi_2076_;
                    let _e261 = (1.25f - (select(_e253, _e254, _e258) / _e209));
                    let _e265 = select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f));
                    let _e270 = (select(0f, select(1f, _e223, (_e223 < 1f)), (_e223 > 0f)) * 2.9f);
                    let _e272 = floor((_e270 + 0.5f));
                    if ((_e272 - _e270) == 0.5f) {
                        let _e278 = ((floor((_e272 * 0.5f)) * 2f) != _e272);
                        if _e278 {
                            phi_2107_ = (_e272 - 1f);
                        } else {
                            phi_2107_ = f32();
                        }
                        let _e281 = phi_2107_;
                        phi_2111_ = _e281;
                        phi_2112_ = select(true, false, _e278);
                    } else {
                        phi_2111_ = f32();
                        phi_2112_ = true;
                    }
                    let _e284 = phi_2111_;
                    let _e286 = phi_2112_;
                    let _e287 = select(_e284, _e272, _e286);
                    if (_e287 > 0f) {
                        let _e293 = select(select(u32(_e287), 0u, (_e287 < 0f)), 4294967295u, (_e287 > 4294967000f));
                        phi_2134_ = select(_e293, 3u, (3u < _e293));
                    } else {
                        phi_2134_ = 0u;
                    }
                    let _e297 = phi_2134_;
                    let _e303 = (select(0f, select(1f, _e237, (_e237 < 1f)), (_e237 > 0f)) * 2.9f);
                    let _e305 = floor((_e303 + 0.5f));
                    if ((_e305 - _e303) == 0.5f) {
                        let _e311 = ((floor((_e305 * 0.5f)) * 2f) != _e305);
                        if _e311 {
                            phi_2161_ = (_e305 - 1f);
                        } else {
                            phi_2161_ = f32();
                        }
                        let _e314 = phi_2161_;
                        phi_2165_ = _e314;
                        phi_2166_ = select(true, false, _e311);
                    } else {
                        phi_2165_ = f32();
                        phi_2166_ = true;
                    }
                    let _e317 = phi_2165_;
                    let _e319 = phi_2166_;
                    let _e320 = select(_e317, _e305, _e319);
                    if (_e320 > 0f) {
                        let _e326 = select(select(u32(_e320), 0u, (_e320 < 0f)), 4294967295u, (_e320 > 4294967000f));
                        phi_2188_ = select(_e326, 3u, (3u < _e326));
                    } else {
                        phi_2188_ = 0u;
                    }
                    let _e330 = phi_2188_;
                    let _e337 = (select(0f, select(1f, _e251, (_e251 < 1f)), (_e251 > 0f)) * 2.9f);
                    let _e339 = floor((_e337 + 0.5f));
                    if ((_e339 - _e337) == 0.5f) {
                        let _e345 = ((floor((_e339 * 0.5f)) * 2f) != _e339);
                        if _e345 {
                            phi_2215_ = (_e339 - 1f);
                        } else {
                            phi_2215_ = f32();
                        }
                        let _e348 = phi_2215_;
                        phi_2219_ = _e348;
                        phi_2220_ = select(true, false, _e345);
                    } else {
                        phi_2219_ = f32();
                        phi_2220_ = true;
                    }
                    let _e351 = phi_2219_;
                    let _e353 = phi_2220_;
                    let _e354 = select(_e351, _e339, _e353);
                    if (_e354 > 0f) {
                        let _e360 = select(select(u32(_e354), 0u, (_e354 < 0f)), 4294967295u, (_e354 > 4294967000f));
                        phi_2242_ = select(_e360, 3u, (3u < _e360));
                    } else {
                        phi_2242_ = 0u;
                    }
                    let _e364 = phi_2242_;
                    let _e371 = (select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f)) * 2.9f);
                    let _e373 = floor((_e371 + 0.5f));
                    if ((_e373 - _e371) == 0.5f) {
                        let _e379 = ((floor((_e373 * 0.5f)) * 2f) != _e373);
                        if _e379 {
                            phi_2269_ = (_e373 - 1f);
                        } else {
                            phi_2269_ = f32();
                        }
                        let _e382 = phi_2269_;
                        phi_2273_ = _e382;
                        phi_2274_ = select(true, false, _e379);
                    } else {
                        phi_2273_ = f32();
                        phi_2274_ = true;
                    }
                    let _e385 = phi_2273_;
                    let _e387 = phi_2274_;
                    let _e388 = select(_e385, _e373, _e387);
                    if (_e388 > 0f) {
                        let _e394 = select(select(u32(_e388), 0u, (_e388 < 0f)), 4294967295u, (_e388 > 4294967000f));
                        phi_2296_ = select(_e394, 3u, (3u < _e394));
                    } else {
                        phi_2296_ = 0u;
                    }
                    let _e398 = phi_2296_;
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
                        phi_2375_ = true;
                    } else {
                        phi_2375_ = (-1f >= _e449);
                    }
                    let _e453 = phi_2375_;
                    let _e454 = select(_e449, -1f, _e453);
                    let _e464 = (f32((bitcast<i32>((((_e441 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e464 != _e464) {
                        phi_2390_ = true;
                    } else {
                        phi_2390_ = (-1f >= _e464);
                    }
                    let _e468 = phi_2390_;
                    let _e469 = select(_e464, -1f, _e468);
                    let _e472 = (1f - abs(_e454));
                    let _e473 = abs(_e469);
                    let _e474 = (_e472 - _e473);
                    if (_e474 < 0f) {
                        phi_2351_ = vec2<f32>(((1f - _e473) * select(1f, -1f, (_e454 < 0f))), (_e472 * select(1f, -1f, (_e469 < 0f))));
                    } else {
                        phi_2351_ = vec2<f32>(_e454, _e469);
                    }
                    let _e485 = phi_2351_;
                    let _e494 = (1f / sqrt((((_e485.x * _e485.x) + (_e485.y * _e485.y)) + (_e474 * _e474))));
                    let _e495 = (_e485.x * _e494);
                    let _e496 = (_e485.y * _e494);
                    let _e497 = (_e474 * _e494);
                    let _e498 = -(_e497);
                    let _e504 = ((((_e495 * _e435) + (_e496 * _e436)) + (_e498 * _e437)) < 0f);
                    let _e507 = select(_e495, -(_e495), _e504);
                    let _e508 = select(_e496, -(_e496), _e504);
                    let _e509 = select(_e498, _e497, _e504);
                    let _e513 = params.member.member_1;
                    let _e516 = params.member.member_2;
                    let _e517 = (_e513 * _e516);
                    let _e521 = (_e517 / (((_e122 * 1.99998f) * _e413) / _e98));
                    let _e525 = params.member.member_11;
                    phi_2407_ = (_e84.y & 63u);
                    phi_2408_ = (_e84.x & 63u);
                    phi_2409_ = 32u;
                    phi_2410_ = 0u;
                    loop {
                        let _e529 = phi_2407_;
                        let _e531 = phi_2408_;
                        let _e533 = phi_2409_;
                        let _e535 = phi_2410_;
                        local = _e535;
                        let _e536 = (_e533 > 0u);
                        if _e536 {
                            let _e539 = select(0u, 1u, ((_e531 & _e533) != 0u));
                            let _e542 = select(0u, 1u, ((_e529 & _e533) != 0u));
                            if (_e542 == 0u) {
                                if (_e539 == 1u) {
                                    phi_2433_ = (63u - _e529);
                                    phi_2434_ = (63u - _e531);
                                } else {
                                    phi_2433_ = _e529;
                                    phi_2434_ = _e531;
                                }
                                let _e553 = phi_2433_;
                                let _e555 = phi_2434_;
                                phi_2437_ = _e555;
                                phi_2438_ = _e553;
                            } else {
                                phi_2437_ = _e529;
                                phi_2438_ = _e531;
                            }
                            let _e557 = phi_2437_;
                            let _e559 = phi_2438_;
                            phi_2442_ = _e557;
                            phi_2443_ = _e559;
                            phi_2444_ = (_e533 / 2u);
                            phi_2445_ = (_e535 + ((_e533 * _e533) * ((3u * _e539) ^ _e542)));
                        } else {
                            phi_2442_ = u32();
                            phi_2443_ = u32();
                            phi_2444_ = u32();
                            phi_2445_ = u32();
                        }
                        let _e562 = phi_2442_;
                        let _e564 = phi_2443_;
                        let _e566 = phi_2444_;
                        let _e568 = phi_2445_;
                        continue;
                        continuing {
                            phi_2407_ = _e562;
                            phi_2408_ = _e564;
                            phi_2409_ = _e566;
                            phi_2410_ = _e568;
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
                        phi_2765_ = false;
                        phi_829_ = 0u;
                        phi_832_ = vec3<f32>(0f, 0f, 0f);
                        phi_834_ = (select(0f, select(1f, _e596, (_e596 < 1f)), (_e596 > 0f)) * 0.5f);
                        loop {
                            let _e608 = phi_2765_;
                            let _e610 = phi_829_;
                            let _e612 = phi_832_;
                            let _e614 = phi_834_;
                            local_7 = _e614;
                            local_8 = _e612;
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
                                let _e658 = (((_e507 * _e651) + (_e508 * _e652)) + (_e509 * _e653));
                                let _e662 = (_e507 - (_e651 * _e658));
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
                                phi_1005_ = 0u;
                                phi_1008_ = _e714;
                                phi_1010_ = _e712;
                                loop {
                                    let _e719 = phi_1005_;
                                    let _e721 = phi_1008_;
                                    let _e723 = phi_1010_;
                                    local_3 = _e721;
                                    local_4 = _e721;
                                    local_5 = _e723;
                                    local_6 = _e723;
                                    let _e724 = (_e719 < _e710);
                                    if _e724 {
                                        let _e729 = ((_e581 - floor(_e581)) + (f32((_e610 + (_e719 * _e710))) * 0.618034f));
                                        let _e735 = (((_e729 - floor(_e729)) + f32(_e719)) / f32(_e710));
                                        let _e738 = params.member.member_4;
                                        if (_e738 == 2f) {
                                            phi_1064_ = (_e735 * _e735);
                                        } else {
                                            phi_1064_ = pow(_e735, _e738);
                                        }
                                        let _e743 = phi_1064_;
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
                                                phi_1109_ = (_e764 - 1f);
                                            } else {
                                                phi_1109_ = f32();
                                            }
                                            let _e773 = phi_1109_;
                                            phi_1111_ = _e773;
                                            phi_1112_ = select(true, false, _e770);
                                        } else {
                                            phi_1111_ = f32();
                                            phi_1112_ = true;
                                        }
                                        let _e776 = phi_1111_;
                                        let _e778 = phi_1112_;
                                        let _e780 = (select(_e776, _e764, _e778) / _e98);
                                        let _e782 = floor((_e746 + 0.5f));
                                        if ((_e782 - _e746) == 0.5f) {
                                            let _e788 = ((floor((_e782 * 0.5f)) * 2f) != _e782);
                                            if _e788 {
                                                phi_1135_ = (_e782 - 1f);
                                            } else {
                                                phi_1135_ = f32();
                                            }
                                            let _e791 = phi_1135_;
                                            phi_1137_ = _e791;
                                            phi_1138_ = select(true, false, _e788);
                                        } else {
                                            phi_1137_ = f32();
                                            phi_1138_ = true;
                                        }
                                        let _e794 = phi_1137_;
                                        let _e796 = phi_1138_;
                                        let _e798 = (select(_e794, _e782, _e796) / _e108);
                                        let _e799 = (_e402 + _e780);
                                        let _e800 = (_e405 + _e798);
                                        let _e801 = (_e402 - _e780);
                                        let _e802 = (_e405 - _e798);
                                        let _e803 = (_e762 > 0f);
                                        if _e803 {
                                            let _e808 = select(select(u32(_e762), 0u, (_e762 < 0f)), 4294967295u, (_e762 > 4294967000f));
                                            phi_1171_ = select(_e808, 4u, (4u < _e808));
                                        } else {
                                            phi_1171_ = 0u;
                                        }
                                        let _e812 = phi_1171_;
                                        let _e813 = (_e812 & 31u);
                                        let _e815 = (_e103 >> bitcast<u32>(_e813));
                                        let _e817 = select(1u, _e815, (1u < _e815));
                                        let _e819 = (_e113 >> bitcast<u32>(_e813));
                                        let _e821 = select(1u, _e819, (1u < _e819));
                                        phi_1187_ = 0u;
                                        phi_1190_ = 0u;
                                        loop {
                                            let _e823 = phi_1187_;
                                            let _e825 = phi_1190_;
                                            local_1 = _e825;
                                            let _e826 = (_e823 < _e812);
                                            if _e826 {
                                                let _e827 = (_e823 & 31u);
                                                let _e829 = (_e103 >> bitcast<u32>(_e827));
                                                let _e833 = (_e113 >> bitcast<u32>(_e827));
                                                phi_1188_ = (_e823 + 1u);
                                                phi_1191_ = (_e825 + (select(1u, _e829, (1u < _e829)) * select(1u, _e833, (1u < _e833))));
                                            } else {
                                                phi_1188_ = u32();
                                                phi_1191_ = u32();
                                            }
                                            let _e840 = phi_1188_;
                                            let _e842 = phi_1191_;
                                            continue;
                                            continuing {
                                                phi_1187_ = _e840;
                                                phi_1190_ = _e842;
                                                break if !(_e826);
                                            }
                                        }
                                        let _e846 = (_e799 * f32(_e817));
                                        if (_e846 > 0f) {
                                            let _e852 = select(select(u32(_e846), 0u, (_e846 < 0f)), 4294967295u, (_e846 > 4294967000f));
                                            let _e853 = (_e817 - 1u);
                                            phi_1235_ = select(_e852, _e853, (_e853 < _e852));
                                        } else {
                                            phi_1235_ = 0u;
                                        }
                                        let _e857 = phi_1235_;
                                        let _e858 = (_e800 * f32(_e821));
                                        if (_e858 > 0f) {
                                            let _e864 = select(select(u32(_e858), 0u, (_e858 < 0f)), 4294967295u, (_e858 > 4294967000f));
                                            let _e865 = (_e821 - 1u);
                                            phi_1254_ = select(_e864, _e865, (_e865 < _e864));
                                        } else {
                                            phi_1254_ = 0u;
                                        }
                                        let _e869 = phi_1254_;
                                        let _e872 = local_1;
                                        let _e874 = ((_e872 + (_e869 * _e817)) + _e857);
                                        if (_e874 < _e87) {
                                        } else {
                                            phi_2711_ = true;
                                            break;
                                        }
                                        let _e878 = mips.member[_e874];
                                        if _e803 {
                                            let _e891 = select(select(u32(_e762), 0u, (_e762 < 0f)), 4294967295u, (_e762 > 4294967000f));
                                            phi_1298_ = select(_e891, 4u, (4u < _e891));
                                        } else {
                                            phi_1298_ = 0u;
                                        }
                                        let _e895 = phi_1298_;
                                        let _e896 = (_e895 & 31u);
                                        let _e898 = (_e103 >> bitcast<u32>(_e896));
                                        let _e900 = select(1u, _e898, (1u < _e898));
                                        let _e902 = (_e113 >> bitcast<u32>(_e896));
                                        let _e904 = select(1u, _e902, (1u < _e902));
                                        phi_1314_ = 0u;
                                        phi_1317_ = 0u;
                                        loop {
                                            let _e906 = phi_1314_;
                                            let _e908 = phi_1317_;
                                            local_2 = _e908;
                                            let _e909 = (_e906 < _e895);
                                            if _e909 {
                                                let _e910 = (_e906 & 31u);
                                                let _e912 = (_e103 >> bitcast<u32>(_e910));
                                                let _e916 = (_e113 >> bitcast<u32>(_e910));
                                                phi_1315_ = (_e906 + 1u);
                                                phi_1318_ = (_e908 + (select(1u, _e912, (1u < _e912)) * select(1u, _e916, (1u < _e916))));
                                            } else {
                                                phi_1315_ = u32();
                                                phi_1318_ = u32();
                                            }
                                            let _e923 = phi_1315_;
                                            let _e925 = phi_1318_;
                                            continue;
                                            continuing {
                                                phi_1314_ = _e923;
                                                phi_1317_ = _e925;
                                                break if !(_e909);
                                            }
                                        }
                                        let _e929 = (_e801 * f32(_e900));
                                        if (_e929 > 0f) {
                                            let _e935 = select(select(u32(_e929), 0u, (_e929 < 0f)), 4294967295u, (_e929 > 4294967000f));
                                            let _e936 = (_e900 - 1u);
                                            phi_1362_ = select(_e935, _e936, (_e936 < _e935));
                                        } else {
                                            phi_1362_ = 0u;
                                        }
                                        let _e940 = phi_1362_;
                                        let _e941 = (_e802 * f32(_e904));
                                        if (_e941 > 0f) {
                                            let _e947 = select(select(u32(_e941), 0u, (_e941 < 0f)), 4294967295u, (_e941 > 4294967000f));
                                            let _e948 = (_e904 - 1u);
                                            phi_1381_ = select(_e947, _e948, (_e948 < _e947));
                                        } else {
                                            phi_1381_ = 0u;
                                        }
                                        let _e952 = phi_1381_;
                                        let _e955 = local_2;
                                        let _e957 = ((_e955 + (_e952 * _e900)) + _e940);
                                        if (_e957 < _e87) {
                                        } else {
                                            phi_2711_ = true;
                                            break;
                                        }
                                        let _e961 = mips.member[_e957];
                                        let _e970 = (((((_e799 * 2f) - 1f) * _e413) * _e878) - _e415);
                                        let _e971 = (((((_e800 * -2f) + 1f) * _e422) * _e878) - _e424);
                                        let _e972 = (_e878 - _e406);
                                        let _e975 = ((_e970 * _e970) + (_e971 * _e971));
                                        let _e978 = sqrt((_e975 + (_e972 * _e972)));
                                        let _e987 = (1f + _e717);
                                        let _e988 = (_e972 * _e987);
                                        let _e991 = sqrt((_e975 + (_e988 * _e988)));
                                        let _e992 = (_e594 > 0f);
                                        if _e992 {
                                            let _e995 = ((-(_e991) + _e517) / _e594);
                                            phi_1464_ = select(0f, select(1f, _e995, (_e995 < 1f)), (_e995 > 0f));
                                        } else {
                                            phi_1464_ = select(0f, 1f, (_e991 <= _e517));
                                        }
                                        let _e1003 = phi_1464_;
                                        let _e1006 = (_e712 + ((((((_e970 / _e978) * _e435) + ((_e971 / _e978) * _e436)) + ((_e972 / _e978) * _e437)) - _e712) * _e1003));
                                        let _e1007 = (((((_e801 * 2f) - 1f) * _e413) * _e961) - _e415);
                                        let _e1008 = (((((_e802 * -2f) + 1f) * _e422) * _e961) - _e424);
                                        let _e1009 = (_e961 - _e406);
                                        let _e1012 = ((_e1007 * _e1007) + (_e1008 * _e1008));
                                        let _e1015 = sqrt((_e1012 + (_e1009 * _e1009)));
                                        let _e1024 = (_e1009 * _e987);
                                        let _e1027 = sqrt((_e1012 + (_e1024 * _e1024)));
                                        if _e992 {
                                            let _e1030 = ((-(_e1027) + _e517) / _e594);
                                            phi_1524_ = select(0f, select(1f, _e1030, (_e1030 < 1f)), (_e1030 > 0f));
                                        } else {
                                            phi_1524_ = select(0f, 1f, (_e1027 <= _e517));
                                        }
                                        let _e1038 = phi_1524_;
                                        let _e1041 = (_e714 + ((((((_e1007 / _e1015) * _e435) + ((_e1008 / _e1015) * _e436)) + ((_e1009 / _e1015) * _e437)) - _e714) * _e1038));
                                        if (_e723 != _e723) {
                                            phi_2479_ = true;
                                        } else {
                                            phi_2479_ = (_e1006 >= _e723);
                                        }
                                        let _e1045 = phi_2479_;
                                        if (_e721 != _e721) {
                                            phi_2494_ = true;
                                        } else {
                                            phi_2494_ = (_e1041 >= _e721);
                                        }
                                        let _e1050 = phi_2494_;
                                        phi_1006_ = (_e719 + 1u);
                                        phi_1009_ = select(_e721, _e1041, _e1050);
                                        phi_1011_ = select(_e723, _e1006, _e1045);
                                    } else {
                                        phi_1006_ = u32();
                                        phi_1009_ = f32();
                                        phi_1011_ = f32();
                                    }
                                    let _e1054 = phi_1006_;
                                    let _e1056 = phi_1009_;
                                    let _e1058 = phi_1011_;
                                    continue;
                                    continuing {
                                        phi_1005_ = _e1054;
                                        phi_1008_ = _e1056;
                                        phi_1010_ = _e1058;
                                        phi_2711_ = _e608;
                                        break if !(_e724);
                                    }
                                }
                                let _e1061 = phi_2711_;
                                phi_2846_ = _e1061;
                                if _e1061 {
                                    break;
                                }
                                let _e1063 = local_3;
                                let _e1064 = abs(_e1063);
                                let _e1075 = (((_e1064 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1064))) >> bitcast<u32>(1i))))));
                                let _e1077 = local_4;
                                let _e1080 = select((3.141593f - _e1075), _e1075, (_e1077 >= 0f));
                                let _e1081 = -(_e1080);
                                let _e1083 = local_5;
                                let _e1084 = abs(_e1083);
                                let _e1095 = (((_e1084 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1084))) >> bitcast<u32>(1i))))));
                                let _e1097 = local_6;
                                let _e1100 = select((3.141593f - _e1095), _e1095, (_e1097 >= 0f));
                                let _e1103 = (_e670 + ((1f - _e670) * 0.05f));
                                let _e1104 = (_e1080 * -2f);
                                let _e1105 = sin(_e705);
                                let _e1111 = (_e1100 * 2f);
                                let _e1123 = params.member.member_13;
                                if (_e1123 == 0u) {
                                    phi_1743_ = _e612;
                                } else {
                                    let _e1129 = ((_e1080 * -3f) - _e705);
                                    let _e1137 = ((_e1100 * 3f) - _e705);
                                    let _e1142 = (_e1081 + _e705);
                                    let _e1144 = (_e1100 + _e705);
                                    let _e1149 = (((((((sin((_e1081 - _e705)) * 6f) - sin(_e1129)) + (sin((_e1100 - _e705)) * 6f)) - sin(_e1137)) + (_e1105 * 16f)) - ((sin(_e1142) + sin(_e1144)) * 3f)) * 0.083333336f);
                                    let _e1161 = (((-(cos(_e1129)) - cos(_e1137)) + (cos(_e705) * 8f)) - ((cos(_e1142) + cos(_e1144)) * 3f));
                                    let _e1162 = (_e622 * _e1149);
                                    let _e1163 = (_e621 * _e1149);
                                    let _e1164 = (_e1161 * -0.083333336f);
                                    let _e1165 = (-1f * _e437);
                                    let _e1166 = (-1f * _e435);
                                    let _e1168 = (1f / (_e1165 + 1f));
                                    let _e1169 = (_e1168 * _e436);
                                    let _e1173 = (_e1169 * _e1166);
                                    let _e1194 = (_e1165 > 0.9997f);
                                    let _e1195 = (_e1165 < -0.9997f);
                                    phi_1743_ = (_e612 + vec3<f32>((select(select(((((_e1165 + (_e1169 * _e436)) * _e1162) + (_e1173 * _e1163)) + (_e1166 * _e1164)), _e1162, _e1195), _e1162, _e1194) * _e1103), (select(select((((_e1173 * _e1162) + ((_e1165 + ((_e1168 * _e1166) * _e1166)) * _e1163)) + (-(_e436) * _e1164)), -(_e1163), _e1195), _e1163, _e1194) * _e1103), (select(select((((_e435 * _e1162) + (_e436 * _e1163)) + (_e1165 * _e1164)), (_e1161 * 0.083333336f), _e1195), _e1164, _e1194) * _e1103)));
                                }
                                let _e1208 = phi_1743_;
                                phi_2847_ = _e1061;
                                phi_830_ = (_e610 + 1u);
                                phi_833_ = _e1208;
                                phi_835_ = (_e614 + ((0.25f * (((_e689 + (_e1104 * _e1105)) - cos((_e1104 - _e705))) + ((_e689 + (_e1111 * _e1105)) - cos((_e1111 - _e705))))) * _e1103));
                            } else {
                                phi_2847_ = _e608;
                                phi_830_ = u32();
                                phi_833_ = vec3<f32>();
                                phi_835_ = f32();
                            }
                            let _e1211 = phi_2847_;
                            let _e1213 = phi_830_;
                            let _e1215 = phi_833_;
                            let _e1217 = phi_835_;
                            continue;
                            continuing {
                                phi_2765_ = _e1211;
                                phi_829_ = _e1213;
                                phi_832_ = _e1215;
                                phi_834_ = _e1217;
                                phi_2846_ = _e1211;
                                break if !(_e615);
                            }
                        }
                        let _e1220 = phi_2846_;
                        if _e1220 {
                            break;
                        }
                        let _e1223 = local_7;
                        let _e1226 = local_8;
                        phi_1749_ = type_23((_e1223 / f32(_e606)), _e1226);
                    } else {
                        phi_1749_ = type_23(1f, vec3<f32>(0f, 0f, 0f));
                    }
                    let _e1229 = phi_1749_;
                    if _e590 {
                        let _e1234 = params.member.member_6;
                        let _e1235 = pow(_e1229.member, _e1234);
                        if (_e1235 != _e1235) {
                            phi_2521_ = true;
                        } else {
                            phi_2521_ = (0.03f >= _e1235);
                        }
                        let _e1239 = phi_2521_;
                        let _e1240 = select(_e1235, 0.03f, _e1239);
                        let _e1243 = params.member.member_13;
                        if (_e1243 == 0u) {
                            let _e1245 = (_e1240 * 0.6666667f);
                            let _e1251 = ((select(0f, select(1f, _e1245, (_e1245 < 1f)), (_e1245 > 0f)) * 255f) + 0.5f);
                            phi_1825_ = select(select(u32(_e1251), 0u, (_e1251 < 0f)), 4294967295u, (_e1251 > 4294967000f));
                        } else {
                            let _e1265 = sqrt((((_e1229.member_1.x * _e1229.member_1.x) + (_e1229.member_1.y * _e1229.member_1.y)) + (_e1229.member_1.z * _e1229.member_1.z)));
                            if (_e1265 > 0f) {
                                phi_1804_ = (_e1229.member_1 / vec3(_e1265));
                            } else {
                                phi_1804_ = vec3<f32>(_e507, _e508, _e509);
                            }
                            let _e1270 = phi_1804_;
                            let _e1271 = (_e1240 * 0.6666667f);
                            let _e1278 = ((_e1270.x * 0.5f) + 0.5f);
                            let _e1279 = ((_e1270.y * 0.5f) + 0.5f);
                            let _e1280 = ((_e1270.z * 0.5f) + 0.5f);
                            let _e1286 = ((select(0f, select(1f, _e1278, (_e1278 < 1f)), (_e1278 > 0f)) * 255f) + 0.5f);
                            let _e1297 = ((select(0f, select(1f, _e1279, (_e1279 < 1f)), (_e1279 > 0f)) * 255f) + 0.5f);
                            let _e1311 = ((select(0f, select(1f, _e1280, (_e1280 < 1f)), (_e1280 > 0f)) * 255f) + 0.5f);
                            let _e1325 = ((select(0f, select(1f, _e1271, (_e1271 < 1f)), (_e1271 > 0f)) * 255f) + 0.5f);
                            phi_1825_ = (((select(select(u32(_e1286), 0u, (_e1286 < 0f)), 4294967295u, (_e1286 > 4294967000f)) | (select(select(u32(_e1297), 0u, (_e1297 < 0f)), 4294967295u, (_e1297 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1311), 0u, (_e1311 < 0f)), 4294967295u, (_e1311 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1325), 0u, (_e1325 < 0f)), 4294967295u, (_e1325 > 4294967000f)) << bitcast<u32>(24i)));
                        }
                        let _e1335 = phi_1825_;
                        phi_1870_ = _e1335;
                    } else {
                        let _e1338 = params.member.member_13;
                        phi_1870_ = select(2852159616u, 170u, (_e1338 == 0u));
                    }
                    let _e1342 = phi_1870_;
                    if (_e119 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e119] = _e1342;
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
