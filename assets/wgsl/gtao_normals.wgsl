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
    var phi_668_: vec3<f32>;
    var phi_686_: vec3<f32>;
    var phi_704_: vec3<f32>;
    var phi_722_: vec3<f32>;
    var phi_890_: vec3<f32>;
    var phi_926_: vec2<f32>;
    var phi_942_: f32;
    var phi_977_: f32;

    let _e30 = id_1;
    let _e35 = params.member.member.member[0u];
    let _e40 = select(select(u32(_e35), 0u, (_e35 < 0f)), 4294967295u, (_e35 > 4294967000f));
    let _e45 = params.member.member.member[1u];
    let _e50 = select(select(u32(_e45), 0u, (_e45 < 0f)), 4294967295u, (_e45 > 4294967000f));
    if (_e30.x >= _e40) {
    } else {
        if (_e30.y >= _e50) {
        } else {
            let _e57 = bitcast<i32>(_e30.x);
            let _e59 = select(0i, _e57, (0i < _e57));
            let _e61 = (bitcast<i32>(_e40) - 1i);
            let _e64 = bitcast<u32>(select(_e59, _e61, (_e61 < _e59)));
            let _e65 = bitcast<i32>(_e30.y);
            let _e67 = select(0i, _e65, (0i < _e65));
            let _e69 = (bitcast<i32>(_e50) - 1i);
            let _e72 = bitcast<u32>(select(_e67, _e69, (_e69 < _e67)));
            let _e73 = (_e72 * _e40);
            let _e77 = depth.member[(_e73 + _e64)];
            let _e81 = params.member.member.member_3;
            let _e85 = select(_e81, _e77, select(false, (_e77 < _e81), (_e77 > 0f)));
            let _e100 = params.member.member.member_1[0u];
            let _e101 = (((((f32(bitcast<i32>(_e64)) + 0.5f) / _e35) * 2f) - 1f) * _e100);
            let _e102 = (_e101 * _e85);
            let _e109 = params.member.member.member_1[1u];
            let _e110 = (((((f32(bitcast<i32>(_e72)) + 0.5f) / _e45) * -2f) + 1f) * _e109);
            let _e111 = (_e110 * _e85);
            let _e112 = (_e57 + -1i);
            let _e114 = select(0i, _e112, (0i < _e112));
            let _e117 = bitcast<u32>(select(_e114, _e61, (_e61 < _e114)));
            let _e121 = depth.member[(_e73 + _e117)];
            let _e125 = select(_e81, _e121, select(false, (_e121 < _e81), (_e121 > 0f)));
            let _e135 = (_e57 + 1i);
            let _e137 = select(0i, _e135, (0i < _e135));
            let _e140 = bitcast<u32>(select(_e137, _e61, (_e61 < _e137)));
            let _e144 = depth.member[(_e73 + _e140)];
            let _e148 = select(_e81, _e144, select(false, (_e144 < _e81), (_e144 > 0f)));
            let _e158 = (_e65 + -1i);
            let _e160 = select(0i, _e158, (0i < _e158));
            let _e163 = bitcast<u32>(select(_e160, _e69, (_e69 < _e160)));
            let _e168 = depth.member[((_e163 * _e40) + _e64)];
            let _e172 = select(_e81, _e168, select(false, (_e168 < _e81), (_e168 > 0f)));
            let _e182 = (_e65 + 1i);
            let _e184 = select(0i, _e182, (0i < _e182));
            let _e187 = bitcast<u32>(select(_e184, _e69, (_e69 < _e184)));
            let _e192 = depth.member[((_e187 * _e40) + _e64)];
            let _e196 = select(_e81, _e192, select(false, (_e192 < _e81), (_e192 > 0f)));
            let _e206 = (_e125 - _e85);
            let _e207 = (_e148 - _e85);
            let _e208 = (_e172 - _e85);
            let _e209 = (_e196 - _e85);
            let _e211 = ((_e207 - _e206) * 0.5f);
            let _e213 = ((_e209 - _e208) * 0.5f);
            let _e214 = (_e85 * 0.011f);
            let _e216 = abs(_e206);
            let _e217 = abs((_e206 + _e211));
            let _e223 = (1.25f - (select(_e217, _e216, ((_e216 < _e217) || (_e217 != _e217))) / _e214));
            let _e227 = select(0f, select(1f, _e223, (_e223 < 1f)), (_e223 > 0f));
            let _e229 = abs(_e207);
            let _e230 = abs((_e207 - _e211));
            let _e236 = (1.25f - (select(_e230, _e229, ((_e229 < _e230) || (_e230 != _e230))) / _e214));
            let _e240 = select(0f, select(1f, _e236, (_e236 < 1f)), (_e236 > 0f));
            let _e242 = abs(_e208);
            let _e243 = abs((_e208 + _e213));
            let _e249 = (1.25f - (select(_e243, _e242, ((_e242 < _e243) || (_e243 != _e243))) / _e214));
            let _e253 = select(0f, select(1f, _e249, (_e249 < 1f)), (_e249 > 0f));
            let _e255 = abs(_e209);
            let _e256 = abs((_e209 - _e213));
            let _e262 = (1.25f - (select(_e256, _e255, ((_e255 < _e256) || (_e256 != _e256))) / _e214));
            let _e266 = select(0f, select(1f, _e262, (_e262 < 1f)), (_e262 > 0f));
            let _e267 = (((((((f32(bitcast<i32>(_e117)) + 0.5f) / _e35) * 2f) - 1f) * _e100) * _e125) - _e102);
            let _e268 = ((_e110 * _e125) - _e111);
            let _e274 = sqrt((((_e267 * _e267) + (_e268 * _e268)) + (_e206 * _e206)));
            if (_e274 > 0f) {
                phi_668_ = vec3<f32>((_e267 / _e274), (_e268 / _e274), (_e206 / _e274));
            } else {
                phi_668_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e281 = phi_668_;
            let _e282 = (((((((f32(bitcast<i32>(_e140)) + 0.5f) / _e35) * 2f) - 1f) * _e100) * _e148) - _e102);
            let _e283 = ((_e110 * _e148) - _e111);
            let _e289 = sqrt((((_e282 * _e282) + (_e283 * _e283)) + (_e207 * _e207)));
            if (_e289 > 0f) {
                phi_686_ = vec3<f32>((_e282 / _e289), (_e283 / _e289), (_e207 / _e289));
            } else {
                phi_686_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e296 = phi_686_;
            let _e297 = ((_e101 * _e172) - _e102);
            let _e298 = (((((((f32(bitcast<i32>(_e163)) + 0.5f) / _e45) * -2f) + 1f) * _e109) * _e172) - _e111);
            let _e304 = sqrt((((_e297 * _e297) + (_e298 * _e298)) + (_e208 * _e208)));
            if (_e304 > 0f) {
                phi_704_ = vec3<f32>((_e297 / _e304), (_e298 / _e304), (_e208 / _e304));
            } else {
                phi_704_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e311 = phi_704_;
            let _e312 = ((_e101 * _e196) - _e102);
            let _e313 = (((((((f32(bitcast<i32>(_e187)) + 0.5f) / _e45) * -2f) + 1f) * _e109) * _e196) - _e111);
            let _e319 = sqrt((((_e312 * _e312) + (_e313 * _e313)) + (_e209 * _e209)));
            if (_e319 > 0f) {
                phi_722_ = vec3<f32>((_e312 / _e319), (_e313 / _e319), (_e209 / _e319));
            } else {
                phi_722_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e326 = phi_722_;
            let _e343 = ((_e227 * _e253) + 0.01f);
            let _e347 = select(0f, select(1f, _e343, (_e343 < 1f)), (_e343 > 0f));
            let _e364 = ((_e253 * _e240) + 0.01f);
            let _e368 = select(0f, select(1f, _e364, (_e364 < 1f)), (_e364 > 0f));
            let _e388 = ((_e240 * _e266) + 0.01f);
            let _e392 = select(0f, select(1f, _e388, (_e388 < 1f)), (_e388 > 0f));
            let _e409 = ((_e266 * _e227) + 0.01f);
            let _e413 = select(0f, select(1f, _e409, (_e409 < 1f)), (_e409 > 0f));
            let _e417 = ((((((_e281.y * _e311.z) - (_e311.y * _e281.z)) * _e347) + (((_e311.y * _e296.z) - (_e296.y * _e311.z)) * _e368)) + (((_e296.y * _e326.z) - (_e326.y * _e296.z)) * _e392)) + (((_e326.y * _e281.z) - (_e281.y * _e326.z)) * _e413));
            let _e418 = ((((((_e281.z * _e311.x) - (_e311.z * _e281.x)) * _e347) + (((_e311.z * _e296.x) - (_e296.z * _e311.x)) * _e368)) + (((_e296.z * _e326.x) - (_e326.z * _e296.x)) * _e392)) + (((_e326.z * _e281.x) - (_e281.z * _e326.x)) * _e413));
            let _e419 = ((((((_e281.x * _e311.y) - (_e311.x * _e281.y)) * _e347) + (((_e311.x * _e296.y) - (_e296.x * _e311.y)) * _e368)) + (((_e296.x * _e326.y) - (_e326.x * _e296.y)) * _e392)) + (((_e326.x * _e281.y) - (_e281.x * _e326.y)) * _e413));
            let _e425 = sqrt((((_e417 * _e417) + (_e418 * _e418)) + (_e419 * _e419)));
            if (_e425 > 0f) {
                phi_890_ = vec3<f32>((_e417 / _e425), (_e418 / _e425), (_e419 / _e425));
            } else {
                phi_890_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e432 = phi_890_;
            let _e436 = -(_e432.z);
            let _e441 = ((abs(_e432.x) + abs(_e432.y)) + abs(_e436));
            let _e442 = (_e432.x / _e441);
            let _e443 = (_e432.y / _e441);
            if (_e436 < 0f) {
                phi_926_ = vec2<f32>(((1f - abs(_e443)) * select(1f, -1f, (_e442 < 0f))), ((1f - abs(_e442)) * select(1f, -1f, (_e443 < 0f))));
            } else {
                phi_926_ = vec2<f32>(_e442, _e443);
            }
            let _e458 = phi_926_;
            if (_e458.x != _e458.x) {
                phi_942_ = 0f;
            } else {
                phi_942_ = select(-1f, select(1f, _e458.x, (_e458.x < 1f)), (_e458.x > -1f));
            }
            let _e466 = phi_942_;
            let _e471 = ((_e466 * 127f) + (0.5f * select(1f, -1f, (_e466 < 0f))));
            if (_e458.y != _e458.y) {
                phi_977_ = 0f;
            } else {
                phi_977_ = select(-1f, select(1f, _e458.y, (_e458.y < 1f)), (_e458.y > -1f));
            }
            let _e488 = phi_977_;
            let _e493 = ((_e488 * 127f) + (0.5f * select(1f, -1f, (_e488 < 0f))));
            normals.member[((_e30.y * _e40) + _e30.x)] = ((bitcast<u32>(select(0i, select(select(i32(_e471), i32(-2147483648), (_e471 < -2147483600f)), 2147483647i, (_e471 > 2147483500f)), (_e471 == _e471))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e493), i32(-2147483648), (_e493 < -2147483600f)), 2147483647i, (_e493 > 2147483500f)), (_e493 == _e493))) & 255u) << bitcast<u32>(8i)));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_normals(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
