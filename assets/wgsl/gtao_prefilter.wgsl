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

struct type_16 {
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

struct type_17 {
    member: type_16,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(2) 
var<uniform> params: type_17;
@group(0) @binding(1) 
var<storage, read_write> mips: type_7;

fn function_() {
    var local: array<f32, 4>;
    var local_1: array<f32, 4>;
    var local_2: array<f32, 4>;
    var local_3: array<vec2<u32>, 4>;
    var local_4: array<f32, 4>;
    var local_5: array<f32, 4>;
    var local_6: array<f32, 4>;
    var local_7: array<vec2<u32>, 4>;
    var local_8: array<f32, 4>;
    var local_9: array<f32, 4>;
    var local_10: array<f32, 4>;
    var local_11: array<vec2<u32>, 4>;
    var local_12: array<f32, 4>;
    var local_13: array<f32, 4>;
    var local_14: array<f32, 4>;
    var local_15: array<vec2<u32>, 4>;
    var local_16: array<f32, 4>;
    var local_17: array<f32, 4>;
    var local_18: array<vec2<u32>, 4>;
    var local_19: array<f32, 4>;
    var phi_642_: u32;
    var phi_663_: u32;
    var phi_702_: u32;
    var phi_705_: u32;
    var phi_703_: u32;
    var phi_706_: u32;
    var phi_748_: u32;
    var phi_751_: u32;
    var phi_749_: u32;
    var phi_752_: u32;
    var phi_794_: u32;
    var phi_797_: u32;
    var phi_795_: u32;
    var phi_798_: u32;
    var phi_840_: f32;
    var phi_2730_: bool;
    var phi_863_: u32;
    var local_20: u32;
    var local_21: u32;
    var local_22: u32;
    var local_23: u32;
    var phi_1010_: u32;
    var phi_1013_: f32;
    var phi_1015_: f32;
    var phi_1051_: f32;
    var phi_1011_: u32;
    var phi_1014_: f32;
    var phi_1016_: f32;
    var phi_2714_: bool;
    var local_24: f32;
    var local_25: f32;
    var local_26: u32;
    var phi_2755_: bool;
    var phi_864_: u32;
    var phi_2754_: bool;
    var phi_1134_: f32;
    var phi_1135_: bool;
    var phi_1149_: f32;
    var phi_1150_: f32;
    var phi_1188_: u32;
    var phi_1191_: f32;
    var phi_1193_: f32;
    var phi_1229_: f32;
    var phi_1189_: u32;
    var phi_1192_: f32;
    var phi_1194_: f32;
    var phi_2758_: bool;
    var local_27: f32;
    var local_28: f32;
    var local_29: u32;
    var phi_2791_: bool;
    var phi_1276_: u32;
    var local_30: u32;
    var local_31: u32;
    var local_32: u32;
    var local_33: u32;
    var phi_1423_: u32;
    var phi_1426_: f32;
    var phi_1428_: f32;
    var phi_1464_: f32;
    var phi_1424_: u32;
    var phi_1427_: f32;
    var phi_1429_: f32;
    var phi_2775_: bool;
    var local_34: f32;
    var local_35: f32;
    var local_36: u32;
    var phi_2797_: bool;
    var phi_1277_: u32;
    var phi_2796_: bool;
    var phi_1547_: f32;
    var phi_1548_: bool;
    var phi_1562_: f32;
    var phi_1563_: f32;
    var phi_1601_: u32;
    var phi_1604_: f32;
    var phi_1606_: f32;
    var phi_1642_: f32;
    var phi_1602_: u32;
    var phi_1605_: f32;
    var phi_1607_: f32;
    var phi_2800_: bool;
    var local_37: f32;
    var local_38: f32;
    var local_39: u32;
    var phi_2833_: bool;
    var phi_1689_: u32;
    var local_40: u32;
    var local_41: u32;
    var local_42: u32;
    var local_43: u32;
    var phi_1836_: u32;
    var phi_1839_: f32;
    var phi_1841_: f32;
    var phi_1877_: f32;
    var phi_1837_: u32;
    var phi_1840_: f32;
    var phi_1842_: f32;
    var phi_2817_: bool;
    var local_44: f32;
    var local_45: f32;
    var local_46: u32;
    var phi_2839_: bool;
    var phi_1690_: u32;
    var phi_2838_: bool;
    var phi_1960_: f32;
    var phi_1961_: bool;
    var phi_1975_: f32;
    var phi_1976_: f32;
    var phi_2014_: u32;
    var phi_2017_: f32;
    var phi_2019_: f32;
    var phi_2055_: f32;
    var phi_2015_: u32;
    var phi_2018_: f32;
    var phi_2020_: f32;
    var phi_2842_: bool;
    var local_47: f32;
    var local_48: f32;
    var local_49: u32;
    var phi_2875_: bool;
    var phi_2103_: u32;
    var local_50: u32;
    var local_51: u32;
    var local_52: u32;
    var local_53: u32;
    var phi_2250_: u32;
    var phi_2253_: f32;
    var phi_2255_: f32;
    var phi_2291_: f32;
    var phi_2251_: u32;
    var phi_2254_: f32;
    var phi_2256_: f32;
    var phi_2859_: bool;
    var local_54: f32;
    var local_55: f32;
    var local_56: u32;
    var phi_2881_: bool;
    var phi_2104_: u32;
    var phi_2880_: bool;
    var phi_2374_: f32;
    var phi_2375_: bool;
    var phi_2389_: f32;
    var phi_2390_: f32;
    var phi_2428_: u32;
    var phi_2431_: f32;
    var phi_2433_: f32;
    var phi_2469_: f32;
    var phi_2429_: u32;
    var phi_2432_: f32;
    var phi_2434_: f32;
    var phi_2884_: bool;
    var local_57: f32;
    var local_58: f32;
    var local_59: u32;
    var phi_2512_: u32;
    var phi_2515_: u32;
    var phi_2513_: u32;
    var phi_2516_: u32;
    var phi_2562_: bool;
    var phi_2573_: f32;
    var phi_2574_: f32;
    var phi_2611_: u32;
    var phi_2614_: f32;
    var phi_2616_: f32;
    var phi_2652_: f32;
    var phi_2612_: u32;
    var phi_2615_: f32;
    var phi_2617_: f32;
    var phi_2901_: bool;
    var local_60: f32;
    var local_61: f32;
    var local_62: u32;
    var phi_128_: u32;
    var phi_148_: u32;
    var phi_233_: u32;
    var phi_236_: u32;
    var phi_234_: u32;
    var phi_237_: u32;
    var phi_457_: u32;
    var phi_458_: u32;
    var phi_2926_: bool;
    var phi_513_: f32;
    var phi_557_: u32;
    var phi_560_: f32;
    var phi_562_: f32;
    var phi_598_: f32;
    var phi_558_: u32;
    var phi_561_: f32;
    var phi_563_: f32;
    var phi_2969_: bool;
    var local_63: f32;
    var local_64: f32;
    var local_65: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e44 = id_1;
            let _e51 = params.member.member.member[0u];
            let _e56 = select(select(u32(_e51), 0u, (_e51 < 0f)), 4294967295u, (_e51 > 4294967000f));
            let _e61 = params.member.member.member[1u];
            let _e66 = select(select(u32(_e61), 0u, (_e61 < 0f)), 4294967295u, (_e61 > 4294967000f));
            let _e69 = params.member.member_12;
            if (_e69 == 0u) {
                let _e1272 = (_e56 / 2u);
                if ((_e56 % 2u) > 0u) {
                    phi_128_ = (_e1272 + 1u);
                } else {
                    phi_128_ = _e1272;
                }
                let _e1277 = phi_128_;
                if (_e44.x < _e1277) {
                    let _e1279 = (_e66 / 2u);
                    if ((_e66 % 2u) > 0u) {
                        phi_148_ = (_e1279 + 1u);
                    } else {
                        phi_148_ = _e1279;
                    }
                    let _e1284 = phi_148_;
                    if (_e44.y < _e1284) {
                        let _e1287 = select(1u, _e56, (1u < _e56));
                        let _e1291 = (_e56 >> bitcast<u32>(1u));
                        let _e1293 = select(1u, _e1291, (1u < _e1291));
                        let _e1295 = (_e66 >> bitcast<u32>(1u));
                        phi_233_ = 0u;
                        phi_236_ = 0u;
                        loop {
                            let _e1299 = phi_233_;
                            let _e1301 = phi_236_;
                            local_65 = _e1301;
                            let _e1302 = (_e1299 < 1u);
                            if _e1302 {
                                let _e1303 = (_e1299 & 31u);
                                let _e1305 = (_e56 >> bitcast<u32>(_e1303));
                                let _e1309 = (_e66 >> bitcast<u32>(_e1303));
                                phi_234_ = (_e1299 + 1u);
                                phi_237_ = (_e1301 + (select(1u, _e1305, (1u < _e1305)) * select(1u, _e1309, (1u < _e1309))));
                            } else {
                                phi_234_ = u32();
                                phi_237_ = u32();
                            }
                            let _e1316 = phi_234_;
                            let _e1318 = phi_237_;
                            continue;
                            continuing {
                                phi_233_ = _e1316;
                                phi_236_ = _e1318;
                                break if !(_e1302);
                            }
                        }
                        let _e1320 = (2u * _e44.x);
                        let _e1321 = (2u * _e44.y);
                        let _e1322 = (_e1320 + 1u);
                        let _e1323 = (_e1321 + 1u);
                        local_18[0u][0u] = _e1320;
                        local_18[0u][1u] = _e1321;
                        local_18[1u][0u] = _e1322;
                        local_18[1u][1u] = _e1321;
                        local_18[2u][0u] = _e1320;
                        local_18[2u][1u] = _e1323;
                        local_18[3u][0u] = _e1322;
                        local_18[3u][1u] = _e1323;
                        let _e1340 = local_18[0u][0u];
                        let _e1341 = local_18[0u][1u];
                        let _e1342 = (_e56 - 1u);
                        let _e1345 = (_e66 - 1u);
                        let _e1352 = depth.member[((select(_e1341, _e1345, (_e1345 < _e1341)) * _e56) + select(_e1340, _e1342, (_e1342 < _e1340)))];
                        let _e1356 = params.member.member.member_3;
                        let _e1360 = select(_e1356, _e1352, select(false, (_e1352 < _e1356), (_e1352 > 0f)));
                        let _e1365 = local_18[1u][0u];
                        let _e1366 = local_18[1u][1u];
                        let _e1375 = depth.member[((select(_e1366, _e1345, (_e1345 < _e1366)) * _e56) + select(_e1365, _e1342, (_e1342 < _e1365)))];
                        let _e1379 = select(_e1356, _e1375, select(false, (_e1375 < _e1356), (_e1375 > 0f)));
                        let _e1384 = local_18[2u][0u];
                        let _e1385 = local_18[2u][1u];
                        let _e1394 = depth.member[((select(_e1385, _e1345, (_e1345 < _e1385)) * _e56) + select(_e1384, _e1342, (_e1342 < _e1384)))];
                        let _e1398 = select(_e1356, _e1394, select(false, (_e1394 < _e1356), (_e1394 > 0f)));
                        let _e1403 = local_18[3u][0u];
                        let _e1404 = local_18[3u][1u];
                        let _e1413 = depth.member[((select(_e1404, _e1345, (_e1345 < _e1404)) * _e56) + select(_e1403, _e1342, (_e1342 < _e1403)))];
                        let _e1417 = select(_e1356, _e1413, select(false, (_e1413 < _e1356), (_e1413 > 0f)));
                        local_19[0u] = select(0f, select(65504f, _e1360, (_e1360 < 65504f)), (_e1360 > 0f));
                        local_19[1u] = select(0f, select(65504f, _e1379, (_e1379 < 65504f)), (_e1379 > 0f));
                        local_19[2u] = select(0f, select(65504f, _e1398, (_e1398 < 65504f)), (_e1398 > 0f));
                        local_19[3u] = select(0f, select(65504f, _e1417, (_e1417 < 65504f)), (_e1417 > 0f));
                        phi_457_ = 0u;
                        loop {
                            let _e1427 = phi_457_;
                            let _e1428 = (_e1427 < 4u);
                            if _e1428 {
                                if _e1428 {
                                } else {
                                    phi_2926_ = true;
                                    break;
                                }
                                let _e1431 = local_18[_e1427][0u];
                                let _e1434 = local_18[_e1427][1u];
                                if _e1428 {
                                } else {
                                    phi_2926_ = true;
                                    break;
                                }
                                let _e1436 = local_19[_e1427];
                                if (_e1431 < _e1287) {
                                    if (_e1434 < select(1u, _e66, (1u < _e66))) {
                                        mips.member[((_e1434 * _e1287) + _e1431)] = _e1436;
                                    }
                                }
                                phi_458_ = (_e1427 + 1u);
                            } else {
                                phi_458_ = u32();
                            }
                            let _e1445 = phi_458_;
                            continue;
                            continuing {
                                phi_457_ = _e1445;
                                phi_2926_ = false;
                                break if !(_e1428);
                            }
                        }
                        let _e1448 = phi_2926_;
                        if _e1448 {
                            break;
                        }
                        let _e1451 = params.member.member_1;
                        let _e1454 = params.member.member_2;
                        let _e1456 = (0.75f * (_e1451 * _e1454));
                        let _e1459 = params.member.member_3;
                        let _e1460 = (_e1459 * _e1456);
                        let _e1461 = (_e1460 <= 0f);
                        if _e1461 {
                            phi_513_ = 0f;
                        } else {
                            phi_513_ = (1f / _e1460);
                        }
                        let _e1464 = phi_513_;
                        let _e1467 = local_19;
                        local_17 = _e1467;
                        let _e1469 = local_17[0u];
                        let _e1471 = local_17[1u];
                        let _e1475 = select(_e1471, _e1469, ((_e1469 > _e1471) || (_e1471 != _e1471)));
                        let _e1477 = local_17[2u];
                        let _e1479 = local_17[3u];
                        let _e1483 = select(_e1479, _e1477, ((_e1477 > _e1479) || (_e1479 != _e1479)));
                        phi_557_ = 0u;
                        phi_560_ = 0f;
                        phi_562_ = 0f;
                        loop {
                            let _e1489 = phi_557_;
                            let _e1491 = phi_560_;
                            let _e1493 = phi_562_;
                            local_63 = _e1493;
                            local_64 = _e1491;
                            let _e1494 = (_e1489 < 4u);
                            if _e1494 {
                                if _e1494 {
                                } else {
                                    phi_2969_ = true;
                                    break;
                                }
                                let _e1496 = local_17[_e1489];
                                let _e1497 = (select(_e1483, _e1475, ((_e1475 > _e1483) || (_e1483 != _e1483))) - _e1496);
                                if _e1461 {
                                    phi_598_ = select(0f, 1f, (_e1497 <= _e1456));
                                } else {
                                    let _e1499 = ((_e1497 * -(_e1464)) + (_e1456 * _e1464));
                                    phi_598_ = select(0f, select(1f, _e1499, (_e1499 < 1f)), (_e1499 > 0f));
                                }
                                let _e1507 = phi_598_;
                                if _e1494 {
                                } else {
                                    phi_2969_ = true;
                                    break;
                                }
                                let _e1508 = local_17[_e1489];
                                phi_558_ = (_e1489 + 1u);
                                phi_561_ = (_e1491 + _e1507);
                                phi_563_ = (_e1493 + (_e1507 * _e1508));
                            } else {
                                phi_558_ = u32();
                                phi_561_ = f32();
                                phi_563_ = f32();
                            }
                            let _e1514 = phi_558_;
                            let _e1516 = phi_561_;
                            let _e1518 = phi_563_;
                            continue;
                            continuing {
                                phi_557_ = _e1514;
                                phi_560_ = _e1516;
                                phi_562_ = _e1518;
                                phi_2969_ = _e1448;
                                break if !(_e1494);
                            }
                        }
                        let _e1521 = phi_2969_;
                        if _e1521 {
                            break;
                        }
                        let _e1523 = local_63;
                        let _e1525 = local_64;
                        if (_e44.x < _e1293) {
                            if (_e44.y < select(1u, _e1295, (1u < _e1295))) {
                                let _e1532 = local_65;
                                mips.member[(_e1532 + ((_e44.y * _e1293) + _e44.x))] = (_e1523 / _e1525);
                            }
                        }
                    }
                }
            } else {
                let _e71 = (_e56 / 16u);
                if ((_e56 % 16u) > 0u) {
                    phi_642_ = (_e71 + 1u);
                } else {
                    phi_642_ = _e71;
                }
                let _e76 = phi_642_;
                if (_e44.x < _e76) {
                    let _e78 = (_e66 / 16u);
                    if ((_e66 % 16u) > 0u) {
                        phi_663_ = (_e78 + 1u);
                    } else {
                        phi_663_ = _e78;
                    }
                    let _e83 = phi_663_;
                    if (_e44.y < _e83) {
                        let _e86 = (_e56 >> bitcast<u32>(1u));
                        let _e88 = select(1u, _e86, (1u < _e86));
                        let _e90 = (_e66 >> bitcast<u32>(1u));
                        let _e92 = select(1u, _e90, (1u < _e90));
                        phi_702_ = 0u;
                        phi_705_ = 0u;
                        loop {
                            let _e94 = phi_702_;
                            let _e96 = phi_705_;
                            local_20 = _e96;
                            local_21 = _e96;
                            local_22 = _e96;
                            local_23 = _e96;
                            local_30 = _e96;
                            local_31 = _e96;
                            local_32 = _e96;
                            local_33 = _e96;
                            local_40 = _e96;
                            local_41 = _e96;
                            local_42 = _e96;
                            local_43 = _e96;
                            local_50 = _e96;
                            local_51 = _e96;
                            local_52 = _e96;
                            local_53 = _e96;
                            let _e97 = (_e94 < 1u);
                            if _e97 {
                                let _e98 = (_e94 & 31u);
                                let _e100 = (_e56 >> bitcast<u32>(_e98));
                                let _e104 = (_e66 >> bitcast<u32>(_e98));
                                phi_703_ = (_e94 + 1u);
                                phi_706_ = (_e96 + (select(1u, _e100, (1u < _e100)) * select(1u, _e104, (1u < _e104))));
                            } else {
                                phi_703_ = u32();
                                phi_706_ = u32();
                            }
                            let _e111 = phi_703_;
                            let _e113 = phi_706_;
                            continue;
                            continuing {
                                phi_702_ = _e111;
                                phi_705_ = _e113;
                                break if !(_e97);
                            }
                        }
                        let _e116 = (_e56 >> bitcast<u32>(2u));
                        let _e118 = select(1u, _e116, (1u < _e116));
                        let _e120 = (_e66 >> bitcast<u32>(2u));
                        let _e122 = select(1u, _e120, (1u < _e120));
                        phi_748_ = 0u;
                        phi_751_ = 0u;
                        loop {
                            let _e124 = phi_748_;
                            let _e126 = phi_751_;
                            local_26 = _e126;
                            local_36 = _e126;
                            local_46 = _e126;
                            local_56 = _e126;
                            let _e127 = (_e124 < 2u);
                            if _e127 {
                                let _e128 = (_e124 & 31u);
                                let _e130 = (_e56 >> bitcast<u32>(_e128));
                                let _e134 = (_e66 >> bitcast<u32>(_e128));
                                phi_749_ = (_e124 + 1u);
                                phi_752_ = (_e126 + (select(1u, _e130, (1u < _e130)) * select(1u, _e134, (1u < _e134))));
                            } else {
                                phi_749_ = u32();
                                phi_752_ = u32();
                            }
                            let _e141 = phi_749_;
                            let _e143 = phi_752_;
                            continue;
                            continuing {
                                phi_748_ = _e141;
                                phi_751_ = _e143;
                                break if !(_e127);
                            }
                        }
                        let _e146 = (_e56 >> bitcast<u32>(3u));
                        let _e148 = select(1u, _e146, (1u < _e146));
                        let _e150 = (_e66 >> bitcast<u32>(3u));
                        let _e152 = select(1u, _e150, (1u < _e150));
                        phi_794_ = 0u;
                        phi_797_ = 0u;
                        loop {
                            let _e154 = phi_794_;
                            let _e156 = phi_797_;
                            local_29 = _e156;
                            local_39 = _e156;
                            local_49 = _e156;
                            local_59 = _e156;
                            let _e157 = (_e154 < 3u);
                            if _e157 {
                                let _e158 = (_e154 & 31u);
                                let _e160 = (_e56 >> bitcast<u32>(_e158));
                                let _e164 = (_e66 >> bitcast<u32>(_e158));
                                phi_795_ = (_e154 + 1u);
                                phi_798_ = (_e156 + (select(1u, _e160, (1u < _e160)) * select(1u, _e164, (1u < _e164))));
                            } else {
                                phi_795_ = u32();
                                phi_798_ = u32();
                            }
                            let _e171 = phi_795_;
                            let _e173 = phi_798_;
                            continue;
                            continuing {
                                phi_794_ = _e171;
                                phi_797_ = _e173;
                                break if !(_e157);
                            }
                        }
                        let _e177 = params.member.member_1;
                        let _e180 = params.member.member_2;
                        let _e182 = (0.75f * (_e177 * _e180));
                        let _e185 = params.member.member_3;
                        let _e186 = (_e185 * _e182);
                        let _e187 = (_e186 <= 0f);
                        if _e187 {
                            phi_840_ = 0f;
                        } else {
                            phi_840_ = (1f / _e186);
                        }
                        let _e190 = phi_840_;
                        let _e191 = -(_e190);
                        let _e192 = (_e182 * _e190);
                        let _e193 = (2u * _e44.x);
                        let _e194 = (2u * _e44.y);
                        let _e195 = (_e44.x * 4u);
                        let _e196 = (_e44.y * 4u);
                        let _e197 = (_e195 + 1u);
                        let _e198 = (_e196 + 1u);
                        local_15[0u][0u] = _e195;
                        local_15[0u][1u] = _e196;
                        local_15[1u][0u] = _e197;
                        local_15[1u][1u] = _e196;
                        local_15[2u][0u] = _e195;
                        local_15[2u][1u] = _e198;
                        local_15[3u][0u] = _e197;
                        local_15[3u][1u] = _e198;
                        local_16 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_2730_ = false;
                        phi_863_ = 0u;
                        loop {
                            let _e216 = phi_2730_;
                            let _e218 = phi_863_;
                            let _e219 = (_e218 < 4u);
                            if _e219 {
                                if _e219 {
                                } else {
                                    phi_2754_ = true;
                                    break;
                                }
                                let _e222 = local_15[_e218][0u];
                                let _e223 = (2u * _e222);
                                if _e219 {
                                } else {
                                    phi_2754_ = true;
                                    break;
                                }
                                let _e226 = local_15[_e218][1u];
                                let _e227 = (2u * _e226);
                                let _e228 = (_e92 - 1u);
                                let _e231 = (select(_e227, _e228, (_e228 < _e227)) * _e88);
                                let _e232 = (_e88 - 1u);
                                let _e234 = select(_e223, _e232, (_e232 < _e223));
                                let _e237 = local_20;
                                let _e241 = mips.member[(_e237 + (_e231 + _e234))];
                                let _e242 = (_e223 + 1u);
                                let _e244 = select(_e242, _e232, (_e232 < _e242));
                                let _e247 = local_21;
                                let _e251 = mips.member[(_e247 + (_e231 + _e244))];
                                let _e252 = (_e227 + 1u);
                                let _e255 = (select(_e252, _e228, (_e228 < _e252)) * _e88);
                                let _e258 = local_22;
                                let _e262 = mips.member[(_e258 + (_e255 + _e234))];
                                let _e265 = local_23;
                                let _e269 = mips.member[(_e265 + (_e255 + _e244))];
                                local_14 = array<f32, 4>(_e241, _e251, _e262, _e269);
                                let _e272 = local_14[0u];
                                let _e274 = local_14[1u];
                                let _e278 = select(_e274, _e272, ((_e272 > _e274) || (_e274 != _e274)));
                                let _e280 = local_14[2u];
                                let _e282 = local_14[3u];
                                let _e286 = select(_e282, _e280, ((_e280 > _e282) || (_e282 != _e282)));
                                phi_1010_ = 0u;
                                phi_1013_ = 0f;
                                phi_1015_ = 0f;
                                loop {
                                    let _e292 = phi_1010_;
                                    let _e294 = phi_1013_;
                                    let _e296 = phi_1015_;
                                    local_24 = _e296;
                                    local_25 = _e294;
                                    let _e297 = (_e292 < 4u);
                                    if _e297 {
                                        if _e297 {
                                        } else {
                                            phi_2714_ = true;
                                            break;
                                        }
                                        let _e299 = local_14[_e292];
                                        let _e300 = (select(_e286, _e278, ((_e278 > _e286) || (_e286 != _e286))) - _e299);
                                        if _e187 {
                                            phi_1051_ = select(0f, 1f, (_e300 <= _e182));
                                        } else {
                                            let _e302 = ((_e300 * _e191) + _e192);
                                            phi_1051_ = select(0f, select(1f, _e302, (_e302 < 1f)), (_e302 > 0f));
                                        }
                                        let _e310 = phi_1051_;
                                        if _e297 {
                                        } else {
                                            phi_2714_ = true;
                                            break;
                                        }
                                        let _e311 = local_14[_e292];
                                        phi_1011_ = (_e292 + 1u);
                                        phi_1014_ = (_e294 + _e310);
                                        phi_1016_ = (_e296 + (_e310 * _e311));
                                    } else {
                                        phi_1011_ = u32();
                                        phi_1014_ = f32();
                                        phi_1016_ = f32();
                                    }
                                    let _e317 = phi_1011_;
                                    let _e319 = phi_1014_;
                                    let _e321 = phi_1016_;
                                    continue;
                                    continuing {
                                        phi_1010_ = _e317;
                                        phi_1013_ = _e319;
                                        phi_1015_ = _e321;
                                        phi_2714_ = _e216;
                                        break if !(_e297);
                                    }
                                }
                                let _e324 = phi_2714_;
                                phi_2754_ = _e324;
                                if _e324 {
                                    break;
                                }
                                let _e326 = local_24;
                                let _e328 = local_25;
                                if _e219 {
                                } else {
                                    phi_2754_ = true;
                                    break;
                                }
                                local_16[_e218] = (_e326 / _e328);
                                if _e219 {
                                } else {
                                    phi_2754_ = true;
                                    break;
                                }
                                let _e331 = local_15[_e218][0u];
                                let _e332 = local_15[_e218][1u];
                                if _e219 {
                                } else {
                                    phi_2754_ = true;
                                    break;
                                }
                                let _e333 = local_16[_e218];
                                if (_e331 < _e118) {
                                    if (_e332 < _e122) {
                                        let _e339 = local_26;
                                        mips.member[(_e339 + ((_e332 * _e118) + _e331))] = _e333;
                                    }
                                }
                                phi_2755_ = _e324;
                                phi_864_ = (_e218 + 1u);
                            } else {
                                phi_2755_ = _e216;
                                phi_864_ = u32();
                            }
                            let _e345 = phi_2755_;
                            let _e347 = phi_864_;
                            continue;
                            continuing {
                                phi_2730_ = _e345;
                                phi_863_ = _e347;
                                phi_2754_ = _e345;
                                break if !(_e219);
                            }
                        }
                        let _e350 = phi_2754_;
                        if _e350 {
                            break;
                        }
                        let _e351 = local_16;
                        let _e356 = (_e118 == 1u);
                        let _e357 = (_e122 == 1u);
                        if _e356 {
                            phi_1134_ = select(f32(), _e351[0], _e357);
                            phi_1135_ = select(true, false, _e357);
                        } else {
                            phi_1134_ = f32();
                            phi_1135_ = true;
                        }
                        let _e363 = phi_1134_;
                        let _e365 = phi_1135_;
                        if _e365 {
                            if _e356 {
                                phi_1149_ = _e351[2];
                            } else {
                                phi_1149_ = select(_e351[3], _e351[1], _e357);
                            }
                            let _e368 = phi_1149_;
                            phi_1150_ = _e368;
                        } else {
                            phi_1150_ = _e363;
                        }
                        let _e370 = phi_1150_;
                        local_13 = array<f32, 4>(_e351[0], select(_e351[1], _e351[0], _e356), select(_e351[2], _e351[0], _e357), _e370);
                        let _e373 = local_13[0u];
                        let _e375 = local_13[1u];
                        let _e379 = select(_e375, _e373, ((_e373 > _e375) || (_e375 != _e375)));
                        let _e381 = local_13[2u];
                        let _e383 = local_13[3u];
                        let _e387 = select(_e383, _e381, ((_e381 > _e383) || (_e383 != _e383)));
                        phi_1188_ = 0u;
                        phi_1191_ = 0f;
                        phi_1193_ = 0f;
                        loop {
                            let _e393 = phi_1188_;
                            let _e395 = phi_1191_;
                            let _e397 = phi_1193_;
                            local_27 = _e397;
                            local_28 = _e395;
                            let _e398 = (_e393 < 4u);
                            if _e398 {
                                if _e398 {
                                } else {
                                    phi_2758_ = true;
                                    break;
                                }
                                let _e400 = local_13[_e393];
                                let _e401 = (select(_e387, _e379, ((_e379 > _e387) || (_e387 != _e387))) - _e400);
                                if _e187 {
                                    phi_1229_ = select(0f, 1f, (_e401 <= _e182));
                                } else {
                                    let _e403 = ((_e401 * _e191) + _e192);
                                    phi_1229_ = select(0f, select(1f, _e403, (_e403 < 1f)), (_e403 > 0f));
                                }
                                let _e411 = phi_1229_;
                                if _e398 {
                                } else {
                                    phi_2758_ = true;
                                    break;
                                }
                                let _e412 = local_13[_e393];
                                phi_1189_ = (_e393 + 1u);
                                phi_1192_ = (_e395 + _e411);
                                phi_1194_ = (_e397 + (_e411 * _e412));
                            } else {
                                phi_1189_ = u32();
                                phi_1192_ = f32();
                                phi_1194_ = f32();
                            }
                            let _e418 = phi_1189_;
                            let _e420 = phi_1192_;
                            let _e422 = phi_1194_;
                            continue;
                            continuing {
                                phi_1188_ = _e418;
                                phi_1191_ = _e420;
                                phi_1193_ = _e422;
                                phi_2758_ = _e350;
                                break if !(_e398);
                            }
                        }
                        let _e425 = phi_2758_;
                        if _e425 {
                            break;
                        }
                        let _e427 = local_27;
                        let _e429 = local_28;
                        let _e430 = (_e427 / _e429);
                        let _e431 = (_e193 < _e148);
                        if _e431 {
                            if (_e194 < _e152) {
                                let _e436 = local_29;
                                mips.member[(_e436 + ((_e194 * _e148) + _e193))] = _e430;
                            }
                        }
                        let _e440 = (_e193 + 1u);
                        let _e441 = (2u * _e440);
                        let _e442 = (_e441 + 1u);
                        local_11[0u][0u] = _e441;
                        local_11[0u][1u] = _e196;
                        local_11[1u][0u] = _e442;
                        local_11[1u][1u] = _e196;
                        local_11[2u][0u] = _e441;
                        local_11[2u][1u] = _e198;
                        local_11[3u][0u] = _e442;
                        local_11[3u][1u] = _e198;
                        local_12 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_2791_ = _e425;
                        phi_1276_ = 0u;
                        loop {
                            let _e460 = phi_2791_;
                            let _e462 = phi_1276_;
                            let _e463 = (_e462 < 4u);
                            if _e463 {
                                if _e463 {
                                } else {
                                    phi_2796_ = true;
                                    break;
                                }
                                let _e466 = local_11[_e462][0u];
                                let _e467 = (2u * _e466);
                                if _e463 {
                                } else {
                                    phi_2796_ = true;
                                    break;
                                }
                                let _e470 = local_11[_e462][1u];
                                let _e471 = (2u * _e470);
                                let _e472 = (_e92 - 1u);
                                let _e475 = (select(_e471, _e472, (_e472 < _e471)) * _e88);
                                let _e476 = (_e88 - 1u);
                                let _e478 = select(_e467, _e476, (_e476 < _e467));
                                let _e481 = local_30;
                                let _e485 = mips.member[(_e481 + (_e475 + _e478))];
                                let _e486 = (_e467 + 1u);
                                let _e488 = select(_e486, _e476, (_e476 < _e486));
                                let _e491 = local_31;
                                let _e495 = mips.member[(_e491 + (_e475 + _e488))];
                                let _e496 = (_e471 + 1u);
                                let _e499 = (select(_e496, _e472, (_e472 < _e496)) * _e88);
                                let _e502 = local_32;
                                let _e506 = mips.member[(_e502 + (_e499 + _e478))];
                                let _e509 = local_33;
                                let _e513 = mips.member[(_e509 + (_e499 + _e488))];
                                local_10 = array<f32, 4>(_e485, _e495, _e506, _e513);
                                let _e516 = local_10[0u];
                                let _e518 = local_10[1u];
                                let _e522 = select(_e518, _e516, ((_e516 > _e518) || (_e518 != _e518)));
                                let _e524 = local_10[2u];
                                let _e526 = local_10[3u];
                                let _e530 = select(_e526, _e524, ((_e524 > _e526) || (_e526 != _e526)));
                                phi_1423_ = 0u;
                                phi_1426_ = 0f;
                                phi_1428_ = 0f;
                                loop {
                                    let _e536 = phi_1423_;
                                    let _e538 = phi_1426_;
                                    let _e540 = phi_1428_;
                                    local_34 = _e540;
                                    local_35 = _e538;
                                    let _e541 = (_e536 < 4u);
                                    if _e541 {
                                        if _e541 {
                                        } else {
                                            phi_2775_ = true;
                                            break;
                                        }
                                        let _e543 = local_10[_e536];
                                        let _e544 = (select(_e530, _e522, ((_e522 > _e530) || (_e530 != _e530))) - _e543);
                                        if _e187 {
                                            phi_1464_ = select(0f, 1f, (_e544 <= _e182));
                                        } else {
                                            let _e546 = ((_e544 * _e191) + _e192);
                                            phi_1464_ = select(0f, select(1f, _e546, (_e546 < 1f)), (_e546 > 0f));
                                        }
                                        let _e554 = phi_1464_;
                                        if _e541 {
                                        } else {
                                            phi_2775_ = true;
                                            break;
                                        }
                                        let _e555 = local_10[_e536];
                                        phi_1424_ = (_e536 + 1u);
                                        phi_1427_ = (_e538 + _e554);
                                        phi_1429_ = (_e540 + (_e554 * _e555));
                                    } else {
                                        phi_1424_ = u32();
                                        phi_1427_ = f32();
                                        phi_1429_ = f32();
                                    }
                                    let _e561 = phi_1424_;
                                    let _e563 = phi_1427_;
                                    let _e565 = phi_1429_;
                                    continue;
                                    continuing {
                                        phi_1423_ = _e561;
                                        phi_1426_ = _e563;
                                        phi_1428_ = _e565;
                                        phi_2775_ = _e460;
                                        break if !(_e541);
                                    }
                                }
                                let _e568 = phi_2775_;
                                phi_2796_ = _e568;
                                if _e568 {
                                    break;
                                }
                                let _e570 = local_34;
                                let _e572 = local_35;
                                if _e463 {
                                } else {
                                    phi_2796_ = true;
                                    break;
                                }
                                local_12[_e462] = (_e570 / _e572);
                                if _e463 {
                                } else {
                                    phi_2796_ = true;
                                    break;
                                }
                                let _e575 = local_11[_e462][0u];
                                let _e576 = local_11[_e462][1u];
                                if _e463 {
                                } else {
                                    phi_2796_ = true;
                                    break;
                                }
                                let _e577 = local_12[_e462];
                                if (_e575 < _e118) {
                                    if (_e576 < _e122) {
                                        let _e583 = local_36;
                                        mips.member[(_e583 + ((_e576 * _e118) + _e575))] = _e577;
                                    }
                                }
                                phi_2797_ = _e568;
                                phi_1277_ = (_e462 + 1u);
                            } else {
                                phi_2797_ = _e460;
                                phi_1277_ = u32();
                            }
                            let _e589 = phi_2797_;
                            let _e591 = phi_1277_;
                            continue;
                            continuing {
                                phi_2791_ = _e589;
                                phi_1276_ = _e591;
                                phi_2796_ = _e589;
                                break if !(_e463);
                            }
                        }
                        let _e594 = phi_2796_;
                        if _e594 {
                            break;
                        }
                        let _e595 = local_12;
                        if _e356 {
                            phi_1547_ = select(f32(), _e595[0], _e357);
                            phi_1548_ = select(true, false, _e357);
                        } else {
                            phi_1547_ = f32();
                            phi_1548_ = true;
                        }
                        let _e605 = phi_1547_;
                        let _e607 = phi_1548_;
                        if _e607 {
                            if _e356 {
                                phi_1562_ = _e595[2];
                            } else {
                                phi_1562_ = select(_e595[3], _e595[1], _e357);
                            }
                            let _e610 = phi_1562_;
                            phi_1563_ = _e610;
                        } else {
                            phi_1563_ = _e605;
                        }
                        let _e612 = phi_1563_;
                        local_9 = array<f32, 4>(_e595[0], select(_e595[1], _e595[0], _e356), select(_e595[2], _e595[0], _e357), _e612);
                        let _e615 = local_9[0u];
                        let _e617 = local_9[1u];
                        let _e621 = select(_e617, _e615, ((_e615 > _e617) || (_e617 != _e617)));
                        let _e623 = local_9[2u];
                        let _e625 = local_9[3u];
                        let _e629 = select(_e625, _e623, ((_e623 > _e625) || (_e625 != _e625)));
                        phi_1601_ = 0u;
                        phi_1604_ = 0f;
                        phi_1606_ = 0f;
                        loop {
                            let _e635 = phi_1601_;
                            let _e637 = phi_1604_;
                            let _e639 = phi_1606_;
                            local_37 = _e639;
                            local_38 = _e637;
                            let _e640 = (_e635 < 4u);
                            if _e640 {
                                if _e640 {
                                } else {
                                    phi_2800_ = true;
                                    break;
                                }
                                let _e642 = local_9[_e635];
                                let _e643 = (select(_e629, _e621, ((_e621 > _e629) || (_e629 != _e629))) - _e642);
                                if _e187 {
                                    phi_1642_ = select(0f, 1f, (_e643 <= _e182));
                                } else {
                                    let _e645 = ((_e643 * _e191) + _e192);
                                    phi_1642_ = select(0f, select(1f, _e645, (_e645 < 1f)), (_e645 > 0f));
                                }
                                let _e653 = phi_1642_;
                                if _e640 {
                                } else {
                                    phi_2800_ = true;
                                    break;
                                }
                                let _e654 = local_9[_e635];
                                phi_1602_ = (_e635 + 1u);
                                phi_1605_ = (_e637 + _e653);
                                phi_1607_ = (_e639 + (_e653 * _e654));
                            } else {
                                phi_1602_ = u32();
                                phi_1605_ = f32();
                                phi_1607_ = f32();
                            }
                            let _e660 = phi_1602_;
                            let _e662 = phi_1605_;
                            let _e664 = phi_1607_;
                            continue;
                            continuing {
                                phi_1601_ = _e660;
                                phi_1604_ = _e662;
                                phi_1606_ = _e664;
                                phi_2800_ = _e594;
                                break if !(_e640);
                            }
                        }
                        let _e667 = phi_2800_;
                        if _e667 {
                            break;
                        }
                        let _e669 = local_37;
                        let _e671 = local_38;
                        let _e672 = (_e669 / _e671);
                        let _e673 = (_e440 < _e148);
                        if _e673 {
                            if (_e194 < _e152) {
                                let _e678 = local_39;
                                mips.member[(_e678 + ((_e194 * _e148) + _e440))] = _e672;
                            }
                        }
                        let _e682 = (_e194 + 1u);
                        let _e683 = (2u * _e682);
                        let _e684 = (_e683 + 1u);
                        local_7[0u][0u] = _e195;
                        local_7[0u][1u] = _e683;
                        local_7[1u][0u] = _e197;
                        local_7[1u][1u] = _e683;
                        local_7[2u][0u] = _e195;
                        local_7[2u][1u] = _e684;
                        local_7[3u][0u] = _e197;
                        local_7[3u][1u] = _e684;
                        local_8 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_2833_ = _e667;
                        phi_1689_ = 0u;
                        loop {
                            let _e702 = phi_2833_;
                            let _e704 = phi_1689_;
                            let _e705 = (_e704 < 4u);
                            if _e705 {
                                if _e705 {
                                } else {
                                    phi_2838_ = true;
                                    break;
                                }
                                let _e708 = local_7[_e704][0u];
                                let _e709 = (2u * _e708);
                                if _e705 {
                                } else {
                                    phi_2838_ = true;
                                    break;
                                }
                                let _e712 = local_7[_e704][1u];
                                let _e713 = (2u * _e712);
                                let _e714 = (_e92 - 1u);
                                let _e717 = (select(_e713, _e714, (_e714 < _e713)) * _e88);
                                let _e718 = (_e88 - 1u);
                                let _e720 = select(_e709, _e718, (_e718 < _e709));
                                let _e723 = local_40;
                                let _e727 = mips.member[(_e723 + (_e717 + _e720))];
                                let _e728 = (_e709 + 1u);
                                let _e730 = select(_e728, _e718, (_e718 < _e728));
                                let _e733 = local_41;
                                let _e737 = mips.member[(_e733 + (_e717 + _e730))];
                                let _e738 = (_e713 + 1u);
                                let _e741 = (select(_e738, _e714, (_e714 < _e738)) * _e88);
                                let _e744 = local_42;
                                let _e748 = mips.member[(_e744 + (_e741 + _e720))];
                                let _e751 = local_43;
                                let _e755 = mips.member[(_e751 + (_e741 + _e730))];
                                local_6 = array<f32, 4>(_e727, _e737, _e748, _e755);
                                let _e758 = local_6[0u];
                                let _e760 = local_6[1u];
                                let _e764 = select(_e760, _e758, ((_e758 > _e760) || (_e760 != _e760)));
                                let _e766 = local_6[2u];
                                let _e768 = local_6[3u];
                                let _e772 = select(_e768, _e766, ((_e766 > _e768) || (_e768 != _e768)));
                                phi_1836_ = 0u;
                                phi_1839_ = 0f;
                                phi_1841_ = 0f;
                                loop {
                                    let _e778 = phi_1836_;
                                    let _e780 = phi_1839_;
                                    let _e782 = phi_1841_;
                                    local_44 = _e782;
                                    local_45 = _e780;
                                    let _e783 = (_e778 < 4u);
                                    if _e783 {
                                        if _e783 {
                                        } else {
                                            phi_2817_ = true;
                                            break;
                                        }
                                        let _e785 = local_6[_e778];
                                        let _e786 = (select(_e772, _e764, ((_e764 > _e772) || (_e772 != _e772))) - _e785);
                                        if _e187 {
                                            phi_1877_ = select(0f, 1f, (_e786 <= _e182));
                                        } else {
                                            let _e788 = ((_e786 * _e191) + _e192);
                                            phi_1877_ = select(0f, select(1f, _e788, (_e788 < 1f)), (_e788 > 0f));
                                        }
                                        let _e796 = phi_1877_;
                                        if _e783 {
                                        } else {
                                            phi_2817_ = true;
                                            break;
                                        }
                                        let _e797 = local_6[_e778];
                                        phi_1837_ = (_e778 + 1u);
                                        phi_1840_ = (_e780 + _e796);
                                        phi_1842_ = (_e782 + (_e796 * _e797));
                                    } else {
                                        phi_1837_ = u32();
                                        phi_1840_ = f32();
                                        phi_1842_ = f32();
                                    }
                                    let _e803 = phi_1837_;
                                    let _e805 = phi_1840_;
                                    let _e807 = phi_1842_;
                                    continue;
                                    continuing {
                                        phi_1836_ = _e803;
                                        phi_1839_ = _e805;
                                        phi_1841_ = _e807;
                                        phi_2817_ = _e702;
                                        break if !(_e783);
                                    }
                                }
                                let _e810 = phi_2817_;
                                phi_2838_ = _e810;
                                if _e810 {
                                    break;
                                }
                                let _e812 = local_44;
                                let _e814 = local_45;
                                if _e705 {
                                } else {
                                    phi_2838_ = true;
                                    break;
                                }
                                local_8[_e704] = (_e812 / _e814);
                                if _e705 {
                                } else {
                                    phi_2838_ = true;
                                    break;
                                }
                                let _e817 = local_7[_e704][0u];
                                let _e818 = local_7[_e704][1u];
                                if _e705 {
                                } else {
                                    phi_2838_ = true;
                                    break;
                                }
                                let _e819 = local_8[_e704];
                                if (_e817 < _e118) {
                                    if (_e818 < _e122) {
                                        let _e825 = local_46;
                                        mips.member[(_e825 + ((_e818 * _e118) + _e817))] = _e819;
                                    }
                                }
                                phi_2839_ = _e810;
                                phi_1690_ = (_e704 + 1u);
                            } else {
                                phi_2839_ = _e702;
                                phi_1690_ = u32();
                            }
                            let _e831 = phi_2839_;
                            let _e833 = phi_1690_;
                            continue;
                            continuing {
                                phi_2833_ = _e831;
                                phi_1689_ = _e833;
                                phi_2838_ = _e831;
                                break if !(_e705);
                            }
                        }
                        let _e836 = phi_2838_;
                        if _e836 {
                            break;
                        }
                        let _e837 = local_8;
                        if _e356 {
                            phi_1960_ = select(f32(), _e837[0], _e357);
                            phi_1961_ = select(true, false, _e357);
                        } else {
                            phi_1960_ = f32();
                            phi_1961_ = true;
                        }
                        let _e847 = phi_1960_;
                        let _e849 = phi_1961_;
                        if _e849 {
                            if _e356 {
                                phi_1975_ = _e837[2];
                            } else {
                                phi_1975_ = select(_e837[3], _e837[1], _e357);
                            }
                            let _e852 = phi_1975_;
                            phi_1976_ = _e852;
                        } else {
                            phi_1976_ = _e847;
                        }
                        let _e854 = phi_1976_;
                        local_5 = array<f32, 4>(_e837[0], select(_e837[1], _e837[0], _e356), select(_e837[2], _e837[0], _e357), _e854);
                        let _e857 = local_5[0u];
                        let _e859 = local_5[1u];
                        let _e863 = select(_e859, _e857, ((_e857 > _e859) || (_e859 != _e859)));
                        let _e865 = local_5[2u];
                        let _e867 = local_5[3u];
                        let _e871 = select(_e867, _e865, ((_e865 > _e867) || (_e867 != _e867)));
                        phi_2014_ = 0u;
                        phi_2017_ = 0f;
                        phi_2019_ = 0f;
                        loop {
                            let _e877 = phi_2014_;
                            let _e879 = phi_2017_;
                            let _e881 = phi_2019_;
                            local_47 = _e881;
                            local_48 = _e879;
                            let _e882 = (_e877 < 4u);
                            if _e882 {
                                if _e882 {
                                } else {
                                    phi_2842_ = true;
                                    break;
                                }
                                let _e884 = local_5[_e877];
                                let _e885 = (select(_e871, _e863, ((_e863 > _e871) || (_e871 != _e871))) - _e884);
                                if _e187 {
                                    phi_2055_ = select(0f, 1f, (_e885 <= _e182));
                                } else {
                                    let _e887 = ((_e885 * _e191) + _e192);
                                    phi_2055_ = select(0f, select(1f, _e887, (_e887 < 1f)), (_e887 > 0f));
                                }
                                let _e895 = phi_2055_;
                                if _e882 {
                                } else {
                                    phi_2842_ = true;
                                    break;
                                }
                                let _e896 = local_5[_e877];
                                phi_2015_ = (_e877 + 1u);
                                phi_2018_ = (_e879 + _e895);
                                phi_2020_ = (_e881 + (_e895 * _e896));
                            } else {
                                phi_2015_ = u32();
                                phi_2018_ = f32();
                                phi_2020_ = f32();
                            }
                            let _e902 = phi_2015_;
                            let _e904 = phi_2018_;
                            let _e906 = phi_2020_;
                            continue;
                            continuing {
                                phi_2014_ = _e902;
                                phi_2017_ = _e904;
                                phi_2019_ = _e906;
                                phi_2842_ = _e836;
                                break if !(_e882);
                            }
                        }
                        let _e909 = phi_2842_;
                        if _e909 {
                            break;
                        }
                        let _e911 = local_47;
                        let _e913 = local_48;
                        let _e914 = (_e911 / _e913);
                        if _e431 {
                            if (_e682 < _e152) {
                                let _e919 = local_49;
                                mips.member[(_e919 + ((_e682 * _e148) + _e193))] = _e914;
                            }
                        }
                        local_3[0u][0u] = _e441;
                        local_3[0u][1u] = _e683;
                        local_3[1u][0u] = _e442;
                        local_3[1u][1u] = _e683;
                        local_3[2u][0u] = _e441;
                        local_3[2u][1u] = _e684;
                        local_3[3u][0u] = _e442;
                        local_3[3u][1u] = _e684;
                        local_4 = array<f32, 4>(0f, 0f, 0f, 0f);
                        phi_2875_ = _e909;
                        phi_2103_ = 0u;
                        loop {
                            let _e940 = phi_2875_;
                            let _e942 = phi_2103_;
                            let _e943 = (_e942 < 4u);
                            if _e943 {
                                if _e943 {
                                } else {
                                    phi_2880_ = true;
                                    break;
                                }
                                let _e946 = local_3[_e942][0u];
                                let _e947 = (2u * _e946);
                                if _e943 {
                                } else {
                                    phi_2880_ = true;
                                    break;
                                }
                                let _e950 = local_3[_e942][1u];
                                let _e951 = (2u * _e950);
                                let _e952 = (_e92 - 1u);
                                let _e955 = (select(_e951, _e952, (_e952 < _e951)) * _e88);
                                let _e956 = (_e88 - 1u);
                                let _e958 = select(_e947, _e956, (_e956 < _e947));
                                let _e961 = local_50;
                                let _e965 = mips.member[(_e961 + (_e955 + _e958))];
                                let _e966 = (_e947 + 1u);
                                let _e968 = select(_e966, _e956, (_e956 < _e966));
                                let _e971 = local_51;
                                let _e975 = mips.member[(_e971 + (_e955 + _e968))];
                                let _e976 = (_e951 + 1u);
                                let _e979 = (select(_e976, _e952, (_e952 < _e976)) * _e88);
                                let _e982 = local_52;
                                let _e986 = mips.member[(_e982 + (_e979 + _e958))];
                                let _e989 = local_53;
                                let _e993 = mips.member[(_e989 + (_e979 + _e968))];
                                local_2 = array<f32, 4>(_e965, _e975, _e986, _e993);
                                let _e996 = local_2[0u];
                                let _e998 = local_2[1u];
                                let _e1002 = select(_e998, _e996, ((_e996 > _e998) || (_e998 != _e998)));
                                let _e1004 = local_2[2u];
                                let _e1006 = local_2[3u];
                                let _e1010 = select(_e1006, _e1004, ((_e1004 > _e1006) || (_e1006 != _e1006)));
                                phi_2250_ = 0u;
                                phi_2253_ = 0f;
                                phi_2255_ = 0f;
                                loop {
                                    let _e1016 = phi_2250_;
                                    let _e1018 = phi_2253_;
                                    let _e1020 = phi_2255_;
                                    local_54 = _e1020;
                                    local_55 = _e1018;
                                    let _e1021 = (_e1016 < 4u);
                                    if _e1021 {
                                        if _e1021 {
                                        } else {
                                            phi_2859_ = true;
                                            break;
                                        }
                                        let _e1023 = local_2[_e1016];
                                        let _e1024 = (select(_e1010, _e1002, ((_e1002 > _e1010) || (_e1010 != _e1010))) - _e1023);
                                        if _e187 {
                                            phi_2291_ = select(0f, 1f, (_e1024 <= _e182));
                                        } else {
                                            let _e1026 = ((_e1024 * _e191) + _e192);
                                            phi_2291_ = select(0f, select(1f, _e1026, (_e1026 < 1f)), (_e1026 > 0f));
                                        }
                                        let _e1034 = phi_2291_;
                                        if _e1021 {
                                        } else {
                                            phi_2859_ = true;
                                            break;
                                        }
                                        let _e1035 = local_2[_e1016];
                                        phi_2251_ = (_e1016 + 1u);
                                        phi_2254_ = (_e1018 + _e1034);
                                        phi_2256_ = (_e1020 + (_e1034 * _e1035));
                                    } else {
                                        phi_2251_ = u32();
                                        phi_2254_ = f32();
                                        phi_2256_ = f32();
                                    }
                                    let _e1041 = phi_2251_;
                                    let _e1043 = phi_2254_;
                                    let _e1045 = phi_2256_;
                                    continue;
                                    continuing {
                                        phi_2250_ = _e1041;
                                        phi_2253_ = _e1043;
                                        phi_2255_ = _e1045;
                                        phi_2859_ = _e940;
                                        break if !(_e1021);
                                    }
                                }
                                let _e1048 = phi_2859_;
                                phi_2880_ = _e1048;
                                if _e1048 {
                                    break;
                                }
                                let _e1050 = local_54;
                                let _e1052 = local_55;
                                if _e943 {
                                } else {
                                    phi_2880_ = true;
                                    break;
                                }
                                local_4[_e942] = (_e1050 / _e1052);
                                if _e943 {
                                } else {
                                    phi_2880_ = true;
                                    break;
                                }
                                let _e1055 = local_3[_e942][0u];
                                let _e1056 = local_3[_e942][1u];
                                if _e943 {
                                } else {
                                    phi_2880_ = true;
                                    break;
                                }
                                let _e1057 = local_4[_e942];
                                if (_e1055 < _e118) {
                                    if (_e1056 < _e122) {
                                        let _e1063 = local_56;
                                        mips.member[(_e1063 + ((_e1056 * _e118) + _e1055))] = _e1057;
                                    }
                                }
                                phi_2881_ = _e1048;
                                phi_2104_ = (_e942 + 1u);
                            } else {
                                phi_2881_ = _e940;
                                phi_2104_ = u32();
                            }
                            let _e1069 = phi_2881_;
                            let _e1071 = phi_2104_;
                            continue;
                            continuing {
                                phi_2875_ = _e1069;
                                phi_2103_ = _e1071;
                                phi_2880_ = _e1069;
                                break if !(_e943);
                            }
                        }
                        let _e1074 = phi_2880_;
                        if _e1074 {
                            break;
                        }
                        let _e1075 = local_4;
                        if _e356 {
                            phi_2374_ = select(f32(), _e1075[0], _e357);
                            phi_2375_ = select(true, false, _e357);
                        } else {
                            phi_2374_ = f32();
                            phi_2375_ = true;
                        }
                        let _e1085 = phi_2374_;
                        let _e1087 = phi_2375_;
                        if _e1087 {
                            if _e356 {
                                phi_2389_ = _e1075[2];
                            } else {
                                phi_2389_ = select(_e1075[3], _e1075[1], _e357);
                            }
                            let _e1090 = phi_2389_;
                            phi_2390_ = _e1090;
                        } else {
                            phi_2390_ = _e1085;
                        }
                        let _e1092 = phi_2390_;
                        local_1 = array<f32, 4>(_e1075[0], select(_e1075[1], _e1075[0], _e356), select(_e1075[2], _e1075[0], _e357), _e1092);
                        let _e1095 = local_1[0u];
                        let _e1097 = local_1[1u];
                        let _e1101 = select(_e1097, _e1095, ((_e1095 > _e1097) || (_e1097 != _e1097)));
                        let _e1103 = local_1[2u];
                        let _e1105 = local_1[3u];
                        let _e1109 = select(_e1105, _e1103, ((_e1103 > _e1105) || (_e1105 != _e1105)));
                        phi_2428_ = 0u;
                        phi_2431_ = 0f;
                        phi_2433_ = 0f;
                        loop {
                            let _e1115 = phi_2428_;
                            let _e1117 = phi_2431_;
                            let _e1119 = phi_2433_;
                            local_57 = _e1119;
                            local_58 = _e1117;
                            let _e1120 = (_e1115 < 4u);
                            if _e1120 {
                                if _e1120 {
                                } else {
                                    phi_2884_ = true;
                                    break;
                                }
                                let _e1122 = local_1[_e1115];
                                let _e1123 = (select(_e1109, _e1101, ((_e1101 > _e1109) || (_e1109 != _e1109))) - _e1122);
                                if _e187 {
                                    phi_2469_ = select(0f, 1f, (_e1123 <= _e182));
                                } else {
                                    let _e1125 = ((_e1123 * _e191) + _e192);
                                    phi_2469_ = select(0f, select(1f, _e1125, (_e1125 < 1f)), (_e1125 > 0f));
                                }
                                let _e1133 = phi_2469_;
                                if _e1120 {
                                } else {
                                    phi_2884_ = true;
                                    break;
                                }
                                let _e1134 = local_1[_e1115];
                                phi_2429_ = (_e1115 + 1u);
                                phi_2432_ = (_e1117 + _e1133);
                                phi_2434_ = (_e1119 + (_e1133 * _e1134));
                            } else {
                                phi_2429_ = u32();
                                phi_2432_ = f32();
                                phi_2434_ = f32();
                            }
                            let _e1140 = phi_2429_;
                            let _e1142 = phi_2432_;
                            let _e1144 = phi_2434_;
                            continue;
                            continuing {
                                phi_2428_ = _e1140;
                                phi_2431_ = _e1142;
                                phi_2433_ = _e1144;
                                phi_2884_ = _e1074;
                                break if !(_e1120);
                            }
                        }
                        let _e1147 = phi_2884_;
                        if _e1147 {
                            break;
                        }
                        let _e1149 = local_57;
                        let _e1151 = local_58;
                        let _e1152 = (_e1149 / _e1151);
                        if _e673 {
                            if (_e682 < _e152) {
                                let _e1157 = local_59;
                                mips.member[(_e1157 + ((_e682 * _e148) + _e440))] = _e1152;
                            }
                        }
                        let _e1162 = (_e56 >> bitcast<u32>(4u));
                        let _e1164 = select(1u, _e1162, (1u < _e1162));
                        let _e1166 = (_e66 >> bitcast<u32>(4u));
                        phi_2512_ = 0u;
                        phi_2515_ = 0u;
                        loop {
                            let _e1170 = phi_2512_;
                            let _e1172 = phi_2515_;
                            local_62 = _e1172;
                            let _e1173 = (_e1170 < 4u);
                            if _e1173 {
                                let _e1174 = (_e1170 & 31u);
                                let _e1176 = (_e56 >> bitcast<u32>(_e1174));
                                let _e1180 = (_e66 >> bitcast<u32>(_e1174));
                                phi_2513_ = (_e1170 + 1u);
                                phi_2516_ = (_e1172 + (select(1u, _e1176, (1u < _e1176)) * select(1u, _e1180, (1u < _e1180))));
                            } else {
                                phi_2513_ = u32();
                                phi_2516_ = u32();
                            }
                            let _e1187 = phi_2513_;
                            let _e1189 = phi_2516_;
                            continue;
                            continuing {
                                phi_2512_ = _e1187;
                                phi_2515_ = _e1189;
                                break if !(_e1173);
                            }
                        }
                        let _e1191 = (_e148 == 1u);
                        let _e1192 = (_e152 == 1u);
                        if _e1191 {
                            phi_2562_ = select(true, false, _e1192);
                        } else {
                            phi_2562_ = true;
                        }
                        let _e1197 = phi_2562_;
                        if _e1197 {
                            if _e1191 {
                                phi_2573_ = _e914;
                            } else {
                                phi_2573_ = select(_e1152, _e672, _e1192);
                            }
                            let _e1200 = phi_2573_;
                            phi_2574_ = _e1200;
                        } else {
                            phi_2574_ = _e430;
                        }
                        let _e1202 = phi_2574_;
                        local = array<f32, 4>(_e430, select(_e672, _e430, _e1191), select(_e914, _e430, _e1192), _e1202);
                        let _e1205 = local[0u];
                        let _e1207 = local[1u];
                        let _e1211 = select(_e1207, _e1205, ((_e1205 > _e1207) || (_e1207 != _e1207)));
                        let _e1213 = local[2u];
                        let _e1215 = local[3u];
                        let _e1219 = select(_e1215, _e1213, ((_e1213 > _e1215) || (_e1215 != _e1215)));
                        phi_2611_ = 0u;
                        phi_2614_ = 0f;
                        phi_2616_ = 0f;
                        loop {
                            let _e1225 = phi_2611_;
                            let _e1227 = phi_2614_;
                            let _e1229 = phi_2616_;
                            local_60 = _e1229;
                            local_61 = _e1227;
                            let _e1230 = (_e1225 < 4u);
                            if _e1230 {
                                if _e1230 {
                                } else {
                                    phi_2901_ = true;
                                    break;
                                }
                                let _e1232 = local[_e1225];
                                let _e1233 = (select(_e1219, _e1211, ((_e1211 > _e1219) || (_e1219 != _e1219))) - _e1232);
                                if _e187 {
                                    phi_2652_ = select(0f, 1f, (_e1233 <= _e182));
                                } else {
                                    let _e1235 = ((_e1233 * _e191) + _e192);
                                    phi_2652_ = select(0f, select(1f, _e1235, (_e1235 < 1f)), (_e1235 > 0f));
                                }
                                let _e1243 = phi_2652_;
                                if _e1230 {
                                } else {
                                    phi_2901_ = true;
                                    break;
                                }
                                let _e1244 = local[_e1225];
                                phi_2612_ = (_e1225 + 1u);
                                phi_2615_ = (_e1227 + _e1243);
                                phi_2617_ = (_e1229 + (_e1243 * _e1244));
                            } else {
                                phi_2612_ = u32();
                                phi_2615_ = f32();
                                phi_2617_ = f32();
                            }
                            let _e1250 = phi_2612_;
                            let _e1252 = phi_2615_;
                            let _e1254 = phi_2617_;
                            continue;
                            continuing {
                                phi_2611_ = _e1250;
                                phi_2614_ = _e1252;
                                phi_2616_ = _e1254;
                                phi_2901_ = _e1147;
                                break if !(_e1230);
                            }
                        }
                        let _e1257 = phi_2901_;
                        if _e1257 {
                            break;
                        }
                        let _e1259 = local_60;
                        let _e1261 = local_61;
                        if (_e44.x < _e1164) {
                            if (_e44.y < select(1u, _e1166, (1u < _e1166))) {
                                let _e1268 = local_62;
                                mips.member[(_e1268 + ((_e44.y * _e1164) + _e44.x))] = (_e1259 / _e1261);
                            }
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
fn gtao_prefilter(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
