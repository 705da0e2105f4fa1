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

struct type_26 {
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

struct type_29 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_30 {
    member: type_29,
    member_1: type_29,
    member_2: type_5,
}

struct type_31 {
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

struct type_32 {
    member: type_30,
    member_1: type_31,
}

struct type_34 {
    member: array<type_32>,
}

struct type_37 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_26,
}

struct type_38 {
    member: type_37,
}

struct type_40 {
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
@group(0) @binding(0) 
var<storage> frame: type_34;
@group(0) @binding(2) 
var<storage> normals: type_11;
@group(0) @binding(6) 
var<uniform> params: type_38;
@group(0) @binding(1) 
var<storage> mips: type_8;
@group(0) @binding(3) 
var<storage> sd_map: type_8;
@group(0) @binding(4) 
var<storage, read_write> terms: type_11;
@group(0) @binding(5) 
var<storage, read_write> edges: type_11;

fn function_() {
    var local: array<type_40, 4>;
    var local_1: array<array<f32, 2>, 16>;
    var local_2: array<array<f32, 2>, 16>;
    var local_3: array<array<f32, 2>, 16>;
    var local_4: array<array<f32, 2>, 16>;
    var local_5: array<array<f32, 2>, 16>;
    var local_6: array<array<f32, 2>, 16>;
    var local_7: array<array<f32, 2>, 16>;
    var local_8: array<array<f32, 2>, 16>;
    var phi_336_: type_26;
    var phi_343_: u32;
    var phi_350_: u32;
    var phi_7716_: bool;
    var phi_1008_: u32;
    var phi_1011_: f32;
    var phi_1013_: f32;
    var phi_1199_: u32;
    var phi_1202_: u32;
    var phi_1259_: f32;
    var phi_1260_: f32;
    var phi_1538_: bool;
    var phi_1691_: bool;
    var phi_1853_: vec2<f32>;
    var phi_1854_: vec2<f32>;
    var phi_2292_: f32;
    var phi_2293_: f32;
    var phi_2294_: f32;
    var phi_2295_: f32;
    var phi_2637_: bool;
    var phi_2864_: f32;
    var phi_2914_: u32;
    var phi_2917_: u32;
    var phi_2918_: u32;
    var phi_2919_: bool;
    var phi_2932_: u32;
    var phi_2963_: bool;
    var phi_3190_: f32;
    var phi_3240_: u32;
    var phi_3243_: u32;
    var phi_3244_: u32;
    var phi_3245_: bool;
    var phi_3258_: u32;
    var phi_3290_: bool;
    var phi_3517_: f32;
    var phi_3567_: u32;
    var phi_3570_: u32;
    var phi_3571_: u32;
    var phi_3572_: bool;
    var phi_3585_: u32;
    var phi_3617_: bool;
    var phi_3844_: f32;
    var phi_3894_: u32;
    var phi_3897_: u32;
    var phi_3898_: u32;
    var phi_3899_: bool;
    var phi_3912_: u32;
    var phi_3914_: u32;
    var phi_3915_: vec3<f32>;
    var phi_4102_: f32;
    var phi_4152_: u32;
    var phi_4155_: u32;
    var phi_4156_: u32;
    var phi_4157_: bool;
    var phi_4171_: u32;
    var phi_4191_: bool;
    var phi_4344_: bool;
    var phi_4506_: vec2<f32>;
    var phi_4507_: vec2<f32>;
    var phi_4945_: f32;
    var phi_4946_: f32;
    var phi_4947_: f32;
    var phi_4948_: f32;
    var phi_5290_: bool;
    var phi_5517_: f32;
    var phi_5567_: u32;
    var phi_5570_: u32;
    var phi_5571_: u32;
    var phi_5572_: bool;
    var phi_5585_: u32;
    var phi_5616_: bool;
    var phi_5843_: f32;
    var phi_5893_: u32;
    var phi_5896_: u32;
    var phi_5897_: u32;
    var phi_5898_: bool;
    var phi_5911_: u32;
    var phi_5943_: bool;
    var phi_6170_: f32;
    var phi_6220_: u32;
    var phi_6223_: u32;
    var phi_6224_: u32;
    var phi_6225_: bool;
    var phi_6238_: u32;
    var phi_6270_: bool;
    var phi_6497_: f32;
    var phi_6547_: u32;
    var phi_6550_: u32;
    var phi_6551_: u32;
    var phi_6552_: bool;
    var phi_6565_: u32;
    var phi_6567_: u32;
    var phi_6568_: vec3<f32>;
    var phi_6755_: f32;
    var phi_6805_: u32;
    var phi_6808_: u32;
    var phi_6809_: u32;
    var phi_6810_: bool;
    var phi_6824_: u32;
    var phi_1200_: u32;
    var phi_1203_: u32;
    var phi_7179_: bool;
    var local_9: u32;
    var phi_6905_: u32;
    var phi_6908_: f32;
    var local_10: u32;
    var phi_6906_: u32;
    var phi_6909_: f32;
    var phi_7800_: bool;
    var local_11: f32;
    var phi_7811_: bool;
    var phi_6958_: f32;
    var phi_6959_: f32;
    var phi_6853_: u32;
    var phi_6856_: f32;
    var phi_6858_: f32;
    var local_12: u32;
    var phi_6854_: u32;
    var phi_6857_: f32;
    var phi_6859_: f32;
    var local_13: f32;
    var phi_7805_: bool;
    var phi_6960_: f32;
    var phi_6961_: f32;
    var phi_7804_: bool;
    var phi_1009_: u32;
    var phi_1012_: f32;
    var phi_1014_: f32;
    var phi_7803_: bool;
    var local_14: f32;
    var local_15: f32;
    var local_16: f32;
    var phi_6969_: f32;
    var phi_6981_: f32;
    var phi_6982_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e184 = id_1;
            let _e191 = (override_type == 0u);
            if _e191 {
                let _e223 = params.member.member_4;
                phi_336_ = _e223;
            } else {
                let _e201 = params.member.member_4.member;
                let _e205 = params.member.member_4.member_1;
                let _e209 = params.member.member_4.member_10;
                let _e213 = params.member.member_4.member_11;
                let _e217 = params.member.member_4.member_12;
                let _e221 = params.member.member_4.member_14;
                phi_336_ = type_26(_e201, _e205, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e209, _e213, _e217, override_type_9, _e221);
            }
            let _e225 = phi_336_;
            if _e191 {
                let _e228 = params.member.member_2;
                phi_343_ = _e228;
            } else {
                phi_343_ = override_type_10;
            }
            let _e230 = phi_343_;
            if _e191 {
                let _e233 = params.member.member_3;
                phi_350_ = _e233;
            } else {
                phi_350_ = override_type_11;
            }
            let _e235 = phi_350_;
            let _e238 = params.member.member;
            let _e241 = params.member.member_1;
            let _e249 = select(select(u32(_e225.member.member.x), 0u, (_e225.member.member.x < 0f)), 4294967295u, (_e225.member.member.x > 4294967000f));
            let _e257 = select(select(u32(_e225.member.member.y), 0u, (_e225.member.member.y < 0f)), 4294967295u, (_e225.member.member.y > 4294967000f));
            if (_e184.x >= _e249) {
            } else {
                if (_e184.y >= _e257) {
                } else {
                    if (0u < arrayLength((&frame.member))) {
                    } else {
                        break;
                    }
                    let _e267 = ((_e184.y * _e249) + _e184.x);
                    let _e270 = mips.member[_e267];
                    let _e271 = bitcast<i32>(_e184.x);
                    let _e272 = (_e271 + -1i);
                    let _e274 = select(0i, _e272, (0i < _e272));
                    let _e276 = (bitcast<i32>(_e249) - 1i);
                    let _e280 = bitcast<i32>(_e184.y);
                    let _e282 = select(0i, _e280, (0i < _e280));
                    let _e284 = (bitcast<i32>(_e257) - 1i);
                    let _e288 = (bitcast<u32>(select(_e282, _e284, (_e284 < _e282))) * _e249);
                    let _e292 = mips.member[(_e288 + bitcast<u32>(select(_e274, _e276, (_e276 < _e274))))];
                    let _e293 = (_e271 + 1i);
                    let _e295 = select(0i, _e293, (0i < _e293));
                    let _e302 = mips.member[(_e288 + bitcast<u32>(select(_e295, _e276, (_e276 < _e295))))];
                    let _e304 = select(0i, _e271, (0i < _e271));
                    let _e307 = bitcast<u32>(select(_e304, _e276, (_e276 < _e304)));
                    let _e308 = (_e280 + -1i);
                    let _e310 = select(0i, _e308, (0i < _e308));
                    let _e318 = mips.member[((bitcast<u32>(select(_e310, _e284, (_e284 < _e310))) * _e249) + _e307)];
                    let _e319 = (_e280 + 1i);
                    let _e321 = select(0i, _e319, (0i < _e319));
                    let _e329 = mips.member[((bitcast<u32>(select(_e321, _e284, (_e284 < _e321))) * _e249) + _e307)];
                    let _e330 = (_e292 - _e270);
                    let _e331 = (_e302 - _e270);
                    let _e332 = (_e318 - _e270);
                    let _e333 = (_e329 - _e270);
                    let _e335 = ((_e331 - _e330) * 0.5f);
                    let _e337 = ((_e333 - _e332) * 0.5f);
                    let _e338 = (_e270 * 0.011f);
                    let _e340 = abs(_e330);
                    let _e341 = abs((_e330 + _e335));
                    let _e347 = (1.25f - (select(_e341, _e340, ((_e340 < _e341) || (_e341 != _e341))) / _e338));
                    let _e351 = select(0f, select(1f, _e347, (_e347 < 1f)), (_e347 > 0f));
                    let _e353 = abs(_e331);
                    let _e354 = abs((_e331 - _e335));
                    let _e360 = (1.25f - (select(_e354, _e353, ((_e353 < _e354) || (_e354 != _e354))) / _e338));
                    let _e364 = select(0f, select(1f, _e360, (_e360 < 1f)), (_e360 > 0f));
                    let _e366 = abs(_e332);
                    let _e367 = abs((_e332 + _e337));
                    let _e373 = (1.25f - (select(_e367, _e366, ((_e366 < _e367) || (_e367 != _e367))) / _e338));
                    let _e377 = select(0f, select(1f, _e373, (_e373 < 1f)), (_e373 > 0f));
                    let _e379 = abs(_e333);
                    let _e380 = abs((_e333 - _e337));
                    let _e386 = (1.25f - (select(_e380, _e379, ((_e379 < _e380) || (_e380 != _e380))) / _e338));
                    let _e390 = select(0f, select(1f, _e386, (_e386 < 1f)), (_e386 > 0f));
                    let _e396 = round((select(0f, select(1f, _e351, (_e351 < 1f)), (_e351 > 0f)) * 2.9f));
                    let _e411 = round((select(0f, select(1f, _e364, (_e364 < 1f)), (_e364 > 0f)) * 2.9f));
                    let _e427 = round((select(0f, select(1f, _e377, (_e377 < 1f)), (_e377 > 0f)) * 2.9f));
                    let _e443 = round((select(0f, select(1f, _e390, (_e390 < 1f)), (_e390 > 0f)) * 2.9f));
                    let _e455 = ((f32(_e271) + 0.5f) / _e225.member.member.x);
                    let _e458 = ((f32(_e280) + 0.5f) / _e225.member.member.y);
                    let _e459 = (_e270 * 0.99999f);
                    let _e466 = ((((_e455 * 2f) - 1f) * _e225.member.member_1.x) * _e459);
                    let _e473 = ((((_e458 * -2f) + 1f) * _e225.member.member_1.y) * _e459);
                    let _e474 = -(_e466);
                    let _e475 = -(_e473);
                    let _e476 = (_e270 * -0.99999f);
                    let _e483 = (1f / sqrt((((_e474 * _e474) + (_e475 * _e475)) + (_e476 * _e476))));
                    let _e484 = (_e474 * _e483);
                    let _e485 = (_e475 * _e483);
                    let _e486 = (_e476 * _e483);
                    let _e489 = normals.member[_e267];
                    let _e492 = f32(bitcast<i32>((_e489 & 255u)));
                    let _e496 = (select(_e492, (_e492 - 256f), (_e492 >= 128f)) * 0.007874016f);
                    let _e499 = select(-1f, _e496, ((_e496 > -1f) || false));
                    let _e504 = f32(bitcast<i32>(((_e489 >> bitcast<u32>(8u)) & 255u)));
                    let _e508 = (select(_e504, (_e504 - 256f), (_e504 >= 128f)) * 0.007874016f);
                    let _e511 = select(-1f, _e508, ((_e508 > -1f) || false));
                    let _e513 = (1f - abs(_e499));
                    let _e514 = abs(_e511);
                    let _e515 = (_e513 - _e514);
                    let _e516 = (_e515 < 0f);
                    let _e524 = select(_e499, ((1f - _e514) * select(1f, -1f, (_e499 < 0f))), _e516);
                    let _e525 = select(_e511, (_e513 * select(1f, -1f, (_e511 < 0f))), _e516);
                    let _e532 = (1f / sqrt((((_e524 * _e524) + (_e525 * _e525)) + (_e515 * _e515))));
                    let _e533 = (_e524 * _e532);
                    let _e534 = (_e525 * _e532);
                    let _e535 = (_e515 * _e532);
                    let _e536 = -(_e535);
                    let _e542 = ((((_e533 * _e484) + (_e534 * _e485)) + (_e536 * _e486)) < 0f);
                    let _e545 = select(_e533, -(_e533), _e542);
                    let _e546 = select(_e534, -(_e534), _e542);
                    let _e547 = select(_e536, _e535, _e542);
                    let _e554 = ((_e225.member_1 * _e225.member_2) / (((_e270 * 1.99998f) * _e225.member.member_1.x) / _e225.member.member.x));
                    let _e557 = (_e184.x & 63u);
                    let _e558 = (_e184.y & 63u);
                    let _e561 = ((_e557 >> bitcast<u32>(5u)) & 1u);
                    let _e564 = ((_e558 >> bitcast<u32>(5u)) & 1u);
                    let _e568 = (_e564 ^ 1u);
                    let _e570 = ((_e561 & _e568) * 63u);
                    let _e571 = (_e557 ^ _e570);
                    let _e572 = (_e558 ^ _e570);
                    let _e574 = ((_e571 ^ _e572) * _e568);
                    let _e575 = (_e571 ^ _e574);
                    let _e576 = (_e572 ^ _e574);
                    let _e579 = ((_e575 >> bitcast<u32>(4u)) & 1u);
                    let _e582 = ((_e576 >> bitcast<u32>(4u)) & 1u);
                    let _e587 = (_e582 ^ 1u);
                    let _e589 = ((_e579 & _e587) * 63u);
                    let _e590 = (_e575 ^ _e589);
                    let _e591 = (_e576 ^ _e589);
                    let _e593 = ((_e590 ^ _e591) * _e587);
                    let _e594 = (_e590 ^ _e593);
                    let _e595 = (_e591 ^ _e593);
                    let _e598 = ((_e594 >> bitcast<u32>(3u)) & 1u);
                    let _e601 = ((_e595 >> bitcast<u32>(3u)) & 1u);
                    let _e606 = (_e601 ^ 1u);
                    let _e608 = ((_e598 & _e606) * 63u);
                    let _e609 = (_e594 ^ _e608);
                    let _e610 = (_e595 ^ _e608);
                    let _e612 = ((_e609 ^ _e610) * _e606);
                    let _e613 = (_e609 ^ _e612);
                    let _e614 = (_e610 ^ _e612);
                    let _e617 = ((_e613 >> bitcast<u32>(2u)) & 1u);
                    let _e620 = ((_e614 >> bitcast<u32>(2u)) & 1u);
                    let _e625 = (_e620 ^ 1u);
                    let _e627 = ((_e617 & _e625) * 63u);
                    let _e628 = (_e613 ^ _e627);
                    let _e629 = (_e614 ^ _e627);
                    let _e631 = ((_e628 ^ _e629) * _e625);
                    let _e632 = (_e628 ^ _e631);
                    let _e633 = (_e629 ^ _e631);
                    let _e636 = ((_e632 >> bitcast<u32>(1u)) & 1u);
                    let _e639 = ((_e633 >> bitcast<u32>(1u)) & 1u);
                    let _e644 = (_e639 ^ 1u);
                    let _e646 = ((_e636 & _e644) * 63u);
                    let _e647 = (_e632 ^ _e646);
                    let _e648 = (_e633 ^ _e646);
                    let _e650 = ((_e647 ^ _e648) * _e644);
                    let _e662 = f32(bitcast<i32>((((((((((_e561 * 3u) ^ _e564) * 1024u) + (((_e579 * 3u) ^ _e582) * 256u)) + (((_e598 * 3u) ^ _e601) * 64u)) + (((_e617 * 3u) ^ _e620) * 16u)) + (((_e636 * 3u) ^ _e639) * 4u)) + ((((_e647 ^ _e650) & 1u) * 3u) ^ ((_e648 ^ _e650) & 1u))) + (288u * (_e225.member_11 % 64u)))));
                    let _e664 = ((_e662 * 0.7548777f) + 0.5f);
                    let _e668 = ((_e662 * 0.5698403f) + 0.5f);
                    let _e674 = exp2(((2f * _e225.member_7) + 1f));
                    let _e679 = select(false, (_e270 < _e225.member.member_3), (_e270 > 0f));
                    if _e679 {
                        let _e682 = select(1u, _e225.member_8, (1u < _e225.member_8));
                        phi_7716_ = false;
                        phi_1008_ = 0u;
                        phi_1011_ = 0f;
                        phi_1013_ = 0f;
                        loop {
                            let _e684 = phi_7716_;
                            let _e686 = phi_1008_;
                            let _e688 = phi_1011_;
                            let _e690 = phi_1013_;
                            local_14 = _e688;
                            local_15 = _e690;
                            local_16 = _e688;
                            let _e691 = (_e686 < _e682);
                            if _e691 {
                                let _e698 = ((((_e664 - floor(_e664)) + f32(bitcast<i32>(_e686))) * 3.1415927f) / f32(bitcast<i32>(_e682)));
                                let _e699 = sin(_e698);
                                let _e700 = cos(_e698);
                                let _e706 = ((_e700 * _e484) + (_e699 * _e485));
                                let _e710 = (_e700 - (_e484 * _e706));
                                let _e711 = (_e699 - (_e485 * _e706));
                                let _e712 = -((_e486 * _e706));
                                let _e715 = ((_e711 * _e486) - (_e485 * _e712));
                                let _e718 = ((_e712 * _e484) - (_e486 * _e710));
                                let _e721 = ((_e710 * _e485) - (_e484 * _e711));
                                let _e728 = (1f / sqrt((((_e715 * _e715) + (_e718 * _e718)) + (_e721 * _e721))));
                                let _e729 = (_e715 * _e728);
                                let _e730 = (_e718 * _e728);
                                let _e731 = (_e721 * _e728);
                                let _e736 = (((_e545 * _e729) + (_e546 * _e730)) + (_e547 * _e731));
                                let _e740 = (_e545 - (_e729 * _e736));
                                let _e741 = (_e546 - (_e730 * _e736));
                                let _e742 = (_e547 - (_e731 * _e736));
                                let _e748 = sqrt((((_e740 * _e740) + (_e741 * _e741)) + (_e742 * _e742)));
                                let _e753 = (((_e710 * _e740) + (_e711 * _e741)) + (_e712 * _e742));
                                let _e763 = ((((_e740 * _e484) + (_e741 * _e485)) + (_e742 * _e486)) / _e748);
                                let _e767 = select(0f, select(1f, _e763, (_e763 < 1f)), (_e763 > 0f));
                                let _e768 = abs(_e767);
                                let _e779 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e768, 0.00667009f), _e768, -0.017088126f), _e768, 0.03089188f), _e768, -0.050174303f), _e768, 0.08897899f), _e768, -0.2145988f), _e768, 1.5707963f) * sqrt((1f - _e768)));
                                let _e782 = (select(select(0f, -1f, (_e753 < 0f)), 1f, (_e753 > 0f)) * select((3.1415927f - _e779), _e779, (_e767 >= 0f)));
                                let _e785 = select(1u, _e225.member_9, (1u < _e225.member_9));
                                phi_1199_ = 0u;
                                phi_1202_ = 0u;
                                loop {
                                    let _e787 = phi_1199_;
                                    let _e789 = phi_1202_;
                                    local_9 = _e789;
                                    local_10 = _e789;
                                    local_12 = _e789;
                                    let _e790 = (_e787 < _e785);
                                    if _e790 {
                                        let _e796 = ((_e668 - floor(_e668)) + (f32(bitcast<i32>((_e686 + (_e787 * _e785)))) * 0.618034f));
                                        let _e805 = (((_e796 - floor(_e796)) + f32(bitcast<i32>(_e787))) * (1f / f32(bitcast<i32>(_e785))));
                                        if (_e225.member_4 == 2f) {
                                            phi_1260_ = (_e805 * _e805);
                                        } else {
                                            if (_e225.member_4 == 1f) {
                                                phi_1259_ = _e805;
                                            } else {
                                                phi_1259_ = pow(_e805, _e225.member_4);
                                            }
                                            let _e811 = phi_1259_;
                                            phi_1260_ = _e811;
                                        }
                                        let _e814 = phi_1260_;
                                        let _e815 = (_e814 + (1.3f / _e554));
                                        let _e816 = ((_e700 * _e554) * _e815);
                                        let _e817 = ((-(_e699) * _e554) * _e815);
                                        let _e820 = ((_e816 * _e816) + (_e817 * _e817));
                                        let _e825 = (select(1u, _e249, (1u < _e249)) * select(1u, _e257, (1u < _e257)));
                                        let _e826 = (_e820 > _e674);
                                        let _e830 = (_e249 >> bitcast<u32>(1u));
                                        let _e834 = (_e257 >> bitcast<u32>(1u));
                                        let _e838 = (_e825 + (select(1u, _e830, (1u < _e830)) * select(1u, _e834, (1u < _e834))));
                                        let _e840 = (_e820 > (_e674 * 4f));
                                        let _e844 = (_e249 >> bitcast<u32>(2u));
                                        let _e848 = (_e257 >> bitcast<u32>(2u));
                                        let _e852 = (_e838 + (select(1u, _e844, (1u < _e844)) * select(1u, _e848, (1u < _e848))));
                                        let _e854 = (_e820 > (_e674 * 16f));
                                        let _e858 = (_e249 >> bitcast<u32>(3u));
                                        let _e862 = (_e257 >> bitcast<u32>(3u));
                                        let _e868 = (_e820 > (_e674 * 64f));
                                        let _e870 = select(select(select(select(0u, _e825, _e826), _e838, _e840), _e852, _e854), (_e852 + (select(1u, _e858, (1u < _e858)) * select(1u, _e862, (1u < _e862)))), _e868);
                                        let _e871 = (select(select(select(select(0u, 1u, _e826), 2u, _e840), 3u, _e854), 4u, _e868) & 31u);
                                        let _e873 = (_e249 >> bitcast<u32>(_e871));
                                        let _e875 = select(1u, _e873, (1u < _e873));
                                        let _e877 = (_e257 >> bitcast<u32>(_e871));
                                        let _e879 = select(1u, _e877, (1u < _e877));
                                        let _e882 = (round(_e816) * (1f / _e225.member.member.x));
                                        let _e885 = (round(_e817) * (1f / _e225.member.member.y));
                                        let _e886 = (_e455 + _e882);
                                        let _e887 = (_e458 + _e885);
                                        let _e888 = (_e455 - _e882);
                                        let _e889 = (_e458 - _e885);
                                        let _e891 = f32(bitcast<i32>(_e875));
                                        let _e892 = (_e886 * _e891);
                                        let _e895 = f32(bitcast<i32>((_e875 - 1u)));
                                        let _e905 = f32(bitcast<i32>(_e879));
                                        let _e906 = (_e887 * _e905);
                                        let _e909 = f32(bitcast<i32>((_e879 - 1u)));
                                        let _e923 = mips.member[((_e870 + ((bitcast<u32>((floor(select(0f, select(_e909, _e906, (_e906 < _e909)), (_e906 > 0f))) + 8388608f)) - 1258291200u) * _e875)) + (bitcast<u32>((floor(select(0f, select(_e895, _e892, (_e892 < _e895)), (_e892 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e927 = ((((_e886 * 2f) - 1f) * _e225.member.member_1.x) * _e923);
                                        let _e931 = ((((_e887 * -2f) + 1f) * _e225.member.member_1.y) * _e923);
                                        let _e932 = (_e888 * _e891);
                                        let _e941 = (_e889 * _e905);
                                        let _e955 = mips.member[((_e870 + ((bitcast<u32>((floor(select(0f, select(_e909, _e941, (_e941 < _e909)), (_e941 > 0f))) + 8388608f)) - 1258291200u) * _e875)) + (bitcast<u32>((floor(select(0f, select(_e895, _e932, (_e932 < _e895)), (_e932 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e959 = ((((_e888 * 2f) - 1f) * _e225.member.member_1.x) * _e955);
                                        let _e963 = ((((_e889 * -2f) + 1f) * _e225.member.member_1.y) * _e955);
                                        let _e964 = (_e927 - _e466);
                                        let _e965 = (_e931 - _e473);
                                        let _e966 = (_e923 - _e459);
                                        let _e971 = (((_e964 * _e964) + (_e965 * _e965)) + (_e966 * _e966));
                                        let _e972 = (_e241 > 0f);
                                        if _e972 {
                                            phi_1538_ = (_e971 > (_e241 * _e241));
                                        } else {
                                            phi_1538_ = false;
                                        }
                                        let _e976 = phi_1538_;
                                        if !(_e976) {
                                            let _e978 = (_e484 * _e238);
                                            let _e979 = (_e485 * _e238);
                                            let _e980 = (_e486 * _e238);
                                            let _e981 = (_e964 - _e978);
                                            let _e982 = (_e965 - _e979);
                                            let _e983 = (_e966 - _e980);
                                            let _e989 = (((_e964 * _e484) + (_e965 * _e485)) + (_e966 * _e486));
                                            let _e993 = (_e964 - (_e484 * _e989));
                                            let _e994 = (_e965 - (_e485 * _e989));
                                            let _e995 = (_e966 - (_e486 * _e989));
                                            let _e998 = ((_e994 * _e486) - (_e485 * _e995));
                                            let _e1001 = ((_e995 * _e484) - (_e486 * _e993));
                                            let _e1004 = ((_e993 * _e485) - (_e484 * _e994));
                                            let _e1015 = ((((_e545 * _e998) + (_e546 * _e1001)) + (_e547 * _e1004)) / (((_e998 * _e998) + (_e1001 * _e1001)) + (_e1004 * _e1004)));
                                            let _e1019 = (_e545 - (_e998 * _e1015));
                                            let _e1020 = (_e546 - (_e1001 * _e1015));
                                            let _e1021 = (_e547 - (_e1004 * _e1015));
                                            let _e1027 = inverseSqrt((((_e1019 * _e1019) + (_e1020 * _e1020)) + (_e1021 * _e1021)));
                                            let _e1033 = ((((_e1019 * _e484) + (_e1020 * _e485)) + (_e1021 * _e486)) * _e1027);
                                            let _e1037 = select(0f, select(1f, _e1033, (_e1033 < 1f)), (_e1033 > 0f));
                                            let _e1038 = abs(_e1037);
                                            let _e1048 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1038, 0.00667009f), _e1038, -0.017088126f), _e1038, 0.03089188f), _e1038, -0.050174303f), _e1038, 0.08897899f), _e1038, -0.2145988f), _e1038, 1.5707963f) * sqrt((1f - _e1038)));
                                            let _e1051 = select((3.1415927f - _e1048), _e1048, (_e1037 >= 0f));
                                            let _e1059 = select(_e1051, -(_e1051), ((((_e993 * _e1019) + (_e994 * _e1020)) + (_e995 * _e1021)) < 0f));
                                            let _e1060 = (_e1027 * 0.02f);
                                            let _e1063 = select(0.19634955f, _e1060, ((_e1060 < 0.19634955f) || false));
                                            let _e1069 = ((((_e993 * _e993) + (_e994 * _e994)) + (_e995 * _e995)) <= 0f);
                                            if _e972 {
                                                phi_1691_ = (_e971 <= (_e241 * _e241));
                                            } else {
                                                phi_1691_ = true;
                                            }
                                            let _e1073 = phi_1691_;
                                            let _e1082 = select(false, ((((_e964 * _e545) + (_e965 * _e546)) + (_e966 * _e547)) > (sqrt(_e971) * 0.018f)), _e1073);
                                            if _e1082 {
                                                let _e1083 = (0.5f / _e923);
                                                let _e1089 = frame.member[0u].member_1.member.member.member_1[0u];
                                                let _e1097 = frame.member[0u].member_1.member.member.member_1[1u];
                                                let _e1102 = frame.member[0u].member_1.member_5[0u];
                                                let _e1105 = frame.member[0u].member_1.member_5[1u];
                                                let _e1106 = f32(_e1102);
                                                let _e1107 = f32(_e1105);
                                                let _e1109 = frame.member[0u].member_1.member_4;
                                                let _e1110 = f32(_e1109);
                                                let _e1111 = (2u * _e1109);
                                                let _e1112 = (_e1102 + _e1111);
                                                let _e1116 = (floor(((((_e927 * _e1083) / _e1089) + 0.5f) * _e1106)) + _e1110);
                                                let _e1119 = f32(bitcast<i32>((_e1112 - 1u)));
                                                let _e1127 = (bitcast<u32>((floor(select(0f, select(_e1119, _e1116, (_e1116 < _e1119)), (_e1116 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e1130 = (floor(((0.5f - ((_e931 * _e1083) / _e1097)) * _e1107)) + _e1110);
                                                let _e1133 = f32(bitcast<i32>(((_e1105 + _e1111) - 1u)));
                                                let _e1141 = (bitcast<u32>((floor(select(0f, select(_e1133, _e1130, (_e1130 < _e1133)), (_e1130 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e1143 = frame.member[0u].member_1.member_8;
                                                let _e1145 = frame.member[0u].member_1.member_12;
                                                let _e1152 = (((((_e1141 % 4u) * 4u) + (_e1127 % 4u)) + (_e1145 % 16u)) % 16u);
                                                if (_e1143 == 1u) {
                                                    local_5 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    let _e1165 = (_e1152 < 16u);
                                                    if _e1165 {
                                                    } else {
                                                        phi_7179_ = true;
                                                        break;
                                                    }
                                                    let _e1168 = local_5[_e1152][0u];
                                                    local_6 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e1165 {
                                                    } else {
                                                        phi_7179_ = true;
                                                        break;
                                                    }
                                                    let _e1171 = local_6[_e1152][1u];
                                                    phi_1854_ = vec2<f32>(_e1168, _e1171);
                                                } else {
                                                    if (_e1143 == 2u) {
                                                        local_7 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        let _e1155 = (_e1152 < 16u);
                                                        if _e1155 {
                                                        } else {
                                                            phi_7179_ = true;
                                                            break;
                                                        }
                                                        let _e1158 = local_7[_e1152][0u];
                                                        local_8 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e1155 {
                                                        } else {
                                                            phi_7179_ = true;
                                                            break;
                                                        }
                                                        let _e1161 = local_8[_e1152][1u];
                                                        phi_1853_ = vec2<f32>(_e1158, _e1161);
                                                    } else {
                                                        phi_1853_ = vec2<f32>(0.5f, 0.5f);
                                                    }
                                                    let _e1164 = phi_1853_;
                                                    phi_1854_ = _e1164;
                                                }
                                                let _e1174 = phi_1854_;
                                                let _e1182 = (((f32(bitcast<i32>(_e1127)) - _e1110) + _e1174.x) * (1f / _e1106));
                                                let _e1188 = (((f32(bitcast<i32>(_e1141)) - _e1110) + _e1174.y) * (1f / _e1107));
                                                let _e1193 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e1198 = select(select(u32(_e1193), 0u, (_e1193 < 0f)), 4294967295u, (_e1193 > 4294967000f));
                                                let _e1203 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e1213 = (select(0f, select(1f, _e1182, (_e1182 < 1f)), (_e1182 > 0f)) * _e1193);
                                                let _e1216 = f32(bitcast<i32>((_e1198 - 1u)));
                                                let _e1229 = (select(0f, select(1f, _e1188, (_e1188 < 1f)), (_e1188 > 0f)) * _e1203);
                                                let _e1232 = f32(bitcast<i32>((select(select(u32(_e1203), 0u, (_e1203 < 0f)), 4294967295u, (_e1203 > 4294967000f)) - 1u)));
                                                let _e1244 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e1232, _e1229, (_e1229 < _e1232)), (_e1229 > 0f))) + 8388608f)) - 1258291200u) * _e1198) + (bitcast<u32>((floor(select(0f, select(_e1216, _e1213, (_e1213 < _e1216)), (_e1213 > 0f))) + 8388608f)) - 1258291200u))];
                                                let _e1250 = select(0x1.fffffep+127f, (_e923 * 1.001f), select(false, (abs((_e1244 - _e923)) <= _e238), _e1082));
                                                let _e1252 = frame.member[0u].member_1.member_6;
                                                let _e1255 = (((_e1141 * _e1112) + _e1127) * _e1252);
                                                let _e1257 = sd_map.member[_e1255];
                                                let _e1261 = frame.member[0u].member_1.member.member.member_3;
                                                let _e1265 = frame.member[0u].member_1.member.member.member_2;
                                                let _e1266 = (_e1261 - _e1265);
                                                let _e1268 = ((_e1257 * _e1266) + _e1265);
                                                let _e1274 = select(_e1261, _e1268, select(false, select(false, (_e1268 > _e1250), (_e1257 < 1f)), (0u < _e1252)));
                                                let _e1275 = (_e1252 - 1u);
                                                let _e1280 = sd_map.member[(_e1255 + select(1u, _e1275, (_e1275 < 1u)))];
                                                let _e1282 = ((_e1280 * _e1266) + _e1265);
                                                let _e1288 = select(_e1261, _e1282, select(false, select(false, (_e1282 > _e1250), (_e1280 < 1f)), (1u < _e1252)));
                                                let _e1293 = sd_map.member[(_e1255 + select(2u, _e1275, (_e1275 < 2u)))];
                                                let _e1295 = ((_e1293 * _e1266) + _e1265);
                                                let _e1301 = select(_e1261, _e1295, select(false, select(false, (_e1295 > _e1250), (_e1293 < 1f)), (2u < _e1252)));
                                                let _e1306 = sd_map.member[(_e1255 + select(3u, _e1275, (_e1275 < 3u)))];
                                                let _e1308 = ((_e1306 * _e1266) + _e1265);
                                                let _e1314 = select(_e1261, _e1308, select(false, select(false, (_e1308 > _e1250), (_e1306 < 1f)), (3u < _e1252)));
                                                if (_e1252 > 4u) {
                                                    let _e1320 = sd_map.member[(_e1255 + select(4u, _e1275, (_e1275 < 4u)))];
                                                    let _e1322 = ((_e1320 * _e1266) + _e1265);
                                                    let _e1333 = sd_map.member[(_e1255 + select(5u, _e1275, (_e1275 < 5u)))];
                                                    let _e1335 = ((_e1333 * _e1266) + _e1265);
                                                    let _e1346 = sd_map.member[(_e1255 + select(6u, _e1275, (_e1275 < 6u)))];
                                                    let _e1348 = ((_e1346 * _e1266) + _e1265);
                                                    let _e1359 = sd_map.member[(_e1255 + select(7u, _e1275, (_e1275 < 7u)))];
                                                    let _e1361 = ((_e1359 * _e1266) + _e1265);
                                                    phi_2292_ = select(_e1261, _e1348, select(false, select(false, (_e1348 > _e1250), (_e1346 < 1f)), (6u < _e1252)));
                                                    phi_2293_ = select(_e1261, _e1335, select(false, select(false, (_e1335 > _e1250), (_e1333 < 1f)), (5u < _e1252)));
                                                    phi_2294_ = select(_e1261, _e1322, select(false, select(false, (_e1322 > _e1250), (_e1320 < 1f)), (4u < _e1252)));
                                                    phi_2295_ = select(_e1261, _e1361, select(false, select(false, (_e1361 > _e1250), (_e1359 < 1f)), (7u < _e1252)));
                                                } else {
                                                    phi_2292_ = _e1261;
                                                    phi_2293_ = _e1261;
                                                    phi_2294_ = _e1261;
                                                    phi_2295_ = _e1261;
                                                }
                                                let _e1369 = phi_2292_;
                                                let _e1371 = phi_2293_;
                                                let _e1373 = phi_2294_;
                                                let _e1375 = phi_2295_;
                                                let _e1377 = (_e1288 != _e1288);
                                                let _e1379 = select(_e1288, _e1274, ((_e1274 < _e1288) || _e1377));
                                                let _e1382 = select(_e1288, _e1274, ((_e1274 > _e1288) || _e1377));
                                                let _e1384 = (_e1314 != _e1314);
                                                let _e1386 = select(_e1314, _e1301, ((_e1301 < _e1314) || _e1384));
                                                let _e1389 = select(_e1314, _e1301, ((_e1301 > _e1314) || _e1384));
                                                let _e1391 = (_e1371 != _e1371);
                                                let _e1393 = select(_e1371, _e1373, ((_e1373 < _e1371) || _e1391));
                                                let _e1396 = select(_e1371, _e1373, ((_e1373 > _e1371) || _e1391));
                                                let _e1398 = (_e1375 != _e1375);
                                                let _e1400 = select(_e1375, _e1369, ((_e1369 < _e1375) || _e1398));
                                                let _e1403 = select(_e1375, _e1369, ((_e1369 > _e1375) || _e1398));
                                                let _e1405 = (_e1386 != _e1386);
                                                let _e1407 = select(_e1386, _e1379, ((_e1379 < _e1386) || _e1405));
                                                let _e1410 = select(_e1386, _e1379, ((_e1379 > _e1386) || _e1405));
                                                let _e1412 = (_e1389 != _e1389);
                                                let _e1414 = select(_e1389, _e1382, ((_e1382 < _e1389) || _e1412));
                                                let _e1417 = select(_e1389, _e1382, ((_e1382 > _e1389) || _e1412));
                                                let _e1419 = (_e1400 != _e1400);
                                                let _e1421 = select(_e1400, _e1393, ((_e1393 < _e1400) || _e1419));
                                                let _e1424 = select(_e1400, _e1393, ((_e1393 > _e1400) || _e1419));
                                                let _e1426 = (_e1403 != _e1403);
                                                let _e1428 = select(_e1403, _e1396, ((_e1396 < _e1403) || _e1426));
                                                let _e1431 = select(_e1403, _e1396, ((_e1396 > _e1403) || _e1426));
                                                let _e1433 = (_e1410 != _e1410);
                                                let _e1435 = select(_e1410, _e1414, ((_e1414 < _e1410) || _e1433));
                                                let _e1438 = select(_e1410, _e1414, ((_e1414 > _e1410) || _e1433));
                                                let _e1440 = (_e1424 != _e1424);
                                                let _e1442 = select(_e1424, _e1428, ((_e1428 < _e1424) || _e1440));
                                                let _e1445 = select(_e1424, _e1428, ((_e1428 > _e1424) || _e1440));
                                                let _e1447 = (_e1421 != _e1421);
                                                let _e1449 = select(_e1421, _e1407, ((_e1407 < _e1421) || _e1447));
                                                let _e1452 = select(_e1421, _e1407, ((_e1407 > _e1421) || _e1447));
                                                let _e1454 = (_e1442 != _e1442);
                                                let _e1456 = select(_e1442, _e1435, ((_e1435 < _e1442) || _e1454));
                                                let _e1459 = select(_e1442, _e1435, ((_e1435 > _e1442) || _e1454));
                                                let _e1461 = (_e1445 != _e1445);
                                                let _e1463 = select(_e1445, _e1438, ((_e1438 < _e1445) || _e1461));
                                                let _e1466 = select(_e1445, _e1438, ((_e1438 > _e1445) || _e1461));
                                                let _e1468 = (_e1431 != _e1431);
                                                let _e1470 = select(_e1431, _e1417, ((_e1417 < _e1431) || _e1468));
                                                let _e1473 = select(_e1431, _e1417, ((_e1417 > _e1431) || _e1468));
                                                let _e1475 = (_e1452 != _e1452);
                                                let _e1477 = select(_e1452, _e1463, ((_e1463 < _e1452) || _e1475));
                                                let _e1480 = select(_e1452, _e1463, ((_e1463 > _e1452) || _e1475));
                                                let _e1482 = (_e1459 != _e1459);
                                                let _e1484 = select(_e1459, _e1470, ((_e1470 < _e1459) || _e1482));
                                                let _e1487 = select(_e1459, _e1470, ((_e1470 > _e1459) || _e1482));
                                                let _e1489 = (_e1477 != _e1477);
                                                let _e1491 = select(_e1477, _e1456, ((_e1456 < _e1477) || _e1489));
                                                let _e1494 = select(_e1477, _e1456, ((_e1456 > _e1477) || _e1489));
                                                let _e1496 = (_e1480 != _e1480);
                                                let _e1498 = select(_e1480, _e1484, ((_e1484 < _e1480) || _e1496));
                                                let _e1501 = select(_e1480, _e1484, ((_e1484 > _e1480) || _e1496));
                                                let _e1503 = (_e1466 != _e1466);
                                                let _e1505 = select(_e1466, _e1487, ((_e1487 < _e1466) || _e1503));
                                                let _e1508 = select(_e1466, _e1487, ((_e1487 > _e1466) || _e1503));
                                                let _e1512 = select(false, (_e1449 > (_e923 + _e238)), (_e1449 < _e1261));
                                                let _e1514 = ((_e1182 * 2f) - 1f);
                                                let _e1518 = ((_e1188 * -2f) + 1f);
                                                let _e1528 = (_e1514 * _e225.member.member_1.x);
                                                let _e1530 = (_e1518 * _e225.member.member_1.y);
                                                let _e1532 = ((_e1528 * _e1491) - _e466);
                                                let _e1533 = ((_e1530 * _e1491) - _e473);
                                                let _e1534 = (_e1491 - _e459);
                                                if _e972 {
                                                    phi_2637_ = ((((_e1532 * _e1532) + (_e1533 * _e1533)) + (_e1534 * _e1534)) <= (_e241 * _e241));
                                                } else {
                                                    phi_2637_ = true;
                                                }
                                                let _e1543 = phi_2637_;
                                                let _e1545 = select(false, _e1543, (_e1491 < _e225.member.member_3));
                                                if _e1545 {
                                                    let _e1546 = (_e1494 < _e225.member.member_3);
                                                    let _e1555 = select((_e1532 - _e978), ((_e1528 * _e1494) - _e466), _e1546);
                                                    let _e1556 = select((_e1533 - _e979), ((_e1530 * _e1494) - _e473), _e1546);
                                                    let _e1557 = select((_e1534 - _e980), (_e1494 - _e459), _e1546);
                                                    let _e1569 = ((((_e1532 * _e484) + (_e1533 * _e485)) + (_e1534 * _e486)) * inverseSqrt((((_e1532 * _e1532) + (_e1533 * _e1533)) + (_e1534 * _e1534))));
                                                    let _e1573 = select(-1f, select(1f, _e1569, (_e1569 < 1f)), (_e1569 > -1f));
                                                    let _e1574 = abs(_e1573);
                                                    let _e1584 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1574, 0.00667009f), _e1574, -0.017088126f), _e1574, 0.03089188f), _e1574, -0.050174303f), _e1574, 0.08897899f), _e1574, -0.2145988f), _e1574, 1.5707963f) * sqrt((1f - _e1574)));
                                                    let _e1591 = ((((select((3.1415927f - _e1584), _e1584, (_e1573 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1595 = select(0f, select(1f, _e1591, (_e1591 < 1f)), (_e1591 > 0f));
                                                    let _e1607 = ((((_e1555 * _e484) + (_e1556 * _e485)) + (_e1557 * _e486)) * inverseSqrt((((_e1555 * _e1555) + (_e1556 * _e1556)) + (_e1557 * _e1557))));
                                                    let _e1611 = select(-1f, select(1f, _e1607, (_e1607 < 1f)), (_e1607 > -1f));
                                                    let _e1612 = abs(_e1611);
                                                    let _e1622 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1612, 0.00667009f), _e1612, -0.017088126f), _e1612, 0.03089188f), _e1612, -0.050174303f), _e1612, 0.08897899f), _e1612, -0.2145988f), _e1612, 1.5707963f) * sqrt((1f - _e1612)));
                                                    let _e1629 = ((((select((3.1415927f - _e1622), _e1622, (_e1611 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1633 = select(0f, select(1f, _e1629, (_e1629 < 1f)), (_e1629 > 0f));
                                                    let _e1635 = (_e1633 != _e1633);
                                                    let _e1637 = select(_e1633, _e1595, ((_e1595 < _e1633) || _e1635));
                                                    let _e1640 = select(_e1633, _e1595, ((_e1595 > _e1633) || _e1635));
                                                    let _e1642 = floor((_e1637 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1650 = -(floor((_e1640 * -32f)));
                                                        let _e1655 = (select(32f, _e1650, ((_e1650 < 32f) || false)) - _e1642);
                                                        phi_2864_ = select(select(0f, _e1655, ((_e1655 > 0f) || false)), 0f, (_e1640 <= _e1637));
                                                    } else {
                                                        phi_2864_ = -(floor(((_e1640 - _e1637) * -32f)));
                                                    }
                                                    let _e1661 = phi_2864_;
                                                    let _e1669 = (bitcast<u32>((floor(select(0f, select(32f, _e1642, (_e1642 < 32f)), (_e1642 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1677 = (bitcast<u32>((floor(select(0f, select(32f, _e1661, (_e1661 < 32f)), (_e1661 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1669 >= 32u) {
                                                        phi_2918_ = u32();
                                                        phi_2919_ = true;
                                                    } else {
                                                        let _e1679 = (_e1677 == 0u);
                                                        if _e1679 {
                                                            phi_2917_ = u32();
                                                        } else {
                                                            if (_e1677 >= 32u) {
                                                                phi_2914_ = 4294967295u;
                                                            } else {
                                                                phi_2914_ = ((1u << bitcast<u32>((_e1677 & 31u))) - 1u);
                                                            }
                                                            let _e1686 = phi_2914_;
                                                            phi_2917_ = (_e1686 << bitcast<u32>((_e1669 & 31u)));
                                                        }
                                                        let _e1691 = phi_2917_;
                                                        phi_2918_ = _e1691;
                                                        phi_2919_ = _e1679;
                                                    }
                                                    let _e1693 = phi_2918_;
                                                    let _e1695 = phi_2919_;
                                                    phi_2932_ = select(0u, select(select(_e1693, 0u, _e1695), 0u, _e1069), _e1545);
                                                } else {
                                                    phi_2932_ = 0u;
                                                }
                                                let _e1700 = phi_2932_;
                                                let _e1703 = ((_e1528 * _e1498) - _e466);
                                                let _e1704 = ((_e1530 * _e1498) - _e473);
                                                let _e1705 = (_e1498 - _e459);
                                                if _e972 {
                                                    phi_2963_ = ((((_e1703 * _e1703) + (_e1704 * _e1704)) + (_e1705 * _e1705)) <= (_e241 * _e241));
                                                } else {
                                                    phi_2963_ = true;
                                                }
                                                let _e1714 = phi_2963_;
                                                let _e1716 = select(false, _e1714, (_e1498 < _e225.member.member_3));
                                                if _e1716 {
                                                    let _e1717 = (_e1501 < _e225.member.member_3);
                                                    let _e1726 = select((_e1703 - _e978), ((_e1528 * _e1501) - _e466), _e1717);
                                                    let _e1727 = select((_e1704 - _e979), ((_e1530 * _e1501) - _e473), _e1717);
                                                    let _e1728 = select((_e1705 - _e980), (_e1501 - _e459), _e1717);
                                                    let _e1740 = ((((_e1703 * _e484) + (_e1704 * _e485)) + (_e1705 * _e486)) * inverseSqrt((((_e1703 * _e1703) + (_e1704 * _e1704)) + (_e1705 * _e1705))));
                                                    let _e1744 = select(-1f, select(1f, _e1740, (_e1740 < 1f)), (_e1740 > -1f));
                                                    let _e1745 = abs(_e1744);
                                                    let _e1755 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1745, 0.00667009f), _e1745, -0.017088126f), _e1745, 0.03089188f), _e1745, -0.050174303f), _e1745, 0.08897899f), _e1745, -0.2145988f), _e1745, 1.5707963f) * sqrt((1f - _e1745)));
                                                    let _e1762 = ((((select((3.1415927f - _e1755), _e1755, (_e1744 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1766 = select(0f, select(1f, _e1762, (_e1762 < 1f)), (_e1762 > 0f));
                                                    let _e1778 = ((((_e1726 * _e484) + (_e1727 * _e485)) + (_e1728 * _e486)) * inverseSqrt((((_e1726 * _e1726) + (_e1727 * _e1727)) + (_e1728 * _e1728))));
                                                    let _e1782 = select(-1f, select(1f, _e1778, (_e1778 < 1f)), (_e1778 > -1f));
                                                    let _e1783 = abs(_e1782);
                                                    let _e1793 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1783, 0.00667009f), _e1783, -0.017088126f), _e1783, 0.03089188f), _e1783, -0.050174303f), _e1783, 0.08897899f), _e1783, -0.2145988f), _e1783, 1.5707963f) * sqrt((1f - _e1783)));
                                                    let _e1800 = ((((select((3.1415927f - _e1793), _e1793, (_e1782 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1804 = select(0f, select(1f, _e1800, (_e1800 < 1f)), (_e1800 > 0f));
                                                    let _e1806 = (_e1804 != _e1804);
                                                    let _e1808 = select(_e1804, _e1766, ((_e1766 < _e1804) || _e1806));
                                                    let _e1811 = select(_e1804, _e1766, ((_e1766 > _e1804) || _e1806));
                                                    let _e1813 = floor((_e1808 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1821 = -(floor((_e1811 * -32f)));
                                                        let _e1826 = (select(32f, _e1821, ((_e1821 < 32f) || false)) - _e1813);
                                                        phi_3190_ = select(select(0f, _e1826, ((_e1826 > 0f) || false)), 0f, (_e1811 <= _e1808));
                                                    } else {
                                                        phi_3190_ = -(floor(((_e1811 - _e1808) * -32f)));
                                                    }
                                                    let _e1832 = phi_3190_;
                                                    let _e1840 = (bitcast<u32>((floor(select(0f, select(32f, _e1813, (_e1813 < 32f)), (_e1813 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1848 = (bitcast<u32>((floor(select(0f, select(32f, _e1832, (_e1832 < 32f)), (_e1832 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1840 >= 32u) {
                                                        phi_3244_ = u32();
                                                        phi_3245_ = true;
                                                    } else {
                                                        let _e1850 = (_e1848 == 0u);
                                                        if _e1850 {
                                                            phi_3243_ = u32();
                                                        } else {
                                                            if (_e1848 >= 32u) {
                                                                phi_3240_ = 4294967295u;
                                                            } else {
                                                                phi_3240_ = ((1u << bitcast<u32>((_e1848 & 31u))) - 1u);
                                                            }
                                                            let _e1857 = phi_3240_;
                                                            phi_3243_ = (_e1857 << bitcast<u32>((_e1840 & 31u)));
                                                        }
                                                        let _e1862 = phi_3243_;
                                                        phi_3244_ = _e1862;
                                                        phi_3245_ = _e1850;
                                                    }
                                                    let _e1864 = phi_3244_;
                                                    let _e1866 = phi_3245_;
                                                    phi_3258_ = select(0u, select(select(_e1864, 0u, _e1866), 0u, _e1069), _e1716);
                                                } else {
                                                    phi_3258_ = 0u;
                                                }
                                                let _e1871 = phi_3258_;
                                                let _e1875 = ((_e1528 * _e1505) - _e466);
                                                let _e1876 = ((_e1530 * _e1505) - _e473);
                                                let _e1877 = (_e1505 - _e459);
                                                if _e972 {
                                                    phi_3290_ = ((((_e1875 * _e1875) + (_e1876 * _e1876)) + (_e1877 * _e1877)) <= (_e241 * _e241));
                                                } else {
                                                    phi_3290_ = true;
                                                }
                                                let _e1886 = phi_3290_;
                                                let _e1888 = select(false, _e1886, (_e1505 < _e225.member.member_3));
                                                if _e1888 {
                                                    let _e1889 = (_e1508 < _e225.member.member_3);
                                                    let _e1898 = select((_e1875 - _e978), ((_e1528 * _e1508) - _e466), _e1889);
                                                    let _e1899 = select((_e1876 - _e979), ((_e1530 * _e1508) - _e473), _e1889);
                                                    let _e1900 = select((_e1877 - _e980), (_e1508 - _e459), _e1889);
                                                    let _e1912 = ((((_e1875 * _e484) + (_e1876 * _e485)) + (_e1877 * _e486)) * inverseSqrt((((_e1875 * _e1875) + (_e1876 * _e1876)) + (_e1877 * _e1877))));
                                                    let _e1916 = select(-1f, select(1f, _e1912, (_e1912 < 1f)), (_e1912 > -1f));
                                                    let _e1917 = abs(_e1916);
                                                    let _e1927 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1917, 0.00667009f), _e1917, -0.017088126f), _e1917, 0.03089188f), _e1917, -0.050174303f), _e1917, 0.08897899f), _e1917, -0.2145988f), _e1917, 1.5707963f) * sqrt((1f - _e1917)));
                                                    let _e1934 = ((((select((3.1415927f - _e1927), _e1927, (_e1916 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1938 = select(0f, select(1f, _e1934, (_e1934 < 1f)), (_e1934 > 0f));
                                                    let _e1950 = ((((_e1898 * _e484) + (_e1899 * _e485)) + (_e1900 * _e486)) * inverseSqrt((((_e1898 * _e1898) + (_e1899 * _e1899)) + (_e1900 * _e1900))));
                                                    let _e1954 = select(-1f, select(1f, _e1950, (_e1950 < 1f)), (_e1950 > -1f));
                                                    let _e1955 = abs(_e1954);
                                                    let _e1965 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1955, 0.00667009f), _e1955, -0.017088126f), _e1955, 0.03089188f), _e1955, -0.050174303f), _e1955, 0.08897899f), _e1955, -0.2145988f), _e1955, 1.5707963f) * sqrt((1f - _e1955)));
                                                    let _e1972 = ((((select((3.1415927f - _e1965), _e1965, (_e1954 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1976 = select(0f, select(1f, _e1972, (_e1972 < 1f)), (_e1972 > 0f));
                                                    let _e1978 = (_e1976 != _e1976);
                                                    let _e1980 = select(_e1976, _e1938, ((_e1938 < _e1976) || _e1978));
                                                    let _e1983 = select(_e1976, _e1938, ((_e1938 > _e1976) || _e1978));
                                                    let _e1985 = floor((_e1980 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1993 = -(floor((_e1983 * -32f)));
                                                        let _e1998 = (select(32f, _e1993, ((_e1993 < 32f) || false)) - _e1985);
                                                        phi_3517_ = select(select(0f, _e1998, ((_e1998 > 0f) || false)), 0f, (_e1983 <= _e1980));
                                                    } else {
                                                        phi_3517_ = -(floor(((_e1983 - _e1980) * -32f)));
                                                    }
                                                    let _e2004 = phi_3517_;
                                                    let _e2012 = (bitcast<u32>((floor(select(0f, select(32f, _e1985, (_e1985 < 32f)), (_e1985 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2020 = (bitcast<u32>((floor(select(0f, select(32f, _e2004, (_e2004 < 32f)), (_e2004 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2012 >= 32u) {
                                                        phi_3571_ = u32();
                                                        phi_3572_ = true;
                                                    } else {
                                                        let _e2022 = (_e2020 == 0u);
                                                        if _e2022 {
                                                            phi_3570_ = u32();
                                                        } else {
                                                            if (_e2020 >= 32u) {
                                                                phi_3567_ = 4294967295u;
                                                            } else {
                                                                phi_3567_ = ((1u << bitcast<u32>((_e2020 & 31u))) - 1u);
                                                            }
                                                            let _e2029 = phi_3567_;
                                                            phi_3570_ = (_e2029 << bitcast<u32>((_e2012 & 31u)));
                                                        }
                                                        let _e2034 = phi_3570_;
                                                        phi_3571_ = _e2034;
                                                        phi_3572_ = _e2022;
                                                    }
                                                    let _e2036 = phi_3571_;
                                                    let _e2038 = phi_3572_;
                                                    phi_3585_ = select(0u, select(select(_e2036, 0u, _e2038), 0u, _e1069), _e1888);
                                                } else {
                                                    phi_3585_ = 0u;
                                                }
                                                let _e2043 = phi_3585_;
                                                let _e2047 = ((_e1528 * _e1473) - _e466);
                                                let _e2048 = ((_e1530 * _e1473) - _e473);
                                                let _e2049 = (_e1473 - _e459);
                                                if _e972 {
                                                    phi_3617_ = ((((_e2047 * _e2047) + (_e2048 * _e2048)) + (_e2049 * _e2049)) <= (_e241 * _e241));
                                                } else {
                                                    phi_3617_ = true;
                                                }
                                                let _e2058 = phi_3617_;
                                                let _e2060 = select(false, _e2058, (_e1473 < _e225.member.member_3));
                                                if _e2060 {
                                                    let _e2061 = (_e1261 < _e225.member.member_3);
                                                    let _e2070 = select((_e2047 - _e978), ((_e1528 * _e1261) - _e466), _e2061);
                                                    let _e2071 = select((_e2048 - _e979), ((_e1530 * _e1261) - _e473), _e2061);
                                                    let _e2072 = select((_e2049 - _e980), (_e1261 - _e459), _e2061);
                                                    let _e2084 = ((((_e2047 * _e484) + (_e2048 * _e485)) + (_e2049 * _e486)) * inverseSqrt((((_e2047 * _e2047) + (_e2048 * _e2048)) + (_e2049 * _e2049))));
                                                    let _e2088 = select(-1f, select(1f, _e2084, (_e2084 < 1f)), (_e2084 > -1f));
                                                    let _e2089 = abs(_e2088);
                                                    let _e2099 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2089, 0.00667009f), _e2089, -0.017088126f), _e2089, 0.03089188f), _e2089, -0.050174303f), _e2089, 0.08897899f), _e2089, -0.2145988f), _e2089, 1.5707963f) * sqrt((1f - _e2089)));
                                                    let _e2106 = ((((select((3.1415927f - _e2099), _e2099, (_e2088 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e2110 = select(0f, select(1f, _e2106, (_e2106 < 1f)), (_e2106 > 0f));
                                                    let _e2122 = ((((_e2070 * _e484) + (_e2071 * _e485)) + (_e2072 * _e486)) * inverseSqrt((((_e2070 * _e2070) + (_e2071 * _e2071)) + (_e2072 * _e2072))));
                                                    let _e2126 = select(-1f, select(1f, _e2122, (_e2122 < 1f)), (_e2122 > -1f));
                                                    let _e2127 = abs(_e2126);
                                                    let _e2137 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2127, 0.00667009f), _e2127, -0.017088126f), _e2127, 0.03089188f), _e2127, -0.050174303f), _e2127, 0.08897899f), _e2127, -0.2145988f), _e2127, 1.5707963f) * sqrt((1f - _e2127)));
                                                    let _e2144 = ((((select((3.1415927f - _e2137), _e2137, (_e2126 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e2148 = select(0f, select(1f, _e2144, (_e2144 < 1f)), (_e2144 > 0f));
                                                    let _e2150 = (_e2148 != _e2148);
                                                    let _e2152 = select(_e2148, _e2110, ((_e2110 < _e2148) || _e2150));
                                                    let _e2155 = select(_e2148, _e2110, ((_e2110 > _e2148) || _e2150));
                                                    let _e2157 = floor((_e2152 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e2165 = -(floor((_e2155 * -32f)));
                                                        let _e2170 = (select(32f, _e2165, ((_e2165 < 32f) || false)) - _e2157);
                                                        phi_3844_ = select(select(0f, _e2170, ((_e2170 > 0f) || false)), 0f, (_e2155 <= _e2152));
                                                    } else {
                                                        phi_3844_ = -(floor(((_e2155 - _e2152) * -32f)));
                                                    }
                                                    let _e2176 = phi_3844_;
                                                    let _e2184 = (bitcast<u32>((floor(select(0f, select(32f, _e2157, (_e2157 < 32f)), (_e2157 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2192 = (bitcast<u32>((floor(select(0f, select(32f, _e2176, (_e2176 < 32f)), (_e2176 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2184 >= 32u) {
                                                        phi_3898_ = u32();
                                                        phi_3899_ = true;
                                                    } else {
                                                        let _e2194 = (_e2192 == 0u);
                                                        if _e2194 {
                                                            phi_3897_ = u32();
                                                        } else {
                                                            if (_e2192 >= 32u) {
                                                                phi_3894_ = 4294967295u;
                                                            } else {
                                                                phi_3894_ = ((1u << bitcast<u32>((_e2192 & 31u))) - 1u);
                                                            }
                                                            let _e2201 = phi_3894_;
                                                            phi_3897_ = (_e2201 << bitcast<u32>((_e2184 & 31u)));
                                                        }
                                                        let _e2206 = phi_3897_;
                                                        phi_3898_ = _e2206;
                                                        phi_3899_ = _e2194;
                                                    }
                                                    let _e2208 = phi_3898_;
                                                    let _e2210 = phi_3899_;
                                                    phi_3912_ = select(0u, select(select(_e2208, 0u, _e2210), 0u, _e1069), _e2060);
                                                } else {
                                                    phi_3912_ = 0u;
                                                }
                                                let _e2215 = phi_3912_;
                                                phi_3914_ = (((_e1700 | _e1871) | _e2043) | _e2215);
                                                phi_3915_ = vec3<f32>(select(_e981, (((_e1514 * _e1089) * _e1449) - _e466), _e1512), select(_e982, (((_e1518 * _e1097) * _e1449) - _e473), _e1512), select(_e983, (_e1449 - _e459), _e1512));
                                            } else {
                                                phi_3914_ = 0u;
                                                phi_3915_ = vec3<f32>(_e981, _e982, _e983);
                                            }
                                            let _e2218 = phi_3914_;
                                            let _e2220 = phi_3915_;
                                            let _e2222 = (_e989 * inverseSqrt(_e971));
                                            let _e2226 = select(-1f, select(1f, _e2222, (_e2222 < 1f)), (_e2222 > -1f));
                                            let _e2227 = abs(_e2226);
                                            let _e2237 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2227, 0.00667009f), _e2227, -0.017088126f), _e2227, 0.03089188f), _e2227, -0.050174303f), _e2227, 0.08897899f), _e2227, -0.2145988f), _e2227, 1.5707963f) * sqrt((1f - _e2227)));
                                            let _e2244 = ((((select((3.1415927f - _e2237), _e2237, (_e2226 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                            let _e2248 = select(0f, select(1f, _e2244, (_e2244 < 1f)), (_e2244 > 0f));
                                            let _e2263 = ((((_e2220.x * _e484) + (_e2220.y * _e485)) + (_e2220.z * _e486)) * inverseSqrt((((_e2220.x * _e2220.x) + (_e2220.y * _e2220.y)) + (_e2220.z * _e2220.z))));
                                            let _e2267 = select(-1f, select(1f, _e2263, (_e2263 < 1f)), (_e2263 > -1f));
                                            let _e2268 = abs(_e2267);
                                            let _e2278 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2268, 0.00667009f), _e2268, -0.017088126f), _e2268, 0.03089188f), _e2268, -0.050174303f), _e2268, 0.08897899f), _e2268, -0.2145988f), _e2268, 1.5707963f) * sqrt((1f - _e2268)));
                                            let _e2285 = ((((select((3.1415927f - _e2278), _e2278, (_e2267 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                            let _e2289 = select(0f, select(1f, _e2285, (_e2285 < 1f)), (_e2285 > 0f));
                                            let _e2291 = (_e2289 != _e2289);
                                            let _e2293 = select(_e2289, _e2248, ((_e2248 < _e2289) || _e2291));
                                            let _e2296 = select(_e2289, _e2248, ((_e2248 > _e2289) || _e2291));
                                            let _e2298 = floor((_e2293 * 32f));
                                            if (_e235 == 1u) {
                                                let _e2306 = -(floor((_e2296 * -32f)));
                                                let _e2311 = (select(32f, _e2306, ((_e2306 < 32f) || false)) - _e2298);
                                                phi_4102_ = select(select(0f, _e2311, ((_e2311 > 0f) || false)), 0f, (_e2296 <= _e2293));
                                            } else {
                                                phi_4102_ = -(floor(((_e2296 - _e2293) * -32f)));
                                            }
                                            let _e2317 = phi_4102_;
                                            let _e2325 = (bitcast<u32>((floor(select(0f, select(32f, _e2298, (_e2298 < 32f)), (_e2298 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e2333 = (bitcast<u32>((floor(select(0f, select(32f, _e2317, (_e2317 < 32f)), (_e2317 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e2325 >= 32u) {
                                                phi_4156_ = u32();
                                                phi_4157_ = true;
                                            } else {
                                                let _e2335 = (_e2333 == 0u);
                                                if _e2335 {
                                                    phi_4155_ = u32();
                                                } else {
                                                    if (_e2333 >= 32u) {
                                                        phi_4152_ = 4294967295u;
                                                    } else {
                                                        phi_4152_ = ((1u << bitcast<u32>((_e2333 & 31u))) - 1u);
                                                    }
                                                    let _e2342 = phi_4152_;
                                                    phi_4155_ = (_e2342 << bitcast<u32>((_e2325 & 31u)));
                                                }
                                                let _e2347 = phi_4155_;
                                                phi_4156_ = _e2347;
                                                phi_4157_ = _e2335;
                                            }
                                            let _e2349 = phi_4156_;
                                            let _e2351 = phi_4157_;
                                            phi_4171_ = select((select(select(_e2349, 0u, _e2351), 0u, _e1069) | _e2218), 0u, _e976);
                                        } else {
                                            phi_4171_ = 0u;
                                        }
                                        let _e2357 = phi_4171_;
                                        let _e2359 = (_e959 - _e466);
                                        let _e2360 = (_e963 - _e473);
                                        let _e2361 = (_e955 - _e459);
                                        let _e2366 = (((_e2359 * _e2359) + (_e2360 * _e2360)) + (_e2361 * _e2361));
                                        if _e972 {
                                            phi_4191_ = (_e2366 > (_e241 * _e241));
                                        } else {
                                            phi_4191_ = false;
                                        }
                                        let _e2370 = phi_4191_;
                                        if !(_e2370) {
                                            let _e2372 = (_e484 * _e238);
                                            let _e2373 = (_e485 * _e238);
                                            let _e2374 = (_e486 * _e238);
                                            let _e2375 = (_e2359 - _e2372);
                                            let _e2376 = (_e2360 - _e2373);
                                            let _e2377 = (_e2361 - _e2374);
                                            let _e2383 = (((_e2359 * _e484) + (_e2360 * _e485)) + (_e2361 * _e486));
                                            let _e2387 = (_e2359 - (_e484 * _e2383));
                                            let _e2388 = (_e2360 - (_e485 * _e2383));
                                            let _e2389 = (_e2361 - (_e486 * _e2383));
                                            let _e2392 = ((_e2388 * _e486) - (_e485 * _e2389));
                                            let _e2395 = ((_e2389 * _e484) - (_e486 * _e2387));
                                            let _e2398 = ((_e2387 * _e485) - (_e484 * _e2388));
                                            let _e2409 = ((((_e545 * _e2392) + (_e546 * _e2395)) + (_e547 * _e2398)) / (((_e2392 * _e2392) + (_e2395 * _e2395)) + (_e2398 * _e2398)));
                                            let _e2413 = (_e545 - (_e2392 * _e2409));
                                            let _e2414 = (_e546 - (_e2395 * _e2409));
                                            let _e2415 = (_e547 - (_e2398 * _e2409));
                                            let _e2421 = inverseSqrt((((_e2413 * _e2413) + (_e2414 * _e2414)) + (_e2415 * _e2415)));
                                            let _e2427 = ((((_e2413 * _e484) + (_e2414 * _e485)) + (_e2415 * _e486)) * _e2421);
                                            let _e2431 = select(0f, select(1f, _e2427, (_e2427 < 1f)), (_e2427 > 0f));
                                            let _e2432 = abs(_e2431);
                                            let _e2442 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2432, 0.00667009f), _e2432, -0.017088126f), _e2432, 0.03089188f), _e2432, -0.050174303f), _e2432, 0.08897899f), _e2432, -0.2145988f), _e2432, 1.5707963f) * sqrt((1f - _e2432)));
                                            let _e2445 = select((3.1415927f - _e2442), _e2442, (_e2431 >= 0f));
                                            let _e2453 = select(_e2445, -(_e2445), ((((_e2387 * _e2413) + (_e2388 * _e2414)) + (_e2389 * _e2415)) < 0f));
                                            let _e2454 = (_e2421 * 0.02f);
                                            let _e2457 = select(0.19634955f, _e2454, ((_e2454 < 0.19634955f) || false));
                                            let _e2463 = ((((_e2387 * _e2387) + (_e2388 * _e2388)) + (_e2389 * _e2389)) <= 0f);
                                            if _e972 {
                                                phi_4344_ = (_e2366 <= (_e241 * _e241));
                                            } else {
                                                phi_4344_ = true;
                                            }
                                            let _e2467 = phi_4344_;
                                            let _e2476 = select(false, ((((_e2359 * _e545) + (_e2360 * _e546)) + (_e2361 * _e547)) > (sqrt(_e2366) * 0.018f)), _e2467);
                                            if _e2476 {
                                                let _e2477 = (0.5f / _e955);
                                                let _e2483 = frame.member[0u].member_1.member.member.member_1[0u];
                                                let _e2491 = frame.member[0u].member_1.member.member.member_1[1u];
                                                let _e2496 = frame.member[0u].member_1.member_5[0u];
                                                let _e2499 = frame.member[0u].member_1.member_5[1u];
                                                let _e2500 = f32(_e2496);
                                                let _e2501 = f32(_e2499);
                                                let _e2503 = frame.member[0u].member_1.member_4;
                                                let _e2504 = f32(_e2503);
                                                let _e2505 = (2u * _e2503);
                                                let _e2506 = (_e2496 + _e2505);
                                                let _e2510 = (floor(((((_e959 * _e2477) / _e2483) + 0.5f) * _e2500)) + _e2504);
                                                let _e2513 = f32(bitcast<i32>((_e2506 - 1u)));
                                                let _e2521 = (bitcast<u32>((floor(select(0f, select(_e2513, _e2510, (_e2510 < _e2513)), (_e2510 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2524 = (floor(((0.5f - ((_e963 * _e2477) / _e2491)) * _e2501)) + _e2504);
                                                let _e2527 = f32(bitcast<i32>(((_e2499 + _e2505) - 1u)));
                                                let _e2535 = (bitcast<u32>((floor(select(0f, select(_e2527, _e2524, (_e2524 < _e2527)), (_e2524 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2537 = frame.member[0u].member_1.member_8;
                                                let _e2539 = frame.member[0u].member_1.member_12;
                                                let _e2546 = (((((_e2535 % 4u) * 4u) + (_e2521 % 4u)) + (_e2539 % 16u)) % 16u);
                                                if (_e2537 == 1u) {
                                                    local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    let _e2559 = (_e2546 < 16u);
                                                    if _e2559 {
                                                    } else {
                                                        phi_7179_ = true;
                                                        break;
                                                    }
                                                    let _e2562 = local_1[_e2546][0u];
                                                    local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e2559 {
                                                    } else {
                                                        phi_7179_ = true;
                                                        break;
                                                    }
                                                    let _e2565 = local_2[_e2546][1u];
                                                    phi_4507_ = vec2<f32>(_e2562, _e2565);
                                                } else {
                                                    if (_e2537 == 2u) {
                                                        local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        let _e2549 = (_e2546 < 16u);
                                                        if _e2549 {
                                                        } else {
                                                            phi_7179_ = true;
                                                            break;
                                                        }
                                                        let _e2552 = local_3[_e2546][0u];
                                                        local_4 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e2549 {
                                                        } else {
                                                            phi_7179_ = true;
                                                            break;
                                                        }
                                                        let _e2555 = local_4[_e2546][1u];
                                                        phi_4506_ = vec2<f32>(_e2552, _e2555);
                                                    } else {
                                                        phi_4506_ = vec2<f32>(0.5f, 0.5f);
                                                    }
                                                    let _e2558 = phi_4506_;
                                                    phi_4507_ = _e2558;
                                                }
                                                let _e2568 = phi_4507_;
                                                let _e2576 = (((f32(bitcast<i32>(_e2521)) - _e2504) + _e2568.x) * (1f / _e2500));
                                                let _e2582 = (((f32(bitcast<i32>(_e2535)) - _e2504) + _e2568.y) * (1f / _e2501));
                                                let _e2587 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e2592 = select(select(u32(_e2587), 0u, (_e2587 < 0f)), 4294967295u, (_e2587 > 4294967000f));
                                                let _e2597 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e2607 = (select(0f, select(1f, _e2576, (_e2576 < 1f)), (_e2576 > 0f)) * _e2587);
                                                let _e2610 = f32(bitcast<i32>((_e2592 - 1u)));
                                                let _e2623 = (select(0f, select(1f, _e2582, (_e2582 < 1f)), (_e2582 > 0f)) * _e2597);
                                                let _e2626 = f32(bitcast<i32>((select(select(u32(_e2597), 0u, (_e2597 < 0f)), 4294967295u, (_e2597 > 4294967000f)) - 1u)));
                                                let _e2638 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e2626, _e2623, (_e2623 < _e2626)), (_e2623 > 0f))) + 8388608f)) - 1258291200u) * _e2592) + (bitcast<u32>((floor(select(0f, select(_e2610, _e2607, (_e2607 < _e2610)), (_e2607 > 0f))) + 8388608f)) - 1258291200u))];
                                                let _e2644 = select(0x1.fffffep+127f, (_e955 * 1.001f), select(false, (abs((_e2638 - _e955)) <= _e238), _e2476));
                                                let _e2646 = frame.member[0u].member_1.member_6;
                                                let _e2649 = (((_e2535 * _e2506) + _e2521) * _e2646);
                                                let _e2651 = sd_map.member[_e2649];
                                                let _e2655 = frame.member[0u].member_1.member.member.member_3;
                                                let _e2659 = frame.member[0u].member_1.member.member.member_2;
                                                let _e2660 = (_e2655 - _e2659);
                                                let _e2662 = ((_e2651 * _e2660) + _e2659);
                                                let _e2668 = select(_e2655, _e2662, select(false, select(false, (_e2662 > _e2644), (_e2651 < 1f)), (0u < _e2646)));
                                                let _e2669 = (_e2646 - 1u);
                                                let _e2674 = sd_map.member[(_e2649 + select(1u, _e2669, (_e2669 < 1u)))];
                                                let _e2676 = ((_e2674 * _e2660) + _e2659);
                                                let _e2682 = select(_e2655, _e2676, select(false, select(false, (_e2676 > _e2644), (_e2674 < 1f)), (1u < _e2646)));
                                                let _e2687 = sd_map.member[(_e2649 + select(2u, _e2669, (_e2669 < 2u)))];
                                                let _e2689 = ((_e2687 * _e2660) + _e2659);
                                                let _e2695 = select(_e2655, _e2689, select(false, select(false, (_e2689 > _e2644), (_e2687 < 1f)), (2u < _e2646)));
                                                let _e2700 = sd_map.member[(_e2649 + select(3u, _e2669, (_e2669 < 3u)))];
                                                let _e2702 = ((_e2700 * _e2660) + _e2659);
                                                let _e2708 = select(_e2655, _e2702, select(false, select(false, (_e2702 > _e2644), (_e2700 < 1f)), (3u < _e2646)));
                                                if (_e2646 > 4u) {
                                                    let _e2714 = sd_map.member[(_e2649 + select(4u, _e2669, (_e2669 < 4u)))];
                                                    let _e2716 = ((_e2714 * _e2660) + _e2659);
                                                    let _e2727 = sd_map.member[(_e2649 + select(5u, _e2669, (_e2669 < 5u)))];
                                                    let _e2729 = ((_e2727 * _e2660) + _e2659);
                                                    let _e2740 = sd_map.member[(_e2649 + select(6u, _e2669, (_e2669 < 6u)))];
                                                    let _e2742 = ((_e2740 * _e2660) + _e2659);
                                                    let _e2753 = sd_map.member[(_e2649 + select(7u, _e2669, (_e2669 < 7u)))];
                                                    let _e2755 = ((_e2753 * _e2660) + _e2659);
                                                    phi_4945_ = select(_e2655, _e2742, select(false, select(false, (_e2742 > _e2644), (_e2740 < 1f)), (6u < _e2646)));
                                                    phi_4946_ = select(_e2655, _e2729, select(false, select(false, (_e2729 > _e2644), (_e2727 < 1f)), (5u < _e2646)));
                                                    phi_4947_ = select(_e2655, _e2716, select(false, select(false, (_e2716 > _e2644), (_e2714 < 1f)), (4u < _e2646)));
                                                    phi_4948_ = select(_e2655, _e2755, select(false, select(false, (_e2755 > _e2644), (_e2753 < 1f)), (7u < _e2646)));
                                                } else {
                                                    phi_4945_ = _e2655;
                                                    phi_4946_ = _e2655;
                                                    phi_4947_ = _e2655;
                                                    phi_4948_ = _e2655;
                                                }
                                                let _e2763 = phi_4945_;
                                                let _e2765 = phi_4946_;
                                                let _e2767 = phi_4947_;
                                                let _e2769 = phi_4948_;
                                                let _e2771 = (_e2682 != _e2682);
                                                let _e2773 = select(_e2682, _e2668, ((_e2668 < _e2682) || _e2771));
                                                let _e2776 = select(_e2682, _e2668, ((_e2668 > _e2682) || _e2771));
                                                let _e2778 = (_e2708 != _e2708);
                                                let _e2780 = select(_e2708, _e2695, ((_e2695 < _e2708) || _e2778));
                                                let _e2783 = select(_e2708, _e2695, ((_e2695 > _e2708) || _e2778));
                                                let _e2785 = (_e2765 != _e2765);
                                                let _e2787 = select(_e2765, _e2767, ((_e2767 < _e2765) || _e2785));
                                                let _e2790 = select(_e2765, _e2767, ((_e2767 > _e2765) || _e2785));
                                                let _e2792 = (_e2769 != _e2769);
                                                let _e2794 = select(_e2769, _e2763, ((_e2763 < _e2769) || _e2792));
                                                let _e2797 = select(_e2769, _e2763, ((_e2763 > _e2769) || _e2792));
                                                let _e2799 = (_e2780 != _e2780);
                                                let _e2801 = select(_e2780, _e2773, ((_e2773 < _e2780) || _e2799));
                                                let _e2804 = select(_e2780, _e2773, ((_e2773 > _e2780) || _e2799));
                                                let _e2806 = (_e2783 != _e2783);
                                                let _e2808 = select(_e2783, _e2776, ((_e2776 < _e2783) || _e2806));
                                                let _e2811 = select(_e2783, _e2776, ((_e2776 > _e2783) || _e2806));
                                                let _e2813 = (_e2794 != _e2794);
                                                let _e2815 = select(_e2794, _e2787, ((_e2787 < _e2794) || _e2813));
                                                let _e2818 = select(_e2794, _e2787, ((_e2787 > _e2794) || _e2813));
                                                let _e2820 = (_e2797 != _e2797);
                                                let _e2822 = select(_e2797, _e2790, ((_e2790 < _e2797) || _e2820));
                                                let _e2825 = select(_e2797, _e2790, ((_e2790 > _e2797) || _e2820));
                                                let _e2827 = (_e2804 != _e2804);
                                                let _e2829 = select(_e2804, _e2808, ((_e2808 < _e2804) || _e2827));
                                                let _e2832 = select(_e2804, _e2808, ((_e2808 > _e2804) || _e2827));
                                                let _e2834 = (_e2818 != _e2818);
                                                let _e2836 = select(_e2818, _e2822, ((_e2822 < _e2818) || _e2834));
                                                let _e2839 = select(_e2818, _e2822, ((_e2822 > _e2818) || _e2834));
                                                let _e2841 = (_e2815 != _e2815);
                                                let _e2843 = select(_e2815, _e2801, ((_e2801 < _e2815) || _e2841));
                                                let _e2846 = select(_e2815, _e2801, ((_e2801 > _e2815) || _e2841));
                                                let _e2848 = (_e2836 != _e2836);
                                                let _e2850 = select(_e2836, _e2829, ((_e2829 < _e2836) || _e2848));
                                                let _e2853 = select(_e2836, _e2829, ((_e2829 > _e2836) || _e2848));
                                                let _e2855 = (_e2839 != _e2839);
                                                let _e2857 = select(_e2839, _e2832, ((_e2832 < _e2839) || _e2855));
                                                let _e2860 = select(_e2839, _e2832, ((_e2832 > _e2839) || _e2855));
                                                let _e2862 = (_e2825 != _e2825);
                                                let _e2864 = select(_e2825, _e2811, ((_e2811 < _e2825) || _e2862));
                                                let _e2867 = select(_e2825, _e2811, ((_e2811 > _e2825) || _e2862));
                                                let _e2869 = (_e2846 != _e2846);
                                                let _e2871 = select(_e2846, _e2857, ((_e2857 < _e2846) || _e2869));
                                                let _e2874 = select(_e2846, _e2857, ((_e2857 > _e2846) || _e2869));
                                                let _e2876 = (_e2853 != _e2853);
                                                let _e2878 = select(_e2853, _e2864, ((_e2864 < _e2853) || _e2876));
                                                let _e2881 = select(_e2853, _e2864, ((_e2864 > _e2853) || _e2876));
                                                let _e2883 = (_e2871 != _e2871);
                                                let _e2885 = select(_e2871, _e2850, ((_e2850 < _e2871) || _e2883));
                                                let _e2888 = select(_e2871, _e2850, ((_e2850 > _e2871) || _e2883));
                                                let _e2890 = (_e2874 != _e2874);
                                                let _e2892 = select(_e2874, _e2878, ((_e2878 < _e2874) || _e2890));
                                                let _e2895 = select(_e2874, _e2878, ((_e2878 > _e2874) || _e2890));
                                                let _e2897 = (_e2860 != _e2860);
                                                let _e2899 = select(_e2860, _e2881, ((_e2881 < _e2860) || _e2897));
                                                let _e2902 = select(_e2860, _e2881, ((_e2881 > _e2860) || _e2897));
                                                let _e2906 = select(false, (_e2843 > (_e955 + _e238)), (_e2843 < _e2655));
                                                let _e2908 = ((_e2576 * 2f) - 1f);
                                                let _e2912 = ((_e2582 * -2f) + 1f);
                                                let _e2922 = (_e2908 * _e225.member.member_1.x);
                                                let _e2924 = (_e2912 * _e225.member.member_1.y);
                                                let _e2926 = ((_e2922 * _e2885) - _e466);
                                                let _e2927 = ((_e2924 * _e2885) - _e473);
                                                let _e2928 = (_e2885 - _e459);
                                                if _e972 {
                                                    phi_5290_ = ((((_e2926 * _e2926) + (_e2927 * _e2927)) + (_e2928 * _e2928)) <= (_e241 * _e241));
                                                } else {
                                                    phi_5290_ = true;
                                                }
                                                let _e2937 = phi_5290_;
                                                let _e2939 = select(false, _e2937, (_e2885 < _e225.member.member_3));
                                                if _e2939 {
                                                    let _e2940 = (_e2888 < _e225.member.member_3);
                                                    let _e2949 = select((_e2926 - _e2372), ((_e2922 * _e2888) - _e466), _e2940);
                                                    let _e2950 = select((_e2927 - _e2373), ((_e2924 * _e2888) - _e473), _e2940);
                                                    let _e2951 = select((_e2928 - _e2374), (_e2888 - _e459), _e2940);
                                                    let _e2963 = ((((_e2926 * _e484) + (_e2927 * _e485)) + (_e2928 * _e486)) * inverseSqrt((((_e2926 * _e2926) + (_e2927 * _e2927)) + (_e2928 * _e2928))));
                                                    let _e2967 = select(-1f, select(1f, _e2963, (_e2963 < 1f)), (_e2963 > -1f));
                                                    let _e2968 = abs(_e2967);
                                                    let _e2978 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2968, 0.00667009f), _e2968, -0.017088126f), _e2968, 0.03089188f), _e2968, -0.050174303f), _e2968, 0.08897899f), _e2968, -0.2145988f), _e2968, 1.5707963f) * sqrt((1f - _e2968)));
                                                    let _e2985 = ((((select((3.1415927f - _e2978), _e2978, (_e2967 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3001 = ((((_e2949 * _e484) + (_e2950 * _e485)) + (_e2951 * _e486)) * inverseSqrt((((_e2949 * _e2949) + (_e2950 * _e2950)) + (_e2951 * _e2951))));
                                                    let _e3005 = select(-1f, select(1f, _e3001, (_e3001 < 1f)), (_e3001 > -1f));
                                                    let _e3006 = abs(_e3005);
                                                    let _e3016 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3006, 0.00667009f), _e3006, -0.017088126f), _e3006, 0.03089188f), _e3006, -0.050174303f), _e3006, 0.08897899f), _e3006, -0.2145988f), _e3006, 1.5707963f) * sqrt((1f - _e3006)));
                                                    let _e3023 = ((((select((3.1415927f - _e3016), _e3016, (_e3005 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3028 = (1f - select(0f, select(1f, _e2985, (_e2985 < 1f)), (_e2985 > 0f)));
                                                    let _e3029 = (1f - select(0f, select(1f, _e3023, (_e3023 < 1f)), (_e3023 > 0f)));
                                                    let _e3031 = (_e3029 != _e3029);
                                                    let _e3033 = select(_e3029, _e3028, ((_e3028 < _e3029) || _e3031));
                                                    let _e3036 = select(_e3029, _e3028, ((_e3028 > _e3029) || _e3031));
                                                    let _e3038 = floor((_e3033 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3046 = -(floor((_e3036 * -32f)));
                                                        let _e3051 = (select(32f, _e3046, ((_e3046 < 32f) || false)) - _e3038);
                                                        phi_5517_ = select(select(0f, _e3051, ((_e3051 > 0f) || false)), 0f, (_e3036 <= _e3033));
                                                    } else {
                                                        phi_5517_ = -(floor(((_e3036 - _e3033) * -32f)));
                                                    }
                                                    let _e3057 = phi_5517_;
                                                    let _e3065 = (bitcast<u32>((floor(select(0f, select(32f, _e3038, (_e3038 < 32f)), (_e3038 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3073 = (bitcast<u32>((floor(select(0f, select(32f, _e3057, (_e3057 < 32f)), (_e3057 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3065 >= 32u) {
                                                        phi_5571_ = u32();
                                                        phi_5572_ = true;
                                                    } else {
                                                        let _e3075 = (_e3073 == 0u);
                                                        if _e3075 {
                                                            phi_5570_ = u32();
                                                        } else {
                                                            if (_e3073 >= 32u) {
                                                                phi_5567_ = 4294967295u;
                                                            } else {
                                                                phi_5567_ = ((1u << bitcast<u32>((_e3073 & 31u))) - 1u);
                                                            }
                                                            let _e3082 = phi_5567_;
                                                            phi_5570_ = (_e3082 << bitcast<u32>((_e3065 & 31u)));
                                                        }
                                                        let _e3087 = phi_5570_;
                                                        phi_5571_ = _e3087;
                                                        phi_5572_ = _e3075;
                                                    }
                                                    let _e3089 = phi_5571_;
                                                    let _e3091 = phi_5572_;
                                                    phi_5585_ = select(0u, select(select(_e3089, 0u, _e3091), 0u, _e2463), _e2939);
                                                } else {
                                                    phi_5585_ = 0u;
                                                }
                                                let _e3096 = phi_5585_;
                                                let _e3099 = ((_e2922 * _e2892) - _e466);
                                                let _e3100 = ((_e2924 * _e2892) - _e473);
                                                let _e3101 = (_e2892 - _e459);
                                                if _e972 {
                                                    phi_5616_ = ((((_e3099 * _e3099) + (_e3100 * _e3100)) + (_e3101 * _e3101)) <= (_e241 * _e241));
                                                } else {
                                                    phi_5616_ = true;
                                                }
                                                let _e3110 = phi_5616_;
                                                let _e3112 = select(false, _e3110, (_e2892 < _e225.member.member_3));
                                                if _e3112 {
                                                    let _e3113 = (_e2895 < _e225.member.member_3);
                                                    let _e3122 = select((_e3099 - _e2372), ((_e2922 * _e2895) - _e466), _e3113);
                                                    let _e3123 = select((_e3100 - _e2373), ((_e2924 * _e2895) - _e473), _e3113);
                                                    let _e3124 = select((_e3101 - _e2374), (_e2895 - _e459), _e3113);
                                                    let _e3136 = ((((_e3099 * _e484) + (_e3100 * _e485)) + (_e3101 * _e486)) * inverseSqrt((((_e3099 * _e3099) + (_e3100 * _e3100)) + (_e3101 * _e3101))));
                                                    let _e3140 = select(-1f, select(1f, _e3136, (_e3136 < 1f)), (_e3136 > -1f));
                                                    let _e3141 = abs(_e3140);
                                                    let _e3151 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3141, 0.00667009f), _e3141, -0.017088126f), _e3141, 0.03089188f), _e3141, -0.050174303f), _e3141, 0.08897899f), _e3141, -0.2145988f), _e3141, 1.5707963f) * sqrt((1f - _e3141)));
                                                    let _e3158 = ((((select((3.1415927f - _e3151), _e3151, (_e3140 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3174 = ((((_e3122 * _e484) + (_e3123 * _e485)) + (_e3124 * _e486)) * inverseSqrt((((_e3122 * _e3122) + (_e3123 * _e3123)) + (_e3124 * _e3124))));
                                                    let _e3178 = select(-1f, select(1f, _e3174, (_e3174 < 1f)), (_e3174 > -1f));
                                                    let _e3179 = abs(_e3178);
                                                    let _e3189 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3179, 0.00667009f), _e3179, -0.017088126f), _e3179, 0.03089188f), _e3179, -0.050174303f), _e3179, 0.08897899f), _e3179, -0.2145988f), _e3179, 1.5707963f) * sqrt((1f - _e3179)));
                                                    let _e3196 = ((((select((3.1415927f - _e3189), _e3189, (_e3178 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3201 = (1f - select(0f, select(1f, _e3158, (_e3158 < 1f)), (_e3158 > 0f)));
                                                    let _e3202 = (1f - select(0f, select(1f, _e3196, (_e3196 < 1f)), (_e3196 > 0f)));
                                                    let _e3204 = (_e3202 != _e3202);
                                                    let _e3206 = select(_e3202, _e3201, ((_e3201 < _e3202) || _e3204));
                                                    let _e3209 = select(_e3202, _e3201, ((_e3201 > _e3202) || _e3204));
                                                    let _e3211 = floor((_e3206 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3219 = -(floor((_e3209 * -32f)));
                                                        let _e3224 = (select(32f, _e3219, ((_e3219 < 32f) || false)) - _e3211);
                                                        phi_5843_ = select(select(0f, _e3224, ((_e3224 > 0f) || false)), 0f, (_e3209 <= _e3206));
                                                    } else {
                                                        phi_5843_ = -(floor(((_e3209 - _e3206) * -32f)));
                                                    }
                                                    let _e3230 = phi_5843_;
                                                    let _e3238 = (bitcast<u32>((floor(select(0f, select(32f, _e3211, (_e3211 < 32f)), (_e3211 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3246 = (bitcast<u32>((floor(select(0f, select(32f, _e3230, (_e3230 < 32f)), (_e3230 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3238 >= 32u) {
                                                        phi_5897_ = u32();
                                                        phi_5898_ = true;
                                                    } else {
                                                        let _e3248 = (_e3246 == 0u);
                                                        if _e3248 {
                                                            phi_5896_ = u32();
                                                        } else {
                                                            if (_e3246 >= 32u) {
                                                                phi_5893_ = 4294967295u;
                                                            } else {
                                                                phi_5893_ = ((1u << bitcast<u32>((_e3246 & 31u))) - 1u);
                                                            }
                                                            let _e3255 = phi_5893_;
                                                            phi_5896_ = (_e3255 << bitcast<u32>((_e3238 & 31u)));
                                                        }
                                                        let _e3260 = phi_5896_;
                                                        phi_5897_ = _e3260;
                                                        phi_5898_ = _e3248;
                                                    }
                                                    let _e3262 = phi_5897_;
                                                    let _e3264 = phi_5898_;
                                                    phi_5911_ = select(0u, select(select(_e3262, 0u, _e3264), 0u, _e2463), _e3112);
                                                } else {
                                                    phi_5911_ = 0u;
                                                }
                                                let _e3269 = phi_5911_;
                                                let _e3273 = ((_e2922 * _e2899) - _e466);
                                                let _e3274 = ((_e2924 * _e2899) - _e473);
                                                let _e3275 = (_e2899 - _e459);
                                                if _e972 {
                                                    phi_5943_ = ((((_e3273 * _e3273) + (_e3274 * _e3274)) + (_e3275 * _e3275)) <= (_e241 * _e241));
                                                } else {
                                                    phi_5943_ = true;
                                                }
                                                let _e3284 = phi_5943_;
                                                let _e3286 = select(false, _e3284, (_e2899 < _e225.member.member_3));
                                                if _e3286 {
                                                    let _e3287 = (_e2902 < _e225.member.member_3);
                                                    let _e3296 = select((_e3273 - _e2372), ((_e2922 * _e2902) - _e466), _e3287);
                                                    let _e3297 = select((_e3274 - _e2373), ((_e2924 * _e2902) - _e473), _e3287);
                                                    let _e3298 = select((_e3275 - _e2374), (_e2902 - _e459), _e3287);
                                                    let _e3310 = ((((_e3273 * _e484) + (_e3274 * _e485)) + (_e3275 * _e486)) * inverseSqrt((((_e3273 * _e3273) + (_e3274 * _e3274)) + (_e3275 * _e3275))));
                                                    let _e3314 = select(-1f, select(1f, _e3310, (_e3310 < 1f)), (_e3310 > -1f));
                                                    let _e3315 = abs(_e3314);
                                                    let _e3325 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3315, 0.00667009f), _e3315, -0.017088126f), _e3315, 0.03089188f), _e3315, -0.050174303f), _e3315, 0.08897899f), _e3315, -0.2145988f), _e3315, 1.5707963f) * sqrt((1f - _e3315)));
                                                    let _e3332 = ((((select((3.1415927f - _e3325), _e3325, (_e3314 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3348 = ((((_e3296 * _e484) + (_e3297 * _e485)) + (_e3298 * _e486)) * inverseSqrt((((_e3296 * _e3296) + (_e3297 * _e3297)) + (_e3298 * _e3298))));
                                                    let _e3352 = select(-1f, select(1f, _e3348, (_e3348 < 1f)), (_e3348 > -1f));
                                                    let _e3353 = abs(_e3352);
                                                    let _e3363 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3353, 0.00667009f), _e3353, -0.017088126f), _e3353, 0.03089188f), _e3353, -0.050174303f), _e3353, 0.08897899f), _e3353, -0.2145988f), _e3353, 1.5707963f) * sqrt((1f - _e3353)));
                                                    let _e3370 = ((((select((3.1415927f - _e3363), _e3363, (_e3352 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3375 = (1f - select(0f, select(1f, _e3332, (_e3332 < 1f)), (_e3332 > 0f)));
                                                    let _e3376 = (1f - select(0f, select(1f, _e3370, (_e3370 < 1f)), (_e3370 > 0f)));
                                                    let _e3378 = (_e3376 != _e3376);
                                                    let _e3380 = select(_e3376, _e3375, ((_e3375 < _e3376) || _e3378));
                                                    let _e3383 = select(_e3376, _e3375, ((_e3375 > _e3376) || _e3378));
                                                    let _e3385 = floor((_e3380 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3393 = -(floor((_e3383 * -32f)));
                                                        let _e3398 = (select(32f, _e3393, ((_e3393 < 32f) || false)) - _e3385);
                                                        phi_6170_ = select(select(0f, _e3398, ((_e3398 > 0f) || false)), 0f, (_e3383 <= _e3380));
                                                    } else {
                                                        phi_6170_ = -(floor(((_e3383 - _e3380) * -32f)));
                                                    }
                                                    let _e3404 = phi_6170_;
                                                    let _e3412 = (bitcast<u32>((floor(select(0f, select(32f, _e3385, (_e3385 < 32f)), (_e3385 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3420 = (bitcast<u32>((floor(select(0f, select(32f, _e3404, (_e3404 < 32f)), (_e3404 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3412 >= 32u) {
                                                        phi_6224_ = u32();
                                                        phi_6225_ = true;
                                                    } else {
                                                        let _e3422 = (_e3420 == 0u);
                                                        if _e3422 {
                                                            phi_6223_ = u32();
                                                        } else {
                                                            if (_e3420 >= 32u) {
                                                                phi_6220_ = 4294967295u;
                                                            } else {
                                                                phi_6220_ = ((1u << bitcast<u32>((_e3420 & 31u))) - 1u);
                                                            }
                                                            let _e3429 = phi_6220_;
                                                            phi_6223_ = (_e3429 << bitcast<u32>((_e3412 & 31u)));
                                                        }
                                                        let _e3434 = phi_6223_;
                                                        phi_6224_ = _e3434;
                                                        phi_6225_ = _e3422;
                                                    }
                                                    let _e3436 = phi_6224_;
                                                    let _e3438 = phi_6225_;
                                                    phi_6238_ = select(0u, select(select(_e3436, 0u, _e3438), 0u, _e2463), _e3286);
                                                } else {
                                                    phi_6238_ = 0u;
                                                }
                                                let _e3443 = phi_6238_;
                                                let _e3447 = ((_e2922 * _e2867) - _e466);
                                                let _e3448 = ((_e2924 * _e2867) - _e473);
                                                let _e3449 = (_e2867 - _e459);
                                                if _e972 {
                                                    phi_6270_ = ((((_e3447 * _e3447) + (_e3448 * _e3448)) + (_e3449 * _e3449)) <= (_e241 * _e241));
                                                } else {
                                                    phi_6270_ = true;
                                                }
                                                let _e3458 = phi_6270_;
                                                let _e3460 = select(false, _e3458, (_e2867 < _e225.member.member_3));
                                                if _e3460 {
                                                    let _e3461 = (_e2655 < _e225.member.member_3);
                                                    let _e3470 = select((_e3447 - _e2372), ((_e2922 * _e2655) - _e466), _e3461);
                                                    let _e3471 = select((_e3448 - _e2373), ((_e2924 * _e2655) - _e473), _e3461);
                                                    let _e3472 = select((_e3449 - _e2374), (_e2655 - _e459), _e3461);
                                                    let _e3484 = ((((_e3447 * _e484) + (_e3448 * _e485)) + (_e3449 * _e486)) * inverseSqrt((((_e3447 * _e3447) + (_e3448 * _e3448)) + (_e3449 * _e3449))));
                                                    let _e3488 = select(-1f, select(1f, _e3484, (_e3484 < 1f)), (_e3484 > -1f));
                                                    let _e3489 = abs(_e3488);
                                                    let _e3499 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3489, 0.00667009f), _e3489, -0.017088126f), _e3489, 0.03089188f), _e3489, -0.050174303f), _e3489, 0.08897899f), _e3489, -0.2145988f), _e3489, 1.5707963f) * sqrt((1f - _e3489)));
                                                    let _e3506 = ((((select((3.1415927f - _e3499), _e3499, (_e3488 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3522 = ((((_e3470 * _e484) + (_e3471 * _e485)) + (_e3472 * _e486)) * inverseSqrt((((_e3470 * _e3470) + (_e3471 * _e3471)) + (_e3472 * _e3472))));
                                                    let _e3526 = select(-1f, select(1f, _e3522, (_e3522 < 1f)), (_e3522 > -1f));
                                                    let _e3527 = abs(_e3526);
                                                    let _e3537 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3527, 0.00667009f), _e3527, -0.017088126f), _e3527, 0.03089188f), _e3527, -0.050174303f), _e3527, 0.08897899f), _e3527, -0.2145988f), _e3527, 1.5707963f) * sqrt((1f - _e3527)));
                                                    let _e3544 = ((((select((3.1415927f - _e3537), _e3537, (_e3526 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                                    let _e3549 = (1f - select(0f, select(1f, _e3506, (_e3506 < 1f)), (_e3506 > 0f)));
                                                    let _e3550 = (1f - select(0f, select(1f, _e3544, (_e3544 < 1f)), (_e3544 > 0f)));
                                                    let _e3552 = (_e3550 != _e3550);
                                                    let _e3554 = select(_e3550, _e3549, ((_e3549 < _e3550) || _e3552));
                                                    let _e3557 = select(_e3550, _e3549, ((_e3549 > _e3550) || _e3552));
                                                    let _e3559 = floor((_e3554 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3567 = -(floor((_e3557 * -32f)));
                                                        let _e3572 = (select(32f, _e3567, ((_e3567 < 32f) || false)) - _e3559);
                                                        phi_6497_ = select(select(0f, _e3572, ((_e3572 > 0f) || false)), 0f, (_e3557 <= _e3554));
                                                    } else {
                                                        phi_6497_ = -(floor(((_e3557 - _e3554) * -32f)));
                                                    }
                                                    let _e3578 = phi_6497_;
                                                    let _e3586 = (bitcast<u32>((floor(select(0f, select(32f, _e3559, (_e3559 < 32f)), (_e3559 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3594 = (bitcast<u32>((floor(select(0f, select(32f, _e3578, (_e3578 < 32f)), (_e3578 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3586 >= 32u) {
                                                        phi_6551_ = u32();
                                                        phi_6552_ = true;
                                                    } else {
                                                        let _e3596 = (_e3594 == 0u);
                                                        if _e3596 {
                                                            phi_6550_ = u32();
                                                        } else {
                                                            if (_e3594 >= 32u) {
                                                                phi_6547_ = 4294967295u;
                                                            } else {
                                                                phi_6547_ = ((1u << bitcast<u32>((_e3594 & 31u))) - 1u);
                                                            }
                                                            let _e3603 = phi_6547_;
                                                            phi_6550_ = (_e3603 << bitcast<u32>((_e3586 & 31u)));
                                                        }
                                                        let _e3608 = phi_6550_;
                                                        phi_6551_ = _e3608;
                                                        phi_6552_ = _e3596;
                                                    }
                                                    let _e3610 = phi_6551_;
                                                    let _e3612 = phi_6552_;
                                                    phi_6565_ = select(0u, select(select(_e3610, 0u, _e3612), 0u, _e2463), _e3460);
                                                } else {
                                                    phi_6565_ = 0u;
                                                }
                                                let _e3617 = phi_6565_;
                                                phi_6567_ = (((_e3096 | _e3269) | _e3443) | _e3617);
                                                phi_6568_ = vec3<f32>(select(_e2375, (((_e2908 * _e2483) * _e2843) - _e466), _e2906), select(_e2376, (((_e2912 * _e2491) * _e2843) - _e473), _e2906), select(_e2377, (_e2843 - _e459), _e2906));
                                            } else {
                                                phi_6567_ = 0u;
                                                phi_6568_ = vec3<f32>(_e2375, _e2376, _e2377);
                                            }
                                            let _e3620 = phi_6567_;
                                            let _e3622 = phi_6568_;
                                            let _e3624 = (_e2383 * inverseSqrt(_e2366));
                                            let _e3628 = select(-1f, select(1f, _e3624, (_e3624 < 1f)), (_e3624 > -1f));
                                            let _e3629 = abs(_e3628);
                                            let _e3639 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3629, 0.00667009f), _e3629, -0.017088126f), _e3629, 0.03089188f), _e3629, -0.050174303f), _e3629, 0.08897899f), _e3629, -0.2145988f), _e3629, 1.5707963f) * sqrt((1f - _e3629)));
                                            let _e3646 = ((((select((3.1415927f - _e3639), _e3639, (_e3628 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                            let _e3665 = ((((_e3622.x * _e484) + (_e3622.y * _e485)) + (_e3622.z * _e486)) * inverseSqrt((((_e3622.x * _e3622.x) + (_e3622.y * _e3622.y)) + (_e3622.z * _e3622.z))));
                                            let _e3669 = select(-1f, select(1f, _e3665, (_e3665 < 1f)), (_e3665 > -1f));
                                            let _e3670 = abs(_e3669);
                                            let _e3680 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3670, 0.00667009f), _e3670, -0.017088126f), _e3670, 0.03089188f), _e3670, -0.050174303f), _e3670, 0.08897899f), _e3670, -0.2145988f), _e3670, 1.5707963f) * sqrt((1f - _e3670)));
                                            let _e3687 = ((((select((3.1415927f - _e3680), _e3680, (_e3669 >= 0f)) + _e2457) - _e2453) + 1.5707964f) * 0.31830987f);
                                            let _e3692 = (1f - select(0f, select(1f, _e3646, (_e3646 < 1f)), (_e3646 > 0f)));
                                            let _e3693 = (1f - select(0f, select(1f, _e3687, (_e3687 < 1f)), (_e3687 > 0f)));
                                            let _e3695 = (_e3693 != _e3693);
                                            let _e3697 = select(_e3693, _e3692, ((_e3692 < _e3693) || _e3695));
                                            let _e3700 = select(_e3693, _e3692, ((_e3692 > _e3693) || _e3695));
                                            let _e3702 = floor((_e3697 * 32f));
                                            if (_e235 == 1u) {
                                                let _e3710 = -(floor((_e3700 * -32f)));
                                                let _e3715 = (select(32f, _e3710, ((_e3710 < 32f) || false)) - _e3702);
                                                phi_6755_ = select(select(0f, _e3715, ((_e3715 > 0f) || false)), 0f, (_e3700 <= _e3697));
                                            } else {
                                                phi_6755_ = -(floor(((_e3700 - _e3697) * -32f)));
                                            }
                                            let _e3721 = phi_6755_;
                                            let _e3729 = (bitcast<u32>((floor(select(0f, select(32f, _e3702, (_e3702 < 32f)), (_e3702 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e3737 = (bitcast<u32>((floor(select(0f, select(32f, _e3721, (_e3721 < 32f)), (_e3721 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e3729 >= 32u) {
                                                phi_6809_ = u32();
                                                phi_6810_ = true;
                                            } else {
                                                let _e3739 = (_e3737 == 0u);
                                                if _e3739 {
                                                    phi_6808_ = u32();
                                                } else {
                                                    if (_e3737 >= 32u) {
                                                        phi_6805_ = 4294967295u;
                                                    } else {
                                                        phi_6805_ = ((1u << bitcast<u32>((_e3737 & 31u))) - 1u);
                                                    }
                                                    let _e3746 = phi_6805_;
                                                    phi_6808_ = (_e3746 << bitcast<u32>((_e3729 & 31u)));
                                                }
                                                let _e3751 = phi_6808_;
                                                phi_6809_ = _e3751;
                                                phi_6810_ = _e3739;
                                            }
                                            let _e3753 = phi_6809_;
                                            let _e3755 = phi_6810_;
                                            phi_6824_ = select((select(select(_e3753, 0u, _e3755), 0u, _e2463) | _e3620), 0u, _e2370);
                                        } else {
                                            phi_6824_ = 0u;
                                        }
                                        let _e3761 = phi_6824_;
                                        phi_1200_ = (_e787 + 1u);
                                        phi_1203_ = ((_e789 | _e2357) | _e3761);
                                    } else {
                                        phi_1200_ = u32();
                                        phi_1203_ = u32();
                                    }
                                    let _e3765 = phi_1200_;
                                    let _e3767 = phi_1203_;
                                    continue;
                                    continuing {
                                        phi_1199_ = _e3765;
                                        phi_1202_ = _e3767;
                                        phi_7179_ = _e684;
                                        break if !(_e790);
                                    }
                                }
                                let _e3770 = phi_7179_;
                                phi_7803_ = _e3770;
                                if _e3770 {
                                    break;
                                }
                                if (_e230 == 2u) {
                                    let _e3829 = (_e782 - 1.5707964f);
                                    let _e3830 = (_e3829 * 2f);
                                    let _e3831 = sin(_e782);
                                    let _e3836 = ((_e767 + (_e3830 * _e3831)) - cos((_e3830 - _e782)));
                                    phi_6853_ = 0u;
                                    phi_6856_ = select((_e3836 * 0.25f), (_e3836 * -0.25f), (_e3829 < 0f));
                                    phi_6858_ = 0f;
                                    loop {
                                        let _e3842 = phi_6853_;
                                        let _e3844 = phi_6856_;
                                        let _e3846 = phi_6858_;
                                        local_13 = _e3846;
                                        let _e3847 = (_e3842 < 32u);
                                        if _e3847 {
                                            let _e3848 = (_e3842 + 1u);
                                            let _e3852 = (_e3829 + (f32(bitcast<i32>(_e3848)) * 0.09817477f));
                                            let _e3853 = (_e3852 * 2f);
                                            let _e3858 = ((_e767 + (_e3853 * _e3831)) - cos((_e3853 - _e782)));
                                            let _e3862 = select((_e3858 * 0.25f), (_e3858 * -0.25f), (_e3852 < 0f));
                                            let _e3865 = local_12;
                                            phi_6854_ = _e3848;
                                            phi_6857_ = _e3862;
                                            phi_6859_ = select(_e3846, (_e3846 + (_e3862 - _e3844)), (((_e3865 >> bitcast<u32>((_e3842 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_6854_ = u32();
                                            phi_6857_ = f32();
                                            phi_6859_ = f32();
                                        }
                                        let _e3874 = phi_6854_;
                                        let _e3876 = phi_6857_;
                                        let _e3878 = phi_6859_;
                                        continue;
                                        continuing {
                                            phi_6853_ = _e3874;
                                            phi_6856_ = _e3876;
                                            phi_6858_ = _e3878;
                                            break if !(_e3847);
                                        }
                                    }
                                    let _e3881 = local_13;
                                    phi_7805_ = _e3770;
                                    phi_6960_ = (_e688 + 1f);
                                    phi_6961_ = (_e690 + ((_e748 + ((1f - _e748) * 0.05f)) * _e3881));
                                } else {
                                    if (_e230 == 1u) {
                                        phi_6905_ = 0u;
                                        phi_6908_ = 0f;
                                        loop {
                                            let _e3784 = phi_6905_;
                                            let _e3786 = phi_6908_;
                                            local_11 = _e3786;
                                            let _e3787 = (_e3784 < 4u);
                                            if _e3787 {
                                                local = array<type_40, 4>(type_40(4026531855u, 0.0095061f), type_40(251658480u, 0.0270951f), type_40(15732480u, 0.0405571f), type_40(1044480u, 0.0478421f));
                                                if _e3787 {
                                                } else {
                                                    phi_7800_ = true;
                                                    break;
                                                }
                                                let _e3790 = local[_e3784].member;
                                                let _e3793 = local[_e3784].member_1;
                                                let _e3795 = local_10;
                                                phi_6906_ = (_e3784 + 1u);
                                                phi_6909_ = (_e3786 + (f32(bitcast<i32>(countOneBits((_e3795 & _e3790)))) * _e3793));
                                            } else {
                                                phi_6906_ = u32();
                                                phi_6909_ = f32();
                                            }
                                            let _e3804 = phi_6906_;
                                            let _e3806 = phi_6909_;
                                            continue;
                                            continuing {
                                                phi_6905_ = _e3804;
                                                phi_6908_ = _e3806;
                                                phi_7800_ = _e3770;
                                                break if !(_e3787);
                                            }
                                        }
                                        let _e3809 = phi_7800_;
                                        phi_7803_ = _e3809;
                                        if _e3809 {
                                            break;
                                        }
                                        let _e3811 = local_11;
                                        let _e3812 = (1f - _e3811);
                                        phi_7811_ = _e3809;
                                        phi_6958_ = (_e688 + _e748);
                                        phi_6959_ = (_e690 + (_e748 * select(0f, select(1f, _e3812, (_e3812 < 1f)), (_e3812 > 0f))));
                                    } else {
                                        let _e3774 = local_9;
                                        phi_7811_ = _e3770;
                                        phi_6958_ = (_e688 + 1f);
                                        phi_6959_ = (_e690 + ((f32(bitcast<i32>(countOneBits((_e3774 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e3821 = phi_7811_;
                                    let _e3823 = phi_6958_;
                                    let _e3825 = phi_6959_;
                                    phi_7805_ = _e3821;
                                    phi_6960_ = _e3823;
                                    phi_6961_ = _e3825;
                                }
                                let _e3886 = phi_7805_;
                                let _e3888 = phi_6960_;
                                let _e3890 = phi_6961_;
                                phi_7804_ = _e3886;
                                phi_1009_ = (_e686 + 1u);
                                phi_1012_ = _e3888;
                                phi_1014_ = _e3890;
                            } else {
                                phi_7804_ = _e684;
                                phi_1009_ = u32();
                                phi_1012_ = f32();
                                phi_1014_ = f32();
                            }
                            let _e3893 = phi_7804_;
                            let _e3895 = phi_1009_;
                            let _e3897 = phi_1012_;
                            let _e3899 = phi_1014_;
                            continue;
                            continuing {
                                phi_7716_ = _e3893;
                                phi_1008_ = _e3895;
                                phi_1011_ = _e3897;
                                phi_1013_ = _e3899;
                                phi_7803_ = _e3893;
                                break if !(_e691);
                            }
                        }
                        let _e3902 = phi_7803_;
                        if _e3902 {
                            break;
                        }
                        let _e3904 = local_14;
                        let _e3907 = local_15;
                        let _e3909 = local_16;
                        phi_6969_ = select(1f, (_e3907 / _e3909), (_e3904 > 0f));
                    } else {
                        phi_6969_ = 1f;
                    }
                    let _e3913 = phi_6969_;
                    if (_e225.member_6 == 2f) {
                        phi_6982_ = (_e3913 * _e3913);
                    } else {
                        if (_e225.member_6 == 1f) {
                            phi_6981_ = _e3913;
                        } else {
                            phi_6981_ = pow(_e3913, _e225.member_6);
                        }
                        let _e3919 = phi_6981_;
                        phi_6982_ = _e3919;
                    }
                    let _e3922 = phi_6982_;
                    let _e3927 = (select(1f, select(0.03f, _e3922, ((_e3922 > 0.03f) || false)), _e679) * 0.6666667f);
                    terms.member[_e267] = (bitcast<u32>((floor(((select(0f, select(1f, _e3927, (_e3927 < 1f)), (_e3927 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                    edges.member[_e267] = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e396, (_e396 < 3f)), (_e396 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e411, (_e411 < 3f)), (_e411 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e427, (_e427 < 3f)), (_e427 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e443, (_e443 < 3f)), (_e443 > 0f))) + 8388608f)) - 1258291200u));
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vbao_sd_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
