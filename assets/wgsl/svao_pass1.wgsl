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
    member_1: f32,
}

struct type_42 {
    member: f32,
    member_1: u32,
}

struct type_45 {
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
var<storage, read_write> ray_min: type_45;
@group(0) @binding(6) 
var<storage, read_write> ray_max: type_45;
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
    var phi_634_: bool;
    var phi_636_: bool;
    var phi_637_: bool;
    var phi_638_: bool;
    var phi_639_: bool;
    var phi_727_: f32;
    var phi_2063_: bool;
    var phi_2078_: bool;
    var phi_803_: vec2<f32>;
    var phi_830_: vec3<f32>;
    var phi_2093_: bool;
    var phi_942_: type_28;
    var phi_943_: type_28;
    var phi_945_: type_28;
    var phi_946_: type_28;
    var phi_947_: bool;
    var phi_951_: type_28;
    var phi_973_: u32;
    var phi_976_: u32;
    var phi_978_: f32;
    var phi_1043_: f32;
    var phi_1068_: f32;
    var phi_1081_: f32;
    var phi_1209_: u32;
    var phi_1240_: u32;
    var phi_2108_: bool;
    var phi_2123_: bool;
    var phi_1450_: f32;
    var phi_2138_: bool;
    var phi_1473_: f32;
    var phi_2153_: bool;
    var phi_2168_: bool;
    var phi_1667_: f32;
    var phi_2183_: bool;
    var phi_2198_: bool;
    var phi_2213_: bool;
    var phi_1681_: f32;
    var phi_1687_: type_41;
    var phi_1703_: f32;
    var phi_1722_: bool;
    var phi_1723_: bool;
    var phi_1735_: f32;
    var phi_2228_: bool;
    var phi_1754_: f32;
    var phi_2243_: bool;
    var phi_2258_: bool;
    var phi_1906_: f32;
    var phi_1913_: u32;
    var phi_1927_: u32;
    var phi_1935_: u32;
    var phi_974_: u32;
    var phi_977_: u32;
    var phi_979_: f32;
    var phi_2263_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_1968_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_1997_: type_42;
    var phi_2002_: type_42;

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
            let _e524 = frame.member[0u].member_1.member.member.member[0u];
            let _e529 = select(select(u32(_e524), 0u, (_e524 < 0f)), 4294967295u, (_e524 > 4294967000f));
            let _e537 = frame.member[0u].member_1.member.member.member[1u];
            let _e542 = select(select(u32(_e537), 0u, (_e537 < 0f)), 4294967295u, (_e537 > 4294967000f));
            if (_e515 >= _e514) {
                if (_e516 >= _e514) {
                    let _e546 = ((_e515 + _e514) < _e529);
                    if _e546 {
                        phi_634_ = ((_e516 + _e514) < _e542);
                    } else {
                        phi_634_ = bool();
                    }
                    let _e550 = phi_634_;
                    phi_636_ = _e550;
                    phi_637_ = select(true, false, _e546);
                } else {
                    phi_636_ = bool();
                    phi_637_ = true;
                }
                let _e553 = phi_636_;
                let _e555 = phi_637_;
                phi_638_ = _e553;
                phi_639_ = _e555;
            } else {
                phi_638_ = bool();
                phi_639_ = true;
            }
            let _e557 = phi_638_;
            let _e559 = phi_639_;
            if select(_e557, false, _e559) {
                let _e566 = frame.member[0u].member_1.member.member_1;
                let _e572 = frame.member[0u].member_1.member.member_4;
                let _e577 = ((f32(_e515) + 0.5f) / _e524);
                let _e578 = ((f32(_e516) + 0.5f) / _e537);
                let _e580 = ((_e516 * _e529) + _e515);
                if (_e580 < _e491) {
                } else {
                    break;
                }
                let _e583 = depth.member[_e580];
                let _e590 = frame.member[0u].member_1.member.member.member_3;
                if select(false, (_e583 < _e590), (_e583 > 0f)) {
                    let _e601 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e609 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e619 = (0.5f * (((_e566 * _e524) / ((2f * _e601) * _e583)) + ((_e566 * _e537) / ((2f * _e609) * _e583))));
                    let _e620 = (_e619 > _e572);
                    if _e620 {
                        phi_727_ = ((_e566 * _e572) / _e619);
                    } else {
                        phi_727_ = _e566;
                    }
                    let _e624 = phi_727_;
                    let _e625 = select(_e619, _e572, _e620);
                    let _e626 = (_e625 < 0.5f);
                    if _e626 {
                        phi_942_ = type_28(0u, type_28().member_1);
                        phi_943_ = type_28();
                    } else {
                        let _e635 = ((((_e577 * 2f) - 1f) * _e583) * _e601);
                        let _e637 = ((((_e578 * -2f) + 1f) * _e583) * _e609);
                        let _e638 = -(_e583);
                        if (_e580 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e642 = normals.member[_e580];
                        let _e650 = (f32((bitcast<i32>(((_e642 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e650 != _e650) {
                            phi_2063_ = true;
                        } else {
                            phi_2063_ = (-1f >= _e650);
                        }
                        let _e654 = phi_2063_;
                        let _e655 = select(_e650, -1f, _e654);
                        let _e665 = (f32((bitcast<i32>((((_e642 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e665 != _e665) {
                            phi_2078_ = true;
                        } else {
                            phi_2078_ = (-1f >= _e665);
                        }
                        let _e669 = phi_2078_;
                        let _e670 = select(_e665, -1f, _e669);
                        let _e673 = (1f - abs(_e655));
                        let _e674 = abs(_e670);
                        let _e675 = (_e673 - _e674);
                        if (_e675 < 0f) {
                            phi_803_ = vec2<f32>(((1f - _e674) * select(1f, -1f, (_e655 < 0f))), (_e673 * select(1f, -1f, (_e670 < 0f))));
                        } else {
                            phi_803_ = vec2<f32>(_e655, _e670);
                        }
                        let _e686 = phi_803_;
                        let _e695 = (1f / sqrt((((_e686.x * _e686.x) + (_e686.y * _e686.y)) + (_e675 * _e675))));
                        let _e696 = (_e686.x * _e695);
                        let _e697 = (_e686.y * _e695);
                        let _e698 = (_e675 * _e695);
                        if ((((_e635 * _e696) + (_e637 * _e697)) + (_e638 * _e698)) > 0f) {
                            phi_830_ = vec3<f32>(-(_e696), -(_e697), -(_e698));
                        } else {
                            phi_830_ = vec3<f32>(_e696, _e697, _e698);
                        }
                        let _e711 = phi_830_;
                        local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e712 = (_e516 % 4u);
                        if (_e712 < 4u) {
                        } else {
                            break;
                        }
                        let _e714 = (_e515 % 4u);
                        if (_e714 < 4u) {
                        } else {
                            break;
                        }
                        let _e718 = local_6[_e712][_e714];
                        let _e728 = sqrt((((_e635 * _e635) + (_e637 * _e637)) + (_e638 * _e638)));
                        let _e729 = (-(_e635) / _e728);
                        let _e730 = (-(_e637) / _e728);
                        let _e731 = (_e583 / _e728);
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
                            phi_2093_ = true;
                        } else {
                            phi_2093_ = (0.0001f >= _e781);
                        }
                        let _e785 = phi_2093_;
                        phi_942_ = type_28();
                        phi_943_ = type_28(1u, type_27(vec2<u32>(_e515, _e516), vec2<f32>(_e577, _e578), _e624, _e625, vec3<f32>(_e635, _e637, _e638), _e711, vec3<f32>(_e729, _e730, _e731), vec3<f32>(_e752, _e755, _e758), vec3<f32>(_e746, _e747, _e748), vec3<f32>((((_e711.x * _e752) + (_e711.y * _e755)) + (_e711.z * _e758)), (((_e711.x * _e746) + (_e711.y * _e747)) + (_e711.z * _e748)), _e777), (1f / (select(1f, -1f, (_e777 < 0f)) * select(_e781, 0.0001f, _e785)))));
                    }
                    let _e794 = phi_942_;
                    let _e796 = phi_943_;
                    phi_945_ = _e794;
                    phi_946_ = _e796;
                    phi_947_ = _e626;
                } else {
                    phi_945_ = type_28(0u, type_28().member_1);
                    phi_946_ = type_28();
                    phi_947_ = true;
                }
                let _e801 = phi_945_;
                let _e803 = phi_946_;
                let _e805 = phi_947_;
                if _e805 {
                    phi_951_ = _e801;
                } else {
                    phi_951_ = _e803;
                }
                let _e807 = phi_951_;
                if (bitcast<i32>(_e807.member) != 0i) {
                    let _e821 = sqrt((((_e807.member_1.member_4.x * _e807.member_1.member_4.x) + (_e807.member_1.member_4.y * _e807.member_1.member_4.y)) + (_e807.member_1.member_4.z * _e807.member_1.member_4.z)));
                    phi_973_ = 0u;
                    phi_976_ = 0u;
                    phi_978_ = 0f;
                    loop {
                        let _e823 = phi_973_;
                        let _e825 = phi_976_;
                        let _e827 = phi_978_;
                        let _e832 = frame.member[0u].member_1.member_11;
                        local_8 = _e827;
                        local_9 = _e825;
                        local_10 = _e825;
                        local_11 = _e825;
                        let _e837 = (8u << bitcast<u32>((select(_e832, 2u, (2u < _e832)) & 31u)));
                        let _e838 = (_e823 < _e837);
                        local_7 = _e837;
                        if _e838 {
                            let _e843 = frame.member[0u].member_1.member_1;
                            let _e844 = (_e843 == 1u);
                            let _e850 = frame.member[0u].member_1.member_10;
                            let _e852 = ((_e837 + _e823) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e853 = (_e852 < 56u);
                            if _e853 {
                            } else {
                                phi_2263_ = true;
                                break;
                            }
                            let _e855 = local[_e852];
                            let _e858 = (_e850 == 1u);
                            if _e858 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e853 {
                                } else {
                                    phi_2263_ = true;
                                    break;
                                }
                                let _e860 = local_1[_e852];
                                phi_1043_ = _e860;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e853 {
                                } else {
                                    phi_2263_ = true;
                                    break;
                                }
                                let _e862 = local_2[_e852];
                                phi_1043_ = _e862;
                            }
                            let _e864 = phi_1043_;
                            let _e866 = (_e807.member_1.member_2 * _e864);
                            let _e867 = (_e866 * _e855[0]);
                            let _e868 = (_e866 * _e855[1]);
                            if _e858 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e853 {
                                } else {
                                    phi_2263_ = true;
                                    break;
                                }
                                let _e870 = local_3[_e852];
                                phi_1068_ = _e870;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e853 {
                                } else {
                                    phi_2263_ = true;
                                    break;
                                }
                                let _e872 = local_4[_e852];
                                phi_1068_ = _e872;
                            }
                            let _e874 = phi_1068_;
                            let _e875 = (_e807.member_1.member_2 * _e874);
                            if _e858 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e853 {
                                } else {
                                    phi_2263_ = true;
                                    break;
                                }
                                let _e877 = local_5[_e852];
                                phi_1081_ = _e877;
                            } else {
                                phi_1081_ = (_e875 * 2f);
                            }
                            let _e880 = phi_1081_;
                            let _e889 = (-(((_e867 * _e807.member_1.member_9.x) + (_e868 * _e807.member_1.member_9.y))) * _e807.member_1.member_10);
                            let _e890 = -(_e875);
                            let _e894 = select(_e890, select(_e875, _e889, (_e889 < _e875)), (_e889 > _e890));
                            let _e895 = (_e875 - _e894);
                            let _e897 = (_e895 > (_e875 * 0.2f));
                            let _e918 = (-0.5f / ((_e807.member_1.member_4.z + (_e807.member_1.member_7.z * _e867)) + (_e807.member_1.member_8.z * _e868)));
                            let _e927 = frame.member[0u].member_1.member.member.member_1[0u];
                            let _e929 = (((((_e807.member_1.member_4.x + (_e807.member_1.member_7.x * _e867)) + (_e807.member_1.member_8.x * _e868)) * _e918) / _e927) + 0.5f);
                            let _e938 = frame.member[0u].member_1.member.member.member_1[1u];
                            let _e940 = (0.5f - ((((_e807.member_1.member_4.y + (_e807.member_1.member_7.y * _e867)) + (_e807.member_1.member_8.y * _e868)) * _e918) / _e938));
                            let _e952 = (select(0f, select(1f, _e929, (_e929 < 1f)), (_e929 > 0f)) * _e524);
                            if (_e952 > 0f) {
                                let _e958 = select(select(u32(_e952), 0u, (_e952 < 0f)), 4294967295u, (_e952 > 4294967000f));
                                let _e959 = (_e529 - 1u);
                                phi_1209_ = select(_e958, _e959, (_e959 < _e958));
                            } else {
                                phi_1209_ = 0u;
                            }
                            let _e963 = phi_1209_;
                            let _e968 = (select(0f, select(1f, _e940, (_e940 < 1f)), (_e940 > 0f)) * _e537);
                            if (_e968 > 0f) {
                                let _e974 = select(select(u32(_e968), 0u, (_e968 < 0f)), 4294967295u, (_e968 > 4294967000f));
                                let _e975 = (_e542 - 1u);
                                phi_1240_ = select(_e974, _e975, (_e975 < _e974));
                            } else {
                                phi_1240_ = 0u;
                            }
                            let _e979 = phi_1240_;
                            let _e986 = ((_e807.member_1.member_1.x - _e929) * _e524);
                            let _e987 = ((_e807.member_1.member_1.y - _e940) * _e537);
                            let _e991 = sqrt(((_e986 * _e986) + (_e987 * _e987)));
                            let _e998 = select(false, (_e979 == _e807.member_1.member.y), (_e963 == _e807.member_1.member.x));
                            let _e1000 = ((_e979 * _e529) + _e963);
                            if (_e1000 < _e491) {
                            } else {
                                phi_2263_ = true;
                                break;
                            }
                            let _e1003 = depth.member[_e1000];
                            let _e1015 = select(_e590, _e1003, select(false, (_e1003 < _e590), (_e1003 > 0f)));
                            let _e1017 = ((((f32(_e963) + 0.5f) * (1f / _e524)) * 2f) - 1f);
                            let _e1019 = ((((f32(_e979) + 0.5f) * (1f / _e537)) * -2f) + 1f);
                            let _e1025 = (((_e1017 * _e1015) * _e927) - _e807.member_1.member_4.x);
                            let _e1026 = (((_e1019 * _e1015) * _e938) - _e807.member_1.member_4.y);
                            let _e1027 = (-(_e1015) - _e807.member_1.member_4.z);
                            let _e1036 = (((_e1025 * _e807.member_1.member_6.x) + (_e1026 * _e807.member_1.member_6.y)) + (_e1027 * _e807.member_1.member_6.z));
                            if _e858 {
                                let _e1041 = (((_e1025 * _e1025) + (_e1026 * _e1026)) + (_e1027 * _e1027));
                                let _e1053 = (((((_e807.member_1.member_5.x * _e1025) + (_e807.member_1.member_5.y * _e1026)) + (_e807.member_1.member_5.z * _e1027)) / sqrt(_e1041)) - 0.1f);
                                let _e1060 = (1f - (_e1041 / (_e566 * _e566)));
                                let _e1067 = ((select(0f, select(1f, _e1053, (_e1053 < 1f)), (_e1053 > 0f)) * select(0f, select(1f, _e1060, (_e1060 < 1f)), (_e1060 > 0f))) / _e880);
                                phi_1450_ = select(0f, select(0f, select(1f, _e1067, (_e1067 < 1f)), (_e1067 > 0f)), (_e1041 > 0f));
                            } else {
                                let _e1078 = frame.member[0u].member_1.member.member_3;
                                if (_e894 != _e894) {
                                    phi_2108_ = true;
                                } else {
                                    phi_2108_ = (_e1036 >= _e894);
                                }
                                let _e1083 = phi_2108_;
                                let _e1085 = (_e875 - select(_e894, _e1036, _e1083));
                                if (_e1085 != _e1085) {
                                    phi_2123_ = true;
                                } else {
                                    phi_2123_ = (0f >= _e1085);
                                }
                                let _e1089 = phi_2123_;
                                let _e1094 = ((_e1036 - (_e807.member_1.member_2 * (1f + _e1078))) * (1f / _e875));
                                phi_1450_ = ((select(_e1085, 0f, _e1089) + (select(0f, select(1f, _e1094, (_e1094 < 1f)), (_e1094 > 0f)) * _e895)) * (0.5f / _e875));
                            }
                            let _e1104 = phi_1450_;
                            let _e1109 = frame.member[0u].member_1.member_9;
                            if (_e1109 == 0u) {
                                phi_1687_ = type_41(_e1036, _e1104);
                            } else {
                                if _e858 {
                                    let _e1112 = (_e807.member_1.member_2 * 0.1f);
                                    if (_e875 != _e875) {
                                        phi_2138_ = true;
                                    } else {
                                        phi_2138_ = (_e1112 >= _e875);
                                    }
                                    let _e1116 = phi_2138_;
                                    phi_1473_ = select(_e875, _e1112, _e1116);
                                } else {
                                    let _e1123 = frame.member[0u].member_1.member.member_3;
                                    phi_1473_ = (_e807.member_1.member_2 * (1f + _e1123));
                                }
                                let _e1127 = phi_1473_;
                                let _e1133 = frame.member[0u].member_1.member_3;
                                let _e1135 = select(false, (_e991 > _e1133), (_e1036 > _e1127));
                                if (_e1000 < arrayLength((&depth2_.member))) {
                                } else {
                                    phi_2263_ = true;
                                    break;
                                }
                                let _e1139 = depth2_.member[_e1000];
                                let _e1143 = select(_e590, _e1139, select(false, (_e1139 < _e590), (_e1139 > 0f)));
                                let _e1149 = (((_e1017 * _e1143) * _e927) - _e807.member_1.member_4.x);
                                let _e1150 = (((_e1019 * _e1143) * _e938) - _e807.member_1.member_4.y);
                                let _e1151 = (-(_e1143) - _e807.member_1.member_4.z);
                                let _e1156 = (((_e1149 * _e807.member_1.member_6.x) + (_e1150 * _e807.member_1.member_6.y)) + (_e1151 * _e807.member_1.member_6.z));
                                if _e858 {
                                    let _e1161 = (((_e1149 * _e1149) + (_e1150 * _e1150)) + (_e1151 * _e1151));
                                    let _e1173 = (((((_e807.member_1.member_5.x * _e1149) + (_e807.member_1.member_5.y * _e1150)) + (_e807.member_1.member_5.z * _e1151)) / sqrt(_e1161)) - 0.1f);
                                    let _e1180 = (1f - (_e1161 / (_e566 * _e566)));
                                    let _e1187 = ((select(0f, select(1f, _e1173, (_e1173 < 1f)), (_e1173 > 0f)) * select(0f, select(1f, _e1180, (_e1180 < 1f)), (_e1180 > 0f))) / _e880);
                                    phi_1667_ = select(0f, select(0f, select(1f, _e1187, (_e1187 < 1f)), (_e1187 > 0f)), (_e1161 > 0f));
                                } else {
                                    let _e1198 = frame.member[0u].member_1.member.member_3;
                                    if (_e894 != _e894) {
                                        phi_2153_ = true;
                                    } else {
                                        phi_2153_ = (_e1156 >= _e894);
                                    }
                                    let _e1203 = phi_2153_;
                                    let _e1205 = (_e875 - select(_e894, _e1156, _e1203));
                                    if (_e1205 != _e1205) {
                                        phi_2168_ = true;
                                    } else {
                                        phi_2168_ = (0f >= _e1205);
                                    }
                                    let _e1209 = phi_2168_;
                                    let _e1214 = ((_e1156 - (_e807.member_1.member_2 * (1f + _e1198))) * (1f / _e875));
                                    phi_1667_ = ((select(_e1205, 0f, _e1209) + (select(0f, select(1f, _e1214, (_e1214 < 1f)), (_e1214 > 0f)) * _e895)) * (0.5f / _e875));
                                }
                                let _e1224 = phi_1667_;
                                if (_e1036 != _e1036) {
                                    phi_2183_ = true;
                                } else {
                                    phi_2183_ = (_e1156 <= _e1036);
                                }
                                let _e1228 = phi_2183_;
                                if _e858 {
                                    if (_e1104 != _e1104) {
                                        phi_2198_ = true;
                                    } else {
                                        phi_2198_ = (_e1224 >= _e1104);
                                    }
                                    let _e1234 = phi_2198_;
                                    phi_1681_ = select(_e1104, _e1224, _e1234);
                                } else {
                                    if (_e1104 != _e1104) {
                                        phi_2213_ = true;
                                    } else {
                                        phi_2213_ = (_e1224 <= _e1104);
                                    }
                                    let _e1239 = phi_2213_;
                                    phi_1681_ = select(_e1104, _e1224, _e1239);
                                }
                                let _e1242 = phi_1681_;
                                phi_1687_ = type_41(select(_e1036, select(_e1036, _e1156, _e1228), _e1135), select(_e1104, _e1242, _e1135));
                            }
                            let _e1246 = phi_1687_;
                            if _e858 {
                                phi_1703_ = 0f;
                            } else {
                                phi_1703_ = (_e895 / (_e875 * 2f));
                            }
                            let _e1252 = phi_1703_;
                            if (_e843 == 2u) {
                                phi_1723_ = true;
                            } else {
                                if _e844 {
                                    let _e1260 = frame.member[0u].member_1.member_4;
                                    phi_1722_ = (_e1260 > 0u);
                                } else {
                                    phi_1722_ = false;
                                }
                                let _e1263 = phi_1722_;
                                phi_1723_ = _e1263;
                            }
                            let _e1265 = phi_1723_;
                            let _e1266 = select(false, _e1265, !(select(false, select(false, (_e940 <= 1f), (_e940 >= 0f)), select(false, (_e929 <= 1f), (_e929 >= 0f)))));
                            if _e844 {
                                phi_1735_ = select(_e1246.member, 0x1.fffffep+127f, _e1266);
                            } else {
                                phi_1735_ = _e1246.member;
                            }
                            let _e1269 = phi_1735_;
                            if _e858 {
                                let _e1271 = (_e807.member_1.member_2 * 0.1f);
                                if (_e875 != _e875) {
                                    phi_2228_ = true;
                                } else {
                                    phi_2228_ = (_e1271 >= _e875);
                                }
                                let _e1275 = phi_2228_;
                                phi_1754_ = select(_e875, _e1271, _e1275);
                            } else {
                                let _e1282 = frame.member[0u].member_1.member.member_3;
                                phi_1754_ = (_e807.member_1.member_2 * (1f + _e1282));
                            }
                            let _e1286 = phi_1754_;
                            let _e1292 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e991 > _e1292), (_e1269 > _e1286)), true, _e1266), (_e843 != 0u)), select(false, !(_e998), _e897)) {
                                if (_e843 != 1u) {
                                } else {
                                    let _e1311 = frame.member[0u].member_1.member_5[0u];
                                    let _e1317 = frame.member[0u].member_1.member_5[1u];
                                    let _e1324 = frame.member[0u].member_1.member_4;
                                    let _e1325 = f32(_e1324);
                                    let _e1326 = (2u * _e1324);
                                    let _e1327 = (_e1311 + _e1326);
                                    let _e1333 = (floor((_e929 * f32(_e1311))) + _e1325);
                                    let _e1334 = f32((_e1327 - 1u));
                                    let _e1338 = select(0f, select(_e1334, _e1333, (_e1333 < _e1334)), (_e1333 > 0f));
                                    let _e1341 = (floor((_e940 * f32(_e1317))) + _e1325);
                                    let _e1342 = f32(((_e1317 + _e1326) - 1u));
                                    let _e1346 = select(0f, select(_e1342, _e1341, (_e1341 < _e1342)), (_e1341 > 0f));
                                    let _e1358 = ((select(select(u32(_e1346), 0u, (_e1346 < 0f)), 4294967295u, (_e1346 > 4294967000f)) * _e1327) + select(select(u32(_e1338), 0u, (_e1338 < 0f)), 4294967295u, (_e1338 > 4294967000f)));
                                    let _e1363 = frame.member[0u].member_1.member_2;
                                    if (_e1363 == 0u) {
                                        if (_e1358 < _e502) {
                                        } else {
                                            phi_2263_ = true;
                                            break;
                                        }
                                        let _e1368 = atomicMax((&ray_max.member[_e1358]), 1u);
                                    } else {
                                        if _e858 {
                                            if (_e1269 != _e1269) {
                                                phi_2243_ = true;
                                            } else {
                                                phi_2243_ = (_e875 <= _e1269);
                                            }
                                            let _e1372 = phi_2243_;
                                            phi_1906_ = select(_e1269, _e875, _e1372);
                                        } else {
                                            let _e1379 = frame.member[0u].member_1.member.member_3;
                                            let _e1382 = (((1f + _e1379) * _e807.member_1.member_2) + _e875);
                                            if (_e1269 != _e1269) {
                                                phi_2258_ = true;
                                            } else {
                                                phi_2258_ = (_e1382 <= _e1269);
                                            }
                                            let _e1386 = phi_2258_;
                                            phi_1906_ = select(_e1269, _e1382, _e1386);
                                        }
                                        let _e1389 = phi_1906_;
                                        let _e1390 = (_e821 - _e1389);
                                        if (_e1390 > 0f) {
                                            phi_1913_ = bitcast<u32>(_e1390);
                                        } else {
                                            phi_1913_ = 0u;
                                        }
                                        let _e1394 = phi_1913_;
                                        if (_e1358 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2263_ = true;
                                            break;
                                        }
                                        let _e1398 = atomicMin((&ray_min.member[_e1358]), _e1394);
                                        let _e1399 = (_e821 - _e894);
                                        if (_e1399 > 0f) {
                                            phi_1927_ = bitcast<u32>(_e1399);
                                        } else {
                                            phi_1927_ = 0u;
                                        }
                                        let _e1403 = phi_1927_;
                                        if (_e1358 < _e502) {
                                        } else {
                                            phi_2263_ = true;
                                            break;
                                        }
                                        let _e1407 = atomicMax((&ray_max.member[_e1358]), _e1403);
                                    }
                                }
                                phi_1935_ = (_e825 | (1u << bitcast<u32>((_e823 & 31u))));
                            } else {
                                phi_1935_ = _e825;
                            }
                            let _e1409 = phi_1935_;
                            phi_974_ = (_e823 + 1u);
                            phi_977_ = _e1409;
                            phi_979_ = (_e827 + select(0f, select(_e1246.member_1, _e1252, _e998), _e897));
                        } else {
                            phi_974_ = u32();
                            phi_977_ = u32();
                            phi_979_ = f32();
                        }
                        let _e1412 = phi_974_;
                        let _e1414 = phi_977_;
                        let _e1416 = phi_979_;
                        continue;
                        continuing {
                            phi_973_ = _e1412;
                            phi_976_ = _e1414;
                            phi_978_ = _e1416;
                            phi_2263_ = false;
                            break if !(_e838);
                        }
                    }
                    let _e1419 = phi_2263_;
                    if _e1419 {
                        break;
                    }
                    let _e1424 = frame.member[0u].member_1.member_10;
                    let _e1425 = (_e1424 == 1u);
                    let _e1428 = local_7;
                    let _e1432 = local_8;
                    let _e1433 = ((select(2f, 1f, _e1425) / f32(_e1428)) * _e1432);
                    let _e1435 = local_9;
                    if (_e1435 == 0u) {
                        if _e1425 {
                            phi_1968_ = (1f - (2f * _e1433));
                        } else {
                            phi_1968_ = _e1433;
                        }
                        let _e1440 = phi_1968_;
                        let _e1450 = frame.member[0u].member_1.member.member_2;
                        let _e1453 = local_10;
                        phi_1997_ = type_42(pow(select(0f, select(1f, _e1440, (_e1440 < 1f)), (_e1440 > 0f)), _e1450), _e1453);
                    } else {
                        let _e1463 = local_11;
                        phi_1997_ = type_42((round((select(0f, select(1f, _e1433, (_e1433 < 1f)), (_e1433 > 0f)) * 255f)) * 0.003921569f), _e1463);
                    }
                    let _e1466 = phi_1997_;
                    phi_2002_ = _e1466;
                } else {
                    phi_2002_ = type_42(1f, 0u);
                }
                let _e1468 = phi_2002_;
                if (_e580 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e580] = _e1468.member;
                if (_e580 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e580] = _e1468.member_1;
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
