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
    var phi_3106_: bool;
    var phi_3121_: bool;
    var phi_3082_: vec2<f32>;
    var phi_3533_: bool;
    var phi_997_: u32;
    var phi_1000_: f32;
    var phi_1002_: f32;
    var phi_1197_: u32;
    var phi_1200_: u32;
    var phi_1255_: f32;
    var phi_1801_: bool;
    var phi_2152_: f32;
    var phi_2194_: u32;
    var phi_2197_: u32;
    var phi_2198_: u32;
    var phi_2199_: bool;
    var phi_2213_: u32;
    var phi_2237_: bool;
    var phi_2588_: f32;
    var phi_2630_: u32;
    var phi_2633_: u32;
    var phi_2634_: u32;
    var phi_2635_: bool;
    var phi_2649_: u32;
    var phi_1198_: u32;
    var phi_1201_: u32;
    var local_1: u32;
    var phi_2733_: u32;
    var phi_2736_: f32;
    var local_2: u32;
    var phi_2734_: u32;
    var phi_2737_: f32;
    var phi_3382_: bool;
    var local_3: f32;
    var phi_3626_: bool;
    var phi_2786_: f32;
    var phi_2787_: f32;
    var phi_2680_: u32;
    var phi_2683_: f32;
    var phi_2685_: f32;
    var local_4: u32;
    var phi_2681_: u32;
    var phi_2684_: f32;
    var phi_2686_: f32;
    var local_5: f32;
    var phi_3620_: bool;
    var phi_2788_: f32;
    var phi_2789_: f32;
    var phi_3619_: bool;
    var phi_998_: u32;
    var phi_1001_: f32;
    var phi_1003_: f32;
    var phi_3618_: bool;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var phi_2797_: f32;
    var phi_3356_: bool;
    var phi_2846_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e96 = id_1;
            let _e103 = params.member.member_4.member.member[0u];
            let _e108 = select(select(u32(_e103), 0u, (_e103 < 0f)), 4294967295u, (_e103 > 4294967000f));
            let _e114 = params.member.member_4.member.member[1u];
            let _e119 = select(select(u32(_e114), 0u, (_e114 < 0f)), 4294967295u, (_e114 > 4294967000f));
            if (_e96.x >= _e108) {
            } else {
                if (_e96.y >= _e119) {
                } else {
                    let _e125 = ((_e96.y * _e108) + _e96.x);
                    let _e127 = mips.member[_e125];
                    let _e128 = bitcast<i32>(_e96.x);
                    let _e129 = (_e128 + -1i);
                    let _e131 = select(0i, _e129, (0i < _e129));
                    let _e133 = (bitcast<i32>(_e108) - 1i);
                    let _e137 = bitcast<i32>(_e96.y);
                    let _e139 = select(0i, _e137, (0i < _e137));
                    let _e141 = (bitcast<i32>(_e119) - 1i);
                    let _e145 = (bitcast<u32>(select(_e139, _e141, (_e141 < _e139))) * _e108);
                    let _e148 = mips.member[(_e145 + bitcast<u32>(select(_e131, _e133, (_e133 < _e131))))];
                    let _e149 = (_e128 + 1i);
                    let _e151 = select(0i, _e149, (0i < _e149));
                    let _e157 = mips.member[(_e145 + bitcast<u32>(select(_e151, _e133, (_e133 < _e151))))];
                    let _e159 = select(0i, _e128, (0i < _e128));
                    let _e162 = bitcast<u32>(select(_e159, _e133, (_e133 < _e159)));
                    let _e163 = (_e137 + -1i);
                    let _e165 = select(0i, _e163, (0i < _e163));
                    let _e172 = mips.member[((bitcast<u32>(select(_e165, _e141, (_e141 < _e165))) * _e108) + _e162)];
                    let _e173 = (_e137 + 1i);
                    let _e175 = select(0i, _e173, (0i < _e173));
                    let _e182 = mips.member[((bitcast<u32>(select(_e175, _e141, (_e141 < _e175))) * _e108) + _e162)];
                    let _e183 = (_e148 - _e127);
                    let _e184 = (_e157 - _e127);
                    let _e185 = (_e172 - _e127);
                    let _e186 = (_e182 - _e127);
                    let _e188 = ((_e184 - _e183) * 0.5f);
                    let _e190 = ((_e186 - _e185) * 0.5f);
                    let _e191 = (_e127 * 0.011f);
                    let _e193 = abs(_e183);
                    let _e194 = abs((_e183 + _e188));
                    let _e200 = (1.25f - (select(_e194, _e193, ((_e193 < _e194) || (_e194 != _e194))) / _e191));
                    let _e204 = select(0f, select(1f, _e200, (_e200 < 1f)), (_e200 > 0f));
                    let _e206 = abs(_e184);
                    let _e207 = abs((_e184 - _e188));
                    let _e213 = (1.25f - (select(_e207, _e206, ((_e206 < _e207) || (_e207 != _e207))) / _e191));
                    let _e217 = select(0f, select(1f, _e213, (_e213 < 1f)), (_e213 > 0f));
                    let _e219 = abs(_e185);
                    let _e220 = abs((_e185 + _e190));
                    let _e226 = (1.25f - (select(_e220, _e219, ((_e219 < _e220) || (_e220 != _e220))) / _e191));
                    let _e230 = select(0f, select(1f, _e226, (_e226 < 1f)), (_e226 > 0f));
                    let _e232 = abs(_e186);
                    let _e233 = abs((_e186 - _e190));
                    let _e239 = (1.25f - (select(_e233, _e232, ((_e232 < _e233) || (_e233 != _e233))) / _e191));
                    let _e243 = select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f));
                    let _e248 = (select(0f, select(1f, _e204, (_e204 < 1f)), (_e204 > 0f)) * 2.9f);
                    let _e250 = floor((_e248 + 0.5f));
                    let _e259 = select(_e250, (_e250 - 1f), (((_e250 - _e248) == 0.5f) && ((floor((_e250 * 0.5f)) * 2f) != _e250)));
                    let _e261 = select(0f, _e259, (_e259 > 0f));
                    let _e270 = (select(0f, select(1f, _e217, (_e217 < 1f)), (_e217 > 0f)) * 2.9f);
                    let _e272 = floor((_e270 + 0.5f));
                    let _e281 = select(_e272, (_e272 - 1f), (((_e272 - _e270) == 0.5f) && ((floor((_e272 * 0.5f)) * 2f) != _e272)));
                    let _e283 = select(0f, _e281, (_e281 > 0f));
                    let _e293 = (select(0f, select(1f, _e230, (_e230 < 1f)), (_e230 > 0f)) * 2.9f);
                    let _e295 = floor((_e293 + 0.5f));
                    let _e304 = select(_e295, (_e295 - 1f), (((_e295 - _e293) == 0.5f) && ((floor((_e295 * 0.5f)) * 2f) != _e295)));
                    let _e306 = select(0f, _e304, (_e304 > 0f));
                    let _e316 = (select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f)) * 2.9f);
                    let _e318 = floor((_e316 + 0.5f));
                    let _e327 = select(_e318, (_e318 - 1f), (((_e318 - _e316) == 0.5f) && ((floor((_e318 * 0.5f)) * 2f) != _e318)));
                    let _e329 = select(0f, _e327, (_e327 > 0f));
                    let _e336 = ((f32(_e96.x) + 0.5f) / _e103);
                    let _e339 = ((f32(_e96.y) + 0.5f) / _e114);
                    let _e340 = (_e127 * 0.99999f);
                    let _e348 = params.member.member_4.member.member_1[0u];
                    let _e350 = ((((_e336 * 2f) - 1f) * _e348) * _e340);
                    let _e358 = params.member.member_4.member.member_1[1u];
                    let _e360 = ((((_e339 * -2f) + 1f) * _e358) * _e340);
                    let _e361 = -(_e350);
                    let _e362 = -(_e360);
                    let _e363 = (_e127 * -0.99999f);
                    let _e370 = (1f / sqrt((((_e361 * _e361) + (_e362 * _e362)) + (_e363 * _e363))));
                    let _e371 = (_e361 * _e370);
                    let _e372 = (_e362 * _e370);
                    let _e373 = (_e363 * _e370);
                    let _e376 = normals.member[_e125];
                    let _e384 = (f32((bitcast<i32>(((_e376 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e384 != _e384) {
                        phi_3106_ = true;
                    } else {
                        phi_3106_ = (-1f >= _e384);
                    }
                    let _e388 = phi_3106_;
                    let _e389 = select(_e384, -1f, _e388);
                    let _e399 = (f32((bitcast<i32>((((_e376 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e399 != _e399) {
                        phi_3121_ = true;
                    } else {
                        phi_3121_ = (-1f >= _e399);
                    }
                    let _e403 = phi_3121_;
                    let _e404 = select(_e399, -1f, _e403);
                    let _e407 = (1f - abs(_e389));
                    let _e408 = abs(_e404);
                    let _e409 = (_e407 - _e408);
                    if (_e409 < 0f) {
                        phi_3082_ = vec2<f32>(((1f - _e408) * select(1f, -1f, (_e389 < 0f))), (_e407 * select(1f, -1f, (_e404 < 0f))));
                    } else {
                        phi_3082_ = vec2<f32>(_e389, _e404);
                    }
                    let _e420 = phi_3082_;
                    let _e429 = (1f / sqrt((((_e420.x * _e420.x) + (_e420.y * _e420.y)) + (_e409 * _e409))));
                    let _e430 = (_e420.x * _e429);
                    let _e431 = (_e420.y * _e429);
                    let _e432 = (_e409 * _e429);
                    let _e433 = -(_e432);
                    let _e439 = ((((_e430 * _e371) + (_e431 * _e372)) + (_e433 * _e373)) < 0f);
                    let _e442 = select(_e430, -(_e430), _e439);
                    let _e443 = select(_e431, -(_e431), _e439);
                    let _e444 = select(_e433, _e432, _e439);
                    let _e448 = params.member.member_4.member_1;
                    let _e452 = params.member.member_4.member_2;
                    let _e457 = ((_e448 * _e452) / (((_e127 * 1.99998f) * _e348) / _e103));
                    let _e462 = params.member.member_4.member_11;
                    let _e463 = (_e96.x & 63u);
                    let _e464 = (_e96.y & 63u);
                    let _e467 = select(0u, 1u, ((_e463 & 32u) != 0u));
                    let _e470 = select(0u, 1u, ((_e464 & 32u) != 0u));
                    let _e474 = (_e470 == 0u);
                    let _e476 = (_e474 && (_e467 == 1u));
                    let _e479 = select(_e463, (63u - _e463), _e476);
                    let _e480 = select(_e464, (63u - _e464), _e476);
                    let _e481 = select(_e479, _e480, _e474);
                    let _e482 = select(_e480, _e479, _e474);
                    let _e485 = select(0u, 1u, ((_e481 & 16u) != 0u));
                    let _e488 = select(0u, 1u, ((_e482 & 16u) != 0u));
                    let _e493 = (_e488 == 0u);
                    let _e495 = (_e493 && (_e485 == 1u));
                    let _e498 = select(_e481, (63u - _e481), _e495);
                    let _e499 = select(_e482, (63u - _e482), _e495);
                    let _e500 = select(_e498, _e499, _e493);
                    let _e501 = select(_e499, _e498, _e493);
                    let _e504 = select(0u, 1u, ((_e500 & 8u) != 0u));
                    let _e507 = select(0u, 1u, ((_e501 & 8u) != 0u));
                    let _e512 = (_e507 == 0u);
                    let _e514 = (_e512 && (_e504 == 1u));
                    let _e517 = select(_e500, (63u - _e500), _e514);
                    let _e518 = select(_e501, (63u - _e501), _e514);
                    let _e519 = select(_e517, _e518, _e512);
                    let _e520 = select(_e518, _e517, _e512);
                    let _e523 = select(0u, 1u, ((_e519 & 4u) != 0u));
                    let _e526 = select(0u, 1u, ((_e520 & 4u) != 0u));
                    let _e531 = (_e526 == 0u);
                    let _e533 = (_e531 && (_e523 == 1u));
                    let _e536 = select(_e519, (63u - _e519), _e533);
                    let _e537 = select(_e520, (63u - _e520), _e533);
                    let _e538 = select(_e536, _e537, _e531);
                    let _e539 = select(_e537, _e536, _e531);
                    let _e542 = select(0u, 1u, ((_e538 & 2u) != 0u));
                    let _e545 = select(0u, 1u, ((_e539 & 2u) != 0u));
                    let _e550 = (_e545 == 0u);
                    let _e552 = (_e550 && (_e542 == 1u));
                    let _e555 = select(_e538, (63u - _e538), _e552);
                    let _e556 = select(_e539, (63u - _e539), _e552);
                    let _e571 = f32((((((((1024u * ((3u * _e467) ^ _e470)) + (256u * ((3u * _e485) ^ _e488))) + (64u * ((3u * _e504) ^ _e507))) + (16u * ((3u * _e523) ^ _e526))) + (4u * ((3u * _e542) ^ _e545))) + ((3u * select(0u, 1u, ((select(_e555, _e556, _e550) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e556, _e555, _e550) & 1u) != 0u)))) + (288u * (_e462 % 64u))));
                    let _e573 = (0.5f + (_e571 * 0.7548777f));
                    let _e577 = (0.5f + (_e571 * 0.5698403f));
                    let _e584 = params.member.member_4.member.member_3;
                    let _e587 = select(false, (_e127 < _e584), (_e127 > 0f));
                    if _e587 {
                        let _e591 = params.member.member_4.member_8;
                        let _e593 = select(1u, _e591, (1u < _e591));
                        phi_3533_ = false;
                        phi_997_ = 0u;
                        phi_1000_ = 0f;
                        phi_1002_ = 0f;
                        loop {
                            let _e595 = phi_3533_;
                            let _e597 = phi_997_;
                            let _e599 = phi_1000_;
                            let _e601 = phi_1002_;
                            local_6 = _e599;
                            local_7 = _e601;
                            local_8 = _e599;
                            let _e602 = (_e597 < _e593);
                            if _e602 {
                                let _e607 = ((((_e573 - floor(_e573)) + f32(_e597)) * 3.1415927f) / f32(_e593));
                                let _e608 = sin(_e607);
                                let _e609 = cos(_e607);
                                let _e615 = ((_e609 * _e371) + (_e608 * _e372));
                                let _e619 = (_e609 - (_e371 * _e615));
                                let _e620 = (_e608 - (_e372 * _e615));
                                let _e621 = -((_e373 * _e615));
                                let _e624 = ((_e620 * _e373) - (_e372 * _e621));
                                let _e627 = ((_e621 * _e371) - (_e373 * _e619));
                                let _e630 = ((_e619 * _e372) - (_e371 * _e620));
                                let _e637 = (1f / sqrt((((_e624 * _e624) + (_e627 * _e627)) + (_e630 * _e630))));
                                let _e638 = (_e624 * _e637);
                                let _e639 = (_e627 * _e637);
                                let _e640 = (_e630 * _e637);
                                let _e645 = (((_e442 * _e638) + (_e443 * _e639)) + (_e444 * _e640));
                                let _e649 = (_e442 - (_e638 * _e645));
                                let _e650 = (_e443 - (_e639 * _e645));
                                let _e651 = (_e444 - (_e640 * _e645));
                                let _e657 = sqrt((((_e649 * _e649) + (_e650 * _e650)) + (_e651 * _e651)));
                                let _e662 = (((_e619 * _e649) + (_e620 * _e650)) + (_e621 * _e651));
                                let _e672 = ((((_e649 * _e371) + (_e650 * _e372)) + (_e651 * _e373)) / _e657);
                                let _e676 = select(0f, select(1f, _e672, (_e672 < 1f)), (_e672 > 0f));
                                let _e677 = abs(_e676);
                                let _e695 = (((((((((((((((_e677 * -0.0012624911f) + 0.00667009f) * _e677) - 0.017088126f) * _e677) + 0.03089188f) * _e677) - 0.050174303f) * _e677) + 0.08897899f) * _e677) - 0.2145988f) * _e677) + 1.5707963f) * sqrt((1f - _e677)));
                                let _e698 = (select(select(0f, -1f, (_e662 < 0f)), 1f, (_e662 > 0f)) * select((3.1415927f - _e695), _e695, (_e676 >= 0f)));
                                let _e702 = params.member.member_4.member_9;
                                let _e704 = select(1u, _e702, (1u < _e702));
                                phi_1197_ = 0u;
                                phi_1200_ = 0u;
                                loop {
                                    let _e706 = phi_1197_;
                                    let _e708 = phi_1200_;
                                    local_1 = _e708;
                                    local_2 = _e708;
                                    local_4 = _e708;
                                    let _e709 = (_e706 < _e704);
                                    if _e709 {
                                        let _e714 = ((_e577 - floor(_e577)) + (f32((_e597 + (_e706 * _e704))) * 0.618034f));
                                        let _e721 = (((_e714 - floor(_e714)) + f32(_e706)) * (1f / f32(_e704)));
                                        let _e725 = params.member.member_4.member_4;
                                        if (_e725 == 2f) {
                                            phi_1255_ = (_e721 * _e721);
                                        } else {
                                            phi_1255_ = pow(_e721, _e725);
                                        }
                                        let _e730 = phi_1255_;
                                        let _e731 = (_e730 + (1.3f / _e457));
                                        let _e732 = ((_e609 * _e457) * _e731);
                                        let _e733 = ((-(_e608) * _e457) * _e731);
                                        let _e742 = params.member.member_4.member_7;
                                        let _e743 = (log2(sqrt(((_e732 * _e732) + (_e733 * _e733)))) - _e742);
                                        let _e750 = (-1f - floor((-0.5f - select(0f, select(5f, _e743, (_e743 < 5f)), (_e743 > 0f)))));
                                        let _e752 = floor((_e732 + 0.5f));
                                        let _e763 = (select(_e752, (_e752 - 1f), (((_e752 - _e732) == 0.5f) && ((floor((_e752 * 0.5f)) * 2f) != _e752))) * (1f / _e103));
                                        let _e765 = floor((_e733 + 0.5f));
                                        let _e776 = (select(_e765, (_e765 - 1f), (((_e765 - _e733) == 0.5f) && ((floor((_e765 * 0.5f)) * 2f) != _e765))) * (1f / _e114));
                                        let _e777 = (_e336 + _e763);
                                        let _e778 = (_e339 + _e776);
                                        let _e779 = (_e336 - _e763);
                                        let _e780 = (_e339 - _e776);
                                        let _e782 = select(1u, _e108, (1u < _e108));
                                        let _e784 = select(1u, _e119, (1u < _e119));
                                        let _e787 = (_e782 * _e784);
                                        let _e789 = (_e108 >> bitcast<u32>(1u));
                                        let _e791 = select(1u, _e789, (1u < _e789));
                                        let _e793 = (_e119 >> bitcast<u32>(1u));
                                        let _e795 = select(1u, _e793, (1u < _e793));
                                        let _e796 = (_e750 >= 1f);
                                        let _e805 = (_e787 + (_e791 * _e795));
                                        let _e807 = (_e108 >> bitcast<u32>(2u));
                                        let _e809 = select(1u, _e807, (1u < _e807));
                                        let _e811 = (_e119 >> bitcast<u32>(2u));
                                        let _e813 = select(1u, _e811, (1u < _e811));
                                        let _e814 = (_e750 >= 2f);
                                        let _e823 = (_e805 + (_e809 * _e813));
                                        let _e825 = (_e108 >> bitcast<u32>(3u));
                                        let _e827 = select(1u, _e825, (1u < _e825));
                                        let _e829 = (_e119 >> bitcast<u32>(3u));
                                        let _e831 = select(1u, _e829, (1u < _e829));
                                        let _e832 = (_e750 >= 3f);
                                        let _e843 = (_e108 >> bitcast<u32>(4u));
                                        let _e845 = select(1u, _e843, (1u < _e843));
                                        let _e847 = (_e119 >> bitcast<u32>(4u));
                                        let _e849 = select(1u, _e847, (1u < _e847));
                                        let _e850 = (_e750 >= 4f);
                                        let _e851 = select(select(select(select(_e782, _e791, _e796), _e809, _e814), _e827, _e832), _e845, _e850);
                                        let _e853 = select(select(select(select(0u, _e787, _e796), _e805, _e814), _e823, _e832), (_e823 + (_e827 * _e831)), _e850);
                                        let _e855 = select(select(select(select(f32(_e782), f32(_e791), _e796), f32(_e809), _e814), f32(_e827), _e832), f32(_e845), _e850);
                                        let _e857 = select(select(select(select(f32(_e784), f32(_e795), _e796), f32(_e813), _e814), f32(_e831), _e832), f32(_e849), _e850);
                                        let _e858 = (_e777 * _e855);
                                        let _e860 = f32((_e851 - 1u));
                                        let _e862 = select(0f, _e858, (_e858 > 0f));
                                        let _e866 = (_e778 * _e857);
                                        let _e868 = f32((select(select(select(select(_e784, _e795, _e796), _e813, _e814), _e831, _e832), _e849, _e850) - 1u));
                                        let _e870 = select(0f, _e866, (_e866 > 0f));
                                        let _e879 = mips.member[((_e853 + (u32(select(_e868, _e870, (_e870 < _e868))) * _e851)) + u32(select(_e860, _e862, (_e862 < _e860))))];
                                        let _e888 = (_e779 * _e855);
                                        let _e890 = select(0f, _e888, (_e888 > 0f));
                                        let _e894 = (_e780 * _e857);
                                        let _e896 = select(0f, _e894, (_e894 > 0f));
                                        let _e905 = mips.member[((_e853 + (u32(select(_e868, _e896, (_e896 < _e868))) * _e851)) + u32(select(_e860, _e890, (_e890 < _e860))))];
                                        let _e914 = (((((_e777 * 2f) - 1f) * _e348) * _e879) - _e350);
                                        let _e915 = (((((_e778 * -2f) + 1f) * _e358) * _e879) - _e360);
                                        let _e916 = (_e879 - _e340);
                                        let _e919 = params.member.member_1;
                                        let _e920 = (_e919 > 0f);
                                        if _e920 {
                                            phi_1801_ = (sqrt((((_e914 * _e914) + (_e915 * _e915)) + (_e916 * _e916))) > _e919);
                                        } else {
                                            phi_1801_ = false;
                                        }
                                        let _e929 = phi_1801_;
                                        if !(_e929) {
                                            let _e933 = params.member.member;
                                            let _e936 = params.member.member_3;
                                            let _e941 = (((_e914 * _e371) + (_e915 * _e372)) + (_e916 * _e373));
                                            let _e945 = (_e914 - (_e371 * _e941));
                                            let _e946 = (_e915 - (_e372 * _e941));
                                            let _e947 = (_e916 - (_e373 * _e941));
                                            let _e956 = ((_e946 * _e373) - (_e372 * _e947));
                                            let _e959 = ((_e947 * _e371) - (_e373 * _e945));
                                            let _e962 = ((_e945 * _e372) - (_e371 * _e946));
                                            let _e969 = (1f / sqrt((((_e956 * _e956) + (_e959 * _e959)) + (_e962 * _e962))));
                                            let _e970 = (_e956 * _e969);
                                            let _e971 = (_e959 * _e969);
                                            let _e972 = (_e962 * _e969);
                                            let _e977 = (((_e442 * _e970) + (_e443 * _e971)) + (_e444 * _e972));
                                            let _e981 = (_e442 - (_e970 * _e977));
                                            let _e982 = (_e443 - (_e971 * _e977));
                                            let _e983 = (_e444 - (_e972 * _e977));
                                            let _e989 = sqrt((((_e981 * _e981) + (_e982 * _e982)) + (_e983 * _e983)));
                                            let _e995 = ((((_e981 * _e371) + (_e982 * _e372)) + (_e983 * _e373)) / _e989);
                                            let _e999 = select(0f, select(1f, _e995, (_e995 < 1f)), (_e995 > 0f));
                                            let _e1000 = abs(_e999);
                                            let _e1017 = (((((((((((((((_e1000 * -0.0012624911f) + 0.00667009f) * _e1000) - 0.017088126f) * _e1000) + 0.03089188f) * _e1000) - 0.050174303f) * _e1000) + 0.08897899f) * _e1000) - 0.2145988f) * _e1000) + 1.5707963f) * sqrt((1f - _e1000)));
                                            let _e1020 = select((3.1415927f - _e1017), _e1017, (_e999 >= 0f));
                                            let _e1028 = select(_e1020, -(_e1020), ((((_e945 * _e981) + (_e946 * _e982)) + (_e947 * _e983)) < 0f));
                                            let _e1029 = (0.02f / _e989);
                                            let _e1032 = select(0.19634955f, _e1029, ((_e1029 < 0.19634955f) || false));
                                            let _e1036 = (_e914 - (_e371 * _e933));
                                            let _e1037 = (_e915 - (_e372 * _e933));
                                            let _e1038 = (_e916 - (_e373 * _e933));
                                            let _e1045 = (1f / sqrt((((_e914 * _e914) + (_e915 * _e915)) + (_e916 * _e916))));
                                            let _e1053 = ((((_e914 * _e1045) * _e371) + ((_e915 * _e1045) * _e372)) + ((_e916 * _e1045) * _e373));
                                            let _e1057 = select(-1f, select(1f, _e1053, (_e1053 < 1f)), (_e1053 > -1f));
                                            let _e1058 = abs(_e1057);
                                            let _e1075 = (((((((((((((((_e1058 * -0.0012624911f) + 0.00667009f) * _e1058) - 0.017088126f) * _e1058) + 0.03089188f) * _e1058) - 0.050174303f) * _e1058) + 0.08897899f) * _e1058) - 0.2145988f) * _e1058) + 1.5707963f) * sqrt((1f - _e1058)));
                                            let _e1082 = ((((select((3.1415927f - _e1075), _e1075, (_e1057 >= 0f)) + _e1032) - _e1028) + 1.5707964f) * 0.31830987f);
                                            let _e1086 = select(0f, select(1f, _e1082, (_e1082 < 1f)), (_e1082 > 0f));
                                            let _e1093 = (1f / sqrt((((_e1036 * _e1036) + (_e1037 * _e1037)) + (_e1038 * _e1038))));
                                            let _e1101 = ((((_e1036 * _e1093) * _e371) + ((_e1037 * _e1093) * _e372)) + ((_e1038 * _e1093) * _e373));
                                            let _e1105 = select(-1f, select(1f, _e1101, (_e1101 < 1f)), (_e1101 > -1f));
                                            let _e1106 = abs(_e1105);
                                            let _e1123 = (((((((((((((((_e1106 * -0.0012624911f) + 0.00667009f) * _e1106) - 0.017088126f) * _e1106) + 0.03089188f) * _e1106) - 0.050174303f) * _e1106) + 0.08897899f) * _e1106) - 0.2145988f) * _e1106) + 1.5707963f) * sqrt((1f - _e1106)));
                                            let _e1130 = ((((select((3.1415927f - _e1123), _e1123, (_e1105 >= 0f)) + _e1032) - _e1028) + 1.5707964f) * 0.31830987f);
                                            let _e1134 = select(0f, select(1f, _e1130, (_e1130 < 1f)), (_e1130 > 0f));
                                            let _e1136 = (_e1134 != _e1134);
                                            let _e1138 = select(_e1134, _e1086, ((_e1086 < _e1134) || _e1136));
                                            let _e1141 = select(_e1134, _e1086, ((_e1086 > _e1134) || _e1136));
                                            let _e1143 = floor((_e1138 * 32f));
                                            if (_e936 == 1u) {
                                                let _e1151 = -(floor((_e1141 * -32f)));
                                                let _e1156 = (select(32f, _e1151, ((_e1151 < 32f) || false)) - _e1143);
                                                phi_2152_ = select(select(0f, _e1156, ((_e1156 > 0f) || false)), 0f, (_e1141 <= _e1138));
                                            } else {
                                                phi_2152_ = -(floor(((_e1141 - _e1138) * -32f)));
                                            }
                                            let _e1162 = phi_2152_;
                                            let _e1164 = select(0f, _e1143, (_e1143 > 0f));
                                            let _e1167 = u32(select(32f, _e1164, (_e1164 < 32f)));
                                            let _e1169 = select(0f, _e1162, (_e1162 > 0f));
                                            let _e1172 = u32(select(32f, _e1169, (_e1169 < 32f)));
                                            if (_e1167 >= 32u) {
                                                phi_2198_ = u32();
                                                phi_2199_ = true;
                                            } else {
                                                let _e1174 = (_e1172 == 0u);
                                                if _e1174 {
                                                    phi_2197_ = u32();
                                                } else {
                                                    if (_e1172 >= 32u) {
                                                        phi_2194_ = 4294967295u;
                                                    } else {
                                                        phi_2194_ = ((1u << bitcast<u32>((_e1172 & 31u))) - 1u);
                                                    }
                                                    let _e1181 = phi_2194_;
                                                    phi_2197_ = (_e1181 << bitcast<u32>((_e1167 & 31u)));
                                                }
                                                let _e1186 = phi_2197_;
                                                phi_2198_ = _e1186;
                                                phi_2199_ = _e1174;
                                            }
                                            let _e1188 = phi_2198_;
                                            let _e1190 = phi_2199_;
                                            phi_2213_ = select(select(select(_e1188, 0u, _e1190), 0u, (sqrt((((_e945 * _e945) + (_e946 * _e946)) + (_e947 * _e947))) <= 0f)), 0u, _e929);
                                        } else {
                                            phi_2213_ = 0u;
                                        }
                                        let _e1196 = phi_2213_;
                                        let _e1198 = (((((_e779 * 2f) - 1f) * _e348) * _e905) - _e350);
                                        let _e1199 = (((((_e780 * -2f) + 1f) * _e358) * _e905) - _e360);
                                        let _e1200 = (_e905 - _e340);
                                        if _e920 {
                                            phi_2237_ = (sqrt((((_e1198 * _e1198) + (_e1199 * _e1199)) + (_e1200 * _e1200))) > _e919);
                                        } else {
                                            phi_2237_ = false;
                                        }
                                        let _e1209 = phi_2237_;
                                        if !(_e1209) {
                                            let _e1213 = params.member.member;
                                            let _e1216 = params.member.member_3;
                                            let _e1221 = (((_e1198 * _e371) + (_e1199 * _e372)) + (_e1200 * _e373));
                                            let _e1225 = (_e1198 - (_e371 * _e1221));
                                            let _e1226 = (_e1199 - (_e372 * _e1221));
                                            let _e1227 = (_e1200 - (_e373 * _e1221));
                                            let _e1236 = ((_e1226 * _e373) - (_e372 * _e1227));
                                            let _e1239 = ((_e1227 * _e371) - (_e373 * _e1225));
                                            let _e1242 = ((_e1225 * _e372) - (_e371 * _e1226));
                                            let _e1249 = (1f / sqrt((((_e1236 * _e1236) + (_e1239 * _e1239)) + (_e1242 * _e1242))));
                                            let _e1250 = (_e1236 * _e1249);
                                            let _e1251 = (_e1239 * _e1249);
                                            let _e1252 = (_e1242 * _e1249);
                                            let _e1257 = (((_e442 * _e1250) + (_e443 * _e1251)) + (_e444 * _e1252));
                                            let _e1261 = (_e442 - (_e1250 * _e1257));
                                            let _e1262 = (_e443 - (_e1251 * _e1257));
                                            let _e1263 = (_e444 - (_e1252 * _e1257));
                                            let _e1269 = sqrt((((_e1261 * _e1261) + (_e1262 * _e1262)) + (_e1263 * _e1263)));
                                            let _e1275 = ((((_e1261 * _e371) + (_e1262 * _e372)) + (_e1263 * _e373)) / _e1269);
                                            let _e1279 = select(0f, select(1f, _e1275, (_e1275 < 1f)), (_e1275 > 0f));
                                            let _e1280 = abs(_e1279);
                                            let _e1297 = (((((((((((((((_e1280 * -0.0012624911f) + 0.00667009f) * _e1280) - 0.017088126f) * _e1280) + 0.03089188f) * _e1280) - 0.050174303f) * _e1280) + 0.08897899f) * _e1280) - 0.2145988f) * _e1280) + 1.5707963f) * sqrt((1f - _e1280)));
                                            let _e1300 = select((3.1415927f - _e1297), _e1297, (_e1279 >= 0f));
                                            let _e1308 = select(_e1300, -(_e1300), ((((_e1225 * _e1261) + (_e1226 * _e1262)) + (_e1227 * _e1263)) < 0f));
                                            let _e1309 = (0.02f / _e1269);
                                            let _e1312 = select(0.19634955f, _e1309, ((_e1309 < 0.19634955f) || false));
                                            let _e1316 = (_e1198 - (_e371 * _e1213));
                                            let _e1317 = (_e1199 - (_e372 * _e1213));
                                            let _e1318 = (_e1200 - (_e373 * _e1213));
                                            let _e1325 = (1f / sqrt((((_e1198 * _e1198) + (_e1199 * _e1199)) + (_e1200 * _e1200))));
                                            let _e1333 = ((((_e1198 * _e1325) * _e371) + ((_e1199 * _e1325) * _e372)) + ((_e1200 * _e1325) * _e373));
                                            let _e1337 = select(-1f, select(1f, _e1333, (_e1333 < 1f)), (_e1333 > -1f));
                                            let _e1338 = abs(_e1337);
                                            let _e1355 = (((((((((((((((_e1338 * -0.0012624911f) + 0.00667009f) * _e1338) - 0.017088126f) * _e1338) + 0.03089188f) * _e1338) - 0.050174303f) * _e1338) + 0.08897899f) * _e1338) - 0.2145988f) * _e1338) + 1.5707963f) * sqrt((1f - _e1338)));
                                            let _e1362 = ((((select((3.1415927f - _e1355), _e1355, (_e1337 >= 0f)) + _e1312) - _e1308) + 1.5707964f) * 0.31830987f);
                                            let _e1373 = (1f / sqrt((((_e1316 * _e1316) + (_e1317 * _e1317)) + (_e1318 * _e1318))));
                                            let _e1381 = ((((_e1316 * _e1373) * _e371) + ((_e1317 * _e1373) * _e372)) + ((_e1318 * _e1373) * _e373));
                                            let _e1385 = select(-1f, select(1f, _e1381, (_e1381 < 1f)), (_e1381 > -1f));
                                            let _e1386 = abs(_e1385);
                                            let _e1403 = (((((((((((((((_e1386 * -0.0012624911f) + 0.00667009f) * _e1386) - 0.017088126f) * _e1386) + 0.03089188f) * _e1386) - 0.050174303f) * _e1386) + 0.08897899f) * _e1386) - 0.2145988f) * _e1386) + 1.5707963f) * sqrt((1f - _e1386)));
                                            let _e1410 = ((((select((3.1415927f - _e1403), _e1403, (_e1385 >= 0f)) + _e1312) - _e1308) + 1.5707964f) * 0.31830987f);
                                            let _e1415 = (1f - select(0f, select(1f, _e1362, (_e1362 < 1f)), (_e1362 > 0f)));
                                            let _e1416 = (1f - select(0f, select(1f, _e1410, (_e1410 < 1f)), (_e1410 > 0f)));
                                            let _e1418 = (_e1416 != _e1416);
                                            let _e1420 = select(_e1416, _e1415, ((_e1415 < _e1416) || _e1418));
                                            let _e1423 = select(_e1416, _e1415, ((_e1415 > _e1416) || _e1418));
                                            let _e1425 = floor((_e1420 * 32f));
                                            if (_e1216 == 1u) {
                                                let _e1433 = -(floor((_e1423 * -32f)));
                                                let _e1438 = (select(32f, _e1433, ((_e1433 < 32f) || false)) - _e1425);
                                                phi_2588_ = select(select(0f, _e1438, ((_e1438 > 0f) || false)), 0f, (_e1423 <= _e1420));
                                            } else {
                                                phi_2588_ = -(floor(((_e1423 - _e1420) * -32f)));
                                            }
                                            let _e1444 = phi_2588_;
                                            let _e1446 = select(0f, _e1425, (_e1425 > 0f));
                                            let _e1449 = u32(select(32f, _e1446, (_e1446 < 32f)));
                                            let _e1451 = select(0f, _e1444, (_e1444 > 0f));
                                            let _e1454 = u32(select(32f, _e1451, (_e1451 < 32f)));
                                            if (_e1449 >= 32u) {
                                                phi_2634_ = u32();
                                                phi_2635_ = true;
                                            } else {
                                                let _e1456 = (_e1454 == 0u);
                                                if _e1456 {
                                                    phi_2633_ = u32();
                                                } else {
                                                    if (_e1454 >= 32u) {
                                                        phi_2630_ = 4294967295u;
                                                    } else {
                                                        phi_2630_ = ((1u << bitcast<u32>((_e1454 & 31u))) - 1u);
                                                    }
                                                    let _e1463 = phi_2630_;
                                                    phi_2633_ = (_e1463 << bitcast<u32>((_e1449 & 31u)));
                                                }
                                                let _e1468 = phi_2633_;
                                                phi_2634_ = _e1468;
                                                phi_2635_ = _e1456;
                                            }
                                            let _e1470 = phi_2634_;
                                            let _e1472 = phi_2635_;
                                            phi_2649_ = select(select(select(_e1470, 0u, _e1472), 0u, (sqrt((((_e1225 * _e1225) + (_e1226 * _e1226)) + (_e1227 * _e1227))) <= 0f)), 0u, _e1209);
                                        } else {
                                            phi_2649_ = 0u;
                                        }
                                        let _e1478 = phi_2649_;
                                        phi_1198_ = (_e706 + 1u);
                                        phi_1201_ = ((_e708 | _e1196) | _e1478);
                                    } else {
                                        phi_1198_ = u32();
                                        phi_1201_ = u32();
                                    }
                                    let _e1482 = phi_1198_;
                                    let _e1484 = phi_1201_;
                                    continue;
                                    continuing {
                                        phi_1197_ = _e1482;
                                        phi_1200_ = _e1484;
                                        break if !(_e709);
                                    }
                                }
                                let _e1488 = params.member.member_2;
                                if (_e1488 == 2u) {
                                    let _e1545 = (_e698 - 1.5707964f);
                                    let _e1546 = (_e1545 * 2f);
                                    let _e1547 = sin(_e698);
                                    let _e1552 = ((_e676 + (_e1546 * _e1547)) - cos((_e1546 - _e698)));
                                    phi_2680_ = 0u;
                                    phi_2683_ = select((_e1552 * 0.25f), (_e1552 * -0.25f), (_e1545 < 0f));
                                    phi_2685_ = 0f;
                                    loop {
                                        let _e1558 = phi_2680_;
                                        let _e1560 = phi_2683_;
                                        let _e1562 = phi_2685_;
                                        local_5 = _e1562;
                                        let _e1563 = (_e1558 < 32u);
                                        if _e1563 {
                                            let _e1564 = (_e1558 + 1u);
                                            let _e1567 = (_e1545 + (f32(_e1564) * 0.09817477f));
                                            let _e1568 = (_e1567 * 2f);
                                            let _e1573 = ((_e676 + (_e1568 * _e1547)) - cos((_e1568 - _e698)));
                                            let _e1577 = select((_e1573 * 0.25f), (_e1573 * -0.25f), (_e1567 < 0f));
                                            let _e1580 = local_4;
                                            phi_2681_ = _e1564;
                                            phi_2684_ = _e1577;
                                            phi_2686_ = select(_e1562, (_e1562 + (_e1577 - _e1560)), (((_e1580 >> bitcast<u32>((_e1558 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2681_ = u32();
                                            phi_2684_ = f32();
                                            phi_2686_ = f32();
                                        }
                                        let _e1589 = phi_2681_;
                                        let _e1591 = phi_2684_;
                                        let _e1593 = phi_2686_;
                                        continue;
                                        continuing {
                                            phi_2680_ = _e1589;
                                            phi_2683_ = _e1591;
                                            phi_2685_ = _e1593;
                                            break if !(_e1563);
                                        }
                                    }
                                    let _e1596 = local_5;
                                    phi_3620_ = _e595;
                                    phi_2788_ = (_e599 + 1f);
                                    phi_2789_ = (_e601 + ((_e657 + ((1f - _e657) * 0.05f)) * _e1596));
                                } else {
                                    if (_e1488 == 1u) {
                                        phi_2733_ = 0u;
                                        phi_2736_ = 0f;
                                        loop {
                                            let _e1501 = phi_2733_;
                                            let _e1503 = phi_2736_;
                                            local_3 = _e1503;
                                            let _e1504 = (_e1501 < 4u);
                                            if _e1504 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1504 {
                                                } else {
                                                    phi_3382_ = true;
                                                    break;
                                                }
                                                let _e1507 = local[_e1501].member;
                                                let _e1510 = local[_e1501].member_1;
                                                let _e1512 = local_2;
                                                phi_2734_ = (_e1501 + 1u);
                                                phi_2737_ = (_e1503 + (f32(countOneBits((_e1512 & _e1507))) * _e1510));
                                            } else {
                                                phi_2734_ = u32();
                                                phi_2737_ = f32();
                                            }
                                            let _e1520 = phi_2734_;
                                            let _e1522 = phi_2737_;
                                            continue;
                                            continuing {
                                                phi_2733_ = _e1520;
                                                phi_2736_ = _e1522;
                                                phi_3382_ = _e595;
                                                break if !(_e1504);
                                            }
                                        }
                                        let _e1525 = phi_3382_;
                                        phi_3618_ = _e1525;
                                        if _e1525 {
                                            break;
                                        }
                                        let _e1527 = local_3;
                                        let _e1528 = (1f - _e1527);
                                        phi_3626_ = _e1525;
                                        phi_2786_ = (_e599 + _e657);
                                        phi_2787_ = (_e601 + (_e657 * select(0f, select(1f, _e1528, (_e1528 < 1f)), (_e1528 > 0f))));
                                    } else {
                                        let _e1492 = local_1;
                                        phi_3626_ = _e595;
                                        phi_2786_ = (_e599 + 1f);
                                        phi_2787_ = (_e601 + ((f32(countOneBits((_e1492 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1537 = phi_3626_;
                                    let _e1539 = phi_2786_;
                                    let _e1541 = phi_2787_;
                                    phi_3620_ = _e1537;
                                    phi_2788_ = _e1539;
                                    phi_2789_ = _e1541;
                                }
                                let _e1601 = phi_3620_;
                                let _e1603 = phi_2788_;
                                let _e1605 = phi_2789_;
                                phi_3619_ = _e1601;
                                phi_998_ = (_e597 + 1u);
                                phi_1001_ = _e1603;
                                phi_1003_ = _e1605;
                            } else {
                                phi_3619_ = _e595;
                                phi_998_ = u32();
                                phi_1001_ = f32();
                                phi_1003_ = f32();
                            }
                            let _e1608 = phi_3619_;
                            let _e1610 = phi_998_;
                            let _e1612 = phi_1001_;
                            let _e1614 = phi_1003_;
                            continue;
                            continuing {
                                phi_3533_ = _e1608;
                                phi_997_ = _e1610;
                                phi_1000_ = _e1612;
                                phi_1002_ = _e1614;
                                phi_3618_ = _e1608;
                                break if !(_e602);
                            }
                        }
                        let _e1617 = phi_3618_;
                        if _e1617 {
                            break;
                        }
                        let _e1619 = local_6;
                        let _e1622 = local_7;
                        let _e1624 = local_8;
                        phi_2797_ = select(1f, (_e1622 / _e1624), (_e1619 > 0f));
                    } else {
                        phi_2797_ = 1f;
                    }
                    let _e1628 = phi_2797_;
                    if _e587 {
                        let _e1632 = params.member.member_4.member_6;
                        let _e1633 = pow(_e1628, _e1632);
                        if (_e1633 != _e1633) {
                            phi_3356_ = true;
                        } else {
                            phi_3356_ = (0.03f >= _e1633);
                        }
                        let _e1637 = phi_3356_;
                        let _e1639 = (select(_e1633, 0.03f, _e1637) * 0.6666667f);
                        let _e1645 = ((select(0f, select(1f, _e1639, (_e1639 < 1f)), (_e1639 > 0f)) * 255f) + 0.5f);
                        phi_2846_ = select(select(u32(_e1645), 0u, (_e1645 < 0f)), 4294967295u, (_e1645 > 4294967000f));
                    } else {
                        phi_2846_ = 170u;
                    }
                    let _e1652 = phi_2846_;
                    terms.member[_e125] = _e1652;
                    edges.member[_e125] = ((((64u * u32(select(3f, _e261, (_e261 < 3f)))) + (16u * u32(select(3f, _e283, (_e283 < 3f))))) + (4u * u32(select(3f, _e306, (_e306 < 3f))))) + u32(select(3f, _e329, (_e329 < 3f))));
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
