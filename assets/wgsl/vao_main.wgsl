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
    var phi_592_: bool;
    var phi_594_: bool;
    var phi_595_: bool;
    var phi_596_: bool;
    var phi_597_: bool;
    var phi_1457_: bool;
    var phi_1472_: bool;
    var phi_1433_: vec2<f32>;
    var phi_1487_: bool;
    var phi_858_: type_35;
    var phi_867_: u32;
    var phi_870_: f32;
    var phi_1075_: u32;
    var phi_1106_: u32;
    var phi_1502_: bool;
    var phi_1517_: bool;
    var phi_868_: u32;
    var phi_871_: f32;
    var phi_1531_: bool;
    var local_4: f32;
    var phi_1269_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e299 = id_1;
            let _e311 = params.member.member.member_4;
            let _e312 = (_e299.x + _e311);
            let _e313 = (_e299.y + _e311);
            let _e318 = params.member.member.member[0u];
            let _e323 = select(select(u32(_e318), 0u, (_e318 < 0f)), 4294967295u, (_e318 > 4294967000f));
            let _e328 = params.member.member.member[1u];
            let _e333 = select(select(u32(_e328), 0u, (_e328 < 0f)), 4294967295u, (_e328 > 4294967000f));
            if (_e312 >= _e311) {
                if (_e313 >= _e311) {
                    let _e337 = ((_e312 + _e311) < _e323);
                    if _e337 {
                        phi_592_ = ((_e313 + _e311) < _e333);
                    } else {
                        phi_592_ = bool();
                    }
                    let _e341 = phi_592_;
                    phi_594_ = _e341;
                    phi_595_ = select(true, false, _e337);
                } else {
                    phi_594_ = bool();
                    phi_595_ = true;
                }
                let _e344 = phi_594_;
                let _e346 = phi_595_;
                phi_596_ = _e344;
                phi_597_ = _e346;
            } else {
                phi_596_ = bool();
                phi_597_ = true;
            }
            let _e348 = phi_596_;
            let _e350 = phi_597_;
            if select(_e348, false, _e350) {
                let _e354 = params.member.member_1;
                let _e357 = params.member.member_4;
                let _e360 = ((f32(_e312) + 0.5f) / _e318);
                let _e363 = ((f32(_e313) + 0.5f) / _e328);
                let _e365 = ((_e313 * _e323) + _e312);
                let _e367 = depth.member[_e365];
                let _e372 = params.member.member.member_1[0u];
                let _e377 = params.member.member.member_1[1u];
                let _e387 = ((((_e354 * _e318) / (_e367 * (2f * _e372))) + ((_e354 * _e328) / (_e367 * (2f * _e377)))) * 0.5f);
                let _e388 = (_e387 > _e357);
                let _e392 = select(_e387, _e357, _e388);
                let _e396 = params.member.member.member_3;
                let _e408 = ((((_e360 * 2f) - 1f) * _e367) * _e372);
                let _e410 = ((((_e363 * -2f) + 1f) * _e367) * _e377);
                let _e411 = -(_e367);
                if (_e365 < arrayLength((&normals.member))) {
                } else {
                    break;
                }
                let _e415 = normals.member[_e365];
                let _e423 = (f32((bitcast<i32>(((_e415 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e423 != _e423) {
                    phi_1457_ = true;
                } else {
                    phi_1457_ = (-1f >= _e423);
                }
                let _e427 = phi_1457_;
                let _e428 = select(_e423, -1f, _e427);
                let _e438 = (f32((bitcast<i32>((((_e415 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e438 != _e438) {
                    phi_1472_ = true;
                } else {
                    phi_1472_ = (-1f >= _e438);
                }
                let _e442 = phi_1472_;
                let _e443 = select(_e438, -1f, _e442);
                let _e446 = (1f - abs(_e428));
                let _e447 = abs(_e443);
                let _e448 = (_e446 - _e447);
                if (_e448 < 0f) {
                    phi_1433_ = vec2<f32>(((1f - _e447) * select(1f, -1f, (_e428 < 0f))), (_e446 * select(1f, -1f, (_e443 < 0f))));
                } else {
                    phi_1433_ = vec2<f32>(_e428, _e443);
                }
                let _e459 = phi_1433_;
                let _e468 = (1f / sqrt((((_e459.x * _e459.x) + (_e459.y * _e459.y)) + (_e448 * _e448))));
                let _e469 = (_e459.x * _e468);
                let _e470 = (_e459.y * _e468);
                let _e471 = (_e448 * _e468);
                let _e477 = ((((_e408 * _e469) + (_e410 * _e470)) + (_e411 * _e471)) > 0f);
                let _e481 = select(_e469, -(_e469), _e477);
                let _e482 = select(_e470, -(_e470), _e477);
                let _e483 = select(_e471, -(_e471), _e477);
                local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e485 = (_e313 % 4u);
                if (_e485 < 4u) {
                } else {
                    break;
                }
                let _e487 = (_e312 % 4u);
                if (_e487 < 4u) {
                } else {
                    break;
                }
                let _e491 = local_3[_e485][_e487];
                let _e501 = sqrt((((_e408 * _e408) + (_e410 * _e410)) + (_e411 * _e411)));
                let _e502 = (-(_e408) / _e501);
                let _e503 = (-(_e410) / _e501);
                let _e504 = (_e367 / _e501);
                let _e507 = -((_e491[1] * _e504));
                let _e508 = (_e504 * _e491[0]);
                let _e511 = ((_e502 * _e491[1]) - (_e491[0] * _e503));
                let _e518 = (1f / sqrt((((_e507 * _e507) + (_e508 * _e508)) + (_e511 * _e511))));
                let _e519 = (_e507 * _e518);
                let _e520 = (_e508 * _e518);
                let _e521 = (_e511 * _e518);
                let _e525 = ((_e520 * _e504) - (_e503 * _e521));
                let _e528 = ((_e521 * _e502) - (_e504 * _e519));
                let _e531 = ((_e519 * _e503) - (_e502 * _e520));
                let _e547 = (((_e481 * _e502) + (_e482 * _e503)) + (_e483 * _e504));
                let _e551 = abs(_e547);
                if (_e551 != _e551) {
                    phi_1487_ = true;
                } else {
                    phi_1487_ = (0.0001f >= _e551);
                }
                let _e555 = phi_1487_;
                if select(false, !((_e392 < 0.5f)), select(false, (_e367 < _e396), (_e367 > 0f))) {
                    phi_858_ = type_35(1u, type_34(vec2<u32>(_e312, _e313), vec2<f32>(_e360, _e363), select(_e354, ((_e354 * _e357) / _e387), _e388), _e392, vec3<f32>(_e408, _e410, _e411), vec3<f32>(_e481, _e482, _e483), vec3<f32>(_e502, _e503, _e504), vec3<f32>(_e525, _e528, _e531), vec3<f32>(_e519, _e520, _e521), vec3<f32>((((_e481 * _e525) + (_e482 * _e528)) + (_e483 * _e531)), (((_e481 * _e519) + (_e482 * _e520)) + (_e483 * _e521)), _e547), (1f / (select(1f, -1f, (_e547 < 0f)) * select(_e551, 0.0001f, _e555)))));
                } else {
                    phi_858_ = type_35(0u, type_35().member_1);
                }
                let _e567 = phi_858_;
                if (bitcast<i32>(_e567.member) != 0i) {
                    phi_867_ = 0u;
                    phi_870_ = 0f;
                    loop {
                        let _e573 = phi_867_;
                        let _e575 = phi_870_;
                        local_4 = _e575;
                        let _e576 = (_e573 < 8u);
                        if _e576 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e577 = (_e573 < 56u);
                            if _e577 {
                            } else {
                                phi_1531_ = true;
                                break;
                            }
                            let _e579 = local[_e573];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e577 {
                            } else {
                                phi_1531_ = true;
                                break;
                            }
                            let _e583 = local_1[_e573];
                            let _e585 = (_e567.member_1.member_2 * _e583);
                            let _e586 = (_e585 * _e579[0]);
                            let _e587 = (_e585 * _e579[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e577 {
                            } else {
                                phi_1531_ = true;
                                break;
                            }
                            let _e589 = local_2[_e573];
                            let _e590 = (_e567.member_1.member_2 * _e589);
                            let _e599 = (-(((_e586 * _e567.member_1.member_9.x) + (_e587 * _e567.member_1.member_9.y))) * _e567.member_1.member_10);
                            let _e600 = -(_e590);
                            let _e604 = select(_e600, select(_e590, _e599, (_e599 < _e590)), (_e599 > _e600));
                            let _e605 = (_e590 - _e604);
                            let _e632 = (-0.5f / ((_e567.member_1.member_4.z + (_e567.member_1.member_7.z * _e586)) + (_e567.member_1.member_8.z * _e587)));
                            let _e635 = (((((_e567.member_1.member_4.x + (_e567.member_1.member_7.x * _e586)) + (_e567.member_1.member_8.x * _e587)) * _e632) / _e372) + 0.5f);
                            let _e638 = (0.5f - ((((_e567.member_1.member_4.y + (_e567.member_1.member_7.y * _e586)) + (_e567.member_1.member_8.y * _e587)) * _e632) / _e377));
                            let _e643 = (select(0f, select(1f, _e635, (_e635 < 1f)), (_e635 > 0f)) * _e318);
                            if (_e643 > 0f) {
                                let _e649 = select(select(u32(_e643), 0u, (_e643 < 0f)), 4294967295u, (_e643 > 4294967000f));
                                let _e650 = (_e323 - 1u);
                                phi_1075_ = select(_e649, _e650, (_e650 < _e649));
                            } else {
                                phi_1075_ = 0u;
                            }
                            let _e654 = phi_1075_;
                            let _e659 = (select(0f, select(1f, _e638, (_e638 < 1f)), (_e638 > 0f)) * _e328);
                            if (_e659 > 0f) {
                                let _e665 = select(select(u32(_e659), 0u, (_e659 < 0f)), 4294967295u, (_e659 > 4294967000f));
                                let _e666 = (_e333 - 1u);
                                phi_1106_ = select(_e665, _e666, (_e666 < _e665));
                            } else {
                                phi_1106_ = 0u;
                            }
                            let _e670 = phi_1106_;
                            let _e681 = depth.member[((_e670 * _e323) + _e654)];
                            let _e693 = select(_e396, _e681, select(false, (_e681 < _e396), (_e681 > 0f)));
                            let _e714 = ((((((((((f32(_e654) + 0.5f) * (1f / _e318)) * 2f) - 1f) * _e693) * _e372) - _e567.member_1.member_4.x) * _e567.member_1.member_6.x) + ((((((((f32(_e670) + 0.5f) * (1f / _e328)) * -2f) + 1f) * _e693) * _e377) - _e567.member_1.member_4.y) * _e567.member_1.member_6.y)) + ((-(_e693) - _e567.member_1.member_4.z) * _e567.member_1.member_6.z));
                            let _e719 = params.member.member_3;
                            if (_e604 != _e604) {
                                phi_1502_ = true;
                            } else {
                                phi_1502_ = (_e714 >= _e604);
                            }
                            let _e724 = phi_1502_;
                            let _e726 = (_e590 - select(_e604, _e714, _e724));
                            if (_e726 != _e726) {
                                phi_1517_ = true;
                            } else {
                                phi_1517_ = (0f >= _e726);
                            }
                            let _e730 = phi_1517_;
                            let _e735 = ((_e714 - (_e567.member_1.member_2 * (1f + _e719))) * (1f / _e590));
                            phi_868_ = (_e573 + 1u);
                            phi_871_ = (_e575 + select(0f, select(((select(_e726, 0f, _e730) + (select(0f, select(1f, _e735, (_e735 < 1f)), (_e735 > 0f)) * _e605)) * (0.5f / _e590)), (_e605 / (_e590 * 2f)), select(false, (_e670 == _e567.member_1.member.y), (_e654 == _e567.member_1.member.x))), (_e605 > (_e590 * 0.2f))));
                        } else {
                            phi_868_ = u32();
                            phi_871_ = f32();
                        }
                        let _e749 = phi_868_;
                        let _e751 = phi_871_;
                        continue;
                        continuing {
                            phi_867_ = _e749;
                            phi_870_ = _e751;
                            phi_1531_ = false;
                            break if !(_e576);
                        }
                    }
                    let _e754 = phi_1531_;
                    if _e754 {
                        break;
                    }
                    let _e756 = local_4;
                    let _e757 = (0.25f * _e756);
                    let _e764 = params.member.member_2;
                    phi_1269_ = pow(select(0f, select(1f, _e757, (_e757 < 1f)), (_e757 > 0f)), _e764);
                } else {
                    phi_1269_ = 1f;
                }
                let _e767 = phi_1269_;
                if (_e365 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e365] = _e767;
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
