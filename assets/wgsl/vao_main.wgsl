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
    var phi_1469_: bool;
    var phi_1484_: bool;
    var phi_1445_: vec2<f32>;
    var phi_1499_: bool;
    var phi_864_: type_35;
    var phi_873_: u32;
    var phi_876_: f32;
    var phi_1081_: u32;
    var phi_1112_: u32;
    var phi_1514_: bool;
    var phi_1529_: bool;
    var phi_874_: u32;
    var phi_877_: f32;
    var phi_1543_: bool;
    var local_4: f32;
    var phi_1281_: f32;

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
                        phi_592_ = ((_e315 + _e313) < _e335);
                    } else {
                        phi_592_ = bool();
                    }
                    let _e343 = phi_592_;
                    phi_594_ = _e343;
                    phi_595_ = select(true, false, _e339);
                } else {
                    phi_594_ = bool();
                    phi_595_ = true;
                }
                let _e346 = phi_594_;
                let _e348 = phi_595_;
                phi_596_ = _e346;
                phi_597_ = _e348;
            } else {
                phi_596_ = bool();
                phi_597_ = true;
            }
            let _e350 = phi_596_;
            let _e352 = phi_597_;
            if select(_e350, false, _e352) {
                let _e356 = params.member.member_1;
                let _e359 = params.member.member_4;
                let _e362 = ((f32(_e314) + 0.5f) / _e320);
                let _e365 = ((f32(_e315) + 0.5f) / _e330);
                let _e367 = ((_e315 * _e325) + _e314);
                if (_e367 < _e302) {
                } else {
                    break;
                }
                let _e370 = depth.member[_e367];
                let _e375 = params.member.member.member_1[0u];
                let _e380 = params.member.member.member_1[1u];
                let _e390 = ((((_e356 * _e320) / (_e370 * (2f * _e375))) + ((_e356 * _e330) / (_e370 * (2f * _e380)))) * 0.5f);
                let _e391 = (_e390 > _e359);
                let _e395 = select(_e390, _e359, _e391);
                let _e399 = params.member.member.member_3;
                let _e411 = ((((_e362 * 2f) - 1f) * _e370) * _e375);
                let _e413 = ((((_e365 * -2f) + 1f) * _e370) * _e380);
                let _e414 = -(_e370);
                if (_e367 < arrayLength((&normals.member))) {
                } else {
                    break;
                }
                let _e418 = normals.member[_e367];
                let _e426 = (f32((bitcast<i32>(((_e418 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e426 != _e426) {
                    phi_1469_ = true;
                } else {
                    phi_1469_ = (-1f >= _e426);
                }
                let _e430 = phi_1469_;
                let _e431 = select(_e426, -1f, _e430);
                let _e441 = (f32((bitcast<i32>((((_e418 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e441 != _e441) {
                    phi_1484_ = true;
                } else {
                    phi_1484_ = (-1f >= _e441);
                }
                let _e445 = phi_1484_;
                let _e446 = select(_e441, -1f, _e445);
                let _e449 = (1f - abs(_e431));
                let _e450 = abs(_e446);
                let _e451 = (_e449 - _e450);
                if (_e451 < 0f) {
                    phi_1445_ = vec2<f32>(((1f - _e450) * select(1f, -1f, (_e431 < 0f))), (_e449 * select(1f, -1f, (_e446 < 0f))));
                } else {
                    phi_1445_ = vec2<f32>(_e431, _e446);
                }
                let _e462 = phi_1445_;
                let _e471 = (1f / sqrt((((_e462.x * _e462.x) + (_e462.y * _e462.y)) + (_e451 * _e451))));
                let _e472 = (_e462.x * _e471);
                let _e473 = (_e462.y * _e471);
                let _e474 = (_e451 * _e471);
                let _e480 = ((((_e411 * _e472) + (_e413 * _e473)) + (_e414 * _e474)) > 0f);
                let _e484 = select(_e472, -(_e472), _e480);
                let _e485 = select(_e473, -(_e473), _e480);
                let _e486 = select(_e474, -(_e474), _e480);
                local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e488 = (_e315 % 4u);
                if (_e488 < 4u) {
                } else {
                    break;
                }
                let _e490 = (_e314 % 4u);
                if (_e490 < 4u) {
                } else {
                    break;
                }
                let _e494 = local_3[_e488][_e490];
                let _e504 = sqrt((((_e411 * _e411) + (_e413 * _e413)) + (_e414 * _e414)));
                let _e505 = (-(_e411) / _e504);
                let _e506 = (-(_e413) / _e504);
                let _e507 = (_e370 / _e504);
                let _e510 = -((_e494[1] * _e507));
                let _e511 = (_e507 * _e494[0]);
                let _e514 = ((_e505 * _e494[1]) - (_e494[0] * _e506));
                let _e521 = (1f / sqrt((((_e510 * _e510) + (_e511 * _e511)) + (_e514 * _e514))));
                let _e522 = (_e510 * _e521);
                let _e523 = (_e511 * _e521);
                let _e524 = (_e514 * _e521);
                let _e528 = ((_e523 * _e507) - (_e506 * _e524));
                let _e531 = ((_e524 * _e505) - (_e507 * _e522));
                let _e534 = ((_e522 * _e506) - (_e505 * _e523));
                let _e550 = (((_e484 * _e505) + (_e485 * _e506)) + (_e486 * _e507));
                let _e554 = abs(_e550);
                if (_e554 != _e554) {
                    phi_1499_ = true;
                } else {
                    phi_1499_ = (0.0001f >= _e554);
                }
                let _e558 = phi_1499_;
                if select(false, !((_e395 < 0.5f)), select(false, (_e370 < _e399), (_e370 > 0f))) {
                    phi_864_ = type_35(1u, type_34(vec2<u32>(_e314, _e315), vec2<f32>(_e362, _e365), select(_e356, ((_e356 * _e359) / _e390), _e391), _e395, vec3<f32>(_e411, _e413, _e414), vec3<f32>(_e484, _e485, _e486), vec3<f32>(_e505, _e506, _e507), vec3<f32>(_e528, _e531, _e534), vec3<f32>(_e522, _e523, _e524), vec3<f32>((((_e484 * _e528) + (_e485 * _e531)) + (_e486 * _e534)), (((_e484 * _e522) + (_e485 * _e523)) + (_e486 * _e524)), _e550), (1f / (select(1f, -1f, (_e550 < 0f)) * select(_e554, 0.0001f, _e558)))));
                } else {
                    phi_864_ = type_35(0u, type_35().member_1);
                }
                let _e570 = phi_864_;
                if (bitcast<i32>(_e570.member) != 0i) {
                    phi_873_ = 0u;
                    phi_876_ = 0f;
                    loop {
                        let _e576 = phi_873_;
                        let _e578 = phi_876_;
                        local_4 = _e578;
                        let _e579 = (_e576 < 8u);
                        if _e579 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e580 = (_e576 < 56u);
                            if _e580 {
                            } else {
                                phi_1543_ = true;
                                break;
                            }
                            let _e582 = local[_e576];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e580 {
                            } else {
                                phi_1543_ = true;
                                break;
                            }
                            let _e586 = local_1[_e576];
                            let _e588 = (_e570.member_1.member_2 * _e586);
                            let _e589 = (_e588 * _e582[0]);
                            let _e590 = (_e588 * _e582[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e580 {
                            } else {
                                phi_1543_ = true;
                                break;
                            }
                            let _e592 = local_2[_e576];
                            let _e593 = (_e570.member_1.member_2 * _e592);
                            let _e602 = (-(((_e589 * _e570.member_1.member_9.x) + (_e590 * _e570.member_1.member_9.y))) * _e570.member_1.member_10);
                            let _e603 = -(_e593);
                            let _e607 = select(_e603, select(_e593, _e602, (_e602 < _e593)), (_e602 > _e603));
                            let _e608 = (_e593 - _e607);
                            let _e635 = (-0.5f / ((_e570.member_1.member_4.z + (_e570.member_1.member_7.z * _e589)) + (_e570.member_1.member_8.z * _e590)));
                            let _e638 = (((((_e570.member_1.member_4.x + (_e570.member_1.member_7.x * _e589)) + (_e570.member_1.member_8.x * _e590)) * _e635) / _e375) + 0.5f);
                            let _e641 = (0.5f - ((((_e570.member_1.member_4.y + (_e570.member_1.member_7.y * _e589)) + (_e570.member_1.member_8.y * _e590)) * _e635) / _e380));
                            let _e646 = (select(0f, select(1f, _e638, (_e638 < 1f)), (_e638 > 0f)) * _e320);
                            if (_e646 > 0f) {
                                let _e652 = select(select(u32(_e646), 0u, (_e646 < 0f)), 4294967295u, (_e646 > 4294967000f));
                                let _e653 = (_e325 - 1u);
                                phi_1081_ = select(_e652, _e653, (_e653 < _e652));
                            } else {
                                phi_1081_ = 0u;
                            }
                            let _e657 = phi_1081_;
                            let _e662 = (select(0f, select(1f, _e641, (_e641 < 1f)), (_e641 > 0f)) * _e330);
                            if (_e662 > 0f) {
                                let _e668 = select(select(u32(_e662), 0u, (_e662 < 0f)), 4294967295u, (_e662 > 4294967000f));
                                let _e669 = (_e335 - 1u);
                                phi_1112_ = select(_e668, _e669, (_e669 < _e668));
                            } else {
                                phi_1112_ = 0u;
                            }
                            let _e673 = phi_1112_;
                            let _e682 = ((_e673 * _e325) + _e657);
                            if (_e682 < _e302) {
                            } else {
                                phi_1543_ = true;
                                break;
                            }
                            let _e685 = depth.member[_e682];
                            let _e697 = select(_e399, _e685, select(false, (_e685 < _e399), (_e685 > 0f)));
                            let _e718 = ((((((((((f32(_e657) + 0.5f) * (1f / _e320)) * 2f) - 1f) * _e697) * _e375) - _e570.member_1.member_4.x) * _e570.member_1.member_6.x) + ((((((((f32(_e673) + 0.5f) * (1f / _e330)) * -2f) + 1f) * _e697) * _e380) - _e570.member_1.member_4.y) * _e570.member_1.member_6.y)) + ((-(_e697) - _e570.member_1.member_4.z) * _e570.member_1.member_6.z));
                            let _e723 = params.member.member_3;
                            if (_e607 != _e607) {
                                phi_1514_ = true;
                            } else {
                                phi_1514_ = (_e718 >= _e607);
                            }
                            let _e728 = phi_1514_;
                            let _e730 = (_e593 - select(_e607, _e718, _e728));
                            if (_e730 != _e730) {
                                phi_1529_ = true;
                            } else {
                                phi_1529_ = (0f >= _e730);
                            }
                            let _e734 = phi_1529_;
                            let _e739 = ((_e718 - (_e570.member_1.member_2 * (1f + _e723))) * (1f / _e593));
                            phi_874_ = (_e576 + 1u);
                            phi_877_ = (_e578 + select(0f, select(((select(_e730, 0f, _e734) + (select(0f, select(1f, _e739, (_e739 < 1f)), (_e739 > 0f)) * _e608)) * (0.5f / _e593)), (_e608 / (_e593 * 2f)), select(false, (_e673 == _e570.member_1.member.y), (_e657 == _e570.member_1.member.x))), (_e608 > (_e593 * 0.2f))));
                        } else {
                            phi_874_ = u32();
                            phi_877_ = f32();
                        }
                        let _e753 = phi_874_;
                        let _e755 = phi_877_;
                        continue;
                        continuing {
                            phi_873_ = _e753;
                            phi_876_ = _e755;
                            phi_1543_ = false;
                            break if !(_e579);
                        }
                    }
                    let _e758 = phi_1543_;
                    if _e758 {
                        break;
                    }
                    let _e760 = local_4;
                    let _e761 = (0.25f * _e760);
                    let _e768 = params.member.member_2;
                    phi_1281_ = pow(select(0f, select(1f, _e761, (_e761 < 1f)), (_e761 > 0f)), _e768);
                } else {
                    phi_1281_ = 1f;
                }
                let _e771 = phi_1281_;
                if (_e367 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e367] = _e771;
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
