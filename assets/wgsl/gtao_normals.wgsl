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
    var phi_994_: bool;
    var phi_1009_: bool;
    var phi_1024_: bool;
    var phi_1039_: bool;
    var phi_637_: vec3<f32>;
    var phi_655_: vec3<f32>;
    var phi_673_: vec3<f32>;
    var phi_691_: vec3<f32>;
    var phi_859_: vec3<f32>;
    var phi_893_: vec2<f32>;
    var phi_909_: f32;
    var phi_944_: f32;

    let _e31 = id_1;
    let _e36 = params.member.member.member[0u];
    let _e41 = select(select(u32(_e36), 0u, (_e36 < 0f)), 4294967295u, (_e36 > 4294967000f));
    let _e46 = params.member.member.member[1u];
    let _e51 = select(select(u32(_e46), 0u, (_e46 < 0f)), 4294967295u, (_e46 > 4294967000f));
    if (_e31.x >= _e41) {
    } else {
        if (_e31.y >= _e51) {
        } else {
            let _e58 = bitcast<i32>(_e31.x);
            let _e60 = select(0i, _e58, (0i < _e58));
            let _e62 = (bitcast<i32>(_e41) - 1i);
            let _e65 = bitcast<u32>(select(_e60, _e62, (_e62 < _e60)));
            let _e66 = bitcast<i32>(_e31.y);
            let _e68 = select(0i, _e66, (0i < _e66));
            let _e70 = (bitcast<i32>(_e51) - 1i);
            let _e73 = bitcast<u32>(select(_e68, _e70, (_e70 < _e68)));
            let _e74 = (_e73 * _e41);
            let _e78 = depth.member[(_e74 + _e65)];
            let _e82 = params.member.member.member_3;
            let _e86 = select(_e82, _e78, select(false, (_e78 < _e82), (_e78 > 0f)));
            let _e99 = params.member.member.member_1[0u];
            let _e100 = (((((f32(_e65) + 0.5f) / _e36) * 2f) - 1f) * _e99);
            let _e101 = (_e100 * _e86);
            let _e108 = params.member.member.member_1[1u];
            let _e109 = (((((f32(_e73) + 0.5f) / _e46) * -2f) + 1f) * _e108);
            let _e110 = (_e109 * _e86);
            let _e111 = (_e58 + -1i);
            let _e113 = select(0i, _e111, (0i < _e111));
            let _e116 = bitcast<u32>(select(_e113, _e62, (_e62 < _e113)));
            let _e120 = depth.member[(_e74 + _e116)];
            let _e124 = select(_e82, _e120, select(false, (_e120 < _e82), (_e120 > 0f)));
            let _e133 = (_e58 + 1i);
            let _e135 = select(0i, _e133, (0i < _e133));
            let _e138 = bitcast<u32>(select(_e135, _e62, (_e62 < _e135)));
            let _e142 = depth.member[(_e74 + _e138)];
            let _e146 = select(_e82, _e142, select(false, (_e142 < _e82), (_e142 > 0f)));
            let _e155 = (_e66 + -1i);
            let _e157 = select(0i, _e155, (0i < _e155));
            let _e160 = bitcast<u32>(select(_e157, _e70, (_e70 < _e157)));
            let _e165 = depth.member[((_e160 * _e41) + _e65)];
            let _e169 = select(_e82, _e165, select(false, (_e165 < _e82), (_e165 > 0f)));
            let _e178 = (_e66 + 1i);
            let _e180 = select(0i, _e178, (0i < _e178));
            let _e183 = bitcast<u32>(select(_e180, _e70, (_e70 < _e180)));
            let _e188 = depth.member[((_e183 * _e41) + _e65)];
            let _e192 = select(_e82, _e188, select(false, (_e188 < _e82), (_e188 > 0f)));
            let _e201 = (_e124 - _e86);
            let _e202 = (_e146 - _e86);
            let _e203 = (_e169 - _e86);
            let _e204 = (_e192 - _e86);
            let _e206 = ((_e202 - _e201) * 0.5f);
            let _e208 = ((_e204 - _e203) * 0.5f);
            let _e209 = (_e86 * 0.011f);
            let _e211 = abs(_e201);
            let _e212 = abs((_e201 + _e206));
            if (_e211 != _e211) {
                phi_994_ = true;
            } else {
                phi_994_ = (_e212 <= _e211);
            }
            let _e216 = phi_994_;
            let _e219 = (1.25f - (select(_e211, _e212, _e216) / _e209));
            let _e223 = select(0f, select(1f, _e219, (_e219 < 1f)), (_e219 > 0f));
            let _e225 = abs(_e202);
            let _e226 = abs((_e202 - _e206));
            if (_e225 != _e225) {
                phi_1009_ = true;
            } else {
                phi_1009_ = (_e226 <= _e225);
            }
            let _e230 = phi_1009_;
            let _e233 = (1.25f - (select(_e225, _e226, _e230) / _e209));
            let _e237 = select(0f, select(1f, _e233, (_e233 < 1f)), (_e233 > 0f));
            let _e239 = abs(_e203);
            let _e240 = abs((_e203 + _e208));
            if (_e239 != _e239) {
                phi_1024_ = true;
            } else {
                phi_1024_ = (_e240 <= _e239);
            }
            let _e244 = phi_1024_;
            let _e247 = (1.25f - (select(_e239, _e240, _e244) / _e209));
            let _e251 = select(0f, select(1f, _e247, (_e247 < 1f)), (_e247 > 0f));
            let _e253 = abs(_e204);
            let _e254 = abs((_e204 - _e208));
            if (_e253 != _e253) {
                phi_1039_ = true;
            } else {
                phi_1039_ = (_e254 <= _e253);
            }
            let _e258 = phi_1039_;
            let _e261 = (1.25f - (select(_e253, _e254, _e258) / _e209));
            let _e265 = select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f));
            let _e266 = (((((((f32(_e116) + 0.5f) / _e36) * 2f) - 1f) * _e99) * _e124) - _e101);
            let _e267 = ((_e109 * _e124) - _e110);
            let _e273 = sqrt((((_e266 * _e266) + (_e267 * _e267)) + (_e201 * _e201)));
            if (_e273 > 0f) {
                phi_637_ = vec3<f32>((_e266 / _e273), (_e267 / _e273), (_e201 / _e273));
            } else {
                phi_637_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e280 = phi_637_;
            let _e281 = (((((((f32(_e138) + 0.5f) / _e36) * 2f) - 1f) * _e99) * _e146) - _e101);
            let _e282 = ((_e109 * _e146) - _e110);
            let _e288 = sqrt((((_e281 * _e281) + (_e282 * _e282)) + (_e202 * _e202)));
            if (_e288 > 0f) {
                phi_655_ = vec3<f32>((_e281 / _e288), (_e282 / _e288), (_e202 / _e288));
            } else {
                phi_655_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e295 = phi_655_;
            let _e296 = ((_e100 * _e169) - _e101);
            let _e297 = (((((((f32(_e160) + 0.5f) / _e46) * -2f) + 1f) * _e108) * _e169) - _e110);
            let _e303 = sqrt((((_e296 * _e296) + (_e297 * _e297)) + (_e203 * _e203)));
            if (_e303 > 0f) {
                phi_673_ = vec3<f32>((_e296 / _e303), (_e297 / _e303), (_e203 / _e303));
            } else {
                phi_673_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e310 = phi_673_;
            let _e311 = ((_e100 * _e192) - _e101);
            let _e312 = (((((((f32(_e183) + 0.5f) / _e46) * -2f) + 1f) * _e108) * _e192) - _e110);
            let _e318 = sqrt((((_e311 * _e311) + (_e312 * _e312)) + (_e204 * _e204)));
            if (_e318 > 0f) {
                phi_691_ = vec3<f32>((_e311 / _e318), (_e312 / _e318), (_e204 / _e318));
            } else {
                phi_691_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e325 = phi_691_;
            let _e342 = ((_e223 * _e251) + 0.01f);
            let _e346 = select(0f, select(1f, _e342, (_e342 < 1f)), (_e342 > 0f));
            let _e363 = ((_e251 * _e237) + 0.01f);
            let _e367 = select(0f, select(1f, _e363, (_e363 < 1f)), (_e363 > 0f));
            let _e387 = ((_e237 * _e265) + 0.01f);
            let _e391 = select(0f, select(1f, _e387, (_e387 < 1f)), (_e387 > 0f));
            let _e408 = ((_e265 * _e223) + 0.01f);
            let _e412 = select(0f, select(1f, _e408, (_e408 < 1f)), (_e408 > 0f));
            let _e416 = ((((((_e280.y * _e310.z) - (_e310.y * _e280.z)) * _e346) + (((_e310.y * _e295.z) - (_e295.y * _e310.z)) * _e367)) + (((_e295.y * _e325.z) - (_e325.y * _e295.z)) * _e391)) + (((_e325.y * _e280.z) - (_e280.y * _e325.z)) * _e412));
            let _e417 = ((((((_e280.z * _e310.x) - (_e310.z * _e280.x)) * _e346) + (((_e310.z * _e295.x) - (_e295.z * _e310.x)) * _e367)) + (((_e295.z * _e325.x) - (_e325.z * _e295.x)) * _e391)) + (((_e325.z * _e280.x) - (_e280.z * _e325.x)) * _e412));
            let _e418 = ((((((_e280.x * _e310.y) - (_e310.x * _e280.y)) * _e346) + (((_e310.x * _e295.y) - (_e295.x * _e310.y)) * _e367)) + (((_e295.x * _e325.y) - (_e325.x * _e295.y)) * _e391)) + (((_e325.x * _e280.y) - (_e280.x * _e325.y)) * _e412));
            let _e424 = sqrt((((_e416 * _e416) + (_e417 * _e417)) + (_e418 * _e418)));
            if (_e424 > 0f) {
                phi_859_ = vec3<f32>((_e416 / _e424), (_e417 / _e424), (_e418 / _e424));
            } else {
                phi_859_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e431 = phi_859_;
            let _e435 = -(_e431.z);
            let _e440 = ((abs(_e431.x) + abs(_e431.y)) + abs(_e435));
            let _e441 = (_e431.x / _e440);
            let _e442 = (_e431.y / _e440);
            if (_e435 < 0f) {
                phi_893_ = vec2<f32>(((1f - abs(_e442)) * select(1f, -1f, (_e441 < 0f))), ((1f - abs(_e441)) * select(1f, -1f, (_e442 < 0f))));
            } else {
                phi_893_ = vec2<f32>(_e441, _e442);
            }
            let _e457 = phi_893_;
            if (_e457.x != _e457.x) {
                phi_909_ = 0f;
            } else {
                phi_909_ = select(-1f, select(1f, _e457.x, (_e457.x < 1f)), (_e457.x > -1f));
            }
            let _e465 = phi_909_;
            let _e470 = ((_e465 * 127f) + (0.5f * select(1f, -1f, (_e465 < 0f))));
            if (_e457.y != _e457.y) {
                phi_944_ = 0f;
            } else {
                phi_944_ = select(-1f, select(1f, _e457.y, (_e457.y < 1f)), (_e457.y > -1f));
            }
            let _e487 = phi_944_;
            let _e492 = ((_e487 * 127f) + (0.5f * select(1f, -1f, (_e487 < 0f))));
            normals.member[((_e31.y * _e41) + _e31.x)] = ((bitcast<u32>(select(0i, select(select(i32(_e470), i32(-2147483648), (_e470 < -2147483600f)), 2147483647i, (_e470 > 2147483500f)), (_e470 == _e470))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e492), i32(-2147483648), (_e492 < -2147483600f)), 2147483647i, (_e492 > 2147483500f)), (_e492 == _e492))) & 255u) << bitcast<u32>(8i)));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_normals(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
