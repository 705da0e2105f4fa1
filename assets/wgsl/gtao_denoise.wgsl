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
    member_1: f32,
    member_2: bool,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(4) 
var<uniform> params: type_20;
@group(0) @binding(0) 
var<storage> terms_in: type_10;
@group(0) @binding(1) 
var<storage> edges: type_10;
@group(0) @binding(2) 
var<storage, read_write> terms_out: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;

fn function_() {
    var phi_155_: f32;
    var phi_173_: i32;
    var phi_192_: i32;
    var phi_211_: i32;
    var phi_230_: i32;
    var phi_249_: i32;
    var phi_268_: i32;
    var phi_287_: i32;
    var phi_306_: i32;
    var phi_430_: f32;
    var phi_443_: f32;
    var phi_454_: f32;
    var phi_465_: f32;
    var phi_476_: f32;
    var phi_511_: i32;
    var phi_530_: i32;
    var phi_549_: i32;
    var phi_568_: i32;
    var phi_587_: i32;
    var phi_606_: i32;
    var phi_625_: i32;
    var phi_644_: i32;
    var phi_846_: u32;
    var phi_1171_: vec3<f32>;
    var phi_1282_: f32;
    var phi_1303_: f32;
    var phi_1324_: f32;
    var phi_1345_: f32;
    var phi_1366_: f32;
    var phi_1387_: f32;
    var phi_1408_: f32;
    var phi_1429_: f32;
    var phi_1221_: type_22;
    var phi_1222_: type_22;

    switch bitcast<i32>(0u) {
        default: {
            let _e41 = id_1;
            let _e43 = arrayLength((&terms_in.member));
            let _e45 = arrayLength((&edges.member));
            let _e54 = params.member.member.member[0u];
            let _e59 = select(select(u32(_e54), 0u, (_e54 < 0f)), 4294967295u, (_e54 > 4294967000f));
            let _e64 = params.member.member.member[1u];
            let _e69 = select(select(u32(_e64), 0u, (_e64 < 0f)), 4294967295u, (_e64 > 4294967000f));
            if (_e41.x >= _e59) {
            } else {
                if (_e41.y >= _e69) {
                } else {
                    let _e76 = params.member.member_10;
                    let _e81 = params.member.member_12;
                    let _e83 = ((_e81 + 1u) >= select(1u, _e76, (1u < _e76)));
                    if (_e76 == 0u) {
                        phi_155_ = 10000f;
                    } else {
                        phi_155_ = select(0.24000001f, 1.2f, _e83);
                    }
                    let _e87 = phi_155_;
                    let _e88 = bitcast<i32>(_e41.x);
                    let _e89 = (_e88 + -1i);
                    let _e91 = (bitcast<i32>(_e59) - 1i);
                    let _e92 = (0i <= _e91);
                    if _e92 {
                    } else {
                        break;
                    }
                    let _e93 = (_e89 < 0i);
                    if _e93 {
                        phi_173_ = 0i;
                    } else {
                        phi_173_ = select(_e89, _e91, (_e89 > _e91));
                    }
                    let _e97 = phi_173_;
                    let _e99 = bitcast<i32>(_e41.y);
                    let _e101 = (bitcast<i32>(_e69) - 1i);
                    let _e102 = (0i <= _e101);
                    if _e102 {
                    } else {
                        break;
                    }
                    let _e103 = (_e99 < 0i);
                    if _e103 {
                        phi_192_ = 0i;
                    } else {
                        phi_192_ = select(_e99, _e101, (_e99 > _e101));
                    }
                    let _e107 = phi_192_;
                    let _e109 = (_e88 + 1i);
                    if _e92 {
                    } else {
                        break;
                    }
                    let _e110 = (_e109 < 0i);
                    if _e110 {
                        phi_211_ = 0i;
                    } else {
                        phi_211_ = select(_e109, _e91, (_e109 > _e91));
                    }
                    let _e114 = phi_211_;
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e103 {
                        phi_230_ = 0i;
                    } else {
                        phi_230_ = select(_e99, _e101, (_e99 > _e101));
                    }
                    let _e119 = phi_230_;
                    if _e92 {
                    } else {
                        break;
                    }
                    let _e121 = (_e88 < 0i);
                    if _e121 {
                        phi_249_ = 0i;
                    } else {
                        phi_249_ = select(_e88, _e91, (_e88 > _e91));
                    }
                    let _e125 = phi_249_;
                    let _e127 = (_e99 + -1i);
                    if _e102 {
                    } else {
                        break;
                    }
                    let _e128 = (_e127 < 0i);
                    if _e128 {
                        phi_268_ = 0i;
                    } else {
                        phi_268_ = select(_e127, _e101, (_e127 > _e101));
                    }
                    let _e132 = phi_268_;
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e121 {
                        phi_287_ = 0i;
                    } else {
                        phi_287_ = select(_e88, _e91, (_e88 > _e91));
                    }
                    let _e137 = phi_287_;
                    let _e139 = (_e99 + 1i);
                    if _e102 {
                    } else {
                        break;
                    }
                    let _e140 = (_e139 < 0i);
                    if _e140 {
                        phi_306_ = 0i;
                    } else {
                        phi_306_ = select(_e139, _e101, (_e139 > _e101));
                    }
                    let _e144 = phi_306_;
                    let _e147 = ((bitcast<u32>(_e107) * _e59) + bitcast<u32>(_e97));
                    if (_e147 < _e45) {
                    } else {
                        break;
                    }
                    let _e151 = edges.member[_e147];
                    let _e166 = ((bitcast<u32>(_e119) * _e59) + bitcast<u32>(_e114));
                    if (_e166 < _e45) {
                    } else {
                        break;
                    }
                    let _e170 = edges.member[_e166];
                    let _e185 = ((bitcast<u32>(_e132) * _e59) + bitcast<u32>(_e125));
                    if (_e185 < _e45) {
                    } else {
                        break;
                    }
                    let _e189 = edges.member[_e185];
                    let _e204 = ((bitcast<u32>(_e144) * _e59) + bitcast<u32>(_e137));
                    if (_e204 < _e45) {
                    } else {
                        break;
                    }
                    let _e208 = edges.member[_e204];
                    let _e225 = ((_e41.y * _e59) + _e41.x);
                    if (_e225 < _e45) {
                    } else {
                        break;
                    }
                    let _e229 = edges.member[_e225];
                    let _e248 = ((f32(((_e229 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f) * (f32(((_e151 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f));
                    let _e249 = ((f32(((_e229 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f) * (f32(((_e170 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f));
                    let _e250 = ((f32(((_e229 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f) * (f32((_e189 & 3u)) * 0.33333334f));
                    let _e251 = ((f32((_e229 & 3u)) * 0.33333334f) * (f32(((_e208 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f));
                    let _e255 = (1.5f - (((_e248 + _e249) + _e250) + _e251));
                    if (_e255 > 0f) {
                        phi_430_ = select(1f, _e255, (_e255 < 1f));
                    } else {
                        phi_430_ = 0f;
                    }
                    let _e260 = phi_430_;
                    let _e261 = (_e260 * 0.33333334f);
                    let _e262 = (_e248 + _e261);
                    if (_e262 > 0f) {
                        phi_443_ = select(1f, _e262, (_e262 < 1f));
                    } else {
                        phi_443_ = 0f;
                    }
                    let _e267 = phi_443_;
                    let _e268 = (_e249 + _e261);
                    if (_e268 > 0f) {
                        phi_454_ = select(1f, _e268, (_e268 < 1f));
                    } else {
                        phi_454_ = 0f;
                    }
                    let _e273 = phi_454_;
                    let _e274 = (_e250 + _e261);
                    if (_e274 > 0f) {
                        phi_465_ = select(1f, _e274, (_e274 < 1f));
                    } else {
                        phi_465_ = 0f;
                    }
                    let _e279 = phi_465_;
                    let _e280 = (_e251 + _e261);
                    if (_e280 > 0f) {
                        phi_476_ = select(1f, _e280, (_e280 < 1f));
                    } else {
                        phi_476_ = 0f;
                    }
                    let _e285 = phi_476_;
                    let _e289 = (0.425f * ((_e267 * (f32(((_e151 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f)) + (_e279 * (f32(((_e189 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f))));
                    let _e293 = (0.425f * ((_e279 * (f32(((_e189 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f)) + (_e273 * (f32(((_e170 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f))));
                    let _e297 = (0.425f * ((_e285 * (f32(((_e208 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f)) + (_e267 * (f32((_e151 & 3u)) * 0.33333334f))));
                    let _e301 = (0.425f * ((_e273 * (f32((_e170 & 3u)) * 0.33333334f)) + (_e285 * (f32(((_e208 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f))));
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e93 {
                        phi_511_ = 0i;
                    } else {
                        phi_511_ = select(_e89, _e91, (_e89 > _e91));
                    }
                    let _e305 = phi_511_;
                    let _e306 = bitcast<u32>(_e305);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e128 {
                        phi_530_ = 0i;
                    } else {
                        phi_530_ = select(_e127, _e101, (_e127 > _e101));
                    }
                    let _e310 = phi_530_;
                    let _e311 = bitcast<u32>(_e310);
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e110 {
                        phi_549_ = 0i;
                    } else {
                        phi_549_ = select(_e109, _e91, (_e109 > _e91));
                    }
                    let _e315 = phi_549_;
                    let _e316 = bitcast<u32>(_e315);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e128 {
                        phi_568_ = 0i;
                    } else {
                        phi_568_ = select(_e127, _e101, (_e127 > _e101));
                    }
                    let _e320 = phi_568_;
                    let _e321 = bitcast<u32>(_e320);
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e93 {
                        phi_587_ = 0i;
                    } else {
                        phi_587_ = select(_e89, _e91, (_e89 > _e91));
                    }
                    let _e325 = phi_587_;
                    let _e326 = bitcast<u32>(_e325);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e140 {
                        phi_606_ = 0i;
                    } else {
                        phi_606_ = select(_e139, _e101, (_e139 > _e101));
                    }
                    let _e330 = phi_606_;
                    let _e331 = bitcast<u32>(_e330);
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e110 {
                        phi_625_ = 0i;
                    } else {
                        phi_625_ = select(_e109, _e91, (_e109 > _e91));
                    }
                    let _e335 = phi_625_;
                    let _e336 = bitcast<u32>(_e335);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e140 {
                        phi_644_ = 0i;
                    } else {
                        phi_644_ = select(_e139, _e101, (_e139 > _e101));
                    }
                    let _e340 = phi_644_;
                    let _e341 = bitcast<u32>(_e340);
                    let _e349 = ((((((((_e87 + _e267) + _e273) + _e279) + _e285) + _e289) + _e293) + _e297) + _e301);
                    let _e352 = params.member.member_13;
                    if (_e352 == 0u) {
                        if (_e225 < _e43) {
                        } else {
                            break;
                        }
                        let _e357 = terms_in.member[_e225];
                        if (_e147 < _e43) {
                        } else {
                            break;
                        }
                        let _e364 = terms_in.member[_e147];
                        if (_e166 < _e43) {
                        } else {
                            break;
                        }
                        let _e372 = terms_in.member[_e166];
                        if (_e185 < _e43) {
                        } else {
                            break;
                        }
                        let _e380 = terms_in.member[_e185];
                        if (_e204 < _e43) {
                        } else {
                            break;
                        }
                        let _e388 = terms_in.member[_e204];
                        let _e394 = ((_e311 * _e59) + _e306);
                        if (_e394 < _e43) {
                        } else {
                            break;
                        }
                        let _e398 = terms_in.member[_e394];
                        let _e404 = ((_e321 * _e59) + _e316);
                        if (_e404 < _e43) {
                        } else {
                            break;
                        }
                        let _e408 = terms_in.member[_e404];
                        let _e414 = ((_e331 * _e59) + _e326);
                        if (_e414 < _e43) {
                        } else {
                            break;
                        }
                        let _e418 = terms_in.member[_e414];
                        let _e424 = ((_e341 * _e59) + _e336);
                        if (_e424 < _e43) {
                        } else {
                            break;
                        }
                        let _e428 = terms_in.member[_e424];
                        let _e433 = (((((((((((f32(_e357) * 0.003921569f) * _e87) + ((f32(_e364) * 0.003921569f) * _e267)) + ((f32(_e372) * 0.003921569f) * _e273)) + ((f32(_e380) * 0.003921569f) * _e279)) + ((f32(_e388) * 0.003921569f) * _e285)) + ((f32(_e398) * 0.003921569f) * _e289)) + ((f32(_e408) * 0.003921569f) * _e293)) + ((f32(_e418) * 0.003921569f) * _e297)) + ((f32(_e428) * 0.003921569f) * _e301)) / _e349);
                        if _e83 {
                            let _e435 = ((_e433 * 382.5f) + 0.5f);
                            let _e440 = select(select(u32(_e435), 0u, (_e435 < 0f)), 4294967295u, (_e435 > 4294967000f));
                            phi_846_ = select(_e440, 255u, (255u < _e440));
                        } else {
                            let _e444 = ((_e433 * 255f) + 0.5f);
                            phi_846_ = select(select(u32(_e444), 0u, (_e444 < 0f)), 4294967295u, (_e444 > 4294967000f));
                        }
                        let _e451 = phi_846_;
                        phi_1222_ = type_22(_e451, (f32(_e451) * 0.003921569f), _e83);
                    } else {
                        if (_e225 < _e43) {
                        } else {
                            break;
                        }
                        let _e458 = terms_in.member[_e225];
                        if (_e147 < _e43) {
                        } else {
                            break;
                        }
                        let _e483 = terms_in.member[_e147];
                        if (_e166 < _e43) {
                        } else {
                            break;
                        }
                        let _e512 = terms_in.member[_e166];
                        if (_e185 < _e43) {
                        } else {
                            break;
                        }
                        let _e541 = terms_in.member[_e185];
                        if (_e204 < _e43) {
                        } else {
                            break;
                        }
                        let _e570 = terms_in.member[_e204];
                        let _e597 = ((_e311 * _e59) + _e306);
                        if (_e597 < _e43) {
                        } else {
                            break;
                        }
                        let _e601 = terms_in.member[_e597];
                        let _e628 = ((_e321 * _e59) + _e316);
                        if (_e628 < _e43) {
                        } else {
                            break;
                        }
                        let _e632 = terms_in.member[_e628];
                        let _e659 = ((_e331 * _e59) + _e326);
                        if (_e659 < _e43) {
                        } else {
                            break;
                        }
                        let _e663 = terms_in.member[_e659];
                        let _e690 = ((_e341 * _e59) + _e336);
                        if (_e690 < _e43) {
                        } else {
                            break;
                        }
                        let _e694 = terms_in.member[_e690];
                        let _e720 = (((((((((((f32((_e458 & 255u)) * 0.003921569f) * _e87) + ((f32((_e483 & 255u)) * 0.003921569f) * _e267)) + ((f32((_e512 & 255u)) * 0.003921569f) * _e273)) + ((f32((_e541 & 255u)) * 0.003921569f) * _e279)) + ((f32((_e570 & 255u)) * 0.003921569f) * _e285)) + ((f32((_e601 & 255u)) * 0.003921569f) * _e289)) + ((f32((_e632 & 255u)) * 0.003921569f) * _e293)) + ((f32((_e663 & 255u)) * 0.003921569f) * _e297)) + ((f32((_e694 & 255u)) * 0.003921569f) * _e301)) / _e349);
                        let _e721 = (((((((((((f32(((_e458 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e87) + ((f32(((_e483 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e267)) + ((f32(((_e512 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e273)) + ((f32(((_e541 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e279)) + ((f32(((_e570 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e285)) + ((f32(((_e601 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e289)) + ((f32(((_e632 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e293)) + ((f32(((_e663 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e297)) + ((f32(((_e694 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e301)) / _e349);
                        let _e722 = (((((((((((f32(((_e458 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e87) + ((f32(((_e483 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e267)) + ((f32(((_e512 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e273)) + ((f32(((_e541 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e279)) + ((f32(((_e570 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e285)) + ((f32(((_e601 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e289)) + ((f32(((_e632 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e293)) + ((f32(((_e663 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e297)) + ((f32(((_e694 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e301)) / _e349);
                        let _e723 = (((((((((((f32((_e458 >> bitcast<u32>(24i))) * 0.003921569f) * _e87) + ((f32((_e483 >> bitcast<u32>(24i))) * 0.003921569f) * _e267)) + ((f32((_e512 >> bitcast<u32>(24i))) * 0.003921569f) * _e273)) + ((f32((_e541 >> bitcast<u32>(24i))) * 0.003921569f) * _e279)) + ((f32((_e570 >> bitcast<u32>(24i))) * 0.003921569f) * _e285)) + ((f32((_e601 >> bitcast<u32>(24i))) * 0.003921569f) * _e289)) + ((f32((_e632 >> bitcast<u32>(24i))) * 0.003921569f) * _e293)) + ((f32((_e663 >> bitcast<u32>(24i))) * 0.003921569f) * _e297)) + ((f32((_e694 >> bitcast<u32>(24i))) * 0.003921569f) * _e301)) / _e349);
                        if _e83 {
                            let _e727 = ((_e720 * 2f) - 1f);
                            let _e728 = ((_e721 * 2f) - 1f);
                            let _e729 = ((_e722 * 2f) - 1f);
                            let _e735 = sqrt((((_e727 * _e727) + (_e728 * _e728)) + (_e729 * _e729)));
                            if (_e735 > 0f) {
                                phi_1171_ = vec3<f32>((_e727 / _e735), (_e728 / _e735), (_e729 / _e735));
                            } else {
                                phi_1171_ = vec3<f32>(0f, 0f, -1f);
                            }
                            let _e742 = phi_1171_;
                            let _e744 = ((_e723 * 382.5f) + 0.5f);
                            let _e749 = select(select(u32(_e744), 0u, (_e744 < 0f)), 4294967295u, (_e744 > 4294967000f));
                            let _e753 = (f32(select(_e749, 255u, (255u < _e749))) * 0.003921569f);
                            let _e760 = ((_e742.x * 0.5f) + 0.5f);
                            let _e761 = ((_e742.y * 0.5f) + 0.5f);
                            let _e762 = ((_e742.z * -0.5f) + 0.5f);
                            if (_e760 > 0f) {
                                phi_1282_ = select(1f, _e760, (_e760 < 1f));
                            } else {
                                phi_1282_ = 0f;
                            }
                            let _e767 = phi_1282_;
                            let _e769 = ((_e767 * 255f) + 0.5f);
                            if (_e761 > 0f) {
                                phi_1303_ = select(1f, _e761, (_e761 < 1f));
                            } else {
                                phi_1303_ = 0f;
                            }
                            let _e779 = phi_1303_;
                            let _e781 = ((_e779 * 255f) + 0.5f);
                            if (_e762 > 0f) {
                                phi_1324_ = select(1f, _e762, (_e762 < 1f));
                            } else {
                                phi_1324_ = 0f;
                            }
                            let _e794 = phi_1324_;
                            let _e796 = ((_e794 * 255f) + 0.5f);
                            if (_e753 > 0f) {
                                phi_1345_ = select(1f, _e753, (_e753 < 1f));
                            } else {
                                phi_1345_ = 0f;
                            }
                            let _e809 = phi_1345_;
                            let _e811 = ((_e809 * 255f) + 0.5f);
                            phi_1221_ = type_22((((select(select(u32(_e769), 0u, (_e769 < 0f)), 4294967295u, (_e769 > 4294967000f)) | (select(select(u32(_e781), 0u, (_e781 < 0f)), 4294967295u, (_e781 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e796), 0u, (_e796 < 0f)), 4294967295u, (_e796 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e811), 0u, (_e811 < 0f)), 4294967295u, (_e811 > 4294967000f)) << bitcast<u32>(24i))), _e753, _e83);
                        } else {
                            if (_e720 > 0f) {
                                phi_1366_ = select(1f, _e720, (_e720 < 1f));
                            } else {
                                phi_1366_ = 0f;
                            }
                            let _e825 = phi_1366_;
                            let _e827 = ((_e825 * 255f) + 0.5f);
                            if (_e721 > 0f) {
                                phi_1387_ = select(1f, _e721, (_e721 < 1f));
                            } else {
                                phi_1387_ = 0f;
                            }
                            let _e837 = phi_1387_;
                            let _e839 = ((_e837 * 255f) + 0.5f);
                            if (_e722 > 0f) {
                                phi_1408_ = select(1f, _e722, (_e722 < 1f));
                            } else {
                                phi_1408_ = 0f;
                            }
                            let _e852 = phi_1408_;
                            let _e854 = ((_e852 * 255f) + 0.5f);
                            if (_e723 > 0f) {
                                phi_1429_ = select(1f, _e723, (_e723 < 1f));
                            } else {
                                phi_1429_ = 0f;
                            }
                            let _e867 = phi_1429_;
                            let _e869 = ((_e867 * 255f) + 0.5f);
                            phi_1221_ = type_22((((select(select(u32(_e827), 0u, (_e827 < 0f)), 4294967295u, (_e827 > 4294967000f)) | (select(select(u32(_e839), 0u, (_e839 < 0f)), 4294967295u, (_e839 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e854), 0u, (_e854 < 0f)), 4294967295u, (_e854 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e869), 0u, (_e869 < 0f)), 4294967295u, (_e869 > 4294967000f)) << bitcast<u32>(24i))), 0f, _e83);
                        }
                        let _e880 = phi_1221_;
                        phi_1222_ = _e880;
                    }
                    let _e882 = phi_1222_;
                    if (_e225 < arrayLength((&terms_out.member))) {
                    } else {
                        break;
                    }
                    terms_out.member[_e225] = _e882.member;
                    if _e882.member_2 {
                        if (_e225 < arrayLength((&ao.member))) {
                        } else {
                            break;
                        }
                        ao.member[_e225] = _e882.member_1;
                    }
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_denoise(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
