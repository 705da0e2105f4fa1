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
    var local_7: array<array<array<f32, 2>, 4>, 4>;
    var phi_712_: bool;
    var phi_714_: bool;
    var phi_715_: bool;
    var phi_716_: bool;
    var phi_717_: bool;
    var phi_2182_: bool;
    var phi_2197_: bool;
    var phi_2158_: vec2<f32>;
    var phi_2212_: bool;
    var phi_1002_: type_31;
    var phi_1024_: u32;
    var phi_1027_: u32;
    var phi_1029_: f32;
    var phi_1094_: f32;
    var phi_1119_: f32;
    var phi_1132_: f32;
    var phi_1260_: u32;
    var phi_1291_: u32;
    var phi_2227_: bool;
    var phi_2242_: bool;
    var phi_1501_: f32;
    var phi_2257_: bool;
    var phi_1524_: f32;
    var phi_2272_: bool;
    var phi_2287_: bool;
    var phi_1718_: f32;
    var phi_2302_: bool;
    var phi_2317_: bool;
    var phi_2332_: bool;
    var phi_1732_: f32;
    var phi_1738_: type_41;
    var phi_1754_: f32;
    var phi_1773_: bool;
    var phi_1774_: bool;
    var phi_1786_: f32;
    var phi_2347_: bool;
    var phi_1805_: f32;
    var phi_2362_: bool;
    var phi_2377_: bool;
    var phi_1957_: f32;
    var phi_1964_: u32;
    var phi_1978_: u32;
    var phi_1986_: u32;
    var phi_1025_: u32;
    var phi_1028_: u32;
    var phi_1030_: f32;
    var phi_2391_: bool;
    var local_8: u32;
    var local_9: f32;
    var local_10: u32;
    var phi_2019_: f32;
    var local_11: u32;
    var local_12: u32;
    var phi_2048_: type_42;
    var phi_2053_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e487 = id_1;
            let _e492 = arrayLength((&depth.member));
            let _e503 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e515 = frame.member[0u].member_1.member.member.member_4;
            let _e516 = (_e487.x + _e515);
            let _e517 = (_e487.y + _e515);
            let _e525 = frame.member[0u].member_1.member.member.member[0u];
            let _e530 = select(select(u32(_e525), 0u, (_e525 < 0f)), 4294967295u, (_e525 > 4294967000f));
            let _e538 = frame.member[0u].member_1.member.member.member[1u];
            let _e543 = select(select(u32(_e538), 0u, (_e538 < 0f)), 4294967295u, (_e538 > 4294967000f));
            if (_e516 >= _e515) {
                if (_e517 >= _e515) {
                    let _e547 = ((_e516 + _e515) < _e530);
                    if _e547 {
                        phi_712_ = ((_e517 + _e515) < _e543);
                    } else {
                        phi_712_ = bool();
                    }
                    let _e551 = phi_712_;
                    phi_714_ = _e551;
                    phi_715_ = select(true, false, _e547);
                } else {
                    phi_714_ = bool();
                    phi_715_ = true;
                }
                let _e554 = phi_714_;
                let _e556 = phi_715_;
                phi_716_ = _e554;
                phi_717_ = _e556;
            } else {
                phi_716_ = bool();
                phi_717_ = true;
            }
            let _e558 = phi_716_;
            let _e560 = phi_717_;
            if select(_e558, false, _e560) {
                let _e567 = frame.member[0u].member_1.member.member_1;
                let _e573 = frame.member[0u].member_1.member.member_4;
                let _e576 = ((f32(_e516) + 0.5f) / _e525);
                let _e579 = ((f32(_e517) + 0.5f) / _e538);
                let _e581 = ((_e517 * _e530) + _e516);
                if (_e581 < _e492) {
                } else {
                    break;
                }
                let _e584 = depth.member[_e581];
                let _e592 = frame.member[0u].member_1.member.member.member_1[0u];
                let _e600 = frame.member[0u].member_1.member.member.member_1[1u];
                let _e610 = ((((_e567 * _e525) / (_e584 * (2f * _e592))) + ((_e567 * _e538) / (_e584 * (2f * _e600)))) * 0.5f);
                let _e611 = (_e610 > _e573);
                let _e615 = select(_e610, _e573, _e611);
                let _e622 = frame.member[0u].member_1.member.member.member_3;
                let _e634 = ((((_e576 * 2f) - 1f) * _e584) * _e592);
                let _e636 = ((((_e579 * -2f) + 1f) * _e584) * _e600);
                let _e637 = -(_e584);
                if (_e581 < arrayLength((&normals.member))) {
                } else {
                    break;
                }
                let _e641 = normals.member[_e581];
                let _e649 = (f32((bitcast<i32>(((_e641 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e649 != _e649) {
                    phi_2182_ = true;
                } else {
                    phi_2182_ = (-1f >= _e649);
                }
                let _e653 = phi_2182_;
                let _e654 = select(_e649, -1f, _e653);
                let _e664 = (f32((bitcast<i32>((((_e641 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e664 != _e664) {
                    phi_2197_ = true;
                } else {
                    phi_2197_ = (-1f >= _e664);
                }
                let _e668 = phi_2197_;
                let _e669 = select(_e664, -1f, _e668);
                let _e672 = (1f - abs(_e654));
                let _e673 = abs(_e669);
                let _e674 = (_e672 - _e673);
                if (_e674 < 0f) {
                    phi_2158_ = vec2<f32>(((1f - _e673) * select(1f, -1f, (_e654 < 0f))), (_e672 * select(1f, -1f, (_e669 < 0f))));
                } else {
                    phi_2158_ = vec2<f32>(_e654, _e669);
                }
                let _e685 = phi_2158_;
                let _e694 = (1f / sqrt((((_e685.x * _e685.x) + (_e685.y * _e685.y)) + (_e674 * _e674))));
                let _e695 = (_e685.x * _e694);
                let _e696 = (_e685.y * _e694);
                let _e697 = (_e674 * _e694);
                let _e703 = ((((_e634 * _e695) + (_e636 * _e696)) + (_e637 * _e697)) > 0f);
                let _e707 = select(_e695, -(_e695), _e703);
                let _e708 = select(_e696, -(_e696), _e703);
                let _e709 = select(_e697, -(_e697), _e703);
                local_7 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e711 = (_e517 % 4u);
                let _e712 = (_e711 < 4u);
                if _e712 {
                } else {
                    break;
                }
                let _e713 = (_e516 % 4u);
                let _e714 = (_e713 < 4u);
                if _e714 {
                } else {
                    break;
                }
                let _e717 = local_7[_e711][_e713];
                local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                if _e712 {
                } else {
                    break;
                }
                if _e714 {
                } else {
                    break;
                }
                let _e721 = local_6[_e711][_e713];
                let _e730 = sqrt((((_e634 * _e634) + (_e636 * _e636)) + (_e637 * _e637)));
                let _e731 = (-(_e634) / _e730);
                let _e732 = (-(_e636) / _e730);
                let _e733 = (_e584 / _e730);
                let _e736 = -((_e721[1] * _e733));
                let _e737 = (_e733 * _e717[0]);
                let _e740 = ((_e731 * _e721[1]) - (_e717[0] * _e732));
                let _e747 = (1f / sqrt((((_e736 * _e736) + (_e737 * _e737)) + (_e740 * _e740))));
                let _e748 = (_e736 * _e747);
                let _e749 = (_e737 * _e747);
                let _e750 = (_e740 * _e747);
                let _e754 = ((_e749 * _e733) - (_e732 * _e750));
                let _e757 = ((_e750 * _e731) - (_e733 * _e748));
                let _e760 = ((_e748 * _e732) - (_e731 * _e749));
                let _e776 = (((_e707 * _e731) + (_e708 * _e732)) + (_e709 * _e733));
                let _e780 = abs(_e776);
                if (_e780 != _e780) {
                    phi_2212_ = true;
                } else {
                    phi_2212_ = (0.0001f >= _e780);
                }
                let _e784 = phi_2212_;
                if select(false, !((_e615 < 0.5f)), select(false, (_e584 < _e622), (_e584 > 0f))) {
                    phi_1002_ = type_31(1u, type_30(vec2<u32>(_e516, _e517), vec2<f32>(_e576, _e579), select(_e567, ((_e567 * _e573) / _e610), _e611), _e615, vec3<f32>(_e634, _e636, _e637), vec3<f32>(_e707, _e708, _e709), vec3<f32>(_e731, _e732, _e733), vec3<f32>(_e754, _e757, _e760), vec3<f32>(_e748, _e749, _e750), vec3<f32>((((_e707 * _e754) + (_e708 * _e757)) + (_e709 * _e760)), (((_e707 * _e748) + (_e708 * _e749)) + (_e709 * _e750)), _e776), (1f / (select(1f, -1f, (_e776 < 0f)) * select(_e780, 0.0001f, _e784)))));
                } else {
                    phi_1002_ = type_31(0u, type_31().member_1);
                }
                let _e796 = phi_1002_;
                if (bitcast<i32>(_e796.member) != 0i) {
                    let _e810 = sqrt((((_e796.member_1.member_4.x * _e796.member_1.member_4.x) + (_e796.member_1.member_4.y * _e796.member_1.member_4.y)) + (_e796.member_1.member_4.z * _e796.member_1.member_4.z)));
                    phi_1024_ = 0u;
                    phi_1027_ = 0u;
                    phi_1029_ = 0f;
                    loop {
                        let _e812 = phi_1024_;
                        let _e814 = phi_1027_;
                        let _e816 = phi_1029_;
                        let _e821 = frame.member[0u].member_1.member_11;
                        local_9 = _e816;
                        local_10 = _e814;
                        local_11 = _e814;
                        local_12 = _e814;
                        let _e826 = (8u << bitcast<u32>((select(_e821, 2u, (2u < _e821)) & 31u)));
                        let _e827 = (_e812 < _e826);
                        local_8 = _e826;
                        if _e827 {
                            let _e832 = frame.member[0u].member_1.member_1;
                            let _e833 = (_e832 == 1u);
                            let _e839 = frame.member[0u].member_1.member_10;
                            let _e841 = ((_e826 + _e812) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e842 = (_e841 < 56u);
                            if _e842 {
                            } else {
                                phi_2391_ = true;
                                break;
                            }
                            let _e844 = local[_e841];
                            let _e847 = (_e839 == 1u);
                            if _e847 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e842 {
                                } else {
                                    phi_2391_ = true;
                                    break;
                                }
                                let _e849 = local_1[_e841];
                                phi_1094_ = _e849;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e842 {
                                } else {
                                    phi_2391_ = true;
                                    break;
                                }
                                let _e851 = local_2[_e841];
                                phi_1094_ = _e851;
                            }
                            let _e853 = phi_1094_;
                            let _e855 = (_e796.member_1.member_2 * _e853);
                            let _e856 = (_e855 * _e844[0]);
                            let _e857 = (_e855 * _e844[1]);
                            if _e847 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e842 {
                                } else {
                                    phi_2391_ = true;
                                    break;
                                }
                                let _e859 = local_3[_e841];
                                phi_1119_ = _e859;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e842 {
                                } else {
                                    phi_2391_ = true;
                                    break;
                                }
                                let _e861 = local_4[_e841];
                                phi_1119_ = _e861;
                            }
                            let _e863 = phi_1119_;
                            let _e864 = (_e796.member_1.member_2 * _e863);
                            if _e847 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e842 {
                                } else {
                                    phi_2391_ = true;
                                    break;
                                }
                                let _e866 = local_5[_e841];
                                phi_1132_ = _e866;
                            } else {
                                phi_1132_ = (_e864 * 2f);
                            }
                            let _e869 = phi_1132_;
                            let _e878 = (-(((_e856 * _e796.member_1.member_9.x) + (_e857 * _e796.member_1.member_9.y))) * _e796.member_1.member_10);
                            let _e879 = -(_e864);
                            let _e883 = select(_e879, select(_e864, _e878, (_e878 < _e864)), (_e878 > _e879));
                            let _e884 = (_e864 - _e883);
                            let _e886 = (_e884 > (_e864 * 0.2f));
                            let _e907 = (-0.5f / ((_e796.member_1.member_4.z + (_e796.member_1.member_7.z * _e856)) + (_e796.member_1.member_8.z * _e857)));
                            let _e910 = (((((_e796.member_1.member_4.x + (_e796.member_1.member_7.x * _e856)) + (_e796.member_1.member_8.x * _e857)) * _e907) / _e592) + 0.5f);
                            let _e913 = (0.5f - ((((_e796.member_1.member_4.y + (_e796.member_1.member_7.y * _e856)) + (_e796.member_1.member_8.y * _e857)) * _e907) / _e600));
                            let _e925 = (select(0f, select(1f, _e910, (_e910 < 1f)), (_e910 > 0f)) * _e525);
                            if (_e925 > 0f) {
                                let _e931 = select(select(u32(_e925), 0u, (_e925 < 0f)), 4294967295u, (_e925 > 4294967000f));
                                let _e932 = (_e530 - 1u);
                                phi_1260_ = select(_e931, _e932, (_e932 < _e931));
                            } else {
                                phi_1260_ = 0u;
                            }
                            let _e936 = phi_1260_;
                            let _e941 = (select(0f, select(1f, _e913, (_e913 < 1f)), (_e913 > 0f)) * _e538);
                            if (_e941 > 0f) {
                                let _e947 = select(select(u32(_e941), 0u, (_e941 < 0f)), 4294967295u, (_e941 > 4294967000f));
                                let _e948 = (_e543 - 1u);
                                phi_1291_ = select(_e947, _e948, (_e948 < _e947));
                            } else {
                                phi_1291_ = 0u;
                            }
                            let _e952 = phi_1291_;
                            let _e959 = ((_e796.member_1.member_1.x - _e910) * _e525);
                            let _e960 = ((_e796.member_1.member_1.y - _e913) * _e538);
                            let _e964 = sqrt(((_e959 * _e959) + (_e960 * _e960)));
                            let _e971 = select(false, (_e952 == _e796.member_1.member.y), (_e936 == _e796.member_1.member.x));
                            let _e973 = ((_e952 * _e530) + _e936);
                            if (_e973 < _e492) {
                            } else {
                                phi_2391_ = true;
                                break;
                            }
                            let _e976 = depth.member[_e973];
                            let _e988 = select(_e622, _e976, select(false, (_e976 < _e622), (_e976 > 0f)));
                            let _e990 = ((((f32(_e936) + 0.5f) * (1f / _e525)) * 2f) - 1f);
                            let _e992 = ((((f32(_e952) + 0.5f) * (1f / _e538)) * -2f) + 1f);
                            let _e998 = (((_e990 * _e988) * _e592) - _e796.member_1.member_4.x);
                            let _e999 = (((_e992 * _e988) * _e600) - _e796.member_1.member_4.y);
                            let _e1000 = (-(_e988) - _e796.member_1.member_4.z);
                            let _e1009 = (((_e998 * _e796.member_1.member_6.x) + (_e999 * _e796.member_1.member_6.y)) + (_e1000 * _e796.member_1.member_6.z));
                            if _e847 {
                                let _e1014 = (((_e998 * _e998) + (_e999 * _e999)) + (_e1000 * _e1000));
                                let _e1026 = (((((_e796.member_1.member_5.x * _e998) + (_e796.member_1.member_5.y * _e999)) + (_e796.member_1.member_5.z * _e1000)) / sqrt(_e1014)) - 0.1f);
                                let _e1033 = (1f - (_e1014 / (_e567 * _e567)));
                                let _e1040 = ((select(0f, select(1f, _e1026, (_e1026 < 1f)), (_e1026 > 0f)) * select(0f, select(1f, _e1033, (_e1033 < 1f)), (_e1033 > 0f))) / _e869);
                                phi_1501_ = select(0f, select(0f, select(1f, _e1040, (_e1040 < 1f)), (_e1040 > 0f)), (_e1014 > 0f));
                            } else {
                                let _e1051 = frame.member[0u].member_1.member.member_3;
                                if (_e883 != _e883) {
                                    phi_2227_ = true;
                                } else {
                                    phi_2227_ = (_e1009 >= _e883);
                                }
                                let _e1056 = phi_2227_;
                                let _e1058 = (_e864 - select(_e883, _e1009, _e1056));
                                if (_e1058 != _e1058) {
                                    phi_2242_ = true;
                                } else {
                                    phi_2242_ = (0f >= _e1058);
                                }
                                let _e1062 = phi_2242_;
                                let _e1067 = ((_e1009 - (_e796.member_1.member_2 * (1f + _e1051))) * (1f / _e864));
                                phi_1501_ = ((select(_e1058, 0f, _e1062) + (select(0f, select(1f, _e1067, (_e1067 < 1f)), (_e1067 > 0f)) * _e884)) * (0.5f / _e864));
                            }
                            let _e1077 = phi_1501_;
                            let _e1082 = frame.member[0u].member_1.member_9;
                            if (_e1082 == 0u) {
                                phi_1738_ = type_41(_e1009, _e1077);
                            } else {
                                if _e847 {
                                    let _e1085 = (_e796.member_1.member_2 * 0.1f);
                                    if (_e864 != _e864) {
                                        phi_2257_ = true;
                                    } else {
                                        phi_2257_ = (_e1085 >= _e864);
                                    }
                                    let _e1089 = phi_2257_;
                                    phi_1524_ = select(_e864, _e1085, _e1089);
                                } else {
                                    let _e1096 = frame.member[0u].member_1.member.member_3;
                                    phi_1524_ = (_e796.member_1.member_2 * (1f + _e1096));
                                }
                                let _e1100 = phi_1524_;
                                let _e1106 = frame.member[0u].member_1.member_3;
                                let _e1108 = select(false, (_e964 > _e1106), (_e1009 > _e1100));
                                if (_e973 < arrayLength((&depth2_.member))) {
                                } else {
                                    phi_2391_ = true;
                                    break;
                                }
                                let _e1112 = depth2_.member[_e973];
                                let _e1116 = select(_e622, _e1112, select(false, (_e1112 < _e622), (_e1112 > 0f)));
                                let _e1122 = (((_e990 * _e1116) * _e592) - _e796.member_1.member_4.x);
                                let _e1123 = (((_e992 * _e1116) * _e600) - _e796.member_1.member_4.y);
                                let _e1124 = (-(_e1116) - _e796.member_1.member_4.z);
                                let _e1129 = (((_e1122 * _e796.member_1.member_6.x) + (_e1123 * _e796.member_1.member_6.y)) + (_e1124 * _e796.member_1.member_6.z));
                                if _e847 {
                                    let _e1134 = (((_e1122 * _e1122) + (_e1123 * _e1123)) + (_e1124 * _e1124));
                                    let _e1146 = (((((_e796.member_1.member_5.x * _e1122) + (_e796.member_1.member_5.y * _e1123)) + (_e796.member_1.member_5.z * _e1124)) / sqrt(_e1134)) - 0.1f);
                                    let _e1153 = (1f - (_e1134 / (_e567 * _e567)));
                                    let _e1160 = ((select(0f, select(1f, _e1146, (_e1146 < 1f)), (_e1146 > 0f)) * select(0f, select(1f, _e1153, (_e1153 < 1f)), (_e1153 > 0f))) / _e869);
                                    phi_1718_ = select(0f, select(0f, select(1f, _e1160, (_e1160 < 1f)), (_e1160 > 0f)), (_e1134 > 0f));
                                } else {
                                    let _e1171 = frame.member[0u].member_1.member.member_3;
                                    if (_e883 != _e883) {
                                        phi_2272_ = true;
                                    } else {
                                        phi_2272_ = (_e1129 >= _e883);
                                    }
                                    let _e1176 = phi_2272_;
                                    let _e1178 = (_e864 - select(_e883, _e1129, _e1176));
                                    if (_e1178 != _e1178) {
                                        phi_2287_ = true;
                                    } else {
                                        phi_2287_ = (0f >= _e1178);
                                    }
                                    let _e1182 = phi_2287_;
                                    let _e1187 = ((_e1129 - (_e796.member_1.member_2 * (1f + _e1171))) * (1f / _e864));
                                    phi_1718_ = ((select(_e1178, 0f, _e1182) + (select(0f, select(1f, _e1187, (_e1187 < 1f)), (_e1187 > 0f)) * _e884)) * (0.5f / _e864));
                                }
                                let _e1197 = phi_1718_;
                                if (_e1009 != _e1009) {
                                    phi_2302_ = true;
                                } else {
                                    phi_2302_ = (_e1129 <= _e1009);
                                }
                                let _e1201 = phi_2302_;
                                if _e847 {
                                    if (_e1077 != _e1077) {
                                        phi_2317_ = true;
                                    } else {
                                        phi_2317_ = (_e1197 >= _e1077);
                                    }
                                    let _e1207 = phi_2317_;
                                    phi_1732_ = select(_e1077, _e1197, _e1207);
                                } else {
                                    if (_e1077 != _e1077) {
                                        phi_2332_ = true;
                                    } else {
                                        phi_2332_ = (_e1197 <= _e1077);
                                    }
                                    let _e1212 = phi_2332_;
                                    phi_1732_ = select(_e1077, _e1197, _e1212);
                                }
                                let _e1215 = phi_1732_;
                                phi_1738_ = type_41(select(_e1009, select(_e1009, _e1129, _e1201), _e1108), select(_e1077, _e1215, _e1108));
                            }
                            let _e1219 = phi_1738_;
                            if _e847 {
                                phi_1754_ = 0f;
                            } else {
                                phi_1754_ = (_e884 / (_e864 * 2f));
                            }
                            let _e1225 = phi_1754_;
                            if (_e832 == 2u) {
                                phi_1774_ = true;
                            } else {
                                if _e833 {
                                    let _e1233 = frame.member[0u].member_1.member_4;
                                    phi_1773_ = (_e1233 > 0u);
                                } else {
                                    phi_1773_ = false;
                                }
                                let _e1236 = phi_1773_;
                                phi_1774_ = _e1236;
                            }
                            let _e1238 = phi_1774_;
                            let _e1239 = select(false, _e1238, !(select(false, select(false, (_e913 <= 1f), (_e913 >= 0f)), select(false, (_e910 <= 1f), (_e910 >= 0f)))));
                            if _e833 {
                                phi_1786_ = select(_e1219.member, 0x1.fffffep+127f, _e1239);
                            } else {
                                phi_1786_ = _e1219.member;
                            }
                            let _e1242 = phi_1786_;
                            if _e847 {
                                let _e1244 = (_e796.member_1.member_2 * 0.1f);
                                if (_e864 != _e864) {
                                    phi_2347_ = true;
                                } else {
                                    phi_2347_ = (_e1244 >= _e864);
                                }
                                let _e1248 = phi_2347_;
                                phi_1805_ = select(_e864, _e1244, _e1248);
                            } else {
                                let _e1255 = frame.member[0u].member_1.member.member_3;
                                phi_1805_ = (_e796.member_1.member_2 * (1f + _e1255));
                            }
                            let _e1259 = phi_1805_;
                            let _e1265 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e964 > _e1265), (_e1242 > _e1259)), true, _e1239), (_e832 != 0u)), select(false, !(_e971), _e886)) {
                                if (_e832 != 1u) {
                                } else {
                                    let _e1284 = frame.member[0u].member_1.member_5[0u];
                                    let _e1290 = frame.member[0u].member_1.member_5[1u];
                                    let _e1297 = frame.member[0u].member_1.member_4;
                                    let _e1298 = f32(_e1297);
                                    let _e1299 = (2u * _e1297);
                                    let _e1300 = (_e1284 + _e1299);
                                    let _e1306 = (floor((_e910 * f32(_e1284))) + _e1298);
                                    let _e1307 = f32((_e1300 - 1u));
                                    let _e1311 = select(0f, select(_e1307, _e1306, (_e1306 < _e1307)), (_e1306 > 0f));
                                    let _e1314 = (floor((_e913 * f32(_e1290))) + _e1298);
                                    let _e1315 = f32(((_e1290 + _e1299) - 1u));
                                    let _e1319 = select(0f, select(_e1315, _e1314, (_e1314 < _e1315)), (_e1314 > 0f));
                                    let _e1331 = ((select(select(u32(_e1319), 0u, (_e1319 < 0f)), 4294967295u, (_e1319 > 4294967000f)) * _e1300) + select(select(u32(_e1311), 0u, (_e1311 < 0f)), 4294967295u, (_e1311 > 4294967000f)));
                                    let _e1336 = frame.member[0u].member_1.member_2;
                                    if (_e1336 == 0u) {
                                        if (_e1331 < _e503) {
                                        } else {
                                            phi_2391_ = true;
                                            break;
                                        }
                                        let _e1341 = atomicMax((&ray_max.member[_e1331]), 1u);
                                    } else {
                                        if _e847 {
                                            if (_e1242 != _e1242) {
                                                phi_2362_ = true;
                                            } else {
                                                phi_2362_ = (_e864 <= _e1242);
                                            }
                                            let _e1345 = phi_2362_;
                                            phi_1957_ = select(_e1242, _e864, _e1345);
                                        } else {
                                            let _e1352 = frame.member[0u].member_1.member.member_3;
                                            let _e1355 = (((1f + _e1352) * _e796.member_1.member_2) + _e864);
                                            if (_e1242 != _e1242) {
                                                phi_2377_ = true;
                                            } else {
                                                phi_2377_ = (_e1355 <= _e1242);
                                            }
                                            let _e1359 = phi_2377_;
                                            phi_1957_ = select(_e1242, _e1355, _e1359);
                                        }
                                        let _e1362 = phi_1957_;
                                        let _e1363 = (_e810 - _e1362);
                                        if (_e1363 > 0f) {
                                            phi_1964_ = bitcast<u32>(_e1363);
                                        } else {
                                            phi_1964_ = 0u;
                                        }
                                        let _e1367 = phi_1964_;
                                        if (_e1331 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2391_ = true;
                                            break;
                                        }
                                        let _e1371 = atomicMin((&ray_min.member[_e1331]), _e1367);
                                        let _e1372 = (_e810 - _e883);
                                        if (_e1372 > 0f) {
                                            phi_1978_ = bitcast<u32>(_e1372);
                                        } else {
                                            phi_1978_ = 0u;
                                        }
                                        let _e1376 = phi_1978_;
                                        if (_e1331 < _e503) {
                                        } else {
                                            phi_2391_ = true;
                                            break;
                                        }
                                        let _e1380 = atomicMax((&ray_max.member[_e1331]), _e1376);
                                    }
                                }
                                phi_1986_ = (_e814 | (1u << bitcast<u32>((_e812 & 31u))));
                            } else {
                                phi_1986_ = _e814;
                            }
                            let _e1382 = phi_1986_;
                            phi_1025_ = (_e812 + 1u);
                            phi_1028_ = _e1382;
                            phi_1030_ = (_e816 + select(0f, select(_e1219.member_1, _e1225, _e971), _e886));
                        } else {
                            phi_1025_ = u32();
                            phi_1028_ = u32();
                            phi_1030_ = f32();
                        }
                        let _e1385 = phi_1025_;
                        let _e1387 = phi_1028_;
                        let _e1389 = phi_1030_;
                        continue;
                        continuing {
                            phi_1024_ = _e1385;
                            phi_1027_ = _e1387;
                            phi_1029_ = _e1389;
                            phi_2391_ = false;
                            break if !(_e827);
                        }
                    }
                    let _e1392 = phi_2391_;
                    if _e1392 {
                        break;
                    }
                    let _e1397 = frame.member[0u].member_1.member_10;
                    let _e1398 = (_e1397 == 1u);
                    let _e1401 = local_8;
                    let _e1405 = local_9;
                    let _e1406 = ((select(2f, 1f, _e1398) / f32(_e1401)) * _e1405);
                    let _e1408 = local_10;
                    if (_e1408 == 0u) {
                        if _e1398 {
                            phi_2019_ = (1f - (2f * _e1406));
                        } else {
                            phi_2019_ = _e1406;
                        }
                        let _e1413 = phi_2019_;
                        let _e1423 = frame.member[0u].member_1.member.member_2;
                        let _e1426 = local_11;
                        phi_2048_ = type_42(pow(select(0f, select(1f, _e1413, (_e1413 < 1f)), (_e1413 > 0f)), _e1423), _e1426);
                    } else {
                        let _e1436 = local_12;
                        phi_2048_ = type_42((round((select(0f, select(1f, _e1406, (_e1406 < 1f)), (_e1406 > 0f)) * 255f)) * 0.003921569f), _e1436);
                    }
                    let _e1439 = phi_2048_;
                    phi_2053_ = _e1439;
                } else {
                    phi_2053_ = type_42(1f, 0u);
                }
                let _e1441 = phi_2053_;
                if (_e581 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e581] = _e1441.member;
                if (_e581 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e581] = _e1441.member_1;
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
