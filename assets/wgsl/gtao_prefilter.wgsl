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
    var phi_160_: bool;
    var phi_194_: u32;
    var phi_197_: u32;
    var phi_195_: u32;
    var phi_198_: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var phi_457_: bool;
    var phi_472_: bool;
    var phi_487_: bool;
    var phi_340_: u32;
    var phi_343_: f32;
    var phi_345_: f32;
    var phi_387_: f32;
    var phi_341_: u32;
    var phi_344_: f32;
    var phi_346_: f32;
    var phi_492_: bool;
    var local_5: f32;
    var local_6: f32;
    var phi_400_: f32;
    var phi_404_: u32;
    var phi_407_: u32;
    var phi_405_: u32;
    var phi_408_: u32;
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
                        if (_e70 > 0f) {
                            phi_160_ = (_e70 < _e74);
                        } else {
                            phi_160_ = false;
                        }
                        let _e78 = phi_160_;
                        let _e79 = select(_e74, _e70, _e78);
                        phi_400_ = select(0f, select(65504f, _e79, (_e79 < 65504f)), (_e79 > 0f));
                    } else {
                        let _e84 = (_e50 - 1u);
                        let _e85 = (_e84 & 31u);
                        let _e87 = (_e37 >> bitcast<u32>(_e85));
                        let _e89 = select(1u, _e87, (1u < _e87));
                        let _e91 = (_e47 >> bitcast<u32>(_e85));
                        phi_194_ = 0u;
                        phi_197_ = 0u;
                        loop {
                            let _e95 = phi_194_;
                            let _e97 = phi_197_;
                            local_1 = _e97;
                            local_2 = _e97;
                            local_3 = _e97;
                            local_4 = _e97;
                            let _e98 = (_e95 < _e84);
                            if _e98 {
                                let _e99 = (_e95 & 31u);
                                let _e101 = (_e37 >> bitcast<u32>(_e99));
                                let _e105 = (_e47 >> bitcast<u32>(_e99));
                                phi_195_ = (_e95 + 1u);
                                phi_198_ = (_e97 + (select(1u, _e101, (1u < _e101)) * select(1u, _e105, (1u < _e105))));
                            } else {
                                phi_195_ = u32();
                                phi_198_ = u32();
                            }
                            let _e112 = phi_195_;
                            let _e114 = phi_198_;
                            continue;
                            continuing {
                                phi_194_ = _e112;
                                phi_197_ = _e114;
                                break if !(_e98);
                            }
                        }
                        let _e116 = (2u * _e23.x);
                        let _e117 = (2u * _e23.y);
                        let _e118 = (select(1u, _e91, (1u < _e91)) - 1u);
                        let _e121 = (select(_e117, _e118, (_e118 < _e117)) * _e89);
                        let _e122 = (_e89 - 1u);
                        let _e124 = select(_e116, _e122, (_e122 < _e116));
                        let _e127 = local_1;
                        let _e128 = (_e127 + (_e121 + _e124));
                        if (_e128 < _e27) {
                        } else {
                            break;
                        }
                        let _e132 = mips.member[_e128];
                        let _e133 = (_e116 + 1u);
                        let _e135 = select(_e133, _e122, (_e122 < _e133));
                        let _e138 = local_2;
                        let _e139 = (_e138 + (_e121 + _e135));
                        if (_e139 < _e27) {
                        } else {
                            break;
                        }
                        let _e143 = mips.member[_e139];
                        let _e144 = (_e117 + 1u);
                        let _e147 = (select(_e144, _e118, (_e118 < _e144)) * _e89);
                        let _e150 = local_3;
                        let _e151 = (_e150 + (_e147 + _e124));
                        if (_e151 < _e27) {
                        } else {
                            break;
                        }
                        let _e155 = mips.member[_e151];
                        let _e158 = local_4;
                        let _e159 = (_e158 + (_e147 + _e135));
                        if (_e159 < _e27) {
                        } else {
                            break;
                        }
                        let _e163 = mips.member[_e159];
                        local = array<f32, 4>(_e132, _e143, _e155, _e163);
                        let _e167 = params.member.member_1;
                        let _e170 = params.member.member_2;
                        let _e172 = (0.75f * (_e167 * _e170));
                        let _e174 = local[0u];
                        let _e176 = local[1u];
                        if (_e174 != _e174) {
                            phi_457_ = true;
                        } else {
                            phi_457_ = (_e176 >= _e174);
                        }
                        let _e180 = phi_457_;
                        let _e181 = select(_e174, _e176, _e180);
                        let _e183 = local[2u];
                        if (_e181 != _e181) {
                            phi_472_ = true;
                        } else {
                            phi_472_ = (_e183 >= _e181);
                        }
                        let _e187 = phi_472_;
                        let _e188 = select(_e181, _e183, _e187);
                        let _e190 = local[3u];
                        if (_e188 != _e188) {
                            phi_487_ = true;
                        } else {
                            phi_487_ = (_e190 >= _e188);
                        }
                        let _e194 = phi_487_;
                        phi_340_ = 0u;
                        phi_343_ = 0f;
                        phi_345_ = 0f;
                        loop {
                            let _e197 = phi_340_;
                            let _e199 = phi_343_;
                            let _e201 = phi_345_;
                            local_5 = _e201;
                            local_6 = _e199;
                            let _e202 = (_e197 < 4u);
                            if _e202 {
                                if _e202 {
                                } else {
                                    phi_492_ = true;
                                    break;
                                }
                                let _e204 = local[_e197];
                                let _e206 = (_e172 - (select(_e188, _e190, _e194) - _e204));
                                let _e209 = params.member.member_3;
                                if (_e209 > 0f) {
                                    let _e212 = (_e206 / (_e209 * _e172));
                                    phi_387_ = select(0f, select(1f, _e212, (_e212 < 1f)), (_e212 > 0f));
                                } else {
                                    phi_387_ = select(0f, 1f, (_e206 >= 0f));
                                }
                                let _e220 = phi_387_;
                                if _e202 {
                                } else {
                                    phi_492_ = true;
                                    break;
                                }
                                let _e221 = local[_e197];
                                phi_341_ = (_e197 + 1u);
                                phi_344_ = (_e199 + _e220);
                                phi_346_ = (_e201 + (_e220 * _e221));
                            } else {
                                phi_341_ = u32();
                                phi_344_ = f32();
                                phi_346_ = f32();
                            }
                            let _e227 = phi_341_;
                            let _e229 = phi_344_;
                            let _e231 = phi_346_;
                            continue;
                            continuing {
                                phi_340_ = _e227;
                                phi_343_ = _e229;
                                phi_345_ = _e231;
                                phi_492_ = false;
                                break if !(_e202);
                            }
                        }
                        let _e234 = phi_492_;
                        if _e234 {
                            break;
                        }
                        let _e236 = local_5;
                        let _e238 = local_6;
                        phi_400_ = (_e236 / _e238);
                    }
                    let _e241 = phi_400_;
                    phi_404_ = 0u;
                    phi_407_ = 0u;
                    loop {
                        let _e243 = phi_404_;
                        let _e245 = phi_407_;
                        local_7 = _e245;
                        let _e246 = (_e243 < _e50);
                        if _e246 {
                            let _e247 = (_e243 & 31u);
                            let _e249 = (_e37 >> bitcast<u32>(_e247));
                            let _e253 = (_e47 >> bitcast<u32>(_e247));
                            phi_405_ = (_e243 + 1u);
                            phi_408_ = (_e245 + (select(1u, _e249, (1u < _e249)) * select(1u, _e253, (1u < _e253))));
                        } else {
                            phi_405_ = u32();
                            phi_408_ = u32();
                        }
                        let _e260 = phi_405_;
                        let _e262 = phi_408_;
                        continue;
                        continuing {
                            phi_404_ = _e260;
                            phi_407_ = _e262;
                            break if !(_e246);
                        }
                    }
                    let _e267 = local_7;
                    let _e268 = (_e267 + ((_e23.y * _e55) + _e23.x));
                    if (_e268 < _e27) {
                    } else {
                        break;
                    }
                    mips.member[_e268] = _e241;
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
