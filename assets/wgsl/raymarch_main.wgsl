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
    var phi_295_: i32;
    var phi_314_: i32;
    var phi_365_: i32;
    var phi_384_: i32;
    var phi_435_: i32;
    var phi_454_: i32;
    var phi_505_: i32;
    var phi_524_: i32;
    var phi_1759_: f32;
    var phi_1763_: f32;
    var phi_1764_: bool;
    var phi_1802_: f32;
    var phi_1806_: f32;
    var phi_1807_: bool;
    var phi_1845_: f32;
    var phi_1849_: f32;
    var phi_1850_: bool;
    var phi_1888_: f32;
    var phi_1892_: f32;
    var phi_1893_: bool;
    var phi_1915_: bool;
    var phi_1930_: bool;
    var phi_781_: vec2<f32>;
    var phi_812_: vec3<f32>;
    var phi_818_: u32;
    var phi_821_: u32;
    var phi_823_: u32;
    var phi_825_: u32;
    var phi_854_: u32;
    var phi_855_: u32;
    var phi_856_: u32;
    var phi_857_: u32;
    var phi_819_: u32;
    var phi_822_: u32;
    var phi_824_: u32;
    var phi_826_: u32;
    var local: u32;
    var phi_888_: type_29;
    var phi_2217_: bool;
    var phi_923_: u32;
    var phi_926_: f32;
    var phi_1945_: bool;
    var phi_1072_: u32;
    var phi_1075_: f32;
    var phi_1077_: bool;
    var phi_1079_: bool;
    var phi_1081_: f32;
    var phi_1083_: f32;
    var phi_1187_: u32;
    var phi_1208_: u32;
    var phi_2120_: bool;
    var phi_2135_: bool;
    var phi_2096_: vec2<f32>;
    var phi_1360_: bool;
    var phi_1405_: u32;
    var phi_1407_: u32;
    var phi_1408_: f32;
    var phi_1409_: bool;
    var phi_1410_: bool;
    var phi_1411_: f32;
    var phi_1414_: bool;
    var phi_1415_: bool;
    var phi_1073_: u32;
    var phi_1076_: f32;
    var phi_1078_: bool;
    var phi_1080_: bool;
    var phi_1082_: f32;
    var phi_1084_: f32;
    var phi_1419_: bool;
    var phi_1421_: bool;
    var phi_1422_: bool;
    var phi_2171_: bool;
    var phi_1732_: bool;
    var phi_1731_: bool;
    var phi_1730_: bool;
    var phi_1729_: bool;
    var phi_1727_: f32;
    var local_1: f32;
    var local_2: bool;
    var local_3: f32;
    var local_4: bool;
    var phi_1462_: f32;
    var phi_2295_: bool;
    var phi_924_: u32;
    var phi_927_: f32;
    var phi_2294_: bool;
    var local_5: f32;
    var phi_1533_: type_30;

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
                        phi_295_ = 0i;
                    } else {
                        phi_295_ = select(_e114, _e116, (_e114 > _e116));
                    }
                    let _e122 = phi_295_;
                    let _e124 = bitcast<i32>(_e60.y);
                    let _e126 = (bitcast<i32>(_e94) - 1i);
                    let _e127 = (0i <= _e126);
                    if _e127 {
                    } else {
                        break;
                    }
                    let _e128 = (_e124 < 0i);
                    if _e128 {
                        phi_314_ = 0i;
                    } else {
                        phi_314_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_314_;
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
                        phi_365_ = 0i;
                    } else {
                        phi_365_ = select(_e144, _e116, (_e144 > _e116));
                    }
                    let _e149 = phi_365_;
                    if _e127 {
                    } else {
                        break;
                    }
                    if _e128 {
                        phi_384_ = 0i;
                    } else {
                        phi_384_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e154 = phi_384_;
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
                        phi_435_ = 0i;
                    } else {
                        phi_435_ = select(_e113, _e116, (_e113 > _e116));
                    }
                    let _e170 = phi_435_;
                    let _e172 = (_e124 + -1i);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e172 < 0i) {
                        phi_454_ = 0i;
                    } else {
                        phi_454_ = select(_e172, _e126, (_e172 > _e126));
                    }
                    let _e177 = phi_454_;
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
                        phi_505_ = 0i;
                    } else {
                        phi_505_ = select(_e113, _e116, (_e113 > _e116));
                    }
                    let _e192 = phi_505_;
                    let _e194 = (_e124 + 1i);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e194 < 0i) {
                        phi_524_ = 0i;
                    } else {
                        phi_524_ = select(_e194, _e126, (_e194 > _e126));
                    }
                    let _e199 = phi_524_;
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
                            phi_1759_ = (_e272 - 1f);
                        } else {
                            phi_1759_ = f32();
                        }
                        let _e281 = phi_1759_;
                        phi_1763_ = _e281;
                        phi_1764_ = select(true, false, _e278);
                    } else {
                        phi_1763_ = f32();
                        phi_1764_ = true;
                    }
                    let _e284 = phi_1763_;
                    let _e286 = phi_1764_;
                    let _e287 = select(_e284, _e272, _e286);
                    let _e298 = (select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f)) * 2.9f);
                    let _e300 = floor((_e298 + 0.5f));
                    if ((_e300 - _e298) == 0.5f) {
                        let _e306 = ((floor((_e300 * 0.5f)) * 2f) != _e300);
                        if _e306 {
                            phi_1802_ = (_e300 - 1f);
                        } else {
                            phi_1802_ = f32();
                        }
                        let _e309 = phi_1802_;
                        phi_1806_ = _e309;
                        phi_1807_ = select(true, false, _e306);
                    } else {
                        phi_1806_ = f32();
                        phi_1807_ = true;
                    }
                    let _e312 = phi_1806_;
                    let _e314 = phi_1807_;
                    let _e315 = select(_e312, _e300, _e314);
                    let _e327 = (select(0f, select(1f, _e260, (_e260 < 1f)), (_e260 > 0f)) * 2.9f);
                    let _e329 = floor((_e327 + 0.5f));
                    if ((_e329 - _e327) == 0.5f) {
                        let _e335 = ((floor((_e329 * 0.5f)) * 2f) != _e329);
                        if _e335 {
                            phi_1845_ = (_e329 - 1f);
                        } else {
                            phi_1845_ = f32();
                        }
                        let _e338 = phi_1845_;
                        phi_1849_ = _e338;
                        phi_1850_ = select(true, false, _e335);
                    } else {
                        phi_1849_ = f32();
                        phi_1850_ = true;
                    }
                    let _e341 = phi_1849_;
                    let _e343 = phi_1850_;
                    let _e344 = select(_e341, _e329, _e343);
                    let _e356 = (select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f)) * 2.9f);
                    let _e358 = floor((_e356 + 0.5f));
                    if ((_e358 - _e356) == 0.5f) {
                        let _e364 = ((floor((_e358 * 0.5f)) * 2f) != _e358);
                        if _e364 {
                            phi_1888_ = (_e358 - 1f);
                        } else {
                            phi_1888_ = f32();
                        }
                        let _e367 = phi_1888_;
                        phi_1892_ = _e367;
                        phi_1893_ = select(true, false, _e364);
                    } else {
                        phi_1892_ = f32();
                        phi_1893_ = true;
                    }
                    let _e370 = phi_1892_;
                    let _e372 = phi_1893_;
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
                            phi_1915_ = true;
                        } else {
                            phi_1915_ = (-1f >= _e416);
                        }
                        let _e420 = phi_1915_;
                        let _e421 = select(_e416, -1f, _e420);
                        let _e431 = (f32((bitcast<i32>((((_e408 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e431 != _e431) {
                            phi_1930_ = true;
                        } else {
                            phi_1930_ = (-1f >= _e431);
                        }
                        let _e435 = phi_1930_;
                        let _e436 = select(_e431, -1f, _e435);
                        let _e439 = (1f - abs(_e421));
                        let _e440 = abs(_e436);
                        let _e441 = (_e439 - _e440);
                        if (_e441 < 0f) {
                            phi_781_ = vec2<f32>(((1f - _e440) * select(1f, -1f, (_e421 < 0f))), (_e439 * select(1f, -1f, (_e436 < 0f))));
                        } else {
                            phi_781_ = vec2<f32>(_e421, _e436);
                        }
                        let _e452 = phi_781_;
                        let _e461 = (1f / sqrt((((_e452.x * _e452.x) + (_e452.y * _e452.y)) + (_e441 * _e441))));
                        let _e462 = (_e452.x * _e461);
                        let _e463 = (_e452.y * _e461);
                        let _e464 = (_e441 * _e461);
                        let _e465 = -(_e464);
                        if ((((_e462 * -(_e394)) + (_e463 * -(_e403))) + (_e465 * -(_e104))) < 0f) {
                            phi_812_ = vec3<f32>(-(_e462), -(_e463), _e464);
                        } else {
                            phi_812_ = vec3<f32>(_e462, _e463, _e465);
                        }
                        let _e480 = phi_812_;
                        let _e483 = params.member.member_8;
                        phi_818_ = (_e60.y & 63u);
                        phi_821_ = (_e60.x & 63u);
                        phi_823_ = 32u;
                        phi_825_ = 0u;
                        loop {
                            let _e487 = phi_818_;
                            let _e489 = phi_821_;
                            let _e491 = phi_823_;
                            let _e493 = phi_825_;
                            local = _e493;
                            let _e494 = (_e491 > 0u);
                            if _e494 {
                                let _e497 = select(0u, 1u, ((_e489 & _e491) != 0u));
                                let _e500 = select(0u, 1u, ((_e487 & _e491) != 0u));
                                if (_e500 == 0u) {
                                    if (_e497 == 1u) {
                                        phi_854_ = (63u - _e487);
                                        phi_855_ = (63u - _e489);
                                    } else {
                                        phi_854_ = _e487;
                                        phi_855_ = _e489;
                                    }
                                    let _e511 = phi_854_;
                                    let _e513 = phi_855_;
                                    phi_856_ = _e513;
                                    phi_857_ = _e511;
                                } else {
                                    phi_856_ = _e487;
                                    phi_857_ = _e489;
                                }
                                let _e515 = phi_856_;
                                let _e517 = phi_857_;
                                phi_819_ = _e515;
                                phi_822_ = _e517;
                                phi_824_ = (_e491 / 2u);
                                phi_826_ = (_e493 + ((_e491 * _e491) * ((3u * _e497) ^ _e500)));
                            } else {
                                phi_819_ = u32();
                                phi_822_ = u32();
                                phi_824_ = u32();
                                phi_826_ = u32();
                            }
                            let _e520 = phi_819_;
                            let _e522 = phi_822_;
                            let _e524 = phi_824_;
                            let _e526 = phi_826_;
                            continue;
                            continuing {
                                phi_818_ = _e520;
                                phi_821_ = _e522;
                                phi_823_ = _e524;
                                phi_825_ = _e526;
                                break if !(_e494);
                            }
                        }
                        let _e531 = local;
                        let _e533 = f32((_e531 + (288u * (_e483 % 64u))));
                        let _e535 = (0.5f + (_e533 * 0.7548777f));
                        let _e539 = (0.5f + (_e533 * 0.5698403f));
                        let _e542 = (6.2831855f * (_e535 - floor(_e535)));
                        phi_888_ = type_29(_e379, type_28(1u, type_27(vec2<u32>(_e60.x, _e60.y), vec3<f32>(_e394, _e403, _e104), _e480, sin(_e542), cos(_e542), (_e539 - floor(_e539)))));
                    } else {
                        phi_888_ = type_29(_e379, type_28(0u, type_28().member_1));
                    }
                    let _e554 = phi_888_;
                    if (bitcast<i32>(_e554.member_1.member) != 0i) {
                        let _e563 = params.member.member_5;
                        let _e565 = select(_e563, 64u, (64u < _e563));
                        let _e567 = select(_e565, _e66, (_e66 < _e565));
                        let _e569 = select(1u, _e567, (1u < _e567));
                        let _e572 = params.member.member_6;
                        let _e574 = select(1u, _e572, (1u < _e572));
                        phi_2217_ = false;
                        phi_923_ = 0u;
                        phi_926_ = 0f;
                        loop {
                            let _e576 = phi_2217_;
                            let _e578 = phi_923_;
                            let _e580 = phi_926_;
                            local_5 = _e580;
                            let _e581 = (_e578 < _e569);
                            if _e581 {
                                if (_e578 < _e66) {
                                } else {
                                    phi_2294_ = true;
                                    break;
                                }
                                let _e586 = kernel.member[_e578][0u];
                                let _e590 = kernel.member[_e578][1u];
                                let _e595 = ((_e554.member_1.member_1.member_4 * _e586) - (_e554.member_1.member_1.member_3 * _e590));
                                let _e598 = ((_e554.member_1.member_1.member_3 * _e586) + (_e554.member_1.member_1.member_4 * _e590));
                                let _e603 = ((1f - (_e595 * _e595)) - (_e598 * _e598));
                                if (_e603 != _e603) {
                                    phi_1945_ = true;
                                } else {
                                    phi_1945_ = (0f >= _e603);
                                }
                                let _e607 = phi_1945_;
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
                                phi_1072_ = 1u;
                                phi_1075_ = _e653;
                                phi_1077_ = false;
                                phi_1079_ = true;
                                phi_1081_ = 0f;
                                phi_1083_ = 0f;
                                loop {
                                    let _e666 = phi_1072_;
                                    let _e668 = phi_1075_;
                                    let _e670 = phi_1077_;
                                    let _e672 = phi_1079_;
                                    let _e674 = phi_1081_;
                                    let _e676 = phi_1083_;
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
                                            let _e721 = (_e701 * _e79);
                                            if (_e721 > 0f) {
                                                let _e727 = select(select(u32(_e721), 0u, (_e721 < 0f)), 4294967295u, (_e721 > 4294967000f));
                                                let _e728 = (_e84 - 1u);
                                                phi_1187_ = select(_e727, _e728, (_e728 < _e727));
                                            } else {
                                                phi_1187_ = 0u;
                                            }
                                            let _e732 = phi_1187_;
                                            let _e733 = (_e710 * _e89);
                                            if (_e733 > 0f) {
                                                let _e739 = select(select(u32(_e733), 0u, (_e733 < 0f)), 4294967295u, (_e733 > 4294967000f));
                                                let _e740 = (_e94 - 1u);
                                                phi_1208_ = select(_e739, _e740, (_e740 < _e739));
                                            } else {
                                                phi_1208_ = 0u;
                                            }
                                            let _e744 = phi_1208_;
                                            let _e746 = ((_e744 * _e84) + _e732);
                                            if (_e746 < _e62) {
                                            } else {
                                                phi_2171_ = true;
                                                phi_1732_ = bool();
                                                phi_1731_ = bool();
                                                phi_1730_ = bool();
                                                phi_1729_ = bool();
                                                phi_1727_ = f32();
                                                break;
                                            }
                                            let _e750 = depth.member[_e746];
                                            let _e754 = select(_e108, _e750, select(false, (_e750 < _e108), (_e750 > 0f)));
                                            let _e757 = (((_e701 * 2f) - 1f) * _e698);
                                            let _e761 = (((_e710 * -2f) + 1f) * _e707);
                                            let _e763 = (_e688 - (_e757 * _e754));
                                            let _e764 = (_e690 - (_e761 * _e754));
                                            let _e765 = (_e692 - _e754);
                                            let _e771 = sqrt((((_e763 * _e763) + (_e764 * _e764)) + (_e765 * _e765)));
                                            let _e772 = params.member.member;
                                            let _e790 = (select(0f, select(1f, _e701, (_e701 < 1f)), (_e701 > 0f)) * _e772.member.x);
                                            let _e795 = (select(0f, select(1f, _e710, (_e710 < 1f)), (_e710 > 0f)) * _e772.member.y);
                                            let _e800 = select(select(u32(_e790), 0u, (_e790 < 0f)), 4294967295u, (_e790 > 4294967000f));
                                            let _e801 = (select(select(u32(_e772.member.x), 0u, (_e772.member.x < 0f)), 4294967295u, (_e772.member.x > 4294967000f)) - 1u);
                                            let _e803 = select(_e800, _e801, (_e801 < _e800));
                                            let _e808 = select(select(u32(_e795), 0u, (_e795 < 0f)), 4294967295u, (_e795 > 4294967000f));
                                            let _e809 = (select(select(u32(_e772.member.y), 0u, (_e772.member.y < 0f)), 4294967295u, (_e772.member.y > 4294967000f)) - 1u);
                                            let _e811 = select(_e808, _e809, (_e809 < _e808));
                                            let _e829 = ((_e811 * _e84) + _e803);
                                            if (_e829 < _e64) {
                                            } else {
                                                phi_2171_ = true;
                                                phi_1732_ = bool();
                                                phi_1731_ = bool();
                                                phi_1730_ = bool();
                                                phi_1729_ = bool();
                                                phi_1727_ = f32();
                                                break;
                                            }
                                            let _e833 = normals.member[_e829];
                                            let _e841 = (f32((bitcast<i32>(((_e833 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e841 != _e841) {
                                                phi_2120_ = true;
                                            } else {
                                                phi_2120_ = (-1f >= _e841);
                                            }
                                            let _e845 = phi_2120_;
                                            let _e846 = select(_e841, -1f, _e845);
                                            let _e856 = (f32((bitcast<i32>((((_e833 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e856 != _e856) {
                                                phi_2135_ = true;
                                            } else {
                                                phi_2135_ = (-1f >= _e856);
                                            }
                                            let _e860 = phi_2135_;
                                            let _e861 = select(_e856, -1f, _e860);
                                            let _e864 = (1f - abs(_e846));
                                            let _e865 = abs(_e861);
                                            let _e866 = (_e864 - _e865);
                                            if (_e866 < 0f) {
                                                phi_2096_ = vec2<f32>(((1f - _e865) * select(1f, -1f, (_e846 < 0f))), (_e864 * select(1f, -1f, (_e861 < 0f))));
                                            } else {
                                                phi_2096_ = vec2<f32>(_e846, _e861);
                                            }
                                            let _e877 = phi_2096_;
                                            let _e886 = (1f / sqrt((((_e877.x * _e877.x) + (_e877.y * _e877.y)) + (_e866 * _e866))));
                                            let _e887 = (_e877.x * _e886);
                                            let _e888 = (_e877.y * _e886);
                                            let _e890 = -((_e866 * _e886));
                                            let _e894 = (((_e887 * _e757) + (_e888 * _e761)) + _e890);
                                            let _e903 = select(((((_e887 * ((((((f32(_e803) + 0.5f) * (1f / _e772.member.x)) * 2f) - 1f) * _e698) * _e754)) + (_e888 * ((((((f32(_e811) + 0.5f) * (1f / _e772.member.y)) * -2f) + 1f) * _e707) * _e754))) + (_e890 * _e754)) / _e894), _e754, (abs(_e894) < 0.001f));
                                            if (_e803 == _e554.member_1.member_1.member.x) {
                                                phi_1360_ = (_e811 == _e554.member_1.member_1.member.y);
                                            } else {
                                                phi_1360_ = false;
                                            }
                                            let _e907 = phi_1360_;
                                            let _e914 = select(select(((_e692 - _e903) > _e660), true, (_e692 < (_e903 * (1f + _e657)))), true, _e907);
                                            let _e916 = select(false, !(_e914), _e720);
                                            let _e917 = (_e674 + _e771);
                                            let _e926 = select(false, _e914, _e720);
                                            if _e926 {
                                                phi_1405_ = (_e666 + 1u);
                                            } else {
                                                phi_1405_ = u32();
                                            }
                                            let _e929 = phi_1405_;
                                            phi_1407_ = _e929;
                                            phi_1408_ = select(_e668, select((_e676 + ((_e674 * (_e683 - _e676)) / _e917)), _e676, (_e917 < 0.000001f)), _e916);
                                            phi_1409_ = select(_e916, true, _e670);
                                            phi_1410_ = _e926;
                                            phi_1411_ = _e771;
                                            phi_1414_ = _e926;
                                            phi_1415_ = select(true, false, _e926);
                                        } else {
                                            phi_1407_ = u32();
                                            phi_1408_ = f32();
                                            phi_1409_ = bool();
                                            phi_1410_ = bool();
                                            phi_1411_ = f32();
                                            phi_1414_ = false;
                                            phi_1415_ = false;
                                        }
                                        let _e932 = phi_1407_;
                                        let _e934 = phi_1408_;
                                        let _e936 = phi_1409_;
                                        let _e938 = phi_1410_;
                                        let _e940 = phi_1411_;
                                        let _e942 = phi_1414_;
                                        let _e944 = phi_1415_;
                                        phi_1073_ = _e932;
                                        phi_1076_ = _e934;
                                        phi_1078_ = _e936;
                                        phi_1080_ = _e938;
                                        phi_1082_ = _e940;
                                        phi_1084_ = _e683;
                                        phi_1419_ = _e942;
                                        phi_1421_ = _e944;
                                        phi_1422_ = select(true, false, _e720);
                                    } else {
                                        phi_1073_ = u32();
                                        phi_1076_ = f32();
                                        phi_1078_ = bool();
                                        phi_1080_ = bool();
                                        phi_1082_ = f32();
                                        phi_1084_ = f32();
                                        phi_1419_ = false;
                                        phi_1421_ = false;
                                        phi_1422_ = false;
                                    }
                                    let _e947 = phi_1073_;
                                    let _e949 = phi_1076_;
                                    let _e951 = phi_1078_;
                                    let _e953 = phi_1080_;
                                    let _e955 = phi_1082_;
                                    let _e957 = phi_1084_;
                                    let _e959 = phi_1419_;
                                    let _e961 = phi_1421_;
                                    let _e963 = phi_1422_;
                                    continue;
                                    continuing {
                                        phi_1072_ = _e947;
                                        phi_1075_ = _e949;
                                        phi_1077_ = _e951;
                                        phi_1079_ = _e953;
                                        phi_1081_ = _e955;
                                        phi_1083_ = _e957;
                                        phi_2171_ = _e576;
                                        phi_1732_ = _e963;
                                        phi_1731_ = _e961;
                                        phi_1730_ = select(true, false, _e677);
                                        phi_1729_ = _e951;
                                        phi_1727_ = _e949;
                                        break if !(_e959);
                                    }
                                }
                                let _e967 = phi_2171_;
                                let _e969 = phi_1732_;
                                let _e971 = phi_1731_;
                                let _e973 = phi_1730_;
                                let _e975 = phi_1729_;
                                let _e977 = phi_1727_;
                                phi_2294_ = _e967;
                                if _e967 {
                                    break;
                                }
                                let _e978 = select(_e971, false, _e973);
                                let _e980 = select(select(_e969, false, _e973), false, _e978);
                                let _e982 = local_1;
                                let _e985 = local_2;
                                let _e987 = select(_e978, true, _e980);
                                let _e989 = local_3;
                                let _e992 = local_4;
                                let _e996 = params.member.member_7;
                                if (_e996 == 1u) {
                                    phi_1462_ = 0f;
                                } else {
                                    let _e998 = (select(_e989, select(_e977, _e982, _e980), _e987) / _e653);
                                    phi_1462_ = select(0f, select(1f, _e998, (_e998 < 1f)), (_e998 > 0f));
                                }
                                let _e1004 = phi_1462_;
                                phi_2295_ = _e967;
                                phi_924_ = (_e578 + 1u);
                                phi_927_ = (_e580 + select(1f, _e1004, select(_e992, select(_e975, _e985, _e980), _e987)));
                            } else {
                                phi_2295_ = _e576;
                                phi_924_ = u32();
                                phi_927_ = f32();
                            }
                            let _e1009 = phi_2295_;
                            let _e1011 = phi_924_;
                            let _e1013 = phi_927_;
                            continue;
                            continuing {
                                phi_2217_ = _e1009;
                                phi_923_ = _e1011;
                                phi_926_ = _e1013;
                                phi_2294_ = _e1009;
                                break if !(_e581);
                            }
                        }
                        let _e1016 = phi_2294_;
                        if _e1016 {
                            break;
                        }
                        let _e1019 = local_5;
                        let _e1023 = params.member.member_2;
                        let _e1024 = pow((_e1019 / f32(_e569)), _e1023);
                        let _e1025 = (_e1024 * 0.6666667f);
                        let _e1031 = ((select(0f, select(1f, _e1025, (_e1025 < 1f)), (_e1025 > 0f)) * 255f) + 0.5f);
                        phi_1533_ = type_30(_e1024, select(select(u32(_e1031), 0u, (_e1031 < 0f)), 4294967295u, (_e1031 > 4294967000f)), _e554.member);
                    } else {
                        phi_1533_ = type_30(1f, 170u, _e554.member);
                    }
                    let _e1040 = phi_1533_;
                    if (_e100 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e100] = _e1040.member;
                    if (_e100 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e100] = _e1040.member_1;
                    if (_e100 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e100] = _e1040.member_2;
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
