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
    var phi_303_: i32;
    var phi_322_: i32;
    var phi_373_: i32;
    var phi_392_: i32;
    var phi_443_: i32;
    var phi_462_: i32;
    var phi_513_: i32;
    var phi_532_: i32;
    var phi_1797_: f32;
    var phi_1801_: f32;
    var phi_1802_: bool;
    var phi_1840_: f32;
    var phi_1844_: f32;
    var phi_1845_: bool;
    var phi_1883_: f32;
    var phi_1887_: f32;
    var phi_1888_: bool;
    var phi_1926_: f32;
    var phi_1930_: f32;
    var phi_1931_: bool;
    var phi_1953_: bool;
    var phi_1968_: bool;
    var phi_789_: vec2<f32>;
    var phi_820_: vec3<f32>;
    var phi_826_: u32;
    var phi_829_: u32;
    var phi_831_: u32;
    var phi_833_: u32;
    var phi_862_: u32;
    var phi_863_: u32;
    var phi_864_: u32;
    var phi_865_: u32;
    var phi_827_: u32;
    var phi_830_: u32;
    var phi_832_: u32;
    var phi_834_: u32;
    var local: u32;
    var phi_896_: type_29;
    var phi_2348_: bool;
    var phi_931_: u32;
    var phi_934_: f32;
    var phi_1983_: bool;
    var phi_1080_: u32;
    var phi_1083_: f32;
    var phi_1085_: bool;
    var phi_1087_: bool;
    var phi_1089_: f32;
    var phi_1091_: f32;
    var phi_2035_: u32;
    var phi_2062_: u32;
    var phi_2234_: bool;
    var phi_2249_: bool;
    var phi_2210_: vec2<f32>;
    var phi_1321_: bool;
    var phi_1366_: u32;
    var phi_1368_: u32;
    var phi_1369_: f32;
    var phi_1370_: bool;
    var phi_1371_: bool;
    var phi_1372_: f32;
    var phi_1375_: bool;
    var phi_1376_: bool;
    var phi_1081_: u32;
    var phi_1084_: f32;
    var phi_1086_: bool;
    var phi_1088_: bool;
    var phi_1090_: f32;
    var phi_1092_: f32;
    var phi_1380_: bool;
    var phi_1382_: bool;
    var phi_1383_: bool;
    var phi_2302_: bool;
    var phi_1770_: bool;
    var phi_1769_: bool;
    var phi_1768_: bool;
    var phi_1767_: bool;
    var phi_1765_: f32;
    var local_1: f32;
    var local_2: bool;
    var local_3: f32;
    var local_4: bool;
    var phi_1423_: f32;
    var phi_2426_: bool;
    var phi_932_: u32;
    var phi_935_: f32;
    var phi_2425_: bool;
    var local_5: f32;
    var phi_1494_: type_30;

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
                    let _e111 = select(false, (_e104 < _e108), (_e104 > 0f));
                    let _e112 = select(_e108, _e104, _e111);
                    let _e113 = bitcast<i32>(_e60.x);
                    let _e114 = (_e113 + -1i);
                    let _e116 = (bitcast<i32>(_e84) - 1i);
                    let _e117 = (0i <= _e116);
                    if _e117 {
                    } else {
                        break;
                    }
                    if (_e114 < 0i) {
                        phi_303_ = 0i;
                    } else {
                        phi_303_ = select(_e114, _e116, (_e114 > _e116));
                    }
                    let _e122 = phi_303_;
                    let _e124 = bitcast<i32>(_e60.y);
                    let _e126 = (bitcast<i32>(_e94) - 1i);
                    let _e127 = (0i <= _e126);
                    if _e127 {
                    } else {
                        break;
                    }
                    let _e128 = (_e124 < 0i);
                    if _e128 {
                        phi_322_ = 0i;
                    } else {
                        phi_322_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_322_;
                    let _e135 = ((bitcast<u32>(_e132) * _e84) + bitcast<u32>(_e122));
                    if (_e135 < _e62) {
                    } else {
                        break;
                    }
                    let _e139 = depth.member[_e135];
                    let _e144 = (_e113 + 1i);
                    if _e117 {
                    } else {
                        break;
                    }
                    if (_e144 < 0i) {
                        phi_373_ = 0i;
                    } else {
                        phi_373_ = select(_e144, _e116, (_e144 > _e116));
                    }
                    let _e149 = phi_373_;
                    if _e127 {
                    } else {
                        break;
                    }
                    if _e128 {
                        phi_392_ = 0i;
                    } else {
                        phi_392_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e154 = phi_392_;
                    let _e157 = ((bitcast<u32>(_e154) * _e84) + bitcast<u32>(_e149));
                    if (_e157 < _e62) {
                    } else {
                        break;
                    }
                    let _e161 = depth.member[_e157];
                    if _e117 {
                    } else {
                        break;
                    }
                    let _e166 = (_e113 < 0i);
                    if _e166 {
                        phi_443_ = 0i;
                    } else {
                        phi_443_ = select(_e113, _e116, (_e113 > _e116));
                    }
                    let _e170 = phi_443_;
                    let _e172 = (_e124 + -1i);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e172 < 0i) {
                        phi_462_ = 0i;
                    } else {
                        phi_462_ = select(_e172, _e126, (_e172 > _e126));
                    }
                    let _e177 = phi_462_;
                    let _e180 = ((bitcast<u32>(_e177) * _e84) + bitcast<u32>(_e170));
                    if (_e180 < _e62) {
                    } else {
                        break;
                    }
                    let _e184 = depth.member[_e180];
                    if _e117 {
                    } else {
                        break;
                    }
                    if _e166 {
                        phi_513_ = 0i;
                    } else {
                        phi_513_ = select(_e113, _e116, (_e113 > _e116));
                    }
                    let _e192 = phi_513_;
                    let _e194 = (_e124 + 1i);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e194 < 0i) {
                        phi_532_ = 0i;
                    } else {
                        phi_532_ = select(_e194, _e126, (_e194 > _e126));
                    }
                    let _e199 = phi_532_;
                    let _e202 = ((bitcast<u32>(_e199) * _e84) + bitcast<u32>(_e192));
                    if (_e202 < _e62) {
                    } else {
                        break;
                    }
                    let _e206 = depth.member[_e202];
                    let _e211 = (select(_e108, _e139, select(false, (_e139 < _e108), (_e139 > 0f))) - _e112);
                    let _e212 = (select(_e108, _e161, select(false, (_e161 < _e108), (_e161 > 0f))) - _e112);
                    let _e213 = (select(_e108, _e184, select(false, (_e184 < _e108), (_e184 > 0f))) - _e112);
                    let _e214 = (select(_e108, _e206, select(false, (_e206 < _e108), (_e206 > 0f))) - _e112);
                    let _e215 = (_e212 - _e211);
                    let _e217 = (_e214 - _e213);
                    let _e225 = abs(_e211);
                    let _e226 = abs(_e212);
                    let _e227 = abs(_e213);
                    let _e228 = abs(_e214);
                    let _e229 = abs((_e211 + (_e215 * 0.5f)));
                    let _e230 = abs((_e212 + (_e215 * -0.5f)));
                    let _e231 = abs((_e213 + (_e217 * 0.5f)));
                    let _e232 = abs((_e214 + (_e217 * -0.5f)));
                    let _e241 = (_e112 * 0.011f);
                    let _e246 = (1.25f - (select(_e229, _e225, (_e225 < _e229)) / _e241));
                    let _e250 = select(0f, select(1f, _e246, (_e246 < 1f)), (_e246 > 0f));
                    let _e251 = (1.25f - (select(_e230, _e226, (_e226 < _e230)) / _e241));
                    let _e255 = select(0f, select(1f, _e251, (_e251 < 1f)), (_e251 > 0f));
                    let _e256 = (1.25f - (select(_e231, _e227, (_e227 < _e231)) / _e241));
                    let _e260 = select(0f, select(1f, _e256, (_e256 < 1f)), (_e256 > 0f));
                    let _e261 = (1.25f - (select(_e232, _e228, (_e228 < _e232)) / _e241));
                    let _e265 = select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f));
                    let _e270 = (select(0f, select(1f, _e250, (_e250 < 1f)), (_e250 > 0f)) * 2.9f);
                    let _e272 = floor((_e270 + 0.5f));
                    if ((_e272 - _e270) == 0.5f) {
                        let _e278 = ((floor((_e272 * 0.5f)) * 2f) != _e272);
                        if _e278 {
                            phi_1797_ = (_e272 - 1f);
                        } else {
                            phi_1797_ = f32();
                        }
                        let _e281 = phi_1797_;
                        phi_1801_ = _e281;
                        phi_1802_ = select(true, false, _e278);
                    } else {
                        phi_1801_ = f32();
                        phi_1802_ = true;
                    }
                    let _e284 = phi_1801_;
                    let _e286 = phi_1802_;
                    let _e287 = select(_e284, _e272, _e286);
                    let _e298 = (select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f)) * 2.9f);
                    let _e300 = floor((_e298 + 0.5f));
                    if ((_e300 - _e298) == 0.5f) {
                        let _e306 = ((floor((_e300 * 0.5f)) * 2f) != _e300);
                        if _e306 {
                            phi_1840_ = (_e300 - 1f);
                        } else {
                            phi_1840_ = f32();
                        }
                        let _e309 = phi_1840_;
                        phi_1844_ = _e309;
                        phi_1845_ = select(true, false, _e306);
                    } else {
                        phi_1844_ = f32();
                        phi_1845_ = true;
                    }
                    let _e312 = phi_1844_;
                    let _e314 = phi_1845_;
                    let _e315 = select(_e312, _e300, _e314);
                    let _e327 = (select(0f, select(1f, _e260, (_e260 < 1f)), (_e260 > 0f)) * 2.9f);
                    let _e329 = floor((_e327 + 0.5f));
                    if ((_e329 - _e327) == 0.5f) {
                        let _e335 = ((floor((_e329 * 0.5f)) * 2f) != _e329);
                        if _e335 {
                            phi_1883_ = (_e329 - 1f);
                        } else {
                            phi_1883_ = f32();
                        }
                        let _e338 = phi_1883_;
                        phi_1887_ = _e338;
                        phi_1888_ = select(true, false, _e335);
                    } else {
                        phi_1887_ = f32();
                        phi_1888_ = true;
                    }
                    let _e341 = phi_1887_;
                    let _e343 = phi_1888_;
                    let _e344 = select(_e341, _e329, _e343);
                    let _e356 = (select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f)) * 2.9f);
                    let _e358 = floor((_e356 + 0.5f));
                    if ((_e358 - _e356) == 0.5f) {
                        let _e364 = ((floor((_e358 * 0.5f)) * 2f) != _e358);
                        if _e364 {
                            phi_1926_ = (_e358 - 1f);
                        } else {
                            phi_1926_ = f32();
                        }
                        let _e367 = phi_1926_;
                        phi_1930_ = _e367;
                        phi_1931_ = select(true, false, _e364);
                    } else {
                        phi_1930_ = f32();
                        phi_1931_ = true;
                    }
                    let _e370 = phi_1930_;
                    let _e372 = phi_1931_;
                    let _e373 = select(_e370, _e358, _e372);
                    let _e379 = ((((64u * select(select(u32(_e287), 0u, (_e287 < 0f)), 4294967295u, (_e287 > 4294967000f))) + (16u * select(select(u32(_e315), 0u, (_e315 < 0f)), 4294967295u, (_e315 > 4294967000f)))) + (4u * select(select(u32(_e344), 0u, (_e344 < 0f)), 4294967295u, (_e344 > 4294967000f)))) + select(select(u32(_e373), 0u, (_e373 < 0f)), 4294967295u, (_e373 > 4294967000f)));
                    if _e101 {
                    } else {
                        break;
                    }
                    if _e111 {
                        let _e392 = params.member.member.member_1[0u];
                        let _e394 = ((((((f32(_e60.x) + 0.5f) / _e79) * 2f) - 1f) * _e392) * _e104);
                        let _e401 = params.member.member.member_1[1u];
                        let _e403 = ((((((f32(_e60.y) + 0.5f) / _e89) * -2f) + 1f) * _e401) * _e104);
                        if (_e100 < _e64) {
                        } else {
                            break;
                        }
                        let _e408 = normals.member[_e100];
                        let _e416 = (f32((bitcast<i32>(((_e408 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e416 != _e416) {
                            phi_1953_ = true;
                        } else {
                            phi_1953_ = (-1f >= _e416);
                        }
                        let _e420 = phi_1953_;
                        let _e421 = select(_e416, -1f, _e420);
                        let _e431 = (f32((bitcast<i32>((((_e408 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e431 != _e431) {
                            phi_1968_ = true;
                        } else {
                            phi_1968_ = (-1f >= _e431);
                        }
                        let _e435 = phi_1968_;
                        let _e436 = select(_e431, -1f, _e435);
                        let _e439 = (1f - abs(_e421));
                        let _e440 = abs(_e436);
                        let _e441 = (_e439 - _e440);
                        if (_e441 < 0f) {
                            phi_789_ = vec2<f32>(((1f - _e440) * select(1f, -1f, (_e421 < 0f))), (_e439 * select(1f, -1f, (_e436 < 0f))));
                        } else {
                            phi_789_ = vec2<f32>(_e421, _e436);
                        }
                        let _e452 = phi_789_;
                        let _e461 = (1f / sqrt((((_e452.x * _e452.x) + (_e452.y * _e452.y)) + (_e441 * _e441))));
                        let _e462 = (_e452.x * _e461);
                        let _e463 = (_e452.y * _e461);
                        let _e464 = (_e441 * _e461);
                        let _e465 = -(_e464);
                        if ((((_e462 * -(_e394)) + (_e463 * -(_e403))) + (_e465 * -(_e104))) < 0f) {
                            phi_820_ = vec3<f32>(-(_e462), -(_e463), _e464);
                        } else {
                            phi_820_ = vec3<f32>(_e462, _e463, _e465);
                        }
                        let _e480 = phi_820_;
                        let _e483 = params.member.member_8;
                        phi_826_ = (_e60.y & 63u);
                        phi_829_ = (_e60.x & 63u);
                        phi_831_ = 32u;
                        phi_833_ = 0u;
                        loop {
                            let _e487 = phi_826_;
                            let _e489 = phi_829_;
                            let _e491 = phi_831_;
                            let _e493 = phi_833_;
                            local = _e493;
                            let _e494 = (_e491 > 0u);
                            if _e494 {
                                let _e497 = select(0u, 1u, ((_e489 & _e491) != 0u));
                                let _e500 = select(0u, 1u, ((_e487 & _e491) != 0u));
                                if (_e500 == 0u) {
                                    if (_e497 == 1u) {
                                        phi_862_ = (63u - _e487);
                                        phi_863_ = (63u - _e489);
                                    } else {
                                        phi_862_ = _e487;
                                        phi_863_ = _e489;
                                    }
                                    let _e511 = phi_862_;
                                    let _e513 = phi_863_;
                                    phi_864_ = _e513;
                                    phi_865_ = _e511;
                                } else {
                                    phi_864_ = _e487;
                                    phi_865_ = _e489;
                                }
                                let _e515 = phi_864_;
                                let _e517 = phi_865_;
                                phi_827_ = _e515;
                                phi_830_ = _e517;
                                phi_832_ = (_e491 / 2u);
                                phi_834_ = (_e493 + ((_e491 * _e491) * ((3u * _e497) ^ _e500)));
                            } else {
                                phi_827_ = u32();
                                phi_830_ = u32();
                                phi_832_ = u32();
                                phi_834_ = u32();
                            }
                            let _e520 = phi_827_;
                            let _e522 = phi_830_;
                            let _e524 = phi_832_;
                            let _e526 = phi_834_;
                            continue;
                            continuing {
                                phi_826_ = _e520;
                                phi_829_ = _e522;
                                phi_831_ = _e524;
                                phi_833_ = _e526;
                                break if !(_e494);
                            }
                        }
                        let _e531 = local;
                        let _e533 = f32((_e531 + (288u * (_e483 % 64u))));
                        let _e535 = (0.5f + (_e533 * 0.7548777f));
                        let _e539 = (0.5f + (_e533 * 0.5698403f));
                        let _e542 = (6.2831855f * (_e535 - floor(_e535)));
                        phi_896_ = type_29(_e379, type_28(1u, type_27(vec2<u32>(_e60.x, _e60.y), vec3<f32>(_e394, _e403, _e104), _e480, sin(_e542), cos(_e542), (_e539 - floor(_e539)))));
                    } else {
                        phi_896_ = type_29(_e379, type_28(0u, type_28().member_1));
                    }
                    let _e554 = phi_896_;
                    if (bitcast<i32>(_e554.member_1.member) != 0i) {
                        let _e563 = params.member.member_5;
                        let _e565 = select(_e563, 64u, (64u < _e563));
                        let _e567 = select(_e565, _e66, (_e66 < _e565));
                        let _e569 = select(1u, _e567, (1u < _e567));
                        let _e572 = params.member.member_6;
                        let _e574 = select(1u, _e572, (1u < _e572));
                        phi_2348_ = false;
                        phi_931_ = 0u;
                        phi_934_ = 0f;
                        loop {
                            let _e576 = phi_2348_;
                            let _e578 = phi_931_;
                            let _e580 = phi_934_;
                            local_5 = _e580;
                            let _e581 = (_e578 < _e569);
                            if _e581 {
                                if (_e578 < _e66) {
                                } else {
                                    phi_2425_ = true;
                                    break;
                                }
                                let _e586 = kernel.member[_e578][0u];
                                let _e590 = kernel.member[_e578][1u];
                                let _e595 = ((_e554.member_1.member_1.member_4 * _e586) - (_e554.member_1.member_1.member_3 * _e590));
                                let _e598 = ((_e554.member_1.member_1.member_3 * _e586) + (_e554.member_1.member_1.member_4 * _e590));
                                let _e603 = ((1f - (_e595 * _e595)) - (_e598 * _e598));
                                if (_e603 != _e603) {
                                    phi_1983_ = true;
                                } else {
                                    phi_1983_ = (0f >= _e603);
                                }
                                let _e607 = phi_1983_;
                                let _e609 = sqrt(select(_e603, 0f, _e607));
                                let _e610 = -(_e609);
                                let _e614 = (-1f * _e554.member_1.member_1.member_2.z);
                                let _e615 = (-1f * _e554.member_1.member_1.member_2.x);
                                let _e617 = (1f / (_e614 + 1f));
                                let _e618 = (_e617 * _e554.member_1.member_1.member_2.y);
                                let _e622 = (_e618 * _e615);
                                let _e642 = (_e614 > 0.9997f);
                                let _e643 = (_e614 < -0.9997f);
                                let _e653 = params.member.member_1;
                                let _e657 = params.member.member_3;
                                let _e660 = params.member.member_4;
                                phi_1080_ = 1u;
                                phi_1083_ = _e653;
                                phi_1085_ = false;
                                phi_1087_ = true;
                                phi_1089_ = 0f;
                                phi_1091_ = 0f;
                                loop {
                                    let _e666 = phi_1080_;
                                    let _e668 = phi_1083_;
                                    let _e670 = phi_1085_;
                                    let _e672 = phi_1087_;
                                    let _e674 = phi_1089_;
                                    let _e676 = phi_1091_;
                                    local_1 = _e668;
                                    local_2 = _e670;
                                    local_3 = _e668;
                                    local_4 = _e670;
                                    let _e677 = (_e666 <= _e574);
                                    if _e677 {
                                        let _e683 = (((-(_e554.member_1.member_1.member_5) + f32(_e666)) * _e653) / f32(_e574));
                                        let _e688 = (_e554.member_1.member_1.member_1.x + (select(select(((((_e614 + (_e618 * _e554.member_1.member_1.member_2.y)) * _e595) + (_e622 * _e598)) + (_e615 * _e610)), _e595, _e643), _e595, _e642) * _e683));
                                        let _e690 = (_e554.member_1.member_1.member_1.y + (select(select((((_e622 * _e595) + ((_e614 + ((_e617 * _e615) * _e615)) * _e598)) + (-(_e554.member_1.member_1.member_2.y) * _e610)), -(_e598), _e643), _e598, _e642) * _e683));
                                        let _e692 = (_e554.member_1.member_1.member_1.z + (select(select((((_e554.member_1.member_1.member_2.x * _e595) + (_e554.member_1.member_1.member_2.y * _e598)) + (_e614 * _e610)), _e609, _e643), _e610, _e642) * _e683));
                                        let _e698 = params.member.member.member_1[0u];
                                        let _e701 = (((_e688 * 0.5f) / (_e692 * _e698)) + 0.5f);
                                        let _e707 = params.member.member.member_1[1u];
                                        let _e710 = (0.5f - ((_e690 * 0.5f) / (_e692 * _e707)));
                                        let _e720 = select(false, select(false, select(false, select(false, (_e710 <= 1f), (_e710 >= 0f)), select(false, (_e701 <= 1f), (_e701 >= 0f))), (_e692 > 0f)), _e672);
                                        if _e720 {
                                            let _e721 = params.member.member;
                                            let _e728 = select(select(u32(_e721.member.x), 0u, (_e721.member.x < 0f)), 4294967295u, (_e721.member.x > 4294967000f));
                                            let _e734 = select(select(u32(_e721.member.y), 0u, (_e721.member.y < 0f)), 4294967295u, (_e721.member.y > 4294967000f));
                                            let _e736 = floor((_e701 * _e721.member.x));
                                            if (_e736 > 0f) {
                                                let _e742 = select(select(u32(_e736), 0u, (_e736 < 0f)), 4294967295u, (_e736 > 4294967000f));
                                                let _e743 = (_e728 - 1u);
                                                phi_2035_ = select(_e742, _e743, (_e743 < _e742));
                                            } else {
                                                phi_2035_ = 0u;
                                            }
                                            let _e747 = phi_2035_;
                                            let _e749 = floor((_e710 * _e721.member.y));
                                            if (_e749 > 0f) {
                                                let _e755 = select(select(u32(_e749), 0u, (_e749 < 0f)), 4294967295u, (_e749 > 4294967000f));
                                                let _e756 = (_e734 - 1u);
                                                phi_2062_ = select(_e755, _e756, (_e756 < _e755));
                                            } else {
                                                phi_2062_ = 0u;
                                            }
                                            let _e760 = phi_2062_;
                                            let _e762 = ((_e760 * _e728) + _e747);
                                            if (_e762 < _e62) {
                                            } else {
                                                phi_2302_ = true;
                                                phi_1770_ = bool();
                                                phi_1769_ = bool();
                                                phi_1768_ = bool();
                                                phi_1767_ = bool();
                                                phi_1765_ = f32();
                                                break;
                                            }
                                            let _e766 = depth.member[_e762];
                                            let _e770 = select(_e108, _e766, select(false, (_e766 < _e108), (_e766 > 0f)));
                                            let _e773 = (((_e701 * 2f) - 1f) * _e698);
                                            let _e777 = (((_e710 * -2f) + 1f) * _e707);
                                            let _e779 = (_e688 - (_e773 * _e770));
                                            let _e780 = (_e690 - (_e777 * _e770));
                                            let _e781 = (_e692 - _e770);
                                            let _e787 = sqrt((((_e779 * _e779) + (_e780 * _e780)) + (_e781 * _e781)));
                                            let _e792 = (select(0f, select(1f, _e701, (_e701 < 1f)), (_e701 > 0f)) * _e721.member.x);
                                            let _e797 = (select(0f, select(1f, _e710, (_e710 < 1f)), (_e710 > 0f)) * _e721.member.y);
                                            let _e802 = select(select(u32(_e792), 0u, (_e792 < 0f)), 4294967295u, (_e792 > 4294967000f));
                                            let _e803 = (_e728 - 1u);
                                            let _e805 = select(_e802, _e803, (_e803 < _e802));
                                            let _e810 = select(select(u32(_e797), 0u, (_e797 < 0f)), 4294967295u, (_e797 > 4294967000f));
                                            let _e811 = (_e734 - 1u);
                                            let _e813 = select(_e810, _e811, (_e811 < _e810));
                                            let _e831 = ((_e813 * _e84) + _e805);
                                            if (_e831 < _e64) {
                                            } else {
                                                phi_2302_ = true;
                                                phi_1770_ = bool();
                                                phi_1769_ = bool();
                                                phi_1768_ = bool();
                                                phi_1767_ = bool();
                                                phi_1765_ = f32();
                                                break;
                                            }
                                            let _e835 = normals.member[_e831];
                                            let _e843 = (f32((bitcast<i32>(((_e835 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e843 != _e843) {
                                                phi_2234_ = true;
                                            } else {
                                                phi_2234_ = (-1f >= _e843);
                                            }
                                            let _e847 = phi_2234_;
                                            let _e848 = select(_e843, -1f, _e847);
                                            let _e858 = (f32((bitcast<i32>((((_e835 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e858 != _e858) {
                                                phi_2249_ = true;
                                            } else {
                                                phi_2249_ = (-1f >= _e858);
                                            }
                                            let _e862 = phi_2249_;
                                            let _e863 = select(_e858, -1f, _e862);
                                            let _e866 = (1f - abs(_e848));
                                            let _e867 = abs(_e863);
                                            let _e868 = (_e866 - _e867);
                                            if (_e868 < 0f) {
                                                phi_2210_ = vec2<f32>(((1f - _e867) * select(1f, -1f, (_e848 < 0f))), (_e866 * select(1f, -1f, (_e863 < 0f))));
                                            } else {
                                                phi_2210_ = vec2<f32>(_e848, _e863);
                                            }
                                            let _e879 = phi_2210_;
                                            let _e888 = (1f / sqrt((((_e879.x * _e879.x) + (_e879.y * _e879.y)) + (_e868 * _e868))));
                                            let _e889 = (_e879.x * _e888);
                                            let _e890 = (_e879.y * _e888);
                                            let _e892 = -((_e868 * _e888));
                                            let _e896 = (((_e889 * _e773) + (_e890 * _e777)) + _e892);
                                            let _e905 = select(((((_e889 * ((((((f32(_e805) + 0.5f) * (1f / _e721.member.x)) * 2f) - 1f) * _e698) * _e770)) + (_e890 * ((((((f32(_e813) + 0.5f) * (1f / _e721.member.y)) * -2f) + 1f) * _e707) * _e770))) + (_e892 * _e770)) / _e896), _e770, (abs(_e896) < 0.001f));
                                            if (_e805 == _e554.member_1.member_1.member.x) {
                                                phi_1321_ = (_e813 == _e554.member_1.member_1.member.y);
                                            } else {
                                                phi_1321_ = false;
                                            }
                                            let _e909 = phi_1321_;
                                            let _e916 = select(select(((_e692 - _e905) > _e660), true, (_e692 < (_e905 * (1f + _e657)))), true, _e909);
                                            let _e918 = select(false, !(_e916), _e720);
                                            let _e919 = (_e674 + _e787);
                                            let _e928 = select(false, _e916, _e720);
                                            if _e928 {
                                                phi_1366_ = (_e666 + 1u);
                                            } else {
                                                phi_1366_ = u32();
                                            }
                                            let _e931 = phi_1366_;
                                            phi_1368_ = _e931;
                                            phi_1369_ = select(_e668, select((_e676 + ((_e674 * (_e683 - _e676)) / _e919)), _e676, (_e919 < 0.000001f)), _e918);
                                            phi_1370_ = select(_e918, true, _e670);
                                            phi_1371_ = _e928;
                                            phi_1372_ = _e787;
                                            phi_1375_ = _e928;
                                            phi_1376_ = select(true, false, _e928);
                                        } else {
                                            phi_1368_ = u32();
                                            phi_1369_ = f32();
                                            phi_1370_ = bool();
                                            phi_1371_ = bool();
                                            phi_1372_ = f32();
                                            phi_1375_ = false;
                                            phi_1376_ = false;
                                        }
                                        let _e934 = phi_1368_;
                                        let _e936 = phi_1369_;
                                        let _e938 = phi_1370_;
                                        let _e940 = phi_1371_;
                                        let _e942 = phi_1372_;
                                        let _e944 = phi_1375_;
                                        let _e946 = phi_1376_;
                                        phi_1081_ = _e934;
                                        phi_1084_ = _e936;
                                        phi_1086_ = _e938;
                                        phi_1088_ = _e940;
                                        phi_1090_ = _e942;
                                        phi_1092_ = _e683;
                                        phi_1380_ = _e944;
                                        phi_1382_ = _e946;
                                        phi_1383_ = select(true, false, _e720);
                                    } else {
                                        phi_1081_ = u32();
                                        phi_1084_ = f32();
                                        phi_1086_ = bool();
                                        phi_1088_ = bool();
                                        phi_1090_ = f32();
                                        phi_1092_ = f32();
                                        phi_1380_ = false;
                                        phi_1382_ = false;
                                        phi_1383_ = false;
                                    }
                                    let _e949 = phi_1081_;
                                    let _e951 = phi_1084_;
                                    let _e953 = phi_1086_;
                                    let _e955 = phi_1088_;
                                    let _e957 = phi_1090_;
                                    let _e959 = phi_1092_;
                                    let _e961 = phi_1380_;
                                    let _e963 = phi_1382_;
                                    let _e965 = phi_1383_;
                                    continue;
                                    continuing {
                                        phi_1080_ = _e949;
                                        phi_1083_ = _e951;
                                        phi_1085_ = _e953;
                                        phi_1087_ = _e955;
                                        phi_1089_ = _e957;
                                        phi_1091_ = _e959;
                                        phi_2302_ = _e576;
                                        phi_1770_ = _e965;
                                        phi_1769_ = _e963;
                                        phi_1768_ = select(true, false, _e677);
                                        phi_1767_ = _e953;
                                        phi_1765_ = _e951;
                                        break if !(_e961);
                                    }
                                }
                                let _e969 = phi_2302_;
                                let _e971 = phi_1770_;
                                let _e973 = phi_1769_;
                                let _e975 = phi_1768_;
                                let _e977 = phi_1767_;
                                let _e979 = phi_1765_;
                                phi_2425_ = _e969;
                                if _e969 {
                                    break;
                                }
                                let _e980 = select(_e973, false, _e975);
                                let _e982 = select(select(_e971, false, _e975), false, _e980);
                                let _e984 = local_1;
                                let _e987 = local_2;
                                let _e989 = select(_e980, true, _e982);
                                let _e991 = local_3;
                                let _e994 = local_4;
                                let _e998 = params.member.member_7;
                                if (_e998 == 1u) {
                                    phi_1423_ = 0f;
                                } else {
                                    let _e1000 = (select(_e991, select(_e979, _e984, _e982), _e989) / _e653);
                                    phi_1423_ = select(0f, select(1f, _e1000, (_e1000 < 1f)), (_e1000 > 0f));
                                }
                                let _e1006 = phi_1423_;
                                phi_2426_ = _e969;
                                phi_932_ = (_e578 + 1u);
                                phi_935_ = (_e580 + select(1f, _e1006, select(_e994, select(_e977, _e987, _e982), _e989)));
                            } else {
                                phi_2426_ = _e576;
                                phi_932_ = u32();
                                phi_935_ = f32();
                            }
                            let _e1011 = phi_2426_;
                            let _e1013 = phi_932_;
                            let _e1015 = phi_935_;
                            continue;
                            continuing {
                                phi_2348_ = _e1011;
                                phi_931_ = _e1013;
                                phi_934_ = _e1015;
                                phi_2425_ = _e1011;
                                break if !(_e581);
                            }
                        }
                        let _e1018 = phi_2425_;
                        if _e1018 {
                            break;
                        }
                        let _e1021 = local_5;
                        let _e1025 = params.member.member_2;
                        let _e1026 = pow((_e1021 / f32(_e569)), _e1025);
                        let _e1027 = (_e1026 * 0.6666667f);
                        let _e1033 = ((select(0f, select(1f, _e1027, (_e1027 < 1f)), (_e1027 > 0f)) * 255f) + 0.5f);
                        phi_1494_ = type_30(_e1026, select(select(u32(_e1033), 0u, (_e1033 < 0f)), 4294967295u, (_e1033 > 4294967000f)), _e554.member);
                    } else {
                        phi_1494_ = type_30(1f, 170u, _e554.member);
                    }
                    let _e1042 = phi_1494_;
                    if (_e100 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e100] = _e1042.member;
                    if (_e100 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e100] = _e1042.member_1;
                    if (_e100 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e100] = _e1042.member_2;
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
