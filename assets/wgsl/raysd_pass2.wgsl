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

struct type_30 {
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

struct type_31 {
    member: u32,
    member_1: type_30,
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
    var local_11: array<array<array<f32, 2>, 4>, 4>;
    var phi_792_: bool;
    var phi_794_: bool;
    var phi_795_: bool;
    var phi_796_: bool;
    var phi_797_: bool;
    var phi_2339_: bool;
    var phi_2354_: bool;
    var phi_2315_: vec2<f32>;
    var phi_2369_: bool;
    var phi_1118_: type_31;
    var phi_2611_: bool;
    var phi_1136_: u32;
    var phi_1139_: u32;
    var phi_1141_: f32;
    var phi_1189_: f32;
    var phi_1214_: f32;
    var phi_1227_: f32;
    var phi_1355_: u32;
    var phi_1386_: u32;
    var phi_2384_: bool;
    var phi_2399_: bool;
    var phi_1596_: f32;
    var phi_2414_: bool;
    var phi_1619_: f32;
    var phi_2429_: bool;
    var phi_2444_: bool;
    var phi_1813_: f32;
    var phi_2459_: bool;
    var phi_2474_: bool;
    var phi_2489_: bool;
    var phi_1827_: f32;
    var phi_1833_: type_41;
    var phi_1846_: f32;
    var phi_1979_: vec2<f32>;
    var phi_1980_: vec2<f32>;
    var phi_2011_: u32;
    var phi_2014_: f32;
    var phi_2504_: bool;
    var phi_2519_: bool;
    var phi_2179_: f32;
    var phi_2534_: bool;
    var phi_2549_: bool;
    var phi_2188_: f32;
    var phi_2012_: u32;
    var phi_2015_: f32;
    var phi_2563_: bool;
    var local_12: f32;
    var phi_2682_: bool;
    var phi_2193_: f32;
    var phi_2681_: bool;
    var phi_1137_: u32;
    var phi_1142_: f32;
    var phi_2680_: bool;
    var local_13: f32;
    var phi_2223_: f32;
    var local_14: u32;
    var phi_2238_: type_42;
    var phi_2240_: type_42;
    var phi_2241_: bool;
    var phi_2245_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e548 = id_1;
            let _e553 = arrayLength((&depth.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e575 = frame.member[0u].member_1.member.member.member_4;
            let _e576 = (_e548.x + _e575);
            let _e577 = (_e548.y + _e575);
            let _e585 = frame.member[0u].member_1.member.member.member[0u];
            let _e590 = select(select(u32(_e585), 0u, (_e585 < 0f)), 4294967295u, (_e585 > 4294967000f));
            let _e598 = frame.member[0u].member_1.member.member.member[1u];
            let _e603 = select(select(u32(_e598), 0u, (_e598 < 0f)), 4294967295u, (_e598 > 4294967000f));
            if (_e576 >= _e575) {
                if (_e577 >= _e575) {
                    let _e607 = ((_e576 + _e575) < _e590);
                    if _e607 {
                        phi_792_ = ((_e577 + _e575) < _e603);
                    } else {
                        phi_792_ = bool();
                    }
                    let _e611 = phi_792_;
                    phi_794_ = _e611;
                    phi_795_ = select(true, false, _e607);
                } else {
                    phi_794_ = bool();
                    phi_795_ = true;
                }
                let _e614 = phi_794_;
                let _e616 = phi_795_;
                phi_796_ = _e614;
                phi_797_ = _e616;
            } else {
                phi_796_ = bool();
                phi_797_ = true;
            }
            let _e618 = phi_796_;
            let _e620 = phi_797_;
            if select(_e618, false, _e620) {
                let _e623 = ((_e577 * _e590) + _e576);
                let _e624 = (_e623 < arrayLength((&ao.member)));
                if _e624 {
                } else {
                    break;
                }
                let _e627 = ao.member[_e623];
                if (_e623 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e631 = mask.member[_e623];
                if (_e631 == 0u) {
                    phi_2240_ = type_42();
                    phi_2241_ = true;
                } else {
                    let _e639 = frame.member[0u].member_1.member.member_1;
                    let _e645 = frame.member[0u].member_1.member.member_4;
                    let _e648 = ((f32(_e576) + 0.5f) / _e585);
                    let _e651 = ((f32(_e577) + 0.5f) / _e598);
                    if (_e623 < _e553) {
                    } else {
                        break;
                    }
                    let _e654 = depth.member[_e623];
                    let _e662 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e670 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e680 = ((((_e639 * _e585) / (_e654 * (2f * _e662))) + ((_e639 * _e598) / (_e654 * (2f * _e670)))) * 0.5f);
                    let _e681 = (_e680 > _e645);
                    let _e685 = select(_e680, _e645, _e681);
                    let _e692 = frame.member[0u].member_1.member.member.member_3;
                    let _e704 = ((((_e648 * 2f) - 1f) * _e654) * _e662);
                    let _e706 = ((((_e651 * -2f) + 1f) * _e654) * _e670);
                    let _e707 = -(_e654);
                    if (_e623 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e711 = normals.member[_e623];
                    let _e719 = (f32((bitcast<i32>(((_e711 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e719 != _e719) {
                        phi_2339_ = true;
                    } else {
                        phi_2339_ = (-1f >= _e719);
                    }
                    let _e723 = phi_2339_;
                    let _e724 = select(_e719, -1f, _e723);
                    let _e734 = (f32((bitcast<i32>((((_e711 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e734 != _e734) {
                        phi_2354_ = true;
                    } else {
                        phi_2354_ = (-1f >= _e734);
                    }
                    let _e738 = phi_2354_;
                    let _e739 = select(_e734, -1f, _e738);
                    let _e742 = (1f - abs(_e724));
                    let _e743 = abs(_e739);
                    let _e744 = (_e742 - _e743);
                    if (_e744 < 0f) {
                        phi_2315_ = vec2<f32>(((1f - _e743) * select(1f, -1f, (_e724 < 0f))), (_e742 * select(1f, -1f, (_e739 < 0f))));
                    } else {
                        phi_2315_ = vec2<f32>(_e724, _e739);
                    }
                    let _e755 = phi_2315_;
                    let _e764 = (1f / sqrt((((_e755.x * _e755.x) + (_e755.y * _e755.y)) + (_e744 * _e744))));
                    let _e765 = (_e755.x * _e764);
                    let _e766 = (_e755.y * _e764);
                    let _e767 = (_e744 * _e764);
                    let _e773 = ((((_e704 * _e765) + (_e706 * _e766)) + (_e707 * _e767)) > 0f);
                    let _e777 = select(_e765, -(_e765), _e773);
                    let _e778 = select(_e766, -(_e766), _e773);
                    let _e779 = select(_e767, -(_e767), _e773);
                    local_11 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                    let _e781 = (_e577 % 4u);
                    let _e782 = (_e781 < 4u);
                    if _e782 {
                    } else {
                        break;
                    }
                    let _e783 = (_e576 % 4u);
                    let _e784 = (_e783 < 4u);
                    if _e784 {
                    } else {
                        break;
                    }
                    let _e787 = local_11[_e781][_e783];
                    local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                    if _e782 {
                    } else {
                        break;
                    }
                    if _e784 {
                    } else {
                        break;
                    }
                    let _e791 = local_10[_e781][_e783];
                    let _e800 = sqrt((((_e704 * _e704) + (_e706 * _e706)) + (_e707 * _e707)));
                    let _e801 = (-(_e704) / _e800);
                    let _e802 = (-(_e706) / _e800);
                    let _e803 = (_e654 / _e800);
                    let _e806 = -((_e791[1] * _e803));
                    let _e807 = (_e803 * _e787[0]);
                    let _e810 = ((_e801 * _e791[1]) - (_e787[0] * _e802));
                    let _e817 = (1f / sqrt((((_e806 * _e806) + (_e807 * _e807)) + (_e810 * _e810))));
                    let _e818 = (_e806 * _e817);
                    let _e819 = (_e807 * _e817);
                    let _e820 = (_e810 * _e817);
                    let _e824 = ((_e819 * _e803) - (_e802 * _e820));
                    let _e827 = ((_e820 * _e801) - (_e803 * _e818));
                    let _e830 = ((_e818 * _e802) - (_e801 * _e819));
                    let _e846 = (((_e777 * _e801) + (_e778 * _e802)) + (_e779 * _e803));
                    let _e850 = abs(_e846);
                    if (_e850 != _e850) {
                        phi_2369_ = true;
                    } else {
                        phi_2369_ = (0.0001f >= _e850);
                    }
                    let _e854 = phi_2369_;
                    if select(false, !((_e685 < 0.5f)), select(false, (_e654 < _e692), (_e654 > 0f))) {
                        phi_1118_ = type_31(1u, type_30(vec2<u32>(_e576, _e577), vec2<f32>(_e648, _e651), select(_e639, ((_e639 * _e645) / _e680), _e681), _e685, vec3<f32>(_e704, _e706, _e707), vec3<f32>(_e777, _e778, _e779), vec3<f32>(_e801, _e802, _e803), vec3<f32>(_e824, _e827, _e830), vec3<f32>(_e818, _e819, _e820), vec3<f32>((((_e777 * _e824) + (_e778 * _e827)) + (_e779 * _e830)), (((_e777 * _e818) + (_e778 * _e819)) + (_e779 * _e820)), _e846), (1f / (select(1f, -1f, (_e846 < 0f)) * select(_e850, 0.0001f, _e854)))));
                    } else {
                        phi_1118_ = type_31(0u, type_31().member_1);
                    }
                    let _e866 = phi_1118_;
                    let _e869 = (bitcast<i32>(_e866.member) != 0i);
                    if _e869 {
                        let _e875 = frame.member[0u].member_1.member_11;
                        let _e880 = (8u << bitcast<u32>((select(_e875, 2u, (2u < _e875)) & 31u)));
                        phi_2611_ = false;
                        phi_1136_ = 0u;
                        phi_1139_ = 0u;
                        phi_1141_ = 0f;
                        loop {
                            let _e882 = phi_2611_;
                            let _e884 = phi_1136_;
                            let _e886 = phi_1139_;
                            let _e888 = phi_1141_;
                            local_13 = _e888;
                            local_14 = _e886;
                            let _e889 = (_e884 < _e880);
                            if _e889 {
                                if ((_e631 & (1u << bitcast<u32>((_e884 & 31u)))) == 0u) {
                                    phi_2682_ = _e882;
                                    phi_2193_ = _e888;
                                } else {
                                    let _e899 = frame.member[0u].member_1.member_10;
                                    let _e901 = ((_e880 + _e884) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e902 = (_e901 < 56u);
                                    if _e902 {
                                    } else {
                                        phi_2680_ = true;
                                        break;
                                    }
                                    let _e904 = local_4[_e901];
                                    let _e907 = (_e899 == 1u);
                                    if _e907 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e902 {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e909 = local_5[_e901];
                                        phi_1189_ = _e909;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e902 {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e911 = local_6[_e901];
                                        phi_1189_ = _e911;
                                    }
                                    let _e913 = phi_1189_;
                                    let _e915 = (_e866.member_1.member_2 * _e913);
                                    let _e916 = (_e915 * _e904[0]);
                                    let _e917 = (_e915 * _e904[1]);
                                    if _e907 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e902 {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e919 = local_7[_e901];
                                        phi_1214_ = _e919;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e902 {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e921 = local_8[_e901];
                                        phi_1214_ = _e921;
                                    }
                                    let _e923 = phi_1214_;
                                    let _e924 = (_e866.member_1.member_2 * _e923);
                                    if _e907 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e902 {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e926 = local_9[_e901];
                                        phi_1227_ = _e926;
                                    } else {
                                        phi_1227_ = (_e924 * 2f);
                                    }
                                    let _e929 = phi_1227_;
                                    let _e938 = (-(((_e916 * _e866.member_1.member_9.x) + (_e917 * _e866.member_1.member_9.y))) * _e866.member_1.member_10);
                                    let _e939 = -(_e924);
                                    let _e943 = select(_e939, select(_e924, _e938, (_e938 < _e924)), (_e938 > _e939));
                                    let _e968 = (-0.5f / ((_e866.member_1.member_4.z + (_e866.member_1.member_7.z * _e916)) + (_e866.member_1.member_8.z * _e917)));
                                    let _e971 = (((((_e866.member_1.member_4.x + (_e866.member_1.member_7.x * _e916)) + (_e866.member_1.member_8.x * _e917)) * _e968) / _e662) + 0.5f);
                                    let _e974 = (0.5f - ((((_e866.member_1.member_4.y + (_e866.member_1.member_7.y * _e916)) + (_e866.member_1.member_8.y * _e917)) * _e968) / _e670));
                                    let _e986 = (select(0f, select(1f, _e971, (_e971 < 1f)), (_e971 > 0f)) * _e585);
                                    if (_e986 > 0f) {
                                        let _e992 = select(select(u32(_e986), 0u, (_e986 < 0f)), 4294967295u, (_e986 > 4294967000f));
                                        let _e993 = (_e590 - 1u);
                                        phi_1355_ = select(_e992, _e993, (_e993 < _e992));
                                    } else {
                                        phi_1355_ = 0u;
                                    }
                                    let _e997 = phi_1355_;
                                    let _e1002 = (select(0f, select(1f, _e974, (_e974 < 1f)), (_e974 > 0f)) * _e598);
                                    if (_e1002 > 0f) {
                                        let _e1008 = select(select(u32(_e1002), 0u, (_e1002 < 0f)), 4294967295u, (_e1002 > 4294967000f));
                                        let _e1009 = (_e603 - 1u);
                                        phi_1386_ = select(_e1008, _e1009, (_e1009 < _e1008));
                                    } else {
                                        phi_1386_ = 0u;
                                    }
                                    let _e1013 = phi_1386_;
                                    let _e1020 = ((_e866.member_1.member_1.x - _e971) * _e585);
                                    let _e1021 = ((_e866.member_1.member_1.y - _e974) * _e598);
                                    let _e1027 = ((_e1013 * _e590) + _e997);
                                    if (_e1027 < _e553) {
                                    } else {
                                        phi_2680_ = true;
                                        break;
                                    }
                                    let _e1030 = depth.member[_e1027];
                                    let _e1042 = select(_e692, _e1030, select(false, (_e1030 < _e692), (_e1030 > 0f)));
                                    let _e1044 = ((((f32(_e997) + 0.5f) * (1f / _e585)) * 2f) - 1f);
                                    let _e1046 = ((((f32(_e1013) + 0.5f) * (1f / _e598)) * -2f) + 1f);
                                    let _e1052 = (((_e1044 * _e1042) * _e662) - _e866.member_1.member_4.x);
                                    let _e1053 = (((_e1046 * _e1042) * _e670) - _e866.member_1.member_4.y);
                                    let _e1054 = (-(_e1042) - _e866.member_1.member_4.z);
                                    let _e1063 = (((_e1052 * _e866.member_1.member_6.x) + (_e1053 * _e866.member_1.member_6.y)) + (_e1054 * _e866.member_1.member_6.z));
                                    if _e907 {
                                        let _e1068 = (((_e1052 * _e1052) + (_e1053 * _e1053)) + (_e1054 * _e1054));
                                        let _e1080 = (((((_e866.member_1.member_5.x * _e1052) + (_e866.member_1.member_5.y * _e1053)) + (_e866.member_1.member_5.z * _e1054)) / sqrt(_e1068)) - 0.1f);
                                        let _e1087 = (1f - (_e1068 / (_e639 * _e639)));
                                        let _e1094 = ((select(0f, select(1f, _e1080, (_e1080 < 1f)), (_e1080 > 0f)) * select(0f, select(1f, _e1087, (_e1087 < 1f)), (_e1087 > 0f))) / _e929);
                                        phi_1596_ = select(0f, select(0f, select(1f, _e1094, (_e1094 < 1f)), (_e1094 > 0f)), (_e1068 > 0f));
                                    } else {
                                        let _e1105 = frame.member[0u].member_1.member.member_3;
                                        if (_e943 != _e943) {
                                            phi_2384_ = true;
                                        } else {
                                            phi_2384_ = (_e1063 >= _e943);
                                        }
                                        let _e1110 = phi_2384_;
                                        let _e1112 = (_e924 - select(_e943, _e1063, _e1110));
                                        if (_e1112 != _e1112) {
                                            phi_2399_ = true;
                                        } else {
                                            phi_2399_ = (0f >= _e1112);
                                        }
                                        let _e1116 = phi_2399_;
                                        let _e1121 = ((_e1063 - (_e866.member_1.member_2 * (1f + _e1105))) * (1f / _e924));
                                        phi_1596_ = ((select(_e1112, 0f, _e1116) + (select(0f, select(1f, _e1121, (_e1121 < 1f)), (_e1121 > 0f)) * (_e924 - _e943))) * (0.5f / _e924));
                                    }
                                    let _e1132 = phi_1596_;
                                    let _e1137 = frame.member[0u].member_1.member_9;
                                    if (_e1137 == 0u) {
                                        phi_1833_ = type_41(_e1063, _e1132);
                                    } else {
                                        if _e907 {
                                            let _e1140 = (_e866.member_1.member_2 * 0.1f);
                                            if (_e924 != _e924) {
                                                phi_2414_ = true;
                                            } else {
                                                phi_2414_ = (_e1140 >= _e924);
                                            }
                                            let _e1144 = phi_2414_;
                                            phi_1619_ = select(_e924, _e1140, _e1144);
                                        } else {
                                            let _e1151 = frame.member[0u].member_1.member.member_3;
                                            phi_1619_ = (_e866.member_1.member_2 * (1f + _e1151));
                                        }
                                        let _e1155 = phi_1619_;
                                        let _e1161 = frame.member[0u].member_1.member_3;
                                        let _e1163 = select(false, (sqrt(((_e1020 * _e1020) + (_e1021 * _e1021))) > _e1161), (_e1063 > _e1155));
                                        if (_e1027 < arrayLength((&depth2_.member))) {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e1167 = depth2_.member[_e1027];
                                        let _e1171 = select(_e692, _e1167, select(false, (_e1167 < _e692), (_e1167 > 0f)));
                                        let _e1177 = (((_e1044 * _e1171) * _e662) - _e866.member_1.member_4.x);
                                        let _e1178 = (((_e1046 * _e1171) * _e670) - _e866.member_1.member_4.y);
                                        let _e1179 = (-(_e1171) - _e866.member_1.member_4.z);
                                        let _e1184 = (((_e1177 * _e866.member_1.member_6.x) + (_e1178 * _e866.member_1.member_6.y)) + (_e1179 * _e866.member_1.member_6.z));
                                        if _e907 {
                                            let _e1189 = (((_e1177 * _e1177) + (_e1178 * _e1178)) + (_e1179 * _e1179));
                                            let _e1201 = (((((_e866.member_1.member_5.x * _e1177) + (_e866.member_1.member_5.y * _e1178)) + (_e866.member_1.member_5.z * _e1179)) / sqrt(_e1189)) - 0.1f);
                                            let _e1208 = (1f - (_e1189 / (_e639 * _e639)));
                                            let _e1215 = ((select(0f, select(1f, _e1201, (_e1201 < 1f)), (_e1201 > 0f)) * select(0f, select(1f, _e1208, (_e1208 < 1f)), (_e1208 > 0f))) / _e929);
                                            phi_1813_ = select(0f, select(0f, select(1f, _e1215, (_e1215 < 1f)), (_e1215 > 0f)), (_e1189 > 0f));
                                        } else {
                                            let _e1226 = frame.member[0u].member_1.member.member_3;
                                            if (_e943 != _e943) {
                                                phi_2429_ = true;
                                            } else {
                                                phi_2429_ = (_e1184 >= _e943);
                                            }
                                            let _e1231 = phi_2429_;
                                            let _e1233 = (_e924 - select(_e943, _e1184, _e1231));
                                            if (_e1233 != _e1233) {
                                                phi_2444_ = true;
                                            } else {
                                                phi_2444_ = (0f >= _e1233);
                                            }
                                            let _e1237 = phi_2444_;
                                            let _e1242 = ((_e1184 - (_e866.member_1.member_2 * (1f + _e1226))) * (1f / _e924));
                                            phi_1813_ = ((select(_e1233, 0f, _e1237) + (select(0f, select(1f, _e1242, (_e1242 < 1f)), (_e1242 > 0f)) * (_e924 - _e943))) * (0.5f / _e924));
                                        }
                                        let _e1253 = phi_1813_;
                                        if (_e1063 != _e1063) {
                                            phi_2459_ = true;
                                        } else {
                                            phi_2459_ = (_e1184 <= _e1063);
                                        }
                                        let _e1257 = phi_2459_;
                                        if _e907 {
                                            if (_e1132 != _e1132) {
                                                phi_2474_ = true;
                                            } else {
                                                phi_2474_ = (_e1253 >= _e1132);
                                            }
                                            let _e1263 = phi_2474_;
                                            phi_1827_ = select(_e1132, _e1253, _e1263);
                                        } else {
                                            if (_e1132 != _e1132) {
                                                phi_2489_ = true;
                                            } else {
                                                phi_2489_ = (_e1253 <= _e1132);
                                            }
                                            let _e1268 = phi_2489_;
                                            phi_1827_ = select(_e1132, _e1253, _e1268);
                                        }
                                        let _e1271 = phi_1827_;
                                        phi_1833_ = type_41(select(_e1063, select(_e1063, _e1184, _e1257), _e1163), select(_e1132, _e1271, _e1163));
                                    }
                                    let _e1275 = phi_1833_;
                                    if select(false, select(false, (_e974 <= 1f), (_e974 >= 0f)), select(false, (_e971 <= 1f), (_e971 >= 0f))) {
                                        phi_1846_ = _e1275.member_1;
                                    } else {
                                        phi_1846_ = select(1f, 0f, _e907);
                                    }
                                    let _e1280 = phi_1846_;
                                    let _e1286 = frame.member[0u].member_1.member_5[0u];
                                    let _e1292 = frame.member[0u].member_1.member_5[1u];
                                    let _e1293 = f32(_e1286);
                                    let _e1294 = f32(_e1292);
                                    let _e1299 = frame.member[0u].member_1.member_4;
                                    let _e1300 = f32(_e1299);
                                    let _e1301 = (2u * _e1299);
                                    let _e1302 = (_e1286 + _e1301);
                                    let _e1308 = (floor((_e971 * _e1293)) + _e1300);
                                    let _e1309 = f32((_e1302 - 1u));
                                    let _e1313 = select(0f, select(_e1309, _e1308, (_e1308 < _e1309)), (_e1308 > 0f));
                                    let _e1316 = (floor((_e974 * _e1294)) + _e1300);
                                    let _e1317 = f32(((_e1292 + _e1301) - 1u));
                                    let _e1321 = select(0f, select(_e1317, _e1316, (_e1316 < _e1317)), (_e1316 > 0f));
                                    let _e1326 = select(select(u32(_e1313), 0u, (_e1313 < 0f)), 4294967295u, (_e1313 > 4294967000f));
                                    let _e1331 = select(select(u32(_e1321), 0u, (_e1321 < 0f)), 4294967295u, (_e1321 > 4294967000f));
                                    let _e1334 = bitcast<i32>(_e1299);
                                    let _e1343 = frame.member[0u].member_1.member_8;
                                    let _e1348 = frame.member[0u].member_1.member_12;
                                    let _e1355 = (((((_e1331 % 4u) * 4u) + (_e1326 % 4u)) + (_e1348 % 16u)) % 16u);
                                    if (_e1343 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1357 = (_e1355 < 16u);
                                        if _e1357 {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e1360 = local[_e1355][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1357 {
                                        } else {
                                            phi_2680_ = true;
                                            break;
                                        }
                                        let _e1363 = local_1[_e1355][1u];
                                        phi_1980_ = vec2<f32>(_e1360, _e1363);
                                    } else {
                                        if (_e1343 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1366 = (_e1355 < 16u);
                                            if _e1366 {
                                            } else {
                                                phi_2680_ = true;
                                                break;
                                            }
                                            let _e1369 = local_2[_e1355][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1366 {
                                            } else {
                                                phi_2680_ = true;
                                                break;
                                            }
                                            let _e1372 = local_3[_e1355][1u];
                                            phi_1979_ = vec2<f32>(_e1369, _e1372);
                                        } else {
                                            phi_1979_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1375 = phi_1979_;
                                        phi_1980_ = _e1375;
                                    }
                                    let _e1377 = phi_1980_;
                                    let _e1390 = frame.member[0u].member_1.member_6;
                                    phi_2011_ = 0u;
                                    phi_2014_ = _e1280;
                                    loop {
                                        let _e1393 = phi_2011_;
                                        let _e1395 = phi_2014_;
                                        local_12 = _e1395;
                                        let _e1396 = (_e1393 < _e1390);
                                        if _e1396 {
                                            let _e1397 = ((((_e1331 * _e1302) + _e1326) * _e1390) + _e1393);
                                            if (_e1397 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2563_ = true;
                                                break;
                                            }
                                            let _e1400 = sd_map.member[_e1397];
                                            let _e1407 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1410 = ((_e1400 * (_e692 - _e1407)) + _e1407);
                                            let _e1420 = (((((((f32((bitcast<i32>(_e1326) - _e1334)) + _e1377.x) / _e1293) * 2f) - 1f) * _e1410) * _e662) - _e866.member_1.member_4.x);
                                            let _e1421 = (((((((f32((bitcast<i32>(_e1331) - _e1334)) + _e1377.y) / _e1294) * -2f) + 1f) * _e1410) * _e670) - _e866.member_1.member_4.y);
                                            let _e1422 = (-(_e1410) - _e866.member_1.member_4.z);
                                            let _e1427 = (((_e1420 * _e866.member_1.member_6.x) + (_e1421 * _e866.member_1.member_6.y)) + (_e1422 * _e866.member_1.member_6.z));
                                            if _e907 {
                                                let _e1432 = (((_e1420 * _e1420) + (_e1421 * _e1421)) + (_e1422 * _e1422));
                                                let _e1444 = (((((_e866.member_1.member_5.x * _e1420) + (_e866.member_1.member_5.y * _e1421)) + (_e866.member_1.member_5.z * _e1422)) / sqrt(_e1432)) - 0.1f);
                                                let _e1451 = (1f - (_e1432 / (_e639 * _e639)));
                                                let _e1458 = ((select(0f, select(1f, _e1444, (_e1444 < 1f)), (_e1444 > 0f)) * select(0f, select(1f, _e1451, (_e1451 < 1f)), (_e1451 > 0f))) / _e929);
                                                phi_2179_ = select(0f, select(0f, select(1f, _e1458, (_e1458 < 1f)), (_e1458 > 0f)), (_e1432 > 0f));
                                            } else {
                                                let _e1469 = frame.member[0u].member_1.member.member_3;
                                                if (_e943 != _e943) {
                                                    phi_2504_ = true;
                                                } else {
                                                    phi_2504_ = (_e1427 >= _e943);
                                                }
                                                let _e1474 = phi_2504_;
                                                let _e1476 = (_e924 - select(_e943, _e1427, _e1474));
                                                if (_e1476 != _e1476) {
                                                    phi_2519_ = true;
                                                } else {
                                                    phi_2519_ = (0f >= _e1476);
                                                }
                                                let _e1480 = phi_2519_;
                                                let _e1485 = ((_e1427 - (_e866.member_1.member_2 * (1f + _e1469))) * (1f / _e924));
                                                phi_2179_ = ((select(_e1476, 0f, _e1480) + (select(0f, select(1f, _e1485, (_e1485 < 1f)), (_e1485 > 0f)) * (_e924 - _e943))) * (0.5f / _e924));
                                            }
                                            let _e1496 = phi_2179_;
                                            if _e907 {
                                                if (_e1395 != _e1395) {
                                                    phi_2534_ = true;
                                                } else {
                                                    phi_2534_ = (_e1496 >= _e1395);
                                                }
                                                let _e1500 = phi_2534_;
                                                phi_2188_ = select(_e1395, _e1496, _e1500);
                                            } else {
                                                if (_e1395 != _e1395) {
                                                    phi_2549_ = true;
                                                } else {
                                                    phi_2549_ = (_e1496 <= _e1395);
                                                }
                                                let _e1505 = phi_2549_;
                                                phi_2188_ = select(_e1395, _e1496, _e1505);
                                            }
                                            let _e1508 = phi_2188_;
                                            phi_2012_ = (_e1393 + 1u);
                                            phi_2015_ = _e1508;
                                        } else {
                                            phi_2012_ = u32();
                                            phi_2015_ = f32();
                                        }
                                        let _e1511 = phi_2012_;
                                        let _e1513 = phi_2015_;
                                        continue;
                                        continuing {
                                            phi_2011_ = _e1511;
                                            phi_2014_ = _e1513;
                                            phi_2563_ = _e882;
                                            break if !(_e1396);
                                        }
                                    }
                                    let _e1516 = phi_2563_;
                                    phi_2680_ = _e1516;
                                    if _e1516 {
                                        break;
                                    }
                                    let _e1518 = local_12;
                                    phi_2682_ = _e1516;
                                    phi_2193_ = ((_e888 - _e1275.member_1) + _e1518);
                                }
                                let _e1521 = phi_2682_;
                                let _e1523 = phi_2193_;
                                phi_2681_ = _e1521;
                                phi_1137_ = (_e884 + 1u);
                                phi_1142_ = _e1523;
                            } else {
                                phi_2681_ = _e882;
                                phi_1137_ = u32();
                                phi_1142_ = f32();
                            }
                            let _e1526 = phi_2681_;
                            let _e1528 = phi_1137_;
                            let _e1530 = phi_1142_;
                            continue;
                            continuing {
                                phi_2611_ = _e1526;
                                phi_1136_ = _e1528;
                                phi_1139_ = select(u32(), _e886, _e889);
                                phi_1141_ = _e1530;
                                phi_2680_ = _e1526;
                                break if !(_e889);
                            }
                        }
                        let _e1534 = phi_2680_;
                        if _e1534 {
                            break;
                        }
                        let _e1539 = frame.member[0u].member_1.member_10;
                        let _e1540 = (_e1539 == 1u);
                        let _e1545 = local_13;
                        let _e1547 = (_e627 + ((select(2f, 1f, _e1540) / f32(_e880)) * _e1545));
                        if _e1540 {
                            phi_2223_ = (1f - (2f * _e1547));
                        } else {
                            phi_2223_ = _e1547;
                        }
                        let _e1551 = phi_2223_;
                        let _e1561 = frame.member[0u].member_1.member.member_2;
                        let _e1564 = local_14;
                        phi_2238_ = type_42(pow(select(0f, select(1f, _e1551, (_e1551 < 1f)), (_e1551 > 0f)), _e1561), _e1564);
                    } else {
                        phi_2238_ = type_42();
                    }
                    let _e1567 = phi_2238_;
                    phi_2240_ = _e1567;
                    phi_2241_ = select(true, false, _e869);
                }
                let _e1570 = phi_2240_;
                let _e1572 = phi_2241_;
                if _e1572 {
                    phi_2245_ = type_42(_e627, 0u);
                } else {
                    phi_2245_ = _e1570;
                }
                let _e1574 = phi_2245_;
                if _e624 {
                } else {
                    break;
                }
                ao.member[_e623] = _e1574.member;
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
