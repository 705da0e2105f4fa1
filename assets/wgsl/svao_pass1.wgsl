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
    member_12: u32,
    member_13: u32,
    member_14: u32,
    member_15: u32,
}

struct type_37 {
    member: type_35,
    member_1: type_36,
}

struct type_39 {
    member: array<type_37>,
}

struct type_42 {
    member: f32,
    member_1: f32,
}

struct type_43 {
    member: f32,
    member_1: u32,
}

struct type_46 {
    member: array<atomic<u32>>,
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
var<storage, read_write> mask: type_11;
@group(0) @binding(5) 
var<storage, read_write> ray_min: type_46;
@group(0) @binding(6) 
var<storage, read_write> ray_max: type_46;
@group(0) @binding(7) 
var<storage> depth2_: type_8;

fn function_() {
    var local: array<array<f32, 2>, 56>;
    var local_1: array<f32, 56>;
    var local_2: array<f32, 56>;
    var local_3: array<f32, 56>;
    var local_4: array<f32, 56>;
    var local_5: array<f32, 56>;
    var local_6: array<array<array<f32, 2>, 4>, 4>;
    var phi_730_: bool;
    var phi_732_: bool;
    var phi_733_: bool;
    var phi_734_: bool;
    var phi_735_: bool;
    var phi_793_: bool;
    var phi_823_: f32;
    var phi_2136_: bool;
    var phi_2151_: bool;
    var phi_899_: vec2<f32>;
    var phi_926_: vec3<f32>;
    var phi_2166_: bool;
    var phi_1038_: type_28;
    var phi_1039_: type_28;
    var phi_1041_: type_28;
    var phi_1042_: type_28;
    var phi_1043_: bool;
    var phi_1047_: type_28;
    var phi_1069_: u32;
    var phi_1072_: u32;
    var phi_1074_: f32;
    var phi_1139_: f32;
    var phi_1164_: f32;
    var phi_1177_: f32;
    var phi_1290_: bool;
    var phi_2272_: bool;
    var phi_2287_: bool;
    var phi_1480_: f32;
    var phi_2302_: bool;
    var phi_1503_: f32;
    var phi_2354_: bool;
    var phi_2369_: bool;
    var phi_1701_: f32;
    var phi_2384_: bool;
    var phi_2399_: bool;
    var phi_2414_: bool;
    var phi_1715_: f32;
    var phi_1721_: type_42;
    var phi_1737_: f32;
    var phi_1756_: bool;
    var phi_1757_: bool;
    var phi_1769_: f32;
    var phi_2429_: bool;
    var phi_1788_: f32;
    var phi_2444_: bool;
    var phi_2459_: bool;
    var phi_1940_: f32;
    var phi_1947_: u32;
    var phi_1961_: u32;
    var phi_1969_: u32;
    var phi_1070_: u32;
    var phi_1073_: u32;
    var phi_1075_: f32;
    var phi_2503_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_2002_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2031_: type_43;
    var phi_2036_: type_43;

    switch bitcast<i32>(0u) {
        default: {
            let _e486 = id_1;
            let _e491 = arrayLength((&depth.member));
            let _e502 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e514 = frame.member[0u].member_1.member.member.member_4;
            let _e515 = (_e486.x + _e514);
            let _e516 = (_e486.y + _e514);
            let _e529 = frame.member[0u].member_1.member.member.member[0u];
            let _e534 = select(select(u32(_e529), 0u, (_e529 < 0f)), 4294967295u, (_e529 > 4294967000f));
            let _e542 = frame.member[0u].member_1.member.member.member[1u];
            if (_e515 >= _e514) {
                if (_e516 >= _e514) {
                    let _e551 = ((_e515 + _e514) < _e534);
                    if _e551 {
                        phi_730_ = ((_e516 + _e514) < select(select(u32(_e542), 0u, (_e542 < 0f)), 4294967295u, (_e542 > 4294967000f)));
                    } else {
                        phi_730_ = bool();
                    }
                    let _e555 = phi_730_;
                    phi_732_ = _e555;
                    phi_733_ = select(true, false, _e551);
                } else {
                    phi_732_ = bool();
                    phi_733_ = true;
                }
                let _e558 = phi_732_;
                let _e560 = phi_733_;
                phi_734_ = _e558;
                phi_735_ = _e560;
            } else {
                phi_734_ = bool();
                phi_735_ = true;
            }
            let _e562 = phi_734_;
            let _e564 = phi_735_;
            if select(_e562, false, _e564) {
                let _e571 = frame.member[0u].member_1.member.member_1;
                let _e577 = frame.member[0u].member_1.member.member_4;
                let _e582 = ((f32(_e515) + 0.5f) / _e529);
                let _e583 = ((f32(_e516) + 0.5f) / _e542);
                let _e585 = ((_e516 * _e534) + _e515);
                if (_e585 < _e491) {
                } else {
                    break;
                }
                let _e588 = depth.member[_e585];
                let _e595 = frame.member[0u].member_1.member.member.member_3;
                if (_e588 > 0f) {
                    phi_793_ = (_e588 < _e595);
                } else {
                    phi_793_ = false;
                }
                let _e599 = phi_793_;
                if _e599 {
                    let _e607 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e615 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e625 = (0.5f * (((_e571 * _e529) / ((2f * _e607) * _e588)) + ((_e571 * _e542) / ((2f * _e615) * _e588))));
                    let _e626 = (_e625 > _e577);
                    if _e626 {
                        phi_823_ = ((_e571 * _e577) / _e625);
                    } else {
                        phi_823_ = _e571;
                    }
                    let _e630 = phi_823_;
                    let _e631 = select(_e625, _e577, _e626);
                    let _e632 = (_e631 < 0.5f);
                    if _e632 {
                        phi_1038_ = type_28(0u, type_28().member_1);
                        phi_1039_ = type_28();
                    } else {
                        let _e641 = ((((_e582 * 2f) - 1f) * _e588) * _e607);
                        let _e643 = ((((_e583 * -2f) + 1f) * _e588) * _e615);
                        let _e644 = -(_e588);
                        if (_e585 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e648 = normals.member[_e585];
                        let _e656 = (f32((bitcast<i32>(((_e648 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e656 != _e656) {
                            phi_2136_ = true;
                        } else {
                            phi_2136_ = (-1f >= _e656);
                        }
                        let _e660 = phi_2136_;
                        let _e661 = select(_e656, -1f, _e660);
                        let _e671 = (f32((bitcast<i32>((((_e648 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e671 != _e671) {
                            phi_2151_ = true;
                        } else {
                            phi_2151_ = (-1f >= _e671);
                        }
                        let _e675 = phi_2151_;
                        let _e676 = select(_e671, -1f, _e675);
                        let _e679 = (1f - abs(_e661));
                        let _e680 = abs(_e676);
                        let _e681 = (_e679 - _e680);
                        if (_e681 < 0f) {
                            phi_899_ = vec2<f32>(((1f - _e680) * select(1f, -1f, (_e661 < 0f))), (_e679 * select(1f, -1f, (_e676 < 0f))));
                        } else {
                            phi_899_ = vec2<f32>(_e661, _e676);
                        }
                        let _e692 = phi_899_;
                        let _e701 = (1f / sqrt((((_e692.x * _e692.x) + (_e692.y * _e692.y)) + (_e681 * _e681))));
                        let _e702 = (_e692.x * _e701);
                        let _e703 = (_e692.y * _e701);
                        let _e704 = (_e681 * _e701);
                        if ((((_e641 * _e702) + (_e643 * _e703)) + (_e644 * _e704)) > 0f) {
                            phi_926_ = vec3<f32>(-(_e702), -(_e703), -(_e704));
                        } else {
                            phi_926_ = vec3<f32>(_e702, _e703, _e704);
                        }
                        let _e717 = phi_926_;
                        local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e718 = (_e516 % 4u);
                        if (_e718 < 4u) {
                        } else {
                            break;
                        }
                        let _e720 = (_e515 % 4u);
                        if (_e720 < 4u) {
                        } else {
                            break;
                        }
                        let _e724 = local_6[_e718][_e720];
                        let _e734 = sqrt((((_e641 * _e641) + (_e643 * _e643)) + (_e644 * _e644)));
                        let _e735 = (-(_e641) / _e734);
                        let _e736 = (-(_e643) / _e734);
                        let _e737 = (_e588 / _e734);
                        let _e740 = -((_e724[1] * _e737));
                        let _e741 = (_e737 * _e724[0]);
                        let _e744 = ((_e735 * _e724[1]) - (_e724[0] * _e736));
                        let _e751 = (1f / sqrt((((_e740 * _e740) + (_e741 * _e741)) + (_e744 * _e744))));
                        let _e752 = (_e740 * _e751);
                        let _e753 = (_e741 * _e751);
                        let _e754 = (_e744 * _e751);
                        let _e758 = ((_e753 * _e737) - (_e736 * _e754));
                        let _e761 = ((_e754 * _e735) - (_e737 * _e752));
                        let _e764 = ((_e752 * _e736) - (_e735 * _e753));
                        let _e783 = (((_e717.x * _e735) + (_e717.y * _e736)) + (_e717.z * _e737));
                        let _e787 = abs(_e783);
                        if (_e787 != _e787) {
                            phi_2166_ = true;
                        } else {
                            phi_2166_ = (0.0001f >= _e787);
                        }
                        let _e791 = phi_2166_;
                        phi_1038_ = type_28();
                        phi_1039_ = type_28(1u, type_27(vec2<u32>(_e515, _e516), vec2<f32>(_e582, _e583), _e630, _e631, vec3<f32>(_e641, _e643, _e644), _e717, vec3<f32>(_e735, _e736, _e737), vec3<f32>(_e758, _e761, _e764), vec3<f32>(_e752, _e753, _e754), vec3<f32>((((_e717.x * _e758) + (_e717.y * _e761)) + (_e717.z * _e764)), (((_e717.x * _e752) + (_e717.y * _e753)) + (_e717.z * _e754)), _e783), (1f / (select(1f, -1f, (_e783 < 0f)) * select(_e787, 0.0001f, _e791)))));
                    }
                    let _e800 = phi_1038_;
                    let _e802 = phi_1039_;
                    phi_1041_ = _e800;
                    phi_1042_ = _e802;
                    phi_1043_ = _e632;
                } else {
                    phi_1041_ = type_28(0u, type_28().member_1);
                    phi_1042_ = type_28();
                    phi_1043_ = true;
                }
                let _e807 = phi_1041_;
                let _e809 = phi_1042_;
                let _e811 = phi_1043_;
                if _e811 {
                    phi_1047_ = _e807;
                } else {
                    phi_1047_ = _e809;
                }
                let _e813 = phi_1047_;
                if (bitcast<i32>(_e813.member) != 0i) {
                    let _e827 = sqrt((((_e813.member_1.member_4.x * _e813.member_1.member_4.x) + (_e813.member_1.member_4.y * _e813.member_1.member_4.y)) + (_e813.member_1.member_4.z * _e813.member_1.member_4.z)));
                    phi_1069_ = 0u;
                    phi_1072_ = 0u;
                    phi_1074_ = 0f;
                    loop {
                        let _e829 = phi_1069_;
                        let _e831 = phi_1072_;
                        let _e833 = phi_1074_;
                        let _e838 = frame.member[0u].member_1.member_11;
                        local_8 = _e833;
                        local_9 = _e831;
                        local_10 = _e831;
                        local_11 = _e831;
                        let _e843 = (8u << bitcast<u32>((select(_e838, 2u, (2u < _e838)) & 31u)));
                        let _e844 = (_e829 < _e843);
                        local_7 = _e843;
                        if _e844 {
                            let _e849 = frame.member[0u].member_1.member_1;
                            let _e850 = (_e849 == 1u);
                            let _e856 = frame.member[0u].member_1.member_10;
                            let _e858 = ((_e843 + _e829) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e859 = (_e858 < 56u);
                            if _e859 {
                            } else {
                                phi_2503_ = true;
                                break;
                            }
                            let _e861 = local[_e858];
                            let _e864 = (_e856 == 1u);
                            if _e864 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e859 {
                                } else {
                                    phi_2503_ = true;
                                    break;
                                }
                                let _e866 = local_1[_e858];
                                phi_1139_ = _e866;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e859 {
                                } else {
                                    phi_2503_ = true;
                                    break;
                                }
                                let _e868 = local_2[_e858];
                                phi_1139_ = _e868;
                            }
                            let _e870 = phi_1139_;
                            let _e872 = (_e813.member_1.member_2 * _e870);
                            let _e873 = (_e872 * _e861[0]);
                            let _e874 = (_e872 * _e861[1]);
                            if _e864 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e859 {
                                } else {
                                    phi_2503_ = true;
                                    break;
                                }
                                let _e876 = local_3[_e858];
                                phi_1164_ = _e876;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e859 {
                                } else {
                                    phi_2503_ = true;
                                    break;
                                }
                                let _e878 = local_4[_e858];
                                phi_1164_ = _e878;
                            }
                            let _e880 = phi_1164_;
                            let _e881 = (_e813.member_1.member_2 * _e880);
                            if _e864 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e859 {
                                } else {
                                    phi_2503_ = true;
                                    break;
                                }
                                let _e883 = local_5[_e858];
                                phi_1177_ = _e883;
                            } else {
                                phi_1177_ = (_e881 * 2f);
                            }
                            let _e886 = phi_1177_;
                            let _e895 = (-(((_e873 * _e813.member_1.member_9.x) + (_e874 * _e813.member_1.member_9.y))) * _e813.member_1.member_10);
                            let _e896 = -(_e881);
                            let _e900 = select(_e896, select(_e881, _e895, (_e895 < _e881)), (_e895 > _e896));
                            let _e901 = (_e881 - _e900);
                            let _e903 = (_e901 > (_e881 * 0.2f));
                            let _e924 = (-0.5f / ((_e813.member_1.member_4.z + (_e813.member_1.member_7.z * _e873)) + (_e813.member_1.member_8.z * _e874)));
                            let _e933 = frame.member[0u].member_1.member.member.member_1[0u];
                            let _e935 = (((((_e813.member_1.member_4.x + (_e813.member_1.member_7.x * _e873)) + (_e813.member_1.member_8.x * _e874)) * _e924) / _e933) + 0.5f);
                            let _e944 = frame.member[0u].member_1.member.member.member_1[1u];
                            let _e946 = (0.5f - ((((_e813.member_1.member_4.y + (_e813.member_1.member_7.y * _e873)) + (_e813.member_1.member_8.y * _e874)) * _e924) / _e944));
                            let _e954 = frame.member[0u].member_1.member.member;
                            let _e961 = select(select(u32(_e954.member.x), 0u, (_e954.member.x < 0f)), 4294967295u, (_e954.member.x > 4294967000f));
                            let _e972 = (select(0f, select(1f, _e935, (_e935 < 1f)), (_e935 > 0f)) * _e954.member.x);
                            let _e977 = (select(0f, select(1f, _e946, (_e946 < 1f)), (_e946 > 0f)) * _e954.member.y);
                            let _e982 = select(select(u32(_e972), 0u, (_e972 < 0f)), 4294967295u, (_e972 > 4294967000f));
                            let _e983 = (_e961 - 1u);
                            let _e985 = select(_e982, _e983, (_e983 < _e982));
                            let _e990 = select(select(u32(_e977), 0u, (_e977 < 0f)), 4294967295u, (_e977 > 4294967000f));
                            let _e991 = (select(select(u32(_e954.member.y), 0u, (_e954.member.y < 0f)), 4294967295u, (_e954.member.y > 4294967000f)) - 1u);
                            let _e993 = select(_e990, _e991, (_e991 < _e990));
                            let _e1000 = ((_e813.member_1.member_1.x - _e935) * _e529);
                            let _e1001 = ((_e813.member_1.member_1.y - _e946) * _e542);
                            let _e1005 = sqrt(((_e1000 * _e1000) + (_e1001 * _e1001)));
                            if (_e985 == _e813.member_1.member.x) {
                                phi_1290_ = (_e993 == _e813.member_1.member.y);
                            } else {
                                phi_1290_ = false;
                            }
                            let _e1013 = phi_1290_;
                            let _e1015 = ((_e993 * _e534) + _e985);
                            if (_e1015 < _e491) {
                            } else {
                                phi_2503_ = true;
                                break;
                            }
                            let _e1018 = depth.member[_e1015];
                            let _e1022 = select(_e595, _e1018, select(false, (_e1018 < _e595), (_e1018 > 0f)));
                            let _e1032 = ((((f32(_e985) + 0.5f) * (1f / _e954.member.x)) * 2f) - 1f);
                            let _e1034 = ((((f32(_e993) + 0.5f) * (1f / _e954.member.y)) * -2f) + 1f);
                            let _e1040 = (((_e1032 * _e1022) * _e933) - _e813.member_1.member_4.x);
                            let _e1041 = (((_e1034 * _e1022) * _e944) - _e813.member_1.member_4.y);
                            let _e1042 = (-(_e1022) - _e813.member_1.member_4.z);
                            let _e1051 = (((_e1040 * _e813.member_1.member_6.x) + (_e1041 * _e813.member_1.member_6.y)) + (_e1042 * _e813.member_1.member_6.z));
                            if _e864 {
                                let _e1056 = (((_e1040 * _e1040) + (_e1041 * _e1041)) + (_e1042 * _e1042));
                                let _e1068 = (((((_e813.member_1.member_5.x * _e1040) + (_e813.member_1.member_5.y * _e1041)) + (_e813.member_1.member_5.z * _e1042)) / sqrt(_e1056)) - 0.1f);
                                let _e1075 = (1f - (_e1056 / (_e571 * _e571)));
                                let _e1082 = ((select(0f, select(1f, _e1068, (_e1068 < 1f)), (_e1068 > 0f)) * select(0f, select(1f, _e1075, (_e1075 < 1f)), (_e1075 > 0f))) / _e886);
                                phi_1480_ = select(0f, select(0f, select(1f, _e1082, (_e1082 < 1f)), (_e1082 > 0f)), (_e1056 > 0f));
                            } else {
                                let _e1093 = frame.member[0u].member_1.member.member_3;
                                if (_e900 != _e900) {
                                    phi_2272_ = true;
                                } else {
                                    phi_2272_ = (_e1051 >= _e900);
                                }
                                let _e1098 = phi_2272_;
                                let _e1100 = (_e881 - select(_e900, _e1051, _e1098));
                                if (_e1100 != _e1100) {
                                    phi_2287_ = true;
                                } else {
                                    phi_2287_ = (0f >= _e1100);
                                }
                                let _e1104 = phi_2287_;
                                let _e1109 = ((_e1051 - (_e813.member_1.member_2 * (1f + _e1093))) * (1f / _e881));
                                phi_1480_ = ((select(_e1100, 0f, _e1104) + (select(0f, select(1f, _e1109, (_e1109 < 1f)), (_e1109 > 0f)) * _e901)) * (0.5f / _e881));
                            }
                            let _e1119 = phi_1480_;
                            let _e1124 = frame.member[0u].member_1.member_9;
                            if (_e1124 == 0u) {
                                phi_1721_ = type_42(_e1051, _e1119);
                            } else {
                                if _e864 {
                                    let _e1127 = (_e813.member_1.member_2 * 0.1f);
                                    if (_e881 != _e881) {
                                        phi_2302_ = true;
                                    } else {
                                        phi_2302_ = (_e1127 >= _e881);
                                    }
                                    let _e1131 = phi_2302_;
                                    phi_1503_ = select(_e881, _e1127, _e1131);
                                } else {
                                    let _e1138 = frame.member[0u].member_1.member.member_3;
                                    phi_1503_ = (_e813.member_1.member_2 * (1f + _e1138));
                                }
                                let _e1142 = phi_1503_;
                                let _e1148 = frame.member[0u].member_1.member_3;
                                let _e1150 = select(false, (_e1005 > _e1148), (_e1051 > _e1142));
                                let _e1152 = ((_e993 * _e961) + _e985);
                                if (_e1152 < arrayLength((&depth2_.member))) {
                                } else {
                                    phi_2503_ = true;
                                    break;
                                }
                                let _e1156 = depth2_.member[_e1152];
                                let _e1160 = select(_e595, _e1156, select(false, (_e1156 < _e595), (_e1156 > 0f)));
                                let _e1166 = (((_e1032 * _e1160) * _e933) - _e813.member_1.member_4.x);
                                let _e1167 = (((_e1034 * _e1160) * _e944) - _e813.member_1.member_4.y);
                                let _e1168 = (-(_e1160) - _e813.member_1.member_4.z);
                                let _e1173 = (((_e1166 * _e813.member_1.member_6.x) + (_e1167 * _e813.member_1.member_6.y)) + (_e1168 * _e813.member_1.member_6.z));
                                if _e864 {
                                    let _e1178 = (((_e1166 * _e1166) + (_e1167 * _e1167)) + (_e1168 * _e1168));
                                    let _e1190 = (((((_e813.member_1.member_5.x * _e1166) + (_e813.member_1.member_5.y * _e1167)) + (_e813.member_1.member_5.z * _e1168)) / sqrt(_e1178)) - 0.1f);
                                    let _e1197 = (1f - (_e1178 / (_e571 * _e571)));
                                    let _e1204 = ((select(0f, select(1f, _e1190, (_e1190 < 1f)), (_e1190 > 0f)) * select(0f, select(1f, _e1197, (_e1197 < 1f)), (_e1197 > 0f))) / _e886);
                                    phi_1701_ = select(0f, select(0f, select(1f, _e1204, (_e1204 < 1f)), (_e1204 > 0f)), (_e1178 > 0f));
                                } else {
                                    let _e1215 = frame.member[0u].member_1.member.member_3;
                                    if (_e900 != _e900) {
                                        phi_2354_ = true;
                                    } else {
                                        phi_2354_ = (_e1173 >= _e900);
                                    }
                                    let _e1220 = phi_2354_;
                                    let _e1222 = (_e881 - select(_e900, _e1173, _e1220));
                                    if (_e1222 != _e1222) {
                                        phi_2369_ = true;
                                    } else {
                                        phi_2369_ = (0f >= _e1222);
                                    }
                                    let _e1226 = phi_2369_;
                                    let _e1231 = ((_e1173 - (_e813.member_1.member_2 * (1f + _e1215))) * (1f / _e881));
                                    phi_1701_ = ((select(_e1222, 0f, _e1226) + (select(0f, select(1f, _e1231, (_e1231 < 1f)), (_e1231 > 0f)) * _e901)) * (0.5f / _e881));
                                }
                                let _e1241 = phi_1701_;
                                if (_e1051 != _e1051) {
                                    phi_2384_ = true;
                                } else {
                                    phi_2384_ = (_e1173 <= _e1051);
                                }
                                let _e1245 = phi_2384_;
                                if _e864 {
                                    if (_e1119 != _e1119) {
                                        phi_2399_ = true;
                                    } else {
                                        phi_2399_ = (_e1241 >= _e1119);
                                    }
                                    let _e1251 = phi_2399_;
                                    phi_1715_ = select(_e1119, _e1241, _e1251);
                                } else {
                                    if (_e1119 != _e1119) {
                                        phi_2414_ = true;
                                    } else {
                                        phi_2414_ = (_e1241 <= _e1119);
                                    }
                                    let _e1256 = phi_2414_;
                                    phi_1715_ = select(_e1119, _e1241, _e1256);
                                }
                                let _e1259 = phi_1715_;
                                phi_1721_ = type_42(select(_e1051, select(_e1051, _e1173, _e1245), _e1150), select(_e1119, _e1259, _e1150));
                            }
                            let _e1263 = phi_1721_;
                            if _e864 {
                                phi_1737_ = 0f;
                            } else {
                                phi_1737_ = (_e901 / (_e881 * 2f));
                            }
                            let _e1269 = phi_1737_;
                            if (_e849 == 2u) {
                                phi_1757_ = true;
                            } else {
                                if _e850 {
                                    let _e1277 = frame.member[0u].member_1.member_4;
                                    phi_1756_ = (_e1277 > 0u);
                                } else {
                                    phi_1756_ = false;
                                }
                                let _e1280 = phi_1756_;
                                phi_1757_ = _e1280;
                            }
                            let _e1282 = phi_1757_;
                            let _e1283 = select(false, _e1282, !(select(false, select(false, (_e946 <= 1f), (_e946 >= 0f)), select(false, (_e935 <= 1f), (_e935 >= 0f)))));
                            if _e850 {
                                phi_1769_ = select(_e1263.member, 0x1.fffffep+127f, _e1283);
                            } else {
                                phi_1769_ = _e1263.member;
                            }
                            let _e1286 = phi_1769_;
                            if _e864 {
                                let _e1288 = (_e813.member_1.member_2 * 0.1f);
                                if (_e881 != _e881) {
                                    phi_2429_ = true;
                                } else {
                                    phi_2429_ = (_e1288 >= _e881);
                                }
                                let _e1292 = phi_2429_;
                                phi_1788_ = select(_e881, _e1288, _e1292);
                            } else {
                                let _e1299 = frame.member[0u].member_1.member.member_3;
                                phi_1788_ = (_e813.member_1.member_2 * (1f + _e1299));
                            }
                            let _e1303 = phi_1788_;
                            let _e1309 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e1005 > _e1309), (_e1286 > _e1303)), true, _e1283), (_e849 != 0u)), select(false, !(_e1013), _e903)) {
                                if (_e849 != 1u) {
                                } else {
                                    let _e1328 = frame.member[0u].member_1.member_5[0u];
                                    let _e1334 = frame.member[0u].member_1.member_5[1u];
                                    let _e1341 = frame.member[0u].member_1.member_4;
                                    let _e1342 = f32(_e1341);
                                    let _e1343 = (2u * _e1341);
                                    let _e1344 = (_e1328 + _e1343);
                                    let _e1350 = (floor((_e935 * f32(_e1328))) + _e1342);
                                    let _e1351 = f32((_e1344 - 1u));
                                    let _e1355 = select(0f, select(_e1351, _e1350, (_e1350 < _e1351)), (_e1350 > 0f));
                                    let _e1358 = (floor((_e946 * f32(_e1334))) + _e1342);
                                    let _e1359 = f32(((_e1334 + _e1343) - 1u));
                                    let _e1363 = select(0f, select(_e1359, _e1358, (_e1358 < _e1359)), (_e1358 > 0f));
                                    let _e1375 = ((select(select(u32(_e1363), 0u, (_e1363 < 0f)), 4294967295u, (_e1363 > 4294967000f)) * _e1344) + select(select(u32(_e1355), 0u, (_e1355 < 0f)), 4294967295u, (_e1355 > 4294967000f)));
                                    let _e1380 = frame.member[0u].member_1.member_2;
                                    if (_e1380 == 0u) {
                                        if (_e1375 < _e502) {
                                        } else {
                                            phi_2503_ = true;
                                            break;
                                        }
                                        let _e1385 = atomicMax((&ray_max.member[_e1375]), 1u);
                                    } else {
                                        if _e864 {
                                            if (_e1286 != _e1286) {
                                                phi_2444_ = true;
                                            } else {
                                                phi_2444_ = (_e881 <= _e1286);
                                            }
                                            let _e1389 = phi_2444_;
                                            phi_1940_ = select(_e1286, _e881, _e1389);
                                        } else {
                                            let _e1396 = frame.member[0u].member_1.member.member_3;
                                            let _e1399 = (((1f + _e1396) * _e813.member_1.member_2) + _e881);
                                            if (_e1286 != _e1286) {
                                                phi_2459_ = true;
                                            } else {
                                                phi_2459_ = (_e1399 <= _e1286);
                                            }
                                            let _e1403 = phi_2459_;
                                            phi_1940_ = select(_e1286, _e1399, _e1403);
                                        }
                                        let _e1406 = phi_1940_;
                                        let _e1407 = (_e827 - _e1406);
                                        if (_e1407 > 0f) {
                                            phi_1947_ = bitcast<u32>(_e1407);
                                        } else {
                                            phi_1947_ = 0u;
                                        }
                                        let _e1411 = phi_1947_;
                                        if (_e1375 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2503_ = true;
                                            break;
                                        }
                                        let _e1415 = atomicMin((&ray_min.member[_e1375]), _e1411);
                                        let _e1416 = (_e827 - _e900);
                                        if (_e1416 > 0f) {
                                            phi_1961_ = bitcast<u32>(_e1416);
                                        } else {
                                            phi_1961_ = 0u;
                                        }
                                        let _e1420 = phi_1961_;
                                        if (_e1375 < _e502) {
                                        } else {
                                            phi_2503_ = true;
                                            break;
                                        }
                                        let _e1424 = atomicMax((&ray_max.member[_e1375]), _e1420);
                                    }
                                }
                                phi_1969_ = (_e831 | (1u << bitcast<u32>((_e829 & 31u))));
                            } else {
                                phi_1969_ = _e831;
                            }
                            let _e1426 = phi_1969_;
                            phi_1070_ = (_e829 + 1u);
                            phi_1073_ = _e1426;
                            phi_1075_ = (_e833 + select(0f, select(_e1263.member_1, _e1269, _e1013), _e903));
                        } else {
                            phi_1070_ = u32();
                            phi_1073_ = u32();
                            phi_1075_ = f32();
                        }
                        let _e1429 = phi_1070_;
                        let _e1431 = phi_1073_;
                        let _e1433 = phi_1075_;
                        continue;
                        continuing {
                            phi_1069_ = _e1429;
                            phi_1072_ = _e1431;
                            phi_1074_ = _e1433;
                            phi_2503_ = false;
                            break if !(_e844);
                        }
                    }
                    let _e1436 = phi_2503_;
                    if _e1436 {
                        break;
                    }
                    let _e1441 = frame.member[0u].member_1.member_10;
                    let _e1442 = (_e1441 == 1u);
                    let _e1445 = local_7;
                    let _e1449 = local_8;
                    let _e1450 = ((select(2f, 1f, _e1442) / f32(_e1445)) * _e1449);
                    let _e1452 = local_9;
                    if (_e1452 == 0u) {
                        if _e1442 {
                            phi_2002_ = (1f - (2f * _e1450));
                        } else {
                            phi_2002_ = _e1450;
                        }
                        let _e1457 = phi_2002_;
                        let _e1467 = frame.member[0u].member_1.member.member_2;
                        let _e1470 = local_10;
                        phi_2031_ = type_43(pow(select(0f, select(1f, _e1457, (_e1457 < 1f)), (_e1457 > 0f)), _e1467), _e1470);
                    } else {
                        let _e1480 = local_11;
                        phi_2031_ = type_43((round((select(0f, select(1f, _e1450, (_e1450 < 1f)), (_e1450 > 0f)) * 255f)) * 0.003921569f), _e1480);
                    }
                    let _e1483 = phi_2031_;
                    phi_2036_ = _e1483;
                } else {
                    phi_2036_ = type_43(1f, 0u);
                }
                let _e1485 = phi_2036_;
                if (_e585 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e585] = _e1485.member;
                if (_e585 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e585] = _e1485.member_1;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn svao_pass1_(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
