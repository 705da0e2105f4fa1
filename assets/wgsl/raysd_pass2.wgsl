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

struct type_41 {
    member: f32,
    member_1: f32,
}

struct type_42 {
    member: f32,
    member_1: u32,
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
    var local_4: array<array<f32, 2>, 56>;
    var local_5: array<f32, 56>;
    var local_6: array<f32, 56>;
    var local_7: array<f32, 56>;
    var local_8: array<f32, 56>;
    var local_9: array<f32, 56>;
    var local_10: array<array<array<f32, 2>, 4>, 4>;
    var phi_714_: bool;
    var phi_716_: bool;
    var phi_717_: bool;
    var phi_718_: bool;
    var phi_719_: bool;
    var phi_843_: f32;
    var phi_2220_: bool;
    var phi_2235_: bool;
    var phi_919_: vec2<f32>;
    var phi_946_: vec3<f32>;
    var phi_2250_: bool;
    var phi_1058_: type_28;
    var phi_1059_: type_28;
    var phi_1061_: type_28;
    var phi_1062_: type_28;
    var phi_1063_: bool;
    var phi_1067_: type_28;
    var phi_2483_: bool;
    var phi_1085_: u32;
    var phi_1088_: u32;
    var phi_1090_: f32;
    var phi_1138_: f32;
    var phi_1163_: f32;
    var phi_1176_: f32;
    var phi_1304_: u32;
    var phi_1335_: u32;
    var phi_2265_: bool;
    var phi_2280_: bool;
    var phi_1545_: f32;
    var phi_2295_: bool;
    var phi_1568_: f32;
    var phi_2310_: bool;
    var phi_2325_: bool;
    var phi_1762_: f32;
    var phi_2340_: bool;
    var phi_2355_: bool;
    var phi_2370_: bool;
    var phi_1776_: f32;
    var phi_1782_: type_41;
    var phi_1795_: f32;
    var phi_1928_: vec2<f32>;
    var phi_1929_: vec2<f32>;
    var phi_1960_: u32;
    var phi_1963_: f32;
    var phi_2385_: bool;
    var phi_2400_: bool;
    var phi_2128_: f32;
    var phi_2415_: bool;
    var phi_2430_: bool;
    var phi_2137_: f32;
    var phi_1961_: u32;
    var phi_1964_: f32;
    var phi_2435_: bool;
    var local_11: f32;
    var phi_2552_: bool;
    var phi_2142_: f32;
    var phi_2551_: bool;
    var phi_1086_: u32;
    var phi_1091_: f32;
    var phi_2550_: bool;
    var local_12: f32;
    var phi_2172_: f32;
    var local_13: u32;
    var phi_2187_: type_42;
    var phi_2189_: type_42;
    var phi_2190_: bool;
    var phi_2194_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e547 = id_1;
            let _e552 = arrayLength((&depth.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e574 = frame.member[0u].member_1.member.member.member_4;
            let _e575 = (_e547.x + _e574);
            let _e576 = (_e547.y + _e574);
            let _e584 = frame.member[0u].member_1.member.member.member[0u];
            let _e589 = select(select(u32(_e584), 0u, (_e584 < 0f)), 4294967295u, (_e584 > 4294967000f));
            let _e597 = frame.member[0u].member_1.member.member.member[1u];
            let _e602 = select(select(u32(_e597), 0u, (_e597 < 0f)), 4294967295u, (_e597 > 4294967000f));
            if (_e575 >= _e574) {
                if (_e576 >= _e574) {
                    let _e606 = ((_e575 + _e574) < _e589);
                    if _e606 {
                        phi_714_ = ((_e576 + _e574) < _e602);
                    } else {
                        phi_714_ = bool();
                    }
                    let _e610 = phi_714_;
                    phi_716_ = _e610;
                    phi_717_ = select(true, false, _e606);
                } else {
                    phi_716_ = bool();
                    phi_717_ = true;
                }
                let _e613 = phi_716_;
                let _e615 = phi_717_;
                phi_718_ = _e613;
                phi_719_ = _e615;
            } else {
                phi_718_ = bool();
                phi_719_ = true;
            }
            let _e617 = phi_718_;
            let _e619 = phi_719_;
            if select(_e617, false, _e619) {
                let _e622 = ((_e576 * _e589) + _e575);
                let _e623 = (_e622 < arrayLength((&ao.member)));
                if _e623 {
                } else {
                    break;
                }
                let _e626 = ao.member[_e622];
                if (_e622 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e630 = mask.member[_e622];
                if (_e630 == 0u) {
                    phi_2189_ = type_42();
                    phi_2190_ = true;
                } else {
                    let _e638 = frame.member[0u].member_1.member.member_1;
                    let _e644 = frame.member[0u].member_1.member.member_4;
                    let _e649 = ((f32(_e575) + 0.5f) / _e584);
                    let _e650 = ((f32(_e576) + 0.5f) / _e597);
                    if (_e622 < _e552) {
                    } else {
                        break;
                    }
                    let _e653 = depth.member[_e622];
                    let _e660 = frame.member[0u].member_1.member.member.member_3;
                    if select(false, (_e653 < _e660), (_e653 > 0f)) {
                        let _e671 = frame.member[0u].member_1.member.member.member_1[0u];
                        let _e679 = frame.member[0u].member_1.member.member.member_1[1u];
                        let _e689 = (0.5f * (((_e638 * _e584) / ((2f * _e671) * _e653)) + ((_e638 * _e597) / ((2f * _e679) * _e653))));
                        let _e690 = (_e689 > _e644);
                        if _e690 {
                            phi_843_ = ((_e638 * _e644) / _e689);
                        } else {
                            phi_843_ = _e638;
                        }
                        let _e694 = phi_843_;
                        let _e695 = select(_e689, _e644, _e690);
                        let _e696 = (_e695 < 0.5f);
                        if _e696 {
                            phi_1058_ = type_28(0u, type_28().member_1);
                            phi_1059_ = type_28();
                        } else {
                            let _e705 = ((((_e649 * 2f) - 1f) * _e653) * _e671);
                            let _e707 = ((((_e650 * -2f) + 1f) * _e653) * _e679);
                            let _e708 = -(_e653);
                            if (_e622 < arrayLength((&normals.member))) {
                            } else {
                                break;
                            }
                            let _e712 = normals.member[_e622];
                            let _e720 = (f32((bitcast<i32>(((_e712 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e720 != _e720) {
                                phi_2220_ = true;
                            } else {
                                phi_2220_ = (-1f >= _e720);
                            }
                            let _e724 = phi_2220_;
                            let _e725 = select(_e720, -1f, _e724);
                            let _e735 = (f32((bitcast<i32>((((_e712 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e735 != _e735) {
                                phi_2235_ = true;
                            } else {
                                phi_2235_ = (-1f >= _e735);
                            }
                            let _e739 = phi_2235_;
                            let _e740 = select(_e735, -1f, _e739);
                            let _e743 = (1f - abs(_e725));
                            let _e744 = abs(_e740);
                            let _e745 = (_e743 - _e744);
                            if (_e745 < 0f) {
                                phi_919_ = vec2<f32>(((1f - _e744) * select(1f, -1f, (_e725 < 0f))), (_e743 * select(1f, -1f, (_e740 < 0f))));
                            } else {
                                phi_919_ = vec2<f32>(_e725, _e740);
                            }
                            let _e756 = phi_919_;
                            let _e765 = (1f / sqrt((((_e756.x * _e756.x) + (_e756.y * _e756.y)) + (_e745 * _e745))));
                            let _e766 = (_e756.x * _e765);
                            let _e767 = (_e756.y * _e765);
                            let _e768 = (_e745 * _e765);
                            if ((((_e705 * _e766) + (_e707 * _e767)) + (_e708 * _e768)) > 0f) {
                                phi_946_ = vec3<f32>(-(_e766), -(_e767), -(_e768));
                            } else {
                                phi_946_ = vec3<f32>(_e766, _e767, _e768);
                            }
                            let _e781 = phi_946_;
                            local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                            let _e782 = (_e576 % 4u);
                            if (_e782 < 4u) {
                            } else {
                                break;
                            }
                            let _e784 = (_e575 % 4u);
                            if (_e784 < 4u) {
                            } else {
                                break;
                            }
                            let _e788 = local_10[_e782][_e784];
                            let _e798 = sqrt((((_e705 * _e705) + (_e707 * _e707)) + (_e708 * _e708)));
                            let _e799 = (-(_e705) / _e798);
                            let _e800 = (-(_e707) / _e798);
                            let _e801 = (_e653 / _e798);
                            let _e804 = -((_e788[1] * _e801));
                            let _e805 = (_e801 * _e788[0]);
                            let _e808 = ((_e799 * _e788[1]) - (_e788[0] * _e800));
                            let _e815 = (1f / sqrt((((_e804 * _e804) + (_e805 * _e805)) + (_e808 * _e808))));
                            let _e816 = (_e804 * _e815);
                            let _e817 = (_e805 * _e815);
                            let _e818 = (_e808 * _e815);
                            let _e822 = ((_e817 * _e801) - (_e800 * _e818));
                            let _e825 = ((_e818 * _e799) - (_e801 * _e816));
                            let _e828 = ((_e816 * _e800) - (_e799 * _e817));
                            let _e847 = (((_e781.x * _e799) + (_e781.y * _e800)) + (_e781.z * _e801));
                            let _e851 = abs(_e847);
                            if (_e851 != _e851) {
                                phi_2250_ = true;
                            } else {
                                phi_2250_ = (0.0001f >= _e851);
                            }
                            let _e855 = phi_2250_;
                            phi_1058_ = type_28();
                            phi_1059_ = type_28(1u, type_27(vec2<u32>(_e575, _e576), vec2<f32>(_e649, _e650), _e694, _e695, vec3<f32>(_e705, _e707, _e708), _e781, vec3<f32>(_e799, _e800, _e801), vec3<f32>(_e822, _e825, _e828), vec3<f32>(_e816, _e817, _e818), vec3<f32>((((_e781.x * _e822) + (_e781.y * _e825)) + (_e781.z * _e828)), (((_e781.x * _e816) + (_e781.y * _e817)) + (_e781.z * _e818)), _e847), (1f / (select(1f, -1f, (_e847 < 0f)) * select(_e851, 0.0001f, _e855)))));
                        }
                        let _e864 = phi_1058_;
                        let _e866 = phi_1059_;
                        phi_1061_ = _e864;
                        phi_1062_ = _e866;
                        phi_1063_ = _e696;
                    } else {
                        phi_1061_ = type_28(0u, type_28().member_1);
                        phi_1062_ = type_28();
                        phi_1063_ = true;
                    }
                    let _e871 = phi_1061_;
                    let _e873 = phi_1062_;
                    let _e875 = phi_1063_;
                    if _e875 {
                        phi_1067_ = _e871;
                    } else {
                        phi_1067_ = _e873;
                    }
                    let _e877 = phi_1067_;
                    let _e880 = (bitcast<i32>(_e877.member) != 0i);
                    if _e880 {
                        let _e886 = frame.member[0u].member_1.member_11;
                        let _e891 = (8u << bitcast<u32>((select(_e886, 2u, (2u < _e886)) & 31u)));
                        phi_2483_ = false;
                        phi_1085_ = 0u;
                        phi_1088_ = 0u;
                        phi_1090_ = 0f;
                        loop {
                            let _e893 = phi_2483_;
                            let _e895 = phi_1085_;
                            let _e897 = phi_1088_;
                            let _e899 = phi_1090_;
                            local_12 = _e899;
                            local_13 = _e897;
                            let _e900 = (_e895 < _e891);
                            if _e900 {
                                if ((_e630 & (1u << bitcast<u32>((_e895 & 31u)))) == 0u) {
                                    phi_2552_ = _e893;
                                    phi_2142_ = _e899;
                                } else {
                                    let _e910 = frame.member[0u].member_1.member_10;
                                    let _e912 = ((_e891 + _e895) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e913 = (_e912 < 56u);
                                    if _e913 {
                                    } else {
                                        phi_2550_ = true;
                                        break;
                                    }
                                    let _e915 = local_4[_e912];
                                    let _e918 = (_e910 == 1u);
                                    if _e918 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e913 {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e920 = local_5[_e912];
                                        phi_1138_ = _e920;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e913 {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e922 = local_6[_e912];
                                        phi_1138_ = _e922;
                                    }
                                    let _e924 = phi_1138_;
                                    let _e926 = (_e877.member_1.member_2 * _e924);
                                    let _e927 = (_e926 * _e915[0]);
                                    let _e928 = (_e926 * _e915[1]);
                                    if _e918 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e913 {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e930 = local_7[_e912];
                                        phi_1163_ = _e930;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e913 {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e932 = local_8[_e912];
                                        phi_1163_ = _e932;
                                    }
                                    let _e934 = phi_1163_;
                                    let _e935 = (_e877.member_1.member_2 * _e934);
                                    if _e918 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e913 {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e937 = local_9[_e912];
                                        phi_1176_ = _e937;
                                    } else {
                                        phi_1176_ = (_e935 * 2f);
                                    }
                                    let _e940 = phi_1176_;
                                    let _e949 = (-(((_e927 * _e877.member_1.member_9.x) + (_e928 * _e877.member_1.member_9.y))) * _e877.member_1.member_10);
                                    let _e950 = -(_e935);
                                    let _e954 = select(_e950, select(_e935, _e949, (_e949 < _e935)), (_e949 > _e950));
                                    let _e979 = (-0.5f / ((_e877.member_1.member_4.z + (_e877.member_1.member_7.z * _e927)) + (_e877.member_1.member_8.z * _e928)));
                                    let _e988 = frame.member[0u].member_1.member.member.member_1[0u];
                                    let _e990 = (((((_e877.member_1.member_4.x + (_e877.member_1.member_7.x * _e927)) + (_e877.member_1.member_8.x * _e928)) * _e979) / _e988) + 0.5f);
                                    let _e999 = frame.member[0u].member_1.member.member.member_1[1u];
                                    let _e1001 = (0.5f - ((((_e877.member_1.member_4.y + (_e877.member_1.member_7.y * _e927)) + (_e877.member_1.member_8.y * _e928)) * _e979) / _e999));
                                    let _e1013 = (select(0f, select(1f, _e990, (_e990 < 1f)), (_e990 > 0f)) * _e584);
                                    if (_e1013 > 0f) {
                                        let _e1019 = select(select(u32(_e1013), 0u, (_e1013 < 0f)), 4294967295u, (_e1013 > 4294967000f));
                                        let _e1020 = (_e589 - 1u);
                                        phi_1304_ = select(_e1019, _e1020, (_e1020 < _e1019));
                                    } else {
                                        phi_1304_ = 0u;
                                    }
                                    let _e1024 = phi_1304_;
                                    let _e1029 = (select(0f, select(1f, _e1001, (_e1001 < 1f)), (_e1001 > 0f)) * _e597);
                                    if (_e1029 > 0f) {
                                        let _e1035 = select(select(u32(_e1029), 0u, (_e1029 < 0f)), 4294967295u, (_e1029 > 4294967000f));
                                        let _e1036 = (_e602 - 1u);
                                        phi_1335_ = select(_e1035, _e1036, (_e1036 < _e1035));
                                    } else {
                                        phi_1335_ = 0u;
                                    }
                                    let _e1040 = phi_1335_;
                                    let _e1047 = ((_e877.member_1.member_1.x - _e990) * _e584);
                                    let _e1048 = ((_e877.member_1.member_1.y - _e1001) * _e597);
                                    let _e1054 = ((_e1040 * _e589) + _e1024);
                                    if (_e1054 < _e552) {
                                    } else {
                                        phi_2550_ = true;
                                        break;
                                    }
                                    let _e1057 = depth.member[_e1054];
                                    let _e1069 = select(_e660, _e1057, select(false, (_e1057 < _e660), (_e1057 > 0f)));
                                    let _e1071 = ((((f32(_e1024) + 0.5f) * (1f / _e584)) * 2f) - 1f);
                                    let _e1073 = ((((f32(_e1040) + 0.5f) * (1f / _e597)) * -2f) + 1f);
                                    let _e1079 = (((_e1071 * _e1069) * _e988) - _e877.member_1.member_4.x);
                                    let _e1080 = (((_e1073 * _e1069) * _e999) - _e877.member_1.member_4.y);
                                    let _e1081 = (-(_e1069) - _e877.member_1.member_4.z);
                                    let _e1090 = (((_e1079 * _e877.member_1.member_6.x) + (_e1080 * _e877.member_1.member_6.y)) + (_e1081 * _e877.member_1.member_6.z));
                                    if _e918 {
                                        let _e1095 = (((_e1079 * _e1079) + (_e1080 * _e1080)) + (_e1081 * _e1081));
                                        let _e1107 = (((((_e877.member_1.member_5.x * _e1079) + (_e877.member_1.member_5.y * _e1080)) + (_e877.member_1.member_5.z * _e1081)) / sqrt(_e1095)) - 0.1f);
                                        let _e1114 = (1f - (_e1095 / (_e638 * _e638)));
                                        let _e1121 = ((select(0f, select(1f, _e1107, (_e1107 < 1f)), (_e1107 > 0f)) * select(0f, select(1f, _e1114, (_e1114 < 1f)), (_e1114 > 0f))) / _e940);
                                        phi_1545_ = select(0f, select(0f, select(1f, _e1121, (_e1121 < 1f)), (_e1121 > 0f)), (_e1095 > 0f));
                                    } else {
                                        let _e1132 = frame.member[0u].member_1.member.member_3;
                                        if (_e954 != _e954) {
                                            phi_2265_ = true;
                                        } else {
                                            phi_2265_ = (_e1090 >= _e954);
                                        }
                                        let _e1137 = phi_2265_;
                                        let _e1139 = (_e935 - select(_e954, _e1090, _e1137));
                                        if (_e1139 != _e1139) {
                                            phi_2280_ = true;
                                        } else {
                                            phi_2280_ = (0f >= _e1139);
                                        }
                                        let _e1143 = phi_2280_;
                                        let _e1148 = ((_e1090 - (_e877.member_1.member_2 * (1f + _e1132))) * (1f / _e935));
                                        phi_1545_ = ((select(_e1139, 0f, _e1143) + (select(0f, select(1f, _e1148, (_e1148 < 1f)), (_e1148 > 0f)) * (_e935 - _e954))) * (0.5f / _e935));
                                    }
                                    let _e1159 = phi_1545_;
                                    let _e1164 = frame.member[0u].member_1.member_9;
                                    if (_e1164 == 0u) {
                                        phi_1782_ = type_41(_e1090, _e1159);
                                    } else {
                                        if _e918 {
                                            let _e1167 = (_e877.member_1.member_2 * 0.1f);
                                            if (_e935 != _e935) {
                                                phi_2295_ = true;
                                            } else {
                                                phi_2295_ = (_e1167 >= _e935);
                                            }
                                            let _e1171 = phi_2295_;
                                            phi_1568_ = select(_e935, _e1167, _e1171);
                                        } else {
                                            let _e1178 = frame.member[0u].member_1.member.member_3;
                                            phi_1568_ = (_e877.member_1.member_2 * (1f + _e1178));
                                        }
                                        let _e1182 = phi_1568_;
                                        let _e1188 = frame.member[0u].member_1.member_3;
                                        let _e1190 = select(false, (sqrt(((_e1047 * _e1047) + (_e1048 * _e1048))) > _e1188), (_e1090 > _e1182));
                                        if (_e1054 < arrayLength((&depth2_.member))) {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e1194 = depth2_.member[_e1054];
                                        let _e1198 = select(_e660, _e1194, select(false, (_e1194 < _e660), (_e1194 > 0f)));
                                        let _e1204 = (((_e1071 * _e1198) * _e988) - _e877.member_1.member_4.x);
                                        let _e1205 = (((_e1073 * _e1198) * _e999) - _e877.member_1.member_4.y);
                                        let _e1206 = (-(_e1198) - _e877.member_1.member_4.z);
                                        let _e1211 = (((_e1204 * _e877.member_1.member_6.x) + (_e1205 * _e877.member_1.member_6.y)) + (_e1206 * _e877.member_1.member_6.z));
                                        if _e918 {
                                            let _e1216 = (((_e1204 * _e1204) + (_e1205 * _e1205)) + (_e1206 * _e1206));
                                            let _e1228 = (((((_e877.member_1.member_5.x * _e1204) + (_e877.member_1.member_5.y * _e1205)) + (_e877.member_1.member_5.z * _e1206)) / sqrt(_e1216)) - 0.1f);
                                            let _e1235 = (1f - (_e1216 / (_e638 * _e638)));
                                            let _e1242 = ((select(0f, select(1f, _e1228, (_e1228 < 1f)), (_e1228 > 0f)) * select(0f, select(1f, _e1235, (_e1235 < 1f)), (_e1235 > 0f))) / _e940);
                                            phi_1762_ = select(0f, select(0f, select(1f, _e1242, (_e1242 < 1f)), (_e1242 > 0f)), (_e1216 > 0f));
                                        } else {
                                            let _e1253 = frame.member[0u].member_1.member.member_3;
                                            if (_e954 != _e954) {
                                                phi_2310_ = true;
                                            } else {
                                                phi_2310_ = (_e1211 >= _e954);
                                            }
                                            let _e1258 = phi_2310_;
                                            let _e1260 = (_e935 - select(_e954, _e1211, _e1258));
                                            if (_e1260 != _e1260) {
                                                phi_2325_ = true;
                                            } else {
                                                phi_2325_ = (0f >= _e1260);
                                            }
                                            let _e1264 = phi_2325_;
                                            let _e1269 = ((_e1211 - (_e877.member_1.member_2 * (1f + _e1253))) * (1f / _e935));
                                            phi_1762_ = ((select(_e1260, 0f, _e1264) + (select(0f, select(1f, _e1269, (_e1269 < 1f)), (_e1269 > 0f)) * (_e935 - _e954))) * (0.5f / _e935));
                                        }
                                        let _e1280 = phi_1762_;
                                        if (_e1090 != _e1090) {
                                            phi_2340_ = true;
                                        } else {
                                            phi_2340_ = (_e1211 <= _e1090);
                                        }
                                        let _e1284 = phi_2340_;
                                        if _e918 {
                                            if (_e1159 != _e1159) {
                                                phi_2355_ = true;
                                            } else {
                                                phi_2355_ = (_e1280 >= _e1159);
                                            }
                                            let _e1290 = phi_2355_;
                                            phi_1776_ = select(_e1159, _e1280, _e1290);
                                        } else {
                                            if (_e1159 != _e1159) {
                                                phi_2370_ = true;
                                            } else {
                                                phi_2370_ = (_e1280 <= _e1159);
                                            }
                                            let _e1295 = phi_2370_;
                                            phi_1776_ = select(_e1159, _e1280, _e1295);
                                        }
                                        let _e1298 = phi_1776_;
                                        phi_1782_ = type_41(select(_e1090, select(_e1090, _e1211, _e1284), _e1190), select(_e1159, _e1298, _e1190));
                                    }
                                    let _e1302 = phi_1782_;
                                    if select(false, select(false, (_e1001 <= 1f), (_e1001 >= 0f)), select(false, (_e990 <= 1f), (_e990 >= 0f))) {
                                        phi_1795_ = _e1302.member_1;
                                    } else {
                                        phi_1795_ = select(1f, 0f, _e918);
                                    }
                                    let _e1307 = phi_1795_;
                                    let _e1313 = frame.member[0u].member_1.member_5[0u];
                                    let _e1319 = frame.member[0u].member_1.member_5[1u];
                                    let _e1320 = f32(_e1313);
                                    let _e1321 = f32(_e1319);
                                    let _e1326 = frame.member[0u].member_1.member_4;
                                    let _e1327 = f32(_e1326);
                                    let _e1328 = (2u * _e1326);
                                    let _e1329 = (_e1313 + _e1328);
                                    let _e1335 = (floor((_e990 * _e1320)) + _e1327);
                                    let _e1336 = f32((_e1329 - 1u));
                                    let _e1340 = select(0f, select(_e1336, _e1335, (_e1335 < _e1336)), (_e1335 > 0f));
                                    let _e1343 = (floor((_e1001 * _e1321)) + _e1327);
                                    let _e1344 = f32(((_e1319 + _e1328) - 1u));
                                    let _e1348 = select(0f, select(_e1344, _e1343, (_e1343 < _e1344)), (_e1343 > 0f));
                                    let _e1353 = select(select(u32(_e1340), 0u, (_e1340 < 0f)), 4294967295u, (_e1340 > 4294967000f));
                                    let _e1358 = select(select(u32(_e1348), 0u, (_e1348 < 0f)), 4294967295u, (_e1348 > 4294967000f));
                                    let _e1361 = bitcast<i32>(_e1326);
                                    let _e1370 = frame.member[0u].member_1.member_8;
                                    let _e1375 = frame.member[0u].member_1.member_12;
                                    let _e1382 = (((((_e1358 % 4u) * 4u) + (_e1353 % 4u)) + (_e1375 % 16u)) % 16u);
                                    if (_e1370 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1384 = (_e1382 < 16u);
                                        if _e1384 {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e1387 = local[_e1382][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1384 {
                                        } else {
                                            phi_2550_ = true;
                                            break;
                                        }
                                        let _e1390 = local_1[_e1382][1u];
                                        phi_1929_ = vec2<f32>(_e1387, _e1390);
                                    } else {
                                        if (_e1370 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1393 = (_e1382 < 16u);
                                            if _e1393 {
                                            } else {
                                                phi_2550_ = true;
                                                break;
                                            }
                                            let _e1396 = local_2[_e1382][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1393 {
                                            } else {
                                                phi_2550_ = true;
                                                break;
                                            }
                                            let _e1399 = local_3[_e1382][1u];
                                            phi_1928_ = vec2<f32>(_e1396, _e1399);
                                        } else {
                                            phi_1928_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1402 = phi_1928_;
                                        phi_1929_ = _e1402;
                                    }
                                    let _e1404 = phi_1929_;
                                    let _e1417 = frame.member[0u].member_1.member_6;
                                    phi_1960_ = 0u;
                                    phi_1963_ = _e1307;
                                    loop {
                                        let _e1420 = phi_1960_;
                                        let _e1422 = phi_1963_;
                                        local_11 = _e1422;
                                        let _e1423 = (_e1420 < _e1417);
                                        if _e1423 {
                                            let _e1424 = ((((_e1358 * _e1329) + _e1353) * _e1417) + _e1420);
                                            if (_e1424 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2435_ = true;
                                                break;
                                            }
                                            let _e1427 = sd_map.member[_e1424];
                                            let _e1434 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1437 = ((_e1427 * (_e660 - _e1434)) + _e1434);
                                            let _e1447 = (((((((f32((bitcast<i32>(_e1353) - _e1361)) + _e1404.x) / _e1320) * 2f) - 1f) * _e1437) * _e988) - _e877.member_1.member_4.x);
                                            let _e1448 = (((((((f32((bitcast<i32>(_e1358) - _e1361)) + _e1404.y) / _e1321) * -2f) + 1f) * _e1437) * _e999) - _e877.member_1.member_4.y);
                                            let _e1449 = (-(_e1437) - _e877.member_1.member_4.z);
                                            let _e1454 = (((_e1447 * _e877.member_1.member_6.x) + (_e1448 * _e877.member_1.member_6.y)) + (_e1449 * _e877.member_1.member_6.z));
                                            if _e918 {
                                                let _e1459 = (((_e1447 * _e1447) + (_e1448 * _e1448)) + (_e1449 * _e1449));
                                                let _e1471 = (((((_e877.member_1.member_5.x * _e1447) + (_e877.member_1.member_5.y * _e1448)) + (_e877.member_1.member_5.z * _e1449)) / sqrt(_e1459)) - 0.1f);
                                                let _e1478 = (1f - (_e1459 / (_e638 * _e638)));
                                                let _e1485 = ((select(0f, select(1f, _e1471, (_e1471 < 1f)), (_e1471 > 0f)) * select(0f, select(1f, _e1478, (_e1478 < 1f)), (_e1478 > 0f))) / _e940);
                                                phi_2128_ = select(0f, select(0f, select(1f, _e1485, (_e1485 < 1f)), (_e1485 > 0f)), (_e1459 > 0f));
                                            } else {
                                                let _e1496 = frame.member[0u].member_1.member.member_3;
                                                if (_e954 != _e954) {
                                                    phi_2385_ = true;
                                                } else {
                                                    phi_2385_ = (_e1454 >= _e954);
                                                }
                                                let _e1501 = phi_2385_;
                                                let _e1503 = (_e935 - select(_e954, _e1454, _e1501));
                                                if (_e1503 != _e1503) {
                                                    phi_2400_ = true;
                                                } else {
                                                    phi_2400_ = (0f >= _e1503);
                                                }
                                                let _e1507 = phi_2400_;
                                                let _e1512 = ((_e1454 - (_e877.member_1.member_2 * (1f + _e1496))) * (1f / _e935));
                                                phi_2128_ = ((select(_e1503, 0f, _e1507) + (select(0f, select(1f, _e1512, (_e1512 < 1f)), (_e1512 > 0f)) * (_e935 - _e954))) * (0.5f / _e935));
                                            }
                                            let _e1523 = phi_2128_;
                                            if _e918 {
                                                if (_e1422 != _e1422) {
                                                    phi_2415_ = true;
                                                } else {
                                                    phi_2415_ = (_e1523 >= _e1422);
                                                }
                                                let _e1527 = phi_2415_;
                                                phi_2137_ = select(_e1422, _e1523, _e1527);
                                            } else {
                                                if (_e1422 != _e1422) {
                                                    phi_2430_ = true;
                                                } else {
                                                    phi_2430_ = (_e1523 <= _e1422);
                                                }
                                                let _e1532 = phi_2430_;
                                                phi_2137_ = select(_e1422, _e1523, _e1532);
                                            }
                                            let _e1535 = phi_2137_;
                                            phi_1961_ = (_e1420 + 1u);
                                            phi_1964_ = _e1535;
                                        } else {
                                            phi_1961_ = u32();
                                            phi_1964_ = f32();
                                        }
                                        let _e1538 = phi_1961_;
                                        let _e1540 = phi_1964_;
                                        continue;
                                        continuing {
                                            phi_1960_ = _e1538;
                                            phi_1963_ = _e1540;
                                            phi_2435_ = _e893;
                                            break if !(_e1423);
                                        }
                                    }
                                    let _e1543 = phi_2435_;
                                    phi_2550_ = _e1543;
                                    if _e1543 {
                                        break;
                                    }
                                    let _e1545 = local_11;
                                    phi_2552_ = _e1543;
                                    phi_2142_ = ((_e899 - _e1302.member_1) + _e1545);
                                }
                                let _e1548 = phi_2552_;
                                let _e1550 = phi_2142_;
                                phi_2551_ = _e1548;
                                phi_1086_ = (_e895 + 1u);
                                phi_1091_ = _e1550;
                            } else {
                                phi_2551_ = _e893;
                                phi_1086_ = u32();
                                phi_1091_ = f32();
                            }
                            let _e1553 = phi_2551_;
                            let _e1555 = phi_1086_;
                            let _e1557 = phi_1091_;
                            continue;
                            continuing {
                                phi_2483_ = _e1553;
                                phi_1085_ = _e1555;
                                phi_1088_ = select(u32(), _e897, _e900);
                                phi_1090_ = _e1557;
                                phi_2550_ = _e1553;
                                break if !(_e900);
                            }
                        }
                        let _e1561 = phi_2550_;
                        if _e1561 {
                            break;
                        }
                        let _e1566 = frame.member[0u].member_1.member_10;
                        let _e1567 = (_e1566 == 1u);
                        let _e1572 = local_12;
                        let _e1574 = (_e626 + ((select(2f, 1f, _e1567) / f32(_e891)) * _e1572));
                        if _e1567 {
                            phi_2172_ = (1f - (2f * _e1574));
                        } else {
                            phi_2172_ = _e1574;
                        }
                        let _e1578 = phi_2172_;
                        let _e1588 = frame.member[0u].member_1.member.member_2;
                        let _e1591 = local_13;
                        phi_2187_ = type_42(pow(select(0f, select(1f, _e1578, (_e1578 < 1f)), (_e1578 > 0f)), _e1588), _e1591);
                    } else {
                        phi_2187_ = type_42();
                    }
                    let _e1594 = phi_2187_;
                    phi_2189_ = _e1594;
                    phi_2190_ = select(true, false, _e880);
                }
                let _e1597 = phi_2189_;
                let _e1599 = phi_2190_;
                if _e1599 {
                    phi_2194_ = type_42(_e626, 0u);
                } else {
                    phi_2194_ = _e1597;
                }
                let _e1601 = phi_2194_;
                if _e623 {
                } else {
                    break;
                }
                ao.member[_e622] = _e1601.member;
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
