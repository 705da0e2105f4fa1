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

struct type_46 {
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
var<storage, read_write> ray_min: type_46;
@group(0) @binding(6) 
var<storage, read_write> ray_max: type_46;
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
    var phi_748_: bool;
    var phi_750_: bool;
    var phi_751_: bool;
    var phi_752_: bool;
    var phi_753_: bool;
    var phi_841_: f32;
    var phi_2132_: bool;
    var phi_2147_: bool;
    var phi_917_: vec2<f32>;
    var phi_944_: vec3<f32>;
    var phi_2162_: bool;
    var phi_1056_: type_28;
    var phi_1057_: type_28;
    var phi_1059_: type_28;
    var phi_1060_: type_28;
    var phi_1061_: bool;
    var phi_1065_: type_28;
    var phi_1087_: u32;
    var phi_1090_: u32;
    var phi_1092_: f32;
    var phi_1157_: f32;
    var phi_1182_: f32;
    var phi_1195_: f32;
    var phi_1308_: bool;
    var phi_2268_: bool;
    var phi_2283_: bool;
    var phi_1496_: f32;
    var phi_2298_: bool;
    var phi_1519_: f32;
    var phi_2350_: bool;
    var phi_2365_: bool;
    var phi_1715_: f32;
    var phi_2380_: bool;
    var phi_2395_: bool;
    var phi_2410_: bool;
    var phi_1729_: f32;
    var phi_1735_: type_42;
    var phi_1751_: f32;
    var phi_1770_: bool;
    var phi_1771_: bool;
    var phi_1783_: f32;
    var phi_2425_: bool;
    var phi_1802_: f32;
    var phi_2440_: bool;
    var phi_2455_: bool;
    var phi_1954_: f32;
    var phi_1961_: u32;
    var phi_1975_: u32;
    var phi_1983_: u32;
    var phi_1088_: u32;
    var phi_1091_: u32;
    var phi_1093_: f32;
    var phi_2499_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_2016_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2045_: type_43;
    var phi_2050_: type_43;

