struct type_5 {
    member: vec2<f32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_6 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
}

struct type_8 {
    member: array<f32>,
}

struct type_11 {
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

struct type_23 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_24 {
    member: type_23,
    member_1: type_23,
    member_2: type_5,
}

struct type_25 {
    member: type_6,
    member_1: u32,
    member_2: u32,
    member_3: f32,
    member_4: u32,
    member_5: vec2<u32>,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: u32,
    member_12: u32,
    member_13: u32,
    member_14: u32,
    member_15: u32,
}

struct type_26 {
    member: type_24,
    member_1: type_25,
}

struct type_28 {
    member: array<type_26>,
}

struct type_30 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
}

struct type_31 {
    member: type_30,
}

struct type_36 {
    member: array<atomic<u32>>,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> frame: type_28;
@group(0) @binding(2) 
var<storage> normals: type_11;
@group(0) @binding(5) 
var<uniform> params: type_31;
@group(0) @binding(1) 
var<storage> mips: type_8;
@group(0) @binding(3) 
var<storage, read_write> ray_min: type_36;
@group(0) @binding(4) 
var<storage, read_write> ray_max: type_36;

fn function_() {
    var phi_1789_: bool;
    var phi_856_: u32;
    var phi_1781_: bool;
    var phi_1025_: u32;
    var phi_1096_: f32;
    var phi_1097_: f32;
    var phi_1372_: i32;
    var phi_1412_: bool;
    var phi_1428_: bool;
    var phi_1549_: u32;
    var phi_1556_: u32;
    var phi_1373_: i32;
    var phi_1737_: bool;
    var phi_1805_: bool;
    var phi_1026_: u32;
    var phi_1804_: bool;
    var phi_1807_: bool;
    var phi_857_: u32;
    var phi_1806_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e58 = id_1;
            let _e70 = params.member.member_4.member.member[0u];
            let _e75 = select(select(u32(_e70), 0u, (_e70 < 0f)), 4294967295u, (_e70 > 4294967000f));
            let _e81 = params.member.member_4.member.member[1u];
            let _e86 = select(select(u32(_e81), 0u, (_e81 < 0f)), 4294967295u, (_e81 > 4294967000f));
            if (_e58.x >= _e75) {
            } else {
                if (_e58.y >= _e86) {
                } else {
                    if (0u < arrayLength((&frame.member))) {
                    } else {
                        break;
                    }
                    let _e93 = ((_e58.y * _e75) + _e58.x);
                    let _e96 = mips.member[_e93];
                    let _e100 = ((f32(bitcast<i32>(_e58.x)) + 0.5f) / _e70);
                    let _e104 = ((f32(bitcast<i32>(_e58.y)) + 0.5f) / _e81);
                    let _e105 = (_e96 * 0.99999f);
                    let _e113 = params.member.member_4.member.member_1[0u];
                    let _e115 = ((((_e100 * 2f) - 1f) * _e113) * _e105);
                    let _e123 = params.member.member_4.member.member_1[1u];
                    let _e125 = ((((_e104 * -2f) + 1f) * _e123) * _e105);
                    let _e126 = -(_e115);
                    let _e127 = -(_e125);
                    let _e128 = (_e96 * -0.99999f);
                    let _e135 = (1f / sqrt((((_e126 * _e126) + (_e127 * _e127)) + (_e128 * _e128))));
                    let _e141 = normals.member[_e93];
                    let _e144 = f32(bitcast<i32>((_e141 & 255u)));
                    let _e148 = (select(_e144, (_e144 - 256f), (_e144 >= 128f)) * 0.007874016f);
                    let _e151 = select(-1f, _e148, ((_e148 > -1f) || false));
                    let _e156 = f32(bitcast<i32>(((_e141 >> bitcast<u32>(8u)) & 255u)));
                    let _e160 = (select(_e156, (_e156 - 256f), (_e156 >= 128f)) * 0.007874016f);
                    let _e163 = select(-1f, _e160, ((_e160 > -1f) || false));
                    let _e165 = (1f - abs(_e151));
                    let _e166 = abs(_e163);
                    let _e167 = (_e165 - _e166);
                    let _e168 = (_e167 < 0f);
                    let _e176 = select(_e151, ((1f - _e166) * select(1f, -1f, (_e151 < 0f))), _e168);
                    let _e177 = select(_e163, (_e165 * select(1f, -1f, (_e163 < 0f))), _e168);
                    let _e184 = (1f / sqrt((((_e176 * _e176) + (_e177 * _e177)) + (_e167 * _e167))));
                    let _e185 = (_e176 * _e184);
                    let _e186 = (_e177 * _e184);
                    let _e187 = (_e167 * _e184);
                    let _e188 = -(_e187);
                    let _e194 = ((((_e185 * (_e126 * _e135)) + (_e186 * (_e127 * _e135))) + (_e188 * (_e128 * _e135))) < 0f);
                    let _e203 = params.member.member_4.member_1;
                    let _e207 = params.member.member_4.member_2;
                    let _e208 = (_e203 * _e207);
                    let _e212 = (_e208 / (((_e96 * 1.99998f) * _e113) / _e70));
                    let _e217 = params.member.member_4.member_11;
                    let _e218 = (_e58.x & 63u);
                    let _e219 = (_e58.y & 63u);
                    let _e222 = ((_e218 >> bitcast<u32>(5u)) & 1u);
                    let _e225 = ((_e219 >> bitcast<u32>(5u)) & 1u);
                    let _e229 = (_e225 ^ 1u);
                    let _e231 = ((_e222 & _e229) * 63u);
                    let _e232 = (_e218 ^ _e231);
                    let _e233 = (_e219 ^ _e231);
                    let _e235 = ((_e232 ^ _e233) * _e229);
                    let _e236 = (_e232 ^ _e235);
                    let _e237 = (_e233 ^ _e235);
                    let _e240 = ((_e236 >> bitcast<u32>(4u)) & 1u);
                    let _e243 = ((_e237 >> bitcast<u32>(4u)) & 1u);
                    let _e248 = (_e243 ^ 1u);
                    let _e250 = ((_e240 & _e248) * 63u);
                    let _e251 = (_e236 ^ _e250);
                    let _e252 = (_e237 ^ _e250);
                    let _e254 = ((_e251 ^ _e252) * _e248);
                    let _e255 = (_e251 ^ _e254);
                    let _e256 = (_e252 ^ _e254);
                    let _e259 = ((_e255 >> bitcast<u32>(3u)) & 1u);
                    let _e262 = ((_e256 >> bitcast<u32>(3u)) & 1u);
                    let _e267 = (_e262 ^ 1u);
                    let _e269 = ((_e259 & _e267) * 63u);
                    let _e270 = (_e255 ^ _e269);
                    let _e271 = (_e256 ^ _e269);
                    let _e273 = ((_e270 ^ _e271) * _e267);
                    let _e274 = (_e270 ^ _e273);
                    let _e275 = (_e271 ^ _e273);
                    let _e278 = ((_e274 >> bitcast<u32>(2u)) & 1u);
                    let _e281 = ((_e275 >> bitcast<u32>(2u)) & 1u);
                    let _e286 = (_e281 ^ 1u);
                    let _e288 = ((_e278 & _e286) * 63u);
                    let _e289 = (_e274 ^ _e288);
                    let _e290 = (_e275 ^ _e288);
                    let _e292 = ((_e289 ^ _e290) * _e286);
                    let _e293 = (_e289 ^ _e292);
                    let _e294 = (_e290 ^ _e292);
                    let _e297 = ((_e293 >> bitcast<u32>(1u)) & 1u);
                    let _e300 = ((_e294 >> bitcast<u32>(1u)) & 1u);
                    let _e305 = (_e300 ^ 1u);
                    let _e307 = ((_e297 & _e305) * 63u);
                    let _e308 = (_e293 ^ _e307);
                    let _e309 = (_e294 ^ _e307);
                    let _e311 = ((_e308 ^ _e309) * _e305);
                    let _e323 = f32(bitcast<i32>((((((((((_e222 * 3u) ^ _e225) * 1024u) + (((_e240 * 3u) ^ _e243) * 256u)) + (((_e259 * 3u) ^ _e262) * 64u)) + (((_e278 * 3u) ^ _e281) * 16u)) + (((_e297 * 3u) ^ _e300) * 4u)) + ((((_e308 ^ _e311) & 1u) * 3u) ^ ((_e309 ^ _e311) & 1u))) + (288u * (_e217 % 64u)))));
                    let _e325 = ((_e323 * 0.7548777f) + 0.5f);
                    let _e329 = ((_e323 * 0.5698403f) + 0.5f);
                    let _e335 = params.member.member_4.member_7;
                    let _e338 = exp2(((2f * _e335) + 1f));
                    let _e343 = params.member.member_4.member.member_3;
                    if select(false, (_e96 < _e343), (_e96 > 0f)) {
                        let _e349 = params.member.member_1;
                        phi_1789_ = false;
                        phi_856_ = 0u;
                        loop {
                            let _e354 = phi_1789_;
                            let _e356 = phi_856_;
                            let _e360 = params.member.member_4.member_8;
                            let _e362 = select(1u, _e360, (1u < _e360));
                            let _e363 = (_e356 < _e362);
                            if _e363 {
                                let _e370 = ((((_e325 - floor(_e325)) + f32(bitcast<i32>(_e356))) * 3.1415927f) / f32(bitcast<i32>(_e362)));
                                phi_1781_ = _e354;
                                phi_1025_ = 0u;
                                loop {
                                    let _e377 = phi_1781_;
                                    let _e379 = phi_1025_;
                                    let _e383 = params.member.member_4.member_9;
                                    let _e385 = select(1u, _e383, (1u < _e383));
                                    let _e386 = (_e379 < _e385);
                                    if _e386 {
                                        let _e392 = ((_e329 - floor(_e329)) + (f32(bitcast<i32>((_e356 + (_e379 * _e385)))) * 0.618034f));
                                        let _e401 = (((_e392 - floor(_e392)) + f32(bitcast<i32>(_e379))) * (1f / f32(bitcast<i32>(_e385))));
                                        let _e405 = params.member.member_4.member_4;
                                        if (_e405 == 2f) {
                                            phi_1097_ = (_e401 * _e401);
                                        } else {
                                            if (_e405 == 1f) {
                                                phi_1096_ = _e401;
                                            } else {
                                                phi_1096_ = pow(_e401, _e405);
                                            }
                                            let _e411 = phi_1096_;
                                            phi_1097_ = _e411;
                                        }
                                        let _e413 = phi_1097_;
                                        let _e414 = (_e413 + (1.3f / _e212));
                                        let _e415 = ((cos(_e370) * _e212) * _e414);
                                        let _e416 = ((-(sin(_e370)) * _e212) * _e414);
                                        let _e419 = ((_e415 * _e415) + (_e416 * _e416));
                                        let _e424 = (select(1u, _e75, (1u < _e75)) * select(1u, _e86, (1u < _e86)));
                                        let _e425 = (_e419 > _e338);
                                        let _e429 = (_e75 >> bitcast<u32>(1u));
                                        let _e433 = (_e86 >> bitcast<u32>(1u));
                                        let _e437 = (_e424 + (select(1u, _e429, (1u < _e429)) * select(1u, _e433, (1u < _e433))));
                                        let _e439 = (_e419 > (_e338 * 4f));
                                        let _e443 = (_e75 >> bitcast<u32>(2u));
                                        let _e447 = (_e86 >> bitcast<u32>(2u));
                                        let _e451 = (_e437 + (select(1u, _e443, (1u < _e443)) * select(1u, _e447, (1u < _e447))));
                                        let _e453 = (_e419 > (_e338 * 16f));
                                        let _e457 = (_e75 >> bitcast<u32>(3u));
                                        let _e461 = (_e86 >> bitcast<u32>(3u));
                                        let _e467 = (_e419 > (_e338 * 64f));
                                        let _e469 = select(select(select(select(0u, _e424, _e425), _e437, _e439), _e451, _e453), (_e451 + (select(1u, _e457, (1u < _e457)) * select(1u, _e461, (1u < _e461)))), _e467);
                                        let _e470 = (select(select(select(select(0u, 1u, _e425), 2u, _e439), 3u, _e453), 4u, _e467) & 31u);
                                        let _e472 = (_e75 >> bitcast<u32>(_e470));
                                        let _e474 = select(1u, _e472, (1u < _e472));
                                        let _e476 = (_e86 >> bitcast<u32>(_e470));
                                        let _e478 = select(1u, _e476, (1u < _e476));
                                        let _e481 = (round(_e415) * (1f / _e70));
                                        let _e484 = (round(_e416) * (1f / _e81));
                                        let _e485 = (_e100 + _e481);
                                        let _e486 = (_e104 + _e484);
                                        let _e487 = (_e100 - _e481);
                                        let _e488 = (_e104 - _e484);
                                        let _e490 = f32(bitcast<i32>(_e474));
                                        let _e491 = (_e485 * _e490);
                                        let _e494 = f32(bitcast<i32>((_e474 - 1u)));
                                        let _e504 = f32(bitcast<i32>(_e478));
                                        let _e505 = (_e486 * _e504);
                                        let _e508 = f32(bitcast<i32>((_e478 - 1u)));
                                        let _e522 = mips.member[((_e469 + ((bitcast<u32>((floor(select(0f, select(_e508, _e505, (_e505 < _e508)), (_e505 > 0f))) + 8388608f)) - 1258291200u) * _e474)) + (bitcast<u32>((floor(select(0f, select(_e494, _e491, (_e491 < _e494)), (_e491 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e532 = (_e487 * _e490);
                                        let _e541 = (_e488 * _e504);
                                        let _e555 = mips.member[((_e469 + ((bitcast<u32>((floor(select(0f, select(_e508, _e541, (_e541 < _e508)), (_e541 > 0f))) + 8388608f)) - 1258291200u) * _e474)) + (bitcast<u32>((floor(select(0f, select(_e494, _e532, (_e532 < _e494)), (_e532 > 0f))) + 8388608f)) - 1258291200u))];
                                        phi_1372_ = 0i;
                                        loop {
                                            let _e566 = phi_1372_;
                                            let _e567 = (_e566 < 2i);
                                            if _e567 {
                                                let _e570 = select(vec3<f32>(((((_e487 * 2f) - 1f) * _e113) * _e555), ((((_e488 * -2f) + 1f) * _e123) * _e555), _e555), vec3<f32>(((((_e485 * 2f) - 1f) * _e113) * _e522), ((((_e486 * -2f) + 1f) * _e123) * _e522), _e522), vec3((_e566 == 0i)));
                                                let _e572 = (_e570.x - _e115);
                                                let _e574 = (_e570.y - _e125);
                                                let _e576 = (_e570.z - _e105);
                                                let _e581 = (((_e572 * _e572) + (_e574 * _e574)) + (_e576 * _e576));
                                                if (_e349 <= 0f) {
                                                    phi_1412_ = true;
                                                } else {
                                                    phi_1412_ = (_e581 <= (_e349 * _e349));
                                                }
                                                let _e586 = phi_1412_;
                                                if _e586 {
                                                    phi_1428_ = ((((_e572 * select(_e185, -(_e185), _e194)) + (_e574 * select(_e186, -(_e186), _e194))) + (_e576 * select(_e188, _e187, _e194))) > (0.018f * sqrt(_e581)));
                                                } else {
                                                    phi_1428_ = false;
                                                }
                                                let _e596 = phi_1428_;
                                                if _e596 {
                                                    let _e597 = (0.5f / _e570.z);
                                                    let _e606 = frame.member[0u].member_1.member.member.member_1[0u];
                                                    let _e617 = frame.member[0u].member_1.member.member.member_1[1u];
                                                    let _e625 = frame.member[0u].member_1.member_5[0u];
                                                    let _e631 = frame.member[0u].member_1.member_5[1u];
                                                    let _e638 = frame.member[0u].member_1.member_4;
                                                    let _e639 = f32(_e638);
                                                    let _e640 = (2u * _e638);
                                                    let _e641 = (_e625 + _e640);
                                                    let _e647 = (floor(((((_e570.x * _e597) / _e606) + 0.5f) * f32(_e625))) + _e639);
                                                    let _e648 = f32((_e641 - 1u));
                                                    let _e652 = select(0f, select(_e648, _e647, (_e647 < _e648)), (_e647 > 0f));
                                                    let _e655 = (floor(((0.5f - ((_e570.y * _e597) / _e617)) * f32(_e631))) + _e639);
                                                    let _e656 = f32(((_e631 + _e640) - 1u));
                                                    let _e660 = select(0f, select(_e656, _e655, (_e655 < _e656)), (_e655 > 0f));
                                                    let _e672 = ((select(select(u32(_e660), 0u, (_e660 < 0f)), 4294967295u, (_e660 > 4294967000f)) * _e641) + select(select(u32(_e652), 0u, (_e652 < 0f)), 4294967295u, (_e652 > 4294967000f)));
                                                    let _e678 = sqrt((((_e570.x * _e570.x) + (_e570.y * _e570.y)) + (_e570.z * _e570.z)));
                                                    if (_e678 > 0f) {
                                                        phi_1549_ = bitcast<u32>(_e678);
                                                    } else {
                                                        phi_1549_ = 0u;
                                                    }
                                                    let _e682 = phi_1549_;
                                                    let _e683 = (_e678 + (2f * select(_e208, _e349, (_e349 > 0f))));
                                                    if (_e683 > 0f) {
                                                        phi_1556_ = bitcast<u32>(_e683);
                                                    } else {
                                                        phi_1556_ = 0u;
                                                    }
                                                    let _e687 = phi_1556_;
                                                    let _e688 = (_e672 < arrayLength((&ray_min.member)));
                                                    if _e688 {
                                                    } else {
                                                        phi_1737_ = true;
                                                        break;
                                                    }
                                                    let _e691 = atomicLoad((&ray_min.member[_e672]));
                                                    if (_e691 > _e682) {
                                                        if _e688 {
                                                        } else {
                                                            phi_1737_ = true;
                                                            break;
                                                        }
                                                        let _e693 = atomicMin((&ray_min.member[_e672]), _e682);
                                                    }
                                                    let _e694 = (_e672 < arrayLength((&ray_max.member)));
                                                    if _e694 {
                                                    } else {
                                                        phi_1737_ = true;
                                                        break;
                                                    }
                                                    let _e697 = atomicLoad((&ray_max.member[_e672]));
                                                    if (_e697 < _e687) {
                                                        if _e694 {
                                                        } else {
                                                            phi_1737_ = true;
                                                            break;
                                                        }
                                                        let _e699 = atomicMax((&ray_max.member[_e672]), _e687);
                                                    }
                                                }
                                                phi_1373_ = (_e566 + 1i);
                                            } else {
                                                phi_1373_ = i32();
                                            }
                                            let _e702 = phi_1373_;
                                            continue;
                                            continuing {
                                                phi_1372_ = _e702;
                                                phi_1737_ = _e377;
                                                break if !(_e567);
                                            }
                                        }
                                        let _e705 = phi_1737_;
                                        phi_1804_ = _e705;
                                        if _e705 {
                                            break;
                                        }
                                        phi_1805_ = _e705;
                                        phi_1026_ = (_e379 + 1u);
                                    } else {
                                        phi_1805_ = _e377;
                                        phi_1026_ = u32();
                                    }
                                    let _e708 = phi_1805_;
                                    let _e710 = phi_1026_;
                                    continue;
                                    continuing {
                                        phi_1781_ = _e708;
                                        phi_1025_ = _e710;
                                        phi_1804_ = _e708;
                                        break if !(_e386);
                                    }
                                }
                                let _e713 = phi_1804_;
                                phi_1806_ = _e713;
                                if _e713 {
                                    break;
                                }
                                phi_1807_ = _e713;
                                phi_857_ = (_e356 + 1u);
                            } else {
                                phi_1807_ = _e354;
                                phi_857_ = u32();
                            }
                            let _e716 = phi_1807_;
                            let _e718 = phi_857_;
                            continue;
                            continuing {
                                phi_1789_ = _e716;
                                phi_856_ = _e718;
                                phi_1806_ = _e716;
                                break if !(_e363);
                            }
                        }
                        let _e721 = phi_1806_;
                        if _e721 {
                            break;
                        }
                    }
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vbao_sd_request(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
