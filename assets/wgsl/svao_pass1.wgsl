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

struct type_44 {
    member: array<atomic<u32>>,
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
var<storage, read_write> mask: type_11;
@group(0) @binding(5) 
var<storage, read_write> ray_min: type_44;
@group(0) @binding(6) 
var<storage, read_write> ray_max: type_44;
@group(0) @binding(7) 
var<storage> depth2_: type_8;

fn function_() {
    var local: array<array<f32, 2>, 56>;
    var local_1: array<f32, 56>;
    var local_2: array<f32, 56>;
    var local_3: array<f32, 56>;
    var local_4: array<f32, 56>;
    var local_5: array<f32, 56>;
    var local_6: array<array<array<f32, 2>, 4>, 4>;
    var phi_632_: bool;
    var phi_634_: bool;
    var phi_635_: bool;
    var phi_636_: bool;
    var phi_637_: bool;
    var phi_695_: bool;
    var phi_725_: f32;
    var phi_2029_: bool;
    var phi_2044_: bool;
    var phi_800_: vec2<f32>;
    var phi_827_: vec3<f32>;
    var phi_2059_: bool;
    var phi_939_: type_28;
    var phi_940_: type_28;
    var phi_942_: type_28;
    var phi_943_: type_28;
    var phi_944_: bool;
    var phi_948_: type_28;
    var phi_985_: u32;
    var phi_988_: u32;
    var phi_990_: f32;
    var phi_1031_: f32;
    var phi_1055_: f32;
    var phi_1069_: f32;
    var phi_1088_: f32;
    var phi_1144_: bool;
    var phi_1146_: bool;
    var phi_1147_: bool;
    var phi_1148_: bool;
    var phi_1149_: bool;
    var phi_1181_: f32;
    var phi_1194_: f32;
    var phi_1245_: bool;
    var phi_1277_: f32;
    var phi_1300_: bool;
    var phi_1397_: f32;
    var phi_1410_: f32;
    var phi_1423_: f32;
    var phi_1424_: f32;
    var phi_2074_: bool;
    var phi_2089_: bool;
    var phi_1447_: f32;
    var phi_1454_: f32;
    var phi_2104_: bool;
    var phi_1476_: f32;
    var phi_1484_: bool;
    var phi_1519_: bool;
    var phi_1616_: f32;
    var phi_1629_: f32;
    var phi_1642_: f32;
    var phi_1643_: f32;
    var phi_2119_: bool;
    var phi_2134_: bool;
    var phi_1666_: f32;
    var phi_1673_: f32;
    var phi_2149_: bool;
    var phi_2164_: bool;
    var phi_1682_: f32;
    var phi_2179_: bool;
    var phi_1684_: f32;
    var phi_1685_: f32;
    var phi_1686_: f32;
    var phi_1687_: f32;
    var phi_1701_: bool;
    var phi_1702_: bool;
    var phi_1703_: bool;
    var phi_1711_: f32;
    var phi_2194_: bool;
    var phi_1736_: f32;
    var phi_1744_: bool;
    var phi_1748_: bool;
    var phi_1798_: f32;
    var phi_1812_: f32;
    var phi_2209_: bool;
    var phi_2224_: bool;
    var phi_1869_: f32;
    var phi_1876_: u32;
    var phi_1891_: u32;
    var phi_1899_: u32;
    var phi_1900_: u32;
    var phi_1901_: u32;
    var phi_1902_: f32;
    var phi_1903_: u32;
    var phi_1904_: f32;
    var phi_986_: u32;
    var phi_989_: u32;
    var phi_991_: f32;
    var phi_2229_: bool;
    var local_7: f32;
    var local_8: u32;
    var phi_1937_: f32;
    var phi_1947_: f32;
    var local_9: u32;
    var phi_1961_: f32;
    var local_10: u32;
    var phi_1966_: type_41;
    var phi_1968_: type_41;

    switch bitcast<i32>(0u) {
        default: {
            let _e485 = id_1;
            let _e490 = arrayLength((&depth.member));
            let _e501 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e513 = frame.member[0u].member_1.member.member.member_4;
            let _e514 = (_e485.x + _e513);
            let _e515 = (_e485.y + _e513);
            let _e523 = frame.member[0u].member_1.member.member.member[0u];
            let _e528 = select(select(u32(_e523), 0u, (_e523 < 0f)), 4294967295u, (_e523 > 4294967000f));
            let _e536 = frame.member[0u].member_1.member.member.member[1u];
            let _e541 = select(select(u32(_e536), 0u, (_e536 < 0f)), 4294967295u, (_e536 > 4294967000f));
            if (_e514 >= _e513) {
                if (_e515 >= _e513) {
                    let _e545 = ((_e514 + _e513) < _e528);
                    if _e545 {
                        phi_632_ = ((_e515 + _e513) < _e541);
                    } else {
                        phi_632_ = bool();
                    }
                    let _e549 = phi_632_;
                    phi_634_ = _e549;
                    phi_635_ = select(true, false, _e545);
                } else {
                    phi_634_ = bool();
                    phi_635_ = true;
                }
                let _e552 = phi_634_;
                let _e554 = phi_635_;
                phi_636_ = _e552;
                phi_637_ = _e554;
            } else {
                phi_636_ = bool();
                phi_637_ = true;
            }
            let _e556 = phi_636_;
            let _e558 = phi_637_;
            if select(_e556, false, _e558) {
                let _e565 = frame.member[0u].member_1.member.member_1;
                let _e571 = frame.member[0u].member_1.member.member_4;
                let _e576 = ((f32(_e514) + 0.5f) / _e523);
                let _e577 = ((f32(_e515) + 0.5f) / _e536);
                let _e579 = ((_e515 * _e528) + _e514);
                if (_e579 < _e490) {
                } else {
                    break;
                }
                let _e582 = depth.member[_e579];
                let _e589 = frame.member[0u].member_1.member.member.member_3;
                if (_e582 > 0f) {
                    phi_695_ = (_e582 < _e589);
                } else {
                    phi_695_ = false;
                }
                let _e593 = phi_695_;
                if _e593 {
                    let _e601 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e609 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e619 = (0.5f * (((_e565 * _e523) / ((2f * _e601) * _e582)) + ((_e565 * _e536) / ((2f * _e609) * _e582))));
                    let _e620 = (_e619 > _e571);
                    if _e620 {
                        phi_725_ = ((_e565 * _e571) / _e619);
                    } else {
                        phi_725_ = _e565;
                    }
                    let _e624 = phi_725_;
                    let _e625 = select(_e619, _e571, _e620);
                    let _e626 = (_e625 < 0.5f);
                    if _e626 {
                        phi_939_ = type_28(0u, type_28().member_1);
                        phi_940_ = type_28();
                    } else {
                        let _e635 = ((((2f * _e576) - 1f) * _e582) * _e601);
                        let _e637 = (((1f - (2f * _e577)) * _e582) * _e609);
                        let _e638 = -(_e582);
                        if (_e579 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e642 = normals.member[_e579];
                        let _e650 = (f32((bitcast<i32>(((_e642 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e650 != _e650) {
                            phi_2029_ = true;
                        } else {
                            phi_2029_ = (-1f >= _e650);
                        }
                        let _e654 = phi_2029_;
                        let _e655 = select(_e650, -1f, _e654);
                        let _e665 = (f32((bitcast<i32>((((_e642 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e665 != _e665) {
                            phi_2044_ = true;
                        } else {
                            phi_2044_ = (-1f >= _e665);
                        }
                        let _e669 = phi_2044_;
                        let _e670 = select(_e665, -1f, _e669);
                        let _e673 = (1f - abs(_e655));
                        let _e674 = abs(_e670);
                        let _e675 = (_e673 - _e674);
                        if (_e675 < 0f) {
                            phi_800_ = vec2<f32>(((1f - _e674) * select(1f, -1f, (_e655 < 0f))), (_e673 * select(1f, -1f, (_e670 < 0f))));
                        } else {
                            phi_800_ = vec2<f32>(_e655, _e670);
                        }
                        let _e686 = phi_800_;
                        let _e695 = (1f / sqrt((((_e686.x * _e686.x) + (_e686.y * _e686.y)) + (_e675 * _e675))));
                        let _e696 = (_e686.x * _e695);
                        let _e697 = (_e686.y * _e695);
                        let _e698 = (_e675 * _e695);
                        if ((((_e635 * _e696) + (_e637 * _e697)) + (_e638 * _e698)) > 0f) {
                            phi_827_ = vec3<f32>(-(_e696), -(_e697), -(_e698));
                        } else {
                            phi_827_ = vec3<f32>(_e696, _e697, _e698);
                        }
                        let _e711 = phi_827_;
                        local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e712 = (_e515 % 4u);
                        if (_e712 < 4u) {
                        } else {
                            break;
                        }
                        let _e714 = (_e514 % 4u);
                        if (_e714 < 4u) {
                        } else {
                            break;
                        }
                        let _e718 = local_6[_e712][_e714];
                        let _e728 = sqrt((((_e635 * _e635) + (_e637 * _e637)) + (_e638 * _e638)));
                        let _e729 = (-(_e635) / _e728);
                        let _e730 = (-(_e637) / _e728);
                        let _e731 = (_e582 / _e728);
                        let _e734 = -((_e718[1] * _e731));
                        let _e735 = (_e731 * _e718[0]);
                        let _e738 = ((_e729 * _e718[1]) - (_e718[0] * _e730));
                        let _e745 = (1f / sqrt((((_e734 * _e734) + (_e735 * _e735)) + (_e738 * _e738))));
                        let _e746 = (_e734 * _e745);
                        let _e747 = (_e735 * _e745);
                        let _e748 = (_e738 * _e745);
                        let _e752 = ((_e747 * _e731) - (_e730 * _e748));
                        let _e755 = ((_e748 * _e729) - (_e731 * _e746));
                        let _e758 = ((_e746 * _e730) - (_e729 * _e747));
                        let _e777 = (((_e711.x * _e729) + (_e711.y * _e730)) + (_e711.z * _e731));
                        let _e781 = abs(_e777);
                        if (_e781 != _e781) {
                            phi_2059_ = true;
                        } else {
                            phi_2059_ = (0.0001f >= _e781);
                        }
                        let _e785 = phi_2059_;
                        phi_939_ = type_28();
                        phi_940_ = type_28(1u, type_27(vec2<u32>(_e514, _e515), vec2<f32>(_e576, _e577), _e624, _e625, vec3<f32>(_e635, _e637, _e638), _e711, vec3<f32>(_e729, _e730, _e731), vec3<f32>(_e752, _e755, _e758), vec3<f32>(_e746, _e747, _e748), vec3<f32>((((_e711.x * _e752) + (_e711.y * _e755)) + (_e711.z * _e758)), (((_e711.x * _e746) + (_e711.y * _e747)) + (_e711.z * _e748)), _e777), (1f / (select(1f, -1f, (_e777 < 0f)) * select(_e781, 0.0001f, _e785)))));
                    }
                    let _e794 = phi_939_;
                    let _e796 = phi_940_;
                    phi_942_ = _e794;
                    phi_943_ = _e796;
                    phi_944_ = _e626;
                } else {
                    phi_942_ = type_28(0u, type_28().member_1);
                    phi_943_ = type_28();
                    phi_944_ = true;
                }
                let _e801 = phi_942_;
                let _e803 = phi_943_;
                let _e805 = phi_944_;
                if _e805 {
                    phi_948_ = _e801;
                } else {
                    phi_948_ = _e803;
                }
                let _e807 = phi_948_;
                if (bitcast<i32>(_e807.member) != 0i) {
                    let _e816 = frame.member[0u].member_1.member_1;
                    let _e817 = (_e816 == 1u);
                    let _e828 = sqrt((((_e807.member_1.member_4.x * _e807.member_1.member_4.x) + (_e807.member_1.member_4.y * _e807.member_1.member_4.y)) + (_e807.member_1.member_4.z * _e807.member_1.member_4.z)));
                    let _e833 = frame.member[0u].member_1.member_11;
                    let _e838 = (8u << bitcast<u32>((select(_e833, 2u, (2u < _e833)) & 31u)));
                    phi_985_ = 0u;
                    phi_988_ = 0u;
                    phi_990_ = 0f;
                    loop {
                        let _e840 = phi_985_;
                        let _e842 = phi_988_;
                        let _e844 = phi_990_;
                        local_7 = _e844;
                        local_8 = _e842;
                        local_9 = _e842;
                        local_10 = _e842;
                        let _e845 = (_e840 < _e838);
                        if _e845 {
                            let _e850 = frame.member[0u].member_1.member_10;
                            let _e852 = ((_e838 + _e840) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e853 = (_e852 < 56u);
                            if _e853 {
                            } else {
                                phi_2229_ = true;
                                break;
                            }
                            let _e855 = local[_e852];
                            let _e858 = (_e850 == 1u);
                            if _e858 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e853 {
                                } else {
                                    phi_2229_ = true;
                                    break;
                                }
                                let _e860 = local_1[_e852];
                                phi_1031_ = _e860;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e853 {
                                } else {
                                    phi_2229_ = true;
                                    break;
                                }
                                let _e862 = local_2[_e852];
                                phi_1031_ = _e862;
                            }
                            let _e864 = phi_1031_;
                            let _e866 = (_e864 * _e807.member_1.member_2);
                            let _e867 = (_e866 * _e855[0]);
                            let _e868 = (_e866 * _e855[1]);
                            if _e858 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e853 {
                                } else {
                                    phi_2229_ = true;
                                    break;
                                }
                                let _e870 = local_3[_e852];
                                phi_1055_ = _e870;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e853 {
                                } else {
                                    phi_2229_ = true;
                                    break;
                                }
                                let _e872 = local_4[_e852];
                                phi_1055_ = _e872;
                            }
                            let _e874 = phi_1055_;
                            let _e875 = (_e874 * _e807.member_1.member_2);
                            if _e858 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e853 {
                                } else {
                                    phi_2229_ = true;
                                    break;
                                }
                                let _e877 = local_5[_e852];
                                phi_1069_ = _e877;
                            } else {
                                phi_1069_ = (2f * _e875);
                            }
                            let _e880 = phi_1069_;
                            let _e890 = (-(((_e867 * _e807.member_1.member_9.x) + (_e868 * _e807.member_1.member_9.y))) * _e807.member_1.member_10);
                            let _e891 = -(_e875);
                            if (_e890 > _e891) {
                                phi_1088_ = select(_e875, _e890, (_e890 < _e875));
                            } else {
                                phi_1088_ = _e891;
                            }
                            let _e896 = phi_1088_;
                            let _e897 = (_e875 - _e896);
                            let _e920 = (-0.5f / ((_e807.member_1.member_4.z + (_e807.member_1.member_7.z * _e867)) + (_e807.member_1.member_8.z * _e868)));
                            let _e929 = frame.member[0u].member_1.member.member.member_1[0u];
                            let _e931 = (0.5f + ((((_e807.member_1.member_4.x + (_e807.member_1.member_7.x * _e867)) + (_e807.member_1.member_8.x * _e868)) * _e920) / _e929));
                            let _e940 = frame.member[0u].member_1.member.member.member_1[1u];
                            let _e942 = (0.5f - ((((_e807.member_1.member_4.y + (_e807.member_1.member_7.y * _e867)) + (_e807.member_1.member_8.y * _e868)) * _e920) / _e940));
                            if (_e931 >= 0f) {
                                if (_e931 <= 1f) {
                                    let _e945 = (_e942 >= 0f);
                                    if _e945 {
                                        phi_1144_ = (_e942 <= 1f);
                                    } else {
                                        phi_1144_ = bool();
                                    }
                                    let _e948 = phi_1144_;
                                    phi_1146_ = _e948;
                                    phi_1147_ = select(true, false, _e945);
                                } else {
                                    phi_1146_ = bool();
                                    phi_1147_ = true;
                                }
                                let _e951 = phi_1146_;
                                let _e953 = phi_1147_;
                                phi_1148_ = _e951;
                                phi_1149_ = _e953;
                            } else {
                                phi_1148_ = bool();
                                phi_1149_ = true;
                            }
                            let _e955 = phi_1148_;
                            let _e957 = phi_1149_;
                            if (_e931 > 0f) {
                                phi_1181_ = select(1f, _e931, (_e931 < 1f));
                            } else {
                                phi_1181_ = 0f;
                            }
                            let _e963 = phi_1181_;
                            let _e964 = (_e963 * _e523);
                            if (_e942 > 0f) {
                                phi_1194_ = select(1f, _e942, (_e942 < 1f));
                            } else {
                                phi_1194_ = 0f;
                            }
                            let _e969 = phi_1194_;
                            let _e970 = (_e969 * _e536);
                            let _e975 = select(select(u32(_e964), 0u, (_e964 < 0f)), 4294967295u, (_e964 > 4294967000f));
                            let _e976 = (_e528 - 1u);
                            let _e978 = select(_e975, _e976, (_e976 < _e975));
                            let _e983 = select(select(u32(_e970), 0u, (_e970 < 0f)), 4294967295u, (_e970 > 4294967000f));
                            let _e984 = (_e541 - 1u);
                            let _e986 = select(_e983, _e984, (_e984 < _e983));
                            let _e993 = ((_e807.member_1.member_1.x - _e931) * _e523);
                            let _e994 = ((_e807.member_1.member_1.y - _e942) * _e536);
                            let _e998 = sqrt(((_e993 * _e993) + (_e994 * _e994)));
                            if (_e978 == _e807.member_1.member.x) {
                                phi_1245_ = (_e986 == _e807.member_1.member.y);
                            } else {
                                phi_1245_ = false;
                            }
                            let _e1006 = phi_1245_;
                            if (_e897 > (0.2f * _e875)) {
                                if _e1006 {
                                    if _e858 {
                                        phi_1277_ = 0f;
                                    } else {
                                        phi_1277_ = (_e897 / (2f * _e875));
                                    }
                                    let _e1010 = phi_1277_;
                                    phi_1901_ = _e842;
                                    phi_1902_ = (_e844 + _e1010);
                                } else {
                                    let _e1013 = ((_e986 * _e528) + _e978);
                                    if (_e1013 < _e490) {
                                    } else {
                                        phi_2229_ = true;
                                        break;
                                    }
                                    let _e1016 = depth.member[_e1013];
                                    if (_e1016 > 0f) {
                                        phi_1300_ = (_e1016 < _e589);
                                    } else {
                                        phi_1300_ = false;
                                    }
                                    let _e1020 = phi_1300_;
                                    let _e1021 = select(_e589, _e1016, _e1020);
                                    let _e1031 = ((2f * ((f32(_e978) + 0.5f) * (1f / _e523))) - 1f);
                                    let _e1033 = (1f - (2f * ((f32(_e986) + 0.5f) * (1f / _e536))));
                                    let _e1039 = (((_e1031 * _e1021) * _e929) - _e807.member_1.member_4.x);
                                    let _e1040 = (((_e1033 * _e1021) * _e940) - _e807.member_1.member_4.y);
                                    let _e1041 = (-(_e1021) - _e807.member_1.member_4.z);
                                    let _e1050 = (((_e1039 * _e807.member_1.member_6.x) + (_e1040 * _e807.member_1.member_6.y)) + (_e1041 * _e807.member_1.member_6.z));
                                    if _e858 {
                                        let _e1055 = (((_e1039 * _e1039) + (_e1040 * _e1040)) + (_e1041 * _e1041));
                                        if (_e1055 <= 0f) {
                                            phi_1424_ = 0f;
                                        } else {
                                            let _e1068 = (((((_e807.member_1.member_5.x * _e1039) + (_e807.member_1.member_5.y * _e1040)) + (_e807.member_1.member_5.z * _e1041)) / sqrt(_e1055)) - 0.1f);
                                            if (_e1068 > 0f) {
                                                phi_1397_ = select(1f, _e1068, (_e1068 < 1f));
                                            } else {
                                                phi_1397_ = 0f;
                                            }
                                            let _e1073 = phi_1397_;
                                            let _e1076 = (1f - (_e1055 / (_e565 * _e565)));
                                            if (_e1076 > 0f) {
                                                phi_1410_ = select(1f, _e1076, (_e1076 < 1f));
                                            } else {
                                                phi_1410_ = 0f;
                                            }
                                            let _e1081 = phi_1410_;
                                            let _e1083 = ((_e1073 * _e1081) / _e880);
                                            if (_e1083 > 0f) {
                                                phi_1423_ = select(1f, _e1083, (_e1083 < 1f));
                                            } else {
                                                phi_1423_ = 0f;
                                            }
                                            let _e1088 = phi_1423_;
                                            phi_1424_ = _e1088;
                                        }
                                        let _e1090 = phi_1424_;
                                        phi_1454_ = _e1090;
                                    } else {
                                        let _e1096 = frame.member[0u].member_1.member.member_3;
                                        if (_e896 != _e896) {
                                            phi_2074_ = true;
                                        } else {
                                            phi_2074_ = (_e1050 >= _e896);
                                        }
                                        let _e1101 = phi_2074_;
                                        let _e1103 = (_e875 - select(_e896, _e1050, _e1101));
                                        if (_e1103 != _e1103) {
                                            phi_2089_ = true;
                                        } else {
                                            phi_2089_ = (0f >= _e1103);
                                        }
                                        let _e1107 = phi_2089_;
                                        let _e1112 = ((_e1050 - ((1f + _e1096) * _e807.member_1.member_2)) * (1f / _e875));
                                        if (_e1112 > 0f) {
                                            phi_1447_ = select(1f, _e1112, (_e1112 < 1f));
                                        } else {
                                            phi_1447_ = 0f;
                                        }
                                        let _e1117 = phi_1447_;
                                        phi_1454_ = ((select(_e1103, 0f, _e1107) + (_e1117 * _e897)) * (0.5f / _e875));
                                    }
                                    let _e1123 = phi_1454_;
                                    let _e1128 = frame.member[0u].member_1.member_9;
                                    if (_e1128 == 0u) {
                                        phi_1686_ = _e1123;
                                        phi_1687_ = _e1050;
                                    } else {
                                        if _e858 {
                                            let _e1130 = (0.1f * _e807.member_1.member_2);
                                            if (_e875 != _e875) {
                                                phi_2104_ = true;
                                            } else {
                                                phi_2104_ = (_e1130 >= _e875);
                                            }
                                            let _e1134 = phi_2104_;
                                            phi_1476_ = select(_e875, _e1130, _e1134);
                                        } else {
                                            let _e1141 = frame.member[0u].member_1.member.member_3;
                                            phi_1476_ = ((1f + _e1141) * _e807.member_1.member_2);
                                        }
                                        let _e1145 = phi_1476_;
                                        if (_e1050 > _e1145) {
                                            let _e1151 = frame.member[0u].member_1.member_3;
                                            phi_1484_ = (_e998 > _e1151);
                                        } else {
                                            phi_1484_ = false;
                                        }
                                        let _e1154 = phi_1484_;
                                        if _e1154 {
                                            if (_e1013 < arrayLength((&depth2_.member))) {
                                            } else {
                                                phi_2229_ = true;
                                                break;
                                            }
                                            let _e1158 = depth2_.member[_e1013];
                                            if (_e1158 > 0f) {
                                                phi_1519_ = (_e1158 < _e589);
                                            } else {
                                                phi_1519_ = false;
                                            }
                                            let _e1162 = phi_1519_;
                                            let _e1163 = select(_e589, _e1158, _e1162);
                                            let _e1169 = (((_e1031 * _e1163) * _e929) - _e807.member_1.member_4.x);
                                            let _e1170 = (((_e1033 * _e1163) * _e940) - _e807.member_1.member_4.y);
                                            let _e1171 = (-(_e1163) - _e807.member_1.member_4.z);
                                            let _e1176 = (((_e1169 * _e807.member_1.member_6.x) + (_e1170 * _e807.member_1.member_6.y)) + (_e1171 * _e807.member_1.member_6.z));
                                            if _e858 {
                                                let _e1181 = (((_e1169 * _e1169) + (_e1170 * _e1170)) + (_e1171 * _e1171));
                                                if (_e1181 <= 0f) {
                                                    phi_1643_ = 0f;
                                                } else {
                                                    let _e1194 = (((((_e807.member_1.member_5.x * _e1169) + (_e807.member_1.member_5.y * _e1170)) + (_e807.member_1.member_5.z * _e1171)) / sqrt(_e1181)) - 0.1f);
                                                    if (_e1194 > 0f) {
                                                        phi_1616_ = select(1f, _e1194, (_e1194 < 1f));
                                                    } else {
                                                        phi_1616_ = 0f;
                                                    }
                                                    let _e1199 = phi_1616_;
                                                    let _e1202 = (1f - (_e1181 / (_e565 * _e565)));
                                                    if (_e1202 > 0f) {
                                                        phi_1629_ = select(1f, _e1202, (_e1202 < 1f));
                                                    } else {
                                                        phi_1629_ = 0f;
                                                    }
                                                    let _e1207 = phi_1629_;
                                                    let _e1209 = ((_e1199 * _e1207) / _e880);
                                                    if (_e1209 > 0f) {
                                                        phi_1642_ = select(1f, _e1209, (_e1209 < 1f));
                                                    } else {
                                                        phi_1642_ = 0f;
                                                    }
                                                    let _e1214 = phi_1642_;
                                                    phi_1643_ = _e1214;
                                                }
                                                let _e1216 = phi_1643_;
                                                phi_1673_ = _e1216;
                                            } else {
                                                let _e1222 = frame.member[0u].member_1.member.member_3;
                                                if (_e896 != _e896) {
                                                    phi_2119_ = true;
                                                } else {
                                                    phi_2119_ = (_e1176 >= _e896);
                                                }
                                                let _e1227 = phi_2119_;
                                                let _e1229 = (_e875 - select(_e896, _e1176, _e1227));
                                                if (_e1229 != _e1229) {
                                                    phi_2134_ = true;
                                                } else {
                                                    phi_2134_ = (0f >= _e1229);
                                                }
                                                let _e1233 = phi_2134_;
                                                let _e1238 = ((_e1176 - ((1f + _e1222) * _e807.member_1.member_2)) * (1f / _e875));
                                                if (_e1238 > 0f) {
                                                    phi_1666_ = select(1f, _e1238, (_e1238 < 1f));
                                                } else {
                                                    phi_1666_ = 0f;
                                                }
                                                let _e1243 = phi_1666_;
                                                phi_1673_ = ((select(_e1229, 0f, _e1233) + (_e1243 * _e897)) * (0.5f / _e875));
                                            }
                                            let _e1249 = phi_1673_;
                                            if _e858 {
                                                if (_e1123 != _e1123) {
                                                    phi_2149_ = true;
                                                } else {
                                                    phi_2149_ = (_e1249 >= _e1123);
                                                }
                                                let _e1253 = phi_2149_;
                                                phi_1682_ = select(_e1123, _e1249, _e1253);
                                            } else {
                                                if (_e1123 != _e1123) {
                                                    phi_2164_ = true;
                                                } else {
                                                    phi_2164_ = (_e1249 <= _e1123);
                                                }
                                                let _e1258 = phi_2164_;
                                                phi_1682_ = select(_e1123, _e1249, _e1258);
                                            }
                                            let _e1261 = phi_1682_;
                                            if (_e1050 != _e1050) {
                                                phi_2179_ = true;
                                            } else {
                                                phi_2179_ = (_e1176 <= _e1050);
                                            }
                                            let _e1265 = phi_2179_;
                                            phi_1684_ = _e1261;
                                            phi_1685_ = select(_e1050, _e1176, _e1265);
                                        } else {
                                            phi_1684_ = _e1123;
                                            phi_1685_ = _e1050;
                                        }
                                        let _e1268 = phi_1684_;
                                        let _e1270 = phi_1685_;
                                        phi_1686_ = _e1268;
                                        phi_1687_ = _e1270;
                                    }
                                    let _e1272 = phi_1686_;
                                    let _e1274 = phi_1687_;
                                    if select(_e955, false, _e957) {
                                        phi_1703_ = false;
                                    } else {
                                        if (_e816 == 2u) {
                                            phi_1702_ = true;
                                        } else {
                                            if _e817 {
                                                let _e1280 = frame.member[0u].member_1.member_4;
                                                phi_1701_ = (_e1280 > 0u);
                                            } else {
                                                phi_1701_ = false;
                                            }
                                            let _e1283 = phi_1701_;
                                            phi_1702_ = _e1283;
                                        }
                                        let _e1285 = phi_1702_;
                                        phi_1703_ = _e1285;
                                    }
                                    let _e1287 = phi_1703_;
                                    if _e1287 {
                                        phi_1711_ = select(_e1274, 0x1.fffffep+127f, _e817);
                                    } else {
                                        phi_1711_ = _e1274;
                                    }
                                    let _e1290 = phi_1711_;
                                    if (_e816 != 0u) {
                                        if _e1287 {
                                            phi_1748_ = true;
                                        } else {
                                            if _e858 {
                                                let _e1292 = (0.1f * _e807.member_1.member_2);
                                                if (_e875 != _e875) {
                                                    phi_2194_ = true;
                                                } else {
                                                    phi_2194_ = (_e1292 >= _e875);
                                                }
                                                let _e1296 = phi_2194_;
                                                phi_1736_ = select(_e875, _e1292, _e1296);
                                            } else {
                                                let _e1303 = frame.member[0u].member_1.member.member_3;
                                                phi_1736_ = ((1f + _e1303) * _e807.member_1.member_2);
                                            }
                                            let _e1307 = phi_1736_;
                                            if (_e1290 > _e1307) {
                                                let _e1313 = frame.member[0u].member_1.member_3;
                                                phi_1744_ = (_e998 > _e1313);
                                            } else {
                                                phi_1744_ = false;
                                            }
                                            let _e1316 = phi_1744_;
                                            phi_1748_ = _e1316;
                                        }
                                        let _e1318 = phi_1748_;
                                        if _e1318 {
                                            if _e817 {
                                                let _e1328 = frame.member[0u].member_1.member_5[0u];
                                                let _e1334 = frame.member[0u].member_1.member_5[1u];
                                                let _e1341 = frame.member[0u].member_1.member_4;
                                                let _e1342 = f32(_e1341);
                                                let _e1343 = (2u * _e1341);
                                                let _e1344 = (_e1328 + _e1343);
                                                let _e1350 = (floor((_e931 * f32(_e1328))) + _e1342);
                                                let _e1351 = f32((_e1344 - 1u));
                                                if (_e1350 > 0f) {
                                                    phi_1798_ = select(_e1351, _e1350, (_e1350 < _e1351));
                                                } else {
                                                    phi_1798_ = 0f;
                                                }
                                                let _e1356 = phi_1798_;
                                                let _e1359 = (floor((_e942 * f32(_e1334))) + _e1342);
                                                let _e1360 = f32(((_e1334 + _e1343) - 1u));
                                                if (_e1359 > 0f) {
                                                    phi_1812_ = select(_e1360, _e1359, (_e1359 < _e1360));
                                                } else {
                                                    phi_1812_ = 0f;
                                                }
                                                let _e1365 = phi_1812_;
                                                let _e1377 = ((select(select(u32(_e1365), 0u, (_e1365 < 0f)), 4294967295u, (_e1365 > 4294967000f)) * _e1344) + select(select(u32(_e1356), 0u, (_e1356 < 0f)), 4294967295u, (_e1356 > 4294967000f)));
                                                let _e1382 = frame.member[0u].member_1.member_2;
                                                if (_e1382 == 0u) {
                                                    if (_e1377 < _e501) {
                                                    } else {
                                                        phi_2229_ = true;
                                                        break;
                                                    }
                                                    let _e1387 = atomicMax((&ray_max.member[_e1377]), 1u);
                                                } else {
                                                    if _e858 {
                                                        if (_e1290 != _e1290) {
                                                            phi_2209_ = true;
                                                        } else {
                                                            phi_2209_ = (_e875 <= _e1290);
                                                        }
                                                        let _e1391 = phi_2209_;
                                                        phi_1869_ = select(_e1290, _e875, _e1391);
                                                    } else {
                                                        let _e1398 = frame.member[0u].member_1.member.member_3;
                                                        let _e1401 = (((1f + _e1398) * _e807.member_1.member_2) + _e875);
                                                        if (_e1290 != _e1290) {
                                                            phi_2224_ = true;
                                                        } else {
                                                            phi_2224_ = (_e1401 <= _e1290);
                                                        }
                                                        let _e1405 = phi_2224_;
                                                        phi_1869_ = select(_e1290, _e1401, _e1405);
                                                    }
                                                    let _e1408 = phi_1869_;
                                                    let _e1409 = (_e828 - _e1408);
                                                    if (_e1409 > 0f) {
                                                        phi_1876_ = bitcast<u32>(_e1409);
                                                    } else {
                                                        phi_1876_ = 0u;
                                                    }
                                                    let _e1413 = phi_1876_;
                                                    if (_e1377 < arrayLength((&ray_min.member))) {
                                                    } else {
                                                        phi_2229_ = true;
                                                        break;
                                                    }
                                                    let _e1417 = atomicMin((&ray_min.member[_e1377]), _e1413);
                                                    let _e1418 = (_e828 - _e896);
                                                    if (_e1418 > 0f) {
                                                        phi_1891_ = bitcast<u32>(_e1418);
                                                    } else {
                                                        phi_1891_ = 0u;
                                                    }
                                                    let _e1422 = phi_1891_;
                                                    if (_e1377 < _e501) {
                                                    } else {
                                                        phi_2229_ = true;
                                                        break;
                                                    }
                                                    let _e1426 = atomicMax((&ray_max.member[_e1377]), _e1422);
                                                }
                                            }
                                            phi_1899_ = (_e842 | (1u << bitcast<u32>((_e840 & 31u))));
                                        } else {
                                            phi_1899_ = _e842;
                                        }
                                        let _e1428 = phi_1899_;
                                        phi_1900_ = _e1428;
                                    } else {
                                        phi_1900_ = _e842;
                                    }
                                    let _e1430 = phi_1900_;
                                    phi_1901_ = _e1430;
                                    phi_1902_ = (_e844 + _e1272);
                                }
                                let _e1432 = phi_1901_;
                                let _e1434 = phi_1902_;
                                phi_1903_ = _e1432;
                                phi_1904_ = _e1434;
                            } else {
                                phi_1903_ = _e842;
                                phi_1904_ = _e844;
                            }
                            let _e1436 = phi_1903_;
                            let _e1438 = phi_1904_;
                            phi_986_ = (_e840 + 1u);
                            phi_989_ = _e1436;
                            phi_991_ = _e1438;
                        } else {
                            phi_986_ = u32();
                            phi_989_ = u32();
                            phi_991_ = f32();
                        }
                        let _e1441 = phi_986_;
                        let _e1443 = phi_989_;
                        let _e1445 = phi_991_;
                        continue;
                        continuing {
                            phi_985_ = _e1441;
                            phi_988_ = _e1443;
                            phi_990_ = _e1445;
                            phi_2229_ = false;
                            break if !(_e845);
                        }
                    }
                    let _e1448 = phi_2229_;
                    if _e1448 {
                        break;
                    }
                    let _e1453 = frame.member[0u].member_1.member_10;
                    let _e1454 = (_e1453 == 1u);
                    let _e1459 = local_7;
                    let _e1460 = ((select(2f, 1f, _e1454) / f32(_e838)) * _e1459);
                    let _e1462 = local_8;
                    if (_e1462 == 0u) {
                        if _e1454 {
                            phi_1937_ = (1f - (2f * _e1460));
                        } else {
                            phi_1937_ = _e1460;
                        }
                        let _e1467 = phi_1937_;
                        if (_e1467 > 0f) {
                            phi_1947_ = select(1f, _e1467, (_e1467 < 1f));
                        } else {
                            phi_1947_ = 0f;
                        }
                        let _e1472 = phi_1947_;
                        let _e1478 = frame.member[0u].member_1.member.member_2;
                        let _e1481 = local_9;
                        phi_1966_ = type_41(pow(_e1472, _e1478), _e1481);
                    } else {
                        if (_e1460 > 0f) {
                            phi_1961_ = select(1f, _e1460, (_e1460 < 1f));
                        } else {
                            phi_1961_ = 0f;
                        }
                        let _e1487 = phi_1961_;
                        let _e1492 = local_10;
                        phi_1966_ = type_41((round((_e1487 * 255f)) * 0.003921569f), _e1492);
                    }
                    let _e1495 = phi_1966_;
                    phi_1968_ = _e1495;
                } else {
                    phi_1968_ = type_41(1f, 0u);
                }
                let _e1497 = phi_1968_;
                if (_e579 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e579] = _e1497.member;
                if (_e579 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e579] = _e1497.member_1;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn svao_pass1_(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
