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

struct type_20 {
    member: type_19,
}

struct type_22 {
    member: u32,
    member_1: u32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(4) 
var<uniform> params: type_20;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_253_: i32;
    var phi_272_: i32;
    var phi_312_: i32;
    var phi_331_: i32;
    var phi_371_: i32;
    var phi_390_: i32;
    var phi_430_: i32;
    var phi_449_: i32;
    var phi_529_: f32;
    var phi_540_: f32;
    var phi_551_: f32;
    var phi_562_: f32;
    var phi_1927_: f32;
    var phi_1942_: f32;
    var phi_1946_: f32;
    var phi_1947_: bool;
    var phi_1970_: f32;
    var phi_1985_: f32;
    var phi_1989_: f32;
    var phi_1990_: bool;
    var phi_2013_: f32;
    var phi_2028_: f32;
    var phi_2032_: f32;
    var phi_2033_: bool;
    var phi_2056_: f32;
    var phi_2071_: f32;
    var phi_2075_: f32;
    var phi_2076_: bool;
    var phi_2099_: bool;
    var phi_2114_: bool;
    var phi_665_: vec2<f32>;
    var phi_693_: vec3<f32>;
    var phi_714_: u32;
    var phi_717_: u32;
    var phi_719_: u32;
    var phi_721_: u32;
    var phi_750_: u32;
    var phi_751_: u32;
    var phi_752_: u32;
    var phi_753_: u32;
    var phi_715_: u32;
    var phi_718_: u32;
    var phi_720_: u32;
    var phi_722_: u32;
    var local: u32;
    var phi_776_: bool;
    var phi_806_: f32;
    var phi_2383_: bool;
    var phi_816_: vec3<f32>;
    var phi_819_: u32;
    var phi_821_: f32;
    var phi_938_: f32;
    var phi_958_: f32;
    var phi_975_: f32;
    var phi_998_: u32;
    var phi_1001_: f32;
    var phi_1003_: f32;
    var phi_1057_: f32;
    var phi_1081_: f32;
    var phi_1104_: u32;
    var phi_1120_: f32;
    var phi_1122_: f32;
    var phi_1123_: bool;
    var phi_1143_: f32;
    var phi_1145_: f32;
    var phi_1146_: bool;
    var phi_1198_: u32;
    var phi_1218_: u32;
    var phi_1220_: u32;
    var phi_1223_: u32;
    var phi_1221_: u32;
    var phi_1224_: u32;
    var local_1: u32;
    var phi_1306_: u32;
    var phi_1326_: u32;
    var phi_1328_: u32;
    var phi_1331_: u32;
    var phi_1329_: u32;
    var phi_1332_: u32;
    var local_2: u32;
    var phi_1430_: f32;
    var phi_1436_: f32;
    var phi_1489_: f32;
    var phi_1495_: f32;
    var phi_2129_: bool;
    var phi_2144_: bool;
    var phi_999_: u32;
    var phi_1002_: f32;
    var phi_1004_: f32;
    var phi_2332_: bool;
    var local_3: f32;
    var local_4: f32;
    var phi_1521_: f32;
    var local_5: f32;
    var local_6: f32;
    var phi_1539_: f32;
    var phi_1695_: vec3<f32>;
    var phi_1696_: vec3<f32>;
    var phi_1697_: vec3<f32>;
    var phi_1698_: vec3<f32>;
    var phi_1699_: bool;
    var phi_1705_: vec3<f32>;
    var phi_2452_: bool;
    var phi_817_: vec3<f32>;
    var phi_820_: u32;
    var phi_822_: f32;
    var phi_2451_: bool;
    var local_7: f32;
    var phi_2159_: bool;
    var phi_1741_: f32;
    var local_8: vec3<f32>;
    var local_9: vec3<f32>;
    var local_10: vec3<f32>;
    var local_11: vec3<f32>;
    var phi_1771_: vec3<f32>;
    var phi_2175_: f32;
    var phi_2196_: f32;
    var phi_2217_: f32;
    var phi_2238_: f32;
    var phi_1793_: type_22;
    var phi_1794_: type_22;
    var phi_1841_: type_22;
    var phi_1842_: type_22;
    var phi_1843_: bool;
    var phi_1847_: type_22;

