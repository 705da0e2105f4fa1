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

struct type_23 {
    member: f32,
    member_1: vec3<f32>,
}

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
    var phi_2499_: bool;
    var phi_2514_: bool;
    var phi_2474_: vec2<f32>;
    var phi_753_: f32;
    var phi_780_: u32;
    var phi_783_: vec3<f32>;
    var phi_785_: f32;
    var phi_956_: u32;
    var phi_959_: f32;
    var phi_961_: f32;
    var phi_1016_: f32;
    var phi_1575_: f32;
    var phi_1596_: f32;
    var phi_1635_: f32;
    var phi_1656_: f32;
    var phi_957_: u32;
    var phi_960_: f32;
    var phi_962_: f32;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_1887_: vec3<f32>;
    var phi_781_: u32;
    var phi_784_: vec3<f32>;
    var phi_786_: f32;
    var local_4: f32;
    var local_5: vec3<f32>;
    var phi_1893_: type_23;
    var phi_2743_: bool;
    var phi_1948_: vec3<f32>;
    var phi_1969_: u32;
    var phi_2014_: u32;

    let _e85 = id_1;
    let _e91 = params.member.member.member[0u];
    let _e96 = select(select(u32(_e91), 0u, (_e91 < 0f)), 4294967295u, (_e91 > 4294967000f));
    let _e101 = params.member.member.member[1u];
    let _e106 = select(select(u32(_e101), 0u, (_e101 < 0f)), 4294967295u, (_e101 > 4294967000f));
    if (_e85.x >= _e96) {
    } else {
        if (_e85.y >= _e106) {
        } else {
            let _e112 = ((_e85.y * _e96) + _e85.x);
            let _e114 = mips.member[_e112];
            let _e115 = bitcast<i32>(_e85.x);
            let _e116 = (_e115 + -1i);
            let _e118 = select(0i, _e116, (0i < _e116));
            let _e120 = (bitcast<i32>(_e96) - 1i);
            let _e124 = bitcast<i32>(_e85.y);
            let _e126 = select(0i, _e124, (0i < _e124));
            let _e128 = (bitcast<i32>(_e106) - 1i);
            let _e132 = (bitcast<u32>(select(_e126, _e128, (_e128 < _e126))) * _e96);
            let _e135 = mips.member[(_e132 + bitcast<u32>(select(_e118, _e120, (_e120 < _e118))))];
            let _e136 = (_e115 + 1i);
            let _e138 = select(0i, _e136, (0i < _e136));
            let _e144 = mips.member[(_e132 + bitcast<u32>(select(_e138, _e120, (_e120 < _e138))))];
            let _e146 = select(0i, _e115, (0i < _e115));
            let _e149 = bitcast<u32>(select(_e146, _e120, (_e120 < _e146)));
            let _e150 = (_e124 + -1i);
            let _e152 = select(0i, _e150, (0i < _e150));
            let _e159 = mips.member[((bitcast<u32>(select(_e152, _e128, (_e128 < _e152))) * _e96) + _e149)];
            let _e160 = (_e124 + 1i);
            let _e162 = select(0i, _e160, (0i < _e160));
            let _e169 = mips.member[((bitcast<u32>(select(_e162, _e128, (_e128 < _e162))) * _e96) + _e149)];
            let _e170 = (_e135 - _e114);
            let _e171 = (_e144 - _e114);
            let _e172 = (_e159 - _e114);
            let _e173 = (_e169 - _e114);
            let _e175 = ((_e171 - _e170) * 0.5f);
            let _e177 = ((_e173 - _e172) * 0.5f);
            let _e178 = (_e114 * 0.011f);
            let _e180 = abs(_e170);
            let _e181 = abs((_e170 + _e175));
            let _e187 = (1.25f - (select(_e181, _e180, ((_e180 < _e181) || (_e181 != _e181))) / _e178));
            let _e191 = select(0f, select(1f, _e187, (_e187 < 1f)), (_e187 > 0f));
            let _e193 = abs(_e171);
            let _e194 = abs((_e171 - _e175));
            let _e200 = (1.25f - (select(_e194, _e193, ((_e193 < _e194) || (_e194 != _e194))) / _e178));
            let _e204 = select(0f, select(1f, _e200, (_e200 < 1f)), (_e200 > 0f));
            let _e206 = abs(_e172);
            let _e207 = abs((_e172 + _e177));
            let _e213 = (1.25f - (select(_e207, _e206, ((_e206 < _e207) || (_e207 != _e207))) / _e178));
            let _e217 = select(0f, select(1f, _e213, (_e213 < 1f)), (_e213 > 0f));
            let _e219 = abs(_e173);
            let _e220 = abs((_e173 - _e177));
            let _e226 = (1.25f - (select(_e220, _e219, ((_e219 < _e220) || (_e220 != _e220))) / _e178));
            let _e230 = select(0f, select(1f, _e226, (_e226 < 1f)), (_e226 > 0f));
            let _e235 = (select(0f, select(1f, _e191, (_e191 < 1f)), (_e191 > 0f)) * 2.9f);
            let _e237 = floor((_e235 + 0.5f));
            let _e246 = select(_e237, (_e237 - 1f), (((_e237 - _e235) == 0.5f) && ((floor((_e237 * 0.5f)) * 2f) != _e237)));
            let _e248 = select(0f, _e246, (_e246 > 0f));
            let _e257 = (select(0f, select(1f, _e204, (_e204 < 1f)), (_e204 > 0f)) * 2.9f);
            let _e259 = floor((_e257 + 0.5f));
            let _e268 = select(_e259, (_e259 - 1f), (((_e259 - _e257) == 0.5f) && ((floor((_e259 * 0.5f)) * 2f) != _e259)));
            let _e270 = select(0f, _e268, (_e268 > 0f));
            let _e280 = (select(0f, select(1f, _e217, (_e217 < 1f)), (_e217 > 0f)) * 2.9f);
            let _e282 = floor((_e280 + 0.5f));
            let _e291 = select(_e282, (_e282 - 1f), (((_e282 - _e280) == 0.5f) && ((floor((_e282 * 0.5f)) * 2f) != _e282)));
            let _e293 = select(0f, _e291, (_e291 > 0f));
            let _e303 = (select(0f, select(1f, _e230, (_e230 < 1f)), (_e230 > 0f)) * 2.9f);
            let _e305 = floor((_e303 + 0.5f));
            let _e314 = select(_e305, (_e305 - 1f), (((_e305 - _e303) == 0.5f) && ((floor((_e305 * 0.5f)) * 2f) != _e305)));
            let _e316 = select(0f, _e314, (_e314 > 0f));
            let _e323 = ((f32(_e85.x) + 0.5f) / _e91);
            let _e326 = ((f32(_e85.y) + 0.5f) / _e101);
            let _e327 = (_e114 * 0.99999f);
            let _e334 = params.member.member.member_1[0u];
            let _e336 = ((((_e323 * 2f) - 1f) * _e334) * _e327);
            let _e343 = params.member.member.member_1[1u];
            let _e345 = ((((_e326 * -2f) + 1f) * _e343) * _e327);
            let _e346 = -(_e336);
            let _e347 = -(_e345);
            let _e348 = (_e114 * -0.99999f);
            let _e355 = (1f / sqrt((((_e346 * _e346) + (_e347 * _e347)) + (_e348 * _e348))));
            let _e356 = (_e346 * _e355);
            let _e357 = (_e347 * _e355);
            let _e358 = (_e348 * _e355);
            let _e361 = normals.member[_e112];
            let _e369 = (f32((bitcast<i32>(((_e361 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e369 != _e369) {
                phi_2499_ = true;
            } else {
                phi_2499_ = (-1f >= _e369);
            }
            let _e373 = phi_2499_;
            let _e374 = select(_e369, -1f, _e373);
            let _e384 = (f32((bitcast<i32>((((_e361 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e384 != _e384) {
                phi_2514_ = true;
            } else {
                phi_2514_ = (-1f >= _e384);
            }
            let _e388 = phi_2514_;
            let _e389 = select(_e384, -1f, _e388);
            let _e392 = (1f - abs(_e374));
            let _e393 = abs(_e389);
            let _e394 = (_e392 - _e393);
            if (_e394 < 0f) {
                phi_2474_ = vec2<f32>(((1f - _e393) * select(1f, -1f, (_e374 < 0f))), (_e392 * select(1f, -1f, (_e389 < 0f))));
            } else {
                phi_2474_ = vec2<f32>(_e374, _e389);
            }
            let _e405 = phi_2474_;
            let _e414 = (1f / sqrt((((_e405.x * _e405.x) + (_e405.y * _e405.y)) + (_e394 * _e394))));
            let _e415 = (_e405.x * _e414);
            let _e416 = (_e405.y * _e414);
            let _e417 = (_e394 * _e414);
            let _e418 = -(_e417);
            let _e424 = ((((_e415 * _e356) + (_e416 * _e357)) + (_e418 * _e358)) < 0f);
            let _e427 = select(_e415, -(_e415), _e424);
            let _e428 = select(_e416, -(_e416), _e424);
            let _e429 = select(_e418, _e417, _e424);
            let _e433 = params.member.member_1;
            let _e436 = params.member.member_2;
            let _e437 = (_e433 * _e436);
            let _e441 = (_e437 / (((_e114 * 1.99998f) * _e334) / _e91));
            let _e445 = params.member.member_11;
            let _e446 = (_e85.x & 63u);
            let _e447 = (_e85.y & 63u);
            let _e450 = select(0u, 1u, ((_e446 & 32u) != 0u));
            let _e453 = select(0u, 1u, ((_e447 & 32u) != 0u));
            let _e457 = (_e453 == 0u);
            let _e459 = (_e457 && (_e450 == 1u));
            let _e462 = select(_e446, (63u - _e446), _e459);
            let _e463 = select(_e447, (63u - _e447), _e459);
            let _e464 = select(_e462, _e463, _e457);
            let _e465 = select(_e463, _e462, _e457);
            let _e468 = select(0u, 1u, ((_e464 & 16u) != 0u));
            let _e471 = select(0u, 1u, ((_e465 & 16u) != 0u));
            let _e476 = (_e471 == 0u);
            let _e478 = (_e476 && (_e468 == 1u));
            let _e481 = select(_e464, (63u - _e464), _e478);
            let _e482 = select(_e465, (63u - _e465), _e478);
            let _e483 = select(_e481, _e482, _e476);
            let _e484 = select(_e482, _e481, _e476);
            let _e487 = select(0u, 1u, ((_e483 & 8u) != 0u));
            let _e490 = select(0u, 1u, ((_e484 & 8u) != 0u));
            let _e495 = (_e490 == 0u);
            let _e497 = (_e495 && (_e487 == 1u));
            let _e500 = select(_e483, (63u - _e483), _e497);
            let _e501 = select(_e484, (63u - _e484), _e497);
            let _e502 = select(_e500, _e501, _e495);
            let _e503 = select(_e501, _e500, _e495);
            let _e506 = select(0u, 1u, ((_e502 & 4u) != 0u));
            let _e509 = select(0u, 1u, ((_e503 & 4u) != 0u));
            let _e514 = (_e509 == 0u);
            let _e516 = (_e514 && (_e506 == 1u));
            let _e519 = select(_e502, (63u - _e502), _e516);
            let _e520 = select(_e503, (63u - _e503), _e516);
            let _e521 = select(_e519, _e520, _e514);
            let _e522 = select(_e520, _e519, _e514);
            let _e525 = select(0u, 1u, ((_e521 & 2u) != 0u));
            let _e528 = select(0u, 1u, ((_e522 & 2u) != 0u));
            let _e533 = (_e528 == 0u);
            let _e535 = (_e533 && (_e525 == 1u));
            let _e538 = select(_e521, (63u - _e521), _e535);
            let _e539 = select(_e522, (63u - _e522), _e535);
            let _e554 = f32((((((((1024u * ((3u * _e450) ^ _e453)) + (256u * ((3u * _e468) ^ _e471))) + (64u * ((3u * _e487) ^ _e490))) + (16u * ((3u * _e506) ^ _e509))) + (4u * ((3u * _e525) ^ _e528))) + ((3u * select(0u, 1u, ((select(_e538, _e539, _e533) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e539, _e538, _e533) & 1u) != 0u)))) + (288u * (_e445 % 64u))));
            let _e556 = (0.5f + (_e554 * 0.7548777f));
            let _e560 = (0.5f + (_e554 * 0.5698403f));
            let _e566 = params.member.member.member_3;
            let _e569 = select(false, (_e114 < _e566), (_e114 > 0f));
            if _e569 {
                let _e572 = params.member.member_3;
                let _e573 = (_e572 * _e437);
                let _e574 = (_e573 <= 0f);
                if _e574 {
                    phi_753_ = 0f;
                } else {
                    phi_753_ = (1f / _e573);
                }
                let _e577 = phi_753_;
                let _e578 = -(_e577);
                let _e579 = (_e437 * _e577);
                let _e581 = ((10f - _e441) * 0.01f);
                let _e589 = params.member.member_8;
                let _e591 = select(1u, _e589, (1u < _e589));
                phi_780_ = 0u;
                phi_783_ = vec3<f32>(0f, 0f, 0f);
                phi_785_ = (select(0f, select(1f, _e581, (_e581 < 1f)), (_e581 > 0f)) * 0.5f);
                loop {
                    let _e593 = phi_780_;
                    let _e595 = phi_783_;
                    let _e597 = phi_785_;
                    local_4 = _e597;
                    local_5 = _e595;
                    let _e598 = (_e593 < _e591);
                    if _e598 {
                        let _e603 = ((((_e556 - floor(_e556)) + f32(_e593)) * 3.1415927f) / f32(_e591));
                        let _e604 = sin(_e603);
                        let _e605 = cos(_e603);
                        let _e611 = ((_e605 * _e356) + (_e604 * _e357));
                        let _e615 = (_e605 - (_e356 * _e611));
                        let _e616 = (_e604 - (_e357 * _e611));
                        let _e617 = -((_e358 * _e611));
                        let _e620 = ((_e616 * _e358) - (_e357 * _e617));
                        let _e623 = ((_e617 * _e356) - (_e358 * _e615));
                        let _e626 = ((_e615 * _e357) - (_e356 * _e616));
                        let _e633 = (1f / sqrt((((_e620 * _e620) + (_e623 * _e623)) + (_e626 * _e626))));
                        let _e634 = (_e620 * _e633);
                        let _e635 = (_e623 * _e633);
                        let _e636 = (_e626 * _e633);
                        let _e641 = (((_e427 * _e634) + (_e428 * _e635)) + (_e429 * _e636));
                        let _e645 = (_e427 - (_e634 * _e641));
                        let _e646 = (_e428 - (_e635 * _e641));
                        let _e647 = (_e429 - (_e636 * _e641));
                        let _e653 = sqrt((((_e645 * _e645) + (_e646 * _e646)) + (_e647 * _e647)));
                        let _e658 = (((_e615 * _e645) + (_e616 * _e646)) + (_e617 * _e647));
                        let _e668 = ((((_e645 * _e356) + (_e646 * _e357)) + (_e647 * _e358)) / _e653);
                        let _e672 = select(0f, select(1f, _e668, (_e668 < 1f)), (_e668 > 0f));
                        let _e673 = abs(_e672);
                        let _e684 = (((_e673 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e673))) >> bitcast<u32>(1i))))));
                        let _e688 = (select(select(0f, -1f, (_e658 < 0f)), 1f, (_e658 > 0f)) * select((3.141593f - _e684), _e684, (_e672 >= 0f)));
                        let _e691 = params.member.member_9;
                        let _e693 = select(1u, _e691, (1u < _e691));
                        let _e695 = cos((_e688 + 1.5707964f));
                        let _e697 = cos((_e688 - 1.5707964f));
                        let _e700 = params.member.member_5;
                        phi_956_ = 0u;
                        phi_959_ = _e697;
                        phi_961_ = _e695;
                        loop {
                            let _e702 = phi_956_;
                            let _e704 = phi_959_;
                            let _e706 = phi_961_;
                            local = _e704;
                            local_1 = _e704;
                            local_2 = _e706;
                            local_3 = _e706;
                            let _e707 = (_e702 < _e693);
                            if _e707 {
                                let _e712 = ((_e560 - floor(_e560)) + (f32((_e593 + (_e702 * _e693))) * 0.618034f));
                                let _e719 = (((_e712 - floor(_e712)) + f32(_e702)) * (1f / f32(_e693)));
                                let _e722 = params.member.member_4;
                                if (_e722 == 2f) {
                                    phi_1016_ = (_e719 * _e719);
                                } else {
                                    phi_1016_ = pow(_e719, _e722);
                                }
                                let _e727 = phi_1016_;
                                let _e728 = (_e727 + (1.3f / _e441));
                                let _e729 = ((_e605 * _e441) * _e728);
                                let _e730 = ((-(_e604) * _e441) * _e728);
                                let _e738 = params.member.member_7;
                                let _e739 = (log2(sqrt(((_e729 * _e729) + (_e730 * _e730)))) - _e738);
                                let _e746 = (-1f - floor((-0.5f - select(0f, select(5f, _e739, (_e739 < 5f)), (_e739 > 0f)))));
                                let _e748 = floor((_e729 + 0.5f));
                                let _e759 = (select(_e748, (_e748 - 1f), (((_e748 - _e729) == 0.5f) && ((floor((_e748 * 0.5f)) * 2f) != _e748))) * (1f / _e91));
                                let _e761 = floor((_e730 + 0.5f));
                                let _e772 = (select(_e761, (_e761 - 1f), (((_e761 - _e730) == 0.5f) && ((floor((_e761 * 0.5f)) * 2f) != _e761))) * (1f / _e101));
                                let _e773 = (_e323 + _e759);
                                let _e774 = (_e326 + _e772);
                                let _e775 = (_e323 - _e759);
                                let _e776 = (_e326 - _e772);
                                let _e778 = select(1u, _e96, (1u < _e96));
                                let _e780 = select(1u, _e106, (1u < _e106));
                                let _e783 = (_e778 * _e780);
                                let _e785 = (_e96 >> bitcast<u32>(1u));
                                let _e787 = select(1u, _e785, (1u < _e785));
                                let _e789 = (_e106 >> bitcast<u32>(1u));
                                let _e791 = select(1u, _e789, (1u < _e789));
                                let _e792 = (_e746 >= 1f);
                                let _e801 = (_e783 + (_e787 * _e791));
                                let _e803 = (_e96 >> bitcast<u32>(2u));
                                let _e805 = select(1u, _e803, (1u < _e803));
                                let _e807 = (_e106 >> bitcast<u32>(2u));
                                let _e809 = select(1u, _e807, (1u < _e807));
                                let _e810 = (_e746 >= 2f);
                                let _e819 = (_e801 + (_e805 * _e809));
                                let _e821 = (_e96 >> bitcast<u32>(3u));
                                let _e823 = select(1u, _e821, (1u < _e821));
                                let _e825 = (_e106 >> bitcast<u32>(3u));
                                let _e827 = select(1u, _e825, (1u < _e825));
                                let _e828 = (_e746 >= 3f);
                                let _e839 = (_e96 >> bitcast<u32>(4u));
                                let _e841 = select(1u, _e839, (1u < _e839));
                                let _e843 = (_e106 >> bitcast<u32>(4u));
                                let _e845 = select(1u, _e843, (1u < _e843));
                                let _e846 = (_e746 >= 4f);
                                let _e847 = select(select(select(select(_e778, _e787, _e792), _e805, _e810), _e823, _e828), _e841, _e846);
                                let _e849 = select(select(select(select(0u, _e783, _e792), _e801, _e810), _e819, _e828), (_e819 + (_e823 * _e827)), _e846);
                                let _e851 = select(select(select(select(f32(_e778), f32(_e787), _e792), f32(_e805), _e810), f32(_e823), _e828), f32(_e841), _e846);
                                let _e853 = select(select(select(select(f32(_e780), f32(_e791), _e792), f32(_e809), _e810), f32(_e827), _e828), f32(_e845), _e846);
                                let _e854 = (_e773 * _e851);
                                let _e856 = f32((_e847 - 1u));
                                let _e858 = select(0f, _e854, (_e854 > 0f));
                                let _e862 = (_e774 * _e853);
                                let _e864 = f32((select(select(select(select(_e780, _e791, _e792), _e809, _e810), _e827, _e828), _e845, _e846) - 1u));
                                let _e866 = select(0f, _e862, (_e862 > 0f));
                                let _e875 = mips.member[((_e849 + (u32(select(_e864, _e866, (_e866 < _e864))) * _e847)) + u32(select(_e856, _e858, (_e858 < _e856))))];
                                let _e884 = (_e775 * _e851);
                                let _e886 = select(0f, _e884, (_e884 > 0f));
                                let _e890 = (_e776 * _e853);
                                let _e892 = select(0f, _e890, (_e890 > 0f));
                                let _e901 = mips.member[((_e849 + (u32(select(_e864, _e892, (_e892 < _e864))) * _e847)) + u32(select(_e856, _e886, (_e886 < _e856))))];
                                let _e910 = (((((_e773 * 2f) - 1f) * _e334) * _e875) - _e336);
                                let _e911 = (((((_e774 * -2f) + 1f) * _e343) * _e875) - _e345);
                                let _e912 = (_e875 - _e327);
                                let _e915 = ((_e910 * _e910) + (_e911 * _e911));
                                let _e918 = sqrt((_e915 + (_e912 * _e912)));
                                let _e925 = (_e700 == 0f);
                                if _e925 {
                                    phi_1575_ = _e918;
                                } else {
                                    let _e927 = (_e912 * (1f + _e700));
                                    phi_1575_ = sqrt((_e915 + (_e927 * _e927)));
                                }
                                let _e932 = phi_1575_;
                                if _e574 {
                                    phi_1596_ = select(0f, 1f, (_e932 <= _e437));
                                } else {
                                    let _e936 = ((_e932 * _e578) + _e579);
                                    phi_1596_ = select(0f, select(1f, _e936, (_e936 < 1f)), (_e936 > 0f));
                                }
                                let _e942 = phi_1596_;
                                let _e945 = (_e695 + ((((((_e910 * _e356) + (_e911 * _e357)) + (_e912 * _e358)) / _e918) - _e695) * _e942));
                                let _e946 = (((((_e775 * 2f) - 1f) * _e334) * _e901) - _e336);
                                let _e947 = (((((_e776 * -2f) + 1f) * _e343) * _e901) - _e345);
                                let _e948 = (_e901 - _e327);
                                let _e951 = ((_e946 * _e946) + (_e947 * _e947));
                                let _e954 = sqrt((_e951 + (_e948 * _e948)));
                                if _e925 {
                                    phi_1635_ = _e954;
                                } else {
                                    let _e962 = (_e948 * (1f + _e700));
                                    phi_1635_ = sqrt((_e951 + (_e962 * _e962)));
                                }
                                let _e967 = phi_1635_;
                                if _e574 {
                                    phi_1656_ = select(0f, 1f, (_e967 <= _e437));
                                } else {
                                    let _e971 = ((_e967 * _e578) + _e579);
                                    phi_1656_ = select(0f, select(1f, _e971, (_e971 < 1f)), (_e971 > 0f));
                                }
                                let _e977 = phi_1656_;
                                let _e980 = (_e697 + ((((((_e946 * _e356) + (_e947 * _e357)) + (_e948 * _e358)) / _e954) - _e697) * _e977));
                                phi_957_ = (_e702 + 1u);
                                phi_960_ = select(_e980, _e704, ((_e704 > _e980) || (_e980 != _e980)));
                                phi_962_ = select(_e945, _e706, ((_e706 > _e945) || (_e945 != _e945)));
                            } else {
                                phi_957_ = u32();
                                phi_960_ = f32();
                                phi_962_ = f32();
                            }
                            let _e991 = phi_957_;
                            let _e993 = phi_960_;
                            let _e995 = phi_962_;
                            continue;
                            continuing {
                                phi_956_ = _e991;
                                phi_959_ = _e993;
                                phi_961_ = _e995;
                                break if !(_e707);
                            }
                        }
                        let _e998 = local;
                        let _e999 = abs(_e998);
                        let _e1010 = (((_e999 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e999))) >> bitcast<u32>(1i))))));
                        let _e1012 = local_1;
                        let _e1015 = select((3.141593f - _e1010), _e1010, (_e1012 >= 0f));
                        let _e1016 = -(_e1015);
                        let _e1018 = local_2;
                        let _e1019 = abs(_e1018);
                        let _e1030 = (((_e1019 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1019))) >> bitcast<u32>(1i))))));
                        let _e1032 = local_3;
                        let _e1035 = select((3.141593f - _e1030), _e1030, (_e1032 >= 0f));
                        let _e1038 = (_e653 + ((1f - _e653) * 0.05f));
                        let _e1039 = (_e1015 * -2f);
                        let _e1040 = sin(_e688);
                        let _e1046 = (_e1035 * 2f);
                        let _e1058 = params.member.member_13;
                        if (_e1058 == 0u) {
                            phi_1887_ = _e595;
                        } else {
                            let _e1064 = ((_e1015 * -3f) - _e688);
                            let _e1072 = ((_e1035 * 3f) - _e688);
                            let _e1077 = (_e1016 + _e688);
                            let _e1079 = (_e1035 + _e688);
                            let _e1084 = (((((((sin((_e1016 - _e688)) * 6f) - sin(_e1064)) + (sin((_e1035 - _e688)) * 6f)) - sin(_e1072)) + (_e1040 * 16f)) - ((sin(_e1077) + sin(_e1079)) * 3f)) * 0.083333336f);
                            let _e1096 = (((-(cos(_e1064)) - cos(_e1072)) + (cos(_e688) * 8f)) - ((cos(_e1077) + cos(_e1079)) * 3f));
                            let _e1097 = (_e605 * _e1084);
                            let _e1098 = (_e604 * _e1084);
                            let _e1099 = (_e1096 * -0.083333336f);
                            let _e1100 = (-1f * _e358);
                            let _e1101 = (-1f * _e356);
                            let _e1103 = (1f / (_e1100 + 1f));
                            let _e1104 = (_e1103 * _e357);
                            let _e1108 = (_e1104 * _e1101);
                            let _e1129 = (_e1100 > 0.9997f);
                            let _e1130 = (_e1100 < -0.9997f);
                            phi_1887_ = (_e595 + vec3<f32>((select(select(((((_e1100 + (_e1104 * _e357)) * _e1097) + (_e1108 * _e1098)) + (_e1101 * _e1099)), _e1097, _e1130), _e1097, _e1129) * _e1038), (select(select((((_e1108 * _e1097) + ((_e1100 + ((_e1103 * _e1101) * _e1101)) * _e1098)) + (-(_e357) * _e1099)), -(_e1098), _e1130), _e1098, _e1129) * _e1038), (select(select((((_e356 * _e1097) + (_e357 * _e1098)) + (_e1100 * _e1099)), (_e1096 * 0.083333336f), _e1130), _e1099, _e1129) * _e1038)));
                        }
                        let _e1143 = phi_1887_;
                        phi_781_ = (_e593 + 1u);
                        phi_784_ = _e1143;
                        phi_786_ = (_e597 + ((0.25f * (((_e672 + (_e1039 * _e1040)) - cos((_e1039 - _e688))) + ((_e672 + (_e1046 * _e1040)) - cos((_e1046 - _e688))))) * _e1038));
                    } else {
                        phi_781_ = u32();
                        phi_784_ = vec3<f32>();
                        phi_786_ = f32();
                    }
                    let _e1146 = phi_781_;
                    let _e1148 = phi_784_;
                    let _e1150 = phi_786_;
                    continue;
                    continuing {
                        phi_780_ = _e1146;
                        phi_783_ = _e1148;
                        phi_785_ = _e1150;
                        break if !(_e598);
                    }
                }
                let _e1154 = local_4;
                let _e1157 = local_5;
                phi_1893_ = type_23((_e1154 / f32(_e591)), _e1157);
            } else {
                phi_1893_ = type_23(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1160 = phi_1893_;
            if _e569 {
                let _e1165 = params.member.member_6;
                let _e1166 = pow(_e1160.member, _e1165);
                if (_e1166 != _e1166) {
                    phi_2743_ = true;
                } else {
                    phi_2743_ = (0.03f >= _e1166);
                }
                let _e1170 = phi_2743_;
                let _e1171 = select(_e1166, 0.03f, _e1170);
                let _e1174 = params.member.member_13;
                if (_e1174 == 0u) {
                    let _e1176 = (_e1171 * 0.6666667f);
                    let _e1182 = ((select(0f, select(1f, _e1176, (_e1176 < 1f)), (_e1176 > 0f)) * 255f) + 0.5f);
                    phi_1969_ = select(select(u32(_e1182), 0u, (_e1182 < 0f)), 4294967295u, (_e1182 > 4294967000f));
                } else {
                    let _e1196 = sqrt((((_e1160.member_1.x * _e1160.member_1.x) + (_e1160.member_1.y * _e1160.member_1.y)) + (_e1160.member_1.z * _e1160.member_1.z)));
                    if (_e1196 > 0f) {
                        phi_1948_ = (_e1160.member_1 / vec3(_e1196));
                    } else {
                        phi_1948_ = vec3<f32>(_e427, _e428, _e429);
                    }
                    let _e1201 = phi_1948_;
                    let _e1202 = (_e1171 * 0.6666667f);
                    let _e1209 = ((_e1201.x * 0.5f) + 0.5f);
                    let _e1210 = ((_e1201.y * 0.5f) + 0.5f);
                    let _e1211 = ((_e1201.z * 0.5f) + 0.5f);
                    let _e1217 = ((select(0f, select(1f, _e1209, (_e1209 < 1f)), (_e1209 > 0f)) * 255f) + 0.5f);
                    let _e1228 = ((select(0f, select(1f, _e1210, (_e1210 < 1f)), (_e1210 > 0f)) * 255f) + 0.5f);
                    let _e1242 = ((select(0f, select(1f, _e1211, (_e1211 < 1f)), (_e1211 > 0f)) * 255f) + 0.5f);
                    let _e1256 = ((select(0f, select(1f, _e1202, (_e1202 < 1f)), (_e1202 > 0f)) * 255f) + 0.5f);
                    phi_1969_ = (((select(select(u32(_e1217), 0u, (_e1217 < 0f)), 4294967295u, (_e1217 > 4294967000f)) | (select(select(u32(_e1228), 0u, (_e1228 < 0f)), 4294967295u, (_e1228 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1242), 0u, (_e1242 < 0f)), 4294967295u, (_e1242 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1256), 0u, (_e1256 < 0f)), 4294967295u, (_e1256 > 4294967000f)) << bitcast<u32>(24i)));
                }
                let _e1266 = phi_1969_;
                phi_2014_ = _e1266;
            } else {
                let _e1269 = params.member.member_13;
                phi_2014_ = select(2852159616u, 170u, (_e1269 == 0u));
            }
            let _e1273 = phi_2014_;
            terms.member[_e112] = _e1273;
            edges.member[_e112] = ((((64u * u32(select(3f, _e248, (_e248 < 3f)))) + (16u * u32(select(3f, _e270, (_e270 < 3f))))) + (4u * u32(select(3f, _e293, (_e293 < 3f))))) + u32(select(3f, _e316, (_e316 < 3f))));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
