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
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
}

struct type_21 {
    member: type_20,
}

struct type_24 {
    member: array<vec2<f32>>,
}

struct type_26 {
    member: vec2<u32>,
    member_1: vec3<f32>,
    member_2: vec3<f32>,
    member_3: f32,
    member_4: f32,
    member_5: f32,
}

struct type_27 {
    member: u32,
    member_1: type_26,
}

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_29 {
    member: f32,
    member_1: u32,
    member_2: u32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;
@group(0) @binding(6) 
var<uniform> params: type_21;
@group(0) @binding(2) 
var<storage> kernel: type_24;
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_1772_: bool;
    var phi_1787_: bool;
    var phi_775_: vec2<f32>;
    var phi_806_: vec3<f32>;
    var phi_812_: u32;
    var phi_815_: u32;
    var phi_817_: u32;
    var phi_819_: u32;
    var phi_848_: u32;
    var phi_849_: u32;
    var phi_850_: u32;
    var phi_851_: u32;
    var phi_813_: u32;
    var phi_816_: u32;
    var phi_818_: u32;
    var phi_820_: u32;
    var local: u32;
    var phi_882_: type_28;
    var phi_917_: u32;
    var phi_920_: f32;
    var phi_1072_: u32;
    var phi_1075_: f32;
    var phi_1077_: bool;
    var phi_1079_: bool;
    var phi_1081_: f32;
    var phi_1083_: f32;
    var phi_1870_: bool;
    var phi_1885_: bool;
    var phi_1846_: vec2<f32>;
    var phi_1443_: u32;
    var phi_1445_: u32;
    var phi_1446_: f32;
    var phi_1447_: bool;
    var phi_1448_: bool;
    var phi_1449_: f32;
    var phi_1452_: bool;
    var phi_1453_: bool;
    var phi_1073_: u32;
    var phi_1076_: f32;
    var phi_1078_: bool;
    var phi_1080_: bool;
    var phi_1082_: f32;
    var phi_1084_: f32;
    var phi_1457_: bool;
    var phi_1459_: bool;
    var phi_1460_: bool;
    var local_1: bool;
    var local_2: bool;
    var local_3: bool;
    var local_4: bool;
    var local_5: f32;
    var local_6: f32;
    var local_7: bool;
    var local_8: bool;
    var local_9: f32;
    var local_10: bool;
    var phi_1500_: f32;
    var phi_918_: u32;
    var phi_921_: f32;
    var phi_1899_: bool;
    var local_11: f32;
    var phi_1571_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e58 = id_1;
            let _e60 = arrayLength((&kernel.member));
            let _e71 = params.member.member.member[0u];
            let _e76 = select(select(u32(_e71), 0u, (_e71 < 0f)), 4294967295u, (_e71 > 4294967000f));
            let _e81 = params.member.member.member[1u];
            let _e86 = select(select(u32(_e81), 0u, (_e81 < 0f)), 4294967295u, (_e81 > 4294967000f));
            if (_e58.x >= _e76) {
            } else {
                if (_e58.y >= _e86) {
                } else {
                    let _e92 = ((_e58.y * _e76) + _e58.x);
                    let _e95 = depth.member[_e92];
                    let _e99 = params.member.member.member_3;
                    let _e102 = select(false, (_e95 < _e99), (_e95 > 0f));
                    let _e103 = select(_e99, _e95, _e102);
                    let _e104 = bitcast<i32>(_e58.x);
                    let _e105 = (_e104 + -1i);
                    let _e107 = select(0i, _e105, (0i < _e105));
                    let _e109 = (bitcast<i32>(_e76) - 1i);
                    let _e113 = bitcast<i32>(_e58.y);
                    let _e115 = select(0i, _e113, (0i < _e113));
                    let _e117 = (bitcast<i32>(_e86) - 1i);
                    let _e121 = (bitcast<u32>(select(_e115, _e117, (_e117 < _e115))) * _e76);
                    let _e125 = depth.member[(_e121 + bitcast<u32>(select(_e107, _e109, (_e109 < _e107))))];
                    let _e130 = (_e104 + 1i);
                    let _e132 = select(0i, _e130, (0i < _e130));
                    let _e139 = depth.member[(_e121 + bitcast<u32>(select(_e132, _e109, (_e109 < _e132))))];
                    let _e145 = select(0i, _e104, (0i < _e104));
                    let _e148 = bitcast<u32>(select(_e145, _e109, (_e109 < _e145)));
                    let _e149 = (_e113 + -1i);
                    let _e151 = select(0i, _e149, (0i < _e149));
                    let _e159 = depth.member[((bitcast<u32>(select(_e151, _e117, (_e117 < _e151))) * _e76) + _e148)];
                    let _e164 = (_e113 + 1i);
                    let _e166 = select(0i, _e164, (0i < _e164));
                    let _e174 = depth.member[((bitcast<u32>(select(_e166, _e117, (_e117 < _e166))) * _e76) + _e148)];
                    let _e179 = (select(_e99, _e125, select(false, (_e125 < _e99), (_e125 > 0f))) - _e103);
                    let _e180 = (select(_e99, _e139, select(false, (_e139 < _e99), (_e139 > 0f))) - _e103);
                    let _e181 = (select(_e99, _e159, select(false, (_e159 < _e99), (_e159 > 0f))) - _e103);
                    let _e182 = (select(_e99, _e174, select(false, (_e174 < _e99), (_e174 > 0f))) - _e103);
                    let _e184 = ((_e180 - _e179) * 0.5f);
                    let _e186 = ((_e182 - _e181) * 0.5f);
                    let _e187 = (_e103 * 0.011f);
                    let _e189 = abs(_e179);
                    let _e190 = abs((_e179 + _e184));
                    let _e196 = (1.25f - (select(_e190, _e189, ((_e189 < _e190) || (_e190 != _e190))) / _e187));
                    let _e200 = select(0f, select(1f, _e196, (_e196 < 1f)), (_e196 > 0f));
                    let _e202 = abs(_e180);
                    let _e203 = abs((_e180 - _e184));
                    let _e209 = (1.25f - (select(_e203, _e202, ((_e202 < _e203) || (_e203 != _e203))) / _e187));
                    let _e213 = select(0f, select(1f, _e209, (_e209 < 1f)), (_e209 > 0f));
                    let _e215 = abs(_e181);
                    let _e216 = abs((_e181 + _e186));
                    let _e222 = (1.25f - (select(_e216, _e215, ((_e215 < _e216) || (_e216 != _e216))) / _e187));
                    let _e226 = select(0f, select(1f, _e222, (_e222 < 1f)), (_e222 > 0f));
                    let _e228 = abs(_e182);
                    let _e229 = abs((_e182 - _e186));
                    let _e235 = (1.25f - (select(_e229, _e228, ((_e228 < _e229) || (_e229 != _e229))) / _e187));
                    let _e239 = select(0f, select(1f, _e235, (_e235 < 1f)), (_e235 > 0f));
                    let _e244 = (select(0f, select(1f, _e200, (_e200 < 1f)), (_e200 > 0f)) * 2.9f);
                    let _e246 = floor((_e244 + 0.5f));
                    let _e255 = select(_e246, (_e246 - 1f), (((_e246 - _e244) == 0.5f) && ((floor((_e246 * 0.5f)) * 2f) != _e246)));
                    let _e257 = select(0f, _e255, (_e255 > 0f));
                    let _e266 = (select(0f, select(1f, _e213, (_e213 < 1f)), (_e213 > 0f)) * 2.9f);
                    let _e268 = floor((_e266 + 0.5f));
                    let _e277 = select(_e268, (_e268 - 1f), (((_e268 - _e266) == 0.5f) && ((floor((_e268 * 0.5f)) * 2f) != _e268)));
                    let _e279 = select(0f, _e277, (_e277 > 0f));
                    let _e289 = (select(0f, select(1f, _e226, (_e226 < 1f)), (_e226 > 0f)) * 2.9f);
                    let _e291 = floor((_e289 + 0.5f));
                    let _e300 = select(_e291, (_e291 - 1f), (((_e291 - _e289) == 0.5f) && ((floor((_e291 * 0.5f)) * 2f) != _e291)));
                    let _e302 = select(0f, _e300, (_e300 > 0f));
                    let _e312 = (select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f)) * 2.9f);
                    let _e314 = floor((_e312 + 0.5f));
                    let _e323 = select(_e314, (_e314 - 1f), (((_e314 - _e312) == 0.5f) && ((floor((_e314 * 0.5f)) * 2f) != _e314)));
                    let _e325 = select(0f, _e323, (_e323 > 0f));
                    let _e329 = ((((64u * u32(select(3f, _e257, (_e257 < 3f)))) + (16u * u32(select(3f, _e279, (_e279 < 3f))))) + (4u * u32(select(3f, _e302, (_e302 < 3f))))) + u32(select(3f, _e325, (_e325 < 3f))));
                    if _e102 {
                        let _e342 = params.member.member.member_1[0u];
                        let _e344 = ((((((f32(_e58.x) + 0.5f) / _e71) * 2f) - 1f) * _e342) * _e95);
                        let _e351 = params.member.member.member_1[1u];
                        let _e353 = ((((((f32(_e58.y) + 0.5f) / _e81) * -2f) + 1f) * _e351) * _e95);
                        let _e357 = normals.member[_e92];
                        let _e365 = (f32((bitcast<i32>(((_e357 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e365 != _e365) {
                            phi_1772_ = true;
                        } else {
                            phi_1772_ = (-1f >= _e365);
                        }
                        let _e369 = phi_1772_;
                        let _e370 = select(_e365, -1f, _e369);
                        let _e380 = (f32((bitcast<i32>((((_e357 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e380 != _e380) {
                            phi_1787_ = true;
                        } else {
                            phi_1787_ = (-1f >= _e380);
                        }
                        let _e384 = phi_1787_;
                        let _e385 = select(_e380, -1f, _e384);
                        let _e388 = (1f - abs(_e370));
                        let _e389 = abs(_e385);
                        let _e390 = (_e388 - _e389);
                        if (_e390 < 0f) {
                            phi_775_ = vec2<f32>(((1f - _e389) * select(1f, -1f, (_e370 < 0f))), (_e388 * select(1f, -1f, (_e385 < 0f))));
                        } else {
                            phi_775_ = vec2<f32>(_e370, _e385);
                        }
                        let _e401 = phi_775_;
                        let _e410 = (1f / sqrt((((_e401.x * _e401.x) + (_e401.y * _e401.y)) + (_e390 * _e390))));
                        let _e411 = (_e401.x * _e410);
                        let _e412 = (_e401.y * _e410);
                        let _e413 = (_e390 * _e410);
                        let _e414 = -(_e413);
                        if ((((_e411 * -(_e344)) + (_e412 * -(_e353))) + (_e414 * -(_e95))) < 0f) {
                            phi_806_ = vec3<f32>(-(_e411), -(_e412), _e413);
                        } else {
                            phi_806_ = vec3<f32>(_e411, _e412, _e414);
                        }
                        let _e429 = phi_806_;
                        let _e432 = params.member.member_8;
                        phi_812_ = (_e58.y & 63u);
                        phi_815_ = (_e58.x & 63u);
                        phi_817_ = 32u;
                        phi_819_ = 0u;
                        loop {
                            let _e436 = phi_812_;
                            let _e438 = phi_815_;
                            let _e440 = phi_817_;
                            let _e442 = phi_819_;
                            local = _e442;
                            let _e443 = (_e440 > 0u);
                            if _e443 {
                                let _e446 = select(0u, 1u, ((_e438 & _e440) != 0u));
                                let _e449 = select(0u, 1u, ((_e436 & _e440) != 0u));
                                if (_e449 == 0u) {
                                    if (_e446 == 1u) {
                                        phi_848_ = (63u - _e436);
                                        phi_849_ = (63u - _e438);
                                    } else {
                                        phi_848_ = _e436;
                                        phi_849_ = _e438;
                                    }
                                    let _e460 = phi_848_;
                                    let _e462 = phi_849_;
                                    phi_850_ = _e462;
                                    phi_851_ = _e460;
                                } else {
                                    phi_850_ = _e436;
                                    phi_851_ = _e438;
                                }
                                let _e464 = phi_850_;
                                let _e466 = phi_851_;
                                phi_813_ = _e464;
                                phi_816_ = _e466;
                                phi_818_ = (_e440 / 2u);
                                phi_820_ = (_e442 + ((_e440 * _e440) * ((3u * _e446) ^ _e449)));
                            } else {
                                phi_813_ = u32();
                                phi_816_ = u32();
                                phi_818_ = u32();
                                phi_820_ = u32();
                            }
                            let _e469 = phi_813_;
                            let _e471 = phi_816_;
                            let _e473 = phi_818_;
                            let _e475 = phi_820_;
                            continue;
                            continuing {
                                phi_812_ = _e469;
                                phi_815_ = _e471;
                                phi_817_ = _e473;
                                phi_819_ = _e475;
                                break if !(_e443);
                            }
                        }
                        let _e480 = local;
                        let _e482 = f32((_e480 + (288u * (_e432 % 64u))));
                        let _e484 = (0.5f + (_e482 * 0.7548777f));
                        let _e488 = (0.5f + (_e482 * 0.5698403f));
                        let _e491 = (6.2831855f * (_e484 - floor(_e484)));
                        phi_882_ = type_28(_e329, type_27(1u, type_26(vec2<u32>(_e58.x, _e58.y), vec3<f32>(_e344, _e353, _e95), _e429, sin(_e491), cos(_e491), (_e488 - floor(_e488)))));
                    } else {
                        phi_882_ = type_28(_e329, type_27(0u, type_27().member_1));
                    }
                    let _e503 = phi_882_;
                    if (bitcast<i32>(_e503.member_1.member) != 0i) {
                        let _e512 = params.member.member_5;
                        let _e514 = select(_e512, 64u, (64u < _e512));
                        let _e516 = select(_e514, _e60, (_e60 < _e514));
                        let _e518 = select(1u, _e516, (1u < _e516));
                        let _e521 = params.member.member_6;
                        let _e523 = select(1u, _e521, (1u < _e521));
                        phi_917_ = 0u;
                        phi_920_ = 0f;
                        loop {
                            let _e525 = phi_917_;
                            let _e527 = phi_920_;
                            local_11 = _e527;
                            let _e528 = (_e525 < _e518);
                            if _e528 {
                                if (_e525 < _e60) {
                                } else {
                                    phi_1899_ = true;
                                    break;
                                }
                                let _e533 = kernel.member[_e525][0u];
                                let _e537 = kernel.member[_e525][1u];
                                let _e542 = ((_e503.member_1.member_1.member_4 * _e533) - (_e503.member_1.member_1.member_3 * _e537));
                                let _e545 = ((_e503.member_1.member_1.member_3 * _e533) + (_e503.member_1.member_1.member_4 * _e537));
                                let _e550 = ((1f - (_e542 * _e542)) - (_e545 * _e545));
                                let _e554 = sqrt(select(0f, _e550, ((_e550 > 0f) || false)));
                                let _e555 = -(_e554);
                                let _e559 = (-1f * _e503.member_1.member_1.member_2.z);
                                let _e560 = (-1f * _e503.member_1.member_1.member_2.x);
                                let _e562 = (1f / (_e559 + 1f));
                                let _e563 = (_e562 * _e503.member_1.member_1.member_2.y);
                                let _e567 = (_e563 * _e560);
                                let _e587 = (_e559 > 0.9997f);
                                let _e588 = (_e559 < -0.9997f);
                                let _e598 = params.member.member_1;
                                let _e602 = params.member.member_3;
                                let _e605 = params.member.member_4;
                                phi_1072_ = 1u;
                                phi_1075_ = _e598;
                                phi_1077_ = false;
                                phi_1079_ = true;
                                phi_1081_ = 0f;
                                phi_1083_ = 0f;
                                loop {
                                    let _e611 = phi_1072_;
                                    let _e613 = phi_1075_;
                                    let _e615 = phi_1077_;
                                    let _e617 = phi_1079_;
                                    let _e619 = phi_1081_;
                                    let _e621 = phi_1083_;
                                    local_5 = _e613;
                                    local_7 = _e615;
                                    local_9 = _e613;
                                    local_10 = _e615;
                                    let _e622 = (_e611 <= _e523);
                                    if _e622 {
                                        let _e628 = (((-(_e503.member_1.member_1.member_5) + f32(_e611)) * _e598) / f32(_e523));
                                        let _e633 = (_e503.member_1.member_1.member_1.x + (select(select(((((_e559 + (_e563 * _e503.member_1.member_1.member_2.y)) * _e542) + (_e567 * _e545)) + (_e560 * _e555)), _e542, _e588), _e542, _e587) * _e628));
                                        let _e635 = (_e503.member_1.member_1.member_1.y + (select(select((((_e567 * _e542) + ((_e559 + ((_e562 * _e560) * _e560)) * _e545)) + (-(_e503.member_1.member_1.member_2.y) * _e555)), -(_e545), _e588), _e545, _e587) * _e628));
                                        let _e637 = (_e503.member_1.member_1.member_1.z + (select(select((((_e503.member_1.member_1.member_2.x * _e542) + (_e503.member_1.member_1.member_2.y * _e545)) + (_e559 * _e555)), _e554, _e588), _e555, _e587) * _e628));
                                        let _e643 = params.member.member.member_1[0u];
                                        let _e646 = (((_e633 * 0.5f) / (_e637 * _e643)) + 0.5f);
                                        let _e652 = params.member.member.member_1[1u];
                                        let _e655 = (0.5f - ((_e635 * 0.5f) / (_e637 * _e652)));
                                        let _e665 = select(false, select(false, select(false, select(false, (_e655 <= 1f), (_e655 >= 0f)), select(false, (_e646 <= 1f), (_e646 >= 0f))), (_e637 > 0f)), _e617);
                                        if _e665 {
                                            let _e666 = (_e646 * _e71);
                                            let _e668 = f32((_e76 - 1u));
                                            let _e670 = select(0f, _e666, (_e666 > 0f));
                                            let _e674 = (_e655 * _e81);
                                            let _e676 = f32((_e86 - 1u));
                                            let _e678 = select(0f, _e674, (_e674 > 0f));
                                            let _e686 = depth.member[((u32(select(_e676, _e678, (_e678 < _e676))) * _e76) + u32(select(_e668, _e670, (_e670 < _e668))))];
                                            let _e690 = select(_e99, _e686, select(false, (_e686 < _e99), (_e686 > 0f)));
                                            let _e693 = (((_e646 * 2f) - 1f) * _e643);
                                            let _e697 = (((_e655 * -2f) + 1f) * _e652);
                                            let _e699 = (_e633 - (_e693 * _e690));
                                            let _e700 = (_e635 - (_e697 * _e690));
                                            let _e701 = (_e637 - _e690);
                                            let _e707 = sqrt((((_e699 * _e699) + (_e700 * _e700)) + (_e701 * _e701)));
                                            let _e712 = (select(0f, select(1f, _e646, (_e646 < 1f)), (_e646 > 0f)) * _e71);
                                            let _e714 = select(0f, _e712, (_e712 > 0f));
                                            let _e717 = u32(select(_e668, _e714, (_e714 < _e668)));
                                            let _e722 = (select(0f, select(1f, _e655, (_e655 < 1f)), (_e655 > 0f)) * _e81);
                                            let _e724 = select(0f, _e722, (_e722 > 0f));
                                            let _e727 = u32(select(_e676, _e724, (_e724 < _e676)));
                                            let _e748 = normals.member[((_e727 * _e76) + _e717)];
                                            let _e756 = (f32((bitcast<i32>(((_e748 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e756 != _e756) {
                                                phi_1870_ = true;
                                            } else {
                                                phi_1870_ = (-1f >= _e756);
                                            }
                                            let _e760 = phi_1870_;
                                            let _e761 = select(_e756, -1f, _e760);
                                            let _e771 = (f32((bitcast<i32>((((_e748 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e771 != _e771) {
                                                phi_1885_ = true;
                                            } else {
                                                phi_1885_ = (-1f >= _e771);
                                            }
                                            let _e775 = phi_1885_;
                                            let _e776 = select(_e771, -1f, _e775);
                                            let _e779 = (1f - abs(_e761));
                                            let _e780 = abs(_e776);
                                            let _e781 = (_e779 - _e780);
                                            if (_e781 < 0f) {
                                                phi_1846_ = vec2<f32>(((1f - _e780) * select(1f, -1f, (_e761 < 0f))), (_e779 * select(1f, -1f, (_e776 < 0f))));
                                            } else {
                                                phi_1846_ = vec2<f32>(_e761, _e776);
                                            }
                                            let _e792 = phi_1846_;
                                            let _e801 = (1f / sqrt((((_e792.x * _e792.x) + (_e792.y * _e792.y)) + (_e781 * _e781))));
                                            let _e802 = (_e792.x * _e801);
                                            let _e803 = (_e792.y * _e801);
                                            let _e805 = -((_e781 * _e801));
                                            let _e809 = (((_e802 * _e693) + (_e803 * _e697)) + _e805);
                                            let _e818 = select(((((_e802 * ((((((f32(_e717) + 0.5f) * (1f / _e71)) * 2f) - 1f) * _e643) * _e690)) + (_e803 * ((((((f32(_e727) + 0.5f) * (1f / _e81)) * -2f) + 1f) * _e652) * _e690))) + (_e805 * _e690)) / _e809), _e690, (abs(_e809) < 0.001f));
                                            let _e828 = select(select(((_e637 - _e818) > _e605), true, (_e637 < (_e818 * (1f + _e602)))), true, select(false, (_e727 == _e503.member_1.member_1.member.y), (_e717 == _e503.member_1.member_1.member.x)));
                                            let _e830 = select(false, !(_e828), _e665);
                                            let _e831 = (_e619 + _e707);
                                            let _e840 = select(false, _e828, _e665);
                                            if _e840 {
                                                phi_1443_ = (_e611 + 1u);
                                            } else {
                                                phi_1443_ = u32();
                                            }
                                            let _e843 = phi_1443_;
                                            phi_1445_ = _e843;
                                            phi_1446_ = select(_e613, select((_e621 + ((_e619 * (_e628 - _e621)) / _e831)), _e621, (_e831 < 0.000001f)), _e830);
                                            phi_1447_ = select(_e830, true, _e615);
                                            phi_1448_ = _e840;
                                            phi_1449_ = _e707;
                                            phi_1452_ = _e840;
                                            phi_1453_ = select(true, false, _e840);
                                        } else {
                                            phi_1445_ = u32();
                                            phi_1446_ = f32();
                                            phi_1447_ = bool();
                                            phi_1448_ = bool();
                                            phi_1449_ = f32();
                                            phi_1452_ = false;
                                            phi_1453_ = false;
                                        }
                                        let _e846 = phi_1445_;
                                        let _e848 = phi_1446_;
                                        let _e850 = phi_1447_;
                                        let _e852 = phi_1448_;
                                        let _e854 = phi_1449_;
                                        let _e856 = phi_1452_;
                                        let _e858 = phi_1453_;
                                        phi_1073_ = _e846;
                                        phi_1076_ = _e848;
                                        phi_1078_ = _e850;
                                        phi_1080_ = _e852;
                                        phi_1082_ = _e854;
                                        phi_1084_ = _e628;
                                        phi_1457_ = _e856;
                                        phi_1459_ = _e858;
                                        phi_1460_ = select(true, false, _e665);
                                    } else {
                                        phi_1073_ = u32();
                                        phi_1076_ = f32();
                                        phi_1078_ = bool();
                                        phi_1080_ = bool();
                                        phi_1082_ = f32();
                                        phi_1084_ = f32();
                                        phi_1457_ = false;
                                        phi_1459_ = false;
                                        phi_1460_ = false;
                                    }
                                    let _e861 = phi_1073_;
                                    let _e863 = phi_1076_;
                                    let _e865 = phi_1078_;
                                    let _e867 = phi_1080_;
                                    let _e869 = phi_1082_;
                                    let _e871 = phi_1084_;
                                    let _e873 = phi_1457_;
                                    let _e875 = phi_1459_;
                                    let _e877 = phi_1460_;
                                    let _e878 = select(true, false, _e622);
                                    local_1 = _e878;
                                    local_2 = _e875;
                                    local_3 = _e878;
                                    local_4 = _e877;
                                    local_6 = _e863;
                                    local_8 = _e865;
                                    continue;
                                    continuing {
                                        phi_1072_ = _e861;
                                        phi_1075_ = _e863;
                                        phi_1077_ = _e865;
                                        phi_1079_ = _e867;
                                        phi_1081_ = _e869;
                                        phi_1083_ = _e871;
                                        break if !(_e873);
                                    }
                                }
                                let _e881 = local_1;
                                let _e883 = local_2;
                                let _e884 = select(_e883, false, _e881);
                                let _e886 = local_3;
                                let _e888 = local_4;
                                let _e890 = select(select(_e888, false, _e886), false, _e884);
                                let _e892 = local_5;
                                let _e894 = local_6;
                                let _e897 = local_7;
                                let _e899 = local_8;
                                let _e901 = select(_e884, true, _e890);
                                let _e903 = local_9;
                                let _e906 = local_10;
                                let _e910 = params.member.member_7;
                                if (_e910 == 1u) {
                                    phi_1500_ = 0f;
                                } else {
                                    let _e912 = (select(_e903, select(_e894, _e892, _e890), _e901) / _e598);
                                    phi_1500_ = select(0f, select(1f, _e912, (_e912 < 1f)), (_e912 > 0f));
                                }
                                let _e918 = phi_1500_;
                                phi_918_ = (_e525 + 1u);
                                phi_921_ = (_e527 + select(1f, _e918, select(_e906, select(_e899, _e897, _e890), _e901)));
                            } else {
                                phi_918_ = u32();
                                phi_921_ = f32();
                            }
                            let _e923 = phi_918_;
                            let _e925 = phi_921_;
                            continue;
                            continuing {
                                phi_917_ = _e923;
                                phi_920_ = _e925;
                                phi_1899_ = false;
                                break if !(_e528);
                            }
                        }
                        let _e928 = phi_1899_;
                        if _e928 {
                            break;
                        }
                        let _e931 = local_11;
                        let _e935 = params.member.member_2;
                        let _e936 = pow((_e931 / f32(_e518)), _e935);
                        let _e937 = (_e936 * 0.6666667f);
                        let _e943 = ((select(0f, select(1f, _e937, (_e937 < 1f)), (_e937 > 0f)) * 255f) + 0.5f);
                        phi_1571_ = type_29(_e936, select(select(u32(_e943), 0u, (_e943 < 0f)), 4294967295u, (_e943 > 4294967000f)), _e503.member);
                    } else {
                        phi_1571_ = type_29(1f, 170u, _e503.member);
                    }
                    let _e952 = phi_1571_;
                    if (_e92 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e92] = _e952.member;
                    if (_e92 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e92] = _e952.member_1;
                    if (_e92 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e92] = _e952.member_2;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn raymarch_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
