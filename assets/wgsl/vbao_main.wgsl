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

struct type_21 {
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

struct type_23 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
}

struct type_24 {
    member: type_23,
}

struct type_26 {
    member: u32,
    member_1: f32,
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
@id(10) override override_type_10: u32 = 0u;
@id(11) override override_type_11: u32 = 0u;

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;
@group(0) @binding(4) 
var<uniform> params: type_24;

fn function_() {
    var local: array<type_26, 4>;
    var phi_528_: type_21;
    var phi_535_: u32;
    var phi_542_: u32;
    var phi_3064_: bool;
    var phi_3079_: bool;
    var phi_3040_: vec2<f32>;
    var phi_3491_: bool;
    var phi_999_: u32;
    var phi_1002_: f32;
    var phi_1004_: f32;
    var phi_1195_: u32;
    var phi_1198_: u32;
    var phi_1248_: f32;
    var phi_1777_: bool;
    var phi_2124_: f32;
    var phi_2166_: u32;
    var phi_2169_: u32;
    var phi_2170_: u32;
    var phi_2171_: bool;
    var phi_2185_: u32;
    var phi_2205_: bool;
    var phi_2552_: f32;
    var phi_2594_: u32;
    var phi_2597_: u32;
    var phi_2598_: u32;
    var phi_2599_: bool;
    var phi_2613_: u32;
    var phi_1196_: u32;
    var phi_1199_: u32;
    var local_1: u32;
    var phi_2693_: u32;
    var phi_2696_: f32;
    var local_2: u32;
    var phi_2694_: u32;
    var phi_2697_: f32;
    var phi_3340_: bool;
    var local_3: f32;
    var phi_3587_: bool;
    var phi_2746_: f32;
    var phi_2747_: f32;
    var phi_2642_: u32;
    var phi_2645_: f32;
    var phi_2647_: f32;
    var local_4: u32;
    var phi_2643_: u32;
    var phi_2646_: f32;
    var phi_2648_: f32;
    var local_5: f32;
    var phi_3581_: bool;
    var phi_2748_: f32;
    var phi_2749_: f32;
    var phi_3580_: bool;
    var phi_1000_: u32;
    var phi_1003_: f32;
    var phi_1005_: f32;
    var phi_3579_: bool;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var phi_2757_: f32;
    var phi_3314_: bool;
    var phi_2804_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e108 = id_1;
            let _e111 = (override_type == 0u);
            if _e111 {
                let _e143 = params.member.member_4;
                phi_528_ = _e143;
            } else {
                let _e121 = params.member.member_4.member;
                let _e125 = params.member.member_4.member_1;
                let _e129 = params.member.member_4.member_10;
                let _e133 = params.member.member_4.member_11;
                let _e137 = params.member.member_4.member_12;
                let _e141 = params.member.member_4.member_14;
                phi_528_ = type_21(_e121, _e125, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e129, _e133, _e137, override_type_9, _e141);
            }
            let _e145 = phi_528_;
            if _e111 {
                let _e148 = params.member.member_2;
                phi_535_ = _e148;
            } else {
                phi_535_ = override_type_10;
            }
            let _e150 = phi_535_;
            if _e111 {
                let _e153 = params.member.member_3;
                phi_542_ = _e153;
            } else {
                phi_542_ = override_type_11;
            }
            let _e155 = phi_542_;
            let _e158 = params.member.member;
            let _e161 = params.member.member_1;
            let _e169 = select(select(u32(_e145.member.member.x), 0u, (_e145.member.member.x < 0f)), 4294967295u, (_e145.member.member.x > 4294967000f));
            let _e177 = select(select(u32(_e145.member.member.y), 0u, (_e145.member.member.y < 0f)), 4294967295u, (_e145.member.member.y > 4294967000f));
            if (_e108.x >= _e169) {
            } else {
                if (_e108.y >= _e177) {
                } else {
                    let _e183 = ((_e108.y * _e169) + _e108.x);
                    let _e186 = mips.member[_e183];
                    let _e187 = bitcast<i32>(_e108.x);
                    let _e188 = (_e187 + -1i);
                    let _e190 = select(0i, _e188, (0i < _e188));
                    let _e192 = (bitcast<i32>(_e169) - 1i);
                    let _e196 = bitcast<i32>(_e108.y);
                    let _e198 = select(0i, _e196, (0i < _e196));
                    let _e200 = (bitcast<i32>(_e177) - 1i);
                    let _e204 = (bitcast<u32>(select(_e198, _e200, (_e200 < _e198))) * _e169);
                    let _e208 = mips.member[(_e204 + bitcast<u32>(select(_e190, _e192, (_e192 < _e190))))];
                    let _e209 = (_e187 + 1i);
                    let _e211 = select(0i, _e209, (0i < _e209));
                    let _e218 = mips.member[(_e204 + bitcast<u32>(select(_e211, _e192, (_e192 < _e211))))];
                    let _e220 = select(0i, _e187, (0i < _e187));
                    let _e223 = bitcast<u32>(select(_e220, _e192, (_e192 < _e220)));
                    let _e224 = (_e196 + -1i);
                    let _e226 = select(0i, _e224, (0i < _e224));
                    let _e234 = mips.member[((bitcast<u32>(select(_e226, _e200, (_e200 < _e226))) * _e169) + _e223)];
                    let _e235 = (_e196 + 1i);
                    let _e237 = select(0i, _e235, (0i < _e235));
                    let _e245 = mips.member[((bitcast<u32>(select(_e237, _e200, (_e200 < _e237))) * _e169) + _e223)];
                    let _e246 = (_e208 - _e186);
                    let _e247 = (_e218 - _e186);
                    let _e248 = (_e234 - _e186);
                    let _e249 = (_e245 - _e186);
                    let _e251 = ((_e247 - _e246) * 0.5f);
                    let _e253 = ((_e249 - _e248) * 0.5f);
                    let _e254 = (_e186 * 0.011f);
                    let _e256 = abs(_e246);
                    let _e257 = abs((_e246 + _e251));
                    let _e263 = (1.25f - (select(_e257, _e256, ((_e256 < _e257) || (_e257 != _e257))) / _e254));
                    let _e267 = select(0f, select(1f, _e263, (_e263 < 1f)), (_e263 > 0f));
                    let _e269 = abs(_e247);
                    let _e270 = abs((_e247 - _e251));
                    let _e276 = (1.25f - (select(_e270, _e269, ((_e269 < _e270) || (_e270 != _e270))) / _e254));
                    let _e280 = select(0f, select(1f, _e276, (_e276 < 1f)), (_e276 > 0f));
                    let _e282 = abs(_e248);
                    let _e283 = abs((_e248 + _e253));
                    let _e289 = (1.25f - (select(_e283, _e282, ((_e282 < _e283) || (_e283 != _e283))) / _e254));
                    let _e293 = select(0f, select(1f, _e289, (_e289 < 1f)), (_e289 > 0f));
                    let _e295 = abs(_e249);
                    let _e296 = abs((_e249 - _e253));
                    let _e302 = (1.25f - (select(_e296, _e295, ((_e295 < _e296) || (_e296 != _e296))) / _e254));
                    let _e306 = select(0f, select(1f, _e302, (_e302 < 1f)), (_e302 > 0f));
                    let _e311 = (select(0f, select(1f, _e267, (_e267 < 1f)), (_e267 > 0f)) * 2.9f);
                    let _e313 = floor((_e311 + 0.5f));
                    let _e322 = select(_e313, (_e313 - 1f), (((_e313 - _e311) == 0.5f) && ((floor((_e313 * 0.5f)) * 2f) != _e313)));
                    let _e324 = select(0f, _e322, (_e322 > 0f));
                    let _e333 = (select(0f, select(1f, _e280, (_e280 < 1f)), (_e280 > 0f)) * 2.9f);
                    let _e335 = floor((_e333 + 0.5f));
                    let _e344 = select(_e335, (_e335 - 1f), (((_e335 - _e333) == 0.5f) && ((floor((_e335 * 0.5f)) * 2f) != _e335)));
                    let _e346 = select(0f, _e344, (_e344 > 0f));
                    let _e356 = (select(0f, select(1f, _e293, (_e293 < 1f)), (_e293 > 0f)) * 2.9f);
                    let _e358 = floor((_e356 + 0.5f));
                    let _e367 = select(_e358, (_e358 - 1f), (((_e358 - _e356) == 0.5f) && ((floor((_e358 * 0.5f)) * 2f) != _e358)));
                    let _e369 = select(0f, _e367, (_e367 > 0f));
                    let _e379 = (select(0f, select(1f, _e306, (_e306 < 1f)), (_e306 > 0f)) * 2.9f);
                    let _e381 = floor((_e379 + 0.5f));
                    let _e390 = select(_e381, (_e381 - 1f), (((_e381 - _e379) == 0.5f) && ((floor((_e381 * 0.5f)) * 2f) != _e381)));
                    let _e392 = select(0f, _e390, (_e390 > 0f));
                    let _e399 = ((f32(_e108.x) + 0.5f) / _e145.member.member.x);
                    let _e402 = ((f32(_e108.y) + 0.5f) / _e145.member.member.y);
                    let _e403 = (_e186 * 0.99999f);
                    let _e410 = ((((_e399 * 2f) - 1f) * _e145.member.member_1.x) * _e403);
                    let _e417 = ((((_e402 * -2f) + 1f) * _e145.member.member_1.y) * _e403);
                    let _e418 = -(_e410);
                    let _e419 = -(_e417);
                    let _e420 = (_e186 * -0.99999f);
                    let _e427 = (1f / sqrt((((_e418 * _e418) + (_e419 * _e419)) + (_e420 * _e420))));
                    let _e428 = (_e418 * _e427);
                    let _e429 = (_e419 * _e427);
                    let _e430 = (_e420 * _e427);
                    let _e433 = normals.member[_e183];
                    let _e441 = (f32((bitcast<i32>(((_e433 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e441 != _e441) {
                        phi_3064_ = true;
                    } else {
                        phi_3064_ = (-1f >= _e441);
                    }
                    let _e445 = phi_3064_;
                    let _e446 = select(_e441, -1f, _e445);
                    let _e456 = (f32((bitcast<i32>((((_e433 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e456 != _e456) {
                        phi_3079_ = true;
                    } else {
                        phi_3079_ = (-1f >= _e456);
                    }
                    let _e460 = phi_3079_;
                    let _e461 = select(_e456, -1f, _e460);
                    let _e464 = (1f - abs(_e446));
                    let _e465 = abs(_e461);
                    let _e466 = (_e464 - _e465);
                    if (_e466 < 0f) {
                        phi_3040_ = vec2<f32>(((1f - _e465) * select(1f, -1f, (_e446 < 0f))), (_e464 * select(1f, -1f, (_e461 < 0f))));
                    } else {
                        phi_3040_ = vec2<f32>(_e446, _e461);
                    }
                    let _e477 = phi_3040_;
                    let _e486 = (1f / sqrt((((_e477.x * _e477.x) + (_e477.y * _e477.y)) + (_e466 * _e466))));
                    let _e487 = (_e477.x * _e486);
                    let _e488 = (_e477.y * _e486);
                    let _e489 = (_e466 * _e486);
                    let _e490 = -(_e489);
                    let _e496 = ((((_e487 * _e428) + (_e488 * _e429)) + (_e490 * _e430)) < 0f);
                    let _e499 = select(_e487, -(_e487), _e496);
                    let _e500 = select(_e488, -(_e488), _e496);
                    let _e501 = select(_e490, _e489, _e496);
                    let _e508 = ((_e145.member_1 * _e145.member_2) / (((_e186 * 1.99998f) * _e145.member.member_1.x) / _e145.member.member.x));
                    let _e511 = (_e108.x & 63u);
                    let _e512 = (_e108.y & 63u);
                    let _e515 = select(0u, 1u, ((_e511 & 32u) != 0u));
                    let _e518 = select(0u, 1u, ((_e512 & 32u) != 0u));
                    let _e522 = (_e518 == 0u);
                    let _e524 = (_e522 && (_e515 == 1u));
                    let _e527 = select(_e511, (63u - _e511), _e524);
                    let _e528 = select(_e512, (63u - _e512), _e524);
                    let _e529 = select(_e527, _e528, _e522);
                    let _e530 = select(_e528, _e527, _e522);
                    let _e533 = select(0u, 1u, ((_e529 & 16u) != 0u));
                    let _e536 = select(0u, 1u, ((_e530 & 16u) != 0u));
                    let _e541 = (_e536 == 0u);
                    let _e543 = (_e541 && (_e533 == 1u));
                    let _e546 = select(_e529, (63u - _e529), _e543);
                    let _e547 = select(_e530, (63u - _e530), _e543);
                    let _e548 = select(_e546, _e547, _e541);
                    let _e549 = select(_e547, _e546, _e541);
                    let _e552 = select(0u, 1u, ((_e548 & 8u) != 0u));
                    let _e555 = select(0u, 1u, ((_e549 & 8u) != 0u));
                    let _e560 = (_e555 == 0u);
                    let _e562 = (_e560 && (_e552 == 1u));
                    let _e565 = select(_e548, (63u - _e548), _e562);
                    let _e566 = select(_e549, (63u - _e549), _e562);
                    let _e567 = select(_e565, _e566, _e560);
                    let _e568 = select(_e566, _e565, _e560);
                    let _e571 = select(0u, 1u, ((_e567 & 4u) != 0u));
                    let _e574 = select(0u, 1u, ((_e568 & 4u) != 0u));
                    let _e579 = (_e574 == 0u);
                    let _e581 = (_e579 && (_e571 == 1u));
                    let _e584 = select(_e567, (63u - _e567), _e581);
                    let _e585 = select(_e568, (63u - _e568), _e581);
                    let _e586 = select(_e584, _e585, _e579);
                    let _e587 = select(_e585, _e584, _e579);
                    let _e590 = select(0u, 1u, ((_e586 & 2u) != 0u));
                    let _e593 = select(0u, 1u, ((_e587 & 2u) != 0u));
                    let _e598 = (_e593 == 0u);
                    let _e600 = (_e598 && (_e590 == 1u));
                    let _e603 = select(_e586, (63u - _e586), _e600);
                    let _e604 = select(_e587, (63u - _e587), _e600);
                    let _e619 = f32((((((((1024u * ((3u * _e515) ^ _e518)) + (256u * ((3u * _e533) ^ _e536))) + (64u * ((3u * _e552) ^ _e555))) + (16u * ((3u * _e571) ^ _e574))) + (4u * ((3u * _e590) ^ _e593))) + ((3u * select(0u, 1u, ((select(_e603, _e604, _e598) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e604, _e603, _e598) & 1u) != 0u)))) + (288u * (_e145.member_11 % 64u))));
                    let _e621 = (0.5f + (_e619 * 0.7548777f));
                    let _e625 = (0.5f + (_e619 * 0.5698403f));
                    let _e632 = select(false, (_e186 < _e145.member.member_3), (_e186 > 0f));
                    if _e632 {
                        let _e635 = select(1u, _e145.member_8, (1u < _e145.member_8));
                        phi_3491_ = false;
                        phi_999_ = 0u;
                        phi_1002_ = 0f;
                        phi_1004_ = 0f;
                        loop {
                            let _e637 = phi_3491_;
                            let _e639 = phi_999_;
                            let _e641 = phi_1002_;
                            let _e643 = phi_1004_;
                            local_6 = _e641;
                            local_7 = _e643;
                            local_8 = _e641;
                            let _e644 = (_e639 < _e635);
                            if _e644 {
                                let _e649 = ((((_e621 - floor(_e621)) + f32(_e639)) * 3.1415927f) / f32(_e635));
                                let _e650 = sin(_e649);
                                let _e651 = cos(_e649);
                                let _e657 = ((_e651 * _e428) + (_e650 * _e429));
                                let _e661 = (_e651 - (_e428 * _e657));
                                let _e662 = (_e650 - (_e429 * _e657));
                                let _e663 = -((_e430 * _e657));
                                let _e666 = ((_e662 * _e430) - (_e429 * _e663));
                                let _e669 = ((_e663 * _e428) - (_e430 * _e661));
                                let _e672 = ((_e661 * _e429) - (_e428 * _e662));
                                let _e679 = (1f / sqrt((((_e666 * _e666) + (_e669 * _e669)) + (_e672 * _e672))));
                                let _e680 = (_e666 * _e679);
                                let _e681 = (_e669 * _e679);
                                let _e682 = (_e672 * _e679);
                                let _e687 = (((_e499 * _e680) + (_e500 * _e681)) + (_e501 * _e682));
                                let _e691 = (_e499 - (_e680 * _e687));
                                let _e692 = (_e500 - (_e681 * _e687));
                                let _e693 = (_e501 - (_e682 * _e687));
                                let _e699 = sqrt((((_e691 * _e691) + (_e692 * _e692)) + (_e693 * _e693)));
                                let _e704 = (((_e661 * _e691) + (_e662 * _e692)) + (_e663 * _e693));
                                let _e714 = ((((_e691 * _e428) + (_e692 * _e429)) + (_e693 * _e430)) / _e699);
                                let _e718 = select(0f, select(1f, _e714, (_e714 < 1f)), (_e714 > 0f));
                                let _e719 = abs(_e718);
                                let _e737 = (((((((((((((((_e719 * -0.0012624911f) + 0.00667009f) * _e719) - 0.017088126f) * _e719) + 0.03089188f) * _e719) - 0.050174303f) * _e719) + 0.08897899f) * _e719) - 0.2145988f) * _e719) + 1.5707963f) * sqrt((1f - _e719)));
                                let _e740 = (select(select(0f, -1f, (_e704 < 0f)), 1f, (_e704 > 0f)) * select((3.1415927f - _e737), _e737, (_e718 >= 0f)));
                                let _e743 = select(1u, _e145.member_9, (1u < _e145.member_9));
                                phi_1195_ = 0u;
                                phi_1198_ = 0u;
                                loop {
                                    let _e745 = phi_1195_;
                                    let _e747 = phi_1198_;
                                    local_1 = _e747;
                                    local_2 = _e747;
                                    local_4 = _e747;
                                    let _e748 = (_e745 < _e743);
                                    if _e748 {
                                        let _e753 = ((_e625 - floor(_e625)) + (f32((_e639 + (_e745 * _e743))) * 0.618034f));
                                        let _e760 = (((_e753 - floor(_e753)) + f32(_e745)) * (1f / f32(_e743)));
                                        if (_e145.member_4 == 2f) {
                                            phi_1248_ = (_e760 * _e760);
                                        } else {
                                            phi_1248_ = pow(_e760, _e145.member_4);
                                        }
                                        let _e766 = phi_1248_;
                                        let _e767 = (_e766 + (1.3f / _e508));
                                        let _e768 = ((_e651 * _e508) * _e767);
                                        let _e769 = ((-(_e650) * _e508) * _e767);
                                        let _e776 = (log2(sqrt(((_e768 * _e768) + (_e769 * _e769)))) - _e145.member_7);
                                        let _e783 = (-1f - floor((-0.5f - select(0f, select(5f, _e776, (_e776 < 5f)), (_e776 > 0f)))));
                                        let _e785 = floor((_e768 + 0.5f));
                                        let _e796 = (select(_e785, (_e785 - 1f), (((_e785 - _e768) == 0.5f) && ((floor((_e785 * 0.5f)) * 2f) != _e785))) * (1f / _e145.member.member.x));
                                        let _e798 = floor((_e769 + 0.5f));
                                        let _e809 = (select(_e798, (_e798 - 1f), (((_e798 - _e769) == 0.5f) && ((floor((_e798 * 0.5f)) * 2f) != _e798))) * (1f / _e145.member.member.y));
                                        let _e810 = (_e399 + _e796);
                                        let _e811 = (_e402 + _e809);
                                        let _e812 = (_e399 - _e796);
                                        let _e813 = (_e402 - _e809);
                                        let _e815 = select(1u, _e169, (1u < _e169));
                                        let _e817 = select(1u, _e177, (1u < _e177));
                                        let _e820 = (_e815 * _e817);
                                        let _e822 = (_e169 >> bitcast<u32>(1u));
                                        let _e824 = select(1u, _e822, (1u < _e822));
                                        let _e826 = (_e177 >> bitcast<u32>(1u));
                                        let _e828 = select(1u, _e826, (1u < _e826));
                                        let _e829 = (_e783 >= 1f);
                                        let _e838 = (_e820 + (_e824 * _e828));
                                        let _e840 = (_e169 >> bitcast<u32>(2u));
                                        let _e842 = select(1u, _e840, (1u < _e840));
                                        let _e844 = (_e177 >> bitcast<u32>(2u));
                                        let _e846 = select(1u, _e844, (1u < _e844));
                                        let _e847 = (_e783 >= 2f);
                                        let _e856 = (_e838 + (_e842 * _e846));
                                        let _e858 = (_e169 >> bitcast<u32>(3u));
                                        let _e860 = select(1u, _e858, (1u < _e858));
                                        let _e862 = (_e177 >> bitcast<u32>(3u));
                                        let _e864 = select(1u, _e862, (1u < _e862));
                                        let _e865 = (_e783 >= 3f);
                                        let _e876 = (_e169 >> bitcast<u32>(4u));
                                        let _e878 = select(1u, _e876, (1u < _e876));
                                        let _e880 = (_e177 >> bitcast<u32>(4u));
                                        let _e882 = select(1u, _e880, (1u < _e880));
                                        let _e883 = (_e783 >= 4f);
                                        let _e884 = select(select(select(select(_e815, _e824, _e829), _e842, _e847), _e860, _e865), _e878, _e883);
                                        let _e886 = select(select(select(select(0u, _e820, _e829), _e838, _e847), _e856, _e865), (_e856 + (_e860 * _e864)), _e883);
                                        let _e888 = select(select(select(select(f32(_e815), f32(_e824), _e829), f32(_e842), _e847), f32(_e860), _e865), f32(_e878), _e883);
                                        let _e890 = select(select(select(select(f32(_e817), f32(_e828), _e829), f32(_e846), _e847), f32(_e864), _e865), f32(_e882), _e883);
                                        let _e891 = (_e810 * _e888);
                                        let _e893 = f32((_e884 - 1u));
                                        let _e895 = select(0f, _e891, (_e891 > 0f));
                                        let _e899 = (_e811 * _e890);
                                        let _e901 = f32((select(select(select(select(_e817, _e828, _e829), _e846, _e847), _e864, _e865), _e882, _e883) - 1u));
                                        let _e903 = select(0f, _e899, (_e899 > 0f));
                                        let _e912 = mips.member[((_e886 + (u32(select(_e901, _e903, (_e903 < _e901))) * _e884)) + u32(select(_e893, _e895, (_e895 < _e893))))];
                                        let _e921 = (_e812 * _e888);
                                        let _e923 = select(0f, _e921, (_e921 > 0f));
                                        let _e927 = (_e813 * _e890);
                                        let _e929 = select(0f, _e927, (_e927 > 0f));
                                        let _e938 = mips.member[((_e886 + (u32(select(_e901, _e929, (_e929 < _e901))) * _e884)) + u32(select(_e893, _e923, (_e923 < _e893))))];
                                        let _e947 = (((((_e810 * 2f) - 1f) * _e145.member.member_1.x) * _e912) - _e410);
                                        let _e948 = (((((_e811 * -2f) + 1f) * _e145.member.member_1.y) * _e912) - _e417);
                                        let _e949 = (_e912 - _e403);
                                        let _e950 = (_e161 > 0f);
                                        if _e950 {
                                            phi_1777_ = (sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))) > _e161);
                                        } else {
                                            phi_1777_ = false;
                                        }
                                        let _e959 = phi_1777_;
                                        if !(_e959) {
                                            let _e965 = (((_e947 * _e428) + (_e948 * _e429)) + (_e949 * _e430));
                                            let _e969 = (_e947 - (_e428 * _e965));
                                            let _e970 = (_e948 - (_e429 * _e965));
                                            let _e971 = (_e949 - (_e430 * _e965));
                                            let _e980 = ((_e970 * _e430) - (_e429 * _e971));
                                            let _e983 = ((_e971 * _e428) - (_e430 * _e969));
                                            let _e986 = ((_e969 * _e429) - (_e428 * _e970));
                                            let _e993 = (1f / sqrt((((_e980 * _e980) + (_e983 * _e983)) + (_e986 * _e986))));
                                            let _e994 = (_e980 * _e993);
                                            let _e995 = (_e983 * _e993);
                                            let _e996 = (_e986 * _e993);
                                            let _e1001 = (((_e499 * _e994) + (_e500 * _e995)) + (_e501 * _e996));
                                            let _e1005 = (_e499 - (_e994 * _e1001));
                                            let _e1006 = (_e500 - (_e995 * _e1001));
                                            let _e1007 = (_e501 - (_e996 * _e1001));
                                            let _e1013 = sqrt((((_e1005 * _e1005) + (_e1006 * _e1006)) + (_e1007 * _e1007)));
                                            let _e1019 = ((((_e1005 * _e428) + (_e1006 * _e429)) + (_e1007 * _e430)) / _e1013);
                                            let _e1023 = select(0f, select(1f, _e1019, (_e1019 < 1f)), (_e1019 > 0f));
                                            let _e1024 = abs(_e1023);
                                            let _e1041 = (((((((((((((((_e1024 * -0.0012624911f) + 0.00667009f) * _e1024) - 0.017088126f) * _e1024) + 0.03089188f) * _e1024) - 0.050174303f) * _e1024) + 0.08897899f) * _e1024) - 0.2145988f) * _e1024) + 1.5707963f) * sqrt((1f - _e1024)));
                                            let _e1044 = select((3.1415927f - _e1041), _e1041, (_e1023 >= 0f));
                                            let _e1052 = select(_e1044, -(_e1044), ((((_e969 * _e1005) + (_e970 * _e1006)) + (_e971 * _e1007)) < 0f));
                                            let _e1053 = (0.02f / _e1013);
                                            let _e1056 = select(0.19634955f, _e1053, ((_e1053 < 0.19634955f) || false));
                                            let _e1060 = (_e947 - (_e428 * _e158));
                                            let _e1061 = (_e948 - (_e429 * _e158));
                                            let _e1062 = (_e949 - (_e430 * _e158));
                                            let _e1069 = (1f / sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))));
                                            let _e1077 = ((((_e947 * _e1069) * _e428) + ((_e948 * _e1069) * _e429)) + ((_e949 * _e1069) * _e430));
                                            let _e1081 = select(-1f, select(1f, _e1077, (_e1077 < 1f)), (_e1077 > -1f));
                                            let _e1082 = abs(_e1081);
                                            let _e1099 = (((((((((((((((_e1082 * -0.0012624911f) + 0.00667009f) * _e1082) - 0.017088126f) * _e1082) + 0.03089188f) * _e1082) - 0.050174303f) * _e1082) + 0.08897899f) * _e1082) - 0.2145988f) * _e1082) + 1.5707963f) * sqrt((1f - _e1082)));
                                            let _e1106 = ((((select((3.1415927f - _e1099), _e1099, (_e1081 >= 0f)) + _e1056) - _e1052) + 1.5707964f) * 0.31830987f);
                                            let _e1110 = select(0f, select(1f, _e1106, (_e1106 < 1f)), (_e1106 > 0f));
                                            let _e1117 = (1f / sqrt((((_e1060 * _e1060) + (_e1061 * _e1061)) + (_e1062 * _e1062))));
                                            let _e1125 = ((((_e1060 * _e1117) * _e428) + ((_e1061 * _e1117) * _e429)) + ((_e1062 * _e1117) * _e430));
                                            let _e1129 = select(-1f, select(1f, _e1125, (_e1125 < 1f)), (_e1125 > -1f));
                                            let _e1130 = abs(_e1129);
                                            let _e1147 = (((((((((((((((_e1130 * -0.0012624911f) + 0.00667009f) * _e1130) - 0.017088126f) * _e1130) + 0.03089188f) * _e1130) - 0.050174303f) * _e1130) + 0.08897899f) * _e1130) - 0.2145988f) * _e1130) + 1.5707963f) * sqrt((1f - _e1130)));
                                            let _e1154 = ((((select((3.1415927f - _e1147), _e1147, (_e1129 >= 0f)) + _e1056) - _e1052) + 1.5707964f) * 0.31830987f);
                                            let _e1158 = select(0f, select(1f, _e1154, (_e1154 < 1f)), (_e1154 > 0f));
                                            let _e1160 = (_e1158 != _e1158);
                                            let _e1162 = select(_e1158, _e1110, ((_e1110 < _e1158) || _e1160));
                                            let _e1165 = select(_e1158, _e1110, ((_e1110 > _e1158) || _e1160));
                                            let _e1167 = floor((_e1162 * 32f));
                                            if (_e155 == 1u) {
                                                let _e1175 = -(floor((_e1165 * -32f)));
                                                let _e1180 = (select(32f, _e1175, ((_e1175 < 32f) || false)) - _e1167);
                                                phi_2124_ = select(select(0f, _e1180, ((_e1180 > 0f) || false)), 0f, (_e1165 <= _e1162));
                                            } else {
                                                phi_2124_ = -(floor(((_e1165 - _e1162) * -32f)));
                                            }
                                            let _e1186 = phi_2124_;
                                            let _e1188 = select(0f, _e1167, (_e1167 > 0f));
                                            let _e1191 = u32(select(32f, _e1188, (_e1188 < 32f)));
                                            let _e1193 = select(0f, _e1186, (_e1186 > 0f));
                                            let _e1196 = u32(select(32f, _e1193, (_e1193 < 32f)));
                                            if (_e1191 >= 32u) {
                                                phi_2170_ = u32();
                                                phi_2171_ = true;
                                            } else {
                                                let _e1198 = (_e1196 == 0u);
                                                if _e1198 {
                                                    phi_2169_ = u32();
                                                } else {
                                                    if (_e1196 >= 32u) {
                                                        phi_2166_ = 4294967295u;
                                                    } else {
                                                        phi_2166_ = ((1u << bitcast<u32>((_e1196 & 31u))) - 1u);
                                                    }
                                                    let _e1205 = phi_2166_;
                                                    phi_2169_ = (_e1205 << bitcast<u32>((_e1191 & 31u)));
                                                }
                                                let _e1210 = phi_2169_;
                                                phi_2170_ = _e1210;
                                                phi_2171_ = _e1198;
                                            }
                                            let _e1212 = phi_2170_;
                                            let _e1214 = phi_2171_;
                                            phi_2185_ = select(select(select(_e1212, 0u, _e1214), 0u, (sqrt((((_e969 * _e969) + (_e970 * _e970)) + (_e971 * _e971))) <= 0f)), 0u, _e959);
                                        } else {
                                            phi_2185_ = 0u;
                                        }
                                        let _e1220 = phi_2185_;
                                        let _e1222 = (((((_e812 * 2f) - 1f) * _e145.member.member_1.x) * _e938) - _e410);
                                        let _e1223 = (((((_e813 * -2f) + 1f) * _e145.member.member_1.y) * _e938) - _e417);
                                        let _e1224 = (_e938 - _e403);
                                        if _e950 {
                                            phi_2205_ = (sqrt((((_e1222 * _e1222) + (_e1223 * _e1223)) + (_e1224 * _e1224))) > _e161);
                                        } else {
                                            phi_2205_ = false;
                                        }
                                        let _e1233 = phi_2205_;
                                        if !(_e1233) {
                                            let _e1239 = (((_e1222 * _e428) + (_e1223 * _e429)) + (_e1224 * _e430));
                                            let _e1243 = (_e1222 - (_e428 * _e1239));
                                            let _e1244 = (_e1223 - (_e429 * _e1239));
                                            let _e1245 = (_e1224 - (_e430 * _e1239));
                                            let _e1254 = ((_e1244 * _e430) - (_e429 * _e1245));
                                            let _e1257 = ((_e1245 * _e428) - (_e430 * _e1243));
                                            let _e1260 = ((_e1243 * _e429) - (_e428 * _e1244));
                                            let _e1267 = (1f / sqrt((((_e1254 * _e1254) + (_e1257 * _e1257)) + (_e1260 * _e1260))));
                                            let _e1268 = (_e1254 * _e1267);
                                            let _e1269 = (_e1257 * _e1267);
                                            let _e1270 = (_e1260 * _e1267);
                                            let _e1275 = (((_e499 * _e1268) + (_e500 * _e1269)) + (_e501 * _e1270));
                                            let _e1279 = (_e499 - (_e1268 * _e1275));
                                            let _e1280 = (_e500 - (_e1269 * _e1275));
                                            let _e1281 = (_e501 - (_e1270 * _e1275));
                                            let _e1287 = sqrt((((_e1279 * _e1279) + (_e1280 * _e1280)) + (_e1281 * _e1281)));
                                            let _e1293 = ((((_e1279 * _e428) + (_e1280 * _e429)) + (_e1281 * _e430)) / _e1287);
                                            let _e1297 = select(0f, select(1f, _e1293, (_e1293 < 1f)), (_e1293 > 0f));
                                            let _e1298 = abs(_e1297);
                                            let _e1315 = (((((((((((((((_e1298 * -0.0012624911f) + 0.00667009f) * _e1298) - 0.017088126f) * _e1298) + 0.03089188f) * _e1298) - 0.050174303f) * _e1298) + 0.08897899f) * _e1298) - 0.2145988f) * _e1298) + 1.5707963f) * sqrt((1f - _e1298)));
                                            let _e1318 = select((3.1415927f - _e1315), _e1315, (_e1297 >= 0f));
                                            let _e1326 = select(_e1318, -(_e1318), ((((_e1243 * _e1279) + (_e1244 * _e1280)) + (_e1245 * _e1281)) < 0f));
                                            let _e1327 = (0.02f / _e1287);
                                            let _e1330 = select(0.19634955f, _e1327, ((_e1327 < 0.19634955f) || false));
                                            let _e1334 = (_e1222 - (_e428 * _e158));
                                            let _e1335 = (_e1223 - (_e429 * _e158));
                                            let _e1336 = (_e1224 - (_e430 * _e158));
                                            let _e1343 = (1f / sqrt((((_e1222 * _e1222) + (_e1223 * _e1223)) + (_e1224 * _e1224))));
                                            let _e1351 = ((((_e1222 * _e1343) * _e428) + ((_e1223 * _e1343) * _e429)) + ((_e1224 * _e1343) * _e430));
                                            let _e1355 = select(-1f, select(1f, _e1351, (_e1351 < 1f)), (_e1351 > -1f));
                                            let _e1356 = abs(_e1355);
                                            let _e1373 = (((((((((((((((_e1356 * -0.0012624911f) + 0.00667009f) * _e1356) - 0.017088126f) * _e1356) + 0.03089188f) * _e1356) - 0.050174303f) * _e1356) + 0.08897899f) * _e1356) - 0.2145988f) * _e1356) + 1.5707963f) * sqrt((1f - _e1356)));
                                            let _e1380 = ((((select((3.1415927f - _e1373), _e1373, (_e1355 >= 0f)) + _e1330) - _e1326) + 1.5707964f) * 0.31830987f);
                                            let _e1391 = (1f / sqrt((((_e1334 * _e1334) + (_e1335 * _e1335)) + (_e1336 * _e1336))));
                                            let _e1399 = ((((_e1334 * _e1391) * _e428) + ((_e1335 * _e1391) * _e429)) + ((_e1336 * _e1391) * _e430));
                                            let _e1403 = select(-1f, select(1f, _e1399, (_e1399 < 1f)), (_e1399 > -1f));
                                            let _e1404 = abs(_e1403);
                                            let _e1421 = (((((((((((((((_e1404 * -0.0012624911f) + 0.00667009f) * _e1404) - 0.017088126f) * _e1404) + 0.03089188f) * _e1404) - 0.050174303f) * _e1404) + 0.08897899f) * _e1404) - 0.2145988f) * _e1404) + 1.5707963f) * sqrt((1f - _e1404)));
                                            let _e1428 = ((((select((3.1415927f - _e1421), _e1421, (_e1403 >= 0f)) + _e1330) - _e1326) + 1.5707964f) * 0.31830987f);
                                            let _e1433 = (1f - select(0f, select(1f, _e1380, (_e1380 < 1f)), (_e1380 > 0f)));
                                            let _e1434 = (1f - select(0f, select(1f, _e1428, (_e1428 < 1f)), (_e1428 > 0f)));
                                            let _e1436 = (_e1434 != _e1434);
                                            let _e1438 = select(_e1434, _e1433, ((_e1433 < _e1434) || _e1436));
                                            let _e1441 = select(_e1434, _e1433, ((_e1433 > _e1434) || _e1436));
                                            let _e1443 = floor((_e1438 * 32f));
                                            if (_e155 == 1u) {
                                                let _e1451 = -(floor((_e1441 * -32f)));
                                                let _e1456 = (select(32f, _e1451, ((_e1451 < 32f) || false)) - _e1443);
                                                phi_2552_ = select(select(0f, _e1456, ((_e1456 > 0f) || false)), 0f, (_e1441 <= _e1438));
                                            } else {
                                                phi_2552_ = -(floor(((_e1441 - _e1438) * -32f)));
                                            }
                                            let _e1462 = phi_2552_;
                                            let _e1464 = select(0f, _e1443, (_e1443 > 0f));
                                            let _e1467 = u32(select(32f, _e1464, (_e1464 < 32f)));
                                            let _e1469 = select(0f, _e1462, (_e1462 > 0f));
                                            let _e1472 = u32(select(32f, _e1469, (_e1469 < 32f)));
                                            if (_e1467 >= 32u) {
                                                phi_2598_ = u32();
                                                phi_2599_ = true;
                                            } else {
                                                let _e1474 = (_e1472 == 0u);
                                                if _e1474 {
                                                    phi_2597_ = u32();
                                                } else {
                                                    if (_e1472 >= 32u) {
                                                        phi_2594_ = 4294967295u;
                                                    } else {
                                                        phi_2594_ = ((1u << bitcast<u32>((_e1472 & 31u))) - 1u);
                                                    }
                                                    let _e1481 = phi_2594_;
                                                    phi_2597_ = (_e1481 << bitcast<u32>((_e1467 & 31u)));
                                                }
                                                let _e1486 = phi_2597_;
                                                phi_2598_ = _e1486;
                                                phi_2599_ = _e1474;
                                            }
                                            let _e1488 = phi_2598_;
                                            let _e1490 = phi_2599_;
                                            phi_2613_ = select(select(select(_e1488, 0u, _e1490), 0u, (sqrt((((_e1243 * _e1243) + (_e1244 * _e1244)) + (_e1245 * _e1245))) <= 0f)), 0u, _e1233);
                                        } else {
                                            phi_2613_ = 0u;
                                        }
                                        let _e1496 = phi_2613_;
                                        phi_1196_ = (_e745 + 1u);
                                        phi_1199_ = ((_e747 | _e1220) | _e1496);
                                    } else {
                                        phi_1196_ = u32();
                                        phi_1199_ = u32();
                                    }
                                    let _e1500 = phi_1196_;
                                    let _e1502 = phi_1199_;
                                    continue;
                                    continuing {
                                        phi_1195_ = _e1500;
                                        phi_1198_ = _e1502;
                                        break if !(_e748);
                                    }
                                }
                                if (_e150 == 2u) {
                                    let _e1560 = (_e740 - 1.5707964f);
                                    let _e1561 = (_e1560 * 2f);
                                    let _e1562 = sin(_e740);
                                    let _e1567 = ((_e718 + (_e1561 * _e1562)) - cos((_e1561 - _e740)));
                                    phi_2642_ = 0u;
                                    phi_2645_ = select((_e1567 * 0.25f), (_e1567 * -0.25f), (_e1560 < 0f));
                                    phi_2647_ = 0f;
                                    loop {
                                        let _e1573 = phi_2642_;
                                        let _e1575 = phi_2645_;
                                        let _e1577 = phi_2647_;
                                        local_5 = _e1577;
                                        let _e1578 = (_e1573 < 32u);
                                        if _e1578 {
                                            let _e1579 = (_e1573 + 1u);
                                            let _e1582 = (_e1560 + (f32(_e1579) * 0.09817477f));
                                            let _e1583 = (_e1582 * 2f);
                                            let _e1588 = ((_e718 + (_e1583 * _e1562)) - cos((_e1583 - _e740)));
                                            let _e1592 = select((_e1588 * 0.25f), (_e1588 * -0.25f), (_e1582 < 0f));
                                            let _e1595 = local_4;
                                            phi_2643_ = _e1579;
                                            phi_2646_ = _e1592;
                                            phi_2648_ = select(_e1577, (_e1577 + (_e1592 - _e1575)), (((_e1595 >> bitcast<u32>((_e1573 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2643_ = u32();
                                            phi_2646_ = f32();
                                            phi_2648_ = f32();
                                        }
                                        let _e1604 = phi_2643_;
                                        let _e1606 = phi_2646_;
                                        let _e1608 = phi_2648_;
                                        continue;
                                        continuing {
                                            phi_2642_ = _e1604;
                                            phi_2645_ = _e1606;
                                            phi_2647_ = _e1608;
                                            break if !(_e1578);
                                        }
                                    }
                                    let _e1611 = local_5;
                                    phi_3581_ = _e637;
                                    phi_2748_ = (_e641 + 1f);
                                    phi_2749_ = (_e643 + ((_e699 + ((1f - _e699) * 0.05f)) * _e1611));
                                } else {
                                    if (_e150 == 1u) {
                                        phi_2693_ = 0u;
                                        phi_2696_ = 0f;
                                        loop {
                                            let _e1516 = phi_2693_;
                                            let _e1518 = phi_2696_;
                                            local_3 = _e1518;
                                            let _e1519 = (_e1516 < 4u);
                                            if _e1519 {
                                                local = array<type_26, 4>(type_26(4026531855u, 0.0095061f), type_26(251658480u, 0.0270951f), type_26(15732480u, 0.0405571f), type_26(1044480u, 0.0478421f));
                                                if _e1519 {
                                                } else {
                                                    phi_3340_ = true;
                                                    break;
                                                }
                                                let _e1522 = local[_e1516].member;
                                                let _e1525 = local[_e1516].member_1;
                                                let _e1527 = local_2;
                                                phi_2694_ = (_e1516 + 1u);
                                                phi_2697_ = (_e1518 + (f32(countOneBits((_e1527 & _e1522))) * _e1525));
                                            } else {
                                                phi_2694_ = u32();
                                                phi_2697_ = f32();
                                            }
                                            let _e1535 = phi_2694_;
                                            let _e1537 = phi_2697_;
                                            continue;
                                            continuing {
                                                phi_2693_ = _e1535;
                                                phi_2696_ = _e1537;
                                                phi_3340_ = _e637;
                                                break if !(_e1519);
                                            }
                                        }
                                        let _e1540 = phi_3340_;
                                        phi_3579_ = _e1540;
                                        if _e1540 {
                                            break;
                                        }
                                        let _e1542 = local_3;
                                        let _e1543 = (1f - _e1542);
                                        phi_3587_ = _e1540;
                                        phi_2746_ = (_e641 + _e699);
                                        phi_2747_ = (_e643 + (_e699 * select(0f, select(1f, _e1543, (_e1543 < 1f)), (_e1543 > 0f))));
                                    } else {
                                        let _e1507 = local_1;
                                        phi_3587_ = _e637;
                                        phi_2746_ = (_e641 + 1f);
                                        phi_2747_ = (_e643 + ((f32(countOneBits((_e1507 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1552 = phi_3587_;
                                    let _e1554 = phi_2746_;
                                    let _e1556 = phi_2747_;
                                    phi_3581_ = _e1552;
                                    phi_2748_ = _e1554;
                                    phi_2749_ = _e1556;
                                }
                                let _e1616 = phi_3581_;
                                let _e1618 = phi_2748_;
                                let _e1620 = phi_2749_;
                                phi_3580_ = _e1616;
                                phi_1000_ = (_e639 + 1u);
                                phi_1003_ = _e1618;
                                phi_1005_ = _e1620;
                            } else {
                                phi_3580_ = _e637;
                                phi_1000_ = u32();
                                phi_1003_ = f32();
                                phi_1005_ = f32();
                            }
                            let _e1623 = phi_3580_;
                            let _e1625 = phi_1000_;
                            let _e1627 = phi_1003_;
                            let _e1629 = phi_1005_;
                            continue;
                            continuing {
                                phi_3491_ = _e1623;
                                phi_999_ = _e1625;
                                phi_1002_ = _e1627;
                                phi_1004_ = _e1629;
                                phi_3579_ = _e1623;
                                break if !(_e644);
                            }
                        }
                        let _e1632 = phi_3579_;
                        if _e1632 {
                            break;
                        }
                        let _e1634 = local_6;
                        let _e1637 = local_7;
                        let _e1639 = local_8;
                        phi_2757_ = select(1f, (_e1637 / _e1639), (_e1634 > 0f));
                    } else {
                        phi_2757_ = 1f;
                    }
                    let _e1643 = phi_2757_;
                    if _e632 {
                        let _e1645 = pow(_e1643, _e145.member_6);
                        if (_e1645 != _e1645) {
                            phi_3314_ = true;
                        } else {
                            phi_3314_ = (0.03f >= _e1645);
                        }
                        let _e1649 = phi_3314_;
                        let _e1651 = (select(_e1645, 0.03f, _e1649) * 0.6666667f);
                        let _e1657 = ((select(0f, select(1f, _e1651, (_e1651 < 1f)), (_e1651 > 0f)) * 255f) + 0.5f);
                        phi_2804_ = select(select(u32(_e1657), 0u, (_e1657 < 0f)), 4294967295u, (_e1657 > 4294967000f));
                    } else {
                        phi_2804_ = 170u;
                    }
                    let _e1664 = phi_2804_;
                    terms.member[_e183] = _e1664;
                    edges.member[_e183] = ((((64u * u32(select(3f, _e324, (_e324 < 3f)))) + (16u * u32(select(3f, _e346, (_e346 < 3f))))) + (4u * u32(select(3f, _e369, (_e369 < 3f))))) + u32(select(3f, _e392, (_e392 < 3f))));
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vbao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
