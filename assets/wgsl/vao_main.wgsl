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
    var local: array<array<f32, 2>, 56>;
    var local_1: array<f32, 56>;
    var local_2: array<f32, 56>;
    var local_3: array<array<array<f32, 2>, 4>, 4>;
    var phi_582_: bool;
    var phi_584_: bool;
    var phi_585_: bool;
    var phi_586_: bool;
    var phi_587_: bool;
    var phi_675_: f32;
    var phi_1369_: bool;
    var phi_1384_: bool;
    var phi_751_: vec2<f32>;
    var phi_778_: vec3<f32>;
    var phi_1399_: bool;
    var phi_890_: type_32;
    var phi_891_: type_32;
    var phi_893_: type_32;
    var phi_894_: type_32;
    var phi_895_: bool;
    var phi_899_: type_32;
    var phi_908_: u32;
    var phi_911_: f32;
    var phi_1116_: u32;
    var phi_1147_: u32;
    var phi_1414_: bool;
    var phi_1429_: bool;
    var phi_909_: u32;
    var phi_912_: f32;
    var phi_1434_: bool;
    var local_4: f32;
    var phi_1316_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e299 = id_1;
            let _e302 = arrayLength((&depth.member));
            let _e313 = params.member.member.member_4;
            let _e314 = (_e299.x + _e313);
            let _e315 = (_e299.y + _e313);
            let _e320 = params.member.member.member[0u];
            let _e325 = select(select(u32(_e320), 0u, (_e320 < 0f)), 4294967295u, (_e320 > 4294967000f));
            let _e330 = params.member.member.member[1u];
            let _e335 = select(select(u32(_e330), 0u, (_e330 < 0f)), 4294967295u, (_e330 > 4294967000f));
            if (_e314 >= _e313) {
                if (_e315 >= _e313) {
                    let _e339 = ((_e314 + _e313) < _e325);
                    if _e339 {
                        phi_582_ = ((_e315 + _e313) < _e335);
                    } else {
                        phi_582_ = bool();
                    }
                    let _e343 = phi_582_;
                    phi_584_ = _e343;
                    phi_585_ = select(true, false, _e339);
                } else {
                    phi_584_ = bool();
                    phi_585_ = true;
                }
                let _e346 = phi_584_;
                let _e348 = phi_585_;
                phi_586_ = _e346;
                phi_587_ = _e348;
            } else {
                phi_586_ = bool();
                phi_587_ = true;
            }
            let _e350 = phi_586_;
            let _e352 = phi_587_;
            if select(_e350, false, _e352) {
                let _e356 = params.member.member_1;
                let _e359 = params.member.member_4;
                let _e364 = ((f32(_e314) + 0.5f) / _e320);
                let _e365 = ((f32(_e315) + 0.5f) / _e330);
                let _e367 = ((_e315 * _e325) + _e314);
                if (_e367 < _e302) {
                } else {
                    break;
                }
                let _e370 = depth.member[_e367];
                let _e374 = params.member.member.member_3;
                if select(false, (_e370 < _e374), (_e370 > 0f)) {
                    let _e385 = params.member.member.member_1[0u];
                    let _e390 = params.member.member.member_1[1u];
                    let _e400 = (0.5f * (((_e356 * _e320) / ((2f * _e385) * _e370)) + ((_e356 * _e330) / ((2f * _e390) * _e370))));
                    let _e401 = (_e400 > _e359);
                    if _e401 {
                        phi_675_ = ((_e356 * _e359) / _e400);
                    } else {
                        phi_675_ = _e356;
                    }
                    let _e405 = phi_675_;
                    let _e406 = select(_e400, _e359, _e401);
                    let _e407 = (_e406 < 0.5f);
                    if _e407 {
                        phi_890_ = type_32(0u, type_32().member_1);
                        phi_891_ = type_32();
                    } else {
                        let _e413 = ((((_e364 * 2f) - 1f) * _e370) * _e385);
                        let _e415 = ((((_e365 * -2f) + 1f) * _e370) * _e390);
                        let _e416 = -(_e370);
                        if (_e367 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e420 = normals.member[_e367];
                        let _e428 = (f32((bitcast<i32>(((_e420 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e428 != _e428) {
                            phi_1369_ = true;
                        } else {
                            phi_1369_ = (-1f >= _e428);
                        }
                        let _e432 = phi_1369_;
                        let _e433 = select(_e428, -1f, _e432);
                        let _e443 = (f32((bitcast<i32>((((_e420 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e443 != _e443) {
                            phi_1384_ = true;
                        } else {
                            phi_1384_ = (-1f >= _e443);
                        }
                        let _e447 = phi_1384_;
                        let _e448 = select(_e443, -1f, _e447);
                        let _e451 = (1f - abs(_e433));
                        let _e452 = abs(_e448);
                        let _e453 = (_e451 - _e452);
                        if (_e453 < 0f) {
                            phi_751_ = vec2<f32>(((1f - _e452) * select(1f, -1f, (_e433 < 0f))), (_e451 * select(1f, -1f, (_e448 < 0f))));
                        } else {
                            phi_751_ = vec2<f32>(_e433, _e448);
                        }
                        let _e464 = phi_751_;
                        let _e473 = (1f / sqrt((((_e464.x * _e464.x) + (_e464.y * _e464.y)) + (_e453 * _e453))));
                        let _e474 = (_e464.x * _e473);
                        let _e475 = (_e464.y * _e473);
                        let _e476 = (_e453 * _e473);
                        if ((((_e413 * _e474) + (_e415 * _e475)) + (_e416 * _e476)) > 0f) {
                            phi_778_ = vec3<f32>(-(_e474), -(_e475), -(_e476));
                        } else {
                            phi_778_ = vec3<f32>(_e474, _e475, _e476);
                        }
                        let _e489 = phi_778_;
                        local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e490 = (_e315 % 4u);
                        if (_e490 < 4u) {
                        } else {
                            break;
                        }
                        let _e492 = (_e314 % 4u);
                        if (_e492 < 4u) {
                        } else {
                            break;
                        }
                        let _e496 = local_3[_e490][_e492];
                        let _e506 = sqrt((((_e413 * _e413) + (_e415 * _e415)) + (_e416 * _e416)));
                        let _e507 = (-(_e413) / _e506);
                        let _e508 = (-(_e415) / _e506);
                        let _e509 = (_e370 / _e506);
                        let _e512 = -((_e496[1] * _e509));
                        let _e513 = (_e509 * _e496[0]);
                        let _e516 = ((_e507 * _e496[1]) - (_e496[0] * _e508));
                        let _e523 = (1f / sqrt((((_e512 * _e512) + (_e513 * _e513)) + (_e516 * _e516))));
                        let _e524 = (_e512 * _e523);
                        let _e525 = (_e513 * _e523);
                        let _e526 = (_e516 * _e523);
                        let _e530 = ((_e525 * _e509) - (_e508 * _e526));
                        let _e533 = ((_e526 * _e507) - (_e509 * _e524));
                        let _e536 = ((_e524 * _e508) - (_e507 * _e525));
                        let _e555 = (((_e489.x * _e507) + (_e489.y * _e508)) + (_e489.z * _e509));
                        let _e559 = abs(_e555);
                        if (_e559 != _e559) {
                            phi_1399_ = true;
                        } else {
                            phi_1399_ = (0.0001f >= _e559);
                        }
                        let _e563 = phi_1399_;
                        phi_890_ = type_32();
                        phi_891_ = type_32(1u, type_31(vec2<u32>(_e314, _e315), vec2<f32>(_e364, _e365), _e405, _e406, vec3<f32>(_e413, _e415, _e416), _e489, vec3<f32>(_e507, _e508, _e509), vec3<f32>(_e530, _e533, _e536), vec3<f32>(_e524, _e525, _e526), vec3<f32>((((_e489.x * _e530) + (_e489.y * _e533)) + (_e489.z * _e536)), (((_e489.x * _e524) + (_e489.y * _e525)) + (_e489.z * _e526)), _e555), (1f / (select(1f, -1f, (_e555 < 0f)) * select(_e559, 0.0001f, _e563)))));
                    }
                    let _e575 = phi_890_;
                    let _e577 = phi_891_;
                    phi_893_ = _e575;
                    phi_894_ = _e577;
                    phi_895_ = _e407;
                } else {
                    phi_893_ = type_32(0u, type_32().member_1);
                    phi_894_ = type_32();
                    phi_895_ = true;
                }
                let _e579 = phi_893_;
                let _e581 = phi_894_;
                let _e583 = phi_895_;
                if _e583 {
                    phi_899_ = _e579;
                } else {
                    phi_899_ = _e581;
                }
                let _e585 = phi_899_;
                if (bitcast<i32>(_e585.member) != 0i) {
                    phi_908_ = 0u;
                    phi_911_ = 0f;
                    loop {
                        let _e591 = phi_908_;
                        let _e593 = phi_911_;
                        local_4 = _e593;
                        let _e594 = (_e591 < 8u);
                        if _e594 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e595 = (_e591 < 56u);
                            if _e595 {
                            } else {
                                phi_1434_ = true;
                                break;
                            }
                            let _e597 = local[_e591];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e595 {
                            } else {
                                phi_1434_ = true;
                                break;
                            }
                            let _e601 = local_1[_e591];
                            let _e603 = (_e585.member_1.member_2 * _e601);
                            let _e604 = (_e603 * _e597[0]);
                            let _e605 = (_e603 * _e597[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e595 {
                            } else {
                                phi_1434_ = true;
                                break;
                            }
                            let _e607 = local_2[_e591];
                            let _e608 = (_e585.member_1.member_2 * _e607);
                            let _e617 = (-(((_e604 * _e585.member_1.member_9.x) + (_e605 * _e585.member_1.member_9.y))) * _e585.member_1.member_10);
                            let _e618 = -(_e608);
                            let _e622 = select(_e618, select(_e608, _e617, (_e617 < _e608)), (_e617 > _e618));
                            let _e623 = (_e608 - _e622);
                            let _e650 = (-0.5f / ((_e585.member_1.member_4.z + (_e585.member_1.member_7.z * _e604)) + (_e585.member_1.member_8.z * _e605)));
                            let _e656 = params.member.member.member_1[0u];
                            let _e658 = (((((_e585.member_1.member_4.x + (_e585.member_1.member_7.x * _e604)) + (_e585.member_1.member_8.x * _e605)) * _e650) / _e656) + 0.5f);
                            let _e664 = params.member.member.member_1[1u];
                            let _e666 = (0.5f - ((((_e585.member_1.member_4.y + (_e585.member_1.member_7.y * _e604)) + (_e585.member_1.member_8.y * _e605)) * _e650) / _e664));
                            let _e671 = (select(0f, select(1f, _e658, (_e658 < 1f)), (_e658 > 0f)) * _e320);
                            if (_e671 > 0f) {
                                let _e677 = select(select(u32(_e671), 0u, (_e671 < 0f)), 4294967295u, (_e671 > 4294967000f));
                                let _e678 = (_e325 - 1u);
                                phi_1116_ = select(_e677, _e678, (_e678 < _e677));
                            } else {
                                phi_1116_ = 0u;
                            }
                            let _e682 = phi_1116_;
                            let _e687 = (select(0f, select(1f, _e666, (_e666 < 1f)), (_e666 > 0f)) * _e330);
                            if (_e687 > 0f) {
                                let _e693 = select(select(u32(_e687), 0u, (_e687 < 0f)), 4294967295u, (_e687 > 4294967000f));
                                let _e694 = (_e335 - 1u);
                                phi_1147_ = select(_e693, _e694, (_e694 < _e693));
                            } else {
                                phi_1147_ = 0u;
                            }
                            let _e698 = phi_1147_;
                            let _e707 = ((_e698 * _e325) + _e682);
                            if (_e707 < _e302) {
                            } else {
                                phi_1434_ = true;
                                break;
                            }
                            let _e710 = depth.member[_e707];
                            let _e722 = select(_e374, _e710, select(false, (_e710 < _e374), (_e710 > 0f)));
                            let _e743 = ((((((((((f32(_e682) + 0.5f) * (1f / _e320)) * 2f) - 1f) * _e722) * _e656) - _e585.member_1.member_4.x) * _e585.member_1.member_6.x) + ((((((((f32(_e698) + 0.5f) * (1f / _e330)) * -2f) + 1f) * _e722) * _e664) - _e585.member_1.member_4.y) * _e585.member_1.member_6.y)) + ((-(_e722) - _e585.member_1.member_4.z) * _e585.member_1.member_6.z));
                            let _e748 = params.member.member_3;
                            if (_e622 != _e622) {
                                phi_1414_ = true;
                            } else {
                                phi_1414_ = (_e743 >= _e622);
                            }
                            let _e753 = phi_1414_;
                            let _e755 = (_e608 - select(_e622, _e743, _e753));
                            if (_e755 != _e755) {
                                phi_1429_ = true;
                            } else {
                                phi_1429_ = (0f >= _e755);
                            }
                            let _e759 = phi_1429_;
                            let _e764 = ((_e743 - (_e585.member_1.member_2 * (1f + _e748))) * (1f / _e608));
                            phi_909_ = (_e591 + 1u);
                            phi_912_ = (_e593 + select(0f, select(((select(_e755, 0f, _e759) + (select(0f, select(1f, _e764, (_e764 < 1f)), (_e764 > 0f)) * _e623)) * (0.5f / _e608)), (_e623 / (_e608 * 2f)), select(false, (_e698 == _e585.member_1.member.y), (_e682 == _e585.member_1.member.x))), (_e623 > (_e608 * 0.2f))));
                        } else {
                            phi_909_ = u32();
                            phi_912_ = f32();
                        }
                        let _e778 = phi_909_;
                        let _e780 = phi_912_;
                        continue;
                        continuing {
                            phi_908_ = _e778;
                            phi_911_ = _e780;
                            phi_1434_ = false;
                            break if !(_e594);
                        }
                    }
                    let _e783 = phi_1434_;
                    if _e783 {
                        break;
                    }
                    let _e785 = local_4;
                    let _e786 = (0.25f * _e785);
                    let _e793 = params.member.member_2;
                    phi_1316_ = pow(select(0f, select(1f, _e786, (_e786 < 1f)), (_e786 > 0f)), _e793);
                } else {
                    phi_1316_ = 1f;
                }
                let _e796 = phi_1316_;
                if (_e367 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e367] = _e796;
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
