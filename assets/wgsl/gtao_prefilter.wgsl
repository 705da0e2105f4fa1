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
    var phi_186_: u32;
    var phi_189_: u32;
    var phi_187_: u32;
    var phi_190_: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var phi_429_: bool;
    var phi_444_: bool;
    var phi_459_: bool;
    var phi_312_: u32;
    var phi_315_: f32;
    var phi_317_: f32;
    var phi_359_: f32;
    var phi_313_: u32;
    var phi_316_: f32;
    var phi_318_: f32;
    var phi_464_: bool;
    var local_5: f32;
    var local_6: f32;
    var phi_372_: f32;
    var phi_376_: u32;
    var phi_379_: u32;
    var phi_377_: u32;
    var phi_380_: u32;
    var local_7: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e23 = id_1;
            let _e30 = params.member.member.member[0u];
            let _e35 = select(select(u32(_e30), 0u, (_e30 < 0f)), 4294967295u, (_e30 > 4294967000f));
            let _e40 = params.member.member.member[1u];
            let _e45 = select(select(u32(_e40), 0u, (_e40 < 0f)), 4294967295u, (_e40 > 4294967000f));
            let _e48 = params.member.member_12;
            let _e49 = (_e48 & 31u);
            let _e51 = (_e35 >> bitcast<u32>(_e49));
            let _e53 = select(1u, _e51, (1u < _e51));
            let _e55 = (_e45 >> bitcast<u32>(_e49));
            if (_e23.x >= _e53) {
            } else {
                if (_e23.y >= select(1u, _e55, (1u < _e55))) {
                } else {
                    if (_e48 == 0u) {
                        let _e67 = depth.member[((_e23.y * _e35) + _e23.x)];
                        let _e71 = params.member.member.member_3;
                        let _e75 = select(_e71, _e67, select(false, (_e67 < _e71), (_e67 > 0f)));
                        phi_372_ = select(0f, select(65504f, _e75, (_e75 < 65504f)), (_e75 > 0f));
                    } else {
                        let _e80 = (_e48 - 1u);
                        let _e81 = (_e80 & 31u);
                        let _e83 = (_e35 >> bitcast<u32>(_e81));
                        let _e85 = select(1u, _e83, (1u < _e83));
                        let _e87 = (_e45 >> bitcast<u32>(_e81));
                        phi_186_ = 0u;
                        phi_189_ = 0u;
                        loop {
                            let _e91 = phi_186_;
                            let _e93 = phi_189_;
                            local_1 = _e93;
                            local_2 = _e93;
                            local_3 = _e93;
                            local_4 = _e93;
                            let _e94 = (_e91 < _e80);
                            if _e94 {
                                let _e95 = (_e91 & 31u);
                                let _e97 = (_e35 >> bitcast<u32>(_e95));
                                let _e101 = (_e45 >> bitcast<u32>(_e95));
                                phi_187_ = (_e91 + 1u);
                                phi_190_ = (_e93 + (select(1u, _e97, (1u < _e97)) * select(1u, _e101, (1u < _e101))));
                            } else {
                                phi_187_ = u32();
                                phi_190_ = u32();
                            }
                            let _e108 = phi_187_;
                            let _e110 = phi_190_;
                            continue;
                            continuing {
                                phi_186_ = _e108;
                                phi_189_ = _e110;
                                break if !(_e94);
                            }
                        }
                        let _e112 = (2u * _e23.x);
                        let _e113 = (2u * _e23.y);
                        let _e114 = (select(1u, _e87, (1u < _e87)) - 1u);
                        let _e117 = (select(_e113, _e114, (_e114 < _e113)) * _e85);
                        let _e118 = (_e85 - 1u);
                        let _e120 = select(_e112, _e118, (_e118 < _e112));
                        let _e123 = local_1;
                        let _e127 = mips.member[(_e123 + (_e117 + _e120))];
                        let _e128 = (_e112 + 1u);
                        let _e130 = select(_e128, _e118, (_e118 < _e128));
                        let _e133 = local_2;
                        let _e137 = mips.member[(_e133 + (_e117 + _e130))];
                        let _e138 = (_e113 + 1u);
                        let _e141 = (select(_e138, _e114, (_e114 < _e138)) * _e85);
                        let _e144 = local_3;
                        let _e148 = mips.member[(_e144 + (_e141 + _e120))];
                        let _e151 = local_4;
                        let _e155 = mips.member[(_e151 + (_e141 + _e130))];
                        local = array<f32, 4>(_e127, _e137, _e148, _e155);
                        let _e159 = params.member.member_1;
                        let _e162 = params.member.member_2;
                        let _e164 = (0.75f * (_e159 * _e162));
                        let _e166 = local[0u];
                        let _e168 = local[1u];
                        if (_e166 != _e166) {
                            phi_429_ = true;
                        } else {
                            phi_429_ = (_e168 >= _e166);
                        }
                        let _e172 = phi_429_;
                        let _e173 = select(_e166, _e168, _e172);
                        let _e175 = local[2u];
                        if (_e173 != _e173) {
                            phi_444_ = true;
                        } else {
                            phi_444_ = (_e175 >= _e173);
                        }
                        let _e179 = phi_444_;
                        let _e180 = select(_e173, _e175, _e179);
                        let _e182 = local[3u];
                        if (_e180 != _e180) {
                            phi_459_ = true;
                        } else {
                            phi_459_ = (_e182 >= _e180);
                        }
                        let _e186 = phi_459_;
                        phi_312_ = 0u;
                        phi_315_ = 0f;
                        phi_317_ = 0f;
                        loop {
                            let _e189 = phi_312_;
                            let _e191 = phi_315_;
                            let _e193 = phi_317_;
                            local_5 = _e193;
                            local_6 = _e191;
                            let _e194 = (_e189 < 4u);
                            if _e194 {
                                if _e194 {
                                } else {
                                    phi_464_ = true;
                                    break;
                                }
                                let _e196 = local[_e189];
                                let _e198 = (_e164 - (select(_e180, _e182, _e186) - _e196));
                                let _e201 = params.member.member_3;
                                if (_e201 > 0f) {
                                    let _e204 = (_e198 / (_e201 * _e164));
                                    phi_359_ = select(0f, select(1f, _e204, (_e204 < 1f)), (_e204 > 0f));
                                } else {
                                    phi_359_ = select(0f, 1f, (_e198 >= 0f));
                                }
                                let _e212 = phi_359_;
                                if _e194 {
                                } else {
                                    phi_464_ = true;
                                    break;
                                }
                                let _e213 = local[_e189];
                                phi_313_ = (_e189 + 1u);
                                phi_316_ = (_e191 + _e212);
                                phi_318_ = (_e193 + (_e212 * _e213));
                            } else {
                                phi_313_ = u32();
                                phi_316_ = f32();
                                phi_318_ = f32();
                            }
                            let _e219 = phi_313_;
                            let _e221 = phi_316_;
                            let _e223 = phi_318_;
                            continue;
                            continuing {
                                phi_312_ = _e219;
                                phi_315_ = _e221;
                                phi_317_ = _e223;
                                phi_464_ = false;
                                break if !(_e194);
                            }
                        }
                        let _e226 = phi_464_;
                        if _e226 {
                            break;
                        }
                        let _e228 = local_5;
                        let _e230 = local_6;
                        phi_372_ = (_e228 / _e230);
                    }
                    let _e233 = phi_372_;
                    phi_376_ = 0u;
                    phi_379_ = 0u;
                    loop {
                        let _e235 = phi_376_;
                        let _e237 = phi_379_;
                        local_7 = _e237;
                        let _e238 = (_e235 < _e48);
                        if _e238 {
                            let _e239 = (_e235 & 31u);
                            let _e241 = (_e35 >> bitcast<u32>(_e239));
                            let _e245 = (_e45 >> bitcast<u32>(_e239));
                            phi_377_ = (_e235 + 1u);
                            phi_380_ = (_e237 + (select(1u, _e241, (1u < _e241)) * select(1u, _e245, (1u < _e245))));
                        } else {
                            phi_377_ = u32();
                            phi_380_ = u32();
                        }
                        let _e252 = phi_377_;
                        let _e254 = phi_380_;
                        continue;
                        continuing {
                            phi_376_ = _e252;
                            phi_379_ = _e254;
                            break if !(_e238);
                        }
                    }
                    let _e259 = local_7;
                    let _e260 = (_e259 + ((_e23.y * _e53) + _e23.x));
                    if (_e260 < arrayLength((&mips.member))) {
                    } else {
                        break;
                    }
                    mips.member[_e260] = _e233;
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
