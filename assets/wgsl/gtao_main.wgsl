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
    var phi_195_: type_20;
    var phi_722_: f32;
    var phi_748_: u32;
    var phi_751_: vec3<f32>;
    var phi_753_: f32;
    var phi_923_: u32;
    var phi_926_: f32;
    var phi_928_: f32;
    var phi_981_: f32;
    var phi_1411_: f32;
    var phi_1432_: f32;
    var phi_1471_: f32;
    var phi_1492_: f32;
    var phi_924_: u32;
    var phi_927_: f32;
    var phi_929_: f32;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_1722_: vec3<f32>;
    var phi_749_: u32;
    var phi_752_: vec3<f32>;
    var phi_754_: f32;
    var local_4: f32;
    var local_5: vec3<f32>;
    var phi_1729_: type_24;
    var phi_2445_: bool;
    var phi_1779_: vec3<f32>;
    var phi_1800_: u32;
    var phi_1840_: u32;
    var phi_1841_: u32;

    let _e97 = id_1;
    if (override_type == 0u) {
        let _e100 = params.member;
        phi_195_ = _e100;
    } else {
        let _e109 = params.member.member;
        let _e112 = params.member.member_1;
        let _e115 = params.member.member_10;
        let _e118 = params.member.member_11;
        let _e121 = params.member.member_12;
        let _e124 = params.member.member_14;
        phi_195_ = type_20(_e109, _e112, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e115, _e118, _e121, override_type_9, _e124);
    }
    let _e127 = phi_195_;
    let _e135 = select(select(u32(_e127.member.member.x), 0u, (_e127.member.member.x < 0f)), 4294967295u, (_e127.member.member.x > 4294967000f));
    let _e143 = select(select(u32(_e127.member.member.y), 0u, (_e127.member.member.y < 0f)), 4294967295u, (_e127.member.member.y > 4294967000f));
    if (_e97.x >= _e135) {
    } else {
        if (_e97.y >= _e143) {
        } else {
            let _e149 = ((_e97.y * _e135) + _e97.x);
            let _e152 = mips.member[_e149];
            let _e153 = bitcast<i32>(_e97.x);
            let _e154 = (_e153 + -1i);
            let _e156 = select(0i, _e154, (0i < _e154));
            let _e158 = (bitcast<i32>(_e135) - 1i);
            let _e162 = bitcast<i32>(_e97.y);
            let _e164 = select(0i, _e162, (0i < _e162));
            let _e166 = (bitcast<i32>(_e143) - 1i);
            let _e170 = (bitcast<u32>(select(_e164, _e166, (_e166 < _e164))) * _e135);
            let _e174 = mips.member[(_e170 + bitcast<u32>(select(_e156, _e158, (_e158 < _e156))))];
            let _e175 = (_e153 + 1i);
            let _e177 = select(0i, _e175, (0i < _e175));
            let _e184 = mips.member[(_e170 + bitcast<u32>(select(_e177, _e158, (_e158 < _e177))))];
            let _e186 = select(0i, _e153, (0i < _e153));
            let _e189 = bitcast<u32>(select(_e186, _e158, (_e158 < _e186)));
            let _e190 = (_e162 + -1i);
            let _e192 = select(0i, _e190, (0i < _e190));
            let _e200 = mips.member[((bitcast<u32>(select(_e192, _e166, (_e166 < _e192))) * _e135) + _e189)];
            let _e201 = (_e162 + 1i);
            let _e203 = select(0i, _e201, (0i < _e201));
            let _e211 = mips.member[((bitcast<u32>(select(_e203, _e166, (_e166 < _e203))) * _e135) + _e189)];
            let _e212 = (_e174 - _e152);
            let _e213 = (_e184 - _e152);
            let _e214 = (_e200 - _e152);
            let _e215 = (_e211 - _e152);
            let _e217 = ((_e213 - _e212) * 0.5f);
            let _e219 = ((_e215 - _e214) * 0.5f);
            let _e220 = (_e152 * 0.011f);
            let _e222 = abs(_e212);
            let _e223 = abs((_e212 + _e217));
            let _e229 = (1.25f - (select(_e223, _e222, ((_e222 < _e223) || (_e223 != _e223))) / _e220));
            let _e231 = select(0f, _e229, (_e229 > 0f));
            let _e233 = select(1f, _e231, (_e231 < 1f));
            let _e235 = abs(_e213);
            let _e236 = abs((_e213 - _e217));
            let _e242 = (1.25f - (select(_e236, _e235, ((_e235 < _e236) || (_e236 != _e236))) / _e220));
            let _e244 = select(0f, _e242, (_e242 > 0f));
            let _e246 = select(1f, _e244, (_e244 < 1f));
            let _e248 = abs(_e214);
            let _e249 = abs((_e214 + _e219));
            let _e255 = (1.25f - (select(_e249, _e248, ((_e248 < _e249) || (_e249 != _e249))) / _e220));
            let _e257 = select(0f, _e255, (_e255 > 0f));
            let _e259 = select(1f, _e257, (_e257 < 1f));
            let _e261 = abs(_e215);
            let _e262 = abs((_e215 - _e219));
            let _e268 = (1.25f - (select(_e262, _e261, ((_e261 < _e262) || (_e262 != _e262))) / _e220));
            let _e270 = select(0f, _e268, (_e268 > 0f));
            let _e272 = select(1f, _e270, (_e270 < 1f));
            let _e274 = select(0f, _e233, (_e233 > 0f));
            let _e278 = round((select(1f, _e274, (_e274 < 1f)) * 2.9f));
            let _e280 = select(0f, _e278, (_e278 > 0f));
            let _e289 = select(0f, _e246, (_e246 > 0f));
            let _e293 = round((select(1f, _e289, (_e289 < 1f)) * 2.9f));
            let _e295 = select(0f, _e293, (_e293 > 0f));
            let _e305 = select(0f, _e259, (_e259 > 0f));
            let _e309 = round((select(1f, _e305, (_e305 < 1f)) * 2.9f));
            let _e311 = select(0f, _e309, (_e309 > 0f));
            let _e321 = select(0f, _e272, (_e272 > 0f));
            let _e325 = round((select(1f, _e321, (_e321 < 1f)) * 2.9f));
            let _e327 = select(0f, _e325, (_e325 > 0f));
            let _e337 = ((f32(_e153) + 0.5f) / _e127.member.member.x);
            let _e340 = ((f32(_e162) + 0.5f) / _e127.member.member.y);
            let _e341 = (_e152 * 0.99999f);
            let _e348 = ((((_e337 * 2f) - 1f) * _e127.member.member_1.x) * _e341);
            let _e355 = ((((_e340 * -2f) + 1f) * _e127.member.member_1.y) * _e341);
            let _e356 = -(_e348);
            let _e357 = -(_e355);
            let _e358 = (_e152 * -0.99999f);
            let _e365 = (1f / sqrt((((_e356 * _e356) + (_e357 * _e357)) + (_e358 * _e358))));
            let _e366 = (_e356 * _e365);
            let _e367 = (_e357 * _e365);
            let _e368 = (_e358 * _e365);
            let _e371 = normals.member[_e149];
            let _e374 = f32(bitcast<i32>((_e371 & 255u)));
            let _e378 = (select(_e374, (_e374 - 256f), (_e374 >= 128f)) * 0.007874016f);
            let _e381 = select(-1f, _e378, ((_e378 > -1f) || false));
            let _e386 = f32(bitcast<i32>(((_e371 >> bitcast<u32>(8u)) & 255u)));
            let _e390 = (select(_e386, (_e386 - 256f), (_e386 >= 128f)) * 0.007874016f);
            let _e393 = select(-1f, _e390, ((_e390 > -1f) || false));
            let _e395 = (1f - abs(_e381));
            let _e396 = abs(_e393);
            let _e397 = (_e395 - _e396);
            let _e398 = (_e397 < 0f);
            let _e406 = select(_e381, ((1f - _e396) * select(1f, -1f, (_e381 < 0f))), _e398);
            let _e407 = select(_e393, (_e395 * select(1f, -1f, (_e393 < 0f))), _e398);
            let _e414 = (1f / sqrt((((_e406 * _e406) + (_e407 * _e407)) + (_e397 * _e397))));
            let _e415 = (_e406 * _e414);
            let _e416 = (_e407 * _e414);
            let _e417 = (_e397 * _e414);
            let _e418 = -(_e417);
            let _e424 = ((((_e415 * _e366) + (_e416 * _e367)) + (_e418 * _e368)) < 0f);
            let _e427 = select(_e415, -(_e415), _e424);
            let _e428 = select(_e416, -(_e416), _e424);
            let _e429 = select(_e418, _e417, _e424);
            let _e433 = (_e127.member_1 * _e127.member_2);
            let _e437 = (_e433 / (((_e152 * 1.99998f) * _e127.member.member_1.x) / _e127.member.member.x));
            let _e440 = (_e97.x & 63u);
            let _e441 = (_e97.y & 63u);
            let _e444 = select(0u, 1u, ((_e440 & 32u) != 0u));
            let _e447 = select(0u, 1u, ((_e441 & 32u) != 0u));
            let _e451 = (_e447 == 0u);
            let _e453 = (_e451 && (_e444 == 1u));
            let _e456 = select(_e440, (63u - _e440), _e453);
            let _e457 = select(_e441, (63u - _e441), _e453);
            let _e458 = select(_e456, _e457, _e451);
            let _e459 = select(_e457, _e456, _e451);
            let _e462 = select(0u, 1u, ((_e458 & 16u) != 0u));
            let _e465 = select(0u, 1u, ((_e459 & 16u) != 0u));
            let _e470 = (_e465 == 0u);
            let _e472 = (_e470 && (_e462 == 1u));
            let _e475 = select(_e458, (63u - _e458), _e472);
            let _e476 = select(_e459, (63u - _e459), _e472);
            let _e477 = select(_e475, _e476, _e470);
            let _e478 = select(_e476, _e475, _e470);
            let _e481 = select(0u, 1u, ((_e477 & 8u) != 0u));
            let _e484 = select(0u, 1u, ((_e478 & 8u) != 0u));
            let _e489 = (_e484 == 0u);
            let _e491 = (_e489 && (_e481 == 1u));
            let _e494 = select(_e477, (63u - _e477), _e491);
            let _e495 = select(_e478, (63u - _e478), _e491);
            let _e496 = select(_e494, _e495, _e489);
            let _e497 = select(_e495, _e494, _e489);
            let _e500 = select(0u, 1u, ((_e496 & 4u) != 0u));
            let _e503 = select(0u, 1u, ((_e497 & 4u) != 0u));
            let _e508 = (_e503 == 0u);
            let _e510 = (_e508 && (_e500 == 1u));
            let _e513 = select(_e496, (63u - _e496), _e510);
            let _e514 = select(_e497, (63u - _e497), _e510);
            let _e515 = select(_e513, _e514, _e508);
            let _e516 = select(_e514, _e513, _e508);
            let _e519 = select(0u, 1u, ((_e515 & 2u) != 0u));
            let _e522 = select(0u, 1u, ((_e516 & 2u) != 0u));
            let _e527 = (_e522 == 0u);
            let _e529 = (_e527 && (_e519 == 1u));
            let _e532 = select(_e515, (63u - _e515), _e529);
            let _e533 = select(_e516, (63u - _e516), _e529);
            let _e549 = f32(bitcast<i32>((((((((1024u * ((3u * _e444) ^ _e447)) + (256u * ((3u * _e462) ^ _e465))) + (64u * ((3u * _e481) ^ _e484))) + (16u * ((3u * _e500) ^ _e503))) + (4u * ((3u * _e519) ^ _e522))) + ((3u * select(0u, 1u, ((select(_e532, _e533, _e527) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e533, _e532, _e527) & 1u) != 0u)))) + (288u * (_e127.member_11 % 64u)))));
            let _e551 = (0.5f + (_e549 * 0.7548777f));
            let _e555 = (0.5f + (_e549 * 0.5698403f));
            let _e562 = select(false, (_e152 < _e127.member.member_3), (_e152 > 0f));
            if _e562 {
                let _e564 = (_e127.member_3 * _e433);
                let _e565 = (_e564 <= 0f);
                if _e565 {
                    phi_722_ = 0f;
                } else {
                    phi_722_ = (1f / _e564);
                }
                let _e568 = phi_722_;
                let _e569 = -(_e568);
                let _e570 = (_e433 * _e568);
                let _e572 = ((10f - _e437) * 0.01f);
                let _e574 = select(0f, _e572, (_e572 > 0f));
                let _e580 = select(1u, _e127.member_8, (1u < _e127.member_8));
                phi_748_ = 0u;
                phi_751_ = vec3<f32>(0f, 0f, 0f);
                phi_753_ = (select(1f, _e574, (_e574 < 1f)) * 0.5f);
                loop {
                    let _e582 = phi_748_;
                    let _e584 = phi_751_;
                    let _e586 = phi_753_;
                    local_4 = _e586;
                    local_5 = _e584;
                    let _e587 = (_e582 < _e580);
                    if _e587 {
                        let _e594 = ((((_e551 - floor(_e551)) + f32(bitcast<i32>(_e582))) * 3.1415927f) / f32(bitcast<i32>(_e580)));
                        let _e595 = sin(_e594);
                        let _e596 = cos(_e594);
                        let _e602 = ((_e596 * _e366) + (_e595 * _e367));
                        let _e606 = (_e596 - (_e366 * _e602));
                        let _e607 = (_e595 - (_e367 * _e602));
                        let _e608 = -((_e368 * _e602));
                        let _e611 = ((_e607 * _e368) - (_e367 * _e608));
                        let _e614 = ((_e608 * _e366) - (_e368 * _e606));
                        let _e617 = ((_e606 * _e367) - (_e366 * _e607));
                        let _e624 = (1f / sqrt((((_e611 * _e611) + (_e614 * _e614)) + (_e617 * _e617))));
                        let _e625 = (_e611 * _e624);
                        let _e626 = (_e614 * _e624);
                        let _e627 = (_e617 * _e624);
                        let _e632 = (((_e427 * _e625) + (_e428 * _e626)) + (_e429 * _e627));
                        let _e636 = (_e427 - (_e625 * _e632));
                        let _e637 = (_e428 - (_e626 * _e632));
                        let _e638 = (_e429 - (_e627 * _e632));
                        let _e644 = sqrt((((_e636 * _e636) + (_e637 * _e637)) + (_e638 * _e638)));
                        let _e649 = (((_e606 * _e636) + (_e607 * _e637)) + (_e608 * _e638));
                        let _e659 = ((((_e636 * _e366) + (_e637 * _e367)) + (_e638 * _e368)) / _e644);
                        let _e661 = select(0f, _e659, (_e659 > 0f));
                        let _e663 = select(1f, _e661, (_e661 < 1f));
                        let _e664 = abs(_e663);
                        let _e675 = (((_e664 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e664))) >> bitcast<u32>(1i))))));
                        let _e679 = (select(select(0f, -1f, (_e649 < 0f)), 1f, (_e649 > 0f)) * select((3.141593f - _e675), _e675, (_e663 >= 0f)));
                        let _e682 = select(1u, _e127.member_9, (1u < _e127.member_9));
                        let _e684 = cos((_e679 + 1.5707964f));
                        let _e686 = cos((_e679 - 1.5707964f));
                        phi_923_ = 0u;
                        phi_926_ = _e686;
                        phi_928_ = _e684;
                        loop {
                            let _e689 = phi_923_;
                            let _e691 = phi_926_;
                            let _e693 = phi_928_;
                            local = _e691;
                            local_1 = _e691;
                            local_2 = _e693;
                            local_3 = _e693;
                            let _e694 = (_e689 < _e682);
                            if _e694 {
                                let _e700 = ((_e555 - floor(_e555)) + (f32(bitcast<i32>((_e582 + (_e689 * _e682)))) * 0.618034f));
                                let _e709 = (((_e700 - floor(_e700)) + f32(bitcast<i32>(_e689))) * (1f / f32(bitcast<i32>(_e682))));
                                if (_e127.member_4 == 2f) {
                                    phi_981_ = (_e709 * _e709);
                                } else {
                                    phi_981_ = pow(_e709, _e127.member_4);
                                }
                                let _e715 = phi_981_;
                                let _e716 = (_e715 + (1.3f / _e437));
                                let _e717 = ((_e596 * _e437) * _e716);
                                let _e718 = ((-(_e595) * _e437) * _e716);
                                let _e725 = (log2(sqrt(((_e717 * _e717) + (_e718 * _e718)))) - _e127.member_7);
                                let _e727 = select(0f, _e725, (_e725 > 0f));
                                let _e732 = (-1f - floor((-0.5f - select(5f, _e727, (_e727 < 5f)))));
                                let _e735 = (round(_e717) * (1f / _e127.member.member.x));
                                let _e738 = (round(_e718) * (1f / _e127.member.member.y));
                                let _e739 = (_e337 + _e735);
                                let _e740 = (_e340 + _e738);
                                let _e741 = (_e337 - _e735);
                                let _e742 = (_e340 - _e738);
                                let _e744 = select(0f, _e732, (_e732 > 0f));
                                let _e751 = ((bitcast<u32>((floor(select(4f, _e744, (_e744 < 4f))) + 8388608f)) - 1258291200u) & 31u);
                                let _e753 = (_e135 >> bitcast<u32>(_e751));
                                let _e755 = select(1u, _e753, (1u < _e753));
                                let _e757 = (_e143 >> bitcast<u32>(_e751));
                                let _e759 = select(1u, _e757, (1u < _e757));
                                let _e764 = (select(1u, _e135, (1u < _e135)) * select(1u, _e143, (1u < _e143)));
                                let _e768 = (_e135 >> bitcast<u32>(1u));
                                let _e772 = (_e143 >> bitcast<u32>(1u));
                                let _e776 = (_e764 + (select(1u, _e768, (1u < _e768)) * select(1u, _e772, (1u < _e772))));
                                let _e780 = (_e135 >> bitcast<u32>(2u));
                                let _e784 = (_e143 >> bitcast<u32>(2u));
                                let _e788 = (_e776 + (select(1u, _e780, (1u < _e780)) * select(1u, _e784, (1u < _e784))));
                                let _e792 = (_e135 >> bitcast<u32>(3u));
                                let _e796 = (_e143 >> bitcast<u32>(3u));
                                let _e802 = select(select(select(select(0u, _e764, (_e732 >= 1f)), _e776, (_e732 >= 2f)), _e788, (_e732 >= 3f)), (_e788 + (select(1u, _e792, (1u < _e792)) * select(1u, _e796, (1u < _e796)))), (_e732 >= 4f));
                                let _e804 = f32(bitcast<i32>(_e755));
                                let _e805 = (_e739 * _e804);
                                let _e808 = f32(bitcast<i32>((_e755 - 1u)));
                                let _e810 = select(0f, _e805, (_e805 > 0f));
                                let _e818 = f32(bitcast<i32>(_e759));
                                let _e819 = (_e740 * _e818);
                                let _e822 = f32(bitcast<i32>((_e759 - 1u)));
                                let _e824 = select(0f, _e819, (_e819 > 0f));
                                let _e836 = mips.member[((_e802 + ((bitcast<u32>((floor(select(_e822, _e824, (_e824 < _e822))) + 8388608f)) - 1258291200u) * _e755)) + (bitcast<u32>((floor(select(_e808, _e810, (_e810 < _e808))) + 8388608f)) - 1258291200u))];
                                let _e845 = (_e741 * _e804);
                                let _e847 = select(0f, _e845, (_e845 > 0f));
                                let _e854 = (_e742 * _e818);
                                let _e856 = select(0f, _e854, (_e854 > 0f));
                                let _e868 = mips.member[((_e802 + ((bitcast<u32>((floor(select(_e822, _e856, (_e856 < _e822))) + 8388608f)) - 1258291200u) * _e755)) + (bitcast<u32>((floor(select(_e808, _e847, (_e847 < _e808))) + 8388608f)) - 1258291200u))];
                                let _e877 = (((((_e739 * 2f) - 1f) * _e127.member.member_1.x) * _e836) - _e348);
                                let _e878 = (((((_e740 * -2f) + 1f) * _e127.member.member_1.y) * _e836) - _e355);
                                let _e879 = (_e836 - _e341);
                                let _e882 = ((_e877 * _e877) + (_e878 * _e878));
                                let _e885 = sqrt((_e882 + (_e879 * _e879)));
                                let _e892 = (_e127.member_5 == 0f);
                                if _e892 {
                                    phi_1411_ = _e885;
                                } else {
                                    let _e894 = (_e879 * (1f + _e127.member_5));
                                    phi_1411_ = sqrt((_e882 + (_e894 * _e894)));
                                }
                                let _e899 = phi_1411_;
                                if _e565 {
                                    phi_1432_ = select(0f, 1f, (_e899 <= _e433));
                                } else {
                                    let _e903 = ((_e899 * _e569) + _e570);
                                    let _e905 = select(0f, _e903, (_e903 > 0f));
                                    phi_1432_ = select(1f, _e905, (_e905 < 1f));
                                }
                                let _e909 = phi_1432_;
                                let _e912 = (_e684 + ((((((_e877 * _e366) + (_e878 * _e367)) + (_e879 * _e368)) / _e885) - _e684) * _e909));
                                let _e913 = (((((_e741 * 2f) - 1f) * _e127.member.member_1.x) * _e868) - _e348);
                                let _e914 = (((((_e742 * -2f) + 1f) * _e127.member.member_1.y) * _e868) - _e355);
                                let _e915 = (_e868 - _e341);
                                let _e918 = ((_e913 * _e913) + (_e914 * _e914));
                                let _e921 = sqrt((_e918 + (_e915 * _e915)));
                                if _e892 {
                                    phi_1471_ = _e921;
                                } else {
                                    let _e929 = (_e915 * (1f + _e127.member_5));
                                    phi_1471_ = sqrt((_e918 + (_e929 * _e929)));
                                }
                                let _e934 = phi_1471_;
                                if _e565 {
                                    phi_1492_ = select(0f, 1f, (_e934 <= _e433));
                                } else {
                                    let _e938 = ((_e934 * _e569) + _e570);
                                    let _e940 = select(0f, _e938, (_e938 > 0f));
                                    phi_1492_ = select(1f, _e940, (_e940 < 1f));
                                }
                                let _e944 = phi_1492_;
                                let _e947 = (_e686 + ((((((_e913 * _e366) + (_e914 * _e367)) + (_e915 * _e368)) / _e921) - _e686) * _e944));
                                phi_924_ = (_e689 + 1u);
                                phi_927_ = select(_e947, _e691, ((_e691 > _e947) || (_e947 != _e947)));
                                phi_929_ = select(_e912, _e693, ((_e693 > _e912) || (_e912 != _e912)));
                            } else {
                                phi_924_ = u32();
                                phi_927_ = f32();
                                phi_929_ = f32();
                            }
                            let _e958 = phi_924_;
                            let _e960 = phi_927_;
                            let _e962 = phi_929_;
                            continue;
                            continuing {
                                phi_923_ = _e958;
                                phi_926_ = _e960;
                                phi_928_ = _e962;
                                break if !(_e694);
                            }
                        }
                        let _e965 = local;
                        let _e966 = abs(_e965);
                        let _e977 = (((_e966 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e966))) >> bitcast<u32>(1i))))));
                        let _e979 = local_1;
                        let _e982 = select((3.141593f - _e977), _e977, (_e979 >= 0f));
                        let _e983 = -(_e982);
                        let _e985 = local_2;
                        let _e986 = abs(_e985);
                        let _e997 = (((_e986 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e986))) >> bitcast<u32>(1i))))));
                        let _e999 = local_3;
                        let _e1002 = select((3.141593f - _e997), _e997, (_e999 >= 0f));
                        let _e1005 = (_e644 + ((1f - _e644) * 0.05f));
                        let _e1006 = (_e982 * -2f);
                        let _e1007 = sin(_e679);
                        let _e1013 = (_e1002 * 2f);
                        if (_e127.member_13 == 0u) {
                            phi_1722_ = _e584;
                        } else {
                            let _e1029 = ((_e982 * -3f) - _e679);
                            let _e1037 = ((_e1002 * 3f) - _e679);
                            let _e1042 = (_e983 + _e679);
                            let _e1044 = (_e1002 + _e679);
                            let _e1049 = (((((((sin((_e983 - _e679)) * 6f) - sin(_e1029)) + (sin((_e1002 - _e679)) * 6f)) - sin(_e1037)) + (_e1007 * 16f)) - ((sin(_e1042) + sin(_e1044)) * 3f)) * 0.083333336f);
                            let _e1061 = (((-(cos(_e1029)) - cos(_e1037)) + (cos(_e679) * 8f)) - ((cos(_e1042) + cos(_e1044)) * 3f));
                            let _e1062 = (_e596 * _e1049);
                            let _e1063 = (_e595 * _e1049);
                            let _e1064 = (_e1061 * -0.083333336f);
                            let _e1065 = (-1f * _e368);
                            let _e1066 = (-1f * _e366);
                            let _e1068 = (1f / (_e1065 + 1f));
                            let _e1069 = (_e1068 * _e367);
                            let _e1073 = (_e1069 * _e1066);
                            let _e1094 = (_e1065 > 0.9997f);
                            let _e1095 = (_e1065 < -0.9997f);
                            phi_1722_ = (_e584 + vec3<f32>((select(select(((((_e1065 + (_e1069 * _e367)) * _e1062) + (_e1073 * _e1063)) + (_e1066 * _e1064)), _e1062, _e1095), _e1062, _e1094) * _e1005), (select(select((((_e1073 * _e1062) + ((_e1065 + ((_e1068 * _e1066) * _e1066)) * _e1063)) + (-(_e367) * _e1064)), -(_e1063), _e1095), _e1063, _e1094) * _e1005), (select(select((((_e366 * _e1062) + (_e367 * _e1063)) + (_e1065 * _e1064)), (_e1061 * 0.083333336f), _e1095), _e1064, _e1094) * _e1005)));
                        }
                        let _e1108 = phi_1722_;
                        phi_749_ = (_e582 + 1u);
                        phi_752_ = _e1108;
                        phi_754_ = (_e586 + ((0.25f * (((_e663 + (_e1006 * _e1007)) - cos((_e1006 - _e679))) + ((_e663 + (_e1013 * _e1007)) - cos((_e1013 - _e679))))) * _e1005));
                    } else {
                        phi_749_ = u32();
                        phi_752_ = vec3<f32>();
                        phi_754_ = f32();
                    }
                    let _e1111 = phi_749_;
                    let _e1113 = phi_752_;
                    let _e1115 = phi_754_;
                    continue;
                    continuing {
                        phi_748_ = _e1111;
                        phi_751_ = _e1113;
                        phi_753_ = _e1115;
                        break if !(_e587);
                    }
                }
                let _e1120 = local_4;
                let _e1123 = local_5;
                phi_1729_ = type_24((_e1120 / f32(bitcast<i32>(_e580))), _e1123);
            } else {
                phi_1729_ = type_24(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1126 = phi_1729_;
            if _e562 {
                let _e1130 = pow(_e1126.member, _e127.member_6);
                if (_e1130 != _e1130) {
                    phi_2445_ = true;
                } else {
                    phi_2445_ = (0.03f >= _e1130);
                }
                let _e1134 = phi_2445_;
                let _e1135 = select(_e1130, 0.03f, _e1134);
                if (_e127.member_13 == 0u) {
                    let _e1138 = (_e1135 * 0.6666667f);
                    let _e1140 = select(0f, _e1138, (_e1138 > 0f));
                    phi_1800_ = (bitcast<u32>((floor(((select(1f, _e1140, (_e1140 < 1f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                } else {
                    let _e1157 = sqrt((((_e1126.member_1.x * _e1126.member_1.x) + (_e1126.member_1.y * _e1126.member_1.y)) + (_e1126.member_1.z * _e1126.member_1.z)));
                    if (_e1157 > 0f) {
                        phi_1779_ = (_e1126.member_1 / vec3(_e1157));
                    } else {
                        phi_1779_ = vec3<f32>(_e427, _e428, _e429);
                    }
                    let _e1162 = phi_1779_;
                    let _e1163 = (_e1135 * 0.6666667f);
                    let _e1170 = ((_e1162.x * 0.5f) + 0.5f);
                    let _e1171 = ((_e1162.y * 0.5f) + 0.5f);
                    let _e1172 = ((_e1162.z * 0.5f) + 0.5f);
                    let _e1174 = select(0f, _e1170, (_e1170 > 0f));
                    let _e1184 = select(0f, _e1171, (_e1171 > 0f));
                    let _e1197 = select(0f, _e1172, (_e1172 > 0f));
                    let _e1210 = select(0f, _e1163, (_e1163 > 0f));
                    phi_1800_ = ((((bitcast<u32>((floor(((select(1f, _e1174, (_e1174 < 1f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) | ((bitcast<u32>((floor(((select(1f, _e1184, (_e1184 < 1f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(8i))) | ((bitcast<u32>((floor(((select(1f, _e1197, (_e1197 < 1f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(((select(1f, _e1210, (_e1210 < 1f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1223 = phi_1800_;
                phi_1841_ = _e1223;
            } else {
                if (_e127.member_13 == 0u) {
                    phi_1840_ = (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u);
                } else {
                    let _e1233 = (bitcast<u32>((floor(128f) + 8388608f)) - 1258291200u);
                    phi_1840_ = (((_e1233 | (_e1233 << bitcast<u32>(8i))) | ((bitcast<u32>((floor(0.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1252 = phi_1840_;
                phi_1841_ = _e1252;
            }
            let _e1254 = phi_1841_;
            terms.member[_e149] = _e1254;
            edges.member[_e149] = ((((64u * (bitcast<u32>((floor(select(3f, _e280, (_e280 < 3f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(3f, _e295, (_e295 < 3f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(3f, _e311, (_e311 < 3f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(3f, _e327, (_e327 < 3f))) + 8388608f)) - 1258291200u));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
