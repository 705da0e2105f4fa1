struct type_5 {
    member: vec2<f32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_6 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
}

struct type_8 {
    member: array<f32>,
}

struct type_11 {
    member: array<u32>,
}

struct type_22 {
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

struct type_25 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_26 {
    member: type_25,
    member_1: type_25,
    member_2: type_5,
}

struct type_27 {
    member: type_6,
    member_1: u32,
    member_2: u32,
    member_3: f32,
    member_4: u32,
    member_5: vec2<u32>,
    member_6: u32,
    member_7: u32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: u32,
    member_12: u32,
    member_13: u32,
    member_14: u32,
    member_15: u32,
}

struct type_28 {
    member: type_26,
    member_1: type_27,
}

struct type_30 {
    member: array<type_28>,
}

struct type_32 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_22,
}

struct type_33 {
    member: type_32,
}

struct type_38 {
    member: array<atomic<u32>>,
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

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> frame: type_30;
@group(0) @binding(2) 
var<storage> normals: type_11;
@group(0) @binding(5) 
var<uniform> params: type_33;
@group(0) @binding(1) 
var<storage> mips: type_8;
@group(0) @binding(3) 
var<storage, read_write> ray_min: type_38;
@group(0) @binding(4) 
var<storage, read_write> ray_max: type_38;

fn function_() {
    var phi_205_: type_22;
    var phi_1766_: bool;
    var phi_867_: u32;
    var phi_1758_: bool;
    var phi_1033_: u32;
    var phi_1097_: f32;
    var phi_1098_: f32;
    var phi_1361_: i32;
    var phi_1399_: bool;
    var phi_1415_: bool;
    var phi_1536_: u32;
    var phi_1543_: u32;
    var phi_1362_: i32;
    var phi_1714_: bool;
    var phi_1785_: bool;
    var phi_1034_: u32;
    var phi_1784_: bool;
    var phi_1787_: bool;
    var phi_868_: u32;
    var phi_1786_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e69 = id_1;
            if (override_type == 0u) {
                let _e79 = params.member.member_4;
                phi_205_ = _e79;
            } else {
                let _e89 = params.member.member_4.member;
                let _e93 = params.member.member_4.member_1;
                let _e97 = params.member.member_4.member_10;
                let _e101 = params.member.member_4.member_11;
                let _e105 = params.member.member_4.member_12;
                let _e109 = params.member.member_4.member_14;
                phi_205_ = type_22(_e89, _e93, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e97, _e101, _e105, override_type_9, _e109);
            }
            let _e112 = phi_205_;
            let _e115 = params.member.member_1;
            let _e123 = select(select(u32(_e112.member.member.x), 0u, (_e112.member.member.x < 0f)), 4294967295u, (_e112.member.member.x > 4294967000f));
            let _e131 = select(select(u32(_e112.member.member.y), 0u, (_e112.member.member.y < 0f)), 4294967295u, (_e112.member.member.y > 4294967000f));
            if (_e69.x >= _e123) {
            } else {
                if (_e69.y >= _e131) {
                } else {
                    if (0u < arrayLength((&frame.member))) {
                    } else {
                        break;
                    }
                    let _e138 = ((_e69.y * _e123) + _e69.x);
                    let _e141 = mips.member[_e138];
                    let _e145 = ((f32(bitcast<i32>(_e69.x)) + 0.5f) / _e112.member.member.x);
                    let _e149 = ((f32(bitcast<i32>(_e69.y)) + 0.5f) / _e112.member.member.y);
                    let _e150 = (_e141 * 0.99999f);
                    let _e157 = ((((_e145 * 2f) - 1f) * _e112.member.member_1.x) * _e150);
                    let _e164 = ((((_e149 * -2f) + 1f) * _e112.member.member_1.y) * _e150);
                    let _e165 = -(_e157);
                    let _e166 = -(_e164);
                    let _e167 = (_e141 * -0.99999f);
                    let _e174 = (1f / sqrt((((_e165 * _e165) + (_e166 * _e166)) + (_e167 * _e167))));
                    let _e180 = normals.member[_e138];
                    let _e183 = f32(bitcast<i32>((_e180 & 255u)));
                    let _e187 = (select(_e183, (_e183 - 256f), (_e183 >= 128f)) * 0.007874016f);
                    let _e190 = select(-1f, _e187, ((_e187 > -1f) || false));
                    let _e195 = f32(bitcast<i32>(((_e180 >> bitcast<u32>(8u)) & 255u)));
                    let _e199 = (select(_e195, (_e195 - 256f), (_e195 >= 128f)) * 0.007874016f);
                    let _e202 = select(-1f, _e199, ((_e199 > -1f) || false));
                    let _e204 = (1f - abs(_e190));
                    let _e205 = abs(_e202);
                    let _e206 = (_e204 - _e205);
                    let _e207 = (_e206 < 0f);
                    let _e215 = select(_e190, ((1f - _e205) * select(1f, -1f, (_e190 < 0f))), _e207);
                    let _e216 = select(_e202, (_e204 * select(1f, -1f, (_e202 < 0f))), _e207);
                    let _e223 = (1f / sqrt((((_e215 * _e215) + (_e216 * _e216)) + (_e206 * _e206))));
                    let _e224 = (_e215 * _e223);
                    let _e225 = (_e216 * _e223);
                    let _e226 = (_e206 * _e223);
                    let _e227 = -(_e226);
                    let _e233 = ((((_e224 * (_e165 * _e174)) + (_e225 * (_e166 * _e174))) + (_e227 * (_e167 * _e174))) < 0f);
                    let _e241 = (_e112.member_1 * _e112.member_2);
                    let _e245 = (_e241 / (((_e141 * 1.99998f) * _e112.member.member_1.x) / _e112.member.member.x));
                    let _e248 = (_e69.x & 63u);
                    let _e249 = (_e69.y & 63u);
                    let _e252 = ((_e248 >> bitcast<u32>(5u)) & 1u);
                    let _e255 = ((_e249 >> bitcast<u32>(5u)) & 1u);
                    let _e259 = (_e255 ^ 1u);
                    let _e261 = ((_e252 & _e259) * 63u);
                    let _e262 = (_e248 ^ _e261);
                    let _e263 = (_e249 ^ _e261);
                    let _e265 = ((_e262 ^ _e263) * _e259);
                    let _e266 = (_e262 ^ _e265);
                    let _e267 = (_e263 ^ _e265);
                    let _e270 = ((_e266 >> bitcast<u32>(4u)) & 1u);
                    let _e273 = ((_e267 >> bitcast<u32>(4u)) & 1u);
                    let _e278 = (_e273 ^ 1u);
                    let _e280 = ((_e270 & _e278) * 63u);
                    let _e281 = (_e266 ^ _e280);
                    let _e282 = (_e267 ^ _e280);
                    let _e284 = ((_e281 ^ _e282) * _e278);
                    let _e285 = (_e281 ^ _e284);
                    let _e286 = (_e282 ^ _e284);
                    let _e289 = ((_e285 >> bitcast<u32>(3u)) & 1u);
                    let _e292 = ((_e286 >> bitcast<u32>(3u)) & 1u);
                    let _e297 = (_e292 ^ 1u);
                    let _e299 = ((_e289 & _e297) * 63u);
                    let _e300 = (_e285 ^ _e299);
                    let _e301 = (_e286 ^ _e299);
                    let _e303 = ((_e300 ^ _e301) * _e297);
                    let _e304 = (_e300 ^ _e303);
                    let _e305 = (_e301 ^ _e303);
                    let _e308 = ((_e304 >> bitcast<u32>(2u)) & 1u);
                    let _e311 = ((_e305 >> bitcast<u32>(2u)) & 1u);
                    let _e316 = (_e311 ^ 1u);
                    let _e318 = ((_e308 & _e316) * 63u);
                    let _e319 = (_e304 ^ _e318);
                    let _e320 = (_e305 ^ _e318);
                    let _e322 = ((_e319 ^ _e320) * _e316);
                    let _e323 = (_e319 ^ _e322);
                    let _e324 = (_e320 ^ _e322);
                    let _e327 = ((_e323 >> bitcast<u32>(1u)) & 1u);
                    let _e330 = ((_e324 >> bitcast<u32>(1u)) & 1u);
                    let _e335 = (_e330 ^ 1u);
                    let _e337 = ((_e327 & _e335) * 63u);
                    let _e338 = (_e323 ^ _e337);
                    let _e339 = (_e324 ^ _e337);
                    let _e341 = ((_e338 ^ _e339) * _e335);
                    let _e353 = f32(bitcast<i32>((((((((((_e252 * 3u) ^ _e255) * 1024u) + (((_e270 * 3u) ^ _e273) * 256u)) + (((_e289 * 3u) ^ _e292) * 64u)) + (((_e308 * 3u) ^ _e311) * 16u)) + (((_e327 * 3u) ^ _e330) * 4u)) + ((((_e338 ^ _e341) & 1u) * 3u) ^ ((_e339 ^ _e341) & 1u))) + (288u * (_e112.member_11 % 64u)))));
                    let _e355 = ((_e353 * 0.7548777f) + 0.5f);
                    let _e359 = ((_e353 * 0.5698403f) + 0.5f);
                    let _e365 = exp2(((2f * _e112.member_7) + 1f));
                    if select(false, (_e141 < _e112.member.member_3), (_e141 > 0f)) {
                        phi_1766_ = false;
                        phi_867_ = 0u;
                        loop {
                            let _e375 = phi_1766_;
                            let _e377 = phi_867_;
                            let _e380 = select(1u, _e112.member_8, (1u < _e112.member_8));
                            let _e381 = (_e377 < _e380);
                            if _e381 {
                                let _e388 = ((((_e355 - floor(_e355)) + f32(bitcast<i32>(_e377))) * 3.1415927f) / f32(bitcast<i32>(_e380)));
                                phi_1758_ = _e375;
                                phi_1033_ = 0u;
                                loop {
                                    let _e395 = phi_1758_;
                                    let _e397 = phi_1033_;
                                    let _e400 = select(1u, _e112.member_9, (1u < _e112.member_9));
                                    let _e401 = (_e397 < _e400);
                                    if _e401 {
                                        let _e407 = ((_e359 - floor(_e359)) + (f32(bitcast<i32>((_e377 + (_e397 * _e400)))) * 0.618034f));
                                        let _e416 = (((_e407 - floor(_e407)) + f32(bitcast<i32>(_e397))) * (1f / f32(bitcast<i32>(_e400))));
                                        if (_e112.member_4 == 2f) {
                                            phi_1098_ = (_e416 * _e416);
                                        } else {
                                            if (_e112.member_4 == 1f) {
                                                phi_1097_ = _e416;
                                            } else {
                                                phi_1097_ = pow(_e416, _e112.member_4);
                                            }
                                            let _e423 = phi_1097_;
                                            phi_1098_ = _e423;
                                        }
                                        let _e425 = phi_1098_;
                                        let _e426 = (_e425 + (1.3f / _e245));
                                        let _e427 = ((cos(_e388) * _e245) * _e426);
                                        let _e428 = ((-(sin(_e388)) * _e245) * _e426);
                                        let _e431 = ((_e427 * _e427) + (_e428 * _e428));
                                        let _e436 = (select(1u, _e123, (1u < _e123)) * select(1u, _e131, (1u < _e131)));
                                        let _e437 = (_e431 > _e365);
                                        let _e441 = (_e123 >> bitcast<u32>(1u));
                                        let _e445 = (_e131 >> bitcast<u32>(1u));
                                        let _e449 = (_e436 + (select(1u, _e441, (1u < _e441)) * select(1u, _e445, (1u < _e445))));
                                        let _e451 = (_e431 > (_e365 * 4f));
                                        let _e455 = (_e123 >> bitcast<u32>(2u));
                                        let _e459 = (_e131 >> bitcast<u32>(2u));
                                        let _e463 = (_e449 + (select(1u, _e455, (1u < _e455)) * select(1u, _e459, (1u < _e459))));
                                        let _e465 = (_e431 > (_e365 * 16f));
                                        let _e469 = (_e123 >> bitcast<u32>(3u));
                                        let _e473 = (_e131 >> bitcast<u32>(3u));
                                        let _e479 = (_e431 > (_e365 * 64f));
                                        let _e481 = select(select(select(select(0u, _e436, _e437), _e449, _e451), _e463, _e465), (_e463 + (select(1u, _e469, (1u < _e469)) * select(1u, _e473, (1u < _e473)))), _e479);
                                        let _e482 = (select(select(select(select(0u, 1u, _e437), 2u, _e451), 3u, _e465), 4u, _e479) & 31u);
                                        let _e484 = (_e123 >> bitcast<u32>(_e482));
                                        let _e486 = select(1u, _e484, (1u < _e484));
                                        let _e488 = (_e131 >> bitcast<u32>(_e482));
                                        let _e490 = select(1u, _e488, (1u < _e488));
                                        let _e493 = (round(_e427) * (1f / _e112.member.member.x));
                                        let _e496 = (round(_e428) * (1f / _e112.member.member.y));
                                        let _e497 = (_e145 + _e493);
                                        let _e498 = (_e149 + _e496);
                                        let _e499 = (_e145 - _e493);
                                        let _e500 = (_e149 - _e496);
                                        let _e502 = f32(bitcast<i32>(_e486));
                                        let _e503 = (_e497 * _e502);
                                        let _e506 = f32(bitcast<i32>((_e486 - 1u)));
                                        let _e516 = f32(bitcast<i32>(_e490));
                                        let _e517 = (_e498 * _e516);
                                        let _e520 = f32(bitcast<i32>((_e490 - 1u)));
                                        let _e534 = mips.member[((_e481 + ((bitcast<u32>((floor(select(0f, select(_e520, _e517, (_e517 < _e520)), (_e517 > 0f))) + 8388608f)) - 1258291200u) * _e486)) + (bitcast<u32>((floor(select(0f, select(_e506, _e503, (_e503 < _e506)), (_e503 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e544 = (_e499 * _e502);
                                        let _e553 = (_e500 * _e516);
                                        let _e567 = mips.member[((_e481 + ((bitcast<u32>((floor(select(0f, select(_e520, _e553, (_e553 < _e520)), (_e553 > 0f))) + 8388608f)) - 1258291200u) * _e486)) + (bitcast<u32>((floor(select(0f, select(_e506, _e544, (_e544 < _e506)), (_e544 > 0f))) + 8388608f)) - 1258291200u))];
                                        phi_1361_ = 0i;
                                        loop {
                                            let _e578 = phi_1361_;
                                            let _e579 = (_e578 < 2i);
                                            if _e579 {
                                                let _e582 = select(vec3<f32>(((((_e499 * 2f) - 1f) * _e112.member.member_1.x) * _e567), ((((_e500 * -2f) + 1f) * _e112.member.member_1.y) * _e567), _e567), vec3<f32>(((((_e497 * 2f) - 1f) * _e112.member.member_1.x) * _e534), ((((_e498 * -2f) + 1f) * _e112.member.member_1.y) * _e534), _e534), vec3((_e578 == 0i)));
                                                let _e584 = (_e582.x - _e157);
                                                let _e586 = (_e582.y - _e164);
                                                let _e588 = (_e582.z - _e150);
                                                let _e593 = (((_e584 * _e584) + (_e586 * _e586)) + (_e588 * _e588));
                                                if (_e115 <= 0f) {
                                                    phi_1399_ = true;
                                                } else {
                                                    phi_1399_ = (_e593 <= (_e115 * _e115));
                                                }
                                                let _e598 = phi_1399_;
                                                if _e598 {
                                                    phi_1415_ = ((((_e584 * select(_e224, -(_e224), _e233)) + (_e586 * select(_e225, -(_e225), _e233))) + (_e588 * select(_e227, _e226, _e233))) > (0.018f * sqrt(_e593)));
                                                } else {
                                                    phi_1415_ = false;
                                                }
                                                let _e608 = phi_1415_;
                                                if _e608 {
                                                    let _e609 = (0.5f / _e582.z);
                                                    let _e618 = frame.member[0u].member_1.member.member.member_1[0u];
                                                    let _e629 = frame.member[0u].member_1.member.member.member_1[1u];
                                                    let _e637 = frame.member[0u].member_1.member_5[0u];
                                                    let _e643 = frame.member[0u].member_1.member_5[1u];
                                                    let _e650 = frame.member[0u].member_1.member_4;
                                                    let _e651 = f32(_e650);
                                                    let _e652 = (2u * _e650);
                                                    let _e653 = (_e637 + _e652);
                                                    let _e659 = (floor(((((_e582.x * _e609) / _e618) + 0.5f) * f32(_e637))) + _e651);
                                                    let _e660 = f32((_e653 - 1u));
                                                    let _e664 = select(0f, select(_e660, _e659, (_e659 < _e660)), (_e659 > 0f));
                                                    let _e667 = (floor(((0.5f - ((_e582.y * _e609) / _e629)) * f32(_e643))) + _e651);
                                                    let _e668 = f32(((_e643 + _e652) - 1u));
                                                    let _e672 = select(0f, select(_e668, _e667, (_e667 < _e668)), (_e667 > 0f));
                                                    let _e684 = ((select(select(u32(_e672), 0u, (_e672 < 0f)), 4294967295u, (_e672 > 4294967000f)) * _e653) + select(select(u32(_e664), 0u, (_e664 < 0f)), 4294967295u, (_e664 > 4294967000f)));
                                                    let _e690 = sqrt((((_e582.x * _e582.x) + (_e582.y * _e582.y)) + (_e582.z * _e582.z)));
                                                    if (_e690 > 0f) {
                                                        phi_1536_ = bitcast<u32>(_e690);
                                                    } else {
                                                        phi_1536_ = 0u;
                                                    }
                                                    let _e694 = phi_1536_;
                                                    let _e695 = (_e690 + (2f * select(_e241, _e115, (_e115 > 0f))));
                                                    if (_e695 > 0f) {
                                                        phi_1543_ = bitcast<u32>(_e695);
                                                    } else {
                                                        phi_1543_ = 0u;
                                                    }
                                                    let _e699 = phi_1543_;
                                                    let _e702 = atomicLoad((&ray_min.member[_e684]));
                                                    if (_e702 > _e694) {
                                                        if (_e684 < arrayLength((&ray_min.member))) {
                                                        } else {
                                                            phi_1714_ = true;
                                                            break;
                                                        }
                                                        let _e707 = atomicMin((&ray_min.member[_e684]), _e694);
                                                    }
                                                    let _e710 = atomicLoad((&ray_max.member[_e684]));
                                                    if (_e710 < _e699) {
                                                        if (_e684 < arrayLength((&ray_max.member))) {
                                                        } else {
                                                            phi_1714_ = true;
                                                            break;
                                                        }
                                                        let _e715 = atomicMax((&ray_max.member[_e684]), _e699);
                                                    }
                                                }
                                                phi_1362_ = (_e578 + 1i);
                                            } else {
                                                phi_1362_ = i32();
                                            }
                                            let _e718 = phi_1362_;
                                            continue;
                                            continuing {
                                                phi_1361_ = _e718;
                                                phi_1714_ = _e395;
                                                break if !(_e579);
                                            }
                                        }
                                        let _e721 = phi_1714_;
                                        phi_1784_ = _e721;
                                        if _e721 {
                                            break;
                                        }
                                        phi_1785_ = _e721;
                                        phi_1034_ = (_e397 + 1u);
                                    } else {
                                        phi_1785_ = _e395;
                                        phi_1034_ = u32();
                                    }
                                    let _e724 = phi_1785_;
                                    let _e726 = phi_1034_;
                                    continue;
                                    continuing {
                                        phi_1758_ = _e724;
                                        phi_1033_ = _e726;
                                        phi_1784_ = _e724;
                                        break if !(_e401);
                                    }
                                }
                                let _e729 = phi_1784_;
                                phi_1786_ = _e729;
                                if _e729 {
                                    break;
                                }
                                phi_1787_ = _e729;
                                phi_868_ = (_e377 + 1u);
                            } else {
                                phi_1787_ = _e375;
                                phi_868_ = u32();
                            }
                            let _e732 = phi_1787_;
                            let _e734 = phi_868_;
                            continue;
                            continuing {
                                phi_1766_ = _e732;
                                phi_867_ = _e734;
                                phi_1786_ = _e732;
                                break if !(_e381);
                            }
                        }
                        let _e737 = phi_1786_;
                        if _e737 {
                            break;
                        }
                    }
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vbao_sd_request(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
