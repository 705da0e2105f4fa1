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

struct type_27 {
    member: vec2<u32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: vec3<f32>,
    member_5: vec3<f32>,
    member_6: vec3<f32>,
    member_7: vec3<f32>,
    member_8: vec3<f32>,
    member_9: vec3<f32>,
    member_10: f32,
}

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_34 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_35 {
    member: type_34,
    member_1: type_34,
    member_2: type_5,
}

struct type_36 {
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
}

struct type_37 {
    member: type_35,
    member_1: type_36,
}

struct type_39 {
    member: array<type_37>,
}

struct type_41 {
    member: f32,
    member_1: u32,
}

struct type_44 {
    member: array<atomic<u32>>,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> depth: type_8;
@group(0) @binding(3) 
var<storage, read_write> ao: type_8;
@group(0) @binding(0) 
var<storage> frame: type_39;
@group(0) @binding(2) 
var<storage> normals: type_11;
@group(0) @binding(4) 
var<storage, read_write> mask: type_11;
@group(0) @binding(5) 
var<storage, read_write> ray_min: type_44;
@group(0) @binding(6) 
var<storage, read_write> ray_max: type_44;
@group(0) @binding(7) 
var<storage> depth2_: type_8;

fn function_() {
    var local: array<array<f32, 2>, 8>;
    var local_1: array<f32, 8>;
    var local_2: array<f32, 8>;
    var local_3: array<f32, 8>;
    var local_4: array<f32, 8>;
    var local_5: array<f32, 8>;
    var local_6: array<array<array<f32, 2>, 4>, 4>;
    var phi_318_: bool;
    var phi_320_: bool;
    var phi_321_: bool;
    var phi_322_: bool;
    var phi_323_: bool;
    var phi_381_: bool;
    var phi_411_: f32;
    var phi_1695_: bool;
    var phi_1710_: bool;
    var phi_486_: vec2<f32>;
    var phi_513_: vec3<f32>;
    var phi_1725_: bool;
    var phi_625_: type_28;
    var phi_626_: type_28;
    var phi_628_: type_28;
    var phi_629_: type_28;
    var phi_630_: bool;
    var phi_634_: type_28;
    var phi_662_: u32;
    var phi_665_: u32;
    var phi_667_: f32;
    var phi_706_: f32;
    var phi_730_: f32;
    var phi_744_: f32;
    var phi_763_: f32;
    var phi_819_: bool;
    var phi_821_: bool;
    var phi_822_: bool;
    var phi_823_: bool;
    var phi_824_: bool;
    var phi_856_: f32;
    var phi_869_: f32;
    var phi_920_: bool;
    var phi_952_: f32;
    var phi_975_: bool;
    var phi_1072_: f32;
    var phi_1085_: f32;
    var phi_1098_: f32;
    var phi_1099_: f32;
    var phi_1740_: bool;
    var phi_1755_: bool;
    var phi_1122_: f32;
    var phi_1129_: f32;
    var phi_1770_: bool;
    var phi_1151_: f32;
    var phi_1159_: bool;
    var phi_1194_: bool;
    var phi_1291_: f32;
    var phi_1304_: f32;
    var phi_1317_: f32;
    var phi_1318_: f32;
    var phi_1785_: bool;
    var phi_1800_: bool;
    var phi_1341_: f32;
    var phi_1348_: f32;
    var phi_1815_: bool;
    var phi_1830_: bool;
    var phi_1357_: f32;
    var phi_1845_: bool;
    var phi_1359_: f32;
    var phi_1360_: f32;
    var phi_1361_: f32;
    var phi_1362_: f32;
    var phi_1376_: bool;
    var phi_1377_: bool;
    var phi_1378_: bool;
    var phi_1386_: f32;
    var phi_1860_: bool;
    var phi_1411_: f32;
    var phi_1419_: bool;
    var phi_1423_: bool;
    var phi_1473_: f32;
    var phi_1487_: f32;
    var phi_1875_: bool;
    var phi_1890_: bool;
    var phi_1544_: f32;
    var phi_1551_: u32;
    var phi_1566_: u32;
    var phi_1574_: u32;
    var phi_1575_: u32;
    var phi_1576_: u32;
    var phi_1577_: f32;
    var phi_1578_: u32;
    var phi_1579_: f32;
    var phi_663_: u32;
    var phi_666_: u32;
    var phi_668_: f32;
    var phi_1895_: bool;
    var local_7: f32;
    var local_8: u32;
    var phi_1603_: f32;
    var phi_1613_: f32;
    var local_9: u32;
    var phi_1627_: f32;
    var local_10: u32;
    var phi_1632_: type_41;
    var phi_1634_: type_41;

    switch bitcast<i32>(0u) {
        default: {
            let _e172 = id_1;
            let _e177 = arrayLength((&depth.member));
            let _e188 = arrayLength((&ray_max.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e200 = frame.member[0u].member_1.member.member.member_4;
            let _e201 = (_e172.x + _e200);
            let _e202 = (_e172.y + _e200);
            let _e210 = frame.member[0u].member_1.member.member.member[0u];
            let _e215 = select(select(u32(_e210), 0u, (_e210 < 0f)), 4294967295u, (_e210 > 4294967000f));
            let _e223 = frame.member[0u].member_1.member.member.member[1u];
            let _e228 = select(select(u32(_e223), 0u, (_e223 < 0f)), 4294967295u, (_e223 > 4294967000f));
            if (_e201 >= _e200) {
                if (_e202 >= _e200) {
                    let _e232 = ((_e201 + _e200) < _e215);
                    if _e232 {
                        phi_318_ = ((_e202 + _e200) < _e228);
                    } else {
                        phi_318_ = bool();
                    }
                    let _e236 = phi_318_;
                    phi_320_ = _e236;
                    phi_321_ = select(true, false, _e232);
                } else {
                    phi_320_ = bool();
                    phi_321_ = true;
                }
                let _e239 = phi_320_;
                let _e241 = phi_321_;
                phi_322_ = _e239;
                phi_323_ = _e241;
            } else {
                phi_322_ = bool();
                phi_323_ = true;
            }
            let _e243 = phi_322_;
            let _e245 = phi_323_;
            if select(_e243, false, _e245) {
                let _e252 = frame.member[0u].member_1.member.member_1;
                let _e258 = frame.member[0u].member_1.member.member_4;
                let _e263 = ((f32(_e201) + 0.5f) / _e210);
                let _e264 = ((f32(_e202) + 0.5f) / _e223);
                let _e266 = ((_e202 * _e215) + _e201);
                if (_e266 < _e177) {
                } else {
                    break;
                }
                let _e269 = depth.member[_e266];
                let _e276 = frame.member[0u].member_1.member.member.member_3;
                if (_e269 > 0f) {
                    phi_381_ = (_e269 < _e276);
                } else {
                    phi_381_ = false;
                }
                let _e280 = phi_381_;
                if _e280 {
                    let _e288 = frame.member[0u].member_1.member.member.member_1[0u];
                    let _e296 = frame.member[0u].member_1.member.member.member_1[1u];
                    let _e306 = (0.5f * (((_e252 * _e210) / ((2f * _e288) * _e269)) + ((_e252 * _e223) / ((2f * _e296) * _e269))));
                    let _e307 = (_e306 > _e258);
                    if _e307 {
                        phi_411_ = ((_e252 * _e258) / _e306);
                    } else {
                        phi_411_ = _e252;
                    }
                    let _e311 = phi_411_;
                    let _e312 = select(_e306, _e258, _e307);
                    let _e313 = (_e312 < 0.5f);
                    if _e313 {
                        phi_625_ = type_28(0u, type_28().member_1);
                        phi_626_ = type_28();
                    } else {
                        let _e322 = ((((2f * _e263) - 1f) * _e269) * _e288);
                        let _e324 = (((1f - (2f * _e264)) * _e269) * _e296);
                        let _e325 = -(_e269);
                        if (_e266 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e329 = normals.member[_e266];
                        let _e337 = (f32((bitcast<i32>(((_e329 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e337 != _e337) {
                            phi_1695_ = true;
                        } else {
                            phi_1695_ = (-1f >= _e337);
                        }
                        let _e341 = phi_1695_;
                        let _e342 = select(_e337, -1f, _e341);
                        let _e352 = (f32((bitcast<i32>((((_e329 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e352 != _e352) {
                            phi_1710_ = true;
                        } else {
                            phi_1710_ = (-1f >= _e352);
                        }
                        let _e356 = phi_1710_;
                        let _e357 = select(_e352, -1f, _e356);
                        let _e360 = (1f - abs(_e342));
                        let _e361 = abs(_e357);
                        let _e362 = (_e360 - _e361);
                        if (_e362 < 0f) {
                            phi_486_ = vec2<f32>(((1f - _e361) * select(1f, -1f, (_e342 < 0f))), (_e360 * select(1f, -1f, (_e357 < 0f))));
                        } else {
                            phi_486_ = vec2<f32>(_e342, _e357);
                        }
                        let _e373 = phi_486_;
                        let _e382 = (1f / sqrt((((_e373.x * _e373.x) + (_e373.y * _e373.y)) + (_e362 * _e362))));
                        let _e383 = (_e373.x * _e382);
                        let _e384 = (_e373.y * _e382);
                        let _e385 = (_e362 * _e382);
                        if ((((_e322 * _e383) + (_e324 * _e384)) + (_e325 * _e385)) > 0f) {
                            phi_513_ = vec3<f32>(-(_e383), -(_e384), -(_e385));
                        } else {
                            phi_513_ = vec3<f32>(_e383, _e384, _e385);
                        }
                        let _e398 = phi_513_;
                        local_6 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                        let _e399 = (_e202 % 4u);
                        if (_e399 < 4u) {
                        } else {
                            break;
                        }
                        let _e401 = (_e201 % 4u);
                        if (_e401 < 4u) {
                        } else {
                            break;
                        }
                        let _e405 = local_6[_e399][_e401];
                        let _e415 = sqrt((((_e322 * _e322) + (_e324 * _e324)) + (_e325 * _e325)));
                        let _e416 = (-(_e322) / _e415);
                        let _e417 = (-(_e324) / _e415);
                        let _e418 = (_e269 / _e415);
                        let _e421 = -((_e405[1] * _e418));
                        let _e422 = (_e418 * _e405[0]);
                        let _e425 = ((_e416 * _e405[1]) - (_e405[0] * _e417));
                        let _e432 = (1f / sqrt((((_e421 * _e421) + (_e422 * _e422)) + (_e425 * _e425))));
                        let _e433 = (_e421 * _e432);
                        let _e434 = (_e422 * _e432);
                        let _e435 = (_e425 * _e432);
                        let _e439 = ((_e434 * _e418) - (_e417 * _e435));
                        let _e442 = ((_e435 * _e416) - (_e418 * _e433));
                        let _e445 = ((_e433 * _e417) - (_e416 * _e434));
                        let _e464 = (((_e398.x * _e416) + (_e398.y * _e417)) + (_e398.z * _e418));
                        let _e468 = abs(_e464);
                        if (_e468 != _e468) {
                            phi_1725_ = true;
                        } else {
                            phi_1725_ = (0.0001f >= _e468);
                        }
                        let _e472 = phi_1725_;
                        phi_625_ = type_28();
                        phi_626_ = type_28(1u, type_27(vec2<u32>(_e201, _e202), vec2<f32>(_e263, _e264), _e311, _e312, vec3<f32>(_e322, _e324, _e325), _e398, vec3<f32>(_e416, _e417, _e418), vec3<f32>(_e439, _e442, _e445), vec3<f32>(_e433, _e434, _e435), vec3<f32>((((_e398.x * _e439) + (_e398.y * _e442)) + (_e398.z * _e445)), (((_e398.x * _e433) + (_e398.y * _e434)) + (_e398.z * _e435)), _e464), (1f / (select(1f, -1f, (_e464 < 0f)) * select(_e468, 0.0001f, _e472)))));
                    }
                    let _e481 = phi_625_;
                    let _e483 = phi_626_;
                    phi_628_ = _e481;
                    phi_629_ = _e483;
                    phi_630_ = _e313;
                } else {
                    phi_628_ = type_28(0u, type_28().member_1);
                    phi_629_ = type_28();
                    phi_630_ = true;
                }
                let _e488 = phi_628_;
                let _e490 = phi_629_;
                let _e492 = phi_630_;
                if _e492 {
                    phi_634_ = _e488;
                } else {
                    phi_634_ = _e490;
                }
                let _e494 = phi_634_;
                if (bitcast<i32>(_e494.member) != 0i) {
                    let _e503 = frame.member[0u].member_1.member_1;
                    let _e504 = (_e503 == 1u);
                    let _e515 = sqrt((((_e494.member_1.member_4.x * _e494.member_1.member_4.x) + (_e494.member_1.member_4.y * _e494.member_1.member_4.y)) + (_e494.member_1.member_4.z * _e494.member_1.member_4.z)));
                    phi_662_ = 0u;
                    phi_665_ = 0u;
                    phi_667_ = 0f;
                    loop {
                        let _e517 = phi_662_;
                        let _e519 = phi_665_;
                        let _e521 = phi_667_;
                        local_7 = _e521;
                        local_8 = _e519;
                        local_9 = _e519;
                        local_10 = _e519;
                        let _e522 = (_e517 < 8u);
                        if _e522 {
                            let _e527 = frame.member[0u].member_1.member_10;
                            local = array<array<f32, 2>, 8>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f));
                            if _e522 {
                            } else {
                                phi_1895_ = true;
                                break;
                            }
                            let _e529 = local[_e517];
                            let _e532 = (_e527 == 1u);
                            if _e532 {
                                local_1 = array<f32, 8>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f);
                                if _e522 {
                                } else {
                                    phi_1895_ = true;
                                    break;
                                }
                                let _e534 = local_1[_e517];
                                phi_706_ = _e534;
                            } else {
                                local_2 = array<f32, 8>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f);
                                if _e522 {
                                } else {
                                    phi_1895_ = true;
                                    break;
                                }
                                let _e536 = local_2[_e517];
                                phi_706_ = _e536;
                            }
                            let _e538 = phi_706_;
                            let _e540 = (_e538 * _e494.member_1.member_2);
                            let _e541 = (_e540 * _e529[0]);
                            let _e542 = (_e540 * _e529[1]);
                            if _e532 {
                                local_3 = array<f32, 8>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f);
                                if _e522 {
                                } else {
                                    phi_1895_ = true;
                                    break;
                                }
                                let _e544 = local_3[_e517];
                                phi_730_ = _e544;
                            } else {
                                local_4 = array<f32, 8>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f);
                                if _e522 {
                                } else {
                                    phi_1895_ = true;
                                    break;
                                }
                                let _e546 = local_4[_e517];
                                phi_730_ = _e546;
                            }
                            let _e548 = phi_730_;
                            let _e549 = (_e548 * _e494.member_1.member_2);
                            if _e532 {
                                local_5 = array<f32, 8>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f);
                                if _e522 {
                                } else {
                                    phi_1895_ = true;
                                    break;
                                }
                                let _e551 = local_5[_e517];
                                phi_744_ = _e551;
                            } else {
                                phi_744_ = (2f * _e549);
                            }
                            let _e554 = phi_744_;
                            let _e564 = (-(((_e541 * _e494.member_1.member_9.x) + (_e542 * _e494.member_1.member_9.y))) * _e494.member_1.member_10);
                            let _e565 = -(_e549);
                            if (_e564 > _e565) {
                                phi_763_ = select(_e549, _e564, (_e564 < _e549));
                            } else {
                                phi_763_ = _e565;
                            }
                            let _e570 = phi_763_;
                            let _e571 = (_e549 - _e570);
                            let _e594 = (-0.5f / ((_e494.member_1.member_4.z + (_e494.member_1.member_7.z * _e541)) + (_e494.member_1.member_8.z * _e542)));
                            let _e603 = frame.member[0u].member_1.member.member.member_1[0u];
                            let _e605 = (0.5f + ((((_e494.member_1.member_4.x + (_e494.member_1.member_7.x * _e541)) + (_e494.member_1.member_8.x * _e542)) * _e594) / _e603));
                            let _e614 = frame.member[0u].member_1.member.member.member_1[1u];
                            let _e616 = (0.5f - ((((_e494.member_1.member_4.y + (_e494.member_1.member_7.y * _e541)) + (_e494.member_1.member_8.y * _e542)) * _e594) / _e614));
                            if (_e605 >= 0f) {
                                if (_e605 <= 1f) {
                                    let _e619 = (_e616 >= 0f);
                                    if _e619 {
                                        phi_819_ = (_e616 <= 1f);
                                    } else {
                                        phi_819_ = bool();
                                    }
                                    let _e622 = phi_819_;
                                    phi_821_ = _e622;
                                    phi_822_ = select(true, false, _e619);
                                } else {
                                    phi_821_ = bool();
                                    phi_822_ = true;
                                }
                                let _e625 = phi_821_;
                                let _e627 = phi_822_;
                                phi_823_ = _e625;
                                phi_824_ = _e627;
                            } else {
                                phi_823_ = bool();
                                phi_824_ = true;
                            }
                            let _e629 = phi_823_;
                            let _e631 = phi_824_;
                            if (_e605 > 0f) {
                                phi_856_ = select(1f, _e605, (_e605 < 1f));
                            } else {
                                phi_856_ = 0f;
                            }
                            let _e637 = phi_856_;
                            let _e638 = (_e637 * _e210);
                            if (_e616 > 0f) {
                                phi_869_ = select(1f, _e616, (_e616 < 1f));
                            } else {
                                phi_869_ = 0f;
                            }
                            let _e643 = phi_869_;
                            let _e644 = (_e643 * _e223);
                            let _e649 = select(select(u32(_e638), 0u, (_e638 < 0f)), 4294967295u, (_e638 > 4294967000f));
                            let _e650 = (_e215 - 1u);
                            let _e652 = select(_e649, _e650, (_e650 < _e649));
                            let _e657 = select(select(u32(_e644), 0u, (_e644 < 0f)), 4294967295u, (_e644 > 4294967000f));
                            let _e658 = (_e228 - 1u);
                            let _e660 = select(_e657, _e658, (_e658 < _e657));
                            let _e667 = ((_e494.member_1.member_1.x - _e605) * _e210);
                            let _e668 = ((_e494.member_1.member_1.y - _e616) * _e223);
                            let _e672 = sqrt(((_e667 * _e667) + (_e668 * _e668)));
                            if (_e652 == _e494.member_1.member.x) {
                                phi_920_ = (_e660 == _e494.member_1.member.y);
                            } else {
                                phi_920_ = false;
                            }
                            let _e680 = phi_920_;
                            if (_e571 > (0.2f * _e549)) {
                                if _e680 {
                                    if _e532 {
                                        phi_952_ = 0f;
                                    } else {
                                        phi_952_ = (_e571 / (2f * _e549));
                                    }
                                    let _e684 = phi_952_;
                                    phi_1576_ = _e519;
                                    phi_1577_ = (_e521 + _e684);
                                } else {
                                    let _e687 = ((_e660 * _e215) + _e652);
                                    if (_e687 < _e177) {
                                    } else {
                                        phi_1895_ = true;
                                        break;
                                    }
                                    let _e690 = depth.member[_e687];
                                    if (_e690 > 0f) {
                                        phi_975_ = (_e690 < _e276);
                                    } else {
                                        phi_975_ = false;
                                    }
                                    let _e694 = phi_975_;
                                    let _e695 = select(_e276, _e690, _e694);
                                    let _e705 = ((2f * ((f32(_e652) + 0.5f) * (1f / _e210))) - 1f);
                                    let _e707 = (1f - (2f * ((f32(_e660) + 0.5f) * (1f / _e223))));
                                    let _e713 = (((_e705 * _e695) * _e603) - _e494.member_1.member_4.x);
                                    let _e714 = (((_e707 * _e695) * _e614) - _e494.member_1.member_4.y);
                                    let _e715 = (-(_e695) - _e494.member_1.member_4.z);
                                    let _e724 = (((_e713 * _e494.member_1.member_6.x) + (_e714 * _e494.member_1.member_6.y)) + (_e715 * _e494.member_1.member_6.z));
                                    if _e532 {
                                        let _e729 = (((_e713 * _e713) + (_e714 * _e714)) + (_e715 * _e715));
                                        if (_e729 <= 0f) {
                                            phi_1099_ = 0f;
                                        } else {
                                            let _e742 = (((((_e494.member_1.member_5.x * _e713) + (_e494.member_1.member_5.y * _e714)) + (_e494.member_1.member_5.z * _e715)) / sqrt(_e729)) - 0.1f);
                                            if (_e742 > 0f) {
                                                phi_1072_ = select(1f, _e742, (_e742 < 1f));
                                            } else {
                                                phi_1072_ = 0f;
                                            }
                                            let _e747 = phi_1072_;
                                            let _e750 = (1f - (_e729 / (_e252 * _e252)));
                                            if (_e750 > 0f) {
                                                phi_1085_ = select(1f, _e750, (_e750 < 1f));
                                            } else {
                                                phi_1085_ = 0f;
                                            }
                                            let _e755 = phi_1085_;
                                            let _e757 = ((_e747 * _e755) / _e554);
                                            if (_e757 > 0f) {
                                                phi_1098_ = select(1f, _e757, (_e757 < 1f));
                                            } else {
                                                phi_1098_ = 0f;
                                            }
                                            let _e762 = phi_1098_;
                                            phi_1099_ = _e762;
                                        }
                                        let _e764 = phi_1099_;
                                        phi_1129_ = _e764;
                                    } else {
                                        let _e770 = frame.member[0u].member_1.member.member_3;
                                        if (_e570 != _e570) {
                                            phi_1740_ = true;
                                        } else {
                                            phi_1740_ = (_e724 >= _e570);
                                        }
                                        let _e775 = phi_1740_;
                                        let _e777 = (_e549 - select(_e570, _e724, _e775));
                                        if (_e777 != _e777) {
                                            phi_1755_ = true;
                                        } else {
                                            phi_1755_ = (0f >= _e777);
                                        }
                                        let _e781 = phi_1755_;
                                        let _e786 = ((_e724 - ((1f + _e770) * _e494.member_1.member_2)) * (1f / _e549));
                                        if (_e786 > 0f) {
                                            phi_1122_ = select(1f, _e786, (_e786 < 1f));
                                        } else {
                                            phi_1122_ = 0f;
                                        }
                                        let _e791 = phi_1122_;
                                        phi_1129_ = ((select(_e777, 0f, _e781) + (_e791 * _e571)) * (0.5f / _e549));
                                    }
                                    let _e797 = phi_1129_;
                                    let _e802 = frame.member[0u].member_1.member_9;
                                    if (_e802 == 0u) {
                                        phi_1361_ = _e797;
                                        phi_1362_ = _e724;
                                    } else {
                                        if _e532 {
                                            let _e804 = (0.1f * _e494.member_1.member_2);
                                            if (_e549 != _e549) {
                                                phi_1770_ = true;
                                            } else {
                                                phi_1770_ = (_e804 >= _e549);
                                            }
                                            let _e808 = phi_1770_;
                                            phi_1151_ = select(_e549, _e804, _e808);
                                        } else {
                                            let _e815 = frame.member[0u].member_1.member.member_3;
                                            phi_1151_ = ((1f + _e815) * _e494.member_1.member_2);
                                        }
                                        let _e819 = phi_1151_;
                                        if (_e724 > _e819) {
                                            let _e825 = frame.member[0u].member_1.member_3;
                                            phi_1159_ = (_e672 > _e825);
                                        } else {
                                            phi_1159_ = false;
                                        }
                                        let _e828 = phi_1159_;
                                        if _e828 {
                                            if (_e687 < arrayLength((&depth2_.member))) {
                                            } else {
                                                phi_1895_ = true;
                                                break;
                                            }
                                            let _e832 = depth2_.member[_e687];
                                            if (_e832 > 0f) {
                                                phi_1194_ = (_e832 < _e276);
                                            } else {
                                                phi_1194_ = false;
                                            }
                                            let _e836 = phi_1194_;
                                            let _e837 = select(_e276, _e832, _e836);
                                            let _e843 = (((_e705 * _e837) * _e603) - _e494.member_1.member_4.x);
                                            let _e844 = (((_e707 * _e837) * _e614) - _e494.member_1.member_4.y);
                                            let _e845 = (-(_e837) - _e494.member_1.member_4.z);
                                            let _e850 = (((_e843 * _e494.member_1.member_6.x) + (_e844 * _e494.member_1.member_6.y)) + (_e845 * _e494.member_1.member_6.z));
                                            if _e532 {
                                                let _e855 = (((_e843 * _e843) + (_e844 * _e844)) + (_e845 * _e845));
                                                if (_e855 <= 0f) {
                                                    phi_1318_ = 0f;
                                                } else {
                                                    let _e868 = (((((_e494.member_1.member_5.x * _e843) + (_e494.member_1.member_5.y * _e844)) + (_e494.member_1.member_5.z * _e845)) / sqrt(_e855)) - 0.1f);
                                                    if (_e868 > 0f) {
                                                        phi_1291_ = select(1f, _e868, (_e868 < 1f));
                                                    } else {
                                                        phi_1291_ = 0f;
                                                    }
                                                    let _e873 = phi_1291_;
                                                    let _e876 = (1f - (_e855 / (_e252 * _e252)));
                                                    if (_e876 > 0f) {
                                                        phi_1304_ = select(1f, _e876, (_e876 < 1f));
                                                    } else {
                                                        phi_1304_ = 0f;
                                                    }
                                                    let _e881 = phi_1304_;
                                                    let _e883 = ((_e873 * _e881) / _e554);
                                                    if (_e883 > 0f) {
                                                        phi_1317_ = select(1f, _e883, (_e883 < 1f));
                                                    } else {
                                                        phi_1317_ = 0f;
                                                    }
                                                    let _e888 = phi_1317_;
                                                    phi_1318_ = _e888;
                                                }
                                                let _e890 = phi_1318_;
                                                phi_1348_ = _e890;
                                            } else {
                                                let _e896 = frame.member[0u].member_1.member.member_3;
                                                if (_e570 != _e570) {
                                                    phi_1785_ = true;
                                                } else {
                                                    phi_1785_ = (_e850 >= _e570);
                                                }
                                                let _e901 = phi_1785_;
                                                let _e903 = (_e549 - select(_e570, _e850, _e901));
                                                if (_e903 != _e903) {
                                                    phi_1800_ = true;
                                                } else {
                                                    phi_1800_ = (0f >= _e903);
                                                }
                                                let _e907 = phi_1800_;
                                                let _e912 = ((_e850 - ((1f + _e896) * _e494.member_1.member_2)) * (1f / _e549));
                                                if (_e912 > 0f) {
                                                    phi_1341_ = select(1f, _e912, (_e912 < 1f));
                                                } else {
                                                    phi_1341_ = 0f;
                                                }
                                                let _e917 = phi_1341_;
                                                phi_1348_ = ((select(_e903, 0f, _e907) + (_e917 * _e571)) * (0.5f / _e549));
                                            }
                                            let _e923 = phi_1348_;
                                            if _e532 {
                                                if (_e797 != _e797) {
                                                    phi_1815_ = true;
                                                } else {
                                                    phi_1815_ = (_e923 >= _e797);
                                                }
                                                let _e927 = phi_1815_;
                                                phi_1357_ = select(_e797, _e923, _e927);
                                            } else {
                                                if (_e797 != _e797) {
                                                    phi_1830_ = true;
                                                } else {
                                                    phi_1830_ = (_e923 <= _e797);
                                                }
                                                let _e932 = phi_1830_;
                                                phi_1357_ = select(_e797, _e923, _e932);
                                            }
                                            let _e935 = phi_1357_;
                                            if (_e724 != _e724) {
                                                phi_1845_ = true;
                                            } else {
                                                phi_1845_ = (_e850 <= _e724);
                                            }
                                            let _e939 = phi_1845_;
                                            phi_1359_ = _e935;
                                            phi_1360_ = select(_e724, _e850, _e939);
                                        } else {
                                            phi_1359_ = _e797;
                                            phi_1360_ = _e724;
                                        }
                                        let _e942 = phi_1359_;
                                        let _e944 = phi_1360_;
                                        phi_1361_ = _e942;
                                        phi_1362_ = _e944;
                                    }
                                    let _e946 = phi_1361_;
                                    let _e948 = phi_1362_;
                                    if select(_e629, false, _e631) {
                                        phi_1378_ = false;
                                    } else {
                                        if (_e503 == 2u) {
                                            phi_1377_ = true;
                                        } else {
                                            if _e504 {
                                                let _e954 = frame.member[0u].member_1.member_4;
                                                phi_1376_ = (_e954 > 0u);
                                            } else {
                                                phi_1376_ = false;
                                            }
                                            let _e957 = phi_1376_;
                                            phi_1377_ = _e957;
                                        }
                                        let _e959 = phi_1377_;
                                        phi_1378_ = _e959;
                                    }
                                    let _e961 = phi_1378_;
                                    if _e961 {
                                        phi_1386_ = select(_e948, 0x1.fffffep+127f, _e504);
                                    } else {
                                        phi_1386_ = _e948;
                                    }
                                    let _e964 = phi_1386_;
                                    if (_e503 != 0u) {
                                        if _e961 {
                                            phi_1423_ = true;
                                        } else {
                                            if _e532 {
                                                let _e966 = (0.1f * _e494.member_1.member_2);
                                                if (_e549 != _e549) {
                                                    phi_1860_ = true;
                                                } else {
                                                    phi_1860_ = (_e966 >= _e549);
                                                }
                                                let _e970 = phi_1860_;
                                                phi_1411_ = select(_e549, _e966, _e970);
                                            } else {
                                                let _e977 = frame.member[0u].member_1.member.member_3;
                                                phi_1411_ = ((1f + _e977) * _e494.member_1.member_2);
                                            }
                                            let _e981 = phi_1411_;
                                            if (_e964 > _e981) {
                                                let _e987 = frame.member[0u].member_1.member_3;
                                                phi_1419_ = (_e672 > _e987);
                                            } else {
                                                phi_1419_ = false;
                                            }
                                            let _e990 = phi_1419_;
                                            phi_1423_ = _e990;
                                        }
                                        let _e992 = phi_1423_;
                                        if _e992 {
                                            if _e504 {
                                                let _e1002 = frame.member[0u].member_1.member_5[0u];
                                                let _e1008 = frame.member[0u].member_1.member_5[1u];
                                                let _e1015 = frame.member[0u].member_1.member_4;
                                                let _e1016 = f32(_e1015);
                                                let _e1017 = (2u * _e1015);
                                                let _e1018 = (_e1002 + _e1017);
                                                let _e1024 = (floor((_e605 * f32(_e1002))) + _e1016);
                                                let _e1025 = f32((_e1018 - 1u));
                                                if (_e1024 > 0f) {
                                                    phi_1473_ = select(_e1025, _e1024, (_e1024 < _e1025));
                                                } else {
                                                    phi_1473_ = 0f;
                                                }
                                                let _e1030 = phi_1473_;
                                                let _e1033 = (floor((_e616 * f32(_e1008))) + _e1016);
                                                let _e1034 = f32(((_e1008 + _e1017) - 1u));
                                                if (_e1033 > 0f) {
                                                    phi_1487_ = select(_e1034, _e1033, (_e1033 < _e1034));
                                                } else {
                                                    phi_1487_ = 0f;
                                                }
                                                let _e1039 = phi_1487_;
                                                let _e1051 = ((select(select(u32(_e1039), 0u, (_e1039 < 0f)), 4294967295u, (_e1039 > 4294967000f)) * _e1018) + select(select(u32(_e1030), 0u, (_e1030 < 0f)), 4294967295u, (_e1030 > 4294967000f)));
                                                let _e1056 = frame.member[0u].member_1.member_2;
                                                if (_e1056 == 0u) {
                                                    if (_e1051 < _e188) {
                                                    } else {
                                                        phi_1895_ = true;
                                                        break;
                                                    }
                                                    let _e1061 = atomicMax((&ray_max.member[_e1051]), 1u);
                                                } else {
                                                    if _e532 {
                                                        if (_e964 != _e964) {
                                                            phi_1875_ = true;
                                                        } else {
                                                            phi_1875_ = (_e549 <= _e964);
                                                        }
                                                        let _e1065 = phi_1875_;
                                                        phi_1544_ = select(_e964, _e549, _e1065);
                                                    } else {
                                                        let _e1072 = frame.member[0u].member_1.member.member_3;
                                                        let _e1075 = (((1f + _e1072) * _e494.member_1.member_2) + _e549);
                                                        if (_e964 != _e964) {
                                                            phi_1890_ = true;
                                                        } else {
                                                            phi_1890_ = (_e1075 <= _e964);
                                                        }
                                                        let _e1079 = phi_1890_;
                                                        phi_1544_ = select(_e964, _e1075, _e1079);
                                                    }
                                                    let _e1082 = phi_1544_;
                                                    let _e1083 = (_e515 - _e1082);
                                                    if (_e1083 > 0f) {
                                                        phi_1551_ = bitcast<u32>(_e1083);
                                                    } else {
                                                        phi_1551_ = 0u;
                                                    }
                                                    let _e1087 = phi_1551_;
                                                    if (_e1051 < arrayLength((&ray_min.member))) {
                                                    } else {
                                                        phi_1895_ = true;
                                                        break;
                                                    }
                                                    let _e1091 = atomicMin((&ray_min.member[_e1051]), _e1087);
                                                    let _e1092 = (_e515 - _e570);
                                                    if (_e1092 > 0f) {
                                                        phi_1566_ = bitcast<u32>(_e1092);
                                                    } else {
                                                        phi_1566_ = 0u;
                                                    }
                                                    let _e1096 = phi_1566_;
                                                    if (_e1051 < _e188) {
                                                    } else {
                                                        phi_1895_ = true;
                                                        break;
                                                    }
                                                    let _e1100 = atomicMax((&ray_max.member[_e1051]), _e1096);
                                                }
                                            }
                                            phi_1574_ = (_e519 | (1u << bitcast<u32>((_e517 & 31u))));
                                        } else {
                                            phi_1574_ = _e519;
                                        }
                                        let _e1102 = phi_1574_;
                                        phi_1575_ = _e1102;
                                    } else {
                                        phi_1575_ = _e519;
                                    }
                                    let _e1104 = phi_1575_;
                                    phi_1576_ = _e1104;
                                    phi_1577_ = (_e521 + _e946);
                                }
                                let _e1106 = phi_1576_;
                                let _e1108 = phi_1577_;
                                phi_1578_ = _e1106;
                                phi_1579_ = _e1108;
                            } else {
                                phi_1578_ = _e519;
                                phi_1579_ = _e521;
                            }
                            let _e1110 = phi_1578_;
                            let _e1112 = phi_1579_;
                            phi_663_ = (_e517 + 1u);
                            phi_666_ = _e1110;
                            phi_668_ = _e1112;
                        } else {
                            phi_663_ = u32();
                            phi_666_ = u32();
                            phi_668_ = f32();
                        }
                        let _e1115 = phi_663_;
                        let _e1117 = phi_666_;
                        let _e1119 = phi_668_;
                        continue;
                        continuing {
                            phi_662_ = _e1115;
                            phi_665_ = _e1117;
                            phi_667_ = _e1119;
                            phi_1895_ = false;
                            break if !(_e522);
                        }
                    }
                    let _e1122 = phi_1895_;
                    if _e1122 {
                        break;
                    }
                    let _e1127 = frame.member[0u].member_1.member_10;
                    let _e1128 = (_e1127 == 1u);
                    let _e1132 = local_7;
                    let _e1133 = ((select(2f, 1f, _e1128) * 0.125f) * _e1132);
                    let _e1135 = local_8;
                    if (_e1135 == 0u) {
                        if _e1128 {
                            phi_1603_ = (1f - (2f * _e1133));
                        } else {
                            phi_1603_ = _e1133;
                        }
                        let _e1140 = phi_1603_;
                        if (_e1140 > 0f) {
                            phi_1613_ = select(1f, _e1140, (_e1140 < 1f));
                        } else {
                            phi_1613_ = 0f;
                        }
                        let _e1145 = phi_1613_;
                        let _e1151 = frame.member[0u].member_1.member.member_2;
                        let _e1154 = local_9;
                        phi_1632_ = type_41(pow(_e1145, _e1151), _e1154);
                    } else {
                        if (_e1133 > 0f) {
                            phi_1627_ = select(1f, _e1133, (_e1133 < 1f));
                        } else {
                            phi_1627_ = 0f;
                        }
                        let _e1160 = phi_1627_;
                        let _e1165 = local_10;
                        phi_1632_ = type_41((round((_e1160 * 255f)) * 0.003921569f), _e1165);
                    }
                    let _e1168 = phi_1632_;
                    phi_1634_ = _e1168;
                } else {
                    phi_1634_ = type_41(1f, 0u);
                }
                let _e1170 = phi_1634_;
                if (_e266 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                ao.member[_e266] = _e1170.member;
                if (_e266 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                mask.member[_e266] = _e1170.member_1;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn svao_pass1_(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
