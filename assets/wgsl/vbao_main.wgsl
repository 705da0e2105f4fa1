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
    var phi_226_: type_21;
    var phi_233_: u32;
    var phi_240_: u32;
    var phi_2674_: bool;
    var phi_888_: u32;
    var phi_891_: f32;
    var phi_893_: f32;
    var phi_1079_: u32;
    var phi_1082_: u32;
    var phi_1139_: f32;
    var phi_1140_: f32;
    var phi_1418_: bool;
    var phi_1734_: f32;
    var phi_1784_: u32;
    var phi_1787_: u32;
    var phi_1788_: u32;
    var phi_1789_: bool;
    var phi_1802_: u32;
    var phi_1822_: bool;
    var phi_2138_: f32;
    var phi_2188_: u32;
    var phi_2191_: u32;
    var phi_2192_: u32;
    var phi_2193_: bool;
    var phi_2206_: u32;
    var phi_1080_: u32;
    var phi_1083_: u32;
    var local_1: u32;
    var phi_2287_: u32;
    var phi_2290_: f32;
    var local_2: u32;
    var phi_2288_: u32;
    var phi_2291_: f32;
    var phi_2569_: bool;
    var local_3: f32;
    var phi_2748_: bool;
    var phi_2340_: f32;
    var phi_2341_: f32;
    var phi_2235_: u32;
    var phi_2238_: f32;
    var phi_2240_: f32;
    var local_4: u32;
    var phi_2236_: u32;
    var phi_2239_: f32;
    var phi_2241_: f32;
    var local_5: f32;
    var phi_2742_: bool;
    var phi_2342_: f32;
    var phi_2343_: f32;
    var phi_2741_: bool;
    var phi_889_: u32;
    var phi_892_: f32;
    var phi_894_: f32;
    var phi_2740_: bool;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var phi_2351_: f32;
    var phi_2363_: f32;
    var phi_2364_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e110 = id_1;
            let _e113 = (override_type == 0u);
            if _e113 {
                let _e145 = params.member.member_4;
                phi_226_ = _e145;
            } else {
                let _e123 = params.member.member_4.member;
                let _e127 = params.member.member_4.member_1;
                let _e131 = params.member.member_4.member_10;
                let _e135 = params.member.member_4.member_11;
                let _e139 = params.member.member_4.member_12;
                let _e143 = params.member.member_4.member_14;
                phi_226_ = type_21(_e123, _e127, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e131, _e135, _e139, override_type_9, _e143);
            }
            let _e147 = phi_226_;
            if _e113 {
                let _e150 = params.member.member_2;
                phi_233_ = _e150;
            } else {
                phi_233_ = override_type_10;
            }
            let _e152 = phi_233_;
            if _e113 {
                let _e155 = params.member.member_3;
                phi_240_ = _e155;
            } else {
                phi_240_ = override_type_11;
            }
            let _e157 = phi_240_;
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
                    let _e269 = select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f));
                    let _e271 = abs(_e249);
                    let _e272 = abs((_e249 - _e253));
                    let _e278 = (1.25f - (select(_e272, _e271, ((_e271 < _e272) || (_e272 != _e272))) / _e256));
                    let _e282 = select(0f, select(1f, _e278, (_e278 < 1f)), (_e278 > 0f));
                    let _e284 = abs(_e250);
                    let _e285 = abs((_e250 + _e255));
                    let _e291 = (1.25f - (select(_e285, _e284, ((_e284 < _e285) || (_e285 != _e285))) / _e256));
                    let _e295 = select(0f, select(1f, _e291, (_e291 < 1f)), (_e291 > 0f));
                    let _e297 = abs(_e251);
                    let _e298 = abs((_e251 - _e255));
                    let _e304 = (1.25f - (select(_e298, _e297, ((_e297 < _e298) || (_e298 != _e298))) / _e256));
                    let _e308 = select(0f, select(1f, _e304, (_e304 < 1f)), (_e304 > 0f));
                    let _e314 = round((select(0f, select(1f, _e269, (_e269 < 1f)), (_e269 > 0f)) * 2.9f));
                    let _e329 = round((select(0f, select(1f, _e282, (_e282 < 1f)), (_e282 > 0f)) * 2.9f));
                    let _e345 = round((select(0f, select(1f, _e295, (_e295 < 1f)), (_e295 > 0f)) * 2.9f));
                    let _e361 = round((select(0f, select(1f, _e308, (_e308 < 1f)), (_e308 > 0f)) * 2.9f));
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
                    let _e479 = ((_e475 >> bitcast<u32>(5u)) & 1u);
                    let _e482 = ((_e476 >> bitcast<u32>(5u)) & 1u);
                    let _e486 = (_e482 ^ 1u);
                    let _e488 = ((_e479 & _e486) * 63u);
                    let _e489 = (_e475 ^ _e488);
                    let _e490 = (_e476 ^ _e488);
                    let _e492 = ((_e489 ^ _e490) * _e486);
                    let _e493 = (_e489 ^ _e492);
                    let _e494 = (_e490 ^ _e492);
                    let _e497 = ((_e493 >> bitcast<u32>(4u)) & 1u);
                    let _e500 = ((_e494 >> bitcast<u32>(4u)) & 1u);
                    let _e505 = (_e500 ^ 1u);
                    let _e507 = ((_e497 & _e505) * 63u);
                    let _e508 = (_e493 ^ _e507);
                    let _e509 = (_e494 ^ _e507);
                    let _e511 = ((_e508 ^ _e509) * _e505);
                    let _e512 = (_e508 ^ _e511);
                    let _e513 = (_e509 ^ _e511);
                    let _e516 = ((_e512 >> bitcast<u32>(3u)) & 1u);
                    let _e519 = ((_e513 >> bitcast<u32>(3u)) & 1u);
                    let _e524 = (_e519 ^ 1u);
                    let _e526 = ((_e516 & _e524) * 63u);
                    let _e527 = (_e512 ^ _e526);
                    let _e528 = (_e513 ^ _e526);
                    let _e530 = ((_e527 ^ _e528) * _e524);
                    let _e531 = (_e527 ^ _e530);
                    let _e532 = (_e528 ^ _e530);
                    let _e535 = ((_e531 >> bitcast<u32>(2u)) & 1u);
                    let _e538 = ((_e532 >> bitcast<u32>(2u)) & 1u);
                    let _e543 = (_e538 ^ 1u);
                    let _e545 = ((_e535 & _e543) * 63u);
                    let _e546 = (_e531 ^ _e545);
                    let _e547 = (_e532 ^ _e545);
                    let _e549 = ((_e546 ^ _e547) * _e543);
                    let _e550 = (_e546 ^ _e549);
                    let _e551 = (_e547 ^ _e549);
                    let _e554 = ((_e550 >> bitcast<u32>(1u)) & 1u);
                    let _e557 = ((_e551 >> bitcast<u32>(1u)) & 1u);
                    let _e562 = (_e557 ^ 1u);
                    let _e564 = ((_e554 & _e562) * 63u);
                    let _e565 = (_e550 ^ _e564);
                    let _e566 = (_e551 ^ _e564);
                    let _e568 = ((_e565 ^ _e566) * _e562);
                    let _e580 = f32(bitcast<i32>((((((((((_e479 * 3u) ^ _e482) * 1024u) + (((_e497 * 3u) ^ _e500) * 256u)) + (((_e516 * 3u) ^ _e519) * 64u)) + (((_e535 * 3u) ^ _e538) * 16u)) + (((_e554 * 3u) ^ _e557) * 4u)) + ((((_e565 ^ _e568) & 1u) * 3u) ^ ((_e566 ^ _e568) & 1u))) + (288u * (_e147.member_11 % 64u)))));
                    let _e582 = ((_e580 * 0.7548777f) + 0.5f);
                    let _e586 = ((_e580 * 0.5698403f) + 0.5f);
                    let _e592 = exp2(((2f * _e147.member_7) + 1f));
                    let _e597 = select(false, (_e188 < _e147.member.member_3), (_e188 > 0f));
                    if _e597 {
                        let _e600 = select(1u, _e147.member_8, (1u < _e147.member_8));
                        phi_2674_ = false;
                        phi_888_ = 0u;
                        phi_891_ = 0f;
                        phi_893_ = 0f;
                        loop {
                            let _e602 = phi_2674_;
                            let _e604 = phi_888_;
                            let _e606 = phi_891_;
                            let _e608 = phi_893_;
                            local_6 = _e606;
                            local_7 = _e608;
                            local_8 = _e606;
                            let _e609 = (_e604 < _e600);
                            if _e609 {
                                let _e616 = ((((_e582 - floor(_e582)) + f32(bitcast<i32>(_e604))) * 3.1415927f) / f32(bitcast<i32>(_e600)));
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
                                let _e685 = select(0f, select(1f, _e681, (_e681 < 1f)), (_e681 > 0f));
                                let _e686 = abs(_e685);
                                let _e697 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e686, 0.00667009f), _e686, -0.017088126f), _e686, 0.03089188f), _e686, -0.050174303f), _e686, 0.08897899f), _e686, -0.2145988f), _e686, 1.5707963f) * sqrt((1f - _e686)));
                                let _e700 = (select(select(0f, -1f, (_e671 < 0f)), 1f, (_e671 > 0f)) * select((3.1415927f - _e697), _e697, (_e685 >= 0f)));
                                let _e703 = select(1u, _e147.member_9, (1u < _e147.member_9));
                                phi_1079_ = 0u;
                                phi_1082_ = 0u;
                                loop {
                                    let _e705 = phi_1079_;
                                    let _e707 = phi_1082_;
                                    local_1 = _e707;
                                    local_2 = _e707;
                                    local_4 = _e707;
                                    let _e708 = (_e705 < _e703);
                                    if _e708 {
                                        let _e714 = ((_e586 - floor(_e586)) + (f32(bitcast<i32>((_e604 + (_e705 * _e703)))) * 0.618034f));
                                        let _e723 = (((_e714 - floor(_e714)) + f32(bitcast<i32>(_e705))) * (1f / f32(bitcast<i32>(_e703))));
                                        if (_e147.member_4 == 2f) {
                                            phi_1140_ = (_e723 * _e723);
                                        } else {
                                            if (_e147.member_4 == 1f) {
                                                phi_1139_ = _e723;
                                            } else {
                                                phi_1139_ = pow(_e723, _e147.member_4);
                                            }
                                            let _e729 = phi_1139_;
                                            phi_1140_ = _e729;
                                        }
                                        let _e732 = phi_1140_;
                                        let _e733 = (_e732 + (1.3f / _e472));
                                        let _e734 = ((_e618 * _e472) * _e733);
                                        let _e735 = ((-(_e617) * _e472) * _e733);
                                        let _e738 = ((_e734 * _e734) + (_e735 * _e735));
                                        let _e743 = (select(1u, _e171, (1u < _e171)) * select(1u, _e179, (1u < _e179)));
                                        let _e744 = (_e738 > _e592);
                                        let _e748 = (_e171 >> bitcast<u32>(1u));
                                        let _e752 = (_e179 >> bitcast<u32>(1u));
                                        let _e756 = (_e743 + (select(1u, _e748, (1u < _e748)) * select(1u, _e752, (1u < _e752))));
                                        let _e758 = (_e738 > (_e592 * 4f));
                                        let _e762 = (_e171 >> bitcast<u32>(2u));
                                        let _e766 = (_e179 >> bitcast<u32>(2u));
                                        let _e770 = (_e756 + (select(1u, _e762, (1u < _e762)) * select(1u, _e766, (1u < _e766))));
                                        let _e772 = (_e738 > (_e592 * 16f));
                                        let _e776 = (_e171 >> bitcast<u32>(3u));
                                        let _e780 = (_e179 >> bitcast<u32>(3u));
                                        let _e786 = (_e738 > (_e592 * 64f));
                                        let _e788 = select(select(select(select(0u, _e743, _e744), _e756, _e758), _e770, _e772), (_e770 + (select(1u, _e776, (1u < _e776)) * select(1u, _e780, (1u < _e780)))), _e786);
                                        let _e789 = (select(select(select(select(0u, 1u, _e744), 2u, _e758), 3u, _e772), 4u, _e786) & 31u);
                                        let _e791 = (_e171 >> bitcast<u32>(_e789));
                                        let _e793 = select(1u, _e791, (1u < _e791));
                                        let _e795 = (_e179 >> bitcast<u32>(_e789));
                                        let _e797 = select(1u, _e795, (1u < _e795));
                                        let _e800 = (round(_e734) * (1f / _e147.member.member.x));
                                        let _e803 = (round(_e735) * (1f / _e147.member.member.y));
                                        let _e804 = (_e373 + _e800);
                                        let _e805 = (_e376 + _e803);
                                        let _e806 = (_e373 - _e800);
                                        let _e807 = (_e376 - _e803);
                                        let _e809 = f32(bitcast<i32>(_e793));
                                        let _e810 = (_e804 * _e809);
                                        let _e813 = f32(bitcast<i32>((_e793 - 1u)));
                                        let _e823 = f32(bitcast<i32>(_e797));
                                        let _e824 = (_e805 * _e823);
                                        let _e827 = f32(bitcast<i32>((_e797 - 1u)));
                                        let _e841 = mips.member[((_e788 + ((bitcast<u32>((floor(select(0f, select(_e827, _e824, (_e824 < _e827)), (_e824 > 0f))) + 8388608f)) - 1258291200u) * _e793)) + (bitcast<u32>((floor(select(0f, select(_e813, _e810, (_e810 < _e813)), (_e810 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e850 = (_e806 * _e809);
                                        let _e859 = (_e807 * _e823);
                                        let _e873 = mips.member[((_e788 + ((bitcast<u32>((floor(select(0f, select(_e827, _e859, (_e859 < _e827)), (_e859 > 0f))) + 8388608f)) - 1258291200u) * _e793)) + (bitcast<u32>((floor(select(0f, select(_e813, _e850, (_e850 < _e813)), (_e850 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e882 = (((((_e804 * 2f) - 1f) * _e147.member.member_1.x) * _e841) - _e384);
                                        let _e883 = (((((_e805 * -2f) + 1f) * _e147.member.member_1.y) * _e841) - _e391);
                                        let _e884 = (_e841 - _e377);
                                        let _e885 = (_e163 > 0f);
                                        if _e885 {
                                            phi_1418_ = ((((_e882 * _e882) + (_e883 * _e883)) + (_e884 * _e884)) > (_e163 * _e163));
                                        } else {
                                            phi_1418_ = false;
                                        }
                                        let _e894 = phi_1418_;
                                        if !(_e894) {
                                            let _e900 = (((_e882 * _e402) + (_e883 * _e403)) + (_e884 * _e404));
                                            let _e904 = (_e882 - (_e402 * _e900));
                                            let _e905 = (_e883 - (_e403 * _e900));
                                            let _e906 = (_e884 - (_e404 * _e900));
                                            let _e909 = ((_e905 * _e404) - (_e403 * _e906));
                                            let _e912 = ((_e906 * _e402) - (_e404 * _e904));
                                            let _e915 = ((_e904 * _e403) - (_e402 * _e905));
                                            let _e926 = ((((_e463 * _e909) + (_e464 * _e912)) + (_e465 * _e915)) / (((_e909 * _e909) + (_e912 * _e912)) + (_e915 * _e915)));
                                            let _e930 = (_e463 - (_e909 * _e926));
                                            let _e931 = (_e464 - (_e912 * _e926));
                                            let _e932 = (_e465 - (_e915 * _e926));
                                            let _e938 = inverseSqrt((((_e930 * _e930) + (_e931 * _e931)) + (_e932 * _e932)));
                                            let _e944 = ((((_e930 * _e402) + (_e931 * _e403)) + (_e932 * _e404)) * _e938);
                                            let _e948 = select(0f, select(1f, _e944, (_e944 < 1f)), (_e944 > 0f));
                                            let _e949 = abs(_e948);
                                            let _e959 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e949, 0.00667009f), _e949, -0.017088126f), _e949, 0.03089188f), _e949, -0.050174303f), _e949, 0.08897899f), _e949, -0.2145988f), _e949, 1.5707963f) * sqrt((1f - _e949)));
                                            let _e962 = select((3.1415927f - _e959), _e959, (_e948 >= 0f));
                                            let _e970 = select(_e962, -(_e962), ((((_e904 * _e930) + (_e905 * _e931)) + (_e906 * _e932)) < 0f));
                                            let _e971 = (_e938 * 0.02f);
                                            let _e974 = select(0.19634955f, _e971, ((_e971 < 0.19634955f) || false));
                                            let _e984 = (_e882 - (_e402 * _e160));
                                            let _e985 = (_e883 - (_e403 * _e160));
                                            let _e986 = (_e884 - (_e404 * _e160));
                                            let _e993 = (_e900 * inverseSqrt((((_e882 * _e882) + (_e883 * _e883)) + (_e884 * _e884))));
                                            let _e997 = select(-1f, select(1f, _e993, (_e993 < 1f)), (_e993 > -1f));
                                            let _e998 = abs(_e997);
                                            let _e1008 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e998, 0.00667009f), _e998, -0.017088126f), _e998, 0.03089188f), _e998, -0.050174303f), _e998, 0.08897899f), _e998, -0.2145988f), _e998, 1.5707963f) * sqrt((1f - _e998)));
                                            let _e1015 = ((((select((3.1415927f - _e1008), _e1008, (_e997 >= 0f)) + _e974) - _e970) + 1.5707964f) * 0.31830987f);
                                            let _e1019 = select(0f, select(1f, _e1015, (_e1015 < 1f)), (_e1015 > 0f));
                                            let _e1031 = ((((_e984 * _e402) + (_e985 * _e403)) + (_e986 * _e404)) * inverseSqrt((((_e984 * _e984) + (_e985 * _e985)) + (_e986 * _e986))));
                                            let _e1035 = select(-1f, select(1f, _e1031, (_e1031 < 1f)), (_e1031 > -1f));
                                            let _e1036 = abs(_e1035);
                                            let _e1046 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1036, 0.00667009f), _e1036, -0.017088126f), _e1036, 0.03089188f), _e1036, -0.050174303f), _e1036, 0.08897899f), _e1036, -0.2145988f), _e1036, 1.5707963f) * sqrt((1f - _e1036)));
                                            let _e1053 = ((((select((3.1415927f - _e1046), _e1046, (_e1035 >= 0f)) + _e974) - _e970) + 1.5707964f) * 0.31830987f);
                                            let _e1057 = select(0f, select(1f, _e1053, (_e1053 < 1f)), (_e1053 > 0f));
                                            let _e1059 = (_e1057 != _e1057);
                                            let _e1061 = select(_e1057, _e1019, ((_e1019 < _e1057) || _e1059));
                                            let _e1064 = select(_e1057, _e1019, ((_e1019 > _e1057) || _e1059));
                                            let _e1066 = floor((_e1061 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1074 = -(floor((_e1064 * -32f)));
                                                let _e1079 = (select(32f, _e1074, ((_e1074 < 32f) || false)) - _e1066);
                                                phi_1734_ = select(select(0f, _e1079, ((_e1079 > 0f) || false)), 0f, (_e1064 <= _e1061));
                                            } else {
                                                phi_1734_ = -(floor(((_e1064 - _e1061) * -32f)));
                                            }
                                            let _e1085 = phi_1734_;
                                            let _e1093 = (bitcast<u32>((floor(select(0f, select(32f, _e1066, (_e1066 < 32f)), (_e1066 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e1101 = (bitcast<u32>((floor(select(0f, select(32f, _e1085, (_e1085 < 32f)), (_e1085 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e1093 >= 32u) {
                                                phi_1788_ = u32();
                                                phi_1789_ = true;
                                            } else {
                                                let _e1103 = (_e1101 == 0u);
                                                if _e1103 {
                                                    phi_1787_ = u32();
                                                } else {
                                                    if (_e1101 >= 32u) {
                                                        phi_1784_ = 4294967295u;
                                                    } else {
                                                        phi_1784_ = ((1u << bitcast<u32>((_e1101 & 31u))) - 1u);
                                                    }
                                                    let _e1110 = phi_1784_;
                                                    phi_1787_ = (_e1110 << bitcast<u32>((_e1093 & 31u)));
                                                }
                                                let _e1115 = phi_1787_;
                                                phi_1788_ = _e1115;
                                                phi_1789_ = _e1103;
                                            }
                                            let _e1117 = phi_1788_;
                                            let _e1119 = phi_1789_;
                                            phi_1802_ = select(select(select(_e1117, 0u, _e1119), 0u, ((((_e904 * _e904) + (_e905 * _e905)) + (_e906 * _e906)) <= 0f)), 0u, _e894);
                                        } else {
                                            phi_1802_ = 0u;
                                        }
                                        let _e1124 = phi_1802_;
                                        let _e1126 = (((((_e806 * 2f) - 1f) * _e147.member.member_1.x) * _e873) - _e384);
                                        let _e1127 = (((((_e807 * -2f) + 1f) * _e147.member.member_1.y) * _e873) - _e391);
                                        let _e1128 = (_e873 - _e377);
                                        if _e885 {
                                            phi_1822_ = ((((_e1126 * _e1126) + (_e1127 * _e1127)) + (_e1128 * _e1128)) > (_e163 * _e163));
                                        } else {
                                            phi_1822_ = false;
                                        }
                                        let _e1137 = phi_1822_;
                                        if !(_e1137) {
                                            let _e1143 = (((_e1126 * _e402) + (_e1127 * _e403)) + (_e1128 * _e404));
                                            let _e1147 = (_e1126 - (_e402 * _e1143));
                                            let _e1148 = (_e1127 - (_e403 * _e1143));
                                            let _e1149 = (_e1128 - (_e404 * _e1143));
                                            let _e1152 = ((_e1148 * _e404) - (_e403 * _e1149));
                                            let _e1155 = ((_e1149 * _e402) - (_e404 * _e1147));
                                            let _e1158 = ((_e1147 * _e403) - (_e402 * _e1148));
                                            let _e1169 = ((((_e463 * _e1152) + (_e464 * _e1155)) + (_e465 * _e1158)) / (((_e1152 * _e1152) + (_e1155 * _e1155)) + (_e1158 * _e1158)));
                                            let _e1173 = (_e463 - (_e1152 * _e1169));
                                            let _e1174 = (_e464 - (_e1155 * _e1169));
                                            let _e1175 = (_e465 - (_e1158 * _e1169));
                                            let _e1181 = inverseSqrt((((_e1173 * _e1173) + (_e1174 * _e1174)) + (_e1175 * _e1175)));
                                            let _e1187 = ((((_e1173 * _e402) + (_e1174 * _e403)) + (_e1175 * _e404)) * _e1181);
                                            let _e1191 = select(0f, select(1f, _e1187, (_e1187 < 1f)), (_e1187 > 0f));
                                            let _e1192 = abs(_e1191);
                                            let _e1202 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1192, 0.00667009f), _e1192, -0.017088126f), _e1192, 0.03089188f), _e1192, -0.050174303f), _e1192, 0.08897899f), _e1192, -0.2145988f), _e1192, 1.5707963f) * sqrt((1f - _e1192)));
                                            let _e1205 = select((3.1415927f - _e1202), _e1202, (_e1191 >= 0f));
                                            let _e1213 = select(_e1205, -(_e1205), ((((_e1147 * _e1173) + (_e1148 * _e1174)) + (_e1149 * _e1175)) < 0f));
                                            let _e1214 = (_e1181 * 0.02f);
                                            let _e1217 = select(0.19634955f, _e1214, ((_e1214 < 0.19634955f) || false));
                                            let _e1227 = (_e1126 - (_e402 * _e160));
                                            let _e1228 = (_e1127 - (_e403 * _e160));
                                            let _e1229 = (_e1128 - (_e404 * _e160));
                                            let _e1236 = (_e1143 * inverseSqrt((((_e1126 * _e1126) + (_e1127 * _e1127)) + (_e1128 * _e1128))));
                                            let _e1240 = select(-1f, select(1f, _e1236, (_e1236 < 1f)), (_e1236 > -1f));
                                            let _e1241 = abs(_e1240);
                                            let _e1251 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1241, 0.00667009f), _e1241, -0.017088126f), _e1241, 0.03089188f), _e1241, -0.050174303f), _e1241, 0.08897899f), _e1241, -0.2145988f), _e1241, 1.5707963f) * sqrt((1f - _e1241)));
                                            let _e1258 = ((((select((3.1415927f - _e1251), _e1251, (_e1240 >= 0f)) + _e1217) - _e1213) + 1.5707964f) * 0.31830987f);
                                            let _e1274 = ((((_e1227 * _e402) + (_e1228 * _e403)) + (_e1229 * _e404)) * inverseSqrt((((_e1227 * _e1227) + (_e1228 * _e1228)) + (_e1229 * _e1229))));
                                            let _e1278 = select(-1f, select(1f, _e1274, (_e1274 < 1f)), (_e1274 > -1f));
                                            let _e1279 = abs(_e1278);
                                            let _e1289 = (fma(fma(fma(fma(fma(fma(fma(-0.0012624911f, _e1279, 0.00667009f), _e1279, -0.017088126f), _e1279, 0.03089188f), _e1279, -0.050174303f), _e1279, 0.08897899f), _e1279, -0.2145988f), _e1279, 1.5707963f) * sqrt((1f - _e1279)));
                                            let _e1296 = ((((select((3.1415927f - _e1289), _e1289, (_e1278 >= 0f)) + _e1217) - _e1213) + 1.5707964f) * 0.31830987f);
                                            let _e1301 = (1f - select(0f, select(1f, _e1258, (_e1258 < 1f)), (_e1258 > 0f)));
                                            let _e1302 = (1f - select(0f, select(1f, _e1296, (_e1296 < 1f)), (_e1296 > 0f)));
                                            let _e1304 = (_e1302 != _e1302);
                                            let _e1306 = select(_e1302, _e1301, ((_e1301 < _e1302) || _e1304));
                                            let _e1309 = select(_e1302, _e1301, ((_e1301 > _e1302) || _e1304));
                                            let _e1311 = floor((_e1306 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1319 = -(floor((_e1309 * -32f)));
                                                let _e1324 = (select(32f, _e1319, ((_e1319 < 32f) || false)) - _e1311);
                                                phi_2138_ = select(select(0f, _e1324, ((_e1324 > 0f) || false)), 0f, (_e1309 <= _e1306));
                                            } else {
                                                phi_2138_ = -(floor(((_e1309 - _e1306) * -32f)));
                                            }
                                            let _e1330 = phi_2138_;
                                            let _e1338 = (bitcast<u32>((floor(select(0f, select(32f, _e1311, (_e1311 < 32f)), (_e1311 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e1346 = (bitcast<u32>((floor(select(0f, select(32f, _e1330, (_e1330 < 32f)), (_e1330 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e1338 >= 32u) {
                                                phi_2192_ = u32();
                                                phi_2193_ = true;
                                            } else {
                                                let _e1348 = (_e1346 == 0u);
                                                if _e1348 {
                                                    phi_2191_ = u32();
                                                } else {
                                                    if (_e1346 >= 32u) {
                                                        phi_2188_ = 4294967295u;
                                                    } else {
                                                        phi_2188_ = ((1u << bitcast<u32>((_e1346 & 31u))) - 1u);
                                                    }
                                                    let _e1355 = phi_2188_;
                                                    phi_2191_ = (_e1355 << bitcast<u32>((_e1338 & 31u)));
                                                }
                                                let _e1360 = phi_2191_;
                                                phi_2192_ = _e1360;
                                                phi_2193_ = _e1348;
                                            }
                                            let _e1362 = phi_2192_;
                                            let _e1364 = phi_2193_;
                                            phi_2206_ = select(select(select(_e1362, 0u, _e1364), 0u, ((((_e1147 * _e1147) + (_e1148 * _e1148)) + (_e1149 * _e1149)) <= 0f)), 0u, _e1137);
                                        } else {
                                            phi_2206_ = 0u;
                                        }
                                        let _e1369 = phi_2206_;
                                        phi_1080_ = (_e705 + 1u);
                                        phi_1083_ = ((_e707 | _e1124) | _e1369);
                                    } else {
                                        phi_1080_ = u32();
                                        phi_1083_ = u32();
                                    }
                                    let _e1373 = phi_1080_;
                                    let _e1375 = phi_1083_;
                                    continue;
                                    continuing {
                                        phi_1079_ = _e1373;
                                        phi_1082_ = _e1375;
                                        break if !(_e708);
                                    }
                                }
                                if (_e152 == 2u) {
                                    let _e1435 = (_e700 - 1.5707964f);
                                    let _e1436 = (_e1435 * 2f);
                                    let _e1437 = sin(_e700);
                                    let _e1442 = ((_e685 + (_e1436 * _e1437)) - cos((_e1436 - _e700)));
                                    phi_2235_ = 0u;
                                    phi_2238_ = select((_e1442 * 0.25f), (_e1442 * -0.25f), (_e1435 < 0f));
                                    phi_2240_ = 0f;
                                    loop {
                                        let _e1448 = phi_2235_;
                                        let _e1450 = phi_2238_;
                                        let _e1452 = phi_2240_;
                                        local_5 = _e1452;
                                        let _e1453 = (_e1448 < 32u);
                                        if _e1453 {
                                            let _e1454 = (_e1448 + 1u);
                                            let _e1458 = (_e1435 + (f32(bitcast<i32>(_e1454)) * 0.09817477f));
                                            let _e1459 = (_e1458 * 2f);
                                            let _e1464 = ((_e685 + (_e1459 * _e1437)) - cos((_e1459 - _e700)));
                                            let _e1468 = select((_e1464 * 0.25f), (_e1464 * -0.25f), (_e1458 < 0f));
                                            let _e1471 = local_4;
                                            phi_2236_ = _e1454;
                                            phi_2239_ = _e1468;
                                            phi_2241_ = select(_e1452, (_e1452 + (_e1468 - _e1450)), (((_e1471 >> bitcast<u32>((_e1448 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2236_ = u32();
                                            phi_2239_ = f32();
                                            phi_2241_ = f32();
                                        }
                                        let _e1480 = phi_2236_;
                                        let _e1482 = phi_2239_;
                                        let _e1484 = phi_2241_;
                                        continue;
                                        continuing {
                                            phi_2235_ = _e1480;
                                            phi_2238_ = _e1482;
                                            phi_2240_ = _e1484;
                                            break if !(_e1453);
                                        }
                                    }
                                    let _e1487 = local_5;
                                    phi_2742_ = _e602;
                                    phi_2342_ = (_e606 + 1f);
                                    phi_2343_ = (_e608 + ((_e666 + ((1f - _e666) * 0.05f)) * _e1487));
                                } else {
                                    if (_e152 == 1u) {
                                        phi_2287_ = 0u;
                                        phi_2290_ = 0f;
                                        loop {
                                            let _e1390 = phi_2287_;
                                            let _e1392 = phi_2290_;
                                            local_3 = _e1392;
                                            let _e1393 = (_e1390 < 4u);
                                            if _e1393 {
                                                local = array<type_26, 4>(type_26(4026531855u, 0.0095061f), type_26(251658480u, 0.0270951f), type_26(15732480u, 0.0405571f), type_26(1044480u, 0.0478421f));
                                                if _e1393 {
                                                } else {
                                                    phi_2569_ = true;
                                                    break;
                                                }
                                                let _e1396 = local[_e1390].member;
                                                let _e1399 = local[_e1390].member_1;
                                                let _e1401 = local_2;
                                                phi_2288_ = (_e1390 + 1u);
                                                phi_2291_ = (_e1392 + (f32(bitcast<i32>(countOneBits((_e1401 & _e1396)))) * _e1399));
                                            } else {
                                                phi_2288_ = u32();
                                                phi_2291_ = f32();
                                            }
                                            let _e1410 = phi_2288_;
                                            let _e1412 = phi_2291_;
                                            continue;
                                            continuing {
                                                phi_2287_ = _e1410;
                                                phi_2290_ = _e1412;
                                                phi_2569_ = _e602;
                                                break if !(_e1393);
                                            }
                                        }
                                        let _e1415 = phi_2569_;
                                        phi_2740_ = _e1415;
                                        if _e1415 {
                                            break;
                                        }
                                        let _e1417 = local_3;
                                        let _e1418 = (1f - _e1417);
                                        phi_2748_ = _e1415;
                                        phi_2340_ = (_e606 + _e666);
                                        phi_2341_ = (_e608 + (_e666 * select(0f, select(1f, _e1418, (_e1418 < 1f)), (_e1418 > 0f))));
                                    } else {
                                        let _e1380 = local_1;
                                        phi_2748_ = _e602;
                                        phi_2340_ = (_e606 + 1f);
                                        phi_2341_ = (_e608 + ((f32(bitcast<i32>(countOneBits((_e1380 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e1427 = phi_2748_;
                                    let _e1429 = phi_2340_;
                                    let _e1431 = phi_2341_;
                                    phi_2742_ = _e1427;
                                    phi_2342_ = _e1429;
                                    phi_2343_ = _e1431;
                                }
                                let _e1492 = phi_2742_;
                                let _e1494 = phi_2342_;
                                let _e1496 = phi_2343_;
                                phi_2741_ = _e1492;
                                phi_889_ = (_e604 + 1u);
                                phi_892_ = _e1494;
                                phi_894_ = _e1496;
                            } else {
                                phi_2741_ = _e602;
                                phi_889_ = u32();
                                phi_892_ = f32();
                                phi_894_ = f32();
                            }
                            let _e1499 = phi_2741_;
                            let _e1501 = phi_889_;
                            let _e1503 = phi_892_;
                            let _e1505 = phi_894_;
                            continue;
                            continuing {
                                phi_2674_ = _e1499;
                                phi_888_ = _e1501;
                                phi_891_ = _e1503;
                                phi_893_ = _e1505;
                                phi_2740_ = _e1499;
                                break if !(_e609);
                            }
                        }
                        let _e1508 = phi_2740_;
                        if _e1508 {
                            break;
                        }
                        let _e1510 = local_6;
                        let _e1513 = local_7;
                        let _e1515 = local_8;
                        phi_2351_ = select(1f, (_e1513 / _e1515), (_e1510 > 0f));
                    } else {
                        phi_2351_ = 1f;
                    }
                    let _e1519 = phi_2351_;
                    if (_e147.member_6 == 2f) {
                        phi_2364_ = (_e1519 * _e1519);
                    } else {
                        if (_e147.member_6 == 1f) {
                            phi_2363_ = _e1519;
                        } else {
                            phi_2363_ = pow(_e1519, _e147.member_6);
                        }
                        let _e1525 = phi_2363_;
                        phi_2364_ = _e1525;
                    }
                    let _e1528 = phi_2364_;
                    let _e1533 = (select(1f, select(0.03f, _e1528, ((_e1528 > 0.03f) || false)), _e597) * 0.6666667f);
                    terms.member[_e185] = (bitcast<u32>((floor(((select(0f, select(1f, _e1533, (_e1533 < 1f)), (_e1533 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                    edges.member[_e185] = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e314, (_e314 < 3f)), (_e314 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e329, (_e329 < 3f)), (_e329 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e345, (_e345 < 3f)), (_e345 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e361, (_e361 < 3f)), (_e361 > 0f))) + 8388608f)) - 1258291200u));
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
