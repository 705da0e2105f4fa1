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
    var phi_220_: bool;
    var phi_439_: bool;
    var phi_441_: bool;
    var phi_442_: bool;
    var phi_443_: bool;
    var phi_444_: bool;
    var phi_458_: type_22;
    var phi_460_: type_22;
    var phi_462_: bool;
    var phi_463_: type_22;
    var phi_464_: bool;
    var phi_465_: bool;
    var phi_466_: type_22;
    var phi_467_: bool;
    var phi_468_: bool;
    var phi_469_: type_22;
    var phi_470_: bool;
    var phi_471_: bool;
    var phi_479_: type_22;
    var phi_480_: bool;
    var phi_481_: type_22;
    var phi_482_: bool;
    var phi_483_: bool;
    var phi_491_: type_22;
    var phi_492_: bool;
    var phi_496_: type_22;
    var phi_522_: i32;
    var phi_525_: f32;
    var phi_527_: f32;
    var phi_562_: f32;
    var phi_568_: f32;
    var phi_625_: bool;
    var phi_627_: bool;
    var phi_628_: bool;
    var phi_629_: bool;
    var phi_630_: bool;
    var phi_666_: bool;
    var phi_674_: bool;
    var phi_688_: f32;
    var phi_689_: f32;
    var phi_690_: f32;
    var phi_691_: f32;
    var phi_692_: f32;
    var phi_693_: f32;
    var phi_694_: f32;
    var phi_695_: f32;
    var phi_696_: f32;
    var phi_697_: f32;
    var phi_523_: i32;
    var phi_526_: f32;
    var phi_528_: f32;
    var phi_764_: bool;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_706_: vec2<f32>;
    var phi_718_: f32;
    var phi_719_: f32;
    var phi_720_: bool;
    var phi_724_: f32;
    var phi_726_: bool;
    var phi_727_: f32;
    var phi_728_: bool;
    var phi_729_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e38 = id_1;
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e58 = frame.member[0u].member.member_2.member[0u];
            let _e63 = select(select(u32(_e58), 0u, (_e58 < 0f)), 4294967295u, (_e58 > 4294967000f));
            let _e70 = frame.member[0u].member.member_2.member[1u];
            let _e75 = select(select(u32(_e70), 0u, (_e70 < 0f)), 4294967295u, (_e70 > 4294967000f));
            if (_e38.x >= _e63) {
            } else {
                if (_e38.y >= _e75) {
                } else {
                    let _e81 = ((_e38.y * _e63) + _e38.x);
                    if (_e81 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    let _e85 = ao.member[_e81];
                    let _e89 = frame.member[0u].member_4;
                    if (_e89 == 0u) {
                        phi_727_ = f32();
                        phi_728_ = true;
                        phi_729_ = false;
                    } else {
                        let _e96 = frame.member[0u].member.member_2.member_4;
                        if (_e38.x >= _e96) {
                            if (_e38.y >= _e96) {
                                let _e100 = ((_e38.x + _e96) < _e63);
                                if _e100 {
                                    phi_183_ = ((_e38.y + _e96) < _e75);
                                } else {
                                    phi_183_ = bool();
                                }
                                let _e104 = phi_183_;
                                phi_185_ = _e104;
                                phi_186_ = select(true, false, _e100);
                            } else {
                                phi_185_ = bool();
                                phi_186_ = true;
                            }
                            let _e107 = phi_185_;
                            let _e109 = phi_186_;
                            phi_187_ = _e107;
                            phi_188_ = _e109;
                        } else {
                            phi_187_ = bool();
                            phi_188_ = true;
                        }
                        let _e111 = phi_187_;
                        let _e113 = phi_188_;
                        let _e114 = select(_e111, false, _e113);
                        if _e114 {
                            if (_e81 < arrayLength((&depth.member))) {
                            } else {
                                break;
                            }
                            let _e118 = depth.member[_e81];
                            let _e124 = frame.member[0u].member.member_2.member_3;
                            if (_e118 > 0f) {
                                phi_220_ = (_e118 < _e124);
                            } else {
                                phi_220_ = false;
                            }
                            let _e128 = phi_220_;
                            if _e128 {
                                let _e146 = frame.member[0u].member.member_2.member_1[0u];
                                let _e147 = ((((2f * ((f32(_e38.x) + 0.5f) / _e58)) - 1f) * _e118) * _e146);
                                let _e155 = frame.member[0u].member.member_2.member_1[1u];
                                let _e156 = (((1f - (2f * ((f32(_e38.y) + 0.5f) / _e70))) * _e118) * _e155);
                                let _e157 = -(_e118);
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
                                    phi_481_ = type_22();
                                    phi_482_ = true;
                                    phi_483_ = false;
                                } else {
                                    let _e273 = frame.member[0u].member_1.member_2.member_2;
                                    let _e274 = (_e266 <= _e273);
                                    if _e274 {
                                        phi_479_ = type_22();
                                        phi_480_ = false;
                                    } else {
                                        let _e275 = (-0.5f / _e265);
                                        let _e283 = frame.member[0u].member_1.member_2.member_1[0u];
                                        let _e293 = frame.member[0u].member_1.member_2.member_1[1u];
                                        let _e302 = frame.member[0u].member_1.member_2.member[0u];
                                        let _e309 = frame.member[0u].member_1.member_2.member[1u];
                                        let _e310 = ((0.5f + (((_e259.x + ((_e244.x * _e211) + ((_e229.x * _e209) + (_e217.x * _e207)))) * _e275) / _e283)) * _e302);
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
                                                                    phi_439_ = ((_e325 + _e341) < select(select(u32(_e309), 0u, (_e309 < 0f)), 4294967295u, (_e309 > 4294967000f)));
                                                                } else {
                                                                    phi_439_ = bool();
                                                                }
                                                                let _e349 = phi_439_;
                                                                phi_441_ = _e349;
                                                                phi_442_ = select(true, false, _e345);
                                                            } else {
                                                                phi_441_ = bool();
                                                                phi_442_ = true;
                                                            }
                                                            let _e352 = phi_441_;
                                                            let _e354 = phi_442_;
                                                            phi_443_ = _e352;
                                                            phi_444_ = _e354;
                                                        } else {
                                                            phi_443_ = bool();
                                                            phi_444_ = true;
                                                        }
                                                        let _e356 = phi_443_;
                                                        let _e358 = phi_444_;
                                                        let _e359 = select(_e356, false, _e358);
                                                        if _e359 {
                                                            phi_458_ = type_22(vec2<u32>(_e320, _e325), vec2<f32>(_e310, _e311), _e266, true);
                                                        } else {
                                                            phi_458_ = type_22();
                                                        }
                                                        let _e364 = phi_458_;
                                                        phi_460_ = _e364;
                                                        phi_462_ = select(true, false, _e359);
                                                    } else {
                                                        phi_460_ = type_22();
                                                        phi_462_ = false;
                                                    }
                                                    let _e367 = phi_460_;
                                                    let _e369 = phi_462_;
                                                    phi_463_ = _e367;
                                                    phi_464_ = select(true, false, _e315);
                                                    phi_465_ = _e369;
                                                } else {
                                                    phi_463_ = type_22();
                                                    phi_464_ = true;
                                                    phi_465_ = false;
                                                }
                                                let _e372 = phi_463_;
                                                let _e374 = phi_464_;
                                                let _e376 = phi_465_;
                                                phi_466_ = _e372;
                                                phi_467_ = _e374;
                                                phi_468_ = _e376;
                                            } else {
                                                phi_466_ = type_22();
                                                phi_467_ = true;
                                                phi_468_ = false;
                                            }
                                            let _e378 = phi_466_;
                                            let _e380 = phi_467_;
                                            let _e382 = phi_468_;
                                            phi_469_ = _e378;
                                            phi_470_ = _e380;
                                            phi_471_ = _e382;
                                        } else {
                                            phi_469_ = type_22();
                                            phi_470_ = true;
                                            phi_471_ = false;
                                        }
                                        let _e384 = phi_469_;
                                        let _e386 = phi_470_;
                                        let _e388 = phi_471_;
                                        phi_479_ = _e384;
                                        phi_480_ = select(_e388, true, _e386);
                                    }
                                    let _e391 = phi_479_;
                                    let _e393 = phi_480_;
                                    phi_481_ = _e391;
                                    phi_482_ = _e274;
                                    phi_483_ = _e393;
                                }
                                let _e395 = phi_481_;
                                let _e397 = phi_482_;
                                let _e399 = phi_483_;
                                phi_491_ = _e395;
                                phi_492_ = select(_e399, true, _e397);
                            } else {
                                phi_491_ = type_22();
                                phi_492_ = true;
                            }
                            let _e402 = phi_491_;
                            let _e404 = phi_492_;
                            if _e404 {
                                phi_496_ = type_22(vec2<u32>(0u, 0u), vec2<f32>(0f, 0f), 0f, false);
                            } else {
                                phi_496_ = _e402;
                            }
                            let _e406 = phi_496_;
                            if _e406.member_3 {
                                let _e411 = frame.member[0u].member_3;
                                let _e416 = (_e406.member_1.x - 0.5f);
                                let _e417 = (_e406.member_1.y - 0.5f);
                                let _e418 = floor(_e416);
                                let _e419 = floor(_e417);
                                let _e428 = (floor((((_e416 - _e418) * 256f) + 0.5f)) * 0.00390625f);
                                let _e429 = (floor((((_e417 - _e419) * 256f) + 0.5f)) * 0.00390625f);
                                phi_522_ = 0i;
                                phi_525_ = 0f;
                                phi_527_ = 0f;
                                loop {
                                    let _e431 = phi_522_;
                                    let _e433 = phi_525_;
                                    let _e435 = phi_527_;
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
                                            phi_562_ = (1f - _e428);
                                        } else {
                                            phi_562_ = _e428;
                                        }
                                        let _e459 = phi_562_;
                                        if (_e439 == 0i) {
                                            phi_568_ = (1f - _e429);
                                        } else {
                                            phi_568_ = _e429;
                                        }
                                        let _e463 = phi_568_;
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
                                                                phi_625_ = ((_e469 + _e499) < select(select(u32(_e488), 0u, (_e488 < 0f)), 4294967295u, (_e488 > 4294967000f)));
                                                            } else {
                                                                phi_625_ = bool();
                                                            }
                                                            let _e507 = phi_625_;
                                                            phi_627_ = _e507;
                                                            phi_628_ = select(true, false, _e503);
                                                        } else {
                                                            phi_627_ = bool();
                                                            phi_628_ = true;
                                                        }
                                                        let _e510 = phi_627_;
                                                        let _e512 = phi_628_;
                                                        phi_629_ = _e510;
                                                        phi_630_ = _e512;
                                                    } else {
                                                        phi_629_ = bool();
                                                        phi_630_ = true;
                                                    }
                                                    let _e514 = phi_629_;
                                                    let _e516 = phi_630_;
                                                    if select(_e514, false, _e516) {
                                                        let _e519 = ((_e469 * _e481) + _e468);
                                                        if (_e519 < arrayLength((&history_depth.member))) {
                                                        } else {
                                                            phi_764_ = true;
                                                            break;
                                                        }
                                                        let _e524 = history_depth.member[_e519];
                                                        let _e530 = frame.member[0u].member_1.member_2.member_3;
                                                        if (_e524 > 0f) {
                                                            phi_666_ = (_e524 < _e530);
                                                        } else {
                                                            phi_666_ = false;
                                                        }
                                                        let _e534 = phi_666_;
                                                        if _e534 {
                                                            phi_674_ = (abs((_e524 - _e406.member_2)) <= (_e411 * _e406.member_2));
                                                        } else {
                                                            phi_674_ = false;
                                                        }
                                                        let _e540 = phi_674_;
                                                        if _e540 {
                                                            if (_e519 < arrayLength((&history_ao.member))) {
                                                            } else {
                                                                phi_764_ = true;
                                                                break;
                                                            }
                                                            let _e544 = history_ao.member[_e519];
                                                            phi_688_ = (_e433 + _e464);
                                                            phi_689_ = (_e435 + (_e464 * _e544));
                                                        } else {
                                                            phi_688_ = _e433;
                                                            phi_689_ = _e435;
                                                        }
                                                        let _e549 = phi_688_;
                                                        let _e551 = phi_689_;
                                                        phi_690_ = _e549;
                                                        phi_691_ = _e551;
                                                    } else {
                                                        phi_690_ = _e433;
                                                        phi_691_ = _e435;
                                                    }
                                                    let _e553 = phi_690_;
                                                    let _e555 = phi_691_;
                                                    phi_692_ = _e553;
                                                    phi_693_ = _e555;
                                                } else {
                                                    phi_692_ = _e433;
                                                    phi_693_ = _e435;
                                                }
                                                let _e557 = phi_692_;
                                                let _e559 = phi_693_;
                                                phi_694_ = _e557;
                                                phi_695_ = _e559;
                                            } else {
                                                phi_694_ = _e433;
                                                phi_695_ = _e435;
                                            }
                                            let _e561 = phi_694_;
                                            let _e563 = phi_695_;
                                            phi_696_ = _e561;
                                            phi_697_ = _e563;
                                        } else {
                                            phi_696_ = _e433;
                                            phi_697_ = _e435;
                                        }
                                        let _e565 = phi_696_;
                                        let _e567 = phi_697_;
                                        phi_523_ = (_e431 + 1i);
                                        phi_526_ = _e565;
                                        phi_528_ = _e567;
                                    } else {
                                        phi_523_ = i32();
                                        phi_526_ = f32();
                                        phi_528_ = f32();
                                    }
                                    let _e570 = phi_523_;
                                    let _e572 = phi_526_;
                                    let _e574 = phi_528_;
                                    continue;
                                    continuing {
                                        phi_522_ = _e570;
                                        phi_525_ = _e572;
                                        phi_527_ = _e574;
                                        phi_764_ = false;
                                        break if !(_e436);
                                    }
                                }
                                let _e577 = phi_764_;
                                if _e577 {
                                    break;
                                }
                                let _e579 = local;
                                if (_e579 > 0f) {
                                    let _e582 = local_1;
                                    let _e584 = local_2;
                                    let _e587 = local_3;
                                    phi_706_ = vec2<f32>(_e587, (_e582 / _e584));
                                } else {
                                    phi_706_ = vec2<f32>(0f, 0f);
                                }
                                let _e590 = phi_706_;
                                let _e593 = (_e590.x <= 0f);
                                if _e593 {
                                    phi_718_ = f32();
                                } else {
                                    let _e597 = frame.member[0u].member_2;
                                    phi_718_ = (_e590.y + (_e597 * (_e85 - _e590.y)));
                                }
                                let _e602 = phi_718_;
                                phi_719_ = _e602;
                                phi_720_ = _e593;
                            } else {
                                phi_719_ = f32();
                                phi_720_ = true;
                            }
                            let _e604 = phi_719_;
                            let _e606 = phi_720_;
                            phi_724_ = _e604;
                            phi_726_ = _e606;
                        } else {
                            phi_724_ = f32();
                            phi_726_ = false;
                        }
                        let _e608 = phi_724_;
                        let _e610 = phi_726_;
                        phi_727_ = _e608;
                        phi_728_ = select(true, false, _e114);
                        phi_729_ = _e610;
                    }
                    let _e613 = phi_727_;
                    let _e615 = phi_728_;
                    let _e617 = phi_729_;
                    if (_e81 < arrayLength((&out.member))) {
                    } else {
                        break;
                    }
                    out.member[_e81] = select(_e613, _e85, select(_e617, true, _e615));
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