    switch bitcast<i32>(0u) {
        default: {
            let _e84 = id_1;
            let _e86 = arrayLength((&mips.member));
            let _e97 = params.member.member.member[0u];
            let _e102 = select(select(u32(_e97), 0u, (_e97 < 0f)), 4294967295u, (_e97 > 4294967000f));
            let _e107 = params.member.member.member[1u];
            let _e112 = select(select(u32(_e107), 0u, (_e107 < 0f)), 4294967295u, (_e107 > 4294967000f));
            if (_e84.x >= _e102) {
            } else {
                if (_e84.y >= _e112) {
                } else {
                    let _e118 = ((_e84.y * _e102) + _e84.x);
                    if (_e118 < _e86) {
                    } else {
                        break;
                    }
                    let _e122 = mips.member[_e118];
                    let _e123 = bitcast<i32>(_e84.x);
                    let _e124 = (_e123 + -1i);
                    let _e126 = (bitcast<i32>(_e102) - 1i);
                    let _e127 = (0i <= _e126);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e124 < 0i) {
                        phi_253_ = 0i;
                    } else {
                        phi_253_ = select(_e124, _e126, (_e124 > _e126));
                    }
                    let _e132 = phi_253_;
                    let _e134 = bitcast<i32>(_e84.y);
                    let _e136 = (bitcast<i32>(_e112) - 1i);
                    let _e137 = (0i <= _e136);
                    if _e137 {
                    } else {
                        break;
                    }
                    let _e138 = (_e134 < 0i);
                    if _e138 {
                        phi_272_ = 0i;
                    } else {
                        phi_272_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e142 = phi_272_;
                    let _e145 = ((bitcast<u32>(_e142) * _e102) + bitcast<u32>(_e132));
                    if (_e145 < _e86) {
                    } else {
                        break;
                    }
                    let _e149 = mips.member[_e145];
                    let _e150 = (_e123 + 1i);
                    if _e127 {
                    } else {
                        break;
                    }
                    if (_e150 < 0i) {
                        phi_312_ = 0i;
                    } else {
                        phi_312_ = select(_e150, _e126, (_e150 > _e126));
                    }
                    let _e155 = phi_312_;
                    if _e137 {
                    } else {
                        break;
                    }
                    if _e138 {
                        phi_331_ = 0i;
                    } else {
                        phi_331_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e160 = phi_331_;
                    let _e163 = ((bitcast<u32>(_e160) * _e102) + bitcast<u32>(_e155));
                    if (_e163 < _e86) {
                    } else {
                        break;
                    }
                    let _e167 = mips.member[_e163];
                    if _e127 {
                    } else {
                        break;
                    }
                    let _e168 = (_e123 < 0i);
                    if _e168 {
                        phi_371_ = 0i;
                    } else {
                        phi_371_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e172 = phi_371_;
                    let _e174 = (_e134 + -1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e174 < 0i) {
                        phi_390_ = 0i;
                    } else {
                        phi_390_ = select(_e174, _e136, (_e174 > _e136));
                    }
                    let _e179 = phi_390_;
                    let _e182 = ((bitcast<u32>(_e179) * _e102) + bitcast<u32>(_e172));
                    if (_e182 < _e86) {
                    } else {
                        break;
                    }
                    let _e186 = mips.member[_e182];
                    if _e127 {
                    } else {
                        break;
                    }
                    if _e168 {
                        phi_430_ = 0i;
                    } else {
                        phi_430_ = select(_e123, _e126, (_e123 > _e126));
                    }
                    let _e190 = phi_430_;
                    let _e192 = (_e134 + 1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e192 < 0i) {
                        phi_449_ = 0i;
                    } else {
                        phi_449_ = select(_e192, _e136, (_e192 > _e136));
                    }
                    let _e197 = phi_449_;
                    let _e200 = ((bitcast<u32>(_e197) * _e102) + bitcast<u32>(_e190));
                    if (_e200 < _e86) {
                    } else {
                        break;
                    }
                    let _e204 = mips.member[_e200];
                    let _e205 = (_e149 - _e122);
                    let _e206 = (_e167 - _e122);
                    let _e207 = (_e186 - _e122);
                    let _e208 = (_e204 - _e122);
                    let _e209 = (_e206 - _e205);
                    let _e211 = (_e208 - _e207);
                    let _e219 = abs(_e205);
                    let _e220 = abs(_e206);
                    let _e221 = abs(_e207);
                    let _e222 = abs(_e208);
                    let _e223 = abs((_e205 + (_e209 * 0.5f)));
                    let _e224 = abs((_e206 + (_e209 * -0.5f)));
                    let _e225 = abs((_e207 + (_e211 * 0.5f)));
                    let _e226 = abs((_e208 + (_e211 * -0.5f)));
                    let _e235 = (_e122 * 0.011f);
                    let _e240 = (1.25f - (select(_e223, _e219, (_e219 < _e223)) / _e235));
                    if (_e240 > 0f) {
                        phi_529_ = select(1f, _e240, (_e240 < 1f));
                    } else {
                        phi_529_ = 0f;
                    }
                    let _e245 = phi_529_;
                    let _e246 = (1.25f - (select(_e224, _e220, (_e220 < _e224)) / _e235));
                    if (_e246 > 0f) {
                        phi_540_ = select(1f, _e246, (_e246 < 1f));
                    } else {
                        phi_540_ = 0f;
                    }
                    let _e251 = phi_540_;
                    let _e252 = (1.25f - (select(_e225, _e221, (_e221 < _e225)) / _e235));
                    if (_e252 > 0f) {
                        phi_551_ = select(1f, _e252, (_e252 < 1f));
                    } else {
                        phi_551_ = 0f;
                    }
                    let _e257 = phi_551_;
                    let _e258 = (1.25f - (select(_e226, _e222, (_e222 < _e226)) / _e235));
                    if (_e258 > 0f) {
                        phi_562_ = select(1f, _e258, (_e258 < 1f));
                    } else {
                        phi_562_ = 0f;
                    }
                    let _e263 = phi_562_;
                    if (_e245 > 0f) {
                        phi_1927_ = select(1f, _e245, (_e245 < 1f));
                    } else {
                        phi_1927_ = 0f;
                    }
                    let _e268 = phi_1927_;
                    let _e269 = (_e268 * 2.9f);
                    let _e271 = floor((_e269 + 0.5f));
                    if ((_e271 - _e269) == 0.5f) {
                        let _e277 = ((floor((_e271 * 0.5f)) * 2f) != _e271);
                        if _e277 {
                            phi_1942_ = (_e271 - 1f);
                        } else {
                            phi_1942_ = f32();
                        }
                        let _e280 = phi_1942_;
                        phi_1946_ = _e280;
                        phi_1947_ = select(true, false, _e277);
                    } else {
                        phi_1946_ = f32();
                        phi_1947_ = true;
                    }
                    let _e283 = phi_1946_;
                    let _e285 = phi_1947_;
                    let _e286 = select(_e283, _e271, _e285);
                    if (_e251 > 0f) {
                        phi_1970_ = select(1f, _e251, (_e251 < 1f));
                    } else {
                        phi_1970_ = 0f;
                    }
                    let _e297 = phi_1970_;
                    let _e298 = (_e297 * 2.9f);
                    let _e300 = floor((_e298 + 0.5f));
                    if ((_e300 - _e298) == 0.5f) {
                        let _e306 = ((floor((_e300 * 0.5f)) * 2f) != _e300);
                        if _e306 {
                            phi_1985_ = (_e300 - 1f);
                        } else {
                            phi_1985_ = f32();
                        }
                        let _e309 = phi_1985_;
                        phi_1989_ = _e309;
                        phi_1990_ = select(true, false, _e306);
                    } else {
                        phi_1989_ = f32();
                        phi_1990_ = true;
                    }
                    let _e312 = phi_1989_;
                    let _e314 = phi_1990_;
                    let _e315 = select(_e312, _e300, _e314);
                    if (_e257 > 0f) {
                        phi_2013_ = select(1f, _e257, (_e257 < 1f));
                    } else {
                        phi_2013_ = 0f;
                    }
                    let _e327 = phi_2013_;
                    let _e328 = (_e327 * 2.9f);
                    let _e330 = floor((_e328 + 0.5f));
                    if ((_e330 - _e328) == 0.5f) {
                        let _e336 = ((floor((_e330 * 0.5f)) * 2f) != _e330);
                        if _e336 {
                            phi_2028_ = (_e330 - 1f);
                        } else {
                            phi_2028_ = f32();
                        }
                        let _e339 = phi_2028_;
                        phi_2032_ = _e339;
                        phi_2033_ = select(true, false, _e336);
                    } else {
                        phi_2032_ = f32();
                        phi_2033_ = true;
                    }
                    let _e342 = phi_2032_;
                    let _e344 = phi_2033_;
                    let _e345 = select(_e342, _e330, _e344);
                    if (_e263 > 0f) {
                        phi_2056_ = select(1f, _e263, (_e263 < 1f));
                    } else {
                        phi_2056_ = 0f;
                    }
                    let _e357 = phi_2056_;
                    let _e358 = (_e357 * 2.9f);
                    let _e360 = floor((_e358 + 0.5f));
                    if ((_e360 - _e358) == 0.5f) {
                        let _e366 = ((floor((_e360 * 0.5f)) * 2f) != _e360);
                        if _e366 {
                            phi_2071_ = (_e360 - 1f);
                        } else {
                            phi_2071_ = f32();
                        }
                        let _e369 = phi_2071_;
                        phi_2075_ = _e369;
                        phi_2076_ = select(true, false, _e366);
                    } else {
                        phi_2075_ = f32();
                        phi_2076_ = true;
                    }
                    let _e372 = phi_2075_;
                    let _e374 = phi_2076_;
                    let _e375 = select(_e372, _e360, _e374);
                    let _e381 = ((((64u * select(select(u32(_e286), 0u, (_e286 < 0f)), 4294967295u, (_e286 > 4294967000f))) + (16u * select(select(u32(_e315), 0u, (_e315 < 0f)), 4294967295u, (_e315 > 4294967000f)))) + (4u * select(select(u32(_e345), 0u, (_e345 < 0f)), 4294967295u, (_e345 > 4294967000f)))) + select(select(u32(_e375), 0u, (_e375 < 0f)), 4294967295u, (_e375 > 4294967000f)));
                    let _e386 = ((f32(_e84.x) + 0.5f) / _e97);
                    let _e387 = ((f32(_e84.y) + 0.5f) / _e107);
                    let _e388 = (_e122 * 0.99999f);
                    let _e395 = params.member.member.member_1[0u];
                    let _e397 = ((((2f * _e386) - 1f) * _e395) * _e388);
                    let _e404 = params.member.member.member_1[1u];
                    let _e406 = (((1f - (2f * _e387)) * _e404) * _e388);
                    let _e407 = -(_e397);
                    let _e408 = -(_e406);
                    let _e409 = (_e122 * -0.99999f);
                    let _e416 = (1f / sqrt((((_e407 * _e407) + (_e408 * _e408)) + (_e409 * _e409))));
                    let _e417 = (_e407 * _e416);
                    let _e418 = (_e408 * _e416);
                    let _e419 = (_e409 * _e416);
                    if (_e118 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e423 = normals.member[_e118];
                    let _e431 = (f32((bitcast<i32>(((_e423 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e431 != _e431) {
                        phi_2099_ = true;
                    } else {
                        phi_2099_ = (-1f >= _e431);
                    }
                    let _e435 = phi_2099_;
                    let _e436 = select(_e431, -1f, _e435);
                    let _e446 = (f32((bitcast<i32>((((_e423 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e446 != _e446) {
                        phi_2114_ = true;
                    } else {
                        phi_2114_ = (-1f >= _e446);
                    }
                    let _e450 = phi_2114_;
                    let _e451 = select(_e446, -1f, _e450);
                    let _e454 = (1f - abs(_e436));
                    let _e455 = abs(_e451);
                    let _e456 = (_e454 - _e455);
                    if (_e456 < 0f) {
                        phi_665_ = vec2<f32>(((1f - _e455) * select(1f, -1f, (_e436 < 0f))), (_e454 * select(1f, -1f, (_e451 < 0f))));
                    } else {
                        phi_665_ = vec2<f32>(_e436, _e451);
                    }
                    let _e467 = phi_665_;
                    let _e476 = (1f / sqrt((((_e467.x * _e467.x) + (_e467.y * _e467.y)) + (_e456 * _e456))));
                    let _e477 = (_e467.x * _e476);
                    let _e478 = (_e467.y * _e476);
                    let _e479 = (_e456 * _e476);
                    let _e480 = -(_e479);
                    if ((((_e477 * _e417) + (_e478 * _e418)) + (_e480 * _e419)) < 0f) {
                        phi_693_ = vec3<f32>(-(_e477), -(_e478), _e479);
                    } else {
                        phi_693_ = vec3<f32>(_e477, _e478, _e480);
                    }
                    let _e492 = phi_693_;
                    let _e495 = params.member.member_1;
                    let _e498 = params.member.member_2;
                    let _e499 = (_e495 * _e498);
                    let _e503 = (_e499 / (((_e122 * 1.99998f) * _e395) / _e97));
                    let _e507 = params.member.member_11;
                    phi_714_ = (_e84.y & 63u);
                    phi_717_ = (_e84.x & 63u);
                    phi_719_ = 32u;
                    phi_721_ = 0u;
                    loop {
                        let _e511 = phi_714_;
                        let _e513 = phi_717_;
                        let _e515 = phi_719_;
                        let _e517 = phi_721_;
                        local = _e517;
                        let _e518 = (_e515 > 0u);
                        if _e518 {
                            let _e521 = select(0u, 1u, ((_e513 & _e515) != 0u));
                            let _e524 = select(0u, 1u, ((_e511 & _e515) != 0u));
                            if (_e524 == 0u) {
                                if (_e521 == 1u) {
                                    phi_750_ = (63u - _e511);
                                    phi_751_ = (63u - _e513);
                                } else {
                                    phi_750_ = _e511;
                                    phi_751_ = _e513;
                                }
                                let _e535 = phi_750_;
                                let _e537 = phi_751_;
                                phi_752_ = _e537;
                                phi_753_ = _e535;
                            } else {
                                phi_752_ = _e511;
                                phi_753_ = _e513;
                            }
                            let _e539 = phi_752_;
                            let _e541 = phi_753_;
                            phi_715_ = _e539;
                            phi_718_ = _e541;
                            phi_720_ = (_e515 / 2u);
                            phi_722_ = (_e517 + ((_e515 * _e515) * ((3u * _e521) ^ _e524)));
                        } else {
                            phi_715_ = u32();
                            phi_718_ = u32();
                            phi_720_ = u32();
                            phi_722_ = u32();
                        }
                        let _e544 = phi_715_;
                        let _e546 = phi_718_;
                        let _e548 = phi_720_;
                        let _e550 = phi_722_;
                        continue;
                        continuing {
                            phi_714_ = _e544;
                            phi_717_ = _e546;
                            phi_719_ = _e548;
                            phi_721_ = _e550;
                            break if !(_e518);
                        }
                    }
                    let _e555 = local;
                    let _e557 = f32((_e555 + (288u * (_e507 % 64u))));
                    let _e559 = (0.5f + (_e557 * 0.7548777f));
                    let _e563 = (0.5f + (_e557 * 0.5698403f));
                    let _e569 = params.member.member.member_3;
                    if (_e122 > 0f) {
                        phi_776_ = (_e122 < _e569);
                    } else {
                        phi_776_ = false;
                    }
                    let _e573 = phi_776_;
                    if _e573 {
                        let _e576 = params.member.member_3;
                        let _e577 = (_e576 * _e499);
                        let _e579 = ((10f - _e503) * 0.01f);
                        if (_e579 > 0f) {
                            phi_806_ = select(1f, _e579, (_e579 < 1f));
                        } else {
                            phi_806_ = 0f;
                        }
                        let _e584 = phi_806_;
                        let _e588 = params.member.member_8;
                        let _e590 = select(1u, _e588, (1u < _e588));
                        phi_2383_ = false;
                        phi_816_ = vec3<f32>(0f, 0f, 0f);
                        phi_819_ = 0u;
                        phi_821_ = (0.5f * _e584);
                        loop {
                            let _e592 = phi_2383_;
                            let _e594 = phi_816_;
                            let _e596 = phi_819_;
                            let _e598 = phi_821_;
                            local_7 = _e598;
                            local_8 = _e594;
                            local_9 = _e594;
                            local_10 = _e594;
                            local_11 = _e594;
                            let _e599 = (_e596 < _e590);
                            if _e599 {
                                let _e604 = ((3.1415927f * (f32(_e596) + (_e559 - floor(_e559)))) / f32(_e590));
                                let _e605 = sin(_e604);
                                let _e606 = cos(_e604);
                                let _e612 = ((_e606 * _e417) + (_e605 * _e418));
                                let _e616 = (_e606 - (_e417 * _e612));
                                let _e617 = (_e605 - (_e418 * _e612));
                                let _e618 = -((_e419 * _e612));
                                let _e621 = ((_e617 * _e419) - (_e418 * _e618));
                                let _e624 = ((_e618 * _e417) - (_e419 * _e616));
                                let _e627 = ((_e616 * _e418) - (_e417 * _e617));
                                let _e634 = (1f / sqrt((((_e621 * _e621) + (_e624 * _e624)) + (_e627 * _e627))));
                                let _e635 = (_e621 * _e634);
                                let _e636 = (_e624 * _e634);
                                let _e637 = (_e627 * _e634);
                                let _e645 = (((_e492.x * _e635) + (_e492.y * _e636)) + (_e492.z * _e637));
                                let _e649 = (_e492.x - (_e635 * _e645));
                                let _e650 = (_e492.y - (_e636 * _e645));
                                let _e651 = (_e492.z - (_e637 * _e645));
                                let _e657 = sqrt((((_e649 * _e649) + (_e650 * _e650)) + (_e651 * _e651)));
                                let _e662 = (((_e616 * _e649) + (_e617 * _e650)) + (_e618 * _e651));
                                if (_e662 > 0f) {
                                    phi_938_ = 1f;
                                } else {
                                    phi_938_ = select(0f, -1f, (_e662 < 0f));
                                }
                                let _e667 = phi_938_;
                                let _e673 = ((((_e649 * _e417) + (_e650 * _e418)) + (_e651 * _e419)) / _e657);
                                if (_e673 > 0f) {
                                    phi_958_ = select(1f, _e673, (_e673 < 1f));
                                } else {
                                    phi_958_ = 0f;
                                }
                                let _e678 = phi_958_;
                                let _e679 = abs(_e678);
                                let _e690 = (((-0.156583f * _e679) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e679))) >> bitcast<u32>(1i))))));
                                if (_e678 >= 0f) {
                                    phi_975_ = _e690;
                                } else {
                                    phi_975_ = (3.141593f - _e690);
                                }
                                let _e694 = phi_975_;
                                let _e695 = (_e667 * _e694);
                                let _e698 = params.member.member_9;
                                let _e700 = select(1u, _e698, (1u < _e698));
                                let _e702 = cos((_e695 + 1.5707964f));
                                let _e704 = cos((_e695 - 1.5707964f));
                                let _e707 = params.member.member_5;
                                phi_998_ = 0u;
                                phi_1001_ = _e704;
                                phi_1003_ = _e702;
                                loop {
                                    let _e709 = phi_998_;
                                    let _e711 = phi_1001_;
                                    let _e713 = phi_1003_;
                                    local_3 = _e711;
                                    local_4 = _e711;
                                    local_5 = _e713;
                                    local_6 = _e713;
                                    let _e714 = (_e709 < _e700);
                                    if _e714 {
                                        let _e719 = ((_e563 - floor(_e563)) + (f32((_e596 + (_e709 * _e700))) * 0.618034f));
                                        let _e725 = ((f32(_e709) + (_e719 - floor(_e719))) / f32(_e700));
                                        let _e728 = params.member.member_4;
                                        if (_e728 == 2f) {
                                            phi_1057_ = (_e725 * _e725);
                                        } else {
                                            phi_1057_ = pow(_e725, _e728);
                                        }
                                        let _e733 = phi_1057_;
                                        let _e734 = (_e733 + (1.3f / _e503));
                                        let _e735 = ((_e606 * _e503) * _e734);
                                        let _e736 = ((-(_e605) * _e503) * _e734);
                                        let _e744 = params.member.member_7;
                                        let _e745 = (log2(sqrt(((_e735 * _e735) + (_e736 * _e736)))) - _e744);
                                        if (_e745 > 0f) {
                                            phi_1081_ = select(5f, _e745, (_e745 < 5f));
                                        } else {
                                            phi_1081_ = 0f;
                                        }
                                        let _e750 = phi_1081_;
                                        let _e753 = (-1f - floor((-0.5f - _e750)));
                                        if (_e753 > 0f) {
                                            let _e759 = select(select(u32(_e753), 0u, (_e753 < 0f)), 4294967295u, (_e753 > 4294967000f));
                                            phi_1104_ = select(_e759, 4u, (4u < _e759));
                                        } else {
                                            phi_1104_ = 0u;
                                        }
                                        let _e763 = phi_1104_;
                                        let _e765 = floor((_e735 + 0.5f));
                                        if ((_e765 - _e735) == 0.5f) {
                                            let _e771 = ((floor((_e765 * 0.5f)) * 2f) != _e765);
                                            if _e771 {
                                                phi_1120_ = (_e765 - 1f);
                                            } else {
                                                phi_1120_ = f32();
                                            }
                                            let _e774 = phi_1120_;
                                            phi_1122_ = _e774;
                                            phi_1123_ = select(true, false, _e771);
                                        } else {
                                            phi_1122_ = f32();
                                            phi_1123_ = true;
                                        }
                                        let _e777 = phi_1122_;
                                        let _e779 = phi_1123_;
                                        let _e782 = floor((_e736 + 0.5f));
                                        if ((_e782 - _e736) == 0.5f) {
                                            let _e788 = ((floor((_e782 * 0.5f)) * 2f) != _e782);
                                            if _e788 {
                                                phi_1143_ = (_e782 - 1f);
                                            } else {
                                                phi_1143_ = f32();
                                            }
                                            let _e791 = phi_1143_;
                                            phi_1145_ = _e791;
                                            phi_1146_ = select(true, false, _e788);
                                        } else {
                                            phi_1145_ = f32();
                                            phi_1146_ = true;
                                        }
                                        let _e794 = phi_1145_;
                                        let _e796 = phi_1146_;
                                        let _e798 = (select(_e777, _e765, _e779) / _e97);
                                        let _e799 = (select(_e794, _e782, _e796) / _e107);
                                        let _e800 = (_e386 + _e798);
                                        let _e801 = (_e387 + _e799);
                                        let _e802 = (_e386 - _e798);
                                        let _e803 = (_e387 - _e799);
                                        let _e804 = (_e763 & 31u);
                                        let _e806 = (_e102 >> bitcast<u32>(_e804));
                                        let _e808 = select(1u, _e806, (1u < _e806));
                                        let _e810 = (_e112 >> bitcast<u32>(_e804));
                                        let _e812 = select(1u, _e810, (1u < _e810));
                                        let _e813 = f32(_e808);
                                        let _e814 = (_e800 * _e813);
                                        if (_e814 > 0f) {
                                            let _e820 = select(select(u32(_e814), 0u, (_e814 < 0f)), 4294967295u, (_e814 > 4294967000f));
                                            let _e821 = (_e808 - 1u);
                                            phi_1198_ = select(_e820, _e821, (_e821 < _e820));
                                        } else {
                                            phi_1198_ = 0u;
                                        }
                                        let _e825 = phi_1198_;
                                        let _e826 = f32(_e812);
                                        let _e827 = (_e801 * _e826);
                                        if (_e827 > 0f) {
                                            let _e833 = select(select(u32(_e827), 0u, (_e827 < 0f)), 4294967295u, (_e827 > 4294967000f));
                                            let _e834 = (_e812 - 1u);
                                            phi_1218_ = select(_e833, _e834, (_e834 < _e833));
                                        } else {
                                            phi_1218_ = 0u;
                                        }
                                        let _e838 = phi_1218_;
                                        phi_1220_ = 0u;
                                        phi_1223_ = 0u;
                                        loop {
                                            let _e840 = phi_1220_;
                                            let _e842 = phi_1223_;
                                            local_1 = _e842;
                                            let _e843 = (_e840 < _e763);
                                            if _e843 {
                                                let _e844 = (_e840 & 31u);
                                                let _e846 = (_e102 >> bitcast<u32>(_e844));
                                                let _e850 = (_e112 >> bitcast<u32>(_e844));
                                                phi_1221_ = (_e840 + 1u);
                                                phi_1224_ = (_e842 + (select(1u, _e846, (1u < _e846)) * select(1u, _e850, (1u < _e850))));
                                            } else {
                                                phi_1221_ = u32();
                                                phi_1224_ = u32();
                                            }
                                            let _e857 = phi_1221_;
                                            let _e859 = phi_1224_;
                                            continue;
                                            continuing {
                                                phi_1220_ = _e857;
                                                phi_1223_ = _e859;
                                                break if !(_e843);
                                            }
                                        }
                                        let _e864 = local_1;
                                        let _e865 = (_e864 + ((_e838 * _e808) + _e825));
                                        if (_e865 < _e86) {
                                        } else {
                                            phi_2332_ = true;
                                            break;
                                        }
                                        let _e869 = mips.member[_e865];
                                        let _e878 = (_e802 * _e813);
                                        if (_e878 > 0f) {
                                            let _e884 = select(select(u32(_e878), 0u, (_e878 < 0f)), 4294967295u, (_e878 > 4294967000f));
                                            let _e885 = (_e808 - 1u);
                                            phi_1306_ = select(_e884, _e885, (_e885 < _e884));
                                        } else {
                                            phi_1306_ = 0u;
                                        }
                                        let _e889 = phi_1306_;
                                        let _e890 = (_e803 * _e826);
                                        if (_e890 > 0f) {
                                            let _e896 = select(select(u32(_e890), 0u, (_e890 < 0f)), 4294967295u, (_e890 > 4294967000f));
                                            let _e897 = (_e812 - 1u);
                                            phi_1326_ = select(_e896, _e897, (_e897 < _e896));
                                        } else {
                                            phi_1326_ = 0u;
                                        }
                                        let _e901 = phi_1326_;
                                        phi_1328_ = 0u;
                                        phi_1331_ = 0u;
                                        loop {
                                            let _e903 = phi_1328_;
                                            let _e905 = phi_1331_;
                                            local_2 = _e905;
                                            let _e906 = (_e903 < _e763);
                                            if _e906 {
                                                let _e907 = (_e903 & 31u);
                                                let _e909 = (_e102 >> bitcast<u32>(_e907));
                                                let _e913 = (_e112 >> bitcast<u32>(_e907));
                                                phi_1329_ = (_e903 + 1u);
                                                phi_1332_ = (_e905 + (select(1u, _e909, (1u < _e909)) * select(1u, _e913, (1u < _e913))));
                                            } else {
                                                phi_1329_ = u32();
                                                phi_1332_ = u32();
                                            }
                                            let _e920 = phi_1329_;
                                            let _e922 = phi_1332_;
                                            continue;
                                            continuing {
                                                phi_1328_ = _e920;
                                                phi_1331_ = _e922;
                                                break if !(_e906);
                                            }
                                        }
                                        let _e927 = local_2;
                                        let _e928 = (_e927 + ((_e901 * _e808) + _e889));
                                        if (_e928 < _e86) {
                                        } else {
                                            phi_2332_ = true;
                                            break;
                                        }
                                        let _e932 = mips.member[_e928];
                                        let _e941 = (((((2f * _e800) - 1f) * _e395) * _e869) - _e397);
                                        let _e942 = ((((1f - (2f * _e801)) * _e404) * _e869) - _e406);
                                        let _e943 = (_e869 - _e388);
                                        let _e946 = ((_e941 * _e941) + (_e942 * _e942));
                                        let _e949 = sqrt((_e946 + (_e943 * _e943)));
                                        let _e958 = (1f + _e707);
                                        let _e959 = (_e943 * _e958);
                                        let _e962 = sqrt((_e946 + (_e959 * _e959)));
                                        let _e963 = (_e577 > 0f);
                                        if _e963 {
                                            let _e965 = ((_e499 - _e962) / _e577);
                                            if (_e965 > 0f) {
                                                phi_1430_ = select(1f, _e965, (_e965 < 1f));
                                            } else {
                                                phi_1430_ = 0f;
                                            }
                                            let _e970 = phi_1430_;
                                            phi_1436_ = _e970;
                                        } else {
                                            phi_1436_ = select(0f, 1f, (_e962 <= _e499));
                                        }
                                        let _e974 = phi_1436_;
                                        let _e977 = (_e702 + ((((((_e941 / _e949) * _e417) + ((_e942 / _e949) * _e418)) + ((_e943 / _e949) * _e419)) - _e702) * _e974));
                                        let _e978 = (((((2f * _e802) - 1f) * _e395) * _e932) - _e397);
                                        let _e979 = ((((1f - (2f * _e803)) * _e404) * _e932) - _e406);
                                        let _e980 = (_e932 - _e388);
                                        let _e983 = ((_e978 * _e978) + (_e979 * _e979));
                                        let _e986 = sqrt((_e983 + (_e980 * _e980)));
                                        let _e995 = (_e980 * _e958);
                                        let _e998 = sqrt((_e983 + (_e995 * _e995)));
                                        if _e963 {
                                            let _e1000 = ((_e499 - _e998) / _e577);
                                            if (_e1000 > 0f) {
                                                phi_1489_ = select(1f, _e1000, (_e1000 < 1f));
                                            } else {
                                                phi_1489_ = 0f;
                                            }
                                            let _e1005 = phi_1489_;
                                            phi_1495_ = _e1005;
                                        } else {
                                            phi_1495_ = select(0f, 1f, (_e998 <= _e499));
                                        }
                                        let _e1009 = phi_1495_;
                                        let _e1012 = (_e704 + ((((((_e978 / _e986) * _e417) + ((_e979 / _e986) * _e418)) + ((_e980 / _e986) * _e419)) - _e704) * _e1009));
                                        if (_e713 != _e713) {
                                            phi_2129_ = true;
                                        } else {
                                            phi_2129_ = (_e977 >= _e713);
                                        }
                                        let _e1016 = phi_2129_;
                                        if (_e711 != _e711) {
                                            phi_2144_ = true;
                                        } else {
                                            phi_2144_ = (_e1012 >= _e711);
                                        }
                                        let _e1021 = phi_2144_;
                                        phi_999_ = (_e709 + 1u);
                                        phi_1002_ = select(_e711, _e1012, _e1021);
                                        phi_1004_ = select(_e713, _e977, _e1016);
                                    } else {
                                        phi_999_ = u32();
                                        phi_1002_ = f32();
                                        phi_1004_ = f32();
                                    }
                                    let _e1025 = phi_999_;
                                    let _e1027 = phi_1002_;
                                    let _e1029 = phi_1004_;
                                    continue;
                                    continuing {
                                        phi_998_ = _e1025;
                                        phi_1001_ = _e1027;
                                        phi_1003_ = _e1029;
                                        phi_2332_ = _e592;
                                        break if !(_e714);
                                    }
                                }
                                let _e1032 = phi_2332_;
                                phi_2451_ = _e1032;
                                if _e1032 {
                                    break;
                                }
                                let _e1035 = (_e657 + ((1f - _e657) * 0.05f));
                                let _e1037 = local_3;
                                let _e1038 = abs(_e1037);
                                let _e1049 = (((-0.156583f * _e1038) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1038))) >> bitcast<u32>(1i))))));
                                let _e1051 = local_4;
                                if (_e1051 >= 0f) {
                                    phi_1521_ = _e1049;
                                } else {
                                    phi_1521_ = (3.141593f - _e1049);
                                }
                                let _e1055 = phi_1521_;
                                let _e1056 = -(_e1055);
                                let _e1058 = local_5;
                                let _e1059 = abs(_e1058);
                                let _e1070 = (((-0.156583f * _e1059) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1059))) >> bitcast<u32>(1i))))));
                                let _e1072 = local_6;
                                if (_e1072 >= 0f) {
                                    phi_1539_ = _e1070;
                                } else {
                                    phi_1539_ = (3.141593f - _e1070);
                                }
                                let _e1076 = phi_1539_;
                                let _e1077 = (_e1055 * -2f);
                                let _e1078 = sin(_e695);
                                let _e1084 = (2f * _e1076);
                                let _e1095 = params.member.member_13;
                                if (_e1095 == 0u) {
                                    phi_1705_ = vec3<f32>(0f, 0f, 0f);
                                } else {
                                    let _e1101 = ((_e1055 * -3f) - _e695);
                                    let _e1109 = ((3f * _e1076) - _e695);
                                    let _e1114 = (_e1056 + _e695);
                                    let _e1116 = (_e1076 + _e695);
                                    let _e1121 = (((((((6f * sin((_e1056 - _e695))) - sin(_e1101)) + (6f * sin((_e1076 - _e695)))) - sin(_e1109)) + (16f * _e1078)) - (3f * (sin(_e1114) + sin(_e1116)))) * 0.083333336f);
                                    let _e1133 = (((-(cos(_e1101)) - cos(_e1109)) + (8f * cos(_e695))) - (3f * (cos(_e1114) + cos(_e1116))));
                                    let _e1134 = (_e606 * _e1121);
                                    let _e1135 = (_e605 * _e1121);
                                    let _e1136 = (_e1133 * -0.083333336f);
                                    let _e1138 = (-1f * _e419);
                                    if (_e1138 > 0.9997f) {
                                        phi_1697_ = vec3<f32>(_e1134, _e1135, _e1136);
                                        phi_1698_ = vec3<f32>();
                                        phi_1699_ = true;
                                    } else {
                                        let _e1140 = (_e1138 < -0.9997f);
                                        if _e1140 {
                                            phi_1695_ = vec3<f32>(_e1134, -(_e1135), (_e1133 * 0.083333336f));
                                            phi_1696_ = vec3<f32>();
                                        } else {
                                            let _e1144 = (-1f * _e417);
                                            let _e1146 = (1f / (1f + _e1138));
                                            let _e1147 = (_e1146 * _e418);
                                            let _e1151 = (_e1147 * _e1144);
                                            phi_1695_ = vec3<f32>();
                                            phi_1696_ = vec3<f32>(((((_e1138 + (_e1147 * _e418)) * _e1134) + (_e1151 * _e1135)) + (_e1144 * _e1136)), (((_e1151 * _e1134) + ((_e1138 + ((_e1146 * _e1144) * _e1144)) * _e1135)) + (-(_e418) * _e1136)), (((_e417 * _e1134) + (_e418 * _e1135)) + (_e1138 * _e1136)));
                                        }
                                        let _e1172 = phi_1695_;
                                        let _e1174 = phi_1696_;
                                        phi_1697_ = _e1172;
                                        phi_1698_ = _e1174;
                                        phi_1699_ = _e1140;
                                    }
                                    let _e1176 = phi_1697_;
                                    let _e1178 = phi_1698_;
                                    let _e1180 = phi_1699_;
                                    phi_1705_ = (select(_e1178, _e1176, vec3(_e1180)) * _e1035);
                                }
                                let _e1185 = phi_1705_;
                                phi_2452_ = _e1032;
                                phi_817_ = (_e594 + _e1185);
                                phi_820_ = (_e596 + 1u);
                                phi_822_ = (_e598 + (_e1035 * (0.25f * (((_e678 + (_e1077 * _e1078)) - cos((_e1077 - _e695))) + ((_e678 + (_e1084 * _e1078)) - cos((_e1084 - _e695)))))));
                            } else {
                                phi_2452_ = _e592;
                                phi_817_ = vec3<f32>();
                                phi_820_ = u32();
                                phi_822_ = f32();
                            }
                            let _e1190 = phi_2452_;
                            let _e1192 = phi_817_;
                            let _e1194 = phi_820_;
                            let _e1196 = phi_822_;
                            continue;
                            continuing {
                                phi_2383_ = _e1190;
                                phi_816_ = _e1192;
                                phi_819_ = _e1194;
                                phi_821_ = _e1196;
                                phi_2451_ = _e1190;
                                break if !(_e599);
                            }
                        }
                        let _e1199 = phi_2451_;
                        if _e1199 {
                            break;
                        }
                        let _e1202 = local_7;
                        let _e1206 = params.member.member_6;
                        let _e1207 = pow((_e1202 / f32(_e590)), _e1206);
                        if (_e1207 != _e1207) {
                            phi_2159_ = true;
                        } else {
                            phi_2159_ = (0.03f >= _e1207);
                        }
                        let _e1211 = phi_2159_;
                        let _e1212 = select(_e1207, 0.03f, _e1211);
                        let _e1215 = params.member.member_13;
                        let _e1216 = (_e1215 == 0u);
                        if _e1216 {
                            let _e1217 = (_e1212 * 0.6666667f);
                            if (_e1217 > 0f) {
                                phi_1741_ = select(1f, _e1217, (_e1217 < 1f));
                            } else {
                                phi_1741_ = 0f;
                            }
                            let _e1222 = phi_1741_;
                            let _e1224 = ((_e1222 * 255f) + 0.5f);
                            phi_1793_ = type_22(select(select(u32(_e1224), 0u, (_e1224 < 0f)), 4294967295u, (_e1224 > 4294967000f)), _e381);
                            phi_1794_ = type_22();
                        } else {
                            let _e1232 = local_8;
                            let _e1236 = local_9;
                            let _e1241 = local_10;
                            let _e1245 = sqrt((((_e1232.x * _e1232.x) + (_e1236.y * _e1236.y)) + (_e1241.z * _e1241.z)));
                            if (_e1245 > 0f) {
                                let _e1249 = local_11;
                                phi_1771_ = (_e1249 / vec3(_e1245));
                            } else {
                                phi_1771_ = _e492;
                            }
                            let _e1252 = phi_1771_;
                            let _e1253 = (_e1212 * 0.6666667f);
                            let _e1260 = ((_e1252.x * 0.5f) + 0.5f);
                            let _e1261 = ((_e1252.y * 0.5f) + 0.5f);
                            let _e1262 = ((_e1252.z * 0.5f) + 0.5f);
                            if (_e1260 > 0f) {
                                phi_2175_ = select(1f, _e1260, (_e1260 < 1f));
                            } else {
                                phi_2175_ = 0f;
                            }
                            let _e1267 = phi_2175_;
                            let _e1269 = ((_e1267 * 255f) + 0.5f);
                            if (_e1261 > 0f) {
                                phi_2196_ = select(1f, _e1261, (_e1261 < 1f));
                            } else {
                                phi_2196_ = 0f;
                            }
                            let _e1279 = phi_2196_;
                            let _e1281 = ((_e1279 * 255f) + 0.5f);
                            if (_e1262 > 0f) {
                                phi_2217_ = select(1f, _e1262, (_e1262 < 1f));
                            } else {
                                phi_2217_ = 0f;
                            }
                            let _e1294 = phi_2217_;
                            let _e1296 = ((_e1294 * 255f) + 0.5f);
                            if (_e1253 > 0f) {
                                phi_2238_ = select(1f, _e1253, (_e1253 < 1f));
                            } else {
                                phi_2238_ = 0f;
                            }
                            let _e1309 = phi_2238_;
                            let _e1311 = ((_e1309 * 255f) + 0.5f);
                            phi_1793_ = type_22();
                            phi_1794_ = type_22((((select(select(u32(_e1269), 0u, (_e1269 < 0f)), 4294967295u, (_e1269 > 4294967000f)) | (select(select(u32(_e1281), 0u, (_e1281 < 0f)), 4294967295u, (_e1281 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1296), 0u, (_e1296 < 0f)), 4294967295u, (_e1296 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1311), 0u, (_e1311 < 0f)), 4294967295u, (_e1311 > 4294967000f)) << bitcast<u32>(24i))), _e381);
                        }
                        let _e1322 = phi_1793_;
                        let _e1324 = phi_1794_;
                        phi_1841_ = _e1322;
                        phi_1842_ = _e1324;
                        phi_1843_ = select(true, false, _e1216);
                    } else {
                        let _e1328 = params.member.member_13;
                        phi_1841_ = type_22();
                        phi_1842_ = type_22(select(2852159616u, 170u, (_e1328 == 0u)), _e381);
                        phi_1843_ = true;
                    }
                    let _e1333 = phi_1841_;
                    let _e1335 = phi_1842_;
                    let _e1337 = phi_1843_;
                    if _e1337 {
                        phi_1847_ = _e1335;
                    } else {
                        phi_1847_ = _e1333;
                    }
                    let _e1339 = phi_1847_;
                    if (_e118 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e118] = _e1339.member;
                    if (_e118 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e118] = _e1339.member_1;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
