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

struct type_8 {
    member: array<f32>,
}

struct type_11 {
    member: array<u32>,
}

struct type_27 {
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

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_34 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_35 {
    member: type_34,
    member_1: type_34,
    member_2: type_5,
}

struct type_36 {
    member: type_6,
    member_1: u32,
    member_2: u32,
    member_3: f32,
    member_4: u32,
    member_5: vec2<u32>,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: u32,
}

struct type_37 {
    member: type_35,
    member_1: type_36,
}

struct type_39 {
    member: array<type_37>,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> depth: type_8;
@group(0) @binding(3) 
var<storage, read_write> ao: type_8;
@group(0) @binding(0) 
var<storage> frame: type_39;
@group(0) @binding(2) 
var<storage> normals: type_11;
@group(0) @binding(4) 
var<storage> mask: type_11;
@group(0) @binding(5) 
var<storage> sd_map: type_8;
@group(0) @binding(6) 
var<storage> depth2_: type_8;

fn function_() {
    var local: array<array<f32, 2>, 16>;
    var local_1: array<array<f32, 2>, 16>;
    var local_2: array<array<f32, 2>, 16>;
    var local_3: array<array<f32, 2>, 16>;
    var local_4: array<array<f32, 2>, 8>;
    var local_5: array<f32, 8>;
    var local_6: array<f32, 8>;
    var local_7: array<f32, 8>;
    var local_8: array<f32, 8>;
    var local_9: array<f32, 8>;
    var local_10: array<array<array<f32, 2>, 4>, 4>;
    var phi_396_: bool;
    var phi_398_: bool;
    var phi_399_: bool;
    var phi_400_: bool;
    var phi_401_: bool;
    var phi_494_: bool;
    var phi_524_: f32;
    var phi_1849_: bool;
    var phi_1864_: bool;
    var phi_599_: vec2<f32>;
    var phi_626_: vec3<f32>;
    var phi_1879_: bool;
    var phi_738_: type_28;
    var phi_739_: type_28;
    var phi_741_: type_28;
    var phi_742_: type_28;
    var phi_743_: bool;
    var phi_747_: type_28;
    var phi_2099_: bool;
    var phi_756_: u32;
    var phi_759_: f32;
    var phi_805_: f32;
    var phi_829_: f32;
    var phi_843_: f32;
    var phi_862_: f32;
    var phi_918_: bool;
    var phi_920_: bool;
    var phi_921_: bool;
    var phi_922_: bool;
    var phi_923_: bool;
    var phi_955_: f32;
    var phi_968_: f32;
    var phi_1053_: bool;
    var phi_1150_: f32;
    var phi_1163_: f32;
    var phi_1176_: f32;
    var phi_1177_: f32;
    var phi_1894_: bool;
    var phi_1909_: bool;
    var phi_1200_: f32;
    var phi_1207_: f32;
    var phi_1924_: bool;
    var phi_1229_: f32;
    var phi_1237_: bool;
    var phi_1272_: bool;
    var phi_1369_: f32;
    var phi_1382_: f32;
    var phi_1395_: f32;
    var phi_1396_: f32;
    var phi_1939_: bool;
    var phi_1954_: bool;
    var phi_1419_: f32;
    var phi_1426_: f32;
    var phi_1969_: bool;
    var phi_1984_: bool;
    var phi_1435_: f32;
    var phi_1437_: f32;
    var phi_1438_: f32;
    var phi_1450_: f32;
    var phi_1491_: f32;
    var phi_1505_: f32;
    var phi_1578_: vec2<f32>;
    var phi_1579_: vec2<f32>;
    var phi_1610_: u32;
    var phi_1613_: f32;
    var phi_1719_: f32;
    var phi_1732_: f32;
    var phi_1745_: f32;
    var phi_1746_: f32;
    var phi_2014_: bool;
    var phi_2029_: bool;
    var phi_1769_: f32;
    var phi_1776_: f32;
    var phi_2044_: bool;
    var phi_2059_: bool;
    var phi_1785_: f32;
    var phi_1611_: u32;
    var phi_1614_: f32;
    var phi_2064_: bool;
    var local_11: f32;
    var phi_2176_: bool;
    var phi_1788_: f32;
    var phi_2175_: bool;
    var phi_757_: u32;
    var phi_760_: f32;
    var phi_2174_: bool;
    var local_12: f32;
    var phi_1809_: f32;
    var phi_1819_: f32;
    var phi_1823_: f32;
    var phi_1824_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e230 = id_1;
            let _e235 = arrayLength((&depth.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e257 = frame.member[0u].member_1.member.member.member_4;
            let _e258 = (_e230.x + _e257);
            let _e259 = (_e230.y + _e257);
            let _e267 = frame.member[0u].member_1.member.member.member[0u];
            let _e272 = select(select(u32(_e267), 0u, (_e267 < 0f)), 4294967295u, (_e267 > 4294967000f));
            let _e280 = frame.member[0u].member_1.member.member.member[1u];
            let _e285 = select(select(u32(_e280), 0u, (_e280 < 0f)), 4294967295u, (_e280 > 4294967000f));
            if (_e258 >= _e257) {
                if (_e259 >= _e257) {
                    let _e289 = ((_e258 + _e257) < _e272);
                    if _e289 {
                        phi_396_ = ((_e259 + _e257) < _e285);
                    } else {
                        phi_396_ = bool();
                    }
                    let _e293 = phi_396_;
                    phi_398_ = _e293;
                    phi_399_ = select(true, false, _e289);
                } else {
                    phi_398_ = bool();
                    phi_399_ = true;
                }
                let _e296 = phi_398_;
                let _e298 = phi_399_;
                phi_400_ = _e296;
                phi_401_ = _e298;
            } else {
                phi_400_ = bool();
                phi_401_ = true;
            }
            let _e300 = phi_400_;
            let _e302 = phi_401_;
            if select(_e300, false, _e302) {
                let _e305 = ((_e259 * _e272) + _e258);
                let _e306 = (_e305 < arrayLength((&ao.member)));
                if _e306 {
                } else {
                    break;
                }
                let _e309 = ao.member[_e305];
                if (_e305 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e313 = mask.member[_e305];
                if (_e313 == 0u) {
                    phi_1824_ = _e309;
                } else {
                    let _e320 = frame.member[0u].member_1.member.member_1;
                    let _e326 = frame.member[0u].member_1.member.member_4;
                    let _e331 = ((f32(_e258) + 0.5f) / _e267);
                    let _e332 = ((f32(_e259) + 0.5f) / _e280);
                    if (_e305 < _e235) {
                    } else {
                        break;
                    }
                    let _e335 = depth.member[_e305];
                    let _e342 = frame.member[0u].member_1.member.member.member_3;
                    if (_e335 > 0f) {
                        phi_494_ = (_e335 < _e342);
                    } else {
                        phi_494_ = false;
                    }
                    let _e346 = phi_494_;
                    if _e346 {
                        let _e354 = frame.member[0u].member_1.member.member.member_1[0u];
                        let _e362 = frame.member[0u].member_1.member.member.member_1[1u];
                        let _e372 = (0.5f * (((_e320 * _e267) / ((2f * _e354) * _e335)) + ((_e320 * _e280) / ((2f * _e362) * _e335))));
                        let _e373 = (_e372 > _e326);
                        if _e373 {
                            phi_524_ = ((_e320 * _e326) / _e372);
                        } else {
                            phi_524_ = _e320;
                        }
                        let _e377 = phi_524_;
                        let _e378 = select(_e372, _e326, _e373);
                        let _e379 = (_e378 < 0.5f);
                        if _e379 {
                            phi_738_ = type_28(0u, type_28().member_1);
                            phi_739_ = type_28();
                        } else {
                            let _e388 = ((((2f * _e331) - 1f) * _e335) * _e354);
                            let _e390 = (((1f - (2f * _e332)) * _e335) * _e362);
                            let _e391 = -(_e335);
                            if (_e305 < arrayLength((&normals.member))) {
                            } else {
                                break;
                            }
                            let _e395 = normals.member[_e305];
                            let _e403 = (f32((bitcast<i32>(((_e395 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e403 != _e403) {
                                phi_1849_ = true;
                            } else {
                                phi_1849_ = (-1f >= _e403);
                            }
                            let _e407 = phi_1849_;
                            let _e408 = select(_e403, -1f, _e407);
                            let _e418 = (f32((bitcast<i32>((((_e395 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e418 != _e418) {
                                phi_1864_ = true;
                            } else {
                                phi_1864_ = (-1f >= _e418);
                            }
                            let _e422 = phi_1864_;
                            let _e423 = select(_e418, -1f, _e422);
                            let _e426 = (1f - abs(_e408));
                            let _e427 = abs(_e423);
                            let _e428 = (_e426 - _e427);
                            if (_e428 < 0f) {
                                phi_599_ = vec2<f32>(((1f - _e427) * select(1f, -1f, (_e408 < 0f))), (_e426 * select(1f, -1f, (_e423 < 0f))));
                            } else {
                                phi_599_ = vec2<f32>(_e408, _e423);
                            }
                            let _e439 = phi_599_;
                            let _e448 = (1f / sqrt((((_e439.x * _e439.x) + (_e439.y * _e439.y)) + (_e428 * _e428))));
                            let _e449 = (_e439.x * _e448);
                            let _e450 = (_e439.y * _e448);
                            let _e451 = (_e428 * _e448);
                            if ((((_e388 * _e449) + (_e390 * _e450)) + (_e391 * _e451)) > 0f) {
                                phi_626_ = vec3<f32>(-(_e449), -(_e450), -(_e451));
                            } else {
                                phi_626_ = vec3<f32>(_e449, _e450, _e451);
                            }
                            let _e464 = phi_626_;
                            local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                            let _e465 = (_e259 % 4u);
                            if (_e465 < 4u) {
                            } else {
                                break;
                            }
                            let _e467 = (_e258 % 4u);
                            if (_e467 < 4u) {
                            } else {
                                break;
                            }
                            let _e471 = local_10[_e465][_e467];
                            let _e481 = sqrt((((_e388 * _e388) + (_e390 * _e390)) + (_e391 * _e391)));
                            let _e482 = (-(_e388) / _e481);
                            let _e483 = (-(_e390) / _e481);
                            let _e484 = (_e335 / _e481);
                            let _e487 = -((_e471[1] * _e484));
                            let _e488 = (_e484 * _e471[0]);
                            let _e491 = ((_e482 * _e471[1]) - (_e471[0] * _e483));
                            let _e498 = (1f / sqrt((((_e487 * _e487) + (_e488 * _e488)) + (_e491 * _e491))));
                            let _e499 = (_e487 * _e498);
                            let _e500 = (_e488 * _e498);
                            let _e501 = (_e491 * _e498);
                            let _e505 = ((_e500 * _e484) - (_e483 * _e501));
                            let _e508 = ((_e501 * _e482) - (_e484 * _e499));
                            let _e511 = ((_e499 * _e483) - (_e482 * _e500));
                            let _e530 = (((_e464.x * _e482) + (_e464.y * _e483)) + (_e464.z * _e484));
                            let _e534 = abs(_e530);
                            if (_e534 != _e534) {
                                phi_1879_ = true;
                            } else {
                                phi_1879_ = (0.0001f >= _e534);
                            }
                            let _e538 = phi_1879_;
                            phi_738_ = type_28();
                            phi_739_ = type_28(1u, type_27(vec2<u32>(_e258, _e259), vec2<f32>(_e331, _e332), _e377, _e378, vec3<f32>(_e388, _e390, _e391), _e464, vec3<f32>(_e482, _e483, _e484), vec3<f32>(_e505, _e508, _e511), vec3<f32>(_e499, _e500, _e501), vec3<f32>((((_e464.x * _e505) + (_e464.y * _e508)) + (_e464.z * _e511)), (((_e464.x * _e499) + (_e464.y * _e500)) + (_e464.z * _e501)), _e530), (1f / (select(1f, -1f, (_e530 < 0f)) * select(_e534, 0.0001f, _e538)))));
                        }
                        let _e547 = phi_738_;
                        let _e549 = phi_739_;
                        phi_741_ = _e547;
                        phi_742_ = _e549;
                        phi_743_ = _e379;
                    } else {
                        phi_741_ = type_28(0u, type_28().member_1);
                        phi_742_ = type_28();
                        phi_743_ = true;
                    }
                    let _e554 = phi_741_;
                    let _e556 = phi_742_;
                    let _e558 = phi_743_;
                    if _e558 {
                        phi_747_ = _e554;
                    } else {
                        phi_747_ = _e556;
                    }
                    let _e560 = phi_747_;
                    if (bitcast<i32>(_e560.member) != 0i) {
                        phi_2099_ = false;
                        phi_756_ = 0u;
                        phi_759_ = 0f;
                        loop {
                            let _e566 = phi_2099_;
                            let _e568 = phi_756_;
                            let _e570 = phi_759_;
                            local_12 = _e570;
                            let _e571 = (_e568 < 8u);
                            if _e571 {
                                if ((_e313 & (1u << bitcast<u32>((_e568 & 31u)))) == 0u) {
                                    phi_2176_ = _e566;
                                    phi_1788_ = _e570;
                                } else {
                                    let _e581 = frame.member[0u].member_1.member_10;
                                    local_4 = array<array<f32, 2>, 8>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f));
                                    if _e571 {
                                    } else {
                                        phi_2174_ = true;
                                        break;
                                    }
                                    let _e583 = local_4[_e568];
                                    let _e586 = (_e581 == 1u);
                                    if _e586 {
                                        local_5 = array<f32, 8>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f);
                                        if _e571 {
                                        } else {
                                            phi_2174_ = true;
                                            break;
                                        }
                                        let _e588 = local_5[_e568];
                                        phi_805_ = _e588;
                                    } else {
                                        local_6 = array<f32, 8>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f);
                                        if _e571 {
                                        } else {
                                            phi_2174_ = true;
                                            break;
                                        }
                                        let _e590 = local_6[_e568];
                                        phi_805_ = _e590;
                                    }
                                    let _e592 = phi_805_;
                                    let _e594 = (_e592 * _e560.member_1.member_2);
                                    let _e595 = (_e594 * _e583[0]);
                                    let _e596 = (_e594 * _e583[1]);
                                    if _e586 {
                                        local_7 = array<f32, 8>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f);
                                        if _e571 {
                                        } else {
                                            phi_2174_ = true;
                                            break;
                                        }
                                        let _e598 = local_7[_e568];
                                        phi_829_ = _e598;
                                    } else {
                                        local_8 = array<f32, 8>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f);
                                        if _e571 {
                                        } else {
                                            phi_2174_ = true;
                                            break;
                                        }
                                        let _e600 = local_8[_e568];
                                        phi_829_ = _e600;
                                    }
                                    let _e602 = phi_829_;
                                    let _e603 = (_e602 * _e560.member_1.member_2);
                                    if _e586 {
                                        local_9 = array<f32, 8>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f);
                                        if _e571 {
                                        } else {
                                            phi_2174_ = true;
                                            break;
                                        }
                                        let _e605 = local_9[_e568];
                                        phi_843_ = _e605;
                                    } else {
                                        phi_843_ = (2f * _e603);
                                    }
                                    let _e608 = phi_843_;
                                    let _e618 = (-(((_e595 * _e560.member_1.member_9.x) + (_e596 * _e560.member_1.member_9.y))) * _e560.member_1.member_10);
                                    let _e619 = -(_e603);
                                    if (_e618 > _e619) {
                                        phi_862_ = select(_e603, _e618, (_e618 < _e603));
                                    } else {
                                        phi_862_ = _e619;
                                    }
                                    let _e624 = phi_862_;
                                    let _e649 = (-0.5f / ((_e560.member_1.member_4.z + (_e560.member_1.member_7.z * _e595)) + (_e560.member_1.member_8.z * _e596)));
                                    let _e658 = frame.member[0u].member_1.member.member.member_1[0u];
                                    let _e660 = (0.5f + ((((_e560.member_1.member_4.x + (_e560.member_1.member_7.x * _e595)) + (_e560.member_1.member_8.x * _e596)) * _e649) / _e658));
                                    let _e669 = frame.member[0u].member_1.member.member.member_1[1u];
                                    let _e671 = (0.5f - ((((_e560.member_1.member_4.y + (_e560.member_1.member_7.y * _e595)) + (_e560.member_1.member_8.y * _e596)) * _e649) / _e669));
                                    if (_e660 >= 0f) {
                                        if (_e660 <= 1f) {
                                            let _e674 = (_e671 >= 0f);
                                            if _e674 {
                                                phi_918_ = (_e671 <= 1f);
                                            } else {
                                                phi_918_ = bool();
                                            }
                                            let _e677 = phi_918_;
                                            phi_920_ = _e677;
                                            phi_921_ = select(true, false, _e674);
                                        } else {
                                            phi_920_ = bool();
                                            phi_921_ = true;
                                        }
                                        let _e680 = phi_920_;
                                        let _e682 = phi_921_;
                                        phi_922_ = _e680;
                                        phi_923_ = _e682;
                                    } else {
                                        phi_922_ = bool();
                                        phi_923_ = true;
                                    }
                                    let _e684 = phi_922_;
                                    let _e686 = phi_923_;
                                    if (_e660 > 0f) {
                                        phi_955_ = select(1f, _e660, (_e660 < 1f));
                                    } else {
                                        phi_955_ = 0f;
                                    }
                                    let _e692 = phi_955_;
                                    let _e693 = (_e692 * _e267);
                                    if (_e671 > 0f) {
                                        phi_968_ = select(1f, _e671, (_e671 < 1f));
                                    } else {
                                        phi_968_ = 0f;
                                    }
                                    let _e698 = phi_968_;
                                    let _e699 = (_e698 * _e280);
                                    let _e704 = select(select(u32(_e693), 0u, (_e693 < 0f)), 4294967295u, (_e693 > 4294967000f));
                                    let _e705 = (_e272 - 1u);
                                    let _e707 = select(_e704, _e705, (_e705 < _e704));
                                    let _e712 = select(select(u32(_e699), 0u, (_e699 < 0f)), 4294967295u, (_e699 > 4294967000f));
                                    let _e713 = (_e285 - 1u);
                                    let _e715 = select(_e712, _e713, (_e713 < _e712));
                                    let _e722 = ((_e560.member_1.member_1.x - _e660) * _e267);
                                    let _e723 = ((_e560.member_1.member_1.y - _e671) * _e280);
                                    let _e729 = ((_e715 * _e272) + _e707);
                                    if (_e729 < _e235) {
                                    } else {
                                        phi_2174_ = true;
                                        break;
                                    }
                                    let _e732 = depth.member[_e729];
                                    if (_e732 > 0f) {
                                        phi_1053_ = (_e732 < _e342);
                                    } else {
                                        phi_1053_ = false;
                                    }
                                    let _e736 = phi_1053_;
                                    let _e737 = select(_e342, _e732, _e736);
                                    let _e747 = ((2f * ((f32(_e707) + 0.5f) * (1f / _e267))) - 1f);
                                    let _e749 = (1f - (2f * ((f32(_e715) + 0.5f) * (1f / _e280))));
                                    let _e755 = (((_e747 * _e737) * _e658) - _e560.member_1.member_4.x);
                                    let _e756 = (((_e749 * _e737) * _e669) - _e560.member_1.member_4.y);
                                    let _e757 = (-(_e737) - _e560.member_1.member_4.z);
                                    let _e766 = (((_e755 * _e560.member_1.member_6.x) + (_e756 * _e560.member_1.member_6.y)) + (_e757 * _e560.member_1.member_6.z));
                                    if _e586 {
                                        let _e771 = (((_e755 * _e755) + (_e756 * _e756)) + (_e757 * _e757));
                                        if (_e771 <= 0f) {
                                            phi_1177_ = 0f;
                                        } else {
                                            let _e784 = (((((_e560.member_1.member_5.x * _e755) + (_e560.member_1.member_5.y * _e756)) + (_e560.member_1.member_5.z * _e757)) / sqrt(_e771)) - 0.1f);
                                            if (_e784 > 0f) {
                                                phi_1150_ = select(1f, _e784, (_e784 < 1f));
                                            } else {
                                                phi_1150_ = 0f;
                                            }
                                            let _e789 = phi_1150_;
                                            let _e792 = (1f - (_e771 / (_e320 * _e320)));
                                            if (_e792 > 0f) {
                                                phi_1163_ = select(1f, _e792, (_e792 < 1f));
                                            } else {
                                                phi_1163_ = 0f;
                                            }
                                            let _e797 = phi_1163_;
                                            let _e799 = ((_e789 * _e797) / _e608);
                                            if (_e799 > 0f) {
                                                phi_1176_ = select(1f, _e799, (_e799 < 1f));
                                            } else {
                                                phi_1176_ = 0f;
                                            }
                                            let _e804 = phi_1176_;
                                            phi_1177_ = _e804;
                                        }
                                        let _e806 = phi_1177_;
                                        phi_1207_ = _e806;
                                    } else {
                                        let _e812 = frame.member[0u].member_1.member.member_3;
                                        if (_e624 != _e624) {
                                            phi_1894_ = true;
                                        } else {
                                            phi_1894_ = (_e766 >= _e624);
                                        }
                                        let _e817 = phi_1894_;
                                        let _e819 = (_e603 - select(_e624, _e766, _e817));
                                        if (_e819 != _e819) {
                                            phi_1909_ = true;
                                        } else {
                                            phi_1909_ = (0f >= _e819);
                                        }
                                        let _e823 = phi_1909_;
                                        let _e828 = ((_e766 - ((1f + _e812) * _e560.member_1.member_2)) * (1f / _e603));
                                        if (_e828 > 0f) {
                                            phi_1200_ = select(1f, _e828, (_e828 < 1f));
                                        } else {
                                            phi_1200_ = 0f;
                                        }
                                        let _e833 = phi_1200_;
                                        phi_1207_ = ((select(_e819, 0f, _e823) + (_e833 * (_e603 - _e624))) * (0.5f / _e603));
                                    }
                                    let _e840 = phi_1207_;
                                    let _e845 = frame.member[0u].member_1.member_9;
                                    if (_e845 == 0u) {
                                        phi_1438_ = _e840;
                                    } else {
                                        if _e586 {
                                            let _e847 = (0.1f * _e560.member_1.member_2);
                                            if (_e603 != _e603) {
                                                phi_1924_ = true;
                                            } else {
                                                phi_1924_ = (_e847 >= _e603);
                                            }
                                            let _e851 = phi_1924_;
                                            phi_1229_ = select(_e603, _e847, _e851);
                                        } else {
                                            let _e858 = frame.member[0u].member_1.member.member_3;
                                            phi_1229_ = ((1f + _e858) * _e560.member_1.member_2);
                                        }
                                        let _e862 = phi_1229_;
                                        if (_e766 > _e862) {
                                            let _e868 = frame.member[0u].member_1.member_3;
                                            phi_1237_ = (sqrt(((_e722 * _e722) + (_e723 * _e723))) > _e868);
                                        } else {
                                            phi_1237_ = false;
                                        }
                                        let _e871 = phi_1237_;
                                        if _e871 {
                                            if (_e729 < arrayLength((&depth2_.member))) {
                                            } else {
                                                phi_2174_ = true;
                                                break;
                                            }
                                            let _e875 = depth2_.member[_e729];
                                            if (_e875 > 0f) {
                                                phi_1272_ = (_e875 < _e342);
                                            } else {
                                                phi_1272_ = false;
                                            }
                                            let _e879 = phi_1272_;
                                            let _e880 = select(_e342, _e875, _e879);
                                            let _e886 = (((_e747 * _e880) * _e658) - _e560.member_1.member_4.x);
                                            let _e887 = (((_e749 * _e880) * _e669) - _e560.member_1.member_4.y);
                                            let _e888 = (-(_e880) - _e560.member_1.member_4.z);
                                            let _e893 = (((_e886 * _e560.member_1.member_6.x) + (_e887 * _e560.member_1.member_6.y)) + (_e888 * _e560.member_1.member_6.z));
                                            if _e586 {
                                                let _e898 = (((_e886 * _e886) + (_e887 * _e887)) + (_e888 * _e888));
                                                if (_e898 <= 0f) {
                                                    phi_1396_ = 0f;
                                                } else {
                                                    let _e911 = (((((_e560.member_1.member_5.x * _e886) + (_e560.member_1.member_5.y * _e887)) + (_e560.member_1.member_5.z * _e888)) / sqrt(_e898)) - 0.1f);
                                                    if (_e911 > 0f) {
                                                        phi_1369_ = select(1f, _e911, (_e911 < 1f));
                                                    } else {
                                                        phi_1369_ = 0f;
                                                    }
                                                    let _e916 = phi_1369_;
                                                    let _e919 = (1f - (_e898 / (_e320 * _e320)));
                                                    if (_e919 > 0f) {
                                                        phi_1382_ = select(1f, _e919, (_e919 < 1f));
                                                    } else {
                                                        phi_1382_ = 0f;
                                                    }
                                                    let _e924 = phi_1382_;
                                                    let _e926 = ((_e916 * _e924) / _e608);
                                                    if (_e926 > 0f) {
                                                        phi_1395_ = select(1f, _e926, (_e926 < 1f));
                                                    } else {
                                                        phi_1395_ = 0f;
                                                    }
                                                    let _e931 = phi_1395_;
                                                    phi_1396_ = _e931;
                                                }
                                                let _e933 = phi_1396_;
                                                phi_1426_ = _e933;
                                            } else {
                                                let _e939 = frame.member[0u].member_1.member.member_3;
                                                if (_e624 != _e624) {
                                                    phi_1939_ = true;
                                                } else {
                                                    phi_1939_ = (_e893 >= _e624);
                                                }
                                                let _e944 = phi_1939_;
                                                let _e946 = (_e603 - select(_e624, _e893, _e944));
                                                if (_e946 != _e946) {
                                                    phi_1954_ = true;
                                                } else {
                                                    phi_1954_ = (0f >= _e946);
                                                }
                                                let _e950 = phi_1954_;
                                                let _e955 = ((_e893 - ((1f + _e939) * _e560.member_1.member_2)) * (1f / _e603));
                                                if (_e955 > 0f) {
                                                    phi_1419_ = select(1f, _e955, (_e955 < 1f));
                                                } else {
                                                    phi_1419_ = 0f;
                                                }
                                                let _e960 = phi_1419_;
                                                phi_1426_ = ((select(_e946, 0f, _e950) + (_e960 * (_e603 - _e624))) * (0.5f / _e603));
                                            }
                                            let _e967 = phi_1426_;
                                            if _e586 {
                                                if (_e840 != _e840) {
                                                    phi_1969_ = true;
                                                } else {
                                                    phi_1969_ = (_e967 >= _e840);
                                                }
                                                let _e971 = phi_1969_;
                                                phi_1435_ = select(_e840, _e967, _e971);
                                            } else {
                                                if (_e840 != _e840) {
                                                    phi_1984_ = true;
                                                } else {
                                                    phi_1984_ = (_e967 <= _e840);
                                                }
                                                let _e976 = phi_1984_;
                                                phi_1435_ = select(_e840, _e967, _e976);
                                            }
                                            let _e979 = phi_1435_;
                                            phi_1437_ = _e979;
                                        } else {
                                            phi_1437_ = _e840;
                                        }
                                        let _e981 = phi_1437_;
                                        phi_1438_ = _e981;
                                    }
                                    let _e983 = phi_1438_;
                                    if select(_e684, false, _e686) {
                                        phi_1450_ = _e983;
                                    } else {
                                        phi_1450_ = select(1f, 0f, _e586);
                                    }
                                    let _e987 = phi_1450_;
                                    let _e993 = frame.member[0u].member_1.member_5[0u];
                                    let _e999 = frame.member[0u].member_1.member_5[1u];
                                    let _e1000 = f32(_e993);
                                    let _e1001 = f32(_e999);
                                    let _e1006 = frame.member[0u].member_1.member_4;
                                    let _e1007 = f32(_e1006);
                                    let _e1008 = (2u * _e1006);
                                    let _e1009 = (_e993 + _e1008);
                                    let _e1015 = (floor((_e660 * _e1000)) + _e1007);
                                    let _e1016 = f32((_e1009 - 1u));
                                    if (_e1015 > 0f) {
                                        phi_1491_ = select(_e1016, _e1015, (_e1015 < _e1016));
                                    } else {
                                        phi_1491_ = 0f;
                                    }
                                    let _e1021 = phi_1491_;
                                    let _e1024 = (floor((_e671 * _e1001)) + _e1007);
                                    let _e1025 = f32(((_e999 + _e1008) - 1u));
                                    if (_e1024 > 0f) {
                                        phi_1505_ = select(_e1025, _e1024, (_e1024 < _e1025));
                                    } else {
                                        phi_1505_ = 0f;
                                    }
                                    let _e1030 = phi_1505_;
                                    let _e1035 = select(select(u32(_e1021), 0u, (_e1021 < 0f)), 4294967295u, (_e1021 > 4294967000f));
                                    let _e1040 = select(select(u32(_e1030), 0u, (_e1030 < 0f)), 4294967295u, (_e1030 > 4294967000f));
                                    let _e1043 = bitcast<i32>(_e1006);
                                    let _e1052 = frame.member[0u].member_1.member_8;
                                    let _e1056 = (((_e1040 % 4u) * 4u) + (_e1035 % 4u));
                                    if (_e1052 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1058 = (_e1056 < 16u);
                                        if _e1058 {
                                        } else {
                                            phi_2174_ = true;
                                            break;
                                        }
                                        let _e1061 = local[_e1056][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1058 {
                                        } else {
                                            phi_2174_ = true;
                                            break;
                                        }
                                        let _e1064 = local_1[_e1056][1u];
                                        phi_1579_ = vec2<f32>(_e1061, _e1064);
                                    } else {
                                        if (_e1052 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1067 = (_e1056 < 16u);
                                            if _e1067 {
                                            } else {
                                                phi_2174_ = true;
                                                break;
                                            }
                                            let _e1070 = local_2[_e1056][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1067 {
                                            } else {
                                                phi_2174_ = true;
                                                break;
                                            }
                                            let _e1073 = local_3[_e1056][1u];
                                            phi_1578_ = vec2<f32>(_e1070, _e1073);
                                        } else {
                                            phi_1578_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1076 = phi_1578_;
                                        phi_1579_ = _e1076;
                                    }
                                    let _e1078 = phi_1579_;
                                    let _e1091 = frame.member[0u].member_1.member_6;
                                    phi_1610_ = 0u;
                                    phi_1613_ = _e987;
                                    loop {
                                        let _e1094 = phi_1610_;
                                        let _e1096 = phi_1613_;
                                        local_11 = _e1096;
                                        let _e1097 = (_e1094 < _e1091);
                                        if _e1097 {
                                            let _e1098 = ((((_e1040 * _e1009) + _e1035) * _e1091) + _e1094);
                                            if (_e1098 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2064_ = true;
                                                break;
                                            }
                                            let _e1101 = sd_map.member[_e1098];
                                            let _e1108 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1111 = ((_e1101 * (_e342 - _e1108)) + _e1108);
                                            let _e1121 = (((((2f * ((f32((bitcast<i32>(_e1035) - _e1043)) + _e1078.x) / _e1000)) - 1f) * _e1111) * _e658) - _e560.member_1.member_4.x);
                                            let _e1122 = ((((1f - (2f * ((f32((bitcast<i32>(_e1040) - _e1043)) + _e1078.y) / _e1001))) * _e1111) * _e669) - _e560.member_1.member_4.y);
                                            let _e1123 = (-(_e1111) - _e560.member_1.member_4.z);
                                            let _e1128 = (((_e1121 * _e560.member_1.member_6.x) + (_e1122 * _e560.member_1.member_6.y)) + (_e1123 * _e560.member_1.member_6.z));
                                            if _e586 {
                                                let _e1133 = (((_e1121 * _e1121) + (_e1122 * _e1122)) + (_e1123 * _e1123));
                                                if (_e1133 <= 0f) {
                                                    phi_1746_ = 0f;
                                                } else {
                                                    let _e1146 = (((((_e560.member_1.member_5.x * _e1121) + (_e560.member_1.member_5.y * _e1122)) + (_e560.member_1.member_5.z * _e1123)) / sqrt(_e1133)) - 0.1f);
                                                    if (_e1146 > 0f) {
                                                        phi_1719_ = select(1f, _e1146, (_e1146 < 1f));
                                                    } else {
                                                        phi_1719_ = 0f;
                                                    }
                                                    let _e1151 = phi_1719_;
                                                    let _e1154 = (1f - (_e1133 / (_e320 * _e320)));
                                                    if (_e1154 > 0f) {
                                                        phi_1732_ = select(1f, _e1154, (_e1154 < 1f));
                                                    } else {
                                                        phi_1732_ = 0f;
                                                    }
                                                    let _e1159 = phi_1732_;
                                                    let _e1161 = ((_e1151 * _e1159) / _e608);
                                                    if (_e1161 > 0f) {
                                                        phi_1745_ = select(1f, _e1161, (_e1161 < 1f));
                                                    } else {
                                                        phi_1745_ = 0f;
                                                    }
                                                    let _e1166 = phi_1745_;
                                                    phi_1746_ = _e1166;
                                                }
                                                let _e1168 = phi_1746_;
                                                phi_1776_ = _e1168;
                                            } else {
                                                let _e1174 = frame.member[0u].member_1.member.member_3;
                                                if (_e624 != _e624) {
                                                    phi_2014_ = true;
                                                } else {
                                                    phi_2014_ = (_e1128 >= _e624);
                                                }
                                                let _e1179 = phi_2014_;
                                                let _e1181 = (_e603 - select(_e624, _e1128, _e1179));
                                                if (_e1181 != _e1181) {
                                                    phi_2029_ = true;
                                                } else {
                                                    phi_2029_ = (0f >= _e1181);
                                                }
                                                let _e1185 = phi_2029_;
                                                let _e1190 = ((_e1128 - ((1f + _e1174) * _e560.member_1.member_2)) * (1f / _e603));
                                                if (_e1190 > 0f) {
                                                    phi_1769_ = select(1f, _e1190, (_e1190 < 1f));
                                                } else {
                                                    phi_1769_ = 0f;
                                                }
                                                let _e1195 = phi_1769_;
                                                phi_1776_ = ((select(_e1181, 0f, _e1185) + (_e1195 * (_e603 - _e624))) * (0.5f / _e603));
                                            }
                                            let _e1202 = phi_1776_;
                                            if _e586 {
                                                if (_e1096 != _e1096) {
                                                    phi_2044_ = true;
                                                } else {
                                                    phi_2044_ = (_e1202 >= _e1096);
                                                }
                                                let _e1206 = phi_2044_;
                                                phi_1785_ = select(_e1096, _e1202, _e1206);
                                            } else {
                                                if (_e1096 != _e1096) {
                                                    phi_2059_ = true;
                                                } else {
                                                    phi_2059_ = (_e1202 <= _e1096);
                                                }
                                                let _e1211 = phi_2059_;
                                                phi_1785_ = select(_e1096, _e1202, _e1211);
                                            }
                                            let _e1214 = phi_1785_;
                                            phi_1611_ = (_e1094 + 1u);
                                            phi_1614_ = _e1214;
                                        } else {
                                            phi_1611_ = u32();
                                            phi_1614_ = f32();
                                        }
                                        let _e1217 = phi_1611_;
                                        let _e1219 = phi_1614_;
                                        continue;
                                        continuing {
                                            phi_1610_ = _e1217;
                                            phi_1613_ = _e1219;
                                            phi_2064_ = _e566;
                                            break if !(_e1097);
                                        }
                                    }
                                    let _e1222 = phi_2064_;
                                    phi_2174_ = _e1222;
                                    if _e1222 {
                                        break;
                                    }
                                    let _e1224 = local_11;
                                    phi_2176_ = _e1222;
                                    phi_1788_ = ((_e570 - _e983) + _e1224);
                                }
                                let _e1227 = phi_2176_;
                                let _e1229 = phi_1788_;
                                phi_2175_ = _e1227;
                                phi_757_ = (_e568 + 1u);
                                phi_760_ = _e1229;
                            } else {
                                phi_2175_ = _e566;
                                phi_757_ = u32();
                                phi_760_ = f32();
                            }
                            let _e1232 = phi_2175_;
                            let _e1234 = phi_757_;
                            let _e1236 = phi_760_;
                            continue;
                            continuing {
                                phi_2099_ = _e1232;
                                phi_756_ = _e1234;
                                phi_759_ = _e1236;
                                phi_2174_ = _e1232;
                                break if !(_e571);
                            }
                        }
                        let _e1239 = phi_2174_;
                        if _e1239 {
                            break;
                        }
                        let _e1244 = frame.member[0u].member_1.member_10;
                        let _e1245 = (_e1244 == 1u);
                        let _e1249 = local_12;
                        let _e1251 = (_e309 + ((select(2f, 1f, _e1245) * 0.125f) * _e1249));
                        if _e1245 {
                            phi_1809_ = (1f - (2f * _e1251));
                        } else {
                            phi_1809_ = _e1251;
                        }
                        let _e1255 = phi_1809_;
                        if (_e1255 > 0f) {
                            phi_1819_ = select(1f, _e1255, (_e1255 < 1f));
                        } else {
                            phi_1819_ = 0f;
                        }
                        let _e1260 = phi_1819_;
                        let _e1266 = frame.member[0u].member_1.member.member_2;
                        phi_1823_ = pow(_e1260, _e1266);
                    } else {
                        phi_1823_ = _e309;
                    }
                    let _e1269 = phi_1823_;
                    phi_1824_ = _e1269;
                }
                let _e1271 = phi_1824_;
                if _e306 {
                } else {
                    break;
                }
                ao.member[_e305] = _e1271;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn raysd_pass2_(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
