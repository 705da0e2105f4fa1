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
    var phi_441_: bool;
    var phi_443_: bool;
    var phi_444_: bool;
    var phi_445_: bool;
    var phi_446_: bool;
    var phi_460_: type_22;
    var phi_462_: type_22;
    var phi_464_: bool;
    var phi_465_: type_22;
    var phi_466_: bool;
    var phi_467_: bool;
    var phi_468_: type_22;
    var phi_469_: bool;
    var phi_470_: bool;
    var phi_471_: type_22;
    var phi_472_: bool;
    var phi_473_: bool;
    var phi_481_: type_22;
    var phi_482_: bool;
    var phi_483_: type_22;
    var phi_484_: bool;
    var phi_485_: bool;
    var phi_493_: type_22;
    var phi_494_: bool;
    var phi_498_: type_22;
    var phi_524_: i32;
    var phi_527_: f32;
    var phi_529_: f32;
    var phi_564_: f32;
    var phi_570_: f32;
    var phi_627_: bool;
    var phi_629_: bool;
    var phi_630_: bool;
    var phi_631_: bool;
    var phi_632_: bool;
    var phi_676_: bool;
    var phi_690_: f32;
    var phi_691_: f32;
    var phi_692_: f32;
    var phi_693_: f32;
    var phi_694_: f32;
    var phi_695_: f32;
    var phi_696_: f32;
    var phi_697_: f32;
    var phi_698_: f32;
    var phi_699_: f32;
    var phi_525_: i32;
    var phi_528_: f32;
    var phi_530_: f32;
    var phi_766_: bool;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_708_: vec2<f32>;
    var phi_720_: f32;
    var phi_721_: f32;
    var phi_722_: bool;
    var phi_726_: f32;
    var phi_728_: bool;
    var phi_729_: f32;
    var phi_730_: bool;
    var phi_731_: bool;

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
                        phi_729_ = f32();
                        phi_730_ = true;
                        phi_731_ = false;
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
                                let _e146 = frame.member[0u].member.member_2.member_1[0u];
                                let _e147 = ((((((f32(_e39.x) + 0.5f) / _e59) * 2f) - 1f) * _e119) * _e146);
                                let _e155 = frame.member[0u].member.member_2.member_1[1u];
                                let _e156 = ((((((f32(_e39.y) + 0.5f) / _e71) * -2f) + 1f) * _e119) * _e155);
                                let _e157 = -(_e119);
                                let _e163 = frame.member[0u].member.member_1.member;
                                let _e175 = frame.member[0u].member.member_1.member_1;
                                let _e190 = frame.member[0u].member.member_1.member_2;
                                let _e205 = frame.member[0u].member.member_1.member_3;
                                let _e207 = (_e205.x + ((_e190.x * _e157) + ((_e175.x * _e156) + (_e163.x * _e147))));
                                let _e209 = (_e205.y + ((_e190.y * _e157) + ((_e175.y * _e156) + (_e163.y * _e147))));
                                let _e211 = (_e205.z + ((_e190.z * _e157) + ((_e175.z * _e156) + (_e163.z * _e147))));
                                let _e217 = frame.member[0u].member_1.member.member;
                                let _e229 = frame.member[0u].member_1.member.member_1;
                                let _e244 = frame.member[0u].member_1.member.member_2;
                                let _e259 = frame.member[0u].member_1.member.member_3;
                                let _e265 = (_e259.z + ((_e244.z * _e211) + ((_e229.z * _e209) + (_e217.z * _e207))));
                                let _e266 = -(_e265);
                                if (_e266 != _e266) {
                                    phi_483_ = type_22();
                                    phi_484_ = true;
                                    phi_485_ = false;
                                } else {
                                    let _e273 = frame.member[0u].member_1.member_2.member_2;
                                    let _e274 = (_e266 <= _e273);
                                    if _e274 {
                                        phi_481_ = type_22();
                                        phi_482_ = false;
                                    } else {
                                        let _e275 = (-0.5f / _e265);
                                        let _e283 = frame.member[0u].member_1.member_2.member_1[0u];
                                        let _e293 = frame.member[0u].member_1.member_2.member_1[1u];
                                        let _e302 = frame.member[0u].member_1.member_2.member[0u];
                                        let _e309 = frame.member[0u].member_1.member_2.member[1u];
                                        let _e310 = (((((_e259.x + ((_e244.x * _e211) + ((_e229.x * _e209) + (_e217.x * _e207)))) * _e275) / _e283) + 0.5f) * _e302);
                                        let _e311 = ((0.5f - (((_e259.y + ((_e244.y * _e211) + ((_e229.y * _e209) + (_e217.y * _e207)))) * _e275) / _e293)) * _e309);
                                        if (_e310 >= 0f) {
                                            if (_e311 >= 0f) {
                                                if (_e310 < _e302) {
                                                    let _e315 = (_e311 < _e309);
                                                    if _e315 {
                                                        let _e320 = select(select(u32(_e310), 0u, (_e310 < 0f)), 4294967295u, (_e310 > 4294967000f));
                                                        let _e325 = select(select(u32(_e311), 0u, (_e311 < 0f)), 4294967295u, (_e311 > 4294967000f));
                                                        let _e341 = frame.member[0u].member_1.member_2.member_4;
                                                        if (_e320 >= _e341) {
                                                            if (_e325 >= _e341) {
                                                                let _e345 = ((_e320 + _e341) < select(select(u32(_e302), 0u, (_e302 < 0f)), 4294967295u, (_e302 > 4294967000f)));
                                                                if _e345 {
                                                                    phi_441_ = ((_e325 + _e341) < select(select(u32(_e309), 0u, (_e309 < 0f)), 4294967295u, (_e309 > 4294967000f)));
                                                                } else {
                                                                    phi_441_ = bool();
                                                                }
                                                                let _e349 = phi_441_;
                                                                phi_443_ = _e349;
                                                                phi_444_ = select(true, false, _e345);
                                                            } else {
                                                                phi_443_ = bool();
                                                                phi_444_ = true;
                                                            }
                                                            let _e352 = phi_443_;
                                                            let _e354 = phi_444_;
                                                            phi_445_ = _e352;
                                                            phi_446_ = _e354;
                                                        } else {
                                                            phi_445_ = bool();
                                                            phi_446_ = true;
                                                        }
                                                        let _e356 = phi_445_;
                                                        let _e358 = phi_446_;
                                                        let _e359 = select(_e356, false, _e358);
                                                        if _e359 {
                                                            phi_460_ = type_22(vec2<u32>(_e320, _e325), vec2<f32>(_e310, _e311), _e266, true);
                                                        } else {
                                                            phi_460_ = type_22();
                                                        }
                                                        let _e364 = phi_460_;
                                                        phi_462_ = _e364;
                                                        phi_464_ = select(true, false, _e359);
                                                    } else {
                                                        phi_462_ = type_22();
                                                        phi_464_ = false;
                                                    }
                                                    let _e367 = phi_462_;
                                                    let _e369 = phi_464_;
                                                    phi_465_ = _e367;
                                                    phi_466_ = select(true, false, _e315);
                                                    phi_467_ = _e369;
                                                } else {
                                                    phi_465_ = type_22();
                                                    phi_466_ = true;
                                                    phi_467_ = false;
                                                }
                                                let _e372 = phi_465_;
                                                let _e374 = phi_466_;
                                                let _e376 = phi_467_;
                                                phi_468_ = _e372;
                                                phi_469_ = _e374;
                                                phi_470_ = _e376;
                                            } else {
                                                phi_468_ = type_22();
                                                phi_469_ = true;
                                                phi_470_ = false;
                                            }
                                            let _e378 = phi_468_;
                                            let _e380 = phi_469_;
                                            let _e382 = phi_470_;
                                            phi_471_ = _e378;
                                            phi_472_ = _e380;
                                            phi_473_ = _e382;
                                        } else {
                                            phi_471_ = type_22();
                                            phi_472_ = true;
                                            phi_473_ = false;
                                        }
                                        let _e384 = phi_471_;
                                        let _e386 = phi_472_;
                                        let _e388 = phi_473_;
                                        phi_481_ = _e384;
                                        phi_482_ = select(_e388, true, _e386);
                                    }
                                    let _e391 = phi_481_;
                                    let _e393 = phi_482_;
                                    phi_483_ = _e391;
                                    phi_484_ = _e274;
                                    phi_485_ = _e393;
                                }
                                let _e395 = phi_483_;
                                let _e397 = phi_484_;
                                let _e399 = phi_485_;
                                phi_493_ = _e395;
                                phi_494_ = select(_e399, true, _e397);
                            } else {
                                phi_493_ = type_22();
                                phi_494_ = true;
                            }
                            let _e402 = phi_493_;
                            let _e404 = phi_494_;
                            if _e404 {
                                phi_498_ = type_22(vec2<u32>(0u, 0u), vec2<f32>(0f, 0f), 0f, false);
                            } else {
                                phi_498_ = _e402;
                            }
                            let _e406 = phi_498_;
                            if _e406.member_3 {
                                let _e411 = frame.member[0u].member_3;
                                let _e416 = (_e406.member_1.x - 0.5f);
                                let _e417 = (_e406.member_1.y - 0.5f);
                                let _e418 = floor(_e416);
                                let _e419 = floor(_e417);
                                let _e428 = (floor((((_e416 - _e418) * 256f) + 0.5f)) * 0.00390625f);
                                let _e429 = (floor((((_e417 - _e419) * 256f) + 0.5f)) * 0.00390625f);
                                phi_524_ = 0i;
                                phi_527_ = 0f;
                                phi_529_ = 0f;
                                loop {
                                    let _e431 = phi_524_;
                                    let _e433 = phi_527_;
                                    let _e435 = phi_529_;
                                    local = _e433;
                                    local_1 = _e435;
                                    local_2 = _e433;
                                    local_3 = _e433;
                                    let _e436 = (_e431 < 4i);
                                    if _e436 {
                                        let _e437 = (_e431 & 1i);
                                        let _e439 = (_e431 >> bitcast<u32>(1i));
                                        let _e447 = (select(0i, select(select(i32(_e418), i32(-2147483648), (_e418 < -2147483600f)), 2147483647i, (_e418 > 2147483500f)), (_e418 == _e418)) + _e437);
                                        let _e455 = (select(0i, select(select(i32(_e419), i32(-2147483648), (_e419 < -2147483600f)), 2147483647i, (_e419 > 2147483500f)), (_e419 == _e419)) + _e439);
                                        if (_e437 == 0i) {
                                            phi_564_ = (1f - _e428);
                                        } else {
                                            phi_564_ = _e428;
                                        }
                                        let _e459 = phi_564_;
                                        if (_e439 == 0i) {
                                            phi_570_ = (1f - _e429);
                                        } else {
                                            phi_570_ = _e429;
                                        }
                                        let _e463 = phi_570_;
                                        let _e464 = (_e459 * _e463);
                                        if (_e464 > 0f) {
                                            if (_e447 >= 0i) {
                                                if (_e455 >= 0i) {
                                                    let _e468 = bitcast<u32>(_e447);
                                                    let _e469 = bitcast<u32>(_e455);
                                                    let _e476 = frame.member[0u].member_1.member_2.member[0u];
                                                    let _e481 = select(select(u32(_e476), 0u, (_e476 < 0f)), 4294967295u, (_e476 > 4294967000f));
                                                    let _e488 = frame.member[0u].member_1.member_2.member[1u];
                                                    let _e499 = frame.member[0u].member_1.member_2.member_4;
                                                    if (_e468 >= _e499) {
                                                        if (_e469 >= _e499) {
                                                            let _e503 = ((_e468 + _e499) < _e481);
                                                            if _e503 {
                                                                phi_627_ = ((_e469 + _e499) < select(select(u32(_e488), 0u, (_e488 < 0f)), 4294967295u, (_e488 > 4294967000f)));
                                                            } else {
                                                                phi_627_ = bool();
                                                            }
                                                            let _e507 = phi_627_;
                                                            phi_629_ = _e507;
                                                            phi_630_ = select(true, false, _e503);
                                                        } else {
                                                            phi_629_ = bool();
                                                            phi_630_ = true;
                                                        }
                                                        let _e510 = phi_629_;
                                                        let _e512 = phi_630_;
                                                        phi_631_ = _e510;
                                                        phi_632_ = _e512;
                                                    } else {
                                                        phi_631_ = bool();
                                                        phi_632_ = true;
                                                    }
                                                    let _e514 = phi_631_;
                                                    let _e516 = phi_632_;
                                                    if select(_e514, false, _e516) {
                                                        let _e519 = ((_e469 * _e481) + _e468);
                                                        if (_e519 < arrayLength((&history_depth.member))) {
                                                        } else {
                                                            phi_766_ = true;
                                                            break;
                                                        }
                                                        let _e524 = history_depth.member[_e519];
                                                        let _e530 = frame.member[0u].member_1.member_2.member_3;
                                                        if select(false, (_e524 < _e530), (_e524 > 0f)) {
                                                            phi_676_ = (abs((_e524 - _e406.member_2)) <= (_e411 * _e406.member_2));
                                                        } else {
                                                            phi_676_ = false;
                                                        }
                                                        let _e539 = phi_676_;
                                                        if _e539 {
                                                            if (_e519 < arrayLength((&history_ao.member))) {
                                                            } else {
                                                                phi_766_ = true;
                                                                break;
                                                            }
                                                            let _e543 = history_ao.member[_e519];
                                                            phi_690_ = (_e433 + _e464);
                                                            phi_691_ = (_e435 + (_e464 * _e543));
                                                        } else {
                                                            phi_690_ = _e433;
                                                            phi_691_ = _e435;
                                                        }
                                                        let _e548 = phi_690_;
                                                        let _e550 = phi_691_;
                                                        phi_692_ = _e548;
                                                        phi_693_ = _e550;
                                                    } else {
                                                        phi_692_ = _e433;
                                                        phi_693_ = _e435;
                                                    }
                                                    let _e552 = phi_692_;
                                                    let _e554 = phi_693_;
                                                    phi_694_ = _e552;
                                                    phi_695_ = _e554;
                                                } else {
                                                    phi_694_ = _e433;
                                                    phi_695_ = _e435;
                                                }
                                                let _e556 = phi_694_;
                                                let _e558 = phi_695_;
                                                phi_696_ = _e556;
                                                phi_697_ = _e558;
                                            } else {
                                                phi_696_ = _e433;
                                                phi_697_ = _e435;
                                            }
                                            let _e560 = phi_696_;
                                            let _e562 = phi_697_;
                                            phi_698_ = _e560;
                                            phi_699_ = _e562;
                                        } else {
                                            phi_698_ = _e433;
                                            phi_699_ = _e435;
                                        }
                                        let _e564 = phi_698_;
                                        let _e566 = phi_699_;
                                        phi_525_ = (_e431 + 1i);
                                        phi_528_ = _e564;
                                        phi_530_ = _e566;
                                    } else {
                                        phi_525_ = i32();
                                        phi_528_ = f32();
                                        phi_530_ = f32();
                                    }
                                    let _e569 = phi_525_;
                                    let _e571 = phi_528_;
                                    let _e573 = phi_530_;
                                    continue;
                                    continuing {
                                        phi_524_ = _e569;
                                        phi_527_ = _e571;
                                        phi_529_ = _e573;
                                        phi_766_ = false;
                                        break if !(_e436);
                                    }
                                }
                                let _e576 = phi_766_;
                                if _e576 {
                                    break;
                                }
                                let _e578 = local;
                                if (_e578 > 0f) {
                                    let _e581 = local_1;
                                    let _e583 = local_2;
                                    let _e586 = local_3;
                                    phi_708_ = vec2<f32>(_e586, (_e581 / _e583));
                                } else {
                                    phi_708_ = vec2<f32>(0f, 0f);
                                }
                                let _e589 = phi_708_;
                                let _e592 = (_e589.x <= 0f);
                                if _e592 {
                                    phi_720_ = f32();
                                } else {
                                    let _e596 = frame.member[0u].member_2;
                                    phi_720_ = (_e589.y + (_e596 * (_e86 - _e589.y)));
                                }
                                let _e601 = phi_720_;
                                phi_721_ = _e601;
                                phi_722_ = _e592;
                            } else {
                                phi_721_ = f32();
                                phi_722_ = true;
                            }
                            let _e603 = phi_721_;
                            let _e605 = phi_722_;
                            phi_726_ = _e603;
                            phi_728_ = _e605;
                        } else {
                            phi_726_ = f32();
                            phi_728_ = false;
                        }
                        let _e607 = phi_726_;
                        let _e609 = phi_728_;
                        phi_729_ = _e607;
                        phi_730_ = select(true, false, _e115);
                        phi_731_ = _e609;
                    }
                    let _e612 = phi_729_;
                    let _e614 = phi_730_;
                    let _e616 = phi_731_;
                    if (_e82 < arrayLength((&out.member))) {
                    } else {
                        break;
                    }
                    out.member[_e82] = select(_e612, _e86, select(_e616, true, _e614));
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
