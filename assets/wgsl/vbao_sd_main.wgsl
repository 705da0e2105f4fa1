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
    var local_5: array<f32, 8>;
    var local_6: array<array<f32, 2>, 16>;
    var local_7: array<array<f32, 2>, 16>;
    var local_8: array<array<f32, 2>, 16>;
    var local_9: array<array<f32, 2>, 16>;
    var local_10: array<f32, 8>;
    var phi_339_: type_26;
    var phi_346_: u32;
    var phi_353_: u32;
    var phi_6710_: bool;
    var phi_1011_: u32;
    var phi_1014_: f32;
    var phi_1016_: f32;
    var phi_6701_: bool;
    var phi_1202_: u32;
    var phi_1205_: u32;
    var phi_1262_: f32;
    var phi_1263_: f32;
    var phi_1544_: bool;
    var phi_1560_: bool;
    var phi_3517_: bool;
    var phi_3833_: f32;
    var phi_3883_: u32;
    var phi_3886_: u32;
    var phi_3887_: u32;
    var phi_3888_: bool;
    var phi_3901_: u32;
    var phi_1719_: vec2<f32>;
    var phi_1720_: vec2<f32>;
    var phi_6657_: bool;
    var phi_2255_: u32;
    var phi_2258_: u32;
    var phi_2298_: u32;
    var phi_2299_: u32;
    var phi_2335_: bool;
    var phi_6653_: bool;
    var local_11: u32;
    var local_12: u32;
    var phi_6776_: bool;
    var phi_2347_: u32;
    var phi_6775_: bool;
    var phi_2348_: u32;
    var phi_6774_: bool;
    var phi_2256_: u32;
    var phi_2259_: u32;
    var phi_6773_: bool;
    var local_13: u32;
    var phi_3078_: f32;
    var phi_3128_: u32;
    var phi_3131_: u32;
    var phi_3132_: u32;
    var phi_3133_: bool;
    var phi_3143_: u32;
    var phi_3146_: u32;
    var local_14: u32;
    var local_15: u32;
    var phi_3225_: vec3<f32>;
    var phi_3240_: bool;
    var phi_3430_: f32;
    var phi_3480_: u32;
    var phi_3483_: u32;
    var phi_3484_: u32;
    var phi_3485_: bool;
    var phi_3495_: u32;
    var phi_3144_: u32;
    var phi_3147_: u32;
    var phi_6777_: bool;
    var phi_2365_: bool;
    var phi_2681_: f32;
    var phi_2731_: u32;
    var phi_2734_: u32;
    var phi_2735_: u32;
    var phi_2736_: bool;
    var phi_2749_: u32;
    var phi_6897_: bool;
    var phi_3497_: u32;
    var phi_3498_: u32;
    var phi_1853_: bool;
    var phi_2169_: f32;
    var phi_2219_: u32;
    var phi_2222_: u32;
    var phi_2223_: u32;
    var phi_2224_: bool;
    var phi_2237_: u32;
    var phi_6862_: bool;
    var phi_3499_: u32;
    var phi_3500_: u32;
    var phi_3501_: bool;
    var phi_6860_: bool;
    var phi_3902_: u32;
    var phi_3925_: bool;
    var phi_3941_: bool;
    var phi_5898_: bool;
    var phi_6214_: f32;
    var phi_6264_: u32;
    var phi_6267_: u32;
    var phi_6268_: u32;
    var phi_6269_: bool;
    var phi_6282_: u32;
    var phi_4100_: vec2<f32>;
    var phi_4101_: vec2<f32>;
    var phi_6844_: bool;
    var phi_4636_: u32;
    var phi_4639_: u32;
    var phi_4679_: u32;
    var phi_4680_: u32;
    var phi_4716_: bool;
    var phi_6840_: bool;
    var local_16: u32;
    var local_17: u32;
    var phi_6970_: bool;
    var phi_4728_: u32;
    var phi_6969_: bool;
    var phi_4729_: u32;
    var phi_6968_: bool;
    var phi_4637_: u32;
    var phi_4640_: u32;
    var phi_6967_: bool;
    var local_18: u32;
    var phi_5459_: f32;
    var phi_5509_: u32;
    var phi_5512_: u32;
    var phi_5513_: u32;
    var phi_5514_: bool;
    var phi_5524_: u32;
    var phi_5527_: u32;
    var local_19: u32;
    var local_20: u32;
    var phi_5606_: vec3<f32>;
    var phi_5621_: bool;
    var phi_5811_: f32;
    var phi_5861_: u32;
    var phi_5864_: u32;
    var phi_5865_: u32;
    var phi_5866_: bool;
    var phi_5876_: u32;
    var phi_5525_: u32;
    var phi_5528_: u32;
    var phi_6971_: bool;
    var phi_4746_: bool;
    var phi_5062_: f32;
    var phi_5112_: u32;
    var phi_5115_: u32;
    var phi_5116_: u32;
    var phi_5117_: bool;
    var phi_5130_: u32;
    var phi_7073_: bool;
    var phi_5878_: u32;
    var phi_5879_: u32;
    var phi_4234_: bool;
    var phi_4550_: f32;
    var phi_4600_: u32;
    var phi_4603_: u32;
    var phi_4604_: u32;
    var phi_4605_: bool;
    var phi_4618_: u32;
    var phi_7038_: bool;
    var phi_5880_: u32;
    var phi_5881_: u32;
    var phi_5882_: bool;
    var phi_7036_: bool;
    var phi_6283_: u32;
    var phi_7035_: bool;
    var phi_1203_: u32;
    var phi_1206_: u32;
    var phi_7034_: bool;
    var local_21: u32;
    var phi_6364_: u32;
    var phi_6367_: f32;
    var local_22: u32;
    var phi_6365_: u32;
    var phi_6368_: f32;
    var phi_7142_: bool;
    var local_23: f32;
    var phi_7153_: bool;
    var phi_6417_: f32;
    var phi_6418_: f32;
    var phi_6312_: u32;
    var phi_6315_: f32;
    var phi_6317_: f32;
    var local_24: u32;
    var phi_6313_: u32;
    var phi_6316_: f32;
    var phi_6318_: f32;
    var local_25: f32;
    var phi_7147_: bool;
    var phi_6419_: f32;
    var phi_6420_: f32;
    var phi_7146_: bool;
    var phi_1012_: u32;
    var phi_1015_: f32;
    var phi_1017_: f32;
    var phi_7145_: bool;
    var local_26: f32;
    var local_27: f32;
    var local_28: f32;
    var phi_6428_: f32;
    var phi_6440_: f32;
    var phi_6441_: f32;
    var local_29: u32;
    var local_30: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e185 = id_1;
            let _e190 = arrayLength((&mips.member));
            let _e193 = arrayLength((&sd_map.member));
            let _e196 = (override_type == 0u);
            if _e196 {
                let _e228 = params.member.member_4;
                phi_339_ = _e228;
            } else {
                let _e206 = params.member.member_4.member;
                let _e210 = params.member.member_4.member_1;
                let _e214 = params.member.member_4.member_10;
                let _e218 = params.member.member_4.member_11;
                let _e222 = params.member.member_4.member_12;
                let _e226 = params.member.member_4.member_14;
                phi_339_ = type_26(_e206, _e210, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e214, _e218, _e222, override_type_9, _e226);
            }
            let _e230 = phi_339_;
            if _e196 {
                let _e233 = params.member.member_2;
                phi_346_ = _e233;
            } else {
                phi_346_ = override_type_10;
            }
            let _e235 = phi_346_;
            if _e196 {
                let _e238 = params.member.member_3;
                phi_353_ = _e238;
            } else {
                phi_353_ = override_type_11;
            }
            let _e240 = phi_353_;
            let _e243 = params.member.member;
            let _e246 = params.member.member_1;
            let _e254 = select(select(u32(_e230.member.member.x), 0u, (_e230.member.member.x < 0f)), 4294967295u, (_e230.member.member.x > 4294967000f));
            let _e262 = select(select(u32(_e230.member.member.y), 0u, (_e230.member.member.y < 0f)), 4294967295u, (_e230.member.member.y > 4294967000f));
            if (_e185.x >= _e254) {
            } else {
                if (_e185.y >= _e262) {
                } else {
                    if (0u < arrayLength((&frame.member))) {
                    } else {
                        break;
                    }
                    let _e272 = ((_e185.y * _e254) + _e185.x);
                    let _e275 = mips.member[_e272];
                    let _e276 = bitcast<i32>(_e185.x);
                    let _e277 = (_e276 + -1i);
                    let _e279 = select(0i, _e277, (0i < _e277));
                    let _e281 = (bitcast<i32>(_e254) - 1i);
                    let _e285 = bitcast<i32>(_e185.y);
                    let _e287 = select(0i, _e285, (0i < _e285));
                    let _e289 = (bitcast<i32>(_e262) - 1i);
                    let _e293 = (bitcast<u32>(select(_e287, _e289, (_e289 < _e287))) * _e254);
                    let _e297 = mips.member[(_e293 + bitcast<u32>(select(_e279, _e281, (_e281 < _e279))))];
                    let _e298 = (_e276 + 1i);
                    let _e300 = select(0i, _e298, (0i < _e298));
                    let _e307 = mips.member[(_e293 + bitcast<u32>(select(_e300, _e281, (_e281 < _e300))))];
                    let _e309 = select(0i, _e276, (0i < _e276));
                    let _e312 = bitcast<u32>(select(_e309, _e281, (_e281 < _e309)));
                    let _e313 = (_e285 + -1i);
                    let _e315 = select(0i, _e313, (0i < _e313));
                    let _e323 = mips.member[((bitcast<u32>(select(_e315, _e289, (_e289 < _e315))) * _e254) + _e312)];
                    let _e324 = (_e285 + 1i);
                    let _e326 = select(0i, _e324, (0i < _e324));
                    let _e334 = mips.member[((bitcast<u32>(select(_e326, _e289, (_e289 < _e326))) * _e254) + _e312)];
                    let _e335 = (_e297 - _e275);
                    let _e336 = (_e307 - _e275);
                    let _e337 = (_e323 - _e275);
                    let _e338 = (_e334 - _e275);
                    let _e340 = ((_e336 - _e335) * 0.5f);
                    let _e342 = ((_e338 - _e337) * 0.5f);
                    let _e343 = (_e275 * 0.011f);
                    let _e345 = abs(_e335);
                    let _e346 = abs((_e335 + _e340));
                    let _e352 = (1.25f - (select(_e346, _e345, ((_e345 < _e346) || (_e346 != _e346))) / _e343));
                    let _e356 = select(0f, select(1f, _e352, (_e352 < 1f)), (_e352 > 0f));
                    let _e358 = abs(_e336);
                    let _e359 = abs((_e336 - _e340));
                    let _e365 = (1.25f - (select(_e359, _e358, ((_e358 < _e359) || (_e359 != _e359))) / _e343));
                    let _e369 = select(0f, select(1f, _e365, (_e365 < 1f)), (_e365 > 0f));
                    let _e371 = abs(_e337);
                    let _e372 = abs((_e337 + _e342));
                    let _e378 = (1.25f - (select(_e372, _e371, ((_e371 < _e372) || (_e372 != _e372))) / _e343));
                    let _e382 = select(0f, select(1f, _e378, (_e378 < 1f)), (_e378 > 0f));
                    let _e384 = abs(_e338);
                    let _e385 = abs((_e338 - _e342));
                    let _e391 = (1.25f - (select(_e385, _e384, ((_e384 < _e385) || (_e385 != _e385))) / _e343));
                    let _e395 = select(0f, select(1f, _e391, (_e391 < 1f)), (_e391 > 0f));
                    let _e401 = round((select(0f, select(1f, _e356, (_e356 < 1f)), (_e356 > 0f)) * 2.9f));
                    let _e416 = round((select(0f, select(1f, _e369, (_e369 < 1f)), (_e369 > 0f)) * 2.9f));
                    let _e432 = round((select(0f, select(1f, _e382, (_e382 < 1f)), (_e382 > 0f)) * 2.9f));
                    let _e448 = round((select(0f, select(1f, _e395, (_e395 < 1f)), (_e395 > 0f)) * 2.9f));
                    let _e460 = ((f32(_e276) + 0.5f) / _e230.member.member.x);
                    let _e463 = ((f32(_e285) + 0.5f) / _e230.member.member.y);
                    let _e464 = (_e275 * 0.99999f);
                    let _e471 = ((((_e460 * 2f) - 1f) * _e230.member.member_1.x) * _e464);
                    let _e478 = ((((_e463 * -2f) + 1f) * _e230.member.member_1.y) * _e464);
                    let _e479 = vec3<f32>(_e471, _e478, _e464);
                    let _e480 = -(_e471);
                    let _e481 = -(_e478);
                    let _e482 = (_e275 * -0.99999f);
                    let _e489 = (1f / sqrt((((_e480 * _e480) + (_e481 * _e481)) + (_e482 * _e482))));
                    let _e490 = (_e480 * _e489);
                    let _e491 = (_e481 * _e489);
                    let _e492 = (_e482 * _e489);
                    let _e495 = normals.member[_e272];
                    let _e498 = f32(bitcast<i32>((_e495 & 255u)));
                    let _e502 = (select(_e498, (_e498 - 256f), (_e498 >= 128f)) * 0.007874016f);
                    let _e505 = select(-1f, _e502, ((_e502 > -1f) || false));
                    let _e510 = f32(bitcast<i32>(((_e495 >> bitcast<u32>(8u)) & 255u)));
                    let _e514 = (select(_e510, (_e510 - 256f), (_e510 >= 128f)) * 0.007874016f);
                    let _e517 = select(-1f, _e514, ((_e514 > -1f) || false));
                    let _e519 = (1f - abs(_e505));
                    let _e520 = abs(_e517);
                    let _e521 = (_e519 - _e520);
                    let _e522 = (_e521 < 0f);
                    let _e530 = select(_e505, ((1f - _e520) * select(1f, -1f, (_e505 < 0f))), _e522);
                    let _e531 = select(_e517, (_e519 * select(1f, -1f, (_e517 < 0f))), _e522);
                    let _e538 = (1f / sqrt((((_e530 * _e530) + (_e531 * _e531)) + (_e521 * _e521))));
                    let _e539 = (_e530 * _e538);
                    let _e540 = (_e531 * _e538);
                    let _e541 = (_e521 * _e538);
                    let _e542 = -(_e541);
                    let _e548 = ((((_e539 * _e490) + (_e540 * _e491)) + (_e542 * _e492)) < 0f);
                    let _e551 = select(_e539, -(_e539), _e548);
                    let _e552 = select(_e540, -(_e540), _e548);
                    let _e553 = select(_e542, _e541, _e548);
                    let _e560 = ((_e230.member_1 * _e230.member_2) / (((_e275 * 1.99998f) * _e230.member.member_1.x) / _e230.member.member.x));
                    let _e563 = (_e185.x & 63u);
                    let _e564 = (_e185.y & 63u);
                    let _e567 = ((_e563 >> bitcast<u32>(5u)) & 1u);
                    let _e570 = ((_e564 >> bitcast<u32>(5u)) & 1u);
                    let _e574 = (_e570 ^ 1u);
                    let _e576 = ((_e567 & _e574) * 63u);
                    let _e577 = (_e563 ^ _e576);
                    let _e578 = (_e564 ^ _e576);
                    let _e580 = ((_e577 ^ _e578) * _e574);
                    let _e581 = (_e577 ^ _e580);
                    let _e582 = (_e578 ^ _e580);
                    let _e585 = ((_e581 >> bitcast<u32>(4u)) & 1u);
                    let _e588 = ((_e582 >> bitcast<u32>(4u)) & 1u);
                    let _e593 = (_e588 ^ 1u);
                    let _e595 = ((_e585 & _e593) * 63u);
                    let _e596 = (_e581 ^ _e595);
                    let _e597 = (_e582 ^ _e595);
                    let _e599 = ((_e596 ^ _e597) * _e593);
                    let _e600 = (_e596 ^ _e599);
                    let _e601 = (_e597 ^ _e599);
                    let _e604 = ((_e600 >> bitcast<u32>(3u)) & 1u);
                    let _e607 = ((_e601 >> bitcast<u32>(3u)) & 1u);
                    let _e612 = (_e607 ^ 1u);
                    let _e614 = ((_e604 & _e612) * 63u);
                    let _e615 = (_e600 ^ _e614);
                    let _e616 = (_e601 ^ _e614);
                    let _e618 = ((_e615 ^ _e616) * _e612);
                    let _e619 = (_e615 ^ _e618);
                    let _e620 = (_e616 ^ _e618);
                    let _e623 = ((_e619 >> bitcast<u32>(2u)) & 1u);
                    let _e626 = ((_e620 >> bitcast<u32>(2u)) & 1u);
                    let _e631 = (_e626 ^ 1u);
                    let _e633 = ((_e623 & _e631) * 63u);
                    let _e634 = (_e619 ^ _e633);
                    let _e635 = (_e620 ^ _e633);
                    let _e637 = ((_e634 ^ _e635) * _e631);
                    let _e638 = (_e634 ^ _e637);
                    let _e639 = (_e635 ^ _e637);
                    let _e642 = ((_e638 >> bitcast<u32>(1u)) & 1u);
                    let _e645 = ((_e639 >> bitcast<u32>(1u)) & 1u);
                    let _e650 = (_e645 ^ 1u);
                    let _e652 = ((_e642 & _e650) * 63u);
                    let _e653 = (_e638 ^ _e652);
                    let _e654 = (_e639 ^ _e652);
                    let _e656 = ((_e653 ^ _e654) * _e650);
                    let _e668 = f32(bitcast<i32>((((((((((_e567 * 3u) ^ _e570) * 1024u) + (((_e585 * 3u) ^ _e588) * 256u)) + (((_e604 * 3u) ^ _e607) * 64u)) + (((_e623 * 3u) ^ _e626) * 16u)) + (((_e642 * 3u) ^ _e645) * 4u)) + ((((_e653 ^ _e656) & 1u) * 3u) ^ ((_e654 ^ _e656) & 1u))) + (288u * (_e230.member_11 % 64u)))));
                    let _e670 = ((_e668 * 0.7548777f) + 0.5f);
                    let _e674 = ((_e668 * 0.5698403f) + 0.5f);
                    let _e680 = exp2(((2f * _e230.member_7) + 1f));
                    let _e685 = select(false, (_e275 < _e230.member.member_3), (_e275 > 0f));
                    if _e685 {
                        let _e688 = select(1u, _e230.member_8, (1u < _e230.member_8));
                        phi_6710_ = false;
                        phi_1011_ = 0u;
                        phi_1014_ = 0f;
                        phi_1016_ = 0f;
                        loop {
                            let _e690 = phi_6710_;
                            let _e692 = phi_1011_;
                            let _e694 = phi_1014_;
                            let _e696 = phi_1016_;
                            local_26 = _e694;
                            local_27 = _e696;
                            local_28 = _e694;
                            let _e697 = (_e692 < _e688);
                            if _e697 {
                                let _e704 = ((((_e670 - floor(_e670)) + f32(bitcast<i32>(_e692))) * 3.1415927f) / f32(bitcast<i32>(_e688)));
                                let _e705 = sin(_e704);
                                let _e706 = cos(_e704);
                                let _e712 = ((_e706 * _e490) + (_e705 * _e491));
                                let _e716 = (_e706 - (_e490 * _e712));
                                let _e717 = (_e705 - (_e491 * _e712));
                                let _e718 = -((_e492 * _e712));
                                let _e721 = ((_e717 * _e492) - (_e491 * _e718));
                                let _e724 = ((_e718 * _e490) - (_e492 * _e716));
                                let _e727 = ((_e716 * _e491) - (_e490 * _e717));
                                let _e734 = (1f / sqrt((((_e721 * _e721) + (_e724 * _e724)) + (_e727 * _e727))));
                                let _e735 = (_e721 * _e734);
                                let _e736 = (_e724 * _e734);
                                let _e737 = (_e727 * _e734);
                                let _e742 = (((_e551 * _e735) + (_e552 * _e736)) + (_e553 * _e737));
                                let _e746 = (_e551 - (_e735 * _e742));
                                let _e747 = (_e552 - (_e736 * _e742));
                                let _e748 = (_e553 - (_e737 * _e742));
                                let _e754 = sqrt((((_e746 * _e746) + (_e747 * _e747)) + (_e748 * _e748)));
                                let _e759 = (((_e716 * _e746) + (_e717 * _e747)) + (_e718 * _e748));
                                let _e769 = ((((_e746 * _e490) + (_e747 * _e491)) + (_e748 * _e492)) / _e754);
                                let _e773 = select(0f, select(1f, _e769, (_e769 < 1f)), (_e769 > 0f));
                                let _e774 = abs(_e773);
                                let _e785 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e774, 0.00667009f), _e774, -0.017088126f), _e774, 0.03089188f), _e774, -0.050174303f), _e774, 0.08897899f), _e774, -0.2145988f), _e774, 1.5707963f) * sqrt((1f - _e774)));
                                let _e788 = (select(select(0f, -1f, (_e759 < 0f)), 1f, (_e759 > 0f)) * select((3.1415927f - _e785), _e785, (_e773 >= 0f)));
                                let _e791 = select(1u, _e230.member_9, (1u < _e230.member_9));
                                phi_6701_ = _e690;
                                phi_1202_ = 0u;
                                phi_1205_ = 0u;
                                loop {
                                    let _e793 = phi_6701_;
                                    let _e795 = phi_1202_;
                                    let _e797 = phi_1205_;
                                    local_21 = _e797;
                                    local_22 = _e797;
                                    local_24 = _e797;
                                    let _e798 = (_e795 < _e791);
                                    if _e798 {
                                        let _e804 = ((_e674 - floor(_e674)) + (f32(bitcast<i32>((_e692 + (_e795 * _e791)))) * 0.618034f));
                                        let _e813 = (((_e804 - floor(_e804)) + f32(bitcast<i32>(_e795))) * (1f / f32(bitcast<i32>(_e791))));
                                        if (_e230.member_4 == 2f) {
                                            phi_1263_ = (_e813 * _e813);
                                        } else {
                                            if (_e230.member_4 == 1f) {
                                                phi_1262_ = _e813;
                                            } else {
                                                phi_1262_ = pow(_e813, _e230.member_4);
                                            }
                                            let _e819 = phi_1262_;
                                            phi_1263_ = _e819;
                                        }
                                        let _e822 = phi_1263_;
                                        let _e823 = (_e822 + (1.3f / _e560));
                                        let _e824 = ((_e706 * _e560) * _e823);
                                        let _e825 = ((-(_e705) * _e560) * _e823);
                                        let _e828 = ((_e824 * _e824) + (_e825 * _e825));
                                        let _e833 = (select(1u, _e254, (1u < _e254)) * select(1u, _e262, (1u < _e262)));
                                        let _e834 = (_e828 > _e680);
                                        let _e838 = (_e254 >> bitcast<u32>(1u));
                                        let _e842 = (_e262 >> bitcast<u32>(1u));
                                        let _e846 = (_e833 + (select(1u, _e838, (1u < _e838)) * select(1u, _e842, (1u < _e842))));
                                        let _e848 = (_e828 > (_e680 * 4f));
                                        let _e852 = (_e254 >> bitcast<u32>(2u));
                                        let _e856 = (_e262 >> bitcast<u32>(2u));
                                        let _e860 = (_e846 + (select(1u, _e852, (1u < _e852)) * select(1u, _e856, (1u < _e856))));
                                        let _e862 = (_e828 > (_e680 * 16f));
                                        let _e866 = (_e254 >> bitcast<u32>(3u));
                                        let _e870 = (_e262 >> bitcast<u32>(3u));
                                        let _e876 = (_e828 > (_e680 * 64f));
                                        let _e878 = select(select(select(select(0u, _e833, _e834), _e846, _e848), _e860, _e862), (_e860 + (select(1u, _e866, (1u < _e866)) * select(1u, _e870, (1u < _e870)))), _e876);
                                        let _e879 = (select(select(select(select(0u, 1u, _e834), 2u, _e848), 3u, _e862), 4u, _e876) & 31u);
                                        let _e881 = (_e254 >> bitcast<u32>(_e879));
                                        let _e883 = select(1u, _e881, (1u < _e881));
                                        let _e885 = (_e262 >> bitcast<u32>(_e879));
                                        let _e887 = select(1u, _e885, (1u < _e885));
                                        let _e890 = (round(_e824) * (1f / _e230.member.member.x));
                                        let _e893 = (round(_e825) * (1f / _e230.member.member.y));
                                        let _e894 = (_e460 + _e890);
                                        let _e895 = (_e463 + _e893);
                                        let _e896 = (_e460 - _e890);
                                        let _e897 = (_e463 - _e893);
                                        let _e899 = f32(bitcast<i32>(_e883));
                                        let _e900 = (_e894 * _e899);
                                        let _e903 = f32(bitcast<i32>((_e883 - 1u)));
                                        let _e913 = f32(bitcast<i32>(_e887));
                                        let _e914 = (_e895 * _e913);
                                        let _e917 = f32(bitcast<i32>((_e887 - 1u)));
                                        let _e931 = mips.member[((_e878 + ((bitcast<u32>((floor(select(0f, select(_e917, _e914, (_e914 < _e917)), (_e914 > 0f))) + 8388608f)) - 1258291200u) * _e883)) + (bitcast<u32>((floor(select(0f, select(_e903, _e900, (_e900 < _e903)), (_e900 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e935 = ((((_e894 * 2f) - 1f) * _e230.member.member_1.x) * _e931);
                                        let _e939 = ((((_e895 * -2f) + 1f) * _e230.member.member_1.y) * _e931);
                                        let _e940 = (_e896 * _e899);
                                        let _e949 = (_e897 * _e913);
                                        let _e963 = mips.member[((_e878 + ((bitcast<u32>((floor(select(0f, select(_e917, _e949, (_e949 < _e917)), (_e949 > 0f))) + 8388608f)) - 1258291200u) * _e883)) + (bitcast<u32>((floor(select(0f, select(_e903, _e940, (_e940 < _e903)), (_e940 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e967 = ((((_e896 * 2f) - 1f) * _e230.member.member_1.x) * _e963);
                                        let _e971 = ((((_e897 * -2f) + 1f) * _e230.member.member_1.y) * _e963);
                                        let _e972 = (_e935 - _e471);
                                        let _e973 = (_e939 - _e478);
                                        let _e974 = (_e931 - _e464);
                                        let _e979 = (((_e972 * _e972) + (_e973 * _e973)) + (_e974 * _e974));
                                        let _e980 = (_e246 <= 0f);
                                        if _e980 {
                                            phi_1544_ = true;
                                        } else {
                                            phi_1544_ = (_e979 <= (_e246 * _e246));
                                        }
                                        let _e984 = phi_1544_;
                                        if _e984 {
                                            phi_1560_ = ((((_e972 * _e551) + (_e973 * _e552)) + (_e974 * _e553)) > (0.018f * sqrt(_e979)));
                                        } else {
                                            phi_1560_ = false;
                                        }
                                        let _e994 = phi_1560_;
                                        if _e994 {
                                            let _e1225 = (0.5f / _e931);
                                            let _e1231 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e1239 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e1244 = frame.member[0u].member_1.member_5[0u];
                                            let _e1247 = frame.member[0u].member_1.member_5[1u];
                                            let _e1248 = f32(_e1244);
                                            let _e1249 = f32(_e1247);
                                            let _e1251 = frame.member[0u].member_1.member_4;
                                            let _e1252 = f32(_e1251);
                                            let _e1253 = (2u * _e1251);
                                            let _e1254 = (_e1244 + _e1253);
                                            let _e1260 = (floor(((((_e935 * _e1225) / _e1231) + 0.5f) * _e1248)) + _e1252);
                                            let _e1261 = f32((_e1254 - 1u));
                                            let _e1265 = select(0f, select(_e1261, _e1260, (_e1260 < _e1261)), (_e1260 > 0f));
                                            let _e1268 = (floor(((0.5f - ((_e939 * _e1225) / _e1239)) * _e1249)) + _e1252);
                                            let _e1269 = f32(((_e1247 + _e1253) - 1u));
                                            let _e1273 = select(0f, select(_e1269, _e1268, (_e1268 < _e1269)), (_e1268 > 0f));
                                            let _e1278 = select(select(u32(_e1265), 0u, (_e1265 < 0f)), 4294967295u, (_e1265 > 4294967000f));
                                            let _e1283 = select(select(u32(_e1273), 0u, (_e1273 < 0f)), 4294967295u, (_e1273 > 4294967000f));
                                            let _e1286 = bitcast<i32>(_e1251);
                                            let _e1292 = frame.member[0u].member_1.member_8;
                                            let _e1294 = frame.member[0u].member_1.member_12;
                                            let _e1301 = (((((_e1283 % 4u) * 4u) + (_e1278 % 4u)) + (_e1294 % 16u)) % 16u);
                                            if (_e1292 == 1u) {
                                                local_6 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                let _e1314 = (_e1301 < 16u);
                                                if _e1314 {
                                                } else {
                                                    phi_7034_ = true;
                                                    break;
                                                }
                                                let _e1317 = local_6[_e1301][0u];
                                                local_7 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                if _e1314 {
                                                } else {
                                                    phi_7034_ = true;
                                                    break;
                                                }
                                                let _e1320 = local_7[_e1301][1u];
                                                phi_1720_ = vec2<f32>(_e1317, _e1320);
                                            } else {
                                                if (_e1292 == 2u) {
                                                    local_8 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    let _e1304 = (_e1301 < 16u);
                                                    if _e1304 {
                                                    } else {
                                                        phi_7034_ = true;
                                                        break;
                                                    }
                                                    let _e1307 = local_8[_e1301][0u];
                                                    local_9 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    if _e1304 {
                                                    } else {
                                                        phi_7034_ = true;
                                                        break;
                                                    }
                                                    let _e1310 = local_9[_e1301][1u];
                                                    phi_1719_ = vec2<f32>(_e1307, _e1310);
                                                } else {
                                                    phi_1719_ = vec2<f32>(0.5f, 0.5f);
                                                }
                                                let _e1313 = phi_1719_;
                                                phi_1720_ = _e1313;
                                            }
                                            let _e1323 = phi_1720_;
                                            let _e1328 = ((f32((bitcast<i32>(_e1278) - _e1286)) + _e1323.x) / _e1248);
                                            let _e1329 = ((f32((bitcast<i32>(_e1283) - _e1286)) + _e1323.y) / _e1249);
                                            let _e1334 = frame.member[0u].member_1.member.member.member[0u];
                                            let _e1339 = select(select(u32(_e1334), 0u, (_e1334 < 0f)), 4294967295u, (_e1334 > 4294967000f));
                                            let _e1344 = frame.member[0u].member_1.member.member.member[1u];
                                            let _e1354 = (select(0f, select(1f, _e1328, (_e1328 < 1f)), (_e1328 > 0f)) * _e1334);
                                            let _e1357 = f32(bitcast<i32>((_e1339 - 1u)));
                                            let _e1370 = (select(0f, select(1f, _e1329, (_e1329 < 1f)), (_e1329 > 0f)) * _e1344);
                                            let _e1373 = f32(bitcast<i32>((select(select(u32(_e1344), 0u, (_e1344 < 0f)), 4294967295u, (_e1344 > 4294967000f)) - 1u)));
                                            let _e1383 = (((bitcast<u32>((floor(select(0f, select(_e1373, _e1370, (_e1370 < _e1373)), (_e1370 > 0f))) + 8388608f)) - 1258291200u) * _e1339) + (bitcast<u32>((floor(select(0f, select(_e1357, _e1354, (_e1354 < _e1357)), (_e1354 > 0f))) + 8388608f)) - 1258291200u));
                                            if (_e1383 < _e190) {
                                            } else {
                                                phi_7034_ = true;
                                                break;
                                            }
                                            let _e1386 = mips.member[_e1383];
                                            if (abs((_e1386 - _e931)) > _e243) {
                                                if (_e246 > 0f) {
                                                    phi_1853_ = (_e979 > (_e246 * _e246));
                                                } else {
                                                    phi_1853_ = false;
                                                }
                                                let _e2132 = phi_1853_;
                                                if !(_e2132) {
                                                    let _e2138 = (((_e972 * _e490) + (_e973 * _e491)) + (_e974 * _e492));
                                                    let _e2142 = (_e972 - (_e490 * _e2138));
                                                    let _e2143 = (_e973 - (_e491 * _e2138));
                                                    let _e2144 = (_e974 - (_e492 * _e2138));
                                                    let _e2147 = ((_e2143 * _e492) - (_e491 * _e2144));
                                                    let _e2150 = ((_e2144 * _e490) - (_e492 * _e2142));
                                                    let _e2153 = ((_e2142 * _e491) - (_e490 * _e2143));
                                                    let _e2164 = ((((_e551 * _e2147) + (_e552 * _e2150)) + (_e553 * _e2153)) / (((_e2147 * _e2147) + (_e2150 * _e2150)) + (_e2153 * _e2153)));
                                                    let _e2168 = (_e551 - (_e2147 * _e2164));
                                                    let _e2169 = (_e552 - (_e2150 * _e2164));
                                                    let _e2170 = (_e553 - (_e2153 * _e2164));
                                                    let _e2176 = inverseSqrt((((_e2168 * _e2168) + (_e2169 * _e2169)) + (_e2170 * _e2170)));
                                                    let _e2182 = ((((_e2168 * _e490) + (_e2169 * _e491)) + (_e2170 * _e492)) * _e2176);
                                                    let _e2186 = select(0f, select(1f, _e2182, (_e2182 < 1f)), (_e2182 > 0f));
                                                    let _e2187 = abs(_e2186);
                                                    let _e2197 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2187, 0.00667009f), _e2187, -0.017088126f), _e2187, 0.03089188f), _e2187, -0.050174303f), _e2187, 0.08897899f), _e2187, -0.2145988f), _e2187, 1.5707963f) * sqrt((1f - _e2187)));
                                                    let _e2200 = select((3.1415927f - _e2197), _e2197, (_e2186 >= 0f));
                                                    let _e2208 = select(_e2200, -(_e2200), ((((_e2142 * _e2168) + (_e2143 * _e2169)) + (_e2144 * _e2170)) < 0f));
                                                    let _e2209 = (_e2176 * 0.02f);
                                                    let _e2212 = select(0.19634955f, _e2209, ((_e2209 < 0.19634955f) || false));
                                                    let _e2222 = (_e972 - (_e490 * _e243));
                                                    let _e2223 = (_e973 - (_e491 * _e243));
                                                    let _e2224 = (_e974 - (_e492 * _e243));
                                                    let _e2226 = (_e2138 * inverseSqrt(_e979));
                                                    let _e2230 = select(-1f, select(1f, _e2226, (_e2226 < 1f)), (_e2226 > -1f));
                                                    let _e2231 = abs(_e2230);
                                                    let _e2241 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2231, 0.00667009f), _e2231, -0.017088126f), _e2231, 0.03089188f), _e2231, -0.050174303f), _e2231, 0.08897899f), _e2231, -0.2145988f), _e2231, 1.5707963f) * sqrt((1f - _e2231)));
                                                    let _e2248 = ((((select((3.1415927f - _e2241), _e2241, (_e2230 >= 0f)) + _e2212) - _e2208) + 1.5707964f) * 0.31830987f);
                                                    let _e2252 = select(0f, select(1f, _e2248, (_e2248 < 1f)), (_e2248 > 0f));
                                                    let _e2264 = ((((_e2222 * _e490) + (_e2223 * _e491)) + (_e2224 * _e492)) * inverseSqrt((((_e2222 * _e2222) + (_e2223 * _e2223)) + (_e2224 * _e2224))));
                                                    let _e2268 = select(-1f, select(1f, _e2264, (_e2264 < 1f)), (_e2264 > -1f));
                                                    let _e2269 = abs(_e2268);
                                                    let _e2279 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2269, 0.00667009f), _e2269, -0.017088126f), _e2269, 0.03089188f), _e2269, -0.050174303f), _e2269, 0.08897899f), _e2269, -0.2145988f), _e2269, 1.5707963f) * sqrt((1f - _e2269)));
                                                    let _e2286 = ((((select((3.1415927f - _e2279), _e2279, (_e2268 >= 0f)) + _e2212) - _e2208) + 1.5707964f) * 0.31830987f);
                                                    let _e2290 = select(0f, select(1f, _e2286, (_e2286 < 1f)), (_e2286 > 0f));
                                                    let _e2292 = (_e2290 != _e2290);
                                                    let _e2294 = select(_e2290, _e2252, ((_e2252 < _e2290) || _e2292));
                                                    let _e2297 = select(_e2290, _e2252, ((_e2252 > _e2290) || _e2292));
                                                    let _e2299 = floor((_e2294 * 32f));
                                                    if (_e240 == 1u) {
                                                        let _e2307 = -(floor((_e2297 * -32f)));
                                                        let _e2312 = (select(32f, _e2307, ((_e2307 < 32f) || false)) - _e2299);
                                                        phi_2169_ = select(select(0f, _e2312, ((_e2312 > 0f) || false)), 0f, (_e2297 <= _e2294));
                                                    } else {
                                                        phi_2169_ = -(floor(((_e2297 - _e2294) * -32f)));
                                                    }
                                                    let _e2318 = phi_2169_;
                                                    let _e2326 = (bitcast<u32>((floor(select(0f, select(32f, _e2299, (_e2299 < 32f)), (_e2299 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2334 = (bitcast<u32>((floor(select(0f, select(32f, _e2318, (_e2318 < 32f)), (_e2318 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2326 >= 32u) {
                                                        phi_2223_ = u32();
                                                        phi_2224_ = true;
                                                    } else {
                                                        let _e2336 = (_e2334 == 0u);
                                                        if _e2336 {
                                                            phi_2222_ = u32();
                                                        } else {
                                                            if (_e2334 >= 32u) {
                                                                phi_2219_ = 4294967295u;
                                                            } else {
                                                                phi_2219_ = ((1u << bitcast<u32>((_e2334 & 31u))) - 1u);
                                                            }
                                                            let _e2343 = phi_2219_;
                                                            phi_2222_ = (_e2343 << bitcast<u32>((_e2326 & 31u)));
                                                        }
                                                        let _e2348 = phi_2222_;
                                                        phi_2223_ = _e2348;
                                                        phi_2224_ = _e2336;
                                                    }
                                                    let _e2350 = phi_2223_;
                                                    let _e2352 = phi_2224_;
                                                    phi_2237_ = select(select(select(_e2350, 0u, _e2352), 0u, ((((_e2142 * _e2142) + (_e2143 * _e2143)) + (_e2144 * _e2144)) <= 0f)), 0u, _e2132);
                                                } else {
                                                    phi_2237_ = 0u;
                                                }
                                                let _e2357 = phi_2237_;
                                                phi_6862_ = _e793;
                                                phi_3499_ = _e2357;
                                                phi_3500_ = u32();
                                                phi_3501_ = true;
                                            } else {
                                                local_10 = array<f32, 8>(0f, 0f, 0f, 0f, 0f, 0f, 0f, 0f);
                                                let _e1393 = frame.member[0u].member_1.member_6;
                                                phi_6657_ = _e793;
                                                phi_2255_ = 0u;
                                                phi_2258_ = 0u;
                                                loop {
                                                    let _e1396 = phi_6657_;
                                                    let _e1398 = phi_2255_;
                                                    let _e1400 = phi_2258_;
                                                    local_13 = _e1400;
                                                    local_14 = _e1400;
                                                    local_15 = _e1400;
                                                    let _e1401 = (_e1398 < _e1393);
                                                    if _e1401 {
                                                        let _e1402 = ((((_e1283 * _e1254) + _e1278) * _e1393) + _e1398);
                                                        if (_e1402 < _e193) {
                                                        } else {
                                                            phi_6773_ = true;
                                                            break;
                                                        }
                                                        let _e1405 = sd_map.member[_e1402];
                                                        let _e1409 = frame.member[0u].member_1.member.member.member_3;
                                                        let _e1413 = frame.member[0u].member_1.member.member.member_2;
                                                        let _e1416 = ((_e1405 * (_e1409 - _e1413)) + _e1413);
                                                        if (_e1405 < 1f) {
                                                            if (_e1416 > (_e931 * 1.001f)) {
                                                                phi_2298_ = _e1400;
                                                                loop {
                                                                    let _e1421 = phi_2298_;
                                                                    local_11 = _e1421;
                                                                    local_12 = _e1421;
                                                                    if (_e1421 > 0u) {
                                                                        let _e1423 = (_e1421 - 1u);
                                                                        let _e1424 = (_e1423 < 8u);
                                                                        if _e1424 {
                                                                        } else {
                                                                            phi_6653_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1426 = local_10[_e1423];
                                                                        let _e1427 = (_e1426 > _e1416);
                                                                        if _e1427 {
                                                                            if _e1424 {
                                                                            } else {
                                                                                phi_6653_ = true;
                                                                                break;
                                                                            }
                                                                            let _e1428 = local_10[_e1423];
                                                                            if (_e1421 < 8u) {
                                                                            } else {
                                                                                phi_6653_ = true;
                                                                                break;
                                                                            }
                                                                            local_10[_e1421] = _e1428;
                                                                        }
                                                                        phi_2299_ = select(u32(), _e1423, _e1427);
                                                                        phi_2335_ = _e1427;
                                                                    } else {
                                                                        phi_2299_ = u32();
                                                                        phi_2335_ = false;
                                                                    }
                                                                    let _e1433 = phi_2299_;
                                                                    let _e1435 = phi_2335_;
                                                                    continue;
                                                                    continuing {
                                                                        phi_2298_ = _e1433;
                                                                        phi_6653_ = _e1396;
                                                                        break if !(_e1435);
                                                                    }
                                                                }
                                                                let _e1438 = phi_6653_;
                                                                phi_6773_ = _e1438;
                                                                if _e1438 {
                                                                    break;
                                                                }
                                                                let _e1440 = local_11;
                                                                if (_e1440 < 8u) {
                                                                } else {
                                                                    phi_6773_ = true;
                                                                    break;
                                                                }
                                                                let _e1443 = local_12;
                                                                local_10[_e1443] = _e1416;
                                                                phi_6776_ = _e1438;
                                                                phi_2347_ = (_e1400 + 1u);
                                                            } else {
                                                                phi_6776_ = _e1396;
                                                                phi_2347_ = _e1400;
                                                            }
                                                            let _e1447 = phi_6776_;
                                                            let _e1449 = phi_2347_;
                                                            phi_6775_ = _e1447;
                                                            phi_2348_ = _e1449;
                                                        } else {
                                                            phi_6775_ = _e1396;
                                                            phi_2348_ = _e1400;
                                                        }
                                                        let _e1451 = phi_6775_;
                                                        let _e1453 = phi_2348_;
                                                        phi_6774_ = _e1451;
                                                        phi_2256_ = (_e1398 + 1u);
                                                        phi_2259_ = _e1453;
                                                    } else {
                                                        phi_6774_ = _e1396;
                                                        phi_2256_ = u32();
                                                        phi_2259_ = u32();
                                                    }
                                                    let _e1456 = phi_6774_;
                                                    let _e1458 = phi_2256_;
                                                    let _e1460 = phi_2259_;
                                                    continue;
                                                    continuing {
                                                        phi_6657_ = _e1456;
                                                        phi_2255_ = _e1458;
                                                        phi_2258_ = _e1460;
                                                        phi_6773_ = _e1456;
                                                        break if !(_e1401);
                                                    }
                                                }
                                                let _e1463 = phi_6773_;
                                                phi_7034_ = _e1463;
                                                if _e1463 {
                                                    break;
                                                }
                                                let _e1465 = local_13;
                                                let _e1466 = (_e1465 == 0u);
                                                if _e1466 {
                                                    if (_e246 > 0f) {
                                                        phi_2365_ = (_e979 > (_e246 * _e246));
                                                    } else {
                                                        phi_2365_ = false;
                                                    }
                                                    let _e1896 = phi_2365_;
                                                    if !(_e1896) {
                                                        let _e1902 = (((_e972 * _e490) + (_e973 * _e491)) + (_e974 * _e492));
                                                        let _e1906 = (_e972 - (_e490 * _e1902));
                                                        let _e1907 = (_e973 - (_e491 * _e1902));
                                                        let _e1908 = (_e974 - (_e492 * _e1902));
                                                        let _e1911 = ((_e1907 * _e492) - (_e491 * _e1908));
                                                        let _e1914 = ((_e1908 * _e490) - (_e492 * _e1906));
                                                        let _e1917 = ((_e1906 * _e491) - (_e490 * _e1907));
                                                        let _e1928 = ((((_e551 * _e1911) + (_e552 * _e1914)) + (_e553 * _e1917)) / (((_e1911 * _e1911) + (_e1914 * _e1914)) + (_e1917 * _e1917)));
                                                        let _e1932 = (_e551 - (_e1911 * _e1928));
                                                        let _e1933 = (_e552 - (_e1914 * _e1928));
                                                        let _e1934 = (_e553 - (_e1917 * _e1928));
                                                        let _e1940 = inverseSqrt((((_e1932 * _e1932) + (_e1933 * _e1933)) + (_e1934 * _e1934)));
                                                        let _e1946 = ((((_e1932 * _e490) + (_e1933 * _e491)) + (_e1934 * _e492)) * _e1940);
                                                        let _e1950 = select(0f, select(1f, _e1946, (_e1946 < 1f)), (_e1946 > 0f));
                                                        let _e1951 = abs(_e1950);
                                                        let _e1961 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1951, 0.00667009f), _e1951, -0.017088126f), _e1951, 0.03089188f), _e1951, -0.050174303f), _e1951, 0.08897899f), _e1951, -0.2145988f), _e1951, 1.5707963f) * sqrt((1f - _e1951)));
                                                        let _e1964 = select((3.1415927f - _e1961), _e1961, (_e1950 >= 0f));
                                                        let _e1972 = select(_e1964, -(_e1964), ((((_e1906 * _e1932) + (_e1907 * _e1933)) + (_e1908 * _e1934)) < 0f));
                                                        let _e1973 = (_e1940 * 0.02f);
                                                        let _e1976 = select(0.19634955f, _e1973, ((_e1973 < 0.19634955f) || false));
                                                        let _e1986 = (_e972 - (_e490 * _e243));
                                                        let _e1987 = (_e973 - (_e491 * _e243));
                                                        let _e1988 = (_e974 - (_e492 * _e243));
                                                        let _e1990 = (_e1902 * inverseSqrt(_e979));
                                                        let _e1994 = select(-1f, select(1f, _e1990, (_e1990 < 1f)), (_e1990 > -1f));
                                                        let _e1995 = abs(_e1994);
                                                        let _e2005 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1995, 0.00667009f), _e1995, -0.017088126f), _e1995, 0.03089188f), _e1995, -0.050174303f), _e1995, 0.08897899f), _e1995, -0.2145988f), _e1995, 1.5707963f) * sqrt((1f - _e1995)));
                                                        let _e2012 = ((((select((3.1415927f - _e2005), _e2005, (_e1994 >= 0f)) + _e1976) - _e1972) + 1.5707964f) * 0.31830987f);
                                                        let _e2016 = select(0f, select(1f, _e2012, (_e2012 < 1f)), (_e2012 > 0f));
                                                        let _e2028 = ((((_e1986 * _e490) + (_e1987 * _e491)) + (_e1988 * _e492)) * inverseSqrt((((_e1986 * _e1986) + (_e1987 * _e1987)) + (_e1988 * _e1988))));
                                                        let _e2032 = select(-1f, select(1f, _e2028, (_e2028 < 1f)), (_e2028 > -1f));
                                                        let _e2033 = abs(_e2032);
                                                        let _e2043 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2033, 0.00667009f), _e2033, -0.017088126f), _e2033, 0.03089188f), _e2033, -0.050174303f), _e2033, 0.08897899f), _e2033, -0.2145988f), _e2033, 1.5707963f) * sqrt((1f - _e2033)));
                                                        let _e2050 = ((((select((3.1415927f - _e2043), _e2043, (_e2032 >= 0f)) + _e1976) - _e1972) + 1.5707964f) * 0.31830987f);
                                                        let _e2054 = select(0f, select(1f, _e2050, (_e2050 < 1f)), (_e2050 > 0f));
                                                        let _e2056 = (_e2054 != _e2054);
                                                        let _e2058 = select(_e2054, _e2016, ((_e2016 < _e2054) || _e2056));
                                                        let _e2061 = select(_e2054, _e2016, ((_e2016 > _e2054) || _e2056));
                                                        let _e2063 = floor((_e2058 * 32f));
                                                        if (_e240 == 1u) {
                                                            let _e2071 = -(floor((_e2061 * -32f)));
                                                            let _e2076 = (select(32f, _e2071, ((_e2071 < 32f) || false)) - _e2063);
                                                            phi_2681_ = select(select(0f, _e2076, ((_e2076 > 0f) || false)), 0f, (_e2061 <= _e2058));
                                                        } else {
                                                            phi_2681_ = -(floor(((_e2061 - _e2058) * -32f)));
                                                        }
                                                        let _e2082 = phi_2681_;
                                                        let _e2090 = (bitcast<u32>((floor(select(0f, select(32f, _e2063, (_e2063 < 32f)), (_e2063 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e2098 = (bitcast<u32>((floor(select(0f, select(32f, _e2082, (_e2082 < 32f)), (_e2082 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e2090 >= 32u) {
                                                            phi_2735_ = u32();
                                                            phi_2736_ = true;
                                                        } else {
                                                            let _e2100 = (_e2098 == 0u);
                                                            if _e2100 {
                                                                phi_2734_ = u32();
                                                            } else {
                                                                if (_e2098 >= 32u) {
                                                                    phi_2731_ = 4294967295u;
                                                                } else {
                                                                    phi_2731_ = ((1u << bitcast<u32>((_e2098 & 31u))) - 1u);
                                                                }
                                                                let _e2107 = phi_2731_;
                                                                phi_2734_ = (_e2107 << bitcast<u32>((_e2090 & 31u)));
                                                            }
                                                            let _e2112 = phi_2734_;
                                                            phi_2735_ = _e2112;
                                                            phi_2736_ = _e2100;
                                                        }
                                                        let _e2114 = phi_2735_;
                                                        let _e2116 = phi_2736_;
                                                        phi_2749_ = select(select(select(_e2114, 0u, _e2116), 0u, ((((_e1906 * _e1906) + (_e1907 * _e1907)) + (_e1908 * _e1908)) <= 0f)), 0u, _e1896);
                                                    } else {
                                                        phi_2749_ = 0u;
                                                    }
                                                    let _e2121 = phi_2749_;
                                                    phi_6897_ = _e1463;
                                                    phi_3497_ = _e2121;
                                                    phi_3498_ = u32();
                                                } else {
                                                    let _e1471 = (((_e972 * _e490) + (_e973 * _e491)) + (_e974 * _e492));
                                                    let _e1475 = (_e972 - (_e490 * _e1471));
                                                    let _e1476 = (_e973 - (_e491 * _e1471));
                                                    let _e1477 = (_e974 - (_e492 * _e1471));
                                                    let _e1480 = ((_e1476 * _e492) - (_e491 * _e1477));
                                                    let _e1483 = ((_e1477 * _e490) - (_e492 * _e1475));
                                                    let _e1486 = ((_e1475 * _e491) - (_e490 * _e1476));
                                                    let _e1497 = ((((_e551 * _e1480) + (_e552 * _e1483)) + (_e553 * _e1486)) / (((_e1480 * _e1480) + (_e1483 * _e1483)) + (_e1486 * _e1486)));
                                                    let _e1501 = (_e551 - (_e1480 * _e1497));
                                                    let _e1502 = (_e552 - (_e1483 * _e1497));
                                                    let _e1503 = (_e553 - (_e1486 * _e1497));
                                                    let _e1509 = inverseSqrt((((_e1501 * _e1501) + (_e1502 * _e1502)) + (_e1503 * _e1503)));
                                                    let _e1515 = ((((_e1501 * _e490) + (_e1502 * _e491)) + (_e1503 * _e492)) * _e1509);
                                                    let _e1519 = select(0f, select(1f, _e1515, (_e1515 < 1f)), (_e1515 > 0f));
                                                    let _e1520 = abs(_e1519);
                                                    let _e1530 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1520, 0.00667009f), _e1520, -0.017088126f), _e1520, 0.03089188f), _e1520, -0.050174303f), _e1520, 0.08897899f), _e1520, -0.2145988f), _e1520, 1.5707963f) * sqrt((1f - _e1520)));
                                                    let _e1533 = select((3.1415927f - _e1530), _e1530, (_e1519 >= 0f));
                                                    let _e1541 = select(_e1533, -(_e1533), ((((_e1475 * _e1501) + (_e1476 * _e1502)) + (_e1477 * _e1503)) < 0f));
                                                    let _e1542 = (_e1509 * 0.02f);
                                                    let _e1545 = select(0.19634955f, _e1542, ((_e1542 < 0.19634955f) || false));
                                                    let _e1551 = ((((_e1475 * _e1475) + (_e1476 * _e1476)) + (_e1477 * _e1477)) <= 0f);
                                                    let _e1553 = local_10[0u];
                                                    let _e1556 = (((_e1328 * 2f) - 1f) * _e1231);
                                                    let _e1560 = (((_e1329 * -2f) + 1f) * _e1239);
                                                    let _e1562 = ((_e1556 * _e1553) - _e471);
                                                    let _e1563 = ((_e1560 * _e1553) - _e478);
                                                    let _e1564 = (_e1553 - _e464);
                                                    let _e1566 = (_e1471 * inverseSqrt(_e979));
                                                    let _e1570 = select(-1f, select(1f, _e1566, (_e1566 < 1f)), (_e1566 > -1f));
                                                    let _e1571 = abs(_e1570);
                                                    let _e1581 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1571, 0.00667009f), _e1571, -0.017088126f), _e1571, 0.03089188f), _e1571, -0.050174303f), _e1571, 0.08897899f), _e1571, -0.2145988f), _e1571, 1.5707963f) * sqrt((1f - _e1571)));
                                                    let _e1588 = ((((select((3.1415927f - _e1581), _e1581, (_e1570 >= 0f)) + _e1545) - _e1541) + 1.5707964f) * 0.31830987f);
                                                    let _e1592 = select(0f, select(1f, _e1588, (_e1588 < 1f)), (_e1588 > 0f));
                                                    let _e1604 = ((((_e1562 * _e490) + (_e1563 * _e491)) + (_e1564 * _e492)) * inverseSqrt((((_e1562 * _e1562) + (_e1563 * _e1563)) + (_e1564 * _e1564))));
                                                    let _e1608 = select(-1f, select(1f, _e1604, (_e1604 < 1f)), (_e1604 > -1f));
                                                    let _e1609 = abs(_e1608);
                                                    let _e1619 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1609, 0.00667009f), _e1609, -0.017088126f), _e1609, 0.03089188f), _e1609, -0.050174303f), _e1609, 0.08897899f), _e1609, -0.2145988f), _e1609, 1.5707963f) * sqrt((1f - _e1609)));
                                                    let _e1626 = ((((select((3.1415927f - _e1619), _e1619, (_e1608 >= 0f)) + _e1545) - _e1541) + 1.5707964f) * 0.31830987f);
                                                    let _e1630 = select(0f, select(1f, _e1626, (_e1626 < 1f)), (_e1626 > 0f));
                                                    let _e1632 = (_e1630 != _e1630);
                                                    let _e1634 = select(_e1630, _e1592, ((_e1592 < _e1630) || _e1632));
                                                    let _e1637 = select(_e1630, _e1592, ((_e1592 > _e1630) || _e1632));
                                                    let _e1639 = floor((_e1634 * 32f));
                                                    let _e1640 = (_e240 == 1u);
                                                    if _e1640 {
                                                        let _e1647 = -(floor((_e1637 * -32f)));
                                                        let _e1652 = (select(32f, _e1647, ((_e1647 < 32f) || false)) - _e1639);
                                                        phi_3078_ = select(select(0f, _e1652, ((_e1652 > 0f) || false)), 0f, (_e1637 <= _e1634));
                                                    } else {
                                                        phi_3078_ = -(floor(((_e1637 - _e1634) * -32f)));
                                                    }
                                                    let _e1658 = phi_3078_;
                                                    let _e1666 = (bitcast<u32>((floor(select(0f, select(32f, _e1639, (_e1639 < 32f)), (_e1639 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1674 = (bitcast<u32>((floor(select(0f, select(32f, _e1658, (_e1658 < 32f)), (_e1658 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1666 >= 32u) {
                                                        phi_3132_ = u32();
                                                        phi_3133_ = true;
                                                    } else {
                                                        let _e1676 = (_e1674 == 0u);
                                                        if _e1676 {
                                                            phi_3131_ = u32();
                                                        } else {
                                                            if (_e1674 >= 32u) {
                                                                phi_3128_ = 4294967295u;
                                                            } else {
                                                                phi_3128_ = ((1u << bitcast<u32>((_e1674 & 31u))) - 1u);
                                                            }
                                                            let _e1683 = phi_3128_;
                                                            phi_3131_ = (_e1683 << bitcast<u32>((_e1666 & 31u)));
                                                        }
                                                        let _e1688 = phi_3131_;
                                                        phi_3132_ = _e1688;
                                                        phi_3133_ = _e1676;
                                                    }
                                                    let _e1690 = phi_3132_;
                                                    let _e1692 = phi_3133_;
                                                    phi_3143_ = 1u;
                                                    phi_3146_ = select(select(_e1690, 0u, _e1692), 0u, _e1551);
                                                    loop {
                                                        let _e1696 = phi_3143_;
                                                        let _e1698 = phi_3146_;
                                                        local_29 = _e1698;
                                                        let _e1700 = local_14;
                                                        let _e1701 = (_e1696 < _e1700);
                                                        if _e1701 {
                                                            if (_e1696 < 8u) {
                                                            } else {
                                                                phi_6777_ = true;
                                                                break;
                                                            }
                                                            let _e1704 = local_10[_e1696];
                                                            let _e1707 = ((_e1556 * _e1704) - _e471);
                                                            let _e1708 = ((_e1560 * _e1704) - _e478);
                                                            let _e1709 = (_e1704 - _e464);
                                                            let _e1710 = (_e1696 + 1u);
                                                            let _e1712 = local_15;
                                                            if (_e1710 < _e1712) {
                                                                if (_e1710 < 8u) {
                                                                } else {
                                                                    phi_6777_ = true;
                                                                    break;
                                                                }
                                                                let _e1723 = local_10[_e1710];
                                                                phi_3225_ = (vec3<f32>((_e1556 * _e1723), (_e1560 * _e1723), _e1723) - _e479);
                                                            } else {
                                                                phi_3225_ = vec3<f32>((_e1707 - (_e490 * _e243)), (_e1708 - (_e491 * _e243)), (_e1709 - (_e492 * _e243)));
                                                            }
                                                            let _e1729 = phi_3225_;
                                                            if _e980 {
                                                                phi_3240_ = true;
                                                            } else {
                                                                phi_3240_ = ((((_e1707 * _e1707) + (_e1708 * _e1708)) + (_e1709 * _e1709)) <= (_e246 * _e246));
                                                            }
                                                            let _e1738 = phi_3240_;
                                                            if _e1738 {
                                                                let _e1750 = ((((_e1707 * _e490) + (_e1708 * _e491)) + (_e1709 * _e492)) * inverseSqrt((((_e1707 * _e1707) + (_e1708 * _e1708)) + (_e1709 * _e1709))));
                                                                let _e1754 = select(-1f, select(1f, _e1750, (_e1750 < 1f)), (_e1750 > -1f));
                                                                let _e1755 = abs(_e1754);
                                                                let _e1765 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1755, 0.00667009f), _e1755, -0.017088126f), _e1755, 0.03089188f), _e1755, -0.050174303f), _e1755, 0.08897899f), _e1755, -0.2145988f), _e1755, 1.5707963f) * sqrt((1f - _e1755)));
                                                                let _e1772 = ((((select((3.1415927f - _e1765), _e1765, (_e1754 >= 0f)) + _e1545) - _e1541) + 1.5707964f) * 0.31830987f);
                                                                let _e1776 = select(0f, select(1f, _e1772, (_e1772 < 1f)), (_e1772 > 0f));
                                                                let _e1791 = ((((_e1729.x * _e490) + (_e1729.y * _e491)) + (_e1729.z * _e492)) * inverseSqrt((((_e1729.x * _e1729.x) + (_e1729.y * _e1729.y)) + (_e1729.z * _e1729.z))));
                                                                let _e1795 = select(-1f, select(1f, _e1791, (_e1791 < 1f)), (_e1791 > -1f));
                                                                let _e1796 = abs(_e1795);
                                                                let _e1806 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1796, 0.00667009f), _e1796, -0.017088126f), _e1796, 0.03089188f), _e1796, -0.050174303f), _e1796, 0.08897899f), _e1796, -0.2145988f), _e1796, 1.5707963f) * sqrt((1f - _e1796)));
                                                                let _e1813 = ((((select((3.1415927f - _e1806), _e1806, (_e1795 >= 0f)) + _e1545) - _e1541) + 1.5707964f) * 0.31830987f);
                                                                let _e1817 = select(0f, select(1f, _e1813, (_e1813 < 1f)), (_e1813 > 0f));
                                                                let _e1819 = (_e1817 != _e1817);
                                                                let _e1821 = select(_e1817, _e1776, ((_e1776 < _e1817) || _e1819));
                                                                let _e1824 = select(_e1817, _e1776, ((_e1776 > _e1817) || _e1819));
                                                                let _e1826 = floor((_e1821 * 32f));
                                                                if _e1640 {
                                                                    let _e1833 = -(floor((_e1824 * -32f)));
                                                                    let _e1838 = (select(32f, _e1833, ((_e1833 < 32f) || false)) - _e1826);
                                                                    phi_3430_ = select(select(0f, _e1838, ((_e1838 > 0f) || false)), 0f, (_e1824 <= _e1821));
                                                                } else {
                                                                    phi_3430_ = -(floor(((_e1824 - _e1821) * -32f)));
                                                                }
                                                                let _e1844 = phi_3430_;
                                                                let _e1852 = (bitcast<u32>((floor(select(0f, select(32f, _e1826, (_e1826 < 32f)), (_e1826 > 0f))) + 8388608f)) - 1258291200u);
                                                                let _e1860 = (bitcast<u32>((floor(select(0f, select(32f, _e1844, (_e1844 < 32f)), (_e1844 > 0f))) + 8388608f)) - 1258291200u);
                                                                if (_e1852 >= 32u) {
                                                                    phi_3484_ = u32();
                                                                    phi_3485_ = true;
                                                                } else {
                                                                    let _e1862 = (_e1860 == 0u);
                                                                    if _e1862 {
                                                                        phi_3483_ = u32();
                                                                    } else {
                                                                        if (_e1860 >= 32u) {
                                                                            phi_3480_ = 4294967295u;
                                                                        } else {
                                                                            phi_3480_ = ((1u << bitcast<u32>((_e1860 & 31u))) - 1u);
                                                                        }
                                                                        let _e1869 = phi_3480_;
                                                                        phi_3483_ = (_e1869 << bitcast<u32>((_e1852 & 31u)));
                                                                    }
                                                                    let _e1874 = phi_3483_;
                                                                    phi_3484_ = _e1874;
                                                                    phi_3485_ = _e1862;
                                                                }
                                                                let _e1876 = phi_3484_;
                                                                let _e1878 = phi_3485_;
                                                                phi_3495_ = (_e1698 | select(select(_e1876, 0u, _e1878), 0u, _e1551));
                                                            } else {
                                                                phi_3495_ = _e1698;
                                                            }
                                                            let _e1883 = phi_3495_;
                                                            phi_3144_ = (_e1696 + 2u);
                                                            phi_3147_ = _e1883;
                                                        } else {
                                                            phi_3144_ = u32();
                                                            phi_3147_ = u32();
                                                        }
                                                        let _e1886 = phi_3144_;
                                                        let _e1888 = phi_3147_;
                                                        continue;
                                                        continuing {
                                                            phi_3143_ = _e1886;
                                                            phi_3146_ = _e1888;
                                                            phi_6777_ = _e1463;
                                                            break if !(_e1701);
                                                        }
                                                    }
                                                    let _e1891 = phi_6777_;
                                                    phi_7034_ = _e1891;
                                                    if _e1891 {
                                                        break;
                                                    }
                                                    phi_6897_ = _e1891;
                                                    phi_3497_ = u32();
                                                    let _e4034 = local_29;
                                                    phi_3498_ = _e4034;
                                                }
                                                let _e2123 = phi_6897_;
                                                let _e2125 = phi_3497_;
                                                let _e2127 = phi_3498_;
                                                phi_6862_ = _e2123;
                                                phi_3499_ = _e2125;
                                                phi_3500_ = _e2127;
                                                phi_3501_ = _e1466;
                                            }
                                            let _e2359 = phi_6862_;
                                            let _e2361 = phi_3499_;
                                            let _e2363 = phi_3500_;
                                            let _e2365 = phi_3501_;
                                            phi_6860_ = _e2359;
                                            phi_3902_ = select(_e2363, _e2361, _e2365);
                                        } else {
                                            if (_e246 > 0f) {
                                                phi_3517_ = (_e979 > (_e246 * _e246));
                                            } else {
                                                phi_3517_ = false;
                                            }
                                            let _e999 = phi_3517_;
                                            if !(_e999) {
                                                let _e1005 = (((_e972 * _e490) + (_e973 * _e491)) + (_e974 * _e492));
                                                let _e1009 = (_e972 - (_e490 * _e1005));
                                                let _e1010 = (_e973 - (_e491 * _e1005));
                                                let _e1011 = (_e974 - (_e492 * _e1005));
                                                let _e1014 = ((_e1010 * _e492) - (_e491 * _e1011));
                                                let _e1017 = ((_e1011 * _e490) - (_e492 * _e1009));
                                                let _e1020 = ((_e1009 * _e491) - (_e490 * _e1010));
                                                let _e1031 = ((((_e551 * _e1014) + (_e552 * _e1017)) + (_e553 * _e1020)) / (((_e1014 * _e1014) + (_e1017 * _e1017)) + (_e1020 * _e1020)));
                                                let _e1035 = (_e551 - (_e1014 * _e1031));
                                                let _e1036 = (_e552 - (_e1017 * _e1031));
                                                let _e1037 = (_e553 - (_e1020 * _e1031));
                                                let _e1043 = inverseSqrt((((_e1035 * _e1035) + (_e1036 * _e1036)) + (_e1037 * _e1037)));
                                                let _e1049 = ((((_e1035 * _e490) + (_e1036 * _e491)) + (_e1037 * _e492)) * _e1043);
                                                let _e1053 = select(0f, select(1f, _e1049, (_e1049 < 1f)), (_e1049 > 0f));
                                                let _e1054 = abs(_e1053);
                                                let _e1064 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1054, 0.00667009f), _e1054, -0.017088126f), _e1054, 0.03089188f), _e1054, -0.050174303f), _e1054, 0.08897899f), _e1054, -0.2145988f), _e1054, 1.5707963f) * sqrt((1f - _e1054)));
                                                let _e1067 = select((3.1415927f - _e1064), _e1064, (_e1053 >= 0f));
                                                let _e1075 = select(_e1067, -(_e1067), ((((_e1009 * _e1035) + (_e1010 * _e1036)) + (_e1011 * _e1037)) < 0f));
                                                let _e1076 = (_e1043 * 0.02f);
                                                let _e1079 = select(0.19634955f, _e1076, ((_e1076 < 0.19634955f) || false));
                                                let _e1089 = (_e972 - (_e490 * _e243));
                                                let _e1090 = (_e973 - (_e491 * _e243));
                                                let _e1091 = (_e974 - (_e492 * _e243));
                                                let _e1093 = (_e1005 * inverseSqrt(_e979));
                                                let _e1097 = select(-1f, select(1f, _e1093, (_e1093 < 1f)), (_e1093 > -1f));
                                                let _e1098 = abs(_e1097);
                                                let _e1108 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1098, 0.00667009f), _e1098, -0.017088126f), _e1098, 0.03089188f), _e1098, -0.050174303f), _e1098, 0.08897899f), _e1098, -0.2145988f), _e1098, 1.5707963f) * sqrt((1f - _e1098)));
                                                let _e1115 = ((((select((3.1415927f - _e1108), _e1108, (_e1097 >= 0f)) + _e1079) - _e1075) + 1.5707964f) * 0.31830987f);
                                                let _e1119 = select(0f, select(1f, _e1115, (_e1115 < 1f)), (_e1115 > 0f));
                                                let _e1131 = ((((_e1089 * _e490) + (_e1090 * _e491)) + (_e1091 * _e492)) * inverseSqrt((((_e1089 * _e1089) + (_e1090 * _e1090)) + (_e1091 * _e1091))));
                                                let _e1135 = select(-1f, select(1f, _e1131, (_e1131 < 1f)), (_e1131 > -1f));
                                                let _e1136 = abs(_e1135);
                                                let _e1146 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1136, 0.00667009f), _e1136, -0.017088126f), _e1136, 0.03089188f), _e1136, -0.050174303f), _e1136, 0.08897899f), _e1136, -0.2145988f), _e1136, 1.5707963f) * sqrt((1f - _e1136)));
                                                let _e1153 = ((((select((3.1415927f - _e1146), _e1146, (_e1135 >= 0f)) + _e1079) - _e1075) + 1.5707964f) * 0.31830987f);
                                                let _e1157 = select(0f, select(1f, _e1153, (_e1153 < 1f)), (_e1153 > 0f));
                                                let _e1159 = (_e1157 != _e1157);
                                                let _e1161 = select(_e1157, _e1119, ((_e1119 < _e1157) || _e1159));
                                                let _e1164 = select(_e1157, _e1119, ((_e1119 > _e1157) || _e1159));
                                                let _e1166 = floor((_e1161 * 32f));
                                                if (_e240 == 1u) {
                                                    let _e1174 = -(floor((_e1164 * -32f)));
                                                    let _e1179 = (select(32f, _e1174, ((_e1174 < 32f) || false)) - _e1166);
                                                    phi_3833_ = select(select(0f, _e1179, ((_e1179 > 0f) || false)), 0f, (_e1164 <= _e1161));
                                                } else {
                                                    phi_3833_ = -(floor(((_e1164 - _e1161) * -32f)));
                                                }
                                                let _e1185 = phi_3833_;
                                                let _e1193 = (bitcast<u32>((floor(select(0f, select(32f, _e1166, (_e1166 < 32f)), (_e1166 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e1201 = (bitcast<u32>((floor(select(0f, select(32f, _e1185, (_e1185 < 32f)), (_e1185 > 0f))) + 8388608f)) - 1258291200u);
                                                if (_e1193 >= 32u) {
                                                    phi_3887_ = u32();
                                                    phi_3888_ = true;
                                                } else {
                                                    let _e1203 = (_e1201 == 0u);
                                                    if _e1203 {
                                                        phi_3886_ = u32();
                                                    } else {
                                                        if (_e1201 >= 32u) {
                                                            phi_3883_ = 4294967295u;
                                                        } else {
                                                            phi_3883_ = ((1u << bitcast<u32>((_e1201 & 31u))) - 1u);
                                                        }
                                                        let _e1210 = phi_3883_;
                                                        phi_3886_ = (_e1210 << bitcast<u32>((_e1193 & 31u)));
                                                    }
                                                    let _e1215 = phi_3886_;
                                                    phi_3887_ = _e1215;
                                                    phi_3888_ = _e1203;
                                                }
                                                let _e1217 = phi_3887_;
                                                let _e1219 = phi_3888_;
                                                phi_3901_ = select(select(select(_e1217, 0u, _e1219), 0u, ((((_e1009 * _e1009) + (_e1010 * _e1010)) + (_e1011 * _e1011)) <= 0f)), 0u, _e999);
                                            } else {
                                                phi_3901_ = 0u;
                                            }
                                            let _e1224 = phi_3901_;
                                            phi_6860_ = _e793;
                                            phi_3902_ = _e1224;
                                        }
                                        let _e2368 = phi_6860_;
                                        let _e2370 = phi_3902_;
                                        let _e2372 = (_e967 - _e471);
                                        let _e2373 = (_e971 - _e478);
                                        let _e2374 = (_e963 - _e464);
                                        let _e2379 = (((_e2372 * _e2372) + (_e2373 * _e2373)) + (_e2374 * _e2374));
                                        if _e980 {
                                            phi_3925_ = true;
                                        } else {
                                            phi_3925_ = (_e2379 <= (_e246 * _e246));
                                        }
                                        let _e2383 = phi_3925_;
                                        if _e2383 {
                                            phi_3941_ = ((((_e2372 * _e551) + (_e2373 * _e552)) + (_e2374 * _e553)) > (0.018f * sqrt(_e2379)));
                                        } else {
                                            phi_3941_ = false;
                                        }
                                        let _e2393 = phi_3941_;
                                        if _e2393 {
                                            let _e2626 = (0.5f / _e963);
                                            let _e2632 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e2640 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e2645 = frame.member[0u].member_1.member_5[0u];
                                            let _e2648 = frame.member[0u].member_1.member_5[1u];
                                            let _e2649 = f32(_e2645);
                                            let _e2650 = f32(_e2648);
                                            let _e2652 = frame.member[0u].member_1.member_4;
                                            let _e2653 = f32(_e2652);
                                            let _e2654 = (2u * _e2652);
                                            let _e2655 = (_e2645 + _e2654);
                                            let _e2661 = (floor(((((_e967 * _e2626) / _e2632) + 0.5f) * _e2649)) + _e2653);
                                            let _e2662 = f32((_e2655 - 1u));
                                            let _e2666 = select(0f, select(_e2662, _e2661, (_e2661 < _e2662)), (_e2661 > 0f));
                                            let _e2669 = (floor(((0.5f - ((_e971 * _e2626) / _e2640)) * _e2650)) + _e2653);
                                            let _e2670 = f32(((_e2648 + _e2654) - 1u));
                                            let _e2674 = select(0f, select(_e2670, _e2669, (_e2669 < _e2670)), (_e2669 > 0f));
                                            let _e2679 = select(select(u32(_e2666), 0u, (_e2666 < 0f)), 4294967295u, (_e2666 > 4294967000f));
                                            let _e2684 = select(select(u32(_e2674), 0u, (_e2674 < 0f)), 4294967295u, (_e2674 > 4294967000f));
                                            let _e2687 = bitcast<i32>(_e2652);
                                            let _e2693 = frame.member[0u].member_1.member_8;
                                            let _e2695 = frame.member[0u].member_1.member_12;
                                            let _e2702 = (((((_e2684 % 4u) * 4u) + (_e2679 % 4u)) + (_e2695 % 16u)) % 16u);
                                            if (_e2693 == 1u) {
                                                local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                let _e2715 = (_e2702 < 16u);
                                                if _e2715 {
                                                } else {
                                                    phi_7034_ = true;
                                                    break;
                                                }
                                                let _e2718 = local_1[_e2702][0u];
                                                local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                if _e2715 {
                                                } else {
                                                    phi_7034_ = true;
                                                    break;
                                                }
                                                let _e2721 = local_2[_e2702][1u];
                                                phi_4101_ = vec2<f32>(_e2718, _e2721);
                                            } else {
                                                if (_e2693 == 2u) {
                                                    local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    let _e2705 = (_e2702 < 16u);
                                                    if _e2705 {
                                                    } else {
                                                        phi_7034_ = true;
                                                        break;
                                                    }
                                                    let _e2708 = local_3[_e2702][0u];
                                                    local_4 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    if _e2705 {
                                                    } else {
                                                        phi_7034_ = true;
                                                        break;
                                                    }
                                                    let _e2711 = local_4[_e2702][1u];
                                                    phi_4100_ = vec2<f32>(_e2708, _e2711);
                                                } else {
                                                    phi_4100_ = vec2<f32>(0.5f, 0.5f);
                                                }
                                                let _e2714 = phi_4100_;
                                                phi_4101_ = _e2714;
                                            }
                                            let _e2724 = phi_4101_;
                                            let _e2729 = ((f32((bitcast<i32>(_e2679) - _e2687)) + _e2724.x) / _e2649);
                                            let _e2730 = ((f32((bitcast<i32>(_e2684) - _e2687)) + _e2724.y) / _e2650);
                                            let _e2735 = frame.member[0u].member_1.member.member.member[0u];
                                            let _e2740 = select(select(u32(_e2735), 0u, (_e2735 < 0f)), 4294967295u, (_e2735 > 4294967000f));
                                            let _e2745 = frame.member[0u].member_1.member.member.member[1u];
                                            let _e2755 = (select(0f, select(1f, _e2729, (_e2729 < 1f)), (_e2729 > 0f)) * _e2735);
                                            let _e2758 = f32(bitcast<i32>((_e2740 - 1u)));
                                            let _e2771 = (select(0f, select(1f, _e2730, (_e2730 < 1f)), (_e2730 > 0f)) * _e2745);
                                            let _e2774 = f32(bitcast<i32>((select(select(u32(_e2745), 0u, (_e2745 < 0f)), 4294967295u, (_e2745 > 4294967000f)) - 1u)));
                                            let _e2784 = (((bitcast<u32>((floor(select(0f, select(_e2774, _e2771, (_e2771 < _e2774)), (_e2771 > 0f))) + 8388608f)) - 1258291200u) * _e2740) + (bitcast<u32>((floor(select(0f, select(_e2758, _e2755, (_e2755 < _e2758)), (_e2755 > 0f))) + 8388608f)) - 1258291200u));
                                            if (_e2784 < _e190) {
                                            } else {
                                                phi_7034_ = true;
                                                break;
                                            }
                                            let _e2787 = mips.member[_e2784];
                                            if (abs((_e2787 - _e963)) > _e243) {
                                                if (_e246 > 0f) {
                                                    phi_4234_ = (_e2379 > (_e246 * _e246));
                                                } else {
                                                    phi_4234_ = false;
                                                }
                                                let _e3539 = phi_4234_;
                                                if !(_e3539) {
                                                    let _e3545 = (((_e2372 * _e490) + (_e2373 * _e491)) + (_e2374 * _e492));
                                                    let _e3549 = (_e2372 - (_e490 * _e3545));
                                                    let _e3550 = (_e2373 - (_e491 * _e3545));
                                                    let _e3551 = (_e2374 - (_e492 * _e3545));
                                                    let _e3554 = ((_e3550 * _e492) - (_e491 * _e3551));
                                                    let _e3557 = ((_e3551 * _e490) - (_e492 * _e3549));
                                                    let _e3560 = ((_e3549 * _e491) - (_e490 * _e3550));
                                                    let _e3571 = ((((_e551 * _e3554) + (_e552 * _e3557)) + (_e553 * _e3560)) / (((_e3554 * _e3554) + (_e3557 * _e3557)) + (_e3560 * _e3560)));
                                                    let _e3575 = (_e551 - (_e3554 * _e3571));
                                                    let _e3576 = (_e552 - (_e3557 * _e3571));
                                                    let _e3577 = (_e553 - (_e3560 * _e3571));
                                                    let _e3583 = inverseSqrt((((_e3575 * _e3575) + (_e3576 * _e3576)) + (_e3577 * _e3577)));
                                                    let _e3589 = ((((_e3575 * _e490) + (_e3576 * _e491)) + (_e3577 * _e492)) * _e3583);
                                                    let _e3593 = select(0f, select(1f, _e3589, (_e3589 < 1f)), (_e3589 > 0f));
                                                    let _e3594 = abs(_e3593);
                                                    let _e3604 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3594, 0.00667009f), _e3594, -0.017088126f), _e3594, 0.03089188f), _e3594, -0.050174303f), _e3594, 0.08897899f), _e3594, -0.2145988f), _e3594, 1.5707963f) * sqrt((1f - _e3594)));
                                                    let _e3607 = select((3.1415927f - _e3604), _e3604, (_e3593 >= 0f));
                                                    let _e3615 = select(_e3607, -(_e3607), ((((_e3549 * _e3575) + (_e3550 * _e3576)) + (_e3551 * _e3577)) < 0f));
                                                    let _e3616 = (_e3583 * 0.02f);
                                                    let _e3619 = select(0.19634955f, _e3616, ((_e3616 < 0.19634955f) || false));
                                                    let _e3629 = (_e2372 - (_e490 * _e243));
                                                    let _e3630 = (_e2373 - (_e491 * _e243));
                                                    let _e3631 = (_e2374 - (_e492 * _e243));
                                                    let _e3633 = (_e3545 * inverseSqrt(_e2379));
                                                    let _e3637 = select(-1f, select(1f, _e3633, (_e3633 < 1f)), (_e3633 > -1f));
                                                    let _e3638 = abs(_e3637);
                                                    let _e3648 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3638, 0.00667009f), _e3638, -0.017088126f), _e3638, 0.03089188f), _e3638, -0.050174303f), _e3638, 0.08897899f), _e3638, -0.2145988f), _e3638, 1.5707963f) * sqrt((1f - _e3638)));
                                                    let _e3655 = ((((select((3.1415927f - _e3648), _e3648, (_e3637 >= 0f)) + _e3619) - _e3615) + 1.5707964f) * 0.31830987f);
                                                    let _e3671 = ((((_e3629 * _e490) + (_e3630 * _e491)) + (_e3631 * _e492)) * inverseSqrt((((_e3629 * _e3629) + (_e3630 * _e3630)) + (_e3631 * _e3631))));
                                                    let _e3675 = select(-1f, select(1f, _e3671, (_e3671 < 1f)), (_e3671 > -1f));
                                                    let _e3676 = abs(_e3675);
                                                    let _e3686 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3676, 0.00667009f), _e3676, -0.017088126f), _e3676, 0.03089188f), _e3676, -0.050174303f), _e3676, 0.08897899f), _e3676, -0.2145988f), _e3676, 1.5707963f) * sqrt((1f - _e3676)));
                                                    let _e3693 = ((((select((3.1415927f - _e3686), _e3686, (_e3675 >= 0f)) + _e3619) - _e3615) + 1.5707964f) * 0.31830987f);
                                                    let _e3698 = (1f - select(0f, select(1f, _e3655, (_e3655 < 1f)), (_e3655 > 0f)));
                                                    let _e3699 = (1f - select(0f, select(1f, _e3693, (_e3693 < 1f)), (_e3693 > 0f)));
                                                    let _e3701 = (_e3699 != _e3699);
                                                    let _e3703 = select(_e3699, _e3698, ((_e3698 < _e3699) || _e3701));
                                                    let _e3706 = select(_e3699, _e3698, ((_e3698 > _e3699) || _e3701));
                                                    let _e3708 = floor((_e3703 * 32f));
                                                    if (_e240 == 1u) {
                                                        let _e3716 = -(floor((_e3706 * -32f)));
                                                        let _e3721 = (select(32f, _e3716, ((_e3716 < 32f) || false)) - _e3708);
                                                        phi_4550_ = select(select(0f, _e3721, ((_e3721 > 0f) || false)), 0f, (_e3706 <= _e3703));
                                                    } else {
                                                        phi_4550_ = -(floor(((_e3706 - _e3703) * -32f)));
                                                    }
                                                    let _e3727 = phi_4550_;
                                                    let _e3735 = (bitcast<u32>((floor(select(0f, select(32f, _e3708, (_e3708 < 32f)), (_e3708 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3743 = (bitcast<u32>((floor(select(0f, select(32f, _e3727, (_e3727 < 32f)), (_e3727 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3735 >= 32u) {
                                                        phi_4604_ = u32();
                                                        phi_4605_ = true;
                                                    } else {
                                                        let _e3745 = (_e3743 == 0u);
                                                        if _e3745 {
                                                            phi_4603_ = u32();
                                                        } else {
                                                            if (_e3743 >= 32u) {
                                                                phi_4600_ = 4294967295u;
                                                            } else {
                                                                phi_4600_ = ((1u << bitcast<u32>((_e3743 & 31u))) - 1u);
                                                            }
                                                            let _e3752 = phi_4600_;
                                                            phi_4603_ = (_e3752 << bitcast<u32>((_e3735 & 31u)));
                                                        }
                                                        let _e3757 = phi_4603_;
                                                        phi_4604_ = _e3757;
                                                        phi_4605_ = _e3745;
                                                    }
                                                    let _e3759 = phi_4604_;
                                                    let _e3761 = phi_4605_;
                                                    phi_4618_ = select(select(select(_e3759, 0u, _e3761), 0u, ((((_e3549 * _e3549) + (_e3550 * _e3550)) + (_e3551 * _e3551)) <= 0f)), 0u, _e3539);
                                                } else {
                                                    phi_4618_ = 0u;
                                                }
                                                let _e3766 = phi_4618_;
                                                phi_7038_ = _e2368;
                                                phi_5880_ = _e3766;
                                                phi_5881_ = u32();
                                                phi_5882_ = true;
                                            } else {
                                                local_5 = array<f32, 8>(0f, 0f, 0f, 0f, 0f, 0f, 0f, 0f);
                                                let _e2794 = frame.member[0u].member_1.member_6;
                                                phi_6844_ = _e2368;
                                                phi_4636_ = 0u;
                                                phi_4639_ = 0u;
                                                loop {
                                                    let _e2797 = phi_6844_;
                                                    let _e2799 = phi_4636_;
                                                    let _e2801 = phi_4639_;
                                                    local_18 = _e2801;
                                                    local_19 = _e2801;
                                                    local_20 = _e2801;
                                                    let _e2802 = (_e2799 < _e2794);
                                                    if _e2802 {
                                                        let _e2803 = ((((_e2684 * _e2655) + _e2679) * _e2794) + _e2799);
                                                        if (_e2803 < _e193) {
                                                        } else {
                                                            phi_6967_ = true;
                                                            break;
                                                        }
                                                        let _e2806 = sd_map.member[_e2803];
                                                        let _e2810 = frame.member[0u].member_1.member.member.member_3;
                                                        let _e2814 = frame.member[0u].member_1.member.member.member_2;
                                                        let _e2817 = ((_e2806 * (_e2810 - _e2814)) + _e2814);
                                                        if (_e2806 < 1f) {
                                                            if (_e2817 > (_e963 * 1.001f)) {
                                                                phi_4679_ = _e2801;
                                                                loop {
                                                                    let _e2822 = phi_4679_;
                                                                    local_16 = _e2822;
                                                                    local_17 = _e2822;
                                                                    if (_e2822 > 0u) {
                                                                        let _e2824 = (_e2822 - 1u);
                                                                        let _e2825 = (_e2824 < 8u);
                                                                        if _e2825 {
                                                                        } else {
                                                                            phi_6840_ = true;
                                                                            break;
                                                                        }
                                                                        let _e2827 = local_5[_e2824];
                                                                        let _e2828 = (_e2827 > _e2817);
                                                                        if _e2828 {
                                                                            if _e2825 {
                                                                            } else {
                                                                                phi_6840_ = true;
                                                                                break;
                                                                            }
                                                                            let _e2829 = local_5[_e2824];
                                                                            if (_e2822 < 8u) {
                                                                            } else {
                                                                                phi_6840_ = true;
                                                                                break;
                                                                            }
                                                                            local_5[_e2822] = _e2829;
                                                                        }
                                                                        phi_4680_ = select(u32(), _e2824, _e2828);
                                                                        phi_4716_ = _e2828;
                                                                    } else {
                                                                        phi_4680_ = u32();
                                                                        phi_4716_ = false;
                                                                    }
                                                                    let _e2834 = phi_4680_;
                                                                    let _e2836 = phi_4716_;
                                                                    continue;
                                                                    continuing {
                                                                        phi_4679_ = _e2834;
                                                                        phi_6840_ = _e2797;
                                                                        break if !(_e2836);
                                                                    }
                                                                }
                                                                let _e2839 = phi_6840_;
                                                                phi_6967_ = _e2839;
                                                                if _e2839 {
                                                                    break;
                                                                }
                                                                let _e2841 = local_16;
                                                                if (_e2841 < 8u) {
                                                                } else {
                                                                    phi_6967_ = true;
                                                                    break;
                                                                }
                                                                let _e2844 = local_17;
                                                                local_5[_e2844] = _e2817;
                                                                phi_6970_ = _e2839;
                                                                phi_4728_ = (_e2801 + 1u);
                                                            } else {
                                                                phi_6970_ = _e2797;
                                                                phi_4728_ = _e2801;
                                                            }
                                                            let _e2848 = phi_6970_;
                                                            let _e2850 = phi_4728_;
                                                            phi_6969_ = _e2848;
                                                            phi_4729_ = _e2850;
                                                        } else {
                                                            phi_6969_ = _e2797;
                                                            phi_4729_ = _e2801;
                                                        }
                                                        let _e2852 = phi_6969_;
                                                        let _e2854 = phi_4729_;
                                                        phi_6968_ = _e2852;
                                                        phi_4637_ = (_e2799 + 1u);
                                                        phi_4640_ = _e2854;
                                                    } else {
                                                        phi_6968_ = _e2797;
                                                        phi_4637_ = u32();
                                                        phi_4640_ = u32();
                                                    }
                                                    let _e2857 = phi_6968_;
                                                    let _e2859 = phi_4637_;
                                                    let _e2861 = phi_4640_;
                                                    continue;
                                                    continuing {
                                                        phi_6844_ = _e2857;
                                                        phi_4636_ = _e2859;
                                                        phi_4639_ = _e2861;
                                                        phi_6967_ = _e2857;
                                                        break if !(_e2802);
                                                    }
                                                }
                                                let _e2864 = phi_6967_;
                                                phi_7034_ = _e2864;
                                                if _e2864 {
                                                    break;
                                                }
                                                let _e2866 = local_18;
                                                let _e2867 = (_e2866 == 0u);
                                                if _e2867 {
                                                    if (_e246 > 0f) {
                                                        phi_4746_ = (_e2379 > (_e246 * _e246));
                                                    } else {
                                                        phi_4746_ = false;
                                                    }
                                                    let _e3301 = phi_4746_;
                                                    if !(_e3301) {
                                                        let _e3307 = (((_e2372 * _e490) + (_e2373 * _e491)) + (_e2374 * _e492));
                                                        let _e3311 = (_e2372 - (_e490 * _e3307));
                                                        let _e3312 = (_e2373 - (_e491 * _e3307));
                                                        let _e3313 = (_e2374 - (_e492 * _e3307));
                                                        let _e3316 = ((_e3312 * _e492) - (_e491 * _e3313));
                                                        let _e3319 = ((_e3313 * _e490) - (_e492 * _e3311));
                                                        let _e3322 = ((_e3311 * _e491) - (_e490 * _e3312));
                                                        let _e3333 = ((((_e551 * _e3316) + (_e552 * _e3319)) + (_e553 * _e3322)) / (((_e3316 * _e3316) + (_e3319 * _e3319)) + (_e3322 * _e3322)));
                                                        let _e3337 = (_e551 - (_e3316 * _e3333));
                                                        let _e3338 = (_e552 - (_e3319 * _e3333));
                                                        let _e3339 = (_e553 - (_e3322 * _e3333));
                                                        let _e3345 = inverseSqrt((((_e3337 * _e3337) + (_e3338 * _e3338)) + (_e3339 * _e3339)));
                                                        let _e3351 = ((((_e3337 * _e490) + (_e3338 * _e491)) + (_e3339 * _e492)) * _e3345);
                                                        let _e3355 = select(0f, select(1f, _e3351, (_e3351 < 1f)), (_e3351 > 0f));
                                                        let _e3356 = abs(_e3355);
                                                        let _e3366 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3356, 0.00667009f), _e3356, -0.017088126f), _e3356, 0.03089188f), _e3356, -0.050174303f), _e3356, 0.08897899f), _e3356, -0.2145988f), _e3356, 1.5707963f) * sqrt((1f - _e3356)));
                                                        let _e3369 = select((3.1415927f - _e3366), _e3366, (_e3355 >= 0f));
                                                        let _e3377 = select(_e3369, -(_e3369), ((((_e3311 * _e3337) + (_e3312 * _e3338)) + (_e3313 * _e3339)) < 0f));
                                                        let _e3378 = (_e3345 * 0.02f);
                                                        let _e3381 = select(0.19634955f, _e3378, ((_e3378 < 0.19634955f) || false));
                                                        let _e3391 = (_e2372 - (_e490 * _e243));
                                                        let _e3392 = (_e2373 - (_e491 * _e243));
                                                        let _e3393 = (_e2374 - (_e492 * _e243));
                                                        let _e3395 = (_e3307 * inverseSqrt(_e2379));
                                                        let _e3399 = select(-1f, select(1f, _e3395, (_e3395 < 1f)), (_e3395 > -1f));
                                                        let _e3400 = abs(_e3399);
                                                        let _e3410 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3400, 0.00667009f), _e3400, -0.017088126f), _e3400, 0.03089188f), _e3400, -0.050174303f), _e3400, 0.08897899f), _e3400, -0.2145988f), _e3400, 1.5707963f) * sqrt((1f - _e3400)));
                                                        let _e3417 = ((((select((3.1415927f - _e3410), _e3410, (_e3399 >= 0f)) + _e3381) - _e3377) + 1.5707964f) * 0.31830987f);
                                                        let _e3433 = ((((_e3391 * _e490) + (_e3392 * _e491)) + (_e3393 * _e492)) * inverseSqrt((((_e3391 * _e3391) + (_e3392 * _e3392)) + (_e3393 * _e3393))));
                                                        let _e3437 = select(-1f, select(1f, _e3433, (_e3433 < 1f)), (_e3433 > -1f));
                                                        let _e3438 = abs(_e3437);
                                                        let _e3448 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3438, 0.00667009f), _e3438, -0.017088126f), _e3438, 0.03089188f), _e3438, -0.050174303f), _e3438, 0.08897899f), _e3438, -0.2145988f), _e3438, 1.5707963f) * sqrt((1f - _e3438)));
                                                        let _e3455 = ((((select((3.1415927f - _e3448), _e3448, (_e3437 >= 0f)) + _e3381) - _e3377) + 1.5707964f) * 0.31830987f);
                                                        let _e3460 = (1f - select(0f, select(1f, _e3417, (_e3417 < 1f)), (_e3417 > 0f)));
                                                        let _e3461 = (1f - select(0f, select(1f, _e3455, (_e3455 < 1f)), (_e3455 > 0f)));
                                                        let _e3463 = (_e3461 != _e3461);
                                                        let _e3465 = select(_e3461, _e3460, ((_e3460 < _e3461) || _e3463));
                                                        let _e3468 = select(_e3461, _e3460, ((_e3460 > _e3461) || _e3463));
                                                        let _e3470 = floor((_e3465 * 32f));
                                                        if (_e240 == 1u) {
                                                            let _e3478 = -(floor((_e3468 * -32f)));
                                                            let _e3483 = (select(32f, _e3478, ((_e3478 < 32f) || false)) - _e3470);
                                                            phi_5062_ = select(select(0f, _e3483, ((_e3483 > 0f) || false)), 0f, (_e3468 <= _e3465));
                                                        } else {
                                                            phi_5062_ = -(floor(((_e3468 - _e3465) * -32f)));
                                                        }
                                                        let _e3489 = phi_5062_;
                                                        let _e3497 = (bitcast<u32>((floor(select(0f, select(32f, _e3470, (_e3470 < 32f)), (_e3470 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e3505 = (bitcast<u32>((floor(select(0f, select(32f, _e3489, (_e3489 < 32f)), (_e3489 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e3497 >= 32u) {
                                                            phi_5116_ = u32();
                                                            phi_5117_ = true;
                                                        } else {
                                                            let _e3507 = (_e3505 == 0u);
                                                            if _e3507 {
                                                                phi_5115_ = u32();
                                                            } else {
                                                                if (_e3505 >= 32u) {
                                                                    phi_5112_ = 4294967295u;
                                                                } else {
                                                                    phi_5112_ = ((1u << bitcast<u32>((_e3505 & 31u))) - 1u);
                                                                }
                                                                let _e3514 = phi_5112_;
                                                                phi_5115_ = (_e3514 << bitcast<u32>((_e3497 & 31u)));
                                                            }
                                                            let _e3519 = phi_5115_;
                                                            phi_5116_ = _e3519;
                                                            phi_5117_ = _e3507;
                                                        }
                                                        let _e3521 = phi_5116_;
                                                        let _e3523 = phi_5117_;
                                                        phi_5130_ = select(select(select(_e3521, 0u, _e3523), 0u, ((((_e3311 * _e3311) + (_e3312 * _e3312)) + (_e3313 * _e3313)) <= 0f)), 0u, _e3301);
                                                    } else {
                                                        phi_5130_ = 0u;
                                                    }
                                                    let _e3528 = phi_5130_;
                                                    phi_7073_ = _e2864;
                                                    phi_5878_ = _e3528;
                                                    phi_5879_ = u32();
                                                } else {
                                                    let _e2872 = (((_e2372 * _e490) + (_e2373 * _e491)) + (_e2374 * _e492));
                                                    let _e2876 = (_e2372 - (_e490 * _e2872));
                                                    let _e2877 = (_e2373 - (_e491 * _e2872));
                                                    let _e2878 = (_e2374 - (_e492 * _e2872));
                                                    let _e2881 = ((_e2877 * _e492) - (_e491 * _e2878));
                                                    let _e2884 = ((_e2878 * _e490) - (_e492 * _e2876));
                                                    let _e2887 = ((_e2876 * _e491) - (_e490 * _e2877));
                                                    let _e2898 = ((((_e551 * _e2881) + (_e552 * _e2884)) + (_e553 * _e2887)) / (((_e2881 * _e2881) + (_e2884 * _e2884)) + (_e2887 * _e2887)));
                                                    let _e2902 = (_e551 - (_e2881 * _e2898));
                                                    let _e2903 = (_e552 - (_e2884 * _e2898));
                                                    let _e2904 = (_e553 - (_e2887 * _e2898));
                                                    let _e2910 = inverseSqrt((((_e2902 * _e2902) + (_e2903 * _e2903)) + (_e2904 * _e2904)));
                                                    let _e2916 = ((((_e2902 * _e490) + (_e2903 * _e491)) + (_e2904 * _e492)) * _e2910);
                                                    let _e2920 = select(0f, select(1f, _e2916, (_e2916 < 1f)), (_e2916 > 0f));
                                                    let _e2921 = abs(_e2920);
                                                    let _e2931 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2921, 0.00667009f), _e2921, -0.017088126f), _e2921, 0.03089188f), _e2921, -0.050174303f), _e2921, 0.08897899f), _e2921, -0.2145988f), _e2921, 1.5707963f) * sqrt((1f - _e2921)));
                                                    let _e2934 = select((3.1415927f - _e2931), _e2931, (_e2920 >= 0f));
                                                    let _e2942 = select(_e2934, -(_e2934), ((((_e2876 * _e2902) + (_e2877 * _e2903)) + (_e2878 * _e2904)) < 0f));
                                                    let _e2943 = (_e2910 * 0.02f);
                                                    let _e2946 = select(0.19634955f, _e2943, ((_e2943 < 0.19634955f) || false));
                                                    let _e2952 = ((((_e2876 * _e2876) + (_e2877 * _e2877)) + (_e2878 * _e2878)) <= 0f);
                                                    let _e2954 = local_5[0u];
                                                    let _e2957 = (((_e2729 * 2f) - 1f) * _e2632);
                                                    let _e2961 = (((_e2730 * -2f) + 1f) * _e2640);
                                                    let _e2963 = ((_e2957 * _e2954) - _e471);
                                                    let _e2964 = ((_e2961 * _e2954) - _e478);
                                                    let _e2965 = (_e2954 - _e464);
                                                    let _e2967 = (_e2872 * inverseSqrt(_e2379));
                                                    let _e2971 = select(-1f, select(1f, _e2967, (_e2967 < 1f)), (_e2967 > -1f));
                                                    let _e2972 = abs(_e2971);
                                                    let _e2982 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2972, 0.00667009f), _e2972, -0.017088126f), _e2972, 0.03089188f), _e2972, -0.050174303f), _e2972, 0.08897899f), _e2972, -0.2145988f), _e2972, 1.5707963f) * sqrt((1f - _e2972)));
                                                    let _e2989 = ((((select((3.1415927f - _e2982), _e2982, (_e2971 >= 0f)) + _e2946) - _e2942) + 1.5707964f) * 0.31830987f);
                                                    let _e3005 = ((((_e2963 * _e490) + (_e2964 * _e491)) + (_e2965 * _e492)) * inverseSqrt((((_e2963 * _e2963) + (_e2964 * _e2964)) + (_e2965 * _e2965))));
                                                    let _e3009 = select(-1f, select(1f, _e3005, (_e3005 < 1f)), (_e3005 > -1f));
                                                    let _e3010 = abs(_e3009);
                                                    let _e3020 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3010, 0.00667009f), _e3010, -0.017088126f), _e3010, 0.03089188f), _e3010, -0.050174303f), _e3010, 0.08897899f), _e3010, -0.2145988f), _e3010, 1.5707963f) * sqrt((1f - _e3010)));
                                                    let _e3027 = ((((select((3.1415927f - _e3020), _e3020, (_e3009 >= 0f)) + _e2946) - _e2942) + 1.5707964f) * 0.31830987f);
                                                    let _e3032 = (1f - select(0f, select(1f, _e2989, (_e2989 < 1f)), (_e2989 > 0f)));
                                                    let _e3033 = (1f - select(0f, select(1f, _e3027, (_e3027 < 1f)), (_e3027 > 0f)));
                                                    let _e3035 = (_e3033 != _e3033);
                                                    let _e3037 = select(_e3033, _e3032, ((_e3032 < _e3033) || _e3035));
                                                    let _e3040 = select(_e3033, _e3032, ((_e3032 > _e3033) || _e3035));
                                                    let _e3042 = floor((_e3037 * 32f));
                                                    let _e3043 = (_e240 == 1u);
                                                    if _e3043 {
                                                        let _e3050 = -(floor((_e3040 * -32f)));
                                                        let _e3055 = (select(32f, _e3050, ((_e3050 < 32f) || false)) - _e3042);
                                                        phi_5459_ = select(select(0f, _e3055, ((_e3055 > 0f) || false)), 0f, (_e3040 <= _e3037));
                                                    } else {
                                                        phi_5459_ = -(floor(((_e3040 - _e3037) * -32f)));
                                                    }
                                                    let _e3061 = phi_5459_;
                                                    let _e3069 = (bitcast<u32>((floor(select(0f, select(32f, _e3042, (_e3042 < 32f)), (_e3042 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3077 = (bitcast<u32>((floor(select(0f, select(32f, _e3061, (_e3061 < 32f)), (_e3061 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3069 >= 32u) {
                                                        phi_5513_ = u32();
                                                        phi_5514_ = true;
                                                    } else {
                                                        let _e3079 = (_e3077 == 0u);
                                                        if _e3079 {
                                                            phi_5512_ = u32();
                                                        } else {
                                                            if (_e3077 >= 32u) {
                                                                phi_5509_ = 4294967295u;
                                                            } else {
                                                                phi_5509_ = ((1u << bitcast<u32>((_e3077 & 31u))) - 1u);
                                                            }
                                                            let _e3086 = phi_5509_;
                                                            phi_5512_ = (_e3086 << bitcast<u32>((_e3069 & 31u)));
                                                        }
                                                        let _e3091 = phi_5512_;
                                                        phi_5513_ = _e3091;
                                                        phi_5514_ = _e3079;
                                                    }
                                                    let _e3093 = phi_5513_;
                                                    let _e3095 = phi_5514_;
                                                    phi_5524_ = 1u;
                                                    phi_5527_ = select(select(_e3093, 0u, _e3095), 0u, _e2952);
                                                    loop {
                                                        let _e3099 = phi_5524_;
                                                        let _e3101 = phi_5527_;
                                                        local_30 = _e3101;
                                                        let _e3103 = local_19;
                                                        let _e3104 = (_e3099 < _e3103);
                                                        if _e3104 {
                                                            if (_e3099 < 8u) {
                                                            } else {
                                                                phi_6971_ = true;
                                                                break;
                                                            }
                                                            let _e3107 = local_5[_e3099];
                                                            let _e3110 = ((_e2957 * _e3107) - _e471);
                                                            let _e3111 = ((_e2961 * _e3107) - _e478);
                                                            let _e3112 = (_e3107 - _e464);
                                                            let _e3113 = (_e3099 + 1u);
                                                            let _e3115 = local_20;
                                                            if (_e3113 < _e3115) {
                                                                if (_e3113 < 8u) {
                                                                } else {
                                                                    phi_6971_ = true;
                                                                    break;
                                                                }
                                                                let _e3126 = local_5[_e3113];
                                                                phi_5606_ = (vec3<f32>((_e2957 * _e3126), (_e2961 * _e3126), _e3126) - _e479);
                                                            } else {
                                                                phi_5606_ = vec3<f32>((_e3110 - (_e490 * _e243)), (_e3111 - (_e491 * _e243)), (_e3112 - (_e492 * _e243)));
                                                            }
                                                            let _e3132 = phi_5606_;
                                                            if _e980 {
                                                                phi_5621_ = true;
                                                            } else {
                                                                phi_5621_ = ((((_e3110 * _e3110) + (_e3111 * _e3111)) + (_e3112 * _e3112)) <= (_e246 * _e246));
                                                            }
                                                            let _e3141 = phi_5621_;
                                                            if _e3141 {
                                                                let _e3153 = ((((_e3110 * _e490) + (_e3111 * _e491)) + (_e3112 * _e492)) * inverseSqrt((((_e3110 * _e3110) + (_e3111 * _e3111)) + (_e3112 * _e3112))));
                                                                let _e3157 = select(-1f, select(1f, _e3153, (_e3153 < 1f)), (_e3153 > -1f));
                                                                let _e3158 = abs(_e3157);
                                                                let _e3168 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3158, 0.00667009f), _e3158, -0.017088126f), _e3158, 0.03089188f), _e3158, -0.050174303f), _e3158, 0.08897899f), _e3158, -0.2145988f), _e3158, 1.5707963f) * sqrt((1f - _e3158)));
                                                                let _e3175 = ((((select((3.1415927f - _e3168), _e3168, (_e3157 >= 0f)) + _e2946) - _e2942) + 1.5707964f) * 0.31830987f);
                                                                let _e3194 = ((((_e3132.x * _e490) + (_e3132.y * _e491)) + (_e3132.z * _e492)) * inverseSqrt((((_e3132.x * _e3132.x) + (_e3132.y * _e3132.y)) + (_e3132.z * _e3132.z))));
                                                                let _e3198 = select(-1f, select(1f, _e3194, (_e3194 < 1f)), (_e3194 > -1f));
                                                                let _e3199 = abs(_e3198);
                                                                let _e3209 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3199, 0.00667009f), _e3199, -0.017088126f), _e3199, 0.03089188f), _e3199, -0.050174303f), _e3199, 0.08897899f), _e3199, -0.2145988f), _e3199, 1.5707963f) * sqrt((1f - _e3199)));
                                                                let _e3216 = ((((select((3.1415927f - _e3209), _e3209, (_e3198 >= 0f)) + _e2946) - _e2942) + 1.5707964f) * 0.31830987f);
                                                                let _e3221 = (1f - select(0f, select(1f, _e3175, (_e3175 < 1f)), (_e3175 > 0f)));
                                                                let _e3222 = (1f - select(0f, select(1f, _e3216, (_e3216 < 1f)), (_e3216 > 0f)));
                                                                let _e3224 = (_e3222 != _e3222);
                                                                let _e3226 = select(_e3222, _e3221, ((_e3221 < _e3222) || _e3224));
                                                                let _e3229 = select(_e3222, _e3221, ((_e3221 > _e3222) || _e3224));
                                                                let _e3231 = floor((_e3226 * 32f));
                                                                if _e3043 {
                                                                    let _e3238 = -(floor((_e3229 * -32f)));
                                                                    let _e3243 = (select(32f, _e3238, ((_e3238 < 32f) || false)) - _e3231);
                                                                    phi_5811_ = select(select(0f, _e3243, ((_e3243 > 0f) || false)), 0f, (_e3229 <= _e3226));
                                                                } else {
                                                                    phi_5811_ = -(floor(((_e3229 - _e3226) * -32f)));
                                                                }
                                                                let _e3249 = phi_5811_;
                                                                let _e3257 = (bitcast<u32>((floor(select(0f, select(32f, _e3231, (_e3231 < 32f)), (_e3231 > 0f))) + 8388608f)) - 1258291200u);
                                                                let _e3265 = (bitcast<u32>((floor(select(0f, select(32f, _e3249, (_e3249 < 32f)), (_e3249 > 0f))) + 8388608f)) - 1258291200u);
                                                                if (_e3257 >= 32u) {
                                                                    phi_5865_ = u32();
                                                                    phi_5866_ = true;
                                                                } else {
                                                                    let _e3267 = (_e3265 == 0u);
                                                                    if _e3267 {
                                                                        phi_5864_ = u32();
                                                                    } else {
                                                                        if (_e3265 >= 32u) {
                                                                            phi_5861_ = 4294967295u;
                                                                        } else {
                                                                            phi_5861_ = ((1u << bitcast<u32>((_e3265 & 31u))) - 1u);
                                                                        }
                                                                        let _e3274 = phi_5861_;
                                                                        phi_5864_ = (_e3274 << bitcast<u32>((_e3257 & 31u)));
                                                                    }
                                                                    let _e3279 = phi_5864_;
                                                                    phi_5865_ = _e3279;
                                                                    phi_5866_ = _e3267;
                                                                }
                                                                let _e3281 = phi_5865_;
                                                                let _e3283 = phi_5866_;
                                                                phi_5876_ = (_e3101 | select(select(_e3281, 0u, _e3283), 0u, _e2952));
                                                            } else {
                                                                phi_5876_ = _e3101;
                                                            }
                                                            let _e3288 = phi_5876_;
                                                            phi_5525_ = (_e3099 + 2u);
                                                            phi_5528_ = _e3288;
                                                        } else {
                                                            phi_5525_ = u32();
                                                            phi_5528_ = u32();
                                                        }
                                                        let _e3291 = phi_5525_;
                                                        let _e3293 = phi_5528_;
                                                        continue;
                                                        continuing {
                                                            phi_5524_ = _e3291;
                                                            phi_5527_ = _e3293;
                                                            phi_6971_ = _e2864;
                                                            break if !(_e3104);
                                                        }
                                                    }
                                                    let _e3296 = phi_6971_;
                                                    phi_7034_ = _e3296;
                                                    if _e3296 {
                                                        break;
                                                    }
                                                    phi_7073_ = _e3296;
                                                    phi_5878_ = u32();
                                                    let _e4108 = local_30;
                                                    phi_5879_ = _e4108;
                                                }
                                                let _e3530 = phi_7073_;
                                                let _e3532 = phi_5878_;
                                                let _e3534 = phi_5879_;
                                                phi_7038_ = _e3530;
                                                phi_5880_ = _e3532;
                                                phi_5881_ = _e3534;
                                                phi_5882_ = _e2867;
                                            }
                                            let _e3768 = phi_7038_;
                                            let _e3770 = phi_5880_;
                                            let _e3772 = phi_5881_;
                                            let _e3774 = phi_5882_;
                                            phi_7036_ = _e3768;
                                            phi_6283_ = select(_e3772, _e3770, _e3774);
                                        } else {
                                            if (_e246 > 0f) {
                                                phi_5898_ = (_e2379 > (_e246 * _e246));
                                            } else {
                                                phi_5898_ = false;
                                            }
                                            let _e2398 = phi_5898_;
                                            if !(_e2398) {
                                                let _e2404 = (((_e2372 * _e490) + (_e2373 * _e491)) + (_e2374 * _e492));
                                                let _e2408 = (_e2372 - (_e490 * _e2404));
                                                let _e2409 = (_e2373 - (_e491 * _e2404));
                                                let _e2410 = (_e2374 - (_e492 * _e2404));
                                                let _e2413 = ((_e2409 * _e492) - (_e491 * _e2410));
                                                let _e2416 = ((_e2410 * _e490) - (_e492 * _e2408));
                                                let _e2419 = ((_e2408 * _e491) - (_e490 * _e2409));
                                                let _e2430 = ((((_e551 * _e2413) + (_e552 * _e2416)) + (_e553 * _e2419)) / (((_e2413 * _e2413) + (_e2416 * _e2416)) + (_e2419 * _e2419)));
                                                let _e2434 = (_e551 - (_e2413 * _e2430));
                                                let _e2435 = (_e552 - (_e2416 * _e2430));
                                                let _e2436 = (_e553 - (_e2419 * _e2430));
                                                let _e2442 = inverseSqrt((((_e2434 * _e2434) + (_e2435 * _e2435)) + (_e2436 * _e2436)));
                                                let _e2448 = ((((_e2434 * _e490) + (_e2435 * _e491)) + (_e2436 * _e492)) * _e2442);
                                                let _e2452 = select(0f, select(1f, _e2448, (_e2448 < 1f)), (_e2448 > 0f));
                                                let _e2453 = abs(_e2452);
                                                let _e2463 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2453, 0.00667009f), _e2453, -0.017088126f), _e2453, 0.03089188f), _e2453, -0.050174303f), _e2453, 0.08897899f), _e2453, -0.2145988f), _e2453, 1.5707963f) * sqrt((1f - _e2453)));
                                                let _e2466 = select((3.1415927f - _e2463), _e2463, (_e2452 >= 0f));
                                                let _e2474 = select(_e2466, -(_e2466), ((((_e2408 * _e2434) + (_e2409 * _e2435)) + (_e2410 * _e2436)) < 0f));
                                                let _e2475 = (_e2442 * 0.02f);
                                                let _e2478 = select(0.19634955f, _e2475, ((_e2475 < 0.19634955f) || false));
                                                let _e2488 = (_e2372 - (_e490 * _e243));
                                                let _e2489 = (_e2373 - (_e491 * _e243));
                                                let _e2490 = (_e2374 - (_e492 * _e243));
                                                let _e2492 = (_e2404 * inverseSqrt(_e2379));
                                                let _e2496 = select(-1f, select(1f, _e2492, (_e2492 < 1f)), (_e2492 > -1f));
                                                let _e2497 = abs(_e2496);
                                                let _e2507 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2497, 0.00667009f), _e2497, -0.017088126f), _e2497, 0.03089188f), _e2497, -0.050174303f), _e2497, 0.08897899f), _e2497, -0.2145988f), _e2497, 1.5707963f) * sqrt((1f - _e2497)));
                                                let _e2514 = ((((select((3.1415927f - _e2507), _e2507, (_e2496 >= 0f)) + _e2478) - _e2474) + 1.5707964f) * 0.31830987f);
                                                let _e2530 = ((((_e2488 * _e490) + (_e2489 * _e491)) + (_e2490 * _e492)) * inverseSqrt((((_e2488 * _e2488) + (_e2489 * _e2489)) + (_e2490 * _e2490))));
                                                let _e2534 = select(-1f, select(1f, _e2530, (_e2530 < 1f)), (_e2530 > -1f));
                                                let _e2535 = abs(_e2534);
                                                let _e2545 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2535, 0.00667009f), _e2535, -0.017088126f), _e2535, 0.03089188f), _e2535, -0.050174303f), _e2535, 0.08897899f), _e2535, -0.2145988f), _e2535, 1.5707963f) * sqrt((1f - _e2535)));
                                                let _e2552 = ((((select((3.1415927f - _e2545), _e2545, (_e2534 >= 0f)) + _e2478) - _e2474) + 1.5707964f) * 0.31830987f);
                                                let _e2557 = (1f - select(0f, select(1f, _e2514, (_e2514 < 1f)), (_e2514 > 0f)));
                                                let _e2558 = (1f - select(0f, select(1f, _e2552, (_e2552 < 1f)), (_e2552 > 0f)));
                                                let _e2560 = (_e2558 != _e2558);
                                                let _e2562 = select(_e2558, _e2557, ((_e2557 < _e2558) || _e2560));
                                                let _e2565 = select(_e2558, _e2557, ((_e2557 > _e2558) || _e2560));
                                                let _e2567 = floor((_e2562 * 32f));
                                                if (_e240 == 1u) {
                                                    let _e2575 = -(floor((_e2565 * -32f)));
                                                    let _e2580 = (select(32f, _e2575, ((_e2575 < 32f) || false)) - _e2567);
                                                    phi_6214_ = select(select(0f, _e2580, ((_e2580 > 0f) || false)), 0f, (_e2565 <= _e2562));
                                                } else {
                                                    phi_6214_ = -(floor(((_e2565 - _e2562) * -32f)));
                                                }
                                                let _e2586 = phi_6214_;
                                                let _e2594 = (bitcast<u32>((floor(select(0f, select(32f, _e2567, (_e2567 < 32f)), (_e2567 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2602 = (bitcast<u32>((floor(select(0f, select(32f, _e2586, (_e2586 < 32f)), (_e2586 > 0f))) + 8388608f)) - 1258291200u);
                                                if (_e2594 >= 32u) {
                                                    phi_6268_ = u32();
                                                    phi_6269_ = true;
                                                } else {
                                                    let _e2604 = (_e2602 == 0u);
                                                    if _e2604 {
                                                        phi_6267_ = u32();
                                                    } else {
                                                        if (_e2602 >= 32u) {
                                                            phi_6264_ = 4294967295u;
                                                        } else {
                                                            phi_6264_ = ((1u << bitcast<u32>((_e2602 & 31u))) - 1u);
                                                        }
                                                        let _e2611 = phi_6264_;
                                                        phi_6267_ = (_e2611 << bitcast<u32>((_e2594 & 31u)));
                                                    }
                                                    let _e2616 = phi_6267_;
                                                    phi_6268_ = _e2616;
                                                    phi_6269_ = _e2604;
                                                }
                                                let _e2618 = phi_6268_;
                                                let _e2620 = phi_6269_;
                                                phi_6282_ = select(select(select(_e2618, 0u, _e2620), 0u, ((((_e2408 * _e2408) + (_e2409 * _e2409)) + (_e2410 * _e2410)) <= 0f)), 0u, _e2398);
                                            } else {
                                                phi_6282_ = 0u;
                                            }
                                            let _e2625 = phi_6282_;
                                            phi_7036_ = _e2368;
                                            phi_6283_ = _e2625;
                                        }
                                        let _e3777 = phi_7036_;
                                        let _e3779 = phi_6283_;
                                        phi_7035_ = _e3777;
                                        phi_1203_ = (_e795 + 1u);
                                        phi_1206_ = ((_e797 | _e2370) | _e3779);
                                    } else {
                                        phi_7035_ = _e793;
                                        phi_1203_ = u32();
                                        phi_1206_ = u32();
                                    }
                                    let _e3783 = phi_7035_;
                                    let _e3785 = phi_1203_;
                                    let _e3787 = phi_1206_;
                                    continue;
                                    continuing {
                                        phi_6701_ = _e3783;
                                        phi_1202_ = _e3785;
                                        phi_1205_ = _e3787;
                                        phi_7034_ = _e3783;
                                        break if !(_e798);
                                    }
                                }
                                let _e3790 = phi_7034_;
                                phi_7145_ = _e3790;
                                if _e3790 {
                                    break;
                                }
                                if (_e235 == 2u) {
                                    let _e3849 = (_e788 - 1.5707964f);
                                    let _e3850 = (_e3849 * 2f);
                                    let _e3851 = sin(_e788);
                                    let _e3856 = ((_e773 + (_e3850 * _e3851)) - cos((_e3850 - _e788)));
                                    phi_6312_ = 0u;
                                    phi_6315_ = select((_e3856 * 0.25f), (_e3856 * -0.25f), (_e3849 < 0f));
                                    phi_6317_ = 0f;
                                    loop {
                                        let _e3862 = phi_6312_;
                                        let _e3864 = phi_6315_;
                                        let _e3866 = phi_6317_;
                                        local_25 = _e3866;
                                        let _e3867 = (_e3862 < 32u);
                                        if _e3867 {
                                            let _e3868 = (_e3862 + 1u);
                                            let _e3872 = (_e3849 + (f32(bitcast<i32>(_e3868)) * 0.09817477f));
                                            let _e3873 = (_e3872 * 2f);
                                            let _e3878 = ((_e773 + (_e3873 * _e3851)) - cos((_e3873 - _e788)));
                                            let _e3882 = select((_e3878 * 0.25f), (_e3878 * -0.25f), (_e3872 < 0f));
                                            let _e3885 = local_24;
                                            phi_6313_ = _e3868;
                                            phi_6316_ = _e3882;
                                            phi_6318_ = select(_e3866, (_e3866 + (_e3882 - _e3864)), (((_e3885 >> bitcast<u32>((_e3862 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_6313_ = u32();
                                            phi_6316_ = f32();
                                            phi_6318_ = f32();
                                        }
                                        let _e3894 = phi_6313_;
                                        let _e3896 = phi_6316_;
                                        let _e3898 = phi_6318_;
                                        continue;
                                        continuing {
                                            phi_6312_ = _e3894;
                                            phi_6315_ = _e3896;
                                            phi_6317_ = _e3898;
                                            break if !(_e3867);
                                        }
                                    }
                                    let _e3901 = local_25;
                                    phi_7147_ = _e3790;
                                    phi_6419_ = (_e694 + 1f);
                                    phi_6420_ = (_e696 + ((_e754 + ((1f - _e754) * 0.05f)) * _e3901));
                                } else {
                                    if (_e235 == 1u) {
                                        phi_6364_ = 0u;
                                        phi_6367_ = 0f;
                                        loop {
                                            let _e3804 = phi_6364_;
                                            let _e3806 = phi_6367_;
                                            local_23 = _e3806;
                                            let _e3807 = (_e3804 < 4u);
                                            if _e3807 {
                                                local = array<type_40, 4>(type_40(4026531855u, 0.0095061f), type_40(251658480u, 0.0270951f), type_40(15732480u, 0.0405571f), type_40(1044480u, 0.0478421f));
                                                if _e3807 {
                                                } else {
                                                    phi_7142_ = true;
                                                    break;
                                                }
                                                let _e3810 = local[_e3804].member;
                                                let _e3813 = local[_e3804].member_1;
                                                let _e3815 = local_22;
                                                phi_6365_ = (_e3804 + 1u);
                                                phi_6368_ = (_e3806 + (f32(bitcast<i32>(countOneBits((_e3815 & _e3810)))) * _e3813));
                                            } else {
                                                phi_6365_ = u32();
                                                phi_6368_ = f32();
                                            }
                                            let _e3824 = phi_6365_;
                                            let _e3826 = phi_6368_;
                                            continue;
                                            continuing {
                                                phi_6364_ = _e3824;
                                                phi_6367_ = _e3826;
                                                phi_7142_ = _e3790;
                                                break if !(_e3807);
                                            }
                                        }
                                        let _e3829 = phi_7142_;
                                        phi_7145_ = _e3829;
                                        if _e3829 {
                                            break;
                                        }
                                        let _e3831 = local_23;
                                        let _e3832 = (1f - _e3831);
                                        phi_7153_ = _e3829;
                                        phi_6417_ = (_e694 + _e754);
                                        phi_6418_ = (_e696 + (_e754 * select(0f, select(1f, _e3832, (_e3832 < 1f)), (_e3832 > 0f))));
                                    } else {
                                        let _e3794 = local_21;
                                        phi_7153_ = _e3790;
                                        phi_6417_ = (_e694 + 1f);
                                        phi_6418_ = (_e696 + ((f32(bitcast<i32>(countOneBits((_e3794 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e3841 = phi_7153_;
                                    let _e3843 = phi_6417_;
                                    let _e3845 = phi_6418_;
                                    phi_7147_ = _e3841;
                                    phi_6419_ = _e3843;
                                    phi_6420_ = _e3845;
                                }
                                let _e3906 = phi_7147_;
                                let _e3908 = phi_6419_;
                                let _e3910 = phi_6420_;
                                phi_7146_ = _e3906;
                                phi_1012_ = (_e692 + 1u);
                                phi_1015_ = _e3908;
                                phi_1017_ = _e3910;
                            } else {
                                phi_7146_ = _e690;
                                phi_1012_ = u32();
                                phi_1015_ = f32();
                                phi_1017_ = f32();
                            }
                            let _e3913 = phi_7146_;
                            let _e3915 = phi_1012_;
                            let _e3917 = phi_1015_;
                            let _e3919 = phi_1017_;
                            continue;
                            continuing {
                                phi_6710_ = _e3913;
                                phi_1011_ = _e3915;
                                phi_1014_ = _e3917;
                                phi_1016_ = _e3919;
                                phi_7145_ = _e3913;
                                break if !(_e697);
                            }
                        }
                        let _e3922 = phi_7145_;
                        if _e3922 {
                            break;
                        }
                        let _e3924 = local_26;
                        let _e3927 = local_27;
                        let _e3929 = local_28;
                        phi_6428_ = select(1f, (_e3927 / _e3929), (_e3924 > 0f));
                    } else {
                        phi_6428_ = 1f;
                    }
                    let _e3933 = phi_6428_;
                    if (_e230.member_6 == 2f) {
                        phi_6441_ = (_e3933 * _e3933);
                    } else {
                        if (_e230.member_6 == 1f) {
                            phi_6440_ = _e3933;
                        } else {
                            phi_6440_ = pow(_e3933, _e230.member_6);
                        }
                        let _e3939 = phi_6440_;
                        phi_6441_ = _e3939;
                    }
                    let _e3942 = phi_6441_;
                    let _e3947 = (select(1f, select(0.03f, _e3942, ((_e3942 > 0.03f) || false)), _e685) * 0.6666667f);
                    terms.member[_e272] = (bitcast<u32>((floor(((select(0f, select(1f, _e3947, (_e3947 < 1f)), (_e3947 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                    edges.member[_e272] = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e401, (_e401 < 3f)), (_e401 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e416, (_e416 < 3f)), (_e416 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e432, (_e432 < 3f)), (_e432 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e448, (_e448 < 3f)), (_e448 > 0f))) + 8388608f)) - 1258291200u));
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
