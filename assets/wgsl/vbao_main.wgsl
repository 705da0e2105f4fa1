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

struct type_21 {
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

struct type_22 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
}

struct type_23 {
    member: type_22,
}

struct type_25 {
    member: u32,
    member_1: f32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;
@group(0) @binding(4) 
var<uniform> params: type_23;

fn function_() {
    var local: array<type_25, 4>;
    var phi_2540_: bool;
    var phi_2555_: bool;
    var phi_2570_: bool;
    var phi_2585_: bool;
    var phi_2616_: f32;
    var phi_2620_: f32;
    var phi_2621_: bool;
    var phi_2643_: u32;
    var phi_2670_: f32;
    var phi_2674_: f32;
    var phi_2675_: bool;
    var phi_2697_: u32;
    var phi_2724_: f32;
    var phi_2728_: f32;
    var phi_2729_: bool;
    var phi_2751_: u32;
    var phi_2778_: f32;
    var phi_2782_: f32;
    var phi_2783_: bool;
    var phi_2805_: u32;
    var phi_2884_: bool;
    var phi_2899_: bool;
    var phi_2860_: vec2<f32>;
    var phi_2916_: u32;
    var phi_2917_: u32;
    var phi_2918_: u32;
    var phi_2919_: u32;
    var phi_2942_: u32;
    var phi_2943_: u32;
    var phi_2946_: u32;
    var phi_2947_: u32;
    var phi_2951_: u32;
    var phi_2952_: u32;
    var phi_2953_: u32;
    var phi_2954_: u32;
    var local_1: u32;
    var phi_3303_: bool;
    var phi_880_: u32;
    var phi_883_: f32;
    var phi_885_: f32;
    var phi_1080_: u32;
    var phi_1083_: u32;
    var phi_1137_: f32;
    var phi_1182_: f32;
    var phi_1184_: f32;
    var phi_1185_: bool;
    var phi_1208_: f32;
    var phi_1210_: f32;
    var phi_1211_: bool;
    var phi_1244_: u32;
    var phi_1260_: u32;
    var phi_1263_: u32;
    var phi_1261_: u32;
    var phi_1264_: u32;
    var phi_1308_: u32;
    var phi_1327_: u32;
    var local_2: u32;
    var phi_1366_: u32;
    var phi_1382_: u32;
    var phi_1385_: u32;
    var phi_1383_: u32;
    var phi_1386_: u32;
    var phi_1430_: u32;
    var phi_1449_: u32;
    var local_3: u32;
    var phi_1493_: bool;
    var phi_2988_: bool;
    var phi_3003_: bool;
    var phi_3018_: bool;
    var phi_3033_: bool;
    var phi_3048_: bool;
    var phi_1814_: f32;
    var phi_1832_: u32;
    var phi_1850_: u32;
    var phi_1866_: u32;
    var phi_1869_: u32;
    var phi_1870_: u32;
    var phi_1871_: bool;
    var phi_1885_: u32;
    var phi_1909_: bool;
    var phi_3063_: bool;
    var phi_3078_: bool;
    var phi_3093_: bool;
    var phi_3108_: bool;
    var phi_3123_: bool;
    var phi_2230_: f32;
    var phi_2248_: u32;
    var phi_2266_: u32;
    var phi_2282_: u32;
    var phi_2285_: u32;
    var phi_2286_: u32;
    var phi_2287_: bool;
    var phi_2301_: u32;
    var phi_1081_: u32;
    var phi_1084_: u32;
    var local_4: u32;
    var phi_2385_: u32;
    var phi_2388_: f32;
    var local_5: u32;
    var phi_2386_: u32;
    var phi_2389_: f32;
    var phi_3182_: bool;
    var local_6: f32;
    var phi_3392_: bool;
    var phi_2438_: f32;
    var phi_2439_: f32;
    var phi_2332_: u32;
    var phi_2335_: f32;
    var phi_2337_: f32;
    var local_7: u32;
    var phi_2333_: u32;
    var phi_2336_: f32;
    var phi_2338_: f32;
    var local_8: f32;
    var phi_3386_: bool;
    var phi_2440_: f32;
    var phi_2441_: f32;
    var phi_3385_: bool;
    var phi_881_: u32;
    var phi_884_: f32;
    var phi_886_: f32;
    var phi_3384_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var phi_2449_: f32;
    var phi_3156_: bool;
    var phi_2498_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e92 = id_1;
            let _e105 = params.member.member_4.member.member[0u];
            let _e110 = select(select(u32(_e105), 0u, (_e105 < 0f)), 4294967295u, (_e105 > 4294967000f));
            let _e116 = params.member.member_4.member.member[1u];
            let _e121 = select(select(u32(_e116), 0u, (_e116 < 0f)), 4294967295u, (_e116 > 4294967000f));
            if (_e92.x >= _e110) {
            } else {
                if (_e92.y >= _e121) {
                } else {
                    let _e127 = ((_e92.y * _e110) + _e92.x);
                    let _e129 = mips.member[_e127];
                    let _e130 = bitcast<i32>(_e92.x);
                    let _e131 = (_e130 + -1i);
                    let _e133 = select(0i, _e131, (0i < _e131));
                    let _e135 = (bitcast<i32>(_e110) - 1i);
                    let _e139 = bitcast<i32>(_e92.y);
                    let _e141 = select(0i, _e139, (0i < _e139));
                    let _e143 = (bitcast<i32>(_e121) - 1i);
                    let _e147 = (bitcast<u32>(select(_e141, _e143, (_e143 < _e141))) * _e110);
                    let _e150 = mips.member[(_e147 + bitcast<u32>(select(_e133, _e135, (_e135 < _e133))))];
                    let _e151 = (_e130 + 1i);
                    let _e153 = select(0i, _e151, (0i < _e151));
                    let _e159 = mips.member[(_e147 + bitcast<u32>(select(_e153, _e135, (_e135 < _e153))))];
                    let _e161 = select(0i, _e130, (0i < _e130));
                    let _e164 = bitcast<u32>(select(_e161, _e135, (_e135 < _e161)));
                    let _e165 = (_e139 + -1i);
                    let _e167 = select(0i, _e165, (0i < _e165));
                    let _e174 = mips.member[((bitcast<u32>(select(_e167, _e143, (_e143 < _e167))) * _e110) + _e164)];
                    let _e175 = (_e139 + 1i);
                    let _e177 = select(0i, _e175, (0i < _e175));
                    let _e184 = mips.member[((bitcast<u32>(select(_e177, _e143, (_e143 < _e177))) * _e110) + _e164)];
                    let _e185 = (_e150 - _e129);
                    let _e186 = (_e159 - _e129);
                    let _e187 = (_e174 - _e129);
                    let _e188 = (_e184 - _e129);
                    let _e190 = ((_e186 - _e185) * 0.5f);
                    let _e192 = ((_e188 - _e187) * 0.5f);
                    let _e193 = (_e129 * 0.011f);
                    let _e195 = abs(_e185);
                    let _e196 = abs((_e185 + _e190));
                    if (_e195 != _e195) {
                        phi_2540_ = true;
                    } else {
                        phi_2540_ = (_e196 <= _e195);
                    }
                    let _e200 = phi_2540_;
                    let _e203 = (1.25f - (select(_e195, _e196, _e200) / _e193));
                    let _e207 = select(0f, select(1f, _e203, (_e203 < 1f)), (_e203 > 0f));
                    let _e209 = abs(_e186);
                    let _e210 = abs((_e186 - _e190));
                    if (_e209 != _e209) {
                        phi_2555_ = true;
                    } else {
                        phi_2555_ = (_e210 <= _e209);
                    }
                    let _e214 = phi_2555_;
                    let _e217 = (1.25f - (select(_e209, _e210, _e214) / _e193));
                    let _e221 = select(0f, select(1f, _e217, (_e217 < 1f)), (_e217 > 0f));
                    let _e223 = abs(_e187);
                    let _e224 = abs((_e187 + _e192));
                    if (_e223 != _e223) {
                        phi_2570_ = true;
                    } else {
                        phi_2570_ = (_e224 <= _e223);
                    }
                    let _e228 = phi_2570_;
                    let _e231 = (1.25f - (select(_e223, _e224, _e228) / _e193));
                    let _e235 = select(0f, select(1f, _e231, (_e231 < 1f)), (_e231 > 0f));
                    let _e237 = abs(_e188);
                    let _e238 = abs((_e188 - _e192));
                    if (_e237 != _e237) {
                        phi_2585_ = true;
                    } else {
                        phi_2585_ = (_e238 <= _e237);
                    }
                    let _e242 = phi_2585_;
                    let _e245 = (1.25f - (select(_e237, _e238, _e242) / _e193));
                    let _e249 = select(0f, select(1f, _e245, (_e245 < 1f)), (_e245 > 0f));
                    let _e254 = (select(0f, select(1f, _e207, (_e207 < 1f)), (_e207 > 0f)) * 2.9f);
                    let _e256 = floor((_e254 + 0.5f));
                    if ((_e256 - _e254) == 0.5f) {
                        let _e262 = ((floor((_e256 * 0.5f)) * 2f) != _e256);
                        if _e262 {
                            phi_2616_ = (_e256 - 1f);
                        } else {
                            phi_2616_ = f32();
                        }
                        let _e265 = phi_2616_;
                        phi_2620_ = _e265;
                        phi_2621_ = select(true, false, _e262);
                    } else {
                        phi_2620_ = f32();
                        phi_2621_ = true;
                    }
                    let _e268 = phi_2620_;
                    let _e270 = phi_2621_;
                    let _e271 = select(_e268, _e256, _e270);
                    if (_e271 > 0f) {
                        let _e277 = select(select(u32(_e271), 0u, (_e271 < 0f)), 4294967295u, (_e271 > 4294967000f));
                        phi_2643_ = select(_e277, 3u, (3u < _e277));
                    } else {
                        phi_2643_ = 0u;
                    }
                    let _e281 = phi_2643_;
                    let _e287 = (select(0f, select(1f, _e221, (_e221 < 1f)), (_e221 > 0f)) * 2.9f);
                    let _e289 = floor((_e287 + 0.5f));
                    if ((_e289 - _e287) == 0.5f) {
                        let _e295 = ((floor((_e289 * 0.5f)) * 2f) != _e289);
                        if _e295 {
                            phi_2670_ = (_e289 - 1f);
                        } else {
                            phi_2670_ = f32();
                        }
                        let _e298 = phi_2670_;
                        phi_2674_ = _e298;
                        phi_2675_ = select(true, false, _e295);
                    } else {
                        phi_2674_ = f32();
                        phi_2675_ = true;
                    }
                    let _e301 = phi_2674_;
                    let _e303 = phi_2675_;
                    let _e304 = select(_e301, _e289, _e303);
                    if (_e304 > 0f) {
                        let _e310 = select(select(u32(_e304), 0u, (_e304 < 0f)), 4294967295u, (_e304 > 4294967000f));
                        phi_2697_ = select(_e310, 3u, (3u < _e310));
                    } else {
                        phi_2697_ = 0u;
                    }
                    let _e314 = phi_2697_;
                    let _e321 = (select(0f, select(1f, _e235, (_e235 < 1f)), (_e235 > 0f)) * 2.9f);
                    let _e323 = floor((_e321 + 0.5f));
                    if ((_e323 - _e321) == 0.5f) {
                        let _e329 = ((floor((_e323 * 0.5f)) * 2f) != _e323);
                        if _e329 {
                            phi_2724_ = (_e323 - 1f);
                        } else {
                            phi_2724_ = f32();
                        }
                        let _e332 = phi_2724_;
                        phi_2728_ = _e332;
                        phi_2729_ = select(true, false, _e329);
                    } else {
                        phi_2728_ = f32();
                        phi_2729_ = true;
                    }
                    let _e335 = phi_2728_;
                    let _e337 = phi_2729_;
                    let _e338 = select(_e335, _e323, _e337);
                    if (_e338 > 0f) {
                        let _e344 = select(select(u32(_e338), 0u, (_e338 < 0f)), 4294967295u, (_e338 > 4294967000f));
                        phi_2751_ = select(_e344, 3u, (3u < _e344));
                    } else {
                        phi_2751_ = 0u;
                    }
                    let _e348 = phi_2751_;
                    let _e355 = (select(0f, select(1f, _e249, (_e249 < 1f)), (_e249 > 0f)) * 2.9f);
                    let _e357 = floor((_e355 + 0.5f));
                    if ((_e357 - _e355) == 0.5f) {
                        let _e363 = ((floor((_e357 * 0.5f)) * 2f) != _e357);
                        if _e363 {
                            phi_2778_ = (_e357 - 1f);
                        } else {
                            phi_2778_ = f32();
                        }
                        let _e366 = phi_2778_;
                        phi_2782_ = _e366;
                        phi_2783_ = select(true, false, _e363);
                    } else {
                        phi_2782_ = f32();
                        phi_2783_ = true;
                    }
                    let _e369 = phi_2782_;
                    let _e371 = phi_2783_;
                    let _e372 = select(_e369, _e357, _e371);
                    if (_e372 > 0f) {
                        let _e378 = select(select(u32(_e372), 0u, (_e372 < 0f)), 4294967295u, (_e372 > 4294967000f));
                        phi_2805_ = select(_e378, 3u, (3u < _e378));
                    } else {
                        phi_2805_ = 0u;
                    }
                    let _e382 = phi_2805_;
                    let _e386 = ((f32(_e92.x) + 0.5f) / _e105);
                    let _e389 = ((f32(_e92.y) + 0.5f) / _e116);
                    let _e390 = (_e129 * 0.99999f);
                    let _e398 = params.member.member_4.member.member_1[0u];
                    let _e400 = ((((_e386 * 2f) - 1f) * _e398) * _e390);
                    let _e408 = params.member.member_4.member.member_1[1u];
                    let _e410 = ((((_e389 * -2f) + 1f) * _e408) * _e390);
                    let _e411 = -(_e400);
                    let _e412 = -(_e410);
                    let _e413 = (_e129 * -0.99999f);
                    let _e420 = (1f / sqrt((((_e411 * _e411) + (_e412 * _e412)) + (_e413 * _e413))));
                    let _e421 = (_e411 * _e420);
                    let _e422 = (_e412 * _e420);
                    let _e423 = (_e413 * _e420);
                    if (_e127 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e427 = normals.member[_e127];
                    let _e435 = (f32((bitcast<i32>(((_e427 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e435 != _e435) {
                        phi_2884_ = true;
                    } else {
                        phi_2884_ = (-1f >= _e435);
                    }
                    let _e439 = phi_2884_;
                    let _e440 = select(_e435, -1f, _e439);
                    let _e450 = (f32((bitcast<i32>((((_e427 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e450 != _e450) {
                        phi_2899_ = true;
                    } else {
                        phi_2899_ = (-1f >= _e450);
                    }
                    let _e454 = phi_2899_;
                    let _e455 = select(_e450, -1f, _e454);
                    let _e458 = (1f - abs(_e440));
                    let _e459 = abs(_e455);
                    let _e460 = (_e458 - _e459);
                    if (_e460 < 0f) {
                        phi_2860_ = vec2<f32>(((1f - _e459) * select(1f, -1f, (_e440 < 0f))), (_e458 * select(1f, -1f, (_e455 < 0f))));
                    } else {
                        phi_2860_ = vec2<f32>(_e440, _e455);
                    }
                    let _e471 = phi_2860_;
                    let _e480 = (1f / sqrt((((_e471.x * _e471.x) + (_e471.y * _e471.y)) + (_e460 * _e460))));
                    let _e481 = (_e471.x * _e480);
                    let _e482 = (_e471.y * _e480);
                    let _e483 = (_e460 * _e480);
                    let _e484 = -(_e483);
                    let _e490 = ((((_e481 * _e421) + (_e482 * _e422)) + (_e484 * _e423)) < 0f);
                    let _e493 = select(_e481, -(_e481), _e490);
                    let _e494 = select(_e482, -(_e482), _e490);
                    let _e495 = select(_e484, _e483, _e490);
                    let _e499 = params.member.member_4.member_1;
                    let _e503 = params.member.member_4.member_2;
                    let _e508 = ((_e499 * _e503) / (((_e129 * 1.99998f) * _e398) / _e105));
                    let _e513 = params.member.member_4.member_11;
                    phi_2916_ = (_e92.y & 63u);
                    phi_2917_ = (_e92.x & 63u);
                    phi_2918_ = 32u;
                    phi_2919_ = 0u;
                    loop {
                        let _e517 = phi_2916_;
                        let _e519 = phi_2917_;
                        let _e521 = phi_2918_;
                        let _e523 = phi_2919_;
                        local_1 = _e523;
                        let _e524 = (_e521 > 0u);
                        if _e524 {
                            let _e527 = select(0u, 1u, ((_e519 & _e521) != 0u));
                            let _e530 = select(0u, 1u, ((_e517 & _e521) != 0u));
                            if (_e530 == 0u) {
                                if (_e527 == 1u) {
                                    phi_2942_ = (63u - _e517);
                                    phi_2943_ = (63u - _e519);
                                } else {
                                    phi_2942_ = _e517;
                                    phi_2943_ = _e519;
                                }
                                let _e541 = phi_2942_;
                                let _e543 = phi_2943_;
                                phi_2946_ = _e543;
                                phi_2947_ = _e541;
                            } else {
                                phi_2946_ = _e517;
                                phi_2947_ = _e519;
                            }
                            let _e545 = phi_2946_;
                            let _e547 = phi_2947_;
                            phi_2951_ = _e545;
                            phi_2952_ = _e547;
                            phi_2953_ = (_e521 / 2u);
                            phi_2954_ = (_e523 + ((_e521 * _e521) * ((3u * _e527) ^ _e530)));
                        } else {
                            phi_2951_ = u32();
                            phi_2952_ = u32();
                            phi_2953_ = u32();
                            phi_2954_ = u32();
                        }
                        let _e550 = phi_2951_;
                        let _e552 = phi_2952_;
                        let _e554 = phi_2953_;
                        let _e556 = phi_2954_;
                        continue;
                        continuing {
                            phi_2916_ = _e550;
                            phi_2917_ = _e552;
                            phi_2918_ = _e554;
                            phi_2919_ = _e556;
                            break if !(_e524);
                        }
                    }
                    let _e561 = local_1;
                    let _e563 = f32((_e561 + (288u * (_e513 % 64u))));
                    let _e565 = (0.5f + (_e563 * 0.7548777f));
                    let _e569 = (0.5f + (_e563 * 0.5698403f));
                    let _e576 = params.member.member_4.member.member_3;
                    let _e579 = select(false, (_e129 < _e576), (_e129 > 0f));
                    if _e579 {
                        let _e583 = params.member.member_4.member_8;
                        let _e585 = select(1u, _e583, (1u < _e583));
                        phi_3303_ = false;
                        phi_880_ = 0u;
                        phi_883_ = 0f;
                        phi_885_ = 0f;
                        loop {
                            let _e587 = phi_3303_;
                            let _e589 = phi_880_;
                            let _e591 = phi_883_;
                            let _e593 = phi_885_;
                            local_9 = _e591;
                            local_10 = _e593;
                            local_11 = _e591;
                            let _e594 = (_e589 < _e585);
                            if _e594 {
                                let _e599 = ((((_e565 - floor(_e565)) + f32(_e589)) * 3.1415927f) / f32(_e585));
                                let _e600 = sin(_e599);
                                let _e601 = cos(_e599);
                                let _e607 = ((_e601 * _e421) + (_e600 * _e422));
                                let _e611 = (_e601 - (_e421 * _e607));
                                let _e612 = (_e600 - (_e422 * _e607));
                                let _e613 = -((_e423 * _e607));
                                let _e616 = ((_e612 * _e423) - (_e422 * _e613));
                                let _e619 = ((_e613 * _e421) - (_e423 * _e611));
                                let _e622 = ((_e611 * _e422) - (_e421 * _e612));
                                let _e629 = (1f / sqrt((((_e616 * _e616) + (_e619 * _e619)) + (_e622 * _e622))));
                                let _e630 = (_e616 * _e629);
                                let _e631 = (_e619 * _e629);
                                let _e632 = (_e622 * _e629);
                                let _e637 = (((_e493 * _e630) + (_e494 * _e631)) + (_e495 * _e632));
                                let _e641 = (_e493 - (_e630 * _e637));
                                let _e642 = (_e494 - (_e631 * _e637));
                                let _e643 = (_e495 - (_e632 * _e637));
                                let _e649 = sqrt((((_e641 * _e641) + (_e642 * _e642)) + (_e643 * _e643)));
                                let _e654 = (((_e611 * _e641) + (_e612 * _e642)) + (_e613 * _e643));
                                let _e664 = ((((_e641 * _e421) + (_e642 * _e422)) + (_e643 * _e423)) / _e649);
                                let _e668 = select(0f, select(1f, _e664, (_e664 < 1f)), (_e664 > 0f));
                                let _e669 = abs(_e668);
                                let _e687 = (((((((((((((((_e669 * -0.0012624911f) + 0.00667009f) * _e669) - 0.017088126f) * _e669) + 0.03089188f) * _e669) - 0.050174303f) * _e669) + 0.08897899f) * _e669) - 0.2145988f) * _e669) + 1.5707963f) * sqrt((1f - _e669)));
                                let _e690 = (select(select(0f, -1f, (_e654 < 0f)), 1f, (_e654 > 0f)) * select((3.1415927f - _e687), _e687, (_e668 >= 0f)));
                                let _e694 = params.member.member_4.member_9;
                                let _e696 = select(1u, _e694, (1u < _e694));
                                phi_1080_ = 0u;
                                phi_1083_ = 0u;
                                loop {
                                    let _e698 = phi_1080_;
                                    let _e700 = phi_1083_;
                                    local_4 = _e700;
                                    local_5 = _e700;
                                    local_7 = _e700;
                                    let _e701 = (_e698 < _e696);
                                    if _e701 {
                                        let _e706 = ((_e569 - floor(_e569)) + (f32((_e589 + (_e698 * _e696))) * 0.618034f));
                                        let _e712 = (((_e706 - floor(_e706)) + f32(_e698)) / f32(_e696));
                                        let _e716 = params.member.member_4.member_4;
                                        if (_e716 == 2f) {
                                            phi_1137_ = (_e712 * _e712);
                                        } else {
                                            phi_1137_ = pow(_e712, _e716);
                                        }
                                        let _e721 = phi_1137_;
                                        let _e722 = (_e721 + (1.3f / _e508));
                                        let _e723 = ((_e601 * _e508) * _e722);
                                        let _e724 = ((-(_e600) * _e508) * _e722);
                                        let _e733 = params.member.member_4.member_7;
                                        let _e734 = (log2(sqrt(((_e723 * _e723) + (_e724 * _e724)))) - _e733);
                                        let _e741 = (-1f - floor((-0.5f - select(0f, select(5f, _e734, (_e734 < 5f)), (_e734 > 0f)))));
                                        let _e743 = floor((_e723 + 0.5f));
                                        if ((_e743 - _e723) == 0.5f) {
                                            let _e749 = ((floor((_e743 * 0.5f)) * 2f) != _e743);
                                            if _e749 {
                                                phi_1182_ = (_e743 - 1f);
                                            } else {
                                                phi_1182_ = f32();
                                            }
                                            let _e752 = phi_1182_;
                                            phi_1184_ = _e752;
                                            phi_1185_ = select(true, false, _e749);
                                        } else {
                                            phi_1184_ = f32();
                                            phi_1185_ = true;
                                        }
                                        let _e755 = phi_1184_;
                                        let _e757 = phi_1185_;
                                        let _e759 = (select(_e755, _e743, _e757) / _e105);
                                        let _e761 = floor((_e724 + 0.5f));
                                        if ((_e761 - _e724) == 0.5f) {
                                            let _e767 = ((floor((_e761 * 0.5f)) * 2f) != _e761);
                                            if _e767 {
                                                phi_1208_ = (_e761 - 1f);
                                            } else {
                                                phi_1208_ = f32();
                                            }
                                            let _e770 = phi_1208_;
                                            phi_1210_ = _e770;
                                            phi_1211_ = select(true, false, _e767);
                                        } else {
                                            phi_1210_ = f32();
                                            phi_1211_ = true;
                                        }
                                        let _e773 = phi_1210_;
                                        let _e775 = phi_1211_;
                                        let _e777 = (select(_e773, _e761, _e775) / _e116);
                                        let _e778 = (_e386 + _e759);
                                        let _e779 = (_e389 + _e777);
                                        let _e780 = (_e386 - _e759);
                                        let _e781 = (_e389 - _e777);
                                        let _e782 = (_e741 > 0f);
                                        if _e782 {
                                            let _e787 = select(select(u32(_e741), 0u, (_e741 < 0f)), 4294967295u, (_e741 > 4294967000f));
                                            phi_1244_ = select(_e787, 4u, (4u < _e787));
                                        } else {
                                            phi_1244_ = 0u;
                                        }
                                        let _e791 = phi_1244_;
                                        let _e792 = (_e791 & 31u);
                                        let _e794 = (_e110 >> bitcast<u32>(_e792));
                                        let _e796 = select(1u, _e794, (1u < _e794));
                                        let _e798 = (_e121 >> bitcast<u32>(_e792));
                                        let _e800 = select(1u, _e798, (1u < _e798));
                                        phi_1260_ = 0u;
                                        phi_1263_ = 0u;
                                        loop {
                                            let _e802 = phi_1260_;
                                            let _e804 = phi_1263_;
                                            local_2 = _e804;
                                            let _e805 = (_e802 < _e791);
                                            if _e805 {
                                                let _e806 = (_e802 & 31u);
                                                let _e808 = (_e110 >> bitcast<u32>(_e806));
                                                let _e812 = (_e121 >> bitcast<u32>(_e806));
                                                phi_1261_ = (_e802 + 1u);
                                                phi_1264_ = (_e804 + (select(1u, _e808, (1u < _e808)) * select(1u, _e812, (1u < _e812))));
                                            } else {
                                                phi_1261_ = u32();
                                                phi_1264_ = u32();
                                            }
                                            let _e819 = phi_1261_;
                                            let _e821 = phi_1264_;
                                            continue;
                                            continuing {
                                                phi_1260_ = _e819;
                                                phi_1263_ = _e821;
                                                break if !(_e805);
                                            }
                                        }
                                        let _e825 = (_e778 * f32(_e796));
                                        if (_e825 > 0f) {
                                            let _e831 = select(select(u32(_e825), 0u, (_e825 < 0f)), 4294967295u, (_e825 > 4294967000f));
                                            let _e832 = (_e796 - 1u);
                                            phi_1308_ = select(_e831, _e832, (_e832 < _e831));
                                        } else {
                                            phi_1308_ = 0u;
                                        }
                                        let _e836 = phi_1308_;
                                        let _e837 = (_e779 * f32(_e800));
                                        if (_e837 > 0f) {
                                            let _e843 = select(select(u32(_e837), 0u, (_e837 < 0f)), 4294967295u, (_e837 > 4294967000f));
                                            let _e844 = (_e800 - 1u);
                                            phi_1327_ = select(_e843, _e844, (_e844 < _e843));
                                        } else {
                                            phi_1327_ = 0u;
                                        }
                                        let _e848 = phi_1327_;
                                        let _e851 = local_2;
                                        let _e856 = mips.member[((_e851 + (_e848 * _e796)) + _e836)];
                                        if _e782 {
                                            let _e869 = select(select(u32(_e741), 0u, (_e741 < 0f)), 4294967295u, (_e741 > 4294967000f));
                                            phi_1366_ = select(_e869, 4u, (4u < _e869));
                                        } else {
                                            phi_1366_ = 0u;
                                        }
                                        let _e873 = phi_1366_;
                                        let _e874 = (_e873 & 31u);
                                        let _e876 = (_e110 >> bitcast<u32>(_e874));
                                        let _e878 = select(1u, _e876, (1u < _e876));
                                        let _e880 = (_e121 >> bitcast<u32>(_e874));
                                        let _e882 = select(1u, _e880, (1u < _e880));
                                        phi_1382_ = 0u;
                                        phi_1385_ = 0u;
                                        loop {
                                            let _e884 = phi_1382_;
                                            let _e886 = phi_1385_;
                                            local_3 = _e886;
                                            let _e887 = (_e884 < _e873);
                                            if _e887 {
                                                let _e888 = (_e884 & 31u);
                                                let _e890 = (_e110 >> bitcast<u32>(_e888));
                                                let _e894 = (_e121 >> bitcast<u32>(_e888));
                                                phi_1383_ = (_e884 + 1u);
                                                phi_1386_ = (_e886 + (select(1u, _e890, (1u < _e890)) * select(1u, _e894, (1u < _e894))));
                                            } else {
                                                phi_1383_ = u32();
                                                phi_1386_ = u32();
                                            }
                                            let _e901 = phi_1383_;
                                            let _e903 = phi_1386_;
                                            continue;
                                            continuing {
                                                phi_1382_ = _e901;
                                                phi_1385_ = _e903;
                                                break if !(_e887);
                                            }
                                        }
                                        let _e907 = (_e780 * f32(_e878));
                                        if (_e907 > 0f) {
                                            let _e913 = select(select(u32(_e907), 0u, (_e907 < 0f)), 4294967295u, (_e907 > 4294967000f));
                                            let _e914 = (_e878 - 1u);
                                            phi_1430_ = select(_e913, _e914, (_e914 < _e913));
                                        } else {
                                            phi_1430_ = 0u;
                                        }
                                        let _e918 = phi_1430_;
                                        let _e919 = (_e781 * f32(_e882));
                                        if (_e919 > 0f) {
                                            let _e925 = select(select(u32(_e919), 0u, (_e919 < 0f)), 4294967295u, (_e919 > 4294967000f));
                                            let _e926 = (_e882 - 1u);
                                            phi_1449_ = select(_e925, _e926, (_e926 < _e925));
                                        } else {
                                            phi_1449_ = 0u;
                                        }
                                        let _e930 = phi_1449_;
                                        let _e933 = local_3;
                                        let _e938 = mips.member[((_e933 + (_e930 * _e878)) + _e918)];
                                        let _e947 = (((((_e778 * 2f) - 1f) * _e398) * _e856) - _e400);
                                        let _e948 = (((((_e779 * -2f) + 1f) * _e408) * _e856) - _e410);
                                        let _e949 = (_e856 - _e390);
                                        let _e952 = params.member.member_1;
                                        let _e953 = (_e952 > 0f);
                                        if _e953 {
                                            phi_1493_ = (sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))) > _e952);
                                        } else {
                                            phi_1493_ = false;
                                        }
                                        let _e962 = phi_1493_;
                                        if !(_e962) {
                                            let _e966 = params.member.member;
                                            let _e969 = params.member.member_3;
                                            let _e974 = (((_e947 * _e421) + (_e948 * _e422)) + (_e949 * _e423));
                                            let _e978 = (_e947 - (_e421 * _e974));
                                            let _e979 = (_e948 - (_e422 * _e974));
                                            let _e980 = (_e949 - (_e423 * _e974));
                                            let _e989 = ((_e979 * _e423) - (_e422 * _e980));
                                            let _e992 = ((_e980 * _e421) - (_e423 * _e978));
                                            let _e995 = ((_e978 * _e422) - (_e421 * _e979));
                                            let _e1002 = (1f / sqrt((((_e989 * _e989) + (_e992 * _e992)) + (_e995 * _e995))));
                                            let _e1003 = (_e989 * _e1002);
                                            let _e1004 = (_e992 * _e1002);
                                            let _e1005 = (_e995 * _e1002);
                                            let _e1010 = (((_e493 * _e1003) + (_e494 * _e1004)) + (_e495 * _e1005));
                                            let _e1014 = (_e493 - (_e1003 * _e1010));
                                            let _e1015 = (_e494 - (_e1004 * _e1010));
                                            let _e1016 = (_e495 - (_e1005 * _e1010));
                                            let _e1022 = sqrt((((_e1014 * _e1014) + (_e1015 * _e1015)) + (_e1016 * _e1016)));
                                            let _e1028 = ((((_e1014 * _e421) + (_e1015 * _e422)) + (_e1016 * _e423)) / _e1022);
                                            let _e1032 = select(0f, select(1f, _e1028, (_e1028 < 1f)), (_e1028 > 0f));
                                            let _e1033 = abs(_e1032);
                                            let _e1050 = (((((((((((((((_e1033 * -0.0012624911f) + 0.00667009f) * _e1033) - 0.017088126f) * _e1033) + 0.03089188f) * _e1033) - 0.050174303f) * _e1033) + 0.08897899f) * _e1033) - 0.2145988f) * _e1033) + 1.5707963f) * sqrt((1f - _e1033)));
                                            let _e1053 = select((3.1415927f - _e1050), _e1050, (_e1032 >= 0f));
                                            let _e1061 = select(_e1053, -(_e1053), ((((_e978 * _e1014) + (_e979 * _e1015)) + (_e980 * _e1016)) < 0f));
                                            let _e1062 = (0.02f / _e1022);
                                            if (_e1062 != _e1062) {
                                                phi_2988_ = true;
                                            } else {
                                                phi_2988_ = (0.19634955f <= _e1062);
                                            }
                                            let _e1066 = phi_2988_;
                                            let _e1067 = select(_e1062, 0.19634955f, _e1066);
                                            let _e1071 = (_e947 - (_e421 * _e966));
                                            let _e1072 = (_e948 - (_e422 * _e966));
                                            let _e1073 = (_e949 - (_e423 * _e966));
                                            let _e1080 = (1f / sqrt((((_e947 * _e947) + (_e948 * _e948)) + (_e949 * _e949))));
                                            let _e1088 = ((((_e947 * _e1080) * _e421) + ((_e948 * _e1080) * _e422)) + ((_e949 * _e1080) * _e423));
                                            let _e1092 = select(-1f, select(1f, _e1088, (_e1088 < 1f)), (_e1088 > -1f));
                                            let _e1093 = abs(_e1092);
                                            let _e1110 = (((((((((((((((_e1093 * -0.0012624911f) + 0.00667009f) * _e1093) - 0.017088126f) * _e1093) + 0.03089188f) * _e1093) - 0.050174303f) * _e1093) + 0.08897899f) * _e1093) - 0.2145988f) * _e1093) + 1.5707963f) * sqrt((1f - _e1093)));
                                            let _e1117 = ((((select((3.1415927f - _e1110), _e1110, (_e1092 >= 0f)) + _e1067) - _e1061) + 1.5707964f) * 0.31830987f);
                                            let _e1121 = select(0f, select(1f, _e1117, (_e1117 < 1f)), (_e1117 > 0f));
                                            let _e1128 = (1f / sqrt((((_e1071 * _e1071) + (_e1072 * _e1072)) + (_e1073 * _e1073))));
                                            let _e1136 = ((((_e1071 * _e1128) * _e421) + ((_e1072 * _e1128) * _e422)) + ((_e1073 * _e1128) * _e423));
                                            let _e1140 = select(-1f, select(1f, _e1136, (_e1136 < 1f)), (_e1136 > -1f));
                                            let _e1141 = abs(_e1140);
                                            let _e1158 = (((((((((((((((_e1141 * -0.0012624911f) + 0.00667009f) * _e1141) - 0.017088126f) * _e1141) + 0.03089188f) * _e1141) - 0.050174303f) * _e1141) + 0.08897899f) * _e1141) - 0.2145988f) * _e1141) + 1.5707963f) * sqrt((1f - _e1141)));
                                            let _e1165 = ((((select((3.1415927f - _e1158), _e1158, (_e1140 >= 0f)) + _e1067) - _e1061) + 1.5707964f) * 0.31830987f);
                                            let _e1169 = select(0f, select(1f, _e1165, (_e1165 < 1f)), (_e1165 > 0f));
                                            let _e1170 = (_e1121 != _e1121);
                                            if _e1170 {
                                                phi_3003_ = true;
                                            } else {
                                                phi_3003_ = (_e1169 <= _e1121);
                                            }
                                            let _e1173 = phi_3003_;
                                            let _e1174 = select(_e1121, _e1169, _e1173);
                                            if _e1170 {
                                                phi_3018_ = true;
                                            } else {
                                                phi_3018_ = (_e1169 >= _e1121);
                                            }
                                            let _e1177 = phi_3018_;
                                            let _e1178 = select(_e1121, _e1169, _e1177);
                                            let _e1180 = floor((_e1174 * 32f));
                                            if (_e969 == 1u) {
                                                let _e1188 = -(floor((_e1178 * -32f)));
                                                if (_e1188 != _e1188) {
                                                    phi_3033_ = true;
                                                } else {
                                                    phi_3033_ = (32f <= _e1188);
                                                }
                                                let _e1192 = phi_3033_;
                                                let _e1195 = (select(_e1188, 32f, _e1192) - _e1180);
                                                if (_e1195 != _e1195) {
                                                    phi_3048_ = true;
                                                } else {
                                                    phi_3048_ = (0f >= _e1195);
                                                }
                                                let _e1199 = phi_3048_;
                                                phi_1814_ = select(select(_e1195, 0f, _e1199), 0f, (_e1178 <= _e1174));
                                            } else {
                                                phi_1814_ = -(floor(((_e1178 - _e1174) * -32f)));
                                            }
                                            let _e1203 = phi_1814_;
                                            if (_e1180 > 0f) {
                                                let _e1209 = select(select(u32(_e1180), 0u, (_e1180 < 0f)), 4294967295u, (_e1180 > 4294967000f));
                                                phi_1832_ = select(_e1209, 32u, (32u < _e1209));
                                            } else {
                                                phi_1832_ = 0u;
                                            }
                                            let _e1213 = phi_1832_;
                                            if (_e1203 > 0f) {
                                                let _e1219 = select(select(u32(_e1203), 0u, (_e1203 < 0f)), 4294967295u, (_e1203 > 4294967000f));
                                                phi_1850_ = select(_e1219, 32u, (32u < _e1219));
                                            } else {
                                                phi_1850_ = 0u;
                                            }
                                            let _e1223 = phi_1850_;
                                            if (_e1213 >= 32u) {
                                                phi_1870_ = u32();
                                                phi_1871_ = true;
                                            } else {
                                                let _e1225 = (_e1223 == 0u);
                                                if _e1225 {
                                                    phi_1869_ = u32();
                                                } else {
                                                    if (_e1223 >= 32u) {
                                                        phi_1866_ = 4294967295u;
                                                    } else {
                                                        phi_1866_ = ((1u << bitcast<u32>((_e1223 & 31u))) - 1u);
                                                    }
                                                    let _e1232 = phi_1866_;
                                                    phi_1869_ = (_e1232 << bitcast<u32>((_e1213 & 31u)));
                                                }
                                                let _e1237 = phi_1869_;
                                                phi_1870_ = _e1237;
                                                phi_1871_ = _e1225;
                                            }
                                            let _e1239 = phi_1870_;
                                            let _e1241 = phi_1871_;
                                            phi_1885_ = select(select(select(_e1239, 0u, _e1241), 0u, (sqrt((((_e978 * _e978) + (_e979 * _e979)) + (_e980 * _e980))) <= 0f)), 0u, _e962);
                                        } else {
                                            phi_1885_ = 0u;
                                        }
                                        let _e1247 = phi_1885_;
                                        let _e1249 = (((((_e780 * 2f) - 1f) * _e398) * _e938) - _e400);
                                        let _e1250 = (((((_e781 * -2f) + 1f) * _e408) * _e938) - _e410);
                                        let _e1251 = (_e938 - _e390);
                                        if _e953 {
                                            phi_1909_ = (sqrt((((_e1249 * _e1249) + (_e1250 * _e1250)) + (_e1251 * _e1251))) > _e952);
                                        } else {
                                            phi_1909_ = false;
                                        }
                                        let _e1260 = phi_1909_;
                                        if !(_e1260) {
                                            let _e1264 = params.member.member;
                                            let _e1267 = params.member.member_3;
                                            let _e1272 = (((_e1249 * _e421) + (_e1250 * _e422)) + (_e1251 * _e423));
                                            let _e1276 = (_e1249 - (_e421 * _e1272));
                                            let _e1277 = (_e1250 - (_e422 * _e1272));
                                            let _e1278 = (_e1251 - (_e423 * _e1272));
                                            let _e1287 = ((_e1277 * _e423) - (_e422 * _e1278));
                                            let _e1290 = ((_e1278 * _e421) - (_e423 * _e1276));
                                            let _e1293 = ((_e1276 * _e422) - (_e421 * _e1277));
                                            let _e1300 = (1f / sqrt((((_e1287 * _e1287) + (_e1290 * _e1290)) + (_e1293 * _e1293))));
                                            let _e1301 = (_e1287 * _e1300);
                                            let _e1302 = (_e1290 * _e1300);
                                            let _e1303 = (_e1293 * _e1300);
                                            let _e1308 = (((_e493 * _e1301) + (_e494 * _e1302)) + (_e495 * _e1303));
                                            let _e1312 = (_e493 - (_e1301 * _e1308));
                                            let _e1313 = (_e494 - (_e1302 * _e1308));
                                            let _e1314 = (_e495 - (_e1303 * _e1308));
                                            let _e1320 = sqrt((((_e1312 * _e1312) + (_e1313 * _e1313)) + (_e1314 * _e1314)));
                                            let _e1326 = ((((_e1312 * _e421) + (_e1313 * _e422)) + (_e1314 * _e423)) / _e1320);
                                            let _e1330 = select(0f, select(1f, _e1326, (_e1326 < 1f)), (_e1326 > 0f));
                                            let _e1331 = abs(_e1330);
                                            let _e1348 = (((((((((((((((_e1331 * -0.0012624911f) + 0.00667009f) * _e1331) - 0.017088126f) * _e1331) + 0.03089188f) * _e1331) - 0.050174303f) * _e1331) + 0.08897899f) * _e1331) - 0.2145988f) * _e1331) + 1.5707963f) * sqrt((1f - _e1331)));
                                            let _e1351 = select((3.1415927f - _e1348), _e1348, (_e1330 >= 0f));
                                            let _e1359 = select(_e1351, -(_e1351), ((((_e1276 * _e1312) + (_e1277 * _e1313)) + (_e1278 * _e1314)) < 0f));
                                            let _e1360 = (0.02f / _e1320);
                                            if (_e1360 != _e1360) {
                                                phi_3063_ = true;
                                            } else {
                                                phi_3063_ = (0.19634955f <= _e1360);
                                            }
                                            let _e1364 = phi_3063_;
                                            let _e1365 = select(_e1360, 0.19634955f, _e1364);
                                            let _e1369 = (_e1249 - (_e421 * _e1264));
                                            let _e1370 = (_e1250 - (_e422 * _e1264));
                                            let _e1371 = (_e1251 - (_e423 * _e1264));
                                            let _e1378 = (1f / sqrt((((_e1249 * _e1249) + (_e1250 * _e1250)) + (_e1251 * _e1251))));
                                            let _e1386 = ((((_e1249 * _e1378) * _e421) + ((_e1250 * _e1378) * _e422)) + ((_e1251 * _e1378) * _e423));
                                            let _e1390 = select(-1f, select(1f, _e1386, (_e1386 < 1f)), (_e1386 > -1f));
                                            let _e1391 = abs(_e1390);
                                            let _e1408 = (((((((((((((((_e1391 * -0.0012624911f) + 0.00667009f) * _e1391) - 0.017088126f) * _e1391) + 0.03089188f) * _e1391) - 0.050174303f) * _e1391) + 0.08897899f) * _e1391) - 0.2145988f) * _e1391) + 1.5707963f) * sqrt((1f - _e1391)));
                                            let _e1415 = ((((select((3.1415927f - _e1408), _e1408, (_e1390 >= 0f)) + _e1365) - _e1359) + 1.5707964f) * 0.31830987f);
                                            let _e1426 = (1f / sqrt((((_e1369 * _e1369) + (_e1370 * _e1370)) + (_e1371 * _e1371))));
                                            let _e1434 = ((((_e1369 * _e1426) * _e421) + ((_e1370 * _e1426) * _e422)) + ((_e1371 * _e1426) * _e423));
                                            let _e1438 = select(-1f, select(1f, _e1434, (_e1434 < 1f)), (_e1434 > -1f));
                                            let _e1439 = abs(_e1438);
                                            let _e1456 = (((((((((((((((_e1439 * -0.0012624911f) + 0.00667009f) * _e1439) - 0.017088126f) * _e1439) + 0.03089188f) * _e1439) - 0.050174303f) * _e1439) + 0.08897899f) * _e1439) - 0.2145988f) * _e1439) + 1.5707963f) * sqrt((1f - _e1439)));
                                            let _e1463 = ((((select((3.1415927f - _e1456), _e1456, (_e1438 >= 0f)) + _e1365) - _e1359) + 1.5707964f) * 0.31830987f);
                                            let _e1468 = (1f - select(0f, select(1f, _e1415, (_e1415 < 1f)), (_e1415 > 0f)));
                                            let _e1469 = (1f - select(0f, select(1f, _e1463, (_e1463 < 1f)), (_e1463 > 0f)));
                                            let _e1470 = (_e1468 != _e1468);
                                            if _e1470 {
                                                phi_3078_ = true;
                                            } else {
                                                phi_3078_ = (_e1469 <= _e1468);
                                            }
                                            let _e1473 = phi_3078_;
                                            let _e1474 = select(_e1468, _e1469, _e1473);
                                            if _e1470 {
                                                phi_3093_ = true;
                                            } else {
                                                phi_3093_ = (_e1469 >= _e1468);
                                            }
                                            let _e1477 = phi_3093_;
                                            let _e1478 = select(_e1468, _e1469, _e1477);
                                            let _e1480 = floor((_e1474 * 32f));
                                            if (_e1267 == 1u) {
                                                let _e1488 = -(floor((_e1478 * -32f)));
                                                if (_e1488 != _e1488) {
                                                    phi_3108_ = true;
                                                } else {
                                                    phi_3108_ = (32f <= _e1488);
                                                }
                                                let _e1492 = phi_3108_;
                                                let _e1495 = (select(_e1488, 32f, _e1492) - _e1480);
                                                if (_e1495 != _e1495) {
                                                    phi_3123_ = true;
                                                } else {
                                                    phi_3123_ = (0f >= _e1495);
                                                }
                                                let _e1499 = phi_3123_;
                                                phi_2230_ = select(select(_e1495, 0f, _e1499), 0f, (_e1478 <= _e1474));
                                            } else {
                                                phi_2230_ = -(floor(((_e1478 - _e1474) * -32f)));
                                            }
                                            let _e1503 = phi_2230_;
                                            if (_e1480 > 0f) {
                                                let _e1509 = select(select(u32(_e1480), 0u, (_e1480 < 0f)), 4294967295u, (_e1480 > 4294967000f));
                                                phi_2248_ = select(_e1509, 32u, (32u < _e1509));
                                            } else {
                                                phi_2248_ = 0u;
                                            }
                                            let _e1513 = phi_2248_;
                                            if (_e1503 > 0f) {
                                                let _e1519 = select(select(u32(_e1503), 0u, (_e1503 < 0f)), 4294967295u, (_e1503 > 4294967000f));
                                                phi_2266_ = select(_e1519, 32u, (32u < _e1519));
                                            } else {
                                                phi_2266_ = 0u;
                                            }
                                            let _e1523 = phi_2266_;
                                            if (_e1513 >= 32u) {
                                                phi_2286_ = u32();
                                                phi_2287_ = true;
                                            } else {
                                                let _e1525 = (_e1523 == 0u);
                                                if _e1525 {
                                                    phi_2285_ = u32();
                                                } else {
                                                    if (_e1523 >= 32u) {
                                                        phi_2282_ = 4294967295u;
                                                    } else {
                                                        phi_2282_ = ((1u << bitcast<u32>((_e1523 & 31u))) - 1u);
                                                    }
                                                    let _e1532 = phi_2282_;
                                                    phi_2285_ = (_e1532 << bitcast<u32>((_e1513 & 31u)));
                                                }
                                                let _e1537 = phi_2285_;
                                                phi_2286_ = _e1537;
                                                phi_2287_ = _e1525;
                                            }
                                            let _e1539 = phi_2286_;
                                            let _e1541 = phi_2287_;
                                            phi_2301_ = select(select(select(_e1539, 0u, _e1541), 0u, (sqrt((((_e1276 * _e1276) + (_e1277 * _e1277)) + (_e1278 * _e1278))) <= 0f)), 0u, _e1260);
                                        } else {
                                            phi_2301_ = 0u;
                                        }
                                        let _e1547 = phi_2301_;
                                        phi_1081_ = (_e698 + 1u);
                                        phi_1084_ = ((_e700 | _e1247) | _e1547);
                                    } else {
                                        phi_1081_ = u32();
                                        phi_1084_ = u32();
                                    }
                                    let _e1551 = phi_1081_;
                                    let _e1553 = phi_1084_;
                                    continue;
                                    continuing {
                                        phi_1080_ = _e1551;
                                        phi_1083_ = _e1553;
                                        break if !(_e701);
                                    }
                                }
                                let _e1557 = params.member.member_2;
                                if (_e1557 == 2u) {
                                    let _e1614 = (_e690 - 1.5707964f);
                                    let _e1615 = (_e1614 * 2f);
                                    let _e1616 = sin(_e690);
                                    let _e1621 = ((_e668 + (_e1615 * _e1616)) - cos((_e1615 - _e690)));
                                    phi_2332_ = 0u;
                                    phi_2335_ = select((_e1621 * 0.25f), (_e1621 * -0.25f), (_e1614 < 0f));
                                    phi_2337_ = 0f;
                                    loop {
                                        let _e1627 = phi_2332_;
                                        let _e1629 = phi_2335_;
                                        let _e1631 = phi_2337_;
                                        local_8 = _e1631;
                                        let _e1632 = (_e1627 < 32u);
                                        if _e1632 {
                                            let _e1633 = (_e1627 + 1u);
                                            let _e1636 = (_e1614 + (f32(_e1633) * 0.09817477f));
                                            let _e1637 = (_e1636 * 2f);
                                            let _e1642 = ((_e668 + (_e1637 * _e1616)) - cos((_e1637 - _e690)));
                                            let _e1646 = select((_e1642 * 0.25f), (_e1642 * -0.25f), (_e1636 < 0f));
                                            let _e1649 = local_7;
                                            phi_2333_ = _e1633;
                                            phi_2336_ = _e1646;
                                            phi_2338_ = select(_e1631, (_e1631 + (_e1646 - _e1629)), (((_e1649 >> bitcast<u32>((_e1627 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2333_ = u32();
                                            phi_2336_ = f32();
                                            phi_2338_ = f32();
                                        }
                                        let _e1658 = phi_2333_;
                                        let _e1660 = phi_2336_;
                                        let _e1662 = phi_2338_;
                                        continue;
                                        continuing {
                                            phi_2332_ = _e1658;
                                            phi_2335_ = _e1660;
                                            phi_2337_ = _e1662;
                                            break if !(_e1632);
                                        }
                                    }
                                    let _e1665 = local_8;
                                    phi_3386_ = _e587;
                                    phi_2440_ = (_e591 + 1f);
                                    phi_2441_ = (_e593 + ((_e649 + ((1f - _e649) * 0.05f)) * _e1665));
                                } else {
                                    if (_e1557 == 1u) {
                                        phi_2385_ = 0u;
                                        phi_2388_ = 0f;
                                        loop {
                                            let _e1570 = phi_2385_;
                                            let _e1572 = phi_2388_;
                                            local_6 = _e1572;
                                            let _e1573 = (_e1570 < 4u);
                                            if _e1573 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1573 {
                                                } else {
                                                    phi_3182_ = true;
                                                    break;
                                                }
                                                let _e1576 = local[_e1570].member;
                                                let _e1579 = local[_e1570].member_1;
                                                let _e1581 = local_5;
                                                phi_2386_ = (_e1570 + 1u);
                                                phi_2389_ = (_e1572 + (f32(countOneBits((_e1581 & _e1576))) * _e1579));
                                            } else {
                                                phi_2386_ = u32();
                                                phi_2389_ = f32();
                                            }
                                            let _e1589 = phi_2386_;
                                            let _e1591 = phi_2389_;
                                            continue;
                                            continuing {
                                                phi_2385_ = _e1589;
                                                phi_2388_ = _e1591;
                                                phi_3182_ = _e587;
                                                break if !(_e1573);
                                            }
                                        }
                                        let _e1594 = phi_3182_;
                                        phi_3384_ = _e1594;
                                        if _e1594 {
                                            break;
                                        }
                                        let _e1596 = local_6;
                                        let _e1597 = (1f - _e1596);
                                        phi_3392_ = _e1594;
                                        phi_2438_ = (_e591 + _e649);
                                        phi_2439_ = (_e593 + (_e649 * select(0f, select(1f, _e1597, (_e1597 < 1f)), (_e1597 > 0f))));
                                    } else {
                                        let _e1561 = local_4;
                                        phi_3392_ = _e587;
                                        phi_2438_ = (_e591 + 1f);
                                        phi_2439_ = (_e593 + ((f32(countOneBits((_e1561 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1606 = phi_3392_;
                                    let _e1608 = phi_2438_;
                                    let _e1610 = phi_2439_;
                                    phi_3386_ = _e1606;
                                    phi_2440_ = _e1608;
                                    phi_2441_ = _e1610;
                                }
                                let _e1670 = phi_3386_;
                                let _e1672 = phi_2440_;
                                let _e1674 = phi_2441_;
                                phi_3385_ = _e1670;
                                phi_881_ = (_e589 + 1u);
                                phi_884_ = _e1672;
                                phi_886_ = _e1674;
                            } else {
                                phi_3385_ = _e587;
                                phi_881_ = u32();
                                phi_884_ = f32();
                                phi_886_ = f32();
                            }
                            let _e1677 = phi_3385_;
                            let _e1679 = phi_881_;
                            let _e1681 = phi_884_;
                            let _e1683 = phi_886_;
                            continue;
                            continuing {
                                phi_3303_ = _e1677;
                                phi_880_ = _e1679;
                                phi_883_ = _e1681;
                                phi_885_ = _e1683;
                                phi_3384_ = _e1677;
                                break if !(_e594);
                            }
                        }
                        let _e1686 = phi_3384_;
                        if _e1686 {
                            break;
                        }
                        let _e1688 = local_9;
                        let _e1691 = local_10;
                        let _e1693 = local_11;
                        phi_2449_ = select(1f, (_e1691 / _e1693), (_e1688 > 0f));
                    } else {
                        phi_2449_ = 1f;
                    }
                    let _e1697 = phi_2449_;
                    if _e579 {
                        let _e1701 = params.member.member_4.member_6;
                        let _e1702 = pow(_e1697, _e1701);
                        if (_e1702 != _e1702) {
                            phi_3156_ = true;
                        } else {
                            phi_3156_ = (0.03f >= _e1702);
                        }
                        let _e1706 = phi_3156_;
                        let _e1708 = (select(_e1702, 0.03f, _e1706) * 0.6666667f);
                        let _e1714 = ((select(0f, select(1f, _e1708, (_e1708 < 1f)), (_e1708 > 0f)) * 255f) + 0.5f);
                        phi_2498_ = select(select(u32(_e1714), 0u, (_e1714 < 0f)), 4294967295u, (_e1714 > 4294967000f));
                    } else {
                        phi_2498_ = 170u;
                    }
                    let _e1721 = phi_2498_;
                    if (_e127 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e127] = _e1721;
                    if (_e127 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e127] = ((((64u * _e281) + (16u * _e314)) + (4u * _e348)) + _e382);
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vbao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
