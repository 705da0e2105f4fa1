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
    var phi_202_: type_21;
    var phi_1973_: bool;
    var phi_864_: u32;
    var phi_1965_: bool;
    var phi_1030_: u32;
    var phi_1094_: f32;
    var phi_1095_: f32;
    var phi_1390_: bool;
    var phi_1503_: u32;
    var phi_1520_: u32;
    var phi_1527_: u32;
    var phi_1504_: u32;
    var phi_1921_: bool;
    var phi_2006_: bool;
    var phi_1600_: bool;
    var phi_1713_: u32;
    var phi_1730_: u32;
    var phi_1737_: u32;
    var phi_1714_: u32;
    var phi_1991_: bool;
    var phi_2009_: bool;
    var phi_2008_: bool;
    var phi_1031_: u32;
    var phi_2007_: bool;
    var phi_2011_: bool;
    var phi_865_: u32;
    var phi_2010_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e65 = id_1;
            let _e69 = arrayLength((&ray_min.member));
            let _e71 = arrayLength((&ray_max.member));
            if (override_type == 0u) {
                let _e75 = params.member.member_4;
                phi_202_ = _e75;
            } else {
                let _e85 = params.member.member_4.member;
                let _e89 = params.member.member_4.member_1;
                let _e93 = params.member.member_4.member_10;
                let _e97 = params.member.member_4.member_11;
                let _e101 = params.member.member_4.member_12;
                let _e105 = params.member.member_4.member_14;
                phi_202_ = type_21(_e85, _e89, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e93, _e97, _e101, override_type_9, _e105);
            }
            let _e108 = phi_202_;
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
                        phi_1973_ = false;
                        phi_864_ = 0u;
                        loop {
                            let _e371 = phi_1973_;
                            let _e373 = phi_864_;
                            let _e376 = select(1u, _e108.member_8, (1u < _e108.member_8));
                            let _e377 = (_e373 < _e376);
                            if _e377 {
                                let _e384 = ((((_e351 - floor(_e351)) + f32(bitcast<i32>(_e373))) * 3.1415927f) / f32(bitcast<i32>(_e376)));
                                phi_1965_ = _e371;
                                phi_1030_ = 0u;
                                loop {
                                    let _e391 = phi_1965_;
                                    let _e393 = phi_1030_;
                                    let _e396 = select(1u, _e108.member_9, (1u < _e108.member_9));
                                    let _e397 = (_e393 < _e396);
                                    if _e397 {
                                        let _e403 = ((_e355 - floor(_e355)) + (f32(bitcast<i32>((_e373 + (_e393 * _e396)))) * 0.618034f));
                                        let _e412 = (((_e403 - floor(_e403)) + f32(bitcast<i32>(_e393))) * (1f / f32(bitcast<i32>(_e396))));
                                        if (_e108.member_4 == 2f) {
                                            phi_1095_ = (_e412 * _e412);
                                        } else {
                                            if (_e108.member_4 == 1f) {
                                                phi_1094_ = _e412;
                                            } else {
                                                phi_1094_ = pow(_e412, _e108.member_4);
                                            }
                                            let _e419 = phi_1094_;
                                            phi_1095_ = _e419;
                                        }
                                        let _e421 = phi_1095_;
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
                                        let _e583 = (((_e571 * _e571) + (_e572 * _e572)) + (_e573 * _e573));
                                        if _e367 {
                                            phi_1390_ = (_e583 > (_e111 * _e111));
                                        } else {
                                            phi_1390_ = false;
                                        }
                                        let _e590 = phi_1390_;
                                        let _e593 = select(false, select(false, ((((_e571 * _e232) + (_e572 * _e233)) + (_e573 * _e234)) > (sqrt(_e583) * 0.018f)), !(_e590)), _e366);
                                        if _e593 {
                                            let _e594 = (0.5f / _e530);
                                            let _e603 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e614 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e622 = frame.member[0u].member_1.member_5[0u];
                                            let _e628 = frame.member[0u].member_1.member_5[1u];
                                            let _e635 = frame.member[0u].member_1.member_4;
                                            let _e636 = f32(_e635);
                                            let _e637 = (2u * _e635);
                                            let _e638 = (_e622 + _e637);
                                            let _e642 = (floor(((((_e534 * _e594) / _e603) + 0.5f) * f32(_e622))) + _e636);
                                            let _e645 = f32(bitcast<i32>((_e638 - 1u)));
                                            let _e656 = (floor(((0.5f - ((_e538 * _e594) / _e614)) * f32(_e628))) + _e636);
                                            let _e659 = f32(bitcast<i32>(((_e628 + _e637) - 1u)));
                                            let _e669 = (((bitcast<u32>((floor(select(0f, select(_e659, _e656, (_e656 < _e659)), (_e656 > 0f))) + 8388608f)) - 1258291200u) * _e638) + (bitcast<u32>((floor(select(0f, select(_e645, _e642, (_e642 < _e645)), (_e642 > 0f))) + 8388608f)) - 1258291200u));
                                            let _e675 = sqrt((((_e534 * _e534) + (_e538 * _e538)) + (_e530 * _e530)));
                                            phi_1503_ = 0u;
                                            loop {
                                                let _e677 = phi_1503_;
                                                let _e678 = (_e677 < 1u);
                                                if _e678 {
                                                    if _e593 {
                                                        if (_e675 > 0f) {
                                                            phi_1520_ = bitcast<u32>(_e675);
                                                        } else {
                                                            phi_1520_ = 0u;
                                                        }
                                                        let _e682 = phi_1520_;
                                                        let _e683 = (_e675 + _e369);
                                                        if (_e683 > 0f) {
                                                            phi_1527_ = bitcast<u32>(_e683);
                                                        } else {
                                                            phi_1527_ = 0u;
                                                        }
                                                        let _e687 = phi_1527_;
                                                        let _e688 = (_e669 < _e69);
                                                        if _e688 {
                                                        } else {
                                                            phi_1921_ = true;
                                                            break;
                                                        }
                                                        let _e691 = atomicLoad((&ray_min.member[_e669]));
                                                        if (_e691 > _e682) {
                                                            if _e688 {
                                                            } else {
                                                                phi_1921_ = true;
                                                                break;
                                                            }
                                                            let _e693 = atomicMin((&ray_min.member[_e669]), _e682);
                                                        }
                                                        let _e694 = (_e669 < _e71);
                                                        if _e694 {
                                                        } else {
                                                            phi_1921_ = true;
                                                            break;
                                                        }
                                                        let _e697 = atomicLoad((&ray_max.member[_e669]));
                                                        if (_e697 < _e687) {
                                                            if _e694 {
                                                            } else {
                                                                phi_1921_ = true;
                                                                break;
                                                            }
                                                            let _e699 = atomicMax((&ray_max.member[_e669]), _e687);
                                                        }
                                                    }
                                                    phi_1504_ = (_e677 + 1u);
                                                } else {
                                                    phi_1504_ = u32();
                                                }
                                                let _e702 = phi_1504_;
                                                continue;
                                                continuing {
                                                    phi_1503_ = _e702;
                                                    phi_1921_ = _e391;
                                                    break if !(_e678);
                                                }
                                            }
                                            let _e705 = phi_1921_;
                                            phi_2007_ = _e705;
                                            if _e705 {
                                                break;
                                            }
                                            phi_2006_ = _e705;
                                        } else {
                                            phi_2006_ = _e391;
                                        }
                                        let _e707 = phi_2006_;
                                        let _e708 = (_e566 - _e153);
                                        let _e709 = (_e570 - _e160);
                                        let _e710 = (_e562 - _e146);
                                        let _e720 = (((_e708 * _e708) + (_e709 * _e709)) + (_e710 * _e710));
                                        if _e367 {
                                            phi_1600_ = (_e720 > (_e111 * _e111));
                                        } else {
                                            phi_1600_ = false;
                                        }
                                        let _e727 = phi_1600_;
                                        let _e730 = select(false, select(false, ((((_e708 * _e232) + (_e709 * _e233)) + (_e710 * _e234)) > (sqrt(_e720) * 0.018f)), !(_e727)), _e366);
                                        if _e730 {
                                            let _e731 = (0.5f / _e562);
                                            let _e740 = frame.member[0u].member_1.member.member.member_1[0u];
                                            let _e751 = frame.member[0u].member_1.member.member.member_1[1u];
                                            let _e759 = frame.member[0u].member_1.member_5[0u];
                                            let _e765 = frame.member[0u].member_1.member_5[1u];
                                            let _e772 = frame.member[0u].member_1.member_4;
                                            let _e773 = f32(_e772);
                                            let _e774 = (2u * _e772);
                                            let _e775 = (_e759 + _e774);
                                            let _e779 = (floor(((((_e566 * _e731) / _e740) + 0.5f) * f32(_e759))) + _e773);
                                            let _e782 = f32(bitcast<i32>((_e775 - 1u)));
                                            let _e793 = (floor(((0.5f - ((_e570 * _e731) / _e751)) * f32(_e765))) + _e773);
                                            let _e796 = f32(bitcast<i32>(((_e765 + _e774) - 1u)));
                                            let _e806 = (((bitcast<u32>((floor(select(0f, select(_e796, _e793, (_e793 < _e796)), (_e793 > 0f))) + 8388608f)) - 1258291200u) * _e775) + (bitcast<u32>((floor(select(0f, select(_e782, _e779, (_e779 < _e782)), (_e779 > 0f))) + 8388608f)) - 1258291200u));
                                            let _e812 = sqrt((((_e566 * _e566) + (_e570 * _e570)) + (_e562 * _e562)));
                                            phi_1713_ = 0u;
                                            loop {
                                                let _e814 = phi_1713_;
                                                let _e815 = (_e814 < 1u);
                                                if _e815 {
                                                    if _e730 {
                                                        if (_e812 > 0f) {
                                                            phi_1730_ = bitcast<u32>(_e812);
                                                        } else {
                                                            phi_1730_ = 0u;
                                                        }
                                                        let _e819 = phi_1730_;
                                                        let _e820 = (_e812 + _e369);
                                                        if (_e820 > 0f) {
                                                            phi_1737_ = bitcast<u32>(_e820);
                                                        } else {
                                                            phi_1737_ = 0u;
                                                        }
                                                        let _e824 = phi_1737_;
                                                        let _e825 = (_e806 < _e69);
                                                        if _e825 {
                                                        } else {
                                                            phi_1991_ = true;
                                                            break;
                                                        }
                                                        let _e828 = atomicLoad((&ray_min.member[_e806]));
                                                        if (_e828 > _e819) {
                                                            if _e825 {
                                                            } else {
                                                                phi_1991_ = true;
                                                                break;
                                                            }
                                                            let _e830 = atomicMin((&ray_min.member[_e806]), _e819);
                                                        }
                                                        let _e831 = (_e806 < _e71);
                                                        if _e831 {
                                                        } else {
                                                            phi_1991_ = true;
                                                            break;
                                                        }
                                                        let _e834 = atomicLoad((&ray_max.member[_e806]));
                                                        if (_e834 < _e824) {
                                                            if _e831 {
                                                            } else {
                                                                phi_1991_ = true;
                                                                break;
                                                            }
                                                            let _e836 = atomicMax((&ray_max.member[_e806]), _e824);
                                                        }
                                                    }
                                                    phi_1714_ = (_e814 + 1u);
                                                } else {
                                                    phi_1714_ = u32();
                                                }
                                                let _e839 = phi_1714_;
                                                continue;
                                                continuing {
                                                    phi_1713_ = _e839;
                                                    phi_1991_ = _e707;
                                                    break if !(_e815);
                                                }
                                            }
                                            let _e842 = phi_1991_;
                                            phi_2007_ = _e842;
                                            if _e842 {
                                                break;
                                            }
                                            phi_2009_ = _e842;
                                        } else {
                                            phi_2009_ = _e707;
                                        }
                                        let _e844 = phi_2009_;
                                        phi_2008_ = _e844;
                                        phi_1031_ = (_e393 + 1u);
                                    } else {
                                        phi_2008_ = _e391;
                                        phi_1031_ = u32();
                                    }
                                    let _e847 = phi_2008_;
                                    let _e849 = phi_1031_;
                                    continue;
                                    continuing {
                                        phi_1965_ = _e847;
                                        phi_1030_ = _e849;
                                        phi_2007_ = _e847;
                                        break if !(_e397);
                                    }
                                }
                                let _e852 = phi_2007_;
                                phi_2010_ = _e852;
                                if _e852 {
                                    break;
                                }
                                phi_2011_ = _e852;
                                phi_865_ = (_e373 + 1u);
                            } else {
                                phi_2011_ = _e371;
                                phi_865_ = u32();
                            }
                            let _e855 = phi_2011_;
                            let _e857 = phi_865_;
                            continue;
                            continuing {
                                phi_1973_ = _e855;
                                phi_864_ = _e857;
                                phi_2010_ = _e855;
                                break if !(_e377);
                            }
                        }
                        let _e860 = phi_2010_;
                        if _e860 {
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
