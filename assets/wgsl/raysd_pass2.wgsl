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
    var phi_790_: bool;
    var phi_792_: bool;
    var phi_793_: bool;
    var phi_794_: bool;
    var phi_795_: bool;
    var phi_2296_: bool;
    var phi_2311_: bool;
    var phi_2272_: vec2<f32>;
    var phi_2326_: bool;
    var phi_1086_: type_31;
    var phi_2568_: bool;
    var phi_1104_: u32;
    var phi_1107_: u32;
    var phi_1109_: f32;
    var phi_1157_: f32;
    var phi_1182_: f32;
    var phi_1195_: f32;
    var phi_1323_: u32;
    var phi_1354_: u32;
    var phi_2341_: bool;
    var phi_2356_: bool;
    var phi_1558_: f32;
    var phi_2371_: bool;
    var phi_1581_: f32;
    var phi_2386_: bool;
    var phi_2401_: bool;
    var phi_1770_: f32;
    var phi_2416_: bool;
    var phi_2431_: bool;
    var phi_2446_: bool;
    var phi_1784_: f32;
    var phi_1790_: type_41;
    var phi_1803_: f32;
    var phi_1936_: vec2<f32>;
    var phi_1937_: vec2<f32>;
    var phi_1968_: u32;
    var phi_1971_: f32;
    var phi_2461_: bool;
    var phi_2476_: bool;
    var phi_2136_: f32;
    var phi_2491_: bool;
    var phi_2506_: bool;
    var phi_2145_: f32;
    var phi_1969_: u32;
    var phi_1972_: f32;
    var phi_2520_: bool;
    var local_11: f32;
    var phi_2639_: bool;
    var phi_2150_: f32;
    var phi_2638_: bool;
    var phi_1105_: u32;
    var phi_1110_: f32;
    var phi_2637_: bool;
    var local_12: f32;
    var phi_2180_: f32;
    var local_13: u32;
    var phi_2195_: type_42;
    var phi_2197_: type_42;
    var phi_2198_: bool;
    var phi_2202_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e547 = id_1;
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e568 = frame.member[0u].member_1.member.member.member_4;
            let _e569 = (_e547.x + _e568);
            let _e570 = (_e547.y + _e568);
            let _e578 = frame.member[0u].member_1.member.member.member[0u];
            let _e583 = select(select(u32(_e578), 0u, (_e578 < 0f)), 4294967295u, (_e578 > 4294967000f));
            let _e591 = frame.member[0u].member_1.member.member.member[1u];
            let _e596 = select(select(u32(_e591), 0u, (_e591 < 0f)), 4294967295u, (_e591 > 4294967000f));
            if (_e569 >= _e568) {
                if (_e570 >= _e568) {
                    let _e600 = ((_e569 + _e568) < _e583);
                    if _e600 {
                        phi_790_ = ((_e570 + _e568) < _e596);
                    } else {
                        phi_790_ = bool();
                    }
                    let _e604 = phi_790_;
                    phi_792_ = _e604;
                    phi_793_ = select(true, false, _e600);
                } else {
                    phi_792_ = bool();
                    phi_793_ = true;
                }
                let _e607 = phi_792_;
                let _e609 = phi_793_;
                phi_794_ = _e607;
                phi_795_ = _e609;
            } else {
                phi_794_ = bool();
                phi_795_ = true;
            }
            let _e611 = phi_794_;
            let _e613 = phi_795_;
            if select(_e611, false, _e613) {
                let _e616 = ((_e570 * _e583) + _e569);
                let _e617 = (_e616 < arrayLength((&ao.member)));
                if _e617 {
                } else {
                    break;
                }
                let _e620 = ao.member[_e616];
                if (_e616 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e624 = mask.member[_e616];
                if (_e624 == 0u) {
                    phi_2197_ = type_42();
                    phi_2198_ = true;
                } else {
                    let _e632 = frame.member[0u].member_1.member.member_1;
                    let _e638 = frame.member[0u].member_1.member.member_4;
                    let _e641 = ((f32(_e569) + 0.5f) / _e578);
                    let _e644 = ((f32(_e570) + 0.5f) / _e591);
                    let _e646 = depth.member[_e616];
                    let _e654 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e662 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e672 = ((((_e632 * _e578) / (_e646 * (2f * _e654))) + ((_e632 * _e591) / (_e646 * (2f * _e662)))) * 0.5f);
                    let _e673 = (_e672 > _e638);
                    let _e677 = select(_e672, _e638, _e673);
                    let _e684 = frame.member[0u].member_1.member.member.member_3;
                    let _e696 = ((((_e641 * 2f) - 1f) * _e646) * _e654);
                    let _e698 = ((((_e644 * -2f) + 1f) * _e646) * _e662);
                    let _e699 = -(_e646);
                    let _e702 = normals.member[_e616];
                    let _e710 = (f32((bitcast<i32>(((_e702 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e710 != _e710) {
                        phi_2296_ = true;
                    } else {
                        phi_2296_ = (-1f >= _e710);
                    }
                    let _e714 = phi_2296_;
                    let _e715 = select(_e710, -1f, _e714);
                    let _e725 = (f32((bitcast<i32>((((_e702 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e725 != _e725) {
                        phi_2311_ = true;
                    } else {
                        phi_2311_ = (-1f >= _e725);
                    }
                    let _e729 = phi_2311_;
                    let _e730 = select(_e725, -1f, _e729);
                    let _e733 = (1f - abs(_e715));
                    let _e734 = abs(_e730);
                    let _e735 = (_e733 - _e734);
                    if (_e735 < 0f) {
                        phi_2272_ = vec2<f32>(((1f - _e734) * select(1f, -1f, (_e715 < 0f))), (_e733 * select(1f, -1f, (_e730 < 0f))));
                    } else {
                        phi_2272_ = vec2<f32>(_e715, _e730);
                    }
                    let _e746 = phi_2272_;
                    let _e755 = (1f / sqrt((((_e746.x * _e746.x) + (_e746.y * _e746.y)) + (_e735 * _e735))));
                    let _e756 = (_e746.x * _e755);
                    let _e757 = (_e746.y * _e755);
                    let _e758 = (_e735 * _e755);
                    let _e764 = ((((_e696 * _e756) + (_e698 * _e757)) + (_e699 * _e758)) > 0f);
                    let _e768 = select(_e756, -(_e756), _e764);
                    let _e769 = select(_e757, -(_e757), _e764);
                    let _e770 = select(_e758, -(_e758), _e764);
                    local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                    let _e772 = (_e570 % 4u);
                    if (_e772 < 4u) {
                    } else {
                        break;
                    }
                    let _e774 = (_e569 % 4u);
                    if (_e774 < 4u) {
                    } else {
                        break;
                    }
                    let _e778 = local_10[_e772][_e774];
                    let _e788 = sqrt((((_e696 * _e696) + (_e698 * _e698)) + (_e699 * _e699)));
                    let _e789 = (-(_e696) / _e788);
                    let _e790 = (-(_e698) / _e788);
                    let _e791 = (_e646 / _e788);
                    let _e794 = -((_e778[1] * _e791));
                    let _e795 = (_e791 * _e778[0]);
                    let _e798 = ((_e789 * _e778[1]) - (_e778[0] * _e790));
                    let _e805 = (1f / sqrt((((_e794 * _e794) + (_e795 * _e795)) + (_e798 * _e798))));
                    let _e806 = (_e794 * _e805);
                    let _e807 = (_e795 * _e805);
                    let _e808 = (_e798 * _e805);
                    let _e812 = ((_e807 * _e791) - (_e790 * _e808));
                    let _e815 = ((_e808 * _e789) - (_e791 * _e806));
                    let _e818 = ((_e806 * _e790) - (_e789 * _e807));
                    let _e834 = (((_e768 * _e789) + (_e769 * _e790)) + (_e770 * _e791));
                    let _e838 = abs(_e834);
                    if (_e838 != _e838) {
                        phi_2326_ = true;
                    } else {
                        phi_2326_ = (0.0001f >= _e838);
                    }
                    let _e842 = phi_2326_;
                    if select(false, !((_e677 < 0.5f)), select(false, (_e646 < _e684), (_e646 > 0f))) {
                        phi_1086_ = type_31(1u, type_30(vec2<u32>(_e569, _e570), vec2<f32>(_e641, _e644), select(_e632, ((_e632 * _e638) / _e672), _e673), _e677, vec3<f32>(_e696, _e698, _e699), vec3<f32>(_e768, _e769, _e770), vec3<f32>(_e789, _e790, _e791), vec3<f32>(_e812, _e815, _e818), vec3<f32>(_e806, _e807, _e808), vec3<f32>((((_e768 * _e812) + (_e769 * _e815)) + (_e770 * _e818)), (((_e768 * _e806) + (_e769 * _e807)) + (_e770 * _e808)), _e834), (1f / (select(1f, -1f, (_e834 < 0f)) * select(_e838, 0.0001f, _e842)))));
                    } else {
                        phi_1086_ = type_31(0u, type_31().member_1);
                    }
                    let _e854 = phi_1086_;
                    let _e857 = (bitcast<i32>(_e854.member) != 0i);
                    if _e857 {
                        let _e863 = frame.member[0u].member_1.member_11;
                        let _e868 = (8u << bitcast<u32>((select(_e863, 2u, (2u < _e863)) & 31u)));
                        phi_2568_ = false;
                        phi_1104_ = 0u;
                        phi_1107_ = 0u;
                        phi_1109_ = 0f;
                        loop {
                            let _e870 = phi_2568_;
                            let _e872 = phi_1104_;
                            let _e874 = phi_1107_;
                            let _e876 = phi_1109_;
                            local_12 = _e876;
                            local_13 = _e874;
                            let _e877 = (_e872 < _e868);
                            if _e877 {
                                if ((_e624 & (1u << bitcast<u32>((_e872 & 31u)))) == 0u) {
                                    phi_2639_ = _e870;
                                    phi_2150_ = _e876;
                                } else {
                                    let _e887 = frame.member[0u].member_1.member_10;
                                    let _e889 = ((_e868 + _e872) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e890 = (_e889 < 56u);
                                    if _e890 {
                                    } else {
                                        phi_2637_ = true;
                                        break;
                                    }
                                    let _e892 = local_4[_e889];
                                    let _e895 = (_e887 == 1u);
                                    if _e895 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e890 {
                                        } else {
                                            phi_2637_ = true;
                                            break;
                                        }
                                        let _e897 = local_5[_e889];
                                        phi_1157_ = _e897;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e890 {
                                        } else {
                                            phi_2637_ = true;
                                            break;
                                        }
                                        let _e899 = local_6[_e889];
                                        phi_1157_ = _e899;
                                    }
                                    let _e901 = phi_1157_;
                                    let _e903 = (_e854.member_1.member_2 * _e901);
                                    let _e904 = (_e903 * _e892[0]);
                                    let _e905 = (_e903 * _e892[1]);
                                    if _e895 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e890 {
                                        } else {
                                            phi_2637_ = true;
                                            break;
                                        }
                                        let _e907 = local_7[_e889];
                                        phi_1182_ = _e907;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e890 {
                                        } else {
                                            phi_2637_ = true;
                                            break;
                                        }
                                        let _e909 = local_8[_e889];
                                        phi_1182_ = _e909;
                                    }
                                    let _e911 = phi_1182_;
                                    let _e912 = (_e854.member_1.member_2 * _e911);
                                    if _e895 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e890 {
                                        } else {
                                            phi_2637_ = true;
                                            break;
                                        }
                                        let _e914 = local_9[_e889];
                                        phi_1195_ = _e914;
                                    } else {
                                        phi_1195_ = (_e912 * 2f);
                                    }
                                    let _e917 = phi_1195_;
                                    let _e926 = (-(((_e904 * _e854.member_1.member_9.x) + (_e905 * _e854.member_1.member_9.y))) * _e854.member_1.member_10);
                                    let _e927 = -(_e912);
                                    let _e931 = select(_e927, select(_e912, _e926, (_e926 < _e912)), (_e926 > _e927));
                                    let _e956 = (-0.5f / ((_e854.member_1.member_4.z + (_e854.member_1.member_7.z * _e904)) + (_e854.member_1.member_8.z * _e905)));
                                    let _e959 = (((((_e854.member_1.member_4.x + (_e854.member_1.member_7.x * _e904)) + (_e854.member_1.member_8.x * _e905)) * _e956) / _e654) + 0.5f);
                                    let _e962 = (0.5f - ((((_e854.member_1.member_4.y + (_e854.member_1.member_7.y * _e904)) + (_e854.member_1.member_8.y * _e905)) * _e956) / _e662));
                                    let _e974 = (select(0f, select(1f, _e959, (_e959 < 1f)), (_e959 > 0f)) * _e578);
                                    if (_e974 > 0f) {
                                        let _e980 = select(select(u32(_e974), 0u, (_e974 < 0f)), 4294967295u, (_e974 > 4294967000f));
                                        let _e981 = (_e583 - 1u);
                                        phi_1323_ = select(_e980, _e981, (_e981 < _e980));
                                    } else {
                                        phi_1323_ = 0u;
                                    }
                                    let _e985 = phi_1323_;
                                    let _e990 = (select(0f, select(1f, _e962, (_e962 < 1f)), (_e962 > 0f)) * _e591);
                                    if (_e990 > 0f) {
                                        let _e996 = select(select(u32(_e990), 0u, (_e990 < 0f)), 4294967295u, (_e990 > 4294967000f));
                                        let _e997 = (_e596 - 1u);
                                        phi_1354_ = select(_e996, _e997, (_e997 < _e996));
                                    } else {
                                        phi_1354_ = 0u;
                                    }
                                    let _e1001 = phi_1354_;
                                    let _e1008 = ((_e854.member_1.member_1.x - _e959) * _e578);
                                    let _e1009 = ((_e854.member_1.member_1.y - _e962) * _e591);
                                    let _e1015 = ((_e1001 * _e583) + _e985);
                                    let _e1017 = depth.member[_e1015];
                                    let _e1029 = select(_e684, _e1017, select(false, (_e1017 < _e684), (_e1017 > 0f)));
                                    let _e1031 = ((((f32(_e985) + 0.5f) * (1f / _e578)) * 2f) - 1f);
                                    let _e1033 = ((((f32(_e1001) + 0.5f) * (1f / _e591)) * -2f) + 1f);
                                    let _e1039 = (((_e1031 * _e1029) * _e654) - _e854.member_1.member_4.x);
                                    let _e1040 = (((_e1033 * _e1029) * _e662) - _e854.member_1.member_4.y);
                                    let _e1041 = (-(_e1029) - _e854.member_1.member_4.z);
                                    let _e1050 = (((_e1039 * _e854.member_1.member_6.x) + (_e1040 * _e854.member_1.member_6.y)) + (_e1041 * _e854.member_1.member_6.z));
                                    if _e895 {
                                        let _e1055 = (((_e1039 * _e1039) + (_e1040 * _e1040)) + (_e1041 * _e1041));
                                        let _e1067 = (((((_e854.member_1.member_5.x * _e1039) + (_e854.member_1.member_5.y * _e1040)) + (_e854.member_1.member_5.z * _e1041)) / sqrt(_e1055)) - 0.1f);
                                        let _e1074 = (1f - (_e1055 / (_e632 * _e632)));
                                        let _e1081 = ((select(0f, select(1f, _e1067, (_e1067 < 1f)), (_e1067 > 0f)) * select(0f, select(1f, _e1074, (_e1074 < 1f)), (_e1074 > 0f))) / _e917);
                                        phi_1558_ = select(0f, select(0f, select(1f, _e1081, (_e1081 < 1f)), (_e1081 > 0f)), (_e1055 > 0f));
                                    } else {
                                        let _e1092 = frame.member[0u].member_1.member.member_3;
                                        if (_e931 != _e931) {
                                            phi_2341_ = true;
                                        } else {
                                            phi_2341_ = (_e1050 >= _e931);
                                        }
                                        let _e1097 = phi_2341_;
                                        let _e1099 = (_e912 - select(_e931, _e1050, _e1097));
                                        if (_e1099 != _e1099) {
                                            phi_2356_ = true;
                                        } else {
                                            phi_2356_ = (0f >= _e1099);
                                        }
                                        let _e1103 = phi_2356_;
                                        let _e1108 = ((_e1050 - (_e854.member_1.member_2 * (1f + _e1092))) * (1f / _e912));
                                        phi_1558_ = ((select(_e1099, 0f, _e1103) + (select(0f, select(1f, _e1108, (_e1108 < 1f)), (_e1108 > 0f)) * (_e912 - _e931))) * (0.5f / _e912));
                                    }
                                    let _e1119 = phi_1558_;
                                    let _e1124 = frame.member[0u].member_1.member_9;
                                    if (_e1124 == 0u) {
                                        phi_1790_ = type_41(_e1050, _e1119);
                                    } else {
                                        if _e895 {
                                            let _e1127 = (_e854.member_1.member_2 * 0.1f);
                                            if (_e912 != _e912) {
                                                phi_2371_ = true;
                                            } else {
                                                phi_2371_ = (_e1127 >= _e912);
                                            }
                                            let _e1131 = phi_2371_;
                                            phi_1581_ = select(_e912, _e1127, _e1131);
                                        } else {
                                            let _e1138 = frame.member[0u].member_1.member.member_3;
                                            phi_1581_ = (_e854.member_1.member_2 * (1f + _e1138));
                                        }
                                        let _e1142 = phi_1581_;
                                        let _e1148 = frame.member[0u].member_1.member_3;
                                        let _e1150 = select(false, (sqrt(((_e1008 * _e1008) + (_e1009 * _e1009))) > _e1148), (_e1050 > _e1142));
                                        let _e1153 = depth2_.member[_e1015];
                                        let _e1157 = select(_e684, _e1153, select(false, (_e1153 < _e684), (_e1153 > 0f)));
                                        let _e1163 = (((_e1031 * _e1157) * _e654) - _e854.member_1.member_4.x);
                                        let _e1164 = (((_e1033 * _e1157) * _e662) - _e854.member_1.member_4.y);
                                        let _e1165 = (-(_e1157) - _e854.member_1.member_4.z);
                                        let _e1170 = (((_e1163 * _e854.member_1.member_6.x) + (_e1164 * _e854.member_1.member_6.y)) + (_e1165 * _e854.member_1.member_6.z));
                                        if _e895 {
                                            let _e1175 = (((_e1163 * _e1163) + (_e1164 * _e1164)) + (_e1165 * _e1165));
                                            let _e1187 = (((((_e854.member_1.member_5.x * _e1163) + (_e854.member_1.member_5.y * _e1164)) + (_e854.member_1.member_5.z * _e1165)) / sqrt(_e1175)) - 0.1f);
                                            let _e1194 = (1f - (_e1175 / (_e632 * _e632)));
                                            let _e1201 = ((select(0f, select(1f, _e1187, (_e1187 < 1f)), (_e1187 > 0f)) * select(0f, select(1f, _e1194, (_e1194 < 1f)), (_e1194 > 0f))) / _e917);
                                            phi_1770_ = select(0f, select(0f, select(1f, _e1201, (_e1201 < 1f)), (_e1201 > 0f)), (_e1175 > 0f));
                                        } else {
                                            let _e1212 = frame.member[0u].member_1.member.member_3;
                                            if (_e931 != _e931) {
                                                phi_2386_ = true;
                                            } else {
                                                phi_2386_ = (_e1170 >= _e931);
                                            }
                                            let _e1217 = phi_2386_;
                                            let _e1219 = (_e912 - select(_e931, _e1170, _e1217));
                                            if (_e1219 != _e1219) {
                                                phi_2401_ = true;
                                            } else {
                                                phi_2401_ = (0f >= _e1219);
                                            }
                                            let _e1223 = phi_2401_;
                                            let _e1228 = ((_e1170 - (_e854.member_1.member_2 * (1f + _e1212))) * (1f / _e912));
                                            phi_1770_ = ((select(_e1219, 0f, _e1223) + (select(0f, select(1f, _e1228, (_e1228 < 1f)), (_e1228 > 0f)) * (_e912 - _e931))) * (0.5f / _e912));
                                        }
                                        let _e1239 = phi_1770_;
                                        if (_e1050 != _e1050) {
                                            phi_2416_ = true;
                                        } else {
                                            phi_2416_ = (_e1170 <= _e1050);
                                        }
                                        let _e1243 = phi_2416_;
                                        if _e895 {
                                            if (_e1119 != _e1119) {
                                                phi_2431_ = true;
                                            } else {
                                                phi_2431_ = (_e1239 >= _e1119);
                                            }
                                            let _e1249 = phi_2431_;
                                            phi_1784_ = select(_e1119, _e1239, _e1249);
                                        } else {
                                            if (_e1119 != _e1119) {
                                                phi_2446_ = true;
                                            } else {
                                                phi_2446_ = (_e1239 <= _e1119);
                                            }
                                            let _e1254 = phi_2446_;
                                            phi_1784_ = select(_e1119, _e1239, _e1254);
                                        }
                                        let _e1257 = phi_1784_;
                                        phi_1790_ = type_41(select(_e1050, select(_e1050, _e1170, _e1243), _e1150), select(_e1119, _e1257, _e1150));
                                    }
                                    let _e1261 = phi_1790_;
                                    if select(false, select(false, (_e962 <= 1f), (_e962 >= 0f)), select(false, (_e959 <= 1f), (_e959 >= 0f))) {
                                        phi_1803_ = _e1261.member_1;
                                    } else {
                                        phi_1803_ = select(1f, 0f, _e895);
                                    }
                                    let _e1266 = phi_1803_;
                                    let _e1272 = frame.member[0u].member_1.member_5[0u];
                                    let _e1278 = frame.member[0u].member_1.member_5[1u];
                                    let _e1279 = f32(_e1272);
                                    let _e1280 = f32(_e1278);
                                    let _e1285 = frame.member[0u].member_1.member_4;
                                    let _e1286 = f32(_e1285);
                                    let _e1287 = (2u * _e1285);
                                    let _e1288 = (_e1272 + _e1287);
                                    let _e1294 = (floor((_e959 * _e1279)) + _e1286);
                                    let _e1295 = f32((_e1288 - 1u));
                                    let _e1299 = select(0f, select(_e1295, _e1294, (_e1294 < _e1295)), (_e1294 > 0f));
                                    let _e1302 = (floor((_e962 * _e1280)) + _e1286);
                                    let _e1303 = f32(((_e1278 + _e1287) - 1u));
                                    let _e1307 = select(0f, select(_e1303, _e1302, (_e1302 < _e1303)), (_e1302 > 0f));
                                    let _e1312 = select(select(u32(_e1299), 0u, (_e1299 < 0f)), 4294967295u, (_e1299 > 4294967000f));
                                    let _e1317 = select(select(u32(_e1307), 0u, (_e1307 < 0f)), 4294967295u, (_e1307 > 4294967000f));
                                    let _e1320 = bitcast<i32>(_e1285);
                                    let _e1329 = frame.member[0u].member_1.member_8;
                                    let _e1334 = frame.member[0u].member_1.member_12;
                                    let _e1341 = (((((_e1317 % 4u) * 4u) + (_e1312 % 4u)) + (_e1334 % 16u)) % 16u);
                                    if (_e1329 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1343 = (_e1341 < 16u);
                                        if _e1343 {
                                        } else {
                                            phi_2637_ = true;
                                            break;
                                        }
                                        let _e1346 = local[_e1341][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1343 {
                                        } else {
                                            phi_2637_ = true;
                                            break;
                                        }
                                        let _e1349 = local_1[_e1341][1u];
                                        phi_1937_ = vec2<f32>(_e1346, _e1349);
                                    } else {
                                        if (_e1329 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1352 = (_e1341 < 16u);
                                            if _e1352 {
                                            } else {
                                                phi_2637_ = true;
                                                break;
                                            }
                                            let _e1355 = local_2[_e1341][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1352 {
                                            } else {
                                                phi_2637_ = true;
                                                break;
                                            }
                                            let _e1358 = local_3[_e1341][1u];
                                            phi_1936_ = vec2<f32>(_e1355, _e1358);
                                        } else {
                                            phi_1936_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1361 = phi_1936_;
                                        phi_1937_ = _e1361;
                                    }
                                    let _e1363 = phi_1937_;
                                    let _e1376 = frame.member[0u].member_1.member_6;
                                    phi_1968_ = 0u;
                                    phi_1971_ = _e1266;
                                    loop {
                                        let _e1379 = phi_1968_;
                                        let _e1381 = phi_1971_;
                                        local_11 = _e1381;
                                        let _e1382 = (_e1379 < _e1376);
                                        if _e1382 {
                                            let _e1383 = ((((_e1317 * _e1288) + _e1312) * _e1376) + _e1379);
                                            if (_e1383 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2520_ = true;
                                                break;
                                            }
                                            let _e1386 = sd_map.member[_e1383];
                                            let _e1393 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1396 = ((_e1386 * (_e684 - _e1393)) + _e1393);
                                            let _e1406 = (((((((f32((bitcast<i32>(_e1312) - _e1320)) + _e1363.x) / _e1279) * 2f) - 1f) * _e1396) * _e654) - _e854.member_1.member_4.x);
                                            let _e1407 = (((((((f32((bitcast<i32>(_e1317) - _e1320)) + _e1363.y) / _e1280) * -2f) + 1f) * _e1396) * _e662) - _e854.member_1.member_4.y);
                                            let _e1408 = (-(_e1396) - _e854.member_1.member_4.z);
                                            let _e1413 = (((_e1406 * _e854.member_1.member_6.x) + (_e1407 * _e854.member_1.member_6.y)) + (_e1408 * _e854.member_1.member_6.z));
                                            if _e895 {
                                                let _e1418 = (((_e1406 * _e1406) + (_e1407 * _e1407)) + (_e1408 * _e1408));
                                                let _e1430 = (((((_e854.member_1.member_5.x * _e1406) + (_e854.member_1.member_5.y * _e1407)) + (_e854.member_1.member_5.z * _e1408)) / sqrt(_e1418)) - 0.1f);
                                                let _e1437 = (1f - (_e1418 / (_e632 * _e632)));
                                                let _e1444 = ((select(0f, select(1f, _e1430, (_e1430 < 1f)), (_e1430 > 0f)) * select(0f, select(1f, _e1437, (_e1437 < 1f)), (_e1437 > 0f))) / _e917);
                                                phi_2136_ = select(0f, select(0f, select(1f, _e1444, (_e1444 < 1f)), (_e1444 > 0f)), (_e1418 > 0f));
                                            } else {
                                                let _e1455 = frame.member[0u].member_1.member.member_3;
                                                if (_e931 != _e931) {
                                                    phi_2461_ = true;
                                                } else {
                                                    phi_2461_ = (_e1413 >= _e931);
                                                }
                                                let _e1460 = phi_2461_;
                                                let _e1462 = (_e912 - select(_e931, _e1413, _e1460));
                                                if (_e1462 != _e1462) {
                                                    phi_2476_ = true;
                                                } else {
                                                    phi_2476_ = (0f >= _e1462);
                                                }
                                                let _e1466 = phi_2476_;
                                                let _e1471 = ((_e1413 - (_e854.member_1.member_2 * (1f + _e1455))) * (1f / _e912));
                                                phi_2136_ = ((select(_e1462, 0f, _e1466) + (select(0f, select(1f, _e1471, (_e1471 < 1f)), (_e1471 > 0f)) * (_e912 - _e931))) * (0.5f / _e912));
                                            }
                                            let _e1482 = phi_2136_;
                                            if _e895 {
                                                if (_e1381 != _e1381) {
                                                    phi_2491_ = true;
                                                } else {
                                                    phi_2491_ = (_e1482 >= _e1381);
                                                }
                                                let _e1486 = phi_2491_;
                                                phi_2145_ = select(_e1381, _e1482, _e1486);
                                            } else {
                                                if (_e1381 != _e1381) {
                                                    phi_2506_ = true;
                                                } else {
                                                    phi_2506_ = (_e1482 <= _e1381);
                                                }
                                                let _e1491 = phi_2506_;
                                                phi_2145_ = select(_e1381, _e1482, _e1491);
                                            }
                                            let _e1494 = phi_2145_;
                                            phi_1969_ = (_e1379 + 1u);
                                            phi_1972_ = _e1494;
                                        } else {
                                            phi_1969_ = u32();
                                            phi_1972_ = f32();
                                        }
                                        let _e1497 = phi_1969_;
                                        let _e1499 = phi_1972_;
                                        continue;
                                        continuing {
                                            phi_1968_ = _e1497;
                                            phi_1971_ = _e1499;
                                            phi_2520_ = _e870;
                                            break if !(_e1382);
                                        }
                                    }
                                    let _e1502 = phi_2520_;
                                    phi_2637_ = _e1502;
                                    if _e1502 {
                                        break;
                                    }
                                    let _e1504 = local_11;
                                    phi_2639_ = _e1502;
                                    phi_2150_ = ((_e876 - _e1261.member_1) + _e1504);
                                }
                                let _e1507 = phi_2639_;
                                let _e1509 = phi_2150_;
                                phi_2638_ = _e1507;
                                phi_1105_ = (_e872 + 1u);
                                phi_1110_ = _e1509;
                            } else {
                                phi_2638_ = _e870;
                                phi_1105_ = u32();
                                phi_1110_ = f32();
                            }
                            let _e1512 = phi_2638_;
                            let _e1514 = phi_1105_;
                            let _e1516 = phi_1110_;
                            continue;
                            continuing {
                                phi_2568_ = _e1512;
                                phi_1104_ = _e1514;
                                phi_1107_ = select(u32(), _e874, _e877);
                                phi_1109_ = _e1516;
                                phi_2637_ = _e1512;
                                break if !(_e877);
                            }
                        }
                        let _e1520 = phi_2637_;
                        if _e1520 {
                            break;
                        }
                        let _e1525 = frame.member[0u].member_1.member_10;
                        let _e1526 = (_e1525 == 1u);
                        let _e1531 = local_12;
                        let _e1533 = (_e620 + ((select(2f, 1f, _e1526) / f32(_e868)) * _e1531));
                        if _e1526 {
                            phi_2180_ = (1f - (2f * _e1533));
                        } else {
                            phi_2180_ = _e1533;
                        }
                        let _e1537 = phi_2180_;
                        let _e1547 = frame.member[0u].member_1.member.member_2;
                        let _e1550 = local_13;
                        phi_2195_ = type_42(pow(select(0f, select(1f, _e1537, (_e1537 < 1f)), (_e1537 > 0f)), _e1547), _e1550);
                    } else {
                        phi_2195_ = type_42();
                    }
                    let _e1553 = phi_2195_;
                    phi_2197_ = _e1553;
                    phi_2198_ = select(true, false, _e857);
                }
                let _e1556 = phi_2197_;
                let _e1558 = phi_2198_;
                if _e1558 {
                    phi_2202_ = type_42(_e620, 0u);
                } else {
                    phi_2202_ = _e1556;
                }
                let _e1560 = phi_2202_;
                if _e617 {
                } else {
                    break;
                }
                ao.member[_e616] = _e1560.member;
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
