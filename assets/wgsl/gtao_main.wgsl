struct type_5 {
    member: vec2<f32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_7 {
    member: array<f32>,
}

struct type_10 {
    member: array<u32>,
}

struct type_20 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: u32,
    member_12: u32,
    member_13: u32,
    member_14: u32,
}

struct type_21 {
    member: type_20,
}

struct type_24 {
    member: f32,
    member_1: vec3<f32>,
}

@id(0) override override_type: u32 = 0u;
@id(4) override override_type_1: u32 = 0u;
@id(5) override override_type_2: u32 = 0u;
@id(6) override override_type_3: u32 = 0u;
@id(7) override override_type_4: u32 = 0u;
@id(8) override override_type_5: u32 = 0u;
@id(9) override override_type_6: u32 = 0u;
@id(1) override override_type_7: u32 = 0u;
@id(2) override override_type_8: u32 = 0u;
@id(3) override override_type_9: u32 = 0u;

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(4) 
var<uniform> params: type_21;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_281_: type_20;
    var phi_2455_: bool;
    var phi_2470_: bool;
    var phi_2430_: vec2<f32>;
    var phi_735_: f32;
    var phi_761_: u32;
    var phi_764_: vec3<f32>;
    var phi_766_: f32;
    var phi_934_: u32;
    var phi_937_: f32;
    var phi_939_: f32;
    var phi_989_: f32;
    var phi_1535_: f32;
    var phi_1556_: f32;
    var phi_1595_: f32;
    var phi_1616_: f32;
    var phi_935_: u32;
    var phi_938_: f32;
    var phi_940_: f32;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_1846_: vec3<f32>;
    var phi_762_: u32;
    var phi_765_: vec3<f32>;
    var phi_767_: f32;
    var local_4: f32;
    var local_5: vec3<f32>;
    var phi_1852_: type_24;
    var phi_2699_: bool;
    var phi_1905_: vec3<f32>;
    var phi_1926_: u32;
    var phi_1970_: u32;

    let _e93 = id_1;
    if (override_type == 0u) {
        let _e96 = params.member;
        phi_281_ = _e96;
    } else {
        let _e105 = params.member.member;
        let _e108 = params.member.member_1;
        let _e111 = params.member.member_10;
        let _e114 = params.member.member_11;
        let _e117 = params.member.member_12;
        let _e120 = params.member.member_14;
        phi_281_ = type_20(_e105, _e108, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e111, _e114, _e117, override_type_9, _e120);
    }
    let _e123 = phi_281_;
    let _e131 = select(select(u32(_e123.member.member.x), 0u, (_e123.member.member.x < 0f)), 4294967295u, (_e123.member.member.x > 4294967000f));
    let _e139 = select(select(u32(_e123.member.member.y), 0u, (_e123.member.member.y < 0f)), 4294967295u, (_e123.member.member.y > 4294967000f));
    if (_e93.x >= _e131) {
    } else {
        if (_e93.y >= _e139) {
        } else {
            let _e145 = ((_e93.y * _e131) + _e93.x);
            let _e148 = mips.member[_e145];
            let _e149 = bitcast<i32>(_e93.x);
            let _e150 = (_e149 + -1i);
            let _e152 = select(0i, _e150, (0i < _e150));
            let _e154 = (bitcast<i32>(_e131) - 1i);
            let _e158 = bitcast<i32>(_e93.y);
            let _e160 = select(0i, _e158, (0i < _e158));
            let _e162 = (bitcast<i32>(_e139) - 1i);
            let _e166 = (bitcast<u32>(select(_e160, _e162, (_e162 < _e160))) * _e131);
            let _e170 = mips.member[(_e166 + bitcast<u32>(select(_e152, _e154, (_e154 < _e152))))];
            let _e171 = (_e149 + 1i);
            let _e173 = select(0i, _e171, (0i < _e171));
            let _e180 = mips.member[(_e166 + bitcast<u32>(select(_e173, _e154, (_e154 < _e173))))];
            let _e182 = select(0i, _e149, (0i < _e149));
            let _e185 = bitcast<u32>(select(_e182, _e154, (_e154 < _e182)));
            let _e186 = (_e158 + -1i);
            let _e188 = select(0i, _e186, (0i < _e186));
            let _e196 = mips.member[((bitcast<u32>(select(_e188, _e162, (_e162 < _e188))) * _e131) + _e185)];
            let _e197 = (_e158 + 1i);
            let _e199 = select(0i, _e197, (0i < _e197));
            let _e207 = mips.member[((bitcast<u32>(select(_e199, _e162, (_e162 < _e199))) * _e131) + _e185)];
            let _e208 = (_e170 - _e148);
            let _e209 = (_e180 - _e148);
            let _e210 = (_e196 - _e148);
            let _e211 = (_e207 - _e148);
            let _e213 = ((_e209 - _e208) * 0.5f);
            let _e215 = ((_e211 - _e210) * 0.5f);
            let _e216 = (_e148 * 0.011f);
            let _e218 = abs(_e208);
            let _e219 = abs((_e208 + _e213));
            let _e225 = (1.25f - (select(_e219, _e218, ((_e218 < _e219) || (_e219 != _e219))) / _e216));
            let _e229 = select(0f, select(1f, _e225, (_e225 < 1f)), (_e225 > 0f));
            let _e231 = abs(_e209);
            let _e232 = abs((_e209 - _e213));
            let _e238 = (1.25f - (select(_e232, _e231, ((_e231 < _e232) || (_e232 != _e232))) / _e216));
            let _e242 = select(0f, select(1f, _e238, (_e238 < 1f)), (_e238 > 0f));
            let _e244 = abs(_e210);
            let _e245 = abs((_e210 + _e215));
            let _e251 = (1.25f - (select(_e245, _e244, ((_e244 < _e245) || (_e245 != _e245))) / _e216));
            let _e255 = select(0f, select(1f, _e251, (_e251 < 1f)), (_e251 > 0f));
            let _e257 = abs(_e211);
            let _e258 = abs((_e211 - _e215));
            let _e264 = (1.25f - (select(_e258, _e257, ((_e257 < _e258) || (_e258 != _e258))) / _e216));
            let _e268 = select(0f, select(1f, _e264, (_e264 < 1f)), (_e264 > 0f));
            let _e273 = (select(0f, select(1f, _e229, (_e229 < 1f)), (_e229 > 0f)) * 2.9f);
            let _e275 = floor((_e273 + 0.5f));
            let _e284 = select(_e275, (_e275 - 1f), (((_e275 - _e273) == 0.5f) && ((floor((_e275 * 0.5f)) * 2f) != _e275)));
            let _e286 = select(0f, _e284, (_e284 > 0f));
            let _e295 = (select(0f, select(1f, _e242, (_e242 < 1f)), (_e242 > 0f)) * 2.9f);
            let _e297 = floor((_e295 + 0.5f));
            let _e306 = select(_e297, (_e297 - 1f), (((_e297 - _e295) == 0.5f) && ((floor((_e297 * 0.5f)) * 2f) != _e297)));
            let _e308 = select(0f, _e306, (_e306 > 0f));
            let _e318 = (select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f)) * 2.9f);
            let _e320 = floor((_e318 + 0.5f));
            let _e329 = select(_e320, (_e320 - 1f), (((_e320 - _e318) == 0.5f) && ((floor((_e320 * 0.5f)) * 2f) != _e320)));
            let _e331 = select(0f, _e329, (_e329 > 0f));
            let _e341 = (select(0f, select(1f, _e268, (_e268 < 1f)), (_e268 > 0f)) * 2.9f);
            let _e343 = floor((_e341 + 0.5f));
            let _e352 = select(_e343, (_e343 - 1f), (((_e343 - _e341) == 0.5f) && ((floor((_e343 * 0.5f)) * 2f) != _e343)));
            let _e354 = select(0f, _e352, (_e352 > 0f));
            let _e361 = ((f32(_e93.x) + 0.5f) / _e123.member.member.x);
            let _e364 = ((f32(_e93.y) + 0.5f) / _e123.member.member.y);
            let _e365 = (_e148 * 0.99999f);
            let _e372 = ((((_e361 * 2f) - 1f) * _e123.member.member_1.x) * _e365);
            let _e379 = ((((_e364 * -2f) + 1f) * _e123.member.member_1.y) * _e365);
            let _e380 = -(_e372);
            let _e381 = -(_e379);
            let _e382 = (_e148 * -0.99999f);
            let _e389 = (1f / sqrt((((_e380 * _e380) + (_e381 * _e381)) + (_e382 * _e382))));
            let _e390 = (_e380 * _e389);
            let _e391 = (_e381 * _e389);
            let _e392 = (_e382 * _e389);
            let _e395 = normals.member[_e145];
            let _e403 = (f32((bitcast<i32>(((_e395 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e403 != _e403) {
                phi_2455_ = true;
            } else {
                phi_2455_ = (-1f >= _e403);
            }
            let _e407 = phi_2455_;
            let _e408 = select(_e403, -1f, _e407);
            let _e418 = (f32((bitcast<i32>((((_e395 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e418 != _e418) {
                phi_2470_ = true;
            } else {
                phi_2470_ = (-1f >= _e418);
            }
            let _e422 = phi_2470_;
            let _e423 = select(_e418, -1f, _e422);
            let _e426 = (1f - abs(_e408));
            let _e427 = abs(_e423);
            let _e428 = (_e426 - _e427);
            if (_e428 < 0f) {
                phi_2430_ = vec2<f32>(((1f - _e427) * select(1f, -1f, (_e408 < 0f))), (_e426 * select(1f, -1f, (_e423 < 0f))));
            } else {
                phi_2430_ = vec2<f32>(_e408, _e423);
            }
            let _e439 = phi_2430_;
            let _e448 = (1f / sqrt((((_e439.x * _e439.x) + (_e439.y * _e439.y)) + (_e428 * _e428))));
            let _e449 = (_e439.x * _e448);
            let _e450 = (_e439.y * _e448);
            let _e451 = (_e428 * _e448);
            let _e452 = -(_e451);
            let _e458 = ((((_e449 * _e390) + (_e450 * _e391)) + (_e452 * _e392)) < 0f);
            let _e461 = select(_e449, -(_e449), _e458);
            let _e462 = select(_e450, -(_e450), _e458);
            let _e463 = select(_e452, _e451, _e458);
            let _e467 = (_e123.member_1 * _e123.member_2);
            let _e471 = (_e467 / (((_e148 * 1.99998f) * _e123.member.member_1.x) / _e123.member.member.x));
            let _e474 = (_e93.x & 63u);
            let _e475 = (_e93.y & 63u);
            let _e478 = select(0u, 1u, ((_e474 & 32u) != 0u));
            let _e481 = select(0u, 1u, ((_e475 & 32u) != 0u));
            let _e485 = (_e481 == 0u);
            let _e487 = (_e485 && (_e478 == 1u));
            let _e490 = select(_e474, (63u - _e474), _e487);
            let _e491 = select(_e475, (63u - _e475), _e487);
            let _e492 = select(_e490, _e491, _e485);
            let _e493 = select(_e491, _e490, _e485);
            let _e496 = select(0u, 1u, ((_e492 & 16u) != 0u));
            let _e499 = select(0u, 1u, ((_e493 & 16u) != 0u));
            let _e504 = (_e499 == 0u);
            let _e506 = (_e504 && (_e496 == 1u));
            let _e509 = select(_e492, (63u - _e492), _e506);
            let _e510 = select(_e493, (63u - _e493), _e506);
            let _e511 = select(_e509, _e510, _e504);
            let _e512 = select(_e510, _e509, _e504);
            let _e515 = select(0u, 1u, ((_e511 & 8u) != 0u));
            let _e518 = select(0u, 1u, ((_e512 & 8u) != 0u));
            let _e523 = (_e518 == 0u);
            let _e525 = (_e523 && (_e515 == 1u));
            let _e528 = select(_e511, (63u - _e511), _e525);
            let _e529 = select(_e512, (63u - _e512), _e525);
            let _e530 = select(_e528, _e529, _e523);
            let _e531 = select(_e529, _e528, _e523);
            let _e534 = select(0u, 1u, ((_e530 & 4u) != 0u));
            let _e537 = select(0u, 1u, ((_e531 & 4u) != 0u));
            let _e542 = (_e537 == 0u);
            let _e544 = (_e542 && (_e534 == 1u));
            let _e547 = select(_e530, (63u - _e530), _e544);
            let _e548 = select(_e531, (63u - _e531), _e544);
            let _e549 = select(_e547, _e548, _e542);
            let _e550 = select(_e548, _e547, _e542);
            let _e553 = select(0u, 1u, ((_e549 & 2u) != 0u));
            let _e556 = select(0u, 1u, ((_e550 & 2u) != 0u));
            let _e561 = (_e556 == 0u);
            let _e563 = (_e561 && (_e553 == 1u));
            let _e566 = select(_e549, (63u - _e549), _e563);
            let _e567 = select(_e550, (63u - _e550), _e563);
            let _e582 = f32((((((((1024u * ((3u * _e478) ^ _e481)) + (256u * ((3u * _e496) ^ _e499))) + (64u * ((3u * _e515) ^ _e518))) + (16u * ((3u * _e534) ^ _e537))) + (4u * ((3u * _e553) ^ _e556))) + ((3u * select(0u, 1u, ((select(_e566, _e567, _e561) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e567, _e566, _e561) & 1u) != 0u)))) + (288u * (_e123.member_11 % 64u))));
            let _e584 = (0.5f + (_e582 * 0.7548777f));
            let _e588 = (0.5f + (_e582 * 0.5698403f));
            let _e595 = select(false, (_e148 < _e123.member.member_3), (_e148 > 0f));
            if _e595 {
                let _e597 = (_e123.member_3 * _e467);
                let _e598 = (_e597 <= 0f);
                if _e598 {
                    phi_735_ = 0f;
                } else {
                    phi_735_ = (1f / _e597);
                }
                let _e601 = phi_735_;
                let _e602 = -(_e601);
                let _e603 = (_e467 * _e601);
                let _e605 = ((10f - _e471) * 0.01f);
                let _e613 = select(1u, _e123.member_8, (1u < _e123.member_8));
                phi_761_ = 0u;
                phi_764_ = vec3<f32>(0f, 0f, 0f);
                phi_766_ = (select(0f, select(1f, _e605, (_e605 < 1f)), (_e605 > 0f)) * 0.5f);
                loop {
                    let _e615 = phi_761_;
                    let _e617 = phi_764_;
                    let _e619 = phi_766_;
                    local_4 = _e619;
                    local_5 = _e617;
                    let _e620 = (_e615 < _e613);
                    if _e620 {
                        let _e625 = ((((_e584 - floor(_e584)) + f32(_e615)) * 3.1415927f) / f32(_e613));
                        let _e626 = sin(_e625);
                        let _e627 = cos(_e625);
                        let _e633 = ((_e627 * _e390) + (_e626 * _e391));
                        let _e637 = (_e627 - (_e390 * _e633));
                        let _e638 = (_e626 - (_e391 * _e633));
                        let _e639 = -((_e392 * _e633));
                        let _e642 = ((_e638 * _e392) - (_e391 * _e639));
                        let _e645 = ((_e639 * _e390) - (_e392 * _e637));
                        let _e648 = ((_e637 * _e391) - (_e390 * _e638));
                        let _e655 = (1f / sqrt((((_e642 * _e642) + (_e645 * _e645)) + (_e648 * _e648))));
                        let _e656 = (_e642 * _e655);
                        let _e657 = (_e645 * _e655);
                        let _e658 = (_e648 * _e655);
                        let _e663 = (((_e461 * _e656) + (_e462 * _e657)) + (_e463 * _e658));
                        let _e667 = (_e461 - (_e656 * _e663));
                        let _e668 = (_e462 - (_e657 * _e663));
                        let _e669 = (_e463 - (_e658 * _e663));
                        let _e675 = sqrt((((_e667 * _e667) + (_e668 * _e668)) + (_e669 * _e669)));
                        let _e680 = (((_e637 * _e667) + (_e638 * _e668)) + (_e639 * _e669));
                        let _e690 = ((((_e667 * _e390) + (_e668 * _e391)) + (_e669 * _e392)) / _e675);
                        let _e694 = select(0f, select(1f, _e690, (_e690 < 1f)), (_e690 > 0f));
                        let _e695 = abs(_e694);
                        let _e706 = (((_e695 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e695))) >> bitcast<u32>(1i))))));
                        let _e710 = (select(select(0f, -1f, (_e680 < 0f)), 1f, (_e680 > 0f)) * select((3.141593f - _e706), _e706, (_e694 >= 0f)));
                        let _e713 = select(1u, _e123.member_9, (1u < _e123.member_9));
                        let _e715 = cos((_e710 + 1.5707964f));
                        let _e717 = cos((_e710 - 1.5707964f));
                        phi_934_ = 0u;
                        phi_937_ = _e717;
                        phi_939_ = _e715;
                        loop {
                            let _e720 = phi_934_;
                            let _e722 = phi_937_;
                            let _e724 = phi_939_;
                            local = _e722;
                            local_1 = _e722;
                            local_2 = _e724;
                            local_3 = _e724;
                            let _e725 = (_e720 < _e713);
                            if _e725 {
                                let _e730 = ((_e588 - floor(_e588)) + (f32((_e615 + (_e720 * _e713))) * 0.618034f));
                                let _e737 = (((_e730 - floor(_e730)) + f32(_e720)) * (1f / f32(_e713)));
                                if (_e123.member_4 == 2f) {
                                    phi_989_ = (_e737 * _e737);
                                } else {
                                    phi_989_ = pow(_e737, _e123.member_4);
                                }
                                let _e743 = phi_989_;
                                let _e744 = (_e743 + (1.3f / _e471));
                                let _e745 = ((_e627 * _e471) * _e744);
                                let _e746 = ((-(_e626) * _e471) * _e744);
                                let _e753 = (log2(sqrt(((_e745 * _e745) + (_e746 * _e746)))) - _e123.member_7);
                                let _e760 = (-1f - floor((-0.5f - select(0f, select(5f, _e753, (_e753 < 5f)), (_e753 > 0f)))));
                                let _e762 = floor((_e745 + 0.5f));
                                let _e773 = (select(_e762, (_e762 - 1f), (((_e762 - _e745) == 0.5f) && ((floor((_e762 * 0.5f)) * 2f) != _e762))) * (1f / _e123.member.member.x));
                                let _e775 = floor((_e746 + 0.5f));
                                let _e786 = (select(_e775, (_e775 - 1f), (((_e775 - _e746) == 0.5f) && ((floor((_e775 * 0.5f)) * 2f) != _e775))) * (1f / _e123.member.member.y));
                                let _e787 = (_e361 + _e773);
                                let _e788 = (_e364 + _e786);
                                let _e789 = (_e361 - _e773);
                                let _e790 = (_e364 - _e786);
                                let _e792 = select(1u, _e131, (1u < _e131));
                                let _e794 = select(1u, _e139, (1u < _e139));
                                let _e797 = (_e792 * _e794);
                                let _e799 = (_e131 >> bitcast<u32>(1u));
                                let _e801 = select(1u, _e799, (1u < _e799));
                                let _e803 = (_e139 >> bitcast<u32>(1u));
                                let _e805 = select(1u, _e803, (1u < _e803));
                                let _e806 = (_e760 >= 1f);
                                let _e815 = (_e797 + (_e801 * _e805));
                                let _e817 = (_e131 >> bitcast<u32>(2u));
                                let _e819 = select(1u, _e817, (1u < _e817));
                                let _e821 = (_e139 >> bitcast<u32>(2u));
                                let _e823 = select(1u, _e821, (1u < _e821));
                                let _e824 = (_e760 >= 2f);
                                let _e833 = (_e815 + (_e819 * _e823));
                                let _e835 = (_e131 >> bitcast<u32>(3u));
                                let _e837 = select(1u, _e835, (1u < _e835));
                                let _e839 = (_e139 >> bitcast<u32>(3u));
                                let _e841 = select(1u, _e839, (1u < _e839));
                                let _e842 = (_e760 >= 3f);
                                let _e853 = (_e131 >> bitcast<u32>(4u));
                                let _e855 = select(1u, _e853, (1u < _e853));
                                let _e857 = (_e139 >> bitcast<u32>(4u));
                                let _e859 = select(1u, _e857, (1u < _e857));
                                let _e860 = (_e760 >= 4f);
                                let _e861 = select(select(select(select(_e792, _e801, _e806), _e819, _e824), _e837, _e842), _e855, _e860);
                                let _e863 = select(select(select(select(0u, _e797, _e806), _e815, _e824), _e833, _e842), (_e833 + (_e837 * _e841)), _e860);
                                let _e865 = select(select(select(select(f32(_e792), f32(_e801), _e806), f32(_e819), _e824), f32(_e837), _e842), f32(_e855), _e860);
                                let _e867 = select(select(select(select(f32(_e794), f32(_e805), _e806), f32(_e823), _e824), f32(_e841), _e842), f32(_e859), _e860);
                                let _e868 = (_e787 * _e865);
                                let _e870 = f32((_e861 - 1u));
                                let _e872 = select(0f, _e868, (_e868 > 0f));
                                let _e876 = (_e788 * _e867);
                                let _e878 = f32((select(select(select(select(_e794, _e805, _e806), _e823, _e824), _e841, _e842), _e859, _e860) - 1u));
                                let _e880 = select(0f, _e876, (_e876 > 0f));
                                let _e889 = mips.member[((_e863 + (u32(select(_e878, _e880, (_e880 < _e878))) * _e861)) + u32(select(_e870, _e872, (_e872 < _e870))))];
                                let _e898 = (_e789 * _e865);
                                let _e900 = select(0f, _e898, (_e898 > 0f));
                                let _e904 = (_e790 * _e867);
                                let _e906 = select(0f, _e904, (_e904 > 0f));
                                let _e915 = mips.member[((_e863 + (u32(select(_e878, _e906, (_e906 < _e878))) * _e861)) + u32(select(_e870, _e900, (_e900 < _e870))))];
                                let _e924 = (((((_e787 * 2f) - 1f) * _e123.member.member_1.x) * _e889) - _e372);
                                let _e925 = (((((_e788 * -2f) + 1f) * _e123.member.member_1.y) * _e889) - _e379);
                                let _e926 = (_e889 - _e365);
                                let _e929 = ((_e924 * _e924) + (_e925 * _e925));
                                let _e932 = sqrt((_e929 + (_e926 * _e926)));
                                let _e939 = (_e123.member_5 == 0f);
                                if _e939 {
                                    phi_1535_ = _e932;
                                } else {
                                    let _e941 = (_e926 * (1f + _e123.member_5));
                                    phi_1535_ = sqrt((_e929 + (_e941 * _e941)));
                                }
                                let _e946 = phi_1535_;
                                if _e598 {
                                    phi_1556_ = select(0f, 1f, (_e946 <= _e467));
                                } else {
                                    let _e950 = ((_e946 * _e602) + _e603);
                                    phi_1556_ = select(0f, select(1f, _e950, (_e950 < 1f)), (_e950 > 0f));
                                }
                                let _e956 = phi_1556_;
                                let _e959 = (_e715 + ((((((_e924 * _e390) + (_e925 * _e391)) + (_e926 * _e392)) / _e932) - _e715) * _e956));
                                let _e960 = (((((_e789 * 2f) - 1f) * _e123.member.member_1.x) * _e915) - _e372);
                                let _e961 = (((((_e790 * -2f) + 1f) * _e123.member.member_1.y) * _e915) - _e379);
                                let _e962 = (_e915 - _e365);
                                let _e965 = ((_e960 * _e960) + (_e961 * _e961));
                                let _e968 = sqrt((_e965 + (_e962 * _e962)));
                                if _e939 {
                                    phi_1595_ = _e968;
                                } else {
                                    let _e976 = (_e962 * (1f + _e123.member_5));
                                    phi_1595_ = sqrt((_e965 + (_e976 * _e976)));
                                }
                                let _e981 = phi_1595_;
                                if _e598 {
                                    phi_1616_ = select(0f, 1f, (_e981 <= _e467));
                                } else {
                                    let _e985 = ((_e981 * _e602) + _e603);
                                    phi_1616_ = select(0f, select(1f, _e985, (_e985 < 1f)), (_e985 > 0f));
                                }
                                let _e991 = phi_1616_;
                                let _e994 = (_e717 + ((((((_e960 * _e390) + (_e961 * _e391)) + (_e962 * _e392)) / _e968) - _e717) * _e991));
                                phi_935_ = (_e720 + 1u);
                                phi_938_ = select(_e994, _e722, ((_e722 > _e994) || (_e994 != _e994)));
                                phi_940_ = select(_e959, _e724, ((_e724 > _e959) || (_e959 != _e959)));
                            } else {
                                phi_935_ = u32();
                                phi_938_ = f32();
                                phi_940_ = f32();
                            }
                            let _e1005 = phi_935_;
                            let _e1007 = phi_938_;
                            let _e1009 = phi_940_;
                            continue;
                            continuing {
                                phi_934_ = _e1005;
                                phi_937_ = _e1007;
                                phi_939_ = _e1009;
                                break if !(_e725);
                            }
                        }
                        let _e1012 = local;
                        let _e1013 = abs(_e1012);
                        let _e1024 = (((_e1013 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1013))) >> bitcast<u32>(1i))))));
                        let _e1026 = local_1;
                        let _e1029 = select((3.141593f - _e1024), _e1024, (_e1026 >= 0f));
                        let _e1030 = -(_e1029);
                        let _e1032 = local_2;
                        let _e1033 = abs(_e1032);
                        let _e1044 = (((_e1033 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1033))) >> bitcast<u32>(1i))))));
                        let _e1046 = local_3;
                        let _e1049 = select((3.141593f - _e1044), _e1044, (_e1046 >= 0f));
                        let _e1052 = (_e675 + ((1f - _e675) * 0.05f));
                        let _e1053 = (_e1029 * -2f);
                        let _e1054 = sin(_e710);
                        let _e1060 = (_e1049 * 2f);
                        if (_e123.member_13 == 0u) {
                            phi_1846_ = _e617;
                        } else {
                            let _e1076 = ((_e1029 * -3f) - _e710);
                            let _e1084 = ((_e1049 * 3f) - _e710);
                            let _e1089 = (_e1030 + _e710);
                            let _e1091 = (_e1049 + _e710);
                            let _e1096 = (((((((sin((_e1030 - _e710)) * 6f) - sin(_e1076)) + (sin((_e1049 - _e710)) * 6f)) - sin(_e1084)) + (_e1054 * 16f)) - ((sin(_e1089) + sin(_e1091)) * 3f)) * 0.083333336f);
                            let _e1108 = (((-(cos(_e1076)) - cos(_e1084)) + (cos(_e710) * 8f)) - ((cos(_e1089) + cos(_e1091)) * 3f));
                            let _e1109 = (_e627 * _e1096);
                            let _e1110 = (_e626 * _e1096);
                            let _e1111 = (_e1108 * -0.083333336f);
                            let _e1112 = (-1f * _e392);
                            let _e1113 = (-1f * _e390);
                            let _e1115 = (1f / (_e1112 + 1f));
                            let _e1116 = (_e1115 * _e391);
                            let _e1120 = (_e1116 * _e1113);
                            let _e1141 = (_e1112 > 0.9997f);
                            let _e1142 = (_e1112 < -0.9997f);
                            phi_1846_ = (_e617 + vec3<f32>((select(select(((((_e1112 + (_e1116 * _e391)) * _e1109) + (_e1120 * _e1110)) + (_e1113 * _e1111)), _e1109, _e1142), _e1109, _e1141) * _e1052), (select(select((((_e1120 * _e1109) + ((_e1112 + ((_e1115 * _e1113) * _e1113)) * _e1110)) + (-(_e391) * _e1111)), -(_e1110), _e1142), _e1110, _e1141) * _e1052), (select(select((((_e390 * _e1109) + (_e391 * _e1110)) + (_e1112 * _e1111)), (_e1108 * 0.083333336f), _e1142), _e1111, _e1141) * _e1052)));
                        }
                        let _e1155 = phi_1846_;
                        phi_762_ = (_e615 + 1u);
                        phi_765_ = _e1155;
                        phi_767_ = (_e619 + ((0.25f * (((_e694 + (_e1053 * _e1054)) - cos((_e1053 - _e710))) + ((_e694 + (_e1060 * _e1054)) - cos((_e1060 - _e710))))) * _e1052));
                    } else {
                        phi_762_ = u32();
                        phi_765_ = vec3<f32>();
                        phi_767_ = f32();
                    }
                    let _e1158 = phi_762_;
                    let _e1160 = phi_765_;
                    let _e1162 = phi_767_;
                    continue;
                    continuing {
                        phi_761_ = _e1158;
                        phi_764_ = _e1160;
                        phi_766_ = _e1162;
                        break if !(_e620);
                    }
                }
                let _e1166 = local_4;
                let _e1169 = local_5;
                phi_1852_ = type_24((_e1166 / f32(_e613)), _e1169);
            } else {
                phi_1852_ = type_24(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1172 = phi_1852_;
            if _e595 {
                let _e1176 = pow(_e1172.member, _e123.member_6);
                if (_e1176 != _e1176) {
                    phi_2699_ = true;
                } else {
                    phi_2699_ = (0.03f >= _e1176);
                }
                let _e1180 = phi_2699_;
                let _e1181 = select(_e1176, 0.03f, _e1180);
                if (_e123.member_13 == 0u) {
                    let _e1184 = (_e1181 * 0.6666667f);
                    let _e1190 = ((select(0f, select(1f, _e1184, (_e1184 < 1f)), (_e1184 > 0f)) * 255f) + 0.5f);
                    phi_1926_ = select(select(u32(_e1190), 0u, (_e1190 < 0f)), 4294967295u, (_e1190 > 4294967000f));
                } else {
                    let _e1204 = sqrt((((_e1172.member_1.x * _e1172.member_1.x) + (_e1172.member_1.y * _e1172.member_1.y)) + (_e1172.member_1.z * _e1172.member_1.z)));
                    if (_e1204 > 0f) {
                        phi_1905_ = (_e1172.member_1 / vec3(_e1204));
                    } else {
                        phi_1905_ = vec3<f32>(_e461, _e462, _e463);
                    }
                    let _e1209 = phi_1905_;
                    let _e1210 = (_e1181 * 0.6666667f);
                    let _e1217 = ((_e1209.x * 0.5f) + 0.5f);
                    let _e1218 = ((_e1209.y * 0.5f) + 0.5f);
                    let _e1219 = ((_e1209.z * 0.5f) + 0.5f);
                    let _e1225 = ((select(0f, select(1f, _e1217, (_e1217 < 1f)), (_e1217 > 0f)) * 255f) + 0.5f);
                    let _e1236 = ((select(0f, select(1f, _e1218, (_e1218 < 1f)), (_e1218 > 0f)) * 255f) + 0.5f);
                    let _e1250 = ((select(0f, select(1f, _e1219, (_e1219 < 1f)), (_e1219 > 0f)) * 255f) + 0.5f);
                    let _e1264 = ((select(0f, select(1f, _e1210, (_e1210 < 1f)), (_e1210 > 0f)) * 255f) + 0.5f);
                    phi_1926_ = (((select(select(u32(_e1225), 0u, (_e1225 < 0f)), 4294967295u, (_e1225 > 4294967000f)) | (select(select(u32(_e1236), 0u, (_e1236 < 0f)), 4294967295u, (_e1236 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1250), 0u, (_e1250 < 0f)), 4294967295u, (_e1250 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1264), 0u, (_e1264 < 0f)), 4294967295u, (_e1264 > 4294967000f)) << bitcast<u32>(24i)));
                }
                let _e1274 = phi_1926_;
                phi_1970_ = _e1274;
            } else {
                phi_1970_ = select(2852159616u, 170u, (_e123.member_13 == 0u));
            }
            let _e1279 = phi_1970_;
            terms.member[_e145] = _e1279;
            edges.member[_e145] = ((((64u * u32(select(3f, _e286, (_e286 < 3f)))) + (16u * u32(select(3f, _e308, (_e308 < 3f))))) + (4u * u32(select(3f, _e331, (_e331 < 3f))))) + u32(select(3f, _e354, (_e354 < 3f))));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
