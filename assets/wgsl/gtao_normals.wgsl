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
    var phi_658_: vec3<f32>;
    var phi_676_: vec3<f32>;
    var phi_694_: vec3<f32>;
    var phi_712_: vec3<f32>;
    var phi_880_: vec3<f32>;
    var phi_914_: vec2<f32>;
    var phi_930_: f32;
    var phi_965_: f32;

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
            let _e98 = params.member.member.member_1[0u];
            let _e99 = (((((f32(_e64) + 0.5f) / _e35) * 2f) - 1f) * _e98);
            let _e100 = (_e99 * _e85);
            let _e107 = params.member.member.member_1[1u];
            let _e108 = (((((f32(_e72) + 0.5f) / _e45) * -2f) + 1f) * _e107);
            let _e109 = (_e108 * _e85);
            let _e110 = (_e57 + -1i);
            let _e112 = select(0i, _e110, (0i < _e110));
            let _e115 = bitcast<u32>(select(_e112, _e61, (_e61 < _e112)));
            let _e119 = depth.member[(_e73 + _e115)];
            let _e123 = select(_e81, _e119, select(false, (_e119 < _e81), (_e119 > 0f)));
            let _e132 = (_e57 + 1i);
            let _e134 = select(0i, _e132, (0i < _e132));
            let _e137 = bitcast<u32>(select(_e134, _e61, (_e61 < _e134)));
            let _e141 = depth.member[(_e73 + _e137)];
            let _e145 = select(_e81, _e141, select(false, (_e141 < _e81), (_e141 > 0f)));
            let _e154 = (_e65 + -1i);
            let _e156 = select(0i, _e154, (0i < _e154));
            let _e159 = bitcast<u32>(select(_e156, _e69, (_e69 < _e156)));
            let _e164 = depth.member[((_e159 * _e40) + _e64)];
            let _e168 = select(_e81, _e164, select(false, (_e164 < _e81), (_e164 > 0f)));
            let _e177 = (_e65 + 1i);
            let _e179 = select(0i, _e177, (0i < _e177));
            let _e182 = bitcast<u32>(select(_e179, _e69, (_e69 < _e179)));
            let _e187 = depth.member[((_e182 * _e40) + _e64)];
            let _e191 = select(_e81, _e187, select(false, (_e187 < _e81), (_e187 > 0f)));
            let _e200 = (_e123 - _e85);
            let _e201 = (_e145 - _e85);
            let _e202 = (_e168 - _e85);
            let _e203 = (_e191 - _e85);
            let _e205 = ((_e201 - _e200) * 0.5f);
            let _e207 = ((_e203 - _e202) * 0.5f);
            let _e208 = (_e85 * 0.011f);
            let _e210 = abs(_e200);
            let _e211 = abs((_e200 + _e205));
            let _e217 = (1.25f - (select(_e211, _e210, ((_e210 < _e211) || (_e211 != _e211))) / _e208));
            let _e221 = select(0f, select(1f, _e217, (_e217 < 1f)), (_e217 > 0f));
            let _e223 = abs(_e201);
            let _e224 = abs((_e201 - _e205));
            let _e230 = (1.25f - (select(_e224, _e223, ((_e223 < _e224) || (_e224 != _e224))) / _e208));
            let _e234 = select(0f, select(1f, _e230, (_e230 < 1f)), (_e230 > 0f));
            let _e236 = abs(_e202);
            let _e237 = abs((_e202 + _e207));
            let _e243 = (1.25f - (select(_e237, _e236, ((_e236 < _e237) || (_e237 != _e237))) / _e208));
            let _e247 = select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f));
            let _e249 = abs(_e203);
            let _e250 = abs((_e203 - _e207));
            let _e256 = (1.25f - (select(_e250, _e249, ((_e249 < _e250) || (_e250 != _e250))) / _e208));
            let _e260 = select(0f, select(1f, _e256, (_e256 < 1f)), (_e256 > 0f));
            let _e261 = (((((((f32(_e115) + 0.5f) / _e35) * 2f) - 1f) * _e98) * _e123) - _e100);
            let _e262 = ((_e108 * _e123) - _e109);
            let _e268 = sqrt((((_e261 * _e261) + (_e262 * _e262)) + (_e200 * _e200)));
            if (_e268 > 0f) {
                phi_658_ = vec3<f32>((_e261 / _e268), (_e262 / _e268), (_e200 / _e268));
            } else {
                phi_658_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e275 = phi_658_;
            let _e276 = (((((((f32(_e137) + 0.5f) / _e35) * 2f) - 1f) * _e98) * _e145) - _e100);
            let _e277 = ((_e108 * _e145) - _e109);
            let _e283 = sqrt((((_e276 * _e276) + (_e277 * _e277)) + (_e201 * _e201)));
            if (_e283 > 0f) {
                phi_676_ = vec3<f32>((_e276 / _e283), (_e277 / _e283), (_e201 / _e283));
            } else {
                phi_676_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e290 = phi_676_;
            let _e291 = ((_e99 * _e168) - _e100);
            let _e292 = (((((((f32(_e159) + 0.5f) / _e45) * -2f) + 1f) * _e107) * _e168) - _e109);
            let _e298 = sqrt((((_e291 * _e291) + (_e292 * _e292)) + (_e202 * _e202)));
            if (_e298 > 0f) {
                phi_694_ = vec3<f32>((_e291 / _e298), (_e292 / _e298), (_e202 / _e298));
            } else {
                phi_694_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e305 = phi_694_;
            let _e306 = ((_e99 * _e191) - _e100);
            let _e307 = (((((((f32(_e182) + 0.5f) / _e45) * -2f) + 1f) * _e107) * _e191) - _e109);
            let _e313 = sqrt((((_e306 * _e306) + (_e307 * _e307)) + (_e203 * _e203)));
            if (_e313 > 0f) {
                phi_712_ = vec3<f32>((_e306 / _e313), (_e307 / _e313), (_e203 / _e313));
            } else {
                phi_712_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e320 = phi_712_;
            let _e337 = ((_e221 * _e247) + 0.01f);
            let _e341 = select(0f, select(1f, _e337, (_e337 < 1f)), (_e337 > 0f));
            let _e358 = ((_e247 * _e234) + 0.01f);
            let _e362 = select(0f, select(1f, _e358, (_e358 < 1f)), (_e358 > 0f));
            let _e382 = ((_e234 * _e260) + 0.01f);
            let _e386 = select(0f, select(1f, _e382, (_e382 < 1f)), (_e382 > 0f));
            let _e403 = ((_e260 * _e221) + 0.01f);
            let _e407 = select(0f, select(1f, _e403, (_e403 < 1f)), (_e403 > 0f));
            let _e411 = ((((((_e275.y * _e305.z) - (_e305.y * _e275.z)) * _e341) + (((_e305.y * _e290.z) - (_e290.y * _e305.z)) * _e362)) + (((_e290.y * _e320.z) - (_e320.y * _e290.z)) * _e386)) + (((_e320.y * _e275.z) - (_e275.y * _e320.z)) * _e407));
            let _e412 = ((((((_e275.z * _e305.x) - (_e305.z * _e275.x)) * _e341) + (((_e305.z * _e290.x) - (_e290.z * _e305.x)) * _e362)) + (((_e290.z * _e320.x) - (_e320.z * _e290.x)) * _e386)) + (((_e320.z * _e275.x) - (_e275.z * _e320.x)) * _e407));
            let _e413 = ((((((_e275.x * _e305.y) - (_e305.x * _e275.y)) * _e341) + (((_e305.x * _e290.y) - (_e290.x * _e305.y)) * _e362)) + (((_e290.x * _e320.y) - (_e320.x * _e290.y)) * _e386)) + (((_e320.x * _e275.y) - (_e275.x * _e320.y)) * _e407));
            let _e419 = sqrt((((_e411 * _e411) + (_e412 * _e412)) + (_e413 * _e413)));
            if (_e419 > 0f) {
                phi_880_ = vec3<f32>((_e411 / _e419), (_e412 / _e419), (_e413 / _e419));
            } else {
                phi_880_ = vec3<f32>(0f, 0f, 0f);
            }
            let _e426 = phi_880_;
            let _e430 = -(_e426.z);
            let _e435 = ((abs(_e426.x) + abs(_e426.y)) + abs(_e430));
            let _e436 = (_e426.x / _e435);
            let _e437 = (_e426.y / _e435);
            if (_e430 < 0f) {
                phi_914_ = vec2<f32>(((1f - abs(_e437)) * select(1f, -1f, (_e436 < 0f))), ((1f - abs(_e436)) * select(1f, -1f, (_e437 < 0f))));
            } else {
                phi_914_ = vec2<f32>(_e436, _e437);
            }
            let _e452 = phi_914_;
            if (_e452.x != _e452.x) {
                phi_930_ = 0f;
            } else {
                phi_930_ = select(-1f, select(1f, _e452.x, (_e452.x < 1f)), (_e452.x > -1f));
            }
            let _e460 = phi_930_;
            let _e465 = ((_e460 * 127f) + (0.5f * select(1f, -1f, (_e460 < 0f))));
            if (_e452.y != _e452.y) {
                phi_965_ = 0f;
            } else {
                phi_965_ = select(-1f, select(1f, _e452.y, (_e452.y < 1f)), (_e452.y > -1f));
            }
            let _e482 = phi_965_;
            let _e487 = ((_e482 * 127f) + (0.5f * select(1f, -1f, (_e482 < 0f))));
            normals.member[((_e30.y * _e40) + _e30.x)] = ((bitcast<u32>(select(0i, select(select(i32(_e465), i32(-2147483648), (_e465 < -2147483600f)), 2147483647i, (_e465 > 2147483500f)), (_e465 == _e465))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e487), i32(-2147483648), (_e487 < -2147483600f)), 2147483647i, (_e487 > 2147483500f)), (_e487 == _e487))) & 255u) << bitcast<u32>(8i)));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_normals(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
