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
    var phi_166_: u32;
    var phi_169_: u32;
    var phi_167_: u32;
    var phi_170_: u32;
    var local_1: u32;
    var local_2: u32;
    var local_3: u32;
    var local_4: u32;
    var phi_317_: f32;
    var phi_321_: u32;
    var phi_324_: f32;
    var phi_326_: f32;
    var phi_362_: f32;
    var phi_322_: u32;
    var phi_325_: f32;
    var phi_327_: f32;
    var phi_418_: bool;
    var local_5: f32;
    var local_6: f32;
    var phi_375_: f32;
    var phi_379_: u32;
    var phi_382_: u32;
    var phi_380_: u32;
    var phi_383_: u32;
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
                        phi_375_ = select(0f, select(65504f, _e73, (_e73 < 65504f)), (_e73 > 0f));
                    } else {
                        let _e78 = (_e46 - 1u);
                        let _e79 = (_e78 & 31u);
                        let _e81 = (_e33 >> bitcast<u32>(_e79));
                        let _e83 = select(1u, _e81, (1u < _e81));
                        let _e85 = (_e43 >> bitcast<u32>(_e79));
                        phi_166_ = 0u;
                        phi_169_ = 0u;
                        loop {
                            let _e89 = phi_166_;
                            let _e91 = phi_169_;
                            local_1 = _e91;
                            local_2 = _e91;
                            local_3 = _e91;
                            local_4 = _e91;
                            let _e92 = (_e89 < _e78);
                            if _e92 {
                                let _e93 = (_e89 & 31u);
                                let _e95 = (_e33 >> bitcast<u32>(_e93));
                                let _e99 = (_e43 >> bitcast<u32>(_e93));
                                phi_167_ = (_e89 + 1u);
                                phi_170_ = (_e91 + (select(1u, _e95, (1u < _e95)) * select(1u, _e99, (1u < _e99))));
                            } else {
                                phi_167_ = u32();
                                phi_170_ = u32();
                            }
                            let _e106 = phi_167_;
                            let _e108 = phi_170_;
                            continue;
                            continuing {
                                phi_166_ = _e106;
                                phi_169_ = _e108;
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
                        let _e170 = select(_e166, _e164, ((_e164 > _e166) || (_e166 != _e166)));
                        let _e172 = local[2u];
                        let _e174 = local[3u];
                        let _e178 = select(_e174, _e172, ((_e172 > _e174) || (_e174 != _e174)));
                        let _e185 = params.member.member_3;
                        let _e186 = (_e185 * _e162);
                        let _e187 = (_e186 <= 0f);
                        if _e187 {
                            phi_317_ = 0f;
                        } else {
                            phi_317_ = (1f / _e186);
                        }
                        let _e190 = phi_317_;
                        phi_321_ = 0u;
                        phi_324_ = 0f;
                        phi_326_ = 0f;
                        loop {
                            let _e194 = phi_321_;
                            let _e196 = phi_324_;
                            let _e198 = phi_326_;
                            local_5 = _e198;
                            local_6 = _e196;
                            let _e199 = (_e194 < 4u);
                            if _e199 {
                                if _e199 {
                                } else {
                                    phi_418_ = true;
                                    break;
                                }
                                let _e201 = local[_e194];
                                let _e202 = (select(_e178, _e170, ((_e170 > _e178) || (_e178 != _e178))) - _e201);
                                if _e187 {
                                    phi_362_ = select(0f, 1f, (_e202 <= _e162));
                                } else {
                                    let _e206 = ((_e202 * -(_e190)) + (_e162 * _e190));
                                    phi_362_ = select(0f, select(1f, _e206, (_e206 < 1f)), (_e206 > 0f));
                                }
                                let _e212 = phi_362_;
                                if _e199 {
                                } else {
                                    phi_418_ = true;
                                    break;
                                }
                                let _e213 = local[_e194];
                                phi_322_ = (_e194 + 1u);
                                phi_325_ = (_e196 + _e212);
                                phi_327_ = (_e198 + (_e212 * _e213));
                            } else {
                                phi_322_ = u32();
                                phi_325_ = f32();
                                phi_327_ = f32();
                            }
                            let _e219 = phi_322_;
                            let _e221 = phi_325_;
                            let _e223 = phi_327_;
                            continue;
                            continuing {
                                phi_321_ = _e219;
                                phi_324_ = _e221;
                                phi_326_ = _e223;
                                phi_418_ = false;
                                break if !(_e199);
                            }
                        }
                        let _e226 = phi_418_;
                        if _e226 {
                            break;
                        }
                        let _e228 = local_5;
                        let _e230 = local_6;
                        phi_375_ = (_e228 / _e230);
                    }
                    let _e233 = phi_375_;
                    phi_379_ = 0u;
                    phi_382_ = 0u;
                    loop {
                        let _e235 = phi_379_;
                        let _e237 = phi_382_;
                        local_7 = _e237;
                        let _e238 = (_e235 < _e46);
                        if _e238 {
                            let _e239 = (_e235 & 31u);
                            let _e241 = (_e33 >> bitcast<u32>(_e239));
                            let _e245 = (_e43 >> bitcast<u32>(_e239));
                            phi_380_ = (_e235 + 1u);
                            phi_383_ = (_e237 + (select(1u, _e241, (1u < _e241)) * select(1u, _e245, (1u < _e245))));
                        } else {
                            phi_380_ = u32();
                            phi_383_ = u32();
                        }
                        let _e252 = phi_380_;
                        let _e254 = phi_383_;
                        continue;
                        continuing {
                            phi_379_ = _e252;
                            phi_382_ = _e254;
                            break if !(_e238);
                        }
                    }
                    let _e259 = local_7;
                    mips.member[(_e259 + ((_e23.y * _e51) + _e23.x))] = _e233;
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
