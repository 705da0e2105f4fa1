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
    var phi_726_: bool;
    var phi_728_: bool;
    var phi_729_: bool;
    var phi_730_: bool;
    var phi_731_: bool;
    var phi_2145_: bool;
    var phi_2160_: bool;
    var phi_2121_: vec2<f32>;
    var phi_2175_: bool;
    var phi_992_: type_31;
    var phi_1014_: u32;
    var phi_1017_: u32;
    var phi_1019_: f32;
    var phi_1084_: f32;
    var phi_1109_: f32;
    var phi_1122_: f32;
    var phi_1250_: u32;
    var phi_1281_: u32;
    var phi_2190_: bool;
    var phi_2205_: bool;
    var phi_1485_: f32;
    var phi_2220_: bool;
    var phi_1508_: f32;
    var phi_2235_: bool;
    var phi_2250_: bool;
    var phi_1697_: f32;
    var phi_2265_: bool;
    var phi_2280_: bool;
    var phi_2295_: bool;
    var phi_1711_: f32;
    var phi_1717_: type_41;
    var phi_1733_: f32;
    var phi_1752_: bool;
    var phi_1753_: bool;
    var phi_1765_: f32;
    var phi_2310_: bool;
    var phi_1784_: f32;
    var phi_2325_: bool;
    var phi_2340_: bool;
    var phi_1936_: f32;
    var phi_1943_: u32;
    var phi_1957_: u32;
    var phi_1965_: u32;
    var phi_1015_: u32;
    var phi_1018_: u32;
    var phi_1020_: f32;
    var phi_2354_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_1998_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2027_: type_42;
    var phi_2032_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e486 = id_1;
            let _e500 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e510 = frame.member[0u].member_1.member.member.member_4;
            let _e511 = (_e486.x + _e510);
            let _e512 = (_e486.y + _e510);
            let _e520 = frame.member[0u].member_1.member.member.member[0u];
            let _e525 = select(select(u32(_e520), 0u, (_e520 < 0f)), 4294967295u, (_e520 > 4294967000f));
            let _e533 = frame.member[0u].member_1.member.member.member[1u];
            let _e538 = select(select(u32(_e533), 0u, (_e533 < 0f)), 4294967295u, (_e533 > 4294967000f));
            if (_e511 >= _e510) {
                if (_e512 >= _e510) {
                    let _e542 = ((_e511 + _e510) < _e525);
                    if _e542 {
                        phi_726_ = ((_e512 + _e510) < _e538);
                    } else {
                        phi_726_ = bool();
                    }
                    let _e546 = phi_726_;
                    phi_728_ = _e546;
                    phi_729_ = select(true, false, _e542);
                } else {
                    phi_728_ = bool();
                    phi_729_ = true;
                }
                let _e549 = phi_728_;
                let _e551 = phi_729_;
                phi_730_ = _e549;
                phi_731_ = _e551;
            } else {
                phi_730_ = bool();
                phi_731_ = true;
            }
            let _e553 = phi_730_;
            let _e555 = phi_731_;
            if select(_e553, false, _e555) {
                let _e562 = frame.member[0u].member_1.member.member_1;
                let _e568 = frame.member[0u].member_1.member.member_4;
                let _e571 = ((f32(_e511) + 0.5f) / _e520);
                let _e574 = ((f32(_e512) + 0.5f) / _e533);
                let _e576 = ((_e512 * _e525) + _e511);
                let _e578 = depth.member[_e576];
                let _e586 = frame.member[0u].member_1.member.member.member_1[0u];
                let _e594 = frame.member[0u].member_1.member.member.member_1[1u];
                let _e604 = ((((_e562 * _e520) / (_e578 * (2f * _e586))) + ((_e562 * _e533) / (_e578 * (2f * _e594)))) * 0.5f);
                let _e605 = (_e604 > _e568);
                let _e609 = select(_e604, _e568, _e605);
                let _e616 = frame.member[0u].member_1.member.member.member_3;
                let _e628 = ((((_e571 * 2f) - 1f) * _e578) * _e586);
                let _e630 = ((((_e574 * -2f) + 1f) * _e578) * _e594);
                let _e631 = -(_e578);
                if (_e576 < arrayLength((&normals.member))) {
                } else {
                    break;
                }
                let _e635 = normals.member[_e576];
                let _e643 = (f32((bitcast<i32>(((_e635 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e643 != _e643) {
                    phi_2145_ = true;
                } else {
                    phi_2145_ = (-1f >= _e643);
                }
                let _e647 = phi_2145_;
                let _e648 = select(_e643, -1f, _e647);
                let _e658 = (f32((bitcast<i32>((((_e635 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e658 != _e658) {
                    phi_2160_ = true;
                } else {
                    phi_2160_ = (-1f >= _e658);
                }
                let _e662 = phi_2160_;
                let _e663 = select(_e658, -1f, _e662);
                let _e666 = (1f - abs(_e648));
                let _e667 = abs(_e663);
                let _e668 = (_e666 - _e667);
                if (_e668 < 0f) {
                    phi_2121_ = vec2<f32>(((1f - _e667) * select(1f, -1f, (_e648 < 0f))), (_e666 * select(1f, -1f, (_e663 < 0f))));
                } else {
                    phi_2121_ = vec2<f32>(_e648, _e663);
                }
                let _e679 = phi_2121_;
                let _e688 = (1f / sqrt((((_e679.x * _e679.x) + (_e679.y * _e679.y)) + (_e668 * _e668))));
                let _e689 = (_e679.x * _e688);
                let _e690 = (_e679.y * _e688);
                let _e691 = (_e668 * _e688);
                let _e697 = ((((_e628 * _e689) + (_e630 * _e690)) + (_e631 * _e691)) > 0f);
                let _e701 = select(_e689, -(_e689), _e697);
                let _e702 = select(_e690, -(_e690), _e697);
                let _e703 = select(_e691, -(_e691), _e697);
                local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e705 = (_e512 % 4u);
                if (_e705 < 4u) {
                } else {
                    break;
                }
                let _e707 = (_e511 % 4u);
                if (_e707 < 4u) {
                } else {
                    break;
                }
                let _e711 = local_6[_e705][_e707];
                let _e721 = sqrt((((_e628 * _e628) + (_e630 * _e630)) + (_e631 * _e631)));
                let _e722 = (-(_e628) / _e721);
                let _e723 = (-(_e630) / _e721);
                let _e724 = (_e578 / _e721);
                let _e727 = -((_e711[1] * _e724));
                let _e728 = (_e724 * _e711[0]);
                let _e731 = ((_e722 * _e711[1]) - (_e711[0] * _e723));
                let _e738 = (1f / sqrt((((_e727 * _e727) + (_e728 * _e728)) + (_e731 * _e731))));
                let _e739 = (_e727 * _e738);
                let _e740 = (_e728 * _e738);
                let _e741 = (_e731 * _e738);
                let _e745 = ((_e740 * _e724) - (_e723 * _e741));
                let _e748 = ((_e741 * _e722) - (_e724 * _e739));
                let _e751 = ((_e739 * _e723) - (_e722 * _e740));
                let _e767 = (((_e701 * _e722) + (_e702 * _e723)) + (_e703 * _e724));
                let _e771 = abs(_e767);
                if (_e771 != _e771) {
                    phi_2175_ = true;
                } else {
                    phi_2175_ = (0.0001f >= _e771);
                }
                let _e775 = phi_2175_;
                if select(false, !((_e609 < 0.5f)), select(false, (_e578 < _e616), (_e578 > 0f))) {
                    phi_992_ = type_31(1u, type_30(vec2<u32>(_e511, _e512), vec2<f32>(_e571, _e574), select(_e562, ((_e562 * _e568) / _e604), _e605), _e609, vec3<f32>(_e628, _e630, _e631), vec3<f32>(_e701, _e702, _e703), vec3<f32>(_e722, _e723, _e724), vec3<f32>(_e745, _e748, _e751), vec3<f32>(_e739, _e740, _e741), vec3<f32>((((_e701 * _e745) + (_e702 * _e748)) + (_e703 * _e751)), (((_e701 * _e739) + (_e702 * _e740)) + (_e703 * _e741)), _e767), (1f / (select(1f, -1f, (_e767 < 0f)) * select(_e771, 0.0001f, _e775)))));
                } else {
                    phi_992_ = type_31(0u, type_31().member_1);
                }
                let _e787 = phi_992_;
                if (bitcast<i32>(_e787.member) != 0i) {
                    let _e801 = sqrt((((_e787.member_1.member_4.x * _e787.member_1.member_4.x) + (_e787.member_1.member_4.y * _e787.member_1.member_4.y)) + (_e787.member_1.member_4.z * _e787.member_1.member_4.z)));
                    phi_1014_ = 0u;
                    phi_1017_ = 0u;
                    phi_1019_ = 0f;
                    loop {
                        let _e803 = phi_1014_;
                        let _e805 = phi_1017_;
                        let _e807 = phi_1019_;
                        let _e812 = frame.member[0u].member_1.member_11;
                        local_8 = _e807;
                        local_9 = _e805;
                        local_10 = _e805;
                        local_11 = _e805;
                        let _e817 = (8u << bitcast<u32>((select(_e812, 2u, (2u < _e812)) & 31u)));
                        let _e818 = (_e803 < _e817);
                        local_7 = _e817;
                        if _e818 {
                            let _e823 = frame.member[0u].member_1.member_1;
                            let _e824 = (_e823 == 1u);
                            let _e830 = frame.member[0u].member_1.member_10;
                            let _e832 = ((_e817 + _e803) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e833 = (_e832 < 56u);
                            if _e833 {
                            } else {
                                phi_2354_ = true;
                                break;
                            }
                            let _e835 = local[_e832];
                            let _e838 = (_e830 == 1u);
                            if _e838 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e833 {
                                } else {
                                    phi_2354_ = true;
                                    break;
                                }
                                let _e840 = local_1[_e832];
                                phi_1084_ = _e840;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e833 {
                                } else {
                                    phi_2354_ = true;
                                    break;
                                }
                                let _e842 = local_2[_e832];
                                phi_1084_ = _e842;
                            }
                            let _e844 = phi_1084_;
                            let _e846 = (_e787.member_1.member_2 * _e844);
                            let _e847 = (_e846 * _e835[0]);
                            let _e848 = (_e846 * _e835[1]);
                            if _e838 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e833 {
                                } else {
                                    phi_2354_ = true;
                                    break;
                                }
                                let _e850 = local_3[_e832];
                                phi_1109_ = _e850;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e833 {
                                } else {
                                    phi_2354_ = true;
                                    break;
                                }
                                let _e852 = local_4[_e832];
                                phi_1109_ = _e852;
                            }
                            let _e854 = phi_1109_;
                            let _e855 = (_e787.member_1.member_2 * _e854);
                            if _e838 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e833 {
                                } else {
                                    phi_2354_ = true;
                                    break;
                                }
                                let _e857 = local_5[_e832];
                                phi_1122_ = _e857;
                            } else {
                                phi_1122_ = (_e855 * 2f);
                            }
                            let _e860 = phi_1122_;
                            let _e869 = (-(((_e847 * _e787.member_1.member_9.x) + (_e848 * _e787.member_1.member_9.y))) * _e787.member_1.member_10);
                            let _e870 = -(_e855);
                            let _e874 = select(_e870, select(_e855, _e869, (_e869 < _e855)), (_e869 > _e870));
                            let _e875 = (_e855 - _e874);
                            let _e877 = (_e875 > (_e855 * 0.2f));
                            let _e898 = (-0.5f / ((_e787.member_1.member_4.z + (_e787.member_1.member_7.z * _e847)) + (_e787.member_1.member_8.z * _e848)));
                            let _e901 = (((((_e787.member_1.member_4.x + (_e787.member_1.member_7.x * _e847)) + (_e787.member_1.member_8.x * _e848)) * _e898) / _e586) + 0.5f);
                            let _e904 = (0.5f - ((((_e787.member_1.member_4.y + (_e787.member_1.member_7.y * _e847)) + (_e787.member_1.member_8.y * _e848)) * _e898) / _e594));
                            let _e916 = (select(0f, select(1f, _e901, (_e901 < 1f)), (_e901 > 0f)) * _e520);
                            if (_e916 > 0f) {
                                let _e922 = select(select(u32(_e916), 0u, (_e916 < 0f)), 4294967295u, (_e916 > 4294967000f));
                                let _e923 = (_e525 - 1u);
                                phi_1250_ = select(_e922, _e923, (_e923 < _e922));
                            } else {
                                phi_1250_ = 0u;
                            }
                            let _e927 = phi_1250_;
                            let _e932 = (select(0f, select(1f, _e904, (_e904 < 1f)), (_e904 > 0f)) * _e533);
                            if (_e932 > 0f) {
                                let _e938 = select(select(u32(_e932), 0u, (_e932 < 0f)), 4294967295u, (_e932 > 4294967000f));
                                let _e939 = (_e538 - 1u);
                                phi_1281_ = select(_e938, _e939, (_e939 < _e938));
                            } else {
                                phi_1281_ = 0u;
                            }
                            let _e943 = phi_1281_;
                            let _e950 = ((_e787.member_1.member_1.x - _e901) * _e520);
                            let _e951 = ((_e787.member_1.member_1.y - _e904) * _e533);
                            let _e955 = sqrt(((_e950 * _e950) + (_e951 * _e951)));
                            let _e962 = select(false, (_e943 == _e787.member_1.member.y), (_e927 == _e787.member_1.member.x));
                            let _e964 = ((_e943 * _e525) + _e927);
                            let _e966 = depth.member[_e964];
                            let _e978 = select(_e616, _e966, select(false, (_e966 < _e616), (_e966 > 0f)));
                            let _e980 = ((((f32(_e927) + 0.5f) * (1f / _e520)) * 2f) - 1f);
                            let _e982 = ((((f32(_e943) + 0.5f) * (1f / _e533)) * -2f) + 1f);
                            let _e988 = (((_e980 * _e978) * _e586) - _e787.member_1.member_4.x);
                            let _e989 = (((_e982 * _e978) * _e594) - _e787.member_1.member_4.y);
                            let _e990 = (-(_e978) - _e787.member_1.member_4.z);
                            let _e999 = (((_e988 * _e787.member_1.member_6.x) + (_e989 * _e787.member_1.member_6.y)) + (_e990 * _e787.member_1.member_6.z));
                            if _e838 {
                                let _e1004 = (((_e988 * _e988) + (_e989 * _e989)) + (_e990 * _e990));
                                let _e1016 = (((((_e787.member_1.member_5.x * _e988) + (_e787.member_1.member_5.y * _e989)) + (_e787.member_1.member_5.z * _e990)) / sqrt(_e1004)) - 0.1f);
                                let _e1023 = (1f - (_e1004 / (_e562 * _e562)));
                                let _e1030 = ((select(0f, select(1f, _e1016, (_e1016 < 1f)), (_e1016 > 0f)) * select(0f, select(1f, _e1023, (_e1023 < 1f)), (_e1023 > 0f))) / _e860);
                                phi_1485_ = select(0f, select(0f, select(1f, _e1030, (_e1030 < 1f)), (_e1030 > 0f)), (_e1004 > 0f));
                            } else {
                                let _e1041 = frame.member[0u].member_1.member.member_3;
                                if (_e874 != _e874) {
                                    phi_2190_ = true;
                                } else {
                                    phi_2190_ = (_e999 >= _e874);
                                }
                                let _e1046 = phi_2190_;
                                let _e1048 = (_e855 - select(_e874, _e999, _e1046));
                                if (_e1048 != _e1048) {
                                    phi_2205_ = true;
                                } else {
                                    phi_2205_ = (0f >= _e1048);
                                }
                                let _e1052 = phi_2205_;
                                let _e1057 = ((_e999 - (_e787.member_1.member_2 * (1f + _e1041))) * (1f / _e855));
                                phi_1485_ = ((select(_e1048, 0f, _e1052) + (select(0f, select(1f, _e1057, (_e1057 < 1f)), (_e1057 > 0f)) * _e875)) * (0.5f / _e855));
                            }
                            let _e1067 = phi_1485_;
                            let _e1072 = frame.member[0u].member_1.member_9;
                            if (_e1072 == 0u) {
                                phi_1717_ = type_41(_e999, _e1067);
                            } else {
                                if _e838 {
                                    let _e1075 = (_e787.member_1.member_2 * 0.1f);
                                    if (_e855 != _e855) {
                                        phi_2220_ = true;
                                    } else {
                                        phi_2220_ = (_e1075 >= _e855);
                                    }
                                    let _e1079 = phi_2220_;
                                    phi_1508_ = select(_e855, _e1075, _e1079);
                                } else {
                                    let _e1086 = frame.member[0u].member_1.member.member_3;
                                    phi_1508_ = (_e787.member_1.member_2 * (1f + _e1086));
                                }
                                let _e1090 = phi_1508_;
                                let _e1096 = frame.member[0u].member_1.member_3;
                                let _e1098 = select(false, (_e955 > _e1096), (_e999 > _e1090));
                                let _e1101 = depth2_.member[_e964];
                                let _e1105 = select(_e616, _e1101, select(false, (_e1101 < _e616), (_e1101 > 0f)));
                                let _e1111 = (((_e980 * _e1105) * _e586) - _e787.member_1.member_4.x);
                                let _e1112 = (((_e982 * _e1105) * _e594) - _e787.member_1.member_4.y);
                                let _e1113 = (-(_e1105) - _e787.member_1.member_4.z);
                                let _e1118 = (((_e1111 * _e787.member_1.member_6.x) + (_e1112 * _e787.member_1.member_6.y)) + (_e1113 * _e787.member_1.member_6.z));
                                if _e838 {
                                    let _e1123 = (((_e1111 * _e1111) + (_e1112 * _e1112)) + (_e1113 * _e1113));
                                    let _e1135 = (((((_e787.member_1.member_5.x * _e1111) + (_e787.member_1.member_5.y * _e1112)) + (_e787.member_1.member_5.z * _e1113)) / sqrt(_e1123)) - 0.1f);
                                    let _e1142 = (1f - (_e1123 / (_e562 * _e562)));
                                    let _e1149 = ((select(0f, select(1f, _e1135, (_e1135 < 1f)), (_e1135 > 0f)) * select(0f, select(1f, _e1142, (_e1142 < 1f)), (_e1142 > 0f))) / _e860);
                                    phi_1697_ = select(0f, select(0f, select(1f, _e1149, (_e1149 < 1f)), (_e1149 > 0f)), (_e1123 > 0f));
                                } else {
                                    let _e1160 = frame.member[0u].member_1.member.member_3;
                                    if (_e874 != _e874) {
                                        phi_2235_ = true;
                                    } else {
                                        phi_2235_ = (_e1118 >= _e874);
                                    }
                                    let _e1165 = phi_2235_;
                                    let _e1167 = (_e855 - select(_e874, _e1118, _e1165));
                                    if (_e1167 != _e1167) {
                                        phi_2250_ = true;
                                    } else {
                                        phi_2250_ = (0f >= _e1167);
                                    }
                                    let _e1171 = phi_2250_;
                                    let _e1176 = ((_e1118 - (_e787.member_1.member_2 * (1f + _e1160))) * (1f / _e855));
                                    phi_1697_ = ((select(_e1167, 0f, _e1171) + (select(0f, select(1f, _e1176, (_e1176 < 1f)), (_e1176 > 0f)) * _e875)) * (0.5f / _e855));
                                }
                                let _e1186 = phi_1697_;
                                if (_e999 != _e999) {
                                    phi_2265_ = true;
                                } else {
                                    phi_2265_ = (_e1118 <= _e999);
                                }
                                let _e1190 = phi_2265_;
                                if _e838 {
                                    if (_e1067 != _e1067) {
                                        phi_2280_ = true;
                                    } else {
                                        phi_2280_ = (_e1186 >= _e1067);
                                    }
                                    let _e1196 = phi_2280_;
                                    phi_1711_ = select(_e1067, _e1186, _e1196);
                                } else {
                                    if (_e1067 != _e1067) {
                                        phi_2295_ = true;
                                    } else {
                                        phi_2295_ = (_e1186 <= _e1067);
                                    }
                                    let _e1201 = phi_2295_;
                                    phi_1711_ = select(_e1067, _e1186, _e1201);
                                }
                                let _e1204 = phi_1711_;
                                phi_1717_ = type_41(select(_e999, select(_e999, _e1118, _e1190), _e1098), select(_e1067, _e1204, _e1098));
                            }
                            let _e1208 = phi_1717_;
                            if _e838 {
                                phi_1733_ = 0f;
                            } else {
                                phi_1733_ = (_e875 / (_e855 * 2f));
                            }
                            let _e1214 = phi_1733_;
                            if (_e823 == 2u) {
                                phi_1753_ = true;
                            } else {
                                if _e824 {
                                    let _e1222 = frame.member[0u].member_1.member_4;
                                    phi_1752_ = (_e1222 > 0u);
                                } else {
                                    phi_1752_ = false;
                                }
                                let _e1225 = phi_1752_;
                                phi_1753_ = _e1225;
                            }
                            let _e1227 = phi_1753_;
                            let _e1228 = select(false, _e1227, !(select(false, select(false, (_e904 <= 1f), (_e904 >= 0f)), select(false, (_e901 <= 1f), (_e901 >= 0f)))));
                            if _e824 {
                                phi_1765_ = select(_e1208.member, 0x1.fffffep+127f, _e1228);
                            } else {
                                phi_1765_ = _e1208.member;
                            }
                            let _e1231 = phi_1765_;
                            if _e838 {
                                let _e1233 = (_e787.member_1.member_2 * 0.1f);
                                if (_e855 != _e855) {
                                    phi_2310_ = true;
                                } else {
                                    phi_2310_ = (_e1233 >= _e855);
                                }
                                let _e1237 = phi_2310_;
                                phi_1784_ = select(_e855, _e1233, _e1237);
                            } else {
                                let _e1244 = frame.member[0u].member_1.member.member_3;
                                phi_1784_ = (_e787.member_1.member_2 * (1f + _e1244));
                            }
                            let _e1248 = phi_1784_;
                            let _e1254 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e955 > _e1254), (_e1231 > _e1248)), true, _e1228), (_e823 != 0u)), select(false, !(_e962), _e877)) {
                                if (_e823 != 1u) {
                                } else {
                                    let _e1273 = frame.member[0u].member_1.member_5[0u];
                                    let _e1279 = frame.member[0u].member_1.member_5[1u];
                                    let _e1286 = frame.member[0u].member_1.member_4;
                                    let _e1287 = f32(_e1286);
                                    let _e1288 = (2u * _e1286);
                                    let _e1289 = (_e1273 + _e1288);
                                    let _e1295 = (floor((_e901 * f32(_e1273))) + _e1287);
                                    let _e1296 = f32((_e1289 - 1u));
                                    let _e1300 = select(0f, select(_e1296, _e1295, (_e1295 < _e1296)), (_e1295 > 0f));
                                    let _e1303 = (floor((_e904 * f32(_e1279))) + _e1287);
                                    let _e1304 = f32(((_e1279 + _e1288) - 1u));
                                    let _e1308 = select(0f, select(_e1304, _e1303, (_e1303 < _e1304)), (_e1303 > 0f));
                                    let _e1320 = ((select(select(u32(_e1308), 0u, (_e1308 < 0f)), 4294967295u, (_e1308 > 4294967000f)) * _e1289) + select(select(u32(_e1300), 0u, (_e1300 < 0f)), 4294967295u, (_e1300 > 4294967000f)));
                                    let _e1325 = frame.member[0u].member_1.member_2;
                                    if (_e1325 == 0u) {
                                        if (_e1320 < _e500) {
                                        } else {
                                            phi_2354_ = true;
                                            break;
                                        }
                                        let _e1330 = atomicMax((&ray_max.member[_e1320]), 1u);
                                    } else {
                                        if _e838 {
                                            if (_e1231 != _e1231) {
                                                phi_2325_ = true;
                                            } else {
                                                phi_2325_ = (_e855 <= _e1231);
                                            }
                                            let _e1334 = phi_2325_;
                                            phi_1936_ = select(_e1231, _e855, _e1334);
                                        } else {
                                            let _e1341 = frame.member[0u].member_1.member.member_3;
                                            let _e1344 = (((1f + _e1341) * _e787.member_1.member_2) + _e855);
                                            if (_e1231 != _e1231) {
                                                phi_2340_ = true;
                                            } else {
                                                phi_2340_ = (_e1344 <= _e1231);
                                            }
                                            let _e1348 = phi_2340_;
                                            phi_1936_ = select(_e1231, _e1344, _e1348);
                                        }
                                        let _e1351 = phi_1936_;
                                        let _e1352 = (_e801 - _e1351);
                                        if (_e1352 > 0f) {
                                            phi_1943_ = bitcast<u32>(_e1352);
                                        } else {
                                            phi_1943_ = 0u;
                                        }
                                        let _e1356 = phi_1943_;
                                        if (_e1320 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2354_ = true;
                                            break;
                                        }
                                        let _e1360 = atomicMin((&ray_min.member[_e1320]), _e1356);
                                        let _e1361 = (_e801 - _e874);
                                        if (_e1361 > 0f) {
                                            phi_1957_ = bitcast<u32>(_e1361);
                                        } else {
                                            phi_1957_ = 0u;
                                        }
                                        let _e1365 = phi_1957_;
                                        if (_e1320 < _e500) {
                                        } else {
                                            phi_2354_ = true;
                                            break;
                                        }
                                        let _e1369 = atomicMax((&ray_max.member[_e1320]), _e1365);
                                    }
                                }
                                phi_1965_ = (_e805 | (1u << bitcast<u32>((_e803 & 31u))));
                            } else {
                                phi_1965_ = _e805;
                            }
                            let _e1371 = phi_1965_;
                            phi_1015_ = (_e803 + 1u);
                            phi_1018_ = _e1371;
                            phi_1020_ = (_e807 + select(0f, select(_e1208.member_1, _e1214, _e962), _e877));
                        } else {
                            phi_1015_ = u32();
                            phi_1018_ = u32();
                            phi_1020_ = f32();
                        }
                        let _e1374 = phi_1015_;
                        let _e1376 = phi_1018_;
                        let _e1378 = phi_1020_;
                        continue;
                        continuing {
                            phi_1014_ = _e1374;
                            phi_1017_ = _e1376;
                            phi_1019_ = _e1378;
                            phi_2354_ = false;
                            break if !(_e818);
                        }
                    }
                    let _e1381 = phi_2354_;
                    if _e1381 {
                        break;
                    }
                    let _e1386 = frame.member[0u].member_1.member_10;
                    let _e1387 = (_e1386 == 1u);
                    let _e1390 = local_7;
                    let _e1394 = local_8;
                    let _e1395 = ((select(2f, 1f, _e1387) / f32(_e1390)) * _e1394);
                    let _e1397 = local_9;
                    if (_e1397 == 0u) {
                        if _e1387 {
                            phi_1998_ = (1f - (2f * _e1395));
                        } else {
                            phi_1998_ = _e1395;
                        }
                        let _e1402 = phi_1998_;
                        let _e1412 = frame.member[0u].member_1.member.member_2;
                        let _e1415 = local_10;
                        phi_2027_ = type_42(pow(select(0f, select(1f, _e1402, (_e1402 < 1f)), (_e1402 > 0f)), _e1412), _e1415);
                    } else {
                        let _e1425 = local_11;
                        phi_2027_ = type_42((round((select(0f, select(1f, _e1395, (_e1395 < 1f)), (_e1395 > 0f)) * 255f)) * 0.003921569f), _e1425);
                    }
                    let _e1428 = phi_2027_;
                    phi_2032_ = _e1428;
                } else {
                    phi_2032_ = type_42(1f, 0u);
                }
                let _e1430 = phi_2032_;
                if (_e576 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e576] = _e1430.member;
                if (_e576 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e576] = _e1430.member_1;
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
