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
    var phi_2369_: bool;
    var phi_2384_: bool;
    var phi_2344_: vec2<f32>;
    var phi_2401_: u32;
    var phi_2402_: u32;
    var phi_2403_: u32;
    var phi_2404_: u32;
    var phi_2427_: u32;
    var phi_2428_: u32;
    var phi_2431_: u32;
    var phi_2432_: u32;
    var phi_2436_: u32;
    var phi_2437_: u32;
    var phi_2438_: u32;
    var phi_2439_: u32;
    var local: u32;
    var phi_751_: f32;
    var phi_778_: u32;
    var phi_781_: vec3<f32>;
    var phi_783_: f32;
    var phi_954_: u32;
    var phi_957_: f32;
    var phi_959_: f32;
    var phi_1014_: f32;
    var phi_1573_: f32;
    var phi_1594_: f32;
    var phi_1633_: f32;
    var phi_1654_: f32;
    var phi_955_: u32;
    var phi_958_: f32;
    var phi_960_: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var local_4: f32;
    var phi_1885_: vec3<f32>;
    var phi_779_: u32;
    var phi_782_: vec3<f32>;
    var phi_784_: f32;
    var local_5: f32;
    var local_6: vec3<f32>;
    var phi_1891_: type_23;
    var phi_2485_: bool;
    var phi_1946_: vec3<f32>;
    var phi_1967_: u32;
    var phi_2012_: u32;

    let _e83 = id_1;
    let _e89 = params.member.member.member[0u];
    let _e94 = select(select(u32(_e89), 0u, (_e89 < 0f)), 4294967295u, (_e89 > 4294967000f));
    let _e99 = params.member.member.member[1u];
    let _e104 = select(select(u32(_e99), 0u, (_e99 < 0f)), 4294967295u, (_e99 > 4294967000f));
    if (_e83.x >= _e94) {
    } else {
        if (_e83.y >= _e104) {
        } else {
            let _e110 = ((_e83.y * _e94) + _e83.x);
            let _e112 = mips.member[_e110];
            let _e113 = bitcast<i32>(_e83.x);
            let _e114 = (_e113 + -1i);
            let _e116 = select(0i, _e114, (0i < _e114));
            let _e118 = (bitcast<i32>(_e94) - 1i);
            let _e122 = bitcast<i32>(_e83.y);
            let _e124 = select(0i, _e122, (0i < _e122));
            let _e126 = (bitcast<i32>(_e104) - 1i);
            let _e130 = (bitcast<u32>(select(_e124, _e126, (_e126 < _e124))) * _e94);
            let _e133 = mips.member[(_e130 + bitcast<u32>(select(_e116, _e118, (_e118 < _e116))))];
            let _e134 = (_e113 + 1i);
            let _e136 = select(0i, _e134, (0i < _e134));
            let _e142 = mips.member[(_e130 + bitcast<u32>(select(_e136, _e118, (_e118 < _e136))))];
            let _e144 = select(0i, _e113, (0i < _e113));
            let _e147 = bitcast<u32>(select(_e144, _e118, (_e118 < _e144)));
            let _e148 = (_e122 + -1i);
            let _e150 = select(0i, _e148, (0i < _e148));
            let _e157 = mips.member[((bitcast<u32>(select(_e150, _e126, (_e126 < _e150))) * _e94) + _e147)];
            let _e158 = (_e122 + 1i);
            let _e160 = select(0i, _e158, (0i < _e158));
            let _e167 = mips.member[((bitcast<u32>(select(_e160, _e126, (_e126 < _e160))) * _e94) + _e147)];
            let _e168 = (_e133 - _e112);
            let _e169 = (_e142 - _e112);
            let _e170 = (_e157 - _e112);
            let _e171 = (_e167 - _e112);
            let _e173 = ((_e169 - _e168) * 0.5f);
            let _e175 = ((_e171 - _e170) * 0.5f);
            let _e176 = (_e112 * 0.011f);
            let _e178 = abs(_e168);
            let _e179 = abs((_e168 + _e173));
            let _e185 = (1.25f - (select(_e179, _e178, ((_e178 < _e179) || (_e179 != _e179))) / _e176));
            let _e189 = select(0f, select(1f, _e185, (_e185 < 1f)), (_e185 > 0f));
            let _e191 = abs(_e169);
            let _e192 = abs((_e169 - _e173));
            let _e198 = (1.25f - (select(_e192, _e191, ((_e191 < _e192) || (_e192 != _e192))) / _e176));
            let _e202 = select(0f, select(1f, _e198, (_e198 < 1f)), (_e198 > 0f));
            let _e204 = abs(_e170);
            let _e205 = abs((_e170 + _e175));
            let _e211 = (1.25f - (select(_e205, _e204, ((_e204 < _e205) || (_e205 != _e205))) / _e176));
            let _e215 = select(0f, select(1f, _e211, (_e211 < 1f)), (_e211 > 0f));
            let _e217 = abs(_e171);
            let _e218 = abs((_e171 - _e175));
            let _e224 = (1.25f - (select(_e218, _e217, ((_e217 < _e218) || (_e218 != _e218))) / _e176));
            let _e228 = select(0f, select(1f, _e224, (_e224 < 1f)), (_e224 > 0f));
            let _e233 = (select(0f, select(1f, _e189, (_e189 < 1f)), (_e189 > 0f)) * 2.9f);
            let _e235 = floor((_e233 + 0.5f));
            let _e244 = select(_e235, (_e235 - 1f), (((_e235 - _e233) == 0.5f) && ((floor((_e235 * 0.5f)) * 2f) != _e235)));
            let _e246 = select(0f, _e244, (_e244 > 0f));
            let _e255 = (select(0f, select(1f, _e202, (_e202 < 1f)), (_e202 > 0f)) * 2.9f);
            let _e257 = floor((_e255 + 0.5f));
            let _e266 = select(_e257, (_e257 - 1f), (((_e257 - _e255) == 0.5f) && ((floor((_e257 * 0.5f)) * 2f) != _e257)));
            let _e268 = select(0f, _e266, (_e266 > 0f));
            let _e278 = (select(0f, select(1f, _e215, (_e215 < 1f)), (_e215 > 0f)) * 2.9f);
            let _e280 = floor((_e278 + 0.5f));
            let _e289 = select(_e280, (_e280 - 1f), (((_e280 - _e278) == 0.5f) && ((floor((_e280 * 0.5f)) * 2f) != _e280)));
            let _e291 = select(0f, _e289, (_e289 > 0f));
            let _e301 = (select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f)) * 2.9f);
            let _e303 = floor((_e301 + 0.5f));
            let _e312 = select(_e303, (_e303 - 1f), (((_e303 - _e301) == 0.5f) && ((floor((_e303 * 0.5f)) * 2f) != _e303)));
            let _e314 = select(0f, _e312, (_e312 > 0f));
            let _e321 = ((f32(_e83.x) + 0.5f) / _e89);
            let _e324 = ((f32(_e83.y) + 0.5f) / _e99);
            let _e325 = (_e112 * 0.99999f);
            let _e332 = params.member.member.member_1[0u];
            let _e334 = ((((_e321 * 2f) - 1f) * _e332) * _e325);
            let _e341 = params.member.member.member_1[1u];
            let _e343 = ((((_e324 * -2f) + 1f) * _e341) * _e325);
            let _e344 = -(_e334);
            let _e345 = -(_e343);
            let _e346 = (_e112 * -0.99999f);
            let _e353 = (1f / sqrt((((_e344 * _e344) + (_e345 * _e345)) + (_e346 * _e346))));
            let _e354 = (_e344 * _e353);
            let _e355 = (_e345 * _e353);
            let _e356 = (_e346 * _e353);
            let _e359 = normals.member[_e110];
            let _e367 = (f32((bitcast<i32>(((_e359 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e367 != _e367) {
                phi_2369_ = true;
            } else {
                phi_2369_ = (-1f >= _e367);
            }
            let _e371 = phi_2369_;
            let _e372 = select(_e367, -1f, _e371);
            let _e382 = (f32((bitcast<i32>((((_e359 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e382 != _e382) {
                phi_2384_ = true;
            } else {
                phi_2384_ = (-1f >= _e382);
            }
            let _e386 = phi_2384_;
            let _e387 = select(_e382, -1f, _e386);
            let _e390 = (1f - abs(_e372));
            let _e391 = abs(_e387);
            let _e392 = (_e390 - _e391);
            if (_e392 < 0f) {
                phi_2344_ = vec2<f32>(((1f - _e391) * select(1f, -1f, (_e372 < 0f))), (_e390 * select(1f, -1f, (_e387 < 0f))));
            } else {
                phi_2344_ = vec2<f32>(_e372, _e387);
            }
            let _e403 = phi_2344_;
            let _e412 = (1f / sqrt((((_e403.x * _e403.x) + (_e403.y * _e403.y)) + (_e392 * _e392))));
            let _e413 = (_e403.x * _e412);
            let _e414 = (_e403.y * _e412);
            let _e415 = (_e392 * _e412);
            let _e416 = -(_e415);
            let _e422 = ((((_e413 * _e354) + (_e414 * _e355)) + (_e416 * _e356)) < 0f);
            let _e425 = select(_e413, -(_e413), _e422);
            let _e426 = select(_e414, -(_e414), _e422);
            let _e427 = select(_e416, _e415, _e422);
            let _e431 = params.member.member_1;
            let _e434 = params.member.member_2;
            let _e435 = (_e431 * _e434);
            let _e439 = (_e435 / (((_e112 * 1.99998f) * _e332) / _e89));
            let _e443 = params.member.member_11;
            phi_2401_ = (_e83.y & 63u);
            phi_2402_ = (_e83.x & 63u);
            phi_2403_ = 32u;
            phi_2404_ = 0u;
            loop {
                let _e447 = phi_2401_;
                let _e449 = phi_2402_;
                let _e451 = phi_2403_;
                let _e453 = phi_2404_;
                local = _e453;
                let _e454 = (_e451 > 0u);
                if _e454 {
                    let _e457 = select(0u, 1u, ((_e449 & _e451) != 0u));
                    let _e460 = select(0u, 1u, ((_e447 & _e451) != 0u));
                    if (_e460 == 0u) {
                        if (_e457 == 1u) {
                            phi_2427_ = (63u - _e447);
                            phi_2428_ = (63u - _e449);
                        } else {
                            phi_2427_ = _e447;
                            phi_2428_ = _e449;
                        }
                        let _e471 = phi_2427_;
                        let _e473 = phi_2428_;
                        phi_2431_ = _e473;
                        phi_2432_ = _e471;
                    } else {
                        phi_2431_ = _e447;
                        phi_2432_ = _e449;
                    }
                    let _e475 = phi_2431_;
                    let _e477 = phi_2432_;
                    phi_2436_ = _e475;
                    phi_2437_ = _e477;
                    phi_2438_ = (_e451 / 2u);
                    phi_2439_ = (_e453 + ((_e451 * _e451) * ((3u * _e457) ^ _e460)));
                } else {
                    phi_2436_ = u32();
                    phi_2437_ = u32();
                    phi_2438_ = u32();
                    phi_2439_ = u32();
                }
                let _e480 = phi_2436_;
                let _e482 = phi_2437_;
                let _e484 = phi_2438_;
                let _e486 = phi_2439_;
                continue;
                continuing {
                    phi_2401_ = _e480;
                    phi_2402_ = _e482;
                    phi_2403_ = _e484;
                    phi_2404_ = _e486;
                    break if !(_e454);
                }
            }
            let _e491 = local;
            let _e493 = f32((_e491 + (288u * (_e443 % 64u))));
            let _e495 = (0.5f + (_e493 * 0.7548777f));
            let _e499 = (0.5f + (_e493 * 0.5698403f));
            let _e505 = params.member.member.member_3;
            let _e508 = select(false, (_e112 < _e505), (_e112 > 0f));
            if _e508 {
                let _e511 = params.member.member_3;
                let _e512 = (_e511 * _e435);
                let _e513 = (_e512 <= 0f);
                if _e513 {
                    phi_751_ = 0f;
                } else {
                    phi_751_ = (1f / _e512);
                }
                let _e516 = phi_751_;
                let _e517 = -(_e516);
                let _e518 = (_e435 * _e516);
                let _e520 = ((10f - _e439) * 0.01f);
                let _e528 = params.member.member_8;
                let _e530 = select(1u, _e528, (1u < _e528));
                phi_778_ = 0u;
                phi_781_ = vec3<f32>(0f, 0f, 0f);
                phi_783_ = (select(0f, select(1f, _e520, (_e520 < 1f)), (_e520 > 0f)) * 0.5f);
                loop {
                    let _e532 = phi_778_;
                    let _e534 = phi_781_;
                    let _e536 = phi_783_;
                    local_5 = _e536;
                    local_6 = _e534;
                    let _e537 = (_e532 < _e530);
                    if _e537 {
                        let _e542 = ((((_e495 - floor(_e495)) + f32(_e532)) * 3.1415927f) / f32(_e530));
                        let _e543 = sin(_e542);
                        let _e544 = cos(_e542);
                        let _e550 = ((_e544 * _e354) + (_e543 * _e355));
                        let _e554 = (_e544 - (_e354 * _e550));
                        let _e555 = (_e543 - (_e355 * _e550));
                        let _e556 = -((_e356 * _e550));
                        let _e559 = ((_e555 * _e356) - (_e355 * _e556));
                        let _e562 = ((_e556 * _e354) - (_e356 * _e554));
                        let _e565 = ((_e554 * _e355) - (_e354 * _e555));
                        let _e572 = (1f / sqrt((((_e559 * _e559) + (_e562 * _e562)) + (_e565 * _e565))));
                        let _e573 = (_e559 * _e572);
                        let _e574 = (_e562 * _e572);
                        let _e575 = (_e565 * _e572);
                        let _e580 = (((_e425 * _e573) + (_e426 * _e574)) + (_e427 * _e575));
                        let _e584 = (_e425 - (_e573 * _e580));
                        let _e585 = (_e426 - (_e574 * _e580));
                        let _e586 = (_e427 - (_e575 * _e580));
                        let _e592 = sqrt((((_e584 * _e584) + (_e585 * _e585)) + (_e586 * _e586)));
                        let _e597 = (((_e554 * _e584) + (_e555 * _e585)) + (_e556 * _e586));
                        let _e607 = ((((_e584 * _e354) + (_e585 * _e355)) + (_e586 * _e356)) / _e592);
                        let _e611 = select(0f, select(1f, _e607, (_e607 < 1f)), (_e607 > 0f));
                        let _e612 = abs(_e611);
                        let _e623 = (((_e612 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e612))) >> bitcast<u32>(1i))))));
                        let _e627 = (select(select(0f, -1f, (_e597 < 0f)), 1f, (_e597 > 0f)) * select((3.141593f - _e623), _e623, (_e611 >= 0f)));
                        let _e630 = params.member.member_9;
                        let _e632 = select(1u, _e630, (1u < _e630));
                        let _e634 = cos((_e627 + 1.5707964f));
                        let _e636 = cos((_e627 - 1.5707964f));
                        let _e639 = params.member.member_5;
                        phi_954_ = 0u;
                        phi_957_ = _e636;
                        phi_959_ = _e634;
                        loop {
                            let _e641 = phi_954_;
                            let _e643 = phi_957_;
                            let _e645 = phi_959_;
                            local_1 = _e643;
                            local_2 = _e643;
                            local_3 = _e645;
                            local_4 = _e645;
                            let _e646 = (_e641 < _e632);
                            if _e646 {
                                let _e651 = ((_e499 - floor(_e499)) + (f32((_e532 + (_e641 * _e632))) * 0.618034f));
                                let _e658 = (((_e651 - floor(_e651)) + f32(_e641)) * (1f / f32(_e632)));
                                let _e661 = params.member.member_4;
                                if (_e661 == 2f) {
                                    phi_1014_ = (_e658 * _e658);
                                } else {
                                    phi_1014_ = pow(_e658, _e661);
                                }
                                let _e666 = phi_1014_;
                                let _e667 = (_e666 + (1.3f / _e439));
                                let _e668 = ((_e544 * _e439) * _e667);
                                let _e669 = ((-(_e543) * _e439) * _e667);
                                let _e677 = params.member.member_7;
                                let _e678 = (log2(sqrt(((_e668 * _e668) + (_e669 * _e669)))) - _e677);
                                let _e685 = (-1f - floor((-0.5f - select(0f, select(5f, _e678, (_e678 < 5f)), (_e678 > 0f)))));
                                let _e687 = floor((_e668 + 0.5f));
                                let _e698 = (select(_e687, (_e687 - 1f), (((_e687 - _e668) == 0.5f) && ((floor((_e687 * 0.5f)) * 2f) != _e687))) * (1f / _e89));
                                let _e700 = floor((_e669 + 0.5f));
                                let _e711 = (select(_e700, (_e700 - 1f), (((_e700 - _e669) == 0.5f) && ((floor((_e700 * 0.5f)) * 2f) != _e700))) * (1f / _e99));
                                let _e712 = (_e321 + _e698);
                                let _e713 = (_e324 + _e711);
                                let _e714 = (_e321 - _e698);
                                let _e715 = (_e324 - _e711);
                                let _e717 = select(1u, _e94, (1u < _e94));
                                let _e719 = select(1u, _e104, (1u < _e104));
                                let _e722 = (_e717 * _e719);
                                let _e724 = (_e94 >> bitcast<u32>(1u));
                                let _e726 = select(1u, _e724, (1u < _e724));
                                let _e728 = (_e104 >> bitcast<u32>(1u));
                                let _e730 = select(1u, _e728, (1u < _e728));
                                let _e731 = (_e685 >= 1f);
                                let _e740 = (_e722 + (_e726 * _e730));
                                let _e742 = (_e94 >> bitcast<u32>(2u));
                                let _e744 = select(1u, _e742, (1u < _e742));
                                let _e746 = (_e104 >> bitcast<u32>(2u));
                                let _e748 = select(1u, _e746, (1u < _e746));
                                let _e749 = (_e685 >= 2f);
                                let _e758 = (_e740 + (_e744 * _e748));
                                let _e760 = (_e94 >> bitcast<u32>(3u));
                                let _e762 = select(1u, _e760, (1u < _e760));
                                let _e764 = (_e104 >> bitcast<u32>(3u));
                                let _e766 = select(1u, _e764, (1u < _e764));
                                let _e767 = (_e685 >= 3f);
                                let _e778 = (_e94 >> bitcast<u32>(4u));
                                let _e780 = select(1u, _e778, (1u < _e778));
                                let _e782 = (_e104 >> bitcast<u32>(4u));
                                let _e784 = select(1u, _e782, (1u < _e782));
                                let _e785 = (_e685 >= 4f);
                                let _e786 = select(select(select(select(_e717, _e726, _e731), _e744, _e749), _e762, _e767), _e780, _e785);
                                let _e788 = select(select(select(select(0u, _e722, _e731), _e740, _e749), _e758, _e767), (_e758 + (_e762 * _e766)), _e785);
                                let _e790 = select(select(select(select(f32(_e717), f32(_e726), _e731), f32(_e744), _e749), f32(_e762), _e767), f32(_e780), _e785);
                                let _e792 = select(select(select(select(f32(_e719), f32(_e730), _e731), f32(_e748), _e749), f32(_e766), _e767), f32(_e784), _e785);
                                let _e793 = (_e712 * _e790);
                                let _e795 = f32((_e786 - 1u));
                                let _e797 = select(0f, _e793, (_e793 > 0f));
                                let _e801 = (_e713 * _e792);
                                let _e803 = f32((select(select(select(select(_e719, _e730, _e731), _e748, _e749), _e766, _e767), _e784, _e785) - 1u));
                                let _e805 = select(0f, _e801, (_e801 > 0f));
                                let _e814 = mips.member[((_e788 + (u32(select(_e803, _e805, (_e805 < _e803))) * _e786)) + u32(select(_e795, _e797, (_e797 < _e795))))];
                                let _e823 = (_e714 * _e790);
                                let _e825 = select(0f, _e823, (_e823 > 0f));
                                let _e829 = (_e715 * _e792);
                                let _e831 = select(0f, _e829, (_e829 > 0f));
                                let _e840 = mips.member[((_e788 + (u32(select(_e803, _e831, (_e831 < _e803))) * _e786)) + u32(select(_e795, _e825, (_e825 < _e795))))];
                                let _e849 = (((((_e712 * 2f) - 1f) * _e332) * _e814) - _e334);
                                let _e850 = (((((_e713 * -2f) + 1f) * _e341) * _e814) - _e343);
                                let _e851 = (_e814 - _e325);
                                let _e854 = ((_e849 * _e849) + (_e850 * _e850));
                                let _e857 = sqrt((_e854 + (_e851 * _e851)));
                                let _e864 = (_e639 == 0f);
                                if _e864 {
                                    phi_1573_ = _e857;
                                } else {
                                    let _e866 = (_e851 * (1f + _e639));
                                    phi_1573_ = sqrt((_e854 + (_e866 * _e866)));
                                }
                                let _e871 = phi_1573_;
                                if _e513 {
                                    phi_1594_ = select(0f, 1f, (_e871 <= _e435));
                                } else {
                                    let _e875 = ((_e871 * _e517) + _e518);
                                    phi_1594_ = select(0f, select(1f, _e875, (_e875 < 1f)), (_e875 > 0f));
                                }
                                let _e881 = phi_1594_;
                                let _e884 = (_e634 + ((((((_e849 * _e354) + (_e850 * _e355)) + (_e851 * _e356)) / _e857) - _e634) * _e881));
                                let _e885 = (((((_e714 * 2f) - 1f) * _e332) * _e840) - _e334);
                                let _e886 = (((((_e715 * -2f) + 1f) * _e341) * _e840) - _e343);
                                let _e887 = (_e840 - _e325);
                                let _e890 = ((_e885 * _e885) + (_e886 * _e886));
                                let _e893 = sqrt((_e890 + (_e887 * _e887)));
                                if _e864 {
                                    phi_1633_ = _e893;
                                } else {
                                    let _e901 = (_e887 * (1f + _e639));
                                    phi_1633_ = sqrt((_e890 + (_e901 * _e901)));
                                }
                                let _e906 = phi_1633_;
                                if _e513 {
                                    phi_1654_ = select(0f, 1f, (_e906 <= _e435));
                                } else {
                                    let _e910 = ((_e906 * _e517) + _e518);
                                    phi_1654_ = select(0f, select(1f, _e910, (_e910 < 1f)), (_e910 > 0f));
                                }
                                let _e916 = phi_1654_;
                                let _e919 = (_e636 + ((((((_e885 * _e354) + (_e886 * _e355)) + (_e887 * _e356)) / _e893) - _e636) * _e916));
                                phi_955_ = (_e641 + 1u);
                                phi_958_ = select(_e919, _e643, ((_e643 > _e919) || (_e919 != _e919)));
                                phi_960_ = select(_e884, _e645, ((_e645 > _e884) || (_e884 != _e884)));
                            } else {
                                phi_955_ = u32();
                                phi_958_ = f32();
                                phi_960_ = f32();
                            }
                            let _e930 = phi_955_;
                            let _e932 = phi_958_;
                            let _e934 = phi_960_;
                            continue;
                            continuing {
                                phi_954_ = _e930;
                                phi_957_ = _e932;
                                phi_959_ = _e934;
                                break if !(_e646);
                            }
                        }
                        let _e937 = local_1;
                        let _e938 = abs(_e937);
                        let _e949 = (((_e938 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e938))) >> bitcast<u32>(1i))))));
                        let _e951 = local_2;
                        let _e954 = select((3.141593f - _e949), _e949, (_e951 >= 0f));
                        let _e955 = -(_e954);
                        let _e957 = local_3;
                        let _e958 = abs(_e957);
                        let _e969 = (((_e958 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e958))) >> bitcast<u32>(1i))))));
                        let _e971 = local_4;
                        let _e974 = select((3.141593f - _e969), _e969, (_e971 >= 0f));
                        let _e977 = (_e592 + ((1f - _e592) * 0.05f));
                        let _e978 = (_e954 * -2f);
                        let _e979 = sin(_e627);
                        let _e985 = (_e974 * 2f);
                        let _e997 = params.member.member_13;
                        if (_e997 == 0u) {
                            phi_1885_ = _e534;
                        } else {
                            let _e1003 = ((_e954 * -3f) - _e627);
                            let _e1011 = ((_e974 * 3f) - _e627);
                            let _e1016 = (_e955 + _e627);
                            let _e1018 = (_e974 + _e627);
                            let _e1023 = (((((((sin((_e955 - _e627)) * 6f) - sin(_e1003)) + (sin((_e974 - _e627)) * 6f)) - sin(_e1011)) + (_e979 * 16f)) - ((sin(_e1016) + sin(_e1018)) * 3f)) * 0.083333336f);
                            let _e1035 = (((-(cos(_e1003)) - cos(_e1011)) + (cos(_e627) * 8f)) - ((cos(_e1016) + cos(_e1018)) * 3f));
                            let _e1036 = (_e544 * _e1023);
                            let _e1037 = (_e543 * _e1023);
                            let _e1038 = (_e1035 * -0.083333336f);
                            let _e1039 = (-1f * _e356);
                            let _e1040 = (-1f * _e354);
                            let _e1042 = (1f / (_e1039 + 1f));
                            let _e1043 = (_e1042 * _e355);
                            let _e1047 = (_e1043 * _e1040);
                            let _e1068 = (_e1039 > 0.9997f);
                            let _e1069 = (_e1039 < -0.9997f);
                            phi_1885_ = (_e534 + vec3<f32>((select(select(((((_e1039 + (_e1043 * _e355)) * _e1036) + (_e1047 * _e1037)) + (_e1040 * _e1038)), _e1036, _e1069), _e1036, _e1068) * _e977), (select(select((((_e1047 * _e1036) + ((_e1039 + ((_e1042 * _e1040) * _e1040)) * _e1037)) + (-(_e355) * _e1038)), -(_e1037), _e1069), _e1037, _e1068) * _e977), (select(select((((_e354 * _e1036) + (_e355 * _e1037)) + (_e1039 * _e1038)), (_e1035 * 0.083333336f), _e1069), _e1038, _e1068) * _e977)));
                        }
                        let _e1082 = phi_1885_;
                        phi_779_ = (_e532 + 1u);
                        phi_782_ = _e1082;
                        phi_784_ = (_e536 + ((0.25f * (((_e611 + (_e978 * _e979)) - cos((_e978 - _e627))) + ((_e611 + (_e985 * _e979)) - cos((_e985 - _e627))))) * _e977));
                    } else {
                        phi_779_ = u32();
                        phi_782_ = vec3<f32>();
                        phi_784_ = f32();
                    }
                    let _e1085 = phi_779_;
                    let _e1087 = phi_782_;
                    let _e1089 = phi_784_;
                    continue;
                    continuing {
                        phi_778_ = _e1085;
                        phi_781_ = _e1087;
                        phi_783_ = _e1089;
                        break if !(_e537);
                    }
                }
                let _e1093 = local_5;
                let _e1096 = local_6;
                phi_1891_ = type_23((_e1093 / f32(_e530)), _e1096);
            } else {
                phi_1891_ = type_23(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1099 = phi_1891_;
            if _e508 {
                let _e1104 = params.member.member_6;
                let _e1105 = pow(_e1099.member, _e1104);
                if (_e1105 != _e1105) {
                    phi_2485_ = true;
                } else {
                    phi_2485_ = (0.03f >= _e1105);
                }
                let _e1109 = phi_2485_;
                let _e1110 = select(_e1105, 0.03f, _e1109);
                let _e1113 = params.member.member_13;
                if (_e1113 == 0u) {
                    let _e1115 = (_e1110 * 0.6666667f);
                    let _e1121 = ((select(0f, select(1f, _e1115, (_e1115 < 1f)), (_e1115 > 0f)) * 255f) + 0.5f);
                    phi_1967_ = select(select(u32(_e1121), 0u, (_e1121 < 0f)), 4294967295u, (_e1121 > 4294967000f));
                } else {
                    let _e1135 = sqrt((((_e1099.member_1.x * _e1099.member_1.x) + (_e1099.member_1.y * _e1099.member_1.y)) + (_e1099.member_1.z * _e1099.member_1.z)));
                    if (_e1135 > 0f) {
                        phi_1946_ = (_e1099.member_1 / vec3(_e1135));
                    } else {
                        phi_1946_ = vec3<f32>(_e425, _e426, _e427);
                    }
                    let _e1140 = phi_1946_;
                    let _e1141 = (_e1110 * 0.6666667f);
                    let _e1148 = ((_e1140.x * 0.5f) + 0.5f);
                    let _e1149 = ((_e1140.y * 0.5f) + 0.5f);
                    let _e1150 = ((_e1140.z * 0.5f) + 0.5f);
                    let _e1156 = ((select(0f, select(1f, _e1148, (_e1148 < 1f)), (_e1148 > 0f)) * 255f) + 0.5f);
                    let _e1167 = ((select(0f, select(1f, _e1149, (_e1149 < 1f)), (_e1149 > 0f)) * 255f) + 0.5f);
                    let _e1181 = ((select(0f, select(1f, _e1150, (_e1150 < 1f)), (_e1150 > 0f)) * 255f) + 0.5f);
                    let _e1195 = ((select(0f, select(1f, _e1141, (_e1141 < 1f)), (_e1141 > 0f)) * 255f) + 0.5f);
                    phi_1967_ = (((select(select(u32(_e1156), 0u, (_e1156 < 0f)), 4294967295u, (_e1156 > 4294967000f)) | (select(select(u32(_e1167), 0u, (_e1167 < 0f)), 4294967295u, (_e1167 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1181), 0u, (_e1181 < 0f)), 4294967295u, (_e1181 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1195), 0u, (_e1195 < 0f)), 4294967295u, (_e1195 > 4294967000f)) << bitcast<u32>(24i)));
                }
                let _e1205 = phi_1967_;
                phi_2012_ = _e1205;
            } else {
                let _e1208 = params.member.member_13;
                phi_2012_ = select(2852159616u, 170u, (_e1208 == 0u));
            }
            let _e1212 = phi_2012_;
            terms.member[_e110] = _e1212;
            edges.member[_e110] = ((((64u * u32(select(3f, _e246, (_e246 < 3f)))) + (16u * u32(select(3f, _e268, (_e268 < 3f))))) + (4u * u32(select(3f, _e291, (_e291 < 3f))))) + u32(select(3f, _e314, (_e314 < 3f))));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
