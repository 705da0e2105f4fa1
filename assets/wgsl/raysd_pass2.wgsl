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
    var phi_791_: bool;
    var phi_793_: bool;
    var phi_794_: bool;
    var phi_795_: bool;
    var phi_796_: bool;
    var phi_2320_: bool;
    var phi_2335_: bool;
    var phi_2296_: vec2<f32>;
    var phi_2350_: bool;
    var phi_1099_: type_31;
    var phi_2592_: bool;
    var phi_1117_: u32;
    var phi_1120_: u32;
    var phi_1122_: f32;
    var phi_1170_: f32;
    var phi_1195_: f32;
    var phi_1208_: f32;
    var phi_1336_: u32;
    var phi_1367_: u32;
    var phi_2365_: bool;
    var phi_2380_: bool;
    var phi_1577_: f32;
    var phi_2395_: bool;
    var phi_1600_: f32;
    var phi_2410_: bool;
    var phi_2425_: bool;
    var phi_1794_: f32;
    var phi_2440_: bool;
    var phi_2455_: bool;
    var phi_2470_: bool;
    var phi_1808_: f32;
    var phi_1814_: type_41;
    var phi_1827_: f32;
    var phi_1960_: vec2<f32>;
    var phi_1961_: vec2<f32>;
    var phi_1992_: u32;
    var phi_1995_: f32;
    var phi_2485_: bool;
    var phi_2500_: bool;
    var phi_2160_: f32;
    var phi_2515_: bool;
    var phi_2530_: bool;
    var phi_2169_: f32;
    var phi_1993_: u32;
    var phi_1996_: f32;
    var phi_2544_: bool;
    var local_11: f32;
    var phi_2663_: bool;
    var phi_2174_: f32;
    var phi_2662_: bool;
    var phi_1118_: u32;
    var phi_1123_: f32;
    var phi_2661_: bool;
    var local_12: f32;
    var phi_2204_: f32;
    var local_13: u32;
    var phi_2219_: type_42;
    var phi_2221_: type_42;
    var phi_2222_: bool;
    var phi_2226_: type_42;

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
                        phi_791_ = ((_e576 + _e574) < _e602);
                    } else {
                        phi_791_ = bool();
                    }
                    let _e610 = phi_791_;
                    phi_793_ = _e610;
                    phi_794_ = select(true, false, _e606);
                } else {
                    phi_793_ = bool();
                    phi_794_ = true;
                }
                let _e613 = phi_793_;
                let _e615 = phi_794_;
                phi_795_ = _e613;
                phi_796_ = _e615;
            } else {
                phi_795_ = bool();
                phi_796_ = true;
            }
            let _e617 = phi_795_;
            let _e619 = phi_796_;
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
                    phi_2221_ = type_42();
                    phi_2222_ = true;
                } else {
                    let _e638 = frame.member[0u].member_1.member.member_1;
                    let _e644 = frame.member[0u].member_1.member.member_4;
                    let _e647 = ((f32(_e575) + 0.5f) / _e584);
                    let _e650 = ((f32(_e576) + 0.5f) / _e597);
                    if (_e622 < _e552) {
                    } else {
                        break;
                    }
                    let _e653 = depth.member[_e622];
                    let _e661 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e669 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e679 = ((((_e638 * _e584) / (_e653 * (2f * _e661))) + ((_e638 * _e597) / (_e653 * (2f * _e669)))) * 0.5f);
                    let _e680 = (_e679 > _e644);
                    let _e684 = select(_e679, _e644, _e680);
                    let _e691 = frame.member[0u].member_1.member.member.member_3;
                    let _e703 = ((((_e647 * 2f) - 1f) * _e653) * _e661);
                    let _e705 = ((((_e650 * -2f) + 1f) * _e653) * _e669);
                    let _e706 = -(_e653);
                    if (_e622 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e710 = normals.member[_e622];
                    let _e718 = (f32((bitcast<i32>(((_e710 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e718 != _e718) {
                        phi_2320_ = true;
                    } else {
                        phi_2320_ = (-1f >= _e718);
                    }
                    let _e722 = phi_2320_;
                    let _e723 = select(_e718, -1f, _e722);
                    let _e733 = (f32((bitcast<i32>((((_e710 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e733 != _e733) {
                        phi_2335_ = true;
                    } else {
                        phi_2335_ = (-1f >= _e733);
                    }
                    let _e737 = phi_2335_;
                    let _e738 = select(_e733, -1f, _e737);
                    let _e741 = (1f - abs(_e723));
                    let _e742 = abs(_e738);
                    let _e743 = (_e741 - _e742);
                    if (_e743 < 0f) {
                        phi_2296_ = vec2<f32>(((1f - _e742) * select(1f, -1f, (_e723 < 0f))), (_e741 * select(1f, -1f, (_e738 < 0f))));
                    } else {
                        phi_2296_ = vec2<f32>(_e723, _e738);
                    }
                    let _e754 = phi_2296_;
                    let _e763 = (1f / sqrt((((_e754.x * _e754.x) + (_e754.y * _e754.y)) + (_e743 * _e743))));
                    let _e764 = (_e754.x * _e763);
                    let _e765 = (_e754.y * _e763);
                    let _e766 = (_e743 * _e763);
                    let _e772 = ((((_e703 * _e764) + (_e705 * _e765)) + (_e706 * _e766)) > 0f);
                    let _e776 = select(_e764, -(_e764), _e772);
                    let _e777 = select(_e765, -(_e765), _e772);
                    let _e778 = select(_e766, -(_e766), _e772);
                    local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                    let _e780 = (_e576 % 4u);
                    if (_e780 < 4u) {
                    } else {
                        break;
                    }
                    let _e782 = (_e575 % 4u);
                    if (_e782 < 4u) {
                    } else {
                        break;
                    }
                    let _e786 = local_10[_e780][_e782];
                    let _e796 = sqrt((((_e703 * _e703) + (_e705 * _e705)) + (_e706 * _e706)));
                    let _e797 = (-(_e703) / _e796);
                    let _e798 = (-(_e705) / _e796);
                    let _e799 = (_e653 / _e796);
                    let _e802 = -((_e786[1] * _e799));
                    let _e803 = (_e799 * _e786[0]);
                    let _e806 = ((_e797 * _e786[1]) - (_e786[0] * _e798));
                    let _e813 = (1f / sqrt((((_e802 * _e802) + (_e803 * _e803)) + (_e806 * _e806))));
                    let _e814 = (_e802 * _e813);
                    let _e815 = (_e803 * _e813);
                    let _e816 = (_e806 * _e813);
                    let _e820 = ((_e815 * _e799) - (_e798 * _e816));
                    let _e823 = ((_e816 * _e797) - (_e799 * _e814));
                    let _e826 = ((_e814 * _e798) - (_e797 * _e815));
                    let _e842 = (((_e776 * _e797) + (_e777 * _e798)) + (_e778 * _e799));
                    let _e846 = abs(_e842);
                    if (_e846 != _e846) {
                        phi_2350_ = true;
                    } else {
                        phi_2350_ = (0.0001f >= _e846);
                    }
                    let _e850 = phi_2350_;
                    if select(false, !((_e684 < 0.5f)), select(false, (_e653 < _e691), (_e653 > 0f))) {
                        phi_1099_ = type_31(1u, type_30(vec2<u32>(_e575, _e576), vec2<f32>(_e647, _e650), select(_e638, ((_e638 * _e644) / _e679), _e680), _e684, vec3<f32>(_e703, _e705, _e706), vec3<f32>(_e776, _e777, _e778), vec3<f32>(_e797, _e798, _e799), vec3<f32>(_e820, _e823, _e826), vec3<f32>(_e814, _e815, _e816), vec3<f32>((((_e776 * _e820) + (_e777 * _e823)) + (_e778 * _e826)), (((_e776 * _e814) + (_e777 * _e815)) + (_e778 * _e816)), _e842), (1f / (select(1f, -1f, (_e842 < 0f)) * select(_e846, 0.0001f, _e850)))));
                    } else {
                        phi_1099_ = type_31(0u, type_31().member_1);
                    }
                    let _e862 = phi_1099_;
                    let _e865 = (bitcast<i32>(_e862.member) != 0i);
                    if _e865 {
                        let _e871 = frame.member[0u].member_1.member_11;
                        let _e876 = (8u << bitcast<u32>((select(_e871, 2u, (2u < _e871)) & 31u)));
                        phi_2592_ = false;
                        phi_1117_ = 0u;
                        phi_1120_ = 0u;
                        phi_1122_ = 0f;
                        loop {
                            let _e878 = phi_2592_;
                            let _e880 = phi_1117_;
                            let _e882 = phi_1120_;
                            let _e884 = phi_1122_;
                            local_12 = _e884;
                            local_13 = _e882;
                            let _e885 = (_e880 < _e876);
                            if _e885 {
                                if ((_e630 & (1u << bitcast<u32>((_e880 & 31u)))) == 0u) {
                                    phi_2663_ = _e878;
                                    phi_2174_ = _e884;
                                } else {
                                    let _e895 = frame.member[0u].member_1.member_10;
                                    let _e897 = ((_e876 + _e880) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e898 = (_e897 < 56u);
                                    if _e898 {
                                    } else {
                                        phi_2661_ = true;
                                        break;
                                    }
                                    let _e900 = local_4[_e897];
                                    let _e903 = (_e895 == 1u);
                                    if _e903 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e898 {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e905 = local_5[_e897];
                                        phi_1170_ = _e905;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e898 {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e907 = local_6[_e897];
                                        phi_1170_ = _e907;
                                    }
                                    let _e909 = phi_1170_;
                                    let _e911 = (_e862.member_1.member_2 * _e909);
                                    let _e912 = (_e911 * _e900[0]);
                                    let _e913 = (_e911 * _e900[1]);
                                    if _e903 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e898 {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e915 = local_7[_e897];
                                        phi_1195_ = _e915;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e898 {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e917 = local_8[_e897];
                                        phi_1195_ = _e917;
                                    }
                                    let _e919 = phi_1195_;
                                    let _e920 = (_e862.member_1.member_2 * _e919);
                                    if _e903 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e898 {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e922 = local_9[_e897];
                                        phi_1208_ = _e922;
                                    } else {
                                        phi_1208_ = (_e920 * 2f);
                                    }
                                    let _e925 = phi_1208_;
                                    let _e934 = (-(((_e912 * _e862.member_1.member_9.x) + (_e913 * _e862.member_1.member_9.y))) * _e862.member_1.member_10);
                                    let _e935 = -(_e920);
                                    let _e939 = select(_e935, select(_e920, _e934, (_e934 < _e920)), (_e934 > _e935));
                                    let _e964 = (-0.5f / ((_e862.member_1.member_4.z + (_e862.member_1.member_7.z * _e912)) + (_e862.member_1.member_8.z * _e913)));
                                    let _e967 = (((((_e862.member_1.member_4.x + (_e862.member_1.member_7.x * _e912)) + (_e862.member_1.member_8.x * _e913)) * _e964) / _e661) + 0.5f);
                                    let _e970 = (0.5f - ((((_e862.member_1.member_4.y + (_e862.member_1.member_7.y * _e912)) + (_e862.member_1.member_8.y * _e913)) * _e964) / _e669));
                                    let _e982 = (select(0f, select(1f, _e967, (_e967 < 1f)), (_e967 > 0f)) * _e584);
                                    if (_e982 > 0f) {
                                        let _e988 = select(select(u32(_e982), 0u, (_e982 < 0f)), 4294967295u, (_e982 > 4294967000f));
                                        let _e989 = (_e589 - 1u);
                                        phi_1336_ = select(_e988, _e989, (_e989 < _e988));
                                    } else {
                                        phi_1336_ = 0u;
                                    }
                                    let _e993 = phi_1336_;
                                    let _e998 = (select(0f, select(1f, _e970, (_e970 < 1f)), (_e970 > 0f)) * _e597);
                                    if (_e998 > 0f) {
                                        let _e1004 = select(select(u32(_e998), 0u, (_e998 < 0f)), 4294967295u, (_e998 > 4294967000f));
                                        let _e1005 = (_e602 - 1u);
                                        phi_1367_ = select(_e1004, _e1005, (_e1005 < _e1004));
                                    } else {
                                        phi_1367_ = 0u;
                                    }
                                    let _e1009 = phi_1367_;
                                    let _e1016 = ((_e862.member_1.member_1.x - _e967) * _e584);
                                    let _e1017 = ((_e862.member_1.member_1.y - _e970) * _e597);
                                    let _e1023 = ((_e1009 * _e589) + _e993);
                                    if (_e1023 < _e552) {
                                    } else {
                                        phi_2661_ = true;
                                        break;
                                    }
                                    let _e1026 = depth.member[_e1023];
                                    let _e1038 = select(_e691, _e1026, select(false, (_e1026 < _e691), (_e1026 > 0f)));
                                    let _e1040 = ((((f32(_e993) + 0.5f) * (1f / _e584)) * 2f) - 1f);
                                    let _e1042 = ((((f32(_e1009) + 0.5f) * (1f / _e597)) * -2f) + 1f);
                                    let _e1048 = (((_e1040 * _e1038) * _e661) - _e862.member_1.member_4.x);
                                    let _e1049 = (((_e1042 * _e1038) * _e669) - _e862.member_1.member_4.y);
                                    let _e1050 = (-(_e1038) - _e862.member_1.member_4.z);
                                    let _e1059 = (((_e1048 * _e862.member_1.member_6.x) + (_e1049 * _e862.member_1.member_6.y)) + (_e1050 * _e862.member_1.member_6.z));
                                    if _e903 {
                                        let _e1064 = (((_e1048 * _e1048) + (_e1049 * _e1049)) + (_e1050 * _e1050));
                                        let _e1076 = (((((_e862.member_1.member_5.x * _e1048) + (_e862.member_1.member_5.y * _e1049)) + (_e862.member_1.member_5.z * _e1050)) / sqrt(_e1064)) - 0.1f);
                                        let _e1083 = (1f - (_e1064 / (_e638 * _e638)));
                                        let _e1090 = ((select(0f, select(1f, _e1076, (_e1076 < 1f)), (_e1076 > 0f)) * select(0f, select(1f, _e1083, (_e1083 < 1f)), (_e1083 > 0f))) / _e925);
                                        phi_1577_ = select(0f, select(0f, select(1f, _e1090, (_e1090 < 1f)), (_e1090 > 0f)), (_e1064 > 0f));
                                    } else {
                                        let _e1101 = frame.member[0u].member_1.member.member_3;
                                        if (_e939 != _e939) {
                                            phi_2365_ = true;
                                        } else {
                                            phi_2365_ = (_e1059 >= _e939);
                                        }
                                        let _e1106 = phi_2365_;
                                        let _e1108 = (_e920 - select(_e939, _e1059, _e1106));
                                        if (_e1108 != _e1108) {
                                            phi_2380_ = true;
                                        } else {
                                            phi_2380_ = (0f >= _e1108);
                                        }
                                        let _e1112 = phi_2380_;
                                        let _e1117 = ((_e1059 - (_e862.member_1.member_2 * (1f + _e1101))) * (1f / _e920));
                                        phi_1577_ = ((select(_e1108, 0f, _e1112) + (select(0f, select(1f, _e1117, (_e1117 < 1f)), (_e1117 > 0f)) * (_e920 - _e939))) * (0.5f / _e920));
                                    }
                                    let _e1128 = phi_1577_;
                                    let _e1133 = frame.member[0u].member_1.member_9;
                                    if (_e1133 == 0u) {
                                        phi_1814_ = type_41(_e1059, _e1128);
                                    } else {
                                        if _e903 {
                                            let _e1136 = (_e862.member_1.member_2 * 0.1f);
                                            if (_e920 != _e920) {
                                                phi_2395_ = true;
                                            } else {
                                                phi_2395_ = (_e1136 >= _e920);
                                            }
                                            let _e1140 = phi_2395_;
                                            phi_1600_ = select(_e920, _e1136, _e1140);
                                        } else {
                                            let _e1147 = frame.member[0u].member_1.member.member_3;
                                            phi_1600_ = (_e862.member_1.member_2 * (1f + _e1147));
                                        }
                                        let _e1151 = phi_1600_;
                                        let _e1157 = frame.member[0u].member_1.member_3;
                                        let _e1159 = select(false, (sqrt(((_e1016 * _e1016) + (_e1017 * _e1017))) > _e1157), (_e1059 > _e1151));
                                        if (_e1023 < arrayLength((&depth2_.member))) {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e1163 = depth2_.member[_e1023];
                                        let _e1167 = select(_e691, _e1163, select(false, (_e1163 < _e691), (_e1163 > 0f)));
                                        let _e1173 = (((_e1040 * _e1167) * _e661) - _e862.member_1.member_4.x);
                                        let _e1174 = (((_e1042 * _e1167) * _e669) - _e862.member_1.member_4.y);
                                        let _e1175 = (-(_e1167) - _e862.member_1.member_4.z);
                                        let _e1180 = (((_e1173 * _e862.member_1.member_6.x) + (_e1174 * _e862.member_1.member_6.y)) + (_e1175 * _e862.member_1.member_6.z));
                                        if _e903 {
                                            let _e1185 = (((_e1173 * _e1173) + (_e1174 * _e1174)) + (_e1175 * _e1175));
                                            let _e1197 = (((((_e862.member_1.member_5.x * _e1173) + (_e862.member_1.member_5.y * _e1174)) + (_e862.member_1.member_5.z * _e1175)) / sqrt(_e1185)) - 0.1f);
                                            let _e1204 = (1f - (_e1185 / (_e638 * _e638)));
                                            let _e1211 = ((select(0f, select(1f, _e1197, (_e1197 < 1f)), (_e1197 > 0f)) * select(0f, select(1f, _e1204, (_e1204 < 1f)), (_e1204 > 0f))) / _e925);
                                            phi_1794_ = select(0f, select(0f, select(1f, _e1211, (_e1211 < 1f)), (_e1211 > 0f)), (_e1185 > 0f));
                                        } else {
                                            let _e1222 = frame.member[0u].member_1.member.member_3;
                                            if (_e939 != _e939) {
                                                phi_2410_ = true;
                                            } else {
                                                phi_2410_ = (_e1180 >= _e939);
                                            }
                                            let _e1227 = phi_2410_;
                                            let _e1229 = (_e920 - select(_e939, _e1180, _e1227));
                                            if (_e1229 != _e1229) {
                                                phi_2425_ = true;
                                            } else {
                                                phi_2425_ = (0f >= _e1229);
                                            }
                                            let _e1233 = phi_2425_;
                                            let _e1238 = ((_e1180 - (_e862.member_1.member_2 * (1f + _e1222))) * (1f / _e920));
                                            phi_1794_ = ((select(_e1229, 0f, _e1233) + (select(0f, select(1f, _e1238, (_e1238 < 1f)), (_e1238 > 0f)) * (_e920 - _e939))) * (0.5f / _e920));
                                        }
                                        let _e1249 = phi_1794_;
                                        if (_e1059 != _e1059) {
                                            phi_2440_ = true;
                                        } else {
                                            phi_2440_ = (_e1180 <= _e1059);
                                        }
                                        let _e1253 = phi_2440_;
                                        if _e903 {
                                            if (_e1128 != _e1128) {
                                                phi_2455_ = true;
                                            } else {
                                                phi_2455_ = (_e1249 >= _e1128);
                                            }
                                            let _e1259 = phi_2455_;
                                            phi_1808_ = select(_e1128, _e1249, _e1259);
                                        } else {
                                            if (_e1128 != _e1128) {
                                                phi_2470_ = true;
                                            } else {
                                                phi_2470_ = (_e1249 <= _e1128);
                                            }
                                            let _e1264 = phi_2470_;
                                            phi_1808_ = select(_e1128, _e1249, _e1264);
                                        }
                                        let _e1267 = phi_1808_;
                                        phi_1814_ = type_41(select(_e1059, select(_e1059, _e1180, _e1253), _e1159), select(_e1128, _e1267, _e1159));
                                    }
                                    let _e1271 = phi_1814_;
                                    if select(false, select(false, (_e970 <= 1f), (_e970 >= 0f)), select(false, (_e967 <= 1f), (_e967 >= 0f))) {
                                        phi_1827_ = _e1271.member_1;
                                    } else {
                                        phi_1827_ = select(1f, 0f, _e903);
                                    }
                                    let _e1276 = phi_1827_;
                                    let _e1282 = frame.member[0u].member_1.member_5[0u];
                                    let _e1288 = frame.member[0u].member_1.member_5[1u];
                                    let _e1289 = f32(_e1282);
                                    let _e1290 = f32(_e1288);
                                    let _e1295 = frame.member[0u].member_1.member_4;
                                    let _e1296 = f32(_e1295);
                                    let _e1297 = (2u * _e1295);
                                    let _e1298 = (_e1282 + _e1297);
                                    let _e1304 = (floor((_e967 * _e1289)) + _e1296);
                                    let _e1305 = f32((_e1298 - 1u));
                                    let _e1309 = select(0f, select(_e1305, _e1304, (_e1304 < _e1305)), (_e1304 > 0f));
                                    let _e1312 = (floor((_e970 * _e1290)) + _e1296);
                                    let _e1313 = f32(((_e1288 + _e1297) - 1u));
                                    let _e1317 = select(0f, select(_e1313, _e1312, (_e1312 < _e1313)), (_e1312 > 0f));
                                    let _e1322 = select(select(u32(_e1309), 0u, (_e1309 < 0f)), 4294967295u, (_e1309 > 4294967000f));
                                    let _e1327 = select(select(u32(_e1317), 0u, (_e1317 < 0f)), 4294967295u, (_e1317 > 4294967000f));
                                    let _e1330 = bitcast<i32>(_e1295);
                                    let _e1339 = frame.member[0u].member_1.member_8;
                                    let _e1344 = frame.member[0u].member_1.member_12;
                                    let _e1351 = (((((_e1327 % 4u) * 4u) + (_e1322 % 4u)) + (_e1344 % 16u)) % 16u);
                                    if (_e1339 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1353 = (_e1351 < 16u);
                                        if _e1353 {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e1356 = local[_e1351][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1353 {
                                        } else {
                                            phi_2661_ = true;
                                            break;
                                        }
                                        let _e1359 = local_1[_e1351][1u];
                                        phi_1961_ = vec2<f32>(_e1356, _e1359);
                                    } else {
                                        if (_e1339 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1362 = (_e1351 < 16u);
                                            if _e1362 {
                                            } else {
                                                phi_2661_ = true;
                                                break;
                                            }
                                            let _e1365 = local_2[_e1351][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1362 {
                                            } else {
                                                phi_2661_ = true;
                                                break;
                                            }
                                            let _e1368 = local_3[_e1351][1u];
                                            phi_1960_ = vec2<f32>(_e1365, _e1368);
                                        } else {
                                            phi_1960_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1371 = phi_1960_;
                                        phi_1961_ = _e1371;
                                    }
                                    let _e1373 = phi_1961_;
                                    let _e1386 = frame.member[0u].member_1.member_6;
                                    phi_1992_ = 0u;
                                    phi_1995_ = _e1276;
                                    loop {
                                        let _e1389 = phi_1992_;
                                        let _e1391 = phi_1995_;
                                        local_11 = _e1391;
                                        let _e1392 = (_e1389 < _e1386);
                                        if _e1392 {
                                            let _e1393 = ((((_e1327 * _e1298) + _e1322) * _e1386) + _e1389);
                                            if (_e1393 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2544_ = true;
                                                break;
                                            }
                                            let _e1396 = sd_map.member[_e1393];
                                            let _e1403 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1406 = ((_e1396 * (_e691 - _e1403)) + _e1403);
                                            let _e1416 = (((((((f32((bitcast<i32>(_e1322) - _e1330)) + _e1373.x) / _e1289) * 2f) - 1f) * _e1406) * _e661) - _e862.member_1.member_4.x);
                                            let _e1417 = (((((((f32((bitcast<i32>(_e1327) - _e1330)) + _e1373.y) / _e1290) * -2f) + 1f) * _e1406) * _e669) - _e862.member_1.member_4.y);
                                            let _e1418 = (-(_e1406) - _e862.member_1.member_4.z);
                                            let _e1423 = (((_e1416 * _e862.member_1.member_6.x) + (_e1417 * _e862.member_1.member_6.y)) + (_e1418 * _e862.member_1.member_6.z));
                                            if _e903 {
                                                let _e1428 = (((_e1416 * _e1416) + (_e1417 * _e1417)) + (_e1418 * _e1418));
                                                let _e1440 = (((((_e862.member_1.member_5.x * _e1416) + (_e862.member_1.member_5.y * _e1417)) + (_e862.member_1.member_5.z * _e1418)) / sqrt(_e1428)) - 0.1f);
                                                let _e1447 = (1f - (_e1428 / (_e638 * _e638)));
                                                let _e1454 = ((select(0f, select(1f, _e1440, (_e1440 < 1f)), (_e1440 > 0f)) * select(0f, select(1f, _e1447, (_e1447 < 1f)), (_e1447 > 0f))) / _e925);
                                                phi_2160_ = select(0f, select(0f, select(1f, _e1454, (_e1454 < 1f)), (_e1454 > 0f)), (_e1428 > 0f));
                                            } else {
                                                let _e1465 = frame.member[0u].member_1.member.member_3;
                                                if (_e939 != _e939) {
                                                    phi_2485_ = true;
                                                } else {
                                                    phi_2485_ = (_e1423 >= _e939);
                                                }
                                                let _e1470 = phi_2485_;
                                                let _e1472 = (_e920 - select(_e939, _e1423, _e1470));
                                                if (_e1472 != _e1472) {
                                                    phi_2500_ = true;
                                                } else {
                                                    phi_2500_ = (0f >= _e1472);
                                                }
                                                let _e1476 = phi_2500_;
                                                let _e1481 = ((_e1423 - (_e862.member_1.member_2 * (1f + _e1465))) * (1f / _e920));
                                                phi_2160_ = ((select(_e1472, 0f, _e1476) + (select(0f, select(1f, _e1481, (_e1481 < 1f)), (_e1481 > 0f)) * (_e920 - _e939))) * (0.5f / _e920));
                                            }
                                            let _e1492 = phi_2160_;
                                            if _e903 {
                                                if (_e1391 != _e1391) {
                                                    phi_2515_ = true;
                                                } else {
                                                    phi_2515_ = (_e1492 >= _e1391);
                                                }
                                                let _e1496 = phi_2515_;
                                                phi_2169_ = select(_e1391, _e1492, _e1496);
                                            } else {
                                                if (_e1391 != _e1391) {
                                                    phi_2530_ = true;
                                                } else {
                                                    phi_2530_ = (_e1492 <= _e1391);
                                                }
                                                let _e1501 = phi_2530_;
                                                phi_2169_ = select(_e1391, _e1492, _e1501);
                                            }
                                            let _e1504 = phi_2169_;
                                            phi_1993_ = (_e1389 + 1u);
                                            phi_1996_ = _e1504;
                                        } else {
                                            phi_1993_ = u32();
                                            phi_1996_ = f32();
                                        }
                                        let _e1507 = phi_1993_;
                                        let _e1509 = phi_1996_;
                                        continue;
                                        continuing {
                                            phi_1992_ = _e1507;
                                            phi_1995_ = _e1509;
                                            phi_2544_ = _e878;
                                            break if !(_e1392);
                                        }
                                    }
                                    let _e1512 = phi_2544_;
                                    phi_2661_ = _e1512;
                                    if _e1512 {
                                        break;
                                    }
                                    let _e1514 = local_11;
                                    phi_2663_ = _e1512;
                                    phi_2174_ = ((_e884 - _e1271.member_1) + _e1514);
                                }
                                let _e1517 = phi_2663_;
                                let _e1519 = phi_2174_;
                                phi_2662_ = _e1517;
                                phi_1118_ = (_e880 + 1u);
                                phi_1123_ = _e1519;
                            } else {
                                phi_2662_ = _e878;
                                phi_1118_ = u32();
                                phi_1123_ = f32();
                            }
                            let _e1522 = phi_2662_;
                            let _e1524 = phi_1118_;
                            let _e1526 = phi_1123_;
                            continue;
                            continuing {
                                phi_2592_ = _e1522;
                                phi_1117_ = _e1524;
                                phi_1120_ = select(u32(), _e882, _e885);
                                phi_1122_ = _e1526;
                                phi_2661_ = _e1522;
                                break if !(_e885);
                            }
                        }
                        let _e1530 = phi_2661_;
                        if _e1530 {
                            break;
                        }
                        let _e1535 = frame.member[0u].member_1.member_10;
                        let _e1536 = (_e1535 == 1u);
                        let _e1541 = local_12;
                        let _e1543 = (_e626 + ((select(2f, 1f, _e1536) / f32(_e876)) * _e1541));
                        if _e1536 {
                            phi_2204_ = (1f - (2f * _e1543));
                        } else {
                            phi_2204_ = _e1543;
                        }
                        let _e1547 = phi_2204_;
                        let _e1557 = frame.member[0u].member_1.member.member_2;
                        let _e1560 = local_13;
                        phi_2219_ = type_42(pow(select(0f, select(1f, _e1547, (_e1547 < 1f)), (_e1547 > 0f)), _e1557), _e1560);
                    } else {
                        phi_2219_ = type_42();
                    }
                    let _e1563 = phi_2219_;
                    phi_2221_ = _e1563;
                    phi_2222_ = select(true, false, _e865);
                }
                let _e1566 = phi_2221_;
                let _e1568 = phi_2222_;
                if _e1568 {
                    phi_2226_ = type_42(_e626, 0u);
                } else {
                    phi_2226_ = _e1566;
                }
                let _e1570 = phi_2226_;
                if _e623 {
                } else {
                    break;
                }
                ao.member[_e622] = _e1570.member;
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