    switch bitcast<i32>(0u) {
        default: {
            let _e486 = id_1;
            let _e491 = arrayLength((&depth.member));
            let _e502 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e514 = frame.member[0u].member_1.member.member.member_4;
            let _e515 = (_e486.x + _e514);
            let _e516 = (_e486.y + _e514);
            let _e529 = frame.member[0u].member_1.member.member.member[0u];
            let _e534 = select(select(u32(_e529), 0u, (_e529 < 0f)), 4294967295u, (_e529 > 4294967000f));
            let _e542 = frame.member[0u].member_1.member.member.member[1u];
            if (_e515 >= _e514) {
                if (_e516 >= _e514) {
                    let _e551 = ((_e515 + _e514) < _e534);
                    if _e551 {
                        phi_748_ = ((_e516 + _e514) < select(select(u32(_e542), 0u, (_e542 < 0f)), 4294967295u, (_e542 > 4294967000f)));
                    } else {
                        phi_748_ = bool();
                    }
                    let _e555 = phi_748_;
                    phi_750_ = _e555;
                    phi_751_ = select(true, false, _e551);
                } else {
                    phi_750_ = bool();
                    phi_751_ = true;
                }
                let _e558 = phi_750_;
                let _e560 = phi_751_;
                phi_752_ = _e558;
                phi_753_ = _e560;
            } else {
                phi_752_ = bool();
                phi_753_ = true;
            }
            let _e562 = phi_752_;
            let _e564 = phi_753_;
            if select(_e562, false, _e564) {
                let _e571 = frame.member[0u].member_1.member.member_1;
                let _e577 = frame.member[0u].member_1.member.member_4;
                let _e582 = ((f32(_e515) + 0.5f) / _e529);
                let _e583 = ((f32(_e516) + 0.5f) / _e542);
                let _e585 = ((_e516 * _e534) + _e515);
                if (_e585 < _e491) {
                } else {
                    break;
                }
                let _e588 = depth.member[_e585];
                let _e595 = frame.member[0u].member_1.member.member.member_3;
                if select(false, (_e588 < _e595), (_e588 > 0f)) {
                    let _e606 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e614 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e624 = (0.5f * (((_e571 * _e529) / ((2f * _e606) * _e588)) + ((_e571 * _e542) / ((2f * _e614) * _e588))));
                    let _e625 = (_e624 > _e577);
                    if _e625 {
                        phi_841_ = ((_e571 * _e577) / _e624);
                    } else {
                        phi_841_ = _e571;
                    }
                    let _e629 = phi_841_;
                    let _e630 = select(_e624, _e577, _e625);
                    let _e631 = (_e630 < 0.5f);
                    if _e631 {
                        phi_1056_ = type_28(0u, type_28().member_1);
                        phi_1057_ = type_28();
                    } else {
                        let _e640 = ((((_e582 * 2f) - 1f) * _e588) * _e606);
                        let _e642 = ((((_e583 * -2f) + 1f) * _e588) * _e614);
                        let _e643 = -(_e588);
                        if (_e585 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e647 = normals.member[_e585];
                        let _e655 = (f32((bitcast<i32>(((_e647 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e655 != _e655) {
                            phi_2132_ = true;
                        } else {
                            phi_2132_ = (-1f >= _e655);
                        }
                        let _e659 = phi_2132_;
                        let _e660 = select(_e655, -1f, _e659);
                        let _e670 = (f32((bitcast<i32>((((_e647 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e670 != _e670) {
                            phi_2147_ = true;
                        } else {
                            phi_2147_ = (-1f >= _e670);
                        }
                        let _e674 = phi_2147_;
                        let _e675 = select(_e670, -1f, _e674);
                        let _e678 = (1f - abs(_e660));
                        let _e679 = abs(_e675);
                        let _e680 = (_e678 - _e679);
                        if (_e680 < 0f) {
                            phi_917_ = vec2<f32>(((1f - _e679) * select(1f, -1f, (_e660 < 0f))), (_e678 * select(1f, -1f, (_e675 < 0f))));
                        } else {
                            phi_917_ = vec2<f32>(_e660, _e675);
                        }
                        let _e691 = phi_917_;
                        let _e700 = (1f / sqrt((((_e691.x * _e691.x) + (_e691.y * _e691.y)) + (_e680 * _e680))));
                        let _e701 = (_e691.x * _e700);
                        let _e702 = (_e691.y * _e700);
                        let _e703 = (_e680 * _e700);
                        if ((((_e640 * _e701) + (_e642 * _e702)) + (_e643 * _e703)) > 0f) {
                            phi_944_ = vec3<f32>(-(_e701), -(_e702), -(_e703));
                        } else {
                            phi_944_ = vec3<f32>(_e701, _e702, _e703);
                        }
                        let _e716 = phi_944_;
                        local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e717 = (_e516 % 4u);
                        if (_e717 < 4u) {
                        } else {
                            break;
                        }
                        let _e719 = (_e515 % 4u);
                        if (_e719 < 4u) {
                        } else {
                            break;
                        }
                        let _e723 = local_6[_e717][_e719];
                        let _e733 = sqrt((((_e640 * _e640) + (_e642 * _e642)) + (_e643 * _e643)));
                        let _e734 = (-(_e640) / _e733);
                        let _e735 = (-(_e642) / _e733);
                        let _e736 = (_e588 / _e733);
                        let _e739 = -((_e723[1] * _e736));
                        let _e740 = (_e736 * _e723[0]);
                        let _e743 = ((_e734 * _e723[1]) - (_e723[0] * _e735));
                        let _e750 = (1f / sqrt((((_e739 * _e739) + (_e740 * _e740)) + (_e743 * _e743))));
                        let _e751 = (_e739 * _e750);
                        let _e752 = (_e740 * _e750);
                        let _e753 = (_e743 * _e750);
                        let _e757 = ((_e752 * _e736) - (_e735 * _e753));
                        let _e760 = ((_e753 * _e734) - (_e736 * _e751));
                        let _e763 = ((_e751 * _e735) - (_e734 * _e752));
                        let _e782 = (((_e716.x * _e734) + (_e716.y * _e735)) + (_e716.z * _e736));
                        let _e786 = abs(_e782);
                        if (_e786 != _e786) {
                            phi_2162_ = true;
                        } else {
                            phi_2162_ = (0.0001f >= _e786);
                        }
                        let _e790 = phi_2162_;
                        phi_1056_ = type_28();
                        phi_1057_ = type_28(1u, type_27(vec2<u32>(_e515, _e516), vec2<f32>(_e582, _e583), _e629, _e630, vec3<f32>(_e640, _e642, _e643), _e716, vec3<f32>(_e734, _e735, _e736), vec3<f32>(_e757, _e760, _e763), vec3<f32>(_e751, _e752, _e753), vec3<f32>((((_e716.x * _e757) + (_e716.y * _e760)) + (_e716.z * _e763)), (((_e716.x * _e751) + (_e716.y * _e752)) + (_e716.z * _e753)), _e782), (1f / (select(1f, -1f, (_e782 < 0f)) * select(_e786, 0.0001f, _e790)))));
                    }
                    let _e799 = phi_1056_;
                    let _e801 = phi_1057_;
                    phi_1059_ = _e799;
                    phi_1060_ = _e801;
                    phi_1061_ = _e631;
                } else {
                    phi_1059_ = type_28(0u, type_28().member_1);
                    phi_1060_ = type_28();
                    phi_1061_ = true;
                }
                let _e806 = phi_1059_;
                let _e808 = phi_1060_;
                let _e810 = phi_1061_;
                if _e810 {
                    phi_1065_ = _e806;
                } else {
                    phi_1065_ = _e808;
                }
                let _e812 = phi_1065_;
                if (bitcast<i32>(_e812.member) != 0i) {
                    let _e826 = sqrt((((_e812.member_1.member_4.x * _e812.member_1.member_4.x) + (_e812.member_1.member_4.y * _e812.member_1.member_4.y)) + (_e812.member_1.member_4.z * _e812.member_1.member_4.z)));
                    phi_1087_ = 0u;
                    phi_1090_ = 0u;
                    phi_1092_ = 0f;
                    loop {
                        let _e828 = phi_1087_;
                        let _e830 = phi_1090_;
                        let _e832 = phi_1092_;
                        let _e837 = frame.member[0u].member_1.member_11;
                        local_8 = _e832;
                        local_9 = _e830;
                        local_10 = _e830;
                        local_11 = _e830;
                        let _e842 = (8u << bitcast<u32>((select(_e837, 2u, (2u < _e837)) & 31u)));
                        let _e843 = (_e828 < _e842);
                        local_7 = _e842;
                        if _e843 {
                            let _e848 = frame.member[0u].member_1.member_1;
                            let _e849 = (_e848 == 1u);
                            let _e855 = frame.member[0u].member_1.member_10;
                            let _e857 = ((_e842 + _e828) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e858 = (_e857 < 56u);
                            if _e858 {
                            } else {
                                phi_2499_ = true;
                                break;
                            }
                            let _e860 = local[_e857];
                            let _e863 = (_e855 == 1u);
                            if _e863 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e858 {
                                } else {
                                    phi_2499_ = true;
                                    break;
                                }
                                let _e865 = local_1[_e857];
                                phi_1157_ = _e865;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e858 {
                                } else {
                                    phi_2499_ = true;
                                    break;
                                }
                                let _e867 = local_2[_e857];
                                phi_1157_ = _e867;
                            }
                            let _e869 = phi_1157_;
                            let _e871 = (_e812.member_1.member_2 * _e869);
                            let _e872 = (_e871 * _e860[0]);
                            let _e873 = (_e871 * _e860[1]);
                            if _e863 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e858 {
                                } else {
                                    phi_2499_ = true;
                                    break;
                                }
                                let _e875 = local_3[_e857];
                                phi_1182_ = _e875;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e858 {
                                } else {
                                    phi_2499_ = true;
                                    break;
                                }
                                let _e877 = local_4[_e857];
                                phi_1182_ = _e877;
                            }
                            let _e879 = phi_1182_;
                            let _e880 = (_e812.member_1.member_2 * _e879);
                            if _e863 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e858 {
                                } else {
                                    phi_2499_ = true;
                                    break;
                                }
                                let _e882 = local_5[_e857];
                                phi_1195_ = _e882;
                            } else {
                                phi_1195_ = (_e880 * 2f);
                            }
                            let _e885 = phi_1195_;
                            let _e894 = (-(((_e872 * _e812.member_1.member_9.x) + (_e873 * _e812.member_1.member_9.y))) * _e812.member_1.member_10);
                            let _e895 = -(_e880);
                            let _e899 = select(_e895, select(_e880, _e894, (_e894 < _e880)), (_e894 > _e895));
                            let _e900 = (_e880 - _e899);
                            let _e902 = (_e900 > (_e880 * 0.2f));
                            let _e923 = (-0.5f / ((_e812.member_1.member_4.z + (_e812.member_1.member_7.z * _e872)) + (_e812.member_1.member_8.z * _e873)));
                            let _e932 = frame.member[0u].member_1.member.member.member_1[0u];
                            let _e934 = (((((_e812.member_1.member_4.x + (_e812.member_1.member_7.x * _e872)) + (_e812.member_1.member_8.x * _e873)) * _e923) / _e932) + 0.5f);
                            let _e943 = frame.member[0u].member_1.member.member.member_1[1u];
                            let _e945 = (0.5f - ((((_e812.member_1.member_4.y + (_e812.member_1.member_7.y * _e872)) + (_e812.member_1.member_8.y * _e873)) * _e923) / _e943));
                            let _e953 = frame.member[0u].member_1.member.member;
                            let _e960 = select(select(u32(_e953.member.x), 0u, (_e953.member.x < 0f)), 4294967295u, (_e953.member.x > 4294967000f));
                            let _e971 = (select(0f, select(1f, _e934, (_e934 < 1f)), (_e934 > 0f)) * _e953.member.x);
                            let _e976 = (select(0f, select(1f, _e945, (_e945 < 1f)), (_e945 > 0f)) * _e953.member.y);
                            let _e981 = select(select(u32(_e971), 0u, (_e971 < 0f)), 4294967295u, (_e971 > 4294967000f));
                            let _e982 = (_e960 - 1u);
                            let _e984 = select(_e981, _e982, (_e982 < _e981));
                            let _e989 = select(select(u32(_e976), 0u, (_e976 < 0f)), 4294967295u, (_e976 > 4294967000f));
                            let _e990 = (select(select(u32(_e953.member.y), 0u, (_e953.member.y < 0f)), 4294967295u, (_e953.member.y > 4294967000f)) - 1u);
                            let _e992 = select(_e989, _e990, (_e990 < _e989));
                            let _e999 = ((_e812.member_1.member_1.x - _e934) * _e529);
                            let _e1000 = ((_e812.member_1.member_1.y - _e945) * _e542);
                            let _e1004 = sqrt(((_e999 * _e999) + (_e1000 * _e1000)));
                            if (_e984 == _e812.member_1.member.x) {
                                phi_1308_ = (_e992 == _e812.member_1.member.y);
                            } else {
                                phi_1308_ = false;
                            }
                            let _e1012 = phi_1308_;
                            let _e1014 = ((_e992 * _e534) + _e984);
                            if (_e1014 < _e491) {
                            } else {
                                phi_2499_ = true;
                                break;
                            }
                            let _e1017 = depth.member[_e1014];
                            let _e1029 = select(_e595, _e1017, select(false, (_e1017 < _e595), (_e1017 > 0f)));
                            let _e1031 = ((((f32(_e984) + 0.5f) * (1f / _e953.member.x)) * 2f) - 1f);
                            let _e1033 = ((((f32(_e992) + 0.5f) * (1f / _e953.member.y)) * -2f) + 1f);
                            let _e1039 = (((_e1031 * _e1029) * _e932) - _e812.member_1.member_4.x);
                            let _e1040 = (((_e1033 * _e1029) * _e943) - _e812.member_1.member_4.y);
                            let _e1041 = (-(_e1029) - _e812.member_1.member_4.z);
                            let _e1050 = (((_e1039 * _e812.member_1.member_6.x) + (_e1040 * _e812.member_1.member_6.y)) + (_e1041 * _e812.member_1.member_6.z));
                            if _e863 {
                                let _e1055 = (((_e1039 * _e1039) + (_e1040 * _e1040)) + (_e1041 * _e1041));
                                let _e1067 = (((((_e812.member_1.member_5.x * _e1039) + (_e812.member_1.member_5.y * _e1040)) + (_e812.member_1.member_5.z * _e1041)) / sqrt(_e1055)) - 0.1f);
                                let _e1074 = (1f - (_e1055 / (_e571 * _e571)));
                                let _e1081 = ((select(0f, select(1f, _e1067, (_e1067 < 1f)), (_e1067 > 0f)) * select(0f, select(1f, _e1074, (_e1074 < 1f)), (_e1074 > 0f))) / _e885);
                                phi_1496_ = select(0f, select(0f, select(1f, _e1081, (_e1081 < 1f)), (_e1081 > 0f)), (_e1055 > 0f));
                            } else {
                                let _e1092 = frame.member[0u].member_1.member.member_3;
                                if (_e899 != _e899) {
                                    phi_2268_ = true;
                                } else {
                                    phi_2268_ = (_e1050 >= _e899);
                                }
                                let _e1097 = phi_2268_;
                                let _e1099 = (_e880 - select(_e899, _e1050, _e1097));
                                if (_e1099 != _e1099) {
                                    phi_2283_ = true;
                                } else {
                                    phi_2283_ = (0f >= _e1099);
                                }
                                let _e1103 = phi_2283_;
                                let _e1108 = ((_e1050 - (_e812.member_1.member_2 * (1f + _e1092))) * (1f / _e880));
                                phi_1496_ = ((select(_e1099, 0f, _e1103) + (select(0f, select(1f, _e1108, (_e1108 < 1f)), (_e1108 > 0f)) * _e900)) * (0.5f / _e880));
                            }
                            let _e1118 = phi_1496_;
                            let _e1123 = frame.member[0u].member_1.member_9;
                            if (_e1123 == 0u) {
                                phi_1735_ = type_42(_e1050, _e1118);
                            } else {
                                if _e863 {
                                    let _e1126 = (_e812.member_1.member_2 * 0.1f);
                                    if (_e880 != _e880) {
                                        phi_2298_ = true;
                                    } else {
                                        phi_2298_ = (_e1126 >= _e880);
                                    }
                                    let _e1130 = phi_2298_;
                                    phi_1519_ = select(_e880, _e1126, _e1130);
                                } else {
                                    let _e1137 = frame.member[0u].member_1.member.member_3;
                                    phi_1519_ = (_e812.member_1.member_2 * (1f + _e1137));
                                }
                                let _e1141 = phi_1519_;
                                let _e1147 = frame.member[0u].member_1.member_3;
                                let _e1149 = select(false, (_e1004 > _e1147), (_e1050 > _e1141));
                                let _e1151 = ((_e992 * _e960) + _e984);
                                if (_e1151 < arrayLength((&depth2_.member))) {
                                } else {
                                    phi_2499_ = true;
                                    break;
                                }
                                let _e1155 = depth2_.member[_e1151];
                                let _e1159 = select(_e595, _e1155, select(false, (_e1155 < _e595), (_e1155 > 0f)));
                                let _e1165 = (((_e1031 * _e1159) * _e932) - _e812.member_1.member_4.x);
                                let _e1166 = (((_e1033 * _e1159) * _e943) - _e812.member_1.member_4.y);
                                let _e1167 = (-(_e1159) - _e812.member_1.member_4.z);
                                let _e1172 = (((_e1165 * _e812.member_1.member_6.x) + (_e1166 * _e812.member_1.member_6.y)) + (_e1167 * _e812.member_1.member_6.z));
                                if _e863 {
                                    let _e1177 = (((_e1165 * _e1165) + (_e1166 * _e1166)) + (_e1167 * _e1167));
                                    let _e1189 = (((((_e812.member_1.member_5.x * _e1165) + (_e812.member_1.member_5.y * _e1166)) + (_e812.member_1.member_5.z * _e1167)) / sqrt(_e1177)) - 0.1f);
                                    let _e1196 = (1f - (_e1177 / (_e571 * _e571)));
                                    let _e1203 = ((select(0f, select(1f, _e1189, (_e1189 < 1f)), (_e1189 > 0f)) * select(0f, select(1f, _e1196, (_e1196 < 1f)), (_e1196 > 0f))) / _e885);
                                    phi_1715_ = select(0f, select(0f, select(1f, _e1203, (_e1203 < 1f)), (_e1203 > 0f)), (_e1177 > 0f));
                                } else {
                                    let _e1214 = frame.member[0u].member_1.member.member_3;
                                    if (_e899 != _e899) {
                                        phi_2350_ = true;
                                    } else {
                                        phi_2350_ = (_e1172 >= _e899);
                                    }
                                    let _e1219 = phi_2350_;
                                    let _e1221 = (_e880 - select(_e899, _e1172, _e1219));
                                    if (_e1221 != _e1221) {
                                        phi_2365_ = true;
                                    } else {
                                        phi_2365_ = (0f >= _e1221);
                                    }
                                    let _e1225 = phi_2365_;
                                    let _e1230 = ((_e1172 - (_e812.member_1.member_2 * (1f + _e1214))) * (1f / _e880));
                                    phi_1715_ = ((select(_e1221, 0f, _e1225) + (select(0f, select(1f, _e1230, (_e1230 < 1f)), (_e1230 > 0f)) * _e900)) * (0.5f / _e880));
                                }
                                let _e1240 = phi_1715_;
                                if (_e1050 != _e1050) {
                                    phi_2380_ = true;
                                } else {
                                    phi_2380_ = (_e1172 <= _e1050);
                                }
                                let _e1244 = phi_2380_;
                                if _e863 {
                                    if (_e1118 != _e1118) {
                                        phi_2395_ = true;
                                    } else {
                                        phi_2395_ = (_e1240 >= _e1118);
                                    }
                                    let _e1250 = phi_2395_;
                                    phi_1729_ = select(_e1118, _e1240, _e1250);
                                } else {
                                    if (_e1118 != _e1118) {
                                        phi_2410_ = true;
                                    } else {
                                        phi_2410_ = (_e1240 <= _e1118);
                                    }
                                    let _e1255 = phi_2410_;
                                    phi_1729_ = select(_e1118, _e1240, _e1255);
                                }
                                let _e1258 = phi_1729_;
                                phi_1735_ = type_42(select(_e1050, select(_e1050, _e1172, _e1244), _e1149), select(_e1118, _e1258, _e1149));
                            }
                            let _e1262 = phi_1735_;
                            if _e863 {
                                phi_1751_ = 0f;
                            } else {
                                phi_1751_ = (_e900 / (_e880 * 2f));
                            }
                            let _e1268 = phi_1751_;
                            if (_e848 == 2u) {
                                phi_1771_ = true;
                            } else {
                                if _e849 {
                                    let _e1276 = frame.member[0u].member_1.member_4;
                                    phi_1770_ = (_e1276 > 0u);
                                } else {
                                    phi_1770_ = false;
                                }
                                let _e1279 = phi_1770_;
                                phi_1771_ = _e1279;
                            }
                            let _e1281 = phi_1771_;
                            let _e1282 = select(false, _e1281, !(select(false, select(false, (_e945 <= 1f), (_e945 >= 0f)), select(false, (_e934 <= 1f), (_e934 >= 0f)))));
                            if _e849 {
                                phi_1783_ = select(_e1262.member, 0x1.fffffep+127f, _e1282);
                            } else {
                                phi_1783_ = _e1262.member;
                            }
                            let _e1285 = phi_1783_;
                            if _e863 {
                                let _e1287 = (_e812.member_1.member_2 * 0.1f);
                                if (_e880 != _e880) {
                                    phi_2425_ = true;
                                } else {
                                    phi_2425_ = (_e1287 >= _e880);
                                }
                                let _e1291 = phi_2425_;
                                phi_1802_ = select(_e880, _e1287, _e1291);
                            } else {
                                let _e1298 = frame.member[0u].member_1.member.member_3;
                                phi_1802_ = (_e812.member_1.member_2 * (1f + _e1298));
                            }
                            let _e1302 = phi_1802_;
                            let _e1308 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e1004 > _e1308), (_e1285 > _e1302)), true, _e1282), (_e848 != 0u)), select(false, !(_e1012), _e902)) {
                                if (_e848 != 1u) {
                                } else {
                                    let _e1327 = frame.member[0u].member_1.member_5[0u];
                                    let _e1333 = frame.member[0u].member_1.member_5[1u];
                                    let _e1340 = frame.member[0u].member_1.member_4;
                                    let _e1341 = f32(_e1340);
                                    let _e1342 = (2u * _e1340);
                                    let _e1343 = (_e1327 + _e1342);
                                    let _e1349 = (floor((_e934 * f32(_e1327))) + _e1341);
                                    let _e1350 = f32((_e1343 - 1u));
                                    let _e1354 = select(0f, select(_e1350, _e1349, (_e1349 < _e1350)), (_e1349 > 0f));
                                    let _e1357 = (floor((_e945 * f32(_e1333))) + _e1341);
                                    let _e1358 = f32(((_e1333 + _e1342) - 1u));
                                    let _e1362 = select(0f, select(_e1358, _e1357, (_e1357 < _e1358)), (_e1357 > 0f));
                                    let _e1374 = ((select(select(u32(_e1362), 0u, (_e1362 < 0f)), 4294967295u, (_e1362 > 4294967000f)) * _e1343) + select(select(u32(_e1354), 0u, (_e1354 < 0f)), 4294967295u, (_e1354 > 4294967000f)));
                                    let _e1379 = frame.member[0u].member_1.member_2;
                                    if (_e1379 == 0u) {
                                        if (_e1374 < _e502) {
                                        } else {
                                            phi_2499_ = true;
                                            break;
                                        }
                                        let _e1384 = atomicMax((&ray_max.member[_e1374]), 1u);
                                    } else {
                                        if _e863 {
                                            if (_e1285 != _e1285) {
                                                phi_2440_ = true;
                                            } else {
                                                phi_2440_ = (_e880 <= _e1285);
                                            }
                                            let _e1388 = phi_2440_;
                                            phi_1954_ = select(_e1285, _e880, _e1388);
                                        } else {
                                            let _e1395 = frame.member[0u].member_1.member.member_3;
                                            let _e1398 = (((1f + _e1395) * _e812.member_1.member_2) + _e880);
                                            if (_e1285 != _e1285) {
                                                phi_2455_ = true;
                                            } else {
                                                phi_2455_ = (_e1398 <= _e1285);
                                            }
                                            let _e1402 = phi_2455_;
                                            phi_1954_ = select(_e1285, _e1398, _e1402);
                                        }
                                        let _e1405 = phi_1954_;
                                        let _e1406 = (_e826 - _e1405);
                                        if (_e1406 > 0f) {
                                            phi_1961_ = bitcast<u32>(_e1406);
                                        } else {
                                            phi_1961_ = 0u;
                                        }
                                        let _e1410 = phi_1961_;
                                        if (_e1374 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2499_ = true;
                                            break;
                                        }
                                        let _e1414 = atomicMin((&ray_min.member[_e1374]), _e1410);
                                        let _e1415 = (_e826 - _e899);
                                        if (_e1415 > 0f) {
                                            phi_1975_ = bitcast<u32>(_e1415);
                                        } else {
                                            phi_1975_ = 0u;
                                        }
                                        let _e1419 = phi_1975_;
                                        if (_e1374 < _e502) {
                                        } else {
                                            phi_2499_ = true;
                                            break;
                                        }
                                        let _e1423 = atomicMax((&ray_max.member[_e1374]), _e1419);
                                    }
                                }
                                phi_1983_ = (_e830 | (1u << bitcast<u32>((_e828 & 31u))));
                            } else {
                                phi_1983_ = _e830;
                            }
                            let _e1425 = phi_1983_;
                            phi_1088_ = (_e828 + 1u);
                            phi_1091_ = _e1425;
                            phi_1093_ = (_e832 + select(0f, select(_e1262.member_1, _e1268, _e1012), _e902));
                        } else {
                            phi_1088_ = u32();
                            phi_1091_ = u32();
                            phi_1093_ = f32();
                        }
                        let _e1428 = phi_1088_;
                        let _e1430 = phi_1091_;
                        let _e1432 = phi_1093_;
                        continue;
                        continuing {
                            phi_1087_ = _e1428;
                            phi_1090_ = _e1430;
                            phi_1092_ = _e1432;
                            phi_2499_ = false;
                            break if !(_e843);
                        }
                    }
                    let _e1435 = phi_2499_;
                    if _e1435 {
                        break;
                    }
                    let _e1440 = frame.member[0u].member_1.member_10;
                    let _e1441 = (_e1440 == 1u);
                    let _e1444 = local_7;
                    let _e1448 = local_8;
                    let _e1449 = ((select(2f, 1f, _e1441) / f32(_e1444)) * _e1448);
                    let _e1451 = local_9;
                    if (_e1451 == 0u) {
                        if _e1441 {
                            phi_2016_ = (1f - (2f * _e1449));
                        } else {
                            phi_2016_ = _e1449;
                        }
                        let _e1456 = phi_2016_;
                        let _e1466 = frame.member[0u].member_1.member.member_2;
                        let _e1469 = local_10;
                        phi_2045_ = type_43(pow(select(0f, select(1f, _e1456, (_e1456 < 1f)), (_e1456 > 0f)), _e1466), _e1469);
                    } else {
                        let _e1479 = local_11;
                        phi_2045_ = type_43((round((select(0f, select(1f, _e1449, (_e1449 < 1f)), (_e1449 > 0f)) * 255f)) * 0.003921569f), _e1479);
                    }
                    let _e1482 = phi_2045_;
                    phi_2050_ = _e1482;
                } else {
                    phi_2050_ = type_43(1f, 0u);
                }
                let _e1484 = phi_2050_;
                if (_e585 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e585] = _e1484.member;
                if (_e585 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e585] = _e1484.member_1;
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
