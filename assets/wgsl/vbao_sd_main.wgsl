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
    var phi_334_: type_26;
    var phi_341_: u32;
    var phi_348_: u32;
    var phi_6952_: bool;
    var phi_1006_: u32;
    var phi_1009_: f32;
    var phi_1011_: f32;
    var phi_6943_: bool;
    var phi_1197_: u32;
    var phi_1200_: u32;
    var phi_1257_: f32;
    var phi_1258_: f32;
    var phi_1539_: bool;
    var phi_1555_: bool;
    var phi_3633_: bool;
    var phi_3949_: f32;
    var phi_3999_: u32;
    var phi_4002_: u32;
    var phi_4003_: u32;
    var phi_4004_: bool;
    var phi_4017_: u32;
    var phi_1714_: vec2<f32>;
    var phi_1715_: vec2<f32>;
    var phi_2255_: u32;
    var phi_2258_: f32;
    var phi_2300_: f32;
    var phi_2301_: f32;
    var phi_2256_: u32;
    var phi_2259_: f32;
    var phi_6894_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var local_12: f32;
    var local_13: f32;
    var phi_2866_: vec3<f32>;
    var phi_3053_: f32;
    var phi_3103_: u32;
    var phi_3106_: u32;
    var phi_3107_: u32;
    var phi_3108_: bool;
    var phi_7021_: bool;
    var phi_3118_: f32;
    var phi_3121_: u32;
    var phi_3123_: u32;
    var phi_3153_: u32;
    var phi_3156_: f32;
    var phi_3198_: f32;
    var phi_3199_: f32;
    var phi_3154_: u32;
    var phi_3157_: f32;
    var phi_7015_: bool;
    var local_14: f32;
    var phi_3227_: u32;
    var phi_3230_: f32;
    var local_15: f32;
    var phi_3272_: f32;
    var phi_3273_: f32;
    var phi_3228_: u32;
    var phi_3231_: f32;
    var phi_7054_: bool;
    var local_16: f32;
    var local_17: f32;
    var local_18: f32;
    var local_19: f32;
    var local_20: f32;
    var local_21: f32;
    var local_22: f32;
    var phi_3332_: vec3<f32>;
    var phi_3347_: bool;
    var phi_3537_: f32;
    var phi_3587_: u32;
    var phi_3590_: u32;
    var phi_3591_: u32;
    var phi_3592_: bool;
    var phi_3602_: u32;
    var phi_7062_: bool;
    var phi_3604_: f32;
    var phi_3605_: u32;
    var phi_3606_: u32;
    var phi_7061_: bool;
    var phi_3119_: f32;
    var phi_3122_: u32;
    var phi_3124_: u32;
    var phi_3608_: bool;
    var phi_7060_: bool;
    var phi_2320_: bool;
    var phi_2636_: f32;
    var phi_2686_: u32;
    var phi_2689_: u32;
    var phi_2690_: u32;
    var phi_2691_: bool;
    var phi_2704_: u32;
    var phi_7150_: bool;
    var phi_3613_: u32;
    var phi_3614_: u32;
    var phi_1848_: bool;
    var phi_2164_: f32;
    var phi_2214_: u32;
    var phi_2217_: u32;
    var phi_2218_: u32;
    var phi_2219_: bool;
    var phi_2232_: u32;
    var phi_7115_: bool;
    var phi_3615_: u32;
    var phi_3616_: u32;
    var phi_3617_: bool;
    var phi_7113_: bool;
    var phi_4018_: u32;
    var phi_4041_: bool;
    var phi_4057_: bool;
    var phi_6135_: bool;
    var phi_6451_: f32;
    var phi_6501_: u32;
    var phi_6504_: u32;
    var phi_6505_: u32;
    var phi_6506_: bool;
    var phi_6519_: u32;
    var phi_4216_: vec2<f32>;
    var phi_4217_: vec2<f32>;
    var phi_4757_: u32;
    var phi_4760_: f32;
    var phi_4802_: f32;
    var phi_4803_: f32;
    var phi_4758_: u32;
    var phi_4761_: f32;
    var phi_7092_: bool;
    var local_23: f32;
    var local_24: f32;
    var local_25: f32;
    var local_26: f32;
    var local_27: f32;
    var phi_5368_: vec3<f32>;
    var phi_5555_: f32;
    var phi_5605_: u32;
    var phi_5608_: u32;
    var phi_5609_: u32;
    var phi_5610_: bool;
    var phi_7226_: bool;
    var phi_5620_: f32;
    var phi_5623_: u32;
    var phi_5625_: u32;
    var phi_5655_: u32;
    var phi_5658_: f32;
    var phi_5700_: f32;
    var phi_5701_: f32;
    var phi_5656_: u32;
    var phi_5659_: f32;
    var phi_7220_: bool;
    var local_28: f32;
    var phi_5729_: u32;
    var phi_5732_: f32;
    var local_29: f32;
    var phi_5774_: f32;
    var phi_5775_: f32;
    var phi_5730_: u32;
    var phi_5733_: f32;
    var phi_7259_: bool;
    var local_30: f32;
    var local_31: f32;
    var local_32: f32;
    var local_33: f32;
    var local_34: f32;
    var local_35: f32;
    var local_36: f32;
    var phi_5834_: vec3<f32>;
    var phi_5849_: bool;
    var phi_6039_: f32;
    var phi_6089_: u32;
    var phi_6092_: u32;
    var phi_6093_: u32;
    var phi_6094_: bool;
    var phi_6104_: u32;
    var phi_7267_: bool;
    var phi_6106_: f32;
    var phi_6107_: u32;
    var phi_6108_: u32;
    var phi_7266_: bool;
    var phi_5621_: f32;
    var phi_5624_: u32;
    var phi_5626_: u32;
    var phi_6110_: bool;
    var phi_7265_: bool;
    var phi_4822_: bool;
    var phi_5138_: f32;
    var phi_5188_: u32;
    var phi_5191_: u32;
    var phi_5192_: u32;
    var phi_5193_: bool;
    var phi_5206_: u32;
    var phi_7336_: bool;
    var phi_6115_: u32;
    var phi_6116_: u32;
    var phi_4350_: bool;
    var phi_4666_: f32;
    var phi_4716_: u32;
    var phi_4719_: u32;
    var phi_4720_: u32;
    var phi_4721_: bool;
    var phi_4734_: u32;
    var phi_7301_: bool;
    var phi_6117_: u32;
    var phi_6118_: u32;
    var phi_6119_: bool;
    var phi_7299_: bool;
    var phi_6520_: u32;
    var phi_7298_: bool;
    var phi_1198_: u32;
    var phi_1201_: u32;
    var phi_7297_: bool;
    var local_37: u32;
    var phi_6601_: u32;
    var phi_6604_: f32;
    var local_38: u32;
    var phi_6602_: u32;
    var phi_6605_: f32;
    var phi_7405_: bool;
    var local_39: f32;
    var phi_7416_: bool;
    var phi_6654_: f32;
    var phi_6655_: f32;
    var phi_6549_: u32;
    var phi_6552_: f32;
    var phi_6554_: f32;
    var local_40: u32;
    var phi_6550_: u32;
    var phi_6553_: f32;
    var phi_6555_: f32;
    var local_41: f32;
    var phi_7410_: bool;
    var phi_6656_: f32;
    var phi_6657_: f32;
    var phi_7409_: bool;
    var phi_1007_: u32;
    var phi_1010_: f32;
    var phi_1012_: f32;
    var phi_7408_: bool;
    var local_42: f32;
    var local_43: f32;
    var local_44: f32;
    var phi_6665_: f32;
    var phi_6677_: f32;
    var phi_6678_: f32;
    var local_45: f32;
    var local_46: f32;
    var local_47: u32;
    var local_48: f32;
    var local_49: f32;
    var local_50: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e182 = id_1;
            let _e187 = arrayLength((&mips.member));
            let _e190 = arrayLength((&sd_map.member));
            let _e193 = (override_type == 0u);
            if _e193 {
                let _e225 = params.member.member_4;
                phi_334_ = _e225;
            } else {
                let _e203 = params.member.member_4.member;
                let _e207 = params.member.member_4.member_1;
                let _e211 = params.member.member_4.member_10;
                let _e215 = params.member.member_4.member_11;
                let _e219 = params.member.member_4.member_12;
                let _e223 = params.member.member_4.member_14;
                phi_334_ = type_26(_e203, _e207, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e211, _e215, _e219, override_type_9, _e223);
            }
            let _e227 = phi_334_;
            if _e193 {
                let _e230 = params.member.member_2;
                phi_341_ = _e230;
            } else {
                phi_341_ = override_type_10;
            }
            let _e232 = phi_341_;
            if _e193 {
                let _e235 = params.member.member_3;
                phi_348_ = _e235;
            } else {
                phi_348_ = override_type_11;
            }
            let _e237 = phi_348_;
            let _e240 = params.member.member;
            let _e243 = params.member.member_1;
            let _e251 = select(select(u32(_e227.member.member.x), 0u, (_e227.member.member.x < 0f)), 4294967295u, (_e227.member.member.x > 4294967000f));
            let _e259 = select(select(u32(_e227.member.member.y), 0u, (_e227.member.member.y < 0f)), 4294967295u, (_e227.member.member.y > 4294967000f));
            if (_e182.x >= _e251) {
            } else {
                if (_e182.y >= _e259) {
                } else {
                    if (0u < arrayLength((&frame.member))) {
                    } else {
                        break;
                    }
                    let _e269 = ((_e182.y * _e251) + _e182.x);
                    let _e272 = mips.member[_e269];
                    let _e273 = bitcast<i32>(_e182.x);
                    let _e274 = (_e273 + -1i);
                    let _e276 = select(0i, _e274, (0i < _e274));
                    let _e278 = (bitcast<i32>(_e251) - 1i);
                    let _e282 = bitcast<i32>(_e182.y);
                    let _e284 = select(0i, _e282, (0i < _e282));
                    let _e286 = (bitcast<i32>(_e259) - 1i);
                    let _e290 = (bitcast<u32>(select(_e284, _e286, (_e286 < _e284))) * _e251);
                    let _e294 = mips.member[(_e290 + bitcast<u32>(select(_e276, _e278, (_e278 < _e276))))];
                    let _e295 = (_e273 + 1i);
                    let _e297 = select(0i, _e295, (0i < _e295));
                    let _e304 = mips.member[(_e290 + bitcast<u32>(select(_e297, _e278, (_e278 < _e297))))];
                    let _e306 = select(0i, _e273, (0i < _e273));
                    let _e309 = bitcast<u32>(select(_e306, _e278, (_e278 < _e306)));
                    let _e310 = (_e282 + -1i);
                    let _e312 = select(0i, _e310, (0i < _e310));
                    let _e320 = mips.member[((bitcast<u32>(select(_e312, _e286, (_e286 < _e312))) * _e251) + _e309)];
                    let _e321 = (_e282 + 1i);
                    let _e323 = select(0i, _e321, (0i < _e321));
                    let _e331 = mips.member[((bitcast<u32>(select(_e323, _e286, (_e286 < _e323))) * _e251) + _e309)];
                    let _e332 = (_e294 - _e272);
                    let _e333 = (_e304 - _e272);
                    let _e334 = (_e320 - _e272);
                    let _e335 = (_e331 - _e272);
                    let _e337 = ((_e333 - _e332) * 0.5f);
                    let _e339 = ((_e335 - _e334) * 0.5f);
                    let _e340 = (_e272 * 0.011f);
                    let _e342 = abs(_e332);
                    let _e343 = abs((_e332 + _e337));
                    let _e349 = (1.25f - (select(_e343, _e342, ((_e342 < _e343) || (_e343 != _e343))) / _e340));
                    let _e353 = select(0f, select(1f, _e349, (_e349 < 1f)), (_e349 > 0f));
                    let _e355 = abs(_e333);
                    let _e356 = abs((_e333 - _e337));
                    let _e362 = (1.25f - (select(_e356, _e355, ((_e355 < _e356) || (_e356 != _e356))) / _e340));
                    let _e366 = select(0f, select(1f, _e362, (_e362 < 1f)), (_e362 > 0f));
                    let _e368 = abs(_e334);
                    let _e369 = abs((_e334 + _e339));
                    let _e375 = (1.25f - (select(_e369, _e368, ((_e368 < _e369) || (_e369 != _e369))) / _e340));
                    let _e379 = select(0f, select(1f, _e375, (_e375 < 1f)), (_e375 > 0f));
                    let _e381 = abs(_e335);
                    let _e382 = abs((_e335 - _e339));
                    let _e388 = (1.25f - (select(_e382, _e381, ((_e381 < _e382) || (_e382 != _e382))) / _e340));
                    let _e392 = select(0f, select(1f, _e388, (_e388 < 1f)), (_e388 > 0f));
                    let _e398 = round((select(0f, select(1f, _e353, (_e353 < 1f)), (_e353 > 0f)) * 2.9f));
                    let _e413 = round((select(0f, select(1f, _e366, (_e366 < 1f)), (_e366 > 0f)) * 2.9f));
                    let _e429 = round((select(0f, select(1f, _e379, (_e379 < 1f)), (_e379 > 0f)) * 2.9f));
                    let _e445 = round((select(0f, select(1f, _e392, (_e392 < 1f)), (_e392 > 0f)) * 2.9f));
                    let _e457 = ((f32(_e273) + 0.5f) / _e227.member.member.x);
                    let _e460 = ((f32(_e282) + 0.5f) / _e227.member.member.y);
                    let _e461 = (_e272 * 0.99999f);
                    let _e468 = ((((_e457 * 2f) - 1f) * _e227.member.member_1.x) * _e461);
                    let _e475 = ((((_e460 * -2f) + 1f) * _e227.member.member_1.y) * _e461);
                    let _e476 = vec3<f32>(_e468, _e475, _e461);
                    let _e477 = -(_e468);
                    let _e478 = -(_e475);
                    let _e479 = (_e272 * -0.99999f);
                    let _e486 = (1f / sqrt((((_e477 * _e477) + (_e478 * _e478)) + (_e479 * _e479))));
                    let _e487 = (_e477 * _e486);
                    let _e488 = (_e478 * _e486);
                    let _e489 = (_e479 * _e486);
                    let _e492 = normals.member[_e269];
                    let _e495 = f32(bitcast<i32>((_e492 & 255u)));
                    let _e499 = (select(_e495, (_e495 - 256f), (_e495 >= 128f)) * 0.007874016f);
                    let _e502 = select(-1f, _e499, ((_e499 > -1f) || false));
                    let _e507 = f32(bitcast<i32>(((_e492 >> bitcast<u32>(8u)) & 255u)));
                    let _e511 = (select(_e507, (_e507 - 256f), (_e507 >= 128f)) * 0.007874016f);
                    let _e514 = select(-1f, _e511, ((_e511 > -1f) || false));
                    let _e516 = (1f - abs(_e502));
                    let _e517 = abs(_e514);
                    let _e518 = (_e516 - _e517);
                    let _e519 = (_e518 < 0f);
                    let _e527 = select(_e502, ((1f - _e517) * select(1f, -1f, (_e502 < 0f))), _e519);
                    let _e528 = select(_e514, (_e516 * select(1f, -1f, (_e514 < 0f))), _e519);
                    let _e535 = (1f / sqrt((((_e527 * _e527) + (_e528 * _e528)) + (_e518 * _e518))));
                    let _e536 = (_e527 * _e535);
                    let _e537 = (_e528 * _e535);
                    let _e538 = (_e518 * _e535);
                    let _e539 = -(_e538);
                    let _e545 = ((((_e536 * _e487) + (_e537 * _e488)) + (_e539 * _e489)) < 0f);
                    let _e548 = select(_e536, -(_e536), _e545);
                    let _e549 = select(_e537, -(_e537), _e545);
                    let _e550 = select(_e539, _e538, _e545);
                    let _e557 = ((_e227.member_1 * _e227.member_2) / (((_e272 * 1.99998f) * _e227.member.member_1.x) / _e227.member.member.x));
                    let _e560 = (_e182.x & 63u);
                    let _e561 = (_e182.y & 63u);
                    let _e564 = ((_e560 >> bitcast<u32>(5u)) & 1u);
                    let _e567 = ((_e561 >> bitcast<u32>(5u)) & 1u);
                    let _e571 = (_e567 ^ 1u);
                    let _e573 = ((_e564 & _e571) * 63u);
                    let _e574 = (_e560 ^ _e573);
                    let _e575 = (_e561 ^ _e573);
                    let _e577 = ((_e574 ^ _e575) * _e571);
                    let _e578 = (_e574 ^ _e577);
                    let _e579 = (_e575 ^ _e577);
                    let _e582 = ((_e578 >> bitcast<u32>(4u)) & 1u);
                    let _e585 = ((_e579 >> bitcast<u32>(4u)) & 1u);
                    let _e590 = (_e585 ^ 1u);
                    let _e592 = ((_e582 & _e590) * 63u);
                    let _e593 = (_e578 ^ _e592);
                    let _e594 = (_e579 ^ _e592);
                    let _e596 = ((_e593 ^ _e594) * _e590);
                    let _e597 = (_e593 ^ _e596);
                    let _e598 = (_e594 ^ _e596);
                    let _e601 = ((_e597 >> bitcast<u32>(3u)) & 1u);
                    let _e604 = ((_e598 >> bitcast<u32>(3u)) & 1u);
                    let _e609 = (_e604 ^ 1u);
                    let _e611 = ((_e601 & _e609) * 63u);
                    let _e612 = (_e597 ^ _e611);
                    let _e613 = (_e598 ^ _e611);
                    let _e615 = ((_e612 ^ _e613) * _e609);
                    let _e616 = (_e612 ^ _e615);
                    let _e617 = (_e613 ^ _e615);
                    let _e620 = ((_e616 >> bitcast<u32>(2u)) & 1u);
                    let _e623 = ((_e617 >> bitcast<u32>(2u)) & 1u);
                    let _e628 = (_e623 ^ 1u);
                    let _e630 = ((_e620 & _e628) * 63u);
                    let _e631 = (_e616 ^ _e630);
                    let _e632 = (_e617 ^ _e630);
                    let _e634 = ((_e631 ^ _e632) * _e628);
                    let _e635 = (_e631 ^ _e634);
                    let _e636 = (_e632 ^ _e634);
                    let _e639 = ((_e635 >> bitcast<u32>(1u)) & 1u);
                    let _e642 = ((_e636 >> bitcast<u32>(1u)) & 1u);
                    let _e647 = (_e642 ^ 1u);
                    let _e649 = ((_e639 & _e647) * 63u);
                    let _e650 = (_e635 ^ _e649);
                    let _e651 = (_e636 ^ _e649);
                    let _e653 = ((_e650 ^ _e651) * _e647);
                    let _e665 = f32(bitcast<i32>((((((((((_e564 * 3u) ^ _e567) * 1024u) + (((_e582 * 3u) ^ _e585) * 256u)) + (((_e601 * 3u) ^ _e604) * 64u)) + (((_e620 * 3u) ^ _e623) * 16u)) + (((_e639 * 3u) ^ _e642) * 4u)) + ((((_e650 ^ _e653) & 1u) * 3u) ^ ((_e651 ^ _e653) & 1u))) + (288u * (_e227.member_11 % 64u)))));
                    let _e667 = ((_e665 * 0.7548777f) + 0.5f);
                    let _e671 = ((_e665 * 0.5698403f) + 0.5f);
                    let _e677 = exp2(((2f * _e227.member_7) + 1f));
                    let _e682 = select(false, (_e272 < _e227.member.member_3), (_e272 > 0f));
                    if _e682 {
                        let _e685 = select(1u, _e227.member_8, (1u < _e227.member_8));
                        phi_6952_ = false;
                        phi_1006_ = 0u;
                        phi_1009_ = 0f;
                        phi_1011_ = 0f;
                        loop {
                            let _e687 = phi_6952_;
                            let _e689 = phi_1006_;
                            let _e691 = phi_1009_;
                            let _e693 = phi_1011_;
                            local_42 = _e691;
                            local_43 = _e693;
                            local_44 = _e691;
                            let _e694 = (_e689 < _e685);
                            if _e694 {
                                let _e701 = ((((_e667 - floor(_e667)) + f32(bitcast<i32>(_e689))) * 3.1415927f) / f32(bitcast<i32>(_e685)));
                                let _e702 = sin(_e701);
                                let _e703 = cos(_e701);
                                let _e709 = ((_e703 * _e487) + (_e702 * _e488));
                                let _e713 = (_e703 - (_e487 * _e709));
                                let _e714 = (_e702 - (_e488 * _e709));
                                let _e715 = -((_e489 * _e709));
                                let _e718 = ((_e714 * _e489) - (_e488 * _e715));
                                let _e721 = ((_e715 * _e487) - (_e489 * _e713));
                                let _e724 = ((_e713 * _e488) - (_e487 * _e714));
                                let _e731 = (1f / sqrt((((_e718 * _e718) + (_e721 * _e721)) + (_e724 * _e724))));
                                let _e732 = (_e718 * _e731);
                                let _e733 = (_e721 * _e731);
                                let _e734 = (_e724 * _e731);
                                let _e739 = (((_e548 * _e732) + (_e549 * _e733)) + (_e550 * _e734));
                                let _e743 = (_e548 - (_e732 * _e739));
                                let _e744 = (_e549 - (_e733 * _e739));
                                let _e745 = (_e550 - (_e734 * _e739));
                                let _e751 = sqrt((((_e743 * _e743) + (_e744 * _e744)) + (_e745 * _e745)));
                                let _e756 = (((_e713 * _e743) + (_e714 * _e744)) + (_e715 * _e745));
                                let _e766 = ((((_e743 * _e487) + (_e744 * _e488)) + (_e745 * _e489)) / _e751);
                                let _e770 = select(0f, select(1f, _e766, (_e766 < 1f)), (_e766 > 0f));
                                let _e771 = abs(_e770);
                                let _e782 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e771, 0.00667009f), _e771, -0.017088126f), _e771, 0.03089188f), _e771, -0.050174303f), _e771, 0.08897899f), _e771, -0.2145988f), _e771, 1.5707963f) * sqrt((1f - _e771)));
                                let _e785 = (select(select(0f, -1f, (_e756 < 0f)), 1f, (_e756 > 0f)) * select((3.1415927f - _e782), _e782, (_e770 >= 0f)));
                                let _e788 = select(1u, _e227.member_9, (1u < _e227.member_9));
                                phi_6943_ = _e687;
                                phi_1197_ = 0u;
                                phi_1200_ = 0u;
                                loop {
                                    let _e790 = phi_6943_;
                                    let _e792 = phi_1197_;
                                    let _e794 = phi_1200_;
                                    local_37 = _e794;
                                    local_38 = _e794;
                                    local_40 = _e794;
                                    let _e795 = (_e792 < _e788);
                                    if _e795 {
                                        let _e801 = ((_e671 - floor(_e671)) + (f32(bitcast<i32>((_e689 + (_e792 * _e788)))) * 0.618034f));
                                        let _e810 = (((_e801 - floor(_e801)) + f32(bitcast<i32>(_e792))) * (1f / f32(bitcast<i32>(_e788))));
                                        if (_e227.member_4 == 2f) {
                                            phi_1258_ = (_e810 * _e810);
                                        } else {
                                            if (_e227.member_4 == 1f) {
                                                phi_1257_ = _e810;
                                            } else {
                                                phi_1257_ = pow(_e810, _e227.member_4);
                                            }
                                            let _e816 = phi_1257_;
                                            phi_1258_ = _e816;
                                        }
                                        let _e819 = phi_1258_;
                                        let _e820 = (_e819 + (1.3f / _e557));
                                        let _e821 = ((_e703 * _e557) * _e820);
                                        let _e822 = ((-(_e702) * _e557) * _e820);
                                        let _e825 = ((_e821 * _e821) + (_e822 * _e822));
                                        let _e830 = (select(1u, _e251, (1u < _e251)) * select(1u, _e259, (1u < _e259)));
                                        let _e831 = (_e825 > _e677);
                                        let _e835 = (_e251 >> bitcast<u32>(1u));
                                        let _e839 = (_e259 >> bitcast<u32>(1u));
                                        let _e843 = (_e830 + (select(1u, _e835, (1u < _e835)) * select(1u, _e839, (1u < _e839))));
                                        let _e845 = (_e825 > (_e677 * 4f));
                                        let _e849 = (_e251 >> bitcast<u32>(2u));
                                        let _e853 = (_e259 >> bitcast<u32>(2u));
                                        let _e857 = (_e843 + (select(1u, _e849, (1u < _e849)) * select(1u, _e853, (1u < _e853))));
                                        let _e859 = (_e825 > (_e677 * 16f));
                                        let _e863 = (_e251 >> bitcast<u32>(3u));
                                        let _e867 = (_e259 >> bitcast<u32>(3u));
                                        let _e873 = (_e825 > (_e677 * 64f));
                                        let _e875 = select(select(select(select(0u, _e830, _e831), _e843, _e845), _e857, _e859), (_e857 + (select(1u, _e863, (1u < _e863)) * select(1u, _e867, (1u < _e867)))), _e873);
                                        let _e876 = (select(select(select(select(0u, 1u, _e831), 2u, _e845), 3u, _e859), 4u, _e873) & 31u);
                                        let _e878 = (_e251 >> bitcast<u32>(_e876));
                                        let _e880 = select(1u, _e878, (1u < _e878));
                                        let _e882 = (_e259 >> bitcast<u32>(_e876));
                                        let _e884 = select(1u, _e882, (1u < _e882));
                                        let _e887 = (round(_e821) * (1f / _e227.member.member.x));
                                        let _e890 = (round(_e822) * (1f / _e227.member.member.y));
                                        let _e891 = (_e457 + _e887);
                                        let _e892 = (_e460 + _e890);
                                        let _e893 = (_e457 - _e887);
                                        let _e894 = (_e460 - _e890);
                                        let _e896 = f32(bitcast<i32>(_e880));
                                        let _e897 = (_e891 * _e896);
                                        let _e900 = f32(bitcast<i32>((_e880 - 1u)));
                                        let _e910 = f32(bitcast<i32>(_e884));
                                        let _e911 = (_e892 * _e910);
                                        let _e914 = f32(bitcast<i32>((_e884 - 1u)));
                                        let _e928 = mips.member[((_e875 + ((bitcast<u32>((floor(select(0f, select(_e914, _e911, (_e911 < _e914)), (_e911 > 0f))) + 8388608f)) - 1258291200u) * _e880)) + (bitcast<u32>((floor(select(0f, select(_e900, _e897, (_e897 < _e900)), (_e897 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e932 = ((((_e891 * 2f) - 1f) * _e227.member.member_1.x) * _e928);
                                        let _e936 = ((((_e892 * -2f) + 1f) * _e227.member.member_1.y) * _e928);
                                        let _e937 = (_e893 * _e896);
                                        let _e946 = (_e894 * _e910);
                                        let _e960 = mips.member[((_e875 + ((bitcast<u32>((floor(select(0f, select(_e914, _e946, (_e946 < _e914)), (_e946 > 0f))) + 8388608f)) - 1258291200u) * _e880)) + (bitcast<u32>((floor(select(0f, select(_e900, _e937, (_e937 < _e900)), (_e937 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e964 = ((((_e893 * 2f) - 1f) * _e227.member.member_1.x) * _e960);
                                        let _e968 = ((((_e894 * -2f) + 1f) * _e227.member.member_1.y) * _e960);
                                        let _e969 = (_e932 - _e468);
                                        let _e970 = (_e936 - _e475);
                                        let _e971 = (_e928 - _e461);
                                        let _e976 = (((_e969 * _e969) + (_e970 * _e970)) + (_e971 * _e971));
                                        let _e977 = (_e243 <= 0f);
                                        if _e977 {
                                            phi_1539_ = true;
                                        } else {
                                            phi_1539_ = (_e976 <= (_e243 * _e243));
                                        }
                                        let _e981 = phi_1539_;
                                        if _e981 {
                                            phi_1555_ = ((((_e969 * _e548) + (_e970 * _e549)) + (_e971 * _e550)) > (0.018f * sqrt(_e976)));
                                        } else {
                                            phi_1555_ = false;
                                        }
                                        let _e991 = phi_1555_;
                                        if _e991 {
                                            let _e1222 = (0.5f / _e928);
                                            let _e1228 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e1236 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e1241 = frame.member[0u].member_1.member_5[0u];
                                            let _e1244 = frame.member[0u].member_1.member_5[1u];
                                            let _e1245 = f32(_e1241);
                                            let _e1246 = f32(_e1244);
                                            let _e1248 = frame.member[0u].member_1.member_4;
                                            let _e1249 = f32(_e1248);
                                            let _e1250 = (2u * _e1248);
                                            let _e1251 = (_e1241 + _e1250);
                                            let _e1257 = (floor(((((_e932 * _e1222) / _e1228) + 0.5f) * _e1245)) + _e1249);
                                            let _e1258 = f32((_e1251 - 1u));
                                            let _e1262 = select(0f, select(_e1258, _e1257, (_e1257 < _e1258)), (_e1257 > 0f));
                                            let _e1265 = (floor(((0.5f - ((_e936 * _e1222) / _e1236)) * _e1246)) + _e1249);
                                            let _e1266 = f32(((_e1244 + _e1250) - 1u));
                                            let _e1270 = select(0f, select(_e1266, _e1265, (_e1265 < _e1266)), (_e1265 > 0f));
                                            let _e1275 = select(select(u32(_e1262), 0u, (_e1262 < 0f)), 4294967295u, (_e1262 > 4294967000f));
                                            let _e1280 = select(select(u32(_e1270), 0u, (_e1270 < 0f)), 4294967295u, (_e1270 > 4294967000f));
                                            let _e1283 = bitcast<i32>(_e1248);
                                            let _e1289 = frame.member[0u].member_1.member_8;
                                            let _e1291 = frame.member[0u].member_1.member_12;
                                            let _e1298 = (((((_e1280 % 4u) * 4u) + (_e1275 % 4u)) + (_e1291 % 16u)) % 16u);
                                            if (_e1289 == 1u) {
                                                local_5 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                let _e1311 = (_e1298 < 16u);
                                                if _e1311 {
                                                } else {
                                                    phi_7297_ = true;
                                                    break;
                                                }
                                                let _e1314 = local_5[_e1298][0u];
                                                local_6 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                if _e1311 {
                                                } else {
                                                    phi_7297_ = true;
                                                    break;
                                                }
                                                let _e1317 = local_6[_e1298][1u];
                                                phi_1715_ = vec2<f32>(_e1314, _e1317);
                                            } else {
                                                if (_e1289 == 2u) {
                                                    local_7 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    let _e1301 = (_e1298 < 16u);
                                                    if _e1301 {
                                                    } else {
                                                        phi_7297_ = true;
                                                        break;
                                                    }
                                                    let _e1304 = local_7[_e1298][0u];
                                                    local_8 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    if _e1301 {
                                                    } else {
                                                        phi_7297_ = true;
                                                        break;
                                                    }
                                                    let _e1307 = local_8[_e1298][1u];
                                                    phi_1714_ = vec2<f32>(_e1304, _e1307);
                                                } else {
                                                    phi_1714_ = vec2<f32>(0.5f, 0.5f);
                                                }
                                                let _e1310 = phi_1714_;
                                                phi_1715_ = _e1310;
                                            }
                                            let _e1320 = phi_1715_;
                                            let _e1325 = ((f32((bitcast<i32>(_e1275) - _e1283)) + _e1320.x) / _e1245);
                                            let _e1326 = ((f32((bitcast<i32>(_e1280) - _e1283)) + _e1320.y) / _e1246);
                                            let _e1331 = frame.member[0u].member_1.member.member.member[0u];
                                            let _e1336 = select(select(u32(_e1331), 0u, (_e1331 < 0f)), 4294967295u, (_e1331 > 4294967000f));
                                            let _e1341 = frame.member[0u].member_1.member.member.member[1u];
                                            let _e1351 = (select(0f, select(1f, _e1325, (_e1325 < 1f)), (_e1325 > 0f)) * _e1331);
                                            let _e1354 = f32(bitcast<i32>((_e1336 - 1u)));
                                            let _e1367 = (select(0f, select(1f, _e1326, (_e1326 < 1f)), (_e1326 > 0f)) * _e1341);
                                            let _e1370 = f32(bitcast<i32>((select(select(u32(_e1341), 0u, (_e1341 < 0f)), 4294967295u, (_e1341 > 4294967000f)) - 1u)));
                                            let _e1380 = (((bitcast<u32>((floor(select(0f, select(_e1370, _e1367, (_e1367 < _e1370)), (_e1367 > 0f))) + 8388608f)) - 1258291200u) * _e1336) + (bitcast<u32>((floor(select(0f, select(_e1354, _e1351, (_e1351 < _e1354)), (_e1351 > 0f))) + 8388608f)) - 1258291200u));
                                            if (_e1380 < _e187) {
                                            } else {
                                                phi_7297_ = true;
                                                break;
                                            }
                                            let _e1383 = mips.member[_e1380];
                                            if (abs((_e1383 - _e928)) > _e240) {
                                                if (_e243 > 0f) {
                                                    phi_1848_ = (_e976 > (_e243 * _e243));
                                                } else {
                                                    phi_1848_ = false;
                                                }
                                                let _e2210 = phi_1848_;
                                                if !(_e2210) {
                                                    let _e2216 = (((_e969 * _e487) + (_e970 * _e488)) + (_e971 * _e489));
                                                    let _e2220 = (_e969 - (_e487 * _e2216));
                                                    let _e2221 = (_e970 - (_e488 * _e2216));
                                                    let _e2222 = (_e971 - (_e489 * _e2216));
                                                    let _e2225 = ((_e2221 * _e489) - (_e488 * _e2222));
                                                    let _e2228 = ((_e2222 * _e487) - (_e489 * _e2220));
                                                    let _e2231 = ((_e2220 * _e488) - (_e487 * _e2221));
                                                    let _e2242 = ((((_e548 * _e2225) + (_e549 * _e2228)) + (_e550 * _e2231)) / (((_e2225 * _e2225) + (_e2228 * _e2228)) + (_e2231 * _e2231)));
                                                    let _e2246 = (_e548 - (_e2225 * _e2242));
                                                    let _e2247 = (_e549 - (_e2228 * _e2242));
                                                    let _e2248 = (_e550 - (_e2231 * _e2242));
                                                    let _e2254 = inverseSqrt((((_e2246 * _e2246) + (_e2247 * _e2247)) + (_e2248 * _e2248)));
                                                    let _e2260 = ((((_e2246 * _e487) + (_e2247 * _e488)) + (_e2248 * _e489)) * _e2254);
                                                    let _e2264 = select(0f, select(1f, _e2260, (_e2260 < 1f)), (_e2260 > 0f));
                                                    let _e2265 = abs(_e2264);
                                                    let _e2275 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2265, 0.00667009f), _e2265, -0.017088126f), _e2265, 0.03089188f), _e2265, -0.050174303f), _e2265, 0.08897899f), _e2265, -0.2145988f), _e2265, 1.5707963f) * sqrt((1f - _e2265)));
                                                    let _e2278 = select((3.1415927f - _e2275), _e2275, (_e2264 >= 0f));
                                                    let _e2286 = select(_e2278, -(_e2278), ((((_e2220 * _e2246) + (_e2221 * _e2247)) + (_e2222 * _e2248)) < 0f));
                                                    let _e2287 = (_e2254 * 0.02f);
                                                    let _e2290 = select(0.19634955f, _e2287, ((_e2287 < 0.19634955f) || false));
                                                    let _e2300 = (_e969 - (_e487 * _e240));
                                                    let _e2301 = (_e970 - (_e488 * _e240));
                                                    let _e2302 = (_e971 - (_e489 * _e240));
                                                    let _e2304 = (_e2216 * inverseSqrt(_e976));
                                                    let _e2308 = select(-1f, select(1f, _e2304, (_e2304 < 1f)), (_e2304 > -1f));
                                                    let _e2309 = abs(_e2308);
                                                    let _e2319 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2309, 0.00667009f), _e2309, -0.017088126f), _e2309, 0.03089188f), _e2309, -0.050174303f), _e2309, 0.08897899f), _e2309, -0.2145988f), _e2309, 1.5707963f) * sqrt((1f - _e2309)));
                                                    let _e2326 = ((((select((3.1415927f - _e2319), _e2319, (_e2308 >= 0f)) + _e2290) - _e2286) + 1.5707964f) * 0.31830987f);
                                                    let _e2330 = select(0f, select(1f, _e2326, (_e2326 < 1f)), (_e2326 > 0f));
                                                    let _e2342 = ((((_e2300 * _e487) + (_e2301 * _e488)) + (_e2302 * _e489)) * inverseSqrt((((_e2300 * _e2300) + (_e2301 * _e2301)) + (_e2302 * _e2302))));
                                                    let _e2346 = select(-1f, select(1f, _e2342, (_e2342 < 1f)), (_e2342 > -1f));
                                                    let _e2347 = abs(_e2346);
                                                    let _e2357 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2347, 0.00667009f), _e2347, -0.017088126f), _e2347, 0.03089188f), _e2347, -0.050174303f), _e2347, 0.08897899f), _e2347, -0.2145988f), _e2347, 1.5707963f) * sqrt((1f - _e2347)));
                                                    let _e2364 = ((((select((3.1415927f - _e2357), _e2357, (_e2346 >= 0f)) + _e2290) - _e2286) + 1.5707964f) * 0.31830987f);
                                                    let _e2368 = select(0f, select(1f, _e2364, (_e2364 < 1f)), (_e2364 > 0f));
                                                    let _e2370 = (_e2368 != _e2368);
                                                    let _e2372 = select(_e2368, _e2330, ((_e2330 < _e2368) || _e2370));
                                                    let _e2375 = select(_e2368, _e2330, ((_e2330 > _e2368) || _e2370));
                                                    let _e2377 = floor((_e2372 * 32f));
                                                    if (_e237 == 1u) {
                                                        let _e2385 = -(floor((_e2375 * -32f)));
                                                        let _e2390 = (select(32f, _e2385, ((_e2385 < 32f) || false)) - _e2377);
                                                        phi_2164_ = select(select(0f, _e2390, ((_e2390 > 0f) || false)), 0f, (_e2375 <= _e2372));
                                                    } else {
                                                        phi_2164_ = -(floor(((_e2375 - _e2372) * -32f)));
                                                    }
                                                    let _e2396 = phi_2164_;
                                                    let _e2404 = (bitcast<u32>((floor(select(0f, select(32f, _e2377, (_e2377 < 32f)), (_e2377 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e2412 = (bitcast<u32>((floor(select(0f, select(32f, _e2396, (_e2396 < 32f)), (_e2396 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e2404 >= 32u) {
                                                        phi_2218_ = u32();
                                                        phi_2219_ = true;
                                                    } else {
                                                        let _e2414 = (_e2412 == 0u);
                                                        if _e2414 {
                                                            phi_2217_ = u32();
                                                        } else {
                                                            if (_e2412 >= 32u) {
                                                                phi_2214_ = 4294967295u;
                                                            } else {
                                                                phi_2214_ = ((1u << bitcast<u32>((_e2412 & 31u))) - 1u);
                                                            }
                                                            let _e2421 = phi_2214_;
                                                            phi_2217_ = (_e2421 << bitcast<u32>((_e2404 & 31u)));
                                                        }
                                                        let _e2426 = phi_2217_;
                                                        phi_2218_ = _e2426;
                                                        phi_2219_ = _e2414;
                                                    }
                                                    let _e2428 = phi_2218_;
                                                    let _e2430 = phi_2219_;
                                                    phi_2232_ = select(select(select(_e2428, 0u, _e2430), 0u, ((((_e2220 * _e2220) + (_e2221 * _e2221)) + (_e2222 * _e2222)) <= 0f)), 0u, _e2210);
                                                } else {
                                                    phi_2232_ = 0u;
                                                }
                                                let _e2435 = phi_2232_;
                                                phi_7115_ = _e790;
                                                phi_3615_ = _e2435;
                                                phi_3616_ = u32();
                                                phi_3617_ = true;
                                            } else {
                                                let _e1391 = frame.member[0u].member_1.member_6;
                                                let _e1392 = (((_e1280 * _e1251) + _e1275) * _e1391);
                                                let _e1396 = frame.member[0u].member_1.member.member.member_3;
                                                phi_2255_ = 0u;
                                                phi_2258_ = _e1396;
                                                loop {
                                                    let _e1398 = phi_2255_;
                                                    let _e1400 = phi_2258_;
                                                    local_9 = _e1400;
                                                    local_10 = _e1400;
                                                    local_11 = _e1400;
                                                    local_12 = _e1400;
                                                    local_13 = _e1400;
                                                    local_45 = _e1400;
                                                    let _e1401 = (_e1398 < _e1391);
                                                    if _e1401 {
                                                        let _e1402 = (_e1392 + _e1398);
                                                        if (_e1402 < _e190) {
                                                        } else {
                                                            phi_6894_ = true;
                                                            break;
                                                        }
                                                        let _e1405 = sd_map.member[_e1402];
                                                        let _e1409 = frame.member[0u].member_1.member.member.member_2;
                                                        let _e1412 = ((_e1405 * (_e1396 - _e1409)) + _e1409);
                                                        if (_e1405 < 1f) {
                                                            if (_e1412 > (_e928 * 1.001f)) {
                                                                phi_2300_ = select(_e1400, _e1412, (_e1412 < _e1400));
                                                            } else {
                                                                phi_2300_ = _e1400;
                                                            }
                                                            let _e1418 = phi_2300_;
                                                            phi_2301_ = _e1418;
                                                        } else {
                                                            phi_2301_ = _e1400;
                                                        }
                                                        let _e1420 = phi_2301_;
                                                        phi_2256_ = (_e1398 + 1u);
                                                        phi_2259_ = _e1420;
                                                    } else {
                                                        phi_2256_ = u32();
                                                        phi_2259_ = f32();
                                                    }
                                                    let _e1423 = phi_2256_;
                                                    let _e1425 = phi_2259_;
                                                    continue;
                                                    continuing {
                                                        phi_2255_ = _e1423;
                                                        phi_2258_ = _e1425;
                                                        phi_6894_ = _e790;
                                                        break if !(_e1401);
                                                    }
                                                }
                                                let _e1428 = phi_6894_;
                                                phi_7297_ = _e1428;
                                                if _e1428 {
                                                    break;
                                                }
                                                let _e1430 = local_9;
                                                let _e1431 = (_e1430 >= _e1396);
                                                if _e1431 {
                                                    if (_e243 > 0f) {
                                                        phi_2320_ = (_e976 > (_e243 * _e243));
                                                    } else {
                                                        phi_2320_ = false;
                                                    }
                                                    let _e1974 = phi_2320_;
                                                    if !(_e1974) {
                                                        let _e1980 = (((_e969 * _e487) + (_e970 * _e488)) + (_e971 * _e489));
                                                        let _e1984 = (_e969 - (_e487 * _e1980));
                                                        let _e1985 = (_e970 - (_e488 * _e1980));
                                                        let _e1986 = (_e971 - (_e489 * _e1980));
                                                        let _e1989 = ((_e1985 * _e489) - (_e488 * _e1986));
                                                        let _e1992 = ((_e1986 * _e487) - (_e489 * _e1984));
                                                        let _e1995 = ((_e1984 * _e488) - (_e487 * _e1985));
                                                        let _e2006 = ((((_e548 * _e1989) + (_e549 * _e1992)) + (_e550 * _e1995)) / (((_e1989 * _e1989) + (_e1992 * _e1992)) + (_e1995 * _e1995)));
                                                        let _e2010 = (_e548 - (_e1989 * _e2006));
                                                        let _e2011 = (_e549 - (_e1992 * _e2006));
                                                        let _e2012 = (_e550 - (_e1995 * _e2006));
                                                        let _e2018 = inverseSqrt((((_e2010 * _e2010) + (_e2011 * _e2011)) + (_e2012 * _e2012)));
                                                        let _e2024 = ((((_e2010 * _e487) + (_e2011 * _e488)) + (_e2012 * _e489)) * _e2018);
                                                        let _e2028 = select(0f, select(1f, _e2024, (_e2024 < 1f)), (_e2024 > 0f));
                                                        let _e2029 = abs(_e2028);
                                                        let _e2039 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2029, 0.00667009f), _e2029, -0.017088126f), _e2029, 0.03089188f), _e2029, -0.050174303f), _e2029, 0.08897899f), _e2029, -0.2145988f), _e2029, 1.5707963f) * sqrt((1f - _e2029)));
                                                        let _e2042 = select((3.1415927f - _e2039), _e2039, (_e2028 >= 0f));
                                                        let _e2050 = select(_e2042, -(_e2042), ((((_e1984 * _e2010) + (_e1985 * _e2011)) + (_e1986 * _e2012)) < 0f));
                                                        let _e2051 = (_e2018 * 0.02f);
                                                        let _e2054 = select(0.19634955f, _e2051, ((_e2051 < 0.19634955f) || false));
                                                        let _e2064 = (_e969 - (_e487 * _e240));
                                                        let _e2065 = (_e970 - (_e488 * _e240));
                                                        let _e2066 = (_e971 - (_e489 * _e240));
                                                        let _e2068 = (_e1980 * inverseSqrt(_e976));
                                                        let _e2072 = select(-1f, select(1f, _e2068, (_e2068 < 1f)), (_e2068 > -1f));
                                                        let _e2073 = abs(_e2072);
                                                        let _e2083 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2073, 0.00667009f), _e2073, -0.017088126f), _e2073, 0.03089188f), _e2073, -0.050174303f), _e2073, 0.08897899f), _e2073, -0.2145988f), _e2073, 1.5707963f) * sqrt((1f - _e2073)));
                                                        let _e2090 = ((((select((3.1415927f - _e2083), _e2083, (_e2072 >= 0f)) + _e2054) - _e2050) + 1.5707964f) * 0.31830987f);
                                                        let _e2094 = select(0f, select(1f, _e2090, (_e2090 < 1f)), (_e2090 > 0f));
                                                        let _e2106 = ((((_e2064 * _e487) + (_e2065 * _e488)) + (_e2066 * _e489)) * inverseSqrt((((_e2064 * _e2064) + (_e2065 * _e2065)) + (_e2066 * _e2066))));
                                                        let _e2110 = select(-1f, select(1f, _e2106, (_e2106 < 1f)), (_e2106 > -1f));
                                                        let _e2111 = abs(_e2110);
                                                        let _e2121 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2111, 0.00667009f), _e2111, -0.017088126f), _e2111, 0.03089188f), _e2111, -0.050174303f), _e2111, 0.08897899f), _e2111, -0.2145988f), _e2111, 1.5707963f) * sqrt((1f - _e2111)));
                                                        let _e2128 = ((((select((3.1415927f - _e2121), _e2121, (_e2110 >= 0f)) + _e2054) - _e2050) + 1.5707964f) * 0.31830987f);
                                                        let _e2132 = select(0f, select(1f, _e2128, (_e2128 < 1f)), (_e2128 > 0f));
                                                        let _e2134 = (_e2132 != _e2132);
                                                        let _e2136 = select(_e2132, _e2094, ((_e2094 < _e2132) || _e2134));
                                                        let _e2139 = select(_e2132, _e2094, ((_e2094 > _e2132) || _e2134));
                                                        let _e2141 = floor((_e2136 * 32f));
                                                        if (_e237 == 1u) {
                                                            let _e2149 = -(floor((_e2139 * -32f)));
                                                            let _e2154 = (select(32f, _e2149, ((_e2149 < 32f) || false)) - _e2141);
                                                            phi_2636_ = select(select(0f, _e2154, ((_e2154 > 0f) || false)), 0f, (_e2139 <= _e2136));
                                                        } else {
                                                            phi_2636_ = -(floor(((_e2139 - _e2136) * -32f)));
                                                        }
                                                        let _e2160 = phi_2636_;
                                                        let _e2168 = (bitcast<u32>((floor(select(0f, select(32f, _e2141, (_e2141 < 32f)), (_e2141 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e2176 = (bitcast<u32>((floor(select(0f, select(32f, _e2160, (_e2160 < 32f)), (_e2160 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e2168 >= 32u) {
                                                            phi_2690_ = u32();
                                                            phi_2691_ = true;
                                                        } else {
                                                            let _e2178 = (_e2176 == 0u);
                                                            if _e2178 {
                                                                phi_2689_ = u32();
                                                            } else {
                                                                if (_e2176 >= 32u) {
                                                                    phi_2686_ = 4294967295u;
                                                                } else {
                                                                    phi_2686_ = ((1u << bitcast<u32>((_e2176 & 31u))) - 1u);
                                                                }
                                                                let _e2185 = phi_2686_;
                                                                phi_2689_ = (_e2185 << bitcast<u32>((_e2168 & 31u)));
                                                            }
                                                            let _e2190 = phi_2689_;
                                                            phi_2690_ = _e2190;
                                                            phi_2691_ = _e2178;
                                                        }
                                                        let _e2192 = phi_2690_;
                                                        let _e2194 = phi_2691_;
                                                        phi_2704_ = select(select(select(_e2192, 0u, _e2194), 0u, ((((_e1984 * _e1984) + (_e1985 * _e1985)) + (_e1986 * _e1986)) <= 0f)), 0u, _e1974);
                                                    } else {
                                                        phi_2704_ = 0u;
                                                    }
                                                    let _e2199 = phi_2704_;
                                                    phi_7150_ = _e1428;
                                                    phi_3613_ = _e2199;
                                                    phi_3614_ = u32();
                                                } else {
                                                    let _e1436 = (((_e969 * _e487) + (_e970 * _e488)) + (_e971 * _e489));
                                                    let _e1440 = (_e969 - (_e487 * _e1436));
                                                    let _e1441 = (_e970 - (_e488 * _e1436));
                                                    let _e1442 = (_e971 - (_e489 * _e1436));
                                                    let _e1445 = ((_e1441 * _e489) - (_e488 * _e1442));
                                                    let _e1448 = ((_e1442 * _e487) - (_e489 * _e1440));
                                                    let _e1451 = ((_e1440 * _e488) - (_e487 * _e1441));
                                                    let _e1462 = ((((_e548 * _e1445) + (_e549 * _e1448)) + (_e550 * _e1451)) / (((_e1445 * _e1445) + (_e1448 * _e1448)) + (_e1451 * _e1451)));
                                                    let _e1466 = (_e548 - (_e1445 * _e1462));
                                                    let _e1467 = (_e549 - (_e1448 * _e1462));
                                                    let _e1468 = (_e550 - (_e1451 * _e1462));
                                                    let _e1474 = inverseSqrt((((_e1466 * _e1466) + (_e1467 * _e1467)) + (_e1468 * _e1468)));
                                                    let _e1480 = ((((_e1466 * _e487) + (_e1467 * _e488)) + (_e1468 * _e489)) * _e1474);
                                                    let _e1484 = select(0f, select(1f, _e1480, (_e1480 < 1f)), (_e1480 > 0f));
                                                    let _e1485 = abs(_e1484);
                                                    let _e1495 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1485, 0.00667009f), _e1485, -0.017088126f), _e1485, 0.03089188f), _e1485, -0.050174303f), _e1485, 0.08897899f), _e1485, -0.2145988f), _e1485, 1.5707963f) * sqrt((1f - _e1485)));
                                                    let _e1498 = select((3.1415927f - _e1495), _e1495, (_e1484 >= 0f));
                                                    let _e1506 = select(_e1498, -(_e1498), ((((_e1440 * _e1466) + (_e1441 * _e1467)) + (_e1442 * _e1468)) < 0f));
                                                    let _e1507 = (_e1474 * 0.02f);
                                                    let _e1510 = select(0.19634955f, _e1507, ((_e1507 < 0.19634955f) || false));
                                                    let _e1516 = ((((_e1440 * _e1440) + (_e1441 * _e1441)) + (_e1442 * _e1442)) <= 0f);
                                                    let _e1517 = (_e487 * _e240);
                                                    let _e1518 = (_e488 * _e240);
                                                    let _e1519 = (_e489 * _e240);
                                                    let _e1526 = local_10;
                                                    if (_e1526 > (_e928 + _e240)) {
                                                        let _e1532 = local_11;
                                                        let _e1538 = local_12;
                                                        let _e1541 = local_13;
                                                        phi_2866_ = (vec3<f32>(((((_e1325 * 2f) - 1f) * _e1228) * _e1532), ((((_e1326 * -2f) + 1f) * _e1236) * _e1538), _e1541) - _e476);
                                                    } else {
                                                        phi_2866_ = vec3<f32>((_e969 - _e1517), (_e970 - _e1518), (_e971 - _e1519));
                                                    }
                                                    let _e1545 = phi_2866_;
                                                    let _e1547 = (_e1436 * inverseSqrt(_e976));
                                                    let _e1551 = select(-1f, select(1f, _e1547, (_e1547 < 1f)), (_e1547 > -1f));
                                                    let _e1552 = abs(_e1551);
                                                    let _e1562 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1552, 0.00667009f), _e1552, -0.017088126f), _e1552, 0.03089188f), _e1552, -0.050174303f), _e1552, 0.08897899f), _e1552, -0.2145988f), _e1552, 1.5707963f) * sqrt((1f - _e1552)));
                                                    let _e1569 = ((((select((3.1415927f - _e1562), _e1562, (_e1551 >= 0f)) + _e1510) - _e1506) + 1.5707964f) * 0.31830987f);
                                                    let _e1573 = select(0f, select(1f, _e1569, (_e1569 < 1f)), (_e1569 > 0f));
                                                    let _e1588 = ((((_e1545.x * _e487) + (_e1545.y * _e488)) + (_e1545.z * _e489)) * inverseSqrt((((_e1545.x * _e1545.x) + (_e1545.y * _e1545.y)) + (_e1545.z * _e1545.z))));
                                                    let _e1592 = select(-1f, select(1f, _e1588, (_e1588 < 1f)), (_e1588 > -1f));
                                                    let _e1593 = abs(_e1592);
                                                    let _e1603 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1593, 0.00667009f), _e1593, -0.017088126f), _e1593, 0.03089188f), _e1593, -0.050174303f), _e1593, 0.08897899f), _e1593, -0.2145988f), _e1593, 1.5707963f) * sqrt((1f - _e1593)));
                                                    let _e1610 = ((((select((3.1415927f - _e1603), _e1603, (_e1592 >= 0f)) + _e1510) - _e1506) + 1.5707964f) * 0.31830987f);
                                                    let _e1614 = select(0f, select(1f, _e1610, (_e1610 < 1f)), (_e1610 > 0f));
                                                    let _e1616 = (_e1614 != _e1614);
                                                    let _e1618 = select(_e1614, _e1573, ((_e1573 < _e1614) || _e1616));
                                                    let _e1621 = select(_e1614, _e1573, ((_e1573 > _e1614) || _e1616));
                                                    let _e1623 = floor((_e1618 * 32f));
                                                    let _e1624 = (_e237 == 1u);
                                                    if _e1624 {
                                                        let _e1631 = -(floor((_e1621 * -32f)));
                                                        let _e1636 = (select(32f, _e1631, ((_e1631 < 32f) || false)) - _e1623);
                                                        phi_3053_ = select(select(0f, _e1636, ((_e1636 > 0f) || false)), 0f, (_e1621 <= _e1618));
                                                    } else {
                                                        phi_3053_ = -(floor(((_e1621 - _e1618) * -32f)));
                                                    }
                                                    let _e1642 = phi_3053_;
                                                    let _e1650 = (bitcast<u32>((floor(select(0f, select(32f, _e1623, (_e1623 < 32f)), (_e1623 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e1658 = (bitcast<u32>((floor(select(0f, select(32f, _e1642, (_e1642 < 32f)), (_e1642 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e1650 >= 32u) {
                                                        phi_3107_ = u32();
                                                        phi_3108_ = true;
                                                    } else {
                                                        let _e1660 = (_e1658 == 0u);
                                                        if _e1660 {
                                                            phi_3106_ = u32();
                                                        } else {
                                                            if (_e1658 >= 32u) {
                                                                phi_3103_ = 4294967295u;
                                                            } else {
                                                                phi_3103_ = ((1u << bitcast<u32>((_e1658 & 31u))) - 1u);
                                                            }
                                                            let _e1667 = phi_3103_;
                                                            phi_3106_ = (_e1667 << bitcast<u32>((_e1650 & 31u)));
                                                        }
                                                        let _e1672 = phi_3106_;
                                                        phi_3107_ = _e1672;
                                                        phi_3108_ = _e1660;
                                                    }
                                                    let _e1674 = phi_3107_;
                                                    let _e1676 = phi_3108_;
                                                    phi_7021_ = _e1428;
                                                    let _e4165 = local_45;
                                                    phi_3118_ = _e4165;
                                                    phi_3121_ = 1u;
                                                    phi_3123_ = select(select(_e1674, 0u, _e1676), 0u, _e1516);
                                                    loop {
                                                        let _e1680 = phi_7021_;
                                                        let _e1682 = phi_3118_;
                                                        let _e1684 = phi_3121_;
                                                        let _e1686 = phi_3123_;
                                                        local_47 = _e1686;
                                                        if (_e1684 < _e1391) {
                                                            phi_3153_ = 0u;
                                                            phi_3156_ = _e1396;
                                                            loop {
                                                                let _e1689 = phi_3153_;
                                                                let _e1691 = phi_3156_;
                                                                local_14 = _e1691;
                                                                local_15 = _e1691;
                                                                local_16 = _e1691;
                                                                local_17 = _e1691;
                                                                local_18 = _e1691;
                                                                let _e1692 = (_e1689 < _e1391);
                                                                if _e1692 {
                                                                    let _e1693 = (_e1392 + _e1689);
                                                                    if (_e1693 < _e190) {
                                                                    } else {
                                                                        phi_7015_ = true;
                                                                        break;
                                                                    }
                                                                    let _e1696 = sd_map.member[_e1693];
                                                                    let _e1700 = frame.member[0u].member_1.member.member.member_2;
                                                                    let _e1703 = ((_e1696 * (_e1396 - _e1700)) + _e1700);
                                                                    if (_e1696 < 1f) {
                                                                        if (_e1703 > _e1682) {
                                                                            phi_3198_ = select(_e1691, _e1703, (_e1703 < _e1691));
                                                                        } else {
                                                                            phi_3198_ = _e1691;
                                                                        }
                                                                        let _e1709 = phi_3198_;
                                                                        phi_3199_ = _e1709;
                                                                    } else {
                                                                        phi_3199_ = _e1691;
                                                                    }
                                                                    let _e1711 = phi_3199_;
                                                                    phi_3154_ = (_e1689 + 1u);
                                                                    phi_3157_ = _e1711;
                                                                } else {
                                                                    phi_3154_ = u32();
                                                                    phi_3157_ = f32();
                                                                }
                                                                let _e1714 = phi_3154_;
                                                                let _e1716 = phi_3157_;
                                                                continue;
                                                                continuing {
                                                                    phi_3153_ = _e1714;
                                                                    phi_3156_ = _e1716;
                                                                    phi_7015_ = _e1680;
                                                                    break if !(_e1692);
                                                                }
                                                            }
                                                            let _e1719 = phi_7015_;
                                                            phi_7060_ = _e1719;
                                                            if _e1719 {
                                                                break;
                                                            }
                                                            let _e1721 = local_14;
                                                            let _e1722 = (_e1721 >= _e1396);
                                                            if _e1722 {
                                                                phi_7062_ = _e1719;
                                                                phi_3604_ = f32();
                                                                phi_3605_ = u32();
                                                                phi_3606_ = u32();
                                                            } else {
                                                                phi_3227_ = 0u;
                                                                phi_3230_ = _e1396;
                                                                loop {
                                                                    let _e1724 = phi_3227_;
                                                                    let _e1726 = phi_3230_;
                                                                    local_19 = _e1726;
                                                                    local_20 = _e1726;
                                                                    local_21 = _e1726;
                                                                    local_22 = _e1726;
                                                                    local_46 = _e1726;
                                                                    let _e1727 = (_e1724 < _e1391);
                                                                    if _e1727 {
                                                                        let _e1728 = (_e1392 + _e1724);
                                                                        if (_e1728 < _e190) {
                                                                        } else {
                                                                            phi_7054_ = true;
                                                                            break;
                                                                        }
                                                                        let _e1731 = sd_map.member[_e1728];
                                                                        let _e1735 = frame.member[0u].member_1.member.member.member_2;
                                                                        let _e1738 = ((_e1731 * (_e1396 - _e1735)) + _e1735);
                                                                        if (_e1731 < 1f) {
                                                                            let _e1741 = local_15;
                                                                            if (_e1738 > _e1741) {
                                                                                phi_3272_ = select(_e1726, _e1738, (_e1738 < _e1726));
                                                                            } else {
                                                                                phi_3272_ = _e1726;
                                                                            }
                                                                            let _e1746 = phi_3272_;
                                                                            phi_3273_ = _e1746;
                                                                        } else {
                                                                            phi_3273_ = _e1726;
                                                                        }
                                                                        let _e1748 = phi_3273_;
                                                                        phi_3228_ = (_e1724 + 1u);
                                                                        phi_3231_ = _e1748;
                                                                    } else {
                                                                        phi_3228_ = u32();
                                                                        phi_3231_ = f32();
                                                                    }
                                                                    let _e1751 = phi_3228_;
                                                                    let _e1753 = phi_3231_;
                                                                    continue;
                                                                    continuing {
                                                                        phi_3227_ = _e1751;
                                                                        phi_3230_ = _e1753;
                                                                        phi_7054_ = _e1719;
                                                                        break if !(_e1727);
                                                                    }
                                                                }
                                                                let _e1756 = phi_7054_;
                                                                phi_7060_ = _e1756;
                                                                if _e1756 {
                                                                    break;
                                                                }
                                                                let _e1759 = (((_e1325 * 2f) - 1f) * _e1228);
                                                                let _e1761 = local_16;
                                                                let _e1765 = (((_e1326 * -2f) + 1f) * _e1236);
                                                                let _e1767 = local_17;
                                                                let _e1769 = ((_e1759 * _e1761) - _e468);
                                                                let _e1770 = ((_e1765 * _e1767) - _e475);
                                                                let _e1772 = local_18;
                                                                let _e1773 = (_e1772 - _e461);
                                                                let _e1775 = local_19;
                                                                if (_e1775 < _e1396) {
                                                                    let _e1782 = local_20;
                                                                    let _e1785 = local_21;
                                                                    let _e1788 = local_22;
                                                                    phi_3332_ = (vec3<f32>((_e1759 * _e1782), (_e1765 * _e1785), _e1788) - _e476);
                                                                } else {
                                                                    phi_3332_ = vec3<f32>((_e1769 - _e1517), (_e1770 - _e1518), (_e1773 - _e1519));
                                                                }
                                                                let _e1792 = phi_3332_;
                                                                if _e977 {
                                                                    phi_3347_ = true;
                                                                } else {
                                                                    phi_3347_ = ((((_e1769 * _e1769) + (_e1770 * _e1770)) + (_e1773 * _e1773)) <= (_e243 * _e243));
                                                                }
                                                                let _e1801 = phi_3347_;
                                                                if _e1801 {
                                                                    let _e1813 = ((((_e1769 * _e487) + (_e1770 * _e488)) + (_e1773 * _e489)) * inverseSqrt((((_e1769 * _e1769) + (_e1770 * _e1770)) + (_e1773 * _e1773))));
                                                                    let _e1817 = select(-1f, select(1f, _e1813, (_e1813 < 1f)), (_e1813 > -1f));
                                                                    let _e1818 = abs(_e1817);
                                                                    let _e1828 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1818, 0.00667009f), _e1818, -0.017088126f), _e1818, 0.03089188f), _e1818, -0.050174303f), _e1818, 0.08897899f), _e1818, -0.2145988f), _e1818, 1.5707963f) * sqrt((1f - _e1818)));
                                                                    let _e1835 = ((((select((3.1415927f - _e1828), _e1828, (_e1817 >= 0f)) + _e1510) - _e1506) + 1.5707964f) * 0.31830987f);
                                                                    let _e1839 = select(0f, select(1f, _e1835, (_e1835 < 1f)), (_e1835 > 0f));
                                                                    let _e1854 = ((((_e1792.x * _e487) + (_e1792.y * _e488)) + (_e1792.z * _e489)) * inverseSqrt((((_e1792.x * _e1792.x) + (_e1792.y * _e1792.y)) + (_e1792.z * _e1792.z))));
                                                                    let _e1858 = select(-1f, select(1f, _e1854, (_e1854 < 1f)), (_e1854 > -1f));
                                                                    let _e1859 = abs(_e1858);
                                                                    let _e1869 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1859, 0.00667009f), _e1859, -0.017088126f), _e1859, 0.03089188f), _e1859, -0.050174303f), _e1859, 0.08897899f), _e1859, -0.2145988f), _e1859, 1.5707963f) * sqrt((1f - _e1859)));
                                                                    let _e1876 = ((((select((3.1415927f - _e1869), _e1869, (_e1858 >= 0f)) + _e1510) - _e1506) + 1.5707964f) * 0.31830987f);
                                                                    let _e1880 = select(0f, select(1f, _e1876, (_e1876 < 1f)), (_e1876 > 0f));
                                                                    let _e1882 = (_e1880 != _e1880);
                                                                    let _e1884 = select(_e1880, _e1839, ((_e1839 < _e1880) || _e1882));
                                                                    let _e1887 = select(_e1880, _e1839, ((_e1839 > _e1880) || _e1882));
                                                                    let _e1889 = floor((_e1884 * 32f));
                                                                    if _e1624 {
                                                                        let _e1896 = -(floor((_e1887 * -32f)));
                                                                        let _e1901 = (select(32f, _e1896, ((_e1896 < 32f) || false)) - _e1889);
                                                                        phi_3537_ = select(select(0f, _e1901, ((_e1901 > 0f) || false)), 0f, (_e1887 <= _e1884));
                                                                    } else {
                                                                        phi_3537_ = -(floor(((_e1887 - _e1884) * -32f)));
                                                                    }
                                                                    let _e1907 = phi_3537_;
                                                                    let _e1915 = (bitcast<u32>((floor(select(0f, select(32f, _e1889, (_e1889 < 32f)), (_e1889 > 0f))) + 8388608f)) - 1258291200u);
                                                                    let _e1923 = (bitcast<u32>((floor(select(0f, select(32f, _e1907, (_e1907 < 32f)), (_e1907 > 0f))) + 8388608f)) - 1258291200u);
                                                                    if (_e1915 >= 32u) {
                                                                        phi_3591_ = u32();
                                                                        phi_3592_ = true;
                                                                    } else {
                                                                        let _e1925 = (_e1923 == 0u);
                                                                        if _e1925 {
                                                                            phi_3590_ = u32();
                                                                        } else {
                                                                            if (_e1923 >= 32u) {
                                                                                phi_3587_ = 4294967295u;
                                                                            } else {
                                                                                phi_3587_ = ((1u << bitcast<u32>((_e1923 & 31u))) - 1u);
                                                                            }
                                                                            let _e1932 = phi_3587_;
                                                                            phi_3590_ = (_e1932 << bitcast<u32>((_e1915 & 31u)));
                                                                        }
                                                                        let _e1937 = phi_3590_;
                                                                        phi_3591_ = _e1937;
                                                                        phi_3592_ = _e1925;
                                                                    }
                                                                    let _e1939 = phi_3591_;
                                                                    let _e1941 = phi_3592_;
                                                                    phi_3602_ = (_e1686 | select(select(_e1939, 0u, _e1941), 0u, _e1516));
                                                                } else {
                                                                    phi_3602_ = _e1686;
                                                                }
                                                                let _e1946 = phi_3602_;
                                                                phi_7062_ = _e1756;
                                                                let _e4202 = local_46;
                                                                phi_3604_ = _e4202;
                                                                phi_3605_ = (_e1684 + 2u);
                                                                phi_3606_ = _e1946;
                                                            }
                                                            let _e1949 = phi_7062_;
                                                            let _e1951 = phi_3604_;
                                                            let _e1953 = phi_3605_;
                                                            let _e1955 = phi_3606_;
                                                            phi_7061_ = _e1949;
                                                            phi_3119_ = _e1951;
                                                            phi_3122_ = _e1953;
                                                            phi_3124_ = _e1955;
                                                            phi_3608_ = select(true, false, _e1722);
                                                        } else {
                                                            phi_7061_ = _e1680;
                                                            phi_3119_ = f32();
                                                            phi_3122_ = u32();
                                                            phi_3124_ = u32();
                                                            phi_3608_ = false;
                                                        }
                                                        let _e1958 = phi_7061_;
                                                        let _e1960 = phi_3119_;
                                                        let _e1962 = phi_3122_;
                                                        let _e1964 = phi_3124_;
                                                        let _e1966 = phi_3608_;
                                                        continue;
                                                        continuing {
                                                            phi_7021_ = _e1958;
                                                            phi_3118_ = _e1960;
                                                            phi_3121_ = _e1962;
                                                            phi_3123_ = _e1964;
                                                            phi_7060_ = _e1958;
                                                            break if !(_e1966);
                                                        }
                                                    }
                                                    let _e1969 = phi_7060_;
                                                    phi_7297_ = _e1969;
                                                    if _e1969 {
                                                        break;
                                                    }
                                                    phi_7150_ = _e1969;
                                                    phi_3613_ = u32();
                                                    let _e4222 = local_47;
                                                    phi_3614_ = _e4222;
                                                }
                                                let _e2201 = phi_7150_;
                                                let _e2203 = phi_3613_;
                                                let _e2205 = phi_3614_;
                                                phi_7115_ = _e2201;
                                                phi_3615_ = _e2203;
                                                phi_3616_ = _e2205;
                                                phi_3617_ = _e1431;
                                            }
                                            let _e2437 = phi_7115_;
                                            let _e2439 = phi_3615_;
                                            let _e2441 = phi_3616_;
                                            let _e2443 = phi_3617_;
                                            phi_7113_ = _e2437;
                                            phi_4018_ = select(_e2441, _e2439, _e2443);
                                        } else {
                                            if (_e243 > 0f) {
                                                phi_3633_ = (_e976 > (_e243 * _e243));
                                            } else {
                                                phi_3633_ = false;
                                            }
                                            let _e996 = phi_3633_;
                                            if !(_e996) {
                                                let _e1002 = (((_e969 * _e487) + (_e970 * _e488)) + (_e971 * _e489));
                                                let _e1006 = (_e969 - (_e487 * _e1002));
                                                let _e1007 = (_e970 - (_e488 * _e1002));
                                                let _e1008 = (_e971 - (_e489 * _e1002));
                                                let _e1011 = ((_e1007 * _e489) - (_e488 * _e1008));
                                                let _e1014 = ((_e1008 * _e487) - (_e489 * _e1006));
                                                let _e1017 = ((_e1006 * _e488) - (_e487 * _e1007));
                                                let _e1028 = ((((_e548 * _e1011) + (_e549 * _e1014)) + (_e550 * _e1017)) / (((_e1011 * _e1011) + (_e1014 * _e1014)) + (_e1017 * _e1017)));
                                                let _e1032 = (_e548 - (_e1011 * _e1028));
                                                let _e1033 = (_e549 - (_e1014 * _e1028));
                                                let _e1034 = (_e550 - (_e1017 * _e1028));
                                                let _e1040 = inverseSqrt((((_e1032 * _e1032) + (_e1033 * _e1033)) + (_e1034 * _e1034)));
                                                let _e1046 = ((((_e1032 * _e487) + (_e1033 * _e488)) + (_e1034 * _e489)) * _e1040);
                                                let _e1050 = select(0f, select(1f, _e1046, (_e1046 < 1f)), (_e1046 > 0f));
                                                let _e1051 = abs(_e1050);
                                                let _e1061 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1051, 0.00667009f), _e1051, -0.017088126f), _e1051, 0.03089188f), _e1051, -0.050174303f), _e1051, 0.08897899f), _e1051, -0.2145988f), _e1051, 1.5707963f) * sqrt((1f - _e1051)));
                                                let _e1064 = select((3.1415927f - _e1061), _e1061, (_e1050 >= 0f));
                                                let _e1072 = select(_e1064, -(_e1064), ((((_e1006 * _e1032) + (_e1007 * _e1033)) + (_e1008 * _e1034)) < 0f));
                                                let _e1073 = (_e1040 * 0.02f);
                                                let _e1076 = select(0.19634955f, _e1073, ((_e1073 < 0.19634955f) || false));
                                                let _e1086 = (_e969 - (_e487 * _e240));
                                                let _e1087 = (_e970 - (_e488 * _e240));
                                                let _e1088 = (_e971 - (_e489 * _e240));
                                                let _e1090 = (_e1002 * inverseSqrt(_e976));
                                                let _e1094 = select(-1f, select(1f, _e1090, (_e1090 < 1f)), (_e1090 > -1f));
                                                let _e1095 = abs(_e1094);
                                                let _e1105 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1095, 0.00667009f), _e1095, -0.017088126f), _e1095, 0.03089188f), _e1095, -0.050174303f), _e1095, 0.08897899f), _e1095, -0.2145988f), _e1095, 1.5707963f) * sqrt((1f - _e1095)));
                                                let _e1112 = ((((select((3.1415927f - _e1105), _e1105, (_e1094 >= 0f)) + _e1076) - _e1072) + 1.5707964f) * 0.31830987f);
                                                let _e1116 = select(0f, select(1f, _e1112, (_e1112 < 1f)), (_e1112 > 0f));
                                                let _e1128 = ((((_e1086 * _e487) + (_e1087 * _e488)) + (_e1088 * _e489)) * inverseSqrt((((_e1086 * _e1086) + (_e1087 * _e1087)) + (_e1088 * _e1088))));
                                                let _e1132 = select(-1f, select(1f, _e1128, (_e1128 < 1f)), (_e1128 > -1f));
                                                let _e1133 = abs(_e1132);
                                                let _e1143 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1133, 0.00667009f), _e1133, -0.017088126f), _e1133, 0.03089188f), _e1133, -0.050174303f), _e1133, 0.08897899f), _e1133, -0.2145988f), _e1133, 1.5707963f) * sqrt((1f - _e1133)));
                                                let _e1150 = ((((select((3.1415927f - _e1143), _e1143, (_e1132 >= 0f)) + _e1076) - _e1072) + 1.5707964f) * 0.31830987f);
                                                let _e1154 = select(0f, select(1f, _e1150, (_e1150 < 1f)), (_e1150 > 0f));
                                                let _e1156 = (_e1154 != _e1154);
                                                let _e1158 = select(_e1154, _e1116, ((_e1116 < _e1154) || _e1156));
                                                let _e1161 = select(_e1154, _e1116, ((_e1116 > _e1154) || _e1156));
                                                let _e1163 = floor((_e1158 * 32f));
                                                if (_e237 == 1u) {
                                                    let _e1171 = -(floor((_e1161 * -32f)));
                                                    let _e1176 = (select(32f, _e1171, ((_e1171 < 32f) || false)) - _e1163);
                                                    phi_3949_ = select(select(0f, _e1176, ((_e1176 > 0f) || false)), 0f, (_e1161 <= _e1158));
                                                } else {
                                                    phi_3949_ = -(floor(((_e1161 - _e1158) * -32f)));
                                                }
                                                let _e1182 = phi_3949_;
                                                let _e1190 = (bitcast<u32>((floor(select(0f, select(32f, _e1163, (_e1163 < 32f)), (_e1163 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e1198 = (bitcast<u32>((floor(select(0f, select(32f, _e1182, (_e1182 < 32f)), (_e1182 > 0f))) + 8388608f)) - 1258291200u);
                                                if (_e1190 >= 32u) {
                                                    phi_4003_ = u32();
                                                    phi_4004_ = true;
                                                } else {
                                                    let _e1200 = (_e1198 == 0u);
                                                    if _e1200 {
                                                        phi_4002_ = u32();
                                                    } else {
                                                        if (_e1198 >= 32u) {
                                                            phi_3999_ = 4294967295u;
                                                        } else {
                                                            phi_3999_ = ((1u << bitcast<u32>((_e1198 & 31u))) - 1u);
                                                        }
                                                        let _e1207 = phi_3999_;
                                                        phi_4002_ = (_e1207 << bitcast<u32>((_e1190 & 31u)));
                                                    }
                                                    let _e1212 = phi_4002_;
                                                    phi_4003_ = _e1212;
                                                    phi_4004_ = _e1200;
                                                }
                                                let _e1214 = phi_4003_;
                                                let _e1216 = phi_4004_;
                                                phi_4017_ = select(select(select(_e1214, 0u, _e1216), 0u, ((((_e1006 * _e1006) + (_e1007 * _e1007)) + (_e1008 * _e1008)) <= 0f)), 0u, _e996);
                                            } else {
                                                phi_4017_ = 0u;
                                            }
                                            let _e1221 = phi_4017_;
                                            phi_7113_ = _e790;
                                            phi_4018_ = _e1221;
                                        }
                                        let _e2446 = phi_7113_;
                                        let _e2448 = phi_4018_;
                                        let _e2450 = (_e964 - _e468);
                                        let _e2451 = (_e968 - _e475);
                                        let _e2452 = (_e960 - _e461);
                                        let _e2457 = (((_e2450 * _e2450) + (_e2451 * _e2451)) + (_e2452 * _e2452));
                                        if _e977 {
                                            phi_4041_ = true;
                                        } else {
                                            phi_4041_ = (_e2457 <= (_e243 * _e243));
                                        }
                                        let _e2461 = phi_4041_;
                                        if _e2461 {
                                            phi_4057_ = ((((_e2450 * _e548) + (_e2451 * _e549)) + (_e2452 * _e550)) > (0.018f * sqrt(_e2457)));
                                        } else {
                                            phi_4057_ = false;
                                        }
                                        let _e2471 = phi_4057_;
                                        if _e2471 {
                                            let _e2704 = (0.5f / _e960);
                                            let _e2710 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e2718 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e2723 = frame.member[0u].member_1.member_5[0u];
                                            let _e2726 = frame.member[0u].member_1.member_5[1u];
                                            let _e2727 = f32(_e2723);
                                            let _e2728 = f32(_e2726);
                                            let _e2730 = frame.member[0u].member_1.member_4;
                                            let _e2731 = f32(_e2730);
                                            let _e2732 = (2u * _e2730);
                                            let _e2733 = (_e2723 + _e2732);
                                            let _e2739 = (floor(((((_e964 * _e2704) / _e2710) + 0.5f) * _e2727)) + _e2731);
                                            let _e2740 = f32((_e2733 - 1u));
                                            let _e2744 = select(0f, select(_e2740, _e2739, (_e2739 < _e2740)), (_e2739 > 0f));
                                            let _e2747 = (floor(((0.5f - ((_e968 * _e2704) / _e2718)) * _e2728)) + _e2731);
                                            let _e2748 = f32(((_e2726 + _e2732) - 1u));
                                            let _e2752 = select(0f, select(_e2748, _e2747, (_e2747 < _e2748)), (_e2747 > 0f));
                                            let _e2757 = select(select(u32(_e2744), 0u, (_e2744 < 0f)), 4294967295u, (_e2744 > 4294967000f));
                                            let _e2762 = select(select(u32(_e2752), 0u, (_e2752 < 0f)), 4294967295u, (_e2752 > 4294967000f));
                                            let _e2765 = bitcast<i32>(_e2730);
                                            let _e2771 = frame.member[0u].member_1.member_8;
                                            let _e2773 = frame.member[0u].member_1.member_12;
                                            let _e2780 = (((((_e2762 % 4u) * 4u) + (_e2757 % 4u)) + (_e2773 % 16u)) % 16u);
                                            if (_e2771 == 1u) {
                                                local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                let _e2793 = (_e2780 < 16u);
                                                if _e2793 {
                                                } else {
                                                    phi_7297_ = true;
                                                    break;
                                                }
                                                let _e2796 = local_1[_e2780][0u];
                                                local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                if _e2793 {
                                                } else {
                                                    phi_7297_ = true;
                                                    break;
                                                }
                                                let _e2799 = local_2[_e2780][1u];
                                                phi_4217_ = vec2<f32>(_e2796, _e2799);
                                            } else {
                                                if (_e2771 == 2u) {
                                                    local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    let _e2783 = (_e2780 < 16u);
                                                    if _e2783 {
                                                    } else {
                                                        phi_7297_ = true;
                                                        break;
                                                    }
                                                    let _e2786 = local_3[_e2780][0u];
                                                    local_4 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                    if _e2783 {
                                                    } else {
                                                        phi_7297_ = true;
                                                        break;
                                                    }
                                                    let _e2789 = local_4[_e2780][1u];
                                                    phi_4216_ = vec2<f32>(_e2786, _e2789);
                                                } else {
                                                    phi_4216_ = vec2<f32>(0.5f, 0.5f);
                                                }
                                                let _e2792 = phi_4216_;
                                                phi_4217_ = _e2792;
                                            }
                                            let _e2802 = phi_4217_;
                                            let _e2807 = ((f32((bitcast<i32>(_e2757) - _e2765)) + _e2802.x) / _e2727);
                                            let _e2808 = ((f32((bitcast<i32>(_e2762) - _e2765)) + _e2802.y) / _e2728);
                                            let _e2813 = frame.member[0u].member_1.member.member.member[0u];
                                            let _e2818 = select(select(u32(_e2813), 0u, (_e2813 < 0f)), 4294967295u, (_e2813 > 4294967000f));
                                            let _e2823 = frame.member[0u].member_1.member.member.member[1u];
                                            let _e2833 = (select(0f, select(1f, _e2807, (_e2807 < 1f)), (_e2807 > 0f)) * _e2813);
                                            let _e2836 = f32(bitcast<i32>((_e2818 - 1u)));
                                            let _e2849 = (select(0f, select(1f, _e2808, (_e2808 < 1f)), (_e2808 > 0f)) * _e2823);
                                            let _e2852 = f32(bitcast<i32>((select(select(u32(_e2823), 0u, (_e2823 < 0f)), 4294967295u, (_e2823 > 4294967000f)) - 1u)));
                                            let _e2862 = (((bitcast<u32>((floor(select(0f, select(_e2852, _e2849, (_e2849 < _e2852)), (_e2849 > 0f))) + 8388608f)) - 1258291200u) * _e2818) + (bitcast<u32>((floor(select(0f, select(_e2836, _e2833, (_e2833 < _e2836)), (_e2833 > 0f))) + 8388608f)) - 1258291200u));
                                            if (_e2862 < _e187) {
                                            } else {
                                                phi_7297_ = true;
                                                break;
                                            }
                                            let _e2865 = mips.member[_e2862];
                                            if (abs((_e2865 - _e960)) > _e240) {
                                                if (_e243 > 0f) {
                                                    phi_4350_ = (_e2457 > (_e243 * _e243));
                                                } else {
                                                    phi_4350_ = false;
                                                }
                                                let _e3698 = phi_4350_;
                                                if !(_e3698) {
                                                    let _e3704 = (((_e2450 * _e487) + (_e2451 * _e488)) + (_e2452 * _e489));
                                                    let _e3708 = (_e2450 - (_e487 * _e3704));
                                                    let _e3709 = (_e2451 - (_e488 * _e3704));
                                                    let _e3710 = (_e2452 - (_e489 * _e3704));
                                                    let _e3713 = ((_e3709 * _e489) - (_e488 * _e3710));
                                                    let _e3716 = ((_e3710 * _e487) - (_e489 * _e3708));
                                                    let _e3719 = ((_e3708 * _e488) - (_e487 * _e3709));
                                                    let _e3730 = ((((_e548 * _e3713) + (_e549 * _e3716)) + (_e550 * _e3719)) / (((_e3713 * _e3713) + (_e3716 * _e3716)) + (_e3719 * _e3719)));
                                                    let _e3734 = (_e548 - (_e3713 * _e3730));
                                                    let _e3735 = (_e549 - (_e3716 * _e3730));
                                                    let _e3736 = (_e550 - (_e3719 * _e3730));
                                                    let _e3742 = inverseSqrt((((_e3734 * _e3734) + (_e3735 * _e3735)) + (_e3736 * _e3736)));
                                                    let _e3748 = ((((_e3734 * _e487) + (_e3735 * _e488)) + (_e3736 * _e489)) * _e3742);
                                                    let _e3752 = select(0f, select(1f, _e3748, (_e3748 < 1f)), (_e3748 > 0f));
                                                    let _e3753 = abs(_e3752);
                                                    let _e3763 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3753, 0.00667009f), _e3753, -0.017088126f), _e3753, 0.03089188f), _e3753, -0.050174303f), _e3753, 0.08897899f), _e3753, -0.2145988f), _e3753, 1.5707963f) * sqrt((1f - _e3753)));
                                                    let _e3766 = select((3.1415927f - _e3763), _e3763, (_e3752 >= 0f));
                                                    let _e3774 = select(_e3766, -(_e3766), ((((_e3708 * _e3734) + (_e3709 * _e3735)) + (_e3710 * _e3736)) < 0f));
                                                    let _e3775 = (_e3742 * 0.02f);
                                                    let _e3778 = select(0.19634955f, _e3775, ((_e3775 < 0.19634955f) || false));
                                                    let _e3788 = (_e2450 - (_e487 * _e240));
                                                    let _e3789 = (_e2451 - (_e488 * _e240));
                                                    let _e3790 = (_e2452 - (_e489 * _e240));
                                                    let _e3792 = (_e3704 * inverseSqrt(_e2457));
                                                    let _e3796 = select(-1f, select(1f, _e3792, (_e3792 < 1f)), (_e3792 > -1f));
                                                    let _e3797 = abs(_e3796);
                                                    let _e3807 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3797, 0.00667009f), _e3797, -0.017088126f), _e3797, 0.03089188f), _e3797, -0.050174303f), _e3797, 0.08897899f), _e3797, -0.2145988f), _e3797, 1.5707963f) * sqrt((1f - _e3797)));
                                                    let _e3814 = ((((select((3.1415927f - _e3807), _e3807, (_e3796 >= 0f)) + _e3778) - _e3774) + 1.5707964f) * 0.31830987f);
                                                    let _e3830 = ((((_e3788 * _e487) + (_e3789 * _e488)) + (_e3790 * _e489)) * inverseSqrt((((_e3788 * _e3788) + (_e3789 * _e3789)) + (_e3790 * _e3790))));
                                                    let _e3834 = select(-1f, select(1f, _e3830, (_e3830 < 1f)), (_e3830 > -1f));
                                                    let _e3835 = abs(_e3834);
                                                    let _e3845 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3835, 0.00667009f), _e3835, -0.017088126f), _e3835, 0.03089188f), _e3835, -0.050174303f), _e3835, 0.08897899f), _e3835, -0.2145988f), _e3835, 1.5707963f) * sqrt((1f - _e3835)));
                                                    let _e3852 = ((((select((3.1415927f - _e3845), _e3845, (_e3834 >= 0f)) + _e3778) - _e3774) + 1.5707964f) * 0.31830987f);
                                                    let _e3857 = (1f - select(0f, select(1f, _e3814, (_e3814 < 1f)), (_e3814 > 0f)));
                                                    let _e3858 = (1f - select(0f, select(1f, _e3852, (_e3852 < 1f)), (_e3852 > 0f)));
                                                    let _e3860 = (_e3858 != _e3858);
                                                    let _e3862 = select(_e3858, _e3857, ((_e3857 < _e3858) || _e3860));
                                                    let _e3865 = select(_e3858, _e3857, ((_e3857 > _e3858) || _e3860));
                                                    let _e3867 = floor((_e3862 * 32f));
                                                    if (_e237 == 1u) {
                                                        let _e3875 = -(floor((_e3865 * -32f)));
                                                        let _e3880 = (select(32f, _e3875, ((_e3875 < 32f) || false)) - _e3867);
                                                        phi_4666_ = select(select(0f, _e3880, ((_e3880 > 0f) || false)), 0f, (_e3865 <= _e3862));
                                                    } else {
                                                        phi_4666_ = -(floor(((_e3865 - _e3862) * -32f)));
                                                    }
                                                    let _e3886 = phi_4666_;
                                                    let _e3894 = (bitcast<u32>((floor(select(0f, select(32f, _e3867, (_e3867 < 32f)), (_e3867 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3902 = (bitcast<u32>((floor(select(0f, select(32f, _e3886, (_e3886 < 32f)), (_e3886 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3894 >= 32u) {
                                                        phi_4720_ = u32();
                                                        phi_4721_ = true;
                                                    } else {
                                                        let _e3904 = (_e3902 == 0u);
                                                        if _e3904 {
                                                            phi_4719_ = u32();
                                                        } else {
                                                            if (_e3902 >= 32u) {
                                                                phi_4716_ = 4294967295u;
                                                            } else {
                                                                phi_4716_ = ((1u << bitcast<u32>((_e3902 & 31u))) - 1u);
                                                            }
                                                            let _e3911 = phi_4716_;
                                                            phi_4719_ = (_e3911 << bitcast<u32>((_e3894 & 31u)));
                                                        }
                                                        let _e3916 = phi_4719_;
                                                        phi_4720_ = _e3916;
                                                        phi_4721_ = _e3904;
                                                    }
                                                    let _e3918 = phi_4720_;
                                                    let _e3920 = phi_4721_;
                                                    phi_4734_ = select(select(select(_e3918, 0u, _e3920), 0u, ((((_e3708 * _e3708) + (_e3709 * _e3709)) + (_e3710 * _e3710)) <= 0f)), 0u, _e3698);
                                                } else {
                                                    phi_4734_ = 0u;
                                                }
                                                let _e3925 = phi_4734_;
                                                phi_7301_ = _e2446;
                                                phi_6117_ = _e3925;
                                                phi_6118_ = u32();
                                                phi_6119_ = true;
                                            } else {
                                                let _e2873 = frame.member[0u].member_1.member_6;
                                                let _e2874 = (((_e2762 * _e2733) + _e2757) * _e2873);
                                                let _e2878 = frame.member[0u].member_1.member.member.member_3;
                                                phi_4757_ = 0u;
                                                phi_4760_ = _e2878;
                                                loop {
                                                    let _e2880 = phi_4757_;
                                                    let _e2882 = phi_4760_;
                                                    local_23 = _e2882;
                                                    local_24 = _e2882;
                                                    local_25 = _e2882;
                                                    local_26 = _e2882;
                                                    local_27 = _e2882;
                                                    local_48 = _e2882;
                                                    let _e2883 = (_e2880 < _e2873);
                                                    if _e2883 {
                                                        let _e2884 = (_e2874 + _e2880);
                                                        if (_e2884 < _e190) {
                                                        } else {
                                                            phi_7092_ = true;
                                                            break;
                                                        }
                                                        let _e2887 = sd_map.member[_e2884];
                                                        let _e2891 = frame.member[0u].member_1.member.member.member_2;
                                                        let _e2894 = ((_e2887 * (_e2878 - _e2891)) + _e2891);
                                                        if (_e2887 < 1f) {
                                                            if (_e2894 > (_e960 * 1.001f)) {
                                                                phi_4802_ = select(_e2882, _e2894, (_e2894 < _e2882));
                                                            } else {
                                                                phi_4802_ = _e2882;
                                                            }
                                                            let _e2900 = phi_4802_;
                                                            phi_4803_ = _e2900;
                                                        } else {
                                                            phi_4803_ = _e2882;
                                                        }
                                                        let _e2902 = phi_4803_;
                                                        phi_4758_ = (_e2880 + 1u);
                                                        phi_4761_ = _e2902;
                                                    } else {
                                                        phi_4758_ = u32();
                                                        phi_4761_ = f32();
                                                    }
                                                    let _e2905 = phi_4758_;
                                                    let _e2907 = phi_4761_;
                                                    continue;
                                                    continuing {
                                                        phi_4757_ = _e2905;
                                                        phi_4760_ = _e2907;
                                                        phi_7092_ = _e2446;
                                                        break if !(_e2883);
                                                    }
                                                }
                                                let _e2910 = phi_7092_;
                                                phi_7297_ = _e2910;
                                                if _e2910 {
                                                    break;
                                                }
                                                let _e2912 = local_23;
                                                let _e2913 = (_e2912 >= _e2878);
                                                if _e2913 {
                                                    if (_e243 > 0f) {
                                                        phi_4822_ = (_e2457 > (_e243 * _e243));
                                                    } else {
                                                        phi_4822_ = false;
                                                    }
                                                    let _e3460 = phi_4822_;
                                                    if !(_e3460) {
                                                        let _e3466 = (((_e2450 * _e487) + (_e2451 * _e488)) + (_e2452 * _e489));
                                                        let _e3470 = (_e2450 - (_e487 * _e3466));
                                                        let _e3471 = (_e2451 - (_e488 * _e3466));
                                                        let _e3472 = (_e2452 - (_e489 * _e3466));
                                                        let _e3475 = ((_e3471 * _e489) - (_e488 * _e3472));
                                                        let _e3478 = ((_e3472 * _e487) - (_e489 * _e3470));
                                                        let _e3481 = ((_e3470 * _e488) - (_e487 * _e3471));
                                                        let _e3492 = ((((_e548 * _e3475) + (_e549 * _e3478)) + (_e550 * _e3481)) / (((_e3475 * _e3475) + (_e3478 * _e3478)) + (_e3481 * _e3481)));
                                                        let _e3496 = (_e548 - (_e3475 * _e3492));
                                                        let _e3497 = (_e549 - (_e3478 * _e3492));
                                                        let _e3498 = (_e550 - (_e3481 * _e3492));
                                                        let _e3504 = inverseSqrt((((_e3496 * _e3496) + (_e3497 * _e3497)) + (_e3498 * _e3498)));
                                                        let _e3510 = ((((_e3496 * _e487) + (_e3497 * _e488)) + (_e3498 * _e489)) * _e3504);
                                                        let _e3514 = select(0f, select(1f, _e3510, (_e3510 < 1f)), (_e3510 > 0f));
                                                        let _e3515 = abs(_e3514);
                                                        let _e3525 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3515, 0.00667009f), _e3515, -0.017088126f), _e3515, 0.03089188f), _e3515, -0.050174303f), _e3515, 0.08897899f), _e3515, -0.2145988f), _e3515, 1.5707963f) * sqrt((1f - _e3515)));
                                                        let _e3528 = select((3.1415927f - _e3525), _e3525, (_e3514 >= 0f));
                                                        let _e3536 = select(_e3528, -(_e3528), ((((_e3470 * _e3496) + (_e3471 * _e3497)) + (_e3472 * _e3498)) < 0f));
                                                        let _e3537 = (_e3504 * 0.02f);
                                                        let _e3540 = select(0.19634955f, _e3537, ((_e3537 < 0.19634955f) || false));
                                                        let _e3550 = (_e2450 - (_e487 * _e240));
                                                        let _e3551 = (_e2451 - (_e488 * _e240));
                                                        let _e3552 = (_e2452 - (_e489 * _e240));
                                                        let _e3554 = (_e3466 * inverseSqrt(_e2457));
                                                        let _e3558 = select(-1f, select(1f, _e3554, (_e3554 < 1f)), (_e3554 > -1f));
                                                        let _e3559 = abs(_e3558);
                                                        let _e3569 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3559, 0.00667009f), _e3559, -0.017088126f), _e3559, 0.03089188f), _e3559, -0.050174303f), _e3559, 0.08897899f), _e3559, -0.2145988f), _e3559, 1.5707963f) * sqrt((1f - _e3559)));
                                                        let _e3576 = ((((select((3.1415927f - _e3569), _e3569, (_e3558 >= 0f)) + _e3540) - _e3536) + 1.5707964f) * 0.31830987f);
                                                        let _e3592 = ((((_e3550 * _e487) + (_e3551 * _e488)) + (_e3552 * _e489)) * inverseSqrt((((_e3550 * _e3550) + (_e3551 * _e3551)) + (_e3552 * _e3552))));
                                                        let _e3596 = select(-1f, select(1f, _e3592, (_e3592 < 1f)), (_e3592 > -1f));
                                                        let _e3597 = abs(_e3596);
                                                        let _e3607 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3597, 0.00667009f), _e3597, -0.017088126f), _e3597, 0.03089188f), _e3597, -0.050174303f), _e3597, 0.08897899f), _e3597, -0.2145988f), _e3597, 1.5707963f) * sqrt((1f - _e3597)));
                                                        let _e3614 = ((((select((3.1415927f - _e3607), _e3607, (_e3596 >= 0f)) + _e3540) - _e3536) + 1.5707964f) * 0.31830987f);
                                                        let _e3619 = (1f - select(0f, select(1f, _e3576, (_e3576 < 1f)), (_e3576 > 0f)));
                                                        let _e3620 = (1f - select(0f, select(1f, _e3614, (_e3614 < 1f)), (_e3614 > 0f)));
                                                        let _e3622 = (_e3620 != _e3620);
                                                        let _e3624 = select(_e3620, _e3619, ((_e3619 < _e3620) || _e3622));
                                                        let _e3627 = select(_e3620, _e3619, ((_e3619 > _e3620) || _e3622));
                                                        let _e3629 = floor((_e3624 * 32f));
                                                        if (_e237 == 1u) {
                                                            let _e3637 = -(floor((_e3627 * -32f)));
                                                            let _e3642 = (select(32f, _e3637, ((_e3637 < 32f) || false)) - _e3629);
                                                            phi_5138_ = select(select(0f, _e3642, ((_e3642 > 0f) || false)), 0f, (_e3627 <= _e3624));
                                                        } else {
                                                            phi_5138_ = -(floor(((_e3627 - _e3624) * -32f)));
                                                        }
                                                        let _e3648 = phi_5138_;
                                                        let _e3656 = (bitcast<u32>((floor(select(0f, select(32f, _e3629, (_e3629 < 32f)), (_e3629 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e3664 = (bitcast<u32>((floor(select(0f, select(32f, _e3648, (_e3648 < 32f)), (_e3648 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e3656 >= 32u) {
                                                            phi_5192_ = u32();
                                                            phi_5193_ = true;
                                                        } else {
                                                            let _e3666 = (_e3664 == 0u);
                                                            if _e3666 {
                                                                phi_5191_ = u32();
                                                            } else {
                                                                if (_e3664 >= 32u) {
                                                                    phi_5188_ = 4294967295u;
                                                                } else {
                                                                    phi_5188_ = ((1u << bitcast<u32>((_e3664 & 31u))) - 1u);
                                                                }
                                                                let _e3673 = phi_5188_;
                                                                phi_5191_ = (_e3673 << bitcast<u32>((_e3656 & 31u)));
                                                            }
                                                            let _e3678 = phi_5191_;
                                                            phi_5192_ = _e3678;
                                                            phi_5193_ = _e3666;
                                                        }
                                                        let _e3680 = phi_5192_;
                                                        let _e3682 = phi_5193_;
                                                        phi_5206_ = select(select(select(_e3680, 0u, _e3682), 0u, ((((_e3470 * _e3470) + (_e3471 * _e3471)) + (_e3472 * _e3472)) <= 0f)), 0u, _e3460);
                                                    } else {
                                                        phi_5206_ = 0u;
                                                    }
                                                    let _e3687 = phi_5206_;
                                                    phi_7336_ = _e2910;
                                                    phi_6115_ = _e3687;
                                                    phi_6116_ = u32();
                                                } else {
                                                    let _e2918 = (((_e2450 * _e487) + (_e2451 * _e488)) + (_e2452 * _e489));
                                                    let _e2922 = (_e2450 - (_e487 * _e2918));
                                                    let _e2923 = (_e2451 - (_e488 * _e2918));
                                                    let _e2924 = (_e2452 - (_e489 * _e2918));
                                                    let _e2927 = ((_e2923 * _e489) - (_e488 * _e2924));
                                                    let _e2930 = ((_e2924 * _e487) - (_e489 * _e2922));
                                                    let _e2933 = ((_e2922 * _e488) - (_e487 * _e2923));
                                                    let _e2944 = ((((_e548 * _e2927) + (_e549 * _e2930)) + (_e550 * _e2933)) / (((_e2927 * _e2927) + (_e2930 * _e2930)) + (_e2933 * _e2933)));
                                                    let _e2948 = (_e548 - (_e2927 * _e2944));
                                                    let _e2949 = (_e549 - (_e2930 * _e2944));
                                                    let _e2950 = (_e550 - (_e2933 * _e2944));
                                                    let _e2956 = inverseSqrt((((_e2948 * _e2948) + (_e2949 * _e2949)) + (_e2950 * _e2950)));
                                                    let _e2962 = ((((_e2948 * _e487) + (_e2949 * _e488)) + (_e2950 * _e489)) * _e2956);
                                                    let _e2966 = select(0f, select(1f, _e2962, (_e2962 < 1f)), (_e2962 > 0f));
                                                    let _e2967 = abs(_e2966);
                                                    let _e2977 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2967, 0.00667009f), _e2967, -0.017088126f), _e2967, 0.03089188f), _e2967, -0.050174303f), _e2967, 0.08897899f), _e2967, -0.2145988f), _e2967, 1.5707963f) * sqrt((1f - _e2967)));
                                                    let _e2980 = select((3.1415927f - _e2977), _e2977, (_e2966 >= 0f));
                                                    let _e2988 = select(_e2980, -(_e2980), ((((_e2922 * _e2948) + (_e2923 * _e2949)) + (_e2924 * _e2950)) < 0f));
                                                    let _e2989 = (_e2956 * 0.02f);
                                                    let _e2992 = select(0.19634955f, _e2989, ((_e2989 < 0.19634955f) || false));
                                                    let _e2998 = ((((_e2922 * _e2922) + (_e2923 * _e2923)) + (_e2924 * _e2924)) <= 0f);
                                                    let _e2999 = (_e487 * _e240);
                                                    let _e3000 = (_e488 * _e240);
                                                    let _e3001 = (_e489 * _e240);
                                                    let _e3008 = local_24;
                                                    if (_e3008 > (_e960 + _e240)) {
                                                        let _e3014 = local_25;
                                                        let _e3020 = local_26;
                                                        let _e3023 = local_27;
                                                        phi_5368_ = (vec3<f32>(((((_e2807 * 2f) - 1f) * _e2710) * _e3014), ((((_e2808 * -2f) + 1f) * _e2718) * _e3020), _e3023) - _e476);
                                                    } else {
                                                        phi_5368_ = vec3<f32>((_e2450 - _e2999), (_e2451 - _e3000), (_e2452 - _e3001));
                                                    }
                                                    let _e3027 = phi_5368_;
                                                    let _e3029 = (_e2918 * inverseSqrt(_e2457));
                                                    let _e3033 = select(-1f, select(1f, _e3029, (_e3029 < 1f)), (_e3029 > -1f));
                                                    let _e3034 = abs(_e3033);
                                                    let _e3044 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3034, 0.00667009f), _e3034, -0.017088126f), _e3034, 0.03089188f), _e3034, -0.050174303f), _e3034, 0.08897899f), _e3034, -0.2145988f), _e3034, 1.5707963f) * sqrt((1f - _e3034)));
                                                    let _e3051 = ((((select((3.1415927f - _e3044), _e3044, (_e3033 >= 0f)) + _e2992) - _e2988) + 1.5707964f) * 0.31830987f);
                                                    let _e3070 = ((((_e3027.x * _e487) + (_e3027.y * _e488)) + (_e3027.z * _e489)) * inverseSqrt((((_e3027.x * _e3027.x) + (_e3027.y * _e3027.y)) + (_e3027.z * _e3027.z))));
                                                    let _e3074 = select(-1f, select(1f, _e3070, (_e3070 < 1f)), (_e3070 > -1f));
                                                    let _e3075 = abs(_e3074);
                                                    let _e3085 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3075, 0.00667009f), _e3075, -0.017088126f), _e3075, 0.03089188f), _e3075, -0.050174303f), _e3075, 0.08897899f), _e3075, -0.2145988f), _e3075, 1.5707963f) * sqrt((1f - _e3075)));
                                                    let _e3092 = ((((select((3.1415927f - _e3085), _e3085, (_e3074 >= 0f)) + _e2992) - _e2988) + 1.5707964f) * 0.31830987f);
                                                    let _e3097 = (1f - select(0f, select(1f, _e3051, (_e3051 < 1f)), (_e3051 > 0f)));
                                                    let _e3098 = (1f - select(0f, select(1f, _e3092, (_e3092 < 1f)), (_e3092 > 0f)));
                                                    let _e3100 = (_e3098 != _e3098);
                                                    let _e3102 = select(_e3098, _e3097, ((_e3097 < _e3098) || _e3100));
                                                    let _e3105 = select(_e3098, _e3097, ((_e3097 > _e3098) || _e3100));
                                                    let _e3107 = floor((_e3102 * 32f));
                                                    let _e3108 = (_e237 == 1u);
                                                    if _e3108 {
                                                        let _e3115 = -(floor((_e3105 * -32f)));
                                                        let _e3120 = (select(32f, _e3115, ((_e3115 < 32f) || false)) - _e3107);
                                                        phi_5555_ = select(select(0f, _e3120, ((_e3120 > 0f) || false)), 0f, (_e3105 <= _e3102));
                                                    } else {
                                                        phi_5555_ = -(floor(((_e3105 - _e3102) * -32f)));
                                                    }
                                                    let _e3126 = phi_5555_;
                                                    let _e3134 = (bitcast<u32>((floor(select(0f, select(32f, _e3107, (_e3107 < 32f)), (_e3107 > 0f))) + 8388608f)) - 1258291200u);
                                                    let _e3142 = (bitcast<u32>((floor(select(0f, select(32f, _e3126, (_e3126 < 32f)), (_e3126 > 0f))) + 8388608f)) - 1258291200u);
                                                    if (_e3134 >= 32u) {
                                                        phi_5609_ = u32();
                                                        phi_5610_ = true;
                                                    } else {
                                                        let _e3144 = (_e3142 == 0u);
                                                        if _e3144 {
                                                            phi_5608_ = u32();
                                                        } else {
                                                            if (_e3142 >= 32u) {
                                                                phi_5605_ = 4294967295u;
                                                            } else {
                                                                phi_5605_ = ((1u << bitcast<u32>((_e3142 & 31u))) - 1u);
                                                            }
                                                            let _e3151 = phi_5605_;
                                                            phi_5608_ = (_e3151 << bitcast<u32>((_e3134 & 31u)));
                                                        }
                                                        let _e3156 = phi_5608_;
                                                        phi_5609_ = _e3156;
                                                        phi_5610_ = _e3144;
                                                    }
                                                    let _e3158 = phi_5609_;
                                                    let _e3160 = phi_5610_;
                                                    phi_7226_ = _e2910;
                                                    let _e4268 = local_48;
                                                    phi_5620_ = _e4268;
                                                    phi_5623_ = 1u;
                                                    phi_5625_ = select(select(_e3158, 0u, _e3160), 0u, _e2998);
                                                    loop {
                                                        let _e3164 = phi_7226_;
                                                        let _e3166 = phi_5620_;
                                                        let _e3168 = phi_5623_;
                                                        let _e3170 = phi_5625_;
                                                        local_50 = _e3170;
                                                        if (_e3168 < _e2873) {
                                                            phi_5655_ = 0u;
                                                            phi_5658_ = _e2878;
                                                            loop {
                                                                let _e3173 = phi_5655_;
                                                                let _e3175 = phi_5658_;
                                                                local_28 = _e3175;
                                                                local_29 = _e3175;
                                                                local_30 = _e3175;
                                                                local_31 = _e3175;
                                                                local_32 = _e3175;
                                                                let _e3176 = (_e3173 < _e2873);
                                                                if _e3176 {
                                                                    let _e3177 = (_e2874 + _e3173);
                                                                    if (_e3177 < _e190) {
                                                                    } else {
                                                                        phi_7220_ = true;
                                                                        break;
                                                                    }
                                                                    let _e3180 = sd_map.member[_e3177];
                                                                    let _e3184 = frame.member[0u].member_1.member.member.member_2;
                                                                    let _e3187 = ((_e3180 * (_e2878 - _e3184)) + _e3184);
                                                                    if (_e3180 < 1f) {
                                                                        if (_e3187 > _e3166) {
                                                                            phi_5700_ = select(_e3175, _e3187, (_e3187 < _e3175));
                                                                        } else {
                                                                            phi_5700_ = _e3175;
                                                                        }
                                                                        let _e3193 = phi_5700_;
                                                                        phi_5701_ = _e3193;
                                                                    } else {
                                                                        phi_5701_ = _e3175;
                                                                    }
                                                                    let _e3195 = phi_5701_;
                                                                    phi_5656_ = (_e3173 + 1u);
                                                                    phi_5659_ = _e3195;
                                                                } else {
                                                                    phi_5656_ = u32();
                                                                    phi_5659_ = f32();
                                                                }
                                                                let _e3198 = phi_5656_;
                                                                let _e3200 = phi_5659_;
                                                                continue;
                                                                continuing {
                                                                    phi_5655_ = _e3198;
                                                                    phi_5658_ = _e3200;
                                                                    phi_7220_ = _e3164;
                                                                    break if !(_e3176);
                                                                }
                                                            }
                                                            let _e3203 = phi_7220_;
                                                            phi_7265_ = _e3203;
                                                            if _e3203 {
                                                                break;
                                                            }
                                                            let _e3205 = local_28;
                                                            let _e3206 = (_e3205 >= _e2878);
                                                            if _e3206 {
                                                                phi_7267_ = _e3203;
                                                                phi_6106_ = f32();
                                                                phi_6107_ = u32();
                                                                phi_6108_ = u32();
                                                            } else {
                                                                phi_5729_ = 0u;
                                                                phi_5732_ = _e2878;
                                                                loop {
                                                                    let _e3208 = phi_5729_;
                                                                    let _e3210 = phi_5732_;
                                                                    local_33 = _e3210;
                                                                    local_34 = _e3210;
                                                                    local_35 = _e3210;
                                                                    local_36 = _e3210;
                                                                    local_49 = _e3210;
                                                                    let _e3211 = (_e3208 < _e2873);
                                                                    if _e3211 {
                                                                        let _e3212 = (_e2874 + _e3208);
                                                                        if (_e3212 < _e190) {
                                                                        } else {
                                                                            phi_7259_ = true;
                                                                            break;
                                                                        }
                                                                        let _e3215 = sd_map.member[_e3212];
                                                                        let _e3219 = frame.member[0u].member_1.member.member.member_2;
                                                                        let _e3222 = ((_e3215 * (_e2878 - _e3219)) + _e3219);
                                                                        if (_e3215 < 1f) {
                                                                            let _e3225 = local_29;
                                                                            if (_e3222 > _e3225) {
                                                                                phi_5774_ = select(_e3210, _e3222, (_e3222 < _e3210));
                                                                            } else {
                                                                                phi_5774_ = _e3210;
                                                                            }
                                                                            let _e3230 = phi_5774_;
                                                                            phi_5775_ = _e3230;
                                                                        } else {
                                                                            phi_5775_ = _e3210;
                                                                        }
                                                                        let _e3232 = phi_5775_;
                                                                        phi_5730_ = (_e3208 + 1u);
                                                                        phi_5733_ = _e3232;
                                                                    } else {
                                                                        phi_5730_ = u32();
                                                                        phi_5733_ = f32();
                                                                    }
                                                                    let _e3235 = phi_5730_;
                                                                    let _e3237 = phi_5733_;
                                                                    continue;
                                                                    continuing {
                                                                        phi_5729_ = _e3235;
                                                                        phi_5732_ = _e3237;
                                                                        phi_7259_ = _e3203;
                                                                        break if !(_e3211);
                                                                    }
                                                                }
                                                                let _e3240 = phi_7259_;
                                                                phi_7265_ = _e3240;
                                                                if _e3240 {
                                                                    break;
                                                                }
                                                                let _e3243 = (((_e2807 * 2f) - 1f) * _e2710);
                                                                let _e3245 = local_30;
                                                                let _e3249 = (((_e2808 * -2f) + 1f) * _e2718);
                                                                let _e3251 = local_31;
                                                                let _e3253 = ((_e3243 * _e3245) - _e468);
                                                                let _e3254 = ((_e3249 * _e3251) - _e475);
                                                                let _e3256 = local_32;
                                                                let _e3257 = (_e3256 - _e461);
                                                                let _e3259 = local_33;
                                                                if (_e3259 < _e2878) {
                                                                    let _e3266 = local_34;
                                                                    let _e3269 = local_35;
                                                                    let _e3272 = local_36;
                                                                    phi_5834_ = (vec3<f32>((_e3243 * _e3266), (_e3249 * _e3269), _e3272) - _e476);
                                                                } else {
                                                                    phi_5834_ = vec3<f32>((_e3253 - _e2999), (_e3254 - _e3000), (_e3257 - _e3001));
                                                                }
                                                                let _e3276 = phi_5834_;
                                                                if _e977 {
                                                                    phi_5849_ = true;
                                                                } else {
                                                                    phi_5849_ = ((((_e3253 * _e3253) + (_e3254 * _e3254)) + (_e3257 * _e3257)) <= (_e243 * _e243));
                                                                }
                                                                let _e3285 = phi_5849_;
                                                                if _e3285 {
                                                                    let _e3297 = ((((_e3253 * _e487) + (_e3254 * _e488)) + (_e3257 * _e489)) * inverseSqrt((((_e3253 * _e3253) + (_e3254 * _e3254)) + (_e3257 * _e3257))));
                                                                    let _e3301 = select(-1f, select(1f, _e3297, (_e3297 < 1f)), (_e3297 > -1f));
                                                                    let _e3302 = abs(_e3301);
                                                                    let _e3312 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3302, 0.00667009f), _e3302, -0.017088126f), _e3302, 0.03089188f), _e3302, -0.050174303f), _e3302, 0.08897899f), _e3302, -0.2145988f), _e3302, 1.5707963f) * sqrt((1f - _e3302)));
                                                                    let _e3319 = ((((select((3.1415927f - _e3312), _e3312, (_e3301 >= 0f)) + _e2992) - _e2988) + 1.5707964f) * 0.31830987f);
                                                                    let _e3338 = ((((_e3276.x * _e487) + (_e3276.y * _e488)) + (_e3276.z * _e489)) * inverseSqrt((((_e3276.x * _e3276.x) + (_e3276.y * _e3276.y)) + (_e3276.z * _e3276.z))));
                                                                    let _e3342 = select(-1f, select(1f, _e3338, (_e3338 < 1f)), (_e3338 > -1f));
                                                                    let _e3343 = abs(_e3342);
                                                                    let _e3353 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3343, 0.00667009f), _e3343, -0.017088126f), _e3343, 0.03089188f), _e3343, -0.050174303f), _e3343, 0.08897899f), _e3343, -0.2145988f), _e3343, 1.5707963f) * sqrt((1f - _e3343)));
                                                                    let _e3360 = ((((select((3.1415927f - _e3353), _e3353, (_e3342 >= 0f)) + _e2992) - _e2988) + 1.5707964f) * 0.31830987f);
                                                                    let _e3365 = (1f - select(0f, select(1f, _e3319, (_e3319 < 1f)), (_e3319 > 0f)));
                                                                    let _e3366 = (1f - select(0f, select(1f, _e3360, (_e3360 < 1f)), (_e3360 > 0f)));
                                                                    let _e3368 = (_e3366 != _e3366);
                                                                    let _e3370 = select(_e3366, _e3365, ((_e3365 < _e3366) || _e3368));
                                                                    let _e3373 = select(_e3366, _e3365, ((_e3365 > _e3366) || _e3368));
                                                                    let _e3375 = floor((_e3370 * 32f));
                                                                    if _e3108 {
                                                                        let _e3382 = -(floor((_e3373 * -32f)));
                                                                        let _e3387 = (select(32f, _e3382, ((_e3382 < 32f) || false)) - _e3375);
                                                                        phi_6039_ = select(select(0f, _e3387, ((_e3387 > 0f) || false)), 0f, (_e3373 <= _e3370));
                                                                    } else {
                                                                        phi_6039_ = -(floor(((_e3373 - _e3370) * -32f)));
                                                                    }
                                                                    let _e3393 = phi_6039_;
                                                                    let _e3401 = (bitcast<u32>((floor(select(0f, select(32f, _e3375, (_e3375 < 32f)), (_e3375 > 0f))) + 8388608f)) - 1258291200u);
                                                                    let _e3409 = (bitcast<u32>((floor(select(0f, select(32f, _e3393, (_e3393 < 32f)), (_e3393 > 0f))) + 8388608f)) - 1258291200u);
                                                                    if (_e3401 >= 32u) {
                                                                        phi_6093_ = u32();
                                                                        phi_6094_ = true;
                                                                    } else {
                                                                        let _e3411 = (_e3409 == 0u);
                                                                        if _e3411 {
                                                                            phi_6092_ = u32();
                                                                        } else {
                                                                            if (_e3409 >= 32u) {
                                                                                phi_6089_ = 4294967295u;
                                                                            } else {
                                                                                phi_6089_ = ((1u << bitcast<u32>((_e3409 & 31u))) - 1u);
                                                                            }
                                                                            let _e3418 = phi_6089_;
                                                                            phi_6092_ = (_e3418 << bitcast<u32>((_e3401 & 31u)));
                                                                        }
                                                                        let _e3423 = phi_6092_;
                                                                        phi_6093_ = _e3423;
                                                                        phi_6094_ = _e3411;
                                                                    }
                                                                    let _e3425 = phi_6093_;
                                                                    let _e3427 = phi_6094_;
                                                                    phi_6104_ = (_e3170 | select(select(_e3425, 0u, _e3427), 0u, _e2998));
                                                                } else {
                                                                    phi_6104_ = _e3170;
                                                                }
                                                                let _e3432 = phi_6104_;
                                                                phi_7267_ = _e3240;
                                                                let _e4305 = local_49;
                                                                phi_6106_ = _e4305;
                                                                phi_6107_ = (_e3168 + 2u);
                                                                phi_6108_ = _e3432;
                                                            }
                                                            let _e3435 = phi_7267_;
                                                            let _e3437 = phi_6106_;
                                                            let _e3439 = phi_6107_;
                                                            let _e3441 = phi_6108_;
                                                            phi_7266_ = _e3435;
                                                            phi_5621_ = _e3437;
                                                            phi_5624_ = _e3439;
                                                            phi_5626_ = _e3441;
                                                            phi_6110_ = select(true, false, _e3206);
                                                        } else {
                                                            phi_7266_ = _e3164;
                                                            phi_5621_ = f32();
                                                            phi_5624_ = u32();
                                                            phi_5626_ = u32();
                                                            phi_6110_ = false;
                                                        }
                                                        let _e3444 = phi_7266_;
                                                        let _e3446 = phi_5621_;
                                                        let _e3448 = phi_5624_;
                                                        let _e3450 = phi_5626_;
                                                        let _e3452 = phi_6110_;
                                                        continue;
                                                        continuing {
                                                            phi_7226_ = _e3444;
                                                            phi_5620_ = _e3446;
                                                            phi_5623_ = _e3448;
                                                            phi_5625_ = _e3450;
                                                            phi_7265_ = _e3444;
                                                            break if !(_e3452);
                                                        }
                                                    }
                                                    let _e3455 = phi_7265_;
                                                    phi_7297_ = _e3455;
                                                    if _e3455 {
                                                        break;
                                                    }
                                                    phi_7336_ = _e3455;
                                                    phi_6115_ = u32();
                                                    let _e4325 = local_50;
                                                    phi_6116_ = _e4325;
                                                }
                                                let _e3689 = phi_7336_;
                                                let _e3691 = phi_6115_;
                                                let _e3693 = phi_6116_;
                                                phi_7301_ = _e3689;
                                                phi_6117_ = _e3691;
                                                phi_6118_ = _e3693;
                                                phi_6119_ = _e2913;
                                            }
                                            let _e3927 = phi_7301_;
                                            let _e3929 = phi_6117_;
                                            let _e3931 = phi_6118_;
                                            let _e3933 = phi_6119_;
                                            phi_7299_ = _e3927;
                                            phi_6520_ = select(_e3931, _e3929, _e3933);
                                        } else {
                                            if (_e243 > 0f) {
                                                phi_6135_ = (_e2457 > (_e243 * _e243));
                                            } else {
                                                phi_6135_ = false;
                                            }
                                            let _e2476 = phi_6135_;
                                            if !(_e2476) {
                                                let _e2482 = (((_e2450 * _e487) + (_e2451 * _e488)) + (_e2452 * _e489));
                                                let _e2486 = (_e2450 - (_e487 * _e2482));
                                                let _e2487 = (_e2451 - (_e488 * _e2482));
                                                let _e2488 = (_e2452 - (_e489 * _e2482));
                                                let _e2491 = ((_e2487 * _e489) - (_e488 * _e2488));
                                                let _e2494 = ((_e2488 * _e487) - (_e489 * _e2486));
                                                let _e2497 = ((_e2486 * _e488) - (_e487 * _e2487));
                                                let _e2508 = ((((_e548 * _e2491) + (_e549 * _e2494)) + (_e550 * _e2497)) / (((_e2491 * _e2491) + (_e2494 * _e2494)) + (_e2497 * _e2497)));
                                                let _e2512 = (_e548 - (_e2491 * _e2508));
                                                let _e2513 = (_e549 - (_e2494 * _e2508));
                                                let _e2514 = (_e550 - (_e2497 * _e2508));
                                                let _e2520 = inverseSqrt((((_e2512 * _e2512) + (_e2513 * _e2513)) + (_e2514 * _e2514)));
                                                let _e2526 = ((((_e2512 * _e487) + (_e2513 * _e488)) + (_e2514 * _e489)) * _e2520);
                                                let _e2530 = select(0f, select(1f, _e2526, (_e2526 < 1f)), (_e2526 > 0f));
                                                let _e2531 = abs(_e2530);
                                                let _e2541 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2531, 0.00667009f), _e2531, -0.017088126f), _e2531, 0.03089188f), _e2531, -0.050174303f), _e2531, 0.08897899f), _e2531, -0.2145988f), _e2531, 1.5707963f) * sqrt((1f - _e2531)));
                                                let _e2544 = select((3.1415927f - _e2541), _e2541, (_e2530 >= 0f));
                                                let _e2552 = select(_e2544, -(_e2544), ((((_e2486 * _e2512) + (_e2487 * _e2513)) + (_e2488 * _e2514)) < 0f));
                                                let _e2553 = (_e2520 * 0.02f);
                                                let _e2556 = select(0.19634955f, _e2553, ((_e2553 < 0.19634955f) || false));
                                                let _e2566 = (_e2450 - (_e487 * _e240));
                                                let _e2567 = (_e2451 - (_e488 * _e240));
                                                let _e2568 = (_e2452 - (_e489 * _e240));
                                                let _e2570 = (_e2482 * inverseSqrt(_e2457));
                                                let _e2574 = select(-1f, select(1f, _e2570, (_e2570 < 1f)), (_e2570 > -1f));
                                                let _e2575 = abs(_e2574);
                                                let _e2585 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2575, 0.00667009f), _e2575, -0.017088126f), _e2575, 0.03089188f), _e2575, -0.050174303f), _e2575, 0.08897899f), _e2575, -0.2145988f), _e2575, 1.5707963f) * sqrt((1f - _e2575)));
                                                let _e2592 = ((((select((3.1415927f - _e2585), _e2585, (_e2574 >= 0f)) + _e2556) - _e2552) + 1.5707964f) * 0.31830987f);
                                                let _e2608 = ((((_e2566 * _e487) + (_e2567 * _e488)) + (_e2568 * _e489)) * inverseSqrt((((_e2566 * _e2566) + (_e2567 * _e2567)) + (_e2568 * _e2568))));
                                                let _e2612 = select(-1f, select(1f, _e2608, (_e2608 < 1f)), (_e2608 > -1f));
                                                let _e2613 = abs(_e2612);
                                                let _e2623 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2613, 0.00667009f), _e2613, -0.017088126f), _e2613, 0.03089188f), _e2613, -0.050174303f), _e2613, 0.08897899f), _e2613, -0.2145988f), _e2613, 1.5707963f) * sqrt((1f - _e2613)));
                                                let _e2630 = ((((select((3.1415927f - _e2623), _e2623, (_e2612 >= 0f)) + _e2556) - _e2552) + 1.5707964f) * 0.31830987f);
                                                let _e2635 = (1f - select(0f, select(1f, _e2592, (_e2592 < 1f)), (_e2592 > 0f)));
                                                let _e2636 = (1f - select(0f, select(1f, _e2630, (_e2630 < 1f)), (_e2630 > 0f)));
                                                let _e2638 = (_e2636 != _e2636);
                                                let _e2640 = select(_e2636, _e2635, ((_e2635 < _e2636) || _e2638));
                                                let _e2643 = select(_e2636, _e2635, ((_e2635 > _e2636) || _e2638));
                                                let _e2645 = floor((_e2640 * 32f));
                                                if (_e237 == 1u) {
                                                    let _e2653 = -(floor((_e2643 * -32f)));
                                                    let _e2658 = (select(32f, _e2653, ((_e2653 < 32f) || false)) - _e2645);
                                                    phi_6451_ = select(select(0f, _e2658, ((_e2658 > 0f) || false)), 0f, (_e2643 <= _e2640));
                                                } else {
                                                    phi_6451_ = -(floor(((_e2643 - _e2640) * -32f)));
                                                }
                                                let _e2664 = phi_6451_;
                                                let _e2672 = (bitcast<u32>((floor(select(0f, select(32f, _e2645, (_e2645 < 32f)), (_e2645 > 0f))) + 8388608f)) - 1258291200u);
                                                let _e2680 = (bitcast<u32>((floor(select(0f, select(32f, _e2664, (_e2664 < 32f)), (_e2664 > 0f))) + 8388608f)) - 1258291200u);
                                                if (_e2672 >= 32u) {
                                                    phi_6505_ = u32();
                                                    phi_6506_ = true;
                                                } else {
                                                    let _e2682 = (_e2680 == 0u);
                                                    if _e2682 {
                                                        phi_6504_ = u32();
                                                    } else {
                                                        if (_e2680 >= 32u) {
                                                            phi_6501_ = 4294967295u;
                                                        } else {
                                                            phi_6501_ = ((1u << bitcast<u32>((_e2680 & 31u))) - 1u);
                                                        }
                                                        let _e2689 = phi_6501_;
                                                        phi_6504_ = (_e2689 << bitcast<u32>((_e2672 & 31u)));
                                                    }
                                                    let _e2694 = phi_6504_;
                                                    phi_6505_ = _e2694;
                                                    phi_6506_ = _e2682;
                                                }
                                                let _e2696 = phi_6505_;
                                                let _e2698 = phi_6506_;
                                                phi_6519_ = select(select(select(_e2696, 0u, _e2698), 0u, ((((_e2486 * _e2486) + (_e2487 * _e2487)) + (_e2488 * _e2488)) <= 0f)), 0u, _e2476);
                                            } else {
                                                phi_6519_ = 0u;
                                            }
                                            let _e2703 = phi_6519_;
                                            phi_7299_ = _e2446;
                                            phi_6520_ = _e2703;
                                        }
                                        let _e3936 = phi_7299_;
                                        let _e3938 = phi_6520_;
                                        phi_7298_ = _e3936;
                                        phi_1198_ = (_e792 + 1u);
                                        phi_1201_ = ((_e794 | _e2448) | _e3938);
                                    } else {
                                        phi_7298_ = _e790;
                                        phi_1198_ = u32();
                                        phi_1201_ = u32();
                                    }
                                    let _e3942 = phi_7298_;
                                    let _e3944 = phi_1198_;
                                    let _e3946 = phi_1201_;
                                    continue;
                                    continuing {
                                        phi_6943_ = _e3942;
                                        phi_1197_ = _e3944;
                                        phi_1200_ = _e3946;
                                        phi_7297_ = _e3942;
                                        break if !(_e795);
                                    }
                                }
                                let _e3949 = phi_7297_;
                                phi_7408_ = _e3949;
                                if _e3949 {
                                    break;
                                }
                                if (_e232 == 2u) {
                                    let _e4008 = (_e785 - 1.5707964f);
                                    let _e4009 = (_e4008 * 2f);
                                    let _e4010 = sin(_e785);
                                    let _e4015 = ((_e770 + (_e4009 * _e4010)) - cos((_e4009 - _e785)));
                                    phi_6549_ = 0u;
                                    phi_6552_ = select((_e4015 * 0.25f), (_e4015 * -0.25f), (_e4008 < 0f));
                                    phi_6554_ = 0f;
                                    loop {
                                        let _e4021 = phi_6549_;
                                        let _e4023 = phi_6552_;
                                        let _e4025 = phi_6554_;
                                        local_41 = _e4025;
                                        let _e4026 = (_e4021 < 32u);
                                        if _e4026 {
                                            let _e4027 = (_e4021 + 1u);
                                            let _e4031 = (_e4008 + (f32(bitcast<i32>(_e4027)) * 0.09817477f));
                                            let _e4032 = (_e4031 * 2f);
                                            let _e4037 = ((_e770 + (_e4032 * _e4010)) - cos((_e4032 - _e785)));
                                            let _e4041 = select((_e4037 * 0.25f), (_e4037 * -0.25f), (_e4031 < 0f));
                                            let _e4044 = local_40;
                                            phi_6550_ = _e4027;
                                            phi_6553_ = _e4041;
                                            phi_6555_ = select(_e4025, (_e4025 + (_e4041 - _e4023)), (((_e4044 >> bitcast<u32>((_e4021 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_6550_ = u32();
                                            phi_6553_ = f32();
                                            phi_6555_ = f32();
                                        }
                                        let _e4053 = phi_6550_;
                                        let _e4055 = phi_6553_;
                                        let _e4057 = phi_6555_;
                                        continue;
                                        continuing {
                                            phi_6549_ = _e4053;
                                            phi_6552_ = _e4055;
                                            phi_6554_ = _e4057;
                                            break if !(_e4026);
                                        }
                                    }
                                    let _e4060 = local_41;
                                    phi_7410_ = _e3949;
                                    phi_6656_ = (_e691 + 1f);
                                    phi_6657_ = (_e693 + ((_e751 + ((1f - _e751) * 0.05f)) * _e4060));
                                } else {
                                    if (_e232 == 1u) {
                                        phi_6601_ = 0u;
                                        phi_6604_ = 0f;
                                        loop {
                                            let _e3963 = phi_6601_;
                                            let _e3965 = phi_6604_;
                                            local_39 = _e3965;
                                            let _e3966 = (_e3963 < 4u);
                                            if _e3966 {
                                                local = array<type_40, 4>(type_40(4026531855u, 0.0095061f), type_40(251658480u, 0.0270951f), type_40(15732480u, 0.0405571f), type_40(1044480u, 0.0478421f));
                                                if _e3966 {
                                                } else {
                                                    phi_7405_ = true;
                                                    break;
                                                }
                                                let _e3969 = local[_e3963].member;
                                                let _e3972 = local[_e3963].member_1;
                                                let _e3974 = local_38;
                                                phi_6602_ = (_e3963 + 1u);
                                                phi_6605_ = (_e3965 + (f32(bitcast<i32>(countOneBits((_e3974 & _e3969)))) * _e3972));
                                            } else {
                                                phi_6602_ = u32();
                                                phi_6605_ = f32();
                                            }
                                            let _e3983 = phi_6602_;
                                            let _e3985 = phi_6605_;
                                            continue;
                                            continuing {
                                                phi_6601_ = _e3983;
                                                phi_6604_ = _e3985;
                                                phi_7405_ = _e3949;
                                                break if !(_e3966);
                                            }
                                        }
                                        let _e3988 = phi_7405_;
                                        phi_7408_ = _e3988;
                                        if _e3988 {
                                            break;
                                        }
                                        let _e3990 = local_39;
                                        let _e3991 = (1f - _e3990);
                                        phi_7416_ = _e3988;
                                        phi_6654_ = (_e691 + _e751);
                                        phi_6655_ = (_e693 + (_e751 * select(0f, select(1f, _e3991, (_e3991 < 1f)), (_e3991 > 0f))));
                                    } else {
                                        let _e3953 = local_37;
                                        phi_7416_ = _e3949;
                                        phi_6654_ = (_e691 + 1f);
                                        phi_6655_ = (_e693 + ((f32(bitcast<i32>(countOneBits((_e3953 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e4000 = phi_7416_;
                                    let _e4002 = phi_6654_;
                                    let _e4004 = phi_6655_;
                                    phi_7410_ = _e4000;
                                    phi_6656_ = _e4002;
                                    phi_6657_ = _e4004;
                                }
                                let _e4065 = phi_7410_;
                                let _e4067 = phi_6656_;
                                let _e4069 = phi_6657_;
                                phi_7409_ = _e4065;
                                phi_1007_ = (_e689 + 1u);
                                phi_1010_ = _e4067;
                                phi_1012_ = _e4069;
                            } else {
                                phi_7409_ = _e687;
                                phi_1007_ = u32();
                                phi_1010_ = f32();
                                phi_1012_ = f32();
                            }
                            let _e4072 = phi_7409_;
                            let _e4074 = phi_1007_;
                            let _e4076 = phi_1010_;
                            let _e4078 = phi_1012_;
                            continue;
                            continuing {
                                phi_6952_ = _e4072;
                                phi_1006_ = _e4074;
                                phi_1009_ = _e4076;
                                phi_1011_ = _e4078;
                                phi_7408_ = _e4072;
                                break if !(_e694);
                            }
                        }
                        let _e4081 = phi_7408_;
                        if _e4081 {
                            break;
                        }
                        let _e4083 = local_42;
                        let _e4086 = local_43;
                        let _e4088 = local_44;
                        phi_6665_ = select(1f, (_e4086 / _e4088), (_e4083 > 0f));
                    } else {
                        phi_6665_ = 1f;
                    }
                    let _e4092 = phi_6665_;
                    if (_e227.member_6 == 2f) {
                        phi_6678_ = (_e4092 * _e4092);
                    } else {
                        if (_e227.member_6 == 1f) {
                            phi_6677_ = _e4092;
                        } else {
                            phi_6677_ = pow(_e4092, _e227.member_6);
                        }
                        let _e4098 = phi_6677_;
                        phi_6678_ = _e4098;
                    }
                    let _e4101 = phi_6678_;
                    let _e4106 = (select(1f, select(0.03f, _e4101, ((_e4101 > 0.03f) || false)), _e682) * 0.6666667f);
                    terms.member[_e269] = (bitcast<u32>((floor(((select(0f, select(1f, _e4106, (_e4106 < 1f)), (_e4106 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                    edges.member[_e269] = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e398, (_e398 < 3f)), (_e398 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e413, (_e413 < 3f)), (_e413 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e429, (_e429 < 3f)), (_e429 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e445, (_e445 < 3f)), (_e445 > 0f))) + 8388608f)) - 1258291200u));
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
