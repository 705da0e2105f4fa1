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
    var phi_1633_: bool;
    var phi_1648_: bool;
    var phi_1663_: bool;
    var phi_1678_: bool;
    var phi_1709_: f32;
    var phi_1713_: f32;
    var phi_1714_: bool;
    var phi_1736_: u32;
    var phi_1763_: f32;
    var phi_1767_: f32;
    var phi_1768_: bool;
    var phi_1790_: u32;
    var phi_1817_: f32;
    var phi_1821_: f32;
    var phi_1822_: bool;
    var phi_1844_: u32;
    var phi_1871_: f32;
    var phi_1875_: f32;
    var phi_1876_: bool;
    var phi_1898_: u32;
    var phi_1909_: bool;
    var phi_1924_: bool;
    var phi_782_: vec2<f32>;
    var phi_813_: vec3<f32>;
    var phi_819_: u32;
    var phi_822_: u32;
    var phi_824_: u32;
    var phi_826_: u32;
    var phi_855_: u32;
    var phi_856_: u32;
    var phi_857_: u32;
    var phi_858_: u32;
    var phi_820_: u32;
    var phi_823_: u32;
    var phi_825_: u32;
    var phi_827_: u32;
    var local: u32;
    var phi_889_: type_28;
    var phi_924_: u32;
    var phi_927_: f32;
    var phi_1939_: bool;
    var phi_1073_: u32;
    var phi_1076_: f32;
    var phi_1078_: bool;
    var phi_1080_: bool;
    var phi_1082_: f32;
    var phi_1084_: f32;
    var phi_1188_: u32;
    var phi_1209_: u32;
    var phi_1298_: u32;
    var phi_1329_: u32;
    var phi_2022_: bool;
    var phi_2037_: bool;
    var phi_1998_: vec2<f32>;
    var phi_1464_: u32;
    var phi_1466_: u32;
    var phi_1467_: f32;
    var phi_1468_: bool;
    var phi_1469_: bool;
    var phi_1470_: f32;
    var phi_1473_: bool;
    var phi_1474_: bool;
    var phi_1074_: u32;
    var phi_1077_: f32;
    var phi_1079_: bool;
    var phi_1081_: bool;
    var phi_1083_: f32;
    var phi_1085_: f32;
    var phi_1478_: bool;
    var phi_1480_: bool;
    var phi_1481_: bool;
    var local_1: bool;
    var local_2: bool;
    var local_3: bool;
    var local_4: bool;
    var local_5: f32;
    var local_6: f32;
    var local_7: bool;
    var local_8: bool;
    var local_9: f32;
    var local_10: bool;
    var phi_1521_: f32;
    var phi_925_: u32;
    var phi_928_: f32;
    var phi_2051_: bool;
    var local_11: f32;
    var phi_1592_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e57 = id_1;
            let _e59 = arrayLength((&kernel.member));
            let _e70 = params.member.member.member[0u];
            let _e75 = select(select(u32(_e70), 0u, (_e70 < 0f)), 4294967295u, (_e70 > 4294967000f));
            let _e80 = params.member.member.member[1u];
            let _e85 = select(select(u32(_e80), 0u, (_e80 < 0f)), 4294967295u, (_e80 > 4294967000f));
            if (_e57.x >= _e75) {
            } else {
                if (_e57.y >= _e85) {
                } else {
                    let _e91 = ((_e57.y * _e75) + _e57.x);
                    let _e94 = depth.member[_e91];
                    let _e98 = params.member.member.member_3;
                    let _e101 = select(false, (_e94 < _e98), (_e94 > 0f));
                    let _e102 = select(_e98, _e94, _e101);
                    let _e103 = bitcast<i32>(_e57.x);
                    let _e104 = (_e103 + -1i);
                    let _e106 = select(0i, _e104, (0i < _e104));
                    let _e108 = (bitcast<i32>(_e75) - 1i);
                    let _e112 = bitcast<i32>(_e57.y);
                    let _e114 = select(0i, _e112, (0i < _e112));
                    let _e116 = (bitcast<i32>(_e85) - 1i);
                    let _e120 = (bitcast<u32>(select(_e114, _e116, (_e116 < _e114))) * _e75);
                    let _e124 = depth.member[(_e120 + bitcast<u32>(select(_e106, _e108, (_e108 < _e106))))];
                    let _e129 = (_e103 + 1i);
                    let _e131 = select(0i, _e129, (0i < _e129));
                    let _e138 = depth.member[(_e120 + bitcast<u32>(select(_e131, _e108, (_e108 < _e131))))];
                    let _e144 = select(0i, _e103, (0i < _e103));
                    let _e147 = bitcast<u32>(select(_e144, _e108, (_e108 < _e144)));
                    let _e148 = (_e112 + -1i);
                    let _e150 = select(0i, _e148, (0i < _e148));
                    let _e158 = depth.member[((bitcast<u32>(select(_e150, _e116, (_e116 < _e150))) * _e75) + _e147)];
                    let _e163 = (_e112 + 1i);
                    let _e165 = select(0i, _e163, (0i < _e163));
                    let _e173 = depth.member[((bitcast<u32>(select(_e165, _e116, (_e116 < _e165))) * _e75) + _e147)];
                    let _e178 = (select(_e98, _e124, select(false, (_e124 < _e98), (_e124 > 0f))) - _e102);
                    let _e179 = (select(_e98, _e138, select(false, (_e138 < _e98), (_e138 > 0f))) - _e102);
                    let _e180 = (select(_e98, _e158, select(false, (_e158 < _e98), (_e158 > 0f))) - _e102);
                    let _e181 = (select(_e98, _e173, select(false, (_e173 < _e98), (_e173 > 0f))) - _e102);
                    let _e183 = ((_e179 - _e178) * 0.5f);
                    let _e185 = ((_e181 - _e180) * 0.5f);
                    let _e186 = (_e102 * 0.011f);
                    let _e188 = abs(_e178);
                    let _e189 = abs((_e178 + _e183));
                    if (_e188 != _e188) {
                        phi_1633_ = true;
                    } else {
                        phi_1633_ = (_e189 <= _e188);
                    }
                    let _e193 = phi_1633_;
                    let _e196 = (1.25f - (select(_e188, _e189, _e193) / _e186));
                    let _e200 = select(0f, select(1f, _e196, (_e196 < 1f)), (_e196 > 0f));
                    let _e202 = abs(_e179);
                    let _e203 = abs((_e179 - _e183));
                    if (_e202 != _e202) {
                        phi_1648_ = true;
                    } else {
                        phi_1648_ = (_e203 <= _e202);
                    }
                    let _e207 = phi_1648_;
                    let _e210 = (1.25f - (select(_e202, _e203, _e207) / _e186));
                    let _e214 = select(0f, select(1f, _e210, (_e210 < 1f)), (_e210 > 0f));
                    let _e216 = abs(_e180);
                    let _e217 = abs((_e180 + _e185));
                    if (_e216 != _e216) {
                        phi_1663_ = true;
                    } else {
                        phi_1663_ = (_e217 <= _e216);
                    }
                    let _e221 = phi_1663_;
                    let _e224 = (1.25f - (select(_e216, _e217, _e221) / _e186));
                    let _e228 = select(0f, select(1f, _e224, (_e224 < 1f)), (_e224 > 0f));
                    let _e230 = abs(_e181);
                    let _e231 = abs((_e181 - _e185));
                    if (_e230 != _e230) {
                        phi_1678_ = true;
                    } else {
                        phi_1678_ = (_e231 <= _e230);
                    }
                    let _e235 = phi_1678_;
                    let _e238 = (1.25f - (select(_e230, _e231, _e235) / _e186));
                    let _e242 = select(0f, select(1f, _e238, (_e238 < 1f)), (_e238 > 0f));
                    let _e247 = (select(0f, select(1f, _e200, (_e200 < 1f)), (_e200 > 0f)) * 2.9f);
                    let _e249 = floor((_e247 + 0.5f));
                    if ((_e249 - _e247) == 0.5f) {
                        let _e255 = ((floor((_e249 * 0.5f)) * 2f) != _e249);
                        if _e255 {
                            phi_1709_ = (_e249 - 1f);
                        } else {
                            phi_1709_ = f32();
                        }
                        let _e258 = phi_1709_;
                        phi_1713_ = _e258;
                        phi_1714_ = select(true, false, _e255);
                    } else {
                        phi_1713_ = f32();
                        phi_1714_ = true;
                    }
                    let _e261 = phi_1713_;
                    let _e263 = phi_1714_;
                    let _e264 = select(_e261, _e249, _e263);
                    if (_e264 > 0f) {
                        let _e270 = select(select(u32(_e264), 0u, (_e264 < 0f)), 4294967295u, (_e264 > 4294967000f));
                        phi_1736_ = select(_e270, 3u, (3u < _e270));
                    } else {
                        phi_1736_ = 0u;
                    }
                    let _e274 = phi_1736_;
                    let _e280 = (select(0f, select(1f, _e214, (_e214 < 1f)), (_e214 > 0f)) * 2.9f);
                    let _e282 = floor((_e280 + 0.5f));
                    if ((_e282 - _e280) == 0.5f) {
                        let _e288 = ((floor((_e282 * 0.5f)) * 2f) != _e282);
                        if _e288 {
                            phi_1763_ = (_e282 - 1f);
                        } else {
                            phi_1763_ = f32();
                        }
                        let _e291 = phi_1763_;
                        phi_1767_ = _e291;
                        phi_1768_ = select(true, false, _e288);
                    } else {
                        phi_1767_ = f32();
                        phi_1768_ = true;
                    }
                    let _e294 = phi_1767_;
                    let _e296 = phi_1768_;
                    let _e297 = select(_e294, _e282, _e296);
                    if (_e297 > 0f) {
                        let _e303 = select(select(u32(_e297), 0u, (_e297 < 0f)), 4294967295u, (_e297 > 4294967000f));
                        phi_1790_ = select(_e303, 3u, (3u < _e303));
                    } else {
                        phi_1790_ = 0u;
                    }
                    let _e307 = phi_1790_;
                    let _e314 = (select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f)) * 2.9f);
                    let _e316 = floor((_e314 + 0.5f));
                    if ((_e316 - _e314) == 0.5f) {
                        let _e322 = ((floor((_e316 * 0.5f)) * 2f) != _e316);
                        if _e322 {
                            phi_1817_ = (_e316 - 1f);
                        } else {
                            phi_1817_ = f32();
                        }
                        let _e325 = phi_1817_;
                        phi_1821_ = _e325;
                        phi_1822_ = select(true, false, _e322);
                    } else {
                        phi_1821_ = f32();
                        phi_1822_ = true;
                    }
                    let _e328 = phi_1821_;
                    let _e330 = phi_1822_;
                    let _e331 = select(_e328, _e316, _e330);
                    if (_e331 > 0f) {
                        let _e337 = select(select(u32(_e331), 0u, (_e331 < 0f)), 4294967295u, (_e331 > 4294967000f));
                        phi_1844_ = select(_e337, 3u, (3u < _e337));
                    } else {
                        phi_1844_ = 0u;
                    }
                    let _e341 = phi_1844_;
                    let _e348 = (select(0f, select(1f, _e242, (_e242 < 1f)), (_e242 > 0f)) * 2.9f);
                    let _e350 = floor((_e348 + 0.5f));
                    if ((_e350 - _e348) == 0.5f) {
                        let _e356 = ((floor((_e350 * 0.5f)) * 2f) != _e350);
                        if _e356 {
                            phi_1871_ = (_e350 - 1f);
                        } else {
                            phi_1871_ = f32();
                        }
                        let _e359 = phi_1871_;
                        phi_1875_ = _e359;
                        phi_1876_ = select(true, false, _e356);
                    } else {
                        phi_1875_ = f32();
                        phi_1876_ = true;
                    }
                    let _e362 = phi_1875_;
                    let _e364 = phi_1876_;
                    let _e365 = select(_e362, _e350, _e364);
                    if (_e365 > 0f) {
                        let _e371 = select(select(u32(_e365), 0u, (_e365 < 0f)), 4294967295u, (_e365 > 4294967000f));
                        phi_1898_ = select(_e371, 3u, (3u < _e371));
                    } else {
                        phi_1898_ = 0u;
                    }
                    let _e375 = phi_1898_;
                    let _e376 = ((((64u * _e274) + (16u * _e307)) + (4u * _e341)) + _e375);
                    if _e101 {
                        let _e389 = params.member.member.member_1[0u];
                        let _e391 = ((((((f32(_e57.x) + 0.5f) / _e70) * 2f) - 1f) * _e389) * _e94);
                        let _e398 = params.member.member.member_1[1u];
                        let _e400 = ((((((f32(_e57.y) + 0.5f) / _e80) * -2f) + 1f) * _e398) * _e94);
                        let _e404 = normals.member[_e91];
                        let _e412 = (f32((bitcast<i32>(((_e404 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e412 != _e412) {
                            phi_1909_ = true;
                        } else {
                            phi_1909_ = (-1f >= _e412);
                        }
                        let _e416 = phi_1909_;
                        let _e417 = select(_e412, -1f, _e416);
                        let _e427 = (f32((bitcast<i32>((((_e404 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e427 != _e427) {
                            phi_1924_ = true;
                        } else {
                            phi_1924_ = (-1f >= _e427);
                        }
                        let _e431 = phi_1924_;
                        let _e432 = select(_e427, -1f, _e431);
                        let _e435 = (1f - abs(_e417));
                        let _e436 = abs(_e432);
                        let _e437 = (_e435 - _e436);
                        if (_e437 < 0f) {
                            phi_782_ = vec2<f32>(((1f - _e436) * select(1f, -1f, (_e417 < 0f))), (_e435 * select(1f, -1f, (_e432 < 0f))));
                        } else {
                            phi_782_ = vec2<f32>(_e417, _e432);
                        }
                        let _e448 = phi_782_;
                        let _e457 = (1f / sqrt((((_e448.x * _e448.x) + (_e448.y * _e448.y)) + (_e437 * _e437))));
                        let _e458 = (_e448.x * _e457);
                        let _e459 = (_e448.y * _e457);
                        let _e460 = (_e437 * _e457);
                        let _e461 = -(_e460);
                        if ((((_e458 * -(_e391)) + (_e459 * -(_e400))) + (_e461 * -(_e94))) < 0f) {
                            phi_813_ = vec3<f32>(-(_e458), -(_e459), _e460);
                        } else {
                            phi_813_ = vec3<f32>(_e458, _e459, _e461);
                        }
                        let _e476 = phi_813_;
                        let _e479 = params.member.member_8;
                        phi_819_ = (_e57.y & 63u);
                        phi_822_ = (_e57.x & 63u);
                        phi_824_ = 32u;
                        phi_826_ = 0u;
                        loop {
                            let _e483 = phi_819_;
                            let _e485 = phi_822_;
                            let _e487 = phi_824_;
                            let _e489 = phi_826_;
                            local = _e489;
                            let _e490 = (_e487 > 0u);
                            if _e490 {
                                let _e493 = select(0u, 1u, ((_e485 & _e487) != 0u));
                                let _e496 = select(0u, 1u, ((_e483 & _e487) != 0u));
                                if (_e496 == 0u) {
                                    if (_e493 == 1u) {
                                        phi_855_ = (63u - _e483);
                                        phi_856_ = (63u - _e485);
                                    } else {
                                        phi_855_ = _e483;
                                        phi_856_ = _e485;
                                    }
                                    let _e507 = phi_855_;
                                    let _e509 = phi_856_;
                                    phi_857_ = _e509;
                                    phi_858_ = _e507;
                                } else {
                                    phi_857_ = _e483;
                                    phi_858_ = _e485;
                                }
                                let _e511 = phi_857_;
                                let _e513 = phi_858_;
                                phi_820_ = _e511;
                                phi_823_ = _e513;
                                phi_825_ = (_e487 / 2u);
                                phi_827_ = (_e489 + ((_e487 * _e487) * ((3u * _e493) ^ _e496)));
                            } else {
                                phi_820_ = u32();
                                phi_823_ = u32();
                                phi_825_ = u32();
                                phi_827_ = u32();
                            }
                            let _e516 = phi_820_;
                            let _e518 = phi_823_;
                            let _e520 = phi_825_;
                            let _e522 = phi_827_;
                            continue;
                            continuing {
                                phi_819_ = _e516;
                                phi_822_ = _e518;
                                phi_824_ = _e520;
                                phi_826_ = _e522;
                                break if !(_e490);
                            }
                        }
                        let _e527 = local;
                        let _e529 = f32((_e527 + (288u * (_e479 % 64u))));
                        let _e531 = (0.5f + (_e529 * 0.7548777f));
                        let _e535 = (0.5f + (_e529 * 0.5698403f));
                        let _e538 = (6.2831855f * (_e531 - floor(_e531)));
                        phi_889_ = type_28(_e376, type_27(1u, type_26(vec2<u32>(_e57.x, _e57.y), vec3<f32>(_e391, _e400, _e94), _e476, sin(_e538), cos(_e538), (_e535 - floor(_e535)))));
                    } else {
                        phi_889_ = type_28(_e376, type_27(0u, type_27().member_1));
                    }
                    let _e550 = phi_889_;
                    if (bitcast<i32>(_e550.member_1.member) != 0i) {
                        let _e559 = params.member.member_5;
                        let _e561 = select(_e559, 64u, (64u < _e559));
                        let _e563 = select(_e561, _e59, (_e59 < _e561));
                        let _e565 = select(1u, _e563, (1u < _e563));
                        let _e568 = params.member.member_6;
                        let _e570 = select(1u, _e568, (1u < _e568));
                        phi_924_ = 0u;
                        phi_927_ = 0f;
                        loop {
                            let _e572 = phi_924_;
                            let _e574 = phi_927_;
                            local_11 = _e574;
                            let _e575 = (_e572 < _e565);
                            if _e575 {
                                if (_e572 < _e59) {
                                } else {
                                    phi_2051_ = true;
                                    break;
                                }
                                let _e580 = kernel.member[_e572][0u];
                                let _e584 = kernel.member[_e572][1u];
                                let _e589 = ((_e550.member_1.member_1.member_4 * _e580) - (_e550.member_1.member_1.member_3 * _e584));
                                let _e592 = ((_e550.member_1.member_1.member_3 * _e580) + (_e550.member_1.member_1.member_4 * _e584));
                                let _e597 = ((1f - (_e589 * _e589)) - (_e592 * _e592));
                                if (_e597 != _e597) {
                                    phi_1939_ = true;
                                } else {
                                    phi_1939_ = (0f >= _e597);
                                }
                                let _e601 = phi_1939_;
                                let _e603 = sqrt(select(_e597, 0f, _e601));
                                let _e604 = -(_e603);
                                let _e608 = (-1f * _e550.member_1.member_1.member_2.z);
                                let _e609 = (-1f * _e550.member_1.member_1.member_2.x);
                                let _e611 = (1f / (_e608 + 1f));
                                let _e612 = (_e611 * _e550.member_1.member_1.member_2.y);
                                let _e616 = (_e612 * _e609);
                                let _e636 = (_e608 > 0.9997f);
                                let _e637 = (_e608 < -0.9997f);
                                let _e647 = params.member.member_1;
                                let _e651 = params.member.member_3;
                                let _e654 = params.member.member_4;
                                phi_1073_ = 1u;
                                phi_1076_ = _e647;
                                phi_1078_ = false;
                                phi_1080_ = true;
                                phi_1082_ = 0f;
                                phi_1084_ = 0f;
                                loop {
                                    let _e660 = phi_1073_;
                                    let _e662 = phi_1076_;
                                    let _e664 = phi_1078_;
                                    let _e666 = phi_1080_;
                                    let _e668 = phi_1082_;
                                    let _e670 = phi_1084_;
                                    local_5 = _e662;
                                    local_7 = _e664;
                                    local_9 = _e662;
                                    local_10 = _e664;
                                    let _e671 = (_e660 <= _e570);
                                    if _e671 {
                                        let _e677 = (((-(_e550.member_1.member_1.member_5) + f32(_e660)) * _e647) / f32(_e570));
                                        let _e682 = (_e550.member_1.member_1.member_1.x + (select(select(((((_e608 + (_e612 * _e550.member_1.member_1.member_2.y)) * _e589) + (_e616 * _e592)) + (_e609 * _e604)), _e589, _e637), _e589, _e636) * _e677));
                                        let _e684 = (_e550.member_1.member_1.member_1.y + (select(select((((_e616 * _e589) + ((_e608 + ((_e611 * _e609) * _e609)) * _e592)) + (-(_e550.member_1.member_1.member_2.y) * _e604)), -(_e592), _e637), _e592, _e636) * _e677));
                                        let _e686 = (_e550.member_1.member_1.member_1.z + (select(select((((_e550.member_1.member_1.member_2.x * _e589) + (_e550.member_1.member_1.member_2.y * _e592)) + (_e608 * _e604)), _e603, _e637), _e604, _e636) * _e677));
                                        let _e692 = params.member.member.member_1[0u];
                                        let _e695 = (((_e682 * 0.5f) / (_e686 * _e692)) + 0.5f);
                                        let _e701 = params.member.member.member_1[1u];
                                        let _e704 = (0.5f - ((_e684 * 0.5f) / (_e686 * _e701)));
                                        let _e714 = select(false, select(false, select(false, select(false, (_e704 <= 1f), (_e704 >= 0f)), select(false, (_e695 <= 1f), (_e695 >= 0f))), (_e686 > 0f)), _e666);
                                        if _e714 {
                                            let _e715 = (_e695 * _e70);
                                            if (_e715 > 0f) {
                                                let _e721 = select(select(u32(_e715), 0u, (_e715 < 0f)), 4294967295u, (_e715 > 4294967000f));
                                                let _e722 = (_e75 - 1u);
                                                phi_1188_ = select(_e721, _e722, (_e722 < _e721));
                                            } else {
                                                phi_1188_ = 0u;
                                            }
                                            let _e726 = phi_1188_;
                                            let _e727 = (_e704 * _e80);
                                            if (_e727 > 0f) {
                                                let _e733 = select(select(u32(_e727), 0u, (_e727 < 0f)), 4294967295u, (_e727 > 4294967000f));
                                                let _e734 = (_e85 - 1u);
                                                phi_1209_ = select(_e733, _e734, (_e734 < _e733));
                                            } else {
                                                phi_1209_ = 0u;
                                            }
                                            let _e738 = phi_1209_;
                                            let _e743 = depth.member[((_e738 * _e75) + _e726)];
                                            let _e747 = select(_e98, _e743, select(false, (_e743 < _e98), (_e743 > 0f)));
                                            let _e750 = (((_e695 * 2f) - 1f) * _e692);
                                            let _e754 = (((_e704 * -2f) + 1f) * _e701);
                                            let _e756 = (_e682 - (_e750 * _e747));
                                            let _e757 = (_e684 - (_e754 * _e747));
                                            let _e758 = (_e686 - _e747);
                                            let _e764 = sqrt((((_e756 * _e756) + (_e757 * _e757)) + (_e758 * _e758)));
                                            let _e769 = (select(0f, select(1f, _e695, (_e695 < 1f)), (_e695 > 0f)) * _e70);
                                            if (_e769 > 0f) {
                                                let _e775 = select(select(u32(_e769), 0u, (_e769 < 0f)), 4294967295u, (_e769 > 4294967000f));
                                                let _e776 = (_e75 - 1u);
                                                phi_1298_ = select(_e775, _e776, (_e776 < _e775));
                                            } else {
                                                phi_1298_ = 0u;
                                            }
                                            let _e780 = phi_1298_;
                                            let _e785 = (select(0f, select(1f, _e704, (_e704 < 1f)), (_e704 > 0f)) * _e80);
                                            if (_e785 > 0f) {
                                                let _e791 = select(select(u32(_e785), 0u, (_e785 < 0f)), 4294967295u, (_e785 > 4294967000f));
                                                let _e792 = (_e85 - 1u);
                                                phi_1329_ = select(_e791, _e792, (_e792 < _e791));
                                            } else {
                                                phi_1329_ = 0u;
                                            }
                                            let _e796 = phi_1329_;
                                            let _e817 = normals.member[((_e796 * _e75) + _e780)];
                                            let _e825 = (f32((bitcast<i32>(((_e817 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e825 != _e825) {
                                                phi_2022_ = true;
                                            } else {
                                                phi_2022_ = (-1f >= _e825);
                                            }
                                            let _e829 = phi_2022_;
                                            let _e830 = select(_e825, -1f, _e829);
                                            let _e840 = (f32((bitcast<i32>((((_e817 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e840 != _e840) {
                                                phi_2037_ = true;
                                            } else {
                                                phi_2037_ = (-1f >= _e840);
                                            }
                                            let _e844 = phi_2037_;
                                            let _e845 = select(_e840, -1f, _e844);
                                            let _e848 = (1f - abs(_e830));
                                            let _e849 = abs(_e845);
                                            let _e850 = (_e848 - _e849);
                                            if (_e850 < 0f) {
                                                phi_1998_ = vec2<f32>(((1f - _e849) * select(1f, -1f, (_e830 < 0f))), (_e848 * select(1f, -1f, (_e845 < 0f))));
                                            } else {
                                                phi_1998_ = vec2<f32>(_e830, _e845);
                                            }
                                            let _e861 = phi_1998_;
                                            let _e870 = (1f / sqrt((((_e861.x * _e861.x) + (_e861.y * _e861.y)) + (_e850 * _e850))));
                                            let _e871 = (_e861.x * _e870);
                                            let _e872 = (_e861.y * _e870);
                                            let _e874 = -((_e850 * _e870));
                                            let _e878 = (((_e871 * _e750) + (_e872 * _e754)) + _e874);
                                            let _e887 = select(((((_e871 * ((((((f32(_e780) + 0.5f) * (1f / _e70)) * 2f) - 1f) * _e692) * _e747)) + (_e872 * ((((((f32(_e796) + 0.5f) * (1f / _e80)) * -2f) + 1f) * _e701) * _e747))) + (_e874 * _e747)) / _e878), _e747, (abs(_e878) < 0.001f));
                                            let _e897 = select(select(((_e686 - _e887) > _e654), true, (_e686 < (_e887 * (1f + _e651)))), true, select(false, (_e796 == _e550.member_1.member_1.member.y), (_e780 == _e550.member_1.member_1.member.x)));
                                            let _e899 = select(false, !(_e897), _e714);
                                            let _e900 = (_e668 + _e764);
                                            let _e909 = select(false, _e897, _e714);
                                            if _e909 {
                                                phi_1464_ = (_e660 + 1u);
                                            } else {
                                                phi_1464_ = u32();
                                            }
                                            let _e912 = phi_1464_;
                                            phi_1466_ = _e912;
                                            phi_1467_ = select(_e662, select((_e670 + ((_e668 * (_e677 - _e670)) / _e900)), _e670, (_e900 < 0.000001f)), _e899);
                                            phi_1468_ = select(_e899, true, _e664);
                                            phi_1469_ = _e909;
                                            phi_1470_ = _e764;
                                            phi_1473_ = _e909;
                                            phi_1474_ = select(true, false, _e909);
                                        } else {
                                            phi_1466_ = u32();
                                            phi_1467_ = f32();
                                            phi_1468_ = bool();
                                            phi_1469_ = bool();
                                            phi_1470_ = f32();
                                            phi_1473_ = false;
                                            phi_1474_ = false;
                                        }
                                        let _e915 = phi_1466_;
                                        let _e917 = phi_1467_;
                                        let _e919 = phi_1468_;
                                        let _e921 = phi_1469_;
                                        let _e923 = phi_1470_;
                                        let _e925 = phi_1473_;
                                        let _e927 = phi_1474_;
                                        phi_1074_ = _e915;
                                        phi_1077_ = _e917;
                                        phi_1079_ = _e919;
                                        phi_1081_ = _e921;
                                        phi_1083_ = _e923;
                                        phi_1085_ = _e677;
                                        phi_1478_ = _e925;
                                        phi_1480_ = _e927;
                                        phi_1481_ = select(true, false, _e714);
                                    } else {
                                        phi_1074_ = u32();
                                        phi_1077_ = f32();
                                        phi_1079_ = bool();
                                        phi_1081_ = bool();
                                        phi_1083_ = f32();
                                        phi_1085_ = f32();
                                        phi_1478_ = false;
                                        phi_1480_ = false;
                                        phi_1481_ = false;
                                    }
                                    let _e930 = phi_1074_;
                                    let _e932 = phi_1077_;
                                    let _e934 = phi_1079_;
                                    let _e936 = phi_1081_;
                                    let _e938 = phi_1083_;
                                    let _e940 = phi_1085_;
                                    let _e942 = phi_1478_;
                                    let _e944 = phi_1480_;
                                    let _e946 = phi_1481_;
                                    let _e947 = select(true, false, _e671);
                                    local_1 = _e947;
                                    local_2 = _e944;
                                    local_3 = _e947;
                                    local_4 = _e946;
                                    local_6 = _e932;
                                    local_8 = _e934;
                                    continue;
                                    continuing {
                                        phi_1073_ = _e930;
                                        phi_1076_ = _e932;
                                        phi_1078_ = _e934;
                                        phi_1080_ = _e936;
                                        phi_1082_ = _e938;
                                        phi_1084_ = _e940;
                                        break if !(_e942);
                                    }
                                }
                                let _e950 = local_1;
                                let _e952 = local_2;
                                let _e953 = select(_e952, false, _e950);
                                let _e955 = local_3;
                                let _e957 = local_4;
                                let _e959 = select(select(_e957, false, _e955), false, _e953);
                                let _e961 = local_5;
                                let _e963 = local_6;
                                let _e966 = local_7;
                                let _e968 = local_8;
                                let _e970 = select(_e953, true, _e959);
                                let _e972 = local_9;
                                let _e975 = local_10;
                                let _e979 = params.member.member_7;
                                if (_e979 == 1u) {
                                    phi_1521_ = 0f;
                                } else {
                                    let _e981 = (select(_e972, select(_e963, _e961, _e959), _e970) / _e647);
                                    phi_1521_ = select(0f, select(1f, _e981, (_e981 < 1f)), (_e981 > 0f));
                                }
                                let _e987 = phi_1521_;
                                phi_925_ = (_e572 + 1u);
                                phi_928_ = (_e574 + select(1f, _e987, select(_e975, select(_e968, _e966, _e959), _e970)));
                            } else {
                                phi_925_ = u32();
                                phi_928_ = f32();
                            }
                            let _e992 = phi_925_;
                            let _e994 = phi_928_;
                            continue;
                            continuing {
                                phi_924_ = _e992;
                                phi_927_ = _e994;
                                phi_2051_ = false;
                                break if !(_e575);
                            }
                        }
                        let _e997 = phi_2051_;
                        if _e997 {
                            break;
                        }
                        let _e1000 = local_11;
                        let _e1004 = params.member.member_2;
                        let _e1005 = pow((_e1000 / f32(_e565)), _e1004);
                        let _e1006 = (_e1005 * 0.6666667f);
                        let _e1012 = ((select(0f, select(1f, _e1006, (_e1006 < 1f)), (_e1006 > 0f)) * 255f) + 0.5f);
                        phi_1592_ = type_29(_e1005, select(select(u32(_e1012), 0u, (_e1012 < 0f)), 4294967295u, (_e1012 > 4294967000f)), _e550.member);
                    } else {
                        phi_1592_ = type_29(1f, 170u, _e550.member);
                    }
                    let _e1021 = phi_1592_;
                    if (_e91 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e91] = _e1021.member;
                    if (_e91 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e91] = _e1021.member_1;
                    if (_e91 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e91] = _e1021.member_2;
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
