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
    var phi_248_: bool;
    var phi_272_: i32;
    var phi_291_: i32;
    var phi_320_: bool;
    var phi_344_: i32;
    var phi_363_: i32;
    var phi_392_: bool;
    var phi_416_: i32;
    var phi_435_: i32;
    var phi_464_: bool;
    var phi_488_: i32;
    var phi_507_: i32;
    var phi_536_: bool;
    var phi_600_: f32;
    var phi_611_: f32;
    var phi_622_: f32;
    var phi_633_: f32;
    var phi_1683_: f32;
    var phi_1698_: f32;
    var phi_1702_: f32;
    var phi_1703_: bool;
    var phi_1726_: f32;
    var phi_1741_: f32;
    var phi_1745_: f32;
    var phi_1746_: bool;
    var phi_1769_: f32;
    var phi_1784_: f32;
    var phi_1788_: f32;
    var phi_1789_: bool;
    var phi_1812_: f32;
    var phi_1827_: f32;
    var phi_1831_: f32;
    var phi_1832_: bool;
    var phi_672_: bool;
    var phi_1855_: bool;
    var phi_1870_: bool;
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
    var phi_1929_: bool;
    var phi_878_: u32;
    var phi_881_: f32;
    var phi_1885_: bool;
    var phi_994_: vec3<f32>;
    var phi_995_: vec3<f32>;
    var phi_996_: vec3<f32>;
    var phi_997_: vec3<f32>;
    var phi_998_: bool;
    var phi_1018_: u32;
    var phi_1021_: f32;
    var phi_1023_: f32;
    var phi_1118_: u32;
    var phi_1140_: u32;
    var phi_1157_: bool;
    var phi_1214_: f32;
    var phi_1227_: f32;
    var phi_1900_: bool;
    var phi_1915_: bool;
    var phi_1344_: vec2<f32>;
    var phi_1388_: f32;
    var phi_1394_: bool;
    var phi_1409_: bool;
    var phi_1410_: bool;
    var phi_1411_: bool;
    var phi_1420_: u32;
    var phi_1422_: u32;
    var phi_1423_: f32;
    var phi_1425_: bool;
    var phi_1426_: bool;
    var phi_1428_: u32;
    var phi_1429_: f32;
    var phi_1431_: bool;
    var phi_1432_: bool;
    var phi_1433_: bool;
    var phi_1435_: u32;
    var phi_1436_: f32;
    var phi_1438_: bool;
    var phi_1439_: bool;
    var phi_1440_: bool;
    var phi_1441_: bool;
    var phi_1443_: u32;
    var phi_1444_: f32;
    var phi_1446_: bool;
    var phi_1447_: bool;
    var phi_1448_: bool;
    var phi_1449_: bool;
    var phi_1450_: bool;
    var phi_1452_: u32;
    var phi_1453_: f32;
    var phi_1455_: bool;
    var phi_1456_: bool;
    var phi_1457_: bool;
    var phi_1458_: bool;
    var phi_1459_: bool;
    var phi_1460_: bool;
    var phi_1019_: u32;
    var phi_1022_: f32;
    var phi_1024_: f32;
    var phi_1463_: bool;
    var phi_1464_: bool;
    var phi_1466_: bool;
    var phi_1467_: bool;
    var phi_1468_: bool;
    var phi_1469_: bool;
    var phi_1470_: bool;
    var phi_1920_: bool;
    var phi_1670_: bool;
    var phi_1669_: bool;
    var phi_1668_: bool;
    var phi_1667_: bool;
    var phi_1666_: bool;
    var phi_1665_: bool;
    var phi_1664_: bool;
    var phi_1662_: f32;
    var phi_1661_: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var local_4: f32;
    var phi_1501_: f32;
    var phi_1503_: type_25;
    var phi_1552_: type_25;
    var phi_1576_: f32;
    var phi_1577_: f32;
    var phi_1578_: f32;
    var phi_2035_: bool;
    var phi_879_: u32;
    var phi_882_: f32;
    var phi_2034_: bool;
    var local_5: f32;
    var phi_1596_: f32;
    var phi_1628_: type_26;
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
                        phi_248_ = (_e101 < _e105);
                    } else {
                        phi_248_ = false;
                    }
                    let _e109 = phi_248_;
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
                        phi_272_ = 0i;
                    } else {
                        phi_272_ = select(_e112, _e114, (_e112 > _e114));
                    }
                    let _e120 = phi_272_;
                    let _e122 = bitcast<i32>(_e59.y);
                    let _e124 = (bitcast<i32>(_e91) - 1i);
                    let _e125 = (0i <= _e124);
                    if _e125 {
                    } else {
                        break;
                    }
                    let _e126 = (_e122 < 0i);
                    if _e126 {
                        phi_291_ = 0i;
                    } else {
                        phi_291_ = select(_e122, _e124, (_e122 > _e124));
                    }
                    let _e130 = phi_291_;
                    let _e133 = ((bitcast<u32>(_e130) * _e81) + bitcast<u32>(_e120));
                    if (_e133 < _e61) {
                    } else {
                        break;
                    }
                    let _e137 = depth.member[_e133];
                    if (_e137 > 0f) {
                        phi_320_ = (_e137 < _e105);
                    } else {
                        phi_320_ = false;
                    }
                    let _e141 = phi_320_;
                    let _e143 = (_e111 + 1i);
                    if _e115 {
                    } else {
                        break;
                    }
                    if (_e143 < 0i) {
                        phi_344_ = 0i;
                    } else {
                        phi_344_ = select(_e143, _e114, (_e143 > _e114));
                    }
                    let _e148 = phi_344_;
                    if _e125 {
                    } else {
                        break;
                    }
                    if _e126 {
                        phi_363_ = 0i;
                    } else {
                        phi_363_ = select(_e122, _e124, (_e122 > _e124));
                    }
                    let _e153 = phi_363_;
                    let _e156 = ((bitcast<u32>(_e153) * _e81) + bitcast<u32>(_e148));
                    if (_e156 < _e61) {
                    } else {
                        break;
                    }
                    let _e160 = depth.member[_e156];
                    if (_e160 > 0f) {
                        phi_392_ = (_e160 < _e105);
                    } else {
                        phi_392_ = false;
                    }
                    let _e164 = phi_392_;
                    if _e115 {
                    } else {
                        break;
                    }
                    let _e166 = (_e111 < 0i);
                    if _e166 {
                        phi_416_ = 0i;
                    } else {
                        phi_416_ = select(_e111, _e114, (_e111 > _e114));
                    }
                    let _e170 = phi_416_;
                    let _e172 = (_e122 + -1i);
                    if _e125 {
                    } else {
                        break;
                    }
                    if (_e172 < 0i) {
                        phi_435_ = 0i;
                    } else {
                        phi_435_ = select(_e172, _e124, (_e172 > _e124));
                    }
                    let _e177 = phi_435_;
                    let _e180 = ((bitcast<u32>(_e177) * _e81) + bitcast<u32>(_e170));
                    if (_e180 < _e61) {
                    } else {
                        break;
                    }
                    let _e184 = depth.member[_e180];
                    if (_e184 > 0f) {
                        phi_464_ = (_e184 < _e105);
                    } else {
                        phi_464_ = false;
                    }
                    let _e188 = phi_464_;
                    if _e115 {
                    } else {
                        break;
                    }
                    if _e166 {
                        phi_488_ = 0i;
                    } else {
                        phi_488_ = select(_e111, _e114, (_e111 > _e114));
                    }
                    let _e193 = phi_488_;
                    let _e195 = (_e122 + 1i);
                    if _e125 {
                    } else {
                        break;
                    }
                    if (_e195 < 0i) {
                        phi_507_ = 0i;
                    } else {
                        phi_507_ = select(_e195, _e124, (_e195 > _e124));
                    }
                    let _e200 = phi_507_;
                    let _e203 = ((bitcast<u32>(_e200) * _e81) + bitcast<u32>(_e193));
                    if (_e203 < _e61) {
                    } else {
                        break;
                    }
                    let _e207 = depth.member[_e203];
                    if (_e207 > 0f) {
                        phi_536_ = (_e207 < _e105);
                    } else {
                        phi_536_ = false;
                    }
                    let _e211 = phi_536_;
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
                    if (_e248 > 0f) {
                        phi_600_ = select(1f, _e248, (_e248 < 1f));
                    } else {
                        phi_600_ = 0f;
                    }
                    let _e253 = phi_600_;
                    let _e254 = (1.25f - (select(_e232, _e228, (_e228 < _e232)) / _e243));
                    if (_e254 > 0f) {
                        phi_611_ = select(1f, _e254, (_e254 < 1f));
                    } else {
                        phi_611_ = 0f;
                    }
                    let _e259 = phi_611_;
                    let _e260 = (1.25f - (select(_e233, _e229, (_e229 < _e233)) / _e243));
                    if (_e260 > 0f) {
                        phi_622_ = select(1f, _e260, (_e260 < 1f));
                    } else {
                        phi_622_ = 0f;
                    }
                    let _e265 = phi_622_;
                    let _e266 = (1.25f - (select(_e234, _e230, (_e230 < _e234)) / _e243));
                    if (_e266 > 0f) {
                        phi_633_ = select(1f, _e266, (_e266 < 1f));
                    } else {
                        phi_633_ = 0f;
                    }
                    let _e271 = phi_633_;
                    if (_e253 > 0f) {
                        phi_1683_ = select(1f, _e253, (_e253 < 1f));
                    } else {
                        phi_1683_ = 0f;
                    }
                    let _e276 = phi_1683_;
                    let _e277 = (_e276 * 2.9f);
                    let _e279 = floor((_e277 + 0.5f));
                    if ((_e279 - _e277) == 0.5f) {
                        let _e285 = ((floor((_e279 * 0.5f)) * 2f) != _e279);
                        if _e285 {
                            phi_1698_ = (_e279 - 1f);
                        } else {
                            phi_1698_ = f32();
                        }
                        let _e288 = phi_1698_;
                        phi_1702_ = _e288;
                        phi_1703_ = select(true, false, _e285);
                    } else {
                        phi_1702_ = f32();
                        phi_1703_ = true;
                    }
                    let _e291 = phi_1702_;
                    let _e293 = phi_1703_;
                    let _e294 = select(_e291, _e279, _e293);
                    if (_e259 > 0f) {
                        phi_1726_ = select(1f, _e259, (_e259 < 1f));
                    } else {
                        phi_1726_ = 0f;
                    }
                    let _e305 = phi_1726_;
                    let _e306 = (_e305 * 2.9f);
                    let _e308 = floor((_e306 + 0.5f));
                    if ((_e308 - _e306) == 0.5f) {
                        let _e314 = ((floor((_e308 * 0.5f)) * 2f) != _e308);
                        if _e314 {
                            phi_1741_ = (_e308 - 1f);
                        } else {
                            phi_1741_ = f32();
                        }
                        let _e317 = phi_1741_;
                        phi_1745_ = _e317;
                        phi_1746_ = select(true, false, _e314);
                    } else {
                        phi_1745_ = f32();
                        phi_1746_ = true;
                    }
                    let _e320 = phi_1745_;
                    let _e322 = phi_1746_;
                    let _e323 = select(_e320, _e308, _e322);
                    if (_e265 > 0f) {
                        phi_1769_ = select(1f, _e265, (_e265 < 1f));
                    } else {
                        phi_1769_ = 0f;
                    }
                    let _e335 = phi_1769_;
                    let _e336 = (_e335 * 2.9f);
                    let _e338 = floor((_e336 + 0.5f));
                    if ((_e338 - _e336) == 0.5f) {
                        let _e344 = ((floor((_e338 * 0.5f)) * 2f) != _e338);
                        if _e344 {
                            phi_1784_ = (_e338 - 1f);
                        } else {
                            phi_1784_ = f32();
                        }
                        let _e347 = phi_1784_;
                        phi_1788_ = _e347;
                        phi_1789_ = select(true, false, _e344);
                    } else {
                        phi_1788_ = f32();
                        phi_1789_ = true;
                    }
                    let _e350 = phi_1788_;
                    let _e352 = phi_1789_;
                    let _e353 = select(_e350, _e338, _e352);
                    if (_e271 > 0f) {
                        phi_1812_ = select(1f, _e271, (_e271 < 1f));
                    } else {
                        phi_1812_ = 0f;
                    }
                    let _e365 = phi_1812_;
                    let _e366 = (_e365 * 2.9f);
                    let _e368 = floor((_e366 + 0.5f));
                    if ((_e368 - _e366) == 0.5f) {
                        let _e374 = ((floor((_e368 * 0.5f)) * 2f) != _e368);
                        if _e374 {
                            phi_1827_ = (_e368 - 1f);
                        } else {
                            phi_1827_ = f32();
                        }
                        let _e377 = phi_1827_;
                        phi_1831_ = _e377;
                        phi_1832_ = select(true, false, _e374);
                    } else {
                        phi_1831_ = f32();
                        phi_1832_ = true;
                    }
                    let _e380 = phi_1831_;
                    let _e382 = phi_1832_;
                    let _e383 = select(_e380, _e368, _e382);
                    let _e389 = ((((64u * select(select(u32(_e294), 0u, (_e294 < 0f)), 4294967295u, (_e294 > 4294967000f))) + (16u * select(select(u32(_e323), 0u, (_e323 < 0f)), 4294967295u, (_e323 > 4294967000f)))) + (4u * select(select(u32(_e353), 0u, (_e353 < 0f)), 4294967295u, (_e353 > 4294967000f)))) + select(select(u32(_e383), 0u, (_e383 < 0f)), 4294967295u, (_e383 > 4294967000f)));
                    if _e98 {
                    } else {
                        break;
                    }
                    if _e106 {
                        phi_672_ = (_e101 < _e105);
                    } else {
                        phi_672_ = false;
                    }
                    let _e392 = phi_672_;
                    if _e392 {
                        let _e405 = params.member.member.member_1[0u];
                        let _e407 = ((((2f * ((f32(_e59.x) + 0.5f) / _e76)) - 1f) * _e405) * _e101);
                        let _e414 = params.member.member.member_1[1u];
                        let _e416 = (((1f - (2f * ((f32(_e59.y) + 0.5f) / _e86))) * _e414) * _e101);
                        if (_e97 < _e63) {
                        } else {
                            break;
                        }
                        let _e420 = normals.member[_e97];
                        let _e428 = (f32((bitcast<i32>(((_e420 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e428 != _e428) {
                            phi_1855_ = true;
                        } else {
                            phi_1855_ = (-1f >= _e428);
                        }
                        let _e432 = phi_1855_;
                        let _e433 = select(_e428, -1f, _e432);
                        let _e443 = (f32((bitcast<i32>((((_e420 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e443 != _e443) {
                            phi_1870_ = true;
                        } else {
                            phi_1870_ = (-1f >= _e443);
                        }
                        let _e447 = phi_1870_;
                        let _e448 = select(_e443, -1f, _e447);
                        let _e451 = (1f - abs(_e433));
                        let _e452 = abs(_e448);
                        let _e453 = (_e451 - _e452);
                        if (_e453 < 0f) {
                            phi_764_ = vec2<f32>(((1f - _e452) * select(1f, -1f, (_e433 < 0f))), (_e451 * select(1f, -1f, (_e448 < 0f))));
                        } else {
                            phi_764_ = vec2<f32>(_e433, _e448);
                        }
                        let _e464 = phi_764_;
                        let _e473 = (1f / sqrt((((_e464.x * _e464.x) + (_e464.y * _e464.y)) + (_e453 * _e453))));
                        let _e474 = (_e464.x * _e473);
                        let _e475 = (_e464.y * _e473);
                        let _e476 = (_e453 * _e473);
                        let _e477 = -(_e476);
                        if ((((_e474 * -(_e407)) + (_e475 * -(_e416))) + (_e477 * -(_e101))) < 0f) {
                            phi_795_ = vec3<f32>(-(_e474), -(_e475), _e476);
                        } else {
                            phi_795_ = vec3<f32>(_e474, _e475, _e477);
                        }
                        let _e492 = phi_795_;
                        let _e495 = params.member.member_8;
                        phi_801_ = (_e59.y & 63u);
                        phi_804_ = (_e59.x & 63u);
                        phi_806_ = 32u;
                        phi_808_ = 0u;
                        loop {
                            let _e499 = phi_801_;
                            let _e501 = phi_804_;
                            let _e503 = phi_806_;
                            let _e505 = phi_808_;
                            local = _e505;
                            let _e506 = (_e503 > 0u);
                            if _e506 {
                                let _e509 = select(0u, 1u, ((_e501 & _e503) != 0u));
                                let _e512 = select(0u, 1u, ((_e499 & _e503) != 0u));
                                if (_e512 == 0u) {
                                    if (_e509 == 1u) {
                                        phi_837_ = (63u - _e499);
                                        phi_838_ = (63u - _e501);
                                    } else {
                                        phi_837_ = _e499;
                                        phi_838_ = _e501;
                                    }
                                    let _e523 = phi_837_;
                                    let _e525 = phi_838_;
                                    phi_839_ = _e525;
                                    phi_840_ = _e523;
                                } else {
                                    phi_839_ = _e499;
                                    phi_840_ = _e501;
                                }
                                let _e527 = phi_839_;
                                let _e529 = phi_840_;
                                phi_802_ = _e527;
                                phi_805_ = _e529;
                                phi_807_ = (_e503 / 2u);
                                phi_809_ = (_e505 + ((_e503 * _e503) * ((3u * _e509) ^ _e512)));
                            } else {
                                phi_802_ = u32();
                                phi_805_ = u32();
                                phi_807_ = u32();
                                phi_809_ = u32();
                            }
                            let _e532 = phi_802_;
                            let _e534 = phi_805_;
                            let _e536 = phi_807_;
                            let _e538 = phi_809_;
                            continue;
                            continuing {
                                phi_801_ = _e532;
                                phi_804_ = _e534;
                                phi_806_ = _e536;
                                phi_808_ = _e538;
                                break if !(_e506);
                            }
                        }
                        let _e543 = local;
                        let _e545 = f32((_e543 + (288u * (_e495 % 64u))));
                        let _e547 = (0.5f + (_e545 * 0.7548777f));
                        let _e551 = (0.5f + (_e545 * 0.5698403f));
                        let _e554 = (6.2831855f * (_e547 - floor(_e547)));
                        let _e555 = sin(_e554);
                        let _e556 = cos(_e554);
                        let _e559 = params.member.member_5;
                        let _e561 = select(_e559, 64u, (64u < _e559));
                        let _e563 = select(_e561, _e65, (_e65 < _e561));
                        let _e565 = select(1u, _e563, (1u < _e563));
                        phi_1929_ = false;
                        phi_878_ = 0u;
                        phi_881_ = 0f;
                        loop {
                            let _e567 = phi_1929_;
                            let _e569 = phi_878_;
                            let _e571 = phi_881_;
                            local_5 = _e571;
                            let _e572 = (_e569 < _e565);
                            if _e572 {
                                if (_e569 < _e65) {
                                } else {
                                    phi_2034_ = true;
                                    break;
                                }
                                let _e577 = kernel.member[_e569][0u];
                                let _e581 = kernel.member[_e569][1u];
                                let _e584 = ((_e556 * _e577) - (_e555 * _e581));
                                let _e587 = ((_e555 * _e577) + (_e556 * _e581));
                                let _e591 = ((1f - (_e584 * _e584)) - (_e587 * _e587));
                                if (_e591 != _e591) {
                                    phi_1885_ = true;
                                } else {
                                    phi_1885_ = (0f >= _e591);
                                }
                                let _e595 = phi_1885_;
                                let _e597 = sqrt(select(_e591, 0f, _e595));
                                let _e598 = -(_e597);
                                let _e603 = (-1f * _e492.z);
                                if (_e603 > 0.9997f) {
                                    phi_996_ = vec3<f32>(_e584, _e587, _e598);
                                    phi_997_ = vec3<f32>();
                                    phi_998_ = true;
                                } else {
                                    let _e605 = (_e603 < -0.9997f);
                                    if _e605 {
                                        phi_994_ = vec3<f32>(_e584, -(_e587), _e597);
                                        phi_995_ = vec3<f32>();
                                    } else {
                                        let _e608 = (-1f * _e492.x);
                                        let _e610 = (1f / (1f + _e603));
                                        let _e611 = (_e610 * _e492.y);
                                        let _e615 = (_e611 * _e608);
                                        phi_994_ = vec3<f32>();
                                        phi_995_ = vec3<f32>(((((_e603 + (_e611 * _e492.y)) * _e584) + (_e615 * _e587)) + (_e608 * _e598)), (((_e615 * _e584) + ((_e603 + ((_e610 * _e608) * _e608)) * _e587)) + (-(_e492.y) * _e598)), (((_e492.x * _e584) + (_e492.y * _e587)) + (_e603 * _e598)));
                                    }
                                    let _e636 = phi_994_;
                                    let _e638 = phi_995_;
                                    phi_996_ = _e636;
                                    phi_997_ = _e638;
                                    phi_998_ = _e605;
                                }
                                let _e640 = phi_996_;
                                let _e642 = phi_997_;
                                let _e644 = phi_998_;
                                let _e646 = select(_e642, _e640, vec3(_e644));
                                let _e649 = params.member.member_6;
                                let _e651 = select(1u, _e649, (1u < _e649));
                                let _e654 = params.member.member_1;
                                let _e657 = params.member.member_3;
                                let _e660 = params.member.member_4;
                                phi_1018_ = 1u;
                                phi_1021_ = 0f;
                                phi_1023_ = 0f;
                                loop {
                                    let _e662 = phi_1018_;
                                    let _e664 = phi_1021_;
                                    let _e666 = phi_1023_;
                                    local_1 = _e664;
                                    local_2 = _e666;
                                    local_3 = _e664;
                                    local_4 = _e666;
                                    local_6 = _e666;
                                    let _e667 = (_e662 <= _e651);
                                    if _e667 {
                                        let _e672 = ((_e654 * (f32(_e662) - (_e551 - floor(_e551)))) / f32(_e651));
                                        let _e679 = (_e407 + (_e646.x * _e672));
                                        let _e680 = (_e416 + (_e646.y * _e672));
                                        let _e681 = (_e101 + (_e646.z * _e672));
                                        let _e682 = (_e681 <= 0f);
                                        if _e682 {
                                            phi_1452_ = u32();
                                            phi_1453_ = f32();
                                            phi_1455_ = false;
                                            phi_1456_ = false;
                                            phi_1457_ = false;
                                            phi_1458_ = false;
                                            phi_1459_ = false;
                                            phi_1460_ = false;
                                        } else {
                                            let _e686 = (0.5f + ((0.5f * _e679) / (_e405 * _e681)));
                                            let _e690 = (0.5f - ((0.5f * _e680) / (_e414 * _e681)));
                                            let _e691 = (_e686 >= 0f);
                                            if _e691 {
                                                let _e692 = (_e686 <= 1f);
                                                if _e692 {
                                                    let _e693 = (_e690 >= 0f);
                                                    if _e693 {
                                                        let _e694 = (_e690 <= 1f);
                                                        if _e694 {
                                                            let _e696 = floor((_e686 * _e76));
                                                            if (_e696 > 0f) {
                                                                let _e702 = select(select(u32(_e696), 0u, (_e696 < 0f)), 4294967295u, (_e696 > 4294967000f));
                                                                let _e703 = (_e81 - 1u);
                                                                phi_1118_ = select(_e702, _e703, (_e703 < _e702));
                                                            } else {
                                                                phi_1118_ = 0u;
                                                            }
                                                            let _e707 = phi_1118_;
                                                            let _e709 = floor((_e690 * _e86));
                                                            if (_e709 > 0f) {
                                                                let _e715 = select(select(u32(_e709), 0u, (_e709 < 0f)), 4294967295u, (_e709 > 4294967000f));
                                                                let _e716 = (_e91 - 1u);
                                                                phi_1140_ = select(_e715, _e716, (_e716 < _e715));
                                                            } else {
                                                                phi_1140_ = 0u;
                                                            }
                                                            let _e720 = phi_1140_;
                                                            let _e722 = ((_e720 * _e81) + _e707);
                                                            if (_e722 < _e61) {
                                                            } else {
                                                                phi_1920_ = true;
                                                                phi_1670_ = bool();
                                                                phi_1669_ = bool();
                                                                phi_1668_ = bool();
                                                                phi_1667_ = bool();
                                                                phi_1666_ = bool();
                                                                phi_1665_ = bool();
                                                                phi_1664_ = bool();
                                                                phi_1662_ = f32();
                                                                phi_1661_ = f32();
                                                                break;
                                                            }
                                                            let _e726 = depth.member[_e722];
                                                            if (_e726 > 0f) {
                                                                phi_1157_ = (_e726 < _e105);
                                                            } else {
                                                                phi_1157_ = false;
                                                            }
                                                            let _e730 = phi_1157_;
                                                            let _e731 = select(_e105, _e726, _e730);
                                                            let _e734 = (((2f * _e686) - 1f) * _e405);
                                                            let _e738 = ((1f - (2f * _e690)) * _e414);
                                                            let _e740 = (_e679 - (_e734 * _e731));
                                                            let _e741 = (_e680 - (_e738 * _e731));
                                                            let _e742 = (_e681 - _e731);
                                                            if (_e686 > 0f) {
                                                                phi_1214_ = select(1f, _e686, (_e686 < 1f));
                                                            } else {
                                                                phi_1214_ = 0f;
                                                            }
                                                            let _e753 = phi_1214_;
                                                            let _e754 = (_e753 * _e76);
                                                            if (_e690 > 0f) {
                                                                phi_1227_ = select(1f, _e690, (_e690 < 1f));
                                                            } else {
                                                                phi_1227_ = 0f;
                                                            }
                                                            let _e759 = phi_1227_;
                                                            let _e760 = (_e759 * _e86);
                                                            let _e765 = select(select(u32(_e754), 0u, (_e754 < 0f)), 4294967295u, (_e754 > 4294967000f));
                                                            let _e766 = (_e81 - 1u);
                                                            let _e768 = select(_e765, _e766, (_e766 < _e765));
                                                            let _e773 = select(select(u32(_e760), 0u, (_e760 < 0f)), 4294967295u, (_e760 > 4294967000f));
                                                            let _e774 = (_e91 - 1u);
                                                            let _e776 = select(_e773, _e774, (_e774 < _e773));
                                                            let _e794 = ((_e776 * _e81) + _e768);
                                                            if (_e794 < _e63) {
                                                            } else {
                                                                phi_1920_ = true;
                                                                phi_1670_ = bool();
                                                                phi_1669_ = bool();
                                                                phi_1668_ = bool();
                                                                phi_1667_ = bool();
                                                                phi_1666_ = bool();
                                                                phi_1665_ = bool();
                                                                phi_1664_ = bool();
                                                                phi_1662_ = f32();
                                                                phi_1661_ = f32();
                                                                break;
                                                            }
                                                            let _e798 = normals.member[_e794];
                                                            let _e806 = (f32((bitcast<i32>(((_e798 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                                            if (_e806 != _e806) {
                                                                phi_1900_ = true;
                                                            } else {
                                                                phi_1900_ = (-1f >= _e806);
                                                            }
                                                            let _e810 = phi_1900_;
                                                            let _e811 = select(_e806, -1f, _e810);
                                                            let _e821 = (f32((bitcast<i32>((((_e798 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                                            if (_e821 != _e821) {
                                                                phi_1915_ = true;
                                                            } else {
                                                                phi_1915_ = (-1f >= _e821);
                                                            }
                                                            let _e825 = phi_1915_;
                                                            let _e826 = select(_e821, -1f, _e825);
                                                            let _e829 = (1f - abs(_e811));
                                                            let _e830 = abs(_e826);
                                                            let _e831 = (_e829 - _e830);
                                                            if (_e831 < 0f) {
                                                                phi_1344_ = vec2<f32>(((1f - _e830) * select(1f, -1f, (_e811 < 0f))), (_e829 * select(1f, -1f, (_e826 < 0f))));
                                                            } else {
                                                                phi_1344_ = vec2<f32>(_e811, _e826);
                                                            }
                                                            let _e842 = phi_1344_;
                                                            let _e851 = (1f / sqrt((((_e842.x * _e842.x) + (_e842.y * _e842.y)) + (_e831 * _e831))));
                                                            let _e852 = (_e842.x * _e851);
                                                            let _e853 = (_e842.y * _e851);
                                                            let _e855 = -((_e831 * _e851));
                                                            let _e859 = (((_e852 * _e734) + (_e853 * _e738)) + _e855);
                                                            if (abs(_e859) < 0.001f) {
                                                                phi_1388_ = _e731;
                                                            } else {
                                                                phi_1388_ = ((((_e852 * ((((2f * ((f32(_e768) + 0.5f) * (1f / _e76))) - 1f) * _e405) * _e731)) + (_e853 * (((1f - (2f * ((f32(_e776) + 0.5f) * (1f / _e86)))) * _e414) * _e731))) + (_e855 * _e731)) / _e859);
                                                            }
                                                            let _e869 = phi_1388_;
                                                            if (_e768 == _e59.x) {
                                                                phi_1394_ = (_e776 == _e59.y);
                                                            } else {
                                                                phi_1394_ = false;
                                                            }
                                                            let _e873 = phi_1394_;
                                                            if _e873 {
                                                                phi_1410_ = true;
                                                                phi_1411_ = false;
                                                            } else {
                                                                let _e876 = (_e681 < (_e869 * (1f + _e657)));
                                                                if _e876 {
                                                                    phi_1409_ = false;
                                                                } else {
                                                                    phi_1409_ = ((_e681 - _e869) > _e660);
                                                                }
                                                                let _e880 = phi_1409_;
                                                                phi_1410_ = _e876;
                                                                phi_1411_ = _e880;
                                                            }
                                                            let _e882 = phi_1410_;
                                                            let _e884 = phi_1411_;
                                                            let _e885 = select(_e884, true, _e882);
                                                            if _e885 {
                                                                phi_1420_ = (_e662 + 1u);
                                                            } else {
                                                                phi_1420_ = u32();
                                                            }
                                                            let _e888 = phi_1420_;
                                                            phi_1422_ = _e888;
                                                            phi_1423_ = sqrt((((_e740 * _e740) + (_e741 * _e741)) + (_e742 * _e742)));
                                                            phi_1425_ = _e885;
                                                            phi_1426_ = select(true, false, _e885);
                                                        } else {
                                                            phi_1422_ = u32();
                                                            phi_1423_ = f32();
                                                            phi_1425_ = false;
                                                            phi_1426_ = false;
                                                        }
                                                        let _e891 = phi_1422_;
                                                        let _e893 = phi_1423_;
                                                        let _e895 = phi_1425_;
                                                        let _e897 = phi_1426_;
                                                        phi_1428_ = _e891;
                                                        phi_1429_ = _e893;
                                                        phi_1431_ = _e895;
                                                        phi_1432_ = _e897;
                                                        phi_1433_ = select(true, false, _e694);
                                                    } else {
                                                        phi_1428_ = u32();
                                                        phi_1429_ = f32();
                                                        phi_1431_ = false;
                                                        phi_1432_ = false;
                                                        phi_1433_ = false;
                                                    }
                                                    let _e900 = phi_1428_;
                                                    let _e902 = phi_1429_;
                                                    let _e904 = phi_1431_;
                                                    let _e906 = phi_1432_;
                                                    let _e908 = phi_1433_;
                                                    phi_1435_ = _e900;
                                                    phi_1436_ = _e902;
                                                    phi_1438_ = _e904;
                                                    phi_1439_ = _e906;
                                                    phi_1440_ = _e908;
                                                    phi_1441_ = select(true, false, _e693);
                                                } else {
                                                    phi_1435_ = u32();
                                                    phi_1436_ = f32();
                                                    phi_1438_ = false;
                                                    phi_1439_ = false;
                                                    phi_1440_ = false;
                                                    phi_1441_ = false;
                                                }
                                                let _e911 = phi_1435_;
                                                let _e913 = phi_1436_;
                                                let _e915 = phi_1438_;
                                                let _e917 = phi_1439_;
                                                let _e919 = phi_1440_;
                                                let _e921 = phi_1441_;
                                                phi_1443_ = _e911;
                                                phi_1444_ = _e913;
                                                phi_1446_ = _e915;
                                                phi_1447_ = _e917;
                                                phi_1448_ = _e919;
                                                phi_1449_ = _e921;
                                                phi_1450_ = select(true, false, _e692);
                                            } else {
                                                phi_1443_ = u32();
                                                phi_1444_ = f32();
                                                phi_1446_ = false;
                                                phi_1447_ = false;
                                                phi_1448_ = false;
                                                phi_1449_ = false;
                                                phi_1450_ = false;
                                            }
                                            let _e924 = phi_1443_;
                                            let _e926 = phi_1444_;
                                            let _e928 = phi_1446_;
                                            let _e930 = phi_1447_;
                                            let _e932 = phi_1448_;
                                            let _e934 = phi_1449_;
                                            let _e936 = phi_1450_;
                                            phi_1452_ = _e924;
                                            phi_1453_ = _e926;
                                            phi_1455_ = _e928;
                                            phi_1456_ = _e930;
                                            phi_1457_ = _e932;
                                            phi_1458_ = _e934;
                                            phi_1459_ = _e936;
                                            phi_1460_ = select(true, false, _e691);
                                        }
                                        let _e939 = phi_1452_;
                                        let _e941 = phi_1453_;
                                        let _e943 = phi_1455_;
                                        let _e945 = phi_1456_;
                                        let _e947 = phi_1457_;
                                        let _e949 = phi_1458_;
                                        let _e951 = phi_1459_;
                                        let _e953 = phi_1460_;
                                        phi_1019_ = _e939;
                                        phi_1022_ = _e941;
                                        phi_1024_ = _e672;
                                        phi_1463_ = _e943;
                                        phi_1464_ = _e682;
                                        phi_1466_ = _e945;
                                        phi_1467_ = _e947;
                                        phi_1468_ = _e949;
                                        phi_1469_ = _e951;
                                        phi_1470_ = _e953;
                                    } else {
                                        phi_1019_ = u32();
                                        phi_1022_ = f32();
                                        phi_1024_ = f32();
                                        phi_1463_ = false;
                                        phi_1464_ = false;
                                        phi_1466_ = false;
                                        phi_1467_ = false;
                                        phi_1468_ = false;
                                        phi_1469_ = false;
                                        phi_1470_ = false;
                                    }
                                    let _e955 = phi_1019_;
                                    let _e957 = phi_1022_;
                                    let _e959 = phi_1024_;
                                    let _e961 = phi_1463_;
                                    let _e963 = phi_1464_;
                                    let _e965 = phi_1466_;
                                    let _e967 = phi_1467_;
                                    let _e969 = phi_1468_;
                                    let _e971 = phi_1469_;
                                    let _e973 = phi_1470_;
                                    continue;
                                    continuing {
                                        phi_1018_ = _e955;
                                        phi_1021_ = _e957;
                                        phi_1023_ = _e959;
                                        phi_1920_ = _e567;
                                        phi_1670_ = _e973;
                                        phi_1669_ = _e971;
                                        phi_1668_ = _e969;
                                        phi_1667_ = _e967;
                                        phi_1666_ = _e965;
                                        phi_1665_ = select(true, false, _e667);
                                        phi_1664_ = _e963;
                                        phi_1662_ = _e957;
                                        phi_1661_ = _e959;
                                        break if !(_e961);
                                    }
                                }
                                let _e977 = phi_1920_;
                                let _e979 = phi_1670_;
                                let _e981 = phi_1669_;
                                let _e983 = phi_1668_;
                                let _e985 = phi_1667_;
                                let _e987 = phi_1666_;
                                let _e989 = phi_1665_;
                                let _e991 = phi_1664_;
                                let _e993 = phi_1662_;
                                let _e995 = phi_1661_;
                                phi_2034_ = _e977;
                                if _e977 {
                                    break;
                                }
                                let _e996 = select(_e989, false, _e991);
                                let _e1002 = select(select(_e987, false, _e991), false, _e996);
                                if _e1002 {
                                    let _e1009 = local_1;
                                    let _e1010 = (_e1009 + _e993);
                                    if (_e1010 < 0.000001f) {
                                        let _e1253 = local_6;
                                        phi_1501_ = _e1253;
                                    } else {
                                        let _e1013 = local_2;
                                        let _e1016 = local_3;
                                        let _e1020 = local_4;
                                        phi_1501_ = (_e1020 + ((_e1016 * (_e995 - _e1013)) / _e1010));
                                    }
                                    let _e1023 = phi_1501_;
                                    phi_1503_ = type_25(_e1023, true);
                                } else {
                                    phi_1503_ = type_25();
                                }
                                let _e1026 = phi_1503_;
                                let _e1027 = select(select(select(_e985, false, _e991), false, _e996), false, _e1002);
                                let _e1033 = select(select(select(select(_e983, false, _e991), false, _e996), false, _e1002), false, _e1027);
                                let _e1038 = select(select(select(select(select(_e981, false, _e991), false, _e996), false, _e1002), false, _e1027), false, _e1033);
                                let _e1043 = select(select(select(select(select(select(_e979, false, _e991), false, _e996), false, _e1002), false, _e1027), false, _e1033), false, _e1038);
                                let _e1047 = select(select(select(_e1027, true, _e1033), true, _e1038), true, _e1043);
                                if select(select(select(select(select(select(select(_e996, false, _e1002), false, _e1027), false, _e1033), false, _e1038), false, _e1043), false, _e1047), true, select(select(select(select(select(select(select(_e991, false, _e996), false, _e1002), false, _e1027), false, _e1033), false, _e1038), false, _e1043), true, _e1047)) {
                                    phi_1552_ = type_25(_e654, false);
                                } else {
                                    phi_1552_ = _e1026;
                                }
                                let _e1055 = phi_1552_;
                                if _e1055.member_1 {
                                    let _e1060 = params.member.member_7;
                                    if (_e1060 == 1u) {
                                        phi_1577_ = 0f;
                                    } else {
                                        let _e1062 = (_e1055.member / _e654);
                                        if (_e1062 > 0f) {
                                            phi_1576_ = select(1f, _e1062, (_e1062 < 1f));
                                        } else {
                                            phi_1576_ = 0f;
                                        }
                                        let _e1067 = phi_1576_;
                                        phi_1577_ = _e1067;
                                    }
                                    let _e1069 = phi_1577_;
                                    phi_1578_ = _e1069;
                                } else {
                                    phi_1578_ = 1f;
                                }
                                let _e1071 = phi_1578_;
                                phi_2035_ = _e977;
                                phi_879_ = (_e569 + 1u);
                                phi_882_ = (_e571 + _e1071);
                            } else {
                                phi_2035_ = _e567;
                                phi_879_ = u32();
                                phi_882_ = f32();
                            }
                            let _e1075 = phi_2035_;
                            let _e1077 = phi_879_;
                            let _e1079 = phi_882_;
                            continue;
                            continuing {
                                phi_1929_ = _e1075;
                                phi_878_ = _e1077;
                                phi_881_ = _e1079;
                                phi_2034_ = _e1075;
                                break if !(_e572);
                            }
                        }
                        let _e1082 = phi_2034_;
                        if _e1082 {
                            break;
                        }
                        let _e1085 = local_5;
                        let _e1089 = params.member.member_2;
                        let _e1090 = pow((_e1085 / f32(_e565)), _e1089);
                        let _e1091 = (_e1090 * 0.6666667f);
                        if (_e1091 > 0f) {
                            phi_1596_ = select(1f, _e1091, (_e1091 < 1f));
                        } else {
                            phi_1596_ = 0f;
                        }
                        let _e1096 = phi_1596_;
                        let _e1098 = ((_e1096 * 255f) + 0.5f);
                        phi_1628_ = type_26(_e1090, select(select(u32(_e1098), 0u, (_e1098 < 0f)), 4294967295u, (_e1098 > 4294967000f)), _e389);
                    } else {
                        phi_1628_ = type_26(1f, 170u, _e389);
                    }
                    let _e1107 = phi_1628_;
                    if (_e97 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e97] = _e1107.member;
                    if (_e97 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e97] = _e1107.member_1;
                    if (_e97 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e97] = _e1107.member_2;
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
