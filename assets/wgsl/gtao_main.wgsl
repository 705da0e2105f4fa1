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
    var phi_215_: i32;
    var phi_234_: i32;
    var phi_274_: i32;
    var phi_293_: i32;
    var phi_333_: i32;
    var phi_352_: i32;
    var phi_392_: i32;
    var phi_411_: i32;
    var phi_491_: f32;
    var phi_502_: f32;
    var phi_513_: f32;
    var phi_524_: f32;
    var phi_1570_: f32;
    var phi_1585_: f32;
    var phi_1589_: f32;
    var phi_1590_: bool;
    var phi_1613_: f32;
    var phi_1628_: f32;
    var phi_1632_: f32;
    var phi_1633_: bool;
    var phi_1656_: f32;
    var phi_1671_: f32;
    var phi_1675_: f32;
    var phi_1676_: bool;
    var phi_1699_: f32;
    var phi_1714_: f32;
    var phi_1718_: f32;
    var phi_1719_: bool;
    var phi_542_: bool;
    var phi_1742_: bool;
    var phi_1757_: bool;
    var phi_636_: vec2<f32>;
    var phi_664_: vec3<f32>;
    var phi_693_: f32;
    var phi_701_: u32;
    var phi_704_: u32;
    var phi_706_: u32;
    var phi_708_: u32;
    var phi_737_: u32;
    var phi_738_: u32;
    var phi_739_: u32;
    var phi_740_: u32;
    var phi_702_: u32;
    var phi_705_: u32;
    var phi_707_: u32;
    var phi_709_: u32;
    var local: u32;
    var phi_1856_: bool;
    var phi_764_: u32;
    var phi_767_: f32;
    var phi_890_: f32;
    var phi_906_: f32;
    var phi_923_: f32;
    var phi_930_: u32;
    var phi_933_: f32;
    var phi_935_: f32;
    var phi_977_: f32;
    var phi_998_: u32;
    var phi_1014_: f32;
    var phi_1016_: f32;
    var phi_1017_: bool;
    var phi_1037_: f32;
    var phi_1039_: f32;
    var phi_1040_: bool;
    var phi_1089_: u32;
    var phi_1110_: u32;
    var phi_1112_: u32;
    var phi_1115_: u32;
    var phi_1113_: u32;
    var phi_1116_: u32;
    var local_1: u32;
    var phi_1199_: u32;
    var phi_1220_: u32;
    var phi_1222_: u32;
    var phi_1225_: u32;
    var phi_1223_: u32;
    var phi_1226_: u32;
    var local_2: u32;
    var phi_1317_: f32;
    var phi_1323_: f32;
    var phi_1369_: f32;
    var phi_1375_: f32;
    var phi_1772_: bool;
    var phi_1787_: bool;
    var phi_931_: u32;
    var phi_934_: f32;
    var phi_936_: f32;
    var phi_1807_: bool;
    var local_3: f32;
    var local_4: f32;
    var phi_1401_: f32;
    var local_5: f32;
    var local_6: f32;
    var phi_1419_: f32;
    var phi_1925_: bool;
    var phi_765_: u32;
    var phi_768_: f32;
    var phi_1924_: bool;
    var local_7: f32;
    var phi_1802_: bool;
    var phi_1458_: f32;
    var phi_1490_: type_22;

    switch bitcast<i32>(0u) {
        default: {
            let _e69 = id_1;
            let _e71 = arrayLength((&mips.member));
            let _e82 = params.member.member.member[0u];
            let _e87 = select(select(u32(_e82), 0u, (_e82 < 0f)), 4294967295u, (_e82 > 4294967000f));
            let _e92 = params.member.member.member[1u];
            let _e97 = select(select(u32(_e92), 0u, (_e92 < 0f)), 4294967295u, (_e92 > 4294967000f));
            if (_e69.x >= _e87) {
            } else {
                if (_e69.y >= _e97) {
                } else {
                    let _e103 = ((_e69.y * _e87) + _e69.x);
                    if (_e103 < _e71) {
                    } else {
                        break;
                    }
                    let _e107 = mips.member[_e103];
                    let _e108 = bitcast<i32>(_e69.x);
                    let _e109 = (_e108 + -1i);
                    let _e111 = (bitcast<i32>(_e87) - 1i);
                    let _e112 = (0i <= _e111);
                    if _e112 {
                    } else {
                        break;
                    }
                    if (_e109 < 0i) {
                        phi_215_ = 0i;
                    } else {
                        phi_215_ = select(_e109, _e111, (_e109 > _e111));
                    }
                    let _e117 = phi_215_;
                    let _e119 = bitcast<i32>(_e69.y);
                    let _e121 = (bitcast<i32>(_e97) - 1i);
                    let _e122 = (0i <= _e121);
                    if _e122 {
                    } else {
                        break;
                    }
                    let _e123 = (_e119 < 0i);
                    if _e123 {
                        phi_234_ = 0i;
                    } else {
                        phi_234_ = select(_e119, _e121, (_e119 > _e121));
                    }
                    let _e127 = phi_234_;
                    let _e130 = ((bitcast<u32>(_e127) * _e87) + bitcast<u32>(_e117));
                    if (_e130 < _e71) {
                    } else {
                        break;
                    }
                    let _e134 = mips.member[_e130];
                    let _e135 = (_e108 + 1i);
                    if _e112 {
                    } else {
                        break;
                    }
                    if (_e135 < 0i) {
                        phi_274_ = 0i;
                    } else {
                        phi_274_ = select(_e135, _e111, (_e135 > _e111));
                    }
                    let _e140 = phi_274_;
                    if _e122 {
                    } else {
                        break;
                    }
                    if _e123 {
                        phi_293_ = 0i;
                    } else {
                        phi_293_ = select(_e119, _e121, (_e119 > _e121));
                    }
                    let _e145 = phi_293_;
                    let _e148 = ((bitcast<u32>(_e145) * _e87) + bitcast<u32>(_e140));
                    if (_e148 < _e71) {
                    } else {
                        break;
                    }
                    let _e152 = mips.member[_e148];
                    if _e112 {
                    } else {
                        break;
                    }
                    let _e153 = (_e108 < 0i);
                    if _e153 {
                        phi_333_ = 0i;
                    } else {
                        phi_333_ = select(_e108, _e111, (_e108 > _e111));
                    }
                    let _e157 = phi_333_;
                    let _e159 = (_e119 + -1i);
                    if _e122 {
                    } else {
                        break;
                    }
                    if (_e159 < 0i) {
                        phi_352_ = 0i;
                    } else {
                        phi_352_ = select(_e159, _e121, (_e159 > _e121));
                    }
                    let _e164 = phi_352_;
                    let _e167 = ((bitcast<u32>(_e164) * _e87) + bitcast<u32>(_e157));
                    if (_e167 < _e71) {
                    } else {
                        break;
                    }
                    let _e171 = mips.member[_e167];
                    if _e112 {
                    } else {
                        break;
                    }
                    if _e153 {
                        phi_392_ = 0i;
                    } else {
                        phi_392_ = select(_e108, _e111, (_e108 > _e111));
                    }
                    let _e175 = phi_392_;
                    let _e177 = (_e119 + 1i);
                    if _e122 {
                    } else {
                        break;
                    }
                    if (_e177 < 0i) {
                        phi_411_ = 0i;
                    } else {
                        phi_411_ = select(_e177, _e121, (_e177 > _e121));
                    }
                    let _e182 = phi_411_;
                    let _e185 = ((bitcast<u32>(_e182) * _e87) + bitcast<u32>(_e175));
                    if (_e185 < _e71) {
                    } else {
                        break;
                    }
                    let _e189 = mips.member[_e185];
                    let _e190 = (_e134 - _e107);
                    let _e191 = (_e152 - _e107);
                    let _e192 = (_e171 - _e107);
                    let _e193 = (_e189 - _e107);
                    let _e194 = (_e191 - _e190);
                    let _e196 = (_e193 - _e192);
                    let _e204 = abs(_e190);
                    let _e205 = abs(_e191);
                    let _e206 = abs(_e192);
                    let _e207 = abs(_e193);
                    let _e208 = abs((_e190 + (_e194 * 0.5f)));
                    let _e209 = abs((_e191 + (_e194 * -0.5f)));
                    let _e210 = abs((_e192 + (_e196 * 0.5f)));
                    let _e211 = abs((_e193 + (_e196 * -0.5f)));
                    let _e220 = (_e107 * 0.011f);
                    let _e225 = (1.25f - (select(_e208, _e204, (_e204 < _e208)) / _e220));
                    if (_e225 > 0f) {
                        phi_491_ = select(1f, _e225, (_e225 < 1f));
                    } else {
                        phi_491_ = 0f;
                    }
                    let _e230 = phi_491_;
                    let _e231 = (1.25f - (select(_e209, _e205, (_e205 < _e209)) / _e220));
                    if (_e231 > 0f) {
                        phi_502_ = select(1f, _e231, (_e231 < 1f));
                    } else {
                        phi_502_ = 0f;
                    }
                    let _e236 = phi_502_;
                    let _e237 = (1.25f - (select(_e210, _e206, (_e206 < _e210)) / _e220));
                    if (_e237 > 0f) {
                        phi_513_ = select(1f, _e237, (_e237 < 1f));
                    } else {
                        phi_513_ = 0f;
                    }
                    let _e242 = phi_513_;
                    let _e243 = (1.25f - (select(_e211, _e207, (_e207 < _e211)) / _e220));
                    if (_e243 > 0f) {
                        phi_524_ = select(1f, _e243, (_e243 < 1f));
                    } else {
                        phi_524_ = 0f;
                    }
                    let _e248 = phi_524_;
                    if (_e230 > 0f) {
                        phi_1570_ = select(1f, _e230, (_e230 < 1f));
                    } else {
                        phi_1570_ = 0f;
                    }
                    let _e253 = phi_1570_;
                    let _e254 = (_e253 * 2.9f);
                    let _e256 = floor((_e254 + 0.5f));
                    if ((_e256 - _e254) == 0.5f) {
                        let _e262 = ((floor((_e256 * 0.5f)) * 2f) != _e256);
                        if _e262 {
                            phi_1585_ = (_e256 - 1f);
                        } else {
                            phi_1585_ = f32();
                        }
                        let _e265 = phi_1585_;
                        phi_1589_ = _e265;
                        phi_1590_ = select(true, false, _e262);
                    } else {
                        phi_1589_ = f32();
                        phi_1590_ = true;
                    }
                    let _e268 = phi_1589_;
                    let _e270 = phi_1590_;
                    let _e271 = select(_e268, _e256, _e270);
                    if (_e236 > 0f) {
                        phi_1613_ = select(1f, _e236, (_e236 < 1f));
                    } else {
                        phi_1613_ = 0f;
                    }
                    let _e282 = phi_1613_;
                    let _e283 = (_e282 * 2.9f);
                    let _e285 = floor((_e283 + 0.5f));
                    if ((_e285 - _e283) == 0.5f) {
                        let _e291 = ((floor((_e285 * 0.5f)) * 2f) != _e285);
                        if _e291 {
                            phi_1628_ = (_e285 - 1f);
                        } else {
                            phi_1628_ = f32();
                        }
                        let _e294 = phi_1628_;
                        phi_1632_ = _e294;
                        phi_1633_ = select(true, false, _e291);
                    } else {
                        phi_1632_ = f32();
                        phi_1633_ = true;
                    }
                    let _e297 = phi_1632_;
                    let _e299 = phi_1633_;
                    let _e300 = select(_e297, _e285, _e299);
                    if (_e242 > 0f) {
                        phi_1656_ = select(1f, _e242, (_e242 < 1f));
                    } else {
                        phi_1656_ = 0f;
                    }
                    let _e312 = phi_1656_;
                    let _e313 = (_e312 * 2.9f);
                    let _e315 = floor((_e313 + 0.5f));
                    if ((_e315 - _e313) == 0.5f) {
                        let _e321 = ((floor((_e315 * 0.5f)) * 2f) != _e315);
                        if _e321 {
                            phi_1671_ = (_e315 - 1f);
                        } else {
                            phi_1671_ = f32();
                        }
                        let _e324 = phi_1671_;
                        phi_1675_ = _e324;
                        phi_1676_ = select(true, false, _e321);
                    } else {
                        phi_1675_ = f32();
                        phi_1676_ = true;
                    }
                    let _e327 = phi_1675_;
                    let _e329 = phi_1676_;
                    let _e330 = select(_e327, _e315, _e329);
                    if (_e248 > 0f) {
                        phi_1699_ = select(1f, _e248, (_e248 < 1f));
                    } else {
                        phi_1699_ = 0f;
                    }
                    let _e342 = phi_1699_;
                    let _e343 = (_e342 * 2.9f);
                    let _e345 = floor((_e343 + 0.5f));
                    if ((_e345 - _e343) == 0.5f) {
                        let _e351 = ((floor((_e345 * 0.5f)) * 2f) != _e345);
                        if _e351 {
                            phi_1714_ = (_e345 - 1f);
                        } else {
                            phi_1714_ = f32();
                        }
                        let _e354 = phi_1714_;
                        phi_1718_ = _e354;
                        phi_1719_ = select(true, false, _e351);
                    } else {
                        phi_1718_ = f32();
                        phi_1719_ = true;
                    }
                    let _e357 = phi_1718_;
                    let _e359 = phi_1719_;
                    let _e360 = select(_e357, _e345, _e359);
                    let _e366 = ((((64u * select(select(u32(_e271), 0u, (_e271 < 0f)), 4294967295u, (_e271 > 4294967000f))) + (16u * select(select(u32(_e300), 0u, (_e300 < 0f)), 4294967295u, (_e300 > 4294967000f)))) + (4u * select(select(u32(_e330), 0u, (_e330 < 0f)), 4294967295u, (_e330 > 4294967000f)))) + select(select(u32(_e360), 0u, (_e360 < 0f)), 4294967295u, (_e360 > 4294967000f)));
                    let _e370 = params.member.member.member_3;
                    if (_e107 > 0f) {
                        phi_542_ = (_e107 < _e370);
                    } else {
                        phi_542_ = false;
                    }
                    let _e374 = phi_542_;
                    if _e374 {
                        let _e379 = ((f32(_e69.x) + 0.5f) / _e82);
                        let _e380 = ((f32(_e69.y) + 0.5f) / _e92);
                        let _e381 = (_e107 * 0.99999f);
                        let _e388 = params.member.member.member_1[0u];
                        let _e390 = ((((2f * _e379) - 1f) * _e388) * _e381);
                        let _e397 = params.member.member.member_1[1u];
                        let _e399 = (((1f - (2f * _e380)) * _e397) * _e381);
                        let _e400 = -(_e390);
                        let _e401 = -(_e399);
                        let _e402 = (_e107 * -0.99999f);
                        let _e409 = (1f / sqrt((((_e400 * _e400) + (_e401 * _e401)) + (_e402 * _e402))));
                        let _e410 = (_e400 * _e409);
                        let _e411 = (_e401 * _e409);
                        let _e412 = (_e402 * _e409);
                        if (_e103 < arrayLength((&normals.member))) {
                        } else {
                            break;
                        }
                        let _e416 = normals.member[_e103];
                        let _e424 = (f32((bitcast<i32>(((_e416 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e424 != _e424) {
                            phi_1742_ = true;
                        } else {
                            phi_1742_ = (-1f >= _e424);
                        }
                        let _e428 = phi_1742_;
                        let _e429 = select(_e424, -1f, _e428);
                        let _e439 = (f32((bitcast<i32>((((_e416 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e439 != _e439) {
                            phi_1757_ = true;
                        } else {
                            phi_1757_ = (-1f >= _e439);
                        }
                        let _e443 = phi_1757_;
                        let _e444 = select(_e439, -1f, _e443);
                        let _e447 = (1f - abs(_e429));
                        let _e448 = abs(_e444);
                        let _e449 = (_e447 - _e448);
                        if (_e449 < 0f) {
                            phi_636_ = vec2<f32>(((1f - _e448) * select(1f, -1f, (_e429 < 0f))), (_e447 * select(1f, -1f, (_e444 < 0f))));
                        } else {
                            phi_636_ = vec2<f32>(_e429, _e444);
                        }
                        let _e460 = phi_636_;
                        let _e469 = (1f / sqrt((((_e460.x * _e460.x) + (_e460.y * _e460.y)) + (_e449 * _e449))));
                        let _e470 = (_e460.x * _e469);
                        let _e471 = (_e460.y * _e469);
                        let _e472 = (_e449 * _e469);
                        let _e473 = -(_e472);
                        if ((((_e470 * _e410) + (_e471 * _e411)) + (_e473 * _e412)) < 0f) {
                            phi_664_ = vec3<f32>(-(_e470), -(_e471), _e472);
                        } else {
                            phi_664_ = vec3<f32>(_e470, _e471, _e473);
                        }
                        let _e485 = phi_664_;
                        let _e488 = params.member.member_1;
                        let _e491 = params.member.member_2;
                        let _e492 = (_e488 * _e491);
                        let _e495 = params.member.member_3;
                        let _e496 = (_e495 * _e492);
                        let _e500 = (_e492 / (((_e107 * 1.99998f) * _e388) / _e82));
                        let _e502 = ((10f - _e500) * 0.01f);
                        if (_e502 > 0f) {
                            phi_693_ = select(1f, _e502, (_e502 < 1f));
                        } else {
                            phi_693_ = 0f;
                        }
                        let _e507 = phi_693_;
                        let _e512 = params.member.member_11;
                        phi_701_ = (_e69.y & 63u);
                        phi_704_ = (_e69.x & 63u);
                        phi_706_ = 32u;
                        phi_708_ = 0u;
                        loop {
                            let _e516 = phi_701_;
                            let _e518 = phi_704_;
                            let _e520 = phi_706_;
                            let _e522 = phi_708_;
                            local = _e522;
                            let _e523 = (_e520 > 0u);
                            if _e523 {
                                let _e526 = select(0u, 1u, ((_e518 & _e520) != 0u));
                                let _e529 = select(0u, 1u, ((_e516 & _e520) != 0u));
                                if (_e529 == 0u) {
                                    if (_e526 == 1u) {
                                        phi_737_ = (63u - _e516);
                                        phi_738_ = (63u - _e518);
                                    } else {
                                        phi_737_ = _e516;
                                        phi_738_ = _e518;
                                    }
                                    let _e540 = phi_737_;
                                    let _e542 = phi_738_;
                                    phi_739_ = _e542;
                                    phi_740_ = _e540;
                                } else {
                                    phi_739_ = _e516;
                                    phi_740_ = _e518;
                                }
                                let _e544 = phi_739_;
                                let _e546 = phi_740_;
                                phi_702_ = _e544;
                                phi_705_ = _e546;
                                phi_707_ = (_e520 / 2u);
                                phi_709_ = (_e522 + ((_e520 * _e520) * ((3u * _e526) ^ _e529)));
                            } else {
                                phi_702_ = u32();
                                phi_705_ = u32();
                                phi_707_ = u32();
                                phi_709_ = u32();
                            }
                            let _e549 = phi_702_;
                            let _e551 = phi_705_;
                            let _e553 = phi_707_;
                            let _e555 = phi_709_;
                            continue;
                            continuing {
                                phi_701_ = _e549;
                                phi_704_ = _e551;
                                phi_706_ = _e553;
                                phi_708_ = _e555;
                                break if !(_e523);
                            }
                        }
                        let _e560 = local;
                        let _e562 = f32((_e560 + (288u * (_e512 % 64u))));
                        let _e564 = (0.5f + (_e562 * 0.7548777f));
                        let _e568 = (0.5f + (_e562 * 0.5698403f));
                        let _e573 = params.member.member_8;
                        let _e575 = select(1u, _e573, (1u < _e573));
                        phi_1856_ = false;
                        phi_764_ = 0u;
                        phi_767_ = (0.5f * _e507);
                        loop {
                            let _e577 = phi_1856_;
                            let _e579 = phi_764_;
                            let _e581 = phi_767_;
                            local_7 = _e581;
                            let _e582 = (_e579 < _e575);
                            if _e582 {
                                let _e585 = params.member.member_9;
                                let _e587 = select(1u, _e585, (1u < _e585));
                                let _e592 = ((3.1415927f * (f32(_e579) + (_e564 - floor(_e564)))) / f32(_e575));
                                let _e593 = sin(_e592);
                                let _e594 = cos(_e592);
                                let _e600 = ((_e594 * _e410) + (_e593 * _e411));
                                let _e604 = (_e594 - (_e410 * _e600));
                                let _e605 = (_e593 - (_e411 * _e600));
                                let _e606 = -((_e412 * _e600));
                                let _e609 = ((_e605 * _e412) - (_e411 * _e606));
                                let _e612 = ((_e606 * _e410) - (_e412 * _e604));
                                let _e615 = ((_e604 * _e411) - (_e410 * _e605));
                                let _e622 = (1f / sqrt((((_e609 * _e609) + (_e612 * _e612)) + (_e615 * _e615))));
                                let _e623 = (_e609 * _e622);
                                let _e624 = (_e612 * _e622);
                                let _e625 = (_e615 * _e622);
                                let _e633 = (((_e485.x * _e623) + (_e485.y * _e624)) + (_e485.z * _e625));
                                let _e637 = (_e485.x - (_e623 * _e633));
                                let _e638 = (_e485.y - (_e624 * _e633));
                                let _e639 = (_e485.z - (_e625 * _e633));
                                let _e645 = sqrt((((_e637 * _e637) + (_e638 * _e638)) + (_e639 * _e639)));
                                let _e650 = (((_e604 * _e637) + (_e605 * _e638)) + (_e606 * _e639));
                                if (_e650 > 0f) {
                                    phi_890_ = 1f;
                                } else {
                                    phi_890_ = select(0f, -1f, (_e650 < 0f));
                                }
                                let _e655 = phi_890_;
                                let _e661 = ((((_e637 * _e410) + (_e638 * _e411)) + (_e639 * _e412)) / _e645);
                                if (_e661 > 0f) {
                                    phi_906_ = select(1f, _e661, (_e661 < 1f));
                                } else {
                                    phi_906_ = 0f;
                                }
                                let _e666 = phi_906_;
                                let _e667 = abs(_e666);
                                let _e678 = (((-0.156583f * _e667) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e667))) >> bitcast<u32>(1i))))));
                                if (_e666 >= 0f) {
                                    phi_923_ = _e678;
                                } else {
                                    phi_923_ = (3.141593f - _e678);
                                }
                                let _e682 = phi_923_;
                                let _e683 = (_e655 * _e682);
                                let _e685 = cos((_e683 + 1.5707964f));
                                let _e687 = cos((_e683 - 1.5707964f));
                                phi_930_ = 0u;
                                phi_933_ = _e687;
                                phi_935_ = _e685;
                                loop {
                                    let _e689 = phi_930_;
                                    let _e691 = phi_933_;
                                    let _e693 = phi_935_;
                                    local_3 = _e691;
                                    local_4 = _e691;
                                    local_5 = _e693;
                                    local_6 = _e693;
                                    let _e694 = (_e689 < _e587);
                                    if _e694 {
                                        let _e699 = ((_e568 - floor(_e568)) + (f32((_e579 + (_e689 * _e587))) * 0.618034f));
                                        let _e708 = params.member.member_4;
                                        let _e710 = (pow(((f32(_e689) + (_e699 - floor(_e699))) / f32(_e587)), _e708) + (1.3f / _e500));
                                        let _e711 = ((_e594 * _e500) * _e710);
                                        let _e712 = ((-(_e593) * _e500) * _e710);
                                        let _e720 = params.member.member_7;
                                        let _e721 = (log2(sqrt(((_e711 * _e711) + (_e712 * _e712)))) - _e720);
                                        if (_e721 > 0f) {
                                            phi_977_ = select(5f, _e721, (_e721 < 5f));
                                        } else {
                                            phi_977_ = 0f;
                                        }
                                        let _e726 = phi_977_;
                                        let _e729 = (ceil((_e726 + 0.5f)) - 1f);
                                        if (_e729 > 0f) {
                                            let _e735 = select(select(u32(_e729), 0u, (_e729 < 0f)), 4294967295u, (_e729 > 4294967000f));
                                            phi_998_ = select(_e735, 4u, (4u < _e735));
                                        } else {
                                            phi_998_ = 0u;
                                        }
                                        let _e739 = phi_998_;
                                        let _e741 = floor((_e711 + 0.5f));
                                        if ((_e741 - _e711) == 0.5f) {
                                            let _e747 = ((floor((_e741 * 0.5f)) * 2f) != _e741);
                                            if _e747 {
                                                phi_1014_ = (_e741 - 1f);
                                            } else {
                                                phi_1014_ = f32();
                                            }
                                            let _e750 = phi_1014_;
                                            phi_1016_ = _e750;
                                            phi_1017_ = select(true, false, _e747);
                                        } else {
                                            phi_1016_ = f32();
                                            phi_1017_ = true;
                                        }
                                        let _e753 = phi_1016_;
                                        let _e755 = phi_1017_;
                                        let _e758 = floor((_e712 + 0.5f));
                                        if ((_e758 - _e712) == 0.5f) {
                                            let _e764 = ((floor((_e758 * 0.5f)) * 2f) != _e758);
                                            if _e764 {
                                                phi_1037_ = (_e758 - 1f);
                                            } else {
                                                phi_1037_ = f32();
                                            }
                                            let _e767 = phi_1037_;
                                            phi_1039_ = _e767;
                                            phi_1040_ = select(true, false, _e764);
                                        } else {
                                            phi_1039_ = f32();
                                            phi_1040_ = true;
                                        }
                                        let _e770 = phi_1039_;
                                        let _e772 = phi_1040_;
                                        let _e774 = (select(_e753, _e741, _e755) / _e82);
                                        let _e775 = (select(_e770, _e758, _e772) / _e92);
                                        let _e776 = (_e379 + _e774);
                                        let _e777 = (_e380 + _e775);
                                        let _e778 = (_e379 - _e774);
                                        let _e779 = (_e380 - _e775);
                                        let _e780 = (_e739 & 31u);
                                        let _e782 = (_e87 >> bitcast<u32>(_e780));
                                        let _e784 = select(1u, _e782, (1u < _e782));
                                        let _e786 = (_e97 >> bitcast<u32>(_e780));
                                        let _e788 = select(1u, _e786, (1u < _e786));
                                        let _e789 = f32(_e784);
                                        let _e791 = floor((_e776 * _e789));
                                        if (_e791 > 0f) {
                                            let _e797 = select(select(u32(_e791), 0u, (_e791 < 0f)), 4294967295u, (_e791 > 4294967000f));
                                            let _e798 = (_e784 - 1u);
                                            phi_1089_ = select(_e797, _e798, (_e798 < _e797));
                                        } else {
                                            phi_1089_ = 0u;
                                        }
                                        let _e802 = phi_1089_;
                                        let _e803 = f32(_e788);
                                        let _e805 = floor((_e777 * _e803));
                                        if (_e805 > 0f) {
                                            let _e811 = select(select(u32(_e805), 0u, (_e805 < 0f)), 4294967295u, (_e805 > 4294967000f));
                                            let _e812 = (_e788 - 1u);
                                            phi_1110_ = select(_e811, _e812, (_e812 < _e811));
                                        } else {
                                            phi_1110_ = 0u;
                                        }
                                        let _e816 = phi_1110_;
                                        phi_1112_ = 0u;
                                        phi_1115_ = 0u;
                                        loop {
                                            let _e818 = phi_1112_;
                                            let _e820 = phi_1115_;
                                            local_1 = _e820;
                                            let _e821 = (_e818 < _e739);
                                            if _e821 {
                                                let _e822 = (_e818 & 31u);
                                                let _e824 = (_e87 >> bitcast<u32>(_e822));
                                                let _e828 = (_e97 >> bitcast<u32>(_e822));
                                                phi_1113_ = (_e818 + 1u);
                                                phi_1116_ = (_e820 + (select(1u, _e824, (1u < _e824)) * select(1u, _e828, (1u < _e828))));
                                            } else {
                                                phi_1113_ = u32();
                                                phi_1116_ = u32();
                                            }
                                            let _e835 = phi_1113_;
                                            let _e837 = phi_1116_;
                                            continue;
                                            continuing {
                                                phi_1112_ = _e835;
                                                phi_1115_ = _e837;
                                                break if !(_e821);
                                            }
                                        }
                                        let _e842 = local_1;
                                        let _e843 = (_e842 + ((_e816 * _e784) + _e802));
                                        if (_e843 < _e71) {
                                        } else {
                                            phi_1807_ = true;
                                            break;
                                        }
                                        let _e847 = mips.member[_e843];
                                        let _e857 = floor((_e778 * _e789));
                                        if (_e857 > 0f) {
                                            let _e863 = select(select(u32(_e857), 0u, (_e857 < 0f)), 4294967295u, (_e857 > 4294967000f));
                                            let _e864 = (_e784 - 1u);
                                            phi_1199_ = select(_e863, _e864, (_e864 < _e863));
                                        } else {
                                            phi_1199_ = 0u;
                                        }
                                        let _e868 = phi_1199_;
                                        let _e870 = floor((_e779 * _e803));
                                        if (_e870 > 0f) {
                                            let _e876 = select(select(u32(_e870), 0u, (_e870 < 0f)), 4294967295u, (_e870 > 4294967000f));
                                            let _e877 = (_e788 - 1u);
                                            phi_1220_ = select(_e876, _e877, (_e877 < _e876));
                                        } else {
                                            phi_1220_ = 0u;
                                        }
                                        let _e881 = phi_1220_;
                                        phi_1222_ = 0u;
                                        phi_1225_ = 0u;
                                        loop {
                                            let _e883 = phi_1222_;
                                            let _e885 = phi_1225_;
                                            local_2 = _e885;
                                            let _e886 = (_e883 < _e739);
                                            if _e886 {
                                                let _e887 = (_e883 & 31u);
                                                let _e889 = (_e87 >> bitcast<u32>(_e887));
                                                let _e893 = (_e97 >> bitcast<u32>(_e887));
                                                phi_1223_ = (_e883 + 1u);
                                                phi_1226_ = (_e885 + (select(1u, _e889, (1u < _e889)) * select(1u, _e893, (1u < _e893))));
                                            } else {
                                                phi_1223_ = u32();
                                                phi_1226_ = u32();
                                            }
                                            let _e900 = phi_1223_;
                                            let _e902 = phi_1226_;
                                            continue;
                                            continuing {
                                                phi_1222_ = _e900;
                                                phi_1225_ = _e902;
                                                break if !(_e886);
                                            }
                                        }
                                        let _e907 = local_2;
                                        let _e908 = (_e907 + ((_e881 * _e784) + _e868));
                                        if (_e908 < _e71) {
                                        } else {
                                            phi_1807_ = true;
                                            break;
                                        }
                                        let _e912 = mips.member[_e908];
                                        let _e921 = (((((2f * _e776) - 1f) * _e388) * _e847) - _e390);
                                        let _e922 = ((((1f - (2f * _e777)) * _e397) * _e847) - _e399);
                                        let _e923 = (_e847 - _e381);
                                        let _e926 = params.member.member_5;
                                        let _e929 = ((_e921 * _e921) + (_e922 * _e922));
                                        let _e932 = sqrt((_e929 + (_e923 * _e923)));
                                        let _e941 = (1f + _e926);
                                        let _e942 = (_e923 * _e941);
                                        let _e945 = sqrt((_e929 + (_e942 * _e942)));
                                        let _e946 = (_e496 > 0f);
                                        if _e946 {
                                            let _e948 = ((_e492 - _e945) / _e496);
                                            if (_e948 > 0f) {
                                                phi_1317_ = select(1f, _e948, (_e948 < 1f));
                                            } else {
                                                phi_1317_ = 0f;
                                            }
                                            let _e953 = phi_1317_;
                                            phi_1323_ = _e953;
                                        } else {
                                            phi_1323_ = select(0f, 1f, (_e945 <= _e492));
                                        }
                                        let _e957 = phi_1323_;
                                        let _e960 = (_e685 + ((((((_e921 / _e932) * _e410) + ((_e922 / _e932) * _e411)) + ((_e923 / _e932) * _e412)) - _e685) * _e957));
                                        let _e961 = (((((2f * _e778) - 1f) * _e388) * _e912) - _e390);
                                        let _e962 = ((((1f - (2f * _e779)) * _e397) * _e912) - _e399);
                                        let _e963 = (_e912 - _e381);
                                        let _e966 = ((_e961 * _e961) + (_e962 * _e962));
                                        let _e969 = sqrt((_e966 + (_e963 * _e963)));
                                        let _e978 = (_e963 * _e941);
                                        let _e981 = sqrt((_e966 + (_e978 * _e978)));
                                        if _e946 {
                                            let _e983 = ((_e492 - _e981) / _e496);
                                            if (_e983 > 0f) {
                                                phi_1369_ = select(1f, _e983, (_e983 < 1f));
                                            } else {
                                                phi_1369_ = 0f;
                                            }
                                            let _e988 = phi_1369_;
                                            phi_1375_ = _e988;
                                        } else {
                                            phi_1375_ = select(0f, 1f, (_e981 <= _e492));
                                        }
                                        let _e992 = phi_1375_;
                                        let _e995 = (_e687 + ((((((_e961 / _e969) * _e410) + ((_e962 / _e969) * _e411)) + ((_e963 / _e969) * _e412)) - _e687) * _e992));
                                        if (_e693 != _e693) {
                                            phi_1772_ = true;
                                        } else {
                                            phi_1772_ = (_e960 >= _e693);
                                        }
                                        let _e999 = phi_1772_;
                                        if (_e691 != _e691) {
                                            phi_1787_ = true;
                                        } else {
                                            phi_1787_ = (_e995 >= _e691);
                                        }
                                        let _e1004 = phi_1787_;
                                        phi_931_ = (_e689 + 1u);
                                        phi_934_ = select(_e691, _e995, _e1004);
                                        phi_936_ = select(_e693, _e960, _e999);
                                    } else {
                                        phi_931_ = u32();
                                        phi_934_ = f32();
                                        phi_936_ = f32();
                                    }
                                    let _e1008 = phi_931_;
                                    let _e1010 = phi_934_;
                                    let _e1012 = phi_936_;
                                    continue;
                                    continuing {
                                        phi_930_ = _e1008;
                                        phi_933_ = _e1010;
                                        phi_935_ = _e1012;
                                        phi_1807_ = _e577;
                                        break if !(_e694);
                                    }
                                }
                                let _e1015 = phi_1807_;
                                phi_1924_ = _e1015;
                                if _e1015 {
                                    break;
                                }
                                let _e1020 = local_3;
                                let _e1021 = abs(_e1020);
                                let _e1032 = (((-0.156583f * _e1021) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1021))) >> bitcast<u32>(1i))))));
                                let _e1034 = local_4;
                                if (_e1034 >= 0f) {
                                    phi_1401_ = _e1032;
                                } else {
                                    phi_1401_ = (3.141593f - _e1032);
                                }
                                let _e1038 = phi_1401_;
                                let _e1040 = local_5;
                                let _e1041 = abs(_e1040);
                                let _e1052 = (((-0.156583f * _e1041) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1041))) >> bitcast<u32>(1i))))));
                                let _e1054 = local_6;
                                if (_e1054 >= 0f) {
                                    phi_1419_ = _e1052;
                                } else {
                                    phi_1419_ = (3.141593f - _e1052);
                                }
                                let _e1058 = phi_1419_;
                                let _e1059 = (_e1038 * -2f);
                                let _e1060 = sin(_e683);
                                let _e1066 = (2f * _e1058);
                                phi_1925_ = _e1015;
                                phi_765_ = (_e579 + 1u);
                                phi_768_ = (_e581 + ((_e645 + ((1f - _e645) * 0.05f)) * (0.25f * (((_e666 + (_e1059 * _e1060)) - cos((_e1059 - _e683))) + ((_e666 + (_e1066 * _e1060)) - cos((_e1066 - _e683)))))));
                            } else {
                                phi_1925_ = _e577;
                                phi_765_ = u32();
                                phi_768_ = f32();
                            }
                            let _e1078 = phi_1925_;
                            let _e1080 = phi_765_;
                            let _e1082 = phi_768_;
                            continue;
                            continuing {
                                phi_1856_ = _e1078;
                                phi_764_ = _e1080;
                                phi_767_ = _e1082;
                                phi_1924_ = _e1078;
                                break if !(_e582);
                            }
                        }
                        let _e1085 = phi_1924_;
                        if _e1085 {
                            break;
                        }
                        let _e1088 = local_7;
                        let _e1092 = params.member.member_6;
                        let _e1093 = pow((_e1088 / f32(_e575)), _e1092);
                        if (_e1093 != _e1093) {
                            phi_1802_ = true;
                        } else {
                            phi_1802_ = (0.03f >= _e1093);
                        }
                        let _e1097 = phi_1802_;
                        let _e1099 = (select(_e1093, 0.03f, _e1097) * 0.6666667f);
                        if (_e1099 > 0f) {
                            phi_1458_ = select(1f, _e1099, (_e1099 < 1f));
                        } else {
                            phi_1458_ = 0f;
                        }
                        let _e1104 = phi_1458_;
                        let _e1106 = ((_e1104 * 255f) + 0.5f);
                        phi_1490_ = type_22(select(select(u32(_e1106), 0u, (_e1106 < 0f)), 4294967295u, (_e1106 > 4294967000f)), _e366);
                    } else {
                        phi_1490_ = type_22(170u, _e366);
                    }
                    let _e1115 = phi_1490_;
                    if (_e103 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e103] = _e1115.member;
                    if (_e103 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e103] = _e1115.member_1;
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
