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
    var phi_725_: bool;
    var phi_727_: bool;
    var phi_728_: bool;
    var phi_729_: bool;
    var phi_730_: bool;
    var phi_2133_: bool;
    var phi_2148_: bool;
    var phi_2109_: vec2<f32>;
    var phi_2163_: bool;
    var phi_985_: type_31;
    var phi_1007_: u32;
    var phi_1010_: u32;
    var phi_1012_: f32;
    var phi_1077_: f32;
    var phi_1102_: f32;
    var phi_1115_: f32;
    var phi_1243_: u32;
    var phi_1274_: u32;
    var phi_2178_: bool;
    var phi_2193_: bool;
    var phi_1478_: f32;
    var phi_2208_: bool;
    var phi_1501_: f32;
    var phi_2223_: bool;
    var phi_2238_: bool;
    var phi_1690_: f32;
    var phi_2253_: bool;
    var phi_2268_: bool;
    var phi_2283_: bool;
    var phi_1704_: f32;
    var phi_1710_: type_41;
    var phi_1726_: f32;
    var phi_1745_: bool;
    var phi_1746_: bool;
    var phi_1758_: f32;
    var phi_2298_: bool;
    var phi_1777_: f32;
    var phi_2313_: bool;
    var phi_2328_: bool;
    var phi_1929_: f32;
    var phi_1936_: u32;
    var phi_1950_: u32;
    var phi_1958_: u32;
    var phi_1008_: u32;
    var phi_1011_: u32;
    var phi_1013_: f32;
    var phi_2342_: bool;
    var local_7: u32;
    var local_8: f32;
    var local_9: u32;
    var phi_1991_: f32;
    var local_10: u32;
    var local_11: u32;
    var phi_2020_: type_42;
    var phi_2025_: type_42;

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
                        phi_725_ = ((_e508 + _e506) < _e534);
                    } else {
                        phi_725_ = bool();
                    }
                    let _e542 = phi_725_;
                    phi_727_ = _e542;
                    phi_728_ = select(true, false, _e538);
                } else {
                    phi_727_ = bool();
                    phi_728_ = true;
                }
                let _e545 = phi_727_;
                let _e547 = phi_728_;
                phi_729_ = _e545;
                phi_730_ = _e547;
            } else {
                phi_729_ = bool();
                phi_730_ = true;
            }
            let _e549 = phi_729_;
            let _e551 = phi_730_;
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
                    phi_2133_ = true;
                } else {
                    phi_2133_ = (-1f >= _e638);
                }
                let _e642 = phi_2133_;
                let _e643 = select(_e638, -1f, _e642);
                let _e653 = (f32((bitcast<i32>((((_e630 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e653 != _e653) {
                    phi_2148_ = true;
                } else {
                    phi_2148_ = (-1f >= _e653);
                }
                let _e657 = phi_2148_;
                let _e658 = select(_e653, -1f, _e657);
                let _e661 = (1f - abs(_e643));
                let _e662 = abs(_e658);
                let _e663 = (_e661 - _e662);
                if (_e663 < 0f) {
                    phi_2109_ = vec2<f32>(((1f - _e662) * select(1f, -1f, (_e643 < 0f))), (_e661 * select(1f, -1f, (_e658 < 0f))));
                } else {
                    phi_2109_ = vec2<f32>(_e643, _e658);
                }
                let _e674 = phi_2109_;
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
                if (_e766 != _e766) {
                    phi_2163_ = true;
                } else {
                    phi_2163_ = (0.0001f >= _e766);
                }
                let _e770 = phi_2163_;
                if select(false, !((_e605 < 0.5f)), select(false, (_e574 < _e612), (_e574 > 0f))) {
                    phi_985_ = type_31(1u, type_30(vec2<u32>(_e507, _e508), vec2<f32>(_e567, _e570), select(_e558, ((_e558 * _e564) / _e600), _e601), _e605, vec3<f32>(_e624, _e626, _e627), vec3<f32>(_e696, _e697, _e698), vec3<f32>(_e717, _e718, _e719), vec3<f32>(_e740, _e743, _e746), vec3<f32>(_e734, _e735, _e736), vec3<f32>((((_e696 * _e740) + (_e697 * _e743)) + (_e698 * _e746)), (((_e696 * _e734) + (_e697 * _e735)) + (_e698 * _e736)), _e762), (1f / (select(1f, -1f, (_e762 < 0f)) * select(_e766, 0.0001f, _e770)))));
                } else {
                    phi_985_ = type_31(0u, type_31().member_1);
                }
                let _e782 = phi_985_;
                if (bitcast<i32>(_e782.member) != 0i) {
                    let _e796 = sqrt((((_e782.member_1.member_4.x * _e782.member_1.member_4.x) + (_e782.member_1.member_4.y * _e782.member_1.member_4.y)) + (_e782.member_1.member_4.z * _e782.member_1.member_4.z)));
                    phi_1007_ = 0u;
                    phi_1010_ = 0u;
                    phi_1012_ = 0f;
                    loop {
                        let _e798 = phi_1007_;
                        let _e800 = phi_1010_;
                        let _e802 = phi_1012_;
                        let _e807 = frame.member[0u].member_1.member_11;
                        local_8 = _e802;
                        local_9 = _e800;
                        local_10 = _e800;
                        local_11 = _e800;
                        let _e812 = (8u << bitcast<u32>((select(_e807, 2u, (2u < _e807)) & 31u)));
                        let _e813 = (_e798 < _e812);
                        local_7 = _e812;
                        if _e813 {
                            let _e818 = frame.member[0u].member_1.member_1;
                            let _e819 = (_e818 == 1u);
                            let _e825 = frame.member[0u].member_1.member_10;
                            let _e827 = ((_e812 + _e798) - 8u);
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e828 = (_e827 < 56u);
                            if _e828 {
                            } else {
                                phi_2342_ = true;
                                break;
                            }
                            let _e830 = local[_e827];
                            let _e833 = (_e825 == 1u);
                            if _e833 {
                                local_1 = array<f32, 56>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f, 0.008364792f, 0.2996842f, 0.13131975f, 0.5251597f, 0.06264064f, 0.40226412f, 0.21027996f, 0.69061786f, 0.033039935f, 0.349031f, 0.16956282f, 0.59961605f, 0.09559796f, 0.46040866f, 0.2535722f, 0.8218291f, 0.0035168785f, 0.2878725f, 0.1221474f, 0.508219f, 0.054890417f, 0.38854375f, 0.19986558f, 0.66562253f, 0.026302148f, 0.3363604f, 0.15977097f, 0.5798254f, 0.08708425f, 0.44533524f, 0.24249692f, 0.78164643f, 0.013886448f, 0.31169695f, 0.14064877f, 0.542692f, 0.07059704f, 0.41628838f, 0.2208546f, 0.7177502f, 0.040069554f, 0.36194277f, 0.1795086f, 0.62038976f, 0.10428292f, 0.47588885f, 0.26482287f, 0.8740953f);
                                if _e828 {
                                } else {
                                    phi_2342_ = true;
                                    break;
                                }
                                let _e835 = local_1[_e827];
                                phi_1077_ = _e835;
                            } else {
                                local_2 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                                if _e828 {
                                } else {
                                    phi_2342_ = true;
                                    break;
                                }
                                let _e837 = local_2[_e827];
                                phi_1077_ = _e837;
                            }
                            let _e839 = phi_1077_;
                            let _e841 = (_e782.member_1.member_2 * _e839);
                            let _e842 = (_e841 * _e830[0]);
                            let _e843 = (_e841 * _e830[1]);
                            if _e833 {
                                local_3 = array<f32, 56>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f, 0.999965f, 0.95403844f, 0.99134004f, 0.8510037f, 0.99803615f, 0.91552365f, 0.9776412f, 0.7232199f, 0.999454f, 0.9371112f, 0.9855194f, 0.8002878f, 0.99542004f, 0.8877071f, 0.96731645f, 0.5697341f, 0.9999938f, 0.9576687f, 0.992512f, 0.86122787f, 0.99849236f, 0.9214303f, 0.97982335f, 0.7462886f, 0.99965405f, 0.94173336f, 0.9871541f, 0.8147408f, 0.996201f, 0.8953639f, 0.9701522f, 0.6237217f, 0.99990356f, 0.95018154f, 0.99005955f, 0.8399318f, 0.9975049f, 0.9092326f, 0.97530675f, 0.6963007f, 0.9991969f, 0.9322003f, 0.9837564f, 0.78429365f, 0.99454767f, 0.87950546f, 0.96429706f, 0.48575446f);
                                if _e828 {
                                } else {
                                    phi_2342_ = true;
                                    break;
                                }
                                let _e845 = local_3[_e827];
                                phi_1102_ = _e845;
                            } else {
                                local_4 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                                if _e828 {
                                } else {
                                    phi_2342_ = true;
                                    break;
                                }
                                let _e847 = local_4[_e827];
                                phi_1102_ = _e847;
                            }
                            let _e849 = phi_1102_;
                            let _e850 = (_e782.member_1.member_2 * _e849);
                            if _e833 {
                                local_5 = array<f32, 56>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f, 0.8887312f, 0.5274526f, 0.72867256f, 0.29448545f, 0.8167736f, 0.41591686f, 0.63161474f, 0.15487643f, 0.8557666f, 0.47269714f, 0.68108714f, 0.22801188f, 0.77407813f, 0.35673028f, 0.58039576f, 0.06768583f, 0.8952564f, 0.5408529f, 0.74024403f, 0.31038457f, 0.8269243f, 0.43031907f, 0.6441499f, 0.17401955f, 0.8647266f, 0.4865651f, 0.6931688f, 0.24512479f, 0.7850342f, 0.37178203f, 0.59336114f, 0.09182964f, 0.8813185f, 0.51393956f, 0.71696603f, 0.27832723f, 0.8063964f, 0.4013655f, 0.618971f, 0.13495624f, 0.84645164f, 0.4587034f, 0.6688883f, 0.21049869f, 0.7629548f, 0.3414897f, 0.56732315f, 0.04020735f);
                                if _e828 {
                                } else {
                                    phi_2342_ = true;
                                    break;
                                }
                                let _e852 = local_5[_e827];
                                phi_1115_ = _e852;
                            } else {
                                phi_1115_ = (_e850 * 2f);
                            }
                            let _e855 = phi_1115_;
                            let _e864 = (-(((_e842 * _e782.member_1.member_9.x) + (_e843 * _e782.member_1.member_9.y))) * _e782.member_1.member_10);
                            let _e865 = -(_e850);
                            let _e869 = select(_e865, select(_e850, _e864, (_e864 < _e850)), (_e864 > _e865));
                            let _e870 = (_e850 - _e869);
                            let _e872 = (_e870 > (_e850 * 0.2f));
                            let _e893 = (-0.5f / ((_e782.member_1.member_4.z + (_e782.member_1.member_7.z * _e842)) + (_e782.member_1.member_8.z * _e843)));
                            let _e896 = (((((_e782.member_1.member_4.x + (_e782.member_1.member_7.x * _e842)) + (_e782.member_1.member_8.x * _e843)) * _e893) / _e582) + 0.5f);
                            let _e899 = (0.5f - ((((_e782.member_1.member_4.y + (_e782.member_1.member_7.y * _e842)) + (_e782.member_1.member_8.y * _e843)) * _e893) / _e590));
                            let _e911 = (select(0f, select(1f, _e896, (_e896 < 1f)), (_e896 > 0f)) * _e516);
                            if (_e911 > 0f) {
                                let _e917 = select(select(u32(_e911), 0u, (_e911 < 0f)), 4294967295u, (_e911 > 4294967000f));
                                let _e918 = (_e521 - 1u);
                                phi_1243_ = select(_e917, _e918, (_e918 < _e917));
                            } else {
                                phi_1243_ = 0u;
                            }
                            let _e922 = phi_1243_;
                            let _e927 = (select(0f, select(1f, _e899, (_e899 < 1f)), (_e899 > 0f)) * _e529);
                            if (_e927 > 0f) {
                                let _e933 = select(select(u32(_e927), 0u, (_e927 < 0f)), 4294967295u, (_e927 > 4294967000f));
                                let _e934 = (_e534 - 1u);
                                phi_1274_ = select(_e933, _e934, (_e934 < _e933));
                            } else {
                                phi_1274_ = 0u;
                            }
                            let _e938 = phi_1274_;
                            let _e945 = ((_e782.member_1.member_1.x - _e896) * _e516);
                            let _e946 = ((_e782.member_1.member_1.y - _e899) * _e529);
                            let _e950 = sqrt(((_e945 * _e945) + (_e946 * _e946)));
                            let _e957 = select(false, (_e938 == _e782.member_1.member.y), (_e922 == _e782.member_1.member.x));
                            let _e959 = ((_e938 * _e521) + _e922);
                            let _e961 = depth.member[_e959];
                            let _e973 = select(_e612, _e961, select(false, (_e961 < _e612), (_e961 > 0f)));
                            let _e975 = ((((f32(_e922) + 0.5f) * (1f / _e516)) * 2f) - 1f);
                            let _e977 = ((((f32(_e938) + 0.5f) * (1f / _e529)) * -2f) + 1f);
                            let _e983 = (((_e975 * _e973) * _e582) - _e782.member_1.member_4.x);
                            let _e984 = (((_e977 * _e973) * _e590) - _e782.member_1.member_4.y);
                            let _e985 = (-(_e973) - _e782.member_1.member_4.z);
                            let _e994 = (((_e983 * _e782.member_1.member_6.x) + (_e984 * _e782.member_1.member_6.y)) + (_e985 * _e782.member_1.member_6.z));
                            if _e833 {
                                let _e999 = (((_e983 * _e983) + (_e984 * _e984)) + (_e985 * _e985));
                                let _e1011 = (((((_e782.member_1.member_5.x * _e983) + (_e782.member_1.member_5.y * _e984)) + (_e782.member_1.member_5.z * _e985)) / sqrt(_e999)) - 0.1f);
                                let _e1018 = (1f - (_e999 / (_e558 * _e558)));
                                let _e1025 = ((select(0f, select(1f, _e1011, (_e1011 < 1f)), (_e1011 > 0f)) * select(0f, select(1f, _e1018, (_e1018 < 1f)), (_e1018 > 0f))) / _e855);
                                phi_1478_ = select(0f, select(0f, select(1f, _e1025, (_e1025 < 1f)), (_e1025 > 0f)), (_e999 > 0f));
                            } else {
                                let _e1036 = frame.member[0u].member_1.member.member_3;
                                if (_e869 != _e869) {
                                    phi_2178_ = true;
                                } else {
                                    phi_2178_ = (_e994 >= _e869);
                                }
                                let _e1041 = phi_2178_;
                                let _e1043 = (_e850 - select(_e869, _e994, _e1041));
                                if (_e1043 != _e1043) {
                                    phi_2193_ = true;
                                } else {
                                    phi_2193_ = (0f >= _e1043);
                                }
                                let _e1047 = phi_2193_;
                                let _e1052 = ((_e994 - (_e782.member_1.member_2 * (1f + _e1036))) * (1f / _e850));
                                phi_1478_ = ((select(_e1043, 0f, _e1047) + (select(0f, select(1f, _e1052, (_e1052 < 1f)), (_e1052 > 0f)) * _e870)) * (0.5f / _e850));
                            }
                            let _e1062 = phi_1478_;
                            let _e1067 = frame.member[0u].member_1.member_9;
                            if (_e1067 == 0u) {
                                phi_1710_ = type_41(_e994, _e1062);
                            } else {
                                if _e833 {
                                    let _e1070 = (_e782.member_1.member_2 * 0.1f);
                                    if (_e850 != _e850) {
                                        phi_2208_ = true;
                                    } else {
                                        phi_2208_ = (_e1070 >= _e850);
                                    }
                                    let _e1074 = phi_2208_;
                                    phi_1501_ = select(_e850, _e1070, _e1074);
                                } else {
                                    let _e1081 = frame.member[0u].member_1.member.member_3;
                                    phi_1501_ = (_e782.member_1.member_2 * (1f + _e1081));
                                }
                                let _e1085 = phi_1501_;
                                let _e1091 = frame.member[0u].member_1.member_3;
                                let _e1093 = select(false, (_e950 > _e1091), (_e994 > _e1085));
                                let _e1096 = depth2_.member[_e959];
                                let _e1100 = select(_e612, _e1096, select(false, (_e1096 < _e612), (_e1096 > 0f)));
                                let _e1106 = (((_e975 * _e1100) * _e582) - _e782.member_1.member_4.x);
                                let _e1107 = (((_e977 * _e1100) * _e590) - _e782.member_1.member_4.y);
                                let _e1108 = (-(_e1100) - _e782.member_1.member_4.z);
                                let _e1113 = (((_e1106 * _e782.member_1.member_6.x) + (_e1107 * _e782.member_1.member_6.y)) + (_e1108 * _e782.member_1.member_6.z));
                                if _e833 {
                                    let _e1118 = (((_e1106 * _e1106) + (_e1107 * _e1107)) + (_e1108 * _e1108));
                                    let _e1130 = (((((_e782.member_1.member_5.x * _e1106) + (_e782.member_1.member_5.y * _e1107)) + (_e782.member_1.member_5.z * _e1108)) / sqrt(_e1118)) - 0.1f);
                                    let _e1137 = (1f - (_e1118 / (_e558 * _e558)));
                                    let _e1144 = ((select(0f, select(1f, _e1130, (_e1130 < 1f)), (_e1130 > 0f)) * select(0f, select(1f, _e1137, (_e1137 < 1f)), (_e1137 > 0f))) / _e855);
                                    phi_1690_ = select(0f, select(0f, select(1f, _e1144, (_e1144 < 1f)), (_e1144 > 0f)), (_e1118 > 0f));
                                } else {
                                    let _e1155 = frame.member[0u].member_1.member.member_3;
                                    if (_e869 != _e869) {
                                        phi_2223_ = true;
                                    } else {
                                        phi_2223_ = (_e1113 >= _e869);
                                    }
                                    let _e1160 = phi_2223_;
                                    let _e1162 = (_e850 - select(_e869, _e1113, _e1160));
                                    if (_e1162 != _e1162) {
                                        phi_2238_ = true;
                                    } else {
                                        phi_2238_ = (0f >= _e1162);
                                    }
                                    let _e1166 = phi_2238_;
                                    let _e1171 = ((_e1113 - (_e782.member_1.member_2 * (1f + _e1155))) * (1f / _e850));
                                    phi_1690_ = ((select(_e1162, 0f, _e1166) + (select(0f, select(1f, _e1171, (_e1171 < 1f)), (_e1171 > 0f)) * _e870)) * (0.5f / _e850));
                                }
                                let _e1181 = phi_1690_;
                                if (_e994 != _e994) {
                                    phi_2253_ = true;
                                } else {
                                    phi_2253_ = (_e1113 <= _e994);
                                }
                                let _e1185 = phi_2253_;
                                if _e833 {
                                    if (_e1062 != _e1062) {
                                        phi_2268_ = true;
                                    } else {
                                        phi_2268_ = (_e1181 >= _e1062);
                                    }
                                    let _e1191 = phi_2268_;
                                    phi_1704_ = select(_e1062, _e1181, _e1191);
                                } else {
                                    if (_e1062 != _e1062) {
                                        phi_2283_ = true;
                                    } else {
                                        phi_2283_ = (_e1181 <= _e1062);
                                    }
                                    let _e1196 = phi_2283_;
                                    phi_1704_ = select(_e1062, _e1181, _e1196);
                                }
                                let _e1199 = phi_1704_;
                                phi_1710_ = type_41(select(_e994, select(_e994, _e1113, _e1185), _e1093), select(_e1062, _e1199, _e1093));
                            }
                            let _e1203 = phi_1710_;
                            if _e833 {
                                phi_1726_ = 0f;
                            } else {
                                phi_1726_ = (_e870 / (_e850 * 2f));
                            }
                            let _e1209 = phi_1726_;
                            if (_e818 == 2u) {
                                phi_1746_ = true;
                            } else {
                                if _e819 {
                                    let _e1217 = frame.member[0u].member_1.member_4;
                                    phi_1745_ = (_e1217 > 0u);
                                } else {
                                    phi_1745_ = false;
                                }
                                let _e1220 = phi_1745_;
                                phi_1746_ = _e1220;
                            }
                            let _e1222 = phi_1746_;
                            let _e1223 = select(false, _e1222, !(select(false, select(false, (_e899 <= 1f), (_e899 >= 0f)), select(false, (_e896 <= 1f), (_e896 >= 0f)))));
                            if _e819 {
                                phi_1758_ = select(_e1203.member, 0x1.fffffep+127f, _e1223);
                            } else {
                                phi_1758_ = _e1203.member;
                            }
                            let _e1226 = phi_1758_;
                            if _e833 {
                                let _e1228 = (_e782.member_1.member_2 * 0.1f);
                                if (_e850 != _e850) {
                                    phi_2298_ = true;
                                } else {
                                    phi_2298_ = (_e1228 >= _e850);
                                }
                                let _e1232 = phi_2298_;
                                phi_1777_ = select(_e850, _e1228, _e1232);
                            } else {
                                let _e1239 = frame.member[0u].member_1.member.member_3;
                                phi_1777_ = (_e782.member_1.member_2 * (1f + _e1239));
                            }
                            let _e1243 = phi_1777_;
                            let _e1249 = frame.member[0u].member_1.member_3;
                            if select(false, select(false, select(select(false, (_e950 > _e1249), (_e1226 > _e1243)), true, _e1223), (_e818 != 0u)), select(false, !(_e957), _e872)) {
                                if (_e818 != 1u) {
                                } else {
                                    let _e1268 = frame.member[0u].member_1.member_5[0u];
                                    let _e1274 = frame.member[0u].member_1.member_5[1u];
                                    let _e1281 = frame.member[0u].member_1.member_4;
                                    let _e1282 = f32(_e1281);
                                    let _e1283 = (2u * _e1281);
                                    let _e1284 = (_e1268 + _e1283);
                                    let _e1290 = (floor((_e896 * f32(_e1268))) + _e1282);
                                    let _e1291 = f32((_e1284 - 1u));
                                    let _e1295 = select(0f, select(_e1291, _e1290, (_e1290 < _e1291)), (_e1290 > 0f));
                                    let _e1298 = (floor((_e899 * f32(_e1274))) + _e1282);
                                    let _e1299 = f32(((_e1274 + _e1283) - 1u));
                                    let _e1303 = select(0f, select(_e1299, _e1298, (_e1298 < _e1299)), (_e1298 > 0f));
                                    let _e1315 = ((select(select(u32(_e1303), 0u, (_e1303 < 0f)), 4294967295u, (_e1303 > 4294967000f)) * _e1284) + select(select(u32(_e1295), 0u, (_e1295 < 0f)), 4294967295u, (_e1295 > 4294967000f)));
                                    let _e1320 = frame.member[0u].member_1.member_2;
                                    if (_e1320 == 0u) {
                                        if (_e1315 < _e496) {
                                        } else {
                                            phi_2342_ = true;
                                            break;
                                        }
                                        let _e1325 = atomicMax((&ray_max.member[_e1315]), 1u);
                                    } else {
                                        if _e833 {
                                            if (_e1226 != _e1226) {
                                                phi_2313_ = true;
                                            } else {
                                                phi_2313_ = (_e850 <= _e1226);
                                            }
                                            let _e1329 = phi_2313_;
                                            phi_1929_ = select(_e1226, _e850, _e1329);
                                        } else {
                                            let _e1336 = frame.member[0u].member_1.member.member_3;
                                            let _e1339 = (((1f + _e1336) * _e782.member_1.member_2) + _e850);
                                            if (_e1226 != _e1226) {
                                                phi_2328_ = true;
                                            } else {
                                                phi_2328_ = (_e1339 <= _e1226);
                                            }
                                            let _e1343 = phi_2328_;
                                            phi_1929_ = select(_e1226, _e1339, _e1343);
                                        }
                                        let _e1346 = phi_1929_;
                                        let _e1347 = (_e796 - _e1346);
                                        if (_e1347 > 0f) {
                                            phi_1936_ = bitcast<u32>(_e1347);
                                        } else {
                                            phi_1936_ = 0u;
                                        }
                                        let _e1351 = phi_1936_;
                                        if (_e1315 < arrayLength((&ray_min.member))) {
                                        } else {
                                            phi_2342_ = true;
                                            break;
                                        }
                                        let _e1355 = atomicMin((&ray_min.member[_e1315]), _e1351);
                                        let _e1356 = (_e796 - _e869);
                                        if (_e1356 > 0f) {
                                            phi_1950_ = bitcast<u32>(_e1356);
                                        } else {
                                            phi_1950_ = 0u;
                                        }
                                        let _e1360 = phi_1950_;
                                        if (_e1315 < _e496) {
                                        } else {
                                            phi_2342_ = true;
                                            break;
                                        }
                                        let _e1364 = atomicMax((&ray_max.member[_e1315]), _e1360);
                                    }
                                }
                                phi_1958_ = (_e800 | (1u << bitcast<u32>((_e798 & 31u))));
                            } else {
                                phi_1958_ = _e800;
                            }
                            let _e1366 = phi_1958_;
                            phi_1008_ = (_e798 + 1u);
                            phi_1011_ = _e1366;
                            phi_1013_ = (_e802 + select(0f, select(_e1203.member_1, _e1209, _e957), _e872));
                        } else {
                            phi_1008_ = u32();
                            phi_1011_ = u32();
                            phi_1013_ = f32();
                        }
                        let _e1369 = phi_1008_;
                        let _e1371 = phi_1011_;
                        let _e1373 = phi_1013_;
                        continue;
                        continuing {
                            phi_1007_ = _e1369;
                            phi_1010_ = _e1371;
                            phi_1012_ = _e1373;
                            phi_2342_ = false;
                            break if !(_e813);
                        }
                    }
                    let _e1376 = phi_2342_;
                    if _e1376 {
                        break;
                    }
                    let _e1381 = frame.member[0u].member_1.member_10;
                    let _e1382 = (_e1381 == 1u);
                    let _e1385 = local_7;
                    let _e1389 = local_8;
                    let _e1390 = ((select(2f, 1f, _e1382) / f32(_e1385)) * _e1389);
                    let _e1392 = local_9;
                    if (_e1392 == 0u) {
                        if _e1382 {
                            phi_1991_ = (1f - (2f * _e1390));
                        } else {
                            phi_1991_ = _e1390;
                        }
                        let _e1397 = phi_1991_;
                        let _e1407 = frame.member[0u].member_1.member.member_2;
                        let _e1410 = local_10;
                        phi_2020_ = type_42(pow(select(0f, select(1f, _e1397, (_e1397 < 1f)), (_e1397 > 0f)), _e1407), _e1410);
                    } else {
                        let _e1420 = local_11;
                        phi_2020_ = type_42((round((select(0f, select(1f, _e1390, (_e1390 < 1f)), (_e1390 > 0f)) * 255f)) * 0.003921569f), _e1420);
                    }
                    let _e1423 = phi_2020_;
                    phi_2025_ = _e1423;
                } else {
                    phi_2025_ = type_42(1f, 0u);
                }
                let _e1425 = phi_2025_;
                ao.member[_e572] = _e1425.member;
                if (_e572 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e572] = _e1425.member_1;
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
