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
    var phi_2302_: bool;
    var phi_2317_: bool;
    var phi_2278_: vec2<f32>;
    var phi_2332_: bool;
    var phi_1092_: type_31;
    var phi_2574_: bool;
    var phi_1110_: u32;
    var phi_1113_: u32;
    var phi_1115_: f32;
    var phi_1163_: f32;
    var phi_1188_: f32;
    var phi_1201_: f32;
    var phi_1329_: u32;
    var phi_1360_: u32;
    var phi_2347_: bool;
    var phi_2362_: bool;
    var phi_1564_: f32;
    var phi_2377_: bool;
    var phi_1587_: f32;
    var phi_2392_: bool;
    var phi_2407_: bool;
    var phi_1776_: f32;
    var phi_2422_: bool;
    var phi_2437_: bool;
    var phi_2452_: bool;
    var phi_1790_: f32;
    var phi_1796_: type_41;
    var phi_1809_: f32;
    var phi_1942_: vec2<f32>;
    var phi_1943_: vec2<f32>;
    var phi_1974_: u32;
    var phi_1977_: f32;
    var phi_2467_: bool;
    var phi_2482_: bool;
    var phi_2142_: f32;
    var phi_2497_: bool;
    var phi_2512_: bool;
    var phi_2151_: f32;
    var phi_1975_: u32;
    var phi_1978_: f32;
    var phi_2526_: bool;
    var local_11: f32;
    var phi_2645_: bool;
    var phi_2156_: f32;
    var phi_2644_: bool;
    var phi_1111_: u32;
    var phi_1116_: f32;
    var phi_2643_: bool;
    var local_12: f32;
    var phi_2186_: f32;
    var local_13: u32;
    var phi_2201_: type_42;
    var phi_2203_: type_42;
    var phi_2204_: bool;
    var phi_2208_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e547 = id_1;
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e570 = frame.member[0u].member_1.member.member.member_4;
            let _e571 = (_e547.x + _e570);
            let _e572 = (_e547.y + _e570);
            let _e580 = frame.member[0u].member_1.member.member.member[0u];
            let _e585 = select(select(u32(_e580), 0u, (_e580 < 0f)), 4294967295u, (_e580 > 4294967000f));
            let _e593 = frame.member[0u].member_1.member.member.member[1u];
            let _e598 = select(select(u32(_e593), 0u, (_e593 < 0f)), 4294967295u, (_e593 > 4294967000f));
            if (_e571 >= _e570) {
                if (_e572 >= _e570) {
                    let _e602 = ((_e571 + _e570) < _e585);
                    if _e602 {
                        phi_790_ = ((_e572 + _e570) < _e598);
                    } else {
                        phi_790_ = bool();
                    }
                    let _e606 = phi_790_;
                    phi_792_ = _e606;
                    phi_793_ = select(true, false, _e602);
                } else {
                    phi_792_ = bool();
                    phi_793_ = true;
                }
                let _e609 = phi_792_;
                let _e611 = phi_793_;
                phi_794_ = _e609;
                phi_795_ = _e611;
            } else {
                phi_794_ = bool();
                phi_795_ = true;
            }
            let _e613 = phi_794_;
            let _e615 = phi_795_;
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
                    phi_2203_ = type_42();
                    phi_2204_ = true;
                } else {
                    let _e634 = frame.member[0u].member_1.member.member_1;
                    let _e640 = frame.member[0u].member_1.member.member_4;
                    let _e643 = ((f32(_e571) + 0.5f) / _e580);
                    let _e646 = ((f32(_e572) + 0.5f) / _e593);
                    let _e648 = depth.member[_e618];
                    let _e656 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e664 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e674 = ((((_e634 * _e580) / (_e648 * (2f * _e656))) + ((_e634 * _e593) / (_e648 * (2f * _e664)))) * 0.5f);
                    let _e675 = (_e674 > _e640);
                    let _e679 = select(_e674, _e640, _e675);
                    let _e686 = frame.member[0u].member_1.member.member.member_3;
                    let _e698 = ((((_e643 * 2f) - 1f) * _e648) * _e656);
                    let _e700 = ((((_e646 * -2f) + 1f) * _e648) * _e664);
                    let _e701 = -(_e648);
                    if (_e618 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e705 = normals.member[_e618];
                    let _e713 = (f32((bitcast<i32>(((_e705 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e713 != _e713) {
                        phi_2302_ = true;
                    } else {
                        phi_2302_ = (-1f >= _e713);
                    }
                    let _e717 = phi_2302_;
                    let _e718 = select(_e713, -1f, _e717);
                    let _e728 = (f32((bitcast<i32>((((_e705 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e728 != _e728) {
                        phi_2317_ = true;
                    } else {
                        phi_2317_ = (-1f >= _e728);
                    }
                    let _e732 = phi_2317_;
                    let _e733 = select(_e728, -1f, _e732);
                    let _e736 = (1f - abs(_e718));
                    let _e737 = abs(_e733);
                    let _e738 = (_e736 - _e737);
                    if (_e738 < 0f) {
                        phi_2278_ = vec2<f32>(((1f - _e737) * select(1f, -1f, (_e718 < 0f))), (_e736 * select(1f, -1f, (_e733 < 0f))));
                    } else {
                        phi_2278_ = vec2<f32>(_e718, _e733);
                    }
                    let _e749 = phi_2278_;
                    let _e758 = (1f / sqrt((((_e749.x * _e749.x) + (_e749.y * _e749.y)) + (_e738 * _e738))));
                    let _e759 = (_e749.x * _e758);
                    let _e760 = (_e749.y * _e758);
                    let _e761 = (_e738 * _e758);
                    let _e767 = ((((_e698 * _e759) + (_e700 * _e760)) + (_e701 * _e761)) > 0f);
                    let _e771 = select(_e759, -(_e759), _e767);
                    let _e772 = select(_e760, -(_e760), _e767);
                    let _e773 = select(_e761, -(_e761), _e767);
                    local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                    let _e775 = (_e572 % 4u);
                    if (_e775 < 4u) {
                    } else {
                        break;
                    }
                    let _e777 = (_e571 % 4u);
                    if (_e777 < 4u) {
                    } else {
                        break;
                    }
                    let _e781 = local_10[_e775][_e777];
                    let _e791 = sqrt((((_e698 * _e698) + (_e700 * _e700)) + (_e701 * _e701)));
                    let _e792 = (-(_e698) / _e791);
                    let _e793 = (-(_e700) / _e791);
                    let _e794 = (_e648 / _e791);
                    let _e797 = -((_e781[1] * _e794));
                    let _e798 = (_e794 * _e781[0]);
                    let _e801 = ((_e792 * _e781[1]) - (_e781[0] * _e793));
                    let _e808 = (1f / sqrt((((_e797 * _e797) + (_e798 * _e798)) + (_e801 * _e801))));
                    let _e809 = (_e797 * _e808);
                    let _e810 = (_e798 * _e808);
                    let _e811 = (_e801 * _e808);
                    let _e815 = ((_e810 * _e794) - (_e793 * _e811));
                    let _e818 = ((_e811 * _e792) - (_e794 * _e809));
                    let _e821 = ((_e809 * _e793) - (_e792 * _e810));
                    let _e837 = (((_e771 * _e792) + (_e772 * _e793)) + (_e773 * _e794));
                    let _e841 = abs(_e837);
                    if (_e841 != _e841) {
                        phi_2332_ = true;
                    } else {
                        phi_2332_ = (0.0001f >= _e841);
                    }
                    let _e845 = phi_2332_;
                    if select(false, !((_e679 < 0.5f)), select(false, (_e648 < _e686), (_e648 > 0f))) {
                        phi_1092_ = type_31(1u, type_30(vec2<u32>(_e571, _e572), vec2<f32>(_e643, _e646), select(_e634, ((_e634 * _e640) / _e674), _e675), _e679, vec3<f32>(_e698, _e700, _e701), vec3<f32>(_e771, _e772, _e773), vec3<f32>(_e792, _e793, _e794), vec3<f32>(_e815, _e818, _e821), vec3<f32>(_e809, _e810, _e811), vec3<f32>((((_e771 * _e815) + (_e772 * _e818)) + (_e773 * _e821)), (((_e771 * _e809) + (_e772 * _e810)) + (_e773 * _e811)), _e837), (1f / (select(1f, -1f, (_e837 < 0f)) * select(_e841, 0.0001f, _e845)))));
                    } else {
                        phi_1092_ = type_31(0u, type_31().member_1);
                    }
                    let _e857 = phi_1092_;
                    let _e860 = (bitcast<i32>(_e857.member) != 0i);
                    if _e860 {
                        let _e866 = frame.member[0u].member_1.member_11;
                        let _e871 = (8u << bitcast<u32>((select(_e866, 2u, (2u < _e866)) & 31u)));
                        phi_2574_ = false;
                        phi_1110_ = 0u;
                        phi_1113_ = 0u;
                        phi_1115_ = 0f;
                        loop {
                            let _e873 = phi_2574_;
                            let _e875 = phi_1110_;
                            let _e877 = phi_1113_;
                            let _e879 = phi_1115_;
                            local_12 = _e879;
                            local_13 = _e877;
                            let _e880 = (_e875 < _e871);
                            if _e880 {
                                if ((_e626 & (1u << bitcast<u32>((_e875 & 31u)))) == 0u) {
                                    phi_2645_ = _e873;
                                    phi_2156_ = _e879;
                                } else {
                                    let _e890 = frame.member[0u].member_1.member_10;
                                    let _e892 = ((_e871 + _e875) - 8u);
                                    local_4 = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                                    let _e893 = (_e892 < 56u);
                                    if _e893 {
                                    } else {
                                        phi_2643_ = true;
                                        break;
                                    }
                                    let _e895 = local_4[_e892];
                                    let _e898 = (_e890 == 1u);
                                    if _e898 {
                                        local_5 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                        if _e893 {
                                        } else {
                                            phi_2643_ = true;
                                            break;
                                        }
                                        let _e900 = local_5[_e892];
                                        phi_1163_ = _e900;
                                    } else {
                                        local_6 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                        if _e893 {
                                        } else {
                                            phi_2643_ = true;
                                            break;
                                        }
                                        let _e902 = local_6[_e892];
                                        phi_1163_ = _e902;
                                    }
                                    let _e904 = phi_1163_;
                                    let _e906 = (_e857.member_1.member_2 * _e904);
                                    let _e907 = (_e906 * _e895[0]);
                                    let _e908 = (_e906 * _e895[1]);
                                    if _e898 {
                                        local_7 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                        if _e893 {
                                        } else {
                                            phi_2643_ = true;
                                            break;
                                        }
                                        let _e910 = local_7[_e892];
                                        phi_1188_ = _e910;
                                    } else {
                                        local_8 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                        if _e893 {
                                        } else {
                                            phi_2643_ = true;
                                            break;
                                        }
                                        let _e912 = local_8[_e892];
                                        phi_1188_ = _e912;
                                    }
                                    let _e914 = phi_1188_;
                                    let _e915 = (_e857.member_1.member_2 * _e914);
                                    if _e898 {
                                        local_9 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                        if _e893 {
                                        } else {
                                            phi_2643_ = true;
                                            break;
                                        }
                                        let _e917 = local_9[_e892];
                                        phi_1201_ = _e917;
                                    } else {
                                        phi_1201_ = (_e915 * 2f);
                                    }
                                    let _e920 = phi_1201_;
                                    let _e929 = (-(((_e907 * _e857.member_1.member_9.x) + (_e908 * _e857.member_1.member_9.y))) * _e857.member_1.member_10);
                                    let _e930 = -(_e915);
                                    let _e934 = select(_e930, select(_e915, _e929, (_e929 < _e915)), (_e929 > _e930));
                                    let _e959 = (-0.5f / ((_e857.member_1.member_4.z + (_e857.member_1.member_7.z * _e907)) + (_e857.member_1.member_8.z * _e908)));
                                    let _e962 = (((((_e857.member_1.member_4.x + (_e857.member_1.member_7.x * _e907)) + (_e857.member_1.member_8.x * _e908)) * _e959) / _e656) + 0.5f);
                                    let _e965 = (0.5f - ((((_e857.member_1.member_4.y + (_e857.member_1.member_7.y * _e907)) + (_e857.member_1.member_8.y * _e908)) * _e959) / _e664));
                                    let _e977 = (select(0f, select(1f, _e962, (_e962 < 1f)), (_e962 > 0f)) * _e580);
                                    if (_e977 > 0f) {
                                        let _e983 = select(select(u32(_e977), 0u, (_e977 < 0f)), 4294967295u, (_e977 > 4294967000f));
                                        let _e984 = (_e585 - 1u);
                                        phi_1329_ = select(_e983, _e984, (_e984 < _e983));
                                    } else {
                                        phi_1329_ = 0u;
                                    }
                                    let _e988 = phi_1329_;
                                    let _e993 = (select(0f, select(1f, _e965, (_e965 < 1f)), (_e965 > 0f)) * _e593);
                                    if (_e993 > 0f) {
                                        let _e999 = select(select(u32(_e993), 0u, (_e993 < 0f)), 4294967295u, (_e993 > 4294967000f));
                                        let _e1000 = (_e598 - 1u);
                                        phi_1360_ = select(_e999, _e1000, (_e1000 < _e999));
                                    } else {
                                        phi_1360_ = 0u;
                                    }
                                    let _e1004 = phi_1360_;
                                    let _e1011 = ((_e857.member_1.member_1.x - _e962) * _e580);
                                    let _e1012 = ((_e857.member_1.member_1.y - _e965) * _e593);
                                    let _e1018 = ((_e1004 * _e585) + _e988);
                                    let _e1020 = depth.member[_e1018];
                                    let _e1032 = select(_e686, _e1020, select(false, (_e1020 < _e686), (_e1020 > 0f)));
                                    let _e1034 = ((((f32(_e988) + 0.5f) * (1f / _e580)) * 2f) - 1f);
                                    let _e1036 = ((((f32(_e1004) + 0.5f) * (1f / _e593)) * -2f) + 1f);
                                    let _e1042 = (((_e1034 * _e1032) * _e656) - _e857.member_1.member_4.x);
                                    let _e1043 = (((_e1036 * _e1032) * _e664) - _e857.member_1.member_4.y);
                                    let _e1044 = (-(_e1032) - _e857.member_1.member_4.z);
                                    let _e1053 = (((_e1042 * _e857.member_1.member_6.x) + (_e1043 * _e857.member_1.member_6.y)) + (_e1044 * _e857.member_1.member_6.z));
                                    if _e898 {
                                        let _e1058 = (((_e1042 * _e1042) + (_e1043 * _e1043)) + (_e1044 * _e1044));
                                        let _e1070 = (((((_e857.member_1.member_5.x * _e1042) + (_e857.member_1.member_5.y * _e1043)) + (_e857.member_1.member_5.z * _e1044)) / sqrt(_e1058)) - 0.1f);
                                        let _e1077 = (1f - (_e1058 / (_e634 * _e634)));
                                        let _e1084 = ((select(0f, select(1f, _e1070, (_e1070 < 1f)), (_e1070 > 0f)) * select(0f, select(1f, _e1077, (_e1077 < 1f)), (_e1077 > 0f))) / _e920);
                                        phi_1564_ = select(0f, select(0f, select(1f, _e1084, (_e1084 < 1f)), (_e1084 > 0f)), (_e1058 > 0f));
                                    } else {
                                        let _e1095 = frame.member[0u].member_1.member.member_3;
                                        if (_e934 != _e934) {
                                            phi_2347_ = true;
                                        } else {
                                            phi_2347_ = (_e1053 >= _e934);
                                        }
                                        let _e1100 = phi_2347_;
                                        let _e1102 = (_e915 - select(_e934, _e1053, _e1100));
                                        if (_e1102 != _e1102) {
                                            phi_2362_ = true;
                                        } else {
                                            phi_2362_ = (0f >= _e1102);
                                        }
                                        let _e1106 = phi_2362_;
                                        let _e1111 = ((_e1053 - (_e857.member_1.member_2 * (1f + _e1095))) * (1f / _e915));
                                        phi_1564_ = ((select(_e1102, 0f, _e1106) + (select(0f, select(1f, _e1111, (_e1111 < 1f)), (_e1111 > 0f)) * (_e915 - _e934))) * (0.5f / _e915));
                                    }
                                    let _e1122 = phi_1564_;
                                    let _e1127 = frame.member[0u].member_1.member_9;
                                    if (_e1127 == 0u) {
                                        phi_1796_ = type_41(_e1053, _e1122);
                                    } else {
                                        if _e898 {
                                            let _e1130 = (_e857.member_1.member_2 * 0.1f);
                                            if (_e915 != _e915) {
                                                phi_2377_ = true;
                                            } else {
                                                phi_2377_ = (_e1130 >= _e915);
                                            }
                                            let _e1134 = phi_2377_;
                                            phi_1587_ = select(_e915, _e1130, _e1134);
                                        } else {
                                            let _e1141 = frame.member[0u].member_1.member.member_3;
                                            phi_1587_ = (_e857.member_1.member_2 * (1f + _e1141));
                                        }
                                        let _e1145 = phi_1587_;
                                        let _e1151 = frame.member[0u].member_1.member_3;
                                        let _e1153 = select(false, (sqrt(((_e1011 * _e1011) + (_e1012 * _e1012))) > _e1151), (_e1053 > _e1145));
                                        let _e1156 = depth2_.member[_e1018];
                                        let _e1160 = select(_e686, _e1156, select(false, (_e1156 < _e686), (_e1156 > 0f)));
                                        let _e1166 = (((_e1034 * _e1160) * _e656) - _e857.member_1.member_4.x);
                                        let _e1167 = (((_e1036 * _e1160) * _e664) - _e857.member_1.member_4.y);
                                        let _e1168 = (-(_e1160) - _e857.member_1.member_4.z);
                                        let _e1173 = (((_e1166 * _e857.member_1.member_6.x) + (_e1167 * _e857.member_1.member_6.y)) + (_e1168 * _e857.member_1.member_6.z));
                                        if _e898 {
                                            let _e1178 = (((_e1166 * _e1166) + (_e1167 * _e1167)) + (_e1168 * _e1168));
                                            let _e1190 = (((((_e857.member_1.member_5.x * _e1166) + (_e857.member_1.member_5.y * _e1167)) + (_e857.member_1.member_5.z * _e1168)) / sqrt(_e1178)) - 0.1f);
                                            let _e1197 = (1f - (_e1178 / (_e634 * _e634)));
                                            let _e1204 = ((select(0f, select(1f, _e1190, (_e1190 < 1f)), (_e1190 > 0f)) * select(0f, select(1f, _e1197, (_e1197 < 1f)), (_e1197 > 0f))) / _e920);
                                            phi_1776_ = select(0f, select(0f, select(1f, _e1204, (_e1204 < 1f)), (_e1204 > 0f)), (_e1178 > 0f));
                                        } else {
                                            let _e1215 = frame.member[0u].member_1.member.member_3;
                                            if (_e934 != _e934) {
                                                phi_2392_ = true;
                                            } else {
                                                phi_2392_ = (_e1173 >= _e934);
                                            }
                                            let _e1220 = phi_2392_;
                                            let _e1222 = (_e915 - select(_e934, _e1173, _e1220));
                                            if (_e1222 != _e1222) {
                                                phi_2407_ = true;
                                            } else {
                                                phi_2407_ = (0f >= _e1222);
                                            }
                                            let _e1226 = phi_2407_;
                                            let _e1231 = ((_e1173 - (_e857.member_1.member_2 * (1f + _e1215))) * (1f / _e915));
                                            phi_1776_ = ((select(_e1222, 0f, _e1226) + (select(0f, select(1f, _e1231, (_e1231 < 1f)), (_e1231 > 0f)) * (_e915 - _e934))) * (0.5f / _e915));
                                        }
                                        let _e1242 = phi_1776_;
                                        if (_e1053 != _e1053) {
                                            phi_2422_ = true;
                                        } else {
                                            phi_2422_ = (_e1173 <= _e1053);
                                        }
                                        let _e1246 = phi_2422_;
                                        if _e898 {
                                            if (_e1122 != _e1122) {
                                                phi_2437_ = true;
                                            } else {
                                                phi_2437_ = (_e1242 >= _e1122);
                                            }
                                            let _e1252 = phi_2437_;
                                            phi_1790_ = select(_e1122, _e1242, _e1252);
                                        } else {
                                            if (_e1122 != _e1122) {
                                                phi_2452_ = true;
                                            } else {
                                                phi_2452_ = (_e1242 <= _e1122);
                                            }
                                            let _e1257 = phi_2452_;
                                            phi_1790_ = select(_e1122, _e1242, _e1257);
                                        }
                                        let _e1260 = phi_1790_;
                                        phi_1796_ = type_41(select(_e1053, select(_e1053, _e1173, _e1246), _e1153), select(_e1122, _e1260, _e1153));
                                    }
                                    let _e1264 = phi_1796_;
                                    if select(false, select(false, (_e965 <= 1f), (_e965 >= 0f)), select(false, (_e962 <= 1f), (_e962 >= 0f))) {
                                        phi_1809_ = _e1264.member_1;
                                    } else {
                                        phi_1809_ = select(1f, 0f, _e898);
                                    }
                                    let _e1269 = phi_1809_;
                                    let _e1275 = frame.member[0u].member_1.member_5[0u];
                                    let _e1281 = frame.member[0u].member_1.member_5[1u];
                                    let _e1282 = f32(_e1275);
                                    let _e1283 = f32(_e1281);
                                    let _e1288 = frame.member[0u].member_1.member_4;
                                    let _e1289 = f32(_e1288);
                                    let _e1290 = (2u * _e1288);
                                    let _e1291 = (_e1275 + _e1290);
                                    let _e1297 = (floor((_e962 * _e1282)) + _e1289);
                                    let _e1298 = f32((_e1291 - 1u));
                                    let _e1302 = select(0f, select(_e1298, _e1297, (_e1297 < _e1298)), (_e1297 > 0f));
                                    let _e1305 = (floor((_e965 * _e1283)) + _e1289);
                                    let _e1306 = f32(((_e1281 + _e1290) - 1u));
                                    let _e1310 = select(0f, select(_e1306, _e1305, (_e1305 < _e1306)), (_e1305 > 0f));
                                    let _e1315 = select(select(u32(_e1302), 0u, (_e1302 < 0f)), 4294967295u, (_e1302 > 4294967000f));
                                    let _e1320 = select(select(u32(_e1310), 0u, (_e1310 < 0f)), 4294967295u, (_e1310 > 4294967000f));
                                    let _e1323 = bitcast<i32>(_e1288);
                                    let _e1332 = frame.member[0u].member_1.member_8;
                                    let _e1337 = frame.member[0u].member_1.member_12;
                                    let _e1344 = (((((_e1320 % 4u) * 4u) + (_e1315 % 4u)) + (_e1337 % 16u)) % 16u);
                                    if (_e1332 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1346 = (_e1344 < 16u);
                                        if _e1346 {
                                        } else {
                                            phi_2643_ = true;
                                            break;
                                        }
                                        let _e1349 = local[_e1344][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1346 {
                                        } else {
                                            phi_2643_ = true;
                                            break;
                                        }
                                        let _e1352 = local_1[_e1344][1u];
                                        phi_1943_ = vec2<f32>(_e1349, _e1352);
                                    } else {
                                        if (_e1332 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1355 = (_e1344 < 16u);
                                            if _e1355 {
                                            } else {
                                                phi_2643_ = true;
                                                break;
                                            }
                                            let _e1358 = local_2[_e1344][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1355 {
                                            } else {
                                                phi_2643_ = true;
                                                break;
                                            }
                                            let _e1361 = local_3[_e1344][1u];
                                            phi_1942_ = vec2<f32>(_e1358, _e1361);
                                        } else {
                                            phi_1942_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1364 = phi_1942_;
                                        phi_1943_ = _e1364;
                                    }
                                    let _e1366 = phi_1943_;
                                    let _e1379 = frame.member[0u].member_1.member_6;
                                    phi_1974_ = 0u;
                                    phi_1977_ = _e1269;
                                    loop {
                                        let _e1382 = phi_1974_;
                                        let _e1384 = phi_1977_;
                                        local_11 = _e1384;
                                        let _e1385 = (_e1382 < _e1379);
                                        if _e1385 {
                                            let _e1386 = ((((_e1320 * _e1291) + _e1315) * _e1379) + _e1382);
                                            if (_e1386 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2526_ = true;
                                                break;
                                            }
                                            let _e1389 = sd_map.member[_e1386];
                                            let _e1396 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1399 = ((_e1389 * (_e686 - _e1396)) + _e1396);
                                            let _e1409 = (((((((f32((bitcast<i32>(_e1315) - _e1323)) + _e1366.x) / _e1282) * 2f) - 1f) * _e1399) * _e656) - _e857.member_1.member_4.x);
                                            let _e1410 = (((((((f32((bitcast<i32>(_e1320) - _e1323)) + _e1366.y) / _e1283) * -2f) + 1f) * _e1399) * _e664) - _e857.member_1.member_4.y);
                                            let _e1411 = (-(_e1399) - _e857.member_1.member_4.z);
                                            let _e1416 = (((_e1409 * _e857.member_1.member_6.x) + (_e1410 * _e857.member_1.member_6.y)) + (_e1411 * _e857.member_1.member_6.z));
                                            if _e898 {
                                                let _e1421 = (((_e1409 * _e1409) + (_e1410 * _e1410)) + (_e1411 * _e1411));
                                                let _e1433 = (((((_e857.member_1.member_5.x * _e1409) + (_e857.member_1.member_5.y * _e1410)) + (_e857.member_1.member_5.z * _e1411)) / sqrt(_e1421)) - 0.1f);
                                                let _e1440 = (1f - (_e1421 / (_e634 * _e634)));
                                                let _e1447 = ((select(0f, select(1f, _e1433, (_e1433 < 1f)), (_e1433 > 0f)) * select(0f, select(1f, _e1440, (_e1440 < 1f)), (_e1440 > 0f))) / _e920);
                                                phi_2142_ = select(0f, select(0f, select(1f, _e1447, (_e1447 < 1f)), (_e1447 > 0f)), (_e1421 > 0f));
                                            } else {
                                                let _e1458 = frame.member[0u].member_1.member.member_3;
                                                if (_e934 != _e934) {
                                                    phi_2467_ = true;
                                                } else {
                                                    phi_2467_ = (_e1416 >= _e934);
                                                }
                                                let _e1463 = phi_2467_;
                                                let _e1465 = (_e915 - select(_e934, _e1416, _e1463));
                                                if (_e1465 != _e1465) {
                                                    phi_2482_ = true;
                                                } else {
                                                    phi_2482_ = (0f >= _e1465);
                                                }
                                                let _e1469 = phi_2482_;
                                                let _e1474 = ((_e1416 - (_e857.member_1.member_2 * (1f + _e1458))) * (1f / _e915));
                                                phi_2142_ = ((select(_e1465, 0f, _e1469) + (select(0f, select(1f, _e1474, (_e1474 < 1f)), (_e1474 > 0f)) * (_e915 - _e934))) * (0.5f / _e915));
                                            }
                                            let _e1485 = phi_2142_;
                                            if _e898 {
                                                if (_e1384 != _e1384) {
                                                    phi_2497_ = true;
                                                } else {
                                                    phi_2497_ = (_e1485 >= _e1384);
                                                }
                                                let _e1489 = phi_2497_;
                                                phi_2151_ = select(_e1384, _e1485, _e1489);
                                            } else {
                                                if (_e1384 != _e1384) {
                                                    phi_2512_ = true;
                                                } else {
                                                    phi_2512_ = (_e1485 <= _e1384);
                                                }
                                                let _e1494 = phi_2512_;
                                                phi_2151_ = select(_e1384, _e1485, _e1494);
                                            }
                                            let _e1497 = phi_2151_;
                                            phi_1975_ = (_e1382 + 1u);
                                            phi_1978_ = _e1497;
                                        } else {
                                            phi_1975_ = u32();
                                            phi_1978_ = f32();
                                        }
                                        let _e1500 = phi_1975_;
                                        let _e1502 = phi_1978_;
                                        continue;
                                        continuing {
                                            phi_1974_ = _e1500;
                                            phi_1977_ = _e1502;
                                            phi_2526_ = _e873;
                                            break if !(_e1385);
                                        }
                                    }
                                    let _e1505 = phi_2526_;
                                    phi_2643_ = _e1505;
                                    if _e1505 {
                                        break;
                                    }
                                    let _e1507 = local_11;
                                    phi_2645_ = _e1505;
                                    phi_2156_ = ((_e879 - _e1264.member_1) + _e1507);
                                }
                                let _e1510 = phi_2645_;
                                let _e1512 = phi_2156_;
                                phi_2644_ = _e1510;
                                phi_1111_ = (_e875 + 1u);
                                phi_1116_ = _e1512;
                            } else {
                                phi_2644_ = _e873;
                                phi_1111_ = u32();
                                phi_1116_ = f32();
                            }
                            let _e1515 = phi_2644_;
                            let _e1517 = phi_1111_;
                            let _e1519 = phi_1116_;
                            continue;
                            continuing {
                                phi_2574_ = _e1515;
                                phi_1110_ = _e1517;
                                phi_1113_ = select(u32(), _e877, _e880);
                                phi_1115_ = _e1519;
                                phi_2643_ = _e1515;
                                break if !(_e880);
                            }
                        }
                        let _e1523 = phi_2643_;
                        if _e1523 {
                            break;
                        }
                        let _e1528 = frame.member[0u].member_1.member_10;
                        let _e1529 = (_e1528 == 1u);
                        let _e1534 = local_12;
                        let _e1536 = (_e622 + ((select(2f, 1f, _e1529) / f32(_e871)) * _e1534));
                        if _e1529 {
                            phi_2186_ = (1f - (2f * _e1536));
                        } else {
                            phi_2186_ = _e1536;
                        }
                        let _e1540 = phi_2186_;
                        let _e1550 = frame.member[0u].member_1.member.member_2;
                        let _e1553 = local_13;
                        phi_2201_ = type_42(pow(select(0f, select(1f, _e1540, (_e1540 < 1f)), (_e1540 > 0f)), _e1550), _e1553);
                    } else {
                        phi_2201_ = type_42();
                    }
                    let _e1556 = phi_2201_;
                    phi_2203_ = _e1556;
                    phi_2204_ = select(true, false, _e860);
                }
                let _e1559 = phi_2203_;
                let _e1561 = phi_2204_;
                if _e1561 {
                    phi_2208_ = type_42(_e622, 0u);
                } else {
                    phi_2208_ = _e1559;
                }
                let _e1563 = phi_2208_;
                if _e619 {
                } else {
                    break;
                }
                ao.member[_e618] = _e1563.member;
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
