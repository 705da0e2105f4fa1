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
    var phi_711_: bool;
    var phi_713_: bool;
    var phi_714_: bool;
    var phi_715_: bool;
    var phi_716_: bool;
    var phi_2199_: bool;
    var phi_2214_: bool;
    var phi_2175_: vec2<f32>;
    var phi_979_: type_31;
    var phi_1001_: u32;
    var phi_1004_: u32;
    var phi_1006_: f32;
    var phi_1071_: f32;
    var phi_1096_: f32;
    var phi_1109_: f32;
    var phi_1484_: f32;
    var phi_1513_: f32;
    var phi_1716_: f32;
    var phi_1748_: f32;
    var phi_1754_: type_41;
    var phi_1770_: f32;
    var phi_1789_: bool;
    var phi_1790_: bool;
    var phi_1802_: f32;
    var phi_1827_: f32;
    var phi_2229_: bool;
    var phi_2244_: bool;
    var phi_1979_: f32;
    var phi_1986_: u32;
    var phi_2000_: u32;
    var phi_2008_: u32;
    var phi_1002_: u32;
    var phi_1005_: u32;
    var phi_1007_: f32;
    var phi_2258_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_2041_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2070_: type_42;
    var phi_2075_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e488 = id_1;
            let _e498 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e508 = frame.member[0u].member_1.member.member.member_4;
            let _e509 = (_e488.x + _e508);
            let _e510 = (_e488.y + _e508);
            let _e518 = frame.member[0u].member_1.member.member.member[0u];
            let _e523 = select(select(u32(_e518), 0u, (_e518 < 0f)), 4294967295u, (_e518 > 4294967000f));
            let _e531 = frame.member[0u].member_1.member.member.member[1u];
            let _e536 = select(select(u32(_e531), 0u, (_e531 < 0f)), 4294967295u, (_e531 > 4294967000f));
            if (_e509 >= _e508) {
                if (_e510 >= _e508) {
                    let _e540 = ((_e509 + _e508) < _e523);
                    if _e540 {
                        phi_711_ = ((_e510 + _e508) < _e536);
                    } else {
                        phi_711_ = bool();
                    }
                    let _e544 = phi_711_;
                    phi_713_ = _e544;
                    phi_714_ = select(true, false, _e540);
                } else {
                    phi_713_ = bool();
                    phi_714_ = true;
                }
                let _e547 = phi_713_;
                let _e549 = phi_714_;
                phi_715_ = _e547;
                phi_716_ = _e549;
            } else {
                phi_715_ = bool();
                phi_716_ = true;
            }
            let _e551 = phi_715_;
            let _e553 = phi_716_;
            if select(_e551, false, _e553) {
                let _e560 = frame.member[0u].member_1.member.member_1;
                let _e566 = frame.member[0u].member_1.member.member_4;
                let _e570 = ((f32(bitcast<i32>(_e509)) + 0.5f) / _e518);
                let _e574 = ((f32(bitcast<i32>(_e510)) + 0.5f) / _e531);
                let _e576 = ((_e510 * _e523) + _e509);
                let _e578 = depth.member[_e576];
                let _e586 = frame.member[0u].member_1.member.member.member_1[0u];
                let _e594 = frame.member[0u].member_1.member.member.member_1[1u];
                let _e604 = ((((_e560 * _e518) / (_e578 * (2f * _e586))) + ((_e560 * _e531) / (_e578 * (2f * _e594)))) * 0.5f);
                let _e605 = (_e604 > _e566);
                let _e609 = select(_e604, _e566, _e605);
                let _e616 = frame.member[0u].member_1.member.member.member_3;
                let _e628 = ((((_e570 * 2f) - 1f) * _e578) * _e586);
                let _e630 = ((((_e574 * -2f) + 1f) * _e578) * _e594);
                let _e631 = -(_e578);
                let _e634 = normals.member[_e576];
                let _e642 = (f32((bitcast<i32>(((_e634 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e642 != _e642) {
                    phi_2199_ = true;
                } else {
                    phi_2199_ = (-1f >= _e642);
                }
                let _e646 = phi_2199_;
                let _e647 = select(_e642, -1f, _e646);
                let _e657 = (f32((bitcast<i32>((((_e634 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e657 != _e657) {
                    phi_2214_ = true;
                } else {
                    phi_2214_ = (-1f >= _e657);
                }
                let _e661 = phi_2214_;
                let _e662 = select(_e657, -1f, _e661);
                let _e665 = (1f - abs(_e647));
                let _e666 = abs(_e662);
                let _e667 = (_e665 - _e666);
                if (_e667 < 0f) {
                    phi_2175_ = vec2<f32>(((1f - _e666) * select(1f, -1f, (_e647 < 0f))), (_e665 * select(1f, -1f, (_e662 < 0f))));
                } else {
                    phi_2175_ = vec2<f32>(_e647, _e662);
                }
                let _e678 = phi_2175_;
                let _e687 = (1f / sqrt((((_e678.x * _e678.x) + (_e678.y * _e678.y)) + (_e667 * _e667))));
                let _e688 = (_e678.x * _e687);
                let _e689 = (_e678.y * _e687);
                let _e690 = (_e667 * _e687);
                let _e696 = ((((_e628 * _e688) + (_e630 * _e689)) + (_e631 * _e690)) > 0f);
                let _e700 = select(_e688, -(_e688), _e696);
                let _e701 = select(_e689, -(_e689), _e696);
                let _e702 = select(_e690, -(_e690), _e696);
                local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e704 = (_e510 % 4u);
                if (_e704 < 4u) {
                } else {
                    break;
                }
                let _e706 = (_e509 % 4u);
                if (_e706 < 4u) {
                } else {
                    break;
                }
                let _e710 = local_6[_e704][_e706];
                let _e720 = sqrt((((_e628 * _e628) + (_e630 * _e630)) + (_e631 * _e631)));
                let _e721 = (-(_e628) / _e720);
                let _e722 = (-(_e630) / _e720);
                let _e723 = (_e578 / _e720);
                let _e726 = -((_e710[1] * _e723));
                let _e727 = (_e723 * _e710[0]);
                let _e730 = ((_e721 * _e710[1]) - (_e710[0] * _e722));
                let _e737 = (1f / sqrt((((_e726 * _e726) + (_e727 * _e727)) + (_e730 * _e730))));
                let _e738 = (_e726 * _e737);
                let _e739 = (_e727 * _e737);
                let _e740 = (_e730 * _e737);
                let _e744 = ((_e739 * _e723) - (_e722 * _e740));
                let _e747 = ((_e740 * _e721) - (_e723 * _e738));
                let _e750 = ((_e738 * _e722) - (_e721 * _e739));
                let _e766 = (((_e700 * _e721) + (_e701 * _e722)) + (_e702 * _e723));
                let _e770 = abs(_e766);
                if select(false, !((_e609 < 0.5f)), select(false, (_e578 < _e616), (_e578 > 0f))) {
                    phi_979_ = type_31(1u, type_30(vec2<u32>(_e509, _e510), vec2<f32>(_e570, _e574), select(_e560, ((_e560 * _e566) / _e604), _e605), _e609, vec3<f32>(_e628, _e630, _e631), vec3<f32>(_e700, _e701, _e702), vec3<f32>(_e721, _e722, _e723), vec3<f32>(_e744, _e747, _e750), vec3<f32>(_e738, _e739, _e740), vec3<f32>((((_e700 * _e744) + (_e701 * _e747)) + (_e702 * _e750)), (((_e700 * _e738) + (_e701 * _e739)) + (_e702 * _e740)), _e766), (1f / (select(1f, -1f, (_e766 < 0f)) * select(0.0001f, _e770, ((_e770 > 0.0001f) || false))))));
                } else {
                    phi_979_ = type_31(0u, type_31().member_1);
                }
                let _e784 = phi_979_;
                if (bitcast<i32>(_e784.member) != 0i) {
                    let _e798 = sqrt((((_e784.member_1.member_4.x * _e784.member_1.member_4.x) + (_e784.member_1.member_4.y * _e784.member_1.member_4.y)) + (_e784.member_1.member_4.z * _e784.member_1.member_4.z)));
                    phi_1001_ = 0u;
                    phi_1004_ = 0u;
                    phi_1006_ = 0f;
                    loop {
                        let _e800 = phi_1001_;
                        let _e802 = phi_1004_;
                        let _e804 = phi_1006_;
                        let _e809 = frame.member[0u].member_1.member_11;
                        local_8 = _e804;
                        local_9 = _e802;
                        local_10 = _e802;
                        local_11 = _e802;
                        let _e814 = (8u << bitcast<u32>((select(_e809, 2u, (2u < _e809)) & 31u)));
                        let _e815 = (_e800 < _e814);
                        local_7 = _e814;
                        if _e815 {
                            let _e820 = frame.member[0u].member_1.member_1;
                            let _e821 = (_e820 == 1u);
                            let _e827 = frame.member[0u].member_1.member_10;
                            let _e829 = ((_e814 + _e800) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e830 = (_e829 < 56u);
                            if _e830 {
                            } else {
                                phi_2258_ = true;
                                break;
                            }
                            let _e832 = local[_e829];
                            let _e835 = (_e827 == 1u);
                            if _e835 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e830 {
                                } else {
                                    phi_2258_ = true;
                                    break;
                                }
                                let _e837 = local_1[_e829];
                                phi_1071_ = _e837;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e830 {
                                } else {
                                    phi_2258_ = true;
                                    break;
                                }
                                let _e839 = local_2[_e829];
                                phi_1071_ = _e839;
                            }
                            let _e841 = phi_1071_;
                            let _e843 = (_e784.member_1.member_2 * _e841);
                            let _e844 = (_e843 * _e832[0]);
                            let _e845 = (_e843 * _e832[1]);
                            if _e835 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e830 {
                                } else {
                                    phi_2258_ = true;
                                    break;
                                }
                                let _e847 = local_3[_e829];
                                phi_1096_ = _e847;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e830 {
                                } else {
                                    phi_2258_ = true;
                                    break;
                                }
                                let _e849 = local_4[_e829];
                                phi_1096_ = _e849;
                            }
                            let _e851 = phi_1096_;
                            let _e852 = (_e784.member_1.member_2 * _e851);
                            if _e835 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e830 {
                                } else {
                                    phi_2258_ = true;
                                    break;
                                }
                                let _e854 = local_5[_e829];
                                phi_1109_ = _e854;
                            } else {
                                phi_1109_ = (_e852 * 2f);
                            }
                            let _e857 = phi_1109_;
                            let _e866 = (-(((_e844 * _e784.member_1.member_9.x) + (_e845 * _e784.member_1.member_9.y))) * _e784.member_1.member_10);
                            let _e867 = -(_e852);
                            let _e871 = select(_e867, select(_e852, _e866, (_e866 < _e852)), (_e866 > _e867));
                            let _e872 = (_e852 - _e871);
                            let _e874 = (_e872 > (_e852 * 0.2f));
                            let _e895 = (-0.5f / ((_e784.member_1.member_4.z + (_e784.member_1.member_7.z * _e844)) + (_e784.member_1.member_8.z * _e845)));
                            let _e898 = (((((_e784.member_1.member_4.x + (_e784.member_1.member_7.x * _e844)) + (_e784.member_1.member_8.x * _e845)) * _e895) / _e586) + 0.5f);
                            let _e901 = (0.5f - ((((_e784.member_1.member_4.y + (_e784.member_1.member_7.y * _e844)) + (_e784.member_1.member_8.y * _e845)) * _e895) / _e594));
                            let _e913 = (select(0f, select(1f, _e898, (_e898 < 1f)), (_e898 > 0f)) * _e518);
                            let _e916 = f32(bitcast<i32>((_e523 - 1u)));
                            let _e918 = select(0f, _e913, (_e913 > 0f));
                            let _e924 = (bitcast<u32>((floor(select(_e916, _e918, (_e918 < _e916))) + 8388608f)) - 1258291200u);
                            let _e929 = (select(0f, select(1f, _e901, (_e901 < 1f)), (_e901 > 0f)) * _e531);
                            let _e932 = f32(bitcast<i32>((_e536 - 1u)));
                            let _e934 = select(0f, _e929, (_e929 > 0f));
                            let _e940 = (bitcast<u32>((floor(select(_e932, _e934, (_e934 < _e932))) + 8388608f)) - 1258291200u);
                            let _e947 = ((_e784.member_1.member_1.x - _e898) * _e518);
                            let _e948 = ((_e784.member_1.member_1.y - _e901) * _e531);
                            let _e952 = sqrt(((_e947 * _e947) + (_e948 * _e948)));
                            let _e959 = select(false, (_e940 == _e784.member_1.member.y), (_e924 == _e784.member_1.member.x));
                            let _e961 = ((_e940 * _e523) + _e924);
                            let _e963 = depth.member[_e961];
                            let _e977 = select(_e616, _e963, select(false, (_e963 < _e616), (_e963 > 0f)));
                            let _e979 = ((((f32(bitcast<i32>(_e924)) + 0.5f) * (1f / _e518)) * 2f) - 1f);
                            let _e981 = ((((f32(bitcast<i32>(_e940)) + 0.5f) * (1f / _e531)) * -2f) + 1f);
                            let _e987 = (((_e979 * _e977) * _e586) - _e784.member_1.member_4.x);
                            let _e988 = (((_e981 * _e977) * _e594) - _e784.member_1.member_4.y);
                            let _e989 = (-(_e977) - _e784.member_1.member_4.z);
                            let _e998 = (((_e987 * _e784.member_1.member_6.x) + (_e988 * _e784.member_1.member_6.y)) + (_e989 * _e784.member_1.member_6.z));
                            if _e835 {
                                let _e1003 = (((_e987 * _e987) + (_e988 * _e988)) + (_e989 * _e989));
                                let _e1015 = (((((_e784.member_1.member_5.x * _e987) + (_e784.member_1.member_5.y * _e988)) + (_e784.member_1.member_5.z * _e989)) / sqrt(_e1003)) - 0.1f);
                                let _e1022 = (1f - (_e1003 / (_e560 * _e560)));
                                let _e1029 = ((select(0f, select(1f, _e1015, (_e1015 < 1f)), (_e1015 > 0f)) * select(0f, select(1f, _e1022, (_e1022 < 1f)), (_e1022 > 0f))) / _e857);
                                phi_1484_ = select(0f, select(0f, select(1f, _e1029, (_e1029 < 1f)), (_e1029 > 0f)), (_e1003 > 0f));
                            } else {
                                let _e1040 = frame.member[0u].member_1.member.member_3;
                                let _e1046 = (_e852 - select(_e998, _e871, ((_e871 > _e998) || (_e998 != _e998))));
                                let _e1053 = ((_e998 - (_e784.member_1.member_2 * (1f + _e1040))) * (1f / _e852));
                                phi_1484_ = ((select(0f, _e1046, ((_e1046 > 0f) || false)) + (select(0f, select(1f, _e1053, (_e1053 < 1f)), (_e1053 > 0f)) * _e872)) * (0.5f / _e852));
                            }
                            let _e1063 = phi_1484_;
                            let _e1068 = frame.member[0u].member_1.member_9;
                            if (_e1068 == 0u) {
                                phi_1754_ = type_41(_e998, _e1063);
                            } else {
                                if _e835 {
                                    let _e1071 = (_e784.member_1.member_2 * 0.1f);
                                    phi_1513_ = select(_e1071, _e852, ((_e852 > _e1071) || (_e1071 != _e1071)));
                                } else {
                                    let _e1081 = frame.member[0u].member_1.member.member_3;
                                    phi_1513_ = (_e784.member_1.member_2 * (1f + _e1081));
                                }
                                let _e1085 = phi_1513_;
                                let _e1091 = frame.member[0u].member_1.member_3;
                                let _e1093 = select(false, (_e952 > _e1091), (_e998 > _e1085));
                                let _e1096 = depth2_.member[_e961];
                                let _e1100 = select(_e616, _e1096, select(false, (_e1096 < _e616), (_e1096 > 0f)));
                                let _e1106 = (((_e979 * _e1100) * _e586) - _e784.member_1.member_4.x);
                                let _e1107 = (((_e981 * _e1100) * _e594) - _e784.member_1.member_4.y);
                                let _e1108 = (-(_e1100) - _e784.member_1.member_4.z);
                                let _e1113 = (((_e1106 * _e784.member_1.member_6.x) + (_e1107 * _e784.member_1.member_6.y)) + (_e1108 * _e784.member_1.member_6.z));
                                if _e835 {
                                    let _e1118 = (((_e1106 * _e1106) + (_e1107 * _e1107)) + (_e1108 * _e1108));
                                    let _e1130 = (((((_e784.member_1.member_5.x * _e1106) + (_e784.member_1.member_5.y * _e1107)) + (_e784.member_1.member_5.z * _e1108)) / sqrt(_e1118)) - 0.1f);
                                    let _e1137 = (1f - (_e1118 / (_e560 * _e560)));
                                    let _e1144 = ((select(0f, select(1f, _e1130, (_e1130 < 1f)), (_e1130 > 0f)) * select(0f, select(1f, _e1137, (_e1137 < 1f)), (_e1137 > 0f))) / _e857);
                                    phi_1716_ = select(0f, select(0f, select(1f, _e1144, (_e1144 < 1f)), (_e1144 > 0f)), (_e1118 > 0f));
                                } else {
                                    let _e1155 = frame.member[0u].member_1.member.member_3;
                                    let _e1161 = (_e852 - select(_e1113, _e871, ((_e871 > _e1113) || (_e1113 != _e1113))));
                                    let _e1168 = ((_e1113 - (_e784.member_1.member_2 * (1f + _e1155))) * (1f / _e852));
                                    phi_1716_ = ((select(0f, _e1161, ((_e1161 > 0f) || false)) + (select(0f, select(1f, _e1168, (_e1168 < 1f)), (_e1168 > 0f)) * _e872)) * (0.5f / _e852));
                                }
                                let _e1178 = phi_1716_;
                                if _e835 {
                                    phi_1748_ = select(_e1178, _e1063, ((_e1063 > _e1178) || (_e1178 != _e1178)));
                                } else {
                                    phi_1748_ = select(_e1178, _e1063, ((_e1063 < _e1178) || (_e1178 != _e1178)));
                                }
                                let _e1193 = phi_1748_;
                                phi_1754_ = type_41(select(_e998, select(_e1113, _e998, ((_e998 < _e1113) || (_e1113 != _e1113))), _e1093), select(_e1063, _e1193, _e1093));
                            }
                            let _e1197 = phi_1754_;
                            if _e835 {
                                phi_1770_ = 0f;
                            } else {
                                phi_1770_ = (_e872 / (_e852 * 2f));
                            }
                            let _e1203 = phi_1770_;
                            if (_e820 == 2u) {
                                phi_1790_ = true;
                            } else {
                                if _e821 {
                                    let _e1211 = frame.member[0u].member_1.member_4;
                                    phi_1789_ = (_e1211 > 0u);
                                } else {
                                    phi_1789_ = false;
                                }
                                let _e1214 = phi_1789_;
                                phi_1790_ = _e1214;
                            }
                            let _e1216 = phi_1790_;
                            let _e1217 = select(false, _e1216, !(select(false, select(false, (_e901 <= 1f), (_e901 >= 0f)), select(false, (_e898 <= 1f), (_e898 >= 0f)))));
                            if _e821 {
                                phi_1802_ = select(_e1197.member, 0x1.fffffep+127f, _e1217);
                            } else {
                                phi_1802_ = _e1197.member;
                            }
                            let _e1220 = phi_1802_;
                            if _e835 {
                                let _e1222 = (_e784.member_1.member_2 * 0.1f);
                                phi_1827_ = select(_e1222, _e852, ((_e852 > _e1222) || (_e1222 != _e1222)));
                            } else {
                                let _e1232 = frame.member[0u].member_1.member.member_3;
                                phi_1827_ = (_e784.member_1.member_2 * (1f + _e1232));
                            }
                            let _e1236 = phi_1827_;
                            let _e1242 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e952 > _e1242), (_e1220 > _e1236)), true, _e1217), (_e820 != 0u)), select(false, !(_e959), _e874)) {
                                if (_e820 != 1u) {
                                } else {
                                    let _e1261 = frame.member[0u].member_1.member_5[0u];
                                    let _e1267 = frame.member[0u].member_1.member_5[1u];
                                    let _e1274 = frame.member[0u].member_1.member_4;
                                    let _e1275 = f32(_e1274);
                                    let _e1276 = (2u * _e1274);
                                    let _e1277 = (_e1261 + _e1276);
                                    let _e1283 = (floor((_e898 * f32(_e1261))) + _e1275);
                                    let _e1284 = f32((_e1277 - 1u));
                                    let _e1288 = select(0f, select(_e1284, _e1283, (_e1283 < _e1284)), (_e1283 > 0f));
                                    let _e1291 = (floor((_e901 * f32(_e1267))) + _e1275);
                                    let _e1292 = f32(((_e1267 + _e1276) - 1u));
                                    let _e1296 = select(0f, select(_e1292, _e1291, (_e1291 < _e1292)), (_e1291 > 0f));
                                    let _e1308 = ((select(select(u32(_e1296), 0u, (_e1296 < 0f)), 4294967295u, (_e1296 > 4294967000f)) * _e1277) + select(select(u32(_e1288), 0u, (_e1288 < 0f)), 4294967295u, (_e1288 > 4294967000f)));
                                    let _e1313 = frame.member[0u].member_1.member_2;
                                    if (_e1313 == 0u) {
                                        if (_e1308 < _e498) {
                                        } else {
                                            phi_2258_ = true;
                                            break;
                                        }
                                        let _e1318 = atomicMax((&ray_max.member[_e1308]), 1u);
                                    } else {
                                        if _e835 {
                                            if (_e1220 != _e1220) {
                                                phi_2229_ = true;
                                            } else {
                                                phi_2229_ = (_e852 <= _e1220);
                                            }
                                            let _e1322 = phi_2229_;
                                            phi_1979_ = select(_e1220, _e852, _e1322);
                                        } else {
                                            let _e1329 = frame.member[0u].member_1.member.member_3;
                                            let _e1332 = (((1f + _e1329) * _e784.member_1.member_2) + _e852);
                                            if (_e1220 != _e1220) {
                                                phi_2244_ = true;
                                            } else {
                                                phi_2244_ = (_e1332 <= _e1220);
                                            }
                                            let _e1336 = phi_2244_;
                                            phi_1979_ = select(_e1220, _e1332, _e1336);
                                        }
                                        let _e1339 = phi_1979_;
                                        let _e1340 = (_e798 - _e1339);
                                        if (_e1340 > 0f) {
                                            phi_1986_ = bitcast<u32>(_e1340);
                                        } else {
                                            phi_1986_ = 0u;
                                        }
                                        let _e1344 = phi_1986_;
                                        if (_e1308 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2258_ = true;
                                            break;
                                        }
                                        let _e1348 = atomicMin((&ray_min.member[_e1308]), _e1344);
                                        let _e1349 = (_e798 - _e871);
                                        if (_e1349 > 0f) {
                                            phi_2000_ = bitcast<u32>(_e1349);
                                        } else {
                                            phi_2000_ = 0u;
                                        }
                                        let _e1353 = phi_2000_;
                                        if (_e1308 < _e498) {
                                        } else {
                                            phi_2258_ = true;
                                            break;
                                        }
                                        let _e1357 = atomicMax((&ray_max.member[_e1308]), _e1353);
                                    }
                                }
                                phi_2008_ = (_e802 | (1u << bitcast<u32>((_e800 & 31u))));
                            } else {
                                phi_2008_ = _e802;
                            }
                            let _e1359 = phi_2008_;
                            phi_1002_ = (_e800 + 1u);
                            phi_1005_ = _e1359;
                            phi_1007_ = (_e804 + select(0f, select(_e1197.member_1, _e1203, _e959), _e874));
                        } else {
                            phi_1002_ = u32();
                            phi_1005_ = u32();
                            phi_1007_ = f32();
                        }
                        let _e1362 = phi_1002_;
                        let _e1364 = phi_1005_;
                        let _e1366 = phi_1007_;
                        continue;
                        continuing {
                            phi_1001_ = _e1362;
                            phi_1004_ = _e1364;
                            phi_1006_ = _e1366;
                            phi_2258_ = false;
                            break if !(_e815);
                        }
                    }
                    let _e1369 = phi_2258_;
                    if _e1369 {
                        break;
                    }
                    let _e1374 = frame.member[0u].member_1.member_10;
                    let _e1375 = (_e1374 == 1u);
                    let _e1378 = local_7;
                    let _e1382 = local_8;
                    let _e1383 = ((select(2f, 1f, _e1375) / f32(_e1378)) * _e1382);
                    let _e1385 = local_9;
                    if (_e1385 == 0u) {
                        if _e1375 {
                            phi_2041_ = (1f - (2f * _e1383));
                        } else {
                            phi_2041_ = _e1383;
                        }
                        let _e1390 = phi_2041_;
                        let _e1400 = frame.member[0u].member_1.member.member_2;
                        let _e1403 = local_10;
                        phi_2070_ = type_42(pow(select(0f, select(1f, _e1390, (_e1390 < 1f)), (_e1390 > 0f)), _e1400), _e1403);
                    } else {
                        let _e1413 = local_11;
                        phi_2070_ = type_42((round((select(0f, select(1f, _e1383, (_e1383 < 1f)), (_e1383 > 0f)) * 255f)) * 0.003921569f), _e1413);
                    }
                    let _e1416 = phi_2070_;
                    phi_2075_ = _e1416;
                } else {
                    phi_2075_ = type_42(1f, 0u);
                }
                let _e1418 = phi_2075_;
                ao.member[_e576] = _e1418.member;
                if (_e576 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e576] = _e1418.member_1;
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
