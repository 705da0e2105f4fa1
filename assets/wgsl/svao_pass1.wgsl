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
    var phi_709_: bool;
    var phi_711_: bool;
    var phi_712_: bool;
    var phi_713_: bool;
    var phi_714_: bool;
    var phi_2183_: bool;
    var phi_2198_: bool;
    var phi_2159_: vec2<f32>;
    var phi_975_: type_31;
    var phi_997_: u32;
    var phi_1000_: u32;
    var phi_1002_: f32;
    var phi_1067_: f32;
    var phi_1092_: f32;
    var phi_1105_: f32;
    var phi_1470_: f32;
    var phi_1499_: f32;
    var phi_1700_: f32;
    var phi_1732_: f32;
    var phi_1738_: type_41;
    var phi_1754_: f32;
    var phi_1773_: bool;
    var phi_1774_: bool;
    var phi_1786_: f32;
    var phi_1811_: f32;
    var phi_2213_: bool;
    var phi_2228_: bool;
    var phi_1963_: f32;
    var phi_1970_: u32;
    var phi_1984_: u32;
    var phi_1992_: u32;
    var phi_998_: u32;
    var phi_1001_: u32;
    var phi_1003_: f32;
    var phi_2242_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_2025_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2054_: type_42;
    var phi_2059_: type_42;

    switch bitcast<i32>(0u) {
        default: {
            let _e486 = id_1;
            let _e496 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e506 = frame.member[0u].member_1.member.member.member_4;
            let _e507 = (_e486.x + _e506);
            let _e508 = (_e486.y + _e506);
            let _e516 = frame.member[0u].member_1.member.member.member[0u];
            let _e521 = select(select(u32(_e516), 0u, (_e516 < 0f)), 4294967295u, (_e516 > 4294967000f));
            let _e529 = frame.member[0u].member_1.member.member.member[1u];
            let _e534 = select(select(u32(_e529), 0u, (_e529 < 0f)), 4294967295u, (_e529 > 4294967000f));
            if (_e507 >= _e506) {
                if (_e508 >= _e506) {
                    let _e538 = ((_e507 + _e506) < _e521);
                    if _e538 {
                        phi_709_ = ((_e508 + _e506) < _e534);
                    } else {
                        phi_709_ = bool();
                    }
                    let _e542 = phi_709_;
                    phi_711_ = _e542;
                    phi_712_ = select(true, false, _e538);
                } else {
                    phi_711_ = bool();
                    phi_712_ = true;
                }
                let _e545 = phi_711_;
                let _e547 = phi_712_;
                phi_713_ = _e545;
                phi_714_ = _e547;
            } else {
                phi_713_ = bool();
                phi_714_ = true;
            }
            let _e549 = phi_713_;
            let _e551 = phi_714_;
            if select(_e549, false, _e551) {
                let _e558 = frame.member[0u].member_1.member.member_1;
                let _e564 = frame.member[0u].member_1.member.member_4;
                let _e567 = ((f32(_e507) + 0.5f) / _e516);
                let _e570 = ((f32(_e508) + 0.5f) / _e529);
                let _e572 = ((_e508 * _e521) + _e507);
                let _e574 = depth.member[_e572];
                let _e582 = frame.member[0u].member_1.member.member.member_1[0u];
                let _e590 = frame.member[0u].member_1.member.member.member_1[1u];
                let _e600 = ((((_e558 * _e516) / (_e574 * (2f * _e582))) + ((_e558 * _e529) / (_e574 * (2f * _e590)))) * 0.5f);
                let _e601 = (_e600 > _e564);
                let _e605 = select(_e600, _e564, _e601);
                let _e612 = frame.member[0u].member_1.member.member.member_3;
                let _e624 = ((((_e567 * 2f) - 1f) * _e574) * _e582);
                let _e626 = ((((_e570 * -2f) + 1f) * _e574) * _e590);
                let _e627 = -(_e574);
                let _e630 = normals.member[_e572];
                let _e638 = (f32((bitcast<i32>(((_e630 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e638 != _e638) {
                    phi_2183_ = true;
                } else {
                    phi_2183_ = (-1f >= _e638);
                }
                let _e642 = phi_2183_;
                let _e643 = select(_e638, -1f, _e642);
                let _e653 = (f32((bitcast<i32>((((_e630 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e653 != _e653) {
                    phi_2198_ = true;
                } else {
                    phi_2198_ = (-1f >= _e653);
                }
                let _e657 = phi_2198_;
                let _e658 = select(_e653, -1f, _e657);
                let _e661 = (1f - abs(_e643));
                let _e662 = abs(_e658);
                let _e663 = (_e661 - _e662);
                if (_e663 < 0f) {
                    phi_2159_ = vec2<f32>(((1f - _e662) * select(1f, -1f, (_e643 < 0f))), (_e661 * select(1f, -1f, (_e658 < 0f))));
                } else {
                    phi_2159_ = vec2<f32>(_e643, _e658);
                }
                let _e674 = phi_2159_;
                let _e683 = (1f / sqrt((((_e674.x * _e674.x) + (_e674.y * _e674.y)) + (_e663 * _e663))));
                let _e684 = (_e674.x * _e683);
                let _e685 = (_e674.y * _e683);
                let _e686 = (_e663 * _e683);
                let _e692 = ((((_e624 * _e684) + (_e626 * _e685)) + (_e627 * _e686)) > 0f);
                let _e696 = select(_e684, -(_e684), _e692);
                let _e697 = select(_e685, -(_e685), _e692);
                let _e698 = select(_e686, -(_e686), _e692);
                local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e700 = (_e508 % 4u);
                if (_e700 < 4u) {
                } else {
                    break;
                }
                let _e702 = (_e507 % 4u);
                if (_e702 < 4u) {
                } else {
                    break;
                }
                let _e706 = local_6[_e700][_e702];
                let _e716 = sqrt((((_e624 * _e624) + (_e626 * _e626)) + (_e627 * _e627)));
                let _e717 = (-(_e624) / _e716);
                let _e718 = (-(_e626) / _e716);
                let _e719 = (_e574 / _e716);
                let _e722 = -((_e706[1] * _e719));
                let _e723 = (_e719 * _e706[0]);
                let _e726 = ((_e717 * _e706[1]) - (_e706[0] * _e718));
                let _e733 = (1f / sqrt((((_e722 * _e722) + (_e723 * _e723)) + (_e726 * _e726))));
                let _e734 = (_e722 * _e733);
                let _e735 = (_e723 * _e733);
                let _e736 = (_e726 * _e733);
                let _e740 = ((_e735 * _e719) - (_e718 * _e736));
                let _e743 = ((_e736 * _e717) - (_e719 * _e734));
                let _e746 = ((_e734 * _e718) - (_e717 * _e735));
                let _e762 = (((_e696 * _e717) + (_e697 * _e718)) + (_e698 * _e719));
                let _e766 = abs(_e762);
                if select(false, !((_e605 < 0.5f)), select(false, (_e574 < _e612), (_e574 > 0f))) {
                    phi_975_ = type_31(1u, type_30(vec2<u32>(_e507, _e508), vec2<f32>(_e567, _e570), select(_e558, ((_e558 * _e564) / _e600), _e601), _e605, vec3<f32>(_e624, _e626, _e627), vec3<f32>(_e696, _e697, _e698), vec3<f32>(_e717, _e718, _e719), vec3<f32>(_e740, _e743, _e746), vec3<f32>(_e734, _e735, _e736), vec3<f32>((((_e696 * _e740) + (_e697 * _e743)) + (_e698 * _e746)), (((_e696 * _e734) + (_e697 * _e735)) + (_e698 * _e736)), _e762), (1f / (select(1f, -1f, (_e762 < 0f)) * select(0.0001f, _e766, ((_e766 > 0.0001f) || false))))));
                } else {
                    phi_975_ = type_31(0u, type_31().member_1);
                }
                let _e780 = phi_975_;
                if (bitcast<i32>(_e780.member) != 0i) {
                    let _e794 = sqrt((((_e780.member_1.member_4.x * _e780.member_1.member_4.x) + (_e780.member_1.member_4.y * _e780.member_1.member_4.y)) + (_e780.member_1.member_4.z * _e780.member_1.member_4.z)));
                    phi_997_ = 0u;
                    phi_1000_ = 0u;
                    phi_1002_ = 0f;
                    loop {
                        let _e796 = phi_997_;
                        let _e798 = phi_1000_;
                        let _e800 = phi_1002_;
                        let _e805 = frame.member[0u].member_1.member_11;
                        local_8 = _e800;
                        local_9 = _e798;
                        local_10 = _e798;
                        local_11 = _e798;
                        let _e810 = (8u << bitcast<u32>((select(_e805, 2u, (2u < _e805)) & 31u)));
                        let _e811 = (_e796 < _e810);
                        local_7 = _e810;
                        if _e811 {
                            let _e816 = frame.member[0u].member_1.member_1;
                            let _e817 = (_e816 == 1u);
                            let _e823 = frame.member[0u].member_1.member_10;
                            let _e825 = ((_e810 + _e796) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e826 = (_e825 < 56u);
                            if _e826 {
                            } else {
                                phi_2242_ = true;
                                break;
                            }
                            let _e828 = local[_e825];
                            let _e831 = (_e823 == 1u);
                            if _e831 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e826 {
                                } else {
                                    phi_2242_ = true;
                                    break;
                                }
                                let _e833 = local_1[_e825];
                                phi_1067_ = _e833;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e826 {
                                } else {
                                    phi_2242_ = true;
                                    break;
                                }
                                let _e835 = local_2[_e825];
                                phi_1067_ = _e835;
                            }
                            let _e837 = phi_1067_;
                            let _e839 = (_e780.member_1.member_2 * _e837);
                            let _e840 = (_e839 * _e828[0]);
                            let _e841 = (_e839 * _e828[1]);
                            if _e831 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e826 {
                                } else {
                                    phi_2242_ = true;
                                    break;
                                }
                                let _e843 = local_3[_e825];
                                phi_1092_ = _e843;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e826 {
                                } else {
                                    phi_2242_ = true;
                                    break;
                                }
                                let _e845 = local_4[_e825];
                                phi_1092_ = _e845;
                            }
                            let _e847 = phi_1092_;
                            let _e848 = (_e780.member_1.member_2 * _e847);
                            if _e831 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e826 {
                                } else {
                                    phi_2242_ = true;
                                    break;
                                }
                                let _e850 = local_5[_e825];
                                phi_1105_ = _e850;
                            } else {
                                phi_1105_ = (_e848 * 2f);
                            }
                            let _e853 = phi_1105_;
                            let _e862 = (-(((_e840 * _e780.member_1.member_9.x) + (_e841 * _e780.member_1.member_9.y))) * _e780.member_1.member_10);
                            let _e863 = -(_e848);
                            let _e867 = select(_e863, select(_e848, _e862, (_e862 < _e848)), (_e862 > _e863));
                            let _e868 = (_e848 - _e867);
                            let _e870 = (_e868 > (_e848 * 0.2f));
                            let _e891 = (-0.5f / ((_e780.member_1.member_4.z + (_e780.member_1.member_7.z * _e840)) + (_e780.member_1.member_8.z * _e841)));
                            let _e894 = (((((_e780.member_1.member_4.x + (_e780.member_1.member_7.x * _e840)) + (_e780.member_1.member_8.x * _e841)) * _e891) / _e582) + 0.5f);
                            let _e897 = (0.5f - ((((_e780.member_1.member_4.y + (_e780.member_1.member_7.y * _e840)) + (_e780.member_1.member_8.y * _e841)) * _e891) / _e590));
                            let _e909 = (select(0f, select(1f, _e894, (_e894 < 1f)), (_e894 > 0f)) * _e516);
                            let _e911 = f32((_e521 - 1u));
                            let _e913 = select(0f, _e909, (_e909 > 0f));
                            let _e916 = u32(select(_e911, _e913, (_e913 < _e911)));
                            let _e921 = (select(0f, select(1f, _e897, (_e897 < 1f)), (_e897 > 0f)) * _e529);
                            let _e923 = f32((_e534 - 1u));
                            let _e925 = select(0f, _e921, (_e921 > 0f));
                            let _e928 = u32(select(_e923, _e925, (_e925 < _e923)));
                            let _e935 = ((_e780.member_1.member_1.x - _e894) * _e516);
                            let _e936 = ((_e780.member_1.member_1.y - _e897) * _e529);
                            let _e940 = sqrt(((_e935 * _e935) + (_e936 * _e936)));
                            let _e947 = select(false, (_e928 == _e780.member_1.member.y), (_e916 == _e780.member_1.member.x));
                            let _e949 = ((_e928 * _e521) + _e916);
                            let _e951 = depth.member[_e949];
                            let _e963 = select(_e612, _e951, select(false, (_e951 < _e612), (_e951 > 0f)));
                            let _e965 = ((((f32(_e916) + 0.5f) * (1f / _e516)) * 2f) - 1f);
                            let _e967 = ((((f32(_e928) + 0.5f) * (1f / _e529)) * -2f) + 1f);
                            let _e973 = (((_e965 * _e963) * _e582) - _e780.member_1.member_4.x);
                            let _e974 = (((_e967 * _e963) * _e590) - _e780.member_1.member_4.y);
                            let _e975 = (-(_e963) - _e780.member_1.member_4.z);
                            let _e984 = (((_e973 * _e780.member_1.member_6.x) + (_e974 * _e780.member_1.member_6.y)) + (_e975 * _e780.member_1.member_6.z));
                            if _e831 {
                                let _e989 = (((_e973 * _e973) + (_e974 * _e974)) + (_e975 * _e975));
                                let _e1001 = (((((_e780.member_1.member_5.x * _e973) + (_e780.member_1.member_5.y * _e974)) + (_e780.member_1.member_5.z * _e975)) / sqrt(_e989)) - 0.1f);
                                let _e1008 = (1f - (_e989 / (_e558 * _e558)));
                                let _e1015 = ((select(0f, select(1f, _e1001, (_e1001 < 1f)), (_e1001 > 0f)) * select(0f, select(1f, _e1008, (_e1008 < 1f)), (_e1008 > 0f))) / _e853);
                                phi_1470_ = select(0f, select(0f, select(1f, _e1015, (_e1015 < 1f)), (_e1015 > 0f)), (_e989 > 0f));
                            } else {
                                let _e1026 = frame.member[0u].member_1.member.member_3;
                                let _e1032 = (_e848 - select(_e984, _e867, ((_e867 > _e984) || (_e984 != _e984))));
                                let _e1039 = ((_e984 - (_e780.member_1.member_2 * (1f + _e1026))) * (1f / _e848));
                                phi_1470_ = ((select(0f, _e1032, ((_e1032 > 0f) || false)) + (select(0f, select(1f, _e1039, (_e1039 < 1f)), (_e1039 > 0f)) * _e868)) * (0.5f / _e848));
                            }
                            let _e1049 = phi_1470_;
                            let _e1054 = frame.member[0u].member_1.member_9;
                            if (_e1054 == 0u) {
                                phi_1738_ = type_41(_e984, _e1049);
                            } else {
                                if _e831 {
                                    let _e1057 = (_e780.member_1.member_2 * 0.1f);
                                    phi_1499_ = select(_e1057, _e848, ((_e848 > _e1057) || (_e1057 != _e1057)));
                                } else {
                                    let _e1067 = frame.member[0u].member_1.member.member_3;
                                    phi_1499_ = (_e780.member_1.member_2 * (1f + _e1067));
                                }
                                let _e1071 = phi_1499_;
                                let _e1077 = frame.member[0u].member_1.member_3;
                                let _e1079 = select(false, (_e940 > _e1077), (_e984 > _e1071));
                                let _e1082 = depth2_.member[_e949];
                                let _e1086 = select(_e612, _e1082, select(false, (_e1082 < _e612), (_e1082 > 0f)));
                                let _e1092 = (((_e965 * _e1086) * _e582) - _e780.member_1.member_4.x);
                                let _e1093 = (((_e967 * _e1086) * _e590) - _e780.member_1.member_4.y);
                                let _e1094 = (-(_e1086) - _e780.member_1.member_4.z);
                                let _e1099 = (((_e1092 * _e780.member_1.member_6.x) + (_e1093 * _e780.member_1.member_6.y)) + (_e1094 * _e780.member_1.member_6.z));
                                if _e831 {
                                    let _e1104 = (((_e1092 * _e1092) + (_e1093 * _e1093)) + (_e1094 * _e1094));
                                    let _e1116 = (((((_e780.member_1.member_5.x * _e1092) + (_e780.member_1.member_5.y * _e1093)) + (_e780.member_1.member_5.z * _e1094)) / sqrt(_e1104)) - 0.1f);
                                    let _e1123 = (1f - (_e1104 / (_e558 * _e558)));
                                    let _e1130 = ((select(0f, select(1f, _e1116, (_e1116 < 1f)), (_e1116 > 0f)) * select(0f, select(1f, _e1123, (_e1123 < 1f)), (_e1123 > 0f))) / _e853);
                                    phi_1700_ = select(0f, select(0f, select(1f, _e1130, (_e1130 < 1f)), (_e1130 > 0f)), (_e1104 > 0f));
                                } else {
                                    let _e1141 = frame.member[0u].member_1.member.member_3;
                                    let _e1147 = (_e848 - select(_e1099, _e867, ((_e867 > _e1099) || (_e1099 != _e1099))));
                                    let _e1154 = ((_e1099 - (_e780.member_1.member_2 * (1f + _e1141))) * (1f / _e848));
                                    phi_1700_ = ((select(0f, _e1147, ((_e1147 > 0f) || false)) + (select(0f, select(1f, _e1154, (_e1154 < 1f)), (_e1154 > 0f)) * _e868)) * (0.5f / _e848));
                                }
                                let _e1164 = phi_1700_;
                                if _e831 {
                                    phi_1732_ = select(_e1164, _e1049, ((_e1049 > _e1164) || (_e1164 != _e1164)));
                                } else {
                                    phi_1732_ = select(_e1164, _e1049, ((_e1049 < _e1164) || (_e1164 != _e1164)));
                                }
                                let _e1179 = phi_1732_;
                                phi_1738_ = type_41(select(_e984, select(_e1099, _e984, ((_e984 < _e1099) || (_e1099 != _e1099))), _e1079), select(_e1049, _e1179, _e1079));
                            }
                            let _e1183 = phi_1738_;
                            if _e831 {
                                phi_1754_ = 0f;
                            } else {
                                phi_1754_ = (_e868 / (_e848 * 2f));
                            }
                            let _e1189 = phi_1754_;
                            if (_e816 == 2u) {
                                phi_1774_ = true;
                            } else {
                                if _e817 {
                                    let _e1197 = frame.member[0u].member_1.member_4;
                                    phi_1773_ = (_e1197 > 0u);
                                } else {
                                    phi_1773_ = false;
                                }
                                let _e1200 = phi_1773_;
                                phi_1774_ = _e1200;
                            }
                            let _e1202 = phi_1774_;
                            let _e1203 = select(false, _e1202, !(select(false, select(false, (_e897 <= 1f), (_e897 >= 0f)), select(false, (_e894 <= 1f), (_e894 >= 0f)))));
                            if _e817 {
                                phi_1786_ = select(_e1183.member, 0x1.fffffep+127f, _e1203);
                            } else {
                                phi_1786_ = _e1183.member;
                            }
                            let _e1206 = phi_1786_;
                            if _e831 {
                                let _e1208 = (_e780.member_1.member_2 * 0.1f);
                                phi_1811_ = select(_e1208, _e848, ((_e848 > _e1208) || (_e1208 != _e1208)));
                            } else {
                                let _e1218 = frame.member[0u].member_1.member.member_3;
                                phi_1811_ = (_e780.member_1.member_2 * (1f + _e1218));
                            }
                            let _e1222 = phi_1811_;
                            let _e1228 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e940 > _e1228), (_e1206 > _e1222)), true, _e1203), (_e816 != 0u)), select(false, !(_e947), _e870)) {
                                if (_e816 != 1u) {
                                } else {
                                    let _e1247 = frame.member[0u].member_1.member_5[0u];
                                    let _e1253 = frame.member[0u].member_1.member_5[1u];
                                    let _e1260 = frame.member[0u].member_1.member_4;
                                    let _e1261 = f32(_e1260);
                                    let _e1262 = (2u * _e1260);
                                    let _e1263 = (_e1247 + _e1262);
                                    let _e1269 = (floor((_e894 * f32(_e1247))) + _e1261);
                                    let _e1270 = f32((_e1263 - 1u));
                                    let _e1274 = select(0f, select(_e1270, _e1269, (_e1269 < _e1270)), (_e1269 > 0f));
                                    let _e1277 = (floor((_e897 * f32(_e1253))) + _e1261);
                                    let _e1278 = f32(((_e1253 + _e1262) - 1u));
                                    let _e1282 = select(0f, select(_e1278, _e1277, (_e1277 < _e1278)), (_e1277 > 0f));
                                    let _e1294 = ((select(select(u32(_e1282), 0u, (_e1282 < 0f)), 4294967295u, (_e1282 > 4294967000f)) * _e1263) + select(select(u32(_e1274), 0u, (_e1274 < 0f)), 4294967295u, (_e1274 > 4294967000f)));
                                    let _e1299 = frame.member[0u].member_1.member_2;
                                    if (_e1299 == 0u) {
                                        if (_e1294 < _e496) {
                                        } else {
                                            phi_2242_ = true;
                                            break;
                                        }
                                        let _e1304 = atomicMax((&ray_max.member[_e1294]), 1u);
                                    } else {
                                        if _e831 {
                                            if (_e1206 != _e1206) {
                                                phi_2213_ = true;
                                            } else {
                                                phi_2213_ = (_e848 <= _e1206);
                                            }
                                            let _e1308 = phi_2213_;
                                            phi_1963_ = select(_e1206, _e848, _e1308);
                                        } else {
                                            let _e1315 = frame.member[0u].member_1.member.member_3;
                                            let _e1318 = (((1f + _e1315) * _e780.member_1.member_2) + _e848);
                                            if (_e1206 != _e1206) {
                                                phi_2228_ = true;
                                            } else {
                                                phi_2228_ = (_e1318 <= _e1206);
                                            }
                                            let _e1322 = phi_2228_;
                                            phi_1963_ = select(_e1206, _e1318, _e1322);
                                        }
                                        let _e1325 = phi_1963_;
                                        let _e1326 = (_e794 - _e1325);
                                        if (_e1326 > 0f) {
                                            phi_1970_ = bitcast<u32>(_e1326);
                                        } else {
                                            phi_1970_ = 0u;
                                        }
                                        let _e1330 = phi_1970_;
                                        if (_e1294 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2242_ = true;
                                            break;
                                        }
                                        let _e1334 = atomicMin((&ray_min.member[_e1294]), _e1330);
                                        let _e1335 = (_e794 - _e867);
                                        if (_e1335 > 0f) {
                                            phi_1984_ = bitcast<u32>(_e1335);
                                        } else {
                                            phi_1984_ = 0u;
                                        }
                                        let _e1339 = phi_1984_;
                                        if (_e1294 < _e496) {
                                        } else {
                                            phi_2242_ = true;
                                            break;
                                        }
                                        let _e1343 = atomicMax((&ray_max.member[_e1294]), _e1339);
                                    }
                                }
                                phi_1992_ = (_e798 | (1u << bitcast<u32>((_e796 & 31u))));
                            } else {
                                phi_1992_ = _e798;
                            }
                            let _e1345 = phi_1992_;
                            phi_998_ = (_e796 + 1u);
                            phi_1001_ = _e1345;
                            phi_1003_ = (_e800 + select(0f, select(_e1183.member_1, _e1189, _e947), _e870));
                        } else {
                            phi_998_ = u32();
                            phi_1001_ = u32();
                            phi_1003_ = f32();
                        }
                        let _e1348 = phi_998_;
                        let _e1350 = phi_1001_;
                        let _e1352 = phi_1003_;
                        continue;
                        continuing {
                            phi_997_ = _e1348;
                            phi_1000_ = _e1350;
                            phi_1002_ = _e1352;
                            phi_2242_ = false;
                            break if !(_e811);
                        }
                    }
                    let _e1355 = phi_2242_;
                    if _e1355 {
                        break;
                    }
                    let _e1360 = frame.member[0u].member_1.member_10;
                    let _e1361 = (_e1360 == 1u);
                    let _e1364 = local_7;
                    let _e1368 = local_8;
                    let _e1369 = ((select(2f, 1f, _e1361) / f32(_e1364)) * _e1368);
                    let _e1371 = local_9;
                    if (_e1371 == 0u) {
                        if _e1361 {
                            phi_2025_ = (1f - (2f * _e1369));
                        } else {
                            phi_2025_ = _e1369;
                        }
                        let _e1376 = phi_2025_;
                        let _e1386 = frame.member[0u].member_1.member.member_2;
                        let _e1389 = local_10;
                        phi_2054_ = type_42(pow(select(0f, select(1f, _e1376, (_e1376 < 1f)), (_e1376 > 0f)), _e1386), _e1389);
                    } else {
                        let _e1399 = local_11;
                        phi_2054_ = type_42((round((select(0f, select(1f, _e1369, (_e1369 < 1f)), (_e1369 > 0f)) * 255f)) * 0.003921569f), _e1399);
                    }
                    let _e1402 = phi_2054_;
                    phi_2059_ = _e1402;
                } else {
                    phi_2059_ = type_42(1f, 0u);
                }
                let _e1404 = phi_2059_;
                ao.member[_e572] = _e1404.member;
                if (_e572 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e572] = _e1404.member_1;
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
