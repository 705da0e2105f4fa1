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
    var phi_617_: bool;
    var phi_619_: bool;
    var phi_620_: bool;
    var phi_621_: bool;
    var phi_622_: bool;
    var phi_950_: type_31;
    var phi_972_: u32;
    var phi_975_: u32;
    var phi_977_: f32;
    var phi_1042_: f32;
    var phi_1067_: f32;
    var phi_1080_: f32;
    var phi_1455_: f32;
    var phi_1484_: f32;
    var phi_1687_: f32;
    var phi_1719_: f32;
    var phi_1725_: type_41;
    var phi_1741_: f32;
    var phi_1760_: bool;
    var phi_1761_: bool;
    var phi_1773_: f32;
    var phi_1798_: f32;
    var phi_2098_: bool;
    var phi_2113_: bool;
    var phi_1946_: f32;
    var phi_1953_: u32;
    var phi_1967_: u32;
    var phi_1975_: u32;
    var phi_973_: u32;
    var phi_976_: u32;
    var phi_978_: f32;
    var phi_2118_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_2008_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2037_: type_42;
    var phi_2042_: type_42;

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
                        phi_617_ = ((_e510 + _e508) < _e536);
                    } else {
                        phi_617_ = bool();
                    }
                    let _e544 = phi_617_;
                    phi_619_ = _e544;
                    phi_620_ = select(true, false, _e540);
                } else {
                    phi_619_ = bool();
                    phi_620_ = true;
                }
                let _e547 = phi_619_;
                let _e549 = phi_620_;
                phi_621_ = _e547;
                phi_622_ = _e549;
            } else {
                phi_621_ = bool();
                phi_622_ = true;
            }
            let _e551 = phi_621_;
            let _e553 = phi_622_;
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
                let _e637 = f32(bitcast<i32>((_e634 & 255u)));
                let _e641 = (select(_e637, (_e637 - 256f), (_e637 >= 128f)) * 0.007874016f);
                let _e644 = select(-1f, _e641, ((_e641 > -1f) || false));
                let _e649 = f32(bitcast<i32>(((_e634 >> bitcast<u32>(8u)) & 255u)));
                let _e653 = (select(_e649, (_e649 - 256f), (_e649 >= 128f)) * 0.007874016f);
                let _e656 = select(-1f, _e653, ((_e653 > -1f) || false));
                let _e658 = (1f - abs(_e644));
                let _e659 = abs(_e656);
                let _e660 = (_e658 - _e659);
                let _e661 = (_e660 < 0f);
                let _e669 = select(_e644, ((1f - _e659) * select(1f, -1f, (_e644 < 0f))), _e661);
                let _e670 = select(_e656, (_e658 * select(1f, -1f, (_e656 < 0f))), _e661);
                let _e677 = (1f / sqrt((((_e669 * _e669) + (_e670 * _e670)) + (_e660 * _e660))));
                let _e678 = (_e669 * _e677);
                let _e679 = (_e670 * _e677);
                let _e680 = (_e660 * _e677);
                let _e686 = ((((_e628 * _e678) + (_e630 * _e679)) + (_e631 * _e680)) > 0f);
                let _e690 = select(_e678, -(_e678), _e686);
                let _e691 = select(_e679, -(_e679), _e686);
                let _e692 = select(_e680, -(_e680), _e686);
                local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e694 = (_e510 % 4u);
                if (_e694 < 4u) {
                } else {
                    break;
                }
                let _e696 = (_e509 % 4u);
                if (_e696 < 4u) {
                } else {
                    break;
                }
                let _e700 = local_6[_e694][_e696];
                let _e710 = sqrt((((_e628 * _e628) + (_e630 * _e630)) + (_e631 * _e631)));
                let _e711 = (-(_e628) / _e710);
                let _e712 = (-(_e630) / _e710);
                let _e713 = (_e578 / _e710);
                let _e716 = -((_e700[1] * _e713));
                let _e717 = (_e713 * _e700[0]);
                let _e720 = ((_e711 * _e700[1]) - (_e700[0] * _e712));
                let _e727 = (1f / sqrt((((_e716 * _e716) + (_e717 * _e717)) + (_e720 * _e720))));
                let _e728 = (_e716 * _e727);
                let _e729 = (_e717 * _e727);
                let _e730 = (_e720 * _e727);
                let _e734 = ((_e729 * _e713) - (_e712 * _e730));
                let _e737 = ((_e730 * _e711) - (_e713 * _e728));
                let _e740 = ((_e728 * _e712) - (_e711 * _e729));
                let _e756 = (((_e690 * _e711) + (_e691 * _e712)) + (_e692 * _e713));
                let _e760 = abs(_e756);
                if select(false, !((_e609 < 0.5f)), select(false, (_e578 < _e616), (_e578 > 0f))) {
                    phi_950_ = type_31(1u, type_30(vec2<u32>(_e509, _e510), vec2<f32>(_e570, _e574), select(_e560, ((_e560 * _e566) / _e604), _e605), _e609, vec3<f32>(_e628, _e630, _e631), vec3<f32>(_e690, _e691, _e692), vec3<f32>(_e711, _e712, _e713), vec3<f32>(_e734, _e737, _e740), vec3<f32>(_e728, _e729, _e730), vec3<f32>((((_e690 * _e734) + (_e691 * _e737)) + (_e692 * _e740)), (((_e690 * _e728) + (_e691 * _e729)) + (_e692 * _e730)), _e756), (1f / (select(1f, -1f, (_e756 < 0f)) * select(0.0001f, _e760, ((_e760 > 0.0001f) || false))))));
                } else {
                    phi_950_ = type_31(0u, type_31().member_1);
                }
                let _e774 = phi_950_;
                if (bitcast<i32>(_e774.member) != 0i) {
                    let _e788 = sqrt((((_e774.member_1.member_4.x * _e774.member_1.member_4.x) + (_e774.member_1.member_4.y * _e774.member_1.member_4.y)) + (_e774.member_1.member_4.z * _e774.member_1.member_4.z)));
                    phi_972_ = 0u;
                    phi_975_ = 0u;
                    phi_977_ = 0f;
                    loop {
                        let _e790 = phi_972_;
                        let _e792 = phi_975_;
                        let _e794 = phi_977_;
                        let _e799 = frame.member[0u].member_1.member_11;
                        local_8 = _e794;
                        local_9 = _e792;
                        local_10 = _e792;
                        local_11 = _e792;
                        let _e804 = (8u << bitcast<u32>((select(_e799, 2u, (2u < _e799)) & 31u)));
                        let _e805 = (_e790 < _e804);
                        local_7 = _e804;
                        if _e805 {
                            let _e810 = frame.member[0u].member_1.member_1;
                            let _e811 = (_e810 == 1u);
                            let _e817 = frame.member[0u].member_1.member_10;
                            let _e819 = ((_e804 + _e790) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e820 = (_e819 < 56u);
                            if _e820 {
                            } else {
                                phi_2118_ = true;
                                break;
                            }
                            let _e822 = local[_e819];
                            let _e825 = (_e817 == 1u);
                            if _e825 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e820 {
                                } else {
                                    phi_2118_ = true;
                                    break;
                                }
                                let _e827 = local_1[_e819];
                                phi_1042_ = _e827;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e820 {
                                } else {
                                    phi_2118_ = true;
                                    break;
                                }
                                let _e829 = local_2[_e819];
                                phi_1042_ = _e829;
                            }
                            let _e831 = phi_1042_;
                            let _e833 = (_e774.member_1.member_2 * _e831);
                            let _e834 = (_e833 * _e822[0]);
                            let _e835 = (_e833 * _e822[1]);
                            if _e825 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e820 {
                                } else {
                                    phi_2118_ = true;
                                    break;
                                }
                                let _e837 = local_3[_e819];
                                phi_1067_ = _e837;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e820 {
                                } else {
                                    phi_2118_ = true;
                                    break;
                                }
                                let _e839 = local_4[_e819];
                                phi_1067_ = _e839;
                            }
                            let _e841 = phi_1067_;
                            let _e842 = (_e774.member_1.member_2 * _e841);
                            if _e825 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e820 {
                                } else {
                                    phi_2118_ = true;
                                    break;
                                }
                                let _e844 = local_5[_e819];
                                phi_1080_ = _e844;
                            } else {
                                phi_1080_ = (_e842 * 2f);
                            }
                            let _e847 = phi_1080_;
                            let _e856 = (-(((_e834 * _e774.member_1.member_9.x) + (_e835 * _e774.member_1.member_9.y))) * _e774.member_1.member_10);
                            let _e857 = -(_e842);
                            let _e861 = select(_e857, select(_e842, _e856, (_e856 < _e842)), (_e856 > _e857));
                            let _e862 = (_e842 - _e861);
                            let _e864 = (_e862 > (_e842 * 0.2f));
                            let _e885 = (-0.5f / ((_e774.member_1.member_4.z + (_e774.member_1.member_7.z * _e834)) + (_e774.member_1.member_8.z * _e835)));
                            let _e888 = (((((_e774.member_1.member_4.x + (_e774.member_1.member_7.x * _e834)) + (_e774.member_1.member_8.x * _e835)) * _e885) / _e586) + 0.5f);
                            let _e891 = (0.5f - ((((_e774.member_1.member_4.y + (_e774.member_1.member_7.y * _e834)) + (_e774.member_1.member_8.y * _e835)) * _e885) / _e594));
                            let _e903 = (select(0f, select(1f, _e888, (_e888 < 1f)), (_e888 > 0f)) * _e518);
                            let _e906 = f32(bitcast<i32>((_e523 - 1u)));
                            let _e914 = (bitcast<u32>((floor(select(0f, select(_e906, _e903, (_e903 < _e906)), (_e903 > 0f))) + 8388608f)) - 1258291200u);
                            let _e919 = (select(0f, select(1f, _e891, (_e891 < 1f)), (_e891 > 0f)) * _e531);
                            let _e922 = f32(bitcast<i32>((_e536 - 1u)));
                            let _e930 = (bitcast<u32>((floor(select(0f, select(_e922, _e919, (_e919 < _e922)), (_e919 > 0f))) + 8388608f)) - 1258291200u);
                            let _e937 = ((_e774.member_1.member_1.x - _e888) * _e518);
                            let _e938 = ((_e774.member_1.member_1.y - _e891) * _e531);
                            let _e942 = sqrt(((_e937 * _e937) + (_e938 * _e938)));
                            let _e949 = select(false, (_e930 == _e774.member_1.member.y), (_e914 == _e774.member_1.member.x));
                            let _e951 = ((_e930 * _e523) + _e914);
                            let _e953 = depth.member[_e951];
                            let _e967 = select(_e616, _e953, select(false, (_e953 < _e616), (_e953 > 0f)));
                            let _e969 = ((((f32(bitcast<i32>(_e914)) + 0.5f) * (1f / _e518)) * 2f) - 1f);
                            let _e971 = ((((f32(bitcast<i32>(_e930)) + 0.5f) * (1f / _e531)) * -2f) + 1f);
                            let _e977 = (((_e969 * _e967) * _e586) - _e774.member_1.member_4.x);
                            let _e978 = (((_e971 * _e967) * _e594) - _e774.member_1.member_4.y);
                            let _e979 = (-(_e967) - _e774.member_1.member_4.z);
                            let _e988 = (((_e977 * _e774.member_1.member_6.x) + (_e978 * _e774.member_1.member_6.y)) + (_e979 * _e774.member_1.member_6.z));
                            if _e825 {
                                let _e993 = (((_e977 * _e977) + (_e978 * _e978)) + (_e979 * _e979));
                                let _e1005 = (((((_e774.member_1.member_5.x * _e977) + (_e774.member_1.member_5.y * _e978)) + (_e774.member_1.member_5.z * _e979)) / sqrt(_e993)) - 0.1f);
                                let _e1012 = (1f - (_e993 / (_e560 * _e560)));
                                let _e1019 = ((select(0f, select(1f, _e1005, (_e1005 < 1f)), (_e1005 > 0f)) * select(0f, select(1f, _e1012, (_e1012 < 1f)), (_e1012 > 0f))) / _e847);
                                phi_1455_ = select(0f, select(0f, select(1f, _e1019, (_e1019 < 1f)), (_e1019 > 0f)), (_e993 > 0f));
                            } else {
                                let _e1030 = frame.member[0u].member_1.member.member_3;
                                let _e1036 = (_e842 - select(_e988, _e861, ((_e861 > _e988) || (_e988 != _e988))));
                                let _e1043 = ((_e988 - (_e774.member_1.member_2 * (1f + _e1030))) * (1f / _e842));
                                phi_1455_ = ((select(0f, _e1036, ((_e1036 > 0f) || false)) + (select(0f, select(1f, _e1043, (_e1043 < 1f)), (_e1043 > 0f)) * _e862)) * (0.5f / _e842));
                            }
                            let _e1053 = phi_1455_;
                            let _e1058 = frame.member[0u].member_1.member_9;
                            if (_e1058 == 0u) {
                                phi_1725_ = type_41(_e988, _e1053);
                            } else {
                                if _e825 {
                                    let _e1061 = (_e774.member_1.member_2 * 0.1f);
                                    phi_1484_ = select(_e1061, _e842, ((_e842 > _e1061) || (_e1061 != _e1061)));
                                } else {
                                    let _e1071 = frame.member[0u].member_1.member.member_3;
                                    phi_1484_ = (_e774.member_1.member_2 * (1f + _e1071));
                                }
                                let _e1075 = phi_1484_;
                                let _e1081 = frame.member[0u].member_1.member_3;
                                let _e1083 = select(false, (_e942 > _e1081), (_e988 > _e1075));
                                let _e1086 = depth2_.member[_e951];
                                let _e1090 = select(_e616, _e1086, select(false, (_e1086 < _e616), (_e1086 > 0f)));
                                let _e1096 = (((_e969 * _e1090) * _e586) - _e774.member_1.member_4.x);
                                let _e1097 = (((_e971 * _e1090) * _e594) - _e774.member_1.member_4.y);
                                let _e1098 = (-(_e1090) - _e774.member_1.member_4.z);
                                let _e1103 = (((_e1096 * _e774.member_1.member_6.x) + (_e1097 * _e774.member_1.member_6.y)) + (_e1098 * _e774.member_1.member_6.z));
                                if _e825 {
                                    let _e1108 = (((_e1096 * _e1096) + (_e1097 * _e1097)) + (_e1098 * _e1098));
                                    let _e1120 = (((((_e774.member_1.member_5.x * _e1096) + (_e774.member_1.member_5.y * _e1097)) + (_e774.member_1.member_5.z * _e1098)) / sqrt(_e1108)) - 0.1f);
                                    let _e1127 = (1f - (_e1108 / (_e560 * _e560)));
                                    let _e1134 = ((select(0f, select(1f, _e1120, (_e1120 < 1f)), (_e1120 > 0f)) * select(0f, select(1f, _e1127, (_e1127 < 1f)), (_e1127 > 0f))) / _e847);
                                    phi_1687_ = select(0f, select(0f, select(1f, _e1134, (_e1134 < 1f)), (_e1134 > 0f)), (_e1108 > 0f));
                                } else {
                                    let _e1145 = frame.member[0u].member_1.member.member_3;
                                    let _e1151 = (_e842 - select(_e1103, _e861, ((_e861 > _e1103) || (_e1103 != _e1103))));
                                    let _e1158 = ((_e1103 - (_e774.member_1.member_2 * (1f + _e1145))) * (1f / _e842));
                                    phi_1687_ = ((select(0f, _e1151, ((_e1151 > 0f) || false)) + (select(0f, select(1f, _e1158, (_e1158 < 1f)), (_e1158 > 0f)) * _e862)) * (0.5f / _e842));
                                }
                                let _e1168 = phi_1687_;
                                if _e825 {
                                    phi_1719_ = select(_e1168, _e1053, ((_e1053 > _e1168) || (_e1168 != _e1168)));
                                } else {
                                    phi_1719_ = select(_e1168, _e1053, ((_e1053 < _e1168) || (_e1168 != _e1168)));
                                }
                                let _e1183 = phi_1719_;
                                phi_1725_ = type_41(select(_e988, select(_e1103, _e988, ((_e988 < _e1103) || (_e1103 != _e1103))), _e1083), select(_e1053, _e1183, _e1083));
                            }
                            let _e1187 = phi_1725_;
                            if _e825 {
                                phi_1741_ = 0f;
                            } else {
                                phi_1741_ = (_e862 / (_e842 * 2f));
                            }
                            let _e1193 = phi_1741_;
                            if (_e810 == 2u) {
                                phi_1761_ = true;
                            } else {
                                if _e811 {
                                    let _e1201 = frame.member[0u].member_1.member_4;
                                    phi_1760_ = (_e1201 > 0u);
                                } else {
                                    phi_1760_ = false;
                                }
                                let _e1204 = phi_1760_;
                                phi_1761_ = _e1204;
                            }
                            let _e1206 = phi_1761_;
                            let _e1207 = select(false, _e1206, !(select(false, select(false, (_e891 <= 1f), (_e891 >= 0f)), select(false, (_e888 <= 1f), (_e888 >= 0f)))));
                            if _e811 {
                                phi_1773_ = select(_e1187.member, 0x1.fffffep+127f, _e1207);
                            } else {
                                phi_1773_ = _e1187.member;
                            }
                            let _e1210 = phi_1773_;
                            if _e825 {
                                let _e1212 = (_e774.member_1.member_2 * 0.1f);
                                phi_1798_ = select(_e1212, _e842, ((_e842 > _e1212) || (_e1212 != _e1212)));
                            } else {
                                let _e1222 = frame.member[0u].member_1.member.member_3;
                                phi_1798_ = (_e774.member_1.member_2 * (1f + _e1222));
                            }
                            let _e1226 = phi_1798_;
                            let _e1232 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e942 > _e1232), (_e1210 > _e1226)), true, _e1207), (_e810 != 0u)), select(false, !(_e949), _e864)) {
                                if (_e810 != 1u) {
                                } else {
                                    let _e1251 = frame.member[0u].member_1.member_5[0u];
                                    let _e1257 = frame.member[0u].member_1.member_5[1u];
                                    let _e1264 = frame.member[0u].member_1.member_4;
                                    let _e1265 = f32(_e1264);
                                    let _e1266 = (2u * _e1264);
                                    let _e1267 = (_e1251 + _e1266);
                                    let _e1271 = (floor((_e888 * f32(_e1251))) + _e1265);
                                    let _e1274 = f32(bitcast<i32>((_e1267 - 1u)));
                                    let _e1285 = (floor((_e891 * f32(_e1257))) + _e1265);
                                    let _e1288 = f32(bitcast<i32>(((_e1257 + _e1266) - 1u)));
                                    let _e1298 = (((bitcast<u32>((floor(select(0f, select(_e1288, _e1285, (_e1285 < _e1288)), (_e1285 > 0f))) + 8388608f)) - 1258291200u) * _e1267) + (bitcast<u32>((floor(select(0f, select(_e1274, _e1271, (_e1271 < _e1274)), (_e1271 > 0f))) + 8388608f)) - 1258291200u));
                                    let _e1303 = frame.member[0u].member_1.member_2;
                                    if (_e1303 == 0u) {
                                        if (_e1298 < _e498) {
                                        } else {
                                            phi_2118_ = true;
                                            break;
                                        }
                                        let _e1308 = atomicMax((&ray_max.member[_e1298]), 1u);
                                    } else {
                                        if _e825 {
                                            if (_e1210 != _e1210) {
                                                phi_2098_ = true;
                                            } else {
                                                phi_2098_ = (_e842 <= _e1210);
                                            }
                                            let _e1312 = phi_2098_;
                                            phi_1946_ = select(_e1210, _e842, _e1312);
                                        } else {
                                            let _e1319 = frame.member[0u].member_1.member.member_3;
                                            let _e1322 = (((1f + _e1319) * _e774.member_1.member_2) + _e842);
                                            if (_e1210 != _e1210) {
                                                phi_2113_ = true;
                                            } else {
                                                phi_2113_ = (_e1322 <= _e1210);
                                            }
                                            let _e1326 = phi_2113_;
                                            phi_1946_ = select(_e1210, _e1322, _e1326);
                                        }
                                        let _e1329 = phi_1946_;
                                        let _e1330 = (_e788 - _e1329);
                                        if (_e1330 > 0f) {
                                            phi_1953_ = bitcast<u32>(_e1330);
                                        } else {
                                            phi_1953_ = 0u;
                                        }
                                        let _e1334 = phi_1953_;
                                        if (_e1298 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2118_ = true;
                                            break;
                                        }
                                        let _e1338 = atomicMin((&ray_min.member[_e1298]), _e1334);
                                        let _e1339 = (_e788 - _e861);
                                        if (_e1339 > 0f) {
                                            phi_1967_ = bitcast<u32>(_e1339);
                                        } else {
                                            phi_1967_ = 0u;
                                        }
                                        let _e1343 = phi_1967_;
                                        if (_e1298 < _e498) {
                                        } else {
                                            phi_2118_ = true;
                                            break;
                                        }
                                        let _e1347 = atomicMax((&ray_max.member[_e1298]), _e1343);
                                    }
                                }
                                phi_1975_ = (_e792 | (1u << bitcast<u32>((_e790 & 31u))));
                            } else {
                                phi_1975_ = _e792;
                            }
                            let _e1349 = phi_1975_;
                            phi_973_ = (_e790 + 1u);
                            phi_976_ = _e1349;
                            phi_978_ = (_e794 + select(0f, select(_e1187.member_1, _e1193, _e949), _e864));
                        } else {
                            phi_973_ = u32();
                            phi_976_ = u32();
                            phi_978_ = f32();
                        }
                        let _e1352 = phi_973_;
                        let _e1354 = phi_976_;
                        let _e1356 = phi_978_;
                        continue;
                        continuing {
                            phi_972_ = _e1352;
                            phi_975_ = _e1354;
                            phi_977_ = _e1356;
                            phi_2118_ = false;
                            break if !(_e805);
                        }
                    }
                    let _e1359 = phi_2118_;
                    if _e1359 {
                        break;
                    }
                    let _e1364 = frame.member[0u].member_1.member_10;
                    let _e1365 = (_e1364 == 1u);
                    let _e1368 = local_7;
                    let _e1372 = local_8;
                    let _e1373 = ((select(2f, 1f, _e1365) / f32(_e1368)) * _e1372);
                    let _e1375 = local_9;
                    if (_e1375 == 0u) {
                        if _e1365 {
                            phi_2008_ = (1f - (2f * _e1373));
                        } else {
                            phi_2008_ = _e1373;
                        }
                        let _e1380 = phi_2008_;
                        let _e1390 = frame.member[0u].member_1.member.member_2;
                        let _e1393 = local_10;
                        phi_2037_ = type_42(pow(select(0f, select(1f, _e1380, (_e1380 < 1f)), (_e1380 > 0f)), _e1390), _e1393);
                    } else {
                        let _e1403 = local_11;
                        phi_2037_ = type_42((round((select(0f, select(1f, _e1373, (_e1373 < 1f)), (_e1373 > 0f)) * 255f)) * 0.003921569f), _e1403);
                    }
                    let _e1406 = phi_2037_;
                    phi_2042_ = _e1406;
                } else {
                    phi_2042_ = type_42(1f, 0u);
                }
                let _e1408 = phi_2042_;
                ao.member[_e576] = _e1408.member;
                if (_e576 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e576] = _e1408.member_1;
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
