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

struct type_7 {
    member: type_6,
}

struct type_10 {
    member: array<f32>,
}

struct type_13 {
    member: array<u32>,
}

struct type_31 {
    member: vec2<u32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: vec3<f32>,
    member_5: vec3<f32>,
    member_6: vec3<f32>,
    member_7: vec3<f32>,
    member_8: vec3<f32>,
    member_9: vec3<f32>,
    member_10: f32,
}

struct type_32 {
    member: u32,
    member_1: type_31,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(3) 
var<uniform> params: type_7;
@group(0) @binding(0) 
var<storage> depth: type_10;
@group(0) @binding(1) 
var<storage> normals: type_13;
@group(0) @binding(2) 
var<storage, read_write> ao: type_10;

fn function_() {
    var local: array<array<f32, 2>, 8>;
    var local_1: array<f32, 8>;
    var local_2: array<f32, 8>;
    var local_3: array<array<array<f32, 2>, 4>, 4>;
    var phi_269_: bool;
    var phi_271_: bool;
    var phi_272_: bool;
    var phi_273_: bool;
    var phi_274_: bool;
    var phi_332_: bool;
    var phi_362_: f32;
    var phi_1049_: bool;
    var phi_1064_: bool;
    var phi_437_: vec2<f32>;
    var phi_464_: vec3<f32>;
    var phi_1079_: bool;
    var phi_576_: type_32;
    var phi_577_: type_32;
    var phi_579_: type_32;
    var phi_580_: type_32;
    var phi_581_: bool;
    var phi_585_: type_32;
    var phi_594_: u32;
    var phi_597_: f32;
    var phi_691_: f32;
    var phi_784_: f32;
    var phi_797_: f32;
    var phi_848_: bool;
    var phi_895_: bool;
    var phi_1094_: bool;
    var phi_1109_: bool;
    var phi_969_: f32;
    var phi_976_: f32;
    var phi_978_: f32;
    var phi_595_: u32;
    var phi_598_: f32;
    var phi_1114_: bool;
    var local_4: f32;
    var phi_992_: f32;
    var phi_996_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e129 = id_1;
            let _e132 = arrayLength((&depth.member));
            let _e143 = params.member.member.member_4;
            let _e144 = (_e129.x + _e143);
            let _e145 = (_e129.y + _e143);
            let _e150 = params.member.member.member[0u];
            let _e155 = select(select(u32(_e150), 0u, (_e150 < 0f)), 4294967295u, (_e150 > 4294967000f));
            let _e160 = params.member.member.member[1u];
            let _e165 = select(select(u32(_e160), 0u, (_e160 < 0f)), 4294967295u, (_e160 > 4294967000f));
            if (_e144 >= _e143) {
                if (_e145 >= _e143) {
                    let _e169 = ((_e144 + _e143) < _e155);
                    if _e169 {
                        phi_269_ = ((_e145 + _e143) < _e165);
                    } else {
                        phi_269_ = bool();
                    }
                    let _e173 = phi_269_;
                    phi_271_ = _e173;
                    phi_272_ = select(true, false, _e169);
                } else {
                    phi_271_ = bool();
                    phi_272_ = true;
                }
                let _e176 = phi_271_;
                let _e178 = phi_272_;
                phi_273_ = _e176;
                phi_274_ = _e178;
            } else {
                phi_273_ = bool();
                phi_274_ = true;
            }
            let _e180 = phi_273_;
            let _e182 = phi_274_;
            if select(_e180, false, _e182) {
                let _e186 = params.member.member_1;
                let _e189 = params.member.member_4;
                let _e194 = ((f32(_e144) + 0.5f) / _e150);
                let _e195 = ((f32(_e145) + 0.5f) / _e160);
                let _e197 = ((_e145 * _e155) + _e144);
                if (_e197 < _e132) {
                } else {
                    break;
                }
                let _e200 = depth.member[_e197];
                let _e204 = params.member.member.member_3;
                if (_e200 > 0f) {
                    phi_332_ = (_e200 < _e204);
                } else {
                    phi_332_ = false;
                }
                let _e208 = phi_332_;
                if _e208 {
                    let _e216 = params.member.member.member_1[0u];
                    let _e221 = params.member.member.member_1[1u];
                    let _e231 = (0.5f * (((_e186 * _e150) / ((2f * _e216) * _e200)) + ((_e186 * _e160) / ((2f * _e221) * _e200))));
                    let _e232 = (_e231 > _e189);
                    if _e232 {
                        phi_362_ = ((_e186 * _e189) / _e231);
                    } else {
                        phi_362_ = _e186;
                    }
                    let _e236 = phi_362_;
                    let _e237 = select(_e231, _e189, _e232);
                    let _e238 = (_e237 < 0.5f);
                    if _e238 {
                        phi_576_ = type_32(0u, type_32().member_1);
                        phi_577_ = type_32();
                    } else {
                        let _e244 = ((((2f * _e194) - 1f) * _e200) * _e216);
                        let _e246 = (((1f - (2f * _e195)) * _e200) * _e221);
                        let _e247 = -(_e200);
                        if (_e197 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e251 = normals.member[_e197];
                        let _e259 = (f32((bitcast<i32>(((_e251 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e259 != _e259) {
                            phi_1049_ = true;
                        } else {
                            phi_1049_ = (-1f >= _e259);
                        }
                        let _e263 = phi_1049_;
                        let _e264 = select(_e259, -1f, _e263);
                        let _e274 = (f32((bitcast<i32>((((_e251 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e274 != _e274) {
                            phi_1064_ = true;
                        } else {
                            phi_1064_ = (-1f >= _e274);
                        }
                        let _e278 = phi_1064_;
                        let _e279 = select(_e274, -1f, _e278);
                        let _e282 = (1f - abs(_e264));
                        let _e283 = abs(_e279);
                        let _e284 = (_e282 - _e283);
                        if (_e284 < 0f) {
                            phi_437_ = vec2<f32>(((1f - _e283) * select(1f, -1f, (_e264 < 0f))), (_e282 * select(1f, -1f, (_e279 < 0f))));
                        } else {
                            phi_437_ = vec2<f32>(_e264, _e279);
                        }
                        let _e295 = phi_437_;
                        let _e304 = (1f / sqrt((((_e295.x * _e295.x) + (_e295.y * _e295.y)) + (_e284 * _e284))));
                        let _e305 = (_e295.x * _e304);
                        let _e306 = (_e295.y * _e304);
                        let _e307 = (_e284 * _e304);
                        if ((((_e244 * _e305) + (_e246 * _e306)) + (_e247 * _e307)) > 0f) {
                            phi_464_ = vec3<f32>(-(_e305), -(_e306), -(_e307));
                        } else {
                            phi_464_ = vec3<f32>(_e305, _e306, _e307);
                        }
                        let _e320 = phi_464_;
                        local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e321 = (_e145 % 4u);
                        if (_e321 < 4u) {
                        } else {
                            break;
                        }
                        let _e323 = (_e144 % 4u);
                        if (_e323 < 4u) {
                        } else {
                            break;
                        }
                        let _e327 = local_3[_e321][_e323];
                        let _e337 = sqrt((((_e244 * _e244) + (_e246 * _e246)) + (_e247 * _e247)));
                        let _e338 = (-(_e244) / _e337);
                        let _e339 = (-(_e246) / _e337);
                        let _e340 = (_e200 / _e337);
                        let _e343 = -((_e327[1] * _e340));
                        let _e344 = (_e340 * _e327[0]);
                        let _e347 = ((_e338 * _e327[1]) - (_e327[0] * _e339));
                        let _e354 = (1f / sqrt((((_e343 * _e343) + (_e344 * _e344)) + (_e347 * _e347))));
                        let _e355 = (_e343 * _e354);
                        let _e356 = (_e344 * _e354);
                        let _e357 = (_e347 * _e354);
                        let _e361 = ((_e356 * _e340) - (_e339 * _e357));
                        let _e364 = ((_e357 * _e338) - (_e340 * _e355));
                        let _e367 = ((_e355 * _e339) - (_e338 * _e356));
                        let _e386 = (((_e320.x * _e338) + (_e320.y * _e339)) + (_e320.z * _e340));
                        let _e390 = abs(_e386);
                        if (_e390 != _e390) {
                            phi_1079_ = true;
                        } else {
                            phi_1079_ = (0.0001f >= _e390);
                        }
                        let _e394 = phi_1079_;
                        phi_576_ = type_32();
                        phi_577_ = type_32(1u, type_31(vec2<u32>(_e144, _e145), vec2<f32>(_e194, _e195), _e236, _e237, vec3<f32>(_e244, _e246, _e247), _e320, vec3<f32>(_e338, _e339, _e340), vec3<f32>(_e361, _e364, _e367), vec3<f32>(_e355, _e356, _e357), vec3<f32>((((_e320.x * _e361) + (_e320.y * _e364)) + (_e320.z * _e367)), (((_e320.x * _e355) + (_e320.y * _e356)) + (_e320.z * _e357)), _e386), (1f / (select(1f, -1f, (_e386 < 0f)) * select(_e390, 0.0001f, _e394)))));
                    }
                    let _e406 = phi_576_;
                    let _e408 = phi_577_;
                    phi_579_ = _e406;
                    phi_580_ = _e408;
                    phi_581_ = _e238;
                } else {
                    phi_579_ = type_32(0u, type_32().member_1);
                    phi_580_ = type_32();
                    phi_581_ = true;
                }
                let _e410 = phi_579_;
                let _e412 = phi_580_;
                let _e414 = phi_581_;
                if _e414 {
                    phi_585_ = _e410;
                } else {
                    phi_585_ = _e412;
                }
                let _e416 = phi_585_;
                if (bitcast<i32>(_e416.member) != 0i) {
                    phi_594_ = 0u;
                    phi_597_ = 0f;
                    loop {
                        let _e422 = phi_594_;
                        let _e424 = phi_597_;
                        local_4 = _e424;
                        let _e425 = (_e422 < 8u);
                        if _e425 {
                            local = array<array<f32, 2>, 8>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f));
                            if _e425 {
                            } else {
                                phi_1114_ = true;
                                break;
                            }
                            let _e427 = local[_e422];
                            local_1 = array<f32, 8>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f);
                            if _e425 {
                            } else {
                                phi_1114_ = true;
                                break;
                            }
                            let _e431 = local_1[_e422];
                            let _e433 = (_e431 * _e416.member_1.member_2);
                            let _e434 = (_e433 * _e427[0]);
                            let _e435 = (_e433 * _e427[1]);
                            local_2 = array<f32, 8>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f);
                            if _e425 {
                            } else {
                                phi_1114_ = true;
                                break;
                            }
                            let _e437 = local_2[_e422];
                            let _e438 = (_e437 * _e416.member_1.member_2);
                            let _e448 = (-(((_e434 * _e416.member_1.member_9.x) + (_e435 * _e416.member_1.member_9.y))) * _e416.member_1.member_10);
                            let _e449 = -(_e438);
                            if (_e448 > _e449) {
                                phi_691_ = select(_e438, _e448, (_e448 < _e438));
                            } else {
                                phi_691_ = _e449;
                            }
                            let _e454 = phi_691_;
                            let _e455 = (_e438 - _e454);
                            let _e482 = (-0.5f / ((_e416.member_1.member_4.z + (_e416.member_1.member_7.z * _e434)) + (_e416.member_1.member_8.z * _e435)));
                            let _e488 = params.member.member.member_1[0u];
                            let _e490 = (0.5f + ((((_e416.member_1.member_4.x + (_e416.member_1.member_7.x * _e434)) + (_e416.member_1.member_8.x * _e435)) * _e482) / _e488));
                            let _e496 = params.member.member.member_1[1u];
                            let _e498 = (0.5f - ((((_e416.member_1.member_4.y + (_e416.member_1.member_7.y * _e434)) + (_e416.member_1.member_8.y * _e435)) * _e482) / _e496));
                            if (_e490 > 0f) {
                                phi_784_ = select(1f, _e490, (_e490 < 1f));
                            } else {
                                phi_784_ = 0f;
                            }
                            let _e503 = phi_784_;
                            let _e504 = (_e503 * _e150);
                            if (_e498 > 0f) {
                                phi_797_ = select(1f, _e498, (_e498 < 1f));
                            } else {
                                phi_797_ = 0f;
                            }
                            let _e509 = phi_797_;
                            let _e510 = (_e509 * _e160);
                            let _e515 = select(select(u32(_e504), 0u, (_e504 < 0f)), 4294967295u, (_e504 > 4294967000f));
                            let _e516 = (_e155 - 1u);
                            let _e518 = select(_e515, _e516, (_e516 < _e515));
                            let _e523 = select(select(u32(_e510), 0u, (_e510 < 0f)), 4294967295u, (_e510 > 4294967000f));
                            let _e524 = (_e165 - 1u);
                            let _e526 = select(_e523, _e524, (_e524 < _e523));
                            if (_e518 == _e416.member_1.member.x) {
                                phi_848_ = (_e526 == _e416.member_1.member.y);
                            } else {
                                phi_848_ = false;
                            }
                            let _e534 = phi_848_;
                            if (_e455 > (0.2f * _e438)) {
                                if _e534 {
                                    phi_976_ = (_e455 / (2f * _e438));
                                } else {
                                    let _e536 = ((_e526 * _e155) + _e518);
                                    if (_e536 < _e132) {
                                    } else {
                                        phi_1114_ = true;
                                        break;
                                    }
                                    let _e539 = depth.member[_e536];
                                    if (_e539 > 0f) {
                                        phi_895_ = (_e539 < _e204);
                                    } else {
                                        phi_895_ = false;
                                    }
                                    let _e543 = phi_895_;
                                    let _e544 = select(_e204, _e539, _e543);
                                    let _e573 = ((((((((2f * ((f32(_e518) + 0.5f) * (1f / _e150))) - 1f) * _e544) * _e488) - _e416.member_1.member_4.x) * _e416.member_1.member_6.x) + (((((1f - (2f * ((f32(_e526) + 0.5f) * (1f / _e160)))) * _e544) * _e496) - _e416.member_1.member_4.y) * _e416.member_1.member_6.y)) + ((-(_e544) - _e416.member_1.member_4.z) * _e416.member_1.member_6.z));
                                    let _e576 = params.member.member_3;
                                    if (_e454 != _e454) {
                                        phi_1094_ = true;
                                    } else {
                                        phi_1094_ = (_e573 >= _e454);
                                    }
                                    let _e581 = phi_1094_;
                                    let _e583 = (_e438 - select(_e454, _e573, _e581));
                                    if (_e583 != _e583) {
                                        phi_1109_ = true;
                                    } else {
                                        phi_1109_ = (0f >= _e583);
                                    }
                                    let _e587 = phi_1109_;
                                    let _e592 = ((_e573 - ((1f + _e576) * _e416.member_1.member_2)) * (1f / _e438));
                                    if (_e592 > 0f) {
                                        phi_969_ = select(1f, _e592, (_e592 < 1f));
                                    } else {
                                        phi_969_ = 0f;
                                    }
                                    let _e597 = phi_969_;
                                    phi_976_ = ((select(_e583, 0f, _e587) + (_e597 * _e455)) * (0.5f / _e438));
                                }
                                let _e605 = phi_976_;
                                phi_978_ = (_e424 + _e605);
                            } else {
                                phi_978_ = _e424;
                            }
                            let _e608 = phi_978_;
                            phi_595_ = (_e422 + 1u);
                            phi_598_ = _e608;
                        } else {
                            phi_595_ = u32();
                            phi_598_ = f32();
                        }
                        let _e611 = phi_595_;
                        let _e613 = phi_598_;
                        continue;
                        continuing {
                            phi_594_ = _e611;
                            phi_597_ = _e613;
                            phi_1114_ = false;
                            break if !(_e425);
                        }
                    }
                    let _e616 = phi_1114_;
                    if _e616 {
                        break;
                    }
                    let _e618 = local_4;
                    let _e619 = (0.25f * _e618);
                    if (_e619 > 0f) {
                        phi_992_ = select(1f, _e619, (_e619 < 1f));
                    } else {
                        phi_992_ = 0f;
                    }
                    let _e624 = phi_992_;
                    let _e627 = params.member.member_2;
                    phi_996_ = pow(_e624, _e627);
                } else {
                    phi_996_ = 1f;
                }
                let _e630 = phi_996_;
                if (_e197 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e197] = _e630;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
