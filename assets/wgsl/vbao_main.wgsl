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
    var phi_446_: type_21;
    var phi_453_: u32;
    var phi_460_: u32;
    var phi_3048_: bool;
    var phi_995_: u32;
    var phi_998_: f32;
    var phi_1000_: f32;
    var phi_1193_: u32;
    var phi_1196_: u32;
    var phi_1249_: f32;
    var phi_1527_: bool;
    var phi_1859_: f32;
    var phi_1909_: u32;
    var phi_1912_: u32;
    var phi_1913_: u32;
    var phi_1914_: bool;
    var phi_1933_: u32;
    var phi_1953_: bool;
    var phi_2285_: f32;
    var phi_2335_: u32;
    var phi_2338_: u32;
    var phi_2339_: u32;
    var phi_2340_: bool;
    var phi_2359_: u32;
    var phi_1194_: u32;
    var phi_1197_: u32;
    var local_1: u32;
    var phi_2440_: u32;
    var phi_2443_: f32;
    var local_2: u32;
    var phi_2441_: u32;
    var phi_2444_: f32;
    var phi_2943_: bool;
    var local_3: f32;
    var phi_3141_: bool;
    var phi_2493_: f32;
    var phi_2494_: f32;
    var phi_2388_: u32;
    var phi_2391_: f32;
    var phi_2393_: f32;
    var local_4: u32;
    var phi_2389_: u32;
    var phi_2392_: f32;
    var phi_2394_: f32;
    var local_5: f32;
    var phi_3135_: bool;
    var phi_2495_: f32;
    var phi_2496_: f32;
    var phi_3134_: bool;
    var phi_996_: u32;
    var phi_999_: f32;
    var phi_1001_: f32;
    var phi_3133_: bool;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var phi_2504_: f32;
    var phi_2925_: bool;
    var phi_2545_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e110 = id_1;
            let _e113 = (override_type == 0u);
            if _e113 {
                let _e145 = params.member.member_4;
                phi_446_ = _e145;
            } else {
                let _e123 = params.member.member_4.member;
                let _e127 = params.member.member_4.member_1;
                let _e131 = params.member.member_4.member_10;
                let _e135 = params.member.member_4.member_11;
                let _e139 = params.member.member_4.member_12;
                let _e143 = params.member.member_4.member_14;
                phi_446_ = type_21(_e123, _e127, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e131, _e135, _e139, override_type_9, _e143);
            }
            let _e147 = phi_446_;
            if _e113 {
                let _e150 = params.member.member_2;
                phi_453_ = _e150;
            } else {
                phi_453_ = override_type_10;
            }
            let _e152 = phi_453_;
            if _e113 {
                let _e155 = params.member.member_3;
                phi_460_ = _e155;
            } else {
                phi_460_ = override_type_11;
            }
            let _e157 = phi_460_;
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
                    let _e596 = exp2(((2f * _e147.member_7) + 1f));
                    let _e601 = select(false, (_e188 < _e147.member.member_3), (_e188 > 0f));
                    if _e601 {
                        let _e604 = select(1u, _e147.member_8, (1u < _e147.member_8));
                        phi_3048_ = false;
                        phi_995_ = 0u;
                        phi_998_ = 0f;
                        phi_1000_ = 0f;
                        loop {
                            let _e606 = phi_3048_;
                            let _e608 = phi_995_;
                            let _e610 = phi_998_;
                            let _e612 = phi_1000_;
                            local_6 = _e610;
                            local_7 = _e612;
                            local_8 = _e610;
                            let _e613 = (_e608 < _e604);
                            if _e613 {
                                let _e620 = ((((_e586 - floor(_e586)) + f32(bitcast<i32>(_e608))) * 3.1415927f) / f32(bitcast<i32>(_e604)));
                                let _e621 = sin(_e620);
                                let _e622 = cos(_e620);
                                let _e628 = ((_e622 * _e402) + (_e621 * _e403));
                                let _e632 = (_e622 - (_e402 * _e628));
                                let _e633 = (_e621 - (_e403 * _e628));
                                let _e634 = -((_e404 * _e628));
                                let _e637 = ((_e633 * _e404) - (_e403 * _e634));
                                let _e640 = ((_e634 * _e402) - (_e404 * _e632));
                                let _e643 = ((_e632 * _e403) - (_e402 * _e633));
                                let _e650 = (1f / sqrt((((_e637 * _e637) + (_e640 * _e640)) + (_e643 * _e643))));
                                let _e651 = (_e637 * _e650);
                                let _e652 = (_e640 * _e650);
                                let _e653 = (_e643 * _e650);
                                let _e658 = (((_e463 * _e651) + (_e464 * _e652)) + (_e465 * _e653));
                                let _e662 = (_e463 - (_e651 * _e658));
                                let _e663 = (_e464 - (_e652 * _e658));
                                let _e664 = (_e465 - (_e653 * _e658));
                                let _e670 = sqrt((((_e662 * _e662) + (_e663 * _e663)) + (_e664 * _e664)));
                                let _e675 = (((_e632 * _e662) + (_e633 * _e663)) + (_e634 * _e664));
                                let _e685 = ((((_e662 * _e402) + (_e663 * _e403)) + (_e664 * _e404)) / _e670);
                                let _e689 = select(0f, select(1f, _e685, (_e685 < 1f)), (_e685 > 0f));
                                let _e690 = abs(_e689);
                                let _e708 = (((((((((((((((_e690 * -0.0012624911f) + 0.00667009f) * _e690) - 0.017088126f) * _e690) + 0.03089188f) * _e690) - 0.050174303f) * _e690) + 0.08897899f) * _e690) - 0.2145988f) * _e690) + 1.5707963f) * sqrt((1f - _e690)));
                                let _e711 = (select(select(0f, -1f, (_e675 < 0f)), 1f, (_e675 > 0f)) * select((3.1415927f - _e708), _e708, (_e689 >= 0f)));
                                let _e714 = select(1u, _e147.member_9, (1u < _e147.member_9));
                                phi_1193_ = 0u;
                                phi_1196_ = 0u;
                                loop {
                                    let _e716 = phi_1193_;
                                    let _e718 = phi_1196_;
                                    local_1 = _e718;
                                    local_2 = _e718;
                                    local_4 = _e718;
                                    let _e719 = (_e716 < _e714);
                                    if _e719 {
                                        let _e725 = ((_e590 - floor(_e590)) + (f32(bitcast<i32>((_e608 + (_e716 * _e714)))) * 0.618034f));
                                        let _e734 = (((_e725 - floor(_e725)) + f32(bitcast<i32>(_e716))) * (1f / f32(bitcast<i32>(_e714))));
                                        if (_e147.member_4 == 2f) {
                                            phi_1249_ = (_e734 * _e734);
                                        } else {
                                            phi_1249_ = pow(_e734, _e147.member_4);
                                        }
                                        let _e740 = phi_1249_;
                                        let _e741 = (_e740 + (1.3f / _e472));
                                        let _e742 = ((_e622 * _e472) * _e741);
                                        let _e743 = ((-(_e621) * _e472) * _e741);
                                        let _e746 = ((_e742 * _e742) + (_e743 * _e743));
                                        let _e751 = (select(1u, _e171, (1u < _e171)) * select(1u, _e179, (1u < _e179)));
                                        let _e752 = (_e746 > _e596);
                                        let _e756 = (_e171 >> bitcast<u32>(1u));
                                        let _e760 = (_e179 >> bitcast<u32>(1u));
                                        let _e764 = (_e751 + (select(1u, _e756, (1u < _e756)) * select(1u, _e760, (1u < _e760))));
                                        let _e766 = (_e746 > (_e596 * 4f));
                                        let _e770 = (_e171 >> bitcast<u32>(2u));
                                        let _e774 = (_e179 >> bitcast<u32>(2u));
                                        let _e778 = (_e764 + (select(1u, _e770, (1u < _e770)) * select(1u, _e774, (1u < _e774))));
                                        let _e780 = (_e746 > (_e596 * 16f));
                                        let _e784 = (_e171 >> bitcast<u32>(3u));
                                        let _e788 = (_e179 >> bitcast<u32>(3u));
                                        let _e794 = (_e746 > (_e596 * 64f));
                                        let _e796 = select(select(select(select(0u, _e751, _e752), _e764, _e766), _e778, _e780), (_e778 + (select(1u, _e784, (1u < _e784)) * select(1u, _e788, (1u < _e788)))), _e794);
                                        let _e797 = (select(select(select(select(0u, 1u, _e752), 2u, _e766), 3u, _e780), 4u, _e794) & 31u);
                                        let _e799 = (_e171 >> bitcast<u32>(_e797));
                                        let _e801 = select(1u, _e799, (1u < _e799));
                                        let _e803 = (_e179 >> bitcast<u32>(_e797));
                                        let _e805 = select(1u, _e803, (1u < _e803));
                                        let _e808 = (round(_e742) * (1f / _e147.member.member.x));
                                        let _e811 = (round(_e743) * (1f / _e147.member.member.y));
                                        let _e812 = (_e373 + _e808);
                                        let _e813 = (_e376 + _e811);
                                        let _e814 = (_e373 - _e808);
                                        let _e815 = (_e376 - _e811);
                                        let _e817 = f32(bitcast<i32>(_e801));
                                        let _e818 = (_e812 * _e817);
                                        let _e821 = f32(bitcast<i32>((_e801 - 1u)));
                                        let _e831 = f32(bitcast<i32>(_e805));
                                        let _e832 = (_e813 * _e831);
                                        let _e835 = f32(bitcast<i32>((_e805 - 1u)));
                                        let _e849 = mips.member[((_e796 + ((bitcast<u32>((floor(select(0f, select(_e835, _e832, (_e832 < _e835)), (_e832 > 0f))) + 8388608f)) - 1258291200u) * _e801)) + (bitcast<u32>((floor(select(0f, select(_e821, _e818, (_e818 < _e821)), (_e818 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e858 = (_e814 * _e817);
                                        let _e867 = (_e815 * _e831);
                                        let _e881 = mips.member[((_e796 + ((bitcast<u32>((floor(select(0f, select(_e835, _e867, (_e867 < _e835)), (_e867 > 0f))) + 8388608f)) - 1258291200u) * _e801)) + (bitcast<u32>((floor(select(0f, select(_e821, _e858, (_e858 < _e821)), (_e858 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e890 = (((((_e812 * 2f) - 1f) * _e147.member.member_1.x) * _e849) - _e384);
                                        let _e891 = (((((_e813 * -2f) + 1f) * _e147.member.member_1.y) * _e849) - _e391);
                                        let _e892 = (_e849 - _e377);
                                        let _e893 = (_e163 > 0f);
                                        if _e893 {
                                            phi_1527_ = (sqrt((((_e890 * _e890) + (_e891 * _e891)) + (_e892 * _e892))) > _e163);
                                        } else {
                                            phi_1527_ = false;
                                        }
                                        let _e902 = phi_1527_;
                                        if !(_e902) {
                                            let _e908 = (((_e890 * _e402) + (_e891 * _e403)) + (_e892 * _e404));
                                            let _e912 = (_e890 - (_e402 * _e908));
                                            let _e913 = (_e891 - (_e403 * _e908));
                                            let _e914 = (_e892 - (_e404 * _e908));
                                            let _e917 = ((_e913 * _e404) - (_e403 * _e914));
                                            let _e920 = ((_e914 * _e402) - (_e404 * _e912));
                                            let _e923 = ((_e912 * _e403) - (_e402 * _e913));
                                            let _e934 = ((((_e463 * _e917) + (_e464 * _e920)) + (_e465 * _e923)) / (((_e917 * _e917) + (_e920 * _e920)) + (_e923 * _e923)));
                                            let _e938 = (_e463 - (_e917 * _e934));
                                            let _e939 = (_e464 - (_e920 * _e934));
                                            let _e940 = (_e465 - (_e923 * _e934));
                                            let _e946 = sqrt((((_e938 * _e938) + (_e939 * _e939)) + (_e940 * _e940)));
                                            let _e953 = ((((_e938 * _e402) + (_e939 * _e403)) + (_e940 * _e404)) * (1f / _e946));
                                            let _e957 = select(0f, select(1f, _e953, (_e953 < 1f)), (_e953 > 0f));
                                            let _e958 = abs(_e957);
                                            let _e975 = (((((((((((((((_e958 * -0.0012624911f) + 0.00667009f) * _e958) - 0.017088126f) * _e958) + 0.03089188f) * _e958) - 0.050174303f) * _e958) + 0.08897899f) * _e958) - 0.2145988f) * _e958) + 1.5707963f) * sqrt((1f - _e958)));
                                            let _e978 = select((3.1415927f - _e975), _e975, (_e957 >= 0f));
                                            let _e986 = select(_e978, -(_e978), ((((_e912 * _e938) + (_e913 * _e939)) + (_e914 * _e940)) < 0f));
                                            let _e987 = (0.02f / _e946);
                                            let _e990 = select(0.19634955f, _e987, ((_e987 < 0.19634955f) || false));
                                            let _e994 = (_e890 - (_e402 * _e160));
                                            let _e995 = (_e891 - (_e403 * _e160));
                                            let _e996 = (_e892 - (_e404 * _e160));
                                            let _e1003 = (_e908 / sqrt((((_e890 * _e890) + (_e891 * _e891)) + (_e892 * _e892))));
                                            let _e1007 = select(-1f, select(1f, _e1003, (_e1003 < 1f)), (_e1003 > -1f));
                                            let _e1008 = abs(_e1007);
                                            let _e1025 = (((((((((((((((_e1008 * -0.0012624911f) + 0.00667009f) * _e1008) - 0.017088126f) * _e1008) + 0.03089188f) * _e1008) - 0.050174303f) * _e1008) + 0.08897899f) * _e1008) - 0.2145988f) * _e1008) + 1.5707963f) * sqrt((1f - _e1008)));
                                            let _e1032 = ((((select((3.1415927f - _e1025), _e1025, (_e1007 >= 0f)) + _e990) - _e986) + 1.5707964f) * 0.31830987f);
                                            let _e1036 = select(0f, select(1f, _e1032, (_e1032 < 1f)), (_e1032 > 0f));
                                            let _e1048 = ((((_e994 * _e402) + (_e995 * _e403)) + (_e996 * _e404)) / sqrt((((_e994 * _e994) + (_e995 * _e995)) + (_e996 * _e996))));
                                            let _e1052 = select(-1f, select(1f, _e1048, (_e1048 < 1f)), (_e1048 > -1f));
                                            let _e1053 = abs(_e1052);
                                            let _e1070 = (((((((((((((((_e1053 * -0.0012624911f) + 0.00667009f) * _e1053) - 0.017088126f) * _e1053) + 0.03089188f) * _e1053) - 0.050174303f) * _e1053) + 0.08897899f) * _e1053) - 0.2145988f) * _e1053) + 1.5707963f) * sqrt((1f - _e1053)));
                                            let _e1077 = ((((select((3.1415927f - _e1070), _e1070, (_e1052 >= 0f)) + _e990) - _e986) + 1.5707964f) * 0.31830987f);
                                            let _e1081 = select(0f, select(1f, _e1077, (_e1077 < 1f)), (_e1077 > 0f));
                                            let _e1083 = (_e1081 != _e1081);
                                            let _e1085 = select(_e1081, _e1036, ((_e1036 < _e1081) || _e1083));
                                            let _e1088 = select(_e1081, _e1036, ((_e1036 > _e1081) || _e1083));
                                            let _e1090 = floor((_e1085 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1098 = -(floor((_e1088 * -32f)));
                                                let _e1103 = (select(32f, _e1098, ((_e1098 < 32f) || false)) - _e1090);
                                                phi_1859_ = select(select(0f, _e1103, ((_e1103 > 0f) || false)), 0f, (_e1088 <= _e1085));
                                            } else {
                                                phi_1859_ = -(floor(((_e1088 - _e1085) * -32f)));
                                            }
                                            let _e1109 = phi_1859_;
                                            let _e1117 = (bitcast<u32>((floor(select(0f, select(32f, _e1090, (_e1090 < 32f)), (_e1090 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e1125 = (bitcast<u32>((floor(select(0f, select(32f, _e1109, (_e1109 < 32f)), (_e1109 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e1117 >= 32u) {
                                                phi_1913_ = u32();
                                                phi_1914_ = true;
                                            } else {
                                                let _e1127 = (_e1125 == 0u);
                                                if _e1127 {
                                                    phi_1912_ = u32();
                                                } else {
                                                    if (_e1125 >= 32u) {
                                                        phi_1909_ = 4294967295u;
                                                    } else {
                                                        phi_1909_ = ((1u << bitcast<u32>((_e1125 & 31u))) - 1u);
                                                    }
                                                    let _e1134 = phi_1909_;
                                                    phi_1912_ = (_e1134 << bitcast<u32>((_e1117 & 31u)));
                                                }
                                                let _e1139 = phi_1912_;
                                                phi_1913_ = _e1139;
                                                phi_1914_ = _e1127;
                                            }
                                            let _e1141 = phi_1913_;
                                            let _e1143 = phi_1914_;
                                            phi_1933_ = select(select(select(_e1141, 0u, _e1143), 0u, ((((_e912 * _e912) + (_e913 * _e913)) + (_e914 * _e914)) <= 0f)), 0u, _e902);
                                        } else {
                                            phi_1933_ = 0u;
                                        }
                                        let _e1154 = phi_1933_;
                                        let _e1156 = (((((_e814 * 2f) - 1f) * _e147.member.member_1.x) * _e881) - _e384);
                                        let _e1157 = (((((_e815 * -2f) + 1f) * _e147.member.member_1.y) * _e881) - _e391);
                                        let _e1158 = (_e881 - _e377);
                                        if _e893 {
                                            phi_1953_ = (sqrt((((_e1156 * _e1156) + (_e1157 * _e1157)) + (_e1158 * _e1158))) > _e163);
                                        } else {
                                            phi_1953_ = false;
                                        }
                                        let _e1167 = phi_1953_;
                                        if !(_e1167) {
                                            let _e1173 = (((_e1156 * _e402) + (_e1157 * _e403)) + (_e1158 * _e404));
                                            let _e1177 = (_e1156 - (_e402 * _e1173));
                                            let _e1178 = (_e1157 - (_e403 * _e1173));
                                            let _e1179 = (_e1158 - (_e404 * _e1173));
                                            let _e1182 = ((_e1178 * _e404) - (_e403 * _e1179));
                                            let _e1185 = ((_e1179 * _e402) - (_e404 * _e1177));
                                            let _e1188 = ((_e1177 * _e403) - (_e402 * _e1178));
                                            let _e1199 = ((((_e463 * _e1182) + (_e464 * _e1185)) + (_e465 * _e1188)) / (((_e1182 * _e1182) + (_e1185 * _e1185)) + (_e1188 * _e1188)));
                                            let _e1203 = (_e463 - (_e1182 * _e1199));
                                            let _e1204 = (_e464 - (_e1185 * _e1199));
                                            let _e1205 = (_e465 - (_e1188 * _e1199));
                                            let _e1211 = sqrt((((_e1203 * _e1203) + (_e1204 * _e1204)) + (_e1205 * _e1205)));
                                            let _e1218 = ((((_e1203 * _e402) + (_e1204 * _e403)) + (_e1205 * _e404)) * (1f / _e1211));
                                            let _e1222 = select(0f, select(1f, _e1218, (_e1218 < 1f)), (_e1218 > 0f));
                                            let _e1223 = abs(_e1222);
                                            let _e1240 = (((((((((((((((_e1223 * -0.0012624911f) + 0.00667009f) * _e1223) - 0.017088126f) * _e1223) + 0.03089188f) * _e1223) - 0.050174303f) * _e1223) + 0.08897899f) * _e1223) - 0.2145988f) * _e1223) + 1.5707963f) * sqrt((1f - _e1223)));
                                            let _e1243 = select((3.1415927f - _e1240), _e1240, (_e1222 >= 0f));
                                            let _e1251 = select(_e1243, -(_e1243), ((((_e1177 * _e1203) + (_e1178 * _e1204)) + (_e1179 * _e1205)) < 0f));
                                            let _e1252 = (0.02f / _e1211);
                                            let _e1255 = select(0.19634955f, _e1252, ((_e1252 < 0.19634955f) || false));
                                            let _e1259 = (_e1156 - (_e402 * _e160));
                                            let _e1260 = (_e1157 - (_e403 * _e160));
                                            let _e1261 = (_e1158 - (_e404 * _e160));
                                            let _e1268 = (_e1173 / sqrt((((_e1156 * _e1156) + (_e1157 * _e1157)) + (_e1158 * _e1158))));
                                            let _e1272 = select(-1f, select(1f, _e1268, (_e1268 < 1f)), (_e1268 > -1f));
                                            let _e1273 = abs(_e1272);
                                            let _e1290 = (((((((((((((((_e1273 * -0.0012624911f) + 0.00667009f) * _e1273) - 0.017088126f) * _e1273) + 0.03089188f) * _e1273) - 0.050174303f) * _e1273) + 0.08897899f) * _e1273) - 0.2145988f) * _e1273) + 1.5707963f) * sqrt((1f - _e1273)));
                                            let _e1297 = ((((select((3.1415927f - _e1290), _e1290, (_e1272 >= 0f)) + _e1255) - _e1251) + 1.5707964f) * 0.31830987f);
                                            let _e1313 = ((((_e1259 * _e402) + (_e1260 * _e403)) + (_e1261 * _e404)) / sqrt((((_e1259 * _e1259) + (_e1260 * _e1260)) + (_e1261 * _e1261))));
                                            let _e1317 = select(-1f, select(1f, _e1313, (_e1313 < 1f)), (_e1313 > -1f));
                                            let _e1318 = abs(_e1317);
                                            let _e1335 = (((((((((((((((_e1318 * -0.0012624911f) + 0.00667009f) * _e1318) - 0.017088126f) * _e1318) + 0.03089188f) * _e1318) - 0.050174303f) * _e1318) + 0.08897899f) * _e1318) - 0.2145988f) * _e1318) + 1.5707963f) * sqrt((1f - _e1318)));
                                            let _e1342 = ((((select((3.1415927f - _e1335), _e1335, (_e1317 >= 0f)) + _e1255) - _e1251) + 1.5707964f) * 0.31830987f);
                                            let _e1347 = (1f - select(0f, select(1f, _e1297, (_e1297 < 1f)), (_e1297 > 0f)));
                                            let _e1348 = (1f - select(0f, select(1f, _e1342, (_e1342 < 1f)), (_e1342 > 0f)));
                                            let _e1350 = (_e1348 != _e1348);
                                            let _e1352 = select(_e1348, _e1347, ((_e1347 < _e1348) || _e1350));
                                            let _e1355 = select(_e1348, _e1347, ((_e1347 > _e1348) || _e1350));
                                            let _e1357 = floor((_e1352 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1365 = -(floor((_e1355 * -32f)));
                                                let _e1370 = (select(32f, _e1365, ((_e1365 < 32f) || false)) - _e1357);
                                                phi_2285_ = select(select(0f, _e1370, ((_e1370 > 0f) || false)), 0f, (_e1355 <= _e1352));
                                            } else {
                                                phi_2285_ = -(floor(((_e1355 - _e1352) * -32f)));
                                            }
                                            let _e1376 = phi_2285_;
                                            let _e1384 = (bitcast<u32>((floor(select(0f, select(32f, _e1357, (_e1357 < 32f)), (_e1357 > 0f))) + 8388608f)) - 1258291200u);
                                            let _e1392 = (bitcast<u32>((floor(select(0f, select(32f, _e1376, (_e1376 < 32f)), (_e1376 > 0f))) + 8388608f)) - 1258291200u);
                                            if (_e1384 >= 32u) {
                                                phi_2339_ = u32();
                                                phi_2340_ = true;
                                            } else {
                                                let _e1394 = (_e1392 == 0u);
                                                if _e1394 {
                                                    phi_2338_ = u32();
                                                } else {
                                                    if (_e1392 >= 32u) {
                                                        phi_2335_ = 4294967295u;
                                                    } else {
                                                        phi_2335_ = ((1u << bitcast<u32>((_e1392 & 31u))) - 1u);
                                                    }
                                                    let _e1401 = phi_2335_;
                                                    phi_2338_ = (_e1401 << bitcast<u32>((_e1384 & 31u)));
                                                }
                                                let _e1406 = phi_2338_;
                                                phi_2339_ = _e1406;
                                                phi_2340_ = _e1394;
                                            }
                                            let _e1408 = phi_2339_;
                                            let _e1410 = phi_2340_;
                                            phi_2359_ = select(select(select(_e1408, 0u, _e1410), 0u, ((((_e1177 * _e1177) + (_e1178 * _e1178)) + (_e1179 * _e1179)) <= 0f)), 0u, _e1167);
                                        } else {
                                            phi_2359_ = 0u;
                                        }
                                        let _e1421 = phi_2359_;
                                        phi_1194_ = (_e716 + 1u);
                                        phi_1197_ = ((_e718 | _e1154) | _e1421);
                                    } else {
                                        phi_1194_ = u32();
                                        phi_1197_ = u32();
                                    }
                                    let _e1425 = phi_1194_;
                                    let _e1427 = phi_1197_;
                                    continue;
                                    continuing {
                                        phi_1193_ = _e1425;
                                        phi_1196_ = _e1427;
                                        break if !(_e719);
                                    }
                                }
                                if (_e152 == 2u) {
                                    let _e1487 = (_e711 - 1.5707964f);
                                    let _e1488 = (_e1487 * 2f);
                                    let _e1489 = sin(_e711);
                                    let _e1494 = ((_e689 + (_e1488 * _e1489)) - cos((_e1488 - _e711)));
                                    phi_2388_ = 0u;
                                    phi_2391_ = select((_e1494 * 0.25f), (_e1494 * -0.25f), (_e1487 < 0f));
                                    phi_2393_ = 0f;
                                    loop {
                                        let _e1500 = phi_2388_;
                                        let _e1502 = phi_2391_;
                                        let _e1504 = phi_2393_;
                                        local_5 = _e1504;
                                        let _e1505 = (_e1500 < 32u);
                                        if _e1505 {
                                            let _e1506 = (_e1500 + 1u);
                                            let _e1510 = (_e1487 + (f32(bitcast<i32>(_e1506)) * 0.09817477f));
                                            let _e1511 = (_e1510 * 2f);
                                            let _e1516 = ((_e689 + (_e1511 * _e1489)) - cos((_e1511 - _e711)));
                                            let _e1520 = select((_e1516 * 0.25f), (_e1516 * -0.25f), (_e1510 < 0f));
                                            let _e1523 = local_4;
                                            phi_2389_ = _e1506;
                                            phi_2392_ = _e1520;
                                            phi_2394_ = select(_e1504, (_e1504 + (_e1520 - _e1502)), (((_e1523 >> bitcast<u32>((_e1500 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2389_ = u32();
                                            phi_2392_ = f32();
                                            phi_2394_ = f32();
                                        }
                                        let _e1532 = phi_2389_;
                                        let _e1534 = phi_2392_;
                                        let _e1536 = phi_2394_;
                                        continue;
                                        continuing {
                                            phi_2388_ = _e1532;
                                            phi_2391_ = _e1534;
                                            phi_2393_ = _e1536;
                                            break if !(_e1505);
                                        }
                                    }
                                    let _e1539 = local_5;
                                    phi_3135_ = _e606;
                                    phi_2495_ = (_e610 + 1f);
                                    phi_2496_ = (_e612 + ((_e670 + ((1f - _e670) * 0.05f)) * _e1539));
                                } else {
                                    if (_e152 == 1u) {
                                        phi_2440_ = 0u;
                                        phi_2443_ = 0f;
                                        loop {
                                            let _e1442 = phi_2440_;
                                            let _e1444 = phi_2443_;
                                            local_3 = _e1444;
                                            let _e1445 = (_e1442 < 4u);
                                            if _e1445 {
                                                local = array<type_26, 4>(type_26(4026531855u, 0.0095061f), type_26(251658480u, 0.0270951f), type_26(15732480u, 0.0405571f), type_26(1044480u, 0.0478421f));
                                                if _e1445 {
                                                } else {
                                                    phi_2943_ = true;
                                                    break;
                                                }
                                                let _e1448 = local[_e1442].member;
                                                let _e1451 = local[_e1442].member_1;
                                                let _e1453 = local_2;
                                                phi_2441_ = (_e1442 + 1u);
                                                phi_2444_ = (_e1444 + (f32(bitcast<i32>(countOneBits((_e1453 & _e1448)))) * _e1451));
                                            } else {
                                                phi_2441_ = u32();
                                                phi_2444_ = f32();
                                            }
                                            let _e1462 = phi_2441_;
                                            let _e1464 = phi_2444_;
                                            continue;
                                            continuing {
                                                phi_2440_ = _e1462;
                                                phi_2443_ = _e1464;
                                                phi_2943_ = _e606;
                                                break if !(_e1445);
                                            }
                                        }
                                        let _e1467 = phi_2943_;
                                        phi_3133_ = _e1467;
                                        if _e1467 {
                                            break;
                                        }
                                        let _e1469 = local_3;
                                        let _e1470 = (1f - _e1469);
                                        phi_3141_ = _e1467;
                                        phi_2493_ = (_e610 + _e670);
                                        phi_2494_ = (_e612 + (_e670 * select(0f, select(1f, _e1470, (_e1470 < 1f)), (_e1470 > 0f))));
                                    } else {
                                        let _e1432 = local_1;
                                        phi_3141_ = _e606;
                                        phi_2493_ = (_e610 + 1f);
                                        phi_2494_ = (_e612 + ((f32(bitcast<i32>(countOneBits((_e1432 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e1479 = phi_3141_;
                                    let _e1481 = phi_2493_;
                                    let _e1483 = phi_2494_;
                                    phi_3135_ = _e1479;
                                    phi_2495_ = _e1481;
                                    phi_2496_ = _e1483;
                                }
                                let _e1544 = phi_3135_;
                                let _e1546 = phi_2495_;
                                let _e1548 = phi_2496_;
                                phi_3134_ = _e1544;
                                phi_996_ = (_e608 + 1u);
                                phi_999_ = _e1546;
                                phi_1001_ = _e1548;
                            } else {
                                phi_3134_ = _e606;
                                phi_996_ = u32();
                                phi_999_ = f32();
                                phi_1001_ = f32();
                            }
                            let _e1551 = phi_3134_;
                            let _e1553 = phi_996_;
                            let _e1555 = phi_999_;
                            let _e1557 = phi_1001_;
                            continue;
                            continuing {
                                phi_3048_ = _e1551;
                                phi_995_ = _e1553;
                                phi_998_ = _e1555;
                                phi_1000_ = _e1557;
                                phi_3133_ = _e1551;
                                break if !(_e613);
                            }
                        }
                        let _e1560 = phi_3133_;
                        if _e1560 {
                            break;
                        }
                        let _e1562 = local_6;
                        let _e1565 = local_7;
                        let _e1567 = local_8;
                        phi_2504_ = select(1f, (_e1565 / _e1567), (_e1562 > 0f));
                    } else {
                        phi_2504_ = 1f;
                    }
                    let _e1571 = phi_2504_;
                    if _e601 {
                        let _e1577 = pow(_e1571, _e147.member_6);
                        if (_e1577 != _e1577) {
                            phi_2925_ = true;
                        } else {
                            phi_2925_ = (0.03f >= _e1577);
                        }
                        let _e1581 = phi_2925_;
                        let _e1583 = (select(_e1577, 0.03f, _e1581) * 0.6666667f);
                        phi_2545_ = (bitcast<u32>((floor(((select(0f, select(1f, _e1583, (_e1583 < 1f)), (_e1583 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                    } else {
                        phi_2545_ = (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u);
                    }
                    let _e1595 = phi_2545_;
                    terms.member[_e185] = _e1595;
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
