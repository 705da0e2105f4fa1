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
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
}

struct type_21 {
    member: type_20,
}

struct type_24 {
    member: array<vec2<f32>>,
}

struct type_26 {
    member: vec2<u32>,
    member_1: vec3<f32>,
    member_2: vec3<f32>,
    member_3: f32,
    member_4: f32,
    member_5: f32,
}

struct type_27 {
    member: u32,
    member_1: type_26,
}

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_29 {
    member: f32,
    member_1: u32,
    member_2: u32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;
@group(0) @binding(6) 
var<uniform> params: type_21;
@group(0) @binding(2) 
var<storage> kernel: type_24;
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_341_: i32;
    var phi_360_: i32;
    var phi_411_: i32;
    var phi_430_: i32;
    var phi_481_: i32;
    var phi_500_: i32;
    var phi_551_: i32;
    var phi_570_: i32;
    var phi_1722_: f32;
    var phi_1726_: f32;
    var phi_1727_: bool;
    var phi_1765_: f32;
    var phi_1769_: f32;
    var phi_1770_: bool;
    var phi_1808_: f32;
    var phi_1812_: f32;
    var phi_1813_: bool;
    var phi_1851_: f32;
    var phi_1855_: f32;
    var phi_1856_: bool;
    var phi_1879_: bool;
    var phi_1894_: bool;
    var phi_827_: vec2<f32>;
    var phi_858_: vec3<f32>;
    var phi_864_: u32;
    var phi_867_: u32;
    var phi_869_: u32;
    var phi_871_: u32;
    var phi_900_: u32;
    var phi_901_: u32;
    var phi_902_: u32;
    var phi_903_: u32;
    var phi_865_: u32;
    var phi_868_: u32;
    var phi_870_: u32;
    var phi_872_: u32;
    var local: u32;
    var phi_934_: type_28;
    var phi_2069_: bool;
    var phi_969_: u32;
    var phi_972_: f32;
    var phi_1909_: bool;
    var phi_1118_: u32;
    var phi_1121_: f32;
    var phi_1123_: bool;
    var phi_1125_: bool;
    var phi_1127_: f32;
    var phi_1129_: f32;
    var phi_1233_: u32;
    var phi_1254_: u32;
    var phi_1348_: u32;
    var phi_1379_: u32;
    var phi_1992_: bool;
    var phi_2007_: bool;
    var phi_1968_: vec2<f32>;
    var phi_1519_: u32;
    var phi_1521_: u32;
    var phi_1522_: f32;
    var phi_1523_: bool;
    var phi_1524_: bool;
    var phi_1525_: f32;
    var phi_1528_: bool;
    var phi_1529_: bool;
    var phi_1119_: u32;
    var phi_1122_: f32;
    var phi_1124_: bool;
    var phi_1126_: bool;
    var phi_1128_: f32;
    var phi_1130_: f32;
    var phi_1533_: bool;
    var phi_1535_: bool;
    var phi_1536_: bool;
    var phi_2021_: bool;
    var phi_1695_: bool;
    var phi_1694_: bool;
    var phi_1693_: bool;
    var phi_1692_: bool;
    var phi_1690_: f32;
    var local_1: f32;
    var local_2: bool;
    var local_3: f32;
    var local_4: bool;
    var phi_1576_: f32;
    var phi_2147_: bool;
    var phi_970_: u32;
    var phi_973_: f32;
    var phi_2146_: bool;
    var local_5: f32;
    var phi_1647_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e60 = id_1;
            let _e62 = arrayLength((&depth.member));
            let _e64 = arrayLength((&normals.member));
            let _e66 = arrayLength((&kernel.member));
            let _e77 = params.member.member.member[0u];
            let _e82 = select(select(u32(_e77), 0u, (_e77 < 0f)), 4294967295u, (_e77 > 4294967000f));
            let _e87 = params.member.member.member[1u];
            let _e92 = select(select(u32(_e87), 0u, (_e87 < 0f)), 4294967295u, (_e87 > 4294967000f));
            if (_e60.x >= _e82) {
            } else {
                if (_e60.y >= _e92) {
                } else {
                    let _e98 = ((_e60.y * _e82) + _e60.x);
                    let _e99 = (_e98 < _e62);
                    if _e99 {
                    } else {
                        break;
                    }
                    let _e102 = depth.member[_e98];
                    let _e106 = params.member.member.member_3;
                    let _e109 = select(false, (_e102 < _e106), (_e102 > 0f));
                    let _e110 = select(_e106, _e102, _e109);
                    let _e111 = bitcast<i32>(_e60.x);
                    let _e112 = (_e111 + -1i);
                    let _e114 = (bitcast<i32>(_e82) - 1i);
                    let _e115 = (0i <= _e114);
                    if _e115 {
                    } else {
                        break;
                    }
                    if (_e112 < 0i) {
                        phi_341_ = 0i;
                    } else {
                        phi_341_ = select(_e112, _e114, (_e112 > _e114));
                    }
                    let _e120 = phi_341_;
                    let _e122 = bitcast<i32>(_e60.y);
                    let _e124 = (bitcast<i32>(_e92) - 1i);
                    let _e125 = (0i <= _e124);
                    if _e125 {
                    } else {
                        break;
                    }
                    let _e126 = (_e122 < 0i);
                    if _e126 {
                        phi_360_ = 0i;
                    } else {
                        phi_360_ = select(_e122, _e124, (_e122 > _e124));
                    }
                    let _e130 = phi_360_;
                    let _e133 = ((bitcast<u32>(_e130) * _e82) + bitcast<u32>(_e120));
                    if (_e133 < _e62) {
                    } else {
                        break;
                    }
                    let _e137 = depth.member[_e133];
                    let _e142 = (_e111 + 1i);
                    if _e115 {
                    } else {
                        break;
                    }
                    if (_e142 < 0i) {
                        phi_411_ = 0i;
                    } else {
                        phi_411_ = select(_e142, _e114, (_e142 > _e114));
                    }
                    let _e147 = phi_411_;
                    if _e125 {
                    } else {
                        break;
                    }
                    if _e126 {
                        phi_430_ = 0i;
                    } else {
                        phi_430_ = select(_e122, _e124, (_e122 > _e124));
                    }
                    let _e152 = phi_430_;
                    let _e155 = ((bitcast<u32>(_e152) * _e82) + bitcast<u32>(_e147));
                    if (_e155 < _e62) {
                    } else {
                        break;
                    }
                    let _e159 = depth.member[_e155];
                    if _e115 {
                    } else {
                        break;
                    }
                    let _e164 = (_e111 < 0i);
                    if _e164 {
                        phi_481_ = 0i;
                    } else {
                        phi_481_ = select(_e111, _e114, (_e111 > _e114));
                    }
                    let _e168 = phi_481_;
                    let _e170 = (_e122 + -1i);
                    if _e125 {
                    } else {
                        break;
                    }
                    if (_e170 < 0i) {
                        phi_500_ = 0i;
                    } else {
                        phi_500_ = select(_e170, _e124, (_e170 > _e124));
                    }
                    let _e175 = phi_500_;
                    let _e178 = ((bitcast<u32>(_e175) * _e82) + bitcast<u32>(_e168));
                    if (_e178 < _e62) {
                    } else {
                        break;
                    }
                    let _e182 = depth.member[_e178];
                    if _e115 {
                    } else {
                        break;
                    }
                    if _e164 {
                        phi_551_ = 0i;
                    } else {
                        phi_551_ = select(_e111, _e114, (_e111 > _e114));
                    }
                    let _e190 = phi_551_;
                    let _e192 = (_e122 + 1i);
                    if _e125 {
                    } else {
                        break;
                    }
                    if (_e192 < 0i) {
                        phi_570_ = 0i;
                    } else {
                        phi_570_ = select(_e192, _e124, (_e192 > _e124));
                    }
                    let _e197 = phi_570_;
                    let _e200 = ((bitcast<u32>(_e197) * _e82) + bitcast<u32>(_e190));
                    if (_e200 < _e62) {
                    } else {
                        break;
                    }
                    let _e204 = depth.member[_e200];
                    let _e209 = (select(_e106, _e137, select(false, (_e137 < _e106), (_e137 > 0f))) - _e110);
                    let _e210 = (select(_e106, _e159, select(false, (_e159 < _e106), (_e159 > 0f))) - _e110);
                    let _e211 = (select(_e106, _e182, select(false, (_e182 < _e106), (_e182 > 0f))) - _e110);
                    let _e212 = (select(_e106, _e204, select(false, (_e204 < _e106), (_e204 > 0f))) - _e110);
                    let _e213 = (_e210 - _e209);
                    let _e215 = (_e212 - _e211);
                    let _e223 = abs(_e209);
                    let _e224 = abs(_e210);
                    let _e225 = abs(_e211);
                    let _e226 = abs(_e212);
                    let _e227 = abs((_e209 + (_e213 * 0.5f)));
                    let _e228 = abs((_e210 + (_e213 * -0.5f)));
                    let _e229 = abs((_e211 + (_e215 * 0.5f)));
                    let _e230 = abs((_e212 + (_e215 * -0.5f)));
                    let _e239 = (_e110 * 0.011f);
                    let _e244 = (1.25f - (select(_e227, _e223, (_e223 < _e227)) / _e239));
                    let _e248 = select(0f, select(1f, _e244, (_e244 < 1f)), (_e244 > 0f));
                    let _e249 = (1.25f - (select(_e228, _e224, (_e224 < _e228)) / _e239));
                    let _e253 = select(0f, select(1f, _e249, (_e249 < 1f)), (_e249 > 0f));
                    let _e254 = (1.25f - (select(_e229, _e225, (_e225 < _e229)) / _e239));
                    let _e258 = select(0f, select(1f, _e254, (_e254 < 1f)), (_e254 > 0f));
                    let _e259 = (1.25f - (select(_e230, _e226, (_e226 < _e230)) / _e239));
                    let _e263 = select(0f, select(1f, _e259, (_e259 < 1f)), (_e259 > 0f));
                    let _e268 = (select(0f, select(1f, _e248, (_e248 < 1f)), (_e248 > 0f)) * 2.9f);
                    let _e270 = floor((_e268 + 0.5f));
                    if ((_e270 - _e268) == 0.5f) {
                        let _e276 = ((floor((_e270 * 0.5f)) * 2f) != _e270);
                        if _e276 {
                            phi_1722_ = (_e270 - 1f);
                        } else {
                            phi_1722_ = f32();
                        }
                        let _e279 = phi_1722_;
                        phi_1726_ = _e279;
                        phi_1727_ = select(true, false, _e276);
                    } else {
                        phi_1726_ = f32();
                        phi_1727_ = true;
                    }
                    let _e282 = phi_1726_;
                    let _e284 = phi_1727_;
                    let _e285 = select(_e282, _e270, _e284);
                    let _e296 = (select(0f, select(1f, _e253, (_e253 < 1f)), (_e253 > 0f)) * 2.9f);
                    let _e298 = floor((_e296 + 0.5f));
                    if ((_e298 - _e296) == 0.5f) {
                        let _e304 = ((floor((_e298 * 0.5f)) * 2f) != _e298);
                        if _e304 {
                            phi_1765_ = (_e298 - 1f);
                        } else {
                            phi_1765_ = f32();
                        }
                        let _e307 = phi_1765_;
                        phi_1769_ = _e307;
                        phi_1770_ = select(true, false, _e304);
                    } else {
                        phi_1769_ = f32();
                        phi_1770_ = true;
                    }
                    let _e310 = phi_1769_;
                    let _e312 = phi_1770_;
                    let _e313 = select(_e310, _e298, _e312);
                    let _e325 = (select(0f, select(1f, _e258, (_e258 < 1f)), (_e258 > 0f)) * 2.9f);
                    let _e327 = floor((_e325 + 0.5f));
                    if ((_e327 - _e325) == 0.5f) {
                        let _e333 = ((floor((_e327 * 0.5f)) * 2f) != _e327);
                        if _e333 {
                            phi_1808_ = (_e327 - 1f);
                        } else {
                            phi_1808_ = f32();
                        }
                        let _e336 = phi_1808_;
                        phi_1812_ = _e336;
                        phi_1813_ = select(true, false, _e333);
                    } else {
                        phi_1812_ = f32();
                        phi_1813_ = true;
                    }
                    let _e339 = phi_1812_;
                    let _e341 = phi_1813_;
                    let _e342 = select(_e339, _e327, _e341);
                    let _e354 = (select(0f, select(1f, _e263, (_e263 < 1f)), (_e263 > 0f)) * 2.9f);
                    let _e356 = floor((_e354 + 0.5f));
                    if ((_e356 - _e354) == 0.5f) {
                        let _e362 = ((floor((_e356 * 0.5f)) * 2f) != _e356);
                        if _e362 {
                            phi_1851_ = (_e356 - 1f);
                        } else {
                            phi_1851_ = f32();
                        }
                        let _e365 = phi_1851_;
                        phi_1855_ = _e365;
                        phi_1856_ = select(true, false, _e362);
                    } else {
                        phi_1855_ = f32();
                        phi_1856_ = true;
                    }
                    let _e368 = phi_1855_;
                    let _e370 = phi_1856_;
                    let _e371 = select(_e368, _e356, _e370);
                    let _e377 = ((((64u * select(select(u32(_e285), 0u, (_e285 < 0f)), 4294967295u, (_e285 > 4294967000f))) + (16u * select(select(u32(_e313), 0u, (_e313 < 0f)), 4294967295u, (_e313 > 4294967000f)))) + (4u * select(select(u32(_e342), 0u, (_e342 < 0f)), 4294967295u, (_e342 > 4294967000f)))) + select(select(u32(_e371), 0u, (_e371 < 0f)), 4294967295u, (_e371 > 4294967000f)));
                    if _e99 {
                    } else {
                        break;
                    }
                    if _e109 {
                        let _e390 = params.member.member.member_1[0u];
                        let _e392 = ((((((f32(_e60.x) + 0.5f) / _e77) * 2f) - 1f) * _e390) * _e102);
                        let _e399 = params.member.member.member_1[1u];
                        let _e401 = ((((((f32(_e60.y) + 0.5f) / _e87) * -2f) + 1f) * _e399) * _e102);
                        if (_e98 < _e64) {
                        } else {
                            break;
                        }
                        let _e406 = normals.member[_e98];
                        let _e414 = (f32((bitcast<i32>(((_e406 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e414 != _e414) {
                            phi_1879_ = true;
                        } else {
                            phi_1879_ = (-1f >= _e414);
                        }
                        let _e418 = phi_1879_;
                        let _e419 = select(_e414, -1f, _e418);
                        let _e429 = (f32((bitcast<i32>((((_e406 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e429 != _e429) {
                            phi_1894_ = true;
                        } else {
                            phi_1894_ = (-1f >= _e429);
                        }
                        let _e433 = phi_1894_;
                        let _e434 = select(_e429, -1f, _e433);
                        let _e437 = (1f - abs(_e419));
                        let _e438 = abs(_e434);
                        let _e439 = (_e437 - _e438);
                        if (_e439 < 0f) {
                            phi_827_ = vec2<f32>(((1f - _e438) * select(1f, -1f, (_e419 < 0f))), (_e437 * select(1f, -1f, (_e434 < 0f))));
                        } else {
                            phi_827_ = vec2<f32>(_e419, _e434);
                        }
                        let _e450 = phi_827_;
                        let _e459 = (1f / sqrt((((_e450.x * _e450.x) + (_e450.y * _e450.y)) + (_e439 * _e439))));
                        let _e460 = (_e450.x * _e459);
                        let _e461 = (_e450.y * _e459);
                        let _e462 = (_e439 * _e459);
                        let _e463 = -(_e462);
                        if ((((_e460 * -(_e392)) + (_e461 * -(_e401))) + (_e463 * -(_e102))) < 0f) {
                            phi_858_ = vec3<f32>(-(_e460), -(_e461), _e462);
                        } else {
                            phi_858_ = vec3<f32>(_e460, _e461, _e463);
                        }
                        let _e478 = phi_858_;
                        let _e481 = params.member.member_8;
                        phi_864_ = (_e60.y & 63u);
                        phi_867_ = (_e60.x & 63u);
                        phi_869_ = 32u;
                        phi_871_ = 0u;
                        loop {
                            let _e485 = phi_864_;
                            let _e487 = phi_867_;
                            let _e489 = phi_869_;
                            let _e491 = phi_871_;
                            local = _e491;
                            let _e492 = (_e489 > 0u);
                            if _e492 {
                                let _e495 = select(0u, 1u, ((_e487 & _e489) != 0u));
                                let _e498 = select(0u, 1u, ((_e485 & _e489) != 0u));
                                if (_e498 == 0u) {
                                    if (_e495 == 1u) {
                                        phi_900_ = (63u - _e485);
                                        phi_901_ = (63u - _e487);
                                    } else {
                                        phi_900_ = _e485;
                                        phi_901_ = _e487;
                                    }
                                    let _e509 = phi_900_;
                                    let _e511 = phi_901_;
                                    phi_902_ = _e511;
                                    phi_903_ = _e509;
                                } else {
                                    phi_902_ = _e485;
                                    phi_903_ = _e487;
                                }
                                let _e513 = phi_902_;
                                let _e515 = phi_903_;
                                phi_865_ = _e513;
                                phi_868_ = _e515;
                                phi_870_ = (_e489 / 2u);
                                phi_872_ = (_e491 + ((_e489 * _e489) * ((3u * _e495) ^ _e498)));
                            } else {
                                phi_865_ = u32();
                                phi_868_ = u32();
                                phi_870_ = u32();
                                phi_872_ = u32();
                            }
                            let _e518 = phi_865_;
                            let _e520 = phi_868_;
                            let _e522 = phi_870_;
                            let _e524 = phi_872_;
                            continue;
                            continuing {
                                phi_864_ = _e518;
                                phi_867_ = _e520;
                                phi_869_ = _e522;
                                phi_871_ = _e524;
                                break if !(_e492);
                            }
                        }
                        let _e529 = local;
                        let _e531 = f32((_e529 + (288u * (_e481 % 64u))));
                        let _e533 = (0.5f + (_e531 * 0.7548777f));
                        let _e537 = (0.5f + (_e531 * 0.5698403f));
                        let _e540 = (6.2831855f * (_e533 - floor(_e533)));
                        phi_934_ = type_28(_e377, type_27(1u, type_26(vec2<u32>(_e60.x, _e60.y), vec3<f32>(_e392, _e401, _e102), _e478, sin(_e540), cos(_e540), (_e537 - floor(_e537)))));
                    } else {
                        phi_934_ = type_28(_e377, type_27(0u, type_27().member_1));
                    }
                    let _e552 = phi_934_;
                    if (bitcast<i32>(_e552.member_1.member) != 0i) {
                        let _e561 = params.member.member_5;
                        let _e563 = select(_e561, 64u, (64u < _e561));
                        let _e565 = select(_e563, _e66, (_e66 < _e563));
                        let _e567 = select(1u, _e565, (1u < _e565));
                        let _e570 = params.member.member_6;
                        let _e572 = select(1u, _e570, (1u < _e570));
                        phi_2069_ = false;
                        phi_969_ = 0u;
                        phi_972_ = 0f;
                        loop {
                            let _e574 = phi_2069_;
                            let _e576 = phi_969_;
                            let _e578 = phi_972_;
                            local_5 = _e578;
                            let _e579 = (_e576 < _e567);
                            if _e579 {
                                if (_e576 < _e66) {
                                } else {
                                    phi_2146_ = true;
                                    break;
                                }
                                let _e584 = kernel.member[_e576][0u];
                                let _e588 = kernel.member[_e576][1u];
                                let _e593 = ((_e552.member_1.member_1.member_4 * _e584) - (_e552.member_1.member_1.member_3 * _e588));
                                let _e596 = ((_e552.member_1.member_1.member_3 * _e584) + (_e552.member_1.member_1.member_4 * _e588));
                                let _e601 = ((1f - (_e593 * _e593)) - (_e596 * _e596));
                                if (_e601 != _e601) {
                                    phi_1909_ = true;
                                } else {
                                    phi_1909_ = (0f >= _e601);
                                }
                                let _e605 = phi_1909_;
                                let _e607 = sqrt(select(_e601, 0f, _e605));
                                let _e608 = -(_e607);
                                let _e612 = (-1f * _e552.member_1.member_1.member_2.z);
                                let _e613 = (-1f * _e552.member_1.member_1.member_2.x);
                                let _e615 = (1f / (_e612 + 1f));
                                let _e616 = (_e615 * _e552.member_1.member_1.member_2.y);
                                let _e620 = (_e616 * _e613);
                                let _e640 = (_e612 > 0.9997f);
                                let _e641 = (_e612 < -0.9997f);
                                let _e651 = params.member.member_1;
                                let _e655 = params.member.member_3;
                                let _e658 = params.member.member_4;
                                phi_1118_ = 1u;
                                phi_1121_ = _e651;
                                phi_1123_ = false;
                                phi_1125_ = true;
                                phi_1127_ = 0f;
                                phi_1129_ = 0f;
                                loop {
                                    let _e664 = phi_1118_;
                                    let _e666 = phi_1121_;
                                    let _e668 = phi_1123_;
                                    let _e670 = phi_1125_;
                                    let _e672 = phi_1127_;
                                    let _e674 = phi_1129_;
                                    local_1 = _e666;
                                    local_2 = _e668;
                                    local_3 = _e666;
                                    local_4 = _e668;
                                    let _e675 = (_e664 <= _e572);
                                    if _e675 {
                                        let _e681 = (((-(_e552.member_1.member_1.member_5) + f32(_e664)) * _e651) / f32(_e572));
                                        let _e686 = (_e552.member_1.member_1.member_1.x + (select(select(((((_e612 + (_e616 * _e552.member_1.member_1.member_2.y)) * _e593) + (_e620 * _e596)) + (_e613 * _e608)), _e593, _e641), _e593, _e640) * _e681));
                                        let _e688 = (_e552.member_1.member_1.member_1.y + (select(select((((_e620 * _e593) + ((_e612 + ((_e615 * _e613) * _e613)) * _e596)) + (-(_e552.member_1.member_1.member_2.y) * _e608)), -(_e596), _e641), _e596, _e640) * _e681));
                                        let _e690 = (_e552.member_1.member_1.member_1.z + (select(select((((_e552.member_1.member_1.member_2.x * _e593) + (_e552.member_1.member_1.member_2.y * _e596)) + (_e612 * _e608)), _e607, _e641), _e608, _e640) * _e681));
                                        let _e696 = params.member.member.member_1[0u];
                                        let _e699 = (((_e686 * 0.5f) / (_e690 * _e696)) + 0.5f);
                                        let _e705 = params.member.member.member_1[1u];
                                        let _e708 = (0.5f - ((_e688 * 0.5f) / (_e690 * _e705)));
                                        let _e718 = select(false, select(false, select(false, select(false, (_e708 <= 1f), (_e708 >= 0f)), select(false, (_e699 <= 1f), (_e699 >= 0f))), (_e690 > 0f)), _e670);
                                        if _e718 {
                                            let _e719 = (_e699 * _e77);
                                            if (_e719 > 0f) {
                                                let _e725 = select(select(u32(_e719), 0u, (_e719 < 0f)), 4294967295u, (_e719 > 4294967000f));
                                                let _e726 = (_e82 - 1u);
                                                phi_1233_ = select(_e725, _e726, (_e726 < _e725));
                                            } else {
                                                phi_1233_ = 0u;
                                            }
                                            let _e730 = phi_1233_;
                                            let _e731 = (_e708 * _e87);
                                            if (_e731 > 0f) {
                                                let _e737 = select(select(u32(_e731), 0u, (_e731 < 0f)), 4294967295u, (_e731 > 4294967000f));
                                                let _e738 = (_e92 - 1u);
                                                phi_1254_ = select(_e737, _e738, (_e738 < _e737));
                                            } else {
                                                phi_1254_ = 0u;
                                            }
                                            let _e742 = phi_1254_;
                                            let _e744 = ((_e742 * _e82) + _e730);
                                            if (_e744 < _e62) {
                                            } else {
                                                phi_2021_ = true;
                                                phi_1695_ = bool();
                                                phi_1694_ = bool();
                                                phi_1693_ = bool();
                                                phi_1692_ = bool();
                                                phi_1690_ = f32();
                                                break;
                                            }
                                            let _e748 = depth.member[_e744];
                                            let _e752 = select(_e106, _e748, select(false, (_e748 < _e106), (_e748 > 0f)));
                                            let _e755 = (((_e699 * 2f) - 1f) * _e696);
                                            let _e759 = (((_e708 * -2f) + 1f) * _e705);
                                            let _e761 = (_e686 - (_e755 * _e752));
                                            let _e762 = (_e688 - (_e759 * _e752));
                                            let _e763 = (_e690 - _e752);
                                            let _e769 = sqrt((((_e761 * _e761) + (_e762 * _e762)) + (_e763 * _e763)));
                                            let _e774 = (select(0f, select(1f, _e699, (_e699 < 1f)), (_e699 > 0f)) * _e77);
                                            if (_e774 > 0f) {
                                                let _e780 = select(select(u32(_e774), 0u, (_e774 < 0f)), 4294967295u, (_e774 > 4294967000f));
                                                let _e781 = (_e82 - 1u);
                                                phi_1348_ = select(_e780, _e781, (_e781 < _e780));
                                            } else {
                                                phi_1348_ = 0u;
                                            }
                                            let _e785 = phi_1348_;
                                            let _e790 = (select(0f, select(1f, _e708, (_e708 < 1f)), (_e708 > 0f)) * _e87);
                                            if (_e790 > 0f) {
                                                let _e796 = select(select(u32(_e790), 0u, (_e790 < 0f)), 4294967295u, (_e790 > 4294967000f));
                                                let _e797 = (_e92 - 1u);
                                                phi_1379_ = select(_e796, _e797, (_e797 < _e796));
                                            } else {
                                                phi_1379_ = 0u;
                                            }
                                            let _e801 = phi_1379_;
                                            let _e819 = ((_e801 * _e82) + _e785);
                                            if (_e819 < _e64) {
                                            } else {
                                                phi_2021_ = true;
                                                phi_1695_ = bool();
                                                phi_1694_ = bool();
                                                phi_1693_ = bool();
                                                phi_1692_ = bool();
                                                phi_1690_ = f32();
                                                break;
                                            }
                                            let _e823 = normals.member[_e819];
                                            let _e831 = (f32((bitcast<i32>(((_e823 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e831 != _e831) {
                                                phi_1992_ = true;
                                            } else {
                                                phi_1992_ = (-1f >= _e831);
                                            }
                                            let _e835 = phi_1992_;
                                            let _e836 = select(_e831, -1f, _e835);
                                            let _e846 = (f32((bitcast<i32>((((_e823 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e846 != _e846) {
                                                phi_2007_ = true;
                                            } else {
                                                phi_2007_ = (-1f >= _e846);
                                            }
                                            let _e850 = phi_2007_;
                                            let _e851 = select(_e846, -1f, _e850);
                                            let _e854 = (1f - abs(_e836));
                                            let _e855 = abs(_e851);
                                            let _e856 = (_e854 - _e855);
                                            if (_e856 < 0f) {
                                                phi_1968_ = vec2<f32>(((1f - _e855) * select(1f, -1f, (_e836 < 0f))), (_e854 * select(1f, -1f, (_e851 < 0f))));
                                            } else {
                                                phi_1968_ = vec2<f32>(_e836, _e851);
                                            }
                                            let _e867 = phi_1968_;
                                            let _e876 = (1f / sqrt((((_e867.x * _e867.x) + (_e867.y * _e867.y)) + (_e856 * _e856))));
                                            let _e877 = (_e867.x * _e876);
                                            let _e878 = (_e867.y * _e876);
                                            let _e880 = -((_e856 * _e876));
                                            let _e884 = (((_e877 * _e755) + (_e878 * _e759)) + _e880);
                                            let _e893 = select(((((_e877 * ((((((f32(_e785) + 0.5f) * (1f / _e77)) * 2f) - 1f) * _e696) * _e752)) + (_e878 * ((((((f32(_e801) + 0.5f) * (1f / _e87)) * -2f) + 1f) * _e705) * _e752))) + (_e880 * _e752)) / _e884), _e752, (abs(_e884) < 0.001f));
                                            let _e903 = select(select(((_e690 - _e893) > _e658), true, (_e690 < (_e893 * (1f + _e655)))), true, select(false, (_e801 == _e552.member_1.member_1.member.y), (_e785 == _e552.member_1.member_1.member.x)));
                                            let _e905 = select(false, !(_e903), _e718);
                                            let _e906 = (_e672 + _e769);
                                            let _e915 = select(false, _e903, _e718);
                                            if _e915 {
                                                phi_1519_ = (_e664 + 1u);
                                            } else {
                                                phi_1519_ = u32();
                                            }
                                            let _e918 = phi_1519_;
                                            phi_1521_ = _e918;
                                            phi_1522_ = select(_e666, select((_e674 + ((_e672 * (_e681 - _e674)) / _e906)), _e674, (_e906 < 0.000001f)), _e905);
                                            phi_1523_ = select(_e905, true, _e668);
                                            phi_1524_ = _e915;
                                            phi_1525_ = _e769;
                                            phi_1528_ = _e915;
                                            phi_1529_ = select(true, false, _e915);
                                        } else {
                                            phi_1521_ = u32();
                                            phi_1522_ = f32();
                                            phi_1523_ = bool();
                                            phi_1524_ = bool();
                                            phi_1525_ = f32();
                                            phi_1528_ = false;
                                            phi_1529_ = false;
                                        }
                                        let _e921 = phi_1521_;
                                        let _e923 = phi_1522_;
                                        let _e925 = phi_1523_;
                                        let _e927 = phi_1524_;
                                        let _e929 = phi_1525_;
                                        let _e931 = phi_1528_;
                                        let _e933 = phi_1529_;
                                        phi_1119_ = _e921;
                                        phi_1122_ = _e923;
                                        phi_1124_ = _e925;
                                        phi_1126_ = _e927;
                                        phi_1128_ = _e929;
                                        phi_1130_ = _e681;
                                        phi_1533_ = _e931;
                                        phi_1535_ = _e933;
                                        phi_1536_ = select(true, false, _e718);
                                    } else {
                                        phi_1119_ = u32();
                                        phi_1122_ = f32();
                                        phi_1124_ = bool();
                                        phi_1126_ = bool();
                                        phi_1128_ = f32();
                                        phi_1130_ = f32();
                                        phi_1533_ = false;
                                        phi_1535_ = false;
                                        phi_1536_ = false;
                                    }
                                    let _e936 = phi_1119_;
                                    let _e938 = phi_1122_;
                                    let _e940 = phi_1124_;
                                    let _e942 = phi_1126_;
                                    let _e944 = phi_1128_;
                                    let _e946 = phi_1130_;
                                    let _e948 = phi_1533_;
                                    let _e950 = phi_1535_;
                                    let _e952 = phi_1536_;
                                    continue;
                                    continuing {
                                        phi_1118_ = _e936;
                                        phi_1121_ = _e938;
                                        phi_1123_ = _e940;
                                        phi_1125_ = _e942;
                                        phi_1127_ = _e944;
                                        phi_1129_ = _e946;
                                        phi_2021_ = _e574;
                                        phi_1695_ = _e952;
                                        phi_1694_ = _e950;
                                        phi_1693_ = select(true, false, _e675);
                                        phi_1692_ = _e940;
                                        phi_1690_ = _e938;
                                        break if !(_e948);
                                    }
                                }
                                let _e956 = phi_2021_;
                                let _e958 = phi_1695_;
                                let _e960 = phi_1694_;
                                let _e962 = phi_1693_;
                                let _e964 = phi_1692_;
                                let _e966 = phi_1690_;
                                phi_2146_ = _e956;
                                if _e956 {
                                    break;
                                }
                                let _e967 = select(_e960, false, _e962);
                                let _e969 = select(select(_e958, false, _e962), false, _e967);
                                let _e971 = local_1;
                                let _e974 = local_2;
                                let _e976 = select(_e967, true, _e969);
                                let _e978 = local_3;
                                let _e981 = local_4;
                                let _e985 = params.member.member_7;
                                if (_e985 == 1u) {
                                    phi_1576_ = 0f;
                                } else {
                                    let _e987 = (select(_e978, select(_e966, _e971, _e969), _e976) / _e651);
                                    phi_1576_ = select(0f, select(1f, _e987, (_e987 < 1f)), (_e987 > 0f));
                                }
                                let _e993 = phi_1576_;
                                phi_2147_ = _e956;
                                phi_970_ = (_e576 + 1u);
                                phi_973_ = (_e578 + select(1f, _e993, select(_e981, select(_e964, _e974, _e969), _e976)));
                            } else {
                                phi_2147_ = _e574;
                                phi_970_ = u32();
                                phi_973_ = f32();
                            }
                            let _e998 = phi_2147_;
                            let _e1000 = phi_970_;
                            let _e1002 = phi_973_;
                            continue;
                            continuing {
                                phi_2069_ = _e998;
                                phi_969_ = _e1000;
                                phi_972_ = _e1002;
                                phi_2146_ = _e998;
                                break if !(_e579);
                            }
                        }
                        let _e1005 = phi_2146_;
                        if _e1005 {
                            break;
                        }
                        let _e1008 = local_5;
                        let _e1012 = params.member.member_2;
                        let _e1013 = pow((_e1008 / f32(_e567)), _e1012);
                        let _e1014 = (_e1013 * 0.6666667f);
                        let _e1020 = ((select(0f, select(1f, _e1014, (_e1014 < 1f)), (_e1014 > 0f)) * 255f) + 0.5f);
                        phi_1647_ = type_29(_e1013, select(select(u32(_e1020), 0u, (_e1020 < 0f)), 4294967295u, (_e1020 > 4294967000f)), _e552.member);
                    } else {
                        phi_1647_ = type_29(1f, 170u, _e552.member);
                    }
                    let _e1029 = phi_1647_;
                    if (_e98 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e98] = _e1029.member;
                    if (_e98 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e98] = _e1029.member_1;
                    if (_e98 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e98] = _e1029.member_2;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn raymarch_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
