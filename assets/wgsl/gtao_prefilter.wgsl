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

struct type_14 {
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

struct type_15 {
    member: type_14,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(2) 
var<uniform> params: type_15;
@group(0) @binding(1) 
var<storage, read_write> mips: type_7;

fn function_() {
    var local: array<f32, 4>;
    var phi_192_: u32;
    var phi_195_: u32;
    var phi_193_: u32;
    var phi_196_: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var phi_455_: bool;
    var phi_470_: bool;
    var phi_485_: bool;
    var phi_338_: u32;
    var phi_341_: f32;
    var phi_343_: f32;
    var phi_385_: f32;
    var phi_339_: u32;
    var phi_342_: f32;
    var phi_344_: f32;
    var phi_490_: bool;
    var local_5: f32;
    var local_6: f32;
    var phi_398_: f32;
    var phi_402_: u32;
    var phi_405_: u32;
    var phi_403_: u32;
    var phi_406_: u32;
    var local_7: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e23 = id_1;
            let _e27 = arrayLength((&mips.member));
            let _e32 = params.member.member.member[0u];
            let _e37 = select(select(u32(_e32), 0u, (_e32 < 0f)), 4294967295u, (_e32 > 4294967000f));
            let _e42 = params.member.member.member[1u];
            let _e47 = select(select(u32(_e42), 0u, (_e42 < 0f)), 4294967295u, (_e42 > 4294967000f));
            let _e50 = params.member.member_12;
            let _e51 = (_e50 & 31u);
            let _e53 = (_e37 >> bitcast<u32>(_e51));
            let _e55 = select(1u, _e53, (1u < _e53));
            let _e57 = (_e47 >> bitcast<u32>(_e51));
            if (_e23.x >= _e55) {
            } else {
                if (_e23.y >= select(1u, _e57, (1u < _e57))) {
                } else {
                    if (_e50 == 0u) {
                        let _e66 = ((_e23.y * _e37) + _e23.x);
                        if (_e66 < arrayLength((&depth.member))) {
                        } else {
                            break;
                        }
                        let _e70 = depth.member[_e66];
                        let _e74 = params.member.member.member_3;
                        let _e78 = select(_e74, _e70, select(false, (_e70 < _e74), (_e70 > 0f)));
                        phi_398_ = select(0f, select(65504f, _e78, (_e78 < 65504f)), (_e78 > 0f));
                    } else {
                        let _e83 = (_e50 - 1u);
                        let _e84 = (_e83 & 31u);
                        let _e86 = (_e37 >> bitcast<u32>(_e84));
                        let _e88 = select(1u, _e86, (1u < _e86));
                        let _e90 = (_e47 >> bitcast<u32>(_e84));
                        phi_192_ = 0u;
                        phi_195_ = 0u;
                        loop {
                            let _e94 = phi_192_;
                            let _e96 = phi_195_;
                            local_1 = _e96;
                            local_2 = _e96;
                            local_3 = _e96;
                            local_4 = _e96;
                            let _e97 = (_e94 < _e83);
                            if _e97 {
                                let _e98 = (_e94 & 31u);
                                let _e100 = (_e37 >> bitcast<u32>(_e98));
                                let _e104 = (_e47 >> bitcast<u32>(_e98));
                                phi_193_ = (_e94 + 1u);
                                phi_196_ = (_e96 + (select(1u, _e100, (1u < _e100)) * select(1u, _e104, (1u < _e104))));
                            } else {
                                phi_193_ = u32();
                                phi_196_ = u32();
                            }
                            let _e111 = phi_193_;
                            let _e113 = phi_196_;
                            continue;
                            continuing {
                                phi_192_ = _e111;
                                phi_195_ = _e113;
                                break if !(_e97);
                            }
                        }
                        let _e115 = (2u * _e23.x);
                        let _e116 = (2u * _e23.y);
                        let _e117 = (select(1u, _e90, (1u < _e90)) - 1u);
                        let _e120 = (select(_e116, _e117, (_e117 < _e116)) * _e88);
                        let _e121 = (_e88 - 1u);
                        let _e123 = select(_e115, _e121, (_e121 < _e115));
                        let _e126 = local_1;
                        let _e127 = (_e126 + (_e120 + _e123));
                        if (_e127 < _e27) {
                        } else {
                            break;
                        }
                        let _e131 = mips.member[_e127];
                        let _e132 = (_e115 + 1u);
                        let _e134 = select(_e132, _e121, (_e121 < _e132));
                        let _e137 = local_2;
                        let _e138 = (_e137 + (_e120 + _e134));
                        if (_e138 < _e27) {
                        } else {
                            break;
                        }
                        let _e142 = mips.member[_e138];
                        let _e143 = (_e116 + 1u);
                        let _e146 = (select(_e143, _e117, (_e117 < _e143)) * _e88);
                        let _e149 = local_3;
                        let _e150 = (_e149 + (_e146 + _e123));
                        if (_e150 < _e27) {
                        } else {
                            break;
                        }
                        let _e154 = mips.member[_e150];
                        let _e157 = local_4;
                        let _e158 = (_e157 + (_e146 + _e134));
                        if (_e158 < _e27) {
                        } else {
                            break;
                        }
                        let _e162 = mips.member[_e158];
                        local = array<f32, 4>(_e131, _e142, _e154, _e162);
                        let _e166 = params.member.member_1;
                        let _e169 = params.member.member_2;
                        let _e171 = (0.75f * (_e166 * _e169));
                        let _e173 = local[0u];
                        let _e175 = local[1u];
                        if (_e173 != _e173) {
                            phi_455_ = true;
                        } else {
                            phi_455_ = (_e175 >= _e173);
                        }
                        let _e179 = phi_455_;
                        let _e180 = select(_e173, _e175, _e179);
                        let _e182 = local[2u];
                        if (_e180 != _e180) {
                            phi_470_ = true;
                        } else {
                            phi_470_ = (_e182 >= _e180);
                        }
                        let _e186 = phi_470_;
                        let _e187 = select(_e180, _e182, _e186);
                        let _e189 = local[3u];
                        if (_e187 != _e187) {
                            phi_485_ = true;
                        } else {
                            phi_485_ = (_e189 >= _e187);
                        }
                        let _e193 = phi_485_;
                        phi_338_ = 0u;
                        phi_341_ = 0f;
                        phi_343_ = 0f;
                        loop {
                            let _e196 = phi_338_;
                            let _e198 = phi_341_;
                            let _e200 = phi_343_;
                            local_5 = _e200;
                            local_6 = _e198;
                            let _e201 = (_e196 < 4u);
                            if _e201 {
                                if _e201 {
                                } else {
                                    phi_490_ = true;
                                    break;
                                }
                                let _e203 = local[_e196];
                                let _e205 = (_e171 - (select(_e187, _e189, _e193) - _e203));
                                let _e208 = params.member.member_3;
                                if (_e208 > 0f) {
                                    let _e211 = (_e205 / (_e208 * _e171));
                                    phi_385_ = select(0f, select(1f, _e211, (_e211 < 1f)), (_e211 > 0f));
                                } else {
                                    phi_385_ = select(0f, 1f, (_e205 >= 0f));
                                }
                                let _e219 = phi_385_;
                                if _e201 {
                                } else {
                                    phi_490_ = true;
                                    break;
                                }
                                let _e220 = local[_e196];
                                phi_339_ = (_e196 + 1u);
                                phi_342_ = (_e198 + _e219);
                                phi_344_ = (_e200 + (_e219 * _e220));
                            } else {
                                phi_339_ = u32();
                                phi_342_ = f32();
                                phi_344_ = f32();
                            }
                            let _e226 = phi_339_;
                            let _e228 = phi_342_;
                            let _e230 = phi_344_;
                            continue;
                            continuing {
                                phi_338_ = _e226;
                                phi_341_ = _e228;
                                phi_343_ = _e230;
                                phi_490_ = false;
                                break if !(_e201);
                            }
                        }
                        let _e233 = phi_490_;
                        if _e233 {
                            break;
                        }
                        let _e235 = local_5;
                        let _e237 = local_6;
                        phi_398_ = (_e235 / _e237);
                    }
                    let _e240 = phi_398_;
                    phi_402_ = 0u;
                    phi_405_ = 0u;
                    loop {
                        let _e242 = phi_402_;
                        let _e244 = phi_405_;
                        local_7 = _e244;
                        let _e245 = (_e242 < _e50);
                        if _e245 {
                            let _e246 = (_e242 & 31u);
                            let _e248 = (_e37 >> bitcast<u32>(_e246));
                            let _e252 = (_e47 >> bitcast<u32>(_e246));
                            phi_403_ = (_e242 + 1u);
                            phi_406_ = (_e244 + (select(1u, _e248, (1u < _e248)) * select(1u, _e252, (1u < _e252))));
                        } else {
                            phi_403_ = u32();
                            phi_406_ = u32();
                        }
                        let _e259 = phi_403_;
                        let _e261 = phi_406_;
                        continue;
                        continuing {
                            phi_402_ = _e259;
                            phi_405_ = _e261;
                            break if !(_e245);
                        }
                    }
                    let _e266 = local_7;
                    let _e267 = (_e266 + ((_e23.y * _e55) + _e23.x));
                    if (_e267 < _e27) {
                    } else {
                        break;
                    }
                    mips.member[_e267] = _e240;
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
