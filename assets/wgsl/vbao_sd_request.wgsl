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

struct type_24 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_25 {
    member: type_24,
    member_1: type_24,
    member_2: type_5,
}

struct type_26 {
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

struct type_27 {
    member: type_25,
    member_1: type_26,
}

struct type_29 {
    member: array<type_27>,
}

struct type_31 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
}

struct type_32 {
    member: type_31,
}

struct type_36 {
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
var<storage> frame: type_29;
@group(0) @binding(2) 
var<storage> normals: type_11;
@group(0) @binding(5) 
var<uniform> params: type_32;
@group(0) @binding(1) 
var<storage> mips: type_8;
@group(0) @binding(3) 
var<storage, read_write> ray_min: type_36;
@group(0) @binding(4) 
var<storage, read_write> ray_max: type_36;

fn function_() {
    var phi_203_: type_21;
    var phi_1961_: bool;
    var phi_865_: u32;
    var phi_1953_: bool;
    var phi_1031_: u32;
    var phi_1095_: f32;
    var phi_1096_: f32;
    var phi_1374_: bool;
    var phi_1498_: u32;
    var phi_1515_: u32;
    var phi_1522_: u32;
    var phi_1499_: u32;
    var phi_1909_: bool;
    var phi_1994_: bool;
    var phi_1578_: bool;
    var phi_1702_: u32;
    var phi_1719_: u32;
    var phi_1726_: u32;
    var phi_1703_: u32;
    var phi_1979_: bool;
    var phi_1997_: bool;
    var phi_1996_: bool;
    var phi_1032_: u32;
    var phi_1995_: bool;
    var phi_1999_: bool;
    var phi_866_: u32;
    var phi_1998_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e65 = id_1;
            let _e69 = arrayLength((&ray_min.member));
            let _e71 = arrayLength((&ray_max.member));
            if (override_type == 0u) {
                let _e75 = params.member.member_4;
                phi_203_ = _e75;
            } else {
                let _e85 = params.member.member_4.member;
                let _e89 = params.member.member_4.member_1;
                let _e93 = params.member.member_4.member_10;
                let _e97 = params.member.member_4.member_11;
                let _e101 = params.member.member_4.member_12;
                let _e105 = params.member.member_4.member_14;
                phi_203_ = type_21(_e85, _e89, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e93, _e97, _e101, override_type_9, _e105);
            }
            let _e108 = phi_203_;
            let _e111 = params.member.member_1;
            let _e119 = select(select(u32(_e108.member.member.x), 0u, (_e108.member.member.x < 0f)), 4294967295u, (_e108.member.member.x > 4294967000f));
            let _e127 = select(select(u32(_e108.member.member.y), 0u, (_e108.member.member.y < 0f)), 4294967295u, (_e108.member.member.y > 4294967000f));
            if (_e65.x >= _e119) {
            } else {
                if (_e65.y >= _e127) {
                } else {
                    if (0u < arrayLength((&frame.member))) {
                    } else {
                        break;
                    }
                    let _e134 = ((_e65.y * _e119) + _e65.x);
                    let _e137 = mips.member[_e134];
                    let _e141 = ((f32(bitcast<i32>(_e65.x)) + 0.5f) / _e108.member.member.x);
                    let _e145 = ((f32(bitcast<i32>(_e65.y)) + 0.5f) / _e108.member.member.y);
                    let _e146 = (_e137 * 0.99999f);
                    let _e153 = ((((_e141 * 2f) - 1f) * _e108.member.member_1.x) * _e146);
                    let _e160 = ((((_e145 * -2f) + 1f) * _e108.member.member_1.y) * _e146);
                    let _e161 = -(_e153);
                    let _e162 = -(_e160);
                    let _e163 = (_e137 * -0.99999f);
                    let _e170 = (1f / sqrt((((_e161 * _e161) + (_e162 * _e162)) + (_e163 * _e163))));
                    let _e176 = normals.member[_e134];
                    let _e179 = f32(bitcast<i32>((_e176 & 255u)));
                    let _e183 = (select(_e179, (_e179 - 256f), (_e179 >= 128f)) * 0.007874016f);
                    let _e186 = select(-1f, _e183, ((_e183 > -1f) || false));
                    let _e191 = f32(bitcast<i32>(((_e176 >> bitcast<u32>(8u)) & 255u)));
                    let _e195 = (select(_e191, (_e191 - 256f), (_e191 >= 128f)) * 0.007874016f);
                    let _e198 = select(-1f, _e195, ((_e195 > -1f) || false));
                    let _e200 = (1f - abs(_e186));
                    let _e201 = abs(_e198);
                    let _e202 = (_e200 - _e201);
                    let _e203 = (_e202 < 0f);
                    let _e211 = select(_e186, ((1f - _e201) * select(1f, -1f, (_e186 < 0f))), _e203);
                    let _e212 = select(_e198, (_e200 * select(1f, -1f, (_e198 < 0f))), _e203);
                    let _e219 = (1f / sqrt((((_e211 * _e211) + (_e212 * _e212)) + (_e202 * _e202))));
                    let _e220 = (_e211 * _e219);
                    let _e221 = (_e212 * _e219);
                    let _e222 = (_e202 * _e219);
                    let _e223 = -(_e222);
                    let _e229 = ((((_e220 * (_e161 * _e170)) + (_e221 * (_e162 * _e170))) + (_e223 * (_e163 * _e170))) < 0f);
                    let _e232 = select(_e220, -(_e220), _e229);
                    let _e233 = select(_e221, -(_e221), _e229);
                    let _e234 = select(_e223, _e222, _e229);
                    let _e237 = (_e108.member_1 * _e108.member_2);
                    let _e241 = (_e237 / (((_e137 * 1.99998f) * _e108.member.member_1.x) / _e108.member.member.x));
                    let _e244 = (_e65.x & 63u);
                    let _e245 = (_e65.y & 63u);
                    let _e248 = ((_e244 >> bitcast<u32>(5u)) & 1u);
                    let _e251 = ((_e245 >> bitcast<u32>(5u)) & 1u);
                    let _e255 = (_e251 ^ 1u);
                    let _e257 = ((_e248 & _e255) * 63u);
                    let _e258 = (_e244 ^ _e257);
                    let _e259 = (_e245 ^ _e257);
                    let _e261 = ((_e258 ^ _e259) * _e255);
                    let _e262 = (_e258 ^ _e261);
                    let _e263 = (_e259 ^ _e261);
                    let _e266 = ((_e262 >> bitcast<u32>(4u)) & 1u);
                    let _e269 = ((_e263 >> bitcast<u32>(4u)) & 1u);
                    let _e274 = (_e269 ^ 1u);
                    let _e276 = ((_e266 & _e274) * 63u);
                    let _e277 = (_e262 ^ _e276);
                    let _e278 = (_e263 ^ _e276);
                    let _e280 = ((_e277 ^ _e278) * _e274);
                    let _e281 = (_e277 ^ _e280);
                    let _e282 = (_e278 ^ _e280);
                    let _e285 = ((_e281 >> bitcast<u32>(3u)) & 1u);
                    let _e288 = ((_e282 >> bitcast<u32>(3u)) & 1u);
                    let _e293 = (_e288 ^ 1u);
                    let _e295 = ((_e285 & _e293) * 63u);
                    let _e296 = (_e281 ^ _e295);
                    let _e297 = (_e282 ^ _e295);
                    let _e299 = ((_e296 ^ _e297) * _e293);
                    let _e300 = (_e296 ^ _e299);
                    let _e301 = (_e297 ^ _e299);
                    let _e304 = ((_e300 >> bitcast<u32>(2u)) & 1u);
                    let _e307 = ((_e301 >> bitcast<u32>(2u)) & 1u);
                    let _e312 = (_e307 ^ 1u);
                    let _e314 = ((_e304 & _e312) * 63u);
                    let _e315 = (_e300 ^ _e314);
                    let _e316 = (_e301 ^ _e314);
                    let _e318 = ((_e315 ^ _e316) * _e312);
                    let _e319 = (_e315 ^ _e318);
                    let _e320 = (_e316 ^ _e318);
                    let _e323 = ((_e319 >> bitcast<u32>(1u)) & 1u);
                    let _e326 = ((_e320 >> bitcast<u32>(1u)) & 1u);
                    let _e331 = (_e326 ^ 1u);
                    let _e333 = ((_e323 & _e331) * 63u);
                    let _e334 = (_e319 ^ _e333);
                    let _e335 = (_e320 ^ _e333);
                    let _e337 = ((_e334 ^ _e335) * _e331);
                    let _e349 = f32(bitcast<i32>((((((((((_e248 * 3u) ^ _e251) * 1024u) + (((_e266 * 3u) ^ _e269) * 256u)) + (((_e285 * 3u) ^ _e288) * 64u)) + (((_e304 * 3u) ^ _e307) * 16u)) + (((_e323 * 3u) ^ _e326) * 4u)) + ((((_e334 ^ _e337) & 1u) * 3u) ^ ((_e335 ^ _e337) & 1u))) + (288u * (_e108.member_11 % 64u)))));
                    let _e351 = ((_e349 * 0.7548777f) + 0.5f);
                    let _e355 = ((_e349 * 0.5698403f) + 0.5f);
                    let _e361 = exp2(((2f * _e108.member_7) + 1f));
                    let _e366 = select(false, (_e137 < _e108.member.member_3), (_e137 > 0f));
                    if _e366 {
                        let _e367 = (_e111 > 0f);
                        let _e369 = (2f * select(_e237, _e111, _e367));
                        phi_1961_ = false;
                        phi_865_ = 0u;
                        loop {
                            let _e371 = phi_1961_;
                            let _e373 = phi_865_;
                            let _e376 = select(1u, _e108.member_8, (1u < _e108.member_8));
                            let _e377 = (_e373 < _e376);
                            if _e377 {
                                let _e384 = ((((_e351 - floor(_e351)) + f32(bitcast<i32>(_e373))) * 3.1415927f) / f32(bitcast<i32>(_e376)));
                                phi_1953_ = _e371;
                                phi_1031_ = 0u;
                                loop {
                                    let _e391 = phi_1953_;
                                    let _e393 = phi_1031_;
                                    let _e396 = select(1u, _e108.member_9, (1u < _e108.member_9));
                                    let _e397 = (_e393 < _e396);
                                    if _e397 {
                                        let _e403 = ((_e355 - floor(_e355)) + (f32(bitcast<i32>((_e373 + (_e393 * _e396)))) * 0.618034f));
                                        let _e412 = (((_e403 - floor(_e403)) + f32(bitcast<i32>(_e393))) * (1f / f32(bitcast<i32>(_e396))));
                                        if (_e108.member_4 == 2f) {
                                            phi_1096_ = (_e412 * _e412);
                                        } else {
                                            if (_e108.member_4 == 1f) {
                                                phi_1095_ = _e412;
                                            } else {
                                                phi_1095_ = pow(_e412, _e108.member_4);
                                            }
                                            let _e419 = phi_1095_;
                                            phi_1096_ = _e419;
                                        }
                                        let _e421 = phi_1096_;
                                        let _e422 = (_e421 + (1.3f / _e241));
                                        let _e423 = ((cos(_e384) * _e241) * _e422);
                                        let _e424 = ((-(sin(_e384)) * _e241) * _e422);
                                        let _e427 = ((_e423 * _e423) + (_e424 * _e424));
                                        let _e432 = (select(1u, _e119, (1u < _e119)) * select(1u, _e127, (1u < _e127)));
                                        let _e433 = (_e427 > _e361);
                                        let _e437 = (_e119 >> bitcast<u32>(1u));
                                        let _e441 = (_e127 >> bitcast<u32>(1u));
                                        let _e445 = (_e432 + (select(1u, _e437, (1u < _e437)) * select(1u, _e441, (1u < _e441))));
                                        let _e447 = (_e427 > (_e361 * 4f));
                                        let _e451 = (_e119 >> bitcast<u32>(2u));
                                        let _e455 = (_e127 >> bitcast<u32>(2u));
                                        let _e459 = (_e445 + (select(1u, _e451, (1u < _e451)) * select(1u, _e455, (1u < _e455))));
                                        let _e461 = (_e427 > (_e361 * 16f));
                                        let _e465 = (_e119 >> bitcast<u32>(3u));
                                        let _e469 = (_e127 >> bitcast<u32>(3u));
                                        let _e475 = (_e427 > (_e361 * 64f));
                                        let _e477 = select(select(select(select(0u, _e432, _e433), _e445, _e447), _e459, _e461), (_e459 + (select(1u, _e465, (1u < _e465)) * select(1u, _e469, (1u < _e469)))), _e475);
                                        let _e478 = (select(select(select(select(0u, 1u, _e433), 2u, _e447), 3u, _e461), 4u, _e475) & 31u);
                                        let _e480 = (_e119 >> bitcast<u32>(_e478));
                                        let _e482 = select(1u, _e480, (1u < _e480));
                                        let _e484 = (_e127 >> bitcast<u32>(_e478));
                                        let _e486 = select(1u, _e484, (1u < _e484));
                                        let _e489 = (round(_e423) * (1f / _e108.member.member.x));
                                        let _e492 = (round(_e424) * (1f / _e108.member.member.y));
                                        let _e493 = (_e141 + _e489);
                                        let _e494 = (_e145 + _e492);
                                        let _e495 = (_e141 - _e489);
                                        let _e496 = (_e145 - _e492);
                                        let _e498 = f32(bitcast<i32>(_e482));
                                        let _e499 = (_e493 * _e498);
                                        let _e502 = f32(bitcast<i32>((_e482 - 1u)));
                                        let _e512 = f32(bitcast<i32>(_e486));
                                        let _e513 = (_e494 * _e512);
                                        let _e516 = f32(bitcast<i32>((_e486 - 1u)));
                                        let _e530 = mips.member[((_e477 + ((bitcast<u32>((floor(select(0f, select(_e516, _e513, (_e513 < _e516)), (_e513 > 0f))) + 8388608f)) - 1258291200u) * _e482)) + (bitcast<u32>((floor(select(0f, select(_e502, _e499, (_e499 < _e502)), (_e499 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e534 = ((((_e493 * 2f) - 1f) * _e108.member.member_1.x) * _e530);
                                        let _e538 = ((((_e494 * -2f) + 1f) * _e108.member.member_1.y) * _e530);
                                        let _e539 = (_e495 * _e498);
                                        let _e548 = (_e496 * _e512);
                                        let _e562 = mips.member[((_e477 + ((bitcast<u32>((floor(select(0f, select(_e516, _e548, (_e548 < _e516)), (_e548 > 0f))) + 8388608f)) - 1258291200u) * _e482)) + (bitcast<u32>((floor(select(0f, select(_e502, _e539, (_e539 < _e502)), (_e539 > 0f))) + 8388608f)) - 1258291200u))];
                                        let _e566 = ((((_e495 * 2f) - 1f) * _e108.member.member_1.x) * _e562);
                                        let _e570 = ((((_e496 * -2f) + 1f) * _e108.member.member_1.y) * _e562);
                                        let _e571 = (_e534 - _e153);
                                        let _e572 = (_e538 - _e160);
                                        let _e573 = (_e530 - _e146);
                                        let _e578 = (((_e571 * _e571) + (_e572 * _e572)) + (_e573 * _e573));
                                        if _e367 {
                                            phi_1374_ = (_e578 <= (_e111 * _e111));
                                        } else {
                                            phi_1374_ = true;
                                        }
                                        let _e582 = phi_1374_;
                                        let _e592 = select(false, select(false, ((((_e571 * _e232) + (_e572 * _e233)) + (_e573 * _e234)) > (sqrt(_e578) * 0.018f)), _e582), _e366);
                                        if _e592 {
                                            let _e593 = (0.5f / _e530);
                                            let _e602 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e613 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e621 = frame.member[0u].member_1.member_5[0u];
                                            let _e627 = frame.member[0u].member_1.member_5[1u];
                                            let _e634 = frame.member[0u].member_1.member_4;
                                            let _e635 = f32(_e634);
                                            let _e636 = (2u * _e634);
                                            let _e637 = (_e621 + _e636);
                                            let _e641 = (floor(((((_e534 * _e593) / _e602) + 0.5f) * f32(_e621))) + _e635);
                                            let _e644 = f32(bitcast<i32>((_e637 - 1u)));
                                            let _e655 = (floor(((0.5f - ((_e538 * _e593) / _e613)) * f32(_e627))) + _e635);
                                            let _e658 = f32(bitcast<i32>(((_e627 + _e636) - 1u)));
                                            let _e668 = (((bitcast<u32>((floor(select(0f, select(_e658, _e655, (_e655 < _e658)), (_e655 > 0f))) + 8388608f)) - 1258291200u) * _e637) + (bitcast<u32>((floor(select(0f, select(_e644, _e641, (_e641 < _e644)), (_e641 > 0f))) + 8388608f)) - 1258291200u));
                                            let _e674 = sqrt((((_e534 * _e534) + (_e538 * _e538)) + (_e530 * _e530)));
                                            phi_1498_ = 0u;
                                            loop {
                                                let _e676 = phi_1498_;
                                                let _e677 = (_e676 < 1u);
                                                if _e677 {
                                                    if _e592 {
                                                        if (_e674 > 0f) {
                                                            phi_1515_ = bitcast<u32>(_e674);
                                                        } else {
                                                            phi_1515_ = 0u;
                                                        }
                                                        let _e681 = phi_1515_;
                                                        let _e682 = (_e674 + _e369);
                                                        if (_e682 > 0f) {
                                                            phi_1522_ = bitcast<u32>(_e682);
                                                        } else {
                                                            phi_1522_ = 0u;
                                                        }
                                                        let _e686 = phi_1522_;
                                                        let _e687 = (_e668 < _e69);
                                                        if _e687 {
                                                        } else {
                                                            phi_1909_ = true;
                                                            break;
                                                        }
                                                        let _e690 = atomicLoad((&ray_min.member[_e668]));
                                                        if (_e690 > _e681) {
                                                            if _e687 {
                                                            } else {
                                                                phi_1909_ = true;
                                                                break;
                                                            }
                                                            let _e692 = atomicMin((&ray_min.member[_e668]), _e681);
                                                        }
                                                        let _e693 = (_e668 < _e71);
                                                        if _e693 {
                                                        } else {
                                                            phi_1909_ = true;
                                                            break;
                                                        }
                                                        let _e696 = atomicLoad((&ray_max.member[_e668]));
                                                        if (_e696 < _e686) {
                                                            if _e693 {
                                                            } else {
                                                                phi_1909_ = true;
                                                                break;
                                                            }
                                                            let _e698 = atomicMax((&ray_max.member[_e668]), _e686);
                                                        }
                                                    }
                                                    phi_1499_ = (_e676 + 1u);
                                                } else {
                                                    phi_1499_ = u32();
                                                }
                                                let _e701 = phi_1499_;
                                                continue;
                                                continuing {
                                                    phi_1498_ = _e701;
                                                    phi_1909_ = _e391;
                                                    break if !(_e677);
                                                }
                                            }
                                            let _e704 = phi_1909_;
                                            phi_1995_ = _e704;
                                            if _e704 {
                                                break;
                                            }
                                            phi_1994_ = _e704;
                                        } else {
                                            phi_1994_ = _e391;
                                        }
                                        let _e706 = phi_1994_;
                                        let _e707 = (_e566 - _e153);
                                        let _e708 = (_e570 - _e160);
                                        let _e709 = (_e562 - _e146);
                                        let _e714 = (((_e707 * _e707) + (_e708 * _e708)) + (_e709 * _e709));
                                        if _e367 {
                                            phi_1578_ = (_e714 <= (_e111 * _e111));
                                        } else {
                                            phi_1578_ = true;
                                        }
                                        let _e718 = phi_1578_;
                                        let _e728 = select(false, select(false, ((((_e707 * _e232) + (_e708 * _e233)) + (_e709 * _e234)) > (sqrt(_e714) * 0.018f)), _e718), _e366);
                                        if _e728 {
                                            let _e729 = (0.5f / _e562);
                                            let _e738 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e749 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e757 = frame.member[0u].member_1.member_5[0u];
                                            let _e763 = frame.member[0u].member_1.member_5[1u];
                                            let _e770 = frame.member[0u].member_1.member_4;
                                            let _e771 = f32(_e770);
                                            let _e772 = (2u * _e770);
                                            let _e773 = (_e757 + _e772);
                                            let _e777 = (floor(((((_e566 * _e729) / _e738) + 0.5f) * f32(_e757))) + _e771);
                                            let _e780 = f32(bitcast<i32>((_e773 - 1u)));
                                            let _e791 = (floor(((0.5f - ((_e570 * _e729) / _e749)) * f32(_e763))) + _e771);
                                            let _e794 = f32(bitcast<i32>(((_e763 + _e772) - 1u)));
                                            let _e804 = (((bitcast<u32>((floor(select(0f, select(_e794, _e791, (_e791 < _e794)), (_e791 > 0f))) + 8388608f)) - 1258291200u) * _e773) + (bitcast<u32>((floor(select(0f, select(_e780, _e777, (_e777 < _e780)), (_e777 > 0f))) + 8388608f)) - 1258291200u));
                                            let _e810 = sqrt((((_e566 * _e566) + (_e570 * _e570)) + (_e562 * _e562)));
                                            phi_1702_ = 0u;
                                            loop {
                                                let _e812 = phi_1702_;
                                                let _e813 = (_e812 < 1u);
                                                if _e813 {
                                                    if _e728 {
                                                        if (_e810 > 0f) {
                                                            phi_1719_ = bitcast<u32>(_e810);
                                                        } else {
                                                            phi_1719_ = 0u;
                                                        }
                                                        let _e817 = phi_1719_;
                                                        let _e818 = (_e810 + _e369);
                                                        if (_e818 > 0f) {
                                                            phi_1726_ = bitcast<u32>(_e818);
                                                        } else {
                                                            phi_1726_ = 0u;
                                                        }
                                                        let _e822 = phi_1726_;
                                                        let _e823 = (_e804 < _e69);
                                                        if _e823 {
                                                        } else {
                                                            phi_1979_ = true;
                                                            break;
                                                        }
                                                        let _e826 = atomicLoad((&ray_min.member[_e804]));
                                                        if (_e826 > _e817) {
                                                            if _e823 {
                                                            } else {
                                                                phi_1979_ = true;
                                                                break;
                                                            }
                                                            let _e828 = atomicMin((&ray_min.member[_e804]), _e817);
                                                        }
                                                        let _e829 = (_e804 < _e71);
                                                        if _e829 {
                                                        } else {
                                                            phi_1979_ = true;
                                                            break;
                                                        }
                                                        let _e832 = atomicLoad((&ray_max.member[_e804]));
                                                        if (_e832 < _e822) {
                                                            if _e829 {
                                                            } else {
                                                                phi_1979_ = true;
                                                                break;
                                                            }
                                                            let _e834 = atomicMax((&ray_max.member[_e804]), _e822);
                                                        }
                                                    }
                                                    phi_1703_ = (_e812 + 1u);
                                                } else {
                                                    phi_1703_ = u32();
                                                }
                                                let _e837 = phi_1703_;
                                                continue;
                                                continuing {
                                                    phi_1702_ = _e837;
                                                    phi_1979_ = _e706;
                                                    break if !(_e813);
                                                }
                                            }
                                            let _e840 = phi_1979_;
                                            phi_1995_ = _e840;
                                            if _e840 {
                                                break;
                                            }
                                            phi_1997_ = _e840;
                                        } else {
                                            phi_1997_ = _e706;
                                        }
                                        let _e842 = phi_1997_;
                                        phi_1996_ = _e842;
                                        phi_1032_ = (_e393 + 1u);
                                    } else {
                                        phi_1996_ = _e391;
                                        phi_1032_ = u32();
                                    }
                                    let _e845 = phi_1996_;
                                    let _e847 = phi_1032_;
                                    continue;
                                    continuing {
                                        phi_1953_ = _e845;
                                        phi_1031_ = _e847;
                                        phi_1995_ = _e845;
                                        break if !(_e397);
                                    }
                                }
                                let _e850 = phi_1995_;
                                phi_1998_ = _e850;
                                if _e850 {
                                    break;
                                }
                                phi_1999_ = _e850;
                                phi_866_ = (_e373 + 1u);
                            } else {
                                phi_1999_ = _e371;
                                phi_866_ = u32();
                            }
                            let _e853 = phi_1999_;
                            let _e855 = phi_866_;
                            continue;
                            continuing {
                                phi_1961_ = _e853;
                                phi_865_ = _e855;
                                phi_1998_ = _e853;
                                break if !(_e377);
                            }
                        }
                        let _e858 = phi_1998_;
                        if _e858 {
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
