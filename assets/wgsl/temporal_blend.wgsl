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

struct type_15 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_16 {
    member: type_15,
    member_1: type_15,
    member_2: type_5,
}

struct type_18 {
    member: type_16,
    member_1: type_16,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_20 {
    member: array<type_18>,
}

struct type_22 {
    member: vec2<u32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: bool,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> depth: type_7;
@group(0) @binding(0) 
var<storage> frame: type_20;
@group(0) @binding(2) 
var<storage> ao: type_7;
@group(0) @binding(3) 
var<storage> history_ao: type_7;
@group(0) @binding(4) 
var<storage> history_depth: type_7;
@group(0) @binding(5) 
var<storage, read_write> out: type_7;

fn function_() {
    var phi_183_: bool;
    var phi_185_: bool;
    var phi_186_: bool;
    var phi_187_: bool;
    var phi_188_: bool;
    var phi_443_: bool;
    var phi_445_: bool;
    var phi_446_: bool;
    var phi_447_: bool;
    var phi_448_: bool;
    var phi_462_: type_22;
    var phi_464_: type_22;
    var phi_466_: bool;
    var phi_467_: type_22;
    var phi_468_: bool;
    var phi_469_: bool;
    var phi_470_: type_22;
    var phi_471_: bool;
    var phi_472_: bool;
    var phi_473_: type_22;
    var phi_474_: bool;
    var phi_475_: bool;
    var phi_483_: type_22;
    var phi_484_: bool;
    var phi_485_: type_22;
    var phi_486_: bool;
    var phi_487_: bool;
    var phi_495_: type_22;
    var phi_496_: bool;
    var phi_500_: type_22;
    var phi_526_: i32;
    var phi_529_: f32;
    var phi_531_: f32;
    var phi_566_: f32;
    var phi_572_: f32;
    var phi_629_: bool;
    var phi_631_: bool;
    var phi_632_: bool;
    var phi_633_: bool;
    var phi_634_: bool;
    var phi_678_: bool;
    var phi_692_: f32;
    var phi_693_: f32;
    var phi_694_: f32;
    var phi_695_: f32;
    var phi_696_: f32;
    var phi_697_: f32;
    var phi_698_: f32;
    var phi_699_: f32;
    var phi_700_: f32;
    var phi_701_: f32;
    var phi_527_: i32;
    var phi_530_: f32;
    var phi_532_: f32;
    var phi_768_: bool;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_710_: vec2<f32>;
    var phi_722_: f32;
    var phi_723_: f32;
    var phi_724_: bool;
    var phi_728_: f32;
    var phi_730_: bool;
    var phi_731_: f32;
    var phi_732_: bool;
    var phi_733_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e39 = id_1;
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e59 = frame.member[0u].member.member_2.member[0u];
            let _e64 = select(select(u32(_e59), 0u, (_e59 < 0f)), 4294967295u, (_e59 > 4294967000f));
            let _e71 = frame.member[0u].member.member_2.member[1u];
            let _e76 = select(select(u32(_e71), 0u, (_e71 < 0f)), 4294967295u, (_e71 > 4294967000f));
            if (_e39.x >= _e64) {
            } else {
                if (_e39.y >= _e76) {
                } else {
                    let _e82 = ((_e39.y * _e64) + _e39.x);
                    if (_e82 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    let _e86 = ao.member[_e82];
                    let _e90 = frame.member[0u].member_4;
                    if (_e90 == 0u) {
                        phi_731_ = f32();
                        phi_732_ = true;
                        phi_733_ = false;
                    } else {
                        let _e97 = frame.member[0u].member.member_2.member_4;
                        if (_e39.x >= _e97) {
                            if (_e39.y >= _e97) {
                                let _e101 = ((_e39.x + _e97) < _e64);
                                if _e101 {
                                    phi_183_ = ((_e39.y + _e97) < _e76);
                                } else {
                                    phi_183_ = bool();
                                }
                                let _e105 = phi_183_;
                                phi_185_ = _e105;
                                phi_186_ = select(true, false, _e101);
                            } else {
                                phi_185_ = bool();
                                phi_186_ = true;
                            }
                            let _e108 = phi_185_;
                            let _e110 = phi_186_;
                            phi_187_ = _e108;
                            phi_188_ = _e110;
                        } else {
                            phi_187_ = bool();
                            phi_188_ = true;
                        }
                        let _e112 = phi_187_;
                        let _e114 = phi_188_;
                        let _e115 = select(_e112, false, _e114);
                        if _e115 {
                            if (_e82 < arrayLength((&depth.member))) {
                            } else {
                                break;
                            }
                            let _e119 = depth.member[_e82];
                            let _e125 = frame.member[0u].member.member_2.member_3;
                            if select(false, (_e119 < _e125), (_e119 > 0f)) {
                                let _e148 = frame.member[0u].member.member_2.member_1[0u];
                                let _e149 = ((((((f32(bitcast<i32>(_e39.x)) + 0.5f) / _e59) * 2f) - 1f) * _e119) * _e148);
                                let _e157 = frame.member[0u].member.member_2.member_1[1u];
                                let _e158 = ((((((f32(bitcast<i32>(_e39.y)) + 0.5f) / _e71) * -2f) + 1f) * _e119) * _e157);
                                let _e159 = -(_e119);
                                let _e165 = frame.member[0u].member.member_1.member;
                                let _e177 = frame.member[0u].member.member_1.member_1;
                                let _e192 = frame.member[0u].member.member_1.member_2;
                                let _e207 = frame.member[0u].member.member_1.member_3;
                                let _e209 = (_e207.x + ((_e192.x * _e159) + ((_e177.x * _e158) + (_e165.x * _e149))));
                                let _e211 = (_e207.y + ((_e192.y * _e159) + ((_e177.y * _e158) + (_e165.y * _e149))));
                                let _e213 = (_e207.z + ((_e192.z * _e159) + ((_e177.z * _e158) + (_e165.z * _e149))));
                                let _e219 = frame.member[0u].member_1.member.member;
                                let _e231 = frame.member[0u].member_1.member.member_1;
                                let _e246 = frame.member[0u].member_1.member.member_2;
                                let _e261 = frame.member[0u].member_1.member.member_3;
                                let _e267 = (_e261.z + ((_e246.z * _e213) + ((_e231.z * _e211) + (_e219.z * _e209))));
                                let _e268 = -(_e267);
                                if (_e268 != _e268) {
                                    phi_485_ = type_22();
                                    phi_486_ = true;
                                    phi_487_ = false;
                                } else {
                                    let _e275 = frame.member[0u].member_1.member_2.member_2;
                                    let _e276 = (_e268 <= _e275);
                                    if _e276 {
                                        phi_483_ = type_22();
                                        phi_484_ = false;
                                    } else {
                                        let _e277 = (-0.5f / _e267);
                                        let _e285 = frame.member[0u].member_1.member_2.member_1[0u];
                                        let _e295 = frame.member[0u].member_1.member_2.member_1[1u];
                                        let _e304 = frame.member[0u].member_1.member_2.member[0u];
                                        let _e311 = frame.member[0u].member_1.member_2.member[1u];
                                        let _e312 = (((((_e261.x + ((_e246.x * _e213) + ((_e231.x * _e211) + (_e219.x * _e209)))) * _e277) / _e285) + 0.5f) * _e304);
                                        let _e313 = ((0.5f - (((_e261.y + ((_e246.y * _e213) + ((_e231.y * _e211) + (_e219.y * _e209)))) * _e277) / _e295)) * _e311);
                                        if (_e312 >= 0f) {
                                            if (_e313 >= 0f) {
                                                if (_e312 < _e304) {
                                                    let _e317 = (_e313 < _e311);
                                                    if _e317 {
                                                        let _e322 = select(select(u32(_e312), 0u, (_e312 < 0f)), 4294967295u, (_e312 > 4294967000f));
                                                        let _e327 = select(select(u32(_e313), 0u, (_e313 < 0f)), 4294967295u, (_e313 > 4294967000f));
                                                        let _e343 = frame.member[0u].member_1.member_2.member_4;
                                                        if (_e322 >= _e343) {
                                                            if (_e327 >= _e343) {
                                                                let _e347 = ((_e322 + _e343) < select(select(u32(_e304), 0u, (_e304 < 0f)), 4294967295u, (_e304 > 4294967000f)));
                                                                if _e347 {
                                                                    phi_443_ = ((_e327 + _e343) < select(select(u32(_e311), 0u, (_e311 < 0f)), 4294967295u, (_e311 > 4294967000f)));
                                                                } else {
                                                                    phi_443_ = bool();
                                                                }
                                                                let _e351 = phi_443_;
                                                                phi_445_ = _e351;
                                                                phi_446_ = select(true, false, _e347);
                                                            } else {
                                                                phi_445_ = bool();
                                                                phi_446_ = true;
                                                            }
                                                            let _e354 = phi_445_;
                                                            let _e356 = phi_446_;
                                                            phi_447_ = _e354;
                                                            phi_448_ = _e356;
                                                        } else {
                                                            phi_447_ = bool();
                                                            phi_448_ = true;
                                                        }
                                                        let _e358 = phi_447_;
                                                        let _e360 = phi_448_;
                                                        let _e361 = select(_e358, false, _e360);
                                                        if _e361 {
                                                            phi_462_ = type_22(vec2<u32>(_e322, _e327), vec2<f32>(_e312, _e313), _e268, true);
                                                        } else {
                                                            phi_462_ = type_22();
                                                        }
                                                        let _e366 = phi_462_;
                                                        phi_464_ = _e366;
                                                        phi_466_ = select(true, false, _e361);
                                                    } else {
                                                        phi_464_ = type_22();
                                                        phi_466_ = false;
                                                    }
                                                    let _e369 = phi_464_;
                                                    let _e371 = phi_466_;
                                                    phi_467_ = _e369;
                                                    phi_468_ = select(true, false, _e317);
                                                    phi_469_ = _e371;
                                                } else {
                                                    phi_467_ = type_22();
                                                    phi_468_ = true;
                                                    phi_469_ = false;
                                                }
                                                let _e374 = phi_467_;
                                                let _e376 = phi_468_;
                                                let _e378 = phi_469_;
                                                phi_470_ = _e374;
                                                phi_471_ = _e376;
                                                phi_472_ = _e378;
                                            } else {
                                                phi_470_ = type_22();
                                                phi_471_ = true;
                                                phi_472_ = false;
                                            }
                                            let _e380 = phi_470_;
                                            let _e382 = phi_471_;
                                            let _e384 = phi_472_;
                                            phi_473_ = _e380;
                                            phi_474_ = _e382;
                                            phi_475_ = _e384;
                                        } else {
                                            phi_473_ = type_22();
                                            phi_474_ = true;
                                            phi_475_ = false;
                                        }
                                        let _e386 = phi_473_;
                                        let _e388 = phi_474_;
                                        let _e390 = phi_475_;
                                        phi_483_ = _e386;
                                        phi_484_ = select(_e390, true, _e388);
                                    }
                                    let _e393 = phi_483_;
                                    let _e395 = phi_484_;
                                    phi_485_ = _e393;
                                    phi_486_ = _e276;
                                    phi_487_ = _e395;
                                }
                                let _e397 = phi_485_;
                                let _e399 = phi_486_;
                                let _e401 = phi_487_;
                                phi_495_ = _e397;
                                phi_496_ = select(_e401, true, _e399);
                            } else {
                                phi_495_ = type_22();
                                phi_496_ = true;
                            }
                            let _e404 = phi_495_;
                            let _e406 = phi_496_;
                            if _e406 {
                                phi_500_ = type_22(vec2<u32>(0u, 0u), vec2<f32>(0f, 0f), 0f, false);
                            } else {
                                phi_500_ = _e404;
                            }
                            let _e408 = phi_500_;
                            if _e408.member_3 {
                                let _e413 = frame.member[0u].member_3;
                                let _e418 = (_e408.member_1.x - 0.5f);
                                let _e419 = (_e408.member_1.y - 0.5f);
                                let _e420 = floor(_e418);
                                let _e421 = floor(_e419);
                                let _e430 = (floor((((_e418 - _e420) * 256f) + 0.5f)) * 0.00390625f);
                                let _e431 = (floor((((_e419 - _e421) * 256f) + 0.5f)) * 0.00390625f);
                                phi_526_ = 0i;
                                phi_529_ = 0f;
                                phi_531_ = 0f;
                                loop {
                                    let _e433 = phi_526_;
                                    let _e435 = phi_529_;
                                    let _e437 = phi_531_;
                                    local = _e435;
                                    local_1 = _e437;
                                    local_2 = _e435;
                                    local_3 = _e435;
                                    let _e438 = (_e433 < 4i);
                                    if _e438 {
                                        let _e439 = (_e433 & 1i);
                                        let _e441 = (_e433 >> bitcast<u32>(1i));
                                        let _e449 = (select(0i, select(select(i32(_e420), i32(-2147483648), (_e420 < -2147483600f)), 2147483647i, (_e420 > 2147483500f)), (_e420 == _e420)) + _e439);
                                        let _e457 = (select(0i, select(select(i32(_e421), i32(-2147483648), (_e421 < -2147483600f)), 2147483647i, (_e421 > 2147483500f)), (_e421 == _e421)) + _e441);
                                        if (_e439 == 0i) {
                                            phi_566_ = (1f - _e430);
                                        } else {
                                            phi_566_ = _e430;
                                        }
                                        let _e461 = phi_566_;
                                        if (_e441 == 0i) {
                                            phi_572_ = (1f - _e431);
                                        } else {
                                            phi_572_ = _e431;
                                        }
                                        let _e465 = phi_572_;
                                        let _e466 = (_e461 * _e465);
                                        if (_e466 > 0f) {
                                            if (_e449 >= 0i) {
                                                if (_e457 >= 0i) {
                                                    let _e470 = bitcast<u32>(_e449);
                                                    let _e471 = bitcast<u32>(_e457);
                                                    let _e478 = frame.member[0u].member_1.member_2.member[0u];
                                                    let _e483 = select(select(u32(_e478), 0u, (_e478 < 0f)), 4294967295u, (_e478 > 4294967000f));
                                                    let _e490 = frame.member[0u].member_1.member_2.member[1u];
                                                    let _e501 = frame.member[0u].member_1.member_2.member_4;
                                                    if (_e470 >= _e501) {
                                                        if (_e471 >= _e501) {
                                                            let _e505 = ((_e470 + _e501) < _e483);
                                                            if _e505 {
                                                                phi_629_ = ((_e471 + _e501) < select(select(u32(_e490), 0u, (_e490 < 0f)), 4294967295u, (_e490 > 4294967000f)));
                                                            } else {
                                                                phi_629_ = bool();
                                                            }
                                                            let _e509 = phi_629_;
                                                            phi_631_ = _e509;
                                                            phi_632_ = select(true, false, _e505);
                                                        } else {
                                                            phi_631_ = bool();
                                                            phi_632_ = true;
                                                        }
                                                        let _e512 = phi_631_;
                                                        let _e514 = phi_632_;
                                                        phi_633_ = _e512;
                                                        phi_634_ = _e514;
                                                    } else {
                                                        phi_633_ = bool();
                                                        phi_634_ = true;
                                                    }
                                                    let _e516 = phi_633_;
                                                    let _e518 = phi_634_;
                                                    if select(_e516, false, _e518) {
                                                        let _e521 = ((_e471 * _e483) + _e470);
                                                        if (_e521 < arrayLength((&history_depth.member))) {
                                                        } else {
                                                            phi_768_ = true;
                                                            break;
                                                        }
                                                        let _e526 = history_depth.member[_e521];
                                                        let _e532 = frame.member[0u].member_1.member_2.member_3;
                                                        if select(false, (_e526 < _e532), (_e526 > 0f)) {
                                                            phi_678_ = (abs((_e526 - _e408.member_2)) <= (_e413 * _e408.member_2));
                                                        } else {
                                                            phi_678_ = false;
                                                        }
                                                        let _e541 = phi_678_;
                                                        if _e541 {
                                                            if (_e521 < arrayLength((&history_ao.member))) {
                                                            } else {
                                                                phi_768_ = true;
                                                                break;
                                                            }
                                                            let _e545 = history_ao.member[_e521];
                                                            phi_692_ = (_e435 + _e466);
                                                            phi_693_ = (_e437 + (_e466 * _e545));
                                                        } else {
                                                            phi_692_ = _e435;
                                                            phi_693_ = _e437;
                                                        }
                                                        let _e550 = phi_692_;
                                                        let _e552 = phi_693_;
                                                        phi_694_ = _e550;
                                                        phi_695_ = _e552;
                                                    } else {
                                                        phi_694_ = _e435;
                                                        phi_695_ = _e437;
                                                    }
                                                    let _e554 = phi_694_;
                                                    let _e556 = phi_695_;
                                                    phi_696_ = _e554;
                                                    phi_697_ = _e556;
                                                } else {
                                                    phi_696_ = _e435;
                                                    phi_697_ = _e437;
                                                }
                                                let _e558 = phi_696_;
                                                let _e560 = phi_697_;
                                                phi_698_ = _e558;
                                                phi_699_ = _e560;
                                            } else {
                                                phi_698_ = _e435;
                                                phi_699_ = _e437;
                                            }
                                            let _e562 = phi_698_;
                                            let _e564 = phi_699_;
                                            phi_700_ = _e562;
                                            phi_701_ = _e564;
                                        } else {
                                            phi_700_ = _e435;
                                            phi_701_ = _e437;
                                        }
                                        let _e566 = phi_700_;
                                        let _e568 = phi_701_;
                                        phi_527_ = (_e433 + 1i);
                                        phi_530_ = _e566;
                                        phi_532_ = _e568;
                                    } else {
                                        phi_527_ = i32();
                                        phi_530_ = f32();
                                        phi_532_ = f32();
                                    }
                                    let _e571 = phi_527_;
                                    let _e573 = phi_530_;
                                    let _e575 = phi_532_;
                                    continue;
                                    continuing {
                                        phi_526_ = _e571;
                                        phi_529_ = _e573;
                                        phi_531_ = _e575;
                                        phi_768_ = false;
                                        break if !(_e438);
                                    }
                                }
                                let _e578 = phi_768_;
                                if _e578 {
                                    break;
                                }
                                let _e580 = local;
                                if (_e580 > 0f) {
                                    let _e583 = local_1;
                                    let _e585 = local_2;
                                    let _e588 = local_3;
                                    phi_710_ = vec2<f32>(_e588, (_e583 / _e585));
                                } else {
                                    phi_710_ = vec2<f32>(0f, 0f);
                                }
                                let _e591 = phi_710_;
                                let _e594 = (_e591.x <= 0f);
                                if _e594 {
                                    phi_722_ = f32();
                                } else {
                                    let _e598 = frame.member[0u].member_2;
                                    phi_722_ = (_e591.y + (_e598 * (_e86 - _e591.y)));
                                }
                                let _e603 = phi_722_;
                                phi_723_ = _e603;
                                phi_724_ = _e594;
                            } else {
                                phi_723_ = f32();
                                phi_724_ = true;
                            }
                            let _e605 = phi_723_;
                            let _e607 = phi_724_;
                            phi_728_ = _e605;
                            phi_730_ = _e607;
                        } else {
                            phi_728_ = f32();
                            phi_730_ = false;
                        }
                        let _e609 = phi_728_;
                        let _e611 = phi_730_;
                        phi_731_ = _e609;
                        phi_732_ = select(true, false, _e115);
                        phi_733_ = _e611;
                    }
                    let _e614 = phi_731_;
                    let _e616 = phi_732_;
                    let _e618 = phi_733_;
                    if (_e82 < arrayLength((&out.member))) {
                    } else {
                        break;
                    }
                    out.member[_e82] = select(_e614, _e86, select(_e618, true, _e616));
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn temporal_blend(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
