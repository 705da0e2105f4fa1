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

struct type_34 {
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

struct type_35 {
    member: u32,
    member_1: type_34,
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
    var phi_591_: bool;
    var phi_593_: bool;
    var phi_594_: bool;
    var phi_595_: bool;
    var phi_596_: bool;
    var phi_1453_: bool;
    var phi_1468_: bool;
    var phi_1429_: vec2<f32>;
    var phi_871_: type_35;
    var phi_880_: u32;
    var phi_883_: f32;
    var phi_881_: u32;
    var phi_884_: f32;
    var phi_1482_: bool;
    var local_4: f32;
    var phi_1284_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e299 = id_1;
            let _e307 = params.member.member.member_4;
            let _e308 = (_e299.x + _e307);
            let _e309 = (_e299.y + _e307);
            let _e314 = params.member.member.member[0u];
            let _e319 = select(select(u32(_e314), 0u, (_e314 < 0f)), 4294967295u, (_e314 > 4294967000f));
            let _e324 = params.member.member.member[1u];
            let _e329 = select(select(u32(_e324), 0u, (_e324 < 0f)), 4294967295u, (_e324 > 4294967000f));
            if (_e308 >= _e307) {
                if (_e309 >= _e307) {
                    let _e333 = ((_e308 + _e307) < _e319);
                    if _e333 {
                        phi_591_ = ((_e309 + _e307) < _e329);
                    } else {
                        phi_591_ = bool();
                    }
                    let _e337 = phi_591_;
                    phi_593_ = _e337;
                    phi_594_ = select(true, false, _e333);
                } else {
                    phi_593_ = bool();
                    phi_594_ = true;
                }
                let _e340 = phi_593_;
                let _e342 = phi_594_;
                phi_595_ = _e340;
                phi_596_ = _e342;
            } else {
                phi_595_ = bool();
                phi_596_ = true;
            }
            let _e344 = phi_595_;
            let _e346 = phi_596_;
            if select(_e344, false, _e346) {
                let _e349 = ((_e309 * _e319) + _e308);
                let _e352 = params.member.member_1;
                let _e355 = params.member.member_4;
                let _e358 = ((f32(_e308) + 0.5f) / _e314);
                let _e361 = ((f32(_e309) + 0.5f) / _e324);
                let _e363 = depth.member[_e349];
                let _e368 = params.member.member.member_1[0u];
                let _e373 = params.member.member.member_1[1u];
                let _e383 = ((((_e352 * _e314) / (_e363 * (2f * _e368))) + ((_e352 * _e324) / (_e363 * (2f * _e373)))) * 0.5f);
                let _e384 = (_e383 > _e355);
                let _e388 = select(_e383, _e355, _e384);
                let _e392 = params.member.member.member_3;
                let _e404 = ((((_e358 * 2f) - 1f) * _e363) * _e368);
                let _e406 = ((((_e361 * -2f) + 1f) * _e363) * _e373);
                let _e407 = -(_e363);
                let _e410 = normals.member[_e349];
                let _e418 = (f32((bitcast<i32>(((_e410 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e418 != _e418) {
                    phi_1453_ = true;
                } else {
                    phi_1453_ = (-1f >= _e418);
                }
                let _e422 = phi_1453_;
                let _e423 = select(_e418, -1f, _e422);
                let _e433 = (f32((bitcast<i32>((((_e410 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e433 != _e433) {
                    phi_1468_ = true;
                } else {
                    phi_1468_ = (-1f >= _e433);
                }
                let _e437 = phi_1468_;
                let _e438 = select(_e433, -1f, _e437);
                let _e441 = (1f - abs(_e423));
                let _e442 = abs(_e438);
                let _e443 = (_e441 - _e442);
                if (_e443 < 0f) {
                    phi_1429_ = vec2<f32>(((1f - _e442) * select(1f, -1f, (_e423 < 0f))), (_e441 * select(1f, -1f, (_e438 < 0f))));
                } else {
                    phi_1429_ = vec2<f32>(_e423, _e438);
                }
                let _e454 = phi_1429_;
                let _e463 = (1f / sqrt((((_e454.x * _e454.x) + (_e454.y * _e454.y)) + (_e443 * _e443))));
                let _e464 = (_e454.x * _e463);
                let _e465 = (_e454.y * _e463);
                let _e466 = (_e443 * _e463);
                let _e472 = ((((_e404 * _e464) + (_e406 * _e465)) + (_e407 * _e466)) > 0f);
                let _e476 = select(_e464, -(_e464), _e472);
                let _e477 = select(_e465, -(_e465), _e472);
                let _e478 = select(_e466, -(_e466), _e472);
                local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e480 = (_e309 % 4u);
                if (_e480 < 4u) {
                } else {
                    break;
                }
                let _e482 = (_e308 % 4u);
                if (_e482 < 4u) {
                } else {
                    break;
                }
                let _e486 = local_3[_e480][_e482];
                let _e496 = sqrt((((_e404 * _e404) + (_e406 * _e406)) + (_e407 * _e407)));
                let _e497 = (-(_e404) / _e496);
                let _e498 = (-(_e406) / _e496);
                let _e499 = (_e363 / _e496);
                let _e502 = -((_e486[1] * _e499));
                let _e503 = (_e499 * _e486[0]);
                let _e506 = ((_e497 * _e486[1]) - (_e486[0] * _e498));
                let _e513 = (1f / sqrt((((_e502 * _e502) + (_e503 * _e503)) + (_e506 * _e506))));
                let _e514 = (_e502 * _e513);
                let _e515 = (_e503 * _e513);
                let _e516 = (_e506 * _e513);
                let _e520 = ((_e515 * _e499) - (_e498 * _e516));
                let _e523 = ((_e516 * _e497) - (_e499 * _e514));
                let _e526 = ((_e514 * _e498) - (_e497 * _e515));
                let _e542 = (((_e476 * _e497) + (_e477 * _e498)) + (_e478 * _e499));
                let _e546 = abs(_e542);
                if select(false, !((_e388 < 0.5f)), select(false, (_e363 < _e392), (_e363 > 0f))) {
                    phi_871_ = type_35(1u, type_34(vec2<u32>(_e308, _e309), vec2<f32>(_e358, _e361), select(_e352, ((_e352 * _e355) / _e383), _e384), _e388, vec3<f32>(_e404, _e406, _e407), vec3<f32>(_e476, _e477, _e478), vec3<f32>(_e497, _e498, _e499), vec3<f32>(_e520, _e523, _e526), vec3<f32>(_e514, _e515, _e516), vec3<f32>((((_e476 * _e520) + (_e477 * _e523)) + (_e478 * _e526)), (((_e476 * _e514) + (_e477 * _e515)) + (_e478 * _e516)), _e542), (1f / (select(1f, -1f, (_e542 < 0f)) * select(0.0001f, _e546, ((_e546 > 0.0001f) || false))))));
                } else {
                    phi_871_ = type_35(0u, type_35().member_1);
                }
                let _e560 = phi_871_;
                if (bitcast<i32>(_e560.member) != 0i) {
                    phi_880_ = 0u;
                    phi_883_ = 0f;
                    loop {
                        let _e566 = phi_880_;
                        let _e568 = phi_883_;
                        local_4 = _e568;
                        let _e569 = (_e566 < 8u);
                        if _e569 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e570 = (_e566 < 56u);
                            if _e570 {
                            } else {
                                phi_1482_ = true;
                                break;
                            }
                            let _e572 = local[_e566];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e570 {
                            } else {
                                phi_1482_ = true;
                                break;
                            }
                            let _e576 = local_1[_e566];
                            let _e578 = (_e560.member_1.member_2 * _e576);
                            let _e579 = (_e578 * _e572[0]);
                            let _e580 = (_e578 * _e572[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e570 {
                            } else {
                                phi_1482_ = true;
                                break;
                            }
                            let _e582 = local_2[_e566];
                            let _e583 = (_e560.member_1.member_2 * _e582);
                            let _e592 = (-(((_e579 * _e560.member_1.member_9.x) + (_e580 * _e560.member_1.member_9.y))) * _e560.member_1.member_10);
                            let _e593 = -(_e583);
                            let _e597 = select(_e593, select(_e583, _e592, (_e592 < _e583)), (_e592 > _e593));
                            let _e598 = (_e583 - _e597);
                            let _e625 = (-0.5f / ((_e560.member_1.member_4.z + (_e560.member_1.member_7.z * _e579)) + (_e560.member_1.member_8.z * _e580)));
                            let _e628 = (((((_e560.member_1.member_4.x + (_e560.member_1.member_7.x * _e579)) + (_e560.member_1.member_8.x * _e580)) * _e625) / _e368) + 0.5f);
                            let _e631 = (0.5f - ((((_e560.member_1.member_4.y + (_e560.member_1.member_7.y * _e579)) + (_e560.member_1.member_8.y * _e580)) * _e625) / _e373));
                            let _e636 = (select(0f, select(1f, _e628, (_e628 < 1f)), (_e628 > 0f)) * _e314);
                            let _e638 = f32((_e319 - 1u));
                            let _e640 = select(0f, _e636, (_e636 > 0f));
                            let _e643 = u32(select(_e638, _e640, (_e640 < _e638)));
                            let _e648 = (select(0f, select(1f, _e631, (_e631 < 1f)), (_e631 > 0f)) * _e324);
                            let _e650 = f32((_e329 - 1u));
                            let _e652 = select(0f, _e648, (_e648 > 0f));
                            let _e655 = u32(select(_e650, _e652, (_e652 < _e650)));
                            let _e666 = depth.member[((_e655 * _e319) + _e643)];
                            let _e678 = select(_e392, _e666, select(false, (_e666 < _e392), (_e666 > 0f)));
                            let _e699 = ((((((((((f32(_e643) + 0.5f) * (1f / _e314)) * 2f) - 1f) * _e678) * _e368) - _e560.member_1.member_4.x) * _e560.member_1.member_6.x) + ((((((((f32(_e655) + 0.5f) * (1f / _e324)) * -2f) + 1f) * _e678) * _e373) - _e560.member_1.member_4.y) * _e560.member_1.member_6.y)) + ((-(_e678) - _e560.member_1.member_4.z) * _e560.member_1.member_6.z));
                            let _e704 = params.member.member_3;
                            let _e710 = (_e583 - select(_e699, _e597, ((_e597 > _e699) || (_e699 != _e699))));
                            let _e717 = ((_e699 - (_e560.member_1.member_2 * (1f + _e704))) * (1f / _e583));
                            phi_881_ = (_e566 + 1u);
                            phi_884_ = (_e568 + select(0f, select(((select(0f, _e710, ((_e710 > 0f) || false)) + (select(0f, select(1f, _e717, (_e717 < 1f)), (_e717 > 0f)) * _e598)) * (0.5f / _e583)), (_e598 / (_e583 * 2f)), select(false, (_e655 == _e560.member_1.member.y), (_e643 == _e560.member_1.member.x))), (_e598 > (_e583 * 0.2f))));
                        } else {
                            phi_881_ = u32();
                            phi_884_ = f32();
                        }
                        let _e731 = phi_881_;
                        let _e733 = phi_884_;
                        continue;
                        continuing {
                            phi_880_ = _e731;
                            phi_883_ = _e733;
                            phi_1482_ = false;
                            break if !(_e569);
                        }
                    }
                    let _e736 = phi_1482_;
                    if _e736 {
                        break;
                    }
                    let _e738 = local_4;
                    let _e739 = (0.25f * _e738);
                    let _e746 = params.member.member_2;
                    phi_1284_ = pow(select(0f, select(1f, _e739, (_e739 < 1f)), (_e739 > 0f)), _e746);
                } else {
                    phi_1284_ = 1f;
                }
                let _e749 = phi_1284_;
                ao.member[_e349] = _e749;
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
