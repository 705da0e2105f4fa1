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
    var phi_181_: bool;
    var phi_232_: i32;
    var phi_251_: i32;
    var phi_281_: bool;
    var phi_332_: i32;
    var phi_351_: i32;
    var phi_381_: bool;
    var phi_432_: i32;
    var phi_451_: i32;
    var phi_481_: bool;
    var phi_532_: i32;
    var phi_551_: i32;
    var phi_581_: bool;
    var phi_723_: vec3<f32>;
    var phi_741_: vec3<f32>;
    var phi_759_: vec3<f32>;
    var phi_777_: vec3<f32>;
    var phi_945_: vec3<f32>;
    var phi_979_: vec2<f32>;
    var phi_995_: f32;
    var phi_1030_: f32;

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
                    if (_e86 > 0f) {
                        phi_181_ = (_e86 < _e90);
                    } else {
                        phi_181_ = false;
                    }
                    let _e94 = phi_181_;
                    let _e95 = select(_e90, _e86, _e94);
                    let _e108 = params.member.member.member_1[0u];
                    let _e110 = ((((((f32(_e70) + 0.5f) / _e41) * 2f) - 1f) * _e108) * _e95);
                    let _e117 = params.member.member.member_1[1u];
                    let _e119 = ((((((f32(_e80) + 0.5f) / _e51) * -2f) + 1f) * _e117) * _e95);
                    let _e120 = (_e61 + -1i);
                    if _e64 {
                    } else {
                        break;
                    }
                    if (_e120 < 0i) {
                        phi_232_ = 0i;
                    } else {
                        phi_232_ = select(_e120, _e63, (_e120 > _e63));
                    }
                    let _e125 = phi_232_;
                    let _e126 = bitcast<u32>(_e125);
                    if _e74 {
                    } else {
                        break;
                    }
                    if _e75 {
                        phi_251_ = 0i;
                    } else {
                        phi_251_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e130 = phi_251_;
                    let _e131 = bitcast<u32>(_e130);
                    let _e133 = ((_e131 * _e46) + _e126);
                    if (_e133 < _e34) {
                    } else {
                        break;
                    }
                    let _e137 = depth.member[_e133];
                    if (_e137 > 0f) {
                        phi_281_ = (_e137 < _e90);
                    } else {
                        phi_281_ = false;
                    }
                    let _e141 = phi_281_;
                    let _e142 = select(_e90, _e137, _e141);
                    let _e157 = (_e61 + 1i);
                    if _e64 {
                    } else {
                        break;
                    }
                    if (_e157 < 0i) {
                        phi_332_ = 0i;
                    } else {
                        phi_332_ = select(_e157, _e63, (_e157 > _e63));
                    }
                    let _e162 = phi_332_;
                    let _e163 = bitcast<u32>(_e162);
                    if _e74 {
                    } else {
                        break;
                    }
                    if _e75 {
                        phi_351_ = 0i;
                    } else {
                        phi_351_ = select(_e71, _e73, (_e71 > _e73));
                    }
                    let _e167 = phi_351_;
                    let _e168 = bitcast<u32>(_e167);
                    let _e170 = ((_e168 * _e46) + _e163);
                    if (_e170 < _e34) {
                    } else {
                        break;
                    }
                    let _e174 = depth.member[_e170];
                    if (_e174 > 0f) {
                        phi_381_ = (_e174 < _e90);
                    } else {
                        phi_381_ = false;
                    }
                    let _e178 = phi_381_;
                    let _e179 = select(_e90, _e174, _e178);
                    if _e64 {
                    } else {
                        break;
                    }
                    if _e65 {
                        phi_432_ = 0i;
                    } else {
                        phi_432_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e197 = phi_432_;
                    let _e198 = bitcast<u32>(_e197);
                    let _e199 = (_e71 + -1i);
                    if _e74 {
                    } else {
                        break;
                    }
                    if (_e199 < 0i) {
                        phi_451_ = 0i;
                    } else {
                        phi_451_ = select(_e199, _e73, (_e199 > _e73));
                    }
                    let _e204 = phi_451_;
                    let _e205 = bitcast<u32>(_e204);
                    let _e207 = ((_e205 * _e46) + _e198);
                    if (_e207 < _e34) {
                    } else {
                        break;
                    }
                    let _e211 = depth.member[_e207];
                    if (_e211 > 0f) {
                        phi_481_ = (_e211 < _e90);
                    } else {
                        phi_481_ = false;
                    }
                    let _e215 = phi_481_;
                    let _e216 = select(_e90, _e211, _e215);
                    if _e64 {
                    } else {
                        break;
                    }
                    if _e65 {
                        phi_532_ = 0i;
                    } else {
                        phi_532_ = select(_e61, _e63, (_e61 > _e63));
                    }
                    let _e234 = phi_532_;
                    let _e235 = bitcast<u32>(_e234);
                    let _e236 = (_e71 + 1i);
                    if _e74 {
                    } else {
                        break;
                    }
                    if (_e236 < 0i) {
                        phi_551_ = 0i;
                    } else {
                        phi_551_ = select(_e236, _e73, (_e236 > _e73));
                    }
                    let _e241 = phi_551_;
                    let _e242 = bitcast<u32>(_e241);
                    let _e244 = ((_e242 * _e46) + _e235);
                    if (_e244 < _e34) {
                    } else {
                        break;
                    }
                    let _e248 = depth.member[_e244];
                    if (_e248 > 0f) {
                        phi_581_ = (_e248 < _e90);
                    } else {
                        phi_581_ = false;
                    }
                    let _e252 = phi_581_;
                    let _e253 = select(_e90, _e248, _e252);
                    let _e268 = (_e142 - _e95);
                    let _e269 = (_e179 - _e95);
                    let _e270 = (_e216 - _e95);
                    let _e271 = (_e253 - _e95);
                    let _e272 = (_e269 - _e268);
                    let _e274 = (_e271 - _e270);
                    let _e282 = abs(_e268);
                    let _e283 = abs(_e269);
                    let _e284 = abs(_e270);
                    let _e285 = abs(_e271);
                    let _e286 = abs((_e268 + (_e272 * 0.5f)));
                    let _e287 = abs((_e269 + (_e272 * -0.5f)));
                    let _e288 = abs((_e270 + (_e274 * 0.5f)));
                    let _e289 = abs((_e271 + (_e274 * -0.5f)));
                    let _e298 = (_e95 * 0.011f);
                    let _e303 = (1.25f - (select(_e286, _e282, (_e282 < _e286)) / _e298));
                    let _e307 = select(0f, select(1f, _e303, (_e303 < 1f)), (_e303 > 0f));
                    let _e308 = (1.25f - (select(_e287, _e283, (_e283 < _e287)) / _e298));
                    let _e312 = select(0f, select(1f, _e308, (_e308 < 1f)), (_e308 > 0f));
                    let _e313 = (1.25f - (select(_e288, _e284, (_e284 < _e288)) / _e298));
                    let _e317 = select(0f, select(1f, _e313, (_e313 < 1f)), (_e313 > 0f));
                    let _e318 = (1.25f - (select(_e289, _e285, (_e285 < _e289)) / _e298));
                    let _e322 = select(0f, select(1f, _e318, (_e318 < 1f)), (_e318 > 0f));
                    let _e323 = (((((((f32(_e126) + 0.5f) / _e41) * 2f) - 1f) * _e108) * _e142) - _e110);
                    let _e324 = (((((((f32(_e131) + 0.5f) / _e51) * -2f) + 1f) * _e117) * _e142) - _e119);
                    let _e330 = sqrt((((_e323 * _e323) + (_e324 * _e324)) + (_e268 * _e268)));
                    if (_e330 > 0f) {
                        phi_723_ = vec3<f32>((_e323 / _e330), (_e324 / _e330), (_e268 / _e330));
                    } else {
                        phi_723_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e337 = phi_723_;
                    let _e338 = (((((((f32(_e163) + 0.5f) / _e41) * 2f) - 1f) * _e108) * _e179) - _e110);
                    let _e339 = (((((((f32(_e168) + 0.5f) / _e51) * -2f) + 1f) * _e117) * _e179) - _e119);
                    let _e345 = sqrt((((_e338 * _e338) + (_e339 * _e339)) + (_e269 * _e269)));
                    if (_e345 > 0f) {
                        phi_741_ = vec3<f32>((_e338 / _e345), (_e339 / _e345), (_e269 / _e345));
                    } else {
                        phi_741_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e352 = phi_741_;
                    let _e353 = (((((((f32(_e198) + 0.5f) / _e41) * 2f) - 1f) * _e108) * _e216) - _e110);
                    let _e354 = (((((((f32(_e205) + 0.5f) / _e51) * -2f) + 1f) * _e117) * _e216) - _e119);
                    let _e360 = sqrt((((_e353 * _e353) + (_e354 * _e354)) + (_e270 * _e270)));
                    if (_e360 > 0f) {
                        phi_759_ = vec3<f32>((_e353 / _e360), (_e354 / _e360), (_e270 / _e360));
                    } else {
                        phi_759_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e367 = phi_759_;
                    let _e368 = (((((((f32(_e235) + 0.5f) / _e41) * 2f) - 1f) * _e108) * _e253) - _e110);
                    let _e369 = (((((((f32(_e242) + 0.5f) / _e51) * -2f) + 1f) * _e117) * _e253) - _e119);
                    let _e375 = sqrt((((_e368 * _e368) + (_e369 * _e369)) + (_e271 * _e271)));
                    if (_e375 > 0f) {
                        phi_777_ = vec3<f32>((_e368 / _e375), (_e369 / _e375), (_e271 / _e375));
                    } else {
                        phi_777_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e382 = phi_777_;
                    let _e399 = ((_e307 * _e317) + 0.01f);
                    let _e403 = select(0f, select(1f, _e399, (_e399 < 1f)), (_e399 > 0f));
                    let _e420 = ((_e317 * _e312) + 0.01f);
                    let _e424 = select(0f, select(1f, _e420, (_e420 < 1f)), (_e420 > 0f));
                    let _e444 = ((_e312 * _e322) + 0.01f);
                    let _e448 = select(0f, select(1f, _e444, (_e444 < 1f)), (_e444 > 0f));
                    let _e465 = ((_e322 * _e307) + 0.01f);
                    let _e469 = select(0f, select(1f, _e465, (_e465 < 1f)), (_e465 > 0f));
                    let _e473 = ((((((_e337.y * _e367.z) - (_e367.y * _e337.z)) * _e403) + (((_e367.y * _e352.z) - (_e352.y * _e367.z)) * _e424)) + (((_e352.y * _e382.z) - (_e382.y * _e352.z)) * _e448)) + (((_e382.y * _e337.z) - (_e337.y * _e382.z)) * _e469));
                    let _e474 = ((((((_e337.z * _e367.x) - (_e367.z * _e337.x)) * _e403) + (((_e367.z * _e352.x) - (_e352.z * _e367.x)) * _e424)) + (((_e352.z * _e382.x) - (_e382.z * _e352.x)) * _e448)) + (((_e382.z * _e337.x) - (_e337.z * _e382.x)) * _e469));
                    let _e475 = ((((((_e337.x * _e367.y) - (_e367.x * _e337.y)) * _e403) + (((_e367.x * _e352.y) - (_e352.x * _e367.y)) * _e424)) + (((_e352.x * _e382.y) - (_e382.x * _e352.y)) * _e448)) + (((_e382.x * _e337.y) - (_e337.x * _e382.y)) * _e469));
                    let _e481 = sqrt((((_e473 * _e473) + (_e474 * _e474)) + (_e475 * _e475)));
                    if (_e481 > 0f) {
                        phi_945_ = vec3<f32>((_e473 / _e481), (_e474 / _e481), (_e475 / _e481));
                    } else {
                        phi_945_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e488 = phi_945_;
                    let _e492 = -(_e488.z);
                    let _e497 = ((abs(_e488.x) + abs(_e488.y)) + abs(_e492));
                    let _e498 = (_e488.x / _e497);
                    let _e499 = (_e488.y / _e497);
                    if (_e492 < 0f) {
                        phi_979_ = vec2<f32>(((1f - abs(_e499)) * select(1f, -1f, (_e498 < 0f))), ((1f - abs(_e498)) * select(1f, -1f, (_e499 < 0f))));
                    } else {
                        phi_979_ = vec2<f32>(_e498, _e499);
                    }
                    let _e514 = phi_979_;
                    if (_e514.x != _e514.x) {
                        phi_995_ = 0f;
                    } else {
                        phi_995_ = select(-1f, select(1f, _e514.x, (_e514.x < 1f)), (_e514.x > -1f));
                    }
                    let _e522 = phi_995_;
                    let _e527 = ((_e522 * 127f) + (0.5f * select(1f, -1f, (_e522 < 0f))));
                    if (_e514.y != _e514.y) {
                        phi_1030_ = 0f;
                    } else {
                        phi_1030_ = select(-1f, select(1f, _e514.y, (_e514.y < 1f)), (_e514.y > -1f));
                    }
                    let _e544 = phi_1030_;
                    let _e549 = ((_e544 * 127f) + (0.5f * select(1f, -1f, (_e544 < 0f))));
                    let _e563 = ((_e32.y * _e46) + _e32.x);
                    if (_e563 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    normals.member[_e563] = ((bitcast<u32>(select(0i, select(select(i32(_e527), i32(-2147483648), (_e527 < -2147483600f)), 2147483647i, (_e527 > 2147483500f)), (_e527 == _e527))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e549), i32(-2147483648), (_e549 < -2147483600f)), 2147483647i, (_e549 > 2147483500f)), (_e549 == _e549))) & 255u) << bitcast<u32>(8i)));
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
