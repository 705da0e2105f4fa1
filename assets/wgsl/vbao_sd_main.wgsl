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
    var phi_355_: type_26;
    var phi_362_: u32;
    var phi_369_: u32;
    var phi_8399_: bool;
    var phi_1027_: u32;
    var phi_1030_: f32;
    var phi_1032_: f32;
    var phi_1218_: u32;
    var phi_1221_: u32;
    var phi_1278_: f32;
    var phi_1279_: f32;
    var phi_1561_: bool;
    var phi_1716_: bool;
    var phi_1732_: bool;
    var phi_1891_: vec2<f32>;
    var phi_1892_: vec2<f32>;
    var phi_2010_: f32;
    var phi_2061_: bool;
    var phi_2062_: bool;
    var phi_2068_: f32;
    var phi_2101_: bool;
    var phi_2102_: bool;
    var phi_2108_: f32;
    var phi_2141_: bool;
    var phi_2142_: bool;
    var phi_2148_: f32;
    var phi_2181_: bool;
    var phi_2182_: bool;
    var phi_2188_: f32;
    var phi_2225_: bool;
    var phi_2226_: bool;
    var phi_2232_: f32;
    var phi_2265_: bool;
    var phi_2266_: bool;
    var phi_2272_: f32;
    var phi_2305_: bool;
    var phi_2306_: bool;
    var phi_2312_: f32;
    var phi_2345_: bool;
    var phi_2346_: bool;
    var phi_2352_: f32;
    var phi_2361_: f32;
    var phi_2362_: f32;
    var phi_2363_: f32;
    var phi_2364_: f32;
    var phi_6854_: bool;
    var phi_6869_: bool;
    var phi_6884_: bool;
    var phi_6899_: bool;
    var phi_6914_: bool;
    var phi_6929_: bool;
    var phi_6944_: bool;
    var phi_6959_: bool;
    var phi_6974_: bool;
    var phi_6989_: bool;
    var phi_7004_: bool;
    var phi_7019_: bool;
    var phi_7034_: bool;
    var phi_7049_: bool;
    var phi_7064_: bool;
    var phi_7079_: bool;
    var phi_7094_: bool;
    var phi_7109_: bool;
    var phi_7124_: bool;
    var phi_7139_: bool;
    var phi_7154_: bool;
    var phi_7169_: bool;
    var phi_7184_: bool;
    var phi_7199_: bool;
    var phi_7214_: bool;
    var phi_7229_: bool;
    var phi_7244_: bool;
    var phi_7259_: bool;
    var phi_7274_: bool;
    var phi_7289_: bool;
    var phi_7304_: bool;
    var phi_7319_: bool;
    var phi_7334_: bool;
    var phi_7349_: bool;
    var phi_7364_: bool;
    var phi_7379_: bool;
    var phi_7394_: bool;
    var phi_7409_: bool;
    var phi_2433_: vec3<f32>;
    var phi_2434_: vec3<f32>;
    var phi_2488_: vec3<f32>;
    var phi_2504_: bool;
    var phi_2694_: f32;
    var phi_2744_: u32;
    var phi_2747_: u32;
    var phi_2748_: u32;
    var phi_2749_: bool;
    var phi_2758_: u32;
    var phi_2760_: u32;
    var phi_2761_: bool;
    var phi_2819_: vec3<f32>;
    var phi_2835_: bool;
    var phi_3025_: f32;
    var phi_3075_: u32;
    var phi_3078_: u32;
    var phi_3079_: u32;
    var phi_3080_: bool;
    var phi_3089_: u32;
    var phi_3091_: u32;
    var phi_3092_: bool;
    var phi_3151_: vec3<f32>;
    var phi_3167_: bool;
    var phi_3357_: f32;
    var phi_3407_: u32;
    var phi_3410_: u32;
    var phi_3411_: u32;
    var phi_3412_: bool;
    var phi_3421_: u32;
    var phi_3423_: u32;
    var phi_3424_: bool;
    var phi_3485_: vec3<f32>;
    var phi_3501_: bool;
    var phi_3691_: f32;
    var phi_3741_: u32;
    var phi_3744_: u32;
    var phi_3745_: u32;
    var phi_3746_: bool;
    var phi_3755_: u32;
    var phi_3757_: u32;
    var phi_3758_: bool;
    var phi_3764_: vec3<f32>;
    var phi_3765_: u32;
    var phi_3952_: f32;
    var phi_4002_: u32;
    var phi_4005_: u32;
    var phi_4006_: u32;
    var phi_4007_: bool;
    var phi_4017_: u32;
    var phi_4041_: bool;
    var phi_4196_: bool;
    var phi_4212_: bool;
    var phi_4371_: vec2<f32>;
    var phi_4372_: vec2<f32>;
    var phi_4490_: f32;
    var phi_4541_: bool;
    var phi_4542_: bool;
    var phi_4548_: f32;
    var phi_4581_: bool;
    var phi_4582_: bool;
    var phi_4588_: f32;
    var phi_4621_: bool;
    var phi_4622_: bool;
    var phi_4628_: f32;
    var phi_4661_: bool;
    var phi_4662_: bool;
    var phi_4668_: f32;
    var phi_4705_: bool;
    var phi_4706_: bool;
    var phi_4712_: f32;
    var phi_4745_: bool;
    var phi_4746_: bool;
    var phi_4752_: f32;
    var phi_4785_: bool;
    var phi_4786_: bool;
    var phi_4792_: f32;
    var phi_4825_: bool;
    var phi_4826_: bool;
    var phi_4832_: f32;
    var phi_4841_: f32;
    var phi_4842_: f32;
    var phi_4843_: f32;
    var phi_4844_: f32;
    var phi_7424_: bool;
    var phi_7439_: bool;
    var phi_7454_: bool;
    var phi_7469_: bool;
    var phi_7484_: bool;
    var phi_7499_: bool;
    var phi_7514_: bool;
    var phi_7529_: bool;
    var phi_7544_: bool;
    var phi_7559_: bool;
    var phi_7574_: bool;
    var phi_7589_: bool;
    var phi_7604_: bool;
    var phi_7619_: bool;
    var phi_7634_: bool;
    var phi_7649_: bool;
    var phi_7664_: bool;
    var phi_7679_: bool;
    var phi_7694_: bool;
    var phi_7709_: bool;
    var phi_7724_: bool;
    var phi_7739_: bool;
    var phi_7754_: bool;
    var phi_7769_: bool;
    var phi_7784_: bool;
    var phi_7799_: bool;
    var phi_7814_: bool;
    var phi_7829_: bool;
    var phi_7844_: bool;
    var phi_7859_: bool;
    var phi_7874_: bool;
    var phi_7889_: bool;
    var phi_7904_: bool;
    var phi_7919_: bool;
    var phi_7934_: bool;
    var phi_7949_: bool;
    var phi_7964_: bool;
    var phi_7979_: bool;
    var phi_4913_: vec3<f32>;
    var phi_4914_: vec3<f32>;
    var phi_4968_: vec3<f32>;
    var phi_4984_: bool;
    var phi_5174_: f32;
    var phi_5224_: u32;
    var phi_5227_: u32;
    var phi_5228_: u32;
    var phi_5229_: bool;
    var phi_5238_: u32;
    var phi_5240_: u32;
    var phi_5241_: bool;
    var phi_5299_: vec3<f32>;
    var phi_5315_: bool;
    var phi_5505_: f32;
    var phi_5555_: u32;
    var phi_5558_: u32;
    var phi_5559_: u32;
    var phi_5560_: bool;
    var phi_5569_: u32;
    var phi_5571_: u32;
    var phi_5572_: bool;
    var phi_5631_: vec3<f32>;
    var phi_5647_: bool;
    var phi_5837_: f32;
    var phi_5887_: u32;
    var phi_5890_: u32;
    var phi_5891_: u32;
    var phi_5892_: bool;
    var phi_5901_: u32;
    var phi_5903_: u32;
    var phi_5904_: bool;
    var phi_5965_: vec3<f32>;
    var phi_5981_: bool;
    var phi_6171_: f32;
    var phi_6221_: u32;
    var phi_6224_: u32;
    var phi_6225_: u32;
    var phi_6226_: bool;
    var phi_6235_: u32;
    var phi_6237_: u32;
    var phi_6238_: bool;
    var phi_6244_: vec3<f32>;
    var phi_6245_: u32;
    var phi_6432_: f32;
    var phi_6482_: u32;
    var phi_6485_: u32;
    var phi_6486_: u32;
    var phi_6487_: bool;
    var phi_6497_: u32;
    var phi_1219_: u32;
    var phi_1222_: u32;
    var phi_8008_: bool;
    var local_9: u32;
    var phi_6578_: u32;
    var phi_6581_: f32;
    var local_10: u32;
    var phi_6579_: u32;
    var phi_6582_: f32;
    var phi_8707_: bool;
    var local_11: f32;
    var phi_8718_: bool;
    var phi_6631_: f32;
    var phi_6632_: f32;
    var phi_6526_: u32;
    var phi_6529_: f32;
    var phi_6531_: f32;
    var local_12: u32;
    var phi_6527_: u32;
    var phi_6530_: f32;
    var phi_6532_: f32;
    var local_13: f32;
    var phi_8712_: bool;
    var phi_6633_: f32;
    var phi_6634_: f32;
    var phi_8711_: bool;
    var phi_1028_: u32;
    var phi_1031_: f32;
    var phi_1033_: f32;
    var phi_8710_: bool;
    var local_14: f32;
    var local_15: f32;
    var local_16: f32;
    var phi_6642_: f32;
    var phi_6654_: f32;
    var phi_6655_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e184 = id_1;
            let _e191 = (override_type == 0u);
            if _e191 {
                let _e223 = params.member.member_4;
                phi_355_ = _e223;
            } else {
                let _e201 = params.member.member_4.member;
                let _e205 = params.member.member_4.member_1;
                let _e209 = params.member.member_4.member_10;
                let _e213 = params.member.member_4.member_11;
                let _e217 = params.member.member_4.member_12;
                let _e221 = params.member.member_4.member_14;
                phi_355_ = type_26(_e201, _e205, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e209, _e213, _e217, override_type_9, _e221);
            }
            let _e225 = phi_355_;
            if _e191 {
                let _e228 = params.member.member_2;
                phi_362_ = _e228;
            } else {
                phi_362_ = override_type_10;
            }
            let _e230 = phi_362_;
            if _e191 {
                let _e233 = params.member.member_3;
                phi_369_ = _e233;
            } else {
                phi_369_ = override_type_11;
            }
            let _e235 = phi_369_;
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
                    let _e474 = vec3<f32>(_e466, _e473, _e459);
                    let _e475 = -(_e466);
                    let _e476 = -(_e473);
                    let _e477 = (_e270 * -0.99999f);
                    let _e484 = (1f / sqrt((((_e475 * _e475) + (_e476 * _e476)) + (_e477 * _e477))));
                    let _e485 = (_e475 * _e484);
                    let _e486 = (_e476 * _e484);
                    let _e487 = (_e477 * _e484);
                    let _e490 = normals.member[_e267];
                    let _e493 = f32(bitcast<i32>((_e490 & 255u)));
                    let _e497 = (select(_e493, (_e493 - 256f), (_e493 >= 128f)) * 0.007874016f);
                    let _e500 = select(-1f, _e497, ((_e497 > -1f) || false));
                    let _e505 = f32(bitcast<i32>(((_e490 >> bitcast<u32>(8u)) & 255u)));
                    let _e509 = (select(_e505, (_e505 - 256f), (_e505 >= 128f)) * 0.007874016f);
                    let _e512 = select(-1f, _e509, ((_e509 > -1f) || false));
                    let _e514 = (1f - abs(_e500));
                    let _e515 = abs(_e512);
                    let _e516 = (_e514 - _e515);
                    let _e517 = (_e516 < 0f);
                    let _e525 = select(_e500, ((1f - _e515) * select(1f, -1f, (_e500 < 0f))), _e517);
                    let _e526 = select(_e512, (_e514 * select(1f, -1f, (_e512 < 0f))), _e517);
                    let _e533 = (1f / sqrt((((_e525 * _e525) + (_e526 * _e526)) + (_e516 * _e516))));
                    let _e534 = (_e525 * _e533);
                    let _e535 = (_e526 * _e533);
                    let _e536 = (_e516 * _e533);
                    let _e537 = -(_e536);
                    let _e543 = ((((_e534 * _e485) + (_e535 * _e486)) + (_e537 * _e487)) < 0f);
                    let _e546 = select(_e534, -(_e534), _e543);
                    let _e547 = select(_e535, -(_e535), _e543);
                    let _e548 = select(_e537, _e536, _e543);
                    let _e555 = ((_e225.member_1 * _e225.member_2) / (((_e270 * 1.99998f) * _e225.member.member_1.x) / _e225.member.member.x));
                    let _e558 = (_e184.x & 63u);
                    let _e559 = (_e184.y & 63u);
                    let _e562 = ((_e558 >> bitcast<u32>(5u)) & 1u);
                    let _e565 = ((_e559 >> bitcast<u32>(5u)) & 1u);
                    let _e569 = (_e565 ^ 1u);
                    let _e571 = ((_e562 & _e569) * 63u);
                    let _e572 = (_e558 ^ _e571);
                    let _e573 = (_e559 ^ _e571);
                    let _e575 = ((_e572 ^ _e573) * _e569);
                    let _e576 = (_e572 ^ _e575);
                    let _e577 = (_e573 ^ _e575);
                    let _e580 = ((_e576 >> bitcast<u32>(4u)) & 1u);
                    let _e583 = ((_e577 >> bitcast<u32>(4u)) & 1u);
                    let _e588 = (_e583 ^ 1u);
                    let _e590 = ((_e580 & _e588) * 63u);
                    let _e591 = (_e576 ^ _e590);
                    let _e592 = (_e577 ^ _e590);
                    let _e594 = ((_e591 ^ _e592) * _e588);
                    let _e595 = (_e591 ^ _e594);
                    let _e596 = (_e592 ^ _e594);
                    let _e599 = ((_e595 >> bitcast<u32>(3u)) & 1u);
                    let _e602 = ((_e596 >> bitcast<u32>(3u)) & 1u);
                    let _e607 = (_e602 ^ 1u);
                    let _e609 = ((_e599 & _e607) * 63u);
                    let _e610 = (_e595 ^ _e609);
                    let _e611 = (_e596 ^ _e609);
                    let _e613 = ((_e610 ^ _e611) * _e607);
                    let _e614 = (_e610 ^ _e613);
                    let _e615 = (_e611 ^ _e613);
                    let _e618 = ((_e614 >> bitcast<u32>(2u)) & 1u);
                    let _e621 = ((_e615 >> bitcast<u32>(2u)) & 1u);
                    let _e626 = (_e621 ^ 1u);
                    let _e628 = ((_e618 & _e626) * 63u);
                    let _e629 = (_e614 ^ _e628);
                    let _e630 = (_e615 ^ _e628);
                    let _e632 = ((_e629 ^ _e630) * _e626);
                    let _e633 = (_e629 ^ _e632);
                    let _e634 = (_e630 ^ _e632);
                    let _e637 = ((_e633 >> bitcast<u32>(1u)) & 1u);
                    let _e640 = ((_e634 >> bitcast<u32>(1u)) & 1u);
                    let _e645 = (_e640 ^ 1u);
                    let _e647 = ((_e637 & _e645) * 63u);
                    let _e648 = (_e633 ^ _e647);
                    let _e649 = (_e634 ^ _e647);
                    let _e651 = ((_e648 ^ _e649) * _e645);
                    let _e663 = f32(bitcast<i32>((((((((((_e562 * 3u) ^ _e565) * 1024u) + (((_e580 * 3u) ^ _e583) * 256u)) + (((_e599 * 3u) ^ _e602) * 64u)) + (((_e618 * 3u) ^ _e621) * 16u)) + (((_e637 * 3u) ^ _e640) * 4u)) + ((((_e648 ^ _e651) & 1u) * 3u) ^ ((_e649 ^ _e651) & 1u))) + (288u * (_e225.member_11 % 64u)))));
                    let _e665 = ((_e663 * 0.7548777f) + 0.5f);
                    let _e669 = ((_e663 * 0.5698403f) + 0.5f);
                    let _e675 = exp2(((2f * _e225.member_7) + 1f));
                    let _e680 = select(false, (_e270 < _e225.member.member_3), (_e270 > 0f));
                    if _e680 {
                        let _e683 = select(1u, _e225.member_8, (1u < _e225.member_8));
                        phi_8399_ = false;
                        phi_1027_ = 0u;
                        phi_1030_ = 0f;
                        phi_1032_ = 0f;
                        loop {
                            let _e685 = phi_8399_;
                            let _e687 = phi_1027_;
                            let _e689 = phi_1030_;
                            let _e691 = phi_1032_;
                            local_14 = _e689;
                            local_15 = _e691;
                            local_16 = _e689;
                            let _e692 = (_e687 < _e683);
                            if _e692 {
                                let _e699 = ((((_e665 - floor(_e665)) + f32(bitcast<i32>(_e687))) * 3.1415927f) / f32(bitcast<i32>(_e683)));
                                let _e700 = sin(_e699);
                                let _e701 = cos(_e699);
                                let _e707 = ((_e701 * _e485) + (_e700 * _e486));
                                let _e711 = (_e701 - (_e485 * _e707));
                                let _e712 = (_e700 - (_e486 * _e707));
                                let _e713 = -((_e487 * _e707));
                                let _e716 = ((_e712 * _e487) - (_e486 * _e713));
                                let _e719 = ((_e713 * _e485) - (_e487 * _e711));
                                let _e722 = ((_e711 * _e486) - (_e485 * _e712));
                                let _e729 = (1f / sqrt((((_e716 * _e716) + (_e719 * _e719)) + (_e722 * _e722))));
                                let _e730 = (_e716 * _e729);
                                let _e731 = (_e719 * _e729);
                                let _e732 = (_e722 * _e729);
                                let _e737 = (((_e546 * _e730) + (_e547 * _e731)) + (_e548 * _e732));
                                let _e741 = (_e546 - (_e730 * _e737));
                                let _e742 = (_e547 - (_e731 * _e737));
                                let _e743 = (_e548 - (_e732 * _e737));
                                let _e749 = sqrt((((_e741 * _e741) + (_e742 * _e742)) + (_e743 * _e743)));
                                let _e754 = (((_e711 * _e741) + (_e712 * _e742)) + (_e713 * _e743));
                                let _e764 = ((((_e741 * _e485) + (_e742 * _e486)) + (_e743 * _e487)) / _e749);
                                let _e768 = select(0f, select(1f, _e764, (_e764 < 1f)), (_e764 > 0f));
                                let _e769 = abs(_e768);
                                let _e780 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e769, 0.00667009f), _e769, -0.017088126f), _e769, 0.03089188f), _e769, -0.050174303f), _e769, 0.08897899f), _e769, -0.2145988f), _e769, 1.5707963f) * sqrt((1f - _e769)));
                                let _e783 = (select(select(0f, -1f, (_e754 < 0f)), 1f, (_e754 > 0f)) * select((3.1415927f - _e780), _e780, (_e768 >= 0f)));
                                let _e786 = select(1u, _e225.member_9, (1u < _e225.member_9));
                                phi_1218_ = 0u;
                                phi_1221_ = 0u;
                                loop {
                                    let _e788 = phi_1218_;
                                    let _e790 = phi_1221_;
                                    local_9 = _e790;
                                    local_10 = _e790;
                                    local_12 = _e790;
                                    let _e791 = (_e788 < _e786);
                                    if _e791 {
                                        let _e797 = ((_e669 - floor(_e669)) + (f32(bitcast<i32>((_e687 + (_e788 * _e786)))) * 0.618034f));
                                        let _e806 = (((_e797 - floor(_e797)) + f32(bitcast<i32>(_e788))) * (1f / f32(bitcast<i32>(_e786))));
                                        if (_e225.member_4 == 2f) {
                                            phi_1279_ = (_e806 * _e806);
                                        } else {
                                            if (_e225.member_4 == 1f) {
                                                phi_1278_ = _e806;
                                            } else {
                                                phi_1278_ = pow(_e806, _e225.member_4);
                                            }
                                            let _e812 = phi_1278_;
                                            phi_1279_ = _e812;
                                        }
                                        let _e815 = phi_1279_;
                                        let _e816 = (_e815 + (1.3f / _e555));
                                        let _e817 = ((_e701 * _e555) * _e816);
                                        let _e818 = ((-(_e700) * _e555) * _e816);
                                        let _e821 = ((_e817 * _e817) + (_e818 * _e818));
                                        let _e826 = (select(1u, _e249, (1u < _e249)) * select(1u, _e257, (1u < _e257)));
                                        let _e827 = (_e821 > _e675);
                                        let _e831 = (_e249 >> bitcast<u32>(1u));
                                        let _e835 = (_e257 >> bitcast<u32>(1u));
                                        let _e839 = (_e826 + (select(1u, _e831, (1u < _e831)) * select(1u, _e835, (1u < _e835))));
                                        let _e841 = (_e821 > (_e675 * 4f));
                                        let _e845 = (_e249 >> bitcast<u32>(2u));
                                        let _e849 = (_e257 >> bitcast<u32>(2u));
                                        let _e853 = (_e839 + (select(1u, _e845, (1u < _e845)) * select(1u, _e849, (1u < _e849))));
                                        let _e855 = (_e821 > (_e675 * 16f));
                                        let _e859 = (_e249 >> bitcast<u32>(3u));
                                        let _e863 = (_e257 >> bitcast<u32>(3u));
                                        let _e869 = (_e821 > (_e675 * 64f));
                                        let _e871 = select(select(select(select(0u, _e826, _e827), _e839, _e841), _e853, _e855), (_e853 + (select(1u, _e859, (1u < _e859)) * select(1u, _e863, (1u < _e863)))), _e869);
                                        let _e872 = (select(select(select(select(0u, 1u, _e827), 2u, _e841), 3u, _e855), 4u, _e869) & 31u);
                                        let _e874 = (_e249 >> bitcast<u32>(_e872));
                                        let _e876 = select(1u, _e874, (1u < _e874));
                                        let _e878 = (_e257 >> bitcast<u32>(_e872));
                                        let _e880 = select(1u, _e878, (1u < _e878));
                                        let _e883 = (round(_e817) * (1f / _e225.member.member.x));
                                        let _e886 = (round(_e818) * (1f / _e225.member.member.y));
                                        let _e887 = (_e455 + _e883);
                                        let _e888 = (_e458 + _e886);
                                        let _e889 = (_e455 - _e883);
                                        let _e890 = (_e458 - _e886);
                                        let _e892 = f32(bitcast<i32>(_e876));
                                        let _e893 = (_e887 * _e892);
                                        let _e896 = f32(bitcast<i32>((_e876 - 1u)));
                                        let _e906 = f32(bitcast<i32>(_e880));
                                        let _e907 = (_e888 * _e906);
                                        let _e910 = f32(bitcast<i32>((_e880 - 1u)));
                                        let _e924 = mips.member[((_e871 + ((bitcast<u32>((floor(select(0f, select(_e910, _e907, (_e907 < _e910)), (_e907 > 0f))) + 8388608f)) - 1258291200u) * _e876)) + (bitcast<u32>((floor(select(0f, select(_e896, _e893, (_e893 < _e896)), (_e893 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e928 = ((((_e887 * 2f) - 1f) * _e225.member.member_1.x) * _e924);
                                        let _e932 = ((((_e888 * -2f) + 1f) * _e225.member.member_1.y) * _e924);
                                        let _e933 = (_e889 * _e892);
                                        let _e942 = (_e890 * _e906);
                                        let _e956 = mips.member[((_e871 + ((bitcast<u32>((floor(select(0f, select(_e910, _e942, (_e942 < _e910)), (_e942 > 0f))) + 8388608f)) - 1258291200u) * _e876)) + (bitcast<u32>((floor(select(0f, select(_e896, _e933, (_e933 < _e896)), (_e933 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e960 = ((((_e889 * 2f) - 1f) * _e225.member.member_1.x) * _e956);
                                        let _e964 = ((((_e890 * -2f) + 1f) * _e225.member.member_1.y) * _e956);
                                        let _e965 = (_e928 - _e466);
                                        let _e966 = (_e932 - _e473);
                                        let _e967 = (_e924 - _e459);
                                        let _e968 = (_e241 > 0f);
                                        if _e968 {
                                            phi_1561_ = select(true, false, ((((_e965 * _e965) + (_e966 * _e966)) + (_e967 * _e967)) > (_e241 * _e241)));
                                        } else {
                                            phi_1561_ = true;
                                        }
                                        let _e978 = phi_1561_;
                                        if _e978 {
                                            let _e979 = (_e485 * _e238);
                                            let _e980 = (_e486 * _e238);
                                            let _e981 = (_e487 * _e238);
                                            let _e985 = vec3<f32>((_e965 - _e979), (_e966 - _e980), (_e967 - _e981));
                                            let _e990 = (((_e965 * _e485) + (_e966 * _e486)) + (_e967 * _e487));
                                            let _e994 = (_e965 - (_e485 * _e990));
                                            let _e995 = (_e966 - (_e486 * _e990));
                                            let _e996 = (_e967 - (_e487 * _e990));
                                            let _e999 = ((_e995 * _e487) - (_e486 * _e996));
                                            let _e1002 = ((_e996 * _e485) - (_e487 * _e994));
                                            let _e1005 = ((_e994 * _e486) - (_e485 * _e995));
                                            let _e1016 = ((((_e546 * _e999) + (_e547 * _e1002)) + (_e548 * _e1005)) / (((_e999 * _e999) + (_e1002 * _e1002)) + (_e1005 * _e1005)));
                                            let _e1020 = (_e546 - (_e999 * _e1016));
                                            let _e1021 = (_e547 - (_e1002 * _e1016));
                                            let _e1022 = (_e548 - (_e1005 * _e1016));
                                            let _e1028 = inverseSqrt((((_e1020 * _e1020) + (_e1021 * _e1021)) + (_e1022 * _e1022)));
                                            let _e1034 = ((((_e1020 * _e485) + (_e1021 * _e486)) + (_e1022 * _e487)) * _e1028);
                                            let _e1038 = select(0f, select(1f, _e1034, (_e1034 < 1f)), (_e1034 > 0f));
                                            let _e1039 = abs(_e1038);
                                            let _e1049 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1039, 0.00667009f), _e1039, -0.017088126f), _e1039, 0.03089188f), _e1039, -0.050174303f), _e1039, 0.08897899f), _e1039, -0.2145988f), _e1039, 1.5707963f) * sqrt((1f - _e1039)));
                                            let _e1052 = select((3.1415927f - _e1049), _e1049, (_e1038 >= 0f));
                                            let _e1060 = select(_e1052, -(_e1052), ((((_e994 * _e1020) + (_e995 * _e1021)) + (_e996 * _e1022)) < 0f));
                                            let _e1061 = (_e1028 * 0.02f);
                                            let _e1064 = select(0.19634955f, _e1061, ((_e1061 < 0.19634955f) || false));
                                            let _e1070 = ((((_e994 * _e994) + (_e995 * _e995)) + (_e996 * _e996)) <= 0f);
                                            let _e1075 = (((_e965 * _e965) + (_e966 * _e966)) + (_e967 * _e967));
                                            if (_e241 <= 0f) {
                                                phi_1716_ = true;
                                            } else {
                                                phi_1716_ = (_e1075 <= (_e241 * _e241));
                                            }
                                            let _e1080 = phi_1716_;
                                            if _e1080 {
                                                phi_1732_ = ((((_e965 * _e546) + (_e966 * _e547)) + (_e967 * _e548)) > (0.018f * sqrt(_e1075)));
                                            } else {
                                                phi_1732_ = false;
                                            }
                                            let _e1090 = phi_1732_;
                                            if _e1090 {
                                                let _e1091 = (0.5f / _e924);
                                                let _e1097 = frame.member[0u].member_1.member.member.member_1[0u];
                                                let _e1105 = frame.member[0u].member_1.member.member.member_1[1u];
                                                let _e1110 = frame.member[0u].member_1.member_5[0u];
                                                let _e1113 = frame.member[0u].member_1.member_5[1u];
                                                let _e1114 = f32(_e1110);
                                                let _e1115 = f32(_e1113);
                                                let _e1117 = frame.member[0u].member_1.member_4;
                                                let _e1118 = f32(_e1117);
                                                let _e1119 = (2u * _e1117);
                                                let _e1120 = (_e1110 + _e1119);
                                                let _e1126 = (floor(((((_e928 * _e1091) / _e1097) + 0.5f) * _e1114)) + _e1118);
                                                let _e1127 = f32((_e1120 - 1u));
                                                let _e1131 = select(0f, select(_e1127, _e1126, (_e1126 < _e1127)), (_e1126 > 0f));
                                                let _e1134 = (floor(((0.5f - ((_e932 * _e1091) / _e1105)) * _e1115)) + _e1118);
                                                let _e1135 = f32(((_e1113 + _e1119) - 1u));
                                                let _e1139 = select(0f, select(_e1135, _e1134, (_e1134 < _e1135)), (_e1134 > 0f));
                                                let _e1144 = select(select(u32(_e1131), 0u, (_e1131 < 0f)), 4294967295u, (_e1131 > 4294967000f));
                                                let _e1149 = select(select(u32(_e1139), 0u, (_e1139 < 0f)), 4294967295u, (_e1139 > 4294967000f));
                                                let _e1152 = bitcast<i32>(_e1117);
                                                let _e1158 = frame.member[0u].member_1.member_8;
                                                let _e1160 = frame.member[0u].member_1.member_12;
                                                let _e1167 = (((((_e1149 % 4u) * 4u) + (_e1144 % 4u)) + (_e1160 % 16u)) % 16u);
                                                if (_e1158 == 1u) {
                                                    local_5 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    let _e1180 = (_e1167 < 16u);
                                                    if _e1180 {
                                                    } else {
                                                        phi_8008_ = true;
                                                        break;
                                                    }
                                                    let _e1183 = local_5[_e1167][0u];
                                                    local_6 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e1180 {
                                                    } else {
                                                        phi_8008_ = true;
                                                        break;
                                                    }
                                                    let _e1186 = local_6[_e1167][1u];
                                                    phi_1892_ = vec2<f32>(_e1183, _e1186);
                                                } else {
                                                    if (_e1158 == 2u) {
                                                        local_7 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        let _e1170 = (_e1167 < 16u);
                                                        if _e1170 {
                                                        } else {
                                                            phi_8008_ = true;
                                                            break;
                                                        }
                                                        let _e1173 = local_7[_e1167][0u];
                                                        local_8 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e1170 {
                                                        } else {
                                                            phi_8008_ = true;
                                                            break;
                                                        }
                                                        let _e1176 = local_8[_e1167][1u];
                                                        phi_1891_ = vec2<f32>(_e1173, _e1176);
                                                    } else {
                                                        phi_1891_ = vec2<f32>(0.5f, 0.5f);
                                                    }
                                                    let _e1179 = phi_1891_;
                                                    phi_1892_ = _e1179;
                                                }
                                                let _e1189 = phi_1892_;
                                                let _e1194 = ((f32((bitcast<i32>(_e1144) - _e1152)) + _e1189.x) / _e1114);
                                                let _e1195 = ((f32((bitcast<i32>(_e1149) - _e1152)) + _e1189.y) / _e1115);
                                                let _e1200 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e1205 = select(select(u32(_e1200), 0u, (_e1200 < 0f)), 4294967295u, (_e1200 > 4294967000f));
                                                let _e1210 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e1220 = (select(0f, select(1f, _e1194, (_e1194 < 1f)), (_e1194 > 0f)) * _e1200);
                                                let _e1223 = f32(bitcast<i32>((_e1205 - 1u)));
                                                let _e1236 = (select(0f, select(1f, _e1195, (_e1195 < 1f)), (_e1195 > 0f)) * _e1210);
                                                let _e1239 = f32(bitcast<i32>((select(select(u32(_e1210), 0u, (_e1210 < 0f)), 4294967295u, (_e1210 > 4294967000f)) - 1u)));
                                                let _e1251 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e1239, _e1236, (_e1236 < _e1239)), (_e1236 > 0f))) + 8388608f)) - 1258291200u) * _e1205) + (bitcast<u32>((floor(select(0f, select(_e1223, _e1220, (_e1220 < _e1223)), (_e1220 > 0f))) + 8388608f)) - 1258291200u))];
                                                if (abs((_e1251 - _e924)) <= _e238) {
                                                    phi_2010_ = (_e924 * 1.001f);
                                                } else {
                                                    phi_2010_ = 0x1.fffffep+127f;
                                                }
                                                let _e1257 = phi_2010_;
                                                let _e1259 = frame.member[0u].member_1.member_6;
                                                let _e1262 = (((_e1149 * _e1120) + _e1144) * _e1259);
                                                let _e1264 = sd_map.member[_e1262];
                                                let _e1268 = frame.member[0u].member_1.member.member.member_3;
                                                let _e1272 = frame.member[0u].member_1.member.member.member_2;
                                                let _e1273 = (_e1268 - _e1272);
                                                let _e1275 = ((_e1264 * _e1273) + _e1272);
                                                if (0u < _e1259) {
                                                    if (_e1264 < 1f) {
                                                        phi_2061_ = select(true, false, (_e1275 > _e1257));
                                                    } else {
                                                        phi_2061_ = true;
                                                    }
                                                    let _e1281 = phi_2061_;
                                                    phi_2062_ = _e1281;
                                                } else {
                                                    phi_2062_ = true;
                                                }
                                                let _e1283 = phi_2062_;
                                                if _e1283 {
                                                    phi_2068_ = _e1268;
                                                } else {
                                                    phi_2068_ = _e1275;
                                                }
                                                let _e1285 = phi_2068_;
                                                let _e1286 = (_e1259 - 1u);
                                                let _e1291 = sd_map.member[(_e1262 + select(1u, _e1286, (_e1286 < 1u)))];
                                                let _e1293 = ((_e1291 * _e1273) + _e1272);
                                                if (1u < _e1259) {
                                                    if (_e1291 < 1f) {
                                                        phi_2101_ = select(true, false, (_e1293 > _e1257));
                                                    } else {
                                                        phi_2101_ = true;
                                                    }
                                                    let _e1299 = phi_2101_;
                                                    phi_2102_ = _e1299;
                                                } else {
                                                    phi_2102_ = true;
                                                }
                                                let _e1301 = phi_2102_;
                                                if _e1301 {
                                                    phi_2108_ = _e1268;
                                                } else {
                                                    phi_2108_ = _e1293;
                                                }
                                                let _e1303 = phi_2108_;
                                                let _e1308 = sd_map.member[(_e1262 + select(2u, _e1286, (_e1286 < 2u)))];
                                                let _e1310 = ((_e1308 * _e1273) + _e1272);
                                                if (2u < _e1259) {
                                                    if (_e1308 < 1f) {
                                                        phi_2141_ = select(true, false, (_e1310 > _e1257));
                                                    } else {
                                                        phi_2141_ = true;
                                                    }
                                                    let _e1316 = phi_2141_;
                                                    phi_2142_ = _e1316;
                                                } else {
                                                    phi_2142_ = true;
                                                }
                                                let _e1318 = phi_2142_;
                                                if _e1318 {
                                                    phi_2148_ = _e1268;
                                                } else {
                                                    phi_2148_ = _e1310;
                                                }
                                                let _e1320 = phi_2148_;
                                                let _e1325 = sd_map.member[(_e1262 + select(3u, _e1286, (_e1286 < 3u)))];
                                                let _e1327 = ((_e1325 * _e1273) + _e1272);
                                                if (3u < _e1259) {
                                                    if (_e1325 < 1f) {
                                                        phi_2181_ = select(true, false, (_e1327 > _e1257));
                                                    } else {
                                                        phi_2181_ = true;
                                                    }
                                                    let _e1333 = phi_2181_;
                                                    phi_2182_ = _e1333;
                                                } else {
                                                    phi_2182_ = true;
                                                }
                                                let _e1335 = phi_2182_;
                                                if _e1335 {
                                                    phi_2188_ = _e1268;
                                                } else {
                                                    phi_2188_ = _e1327;
                                                }
                                                let _e1337 = phi_2188_;
                                                if (_e1259 > 4u) {
                                                    let _e1343 = sd_map.member[(_e1262 + select(4u, _e1286, (_e1286 < 4u)))];
                                                    let _e1345 = ((_e1343 * _e1273) + _e1272);
                                                    if (4u < _e1259) {
                                                        if (_e1343 < 1f) {
                                                            phi_2225_ = select(true, false, (_e1345 > _e1257));
                                                        } else {
                                                            phi_2225_ = true;
                                                        }
                                                        let _e1351 = phi_2225_;
                                                        phi_2226_ = _e1351;
                                                    } else {
                                                        phi_2226_ = true;
                                                    }
                                                    let _e1353 = phi_2226_;
                                                    if _e1353 {
                                                        phi_2232_ = _e1268;
                                                    } else {
                                                        phi_2232_ = _e1345;
                                                    }
                                                    let _e1355 = phi_2232_;
                                                    let _e1360 = sd_map.member[(_e1262 + select(5u, _e1286, (_e1286 < 5u)))];
                                                    let _e1362 = ((_e1360 * _e1273) + _e1272);
                                                    if (5u < _e1259) {
                                                        if (_e1360 < 1f) {
                                                            phi_2265_ = select(true, false, (_e1362 > _e1257));
                                                        } else {
                                                            phi_2265_ = true;
                                                        }
                                                        let _e1368 = phi_2265_;
                                                        phi_2266_ = _e1368;
                                                    } else {
                                                        phi_2266_ = true;
                                                    }
                                                    let _e1370 = phi_2266_;
                                                    if _e1370 {
                                                        phi_2272_ = _e1268;
                                                    } else {
                                                        phi_2272_ = _e1362;
                                                    }
                                                    let _e1372 = phi_2272_;
                                                    let _e1377 = sd_map.member[(_e1262 + select(6u, _e1286, (_e1286 < 6u)))];
                                                    let _e1379 = ((_e1377 * _e1273) + _e1272);
                                                    if (6u < _e1259) {
                                                        if (_e1377 < 1f) {
                                                            phi_2305_ = select(true, false, (_e1379 > _e1257));
                                                        } else {
                                                            phi_2305_ = true;
                                                        }
                                                        let _e1385 = phi_2305_;
                                                        phi_2306_ = _e1385;
                                                    } else {
                                                        phi_2306_ = true;
                                                    }
                                                    let _e1387 = phi_2306_;
                                                    if _e1387 {
                                                        phi_2312_ = _e1268;
                                                    } else {
                                                        phi_2312_ = _e1379;
                                                    }
                                                    let _e1389 = phi_2312_;
                                                    let _e1394 = sd_map.member[(_e1262 + select(7u, _e1286, (_e1286 < 7u)))];
                                                    let _e1396 = ((_e1394 * _e1273) + _e1272);
                                                    if (7u < _e1259) {
                                                        if (_e1394 < 1f) {
                                                            phi_2345_ = select(true, false, (_e1396 > _e1257));
                                                        } else {
                                                            phi_2345_ = true;
                                                        }
                                                        let _e1402 = phi_2345_;
                                                        phi_2346_ = _e1402;
                                                    } else {
                                                        phi_2346_ = true;
                                                    }
                                                    let _e1404 = phi_2346_;
                                                    if _e1404 {
                                                        phi_2352_ = _e1268;
                                                    } else {
                                                        phi_2352_ = _e1396;
                                                    }
                                                    let _e1406 = phi_2352_;
                                                    phi_2361_ = _e1406;
                                                    phi_2362_ = _e1389;
                                                    phi_2363_ = _e1372;
                                                    phi_2364_ = _e1355;
                                                } else {
                                                    phi_2361_ = _e1268;
                                                    phi_2362_ = _e1268;
                                                    phi_2363_ = _e1268;
                                                    phi_2364_ = _e1268;
                                                }
                                                let _e1408 = phi_2361_;
                                                let _e1410 = phi_2362_;
                                                let _e1412 = phi_2363_;
                                                let _e1414 = phi_2364_;
                                                let _e1415 = (_e1285 != _e1285);
                                                if _e1415 {
                                                    phi_6854_ = true;
                                                } else {
                                                    phi_6854_ = (_e1303 <= _e1285);
                                                }
                                                let _e1418 = phi_6854_;
                                                let _e1419 = select(_e1285, _e1303, _e1418);
                                                if _e1415 {
                                                    phi_6869_ = true;
                                                } else {
                                                    phi_6869_ = (_e1303 >= _e1285);
                                                }
                                                let _e1422 = phi_6869_;
                                                let _e1423 = select(_e1285, _e1303, _e1422);
                                                let _e1424 = (_e1320 != _e1320);
                                                if _e1424 {
                                                    phi_6884_ = true;
                                                } else {
                                                    phi_6884_ = (_e1337 <= _e1320);
                                                }
                                                let _e1427 = phi_6884_;
                                                let _e1428 = select(_e1320, _e1337, _e1427);
                                                if _e1424 {
                                                    phi_6899_ = true;
                                                } else {
                                                    phi_6899_ = (_e1337 >= _e1320);
                                                }
                                                let _e1431 = phi_6899_;
                                                let _e1432 = select(_e1320, _e1337, _e1431);
                                                let _e1433 = (_e1414 != _e1414);
                                                if _e1433 {
                                                    phi_6914_ = true;
                                                } else {
                                                    phi_6914_ = (_e1412 <= _e1414);
                                                }
                                                let _e1436 = phi_6914_;
                                                let _e1437 = select(_e1414, _e1412, _e1436);
                                                if _e1433 {
                                                    phi_6929_ = true;
                                                } else {
                                                    phi_6929_ = (_e1412 >= _e1414);
                                                }
                                                let _e1440 = phi_6929_;
                                                let _e1441 = select(_e1414, _e1412, _e1440);
                                                let _e1442 = (_e1410 != _e1410);
                                                if _e1442 {
                                                    phi_6944_ = true;
                                                } else {
                                                    phi_6944_ = (_e1408 <= _e1410);
                                                }
                                                let _e1445 = phi_6944_;
                                                let _e1446 = select(_e1410, _e1408, _e1445);
                                                if _e1442 {
                                                    phi_6959_ = true;
                                                } else {
                                                    phi_6959_ = (_e1408 >= _e1410);
                                                }
                                                let _e1449 = phi_6959_;
                                                let _e1450 = select(_e1410, _e1408, _e1449);
                                                let _e1451 = (_e1419 != _e1419);
                                                if _e1451 {
                                                    phi_6974_ = true;
                                                } else {
                                                    phi_6974_ = (_e1428 <= _e1419);
                                                }
                                                let _e1454 = phi_6974_;
                                                let _e1455 = select(_e1419, _e1428, _e1454);
                                                if _e1451 {
                                                    phi_6989_ = true;
                                                } else {
                                                    phi_6989_ = (_e1428 >= _e1419);
                                                }
                                                let _e1458 = phi_6989_;
                                                let _e1459 = select(_e1419, _e1428, _e1458);
                                                let _e1460 = (_e1423 != _e1423);
                                                if _e1460 {
                                                    phi_7004_ = true;
                                                } else {
                                                    phi_7004_ = (_e1432 <= _e1423);
                                                }
                                                let _e1463 = phi_7004_;
                                                let _e1464 = select(_e1423, _e1432, _e1463);
                                                if _e1460 {
                                                    phi_7019_ = true;
                                                } else {
                                                    phi_7019_ = (_e1432 >= _e1423);
                                                }
                                                let _e1467 = phi_7019_;
                                                let _e1468 = select(_e1423, _e1432, _e1467);
                                                let _e1469 = (_e1437 != _e1437);
                                                if _e1469 {
                                                    phi_7034_ = true;
                                                } else {
                                                    phi_7034_ = (_e1446 <= _e1437);
                                                }
                                                let _e1472 = phi_7034_;
                                                let _e1473 = select(_e1437, _e1446, _e1472);
                                                if _e1469 {
                                                    phi_7049_ = true;
                                                } else {
                                                    phi_7049_ = (_e1446 >= _e1437);
                                                }
                                                let _e1476 = phi_7049_;
                                                let _e1477 = select(_e1437, _e1446, _e1476);
                                                let _e1478 = (_e1441 != _e1441);
                                                if _e1478 {
                                                    phi_7064_ = true;
                                                } else {
                                                    phi_7064_ = (_e1450 <= _e1441);
                                                }
                                                let _e1481 = phi_7064_;
                                                let _e1482 = select(_e1441, _e1450, _e1481);
                                                if _e1478 {
                                                    phi_7079_ = true;
                                                } else {
                                                    phi_7079_ = (_e1450 >= _e1441);
                                                }
                                                let _e1485 = phi_7079_;
                                                let _e1486 = select(_e1441, _e1450, _e1485);
                                                let _e1487 = (_e1464 != _e1464);
                                                if _e1487 {
                                                    phi_7094_ = true;
                                                } else {
                                                    phi_7094_ = (_e1459 <= _e1464);
                                                }
                                                let _e1490 = phi_7094_;
                                                let _e1491 = select(_e1464, _e1459, _e1490);
                                                if _e1487 {
                                                    phi_7109_ = true;
                                                } else {
                                                    phi_7109_ = (_e1459 >= _e1464);
                                                }
                                                let _e1494 = phi_7109_;
                                                let _e1495 = select(_e1464, _e1459, _e1494);
                                                let _e1496 = (_e1482 != _e1482);
                                                if _e1496 {
                                                    phi_7124_ = true;
                                                } else {
                                                    phi_7124_ = (_e1477 <= _e1482);
                                                }
                                                let _e1499 = phi_7124_;
                                                let _e1500 = select(_e1482, _e1477, _e1499);
                                                if _e1496 {
                                                    phi_7139_ = true;
                                                } else {
                                                    phi_7139_ = (_e1477 >= _e1482);
                                                }
                                                let _e1503 = phi_7139_;
                                                let _e1504 = select(_e1482, _e1477, _e1503);
                                                let _e1505 = (_e1455 != _e1455);
                                                if _e1505 {
                                                    phi_7154_ = true;
                                                } else {
                                                    phi_7154_ = (_e1473 <= _e1455);
                                                }
                                                let _e1508 = phi_7154_;
                                                let _e1509 = select(_e1455, _e1473, _e1508);
                                                if _e1505 {
                                                    phi_7169_ = true;
                                                } else {
                                                    phi_7169_ = (_e1473 >= _e1455);
                                                }
                                                let _e1512 = phi_7169_;
                                                let _e1513 = select(_e1455, _e1473, _e1512);
                                                let _e1514 = (_e1491 != _e1491);
                                                if _e1514 {
                                                    phi_7184_ = true;
                                                } else {
                                                    phi_7184_ = (_e1500 <= _e1491);
                                                }
                                                let _e1517 = phi_7184_;
                                                let _e1518 = select(_e1491, _e1500, _e1517);
                                                if _e1514 {
                                                    phi_7199_ = true;
                                                } else {
                                                    phi_7199_ = (_e1500 >= _e1491);
                                                }
                                                let _e1521 = phi_7199_;
                                                let _e1522 = select(_e1491, _e1500, _e1521);
                                                let _e1523 = (_e1495 != _e1495);
                                                if _e1523 {
                                                    phi_7214_ = true;
                                                } else {
                                                    phi_7214_ = (_e1504 <= _e1495);
                                                }
                                                let _e1526 = phi_7214_;
                                                let _e1527 = select(_e1495, _e1504, _e1526);
                                                if _e1523 {
                                                    phi_7229_ = true;
                                                } else {
                                                    phi_7229_ = (_e1504 >= _e1495);
                                                }
                                                let _e1530 = phi_7229_;
                                                let _e1531 = select(_e1495, _e1504, _e1530);
                                                let _e1532 = (_e1468 != _e1468);
                                                if _e1532 {
                                                    phi_7244_ = true;
                                                } else {
                                                    phi_7244_ = (_e1486 <= _e1468);
                                                }
                                                let _e1535 = phi_7244_;
                                                let _e1536 = select(_e1468, _e1486, _e1535);
                                                if _e1532 {
                                                    phi_7259_ = true;
                                                } else {
                                                    phi_7259_ = (_e1486 >= _e1468);
                                                }
                                                let _e1539 = phi_7259_;
                                                let _e1540 = select(_e1468, _e1486, _e1539);
                                                let _e1541 = (_e1527 != _e1527);
                                                if _e1541 {
                                                    phi_7274_ = true;
                                                } else {
                                                    phi_7274_ = (_e1513 <= _e1527);
                                                }
                                                let _e1544 = phi_7274_;
                                                let _e1545 = select(_e1527, _e1513, _e1544);
                                                if _e1541 {
                                                    phi_7289_ = true;
                                                } else {
                                                    phi_7289_ = (_e1513 >= _e1527);
                                                }
                                                let _e1548 = phi_7289_;
                                                let _e1549 = select(_e1527, _e1513, _e1548);
                                                let _e1550 = (_e1536 != _e1536);
                                                if _e1550 {
                                                    phi_7304_ = true;
                                                } else {
                                                    phi_7304_ = (_e1522 <= _e1536);
                                                }
                                                let _e1553 = phi_7304_;
                                                let _e1554 = select(_e1536, _e1522, _e1553);
                                                if _e1550 {
                                                    phi_7319_ = true;
                                                } else {
                                                    phi_7319_ = (_e1522 >= _e1536);
                                                }
                                                let _e1557 = phi_7319_;
                                                let _e1558 = select(_e1536, _e1522, _e1557);
                                                let _e1559 = (_e1518 != _e1518);
                                                if _e1559 {
                                                    phi_7334_ = true;
                                                } else {
                                                    phi_7334_ = (_e1545 <= _e1518);
                                                }
                                                let _e1562 = phi_7334_;
                                                let _e1563 = select(_e1518, _e1545, _e1562);
                                                if _e1559 {
                                                    phi_7349_ = true;
                                                } else {
                                                    phi_7349_ = (_e1545 >= _e1518);
                                                }
                                                let _e1566 = phi_7349_;
                                                let _e1567 = select(_e1518, _e1545, _e1566);
                                                let _e1568 = (_e1554 != _e1554);
                                                if _e1568 {
                                                    phi_7364_ = true;
                                                } else {
                                                    phi_7364_ = (_e1549 <= _e1554);
                                                }
                                                let _e1571 = phi_7364_;
                                                let _e1572 = select(_e1554, _e1549, _e1571);
                                                if _e1568 {
                                                    phi_7379_ = true;
                                                } else {
                                                    phi_7379_ = (_e1549 >= _e1554);
                                                }
                                                let _e1575 = phi_7379_;
                                                let _e1576 = select(_e1554, _e1549, _e1575);
                                                let _e1577 = (_e1558 != _e1558);
                                                if _e1577 {
                                                    phi_7394_ = true;
                                                } else {
                                                    phi_7394_ = (_e1531 <= _e1558);
                                                }
                                                let _e1580 = phi_7394_;
                                                let _e1581 = select(_e1558, _e1531, _e1580);
                                                if _e1577 {
                                                    phi_7409_ = true;
                                                } else {
                                                    phi_7409_ = (_e1531 >= _e1558);
                                                }
                                                let _e1584 = phi_7409_;
                                                let _e1585 = select(_e1558, _e1531, _e1584);
                                                if (_e1509 < _e1268) {
                                                    if (_e1509 > (_e924 + _e238)) {
                                                        phi_2433_ = (vec3<f32>(((((_e1194 * 2f) - 1f) * _e1097) * _e1509), ((((_e1195 * -2f) + 1f) * _e1105) * _e1509), _e1509) - _e474);
                                                    } else {
                                                        phi_2433_ = _e985;
                                                    }
                                                    let _e1600 = phi_2433_;
                                                    phi_2434_ = _e1600;
                                                } else {
                                                    phi_2434_ = _e985;
                                                }
                                                let _e1602 = phi_2434_;
                                                if (_e1563 >= _e225.member.member_3) {
                                                    phi_2760_ = u32();
                                                    phi_2761_ = true;
                                                } else {
                                                    let _e1606 = (((_e1194 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e1610 = (((_e1195 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e1612 = ((_e1606 * _e1563) - _e466);
                                                    let _e1613 = ((_e1610 * _e1563) - _e473);
                                                    let _e1614 = (_e1563 - _e459);
                                                    if (_e1567 < _e225.member.member_3) {
                                                        phi_2488_ = (vec3<f32>((_e1606 * _e1567), (_e1610 * _e1567), _e1567) - _e474);
                                                    } else {
                                                        phi_2488_ = vec3<f32>((_e1612 - _e979), (_e1613 - _e980), (_e1614 - _e981));
                                                    }
                                                    let _e1625 = phi_2488_;
                                                    if _e968 {
                                                        phi_2504_ = select(true, false, ((((_e1612 * _e1612) + (_e1613 * _e1613)) + (_e1614 * _e1614)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_2504_ = true;
                                                    }
                                                    let _e1635 = phi_2504_;
                                                    if _e1635 {
                                                        let _e1647 = ((((_e1612 * _e485) + (_e1613 * _e486)) + (_e1614 * _e487)) * inverseSqrt((((_e1612 * _e1612) + (_e1613 * _e1613)) + (_e1614 * _e1614))));
                                                        let _e1651 = select(-1f, select(1f, _e1647, (_e1647 < 1f)), (_e1647 > -1f));
                                                        let _e1652 = abs(_e1651);
                                                        let _e1662 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1652, 0.00667009f), _e1652, -0.017088126f), _e1652, 0.03089188f), _e1652, -0.050174303f), _e1652, 0.08897899f), _e1652, -0.2145988f), _e1652, 1.5707963f) * sqrt((1f - _e1652)));
                                                        let _e1669 = ((((select((3.1415927f - _e1662), _e1662, (_e1651 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e1673 = select(0f, select(1f, _e1669, (_e1669 < 1f)), (_e1669 > 0f));
                                                        let _e1688 = ((((_e1625.x * _e485) + (_e1625.y * _e486)) + (_e1625.z * _e487)) * inverseSqrt((((_e1625.x * _e1625.x) + (_e1625.y * _e1625.y)) + (_e1625.z * _e1625.z))));
                                                        let _e1692 = select(-1f, select(1f, _e1688, (_e1688 < 1f)), (_e1688 > -1f));
                                                        let _e1693 = abs(_e1692);
                                                        let _e1703 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1693, 0.00667009f), _e1693, -0.017088126f), _e1693, 0.03089188f), _e1693, -0.050174303f), _e1693, 0.08897899f), _e1693, -0.2145988f), _e1693, 1.5707963f) * sqrt((1f - _e1693)));
                                                        let _e1710 = ((((select((3.1415927f - _e1703), _e1703, (_e1692 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e1714 = select(0f, select(1f, _e1710, (_e1710 < 1f)), (_e1710 > 0f));
                                                        let _e1716 = (_e1714 != _e1714);
                                                        let _e1718 = select(_e1714, _e1673, ((_e1673 < _e1714) || _e1716));
                                                        let _e1721 = select(_e1714, _e1673, ((_e1673 > _e1714) || _e1716));
                                                        let _e1723 = floor((_e1718 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e1731 = -(floor((_e1721 * -32f)));
                                                            let _e1736 = (select(32f, _e1731, ((_e1731 < 32f) || false)) - _e1723);
                                                            phi_2694_ = select(select(0f, _e1736, ((_e1736 > 0f) || false)), 0f, (_e1721 <= _e1718));
                                                        } else {
                                                            phi_2694_ = -(floor(((_e1721 - _e1718) * -32f)));
                                                        }
                                                        let _e1742 = phi_2694_;
                                                        let _e1750 = (bitcast<u32>((floor(select(0f, select(32f, _e1723, (_e1723 < 32f)), (_e1723 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e1758 = (bitcast<u32>((floor(select(0f, select(32f, _e1742, (_e1742 < 32f)), (_e1742 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e1750 >= 32u) {
                                                            phi_2748_ = u32();
                                                            phi_2749_ = true;
                                                        } else {
                                                            let _e1760 = (_e1758 == 0u);
                                                            if _e1760 {
                                                                phi_2747_ = u32();
                                                            } else {
                                                                if (_e1758 >= 32u) {
                                                                    phi_2744_ = 4294967295u;
                                                                } else {
                                                                    phi_2744_ = ((1u << bitcast<u32>((_e1758 & 31u))) - 1u);
                                                                }
                                                                let _e1767 = phi_2744_;
                                                                phi_2747_ = (_e1767 << bitcast<u32>((_e1750 & 31u)));
                                                            }
                                                            let _e1772 = phi_2747_;
                                                            phi_2748_ = _e1772;
                                                            phi_2749_ = _e1760;
                                                        }
                                                        let _e1774 = phi_2748_;
                                                        let _e1776 = phi_2749_;
                                                        phi_2758_ = select(select(_e1774, 0u, _e1776), 0u, _e1070);
                                                    } else {
                                                        phi_2758_ = u32();
                                                    }
                                                    let _e1780 = phi_2758_;
                                                    phi_2760_ = _e1780;
                                                    phi_2761_ = select(true, false, _e1635);
                                                }
                                                let _e1783 = phi_2760_;
                                                let _e1785 = phi_2761_;
                                                if (_e1572 >= _e225.member.member_3) {
                                                    phi_3091_ = u32();
                                                    phi_3092_ = true;
                                                } else {
                                                    let _e1790 = (((_e1194 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e1794 = (((_e1195 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e1796 = ((_e1790 * _e1572) - _e466);
                                                    let _e1797 = ((_e1794 * _e1572) - _e473);
                                                    let _e1798 = (_e1572 - _e459);
                                                    if (_e1576 < _e225.member.member_3) {
                                                        phi_2819_ = (vec3<f32>((_e1790 * _e1576), (_e1794 * _e1576), _e1576) - _e474);
                                                    } else {
                                                        phi_2819_ = vec3<f32>((_e1796 - _e979), (_e1797 - _e980), (_e1798 - _e981));
                                                    }
                                                    let _e1809 = phi_2819_;
                                                    if _e968 {
                                                        phi_2835_ = select(true, false, ((((_e1796 * _e1796) + (_e1797 * _e1797)) + (_e1798 * _e1798)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_2835_ = true;
                                                    }
                                                    let _e1819 = phi_2835_;
                                                    if _e1819 {
                                                        let _e1831 = ((((_e1796 * _e485) + (_e1797 * _e486)) + (_e1798 * _e487)) * inverseSqrt((((_e1796 * _e1796) + (_e1797 * _e1797)) + (_e1798 * _e1798))));
                                                        let _e1835 = select(-1f, select(1f, _e1831, (_e1831 < 1f)), (_e1831 > -1f));
                                                        let _e1836 = abs(_e1835);
                                                        let _e1846 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1836, 0.00667009f), _e1836, -0.017088126f), _e1836, 0.03089188f), _e1836, -0.050174303f), _e1836, 0.08897899f), _e1836, -0.2145988f), _e1836, 1.5707963f) * sqrt((1f - _e1836)));
                                                        let _e1853 = ((((select((3.1415927f - _e1846), _e1846, (_e1835 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e1857 = select(0f, select(1f, _e1853, (_e1853 < 1f)), (_e1853 > 0f));
                                                        let _e1872 = ((((_e1809.x * _e485) + (_e1809.y * _e486)) + (_e1809.z * _e487)) * inverseSqrt((((_e1809.x * _e1809.x) + (_e1809.y * _e1809.y)) + (_e1809.z * _e1809.z))));
                                                        let _e1876 = select(-1f, select(1f, _e1872, (_e1872 < 1f)), (_e1872 > -1f));
                                                        let _e1877 = abs(_e1876);
                                                        let _e1887 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1877, 0.00667009f), _e1877, -0.017088126f), _e1877, 0.03089188f), _e1877, -0.050174303f), _e1877, 0.08897899f), _e1877, -0.2145988f), _e1877, 1.5707963f) * sqrt((1f - _e1877)));
                                                        let _e1894 = ((((select((3.1415927f - _e1887), _e1887, (_e1876 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e1898 = select(0f, select(1f, _e1894, (_e1894 < 1f)), (_e1894 > 0f));
                                                        let _e1900 = (_e1898 != _e1898);
                                                        let _e1902 = select(_e1898, _e1857, ((_e1857 < _e1898) || _e1900));
                                                        let _e1905 = select(_e1898, _e1857, ((_e1857 > _e1898) || _e1900));
                                                        let _e1907 = floor((_e1902 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e1915 = -(floor((_e1905 * -32f)));
                                                            let _e1920 = (select(32f, _e1915, ((_e1915 < 32f) || false)) - _e1907);
                                                            phi_3025_ = select(select(0f, _e1920, ((_e1920 > 0f) || false)), 0f, (_e1905 <= _e1902));
                                                        } else {
                                                            phi_3025_ = -(floor(((_e1905 - _e1902) * -32f)));
                                                        }
                                                        let _e1926 = phi_3025_;
                                                        let _e1934 = (bitcast<u32>((floor(select(0f, select(32f, _e1907, (_e1907 < 32f)), (_e1907 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e1942 = (bitcast<u32>((floor(select(0f, select(32f, _e1926, (_e1926 < 32f)), (_e1926 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e1934 >= 32u) {
                                                            phi_3079_ = u32();
                                                            phi_3080_ = true;
                                                        } else {
                                                            let _e1944 = (_e1942 == 0u);
                                                            if _e1944 {
                                                                phi_3078_ = u32();
                                                            } else {
                                                                if (_e1942 >= 32u) {
                                                                    phi_3075_ = 4294967295u;
                                                                } else {
                                                                    phi_3075_ = ((1u << bitcast<u32>((_e1942 & 31u))) - 1u);
                                                                }
                                                                let _e1951 = phi_3075_;
                                                                phi_3078_ = (_e1951 << bitcast<u32>((_e1934 & 31u)));
                                                            }
                                                            let _e1956 = phi_3078_;
                                                            phi_3079_ = _e1956;
                                                            phi_3080_ = _e1944;
                                                        }
                                                        let _e1958 = phi_3079_;
                                                        let _e1960 = phi_3080_;
                                                        phi_3089_ = select(select(_e1958, 0u, _e1960), 0u, _e1070);
                                                    } else {
                                                        phi_3089_ = u32();
                                                    }
                                                    let _e1964 = phi_3089_;
                                                    phi_3091_ = _e1964;
                                                    phi_3092_ = select(true, false, _e1819);
                                                }
                                                let _e1967 = phi_3091_;
                                                let _e1969 = phi_3092_;
                                                if (_e1581 >= _e225.member.member_3) {
                                                    phi_3423_ = u32();
                                                    phi_3424_ = true;
                                                } else {
                                                    let _e1975 = (((_e1194 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e1979 = (((_e1195 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e1981 = ((_e1975 * _e1581) - _e466);
                                                    let _e1982 = ((_e1979 * _e1581) - _e473);
                                                    let _e1983 = (_e1581 - _e459);
                                                    if (_e1585 < _e225.member.member_3) {
                                                        phi_3151_ = (vec3<f32>((_e1975 * _e1585), (_e1979 * _e1585), _e1585) - _e474);
                                                    } else {
                                                        phi_3151_ = vec3<f32>((_e1981 - _e979), (_e1982 - _e980), (_e1983 - _e981));
                                                    }
                                                    let _e1994 = phi_3151_;
                                                    if _e968 {
                                                        phi_3167_ = select(true, false, ((((_e1981 * _e1981) + (_e1982 * _e1982)) + (_e1983 * _e1983)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_3167_ = true;
                                                    }
                                                    let _e2004 = phi_3167_;
                                                    if _e2004 {
                                                        let _e2016 = ((((_e1981 * _e485) + (_e1982 * _e486)) + (_e1983 * _e487)) * inverseSqrt((((_e1981 * _e1981) + (_e1982 * _e1982)) + (_e1983 * _e1983))));
                                                        let _e2020 = select(-1f, select(1f, _e2016, (_e2016 < 1f)), (_e2016 > -1f));
                                                        let _e2021 = abs(_e2020);
                                                        let _e2031 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2021, 0.00667009f), _e2021, -0.017088126f), _e2021, 0.03089188f), _e2021, -0.050174303f), _e2021, 0.08897899f), _e2021, -0.2145988f), _e2021, 1.5707963f) * sqrt((1f - _e2021)));
                                                        let _e2038 = ((((select((3.1415927f - _e2031), _e2031, (_e2020 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e2042 = select(0f, select(1f, _e2038, (_e2038 < 1f)), (_e2038 > 0f));
                                                        let _e2057 = ((((_e1994.x * _e485) + (_e1994.y * _e486)) + (_e1994.z * _e487)) * inverseSqrt((((_e1994.x * _e1994.x) + (_e1994.y * _e1994.y)) + (_e1994.z * _e1994.z))));
                                                        let _e2061 = select(-1f, select(1f, _e2057, (_e2057 < 1f)), (_e2057 > -1f));
                                                        let _e2062 = abs(_e2061);
                                                        let _e2072 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2062, 0.00667009f), _e2062, -0.017088126f), _e2062, 0.03089188f), _e2062, -0.050174303f), _e2062, 0.08897899f), _e2062, -0.2145988f), _e2062, 1.5707963f) * sqrt((1f - _e2062)));
                                                        let _e2079 = ((((select((3.1415927f - _e2072), _e2072, (_e2061 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e2083 = select(0f, select(1f, _e2079, (_e2079 < 1f)), (_e2079 > 0f));
                                                        let _e2085 = (_e2083 != _e2083);
                                                        let _e2087 = select(_e2083, _e2042, ((_e2042 < _e2083) || _e2085));
                                                        let _e2090 = select(_e2083, _e2042, ((_e2042 > _e2083) || _e2085));
                                                        let _e2092 = floor((_e2087 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e2100 = -(floor((_e2090 * -32f)));
                                                            let _e2105 = (select(32f, _e2100, ((_e2100 < 32f) || false)) - _e2092);
                                                            phi_3357_ = select(select(0f, _e2105, ((_e2105 > 0f) || false)), 0f, (_e2090 <= _e2087));
                                                        } else {
                                                            phi_3357_ = -(floor(((_e2090 - _e2087) * -32f)));
                                                        }
                                                        let _e2111 = phi_3357_;
                                                        let _e2119 = (bitcast<u32>((floor(select(0f, select(32f, _e2092, (_e2092 < 32f)), (_e2092 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e2127 = (bitcast<u32>((floor(select(0f, select(32f, _e2111, (_e2111 < 32f)), (_e2111 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e2119 >= 32u) {
                                                            phi_3411_ = u32();
                                                            phi_3412_ = true;
                                                        } else {
                                                            let _e2129 = (_e2127 == 0u);
                                                            if _e2129 {
                                                                phi_3410_ = u32();
                                                            } else {
                                                                if (_e2127 >= 32u) {
                                                                    phi_3407_ = 4294967295u;
                                                                } else {
                                                                    phi_3407_ = ((1u << bitcast<u32>((_e2127 & 31u))) - 1u);
                                                                }
                                                                let _e2136 = phi_3407_;
                                                                phi_3410_ = (_e2136 << bitcast<u32>((_e2119 & 31u)));
                                                            }
                                                            let _e2141 = phi_3410_;
                                                            phi_3411_ = _e2141;
                                                            phi_3412_ = _e2129;
                                                        }
                                                        let _e2143 = phi_3411_;
                                                        let _e2145 = phi_3412_;
                                                        phi_3421_ = select(select(_e2143, 0u, _e2145), 0u, _e1070);
                                                    } else {
                                                        phi_3421_ = u32();
                                                    }
                                                    let _e2149 = phi_3421_;
                                                    phi_3423_ = _e2149;
                                                    phi_3424_ = select(true, false, _e2004);
                                                }
                                                let _e2152 = phi_3423_;
                                                let _e2154 = phi_3424_;
                                                if (_e1540 >= _e225.member.member_3) {
                                                    phi_3757_ = u32();
                                                    phi_3758_ = true;
                                                } else {
                                                    let _e2160 = (((_e1194 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e2164 = (((_e1195 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e2166 = ((_e2160 * _e1540) - _e466);
                                                    let _e2167 = ((_e2164 * _e1540) - _e473);
                                                    let _e2168 = (_e1540 - _e459);
                                                    if (_e1268 < _e225.member.member_3) {
                                                        phi_3485_ = (vec3<f32>((_e2160 * _e1268), (_e2164 * _e1268), _e1268) - _e474);
                                                    } else {
                                                        phi_3485_ = vec3<f32>((_e2166 - _e979), (_e2167 - _e980), (_e2168 - _e981));
                                                    }
                                                    let _e2179 = phi_3485_;
                                                    if _e968 {
                                                        phi_3501_ = select(true, false, ((((_e2166 * _e2166) + (_e2167 * _e2167)) + (_e2168 * _e2168)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_3501_ = true;
                                                    }
                                                    let _e2189 = phi_3501_;
                                                    if _e2189 {
                                                        let _e2201 = ((((_e2166 * _e485) + (_e2167 * _e486)) + (_e2168 * _e487)) * inverseSqrt((((_e2166 * _e2166) + (_e2167 * _e2167)) + (_e2168 * _e2168))));
                                                        let _e2205 = select(-1f, select(1f, _e2201, (_e2201 < 1f)), (_e2201 > -1f));
                                                        let _e2206 = abs(_e2205);
                                                        let _e2216 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2206, 0.00667009f), _e2206, -0.017088126f), _e2206, 0.03089188f), _e2206, -0.050174303f), _e2206, 0.08897899f), _e2206, -0.2145988f), _e2206, 1.5707963f) * sqrt((1f - _e2206)));
                                                        let _e2223 = ((((select((3.1415927f - _e2216), _e2216, (_e2205 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e2227 = select(0f, select(1f, _e2223, (_e2223 < 1f)), (_e2223 > 0f));
                                                        let _e2242 = ((((_e2179.x * _e485) + (_e2179.y * _e486)) + (_e2179.z * _e487)) * inverseSqrt((((_e2179.x * _e2179.x) + (_e2179.y * _e2179.y)) + (_e2179.z * _e2179.z))));
                                                        let _e2246 = select(-1f, select(1f, _e2242, (_e2242 < 1f)), (_e2242 > -1f));
                                                        let _e2247 = abs(_e2246);
                                                        let _e2257 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2247, 0.00667009f), _e2247, -0.017088126f), _e2247, 0.03089188f), _e2247, -0.050174303f), _e2247, 0.08897899f), _e2247, -0.2145988f), _e2247, 1.5707963f) * sqrt((1f - _e2247)));
                                                        let _e2264 = ((((select((3.1415927f - _e2257), _e2257, (_e2246 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                                        let _e2268 = select(0f, select(1f, _e2264, (_e2264 < 1f)), (_e2264 > 0f));
                                                        let _e2270 = (_e2268 != _e2268);
                                                        let _e2272 = select(_e2268, _e2227, ((_e2227 < _e2268) || _e2270));
                                                        let _e2275 = select(_e2268, _e2227, ((_e2227 > _e2268) || _e2270));
                                                        let _e2277 = floor((_e2272 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e2285 = -(floor((_e2275 * -32f)));
                                                            let _e2290 = (select(32f, _e2285, ((_e2285 < 32f) || false)) - _e2277);
                                                            phi_3691_ = select(select(0f, _e2290, ((_e2290 > 0f) || false)), 0f, (_e2275 <= _e2272));
                                                        } else {
                                                            phi_3691_ = -(floor(((_e2275 - _e2272) * -32f)));
                                                        }
                                                        let _e2296 = phi_3691_;
                                                        let _e2304 = (bitcast<u32>((floor(select(0f, select(32f, _e2277, (_e2277 < 32f)), (_e2277 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e2312 = (bitcast<u32>((floor(select(0f, select(32f, _e2296, (_e2296 < 32f)), (_e2296 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e2304 >= 32u) {
                                                            phi_3745_ = u32();
                                                            phi_3746_ = true;
                                                        } else {
                                                            let _e2314 = (_e2312 == 0u);
                                                            if _e2314 {
                                                                phi_3744_ = u32();
                                                            } else {
                                                                if (_e2312 >= 32u) {
                                                                    phi_3741_ = 4294967295u;
                                                                } else {
                                                                    phi_3741_ = ((1u << bitcast<u32>((_e2312 & 31u))) - 1u);
                                                                }
                                                                let _e2321 = phi_3741_;
                                                                phi_3744_ = (_e2321 << bitcast<u32>((_e2304 & 31u)));
                                                            }
                                                            let _e2326 = phi_3744_;
                                                            phi_3745_ = _e2326;
                                                            phi_3746_ = _e2314;
                                                        }
                                                        let _e2328 = phi_3745_;
                                                        let _e2330 = phi_3746_;
                                                        phi_3755_ = select(select(_e2328, 0u, _e2330), 0u, _e1070);
                                                    } else {
                                                        phi_3755_ = u32();
                                                    }
                                                    let _e2334 = phi_3755_;
                                                    phi_3757_ = _e2334;
                                                    phi_3758_ = select(true, false, _e2189);
                                                }
                                                let _e2337 = phi_3757_;
                                                let _e2339 = phi_3758_;
                                                phi_3764_ = _e1602;
                                                phi_3765_ = (((select(_e1783, 0u, _e1785) | select(_e1967, 0u, _e1969)) | select(_e2152, 0u, _e2154)) | select(_e2337, 0u, _e2339));
                                            } else {
                                                phi_3764_ = _e985;
                                                phi_3765_ = 0u;
                                            }
                                            let _e2343 = phi_3764_;
                                            let _e2345 = phi_3765_;
                                            let _e2347 = (_e990 * inverseSqrt(_e1075));
                                            let _e2351 = select(-1f, select(1f, _e2347, (_e2347 < 1f)), (_e2347 > -1f));
                                            let _e2352 = abs(_e2351);
                                            let _e2362 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2352, 0.00667009f), _e2352, -0.017088126f), _e2352, 0.03089188f), _e2352, -0.050174303f), _e2352, 0.08897899f), _e2352, -0.2145988f), _e2352, 1.5707963f) * sqrt((1f - _e2352)));
                                            let _e2369 = ((((select((3.1415927f - _e2362), _e2362, (_e2351 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                            let _e2373 = select(0f, select(1f, _e2369, (_e2369 < 1f)), (_e2369 > 0f));
                                            let _e2388 = ((((_e2343.x * _e485) + (_e2343.y * _e486)) + (_e2343.z * _e487)) * inverseSqrt((((_e2343.x * _e2343.x) + (_e2343.y * _e2343.y)) + (_e2343.z * _e2343.z))));
                                            let _e2392 = select(-1f, select(1f, _e2388, (_e2388 < 1f)), (_e2388 > -1f));
                                            let _e2393 = abs(_e2392);
                                            let _e2403 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2393, 0.00667009f), _e2393, -0.017088126f), _e2393, 0.03089188f), _e2393, -0.050174303f), _e2393, 0.08897899f), _e2393, -0.2145988f), _e2393, 1.5707963f) * sqrt((1f - _e2393)));
                                            let _e2410 = ((((select((3.1415927f - _e2403), _e2403, (_e2392 >= 0f)) + _e1064) - _e1060) + 1.5707964f) * 0.31830987f);
                                            let _e2414 = select(0f, select(1f, _e2410, (_e2410 < 1f)), (_e2410 > 0f));
                                            let _e2416 = (_e2414 != _e2414);
                                            let _e2418 = select(_e2414, _e2373, ((_e2373 < _e2414) || _e2416));
                                            let _e2421 = select(_e2414, _e2373, ((_e2373 > _e2414) || _e2416));
                                            let _e2423 = floor((_e2418 * 32f));
                                            if (_e235 == 1u) {
                                                let _e2431 = -(floor((_e2421 * -32f)));
                                                let _e2436 = (select(32f, _e2431, ((_e2431 < 32f) || false)) - _e2423);
                                                phi_3952_ = select(select(0f, _e2436, ((_e2436 > 0f) || false)), 0f, (_e2421 <= _e2418));
                                            } else {
                                                phi_3952_ = -(floor(((_e2421 - _e2418) * -32f)));
                                            }
                                            let _e2442 = phi_3952_;
                                            let _e2450 = (bitcast<u32>((floor(select(0f, select(32f, _e2423, (_e2423 < 32f)), (_e2423 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e2458 = (bitcast<u32>((floor(select(0f, select(32f, _e2442, (_e2442 < 32f)), (_e2442 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e2450 >= 32u) {
                                                phi_4006_ = u32();
                                                phi_4007_ = true;
                                            } else {
                                                let _e2460 = (_e2458 == 0u);
                                                if _e2460 {
                                                    phi_4005_ = u32();
                                                } else {
                                                    if (_e2458 >= 32u) {
                                                        phi_4002_ = 4294967295u;
                                                    } else {
                                                        phi_4002_ = ((1u << bitcast<u32>((_e2458 & 31u))) - 1u);
                                                    }
                                                    let _e2467 = phi_4002_;
                                                    phi_4005_ = (_e2467 << bitcast<u32>((_e2450 & 31u)));
                                                }
                                                let _e2472 = phi_4005_;
                                                phi_4006_ = _e2472;
                                                phi_4007_ = _e2460;
                                            }
                                            let _e2474 = phi_4006_;
                                            let _e2476 = phi_4007_;
                                            phi_4017_ = (select(select(_e2474, 0u, _e2476), 0u, _e1070) | _e2345);
                                        } else {
                                            phi_4017_ = 0u;
                                        }
                                        let _e2481 = phi_4017_;
                                        let _e2483 = (_e960 - _e466);
                                        let _e2484 = (_e964 - _e473);
                                        let _e2485 = (_e956 - _e459);
                                        if _e968 {
                                            phi_4041_ = select(true, false, ((((_e2483 * _e2483) + (_e2484 * _e2484)) + (_e2485 * _e2485)) > (_e241 * _e241)));
                                        } else {
                                            phi_4041_ = true;
                                        }
                                        let _e2495 = phi_4041_;
                                        if _e2495 {
                                            let _e2496 = (_e485 * _e238);
                                            let _e2497 = (_e486 * _e238);
                                            let _e2498 = (_e487 * _e238);
                                            let _e2502 = vec3<f32>((_e2483 - _e2496), (_e2484 - _e2497), (_e2485 - _e2498));
                                            let _e2507 = (((_e2483 * _e485) + (_e2484 * _e486)) + (_e2485 * _e487));
                                            let _e2511 = (_e2483 - (_e485 * _e2507));
                                            let _e2512 = (_e2484 - (_e486 * _e2507));
                                            let _e2513 = (_e2485 - (_e487 * _e2507));
                                            let _e2516 = ((_e2512 * _e487) - (_e486 * _e2513));
                                            let _e2519 = ((_e2513 * _e485) - (_e487 * _e2511));
                                            let _e2522 = ((_e2511 * _e486) - (_e485 * _e2512));
                                            let _e2533 = ((((_e546 * _e2516) + (_e547 * _e2519)) + (_e548 * _e2522)) / (((_e2516 * _e2516) + (_e2519 * _e2519)) + (_e2522 * _e2522)));
                                            let _e2537 = (_e546 - (_e2516 * _e2533));
                                            let _e2538 = (_e547 - (_e2519 * _e2533));
                                            let _e2539 = (_e548 - (_e2522 * _e2533));
                                            let _e2545 = inverseSqrt((((_e2537 * _e2537) + (_e2538 * _e2538)) + (_e2539 * _e2539)));
                                            let _e2551 = ((((_e2537 * _e485) + (_e2538 * _e486)) + (_e2539 * _e487)) * _e2545);
                                            let _e2555 = select(0f, select(1f, _e2551, (_e2551 < 1f)), (_e2551 > 0f));
                                            let _e2556 = abs(_e2555);
                                            let _e2566 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e2556, 0.00667009f), _e2556, -0.017088126f), _e2556, 0.03089188f), _e2556, -0.050174303f), _e2556, 0.08897899f), _e2556, -0.2145988f), _e2556, 1.5707963f) * sqrt((1f - _e2556)));
                                            let _e2569 = select((3.1415927f - _e2566), _e2566, (_e2555 >= 0f));
                                            let _e2577 = select(_e2569, -(_e2569), ((((_e2511 * _e2537) + (_e2512 * _e2538)) + (_e2513 * _e2539)) < 0f));
                                            let _e2578 = (_e2545 * 0.02f);
                                            let _e2581 = select(0.19634955f, _e2578, ((_e2578 < 0.19634955f) || false));
                                            let _e2587 = ((((_e2511 * _e2511) + (_e2512 * _e2512)) + (_e2513 * _e2513)) <= 0f);
                                            let _e2592 = (((_e2483 * _e2483) + (_e2484 * _e2484)) + (_e2485 * _e2485));
                                            if (_e241 <= 0f) {
                                                phi_4196_ = true;
                                            } else {
                                                phi_4196_ = (_e2592 <= (_e241 * _e241));
                                            }
                                            let _e2597 = phi_4196_;
                                            if _e2597 {
                                                phi_4212_ = ((((_e2483 * _e546) + (_e2484 * _e547)) + (_e2485 * _e548)) > (0.018f * sqrt(_e2592)));
                                            } else {
                                                phi_4212_ = false;
                                            }
                                            let _e2607 = phi_4212_;
                                            if _e2607 {
                                                let _e2608 = (0.5f / _e956);
                                                let _e2614 = frame.member[0u].member_1.member.member.member_1[0u];
                                                let _e2622 = frame.member[0u].member_1.member.member.member_1[1u];
                                                let _e2627 = frame.member[0u].member_1.member_5[0u];
                                                let _e2630 = frame.member[0u].member_1.member_5[1u];
                                                let _e2631 = f32(_e2627);
                                                let _e2632 = f32(_e2630);
                                                let _e2634 = frame.member[0u].member_1.member_4;
                                                let _e2635 = f32(_e2634);
                                                let _e2636 = (2u * _e2634);
                                                let _e2637 = (_e2627 + _e2636);
                                                let _e2643 = (floor(((((_e960 * _e2608) / _e2614) + 0.5f) * _e2631)) + _e2635);
                                                let _e2644 = f32((_e2637 - 1u));
                                                let _e2648 = select(0f, select(_e2644, _e2643, (_e2643 < _e2644)), (_e2643 > 0f));
                                                let _e2651 = (floor(((0.5f - ((_e964 * _e2608) / _e2622)) * _e2632)) + _e2635);
                                                let _e2652 = f32(((_e2630 + _e2636) - 1u));
                                                let _e2656 = select(0f, select(_e2652, _e2651, (_e2651 < _e2652)), (_e2651 > 0f));
                                                let _e2661 = select(select(u32(_e2648), 0u, (_e2648 < 0f)), 4294967295u, (_e2648 > 4294967000f));
                                                let _e2666 = select(select(u32(_e2656), 0u, (_e2656 < 0f)), 4294967295u, (_e2656 > 4294967000f));
                                                let _e2669 = bitcast<i32>(_e2634);
                                                let _e2675 = frame.member[0u].member_1.member_8;
                                                let _e2677 = frame.member[0u].member_1.member_12;
                                                let _e2684 = (((((_e2666 % 4u) * 4u) + (_e2661 % 4u)) + (_e2677 % 16u)) % 16u);
                                                if (_e2675 == 1u) {
                                                    local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    let _e2697 = (_e2684 < 16u);
                                                    if _e2697 {
                                                    } else {
                                                        phi_8008_ = true;
                                                        break;
                                                    }
                                                    let _e2700 = local_1[_e2684][0u];
                                                    local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                                    if _e2697 {
                                                    } else {
                                                        phi_8008_ = true;
                                                        break;
                                                    }
                                                    let _e2703 = local_2[_e2684][1u];
                                                    phi_4372_ = vec2<f32>(_e2700, _e2703);
                                                } else {
                                                    if (_e2675 == 2u) {
                                                        local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        let _e2687 = (_e2684 < 16u);
                                                        if _e2687 {
                                                        } else {
                                                            phi_8008_ = true;
                                                            break;
                                                        }
                                                        let _e2690 = local_3[_e2684][0u];
                                                        local_4 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                                        if _e2687 {
                                                        } else {
                                                            phi_8008_ = true;
                                                            break;
                                                        }
                                                        let _e2693 = local_4[_e2684][1u];
                                                        phi_4371_ = vec2<f32>(_e2690, _e2693);
                                                    } else {
                                                        phi_4371_ = vec2<f32>(0.5f, 0.5f);
                                                    }
                                                    let _e2696 = phi_4371_;
                                                    phi_4372_ = _e2696;
                                                }
                                                let _e2706 = phi_4372_;
                                                let _e2711 = ((f32((bitcast<i32>(_e2661) - _e2669)) + _e2706.x) / _e2631);
                                                let _e2712 = ((f32((bitcast<i32>(_e2666) - _e2669)) + _e2706.y) / _e2632);
                                                let _e2717 = frame.member[0u].member_1.member.member.member[0u];
                                                let _e2722 = select(select(u32(_e2717), 0u, (_e2717 < 0f)), 4294967295u, (_e2717 > 4294967000f));
                                                let _e2727 = frame.member[0u].member_1.member.member.member[1u];
                                                let _e2737 = (select(0f, select(1f, _e2711, (_e2711 < 1f)), (_e2711 > 0f)) * _e2717);
                                                let _e2740 = f32(bitcast<i32>((_e2722 - 1u)));
                                                let _e2753 = (select(0f, select(1f, _e2712, (_e2712 < 1f)), (_e2712 > 0f)) * _e2727);
                                                let _e2756 = f32(bitcast<i32>((select(select(u32(_e2727), 0u, (_e2727 < 0f)), 4294967295u, (_e2727 > 4294967000f)) - 1u)));
                                                let _e2768 = mips.member[(((bitcast<u32>((floor(select(0f, select(_e2756, _e2753, (_e2753 < _e2756)), (_e2753 > 0f))) + 8388608f)) - 1258291200u) * _e2722) + (bitcast<u32>((floor(select(0f, select(_e2740, _e2737, (_e2737 < _e2740)), (_e2737 > 0f))) + 8388608f)) - 1258291200u))];
                                                if (abs((_e2768 - _e956)) <= _e238) {
                                                    phi_4490_ = (_e956 * 1.001f);
                                                } else {
                                                    phi_4490_ = 0x1.fffffep+127f;
                                                }
                                                let _e2774 = phi_4490_;
                                                let _e2776 = frame.member[0u].member_1.member_6;
                                                let _e2779 = (((_e2666 * _e2637) + _e2661) * _e2776);
                                                let _e2781 = sd_map.member[_e2779];
                                                let _e2785 = frame.member[0u].member_1.member.member.member_3;
                                                let _e2789 = frame.member[0u].member_1.member.member.member_2;
                                                let _e2790 = (_e2785 - _e2789);
                                                let _e2792 = ((_e2781 * _e2790) + _e2789);
                                                if (0u < _e2776) {
                                                    if (_e2781 < 1f) {
                                                        phi_4541_ = select(true, false, (_e2792 > _e2774));
                                                    } else {
                                                        phi_4541_ = true;
                                                    }
                                                    let _e2798 = phi_4541_;
                                                    phi_4542_ = _e2798;
                                                } else {
                                                    phi_4542_ = true;
                                                }
                                                let _e2800 = phi_4542_;
                                                if _e2800 {
                                                    phi_4548_ = _e2785;
                                                } else {
                                                    phi_4548_ = _e2792;
                                                }
                                                let _e2802 = phi_4548_;
                                                let _e2803 = (_e2776 - 1u);
                                                let _e2808 = sd_map.member[(_e2779 + select(1u, _e2803, (_e2803 < 1u)))];
                                                let _e2810 = ((_e2808 * _e2790) + _e2789);
                                                if (1u < _e2776) {
                                                    if (_e2808 < 1f) {
                                                        phi_4581_ = select(true, false, (_e2810 > _e2774));
                                                    } else {
                                                        phi_4581_ = true;
                                                    }
                                                    let _e2816 = phi_4581_;
                                                    phi_4582_ = _e2816;
                                                } else {
                                                    phi_4582_ = true;
                                                }
                                                let _e2818 = phi_4582_;
                                                if _e2818 {
                                                    phi_4588_ = _e2785;
                                                } else {
                                                    phi_4588_ = _e2810;
                                                }
                                                let _e2820 = phi_4588_;
                                                let _e2825 = sd_map.member[(_e2779 + select(2u, _e2803, (_e2803 < 2u)))];
                                                let _e2827 = ((_e2825 * _e2790) + _e2789);
                                                if (2u < _e2776) {
                                                    if (_e2825 < 1f) {
                                                        phi_4621_ = select(true, false, (_e2827 > _e2774));
                                                    } else {
                                                        phi_4621_ = true;
                                                    }
                                                    let _e2833 = phi_4621_;
                                                    phi_4622_ = _e2833;
                                                } else {
                                                    phi_4622_ = true;
                                                }
                                                let _e2835 = phi_4622_;
                                                if _e2835 {
                                                    phi_4628_ = _e2785;
                                                } else {
                                                    phi_4628_ = _e2827;
                                                }
                                                let _e2837 = phi_4628_;
                                                let _e2842 = sd_map.member[(_e2779 + select(3u, _e2803, (_e2803 < 3u)))];
                                                let _e2844 = ((_e2842 * _e2790) + _e2789);
                                                if (3u < _e2776) {
                                                    if (_e2842 < 1f) {
                                                        phi_4661_ = select(true, false, (_e2844 > _e2774));
                                                    } else {
                                                        phi_4661_ = true;
                                                    }
                                                    let _e2850 = phi_4661_;
                                                    phi_4662_ = _e2850;
                                                } else {
                                                    phi_4662_ = true;
                                                }
                                                let _e2852 = phi_4662_;
                                                if _e2852 {
                                                    phi_4668_ = _e2785;
                                                } else {
                                                    phi_4668_ = _e2844;
                                                }
                                                let _e2854 = phi_4668_;
                                                if (_e2776 > 4u) {
                                                    let _e2860 = sd_map.member[(_e2779 + select(4u, _e2803, (_e2803 < 4u)))];
                                                    let _e2862 = ((_e2860 * _e2790) + _e2789);
                                                    if (4u < _e2776) {
                                                        if (_e2860 < 1f) {
                                                            phi_4705_ = select(true, false, (_e2862 > _e2774));
                                                        } else {
                                                            phi_4705_ = true;
                                                        }
                                                        let _e2868 = phi_4705_;
                                                        phi_4706_ = _e2868;
                                                    } else {
                                                        phi_4706_ = true;
                                                    }
                                                    let _e2870 = phi_4706_;
                                                    if _e2870 {
                                                        phi_4712_ = _e2785;
                                                    } else {
                                                        phi_4712_ = _e2862;
                                                    }
                                                    let _e2872 = phi_4712_;
                                                    let _e2877 = sd_map.member[(_e2779 + select(5u, _e2803, (_e2803 < 5u)))];
                                                    let _e2879 = ((_e2877 * _e2790) + _e2789);
                                                    if (5u < _e2776) {
                                                        if (_e2877 < 1f) {
                                                            phi_4745_ = select(true, false, (_e2879 > _e2774));
                                                        } else {
                                                            phi_4745_ = true;
                                                        }
                                                        let _e2885 = phi_4745_;
                                                        phi_4746_ = _e2885;
                                                    } else {
                                                        phi_4746_ = true;
                                                    }
                                                    let _e2887 = phi_4746_;
                                                    if _e2887 {
                                                        phi_4752_ = _e2785;
                                                    } else {
                                                        phi_4752_ = _e2879;
                                                    }
                                                    let _e2889 = phi_4752_;
                                                    let _e2894 = sd_map.member[(_e2779 + select(6u, _e2803, (_e2803 < 6u)))];
                                                    let _e2896 = ((_e2894 * _e2790) + _e2789);
                                                    if (6u < _e2776) {
                                                        if (_e2894 < 1f) {
                                                            phi_4785_ = select(true, false, (_e2896 > _e2774));
                                                        } else {
                                                            phi_4785_ = true;
                                                        }
                                                        let _e2902 = phi_4785_;
                                                        phi_4786_ = _e2902;
                                                    } else {
                                                        phi_4786_ = true;
                                                    }
                                                    let _e2904 = phi_4786_;
                                                    if _e2904 {
                                                        phi_4792_ = _e2785;
                                                    } else {
                                                        phi_4792_ = _e2896;
                                                    }
                                                    let _e2906 = phi_4792_;
                                                    let _e2911 = sd_map.member[(_e2779 + select(7u, _e2803, (_e2803 < 7u)))];
                                                    let _e2913 = ((_e2911 * _e2790) + _e2789);
                                                    if (7u < _e2776) {
                                                        if (_e2911 < 1f) {
                                                            phi_4825_ = select(true, false, (_e2913 > _e2774));
                                                        } else {
                                                            phi_4825_ = true;
                                                        }
                                                        let _e2919 = phi_4825_;
                                                        phi_4826_ = _e2919;
                                                    } else {
                                                        phi_4826_ = true;
                                                    }
                                                    let _e2921 = phi_4826_;
                                                    if _e2921 {
                                                        phi_4832_ = _e2785;
                                                    } else {
                                                        phi_4832_ = _e2913;
                                                    }
                                                    let _e2923 = phi_4832_;
                                                    phi_4841_ = _e2923;
                                                    phi_4842_ = _e2906;
                                                    phi_4843_ = _e2889;
                                                    phi_4844_ = _e2872;
                                                } else {
                                                    phi_4841_ = _e2785;
                                                    phi_4842_ = _e2785;
                                                    phi_4843_ = _e2785;
                                                    phi_4844_ = _e2785;
                                                }
                                                let _e2925 = phi_4841_;
                                                let _e2927 = phi_4842_;
                                                let _e2929 = phi_4843_;
                                                let _e2931 = phi_4844_;
                                                let _e2932 = (_e2802 != _e2802);
                                                if _e2932 {
                                                    phi_7424_ = true;
                                                } else {
                                                    phi_7424_ = (_e2820 <= _e2802);
                                                }
                                                let _e2935 = phi_7424_;
                                                let _e2936 = select(_e2802, _e2820, _e2935);
                                                if _e2932 {
                                                    phi_7439_ = true;
                                                } else {
                                                    phi_7439_ = (_e2820 >= _e2802);
                                                }
                                                let _e2939 = phi_7439_;
                                                let _e2940 = select(_e2802, _e2820, _e2939);
                                                let _e2941 = (_e2837 != _e2837);
                                                if _e2941 {
                                                    phi_7454_ = true;
                                                } else {
                                                    phi_7454_ = (_e2854 <= _e2837);
                                                }
                                                let _e2944 = phi_7454_;
                                                let _e2945 = select(_e2837, _e2854, _e2944);
                                                if _e2941 {
                                                    phi_7469_ = true;
                                                } else {
                                                    phi_7469_ = (_e2854 >= _e2837);
                                                }
                                                let _e2948 = phi_7469_;
                                                let _e2949 = select(_e2837, _e2854, _e2948);
                                                let _e2950 = (_e2931 != _e2931);
                                                if _e2950 {
                                                    phi_7484_ = true;
                                                } else {
                                                    phi_7484_ = (_e2929 <= _e2931);
                                                }
                                                let _e2953 = phi_7484_;
                                                let _e2954 = select(_e2931, _e2929, _e2953);
                                                if _e2950 {
                                                    phi_7499_ = true;
                                                } else {
                                                    phi_7499_ = (_e2929 >= _e2931);
                                                }
                                                let _e2957 = phi_7499_;
                                                let _e2958 = select(_e2931, _e2929, _e2957);
                                                let _e2959 = (_e2927 != _e2927);
                                                if _e2959 {
                                                    phi_7514_ = true;
                                                } else {
                                                    phi_7514_ = (_e2925 <= _e2927);
                                                }
                                                let _e2962 = phi_7514_;
                                                let _e2963 = select(_e2927, _e2925, _e2962);
                                                if _e2959 {
                                                    phi_7529_ = true;
                                                } else {
                                                    phi_7529_ = (_e2925 >= _e2927);
                                                }
                                                let _e2966 = phi_7529_;
                                                let _e2967 = select(_e2927, _e2925, _e2966);
                                                let _e2968 = (_e2936 != _e2936);
                                                if _e2968 {
                                                    phi_7544_ = true;
                                                } else {
                                                    phi_7544_ = (_e2945 <= _e2936);
                                                }
                                                let _e2971 = phi_7544_;
                                                let _e2972 = select(_e2936, _e2945, _e2971);
                                                if _e2968 {
                                                    phi_7559_ = true;
                                                } else {
                                                    phi_7559_ = (_e2945 >= _e2936);
                                                }
                                                let _e2975 = phi_7559_;
                                                let _e2976 = select(_e2936, _e2945, _e2975);
                                                let _e2977 = (_e2940 != _e2940);
                                                if _e2977 {
                                                    phi_7574_ = true;
                                                } else {
                                                    phi_7574_ = (_e2949 <= _e2940);
                                                }
                                                let _e2980 = phi_7574_;
                                                let _e2981 = select(_e2940, _e2949, _e2980);
                                                if _e2977 {
                                                    phi_7589_ = true;
                                                } else {
                                                    phi_7589_ = (_e2949 >= _e2940);
                                                }
                                                let _e2984 = phi_7589_;
                                                let _e2985 = select(_e2940, _e2949, _e2984);
                                                let _e2986 = (_e2954 != _e2954);
                                                if _e2986 {
                                                    phi_7604_ = true;
                                                } else {
                                                    phi_7604_ = (_e2963 <= _e2954);
                                                }
                                                let _e2989 = phi_7604_;
                                                let _e2990 = select(_e2954, _e2963, _e2989);
                                                if _e2986 {
                                                    phi_7619_ = true;
                                                } else {
                                                    phi_7619_ = (_e2963 >= _e2954);
                                                }
                                                let _e2993 = phi_7619_;
                                                let _e2994 = select(_e2954, _e2963, _e2993);
                                                let _e2995 = (_e2958 != _e2958);
                                                if _e2995 {
                                                    phi_7634_ = true;
                                                } else {
                                                    phi_7634_ = (_e2967 <= _e2958);
                                                }
                                                let _e2998 = phi_7634_;
                                                let _e2999 = select(_e2958, _e2967, _e2998);
                                                if _e2995 {
                                                    phi_7649_ = true;
                                                } else {
                                                    phi_7649_ = (_e2967 >= _e2958);
                                                }
                                                let _e3002 = phi_7649_;
                                                let _e3003 = select(_e2958, _e2967, _e3002);
                                                let _e3004 = (_e2981 != _e2981);
                                                if _e3004 {
                                                    phi_7664_ = true;
                                                } else {
                                                    phi_7664_ = (_e2976 <= _e2981);
                                                }
                                                let _e3007 = phi_7664_;
                                                let _e3008 = select(_e2981, _e2976, _e3007);
                                                if _e3004 {
                                                    phi_7679_ = true;
                                                } else {
                                                    phi_7679_ = (_e2976 >= _e2981);
                                                }
                                                let _e3011 = phi_7679_;
                                                let _e3012 = select(_e2981, _e2976, _e3011);
                                                let _e3013 = (_e2999 != _e2999);
                                                if _e3013 {
                                                    phi_7694_ = true;
                                                } else {
                                                    phi_7694_ = (_e2994 <= _e2999);
                                                }
                                                let _e3016 = phi_7694_;
                                                let _e3017 = select(_e2999, _e2994, _e3016);
                                                if _e3013 {
                                                    phi_7709_ = true;
                                                } else {
                                                    phi_7709_ = (_e2994 >= _e2999);
                                                }
                                                let _e3020 = phi_7709_;
                                                let _e3021 = select(_e2999, _e2994, _e3020);
                                                let _e3022 = (_e2972 != _e2972);
                                                if _e3022 {
                                                    phi_7724_ = true;
                                                } else {
                                                    phi_7724_ = (_e2990 <= _e2972);
                                                }
                                                let _e3025 = phi_7724_;
                                                let _e3026 = select(_e2972, _e2990, _e3025);
                                                if _e3022 {
                                                    phi_7739_ = true;
                                                } else {
                                                    phi_7739_ = (_e2990 >= _e2972);
                                                }
                                                let _e3029 = phi_7739_;
                                                let _e3030 = select(_e2972, _e2990, _e3029);
                                                let _e3031 = (_e3008 != _e3008);
                                                if _e3031 {
                                                    phi_7754_ = true;
                                                } else {
                                                    phi_7754_ = (_e3017 <= _e3008);
                                                }
                                                let _e3034 = phi_7754_;
                                                let _e3035 = select(_e3008, _e3017, _e3034);
                                                if _e3031 {
                                                    phi_7769_ = true;
                                                } else {
                                                    phi_7769_ = (_e3017 >= _e3008);
                                                }
                                                let _e3038 = phi_7769_;
                                                let _e3039 = select(_e3008, _e3017, _e3038);
                                                let _e3040 = (_e3012 != _e3012);
                                                if _e3040 {
                                                    phi_7784_ = true;
                                                } else {
                                                    phi_7784_ = (_e3021 <= _e3012);
                                                }
                                                let _e3043 = phi_7784_;
                                                let _e3044 = select(_e3012, _e3021, _e3043);
                                                if _e3040 {
                                                    phi_7799_ = true;
                                                } else {
                                                    phi_7799_ = (_e3021 >= _e3012);
                                                }
                                                let _e3047 = phi_7799_;
                                                let _e3048 = select(_e3012, _e3021, _e3047);
                                                let _e3049 = (_e2985 != _e2985);
                                                if _e3049 {
                                                    phi_7814_ = true;
                                                } else {
                                                    phi_7814_ = (_e3003 <= _e2985);
                                                }
                                                let _e3052 = phi_7814_;
                                                let _e3053 = select(_e2985, _e3003, _e3052);
                                                if _e3049 {
                                                    phi_7829_ = true;
                                                } else {
                                                    phi_7829_ = (_e3003 >= _e2985);
                                                }
                                                let _e3056 = phi_7829_;
                                                let _e3057 = select(_e2985, _e3003, _e3056);
                                                let _e3058 = (_e3044 != _e3044);
                                                if _e3058 {
                                                    phi_7844_ = true;
                                                } else {
                                                    phi_7844_ = (_e3030 <= _e3044);
                                                }
                                                let _e3061 = phi_7844_;
                                                let _e3062 = select(_e3044, _e3030, _e3061);
                                                if _e3058 {
                                                    phi_7859_ = true;
                                                } else {
                                                    phi_7859_ = (_e3030 >= _e3044);
                                                }
                                                let _e3065 = phi_7859_;
                                                let _e3066 = select(_e3044, _e3030, _e3065);
                                                let _e3067 = (_e3053 != _e3053);
                                                if _e3067 {
                                                    phi_7874_ = true;
                                                } else {
                                                    phi_7874_ = (_e3039 <= _e3053);
                                                }
                                                let _e3070 = phi_7874_;
                                                let _e3071 = select(_e3053, _e3039, _e3070);
                                                if _e3067 {
                                                    phi_7889_ = true;
                                                } else {
                                                    phi_7889_ = (_e3039 >= _e3053);
                                                }
                                                let _e3074 = phi_7889_;
                                                let _e3075 = select(_e3053, _e3039, _e3074);
                                                let _e3076 = (_e3035 != _e3035);
                                                if _e3076 {
                                                    phi_7904_ = true;
                                                } else {
                                                    phi_7904_ = (_e3062 <= _e3035);
                                                }
                                                let _e3079 = phi_7904_;
                                                let _e3080 = select(_e3035, _e3062, _e3079);
                                                if _e3076 {
                                                    phi_7919_ = true;
                                                } else {
                                                    phi_7919_ = (_e3062 >= _e3035);
                                                }
                                                let _e3083 = phi_7919_;
                                                let _e3084 = select(_e3035, _e3062, _e3083);
                                                let _e3085 = (_e3071 != _e3071);
                                                if _e3085 {
                                                    phi_7934_ = true;
                                                } else {
                                                    phi_7934_ = (_e3066 <= _e3071);
                                                }
                                                let _e3088 = phi_7934_;
                                                let _e3089 = select(_e3071, _e3066, _e3088);
                                                if _e3085 {
                                                    phi_7949_ = true;
                                                } else {
                                                    phi_7949_ = (_e3066 >= _e3071);
                                                }
                                                let _e3092 = phi_7949_;
                                                let _e3093 = select(_e3071, _e3066, _e3092);
                                                let _e3094 = (_e3075 != _e3075);
                                                if _e3094 {
                                                    phi_7964_ = true;
                                                } else {
                                                    phi_7964_ = (_e3048 <= _e3075);
                                                }
                                                let _e3097 = phi_7964_;
                                                let _e3098 = select(_e3075, _e3048, _e3097);
                                                if _e3094 {
                                                    phi_7979_ = true;
                                                } else {
                                                    phi_7979_ = (_e3048 >= _e3075);
                                                }
                                                let _e3101 = phi_7979_;
                                                let _e3102 = select(_e3075, _e3048, _e3101);
                                                if (_e3026 < _e2785) {
                                                    if (_e3026 > (_e956 + _e238)) {
                                                        phi_4913_ = (vec3<f32>(((((_e2711 * 2f) - 1f) * _e2614) * _e3026), ((((_e2712 * -2f) + 1f) * _e2622) * _e3026), _e3026) - _e474);
                                                    } else {
                                                        phi_4913_ = _e2502;
                                                    }
                                                    let _e3117 = phi_4913_;
                                                    phi_4914_ = _e3117;
                                                } else {
                                                    phi_4914_ = _e2502;
                                                }
                                                let _e3119 = phi_4914_;
                                                if (_e3080 >= _e225.member.member_3) {
                                                    phi_5240_ = u32();
                                                    phi_5241_ = true;
                                                } else {
                                                    let _e3123 = (((_e2711 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e3127 = (((_e2712 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e3129 = ((_e3123 * _e3080) - _e466);
                                                    let _e3130 = ((_e3127 * _e3080) - _e473);
                                                    let _e3131 = (_e3080 - _e459);
                                                    if (_e3084 < _e225.member.member_3) {
                                                        phi_4968_ = (vec3<f32>((_e3123 * _e3084), (_e3127 * _e3084), _e3084) - _e474);
                                                    } else {
                                                        phi_4968_ = vec3<f32>((_e3129 - _e2496), (_e3130 - _e2497), (_e3131 - _e2498));
                                                    }
                                                    let _e3142 = phi_4968_;
                                                    if _e968 {
                                                        phi_4984_ = select(true, false, ((((_e3129 * _e3129) + (_e3130 * _e3130)) + (_e3131 * _e3131)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_4984_ = true;
                                                    }
                                                    let _e3152 = phi_4984_;
                                                    if _e3152 {
                                                        let _e3164 = ((((_e3129 * _e485) + (_e3130 * _e486)) + (_e3131 * _e487)) * inverseSqrt((((_e3129 * _e3129) + (_e3130 * _e3130)) + (_e3131 * _e3131))));
                                                        let _e3168 = select(-1f, select(1f, _e3164, (_e3164 < 1f)), (_e3164 > -1f));
                                                        let _e3169 = abs(_e3168);
                                                        let _e3179 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3169, 0.00667009f), _e3169, -0.017088126f), _e3169, 0.03089188f), _e3169, -0.050174303f), _e3169, 0.08897899f), _e3169, -0.2145988f), _e3169, 1.5707963f) * sqrt((1f - _e3169)));
                                                        let _e3186 = ((((select((3.1415927f - _e3179), _e3179, (_e3168 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3205 = ((((_e3142.x * _e485) + (_e3142.y * _e486)) + (_e3142.z * _e487)) * inverseSqrt((((_e3142.x * _e3142.x) + (_e3142.y * _e3142.y)) + (_e3142.z * _e3142.z))));
                                                        let _e3209 = select(-1f, select(1f, _e3205, (_e3205 < 1f)), (_e3205 > -1f));
                                                        let _e3210 = abs(_e3209);
                                                        let _e3220 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3210, 0.00667009f), _e3210, -0.017088126f), _e3210, 0.03089188f), _e3210, -0.050174303f), _e3210, 0.08897899f), _e3210, -0.2145988f), _e3210, 1.5707963f) * sqrt((1f - _e3210)));
                                                        let _e3227 = ((((select((3.1415927f - _e3220), _e3220, (_e3209 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3232 = (1f - select(0f, select(1f, _e3186, (_e3186 < 1f)), (_e3186 > 0f)));
                                                        let _e3233 = (1f - select(0f, select(1f, _e3227, (_e3227 < 1f)), (_e3227 > 0f)));
                                                        let _e3235 = (_e3233 != _e3233);
                                                        let _e3237 = select(_e3233, _e3232, ((_e3232 < _e3233) || _e3235));
                                                        let _e3240 = select(_e3233, _e3232, ((_e3232 > _e3233) || _e3235));
                                                        let _e3242 = floor((_e3237 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e3250 = -(floor((_e3240 * -32f)));
                                                            let _e3255 = (select(32f, _e3250, ((_e3250 < 32f) || false)) - _e3242);
                                                            phi_5174_ = select(select(0f, _e3255, ((_e3255 > 0f) || false)), 0f, (_e3240 <= _e3237));
                                                        } else {
                                                            phi_5174_ = -(floor(((_e3240 - _e3237) * -32f)));
                                                        }
                                                        let _e3261 = phi_5174_;
                                                        let _e3269 = (bitcast<u32>((floor(select(0f, select(32f, _e3242, (_e3242 < 32f)), (_e3242 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e3277 = (bitcast<u32>((floor(select(0f, select(32f, _e3261, (_e3261 < 32f)), (_e3261 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e3269 >= 32u) {
                                                            phi_5228_ = u32();
                                                            phi_5229_ = true;
                                                        } else {
                                                            let _e3279 = (_e3277 == 0u);
                                                            if _e3279 {
                                                                phi_5227_ = u32();
                                                            } else {
                                                                if (_e3277 >= 32u) {
                                                                    phi_5224_ = 4294967295u;
                                                                } else {
                                                                    phi_5224_ = ((1u << bitcast<u32>((_e3277 & 31u))) - 1u);
                                                                }
                                                                let _e3286 = phi_5224_;
                                                                phi_5227_ = (_e3286 << bitcast<u32>((_e3269 & 31u)));
                                                            }
                                                            let _e3291 = phi_5227_;
                                                            phi_5228_ = _e3291;
                                                            phi_5229_ = _e3279;
                                                        }
                                                        let _e3293 = phi_5228_;
                                                        let _e3295 = phi_5229_;
                                                        phi_5238_ = select(select(_e3293, 0u, _e3295), 0u, _e2587);
                                                    } else {
                                                        phi_5238_ = u32();
                                                    }
                                                    let _e3299 = phi_5238_;
                                                    phi_5240_ = _e3299;
                                                    phi_5241_ = select(true, false, _e3152);
                                                }
                                                let _e3302 = phi_5240_;
                                                let _e3304 = phi_5241_;
                                                if (_e3089 >= _e225.member.member_3) {
                                                    phi_5571_ = u32();
                                                    phi_5572_ = true;
                                                } else {
                                                    let _e3309 = (((_e2711 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e3313 = (((_e2712 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e3315 = ((_e3309 * _e3089) - _e466);
                                                    let _e3316 = ((_e3313 * _e3089) - _e473);
                                                    let _e3317 = (_e3089 - _e459);
                                                    if (_e3093 < _e225.member.member_3) {
                                                        phi_5299_ = (vec3<f32>((_e3309 * _e3093), (_e3313 * _e3093), _e3093) - _e474);
                                                    } else {
                                                        phi_5299_ = vec3<f32>((_e3315 - _e2496), (_e3316 - _e2497), (_e3317 - _e2498));
                                                    }
                                                    let _e3328 = phi_5299_;
                                                    if _e968 {
                                                        phi_5315_ = select(true, false, ((((_e3315 * _e3315) + (_e3316 * _e3316)) + (_e3317 * _e3317)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_5315_ = true;
                                                    }
                                                    let _e3338 = phi_5315_;
                                                    if _e3338 {
                                                        let _e3350 = ((((_e3315 * _e485) + (_e3316 * _e486)) + (_e3317 * _e487)) * inverseSqrt((((_e3315 * _e3315) + (_e3316 * _e3316)) + (_e3317 * _e3317))));
                                                        let _e3354 = select(-1f, select(1f, _e3350, (_e3350 < 1f)), (_e3350 > -1f));
                                                        let _e3355 = abs(_e3354);
                                                        let _e3365 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3355, 0.00667009f), _e3355, -0.017088126f), _e3355, 0.03089188f), _e3355, -0.050174303f), _e3355, 0.08897899f), _e3355, -0.2145988f), _e3355, 1.5707963f) * sqrt((1f - _e3355)));
                                                        let _e3372 = ((((select((3.1415927f - _e3365), _e3365, (_e3354 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3391 = ((((_e3328.x * _e485) + (_e3328.y * _e486)) + (_e3328.z * _e487)) * inverseSqrt((((_e3328.x * _e3328.x) + (_e3328.y * _e3328.y)) + (_e3328.z * _e3328.z))));
                                                        let _e3395 = select(-1f, select(1f, _e3391, (_e3391 < 1f)), (_e3391 > -1f));
                                                        let _e3396 = abs(_e3395);
                                                        let _e3406 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3396, 0.00667009f), _e3396, -0.017088126f), _e3396, 0.03089188f), _e3396, -0.050174303f), _e3396, 0.08897899f), _e3396, -0.2145988f), _e3396, 1.5707963f) * sqrt((1f - _e3396)));
                                                        let _e3413 = ((((select((3.1415927f - _e3406), _e3406, (_e3395 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3418 = (1f - select(0f, select(1f, _e3372, (_e3372 < 1f)), (_e3372 > 0f)));
                                                        let _e3419 = (1f - select(0f, select(1f, _e3413, (_e3413 < 1f)), (_e3413 > 0f)));
                                                        let _e3421 = (_e3419 != _e3419);
                                                        let _e3423 = select(_e3419, _e3418, ((_e3418 < _e3419) || _e3421));
                                                        let _e3426 = select(_e3419, _e3418, ((_e3418 > _e3419) || _e3421));
                                                        let _e3428 = floor((_e3423 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e3436 = -(floor((_e3426 * -32f)));
                                                            let _e3441 = (select(32f, _e3436, ((_e3436 < 32f) || false)) - _e3428);
                                                            phi_5505_ = select(select(0f, _e3441, ((_e3441 > 0f) || false)), 0f, (_e3426 <= _e3423));
                                                        } else {
                                                            phi_5505_ = -(floor(((_e3426 - _e3423) * -32f)));
                                                        }
                                                        let _e3447 = phi_5505_;
                                                        let _e3455 = (bitcast<u32>((floor(select(0f, select(32f, _e3428, (_e3428 < 32f)), (_e3428 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e3463 = (bitcast<u32>((floor(select(0f, select(32f, _e3447, (_e3447 < 32f)), (_e3447 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e3455 >= 32u) {
                                                            phi_5559_ = u32();
                                                            phi_5560_ = true;
                                                        } else {
                                                            let _e3465 = (_e3463 == 0u);
                                                            if _e3465 {
                                                                phi_5558_ = u32();
                                                            } else {
                                                                if (_e3463 >= 32u) {
                                                                    phi_5555_ = 4294967295u;
                                                                } else {
                                                                    phi_5555_ = ((1u << bitcast<u32>((_e3463 & 31u))) - 1u);
                                                                }
                                                                let _e3472 = phi_5555_;
                                                                phi_5558_ = (_e3472 << bitcast<u32>((_e3455 & 31u)));
                                                            }
                                                            let _e3477 = phi_5558_;
                                                            phi_5559_ = _e3477;
                                                            phi_5560_ = _e3465;
                                                        }
                                                        let _e3479 = phi_5559_;
                                                        let _e3481 = phi_5560_;
                                                        phi_5569_ = select(select(_e3479, 0u, _e3481), 0u, _e2587);
                                                    } else {
                                                        phi_5569_ = u32();
                                                    }
                                                    let _e3485 = phi_5569_;
                                                    phi_5571_ = _e3485;
                                                    phi_5572_ = select(true, false, _e3338);
                                                }
                                                let _e3488 = phi_5571_;
                                                let _e3490 = phi_5572_;
                                                if (_e3098 >= _e225.member.member_3) {
                                                    phi_5903_ = u32();
                                                    phi_5904_ = true;
                                                } else {
                                                    let _e3496 = (((_e2711 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e3500 = (((_e2712 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e3502 = ((_e3496 * _e3098) - _e466);
                                                    let _e3503 = ((_e3500 * _e3098) - _e473);
                                                    let _e3504 = (_e3098 - _e459);
                                                    if (_e3102 < _e225.member.member_3) {
                                                        phi_5631_ = (vec3<f32>((_e3496 * _e3102), (_e3500 * _e3102), _e3102) - _e474);
                                                    } else {
                                                        phi_5631_ = vec3<f32>((_e3502 - _e2496), (_e3503 - _e2497), (_e3504 - _e2498));
                                                    }
                                                    let _e3515 = phi_5631_;
                                                    if _e968 {
                                                        phi_5647_ = select(true, false, ((((_e3502 * _e3502) + (_e3503 * _e3503)) + (_e3504 * _e3504)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_5647_ = true;
                                                    }
                                                    let _e3525 = phi_5647_;
                                                    if _e3525 {
                                                        let _e3537 = ((((_e3502 * _e485) + (_e3503 * _e486)) + (_e3504 * _e487)) * inverseSqrt((((_e3502 * _e3502) + (_e3503 * _e3503)) + (_e3504 * _e3504))));
                                                        let _e3541 = select(-1f, select(1f, _e3537, (_e3537 < 1f)), (_e3537 > -1f));
                                                        let _e3542 = abs(_e3541);
                                                        let _e3552 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3542, 0.00667009f), _e3542, -0.017088126f), _e3542, 0.03089188f), _e3542, -0.050174303f), _e3542, 0.08897899f), _e3542, -0.2145988f), _e3542, 1.5707963f) * sqrt((1f - _e3542)));
                                                        let _e3559 = ((((select((3.1415927f - _e3552), _e3552, (_e3541 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3578 = ((((_e3515.x * _e485) + (_e3515.y * _e486)) + (_e3515.z * _e487)) * inverseSqrt((((_e3515.x * _e3515.x) + (_e3515.y * _e3515.y)) + (_e3515.z * _e3515.z))));
                                                        let _e3582 = select(-1f, select(1f, _e3578, (_e3578 < 1f)), (_e3578 > -1f));
                                                        let _e3583 = abs(_e3582);
                                                        let _e3593 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3583, 0.00667009f), _e3583, -0.017088126f), _e3583, 0.03089188f), _e3583, -0.050174303f), _e3583, 0.08897899f), _e3583, -0.2145988f), _e3583, 1.5707963f) * sqrt((1f - _e3583)));
                                                        let _e3600 = ((((select((3.1415927f - _e3593), _e3593, (_e3582 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3605 = (1f - select(0f, select(1f, _e3559, (_e3559 < 1f)), (_e3559 > 0f)));
                                                        let _e3606 = (1f - select(0f, select(1f, _e3600, (_e3600 < 1f)), (_e3600 > 0f)));
                                                        let _e3608 = (_e3606 != _e3606);
                                                        let _e3610 = select(_e3606, _e3605, ((_e3605 < _e3606) || _e3608));
                                                        let _e3613 = select(_e3606, _e3605, ((_e3605 > _e3606) || _e3608));
                                                        let _e3615 = floor((_e3610 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e3623 = -(floor((_e3613 * -32f)));
                                                            let _e3628 = (select(32f, _e3623, ((_e3623 < 32f) || false)) - _e3615);
                                                            phi_5837_ = select(select(0f, _e3628, ((_e3628 > 0f) || false)), 0f, (_e3613 <= _e3610));
                                                        } else {
                                                            phi_5837_ = -(floor(((_e3613 - _e3610) * -32f)));
                                                        }
                                                        let _e3634 = phi_5837_;
                                                        let _e3642 = (bitcast<u32>((floor(select(0f, select(32f, _e3615, (_e3615 < 32f)), (_e3615 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e3650 = (bitcast<u32>((floor(select(0f, select(32f, _e3634, (_e3634 < 32f)), (_e3634 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e3642 >= 32u) {
                                                            phi_5891_ = u32();
                                                            phi_5892_ = true;
                                                        } else {
                                                            let _e3652 = (_e3650 == 0u);
                                                            if _e3652 {
                                                                phi_5890_ = u32();
                                                            } else {
                                                                if (_e3650 >= 32u) {
                                                                    phi_5887_ = 4294967295u;
                                                                } else {
                                                                    phi_5887_ = ((1u << bitcast<u32>((_e3650 & 31u))) - 1u);
                                                                }
                                                                let _e3659 = phi_5887_;
                                                                phi_5890_ = (_e3659 << bitcast<u32>((_e3642 & 31u)));
                                                            }
                                                            let _e3664 = phi_5890_;
                                                            phi_5891_ = _e3664;
                                                            phi_5892_ = _e3652;
                                                        }
                                                        let _e3666 = phi_5891_;
                                                        let _e3668 = phi_5892_;
                                                        phi_5901_ = select(select(_e3666, 0u, _e3668), 0u, _e2587);
                                                    } else {
                                                        phi_5901_ = u32();
                                                    }
                                                    let _e3672 = phi_5901_;
                                                    phi_5903_ = _e3672;
                                                    phi_5904_ = select(true, false, _e3525);
                                                }
                                                let _e3675 = phi_5903_;
                                                let _e3677 = phi_5904_;
                                                if (_e3057 >= _e225.member.member_3) {
                                                    phi_6237_ = u32();
                                                    phi_6238_ = true;
                                                } else {
                                                    let _e3683 = (((_e2711 * 2f) - 1f) * _e225.member.member_1.x);
                                                    let _e3687 = (((_e2712 * -2f) + 1f) * _e225.member.member_1.y);
                                                    let _e3689 = ((_e3683 * _e3057) - _e466);
                                                    let _e3690 = ((_e3687 * _e3057) - _e473);
                                                    let _e3691 = (_e3057 - _e459);
                                                    if (_e2785 < _e225.member.member_3) {
                                                        phi_5965_ = (vec3<f32>((_e3683 * _e2785), (_e3687 * _e2785), _e2785) - _e474);
                                                    } else {
                                                        phi_5965_ = vec3<f32>((_e3689 - _e2496), (_e3690 - _e2497), (_e3691 - _e2498));
                                                    }
                                                    let _e3702 = phi_5965_;
                                                    if _e968 {
                                                        phi_5981_ = select(true, false, ((((_e3689 * _e3689) + (_e3690 * _e3690)) + (_e3691 * _e3691)) > (_e241 * _e241)));
                                                    } else {
                                                        phi_5981_ = true;
                                                    }
                                                    let _e3712 = phi_5981_;
                                                    if _e3712 {
                                                        let _e3724 = ((((_e3689 * _e485) + (_e3690 * _e486)) + (_e3691 * _e487)) * inverseSqrt((((_e3689 * _e3689) + (_e3690 * _e3690)) + (_e3691 * _e3691))));
                                                        let _e3728 = select(-1f, select(1f, _e3724, (_e3724 < 1f)), (_e3724 > -1f));
                                                        let _e3729 = abs(_e3728);
                                                        let _e3739 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3729, 0.00667009f), _e3729, -0.017088126f), _e3729, 0.03089188f), _e3729, -0.050174303f), _e3729, 0.08897899f), _e3729, -0.2145988f), _e3729, 1.5707963f) * sqrt((1f - _e3729)));
                                                        let _e3746 = ((((select((3.1415927f - _e3739), _e3739, (_e3728 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3765 = ((((_e3702.x * _e485) + (_e3702.y * _e486)) + (_e3702.z * _e487)) * inverseSqrt((((_e3702.x * _e3702.x) + (_e3702.y * _e3702.y)) + (_e3702.z * _e3702.z))));
                                                        let _e3769 = select(-1f, select(1f, _e3765, (_e3765 < 1f)), (_e3765 > -1f));
                                                        let _e3770 = abs(_e3769);
                                                        let _e3780 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3770, 0.00667009f), _e3770, -0.017088126f), _e3770, 0.03089188f), _e3770, -0.050174303f), _e3770, 0.08897899f), _e3770, -0.2145988f), _e3770, 1.5707963f) * sqrt((1f - _e3770)));
                                                        let _e3787 = ((((select((3.1415927f - _e3780), _e3780, (_e3769 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                                        let _e3792 = (1f - select(0f, select(1f, _e3746, (_e3746 < 1f)), (_e3746 > 0f)));
                                                        let _e3793 = (1f - select(0f, select(1f, _e3787, (_e3787 < 1f)), (_e3787 > 0f)));
                                                        let _e3795 = (_e3793 != _e3793);
                                                        let _e3797 = select(_e3793, _e3792, ((_e3792 < _e3793) || _e3795));
                                                        let _e3800 = select(_e3793, _e3792, ((_e3792 > _e3793) || _e3795));
                                                        let _e3802 = floor((_e3797 * 32f));
                                                        if (_e235 == 1u) {
                                                            let _e3810 = -(floor((_e3800 * -32f)));
                                                            let _e3815 = (select(32f, _e3810, ((_e3810 < 32f) || false)) - _e3802);
                                                            phi_6171_ = select(select(0f, _e3815, ((_e3815 > 0f) || false)), 0f, (_e3800 <= _e3797));
                                                        } else {
                                                            phi_6171_ = -(floor(((_e3800 - _e3797) * -32f)));
                                                        }
                                                        let _e3821 = phi_6171_;
                                                        let _e3829 = (bitcast<u32>((floor(select(0f, select(32f, _e3802, (_e3802 < 32f)), (_e3802 > 0f))) + 8388608f)) - 1258291200u);
                                                        let _e3837 = (bitcast<u32>((floor(select(0f, select(32f, _e3821, (_e3821 < 32f)), (_e3821 > 0f))) + 8388608f)) - 1258291200u);
                                                        if (_e3829 >= 32u) {
                                                            phi_6225_ = u32();
                                                            phi_6226_ = true;
                                                        } else {
                                                            let _e3839 = (_e3837 == 0u);
                                                            if _e3839 {
                                                                phi_6224_ = u32();
                                                            } else {
                                                                if (_e3837 >= 32u) {
                                                                    phi_6221_ = 4294967295u;
                                                                } else {
                                                                    phi_6221_ = ((1u << bitcast<u32>((_e3837 & 31u))) - 1u);
                                                                }
                                                                let _e3846 = phi_6221_;
                                                                phi_6224_ = (_e3846 << bitcast<u32>((_e3829 & 31u)));
                                                            }
                                                            let _e3851 = phi_6224_;
                                                            phi_6225_ = _e3851;
                                                            phi_6226_ = _e3839;
                                                        }
                                                        let _e3853 = phi_6225_;
                                                        let _e3855 = phi_6226_;
                                                        phi_6235_ = select(select(_e3853, 0u, _e3855), 0u, _e2587);
                                                    } else {
                                                        phi_6235_ = u32();
                                                    }
                                                    let _e3859 = phi_6235_;
                                                    phi_6237_ = _e3859;
                                                    phi_6238_ = select(true, false, _e3712);
                                                }
                                                let _e3862 = phi_6237_;
                                                let _e3864 = phi_6238_;
                                                phi_6244_ = _e3119;
                                                phi_6245_ = (((select(_e3302, 0u, _e3304) | select(_e3488, 0u, _e3490)) | select(_e3675, 0u, _e3677)) | select(_e3862, 0u, _e3864));
                                            } else {
                                                phi_6244_ = _e2502;
                                                phi_6245_ = 0u;
                                            }
                                            let _e3868 = phi_6244_;
                                            let _e3870 = phi_6245_;
                                            let _e3872 = (_e2507 * inverseSqrt(_e2592));
                                            let _e3876 = select(-1f, select(1f, _e3872, (_e3872 < 1f)), (_e3872 > -1f));
                                            let _e3877 = abs(_e3876);
                                            let _e3887 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3877, 0.00667009f), _e3877, -0.017088126f), _e3877, 0.03089188f), _e3877, -0.050174303f), _e3877, 0.08897899f), _e3877, -0.2145988f), _e3877, 1.5707963f) * sqrt((1f - _e3877)));
                                            let _e3894 = ((((select((3.1415927f - _e3887), _e3887, (_e3876 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                            let _e3913 = ((((_e3868.x * _e485) + (_e3868.y * _e486)) + (_e3868.z * _e487)) * inverseSqrt((((_e3868.x * _e3868.x) + (_e3868.y * _e3868.y)) + (_e3868.z * _e3868.z))));
                                            let _e3917 = select(-1f, select(1f, _e3913, (_e3913 < 1f)), (_e3913 > -1f));
                                            let _e3918 = abs(_e3917);
                                            let _e3928 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e3918, 0.00667009f), _e3918, -0.017088126f), _e3918, 0.03089188f), _e3918, -0.050174303f), _e3918, 0.08897899f), _e3918, -0.2145988f), _e3918, 1.5707963f) * sqrt((1f - _e3918)));
                                            let _e3935 = ((((select((3.1415927f - _e3928), _e3928, (_e3917 >= 0f)) + _e2581) - _e2577) + 1.5707964f) * 0.31830987f);
                                            let _e3940 = (1f - select(0f, select(1f, _e3894, (_e3894 < 1f)), (_e3894 > 0f)));
                                            let _e3941 = (1f - select(0f, select(1f, _e3935, (_e3935 < 1f)), (_e3935 > 0f)));
                                            let _e3943 = (_e3941 != _e3941);
                                            let _e3945 = select(_e3941, _e3940, ((_e3940 < _e3941) || _e3943));
                                            let _e3948 = select(_e3941, _e3940, ((_e3940 > _e3941) || _e3943));
                                            let _e3950 = floor((_e3945 * 32f));
                                            if (_e235 == 1u) {
                                                let _e3958 = -(floor((_e3948 * -32f)));
                                                let _e3963 = (select(32f, _e3958, ((_e3958 < 32f) || false)) - _e3950);
                                                phi_6432_ = select(select(0f, _e3963, ((_e3963 > 0f) || false)), 0f, (_e3948 <= _e3945));
                                            } else {
                                                phi_6432_ = -(floor(((_e3948 - _e3945) * -32f)));
                                            }
                                            let _e3969 = phi_6432_;
                                            let _e3977 = (bitcast<u32>((floor(select(0f, select(32f, _e3950, (_e3950 < 32f)), (_e3950 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e3985 = (bitcast<u32>((floor(select(0f, select(32f, _e3969, (_e3969 < 32f)), (_e3969 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e3977 >= 32u) {
                                                phi_6486_ = u32();
                                                phi_6487_ = true;
                                            } else {
                                                let _e3987 = (_e3985 == 0u);
                                                if _e3987 {
                                                    phi_6485_ = u32();
                                                } else {
                                                    if (_e3985 >= 32u) {
                                                        phi_6482_ = 4294967295u;
                                                    } else {
                                                        phi_6482_ = ((1u << bitcast<u32>((_e3985 & 31u))) - 1u);
                                                    }
                                                    let _e3994 = phi_6482_;
                                                    phi_6485_ = (_e3994 << bitcast<u32>((_e3977 & 31u)));
                                                }
                                                let _e3999 = phi_6485_;
                                                phi_6486_ = _e3999;
                                                phi_6487_ = _e3987;
                                            }
                                            let _e4001 = phi_6486_;
                                            let _e4003 = phi_6487_;
                                            phi_6497_ = (select(select(_e4001, 0u, _e4003), 0u, _e2587) | _e3870);
                                        } else {
                                            phi_6497_ = 0u;
                                        }
                                        let _e4008 = phi_6497_;
                                        phi_1219_ = (_e788 + 1u);
                                        phi_1222_ = ((_e790 | _e2481) | _e4008);
                                    } else {
                                        phi_1219_ = u32();
                                        phi_1222_ = u32();
                                    }
                                    let _e4012 = phi_1219_;
                                    let _e4014 = phi_1222_;
                                    continue;
                                    continuing {
                                        phi_1218_ = _e4012;
                                        phi_1221_ = _e4014;
                                        phi_8008_ = _e685;
                                        break if !(_e791);
                                    }
                                }
                                let _e4017 = phi_8008_;
                                phi_8710_ = _e4017;
                                if _e4017 {
                                    break;
                                }
                                if (_e230 == 2u) {
                                    let _e4076 = (_e783 - 1.5707964f);
                                    let _e4077 = (_e4076 * 2f);
                                    let _e4078 = sin(_e783);
                                    let _e4083 = ((_e768 + (_e4077 * _e4078)) - cos((_e4077 - _e783)));
                                    phi_6526_ = 0u;
                                    phi_6529_ = select((_e4083 * 0.25f), (_e4083 * -0.25f), (_e4076 < 0f));
                                    phi_6531_ = 0f;
                                    loop {
                                        let _e4089 = phi_6526_;
                                        let _e4091 = phi_6529_;
                                        let _e4093 = phi_6531_;
                                        local_13 = _e4093;
                                        let _e4094 = (_e4089 < 32u);
                                        if _e4094 {
                                            let _e4095 = (_e4089 + 1u);
                                            let _e4099 = (_e4076 + (f32(bitcast<i32>(_e4095)) * 0.09817477f));
                                            let _e4100 = (_e4099 * 2f);
                                            let _e4105 = ((_e768 + (_e4100 * _e4078)) - cos((_e4100 - _e783)));
                                            let _e4109 = select((_e4105 * 0.25f), (_e4105 * -0.25f), (_e4099 < 0f));
                                            let _e4112 = local_12;
                                            phi_6527_ = _e4095;
                                            phi_6530_ = _e4109;
                                            phi_6532_ = select(_e4093, (_e4093 + (_e4109 - _e4091)), (((_e4112 >> bitcast<u32>((_e4089 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_6527_ = u32();
                                            phi_6530_ = f32();
                                            phi_6532_ = f32();
                                        }
                                        let _e4121 = phi_6527_;
                                        let _e4123 = phi_6530_;
                                        let _e4125 = phi_6532_;
                                        continue;
                                        continuing {
                                            phi_6526_ = _e4121;
                                            phi_6529_ = _e4123;
                                            phi_6531_ = _e4125;
                                            break if !(_e4094);
                                        }
                                    }
                                    let _e4128 = local_13;
                                    phi_8712_ = _e4017;
                                    phi_6633_ = (_e689 + 1f);
                                    phi_6634_ = (_e691 + ((_e749 + ((1f - _e749) * 0.05f)) * _e4128));
                                } else {
                                    if (_e230 == 1u) {
                                        phi_6578_ = 0u;
                                        phi_6581_ = 0f;
                                        loop {
                                            let _e4031 = phi_6578_;
                                            let _e4033 = phi_6581_;
                                            local_11 = _e4033;
                                            let _e4034 = (_e4031 < 4u);
                                            if _e4034 {
                                                local = array<type_40, 4>(type_40(4026531855u, 0.0095061f), type_40(251658480u, 0.0270951f), type_40(15732480u, 0.0405571f), type_40(1044480u, 0.0478421f));
                                                if _e4034 {
                                                } else {
                                                    phi_8707_ = true;
                                                    break;
                                                }
                                                let _e4037 = local[_e4031].member;
                                                let _e4040 = local[_e4031].member_1;
                                                let _e4042 = local_10;
                                                phi_6579_ = (_e4031 + 1u);
                                                phi_6582_ = (_e4033 + (f32(bitcast<i32>(countOneBits((_e4042 & _e4037)))) * _e4040));
                                            } else {
                                                phi_6579_ = u32();
                                                phi_6582_ = f32();
                                            }
                                            let _e4051 = phi_6579_;
                                            let _e4053 = phi_6582_;
                                            continue;
                                            continuing {
                                                phi_6578_ = _e4051;
                                                phi_6581_ = _e4053;
                                                phi_8707_ = _e4017;
                                                break if !(_e4034);
                                            }
                                        }
                                        let _e4056 = phi_8707_;
                                        phi_8710_ = _e4056;
                                        if _e4056 {
                                            break;
                                        }
                                        let _e4058 = local_11;
                                        let _e4059 = (1f - _e4058);
                                        phi_8718_ = _e4056;
                                        phi_6631_ = (_e689 + _e749);
                                        phi_6632_ = (_e691 + (_e749 * select(0f, select(1f, _e4059, (_e4059 < 1f)), (_e4059 > 0f))));
                                    } else {
                                        let _e4021 = local_9;
                                        phi_8718_ = _e4017;
                                        phi_6631_ = (_e689 + 1f);
                                        phi_6632_ = (_e691 + ((f32(bitcast<i32>(countOneBits((_e4021 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e4068 = phi_8718_;
                                    let _e4070 = phi_6631_;
                                    let _e4072 = phi_6632_;
                                    phi_8712_ = _e4068;
                                    phi_6633_ = _e4070;
                                    phi_6634_ = _e4072;
                                }
                                let _e4133 = phi_8712_;
                                let _e4135 = phi_6633_;
                                let _e4137 = phi_6634_;
                                phi_8711_ = _e4133;
                                phi_1028_ = (_e687 + 1u);
                                phi_1031_ = _e4135;
                                phi_1033_ = _e4137;
                            } else {
                                phi_8711_ = _e685;
                                phi_1028_ = u32();
                                phi_1031_ = f32();
                                phi_1033_ = f32();
                            }
                            let _e4140 = phi_8711_;
                            let _e4142 = phi_1028_;
                            let _e4144 = phi_1031_;
                            let _e4146 = phi_1033_;
                            continue;
                            continuing {
                                phi_8399_ = _e4140;
                                phi_1027_ = _e4142;
                                phi_1030_ = _e4144;
                                phi_1032_ = _e4146;
                                phi_8710_ = _e4140;
                                break if !(_e692);
                            }
                        }
                        let _e4149 = phi_8710_;
                        if _e4149 {
                            break;
                        }
                        let _e4151 = local_14;
                        let _e4154 = local_15;
                        let _e4156 = local_16;
                        phi_6642_ = select(1f, (_e4154 / _e4156), (_e4151 > 0f));
                    } else {
                        phi_6642_ = 1f;
                    }
                    let _e4160 = phi_6642_;
                    if (_e225.member_6 == 2f) {
                        phi_6655_ = (_e4160 * _e4160);
                    } else {
                        if (_e225.member_6 == 1f) {
                            phi_6654_ = _e4160;
                        } else {
                            phi_6654_ = pow(_e4160, _e225.member_6);
                        }
                        let _e4166 = phi_6654_;
                        phi_6655_ = _e4166;
                    }
                    let _e4169 = phi_6655_;
                    let _e4174 = (select(1f, select(0.03f, _e4169, ((_e4169 > 0.03f) || false)), _e680) * 0.6666667f);
                    terms.member[_e267] = (bitcast<u32>((floor(((select(0f, select(1f, _e4174, (_e4174 < 1f)), (_e4174 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
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
