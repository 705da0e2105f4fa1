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
    var phi_176_: f32;
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
    var phi_381_: f32;
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
                        if (_e79 > 0f) {
                            phi_176_ = select(65504f, _e79, (_e79 < 65504f));
                        } else {
                            phi_176_ = 0f;
                        }
                        let _e84 = phi_176_;
                        phi_400_ = _e84;
                    } else {
                        let _e85 = (_e50 - 1u);
                        let _e86 = (_e85 & 31u);
                        let _e88 = (_e37 >> bitcast<u32>(_e86));
                        let _e90 = select(1u, _e88, (1u < _e88));
                        let _e92 = (_e47 >> bitcast<u32>(_e86));
                        phi_194_ = 0u;
                        phi_197_ = 0u;
                        loop {
                            let _e96 = phi_194_;
                            let _e98 = phi_197_;
                            local_1 = _e98;
                            local_2 = _e98;
                            local_3 = _e98;
                            local_4 = _e98;
                            let _e99 = (_e96 < _e85);
                            if _e99 {
                                let _e100 = (_e96 & 31u);
                                let _e102 = (_e37 >> bitcast<u32>(_e100));
                                let _e106 = (_e47 >> bitcast<u32>(_e100));
                                phi_195_ = (_e96 + 1u);
                                phi_198_ = (_e98 + (select(1u, _e102, (1u < _e102)) * select(1u, _e106, (1u < _e106))));
                            } else {
                                phi_195_ = u32();
                                phi_198_ = u32();
                            }
                            let _e113 = phi_195_;
                            let _e115 = phi_198_;
                            continue;
                            continuing {
                                phi_194_ = _e113;
                                phi_197_ = _e115;
                                break if !(_e99);
                            }
                        }
                        let _e117 = (2u * _e23.x);
                        let _e118 = (2u * _e23.y);
                        let _e119 = (select(1u, _e92, (1u < _e92)) - 1u);
                        let _e122 = (select(_e118, _e119, (_e119 < _e118)) * _e90);
                        let _e123 = (_e90 - 1u);
                        let _e125 = select(_e117, _e123, (_e123 < _e117));
                        let _e128 = local_1;
                        let _e129 = (_e128 + (_e122 + _e125));
                        if (_e129 < _e27) {
                        } else {
                            break;
                        }
                        let _e133 = mips.member[_e129];
                        let _e134 = (_e117 + 1u);
                        let _e136 = select(_e134, _e123, (_e123 < _e134));
                        let _e139 = local_2;
                        let _e140 = (_e139 + (_e122 + _e136));
                        if (_e140 < _e27) {
                        } else {
                            break;
                        }
                        let _e144 = mips.member[_e140];
                        let _e145 = (_e118 + 1u);
                        let _e148 = (select(_e145, _e119, (_e119 < _e145)) * _e90);
                        let _e151 = local_3;
                        let _e152 = (_e151 + (_e148 + _e125));
                        if (_e152 < _e27) {
                        } else {
                            break;
                        }
                        let _e156 = mips.member[_e152];
                        let _e159 = local_4;
                        let _e160 = (_e159 + (_e148 + _e136));
                        if (_e160 < _e27) {
                        } else {
                            break;
                        }
                        let _e164 = mips.member[_e160];
                        local = array<f32, 4>(_e133, _e144, _e156, _e164);
                        let _e168 = params.member.member_1;
                        let _e171 = params.member.member_2;
                        let _e173 = (0.75f * (_e168 * _e171));
                        let _e175 = local[0u];
                        let _e177 = local[1u];
                        if (_e175 != _e175) {
                            phi_457_ = true;
                        } else {
                            phi_457_ = (_e177 >= _e175);
                        }
                        let _e181 = phi_457_;
                        let _e182 = select(_e175, _e177, _e181);
                        let _e184 = local[2u];
                        if (_e182 != _e182) {
                            phi_472_ = true;
                        } else {
                            phi_472_ = (_e184 >= _e182);
                        }
                        let _e188 = phi_472_;
                        let _e189 = select(_e182, _e184, _e188);
                        let _e191 = local[3u];
                        if (_e189 != _e189) {
                            phi_487_ = true;
                        } else {
                            phi_487_ = (_e191 >= _e189);
                        }
                        let _e195 = phi_487_;
                        phi_340_ = 0u;
                        phi_343_ = 0f;
                        phi_345_ = 0f;
                        loop {
                            let _e198 = phi_340_;
                            let _e200 = phi_343_;
                            let _e202 = phi_345_;
                            local_5 = _e202;
                            local_6 = _e200;
                            let _e203 = (_e198 < 4u);
                            if _e203 {
                                if _e203 {
                                } else {
                                    phi_492_ = true;
                                    break;
                                }
                                let _e205 = local[_e198];
                                let _e207 = (_e173 - (select(_e189, _e191, _e195) - _e205));
                                let _e210 = params.member.member_3;
                                if (_e210 > 0f) {
                                    let _e213 = (_e207 / (_e210 * _e173));
                                    if (_e213 > 0f) {
                                        phi_381_ = select(1f, _e213, (_e213 < 1f));
                                    } else {
                                        phi_381_ = 0f;
                                    }
                                    let _e218 = phi_381_;
                                    phi_387_ = _e218;
                                } else {
                                    phi_387_ = select(0f, 1f, (_e207 >= 0f));
                                }
                                let _e222 = phi_387_;
                                if _e203 {
                                } else {
                                    phi_492_ = true;
                                    break;
                                }
                                let _e223 = local[_e198];
                                phi_341_ = (_e198 + 1u);
                                phi_344_ = (_e200 + _e222);
                                phi_346_ = (_e202 + (_e222 * _e223));
                            } else {
                                phi_341_ = u32();
                                phi_344_ = f32();
                                phi_346_ = f32();
                            }
                            let _e229 = phi_341_;
                            let _e231 = phi_344_;
                            let _e233 = phi_346_;
                            continue;
                            continuing {
                                phi_340_ = _e229;
                                phi_343_ = _e231;
                                phi_345_ = _e233;
                                phi_492_ = false;
                                break if !(_e203);
                            }
                        }
                        let _e236 = phi_492_;
                        if _e236 {
                            break;
                        }
                        let _e238 = local_5;
                        let _e240 = local_6;
                        phi_400_ = (_e238 / _e240);
                    }
                    let _e243 = phi_400_;
                    phi_404_ = 0u;
                    phi_407_ = 0u;
                    loop {
                        let _e245 = phi_404_;
                        let _e247 = phi_407_;
                        local_7 = _e247;
                        let _e248 = (_e245 < _e50);
                        if _e248 {
                            let _e249 = (_e245 & 31u);
                            let _e251 = (_e37 >> bitcast<u32>(_e249));
                            let _e255 = (_e47 >> bitcast<u32>(_e249));
                            phi_405_ = (_e245 + 1u);
                            phi_408_ = (_e247 + (select(1u, _e251, (1u < _e251)) * select(1u, _e255, (1u < _e255))));
                        } else {
                            phi_405_ = u32();
                            phi_408_ = u32();
                        }
                        let _e262 = phi_405_;
                        let _e264 = phi_408_;
                        continue;
                        continuing {
                            phi_404_ = _e262;
                            phi_407_ = _e264;
                            break if !(_e248);
                        }
                    }
                    let _e269 = local_7;
                    let _e270 = (_e269 + ((_e23.y * _e55) + _e23.x));
                    if (_e270 < _e27) {
                    } else {
                        break;
                    }
                    mips.member[_e270] = _e243;
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
