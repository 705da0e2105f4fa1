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
    var local_4: array<array<array<f32, 2>, 4>, 4>;
    var phi_593_: bool;
    var phi_595_: bool;
    var phi_596_: bool;
    var phi_597_: bool;
    var phi_598_: bool;
    var phi_1488_: bool;
    var phi_1503_: bool;
    var phi_1464_: vec2<f32>;
    var phi_1518_: bool;
    var phi_883_: type_35;
    var phi_892_: u32;
    var phi_895_: f32;
    var phi_1100_: u32;
    var phi_1131_: u32;
    var phi_1533_: bool;
    var phi_1548_: bool;
    var phi_893_: u32;
    var phi_896_: f32;
    var phi_1562_: bool;
    var local_5: f32;
    var phi_1300_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e300 = id_1;
            let _e303 = arrayLength((&depth.member));
            let _e314 = params.member.member.member_4;
            let _e315 = (_e300.x + _e314);
            let _e316 = (_e300.y + _e314);
            let _e321 = params.member.member.member[0u];
            let _e326 = select(select(u32(_e321), 0u, (_e321 < 0f)), 4294967295u, (_e321 > 4294967000f));
            let _e331 = params.member.member.member[1u];
            let _e336 = select(select(u32(_e331), 0u, (_e331 < 0f)), 4294967295u, (_e331 > 4294967000f));
            if (_e315 >= _e314) {
                if (_e316 >= _e314) {
                    let _e340 = ((_e315 + _e314) < _e326);
                    if _e340 {
                        phi_593_ = ((_e316 + _e314) < _e336);
                    } else {
                        phi_593_ = bool();
                    }
                    let _e344 = phi_593_;
                    phi_595_ = _e344;
                    phi_596_ = select(true, false, _e340);
                } else {
                    phi_595_ = bool();
                    phi_596_ = true;
                }
                let _e347 = phi_595_;
                let _e349 = phi_596_;
                phi_597_ = _e347;
                phi_598_ = _e349;
            } else {
                phi_597_ = bool();
                phi_598_ = true;
            }
            let _e351 = phi_597_;
            let _e353 = phi_598_;
            if select(_e351, false, _e353) {
                let _e357 = params.member.member_1;
                let _e360 = params.member.member_4;
                let _e363 = ((f32(_e315) + 0.5f) / _e321);
                let _e366 = ((f32(_e316) + 0.5f) / _e331);
                let _e368 = ((_e316 * _e326) + _e315);
                if (_e368 < _e303) {
                } else {
                    break;
                }
                let _e371 = depth.member[_e368];
                let _e376 = params.member.member.member_1[0u];
                let _e381 = params.member.member.member_1[1u];
                let _e391 = ((((_e357 * _e321) / (_e371 * (2f * _e376))) + ((_e357 * _e331) / (_e371 * (2f * _e381)))) * 0.5f);
                let _e392 = (_e391 > _e360);
                let _e396 = select(_e391, _e360, _e392);
                let _e400 = params.member.member.member_3;
                let _e412 = ((((_e363 * 2f) - 1f) * _e371) * _e376);
                let _e414 = ((((_e366 * -2f) + 1f) * _e371) * _e381);
                let _e415 = -(_e371);
                if (_e368 < arrayLength((&normals.member))) {
                } else {
                    break;
                }
                let _e419 = normals.member[_e368];
                let _e427 = (f32((bitcast<i32>(((_e419 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e427 != _e427) {
                    phi_1488_ = true;
                } else {
                    phi_1488_ = (-1f >= _e427);
                }
                let _e431 = phi_1488_;
                let _e432 = select(_e427, -1f, _e431);
                let _e442 = (f32((bitcast<i32>((((_e419 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e442 != _e442) {
                    phi_1503_ = true;
                } else {
                    phi_1503_ = (-1f >= _e442);
                }
                let _e446 = phi_1503_;
                let _e447 = select(_e442, -1f, _e446);
                let _e450 = (1f - abs(_e432));
                let _e451 = abs(_e447);
                let _e452 = (_e450 - _e451);
                if (_e452 < 0f) {
                    phi_1464_ = vec2<f32>(((1f - _e451) * select(1f, -1f, (_e432 < 0f))), (_e450 * select(1f, -1f, (_e447 < 0f))));
                } else {
                    phi_1464_ = vec2<f32>(_e432, _e447);
                }
                let _e463 = phi_1464_;
                let _e472 = (1f / sqrt((((_e463.x * _e463.x) + (_e463.y * _e463.y)) + (_e452 * _e452))));
                let _e473 = (_e463.x * _e472);
                let _e474 = (_e463.y * _e472);
                let _e475 = (_e452 * _e472);
                let _e481 = ((((_e412 * _e473) + (_e414 * _e474)) + (_e415 * _e475)) > 0f);
                let _e485 = select(_e473, -(_e473), _e481);
                let _e486 = select(_e474, -(_e474), _e481);
                let _e487 = select(_e475, -(_e475), _e481);
                local_4 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e489 = (_e316 % 4u);
                let _e490 = (_e489 < 4u);
                if _e490 {
                } else {
                    break;
                }
                let _e491 = (_e315 % 4u);
                let _e492 = (_e491 < 4u);
                if _e492 {
                } else {
                    break;
                }
                let _e495 = local_4[_e489][_e491];
                local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                if _e490 {
                } else {
                    break;
                }
                if _e492 {
                } else {
                    break;
                }
                let _e499 = local_3[_e489][_e491];
                let _e508 = sqrt((((_e412 * _e412) + (_e414 * _e414)) + (_e415 * _e415)));
                let _e509 = (-(_e412) / _e508);
                let _e510 = (-(_e414) / _e508);
                let _e511 = (_e371 / _e508);
                let _e514 = -((_e499[1] * _e511));
                let _e515 = (_e511 * _e495[0]);
                let _e518 = ((_e509 * _e499[1]) - (_e495[0] * _e510));
                let _e525 = (1f / sqrt((((_e514 * _e514) + (_e515 * _e515)) + (_e518 * _e518))));
                let _e526 = (_e514 * _e525);
                let _e527 = (_e515 * _e525);
                let _e528 = (_e518 * _e525);
                let _e532 = ((_e527 * _e511) - (_e510 * _e528));
                let _e535 = ((_e528 * _e509) - (_e511 * _e526));
                let _e538 = ((_e526 * _e510) - (_e509 * _e527));
                let _e554 = (((_e485 * _e509) + (_e486 * _e510)) + (_e487 * _e511));
                let _e558 = abs(_e554);
                if (_e558 != _e558) {
                    phi_1518_ = true;
                } else {
                    phi_1518_ = (0.0001f >= _e558);
                }
                let _e562 = phi_1518_;
                if select(false, !((_e396 < 0.5f)), select(false, (_e371 < _e400), (_e371 > 0f))) {
                    phi_883_ = type_35(1u, type_34(vec2<u32>(_e315, _e316), vec2<f32>(_e363, _e366), select(_e357, ((_e357 * _e360) / _e391), _e392), _e396, vec3<f32>(_e412, _e414, _e415), vec3<f32>(_e485, _e486, _e487), vec3<f32>(_e509, _e510, _e511), vec3<f32>(_e532, _e535, _e538), vec3<f32>(_e526, _e527, _e528), vec3<f32>((((_e485 * _e532) + (_e486 * _e535)) + (_e487 * _e538)), (((_e485 * _e526) + (_e486 * _e527)) + (_e487 * _e528)), _e554), (1f / (select(1f, -1f, (_e554 < 0f)) * select(_e558, 0.0001f, _e562)))));
                } else {
                    phi_883_ = type_35(0u, type_35().member_1);
                }
                let _e574 = phi_883_;
                if (bitcast<i32>(_e574.member) != 0i) {
                    phi_892_ = 0u;
                    phi_895_ = 0f;
                    loop {
                        let _e580 = phi_892_;
                        let _e582 = phi_895_;
                        local_5 = _e582;
                        let _e583 = (_e580 < 8u);
                        if _e583 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e584 = (_e580 < 56u);
                            if _e584 {
                            } else {
                                phi_1562_ = true;
                                break;
                            }
                            let _e586 = local[_e580];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e584 {
                            } else {
                                phi_1562_ = true;
                                break;
                            }
                            let _e590 = local_1[_e580];
                            let _e592 = (_e574.member_1.member_2 * _e590);
                            let _e593 = (_e592 * _e586[0]);
                            let _e594 = (_e592 * _e586[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e584 {
                            } else {
                                phi_1562_ = true;
                                break;
                            }
                            let _e596 = local_2[_e580];
                            let _e597 = (_e574.member_1.member_2 * _e596);
                            let _e606 = (-(((_e593 * _e574.member_1.member_9.x) + (_e594 * _e574.member_1.member_9.y))) * _e574.member_1.member_10);
                            let _e607 = -(_e597);
                            let _e611 = select(_e607, select(_e597, _e606, (_e606 < _e597)), (_e606 > _e607));
                            let _e612 = (_e597 - _e611);
                            let _e639 = (-0.5f / ((_e574.member_1.member_4.z + (_e574.member_1.member_7.z * _e593)) + (_e574.member_1.member_8.z * _e594)));
                            let _e642 = (((((_e574.member_1.member_4.x + (_e574.member_1.member_7.x * _e593)) + (_e574.member_1.member_8.x * _e594)) * _e639) / _e376) + 0.5f);
                            let _e645 = (0.5f - ((((_e574.member_1.member_4.y + (_e574.member_1.member_7.y * _e593)) + (_e574.member_1.member_8.y * _e594)) * _e639) / _e381));
                            let _e650 = (select(0f, select(1f, _e642, (_e642 < 1f)), (_e642 > 0f)) * _e321);
                            if (_e650 > 0f) {
                                let _e656 = select(select(u32(_e650), 0u, (_e650 < 0f)), 4294967295u, (_e650 > 4294967000f));
                                let _e657 = (_e326 - 1u);
                                phi_1100_ = select(_e656, _e657, (_e657 < _e656));
                            } else {
                                phi_1100_ = 0u;
                            }
                            let _e661 = phi_1100_;
                            let _e666 = (select(0f, select(1f, _e645, (_e645 < 1f)), (_e645 > 0f)) * _e331);
                            if (_e666 > 0f) {
                                let _e672 = select(select(u32(_e666), 0u, (_e666 < 0f)), 4294967295u, (_e666 > 4294967000f));
                                let _e673 = (_e336 - 1u);
                                phi_1131_ = select(_e672, _e673, (_e673 < _e672));
                            } else {
                                phi_1131_ = 0u;
                            }
                            let _e677 = phi_1131_;
                            let _e686 = ((_e677 * _e326) + _e661);
                            if (_e686 < _e303) {
                            } else {
                                phi_1562_ = true;
                                break;
                            }
                            let _e689 = depth.member[_e686];
                            let _e701 = select(_e400, _e689, select(false, (_e689 < _e400), (_e689 > 0f)));
                            let _e722 = ((((((((((f32(_e661) + 0.5f) * (1f / _e321)) * 2f) - 1f) * _e701) * _e376) - _e574.member_1.member_4.x) * _e574.member_1.member_6.x) + ((((((((f32(_e677) + 0.5f) * (1f / _e331)) * -2f) + 1f) * _e701) * _e381) - _e574.member_1.member_4.y) * _e574.member_1.member_6.y)) + ((-(_e701) - _e574.member_1.member_4.z) * _e574.member_1.member_6.z));
                            let _e727 = params.member.member_3;
                            if (_e611 != _e611) {
                                phi_1533_ = true;
                            } else {
                                phi_1533_ = (_e722 >= _e611);
                            }
                            let _e732 = phi_1533_;
                            let _e734 = (_e597 - select(_e611, _e722, _e732));
                            if (_e734 != _e734) {
                                phi_1548_ = true;
                            } else {
                                phi_1548_ = (0f >= _e734);
                            }
                            let _e738 = phi_1548_;
                            let _e743 = ((_e722 - (_e574.member_1.member_2 * (1f + _e727))) * (1f / _e597));
                            phi_893_ = (_e580 + 1u);
                            phi_896_ = (_e582 + select(0f, select(((select(_e734, 0f, _e738) + (select(0f, select(1f, _e743, (_e743 < 1f)), (_e743 > 0f)) * _e612)) * (0.5f / _e597)), (_e612 / (_e597 * 2f)), select(false, (_e677 == _e574.member_1.member.y), (_e661 == _e574.member_1.member.x))), (_e612 > (_e597 * 0.2f))));
                        } else {
                            phi_893_ = u32();
                            phi_896_ = f32();
                        }
                        let _e757 = phi_893_;
                        let _e759 = phi_896_;
                        continue;
                        continuing {
                            phi_892_ = _e757;
                            phi_895_ = _e759;
                            phi_1562_ = false;
                            break if !(_e583);
                        }
                    }
                    let _e762 = phi_1562_;
                    if _e762 {
                        break;
                    }
                    let _e764 = local_5;
                    let _e765 = (0.25f * _e764);
                    let _e772 = params.member.member_2;
                    phi_1300_ = pow(select(0f, select(1f, _e765, (_e765 < 1f)), (_e765 > 0f)), _e772);
                } else {
                    phi_1300_ = 1f;
                }
                let _e775 = phi_1300_;
                if (_e368 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e368] = _e775;
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
