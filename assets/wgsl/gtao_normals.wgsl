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

struct type_18 {
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

struct type_19 {
    member: type_18,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(2) 
var<uniform> params: type_19;
@group(0) @binding(1) 
var<storage, read_write> normals: type_10;

fn function_() {
    var phi_1004_: bool;
    var phi_1019_: bool;
    var phi_1034_: bool;
    var phi_1049_: bool;
    var phi_636_: vec3<f32>;
    var phi_654_: vec3<f32>;
    var phi_672_: vec3<f32>;
    var phi_690_: vec3<f32>;
    var phi_858_: vec3<f32>;
    var phi_892_: vec2<f32>;
    var phi_908_: f32;
    var phi_943_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e32 = id_1;
            let _e39 = params.member.member.member[0u];
            let _e44 = select(select(u32(_e39), 0u, (_e39 < 0f)), 4294967295u, (_e39 > 4294967000f));
            let _e49 = params.member.member.member[1u];
            let _e54 = select(select(u32(_e49), 0u, (_e49 < 0f)), 4294967295u, (_e49 > 4294967000f));
            if (_e32.x >= _e44) {
            } else {
                if (_e32.y >= _e54) {
                } else {
                    let _e59 = bitcast<i32>(_e32.x);
                    let _e61 = select(0i, _e59, (0i < _e59));
                    let _e63 = (bitcast<i32>(_e44) - 1i);
                    let _e66 = bitcast<u32>(select(_e61, _e63, (_e63 < _e61)));
                    let _e67 = bitcast<i32>(_e32.y);
                    let _e69 = select(0i, _e67, (0i < _e67));
                    let _e71 = (bitcast<i32>(_e54) - 1i);
                    let _e74 = bitcast<u32>(select(_e69, _e71, (_e71 < _e69)));
                    let _e75 = (_e74 * _e44);
                    let _e79 = depth.member[(_e75 + _e66)];
                    let _e83 = params.member.member.member_3;
                    let _e87 = select(_e83, _e79, select(false, (_e79 < _e83), (_e79 > 0f)));
                    let _e100 = params.member.member.member_1[0u];
                    let _e101 = (((((f32(_e66) + 0.5f) / _e39) * 2f) - 1f) * _e100);
                    let _e102 = (_e101 * _e87);
                    let _e109 = params.member.member.member_1[1u];
                    let _e110 = (((((f32(_e74) + 0.5f) / _e49) * -2f) + 1f) * _e109);
                    let _e111 = (_e110 * _e87);
                    let _e112 = (_e59 + -1i);
                    let _e114 = select(0i, _e112, (0i < _e112));
                    let _e117 = bitcast<u32>(select(_e114, _e63, (_e63 < _e114)));
                    let _e121 = depth.member[(_e75 + _e117)];
                    let _e125 = select(_e83, _e121, select(false, (_e121 < _e83), (_e121 > 0f)));
                    let _e134 = (_e59 + 1i);
                    let _e136 = select(0i, _e134, (0i < _e134));
                    let _e139 = bitcast<u32>(select(_e136, _e63, (_e63 < _e136)));
                    let _e143 = depth.member[(_e75 + _e139)];
                    let _e147 = select(_e83, _e143, select(false, (_e143 < _e83), (_e143 > 0f)));
                    let _e156 = (_e67 + -1i);
                    let _e158 = select(0i, _e156, (0i < _e156));
                    let _e161 = bitcast<u32>(select(_e158, _e71, (_e71 < _e158)));
                    let _e166 = depth.member[((_e161 * _e44) + _e66)];
                    let _e170 = select(_e83, _e166, select(false, (_e166 < _e83), (_e166 > 0f)));
                    let _e179 = (_e67 + 1i);
                    let _e181 = select(0i, _e179, (0i < _e179));
                    let _e184 = bitcast<u32>(select(_e181, _e71, (_e71 < _e181)));
                    let _e189 = depth.member[((_e184 * _e44) + _e66)];
                    let _e193 = select(_e83, _e189, select(false, (_e189 < _e83), (_e189 > 0f)));
                    let _e202 = (_e125 - _e87);
                    let _e203 = (_e147 - _e87);
                    let _e204 = (_e170 - _e87);
                    let _e205 = (_e193 - _e87);
                    let _e207 = ((_e203 - _e202) * 0.5f);
                    let _e209 = ((_e205 - _e204) * 0.5f);
                    let _e210 = (_e87 * 0.011f);
                    let _e212 = abs(_e202);
                    let _e213 = abs((_e202 + _e207));
                    if (_e212 != _e212) {
                        phi_1004_ = true;
                    } else {
                        phi_1004_ = (_e213 <= _e212);
                    }
                    let _e217 = phi_1004_;
                    let _e220 = (1.25f - (select(_e212, _e213, _e217) / _e210));
                    let _e224 = select(0f, select(1f, _e220, (_e220 < 1f)), (_e220 > 0f));
                    let _e226 = abs(_e203);
                    let _e227 = abs((_e203 - _e207));
                    if (_e226 != _e226) {
                        phi_1019_ = true;
                    } else {
                        phi_1019_ = (_e227 <= _e226);
                    }
                    let _e231 = phi_1019_;
                    let _e234 = (1.25f - (select(_e226, _e227, _e231) / _e210));
                    let _e238 = select(0f, select(1f, _e234, (_e234 < 1f)), (_e234 > 0f));
                    let _e240 = abs(_e204);
                    let _e241 = abs((_e204 + _e209));
                    if (_e240 != _e240) {
                        phi_1034_ = true;
                    } else {
                        phi_1034_ = (_e241 <= _e240);
                    }
                    let _e245 = phi_1034_;
                    let _e248 = (1.25f - (select(_e240, _e241, _e245) / _e210));
                    let _e252 = select(0f, select(1f, _e248, (_e248 < 1f)), (_e248 > 0f));
                    let _e254 = abs(_e205);
                    let _e255 = abs((_e205 - _e209));
                    if (_e254 != _e254) {
                        phi_1049_ = true;
                    } else {
                        phi_1049_ = (_e255 <= _e254);
                    }
                    let _e259 = phi_1049_;
                    let _e262 = (1.25f - (select(_e254, _e255, _e259) / _e210));
                    let _e266 = select(0f, select(1f, _e262, (_e262 < 1f)), (_e262 > 0f));
                    let _e267 = (((((((f32(_e117) + 0.5f) / _e39) * 2f) - 1f) * _e100) * _e125) - _e102);
                    let _e268 = ((_e110 * _e125) - _e111);
                    let _e274 = sqrt((((_e267 * _e267) + (_e268 * _e268)) + (_e202 * _e202)));
                    if (_e274 > 0f) {
                        phi_636_ = vec3<f32>((_e267 / _e274), (_e268 / _e274), (_e202 / _e274));
                    } else {
                        phi_636_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e281 = phi_636_;
                    let _e282 = (((((((f32(_e139) + 0.5f) / _e39) * 2f) - 1f) * _e100) * _e147) - _e102);
                    let _e283 = ((_e110 * _e147) - _e111);
                    let _e289 = sqrt((((_e282 * _e282) + (_e283 * _e283)) + (_e203 * _e203)));
                    if (_e289 > 0f) {
                        phi_654_ = vec3<f32>((_e282 / _e289), (_e283 / _e289), (_e203 / _e289));
                    } else {
                        phi_654_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e296 = phi_654_;
                    let _e297 = ((_e101 * _e170) - _e102);
                    let _e298 = (((((((f32(_e161) + 0.5f) / _e49) * -2f) + 1f) * _e109) * _e170) - _e111);
                    let _e304 = sqrt((((_e297 * _e297) + (_e298 * _e298)) + (_e204 * _e204)));
                    if (_e304 > 0f) {
                        phi_672_ = vec3<f32>((_e297 / _e304), (_e298 / _e304), (_e204 / _e304));
                    } else {
                        phi_672_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e311 = phi_672_;
                    let _e312 = ((_e101 * _e193) - _e102);
                    let _e313 = (((((((f32(_e184) + 0.5f) / _e49) * -2f) + 1f) * _e109) * _e193) - _e111);
                    let _e319 = sqrt((((_e312 * _e312) + (_e313 * _e313)) + (_e205 * _e205)));
                    if (_e319 > 0f) {
                        phi_690_ = vec3<f32>((_e312 / _e319), (_e313 / _e319), (_e205 / _e319));
                    } else {
                        phi_690_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e326 = phi_690_;
                    let _e343 = ((_e224 * _e252) + 0.01f);
                    let _e347 = select(0f, select(1f, _e343, (_e343 < 1f)), (_e343 > 0f));
                    let _e364 = ((_e252 * _e238) + 0.01f);
                    let _e368 = select(0f, select(1f, _e364, (_e364 < 1f)), (_e364 > 0f));
                    let _e388 = ((_e238 * _e266) + 0.01f);
                    let _e392 = select(0f, select(1f, _e388, (_e388 < 1f)), (_e388 > 0f));
                    let _e409 = ((_e266 * _e224) + 0.01f);
                    let _e413 = select(0f, select(1f, _e409, (_e409 < 1f)), (_e409 > 0f));
                    let _e417 = ((((((_e281.y * _e311.z) - (_e311.y * _e281.z)) * _e347) + (((_e311.y * _e296.z) - (_e296.y * _e311.z)) * _e368)) + (((_e296.y * _e326.z) - (_e326.y * _e296.z)) * _e392)) + (((_e326.y * _e281.z) - (_e281.y * _e326.z)) * _e413));
                    let _e418 = ((((((_e281.z * _e311.x) - (_e311.z * _e281.x)) * _e347) + (((_e311.z * _e296.x) - (_e296.z * _e311.x)) * _e368)) + (((_e296.z * _e326.x) - (_e326.z * _e296.x)) * _e392)) + (((_e326.z * _e281.x) - (_e281.z * _e326.x)) * _e413));
                    let _e419 = ((((((_e281.x * _e311.y) - (_e311.x * _e281.y)) * _e347) + (((_e311.x * _e296.y) - (_e296.x * _e311.y)) * _e368)) + (((_e296.x * _e326.y) - (_e326.x * _e296.y)) * _e392)) + (((_e326.x * _e281.y) - (_e281.x * _e326.y)) * _e413));
                    let _e425 = sqrt((((_e417 * _e417) + (_e418 * _e418)) + (_e419 * _e419)));
                    if (_e425 > 0f) {
                        phi_858_ = vec3<f32>((_e417 / _e425), (_e418 / _e425), (_e419 / _e425));
                    } else {
                        phi_858_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e432 = phi_858_;
                    let _e436 = -(_e432.z);
                    let _e441 = ((abs(_e432.x) + abs(_e432.y)) + abs(_e436));
                    let _e442 = (_e432.x / _e441);
                    let _e443 = (_e432.y / _e441);
                    if (_e436 < 0f) {
                        phi_892_ = vec2<f32>(((1f - abs(_e443)) * select(1f, -1f, (_e442 < 0f))), ((1f - abs(_e442)) * select(1f, -1f, (_e443 < 0f))));
                    } else {
                        phi_892_ = vec2<f32>(_e442, _e443);
                    }
                    let _e458 = phi_892_;
                    if (_e458.x != _e458.x) {
                        phi_908_ = 0f;
                    } else {
                        phi_908_ = select(-1f, select(1f, _e458.x, (_e458.x < 1f)), (_e458.x > -1f));
                    }
                    let _e466 = phi_908_;
                    let _e471 = ((_e466 * 127f) + (0.5f * select(1f, -1f, (_e466 < 0f))));
                    if (_e458.y != _e458.y) {
                        phi_943_ = 0f;
                    } else {
                        phi_943_ = select(-1f, select(1f, _e458.y, (_e458.y < 1f)), (_e458.y > -1f));
                    }
                    let _e488 = phi_943_;
                    let _e493 = ((_e488 * 127f) + (0.5f * select(1f, -1f, (_e488 < 0f))));
                    let _e507 = ((_e32.y * _e44) + _e32.x);
                    if (_e507 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    normals.member[_e507] = ((bitcast<u32>(select(0i, select(select(i32(_e471), i32(-2147483648), (_e471 < -2147483600f)), 2147483647i, (_e471 > 2147483500f)), (_e471 == _e471))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e493), i32(-2147483648), (_e493 < -2147483600f)), 2147483647i, (_e493 > 2147483500f)), (_e493 == _e493))) & 255u) << bitcast<u32>(8i)));
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_normals(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
