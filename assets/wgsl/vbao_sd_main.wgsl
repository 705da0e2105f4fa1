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
    var phi_7728_: bool;
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
    var phi_2297_: f32;
    var phi_2298_: f32;
    var phi_2299_: f32;
    var phi_2300_: f32;
    var phi_2642_: bool;
    var phi_2869_: f32;
    var phi_2919_: u32;
    var phi_2922_: u32;
    var phi_2923_: u32;
    var phi_2924_: bool;
    var phi_2937_: u32;
    var phi_2968_: bool;
    var phi_3195_: f32;
    var phi_3245_: u32;
    var phi_3248_: u32;
    var phi_3249_: u32;
    var phi_3250_: bool;
    var phi_3263_: u32;
    var phi_3295_: bool;
    var phi_3522_: f32;
    var phi_3572_: u32;
    var phi_3575_: u32;
    var phi_3576_: u32;
    var phi_3577_: bool;
    var phi_3590_: u32;
    var phi_3622_: bool;
    var phi_3849_: f32;
    var phi_3899_: u32;
    var phi_3902_: u32;
    var phi_3903_: u32;
    var phi_3904_: bool;
    var phi_3917_: u32;
    var phi_3919_: u32;
    var phi_3920_: vec3<f32>;
    var phi_4107_: f32;
    var phi_4157_: u32;
    var phi_4160_: u32;
    var phi_4161_: u32;
    var phi_4162_: bool;
    var phi_4176_: u32;
    var phi_4196_: bool;
    var phi_4349_: bool;
    var phi_4511_: vec2<f32>;
    var phi_4512_: vec2<f32>;
    var phi_4955_: f32;
    var phi_4956_: f32;
    var phi_4957_: f32;
    var phi_4958_: f32;
    var phi_5300_: bool;
    var phi_5527_: f32;
    var phi_5577_: u32;
    var phi_5580_: u32;
    var phi_5581_: u32;
    var phi_5582_: bool;
    var phi_5595_: u32;
    var phi_5626_: bool;
    var phi_5853_: f32;
    var phi_5903_: u32;
    var phi_5906_: u32;
    var phi_5907_: u32;
    var phi_5908_: bool;
    var phi_5921_: u32;
    var phi_5953_: bool;
    var phi_6180_: f32;
    var phi_6230_: u32;
    var phi_6233_: u32;
    var phi_6234_: u32;
    var phi_6235_: bool;
    var phi_6248_: u32;
    var phi_6280_: bool;
    var phi_6507_: f32;
    var phi_6557_: u32;
    var phi_6560_: u32;
    var phi_6561_: u32;
    var phi_6562_: bool;
    var phi_6575_: u32;
    var phi_6577_: u32;
    var phi_6578_: vec3<f32>;
    var phi_6765_: f32;
    var phi_6815_: u32;
    var phi_6818_: u32;
    var phi_6819_: u32;
    var phi_6820_: bool;
    var phi_6834_: u32;
    var phi_1200_: u32;
    var phi_1203_: u32;
    var phi_7189_: bool;
    var local_9: u32;
    var phi_6915_: u32;
    var phi_6918_: f32;
    var local_10: u32;
    var phi_6916_: u32;
    var phi_6919_: f32;
    var phi_7812_: bool;
    var local_11: f32;
    var phi_7823_: bool;
    var phi_6968_: f32;
    var phi_6969_: f32;
    var phi_6863_: u32;
    var phi_6866_: f32;
    var phi_6868_: f32;
    var local_12: u32;
    var phi_6864_: u32;
    var phi_6867_: f32;
    var phi_6869_: f32;
    var local_13: f32;
    var phi_7817_: bool;
    var phi_6970_: f32;
    var phi_6971_: f32;
    var phi_7816_: bool;
    var phi_1009_: u32;
    var phi_1012_: f32;
    var phi_1014_: f32;
    var phi_7815_: bool;
    var local_14: f32;
    var local_15: f32;
    var local_16: f32;
    var phi_6979_: f32;
    var phi_6991_: f32;
    var phi_6992_: f32;

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
                        phi_7728_ = false;
                        phi_1008_ = 0u;
                        phi_1011_ = 0f;
                        phi_1013_ = 0f;
                        loop {
                            let _e684 = phi_7728_;
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
                                                        phi_7189_ = true;
                                                        break;
                                                    }
                                                    let _e1168 = local_5[_e1152][0u];
                                                    local_6 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e1165 {
                                                    } else {
                                                        phi_7189_ = true;
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
                                                            phi_7189_ = true;
                                                            break;
                                                        }
                                                        let _e1158 = local_7[_e1152][0u];
                                                        local_8 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e1155 {
                                                        } else {
                                                            phi_7189_ = true;
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
                                                let _e1181 = (((f32(bitcast<i32>(_e1127)) - _e1110) + _e1174.x) / _e1106);
                                                let _e1186 = (((f32(bitcast<i32>(_e1141)) - _e1110) + _e1174.y) / _e1107);
                                                let _e1191 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e1196 = select(select(u32(_e1191), 0u, (_e1191 < 0f)), 4294967295u, (_e1191 > 4294967000f));
                                                let _e1201 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e1211 = (select(0f, select(1f, _e1181, (_e1181 < 1f)), (_e1181 > 0f)) * _e1191);
                                                let _e1214 = f32(bitcast<i32>((_e1196 - 1u)));
                                                let _e1227 = (select(0f, select(1f, _e1186, (_e1186 < 1f)), (_e1186 > 0f)) * _e1201);
                                                let _e1230 = f32(bitcast<i32>((select(select(u32(_e1201), 0u, (_e1201 < 0f)), 4294967295u, (_e1201 > 4294967000f)) - 1u)));
                                                let _e1242 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e1230, _e1227, (_e1227 < _e1230)), (_e1227 > 0f))) + 8388608f)) - 1258291200u) * _e1196) + (bitcast<u32>((floor(select(0f, select(_e1214, _e1211, (_e1211 < _e1214)), (_e1211 > 0f))) + 8388608f)) - 1258291200u))];
                                                let _e1252 = select(0x1.fffffep+127f, (select(_e1242, _e923, ((_e923 > _e1242) || (_e1242 != _e1242))) * 1.001f), select(false, (abs((_e1242 - _e923)) <= _e238), _e1082));
                                                let _e1254 = frame.member[0u].member_1.member_6;
                                                let _e1257 = (((_e1141 * _e1112) + _e1127) * _e1254);
                                                let _e1259 = sd_map.member[_e1257];
                                                let _e1263 = frame.member[0u].member_1.member.member.member_3;
                                                let _e1267 = frame.member[0u].member_1.member.member.member_2;
                                                let _e1268 = (_e1263 - _e1267);
                                                let _e1270 = ((_e1259 * _e1268) + _e1267);
                                                let _e1276 = select(_e1263, _e1270, select(false, select(false, (_e1270 > _e1252), (_e1259 < 1f)), (0u < _e1254)));
                                                let _e1277 = (_e1254 - 1u);
                                                let _e1282 = sd_map.member[(_e1257 + select(1u, _e1277, (_e1277 < 1u)))];
                                                let _e1284 = ((_e1282 * _e1268) + _e1267);
                                                let _e1290 = select(_e1263, _e1284, select(false, select(false, (_e1284 > _e1252), (_e1282 < 1f)), (1u < _e1254)));
                                                let _e1295 = sd_map.member[(_e1257 + select(2u, _e1277, (_e1277 < 2u)))];
                                                let _e1297 = ((_e1295 * _e1268) + _e1267);
                                                let _e1303 = select(_e1263, _e1297, select(false, select(false, (_e1297 > _e1252), (_e1295 < 1f)), (2u < _e1254)));
                                                let _e1308 = sd_map.member[(_e1257 + select(3u, _e1277, (_e1277 < 3u)))];
                                                let _e1310 = ((_e1308 * _e1268) + _e1267);
                                                let _e1316 = select(_e1263, _e1310, select(false, select(false, (_e1310 > _e1252), (_e1308 < 1f)), (3u < _e1254)));
                                                if (_e1254 > 4u) {
                                                    let _e1322 = sd_map.member[(_e1257 + select(4u, _e1277, (_e1277 < 4u)))];
                                                    let _e1324 = ((_e1322 * _e1268) + _e1267);
                                                    let _e1335 = sd_map.member[(_e1257 + select(5u, _e1277, (_e1277 < 5u)))];
                                                    let _e1337 = ((_e1335 * _e1268) + _e1267);
                                                    let _e1348 = sd_map.member[(_e1257 + select(6u, _e1277, (_e1277 < 6u)))];
                                                    let _e1350 = ((_e1348 * _e1268) + _e1267);
                                                    let _e1361 = sd_map.member[(_e1257 + select(7u, _e1277, (_e1277 < 7u)))];
                                                    let _e1363 = ((_e1361 * _e1268) + _e1267);
                                                    phi_2297_ = select(_e1263, _e1350, select(false, select(false, (_e1350 > _e1252), (_e1348 < 1f)), (6u < _e1254)));
                                                    phi_2298_ = select(_e1263, _e1337, select(false, select(false, (_e1337 > _e1252), (_e1335 < 1f)), (5u < _e1254)));
                                                    phi_2299_ = select(_e1263, _e1324, select(false, select(false, (_e1324 > _e1252), (_e1322 < 1f)), (4u < _e1254)));
                                                    phi_2300_ = select(_e1263, _e1363, select(false, select(false, (_e1363 > _e1252), (_e1361 < 1f)), (7u < _e1254)));
                                                } else {
                                                    phi_2297_ = _e1263;
                                                    phi_2298_ = _e1263;
                                                    phi_2299_ = _e1263;
                                                    phi_2300_ = _e1263;
                                                }
                                                let _e1371 = phi_2297_;
                                                let _e1373 = phi_2298_;
                                                let _e1375 = phi_2299_;
                                                let _e1377 = phi_2300_;
                                                let _e1379 = (_e1290 != _e1290);
                                                let _e1381 = select(_e1290, _e1276, ((_e1276 < _e1290) || _e1379));
                                                let _e1384 = select(_e1290, _e1276, ((_e1276 > _e1290) || _e1379));
                                                let _e1386 = (_e1316 != _e1316);
                                                let _e1388 = select(_e1316, _e1303, ((_e1303 < _e1316) || _e1386));
                                                let _e1391 = select(_e1316, _e1303, ((_e1303 > _e1316) || _e1386));
                                                let _e1393 = (_e1373 != _e1373);
                                                let _e1395 = select(_e1373, _e1375, ((_e1375 < _e1373) || _e1393));
                                                let _e1398 = select(_e1373, _e1375, ((_e1375 > _e1373) || _e1393));
                                                let _e1400 = (_e1377 != _e1377);
                                                let _e1402 = select(_e1377, _e1371, ((_e1371 < _e1377) || _e1400));
                                                let _e1405 = select(_e1377, _e1371, ((_e1371 > _e1377) || _e1400));
                                                let _e1407 = (_e1388 != _e1388);
                                                let _e1409 = select(_e1388, _e1381, ((_e1381 < _e1388) || _e1407));
                                                let _e1412 = select(_e1388, _e1381, ((_e1381 > _e1388) || _e1407));
                                                let _e1414 = (_e1391 != _e1391);
                                                let _e1416 = select(_e1391, _e1384, ((_e1384 < _e1391) || _e1414));
                                                let _e1419 = select(_e1391, _e1384, ((_e1384 > _e1391) || _e1414));
                                                let _e1421 = (_e1402 != _e1402);
                                                let _e1423 = select(_e1402, _e1395, ((_e1395 < _e1402) || _e1421));
                                                let _e1426 = select(_e1402, _e1395, ((_e1395 > _e1402) || _e1421));
                                                let _e1428 = (_e1405 != _e1405);
                                                let _e1430 = select(_e1405, _e1398, ((_e1398 < _e1405) || _e1428));
                                                let _e1433 = select(_e1405, _e1398, ((_e1398 > _e1405) || _e1428));
                                                let _e1435 = (_e1412 != _e1412);
                                                let _e1437 = select(_e1412, _e1416, ((_e1416 < _e1412) || _e1435));
                                                let _e1440 = select(_e1412, _e1416, ((_e1416 > _e1412) || _e1435));
                                                let _e1442 = (_e1426 != _e1426);
                                                let _e1444 = select(_e1426, _e1430, ((_e1430 < _e1426) || _e1442));
                                                let _e1447 = select(_e1426, _e1430, ((_e1430 > _e1426) || _e1442));
                                                let _e1449 = (_e1423 != _e1423);
                                                let _e1451 = select(_e1423, _e1409, ((_e1409 < _e1423) || _e1449));
                                                let _e1454 = select(_e1423, _e1409, ((_e1409 > _e1423) || _e1449));
                                                let _e1456 = (_e1444 != _e1444);
                                                let _e1458 = select(_e1444, _e1437, ((_e1437 < _e1444) || _e1456));
                                                let _e1461 = select(_e1444, _e1437, ((_e1437 > _e1444) || _e1456));
                                                let _e1463 = (_e1447 != _e1447);
                                                let _e1465 = select(_e1447, _e1440, ((_e1440 < _e1447) || _e1463));
                                                let _e1468 = select(_e1447, _e1440, ((_e1440 > _e1447) || _e1463));
                                                let _e1470 = (_e1433 != _e1433);
                                                let _e1472 = select(_e1433, _e1419, ((_e1419 < _e1433) || _e1470));
                                                let _e1475 = select(_e1433, _e1419, ((_e1419 > _e1433) || _e1470));
                                                let _e1477 = (_e1454 != _e1454);
                                                let _e1479 = select(_e1454, _e1465, ((_e1465 < _e1454) || _e1477));
                                                let _e1482 = select(_e1454, _e1465, ((_e1465 > _e1454) || _e1477));
                                                let _e1484 = (_e1461 != _e1461);
                                                let _e1486 = select(_e1461, _e1472, ((_e1472 < _e1461) || _e1484));
                                                let _e1489 = select(_e1461, _e1472, ((_e1472 > _e1461) || _e1484));
                                                let _e1491 = (_e1479 != _e1479);
                                                let _e1493 = select(_e1479, _e1458, ((_e1458 < _e1479) || _e1491));
                                                let _e1496 = select(_e1479, _e1458, ((_e1458 > _e1479) || _e1491));
                                                let _e1498 = (_e1482 != _e1482);
                                                let _e1500 = select(_e1482, _e1486, ((_e1486 < _e1482) || _e1498));
                                                let _e1503 = select(_e1482, _e1486, ((_e1486 > _e1482) || _e1498));
                                                let _e1505 = (_e1468 != _e1468);
                                                let _e1507 = select(_e1468, _e1489, ((_e1489 < _e1468) || _e1505));
                                                let _e1510 = select(_e1468, _e1489, ((_e1489 > _e1468) || _e1505));
                                                let _e1514 = select(false, (_e1451 > (_e923 + _e238)), (_e1451 < _e1263));
                                                let _e1516 = ((_e1181 * 2f) - 1f);
                                                let _e1520 = ((_e1186 * -2f) + 1f);
                                                let _e1530 = (_e1516 * _e225.member.member_1.x);
                                                let _e1532 = (_e1520 * _e225.member.member_1.y);
                                                let _e1534 = ((_e1530 * _e1493) - _e466);
                                                let _e1535 = ((_e1532 * _e1493) - _e473);
                                                let _e1536 = (_e1493 - _e459);
                                                if _e972 {
                                                    phi_2642_ = ((((_e1534 * _e1534) + (_e1535 * _e1535)) + (_e1536 * _e1536)) <= (_e241 * _e241));
                                                } else {
                                                    phi_2642_ = true;
                                                }
                                                let _e1545 = phi_2642_;
                                                let _e1547 = select(false, _e1545, (_e1493 < _e225.member.member_3));
                                                if _e1547 {
                                                    let _e1548 = (_e1496 < _e225.member.member_3);
                                                    let _e1557 = select((_e1534 - _e978), ((_e1530 * _e1496) - _e466), _e1548);
                                                    let _e1558 = select((_e1535 - _e979), ((_e1532 * _e1496) - _e473), _e1548);
                                                    let _e1559 = select((_e1536 - _e980), (_e1496 - _e459), _e1548);
                                                    let _e1571 = ((((_e1534 * _e484) + (_e1535 * _e485)) + (_e1536 * _e486)) * inverseSqrt((((_e1534 * _e1534) + (_e1535 * _e1535)) + (_e1536 * _e1536))));
                                                    let _e1575 = select(-1f, select(1f, _e1571, (_e1571 < 1f)), (_e1571 > -1f));
                                                    let _e1576 = abs(_e1575);
                                                    let _e1586 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1576, 0.00667009f), _e1576, -0.017088126f), _e1576, 0.03089188f), _e1576, -0.050174303f), _e1576, 0.08897899f), _e1576, -0.2145988f), _e1576, 1.5707963f) * sqrt((1f - _e1576)));
                                                    let _e1593 = ((((select((3.1415927f - _e1586), _e1586, (_e1575 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1597 = select(0f, select(1f, _e1593, (_e1593 < 1f)), (_e1593 > 0f));
                                                    let _e1609 = ((((_e1557 * _e484) + (_e1558 * _e485)) + (_e1559 * _e486)) * inverseSqrt((((_e1557 * _e1557) + (_e1558 * _e1558)) + (_e1559 * _e1559))));
                                                    let _e1613 = select(-1f, select(1f, _e1609, (_e1609 < 1f)), (_e1609 > -1f));
                                                    let _e1614 = abs(_e1613);
                                                    let _e1624 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1614, 0.00667009f), _e1614, -0.017088126f), _e1614, 0.03089188f), _e1614, -0.050174303f), _e1614, 0.08897899f), _e1614, -0.2145988f), _e1614, 1.5707963f) * sqrt((1f - _e1614)));
                                                    let _e1631 = ((((select((3.1415927f - _e1624), _e1624, (_e1613 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1635 = select(0f, select(1f, _e1631, (_e1631 < 1f)), (_e1631 > 0f));
                                                    let _e1637 = (_e1635 != _e1635);
                                                    let _e1639 = select(_e1635, _e1597, ((_e1597 < _e1635) || _e1637));
                                                    let _e1642 = select(_e1635, _e1597, ((_e1597 > _e1635) || _e1637));
                                                    let _e1644 = floor((_e1639 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1652 = -(floor((_e1642 * -32f)));
                                                        let _e1657 = (select(32f, _e1652, ((_e1652 < 32f) || false)) - _e1644);
                                                        phi_2869_ = select(select(0f, _e1657, ((_e1657 > 0f) || false)), 0f, (_e1642 <= _e1639));
                                                    } else {
                                                        phi_2869_ = -(floor(((_e1642 - _e1639) * -32f)));
                                                    }
                                                    let _e1663 = phi_2869_;
                                                    let _e1671 = (bitcast<u32>((floor(select(0f, select(32f, _e1644, (_e1644 < 32f)), (_e1644 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1679 = (bitcast<u32>((floor(select(0f, select(32f, _e1663, (_e1663 < 32f)), (_e1663 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1671 >= 32u) {
                                                        phi_2923_ = u32();
                                                        phi_2924_ = true;
                                                    } else {
                                                        let _e1681 = (_e1679 == 0u);
                                                        if _e1681 {
                                                            phi_2922_ = u32();
                                                        } else {
                                                            if (_e1679 >= 32u) {
                                                                phi_2919_ = 4294967295u;
                                                            } else {
                                                                phi_2919_ = ((1u << bitcast<u32>((_e1679 & 31u))) - 1u);
                                                            }
                                                            let _e1688 = phi_2919_;
                                                            phi_2922_ = (_e1688 << bitcast<u32>((_e1671 & 31u)));
                                                        }
                                                        let _e1693 = phi_2922_;
                                                        phi_2923_ = _e1693;
                                                        phi_2924_ = _e1681;
                                                    }
                                                    let _e1695 = phi_2923_;
                                                    let _e1697 = phi_2924_;
                                                    phi_2937_ = select(0u, select(select(_e1695, 0u, _e1697), 0u, _e1069), _e1547);
                                                } else {
                                                    phi_2937_ = 0u;
                                                }
                                                let _e1702 = phi_2937_;
                                                let _e1705 = ((_e1530 * _e1500) - _e466);
                                                let _e1706 = ((_e1532 * _e1500) - _e473);
                                                let _e1707 = (_e1500 - _e459);
                                                if _e972 {
                                                    phi_2968_ = ((((_e1705 * _e1705) + (_e1706 * _e1706)) + (_e1707 * _e1707)) <= (_e241 * _e241));
                                                } else {
                                                    phi_2968_ = true;
                                                }
                                                let _e1716 = phi_2968_;
                                                let _e1718 = select(false, _e1716, (_e1500 < _e225.member.member_3));
                                                if _e1718 {
                                                    let _e1719 = (_e1503 < _e225.member.member_3);
                                                    let _e1728 = select((_e1705 - _e978), ((_e1530 * _e1503) - _e466), _e1719);
                                                    let _e1729 = select((_e1706 - _e979), ((_e1532 * _e1503) - _e473), _e1719);
                                                    let _e1730 = select((_e1707 - _e980), (_e1503 - _e459), _e1719);
                                                    let _e1742 = ((((_e1705 * _e484) + (_e1706 * _e485)) + (_e1707 * _e486)) * inverseSqrt((((_e1705 * _e1705) + (_e1706 * _e1706)) + (_e1707 * _e1707))));
                                                    let _e1746 = select(-1f, select(1f, _e1742, (_e1742 < 1f)), (_e1742 > -1f));
                                                    let _e1747 = abs(_e1746);
                                                    let _e1757 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1747, 0.00667009f), _e1747, -0.017088126f), _e1747, 0.03089188f), _e1747, -0.050174303f), _e1747, 0.08897899f), _e1747, -0.2145988f), _e1747, 1.5707963f) * sqrt((1f - _e1747)));
                                                    let _e1764 = ((((select((3.1415927f - _e1757), _e1757, (_e1746 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1768 = select(0f, select(1f, _e1764, (_e1764 < 1f)), (_e1764 > 0f));
                                                    let _e1780 = ((((_e1728 * _e484) + (_e1729 * _e485)) + (_e1730 * _e486)) * inverseSqrt((((_e1728 * _e1728) + (_e1729 * _e1729)) + (_e1730 * _e1730))));
                                                    let _e1784 = select(-1f, select(1f, _e1780, (_e1780 < 1f)), (_e1780 > -1f));
                                                    let _e1785 = abs(_e1784);
                                                    let _e1795 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1785, 0.00667009f), _e1785, -0.017088126f), _e1785, 0.03089188f), _e1785, -0.050174303f), _e1785, 0.08897899f), _e1785, -0.2145988f), _e1785, 1.5707963f) * sqrt((1f - _e1785)));
                                                    let _e1802 = ((((select((3.1415927f - _e1795), _e1795, (_e1784 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1806 = select(0f, select(1f, _e1802, (_e1802 < 1f)), (_e1802 > 0f));
                                                    let _e1808 = (_e1806 != _e1806);
                                                    let _e1810 = select(_e1806, _e1768, ((_e1768 < _e1806) || _e1808));
                                                    let _e1813 = select(_e1806, _e1768, ((_e1768 > _e1806) || _e1808));
                                                    let _e1815 = floor((_e1810 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1823 = -(floor((_e1813 * -32f)));
                                                        let _e1828 = (select(32f, _e1823, ((_e1823 < 32f) || false)) - _e1815);
                                                        phi_3195_ = select(select(0f, _e1828, ((_e1828 > 0f) || false)), 0f, (_e1813 <= _e1810));
                                                    } else {
                                                        phi_3195_ = -(floor(((_e1813 - _e1810) * -32f)));
                                                    }
                                                    let _e1834 = phi_3195_;
                                                    let _e1842 = (bitcast<u32>((floor(select(0f, select(32f, _e1815, (_e1815 < 32f)), (_e1815 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1850 = (bitcast<u32>((floor(select(0f, select(32f, _e1834, (_e1834 < 32f)), (_e1834 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1842 >= 32u) {
                                                        phi_3249_ = u32();
                                                        phi_3250_ = true;
                                                    } else {
                                                        let _e1852 = (_e1850 == 0u);
                                                        if _e1852 {
                                                            phi_3248_ = u32();
                                                        } else {
                                                            if (_e1850 >= 32u) {
                                                                phi_3245_ = 4294967295u;
                                                            } else {
                                                                phi_3245_ = ((1u << bitcast<u32>((_e1850 & 31u))) - 1u);
                                                            }
                                                            let _e1859 = phi_3245_;
                                                            phi_3248_ = (_e1859 << bitcast<u32>((_e1842 & 31u)));
                                                        }
                                                        let _e1864 = phi_3248_;
                                                        phi_3249_ = _e1864;
                                                        phi_3250_ = _e1852;
                                                    }
                                                    let _e1866 = phi_3249_;
                                                    let _e1868 = phi_3250_;
                                                    phi_3263_ = select(0u, select(select(_e1866, 0u, _e1868), 0u, _e1069), _e1718);
                                                } else {
                                                    phi_3263_ = 0u;
                                                }
                                                let _e1873 = phi_3263_;
                                                let _e1877 = ((_e1530 * _e1507) - _e466);
                                                let _e1878 = ((_e1532 * _e1507) - _e473);
                                                let _e1879 = (_e1507 - _e459);
                                                if _e972 {
                                                    phi_3295_ = ((((_e1877 * _e1877) + (_e1878 * _e1878)) + (_e1879 * _e1879)) <= (_e241 * _e241));
                                                } else {
                                                    phi_3295_ = true;
                                                }
                                                let _e1888 = phi_3295_;
                                                let _e1890 = select(false, _e1888, (_e1507 < _e225.member.member_3));
                                                if _e1890 {
                                                    let _e1891 = (_e1510 < _e225.member.member_3);
                                                    let _e1900 = select((_e1877 - _e978), ((_e1530 * _e1510) - _e466), _e1891);
                                                    let _e1901 = select((_e1878 - _e979), ((_e1532 * _e1510) - _e473), _e1891);
                                                    let _e1902 = select((_e1879 - _e980), (_e1510 - _e459), _e1891);
                                                    let _e1914 = ((((_e1877 * _e484) + (_e1878 * _e485)) + (_e1879 * _e486)) * inverseSqrt((((_e1877 * _e1877) + (_e1878 * _e1878)) + (_e1879 * _e1879))));
                                                    let _e1918 = select(-1f, select(1f, _e1914, (_e1914 < 1f)), (_e1914 > -1f));
                                                    let _e1919 = abs(_e1918);
                                                    let _e1929 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1919, 0.00667009f), _e1919, -0.017088126f), _e1919, 0.03089188f), _e1919, -0.050174303f), _e1919, 0.08897899f), _e1919, -0.2145988f), _e1919, 1.5707963f) * sqrt((1f - _e1919)));
                                                    let _e1936 = ((((select((3.1415927f - _e1929), _e1929, (_e1918 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1940 = select(0f, select(1f, _e1936, (_e1936 < 1f)), (_e1936 > 0f));
                                                    let _e1952 = ((((_e1900 * _e484) + (_e1901 * _e485)) + (_e1902 * _e486)) * inverseSqrt((((_e1900 * _e1900) + (_e1901 * _e1901)) + (_e1902 * _e1902))));
                                                    let _e1956 = select(-1f, select(1f, _e1952, (_e1952 < 1f)), (_e1952 > -1f));
                                                    let _e1957 = abs(_e1956);
                                                    let _e1967 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1957, 0.00667009f), _e1957, -0.017088126f), _e1957, 0.03089188f), _e1957, -0.050174303f), _e1957, 0.08897899f), _e1957, -0.2145988f), _e1957, 1.5707963f) * sqrt((1f - _e1957)));
                                                    let _e1974 = ((((select((3.1415927f - _e1967), _e1967, (_e1956 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e1978 = select(0f, select(1f, _e1974, (_e1974 < 1f)), (_e1974 > 0f));
                                                    let _e1980 = (_e1978 != _e1978);
                                                    let _e1982 = select(_e1978, _e1940, ((_e1940 < _e1978) || _e1980));
                                                    let _e1985 = select(_e1978, _e1940, ((_e1940 > _e1978) || _e1980));
                                                    let _e1987 = floor((_e1982 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e1995 = -(floor((_e1985 * -32f)));
                                                        let _e2000 = (select(32f, _e1995, ((_e1995 < 32f) || false)) - _e1987);
                                                        phi_3522_ = select(select(0f, _e2000, ((_e2000 > 0f) || false)), 0f, (_e1985 <= _e1982));
                                                    } else {
                                                        phi_3522_ = -(floor(((_e1985 - _e1982) * -32f)));
                                                    }
                                                    let _e2006 = phi_3522_;
                                                    let _e2014 = (bitcast<u32>((floor(select(0f, select(32f, _e1987, (_e1987 < 32f)), (_e1987 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2022 = (bitcast<u32>((floor(select(0f, select(32f, _e2006, (_e2006 < 32f)), (_e2006 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2014 >= 32u) {
                                                        phi_3576_ = u32();
                                                        phi_3577_ = true;
                                                    } else {
                                                        let _e2024 = (_e2022 == 0u);
                                                        if _e2024 {
                                                            phi_3575_ = u32();
                                                        } else {
                                                            if (_e2022 >= 32u) {
                                                                phi_3572_ = 4294967295u;
                                                            } else {
                                                                phi_3572_ = ((1u << bitcast<u32>((_e2022 & 31u))) - 1u);
                                                            }
                                                            let _e2031 = phi_3572_;
                                                            phi_3575_ = (_e2031 << bitcast<u32>((_e2014 & 31u)));
                                                        }
                                                        let _e2036 = phi_3575_;
                                                        phi_3576_ = _e2036;
                                                        phi_3577_ = _e2024;
                                                    }
                                                    let _e2038 = phi_3576_;
                                                    let _e2040 = phi_3577_;
                                                    phi_3590_ = select(0u, select(select(_e2038, 0u, _e2040), 0u, _e1069), _e1890);
                                                } else {
                                                    phi_3590_ = 0u;
                                                }
                                                let _e2045 = phi_3590_;
                                                let _e2049 = ((_e1530 * _e1475) - _e466);
                                                let _e2050 = ((_e1532 * _e1475) - _e473);
                                                let _e2051 = (_e1475 - _e459);
                                                if _e972 {
                                                    phi_3622_ = ((((_e2049 * _e2049) + (_e2050 * _e2050)) + (_e2051 * _e2051)) <= (_e241 * _e241));
                                                } else {
                                                    phi_3622_ = true;
                                                }
                                                let _e2060 = phi_3622_;
                                                let _e2062 = select(false, _e2060, (_e1475 < _e225.member.member_3));
                                                if _e2062 {
                                                    let _e2063 = (_e1263 < _e225.member.member_3);
                                                    let _e2072 = select((_e2049 - _e978), ((_e1530 * _e1263) - _e466), _e2063);
                                                    let _e2073 = select((_e2050 - _e979), ((_e1532 * _e1263) - _e473), _e2063);
                                                    let _e2074 = select((_e2051 - _e980), (_e1263 - _e459), _e2063);
                                                    let _e2086 = ((((_e2049 * _e484) + (_e2050 * _e485)) + (_e2051 * _e486)) * inverseSqrt((((_e2049 * _e2049) + (_e2050 * _e2050)) + (_e2051 * _e2051))));
                                                    let _e2090 = select(-1f, select(1f, _e2086, (_e2086 < 1f)), (_e2086 > -1f));
                                                    let _e2091 = abs(_e2090);
                                                    let _e2101 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2091, 0.00667009f), _e2091, -0.017088126f), _e2091, 0.03089188f), _e2091, -0.050174303f), _e2091, 0.08897899f), _e2091, -0.2145988f), _e2091, 1.5707963f) * sqrt((1f - _e2091)));
                                                    let _e2108 = ((((select((3.1415927f - _e2101), _e2101, (_e2090 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e2112 = select(0f, select(1f, _e2108, (_e2108 < 1f)), (_e2108 > 0f));
                                                    let _e2124 = ((((_e2072 * _e484) + (_e2073 * _e485)) + (_e2074 * _e486)) * inverseSqrt((((_e2072 * _e2072) + (_e2073 * _e2073)) + (_e2074 * _e2074))));
                                                    let _e2128 = select(-1f, select(1f, _e2124, (_e2124 < 1f)), (_e2124 > -1f));
                                                    let _e2129 = abs(_e2128);
                                                    let _e2139 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2129, 0.00667009f), _e2129, -0.017088126f), _e2129, 0.03089188f), _e2129, -0.050174303f), _e2129, 0.08897899f), _e2129, -0.2145988f), _e2129, 1.5707963f) * sqrt((1f - _e2129)));
                                                    let _e2146 = ((((select((3.1415927f - _e2139), _e2139, (_e2128 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                                    let _e2150 = select(0f, select(1f, _e2146, (_e2146 < 1f)), (_e2146 > 0f));
                                                    let _e2152 = (_e2150 != _e2150);
                                                    let _e2154 = select(_e2150, _e2112, ((_e2112 < _e2150) || _e2152));
                                                    let _e2157 = select(_e2150, _e2112, ((_e2112 > _e2150) || _e2152));
                                                    let _e2159 = floor((_e2154 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e2167 = -(floor((_e2157 * -32f)));
                                                        let _e2172 = (select(32f, _e2167, ((_e2167 < 32f) || false)) - _e2159);
                                                        phi_3849_ = select(select(0f, _e2172, ((_e2172 > 0f) || false)), 0f, (_e2157 <= _e2154));
                                                    } else {
                                                        phi_3849_ = -(floor(((_e2157 - _e2154) * -32f)));
                                                    }
                                                    let _e2178 = phi_3849_;
                                                    let _e2186 = (bitcast<u32>((floor(select(0f, select(32f, _e2159, (_e2159 < 32f)), (_e2159 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2194 = (bitcast<u32>((floor(select(0f, select(32f, _e2178, (_e2178 < 32f)), (_e2178 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2186 >= 32u) {
                                                        phi_3903_ = u32();
                                                        phi_3904_ = true;
                                                    } else {
                                                        let _e2196 = (_e2194 == 0u);
                                                        if _e2196 {
                                                            phi_3902_ = u32();
                                                        } else {
                                                            if (_e2194 >= 32u) {
                                                                phi_3899_ = 4294967295u;
                                                            } else {
                                                                phi_3899_ = ((1u << bitcast<u32>((_e2194 & 31u))) - 1u);
                                                            }
                                                            let _e2203 = phi_3899_;
                                                            phi_3902_ = (_e2203 << bitcast<u32>((_e2186 & 31u)));
                                                        }
                                                        let _e2208 = phi_3902_;
                                                        phi_3903_ = _e2208;
                                                        phi_3904_ = _e2196;
                                                    }
                                                    let _e2210 = phi_3903_;
                                                    let _e2212 = phi_3904_;
                                                    phi_3917_ = select(0u, select(select(_e2210, 0u, _e2212), 0u, _e1069), _e2062);
                                                } else {
                                                    phi_3917_ = 0u;
                                                }
                                                let _e2217 = phi_3917_;
                                                phi_3919_ = (((_e1702 | _e1873) | _e2045) | _e2217);
                                                phi_3920_ = vec3<f32>(select(_e981, (((_e1516 * _e1089) * _e1451) - _e466), _e1514), select(_e982, (((_e1520 * _e1097) * _e1451) - _e473), _e1514), select(_e983, (_e1451 - _e459), _e1514));
                                            } else {
                                                phi_3919_ = 0u;
                                                phi_3920_ = vec3<f32>(_e981, _e982, _e983);
                                            }
                                            let _e2220 = phi_3919_;
                                            let _e2222 = phi_3920_;
                                            let _e2224 = (_e989 * inverseSqrt(_e971));
                                            let _e2228 = select(-1f, select(1f, _e2224, (_e2224 < 1f)), (_e2224 > -1f));
                                            let _e2229 = abs(_e2228);
                                            let _e2239 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2229, 0.00667009f), _e2229, -0.017088126f), _e2229, 0.03089188f), _e2229, -0.050174303f), _e2229, 0.08897899f), _e2229, -0.2145988f), _e2229, 1.5707963f) * sqrt((1f - _e2229)));
                                            let _e2246 = ((((select((3.1415927f - _e2239), _e2239, (_e2228 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                            let _e2250 = select(0f, select(1f, _e2246, (_e2246 < 1f)), (_e2246 > 0f));
                                            let _e2265 = ((((_e2222.x * _e484) + (_e2222.y * _e485)) + (_e2222.z * _e486)) * inverseSqrt((((_e2222.x * _e2222.x) + (_e2222.y * _e2222.y)) + (_e2222.z * _e2222.z))));
                                            let _e2269 = select(-1f, select(1f, _e2265, (_e2265 < 1f)), (_e2265 > -1f));
                                            let _e2270 = abs(_e2269);
                                            let _e2280 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2270, 0.00667009f), _e2270, -0.017088126f), _e2270, 0.03089188f), _e2270, -0.050174303f), _e2270, 0.08897899f), _e2270, -0.2145988f), _e2270, 1.5707963f) * sqrt((1f - _e2270)));
                                            let _e2287 = ((((select((3.1415927f - _e2280), _e2280, (_e2269 >= 0f)) + _e1063) - _e1059) + 1.5707964f) * 0.31830987f);
                                            let _e2291 = select(0f, select(1f, _e2287, (_e2287 < 1f)), (_e2287 > 0f));
                                            let _e2293 = (_e2291 != _e2291);
                                            let _e2295 = select(_e2291, _e2250, ((_e2250 < _e2291) || _e2293));
                                            let _e2298 = select(_e2291, _e2250, ((_e2250 > _e2291) || _e2293));
                                            let _e2300 = floor((_e2295 * 32f));
                                            if (_e235 == 1u) {
                                                let _e2308 = -(floor((_e2298 * -32f)));
                                                let _e2313 = (select(32f, _e2308, ((_e2308 < 32f) || false)) - _e2300);
                                                phi_4107_ = select(select(0f, _e2313, ((_e2313 > 0f) || false)), 0f, (_e2298 <= _e2295));
                                            } else {
                                                phi_4107_ = -(floor(((_e2298 - _e2295) * -32f)));
                                            }
                                            let _e2319 = phi_4107_;
                                            let _e2327 = (bitcast<u32>((floor(select(0f, select(32f, _e2300, (_e2300 < 32f)), (_e2300 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e2335 = (bitcast<u32>((floor(select(0f, select(32f, _e2319, (_e2319 < 32f)), (_e2319 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e2327 >= 32u) {
                                                phi_4161_ = u32();
                                                phi_4162_ = true;
                                            } else {
                                                let _e2337 = (_e2335 == 0u);
                                                if _e2337 {
                                                    phi_4160_ = u32();
                                                } else {
                                                    if (_e2335 >= 32u) {
                                                        phi_4157_ = 4294967295u;
                                                    } else {
                                                        phi_4157_ = ((1u << bitcast<u32>((_e2335 & 31u))) - 1u);
                                                    }
                                                    let _e2344 = phi_4157_;
                                                    phi_4160_ = (_e2344 << bitcast<u32>((_e2327 & 31u)));
                                                }
                                                let _e2349 = phi_4160_;
                                                phi_4161_ = _e2349;
                                                phi_4162_ = _e2337;
                                            }
                                            let _e2351 = phi_4161_;
                                            let _e2353 = phi_4162_;
                                            phi_4176_ = select((select(select(_e2351, 0u, _e2353), 0u, _e1069) | _e2220), 0u, _e976);
                                        } else {
                                            phi_4176_ = 0u;
                                        }
                                        let _e2359 = phi_4176_;
                                        let _e2361 = (_e959 - _e466);
                                        let _e2362 = (_e963 - _e473);
                                        let _e2363 = (_e955 - _e459);
                                        let _e2368 = (((_e2361 * _e2361) + (_e2362 * _e2362)) + (_e2363 * _e2363));
                                        if _e972 {
                                            phi_4196_ = (_e2368 > (_e241 * _e241));
                                        } else {
                                            phi_4196_ = false;
                                        }
                                        let _e2372 = phi_4196_;
                                        if !(_e2372) {
                                            let _e2374 = (_e484 * _e238);
                                            let _e2375 = (_e485 * _e238);
                                            let _e2376 = (_e486 * _e238);
                                            let _e2377 = (_e2361 - _e2374);
                                            let _e2378 = (_e2362 - _e2375);
                                            let _e2379 = (_e2363 - _e2376);
                                            let _e2385 = (((_e2361 * _e484) + (_e2362 * _e485)) + (_e2363 * _e486));
                                            let _e2389 = (_e2361 - (_e484 * _e2385));
                                            let _e2390 = (_e2362 - (_e485 * _e2385));
                                            let _e2391 = (_e2363 - (_e486 * _e2385));
                                            let _e2394 = ((_e2390 * _e486) - (_e485 * _e2391));
                                            let _e2397 = ((_e2391 * _e484) - (_e486 * _e2389));
                                            let _e2400 = ((_e2389 * _e485) - (_e484 * _e2390));
                                            let _e2411 = ((((_e545 * _e2394) + (_e546 * _e2397)) + (_e547 * _e2400)) / (((_e2394 * _e2394) + (_e2397 * _e2397)) + (_e2400 * _e2400)));
                                            let _e2415 = (_e545 - (_e2394 * _e2411));
                                            let _e2416 = (_e546 - (_e2397 * _e2411));
                                            let _e2417 = (_e547 - (_e2400 * _e2411));
                                            let _e2423 = inverseSqrt((((_e2415 * _e2415) + (_e2416 * _e2416)) + (_e2417 * _e2417)));
                                            let _e2429 = ((((_e2415 * _e484) + (_e2416 * _e485)) + (_e2417 * _e486)) * _e2423);
                                            let _e2433 = select(0f, select(1f, _e2429, (_e2429 < 1f)), (_e2429 > 0f));
                                            let _e2434 = abs(_e2433);
                                            let _e2444 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2434, 0.00667009f), _e2434, -0.017088126f), _e2434, 0.03089188f), _e2434, -0.050174303f), _e2434, 0.08897899f), _e2434, -0.2145988f), _e2434, 1.5707963f) * sqrt((1f - _e2434)));
                                            let _e2447 = select((3.1415927f - _e2444), _e2444, (_e2433 >= 0f));
                                            let _e2455 = select(_e2447, -(_e2447), ((((_e2389 * _e2415) + (_e2390 * _e2416)) + (_e2391 * _e2417)) < 0f));
                                            let _e2456 = (_e2423 * 0.02f);
                                            let _e2459 = select(0.19634955f, _e2456, ((_e2456 < 0.19634955f) || false));
                                            let _e2465 = ((((_e2389 * _e2389) + (_e2390 * _e2390)) + (_e2391 * _e2391)) <= 0f);
                                            if _e972 {
                                                phi_4349_ = (_e2368 <= (_e241 * _e241));
                                            } else {
                                                phi_4349_ = true;
                                            }
                                            let _e2469 = phi_4349_;
                                            let _e2478 = select(false, ((((_e2361 * _e545) + (_e2362 * _e546)) + (_e2363 * _e547)) > (sqrt(_e2368) * 0.018f)), _e2469);
                                            if _e2478 {
                                                let _e2479 = (0.5f / _e955);
                                                let _e2485 = frame.member[0u].member_1.member.member.member_1[0u];
                                                let _e2493 = frame.member[0u].member_1.member.member.member_1[1u];
                                                let _e2498 = frame.member[0u].member_1.member_5[0u];
                                                let _e2501 = frame.member[0u].member_1.member_5[1u];
                                                let _e2502 = f32(_e2498);
                                                let _e2503 = f32(_e2501);
                                                let _e2505 = frame.member[0u].member_1.member_4;
                                                let _e2506 = f32(_e2505);
                                                let _e2507 = (2u * _e2505);
                                                let _e2508 = (_e2498 + _e2507);
                                                let _e2512 = (floor(((((_e959 * _e2479) / _e2485) + 0.5f) * _e2502)) + _e2506);
                                                let _e2515 = f32(bitcast<i32>((_e2508 - 1u)));
                                                let _e2523 = (bitcast<u32>((floor(select(0f, select(_e2515, _e2512, (_e2512 < _e2515)), (_e2512 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2526 = (floor(((0.5f - ((_e963 * _e2479) / _e2493)) * _e2503)) + _e2506);
                                                let _e2529 = f32(bitcast<i32>(((_e2501 + _e2507) - 1u)));
                                                let _e2537 = (bitcast<u32>((floor(select(0f, select(_e2529, _e2526, (_e2526 < _e2529)), (_e2526 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2539 = frame.member[0u].member_1.member_8;
                                                let _e2541 = frame.member[0u].member_1.member_12;
                                                let _e2548 = (((((_e2537 % 4u) * 4u) + (_e2523 % 4u)) + (_e2541 % 16u)) % 16u);
                                                if (_e2539 == 1u) {
                                                    local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    let _e2561 = (_e2548 < 16u);
                                                    if _e2561 {
                                                    } else {
                                                        phi_7189_ = true;
                                                        break;
                                                    }
                                                    let _e2564 = local_1[_e2548][0u];
                                                    local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e2561 {
                                                    } else {
                                                        phi_7189_ = true;
                                                        break;
                                                    }
                                                    let _e2567 = local_2[_e2548][1u];
                                                    phi_4512_ = vec2<f32>(_e2564, _e2567);
                                                } else {
                                                    if (_e2539 == 2u) {
                                                        local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        let _e2551 = (_e2548 < 16u);
                                                        if _e2551 {
                                                        } else {
                                                            phi_7189_ = true;
                                                            break;
                                                        }
                                                        let _e2554 = local_3[_e2548][0u];
                                                        local_4 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e2551 {
                                                        } else {
                                                            phi_7189_ = true;
                                                            break;
                                                        }
                                                        let _e2557 = local_4[_e2548][1u];
                                                        phi_4511_ = vec2<f32>(_e2554, _e2557);
                                                    } else {
                                                        phi_4511_ = vec2<f32>(0.5f, 0.5f);
                                                    }
                                                    let _e2560 = phi_4511_;
                                                    phi_4512_ = _e2560;
                                                }
                                                let _e2570 = phi_4512_;
                                                let _e2577 = (((f32(bitcast<i32>(_e2523)) - _e2506) + _e2570.x) / _e2502);
                                                let _e2582 = (((f32(bitcast<i32>(_e2537)) - _e2506) + _e2570.y) / _e2503);
                                                let _e2587 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e2592 = select(select(u32(_e2587), 0u, (_e2587 < 0f)), 4294967295u, (_e2587 > 4294967000f));
                                                let _e2597 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e2607 = (select(0f, select(1f, _e2577, (_e2577 < 1f)), (_e2577 > 0f)) * _e2587);
                                                let _e2610 = f32(bitcast<i32>((_e2592 - 1u)));
                                                let _e2623 = (select(0f, select(1f, _e2582, (_e2582 < 1f)), (_e2582 > 0f)) * _e2597);
                                                let _e2626 = f32(bitcast<i32>((select(select(u32(_e2597), 0u, (_e2597 < 0f)), 4294967295u, (_e2597 > 4294967000f)) - 1u)));
                                                let _e2638 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e2626, _e2623, (_e2623 < _e2626)), (_e2623 > 0f))) + 8388608f)) - 1258291200u) * _e2592) + (bitcast<u32>((floor(select(0f, select(_e2610, _e2607, (_e2607 < _e2610)), (_e2607 > 0f))) + 8388608f)) - 1258291200u))];
                                                let _e2648 = select(0x1.fffffep+127f, (select(_e2638, _e955, ((_e955 > _e2638) || (_e2638 != _e2638))) * 1.001f), select(false, (abs((_e2638 - _e955)) <= _e238), _e2478));
                                                let _e2650 = frame.member[0u].member_1.member_6;
                                                let _e2653 = (((_e2537 * _e2508) + _e2523) * _e2650);
                                                let _e2655 = sd_map.member[_e2653];
                                                let _e2659 = frame.member[0u].member_1.member.member.member_3;
                                                let _e2663 = frame.member[0u].member_1.member.member.member_2;
                                                let _e2664 = (_e2659 - _e2663);
                                                let _e2666 = ((_e2655 * _e2664) + _e2663);
                                                let _e2672 = select(_e2659, _e2666, select(false, select(false, (_e2666 > _e2648), (_e2655 < 1f)), (0u < _e2650)));
                                                let _e2673 = (_e2650 - 1u);
                                                let _e2678 = sd_map.member[(_e2653 + select(1u, _e2673, (_e2673 < 1u)))];
                                                let _e2680 = ((_e2678 * _e2664) + _e2663);
                                                let _e2686 = select(_e2659, _e2680, select(false, select(false, (_e2680 > _e2648), (_e2678 < 1f)), (1u < _e2650)));
                                                let _e2691 = sd_map.member[(_e2653 + select(2u, _e2673, (_e2673 < 2u)))];
                                                let _e2693 = ((_e2691 * _e2664) + _e2663);
                                                let _e2699 = select(_e2659, _e2693, select(false, select(false, (_e2693 > _e2648), (_e2691 < 1f)), (2u < _e2650)));
                                                let _e2704 = sd_map.member[(_e2653 + select(3u, _e2673, (_e2673 < 3u)))];
                                                let _e2706 = ((_e2704 * _e2664) + _e2663);
                                                let _e2712 = select(_e2659, _e2706, select(false, select(false, (_e2706 > _e2648), (_e2704 < 1f)), (3u < _e2650)));
                                                if (_e2650 > 4u) {
                                                    let _e2718 = sd_map.member[(_e2653 + select(4u, _e2673, (_e2673 < 4u)))];
                                                    let _e2720 = ((_e2718 * _e2664) + _e2663);
                                                    let _e2731 = sd_map.member[(_e2653 + select(5u, _e2673, (_e2673 < 5u)))];
                                                    let _e2733 = ((_e2731 * _e2664) + _e2663);
                                                    let _e2744 = sd_map.member[(_e2653 + select(6u, _e2673, (_e2673 < 6u)))];
                                                    let _e2746 = ((_e2744 * _e2664) + _e2663);
                                                    let _e2757 = sd_map.member[(_e2653 + select(7u, _e2673, (_e2673 < 7u)))];
                                                    let _e2759 = ((_e2757 * _e2664) + _e2663);
                                                    phi_4955_ = select(_e2659, _e2746, select(false, select(false, (_e2746 > _e2648), (_e2744 < 1f)), (6u < _e2650)));
                                                    phi_4956_ = select(_e2659, _e2733, select(false, select(false, (_e2733 > _e2648), (_e2731 < 1f)), (5u < _e2650)));
                                                    phi_4957_ = select(_e2659, _e2720, select(false, select(false, (_e2720 > _e2648), (_e2718 < 1f)), (4u < _e2650)));
                                                    phi_4958_ = select(_e2659, _e2759, select(false, select(false, (_e2759 > _e2648), (_e2757 < 1f)), (7u < _e2650)));
                                                } else {
                                                    phi_4955_ = _e2659;
                                                    phi_4956_ = _e2659;
                                                    phi_4957_ = _e2659;
                                                    phi_4958_ = _e2659;
                                                }
                                                let _e2767 = phi_4955_;
                                                let _e2769 = phi_4956_;
                                                let _e2771 = phi_4957_;
                                                let _e2773 = phi_4958_;
                                                let _e2775 = (_e2686 != _e2686);
                                                let _e2777 = select(_e2686, _e2672, ((_e2672 < _e2686) || _e2775));
                                                let _e2780 = select(_e2686, _e2672, ((_e2672 > _e2686) || _e2775));
                                                let _e2782 = (_e2712 != _e2712);
                                                let _e2784 = select(_e2712, _e2699, ((_e2699 < _e2712) || _e2782));
                                                let _e2787 = select(_e2712, _e2699, ((_e2699 > _e2712) || _e2782));
                                                let _e2789 = (_e2769 != _e2769);
                                                let _e2791 = select(_e2769, _e2771, ((_e2771 < _e2769) || _e2789));
                                                let _e2794 = select(_e2769, _e2771, ((_e2771 > _e2769) || _e2789));
                                                let _e2796 = (_e2773 != _e2773);
                                                let _e2798 = select(_e2773, _e2767, ((_e2767 < _e2773) || _e2796));
                                                let _e2801 = select(_e2773, _e2767, ((_e2767 > _e2773) || _e2796));
                                                let _e2803 = (_e2784 != _e2784);
                                                let _e2805 = select(_e2784, _e2777, ((_e2777 < _e2784) || _e2803));
                                                let _e2808 = select(_e2784, _e2777, ((_e2777 > _e2784) || _e2803));
                                                let _e2810 = (_e2787 != _e2787);
                                                let _e2812 = select(_e2787, _e2780, ((_e2780 < _e2787) || _e2810));
                                                let _e2815 = select(_e2787, _e2780, ((_e2780 > _e2787) || _e2810));
                                                let _e2817 = (_e2798 != _e2798);
                                                let _e2819 = select(_e2798, _e2791, ((_e2791 < _e2798) || _e2817));
                                                let _e2822 = select(_e2798, _e2791, ((_e2791 > _e2798) || _e2817));
                                                let _e2824 = (_e2801 != _e2801);
                                                let _e2826 = select(_e2801, _e2794, ((_e2794 < _e2801) || _e2824));
                                                let _e2829 = select(_e2801, _e2794, ((_e2794 > _e2801) || _e2824));
                                                let _e2831 = (_e2808 != _e2808);
                                                let _e2833 = select(_e2808, _e2812, ((_e2812 < _e2808) || _e2831));
                                                let _e2836 = select(_e2808, _e2812, ((_e2812 > _e2808) || _e2831));
                                                let _e2838 = (_e2822 != _e2822);
                                                let _e2840 = select(_e2822, _e2826, ((_e2826 < _e2822) || _e2838));
                                                let _e2843 = select(_e2822, _e2826, ((_e2826 > _e2822) || _e2838));
                                                let _e2845 = (_e2819 != _e2819);
                                                let _e2847 = select(_e2819, _e2805, ((_e2805 < _e2819) || _e2845));
                                                let _e2850 = select(_e2819, _e2805, ((_e2805 > _e2819) || _e2845));
                                                let _e2852 = (_e2840 != _e2840);
                                                let _e2854 = select(_e2840, _e2833, ((_e2833 < _e2840) || _e2852));
                                                let _e2857 = select(_e2840, _e2833, ((_e2833 > _e2840) || _e2852));
                                                let _e2859 = (_e2843 != _e2843);
                                                let _e2861 = select(_e2843, _e2836, ((_e2836 < _e2843) || _e2859));
                                                let _e2864 = select(_e2843, _e2836, ((_e2836 > _e2843) || _e2859));
                                                let _e2866 = (_e2829 != _e2829);
                                                let _e2868 = select(_e2829, _e2815, ((_e2815 < _e2829) || _e2866));
                                                let _e2871 = select(_e2829, _e2815, ((_e2815 > _e2829) || _e2866));
                                                let _e2873 = (_e2850 != _e2850);
                                                let _e2875 = select(_e2850, _e2861, ((_e2861 < _e2850) || _e2873));
                                                let _e2878 = select(_e2850, _e2861, ((_e2861 > _e2850) || _e2873));
                                                let _e2880 = (_e2857 != _e2857);
                                                let _e2882 = select(_e2857, _e2868, ((_e2868 < _e2857) || _e2880));
                                                let _e2885 = select(_e2857, _e2868, ((_e2868 > _e2857) || _e2880));
                                                let _e2887 = (_e2875 != _e2875);
                                                let _e2889 = select(_e2875, _e2854, ((_e2854 < _e2875) || _e2887));
                                                let _e2892 = select(_e2875, _e2854, ((_e2854 > _e2875) || _e2887));
                                                let _e2894 = (_e2878 != _e2878);
                                                let _e2896 = select(_e2878, _e2882, ((_e2882 < _e2878) || _e2894));
                                                let _e2899 = select(_e2878, _e2882, ((_e2882 > _e2878) || _e2894));
                                                let _e2901 = (_e2864 != _e2864);
                                                let _e2903 = select(_e2864, _e2885, ((_e2885 < _e2864) || _e2901));
                                                let _e2906 = select(_e2864, _e2885, ((_e2885 > _e2864) || _e2901));
                                                let _e2910 = select(false, (_e2847 > (_e955 + _e238)), (_e2847 < _e2659));
                                                let _e2912 = ((_e2577 * 2f) - 1f);
                                                let _e2916 = ((_e2582 * -2f) + 1f);
                                                let _e2926 = (_e2912 * _e225.member.member_1.x);
                                                let _e2928 = (_e2916 * _e225.member.member_1.y);
                                                let _e2930 = ((_e2926 * _e2889) - _e466);
                                                let _e2931 = ((_e2928 * _e2889) - _e473);
                                                let _e2932 = (_e2889 - _e459);
                                                if _e972 {
                                                    phi_5300_ = ((((_e2930 * _e2930) + (_e2931 * _e2931)) + (_e2932 * _e2932)) <= (_e241 * _e241));
                                                } else {
                                                    phi_5300_ = true;
                                                }
                                                let _e2941 = phi_5300_;
                                                let _e2943 = select(false, _e2941, (_e2889 < _e225.member.member_3));
                                                if _e2943 {
                                                    let _e2944 = (_e2892 < _e225.member.member_3);
                                                    let _e2953 = select((_e2930 - _e2374), ((_e2926 * _e2892) - _e466), _e2944);
                                                    let _e2954 = select((_e2931 - _e2375), ((_e2928 * _e2892) - _e473), _e2944);
                                                    let _e2955 = select((_e2932 - _e2376), (_e2892 - _e459), _e2944);
                                                    let _e2967 = ((((_e2930 * _e484) + (_e2931 * _e485)) + (_e2932 * _e486)) * inverseSqrt((((_e2930 * _e2930) + (_e2931 * _e2931)) + (_e2932 * _e2932))));
                                                    let _e2971 = select(-1f, select(1f, _e2967, (_e2967 < 1f)), (_e2967 > -1f));
                                                    let _e2972 = abs(_e2971);
                                                    let _e2982 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2972, 0.00667009f), _e2972, -0.017088126f), _e2972, 0.03089188f), _e2972, -0.050174303f), _e2972, 0.08897899f), _e2972, -0.2145988f), _e2972, 1.5707963f) * sqrt((1f - _e2972)));
                                                    let _e2989 = ((((select((3.1415927f - _e2982), _e2982, (_e2971 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3005 = ((((_e2953 * _e484) + (_e2954 * _e485)) + (_e2955 * _e486)) * inverseSqrt((((_e2953 * _e2953) + (_e2954 * _e2954)) + (_e2955 * _e2955))));
                                                    let _e3009 = select(-1f, select(1f, _e3005, (_e3005 < 1f)), (_e3005 > -1f));
                                                    let _e3010 = abs(_e3009);
                                                    let _e3020 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3010, 0.00667009f), _e3010, -0.017088126f), _e3010, 0.03089188f), _e3010, -0.050174303f), _e3010, 0.08897899f), _e3010, -0.2145988f), _e3010, 1.5707963f) * sqrt((1f - _e3010)));
                                                    let _e3027 = ((((select((3.1415927f - _e3020), _e3020, (_e3009 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3032 = (1f - select(0f, select(1f, _e2989, (_e2989 < 1f)), (_e2989 > 0f)));
                                                    let _e3033 = (1f - select(0f, select(1f, _e3027, (_e3027 < 1f)), (_e3027 > 0f)));
                                                    let _e3035 = (_e3033 != _e3033);
                                                    let _e3037 = select(_e3033, _e3032, ((_e3032 < _e3033) || _e3035));
                                                    let _e3040 = select(_e3033, _e3032, ((_e3032 > _e3033) || _e3035));
                                                    let _e3042 = floor((_e3037 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3050 = -(floor((_e3040 * -32f)));
                                                        let _e3055 = (select(32f, _e3050, ((_e3050 < 32f) || false)) - _e3042);
                                                        phi_5527_ = select(select(0f, _e3055, ((_e3055 > 0f) || false)), 0f, (_e3040 <= _e3037));
                                                    } else {
                                                        phi_5527_ = -(floor(((_e3040 - _e3037) * -32f)));
                                                    }
                                                    let _e3061 = phi_5527_;
                                                    let _e3069 = (bitcast<u32>((floor(select(0f, select(32f, _e3042, (_e3042 < 32f)), (_e3042 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3077 = (bitcast<u32>((floor(select(0f, select(32f, _e3061, (_e3061 < 32f)), (_e3061 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3069 >= 32u) {
                                                        phi_5581_ = u32();
                                                        phi_5582_ = true;
                                                    } else {
                                                        let _e3079 = (_e3077 == 0u);
                                                        if _e3079 {
                                                            phi_5580_ = u32();
                                                        } else {
                                                            if (_e3077 >= 32u) {
                                                                phi_5577_ = 4294967295u;
                                                            } else {
                                                                phi_5577_ = ((1u << bitcast<u32>((_e3077 & 31u))) - 1u);
                                                            }
                                                            let _e3086 = phi_5577_;
                                                            phi_5580_ = (_e3086 << bitcast<u32>((_e3069 & 31u)));
                                                        }
                                                        let _e3091 = phi_5580_;
                                                        phi_5581_ = _e3091;
                                                        phi_5582_ = _e3079;
                                                    }
                                                    let _e3093 = phi_5581_;
                                                    let _e3095 = phi_5582_;
                                                    phi_5595_ = select(0u, select(select(_e3093, 0u, _e3095), 0u, _e2465), _e2943);
                                                } else {
                                                    phi_5595_ = 0u;
                                                }
                                                let _e3100 = phi_5595_;
                                                let _e3103 = ((_e2926 * _e2896) - _e466);
                                                let _e3104 = ((_e2928 * _e2896) - _e473);
                                                let _e3105 = (_e2896 - _e459);
                                                if _e972 {
                                                    phi_5626_ = ((((_e3103 * _e3103) + (_e3104 * _e3104)) + (_e3105 * _e3105)) <= (_e241 * _e241));
                                                } else {
                                                    phi_5626_ = true;
                                                }
                                                let _e3114 = phi_5626_;
                                                let _e3116 = select(false, _e3114, (_e2896 < _e225.member.member_3));
                                                if _e3116 {
                                                    let _e3117 = (_e2899 < _e225.member.member_3);
                                                    let _e3126 = select((_e3103 - _e2374), ((_e2926 * _e2899) - _e466), _e3117);
                                                    let _e3127 = select((_e3104 - _e2375), ((_e2928 * _e2899) - _e473), _e3117);
                                                    let _e3128 = select((_e3105 - _e2376), (_e2899 - _e459), _e3117);
                                                    let _e3140 = ((((_e3103 * _e484) + (_e3104 * _e485)) + (_e3105 * _e486)) * inverseSqrt((((_e3103 * _e3103) + (_e3104 * _e3104)) + (_e3105 * _e3105))));
                                                    let _e3144 = select(-1f, select(1f, _e3140, (_e3140 < 1f)), (_e3140 > -1f));
                                                    let _e3145 = abs(_e3144);
                                                    let _e3155 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3145, 0.00667009f), _e3145, -0.017088126f), _e3145, 0.03089188f), _e3145, -0.050174303f), _e3145, 0.08897899f), _e3145, -0.2145988f), _e3145, 1.5707963f) * sqrt((1f - _e3145)));
                                                    let _e3162 = ((((select((3.1415927f - _e3155), _e3155, (_e3144 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3178 = ((((_e3126 * _e484) + (_e3127 * _e485)) + (_e3128 * _e486)) * inverseSqrt((((_e3126 * _e3126) + (_e3127 * _e3127)) + (_e3128 * _e3128))));
                                                    let _e3182 = select(-1f, select(1f, _e3178, (_e3178 < 1f)), (_e3178 > -1f));
                                                    let _e3183 = abs(_e3182);
                                                    let _e3193 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3183, 0.00667009f), _e3183, -0.017088126f), _e3183, 0.03089188f), _e3183, -0.050174303f), _e3183, 0.08897899f), _e3183, -0.2145988f), _e3183, 1.5707963f) * sqrt((1f - _e3183)));
                                                    let _e3200 = ((((select((3.1415927f - _e3193), _e3193, (_e3182 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3205 = (1f - select(0f, select(1f, _e3162, (_e3162 < 1f)), (_e3162 > 0f)));
                                                    let _e3206 = (1f - select(0f, select(1f, _e3200, (_e3200 < 1f)), (_e3200 > 0f)));
                                                    let _e3208 = (_e3206 != _e3206);
                                                    let _e3210 = select(_e3206, _e3205, ((_e3205 < _e3206) || _e3208));
                                                    let _e3213 = select(_e3206, _e3205, ((_e3205 > _e3206) || _e3208));
                                                    let _e3215 = floor((_e3210 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3223 = -(floor((_e3213 * -32f)));
                                                        let _e3228 = (select(32f, _e3223, ((_e3223 < 32f) || false)) - _e3215);
                                                        phi_5853_ = select(select(0f, _e3228, ((_e3228 > 0f) || false)), 0f, (_e3213 <= _e3210));
                                                    } else {
                                                        phi_5853_ = -(floor(((_e3213 - _e3210) * -32f)));
                                                    }
                                                    let _e3234 = phi_5853_;
                                                    let _e3242 = (bitcast<u32>((floor(select(0f, select(32f, _e3215, (_e3215 < 32f)), (_e3215 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3250 = (bitcast<u32>((floor(select(0f, select(32f, _e3234, (_e3234 < 32f)), (_e3234 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3242 >= 32u) {
                                                        phi_5907_ = u32();
                                                        phi_5908_ = true;
                                                    } else {
                                                        let _e3252 = (_e3250 == 0u);
                                                        if _e3252 {
                                                            phi_5906_ = u32();
                                                        } else {
                                                            if (_e3250 >= 32u) {
                                                                phi_5903_ = 4294967295u;
                                                            } else {
                                                                phi_5903_ = ((1u << bitcast<u32>((_e3250 & 31u))) - 1u);
                                                            }
                                                            let _e3259 = phi_5903_;
                                                            phi_5906_ = (_e3259 << bitcast<u32>((_e3242 & 31u)));
                                                        }
                                                        let _e3264 = phi_5906_;
                                                        phi_5907_ = _e3264;
                                                        phi_5908_ = _e3252;
                                                    }
                                                    let _e3266 = phi_5907_;
                                                    let _e3268 = phi_5908_;
                                                    phi_5921_ = select(0u, select(select(_e3266, 0u, _e3268), 0u, _e2465), _e3116);
                                                } else {
                                                    phi_5921_ = 0u;
                                                }
                                                let _e3273 = phi_5921_;
                                                let _e3277 = ((_e2926 * _e2903) - _e466);
                                                let _e3278 = ((_e2928 * _e2903) - _e473);
                                                let _e3279 = (_e2903 - _e459);
                                                if _e972 {
                                                    phi_5953_ = ((((_e3277 * _e3277) + (_e3278 * _e3278)) + (_e3279 * _e3279)) <= (_e241 * _e241));
                                                } else {
                                                    phi_5953_ = true;
                                                }
                                                let _e3288 = phi_5953_;
                                                let _e3290 = select(false, _e3288, (_e2903 < _e225.member.member_3));
                                                if _e3290 {
                                                    let _e3291 = (_e2906 < _e225.member.member_3);
                                                    let _e3300 = select((_e3277 - _e2374), ((_e2926 * _e2906) - _e466), _e3291);
                                                    let _e3301 = select((_e3278 - _e2375), ((_e2928 * _e2906) - _e473), _e3291);
                                                    let _e3302 = select((_e3279 - _e2376), (_e2906 - _e459), _e3291);
                                                    let _e3314 = ((((_e3277 * _e484) + (_e3278 * _e485)) + (_e3279 * _e486)) * inverseSqrt((((_e3277 * _e3277) + (_e3278 * _e3278)) + (_e3279 * _e3279))));
                                                    let _e3318 = select(-1f, select(1f, _e3314, (_e3314 < 1f)), (_e3314 > -1f));
                                                    let _e3319 = abs(_e3318);
                                                    let _e3329 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3319, 0.00667009f), _e3319, -0.017088126f), _e3319, 0.03089188f), _e3319, -0.050174303f), _e3319, 0.08897899f), _e3319, -0.2145988f), _e3319, 1.5707963f) * sqrt((1f - _e3319)));
                                                    let _e3336 = ((((select((3.1415927f - _e3329), _e3329, (_e3318 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3352 = ((((_e3300 * _e484) + (_e3301 * _e485)) + (_e3302 * _e486)) * inverseSqrt((((_e3300 * _e3300) + (_e3301 * _e3301)) + (_e3302 * _e3302))));
                                                    let _e3356 = select(-1f, select(1f, _e3352, (_e3352 < 1f)), (_e3352 > -1f));
                                                    let _e3357 = abs(_e3356);
                                                    let _e3367 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3357, 0.00667009f), _e3357, -0.017088126f), _e3357, 0.03089188f), _e3357, -0.050174303f), _e3357, 0.08897899f), _e3357, -0.2145988f), _e3357, 1.5707963f) * sqrt((1f - _e3357)));
                                                    let _e3374 = ((((select((3.1415927f - _e3367), _e3367, (_e3356 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3379 = (1f - select(0f, select(1f, _e3336, (_e3336 < 1f)), (_e3336 > 0f)));
                                                    let _e3380 = (1f - select(0f, select(1f, _e3374, (_e3374 < 1f)), (_e3374 > 0f)));
                                                    let _e3382 = (_e3380 != _e3380);
                                                    let _e3384 = select(_e3380, _e3379, ((_e3379 < _e3380) || _e3382));
                                                    let _e3387 = select(_e3380, _e3379, ((_e3379 > _e3380) || _e3382));
                                                    let _e3389 = floor((_e3384 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3397 = -(floor((_e3387 * -32f)));
                                                        let _e3402 = (select(32f, _e3397, ((_e3397 < 32f) || false)) - _e3389);
                                                        phi_6180_ = select(select(0f, _e3402, ((_e3402 > 0f) || false)), 0f, (_e3387 <= _e3384));
                                                    } else {
                                                        phi_6180_ = -(floor(((_e3387 - _e3384) * -32f)));
                                                    }
                                                    let _e3408 = phi_6180_;
                                                    let _e3416 = (bitcast<u32>((floor(select(0f, select(32f, _e3389, (_e3389 < 32f)), (_e3389 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3424 = (bitcast<u32>((floor(select(0f, select(32f, _e3408, (_e3408 < 32f)), (_e3408 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3416 >= 32u) {
                                                        phi_6234_ = u32();
                                                        phi_6235_ = true;
                                                    } else {
                                                        let _e3426 = (_e3424 == 0u);
                                                        if _e3426 {
                                                            phi_6233_ = u32();
                                                        } else {
                                                            if (_e3424 >= 32u) {
                                                                phi_6230_ = 4294967295u;
                                                            } else {
                                                                phi_6230_ = ((1u << bitcast<u32>((_e3424 & 31u))) - 1u);
                                                            }
                                                            let _e3433 = phi_6230_;
                                                            phi_6233_ = (_e3433 << bitcast<u32>((_e3416 & 31u)));
                                                        }
                                                        let _e3438 = phi_6233_;
                                                        phi_6234_ = _e3438;
                                                        phi_6235_ = _e3426;
                                                    }
                                                    let _e3440 = phi_6234_;
                                                    let _e3442 = phi_6235_;
                                                    phi_6248_ = select(0u, select(select(_e3440, 0u, _e3442), 0u, _e2465), _e3290);
                                                } else {
                                                    phi_6248_ = 0u;
                                                }
                                                let _e3447 = phi_6248_;
                                                let _e3451 = ((_e2926 * _e2871) - _e466);
                                                let _e3452 = ((_e2928 * _e2871) - _e473);
                                                let _e3453 = (_e2871 - _e459);
                                                if _e972 {
                                                    phi_6280_ = ((((_e3451 * _e3451) + (_e3452 * _e3452)) + (_e3453 * _e3453)) <= (_e241 * _e241));
                                                } else {
                                                    phi_6280_ = true;
                                                }
                                                let _e3462 = phi_6280_;
                                                let _e3464 = select(false, _e3462, (_e2871 < _e225.member.member_3));
                                                if _e3464 {
                                                    let _e3465 = (_e2659 < _e225.member.member_3);
                                                    let _e3474 = select((_e3451 - _e2374), ((_e2926 * _e2659) - _e466), _e3465);
                                                    let _e3475 = select((_e3452 - _e2375), ((_e2928 * _e2659) - _e473), _e3465);
                                                    let _e3476 = select((_e3453 - _e2376), (_e2659 - _e459), _e3465);
                                                    let _e3488 = ((((_e3451 * _e484) + (_e3452 * _e485)) + (_e3453 * _e486)) * inverseSqrt((((_e3451 * _e3451) + (_e3452 * _e3452)) + (_e3453 * _e3453))));
                                                    let _e3492 = select(-1f, select(1f, _e3488, (_e3488 < 1f)), (_e3488 > -1f));
                                                    let _e3493 = abs(_e3492);
                                                    let _e3503 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3493, 0.00667009f), _e3493, -0.017088126f), _e3493, 0.03089188f), _e3493, -0.050174303f), _e3493, 0.08897899f), _e3493, -0.2145988f), _e3493, 1.5707963f) * sqrt((1f - _e3493)));
                                                    let _e3510 = ((((select((3.1415927f - _e3503), _e3503, (_e3492 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3526 = ((((_e3474 * _e484) + (_e3475 * _e485)) + (_e3476 * _e486)) * inverseSqrt((((_e3474 * _e3474) + (_e3475 * _e3475)) + (_e3476 * _e3476))));
                                                    let _e3530 = select(-1f, select(1f, _e3526, (_e3526 < 1f)), (_e3526 > -1f));
                                                    let _e3531 = abs(_e3530);
                                                    let _e3541 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3531, 0.00667009f), _e3531, -0.017088126f), _e3531, 0.03089188f), _e3531, -0.050174303f), _e3531, 0.08897899f), _e3531, -0.2145988f), _e3531, 1.5707963f) * sqrt((1f - _e3531)));
                                                    let _e3548 = ((((select((3.1415927f - _e3541), _e3541, (_e3530 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                                    let _e3553 = (1f - select(0f, select(1f, _e3510, (_e3510 < 1f)), (_e3510 > 0f)));
                                                    let _e3554 = (1f - select(0f, select(1f, _e3548, (_e3548 < 1f)), (_e3548 > 0f)));
                                                    let _e3556 = (_e3554 != _e3554);
                                                    let _e3558 = select(_e3554, _e3553, ((_e3553 < _e3554) || _e3556));
                                                    let _e3561 = select(_e3554, _e3553, ((_e3553 > _e3554) || _e3556));
                                                    let _e3563 = floor((_e3558 * 32f));
                                                    if (_e235 == 1u) {
                                                        let _e3571 = -(floor((_e3561 * -32f)));
                                                        let _e3576 = (select(32f, _e3571, ((_e3571 < 32f) || false)) - _e3563);
                                                        phi_6507_ = select(select(0f, _e3576, ((_e3576 > 0f) || false)), 0f, (_e3561 <= _e3558));
                                                    } else {
                                                        phi_6507_ = -(floor(((_e3561 - _e3558) * -32f)));
                                                    }
                                                    let _e3582 = phi_6507_;
                                                    let _e3590 = (bitcast<u32>((floor(select(0f, select(32f, _e3563, (_e3563 < 32f)), (_e3563 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3598 = (bitcast<u32>((floor(select(0f, select(32f, _e3582, (_e3582 < 32f)), (_e3582 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3590 >= 32u) {
                                                        phi_6561_ = u32();
                                                        phi_6562_ = true;
                                                    } else {
                                                        let _e3600 = (_e3598 == 0u);
                                                        if _e3600 {
                                                            phi_6560_ = u32();
                                                        } else {
                                                            if (_e3598 >= 32u) {
                                                                phi_6557_ = 4294967295u;
                                                            } else {
                                                                phi_6557_ = ((1u << bitcast<u32>((_e3598 & 31u))) - 1u);
                                                            }
                                                            let _e3607 = phi_6557_;
                                                            phi_6560_ = (_e3607 << bitcast<u32>((_e3590 & 31u)));
                                                        }
                                                        let _e3612 = phi_6560_;
                                                        phi_6561_ = _e3612;
                                                        phi_6562_ = _e3600;
                                                    }
                                                    let _e3614 = phi_6561_;
                                                    let _e3616 = phi_6562_;
                                                    phi_6575_ = select(0u, select(select(_e3614, 0u, _e3616), 0u, _e2465), _e3464);
                                                } else {
                                                    phi_6575_ = 0u;
                                                }
                                                let _e3621 = phi_6575_;
                                                phi_6577_ = (((_e3100 | _e3273) | _e3447) | _e3621);
                                                phi_6578_ = vec3<f32>(select(_e2377, (((_e2912 * _e2485) * _e2847) - _e466), _e2910), select(_e2378, (((_e2916 * _e2493) * _e2847) - _e473), _e2910), select(_e2379, (_e2847 - _e459), _e2910));
                                            } else {
                                                phi_6577_ = 0u;
                                                phi_6578_ = vec3<f32>(_e2377, _e2378, _e2379);
                                            }
                                            let _e3624 = phi_6577_;
                                            let _e3626 = phi_6578_;
                                            let _e3628 = (_e2385 * inverseSqrt(_e2368));
                                            let _e3632 = select(-1f, select(1f, _e3628, (_e3628 < 1f)), (_e3628 > -1f));
                                            let _e3633 = abs(_e3632);
                                            let _e3643 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3633, 0.00667009f), _e3633, -0.017088126f), _e3633, 0.03089188f), _e3633, -0.050174303f), _e3633, 0.08897899f), _e3633, -0.2145988f), _e3633, 1.5707963f) * sqrt((1f - _e3633)));
                                            let _e3650 = ((((select((3.1415927f - _e3643), _e3643, (_e3632 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                            let _e3669 = ((((_e3626.x * _e484) + (_e3626.y * _e485)) + (_e3626.z * _e486)) * inverseSqrt((((_e3626.x * _e3626.x) + (_e3626.y * _e3626.y)) + (_e3626.z * _e3626.z))));
                                            let _e3673 = select(-1f, select(1f, _e3669, (_e3669 < 1f)), (_e3669 > -1f));
                                            let _e3674 = abs(_e3673);
                                            let _e3684 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3674, 0.00667009f), _e3674, -0.017088126f), _e3674, 0.03089188f), _e3674, -0.050174303f), _e3674, 0.08897899f), _e3674, -0.2145988f), _e3674, 1.5707963f) * sqrt((1f - _e3674)));
                                            let _e3691 = ((((select((3.1415927f - _e3684), _e3684, (_e3673 >= 0f)) + _e2459) - _e2455) + 1.5707964f) * 0.31830987f);
                                            let _e3696 = (1f - select(0f, select(1f, _e3650, (_e3650 < 1f)), (_e3650 > 0f)));
                                            let _e3697 = (1f - select(0f, select(1f, _e3691, (_e3691 < 1f)), (_e3691 > 0f)));
                                            let _e3699 = (_e3697 != _e3697);
                                            let _e3701 = select(_e3697, _e3696, ((_e3696 < _e3697) || _e3699));
                                            let _e3704 = select(_e3697, _e3696, ((_e3696 > _e3697) || _e3699));
                                            let _e3706 = floor((_e3701 * 32f));
                                            if (_e235 == 1u) {
                                                let _e3714 = -(floor((_e3704 * -32f)));
                                                let _e3719 = (select(32f, _e3714, ((_e3714 < 32f) || false)) - _e3706);
                                                phi_6765_ = select(select(0f, _e3719, ((_e3719 > 0f) || false)), 0f, (_e3704 <= _e3701));
                                            } else {
                                                phi_6765_ = -(floor(((_e3704 - _e3701) * -32f)));
                                            }
                                            let _e3725 = phi_6765_;
                                            let _e3733 = (bitcast<u32>((floor(select(0f, select(32f, _e3706, (_e3706 < 32f)), (_e3706 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e3741 = (bitcast<u32>((floor(select(0f, select(32f, _e3725, (_e3725 < 32f)), (_e3725 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e3733 >= 32u) {
                                                phi_6819_ = u32();
                                                phi_6820_ = true;
                                            } else {
                                                let _e3743 = (_e3741 == 0u);
                                                if _e3743 {
                                                    phi_6818_ = u32();
                                                } else {
                                                    if (_e3741 >= 32u) {
                                                        phi_6815_ = 4294967295u;
                                                    } else {
                                                        phi_6815_ = ((1u << bitcast<u32>((_e3741 & 31u))) - 1u);
                                                    }
                                                    let _e3750 = phi_6815_;
                                                    phi_6818_ = (_e3750 << bitcast<u32>((_e3733 & 31u)));
                                                }
                                                let _e3755 = phi_6818_;
                                                phi_6819_ = _e3755;
                                                phi_6820_ = _e3743;
                                            }
                                            let _e3757 = phi_6819_;
                                            let _e3759 = phi_6820_;
                                            phi_6834_ = select((select(select(_e3757, 0u, _e3759), 0u, _e2465) | _e3624), 0u, _e2372);
                                        } else {
                                            phi_6834_ = 0u;
                                        }
                                        let _e3765 = phi_6834_;
                                        phi_1200_ = (_e787 + 1u);
                                        phi_1203_ = ((_e789 | _e2359) | _e3765);
                                    } else {
                                        phi_1200_ = u32();
                                        phi_1203_ = u32();
                                    }
                                    let _e3769 = phi_1200_;
                                    let _e3771 = phi_1203_;
                                    continue;
                                    continuing {
                                        phi_1199_ = _e3769;
                                        phi_1202_ = _e3771;
                                        phi_7189_ = _e684;
                                        break if !(_e790);
                                    }
                                }
                                let _e3774 = phi_7189_;
                                phi_7815_ = _e3774;
                                if _e3774 {
                                    break;
                                }
                                if (_e230 == 2u) {
                                    let _e3833 = (_e782 - 1.5707964f);
                                    let _e3834 = (_e3833 * 2f);
                                    let _e3835 = sin(_e782);
                                    let _e3840 = ((_e767 + (_e3834 * _e3835)) - cos((_e3834 - _e782)));
                                    phi_6863_ = 0u;
                                    phi_6866_ = select((_e3840 * 0.25f), (_e3840 * -0.25f), (_e3833 < 0f));
                                    phi_6868_ = 0f;
                                    loop {
                                        let _e3846 = phi_6863_;
                                        let _e3848 = phi_6866_;
                                        let _e3850 = phi_6868_;
                                        local_13 = _e3850;
                                        let _e3851 = (_e3846 < 32u);
                                        if _e3851 {
                                            let _e3852 = (_e3846 + 1u);
                                            let _e3856 = (_e3833 + (f32(bitcast<i32>(_e3852)) * 0.09817477f));
                                            let _e3857 = (_e3856 * 2f);
                                            let _e3862 = ((_e767 + (_e3857 * _e3835)) - cos((_e3857 - _e782)));
                                            let _e3866 = select((_e3862 * 0.25f), (_e3862 * -0.25f), (_e3856 < 0f));
                                            let _e3869 = local_12;
                                            phi_6864_ = _e3852;
                                            phi_6867_ = _e3866;
                                            phi_6869_ = select(_e3850, (_e3850 + (_e3866 - _e3848)), (((_e3869 >> bitcast<u32>((_e3846 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_6864_ = u32();
                                            phi_6867_ = f32();
                                            phi_6869_ = f32();
                                        }
                                        let _e3878 = phi_6864_;
                                        let _e3880 = phi_6867_;
                                        let _e3882 = phi_6869_;
                                        continue;
                                        continuing {
                                            phi_6863_ = _e3878;
                                            phi_6866_ = _e3880;
                                            phi_6868_ = _e3882;
                                            break if !(_e3851);
                                        }
                                    }
                                    let _e3885 = local_13;
                                    phi_7817_ = _e3774;
                                    phi_6970_ = (_e688 + 1f);
                                    phi_6971_ = (_e690 + ((_e748 + ((1f - _e748) * 0.05f)) * _e3885));
                                } else {
                                    if (_e230 == 1u) {
                                        phi_6915_ = 0u;
                                        phi_6918_ = 0f;
                                        loop {
                                            let _e3788 = phi_6915_;
                                            let _e3790 = phi_6918_;
                                            local_11 = _e3790;
                                            let _e3791 = (_e3788 < 4u);
                                            if _e3791 {
                                                local = array<type_40, 4>(type_40(4026531855u, 0.0095061f), type_40(251658480u, 0.0270951f), type_40(15732480u, 0.0405571f), type_40(1044480u, 0.0478421f));
                                                if _e3791 {
                                                } else {
                                                    phi_7812_ = true;
                                                    break;
                                                }
                                                let _e3794 = local[_e3788].member;
                                                let _e3797 = local[_e3788].member_1;
                                                let _e3799 = local_10;
                                                phi_6916_ = (_e3788 + 1u);
                                                phi_6919_ = (_e3790 + (f32(bitcast<i32>(countOneBits((_e3799 & _e3794)))) * _e3797));
                                            } else {
                                                phi_6916_ = u32();
                                                phi_6919_ = f32();
                                            }
                                            let _e3808 = phi_6916_;
                                            let _e3810 = phi_6919_;
                                            continue;
                                            continuing {
                                                phi_6915_ = _e3808;
                                                phi_6918_ = _e3810;
                                                phi_7812_ = _e3774;
                                                break if !(_e3791);
                                            }
                                        }
                                        let _e3813 = phi_7812_;
                                        phi_7815_ = _e3813;
                                        if _e3813 {
                                            break;
                                        }
                                        let _e3815 = local_11;
                                        let _e3816 = (1f - _e3815);
                                        phi_7823_ = _e3813;
                                        phi_6968_ = (_e688 + _e748);
                                        phi_6969_ = (_e690 + (_e748 * select(0f, select(1f, _e3816, (_e3816 < 1f)), (_e3816 > 0f))));
                                    } else {
                                        let _e3778 = local_9;
                                        phi_7823_ = _e3774;
                                        phi_6968_ = (_e688 + 1f);
                                        phi_6969_ = (_e690 + ((f32(bitcast<i32>(countOneBits((_e3778 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e3825 = phi_7823_;
                                    let _e3827 = phi_6968_;
                                    let _e3829 = phi_6969_;
                                    phi_7817_ = _e3825;
                                    phi_6970_ = _e3827;
                                    phi_6971_ = _e3829;
                                }
                                let _e3890 = phi_7817_;
                                let _e3892 = phi_6970_;
                                let _e3894 = phi_6971_;
                                phi_7816_ = _e3890;
                                phi_1009_ = (_e686 + 1u);
                                phi_1012_ = _e3892;
                                phi_1014_ = _e3894;
                            } else {
                                phi_7816_ = _e684;
                                phi_1009_ = u32();
                                phi_1012_ = f32();
                                phi_1014_ = f32();
                            }
                            let _e3897 = phi_7816_;
                            let _e3899 = phi_1009_;
                            let _e3901 = phi_1012_;
                            let _e3903 = phi_1014_;
                            continue;
                            continuing {
                                phi_7728_ = _e3897;
                                phi_1008_ = _e3899;
                                phi_1011_ = _e3901;
                                phi_1013_ = _e3903;
                                phi_7815_ = _e3897;
                                break if !(_e691);
                            }
                        }
                        let _e3906 = phi_7815_;
                        if _e3906 {
                            break;
                        }
                        let _e3908 = local_14;
                        let _e3911 = local_15;
                        let _e3913 = local_16;
                        phi_6979_ = select(1f, (_e3911 / _e3913), (_e3908 > 0f));
                    } else {
                        phi_6979_ = 1f;
                    }
                    let _e3917 = phi_6979_;
                    if (_e225.member_6 == 2f) {
                        phi_6992_ = (_e3917 * _e3917);
                    } else {
                        if (_e225.member_6 == 1f) {
                            phi_6991_ = _e3917;
                        } else {
                            phi_6991_ = pow(_e3917, _e225.member_6);
                        }
                        let _e3923 = phi_6991_;
                        phi_6992_ = _e3923;
                    }
                    let _e3926 = phi_6992_;
                    let _e3931 = (select(1f, select(0.03f, _e3926, ((_e3926 > 0.03f) || false)), _e679) * 0.6666667f);
                    terms.member[_e267] = (bitcast<u32>((floor(((select(0f, select(1f, _e3931, (_e3931 < 1f)), (_e3931 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
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
