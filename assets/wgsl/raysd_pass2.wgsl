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
    var phi_775_: bool;
    var phi_777_: bool;
    var phi_778_: bool;
    var phi_779_: bool;
    var phi_780_: bool;
    var phi_2363_: bool;
    var phi_2378_: bool;
    var phi_2339_: vec2<f32>;
    var phi_1079_: type_31;
    var phi_2439_: bool;
    var phi_1097_: u32;
    var phi_1100_: u32;
    var phi_1102_: f32;
    var phi_1150_: f32;
    var phi_1175_: f32;
    var phi_1188_: f32;
    var phi_1563_: f32;
    var phi_1592_: f32;
    var phi_1795_: f32;
    var phi_1827_: f32;
    var phi_1833_: type_41;
    var phi_1846_: f32;
    var phi_1979_: vec2<f32>;
    var phi_1980_: vec2<f32>;
    var phi_2011_: u32;
    var phi_2014_: f32;
    var phi_2191_: f32;
    var phi_2212_: f32;
    var phi_2012_: u32;
    var phi_2015_: f32;
    var phi_2392_: bool;
    var local_11: f32;
    var phi_2498_: bool;
    var phi_2217_: f32;
    var phi_2497_: bool;
    var phi_1098_: u32;
    var phi_1103_: f32;
    var phi_2496_: bool;
    var local_12: f32;
    var phi_2247_: f32;
    var local_13: u32;
    var phi_2262_: type_42;
    var phi_2264_: type_42;
    var phi_2265_: bool;
    var phi_2269_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e549 = id_1;
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e570 = frame.member[0u].member_1.member.member.member_4;
            let _e571 = (_e549.x + _e570);
            let _e572 = (_e549.y + _e570);
            let _e580 = frame.member[0u].member_1.member.member.member[0u];
            let _e585 = select(select(u32(_e580), 0u, (_e580 < 0f)), 4294967295u, (_e580 > 4294967000f));
            let _e593 = frame.member[0u].member_1.member.member.member[1u];
            let _e598 = select(select(u32(_e593), 0u, (_e593 < 0f)), 4294967295u, (_e593 > 4294967000f));
            if (_e571 >= _e570) {
                if (_e572 >= _e570) {
                    let _e602 = ((_e571 + _e570) < _e585);
                    if _e602 {
                        phi_775_ = ((_e572 + _e570) < _e598);
                    } else {
                        phi_775_ = bool();
                    }
                    let _e606 = phi_775_;
                    phi_777_ = _e606;
                    phi_778_ = select(true, false, _e602);
                } else {
                    phi_777_ = bool();
                    phi_778_ = true;
                }
                let _e609 = phi_777_;
                let _e611 = phi_778_;
                phi_779_ = _e609;
                phi_780_ = _e611;
            } else {
                phi_779_ = bool();
                phi_780_ = true;
            }
            let _e613 = phi_779_;
            let _e615 = phi_780_;
            if select(_e613, false, _e615) {
                let _e618 = ((_e572 * _e585) + _e571);
                let _e619 = (_e618 < arrayLength((&ao.member)));
                if _e619 {
                } else {
                    break;
                }
                let _e622 = ao.member[_e618];
                if (_e618 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e626 = mask.member[_e618];
                if (_e626 == 0u) {
                    phi_2264_ = type_42();
                    phi_2265_ = true;
                } else {
                    let _e634 = frame.member[0u].member_1.member.member_1;
                    let _e640 = frame.member[0u].member_1.member.member_4;
                    let _e644 = ((f32(bitcast<i32>(_e571)) + 0.5f) / _e580);
                    let _e648 = ((f32(bitcast<i32>(_e572)) + 0.5f) / _e593);
                    let _e650 = depth.member[_e618];
                    let _e658 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e666 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e676 = ((((_e634 * _e580) / (_e650 * (2f * _e658))) + ((_e634 * _e593) / (_e650 * (2f * _e666)))) * 0.5f);
                    let _e677 = (_e676 > _e640);
                    let _e681 = select(_e676, _e640, _e677);
                    let _e688 = frame.member[0u].member_1.member.member.member_3;
                    let _e700 = ((((_e644 * 2f) - 1f) * _e650) * _e658);
                    let _e702 = ((((_e648 * -2f) + 1f) * _e650) * _e666);
                    let _e703 = -(_e650);
                    let _e706 = normals.member[_e618];
                    let _e714 = (f32((bitcast<i32>(((_e706 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e714 != _e714) {
                        phi_2363_ = true;
                    } else {
                        phi_2363_ = (-1f >= _e714);
                    }
                    let _e718 = phi_2363_;
                    let _e719 = select(_e714, -1f, _e718);
                    let _e729 = (f32((bitcast<i32>((((_e706 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e729 != _e729) {
                        phi_2378_ = true;
                    } else {
                        phi_2378_ = (-1f >= _e729);
                    }
                    let _e733 = phi_2378_;
                    let _e734 = select(_e729, -1f, _e733);
                    let _e737 = (1f - abs(_e719));
                    let _e738 = abs(_e734);
                    let _e739 = (_e737 - _e738);
                    if (_e739 < 0f) {
                        phi_2339_ = vec2<f32>(((1f - _e738) * select(1f, -1f, (_e719 < 0f))), (_e737 * select(1f, -1f, (_e734 < 0f))));
                    } else {
                        phi_2339_ = vec2<f32>(_e719, _e734);
                    }
                    let _e750 = phi_2339_;
                    let _e759 = (1f / sqrt((((_e750.x * _e750.x) + (_e750.y * _e750.y)) + (_e739 * _e739))));
                    let _e760 = (_e750.x * _e759);
                    let _e761 = (_e750.y * _e759);
                    let _e762 = (_e739 * _e759);
                    let _e768 = ((((_e700 * _e760) + (_e702 * _e761)) + (_e703 * _e762)) > 0f);
                    let _e772 = select(_e760, -(_e760), _e768);
                    let _e773 = select(_e761, -(_e761), _e768);
                    let _e774 = select(_e762, -(_e762), _e768);
                    local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                    let _e776 = (_e572 % 4u);
                    if (_e776 < 4u) {
                    } else {
                        break;
                    }
                    let _e778 = (_e571 % 4u);
                    if (_e778 < 4u) {
                    } else {
                        break;
                    }
                    let _e782 = local_10[_e776][_e778];
                    let _e792 = sqrt((((_e700 * _e700) + (_e702 * _e702)) + (_e703 * _e703)));
                    let _e793 = (-(_e700) / _e792);
                    let _e794 = (-(_e702) / _e792);
                    let _e795 = (_e650 / _e792);
                    let _e798 = -((_e782[1] * _e795));
                    let _e799 = (_e795 * _e782[0]);
                    let _e802 = ((_e793 * _e782[1]) - (_e782[0] * _e794));
                    let _e809 = (1f / sqrt((((_e798 * _e798) + (_e799 * _e799)) + (_e802 * _e802))));
                    let _e810 = (_e798 * _e809);
                    let _e811 = (_e799 * _e809);
                    let _e812 = (_e802 * _e809);
                    let _e816 = ((_e811 * _e795) - (_e794 * _e812));
                    let _e819 = ((_e812 * _e793) - (_e795 * _e810));
                    let _e822 = ((_e810 * _e794) - (_e793 * _e811));
                    let _e838 = (((_e772 * _e793) + (_e773 * _e794)) + (_e774 * _e795));
                    let _e842 = abs(_e838);
                    if select(false, !((_e681 < 0.5f)), select(false, (_e650 < _e688), (_e650 > 0f))) {
                        phi_1079_ = type_31(1u, type_30(vec2<u32>(_e571, _e572), vec2<f32>(_e644, _e648), select(_e634, ((_e634 * _e640) / _e676), _e677), _e681, vec3<f32>(_e700, _e702, _e703), vec3<f32>(_e772, _e773, _e774), vec3<f32>(_e793, _e794, _e795), vec3<f32>(_e816, _e819, _e822), vec3<f32>(_e810, _e811, _e812), vec3<f32>((((_e772 * _e816) + (_e773 * _e819)) + (_e774 * _e822)), (((_e772 * _e810) + (_e773 * _e811)) + (_e774 * _e812)), _e838), (1f / (select(1f, -1f, (_e838 < 0f)) * select(0.0001f, _e842, ((_e842 > 0.0001f) || false))))));
                    } else {
                        phi_1079_ = type_31(0u, type_31().member_1);
                    }
                    let _e856 = phi_1079_;
                    let _e859 = (bitcast<i32>(_e856.member) != 0i);
                    if _e859 {
                        let _e865 = frame.member[0u].member_1.member_11;
                        let _e870 = (8u << bitcast<u32>((select(_e865, 2u, (2u < _e865)) & 31u)));
                        phi_2439_ = false;
                        phi_1097_ = 0u;
                        phi_1100_ = 0u;
                        phi_1102_ = 0f;
                        loop {
                            let _e872 = phi_2439_;
                            let _e874 = phi_1097_;
                            let _e876 = phi_1100_;
                            let _e878 = phi_1102_;
                            local_12 = _e878;
                            local_13 = _e876;
                            let _e879 = (_e874 < _e870);
                            if _e879 {
                                if ((_e626 & (1u << bitcast<u32>((_e874 & 31u)))) == 0u) {
                                    phi_2498_ = _e872;
                                    phi_2217_ = _e878;
                                } else {
                                    let _e889 = frame.member[0u].member_1.member_10;
                                    let _e891 = ((_e870 + _e874) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e892 = (_e891 < 56u);
                                    if _e892 {
                                    } else {
                                        phi_2496_ = true;
                                        break;
                                    }
                                    let _e894 = local_4[_e891];
                                    let _e897 = (_e889 == 1u);
                                    if _e897 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e892 {
                                        } else {
                                            phi_2496_ = true;
                                            break;
                                        }
                                        let _e899 = local_5[_e891];
                                        phi_1150_ = _e899;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e892 {
                                        } else {
                                            phi_2496_ = true;
                                            break;
                                        }
                                        let _e901 = local_6[_e891];
                                        phi_1150_ = _e901;
                                    }
                                    let _e903 = phi_1150_;
                                    let _e905 = (_e856.member_1.member_2 * _e903);
                                    let _e906 = (_e905 * _e894[0]);
                                    let _e907 = (_e905 * _e894[1]);
                                    if _e897 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e892 {
                                        } else {
                                            phi_2496_ = true;
                                            break;
                                        }
                                        let _e909 = local_7[_e891];
                                        phi_1175_ = _e909;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e892 {
                                        } else {
                                            phi_2496_ = true;
                                            break;
                                        }
                                        let _e911 = local_8[_e891];
                                        phi_1175_ = _e911;
                                    }
                                    let _e913 = phi_1175_;
                                    let _e914 = (_e856.member_1.member_2 * _e913);
                                    if _e897 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e892 {
                                        } else {
                                            phi_2496_ = true;
                                            break;
                                        }
                                        let _e916 = local_9[_e891];
                                        phi_1188_ = _e916;
                                    } else {
                                        phi_1188_ = (_e914 * 2f);
                                    }
                                    let _e919 = phi_1188_;
                                    let _e928 = (-(((_e906 * _e856.member_1.member_9.x) + (_e907 * _e856.member_1.member_9.y))) * _e856.member_1.member_10);
                                    let _e929 = -(_e914);
                                    let _e933 = select(_e929, select(_e914, _e928, (_e928 < _e914)), (_e928 > _e929));
                                    let _e958 = (-0.5f / ((_e856.member_1.member_4.z + (_e856.member_1.member_7.z * _e906)) + (_e856.member_1.member_8.z * _e907)));
                                    let _e961 = (((((_e856.member_1.member_4.x + (_e856.member_1.member_7.x * _e906)) + (_e856.member_1.member_8.x * _e907)) * _e958) / _e658) + 0.5f);
                                    let _e964 = (0.5f - ((((_e856.member_1.member_4.y + (_e856.member_1.member_7.y * _e906)) + (_e856.member_1.member_8.y * _e907)) * _e958) / _e666));
                                    let _e976 = (select(0f, select(1f, _e961, (_e961 < 1f)), (_e961 > 0f)) * _e580);
                                    let _e979 = f32(bitcast<i32>((_e585 - 1u)));
                                    let _e981 = select(0f, _e976, (_e976 > 0f));
                                    let _e987 = (bitcast<u32>((floor(select(_e979, _e981, (_e981 < _e979))) + 8388608f)) - 1258291200u);
                                    let _e992 = (select(0f, select(1f, _e964, (_e964 < 1f)), (_e964 > 0f)) * _e593);
                                    let _e995 = f32(bitcast<i32>((_e598 - 1u)));
                                    let _e997 = select(0f, _e992, (_e992 > 0f));
                                    let _e1003 = (bitcast<u32>((floor(select(_e995, _e997, (_e997 < _e995))) + 8388608f)) - 1258291200u);
                                    let _e1010 = ((_e856.member_1.member_1.x - _e961) * _e580);
                                    let _e1011 = ((_e856.member_1.member_1.y - _e964) * _e593);
                                    let _e1017 = ((_e1003 * _e585) + _e987);
                                    let _e1019 = depth.member[_e1017];
                                    let _e1033 = select(_e688, _e1019, select(false, (_e1019 < _e688), (_e1019 > 0f)));
                                    let _e1035 = ((((f32(bitcast<i32>(_e987)) + 0.5f) * (1f / _e580)) * 2f) - 1f);
                                    let _e1037 = ((((f32(bitcast<i32>(_e1003)) + 0.5f) * (1f / _e593)) * -2f) + 1f);
                                    let _e1043 = (((_e1035 * _e1033) * _e658) - _e856.member_1.member_4.x);
                                    let _e1044 = (((_e1037 * _e1033) * _e666) - _e856.member_1.member_4.y);
                                    let _e1045 = (-(_e1033) - _e856.member_1.member_4.z);
                                    let _e1054 = (((_e1043 * _e856.member_1.member_6.x) + (_e1044 * _e856.member_1.member_6.y)) + (_e1045 * _e856.member_1.member_6.z));
                                    if _e897 {
                                        let _e1059 = (((_e1043 * _e1043) + (_e1044 * _e1044)) + (_e1045 * _e1045));
                                        let _e1071 = (((((_e856.member_1.member_5.x * _e1043) + (_e856.member_1.member_5.y * _e1044)) + (_e856.member_1.member_5.z * _e1045)) / sqrt(_e1059)) - 0.1f);
                                        let _e1078 = (1f - (_e1059 / (_e634 * _e634)));
                                        let _e1085 = ((select(0f, select(1f, _e1071, (_e1071 < 1f)), (_e1071 > 0f)) * select(0f, select(1f, _e1078, (_e1078 < 1f)), (_e1078 > 0f))) / _e919);
                                        phi_1563_ = select(0f, select(0f, select(1f, _e1085, (_e1085 < 1f)), (_e1085 > 0f)), (_e1059 > 0f));
                                    } else {
                                        let _e1096 = frame.member[0u].member_1.member.member_3;
                                        let _e1102 = (_e914 - select(_e1054, _e933, ((_e933 > _e1054) || (_e1054 != _e1054))));
                                        let _e1109 = ((_e1054 - (_e856.member_1.member_2 * (1f + _e1096))) * (1f / _e914));
                                        phi_1563_ = ((select(0f, _e1102, ((_e1102 > 0f) || false)) + (select(0f, select(1f, _e1109, (_e1109 < 1f)), (_e1109 > 0f)) * (_e914 - _e933))) * (0.5f / _e914));
                                    }
                                    let _e1120 = phi_1563_;
                                    let _e1125 = frame.member[0u].member_1.member_9;
                                    if (_e1125 == 0u) {
                                        phi_1833_ = type_41(_e1054, _e1120);
                                    } else {
                                        if _e897 {
                                            let _e1128 = (_e856.member_1.member_2 * 0.1f);
                                            phi_1592_ = select(_e1128, _e914, ((_e914 > _e1128) || (_e1128 != _e1128)));
                                        } else {
                                            let _e1138 = frame.member[0u].member_1.member.member_3;
                                            phi_1592_ = (_e856.member_1.member_2 * (1f + _e1138));
                                        }
                                        let _e1142 = phi_1592_;
                                        let _e1148 = frame.member[0u].member_1.member_3;
                                        let _e1150 = select(false, (sqrt(((_e1010 * _e1010) + (_e1011 * _e1011))) > _e1148), (_e1054 > _e1142));
                                        let _e1153 = depth2_.member[_e1017];
                                        let _e1157 = select(_e688, _e1153, select(false, (_e1153 < _e688), (_e1153 > 0f)));
                                        let _e1163 = (((_e1035 * _e1157) * _e658) - _e856.member_1.member_4.x);
                                        let _e1164 = (((_e1037 * _e1157) * _e666) - _e856.member_1.member_4.y);
                                        let _e1165 = (-(_e1157) - _e856.member_1.member_4.z);
                                        let _e1170 = (((_e1163 * _e856.member_1.member_6.x) + (_e1164 * _e856.member_1.member_6.y)) + (_e1165 * _e856.member_1.member_6.z));
                                        if _e897 {
                                            let _e1175 = (((_e1163 * _e1163) + (_e1164 * _e1164)) + (_e1165 * _e1165));
                                            let _e1187 = (((((_e856.member_1.member_5.x * _e1163) + (_e856.member_1.member_5.y * _e1164)) + (_e856.member_1.member_5.z * _e1165)) / sqrt(_e1175)) - 0.1f);
                                            let _e1194 = (1f - (_e1175 / (_e634 * _e634)));
                                            let _e1201 = ((select(0f, select(1f, _e1187, (_e1187 < 1f)), (_e1187 > 0f)) * select(0f, select(1f, _e1194, (_e1194 < 1f)), (_e1194 > 0f))) / _e919);
                                            phi_1795_ = select(0f, select(0f, select(1f, _e1201, (_e1201 < 1f)), (_e1201 > 0f)), (_e1175 > 0f));
                                        } else {
                                            let _e1212 = frame.member[0u].member_1.member.member_3;
                                            let _e1218 = (_e914 - select(_e1170, _e933, ((_e933 > _e1170) || (_e1170 != _e1170))));
                                            let _e1225 = ((_e1170 - (_e856.member_1.member_2 * (1f + _e1212))) * (1f / _e914));
                                            phi_1795_ = ((select(0f, _e1218, ((_e1218 > 0f) || false)) + (select(0f, select(1f, _e1225, (_e1225 < 1f)), (_e1225 > 0f)) * (_e914 - _e933))) * (0.5f / _e914));
                                        }
                                        let _e1236 = phi_1795_;
                                        if _e897 {
                                            phi_1827_ = select(_e1236, _e1120, ((_e1120 > _e1236) || (_e1236 != _e1236)));
                                        } else {
                                            phi_1827_ = select(_e1236, _e1120, ((_e1120 < _e1236) || (_e1236 != _e1236)));
                                        }
                                        let _e1251 = phi_1827_;
                                        phi_1833_ = type_41(select(_e1054, select(_e1170, _e1054, ((_e1054 < _e1170) || (_e1170 != _e1170))), _e1150), select(_e1120, _e1251, _e1150));
                                    }
                                    let _e1255 = phi_1833_;
                                    if select(false, select(false, (_e964 <= 1f), (_e964 >= 0f)), select(false, (_e961 <= 1f), (_e961 >= 0f))) {
                                        phi_1846_ = _e1255.member_1;
                                    } else {
                                        phi_1846_ = select(1f, 0f, _e897);
                                    }
                                    let _e1260 = phi_1846_;
                                    let _e1266 = frame.member[0u].member_1.member_5[0u];
                                    let _e1272 = frame.member[0u].member_1.member_5[1u];
                                    let _e1273 = f32(_e1266);
                                    let _e1274 = f32(_e1272);
                                    let _e1279 = frame.member[0u].member_1.member_4;
                                    let _e1280 = f32(_e1279);
                                    let _e1281 = (2u * _e1279);
                                    let _e1282 = (_e1266 + _e1281);
                                    let _e1288 = (floor((_e961 * _e1273)) + _e1280);
                                    let _e1289 = f32((_e1282 - 1u));
                                    let _e1293 = select(0f, select(_e1289, _e1288, (_e1288 < _e1289)), (_e1288 > 0f));
                                    let _e1296 = (floor((_e964 * _e1274)) + _e1280);
                                    let _e1297 = f32(((_e1272 + _e1281) - 1u));
                                    let _e1301 = select(0f, select(_e1297, _e1296, (_e1296 < _e1297)), (_e1296 > 0f));
                                    let _e1306 = select(select(u32(_e1293), 0u, (_e1293 < 0f)), 4294967295u, (_e1293 > 4294967000f));
                                    let _e1311 = select(select(u32(_e1301), 0u, (_e1301 < 0f)), 4294967295u, (_e1301 > 4294967000f));
                                    let _e1314 = bitcast<i32>(_e1279);
                                    let _e1323 = frame.member[0u].member_1.member_8;
                                    let _e1328 = frame.member[0u].member_1.member_12;
                                    let _e1335 = (((((_e1311 % 4u) * 4u) + (_e1306 % 4u)) + (_e1328 % 16u)) % 16u);
                                    if (_e1323 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1337 = (_e1335 < 16u);
                                        if _e1337 {
                                        } else {
                                            phi_2496_ = true;
                                            break;
                                        }
                                        let _e1340 = local[_e1335][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1337 {
                                        } else {
                                            phi_2496_ = true;
                                            break;
                                        }
                                        let _e1343 = local_1[_e1335][1u];
                                        phi_1980_ = vec2<f32>(_e1340, _e1343);
                                    } else {
                                        if (_e1323 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1346 = (_e1335 < 16u);
                                            if _e1346 {
                                            } else {
                                                phi_2496_ = true;
                                                break;
                                            }
                                            let _e1349 = local_2[_e1335][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1346 {
                                            } else {
                                                phi_2496_ = true;
                                                break;
                                            }
                                            let _e1352 = local_3[_e1335][1u];
                                            phi_1979_ = vec2<f32>(_e1349, _e1352);
                                        } else {
                                            phi_1979_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1355 = phi_1979_;
                                        phi_1980_ = _e1355;
                                    }
                                    let _e1357 = phi_1980_;
                                    let _e1370 = frame.member[0u].member_1.member_6;
                                    phi_2011_ = 0u;
                                    phi_2014_ = _e1260;
                                    loop {
                                        let _e1373 = phi_2011_;
                                        let _e1375 = phi_2014_;
                                        local_11 = _e1375;
                                        let _e1376 = (_e1373 < _e1370);
                                        if _e1376 {
                                            let _e1377 = ((((_e1311 * _e1282) + _e1306) * _e1370) + _e1373);
                                            if (_e1377 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2392_ = true;
                                                break;
                                            }
                                            let _e1380 = sd_map.member[_e1377];
                                            let _e1387 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1390 = ((_e1380 * (_e688 - _e1387)) + _e1387);
                                            let _e1400 = (((((((f32((bitcast<i32>(_e1306) - _e1314)) + _e1357.x) / _e1273) * 2f) - 1f) * _e1390) * _e658) - _e856.member_1.member_4.x);
                                            let _e1401 = (((((((f32((bitcast<i32>(_e1311) - _e1314)) + _e1357.y) / _e1274) * -2f) + 1f) * _e1390) * _e666) - _e856.member_1.member_4.y);
                                            let _e1402 = (-(_e1390) - _e856.member_1.member_4.z);
                                            let _e1407 = (((_e1400 * _e856.member_1.member_6.x) + (_e1401 * _e856.member_1.member_6.y)) + (_e1402 * _e856.member_1.member_6.z));
                                            if _e897 {
                                                let _e1412 = (((_e1400 * _e1400) + (_e1401 * _e1401)) + (_e1402 * _e1402));
                                                let _e1424 = (((((_e856.member_1.member_5.x * _e1400) + (_e856.member_1.member_5.y * _e1401)) + (_e856.member_1.member_5.z * _e1402)) / sqrt(_e1412)) - 0.1f);
                                                let _e1431 = (1f - (_e1412 / (_e634 * _e634)));
                                                let _e1438 = ((select(0f, select(1f, _e1424, (_e1424 < 1f)), (_e1424 > 0f)) * select(0f, select(1f, _e1431, (_e1431 < 1f)), (_e1431 > 0f))) / _e919);
                                                phi_2191_ = select(0f, select(0f, select(1f, _e1438, (_e1438 < 1f)), (_e1438 > 0f)), (_e1412 > 0f));
                                            } else {
                                                let _e1449 = frame.member[0u].member_1.member.member_3;
                                                let _e1455 = (_e914 - select(_e1407, _e933, ((_e933 > _e1407) || (_e1407 != _e1407))));
                                                let _e1462 = ((_e1407 - (_e856.member_1.member_2 * (1f + _e1449))) * (1f / _e914));
                                                phi_2191_ = ((select(0f, _e1455, ((_e1455 > 0f) || false)) + (select(0f, select(1f, _e1462, (_e1462 < 1f)), (_e1462 > 0f)) * (_e914 - _e933))) * (0.5f / _e914));
                                            }
                                            let _e1473 = phi_2191_;
                                            if _e897 {
                                                phi_2212_ = select(_e1473, _e1375, ((_e1375 > _e1473) || (_e1473 != _e1473)));
                                            } else {
                                                phi_2212_ = select(_e1473, _e1375, ((_e1375 < _e1473) || (_e1473 != _e1473)));
                                            }
                                            let _e1483 = phi_2212_;
                                            phi_2012_ = (_e1373 + 1u);
                                            phi_2015_ = _e1483;
                                        } else {
                                            phi_2012_ = u32();
                                            phi_2015_ = f32();
                                        }
                                        let _e1486 = phi_2012_;
                                        let _e1488 = phi_2015_;
                                        continue;
                                        continuing {
                                            phi_2011_ = _e1486;
                                            phi_2014_ = _e1488;
                                            phi_2392_ = _e872;
                                            break if !(_e1376);
                                        }
                                    }
                                    let _e1491 = phi_2392_;
                                    phi_2496_ = _e1491;
                                    if _e1491 {
                                        break;
                                    }
                                    let _e1493 = local_11;
                                    phi_2498_ = _e1491;
                                    phi_2217_ = ((_e878 - _e1255.member_1) + _e1493);
                                }
                                let _e1496 = phi_2498_;
                                let _e1498 = phi_2217_;
                                phi_2497_ = _e1496;
                                phi_1098_ = (_e874 + 1u);
                                phi_1103_ = _e1498;
                            } else {
                                phi_2497_ = _e872;
                                phi_1098_ = u32();
                                phi_1103_ = f32();
                            }
                            let _e1501 = phi_2497_;
                            let _e1503 = phi_1098_;
                            let _e1505 = phi_1103_;
                            continue;
                            continuing {
                                phi_2439_ = _e1501;
                                phi_1097_ = _e1503;
                                phi_1100_ = select(u32(), _e876, _e879);
                                phi_1102_ = _e1505;
                                phi_2496_ = _e1501;
                                break if !(_e879);
                            }
                        }
                        let _e1509 = phi_2496_;
                        if _e1509 {
                            break;
                        }
                        let _e1514 = frame.member[0u].member_1.member_10;
                        let _e1515 = (_e1514 == 1u);
                        let _e1520 = local_12;
                        let _e1522 = (_e622 + ((select(2f, 1f, _e1515) / f32(_e870)) * _e1520));
                        if _e1515 {
                            phi_2247_ = (1f - (2f * _e1522));
                        } else {
                            phi_2247_ = _e1522;
                        }
                        let _e1526 = phi_2247_;
                        let _e1536 = frame.member[0u].member_1.member.member_2;
                        let _e1539 = local_13;
                        phi_2262_ = type_42(pow(select(0f, select(1f, _e1526, (_e1526 < 1f)), (_e1526 > 0f)), _e1536), _e1539);
                    } else {
                        phi_2262_ = type_42();
                    }
                    let _e1542 = phi_2262_;
                    phi_2264_ = _e1542;
                    phi_2265_ = select(true, false, _e859);
                }
                let _e1545 = phi_2264_;
                let _e1547 = phi_2265_;
                if _e1547 {
                    phi_2269_ = type_42(_e622, 0u);
                } else {
                    phi_2269_ = _e1545;
                }
                let _e1549 = phi_2269_;
                if _e619 {
                } else {
                    break;
                }
                ao.member[_e618] = _e1549.member;
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
