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
    var phi_2976_: bool;
    var phi_2991_: bool;
    var phi_2952_: vec2<f32>;
    var phi_3008_: u32;
    var phi_3009_: u32;
    var phi_3010_: u32;
    var phi_3011_: u32;
    var phi_3034_: u32;
    var phi_3035_: u32;
    var phi_3038_: u32;
    var phi_3039_: u32;
    var phi_3043_: u32;
    var phi_3044_: u32;
    var phi_3045_: u32;
    var phi_3046_: u32;
    var local_1: u32;
    var phi_3275_: bool;
    var phi_867_: u32;
    var phi_870_: f32;
    var phi_872_: f32;
    var phi_1067_: u32;
    var phi_1070_: u32;
    var phi_1125_: f32;
    var phi_1671_: bool;
    var phi_2022_: f32;
    var phi_2064_: u32;
    var phi_2067_: u32;
    var phi_2068_: u32;
    var phi_2069_: bool;
    var phi_2083_: u32;
    var phi_2107_: bool;
    var phi_2458_: f32;
    var phi_2500_: u32;
    var phi_2503_: u32;
    var phi_2504_: u32;
    var phi_2505_: bool;
    var phi_2519_: u32;
    var phi_1068_: u32;
    var phi_1071_: u32;
    var local_2: u32;
    var phi_2603_: u32;
    var phi_2606_: f32;
    var local_3: u32;
    var phi_2604_: u32;
    var phi_2607_: f32;
    var phi_3124_: bool;
    var local_4: f32;
    var phi_3352_: bool;
    var phi_2656_: f32;
    var phi_2657_: f32;
    var phi_2550_: u32;
    var phi_2553_: f32;
    var phi_2555_: f32;
    var local_5: u32;
    var phi_2551_: u32;
    var phi_2554_: f32;
    var phi_2556_: f32;
    var local_6: f32;
    var phi_3346_: bool;
    var phi_2658_: f32;
    var phi_2659_: f32;
    var phi_3345_: bool;
    var phi_868_: u32;
    var phi_871_: f32;
    var phi_873_: f32;
    var phi_3344_: bool;
    var local_7: f32;
    var local_8: f32;
    var local_9: f32;
    var phi_2667_: f32;
    var phi_3098_: bool;
    var phi_2716_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e94 = id_1;
            let _e101 = params.member.member_4.member.member[0u];
            let _e106 = select(select(u32(_e101), 0u, (_e101 < 0f)), 4294967295u, (_e101 > 4294967000f));
            let _e112 = params.member.member_4.member.member[1u];
            let _e117 = select(select(u32(_e112), 0u, (_e112 < 0f)), 4294967295u, (_e112 > 4294967000f));
            if (_e94.x >= _e106) {
            } else {
                if (_e94.y >= _e117) {
                } else {
                    let _e123 = ((_e94.y * _e106) + _e94.x);
                    let _e125 = mips.member[_e123];
                    let _e126 = bitcast<i32>(_e94.x);
                    let _e127 = (_e126 + -1i);
                    let _e129 = select(0i, _e127, (0i < _e127));
                    let _e131 = (bitcast<i32>(_e106) - 1i);
                    let _e135 = bitcast<i32>(_e94.y);
                    let _e137 = select(0i, _e135, (0i < _e135));
                    let _e139 = (bitcast<i32>(_e117) - 1i);
                    let _e143 = (bitcast<u32>(select(_e137, _e139, (_e139 < _e137))) * _e106);
                    let _e146 = mips.member[(_e143 + bitcast<u32>(select(_e129, _e131, (_e131 < _e129))))];
                    let _e147 = (_e126 + 1i);
                    let _e149 = select(0i, _e147, (0i < _e147));
                    let _e155 = mips.member[(_e143 + bitcast<u32>(select(_e149, _e131, (_e131 < _e149))))];
                    let _e157 = select(0i, _e126, (0i < _e126));
                    let _e160 = bitcast<u32>(select(_e157, _e131, (_e131 < _e157)));
                    let _e161 = (_e135 + -1i);
                    let _e163 = select(0i, _e161, (0i < _e161));
                    let _e170 = mips.member[((bitcast<u32>(select(_e163, _e139, (_e139 < _e163))) * _e106) + _e160)];
                    let _e171 = (_e135 + 1i);
                    let _e173 = select(0i, _e171, (0i < _e171));
                    let _e180 = mips.member[((bitcast<u32>(select(_e173, _e139, (_e139 < _e173))) * _e106) + _e160)];
                    let _e181 = (_e146 - _e125);
                    let _e182 = (_e155 - _e125);
                    let _e183 = (_e170 - _e125);
                    let _e184 = (_e180 - _e125);
                    let _e186 = ((_e182 - _e181) * 0.5f);
                    let _e188 = ((_e184 - _e183) * 0.5f);
                    let _e189 = (_e125 * 0.011f);
                    let _e191 = abs(_e181);
                    let _e192 = abs((_e181 + _e186));
                    let _e198 = (1.25f - (select(_e192, _e191, ((_e191 < _e192) || (_e192 != _e192))) / _e189));
                    let _e202 = select(0f, select(1f, _e198, (_e198 < 1f)), (_e198 > 0f));
                    let _e204 = abs(_e182);
                    let _e205 = abs((_e182 - _e186));
                    let _e211 = (1.25f - (select(_e205, _e204, ((_e204 < _e205) || (_e205 != _e205))) / _e189));
                    let _e215 = select(0f, select(1f, _e211, (_e211 < 1f)), (_e211 > 0f));
                    let _e217 = abs(_e183);
                    let _e218 = abs((_e183 + _e188));
                    let _e224 = (1.25f - (select(_e218, _e217, ((_e217 < _e218) || (_e218 != _e218))) / _e189));
                    let _e228 = select(0f, select(1f, _e224, (_e224 < 1f)), (_e224 > 0f));
                    let _e230 = abs(_e184);
                    let _e231 = abs((_e184 - _e188));
                    let _e237 = (1.25f - (select(_e231, _e230, ((_e230 < _e231) || (_e231 != _e231))) / _e189));
                    let _e241 = select(0f, select(1f, _e237, (_e237 < 1f)), (_e237 > 0f));
                    let _e246 = (select(0f, select(1f, _e202, (_e202 < 1f)), (_e202 > 0f)) * 2.9f);
                    let _e248 = floor((_e246 + 0.5f));
                    let _e257 = select(_e248, (_e248 - 1f), (((_e248 - _e246) == 0.5f) && ((floor((_e248 * 0.5f)) * 2f) != _e248)));
                    let _e259 = select(0f, _e257, (_e257 > 0f));
                    let _e268 = (select(0f, select(1f, _e215, (_e215 < 1f)), (_e215 > 0f)) * 2.9f);
                    let _e270 = floor((_e268 + 0.5f));
                    let _e279 = select(_e270, (_e270 - 1f), (((_e270 - _e268) == 0.5f) && ((floor((_e270 * 0.5f)) * 2f) != _e270)));
                    let _e281 = select(0f, _e279, (_e279 > 0f));
                    let _e291 = (select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f)) * 2.9f);
                    let _e293 = floor((_e291 + 0.5f));
                    let _e302 = select(_e293, (_e293 - 1f), (((_e293 - _e291) == 0.5f) && ((floor((_e293 * 0.5f)) * 2f) != _e293)));
                    let _e304 = select(0f, _e302, (_e302 > 0f));
                    let _e314 = (select(0f, select(1f, _e241, (_e241 < 1f)), (_e241 > 0f)) * 2.9f);
                    let _e316 = floor((_e314 + 0.5f));
                    let _e325 = select(_e316, (_e316 - 1f), (((_e316 - _e314) == 0.5f) && ((floor((_e316 * 0.5f)) * 2f) != _e316)));
                    let _e327 = select(0f, _e325, (_e325 > 0f));
                    let _e334 = ((f32(_e94.x) + 0.5f) / _e101);
                    let _e337 = ((f32(_e94.y) + 0.5f) / _e112);
                    let _e338 = (_e125 * 0.99999f);
                    let _e346 = params.member.member_4.member.member_1[0u];
                    let _e348 = ((((_e334 * 2f) - 1f) * _e346) * _e338);
                    let _e356 = params.member.member_4.member.member_1[1u];
                    let _e358 = ((((_e337 * -2f) + 1f) * _e356) * _e338);
                    let _e359 = -(_e348);
                    let _e360 = -(_e358);
                    let _e361 = (_e125 * -0.99999f);
                    let _e368 = (1f / sqrt((((_e359 * _e359) + (_e360 * _e360)) + (_e361 * _e361))));
                    let _e369 = (_e359 * _e368);
                    let _e370 = (_e360 * _e368);
                    let _e371 = (_e361 * _e368);
                    let _e374 = normals.member[_e123];
                    let _e382 = (f32((bitcast<i32>(((_e374 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e382 != _e382) {
                        phi_2976_ = true;
                    } else {
                        phi_2976_ = (-1f >= _e382);
                    }
                    let _e386 = phi_2976_;
                    let _e387 = select(_e382, -1f, _e386);
                    let _e397 = (f32((bitcast<i32>((((_e374 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e397 != _e397) {
                        phi_2991_ = true;
                    } else {
                        phi_2991_ = (-1f >= _e397);
                    }
                    let _e401 = phi_2991_;
                    let _e402 = select(_e397, -1f, _e401);
                    let _e405 = (1f - abs(_e387));
                    let _e406 = abs(_e402);
                    let _e407 = (_e405 - _e406);
                    if (_e407 < 0f) {
                        phi_2952_ = vec2<f32>(((1f - _e406) * select(1f, -1f, (_e387 < 0f))), (_e405 * select(1f, -1f, (_e402 < 0f))));
                    } else {
                        phi_2952_ = vec2<f32>(_e387, _e402);
                    }
                    let _e418 = phi_2952_;
                    let _e427 = (1f / sqrt((((_e418.x * _e418.x) + (_e418.y * _e418.y)) + (_e407 * _e407))));
                    let _e428 = (_e418.x * _e427);
                    let _e429 = (_e418.y * _e427);
                    let _e430 = (_e407 * _e427);
                    let _e431 = -(_e430);
                    let _e437 = ((((_e428 * _e369) + (_e429 * _e370)) + (_e431 * _e371)) < 0f);
                    let _e440 = select(_e428, -(_e428), _e437);
                    let _e441 = select(_e429, -(_e429), _e437);
                    let _e442 = select(_e431, _e430, _e437);
                    let _e446 = params.member.member_4.member_1;
                    let _e450 = params.member.member_4.member_2;
                    let _e455 = ((_e446 * _e450) / (((_e125 * 1.99998f) * _e346) / _e101));
                    let _e460 = params.member.member_4.member_11;
                    phi_3008_ = (_e94.y & 63u);
                    phi_3009_ = (_e94.x & 63u);
                    phi_3010_ = 32u;
                    phi_3011_ = 0u;
                    loop {
                        let _e464 = phi_3008_;
                        let _e466 = phi_3009_;
                        let _e468 = phi_3010_;
                        let _e470 = phi_3011_;
                        local_1 = _e470;
                        let _e471 = (_e468 > 0u);
                        if _e471 {
                            let _e474 = select(0u, 1u, ((_e466 & _e468) != 0u));
                            let _e477 = select(0u, 1u, ((_e464 & _e468) != 0u));
                            if (_e477 == 0u) {
                                if (_e474 == 1u) {
                                    phi_3034_ = (63u - _e464);
                                    phi_3035_ = (63u - _e466);
                                } else {
                                    phi_3034_ = _e464;
                                    phi_3035_ = _e466;
                                }
                                let _e488 = phi_3034_;
                                let _e490 = phi_3035_;
                                phi_3038_ = _e490;
                                phi_3039_ = _e488;
                            } else {
                                phi_3038_ = _e464;
                                phi_3039_ = _e466;
                            }
                            let _e492 = phi_3038_;
                            let _e494 = phi_3039_;
                            phi_3043_ = _e492;
                            phi_3044_ = _e494;
                            phi_3045_ = (_e468 / 2u);
                            phi_3046_ = (_e470 + ((_e468 * _e468) * ((3u * _e474) ^ _e477)));
                        } else {
                            phi_3043_ = u32();
                            phi_3044_ = u32();
                            phi_3045_ = u32();
                            phi_3046_ = u32();
                        }
                        let _e497 = phi_3043_;
                        let _e499 = phi_3044_;
                        let _e501 = phi_3045_;
                        let _e503 = phi_3046_;
                        continue;
                        continuing {
                            phi_3008_ = _e497;
                            phi_3009_ = _e499;
                            phi_3010_ = _e501;
                            phi_3011_ = _e503;
                            break if !(_e471);
                        }
                    }
                    let _e508 = local_1;
                    let _e510 = f32((_e508 + (288u * (_e460 % 64u))));
                    let _e512 = (0.5f + (_e510 * 0.7548777f));
                    let _e516 = (0.5f + (_e510 * 0.5698403f));
                    let _e523 = params.member.member_4.member.member_3;
                    let _e526 = select(false, (_e125 < _e523), (_e125 > 0f));
                    if _e526 {
                        let _e530 = params.member.member_4.member_8;
                        let _e532 = select(1u, _e530, (1u < _e530));
                        phi_3275_ = false;
                        phi_867_ = 0u;
                        phi_870_ = 0f;
                        phi_872_ = 0f;
                        loop {
                            let _e534 = phi_3275_;
                            let _e536 = phi_867_;
                            let _e538 = phi_870_;
                            let _e540 = phi_872_;
                            local_7 = _e538;
                            local_8 = _e540;
                            local_9 = _e538;
                            let _e541 = (_e536 < _e532);
                            if _e541 {
                                let _e546 = ((((_e512 - floor(_e512)) + f32(_e536)) * 3.1415927f) / f32(_e532));
                                let _e547 = sin(_e546);
                                let _e548 = cos(_e546);
                                let _e554 = ((_e548 * _e369) + (_e547 * _e370));
                                let _e558 = (_e548 - (_e369 * _e554));
                                let _e559 = (_e547 - (_e370 * _e554));
                                let _e560 = -((_e371 * _e554));
                                let _e563 = ((_e559 * _e371) - (_e370 * _e560));
                                let _e566 = ((_e560 * _e369) - (_e371 * _e558));
                                let _e569 = ((_e558 * _e370) - (_e369 * _e559));
                                let _e576 = (1f / sqrt((((_e563 * _e563) + (_e566 * _e566)) + (_e569 * _e569))));
                                let _e577 = (_e563 * _e576);
                                let _e578 = (_e566 * _e576);
                                let _e579 = (_e569 * _e576);
                                let _e584 = (((_e440 * _e577) + (_e441 * _e578)) + (_e442 * _e579));
                                let _e588 = (_e440 - (_e577 * _e584));
                                let _e589 = (_e441 - (_e578 * _e584));
                                let _e590 = (_e442 - (_e579 * _e584));
                                let _e596 = sqrt((((_e588 * _e588) + (_e589 * _e589)) + (_e590 * _e590)));
                                let _e601 = (((_e558 * _e588) + (_e559 * _e589)) + (_e560 * _e590));
                                let _e611 = ((((_e588 * _e369) + (_e589 * _e370)) + (_e590 * _e371)) / _e596);
                                let _e615 = select(0f, select(1f, _e611, (_e611 < 1f)), (_e611 > 0f));
                                let _e616 = abs(_e615);
                                let _e634 = (((((((((((((((_e616 * -0.0012624911f) + 0.00667009f) * _e616) - 0.017088126f) * _e616) + 0.03089188f) * _e616) - 0.050174303f) * _e616) + 0.08897899f) * _e616) - 0.2145988f) * _e616) + 1.5707963f) * sqrt((1f - _e616)));
                                let _e637 = (select(select(0f, -1f, (_e601 < 0f)), 1f, (_e601 > 0f)) * select((3.1415927f - _e634), _e634, (_e615 >= 0f)));
                                let _e641 = params.member.member_4.member_9;
                                let _e643 = select(1u, _e641, (1u < _e641));
                                phi_1067_ = 0u;
                                phi_1070_ = 0u;
                                loop {
                                    let _e645 = phi_1067_;
                                    let _e647 = phi_1070_;
                                    local_2 = _e647;
                                    local_3 = _e647;
                                    local_5 = _e647;
                                    let _e648 = (_e645 < _e643);
                                    if _e648 {
                                        let _e653 = ((_e516 - floor(_e516)) + (f32((_e536 + (_e645 * _e643))) * 0.618034f));
                                        let _e660 = (((_e653 - floor(_e653)) + f32(_e645)) * (1f / f32(_e643)));
                                        let _e664 = params.member.member_4.member_4;
                                        if (_e664 == 2f) {
                                            phi_1125_ = (_e660 * _e660);
                                        } else {
                                            phi_1125_ = pow(_e660, _e664);
                                        }
                                        let _e669 = phi_1125_;
                                        let _e670 = (_e669 + (1.3f / _e455));
                                        let _e671 = ((_e548 * _e455) * _e670);
                                        let _e672 = ((-(_e547) * _e455) * _e670);
                                        let _e681 = params.member.member_4.member_7;
                                        let _e682 = (log2(sqrt(((_e671 * _e671) + (_e672 * _e672)))) - _e681);
                                        let _e689 = (-1f - floor((-0.5f - select(0f, select(5f, _e682, (_e682 < 5f)), (_e682 > 0f)))));
                                        let _e691 = floor((_e671 + 0.5f));
                                        let _e702 = (select(_e691, (_e691 - 1f), (((_e691 - _e671) == 0.5f) && ((floor((_e691 * 0.5f)) * 2f) != _e691))) * (1f / _e101));
                                        let _e704 = floor((_e672 + 0.5f));
                                        let _e715 = (select(_e704, (_e704 - 1f), (((_e704 - _e672) == 0.5f) && ((floor((_e704 * 0.5f)) * 2f) != _e704))) * (1f / _e112));
                                        let _e716 = (_e334 + _e702);
                                        let _e717 = (_e337 + _e715);
                                        let _e718 = (_e334 - _e702);
                                        let _e719 = (_e337 - _e715);
                                        let _e721 = select(1u, _e106, (1u < _e106));
                                        let _e723 = select(1u, _e117, (1u < _e117));
                                        let _e726 = (_e721 * _e723);
                                        let _e728 = (_e106 >> bitcast<u32>(1u));
                                        let _e730 = select(1u, _e728, (1u < _e728));
                                        let _e732 = (_e117 >> bitcast<u32>(1u));
                                        let _e734 = select(1u, _e732, (1u < _e732));
                                        let _e735 = (_e689 >= 1f);
                                        let _e744 = (_e726 + (_e730 * _e734));
                                        let _e746 = (_e106 >> bitcast<u32>(2u));
                                        let _e748 = select(1u, _e746, (1u < _e746));
                                        let _e750 = (_e117 >> bitcast<u32>(2u));
                                        let _e752 = select(1u, _e750, (1u < _e750));
                                        let _e753 = (_e689 >= 2f);
                                        let _e762 = (_e744 + (_e748 * _e752));
                                        let _e764 = (_e106 >> bitcast<u32>(3u));
                                        let _e766 = select(1u, _e764, (1u < _e764));
                                        let _e768 = (_e117 >> bitcast<u32>(3u));
                                        let _e770 = select(1u, _e768, (1u < _e768));
                                        let _e771 = (_e689 >= 3f);
                                        let _e782 = (_e106 >> bitcast<u32>(4u));
                                        let _e784 = select(1u, _e782, (1u < _e782));
                                        let _e786 = (_e117 >> bitcast<u32>(4u));
                                        let _e788 = select(1u, _e786, (1u < _e786));
                                        let _e789 = (_e689 >= 4f);
                                        let _e790 = select(select(select(select(_e721, _e730, _e735), _e748, _e753), _e766, _e771), _e784, _e789);
                                        let _e792 = select(select(select(select(0u, _e726, _e735), _e744, _e753), _e762, _e771), (_e762 + (_e766 * _e770)), _e789);
                                        let _e794 = select(select(select(select(f32(_e721), f32(_e730), _e735), f32(_e748), _e753), f32(_e766), _e771), f32(_e784), _e789);
                                        let _e796 = select(select(select(select(f32(_e723), f32(_e734), _e735), f32(_e752), _e753), f32(_e770), _e771), f32(_e788), _e789);
                                        let _e797 = (_e716 * _e794);
                                        let _e799 = f32((_e790 - 1u));
                                        let _e801 = select(0f, _e797, (_e797 > 0f));
                                        let _e805 = (_e717 * _e796);
                                        let _e807 = f32((select(select(select(select(_e723, _e734, _e735), _e752, _e753), _e770, _e771), _e788, _e789) - 1u));
                                        let _e809 = select(0f, _e805, (_e805 > 0f));
                                        let _e818 = mips.member[((_e792 + (u32(select(_e807, _e809, (_e809 < _e807))) * _e790)) + u32(select(_e799, _e801, (_e801 < _e799))))];
                                        let _e827 = (_e718 * _e794);
                                        let _e829 = select(0f, _e827, (_e827 > 0f));
                                        let _e833 = (_e719 * _e796);
                                        let _e835 = select(0f, _e833, (_e833 > 0f));
                                        let _e844 = mips.member[((_e792 + (u32(select(_e807, _e835, (_e835 < _e807))) * _e790)) + u32(select(_e799, _e829, (_e829 < _e799))))];
                                        let _e853 = (((((_e716 * 2f) - 1f) * _e346) * _e818) - _e348);
                                        let _e854 = (((((_e717 * -2f) + 1f) * _e356) * _e818) - _e358);
                                        let _e855 = (_e818 - _e338);
                                        let _e858 = params.member.member_1;
                                        let _e859 = (_e858 > 0f);
                                        if _e859 {
                                            phi_1671_ = (sqrt((((_e853 * _e853) + (_e854 * _e854)) + (_e855 * _e855))) > _e858);
                                        } else {
                                            phi_1671_ = false;
                                        }
                                        let _e868 = phi_1671_;
                                        if !(_e868) {
                                            let _e872 = params.member.member;
                                            let _e875 = params.member.member_3;
                                            let _e880 = (((_e853 * _e369) + (_e854 * _e370)) + (_e855 * _e371));
                                            let _e884 = (_e853 - (_e369 * _e880));
                                            let _e885 = (_e854 - (_e370 * _e880));
                                            let _e886 = (_e855 - (_e371 * _e880));
                                            let _e895 = ((_e885 * _e371) - (_e370 * _e886));
                                            let _e898 = ((_e886 * _e369) - (_e371 * _e884));
                                            let _e901 = ((_e884 * _e370) - (_e369 * _e885));
                                            let _e908 = (1f / sqrt((((_e895 * _e895) + (_e898 * _e898)) + (_e901 * _e901))));
                                            let _e909 = (_e895 * _e908);
                                            let _e910 = (_e898 * _e908);
                                            let _e911 = (_e901 * _e908);
                                            let _e916 = (((_e440 * _e909) + (_e441 * _e910)) + (_e442 * _e911));
                                            let _e920 = (_e440 - (_e909 * _e916));
                                            let _e921 = (_e441 - (_e910 * _e916));
                                            let _e922 = (_e442 - (_e911 * _e916));
                                            let _e928 = sqrt((((_e920 * _e920) + (_e921 * _e921)) + (_e922 * _e922)));
                                            let _e934 = ((((_e920 * _e369) + (_e921 * _e370)) + (_e922 * _e371)) / _e928);
                                            let _e938 = select(0f, select(1f, _e934, (_e934 < 1f)), (_e934 > 0f));
                                            let _e939 = abs(_e938);
                                            let _e956 = (((((((((((((((_e939 * -0.0012624911f) + 0.00667009f) * _e939) - 0.017088126f) * _e939) + 0.03089188f) * _e939) - 0.050174303f) * _e939) + 0.08897899f) * _e939) - 0.2145988f) * _e939) + 1.5707963f) * sqrt((1f - _e939)));
                                            let _e959 = select((3.1415927f - _e956), _e956, (_e938 >= 0f));
                                            let _e967 = select(_e959, -(_e959), ((((_e884 * _e920) + (_e885 * _e921)) + (_e886 * _e922)) < 0f));
                                            let _e968 = (0.02f / _e928);
                                            let _e971 = select(0.19634955f, _e968, ((_e968 < 0.19634955f) || false));
                                            let _e975 = (_e853 - (_e369 * _e872));
                                            let _e976 = (_e854 - (_e370 * _e872));
                                            let _e977 = (_e855 - (_e371 * _e872));
                                            let _e984 = (1f / sqrt((((_e853 * _e853) + (_e854 * _e854)) + (_e855 * _e855))));
                                            let _e992 = ((((_e853 * _e984) * _e369) + ((_e854 * _e984) * _e370)) + ((_e855 * _e984) * _e371));
                                            let _e996 = select(-1f, select(1f, _e992, (_e992 < 1f)), (_e992 > -1f));
                                            let _e997 = abs(_e996);
                                            let _e1014 = (((((((((((((((_e997 * -0.0012624911f) + 0.00667009f) * _e997) - 0.017088126f) * _e997) + 0.03089188f) * _e997) - 0.050174303f) * _e997) + 0.08897899f) * _e997) - 0.2145988f) * _e997) + 1.5707963f) * sqrt((1f - _e997)));
                                            let _e1021 = ((((select((3.1415927f - _e1014), _e1014, (_e996 >= 0f)) + _e971) - _e967) + 1.5707964f) * 0.31830987f);
                                            let _e1025 = select(0f, select(1f, _e1021, (_e1021 < 1f)), (_e1021 > 0f));
                                            let _e1032 = (1f / sqrt((((_e975 * _e975) + (_e976 * _e976)) + (_e977 * _e977))));
                                            let _e1040 = ((((_e975 * _e1032) * _e369) + ((_e976 * _e1032) * _e370)) + ((_e977 * _e1032) * _e371));
                                            let _e1044 = select(-1f, select(1f, _e1040, (_e1040 < 1f)), (_e1040 > -1f));
                                            let _e1045 = abs(_e1044);
                                            let _e1062 = (((((((((((((((_e1045 * -0.0012624911f) + 0.00667009f) * _e1045) - 0.017088126f) * _e1045) + 0.03089188f) * _e1045) - 0.050174303f) * _e1045) + 0.08897899f) * _e1045) - 0.2145988f) * _e1045) + 1.5707963f) * sqrt((1f - _e1045)));
                                            let _e1069 = ((((select((3.1415927f - _e1062), _e1062, (_e1044 >= 0f)) + _e971) - _e967) + 1.5707964f) * 0.31830987f);
                                            let _e1073 = select(0f, select(1f, _e1069, (_e1069 < 1f)), (_e1069 > 0f));
                                            let _e1075 = (_e1073 != _e1073);
                                            let _e1077 = select(_e1073, _e1025, ((_e1025 < _e1073) || _e1075));
                                            let _e1080 = select(_e1073, _e1025, ((_e1025 > _e1073) || _e1075));
                                            let _e1082 = floor((_e1077 * 32f));
                                            if (_e875 == 1u) {
                                                let _e1090 = -(floor((_e1080 * -32f)));
                                                let _e1095 = (select(32f, _e1090, ((_e1090 < 32f) || false)) - _e1082);
                                                phi_2022_ = select(select(0f, _e1095, ((_e1095 > 0f) || false)), 0f, (_e1080 <= _e1077));
                                            } else {
                                                phi_2022_ = -(floor(((_e1080 - _e1077) * -32f)));
                                            }
                                            let _e1101 = phi_2022_;
                                            let _e1103 = select(0f, _e1082, (_e1082 > 0f));
                                            let _e1106 = u32(select(32f, _e1103, (_e1103 < 32f)));
                                            let _e1108 = select(0f, _e1101, (_e1101 > 0f));
                                            let _e1111 = u32(select(32f, _e1108, (_e1108 < 32f)));
                                            if (_e1106 >= 32u) {
                                                phi_2068_ = u32();
                                                phi_2069_ = true;
                                            } else {
                                                let _e1113 = (_e1111 == 0u);
                                                if _e1113 {
                                                    phi_2067_ = u32();
                                                } else {
                                                    if (_e1111 >= 32u) {
                                                        phi_2064_ = 4294967295u;
                                                    } else {
                                                        phi_2064_ = ((1u << bitcast<u32>((_e1111 & 31u))) - 1u);
                                                    }
                                                    let _e1120 = phi_2064_;
                                                    phi_2067_ = (_e1120 << bitcast<u32>((_e1106 & 31u)));
                                                }
                                                let _e1125 = phi_2067_;
                                                phi_2068_ = _e1125;
                                                phi_2069_ = _e1113;
                                            }
                                            let _e1127 = phi_2068_;
                                            let _e1129 = phi_2069_;
                                            phi_2083_ = select(select(select(_e1127, 0u, _e1129), 0u, (sqrt((((_e884 * _e884) + (_e885 * _e885)) + (_e886 * _e886))) <= 0f)), 0u, _e868);
                                        } else {
                                            phi_2083_ = 0u;
                                        }
                                        let _e1135 = phi_2083_;
                                        let _e1137 = (((((_e718 * 2f) - 1f) * _e346) * _e844) - _e348);
                                        let _e1138 = (((((_e719 * -2f) + 1f) * _e356) * _e844) - _e358);
                                        let _e1139 = (_e844 - _e338);
                                        if _e859 {
                                            phi_2107_ = (sqrt((((_e1137 * _e1137) + (_e1138 * _e1138)) + (_e1139 * _e1139))) > _e858);
                                        } else {
                                            phi_2107_ = false;
                                        }
                                        let _e1148 = phi_2107_;
                                        if !(_e1148) {
                                            let _e1152 = params.member.member;
                                            let _e1155 = params.member.member_3;
                                            let _e1160 = (((_e1137 * _e369) + (_e1138 * _e370)) + (_e1139 * _e371));
                                            let _e1164 = (_e1137 - (_e369 * _e1160));
                                            let _e1165 = (_e1138 - (_e370 * _e1160));
                                            let _e1166 = (_e1139 - (_e371 * _e1160));
                                            let _e1175 = ((_e1165 * _e371) - (_e370 * _e1166));
                                            let _e1178 = ((_e1166 * _e369) - (_e371 * _e1164));
                                            let _e1181 = ((_e1164 * _e370) - (_e369 * _e1165));
                                            let _e1188 = (1f / sqrt((((_e1175 * _e1175) + (_e1178 * _e1178)) + (_e1181 * _e1181))));
                                            let _e1189 = (_e1175 * _e1188);
                                            let _e1190 = (_e1178 * _e1188);
                                            let _e1191 = (_e1181 * _e1188);
                                            let _e1196 = (((_e440 * _e1189) + (_e441 * _e1190)) + (_e442 * _e1191));
                                            let _e1200 = (_e440 - (_e1189 * _e1196));
                                            let _e1201 = (_e441 - (_e1190 * _e1196));
                                            let _e1202 = (_e442 - (_e1191 * _e1196));
                                            let _e1208 = sqrt((((_e1200 * _e1200) + (_e1201 * _e1201)) + (_e1202 * _e1202)));
                                            let _e1214 = ((((_e1200 * _e369) + (_e1201 * _e370)) + (_e1202 * _e371)) / _e1208);
                                            let _e1218 = select(0f, select(1f, _e1214, (_e1214 < 1f)), (_e1214 > 0f));
                                            let _e1219 = abs(_e1218);
                                            let _e1236 = (((((((((((((((_e1219 * -0.0012624911f) + 0.00667009f) * _e1219) - 0.017088126f) * _e1219) + 0.03089188f) * _e1219) - 0.050174303f) * _e1219) + 0.08897899f) * _e1219) - 0.2145988f) * _e1219) + 1.5707963f) * sqrt((1f - _e1219)));
                                            let _e1239 = select((3.1415927f - _e1236), _e1236, (_e1218 >= 0f));
                                            let _e1247 = select(_e1239, -(_e1239), ((((_e1164 * _e1200) + (_e1165 * _e1201)) + (_e1166 * _e1202)) < 0f));
                                            let _e1248 = (0.02f / _e1208);
                                            let _e1251 = select(0.19634955f, _e1248, ((_e1248 < 0.19634955f) || false));
                                            let _e1255 = (_e1137 - (_e369 * _e1152));
                                            let _e1256 = (_e1138 - (_e370 * _e1152));
                                            let _e1257 = (_e1139 - (_e371 * _e1152));
                                            let _e1264 = (1f / sqrt((((_e1137 * _e1137) + (_e1138 * _e1138)) + (_e1139 * _e1139))));
                                            let _e1272 = ((((_e1137 * _e1264) * _e369) + ((_e1138 * _e1264) * _e370)) + ((_e1139 * _e1264) * _e371));
                                            let _e1276 = select(-1f, select(1f, _e1272, (_e1272 < 1f)), (_e1272 > -1f));
                                            let _e1277 = abs(_e1276);
                                            let _e1294 = (((((((((((((((_e1277 * -0.0012624911f) + 0.00667009f) * _e1277) - 0.017088126f) * _e1277) + 0.03089188f) * _e1277) - 0.050174303f) * _e1277) + 0.08897899f) * _e1277) - 0.2145988f) * _e1277) + 1.5707963f) * sqrt((1f - _e1277)));
                                            let _e1301 = ((((select((3.1415927f - _e1294), _e1294, (_e1276 >= 0f)) + _e1251) - _e1247) + 1.5707964f) * 0.31830987f);
                                            let _e1312 = (1f / sqrt((((_e1255 * _e1255) + (_e1256 * _e1256)) + (_e1257 * _e1257))));
                                            let _e1320 = ((((_e1255 * _e1312) * _e369) + ((_e1256 * _e1312) * _e370)) + ((_e1257 * _e1312) * _e371));
                                            let _e1324 = select(-1f, select(1f, _e1320, (_e1320 < 1f)), (_e1320 > -1f));
                                            let _e1325 = abs(_e1324);
                                            let _e1342 = (((((((((((((((_e1325 * -0.0012624911f) + 0.00667009f) * _e1325) - 0.017088126f) * _e1325) + 0.03089188f) * _e1325) - 0.050174303f) * _e1325) + 0.08897899f) * _e1325) - 0.2145988f) * _e1325) + 1.5707963f) * sqrt((1f - _e1325)));
                                            let _e1349 = ((((select((3.1415927f - _e1342), _e1342, (_e1324 >= 0f)) + _e1251) - _e1247) + 1.5707964f) * 0.31830987f);
                                            let _e1354 = (1f - select(0f, select(1f, _e1301, (_e1301 < 1f)), (_e1301 > 0f)));
                                            let _e1355 = (1f - select(0f, select(1f, _e1349, (_e1349 < 1f)), (_e1349 > 0f)));
                                            let _e1357 = (_e1355 != _e1355);
                                            let _e1359 = select(_e1355, _e1354, ((_e1354 < _e1355) || _e1357));
                                            let _e1362 = select(_e1355, _e1354, ((_e1354 > _e1355) || _e1357));
                                            let _e1364 = floor((_e1359 * 32f));
                                            if (_e1155 == 1u) {
                                                let _e1372 = -(floor((_e1362 * -32f)));
                                                let _e1377 = (select(32f, _e1372, ((_e1372 < 32f) || false)) - _e1364);
                                                phi_2458_ = select(select(0f, _e1377, ((_e1377 > 0f) || false)), 0f, (_e1362 <= _e1359));
                                            } else {
                                                phi_2458_ = -(floor(((_e1362 - _e1359) * -32f)));
                                            }
                                            let _e1383 = phi_2458_;
                                            let _e1385 = select(0f, _e1364, (_e1364 > 0f));
                                            let _e1388 = u32(select(32f, _e1385, (_e1385 < 32f)));
                                            let _e1390 = select(0f, _e1383, (_e1383 > 0f));
                                            let _e1393 = u32(select(32f, _e1390, (_e1390 < 32f)));
                                            if (_e1388 >= 32u) {
                                                phi_2504_ = u32();
                                                phi_2505_ = true;
                                            } else {
                                                let _e1395 = (_e1393 == 0u);
                                                if _e1395 {
                                                    phi_2503_ = u32();
                                                } else {
                                                    if (_e1393 >= 32u) {
                                                        phi_2500_ = 4294967295u;
                                                    } else {
                                                        phi_2500_ = ((1u << bitcast<u32>((_e1393 & 31u))) - 1u);
                                                    }
                                                    let _e1402 = phi_2500_;
                                                    phi_2503_ = (_e1402 << bitcast<u32>((_e1388 & 31u)));
                                                }
                                                let _e1407 = phi_2503_;
                                                phi_2504_ = _e1407;
                                                phi_2505_ = _e1395;
                                            }
                                            let _e1409 = phi_2504_;
                                            let _e1411 = phi_2505_;
                                            phi_2519_ = select(select(select(_e1409, 0u, _e1411), 0u, (sqrt((((_e1164 * _e1164) + (_e1165 * _e1165)) + (_e1166 * _e1166))) <= 0f)), 0u, _e1148);
                                        } else {
                                            phi_2519_ = 0u;
                                        }
                                        let _e1417 = phi_2519_;
                                        phi_1068_ = (_e645 + 1u);
                                        phi_1071_ = ((_e647 | _e1135) | _e1417);
                                    } else {
                                        phi_1068_ = u32();
                                        phi_1071_ = u32();
                                    }
                                    let _e1421 = phi_1068_;
                                    let _e1423 = phi_1071_;
                                    continue;
                                    continuing {
                                        phi_1067_ = _e1421;
                                        phi_1070_ = _e1423;
                                        break if !(_e648);
                                    }
                                }
                                let _e1427 = params.member.member_2;
                                if (_e1427 == 2u) {
                                    let _e1484 = (_e637 - 1.5707964f);
                                    let _e1485 = (_e1484 * 2f);
                                    let _e1486 = sin(_e637);
                                    let _e1491 = ((_e615 + (_e1485 * _e1486)) - cos((_e1485 - _e637)));
                                    phi_2550_ = 0u;
                                    phi_2553_ = select((_e1491 * 0.25f), (_e1491 * -0.25f), (_e1484 < 0f));
                                    phi_2555_ = 0f;
                                    loop {
                                        let _e1497 = phi_2550_;
                                        let _e1499 = phi_2553_;
                                        let _e1501 = phi_2555_;
                                        local_6 = _e1501;
                                        let _e1502 = (_e1497 < 32u);
                                        if _e1502 {
                                            let _e1503 = (_e1497 + 1u);
                                            let _e1506 = (_e1484 + (f32(_e1503) * 0.09817477f));
                                            let _e1507 = (_e1506 * 2f);
                                            let _e1512 = ((_e615 + (_e1507 * _e1486)) - cos((_e1507 - _e637)));
                                            let _e1516 = select((_e1512 * 0.25f), (_e1512 * -0.25f), (_e1506 < 0f));
                                            let _e1519 = local_5;
                                            phi_2551_ = _e1503;
                                            phi_2554_ = _e1516;
                                            phi_2556_ = select(_e1501, (_e1501 + (_e1516 - _e1499)), (((_e1519 >> bitcast<u32>((_e1497 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2551_ = u32();
                                            phi_2554_ = f32();
                                            phi_2556_ = f32();
                                        }
                                        let _e1528 = phi_2551_;
                                        let _e1530 = phi_2554_;
                                        let _e1532 = phi_2556_;
                                        continue;
                                        continuing {
                                            phi_2550_ = _e1528;
                                            phi_2553_ = _e1530;
                                            phi_2555_ = _e1532;
                                            break if !(_e1502);
                                        }
                                    }
                                    let _e1535 = local_6;
                                    phi_3346_ = _e534;
                                    phi_2658_ = (_e538 + 1f);
                                    phi_2659_ = (_e540 + ((_e596 + ((1f - _e596) * 0.05f)) * _e1535));
                                } else {
                                    if (_e1427 == 1u) {
                                        phi_2603_ = 0u;
                                        phi_2606_ = 0f;
                                        loop {
                                            let _e1440 = phi_2603_;
                                            let _e1442 = phi_2606_;
                                            local_4 = _e1442;
                                            let _e1443 = (_e1440 < 4u);
                                            if _e1443 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1443 {
                                                } else {
                                                    phi_3124_ = true;
                                                    break;
                                                }
                                                let _e1446 = local[_e1440].member;
                                                let _e1449 = local[_e1440].member_1;
                                                let _e1451 = local_3;
                                                phi_2604_ = (_e1440 + 1u);
                                                phi_2607_ = (_e1442 + (f32(countOneBits((_e1451 & _e1446))) * _e1449));
                                            } else {
                                                phi_2604_ = u32();
                                                phi_2607_ = f32();
                                            }
                                            let _e1459 = phi_2604_;
                                            let _e1461 = phi_2607_;
                                            continue;
                                            continuing {
                                                phi_2603_ = _e1459;
                                                phi_2606_ = _e1461;
                                                phi_3124_ = _e534;
                                                break if !(_e1443);
                                            }
                                        }
                                        let _e1464 = phi_3124_;
                                        phi_3344_ = _e1464;
                                        if _e1464 {
                                            break;
                                        }
                                        let _e1466 = local_4;
                                        let _e1467 = (1f - _e1466);
                                        phi_3352_ = _e1464;
                                        phi_2656_ = (_e538 + _e596);
                                        phi_2657_ = (_e540 + (_e596 * select(0f, select(1f, _e1467, (_e1467 < 1f)), (_e1467 > 0f))));
                                    } else {
                                        let _e1431 = local_2;
                                        phi_3352_ = _e534;
                                        phi_2656_ = (_e538 + 1f);
                                        phi_2657_ = (_e540 + ((f32(countOneBits((_e1431 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1476 = phi_3352_;
                                    let _e1478 = phi_2656_;
                                    let _e1480 = phi_2657_;
                                    phi_3346_ = _e1476;
                                    phi_2658_ = _e1478;
                                    phi_2659_ = _e1480;
                                }
                                let _e1540 = phi_3346_;
                                let _e1542 = phi_2658_;
                                let _e1544 = phi_2659_;
                                phi_3345_ = _e1540;
                                phi_868_ = (_e536 + 1u);
                                phi_871_ = _e1542;
                                phi_873_ = _e1544;
                            } else {
                                phi_3345_ = _e534;
                                phi_868_ = u32();
                                phi_871_ = f32();
                                phi_873_ = f32();
                            }
                            let _e1547 = phi_3345_;
                            let _e1549 = phi_868_;
                            let _e1551 = phi_871_;
                            let _e1553 = phi_873_;
                            continue;
                            continuing {
                                phi_3275_ = _e1547;
                                phi_867_ = _e1549;
                                phi_870_ = _e1551;
                                phi_872_ = _e1553;
                                phi_3344_ = _e1547;
                                break if !(_e541);
                            }
                        }
                        let _e1556 = phi_3344_;
                        if _e1556 {
                            break;
                        }
                        let _e1558 = local_7;
                        let _e1561 = local_8;
                        let _e1563 = local_9;
                        phi_2667_ = select(1f, (_e1561 / _e1563), (_e1558 > 0f));
                    } else {
                        phi_2667_ = 1f;
                    }
                    let _e1567 = phi_2667_;
                    if _e526 {
                        let _e1571 = params.member.member_4.member_6;
                        let _e1572 = pow(_e1567, _e1571);
                        if (_e1572 != _e1572) {
                            phi_3098_ = true;
                        } else {
                            phi_3098_ = (0.03f >= _e1572);
                        }
                        let _e1576 = phi_3098_;
                        let _e1578 = (select(_e1572, 0.03f, _e1576) * 0.6666667f);
                        let _e1584 = ((select(0f, select(1f, _e1578, (_e1578 < 1f)), (_e1578 > 0f)) * 255f) + 0.5f);
                        phi_2716_ = select(select(u32(_e1584), 0u, (_e1584 < 0f)), 4294967295u, (_e1584 > 4294967000f));
                    } else {
                        phi_2716_ = 170u;
                    }
                    let _e1591 = phi_2716_;
                    terms.member[_e123] = _e1591;
                    edges.member[_e123] = ((((64u * u32(select(3f, _e259, (_e259 < 3f)))) + (16u * u32(select(3f, _e281, (_e281 < 3f))))) + (4u * u32(select(3f, _e304, (_e304 < 3f))))) + u32(select(3f, _e327, (_e327 < 3f))));
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
