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

struct type_21 {
    member: type_5,
    member_1: type_5,
    member_2: u32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_22 {
    member: type_21,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(5) 
var<uniform> params: type_22;
@group(0) @binding(2) 
var<storage> half_depth: type_7;
@group(0) @binding(3) 
var<storage> half_ao: type_7;
@group(0) @binding(4) 
var<storage, read_write> ao: type_7;

fn function_() {
    var local: array<f32, 2>;
    var local_1: array<f32, 2>;
    var local_2: array<f32, 2>;
    var local_3: array<f32, 2>;
    var phi_129_: bool;
    var phi_131_: bool;
    var phi_132_: bool;
    var phi_133_: bool;
    var phi_134_: bool;
    var phi_431_: u32;
    var phi_434_: f32;
    var phi_436_: f32;
    var phi_438_: f32;
    var phi_440_: f32;
    var phi_521_: f32;
    var phi_528_: f32;
    var phi_432_: u32;
    var phi_435_: f32;
    var phi_437_: f32;
    var phi_439_: f32;
    var phi_441_: f32;
    var phi_620_: bool;
    var local_4: f32;
    var local_5: f32;
    var local_6: f32;
    var local_7: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e39 = id_1;
            let _e45 = params.member.member.member_4;
            let _e46 = (_e39.x + _e45);
            let _e47 = (_e39.y + _e45);
            let _e52 = params.member.member.member[0u];
            let _e57 = select(select(u32(_e52), 0u, (_e52 < 0f)), 4294967295u, (_e52 > 4294967000f));
            let _e62 = params.member.member.member[1u];
            if (_e46 >= _e45) {
                if (_e47 >= _e45) {
                    let _e71 = ((_e46 + _e45) < _e57);
                    if _e71 {
                        phi_129_ = ((_e47 + _e45) < select(select(u32(_e62), 0u, (_e62 < 0f)), 4294967295u, (_e62 > 4294967000f)));
                    } else {
                        phi_129_ = bool();
                    }
                    let _e75 = phi_129_;
                    phi_131_ = _e75;
                    phi_132_ = select(true, false, _e71);
                } else {
                    phi_131_ = bool();
                    phi_132_ = true;
                }
                let _e78 = phi_131_;
                let _e80 = phi_132_;
                phi_133_ = _e78;
                phi_134_ = _e80;
            } else {
                phi_133_ = bool();
                phi_134_ = true;
            }
            let _e82 = phi_133_;
            let _e84 = phi_134_;
            if select(_e82, false, _e84) {
                let _e87 = ((_e47 * _e57) + _e46);
                let _e90 = depth.member[_e87];
                let _e94 = params.member.member.member_3;
                let _e100 = normals.member[_e87];
                let _e103 = f32(bitcast<i32>((_e100 & 255u)));
                let _e107 = (select(_e103, (_e103 - 256f), (_e103 >= 128f)) * 0.007874016f);
                let _e110 = select(-1f, _e107, ((_e107 > -1f) || false));
                let _e115 = f32(bitcast<i32>(((_e100 >> bitcast<u32>(8u)) & 255u)));
                let _e119 = (select(_e115, (_e115 - 256f), (_e115 >= 128f)) * 0.007874016f);
                let _e122 = select(-1f, _e119, ((_e119 > -1f) || false));
                let _e124 = (1f - abs(_e110));
                let _e125 = abs(_e122);
                let _e126 = (_e124 - _e125);
                let _e127 = (_e126 < 0f);
                let _e135 = select(_e110, ((1f - _e125) * select(1f, -1f, (_e110 < 0f))), _e127);
                let _e136 = select(_e122, (_e124 * select(1f, -1f, (_e122 < 0f))), _e127);
                let _e143 = (1f / sqrt((((_e135 * _e135) + (_e136 * _e136)) + (_e126 * _e126))));
                let _e144 = (_e135 * _e143);
                let _e145 = (_e136 * _e143);
                let _e146 = (_e126 * _e143);
                let _e148 = f32(bitcast<i32>(_e46));
                let _e150 = f32(bitcast<i32>(_e47));
                let _e155 = params.member.member.member_1[0u];
                let _e160 = params.member.member.member_1[1u];
                let _e162 = (2f * _e155);
                let _e168 = (2f * _e160);
                let _e169 = (_e168 / _e62);
                let _e179 = params.member.member_3;
                let _e184 = ((_e148 * 0.5f) - 0.25f);
                let _e186 = ((_e150 * 0.5f) - 0.25f);
                let _e187 = floor(_e184);
                let _e188 = floor(_e186);
                let _e189 = (_e184 - _e187);
                let _e190 = (_e186 - _e188);
                let _e195 = params.member.member_1.member[0u];
                let _e200 = select(select(u32(_e195), 0u, (_e195 < 0f)), 4294967295u, (_e195 > 4294967000f));
                let _e205 = params.member.member_1.member[1u];
                let _e210 = select(select(u32(_e205), 0u, (_e205 < 0f)), 4294967295u, (_e205 > 4294967000f));
                let _e214 = params.member.member_1.member_4;
                let _e215 = f32(_e214);
                let _e218 = f32(((_e200 - _e214) - 1u));
                let _e223 = (_e187 + 1f);
                local[0u] = select(_e215, select(_e218, _e187, (_e187 < _e218)), (_e187 > _e215));
                local[1u] = select(_e215, select(_e218, _e223, (_e223 < _e218)), (_e223 > _e215));
                let _e232 = f32(((_e210 - _e214) - 1u));
                let _e237 = (_e188 + 1f);
                local_1[0u] = select(_e215, select(_e232, _e188, (_e188 < _e232)), (_e188 > _e215));
                local_1[1u] = select(_e215, select(_e232, _e237, (_e237 < _e232)), (_e237 > _e215));
                let _e244 = local[0u];
                let _e246 = (_e162 / _e195);
                let _e250 = local[1u];
                local_2[0u] = (_e144 * (((_e244 + 0.5f) * _e246) - _e155));
                local_2[1u] = (_e144 * (((_e250 + 0.5f) * _e246) - _e155));
                let _e257 = local_1[0u];
                let _e259 = (_e168 / _e205);
                let _e264 = local_1[1u];
                local_3[0u] = (_e145 * (-(((_e257 + 0.5f) * _e259)) + _e160));
                local_3[1u] = (_e145 * (-(((_e264 + 0.5f) * _e259)) + _e160));
                phi_431_ = 0u;
                phi_434_ = 0x1.fffffep+127f;
                phi_436_ = 1f;
                phi_438_ = 0f;
                phi_440_ = 0f;
                loop {
                    let _e273 = phi_431_;
                    let _e275 = phi_434_;
                    let _e277 = phi_436_;
                    let _e279 = phi_438_;
                    let _e281 = phi_440_;
                    local_4 = _e279;
                    local_5 = _e281;
                    local_6 = _e279;
                    local_7 = _e277;
                    let _e282 = (_e273 < 4u);
                    if _e282 {
                        let _e283 = (_e273 & 1u);
                        let _e285 = (_e273 >> bitcast<u32>(1i));
                        let _e286 = (_e283 < 2u);
                        if _e286 {
                        } else {
                            phi_620_ = true;
                            break;
                        }
                        let _e288 = local[_e283];
                        let _e291 = f32(bitcast<i32>((_e200 - 1u)));
                        let _e300 = (_e285 < 2u);
                        if _e300 {
                        } else {
                            phi_620_ = true;
                            break;
                        }
                        let _e302 = local_1[_e285];
                        let _e305 = f32(bitcast<i32>((_e210 - 1u)));
                        let _e315 = (((bitcast<u32>((floor(select(0f, select(_e305, _e302, (_e302 < _e305)), (_e302 > 0f))) + 8388608f)) - 1258291200u) * _e200) + (bitcast<u32>((floor(select(0f, select(_e291, _e288, (_e288 < _e291)), (_e288 > 0f))) + 8388608f)) - 1258291200u));
                        let _e318 = half_ao.member[_e315];
                        let _e321 = half_depth.member[_e315];
                        if (_e283 == 0u) {
                            phi_521_ = (1f - _e189);
                        } else {
                            phi_521_ = _e189;
                        }
                        let _e325 = phi_521_;
                        if (_e285 == 0u) {
                            phi_528_ = (1f - _e190);
                        } else {
                            phi_528_ = _e190;
                        }
                        let _e329 = phi_528_;
                        let _e330 = (_e325 * _e329);
                        if _e286 {
                        } else {
                            phi_620_ = true;
                            break;
                        }
                        let _e332 = local_2[_e283];
                        if _e300 {
                        } else {
                            phi_620_ = true;
                            break;
                        }
                        let _e334 = local_3[_e285];
                        let _e339 = abs(((_e321 * ((_e332 + _e334) - _e146)) - (_e90 * (((_e144 * (((_e148 + 0.5f) * (_e162 / _e52)) - _e155)) + (_e145 * (-(((_e150 + 0.5f) * _e169)) + _e160))) - _e146))));
                        let _e343 = params.member.member_1.member_3;
                        let _e346 = select(false, (_e321 < _e343), (_e321 > 0f));
                        let _e348 = (1f - (_e339 * (1f / (_e90 * (_e179 * _e169)))));
                        let _e354 = select(_e330, select(0f, (_e330 * select(0f, _e348, ((_e348 > 0f) || false))), _e346), select(false, (_e90 < _e94), (_e90 > 0f)));
                        let _e356 = select(false, (_e339 < _e275), _e346);
                        phi_432_ = (_e273 + 1u);
                        phi_435_ = select(_e275, _e339, _e356);
                        phi_437_ = select(_e277, _e318, _e356);
                        phi_439_ = (_e279 + _e354);
                        phi_441_ = (_e281 + (_e354 * _e318));
                    } else {
                        phi_432_ = u32();
                        phi_435_ = f32();
                        phi_437_ = f32();
                        phi_439_ = f32();
                        phi_441_ = f32();
                    }
                    let _e364 = phi_432_;
                    let _e366 = phi_435_;
                    let _e368 = phi_437_;
                    let _e370 = phi_439_;
                    let _e372 = phi_441_;
                    continue;
                    continuing {
                        phi_431_ = _e364;
                        phi_434_ = _e366;
                        phi_436_ = _e368;
                        phi_438_ = _e370;
                        phi_440_ = _e372;
                        phi_620_ = false;
                        break if !(_e282);
                    }
                }
                let _e375 = phi_620_;
                if _e375 {
                    break;
                }
                let _e377 = local_4;
                let _e380 = local_5;
                let _e382 = local_6;
                let _e385 = local_7;
                ao.member[_e87] = select(_e385, (_e380 / _e382), (_e377 > 0f));
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn half_upsample(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
