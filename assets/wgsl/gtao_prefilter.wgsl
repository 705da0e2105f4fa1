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
    var phi_185_: u32;
    var phi_188_: u32;
    var phi_186_: u32;
    var phi_189_: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var phi_423_: bool;
    var phi_438_: bool;
    var phi_453_: bool;
    var phi_311_: u32;
    var phi_314_: f32;
    var phi_316_: f32;
    var phi_358_: f32;
    var phi_312_: u32;
    var phi_315_: f32;
    var phi_317_: f32;
    var phi_458_: bool;
    var local_5: f32;
    var local_6: f32;
    var phi_371_: f32;
    var phi_375_: u32;
    var phi_378_: u32;
    var phi_376_: u32;
    var phi_379_: u32;
    var local_7: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e23 = id_1;
            let _e28 = params.member.member.member[0u];
            let _e33 = select(select(u32(_e28), 0u, (_e28 < 0f)), 4294967295u, (_e28 > 4294967000f));
            let _e38 = params.member.member.member[1u];
            let _e43 = select(select(u32(_e38), 0u, (_e38 < 0f)), 4294967295u, (_e38 > 4294967000f));
            let _e46 = params.member.member_12;
            let _e47 = (_e46 & 31u);
            let _e49 = (_e33 >> bitcast<u32>(_e47));
            let _e51 = select(1u, _e49, (1u < _e49));
            let _e53 = (_e43 >> bitcast<u32>(_e47));
            if (_e23.x >= _e51) {
            } else {
                if (_e23.y >= select(1u, _e53, (1u < _e53))) {
                } else {
                    if (_e46 == 0u) {
                        let _e65 = depth.member[((_e23.y * _e33) + _e23.x)];
                        let _e69 = params.member.member.member_3;
                        let _e73 = select(_e69, _e65, select(false, (_e65 < _e69), (_e65 > 0f)));
                        phi_371_ = select(0f, select(65504f, _e73, (_e73 < 65504f)), (_e73 > 0f));
                    } else {
                        let _e78 = (_e46 - 1u);
                        let _e79 = (_e78 & 31u);
                        let _e81 = (_e33 >> bitcast<u32>(_e79));
                        let _e83 = select(1u, _e81, (1u < _e81));
                        let _e85 = (_e43 >> bitcast<u32>(_e79));
                        phi_185_ = 0u;
                        phi_188_ = 0u;
                        loop {
                            let _e89 = phi_185_;
                            let _e91 = phi_188_;
                            local_1 = _e91;
                            local_2 = _e91;
                            local_3 = _e91;
                            local_4 = _e91;
                            let _e92 = (_e89 < _e78);
                            if _e92 {
                                let _e93 = (_e89 & 31u);
                                let _e95 = (_e33 >> bitcast<u32>(_e93));
                                let _e99 = (_e43 >> bitcast<u32>(_e93));
                                phi_186_ = (_e89 + 1u);
                                phi_189_ = (_e91 + (select(1u, _e95, (1u < _e95)) * select(1u, _e99, (1u < _e99))));
                            } else {
                                phi_186_ = u32();
                                phi_189_ = u32();
                            }
                            let _e106 = phi_186_;
                            let _e108 = phi_189_;
                            continue;
                            continuing {
                                phi_185_ = _e106;
                                phi_188_ = _e108;
                                break if !(_e92);
                            }
                        }
                        let _e110 = (2u * _e23.x);
                        let _e111 = (2u * _e23.y);
                        let _e112 = (select(1u, _e85, (1u < _e85)) - 1u);
                        let _e115 = (select(_e111, _e112, (_e112 < _e111)) * _e83);
                        let _e116 = (_e83 - 1u);
                        let _e118 = select(_e110, _e116, (_e116 < _e110));
                        let _e121 = local_1;
                        let _e125 = mips.member[(_e121 + (_e115 + _e118))];
                        let _e126 = (_e110 + 1u);
                        let _e128 = select(_e126, _e116, (_e116 < _e126));
                        let _e131 = local_2;
                        let _e135 = mips.member[(_e131 + (_e115 + _e128))];
                        let _e136 = (_e111 + 1u);
                        let _e139 = (select(_e136, _e112, (_e112 < _e136)) * _e83);
                        let _e142 = local_3;
                        let _e146 = mips.member[(_e142 + (_e139 + _e118))];
                        let _e149 = local_4;
                        let _e153 = mips.member[(_e149 + (_e139 + _e128))];
                        local = array<f32, 4>(_e125, _e135, _e146, _e153);
                        let _e157 = params.member.member_1;
                        let _e160 = params.member.member_2;
                        let _e162 = (0.75f * (_e157 * _e160));
                        let _e164 = local[0u];
                        let _e166 = local[1u];
                        if (_e164 != _e164) {
                            phi_423_ = true;
                        } else {
                            phi_423_ = (_e166 >= _e164);
                        }
                        let _e170 = phi_423_;
                        let _e171 = select(_e164, _e166, _e170);
                        let _e173 = local[2u];
                        if (_e171 != _e171) {
                            phi_438_ = true;
                        } else {
                            phi_438_ = (_e173 >= _e171);
                        }
                        let _e177 = phi_438_;
                        let _e178 = select(_e171, _e173, _e177);
                        let _e180 = local[3u];
                        if (_e178 != _e178) {
                            phi_453_ = true;
                        } else {
                            phi_453_ = (_e180 >= _e178);
                        }
                        let _e184 = phi_453_;
                        phi_311_ = 0u;
                        phi_314_ = 0f;
                        phi_316_ = 0f;
                        loop {
                            let _e187 = phi_311_;
                            let _e189 = phi_314_;
                            let _e191 = phi_316_;
                            local_5 = _e191;
                            local_6 = _e189;
                            let _e192 = (_e187 < 4u);
                            if _e192 {
                                if _e192 {
                                } else {
                                    phi_458_ = true;
                                    break;
                                }
                                let _e194 = local[_e187];
                                let _e196 = (_e162 - (select(_e178, _e180, _e184) - _e194));
                                let _e199 = params.member.member_3;
                                if (_e199 > 0f) {
                                    let _e202 = (_e196 / (_e199 * _e162));
                                    phi_358_ = select(0f, select(1f, _e202, (_e202 < 1f)), (_e202 > 0f));
                                } else {
                                    phi_358_ = select(0f, 1f, (_e196 >= 0f));
                                }
                                let _e210 = phi_358_;
                                if _e192 {
                                } else {
                                    phi_458_ = true;
                                    break;
                                }
                                let _e211 = local[_e187];
                                phi_312_ = (_e187 + 1u);
                                phi_315_ = (_e189 + _e210);
                                phi_317_ = (_e191 + (_e210 * _e211));
                            } else {
                                phi_312_ = u32();
                                phi_315_ = f32();
                                phi_317_ = f32();
                            }
                            let _e217 = phi_312_;
                            let _e219 = phi_315_;
                            let _e221 = phi_317_;
                            continue;
                            continuing {
                                phi_311_ = _e217;
                                phi_314_ = _e219;
                                phi_316_ = _e221;
                                phi_458_ = false;
                                break if !(_e192);
                            }
                        }
                        let _e224 = phi_458_;
                        if _e224 {
                            break;
                        }
                        let _e226 = local_5;
                        let _e228 = local_6;
                        phi_371_ = (_e226 / _e228);
                    }
                    let _e231 = phi_371_;
                    phi_375_ = 0u;
                    phi_378_ = 0u;
                    loop {
                        let _e233 = phi_375_;
                        let _e235 = phi_378_;
                        local_7 = _e235;
                        let _e236 = (_e233 < _e46);
                        if _e236 {
                            let _e237 = (_e233 & 31u);
                            let _e239 = (_e33 >> bitcast<u32>(_e237));
                            let _e243 = (_e43 >> bitcast<u32>(_e237));
                            phi_376_ = (_e233 + 1u);
                            phi_379_ = (_e235 + (select(1u, _e239, (1u < _e239)) * select(1u, _e243, (1u < _e243))));
                        } else {
                            phi_376_ = u32();
                            phi_379_ = u32();
                        }
                        let _e250 = phi_376_;
                        let _e252 = phi_379_;
                        continue;
                        continuing {
                            phi_375_ = _e250;
                            phi_378_ = _e252;
                            break if !(_e236);
                        }
                    }
                    let _e257 = local_7;
                    mips.member[(_e257 + ((_e23.y * _e51) + _e23.x))] = _e231;
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
