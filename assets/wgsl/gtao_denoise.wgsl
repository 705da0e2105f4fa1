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
    var phi_516_: i32;
    var phi_535_: i32;
    var phi_554_: i32;
    var phi_573_: i32;
    var phi_592_: i32;
    var phi_611_: i32;
    var phi_630_: i32;
    var phi_649_: i32;
    var phi_851_: u32;
    var phi_1176_: vec3<f32>;
    var phi_1226_: type_22;
    var phi_1227_: type_22;

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
                    let _e260 = (select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f)) * 0.33333334f);
                    let _e261 = (_e248 + _e260);
                    let _e265 = select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f));
                    let _e266 = (_e249 + _e260);
                    let _e270 = select(0f, select(1f, _e266, (_e266 < 1f)), (_e266 > 0f));
                    let _e271 = (_e250 + _e260);
                    let _e275 = select(0f, select(1f, _e271, (_e271 < 1f)), (_e271 > 0f));
                    let _e276 = (_e251 + _e260);
                    let _e280 = select(0f, select(1f, _e276, (_e276 < 1f)), (_e276 > 0f));
                    let _e284 = (0.425f * ((_e265 * (f32(((_e151 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f)) + (_e275 * (f32(((_e189 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f))));
                    let _e288 = (0.425f * ((_e275 * (f32(((_e189 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f)) + (_e270 * (f32(((_e170 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f))));
                    let _e292 = (0.425f * ((_e280 * (f32(((_e208 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f)) + (_e265 * (f32((_e151 & 3u)) * 0.33333334f))));
                    let _e296 = (0.425f * ((_e270 * (f32((_e170 & 3u)) * 0.33333334f)) + (_e280 * (f32(((_e208 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f))));
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e93 {
                        phi_516_ = 0i;
                    } else {
                        phi_516_ = select(_e89, _e91, (_e89 > _e91));
                    }
                    let _e300 = phi_516_;
                    let _e301 = bitcast<u32>(_e300);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e128 {
                        phi_535_ = 0i;
                    } else {
                        phi_535_ = select(_e127, _e101, (_e127 > _e101));
                    }
                    let _e305 = phi_535_;
                    let _e306 = bitcast<u32>(_e305);
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e110 {
                        phi_554_ = 0i;
                    } else {
                        phi_554_ = select(_e109, _e91, (_e109 > _e91));
                    }
                    let _e310 = phi_554_;
                    let _e311 = bitcast<u32>(_e310);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e128 {
                        phi_573_ = 0i;
                    } else {
                        phi_573_ = select(_e127, _e101, (_e127 > _e101));
                    }
                    let _e315 = phi_573_;
                    let _e316 = bitcast<u32>(_e315);
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e93 {
                        phi_592_ = 0i;
                    } else {
                        phi_592_ = select(_e89, _e91, (_e89 > _e91));
                    }
                    let _e320 = phi_592_;
                    let _e321 = bitcast<u32>(_e320);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e140 {
                        phi_611_ = 0i;
                    } else {
                        phi_611_ = select(_e139, _e101, (_e139 > _e101));
                    }
                    let _e325 = phi_611_;
                    let _e326 = bitcast<u32>(_e325);
                    if _e92 {
                    } else {
                        break;
                    }
                    if _e110 {
                        phi_630_ = 0i;
                    } else {
                        phi_630_ = select(_e109, _e91, (_e109 > _e91));
                    }
                    let _e330 = phi_630_;
                    let _e331 = bitcast<u32>(_e330);
                    if _e102 {
                    } else {
                        break;
                    }
                    if _e140 {
                        phi_649_ = 0i;
                    } else {
                        phi_649_ = select(_e139, _e101, (_e139 > _e101));
                    }
                    let _e335 = phi_649_;
                    let _e336 = bitcast<u32>(_e335);
                    let _e344 = ((((((((_e87 + _e265) + _e270) + _e275) + _e280) + _e284) + _e288) + _e292) + _e296);
                    let _e347 = params.member.member_13;
                    if (_e347 == 0u) {
                        if (_e225 < _e43) {
                        } else {
                            break;
                        }
                        let _e352 = terms_in.member[_e225];
                        if (_e147 < _e43) {
                        } else {
                            break;
                        }
                        let _e359 = terms_in.member[_e147];
                        if (_e166 < _e43) {
                        } else {
                            break;
                        }
                        let _e367 = terms_in.member[_e166];
                        if (_e185 < _e43) {
                        } else {
                            break;
                        }
                        let _e375 = terms_in.member[_e185];
                        if (_e204 < _e43) {
                        } else {
                            break;
                        }
                        let _e383 = terms_in.member[_e204];
                        let _e389 = ((_e306 * _e59) + _e301);
                        if (_e389 < _e43) {
                        } else {
                            break;
                        }
                        let _e393 = terms_in.member[_e389];
                        let _e399 = ((_e316 * _e59) + _e311);
                        if (_e399 < _e43) {
                        } else {
                            break;
                        }
                        let _e403 = terms_in.member[_e399];
                        let _e409 = ((_e326 * _e59) + _e321);
                        if (_e409 < _e43) {
                        } else {
                            break;
                        }
                        let _e413 = terms_in.member[_e409];
                        let _e419 = ((_e336 * _e59) + _e331);
                        if (_e419 < _e43) {
                        } else {
                            break;
                        }
                        let _e423 = terms_in.member[_e419];
                        let _e428 = (((((((((((f32(_e352) * 0.003921569f) * _e87) + ((f32(_e359) * 0.003921569f) * _e265)) + ((f32(_e367) * 0.003921569f) * _e270)) + ((f32(_e375) * 0.003921569f) * _e275)) + ((f32(_e383) * 0.003921569f) * _e280)) + ((f32(_e393) * 0.003921569f) * _e284)) + ((f32(_e403) * 0.003921569f) * _e288)) + ((f32(_e413) * 0.003921569f) * _e292)) + ((f32(_e423) * 0.003921569f) * _e296)) / _e344);
                        if _e83 {
                            let _e430 = ((_e428 * 382.5f) + 0.5f);
                            let _e435 = select(select(u32(_e430), 0u, (_e430 < 0f)), 4294967295u, (_e430 > 4294967000f));
                            phi_851_ = select(_e435, 255u, (255u < _e435));
                        } else {
                            let _e439 = ((_e428 * 255f) + 0.5f);
                            phi_851_ = select(select(u32(_e439), 0u, (_e439 < 0f)), 4294967295u, (_e439 > 4294967000f));
                        }
                        let _e446 = phi_851_;
                        phi_1227_ = type_22(_e446, (f32(_e446) * 0.003921569f), _e83);
                    } else {
                        if (_e225 < _e43) {
                        } else {
                            break;
                        }
                        let _e453 = terms_in.member[_e225];
                        if (_e147 < _e43) {
                        } else {
                            break;
                        }
                        let _e478 = terms_in.member[_e147];
                        if (_e166 < _e43) {
                        } else {
                            break;
                        }
                        let _e507 = terms_in.member[_e166];
                        if (_e185 < _e43) {
                        } else {
                            break;
                        }
                        let _e536 = terms_in.member[_e185];
                        if (_e204 < _e43) {
                        } else {
                            break;
                        }
                        let _e565 = terms_in.member[_e204];
                        let _e592 = ((_e306 * _e59) + _e301);
                        if (_e592 < _e43) {
                        } else {
                            break;
                        }
                        let _e596 = terms_in.member[_e592];
                        let _e623 = ((_e316 * _e59) + _e311);
                        if (_e623 < _e43) {
                        } else {
                            break;
                        }
                        let _e627 = terms_in.member[_e623];
                        let _e654 = ((_e326 * _e59) + _e321);
                        if (_e654 < _e43) {
                        } else {
                            break;
                        }
                        let _e658 = terms_in.member[_e654];
                        let _e685 = ((_e336 * _e59) + _e331);
                        if (_e685 < _e43) {
                        } else {
                            break;
                        }
                        let _e689 = terms_in.member[_e685];
                        let _e715 = (((((((((((f32((_e453 & 255u)) * 0.003921569f) * _e87) + ((f32((_e478 & 255u)) * 0.003921569f) * _e265)) + ((f32((_e507 & 255u)) * 0.003921569f) * _e270)) + ((f32((_e536 & 255u)) * 0.003921569f) * _e275)) + ((f32((_e565 & 255u)) * 0.003921569f) * _e280)) + ((f32((_e596 & 255u)) * 0.003921569f) * _e284)) + ((f32((_e627 & 255u)) * 0.003921569f) * _e288)) + ((f32((_e658 & 255u)) * 0.003921569f) * _e292)) + ((f32((_e689 & 255u)) * 0.003921569f) * _e296)) / _e344);
                        let _e716 = (((((((((((f32(((_e453 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e87) + ((f32(((_e478 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e265)) + ((f32(((_e507 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e270)) + ((f32(((_e536 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e275)) + ((f32(((_e565 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e280)) + ((f32(((_e596 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e284)) + ((f32(((_e627 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e288)) + ((f32(((_e658 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e292)) + ((f32(((_e689 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e296)) / _e344);
                        let _e717 = (((((((((((f32(((_e453 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e87) + ((f32(((_e478 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e265)) + ((f32(((_e507 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e270)) + ((f32(((_e536 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e275)) + ((f32(((_e565 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e280)) + ((f32(((_e596 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e284)) + ((f32(((_e627 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e288)) + ((f32(((_e658 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e292)) + ((f32(((_e689 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e296)) / _e344);
                        let _e718 = (((((((((((f32((_e453 >> bitcast<u32>(24i))) * 0.003921569f) * _e87) + ((f32((_e478 >> bitcast<u32>(24i))) * 0.003921569f) * _e265)) + ((f32((_e507 >> bitcast<u32>(24i))) * 0.003921569f) * _e270)) + ((f32((_e536 >> bitcast<u32>(24i))) * 0.003921569f) * _e275)) + ((f32((_e565 >> bitcast<u32>(24i))) * 0.003921569f) * _e280)) + ((f32((_e596 >> bitcast<u32>(24i))) * 0.003921569f) * _e284)) + ((f32((_e627 >> bitcast<u32>(24i))) * 0.003921569f) * _e288)) + ((f32((_e658 >> bitcast<u32>(24i))) * 0.003921569f) * _e292)) + ((f32((_e689 >> bitcast<u32>(24i))) * 0.003921569f) * _e296)) / _e344);
                        if _e83 {
                            let _e722 = ((_e715 * 2f) - 1f);
                            let _e723 = ((_e716 * 2f) - 1f);
                            let _e724 = ((_e717 * 2f) - 1f);
                            let _e730 = sqrt((((_e722 * _e722) + (_e723 * _e723)) + (_e724 * _e724)));
                            if (_e730 > 0f) {
                                phi_1176_ = vec3<f32>((_e722 / _e730), (_e723 / _e730), (_e724 / _e730));
                            } else {
                                phi_1176_ = vec3<f32>(0f, 0f, -1f);
                            }
                            let _e737 = phi_1176_;
                            let _e739 = ((_e718 * 382.5f) + 0.5f);
                            let _e744 = select(select(u32(_e739), 0u, (_e739 < 0f)), 4294967295u, (_e739 > 4294967000f));
                            let _e748 = (f32(select(_e744, 255u, (255u < _e744))) * 0.003921569f);
                            let _e755 = ((_e737.x * 0.5f) + 0.5f);
                            let _e756 = ((_e737.y * 0.5f) + 0.5f);
                            let _e757 = ((_e737.z * -0.5f) + 0.5f);
                            let _e763 = ((select(0f, select(1f, _e755, (_e755 < 1f)), (_e755 > 0f)) * 255f) + 0.5f);
                            let _e774 = ((select(0f, select(1f, _e756, (_e756 < 1f)), (_e756 > 0f)) * 255f) + 0.5f);
                            let _e788 = ((select(0f, select(1f, _e757, (_e757 < 1f)), (_e757 > 0f)) * 255f) + 0.5f);
                            let _e802 = ((select(0f, select(1f, _e748, (_e748 < 1f)), (_e748 > 0f)) * 255f) + 0.5f);
                            phi_1226_ = type_22((((select(select(u32(_e763), 0u, (_e763 < 0f)), 4294967295u, (_e763 > 4294967000f)) | (select(select(u32(_e774), 0u, (_e774 < 0f)), 4294967295u, (_e774 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e788), 0u, (_e788 < 0f)), 4294967295u, (_e788 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e802), 0u, (_e802 < 0f)), 4294967295u, (_e802 > 4294967000f)) << bitcast<u32>(24i))), _e748, _e83);
                        } else {
                            let _e817 = ((select(0f, select(1f, _e715, (_e715 < 1f)), (_e715 > 0f)) * 255f) + 0.5f);
                            let _e828 = ((select(0f, select(1f, _e716, (_e716 < 1f)), (_e716 > 0f)) * 255f) + 0.5f);
                            let _e842 = ((select(0f, select(1f, _e717, (_e717 < 1f)), (_e717 > 0f)) * 255f) + 0.5f);
                            let _e856 = ((select(0f, select(1f, _e718, (_e718 < 1f)), (_e718 > 0f)) * 255f) + 0.5f);
                            phi_1226_ = type_22((((select(select(u32(_e817), 0u, (_e817 < 0f)), 4294967295u, (_e817 > 4294967000f)) | (select(select(u32(_e828), 0u, (_e828 < 0f)), 4294967295u, (_e828 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e842), 0u, (_e842 < 0f)), 4294967295u, (_e842 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e856), 0u, (_e856 < 0f)), 4294967295u, (_e856 > 4294967000f)) << bitcast<u32>(24i))), 0f, _e83);
                        }
                        let _e867 = phi_1226_;
                        phi_1227_ = _e867;
                    }
                    let _e869 = phi_1227_;
                    if (_e225 < arrayLength((&terms_out.member))) {
                    } else {
                        break;
                    }
                    terms_out.member[_e225] = _e869.member;
                    if _e869.member_2 {
                        if (_e225 < arrayLength((&ao.member))) {
                        } else {
                            break;
                        }
                        ao.member[_e225] = _e869.member_1;
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
