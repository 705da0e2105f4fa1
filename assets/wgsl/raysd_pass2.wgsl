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
    var phi_849_: bool;
    var phi_851_: bool;
    var phi_852_: bool;
    var phi_853_: bool;
    var phi_854_: bool;
    var phi_978_: f32;
    var phi_2289_: bool;
    var phi_2304_: bool;
    var phi_1054_: vec2<f32>;
    var phi_1081_: vec3<f32>;
    var phi_2319_: bool;
    var phi_1193_: type_28;
    var phi_1194_: type_28;
    var phi_1196_: type_28;
    var phi_1197_: type_28;
    var phi_1198_: bool;
    var phi_1202_: type_28;
    var phi_2717_: bool;
    var phi_1220_: u32;
    var phi_1223_: u32;
    var phi_1225_: f32;
    var phi_1273_: f32;
    var phi_1298_: f32;
    var phi_1311_: f32;
    var phi_2425_: bool;
    var phi_2440_: bool;
    var phi_1612_: f32;
    var phi_2455_: bool;
    var phi_1635_: f32;
    var phi_2507_: bool;
    var phi_2522_: bool;
    var phi_1831_: f32;
    var phi_2537_: bool;
    var phi_2552_: bool;
    var phi_2567_: bool;
    var phi_1845_: f32;
    var phi_1851_: type_42;
    var phi_1864_: f32;
    var phi_1997_: vec2<f32>;
    var phi_1998_: vec2<f32>;
    var phi_2029_: u32;
    var phi_2032_: f32;
    var phi_2582_: bool;
    var phi_2597_: bool;
    var phi_2197_: f32;
    var phi_2612_: bool;
    var phi_2627_: bool;
    var phi_2206_: f32;
    var phi_2030_: u32;
    var phi_2033_: f32;
    var phi_2671_: bool;
    var local_11: f32;
    var phi_2786_: bool;
    var phi_2211_: f32;
    var phi_2785_: bool;
    var phi_1221_: u32;
    var phi_1226_: f32;
    var phi_2784_: bool;
    var local_12: f32;
    var phi_2241_: f32;
    var local_13: u32;
    var phi_2256_: type_43;
    var phi_2258_: type_43;
    var phi_2259_: bool;
    var phi_2263_: type_43;

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
            let _e589 = frame.member[0u].member_1.member.member.member[0u];
            let _e594 = select(select(u32(_e589), 0u, (_e589 < 0f)), 4294967295u, (_e589 > 4294967000f));
            let _e602 = frame.member[0u].member_1.member.member.member[1u];
            if (_e575 >= _e574) {
                if (_e576 >= _e574) {
                    let _e611 = ((_e575 + _e574) < _e594);
                    if _e611 {
                        phi_849_ = ((_e576 + _e574) < select(select(u32(_e602), 0u, (_e602 < 0f)), 4294967295u, (_e602 > 4294967000f)));
                    } else {
                        phi_849_ = bool();
                    }
                    let _e615 = phi_849_;
                    phi_851_ = _e615;
                    phi_852_ = select(true, false, _e611);
                } else {
                    phi_851_ = bool();
                    phi_852_ = true;
                }
                let _e618 = phi_851_;
                let _e620 = phi_852_;
                phi_853_ = _e618;
                phi_854_ = _e620;
            } else {
                phi_853_ = bool();
                phi_854_ = true;
            }
            let _e622 = phi_853_;
            let _e624 = phi_854_;
            if select(_e622, false, _e624) {
                let _e627 = ((_e576 * _e594) + _e575);
                let _e628 = (_e627 < arrayLength((&ao.member)));
                if _e628 {
                } else {
                    break;
                }
                let _e631 = ao.member[_e627];
                if (_e627 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e635 = mask.member[_e627];
                if (_e635 == 0u) {
                    phi_2258_ = type_43();
                    phi_2259_ = true;
                } else {
                    let _e643 = frame.member[0u].member_1.member.member_1;
                    let _e649 = frame.member[0u].member_1.member.member_4;
                    let _e654 = ((f32(_e575) + 0.5f) / _e589);
                    let _e655 = ((f32(_e576) + 0.5f) / _e602);
                    if (_e627 < _e552) {
                    } else {
                        break;
                    }
                    let _e658 = depth.member[_e627];
                    let _e665 = frame.member[0u].member_1.member.member.member_3;
                    if select(false, (_e658 < _e665), (_e658 > 0f)) {
                        let _e676 = frame.member[0u].member_1.member.member.member_1[0u];
                        let _e684 = frame.member[0u].member_1.member.member.member_1[1u];
                        let _e694 = (0.5f * (((_e643 * _e589) / ((2f * _e676) * _e658)) + ((_e643 * _e602) / ((2f * _e684) * _e658))));
                        let _e695 = (_e694 > _e649);
                        if _e695 {
                            phi_978_ = ((_e643 * _e649) / _e694);
                        } else {
                            phi_978_ = _e643;
                        }
                        let _e699 = phi_978_;
                        let _e700 = select(_e694, _e649, _e695);
                        let _e701 = (_e700 < 0.5f);
                        if _e701 {
                            phi_1193_ = type_28(0u, type_28().member_1);
                            phi_1194_ = type_28();
                        } else {
                            let _e710 = ((((_e654 * 2f) - 1f) * _e658) * _e676);
                            let _e712 = ((((_e655 * -2f) + 1f) * _e658) * _e684);
                            let _e713 = -(_e658);
                            if (_e627 < arrayLength((&normals.member))) {
                            } else {
                                break;
                            }
                            let _e717 = normals.member[_e627];
                            let _e725 = (f32((bitcast<i32>(((_e717 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e725 != _e725) {
                                phi_2289_ = true;
                            } else {
                                phi_2289_ = (-1f >= _e725);
                            }
                            let _e729 = phi_2289_;
                            let _e730 = select(_e725, -1f, _e729);
                            let _e740 = (f32((bitcast<i32>((((_e717 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e740 != _e740) {
                                phi_2304_ = true;
                            } else {
                                phi_2304_ = (-1f >= _e740);
                            }
                            let _e744 = phi_2304_;
                            let _e745 = select(_e740, -1f, _e744);
                            let _e748 = (1f - abs(_e730));
                            let _e749 = abs(_e745);
                            let _e750 = (_e748 - _e749);
                            if (_e750 < 0f) {
                                phi_1054_ = vec2<f32>(((1f - _e749) * select(1f, -1f, (_e730 < 0f))), (_e748 * select(1f, -1f, (_e745 < 0f))));
                            } else {
                                phi_1054_ = vec2<f32>(_e730, _e745);
                            }
                            let _e761 = phi_1054_;
                            let _e770 = (1f / sqrt((((_e761.x * _e761.x) + (_e761.y * _e761.y)) + (_e750 * _e750))));
                            let _e771 = (_e761.x * _e770);
                            let _e772 = (_e761.y * _e770);
                            let _e773 = (_e750 * _e770);
                            if ((((_e710 * _e771) + (_e712 * _e772)) + (_e713 * _e773)) > 0f) {
                                phi_1081_ = vec3<f32>(-(_e771), -(_e772), -(_e773));
                            } else {
                                phi_1081_ = vec3<f32>(_e771, _e772, _e773);
                            }
                            let _e786 = phi_1081_;
                            local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                            let _e787 = (_e576 % 4u);
                            if (_e787 < 4u) {
                            } else {
                                break;
                            }
                            let _e789 = (_e575 % 4u);
                            if (_e789 < 4u) {
                            } else {
                                break;
                            }
                            let _e793 = local_10[_e787][_e789];
                            let _e803 = sqrt((((_e710 * _e710) + (_e712 * _e712)) + (_e713 * _e713)));
                            let _e804 = (-(_e710) / _e803);
                            let _e805 = (-(_e712) / _e803);
                            let _e806 = (_e658 / _e803);
                            let _e809 = -((_e793[1] * _e806));
                            let _e810 = (_e806 * _e793[0]);
                            let _e813 = ((_e804 * _e793[1]) - (_e793[0] * _e805));
                            let _e820 = (1f / sqrt((((_e809 * _e809) + (_e810 * _e810)) + (_e813 * _e813))));
                            let _e821 = (_e809 * _e820);
                            let _e822 = (_e810 * _e820);
                            let _e823 = (_e813 * _e820);
                            let _e827 = ((_e822 * _e806) - (_e805 * _e823));
                            let _e830 = ((_e823 * _e804) - (_e806 * _e821));
                            let _e833 = ((_e821 * _e805) - (_e804 * _e822));
                            let _e852 = (((_e786.x * _e804) + (_e786.y * _e805)) + (_e786.z * _e806));
                            let _e856 = abs(_e852);
                            if (_e856 != _e856) {
                                phi_2319_ = true;
                            } else {
                                phi_2319_ = (0.0001f >= _e856);
                            }
                            let _e860 = phi_2319_;
                            phi_1193_ = type_28();
                            phi_1194_ = type_28(1u, type_27(vec2<u32>(_e575, _e576), vec2<f32>(_e654, _e655), _e699, _e700, vec3<f32>(_e710, _e712, _e713), _e786, vec3<f32>(_e804, _e805, _e806), vec3<f32>(_e827, _e830, _e833), vec3<f32>(_e821, _e822, _e823), vec3<f32>((((_e786.x * _e827) + (_e786.y * _e830)) + (_e786.z * _e833)), (((_e786.x * _e821) + (_e786.y * _e822)) + (_e786.z * _e823)), _e852), (1f / (select(1f, -1f, (_e852 < 0f)) * select(_e856, 0.0001f, _e860)))));
                        }
                        let _e869 = phi_1193_;
                        let _e871 = phi_1194_;
                        phi_1196_ = _e869;
                        phi_1197_ = _e871;
                        phi_1198_ = _e701;
                    } else {
                        phi_1196_ = type_28(0u, type_28().member_1);
                        phi_1197_ = type_28();
                        phi_1198_ = true;
                    }
                    let _e876 = phi_1196_;
                    let _e878 = phi_1197_;
                    let _e880 = phi_1198_;
                    if _e880 {
                        phi_1202_ = _e876;
                    } else {
                        phi_1202_ = _e878;
                    }
                    let _e882 = phi_1202_;
                    let _e885 = (bitcast<i32>(_e882.member) != 0i);
                    if _e885 {
                        let _e891 = frame.member[0u].member_1.member_11;
                        let _e896 = (8u << bitcast<u32>((select(_e891, 2u, (2u < _e891)) & 31u)));
                        phi_2717_ = false;
                        phi_1220_ = 0u;
                        phi_1223_ = 0u;
                        phi_1225_ = 0f;
                        loop {
                            let _e898 = phi_2717_;
                            let _e900 = phi_1220_;
                            let _e902 = phi_1223_;
                            let _e904 = phi_1225_;
                            local_12 = _e904;
                            local_13 = _e902;
                            let _e905 = (_e900 < _e896);
                            if _e905 {
                                if ((_e635 & (1u << bitcast<u32>((_e900 & 31u)))) == 0u) {
                                    phi_2786_ = _e898;
                                    phi_2211_ = _e904;
                                } else {
                                    let _e915 = frame.member[0u].member_1.member_10;
                                    let _e917 = ((_e896 + _e900) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e918 = (_e917 < 56u);
                                    if _e918 {
                                    } else {
                                        phi_2784_ = true;
                                        break;
                                    }
                                    let _e920 = local_4[_e917];
                                    let _e923 = (_e915 == 1u);
                                    if _e923 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e918 {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e925 = local_5[_e917];
                                        phi_1273_ = _e925;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e918 {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e927 = local_6[_e917];
                                        phi_1273_ = _e927;
                                    }
                                    let _e929 = phi_1273_;
                                    let _e931 = (_e882.member_1.member_2 * _e929);
                                    let _e932 = (_e931 * _e920[0]);
                                    let _e933 = (_e931 * _e920[1]);
                                    if _e923 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e918 {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e935 = local_7[_e917];
                                        phi_1298_ = _e935;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e918 {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e937 = local_8[_e917];
                                        phi_1298_ = _e937;
                                    }
                                    let _e939 = phi_1298_;
                                    let _e940 = (_e882.member_1.member_2 * _e939);
                                    if _e923 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e918 {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e942 = local_9[_e917];
                                        phi_1311_ = _e942;
                                    } else {
                                        phi_1311_ = (_e940 * 2f);
                                    }
                                    let _e945 = phi_1311_;
                                    let _e954 = (-(((_e932 * _e882.member_1.member_9.x) + (_e933 * _e882.member_1.member_9.y))) * _e882.member_1.member_10);
                                    let _e955 = -(_e940);
                                    let _e959 = select(_e955, select(_e940, _e954, (_e954 < _e940)), (_e954 > _e955));
                                    let _e984 = (-0.5f / ((_e882.member_1.member_4.z + (_e882.member_1.member_7.z * _e932)) + (_e882.member_1.member_8.z * _e933)));
                                    let _e993 = frame.member[0u].member_1.member.member.member_1[0u];
                                    let _e995 = (((((_e882.member_1.member_4.x + (_e882.member_1.member_7.x * _e932)) + (_e882.member_1.member_8.x * _e933)) * _e984) / _e993) + 0.5f);
                                    let _e1004 = frame.member[0u].member_1.member.member.member_1[1u];
                                    let _e1006 = (0.5f - ((((_e882.member_1.member_4.y + (_e882.member_1.member_7.y * _e932)) + (_e882.member_1.member_8.y * _e933)) * _e984) / _e1004));
                                    let _e1014 = frame.member[0u].member_1.member.member;
                                    let _e1021 = select(select(u32(_e1014.member.x), 0u, (_e1014.member.x < 0f)), 4294967295u, (_e1014.member.x > 4294967000f));
                                    let _e1032 = (select(0f, select(1f, _e995, (_e995 < 1f)), (_e995 > 0f)) * _e1014.member.x);
                                    let _e1037 = (select(0f, select(1f, _e1006, (_e1006 < 1f)), (_e1006 > 0f)) * _e1014.member.y);
                                    let _e1042 = select(select(u32(_e1032), 0u, (_e1032 < 0f)), 4294967295u, (_e1032 > 4294967000f));
                                    let _e1043 = (_e1021 - 1u);
                                    let _e1045 = select(_e1042, _e1043, (_e1043 < _e1042));
                                    let _e1050 = select(select(u32(_e1037), 0u, (_e1037 < 0f)), 4294967295u, (_e1037 > 4294967000f));
                                    let _e1051 = (select(select(u32(_e1014.member.y), 0u, (_e1014.member.y < 0f)), 4294967295u, (_e1014.member.y > 4294967000f)) - 1u);
                                    let _e1053 = select(_e1050, _e1051, (_e1051 < _e1050));
                                    let _e1060 = ((_e882.member_1.member_1.x - _e995) * _e589);
                                    let _e1061 = ((_e882.member_1.member_1.y - _e1006) * _e602);
                                    let _e1067 = ((_e1053 * _e594) + _e1045);
                                    if (_e1067 < _e552) {
                                    } else {
                                        phi_2784_ = true;
                                        break;
                                    }
                                    let _e1070 = depth.member[_e1067];
                                    let _e1082 = select(_e665, _e1070, select(false, (_e1070 < _e665), (_e1070 > 0f)));
                                    let _e1084 = ((((f32(_e1045) + 0.5f) * (1f / _e1014.member.x)) * 2f) - 1f);
                                    let _e1086 = ((((f32(_e1053) + 0.5f) * (1f / _e1014.member.y)) * -2f) + 1f);
                                    let _e1092 = (((_e1084 * _e1082) * _e993) - _e882.member_1.member_4.x);
                                    let _e1093 = (((_e1086 * _e1082) * _e1004) - _e882.member_1.member_4.y);
                                    let _e1094 = (-(_e1082) - _e882.member_1.member_4.z);
                                    let _e1103 = (((_e1092 * _e882.member_1.member_6.x) + (_e1093 * _e882.member_1.member_6.y)) + (_e1094 * _e882.member_1.member_6.z));
                                    if _e923 {
                                        let _e1108 = (((_e1092 * _e1092) + (_e1093 * _e1093)) + (_e1094 * _e1094));
                                        let _e1120 = (((((_e882.member_1.member_5.x * _e1092) + (_e882.member_1.member_5.y * _e1093)) + (_e882.member_1.member_5.z * _e1094)) / sqrt(_e1108)) - 0.1f);
                                        let _e1127 = (1f - (_e1108 / (_e643 * _e643)));
                                        let _e1134 = ((select(0f, select(1f, _e1120, (_e1120 < 1f)), (_e1120 > 0f)) * select(0f, select(1f, _e1127, (_e1127 < 1f)), (_e1127 > 0f))) / _e945);
                                        phi_1612_ = select(0f, select(0f, select(1f, _e1134, (_e1134 < 1f)), (_e1134 > 0f)), (_e1108 > 0f));
                                    } else {
                                        let _e1145 = frame.member[0u].member_1.member.member_3;
                                        if (_e959 != _e959) {
                                            phi_2425_ = true;
                                        } else {
                                            phi_2425_ = (_e1103 >= _e959);
                                        }
                                        let _e1150 = phi_2425_;
                                        let _e1152 = (_e940 - select(_e959, _e1103, _e1150));
                                        if (_e1152 != _e1152) {
                                            phi_2440_ = true;
                                        } else {
                                            phi_2440_ = (0f >= _e1152);
                                        }
                                        let _e1156 = phi_2440_;
                                        let _e1161 = ((_e1103 - (_e882.member_1.member_2 * (1f + _e1145))) * (1f / _e940));
                                        phi_1612_ = ((select(_e1152, 0f, _e1156) + (select(0f, select(1f, _e1161, (_e1161 < 1f)), (_e1161 > 0f)) * (_e940 - _e959))) * (0.5f / _e940));
                                    }
                                    let _e1172 = phi_1612_;
                                    let _e1177 = frame.member[0u].member_1.member_9;
                                    if (_e1177 == 0u) {
                                        phi_1851_ = type_42(_e1103, _e1172);
                                    } else {
                                        if _e923 {
                                            let _e1180 = (_e882.member_1.member_2 * 0.1f);
                                            if (_e940 != _e940) {
                                                phi_2455_ = true;
                                            } else {
                                                phi_2455_ = (_e1180 >= _e940);
                                            }
                                            let _e1184 = phi_2455_;
                                            phi_1635_ = select(_e940, _e1180, _e1184);
                                        } else {
                                            let _e1191 = frame.member[0u].member_1.member.member_3;
                                            phi_1635_ = (_e882.member_1.member_2 * (1f + _e1191));
                                        }
                                        let _e1195 = phi_1635_;
                                        let _e1201 = frame.member[0u].member_1.member_3;
                                        let _e1203 = select(false, (sqrt(((_e1060 * _e1060) + (_e1061 * _e1061))) > _e1201), (_e1103 > _e1195));
                                        let _e1205 = ((_e1053 * _e1021) + _e1045);
                                        if (_e1205 < arrayLength((&depth2_.member))) {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e1209 = depth2_.member[_e1205];
                                        let _e1213 = select(_e665, _e1209, select(false, (_e1209 < _e665), (_e1209 > 0f)));
                                        let _e1219 = (((_e1084 * _e1213) * _e993) - _e882.member_1.member_4.x);
                                        let _e1220 = (((_e1086 * _e1213) * _e1004) - _e882.member_1.member_4.y);
                                        let _e1221 = (-(_e1213) - _e882.member_1.member_4.z);
                                        let _e1226 = (((_e1219 * _e882.member_1.member_6.x) + (_e1220 * _e882.member_1.member_6.y)) + (_e1221 * _e882.member_1.member_6.z));
                                        if _e923 {
                                            let _e1231 = (((_e1219 * _e1219) + (_e1220 * _e1220)) + (_e1221 * _e1221));
                                            let _e1243 = (((((_e882.member_1.member_5.x * _e1219) + (_e882.member_1.member_5.y * _e1220)) + (_e882.member_1.member_5.z * _e1221)) / sqrt(_e1231)) - 0.1f);
                                            let _e1250 = (1f - (_e1231 / (_e643 * _e643)));
                                            let _e1257 = ((select(0f, select(1f, _e1243, (_e1243 < 1f)), (_e1243 > 0f)) * select(0f, select(1f, _e1250, (_e1250 < 1f)), (_e1250 > 0f))) / _e945);
                                            phi_1831_ = select(0f, select(0f, select(1f, _e1257, (_e1257 < 1f)), (_e1257 > 0f)), (_e1231 > 0f));
                                        } else {
                                            let _e1268 = frame.member[0u].member_1.member.member_3;
                                            if (_e959 != _e959) {
                                                phi_2507_ = true;
                                            } else {
                                                phi_2507_ = (_e1226 >= _e959);
                                            }
                                            let _e1273 = phi_2507_;
                                            let _e1275 = (_e940 - select(_e959, _e1226, _e1273));
                                            if (_e1275 != _e1275) {
                                                phi_2522_ = true;
                                            } else {
                                                phi_2522_ = (0f >= _e1275);
                                            }
                                            let _e1279 = phi_2522_;
                                            let _e1284 = ((_e1226 - (_e882.member_1.member_2 * (1f + _e1268))) * (1f / _e940));
                                            phi_1831_ = ((select(_e1275, 0f, _e1279) + (select(0f, select(1f, _e1284, (_e1284 < 1f)), (_e1284 > 0f)) * (_e940 - _e959))) * (0.5f / _e940));
                                        }
                                        let _e1295 = phi_1831_;
                                        if (_e1103 != _e1103) {
                                            phi_2537_ = true;
                                        } else {
                                            phi_2537_ = (_e1226 <= _e1103);
                                        }
                                        let _e1299 = phi_2537_;
                                        if _e923 {
                                            if (_e1172 != _e1172) {
                                                phi_2552_ = true;
                                            } else {
                                                phi_2552_ = (_e1295 >= _e1172);
                                            }
                                            let _e1305 = phi_2552_;
                                            phi_1845_ = select(_e1172, _e1295, _e1305);
                                        } else {
                                            if (_e1172 != _e1172) {
                                                phi_2567_ = true;
                                            } else {
                                                phi_2567_ = (_e1295 <= _e1172);
                                            }
                                            let _e1310 = phi_2567_;
                                            phi_1845_ = select(_e1172, _e1295, _e1310);
                                        }
                                        let _e1313 = phi_1845_;
                                        phi_1851_ = type_42(select(_e1103, select(_e1103, _e1226, _e1299), _e1203), select(_e1172, _e1313, _e1203));
                                    }
                                    let _e1317 = phi_1851_;
                                    if select(false, select(false, (_e1006 <= 1f), (_e1006 >= 0f)), select(false, (_e995 <= 1f), (_e995 >= 0f))) {
                                        phi_1864_ = _e1317.member_1;
                                    } else {
                                        phi_1864_ = select(1f, 0f, _e923);
                                    }
                                    let _e1322 = phi_1864_;
                                    let _e1328 = frame.member[0u].member_1.member_5[0u];
                                    let _e1334 = frame.member[0u].member_1.member_5[1u];
                                    let _e1335 = f32(_e1328);
                                    let _e1336 = f32(_e1334);
                                    let _e1341 = frame.member[0u].member_1.member_4;
                                    let _e1342 = f32(_e1341);
                                    let _e1343 = (2u * _e1341);
                                    let _e1344 = (_e1328 + _e1343);
                                    let _e1350 = (floor((_e995 * _e1335)) + _e1342);
                                    let _e1351 = f32((_e1344 - 1u));
                                    let _e1355 = select(0f, select(_e1351, _e1350, (_e1350 < _e1351)), (_e1350 > 0f));
                                    let _e1358 = (floor((_e1006 * _e1336)) + _e1342);
                                    let _e1359 = f32(((_e1334 + _e1343) - 1u));
                                    let _e1363 = select(0f, select(_e1359, _e1358, (_e1358 < _e1359)), (_e1358 > 0f));
                                    let _e1368 = select(select(u32(_e1355), 0u, (_e1355 < 0f)), 4294967295u, (_e1355 > 4294967000f));
                                    let _e1373 = select(select(u32(_e1363), 0u, (_e1363 < 0f)), 4294967295u, (_e1363 > 4294967000f));
                                    let _e1376 = bitcast<i32>(_e1341);
                                    let _e1385 = frame.member[0u].member_1.member_8;
                                    let _e1390 = frame.member[0u].member_1.member_12;
                                    let _e1397 = (((((_e1373 % 4u) * 4u) + (_e1368 % 4u)) + (_e1390 % 16u)) % 16u);
                                    if (_e1385 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1399 = (_e1397 < 16u);
                                        if _e1399 {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e1402 = local[_e1397][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1399 {
                                        } else {
                                            phi_2784_ = true;
                                            break;
                                        }
                                        let _e1405 = local_1[_e1397][1u];
                                        phi_1998_ = vec2<f32>(_e1402, _e1405);
                                    } else {
                                        if (_e1385 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1408 = (_e1397 < 16u);
                                            if _e1408 {
                                            } else {
                                                phi_2784_ = true;
                                                break;
                                            }
                                            let _e1411 = local_2[_e1397][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1408 {
                                            } else {
                                                phi_2784_ = true;
                                                break;
                                            }
                                            let _e1414 = local_3[_e1397][1u];
                                            phi_1997_ = vec2<f32>(_e1411, _e1414);
                                        } else {
                                            phi_1997_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1417 = phi_1997_;
                                        phi_1998_ = _e1417;
                                    }
                                    let _e1419 = phi_1998_;
                                    let _e1432 = frame.member[0u].member_1.member_6;
                                    phi_2029_ = 0u;
                                    phi_2032_ = _e1322;
                                    loop {
                                        let _e1435 = phi_2029_;
                                        let _e1437 = phi_2032_;
                                        local_11 = _e1437;
                                        let _e1438 = (_e1435 < _e1432);
                                        if _e1438 {
                                            let _e1439 = ((((_e1373 * _e1344) + _e1368) * _e1432) + _e1435);
                                            if (_e1439 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2671_ = true;
                                                break;
                                            }
                                            let _e1442 = sd_map.member[_e1439];
                                            let _e1449 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1452 = ((_e1442 * (_e665 - _e1449)) + _e1449);
                                            let _e1462 = (((((((f32((bitcast<i32>(_e1368) - _e1376)) + _e1419.x) / _e1335) * 2f) - 1f) * _e1452) * _e993) - _e882.member_1.member_4.x);
                                            let _e1463 = (((((((f32((bitcast<i32>(_e1373) - _e1376)) + _e1419.y) / _e1336) * -2f) + 1f) * _e1452) * _e1004) - _e882.member_1.member_4.y);
                                            let _e1464 = (-(_e1452) - _e882.member_1.member_4.z);
                                            let _e1469 = (((_e1462 * _e882.member_1.member_6.x) + (_e1463 * _e882.member_1.member_6.y)) + (_e1464 * _e882.member_1.member_6.z));
                                            if _e923 {
                                                let _e1474 = (((_e1462 * _e1462) + (_e1463 * _e1463)) + (_e1464 * _e1464));
                                                let _e1486 = (((((_e882.member_1.member_5.x * _e1462) + (_e882.member_1.member_5.y * _e1463)) + (_e882.member_1.member_5.z * _e1464)) / sqrt(_e1474)) - 0.1f);
                                                let _e1493 = (1f - (_e1474 / (_e643 * _e643)));
                                                let _e1500 = ((select(0f, select(1f, _e1486, (_e1486 < 1f)), (_e1486 > 0f)) * select(0f, select(1f, _e1493, (_e1493 < 1f)), (_e1493 > 0f))) / _e945);
                                                phi_2197_ = select(0f, select(0f, select(1f, _e1500, (_e1500 < 1f)), (_e1500 > 0f)), (_e1474 > 0f));
                                            } else {
                                                let _e1511 = frame.member[0u].member_1.member.member_3;
                                                if (_e959 != _e959) {
                                                    phi_2582_ = true;
                                                } else {
                                                    phi_2582_ = (_e1469 >= _e959);
                                                }
                                                let _e1516 = phi_2582_;
                                                let _e1518 = (_e940 - select(_e959, _e1469, _e1516));
                                                if (_e1518 != _e1518) {
                                                    phi_2597_ = true;
                                                } else {
                                                    phi_2597_ = (0f >= _e1518);
                                                }
                                                let _e1522 = phi_2597_;
                                                let _e1527 = ((_e1469 - (_e882.member_1.member_2 * (1f + _e1511))) * (1f / _e940));
                                                phi_2197_ = ((select(_e1518, 0f, _e1522) + (select(0f, select(1f, _e1527, (_e1527 < 1f)), (_e1527 > 0f)) * (_e940 - _e959))) * (0.5f / _e940));
                                            }
                                            let _e1538 = phi_2197_;
                                            if _e923 {
                                                if (_e1437 != _e1437) {
                                                    phi_2612_ = true;
                                                } else {
                                                    phi_2612_ = (_e1538 >= _e1437);
                                                }
                                                let _e1542 = phi_2612_;
                                                phi_2206_ = select(_e1437, _e1538, _e1542);
                                            } else {
                                                if (_e1437 != _e1437) {
                                                    phi_2627_ = true;
                                                } else {
                                                    phi_2627_ = (_e1538 <= _e1437);
                                                }
                                                let _e1547 = phi_2627_;
                                                phi_2206_ = select(_e1437, _e1538, _e1547);
                                            }
                                            let _e1550 = phi_2206_;
                                            phi_2030_ = (_e1435 + 1u);
                                            phi_2033_ = _e1550;
                                        } else {
                                            phi_2030_ = u32();
                                            phi_2033_ = f32();
                                        }
                                        let _e1553 = phi_2030_;
                                        let _e1555 = phi_2033_;
                                        continue;
                                        continuing {
                                            phi_2029_ = _e1553;
                                            phi_2032_ = _e1555;
                                            phi_2671_ = _e898;
                                            break if !(_e1438);
                                        }
                                    }
                                    let _e1558 = phi_2671_;
                                    phi_2784_ = _e1558;
                                    if _e1558 {
                                        break;
                                    }
                                    let _e1560 = local_11;
                                    phi_2786_ = _e1558;
                                    phi_2211_ = ((_e904 - _e1317.member_1) + _e1560);
                                }
                                let _e1563 = phi_2786_;
                                let _e1565 = phi_2211_;
                                phi_2785_ = _e1563;
                                phi_1221_ = (_e900 + 1u);
                                phi_1226_ = _e1565;
                            } else {
                                phi_2785_ = _e898;
                                phi_1221_ = u32();
                                phi_1226_ = f32();
                            }
                            let _e1568 = phi_2785_;
                            let _e1570 = phi_1221_;
                            let _e1572 = phi_1226_;
                            continue;
                            continuing {
                                phi_2717_ = _e1568;
                                phi_1220_ = _e1570;
                                phi_1223_ = select(u32(), _e902, _e905);
                                phi_1225_ = _e1572;
                                phi_2784_ = _e1568;
                                break if !(_e905);
                            }
                        }
                        let _e1576 = phi_2784_;
                        if _e1576 {
                            break;
                        }
                        let _e1581 = frame.member[0u].member_1.member_10;
                        let _e1582 = (_e1581 == 1u);
                        let _e1587 = local_12;
                        let _e1589 = (_e631 + ((select(2f, 1f, _e1582) / f32(_e896)) * _e1587));
                        if _e1582 {
                            phi_2241_ = (1f - (2f * _e1589));
                        } else {
                            phi_2241_ = _e1589;
                        }
                        let _e1593 = phi_2241_;
                        let _e1603 = frame.member[0u].member_1.member.member_2;
                        let _e1606 = local_13;
                        phi_2256_ = type_43(pow(select(0f, select(1f, _e1593, (_e1593 < 1f)), (_e1593 > 0f)), _e1603), _e1606);
                    } else {
                        phi_2256_ = type_43();
                    }
                    let _e1609 = phi_2256_;
                    phi_2258_ = _e1609;
                    phi_2259_ = select(true, false, _e885);
                }
                let _e1612 = phi_2258_;
                let _e1614 = phi_2259_;
                if _e1614 {
                    phi_2263_ = type_43(_e631, 0u);
                } else {
                    phi_2263_ = _e1612;
                }
                let _e1616 = phi_2263_;
                if _e628 {
                } else {
                    break;
                }
                ao.member[_e627] = _e1616.member;
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
