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
    var phi_7748_: bool;
    var phi_1008_: u32;
    var phi_1011_: f32;
    var phi_1013_: f32;
    var phi_1199_: u32;
    var phi_1202_: u32;
    var phi_1259_: f32;
    var phi_1260_: f32;
    var phi_1538_: bool;
    var phi_1708_: bool;
    var phi_1859_: vec2<f32>;
    var phi_1860_: vec2<f32>;
    var phi_2303_: f32;
    var phi_2304_: f32;
    var phi_2305_: f32;
    var phi_2306_: f32;
    var phi_2649_: bool;
    var phi_2876_: f32;
    var phi_2926_: u32;
    var phi_2929_: u32;
    var phi_2930_: u32;
    var phi_2931_: bool;
    var phi_2944_: u32;
    var phi_2976_: bool;
    var phi_3203_: f32;
    var phi_3253_: u32;
    var phi_3256_: u32;
    var phi_3257_: u32;
    var phi_3258_: bool;
    var phi_3271_: u32;
    var phi_3304_: bool;
    var phi_3531_: f32;
    var phi_3581_: u32;
    var phi_3584_: u32;
    var phi_3585_: u32;
    var phi_3586_: bool;
    var phi_3599_: u32;
    var phi_3632_: bool;
    var phi_3859_: f32;
    var phi_3909_: u32;
    var phi_3912_: u32;
    var phi_3913_: u32;
    var phi_3914_: bool;
    var phi_3927_: u32;
    var phi_3929_: u32;
    var phi_3930_: vec3<f32>;
    var phi_4117_: f32;
    var phi_4167_: u32;
    var phi_4170_: u32;
    var phi_4171_: u32;
    var phi_4172_: bool;
    var phi_4186_: u32;
    var phi_4206_: bool;
    var phi_4376_: bool;
    var phi_4527_: vec2<f32>;
    var phi_4528_: vec2<f32>;
    var phi_4971_: f32;
    var phi_4972_: f32;
    var phi_4973_: f32;
    var phi_4974_: f32;
    var phi_5317_: bool;
    var phi_5544_: f32;
    var phi_5594_: u32;
    var phi_5597_: u32;
    var phi_5598_: u32;
    var phi_5599_: bool;
    var phi_5612_: u32;
    var phi_5644_: bool;
    var phi_5871_: f32;
    var phi_5921_: u32;
    var phi_5924_: u32;
    var phi_5925_: u32;
    var phi_5926_: bool;
    var phi_5939_: u32;
    var phi_5972_: bool;
    var phi_6199_: f32;
    var phi_6249_: u32;
    var phi_6252_: u32;
    var phi_6253_: u32;
    var phi_6254_: bool;
    var phi_6267_: u32;
    var phi_6300_: bool;
    var phi_6527_: f32;
    var phi_6577_: u32;
    var phi_6580_: u32;
    var phi_6581_: u32;
    var phi_6582_: bool;
    var phi_6595_: u32;
    var phi_6597_: u32;
    var phi_6598_: vec3<f32>;
    var phi_6785_: f32;
    var phi_6835_: u32;
    var phi_6838_: u32;
    var phi_6839_: u32;
    var phi_6840_: bool;
    var phi_6854_: u32;
    var phi_1200_: u32;
    var phi_1203_: u32;
    var phi_7209_: bool;
    var local_9: u32;
    var phi_6935_: u32;
    var phi_6938_: f32;
    var local_10: u32;
    var phi_6936_: u32;
    var phi_6939_: f32;
    var phi_7832_: bool;
    var local_11: f32;
    var phi_7843_: bool;
    var phi_6988_: f32;
    var phi_6989_: f32;
    var phi_6883_: u32;
    var phi_6886_: f32;
    var phi_6888_: f32;
    var local_12: u32;
    var phi_6884_: u32;
    var phi_6887_: f32;
    var phi_6889_: f32;
    var local_13: f32;
    var phi_7837_: bool;
    var phi_6990_: f32;
    var phi_6991_: f32;
    var phi_7836_: bool;
    var phi_1009_: u32;
    var phi_1012_: f32;
    var phi_1014_: f32;
    var phi_7835_: bool;
    var local_14: f32;
    var local_15: f32;
    var local_16: f32;
    var phi_6999_: f32;
    var phi_7011_: f32;
    var phi_7012_: f32;

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
                        phi_7748_ = false;
                        phi_1008_ = 0u;
                        phi_1011_ = 0f;
                        phi_1013_ = 0f;
                        loop {
                            let _e684 = phi_7748_;
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
                                        let _e967 = (_e241 > 0f);
                                        if _e967 {
                                            phi_1538_ = ((((_e964 * _e964) + (_e965 * _e965)) + (_e966 * _e966)) > (_e241 * _e241));
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
                                            let _e1079 = (((_e964 * _e964) + (_e965 * _e965)) + (_e966 * _e966));
                                            if _e967 {
                                                phi_1708_ = (_e1079 > (_e241 * _e241));
                                            } else {
                                                phi_1708_ = false;
                                            }
                                            let _e1086 = phi_1708_;
                                            let _e1088 = select(false, ((((_e964 * _e545) + (_e965 * _e546)) + (_e966 * _e547)) > (sqrt(_e1079) * 0.018f)), !(_e1086));
                                            if _e1088 {
                                                let _e1089 = (0.5f / _e923);
                                                let _e1095 = frame.member[0u].member_1.member.member.member_1[0u];
                                                let _e1103 = frame.member[0u].member_1.member.member.member_1[1u];
                                                let _e1108 = frame.member[0u].member_1.member_5[0u];
                                                let _e1111 = frame.member[0u].member_1.member_5[1u];
                                                let _e1112 = f32(_e1108);
                                                let _e1113 = f32(_e1111);
                                                let _e1115 = frame.member[0u].member_1.member_4;
                                                let _e1116 = f32(_e1115);
                                                let _e1117 = (2u * _e1115);
                                                let _e1118 = (_e1108 + _e1117);
                                                let _e1122 = (floor(((((_e927 * _e1089) / _e1095) + 0.5f) * _e1112)) + _e1116);
                                                let _e1125 = f32(bitcast<i32>((_e1118 - 1u)));
                                                let _e1133 = (bitcast<u32>((floor(select(0f, select(_e1125, _e1122, (_e1122 < _e1125)), (_e1122 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e1136 = (floor(((0.5f - ((_e931 * _e1089) / _e1103)) * _e1113)) + _e1116);
                                                let _e1139 = f32(bitcast<i32>(((_e1111 + _e1117) - 1u)));
                                                let _e1147 = (bitcast<u32>((floor(select(0f, select(_e1139, _e1136, (_e1136 < _e1139)), (_e1136 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e1149 = frame.member[0u].member_1.member_8;
                                                let _e1151 = frame.member[0u].member_1.member_12;
                                                let _e1158 = (((((_e1147 % 4u) * 4u) + (_e1133 % 4u)) + (_e1151 % 16u)) % 16u);
                                                if (_e1149 == 1u) {
                                                    local_5 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    let _e1171 = (_e1158 < 16u);
                                                    if _e1171 {
                                                    } else {
                                                        phi_7209_ = true;
                                                        break;
                                                    }
                                                    let _e1174 = local_5[_e1158][0u];
                                                    local_6 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e1171 {
                                                    } else {
                                                        phi_7209_ = true;
                                                        break;
                                                    }
                                                    let _e1177 = local_6[_e1158][1u];
                                                    phi_1860_ = vec2<f32>(_e1174, _e1177);
                                                } else {
                                                    if (_e1149 == 2u) {
                                                        local_7 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        let _e1161 = (_e1158 < 16u);
                                                        if _e1161 {
                                                        } else {
                                                            phi_7209_ = true;
                                                            break;
                                                        }
                                                        let _e1164 = local_7[_e1158][0u];
                                                        local_8 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e1161 {
                                                        } else {
                                                            phi_7209_ = true;
                                                            break;
                                                        }
                                                        let _e1167 = local_8[_e1158][1u];
                                                        phi_1859_ = vec2<f32>(_e1164, _e1167);
                                                    } else {
                                                        phi_1859_ = vec2<f32>(0.5f, 0.5f);
                                                    }
                                                    let _e1170 = phi_1859_;
                                                    phi_1860_ = _e1170;
                                                }
                                                let _e1180 = phi_1860_;
                                                let _e1187 = (((f32(bitcast<i32>(_e1133)) - _e1116) + _e1180.x) / _e1112);
                                                let _e1192 = (((f32(bitcast<i32>(_e1147)) - _e1116) + _e1180.y) / _e1113);
                                                let _e1197 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e1202 = select(select(u32(_e1197), 0u, (_e1197 < 0f)), 4294967295u, (_e1197 > 4294967000f));
                                                let _e1207 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e1217 = (select(0f, select(1f, _e1187, (_e1187 < 1f)), (_e1187 > 0f)) * _e1197);
                                                let _e1220 = f32(bitcast<i32>((_e1202 - 1u)));
                                                let _e1233 = (select(0f, select(1f, _e1192, (_e1192 < 1f)), (_e1192 > 0f)) * _e1207);
                                                let _e1236 = f32(bitcast<i32>((select(select(u32(_e1207), 0u, (_e1207 < 0f)), 4294967295u, (_e1207 > 4294967000f)) - 1u)));
                                                let _e1248 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e1236, _e1233, (_e1233 < _e1236)), (_e1233 > 0f))) + 8388608f)) - 1258291200u) * _e1202) + (bitcast<u32>((floor(select(0f, select(_e1220, _e1217, (_e1217 < _e1220)), (_e1217 > 0f))) + 8388608f)) - 1258291200u))];
                                                let _e1258 = select(0x1.fffffep+127f, (select(_e1248, _e923, ((_e923 > _e1248) || (_e1248 != _e1248))) * 1.001f), select(false, (abs((_e1248 - _e923)) <= _e238), _e1088));
                                                let _e1260 = frame.member[0u].member_1.member_6;
                                                let _e1263 = (((_e1147 * _e1118) + _e1133) * _e1260);
                                                let _e1265 = sd_map.member[_e1263];
                                                let _e1269 = frame.member[0u].member_1.member.member.member_3;
                                                let _e1273 = frame.member[0u].member_1.member.member.member_2;
                                                let _e1274 = (_e1269 - _e1273);
                                                let _e1276 = ((_e1265 * _e1274) + _e1273);
                                                let _e1282 = select(_e1269, _e1276, select(false, select(false, (_e1276 > _e1258), (_e1265 < 1f)), (0u < _e1260)));
                                                let _e1283 = (_e1260 - 1u);
                                                let _e1288 = sd_map.member[(_e1263 + select(1u, _e1283, (_e1283 < 1u)))];
                                                let _e1290 = ((_e1288 * _e1274) + _e1273);
                                                let _e1296 = select(_e1269, _e1290, select(false, select(false, (_e1290 > _e1258), (_e1288 < 1f)), (1u < _e1260)));
                                                let _e1301 = sd_map.member[(_e1263 + select(2u, _e1283, (_e1283 < 2u)))];
                                                let _e1303 = ((_e1301 * _e1274) + _e1273);
                                                let _e1309 = select(_e1269, _e1303, select(false, select(false, (_e1303 > _e1258), (_e1301 < 1f)), (2u < _e1260)));
                                                let _e1314 = sd_map.member[(_e1263 + select(3u, _e1283, (_e1283 < 3u)))];
                                                let _e1316 = ((_e1314 * _e1274) + _e1273);
                                                let _e1322 = select(_e1269, _e1316, select(false, select(false, (_e1316 > _e1258), (_e1314 < 1f)), (3u < _e1260)));
                                                if (_e1260 > 4u) {
                                                    let _e1328 = sd_map.member[(_e1263 + select(4u, _e1283, (_e1283 < 4u)))];
                                                    let _e1330 = ((_e1328 * _e1274) + _e1273);
                                                    let _e1341 = sd_map.member[(_e1263 + select(5u, _e1283, (_e1283 < 5u)))];
                                                    let _e1343 = ((_e1341 * _e1274) + _e1273);
                                                    let _e1354 = sd_map.member[(_e1263 + select(6u, _e1283, (_e1283 < 6u)))];
                                                    let _e1356 = ((_e1354 * _e1274) + _e1273);
                                                    let _e1367 = sd_map.member[(_e1263 + select(7u, _e1283, (_e1283 < 7u)))];
                                                    let _e1369 = ((_e1367 * _e1274) + _e1273);
                                                    phi_2303_ = select(_e1269, _e1356, select(false, select(false, (_e1356 > _e1258), (_e1354 < 1f)), (6u < _e1260)));
                                                    phi_2304_ = select(_e1269, _e1343, select(false, select(false, (_e1343 > _e1258), (_e1341 < 1f)), (5u < _e1260)));
                                                    phi_2305_ = select(_e1269, _e1330, select(false, select(false, (_e1330 > _e1258), (_e1328 < 1f)), (4u < _e1260)));
                                                    phi_2306_ = select(_e1269, _e1369, select(false, select(false, (_e1369 > _e1258), (_e1367 < 1f)), (7u < _e1260)));
                                                } else {
                                                    phi_2303_ = _e1269;
                                                    phi_2304_ = _e1269;
                                                    phi_2305_ = _e1269;
                                                    phi_2306_ = _e1269;
                                                }
                                                let _e1377 = phi_2303_;
                                                let _e1379 = phi_2304_;
                                                let _e1381 = phi_2305_;
                                                let _e1383 = phi_2306_;
                                                let _e1385 = (_e1296 != _e1296);
                                                let _e1387 = select(_e1296, _e1282, ((_e1282 < _e1296) || _e1385));
                                                let _e1390 = select(_e1296, _e1282, ((_e1282 > _e1296) || _e1385));
                                                let _e1392 = (_e1322 != _e1322);
                                                let _e1394 = select(_e1322, _e1309, ((_e1309 < _e1322) || _e1392));
                                                let _e1397 = select(_e1322, _e1309, ((_e1309 > _e1322) || _e1392));
                                                let _e1399 = (_e1379 != _e1379);
                                                let _e1401 = select(_e1379, _e1381, ((_e1381 < _e1379) || _e1399));
                                                let _e1404 = select(_e1379, _e1381, ((_e1381 > _e1379) || _e1399));
                                                let _e1406 = (_e1383 != _e1383);
                                                let _e1408 = select(_e1383, _e1377, ((_e1377 < _e1383) || _e1406));
                                                let _e1411 = select(_e1383, _e1377, ((_e1377 > _e1383) || _e1406));
                                                let _e1413 = (_e1394 != _e1394);
                                                let _e1415 = select(_e1394, _e1387, ((_e1387 < _e1394) || _e1413));
                                                let _e1418 = select(_e1394, _e1387, ((_e1387 > _e1394) || _e1413));
                                                let _e1420 = (_e1397 != _e1397);
                                                let _e1422 = select(_e1397, _e1390, ((_e1390 < _e1397) || _e1420));
                                                let _e1425 = select(_e1397, _e1390, ((_e1390 > _e1397) || _e1420));
                                                let _e1427 = (_e1408 != _e1408);
                                                let _e1429 = select(_e1408, _e1401, ((_e1401 < _e1408) || _e1427));
                                                let _e1432 = select(_e1408, _e1401, ((_e1401 > _e1408) || _e1427));
                                                let _e1434 = (_e1411 != _e1411);
                                                let _e1436 = select(_e1411, _e1404, ((_e1404 < _e1411) || _e1434));
                                                let _e1439 = select(_e1411, _e1404, ((_e1404 > _e1411) || _e1434));
                                                let _e1441 = (_e1418 != _e1418);
                                                let _e1443 = select(_e1418, _e1422, ((_e1422 < _e1418) || _e1441));
                                                let _e1446 = select(_e1418, _e1422, ((_e1422 > _e1418) || _e1441));
                                                let _e1448 = (_e1432 != _e1432);
                                                let _e1450 = select(_e1432, _e1436, ((_e1436 < _e1432) || _e1448));
                                                let _e1453 = select(_e1432, _e1436, ((_e1436 > _e1432) || _e1448));
                                                let _e1455 = (_e1429 != _e1429);
                                                let _e1457 = select(_e1429, _e1415, ((_e1415 < _e1429) || _e1455));
                                                let _e1460 = select(_e1429, _e1415, ((_e1415 > _e1429) || _e1455));
                                                let _e1462 = (_e1450 != _e1450);
                                                let _e1464 = select(_e1450, _e1443, ((_e1443 < _e1450) || _e1462));
                                                let _e1467 = select(_e1450, _e1443, ((_e1443 > _e1450) || _e1462));
                                                let _e1469 = (_e1453 != _e1453);
                                                let _e1471 = select(_e1453, _e1446, ((_e1446 < _e1453) || _e1469));
                                                let _e1474 = select(_e1453, _e1446, ((_e1446 > _e1453) || _e1469));
                                                let _e1476 = (_e1439 != _e1439);
                                                let _e1478 = select(_e1439, _e1425, ((_e1425 < _e1439) || _e1476));
                                                let _e1481 = select(_e1439, _e1425, ((_e1425 > _e1439) || _e1476));
                                                let _e1483 = (_e1460 != _e1460);
                                                let _e1485 = select(_e1460, _e1471, ((_e1471 < _e1460) || _e1483));
                                                let _e1488 = select(_e1460, _e1471, ((_e1471 > _e1460) || _e1483));
                                                let _e1490 = (_e1467 != _e1467);
                                                let _e1492 = select(_e1467, _e1478, ((_e1478 < _e1467) || _e1490));
                                                let _e1495 = select(_e1467, _e1478, ((_e1478 > _e1467) || _e1490));
                                                let _e1497 = (_e1485 != _e1485);
                                                let _e1499 = select(_e1485, _e1464, ((_e1464 < _e1485) || _e1497));
                                                let _e1502 = select(_e1485, _e1464, ((_e1464 > _e1485) || _e1497));
                                                let _e1504 = (_e1488 != _e1488);
                                                let _e1506 = select(_e1488, _e1492, ((_e1492 < _e1488) || _e1504));
                                                let _e1509 = select(_e1488, _e1492, ((_e1492 > _e1488) || _e1504));
                                                let _e1511 = (_e1474 != _e1474);
                                                let _e1513 = select(_e1474, _e1495, ((_e1495 < _e1474) || _e1511));
                                                let _e1516 = select(_e1474, _e1495, ((_e1495 > _e1474) || _e1511));
                                                let _e1520 = select(false, (_e1457 > (_e923 + _e238)), (_e1457 < _e1269));
                                                let _e1522 = ((_e1187 * 2f) - 1f);
                                                let _e1526 = ((_e1192 * -2f) + 1f);
                                                let _e1536 = (_e1522 * _e225.member.member_1.x);
                                                let _e1538 = (_e1526 * _e225.member.member_1.y);
                                                let _e1540 = ((_e1536 * _e1499) - _e466);
                                                let _e1541 = ((_e1538 * _e1499) - _e473);
                                                let _e1542 = (_e1499 - _e459);
                                                if _e967 {
                                                    phi_2649_ = ((((_e1540 * _e1540) + (_e1541 * _e1541)) + (_e1542 * _e1542)) > (_e241 * _e241));
                                                } else {
                                                    phi_2649_ = false;
                                                }
                                                let _e1552 = phi_2649_;
                                                let _e1554 = select(false, !(_e1552), (_e1499 < _e225.member.member_3));
                                                if _e1554 {
                                                    let _e1555 = (_e1502 < _e225.member.member_3);
                                                    let _e1564 = select((_e1540 - _e978), ((_e1536 * _e1502) - _e466), _e1555);
                                                    let _e1565 = select((_e1541 - _e979), ((_e1538 * _e1502) - _e473), _e1555);
                                                    let _e1566 = select((_e1542 - _e980), (_e1502 - _e459), _e1555);
                                                    let _e1578 = ((((_e1540 * _e484) + (_e1541 * _e485)) + (_e1542 * _e486)) * inverseSqrt((((_e1540 * _e1540) + (_e1541 * _e1541)) + (_e1542 * _e1542))));
                                                    let _e1582 = select(-1f, select(1f, _e1578, (_e1578 < 1f)), (_e1578 > -1f));
                                                    let _e1583 = abs(_e1582);
                                                    let _e1593 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1583, 0.00667009f), _e1583, -0.017088126f), _e1583, 0.03089188f), _e1583, -0.050174303f), _e1583, 0.08897899f), _e1583, -0.2145988f), _e1583, 1.5707963f) * sqrt((1f - _e1583)));
                                                    let _e1600 = ((((select((3.1415927f - _e1593), _e1593, (_e1582 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1604 = select(0f, select(1f, _e1600, (_e1600 < 1f)), (_e1600 > 0f));
                                                    let _e1616 = ((((_e1564 * _e484) + (_e1565 * _e485)) + (_e1566 * _e486)) * inverseSqrt((((_e1564 * _e1564) + (_e1565 * _e1565)) + (_e1566 * _e1566))));
                                                    let _e1620 = select(-1f, select(1f, _e1616, (_e1616 < 1f)), (_e1616 > -1f));
                                                    let _e1621 = abs(_e1620);
                                                    let _e1631 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1621, 0.00667009f), _e1621, -0.017088126f), _e1621, 0.03089188f), _e1621, -0.050174303f), _e1621, 0.08897899f), _e1621, -0.2145988f), _e1621, 1.5707963f) * sqrt((1f - _e1621)));
                                                    let _e1638 = ((((select((3.1415927f - _e1631), _e1631, (_e1620 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1642 = select(0f, select(1f, _e1638, (_e1638 < 1f)), (_e1638 > 0f));
                                                    let _e1644 = (_e1642 != _e1642);
                                                    let _e1646 = select(_e1642, _e1604, ((_e1604 < _e1642) || _e1644));
                                                    let _e1649 = select(_e1642, _e1604, ((_e1604 > _e1642) || _e1644));
                                                    let _e1651 = floor((_e1646 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1659 = -(floor((_e1649 * -32f)));
                                                        let _e1664 = (select(32f, _e1659, ((_e1659 < 32f) || false)) - _e1651);
                                                        phi_2876_ = select(select(0f, _e1664, ((_e1664 > 0f) || false)), 0f, (_e1649 <= _e1646));
                                                    } else {
                                                        phi_2876_ = -(floor(((_e1649 - _e1646) * -32f)));
                                                    }
                                                    let _e1670 = phi_2876_;
                                                    let _e1678 = (bitcast<u32>((floor(select(0f, select(32f, _e1651, (_e1651 < 32f)), (_e1651 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1686 = (bitcast<u32>((floor(select(0f, select(32f, _e1670, (_e1670 < 32f)), (_e1670 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1678 >= 32u) {
                                                        phi_2930_ = u32();
                                                        phi_2931_ = true;
                                                    } else {
                                                        let _e1688 = (_e1686 == 0u);
                                                        if _e1688 {
                                                            phi_2929_ = u32();
                                                        } else {
                                                            if (_e1686 >= 32u) {
                                                                phi_2926_ = 4294967295u;
                                                            } else {
                                                                phi_2926_ = ((1u << bitcast<u32>((_e1686 & 31u))) - 1u);
                                                            }
                                                            let _e1695 = phi_2926_;
                                                            phi_2929_ = (_e1695 << bitcast<u32>((_e1678 & 31u)));
                                                        }
                                                        let _e1700 = phi_2929_;
                                                        phi_2930_ = _e1700;
                                                        phi_2931_ = _e1688;
                                                    }
                                                    let _e1702 = phi_2930_;
                                                    let _e1704 = phi_2931_;
                                                    phi_2944_ = select(0u, select(select(_e1702, 0u, _e1704), 0u, _e1069), _e1554);
                                                } else {
                                                    phi_2944_ = 0u;
                                                }
                                                let _e1709 = phi_2944_;
                                                let _e1712 = ((_e1536 * _e1506) - _e466);
                                                let _e1713 = ((_e1538 * _e1506) - _e473);
                                                let _e1714 = (_e1506 - _e459);
                                                if _e967 {
                                                    phi_2976_ = ((((_e1712 * _e1712) + (_e1713 * _e1713)) + (_e1714 * _e1714)) > (_e241 * _e241));
                                                } else {
                                                    phi_2976_ = false;
                                                }
                                                let _e1724 = phi_2976_;
                                                let _e1726 = select(false, !(_e1724), (_e1506 < _e225.member.member_3));
                                                if _e1726 {
                                                    let _e1727 = (_e1509 < _e225.member.member_3);
                                                    let _e1736 = select((_e1712 - _e978), ((_e1536 * _e1509) - _e466), _e1727);
                                                    let _e1737 = select((_e1713 - _e979), ((_e1538 * _e1509) - _e473), _e1727);
                                                    let _e1738 = select((_e1714 - _e980), (_e1509 - _e459), _e1727);
                                                    let _e1750 = ((((_e1712 * _e484) + (_e1713 * _e485)) + (_e1714 * _e486)) * inverseSqrt((((_e1712 * _e1712) + (_e1713 * _e1713)) + (_e1714 * _e1714))));
                                                    let _e1754 = select(-1f, select(1f, _e1750, (_e1750 < 1f)), (_e1750 > -1f));
                                                    let _e1755 = abs(_e1754);
                                                    let _e1765 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1755, 0.00667009f), _e1755, -0.017088126f), _e1755, 0.03089188f), _e1755, -0.050174303f), _e1755, 0.08897899f), _e1755, -0.2145988f), _e1755, 1.5707963f) * sqrt((1f - _e1755)));
                                                    let _e1772 = ((((select((3.1415927f - _e1765), _e1765, (_e1754 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1776 = select(0f, select(1f, _e1772, (_e1772 < 1f)), (_e1772 > 0f));
                                                    let _e1788 = ((((_e1736 * _e484) + (_e1737 * _e485)) + (_e1738 * _e486)) * inverseSqrt((((_e1736 * _e1736) + (_e1737 * _e1737)) + (_e1738 * _e1738))));
                                                    let _e1792 = select(-1f, select(1f, _e1788, (_e1788 < 1f)), (_e1788 > -1f));
                                                    let _e1793 = abs(_e1792);
                                                    let _e1803 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1793, 0.00667009f), _e1793, -0.017088126f), _e1793, 0.03089188f), _e1793, -0.050174303f), _e1793, 0.08897899f), _e1793, -0.2145988f), _e1793, 1.5707963f) * sqrt((1f - _e1793)));
                                                    let _e1810 = ((((select((3.1415927f - _e1803), _e1803, (_e1792 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1814 = select(0f, select(1f, _e1810, (_e1810 < 1f)), (_e1810 > 0f));
                                                    let _e1816 = (_e1814 != _e1814);
                                                    let _e1818 = select(_e1814, _e1776, ((_e1776 < _e1814) || _e1816));
                                                    let _e1821 = select(_e1814, _e1776, ((_e1776 > _e1814) || _e1816));
                                                    let _e1823 = floor((_e1818 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1831 = -(floor((_e1821 * -32f)));
                                                        let _e1836 = (select(32f, _e1831, ((_e1831 < 32f) || false)) - _e1823);
                                                        phi_3203_ = select(select(0f, _e1836, ((_e1836 > 0f) || false)), 0f, (_e1821 <= _e1818));
                                                    } else {
                                                        phi_3203_ = -(floor(((_e1821 - _e1818) * -32f)));
                                                    }
                                                    let _e1842 = phi_3203_;
                                                    let _e1850 = (bitcast<u32>((floor(select(0f, select(32f, _e1823, (_e1823 < 32f)), (_e1823 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1858 = (bitcast<u32>((floor(select(0f, select(32f, _e1842, (_e1842 < 32f)), (_e1842 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1850 >= 32u) {
                                                        phi_3257_ = u32();
                                                        phi_3258_ = true;
                                                    } else {
                                                        let _e1860 = (_e1858 == 0u);
                                                        if _e1860 {
                                                            phi_3256_ = u32();
                                                        } else {
                                                            if (_e1858 >= 32u) {
                                                                phi_3253_ = 4294967295u;
                                                            } else {
                                                                phi_3253_ = ((1u << bitcast<u32>((_e1858 & 31u))) - 1u);
                                                            }
                                                            let _e1867 = phi_3253_;
                                                            phi_3256_ = (_e1867 << bitcast<u32>((_e1850 & 31u)));
                                                        }
                                                        let _e1872 = phi_3256_;
                                                        phi_3257_ = _e1872;
                                                        phi_3258_ = _e1860;
                                                    }
                                                    let _e1874 = phi_3257_;
                                                    let _e1876 = phi_3258_;
                                                    phi_3271_ = select(0u, select(select(_e1874, 0u, _e1876), 0u, _e1069), _e1726);
                                                } else {
                                                    phi_3271_ = 0u;
                                                }
                                                let _e1881 = phi_3271_;
                                                let _e1885 = ((_e1536 * _e1513) - _e466);
                                                let _e1886 = ((_e1538 * _e1513) - _e473);
                                                let _e1887 = (_e1513 - _e459);
                                                if _e967 {
                                                    phi_3304_ = ((((_e1885 * _e1885) + (_e1886 * _e1886)) + (_e1887 * _e1887)) > (_e241 * _e241));
                                                } else {
                                                    phi_3304_ = false;
                                                }
                                                let _e1897 = phi_3304_;
                                                let _e1899 = select(false, !(_e1897), (_e1513 < _e225.member.member_3));
                                                if _e1899 {
                                                    let _e1900 = (_e1516 < _e225.member.member_3);
                                                    let _e1909 = select((_e1885 - _e978), ((_e1536 * _e1516) - _e466), _e1900);
                                                    let _e1910 = select((_e1886 - _e979), ((_e1538 * _e1516) - _e473), _e1900);
                                                    let _e1911 = select((_e1887 - _e980), (_e1516 - _e459), _e1900);
                                                    let _e1923 = ((((_e1885 * _e484) + (_e1886 * _e485)) + (_e1887 * _e486)) * inverseSqrt((((_e1885 * _e1885) + (_e1886 * _e1886)) + (_e1887 * _e1887))));
                                                    let _e1927 = select(-1f, select(1f, _e1923, (_e1923 < 1f)), (_e1923 > -1f));
                                                    let _e1928 = abs(_e1927);
                                                    let _e1938 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1928, 0.00667009f), _e1928, -0.017088126f), _e1928, 0.03089188f), _e1928, -0.050174303f), _e1928, 0.08897899f), _e1928, -0.2145988f), _e1928, 1.5707963f) * sqrt((1f - _e1928)));
                                                    let _e1945 = ((((select((3.1415927f - _e1938), _e1938, (_e1927 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1949 = select(0f, select(1f, _e1945, (_e1945 < 1f)), (_e1945 > 0f));
                                                    let _e1961 = ((((_e1909 * _e484) + (_e1910 * _e485)) + (_e1911 * _e486)) * inverseSqrt((((_e1909 * _e1909) + (_e1910 * _e1910)) + (_e1911 * _e1911))));
                                                    let _e1965 = select(-1f, select(1f, _e1961, (_e1961 < 1f)), (_e1961 > -1f));
                                                    let _e1966 = abs(_e1965);
                                                    let _e1976 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1966, 0.00667009f), _e1966, -0.017088126f), _e1966, 0.03089188f), _e1966, -0.050174303f), _e1966, 0.08897899f), _e1966, -0.2145988f), _e1966, 1.5707963f) * sqrt((1f - _e1966)));
                                                    let _e1983 = ((((select((3.1415927f - _e1976), _e1976, (_e1965 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1987 = select(0f, select(1f, _e1983, (_e1983 < 1f)), (_e1983 > 0f));
                                                    let _e1989 = (_e1987 != _e1987);
                                                    let _e1991 = select(_e1987, _e1949, ((_e1949 < _e1987) || _e1989));
                                                    let _e1994 = select(_e1987, _e1949, ((_e1949 > _e1987) || _e1989));
                                                    let _e1996 = floor((_e1991 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e2004 = -(floor((_e1994 * -32f)));
                                                        let _e2009 = (select(32f, _e2004, ((_e2004 < 32f) || false)) - _e1996);
                                                        phi_3531_ = select(select(0f, _e2009, ((_e2009 > 0f) || false)), 0f, (_e1994 <= _e1991));
                                                    } else {
                                                        phi_3531_ = -(floor(((_e1994 - _e1991) * -32f)));
                                                    }
                                                    let _e2015 = phi_3531_;
                                                    let _e2023 = (bitcast<u32>((floor(select(0f, select(32f, _e1996, (_e1996 < 32f)), (_e1996 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2031 = (bitcast<u32>((floor(select(0f, select(32f, _e2015, (_e2015 < 32f)), (_e2015 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2023 >= 32u) {
                                                        phi_3585_ = u32();
                                                        phi_3586_ = true;
                                                    } else {
                                                        let _e2033 = (_e2031 == 0u);
                                                        if _e2033 {
                                                            phi_3584_ = u32();
                                                        } else {
                                                            if (_e2031 >= 32u) {
                                                                phi_3581_ = 4294967295u;
                                                            } else {
                                                                phi_3581_ = ((1u << bitcast<u32>((_e2031 & 31u))) - 1u);
                                                            }
                                                            let _e2040 = phi_3581_;
                                                            phi_3584_ = (_e2040 << bitcast<u32>((_e2023 & 31u)));
                                                        }
                                                        let _e2045 = phi_3584_;
                                                        phi_3585_ = _e2045;
                                                        phi_3586_ = _e2033;
                                                    }
                                                    let _e2047 = phi_3585_;
                                                    let _e2049 = phi_3586_;
                                                    phi_3599_ = select(0u, select(select(_e2047, 0u, _e2049), 0u, _e1069), _e1899);
                                                } else {
                                                    phi_3599_ = 0u;
                                                }
                                                let _e2054 = phi_3599_;
                                                let _e2058 = ((_e1536 * _e1481) - _e466);
                                                let _e2059 = ((_e1538 * _e1481) - _e473);
                                                let _e2060 = (_e1481 - _e459);
                                                if _e967 {
                                                    phi_3632_ = ((((_e2058 * _e2058) + (_e2059 * _e2059)) + (_e2060 * _e2060)) > (_e241 * _e241));
                                                } else {
                                                    phi_3632_ = false;
                                                }
                                                let _e2070 = phi_3632_;
                                                let _e2072 = select(false, !(_e2070), (_e1481 < _e225.member.member_3));
                                                if _e2072 {
                                                    let _e2073 = (_e1269 < _e225.member.member_3);
                                                    let _e2082 = select((_e2058 - _e978), ((_e1536 * _e1269) - _e466), _e2073);
                                                    let _e2083 = select((_e2059 - _e979), ((_e1538 * _e1269) - _e473), _e2073);
                                                    let _e2084 = select((_e2060 - _e980), (_e1269 - _e459), _e2073);
                                                    let _e2096 = ((((_e2058 * _e484) + (_e2059 * _e485)) + (_e2060 * _e486)) * inverseSqrt((((_e2058 * _e2058) + (_e2059 * _e2059)) + (_e2060 * _e2060))));
                                                    let _e2100 = select(-1f, select(1f, _e2096, (_e2096 < 1f)), (_e2096 > -1f));
                                                    let _e2101 = abs(_e2100);
                                                    let _e2111 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2101, 0.00667009f), _e2101, -0.017088126f), _e2101, 0.03089188f), _e2101, -0.050174303f), _e2101, 0.08897899f), _e2101, -0.2145988f), _e2101, 1.5707963f) * sqrt((1f - _e2101)));
                                                    let _e2118 = ((((select((3.1415927f - _e2111), _e2111, (_e2100 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e2122 = select(0f, select(1f, _e2118, (_e2118 < 1f)), (_e2118 > 0f));
                                                    let _e2134 = ((((_e2082 * _e484) + (_e2083 * _e485)) + (_e2084 * _e486)) * inverseSqrt((((_e2082 * _e2082) + (_e2083 * _e2083)) + (_e2084 * _e2084))));
                                                    let _e2138 = select(-1f, select(1f, _e2134, (_e2134 < 1f)), (_e2134 > -1f));
                                                    let _e2139 = abs(_e2138);
                                                    let _e2149 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2139, 0.00667009f), _e2139, -0.017088126f), _e2139, 0.03089188f), _e2139, -0.050174303f), _e2139, 0.08897899f), _e2139, -0.2145988f), _e2139, 1.5707963f) * sqrt((1f - _e2139)));
                                                    let _e2156 = ((((select((3.1415927f - _e2149), _e2149, (_e2138 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e2160 = select(0f, select(1f, _e2156, (_e2156 < 1f)), (_e2156 > 0f));
                                                    let _e2162 = (_e2160 != _e2160);
                                                    let _e2164 = select(_e2160, _e2122, ((_e2122 < _e2160) || _e2162));
                                                    let _e2167 = select(_e2160, _e2122, ((_e2122 > _e2160) || _e2162));
                                                    let _e2169 = floor((_e2164 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e2177 = -(floor((_e2167 * -32f)));
                                                        let _e2182 = (select(32f, _e2177, ((_e2177 < 32f) || false)) - _e2169);
                                                        phi_3859_ = select(select(0f, _e2182, ((_e2182 > 0f) || false)), 0f, (_e2167 <= _e2164));
                                                    } else {
                                                        phi_3859_ = -(floor(((_e2167 - _e2164) * -32f)));
                                                    }
                                                    let _e2188 = phi_3859_;
                                                    let _e2196 = (bitcast<u32>((floor(select(0f, select(32f, _e2169, (_e2169 < 32f)), (_e2169 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2204 = (bitcast<u32>((floor(select(0f, select(32f, _e2188, (_e2188 < 32f)), (_e2188 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2196 >= 32u) {
                                                        phi_3913_ = u32();
                                                        phi_3914_ = true;
                                                    } else {
                                                        let _e2206 = (_e2204 == 0u);
                                                        if _e2206 {
                                                            phi_3912_ = u32();
                                                        } else {
                                                            if (_e2204 >= 32u) {
                                                                phi_3909_ = 4294967295u;
                                                            } else {
                                                                phi_3909_ = ((1u << bitcast<u32>((_e2204 & 31u))) - 1u);
                                                            }
                                                            let _e2213 = phi_3909_;
                                                            phi_3912_ = (_e2213 << bitcast<u32>((_e2196 & 31u)));
                                                        }
                                                        let _e2218 = phi_3912_;
                                                        phi_3913_ = _e2218;
                                                        phi_3914_ = _e2206;
                                                    }
                                                    let _e2220 = phi_3913_;
                                                    let _e2222 = phi_3914_;
                                                    phi_3927_ = select(0u, select(select(_e2220, 0u, _e2222), 0u, _e1069), _e2072);
                                                } else {
                                                    phi_3927_ = 0u;
                                                }
                                                let _e2227 = phi_3927_;
                                                phi_3929_ = (((_e1709 | _e1881) | _e2054) | _e2227);
                                                phi_3930_ = vec3<f32>(select(_e981, (((_e1522 * _e1095) * _e1457) - _e466), _e1520), select(_e982, (((_e1526 * _e1103) * _e1457) - _e473), _e1520), select(_e983, (_e1457 - _e459), _e1520));
                                            } else {
                                                phi_3929_ = 0u;
                                                phi_3930_ = vec3<f32>(_e981, _e982, _e983);
                                            }
                                            let _e2230 = phi_3929_;
                                            let _e2232 = phi_3930_;
                                            let _e2234 = (_e989 * inverseSqrt(_e1079));
                                            let _e2238 = select(-1f, select(1f, _e2234, (_e2234 < 1f)), (_e2234 > -1f));
                                            let _e2239 = abs(_e2238);
                                            let _e2249 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2239, 0.00667009f), _e2239, -0.017088126f), _e2239, 0.03089188f), _e2239, -0.050174303f), _e2239, 0.08897899f), _e2239, -0.2145988f), _e2239, 1.5707963f) * sqrt((1f - _e2239)));
                                            let _e2256 = ((((select((3.1415927f - _e2249), _e2249, (_e2238 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                            let _e2260 = select(0f, select(1f, _e2256, (_e2256 < 1f)), (_e2256 > 0f));
                                            let _e2275 = ((((_e2232.x * _e484) + (_e2232.y * _e485)) + (_e2232.z * _e486)) * inverseSqrt((((_e2232.x * _e2232.x) + (_e2232.y * _e2232.y)) + (_e2232.z * _e2232.z))));
                                            let _e2279 = select(-1f, select(1f, _e2275, (_e2275 < 1f)), (_e2275 > -1f));
                                            let _e2280 = abs(_e2279);
                                            let _e2290 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2280, 0.00667009f), _e2280, -0.017088126f), _e2280, 0.03089188f), _e2280, -0.050174303f), _e2280, 0.08897899f), _e2280, -0.2145988f), _e2280, 1.5707963f) * sqrt((1f - _e2280)));
                                            let _e2297 = ((((select((3.1415927f - _e2290), _e2290, (_e2279 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                            let _e2301 = select(0f, select(1f, _e2297, (_e2297 < 1f)), (_e2297 > 0f));
                                            let _e2303 = (_e2301 != _e2301);
                                            let _e2305 = select(_e2301, _e2260, ((_e2260 < _e2301) || _e2303));
                                            let _e2308 = select(_e2301, _e2260, ((_e2260 > _e2301) || _e2303));
                                            let _e2310 = floor((_e2305 * 32f));
                                            if (_e235 == 1u) {
                                                let _e2318 = -(floor((_e2308 * -32f)));
                                                let _e2323 = (select(32f, _e2318, ((_e2318 < 32f) || false)) - _e2310);
                                                phi_4117_ = select(select(0f, _e2323, ((_e2323 > 0f) || false)), 0f, (_e2308 <= _e2305));
                                            } else {
                                                phi_4117_ = -(floor(((_e2308 - _e2305) * -32f)));
                                            }
                                            let _e2329 = phi_4117_;
                                            let _e2337 = (bitcast<u32>((floor(select(0f, select(32f, _e2310, (_e2310 < 32f)), (_e2310 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e2345 = (bitcast<u32>((floor(select(0f, select(32f, _e2329, (_e2329 < 32f)), (_e2329 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e2337 >= 32u) {
                                                phi_4171_ = u32();
                                                phi_4172_ = true;
                                            } else {
                                                let _e2347 = (_e2345 == 0u);
                                                if _e2347 {
                                                    phi_4170_ = u32();
                                                } else {
                                                    if (_e2345 >= 32u) {
                                                        phi_4167_ = 4294967295u;
                                                    } else {
                                                        phi_4167_ = ((1u << bitcast<u32>((_e2345 & 31u))) - 1u);
                                                    }
                                                    let _e2354 = phi_4167_;
                                                    phi_4170_ = (_e2354 << bitcast<u32>((_e2337 & 31u)));
                                                }
                                                let _e2359 = phi_4170_;
                                                phi_4171_ = _e2359;
                                                phi_4172_ = _e2347;
                                            }
                                            let _e2361 = phi_4171_;
                                            let _e2363 = phi_4172_;
                                            phi_4186_ = select((select(select(_e2361, 0u, _e2363), 0u, _e1069) | _e2230), 0u, _e976);
                                        } else {
                                            phi_4186_ = 0u;
                                        }
                                        let _e2369 = phi_4186_;
                                        let _e2371 = (_e959 - _e466);
                                        let _e2372 = (_e963 - _e473);
                                        let _e2373 = (_e955 - _e459);
                                        if _e967 {
                                            phi_4206_ = ((((_e2371 * _e2371) + (_e2372 * _e2372)) + (_e2373 * _e2373)) > (_e241 * _e241));
                                        } else {
                                            phi_4206_ = false;
                                        }
                                        let _e2382 = phi_4206_;
                                        if !(_e2382) {
                                            let _e2384 = (_e484 * _e238);
                                            let _e2385 = (_e485 * _e238);
                                            let _e2386 = (_e486 * _e238);
                                            let _e2387 = (_e2371 - _e2384);
                                            let _e2388 = (_e2372 - _e2385);
                                            let _e2389 = (_e2373 - _e2386);
                                            let _e2395 = (((_e2371 * _e484) + (_e2372 * _e485)) + (_e2373 * _e486));
                                            let _e2399 = (_e2371 - (_e484 * _e2395));
                                            let _e2400 = (_e2372 - (_e485 * _e2395));
                                            let _e2401 = (_e2373 - (_e486 * _e2395));
                                            let _e2404 = ((_e2400 * _e486) - (_e485 * _e2401));
                                            let _e2407 = ((_e2401 * _e484) - (_e486 * _e2399));
                                            let _e2410 = ((_e2399 * _e485) - (_e484 * _e2400));
                                            let _e2421 = ((((_e545 * _e2404) + (_e546 * _e2407)) + (_e547 * _e2410)) / (((_e2404 * _e2404) + (_e2407 * _e2407)) + (_e2410 * _e2410)));
                                            let _e2425 = (_e545 - (_e2404 * _e2421));
                                            let _e2426 = (_e546 - (_e2407 * _e2421));
                                            let _e2427 = (_e547 - (_e2410 * _e2421));
                                            let _e2433 = inverseSqrt((((_e2425 * _e2425) + (_e2426 * _e2426)) + (_e2427 * _e2427)));
                                            let _e2439 = ((((_e2425 * _e484) + (_e2426 * _e485)) + (_e2427 * _e486)) * _e2433);
                                            let _e2443 = select(0f, select(1f, _e2439, (_e2439 < 1f)), (_e2439 > 0f));
                                            let _e2444 = abs(_e2443);
                                            let _e2454 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2444, 0.00667009f), _e2444, -0.017088126f), _e2444, 0.03089188f), _e2444, -0.050174303f), _e2444, 0.08897899f), _e2444, -0.2145988f), _e2444, 1.5707963f) * sqrt((1f - _e2444)));
                                            let _e2457 = select((3.1415927f - _e2454), _e2454, (_e2443 >= 0f));
                                            let _e2465 = select(_e2457, -(_e2457), ((((_e2399 * _e2425) + (_e2400 * _e2426)) + (_e2401 * _e2427)) < 0f));
                                            let _e2466 = (_e2433 * 0.02f);
                                            let _e2469 = select(0.19634955f, _e2466, ((_e2466 < 0.19634955f) || false));
                                            let _e2475 = ((((_e2399 * _e2399) + (_e2400 * _e2400)) + (_e2401 * _e2401)) <= 0f);
                                            let _e2485 = (((_e2371 * _e2371) + (_e2372 * _e2372)) + (_e2373 * _e2373));
                                            if _e967 {
                                                phi_4376_ = (_e2485 > (_e241 * _e241));
                                            } else {
                                                phi_4376_ = false;
                                            }
                                            let _e2492 = phi_4376_;
                                            let _e2494 = select(false, ((((_e2371 * _e545) + (_e2372 * _e546)) + (_e2373 * _e547)) > (sqrt(_e2485) * 0.018f)), !(_e2492));
                                            if _e2494 {
                                                let _e2495 = (0.5f / _e955);
                                                let _e2501 = frame.member[0u].member_1.member.member.member_1[0u];
                                                let _e2509 = frame.member[0u].member_1.member.member.member_1[1u];
                                                let _e2514 = frame.member[0u].member_1.member_5[0u];
                                                let _e2517 = frame.member[0u].member_1.member_5[1u];
                                                let _e2518 = f32(_e2514);
                                                let _e2519 = f32(_e2517);
                                                let _e2521 = frame.member[0u].member_1.member_4;
                                                let _e2522 = f32(_e2521);
                                                let _e2523 = (2u * _e2521);
                                                let _e2524 = (_e2514 + _e2523);
                                                let _e2528 = (floor(((((_e959 * _e2495) / _e2501) + 0.5f) * _e2518)) + _e2522);
                                                let _e2531 = f32(bitcast<i32>((_e2524 - 1u)));
                                                let _e2539 = (bitcast<u32>((floor(select(0f, select(_e2531, _e2528, (_e2528 < _e2531)), (_e2528 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2542 = (floor(((0.5f - ((_e963 * _e2495) / _e2509)) * _e2519)) + _e2522);
                                                let _e2545 = f32(bitcast<i32>(((_e2517 + _e2523) - 1u)));
                                                let _e2553 = (bitcast<u32>((floor(select(0f, select(_e2545, _e2542, (_e2542 < _e2545)), (_e2542 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2555 = frame.member[0u].member_1.member_8;
                                                let _e2557 = frame.member[0u].member_1.member_12;
                                                let _e2564 = (((((_e2553 % 4u) * 4u) + (_e2539 % 4u)) + (_e2557 % 16u)) % 16u);
                                                if (_e2555 == 1u) {
                                                    local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    let _e2577 = (_e2564 < 16u);
                                                    if _e2577 {
                                                    } else {
                                                        phi_7209_ = true;
                                                        break;
                                                    }
                                                    let _e2580 = local_1[_e2564][0u];
                                                    local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e2577 {
                                                    } else {
                                                        phi_7209_ = true;
                                                        break;
                                                    }
                                                    let _e2583 = local_2[_e2564][1u];
                                                    phi_4528_ = vec2<f32>(_e2580, _e2583);
                                                } else {
                                                    if (_e2555 == 2u) {
                                                        local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        let _e2567 = (_e2564 < 16u);
                                                        if _e2567 {
                                                        } else {
                                                            phi_7209_ = true;
                                                            break;
                                                        }
                                                        let _e2570 = local_3[_e2564][0u];
                                                        local_4 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e2567 {
                                                        } else {
                                                            phi_7209_ = true;
                                                            break;
                                                        }
                                                        let _e2573 = local_4[_e2564][1u];
                                                        phi_4527_ = vec2<f32>(_e2570, _e2573);
                                                    } else {
                                                        phi_4527_ = vec2<f32>(0.5f, 0.5f);
                                                    }
                                                    let _e2576 = phi_4527_;
                                                    phi_4528_ = _e2576;
                                                }
                                                let _e2586 = phi_4528_;
                                                let _e2593 = (((f32(bitcast<i32>(_e2539)) - _e2522) + _e2586.x) / _e2518);
                                                let _e2598 = (((f32(bitcast<i32>(_e2553)) - _e2522) + _e2586.y) / _e2519);
                                                let _e2603 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e2608 = select(select(u32(_e2603), 0u, (_e2603 < 0f)), 4294967295u, (_e2603 > 4294967000f));
                                                let _e2613 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e2623 = (select(0f, select(1f, _e2593, (_e2593 < 1f)), (_e2593 > 0f)) * _e2603);
                                                let _e2626 = f32(bitcast<i32>((_e2608 - 1u)));
                                                let _e2639 = (select(0f, select(1f, _e2598, (_e2598 < 1f)), (_e2598 > 0f)) * _e2613);
                                                let _e2642 = f32(bitcast<i32>((select(select(u32(_e2613), 0u, (_e2613 < 0f)), 4294967295u, (_e2613 > 4294967000f)) - 1u)));
                                                let _e2654 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e2642, _e2639, (_e2639 < _e2642)), (_e2639 > 0f))) + 8388608f)) - 1258291200u) * _e2608) + (bitcast<u32>((floor(select(0f, select(_e2626, _e2623, (_e2623 < _e2626)), (_e2623 > 0f))) + 8388608f)) - 1258291200u))];
                                                let _e2664 = select(0x1.fffffep+127f, (select(_e2654, _e955, ((_e955 > _e2654) || (_e2654 != _e2654))) * 1.001f), select(false, (abs((_e2654 - _e955)) <= _e238), _e2494));
                                                let _e2666 = frame.member[0u].member_1.member_6;
                                                let _e2669 = (((_e2553 * _e2524) + _e2539) * _e2666);
                                                let _e2671 = sd_map.member[_e2669];
                                                let _e2675 = frame.member[0u].member_1.member.member.member_3;
                                                let _e2679 = frame.member[0u].member_1.member.member.member_2;
                                                let _e2680 = (_e2675 - _e2679);
                                                let _e2682 = ((_e2671 * _e2680) + _e2679);
                                                let _e2688 = select(_e2675, _e2682, select(false, select(false, (_e2682 > _e2664), (_e2671 < 1f)), (0u < _e2666)));
                                                let _e2689 = (_e2666 - 1u);
                                                let _e2694 = sd_map.member[(_e2669 + select(1u, _e2689, (_e2689 < 1u)))];
                                                let _e2696 = ((_e2694 * _e2680) + _e2679);
                                                let _e2702 = select(_e2675, _e2696, select(false, select(false, (_e2696 > _e2664), (_e2694 < 1f)), (1u < _e2666)));
                                                let _e2707 = sd_map.member[(_e2669 + select(2u, _e2689, (_e2689 < 2u)))];
                                                let _e2709 = ((_e2707 * _e2680) + _e2679);
                                                let _e2715 = select(_e2675, _e2709, select(false, select(false, (_e2709 > _e2664), (_e2707 < 1f)), (2u < _e2666)));
                                                let _e2720 = sd_map.member[(_e2669 + select(3u, _e2689, (_e2689 < 3u)))];
                                                let _e2722 = ((_e2720 * _e2680) + _e2679);
                                                let _e2728 = select(_e2675, _e2722, select(false, select(false, (_e2722 > _e2664), (_e2720 < 1f)), (3u < _e2666)));
                                                if (_e2666 > 4u) {
                                                    let _e2734 = sd_map.member[(_e2669 + select(4u, _e2689, (_e2689 < 4u)))];
                                                    let _e2736 = ((_e2734 * _e2680) + _e2679);
                                                    let _e2747 = sd_map.member[(_e2669 + select(5u, _e2689, (_e2689 < 5u)))];
                                                    let _e2749 = ((_e2747 * _e2680) + _e2679);
                                                    let _e2760 = sd_map.member[(_e2669 + select(6u, _e2689, (_e2689 < 6u)))];
                                                    let _e2762 = ((_e2760 * _e2680) + _e2679);
                                                    let _e2773 = sd_map.member[(_e2669 + select(7u, _e2689, (_e2689 < 7u)))];
                                                    let _e2775 = ((_e2773 * _e2680) + _e2679);
                                                    phi_4971_ = select(_e2675, _e2762, select(false, select(false, (_e2762 > _e2664), (_e2760 < 1f)), (6u < _e2666)));
                                                    phi_4972_ = select(_e2675, _e2749, select(false, select(false, (_e2749 > _e2664), (_e2747 < 1f)), (5u < _e2666)));
                                                    phi_4973_ = select(_e2675, _e2736, select(false, select(false, (_e2736 > _e2664), (_e2734 < 1f)), (4u < _e2666)));
                                                    phi_4974_ = select(_e2675, _e2775, select(false, select(false, (_e2775 > _e2664), (_e2773 < 1f)), (7u < _e2666)));
                                                } else {
                                                    phi_4971_ = _e2675;
                                                    phi_4972_ = _e2675;
                                                    phi_4973_ = _e2675;
                                                    phi_4974_ = _e2675;
                                                }
                                                let _e2783 = phi_4971_;
                                                let _e2785 = phi_4972_;
                                                let _e2787 = phi_4973_;
                                                let _e2789 = phi_4974_;
                                                let _e2791 = (_e2702 != _e2702);
                                                let _e2793 = select(_e2702, _e2688, ((_e2688 < _e2702) || _e2791));
                                                let _e2796 = select(_e2702, _e2688, ((_e2688 > _e2702) || _e2791));
                                                let _e2798 = (_e2728 != _e2728);
                                                let _e2800 = select(_e2728, _e2715, ((_e2715 < _e2728) || _e2798));
                                                let _e2803 = select(_e2728, _e2715, ((_e2715 > _e2728) || _e2798));
                                                let _e2805 = (_e2785 != _e2785);
                                                let _e2807 = select(_e2785, _e2787, ((_e2787 < _e2785) || _e2805));
                                                let _e2810 = select(_e2785, _e2787, ((_e2787 > _e2785) || _e2805));
                                                let _e2812 = (_e2789 != _e2789);
                                                let _e2814 = select(_e2789, _e2783, ((_e2783 < _e2789) || _e2812));
                                                let _e2817 = select(_e2789, _e2783, ((_e2783 > _e2789) || _e2812));
                                                let _e2819 = (_e2800 != _e2800);
                                                let _e2821 = select(_e2800, _e2793, ((_e2793 < _e2800) || _e2819));
                                                let _e2824 = select(_e2800, _e2793, ((_e2793 > _e2800) || _e2819));
                                                let _e2826 = (_e2803 != _e2803);
                                                let _e2828 = select(_e2803, _e2796, ((_e2796 < _e2803) || _e2826));
                                                let _e2831 = select(_e2803, _e2796, ((_e2796 > _e2803) || _e2826));
                                                let _e2833 = (_e2814 != _e2814);
                                                let _e2835 = select(_e2814, _e2807, ((_e2807 < _e2814) || _e2833));
                                                let _e2838 = select(_e2814, _e2807, ((_e2807 > _e2814) || _e2833));
                                                let _e2840 = (_e2817 != _e2817);
                                                let _e2842 = select(_e2817, _e2810, ((_e2810 < _e2817) || _e2840));
                                                let _e2845 = select(_e2817, _e2810, ((_e2810 > _e2817) || _e2840));
                                                let _e2847 = (_e2824 != _e2824);
                                                let _e2849 = select(_e2824, _e2828, ((_e2828 < _e2824) || _e2847));
                                                let _e2852 = select(_e2824, _e2828, ((_e2828 > _e2824) || _e2847));
                                                let _e2854 = (_e2838 != _e2838);
                                                let _e2856 = select(_e2838, _e2842, ((_e2842 < _e2838) || _e2854));
                                                let _e2859 = select(_e2838, _e2842, ((_e2842 > _e2838) || _e2854));
                                                let _e2861 = (_e2835 != _e2835);
                                                let _e2863 = select(_e2835, _e2821, ((_e2821 < _e2835) || _e2861));
                                                let _e2866 = select(_e2835, _e2821, ((_e2821 > _e2835) || _e2861));
                                                let _e2868 = (_e2856 != _e2856);
                                                let _e2870 = select(_e2856, _e2849, ((_e2849 < _e2856) || _e2868));
                                                let _e2873 = select(_e2856, _e2849, ((_e2849 > _e2856) || _e2868));
                                                let _e2875 = (_e2859 != _e2859);
                                                let _e2877 = select(_e2859, _e2852, ((_e2852 < _e2859) || _e2875));
                                                let _e2880 = select(_e2859, _e2852, ((_e2852 > _e2859) || _e2875));
                                                let _e2882 = (_e2845 != _e2845);
                                                let _e2884 = select(_e2845, _e2831, ((_e2831 < _e2845) || _e2882));
                                                let _e2887 = select(_e2845, _e2831, ((_e2831 > _e2845) || _e2882));
                                                let _e2889 = (_e2866 != _e2866);
                                                let _e2891 = select(_e2866, _e2877, ((_e2877 < _e2866) || _e2889));
                                                let _e2894 = select(_e2866, _e2877, ((_e2877 > _e2866) || _e2889));
                                                let _e2896 = (_e2873 != _e2873);
                                                let _e2898 = select(_e2873, _e2884, ((_e2884 < _e2873) || _e2896));
                                                let _e2901 = select(_e2873, _e2884, ((_e2884 > _e2873) || _e2896));
                                                let _e2903 = (_e2891 != _e2891);
                                                let _e2905 = select(_e2891, _e2870, ((_e2870 < _e2891) || _e2903));
                                                let _e2908 = select(_e2891, _e2870, ((_e2870 > _e2891) || _e2903));
                                                let _e2910 = (_e2894 != _e2894);
                                                let _e2912 = select(_e2894, _e2898, ((_e2898 < _e2894) || _e2910));
                                                let _e2915 = select(_e2894, _e2898, ((_e2898 > _e2894) || _e2910));
                                                let _e2917 = (_e2880 != _e2880);
                                                let _e2919 = select(_e2880, _e2901, ((_e2901 < _e2880) || _e2917));
                                                let _e2922 = select(_e2880, _e2901, ((_e2901 > _e2880) || _e2917));
                                                let _e2926 = select(false, (_e2863 > (_e955 + _e238)), (_e2863 < _e2675));
                                                let _e2928 = ((_e2593 * 2f) - 1f);
                                                let _e2932 = ((_e2598 * -2f) + 1f);
                                                let _e2942 = (_e2928 * _e225.member.member_1.x);
                                                let _e2944 = (_e2932 * _e225.member.member_1.y);
                                                let _e2946 = ((_e2942 * _e2905) - _e466);
                                                let _e2947 = ((_e2944 * _e2905) - _e473);
                                                let _e2948 = (_e2905 - _e459);
                                                if _e967 {
                                                    phi_5317_ = ((((_e2946 * _e2946) + (_e2947 * _e2947)) + (_e2948 * _e2948)) > (_e241 * _e241));
                                                } else {
                                                    phi_5317_ = false;
                                                }
                                                let _e2958 = phi_5317_;
                                                let _e2960 = select(false, !(_e2958), (_e2905 < _e225.member.member_3));
                                                if _e2960 {
                                                    let _e2961 = (_e2908 < _e225.member.member_3);
                                                    let _e2970 = select((_e2946 - _e2384), ((_e2942 * _e2908) - _e466), _e2961);
                                                    let _e2971 = select((_e2947 - _e2385), ((_e2944 * _e2908) - _e473), _e2961);
                                                    let _e2972 = select((_e2948 - _e2386), (_e2908 - _e459), _e2961);
                                                    let _e2984 = ((((_e2946 * _e484) + (_e2947 * _e485)) + (_e2948 * _e486)) * inverseSqrt((((_e2946 * _e2946) + (_e2947 * _e2947)) + (_e2948 * _e2948))));
                                                    let _e2988 = select(-1f, select(1f, _e2984, (_e2984 < 1f)), (_e2984 > -1f));
                                                    let _e2989 = abs(_e2988);
                                                    let _e2999 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2989, 0.00667009f), _e2989, -0.017088126f), _e2989, 0.03089188f), _e2989, -0.050174303f), _e2989, 0.08897899f), _e2989, -0.2145988f), _e2989, 1.5707963f) * sqrt((1f - _e2989)));
                                                    let _e3006 = ((((select((3.1415927f - _e2999), _e2999, (_e2988 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3022 = ((((_e2970 * _e484) + (_e2971 * _e485)) + (_e2972 * _e486)) * inverseSqrt((((_e2970 * _e2970) + (_e2971 * _e2971)) + (_e2972 * _e2972))));
                                                    let _e3026 = select(-1f, select(1f, _e3022, (_e3022 < 1f)), (_e3022 > -1f));
                                                    let _e3027 = abs(_e3026);
                                                    let _e3037 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3027, 0.00667009f), _e3027, -0.017088126f), _e3027, 0.03089188f), _e3027, -0.050174303f), _e3027, 0.08897899f), _e3027, -0.2145988f), _e3027, 1.5707963f) * sqrt((1f - _e3027)));
                                                    let _e3044 = ((((select((3.1415927f - _e3037), _e3037, (_e3026 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3049 = (1f - select(0f, select(1f, _e3006, (_e3006 < 1f)), (_e3006 > 0f)));
                                                    let _e3050 = (1f - select(0f, select(1f, _e3044, (_e3044 < 1f)), (_e3044 > 0f)));
                                                    let _e3052 = (_e3050 != _e3050);
                                                    let _e3054 = select(_e3050, _e3049, ((_e3049 < _e3050) || _e3052));
                                                    let _e3057 = select(_e3050, _e3049, ((_e3049 > _e3050) || _e3052));
                                                    let _e3059 = floor((_e3054 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3067 = -(floor((_e3057 * -32f)));
                                                        let _e3072 = (select(32f, _e3067, ((_e3067 < 32f) || false)) - _e3059);
                                                        phi_5544_ = select(select(0f, _e3072, ((_e3072 > 0f) || false)), 0f, (_e3057 <= _e3054));
                                                    } else {
                                                        phi_5544_ = -(floor(((_e3057 - _e3054) * -32f)));
                                                    }
                                                    let _e3078 = phi_5544_;
                                                    let _e3086 = (bitcast<u32>((floor(select(0f, select(32f, _e3059, (_e3059 < 32f)), (_e3059 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3094 = (bitcast<u32>((floor(select(0f, select(32f, _e3078, (_e3078 < 32f)), (_e3078 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3086 >= 32u) {
                                                        phi_5598_ = u32();
                                                        phi_5599_ = true;
                                                    } else {
                                                        let _e3096 = (_e3094 == 0u);
                                                        if _e3096 {
                                                            phi_5597_ = u32();
                                                        } else {
                                                            if (_e3094 >= 32u) {
                                                                phi_5594_ = 4294967295u;
                                                            } else {
                                                                phi_5594_ = ((1u << bitcast<u32>((_e3094 & 31u))) - 1u);
                                                            }
                                                            let _e3103 = phi_5594_;
                                                            phi_5597_ = (_e3103 << bitcast<u32>((_e3086 & 31u)));
                                                        }
                                                        let _e3108 = phi_5597_;
                                                        phi_5598_ = _e3108;
                                                        phi_5599_ = _e3096;
                                                    }
                                                    let _e3110 = phi_5598_;
                                                    let _e3112 = phi_5599_;
                                                    phi_5612_ = select(0u, select(select(_e3110, 0u, _e3112), 0u, _e2475), _e2960);
                                                } else {
                                                    phi_5612_ = 0u;
                                                }
                                                let _e3117 = phi_5612_;
                                                let _e3120 = ((_e2942 * _e2912) - _e466);
                                                let _e3121 = ((_e2944 * _e2912) - _e473);
                                                let _e3122 = (_e2912 - _e459);
                                                if _e967 {
                                                    phi_5644_ = ((((_e3120 * _e3120) + (_e3121 * _e3121)) + (_e3122 * _e3122)) > (_e241 * _e241));
                                                } else {
                                                    phi_5644_ = false;
                                                }
                                                let _e3132 = phi_5644_;
                                                let _e3134 = select(false, !(_e3132), (_e2912 < _e225.member.member_3));
                                                if _e3134 {
                                                    let _e3135 = (_e2915 < _e225.member.member_3);
                                                    let _e3144 = select((_e3120 - _e2384), ((_e2942 * _e2915) - _e466), _e3135);
                                                    let _e3145 = select((_e3121 - _e2385), ((_e2944 * _e2915) - _e473), _e3135);
                                                    let _e3146 = select((_e3122 - _e2386), (_e2915 - _e459), _e3135);
                                                    let _e3158 = ((((_e3120 * _e484) + (_e3121 * _e485)) + (_e3122 * _e486)) * inverseSqrt((((_e3120 * _e3120) + (_e3121 * _e3121)) + (_e3122 * _e3122))));
                                                    let _e3162 = select(-1f, select(1f, _e3158, (_e3158 < 1f)), (_e3158 > -1f));
                                                    let _e3163 = abs(_e3162);
                                                    let _e3173 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3163, 0.00667009f), _e3163, -0.017088126f), _e3163, 0.03089188f), _e3163, -0.050174303f), _e3163, 0.08897899f), _e3163, -0.2145988f), _e3163, 1.5707963f) * sqrt((1f - _e3163)));
                                                    let _e3180 = ((((select((3.1415927f - _e3173), _e3173, (_e3162 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3196 = ((((_e3144 * _e484) + (_e3145 * _e485)) + (_e3146 * _e486)) * inverseSqrt((((_e3144 * _e3144) + (_e3145 * _e3145)) + (_e3146 * _e3146))));
                                                    let _e3200 = select(-1f, select(1f, _e3196, (_e3196 < 1f)), (_e3196 > -1f));
                                                    let _e3201 = abs(_e3200);
                                                    let _e3211 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3201, 0.00667009f), _e3201, -0.017088126f), _e3201, 0.03089188f), _e3201, -0.050174303f), _e3201, 0.08897899f), _e3201, -0.2145988f), _e3201, 1.5707963f) * sqrt((1f - _e3201)));
                                                    let _e3218 = ((((select((3.1415927f - _e3211), _e3211, (_e3200 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3223 = (1f - select(0f, select(1f, _e3180, (_e3180 < 1f)), (_e3180 > 0f)));
                                                    let _e3224 = (1f - select(0f, select(1f, _e3218, (_e3218 < 1f)), (_e3218 > 0f)));
                                                    let _e3226 = (_e3224 != _e3224);
                                                    let _e3228 = select(_e3224, _e3223, ((_e3223 < _e3224) || _e3226));
                                                    let _e3231 = select(_e3224, _e3223, ((_e3223 > _e3224) || _e3226));
                                                    let _e3233 = floor((_e3228 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3241 = -(floor((_e3231 * -32f)));
                                                        let _e3246 = (select(32f, _e3241, ((_e3241 < 32f) || false)) - _e3233);
                                                        phi_5871_ = select(select(0f, _e3246, ((_e3246 > 0f) || false)), 0f, (_e3231 <= _e3228));
                                                    } else {
                                                        phi_5871_ = -(floor(((_e3231 - _e3228) * -32f)));
                                                    }
                                                    let _e3252 = phi_5871_;
                                                    let _e3260 = (bitcast<u32>((floor(select(0f, select(32f, _e3233, (_e3233 < 32f)), (_e3233 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3268 = (bitcast<u32>((floor(select(0f, select(32f, _e3252, (_e3252 < 32f)), (_e3252 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3260 >= 32u) {
                                                        phi_5925_ = u32();
                                                        phi_5926_ = true;
                                                    } else {
                                                        let _e3270 = (_e3268 == 0u);
                                                        if _e3270 {
                                                            phi_5924_ = u32();
                                                        } else {
                                                            if (_e3268 >= 32u) {
                                                                phi_5921_ = 4294967295u;
                                                            } else {
                                                                phi_5921_ = ((1u << bitcast<u32>((_e3268 & 31u))) - 1u);
                                                            }
                                                            let _e3277 = phi_5921_;
                                                            phi_5924_ = (_e3277 << bitcast<u32>((_e3260 & 31u)));
                                                        }
                                                        let _e3282 = phi_5924_;
                                                        phi_5925_ = _e3282;
                                                        phi_5926_ = _e3270;
                                                    }
                                                    let _e3284 = phi_5925_;
                                                    let _e3286 = phi_5926_;
                                                    phi_5939_ = select(0u, select(select(_e3284, 0u, _e3286), 0u, _e2475), _e3134);
                                                } else {
                                                    phi_5939_ = 0u;
                                                }
                                                let _e3291 = phi_5939_;
                                                let _e3295 = ((_e2942 * _e2919) - _e466);
                                                let _e3296 = ((_e2944 * _e2919) - _e473);
                                                let _e3297 = (_e2919 - _e459);
                                                if _e967 {
                                                    phi_5972_ = ((((_e3295 * _e3295) + (_e3296 * _e3296)) + (_e3297 * _e3297)) > (_e241 * _e241));
                                                } else {
                                                    phi_5972_ = false;
                                                }
                                                let _e3307 = phi_5972_;
                                                let _e3309 = select(false, !(_e3307), (_e2919 < _e225.member.member_3));
                                                if _e3309 {
                                                    let _e3310 = (_e2922 < _e225.member.member_3);
                                                    let _e3319 = select((_e3295 - _e2384), ((_e2942 * _e2922) - _e466), _e3310);
                                                    let _e3320 = select((_e3296 - _e2385), ((_e2944 * _e2922) - _e473), _e3310);
                                                    let _e3321 = select((_e3297 - _e2386), (_e2922 - _e459), _e3310);
                                                    let _e3333 = ((((_e3295 * _e484) + (_e3296 * _e485)) + (_e3297 * _e486)) * inverseSqrt((((_e3295 * _e3295) + (_e3296 * _e3296)) + (_e3297 * _e3297))));
                                                    let _e3337 = select(-1f, select(1f, _e3333, (_e3333 < 1f)), (_e3333 > -1f));
                                                    let _e3338 = abs(_e3337);
                                                    let _e3348 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3338, 0.00667009f), _e3338, -0.017088126f), _e3338, 0.03089188f), _e3338, -0.050174303f), _e3338, 0.08897899f), _e3338, -0.2145988f), _e3338, 1.5707963f) * sqrt((1f - _e3338)));
                                                    let _e3355 = ((((select((3.1415927f - _e3348), _e3348, (_e3337 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3371 = ((((_e3319 * _e484) + (_e3320 * _e485)) + (_e3321 * _e486)) * inverseSqrt((((_e3319 * _e3319) + (_e3320 * _e3320)) + (_e3321 * _e3321))));
                                                    let _e3375 = select(-1f, select(1f, _e3371, (_e3371 < 1f)), (_e3371 > -1f));
                                                    let _e3376 = abs(_e3375);
                                                    let _e3386 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3376, 0.00667009f), _e3376, -0.017088126f), _e3376, 0.03089188f), _e3376, -0.050174303f), _e3376, 0.08897899f), _e3376, -0.2145988f), _e3376, 1.5707963f) * sqrt((1f - _e3376)));
                                                    let _e3393 = ((((select((3.1415927f - _e3386), _e3386, (_e3375 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3398 = (1f - select(0f, select(1f, _e3355, (_e3355 < 1f)), (_e3355 > 0f)));
                                                    let _e3399 = (1f - select(0f, select(1f, _e3393, (_e3393 < 1f)), (_e3393 > 0f)));
                                                    let _e3401 = (_e3399 != _e3399);
                                                    let _e3403 = select(_e3399, _e3398, ((_e3398 < _e3399) || _e3401));
                                                    let _e3406 = select(_e3399, _e3398, ((_e3398 > _e3399) || _e3401));
                                                    let _e3408 = floor((_e3403 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3416 = -(floor((_e3406 * -32f)));
                                                        let _e3421 = (select(32f, _e3416, ((_e3416 < 32f) || false)) - _e3408);
                                                        phi_6199_ = select(select(0f, _e3421, ((_e3421 > 0f) || false)), 0f, (_e3406 <= _e3403));
                                                    } else {
                                                        phi_6199_ = -(floor(((_e3406 - _e3403) * -32f)));
                                                    }
                                                    let _e3427 = phi_6199_;
                                                    let _e3435 = (bitcast<u32>((floor(select(0f, select(32f, _e3408, (_e3408 < 32f)), (_e3408 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3443 = (bitcast<u32>((floor(select(0f, select(32f, _e3427, (_e3427 < 32f)), (_e3427 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3435 >= 32u) {
                                                        phi_6253_ = u32();
                                                        phi_6254_ = true;
                                                    } else {
                                                        let _e3445 = (_e3443 == 0u);
                                                        if _e3445 {
                                                            phi_6252_ = u32();
                                                        } else {
                                                            if (_e3443 >= 32u) {
                                                                phi_6249_ = 4294967295u;
                                                            } else {
                                                                phi_6249_ = ((1u << bitcast<u32>((_e3443 & 31u))) - 1u);
                                                            }
                                                            let _e3452 = phi_6249_;
                                                            phi_6252_ = (_e3452 << bitcast<u32>((_e3435 & 31u)));
                                                        }
                                                        let _e3457 = phi_6252_;
                                                        phi_6253_ = _e3457;
                                                        phi_6254_ = _e3445;
                                                    }
                                                    let _e3459 = phi_6253_;
                                                    let _e3461 = phi_6254_;
                                                    phi_6267_ = select(0u, select(select(_e3459, 0u, _e3461), 0u, _e2475), _e3309);
                                                } else {
                                                    phi_6267_ = 0u;
                                                }
                                                let _e3466 = phi_6267_;
                                                let _e3470 = ((_e2942 * _e2887) - _e466);
                                                let _e3471 = ((_e2944 * _e2887) - _e473);
                                                let _e3472 = (_e2887 - _e459);
                                                if _e967 {
                                                    phi_6300_ = ((((_e3470 * _e3470) + (_e3471 * _e3471)) + (_e3472 * _e3472)) > (_e241 * _e241));
                                                } else {
                                                    phi_6300_ = false;
                                                }
                                                let _e3482 = phi_6300_;
                                                let _e3484 = select(false, !(_e3482), (_e2887 < _e225.member.member_3));
                                                if _e3484 {
                                                    let _e3485 = (_e2675 < _e225.member.member_3);
                                                    let _e3494 = select((_e3470 - _e2384), ((_e2942 * _e2675) - _e466), _e3485);
                                                    let _e3495 = select((_e3471 - _e2385), ((_e2944 * _e2675) - _e473), _e3485);
                                                    let _e3496 = select((_e3472 - _e2386), (_e2675 - _e459), _e3485);
                                                    let _e3508 = ((((_e3470 * _e484) + (_e3471 * _e485)) + (_e3472 * _e486)) * inverseSqrt((((_e3470 * _e3470) + (_e3471 * _e3471)) + (_e3472 * _e3472))));
                                                    let _e3512 = select(-1f, select(1f, _e3508, (_e3508 < 1f)), (_e3508 > -1f));
                                                    let _e3513 = abs(_e3512);
                                                    let _e3523 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3513, 0.00667009f), _e3513, -0.017088126f), _e3513, 0.03089188f), _e3513, -0.050174303f), _e3513, 0.08897899f), _e3513, -0.2145988f), _e3513, 1.5707963f) * sqrt((1f - _e3513)));
                                                    let _e3530 = ((((select((3.1415927f - _e3523), _e3523, (_e3512 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3546 = ((((_e3494 * _e484) + (_e3495 * _e485)) + (_e3496 * _e486)) * inverseSqrt((((_e3494 * _e3494) + (_e3495 * _e3495)) + (_e3496 * _e3496))));
                                                    let _e3550 = select(-1f, select(1f, _e3546, (_e3546 < 1f)), (_e3546 > -1f));
                                                    let _e3551 = abs(_e3550);
                                                    let _e3561 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3551, 0.00667009f), _e3551, -0.017088126f), _e3551, 0.03089188f), _e3551, -0.050174303f), _e3551, 0.08897899f), _e3551, -0.2145988f), _e3551, 1.5707963f) * sqrt((1f - _e3551)));
                                                    let _e3568 = ((((select((3.1415927f - _e3561), _e3561, (_e3550 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                                    let _e3573 = (1f - select(0f, select(1f, _e3530, (_e3530 < 1f)), (_e3530 > 0f)));
                                                    let _e3574 = (1f - select(0f, select(1f, _e3568, (_e3568 < 1f)), (_e3568 > 0f)));
                                                    let _e3576 = (_e3574 != _e3574);
                                                    let _e3578 = select(_e3574, _e3573, ((_e3573 < _e3574) || _e3576));
                                                    let _e3581 = select(_e3574, _e3573, ((_e3573 > _e3574) || _e3576));
                                                    let _e3583 = floor((_e3578 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3591 = -(floor((_e3581 * -32f)));
                                                        let _e3596 = (select(32f, _e3591, ((_e3591 < 32f) || false)) - _e3583);
                                                        phi_6527_ = select(select(0f, _e3596, ((_e3596 > 0f) || false)), 0f, (_e3581 <= _e3578));
                                                    } else {
                                                        phi_6527_ = -(floor(((_e3581 - _e3578) * -32f)));
                                                    }
                                                    let _e3602 = phi_6527_;
                                                    let _e3610 = (bitcast<u32>((floor(select(0f, select(32f, _e3583, (_e3583 < 32f)), (_e3583 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3618 = (bitcast<u32>((floor(select(0f, select(32f, _e3602, (_e3602 < 32f)), (_e3602 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3610 >= 32u) {
                                                        phi_6581_ = u32();
                                                        phi_6582_ = true;
                                                    } else {
                                                        let _e3620 = (_e3618 == 0u);
                                                        if _e3620 {
                                                            phi_6580_ = u32();
                                                        } else {
                                                            if (_e3618 >= 32u) {
                                                                phi_6577_ = 4294967295u;
                                                            } else {
                                                                phi_6577_ = ((1u << bitcast<u32>((_e3618 & 31u))) - 1u);
                                                            }
                                                            let _e3627 = phi_6577_;
                                                            phi_6580_ = (_e3627 << bitcast<u32>((_e3610 & 31u)));
                                                        }
                                                        let _e3632 = phi_6580_;
                                                        phi_6581_ = _e3632;
                                                        phi_6582_ = _e3620;
                                                    }
                                                    let _e3634 = phi_6581_;
                                                    let _e3636 = phi_6582_;
                                                    phi_6595_ = select(0u, select(select(_e3634, 0u, _e3636), 0u, _e2475), _e3484);
                                                } else {
                                                    phi_6595_ = 0u;
                                                }
                                                let _e3641 = phi_6595_;
                                                phi_6597_ = (((_e3117 | _e3291) | _e3466) | _e3641);
                                                phi_6598_ = vec3<f32>(select(_e2387, (((_e2928 * _e2501) * _e2863) - _e466), _e2926), select(_e2388, (((_e2932 * _e2509) * _e2863) - _e473), _e2926), select(_e2389, (_e2863 - _e459), _e2926));
                                            } else {
                                                phi_6597_ = 0u;
                                                phi_6598_ = vec3<f32>(_e2387, _e2388, _e2389);
                                            }
                                            let _e3644 = phi_6597_;
                                            let _e3646 = phi_6598_;
                                            let _e3648 = (_e2395 * inverseSqrt(_e2485));
                                            let _e3652 = select(-1f, select(1f, _e3648, (_e3648 < 1f)), (_e3648 > -1f));
                                            let _e3653 = abs(_e3652);
                                            let _e3663 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3653, 0.00667009f), _e3653, -0.017088126f), _e3653, 0.03089188f), _e3653, -0.050174303f), _e3653, 0.08897899f), _e3653, -0.2145988f), _e3653, 1.5707963f) * sqrt((1f - _e3653)));
                                            let _e3670 = ((((select((3.1415927f - _e3663), _e3663, (_e3652 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                            let _e3689 = ((((_e3646.x * _e484) + (_e3646.y * _e485)) + (_e3646.z * _e486)) * inverseSqrt((((_e3646.x * _e3646.x) + (_e3646.y * _e3646.y)) + (_e3646.z * _e3646.z))));
                                            let _e3693 = select(-1f, select(1f, _e3689, (_e3689 < 1f)), (_e3689 > -1f));
                                            let _e3694 = abs(_e3693);
                                            let _e3704 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3694, 0.00667009f), _e3694, -0.017088126f), _e3694, 0.03089188f), _e3694, -0.050174303f), _e3694, 0.08897899f), _e3694, -0.2145988f), _e3694, 1.5707963f) * sqrt((1f - _e3694)));
                                            let _e3711 = ((((select((3.1415927f - _e3704), _e3704, (_e3693 >= 0f)) + _e2469) - _e2465) + 1.5707964f) * 0.31830987f);
                                            let _e3716 = (1f - select(0f, select(1f, _e3670, (_e3670 < 1f)), (_e3670 > 0f)));
                                            let _e3717 = (1f - select(0f, select(1f, _e3711, (_e3711 < 1f)), (_e3711 > 0f)));
                                            let _e3719 = (_e3717 != _e3717);
                                            let _e3721 = select(_e3717, _e3716, ((_e3716 < _e3717) || _e3719));
                                            let _e3724 = select(_e3717, _e3716, ((_e3716 > _e3717) || _e3719));
                                            let _e3726 = floor((_e3721 * 32f));
                                            if (_e235 == 1u) {
                                                let _e3734 = -(floor((_e3724 * -32f)));
                                                let _e3739 = (select(32f, _e3734, ((_e3734 < 32f) || false)) - _e3726);
                                                phi_6785_ = select(select(0f, _e3739, ((_e3739 > 0f) || false)), 0f, (_e3724 <= _e3721));
                                            } else {
                                                phi_6785_ = -(floor(((_e3724 - _e3721) * -32f)));
                                            }
                                            let _e3745 = phi_6785_;
                                            let _e3753 = (bitcast<u32>((floor(select(0f, select(32f, _e3726, (_e3726 < 32f)), (_e3726 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e3761 = (bitcast<u32>((floor(select(0f, select(32f, _e3745, (_e3745 < 32f)), (_e3745 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e3753 >= 32u) {
                                                phi_6839_ = u32();
                                                phi_6840_ = true;
                                            } else {
                                                let _e3763 = (_e3761 == 0u);
                                                if _e3763 {
                                                    phi_6838_ = u32();
                                                } else {
                                                    if (_e3761 >= 32u) {
                                                        phi_6835_ = 4294967295u;
                                                    } else {
                                                        phi_6835_ = ((1u << bitcast<u32>((_e3761 & 31u))) - 1u);
                                                    }
                                                    let _e3770 = phi_6835_;
                                                    phi_6838_ = (_e3770 << bitcast<u32>((_e3753 & 31u)));
                                                }
                                                let _e3775 = phi_6838_;
                                                phi_6839_ = _e3775;
                                                phi_6840_ = _e3763;
                                            }
                                            let _e3777 = phi_6839_;
                                            let _e3779 = phi_6840_;
                                            phi_6854_ = select((select(select(_e3777, 0u, _e3779), 0u, _e2475) | _e3644), 0u, _e2382);
                                        } else {
                                            phi_6854_ = 0u;
                                        }
                                        let _e3785 = phi_6854_;
                                        phi_1200_ = (_e787 + 1u);
                                        phi_1203_ = ((_e789 | _e2369) | _e3785);
                                    } else {
                                        phi_1200_ = u32();
                                        phi_1203_ = u32();
                                    }
                                    let _e3789 = phi_1200_;
                                    let _e3791 = phi_1203_;
                                    continue;
                                    continuing {
                                        phi_1199_ = _e3789;
                                        phi_1202_ = _e3791;
                                        phi_7209_ = _e684;
                                        break if !(_e790);
                                    }
                                }
                                let _e3794 = phi_7209_;
                                phi_7835_ = _e3794;
                                if _e3794 {
                                    break;
                                }
                                if (_e230 == 2u) {
                                    let _e3853 = (_e782 - 1.5707964f);
                                    let _e3854 = (_e3853 * 2f);
                                    let _e3855 = sin(_e782);
                                    let _e3860 = ((_e767 + (_e3854 * _e3855)) - cos((_e3854 - _e782)));
                                    phi_6883_ = 0u;
                                    phi_6886_ = select((_e3860 * 0.25f), (_e3860 * -0.25f), (_e3853 < 0f));
                                    phi_6888_ = 0f;
                                    loop {
                                        let _e3866 = phi_6883_;
                                        let _e3868 = phi_6886_;
                                        let _e3870 = phi_6888_;
                                        local_13 = _e3870;
                                        let _e3871 = (_e3866 < 32u);
                                        if _e3871 {
                                            let _e3872 = (_e3866 + 1u);
                                            let _e3876 = (_e3853 + (f32(bitcast<i32>(_e3872)) * 0.09817477f));
                                            let _e3877 = (_e3876 * 2f);
                                            let _e3882 = ((_e767 + (_e3877 * _e3855)) - cos((_e3877 - _e782)));
                                            let _e3886 = select((_e3882 * 0.25f), (_e3882 * -0.25f), (_e3876 < 0f));
                                            let _e3889 = local_12;
                                            phi_6884_ = _e3872;
                                            phi_6887_ = _e3886;
                                            phi_6889_ = select(_e3870, (_e3870 + (_e3886 - _e3868)), (((_e3889 >> bitcast<u32>((_e3866 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_6884_ = u32();
                                            phi_6887_ = f32();
                                            phi_6889_ = f32();
                                        }
                                        let _e3898 = phi_6884_;
                                        let _e3900 = phi_6887_;
                                        let _e3902 = phi_6889_;
                                        continue;
                                        continuing {
                                            phi_6883_ = _e3898;
                                            phi_6886_ = _e3900;
                                            phi_6888_ = _e3902;
                                            break if !(_e3871);
                                        }
                                    }
                                    let _e3905 = local_13;
                                    phi_7837_ = _e3794;
                                    phi_6990_ = (_e688 + 1f);
                                    phi_6991_ = (_e690 + ((_e748 + ((1f - _e748) * 0.05f)) * _e3905));
                                } else {
                                    if (_e230 == 1u) {
                                        phi_6935_ = 0u;
                                        phi_6938_ = 0f;
                                        loop {
                                            let _e3808 = phi_6935_;
                                            let _e3810 = phi_6938_;
                                            local_11 = _e3810;
                                            let _e3811 = (_e3808 < 4u);
                                            if _e3811 {
                                                local = array<type_40, 4>(type_40(4026531855u, 0.0095061f), type_40(251658480u, 0.0270951f), type_40(15732480u, 0.0405571f), type_40(1044480u, 0.0478421f));
                                                if _e3811 {
                                                } else {
                                                    phi_7832_ = true;
                                                    break;
                                                }
                                                let _e3814 = local[_e3808].member;
                                                let _e3817 = local[_e3808].member_1;
                                                let _e3819 = local_10;
                                                phi_6936_ = (_e3808 + 1u);
                                                phi_6939_ = (_e3810 + (f32(bitcast<i32>(countOneBits((_e3819 & _e3814)))) * _e3817));
                                            } else {
                                                phi_6936_ = u32();
                                                phi_6939_ = f32();
                                            }
                                            let _e3828 = phi_6936_;
                                            let _e3830 = phi_6939_;
                                            continue;
                                            continuing {
                                                phi_6935_ = _e3828;
                                                phi_6938_ = _e3830;
                                                phi_7832_ = _e3794;
                                                break if !(_e3811);
                                            }
                                        }
                                        let _e3833 = phi_7832_;
                                        phi_7835_ = _e3833;
                                        if _e3833 {
                                            break;
                                        }
                                        let _e3835 = local_11;
                                        let _e3836 = (1f - _e3835);
                                        phi_7843_ = _e3833;
                                        phi_6988_ = (_e688 + _e748);
                                        phi_6989_ = (_e690 + (_e748 * select(0f, select(1f, _e3836, (_e3836 < 1f)), (_e3836 > 0f))));
                                    } else {
                                        let _e3798 = local_9;
                                        phi_7843_ = _e3794;
                                        phi_6988_ = (_e688 + 1f);
                                        phi_6989_ = (_e690 + ((f32(bitcast<i32>(countOneBits((_e3798 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e3845 = phi_7843_;
                                    let _e3847 = phi_6988_;
                                    let _e3849 = phi_6989_;
                                    phi_7837_ = _e3845;
                                    phi_6990_ = _e3847;
                                    phi_6991_ = _e3849;
                                }
                                let _e3910 = phi_7837_;
                                let _e3912 = phi_6990_;
                                let _e3914 = phi_6991_;
                                phi_7836_ = _e3910;
                                phi_1009_ = (_e686 + 1u);
                                phi_1012_ = _e3912;
                                phi_1014_ = _e3914;
                            } else {
                                phi_7836_ = _e684;
                                phi_1009_ = u32();
                                phi_1012_ = f32();
                                phi_1014_ = f32();
                            }
                            let _e3917 = phi_7836_;
                            let _e3919 = phi_1009_;
                            let _e3921 = phi_1012_;
                            let _e3923 = phi_1014_;
                            continue;
                            continuing {
                                phi_7748_ = _e3917;
                                phi_1008_ = _e3919;
                                phi_1011_ = _e3921;
                                phi_1013_ = _e3923;
                                phi_7835_ = _e3917;
                                break if !(_e691);
                            }
                        }
                        let _e3926 = phi_7835_;
                        if _e3926 {
                            break;
                        }
                        let _e3928 = local_14;
                        let _e3931 = local_15;
                        let _e3933 = local_16;
                        phi_6999_ = select(1f, (_e3931 / _e3933), (_e3928 > 0f));
                    } else {
                        phi_6999_ = 1f;
                    }
                    let _e3937 = phi_6999_;
                    if (_e225.member_6 == 2f) {
                        phi_7012_ = (_e3937 * _e3937);
                    } else {
                        if (_e225.member_6 == 1f) {
                            phi_7011_ = _e3937;
                        } else {
                            phi_7011_ = pow(_e3937, _e225.member_6);
                        }
                        let _e3943 = phi_7011_;
                        phi_7012_ = _e3943;
                    }
                    let _e3946 = phi_7012_;
                    let _e3951 = (select(1f, select(0.03f, _e3946, ((_e3946 > 0.03f) || false)), _e679) * 0.6666667f);
                    terms.member[_e267] = (bitcast<u32>((floor(((select(0f, select(1f, _e3951, (_e3951 < 1f)), (_e3951 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
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
