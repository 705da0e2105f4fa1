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
    var phi_132_: i32;
    var phi_151_: i32;
    var phi_230_: i32;
    var phi_249_: i32;
    var phi_328_: i32;
    var phi_347_: i32;
    var phi_426_: i32;
    var phi_445_: i32;
    var phi_524_: i32;
    var phi_543_: i32;
    var phi_713_: vec3<f32>;
    var phi_731_: vec3<f32>;
    var phi_749_: vec3<f32>;
    var phi_767_: vec3<f32>;
    var phi_935_: vec3<f32>;
    var phi_969_: vec2<f32>;
    var phi_985_: f32;
    var phi_1020_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e32 = id_1;
            let _e34 = arrayLength((&depth.member));
            let _e41 = params.member.member.member[0u];
            let _e46 = select(select(u32(_e41), 0u, (_e41 < 0f)), 4294967295u, (_e41 > 4294967000f));
            let _e51 = params.member.member.member[1u];
            let _e56 = select(select(u32(_e51), 0u, (_e51 < 0f)), 4294967295u, (_e51 > 4294967000f));
            if (_e32.x >= _e46) {
            } else {
                if (_e32.y >= _e56) {
                } else {
                    let _e61 = bitcast<i32>(_e32.x);
                    let _e63 = (bitcast<i32>(_e46) - 1i);
                    let _e64 = (0i <= _e63);
                    if _e64 {
                    } else {
                        break;
                    }
                    let _e65 = (_e61 < 0i);
                    if _e65 {
                        phi_132_ = 0i;
                    } else {
                        phi_132_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e69 = phi_132_;
                    let _e70 = bitcast<u32>(_e69);
                    let _e71 = bitcast<i32>(_e32.y);
                    let _e73 = (bitcast<i32>(_e56) - 1i);
                    let _e74 = (0i <= _e73);
                    if _e74 {
                    } else {
                        break;
                    }
                    let _e75 = (_e71 < 0i);
                    if _e75 {
                        phi_151_ = 0i;
                    } else {
                        phi_151_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e79 = phi_151_;
                    let _e80 = bitcast<u32>(_e79);
                    let _e82 = ((_e80 * _e46) + _e70);
                    if (_e82 < _e34) {
                    } else {
                        break;
                    }
                    let _e86 = depth.member[_e82];
                    let _e90 = params.member.member.member_3;
                    let _e94 = select(_e90, _e86, select(false, (_e86 < _e90), (_e86 > 0f)));
                    let _e107 = params.member.member.member_1[0u];
                    let _e109 = ((((((f32(_e70) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e94);
                    let _e116 = params.member.member.member_1[1u];
                    let _e118 = ((((((f32(_e80) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e94);
                    let _e119 = (_e61 + -1i);
                    if _e64 {
                    } else {
                        break;
                    }
                    if (_e119 < 0i) {
                        phi_230_ = 0i;
                    } else {
                        phi_230_ = select(_e119, _e63, (_e119 > _e63));
                    }
                    let _e124 = phi_230_;
                    let _e125 = bitcast<u32>(_e124);
                    if _e74 {
                    } else {
                        break;
                    }
                    if _e75 {
                        phi_249_ = 0i;
                    } else {
                        phi_249_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e129 = phi_249_;
                    let _e130 = bitcast<u32>(_e129);
                    let _e132 = ((_e130 * _e46) + _e125);
                    if (_e132 < _e34) {
                    } else {
                        break;
                    }
                    let _e136 = depth.member[_e132];
                    let _e140 = select(_e90, _e136, select(false, (_e136 < _e90), (_e136 > 0f)));
                    let _e155 = (_e61 + 1i);
                    if _e64 {
                    } else {
                        break;
                    }
                    if (_e155 < 0i) {
                        phi_328_ = 0i;
                    } else {
                        phi_328_ = select(_e155, _e63, (_e155 > _e63));
                    }
                    let _e160 = phi_328_;
                    let _e161 = bitcast<u32>(_e160);
                    if _e74 {
                    } else {
                        break;
                    }
                    if _e75 {
                        phi_347_ = 0i;
                    } else {
                        phi_347_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e165 = phi_347_;
                    let _e166 = bitcast<u32>(_e165);
                    let _e168 = ((_e166 * _e46) + _e161);
                    if (_e168 < _e34) {
                    } else {
                        break;
                    }
                    let _e172 = depth.member[_e168];
                    let _e176 = select(_e90, _e172, select(false, (_e172 < _e90), (_e172 > 0f)));
                    if _e64 {
                    } else {
                        break;
                    }
                    if _e65 {
                        phi_426_ = 0i;
                    } else {
                        phi_426_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e194 = phi_426_;
                    let _e195 = bitcast<u32>(_e194);
                    let _e196 = (_e71 + -1i);
                    if _e74 {
                    } else {
                        break;
                    }
                    if (_e196 < 0i) {
                        phi_445_ = 0i;
                    } else {
                        phi_445_ = select(_e196, _e73, (_e196 > _e73));
                    }
                    let _e201 = phi_445_;
                    let _e202 = bitcast<u32>(_e201);
                    let _e204 = ((_e202 * _e46) + _e195);
                    if (_e204 < _e34) {
                    } else {
                        break;
                    }
                    let _e208 = depth.member[_e204];
                    let _e212 = select(_e90, _e208, select(false, (_e208 < _e90), (_e208 > 0f)));
                    if _e64 {
                    } else {
                        break;
                    }
                    if _e65 {
                        phi_524_ = 0i;
                    } else {
                        phi_524_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e230 = phi_524_;
                    let _e231 = bitcast<u32>(_e230);
                    let _e232 = (_e71 + 1i);
                    if _e74 {
                    } else {
                        break;
                    }
                    if (_e232 < 0i) {
                        phi_543_ = 0i;
                    } else {
                        phi_543_ = select(_e232, _e73, (_e232 > _e73));
                    }
                    let _e237 = phi_543_;
                    let _e238 = bitcast<u32>(_e237);
                    let _e240 = ((_e238 * _e46) + _e231);
                    if (_e240 < _e34) {
                    } else {
                        break;
                    }
                    let _e244 = depth.member[_e240];
                    let _e248 = select(_e90, _e244, select(false, (_e244 < _e90), (_e244 > 0f)));
                    let _e263 = (_e140 - _e94);
                    let _e264 = (_e176 - _e94);
                    let _e265 = (_e212 - _e94);
                    let _e266 = (_e248 - _e94);
                    let _e267 = (_e264 - _e263);
                    let _e269 = (_e266 - _e265);
                    let _e277 = abs(_e263);
                    let _e278 = abs(_e264);
                    let _e279 = abs(_e265);
                    let _e280 = abs(_e266);
                    let _e281 = abs((_e263 + (_e267 * 0.5f)));
                    let _e282 = abs((_e264 + (_e267 * -0.5f)));
                    let _e283 = abs((_e265 + (_e269 * 0.5f)));
                    let _e284 = abs((_e266 + (_e269 * -0.5f)));
                    let _e293 = (_e94 * 0.011f);
                    let _e298 = (1.25f - (select(_e281, _e277, (_e277 < _e281)) / _e293));
                    let _e302 = select(0f, select(1f, _e298, (_e298 < 1f)), (_e298 > 0f));
                    let _e303 = (1.25f - (select(_e282, _e278, (_e278 < _e282)) / _e293));
                    let _e307 = select(0f, select(1f, _e303, (_e303 < 1f)), (_e303 > 0f));
                    let _e308 = (1.25f - (select(_e283, _e279, (_e279 < _e283)) / _e293));
                    let _e312 = select(0f, select(1f, _e308, (_e308 < 1f)), (_e308 > 0f));
                    let _e313 = (1.25f - (select(_e284, _e280, (_e280 < _e284)) / _e293));
                    let _e317 = select(0f, select(1f, _e313, (_e313 < 1f)), (_e313 > 0f));
                    let _e318 = (((((((f32(_e125) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e140) - _e109);
                    let _e319 = (((((((f32(_e130) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e140) - _e118);
                    let _e325 = sqrt((((_e318 * _e318) + (_e319 * _e319)) + (_e263 * _e263)));
                    if (_e325 > 0f) {
                        phi_713_ = vec3<f32>((_e318 / _e325), (_e319 / _e325), (_e263 / _e325));
                    } else {
                        phi_713_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e332 = phi_713_;
                    let _e333 = (((((((f32(_e161) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e176) - _e109);
                    let _e334 = (((((((f32(_e166) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e176) - _e118);
                    let _e340 = sqrt((((_e333 * _e333) + (_e334 * _e334)) + (_e264 * _e264)));
                    if (_e340 > 0f) {
                        phi_731_ = vec3<f32>((_e333 / _e340), (_e334 / _e340), (_e264 / _e340));
                    } else {
                        phi_731_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e347 = phi_731_;
                    let _e348 = (((((((f32(_e195) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e212) - _e109);
                    let _e349 = (((((((f32(_e202) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e212) - _e118);
                    let _e355 = sqrt((((_e348 * _e348) + (_e349 * _e349)) + (_e265 * _e265)));
                    if (_e355 > 0f) {
                        phi_749_ = vec3<f32>((_e348 / _e355), (_e349 / _e355), (_e265 / _e355));
                    } else {
                        phi_749_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e362 = phi_749_;
                    let _e363 = (((((((f32(_e231) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e248) - _e109);
                    let _e364 = (((((((f32(_e238) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e248) - _e118);
                    let _e370 = sqrt((((_e363 * _e363) + (_e364 * _e364)) + (_e266 * _e266)));
                    if (_e370 > 0f) {
                        phi_767_ = vec3<f32>((_e363 / _e370), (_e364 / _e370), (_e266 / _e370));
                    } else {
                        phi_767_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e377 = phi_767_;
                    let _e394 = ((_e302 * _e312) + 0.01f);
                    let _e398 = select(0f, select(1f, _e394, (_e394 < 1f)), (_e394 > 0f));
                    let _e415 = ((_e312 * _e307) + 0.01f);
                    let _e419 = select(0f, select(1f, _e415, (_e415 < 1f)), (_e415 > 0f));
                    let _e439 = ((_e307 * _e317) + 0.01f);
                    let _e443 = select(0f, select(1f, _e439, (_e439 < 1f)), (_e439 > 0f));
                    let _e460 = ((_e317 * _e302) + 0.01f);
                    let _e464 = select(0f, select(1f, _e460, (_e460 < 1f)), (_e460 > 0f));
                    let _e468 = ((((((_e332.y * _e362.z) - (_e362.y * _e332.z)) * _e398) + (((_e362.y * _e347.z) - (_e347.y * _e362.z)) * _e419)) + (((_e347.y * _e377.z) - (_e377.y * _e347.z)) * _e443)) + (((_e377.y * _e332.z) - (_e332.y * _e377.z)) * _e464));
                    let _e469 = ((((((_e332.z * _e362.x) - (_e362.z * _e332.x)) * _e398) + (((_e362.z * _e347.x) - (_e347.z * _e362.x)) * _e419)) + (((_e347.z * _e377.x) - (_e377.z * _e347.x)) * _e443)) + (((_e377.z * _e332.x) - (_e332.z * _e377.x)) * _e464));
                    let _e470 = ((((((_e332.x * _e362.y) - (_e362.x * _e332.y)) * _e398) + (((_e362.x * _e347.y) - (_e347.x * _e362.y)) * _e419)) + (((_e347.x * _e377.y) - (_e377.x * _e347.y)) * _e443)) + (((_e377.x * _e332.y) - (_e332.x * _e377.y)) * _e464));
                    let _e476 = sqrt((((_e468 * _e468) + (_e469 * _e469)) + (_e470 * _e470)));
                    if (_e476 > 0f) {
                        phi_935_ = vec3<f32>((_e468 / _e476), (_e469 / _e476), (_e470 / _e476));
                    } else {
                        phi_935_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e483 = phi_935_;
                    let _e487 = -(_e483.z);
                    let _e492 = ((abs(_e483.x) + abs(_e483.y)) + abs(_e487));
                    let _e493 = (_e483.x / _e492);
                    let _e494 = (_e483.y / _e492);
                    if (_e487 < 0f) {
                        phi_969_ = vec2<f32>(((1f - abs(_e494)) * select(1f, -1f, (_e493 < 0f))), ((1f - abs(_e493)) * select(1f, -1f, (_e494 < 0f))));
                    } else {
                        phi_969_ = vec2<f32>(_e493, _e494);
                    }
                    let _e509 = phi_969_;
                    if (_e509.x != _e509.x) {
                        phi_985_ = 0f;
                    } else {
                        phi_985_ = select(-1f, select(1f, _e509.x, (_e509.x < 1f)), (_e509.x > -1f));
                    }
                    let _e517 = phi_985_;
                    let _e522 = ((_e517 * 127f) + (0.5f * select(1f, -1f, (_e517 < 0f))));
                    if (_e509.y != _e509.y) {
                        phi_1020_ = 0f;
                    } else {
                        phi_1020_ = select(-1f, select(1f, _e509.y, (_e509.y < 1f)), (_e509.y > -1f));
                    }
                    let _e539 = phi_1020_;
                    let _e544 = ((_e539 * 127f) + (0.5f * select(1f, -1f, (_e539 < 0f))));
                    let _e558 = ((_e32.y * _e46) + _e32.x);
                    if (_e558 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    normals.member[_e558] = ((bitcast<u32>(select(0i, select(select(i32(_e522), i32(-2147483648), (_e522 < -2147483600f)), 2147483647i, (_e522 > 2147483500f)), (_e522 == _e522))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e544), i32(-2147483648), (_e544 < -2147483600f)), 2147483647i, (_e544 > 2147483500f)), (_e544 == _e544))) & 255u) << bitcast<u32>(8i)));
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
