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
    var phi_948_: bool;
    var phi_978_: f32;
    var phi_2293_: bool;
    var phi_2308_: bool;
    var phi_1054_: vec2<f32>;
    var phi_1081_: vec3<f32>;
    var phi_2323_: bool;
    var phi_1193_: type_28;
    var phi_1194_: type_28;
    var phi_1196_: type_28;
    var phi_1197_: type_28;
    var phi_1198_: bool;
    var phi_1202_: type_28;
    var phi_2721_: bool;
    var phi_1220_: u32;
    var phi_1223_: u32;
    var phi_1225_: f32;
    var phi_1273_: f32;
    var phi_1298_: f32;
    var phi_1311_: f32;
    var phi_2429_: bool;
    var phi_2444_: bool;
    var phi_1614_: f32;
    var phi_2459_: bool;
    var phi_1637_: f32;
    var phi_2511_: bool;
    var phi_2526_: bool;
    var phi_1835_: f32;
    var phi_2541_: bool;
    var phi_2556_: bool;
    var phi_2571_: bool;
    var phi_1849_: f32;
    var phi_1855_: type_42;
    var phi_1868_: f32;
    var phi_2001_: vec2<f32>;
    var phi_2002_: vec2<f32>;
    var phi_2033_: u32;
    var phi_2036_: f32;
    var phi_2586_: bool;
    var phi_2601_: bool;
    var phi_2201_: f32;
    var phi_2616_: bool;
    var phi_2631_: bool;
    var phi_2210_: f32;
    var phi_2034_: u32;
    var phi_2037_: f32;
    var phi_2675_: bool;
    var local_11: f32;
    var phi_2790_: bool;
    var phi_2215_: f32;
    var phi_2789_: bool;
    var phi_1221_: u32;
    var phi_1226_: f32;
    var phi_2788_: bool;
    var local_12: f32;
    var phi_2245_: f32;
    var local_13: u32;
    var phi_2260_: type_43;
    var phi_2262_: type_43;
    var phi_2263_: bool;
    var phi_2267_: type_43;

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
                    phi_2262_ = type_43();
                    phi_2263_ = true;
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
                    if (_e658 > 0f) {
                        phi_948_ = (_e658 < _e665);
                    } else {
                        phi_948_ = false;
                    }
                    let _e669 = phi_948_;
                    if _e669 {
                        let _e677 = frame.member[0u].member_1.member.member.member_1[0u];
                        let _e685 = frame.member[0u].member_1.member.member.member_1[1u];
                        let _e695 = (0.5f * (((_e643 * _e589) / ((2f * _e677) * _e658)) + ((_e643 * _e602) / ((2f * _e685) * _e658))));
                        let _e696 = (_e695 > _e649);
                        if _e696 {
                            phi_978_ = ((_e643 * _e649) / _e695);
                        } else {
                            phi_978_ = _e643;
                        }
                        let _e700 = phi_978_;
                        let _e701 = select(_e695, _e649, _e696);
                        let _e702 = (_e701 < 0.5f);
                        if _e702 {
                            phi_1193_ = type_28(0u, type_28().member_1);
                            phi_1194_ = type_28();
                        } else {
                            let _e711 = ((((_e654 * 2f) - 1f) * _e658) * _e677);
                            let _e713 = ((((_e655 * -2f) + 1f) * _e658) * _e685);
                            let _e714 = -(_e658);
                            if (_e627 < arrayLength((&normals.member))) {
                            } else {
                                break;
                            }
                            let _e718 = normals.member[_e627];
                            let _e726 = (f32((bitcast<i32>(((_e718 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e726 != _e726) {
                                phi_2293_ = true;
                            } else {
                                phi_2293_ = (-1f >= _e726);
                            }
                            let _e730 = phi_2293_;
                            let _e731 = select(_e726, -1f, _e730);
                            let _e741 = (f32((bitcast<i32>((((_e718 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e741 != _e741) {
                                phi_2308_ = true;
                            } else {
                                phi_2308_ = (-1f >= _e741);
                            }
                            let _e745 = phi_2308_;
                            let _e746 = select(_e741, -1f, _e745);
                            let _e749 = (1f - abs(_e731));
                            let _e750 = abs(_e746);
                            let _e751 = (_e749 - _e750);
                            if (_e751 < 0f) {
                                phi_1054_ = vec2<f32>(((1f - _e750) * select(1f, -1f, (_e731 < 0f))), (_e749 * select(1f, -1f, (_e746 < 0f))));
                            } else {
                                phi_1054_ = vec2<f32>(_e731, _e746);
                            }
                            let _e762 = phi_1054_;
                            let _e771 = (1f / sqrt((((_e762.x * _e762.x) + (_e762.y * _e762.y)) + (_e751 * _e751))));
                            let _e772 = (_e762.x * _e771);
                            let _e773 = (_e762.y * _e771);
                            let _e774 = (_e751 * _e771);
                            if ((((_e711 * _e772) + (_e713 * _e773)) + (_e714 * _e774)) > 0f) {
                                phi_1081_ = vec3<f32>(-(_e772), -(_e773), -(_e774));
                            } else {
                                phi_1081_ = vec3<f32>(_e772, _e773, _e774);
                            }
                            let _e787 = phi_1081_;
                            local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                            let _e788 = (_e576 % 4u);
                            if (_e788 < 4u) {
                            } else {
                                break;
                            }
                            let _e790 = (_e575 % 4u);
                            if (_e790 < 4u) {
                            } else {
                                break;
                            }
                            let _e794 = local_10[_e788][_e790];
                            let _e804 = sqrt((((_e711 * _e711) + (_e713 * _e713)) + (_e714 * _e714)));
                            let _e805 = (-(_e711) / _e804);
                            let _e806 = (-(_e713) / _e804);
                            let _e807 = (_e658 / _e804);
                            let _e810 = -((_e794[1] * _e807));
                            let _e811 = (_e807 * _e794[0]);
                            let _e814 = ((_e805 * _e794[1]) - (_e794[0] * _e806));
                            let _e821 = (1f / sqrt((((_e810 * _e810) + (_e811 * _e811)) + (_e814 * _e814))));
                            let _e822 = (_e810 * _e821);
                            let _e823 = (_e811 * _e821);
                            let _e824 = (_e814 * _e821);
                            let _e828 = ((_e823 * _e807) - (_e806 * _e824));
                            let _e831 = ((_e824 * _e805) - (_e807 * _e822));
                            let _e834 = ((_e822 * _e806) - (_e805 * _e823));
                            let _e853 = (((_e787.x * _e805) + (_e787.y * _e806)) + (_e787.z * _e807));
                            let _e857 = abs(_e853);
                            if (_e857 != _e857) {
                                phi_2323_ = true;
                            } else {
                                phi_2323_ = (0.0001f >= _e857);
                            }
                            let _e861 = phi_2323_;
                            phi_1193_ = type_28();
                            phi_1194_ = type_28(1u, type_27(vec2<u32>(_e575, _e576), vec2<f32>(_e654, _e655), _e700, _e701, vec3<f32>(_e711, _e713, _e714), _e787, vec3<f32>(_e805, _e806, _e807), vec3<f32>(_e828, _e831, _e834), vec3<f32>(_e822, _e823, _e824), vec3<f32>((((_e787.x * _e828) + (_e787.y * _e831)) + (_e787.z * _e834)), (((_e787.x * _e822) + (_e787.y * _e823)) + (_e787.z * _e824)), _e853), (1f / (select(1f, -1f, (_e853 < 0f)) * select(_e857, 0.0001f, _e861)))));
                        }
                        let _e870 = phi_1193_;
                        let _e872 = phi_1194_;
                        phi_1196_ = _e870;
                        phi_1197_ = _e872;
                        phi_1198_ = _e702;
                    } else {
                        phi_1196_ = type_28(0u, type_28().member_1);
                        phi_1197_ = type_28();
                        phi_1198_ = true;
                    }
                    let _e877 = phi_1196_;
                    let _e879 = phi_1197_;
                    let _e881 = phi_1198_;
                    if _e881 {
                        phi_1202_ = _e877;
                    } else {
                        phi_1202_ = _e879;
                    }
                    let _e883 = phi_1202_;
                    let _e886 = (bitcast<i32>(_e883.member) != 0i);
                    if _e886 {
                        let _e892 = frame.member[0u].member_1.member_11;
                        let _e897 = (8u << bitcast<u32>((select(_e892, 2u, (2u < _e892)) & 31u)));
                        phi_2721_ = false;
                        phi_1220_ = 0u;
                        phi_1223_ = 0u;
                        phi_1225_ = 0f;
                        loop {
                            let _e899 = phi_2721_;
                            let _e901 = phi_1220_;
                            let _e903 = phi_1223_;
                            let _e905 = phi_1225_;
                            local_12 = _e905;
                            local_13 = _e903;
                            let _e906 = (_e901 < _e897);
                            if _e906 {
                                if ((_e635 & (1u << bitcast<u32>((_e901 & 31u)))) == 0u) {
                                    phi_2790_ = _e899;
                                    phi_2215_ = _e905;
                                } else {
                                    let _e916 = frame.member[0u].member_1.member_10;
                                    let _e918 = ((_e897 + _e901) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e919 = (_e918 < 56u);
                                    if _e919 {
                                    } else {
                                        phi_2788_ = true;
                                        break;
                                    }
                                    let _e921 = local_4[_e918];
                                    let _e924 = (_e916 == 1u);
                                    if _e924 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e919 {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e926 = local_5[_e918];
                                        phi_1273_ = _e926;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e919 {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e928 = local_6[_e918];
                                        phi_1273_ = _e928;
                                    }
                                    let _e930 = phi_1273_;
                                    let _e932 = (_e883.member_1.member_2 * _e930);
                                    let _e933 = (_e932 * _e921[0]);
                                    let _e934 = (_e932 * _e921[1]);
                                    if _e924 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e919 {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e936 = local_7[_e918];
                                        phi_1298_ = _e936;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e919 {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e938 = local_8[_e918];
                                        phi_1298_ = _e938;
                                    }
                                    let _e940 = phi_1298_;
                                    let _e941 = (_e883.member_1.member_2 * _e940);
                                    if _e924 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e919 {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e943 = local_9[_e918];
                                        phi_1311_ = _e943;
                                    } else {
                                        phi_1311_ = (_e941 * 2f);
                                    }
                                    let _e946 = phi_1311_;
                                    let _e955 = (-(((_e933 * _e883.member_1.member_9.x) + (_e934 * _e883.member_1.member_9.y))) * _e883.member_1.member_10);
                                    let _e956 = -(_e941);
                                    let _e960 = select(_e956, select(_e941, _e955, (_e955 < _e941)), (_e955 > _e956));
                                    let _e985 = (-0.5f / ((_e883.member_1.member_4.z + (_e883.member_1.member_7.z * _e933)) + (_e883.member_1.member_8.z * _e934)));
                                    let _e994 = frame.member[0u].member_1.member.member.member_1[0u];
                                    let _e996 = (((((_e883.member_1.member_4.x + (_e883.member_1.member_7.x * _e933)) + (_e883.member_1.member_8.x * _e934)) * _e985) / _e994) + 0.5f);
                                    let _e1005 = frame.member[0u].member_1.member.member.member_1[1u];
                                    let _e1007 = (0.5f - ((((_e883.member_1.member_4.y + (_e883.member_1.member_7.y * _e933)) + (_e883.member_1.member_8.y * _e934)) * _e985) / _e1005));
                                    let _e1015 = frame.member[0u].member_1.member.member;
                                    let _e1022 = select(select(u32(_e1015.member.x), 0u, (_e1015.member.x < 0f)), 4294967295u, (_e1015.member.x > 4294967000f));
                                    let _e1033 = (select(0f, select(1f, _e996, (_e996 < 1f)), (_e996 > 0f)) * _e1015.member.x);
                                    let _e1038 = (select(0f, select(1f, _e1007, (_e1007 < 1f)), (_e1007 > 0f)) * _e1015.member.y);
                                    let _e1043 = select(select(u32(_e1033), 0u, (_e1033 < 0f)), 4294967295u, (_e1033 > 4294967000f));
                                    let _e1044 = (_e1022 - 1u);
                                    let _e1046 = select(_e1043, _e1044, (_e1044 < _e1043));
                                    let _e1051 = select(select(u32(_e1038), 0u, (_e1038 < 0f)), 4294967295u, (_e1038 > 4294967000f));
                                    let _e1052 = (select(select(u32(_e1015.member.y), 0u, (_e1015.member.y < 0f)), 4294967295u, (_e1015.member.y > 4294967000f)) - 1u);
                                    let _e1054 = select(_e1051, _e1052, (_e1052 < _e1051));
                                    let _e1061 = ((_e883.member_1.member_1.x - _e996) * _e589);
                                    let _e1062 = ((_e883.member_1.member_1.y - _e1007) * _e602);
                                    let _e1068 = ((_e1054 * _e594) + _e1046);
                                    if (_e1068 < _e552) {
                                    } else {
                                        phi_2788_ = true;
                                        break;
                                    }
                                    let _e1071 = depth.member[_e1068];
                                    let _e1075 = select(_e665, _e1071, select(false, (_e1071 < _e665), (_e1071 > 0f)));
                                    let _e1085 = ((((f32(_e1046) + 0.5f) * (1f / _e1015.member.x)) * 2f) - 1f);
                                    let _e1087 = ((((f32(_e1054) + 0.5f) * (1f / _e1015.member.y)) * -2f) + 1f);
                                    let _e1093 = (((_e1085 * _e1075) * _e994) - _e883.member_1.member_4.x);
                                    let _e1094 = (((_e1087 * _e1075) * _e1005) - _e883.member_1.member_4.y);
                                    let _e1095 = (-(_e1075) - _e883.member_1.member_4.z);
                                    let _e1104 = (((_e1093 * _e883.member_1.member_6.x) + (_e1094 * _e883.member_1.member_6.y)) + (_e1095 * _e883.member_1.member_6.z));
                                    if _e924 {
                                        let _e1109 = (((_e1093 * _e1093) + (_e1094 * _e1094)) + (_e1095 * _e1095));
                                        let _e1121 = (((((_e883.member_1.member_5.x * _e1093) + (_e883.member_1.member_5.y * _e1094)) + (_e883.member_1.member_5.z * _e1095)) / sqrt(_e1109)) - 0.1f);
                                        let _e1128 = (1f - (_e1109 / (_e643 * _e643)));
                                        let _e1135 = ((select(0f, select(1f, _e1121, (_e1121 < 1f)), (_e1121 > 0f)) * select(0f, select(1f, _e1128, (_e1128 < 1f)), (_e1128 > 0f))) / _e946);
                                        phi_1614_ = select(0f, select(0f, select(1f, _e1135, (_e1135 < 1f)), (_e1135 > 0f)), (_e1109 > 0f));
                                    } else {
                                        let _e1146 = frame.member[0u].member_1.member.member_3;
                                        if (_e960 != _e960) {
                                            phi_2429_ = true;
                                        } else {
                                            phi_2429_ = (_e1104 >= _e960);
                                        }
                                        let _e1151 = phi_2429_;
                                        let _e1153 = (_e941 - select(_e960, _e1104, _e1151));
                                        if (_e1153 != _e1153) {
                                            phi_2444_ = true;
                                        } else {
                                            phi_2444_ = (0f >= _e1153);
                                        }
                                        let _e1157 = phi_2444_;
                                        let _e1162 = ((_e1104 - (_e883.member_1.member_2 * (1f + _e1146))) * (1f / _e941));
                                        phi_1614_ = ((select(_e1153, 0f, _e1157) + (select(0f, select(1f, _e1162, (_e1162 < 1f)), (_e1162 > 0f)) * (_e941 - _e960))) * (0.5f / _e941));
                                    }
                                    let _e1173 = phi_1614_;
                                    let _e1178 = frame.member[0u].member_1.member_9;
                                    if (_e1178 == 0u) {
                                        phi_1855_ = type_42(_e1104, _e1173);
                                    } else {
                                        if _e924 {
                                            let _e1181 = (_e883.member_1.member_2 * 0.1f);
                                            if (_e941 != _e941) {
                                                phi_2459_ = true;
                                            } else {
                                                phi_2459_ = (_e1181 >= _e941);
                                            }
                                            let _e1185 = phi_2459_;
                                            phi_1637_ = select(_e941, _e1181, _e1185);
                                        } else {
                                            let _e1192 = frame.member[0u].member_1.member.member_3;
                                            phi_1637_ = (_e883.member_1.member_2 * (1f + _e1192));
                                        }
                                        let _e1196 = phi_1637_;
                                        let _e1202 = frame.member[0u].member_1.member_3;
                                        let _e1204 = select(false, (sqrt(((_e1061 * _e1061) + (_e1062 * _e1062))) > _e1202), (_e1104 > _e1196));
                                        let _e1206 = ((_e1054 * _e1022) + _e1046);
                                        if (_e1206 < arrayLength((&depth2_.member))) {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e1210 = depth2_.member[_e1206];
                                        let _e1214 = select(_e665, _e1210, select(false, (_e1210 < _e665), (_e1210 > 0f)));
                                        let _e1220 = (((_e1085 * _e1214) * _e994) - _e883.member_1.member_4.x);
                                        let _e1221 = (((_e1087 * _e1214) * _e1005) - _e883.member_1.member_4.y);
                                        let _e1222 = (-(_e1214) - _e883.member_1.member_4.z);
                                        let _e1227 = (((_e1220 * _e883.member_1.member_6.x) + (_e1221 * _e883.member_1.member_6.y)) + (_e1222 * _e883.member_1.member_6.z));
                                        if _e924 {
                                            let _e1232 = (((_e1220 * _e1220) + (_e1221 * _e1221)) + (_e1222 * _e1222));
                                            let _e1244 = (((((_e883.member_1.member_5.x * _e1220) + (_e883.member_1.member_5.y * _e1221)) + (_e883.member_1.member_5.z * _e1222)) / sqrt(_e1232)) - 0.1f);
                                            let _e1251 = (1f - (_e1232 / (_e643 * _e643)));
                                            let _e1258 = ((select(0f, select(1f, _e1244, (_e1244 < 1f)), (_e1244 > 0f)) * select(0f, select(1f, _e1251, (_e1251 < 1f)), (_e1251 > 0f))) / _e946);
                                            phi_1835_ = select(0f, select(0f, select(1f, _e1258, (_e1258 < 1f)), (_e1258 > 0f)), (_e1232 > 0f));
                                        } else {
                                            let _e1269 = frame.member[0u].member_1.member.member_3;
                                            if (_e960 != _e960) {
                                                phi_2511_ = true;
                                            } else {
                                                phi_2511_ = (_e1227 >= _e960);
                                            }
                                            let _e1274 = phi_2511_;
                                            let _e1276 = (_e941 - select(_e960, _e1227, _e1274));
                                            if (_e1276 != _e1276) {
                                                phi_2526_ = true;
                                            } else {
                                                phi_2526_ = (0f >= _e1276);
                                            }
                                            let _e1280 = phi_2526_;
                                            let _e1285 = ((_e1227 - (_e883.member_1.member_2 * (1f + _e1269))) * (1f / _e941));
                                            phi_1835_ = ((select(_e1276, 0f, _e1280) + (select(0f, select(1f, _e1285, (_e1285 < 1f)), (_e1285 > 0f)) * (_e941 - _e960))) * (0.5f / _e941));
                                        }
                                        let _e1296 = phi_1835_;
                                        if (_e1104 != _e1104) {
                                            phi_2541_ = true;
                                        } else {
                                            phi_2541_ = (_e1227 <= _e1104);
                                        }
                                        let _e1300 = phi_2541_;
                                        if _e924 {
                                            if (_e1173 != _e1173) {
                                                phi_2556_ = true;
                                            } else {
                                                phi_2556_ = (_e1296 >= _e1173);
                                            }
                                            let _e1306 = phi_2556_;
                                            phi_1849_ = select(_e1173, _e1296, _e1306);
                                        } else {
                                            if (_e1173 != _e1173) {
                                                phi_2571_ = true;
                                            } else {
                                                phi_2571_ = (_e1296 <= _e1173);
                                            }
                                            let _e1311 = phi_2571_;
                                            phi_1849_ = select(_e1173, _e1296, _e1311);
                                        }
                                        let _e1314 = phi_1849_;
                                        phi_1855_ = type_42(select(_e1104, select(_e1104, _e1227, _e1300), _e1204), select(_e1173, _e1314, _e1204));
                                    }
                                    let _e1318 = phi_1855_;
                                    if select(false, select(false, (_e1007 <= 1f), (_e1007 >= 0f)), select(false, (_e996 <= 1f), (_e996 >= 0f))) {
                                        phi_1868_ = _e1318.member_1;
                                    } else {
                                        phi_1868_ = select(1f, 0f, _e924);
                                    }
                                    let _e1323 = phi_1868_;
                                    let _e1329 = frame.member[0u].member_1.member_5[0u];
                                    let _e1335 = frame.member[0u].member_1.member_5[1u];
                                    let _e1336 = f32(_e1329);
                                    let _e1337 = f32(_e1335);
                                    let _e1342 = frame.member[0u].member_1.member_4;
                                    let _e1343 = f32(_e1342);
                                    let _e1344 = (2u * _e1342);
                                    let _e1345 = (_e1329 + _e1344);
                                    let _e1351 = (floor((_e996 * _e1336)) + _e1343);
                                    let _e1352 = f32((_e1345 - 1u));
                                    let _e1356 = select(0f, select(_e1352, _e1351, (_e1351 < _e1352)), (_e1351 > 0f));
                                    let _e1359 = (floor((_e1007 * _e1337)) + _e1343);
                                    let _e1360 = f32(((_e1335 + _e1344) - 1u));
                                    let _e1364 = select(0f, select(_e1360, _e1359, (_e1359 < _e1360)), (_e1359 > 0f));
                                    let _e1369 = select(select(u32(_e1356), 0u, (_e1356 < 0f)), 4294967295u, (_e1356 > 4294967000f));
                                    let _e1374 = select(select(u32(_e1364), 0u, (_e1364 < 0f)), 4294967295u, (_e1364 > 4294967000f));
                                    let _e1377 = bitcast<i32>(_e1342);
                                    let _e1386 = frame.member[0u].member_1.member_8;
                                    let _e1391 = frame.member[0u].member_1.member_12;
                                    let _e1398 = (((((_e1374 % 4u) * 4u) + (_e1369 % 4u)) + (_e1391 % 16u)) % 16u);
                                    if (_e1386 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1400 = (_e1398 < 16u);
                                        if _e1400 {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e1403 = local[_e1398][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1400 {
                                        } else {
                                            phi_2788_ = true;
                                            break;
                                        }
                                        let _e1406 = local_1[_e1398][1u];
                                        phi_2002_ = vec2<f32>(_e1403, _e1406);
                                    } else {
                                        if (_e1386 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1409 = (_e1398 < 16u);
                                            if _e1409 {
                                            } else {
                                                phi_2788_ = true;
                                                break;
                                            }
                                            let _e1412 = local_2[_e1398][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1409 {
                                            } else {
                                                phi_2788_ = true;
                                                break;
                                            }
                                            let _e1415 = local_3[_e1398][1u];
                                            phi_2001_ = vec2<f32>(_e1412, _e1415);
                                        } else {
                                            phi_2001_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1418 = phi_2001_;
                                        phi_2002_ = _e1418;
                                    }
                                    let _e1420 = phi_2002_;
                                    let _e1433 = frame.member[0u].member_1.member_6;
                                    phi_2033_ = 0u;
                                    phi_2036_ = _e1323;
                                    loop {
                                        let _e1436 = phi_2033_;
                                        let _e1438 = phi_2036_;
                                        local_11 = _e1438;
                                        let _e1439 = (_e1436 < _e1433);
                                        if _e1439 {
                                            let _e1440 = ((((_e1374 * _e1345) + _e1369) * _e1433) + _e1436);
                                            if (_e1440 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2675_ = true;
                                                break;
                                            }
                                            let _e1443 = sd_map.member[_e1440];
                                            let _e1450 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1453 = ((_e1443 * (_e665 - _e1450)) + _e1450);
                                            let _e1463 = (((((((f32((bitcast<i32>(_e1369) - _e1377)) + _e1420.x) / _e1336) * 2f) - 1f) * _e1453) * _e994) - _e883.member_1.member_4.x);
                                            let _e1464 = (((((((f32((bitcast<i32>(_e1374) - _e1377)) + _e1420.y) / _e1337) * -2f) + 1f) * _e1453) * _e1005) - _e883.member_1.member_4.y);
                                            let _e1465 = (-(_e1453) - _e883.member_1.member_4.z);
                                            let _e1470 = (((_e1463 * _e883.member_1.member_6.x) + (_e1464 * _e883.member_1.member_6.y)) + (_e1465 * _e883.member_1.member_6.z));
                                            if _e924 {
                                                let _e1475 = (((_e1463 * _e1463) + (_e1464 * _e1464)) + (_e1465 * _e1465));
                                                let _e1487 = (((((_e883.member_1.member_5.x * _e1463) + (_e883.member_1.member_5.y * _e1464)) + (_e883.member_1.member_5.z * _e1465)) / sqrt(_e1475)) - 0.1f);
                                                let _e1494 = (1f - (_e1475 / (_e643 * _e643)));
                                                let _e1501 = ((select(0f, select(1f, _e1487, (_e1487 < 1f)), (_e1487 > 0f)) * select(0f, select(1f, _e1494, (_e1494 < 1f)), (_e1494 > 0f))) / _e946);
                                                phi_2201_ = select(0f, select(0f, select(1f, _e1501, (_e1501 < 1f)), (_e1501 > 0f)), (_e1475 > 0f));
                                            } else {
                                                let _e1512 = frame.member[0u].member_1.member.member_3;
                                                if (_e960 != _e960) {
                                                    phi_2586_ = true;
                                                } else {
                                                    phi_2586_ = (_e1470 >= _e960);
                                                }
                                                let _e1517 = phi_2586_;
                                                let _e1519 = (_e941 - select(_e960, _e1470, _e1517));
                                                if (_e1519 != _e1519) {
                                                    phi_2601_ = true;
                                                } else {
                                                    phi_2601_ = (0f >= _e1519);
                                                }
                                                let _e1523 = phi_2601_;
                                                let _e1528 = ((_e1470 - (_e883.member_1.member_2 * (1f + _e1512))) * (1f / _e941));
                                                phi_2201_ = ((select(_e1519, 0f, _e1523) + (select(0f, select(1f, _e1528, (_e1528 < 1f)), (_e1528 > 0f)) * (_e941 - _e960))) * (0.5f / _e941));
                                            }
                                            let _e1539 = phi_2201_;
                                            if _e924 {
                                                if (_e1438 != _e1438) {
                                                    phi_2616_ = true;
                                                } else {
                                                    phi_2616_ = (_e1539 >= _e1438);
                                                }
                                                let _e1543 = phi_2616_;
                                                phi_2210_ = select(_e1438, _e1539, _e1543);
                                            } else {
                                                if (_e1438 != _e1438) {
                                                    phi_2631_ = true;
                                                } else {
                                                    phi_2631_ = (_e1539 <= _e1438);
                                                }
                                                let _e1548 = phi_2631_;
                                                phi_2210_ = select(_e1438, _e1539, _e1548);
                                            }
                                            let _e1551 = phi_2210_;
                                            phi_2034_ = (_e1436 + 1u);
                                            phi_2037_ = _e1551;
                                        } else {
                                            phi_2034_ = u32();
                                            phi_2037_ = f32();
                                        }
                                        let _e1554 = phi_2034_;
                                        let _e1556 = phi_2037_;
                                        continue;
                                        continuing {
                                            phi_2033_ = _e1554;
                                            phi_2036_ = _e1556;
                                            phi_2675_ = _e899;
                                            break if !(_e1439);
                                        }
                                    }
                                    let _e1559 = phi_2675_;
                                    phi_2788_ = _e1559;
                                    if _e1559 {
                                        break;
                                    }
                                    let _e1561 = local_11;
                                    phi_2790_ = _e1559;
                                    phi_2215_ = ((_e905 - _e1318.member_1) + _e1561);
                                }
                                let _e1564 = phi_2790_;
                                let _e1566 = phi_2215_;
                                phi_2789_ = _e1564;
                                phi_1221_ = (_e901 + 1u);
                                phi_1226_ = _e1566;
                            } else {
                                phi_2789_ = _e899;
                                phi_1221_ = u32();
                                phi_1226_ = f32();
                            }
                            let _e1569 = phi_2789_;
                            let _e1571 = phi_1221_;
                            let _e1573 = phi_1226_;
                            continue;
                            continuing {
                                phi_2721_ = _e1569;
                                phi_1220_ = _e1571;
                                phi_1223_ = select(u32(), _e903, _e906);
                                phi_1225_ = _e1573;
                                phi_2788_ = _e1569;
                                break if !(_e906);
                            }
                        }
                        let _e1577 = phi_2788_;
                        if _e1577 {
                            break;
                        }
                        let _e1582 = frame.member[0u].member_1.member_10;
                        let _e1583 = (_e1582 == 1u);
                        let _e1588 = local_12;
                        let _e1590 = (_e631 + ((select(2f, 1f, _e1583) / f32(_e897)) * _e1588));
                        if _e1583 {
                            phi_2245_ = (1f - (2f * _e1590));
                        } else {
                            phi_2245_ = _e1590;
                        }
                        let _e1594 = phi_2245_;
                        let _e1604 = frame.member[0u].member_1.member.member_2;
                        let _e1607 = local_13;
                        phi_2260_ = type_43(pow(select(0f, select(1f, _e1594, (_e1594 < 1f)), (_e1594 > 0f)), _e1604), _e1607);
                    } else {
                        phi_2260_ = type_43();
                    }
                    let _e1610 = phi_2260_;
                    phi_2262_ = _e1610;
                    phi_2263_ = select(true, false, _e886);
                }
                let _e1613 = phi_2262_;
                let _e1615 = phi_2263_;
                if _e1615 {
                    phi_2267_ = type_43(_e631, 0u);
                } else {
                    phi_2267_ = _e1613;
                }
                let _e1617 = phi_2267_;
                if _e628 {
                } else {
                    break;
                }
                ao.member[_e627] = _e1617.member;
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
