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

struct type_19 {
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

struct type_20 {
    member: type_19,
}

struct type_23 {
    member: array<vec2<f32>>,
}

struct type_25 {
    member: f32,
    member_1: bool,
}

struct type_26 {
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
var<uniform> params: type_20;
@group(0) @binding(2) 
var<storage> kernel: type_23;
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_247_: bool;
    var phi_271_: i32;
    var phi_290_: i32;
    var phi_319_: bool;
    var phi_343_: i32;
    var phi_362_: i32;
    var phi_391_: bool;
    var phi_415_: i32;
    var phi_434_: i32;
    var phi_463_: bool;
    var phi_487_: i32;
    var phi_506_: i32;
    var phi_535_: bool;
    var phi_1704_: f32;
    var phi_1708_: f32;
    var phi_1709_: bool;
    var phi_1747_: f32;
    var phi_1751_: f32;
    var phi_1752_: bool;
    var phi_1790_: f32;
    var phi_1794_: f32;
    var phi_1795_: bool;
    var phi_1833_: f32;
    var phi_1837_: f32;
    var phi_1838_: bool;
    var phi_671_: bool;
    var phi_1861_: bool;
    var phi_1876_: bool;
    var phi_764_: vec2<f32>;
    var phi_795_: vec3<f32>;
    var phi_801_: u32;
    var phi_804_: u32;
    var phi_806_: u32;
    var phi_808_: u32;
    var phi_837_: u32;
    var phi_838_: u32;
    var phi_839_: u32;
    var phi_840_: u32;
    var phi_802_: u32;
    var phi_805_: u32;
    var phi_807_: u32;
    var phi_809_: u32;
    var local: u32;
    var phi_1939_: bool;
    var phi_878_: u32;
    var phi_881_: f32;
    var phi_1891_: bool;
    var phi_1024_: u32;
    var phi_1027_: f32;
    var phi_1029_: f32;
    var phi_1121_: u32;
    var phi_1143_: u32;
    var phi_1160_: bool;
    var phi_1906_: bool;
    var phi_1921_: bool;
    var phi_1349_: vec2<f32>;
    var phi_1394_: f32;
    var phi_1400_: bool;
    var phi_1415_: bool;
    var phi_1416_: bool;
    var phi_1417_: bool;
    var phi_1426_: u32;
    var phi_1428_: u32;
    var phi_1429_: f32;
    var phi_1431_: bool;
    var phi_1432_: bool;
    var phi_1434_: u32;
    var phi_1435_: f32;
    var phi_1437_: bool;
    var phi_1438_: bool;
    var phi_1439_: bool;
    var phi_1441_: u32;
    var phi_1442_: f32;
    var phi_1444_: bool;
    var phi_1445_: bool;
    var phi_1446_: bool;
    var phi_1447_: bool;
    var phi_1449_: u32;
    var phi_1450_: f32;
    var phi_1452_: bool;
    var phi_1453_: bool;
    var phi_1454_: bool;
    var phi_1455_: bool;
    var phi_1456_: bool;
    var phi_1458_: u32;
    var phi_1459_: f32;
    var phi_1461_: bool;
    var phi_1462_: bool;
    var phi_1463_: bool;
    var phi_1464_: bool;
    var phi_1465_: bool;
    var phi_1466_: bool;
    var phi_1025_: u32;
    var phi_1028_: f32;
    var phi_1030_: f32;
    var phi_1469_: bool;
    var phi_1470_: bool;
    var phi_1472_: bool;
    var phi_1473_: bool;
    var phi_1474_: bool;
    var phi_1475_: bool;
    var phi_1476_: bool;
    var phi_1926_: bool;
    var phi_1676_: bool;
    var phi_1675_: bool;
    var phi_1674_: bool;
    var phi_1673_: bool;
    var phi_1672_: bool;
    var phi_1671_: bool;
    var phi_1670_: bool;
    var phi_1668_: f32;
    var phi_1667_: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var local_4: f32;
    var phi_1507_: f32;
    var phi_1509_: type_25;
    var phi_1558_: type_25;
    var phi_1583_: f32;
    var phi_1584_: f32;
    var phi_2044_: bool;
    var phi_879_: u32;
    var phi_882_: f32;
    var phi_2043_: bool;
    var local_5: f32;
    var phi_1634_: type_26;
    var local_6: f32;

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
                    let _e106 = (_e101 > 0f);
                    if _e106 {
                        phi_247_ = (_e101 < _e105);
                    } else {
                        phi_247_ = false;
                    }
                    let _e109 = phi_247_;
                    let _e110 = select(_e105, _e101, _e109);
                    let _e111 = bitcast<i32>(_e59.x);
                    let _e112 = (_e111 + -1i);
                    let _e114 = (bitcast<i32>(_e81) - 1i);
                    let _e115 = (0i <= _e114);
                    if _e115 {
                    } else {
                        break;
                    }
                    if (_e112 < 0i) {
                        phi_271_ = 0i;
                    } else {
                        phi_271_ = select(_e112, _e114, (_e112 > _e114));
                    }
                    let _e120 = phi_271_;
                    let _e122 = bitcast<i32>(_e59.y);
                    let _e124 = (bitcast<i32>(_e91) - 1i);
                    let _e125 = (0i <= _e124);
                    if _e125 {
                    } else {
                        break;
                    }
                    let _e126 = (_e122 < 0i);
                    if _e126 {
                        phi_290_ = 0i;
                    } else {
                        phi_290_ = select(_e122, _e124, (_e122 > _e124));
                    }
                    let _e130 = phi_290_;
                    let _e133 = ((bitcast<u32>(_e130) * _e81) + bitcast<u32>(_e120));
                    if (_e133 < _e61) {
                    } else {
                        break;
                    }
                    let _e137 = depth.member[_e133];
                    if (_e137 > 0f) {
                        phi_319_ = (_e137 < _e105);
                    } else {
                        phi_319_ = false;
                    }
                    let _e141 = phi_319_;
                    let _e143 = (_e111 + 1i);
                    if _e115 {
                    } else {
                        break;
                    }
                    if (_e143 < 0i) {
                        phi_343_ = 0i;
                    } else {
                        phi_343_ = select(_e143, _e114, (_e143 > _e114));
                    }
                    let _e148 = phi_343_;
                    if _e125 {
                    } else {
                        break;
                    }
                    if _e126 {
                        phi_362_ = 0i;
                    } else {
                        phi_362_ = select(_e122, _e124, (_e122 > _e124));
                    }
                    let _e153 = phi_362_;
                    let _e156 = ((bitcast<u32>(_e153) * _e81) + bitcast<u32>(_e148));
                    if (_e156 < _e61) {
                    } else {
                        break;
                    }
                    let _e160 = depth.member[_e156];
                    if (_e160 > 0f) {
                        phi_391_ = (_e160 < _e105);
                    } else {
                        phi_391_ = false;
                    }
                    let _e164 = phi_391_;
                    if _e115 {
                    } else {
                        break;
                    }
                    let _e166 = (_e111 < 0i);
                    if _e166 {
                        phi_415_ = 0i;
                    } else {
                        phi_415_ = select(_e111, _e114, (_e111 > _e114));
                    }
                    let _e170 = phi_415_;
                    let _e172 = (_e122 + -1i);
                    if _e125 {
                    } else {
                        break;
                    }
                    if (_e172 < 0i) {
                        phi_434_ = 0i;
                    } else {
                        phi_434_ = select(_e172, _e124, (_e172 > _e124));
                    }
                    let _e177 = phi_434_;
                    let _e180 = ((bitcast<u32>(_e177) * _e81) + bitcast<u32>(_e170));
                    if (_e180 < _e61) {
                    } else {
                        break;
                    }
                    let _e184 = depth.member[_e180];
                    if (_e184 > 0f) {
                        phi_463_ = (_e184 < _e105);
                    } else {
                        phi_463_ = false;
                    }
                    let _e188 = phi_463_;
                    if _e115 {
                    } else {
                        break;
                    }
                    if _e166 {
                        phi_487_ = 0i;
                    } else {
                        phi_487_ = select(_e111, _e114, (_e111 > _e114));
                    }
                    let _e193 = phi_487_;
                    let _e195 = (_e122 + 1i);
                    if _e125 {
                    } else {
                        break;
                    }
                    if (_e195 < 0i) {
                        phi_506_ = 0i;
                    } else {
                        phi_506_ = select(_e195, _e124, (_e195 > _e124));
                    }
                    let _e200 = phi_506_;
                    let _e203 = ((bitcast<u32>(_e200) * _e81) + bitcast<u32>(_e193));
                    if (_e203 < _e61) {
                    } else {
                        break;
                    }
                    let _e207 = depth.member[_e203];
                    if (_e207 > 0f) {
                        phi_535_ = (_e207 < _e105);
                    } else {
                        phi_535_ = false;
                    }
                    let _e211 = phi_535_;
                    let _e213 = (select(_e105, _e137, _e141) - _e110);
                    let _e214 = (select(_e105, _e160, _e164) - _e110);
                    let _e215 = (select(_e105, _e184, _e188) - _e110);
                    let _e216 = (select(_e105, _e207, _e211) - _e110);
                    let _e217 = (_e214 - _e213);
                    let _e219 = (_e216 - _e215);
                    let _e227 = abs(_e213);
                    let _e228 = abs(_e214);
                    let _e229 = abs(_e215);
                    let _e230 = abs(_e216);
                    let _e231 = abs((_e213 + (_e217 * 0.5f)));
                    let _e232 = abs((_e214 + (_e217 * -0.5f)));
                    let _e233 = abs((_e215 + (_e219 * 0.5f)));
                    let _e234 = abs((_e216 + (_e219 * -0.5f)));
                    let _e243 = (_e110 * 0.011f);
                    let _e248 = (1.25f - (select(_e231, _e227, (_e227 < _e231)) / _e243));
                    let _e252 = select(0f, select(1f, _e248, (_e248 < 1f)), (_e248 > 0f));
                    let _e253 = (1.25f - (select(_e232, _e228, (_e228 < _e232)) / _e243));
                    let _e257 = select(0f, select(1f, _e253, (_e253 < 1f)), (_e253 > 0f));
                    let _e258 = (1.25f - (select(_e233, _e229, (_e229 < _e233)) / _e243));
                    let _e262 = select(0f, select(1f, _e258, (_e258 < 1f)), (_e258 > 0f));
                    let _e263 = (1.25f - (select(_e234, _e230, (_e230 < _e234)) / _e243));
                    let _e267 = select(0f, select(1f, _e263, (_e263 < 1f)), (_e263 > 0f));
                    let _e272 = (select(0f, select(1f, _e252, (_e252 < 1f)), (_e252 > 0f)) * 2.9f);
                    let _e274 = floor((_e272 + 0.5f));
                    if ((_e274 - _e272) == 0.5f) {
                        let _e280 = ((floor((_e274 * 0.5f)) * 2f) != _e274);
                        if _e280 {
                            phi_1704_ = (_e274 - 1f);
                        } else {
                            phi_1704_ = f32();
                        }
                        let _e283 = phi_1704_;
                        phi_1708_ = _e283;
                        phi_1709_ = select(true, false, _e280);
                    } else {
                        phi_1708_ = f32();
                        phi_1709_ = true;
                    }
                    let _e286 = phi_1708_;
                    let _e288 = phi_1709_;
                    let _e289 = select(_e286, _e274, _e288);
                    let _e300 = (select(0f, select(1f, _e257, (_e257 < 1f)), (_e257 > 0f)) * 2.9f);
                    let _e302 = floor((_e300 + 0.5f));
                    if ((_e302 - _e300) == 0.5f) {
                        let _e308 = ((floor((_e302 * 0.5f)) * 2f) != _e302);
                        if _e308 {
                            phi_1747_ = (_e302 - 1f);
                        } else {
                            phi_1747_ = f32();
                        }
                        let _e311 = phi_1747_;
                        phi_1751_ = _e311;
                        phi_1752_ = select(true, false, _e308);
                    } else {
                        phi_1751_ = f32();
                        phi_1752_ = true;
                    }
                    let _e314 = phi_1751_;
                    let _e316 = phi_1752_;
                    let _e317 = select(_e314, _e302, _e316);
                    let _e329 = (select(0f, select(1f, _e262, (_e262 < 1f)), (_e262 > 0f)) * 2.9f);
                    let _e331 = floor((_e329 + 0.5f));
                    if ((_e331 - _e329) == 0.5f) {
                        let _e337 = ((floor((_e331 * 0.5f)) * 2f) != _e331);
                        if _e337 {
                            phi_1790_ = (_e331 - 1f);
                        } else {
                            phi_1790_ = f32();
                        }
                        let _e340 = phi_1790_;
                        phi_1794_ = _e340;
                        phi_1795_ = select(true, false, _e337);
                    } else {
                        phi_1794_ = f32();
                        phi_1795_ = true;
                    }
                    let _e343 = phi_1794_;
                    let _e345 = phi_1795_;
                    let _e346 = select(_e343, _e331, _e345);
                    let _e358 = (select(0f, select(1f, _e267, (_e267 < 1f)), (_e267 > 0f)) * 2.9f);
                    let _e360 = floor((_e358 + 0.5f));
                    if ((_e360 - _e358) == 0.5f) {
                        let _e366 = ((floor((_e360 * 0.5f)) * 2f) != _e360);
                        if _e366 {
                            phi_1833_ = (_e360 - 1f);
                        } else {
                            phi_1833_ = f32();
                        }
                        let _e369 = phi_1833_;
                        phi_1837_ = _e369;
                        phi_1838_ = select(true, false, _e366);
                    } else {
                        phi_1837_ = f32();
                        phi_1838_ = true;
                    }
                    let _e372 = phi_1837_;
                    let _e374 = phi_1838_;
                    let _e375 = select(_e372, _e360, _e374);
                    let _e381 = ((((64u * select(select(u32(_e289), 0u, (_e289 < 0f)), 4294967295u, (_e289 > 4294967000f))) + (16u * select(select(u32(_e317), 0u, (_e317 < 0f)), 4294967295u, (_e317 > 4294967000f)))) + (4u * select(select(u32(_e346), 0u, (_e346 < 0f)), 4294967295u, (_e346 > 4294967000f)))) + select(select(u32(_e375), 0u, (_e375 < 0f)), 4294967295u, (_e375 > 4294967000f)));
                    if _e98 {
                    } else {
                        break;
                    }
                    if _e106 {
                        phi_671_ = (_e101 < _e105);
                    } else {
                        phi_671_ = false;
                    }
                    let _e384 = phi_671_;
                    if _e384 {
                        let _e397 = params.member.member.member_1[0u];
                        let _e399 = ((((((f32(_e59.x) + 0.5f) / _e76) * 2f) - 1f) * _e397) * _e101);
                        let _e406 = params.member.member.member_1[1u];
                        let _e408 = ((((((f32(_e59.y) + 0.5f) / _e86) * -2f) + 1f) * _e406) * _e101);
                        if (_e97 < _e63) {
                        } else {
                            break;
                        }
                        let _e412 = normals.member[_e97];
                        let _e420 = (f32((bitcast<i32>(((_e412 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e420 != _e420) {
                            phi_1861_ = true;
                        } else {
                            phi_1861_ = (-1f >= _e420);
                        }
                        let _e424 = phi_1861_;
                        let _e425 = select(_e420, -1f, _e424);
                        let _e435 = (f32((bitcast<i32>((((_e412 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e435 != _e435) {
                            phi_1876_ = true;
                        } else {
                            phi_1876_ = (-1f >= _e435);
                        }
                        let _e439 = phi_1876_;
                        let _e440 = select(_e435, -1f, _e439);
                        let _e443 = (1f - abs(_e425));
                        let _e444 = abs(_e440);
                        let _e445 = (_e443 - _e444);
                        if (_e445 < 0f) {
                            phi_764_ = vec2<f32>(((1f - _e444) * select(1f, -1f, (_e425 < 0f))), (_e443 * select(1f, -1f, (_e440 < 0f))));
                        } else {
                            phi_764_ = vec2<f32>(_e425, _e440);
                        }
                        let _e456 = phi_764_;
                        let _e465 = (1f / sqrt((((_e456.x * _e456.x) + (_e456.y * _e456.y)) + (_e445 * _e445))));
                        let _e466 = (_e456.x * _e465);
                        let _e467 = (_e456.y * _e465);
                        let _e468 = (_e445 * _e465);
                        let _e469 = -(_e468);
                        if ((((_e466 * -(_e399)) + (_e467 * -(_e408))) + (_e469 * -(_e101))) < 0f) {
                            phi_795_ = vec3<f32>(-(_e466), -(_e467), _e468);
                        } else {
                            phi_795_ = vec3<f32>(_e466, _e467, _e469);
                        }
                        let _e484 = phi_795_;
                        let _e487 = params.member.member_8;
                        phi_801_ = (_e59.y & 63u);
                        phi_804_ = (_e59.x & 63u);
                        phi_806_ = 32u;
                        phi_808_ = 0u;
                        loop {
                            let _e491 = phi_801_;
                            let _e493 = phi_804_;
                            let _e495 = phi_806_;
                            let _e497 = phi_808_;
                            local = _e497;
                            let _e498 = (_e495 > 0u);
                            if _e498 {
                                let _e501 = select(0u, 1u, ((_e493 & _e495) != 0u));
                                let _e504 = select(0u, 1u, ((_e491 & _e495) != 0u));
                                if (_e504 == 0u) {
                                    if (_e501 == 1u) {
                                        phi_837_ = (63u - _e491);
                                        phi_838_ = (63u - _e493);
                                    } else {
                                        phi_837_ = _e491;
                                        phi_838_ = _e493;
                                    }
                                    let _e515 = phi_837_;
                                    let _e517 = phi_838_;
                                    phi_839_ = _e517;
                                    phi_840_ = _e515;
                                } else {
                                    phi_839_ = _e491;
                                    phi_840_ = _e493;
                                }
                                let _e519 = phi_839_;
                                let _e521 = phi_840_;
                                phi_802_ = _e519;
                                phi_805_ = _e521;
                                phi_807_ = (_e495 / 2u);
                                phi_809_ = (_e497 + ((_e495 * _e495) * ((3u * _e501) ^ _e504)));
                            } else {
                                phi_802_ = u32();
                                phi_805_ = u32();
                                phi_807_ = u32();
                                phi_809_ = u32();
                            }
                            let _e524 = phi_802_;
                            let _e526 = phi_805_;
                            let _e528 = phi_807_;
                            let _e530 = phi_809_;
                            continue;
                            continuing {
                                phi_801_ = _e524;
                                phi_804_ = _e526;
                                phi_806_ = _e528;
                                phi_808_ = _e530;
                                break if !(_e498);
                            }
                        }
                        let _e535 = local;
                        let _e537 = f32((_e535 + (288u * (_e487 % 64u))));
                        let _e539 = (0.5f + (_e537 * 0.7548777f));
                        let _e543 = (0.5f + (_e537 * 0.5698403f));
                        let _e546 = (6.2831855f * (_e539 - floor(_e539)));
                        let _e547 = sin(_e546);
                        let _e548 = cos(_e546);
                        let _e551 = params.member.member_5;
                        let _e553 = select(_e551, 64u, (64u < _e551));
                        let _e555 = select(_e553, _e65, (_e65 < _e553));
                        let _e557 = select(1u, _e555, (1u < _e555));
                        phi_1939_ = false;
                        phi_878_ = 0u;
                        phi_881_ = 0f;
                        loop {
                            let _e559 = phi_1939_;
                            let _e561 = phi_878_;
                            let _e563 = phi_881_;
                            local_5 = _e563;
                            let _e564 = (_e561 < _e557);
                            if _e564 {
                                if (_e561 < _e65) {
                                } else {
                                    phi_2043_ = true;
                                    break;
                                }
                                let _e569 = kernel.member[_e561][0u];
                                let _e573 = kernel.member[_e561][1u];
                                let _e576 = ((_e548 * _e569) - (_e547 * _e573));
                                let _e579 = ((_e547 * _e569) + (_e548 * _e573));
                                let _e583 = ((1f - (_e576 * _e576)) - (_e579 * _e579));
                                if (_e583 != _e583) {
                                    phi_1891_ = true;
                                } else {
                                    phi_1891_ = (0f >= _e583);
                                }
                                let _e587 = phi_1891_;
                                let _e589 = sqrt(select(_e583, 0f, _e587));
                                let _e590 = -(_e589);
                                let _e594 = (-1f * _e484.z);
                                let _e595 = (-1f * _e484.x);
                                let _e597 = (1f / (_e594 + 1f));
                                let _e598 = (_e597 * _e484.y);
                                let _e602 = (_e598 * _e595);
                                let _e622 = (_e594 > 0.9997f);
                                let _e623 = (_e594 < -0.9997f);
                                let _e632 = params.member.member_6;
                                let _e634 = select(1u, _e632, (1u < _e632));
                                let _e637 = params.member.member_1;
                                let _e640 = params.member.member_3;
                                let _e643 = params.member.member_4;
                                phi_1024_ = 1u;
                                phi_1027_ = 0f;
                                phi_1029_ = 0f;
                                loop {
                                    let _e645 = phi_1024_;
                                    let _e647 = phi_1027_;
                                    let _e649 = phi_1029_;
                                    local_1 = _e647;
                                    local_2 = _e649;
                                    local_3 = _e647;
                                    local_4 = _e649;
                                    local_6 = _e649;
                                    let _e650 = (_e645 <= _e634);
                                    if _e650 {
                                        let _e655 = ((_e637 * (f32(_e645) - (_e543 - floor(_e543)))) / f32(_e634));
                                        let _e659 = (_e399 + (select(select(((((_e594 + (_e598 * _e484.y)) * _e576) + (_e602 * _e579)) + (_e595 * _e590)), _e576, _e623), _e576, _e622) * _e655));
                                        let _e660 = (_e408 + (select(select((((_e602 * _e576) + ((_e594 + ((_e597 * _e595) * _e595)) * _e579)) + (-(_e484.y) * _e590)), -(_e579), _e623), _e579, _e622) * _e655));
                                        let _e661 = (_e101 + (select(select((((_e484.x * _e576) + (_e484.y * _e579)) + (_e594 * _e590)), _e589, _e623), _e590, _e622) * _e655));
                                        let _e662 = (_e661 <= 0f);
                                        if _e662 {
                                            phi_1458_ = u32();
                                            phi_1459_ = f32();
                                            phi_1461_ = false;
                                            phi_1462_ = false;
                                            phi_1463_ = false;
                                            phi_1464_ = false;
                                            phi_1465_ = false;
                                            phi_1466_ = false;
                                        } else {
                                            let _e666 = (0.5f + ((0.5f * _e659) / (_e397 * _e661)));
                                            let _e670 = (0.5f - ((0.5f * _e660) / (_e406 * _e661)));
                                            let _e671 = (_e666 >= 0f);
                                            if _e671 {
                                                let _e672 = (_e666 <= 1f);
                                                if _e672 {
                                                    let _e673 = (_e670 >= 0f);
                                                    if _e673 {
                                                        let _e674 = (_e670 <= 1f);
                                                        if _e674 {
                                                            let _e676 = floor((_e666 * _e76));
                                                            if (_e676 > 0f) {
                                                                let _e682 = select(select(u32(_e676), 0u, (_e676 < 0f)), 4294967295u, (_e676 > 4294967000f));
                                                                let _e683 = (_e81 - 1u);
                                                                phi_1121_ = select(_e682, _e683, (_e683 < _e682));
                                                            } else {
                                                                phi_1121_ = 0u;
                                                            }
                                                            let _e687 = phi_1121_;
                                                            let _e689 = floor((_e670 * _e86));
                                                            if (_e689 > 0f) {
                                                                let _e695 = select(select(u32(_e689), 0u, (_e689 < 0f)), 4294967295u, (_e689 > 4294967000f));
                                                                let _e696 = (_e91 - 1u);
                                                                phi_1143_ = select(_e695, _e696, (_e696 < _e695));
                                                            } else {
                                                                phi_1143_ = 0u;
                                                            }
                                                            let _e700 = phi_1143_;
                                                            let _e702 = ((_e700 * _e81) + _e687);
                                                            if (_e702 < _e61) {
                                                            } else {
                                                                phi_1926_ = true;
                                                                phi_1676_ = bool();
                                                                phi_1675_ = bool();
                                                                phi_1674_ = bool();
                                                                phi_1673_ = bool();
                                                                phi_1672_ = bool();
                                                                phi_1671_ = bool();
                                                                phi_1670_ = bool();
                                                                phi_1668_ = f32();
                                                                phi_1667_ = f32();
                                                                break;
                                                            }
                                                            let _e706 = depth.member[_e702];
                                                            if (_e706 > 0f) {
                                                                phi_1160_ = (_e706 < _e105);
                                                            } else {
                                                                phi_1160_ = false;
                                                            }
                                                            let _e710 = phi_1160_;
                                                            let _e711 = select(_e105, _e706, _e710);
                                                            let _e714 = (((_e666 * 2f) - 1f) * _e397);
                                                            let _e718 = (((_e670 * -2f) + 1f) * _e406);
                                                            let _e720 = (_e659 - (_e714 * _e711));
                                                            let _e721 = (_e660 - (_e718 * _e711));
                                                            let _e722 = (_e661 - _e711);
                                                            let _e733 = (select(0f, select(1f, _e666, (_e666 < 1f)), (_e666 > 0f)) * _e76);
                                                            let _e738 = (select(0f, select(1f, _e670, (_e670 < 1f)), (_e670 > 0f)) * _e86);
                                                            let _e743 = select(select(u32(_e733), 0u, (_e733 < 0f)), 4294967295u, (_e733 > 4294967000f));
                                                            let _e744 = (_e81 - 1u);
                                                            let _e746 = select(_e743, _e744, (_e744 < _e743));
                                                            let _e751 = select(select(u32(_e738), 0u, (_e738 < 0f)), 4294967295u, (_e738 > 4294967000f));
                                                            let _e752 = (_e91 - 1u);
                                                            let _e754 = select(_e751, _e752, (_e752 < _e751));
                                                            let _e772 = ((_e754 * _e81) + _e746);
                                                            if (_e772 < _e63) {
                                                            } else {
                                                                phi_1926_ = true;
                                                                phi_1676_ = bool();
                                                                phi_1675_ = bool();
                                                                phi_1674_ = bool();
                                                                phi_1673_ = bool();
                                                                phi_1672_ = bool();
                                                                phi_1671_ = bool();
                                                                phi_1670_ = bool();
                                                                phi_1668_ = f32();
                                                                phi_1667_ = f32();
                                                                break;
                                                            }
                                                            let _e776 = normals.member[_e772];
                                                            let _e784 = (f32((bitcast<i32>(((_e776 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                                            if (_e784 != _e784) {
                                                                phi_1906_ = true;
                                                            } else {
                                                                phi_1906_ = (-1f >= _e784);
                                                            }
                                                            let _e788 = phi_1906_;
                                                            let _e789 = select(_e784, -1f, _e788);
                                                            let _e799 = (f32((bitcast<i32>((((_e776 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                                            if (_e799 != _e799) {
                                                                phi_1921_ = true;
                                                            } else {
                                                                phi_1921_ = (-1f >= _e799);
                                                            }
                                                            let _e803 = phi_1921_;
                                                            let _e804 = select(_e799, -1f, _e803);
                                                            let _e807 = (1f - abs(_e789));
                                                            let _e808 = abs(_e804);
                                                            let _e809 = (_e807 - _e808);
                                                            if (_e809 < 0f) {
                                                                phi_1349_ = vec2<f32>(((1f - _e808) * select(1f, -1f, (_e789 < 0f))), (_e807 * select(1f, -1f, (_e804 < 0f))));
                                                            } else {
                                                                phi_1349_ = vec2<f32>(_e789, _e804);
                                                            }
                                                            let _e820 = phi_1349_;
                                                            let _e829 = (1f / sqrt((((_e820.x * _e820.x) + (_e820.y * _e820.y)) + (_e809 * _e809))));
                                                            let _e830 = (_e820.x * _e829);
                                                            let _e831 = (_e820.y * _e829);
                                                            let _e833 = -((_e809 * _e829));
                                                            let _e837 = (((_e830 * _e714) + (_e831 * _e718)) + _e833);
                                                            if (abs(_e837) < 0.001f) {
                                                                phi_1394_ = _e711;
                                                            } else {
                                                                phi_1394_ = ((((_e830 * ((((((f32(_e746) + 0.5f) * (1f / _e76)) * 2f) - 1f) * _e397) * _e711)) + (_e831 * ((((((f32(_e754) + 0.5f) * (1f / _e86)) * -2f) + 1f) * _e406) * _e711))) + (_e833 * _e711)) / _e837);
                                                            }
                                                            let _e847 = phi_1394_;
                                                            if (_e746 == _e59.x) {
                                                                phi_1400_ = (_e754 == _e59.y);
                                                            } else {
                                                                phi_1400_ = false;
                                                            }
                                                            let _e851 = phi_1400_;
                                                            if _e851 {
                                                                phi_1416_ = true;
                                                                phi_1417_ = false;
                                                            } else {
                                                                let _e854 = (_e661 < (_e847 * (1f + _e640)));
                                                                if _e854 {
                                                                    phi_1415_ = false;
                                                                } else {
                                                                    phi_1415_ = ((_e661 - _e847) > _e643);
                                                                }
                                                                let _e858 = phi_1415_;
                                                                phi_1416_ = _e854;
                                                                phi_1417_ = _e858;
                                                            }
                                                            let _e860 = phi_1416_;
                                                            let _e862 = phi_1417_;
                                                            let _e863 = select(_e862, true, _e860);
                                                            if _e863 {
                                                                phi_1426_ = (_e645 + 1u);
                                                            } else {
                                                                phi_1426_ = u32();
                                                            }
                                                            let _e866 = phi_1426_;
                                                            phi_1428_ = _e866;
                                                            phi_1429_ = sqrt((((_e720 * _e720) + (_e721 * _e721)) + (_e722 * _e722)));
                                                            phi_1431_ = _e863;
                                                            phi_1432_ = select(true, false, _e863);
                                                        } else {
                                                            phi_1428_ = u32();
                                                            phi_1429_ = f32();
                                                            phi_1431_ = false;
                                                            phi_1432_ = false;
                                                        }
                                                        let _e869 = phi_1428_;
                                                        let _e871 = phi_1429_;
                                                        let _e873 = phi_1431_;
                                                        let _e875 = phi_1432_;
                                                        phi_1434_ = _e869;
                                                        phi_1435_ = _e871;
                                                        phi_1437_ = _e873;
                                                        phi_1438_ = _e875;
                                                        phi_1439_ = select(true, false, _e674);
                                                    } else {
                                                        phi_1434_ = u32();
                                                        phi_1435_ = f32();
                                                        phi_1437_ = false;
                                                        phi_1438_ = false;
                                                        phi_1439_ = false;
                                                    }
                                                    let _e878 = phi_1434_;
                                                    let _e880 = phi_1435_;
                                                    let _e882 = phi_1437_;
                                                    let _e884 = phi_1438_;
                                                    let _e886 = phi_1439_;
                                                    phi_1441_ = _e878;
                                                    phi_1442_ = _e880;
                                                    phi_1444_ = _e882;
                                                    phi_1445_ = _e884;
                                                    phi_1446_ = _e886;
                                                    phi_1447_ = select(true, false, _e673);
                                                } else {
                                                    phi_1441_ = u32();
                                                    phi_1442_ = f32();
                                                    phi_1444_ = false;
                                                    phi_1445_ = false;
                                                    phi_1446_ = false;
                                                    phi_1447_ = false;
                                                }
                                                let _e889 = phi_1441_;
                                                let _e891 = phi_1442_;
                                                let _e893 = phi_1444_;
                                                let _e895 = phi_1445_;
                                                let _e897 = phi_1446_;
                                                let _e899 = phi_1447_;
                                                phi_1449_ = _e889;
                                                phi_1450_ = _e891;
                                                phi_1452_ = _e893;
                                                phi_1453_ = _e895;
                                                phi_1454_ = _e897;
                                                phi_1455_ = _e899;
                                                phi_1456_ = select(true, false, _e672);
                                            } else {
                                                phi_1449_ = u32();
                                                phi_1450_ = f32();
                                                phi_1452_ = false;
                                                phi_1453_ = false;
                                                phi_1454_ = false;
                                                phi_1455_ = false;
                                                phi_1456_ = false;
                                            }
                                            let _e902 = phi_1449_;
                                            let _e904 = phi_1450_;
                                            let _e906 = phi_1452_;
                                            let _e908 = phi_1453_;
                                            let _e910 = phi_1454_;
                                            let _e912 = phi_1455_;
                                            let _e914 = phi_1456_;
                                            phi_1458_ = _e902;
                                            phi_1459_ = _e904;
                                            phi_1461_ = _e906;
                                            phi_1462_ = _e908;
                                            phi_1463_ = _e910;
                                            phi_1464_ = _e912;
                                            phi_1465_ = _e914;
                                            phi_1466_ = select(true, false, _e671);
                                        }
                                        let _e917 = phi_1458_;
                                        let _e919 = phi_1459_;
                                        let _e921 = phi_1461_;
                                        let _e923 = phi_1462_;
                                        let _e925 = phi_1463_;
                                        let _e927 = phi_1464_;
                                        let _e929 = phi_1465_;
                                        let _e931 = phi_1466_;
                                        phi_1025_ = _e917;
                                        phi_1028_ = _e919;
                                        phi_1030_ = _e655;
                                        phi_1469_ = _e921;
                                        phi_1470_ = _e662;
                                        phi_1472_ = _e923;
                                        phi_1473_ = _e925;
                                        phi_1474_ = _e927;
                                        phi_1475_ = _e929;
                                        phi_1476_ = _e931;
                                    } else {
                                        phi_1025_ = u32();
                                        phi_1028_ = f32();
                                        phi_1030_ = f32();
                                        phi_1469_ = false;
                                        phi_1470_ = false;
                                        phi_1472_ = false;
                                        phi_1473_ = false;
                                        phi_1474_ = false;
                                        phi_1475_ = false;
                                        phi_1476_ = false;
                                    }
                                    let _e933 = phi_1025_;
                                    let _e935 = phi_1028_;
                                    let _e937 = phi_1030_;
                                    let _e939 = phi_1469_;
                                    let _e941 = phi_1470_;
                                    let _e943 = phi_1472_;
                                    let _e945 = phi_1473_;
                                    let _e947 = phi_1474_;
                                    let _e949 = phi_1475_;
                                    let _e951 = phi_1476_;
                                    continue;
                                    continuing {
                                        phi_1024_ = _e933;
                                        phi_1027_ = _e935;
                                        phi_1029_ = _e937;
                                        phi_1926_ = _e559;
                                        phi_1676_ = _e951;
                                        phi_1675_ = _e949;
                                        phi_1674_ = _e947;
                                        phi_1673_ = _e945;
                                        phi_1672_ = _e943;
                                        phi_1671_ = select(true, false, _e650);
                                        phi_1670_ = _e941;
                                        phi_1668_ = _e935;
                                        phi_1667_ = _e937;
                                        break if !(_e939);
                                    }
                                }
                                let _e955 = phi_1926_;
                                let _e957 = phi_1676_;
                                let _e959 = phi_1675_;
                                let _e961 = phi_1674_;
                                let _e963 = phi_1673_;
                                let _e965 = phi_1672_;
                                let _e967 = phi_1671_;
                                let _e969 = phi_1670_;
                                let _e971 = phi_1668_;
                                let _e973 = phi_1667_;
                                phi_2043_ = _e955;
                                if _e955 {
                                    break;
                                }
                                let _e974 = select(_e967, false, _e969);
                                let _e980 = select(select(_e965, false, _e969), false, _e974);
                                if _e980 {
                                    let _e987 = local_1;
                                    let _e988 = (_e987 + _e971);
                                    if (_e988 < 0.000001f) {
                                        let _e1214 = local_6;
                                        phi_1507_ = _e1214;
                                    } else {
                                        let _e991 = local_2;
                                        let _e994 = local_3;
                                        let _e998 = local_4;
                                        phi_1507_ = (_e998 + ((_e994 * (_e973 - _e991)) / _e988));
                                    }
                                    let _e1001 = phi_1507_;
                                    phi_1509_ = type_25(_e1001, true);
                                } else {
                                    phi_1509_ = type_25();
                                }
                                let _e1004 = phi_1509_;
                                let _e1005 = select(select(select(_e963, false, _e969), false, _e974), false, _e980);
                                let _e1011 = select(select(select(select(_e961, false, _e969), false, _e974), false, _e980), false, _e1005);
                                let _e1016 = select(select(select(select(select(_e959, false, _e969), false, _e974), false, _e980), false, _e1005), false, _e1011);
                                let _e1021 = select(select(select(select(select(select(_e957, false, _e969), false, _e974), false, _e980), false, _e1005), false, _e1011), false, _e1016);
                                let _e1025 = select(select(select(_e1005, true, _e1011), true, _e1016), true, _e1021);
                                if select(select(select(select(select(select(select(_e974, false, _e980), false, _e1005), false, _e1011), false, _e1016), false, _e1021), false, _e1025), true, select(select(select(select(select(select(select(_e969, false, _e974), false, _e980), false, _e1005), false, _e1011), false, _e1016), false, _e1021), true, _e1025)) {
                                    phi_1558_ = type_25(_e637, false);
                                } else {
                                    phi_1558_ = _e1004;
                                }
                                let _e1033 = phi_1558_;
                                if _e1033.member_1 {
                                    let _e1038 = params.member.member_7;
                                    if (_e1038 == 1u) {
                                        phi_1583_ = 0f;
                                    } else {
                                        let _e1040 = (_e1033.member / _e637);
                                        phi_1583_ = select(0f, select(1f, _e1040, (_e1040 < 1f)), (_e1040 > 0f));
                                    }
                                    let _e1046 = phi_1583_;
                                    phi_1584_ = _e1046;
                                } else {
                                    phi_1584_ = 1f;
                                }
                                let _e1048 = phi_1584_;
                                phi_2044_ = _e955;
                                phi_879_ = (_e561 + 1u);
                                phi_882_ = (_e563 + _e1048);
                            } else {
                                phi_2044_ = _e559;
                                phi_879_ = u32();
                                phi_882_ = f32();
                            }
                            let _e1052 = phi_2044_;
                            let _e1054 = phi_879_;
                            let _e1056 = phi_882_;
                            continue;
                            continuing {
                                phi_1939_ = _e1052;
                                phi_878_ = _e1054;
                                phi_881_ = _e1056;
                                phi_2043_ = _e1052;
                                break if !(_e564);
                            }
                        }
                        let _e1059 = phi_2043_;
                        if _e1059 {
                            break;
                        }
                        let _e1062 = local_5;
                        let _e1066 = params.member.member_2;
                        let _e1067 = pow((_e1062 / f32(_e557)), _e1066);
                        let _e1068 = (_e1067 * 0.6666667f);
                        let _e1074 = ((select(0f, select(1f, _e1068, (_e1068 < 1f)), (_e1068 > 0f)) * 255f) + 0.5f);
                        phi_1634_ = type_26(_e1067, select(select(u32(_e1074), 0u, (_e1074 < 0f)), 4294967295u, (_e1074 > 4294967000f)), _e381);
                    } else {
                        phi_1634_ = type_26(1f, 170u, _e381);
                    }
                    let _e1083 = phi_1634_;
                    if (_e97 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e97] = _e1083.member;
                    if (_e97 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e97] = _e1083.member_1;
                    if (_e97 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e97] = _e1083.member_2;
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
