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
    var phi_727_: bool;
    var phi_729_: bool;
    var phi_730_: bool;
    var phi_731_: bool;
    var phi_732_: bool;
    var phi_2163_: bool;
    var phi_2178_: bool;
    var phi_2139_: vec2<f32>;
    var phi_2193_: bool;
    var phi_999_: type_31;
    var phi_1021_: u32;
    var phi_1024_: u32;
    var phi_1026_: f32;
    var phi_1091_: f32;
    var phi_1116_: f32;
    var phi_1129_: f32;
    var phi_1257_: u32;
    var phi_1288_: u32;
    var phi_2208_: bool;
    var phi_2223_: bool;
    var phi_1498_: f32;
    var phi_2238_: bool;
    var phi_1521_: f32;
    var phi_2253_: bool;
    var phi_2268_: bool;
    var phi_1715_: f32;
    var phi_2283_: bool;
    var phi_2298_: bool;
    var phi_2313_: bool;
    var phi_1729_: f32;
    var phi_1735_: type_41;
    var phi_1751_: f32;
    var phi_1770_: bool;
    var phi_1771_: bool;
    var phi_1783_: f32;
    var phi_2328_: bool;
    var phi_1802_: f32;
    var phi_2343_: bool;
    var phi_2358_: bool;
    var phi_1954_: f32;
    var phi_1961_: u32;
    var phi_1975_: u32;
    var phi_1983_: u32;
    var phi_1022_: u32;
    var phi_1025_: u32;
    var phi_1027_: f32;
    var phi_2372_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_2016_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2045_: type_42;
    var phi_2050_: type_42;

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
                        phi_727_ = ((_e516 + _e514) < _e542);
                    } else {
                        phi_727_ = bool();
                    }
                    let _e550 = phi_727_;
                    phi_729_ = _e550;
                    phi_730_ = select(true, false, _e546);
                } else {
                    phi_729_ = bool();
                    phi_730_ = true;
                }
                let _e553 = phi_729_;
                let _e555 = phi_730_;
                phi_731_ = _e553;
                phi_732_ = _e555;
            } else {
                phi_731_ = bool();
                phi_732_ = true;
            }
            let _e557 = phi_731_;
            let _e559 = phi_732_;
            if select(_e557, false, _e559) {
                let _e566 = frame.member[0u].member_1.member.member_1;
                let _e572 = frame.member[0u].member_1.member.member_4;
                let _e575 = ((f32(_e515) + 0.5f) / _e524);
                let _e578 = ((f32(_e516) + 0.5f) / _e537);
                let _e580 = ((_e516 * _e529) + _e515);
                if (_e580 < _e491) {
                } else {
                    break;
                }
                let _e583 = depth.member[_e580];
                let _e591 = frame.member[0u].member_1.member.member.member_1[0u];
                let _e599 = frame.member[0u].member_1.member.member.member_1[1u];
                let _e609 = ((((_e566 * _e524) / (_e583 * (2f * _e591))) + ((_e566 * _e537) / (_e583 * (2f * _e599)))) * 0.5f);
                let _e610 = (_e609 > _e572);
                let _e614 = select(_e609, _e572, _e610);
                let _e621 = frame.member[0u].member_1.member.member.member_3;
                let _e633 = ((((_e575 * 2f) - 1f) * _e583) * _e591);
                let _e635 = ((((_e578 * -2f) + 1f) * _e583) * _e599);
                let _e636 = -(_e583);
                if (_e580 < arrayLength((&normals.member))) {
                } else {
                    break;
                }
                let _e640 = normals.member[_e580];
                let _e648 = (f32((bitcast<i32>(((_e640 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e648 != _e648) {
                    phi_2163_ = true;
                } else {
                    phi_2163_ = (-1f >= _e648);
                }
                let _e652 = phi_2163_;
                let _e653 = select(_e648, -1f, _e652);
                let _e663 = (f32((bitcast<i32>((((_e640 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e663 != _e663) {
                    phi_2178_ = true;
                } else {
                    phi_2178_ = (-1f >= _e663);
                }
                let _e667 = phi_2178_;
                let _e668 = select(_e663, -1f, _e667);
                let _e671 = (1f - abs(_e653));
                let _e672 = abs(_e668);
                let _e673 = (_e671 - _e672);
                if (_e673 < 0f) {
                    phi_2139_ = vec2<f32>(((1f - _e672) * select(1f, -1f, (_e653 < 0f))), (_e671 * select(1f, -1f, (_e668 < 0f))));
                } else {
                    phi_2139_ = vec2<f32>(_e653, _e668);
                }
                let _e684 = phi_2139_;
                let _e693 = (1f / sqrt((((_e684.x * _e684.x) + (_e684.y * _e684.y)) + (_e673 * _e673))));
                let _e694 = (_e684.x * _e693);
                let _e695 = (_e684.y * _e693);
                let _e696 = (_e673 * _e693);
                let _e702 = ((((_e633 * _e694) + (_e635 * _e695)) + (_e636 * _e696)) > 0f);
                let _e706 = select(_e694, -(_e694), _e702);
                let _e707 = select(_e695, -(_e695), _e702);
                let _e708 = select(_e696, -(_e696), _e702);
                local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e710 = (_e516 % 4u);
                if (_e710 < 4u) {
                } else {
                    break;
                }
                let _e712 = (_e515 % 4u);
                if (_e712 < 4u) {
                } else {
                    break;
                }
                let _e716 = local_6[_e710][_e712];
                let _e726 = sqrt((((_e633 * _e633) + (_e635 * _e635)) + (_e636 * _e636)));
                let _e727 = (-(_e633) / _e726);
                let _e728 = (-(_e635) / _e726);
                let _e729 = (_e583 / _e726);
                let _e732 = -((_e716[1] * _e729));
                let _e733 = (_e729 * _e716[0]);
                let _e736 = ((_e727 * _e716[1]) - (_e716[0] * _e728));
                let _e743 = (1f / sqrt((((_e732 * _e732) + (_e733 * _e733)) + (_e736 * _e736))));
                let _e744 = (_e732 * _e743);
                let _e745 = (_e733 * _e743);
                let _e746 = (_e736 * _e743);
                let _e750 = ((_e745 * _e729) - (_e728 * _e746));
                let _e753 = ((_e746 * _e727) - (_e729 * _e744));
                let _e756 = ((_e744 * _e728) - (_e727 * _e745));
                let _e772 = (((_e706 * _e727) + (_e707 * _e728)) + (_e708 * _e729));
                let _e776 = abs(_e772);
                if (_e776 != _e776) {
                    phi_2193_ = true;
                } else {
                    phi_2193_ = (0.0001f >= _e776);
                }
                let _e780 = phi_2193_;
                if select(false, !((_e614 < 0.5f)), select(false, (_e583 < _e621), (_e583 > 0f))) {
                    phi_999_ = type_31(1u, type_30(vec2<u32>(_e515, _e516), vec2<f32>(_e575, _e578), select(_e566, ((_e566 * _e572) / _e609), _e610), _e614, vec3<f32>(_e633, _e635, _e636), vec3<f32>(_e706, _e707, _e708), vec3<f32>(_e727, _e728, _e729), vec3<f32>(_e750, _e753, _e756), vec3<f32>(_e744, _e745, _e746), vec3<f32>((((_e706 * _e750) + (_e707 * _e753)) + (_e708 * _e756)), (((_e706 * _e744) + (_e707 * _e745)) + (_e708 * _e746)), _e772), (1f / (select(1f, -1f, (_e772 < 0f)) * select(_e776, 0.0001f, _e780)))));
                } else {
                    phi_999_ = type_31(0u, type_31().member_1);
                }
                let _e792 = phi_999_;
                if (bitcast<i32>(_e792.member) != 0i) {
                    let _e806 = sqrt((((_e792.member_1.member_4.x * _e792.member_1.member_4.x) + (_e792.member_1.member_4.y * _e792.member_1.member_4.y)) + (_e792.member_1.member_4.z * _e792.member_1.member_4.z)));
                    phi_1021_ = 0u;
                    phi_1024_ = 0u;
                    phi_1026_ = 0f;
                    loop {
                        let _e808 = phi_1021_;
                        let _e810 = phi_1024_;
                        let _e812 = phi_1026_;
                        let _e817 = frame.member[0u].member_1.member_11;
                        local_8 = _e812;
                        local_9 = _e810;
                        local_10 = _e810;
                        local_11 = _e810;
                        let _e822 = (8u << bitcast<u32>((select(_e817, 2u, (2u < _e817)) & 31u)));
                        let _e823 = (_e808 < _e822);
                        local_7 = _e822;
                        if _e823 {
                            let _e828 = frame.member[0u].member_1.member_1;
                            let _e829 = (_e828 == 1u);
                            let _e835 = frame.member[0u].member_1.member_10;
                            let _e837 = ((_e822 + _e808) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e838 = (_e837 < 56u);
                            if _e838 {
                            } else {
                                phi_2372_ = true;
                                break;
                            }
                            let _e840 = local[_e837];
                            let _e843 = (_e835 == 1u);
                            if _e843 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e838 {
                                } else {
                                    phi_2372_ = true;
                                    break;
                                }
                                let _e845 = local_1[_e837];
                                phi_1091_ = _e845;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e838 {
                                } else {
                                    phi_2372_ = true;
                                    break;
                                }
                                let _e847 = local_2[_e837];
                                phi_1091_ = _e847;
                            }
                            let _e849 = phi_1091_;
                            let _e851 = (_e792.member_1.member_2 * _e849);
                            let _e852 = (_e851 * _e840[0]);
                            let _e853 = (_e851 * _e840[1]);
                            if _e843 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e838 {
                                } else {
                                    phi_2372_ = true;
                                    break;
                                }
                                let _e855 = local_3[_e837];
                                phi_1116_ = _e855;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e838 {
                                } else {
                                    phi_2372_ = true;
                                    break;
                                }
                                let _e857 = local_4[_e837];
                                phi_1116_ = _e857;
                            }
                            let _e859 = phi_1116_;
                            let _e860 = (_e792.member_1.member_2 * _e859);
                            if _e843 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e838 {
                                } else {
                                    phi_2372_ = true;
                                    break;
                                }
                                let _e862 = local_5[_e837];
                                phi_1129_ = _e862;
                            } else {
                                phi_1129_ = (_e860 * 2f);
                            }
                            let _e865 = phi_1129_;
                            let _e874 = (-(((_e852 * _e792.member_1.member_9.x) + (_e853 * _e792.member_1.member_9.y))) * _e792.member_1.member_10);
                            let _e875 = -(_e860);
                            let _e879 = select(_e875, select(_e860, _e874, (_e874 < _e860)), (_e874 > _e875));
                            let _e880 = (_e860 - _e879);
                            let _e882 = (_e880 > (_e860 * 0.2f));
                            let _e903 = (-0.5f / ((_e792.member_1.member_4.z + (_e792.member_1.member_7.z * _e852)) + (_e792.member_1.member_8.z * _e853)));
                            let _e906 = (((((_e792.member_1.member_4.x + (_e792.member_1.member_7.x * _e852)) + (_e792.member_1.member_8.x * _e853)) * _e903) / _e591) + 0.5f);
                            let _e909 = (0.5f - ((((_e792.member_1.member_4.y + (_e792.member_1.member_7.y * _e852)) + (_e792.member_1.member_8.y * _e853)) * _e903) / _e599));
                            let _e921 = (select(0f, select(1f, _e906, (_e906 < 1f)), (_e906 > 0f)) * _e524);
                            if (_e921 > 0f) {
                                let _e927 = select(select(u32(_e921), 0u, (_e921 < 0f)), 4294967295u, (_e921 > 4294967000f));
                                let _e928 = (_e529 - 1u);
                                phi_1257_ = select(_e927, _e928, (_e928 < _e927));
                            } else {
                                phi_1257_ = 0u;
                            }
                            let _e932 = phi_1257_;
                            let _e937 = (select(0f, select(1f, _e909, (_e909 < 1f)), (_e909 > 0f)) * _e537);
                            if (_e937 > 0f) {
                                let _e943 = select(select(u32(_e937), 0u, (_e937 < 0f)), 4294967295u, (_e937 > 4294967000f));
                                let _e944 = (_e542 - 1u);
                                phi_1288_ = select(_e943, _e944, (_e944 < _e943));
                            } else {
                                phi_1288_ = 0u;
                            }
                            let _e948 = phi_1288_;
                            let _e955 = ((_e792.member_1.member_1.x - _e906) * _e524);
                            let _e956 = ((_e792.member_1.member_1.y - _e909) * _e537);
                            let _e960 = sqrt(((_e955 * _e955) + (_e956 * _e956)));
                            let _e967 = select(false, (_e948 == _e792.member_1.member.y), (_e932 == _e792.member_1.member.x));
                            let _e969 = ((_e948 * _e529) + _e932);
                            if (_e969 < _e491) {
                            } else {
                                phi_2372_ = true;
                                break;
                            }
                            let _e972 = depth.member[_e969];
                            let _e984 = select(_e621, _e972, select(false, (_e972 < _e621), (_e972 > 0f)));
                            let _e986 = ((((f32(_e932) + 0.5f) * (1f / _e524)) * 2f) - 1f);
                            let _e988 = ((((f32(_e948) + 0.5f) * (1f / _e537)) * -2f) + 1f);
                            let _e994 = (((_e986 * _e984) * _e591) - _e792.member_1.member_4.x);
                            let _e995 = (((_e988 * _e984) * _e599) - _e792.member_1.member_4.y);
                            let _e996 = (-(_e984) - _e792.member_1.member_4.z);
                            let _e1005 = (((_e994 * _e792.member_1.member_6.x) + (_e995 * _e792.member_1.member_6.y)) + (_e996 * _e792.member_1.member_6.z));
                            if _e843 {
                                let _e1010 = (((_e994 * _e994) + (_e995 * _e995)) + (_e996 * _e996));
                                let _e1022 = (((((_e792.member_1.member_5.x * _e994) + (_e792.member_1.member_5.y * _e995)) + (_e792.member_1.member_5.z * _e996)) / sqrt(_e1010)) - 0.1f);
                                let _e1029 = (1f - (_e1010 / (_e566 * _e566)));
                                let _e1036 = ((select(0f, select(1f, _e1022, (_e1022 < 1f)), (_e1022 > 0f)) * select(0f, select(1f, _e1029, (_e1029 < 1f)), (_e1029 > 0f))) / _e865);
                                phi_1498_ = select(0f, select(0f, select(1f, _e1036, (_e1036 < 1f)), (_e1036 > 0f)), (_e1010 > 0f));
                            } else {
                                let _e1047 = frame.member[0u].member_1.member.member_3;
                                if (_e879 != _e879) {
                                    phi_2208_ = true;
                                } else {
                                    phi_2208_ = (_e1005 >= _e879);
                                }
                                let _e1052 = phi_2208_;
                                let _e1054 = (_e860 - select(_e879, _e1005, _e1052));
                                if (_e1054 != _e1054) {
                                    phi_2223_ = true;
                                } else {
                                    phi_2223_ = (0f >= _e1054);
                                }
                                let _e1058 = phi_2223_;
                                let _e1063 = ((_e1005 - (_e792.member_1.member_2 * (1f + _e1047))) * (1f / _e860));
                                phi_1498_ = ((select(_e1054, 0f, _e1058) + (select(0f, select(1f, _e1063, (_e1063 < 1f)), (_e1063 > 0f)) * _e880)) * (0.5f / _e860));
                            }
                            let _e1073 = phi_1498_;
                            let _e1078 = frame.member[0u].member_1.member_9;
                            if (_e1078 == 0u) {
                                phi_1735_ = type_41(_e1005, _e1073);
                            } else {
                                if _e843 {
                                    let _e1081 = (_e792.member_1.member_2 * 0.1f);
                                    if (_e860 != _e860) {
                                        phi_2238_ = true;
                                    } else {
                                        phi_2238_ = (_e1081 >= _e860);
                                    }
                                    let _e1085 = phi_2238_;
                                    phi_1521_ = select(_e860, _e1081, _e1085);
                                } else {
                                    let _e1092 = frame.member[0u].member_1.member.member_3;
                                    phi_1521_ = (_e792.member_1.member_2 * (1f + _e1092));
                                }
                                let _e1096 = phi_1521_;
                                let _e1102 = frame.member[0u].member_1.member_3;
                                let _e1104 = select(false, (_e960 > _e1102), (_e1005 > _e1096));
                                if (_e969 < arrayLength((&depth2_.member))) {
                                } else {
                                    phi_2372_ = true;
                                    break;
                                }
                                let _e1108 = depth2_.member[_e969];
                                let _e1112 = select(_e621, _e1108, select(false, (_e1108 < _e621), (_e1108 > 0f)));
                                let _e1118 = (((_e986 * _e1112) * _e591) - _e792.member_1.member_4.x);
                                let _e1119 = (((_e988 * _e1112) * _e599) - _e792.member_1.member_4.y);
                                let _e1120 = (-(_e1112) - _e792.member_1.member_4.z);
                                let _e1125 = (((_e1118 * _e792.member_1.member_6.x) + (_e1119 * _e792.member_1.member_6.y)) + (_e1120 * _e792.member_1.member_6.z));
                                if _e843 {
                                    let _e1130 = (((_e1118 * _e1118) + (_e1119 * _e1119)) + (_e1120 * _e1120));
                                    let _e1142 = (((((_e792.member_1.member_5.x * _e1118) + (_e792.member_1.member_5.y * _e1119)) + (_e792.member_1.member_5.z * _e1120)) / sqrt(_e1130)) - 0.1f);
                                    let _e1149 = (1f - (_e1130 / (_e566 * _e566)));
                                    let _e1156 = ((select(0f, select(1f, _e1142, (_e1142 < 1f)), (_e1142 > 0f)) * select(0f, select(1f, _e1149, (_e1149 < 1f)), (_e1149 > 0f))) / _e865);
                                    phi_1715_ = select(0f, select(0f, select(1f, _e1156, (_e1156 < 1f)), (_e1156 > 0f)), (_e1130 > 0f));
                                } else {
                                    let _e1167 = frame.member[0u].member_1.member.member_3;
                                    if (_e879 != _e879) {
                                        phi_2253_ = true;
                                    } else {
                                        phi_2253_ = (_e1125 >= _e879);
                                    }
                                    let _e1172 = phi_2253_;
                                    let _e1174 = (_e860 - select(_e879, _e1125, _e1172));
                                    if (_e1174 != _e1174) {
                                        phi_2268_ = true;
                                    } else {
                                        phi_2268_ = (0f >= _e1174);
                                    }
                                    let _e1178 = phi_2268_;
                                    let _e1183 = ((_e1125 - (_e792.member_1.member_2 * (1f + _e1167))) * (1f / _e860));
                                    phi_1715_ = ((select(_e1174, 0f, _e1178) + (select(0f, select(1f, _e1183, (_e1183 < 1f)), (_e1183 > 0f)) * _e880)) * (0.5f / _e860));
                                }
                                let _e1193 = phi_1715_;
                                if (_e1005 != _e1005) {
                                    phi_2283_ = true;
                                } else {
                                    phi_2283_ = (_e1125 <= _e1005);
                                }
                                let _e1197 = phi_2283_;
                                if _e843 {
                                    if (_e1073 != _e1073) {
                                        phi_2298_ = true;
                                    } else {
                                        phi_2298_ = (_e1193 >= _e1073);
                                    }
                                    let _e1203 = phi_2298_;
                                    phi_1729_ = select(_e1073, _e1193, _e1203);
                                } else {
                                    if (_e1073 != _e1073) {
                                        phi_2313_ = true;
                                    } else {
                                        phi_2313_ = (_e1193 <= _e1073);
                                    }
                                    let _e1208 = phi_2313_;
                                    phi_1729_ = select(_e1073, _e1193, _e1208);
                                }
                                let _e1211 = phi_1729_;
                                phi_1735_ = type_41(select(_e1005, select(_e1005, _e1125, _e1197), _e1104), select(_e1073, _e1211, _e1104));
                            }
                            let _e1215 = phi_1735_;
                            if _e843 {
                                phi_1751_ = 0f;
                            } else {
                                phi_1751_ = (_e880 / (_e860 * 2f));
                            }
                            let _e1221 = phi_1751_;
                            if (_e828 == 2u) {
                                phi_1771_ = true;
                            } else {
                                if _e829 {
                                    let _e1229 = frame.member[0u].member_1.member_4;
                                    phi_1770_ = (_e1229 > 0u);
                                } else {
                                    phi_1770_ = false;
                                }
                                let _e1232 = phi_1770_;
                                phi_1771_ = _e1232;
                            }
                            let _e1234 = phi_1771_;
                            let _e1235 = select(false, _e1234, !(select(false, select(false, (_e909 <= 1f), (_e909 >= 0f)), select(false, (_e906 <= 1f), (_e906 >= 0f)))));
                            if _e829 {
                                phi_1783_ = select(_e1215.member, 0x1.fffffep+127f, _e1235);
                            } else {
                                phi_1783_ = _e1215.member;
                            }
                            let _e1238 = phi_1783_;
                            if _e843 {
                                let _e1240 = (_e792.member_1.member_2 * 0.1f);
                                if (_e860 != _e860) {
                                    phi_2328_ = true;
                                } else {
                                    phi_2328_ = (_e1240 >= _e860);
                                }
                                let _e1244 = phi_2328_;
                                phi_1802_ = select(_e860, _e1240, _e1244);
                            } else {
                                let _e1251 = frame.member[0u].member_1.member.member_3;
                                phi_1802_ = (_e792.member_1.member_2 * (1f + _e1251));
                            }
                            let _e1255 = phi_1802_;
                            let _e1261 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e960 > _e1261), (_e1238 > _e1255)), true, _e1235), (_e828 != 0u)), select(false, !(_e967), _e882)) {
                                if (_e828 != 1u) {
                                } else {
                                    let _e1280 = frame.member[0u].member_1.member_5[0u];
                                    let _e1286 = frame.member[0u].member_1.member_5[1u];
                                    let _e1293 = frame.member[0u].member_1.member_4;
                                    let _e1294 = f32(_e1293);
                                    let _e1295 = (2u * _e1293);
                                    let _e1296 = (_e1280 + _e1295);
                                    let _e1302 = (floor((_e906 * f32(_e1280))) + _e1294);
                                    let _e1303 = f32((_e1296 - 1u));
                                    let _e1307 = select(0f, select(_e1303, _e1302, (_e1302 < _e1303)), (_e1302 > 0f));
                                    let _e1310 = (floor((_e909 * f32(_e1286))) + _e1294);
                                    let _e1311 = f32(((_e1286 + _e1295) - 1u));
                                    let _e1315 = select(0f, select(_e1311, _e1310, (_e1310 < _e1311)), (_e1310 > 0f));
                                    let _e1327 = ((select(select(u32(_e1315), 0u, (_e1315 < 0f)), 4294967295u, (_e1315 > 4294967000f)) * _e1296) + select(select(u32(_e1307), 0u, (_e1307 < 0f)), 4294967295u, (_e1307 > 4294967000f)));
                                    let _e1332 = frame.member[0u].member_1.member_2;
                                    if (_e1332 == 0u) {
                                        if (_e1327 < _e502) {
                                        } else {
                                            phi_2372_ = true;
                                            break;
                                        }
                                        let _e1337 = atomicMax((&ray_max.member[_e1327]), 1u);
                                    } else {
                                        if _e843 {
                                            if (_e1238 != _e1238) {
                                                phi_2343_ = true;
                                            } else {
                                                phi_2343_ = (_e860 <= _e1238);
                                            }
                                            let _e1341 = phi_2343_;
                                            phi_1954_ = select(_e1238, _e860, _e1341);
                                        } else {
                                            let _e1348 = frame.member[0u].member_1.member.member_3;
                                            let _e1351 = (((1f + _e1348) * _e792.member_1.member_2) + _e860);
                                            if (_e1238 != _e1238) {
                                                phi_2358_ = true;
                                            } else {
                                                phi_2358_ = (_e1351 <= _e1238);
                                            }
                                            let _e1355 = phi_2358_;
                                            phi_1954_ = select(_e1238, _e1351, _e1355);
                                        }
                                        let _e1358 = phi_1954_;
                                        let _e1359 = (_e806 - _e1358);
                                        if (_e1359 > 0f) {
                                            phi_1961_ = bitcast<u32>(_e1359);
                                        } else {
                                            phi_1961_ = 0u;
                                        }
                                        let _e1363 = phi_1961_;
                                        if (_e1327 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2372_ = true;
                                            break;
                                        }
                                        let _e1367 = atomicMin((&ray_min.member[_e1327]), _e1363);
                                        let _e1368 = (_e806 - _e879);
                                        if (_e1368 > 0f) {
                                            phi_1975_ = bitcast<u32>(_e1368);
                                        } else {
                                            phi_1975_ = 0u;
                                        }
                                        let _e1372 = phi_1975_;
                                        if (_e1327 < _e502) {
                                        } else {
                                            phi_2372_ = true;
                                            break;
                                        }
                                        let _e1376 = atomicMax((&ray_max.member[_e1327]), _e1372);
                                    }
                                }
                                phi_1983_ = (_e810 | (1u << bitcast<u32>((_e808 & 31u))));
                            } else {
                                phi_1983_ = _e810;
                            }
                            let _e1378 = phi_1983_;
                            phi_1022_ = (_e808 + 1u);
                            phi_1025_ = _e1378;
                            phi_1027_ = (_e812 + select(0f, select(_e1215.member_1, _e1221, _e967), _e882));
                        } else {
                            phi_1022_ = u32();
                            phi_1025_ = u32();
                            phi_1027_ = f32();
                        }
                        let _e1381 = phi_1022_;
                        let _e1383 = phi_1025_;
                        let _e1385 = phi_1027_;
                        continue;
                        continuing {
                            phi_1021_ = _e1381;
                            phi_1024_ = _e1383;
                            phi_1026_ = _e1385;
                            phi_2372_ = false;
                            break if !(_e823);
                        }
                    }
                    let _e1388 = phi_2372_;
                    if _e1388 {
                        break;
                    }
                    let _e1393 = frame.member[0u].member_1.member_10;
                    let _e1394 = (_e1393 == 1u);
                    let _e1397 = local_7;
                    let _e1401 = local_8;
                    let _e1402 = ((select(2f, 1f, _e1394) / f32(_e1397)) * _e1401);
                    let _e1404 = local_9;
                    if (_e1404 == 0u) {
                        if _e1394 {
                            phi_2016_ = (1f - (2f * _e1402));
                        } else {
                            phi_2016_ = _e1402;
                        }
                        let _e1409 = phi_2016_;
                        let _e1419 = frame.member[0u].member_1.member.member_2;
                        let _e1422 = local_10;
                        phi_2045_ = type_42(pow(select(0f, select(1f, _e1409, (_e1409 < 1f)), (_e1409 > 0f)), _e1419), _e1422);
                    } else {
                        let _e1432 = local_11;
                        phi_2045_ = type_42((round((select(0f, select(1f, _e1402, (_e1402 < 1f)), (_e1402 > 0f)) * 255f)) * 0.003921569f), _e1432);
                    }
                    let _e1435 = phi_2045_;
                    phi_2050_ = _e1435;
                } else {
                    phi_2050_ = type_42(1f, 0u);
                }
                let _e1437 = phi_2050_;
                if (_e580 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e580] = _e1437.member;
                if (_e580 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e580] = _e1437.member_1;
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
