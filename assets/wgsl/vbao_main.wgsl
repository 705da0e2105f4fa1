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

struct type_23 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
}

struct type_24 {
    member: type_23,
}

struct type_26 {
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
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;
@group(0) @binding(4) 
var<uniform> params: type_24;

fn function_() {
    var local: array<type_26, 4>;
    var phi_451_: type_21;
    var phi_458_: u32;
    var phi_465_: u32;
    var phi_3199_: bool;
    var phi_995_: u32;
    var phi_998_: f32;
    var phi_1000_: f32;
    var phi_1193_: u32;
    var phi_1196_: u32;
    var phi_1249_: f32;
    var phi_1662_: bool;
    var phi_1994_: f32;
    var phi_2044_: u32;
    var phi_2047_: u32;
    var phi_2048_: u32;
    var phi_2049_: bool;
    var phi_2068_: u32;
    var phi_2088_: bool;
    var phi_2420_: f32;
    var phi_2470_: u32;
    var phi_2473_: u32;
    var phi_2474_: u32;
    var phi_2475_: bool;
    var phi_2494_: u32;
    var phi_1194_: u32;
    var phi_1197_: u32;
    var local_1: u32;
    var phi_2575_: u32;
    var phi_2578_: f32;
    var local_2: u32;
    var phi_2576_: u32;
    var phi_2579_: f32;
    var phi_3078_: bool;
    var local_3: f32;
    var phi_3292_: bool;
    var phi_2628_: f32;
    var phi_2629_: f32;
    var phi_2523_: u32;
    var phi_2526_: f32;
    var phi_2528_: f32;
    var local_4: u32;
    var phi_2524_: u32;
    var phi_2527_: f32;
    var phi_2529_: f32;
    var local_5: f32;
    var phi_3286_: bool;
    var phi_2630_: f32;
    var phi_2631_: f32;
    var phi_3285_: bool;
    var phi_996_: u32;
    var phi_999_: f32;
    var phi_1001_: f32;
    var phi_3284_: bool;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var phi_2639_: f32;
    var phi_3060_: bool;
    var phi_2680_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e110 = id_1;
            let _e113 = (override_type == 0u);
            if _e113 {
                let _e145 = params.member.member_4;
                phi_451_ = _e145;
            } else {
                let _e123 = params.member.member_4.member;
                let _e127 = params.member.member_4.member_1;
                let _e131 = params.member.member_4.member_10;
                let _e135 = params.member.member_4.member_11;
                let _e139 = params.member.member_4.member_12;
                let _e143 = params.member.member_4.member_14;
                phi_451_ = type_21(_e123, _e127, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e131, _e135, _e139, override_type_9, _e143);
            }
            let _e147 = phi_451_;
            if _e113 {
                let _e150 = params.member.member_2;
                phi_458_ = _e150;
            } else {
                phi_458_ = override_type_10;
            }
            let _e152 = phi_458_;
            if _e113 {
                let _e155 = params.member.member_3;
                phi_465_ = _e155;
            } else {
                phi_465_ = override_type_11;
            }
            let _e157 = phi_465_;
            let _e160 = params.member.member;
            let _e163 = params.member.member_1;
            let _e171 = select(select(u32(_e147.member.member.x), 0u, (_e147.member.member.x < 0f)), 4294967295u, (_e147.member.member.x > 4294967000f));
            let _e179 = select(select(u32(_e147.member.member.y), 0u, (_e147.member.member.y < 0f)), 4294967295u, (_e147.member.member.y > 4294967000f));
            if (_e110.x >= _e171) {
            } else {
                if (_e110.y >= _e179) {
                } else {
                    let _e185 = ((_e110.y * _e171) + _e110.x);
                    let _e188 = mips.member[_e185];
                    let _e189 = bitcast<i32>(_e110.x);
                    let _e190 = (_e189 + -1i);
                    let _e192 = select(0i, _e190, (0i < _e190));
                    let _e194 = (bitcast<i32>(_e171) - 1i);
                    let _e198 = bitcast<i32>(_e110.y);
                    let _e200 = select(0i, _e198, (0i < _e198));
                    let _e202 = (bitcast<i32>(_e179) - 1i);
                    let _e206 = (bitcast<u32>(select(_e200, _e202, (_e202 < _e200))) * _e171);
                    let _e210 = mips.member[(_e206 + bitcast<u32>(select(_e192, _e194, (_e194 < _e192))))];
                    let _e211 = (_e189 + 1i);
                    let _e213 = select(0i, _e211, (0i < _e211));
                    let _e220 = mips.member[(_e206 + bitcast<u32>(select(_e213, _e194, (_e194 < _e213))))];
                    let _e222 = select(0i, _e189, (0i < _e189));
                    let _e225 = bitcast<u32>(select(_e222, _e194, (_e194 < _e222)));
                    let _e226 = (_e198 + -1i);
                    let _e228 = select(0i, _e226, (0i < _e226));
                    let _e236 = mips.member[((bitcast<u32>(select(_e228, _e202, (_e202 < _e228))) * _e171) + _e225)];
                    let _e237 = (_e198 + 1i);
                    let _e239 = select(0i, _e237, (0i < _e237));
                    let _e247 = mips.member[((bitcast<u32>(select(_e239, _e202, (_e202 < _e239))) * _e171) + _e225)];
                    let _e248 = (_e210 - _e188);
                    let _e249 = (_e220 - _e188);
                    let _e250 = (_e236 - _e188);
                    let _e251 = (_e247 - _e188);
                    let _e253 = ((_e249 - _e248) * 0.5f);
                    let _e255 = ((_e251 - _e250) * 0.5f);
                    let _e256 = (_e188 * 0.011f);
                    let _e258 = abs(_e248);
                    let _e259 = abs((_e248 + _e253));
                    let _e265 = (1.25f - (select(_e259, _e258, ((_e258 < _e259) || (_e259 != _e259))) / _e256));
                    let _e267 = select(0f, _e265, (_e265 > 0f));
                    let _e269 = select(1f, _e267, (_e267 < 1f));
                    let _e271 = abs(_e249);
                    let _e272 = abs((_e249 - _e253));
                    let _e278 = (1.25f - (select(_e272, _e271, ((_e271 < _e272) || (_e272 != _e272))) / _e256));
                    let _e280 = select(0f, _e278, (_e278 > 0f));
                    let _e282 = select(1f, _e280, (_e280 < 1f));
                    let _e284 = abs(_e250);
                    let _e285 = abs((_e250 + _e255));
                    let _e291 = (1.25f - (select(_e285, _e284, ((_e284 < _e285) || (_e285 != _e285))) / _e256));
                    let _e293 = select(0f, _e291, (_e291 > 0f));
                    let _e295 = select(1f, _e293, (_e293 < 1f));
                    let _e297 = abs(_e251);
                    let _e298 = abs((_e251 - _e255));
                    let _e304 = (1.25f - (select(_e298, _e297, ((_e297 < _e298) || (_e298 != _e298))) / _e256));
                    let _e306 = select(0f, _e304, (_e304 > 0f));
                    let _e308 = select(1f, _e306, (_e306 < 1f));
                    let _e310 = select(0f, _e269, (_e269 > 0f));
                    let _e314 = round((select(1f, _e310, (_e310 < 1f)) * 2.9f));
                    let _e316 = select(0f, _e314, (_e314 > 0f));
                    let _e325 = select(0f, _e282, (_e282 > 0f));
                    let _e329 = round((select(1f, _e325, (_e325 < 1f)) * 2.9f));
                    let _e331 = select(0f, _e329, (_e329 > 0f));
                    let _e341 = select(0f, _e295, (_e295 > 0f));
                    let _e345 = round((select(1f, _e341, (_e341 < 1f)) * 2.9f));
                    let _e347 = select(0f, _e345, (_e345 > 0f));
                    let _e357 = select(0f, _e308, (_e308 > 0f));
                    let _e361 = round((select(1f, _e357, (_e357 < 1f)) * 2.9f));
                    let _e363 = select(0f, _e361, (_e361 > 0f));
                    let _e373 = ((f32(_e189) + 0.5f) / _e147.member.member.x);
                    let _e376 = ((f32(_e198) + 0.5f) / _e147.member.member.y);
                    let _e377 = (_e188 * 0.99999f);
                    let _e384 = ((((_e373 * 2f) - 1f) * _e147.member.member_1.x) * _e377);
                    let _e391 = ((((_e376 * -2f) + 1f) * _e147.member.member_1.y) * _e377);
                    let _e392 = -(_e384);
                    let _e393 = -(_e391);
                    let _e394 = (_e188 * -0.99999f);
                    let _e401 = (1f / sqrt((((_e392 * _e392) + (_e393 * _e393)) + (_e394 * _e394))));
                    let _e402 = (_e392 * _e401);
                    let _e403 = (_e393 * _e401);
                    let _e404 = (_e394 * _e401);
                    let _e407 = normals.member[_e185];
                    let _e410 = f32(bitcast<i32>((_e407 & 255u)));
                    let _e414 = (select(_e410, (_e410 - 256f), (_e410 >= 128f)) * 0.007874016f);
                    let _e417 = select(-1f, _e414, ((_e414 > -1f) || false));
                    let _e422 = f32(bitcast<i32>(((_e407 >> bitcast<u32>(8u)) & 255u)));
                    let _e426 = (select(_e422, (_e422 - 256f), (_e422 >= 128f)) * 0.007874016f);
                    let _e429 = select(-1f, _e426, ((_e426 > -1f) || false));
                    let _e431 = (1f - abs(_e417));
                    let _e432 = abs(_e429);
                    let _e433 = (_e431 - _e432);
                    let _e434 = (_e433 < 0f);
                    let _e442 = select(_e417, ((1f - _e432) * select(1f, -1f, (_e417 < 0f))), _e434);
                    let _e443 = select(_e429, (_e431 * select(1f, -1f, (_e429 < 0f))), _e434);
                    let _e450 = (1f / sqrt((((_e442 * _e442) + (_e443 * _e443)) + (_e433 * _e433))));
                    let _e451 = (_e442 * _e450);
                    let _e452 = (_e443 * _e450);
                    let _e453 = (_e433 * _e450);
                    let _e454 = -(_e453);
                    let _e460 = ((((_e451 * _e402) + (_e452 * _e403)) + (_e454 * _e404)) < 0f);
                    let _e463 = select(_e451, -(_e451), _e460);
                    let _e464 = select(_e452, -(_e452), _e460);
                    let _e465 = select(_e454, _e453, _e460);
                    let _e472 = ((_e147.member_1 * _e147.member_2) / (((_e188 * 1.99998f) * _e147.member.member_1.x) / _e147.member.member.x));
                    let _e475 = (_e110.x & 63u);
                    let _e476 = (_e110.y & 63u);
                    let _e479 = select(0u, 1u, ((_e475 & 32u) != 0u));
                    let _e482 = select(0u, 1u, ((_e476 & 32u) != 0u));
                    let _e486 = (_e482 == 0u);
                    let _e488 = (_e486 && (_e479 == 1u));
                    let _e491 = select(_e475, (63u - _e475), _e488);
                    let _e492 = select(_e476, (63u - _e476), _e488);
                    let _e493 = select(_e491, _e492, _e486);
                    let _e494 = select(_e492, _e491, _e486);
                    let _e497 = select(0u, 1u, ((_e493 & 16u) != 0u));
                    let _e500 = select(0u, 1u, ((_e494 & 16u) != 0u));
                    let _e505 = (_e500 == 0u);
                    let _e507 = (_e505 && (_e497 == 1u));
                    let _e510 = select(_e493, (63u - _e493), _e507);
                    let _e511 = select(_e494, (63u - _e494), _e507);
                    let _e512 = select(_e510, _e511, _e505);
                    let _e513 = select(_e511, _e510, _e505);
                    let _e516 = select(0u, 1u, ((_e512 & 8u) != 0u));
                    let _e519 = select(0u, 1u, ((_e513 & 8u) != 0u));
                    let _e524 = (_e519 == 0u);
                    let _e526 = (_e524 && (_e516 == 1u));
                    let _e529 = select(_e512, (63u - _e512), _e526);
                    let _e530 = select(_e513, (63u - _e513), _e526);
                    let _e531 = select(_e529, _e530, _e524);
                    let _e532 = select(_e530, _e529, _e524);
                    let _e535 = select(0u, 1u, ((_e531 & 4u) != 0u));
                    let _e538 = select(0u, 1u, ((_e532 & 4u) != 0u));
                    let _e543 = (_e538 == 0u);
                    let _e545 = (_e543 && (_e535 == 1u));
                    let _e548 = select(_e531, (63u - _e531), _e545);
                    let _e549 = select(_e532, (63u - _e532), _e545);
                    let _e550 = select(_e548, _e549, _e543);
                    let _e551 = select(_e549, _e548, _e543);
                    let _e554 = select(0u, 1u, ((_e550 & 2u) != 0u));
                    let _e557 = select(0u, 1u, ((_e551 & 2u) != 0u));
                    let _e562 = (_e557 == 0u);
                    let _e564 = (_e562 && (_e554 == 1u));
                    let _e567 = select(_e550, (63u - _e550), _e564);
                    let _e568 = select(_e551, (63u - _e551), _e564);
                    let _e584 = f32(bitcast<i32>((((((((1024u * ((3u * _e479) ^ _e482)) + (256u * ((3u * _e497) ^ _e500))) + (64u * ((3u * _e516) ^ _e519))) + (16u * ((3u * _e535) ^ _e538))) + (4u * ((3u * _e554) ^ _e557))) + ((3u * select(0u, 1u, ((select(_e567, _e568, _e562) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e568, _e567, _e562) & 1u) != 0u)))) + (288u * (_e147.member_11 % 64u)))));
                    let _e586 = (0.5f + (_e584 * 0.7548777f));
                    let _e590 = (0.5f + (_e584 * 0.5698403f));
                    let _e597 = select(false, (_e188 < _e147.member.member_3), (_e188 > 0f));
                    if _e597 {
                        let _e600 = select(1u, _e147.member_8, (1u < _e147.member_8));
                        phi_3199_ = false;
                        phi_995_ = 0u;
                        phi_998_ = 0f;
                        phi_1000_ = 0f;
                        loop {
                            let _e602 = phi_3199_;
                            let _e604 = phi_995_;
                            let _e606 = phi_998_;
                            let _e608 = phi_1000_;
                            local_6 = _e606;
                            local_7 = _e608;
                            local_8 = _e606;
                            let _e609 = (_e604 < _e600);
                            if _e609 {
                                let _e616 = ((((_e586 - floor(_e586)) + f32(bitcast<i32>(_e604))) * 3.1415927f) / f32(bitcast<i32>(_e600)));
                                let _e617 = sin(_e616);
                                let _e618 = cos(_e616);
                                let _e624 = ((_e618 * _e402) + (_e617 * _e403));
                                let _e628 = (_e618 - (_e402 * _e624));
                                let _e629 = (_e617 - (_e403 * _e624));
                                let _e630 = -((_e404 * _e624));
                                let _e633 = ((_e629 * _e404) - (_e403 * _e630));
                                let _e636 = ((_e630 * _e402) - (_e404 * _e628));
                                let _e639 = ((_e628 * _e403) - (_e402 * _e629));
                                let _e646 = (1f / sqrt((((_e633 * _e633) + (_e636 * _e636)) + (_e639 * _e639))));
                                let _e647 = (_e633 * _e646);
                                let _e648 = (_e636 * _e646);
                                let _e649 = (_e639 * _e646);
                                let _e654 = (((_e463 * _e647) + (_e464 * _e648)) + (_e465 * _e649));
                                let _e658 = (_e463 - (_e647 * _e654));
                                let _e659 = (_e464 - (_e648 * _e654));
                                let _e660 = (_e465 - (_e649 * _e654));
                                let _e666 = sqrt((((_e658 * _e658) + (_e659 * _e659)) + (_e660 * _e660)));
                                let _e671 = (((_e628 * _e658) + (_e629 * _e659)) + (_e630 * _e660));
                                let _e681 = ((((_e658 * _e402) + (_e659 * _e403)) + (_e660 * _e404)) / _e666);
                                let _e683 = select(0f, _e681, (_e681 > 0f));
                                let _e685 = select(1f, _e683, (_e683 < 1f));
                                let _e686 = abs(_e685);
                                let _e704 = (((((((((((((((_e686 * -0.0012624911f) + 0.00667009f) * _e686) - 0.017088126f) * _e686) + 0.03089188f) * _e686) - 0.050174303f) * _e686) + 0.08897899f) * _e686) - 0.2145988f) * _e686) + 1.5707963f) * sqrt((1f - _e686)));
                                let _e707 = (select(select(0f, -1f, (_e671 < 0f)), 1f, (_e671 > 0f)) * select((3.1415927f - _e704), _e704, (_e685 >= 0f)));
                                let _e710 = select(1u, _e147.member_9, (1u < _e147.member_9));
                                phi_1193_ = 0u;
                                phi_1196_ = 0u;
                                loop {
                                    let _e712 = phi_1193_;
                                    let _e714 = phi_1196_;
                                    local_1 = _e714;
                                    local_2 = _e714;
                                    local_4 = _e714;
                                    let _e715 = (_e712 < _e710);
                                    if _e715 {
                                        let _e721 = ((_e590 - floor(_e590)) + (f32(bitcast<i32>((_e604 + (_e712 * _e710)))) * 0.618034f));
                                        let _e730 = (((_e721 - floor(_e721)) + f32(bitcast<i32>(_e712))) * (1f / f32(bitcast<i32>(_e710))));
                                        if (_e147.member_4 == 2f) {
                                            phi_1249_ = (_e730 * _e730);
                                        } else {
                                            phi_1249_ = pow(_e730, _e147.member_4);
                                        }
                                        let _e736 = phi_1249_;
                                        let _e737 = (_e736 + (1.3f / _e472));
                                        let _e738 = ((_e618 * _e472) * _e737);
                                        let _e739 = ((-(_e617) * _e472) * _e737);
                                        let _e746 = (log2(sqrt(((_e738 * _e738) + (_e739 * _e739)))) - _e147.member_7);
                                        let _e748 = select(0f, _e746, (_e746 > 0f));
                                        let _e753 = (-1f - floor((-0.5f - select(5f, _e748, (_e748 < 5f)))));
                                        let _e756 = (round(_e738) * (1f / _e147.member.member.x));
                                        let _e759 = (round(_e739) * (1f / _e147.member.member.y));
                                        let _e760 = (_e373 + _e756);
                                        let _e761 = (_e376 + _e759);
                                        let _e762 = (_e373 - _e756);
                                        let _e763 = (_e376 - _e759);
                                        let _e765 = select(0f, _e753, (_e753 > 0f));
                                        let _e772 = ((bitcast<u32>((floor(select(4f, _e765, (_e765 < 4f))) + 8388608f)) - 1258291200u) & 31u);
                                        let _e774 = (_e171 >> bitcast<u32>(_e772));
                                        let _e776 = select(1u, _e774, (1u < _e774));
                                        let _e778 = (_e179 >> bitcast<u32>(_e772));
                                        let _e780 = select(1u, _e778, (1u < _e778));
                                        let _e785 = (select(1u, _e171, (1u < _e171)) * select(1u, _e179, (1u < _e179)));
                                        let _e789 = (_e171 >> bitcast<u32>(1u));
                                        let _e793 = (_e179 >> bitcast<u32>(1u));
                                        let _e797 = (_e785 + (select(1u, _e789, (1u < _e789)) * select(1u, _e793, (1u < _e793))));
                                        let _e801 = (_e171 >> bitcast<u32>(2u));
                                        let _e805 = (_e179 >> bitcast<u32>(2u));
                                        let _e809 = (_e797 + (select(1u, _e801, (1u < _e801)) * select(1u, _e805, (1u < _e805))));
                                        let _e813 = (_e171 >> bitcast<u32>(3u));
                                        let _e817 = (_e179 >> bitcast<u32>(3u));
                                        let _e823 = select(select(select(select(0u, _e785, (_e753 >= 1f)), _e797, (_e753 >= 2f)), _e809, (_e753 >= 3f)), (_e809 + (select(1u, _e813, (1u < _e813)) * select(1u, _e817, (1u < _e817)))), (_e753 >= 4f));
                                        let _e825 = f32(bitcast<i32>(_e776));
                                        let _e826 = (_e760 * _e825);
                                        let _e829 = f32(bitcast<i32>((_e776 - 1u)));
                                        let _e831 = select(0f, _e826, (_e826 > 0f));
                                        let _e839 = f32(bitcast<i32>(_e780));
                                        let _e840 = (_e761 * _e839);
                                        let _e843 = f32(bitcast<i32>((_e780 - 1u)));
                                        let _e845 = select(0f, _e840, (_e840 > 0f));
                                        let _e857 = mips.member[((_e823 + ((bitcast<u32>((floor(select(_e843, _e845, (_e845 < _e843))) + 8388608f)) - 1258291200u) * _e776)) + (bitcast<u32>((floor(select(_e829, _e831, (_e831 < _e829))) + 8388608f)) - 1258291200u))];
                                        let _e866 = (_e762 * _e825);
                                        let _e868 = select(0f, _e866, (_e866 > 0f));
                                        let _e875 = (_e763 * _e839);
                                        let _e877 = select(0f, _e875, (_e875 > 0f));
                                        let _e889 = mips.member[((_e823 + ((bitcast<u32>((floor(select(_e843, _e877, (_e877 < _e843))) + 8388608f)) - 1258291200u) * _e776)) + (bitcast<u32>((floor(select(_e829, _e868, (_e868 < _e829))) + 8388608f)) - 1258291200u))];
                                        let _e898 = (((((_e760 * 2f) - 1f) * _e147.member.member_1.x) * _e857) - _e384);
                                        let _e899 = (((((_e761 * -2f) + 1f) * _e147.member.member_1.y) * _e857) - _e391);
                                        let _e900 = (_e857 - _e377);
                                        let _e901 = (_e163 > 0f);
                                        if _e901 {
                                            phi_1662_ = (sqrt((((_e898 * _e898) + (_e899 * _e899)) + (_e900 * _e900))) > _e163);
                                        } else {
                                            phi_1662_ = false;
                                        }
                                        let _e910 = phi_1662_;
                                        if !(_e910) {
                                            let _e916 = (((_e898 * _e402) + (_e899 * _e403)) + (_e900 * _e404));
                                            let _e920 = (_e898 - (_e402 * _e916));
                                            let _e921 = (_e899 - (_e403 * _e916));
                                            let _e922 = (_e900 - (_e404 * _e916));
                                            let _e925 = ((_e921 * _e404) - (_e403 * _e922));
                                            let _e928 = ((_e922 * _e402) - (_e404 * _e920));
                                            let _e931 = ((_e920 * _e403) - (_e402 * _e921));
                                            let _e942 = ((((_e463 * _e925) + (_e464 * _e928)) + (_e465 * _e931)) / (((_e925 * _e925) + (_e928 * _e928)) + (_e931 * _e931)));
                                            let _e946 = (_e463 - (_e925 * _e942));
                                            let _e947 = (_e464 - (_e928 * _e942));
                                            let _e948 = (_e465 - (_e931 * _e942));
                                            let _e954 = sqrt((((_e946 * _e946) + (_e947 * _e947)) + (_e948 * _e948)));
                                            let _e961 = ((((_e946 * _e402) + (_e947 * _e403)) + (_e948 * _e404)) * (1f / _e954));
                                            let _e963 = select(0f, _e961, (_e961 > 0f));
                                            let _e965 = select(1f, _e963, (_e963 < 1f));
                                            let _e966 = abs(_e965);
                                            let _e983 = (((((((((((((((_e966 * -0.0012624911f) + 0.00667009f) * _e966) - 0.017088126f) * _e966) + 0.03089188f) * _e966) - 0.050174303f) * _e966) + 0.08897899f) * _e966) - 0.2145988f) * _e966) + 1.5707963f) * sqrt((1f - _e966)));
                                            let _e986 = select((3.1415927f - _e983), _e983, (_e965 >= 0f));
                                            let _e994 = select(_e986, -(_e986), ((((_e920 * _e946) + (_e921 * _e947)) + (_e922 * _e948)) < 0f));
                                            let _e995 = (0.02f / _e954);
                                            let _e998 = select(0.19634955f, _e995, ((_e995 < 0.19634955f) || false));
                                            let _e1002 = (_e898 - (_e402 * _e160));
                                            let _e1003 = (_e899 - (_e403 * _e160));
                                            let _e1004 = (_e900 - (_e404 * _e160));
                                            let _e1011 = (_e916 / sqrt((((_e898 * _e898) + (_e899 * _e899)) + (_e900 * _e900))));
                                            let _e1013 = select(-1f, _e1011, (_e1011 > -1f));
                                            let _e1015 = select(1f, _e1013, (_e1013 < 1f));
                                            let _e1016 = abs(_e1015);
                                            let _e1033 = (((((((((((((((_e1016 * -0.0012624911f) + 0.00667009f) * _e1016) - 0.017088126f) * _e1016) + 0.03089188f) * _e1016) - 0.050174303f) * _e1016) + 0.08897899f) * _e1016) - 0.2145988f) * _e1016) + 1.5707963f) * sqrt((1f - _e1016)));
                                            let _e1040 = ((((select((3.1415927f - _e1033), _e1033, (_e1015 >= 0f)) + _e998) - _e994) + 1.5707964f) * 0.31830987f);
                                            let _e1042 = select(0f, _e1040, (_e1040 > 0f));
                                            let _e1044 = select(1f, _e1042, (_e1042 < 1f));
                                            let _e1056 = ((((_e1002 * _e402) + (_e1003 * _e403)) + (_e1004 * _e404)) / sqrt((((_e1002 * _e1002) + (_e1003 * _e1003)) + (_e1004 * _e1004))));
                                            let _e1058 = select(-1f, _e1056, (_e1056 > -1f));
                                            let _e1060 = select(1f, _e1058, (_e1058 < 1f));
                                            let _e1061 = abs(_e1060);
                                            let _e1078 = (((((((((((((((_e1061 * -0.0012624911f) + 0.00667009f) * _e1061) - 0.017088126f) * _e1061) + 0.03089188f) * _e1061) - 0.050174303f) * _e1061) + 0.08897899f) * _e1061) - 0.2145988f) * _e1061) + 1.5707963f) * sqrt((1f - _e1061)));
                                            let _e1085 = ((((select((3.1415927f - _e1078), _e1078, (_e1060 >= 0f)) + _e998) - _e994) + 1.5707964f) * 0.31830987f);
                                            let _e1087 = select(0f, _e1085, (_e1085 > 0f));
                                            let _e1089 = select(1f, _e1087, (_e1087 < 1f));
                                            let _e1091 = (_e1089 != _e1089);
                                            let _e1093 = select(_e1089, _e1044, ((_e1044 < _e1089) || _e1091));
                                            let _e1096 = select(_e1089, _e1044, ((_e1044 > _e1089) || _e1091));
                                            let _e1098 = floor((_e1093 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1106 = -(floor((_e1096 * -32f)));
                                                let _e1111 = (select(32f, _e1106, ((_e1106 < 32f) || false)) - _e1098);
                                                phi_1994_ = select(select(0f, _e1111, ((_e1111 > 0f) || false)), 0f, (_e1096 <= _e1093));
                                            } else {
                                                phi_1994_ = -(floor(((_e1096 - _e1093) * -32f)));
                                            }
                                            let _e1117 = phi_1994_;
                                            let _e1119 = select(0f, _e1098, (_e1098 > 0f));
                                            let _e1125 = (bitcast<u32>((floor(select(32f, _e1119, (_e1119 < 32f))) + 8388608f)) - 1258291200u);
                                            let _e1127 = select(0f, _e1117, (_e1117 > 0f));
                                            let _e1133 = (bitcast<u32>((floor(select(32f, _e1127, (_e1127 < 32f))) + 8388608f)) - 1258291200u);
                                            if (_e1125 >= 32u) {
                                                phi_2048_ = u32();
                                                phi_2049_ = true;
                                            } else {
                                                let _e1135 = (_e1133 == 0u);
                                                if _e1135 {
                                                    phi_2047_ = u32();
                                                } else {
                                                    if (_e1133 >= 32u) {
                                                        phi_2044_ = 4294967295u;
                                                    } else {
                                                        phi_2044_ = ((1u << bitcast<u32>((_e1133 & 31u))) - 1u);
                                                    }
                                                    let _e1142 = phi_2044_;
                                                    phi_2047_ = (_e1142 << bitcast<u32>((_e1125 & 31u)));
                                                }
                                                let _e1147 = phi_2047_;
                                                phi_2048_ = _e1147;
                                                phi_2049_ = _e1135;
                                            }
                                            let _e1149 = phi_2048_;
                                            let _e1151 = phi_2049_;
                                            phi_2068_ = select(select(select(_e1149, 0u, _e1151), 0u, ((((_e920 * _e920) + (_e921 * _e921)) + (_e922 * _e922)) <= 0f)), 0u, _e910);
                                        } else {
                                            phi_2068_ = 0u;
                                        }
                                        let _e1162 = phi_2068_;
                                        let _e1164 = (((((_e762 * 2f) - 1f) * _e147.member.member_1.x) * _e889) - _e384);
                                        let _e1165 = (((((_e763 * -2f) + 1f) * _e147.member.member_1.y) * _e889) - _e391);
                                        let _e1166 = (_e889 - _e377);
                                        if _e901 {
                                            phi_2088_ = (sqrt((((_e1164 * _e1164) + (_e1165 * _e1165)) + (_e1166 * _e1166))) > _e163);
                                        } else {
                                            phi_2088_ = false;
                                        }
                                        let _e1175 = phi_2088_;
                                        if !(_e1175) {
                                            let _e1181 = (((_e1164 * _e402) + (_e1165 * _e403)) + (_e1166 * _e404));
                                            let _e1185 = (_e1164 - (_e402 * _e1181));
                                            let _e1186 = (_e1165 - (_e403 * _e1181));
                                            let _e1187 = (_e1166 - (_e404 * _e1181));
                                            let _e1190 = ((_e1186 * _e404) - (_e403 * _e1187));
                                            let _e1193 = ((_e1187 * _e402) - (_e404 * _e1185));
                                            let _e1196 = ((_e1185 * _e403) - (_e402 * _e1186));
                                            let _e1207 = ((((_e463 * _e1190) + (_e464 * _e1193)) + (_e465 * _e1196)) / (((_e1190 * _e1190) + (_e1193 * _e1193)) + (_e1196 * _e1196)));
                                            let _e1211 = (_e463 - (_e1190 * _e1207));
                                            let _e1212 = (_e464 - (_e1193 * _e1207));
                                            let _e1213 = (_e465 - (_e1196 * _e1207));
                                            let _e1219 = sqrt((((_e1211 * _e1211) + (_e1212 * _e1212)) + (_e1213 * _e1213)));
                                            let _e1226 = ((((_e1211 * _e402) + (_e1212 * _e403)) + (_e1213 * _e404)) * (1f / _e1219));
                                            let _e1228 = select(0f, _e1226, (_e1226 > 0f));
                                            let _e1230 = select(1f, _e1228, (_e1228 < 1f));
                                            let _e1231 = abs(_e1230);
                                            let _e1248 = (((((((((((((((_e1231 * -0.0012624911f) + 0.00667009f) * _e1231) - 0.017088126f) * _e1231) + 0.03089188f) * _e1231) - 0.050174303f) * _e1231) + 0.08897899f) * _e1231) - 0.2145988f) * _e1231) + 1.5707963f) * sqrt((1f - _e1231)));
                                            let _e1251 = select((3.1415927f - _e1248), _e1248, (_e1230 >= 0f));
                                            let _e1259 = select(_e1251, -(_e1251), ((((_e1185 * _e1211) + (_e1186 * _e1212)) + (_e1187 * _e1213)) < 0f));
                                            let _e1260 = (0.02f / _e1219);
                                            let _e1263 = select(0.19634955f, _e1260, ((_e1260 < 0.19634955f) || false));
                                            let _e1267 = (_e1164 - (_e402 * _e160));
                                            let _e1268 = (_e1165 - (_e403 * _e160));
                                            let _e1269 = (_e1166 - (_e404 * _e160));
                                            let _e1276 = (_e1181 / sqrt((((_e1164 * _e1164) + (_e1165 * _e1165)) + (_e1166 * _e1166))));
                                            let _e1278 = select(-1f, _e1276, (_e1276 > -1f));
                                            let _e1280 = select(1f, _e1278, (_e1278 < 1f));
                                            let _e1281 = abs(_e1280);
                                            let _e1298 = (((((((((((((((_e1281 * -0.0012624911f) + 0.00667009f) * _e1281) - 0.017088126f) * _e1281) + 0.03089188f) * _e1281) - 0.050174303f) * _e1281) + 0.08897899f) * _e1281) - 0.2145988f) * _e1281) + 1.5707963f) * sqrt((1f - _e1281)));
                                            let _e1305 = ((((select((3.1415927f - _e1298), _e1298, (_e1280 >= 0f)) + _e1263) - _e1259) + 1.5707964f) * 0.31830987f);
                                            let _e1307 = select(0f, _e1305, (_e1305 > 0f));
                                            let _e1321 = ((((_e1267 * _e402) + (_e1268 * _e403)) + (_e1269 * _e404)) / sqrt((((_e1267 * _e1267) + (_e1268 * _e1268)) + (_e1269 * _e1269))));
                                            let _e1323 = select(-1f, _e1321, (_e1321 > -1f));
                                            let _e1325 = select(1f, _e1323, (_e1323 < 1f));
                                            let _e1326 = abs(_e1325);
                                            let _e1343 = (((((((((((((((_e1326 * -0.0012624911f) + 0.00667009f) * _e1326) - 0.017088126f) * _e1326) + 0.03089188f) * _e1326) - 0.050174303f) * _e1326) + 0.08897899f) * _e1326) - 0.2145988f) * _e1326) + 1.5707963f) * sqrt((1f - _e1326)));
                                            let _e1350 = ((((select((3.1415927f - _e1343), _e1343, (_e1325 >= 0f)) + _e1263) - _e1259) + 1.5707964f) * 0.31830987f);
                                            let _e1352 = select(0f, _e1350, (_e1350 > 0f));
                                            let _e1355 = (1f - select(1f, _e1307, (_e1307 < 1f)));
                                            let _e1356 = (1f - select(1f, _e1352, (_e1352 < 1f)));
                                            let _e1358 = (_e1356 != _e1356);
                                            let _e1360 = select(_e1356, _e1355, ((_e1355 < _e1356) || _e1358));
                                            let _e1363 = select(_e1356, _e1355, ((_e1355 > _e1356) || _e1358));
                                            let _e1365 = floor((_e1360 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1373 = -(floor((_e1363 * -32f)));
                                                let _e1378 = (select(32f, _e1373, ((_e1373 < 32f) || false)) - _e1365);
                                                phi_2420_ = select(select(0f, _e1378, ((_e1378 > 0f) || false)), 0f, (_e1363 <= _e1360));
                                            } else {
                                                phi_2420_ = -(floor(((_e1363 - _e1360) * -32f)));
                                            }
                                            let _e1384 = phi_2420_;
                                            let _e1386 = select(0f, _e1365, (_e1365 > 0f));
                                            let _e1392 = (bitcast<u32>((floor(select(32f, _e1386, (_e1386 < 32f))) + 8388608f)) - 1258291200u);
                                            let _e1394 = select(0f, _e1384, (_e1384 > 0f));
                                            let _e1400 = (bitcast<u32>((floor(select(32f, _e1394, (_e1394 < 32f))) + 8388608f)) - 1258291200u);
                                            if (_e1392 >= 32u) {
                                                phi_2474_ = u32();
                                                phi_2475_ = true;
                                            } else {
                                                let _e1402 = (_e1400 == 0u);
                                                if _e1402 {
                                                    phi_2473_ = u32();
                                                } else {
                                                    if (_e1400 >= 32u) {
                                                        phi_2470_ = 4294967295u;
                                                    } else {
                                                        phi_2470_ = ((1u << bitcast<u32>((_e1400 & 31u))) - 1u);
                                                    }
                                                    let _e1409 = phi_2470_;
                                                    phi_2473_ = (_e1409 << bitcast<u32>((_e1392 & 31u)));
                                                }
                                                let _e1414 = phi_2473_;
                                                phi_2474_ = _e1414;
                                                phi_2475_ = _e1402;
                                            }
                                            let _e1416 = phi_2474_;
                                            let _e1418 = phi_2475_;
                                            phi_2494_ = select(select(select(_e1416, 0u, _e1418), 0u, ((((_e1185 * _e1185) + (_e1186 * _e1186)) + (_e1187 * _e1187)) <= 0f)), 0u, _e1175);
                                        } else {
                                            phi_2494_ = 0u;
                                        }
                                        let _e1429 = phi_2494_;
                                        phi_1194_ = (_e712 + 1u);
                                        phi_1197_ = ((_e714 | _e1162) | _e1429);
                                    } else {
                                        phi_1194_ = u32();
                                        phi_1197_ = u32();
                                    }
                                    let _e1433 = phi_1194_;
                                    let _e1435 = phi_1197_;
                                    continue;
                                    continuing {
                                        phi_1193_ = _e1433;
                                        phi_1196_ = _e1435;
                                        break if !(_e715);
                                    }
                                }
                                if (_e152 == 2u) {
                                    let _e1495 = (_e707 - 1.5707964f);
                                    let _e1496 = (_e1495 * 2f);
                                    let _e1497 = sin(_e707);
                                    let _e1502 = ((_e685 + (_e1496 * _e1497)) - cos((_e1496 - _e707)));
                                    phi_2523_ = 0u;
                                    phi_2526_ = select((_e1502 * 0.25f), (_e1502 * -0.25f), (_e1495 < 0f));
                                    phi_2528_ = 0f;
                                    loop {
                                        let _e1508 = phi_2523_;
                                        let _e1510 = phi_2526_;
                                        let _e1512 = phi_2528_;
                                        local_5 = _e1512;
                                        let _e1513 = (_e1508 < 32u);
                                        if _e1513 {
                                            let _e1514 = (_e1508 + 1u);
                                            let _e1518 = (_e1495 + (f32(bitcast<i32>(_e1514)) * 0.09817477f));
                                            let _e1519 = (_e1518 * 2f);
                                            let _e1524 = ((_e685 + (_e1519 * _e1497)) - cos((_e1519 - _e707)));
                                            let _e1528 = select((_e1524 * 0.25f), (_e1524 * -0.25f), (_e1518 < 0f));
                                            let _e1531 = local_4;
                                            phi_2524_ = _e1514;
                                            phi_2527_ = _e1528;
                                            phi_2529_ = select(_e1512, (_e1512 + (_e1528 - _e1510)), (((_e1531 >> bitcast<u32>((_e1508 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2524_ = u32();
                                            phi_2527_ = f32();
                                            phi_2529_ = f32();
                                        }
                                        let _e1540 = phi_2524_;
                                        let _e1542 = phi_2527_;
                                        let _e1544 = phi_2529_;
                                        continue;
                                        continuing {
                                            phi_2523_ = _e1540;
                                            phi_2526_ = _e1542;
                                            phi_2528_ = _e1544;
                                            break if !(_e1513);
                                        }
                                    }
                                    let _e1547 = local_5;
                                    phi_3286_ = _e602;
                                    phi_2630_ = (_e606 + 1f);
                                    phi_2631_ = (_e608 + ((_e666 + ((1f - _e666) * 0.05f)) * _e1547));
                                } else {
                                    if (_e152 == 1u) {
                                        phi_2575_ = 0u;
                                        phi_2578_ = 0f;
                                        loop {
                                            let _e1450 = phi_2575_;
                                            let _e1452 = phi_2578_;
                                            local_3 = _e1452;
                                            let _e1453 = (_e1450 < 4u);
                                            if _e1453 {
                                                local = array<type_26, 4>(type_26(4026531855u, 0.0095061f), type_26(251658480u, 0.0270951f), type_26(15732480u, 0.0405571f), type_26(1044480u, 0.0478421f));
                                                if _e1453 {
                                                } else {
                                                    phi_3078_ = true;
                                                    break;
                                                }
                                                let _e1456 = local[_e1450].member;
                                                let _e1459 = local[_e1450].member_1;
                                                let _e1461 = local_2;
                                                phi_2576_ = (_e1450 + 1u);
                                                phi_2579_ = (_e1452 + (f32(bitcast<i32>(countOneBits((_e1461 & _e1456)))) * _e1459));
                                            } else {
                                                phi_2576_ = u32();
                                                phi_2579_ = f32();
                                            }
                                            let _e1470 = phi_2576_;
                                            let _e1472 = phi_2579_;
                                            continue;
                                            continuing {
                                                phi_2575_ = _e1470;
                                                phi_2578_ = _e1472;
                                                phi_3078_ = _e602;
                                                break if !(_e1453);
                                            }
                                        }
                                        let _e1475 = phi_3078_;
                                        phi_3284_ = _e1475;
                                        if _e1475 {
                                            break;
                                        }
                                        let _e1477 = local_3;
                                        let _e1478 = (1f - _e1477);
                                        let _e1480 = select(0f, _e1478, (_e1478 > 0f));
                                        phi_3292_ = _e1475;
                                        phi_2628_ = (_e606 + _e666);
                                        phi_2629_ = (_e608 + (_e666 * select(1f, _e1480, (_e1480 < 1f))));
                                    } else {
                                        let _e1440 = local_1;
                                        phi_3292_ = _e602;
                                        phi_2628_ = (_e606 + 1f);
                                        phi_2629_ = (_e608 + ((f32(bitcast<i32>(countOneBits((_e1440 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e1487 = phi_3292_;
                                    let _e1489 = phi_2628_;
                                    let _e1491 = phi_2629_;
                                    phi_3286_ = _e1487;
                                    phi_2630_ = _e1489;
                                    phi_2631_ = _e1491;
                                }
                                let _e1552 = phi_3286_;
                                let _e1554 = phi_2630_;
                                let _e1556 = phi_2631_;
                                phi_3285_ = _e1552;
                                phi_996_ = (_e604 + 1u);
                                phi_999_ = _e1554;
                                phi_1001_ = _e1556;
                            } else {
                                phi_3285_ = _e602;
                                phi_996_ = u32();
                                phi_999_ = f32();
                                phi_1001_ = f32();
                            }
                            let _e1559 = phi_3285_;
                            let _e1561 = phi_996_;
                            let _e1563 = phi_999_;
                            let _e1565 = phi_1001_;
                            continue;
                            continuing {
                                phi_3199_ = _e1559;
                                phi_995_ = _e1561;
                                phi_998_ = _e1563;
                                phi_1000_ = _e1565;
                                phi_3284_ = _e1559;
                                break if !(_e609);
                            }
                        }
                        let _e1568 = phi_3284_;
                        if _e1568 {
                            break;
                        }
                        let _e1570 = local_6;
                        let _e1573 = local_7;
                        let _e1575 = local_8;
                        phi_2639_ = select(1f, (_e1573 / _e1575), (_e1570 > 0f));
                    } else {
                        phi_2639_ = 1f;
                    }
                    let _e1579 = phi_2639_;
                    if _e597 {
                        let _e1585 = pow(_e1579, _e147.member_6);
                        if (_e1585 != _e1585) {
                            phi_3060_ = true;
                        } else {
                            phi_3060_ = (0.03f >= _e1585);
                        }
                        let _e1589 = phi_3060_;
                        let _e1591 = (select(_e1585, 0.03f, _e1589) * 0.6666667f);
                        let _e1593 = select(0f, _e1591, (_e1591 > 0f));
                        phi_2680_ = (bitcast<u32>((floor(((select(1f, _e1593, (_e1593 < 1f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                    } else {
                        phi_2680_ = (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u);
                    }
                    let _e1603 = phi_2680_;
                    terms.member[_e185] = _e1603;
                    edges.member[_e185] = ((((64u * (bitcast<u32>((floor(select(3f, _e316, (_e316 < 3f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(3f, _e331, (_e331 < 3f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(3f, _e347, (_e347 < 3f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(3f, _e363, (_e363 < 3f))) + 8388608f)) - 1258291200u));
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
