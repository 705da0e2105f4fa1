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
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
}

struct type_22 {
    member: type_21,
}

struct type_25 {
    member: array<vec2<f32>>,
}

struct type_27 {
    member: vec2<u32>,
    member_1: vec3<f32>,
    member_2: vec3<f32>,
    member_3: f32,
    member_4: f32,
    member_5: f32,
}

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_29 {
    member: u32,
    member_1: type_28,
}

struct type_30 {
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
var<uniform> params: type_22;
@group(0) @binding(2) 
var<storage> kernel: type_25;
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_281_: bool;
    var phi_305_: i32;
    var phi_324_: i32;
    var phi_353_: bool;
    var phi_377_: i32;
    var phi_396_: i32;
    var phi_425_: bool;
    var phi_449_: i32;
    var phi_468_: i32;
    var phi_497_: bool;
    var phi_521_: i32;
    var phi_540_: i32;
    var phi_569_: bool;
    var phi_1809_: f32;
    var phi_1813_: f32;
    var phi_1814_: bool;
    var phi_1852_: f32;
    var phi_1856_: f32;
    var phi_1857_: bool;
    var phi_1895_: f32;
    var phi_1899_: f32;
    var phi_1900_: bool;
    var phi_1938_: f32;
    var phi_1942_: f32;
    var phi_1943_: bool;
    var phi_705_: bool;
    var phi_1965_: bool;
    var phi_1980_: bool;
    var phi_799_: vec2<f32>;
    var phi_830_: vec3<f32>;
    var phi_836_: u32;
    var phi_839_: u32;
    var phi_841_: u32;
    var phi_843_: u32;
    var phi_872_: u32;
    var phi_873_: u32;
    var phi_874_: u32;
    var phi_875_: u32;
    var phi_837_: u32;
    var phi_840_: u32;
    var phi_842_: u32;
    var phi_844_: u32;
    var local: u32;
    var phi_906_: type_29;
    var phi_2360_: bool;
    var phi_941_: u32;
    var phi_944_: f32;
    var phi_1995_: bool;
    var phi_1090_: u32;
    var phi_1093_: f32;
    var phi_1095_: bool;
    var phi_1097_: bool;
    var phi_1099_: f32;
    var phi_1101_: f32;
    var phi_2047_: u32;
    var phi_2074_: u32;
    var phi_2246_: bool;
    var phi_2261_: bool;
    var phi_2222_: vec2<f32>;
    var phi_1333_: bool;
    var phi_1378_: u32;
    var phi_1380_: u32;
    var phi_1381_: f32;
    var phi_1382_: bool;
    var phi_1383_: bool;
    var phi_1384_: f32;
    var phi_1387_: bool;
    var phi_1388_: bool;
    var phi_1091_: u32;
    var phi_1094_: f32;
    var phi_1096_: bool;
    var phi_1098_: bool;
    var phi_1100_: f32;
    var phi_1102_: f32;
    var phi_1392_: bool;
    var phi_1394_: bool;
    var phi_1395_: bool;
    var phi_2314_: bool;
    var phi_1782_: bool;
    var phi_1781_: bool;
    var phi_1780_: bool;
    var phi_1779_: bool;
    var phi_1777_: f32;
    var local_1: f32;
    var local_2: bool;
    var local_3: f32;
    var local_4: bool;
    var phi_1435_: f32;
    var phi_2438_: bool;
    var phi_942_: u32;
    var phi_945_: f32;
    var phi_2437_: bool;
    var local_5: f32;
    var phi_1506_: type_30;

