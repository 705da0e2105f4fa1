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
    var phi_773_: bool;
    var phi_775_: bool;
    var phi_776_: bool;
    var phi_777_: bool;
    var phi_778_: bool;
    var phi_2347_: bool;
    var phi_2362_: bool;
    var phi_2323_: vec2<f32>;
    var phi_1075_: type_31;
    var phi_2423_: bool;
    var phi_1093_: u32;
    var phi_1096_: u32;
    var phi_1098_: f32;
    var phi_1146_: f32;
    var phi_1171_: f32;
    var phi_1184_: f32;
    var phi_1549_: f32;
    var phi_1578_: f32;
    var phi_1779_: f32;
    var phi_1811_: f32;
    var phi_1817_: type_41;
    var phi_1830_: f32;
    var phi_1963_: vec2<f32>;
    var phi_1964_: vec2<f32>;
    var phi_1995_: u32;
    var phi_1998_: f32;
    var phi_2175_: f32;
    var phi_2196_: f32;
    var phi_1996_: u32;
    var phi_1999_: f32;
    var phi_2376_: bool;
    var local_11: f32;
    var phi_2482_: bool;
    var phi_2201_: f32;
    var phi_2481_: bool;
    var phi_1094_: u32;
    var phi_1099_: f32;
    var phi_2480_: bool;
    var local_12: f32;
    var phi_2231_: f32;
    var local_13: u32;
    var phi_2246_: type_42;
    var phi_2248_: type_42;
    var phi_2249_: bool;
    var phi_2253_: type_42;

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
                        phi_773_ = ((_e570 + _e568) < _e596);
                    } else {
                        phi_773_ = bool();
                    }
                    let _e604 = phi_773_;
                    phi_775_ = _e604;
                    phi_776_ = select(true, false, _e600);
                } else {
                    phi_775_ = bool();
                    phi_776_ = true;
                }
                let _e607 = phi_775_;
                let _e609 = phi_776_;
                phi_777_ = _e607;
                phi_778_ = _e609;
            } else {
                phi_777_ = bool();
                phi_778_ = true;
            }
            let _e611 = phi_777_;
            let _e613 = phi_778_;
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
                    phi_2248_ = type_42();
                    phi_2249_ = true;
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
                        phi_2347_ = true;
                    } else {
                        phi_2347_ = (-1f >= _e710);
                    }
                    let _e714 = phi_2347_;
                    let _e715 = select(_e710, -1f, _e714);
                    let _e725 = (f32((bitcast<i32>((((_e702 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e725 != _e725) {
                        phi_2362_ = true;
                    } else {
                        phi_2362_ = (-1f >= _e725);
                    }
                    let _e729 = phi_2362_;
                    let _e730 = select(_e725, -1f, _e729);
                    let _e733 = (1f - abs(_e715));
                    let _e734 = abs(_e730);
                    let _e735 = (_e733 - _e734);
                    if (_e735 < 0f) {
                        phi_2323_ = vec2<f32>(((1f - _e734) * select(1f, -1f, (_e715 < 0f))), (_e733 * select(1f, -1f, (_e730 < 0f))));
                    } else {
                        phi_2323_ = vec2<f32>(_e715, _e730);
                    }
                    let _e746 = phi_2323_;
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
                    if select(false, !((_e677 < 0.5f)), select(false, (_e646 < _e684), (_e646 > 0f))) {
                        phi_1075_ = type_31(1u, type_30(vec2<u32>(_e569, _e570), vec2<f32>(_e641, _e644), select(_e632, ((_e632 * _e638) / _e672), _e673), _e677, vec3<f32>(_e696, _e698, _e699), vec3<f32>(_e768, _e769, _e770), vec3<f32>(_e789, _e790, _e791), vec3<f32>(_e812, _e815, _e818), vec3<f32>(_e806, _e807, _e808), vec3<f32>((((_e768 * _e812) + (_e769 * _e815)) + (_e770 * _e818)), (((_e768 * _e806) + (_e769 * _e807)) + (_e770 * _e808)), _e834), (1f / (select(1f, -1f, (_e834 < 0f)) * select(0.0001f, _e838, ((_e838 > 0.0001f) || false))))));
                    } else {
                        phi_1075_ = type_31(0u, type_31().member_1);
                    }
                    let _e852 = phi_1075_;
                    let _e855 = (bitcast<i32>(_e852.member) != 0i);
                    if _e855 {
                        let _e861 = frame.member[0u].member_1.member_11;
                        let _e866 = (8u << bitcast<u32>((select(_e861, 2u, (2u < _e861)) & 31u)));
                        phi_2423_ = false;
                        phi_1093_ = 0u;
                        phi_1096_ = 0u;
                        phi_1098_ = 0f;
                        loop {
                            let _e868 = phi_2423_;
                            let _e870 = phi_1093_;
                            let _e872 = phi_1096_;
                            let _e874 = phi_1098_;
                            local_12 = _e874;
                            local_13 = _e872;
                            let _e875 = (_e870 < _e866);
                            if _e875 {
                                if ((_e624 & (1u << bitcast<u32>((_e870 & 31u)))) == 0u) {
                                    phi_2482_ = _e868;
                                    phi_2201_ = _e874;
                                } else {
                                    let _e885 = frame.member[0u].member_1.member_10;
                                    let _e887 = ((_e866 + _e870) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e888 = (_e887 < 56u);
                                    if _e888 {
                                    } else {
                                        phi_2480_ = true;
                                        break;
                                    }
                                    let _e890 = local_4[_e887];
                                    let _e893 = (_e885 == 1u);
                                    if _e893 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e888 {
                                        } else {
                                            phi_2480_ = true;
                                            break;
                                        }
                                        let _e895 = local_5[_e887];
                                        phi_1146_ = _e895;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e888 {
                                        } else {
                                            phi_2480_ = true;
                                            break;
                                        }
                                        let _e897 = local_6[_e887];
                                        phi_1146_ = _e897;
                                    }
                                    let _e899 = phi_1146_;
                                    let _e901 = (_e852.member_1.member_2 * _e899);
                                    let _e902 = (_e901 * _e890[0]);
                                    let _e903 = (_e901 * _e890[1]);
                                    if _e893 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e888 {
                                        } else {
                                            phi_2480_ = true;
                                            break;
                                        }
                                        let _e905 = local_7[_e887];
                                        phi_1171_ = _e905;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e888 {
                                        } else {
                                            phi_2480_ = true;
                                            break;
                                        }
                                        let _e907 = local_8[_e887];
                                        phi_1171_ = _e907;
                                    }
                                    let _e909 = phi_1171_;
                                    let _e910 = (_e852.member_1.member_2 * _e909);
                                    if _e893 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e888 {
                                        } else {
                                            phi_2480_ = true;
                                            break;
                                        }
                                        let _e912 = local_9[_e887];
                                        phi_1184_ = _e912;
                                    } else {
                                        phi_1184_ = (_e910 * 2f);
                                    }
                                    let _e915 = phi_1184_;
                                    let _e924 = (-(((_e902 * _e852.member_1.member_9.x) + (_e903 * _e852.member_1.member_9.y))) * _e852.member_1.member_10);
                                    let _e925 = -(_e910);
                                    let _e929 = select(_e925, select(_e910, _e924, (_e924 < _e910)), (_e924 > _e925));
                                    let _e954 = (-0.5f / ((_e852.member_1.member_4.z + (_e852.member_1.member_7.z * _e902)) + (_e852.member_1.member_8.z * _e903)));
                                    let _e957 = (((((_e852.member_1.member_4.x + (_e852.member_1.member_7.x * _e902)) + (_e852.member_1.member_8.x * _e903)) * _e954) / _e654) + 0.5f);
                                    let _e960 = (0.5f - ((((_e852.member_1.member_4.y + (_e852.member_1.member_7.y * _e902)) + (_e852.member_1.member_8.y * _e903)) * _e954) / _e662));
                                    let _e972 = (select(0f, select(1f, _e957, (_e957 < 1f)), (_e957 > 0f)) * _e578);
                                    let _e974 = f32((_e583 - 1u));
                                    let _e976 = select(0f, _e972, (_e972 > 0f));
                                    let _e979 = u32(select(_e974, _e976, (_e976 < _e974)));
                                    let _e984 = (select(0f, select(1f, _e960, (_e960 < 1f)), (_e960 > 0f)) * _e591);
                                    let _e986 = f32((_e596 - 1u));
                                    let _e988 = select(0f, _e984, (_e984 > 0f));
                                    let _e991 = u32(select(_e986, _e988, (_e988 < _e986)));
                                    let _e998 = ((_e852.member_1.member_1.x - _e957) * _e578);
                                    let _e999 = ((_e852.member_1.member_1.y - _e960) * _e591);
                                    let _e1005 = ((_e991 * _e583) + _e979);
                                    let _e1007 = depth.member[_e1005];
                                    let _e1019 = select(_e684, _e1007, select(false, (_e1007 < _e684), (_e1007 > 0f)));
                                    let _e1021 = ((((f32(_e979) + 0.5f) * (1f / _e578)) * 2f) - 1f);
                                    let _e1023 = ((((f32(_e991) + 0.5f) * (1f / _e591)) * -2f) + 1f);
                                    let _e1029 = (((_e1021 * _e1019) * _e654) - _e852.member_1.member_4.x);
                                    let _e1030 = (((_e1023 * _e1019) * _e662) - _e852.member_1.member_4.y);
                                    let _e1031 = (-(_e1019) - _e852.member_1.member_4.z);
                                    let _e1040 = (((_e1029 * _e852.member_1.member_6.x) + (_e1030 * _e852.member_1.member_6.y)) + (_e1031 * _e852.member_1.member_6.z));
                                    if _e893 {
                                        let _e1045 = (((_e1029 * _e1029) + (_e1030 * _e1030)) + (_e1031 * _e1031));
                                        let _e1057 = (((((_e852.member_1.member_5.x * _e1029) + (_e852.member_1.member_5.y * _e1030)) + (_e852.member_1.member_5.z * _e1031)) / sqrt(_e1045)) - 0.1f);
                                        let _e1064 = (1f - (_e1045 / (_e632 * _e632)));
                                        let _e1071 = ((select(0f, select(1f, _e1057, (_e1057 < 1f)), (_e1057 > 0f)) * select(0f, select(1f, _e1064, (_e1064 < 1f)), (_e1064 > 0f))) / _e915);
                                        phi_1549_ = select(0f, select(0f, select(1f, _e1071, (_e1071 < 1f)), (_e1071 > 0f)), (_e1045 > 0f));
                                    } else {
                                        let _e1082 = frame.member[0u].member_1.member.member_3;
                                        let _e1088 = (_e910 - select(_e1040, _e929, ((_e929 > _e1040) || (_e1040 != _e1040))));
                                        let _e1095 = ((_e1040 - (_e852.member_1.member_2 * (1f + _e1082))) * (1f / _e910));
                                        phi_1549_ = ((select(0f, _e1088, ((_e1088 > 0f) || false)) + (select(0f, select(1f, _e1095, (_e1095 < 1f)), (_e1095 > 0f)) * (_e910 - _e929))) * (0.5f / _e910));
                                    }
                                    let _e1106 = phi_1549_;
                                    let _e1111 = frame.member[0u].member_1.member_9;
                                    if (_e1111 == 0u) {
                                        phi_1817_ = type_41(_e1040, _e1106);
                                    } else {
                                        if _e893 {
                                            let _e1114 = (_e852.member_1.member_2 * 0.1f);
                                            phi_1578_ = select(_e1114, _e910, ((_e910 > _e1114) || (_e1114 != _e1114)));
                                        } else {
                                            let _e1124 = frame.member[0u].member_1.member.member_3;
                                            phi_1578_ = (_e852.member_1.member_2 * (1f + _e1124));
                                        }
                                        let _e1128 = phi_1578_;
                                        let _e1134 = frame.member[0u].member_1.member_3;
                                        let _e1136 = select(false, (sqrt(((_e998 * _e998) + (_e999 * _e999))) > _e1134), (_e1040 > _e1128));
                                        let _e1139 = depth2_.member[_e1005];
                                        let _e1143 = select(_e684, _e1139, select(false, (_e1139 < _e684), (_e1139 > 0f)));
                                        let _e1149 = (((_e1021 * _e1143) * _e654) - _e852.member_1.member_4.x);
                                        let _e1150 = (((_e1023 * _e1143) * _e662) - _e852.member_1.member_4.y);
                                        let _e1151 = (-(_e1143) - _e852.member_1.member_4.z);
                                        let _e1156 = (((_e1149 * _e852.member_1.member_6.x) + (_e1150 * _e852.member_1.member_6.y)) + (_e1151 * _e852.member_1.member_6.z));
                                        if _e893 {
                                            let _e1161 = (((_e1149 * _e1149) + (_e1150 * _e1150)) + (_e1151 * _e1151));
                                            let _e1173 = (((((_e852.member_1.member_5.x * _e1149) + (_e852.member_1.member_5.y * _e1150)) + (_e852.member_1.member_5.z * _e1151)) / sqrt(_e1161)) - 0.1f);
                                            let _e1180 = (1f - (_e1161 / (_e632 * _e632)));
                                            let _e1187 = ((select(0f, select(1f, _e1173, (_e1173 < 1f)), (_e1173 > 0f)) * select(0f, select(1f, _e1180, (_e1180 < 1f)), (_e1180 > 0f))) / _e915);
                                            phi_1779_ = select(0f, select(0f, select(1f, _e1187, (_e1187 < 1f)), (_e1187 > 0f)), (_e1161 > 0f));
                                        } else {
                                            let _e1198 = frame.member[0u].member_1.member.member_3;
                                            let _e1204 = (_e910 - select(_e1156, _e929, ((_e929 > _e1156) || (_e1156 != _e1156))));
                                            let _e1211 = ((_e1156 - (_e852.member_1.member_2 * (1f + _e1198))) * (1f / _e910));
                                            phi_1779_ = ((select(0f, _e1204, ((_e1204 > 0f) || false)) + (select(0f, select(1f, _e1211, (_e1211 < 1f)), (_e1211 > 0f)) * (_e910 - _e929))) * (0.5f / _e910));
                                        }
                                        let _e1222 = phi_1779_;
                                        if _e893 {
                                            phi_1811_ = select(_e1222, _e1106, ((_e1106 > _e1222) || (_e1222 != _e1222)));
                                        } else {
                                            phi_1811_ = select(_e1222, _e1106, ((_e1106 < _e1222) || (_e1222 != _e1222)));
                                        }
                                        let _e1237 = phi_1811_;
                                        phi_1817_ = type_41(select(_e1040, select(_e1156, _e1040, ((_e1040 < _e1156) || (_e1156 != _e1156))), _e1136), select(_e1106, _e1237, _e1136));
                                    }
                                    let _e1241 = phi_1817_;
                                    if select(false, select(false, (_e960 <= 1f), (_e960 >= 0f)), select(false, (_e957 <= 1f), (_e957 >= 0f))) {
                                        phi_1830_ = _e1241.member_1;
                                    } else {
                                        phi_1830_ = select(1f, 0f, _e893);
                                    }
                                    let _e1246 = phi_1830_;
                                    let _e1252 = frame.member[0u].member_1.member_5[0u];
                                    let _e1258 = frame.member[0u].member_1.member_5[1u];
                                    let _e1259 = f32(_e1252);
                                    let _e1260 = f32(_e1258);
                                    let _e1265 = frame.member[0u].member_1.member_4;
                                    let _e1266 = f32(_e1265);
                                    let _e1267 = (2u * _e1265);
                                    let _e1268 = (_e1252 + _e1267);
                                    let _e1274 = (floor((_e957 * _e1259)) + _e1266);
                                    let _e1275 = f32((_e1268 - 1u));
                                    let _e1279 = select(0f, select(_e1275, _e1274, (_e1274 < _e1275)), (_e1274 > 0f));
                                    let _e1282 = (floor((_e960 * _e1260)) + _e1266);
                                    let _e1283 = f32(((_e1258 + _e1267) - 1u));
                                    let _e1287 = select(0f, select(_e1283, _e1282, (_e1282 < _e1283)), (_e1282 > 0f));
                                    let _e1292 = select(select(u32(_e1279), 0u, (_e1279 < 0f)), 4294967295u, (_e1279 > 4294967000f));
                                    let _e1297 = select(select(u32(_e1287), 0u, (_e1287 < 0f)), 4294967295u, (_e1287 > 4294967000f));
                                    let _e1300 = bitcast<i32>(_e1265);
                                    let _e1309 = frame.member[0u].member_1.member_8;
                                    let _e1314 = frame.member[0u].member_1.member_12;
                                    let _e1321 = (((((_e1297 % 4u) * 4u) + (_e1292 % 4u)) + (_e1314 % 16u)) % 16u);
                                    if (_e1309 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1323 = (_e1321 < 16u);
                                        if _e1323 {
                                        } else {
                                            phi_2480_ = true;
                                            break;
                                        }
                                        let _e1326 = local[_e1321][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1323 {
                                        } else {
                                            phi_2480_ = true;
                                            break;
                                        }
                                        let _e1329 = local_1[_e1321][1u];
                                        phi_1964_ = vec2<f32>(_e1326, _e1329);
                                    } else {
                                        if (_e1309 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1332 = (_e1321 < 16u);
                                            if _e1332 {
                                            } else {
                                                phi_2480_ = true;
                                                break;
                                            }
                                            let _e1335 = local_2[_e1321][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1332 {
                                            } else {
                                                phi_2480_ = true;
                                                break;
                                            }
                                            let _e1338 = local_3[_e1321][1u];
                                            phi_1963_ = vec2<f32>(_e1335, _e1338);
                                        } else {
                                            phi_1963_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1341 = phi_1963_;
                                        phi_1964_ = _e1341;
                                    }
                                    let _e1343 = phi_1964_;
                                    let _e1356 = frame.member[0u].member_1.member_6;
                                    phi_1995_ = 0u;
                                    phi_1998_ = _e1246;
                                    loop {
                                        let _e1359 = phi_1995_;
                                        let _e1361 = phi_1998_;
                                        local_11 = _e1361;
                                        let _e1362 = (_e1359 < _e1356);
                                        if _e1362 {
                                            let _e1363 = ((((_e1297 * _e1268) + _e1292) * _e1356) + _e1359);
                                            if (_e1363 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2376_ = true;
                                                break;
                                            }
                                            let _e1366 = sd_map.member[_e1363];
                                            let _e1373 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1376 = ((_e1366 * (_e684 - _e1373)) + _e1373);
                                            let _e1386 = (((((((f32((bitcast<i32>(_e1292) - _e1300)) + _e1343.x) / _e1259) * 2f) - 1f) * _e1376) * _e654) - _e852.member_1.member_4.x);
                                            let _e1387 = (((((((f32((bitcast<i32>(_e1297) - _e1300)) + _e1343.y) / _e1260) * -2f) + 1f) * _e1376) * _e662) - _e852.member_1.member_4.y);
                                            let _e1388 = (-(_e1376) - _e852.member_1.member_4.z);
                                            let _e1393 = (((_e1386 * _e852.member_1.member_6.x) + (_e1387 * _e852.member_1.member_6.y)) + (_e1388 * _e852.member_1.member_6.z));
                                            if _e893 {
                                                let _e1398 = (((_e1386 * _e1386) + (_e1387 * _e1387)) + (_e1388 * _e1388));
                                                let _e1410 = (((((_e852.member_1.member_5.x * _e1386) + (_e852.member_1.member_5.y * _e1387)) + (_e852.member_1.member_5.z * _e1388)) / sqrt(_e1398)) - 0.1f);
                                                let _e1417 = (1f - (_e1398 / (_e632 * _e632)));
                                                let _e1424 = ((select(0f, select(1f, _e1410, (_e1410 < 1f)), (_e1410 > 0f)) * select(0f, select(1f, _e1417, (_e1417 < 1f)), (_e1417 > 0f))) / _e915);
                                                phi_2175_ = select(0f, select(0f, select(1f, _e1424, (_e1424 < 1f)), (_e1424 > 0f)), (_e1398 > 0f));
                                            } else {
                                                let _e1435 = frame.member[0u].member_1.member.member_3;
                                                let _e1441 = (_e910 - select(_e1393, _e929, ((_e929 > _e1393) || (_e1393 != _e1393))));
                                                let _e1448 = ((_e1393 - (_e852.member_1.member_2 * (1f + _e1435))) * (1f / _e910));
                                                phi_2175_ = ((select(0f, _e1441, ((_e1441 > 0f) || false)) + (select(0f, select(1f, _e1448, (_e1448 < 1f)), (_e1448 > 0f)) * (_e910 - _e929))) * (0.5f / _e910));
                                            }
                                            let _e1459 = phi_2175_;
                                            if _e893 {
                                                phi_2196_ = select(_e1459, _e1361, ((_e1361 > _e1459) || (_e1459 != _e1459)));
                                            } else {
                                                phi_2196_ = select(_e1459, _e1361, ((_e1361 < _e1459) || (_e1459 != _e1459)));
                                            }
                                            let _e1469 = phi_2196_;
                                            phi_1996_ = (_e1359 + 1u);
                                            phi_1999_ = _e1469;
                                        } else {
                                            phi_1996_ = u32();
                                            phi_1999_ = f32();
                                        }
                                        let _e1472 = phi_1996_;
                                        let _e1474 = phi_1999_;
                                        continue;
                                        continuing {
                                            phi_1995_ = _e1472;
                                            phi_1998_ = _e1474;
                                            phi_2376_ = _e868;
                                            break if !(_e1362);
                                        }
                                    }
                                    let _e1477 = phi_2376_;
                                    phi_2480_ = _e1477;
                                    if _e1477 {
                                        break;
                                    }
                                    let _e1479 = local_11;
                                    phi_2482_ = _e1477;
                                    phi_2201_ = ((_e874 - _e1241.member_1) + _e1479);
                                }
                                let _e1482 = phi_2482_;
                                let _e1484 = phi_2201_;
                                phi_2481_ = _e1482;
                                phi_1094_ = (_e870 + 1u);
                                phi_1099_ = _e1484;
                            } else {
                                phi_2481_ = _e868;
                                phi_1094_ = u32();
                                phi_1099_ = f32();
                            }
                            let _e1487 = phi_2481_;
                            let _e1489 = phi_1094_;
                            let _e1491 = phi_1099_;
                            continue;
                            continuing {
                                phi_2423_ = _e1487;
                                phi_1093_ = _e1489;
                                phi_1096_ = select(u32(), _e872, _e875);
                                phi_1098_ = _e1491;
                                phi_2480_ = _e1487;
                                break if !(_e875);
                            }
                        }
                        let _e1495 = phi_2480_;
                        if _e1495 {
                            break;
                        }
                        let _e1500 = frame.member[0u].member_1.member_10;
                        let _e1501 = (_e1500 == 1u);
                        let _e1506 = local_12;
                        let _e1508 = (_e620 + ((select(2f, 1f, _e1501) / f32(_e866)) * _e1506));
                        if _e1501 {
                            phi_2231_ = (1f - (2f * _e1508));
                        } else {
                            phi_2231_ = _e1508;
                        }
                        let _e1512 = phi_2231_;
                        let _e1522 = frame.member[0u].member_1.member.member_2;
                        let _e1525 = local_13;
                        phi_2246_ = type_42(pow(select(0f, select(1f, _e1512, (_e1512 < 1f)), (_e1512 > 0f)), _e1522), _e1525);
                    } else {
                        phi_2246_ = type_42();
                    }
                    let _e1528 = phi_2246_;
                    phi_2248_ = _e1528;
                    phi_2249_ = select(true, false, _e855);
                }
                let _e1531 = phi_2248_;
                let _e1533 = phi_2249_;
                if _e1533 {
                    phi_2253_ = type_42(_e620, 0u);
                } else {
                    phi_2253_ = _e1531;
                }
                let _e1535 = phi_2253_;
                if _e617 {
                } else {
                    break;
                }
                ao.member[_e616] = _e1535.member;
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
