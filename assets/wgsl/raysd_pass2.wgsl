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
    var phi_713_: bool;
    var phi_715_: bool;
    var phi_716_: bool;
    var phi_717_: bool;
    var phi_718_: bool;
    var phi_812_: bool;
    var phi_842_: f32;
    var phi_2204_: bool;
    var phi_2219_: bool;
    var phi_917_: vec2<f32>;
    var phi_944_: vec3<f32>;
    var phi_2234_: bool;
    var phi_1056_: type_28;
    var phi_1057_: type_28;
    var phi_1059_: type_28;
    var phi_1060_: type_28;
    var phi_1061_: bool;
    var phi_1065_: type_28;
    var phi_2454_: bool;
    var phi_1083_: u32;
    var phi_1086_: u32;
    var phi_1088_: f32;
    var phi_1136_: f32;
    var phi_1160_: f32;
    var phi_1174_: f32;
    var phi_1193_: f32;
    var phi_1249_: bool;
    var phi_1251_: bool;
    var phi_1252_: bool;
    var phi_1253_: bool;
    var phi_1254_: bool;
    var phi_1286_: f32;
    var phi_1299_: f32;
    var phi_1384_: bool;
    var phi_1481_: f32;
    var phi_1494_: f32;
    var phi_1507_: f32;
    var phi_1508_: f32;
    var phi_2249_: bool;
    var phi_2264_: bool;
    var phi_1531_: f32;
    var phi_1538_: f32;
    var phi_2279_: bool;
    var phi_1560_: f32;
    var phi_1568_: bool;
    var phi_1603_: bool;
    var phi_1700_: f32;
    var phi_1713_: f32;
    var phi_1726_: f32;
    var phi_1727_: f32;
    var phi_2294_: bool;
    var phi_2309_: bool;
    var phi_1750_: f32;
    var phi_1757_: f32;
    var phi_2324_: bool;
    var phi_2339_: bool;
    var phi_1766_: f32;
    var phi_1768_: f32;
    var phi_1769_: f32;
    var phi_1781_: f32;
    var phi_1822_: f32;
    var phi_1836_: f32;
    var phi_1914_: vec2<f32>;
    var phi_1915_: vec2<f32>;
    var phi_1946_: u32;
    var phi_1949_: f32;
    var phi_2055_: f32;
    var phi_2068_: f32;
    var phi_2081_: f32;
    var phi_2082_: f32;
    var phi_2369_: bool;
    var phi_2384_: bool;
    var phi_2105_: f32;
    var phi_2112_: f32;
    var phi_2399_: bool;
    var phi_2414_: bool;
    var phi_2121_: f32;
    var phi_1947_: u32;
    var phi_1950_: f32;
    var phi_2419_: bool;
    var local_11: f32;
    var phi_2532_: bool;
    var phi_2126_: f32;
    var phi_2531_: bool;
    var phi_1084_: u32;
    var phi_1089_: f32;
    var phi_2530_: bool;
    var local_12: f32;
    var phi_2156_: f32;
    var phi_2166_: f32;
    var local_13: u32;
    var phi_2171_: type_41;
    var phi_2173_: type_41;
    var phi_2174_: bool;
    var phi_2178_: type_41;

    switch bitcast<i32>(0u) {
        default: {
            let _e546 = id_1;
            let _e551 = arrayLength((&depth.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e573 = frame.member[0u].member_1.member.member.member_4;
            let _e574 = (_e546.x + _e573);
            let _e575 = (_e546.y + _e573);
            let _e583 = frame.member[0u].member_1.member.member.member[0u];
            let _e588 = select(select(u32(_e583), 0u, (_e583 < 0f)), 4294967295u, (_e583 > 4294967000f));
            let _e596 = frame.member[0u].member_1.member.member.member[1u];
            let _e601 = select(select(u32(_e596), 0u, (_e596 < 0f)), 4294967295u, (_e596 > 4294967000f));
            if (_e574 >= _e573) {
                if (_e575 >= _e573) {
                    let _e605 = ((_e574 + _e573) < _e588);
                    if _e605 {
                        phi_713_ = ((_e575 + _e573) < _e601);
                    } else {
                        phi_713_ = bool();
                    }
                    let _e609 = phi_713_;
                    phi_715_ = _e609;
                    phi_716_ = select(true, false, _e605);
                } else {
                    phi_715_ = bool();
                    phi_716_ = true;
                }
                let _e612 = phi_715_;
                let _e614 = phi_716_;
                phi_717_ = _e612;
                phi_718_ = _e614;
            } else {
                phi_717_ = bool();
                phi_718_ = true;
            }
            let _e616 = phi_717_;
            let _e618 = phi_718_;
            if select(_e616, false, _e618) {
                let _e621 = ((_e575 * _e588) + _e574);
                let _e622 = (_e621 < arrayLength((&ao.member)));
                if _e622 {
                } else {
                    break;
                }
                let _e625 = ao.member[_e621];
                if (_e621 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e629 = mask.member[_e621];
                if (_e629 == 0u) {
                    phi_2173_ = type_41();
                    phi_2174_ = true;
                } else {
                    let _e637 = frame.member[0u].member_1.member.member_1;
                    let _e643 = frame.member[0u].member_1.member.member_4;
                    let _e648 = ((f32(_e574) + 0.5f) / _e583);
                    let _e649 = ((f32(_e575) + 0.5f) / _e596);
                    if (_e621 < _e551) {
                    } else {
                        break;
                    }
                    let _e652 = depth.member[_e621];
                    let _e659 = frame.member[0u].member_1.member.member.member_3;
                    if (_e652 > 0f) {
                        phi_812_ = (_e652 < _e659);
                    } else {
                        phi_812_ = false;
                    }
                    let _e663 = phi_812_;
                    if _e663 {
                        let _e671 = frame.member[0u].member_1.member.member.member_1[0u];
                        let _e679 = frame.member[0u].member_1.member.member.member_1[1u];
                        let _e689 = (0.5f * (((_e637 * _e583) / ((2f * _e671) * _e652)) + ((_e637 * _e596) / ((2f * _e679) * _e652))));
                        let _e690 = (_e689 > _e643);
                        if _e690 {
                            phi_842_ = ((_e637 * _e643) / _e689);
                        } else {
                            phi_842_ = _e637;
                        }
                        let _e694 = phi_842_;
                        let _e695 = select(_e689, _e643, _e690);
                        let _e696 = (_e695 < 0.5f);
                        if _e696 {
                            phi_1056_ = type_28(0u, type_28().member_1);
                            phi_1057_ = type_28();
                        } else {
                            let _e705 = ((((2f * _e648) - 1f) * _e652) * _e671);
                            let _e707 = (((1f - (2f * _e649)) * _e652) * _e679);
                            let _e708 = -(_e652);
                            if (_e621 < arrayLength((&normals.member))) {
                            } else {
                                break;
                            }
                            let _e712 = normals.member[_e621];
                            let _e720 = (f32((bitcast<i32>(((_e712 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e720 != _e720) {
                                phi_2204_ = true;
                            } else {
                                phi_2204_ = (-1f >= _e720);
                            }
                            let _e724 = phi_2204_;
                            let _e725 = select(_e720, -1f, _e724);
                            let _e735 = (f32((bitcast<i32>((((_e712 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e735 != _e735) {
                                phi_2219_ = true;
                            } else {
                                phi_2219_ = (-1f >= _e735);
                            }
                            let _e739 = phi_2219_;
                            let _e740 = select(_e735, -1f, _e739);
                            let _e743 = (1f - abs(_e725));
                            let _e744 = abs(_e740);
                            let _e745 = (_e743 - _e744);
                            if (_e745 < 0f) {
                                phi_917_ = vec2<f32>(((1f - _e744) * select(1f, -1f, (_e725 < 0f))), (_e743 * select(1f, -1f, (_e740 < 0f))));
                            } else {
                                phi_917_ = vec2<f32>(_e725, _e740);
                            }
                            let _e756 = phi_917_;
                            let _e765 = (1f / sqrt((((_e756.x * _e756.x) + (_e756.y * _e756.y)) + (_e745 * _e745))));
                            let _e766 = (_e756.x * _e765);
                            let _e767 = (_e756.y * _e765);
                            let _e768 = (_e745 * _e765);
                            if ((((_e705 * _e766) + (_e707 * _e767)) + (_e708 * _e768)) > 0f) {
                                phi_944_ = vec3<f32>(-(_e766), -(_e767), -(_e768));
                            } else {
                                phi_944_ = vec3<f32>(_e766, _e767, _e768);
                            }
                            let _e781 = phi_944_;
                            local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                            let _e782 = (_e575 % 4u);
                            if (_e782 < 4u) {
                            } else {
                                break;
                            }
                            let _e784 = (_e574 % 4u);
                            if (_e784 < 4u) {
                            } else {
                                break;
                            }
                            let _e788 = local_10[_e782][_e784];
                            let _e798 = sqrt((((_e705 * _e705) + (_e707 * _e707)) + (_e708 * _e708)));
                            let _e799 = (-(_e705) / _e798);
                            let _e800 = (-(_e707) / _e798);
                            let _e801 = (_e652 / _e798);
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
                                phi_2234_ = true;
                            } else {
                                phi_2234_ = (0.0001f >= _e851);
                            }
                            let _e855 = phi_2234_;
                            phi_1056_ = type_28();
                            phi_1057_ = type_28(1u, type_27(vec2<u32>(_e574, _e575), vec2<f32>(_e648, _e649), _e694, _e695, vec3<f32>(_e705, _e707, _e708), _e781, vec3<f32>(_e799, _e800, _e801), vec3<f32>(_e822, _e825, _e828), vec3<f32>(_e816, _e817, _e818), vec3<f32>((((_e781.x * _e822) + (_e781.y * _e825)) + (_e781.z * _e828)), (((_e781.x * _e816) + (_e781.y * _e817)) + (_e781.z * _e818)), _e847), (1f / (select(1f, -1f, (_e847 < 0f)) * select(_e851, 0.0001f, _e855)))));
                        }
                        let _e864 = phi_1056_;
                        let _e866 = phi_1057_;
                        phi_1059_ = _e864;
                        phi_1060_ = _e866;
                        phi_1061_ = _e696;
                    } else {
                        phi_1059_ = type_28(0u, type_28().member_1);
                        phi_1060_ = type_28();
                        phi_1061_ = true;
                    }
                    let _e871 = phi_1059_;
                    let _e873 = phi_1060_;
                    let _e875 = phi_1061_;
                    if _e875 {
                        phi_1065_ = _e871;
                    } else {
                        phi_1065_ = _e873;
                    }
                    let _e877 = phi_1065_;
                    let _e880 = (bitcast<i32>(_e877.member) != 0i);
                    if _e880 {
                        let _e886 = frame.member[0u].member_1.member_11;
                        let _e891 = (8u << bitcast<u32>((select(_e886, 2u, (2u < _e886)) & 31u)));
                        phi_2454_ = false;
                        phi_1083_ = 0u;
                        phi_1086_ = 0u;
                        phi_1088_ = 0f;
                        loop {
                            let _e893 = phi_2454_;
                            let _e895 = phi_1083_;
                            let _e897 = phi_1086_;
                            let _e899 = phi_1088_;
                            local_12 = _e899;
                            local_13 = _e897;
                            let _e900 = (_e895 < _e891);
                            if _e900 {
                                if ((_e629 & (1u << bitcast<u32>((_e895 & 31u)))) == 0u) {
                                    phi_2532_ = _e893;
                                    phi_2126_ = _e899;
                                } else {
                                    let _e910 = frame.member[0u].member_1.member_10;
                                    let _e912 = ((_e891 + _e895) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e913 = (_e912 < 56u);
                                    if _e913 {
                                    } else {
                                        phi_2530_ = true;
                                        break;
                                    }
                                    let _e915 = local_4[_e912];
                                    let _e918 = (_e910 == 1u);
                                    if _e918 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e913 {
                                        } else {
                                            phi_2530_ = true;
                                            break;
                                        }
                                        let _e920 = local_5[_e912];
                                        phi_1136_ = _e920;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e913 {
                                        } else {
                                            phi_2530_ = true;
                                            break;
                                        }
                                        let _e922 = local_6[_e912];
                                        phi_1136_ = _e922;
                                    }
                                    let _e924 = phi_1136_;
                                    let _e926 = (_e924 * _e877.member_1.member_2);
                                    let _e927 = (_e926 * _e915[0]);
                                    let _e928 = (_e926 * _e915[1]);
                                    if _e918 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e913 {
                                        } else {
                                            phi_2530_ = true;
                                            break;
                                        }
                                        let _e930 = local_7[_e912];
                                        phi_1160_ = _e930;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e913 {
                                        } else {
                                            phi_2530_ = true;
                                            break;
                                        }
                                        let _e932 = local_8[_e912];
                                        phi_1160_ = _e932;
                                    }
                                    let _e934 = phi_1160_;
                                    let _e935 = (_e934 * _e877.member_1.member_2);
                                    if _e918 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e913 {
                                        } else {
                                            phi_2530_ = true;
                                            break;
                                        }
                                        let _e937 = local_9[_e912];
                                        phi_1174_ = _e937;
                                    } else {
                                        phi_1174_ = (2f * _e935);
                                    }
                                    let _e940 = phi_1174_;
                                    let _e950 = (-(((_e927 * _e877.member_1.member_9.x) + (_e928 * _e877.member_1.member_9.y))) * _e877.member_1.member_10);
                                    let _e951 = -(_e935);
                                    if (_e950 > _e951) {
                                        phi_1193_ = select(_e935, _e950, (_e950 < _e935));
                                    } else {
                                        phi_1193_ = _e951;
                                    }
                                    let _e956 = phi_1193_;
                                    let _e981 = (-0.5f / ((_e877.member_1.member_4.z + (_e877.member_1.member_7.z * _e927)) + (_e877.member_1.member_8.z * _e928)));
                                    let _e990 = frame.member[0u].member_1.member.member.member_1[0u];
                                    let _e992 = (0.5f + ((((_e877.member_1.member_4.x + (_e877.member_1.member_7.x * _e927)) + (_e877.member_1.member_8.x * _e928)) * _e981) / _e990));
                                    let _e1001 = frame.member[0u].member_1.member.member.member_1[1u];
                                    let _e1003 = (0.5f - ((((_e877.member_1.member_4.y + (_e877.member_1.member_7.y * _e927)) + (_e877.member_1.member_8.y * _e928)) * _e981) / _e1001));
                                    if (_e992 >= 0f) {
                                        if (_e992 <= 1f) {
                                            let _e1006 = (_e1003 >= 0f);
                                            if _e1006 {
                                                phi_1249_ = (_e1003 <= 1f);
                                            } else {
                                                phi_1249_ = bool();
                                            }
                                            let _e1009 = phi_1249_;
                                            phi_1251_ = _e1009;
                                            phi_1252_ = select(true, false, _e1006);
                                        } else {
                                            phi_1251_ = bool();
                                            phi_1252_ = true;
                                        }
                                        let _e1012 = phi_1251_;
                                        let _e1014 = phi_1252_;
                                        phi_1253_ = _e1012;
                                        phi_1254_ = _e1014;
                                    } else {
                                        phi_1253_ = bool();
                                        phi_1254_ = true;
                                    }
                                    let _e1016 = phi_1253_;
                                    let _e1018 = phi_1254_;
                                    if (_e992 > 0f) {
                                        phi_1286_ = select(1f, _e992, (_e992 < 1f));
                                    } else {
                                        phi_1286_ = 0f;
                                    }
                                    let _e1024 = phi_1286_;
                                    let _e1025 = (_e1024 * _e583);
                                    if (_e1003 > 0f) {
                                        phi_1299_ = select(1f, _e1003, (_e1003 < 1f));
                                    } else {
                                        phi_1299_ = 0f;
                                    }
                                    let _e1030 = phi_1299_;
                                    let _e1031 = (_e1030 * _e596);
                                    let _e1036 = select(select(u32(_e1025), 0u, (_e1025 < 0f)), 4294967295u, (_e1025 > 4294967000f));
                                    let _e1037 = (_e588 - 1u);
                                    let _e1039 = select(_e1036, _e1037, (_e1037 < _e1036));
                                    let _e1044 = select(select(u32(_e1031), 0u, (_e1031 < 0f)), 4294967295u, (_e1031 > 4294967000f));
                                    let _e1045 = (_e601 - 1u);
                                    let _e1047 = select(_e1044, _e1045, (_e1045 < _e1044));
                                    let _e1054 = ((_e877.member_1.member_1.x - _e992) * _e583);
                                    let _e1055 = ((_e877.member_1.member_1.y - _e1003) * _e596);
                                    let _e1061 = ((_e1047 * _e588) + _e1039);
                                    if (_e1061 < _e551) {
                                    } else {
                                        phi_2530_ = true;
                                        break;
                                    }
                                    let _e1064 = depth.member[_e1061];
                                    if (_e1064 > 0f) {
                                        phi_1384_ = (_e1064 < _e659);
                                    } else {
                                        phi_1384_ = false;
                                    }
                                    let _e1068 = phi_1384_;
                                    let _e1069 = select(_e659, _e1064, _e1068);
                                    let _e1079 = ((2f * ((f32(_e1039) + 0.5f) * (1f / _e583))) - 1f);
                                    let _e1081 = (1f - (2f * ((f32(_e1047) + 0.5f) * (1f / _e596))));
                                    let _e1087 = (((_e1079 * _e1069) * _e990) - _e877.member_1.member_4.x);
                                    let _e1088 = (((_e1081 * _e1069) * _e1001) - _e877.member_1.member_4.y);
                                    let _e1089 = (-(_e1069) - _e877.member_1.member_4.z);
                                    let _e1098 = (((_e1087 * _e877.member_1.member_6.x) + (_e1088 * _e877.member_1.member_6.y)) + (_e1089 * _e877.member_1.member_6.z));
                                    if _e918 {
                                        let _e1103 = (((_e1087 * _e1087) + (_e1088 * _e1088)) + (_e1089 * _e1089));
                                        if (_e1103 <= 0f) {
                                            phi_1508_ = 0f;
                                        } else {
                                            let _e1116 = (((((_e877.member_1.member_5.x * _e1087) + (_e877.member_1.member_5.y * _e1088)) + (_e877.member_1.member_5.z * _e1089)) / sqrt(_e1103)) - 0.1f);
                                            if (_e1116 > 0f) {
                                                phi_1481_ = select(1f, _e1116, (_e1116 < 1f));
                                            } else {
                                                phi_1481_ = 0f;
                                            }
                                            let _e1121 = phi_1481_;
                                            let _e1124 = (1f - (_e1103 / (_e637 * _e637)));
                                            if (_e1124 > 0f) {
                                                phi_1494_ = select(1f, _e1124, (_e1124 < 1f));
                                            } else {
                                                phi_1494_ = 0f;
                                            }
                                            let _e1129 = phi_1494_;
                                            let _e1131 = ((_e1121 * _e1129) / _e940);
                                            if (_e1131 > 0f) {
                                                phi_1507_ = select(1f, _e1131, (_e1131 < 1f));
                                            } else {
                                                phi_1507_ = 0f;
                                            }
                                            let _e1136 = phi_1507_;
                                            phi_1508_ = _e1136;
                                        }
                                        let _e1138 = phi_1508_;
                                        phi_1538_ = _e1138;
                                    } else {
                                        let _e1144 = frame.member[0u].member_1.member.member_3;
                                        if (_e956 != _e956) {
                                            phi_2249_ = true;
                                        } else {
                                            phi_2249_ = (_e1098 >= _e956);
                                        }
                                        let _e1149 = phi_2249_;
                                        let _e1151 = (_e935 - select(_e956, _e1098, _e1149));
                                        if (_e1151 != _e1151) {
                                            phi_2264_ = true;
                                        } else {
                                            phi_2264_ = (0f >= _e1151);
                                        }
                                        let _e1155 = phi_2264_;
                                        let _e1160 = ((_e1098 - ((1f + _e1144) * _e877.member_1.member_2)) * (1f / _e935));
                                        if (_e1160 > 0f) {
                                            phi_1531_ = select(1f, _e1160, (_e1160 < 1f));
                                        } else {
                                            phi_1531_ = 0f;
                                        }
                                        let _e1165 = phi_1531_;
                                        phi_1538_ = ((select(_e1151, 0f, _e1155) + (_e1165 * (_e935 - _e956))) * (0.5f / _e935));
                                    }
                                    let _e1172 = phi_1538_;
                                    let _e1177 = frame.member[0u].member_1.member_9;
                                    if (_e1177 == 0u) {
                                        phi_1769_ = _e1172;
                                    } else {
                                        if _e918 {
                                            let _e1179 = (0.1f * _e877.member_1.member_2);
                                            if (_e935 != _e935) {
                                                phi_2279_ = true;
                                            } else {
                                                phi_2279_ = (_e1179 >= _e935);
                                            }
                                            let _e1183 = phi_2279_;
                                            phi_1560_ = select(_e935, _e1179, _e1183);
                                        } else {
                                            let _e1190 = frame.member[0u].member_1.member.member_3;
                                            phi_1560_ = ((1f + _e1190) * _e877.member_1.member_2);
                                        }
                                        let _e1194 = phi_1560_;
                                        if (_e1098 > _e1194) {
                                            let _e1200 = frame.member[0u].member_1.member_3;
                                            phi_1568_ = (sqrt(((_e1054 * _e1054) + (_e1055 * _e1055))) > _e1200);
                                        } else {
                                            phi_1568_ = false;
                                        }
                                        let _e1203 = phi_1568_;
                                        if _e1203 {
                                            if (_e1061 < arrayLength((&depth2_.member))) {
                                            } else {
                                                phi_2530_ = true;
                                                break;
                                            }
                                            let _e1207 = depth2_.member[_e1061];
                                            if (_e1207 > 0f) {
                                                phi_1603_ = (_e1207 < _e659);
                                            } else {
                                                phi_1603_ = false;
                                            }
                                            let _e1211 = phi_1603_;
                                            let _e1212 = select(_e659, _e1207, _e1211);
                                            let _e1218 = (((_e1079 * _e1212) * _e990) - _e877.member_1.member_4.x);
                                            let _e1219 = (((_e1081 * _e1212) * _e1001) - _e877.member_1.member_4.y);
                                            let _e1220 = (-(_e1212) - _e877.member_1.member_4.z);
                                            let _e1225 = (((_e1218 * _e877.member_1.member_6.x) + (_e1219 * _e877.member_1.member_6.y)) + (_e1220 * _e877.member_1.member_6.z));
                                            if _e918 {
                                                let _e1230 = (((_e1218 * _e1218) + (_e1219 * _e1219)) + (_e1220 * _e1220));
                                                if (_e1230 <= 0f) {
                                                    phi_1727_ = 0f;
                                                } else {
                                                    let _e1243 = (((((_e877.member_1.member_5.x * _e1218) + (_e877.member_1.member_5.y * _e1219)) + (_e877.member_1.member_5.z * _e1220)) / sqrt(_e1230)) - 0.1f);
                                                    if (_e1243 > 0f) {
                                                        phi_1700_ = select(1f, _e1243, (_e1243 < 1f));
                                                    } else {
                                                        phi_1700_ = 0f;
                                                    }
                                                    let _e1248 = phi_1700_;
                                                    let _e1251 = (1f - (_e1230 / (_e637 * _e637)));
                                                    if (_e1251 > 0f) {
                                                        phi_1713_ = select(1f, _e1251, (_e1251 < 1f));
                                                    } else {
                                                        phi_1713_ = 0f;
                                                    }
                                                    let _e1256 = phi_1713_;
                                                    let _e1258 = ((_e1248 * _e1256) / _e940);
                                                    if (_e1258 > 0f) {
                                                        phi_1726_ = select(1f, _e1258, (_e1258 < 1f));
                                                    } else {
                                                        phi_1726_ = 0f;
                                                    }
                                                    let _e1263 = phi_1726_;
                                                    phi_1727_ = _e1263;
                                                }
                                                let _e1265 = phi_1727_;
                                                phi_1757_ = _e1265;
                                            } else {
                                                let _e1271 = frame.member[0u].member_1.member.member_3;
                                                if (_e956 != _e956) {
                                                    phi_2294_ = true;
                                                } else {
                                                    phi_2294_ = (_e1225 >= _e956);
                                                }
                                                let _e1276 = phi_2294_;
                                                let _e1278 = (_e935 - select(_e956, _e1225, _e1276));
                                                if (_e1278 != _e1278) {
                                                    phi_2309_ = true;
                                                } else {
                                                    phi_2309_ = (0f >= _e1278);
                                                }
                                                let _e1282 = phi_2309_;
                                                let _e1287 = ((_e1225 - ((1f + _e1271) * _e877.member_1.member_2)) * (1f / _e935));
                                                if (_e1287 > 0f) {
                                                    phi_1750_ = select(1f, _e1287, (_e1287 < 1f));
                                                } else {
                                                    phi_1750_ = 0f;
                                                }
                                                let _e1292 = phi_1750_;
                                                phi_1757_ = ((select(_e1278, 0f, _e1282) + (_e1292 * (_e935 - _e956))) * (0.5f / _e935));
                                            }
                                            let _e1299 = phi_1757_;
                                            if _e918 {
                                                if (_e1172 != _e1172) {
                                                    phi_2324_ = true;
                                                } else {
                                                    phi_2324_ = (_e1299 >= _e1172);
                                                }
                                                let _e1303 = phi_2324_;
                                                phi_1766_ = select(_e1172, _e1299, _e1303);
                                            } else {
                                                if (_e1172 != _e1172) {
                                                    phi_2339_ = true;
                                                } else {
                                                    phi_2339_ = (_e1299 <= _e1172);
                                                }
                                                let _e1308 = phi_2339_;
                                                phi_1766_ = select(_e1172, _e1299, _e1308);
                                            }
                                            let _e1311 = phi_1766_;
                                            phi_1768_ = _e1311;
                                        } else {
                                            phi_1768_ = _e1172;
                                        }
                                        let _e1313 = phi_1768_;
                                        phi_1769_ = _e1313;
                                    }
                                    let _e1315 = phi_1769_;
                                    if select(_e1016, false, _e1018) {
                                        phi_1781_ = _e1315;
                                    } else {
                                        phi_1781_ = select(1f, 0f, _e918);
                                    }
                                    let _e1319 = phi_1781_;
                                    let _e1325 = frame.member[0u].member_1.member_5[0u];
                                    let _e1331 = frame.member[0u].member_1.member_5[1u];
                                    let _e1332 = f32(_e1325);
                                    let _e1333 = f32(_e1331);
                                    let _e1338 = frame.member[0u].member_1.member_4;
                                    let _e1339 = f32(_e1338);
                                    let _e1340 = (2u * _e1338);
                                    let _e1341 = (_e1325 + _e1340);
                                    let _e1347 = (floor((_e992 * _e1332)) + _e1339);
                                    let _e1348 = f32((_e1341 - 1u));
                                    if (_e1347 > 0f) {
                                        phi_1822_ = select(_e1348, _e1347, (_e1347 < _e1348));
                                    } else {
                                        phi_1822_ = 0f;
                                    }
                                    let _e1353 = phi_1822_;
                                    let _e1356 = (floor((_e1003 * _e1333)) + _e1339);
                                    let _e1357 = f32(((_e1331 + _e1340) - 1u));
                                    if (_e1356 > 0f) {
                                        phi_1836_ = select(_e1357, _e1356, (_e1356 < _e1357));
                                    } else {
                                        phi_1836_ = 0f;
                                    }
                                    let _e1362 = phi_1836_;
                                    let _e1367 = select(select(u32(_e1353), 0u, (_e1353 < 0f)), 4294967295u, (_e1353 > 4294967000f));
                                    let _e1372 = select(select(u32(_e1362), 0u, (_e1362 < 0f)), 4294967295u, (_e1362 > 4294967000f));
                                    let _e1375 = bitcast<i32>(_e1338);
                                    let _e1384 = frame.member[0u].member_1.member_8;
                                    let _e1389 = frame.member[0u].member_1.member_12;
                                    let _e1396 = (((((_e1372 % 4u) * 4u) + (_e1367 % 4u)) + (_e1389 % 16u)) % 16u);
                                    if (_e1384 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1398 = (_e1396 < 16u);
                                        if _e1398 {
                                        } else {
                                            phi_2530_ = true;
                                            break;
                                        }
                                        let _e1401 = local[_e1396][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1398 {
                                        } else {
                                            phi_2530_ = true;
                                            break;
                                        }
                                        let _e1404 = local_1[_e1396][1u];
                                        phi_1915_ = vec2<f32>(_e1401, _e1404);
                                    } else {
                                        if (_e1384 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1407 = (_e1396 < 16u);
                                            if _e1407 {
                                            } else {
                                                phi_2530_ = true;
                                                break;
                                            }
                                            let _e1410 = local_2[_e1396][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1407 {
                                            } else {
                                                phi_2530_ = true;
                                                break;
                                            }
                                            let _e1413 = local_3[_e1396][1u];
                                            phi_1914_ = vec2<f32>(_e1410, _e1413);
                                        } else {
                                            phi_1914_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1416 = phi_1914_;
                                        phi_1915_ = _e1416;
                                    }
                                    let _e1418 = phi_1915_;
                                    let _e1431 = frame.member[0u].member_1.member_6;
                                    phi_1946_ = 0u;
                                    phi_1949_ = _e1319;
                                    loop {
                                        let _e1434 = phi_1946_;
                                        let _e1436 = phi_1949_;
                                        local_11 = _e1436;
                                        let _e1437 = (_e1434 < _e1431);
                                        if _e1437 {
                                            let _e1438 = ((((_e1372 * _e1341) + _e1367) * _e1431) + _e1434);
                                            if (_e1438 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2419_ = true;
                                                break;
                                            }
                                            let _e1441 = sd_map.member[_e1438];
                                            let _e1448 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1451 = ((_e1441 * (_e659 - _e1448)) + _e1448);
                                            let _e1461 = (((((2f * ((f32((bitcast<i32>(_e1367) - _e1375)) + _e1418.x) / _e1332)) - 1f) * _e1451) * _e990) - _e877.member_1.member_4.x);
                                            let _e1462 = ((((1f - (2f * ((f32((bitcast<i32>(_e1372) - _e1375)) + _e1418.y) / _e1333))) * _e1451) * _e1001) - _e877.member_1.member_4.y);
                                            let _e1463 = (-(_e1451) - _e877.member_1.member_4.z);
                                            let _e1468 = (((_e1461 * _e877.member_1.member_6.x) + (_e1462 * _e877.member_1.member_6.y)) + (_e1463 * _e877.member_1.member_6.z));
                                            if _e918 {
                                                let _e1473 = (((_e1461 * _e1461) + (_e1462 * _e1462)) + (_e1463 * _e1463));
                                                if (_e1473 <= 0f) {
                                                    phi_2082_ = 0f;
                                                } else {
                                                    let _e1486 = (((((_e877.member_1.member_5.x * _e1461) + (_e877.member_1.member_5.y * _e1462)) + (_e877.member_1.member_5.z * _e1463)) / sqrt(_e1473)) - 0.1f);
                                                    if (_e1486 > 0f) {
                                                        phi_2055_ = select(1f, _e1486, (_e1486 < 1f));
                                                    } else {
                                                        phi_2055_ = 0f;
                                                    }
                                                    let _e1491 = phi_2055_;
                                                    let _e1494 = (1f - (_e1473 / (_e637 * _e637)));
                                                    if (_e1494 > 0f) {
                                                        phi_2068_ = select(1f, _e1494, (_e1494 < 1f));
                                                    } else {
                                                        phi_2068_ = 0f;
                                                    }
                                                    let _e1499 = phi_2068_;
                                                    let _e1501 = ((_e1491 * _e1499) / _e940);
                                                    if (_e1501 > 0f) {
                                                        phi_2081_ = select(1f, _e1501, (_e1501 < 1f));
                                                    } else {
                                                        phi_2081_ = 0f;
                                                    }
                                                    let _e1506 = phi_2081_;
                                                    phi_2082_ = _e1506;
                                                }
                                                let _e1508 = phi_2082_;
                                                phi_2112_ = _e1508;
                                            } else {
                                                let _e1514 = frame.member[0u].member_1.member.member_3;
                                                if (_e956 != _e956) {
                                                    phi_2369_ = true;
                                                } else {
                                                    phi_2369_ = (_e1468 >= _e956);
                                                }
                                                let _e1519 = phi_2369_;
                                                let _e1521 = (_e935 - select(_e956, _e1468, _e1519));
                                                if (_e1521 != _e1521) {
                                                    phi_2384_ = true;
                                                } else {
                                                    phi_2384_ = (0f >= _e1521);
                                                }
                                                let _e1525 = phi_2384_;
                                                let _e1530 = ((_e1468 - ((1f + _e1514) * _e877.member_1.member_2)) * (1f / _e935));
                                                if (_e1530 > 0f) {
                                                    phi_2105_ = select(1f, _e1530, (_e1530 < 1f));
                                                } else {
                                                    phi_2105_ = 0f;
                                                }
                                                let _e1535 = phi_2105_;
                                                phi_2112_ = ((select(_e1521, 0f, _e1525) + (_e1535 * (_e935 - _e956))) * (0.5f / _e935));
                                            }
                                            let _e1542 = phi_2112_;
                                            if _e918 {
                                                if (_e1436 != _e1436) {
                                                    phi_2399_ = true;
                                                } else {
                                                    phi_2399_ = (_e1542 >= _e1436);
                                                }
                                                let _e1546 = phi_2399_;
                                                phi_2121_ = select(_e1436, _e1542, _e1546);
                                            } else {
                                                if (_e1436 != _e1436) {
                                                    phi_2414_ = true;
                                                } else {
                                                    phi_2414_ = (_e1542 <= _e1436);
                                                }
                                                let _e1551 = phi_2414_;
                                                phi_2121_ = select(_e1436, _e1542, _e1551);
                                            }
                                            let _e1554 = phi_2121_;
                                            phi_1947_ = (_e1434 + 1u);
                                            phi_1950_ = _e1554;
                                        } else {
                                            phi_1947_ = u32();
                                            phi_1950_ = f32();
                                        }
                                        let _e1557 = phi_1947_;
                                        let _e1559 = phi_1950_;
                                        continue;
                                        continuing {
                                            phi_1946_ = _e1557;
                                            phi_1949_ = _e1559;
                                            phi_2419_ = _e893;
                                            break if !(_e1437);
                                        }
                                    }
                                    let _e1562 = phi_2419_;
                                    phi_2530_ = _e1562;
                                    if _e1562 {
                                        break;
                                    }
                                    let _e1564 = local_11;
                                    phi_2532_ = _e1562;
                                    phi_2126_ = ((_e899 - _e1315) + _e1564);
                                }
                                let _e1567 = phi_2532_;
                                let _e1569 = phi_2126_;
                                phi_2531_ = _e1567;
                                phi_1084_ = (_e895 + 1u);
                                phi_1089_ = _e1569;
                            } else {
                                phi_2531_ = _e893;
                                phi_1084_ = u32();
                                phi_1089_ = f32();
                            }
                            let _e1572 = phi_2531_;
                            let _e1574 = phi_1084_;
                            let _e1576 = phi_1089_;
                            continue;
                            continuing {
                                phi_2454_ = _e1572;
                                phi_1083_ = _e1574;
                                phi_1086_ = select(u32(), _e897, _e900);
                                phi_1088_ = _e1576;
                                phi_2530_ = _e1572;
                                break if !(_e900);
                            }
                        }
                        let _e1580 = phi_2530_;
                        if _e1580 {
                            break;
                        }
                        let _e1585 = frame.member[0u].member_1.member_10;
                        let _e1586 = (_e1585 == 1u);
                        let _e1591 = local_12;
                        let _e1593 = (_e625 + ((select(2f, 1f, _e1586) / f32(_e891)) * _e1591));
                        if _e1586 {
                            phi_2156_ = (1f - (2f * _e1593));
                        } else {
                            phi_2156_ = _e1593;
                        }
                        let _e1597 = phi_2156_;
                        if (_e1597 > 0f) {
                            phi_2166_ = select(1f, _e1597, (_e1597 < 1f));
                        } else {
                            phi_2166_ = 0f;
                        }
                        let _e1602 = phi_2166_;
                        let _e1608 = frame.member[0u].member_1.member.member_2;
                        let _e1611 = local_13;
                        phi_2171_ = type_41(pow(_e1602, _e1608), _e1611);
                    } else {
                        phi_2171_ = type_41();
                    }
                    let _e1614 = phi_2171_;
                    phi_2173_ = _e1614;
                    phi_2174_ = select(true, false, _e880);
                }
                let _e1617 = phi_2173_;
                let _e1619 = phi_2174_;
                if _e1619 {
                    phi_2178_ = type_41(_e625, 0u);
                } else {
                    phi_2178_ = _e1617;
                }
                let _e1621 = phi_2178_;
                if _e622 {
                } else {
                    break;
                }
                ao.member[_e621] = _e1621.member;
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
