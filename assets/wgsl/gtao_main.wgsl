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
    var phi_2297_: bool;
    var phi_2312_: bool;
    var phi_2272_: vec2<f32>;
    var phi_737_: f32;
    var phi_763_: u32;
    var phi_766_: vec3<f32>;
    var phi_768_: f32;
    var phi_938_: u32;
    var phi_941_: f32;
    var phi_943_: f32;
    var phi_996_: f32;
    var phi_1426_: f32;
    var phi_1447_: f32;
    var phi_1486_: f32;
    var phi_1507_: f32;
    var phi_939_: u32;
    var phi_942_: f32;
    var phi_944_: f32;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_1737_: vec3<f32>;
    var phi_764_: u32;
    var phi_767_: vec3<f32>;
    var phi_769_: f32;
    var local_4: f32;
    var local_5: vec3<f32>;
    var phi_1744_: type_24;
    var phi_2542_: bool;
    var phi_1794_: vec3<f32>;
    var phi_1815_: u32;
    var phi_1855_: u32;
    var phi_1856_: u32;

    let _e96 = id_1;
    if (override_type == 0u) {
        let _e99 = params.member;
        phi_281_ = _e99;
    } else {
        let _e108 = params.member.member;
        let _e111 = params.member.member_1;
        let _e114 = params.member.member_10;
        let _e117 = params.member.member_11;
        let _e120 = params.member.member_12;
        let _e123 = params.member.member_14;
        phi_281_ = type_20(_e108, _e111, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e114, _e117, _e120, override_type_9, _e123);
    }
    let _e126 = phi_281_;
    let _e134 = select(select(u32(_e126.member.member.x), 0u, (_e126.member.member.x < 0f)), 4294967295u, (_e126.member.member.x > 4294967000f));
    let _e142 = select(select(u32(_e126.member.member.y), 0u, (_e126.member.member.y < 0f)), 4294967295u, (_e126.member.member.y > 4294967000f));
    if (_e96.x >= _e134) {
    } else {
        if (_e96.y >= _e142) {
        } else {
            let _e148 = ((_e96.y * _e134) + _e96.x);
            let _e151 = mips.member[_e148];
            let _e152 = bitcast<i32>(_e96.x);
            let _e153 = (_e152 + -1i);
            let _e155 = select(0i, _e153, (0i < _e153));
            let _e157 = (bitcast<i32>(_e134) - 1i);
            let _e161 = bitcast<i32>(_e96.y);
            let _e163 = select(0i, _e161, (0i < _e161));
            let _e165 = (bitcast<i32>(_e142) - 1i);
            let _e169 = (bitcast<u32>(select(_e163, _e165, (_e165 < _e163))) * _e134);
            let _e173 = mips.member[(_e169 + bitcast<u32>(select(_e155, _e157, (_e157 < _e155))))];
            let _e174 = (_e152 + 1i);
            let _e176 = select(0i, _e174, (0i < _e174));
            let _e183 = mips.member[(_e169 + bitcast<u32>(select(_e176, _e157, (_e157 < _e176))))];
            let _e185 = select(0i, _e152, (0i < _e152));
            let _e188 = bitcast<u32>(select(_e185, _e157, (_e157 < _e185)));
            let _e189 = (_e161 + -1i);
            let _e191 = select(0i, _e189, (0i < _e189));
            let _e199 = mips.member[((bitcast<u32>(select(_e191, _e165, (_e165 < _e191))) * _e134) + _e188)];
            let _e200 = (_e161 + 1i);
            let _e202 = select(0i, _e200, (0i < _e200));
            let _e210 = mips.member[((bitcast<u32>(select(_e202, _e165, (_e165 < _e202))) * _e134) + _e188)];
            let _e211 = (_e173 - _e151);
            let _e212 = (_e183 - _e151);
            let _e213 = (_e199 - _e151);
            let _e214 = (_e210 - _e151);
            let _e216 = ((_e212 - _e211) * 0.5f);
            let _e218 = ((_e214 - _e213) * 0.5f);
            let _e219 = (_e151 * 0.011f);
            let _e221 = abs(_e211);
            let _e222 = abs((_e211 + _e216));
            let _e228 = (1.25f - (select(_e222, _e221, ((_e221 < _e222) || (_e222 != _e222))) / _e219));
            let _e232 = select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f));
            let _e234 = abs(_e212);
            let _e235 = abs((_e212 - _e216));
            let _e241 = (1.25f - (select(_e235, _e234, ((_e234 < _e235) || (_e235 != _e235))) / _e219));
            let _e245 = select(0f, select(1f, _e241, (_e241 < 1f)), (_e241 > 0f));
            let _e247 = abs(_e213);
            let _e248 = abs((_e213 + _e218));
            let _e254 = (1.25f - (select(_e248, _e247, ((_e247 < _e248) || (_e248 != _e248))) / _e219));
            let _e258 = select(0f, select(1f, _e254, (_e254 < 1f)), (_e254 > 0f));
            let _e260 = abs(_e214);
            let _e261 = abs((_e214 - _e218));
            let _e267 = (1.25f - (select(_e261, _e260, ((_e260 < _e261) || (_e261 != _e261))) / _e219));
            let _e271 = select(0f, select(1f, _e267, (_e267 < 1f)), (_e267 > 0f));
            let _e277 = round((select(0f, select(1f, _e232, (_e232 < 1f)), (_e232 > 0f)) * 2.9f));
            let _e279 = select(0f, _e277, (_e277 > 0f));
            let _e292 = round((select(0f, select(1f, _e245, (_e245 < 1f)), (_e245 > 0f)) * 2.9f));
            let _e294 = select(0f, _e292, (_e292 > 0f));
            let _e308 = round((select(0f, select(1f, _e258, (_e258 < 1f)), (_e258 > 0f)) * 2.9f));
            let _e310 = select(0f, _e308, (_e308 > 0f));
            let _e324 = round((select(0f, select(1f, _e271, (_e271 < 1f)), (_e271 > 0f)) * 2.9f));
            let _e326 = select(0f, _e324, (_e324 > 0f));
            let _e336 = ((f32(_e152) + 0.5f) / _e126.member.member.x);
            let _e339 = ((f32(_e161) + 0.5f) / _e126.member.member.y);
            let _e340 = (_e151 * 0.99999f);
            let _e347 = ((((_e336 * 2f) - 1f) * _e126.member.member_1.x) * _e340);
            let _e354 = ((((_e339 * -2f) + 1f) * _e126.member.member_1.y) * _e340);
            let _e355 = -(_e347);
            let _e356 = -(_e354);
            let _e357 = (_e151 * -0.99999f);
            let _e364 = (1f / sqrt((((_e355 * _e355) + (_e356 * _e356)) + (_e357 * _e357))));
            let _e365 = (_e355 * _e364);
            let _e366 = (_e356 * _e364);
            let _e367 = (_e357 * _e364);
            let _e370 = normals.member[_e148];
            let _e378 = (f32((bitcast<i32>(((_e370 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e378 != _e378) {
                phi_2297_ = true;
            } else {
                phi_2297_ = (-1f >= _e378);
            }
            let _e382 = phi_2297_;
            let _e383 = select(_e378, -1f, _e382);
            let _e393 = (f32((bitcast<i32>((((_e370 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e393 != _e393) {
                phi_2312_ = true;
            } else {
                phi_2312_ = (-1f >= _e393);
            }
            let _e397 = phi_2312_;
            let _e398 = select(_e393, -1f, _e397);
            let _e401 = (1f - abs(_e383));
            let _e402 = abs(_e398);
            let _e403 = (_e401 - _e402);
            if (_e403 < 0f) {
                phi_2272_ = vec2<f32>(((1f - _e402) * select(1f, -1f, (_e383 < 0f))), (_e401 * select(1f, -1f, (_e398 < 0f))));
            } else {
                phi_2272_ = vec2<f32>(_e383, _e398);
            }
            let _e414 = phi_2272_;
            let _e423 = (1f / sqrt((((_e414.x * _e414.x) + (_e414.y * _e414.y)) + (_e403 * _e403))));
            let _e424 = (_e414.x * _e423);
            let _e425 = (_e414.y * _e423);
            let _e426 = (_e403 * _e423);
            let _e427 = -(_e426);
            let _e433 = ((((_e424 * _e365) + (_e425 * _e366)) + (_e427 * _e367)) < 0f);
            let _e436 = select(_e424, -(_e424), _e433);
            let _e437 = select(_e425, -(_e425), _e433);
            let _e438 = select(_e427, _e426, _e433);
            let _e442 = (_e126.member_1 * _e126.member_2);
            let _e446 = (_e442 / (((_e151 * 1.99998f) * _e126.member.member_1.x) / _e126.member.member.x));
            let _e449 = (_e96.x & 63u);
            let _e450 = (_e96.y & 63u);
            let _e453 = select(0u, 1u, ((_e449 & 32u) != 0u));
            let _e456 = select(0u, 1u, ((_e450 & 32u) != 0u));
            let _e460 = (_e456 == 0u);
            let _e462 = (_e460 && (_e453 == 1u));
            let _e465 = select(_e449, (63u - _e449), _e462);
            let _e466 = select(_e450, (63u - _e450), _e462);
            let _e467 = select(_e465, _e466, _e460);
            let _e468 = select(_e466, _e465, _e460);
            let _e471 = select(0u, 1u, ((_e467 & 16u) != 0u));
            let _e474 = select(0u, 1u, ((_e468 & 16u) != 0u));
            let _e479 = (_e474 == 0u);
            let _e481 = (_e479 && (_e471 == 1u));
            let _e484 = select(_e467, (63u - _e467), _e481);
            let _e485 = select(_e468, (63u - _e468), _e481);
            let _e486 = select(_e484, _e485, _e479);
            let _e487 = select(_e485, _e484, _e479);
            let _e490 = select(0u, 1u, ((_e486 & 8u) != 0u));
            let _e493 = select(0u, 1u, ((_e487 & 8u) != 0u));
            let _e498 = (_e493 == 0u);
            let _e500 = (_e498 && (_e490 == 1u));
            let _e503 = select(_e486, (63u - _e486), _e500);
            let _e504 = select(_e487, (63u - _e487), _e500);
            let _e505 = select(_e503, _e504, _e498);
            let _e506 = select(_e504, _e503, _e498);
            let _e509 = select(0u, 1u, ((_e505 & 4u) != 0u));
            let _e512 = select(0u, 1u, ((_e506 & 4u) != 0u));
            let _e517 = (_e512 == 0u);
            let _e519 = (_e517 && (_e509 == 1u));
            let _e522 = select(_e505, (63u - _e505), _e519);
            let _e523 = select(_e506, (63u - _e506), _e519);
            let _e524 = select(_e522, _e523, _e517);
            let _e525 = select(_e523, _e522, _e517);
            let _e528 = select(0u, 1u, ((_e524 & 2u) != 0u));
            let _e531 = select(0u, 1u, ((_e525 & 2u) != 0u));
            let _e536 = (_e531 == 0u);
            let _e538 = (_e536 && (_e528 == 1u));
            let _e541 = select(_e524, (63u - _e524), _e538);
            let _e542 = select(_e525, (63u - _e525), _e538);
            let _e558 = f32(bitcast<i32>((((((((1024u * ((3u * _e453) ^ _e456)) + (256u * ((3u * _e471) ^ _e474))) + (64u * ((3u * _e490) ^ _e493))) + (16u * ((3u * _e509) ^ _e512))) + (4u * ((3u * _e528) ^ _e531))) + ((3u * select(0u, 1u, ((select(_e541, _e542, _e536) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e542, _e541, _e536) & 1u) != 0u)))) + (288u * (_e126.member_11 % 64u)))));
            let _e560 = (0.5f + (_e558 * 0.7548777f));
            let _e564 = (0.5f + (_e558 * 0.5698403f));
            let _e571 = select(false, (_e151 < _e126.member.member_3), (_e151 > 0f));
            if _e571 {
                let _e573 = (_e126.member_3 * _e442);
                let _e574 = (_e573 <= 0f);
                if _e574 {
                    phi_737_ = 0f;
                } else {
                    phi_737_ = (1f / _e573);
                }
                let _e577 = phi_737_;
                let _e578 = -(_e577);
                let _e579 = (_e442 * _e577);
                let _e581 = ((10f - _e446) * 0.01f);
                let _e589 = select(1u, _e126.member_8, (1u < _e126.member_8));
                phi_763_ = 0u;
                phi_766_ = vec3<f32>(0f, 0f, 0f);
                phi_768_ = (select(0f, select(1f, _e581, (_e581 < 1f)), (_e581 > 0f)) * 0.5f);
                loop {
                    let _e591 = phi_763_;
                    let _e593 = phi_766_;
                    let _e595 = phi_768_;
                    local_4 = _e595;
                    local_5 = _e593;
                    let _e596 = (_e591 < _e589);
                    if _e596 {
                        let _e603 = ((((_e560 - floor(_e560)) + f32(bitcast<i32>(_e591))) * 3.1415927f) / f32(bitcast<i32>(_e589)));
                        let _e604 = sin(_e603);
                        let _e605 = cos(_e603);
                        let _e611 = ((_e605 * _e365) + (_e604 * _e366));
                        let _e615 = (_e605 - (_e365 * _e611));
                        let _e616 = (_e604 - (_e366 * _e611));
                        let _e617 = -((_e367 * _e611));
                        let _e620 = ((_e616 * _e367) - (_e366 * _e617));
                        let _e623 = ((_e617 * _e365) - (_e367 * _e615));
                        let _e626 = ((_e615 * _e366) - (_e365 * _e616));
                        let _e633 = (1f / sqrt((((_e620 * _e620) + (_e623 * _e623)) + (_e626 * _e626))));
                        let _e634 = (_e620 * _e633);
                        let _e635 = (_e623 * _e633);
                        let _e636 = (_e626 * _e633);
                        let _e641 = (((_e436 * _e634) + (_e437 * _e635)) + (_e438 * _e636));
                        let _e645 = (_e436 - (_e634 * _e641));
                        let _e646 = (_e437 - (_e635 * _e641));
                        let _e647 = (_e438 - (_e636 * _e641));
                        let _e653 = sqrt((((_e645 * _e645) + (_e646 * _e646)) + (_e647 * _e647)));
                        let _e658 = (((_e615 * _e645) + (_e616 * _e646)) + (_e617 * _e647));
                        let _e668 = ((((_e645 * _e365) + (_e646 * _e366)) + (_e647 * _e367)) / _e653);
                        let _e672 = select(0f, select(1f, _e668, (_e668 < 1f)), (_e668 > 0f));
                        let _e673 = abs(_e672);
                        let _e684 = (((_e673 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e673))) >> bitcast<u32>(1i))))));
                        let _e688 = (select(select(0f, -1f, (_e658 < 0f)), 1f, (_e658 > 0f)) * select((3.141593f - _e684), _e684, (_e672 >= 0f)));
                        let _e691 = select(1u, _e126.member_9, (1u < _e126.member_9));
                        let _e693 = cos((_e688 + 1.5707964f));
                        let _e695 = cos((_e688 - 1.5707964f));
                        phi_938_ = 0u;
                        phi_941_ = _e695;
                        phi_943_ = _e693;
                        loop {
                            let _e698 = phi_938_;
                            let _e700 = phi_941_;
                            let _e702 = phi_943_;
                            local = _e700;
                            local_1 = _e700;
                            local_2 = _e702;
                            local_3 = _e702;
                            let _e703 = (_e698 < _e691);
                            if _e703 {
                                let _e709 = ((_e564 - floor(_e564)) + (f32(bitcast<i32>((_e591 + (_e698 * _e691)))) * 0.618034f));
                                let _e718 = (((_e709 - floor(_e709)) + f32(bitcast<i32>(_e698))) * (1f / f32(bitcast<i32>(_e691))));
                                if (_e126.member_4 == 2f) {
                                    phi_996_ = (_e718 * _e718);
                                } else {
                                    phi_996_ = pow(_e718, _e126.member_4);
                                }
                                let _e724 = phi_996_;
                                let _e725 = (_e724 + (1.3f / _e446));
                                let _e726 = ((_e605 * _e446) * _e725);
                                let _e727 = ((-(_e604) * _e446) * _e725);
                                let _e734 = (log2(sqrt(((_e726 * _e726) + (_e727 * _e727)))) - _e126.member_7);
                                let _e741 = (-1f - floor((-0.5f - select(0f, select(5f, _e734, (_e734 < 5f)), (_e734 > 0f)))));
                                let _e744 = (round(_e726) * (1f / _e126.member.member.x));
                                let _e747 = (round(_e727) * (1f / _e126.member.member.y));
                                let _e748 = (_e336 + _e744);
                                let _e749 = (_e339 + _e747);
                                let _e750 = (_e336 - _e744);
                                let _e751 = (_e339 - _e747);
                                let _e753 = select(0f, _e741, (_e741 > 0f));
                                let _e760 = ((bitcast<u32>((floor(select(4f, _e753, (_e753 < 4f))) + 8388608f)) - 1258291200u) & 31u);
                                let _e762 = (_e134 >> bitcast<u32>(_e760));
                                let _e764 = select(1u, _e762, (1u < _e762));
                                let _e766 = (_e142 >> bitcast<u32>(_e760));
                                let _e768 = select(1u, _e766, (1u < _e766));
                                let _e773 = (select(1u, _e134, (1u < _e134)) * select(1u, _e142, (1u < _e142)));
                                let _e777 = (_e134 >> bitcast<u32>(1u));
                                let _e781 = (_e142 >> bitcast<u32>(1u));
                                let _e785 = (_e773 + (select(1u, _e777, (1u < _e777)) * select(1u, _e781, (1u < _e781))));
                                let _e789 = (_e134 >> bitcast<u32>(2u));
                                let _e793 = (_e142 >> bitcast<u32>(2u));
                                let _e797 = (_e785 + (select(1u, _e789, (1u < _e789)) * select(1u, _e793, (1u < _e793))));
                                let _e801 = (_e134 >> bitcast<u32>(3u));
                                let _e805 = (_e142 >> bitcast<u32>(3u));
                                let _e811 = select(select(select(select(0u, _e773, (_e741 >= 1f)), _e785, (_e741 >= 2f)), _e797, (_e741 >= 3f)), (_e797 + (select(1u, _e801, (1u < _e801)) * select(1u, _e805, (1u < _e805)))), (_e741 >= 4f));
                                let _e813 = f32(bitcast<i32>(_e764));
                                let _e814 = (_e748 * _e813);
                                let _e817 = f32(bitcast<i32>((_e764 - 1u)));
                                let _e819 = select(0f, _e814, (_e814 > 0f));
                                let _e827 = f32(bitcast<i32>(_e768));
                                let _e828 = (_e749 * _e827);
                                let _e831 = f32(bitcast<i32>((_e768 - 1u)));
                                let _e833 = select(0f, _e828, (_e828 > 0f));
                                let _e845 = mips.member[((_e811 + ((bitcast<u32>((floor(select(_e831, _e833, (_e833 < _e831))) + 8388608f)) - 1258291200u) * _e764)) + (bitcast<u32>((floor(select(_e817, _e819, (_e819 < _e817))) + 8388608f)) - 1258291200u))];
                                let _e854 = (_e750 * _e813);
                                let _e856 = select(0f, _e854, (_e854 > 0f));
                                let _e863 = (_e751 * _e827);
                                let _e865 = select(0f, _e863, (_e863 > 0f));
                                let _e877 = mips.member[((_e811 + ((bitcast<u32>((floor(select(_e831, _e865, (_e865 < _e831))) + 8388608f)) - 1258291200u) * _e764)) + (bitcast<u32>((floor(select(_e817, _e856, (_e856 < _e817))) + 8388608f)) - 1258291200u))];
                                let _e886 = (((((_e748 * 2f) - 1f) * _e126.member.member_1.x) * _e845) - _e347);
                                let _e887 = (((((_e749 * -2f) + 1f) * _e126.member.member_1.y) * _e845) - _e354);
                                let _e888 = (_e845 - _e340);
                                let _e891 = ((_e886 * _e886) + (_e887 * _e887));
                                let _e894 = sqrt((_e891 + (_e888 * _e888)));
                                let _e901 = (_e126.member_5 == 0f);
                                if _e901 {
                                    phi_1426_ = _e894;
                                } else {
                                    let _e903 = (_e888 * (1f + _e126.member_5));
                                    phi_1426_ = sqrt((_e891 + (_e903 * _e903)));
                                }
                                let _e908 = phi_1426_;
                                if _e574 {
                                    phi_1447_ = select(0f, 1f, (_e908 <= _e442));
                                } else {
                                    let _e912 = ((_e908 * _e578) + _e579);
                                    phi_1447_ = select(0f, select(1f, _e912, (_e912 < 1f)), (_e912 > 0f));
                                }
                                let _e918 = phi_1447_;
                                let _e921 = (_e693 + ((((((_e886 * _e365) + (_e887 * _e366)) + (_e888 * _e367)) / _e894) - _e693) * _e918));
                                let _e922 = (((((_e750 * 2f) - 1f) * _e126.member.member_1.x) * _e877) - _e347);
                                let _e923 = (((((_e751 * -2f) + 1f) * _e126.member.member_1.y) * _e877) - _e354);
                                let _e924 = (_e877 - _e340);
                                let _e927 = ((_e922 * _e922) + (_e923 * _e923));
                                let _e930 = sqrt((_e927 + (_e924 * _e924)));
                                if _e901 {
                                    phi_1486_ = _e930;
                                } else {
                                    let _e938 = (_e924 * (1f + _e126.member_5));
                                    phi_1486_ = sqrt((_e927 + (_e938 * _e938)));
                                }
                                let _e943 = phi_1486_;
                                if _e574 {
                                    phi_1507_ = select(0f, 1f, (_e943 <= _e442));
                                } else {
                                    let _e947 = ((_e943 * _e578) + _e579);
                                    phi_1507_ = select(0f, select(1f, _e947, (_e947 < 1f)), (_e947 > 0f));
                                }
                                let _e953 = phi_1507_;
                                let _e956 = (_e695 + ((((((_e922 * _e365) + (_e923 * _e366)) + (_e924 * _e367)) / _e930) - _e695) * _e953));
                                phi_939_ = (_e698 + 1u);
                                phi_942_ = select(_e956, _e700, ((_e700 > _e956) || (_e956 != _e956)));
                                phi_944_ = select(_e921, _e702, ((_e702 > _e921) || (_e921 != _e921)));
                            } else {
                                phi_939_ = u32();
                                phi_942_ = f32();
                                phi_944_ = f32();
                            }
                            let _e967 = phi_939_;
                            let _e969 = phi_942_;
                            let _e971 = phi_944_;
                            continue;
                            continuing {
                                phi_938_ = _e967;
                                phi_941_ = _e969;
                                phi_943_ = _e971;
                                break if !(_e703);
                            }
                        }
                        let _e974 = local;
                        let _e975 = abs(_e974);
                        let _e986 = (((_e975 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e975))) >> bitcast<u32>(1i))))));
                        let _e988 = local_1;
                        let _e991 = select((3.141593f - _e986), _e986, (_e988 >= 0f));
                        let _e992 = -(_e991);
                        let _e994 = local_2;
                        let _e995 = abs(_e994);
                        let _e1006 = (((_e995 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e995))) >> bitcast<u32>(1i))))));
                        let _e1008 = local_3;
                        let _e1011 = select((3.141593f - _e1006), _e1006, (_e1008 >= 0f));
                        let _e1014 = (_e653 + ((1f - _e653) * 0.05f));
                        let _e1015 = (_e991 * -2f);
                        let _e1016 = sin(_e688);
                        let _e1022 = (_e1011 * 2f);
                        if (_e126.member_13 == 0u) {
                            phi_1737_ = _e593;
                        } else {
                            let _e1038 = ((_e991 * -3f) - _e688);
                            let _e1046 = ((_e1011 * 3f) - _e688);
                            let _e1051 = (_e992 + _e688);
                            let _e1053 = (_e1011 + _e688);
                            let _e1058 = (((((((sin((_e992 - _e688)) * 6f) - sin(_e1038)) + (sin((_e1011 - _e688)) * 6f)) - sin(_e1046)) + (_e1016 * 16f)) - ((sin(_e1051) + sin(_e1053)) * 3f)) * 0.083333336f);
                            let _e1070 = (((-(cos(_e1038)) - cos(_e1046)) + (cos(_e688) * 8f)) - ((cos(_e1051) + cos(_e1053)) * 3f));
                            let _e1071 = (_e605 * _e1058);
                            let _e1072 = (_e604 * _e1058);
                            let _e1073 = (_e1070 * -0.083333336f);
                            let _e1074 = (-1f * _e367);
                            let _e1075 = (-1f * _e365);
                            let _e1077 = (1f / (_e1074 + 1f));
                            let _e1078 = (_e1077 * _e366);
                            let _e1082 = (_e1078 * _e1075);
                            let _e1103 = (_e1074 > 0.9997f);
                            let _e1104 = (_e1074 < -0.9997f);
                            phi_1737_ = (_e593 + vec3<f32>((select(select(((((_e1074 + (_e1078 * _e366)) * _e1071) + (_e1082 * _e1072)) + (_e1075 * _e1073)), _e1071, _e1104), _e1071, _e1103) * _e1014), (select(select((((_e1082 * _e1071) + ((_e1074 + ((_e1077 * _e1075) * _e1075)) * _e1072)) + (-(_e366) * _e1073)), -(_e1072), _e1104), _e1072, _e1103) * _e1014), (select(select((((_e365 * _e1071) + (_e366 * _e1072)) + (_e1074 * _e1073)), (_e1070 * 0.083333336f), _e1104), _e1073, _e1103) * _e1014)));
                        }
                        let _e1117 = phi_1737_;
                        phi_764_ = (_e591 + 1u);
                        phi_767_ = _e1117;
                        phi_769_ = (_e595 + ((0.25f * (((_e672 + (_e1015 * _e1016)) - cos((_e1015 - _e688))) + ((_e672 + (_e1022 * _e1016)) - cos((_e1022 - _e688))))) * _e1014));
                    } else {
                        phi_764_ = u32();
                        phi_767_ = vec3<f32>();
                        phi_769_ = f32();
                    }
                    let _e1120 = phi_764_;
                    let _e1122 = phi_767_;
                    let _e1124 = phi_769_;
                    continue;
                    continuing {
                        phi_763_ = _e1120;
                        phi_766_ = _e1122;
                        phi_768_ = _e1124;
                        break if !(_e596);
                    }
                }
                let _e1129 = local_4;
                let _e1132 = local_5;
                phi_1744_ = type_24((_e1129 / f32(bitcast<i32>(_e589))), _e1132);
            } else {
                phi_1744_ = type_24(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1135 = phi_1744_;
            if _e571 {
                let _e1139 = pow(_e1135.member, _e126.member_6);
                if (_e1139 != _e1139) {
                    phi_2542_ = true;
                } else {
                    phi_2542_ = (0.03f >= _e1139);
                }
                let _e1143 = phi_2542_;
                let _e1144 = select(_e1139, 0.03f, _e1143);
                if (_e126.member_13 == 0u) {
                    let _e1147 = (_e1144 * 0.6666667f);
                    phi_1815_ = (bitcast<u32>((floor(((select(0f, select(1f, _e1147, (_e1147 < 1f)), (_e1147 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                } else {
                    let _e1166 = sqrt((((_e1135.member_1.x * _e1135.member_1.x) + (_e1135.member_1.y * _e1135.member_1.y)) + (_e1135.member_1.z * _e1135.member_1.z)));
                    if (_e1166 > 0f) {
                        phi_1794_ = (_e1135.member_1 / vec3(_e1166));
                    } else {
                        phi_1794_ = vec3<f32>(_e436, _e437, _e438);
                    }
                    let _e1171 = phi_1794_;
                    let _e1172 = (_e1144 * 0.6666667f);
                    let _e1179 = ((_e1171.x * 0.5f) + 0.5f);
                    let _e1180 = ((_e1171.y * 0.5f) + 0.5f);
                    let _e1181 = ((_e1171.z * 0.5f) + 0.5f);
                    phi_1815_ = ((((bitcast<u32>((floor(((select(0f, select(1f, _e1179, (_e1179 < 1f)), (_e1179 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1180, (_e1180 < 1f)), (_e1180 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(8i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1181, (_e1181 < 1f)), (_e1181 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1172, (_e1172 < 1f)), (_e1172 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1232 = phi_1815_;
                phi_1856_ = _e1232;
            } else {
                if (_e126.member_13 == 0u) {
                    phi_1855_ = (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u);
                } else {
                    let _e1242 = (bitcast<u32>((floor(128f) + 8388608f)) - 1258291200u);
                    phi_1855_ = (((_e1242 | (_e1242 << bitcast<u32>(8i))) | ((bitcast<u32>((floor(0.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1261 = phi_1855_;
                phi_1856_ = _e1261;
            }
            let _e1263 = phi_1856_;
            terms.member[_e148] = _e1263;
            edges.member[_e148] = ((((64u * (bitcast<u32>((floor(select(3f, _e279, (_e279 < 3f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(3f, _e294, (_e294 < 3f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(3f, _e310, (_e310 < 3f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(3f, _e326, (_e326 < 3f))) + 8388608f)) - 1258291200u));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
