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
    var phi_680_: bool;
    var phi_682_: bool;
    var phi_683_: bool;
    var phi_684_: bool;
    var phi_685_: bool;
    var phi_1049_: type_31;
    var phi_2298_: bool;
    var phi_1067_: u32;
    var phi_1070_: u32;
    var phi_1072_: f32;
    var phi_1120_: f32;
    var phi_1145_: f32;
    var phi_1158_: f32;
    var phi_1533_: f32;
    var phi_1562_: f32;
    var phi_1765_: f32;
    var phi_1797_: f32;
    var phi_1803_: type_41;
    var phi_1816_: f32;
    var phi_1936_: vec2<f32>;
    var phi_1937_: vec2<f32>;
    var phi_1977_: u32;
    var phi_1980_: f32;
    var phi_2157_: f32;
    var phi_2178_: f32;
    var phi_1978_: u32;
    var phi_1981_: f32;
    var phi_2251_: bool;
    var local_11: f32;
    var phi_2358_: bool;
    var phi_2183_: f32;
    var phi_2357_: bool;
    var phi_1068_: u32;
    var phi_1073_: f32;
    var phi_2356_: bool;
    var local_12: f32;
    var phi_2213_: f32;
    var local_13: u32;
    var phi_2228_: type_42;
    var phi_2230_: type_42;
    var phi_2231_: bool;
    var phi_2235_: type_42;

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
                        phi_680_ = ((_e572 + _e570) < _e598);
                    } else {
                        phi_680_ = bool();
                    }
                    let _e606 = phi_680_;
                    phi_682_ = _e606;
                    phi_683_ = select(true, false, _e602);
                } else {
                    phi_682_ = bool();
                    phi_683_ = true;
                }
                let _e609 = phi_682_;
                let _e611 = phi_683_;
                phi_684_ = _e609;
                phi_685_ = _e611;
            } else {
                phi_684_ = bool();
                phi_685_ = true;
            }
            let _e613 = phi_684_;
            let _e615 = phi_685_;
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
                    phi_2230_ = type_42();
                    phi_2231_ = true;
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
                    let _e709 = f32(bitcast<i32>((_e706 & 255u)));
                    let _e713 = (select(_e709, (_e709 - 256f), (_e709 >= 128f)) * 0.007874016f);
                    let _e716 = select(-1f, _e713, ((_e713 > -1f) || false));
                    let _e721 = f32(bitcast<i32>(((_e706 >> bitcast<u32>(8u)) & 255u)));
                    let _e725 = (select(_e721, (_e721 - 256f), (_e721 >= 128f)) * 0.007874016f);
                    let _e728 = select(-1f, _e725, ((_e725 > -1f) || false));
                    let _e730 = (1f - abs(_e716));
                    let _e731 = abs(_e728);
                    let _e732 = (_e730 - _e731);
                    let _e733 = (_e732 < 0f);
                    let _e741 = select(_e716, ((1f - _e731) * select(1f, -1f, (_e716 < 0f))), _e733);
                    let _e742 = select(_e728, (_e730 * select(1f, -1f, (_e728 < 0f))), _e733);
                    let _e749 = (1f / sqrt((((_e741 * _e741) + (_e742 * _e742)) + (_e732 * _e732))));
                    let _e750 = (_e741 * _e749);
                    let _e751 = (_e742 * _e749);
                    let _e752 = (_e732 * _e749);
                    let _e758 = ((((_e700 * _e750) + (_e702 * _e751)) + (_e703 * _e752)) > 0f);
                    let _e762 = select(_e750, -(_e750), _e758);
                    let _e763 = select(_e751, -(_e751), _e758);
                    let _e764 = select(_e752, -(_e752), _e758);
                    local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                    let _e766 = (_e572 % 4u);
                    if (_e766 < 4u) {
                    } else {
                        break;
                    }
                    let _e768 = (_e571 % 4u);
                    if (_e768 < 4u) {
                    } else {
                        break;
                    }
                    let _e772 = local_10[_e766][_e768];
                    let _e782 = sqrt((((_e700 * _e700) + (_e702 * _e702)) + (_e703 * _e703)));
                    let _e783 = (-(_e700) / _e782);
                    let _e784 = (-(_e702) / _e782);
                    let _e785 = (_e650 / _e782);
                    let _e788 = -((_e772[1] * _e785));
                    let _e789 = (_e785 * _e772[0]);
                    let _e792 = ((_e783 * _e772[1]) - (_e772[0] * _e784));
                    let _e799 = (1f / sqrt((((_e788 * _e788) + (_e789 * _e789)) + (_e792 * _e792))));
                    let _e800 = (_e788 * _e799);
                    let _e801 = (_e789 * _e799);
                    let _e802 = (_e792 * _e799);
                    let _e806 = ((_e801 * _e785) - (_e784 * _e802));
                    let _e809 = ((_e802 * _e783) - (_e785 * _e800));
                    let _e812 = ((_e800 * _e784) - (_e783 * _e801));
                    let _e828 = (((_e762 * _e783) + (_e763 * _e784)) + (_e764 * _e785));
                    let _e832 = abs(_e828);
                    if select(false, !((_e681 < 0.5f)), select(false, (_e650 < _e688), (_e650 > 0f))) {
                        phi_1049_ = type_31(1u, type_30(vec2<u32>(_e571, _e572), vec2<f32>(_e644, _e648), select(_e634, ((_e634 * _e640) / _e676), _e677), _e681, vec3<f32>(_e700, _e702, _e703), vec3<f32>(_e762, _e763, _e764), vec3<f32>(_e783, _e784, _e785), vec3<f32>(_e806, _e809, _e812), vec3<f32>(_e800, _e801, _e802), vec3<f32>((((_e762 * _e806) + (_e763 * _e809)) + (_e764 * _e812)), (((_e762 * _e800) + (_e763 * _e801)) + (_e764 * _e802)), _e828), (1f / (select(1f, -1f, (_e828 < 0f)) * select(0.0001f, _e832, ((_e832 > 0.0001f) || false))))));
                    } else {
                        phi_1049_ = type_31(0u, type_31().member_1);
                    }
                    let _e846 = phi_1049_;
                    let _e849 = (bitcast<i32>(_e846.member) != 0i);
                    if _e849 {
                        let _e855 = frame.member[0u].member_1.member_11;
                        let _e860 = (8u << bitcast<u32>((select(_e855, 2u, (2u < _e855)) & 31u)));
                        phi_2298_ = false;
                        phi_1067_ = 0u;
                        phi_1070_ = 0u;
                        phi_1072_ = 0f;
                        loop {
                            let _e862 = phi_2298_;
                            let _e864 = phi_1067_;
                            let _e866 = phi_1070_;
                            let _e868 = phi_1072_;
                            local_12 = _e868;
                            local_13 = _e866;
                            let _e869 = (_e864 < _e860);
                            if _e869 {
                                if ((_e626 & (1u << bitcast<u32>((_e864 & 31u)))) == 0u) {
                                    phi_2358_ = _e862;
                                    phi_2183_ = _e868;
                                } else {
                                    let _e879 = frame.member[0u].member_1.member_10;
                                    let _e881 = ((_e860 + _e864) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e882 = (_e881 < 56u);
                                    if _e882 {
                                    } else {
                                        phi_2356_ = true;
                                        break;
                                    }
                                    let _e884 = local_4[_e881];
                                    let _e887 = (_e879 == 1u);
                                    if _e887 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e882 {
                                        } else {
                                            phi_2356_ = true;
                                            break;
                                        }
                                        let _e889 = local_5[_e881];
                                        phi_1120_ = _e889;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e882 {
                                        } else {
                                            phi_2356_ = true;
                                            break;
                                        }
                                        let _e891 = local_6[_e881];
                                        phi_1120_ = _e891;
                                    }
                                    let _e893 = phi_1120_;
                                    let _e895 = (_e846.member_1.member_2 * _e893);
                                    let _e896 = (_e895 * _e884[0]);
                                    let _e897 = (_e895 * _e884[1]);
                                    if _e887 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e882 {
                                        } else {
                                            phi_2356_ = true;
                                            break;
                                        }
                                        let _e899 = local_7[_e881];
                                        phi_1145_ = _e899;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e882 {
                                        } else {
                                            phi_2356_ = true;
                                            break;
                                        }
                                        let _e901 = local_8[_e881];
                                        phi_1145_ = _e901;
                                    }
                                    let _e903 = phi_1145_;
                                    let _e904 = (_e846.member_1.member_2 * _e903);
                                    if _e887 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e882 {
                                        } else {
                                            phi_2356_ = true;
                                            break;
                                        }
                                        let _e906 = local_9[_e881];
                                        phi_1158_ = _e906;
                                    } else {
                                        phi_1158_ = (_e904 * 2f);
                                    }
                                    let _e909 = phi_1158_;
                                    let _e918 = (-(((_e896 * _e846.member_1.member_9.x) + (_e897 * _e846.member_1.member_9.y))) * _e846.member_1.member_10);
                                    let _e919 = -(_e904);
                                    let _e923 = select(_e919, select(_e904, _e918, (_e918 < _e904)), (_e918 > _e919));
                                    let _e948 = (-0.5f / ((_e846.member_1.member_4.z + (_e846.member_1.member_7.z * _e896)) + (_e846.member_1.member_8.z * _e897)));
                                    let _e951 = (((((_e846.member_1.member_4.x + (_e846.member_1.member_7.x * _e896)) + (_e846.member_1.member_8.x * _e897)) * _e948) / _e658) + 0.5f);
                                    let _e954 = (0.5f - ((((_e846.member_1.member_4.y + (_e846.member_1.member_7.y * _e896)) + (_e846.member_1.member_8.y * _e897)) * _e948) / _e666));
                                    let _e966 = (select(0f, select(1f, _e951, (_e951 < 1f)), (_e951 > 0f)) * _e580);
                                    let _e969 = f32(bitcast<i32>((_e585 - 1u)));
                                    let _e977 = (bitcast<u32>((floor(select(0f, select(_e969, _e966, (_e966 < _e969)), (_e966 > 0f))) + 8388608f)) - 1258291200u);
                                    let _e982 = (select(0f, select(1f, _e954, (_e954 < 1f)), (_e954 > 0f)) * _e593);
                                    let _e985 = f32(bitcast<i32>((_e598 - 1u)));
                                    let _e993 = (bitcast<u32>((floor(select(0f, select(_e985, _e982, (_e982 < _e985)), (_e982 > 0f))) + 8388608f)) - 1258291200u);
                                    let _e1000 = ((_e846.member_1.member_1.x - _e951) * _e580);
                                    let _e1001 = ((_e846.member_1.member_1.y - _e954) * _e593);
                                    let _e1007 = ((_e993 * _e585) + _e977);
                                    let _e1009 = depth.member[_e1007];
                                    let _e1023 = select(_e688, _e1009, select(false, (_e1009 < _e688), (_e1009 > 0f)));
                                    let _e1025 = ((((f32(bitcast<i32>(_e977)) + 0.5f) * (1f / _e580)) * 2f) - 1f);
                                    let _e1027 = ((((f32(bitcast<i32>(_e993)) + 0.5f) * (1f / _e593)) * -2f) + 1f);
                                    let _e1033 = (((_e1025 * _e1023) * _e658) - _e846.member_1.member_4.x);
                                    let _e1034 = (((_e1027 * _e1023) * _e666) - _e846.member_1.member_4.y);
                                    let _e1035 = (-(_e1023) - _e846.member_1.member_4.z);
                                    let _e1044 = (((_e1033 * _e846.member_1.member_6.x) + (_e1034 * _e846.member_1.member_6.y)) + (_e1035 * _e846.member_1.member_6.z));
                                    if _e887 {
                                        let _e1049 = (((_e1033 * _e1033) + (_e1034 * _e1034)) + (_e1035 * _e1035));
                                        let _e1061 = (((((_e846.member_1.member_5.x * _e1033) + (_e846.member_1.member_5.y * _e1034)) + (_e846.member_1.member_5.z * _e1035)) / sqrt(_e1049)) - 0.1f);
                                        let _e1068 = (1f - (_e1049 / (_e634 * _e634)));
                                        let _e1075 = ((select(0f, select(1f, _e1061, (_e1061 < 1f)), (_e1061 > 0f)) * select(0f, select(1f, _e1068, (_e1068 < 1f)), (_e1068 > 0f))) / _e909);
                                        phi_1533_ = select(0f, select(0f, select(1f, _e1075, (_e1075 < 1f)), (_e1075 > 0f)), (_e1049 > 0f));
                                    } else {
                                        let _e1086 = frame.member[0u].member_1.member.member_3;
                                        let _e1092 = (_e904 - select(_e1044, _e923, ((_e923 > _e1044) || (_e1044 != _e1044))));
                                        let _e1099 = ((_e1044 - (_e846.member_1.member_2 * (1f + _e1086))) * (1f / _e904));
                                        phi_1533_ = ((select(0f, _e1092, ((_e1092 > 0f) || false)) + (select(0f, select(1f, _e1099, (_e1099 < 1f)), (_e1099 > 0f)) * (_e904 - _e923))) * (0.5f / _e904));
                                    }
                                    let _e1110 = phi_1533_;
                                    let _e1115 = frame.member[0u].member_1.member_9;
                                    if (_e1115 == 0u) {
                                        phi_1803_ = type_41(_e1044, _e1110);
                                    } else {
                                        if _e887 {
                                            let _e1118 = (_e846.member_1.member_2 * 0.1f);
                                            phi_1562_ = select(_e1118, _e904, ((_e904 > _e1118) || (_e1118 != _e1118)));
                                        } else {
                                            let _e1128 = frame.member[0u].member_1.member.member_3;
                                            phi_1562_ = (_e846.member_1.member_2 * (1f + _e1128));
                                        }
                                        let _e1132 = phi_1562_;
                                        let _e1138 = frame.member[0u].member_1.member_3;
                                        let _e1140 = select(false, (sqrt(((_e1000 * _e1000) + (_e1001 * _e1001))) > _e1138), (_e1044 > _e1132));
                                        let _e1143 = depth2_.member[_e1007];
                                        let _e1147 = select(_e688, _e1143, select(false, (_e1143 < _e688), (_e1143 > 0f)));
                                        let _e1153 = (((_e1025 * _e1147) * _e658) - _e846.member_1.member_4.x);
                                        let _e1154 = (((_e1027 * _e1147) * _e666) - _e846.member_1.member_4.y);
                                        let _e1155 = (-(_e1147) - _e846.member_1.member_4.z);
                                        let _e1160 = (((_e1153 * _e846.member_1.member_6.x) + (_e1154 * _e846.member_1.member_6.y)) + (_e1155 * _e846.member_1.member_6.z));
                                        if _e887 {
                                            let _e1165 = (((_e1153 * _e1153) + (_e1154 * _e1154)) + (_e1155 * _e1155));
                                            let _e1177 = (((((_e846.member_1.member_5.x * _e1153) + (_e846.member_1.member_5.y * _e1154)) + (_e846.member_1.member_5.z * _e1155)) / sqrt(_e1165)) - 0.1f);
                                            let _e1184 = (1f - (_e1165 / (_e634 * _e634)));
                                            let _e1191 = ((select(0f, select(1f, _e1177, (_e1177 < 1f)), (_e1177 > 0f)) * select(0f, select(1f, _e1184, (_e1184 < 1f)), (_e1184 > 0f))) / _e909);
                                            phi_1765_ = select(0f, select(0f, select(1f, _e1191, (_e1191 < 1f)), (_e1191 > 0f)), (_e1165 > 0f));
                                        } else {
                                            let _e1202 = frame.member[0u].member_1.member.member_3;
                                            let _e1208 = (_e904 - select(_e1160, _e923, ((_e923 > _e1160) || (_e1160 != _e1160))));
                                            let _e1215 = ((_e1160 - (_e846.member_1.member_2 * (1f + _e1202))) * (1f / _e904));
                                            phi_1765_ = ((select(0f, _e1208, ((_e1208 > 0f) || false)) + (select(0f, select(1f, _e1215, (_e1215 < 1f)), (_e1215 > 0f)) * (_e904 - _e923))) * (0.5f / _e904));
                                        }
                                        let _e1226 = phi_1765_;
                                        if _e887 {
                                            phi_1797_ = select(_e1226, _e1110, ((_e1110 > _e1226) || (_e1226 != _e1226)));
                                        } else {
                                            phi_1797_ = select(_e1226, _e1110, ((_e1110 < _e1226) || (_e1226 != _e1226)));
                                        }
                                        let _e1241 = phi_1797_;
                                        phi_1803_ = type_41(select(_e1044, select(_e1160, _e1044, ((_e1044 < _e1160) || (_e1160 != _e1160))), _e1140), select(_e1110, _e1241, _e1140));
                                    }
                                    let _e1245 = phi_1803_;
                                    if select(false, select(false, (_e954 <= 1f), (_e954 >= 0f)), select(false, (_e951 <= 1f), (_e951 >= 0f))) {
                                        phi_1816_ = _e1245.member_1;
                                    } else {
                                        phi_1816_ = select(1f, 0f, _e887);
                                    }
                                    let _e1250 = phi_1816_;
                                    let _e1256 = frame.member[0u].member_1.member_5[0u];
                                    let _e1262 = frame.member[0u].member_1.member_5[1u];
                                    let _e1263 = f32(_e1256);
                                    let _e1264 = f32(_e1262);
                                    let _e1269 = frame.member[0u].member_1.member_4;
                                    let _e1270 = f32(_e1269);
                                    let _e1271 = (2u * _e1269);
                                    let _e1272 = (_e1256 + _e1271);
                                    let _e1276 = (floor((_e951 * _e1263)) + _e1270);
                                    let _e1279 = f32(bitcast<i32>((_e1272 - 1u)));
                                    let _e1287 = (bitcast<u32>((floor(select(0f, select(_e1279, _e1276, (_e1276 < _e1279)), (_e1276 > 0f))) + 8388608f)) - 1258291200u);
                                    let _e1290 = (floor((_e954 * _e1264)) + _e1270);
                                    let _e1293 = f32(bitcast<i32>(((_e1262 + _e1271) - 1u)));
                                    let _e1301 = (bitcast<u32>((floor(select(0f, select(_e1293, _e1290, (_e1290 < _e1293)), (_e1290 > 0f))) + 8388608f)) - 1258291200u);
                                    let _e1306 = frame.member[0u].member_1.member_8;
                                    let _e1311 = frame.member[0u].member_1.member_12;
                                    let _e1318 = (((((_e1301 % 4u) * 4u) + (_e1287 % 4u)) + (_e1311 % 16u)) % 16u);
                                    if (_e1306 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1320 = (_e1318 < 16u);
                                        if _e1320 {
                                        } else {
                                            phi_2356_ = true;
                                            break;
                                        }
                                        let _e1323 = local[_e1318][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1320 {
                                        } else {
                                            phi_2356_ = true;
                                            break;
                                        }
                                        let _e1326 = local_1[_e1318][1u];
                                        phi_1937_ = vec2<f32>(_e1323, _e1326);
                                    } else {
                                        if (_e1306 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1329 = (_e1318 < 16u);
                                            if _e1329 {
                                            } else {
                                                phi_2356_ = true;
                                                break;
                                            }
                                            let _e1332 = local_2[_e1318][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1329 {
                                            } else {
                                                phi_2356_ = true;
                                                break;
                                            }
                                            let _e1335 = local_3[_e1318][1u];
                                            phi_1936_ = vec2<f32>(_e1332, _e1335);
                                        } else {
                                            phi_1936_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1338 = phi_1936_;
                                        phi_1937_ = _e1338;
                                    }
                                    let _e1340 = phi_1937_;
                                    let _e1359 = frame.member[0u].member_1.member_6;
                                    phi_1977_ = 0u;
                                    phi_1980_ = _e1250;
                                    loop {
                                        let _e1362 = phi_1977_;
                                        let _e1364 = phi_1980_;
                                        local_11 = _e1364;
                                        let _e1365 = (_e1362 < _e1359);
                                        if _e1365 {
                                            let _e1366 = ((((_e1301 * _e1272) + _e1287) * _e1359) + _e1362);
                                            if (_e1366 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2251_ = true;
                                                break;
                                            }
                                            let _e1369 = sd_map.member[_e1366];
                                            let _e1376 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1379 = ((_e1369 * (_e688 - _e1376)) + _e1376);
                                            let _e1389 = ((((((((f32(bitcast<i32>(_e1287)) - _e1270) + _e1340.x) / _e1263) * 2f) - 1f) * _e1379) * _e658) - _e846.member_1.member_4.x);
                                            let _e1390 = ((((((((f32(bitcast<i32>(_e1301)) - _e1270) + _e1340.y) / _e1264) * -2f) + 1f) * _e1379) * _e666) - _e846.member_1.member_4.y);
                                            let _e1391 = (-(_e1379) - _e846.member_1.member_4.z);
                                            let _e1396 = (((_e1389 * _e846.member_1.member_6.x) + (_e1390 * _e846.member_1.member_6.y)) + (_e1391 * _e846.member_1.member_6.z));
                                            if _e887 {
                                                let _e1401 = (((_e1389 * _e1389) + (_e1390 * _e1390)) + (_e1391 * _e1391));
                                                let _e1413 = (((((_e846.member_1.member_5.x * _e1389) + (_e846.member_1.member_5.y * _e1390)) + (_e846.member_1.member_5.z * _e1391)) / sqrt(_e1401)) - 0.1f);
                                                let _e1420 = (1f - (_e1401 / (_e634 * _e634)));
                                                let _e1427 = ((select(0f, select(1f, _e1413, (_e1413 < 1f)), (_e1413 > 0f)) * select(0f, select(1f, _e1420, (_e1420 < 1f)), (_e1420 > 0f))) / _e909);
                                                phi_2157_ = select(0f, select(0f, select(1f, _e1427, (_e1427 < 1f)), (_e1427 > 0f)), (_e1401 > 0f));
                                            } else {
                                                let _e1438 = frame.member[0u].member_1.member.member_3;
                                                let _e1444 = (_e904 - select(_e1396, _e923, ((_e923 > _e1396) || (_e1396 != _e1396))));
                                                let _e1451 = ((_e1396 - (_e846.member_1.member_2 * (1f + _e1438))) * (1f / _e904));
                                                phi_2157_ = ((select(0f, _e1444, ((_e1444 > 0f) || false)) + (select(0f, select(1f, _e1451, (_e1451 < 1f)), (_e1451 > 0f)) * (_e904 - _e923))) * (0.5f / _e904));
                                            }
                                            let _e1462 = phi_2157_;
                                            if _e887 {
                                                phi_2178_ = select(_e1462, _e1364, ((_e1364 > _e1462) || (_e1462 != _e1462)));
                                            } else {
                                                phi_2178_ = select(_e1462, _e1364, ((_e1364 < _e1462) || (_e1462 != _e1462)));
                                            }
                                            let _e1472 = phi_2178_;
                                            phi_1978_ = (_e1362 + 1u);
                                            phi_1981_ = _e1472;
                                        } else {
                                            phi_1978_ = u32();
                                            phi_1981_ = f32();
                                        }
                                        let _e1475 = phi_1978_;
                                        let _e1477 = phi_1981_;
                                        continue;
                                        continuing {
                                            phi_1977_ = _e1475;
                                            phi_1980_ = _e1477;
                                            phi_2251_ = _e862;
                                            break if !(_e1365);
                                        }
                                    }
                                    let _e1480 = phi_2251_;
                                    phi_2356_ = _e1480;
                                    if _e1480 {
                                        break;
                                    }
                                    let _e1482 = local_11;
                                    phi_2358_ = _e1480;
                                    phi_2183_ = ((_e868 - _e1245.member_1) + _e1482);
                                }
                                let _e1485 = phi_2358_;
                                let _e1487 = phi_2183_;
                                phi_2357_ = _e1485;
                                phi_1068_ = (_e864 + 1u);
                                phi_1073_ = _e1487;
                            } else {
                                phi_2357_ = _e862;
                                phi_1068_ = u32();
                                phi_1073_ = f32();
                            }
                            let _e1490 = phi_2357_;
                            let _e1492 = phi_1068_;
                            let _e1494 = phi_1073_;
                            continue;
                            continuing {
                                phi_2298_ = _e1490;
                                phi_1067_ = _e1492;
                                phi_1070_ = select(u32(), _e866, _e869);
                                phi_1072_ = _e1494;
                                phi_2356_ = _e1490;
                                break if !(_e869);
                            }
                        }
                        let _e1498 = phi_2356_;
                        if _e1498 {
                            break;
                        }
                        let _e1503 = frame.member[0u].member_1.member_10;
                        let _e1504 = (_e1503 == 1u);
                        let _e1509 = local_12;
                        let _e1511 = (_e622 + ((select(2f, 1f, _e1504) / f32(_e860)) * _e1509));
                        if _e1504 {
                            phi_2213_ = (1f - (2f * _e1511));
                        } else {
                            phi_2213_ = _e1511;
                        }
                        let _e1515 = phi_2213_;
                        let _e1525 = frame.member[0u].member_1.member.member_2;
                        let _e1528 = local_13;
                        phi_2228_ = type_42(pow(select(0f, select(1f, _e1515, (_e1515 < 1f)), (_e1515 > 0f)), _e1525), _e1528);
                    } else {
                        phi_2228_ = type_42();
                    }
                    let _e1531 = phi_2228_;
                    phi_2230_ = _e1531;
                    phi_2231_ = select(true, false, _e849);
                }
                let _e1534 = phi_2230_;
                let _e1536 = phi_2231_;
                if _e1536 {
                    phi_2235_ = type_42(_e622, 0u);
                } else {
                    phi_2235_ = _e1534;
                }
                let _e1538 = phi_2235_;
                if _e619 {
                } else {
                    break;
                }
                ao.member[_e618] = _e1538.member;
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
