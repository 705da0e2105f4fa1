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

struct type_20 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
}

struct type_21 {
    member: type_20,
}

struct type_24 {
    member: array<vec2<f32>>,
}

struct type_26 {
    member: vec2<u32>,
    member_1: vec3<f32>,
    member_2: vec3<f32>,
    member_3: f32,
    member_4: f32,
    member_5: f32,
}

struct type_27 {
    member: u32,
    member_1: type_26,
}

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_29 {
    member: f32,
    member_1: u32,
    member_2: u32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;
@group(0) @binding(6) 
var<uniform> params: type_21;
@group(0) @binding(2) 
var<storage> kernel: type_24;
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_379_: i32;
    var phi_398_: i32;
    var phi_449_: i32;
    var phi_468_: i32;
    var phi_519_: i32;
    var phi_538_: i32;
    var phi_589_: i32;
    var phi_608_: i32;
    var phi_1721_: bool;
    var phi_1736_: bool;
    var phi_1751_: bool;
    var phi_1766_: bool;
    var phi_1797_: f32;
    var phi_1801_: f32;
    var phi_1802_: bool;
    var phi_1824_: u32;
    var phi_1851_: f32;
    var phi_1855_: f32;
    var phi_1856_: bool;
    var phi_1878_: u32;
    var phi_1905_: f32;
    var phi_1909_: f32;
    var phi_1910_: bool;
    var phi_1932_: u32;
    var phi_1959_: f32;
    var phi_1963_: f32;
    var phi_1964_: bool;
    var phi_1986_: u32;
    var phi_1997_: bool;
    var phi_2012_: bool;
    var phi_851_: vec2<f32>;
    var phi_882_: vec3<f32>;
    var phi_888_: u32;
    var phi_891_: u32;
    var phi_893_: u32;
    var phi_895_: u32;
    var phi_924_: u32;
    var phi_925_: u32;
    var phi_926_: u32;
    var phi_927_: u32;
    var phi_889_: u32;
    var phi_892_: u32;
    var phi_894_: u32;
    var phi_896_: u32;
    var local: u32;
    var phi_958_: type_28;
    var phi_2187_: bool;
    var phi_993_: u32;
    var phi_996_: f32;
    var phi_2027_: bool;
    var phi_1142_: u32;
    var phi_1145_: f32;
    var phi_1147_: bool;
    var phi_1149_: bool;
    var phi_1151_: f32;
    var phi_1153_: f32;
    var phi_1257_: u32;
    var phi_1278_: u32;
    var phi_1372_: u32;
    var phi_1403_: u32;
    var phi_2110_: bool;
    var phi_2125_: bool;
    var phi_2086_: vec2<f32>;
    var phi_1543_: u32;
    var phi_1545_: u32;
    var phi_1546_: f32;
    var phi_1547_: bool;
    var phi_1548_: bool;
    var phi_1549_: f32;
    var phi_1552_: bool;
    var phi_1553_: bool;
    var phi_1143_: u32;
    var phi_1146_: f32;
    var phi_1148_: bool;
    var phi_1150_: bool;
    var phi_1152_: f32;
    var phi_1154_: f32;
    var phi_1557_: bool;
    var phi_1559_: bool;
    var phi_1560_: bool;
    var phi_2139_: bool;
    var phi_1709_: bool;
    var phi_1708_: bool;
    var phi_1707_: bool;
    var phi_1706_: bool;
    var phi_1704_: f32;
    var local_1: f32;
    var local_2: bool;
    var local_3: f32;
    var local_4: bool;
    var phi_1600_: f32;
    var phi_2277_: bool;
    var phi_994_: u32;
    var phi_997_: f32;
    var phi_2276_: bool;
    var local_5: f32;
    var phi_1671_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e59 = id_1;
            let _e61 = arrayLength((&depth.member));
            let _e63 = arrayLength((&normals.member));
            let _e65 = arrayLength((&kernel.member));
            let _e76 = params.member.member.member[0u];
            let _e81 = select(select(u32(_e76), 0u, (_e76 < 0f)), 4294967295u, (_e76 > 4294967000f));
            let _e86 = params.member.member.member[1u];
            let _e91 = select(select(u32(_e86), 0u, (_e86 < 0f)), 4294967295u, (_e86 > 4294967000f));
            if (_e59.x >= _e81) {
            } else {
                if (_e59.y >= _e91) {
                } else {
                    let _e97 = ((_e59.y * _e81) + _e59.x);
                    let _e98 = (_e97 < _e61);
                    if _e98 {
                    } else {
                        break;
                    }
                    let _e101 = depth.member[_e97];
                    let _e105 = params.member.member.member_3;
                    let _e108 = select(false, (_e101 < _e105), (_e101 > 0f));
                    let _e109 = select(_e105, _e101, _e108);
                    let _e110 = bitcast<i32>(_e59.x);
                    let _e111 = (_e110 + -1i);
                    let _e113 = (bitcast<i32>(_e81) - 1i);
                    let _e114 = (0i <= _e113);
                    if _e114 {
                    } else {
                        break;
                    }
                    if (_e111 < 0i) {
                        phi_379_ = 0i;
                    } else {
                        phi_379_ = select(_e111, _e113, (_e111 > _e113));
                    }
                    let _e119 = phi_379_;
                    let _e121 = bitcast<i32>(_e59.y);
                    let _e123 = (bitcast<i32>(_e91) - 1i);
                    let _e124 = (0i <= _e123);
                    if _e124 {
                    } else {
                        break;
                    }
                    let _e125 = (_e121 < 0i);
                    if _e125 {
                        phi_398_ = 0i;
                    } else {
                        phi_398_ = select(_e121, _e123, (_e121 > _e123));
                    }
                    let _e129 = phi_398_;
                    let _e132 = ((bitcast<u32>(_e129) * _e81) + bitcast<u32>(_e119));
                    if (_e132 < _e61) {
                    } else {
                        break;
                    }
                    let _e136 = depth.member[_e132];
                    let _e141 = (_e110 + 1i);
                    if _e114 {
                    } else {
                        break;
                    }
                    if (_e141 < 0i) {
                        phi_449_ = 0i;
                    } else {
                        phi_449_ = select(_e141, _e113, (_e141 > _e113));
                    }
                    let _e146 = phi_449_;
                    if _e124 {
                    } else {
                        break;
                    }
                    if _e125 {
                        phi_468_ = 0i;
                    } else {
                        phi_468_ = select(_e121, _e123, (_e121 > _e123));
                    }
                    let _e151 = phi_468_;
                    let _e154 = ((bitcast<u32>(_e151) * _e81) + bitcast<u32>(_e146));
                    if (_e154 < _e61) {
                    } else {
                        break;
                    }
                    let _e158 = depth.member[_e154];
                    if _e114 {
                    } else {
                        break;
                    }
                    let _e163 = (_e110 < 0i);
                    if _e163 {
                        phi_519_ = 0i;
                    } else {
                        phi_519_ = select(_e110, _e113, (_e110 > _e113));
                    }
                    let _e167 = phi_519_;
                    let _e169 = (_e121 + -1i);
                    if _e124 {
                    } else {
                        break;
                    }
                    if (_e169 < 0i) {
                        phi_538_ = 0i;
                    } else {
                        phi_538_ = select(_e169, _e123, (_e169 > _e123));
                    }
                    let _e174 = phi_538_;
                    let _e177 = ((bitcast<u32>(_e174) * _e81) + bitcast<u32>(_e167));
                    if (_e177 < _e61) {
                    } else {
                        break;
                    }
                    let _e181 = depth.member[_e177];
                    if _e114 {
                    } else {
                        break;
                    }
                    if _e163 {
                        phi_589_ = 0i;
                    } else {
                        phi_589_ = select(_e110, _e113, (_e110 > _e113));
                    }
                    let _e189 = phi_589_;
                    let _e191 = (_e121 + 1i);
                    if _e124 {
                    } else {
                        break;
                    }
                    if (_e191 < 0i) {
                        phi_608_ = 0i;
                    } else {
                        phi_608_ = select(_e191, _e123, (_e191 > _e123));
                    }
                    let _e196 = phi_608_;
                    let _e199 = ((bitcast<u32>(_e196) * _e81) + bitcast<u32>(_e189));
                    if (_e199 < _e61) {
                    } else {
                        break;
                    }
                    let _e203 = depth.member[_e199];
                    let _e208 = (select(_e105, _e136, select(false, (_e136 < _e105), (_e136 > 0f))) - _e109);
                    let _e209 = (select(_e105, _e158, select(false, (_e158 < _e105), (_e158 > 0f))) - _e109);
                    let _e210 = (select(_e105, _e181, select(false, (_e181 < _e105), (_e181 > 0f))) - _e109);
                    let _e211 = (select(_e105, _e203, select(false, (_e203 < _e105), (_e203 > 0f))) - _e109);
                    let _e213 = ((_e209 - _e208) * 0.5f);
                    let _e215 = ((_e211 - _e210) * 0.5f);
                    let _e216 = (_e109 * 0.011f);
                    let _e218 = abs(_e208);
                    let _e219 = abs((_e208 + _e213));
                    if (_e218 != _e218) {
                        phi_1721_ = true;
                    } else {
                        phi_1721_ = (_e219 <= _e218);
                    }
                    let _e223 = phi_1721_;
                    let _e226 = (1.25f - (select(_e218, _e219, _e223) / _e216));
                    let _e230 = select(0f, select(1f, _e226, (_e226 < 1f)), (_e226 > 0f));
                    let _e232 = abs(_e209);
                    let _e233 = abs((_e209 - _e213));
                    if (_e232 != _e232) {
                        phi_1736_ = true;
                    } else {
                        phi_1736_ = (_e233 <= _e232);
                    }
                    let _e237 = phi_1736_;
                    let _e240 = (1.25f - (select(_e232, _e233, _e237) / _e216));
                    let _e244 = select(0f, select(1f, _e240, (_e240 < 1f)), (_e240 > 0f));
                    let _e246 = abs(_e210);
                    let _e247 = abs((_e210 + _e215));
                    if (_e246 != _e246) {
                        phi_1751_ = true;
                    } else {
                        phi_1751_ = (_e247 <= _e246);
                    }
                    let _e251 = phi_1751_;
                    let _e254 = (1.25f - (select(_e246, _e247, _e251) / _e216));
                    let _e258 = select(0f, select(1f, _e254, (_e254 < 1f)), (_e254 > 0f));
                    let _e260 = abs(_e211);
                    let _e261 = abs((_e211 - _e215));
                    if (_e260 != _e260) {
                        phi_1766_ = true;
                    } else {
                        phi_1766_ = (_e261 <= _e260);
                    }
                    let _e265 = phi_1766_;
                    let _e268 = (1.25f - (select(_e260, _e261, _e265) / _e216));
                    let _e272 = select(0f, select(1f, _e268, (_e268 < 1f)), (_e268 > 0f));
                    let _e277 = (select(0f, select(1f, _e230, (_e230 < 1f)), (_e230 > 0f)) * 2.9f);
                    let _e279 = floor((_e277 + 0.5f));
                    if ((_e279 - _e277) == 0.5f) {
                        let _e285 = ((floor((_e279 * 0.5f)) * 2f) != _e279);
                        if _e285 {
                            phi_1797_ = (_e279 - 1f);
                        } else {
                            phi_1797_ = f32();
                        }
                        let _e288 = phi_1797_;
                        phi_1801_ = _e288;
                        phi_1802_ = select(true, false, _e285);
                    } else {
                        phi_1801_ = f32();
                        phi_1802_ = true;
                    }
                    let _e291 = phi_1801_;
                    let _e293 = phi_1802_;
                    let _e294 = select(_e291, _e279, _e293);
                    if (_e294 > 0f) {
                        let _e300 = select(select(u32(_e294), 0u, (_e294 < 0f)), 4294967295u, (_e294 > 4294967000f));
                        phi_1824_ = select(_e300, 3u, (3u < _e300));
                    } else {
                        phi_1824_ = 0u;
                    }
                    let _e304 = phi_1824_;
                    let _e310 = (select(0f, select(1f, _e244, (_e244 < 1f)), (_e244 > 0f)) * 2.9f);
                    let _e312 = floor((_e310 + 0.5f));
                    if ((_e312 - _e310) == 0.5f) {
                        let _e318 = ((floor((_e312 * 0.5f)) * 2f) != _e312);
                        if _e318 {
                            phi_1851_ = (_e312 - 1f);
                        } else {
                            phi_1851_ = f32();
                        }
                        let _e321 = phi_1851_;
                        phi_1855_ = _e321;
                        phi_1856_ = select(true, false, _e318);
                    } else {
                        phi_1855_ = f32();
                        phi_1856_ = true;
                    }
                    let _e324 = phi_1855_;
                    let _e326 = phi_1856_;
                    let _e327 = select(_e324, _e312, _e326);
                    if (_e327 > 0f) {
                        let _e333 = select(select(u32(_e327), 0u, (_e327 < 0f)), 4294967295u, (_e327 > 4294967000f));
                        phi_1878_ = select(_e333, 3u, (3u < _e333));
                    } else {
                        phi_1878_ = 0u;
                    }
                    let _e337 = phi_1878_;
                    let _e344 = (select(0f, select(1f, _e258, (_e258 < 1f)), (_e258 > 0f)) * 2.9f);
                    let _e346 = floor((_e344 + 0.5f));
                    if ((_e346 - _e344) == 0.5f) {
                        let _e352 = ((floor((_e346 * 0.5f)) * 2f) != _e346);
                        if _e352 {
                            phi_1905_ = (_e346 - 1f);
                        } else {
                            phi_1905_ = f32();
                        }
                        let _e355 = phi_1905_;
                        phi_1909_ = _e355;
                        phi_1910_ = select(true, false, _e352);
                    } else {
                        phi_1909_ = f32();
                        phi_1910_ = true;
                    }
                    let _e358 = phi_1909_;
                    let _e360 = phi_1910_;
                    let _e361 = select(_e358, _e346, _e360);
                    if (_e361 > 0f) {
                        let _e367 = select(select(u32(_e361), 0u, (_e361 < 0f)), 4294967295u, (_e361 > 4294967000f));
                        phi_1932_ = select(_e367, 3u, (3u < _e367));
                    } else {
                        phi_1932_ = 0u;
                    }
                    let _e371 = phi_1932_;
                    let _e378 = (select(0f, select(1f, _e272, (_e272 < 1f)), (_e272 > 0f)) * 2.9f);
                    let _e380 = floor((_e378 + 0.5f));
                    if ((_e380 - _e378) == 0.5f) {
                        let _e386 = ((floor((_e380 * 0.5f)) * 2f) != _e380);
                        if _e386 {
                            phi_1959_ = (_e380 - 1f);
                        } else {
                            phi_1959_ = f32();
                        }
                        let _e389 = phi_1959_;
                        phi_1963_ = _e389;
                        phi_1964_ = select(true, false, _e386);
                    } else {
                        phi_1963_ = f32();
                        phi_1964_ = true;
                    }
                    let _e392 = phi_1963_;
                    let _e394 = phi_1964_;
                    let _e395 = select(_e392, _e380, _e394);
                    if (_e395 > 0f) {
                        let _e401 = select(select(u32(_e395), 0u, (_e395 < 0f)), 4294967295u, (_e395 > 4294967000f));
                        phi_1986_ = select(_e401, 3u, (3u < _e401));
                    } else {
                        phi_1986_ = 0u;
                    }
                    let _e405 = phi_1986_;
                    let _e406 = ((((64u * _e304) + (16u * _e337)) + (4u * _e371)) + _e405);
                    if _e98 {
                    } else {
                        break;
                    }
                    if _e108 {
                        let _e419 = params.member.member.member_1[0u];
                        let _e421 = ((((((f32(_e59.x) + 0.5f) / _e76) * 2f) - 1f) * _e419) * _e101);
                        let _e428 = params.member.member.member_1[1u];
                        let _e430 = ((((((f32(_e59.y) + 0.5f) / _e86) * -2f) + 1f) * _e428) * _e101);
                        if (_e97 < _e63) {
                        } else {
                            break;
                        }
                        let _e435 = normals.member[_e97];
                        let _e443 = (f32((bitcast<i32>(((_e435 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e443 != _e443) {
                            phi_1997_ = true;
                        } else {
                            phi_1997_ = (-1f >= _e443);
                        }
                        let _e447 = phi_1997_;
                        let _e448 = select(_e443, -1f, _e447);
                        let _e458 = (f32((bitcast<i32>((((_e435 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e458 != _e458) {
                            phi_2012_ = true;
                        } else {
                            phi_2012_ = (-1f >= _e458);
                        }
                        let _e462 = phi_2012_;
                        let _e463 = select(_e458, -1f, _e462);
                        let _e466 = (1f - abs(_e448));
                        let _e467 = abs(_e463);
                        let _e468 = (_e466 - _e467);
                        if (_e468 < 0f) {
                            phi_851_ = vec2<f32>(((1f - _e467) * select(1f, -1f, (_e448 < 0f))), (_e466 * select(1f, -1f, (_e463 < 0f))));
                        } else {
                            phi_851_ = vec2<f32>(_e448, _e463);
                        }
                        let _e479 = phi_851_;
                        let _e488 = (1f / sqrt((((_e479.x * _e479.x) + (_e479.y * _e479.y)) + (_e468 * _e468))));
                        let _e489 = (_e479.x * _e488);
                        let _e490 = (_e479.y * _e488);
                        let _e491 = (_e468 * _e488);
                        let _e492 = -(_e491);
                        if ((((_e489 * -(_e421)) + (_e490 * -(_e430))) + (_e492 * -(_e101))) < 0f) {
                            phi_882_ = vec3<f32>(-(_e489), -(_e490), _e491);
                        } else {
                            phi_882_ = vec3<f32>(_e489, _e490, _e492);
                        }
                        let _e507 = phi_882_;
                        let _e510 = params.member.member_8;
                        phi_888_ = (_e59.y & 63u);
                        phi_891_ = (_e59.x & 63u);
                        phi_893_ = 32u;
                        phi_895_ = 0u;
                        loop {
                            let _e514 = phi_888_;
                            let _e516 = phi_891_;
                            let _e518 = phi_893_;
                            let _e520 = phi_895_;
                            local = _e520;
                            let _e521 = (_e518 > 0u);
                            if _e521 {
                                let _e524 = select(0u, 1u, ((_e516 & _e518) != 0u));
                                let _e527 = select(0u, 1u, ((_e514 & _e518) != 0u));
                                if (_e527 == 0u) {
                                    if (_e524 == 1u) {
                                        phi_924_ = (63u - _e514);
                                        phi_925_ = (63u - _e516);
                                    } else {
                                        phi_924_ = _e514;
                                        phi_925_ = _e516;
                                    }
                                    let _e538 = phi_924_;
                                    let _e540 = phi_925_;
                                    phi_926_ = _e540;
                                    phi_927_ = _e538;
                                } else {
                                    phi_926_ = _e514;
                                    phi_927_ = _e516;
                                }
                                let _e542 = phi_926_;
                                let _e544 = phi_927_;
                                phi_889_ = _e542;
                                phi_892_ = _e544;
                                phi_894_ = (_e518 / 2u);
                                phi_896_ = (_e520 + ((_e518 * _e518) * ((3u * _e524) ^ _e527)));
                            } else {
                                phi_889_ = u32();
                                phi_892_ = u32();
                                phi_894_ = u32();
                                phi_896_ = u32();
                            }
                            let _e547 = phi_889_;
                            let _e549 = phi_892_;
                            let _e551 = phi_894_;
                            let _e553 = phi_896_;
                            continue;
                            continuing {
                                phi_888_ = _e547;
                                phi_891_ = _e549;
                                phi_893_ = _e551;
                                phi_895_ = _e553;
                                break if !(_e521);
                            }
                        }
                        let _e558 = local;
                        let _e560 = f32((_e558 + (288u * (_e510 % 64u))));
                        let _e562 = (0.5f + (_e560 * 0.7548777f));
                        let _e566 = (0.5f + (_e560 * 0.5698403f));
                        let _e569 = (6.2831855f * (_e562 - floor(_e562)));
                        phi_958_ = type_28(_e406, type_27(1u, type_26(vec2<u32>(_e59.x, _e59.y), vec3<f32>(_e421, _e430, _e101), _e507, sin(_e569), cos(_e569), (_e566 - floor(_e566)))));
                    } else {
                        phi_958_ = type_28(_e406, type_27(0u, type_27().member_1));
                    }
                    let _e581 = phi_958_;
                    if (bitcast<i32>(_e581.member_1.member) != 0i) {
                        let _e590 = params.member.member_5;
                        let _e592 = select(_e590, 64u, (64u < _e590));
                        let _e594 = select(_e592, _e65, (_e65 < _e592));
                        let _e596 = select(1u, _e594, (1u < _e594));
                        let _e599 = params.member.member_6;
                        let _e601 = select(1u, _e599, (1u < _e599));
                        phi_2187_ = false;
                        phi_993_ = 0u;
                        phi_996_ = 0f;
                        loop {
                            let _e603 = phi_2187_;
                            let _e605 = phi_993_;
                            let _e607 = phi_996_;
                            local_5 = _e607;
                            let _e608 = (_e605 < _e596);
                            if _e608 {
                                if (_e605 < _e65) {
                                } else {
                                    phi_2276_ = true;
                                    break;
                                }
                                let _e613 = kernel.member[_e605][0u];
                                let _e617 = kernel.member[_e605][1u];
                                let _e622 = ((_e581.member_1.member_1.member_4 * _e613) - (_e581.member_1.member_1.member_3 * _e617));
                                let _e625 = ((_e581.member_1.member_1.member_3 * _e613) + (_e581.member_1.member_1.member_4 * _e617));
                                let _e630 = ((1f - (_e622 * _e622)) - (_e625 * _e625));
                                if (_e630 != _e630) {
                                    phi_2027_ = true;
                                } else {
                                    phi_2027_ = (0f >= _e630);
                                }
                                let _e634 = phi_2027_;
                                let _e636 = sqrt(select(_e630, 0f, _e634));
                                let _e637 = -(_e636);
                                let _e641 = (-1f * _e581.member_1.member_1.member_2.z);
                                let _e642 = (-1f * _e581.member_1.member_1.member_2.x);
                                let _e644 = (1f / (_e641 + 1f));
                                let _e645 = (_e644 * _e581.member_1.member_1.member_2.y);
                                let _e649 = (_e645 * _e642);
                                let _e669 = (_e641 > 0.9997f);
                                let _e670 = (_e641 < -0.9997f);
                                let _e680 = params.member.member_1;
                                let _e684 = params.member.member_3;
                                let _e687 = params.member.member_4;
                                phi_1142_ = 1u;
                                phi_1145_ = _e680;
                                phi_1147_ = false;
                                phi_1149_ = true;
                                phi_1151_ = 0f;
                                phi_1153_ = 0f;
                                loop {
                                    let _e693 = phi_1142_;
                                    let _e695 = phi_1145_;
                                    let _e697 = phi_1147_;
                                    let _e699 = phi_1149_;
                                    let _e701 = phi_1151_;
                                    let _e703 = phi_1153_;
                                    local_1 = _e695;
                                    local_2 = _e697;
                                    local_3 = _e695;
                                    local_4 = _e697;
                                    let _e704 = (_e693 <= _e601);
                                    if _e704 {
                                        let _e710 = (((-(_e581.member_1.member_1.member_5) + f32(_e693)) * _e680) / f32(_e601));
                                        let _e715 = (_e581.member_1.member_1.member_1.x + (select(select(((((_e641 + (_e645 * _e581.member_1.member_1.member_2.y)) * _e622) + (_e649 * _e625)) + (_e642 * _e637)), _e622, _e670), _e622, _e669) * _e710));
                                        let _e717 = (_e581.member_1.member_1.member_1.y + (select(select((((_e649 * _e622) + ((_e641 + ((_e644 * _e642) * _e642)) * _e625)) + (-(_e581.member_1.member_1.member_2.y) * _e637)), -(_e625), _e670), _e625, _e669) * _e710));
                                        let _e719 = (_e581.member_1.member_1.member_1.z + (select(select((((_e581.member_1.member_1.member_2.x * _e622) + (_e581.member_1.member_1.member_2.y * _e625)) + (_e641 * _e637)), _e636, _e670), _e637, _e669) * _e710));
                                        let _e725 = params.member.member.member_1[0u];
                                        let _e728 = (((_e715 * 0.5f) / (_e719 * _e725)) + 0.5f);
                                        let _e734 = params.member.member.member_1[1u];
                                        let _e737 = (0.5f - ((_e717 * 0.5f) / (_e719 * _e734)));
                                        let _e747 = select(false, select(false, select(false, select(false, (_e737 <= 1f), (_e737 >= 0f)), select(false, (_e728 <= 1f), (_e728 >= 0f))), (_e719 > 0f)), _e699);
                                        if _e747 {
                                            let _e748 = (_e728 * _e76);
                                            if (_e748 > 0f) {
                                                let _e754 = select(select(u32(_e748), 0u, (_e748 < 0f)), 4294967295u, (_e748 > 4294967000f));
                                                let _e755 = (_e81 - 1u);
                                                phi_1257_ = select(_e754, _e755, (_e755 < _e754));
                                            } else {
                                                phi_1257_ = 0u;
                                            }
                                            let _e759 = phi_1257_;
                                            let _e760 = (_e737 * _e86);
                                            if (_e760 > 0f) {
                                                let _e766 = select(select(u32(_e760), 0u, (_e760 < 0f)), 4294967295u, (_e760 > 4294967000f));
                                                let _e767 = (_e91 - 1u);
                                                phi_1278_ = select(_e766, _e767, (_e767 < _e766));
                                            } else {
                                                phi_1278_ = 0u;
                                            }
                                            let _e771 = phi_1278_;
                                            let _e773 = ((_e771 * _e81) + _e759);
                                            if (_e773 < _e61) {
                                            } else {
                                                phi_2139_ = true;
                                                phi_1709_ = bool();
                                                phi_1708_ = bool();
                                                phi_1707_ = bool();
                                                phi_1706_ = bool();
                                                phi_1704_ = f32();
                                                break;
                                            }
                                            let _e777 = depth.member[_e773];
                                            let _e781 = select(_e105, _e777, select(false, (_e777 < _e105), (_e777 > 0f)));
                                            let _e784 = (((_e728 * 2f) - 1f) * _e725);
                                            let _e788 = (((_e737 * -2f) + 1f) * _e734);
                                            let _e790 = (_e715 - (_e784 * _e781));
                                            let _e791 = (_e717 - (_e788 * _e781));
                                            let _e792 = (_e719 - _e781);
                                            let _e798 = sqrt((((_e790 * _e790) + (_e791 * _e791)) + (_e792 * _e792)));
                                            let _e803 = (select(0f, select(1f, _e728, (_e728 < 1f)), (_e728 > 0f)) * _e76);
                                            if (_e803 > 0f) {
                                                let _e809 = select(select(u32(_e803), 0u, (_e803 < 0f)), 4294967295u, (_e803 > 4294967000f));
                                                let _e810 = (_e81 - 1u);
                                                phi_1372_ = select(_e809, _e810, (_e810 < _e809));
                                            } else {
                                                phi_1372_ = 0u;
                                            }
                                            let _e814 = phi_1372_;
                                            let _e819 = (select(0f, select(1f, _e737, (_e737 < 1f)), (_e737 > 0f)) * _e86);
                                            if (_e819 > 0f) {
                                                let _e825 = select(select(u32(_e819), 0u, (_e819 < 0f)), 4294967295u, (_e819 > 4294967000f));
                                                let _e826 = (_e91 - 1u);
                                                phi_1403_ = select(_e825, _e826, (_e826 < _e825));
                                            } else {
                                                phi_1403_ = 0u;
                                            }
                                            let _e830 = phi_1403_;
                                            let _e848 = ((_e830 * _e81) + _e814);
                                            if (_e848 < _e63) {
                                            } else {
                                                phi_2139_ = true;
                                                phi_1709_ = bool();
                                                phi_1708_ = bool();
                                                phi_1707_ = bool();
                                                phi_1706_ = bool();
                                                phi_1704_ = f32();
                                                break;
                                            }
                                            let _e852 = normals.member[_e848];
                                            let _e860 = (f32((bitcast<i32>(((_e852 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e860 != _e860) {
                                                phi_2110_ = true;
                                            } else {
                                                phi_2110_ = (-1f >= _e860);
                                            }
                                            let _e864 = phi_2110_;
                                            let _e865 = select(_e860, -1f, _e864);
                                            let _e875 = (f32((bitcast<i32>((((_e852 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e875 != _e875) {
                                                phi_2125_ = true;
                                            } else {
                                                phi_2125_ = (-1f >= _e875);
                                            }
                                            let _e879 = phi_2125_;
                                            let _e880 = select(_e875, -1f, _e879);
                                            let _e883 = (1f - abs(_e865));
                                            let _e884 = abs(_e880);
                                            let _e885 = (_e883 - _e884);
                                            if (_e885 < 0f) {
                                                phi_2086_ = vec2<f32>(((1f - _e884) * select(1f, -1f, (_e865 < 0f))), (_e883 * select(1f, -1f, (_e880 < 0f))));
                                            } else {
                                                phi_2086_ = vec2<f32>(_e865, _e880);
                                            }
                                            let _e896 = phi_2086_;
                                            let _e905 = (1f / sqrt((((_e896.x * _e896.x) + (_e896.y * _e896.y)) + (_e885 * _e885))));
                                            let _e906 = (_e896.x * _e905);
                                            let _e907 = (_e896.y * _e905);
                                            let _e909 = -((_e885 * _e905));
                                            let _e913 = (((_e906 * _e784) + (_e907 * _e788)) + _e909);
                                            let _e922 = select(((((_e906 * ((((((f32(_e814) + 0.5f) * (1f / _e76)) * 2f) - 1f) * _e725) * _e781)) + (_e907 * ((((((f32(_e830) + 0.5f) * (1f / _e86)) * -2f) + 1f) * _e734) * _e781))) + (_e909 * _e781)) / _e913), _e781, (abs(_e913) < 0.001f));
                                            let _e932 = select(select(((_e719 - _e922) > _e687), true, (_e719 < (_e922 * (1f + _e684)))), true, select(false, (_e830 == _e581.member_1.member_1.member.y), (_e814 == _e581.member_1.member_1.member.x)));
                                            let _e934 = select(false, !(_e932), _e747);
                                            let _e935 = (_e701 + _e798);
                                            let _e944 = select(false, _e932, _e747);
                                            if _e944 {
                                                phi_1543_ = (_e693 + 1u);
                                            } else {
                                                phi_1543_ = u32();
                                            }
                                            let _e947 = phi_1543_;
                                            phi_1545_ = _e947;
                                            phi_1546_ = select(_e695, select((_e703 + ((_e701 * (_e710 - _e703)) / _e935)), _e703, (_e935 < 0.000001f)), _e934);
                                            phi_1547_ = select(_e934, true, _e697);
                                            phi_1548_ = _e944;
                                            phi_1549_ = _e798;
                                            phi_1552_ = _e944;
                                            phi_1553_ = select(true, false, _e944);
                                        } else {
                                            phi_1545_ = u32();
                                            phi_1546_ = f32();
                                            phi_1547_ = bool();
                                            phi_1548_ = bool();
                                            phi_1549_ = f32();
                                            phi_1552_ = false;
                                            phi_1553_ = false;
                                        }
                                        let _e950 = phi_1545_;
                                        let _e952 = phi_1546_;
                                        let _e954 = phi_1547_;
                                        let _e956 = phi_1548_;
                                        let _e958 = phi_1549_;
                                        let _e960 = phi_1552_;
                                        let _e962 = phi_1553_;
                                        phi_1143_ = _e950;
                                        phi_1146_ = _e952;
                                        phi_1148_ = _e954;
                                        phi_1150_ = _e956;
                                        phi_1152_ = _e958;
                                        phi_1154_ = _e710;
                                        phi_1557_ = _e960;
                                        phi_1559_ = _e962;
                                        phi_1560_ = select(true, false, _e747);
                                    } else {
                                        phi_1143_ = u32();
                                        phi_1146_ = f32();
                                        phi_1148_ = bool();
                                        phi_1150_ = bool();
                                        phi_1152_ = f32();
                                        phi_1154_ = f32();
                                        phi_1557_ = false;
                                        phi_1559_ = false;
                                        phi_1560_ = false;
                                    }
                                    let _e965 = phi_1143_;
                                    let _e967 = phi_1146_;
                                    let _e969 = phi_1148_;
                                    let _e971 = phi_1150_;
                                    let _e973 = phi_1152_;
                                    let _e975 = phi_1154_;
                                    let _e977 = phi_1557_;
                                    let _e979 = phi_1559_;
                                    let _e981 = phi_1560_;
                                    continue;
                                    continuing {
                                        phi_1142_ = _e965;
                                        phi_1145_ = _e967;
                                        phi_1147_ = _e969;
                                        phi_1149_ = _e971;
                                        phi_1151_ = _e973;
                                        phi_1153_ = _e975;
                                        phi_2139_ = _e603;
                                        phi_1709_ = _e981;
                                        phi_1708_ = _e979;
                                        phi_1707_ = select(true, false, _e704);
                                        phi_1706_ = _e969;
                                        phi_1704_ = _e967;
                                        break if !(_e977);
                                    }
                                }
                                let _e985 = phi_2139_;
                                let _e987 = phi_1709_;
                                let _e989 = phi_1708_;
                                let _e991 = phi_1707_;
                                let _e993 = phi_1706_;
                                let _e995 = phi_1704_;
                                phi_2276_ = _e985;
                                if _e985 {
                                    break;
                                }
                                let _e996 = select(_e989, false, _e991);
                                let _e998 = select(select(_e987, false, _e991), false, _e996);
                                let _e1000 = local_1;
                                let _e1003 = local_2;
                                let _e1005 = select(_e996, true, _e998);
                                let _e1007 = local_3;
                                let _e1010 = local_4;
                                let _e1014 = params.member.member_7;
                                if (_e1014 == 1u) {
                                    phi_1600_ = 0f;
                                } else {
                                    let _e1016 = (select(_e1007, select(_e995, _e1000, _e998), _e1005) / _e680);
                                    phi_1600_ = select(0f, select(1f, _e1016, (_e1016 < 1f)), (_e1016 > 0f));
                                }
                                let _e1022 = phi_1600_;
                                phi_2277_ = _e985;
                                phi_994_ = (_e605 + 1u);
                                phi_997_ = (_e607 + select(1f, _e1022, select(_e1010, select(_e993, _e1003, _e998), _e1005)));
                            } else {
                                phi_2277_ = _e603;
                                phi_994_ = u32();
                                phi_997_ = f32();
                            }
                            let _e1027 = phi_2277_;
                            let _e1029 = phi_994_;
                            let _e1031 = phi_997_;
                            continue;
                            continuing {
                                phi_2187_ = _e1027;
                                phi_993_ = _e1029;
                                phi_996_ = _e1031;
                                phi_2276_ = _e1027;
                                break if !(_e608);
                            }
                        }
                        let _e1034 = phi_2276_;
                        if _e1034 {
                            break;
                        }
                        let _e1037 = local_5;
                        let _e1041 = params.member.member_2;
                        let _e1042 = pow((_e1037 / f32(_e596)), _e1041);
                        let _e1043 = (_e1042 * 0.6666667f);
                        let _e1049 = ((select(0f, select(1f, _e1043, (_e1043 < 1f)), (_e1043 > 0f)) * 255f) + 0.5f);
                        phi_1671_ = type_29(_e1042, select(select(u32(_e1049), 0u, (_e1049 < 0f)), 4294967295u, (_e1049 > 4294967000f)), _e581.member);
                    } else {
                        phi_1671_ = type_29(1f, 170u, _e581.member);
                    }
                    let _e1058 = phi_1671_;
                    if (_e97 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e97] = _e1058.member;
                    if (_e97 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e97] = _e1058.member_1;
                    if (_e97 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e97] = _e1058.member_2;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn raymarch_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
