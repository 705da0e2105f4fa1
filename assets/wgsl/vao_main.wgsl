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
    var phi_685_: f32;
    var phi_1405_: bool;
    var phi_1420_: bool;
    var phi_761_: vec2<f32>;
    var phi_788_: vec3<f32>;
    var phi_1435_: bool;
    var phi_900_: type_33;
    var phi_901_: type_33;
    var phi_903_: type_33;
    var phi_904_: type_33;
    var phi_905_: bool;
    var phi_909_: type_33;
    var phi_918_: u32;
    var phi_921_: f32;
    var phi_1111_: bool;
    var phi_1542_: bool;
    var phi_1557_: bool;
    var phi_919_: u32;
    var phi_922_: f32;
    var phi_1584_: bool;
    var local_4: f32;
    var phi_1258_: f32;

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
                if select(false, (_e372 < _e376), (_e372 > 0f)) {
                    let _e387 = params.member.member.member_1[0u];
                    let _e392 = params.member.member.member_1[1u];
                    let _e402 = (0.5f * (((_e358 * _e322) / ((2f * _e387) * _e372)) + ((_e358 * _e332) / ((2f * _e392) * _e372))));
                    let _e403 = (_e402 > _e361);
                    if _e403 {
                        phi_685_ = ((_e358 * _e361) / _e402);
                    } else {
                        phi_685_ = _e358;
                    }
                    let _e407 = phi_685_;
                    let _e408 = select(_e402, _e361, _e403);
                    let _e409 = (_e408 < 0.5f);
                    if _e409 {
                        phi_900_ = type_33(0u, type_33().member_1);
                        phi_901_ = type_33();
                    } else {
                        let _e415 = ((((_e366 * 2f) - 1f) * _e372) * _e387);
                        let _e417 = ((((_e367 * -2f) + 1f) * _e372) * _e392);
                        let _e418 = -(_e372);
                        if (_e369 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e422 = normals.member[_e369];
                        let _e430 = (f32((bitcast<i32>(((_e422 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e430 != _e430) {
                            phi_1405_ = true;
                        } else {
                            phi_1405_ = (-1f >= _e430);
                        }
                        let _e434 = phi_1405_;
                        let _e435 = select(_e430, -1f, _e434);
                        let _e445 = (f32((bitcast<i32>((((_e422 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e445 != _e445) {
                            phi_1420_ = true;
                        } else {
                            phi_1420_ = (-1f >= _e445);
                        }
                        let _e449 = phi_1420_;
                        let _e450 = select(_e445, -1f, _e449);
                        let _e453 = (1f - abs(_e435));
                        let _e454 = abs(_e450);
                        let _e455 = (_e453 - _e454);
                        if (_e455 < 0f) {
                            phi_761_ = vec2<f32>(((1f - _e454) * select(1f, -1f, (_e435 < 0f))), (_e453 * select(1f, -1f, (_e450 < 0f))));
                        } else {
                            phi_761_ = vec2<f32>(_e435, _e450);
                        }
                        let _e466 = phi_761_;
                        let _e475 = (1f / sqrt((((_e466.x * _e466.x) + (_e466.y * _e466.y)) + (_e455 * _e455))));
                        let _e476 = (_e466.x * _e475);
                        let _e477 = (_e466.y * _e475);
                        let _e478 = (_e455 * _e475);
                        if ((((_e415 * _e476) + (_e417 * _e477)) + (_e418 * _e478)) > 0f) {
                            phi_788_ = vec3<f32>(-(_e476), -(_e477), -(_e478));
                        } else {
                            phi_788_ = vec3<f32>(_e476, _e477, _e478);
                        }
                        let _e491 = phi_788_;
                        local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e492 = (_e315 % 4u);
                        if (_e492 < 4u) {
                        } else {
                            break;
                        }
                        let _e494 = (_e314 % 4u);
                        if (_e494 < 4u) {
                        } else {
                            break;
                        }
                        let _e498 = local_3[_e492][_e494];
                        let _e508 = sqrt((((_e415 * _e415) + (_e417 * _e417)) + (_e418 * _e418)));
                        let _e509 = (-(_e415) / _e508);
                        let _e510 = (-(_e417) / _e508);
                        let _e511 = (_e372 / _e508);
                        let _e514 = -((_e498[1] * _e511));
                        let _e515 = (_e511 * _e498[0]);
                        let _e518 = ((_e509 * _e498[1]) - (_e498[0] * _e510));
                        let _e525 = (1f / sqrt((((_e514 * _e514) + (_e515 * _e515)) + (_e518 * _e518))));
                        let _e526 = (_e514 * _e525);
                        let _e527 = (_e515 * _e525);
                        let _e528 = (_e518 * _e525);
                        let _e532 = ((_e527 * _e511) - (_e510 * _e528));
                        let _e535 = ((_e528 * _e509) - (_e511 * _e526));
                        let _e538 = ((_e526 * _e510) - (_e509 * _e527));
                        let _e557 = (((_e491.x * _e509) + (_e491.y * _e510)) + (_e491.z * _e511));
                        let _e561 = abs(_e557);
                        if (_e561 != _e561) {
                            phi_1435_ = true;
                        } else {
                            phi_1435_ = (0.0001f >= _e561);
                        }
                        let _e565 = phi_1435_;
                        phi_900_ = type_33();
                        phi_901_ = type_33(1u, type_32(vec2<u32>(_e314, _e315), vec2<f32>(_e366, _e367), _e407, _e408, vec3<f32>(_e415, _e417, _e418), _e491, vec3<f32>(_e509, _e510, _e511), vec3<f32>(_e532, _e535, _e538), vec3<f32>(_e526, _e527, _e528), vec3<f32>((((_e491.x * _e532) + (_e491.y * _e535)) + (_e491.z * _e538)), (((_e491.x * _e526) + (_e491.y * _e527)) + (_e491.z * _e528)), _e557), (1f / (select(1f, -1f, (_e557 < 0f)) * select(_e561, 0.0001f, _e565)))));
                    }
                    let _e577 = phi_900_;
                    let _e579 = phi_901_;
                    phi_903_ = _e577;
                    phi_904_ = _e579;
                    phi_905_ = _e409;
                } else {
                    phi_903_ = type_33(0u, type_33().member_1);
                    phi_904_ = type_33();
                    phi_905_ = true;
                }
                let _e581 = phi_903_;
                let _e583 = phi_904_;
                let _e585 = phi_905_;
                if _e585 {
                    phi_909_ = _e581;
                } else {
                    phi_909_ = _e583;
                }
                let _e587 = phi_909_;
                if (bitcast<i32>(_e587.member) != 0i) {
                    phi_918_ = 0u;
                    phi_921_ = 0f;
                    loop {
                        let _e593 = phi_918_;
                        let _e595 = phi_921_;
                        local_4 = _e595;
                        let _e596 = (_e593 < 8u);
                        if _e596 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e597 = (_e593 < 56u);
                            if _e597 {
                            } else {
                                phi_1584_ = true;
                                break;
                            }
                            let _e599 = local[_e593];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e597 {
                            } else {
                                phi_1584_ = true;
                                break;
                            }
                            let _e603 = local_1[_e593];
                            let _e605 = (_e587.member_1.member_2 * _e603);
                            let _e606 = (_e605 * _e599[0]);
                            let _e607 = (_e605 * _e599[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e597 {
                            } else {
                                phi_1584_ = true;
                                break;
                            }
                            let _e609 = local_2[_e593];
                            let _e610 = (_e587.member_1.member_2 * _e609);
                            let _e619 = (-(((_e606 * _e587.member_1.member_9.x) + (_e607 * _e587.member_1.member_9.y))) * _e587.member_1.member_10);
                            let _e620 = -(_e610);
                            let _e624 = select(_e620, select(_e610, _e619, (_e619 < _e610)), (_e619 > _e620));
                            let _e625 = (_e610 - _e624);
                            let _e652 = (-0.5f / ((_e587.member_1.member_4.z + (_e587.member_1.member_7.z * _e606)) + (_e587.member_1.member_8.z * _e607)));
                            let _e658 = params.member.member.member_1[0u];
                            let _e660 = (((((_e587.member_1.member_4.x + (_e587.member_1.member_7.x * _e606)) + (_e587.member_1.member_8.x * _e607)) * _e652) / _e658) + 0.5f);
                            let _e666 = params.member.member.member_1[1u];
                            let _e668 = (0.5f - ((((_e587.member_1.member_4.y + (_e587.member_1.member_7.y * _e606)) + (_e587.member_1.member_8.y * _e607)) * _e652) / _e666));
                            let _e669 = params.member.member;
                            let _e687 = (select(0f, select(1f, _e660, (_e660 < 1f)), (_e660 > 0f)) * _e669.member.x);
                            let _e692 = (select(0f, select(1f, _e668, (_e668 < 1f)), (_e668 > 0f)) * _e669.member.y);
                            let _e697 = select(select(u32(_e687), 0u, (_e687 < 0f)), 4294967295u, (_e687 > 4294967000f));
                            let _e698 = (select(select(u32(_e669.member.x), 0u, (_e669.member.x < 0f)), 4294967295u, (_e669.member.x > 4294967000f)) - 1u);
                            let _e700 = select(_e697, _e698, (_e698 < _e697));
                            let _e705 = select(select(u32(_e692), 0u, (_e692 < 0f)), 4294967295u, (_e692 > 4294967000f));
                            let _e706 = (select(select(u32(_e669.member.y), 0u, (_e669.member.y < 0f)), 4294967295u, (_e669.member.y > 4294967000f)) - 1u);
                            let _e708 = select(_e705, _e706, (_e706 < _e705));
                            if (_e700 == _e587.member_1.member.x) {
                                phi_1111_ = (_e708 == _e587.member_1.member.y);
                            } else {
                                phi_1111_ = false;
                            }
                            let _e716 = phi_1111_;
                            let _e718 = ((_e708 * _e327) + _e700);
                            if (_e718 < _e302) {
                            } else {
                                phi_1584_ = true;
                                break;
                            }
                            let _e721 = depth.member[_e718];
                            let _e733 = select(_e376, _e721, select(false, (_e721 < _e376), (_e721 > 0f)));
                            let _e754 = ((((((((((f32(_e700) + 0.5f) * (1f / _e669.member.x)) * 2f) - 1f) * _e733) * _e658) - _e587.member_1.member_4.x) * _e587.member_1.member_6.x) + ((((((((f32(_e708) + 0.5f) * (1f / _e669.member.y)) * -2f) + 1f) * _e733) * _e666) - _e587.member_1.member_4.y) * _e587.member_1.member_6.y)) + ((-(_e733) - _e587.member_1.member_4.z) * _e587.member_1.member_6.z));
                            let _e759 = params.member.member_3;
                            if (_e624 != _e624) {
                                phi_1542_ = true;
                            } else {
                                phi_1542_ = (_e754 >= _e624);
                            }
                            let _e764 = phi_1542_;
                            let _e766 = (_e610 - select(_e624, _e754, _e764));
                            if (_e766 != _e766) {
                                phi_1557_ = true;
                            } else {
                                phi_1557_ = (0f >= _e766);
                            }
                            let _e770 = phi_1557_;
                            let _e775 = ((_e754 - (_e587.member_1.member_2 * (1f + _e759))) * (1f / _e610));
                            phi_919_ = (_e593 + 1u);
                            phi_922_ = (_e595 + select(0f, select(((select(_e766, 0f, _e770) + (select(0f, select(1f, _e775, (_e775 < 1f)), (_e775 > 0f)) * _e625)) * (0.5f / _e610)), (_e625 / (_e610 * 2f)), _e716), (_e625 > (_e610 * 0.2f))));
                        } else {
                            phi_919_ = u32();
                            phi_922_ = f32();
                        }
                        let _e789 = phi_919_;
                        let _e791 = phi_922_;
                        continue;
                        continuing {
                            phi_918_ = _e789;
                            phi_921_ = _e791;
                            phi_1584_ = false;
                            break if !(_e596);
                        }
                    }
                    let _e794 = phi_1584_;
                    if _e794 {
                        break;
                    }
                    let _e796 = local_4;
                    let _e797 = (0.25f * _e796);
                    let _e804 = params.member.member_2;
                    phi_1258_ = pow(select(0f, select(1f, _e797, (_e797 < 1f)), (_e797 > 0f)), _e804);
                } else {
                    phi_1258_ = 1f;
                }
                let _e807 = phi_1258_;
                if (_e369 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e369] = _e807;
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
