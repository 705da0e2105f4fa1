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
var<storage> mask: type_11;
@group(0) @binding(5) 
var<storage> sd_map: type_8;
@group(0) @binding(6) 
var<storage> depth2_: type_8;

fn function_() {
    var local: array<array<f32, 2>, 16>;
    var local_1: array<array<f32, 2>, 16>;
    var local_2: array<array<f32, 2>, 16>;
    var local_3: array<array<f32, 2>, 16>;
    var local_4: array<array<f32, 2>, 8>;
    var local_5: array<f32, 8>;
    var local_6: array<f32, 8>;
    var local_7: array<f32, 8>;
    var local_8: array<f32, 8>;
    var local_9: array<f32, 8>;
    var local_10: array<array<array<f32, 2>, 4>, 4>;
    var phi_398_: bool;
    var phi_400_: bool;
    var phi_401_: bool;
    var phi_402_: bool;
    var phi_403_: bool;
    var phi_497_: bool;
    var phi_527_: f32;
    var phi_1864_: bool;
    var phi_1879_: bool;
    var phi_602_: vec2<f32>;
    var phi_629_: vec3<f32>;
    var phi_1894_: bool;
    var phi_741_: type_28;
    var phi_742_: type_28;
    var phi_744_: type_28;
    var phi_745_: type_28;
    var phi_746_: bool;
    var phi_750_: type_28;
    var phi_2114_: bool;
    var phi_759_: u32;
    var phi_762_: u32;
    var phi_764_: f32;
    var phi_810_: f32;
    var phi_834_: f32;
    var phi_848_: f32;
    var phi_867_: f32;
    var phi_923_: bool;
    var phi_925_: bool;
    var phi_926_: bool;
    var phi_927_: bool;
    var phi_928_: bool;
    var phi_960_: f32;
    var phi_973_: f32;
    var phi_1058_: bool;
    var phi_1155_: f32;
    var phi_1168_: f32;
    var phi_1181_: f32;
    var phi_1182_: f32;
    var phi_1909_: bool;
    var phi_1924_: bool;
    var phi_1205_: f32;
    var phi_1212_: f32;
    var phi_1939_: bool;
    var phi_1234_: f32;
    var phi_1242_: bool;
    var phi_1277_: bool;
    var phi_1374_: f32;
    var phi_1387_: f32;
    var phi_1400_: f32;
    var phi_1401_: f32;
    var phi_1954_: bool;
    var phi_1969_: bool;
    var phi_1424_: f32;
    var phi_1431_: f32;
    var phi_1984_: bool;
    var phi_1999_: bool;
    var phi_1440_: f32;
    var phi_1442_: f32;
    var phi_1443_: f32;
    var phi_1455_: f32;
    var phi_1496_: f32;
    var phi_1510_: f32;
    var phi_1583_: vec2<f32>;
    var phi_1584_: vec2<f32>;
    var phi_1615_: u32;
    var phi_1618_: f32;
    var phi_1724_: f32;
    var phi_1737_: f32;
    var phi_1750_: f32;
    var phi_1751_: f32;
    var phi_2029_: bool;
    var phi_2044_: bool;
    var phi_1774_: f32;
    var phi_1781_: f32;
    var phi_2059_: bool;
    var phi_2074_: bool;
    var phi_1790_: f32;
    var phi_1616_: u32;
    var phi_1619_: f32;
    var phi_2079_: bool;
    var local_11: f32;
    var phi_2191_: bool;
    var phi_1795_: f32;
    var phi_2190_: bool;
    var phi_760_: u32;
    var phi_765_: f32;
    var phi_2189_: bool;
    var local_12: f32;
    var phi_1816_: f32;
    var phi_1826_: f32;
    var local_13: u32;
    var phi_1831_: type_41;
    var phi_1833_: type_41;
    var phi_1834_: bool;
    var phi_1838_: type_41;

    switch bitcast<i32>(0u) {
        default: {
            let _e231 = id_1;
            let _e236 = arrayLength((&depth.member));
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e258 = frame.member[0u].member_1.member.member.member_4;
            let _e259 = (_e231.x + _e258);
            let _e260 = (_e231.y + _e258);
            let _e268 = frame.member[0u].member_1.member.member.member[0u];
            let _e273 = select(select(u32(_e268), 0u, (_e268 < 0f)), 4294967295u, (_e268 > 4294967000f));
            let _e281 = frame.member[0u].member_1.member.member.member[1u];
            let _e286 = select(select(u32(_e281), 0u, (_e281 < 0f)), 4294967295u, (_e281 > 4294967000f));
            if (_e259 >= _e258) {
                if (_e260 >= _e258) {
                    let _e290 = ((_e259 + _e258) < _e273);
                    if _e290 {
                        phi_398_ = ((_e260 + _e258) < _e286);
                    } else {
                        phi_398_ = bool();
                    }
                    let _e294 = phi_398_;
                    phi_400_ = _e294;
                    phi_401_ = select(true, false, _e290);
                } else {
                    phi_400_ = bool();
                    phi_401_ = true;
                }
                let _e297 = phi_400_;
                let _e299 = phi_401_;
                phi_402_ = _e297;
                phi_403_ = _e299;
            } else {
                phi_402_ = bool();
                phi_403_ = true;
            }
            let _e301 = phi_402_;
            let _e303 = phi_403_;
            if select(_e301, false, _e303) {
                let _e306 = ((_e260 * _e273) + _e259);
                let _e307 = (_e306 < arrayLength((&ao.member)));
                if _e307 {
                } else {
                    break;
                }
                let _e310 = ao.member[_e306];
                if (_e306 < arrayLength((&mask.member))) {
                } else {
                    break;
                }
                let _e314 = mask.member[_e306];
                if (_e314 == 0u) {
                    phi_1833_ = type_41();
                    phi_1834_ = true;
                } else {
                    let _e322 = frame.member[0u].member_1.member.member_1;
                    let _e328 = frame.member[0u].member_1.member.member_4;
                    let _e333 = ((f32(_e259) + 0.5f) / _e268);
                    let _e334 = ((f32(_e260) + 0.5f) / _e281);
                    if (_e306 < _e236) {
                    } else {
                        break;
                    }
                    let _e337 = depth.member[_e306];
                    let _e344 = frame.member[0u].member_1.member.member.member_3;
                    if (_e337 > 0f) {
                        phi_497_ = (_e337 < _e344);
                    } else {
                        phi_497_ = false;
                    }
                    let _e348 = phi_497_;
                    if _e348 {
                        let _e356 = frame.member[0u].member_1.member.member.member_1[0u];
                        let _e364 = frame.member[0u].member_1.member.member.member_1[1u];
                        let _e374 = (0.5f * (((_e322 * _e268) / ((2f * _e356) * _e337)) + ((_e322 * _e281) / ((2f * _e364) * _e337))));
                        let _e375 = (_e374 > _e328);
                        if _e375 {
                            phi_527_ = ((_e322 * _e328) / _e374);
                        } else {
                            phi_527_ = _e322;
                        }
                        let _e379 = phi_527_;
                        let _e380 = select(_e374, _e328, _e375);
                        let _e381 = (_e380 < 0.5f);
                        if _e381 {
                            phi_741_ = type_28(0u, type_28().member_1);
                            phi_742_ = type_28();
                        } else {
                            let _e390 = ((((2f * _e333) - 1f) * _e337) * _e356);
                            let _e392 = (((1f - (2f * _e334)) * _e337) * _e364);
                            let _e393 = -(_e337);
                            if (_e306 < arrayLength((&normals.member))) {
                            } else {
                                break;
                            }
                            let _e397 = normals.member[_e306];
                            let _e405 = (f32((bitcast<i32>(((_e397 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e405 != _e405) {
                                phi_1864_ = true;
                            } else {
                                phi_1864_ = (-1f >= _e405);
                            }
                            let _e409 = phi_1864_;
                            let _e410 = select(_e405, -1f, _e409);
                            let _e420 = (f32((bitcast<i32>((((_e397 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                            if (_e420 != _e420) {
                                phi_1879_ = true;
                            } else {
                                phi_1879_ = (-1f >= _e420);
                            }
                            let _e424 = phi_1879_;
                            let _e425 = select(_e420, -1f, _e424);
                            let _e428 = (1f - abs(_e410));
                            let _e429 = abs(_e425);
                            let _e430 = (_e428 - _e429);
                            if (_e430 < 0f) {
                                phi_602_ = vec2<f32>(((1f - _e429) * select(1f, -1f, (_e410 < 0f))), (_e428 * select(1f, -1f, (_e425 < 0f))));
                            } else {
                                phi_602_ = vec2<f32>(_e410, _e425);
                            }
                            let _e441 = phi_602_;
                            let _e450 = (1f / sqrt((((_e441.x * _e441.x) + (_e441.y * _e441.y)) + (_e430 * _e430))));
                            let _e451 = (_e441.x * _e450);
                            let _e452 = (_e441.y * _e450);
                            let _e453 = (_e430 * _e450);
                            if ((((_e390 * _e451) + (_e392 * _e452)) + (_e393 * _e453)) > 0f) {
                                phi_629_ = vec3<f32>(-(_e451), -(_e452), -(_e453));
                            } else {
                                phi_629_ = vec3<f32>(_e451, _e452, _e453);
                            }
                            let _e466 = phi_629_;
                            local_10 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                            let _e467 = (_e260 % 4u);
                            if (_e467 < 4u) {
                            } else {
                                break;
                            }
                            let _e469 = (_e259 % 4u);
                            if (_e469 < 4u) {
                            } else {
                                break;
                            }
                            let _e473 = local_10[_e467][_e469];
                            let _e483 = sqrt((((_e390 * _e390) + (_e392 * _e392)) + (_e393 * _e393)));
                            let _e484 = (-(_e390) / _e483);
                            let _e485 = (-(_e392) / _e483);
                            let _e486 = (_e337 / _e483);
                            let _e489 = -((_e473[1] * _e486));
                            let _e490 = (_e486 * _e473[0]);
                            let _e493 = ((_e484 * _e473[1]) - (_e473[0] * _e485));
                            let _e500 = (1f / sqrt((((_e489 * _e489) + (_e490 * _e490)) + (_e493 * _e493))));
                            let _e501 = (_e489 * _e500);
                            let _e502 = (_e490 * _e500);
                            let _e503 = (_e493 * _e500);
                            let _e507 = ((_e502 * _e486) - (_e485 * _e503));
                            let _e510 = ((_e503 * _e484) - (_e486 * _e501));
                            let _e513 = ((_e501 * _e485) - (_e484 * _e502));
                            let _e532 = (((_e466.x * _e484) + (_e466.y * _e485)) + (_e466.z * _e486));
                            let _e536 = abs(_e532);
                            if (_e536 != _e536) {
                                phi_1894_ = true;
                            } else {
                                phi_1894_ = (0.0001f >= _e536);
                            }
                            let _e540 = phi_1894_;
                            phi_741_ = type_28();
                            phi_742_ = type_28(1u, type_27(vec2<u32>(_e259, _e260), vec2<f32>(_e333, _e334), _e379, _e380, vec3<f32>(_e390, _e392, _e393), _e466, vec3<f32>(_e484, _e485, _e486), vec3<f32>(_e507, _e510, _e513), vec3<f32>(_e501, _e502, _e503), vec3<f32>((((_e466.x * _e507) + (_e466.y * _e510)) + (_e466.z * _e513)), (((_e466.x * _e501) + (_e466.y * _e502)) + (_e466.z * _e503)), _e532), (1f / (select(1f, -1f, (_e532 < 0f)) * select(_e536, 0.0001f, _e540)))));
                        }
                        let _e549 = phi_741_;
                        let _e551 = phi_742_;
                        phi_744_ = _e549;
                        phi_745_ = _e551;
                        phi_746_ = _e381;
                    } else {
                        phi_744_ = type_28(0u, type_28().member_1);
                        phi_745_ = type_28();
                        phi_746_ = true;
                    }
                    let _e556 = phi_744_;
                    let _e558 = phi_745_;
                    let _e560 = phi_746_;
                    if _e560 {
                        phi_750_ = _e556;
                    } else {
                        phi_750_ = _e558;
                    }
                    let _e562 = phi_750_;
                    let _e565 = (bitcast<i32>(_e562.member) != 0i);
                    if _e565 {
                        phi_2114_ = false;
                        phi_759_ = 0u;
                        phi_762_ = 0u;
                        phi_764_ = 0f;
                        loop {
                            let _e568 = phi_2114_;
                            let _e570 = phi_759_;
                            let _e572 = phi_762_;
                            let _e574 = phi_764_;
                            local_12 = _e574;
                            local_13 = _e572;
                            let _e575 = (_e570 < 8u);
                            if _e575 {
                                if ((_e314 & (1u << bitcast<u32>((_e570 & 31u)))) == 0u) {
                                    phi_2191_ = _e568;
                                    phi_1795_ = _e574;
                                } else {
                                    let _e585 = frame.member[0u].member_1.member_10;
                                    local_4 = array<array<f32, 2>, 8>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f));
                                    if _e575 {
                                    } else {
                                        phi_2189_ = true;
                                        break;
                                    }
                                    let _e587 = local_4[_e570];
                                    let _e590 = (_e585 == 1u);
                                    if _e590 {
                                        local_5 = array<f32, 8>(0.019897608f, 0.3239192f, 0.15013283f, 0.5608856f, 0.07874805f, 0.4306375f, 0.23159242f, 0.74770695f);
                                        if _e575 {
                                        } else {
                                            phi_2189_ = true;
                                            break;
                                        }
                                        let _e592 = local_5[_e570];
                                        phi_810_ = _e592;
                                    } else {
                                        local_6 = array<f32, 8>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f);
                                        if _e575 {
                                        } else {
                                            phi_2189_ = true;
                                            break;
                                        }
                                        let _e594 = local_6[_e570];
                                        phi_810_ = _e594;
                                    }
                                    let _e596 = phi_810_;
                                    let _e598 = (_e596 * _e562.member_1.member_2);
                                    let _e599 = (_e598 * _e587[0]);
                                    let _e600 = (_e598 * _e587[1]);
                                    if _e590 {
                                        local_7 = array<f32, 8>(0.999802f, 0.94608474f, 0.9886658f, 0.8278933f, 0.99689454f, 0.902525f, 0.9728129f, 0.6640288f);
                                        if _e575 {
                                        } else {
                                            phi_2189_ = true;
                                            break;
                                        }
                                        let _e602 = local_7[_e570];
                                        phi_834_ = _e602;
                                    } else {
                                        local_8 = array<f32, 8>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f);
                                        if _e575 {
                                        } else {
                                            phi_2189_ = true;
                                            break;
                                        }
                                        let _e604 = local_8[_e570];
                                        phi_834_ = _e604;
                                    }
                                    let _e606 = phi_834_;
                                    let _e607 = (_e606 * _e562.member_1.member_2);
                                    if _e590 {
                                        local_9 = array<f32, 8>(0.8732723f, 0.50031143f, 0.7051298f, 0.261884f, 0.79581136f, 0.38665694f, 0.6062196f, 0.11405134f);
                                        if _e575 {
                                        } else {
                                            phi_2189_ = true;
                                            break;
                                        }
                                        let _e609 = local_9[_e570];
                                        phi_848_ = _e609;
                                    } else {
                                        phi_848_ = (2f * _e607);
                                    }
                                    let _e612 = phi_848_;
                                    let _e622 = (-(((_e599 * _e562.member_1.member_9.x) + (_e600 * _e562.member_1.member_9.y))) * _e562.member_1.member_10);
                                    let _e623 = -(_e607);
                                    if (_e622 > _e623) {
                                        phi_867_ = select(_e607, _e622, (_e622 < _e607));
                                    } else {
                                        phi_867_ = _e623;
                                    }
                                    let _e628 = phi_867_;
                                    let _e653 = (-0.5f / ((_e562.member_1.member_4.z + (_e562.member_1.member_7.z * _e599)) + (_e562.member_1.member_8.z * _e600)));
                                    let _e662 = frame.member[0u].member_1.member.member.member_1[0u];
                                    let _e664 = (0.5f + ((((_e562.member_1.member_4.x + (_e562.member_1.member_7.x * _e599)) + (_e562.member_1.member_8.x * _e600)) * _e653) / _e662));
                                    let _e673 = frame.member[0u].member_1.member.member.member_1[1u];
                                    let _e675 = (0.5f - ((((_e562.member_1.member_4.y + (_e562.member_1.member_7.y * _e599)) + (_e562.member_1.member_8.y * _e600)) * _e653) / _e673));
                                    if (_e664 >= 0f) {
                                        if (_e664 <= 1f) {
                                            let _e678 = (_e675 >= 0f);
                                            if _e678 {
                                                phi_923_ = (_e675 <= 1f);
                                            } else {
                                                phi_923_ = bool();
                                            }
                                            let _e681 = phi_923_;
                                            phi_925_ = _e681;
                                            phi_926_ = select(true, false, _e678);
                                        } else {
                                            phi_925_ = bool();
                                            phi_926_ = true;
                                        }
                                        let _e684 = phi_925_;
                                        let _e686 = phi_926_;
                                        phi_927_ = _e684;
                                        phi_928_ = _e686;
                                    } else {
                                        phi_927_ = bool();
                                        phi_928_ = true;
                                    }
                                    let _e688 = phi_927_;
                                    let _e690 = phi_928_;
                                    if (_e664 > 0f) {
                                        phi_960_ = select(1f, _e664, (_e664 < 1f));
                                    } else {
                                        phi_960_ = 0f;
                                    }
                                    let _e696 = phi_960_;
                                    let _e697 = (_e696 * _e268);
                                    if (_e675 > 0f) {
                                        phi_973_ = select(1f, _e675, (_e675 < 1f));
                                    } else {
                                        phi_973_ = 0f;
                                    }
                                    let _e702 = phi_973_;
                                    let _e703 = (_e702 * _e281);
                                    let _e708 = select(select(u32(_e697), 0u, (_e697 < 0f)), 4294967295u, (_e697 > 4294967000f));
                                    let _e709 = (_e273 - 1u);
                                    let _e711 = select(_e708, _e709, (_e709 < _e708));
                                    let _e716 = select(select(u32(_e703), 0u, (_e703 < 0f)), 4294967295u, (_e703 > 4294967000f));
                                    let _e717 = (_e286 - 1u);
                                    let _e719 = select(_e716, _e717, (_e717 < _e716));
                                    let _e726 = ((_e562.member_1.member_1.x - _e664) * _e268);
                                    let _e727 = ((_e562.member_1.member_1.y - _e675) * _e281);
                                    let _e733 = ((_e719 * _e273) + _e711);
                                    if (_e733 < _e236) {
                                    } else {
                                        phi_2189_ = true;
                                        break;
                                    }
                                    let _e736 = depth.member[_e733];
                                    if (_e736 > 0f) {
                                        phi_1058_ = (_e736 < _e344);
                                    } else {
                                        phi_1058_ = false;
                                    }
                                    let _e740 = phi_1058_;
                                    let _e741 = select(_e344, _e736, _e740);
                                    let _e751 = ((2f * ((f32(_e711) + 0.5f) * (1f / _e268))) - 1f);
                                    let _e753 = (1f - (2f * ((f32(_e719) + 0.5f) * (1f / _e281))));
                                    let _e759 = (((_e751 * _e741) * _e662) - _e562.member_1.member_4.x);
                                    let _e760 = (((_e753 * _e741) * _e673) - _e562.member_1.member_4.y);
                                    let _e761 = (-(_e741) - _e562.member_1.member_4.z);
                                    let _e770 = (((_e759 * _e562.member_1.member_6.x) + (_e760 * _e562.member_1.member_6.y)) + (_e761 * _e562.member_1.member_6.z));
                                    if _e590 {
                                        let _e775 = (((_e759 * _e759) + (_e760 * _e760)) + (_e761 * _e761));
                                        if (_e775 <= 0f) {
                                            phi_1182_ = 0f;
                                        } else {
                                            let _e788 = (((((_e562.member_1.member_5.x * _e759) + (_e562.member_1.member_5.y * _e760)) + (_e562.member_1.member_5.z * _e761)) / sqrt(_e775)) - 0.1f);
                                            if (_e788 > 0f) {
                                                phi_1155_ = select(1f, _e788, (_e788 < 1f));
                                            } else {
                                                phi_1155_ = 0f;
                                            }
                                            let _e793 = phi_1155_;
                                            let _e796 = (1f - (_e775 / (_e322 * _e322)));
                                            if (_e796 > 0f) {
                                                phi_1168_ = select(1f, _e796, (_e796 < 1f));
                                            } else {
                                                phi_1168_ = 0f;
                                            }
                                            let _e801 = phi_1168_;
                                            let _e803 = ((_e793 * _e801) / _e612);
                                            if (_e803 > 0f) {
                                                phi_1181_ = select(1f, _e803, (_e803 < 1f));
                                            } else {
                                                phi_1181_ = 0f;
                                            }
                                            let _e808 = phi_1181_;
                                            phi_1182_ = _e808;
                                        }
                                        let _e810 = phi_1182_;
                                        phi_1212_ = _e810;
                                    } else {
                                        let _e816 = frame.member[0u].member_1.member.member_3;
                                        if (_e628 != _e628) {
                                            phi_1909_ = true;
                                        } else {
                                            phi_1909_ = (_e770 >= _e628);
                                        }
                                        let _e821 = phi_1909_;
                                        let _e823 = (_e607 - select(_e628, _e770, _e821));
                                        if (_e823 != _e823) {
                                            phi_1924_ = true;
                                        } else {
                                            phi_1924_ = (0f >= _e823);
                                        }
                                        let _e827 = phi_1924_;
                                        let _e832 = ((_e770 - ((1f + _e816) * _e562.member_1.member_2)) * (1f / _e607));
                                        if (_e832 > 0f) {
                                            phi_1205_ = select(1f, _e832, (_e832 < 1f));
                                        } else {
                                            phi_1205_ = 0f;
                                        }
                                        let _e837 = phi_1205_;
                                        phi_1212_ = ((select(_e823, 0f, _e827) + (_e837 * (_e607 - _e628))) * (0.5f / _e607));
                                    }
                                    let _e844 = phi_1212_;
                                    let _e849 = frame.member[0u].member_1.member_9;
                                    if (_e849 == 0u) {
                                        phi_1443_ = _e844;
                                    } else {
                                        if _e590 {
                                            let _e851 = (0.1f * _e562.member_1.member_2);
                                            if (_e607 != _e607) {
                                                phi_1939_ = true;
                                            } else {
                                                phi_1939_ = (_e851 >= _e607);
                                            }
                                            let _e855 = phi_1939_;
                                            phi_1234_ = select(_e607, _e851, _e855);
                                        } else {
                                            let _e862 = frame.member[0u].member_1.member.member_3;
                                            phi_1234_ = ((1f + _e862) * _e562.member_1.member_2);
                                        }
                                        let _e866 = phi_1234_;
                                        if (_e770 > _e866) {
                                            let _e872 = frame.member[0u].member_1.member_3;
                                            phi_1242_ = (sqrt(((_e726 * _e726) + (_e727 * _e727))) > _e872);
                                        } else {
                                            phi_1242_ = false;
                                        }
                                        let _e875 = phi_1242_;
                                        if _e875 {
                                            if (_e733 < arrayLength((&depth2_.member))) {
                                            } else {
                                                phi_2189_ = true;
                                                break;
                                            }
                                            let _e879 = depth2_.member[_e733];
                                            if (_e879 > 0f) {
                                                phi_1277_ = (_e879 < _e344);
                                            } else {
                                                phi_1277_ = false;
                                            }
                                            let _e883 = phi_1277_;
                                            let _e884 = select(_e344, _e879, _e883);
                                            let _e890 = (((_e751 * _e884) * _e662) - _e562.member_1.member_4.x);
                                            let _e891 = (((_e753 * _e884) * _e673) - _e562.member_1.member_4.y);
                                            let _e892 = (-(_e884) - _e562.member_1.member_4.z);
                                            let _e897 = (((_e890 * _e562.member_1.member_6.x) + (_e891 * _e562.member_1.member_6.y)) + (_e892 * _e562.member_1.member_6.z));
                                            if _e590 {
                                                let _e902 = (((_e890 * _e890) + (_e891 * _e891)) + (_e892 * _e892));
                                                if (_e902 <= 0f) {
                                                    phi_1401_ = 0f;
                                                } else {
                                                    let _e915 = (((((_e562.member_1.member_5.x * _e890) + (_e562.member_1.member_5.y * _e891)) + (_e562.member_1.member_5.z * _e892)) / sqrt(_e902)) - 0.1f);
                                                    if (_e915 > 0f) {
                                                        phi_1374_ = select(1f, _e915, (_e915 < 1f));
                                                    } else {
                                                        phi_1374_ = 0f;
                                                    }
                                                    let _e920 = phi_1374_;
                                                    let _e923 = (1f - (_e902 / (_e322 * _e322)));
                                                    if (_e923 > 0f) {
                                                        phi_1387_ = select(1f, _e923, (_e923 < 1f));
                                                    } else {
                                                        phi_1387_ = 0f;
                                                    }
                                                    let _e928 = phi_1387_;
                                                    let _e930 = ((_e920 * _e928) / _e612);
                                                    if (_e930 > 0f) {
                                                        phi_1400_ = select(1f, _e930, (_e930 < 1f));
                                                    } else {
                                                        phi_1400_ = 0f;
                                                    }
                                                    let _e935 = phi_1400_;
                                                    phi_1401_ = _e935;
                                                }
                                                let _e937 = phi_1401_;
                                                phi_1431_ = _e937;
                                            } else {
                                                let _e943 = frame.member[0u].member_1.member.member_3;
                                                if (_e628 != _e628) {
                                                    phi_1954_ = true;
                                                } else {
                                                    phi_1954_ = (_e897 >= _e628);
                                                }
                                                let _e948 = phi_1954_;
                                                let _e950 = (_e607 - select(_e628, _e897, _e948));
                                                if (_e950 != _e950) {
                                                    phi_1969_ = true;
                                                } else {
                                                    phi_1969_ = (0f >= _e950);
                                                }
                                                let _e954 = phi_1969_;
                                                let _e959 = ((_e897 - ((1f + _e943) * _e562.member_1.member_2)) * (1f / _e607));
                                                if (_e959 > 0f) {
                                                    phi_1424_ = select(1f, _e959, (_e959 < 1f));
                                                } else {
                                                    phi_1424_ = 0f;
                                                }
                                                let _e964 = phi_1424_;
                                                phi_1431_ = ((select(_e950, 0f, _e954) + (_e964 * (_e607 - _e628))) * (0.5f / _e607));
                                            }
                                            let _e971 = phi_1431_;
                                            if _e590 {
                                                if (_e844 != _e844) {
                                                    phi_1984_ = true;
                                                } else {
                                                    phi_1984_ = (_e971 >= _e844);
                                                }
                                                let _e975 = phi_1984_;
                                                phi_1440_ = select(_e844, _e971, _e975);
                                            } else {
                                                if (_e844 != _e844) {
                                                    phi_1999_ = true;
                                                } else {
                                                    phi_1999_ = (_e971 <= _e844);
                                                }
                                                let _e980 = phi_1999_;
                                                phi_1440_ = select(_e844, _e971, _e980);
                                            }
                                            let _e983 = phi_1440_;
                                            phi_1442_ = _e983;
                                        } else {
                                            phi_1442_ = _e844;
                                        }
                                        let _e985 = phi_1442_;
                                        phi_1443_ = _e985;
                                    }
                                    let _e987 = phi_1443_;
                                    if select(_e688, false, _e690) {
                                        phi_1455_ = _e987;
                                    } else {
                                        phi_1455_ = select(1f, 0f, _e590);
                                    }
                                    let _e991 = phi_1455_;
                                    let _e997 = frame.member[0u].member_1.member_5[0u];
                                    let _e1003 = frame.member[0u].member_1.member_5[1u];
                                    let _e1004 = f32(_e997);
                                    let _e1005 = f32(_e1003);
                                    let _e1010 = frame.member[0u].member_1.member_4;
                                    let _e1011 = f32(_e1010);
                                    let _e1012 = (2u * _e1010);
                                    let _e1013 = (_e997 + _e1012);
                                    let _e1019 = (floor((_e664 * _e1004)) + _e1011);
                                    let _e1020 = f32((_e1013 - 1u));
                                    if (_e1019 > 0f) {
                                        phi_1496_ = select(_e1020, _e1019, (_e1019 < _e1020));
                                    } else {
                                        phi_1496_ = 0f;
                                    }
                                    let _e1025 = phi_1496_;
                                    let _e1028 = (floor((_e675 * _e1005)) + _e1011);
                                    let _e1029 = f32(((_e1003 + _e1012) - 1u));
                                    if (_e1028 > 0f) {
                                        phi_1510_ = select(_e1029, _e1028, (_e1028 < _e1029));
                                    } else {
                                        phi_1510_ = 0f;
                                    }
                                    let _e1034 = phi_1510_;
                                    let _e1039 = select(select(u32(_e1025), 0u, (_e1025 < 0f)), 4294967295u, (_e1025 > 4294967000f));
                                    let _e1044 = select(select(u32(_e1034), 0u, (_e1034 < 0f)), 4294967295u, (_e1034 > 4294967000f));
                                    let _e1047 = bitcast<i32>(_e1010);
                                    let _e1056 = frame.member[0u].member_1.member_8;
                                    let _e1060 = (((_e1044 % 4u) * 4u) + (_e1039 % 4u));
                                    if (_e1056 == 1u) {
                                        local = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        let _e1062 = (_e1060 < 16u);
                                        if _e1062 {
                                        } else {
                                            phi_2189_ = true;
                                            break;
                                        }
                                        let _e1065 = local[_e1060][0u];
                                        local_1 = array<array<f32, 2>, 16>(array<f32, 2>(0.6483605f, 0.9140704f), array<f32, 2>(0.72791195f, 0.10379416f), array<f32, 2>(0.4888699f, 0.6991781f), array<f32, 2>(0.38482714f, 0.25951505f), array<f32, 2>(0.15558368f, 0.80202746f), array<f32, 2>(0.22056288f, 0.241263f), array<f32, 2>(0.99621886f, 0.58466333f), array<f32, 2>(0.87760407f, 0.39548847f), array<f32, 2>(0.9271227f, 0.831196f), array<f32, 2>(0.9490577f, 0.14202158f), array<f32, 2>(0.20916066f, 0.54767716f), array<f32, 2>(0.16468945f, 0.48691297f), array<f32, 2>(0.43544456f, 0.9515445f), array<f32, 2>(0.4408541f, 0.011881717f), array<f32, 2>(0.71736413f, 0.6695209f), array<f32, 2>(0.6563677f, 0.35924512f));
                                        if _e1062 {
                                        } else {
                                            phi_2189_ = true;
                                            break;
                                        }
                                        let _e1068 = local_1[_e1060][1u];
                                        phi_1584_ = vec2<f32>(_e1065, _e1068);
                                    } else {
                                        if (_e1056 == 2u) {
                                            local_2 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            let _e1071 = (_e1060 < 16u);
                                            if _e1071 {
                                            } else {
                                                phi_2189_ = true;
                                                break;
                                            }
                                            let _e1074 = local_2[_e1060][0u];
                                            local_3 = array<array<f32, 2>, 16>(array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.625f, 0.625f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.375f, 0.875f), array<f32, 2>(0.125f, 0.125f), array<f32, 2>(0.875f, 0.375f), array<f32, 2>(0.625f, 0.625f));
                                            if _e1071 {
                                            } else {
                                                phi_2189_ = true;
                                                break;
                                            }
                                            let _e1077 = local_3[_e1060][1u];
                                            phi_1583_ = vec2<f32>(_e1074, _e1077);
                                        } else {
                                            phi_1583_ = vec2<f32>(0.5f, 0.5f);
                                        }
                                        let _e1080 = phi_1583_;
                                        phi_1584_ = _e1080;
                                    }
                                    let _e1082 = phi_1584_;
                                    let _e1095 = frame.member[0u].member_1.member_6;
                                    phi_1615_ = 0u;
                                    phi_1618_ = _e991;
                                    loop {
                                        let _e1098 = phi_1615_;
                                        let _e1100 = phi_1618_;
                                        local_11 = _e1100;
                                        let _e1101 = (_e1098 < _e1095);
                                        if _e1101 {
                                            let _e1102 = ((((_e1044 * _e1013) + _e1039) * _e1095) + _e1098);
                                            if (_e1102 < arrayLength((&sd_map.member))) {
                                            } else {
                                                phi_2079_ = true;
                                                break;
                                            }
                                            let _e1105 = sd_map.member[_e1102];
                                            let _e1112 = frame.member[0u].member_1.member.member.member_2;
                                            let _e1115 = ((_e1105 * (_e344 - _e1112)) + _e1112);
                                            let _e1125 = (((((2f * ((f32((bitcast<i32>(_e1039) - _e1047)) + _e1082.x) / _e1004)) - 1f) * _e1115) * _e662) - _e562.member_1.member_4.x);
                                            let _e1126 = ((((1f - (2f * ((f32((bitcast<i32>(_e1044) - _e1047)) + _e1082.y) / _e1005))) * _e1115) * _e673) - _e562.member_1.member_4.y);
                                            let _e1127 = (-(_e1115) - _e562.member_1.member_4.z);
                                            let _e1132 = (((_e1125 * _e562.member_1.member_6.x) + (_e1126 * _e562.member_1.member_6.y)) + (_e1127 * _e562.member_1.member_6.z));
                                            if _e590 {
                                                let _e1137 = (((_e1125 * _e1125) + (_e1126 * _e1126)) + (_e1127 * _e1127));
                                                if (_e1137 <= 0f) {
                                                    phi_1751_ = 0f;
                                                } else {
                                                    let _e1150 = (((((_e562.member_1.member_5.x * _e1125) + (_e562.member_1.member_5.y * _e1126)) + (_e562.member_1.member_5.z * _e1127)) / sqrt(_e1137)) - 0.1f);
                                                    if (_e1150 > 0f) {
                                                        phi_1724_ = select(1f, _e1150, (_e1150 < 1f));
                                                    } else {
                                                        phi_1724_ = 0f;
                                                    }
                                                    let _e1155 = phi_1724_;
                                                    let _e1158 = (1f - (_e1137 / (_e322 * _e322)));
                                                    if (_e1158 > 0f) {
                                                        phi_1737_ = select(1f, _e1158, (_e1158 < 1f));
                                                    } else {
                                                        phi_1737_ = 0f;
                                                    }
                                                    let _e1163 = phi_1737_;
                                                    let _e1165 = ((_e1155 * _e1163) / _e612);
                                                    if (_e1165 > 0f) {
                                                        phi_1750_ = select(1f, _e1165, (_e1165 < 1f));
                                                    } else {
                                                        phi_1750_ = 0f;
                                                    }
                                                    let _e1170 = phi_1750_;
                                                    phi_1751_ = _e1170;
                                                }
                                                let _e1172 = phi_1751_;
                                                phi_1781_ = _e1172;
                                            } else {
                                                let _e1178 = frame.member[0u].member_1.member.member_3;
                                                if (_e628 != _e628) {
                                                    phi_2029_ = true;
                                                } else {
                                                    phi_2029_ = (_e1132 >= _e628);
                                                }
                                                let _e1183 = phi_2029_;
                                                let _e1185 = (_e607 - select(_e628, _e1132, _e1183));
                                                if (_e1185 != _e1185) {
                                                    phi_2044_ = true;
                                                } else {
                                                    phi_2044_ = (0f >= _e1185);
                                                }
                                                let _e1189 = phi_2044_;
                                                let _e1194 = ((_e1132 - ((1f + _e1178) * _e562.member_1.member_2)) * (1f / _e607));
                                                if (_e1194 > 0f) {
                                                    phi_1774_ = select(1f, _e1194, (_e1194 < 1f));
                                                } else {
                                                    phi_1774_ = 0f;
                                                }
                                                let _e1199 = phi_1774_;
                                                phi_1781_ = ((select(_e1185, 0f, _e1189) + (_e1199 * (_e607 - _e628))) * (0.5f / _e607));
                                            }
                                            let _e1206 = phi_1781_;
                                            if _e590 {
                                                if (_e1100 != _e1100) {
                                                    phi_2059_ = true;
                                                } else {
                                                    phi_2059_ = (_e1206 >= _e1100);
                                                }
                                                let _e1210 = phi_2059_;
                                                phi_1790_ = select(_e1100, _e1206, _e1210);
                                            } else {
                                                if (_e1100 != _e1100) {
                                                    phi_2074_ = true;
                                                } else {
                                                    phi_2074_ = (_e1206 <= _e1100);
                                                }
                                                let _e1215 = phi_2074_;
                                                phi_1790_ = select(_e1100, _e1206, _e1215);
                                            }
                                            let _e1218 = phi_1790_;
                                            phi_1616_ = (_e1098 + 1u);
                                            phi_1619_ = _e1218;
                                        } else {
                                            phi_1616_ = u32();
                                            phi_1619_ = f32();
                                        }
                                        let _e1221 = phi_1616_;
                                        let _e1223 = phi_1619_;
                                        continue;
                                        continuing {
                                            phi_1615_ = _e1221;
                                            phi_1618_ = _e1223;
                                            phi_2079_ = _e568;
                                            break if !(_e1101);
                                        }
                                    }
                                    let _e1226 = phi_2079_;
                                    phi_2189_ = _e1226;
                                    if _e1226 {
                                        break;
                                    }
                                    let _e1228 = local_11;
                                    phi_2191_ = _e1226;
                                    phi_1795_ = ((_e574 - _e987) + _e1228);
                                }
                                let _e1231 = phi_2191_;
                                let _e1233 = phi_1795_;
                                phi_2190_ = _e1231;
                                phi_760_ = (_e570 + 1u);
                                phi_765_ = _e1233;
                            } else {
                                phi_2190_ = _e568;
                                phi_760_ = u32();
                                phi_765_ = f32();
                            }
                            let _e1236 = phi_2190_;
                            let _e1238 = phi_760_;
                            let _e1240 = phi_765_;
                            continue;
                            continuing {
                                phi_2114_ = _e1236;
                                phi_759_ = _e1238;
                                phi_762_ = select(u32(), _e572, _e575);
                                phi_764_ = _e1240;
                                phi_2189_ = _e1236;
                                break if !(_e575);
                            }
                        }
                        let _e1244 = phi_2189_;
                        if _e1244 {
                            break;
                        }
                        let _e1249 = frame.member[0u].member_1.member_10;
                        let _e1250 = (_e1249 == 1u);
                        let _e1254 = local_12;
                        let _e1256 = (_e310 + ((select(2f, 1f, _e1250) * 0.125f) * _e1254));
                        if _e1250 {
                            phi_1816_ = (1f - (2f * _e1256));
                        } else {
                            phi_1816_ = _e1256;
                        }
                        let _e1260 = phi_1816_;
                        if (_e1260 > 0f) {
                            phi_1826_ = select(1f, _e1260, (_e1260 < 1f));
                        } else {
                            phi_1826_ = 0f;
                        }
                        let _e1265 = phi_1826_;
                        let _e1271 = frame.member[0u].member_1.member.member_2;
                        let _e1274 = local_13;
                        phi_1831_ = type_41(pow(_e1265, _e1271), _e1274);
                    } else {
                        phi_1831_ = type_41();
                    }
                    let _e1277 = phi_1831_;
                    phi_1833_ = _e1277;
                    phi_1834_ = select(true, false, _e565);
                }
                let _e1280 = phi_1833_;
                let _e1282 = phi_1834_;
                if _e1282 {
                    phi_1838_ = type_41(_e310, 0u);
                } else {
                    phi_1838_ = _e1280;
                }
                let _e1284 = phi_1838_;
                if _e307 {
                } else {
                    break;
                }
                ao.member[_e306] = _e1284.member;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn raysd_pass2_(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