    switch bitcast<i32>(0u) {
        default: {
            let _e60 = id_1;
            let _e62 = arrayLength((&depth.member));
            let _e64 = arrayLength((&normals.member));
            let _e66 = arrayLength((&kernel.member));
            let _e79 = params.member.member.member[0u];
            let _e84 = select(select(u32(_e79), 0u, (_e79 < 0f)), 4294967295u, (_e79 > 4294967000f));
            let _e89 = params.member.member.member[1u];
            let _e94 = select(select(u32(_e89), 0u, (_e89 < 0f)), 4294967295u, (_e89 > 4294967000f));
            if (_e60.x >= _e84) {
            } else {
                if (_e60.y >= _e94) {
                } else {
                    let _e100 = ((_e60.y * _e84) + _e60.x);
                    let _e101 = (_e100 < _e62);
                    if _e101 {
                    } else {
                        break;
                    }
                    let _e104 = depth.member[_e100];
                    let _e108 = params.member.member.member_3;
                    let _e109 = (_e104 > 0f);
                    if _e109 {
                        phi_281_ = (_e104 < _e108);
                    } else {
                        phi_281_ = false;
                    }
                    let _e112 = phi_281_;
                    let _e113 = select(_e108, _e104, _e112);
                    let _e114 = bitcast<i32>(_e60.x);
                    let _e115 = (_e114 + -1i);
                    let _e117 = (bitcast<i32>(_e84) - 1i);
                    let _e118 = (0i <= _e117);
                    if _e118 {
                    } else {
                        break;
                    }
                    if (_e115 < 0i) {
                        phi_305_ = 0i;
                    } else {
                        phi_305_ = select(_e115, _e117, (_e115 > _e117));
                    }
                    let _e123 = phi_305_;
                    let _e125 = bitcast<i32>(_e60.y);
                    let _e127 = (bitcast<i32>(_e94) - 1i);
                    let _e128 = (0i <= _e127);
                    if _e128 {
                    } else {
                        break;
                    }
                    let _e129 = (_e125 < 0i);
                    if _e129 {
                        phi_324_ = 0i;
                    } else {
                        phi_324_ = select(_e125, _e127, (_e125 > _e127));
                    }
                    let _e133 = phi_324_;
                    let _e136 = ((bitcast<u32>(_e133) * _e84) + bitcast<u32>(_e123));
                    if (_e136 < _e62) {
                    } else {
                        break;
                    }
                    let _e140 = depth.member[_e136];
                    if (_e140 > 0f) {
                        phi_353_ = (_e140 < _e108);
                    } else {
                        phi_353_ = false;
                    }
                    let _e144 = phi_353_;
                    let _e146 = (_e114 + 1i);
                    if _e118 {
                    } else {
                        break;
                    }
                    if (_e146 < 0i) {
                        phi_377_ = 0i;
                    } else {
                        phi_377_ = select(_e146, _e117, (_e146 > _e117));
                    }
                    let _e151 = phi_377_;
                    if _e128 {
                    } else {
                        break;
                    }
                    if _e129 {
                        phi_396_ = 0i;
                    } else {
                        phi_396_ = select(_e125, _e127, (_e125 > _e127));
                    }
                    let _e156 = phi_396_;
                    let _e159 = ((bitcast<u32>(_e156) * _e84) + bitcast<u32>(_e151));
                    if (_e159 < _e62) {
                    } else {
                        break;
                    }
                    let _e163 = depth.member[_e159];
                    if (_e163 > 0f) {
                        phi_425_ = (_e163 < _e108);
                    } else {
                        phi_425_ = false;
                    }
                    let _e167 = phi_425_;
                    if _e118 {
                    } else {
                        break;
                    }
                    let _e169 = (_e114 < 0i);
                    if _e169 {
                        phi_449_ = 0i;
                    } else {
                        phi_449_ = select(_e114, _e117, (_e114 > _e117));
                    }
                    let _e173 = phi_449_;
                    let _e175 = (_e125 + -1i);
                    if _e128 {
                    } else {
                        break;
                    }
                    if (_e175 < 0i) {
                        phi_468_ = 0i;
                    } else {
                        phi_468_ = select(_e175, _e127, (_e175 > _e127));
                    }
                    let _e180 = phi_468_;
                    let _e183 = ((bitcast<u32>(_e180) * _e84) + bitcast<u32>(_e173));
                    if (_e183 < _e62) {
                    } else {
                        break;
                    }
                    let _e187 = depth.member[_e183];
                    if (_e187 > 0f) {
                        phi_497_ = (_e187 < _e108);
                    } else {
                        phi_497_ = false;
                    }
                    let _e191 = phi_497_;
                    if _e118 {
                    } else {
                        break;
                    }
                    if _e169 {
                        phi_521_ = 0i;
                    } else {
                        phi_521_ = select(_e114, _e117, (_e114 > _e117));
                    }
                    let _e196 = phi_521_;
                    let _e198 = (_e125 + 1i);
                    if _e128 {
                    } else {
                        break;
                    }
                    if (_e198 < 0i) {
                        phi_540_ = 0i;
                    } else {
                        phi_540_ = select(_e198, _e127, (_e198 > _e127));
                    }
                    let _e203 = phi_540_;
                    let _e206 = ((bitcast<u32>(_e203) * _e84) + bitcast<u32>(_e196));
                    if (_e206 < _e62) {
                    } else {
                        break;
                    }
                    let _e210 = depth.member[_e206];
                    if (_e210 > 0f) {
                        phi_569_ = (_e210 < _e108);
                    } else {
                        phi_569_ = false;
                    }
                    let _e214 = phi_569_;
                    let _e216 = (select(_e108, _e140, _e144) - _e113);
                    let _e217 = (select(_e108, _e163, _e167) - _e113);
                    let _e218 = (select(_e108, _e187, _e191) - _e113);
                    let _e219 = (select(_e108, _e210, _e214) - _e113);
                    let _e220 = (_e217 - _e216);
                    let _e222 = (_e219 - _e218);
                    let _e230 = abs(_e216);
                    let _e231 = abs(_e217);
                    let _e232 = abs(_e218);
                    let _e233 = abs(_e219);
                    let _e234 = abs((_e216 + (_e220 * 0.5f)));
                    let _e235 = abs((_e217 + (_e220 * -0.5f)));
                    let _e236 = abs((_e218 + (_e222 * 0.5f)));
                    let _e237 = abs((_e219 + (_e222 * -0.5f)));
                    let _e246 = (_e113 * 0.011f);
                    let _e251 = (1.25f - (select(_e234, _e230, (_e230 < _e234)) / _e246));
                    let _e255 = select(0f, select(1f, _e251, (_e251 < 1f)), (_e251 > 0f));
                    let _e256 = (1.25f - (select(_e235, _e231, (_e231 < _e235)) / _e246));
                    let _e260 = select(0f, select(1f, _e256, (_e256 < 1f)), (_e256 > 0f));
                    let _e261 = (1.25f - (select(_e236, _e232, (_e232 < _e236)) / _e246));
                    let _e265 = select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f));
                    let _e266 = (1.25f - (select(_e237, _e233, (_e233 < _e237)) / _e246));
                    let _e270 = select(0f, select(1f, _e266, (_e266 < 1f)), (_e266 > 0f));
                    let _e275 = (select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f)) * 2.9f);
                    let _e277 = floor((_e275 + 0.5f));
                    if ((_e277 - _e275) == 0.5f) {
                        let _e283 = ((floor((_e277 * 0.5f)) * 2f) != _e277);
                        if _e283 {
                            phi_1809_ = (_e277 - 1f);
                        } else {
                            phi_1809_ = f32();
                        }
                        let _e286 = phi_1809_;
                        phi_1813_ = _e286;
                        phi_1814_ = select(true, false, _e283);
                    } else {
                        phi_1813_ = f32();
                        phi_1814_ = true;
                    }
                    let _e289 = phi_1813_;
                    let _e291 = phi_1814_;
                    let _e292 = select(_e289, _e277, _e291);
                    let _e303 = (select(0f, select(1f, _e260, (_e260 < 1f)), (_e260 > 0f)) * 2.9f);
                    let _e305 = floor((_e303 + 0.5f));
                    if ((_e305 - _e303) == 0.5f) {
                        let _e311 = ((floor((_e305 * 0.5f)) * 2f) != _e305);
                        if _e311 {
                            phi_1852_ = (_e305 - 1f);
                        } else {
                            phi_1852_ = f32();
                        }
                        let _e314 = phi_1852_;
                        phi_1856_ = _e314;
                        phi_1857_ = select(true, false, _e311);
                    } else {
                        phi_1856_ = f32();
                        phi_1857_ = true;
                    }
                    let _e317 = phi_1856_;
                    let _e319 = phi_1857_;
                    let _e320 = select(_e317, _e305, _e319);
                    let _e332 = (select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f)) * 2.9f);
                    let _e334 = floor((_e332 + 0.5f));
                    if ((_e334 - _e332) == 0.5f) {
                        let _e340 = ((floor((_e334 * 0.5f)) * 2f) != _e334);
                        if _e340 {
                            phi_1895_ = (_e334 - 1f);
                        } else {
                            phi_1895_ = f32();
                        }
                        let _e343 = phi_1895_;
                        phi_1899_ = _e343;
                        phi_1900_ = select(true, false, _e340);
                    } else {
                        phi_1899_ = f32();
                        phi_1900_ = true;
                    }
                    let _e346 = phi_1899_;
                    let _e348 = phi_1900_;
                    let _e349 = select(_e346, _e334, _e348);
                    let _e361 = (select(0f, select(1f, _e270, (_e270 < 1f)), (_e270 > 0f)) * 2.9f);
                    let _e363 = floor((_e361 + 0.5f));
                    if ((_e363 - _e361) == 0.5f) {
                        let _e369 = ((floor((_e363 * 0.5f)) * 2f) != _e363);
                        if _e369 {
                            phi_1938_ = (_e363 - 1f);
                        } else {
                            phi_1938_ = f32();
                        }
                        let _e372 = phi_1938_;
                        phi_1942_ = _e372;
                        phi_1943_ = select(true, false, _e369);
                    } else {
                        phi_1942_ = f32();
                        phi_1943_ = true;
                    }
                    let _e375 = phi_1942_;
                    let _e377 = phi_1943_;
                    let _e378 = select(_e375, _e363, _e377);
                    let _e384 = ((((64u * select(select(u32(_e292), 0u, (_e292 < 0f)), 4294967295u, (_e292 > 4294967000f))) + (16u * select(select(u32(_e320), 0u, (_e320 < 0f)), 4294967295u, (_e320 > 4294967000f)))) + (4u * select(select(u32(_e349), 0u, (_e349 < 0f)), 4294967295u, (_e349 > 4294967000f)))) + select(select(u32(_e378), 0u, (_e378 < 0f)), 4294967295u, (_e378 > 4294967000f)));
                    if _e101 {
                    } else {
                        break;
                    }
                    if _e109 {
                        phi_705_ = (_e104 < _e108);
                    } else {
                        phi_705_ = false;
                    }
                    let _e387 = phi_705_;
                    if _e387 {
                        let _e400 = params.member.member.member_1[0u];
                        let _e402 = ((((((f32(_e60.x) + 0.5f) / _e79) * 2f) - 1f) * _e400) * _e104);
                        let _e409 = params.member.member.member_1[1u];
                        let _e411 = ((((((f32(_e60.y) + 0.5f) / _e89) * -2f) + 1f) * _e409) * _e104);
                        if (_e100 < _e64) {
                        } else {
                            break;
                        }
                        let _e416 = normals.member[_e100];
                        let _e424 = (f32((bitcast<i32>(((_e416 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e424 != _e424) {
                            phi_1965_ = true;
                        } else {
                            phi_1965_ = (-1f >= _e424);
                        }
                        let _e428 = phi_1965_;
                        let _e429 = select(_e424, -1f, _e428);
                        let _e439 = (f32((bitcast<i32>((((_e416 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e439 != _e439) {
                            phi_1980_ = true;
                        } else {
                            phi_1980_ = (-1f >= _e439);
                        }
                        let _e443 = phi_1980_;
                        let _e444 = select(_e439, -1f, _e443);
                        let _e447 = (1f - abs(_e429));
                        let _e448 = abs(_e444);
                        let _e449 = (_e447 - _e448);
                        if (_e449 < 0f) {
                            phi_799_ = vec2<f32>(((1f - _e448) * select(1f, -1f, (_e429 < 0f))), (_e447 * select(1f, -1f, (_e444 < 0f))));
                        } else {
                            phi_799_ = vec2<f32>(_e429, _e444);
                        }
                        let _e460 = phi_799_;
                        let _e469 = (1f / sqrt((((_e460.x * _e460.x) + (_e460.y * _e460.y)) + (_e449 * _e449))));
                        let _e470 = (_e460.x * _e469);
                        let _e471 = (_e460.y * _e469);
                        let _e472 = (_e449 * _e469);
                        let _e473 = -(_e472);
                        if ((((_e470 * -(_e402)) + (_e471 * -(_e411))) + (_e473 * -(_e104))) < 0f) {
                            phi_830_ = vec3<f32>(-(_e470), -(_e471), _e472);
                        } else {
                            phi_830_ = vec3<f32>(_e470, _e471, _e473);
                        }
                        let _e488 = phi_830_;
                        let _e491 = params.member.member_8;
                        phi_836_ = (_e60.y & 63u);
                        phi_839_ = (_e60.x & 63u);
                        phi_841_ = 32u;
                        phi_843_ = 0u;
                        loop {
                            let _e495 = phi_836_;
                            let _e497 = phi_839_;
                            let _e499 = phi_841_;
                            let _e501 = phi_843_;
                            local = _e501;
                            let _e502 = (_e499 > 0u);
                            if _e502 {
                                let _e505 = select(0u, 1u, ((_e497 & _e499) != 0u));
                                let _e508 = select(0u, 1u, ((_e495 & _e499) != 0u));
                                if (_e508 == 0u) {
                                    if (_e505 == 1u) {
                                        phi_872_ = (63u - _e495);
                                        phi_873_ = (63u - _e497);
                                    } else {
                                        phi_872_ = _e495;
                                        phi_873_ = _e497;
                                    }
                                    let _e519 = phi_872_;
                                    let _e521 = phi_873_;
                                    phi_874_ = _e521;
                                    phi_875_ = _e519;
                                } else {
                                    phi_874_ = _e495;
                                    phi_875_ = _e497;
                                }
                                let _e523 = phi_874_;
                                let _e525 = phi_875_;
                                phi_837_ = _e523;
                                phi_840_ = _e525;
                                phi_842_ = (_e499 / 2u);
                                phi_844_ = (_e501 + ((_e499 * _e499) * ((3u * _e505) ^ _e508)));
                            } else {
                                phi_837_ = u32();
                                phi_840_ = u32();
                                phi_842_ = u32();
                                phi_844_ = u32();
                            }
                            let _e528 = phi_837_;
                            let _e530 = phi_840_;
                            let _e532 = phi_842_;
                            let _e534 = phi_844_;
                            continue;
                            continuing {
                                phi_836_ = _e528;
                                phi_839_ = _e530;
                                phi_841_ = _e532;
                                phi_843_ = _e534;
                                break if !(_e502);
                            }
                        }
                        let _e539 = local;
                        let _e541 = f32((_e539 + (288u * (_e491 % 64u))));
                        let _e543 = (0.5f + (_e541 * 0.7548777f));
                        let _e547 = (0.5f + (_e541 * 0.5698403f));
                        let _e550 = (6.2831855f * (_e543 - floor(_e543)));
                        phi_906_ = type_29(_e384, type_28(1u, type_27(vec2<u32>(_e60.x, _e60.y), vec3<f32>(_e402, _e411, _e104), _e488, sin(_e550), cos(_e550), (_e547 - floor(_e547)))));
                    } else {
                        phi_906_ = type_29(_e384, type_28(0u, type_28().member_1));
                    }
                    let _e562 = phi_906_;
                    if (bitcast<i32>(_e562.member_1.member) != 0i) {
                        let _e571 = params.member.member_5;
                        let _e573 = select(_e571, 64u, (64u < _e571));
                        let _e575 = select(_e573, _e66, (_e66 < _e573));
                        let _e577 = select(1u, _e575, (1u < _e575));
                        let _e580 = params.member.member_6;
                        let _e582 = select(1u, _e580, (1u < _e580));
                        phi_2360_ = false;
                        phi_941_ = 0u;
                        phi_944_ = 0f;
                        loop {
                            let _e584 = phi_2360_;
                            let _e586 = phi_941_;
                            let _e588 = phi_944_;
                            local_5 = _e588;
                            let _e589 = (_e586 < _e577);
                            if _e589 {
                                if (_e586 < _e66) {
                                } else {
                                    phi_2437_ = true;
                                    break;
                                }
                                let _e594 = kernel.member[_e586][0u];
                                let _e598 = kernel.member[_e586][1u];
                                let _e603 = ((_e562.member_1.member_1.member_4 * _e594) - (_e562.member_1.member_1.member_3 * _e598));
                                let _e606 = ((_e562.member_1.member_1.member_3 * _e594) + (_e562.member_1.member_1.member_4 * _e598));
                                let _e611 = ((1f - (_e603 * _e603)) - (_e606 * _e606));
                                if (_e611 != _e611) {
                                    phi_1995_ = true;
                                } else {
                                    phi_1995_ = (0f >= _e611);
                                }
                                let _e615 = phi_1995_;
                                let _e617 = sqrt(select(_e611, 0f, _e615));
                                let _e618 = -(_e617);
                                let _e622 = (-1f * _e562.member_1.member_1.member_2.z);
                                let _e623 = (-1f * _e562.member_1.member_1.member_2.x);
                                let _e625 = (1f / (_e622 + 1f));
                                let _e626 = (_e625 * _e562.member_1.member_1.member_2.y);
                                let _e630 = (_e626 * _e623);
                                let _e650 = (_e622 > 0.9997f);
                                let _e651 = (_e622 < -0.9997f);
                                let _e661 = params.member.member_1;
                                let _e665 = params.member.member_3;
                                let _e668 = params.member.member_4;
                                phi_1090_ = 1u;
                                phi_1093_ = _e661;
                                phi_1095_ = false;
                                phi_1097_ = true;
                                phi_1099_ = 0f;
                                phi_1101_ = 0f;
                                loop {
                                    let _e674 = phi_1090_;
                                    let _e676 = phi_1093_;
                                    let _e678 = phi_1095_;
                                    let _e680 = phi_1097_;
                                    let _e682 = phi_1099_;
                                    let _e684 = phi_1101_;
                                    local_1 = _e676;
                                    local_2 = _e678;
                                    local_3 = _e676;
                                    local_4 = _e678;
                                    let _e685 = (_e674 <= _e582);
                                    if _e685 {
                                        let _e691 = (((-(_e562.member_1.member_1.member_5) + f32(_e674)) * _e661) / f32(_e582));
                                        let _e696 = (_e562.member_1.member_1.member_1.x + (select(select(((((_e622 + (_e626 * _e562.member_1.member_1.member_2.y)) * _e603) + (_e630 * _e606)) + (_e623 * _e618)), _e603, _e651), _e603, _e650) * _e691));
                                        let _e698 = (_e562.member_1.member_1.member_1.y + (select(select((((_e630 * _e603) + ((_e622 + ((_e625 * _e623) * _e623)) * _e606)) + (-(_e562.member_1.member_1.member_2.y) * _e618)), -(_e606), _e651), _e606, _e650) * _e691));
                                        let _e700 = (_e562.member_1.member_1.member_1.z + (select(select((((_e562.member_1.member_1.member_2.x * _e603) + (_e562.member_1.member_1.member_2.y * _e606)) + (_e622 * _e618)), _e617, _e651), _e618, _e650) * _e691));
                                        let _e706 = params.member.member.member_1[0u];
                                        let _e709 = (((_e696 * 0.5f) / (_e700 * _e706)) + 0.5f);
                                        let _e715 = params.member.member.member_1[1u];
                                        let _e718 = (0.5f - ((_e698 * 0.5f) / (_e700 * _e715)));
                                        let _e728 = select(false, select(false, select(false, select(false, (_e718 <= 1f), (_e718 >= 0f)), select(false, (_e709 <= 1f), (_e709 >= 0f))), (_e700 > 0f)), _e680);
                                        if _e728 {
                                            let _e729 = params.member.member;
                                            let _e736 = select(select(u32(_e729.member.x), 0u, (_e729.member.x < 0f)), 4294967295u, (_e729.member.x > 4294967000f));
                                            let _e742 = select(select(u32(_e729.member.y), 0u, (_e729.member.y < 0f)), 4294967295u, (_e729.member.y > 4294967000f));
                                            let _e744 = floor((_e709 * _e729.member.x));
                                            if (_e744 > 0f) {
                                                let _e750 = select(select(u32(_e744), 0u, (_e744 < 0f)), 4294967295u, (_e744 > 4294967000f));
                                                let _e751 = (_e736 - 1u);
                                                phi_2047_ = select(_e750, _e751, (_e751 < _e750));
                                            } else {
                                                phi_2047_ = 0u;
                                            }
                                            let _e755 = phi_2047_;
                                            let _e757 = floor((_e718 * _e729.member.y));
                                            if (_e757 > 0f) {
                                                let _e763 = select(select(u32(_e757), 0u, (_e757 < 0f)), 4294967295u, (_e757 > 4294967000f));
                                                let _e764 = (_e742 - 1u);
                                                phi_2074_ = select(_e763, _e764, (_e764 < _e763));
                                            } else {
                                                phi_2074_ = 0u;
                                            }
                                            let _e768 = phi_2074_;
                                            let _e770 = ((_e768 * _e736) + _e755);
                                            if (_e770 < _e62) {
                                            } else {
                                                phi_2314_ = true;
                                                phi_1782_ = bool();
                                                phi_1781_ = bool();
                                                phi_1780_ = bool();
                                                phi_1779_ = bool();
                                                phi_1777_ = f32();
                                                break;
                                            }
                                            let _e774 = depth.member[_e770];
                                            let _e778 = select(_e108, _e774, select(false, (_e774 < _e108), (_e774 > 0f)));
                                            let _e781 = (((_e709 * 2f) - 1f) * _e706);
                                            let _e785 = (((_e718 * -2f) + 1f) * _e715);
                                            let _e787 = (_e696 - (_e781 * _e778));
                                            let _e788 = (_e698 - (_e785 * _e778));
                                            let _e789 = (_e700 - _e778);
                                            let _e795 = sqrt((((_e787 * _e787) + (_e788 * _e788)) + (_e789 * _e789)));
                                            let _e800 = (select(0f, select(1f, _e709, (_e709 < 1f)), (_e709 > 0f)) * _e729.member.x);
                                            let _e805 = (select(0f, select(1f, _e718, (_e718 < 1f)), (_e718 > 0f)) * _e729.member.y);
                                            let _e810 = select(select(u32(_e800), 0u, (_e800 < 0f)), 4294967295u, (_e800 > 4294967000f));
                                            let _e811 = (_e736 - 1u);
                                            let _e813 = select(_e810, _e811, (_e811 < _e810));
                                            let _e818 = select(select(u32(_e805), 0u, (_e805 < 0f)), 4294967295u, (_e805 > 4294967000f));
                                            let _e819 = (_e742 - 1u);
                                            let _e821 = select(_e818, _e819, (_e819 < _e818));
                                            let _e839 = ((_e821 * _e84) + _e813);
                                            if (_e839 < _e64) {
                                            } else {
                                                phi_2314_ = true;
                                                phi_1782_ = bool();
                                                phi_1781_ = bool();
                                                phi_1780_ = bool();
                                                phi_1779_ = bool();
                                                phi_1777_ = f32();
                                                break;
                                            }
                                            let _e843 = normals.member[_e839];
                                            let _e851 = (f32((bitcast<i32>(((_e843 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e851 != _e851) {
                                                phi_2246_ = true;
                                            } else {
                                                phi_2246_ = (-1f >= _e851);
                                            }
                                            let _e855 = phi_2246_;
                                            let _e856 = select(_e851, -1f, _e855);
                                            let _e866 = (f32((bitcast<i32>((((_e843 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e866 != _e866) {
                                                phi_2261_ = true;
                                            } else {
                                                phi_2261_ = (-1f >= _e866);
                                            }
                                            let _e870 = phi_2261_;
                                            let _e871 = select(_e866, -1f, _e870);
                                            let _e874 = (1f - abs(_e856));
                                            let _e875 = abs(_e871);
                                            let _e876 = (_e874 - _e875);
                                            if (_e876 < 0f) {
                                                phi_2222_ = vec2<f32>(((1f - _e875) * select(1f, -1f, (_e856 < 0f))), (_e874 * select(1f, -1f, (_e871 < 0f))));
                                            } else {
                                                phi_2222_ = vec2<f32>(_e856, _e871);
                                            }
                                            let _e887 = phi_2222_;
                                            let _e896 = (1f / sqrt((((_e887.x * _e887.x) + (_e887.y * _e887.y)) + (_e876 * _e876))));
                                            let _e897 = (_e887.x * _e896);
                                            let _e898 = (_e887.y * _e896);
                                            let _e900 = -((_e876 * _e896));
                                            let _e904 = (((_e897 * _e781) + (_e898 * _e785)) + _e900);
                                            let _e913 = select(((((_e897 * ((((((f32(_e813) + 0.5f) * (1f / _e729.member.x)) * 2f) - 1f) * _e706) * _e778)) + (_e898 * ((((((f32(_e821) + 0.5f) * (1f / _e729.member.y)) * -2f) + 1f) * _e715) * _e778))) + (_e900 * _e778)) / _e904), _e778, (abs(_e904) < 0.001f));
                                            if (_e813 == _e562.member_1.member_1.member.x) {
                                                phi_1333_ = (_e821 == _e562.member_1.member_1.member.y);
                                            } else {
                                                phi_1333_ = false;
                                            }
                                            let _e917 = phi_1333_;
                                            let _e924 = select(select(((_e700 - _e913) > _e668), true, (_e700 < (_e913 * (1f + _e665)))), true, _e917);
                                            let _e926 = select(false, !(_e924), _e728);
                                            let _e927 = (_e682 + _e795);
                                            let _e936 = select(false, _e924, _e728);
                                            if _e936 {
                                                phi_1378_ = (_e674 + 1u);
                                            } else {
                                                phi_1378_ = u32();
                                            }
                                            let _e939 = phi_1378_;
                                            phi_1380_ = _e939;
                                            phi_1381_ = select(_e676, select((_e684 + ((_e682 * (_e691 - _e684)) / _e927)), _e684, (_e927 < 0.000001f)), _e926);
                                            phi_1382_ = select(_e926, true, _e678);
                                            phi_1383_ = _e936;
                                            phi_1384_ = _e795;
                                            phi_1387_ = _e936;
                                            phi_1388_ = select(true, false, _e936);
                                        } else {
                                            phi_1380_ = u32();
                                            phi_1381_ = f32();
                                            phi_1382_ = bool();
                                            phi_1383_ = bool();
                                            phi_1384_ = f32();
                                            phi_1387_ = false;
                                            phi_1388_ = false;
                                        }
                                        let _e942 = phi_1380_;
                                        let _e944 = phi_1381_;
                                        let _e946 = phi_1382_;
                                        let _e948 = phi_1383_;
                                        let _e950 = phi_1384_;
                                        let _e952 = phi_1387_;
                                        let _e954 = phi_1388_;
                                        phi_1091_ = _e942;
                                        phi_1094_ = _e944;
                                        phi_1096_ = _e946;
                                        phi_1098_ = _e948;
                                        phi_1100_ = _e950;
                                        phi_1102_ = _e691;
                                        phi_1392_ = _e952;
                                        phi_1394_ = _e954;
                                        phi_1395_ = select(true, false, _e728);
                                    } else {
                                        phi_1091_ = u32();
                                        phi_1094_ = f32();
                                        phi_1096_ = bool();
                                        phi_1098_ = bool();
                                        phi_1100_ = f32();
                                        phi_1102_ = f32();
                                        phi_1392_ = false;
                                        phi_1394_ = false;
                                        phi_1395_ = false;
                                    }
                                    let _e957 = phi_1091_;
                                    let _e959 = phi_1094_;
                                    let _e961 = phi_1096_;
                                    let _e963 = phi_1098_;
                                    let _e965 = phi_1100_;
                                    let _e967 = phi_1102_;
                                    let _e969 = phi_1392_;
                                    let _e971 = phi_1394_;
                                    let _e973 = phi_1395_;
                                    continue;
                                    continuing {
                                        phi_1090_ = _e957;
                                        phi_1093_ = _e959;
                                        phi_1095_ = _e961;
                                        phi_1097_ = _e963;
                                        phi_1099_ = _e965;
                                        phi_1101_ = _e967;
                                        phi_2314_ = _e584;
                                        phi_1782_ = _e973;
                                        phi_1781_ = _e971;
                                        phi_1780_ = select(true, false, _e685);
                                        phi_1779_ = _e961;
                                        phi_1777_ = _e959;
                                        break if !(_e969);
                                    }
                                }
                                let _e977 = phi_2314_;
                                let _e979 = phi_1782_;
                                let _e981 = phi_1781_;
                                let _e983 = phi_1780_;
                                let _e985 = phi_1779_;
                                let _e987 = phi_1777_;
                                phi_2437_ = _e977;
                                if _e977 {
                                    break;
                                }
                                let _e988 = select(_e981, false, _e983);
                                let _e990 = select(select(_e979, false, _e983), false, _e988);
                                let _e992 = local_1;
                                let _e995 = local_2;
                                let _e997 = select(_e988, true, _e990);
                                let _e999 = local_3;
                                let _e1002 = local_4;
                                let _e1006 = params.member.member_7;
                                if (_e1006 == 1u) {
                                    phi_1435_ = 0f;
                                } else {
                                    let _e1008 = (select(_e999, select(_e987, _e992, _e990), _e997) / _e661);
                                    phi_1435_ = select(0f, select(1f, _e1008, (_e1008 < 1f)), (_e1008 > 0f));
                                }
                                let _e1014 = phi_1435_;
                                phi_2438_ = _e977;
                                phi_942_ = (_e586 + 1u);
                                phi_945_ = (_e588 + select(1f, _e1014, select(_e1002, select(_e985, _e995, _e990), _e997)));
                            } else {
                                phi_2438_ = _e584;
                                phi_942_ = u32();
                                phi_945_ = f32();
                            }
                            let _e1019 = phi_2438_;
                            let _e1021 = phi_942_;
                            let _e1023 = phi_945_;
                            continue;
                            continuing {
                                phi_2360_ = _e1019;
                                phi_941_ = _e1021;
                                phi_944_ = _e1023;
                                phi_2437_ = _e1019;
                                break if !(_e589);
                            }
                        }
                        let _e1026 = phi_2437_;
                        if _e1026 {
                            break;
                        }
                        let _e1029 = local_5;
                        let _e1033 = params.member.member_2;
                        let _e1034 = pow((_e1029 / f32(_e577)), _e1033);
                        let _e1035 = (_e1034 * 0.6666667f);
                        let _e1041 = ((select(0f, select(1f, _e1035, (_e1035 < 1f)), (_e1035 > 0f)) * 255f) + 0.5f);
                        phi_1506_ = type_30(_e1034, select(select(u32(_e1041), 0u, (_e1041 < 0f)), 4294967295u, (_e1041 > 4294967000f)), _e562.member);
                    } else {
                        phi_1506_ = type_30(1f, 170u, _e562.member);
                    }
                    let _e1050 = phi_1506_;
                    if (_e100 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e100] = _e1050.member;
                    if (_e100 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e100] = _e1050.member_1;
                    if (_e100 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e100] = _e1050.member_2;
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
