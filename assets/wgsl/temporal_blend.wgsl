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
    var phi_668_: bool;
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
                            if (_e119 > 0f) {
                                phi_220_ = (_e119 < _e125);
                            } else {
                                phi_220_ = false;
                            }
                            let _e129 = phi_220_;
                            if _e129 {
                                let _e147 = frame.member[0u].member.member_2.member_1[0u];
                                let _e148 = ((((((f32(_e39.x) + 0.5f) / _e59) * 2f) - 1f) * _e119) * _e147);
                                let _e156 = frame.member[0u].member.member_2.member_1[1u];
                                let _e157 = ((((((f32(_e39.y) + 0.5f) / _e71) * -2f) + 1f) * _e119) * _e156);
                                let _e158 = -(_e119);
                                let _e164 = frame.member[0u].member.member_1.member;
                                let _e176 = frame.member[0u].member.member_1.member_1;
                                let _e191 = frame.member[0u].member.member_1.member_2;
                                let _e206 = frame.member[0u].member.member_1.member_3;
                                let _e208 = (_e206.x + ((_e191.x * _e158) + ((_e176.x * _e157) + (_e164.x * _e148))));
                                let _e210 = (_e206.y + ((_e191.y * _e158) + ((_e176.y * _e157) + (_e164.y * _e148))));
                                let _e212 = (_e206.z + ((_e191.z * _e158) + ((_e176.z * _e157) + (_e164.z * _e148))));
                                let _e218 = frame.member[0u].member_1.member.member;
                                let _e230 = frame.member[0u].member_1.member.member_1;
                                let _e245 = frame.member[0u].member_1.member.member_2;
                                let _e260 = frame.member[0u].member_1.member.member_3;
                                let _e266 = (_e260.z + ((_e245.z * _e212) + ((_e230.z * _e210) + (_e218.z * _e208))));
                                let _e267 = -(_e266);
                                if (_e267 != _e267) {
                                    phi_483_ = type_22();
                                    phi_484_ = true;
                                    phi_485_ = false;
                                } else {
                                    let _e274 = frame.member[0u].member_1.member_2.member_2;
                                    let _e275 = (_e267 <= _e274);
                                    if _e275 {
                                        phi_481_ = type_22();
                                        phi_482_ = false;
                                    } else {
                                        let _e276 = (-0.5f / _e266);
                                        let _e284 = frame.member[0u].member_1.member_2.member_1[0u];
                                        let _e294 = frame.member[0u].member_1.member_2.member_1[1u];
                                        let _e303 = frame.member[0u].member_1.member_2.member[0u];
                                        let _e310 = frame.member[0u].member_1.member_2.member[1u];
                                        let _e311 = (((((_e260.x + ((_e245.x * _e212) + ((_e230.x * _e210) + (_e218.x * _e208)))) * _e276) / _e284) + 0.5f) * _e303);
                                        let _e312 = ((0.5f - (((_e260.y + ((_e245.y * _e212) + ((_e230.y * _e210) + (_e218.y * _e208)))) * _e276) / _e294)) * _e310);
                                        if (_e311 >= 0f) {
                                            if (_e312 >= 0f) {
                                                if (_e311 < _e303) {
                                                    let _e316 = (_e312 < _e310);
                                                    if _e316 {
                                                        let _e321 = select(select(u32(_e311), 0u, (_e311 < 0f)), 4294967295u, (_e311 > 4294967000f));
                                                        let _e326 = select(select(u32(_e312), 0u, (_e312 < 0f)), 4294967295u, (_e312 > 4294967000f));
                                                        let _e342 = frame.member[0u].member_1.member_2.member_4;
                                                        if (_e321 >= _e342) {
                                                            if (_e326 >= _e342) {
                                                                let _e346 = ((_e321 + _e342) < select(select(u32(_e303), 0u, (_e303 < 0f)), 4294967295u, (_e303 > 4294967000f)));
                                                                if _e346 {
                                                                    phi_441_ = ((_e326 + _e342) < select(select(u32(_e310), 0u, (_e310 < 0f)), 4294967295u, (_e310 > 4294967000f)));
                                                                } else {
                                                                    phi_441_ = bool();
                                                                }
                                                                let _e350 = phi_441_;
                                                                phi_443_ = _e350;
                                                                phi_444_ = select(true, false, _e346);
                                                            } else {
                                                                phi_443_ = bool();
                                                                phi_444_ = true;
                                                            }
                                                            let _e353 = phi_443_;
                                                            let _e355 = phi_444_;
                                                            phi_445_ = _e353;
                                                            phi_446_ = _e355;
                                                        } else {
                                                            phi_445_ = bool();
                                                            phi_446_ = true;
                                                        }
                                                        let _e357 = phi_445_;
                                                        let _e359 = phi_446_;
                                                        let _e360 = select(_e357, false, _e359);
                                                        if _e360 {
                                                            phi_460_ = type_22(vec2<u32>(_e321, _e326), vec2<f32>(_e311, _e312), _e267, true);
                                                        } else {
                                                            phi_460_ = type_22();
                                                        }
                                                        let _e365 = phi_460_;
                                                        phi_462_ = _e365;
                                                        phi_464_ = select(true, false, _e360);
                                                    } else {
                                                        phi_462_ = type_22();
                                                        phi_464_ = false;
                                                    }
                                                    let _e368 = phi_462_;
                                                    let _e370 = phi_464_;
                                                    phi_465_ = _e368;
                                                    phi_466_ = select(true, false, _e316);
                                                    phi_467_ = _e370;
                                                } else {
                                                    phi_465_ = type_22();
                                                    phi_466_ = true;
                                                    phi_467_ = false;
                                                }
                                                let _e373 = phi_465_;
                                                let _e375 = phi_466_;
                                                let _e377 = phi_467_;
                                                phi_468_ = _e373;
                                                phi_469_ = _e375;
                                                phi_470_ = _e377;
                                            } else {
                                                phi_468_ = type_22();
                                                phi_469_ = true;
                                                phi_470_ = false;
                                            }
                                            let _e379 = phi_468_;
                                            let _e381 = phi_469_;
                                            let _e383 = phi_470_;
                                            phi_471_ = _e379;
                                            phi_472_ = _e381;
                                            phi_473_ = _e383;
                                        } else {
                                            phi_471_ = type_22();
                                            phi_472_ = true;
                                            phi_473_ = false;
                                        }
                                        let _e385 = phi_471_;
                                        let _e387 = phi_472_;
                                        let _e389 = phi_473_;
                                        phi_481_ = _e385;
                                        phi_482_ = select(_e389, true, _e387);
                                    }
                                    let _e392 = phi_481_;
                                    let _e394 = phi_482_;
                                    phi_483_ = _e392;
                                    phi_484_ = _e275;
                                    phi_485_ = _e394;
                                }
                                let _e396 = phi_483_;
                                let _e398 = phi_484_;
                                let _e400 = phi_485_;
                                phi_493_ = _e396;
                                phi_494_ = select(_e400, true, _e398);
                            } else {
                                phi_493_ = type_22();
                                phi_494_ = true;
                            }
                            let _e403 = phi_493_;
                            let _e405 = phi_494_;
                            if _e405 {
                                phi_498_ = type_22(vec2<u32>(0u, 0u), vec2<f32>(0f, 0f), 0f, false);
                            } else {
                                phi_498_ = _e403;
                            }
                            let _e407 = phi_498_;
                            if _e407.member_3 {
                                let _e412 = frame.member[0u].member_3;
                                let _e417 = (_e407.member_1.x - 0.5f);
                                let _e418 = (_e407.member_1.y - 0.5f);
                                let _e419 = floor(_e417);
                                let _e420 = floor(_e418);
                                let _e429 = (floor((((_e417 - _e419) * 256f) + 0.5f)) * 0.00390625f);
                                let _e430 = (floor((((_e418 - _e420) * 256f) + 0.5f)) * 0.00390625f);
                                phi_524_ = 0i;
                                phi_527_ = 0f;
                                phi_529_ = 0f;
                                loop {
                                    let _e432 = phi_524_;
                                    let _e434 = phi_527_;
                                    let _e436 = phi_529_;
                                    local = _e434;
                                    local_1 = _e436;
                                    local_2 = _e434;
                                    local_3 = _e434;
                                    let _e437 = (_e432 < 4i);
                                    if _e437 {
                                        let _e438 = (_e432 & 1i);
                                        let _e440 = (_e432 >> bitcast<u32>(1i));
                                        let _e448 = (select(0i, select(select(i32(_e419), i32(-2147483648), (_e419 < -2147483600f)), 2147483647i, (_e419 > 2147483500f)), (_e419 == _e419)) + _e438);
                                        let _e456 = (select(0i, select(select(i32(_e420), i32(-2147483648), (_e420 < -2147483600f)), 2147483647i, (_e420 > 2147483500f)), (_e420 == _e420)) + _e440);
                                        if (_e438 == 0i) {
                                            phi_564_ = (1f - _e429);
                                        } else {
                                            phi_564_ = _e429;
                                        }
                                        let _e460 = phi_564_;
                                        if (_e440 == 0i) {
                                            phi_570_ = (1f - _e430);
                                        } else {
                                            phi_570_ = _e430;
                                        }
                                        let _e464 = phi_570_;
                                        let _e465 = (_e460 * _e464);
                                        if (_e465 > 0f) {
                                            if (_e448 >= 0i) {
                                                if (_e456 >= 0i) {
                                                    let _e469 = bitcast<u32>(_e448);
                                                    let _e470 = bitcast<u32>(_e456);
                                                    let _e477 = frame.member[0u].member_1.member_2.member[0u];
                                                    let _e482 = select(select(u32(_e477), 0u, (_e477 < 0f)), 4294967295u, (_e477 > 4294967000f));
                                                    let _e489 = frame.member[0u].member_1.member_2.member[1u];
                                                    let _e500 = frame.member[0u].member_1.member_2.member_4;
                                                    if (_e469 >= _e500) {
                                                        if (_e470 >= _e500) {
                                                            let _e504 = ((_e469 + _e500) < _e482);
                                                            if _e504 {
                                                                phi_627_ = ((_e470 + _e500) < select(select(u32(_e489), 0u, (_e489 < 0f)), 4294967295u, (_e489 > 4294967000f)));
                                                            } else {
                                                                phi_627_ = bool();
                                                            }
                                                            let _e508 = phi_627_;
                                                            phi_629_ = _e508;
                                                            phi_630_ = select(true, false, _e504);
                                                        } else {
                                                            phi_629_ = bool();
                                                            phi_630_ = true;
                                                        }
                                                        let _e511 = phi_629_;
                                                        let _e513 = phi_630_;
                                                        phi_631_ = _e511;
                                                        phi_632_ = _e513;
                                                    } else {
                                                        phi_631_ = bool();
                                                        phi_632_ = true;
                                                    }
                                                    let _e515 = phi_631_;
                                                    let _e517 = phi_632_;
                                                    if select(_e515, false, _e517) {
                                                        let _e520 = ((_e470 * _e482) + _e469);
                                                        if (_e520 < arrayLength((&history_depth.member))) {
                                                        } else {
                                                            phi_766_ = true;
                                                            break;
                                                        }
                                                        let _e525 = history_depth.member[_e520];
                                                        let _e531 = frame.member[0u].member_1.member_2.member_3;
                                                        if (_e525 > 0f) {
                                                            phi_668_ = (_e525 < _e531);
                                                        } else {
                                                            phi_668_ = false;
                                                        }
                                                        let _e535 = phi_668_;
                                                        if _e535 {
                                                            phi_676_ = (abs((_e525 - _e407.member_2)) <= (_e412 * _e407.member_2));
                                                        } else {
                                                            phi_676_ = false;
                                                        }
                                                        let _e541 = phi_676_;
                                                        if _e541 {
                                                            if (_e520 < arrayLength((&history_ao.member))) {
                                                            } else {
                                                                phi_766_ = true;
                                                                break;
                                                            }
                                                            let _e545 = history_ao.member[_e520];
                                                            phi_690_ = (_e434 + _e465);
                                                            phi_691_ = (_e436 + (_e465 * _e545));
                                                        } else {
                                                            phi_690_ = _e434;
                                                            phi_691_ = _e436;
                                                        }
                                                        let _e550 = phi_690_;
                                                        let _e552 = phi_691_;
                                                        phi_692_ = _e550;
                                                        phi_693_ = _e552;
                                                    } else {
                                                        phi_692_ = _e434;
                                                        phi_693_ = _e436;
                                                    }
                                                    let _e554 = phi_692_;
                                                    let _e556 = phi_693_;
                                                    phi_694_ = _e554;
                                                    phi_695_ = _e556;
                                                } else {
                                                    phi_694_ = _e434;
                                                    phi_695_ = _e436;
                                                }
                                                let _e558 = phi_694_;
                                                let _e560 = phi_695_;
                                                phi_696_ = _e558;
                                                phi_697_ = _e560;
                                            } else {
                                                phi_696_ = _e434;
                                                phi_697_ = _e436;
                                            }
                                            let _e562 = phi_696_;
                                            let _e564 = phi_697_;
                                            phi_698_ = _e562;
                                            phi_699_ = _e564;
                                        } else {
                                            phi_698_ = _e434;
                                            phi_699_ = _e436;
                                        }
                                        let _e566 = phi_698_;
                                        let _e568 = phi_699_;
                                        phi_525_ = (_e432 + 1i);
                                        phi_528_ = _e566;
                                        phi_530_ = _e568;
                                    } else {
                                        phi_525_ = i32();
                                        phi_528_ = f32();
                                        phi_530_ = f32();
                                    }
                                    let _e571 = phi_525_;
                                    let _e573 = phi_528_;
                                    let _e575 = phi_530_;
                                    continue;
                                    continuing {
                                        phi_524_ = _e571;
                                        phi_527_ = _e573;
                                        phi_529_ = _e575;
                                        phi_766_ = false;
                                        break if !(_e437);
                                    }
                                }
                                let _e578 = phi_766_;
                                if _e578 {
                                    break;
                                }
                                let _e580 = local;
                                if (_e580 > 0f) {
                                    let _e583 = local_1;
                                    let _e585 = local_2;
                                    let _e588 = local_3;
                                    phi_708_ = vec2<f32>(_e588, (_e583 / _e585));
                                } else {
                                    phi_708_ = vec2<f32>(0f, 0f);
                                }
                                let _e591 = phi_708_;
                                let _e594 = (_e591.x <= 0f);
                                if _e594 {
                                    phi_720_ = f32();
                                } else {
                                    let _e598 = frame.member[0u].member_2;
                                    phi_720_ = (_e591.y + (_e598 * (_e86 - _e591.y)));
                                }
                                let _e603 = phi_720_;
                                phi_721_ = _e603;
                                phi_722_ = _e594;
                            } else {
                                phi_721_ = f32();
                                phi_722_ = true;
                            }
                            let _e605 = phi_721_;
                            let _e607 = phi_722_;
                            phi_726_ = _e605;
                            phi_728_ = _e607;
                        } else {
                            phi_726_ = f32();
                            phi_728_ = false;
                        }
                        let _e609 = phi_726_;
                        let _e611 = phi_728_;
                        phi_729_ = _e609;
                        phi_730_ = select(true, false, _e115);
                        phi_731_ = _e611;
                    }
                    let _e614 = phi_729_;
                    let _e616 = phi_730_;
                    let _e618 = phi_731_;
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
