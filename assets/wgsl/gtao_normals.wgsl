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
    var phi_135_: i32;
    var phi_154_: i32;
    var phi_233_: i32;
    var phi_252_: i32;
    var phi_331_: i32;
    var phi_350_: i32;
    var phi_429_: i32;
    var phi_448_: i32;
    var phi_527_: i32;
    var phi_546_: i32;
    var phi_1070_: bool;
    var phi_1085_: bool;
    var phi_1100_: bool;
    var phi_1115_: bool;
    var phi_702_: vec3<f32>;
    var phi_720_: vec3<f32>;
    var phi_738_: vec3<f32>;
    var phi_756_: vec3<f32>;
    var phi_924_: vec3<f32>;
    var phi_958_: vec2<f32>;
    var phi_974_: f32;
    var phi_1009_: f32;

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
                        phi_135_ = 0i;
                    } else {
                        phi_135_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e69 = phi_135_;
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
                        phi_154_ = 0i;
                    } else {
                        phi_154_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e79 = phi_154_;
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
                        phi_233_ = 0i;
                    } else {
                        phi_233_ = select(_e119, _e63, (_e119 > _e63));
                    }
                    let _e124 = phi_233_;
                    let _e125 = bitcast<u32>(_e124);
                    if _e74 {
                    } else {
                        break;
                    }
                    if _e75 {
                        phi_252_ = 0i;
                    } else {
                        phi_252_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e129 = phi_252_;
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
                        phi_331_ = 0i;
                    } else {
                        phi_331_ = select(_e155, _e63, (_e155 > _e63));
                    }
                    let _e160 = phi_331_;
                    let _e161 = bitcast<u32>(_e160);
                    if _e74 {
                    } else {
                        break;
                    }
                    if _e75 {
                        phi_350_ = 0i;
                    } else {
                        phi_350_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e165 = phi_350_;
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
                        phi_429_ = 0i;
                    } else {
                        phi_429_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e194 = phi_429_;
                    let _e195 = bitcast<u32>(_e194);
                    let _e196 = (_e71 + -1i);
                    if _e74 {
                    } else {
                        break;
                    }
                    if (_e196 < 0i) {
                        phi_448_ = 0i;
                    } else {
                        phi_448_ = select(_e196, _e73, (_e196 > _e73));
                    }
                    let _e201 = phi_448_;
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
                        phi_527_ = 0i;
                    } else {
                        phi_527_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e230 = phi_527_;
                    let _e231 = bitcast<u32>(_e230);
                    let _e232 = (_e71 + 1i);
                    if _e74 {
                    } else {
                        break;
                    }
                    if (_e232 < 0i) {
                        phi_546_ = 0i;
                    } else {
                        phi_546_ = select(_e232, _e73, (_e232 > _e73));
                    }
                    let _e237 = phi_546_;
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
                    let _e268 = ((_e264 - _e263) * 0.5f);
                    let _e270 = ((_e266 - _e265) * 0.5f);
                    let _e271 = (_e94 * 0.011f);
                    let _e273 = abs(_e263);
                    let _e274 = abs((_e263 + _e268));
                    if (_e273 != _e273) {
                        phi_1070_ = true;
                    } else {
                        phi_1070_ = (_e274 <= _e273);
                    }
                    let _e278 = phi_1070_;
                    let _e281 = (1.25f - (select(_e273, _e274, _e278) / _e271));
                    let _e285 = select(0f, select(1f, _e281, (_e281 < 1f)), (_e281 > 0f));
                    let _e287 = abs(_e264);
                    let _e288 = abs((_e264 - _e268));
                    if (_e287 != _e287) {
                        phi_1085_ = true;
                    } else {
                        phi_1085_ = (_e288 <= _e287);
                    }
                    let _e292 = phi_1085_;
                    let _e295 = (1.25f - (select(_e287, _e288, _e292) / _e271));
                    let _e299 = select(0f, select(1f, _e295, (_e295 < 1f)), (_e295 > 0f));
                    let _e301 = abs(_e265);
                    let _e302 = abs((_e265 + _e270));
                    if (_e301 != _e301) {
                        phi_1100_ = true;
                    } else {
                        phi_1100_ = (_e302 <= _e301);
                    }
                    let _e306 = phi_1100_;
                    let _e309 = (1.25f - (select(_e301, _e302, _e306) / _e271));
                    let _e313 = select(0f, select(1f, _e309, (_e309 < 1f)), (_e309 > 0f));
                    let _e315 = abs(_e266);
                    let _e316 = abs((_e266 - _e270));
                    if (_e315 != _e315) {
                        phi_1115_ = true;
                    } else {
                        phi_1115_ = (_e316 <= _e315);
                    }
                    let _e320 = phi_1115_;
                    let _e323 = (1.25f - (select(_e315, _e316, _e320) / _e271));
                    let _e327 = select(0f, select(1f, _e323, (_e323 < 1f)), (_e323 > 0f));
                    let _e328 = (((((((f32(_e125) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e140) - _e109);
                    let _e329 = (((((((f32(_e130) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e140) - _e118);
                    let _e335 = sqrt((((_e328 * _e328) + (_e329 * _e329)) + (_e263 * _e263)));
                    if (_e335 > 0f) {
                        phi_702_ = vec3<f32>((_e328 / _e335), (_e329 / _e335), (_e263 / _e335));
                    } else {
                        phi_702_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e342 = phi_702_;
                    let _e343 = (((((((f32(_e161) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e176) - _e109);
                    let _e344 = (((((((f32(_e166) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e176) - _e118);
                    let _e350 = sqrt((((_e343 * _e343) + (_e344 * _e344)) + (_e264 * _e264)));
                    if (_e350 > 0f) {
                        phi_720_ = vec3<f32>((_e343 / _e350), (_e344 / _e350), (_e264 / _e350));
                    } else {
                        phi_720_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e357 = phi_720_;
                    let _e358 = (((((((f32(_e195) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e212) - _e109);
                    let _e359 = (((((((f32(_e202) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e212) - _e118);
                    let _e365 = sqrt((((_e358 * _e358) + (_e359 * _e359)) + (_e265 * _e265)));
                    if (_e365 > 0f) {
                        phi_738_ = vec3<f32>((_e358 / _e365), (_e359 / _e365), (_e265 / _e365));
                    } else {
                        phi_738_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e372 = phi_738_;
                    let _e373 = (((((((f32(_e231) + 0.5f) / _e41) * 2f) - 1f) * _e107) * _e248) - _e109);
                    let _e374 = (((((((f32(_e238) + 0.5f) / _e51) * -2f) + 1f) * _e116) * _e248) - _e118);
                    let _e380 = sqrt((((_e373 * _e373) + (_e374 * _e374)) + (_e266 * _e266)));
                    if (_e380 > 0f) {
                        phi_756_ = vec3<f32>((_e373 / _e380), (_e374 / _e380), (_e266 / _e380));
                    } else {
                        phi_756_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e387 = phi_756_;
                    let _e404 = ((_e285 * _e313) + 0.01f);
                    let _e408 = select(0f, select(1f, _e404, (_e404 < 1f)), (_e404 > 0f));
                    let _e425 = ((_e313 * _e299) + 0.01f);
                    let _e429 = select(0f, select(1f, _e425, (_e425 < 1f)), (_e425 > 0f));
                    let _e449 = ((_e299 * _e327) + 0.01f);
                    let _e453 = select(0f, select(1f, _e449, (_e449 < 1f)), (_e449 > 0f));
                    let _e470 = ((_e327 * _e285) + 0.01f);
                    let _e474 = select(0f, select(1f, _e470, (_e470 < 1f)), (_e470 > 0f));
                    let _e478 = ((((((_e342.y * _e372.z) - (_e372.y * _e342.z)) * _e408) + (((_e372.y * _e357.z) - (_e357.y * _e372.z)) * _e429)) + (((_e357.y * _e387.z) - (_e387.y * _e357.z)) * _e453)) + (((_e387.y * _e342.z) - (_e342.y * _e387.z)) * _e474));
                    let _e479 = ((((((_e342.z * _e372.x) - (_e372.z * _e342.x)) * _e408) + (((_e372.z * _e357.x) - (_e357.z * _e372.x)) * _e429)) + (((_e357.z * _e387.x) - (_e387.z * _e357.x)) * _e453)) + (((_e387.z * _e342.x) - (_e342.z * _e387.x)) * _e474));
                    let _e480 = ((((((_e342.x * _e372.y) - (_e372.x * _e342.y)) * _e408) + (((_e372.x * _e357.y) - (_e357.x * _e372.y)) * _e429)) + (((_e357.x * _e387.y) - (_e387.x * _e357.y)) * _e453)) + (((_e387.x * _e342.y) - (_e342.x * _e387.y)) * _e474));
                    let _e486 = sqrt((((_e478 * _e478) + (_e479 * _e479)) + (_e480 * _e480)));
                    if (_e486 > 0f) {
                        phi_924_ = vec3<f32>((_e478 / _e486), (_e479 / _e486), (_e480 / _e486));
                    } else {
                        phi_924_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e493 = phi_924_;
                    let _e497 = -(_e493.z);
                    let _e502 = ((abs(_e493.x) + abs(_e493.y)) + abs(_e497));
                    let _e503 = (_e493.x / _e502);
                    let _e504 = (_e493.y / _e502);
                    if (_e497 < 0f) {
                        phi_958_ = vec2<f32>(((1f - abs(_e504)) * select(1f, -1f, (_e503 < 0f))), ((1f - abs(_e503)) * select(1f, -1f, (_e504 < 0f))));
                    } else {
                        phi_958_ = vec2<f32>(_e503, _e504);
                    }
                    let _e519 = phi_958_;
                    if (_e519.x != _e519.x) {
                        phi_974_ = 0f;
                    } else {
                        phi_974_ = select(-1f, select(1f, _e519.x, (_e519.x < 1f)), (_e519.x > -1f));
                    }
                    let _e527 = phi_974_;
                    let _e532 = ((_e527 * 127f) + (0.5f * select(1f, -1f, (_e527 < 0f))));
                    if (_e519.y != _e519.y) {
                        phi_1009_ = 0f;
                    } else {
                        phi_1009_ = select(-1f, select(1f, _e519.y, (_e519.y < 1f)), (_e519.y > -1f));
                    }
                    let _e549 = phi_1009_;
                    let _e554 = ((_e549 * 127f) + (0.5f * select(1f, -1f, (_e549 < 0f))));
                    let _e568 = ((_e32.y * _e46) + _e32.x);
                    if (_e568 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    normals.member[_e568] = ((bitcast<u32>(select(0i, select(select(i32(_e532), i32(-2147483648), (_e532 < -2147483600f)), 2147483647i, (_e532 > 2147483500f)), (_e532 == _e532))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e554), i32(-2147483648), (_e554 < -2147483600f)), 2147483647i, (_e554 > 2147483500f)), (_e554 == _e554))) & 255u) << bitcast<u32>(8i)));
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
