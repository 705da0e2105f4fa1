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

struct type_32 {
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

struct type_33 {
    member: u32,
    member_1: type_32,
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
    var phi_655_: bool;
    var phi_685_: f32;
    var phi_1407_: bool;
    var phi_1422_: bool;
    var phi_761_: vec2<f32>;
    var phi_788_: vec3<f32>;
    var phi_1437_: bool;
    var phi_900_: type_33;
    var phi_901_: type_33;
    var phi_903_: type_33;
    var phi_904_: type_33;
    var phi_905_: bool;
    var phi_909_: type_33;
    var phi_918_: u32;
    var phi_921_: f32;
    var phi_1111_: bool;
    var phi_1544_: bool;
    var phi_1559_: bool;
    var phi_919_: u32;
    var phi_922_: f32;
    var phi_1586_: bool;
    var local_4: f32;
    var phi_1260_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e299 = id_1;
            let _e302 = arrayLength((&depth.member));
            let _e313 = params.member.member.member_4;
            let _e314 = (_e299.x + _e313);
            let _e315 = (_e299.y + _e313);
            let _e322 = params.member.member.member[0u];
            let _e327 = select(select(u32(_e322), 0u, (_e322 < 0f)), 4294967295u, (_e322 > 4294967000f));
            let _e332 = params.member.member.member[1u];
            if (_e314 >= _e313) {
                if (_e315 >= _e313) {
                    let _e341 = ((_e314 + _e313) < _e327);
                    if _e341 {
                        phi_592_ = ((_e315 + _e313) < select(select(u32(_e332), 0u, (_e332 < 0f)), 4294967295u, (_e332 > 4294967000f)));
                    } else {
                        phi_592_ = bool();
                    }
                    let _e345 = phi_592_;
                    phi_594_ = _e345;
                    phi_595_ = select(true, false, _e341);
                } else {
                    phi_594_ = bool();
                    phi_595_ = true;
                }
                let _e348 = phi_594_;
                let _e350 = phi_595_;
                phi_596_ = _e348;
                phi_597_ = _e350;
            } else {
                phi_596_ = bool();
                phi_597_ = true;
            }
            let _e352 = phi_596_;
            let _e354 = phi_597_;
            if select(_e352, false, _e354) {
                let _e358 = params.member.member_1;
                let _e361 = params.member.member_4;
                let _e366 = ((f32(_e314) + 0.5f) / _e322);
                let _e367 = ((f32(_e315) + 0.5f) / _e332);
                let _e369 = ((_e315 * _e327) + _e314);
                if (_e369 < _e302) {
                } else {
                    break;
                }
                let _e372 = depth.member[_e369];
                let _e376 = params.member.member.member_3;
                if (_e372 > 0f) {
                    phi_655_ = (_e372 < _e376);
                } else {
                    phi_655_ = false;
                }
                let _e380 = phi_655_;
                if _e380 {
                    let _e388 = params.member.member.member_1[0u];
                    let _e393 = params.member.member.member_1[1u];
                    let _e403 = (0.5f * (((_e358 * _e322) / ((2f * _e388) * _e372)) + ((_e358 * _e332) / ((2f * _e393) * _e372))));
                    let _e404 = (_e403 > _e361);
                    if _e404 {
                        phi_685_ = ((_e358 * _e361) / _e403);
                    } else {
                        phi_685_ = _e358;
                    }
                    let _e408 = phi_685_;
                    let _e409 = select(_e403, _e361, _e404);
                    let _e410 = (_e409 < 0.5f);
                    if _e410 {
                        phi_900_ = type_33(0u, type_33().member_1);
                        phi_901_ = type_33();
                    } else {
                        let _e416 = ((((_e366 * 2f) - 1f) * _e372) * _e388);
                        let _e418 = ((((_e367 * -2f) + 1f) * _e372) * _e393);
                        let _e419 = -(_e372);
                        if (_e369 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e423 = normals.member[_e369];
                        let _e431 = (f32((bitcast<i32>(((_e423 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e431 != _e431) {
                            phi_1407_ = true;
                        } else {
                            phi_1407_ = (-1f >= _e431);
                        }
                        let _e435 = phi_1407_;
                        let _e436 = select(_e431, -1f, _e435);
                        let _e446 = (f32((bitcast<i32>((((_e423 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e446 != _e446) {
                            phi_1422_ = true;
                        } else {
                            phi_1422_ = (-1f >= _e446);
                        }
                        let _e450 = phi_1422_;
                        let _e451 = select(_e446, -1f, _e450);
                        let _e454 = (1f - abs(_e436));
                        let _e455 = abs(_e451);
                        let _e456 = (_e454 - _e455);
                        if (_e456 < 0f) {
                            phi_761_ = vec2<f32>(((1f - _e455) * select(1f, -1f, (_e436 < 0f))), (_e454 * select(1f, -1f, (_e451 < 0f))));
                        } else {
                            phi_761_ = vec2<f32>(_e436, _e451);
                        }
                        let _e467 = phi_761_;
                        let _e476 = (1f / sqrt((((_e467.x * _e467.x) + (_e467.y * _e467.y)) + (_e456 * _e456))));
                        let _e477 = (_e467.x * _e476);
                        let _e478 = (_e467.y * _e476);
                        let _e479 = (_e456 * _e476);
                        if ((((_e416 * _e477) + (_e418 * _e478)) + (_e419 * _e479)) > 0f) {
                            phi_788_ = vec3<f32>(-(_e477), -(_e478), -(_e479));
                        } else {
                            phi_788_ = vec3<f32>(_e477, _e478, _e479);
                        }
                        let _e492 = phi_788_;
                        local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e493 = (_e315 % 4u);
                        if (_e493 < 4u) {
                        } else {
                            break;
                        }
                        let _e495 = (_e314 % 4u);
                        if (_e495 < 4u) {
                        } else {
                            break;
                        }
                        let _e499 = local_3[_e493][_e495];
                        let _e509 = sqrt((((_e416 * _e416) + (_e418 * _e418)) + (_e419 * _e419)));
                        let _e510 = (-(_e416) / _e509);
                        let _e511 = (-(_e418) / _e509);
                        let _e512 = (_e372 / _e509);
                        let _e515 = -((_e499[1] * _e512));
                        let _e516 = (_e512 * _e499[0]);
                        let _e519 = ((_e510 * _e499[1]) - (_e499[0] * _e511));
                        let _e526 = (1f / sqrt((((_e515 * _e515) + (_e516 * _e516)) + (_e519 * _e519))));
                        let _e527 = (_e515 * _e526);
                        let _e528 = (_e516 * _e526);
                        let _e529 = (_e519 * _e526);
                        let _e533 = ((_e528 * _e512) - (_e511 * _e529));
                        let _e536 = ((_e529 * _e510) - (_e512 * _e527));
                        let _e539 = ((_e527 * _e511) - (_e510 * _e528));
                        let _e558 = (((_e492.x * _e510) + (_e492.y * _e511)) + (_e492.z * _e512));
                        let _e562 = abs(_e558);
                        if (_e562 != _e562) {
                            phi_1437_ = true;
                        } else {
                            phi_1437_ = (0.0001f >= _e562);
                        }
                        let _e566 = phi_1437_;
                        phi_900_ = type_33();
                        phi_901_ = type_33(1u, type_32(vec2<u32>(_e314, _e315), vec2<f32>(_e366, _e367), _e408, _e409, vec3<f32>(_e416, _e418, _e419), _e492, vec3<f32>(_e510, _e511, _e512), vec3<f32>(_e533, _e536, _e539), vec3<f32>(_e527, _e528, _e529), vec3<f32>((((_e492.x * _e533) + (_e492.y * _e536)) + (_e492.z * _e539)), (((_e492.x * _e527) + (_e492.y * _e528)) + (_e492.z * _e529)), _e558), (1f / (select(1f, -1f, (_e558 < 0f)) * select(_e562, 0.0001f, _e566)))));
                    }
                    let _e578 = phi_900_;
                    let _e580 = phi_901_;
                    phi_903_ = _e578;
                    phi_904_ = _e580;
                    phi_905_ = _e410;
                } else {
                    phi_903_ = type_33(0u, type_33().member_1);
                    phi_904_ = type_33();
                    phi_905_ = true;
                }
                let _e582 = phi_903_;
                let _e584 = phi_904_;
                let _e586 = phi_905_;
                if _e586 {
                    phi_909_ = _e582;
                } else {
                    phi_909_ = _e584;
                }
                let _e588 = phi_909_;
                if (bitcast<i32>(_e588.member) != 0i) {
                    phi_918_ = 0u;
                    phi_921_ = 0f;
                    loop {
                        let _e594 = phi_918_;
                        let _e596 = phi_921_;
                        local_4 = _e596;
                        let _e597 = (_e594 < 8u);
                        if _e597 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e598 = (_e594 < 56u);
                            if _e598 {
                            } else {
                                phi_1586_ = true;
                                break;
                            }
                            let _e600 = local[_e594];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e598 {
                            } else {
                                phi_1586_ = true;
                                break;
                            }
                            let _e604 = local_1[_e594];
                            let _e606 = (_e588.member_1.member_2 * _e604);
                            let _e607 = (_e606 * _e600[0]);
                            let _e608 = (_e606 * _e600[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e598 {
                            } else {
                                phi_1586_ = true;
                                break;
                            }
                            let _e610 = local_2[_e594];
                            let _e611 = (_e588.member_1.member_2 * _e610);
                            let _e620 = (-(((_e607 * _e588.member_1.member_9.x) + (_e608 * _e588.member_1.member_9.y))) * _e588.member_1.member_10);
                            let _e621 = -(_e611);
                            let _e625 = select(_e621, select(_e611, _e620, (_e620 < _e611)), (_e620 > _e621));
                            let _e626 = (_e611 - _e625);
                            let _e653 = (-0.5f / ((_e588.member_1.member_4.z + (_e588.member_1.member_7.z * _e607)) + (_e588.member_1.member_8.z * _e608)));
                            let _e659 = params.member.member.member_1[0u];
                            let _e661 = (((((_e588.member_1.member_4.x + (_e588.member_1.member_7.x * _e607)) + (_e588.member_1.member_8.x * _e608)) * _e653) / _e659) + 0.5f);
                            let _e667 = params.member.member.member_1[1u];
                            let _e669 = (0.5f - ((((_e588.member_1.member_4.y + (_e588.member_1.member_7.y * _e607)) + (_e588.member_1.member_8.y * _e608)) * _e653) / _e667));
                            let _e670 = params.member.member;
                            let _e688 = (select(0f, select(1f, _e661, (_e661 < 1f)), (_e661 > 0f)) * _e670.member.x);
                            let _e693 = (select(0f, select(1f, _e669, (_e669 < 1f)), (_e669 > 0f)) * _e670.member.y);
                            let _e698 = select(select(u32(_e688), 0u, (_e688 < 0f)), 4294967295u, (_e688 > 4294967000f));
                            let _e699 = (select(select(u32(_e670.member.x), 0u, (_e670.member.x < 0f)), 4294967295u, (_e670.member.x > 4294967000f)) - 1u);
                            let _e701 = select(_e698, _e699, (_e699 < _e698));
                            let _e706 = select(select(u32(_e693), 0u, (_e693 < 0f)), 4294967295u, (_e693 > 4294967000f));
                            let _e707 = (select(select(u32(_e670.member.y), 0u, (_e670.member.y < 0f)), 4294967295u, (_e670.member.y > 4294967000f)) - 1u);
                            let _e709 = select(_e706, _e707, (_e707 < _e706));
                            if (_e701 == _e588.member_1.member.x) {
                                phi_1111_ = (_e709 == _e588.member_1.member.y);
                            } else {
                                phi_1111_ = false;
                            }
                            let _e717 = phi_1111_;
                            let _e719 = ((_e709 * _e327) + _e701);
                            if (_e719 < _e302) {
                            } else {
                                phi_1586_ = true;
                                break;
                            }
                            let _e722 = depth.member[_e719];
                            let _e726 = select(_e376, _e722, select(false, (_e722 < _e376), (_e722 > 0f)));
                            let _e755 = ((((((((((f32(_e701) + 0.5f) * (1f / _e670.member.x)) * 2f) - 1f) * _e726) * _e659) - _e588.member_1.member_4.x) * _e588.member_1.member_6.x) + ((((((((f32(_e709) + 0.5f) * (1f / _e670.member.y)) * -2f) + 1f) * _e726) * _e667) - _e588.member_1.member_4.y) * _e588.member_1.member_6.y)) + ((-(_e726) - _e588.member_1.member_4.z) * _e588.member_1.member_6.z));
                            let _e760 = params.member.member_3;
                            if (_e625 != _e625) {
                                phi_1544_ = true;
                            } else {
                                phi_1544_ = (_e755 >= _e625);
                            }
                            let _e765 = phi_1544_;
                            let _e767 = (_e611 - select(_e625, _e755, _e765));
                            if (_e767 != _e767) {
                                phi_1559_ = true;
                            } else {
                                phi_1559_ = (0f >= _e767);
                            }
                            let _e771 = phi_1559_;
                            let _e776 = ((_e755 - (_e588.member_1.member_2 * (1f + _e760))) * (1f / _e611));
                            phi_919_ = (_e594 + 1u);
                            phi_922_ = (_e596 + select(0f, select(((select(_e767, 0f, _e771) + (select(0f, select(1f, _e776, (_e776 < 1f)), (_e776 > 0f)) * _e626)) * (0.5f / _e611)), (_e626 / (_e611 * 2f)), _e717), (_e626 > (_e611 * 0.2f))));
                        } else {
                            phi_919_ = u32();
                            phi_922_ = f32();
                        }
                        let _e790 = phi_919_;
                        let _e792 = phi_922_;
                        continue;
                        continuing {
                            phi_918_ = _e790;
                            phi_921_ = _e792;
                            phi_1586_ = false;
                            break if !(_e597);
                        }
                    }
                    let _e795 = phi_1586_;
                    if _e795 {
                        break;
                    }
                    let _e797 = local_4;
                    let _e798 = (0.25f * _e797);
                    let _e805 = params.member.member_2;
                    phi_1260_ = pow(select(0f, select(1f, _e798, (_e798 < 1f)), (_e798 > 0f)), _e805);
                } else {
                    phi_1260_ = 1f;
                }
                let _e808 = phi_1260_;
                if (_e369 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e369] = _e808;
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
