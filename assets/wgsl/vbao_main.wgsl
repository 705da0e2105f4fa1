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
    var phi_2522_: bool;
    var phi_2537_: bool;
    var phi_2552_: bool;
    var phi_2567_: bool;
    var phi_2598_: f32;
    var phi_2602_: f32;
    var phi_2603_: bool;
    var phi_2625_: u32;
    var phi_2652_: f32;
    var phi_2656_: f32;
    var phi_2657_: bool;
    var phi_2679_: u32;
    var phi_2706_: f32;
    var phi_2710_: f32;
    var phi_2711_: bool;
    var phi_2733_: u32;
    var phi_2760_: f32;
    var phi_2764_: f32;
    var phi_2765_: bool;
    var phi_2787_: u32;
    var phi_2866_: bool;
    var phi_2881_: bool;
    var phi_2842_: vec2<f32>;
    var phi_2898_: u32;
    var phi_2899_: u32;
    var phi_2900_: u32;
    var phi_2901_: u32;
    var phi_2924_: u32;
    var phi_2925_: u32;
    var phi_2928_: u32;
    var phi_2929_: u32;
    var phi_2933_: u32;
    var phi_2934_: u32;
    var phi_2935_: u32;
    var phi_2936_: u32;
    var local_1: u32;
    var phi_3285_: bool;
    var phi_872_: u32;
    var phi_875_: f32;
    var phi_877_: f32;
    var phi_1072_: u32;
    var phi_1075_: u32;
    var phi_1129_: f32;
    var phi_1174_: f32;
    var phi_1176_: f32;
    var phi_1177_: bool;
    var phi_1200_: f32;
    var phi_1202_: f32;
    var phi_1203_: bool;
    var phi_1236_: u32;
    var phi_1252_: u32;
    var phi_1255_: u32;
    var phi_1253_: u32;
    var phi_1256_: u32;
    var phi_1300_: u32;
    var phi_1319_: u32;
    var local_2: u32;
    var phi_1358_: u32;
    var phi_1374_: u32;
    var phi_1377_: u32;
    var phi_1375_: u32;
    var phi_1378_: u32;
    var phi_1422_: u32;
    var phi_1441_: u32;
    var local_3: u32;
    var phi_1485_: bool;
    var phi_2970_: bool;
    var phi_2985_: bool;
    var phi_3000_: bool;
    var phi_3015_: bool;
    var phi_3030_: bool;
    var phi_1806_: f32;
    var phi_1824_: u32;
    var phi_1842_: u32;
    var phi_1858_: u32;
    var phi_1861_: u32;
    var phi_1862_: u32;
    var phi_1863_: bool;
    var phi_1877_: u32;
    var phi_1901_: bool;
    var phi_3045_: bool;
    var phi_3060_: bool;
    var phi_3075_: bool;
    var phi_3090_: bool;
    var phi_3105_: bool;
    var phi_2222_: f32;
    var phi_2240_: u32;
    var phi_2258_: u32;
    var phi_2274_: u32;
    var phi_2277_: u32;
    var phi_2278_: u32;
    var phi_2279_: bool;
    var phi_2293_: u32;
    var phi_1073_: u32;
    var phi_1076_: u32;
    var local_4: u32;
    var phi_2377_: u32;
    var phi_2380_: f32;
    var local_5: u32;
    var phi_2378_: u32;
    var phi_2381_: f32;
    var phi_3164_: bool;
    var local_6: f32;
    var phi_3374_: bool;
    var phi_2430_: f32;
    var phi_2431_: f32;
    var phi_2324_: u32;
    var phi_2327_: f32;
    var phi_2329_: f32;
    var local_7: u32;
    var phi_2325_: u32;
    var phi_2328_: f32;
    var phi_2330_: f32;
    var local_8: f32;
    var phi_3368_: bool;
    var phi_2432_: f32;
    var phi_2433_: f32;
    var phi_3367_: bool;
    var phi_873_: u32;
    var phi_876_: f32;
    var phi_878_: f32;
    var phi_3366_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var phi_2441_: f32;
    var phi_3138_: bool;
    var phi_2490_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e92 = id_1;
            let _e99 = params.member.member_4.member.member[0u];
            let _e104 = select(select(u32(_e99), 0u, (_e99 < 0f)), 4294967295u, (_e99 > 4294967000f));
            let _e110 = params.member.member_4.member.member[1u];
            let _e115 = select(select(u32(_e110), 0u, (_e110 < 0f)), 4294967295u, (_e110 > 4294967000f));
            if (_e92.x >= _e104) {
            } else {
                if (_e92.y >= _e115) {
                } else {
                    let _e121 = ((_e92.y * _e104) + _e92.x);
                    let _e123 = mips.member[_e121];
                    let _e124 = bitcast<i32>(_e92.x);
                    let _e125 = (_e124 + -1i);
                    let _e127 = select(0i, _e125, (0i < _e125));
                    let _e129 = (bitcast<i32>(_e104) - 1i);
                    let _e133 = bitcast<i32>(_e92.y);
                    let _e135 = select(0i, _e133, (0i < _e133));
                    let _e137 = (bitcast<i32>(_e115) - 1i);
                    let _e141 = (bitcast<u32>(select(_e135, _e137, (_e137 < _e135))) * _e104);
                    let _e144 = mips.member[(_e141 + bitcast<u32>(select(_e127, _e129, (_e129 < _e127))))];
                    let _e145 = (_e124 + 1i);
                    let _e147 = select(0i, _e145, (0i < _e145));
                    let _e153 = mips.member[(_e141 + bitcast<u32>(select(_e147, _e129, (_e129 < _e147))))];
                    let _e155 = select(0i, _e124, (0i < _e124));
                    let _e158 = bitcast<u32>(select(_e155, _e129, (_e129 < _e155)));
                    let _e159 = (_e133 + -1i);
                    let _e161 = select(0i, _e159, (0i < _e159));
                    let _e168 = mips.member[((bitcast<u32>(select(_e161, _e137, (_e137 < _e161))) * _e104) + _e158)];
                    let _e169 = (_e133 + 1i);
                    let _e171 = select(0i, _e169, (0i < _e169));
                    let _e178 = mips.member[((bitcast<u32>(select(_e171, _e137, (_e137 < _e171))) * _e104) + _e158)];
                    let _e179 = (_e144 - _e123);
                    let _e180 = (_e153 - _e123);
                    let _e181 = (_e168 - _e123);
                    let _e182 = (_e178 - _e123);
                    let _e184 = ((_e180 - _e179) * 0.5f);
                    let _e186 = ((_e182 - _e181) * 0.5f);
                    let _e187 = (_e123 * 0.011f);
                    let _e189 = abs(_e179);
                    let _e190 = abs((_e179 + _e184));
                    if (_e189 != _e189) {
                        phi_2522_ = true;
                    } else {
                        phi_2522_ = (_e190 <= _e189);
                    }
                    let _e194 = phi_2522_;
                    let _e197 = (1.25f - (select(_e189, _e190, _e194) / _e187));
                    let _e201 = select(0f, select(1f, _e197, (_e197 < 1f)), (_e197 > 0f));
                    let _e203 = abs(_e180);
                    let _e204 = abs((_e180 - _e184));
                    if (_e203 != _e203) {
                        phi_2537_ = true;
                    } else {
                        phi_2537_ = (_e204 <= _e203);
                    }
                    let _e208 = phi_2537_;
                    let _e211 = (1.25f - (select(_e203, _e204, _e208) / _e187));
                    let _e215 = select(0f, select(1f, _e211, (_e211 < 1f)), (_e211 > 0f));
                    let _e217 = abs(_e181);
                    let _e218 = abs((_e181 + _e186));
                    if (_e217 != _e217) {
                        phi_2552_ = true;
                    } else {
                        phi_2552_ = (_e218 <= _e217);
                    }
                    let _e222 = phi_2552_;
                    let _e225 = (1.25f - (select(_e217, _e218, _e222) / _e187));
                    let _e229 = select(0f, select(1f, _e225, (_e225 < 1f)), (_e225 > 0f));
                    let _e231 = abs(_e182);
                    let _e232 = abs((_e182 - _e186));
                    if (_e231 != _e231) {
                        phi_2567_ = true;
                    } else {
                        phi_2567_ = (_e232 <= _e231);
                    }
                    let _e236 = phi_2567_;
                    let _e239 = (1.25f - (select(_e231, _e232, _e236) / _e187));
                    let _e243 = select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f));
                    let _e248 = (select(0f, select(1f, _e201, (_e201 < 1f)), (_e201 > 0f)) * 2.9f);
                    let _e250 = floor((_e248 + 0.5f));
                    if ((_e250 - _e248) == 0.5f) {
                        let _e256 = ((floor((_e250 * 0.5f)) * 2f) != _e250);
                        if _e256 {
                            phi_2598_ = (_e250 - 1f);
                        } else {
                            phi_2598_ = f32();
                        }
                        let _e259 = phi_2598_;
                        phi_2602_ = _e259;
                        phi_2603_ = select(true, false, _e256);
                    } else {
                        phi_2602_ = f32();
                        phi_2603_ = true;
                    }
                    let _e262 = phi_2602_;
                    let _e264 = phi_2603_;
                    let _e265 = select(_e262, _e250, _e264);
                    if (_e265 > 0f) {
                        let _e271 = select(select(u32(_e265), 0u, (_e265 < 0f)), 4294967295u, (_e265 > 4294967000f));
                        phi_2625_ = select(_e271, 3u, (3u < _e271));
                    } else {
                        phi_2625_ = 0u;
                    }
                    let _e275 = phi_2625_;
                    let _e281 = (select(0f, select(1f, _e215, (_e215 < 1f)), (_e215 > 0f)) * 2.9f);
                    let _e283 = floor((_e281 + 0.5f));
                    if ((_e283 - _e281) == 0.5f) {
                        let _e289 = ((floor((_e283 * 0.5f)) * 2f) != _e283);
                        if _e289 {
                            phi_2652_ = (_e283 - 1f);
                        } else {
                            phi_2652_ = f32();
                        }
                        let _e292 = phi_2652_;
                        phi_2656_ = _e292;
                        phi_2657_ = select(true, false, _e289);
                    } else {
                        phi_2656_ = f32();
                        phi_2657_ = true;
                    }
                    let _e295 = phi_2656_;
                    let _e297 = phi_2657_;
                    let _e298 = select(_e295, _e283, _e297);
                    if (_e298 > 0f) {
                        let _e304 = select(select(u32(_e298), 0u, (_e298 < 0f)), 4294967295u, (_e298 > 4294967000f));
                        phi_2679_ = select(_e304, 3u, (3u < _e304));
                    } else {
                        phi_2679_ = 0u;
                    }
                    let _e308 = phi_2679_;
                    let _e315 = (select(0f, select(1f, _e229, (_e229 < 1f)), (_e229 > 0f)) * 2.9f);
                    let _e317 = floor((_e315 + 0.5f));
                    if ((_e317 - _e315) == 0.5f) {
                        let _e323 = ((floor((_e317 * 0.5f)) * 2f) != _e317);
                        if _e323 {
                            phi_2706_ = (_e317 - 1f);
                        } else {
                            phi_2706_ = f32();
                        }
                        let _e326 = phi_2706_;
                        phi_2710_ = _e326;
                        phi_2711_ = select(true, false, _e323);
                    } else {
                        phi_2710_ = f32();
                        phi_2711_ = true;
                    }
                    let _e329 = phi_2710_;
                    let _e331 = phi_2711_;
                    let _e332 = select(_e329, _e317, _e331);
                    if (_e332 > 0f) {
                        let _e338 = select(select(u32(_e332), 0u, (_e332 < 0f)), 4294967295u, (_e332 > 4294967000f));
                        phi_2733_ = select(_e338, 3u, (3u < _e338));
                    } else {
                        phi_2733_ = 0u;
                    }
                    let _e342 = phi_2733_;
                    let _e349 = (select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f)) * 2.9f);
                    let _e351 = floor((_e349 + 0.5f));
                    if ((_e351 - _e349) == 0.5f) {
                        let _e357 = ((floor((_e351 * 0.5f)) * 2f) != _e351);
                        if _e357 {
                            phi_2760_ = (_e351 - 1f);
                        } else {
                            phi_2760_ = f32();
                        }
                        let _e360 = phi_2760_;
                        phi_2764_ = _e360;
                        phi_2765_ = select(true, false, _e357);
                    } else {
                        phi_2764_ = f32();
                        phi_2765_ = true;
                    }
                    let _e363 = phi_2764_;
                    let _e365 = phi_2765_;
                    let _e366 = select(_e363, _e351, _e365);
                    if (_e366 > 0f) {
                        let _e372 = select(select(u32(_e366), 0u, (_e366 < 0f)), 4294967295u, (_e366 > 4294967000f));
                        phi_2787_ = select(_e372, 3u, (3u < _e372));
                    } else {
                        phi_2787_ = 0u;
                    }
                    let _e376 = phi_2787_;
                    let _e380 = ((f32(_e92.x) + 0.5f) / _e99);
                    let _e383 = ((f32(_e92.y) + 0.5f) / _e110);
                    let _e384 = (_e123 * 0.99999f);
                    let _e392 = params.member.member_4.member.member_1[0u];
                    let _e394 = ((((_e380 * 2f) - 1f) * _e392) * _e384);
                    let _e402 = params.member.member_4.member.member_1[1u];
                    let _e404 = ((((_e383 * -2f) + 1f) * _e402) * _e384);
                    let _e405 = -(_e394);
                    let _e406 = -(_e404);
                    let _e407 = (_e123 * -0.99999f);
                    let _e414 = (1f / sqrt((((_e405 * _e405) + (_e406 * _e406)) + (_e407 * _e407))));
                    let _e415 = (_e405 * _e414);
                    let _e416 = (_e406 * _e414);
                    let _e417 = (_e407 * _e414);
                    let _e420 = normals.member[_e121];
                    let _e428 = (f32((bitcast<i32>(((_e420 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e428 != _e428) {
                        phi_2866_ = true;
                    } else {
                        phi_2866_ = (-1f >= _e428);
                    }
                    let _e432 = phi_2866_;
                    let _e433 = select(_e428, -1f, _e432);
                    let _e443 = (f32((bitcast<i32>((((_e420 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e443 != _e443) {
                        phi_2881_ = true;
                    } else {
                        phi_2881_ = (-1f >= _e443);
                    }
                    let _e447 = phi_2881_;
                    let _e448 = select(_e443, -1f, _e447);
                    let _e451 = (1f - abs(_e433));
                    let _e452 = abs(_e448);
                    let _e453 = (_e451 - _e452);
                    if (_e453 < 0f) {
                        phi_2842_ = vec2<f32>(((1f - _e452) * select(1f, -1f, (_e433 < 0f))), (_e451 * select(1f, -1f, (_e448 < 0f))));
                    } else {
                        phi_2842_ = vec2<f32>(_e433, _e448);
                    }
                    let _e464 = phi_2842_;
                    let _e473 = (1f / sqrt((((_e464.x * _e464.x) + (_e464.y * _e464.y)) + (_e453 * _e453))));
                    let _e474 = (_e464.x * _e473);
                    let _e475 = (_e464.y * _e473);
                    let _e476 = (_e453 * _e473);
                    let _e477 = -(_e476);
                    let _e483 = ((((_e474 * _e415) + (_e475 * _e416)) + (_e477 * _e417)) < 0f);
                    let _e486 = select(_e474, -(_e474), _e483);
                    let _e487 = select(_e475, -(_e475), _e483);
                    let _e488 = select(_e477, _e476, _e483);
                    let _e492 = params.member.member_4.member_1;
                    let _e496 = params.member.member_4.member_2;
                    let _e501 = ((_e492 * _e496) / (((_e123 * 1.99998f) * _e392) / _e99));
                    let _e506 = params.member.member_4.member_11;
                    phi_2898_ = (_e92.y & 63u);
                    phi_2899_ = (_e92.x & 63u);
                    phi_2900_ = 32u;
                    phi_2901_ = 0u;
                    loop {
                        let _e510 = phi_2898_;
                        let _e512 = phi_2899_;
                        let _e514 = phi_2900_;
                        let _e516 = phi_2901_;
                        local_1 = _e516;
                        let _e517 = (_e514 > 0u);
                        if _e517 {
                            let _e520 = select(0u, 1u, ((_e512 & _e514) != 0u));
                            let _e523 = select(0u, 1u, ((_e510 & _e514) != 0u));
                            if (_e523 == 0u) {
                                if (_e520 == 1u) {
                                    phi_2924_ = (63u - _e510);
                                    phi_2925_ = (63u - _e512);
                                } else {
                                    phi_2924_ = _e510;
                                    phi_2925_ = _e512;
                                }
                                let _e534 = phi_2924_;
                                let _e536 = phi_2925_;
                                phi_2928_ = _e536;
                                phi_2929_ = _e534;
                            } else {
                                phi_2928_ = _e510;
                                phi_2929_ = _e512;
                            }
                            let _e538 = phi_2928_;
                            let _e540 = phi_2929_;
                            phi_2933_ = _e538;
                            phi_2934_ = _e540;
                            phi_2935_ = (_e514 / 2u);
                            phi_2936_ = (_e516 + ((_e514 * _e514) * ((3u * _e520) ^ _e523)));
                        } else {
                            phi_2933_ = u32();
                            phi_2934_ = u32();
                            phi_2935_ = u32();
                            phi_2936_ = u32();
                        }
                        let _e543 = phi_2933_;
                        let _e545 = phi_2934_;
                        let _e547 = phi_2935_;
                        let _e549 = phi_2936_;
                        continue;
                        continuing {
                            phi_2898_ = _e543;
                            phi_2899_ = _e545;
                            phi_2900_ = _e547;
                            phi_2901_ = _e549;
                            break if !(_e517);
                        }
                    }
                    let _e554 = local_1;
                    let _e556 = f32((_e554 + (288u * (_e506 % 64u))));
                    let _e558 = (0.5f + (_e556 * 0.7548777f));
                    let _e562 = (0.5f + (_e556 * 0.5698403f));
                    let _e569 = params.member.member_4.member.member_3;
                    let _e572 = select(false, (_e123 < _e569), (_e123 > 0f));
                    if _e572 {
                        let _e576 = params.member.member_4.member_8;
                        let _e578 = select(1u, _e576, (1u < _e576));
                        phi_3285_ = false;
                        phi_872_ = 0u;
                        phi_875_ = 0f;
                        phi_877_ = 0f;
                        loop {
                            let _e580 = phi_3285_;
                            let _e582 = phi_872_;
                            let _e584 = phi_875_;
                            let _e586 = phi_877_;
                            local_9 = _e584;
                            local_10 = _e586;
                            local_11 = _e584;
                            let _e587 = (_e582 < _e578);
                            if _e587 {
                                let _e592 = ((((_e558 - floor(_e558)) + f32(_e582)) * 3.1415927f) / f32(_e578));
                                let _e593 = sin(_e592);
                                let _e594 = cos(_e592);
                                let _e600 = ((_e594 * _e415) + (_e593 * _e416));
                                let _e604 = (_e594 - (_e415 * _e600));
                                let _e605 = (_e593 - (_e416 * _e600));
                                let _e606 = -((_e417 * _e600));
                                let _e609 = ((_e605 * _e417) - (_e416 * _e606));
                                let _e612 = ((_e606 * _e415) - (_e417 * _e604));
                                let _e615 = ((_e604 * _e416) - (_e415 * _e605));
                                let _e622 = (1f / sqrt((((_e609 * _e609) + (_e612 * _e612)) + (_e615 * _e615))));
                                let _e623 = (_e609 * _e622);
                                let _e624 = (_e612 * _e622);
                                let _e625 = (_e615 * _e622);
                                let _e630 = (((_e486 * _e623) + (_e487 * _e624)) + (_e488 * _e625));
                                let _e634 = (_e486 - (_e623 * _e630));
                                let _e635 = (_e487 - (_e624 * _e630));
                                let _e636 = (_e488 - (_e625 * _e630));
                                let _e642 = sqrt((((_e634 * _e634) + (_e635 * _e635)) + (_e636 * _e636)));
                                let _e647 = (((_e604 * _e634) + (_e605 * _e635)) + (_e606 * _e636));
                                let _e657 = ((((_e634 * _e415) + (_e635 * _e416)) + (_e636 * _e417)) / _e642);
                                let _e661 = select(0f, select(1f, _e657, (_e657 < 1f)), (_e657 > 0f));
                                let _e662 = abs(_e661);
                                let _e680 = (((((((((((((((_e662 * -0.0012624911f) + 0.00667009f) * _e662) - 0.017088126f) * _e662) + 0.03089188f) * _e662) - 0.050174303f) * _e662) + 0.08897899f) * _e662) - 0.2145988f) * _e662) + 1.5707963f) * sqrt((1f - _e662)));
                                let _e683 = (select(select(0f, -1f, (_e647 < 0f)), 1f, (_e647 > 0f)) * select((3.1415927f - _e680), _e680, (_e661 >= 0f)));
                                let _e687 = params.member.member_4.member_9;
                                let _e689 = select(1u, _e687, (1u < _e687));
                                phi_1072_ = 0u;
                                phi_1075_ = 0u;
                                loop {
                                    let _e691 = phi_1072_;
                                    let _e693 = phi_1075_;
                                    local_4 = _e693;
                                    local_5 = _e693;
                                    local_7 = _e693;
                                    let _e694 = (_e691 < _e689);
                                    if _e694 {
                                        let _e699 = ((_e562 - floor(_e562)) + (f32((_e582 + (_e691 * _e689))) * 0.618034f));
                                        let _e705 = (((_e699 - floor(_e699)) + f32(_e691)) / f32(_e689));
                                        let _e709 = params.member.member_4.member_4;
                                        if (_e709 == 2f) {
                                            phi_1129_ = (_e705 * _e705);
                                        } else {
                                            phi_1129_ = pow(_e705, _e709);
                                        }
                                        let _e714 = phi_1129_;
                                        let _e715 = (_e714 + (1.3f / _e501));
                                        let _e716 = ((_e594 * _e501) * _e715);
                                        let _e717 = ((-(_e593) * _e501) * _e715);
                                        let _e726 = params.member.member_4.member_7;
                                        let _e727 = (log2(sqrt(((_e716 * _e716) + (_e717 * _e717)))) - _e726);
                                        let _e734 = (-1f - floor((-0.5f - select(0f, select(5f, _e727, (_e727 < 5f)), (_e727 > 0f)))));
                                        let _e736 = floor((_e716 + 0.5f));
                                        if ((_e736 - _e716) == 0.5f) {
                                            let _e742 = ((floor((_e736 * 0.5f)) * 2f) != _e736);
                                            if _e742 {
                                                phi_1174_ = (_e736 - 1f);
                                            } else {
                                                phi_1174_ = f32();
                                            }
                                            let _e745 = phi_1174_;
                                            phi_1176_ = _e745;
                                            phi_1177_ = select(true, false, _e742);
                                        } else {
                                            phi_1176_ = f32();
                                            phi_1177_ = true;
                                        }
                                        let _e748 = phi_1176_;
                                        let _e750 = phi_1177_;
                                        let _e752 = (select(_e748, _e736, _e750) / _e99);
                                        let _e754 = floor((_e717 + 0.5f));
                                        if ((_e754 - _e717) == 0.5f) {
                                            let _e760 = ((floor((_e754 * 0.5f)) * 2f) != _e754);
                                            if _e760 {
                                                phi_1200_ = (_e754 - 1f);
                                            } else {
                                                phi_1200_ = f32();
                                            }
                                            let _e763 = phi_1200_;
                                            phi_1202_ = _e763;
                                            phi_1203_ = select(true, false, _e760);
                                        } else {
                                            phi_1202_ = f32();
                                            phi_1203_ = true;
                                        }
                                        let _e766 = phi_1202_;
                                        let _e768 = phi_1203_;
                                        let _e770 = (select(_e766, _e754, _e768) / _e110);
                                        let _e771 = (_e380 + _e752);
                                        let _e772 = (_e383 + _e770);
                                        let _e773 = (_e380 - _e752);
                                        let _e774 = (_e383 - _e770);
                                        let _e775 = (_e734 > 0f);
                                        if _e775 {
                                            let _e780 = select(select(u32(_e734), 0u, (_e734 < 0f)), 4294967295u, (_e734 > 4294967000f));
                                            phi_1236_ = select(_e780, 4u, (4u < _e780));
                                        } else {
                                            phi_1236_ = 0u;
                                        }
                                        let _e784 = phi_1236_;
                                        let _e785 = (_e784 & 31u);
                                        let _e787 = (_e104 >> bitcast<u32>(_e785));
                                        let _e789 = select(1u, _e787, (1u < _e787));
                                        let _e791 = (_e115 >> bitcast<u32>(_e785));
                                        let _e793 = select(1u, _e791, (1u < _e791));
                                        phi_1252_ = 0u;
                                        phi_1255_ = 0u;
                                        loop {
                                            let _e795 = phi_1252_;
                                            let _e797 = phi_1255_;
                                            local_2 = _e797;
                                            let _e798 = (_e795 < _e784);
                                            if _e798 {
                                                let _e799 = (_e795 & 31u);
                                                let _e801 = (_e104 >> bitcast<u32>(_e799));
                                                let _e805 = (_e115 >> bitcast<u32>(_e799));
                                                phi_1253_ = (_e795 + 1u);
                                                phi_1256_ = (_e797 + (select(1u, _e801, (1u < _e801)) * select(1u, _e805, (1u < _e805))));
                                            } else {
                                                phi_1253_ = u32();
                                                phi_1256_ = u32();
                                            }
                                            let _e812 = phi_1253_;
                                            let _e814 = phi_1256_;
                                            continue;
                                            continuing {
                                                phi_1252_ = _e812;
                                                phi_1255_ = _e814;
                                                break if !(_e798);
                                            }
                                        }
                                        let _e818 = (_e771 * f32(_e789));
                                        if (_e818 > 0f) {
                                            let _e824 = select(select(u32(_e818), 0u, (_e818 < 0f)), 4294967295u, (_e818 > 4294967000f));
                                            let _e825 = (_e789 - 1u);
                                            phi_1300_ = select(_e824, _e825, (_e825 < _e824));
                                        } else {
                                            phi_1300_ = 0u;
                                        }
                                        let _e829 = phi_1300_;
                                        let _e830 = (_e772 * f32(_e793));
                                        if (_e830 > 0f) {
                                            let _e836 = select(select(u32(_e830), 0u, (_e830 < 0f)), 4294967295u, (_e830 > 4294967000f));
                                            let _e837 = (_e793 - 1u);
                                            phi_1319_ = select(_e836, _e837, (_e837 < _e836));
                                        } else {
                                            phi_1319_ = 0u;
                                        }
                                        let _e841 = phi_1319_;
                                        let _e844 = local_2;
                                        let _e849 = mips.member[((_e844 + (_e841 * _e789)) + _e829)];
                                        if _e775 {
                                            let _e862 = select(select(u32(_e734), 0u, (_e734 < 0f)), 4294967295u, (_e734 > 4294967000f));
                                            phi_1358_ = select(_e862, 4u, (4u < _e862));
                                        } else {
                                            phi_1358_ = 0u;
                                        }
                                        let _e866 = phi_1358_;
                                        let _e867 = (_e866 & 31u);
                                        let _e869 = (_e104 >> bitcast<u32>(_e867));
                                        let _e871 = select(1u, _e869, (1u < _e869));
                                        let _e873 = (_e115 >> bitcast<u32>(_e867));
                                        let _e875 = select(1u, _e873, (1u < _e873));
                                        phi_1374_ = 0u;
                                        phi_1377_ = 0u;
                                        loop {
                                            let _e877 = phi_1374_;
                                            let _e879 = phi_1377_;
                                            local_3 = _e879;
                                            let _e880 = (_e877 < _e866);
                                            if _e880 {
                                                let _e881 = (_e877 & 31u);
                                                let _e883 = (_e104 >> bitcast<u32>(_e881));
                                                let _e887 = (_e115 >> bitcast<u32>(_e881));
                                                phi_1375_ = (_e877 + 1u);
                                                phi_1378_ = (_e879 + (select(1u, _e883, (1u < _e883)) * select(1u, _e887, (1u < _e887))));
                                            } else {
                                                phi_1375_ = u32();
                                                phi_1378_ = u32();
                                            }
                                            let _e894 = phi_1375_;
                                            let _e896 = phi_1378_;
                                            continue;
                                            continuing {
                                                phi_1374_ = _e894;
                                                phi_1377_ = _e896;
                                                break if !(_e880);
                                            }
                                        }
                                        let _e900 = (_e773 * f32(_e871));
                                        if (_e900 > 0f) {
                                            let _e906 = select(select(u32(_e900), 0u, (_e900 < 0f)), 4294967295u, (_e900 > 4294967000f));
                                            let _e907 = (_e871 - 1u);
                                            phi_1422_ = select(_e906, _e907, (_e907 < _e906));
                                        } else {
                                            phi_1422_ = 0u;
                                        }
                                        let _e911 = phi_1422_;
                                        let _e912 = (_e774 * f32(_e875));
                                        if (_e912 > 0f) {
                                            let _e918 = select(select(u32(_e912), 0u, (_e912 < 0f)), 4294967295u, (_e912 > 4294967000f));
                                            let _e919 = (_e875 - 1u);
                                            phi_1441_ = select(_e918, _e919, (_e919 < _e918));
                                        } else {
                                            phi_1441_ = 0u;
                                        }
                                        let _e923 = phi_1441_;
                                        let _e926 = local_3;
                                        let _e931 = mips.member[((_e926 + (_e923 * _e871)) + _e911)];
                                        let _e940 = (((((_e771 * 2f) - 1f) * _e392) * _e849) - _e394);
                                        let _e941 = (((((_e772 * -2f) + 1f) * _e402) * _e849) - _e404);
                                        let _e942 = (_e849 - _e384);
                                        let _e945 = params.member.member_1;
                                        let _e946 = (_e945 > 0f);
                                        if _e946 {
                                            phi_1485_ = (sqrt((((_e940 * _e940) + (_e941 * _e941)) + (_e942 * _e942))) > _e945);
                                        } else {
                                            phi_1485_ = false;
                                        }
                                        let _e955 = phi_1485_;
                                        if !(_e955) {
                                            let _e959 = params.member.member;
                                            let _e962 = params.member.member_3;
                                            let _e967 = (((_e940 * _e415) + (_e941 * _e416)) + (_e942 * _e417));
                                            let _e971 = (_e940 - (_e415 * _e967));
                                            let _e972 = (_e941 - (_e416 * _e967));
                                            let _e973 = (_e942 - (_e417 * _e967));
                                            let _e982 = ((_e972 * _e417) - (_e416 * _e973));
                                            let _e985 = ((_e973 * _e415) - (_e417 * _e971));
                                            let _e988 = ((_e971 * _e416) - (_e415 * _e972));
                                            let _e995 = (1f / sqrt((((_e982 * _e982) + (_e985 * _e985)) + (_e988 * _e988))));
                                            let _e996 = (_e982 * _e995);
                                            let _e997 = (_e985 * _e995);
                                            let _e998 = (_e988 * _e995);
                                            let _e1003 = (((_e486 * _e996) + (_e487 * _e997)) + (_e488 * _e998));
                                            let _e1007 = (_e486 - (_e996 * _e1003));
                                            let _e1008 = (_e487 - (_e997 * _e1003));
                                            let _e1009 = (_e488 - (_e998 * _e1003));
                                            let _e1015 = sqrt((((_e1007 * _e1007) + (_e1008 * _e1008)) + (_e1009 * _e1009)));
                                            let _e1021 = ((((_e1007 * _e415) + (_e1008 * _e416)) + (_e1009 * _e417)) / _e1015);
                                            let _e1025 = select(0f, select(1f, _e1021, (_e1021 < 1f)), (_e1021 > 0f));
                                            let _e1026 = abs(_e1025);
                                            let _e1043 = (((((((((((((((_e1026 * -0.0012624911f) + 0.00667009f) * _e1026) - 0.017088126f) * _e1026) + 0.03089188f) * _e1026) - 0.050174303f) * _e1026) + 0.08897899f) * _e1026) - 0.2145988f) * _e1026) + 1.5707963f) * sqrt((1f - _e1026)));
                                            let _e1046 = select((3.1415927f - _e1043), _e1043, (_e1025 >= 0f));
                                            let _e1054 = select(_e1046, -(_e1046), ((((_e971 * _e1007) + (_e972 * _e1008)) + (_e973 * _e1009)) < 0f));
                                            let _e1055 = (0.02f / _e1015);
                                            if (_e1055 != _e1055) {
                                                phi_2970_ = true;
                                            } else {
                                                phi_2970_ = (0.19634955f <= _e1055);
                                            }
                                            let _e1059 = phi_2970_;
                                            let _e1060 = select(_e1055, 0.19634955f, _e1059);
                                            let _e1064 = (_e940 - (_e415 * _e959));
                                            let _e1065 = (_e941 - (_e416 * _e959));
                                            let _e1066 = (_e942 - (_e417 * _e959));
                                            let _e1073 = (1f / sqrt((((_e940 * _e940) + (_e941 * _e941)) + (_e942 * _e942))));
                                            let _e1081 = ((((_e940 * _e1073) * _e415) + ((_e941 * _e1073) * _e416)) + ((_e942 * _e1073) * _e417));
                                            let _e1085 = select(-1f, select(1f, _e1081, (_e1081 < 1f)), (_e1081 > -1f));
                                            let _e1086 = abs(_e1085);
                                            let _e1103 = (((((((((((((((_e1086 * -0.0012624911f) + 0.00667009f) * _e1086) - 0.017088126f) * _e1086) + 0.03089188f) * _e1086) - 0.050174303f) * _e1086) + 0.08897899f) * _e1086) - 0.2145988f) * _e1086) + 1.5707963f) * sqrt((1f - _e1086)));
                                            let _e1110 = ((((select((3.1415927f - _e1103), _e1103, (_e1085 >= 0f)) + _e1060) - _e1054) + 1.5707964f) * 0.31830987f);
                                            let _e1114 = select(0f, select(1f, _e1110, (_e1110 < 1f)), (_e1110 > 0f));
                                            let _e1121 = (1f / sqrt((((_e1064 * _e1064) + (_e1065 * _e1065)) + (_e1066 * _e1066))));
                                            let _e1129 = ((((_e1064 * _e1121) * _e415) + ((_e1065 * _e1121) * _e416)) + ((_e1066 * _e1121) * _e417));
                                            let _e1133 = select(-1f, select(1f, _e1129, (_e1129 < 1f)), (_e1129 > -1f));
                                            let _e1134 = abs(_e1133);
                                            let _e1151 = (((((((((((((((_e1134 * -0.0012624911f) + 0.00667009f) * _e1134) - 0.017088126f) * _e1134) + 0.03089188f) * _e1134) - 0.050174303f) * _e1134) + 0.08897899f) * _e1134) - 0.2145988f) * _e1134) + 1.5707963f) * sqrt((1f - _e1134)));
                                            let _e1158 = ((((select((3.1415927f - _e1151), _e1151, (_e1133 >= 0f)) + _e1060) - _e1054) + 1.5707964f) * 0.31830987f);
                                            let _e1162 = select(0f, select(1f, _e1158, (_e1158 < 1f)), (_e1158 > 0f));
                                            let _e1163 = (_e1114 != _e1114);
                                            if _e1163 {
                                                phi_2985_ = true;
                                            } else {
                                                phi_2985_ = (_e1162 <= _e1114);
                                            }
                                            let _e1166 = phi_2985_;
                                            let _e1167 = select(_e1114, _e1162, _e1166);
                                            if _e1163 {
                                                phi_3000_ = true;
                                            } else {
                                                phi_3000_ = (_e1162 >= _e1114);
                                            }
                                            let _e1170 = phi_3000_;
                                            let _e1171 = select(_e1114, _e1162, _e1170);
                                            let _e1173 = floor((_e1167 * 32f));
                                            if (_e962 == 1u) {
                                                let _e1181 = -(floor((_e1171 * -32f)));
                                                if (_e1181 != _e1181) {
                                                    phi_3015_ = true;
                                                } else {
                                                    phi_3015_ = (32f <= _e1181);
                                                }
                                                let _e1185 = phi_3015_;
                                                let _e1188 = (select(_e1181, 32f, _e1185) - _e1173);
                                                if (_e1188 != _e1188) {
                                                    phi_3030_ = true;
                                                } else {
                                                    phi_3030_ = (0f >= _e1188);
                                                }
                                                let _e1192 = phi_3030_;
                                                phi_1806_ = select(select(_e1188, 0f, _e1192), 0f, (_e1171 <= _e1167));
                                            } else {
                                                phi_1806_ = -(floor(((_e1171 - _e1167) * -32f)));
                                            }
                                            let _e1196 = phi_1806_;
                                            if (_e1173 > 0f) {
                                                let _e1202 = select(select(u32(_e1173), 0u, (_e1173 < 0f)), 4294967295u, (_e1173 > 4294967000f));
                                                phi_1824_ = select(_e1202, 32u, (32u < _e1202));
                                            } else {
                                                phi_1824_ = 0u;
                                            }
                                            let _e1206 = phi_1824_;
                                            if (_e1196 > 0f) {
                                                let _e1212 = select(select(u32(_e1196), 0u, (_e1196 < 0f)), 4294967295u, (_e1196 > 4294967000f));
                                                phi_1842_ = select(_e1212, 32u, (32u < _e1212));
                                            } else {
                                                phi_1842_ = 0u;
                                            }
                                            let _e1216 = phi_1842_;
                                            if (_e1206 >= 32u) {
                                                phi_1862_ = u32();
                                                phi_1863_ = true;
                                            } else {
                                                let _e1218 = (_e1216 == 0u);
                                                if _e1218 {
                                                    phi_1861_ = u32();
                                                } else {
                                                    if (_e1216 >= 32u) {
                                                        phi_1858_ = 4294967295u;
                                                    } else {
                                                        phi_1858_ = ((1u << bitcast<u32>((_e1216 & 31u))) - 1u);
                                                    }
                                                    let _e1225 = phi_1858_;
                                                    phi_1861_ = (_e1225 << bitcast<u32>((_e1206 & 31u)));
                                                }
                                                let _e1230 = phi_1861_;
                                                phi_1862_ = _e1230;
                                                phi_1863_ = _e1218;
                                            }
                                            let _e1232 = phi_1862_;
                                            let _e1234 = phi_1863_;
                                            phi_1877_ = select(select(select(_e1232, 0u, _e1234), 0u, (sqrt((((_e971 * _e971) + (_e972 * _e972)) + (_e973 * _e973))) <= 0f)), 0u, _e955);
                                        } else {
                                            phi_1877_ = 0u;
                                        }
                                        let _e1240 = phi_1877_;
                                        let _e1242 = (((((_e773 * 2f) - 1f) * _e392) * _e931) - _e394);
                                        let _e1243 = (((((_e774 * -2f) + 1f) * _e402) * _e931) - _e404);
                                        let _e1244 = (_e931 - _e384);
                                        if _e946 {
                                            phi_1901_ = (sqrt((((_e1242 * _e1242) + (_e1243 * _e1243)) + (_e1244 * _e1244))) > _e945);
                                        } else {
                                            phi_1901_ = false;
                                        }
                                        let _e1253 = phi_1901_;
                                        if !(_e1253) {
                                            let _e1257 = params.member.member;
                                            let _e1260 = params.member.member_3;
                                            let _e1265 = (((_e1242 * _e415) + (_e1243 * _e416)) + (_e1244 * _e417));
                                            let _e1269 = (_e1242 - (_e415 * _e1265));
                                            let _e1270 = (_e1243 - (_e416 * _e1265));
                                            let _e1271 = (_e1244 - (_e417 * _e1265));
                                            let _e1280 = ((_e1270 * _e417) - (_e416 * _e1271));
                                            let _e1283 = ((_e1271 * _e415) - (_e417 * _e1269));
                                            let _e1286 = ((_e1269 * _e416) - (_e415 * _e1270));
                                            let _e1293 = (1f / sqrt((((_e1280 * _e1280) + (_e1283 * _e1283)) + (_e1286 * _e1286))));
                                            let _e1294 = (_e1280 * _e1293);
                                            let _e1295 = (_e1283 * _e1293);
                                            let _e1296 = (_e1286 * _e1293);
                                            let _e1301 = (((_e486 * _e1294) + (_e487 * _e1295)) + (_e488 * _e1296));
                                            let _e1305 = (_e486 - (_e1294 * _e1301));
                                            let _e1306 = (_e487 - (_e1295 * _e1301));
                                            let _e1307 = (_e488 - (_e1296 * _e1301));
                                            let _e1313 = sqrt((((_e1305 * _e1305) + (_e1306 * _e1306)) + (_e1307 * _e1307)));
                                            let _e1319 = ((((_e1305 * _e415) + (_e1306 * _e416)) + (_e1307 * _e417)) / _e1313);
                                            let _e1323 = select(0f, select(1f, _e1319, (_e1319 < 1f)), (_e1319 > 0f));
                                            let _e1324 = abs(_e1323);
                                            let _e1341 = (((((((((((((((_e1324 * -0.0012624911f) + 0.00667009f) * _e1324) - 0.017088126f) * _e1324) + 0.03089188f) * _e1324) - 0.050174303f) * _e1324) + 0.08897899f) * _e1324) - 0.2145988f) * _e1324) + 1.5707963f) * sqrt((1f - _e1324)));
                                            let _e1344 = select((3.1415927f - _e1341), _e1341, (_e1323 >= 0f));
                                            let _e1352 = select(_e1344, -(_e1344), ((((_e1269 * _e1305) + (_e1270 * _e1306)) + (_e1271 * _e1307)) < 0f));
                                            let _e1353 = (0.02f / _e1313);
                                            if (_e1353 != _e1353) {
                                                phi_3045_ = true;
                                            } else {
                                                phi_3045_ = (0.19634955f <= _e1353);
                                            }
                                            let _e1357 = phi_3045_;
                                            let _e1358 = select(_e1353, 0.19634955f, _e1357);
                                            let _e1362 = (_e1242 - (_e415 * _e1257));
                                            let _e1363 = (_e1243 - (_e416 * _e1257));
                                            let _e1364 = (_e1244 - (_e417 * _e1257));
                                            let _e1371 = (1f / sqrt((((_e1242 * _e1242) + (_e1243 * _e1243)) + (_e1244 * _e1244))));
                                            let _e1379 = ((((_e1242 * _e1371) * _e415) + ((_e1243 * _e1371) * _e416)) + ((_e1244 * _e1371) * _e417));
                                            let _e1383 = select(-1f, select(1f, _e1379, (_e1379 < 1f)), (_e1379 > -1f));
                                            let _e1384 = abs(_e1383);
                                            let _e1401 = (((((((((((((((_e1384 * -0.0012624911f) + 0.00667009f) * _e1384) - 0.017088126f) * _e1384) + 0.03089188f) * _e1384) - 0.050174303f) * _e1384) + 0.08897899f) * _e1384) - 0.2145988f) * _e1384) + 1.5707963f) * sqrt((1f - _e1384)));
                                            let _e1408 = ((((select((3.1415927f - _e1401), _e1401, (_e1383 >= 0f)) + _e1358) - _e1352) + 1.5707964f) * 0.31830987f);
                                            let _e1419 = (1f / sqrt((((_e1362 * _e1362) + (_e1363 * _e1363)) + (_e1364 * _e1364))));
                                            let _e1427 = ((((_e1362 * _e1419) * _e415) + ((_e1363 * _e1419) * _e416)) + ((_e1364 * _e1419) * _e417));
                                            let _e1431 = select(-1f, select(1f, _e1427, (_e1427 < 1f)), (_e1427 > -1f));
                                            let _e1432 = abs(_e1431);
                                            let _e1449 = (((((((((((((((_e1432 * -0.0012624911f) + 0.00667009f) * _e1432) - 0.017088126f) * _e1432) + 0.03089188f) * _e1432) - 0.050174303f) * _e1432) + 0.08897899f) * _e1432) - 0.2145988f) * _e1432) + 1.5707963f) * sqrt((1f - _e1432)));
                                            let _e1456 = ((((select((3.1415927f - _e1449), _e1449, (_e1431 >= 0f)) + _e1358) - _e1352) + 1.5707964f) * 0.31830987f);
                                            let _e1461 = (1f - select(0f, select(1f, _e1408, (_e1408 < 1f)), (_e1408 > 0f)));
                                            let _e1462 = (1f - select(0f, select(1f, _e1456, (_e1456 < 1f)), (_e1456 > 0f)));
                                            let _e1463 = (_e1461 != _e1461);
                                            if _e1463 {
                                                phi_3060_ = true;
                                            } else {
                                                phi_3060_ = (_e1462 <= _e1461);
                                            }
                                            let _e1466 = phi_3060_;
                                            let _e1467 = select(_e1461, _e1462, _e1466);
                                            if _e1463 {
                                                phi_3075_ = true;
                                            } else {
                                                phi_3075_ = (_e1462 >= _e1461);
                                            }
                                            let _e1470 = phi_3075_;
                                            let _e1471 = select(_e1461, _e1462, _e1470);
                                            let _e1473 = floor((_e1467 * 32f));
                                            if (_e1260 == 1u) {
                                                let _e1481 = -(floor((_e1471 * -32f)));
                                                if (_e1481 != _e1481) {
                                                    phi_3090_ = true;
                                                } else {
                                                    phi_3090_ = (32f <= _e1481);
                                                }
                                                let _e1485 = phi_3090_;
                                                let _e1488 = (select(_e1481, 32f, _e1485) - _e1473);
                                                if (_e1488 != _e1488) {
                                                    phi_3105_ = true;
                                                } else {
                                                    phi_3105_ = (0f >= _e1488);
                                                }
                                                let _e1492 = phi_3105_;
                                                phi_2222_ = select(select(_e1488, 0f, _e1492), 0f, (_e1471 <= _e1467));
                                            } else {
                                                phi_2222_ = -(floor(((_e1471 - _e1467) * -32f)));
                                            }
                                            let _e1496 = phi_2222_;
                                            if (_e1473 > 0f) {
                                                let _e1502 = select(select(u32(_e1473), 0u, (_e1473 < 0f)), 4294967295u, (_e1473 > 4294967000f));
                                                phi_2240_ = select(_e1502, 32u, (32u < _e1502));
                                            } else {
                                                phi_2240_ = 0u;
                                            }
                                            let _e1506 = phi_2240_;
                                            if (_e1496 > 0f) {
                                                let _e1512 = select(select(u32(_e1496), 0u, (_e1496 < 0f)), 4294967295u, (_e1496 > 4294967000f));
                                                phi_2258_ = select(_e1512, 32u, (32u < _e1512));
                                            } else {
                                                phi_2258_ = 0u;
                                            }
                                            let _e1516 = phi_2258_;
                                            if (_e1506 >= 32u) {
                                                phi_2278_ = u32();
                                                phi_2279_ = true;
                                            } else {
                                                let _e1518 = (_e1516 == 0u);
                                                if _e1518 {
                                                    phi_2277_ = u32();
                                                } else {
                                                    if (_e1516 >= 32u) {
                                                        phi_2274_ = 4294967295u;
                                                    } else {
                                                        phi_2274_ = ((1u << bitcast<u32>((_e1516 & 31u))) - 1u);
                                                    }
                                                    let _e1525 = phi_2274_;
                                                    phi_2277_ = (_e1525 << bitcast<u32>((_e1506 & 31u)));
                                                }
                                                let _e1530 = phi_2277_;
                                                phi_2278_ = _e1530;
                                                phi_2279_ = _e1518;
                                            }
                                            let _e1532 = phi_2278_;
                                            let _e1534 = phi_2279_;
                                            phi_2293_ = select(select(select(_e1532, 0u, _e1534), 0u, (sqrt((((_e1269 * _e1269) + (_e1270 * _e1270)) + (_e1271 * _e1271))) <= 0f)), 0u, _e1253);
                                        } else {
                                            phi_2293_ = 0u;
                                        }
                                        let _e1540 = phi_2293_;
                                        phi_1073_ = (_e691 + 1u);
                                        phi_1076_ = ((_e693 | _e1240) | _e1540);
                                    } else {
                                        phi_1073_ = u32();
                                        phi_1076_ = u32();
                                    }
                                    let _e1544 = phi_1073_;
                                    let _e1546 = phi_1076_;
                                    continue;
                                    continuing {
                                        phi_1072_ = _e1544;
                                        phi_1075_ = _e1546;
                                        break if !(_e694);
                                    }
                                }
                                let _e1550 = params.member.member_2;
                                if (_e1550 == 2u) {
                                    let _e1607 = (_e683 - 1.5707964f);
                                    let _e1608 = (_e1607 * 2f);
                                    let _e1609 = sin(_e683);
                                    let _e1614 = ((_e661 + (_e1608 * _e1609)) - cos((_e1608 - _e683)));
                                    phi_2324_ = 0u;
                                    phi_2327_ = select((_e1614 * 0.25f), (_e1614 * -0.25f), (_e1607 < 0f));
                                    phi_2329_ = 0f;
                                    loop {
                                        let _e1620 = phi_2324_;
                                        let _e1622 = phi_2327_;
                                        let _e1624 = phi_2329_;
                                        local_8 = _e1624;
                                        let _e1625 = (_e1620 < 32u);
                                        if _e1625 {
                                            let _e1626 = (_e1620 + 1u);
                                            let _e1629 = (_e1607 + (f32(_e1626) * 0.09817477f));
                                            let _e1630 = (_e1629 * 2f);
                                            let _e1635 = ((_e661 + (_e1630 * _e1609)) - cos((_e1630 - _e683)));
                                            let _e1639 = select((_e1635 * 0.25f), (_e1635 * -0.25f), (_e1629 < 0f));
                                            let _e1642 = local_7;
                                            phi_2325_ = _e1626;
                                            phi_2328_ = _e1639;
                                            phi_2330_ = select(_e1624, (_e1624 + (_e1639 - _e1622)), (((_e1642 >> bitcast<u32>((_e1620 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2325_ = u32();
                                            phi_2328_ = f32();
                                            phi_2330_ = f32();
                                        }
                                        let _e1651 = phi_2325_;
                                        let _e1653 = phi_2328_;
                                        let _e1655 = phi_2330_;
                                        continue;
                                        continuing {
                                            phi_2324_ = _e1651;
                                            phi_2327_ = _e1653;
                                            phi_2329_ = _e1655;
                                            break if !(_e1625);
                                        }
                                    }
                                    let _e1658 = local_8;
                                    phi_3368_ = _e580;
                                    phi_2432_ = (_e584 + 1f);
                                    phi_2433_ = (_e586 + ((_e642 + ((1f - _e642) * 0.05f)) * _e1658));
                                } else {
                                    if (_e1550 == 1u) {
                                        phi_2377_ = 0u;
                                        phi_2380_ = 0f;
                                        loop {
                                            let _e1563 = phi_2377_;
                                            let _e1565 = phi_2380_;
                                            local_6 = _e1565;
                                            let _e1566 = (_e1563 < 4u);
                                            if _e1566 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1566 {
                                                } else {
                                                    phi_3164_ = true;
                                                    break;
                                                }
                                                let _e1569 = local[_e1563].member;
                                                let _e1572 = local[_e1563].member_1;
                                                let _e1574 = local_5;
                                                phi_2378_ = (_e1563 + 1u);
                                                phi_2381_ = (_e1565 + (f32(countOneBits((_e1574 & _e1569))) * _e1572));
                                            } else {
                                                phi_2378_ = u32();
                                                phi_2381_ = f32();
                                            }
                                            let _e1582 = phi_2378_;
                                            let _e1584 = phi_2381_;
                                            continue;
                                            continuing {
                                                phi_2377_ = _e1582;
                                                phi_2380_ = _e1584;
                                                phi_3164_ = _e580;
                                                break if !(_e1566);
                                            }
                                        }
                                        let _e1587 = phi_3164_;
                                        phi_3366_ = _e1587;
                                        if _e1587 {
                                            break;
                                        }
                                        let _e1589 = local_6;
                                        let _e1590 = (1f - _e1589);
                                        phi_3374_ = _e1587;
                                        phi_2430_ = (_e584 + _e642);
                                        phi_2431_ = (_e586 + (_e642 * select(0f, select(1f, _e1590, (_e1590 < 1f)), (_e1590 > 0f))));
                                    } else {
                                        let _e1554 = local_4;
                                        phi_3374_ = _e580;
                                        phi_2430_ = (_e584 + 1f);
                                        phi_2431_ = (_e586 + ((f32(countOneBits((_e1554 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1599 = phi_3374_;
                                    let _e1601 = phi_2430_;
                                    let _e1603 = phi_2431_;
                                    phi_3368_ = _e1599;
                                    phi_2432_ = _e1601;
                                    phi_2433_ = _e1603;
                                }
                                let _e1663 = phi_3368_;
                                let _e1665 = phi_2432_;
                                let _e1667 = phi_2433_;
                                phi_3367_ = _e1663;
                                phi_873_ = (_e582 + 1u);
                                phi_876_ = _e1665;
                                phi_878_ = _e1667;
                            } else {
                                phi_3367_ = _e580;
                                phi_873_ = u32();
                                phi_876_ = f32();
                                phi_878_ = f32();
                            }
                            let _e1670 = phi_3367_;
                            let _e1672 = phi_873_;
                            let _e1674 = phi_876_;
                            let _e1676 = phi_878_;
                            continue;
                            continuing {
                                phi_3285_ = _e1670;
                                phi_872_ = _e1672;
                                phi_875_ = _e1674;
                                phi_877_ = _e1676;
                                phi_3366_ = _e1670;
                                break if !(_e587);
                            }
                        }
                        let _e1679 = phi_3366_;
                        if _e1679 {
                            break;
                        }
                        let _e1681 = local_9;
                        let _e1684 = local_10;
                        let _e1686 = local_11;
                        phi_2441_ = select(1f, (_e1684 / _e1686), (_e1681 > 0f));
                    } else {
                        phi_2441_ = 1f;
                    }
                    let _e1690 = phi_2441_;
                    if _e572 {
                        let _e1694 = params.member.member_4.member_6;
                        let _e1695 = pow(_e1690, _e1694);
                        if (_e1695 != _e1695) {
                            phi_3138_ = true;
                        } else {
                            phi_3138_ = (0.03f >= _e1695);
                        }
                        let _e1699 = phi_3138_;
                        let _e1701 = (select(_e1695, 0.03f, _e1699) * 0.6666667f);
                        let _e1707 = ((select(0f, select(1f, _e1701, (_e1701 < 1f)), (_e1701 > 0f)) * 255f) + 0.5f);
                        phi_2490_ = select(select(u32(_e1707), 0u, (_e1707 < 0f)), 4294967295u, (_e1707 > 4294967000f));
                    } else {
                        phi_2490_ = 170u;
                    }
                    let _e1714 = phi_2490_;
                    terms.member[_e121] = _e1714;
                    edges.member[_e121] = ((((64u * _e275) + (16u * _e308)) + (4u * _e342)) + _e376);
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
