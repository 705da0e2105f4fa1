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
    var phi_231_: i32;
    var phi_250_: i32;
    var phi_280_: bool;
    var phi_330_: i32;
    var phi_349_: i32;
    var phi_379_: bool;
    var phi_429_: i32;
    var phi_448_: i32;
    var phi_478_: bool;
    var phi_528_: i32;
    var phi_547_: i32;
    var phi_577_: bool;
    var phi_667_: f32;
    var phi_678_: f32;
    var phi_689_: f32;
    var phi_700_: f32;
    var phi_718_: vec3<f32>;
    var phi_736_: vec3<f32>;
    var phi_754_: vec3<f32>;
    var phi_772_: vec3<f32>;
    var phi_805_: f32;
    var phi_841_: f32;
    var phi_880_: f32;
    var phi_919_: f32;
    var phi_940_: vec3<f32>;
    var phi_974_: vec2<f32>;
    var phi_989_: f32;
    var phi_990_: f32;
    var phi_1024_: f32;
    var phi_1025_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e31 = id_1;
            let _e33 = arrayLength((&depth.member));
            let _e40 = params.member.member.member[0u];
            let _e45 = select(select(u32(_e40), 0u, (_e40 < 0f)), 4294967295u, (_e40 > 4294967000f));
            let _e50 = params.member.member.member[1u];
            let _e55 = select(select(u32(_e50), 0u, (_e50 < 0f)), 4294967295u, (_e50 > 4294967000f));
            if (_e31.x >= _e45) {
            } else {
                if (_e31.y >= _e55) {
                } else {
                    let _e60 = bitcast<i32>(_e31.x);
                    let _e62 = (bitcast<i32>(_e45) - 1i);
                    let _e63 = (0i <= _e62);
                    if _e63 {
                    } else {
                        break;
                    }
                    let _e64 = (_e60 < 0i);
                    if _e64 {
                        phi_132_ = 0i;
                    } else {
                        phi_132_ = select(_e60, _e62, (_e60 > _e62));
                    }
                    let _e68 = phi_132_;
                    let _e69 = bitcast<u32>(_e68);
                    let _e70 = bitcast<i32>(_e31.y);
                    let _e72 = (bitcast<i32>(_e55) - 1i);
                    let _e73 = (0i <= _e72);
                    if _e73 {
                    } else {
                        break;
                    }
                    let _e74 = (_e70 < 0i);
                    if _e74 {
                        phi_151_ = 0i;
                    } else {
                        phi_151_ = select(_e70, _e72, (_e70 > _e72));
                    }
                    let _e78 = phi_151_;
                    let _e79 = bitcast<u32>(_e78);
                    let _e81 = ((_e79 * _e45) + _e69);
                    if (_e81 < _e33) {
                    } else {
                        break;
                    }
                    let _e85 = depth.member[_e81];
                    let _e89 = params.member.member.member_3;
                    if (_e85 > 0f) {
                        phi_181_ = (_e85 < _e89);
                    } else {
                        phi_181_ = false;
                    }
                    let _e93 = phi_181_;
                    let _e94 = select(_e89, _e85, _e93);
                    let _e107 = params.member.member.member_1[0u];
                    let _e109 = ((((2f * ((f32(_e69) + 0.5f) / _e40)) - 1f) * _e107) * _e94);
                    let _e116 = params.member.member.member_1[1u];
                    let _e118 = (((1f - (2f * ((f32(_e79) + 0.5f) / _e50))) * _e116) * _e94);
                    let _e119 = (_e60 + -1i);
                    if _e63 {
                    } else {
                        break;
                    }
                    if (_e119 < 0i) {
                        phi_231_ = 0i;
                    } else {
                        phi_231_ = select(_e119, _e62, (_e119 > _e62));
                    }
                    let _e124 = phi_231_;
                    let _e125 = bitcast<u32>(_e124);
                    if _e73 {
                    } else {
                        break;
                    }
                    if _e74 {
                        phi_250_ = 0i;
                    } else {
                        phi_250_ = select(_e70, _e72, (_e70 > _e72));
                    }
                    let _e129 = phi_250_;
                    let _e130 = bitcast<u32>(_e129);
                    let _e132 = ((_e130 * _e45) + _e125);
                    if (_e132 < _e33) {
                    } else {
                        break;
                    }
                    let _e136 = depth.member[_e132];
                    if (_e136 > 0f) {
                        phi_280_ = (_e136 < _e89);
                    } else {
                        phi_280_ = false;
                    }
                    let _e140 = phi_280_;
                    let _e141 = select(_e89, _e136, _e140);
                    let _e156 = (_e60 + 1i);
                    if _e63 {
                    } else {
                        break;
                    }
                    if (_e156 < 0i) {
                        phi_330_ = 0i;
                    } else {
                        phi_330_ = select(_e156, _e62, (_e156 > _e62));
                    }
                    let _e161 = phi_330_;
                    let _e162 = bitcast<u32>(_e161);
                    if _e73 {
                    } else {
                        break;
                    }
                    if _e74 {
                        phi_349_ = 0i;
                    } else {
                        phi_349_ = select(_e70, _e72, (_e70 > _e72));
                    }
                    let _e166 = phi_349_;
                    let _e167 = bitcast<u32>(_e166);
                    let _e169 = ((_e167 * _e45) + _e162);
                    if (_e169 < _e33) {
                    } else {
                        break;
                    }
                    let _e173 = depth.member[_e169];
                    if (_e173 > 0f) {
                        phi_379_ = (_e173 < _e89);
                    } else {
                        phi_379_ = false;
                    }
                    let _e177 = phi_379_;
                    let _e178 = select(_e89, _e173, _e177);
                    if _e63 {
                    } else {
                        break;
                    }
                    if _e64 {
                        phi_429_ = 0i;
                    } else {
                        phi_429_ = select(_e60, _e62, (_e60 > _e62));
                    }
                    let _e196 = phi_429_;
                    let _e197 = bitcast<u32>(_e196);
                    let _e198 = (_e70 + -1i);
                    if _e73 {
                    } else {
                        break;
                    }
                    if (_e198 < 0i) {
                        phi_448_ = 0i;
                    } else {
                        phi_448_ = select(_e198, _e72, (_e198 > _e72));
                    }
                    let _e203 = phi_448_;
                    let _e204 = bitcast<u32>(_e203);
                    let _e206 = ((_e204 * _e45) + _e197);
                    if (_e206 < _e33) {
                    } else {
                        break;
                    }
                    let _e210 = depth.member[_e206];
                    if (_e210 > 0f) {
                        phi_478_ = (_e210 < _e89);
                    } else {
                        phi_478_ = false;
                    }
                    let _e214 = phi_478_;
                    let _e215 = select(_e89, _e210, _e214);
                    if _e63 {
                    } else {
                        break;
                    }
                    if _e64 {
                        phi_528_ = 0i;
                    } else {
                        phi_528_ = select(_e60, _e62, (_e60 > _e62));
                    }
                    let _e233 = phi_528_;
                    let _e234 = bitcast<u32>(_e233);
                    let _e235 = (_e70 + 1i);
                    if _e73 {
                    } else {
                        break;
                    }
                    if (_e235 < 0i) {
                        phi_547_ = 0i;
                    } else {
                        phi_547_ = select(_e235, _e72, (_e235 > _e72));
                    }
                    let _e240 = phi_547_;
                    let _e241 = bitcast<u32>(_e240);
                    let _e243 = ((_e241 * _e45) + _e234);
                    if (_e243 < _e33) {
                    } else {
                        break;
                    }
                    let _e247 = depth.member[_e243];
                    if (_e247 > 0f) {
                        phi_577_ = (_e247 < _e89);
                    } else {
                        phi_577_ = false;
                    }
                    let _e251 = phi_577_;
                    let _e252 = select(_e89, _e247, _e251);
                    let _e267 = (_e141 - _e94);
                    let _e268 = (_e178 - _e94);
                    let _e269 = (_e215 - _e94);
                    let _e270 = (_e252 - _e94);
                    let _e271 = (_e268 - _e267);
                    let _e273 = (_e270 - _e269);
                    let _e281 = abs(_e267);
                    let _e282 = abs(_e268);
                    let _e283 = abs(_e269);
                    let _e284 = abs(_e270);
                    let _e285 = abs((_e267 + (_e271 * 0.5f)));
                    let _e286 = abs((_e268 + (_e271 * -0.5f)));
                    let _e287 = abs((_e269 + (_e273 * 0.5f)));
                    let _e288 = abs((_e270 + (_e273 * -0.5f)));
                    let _e297 = (_e94 * 0.011f);
                    let _e302 = (1.25f - (select(_e285, _e281, (_e281 < _e285)) / _e297));
                    if (_e302 > 0f) {
                        phi_667_ = select(1f, _e302, (_e302 < 1f));
                    } else {
                        phi_667_ = 0f;
                    }
                    let _e307 = phi_667_;
                    let _e308 = (1.25f - (select(_e286, _e282, (_e282 < _e286)) / _e297));
                    if (_e308 > 0f) {
                        phi_678_ = select(1f, _e308, (_e308 < 1f));
                    } else {
                        phi_678_ = 0f;
                    }
                    let _e313 = phi_678_;
                    let _e314 = (1.25f - (select(_e287, _e283, (_e283 < _e287)) / _e297));
                    if (_e314 > 0f) {
                        phi_689_ = select(1f, _e314, (_e314 < 1f));
                    } else {
                        phi_689_ = 0f;
                    }
                    let _e319 = phi_689_;
                    let _e320 = (1.25f - (select(_e288, _e284, (_e284 < _e288)) / _e297));
                    if (_e320 > 0f) {
                        phi_700_ = select(1f, _e320, (_e320 < 1f));
                    } else {
                        phi_700_ = 0f;
                    }
                    let _e325 = phi_700_;
                    let _e326 = (((((2f * ((f32(_e125) + 0.5f) / _e40)) - 1f) * _e107) * _e141) - _e109);
                    let _e327 = ((((1f - (2f * ((f32(_e130) + 0.5f) / _e50))) * _e116) * _e141) - _e118);
                    let _e333 = sqrt((((_e326 * _e326) + (_e327 * _e327)) + (_e267 * _e267)));
                    if (_e333 > 0f) {
                        phi_718_ = vec3<f32>((_e326 / _e333), (_e327 / _e333), (_e267 / _e333));
                    } else {
                        phi_718_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e340 = phi_718_;
                    let _e341 = (((((2f * ((f32(_e162) + 0.5f) / _e40)) - 1f) * _e107) * _e178) - _e109);
                    let _e342 = ((((1f - (2f * ((f32(_e167) + 0.5f) / _e50))) * _e116) * _e178) - _e118);
                    let _e348 = sqrt((((_e341 * _e341) + (_e342 * _e342)) + (_e268 * _e268)));
                    if (_e348 > 0f) {
                        phi_736_ = vec3<f32>((_e341 / _e348), (_e342 / _e348), (_e268 / _e348));
                    } else {
                        phi_736_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e355 = phi_736_;
                    let _e356 = (((((2f * ((f32(_e197) + 0.5f) / _e40)) - 1f) * _e107) * _e215) - _e109);
                    let _e357 = ((((1f - (2f * ((f32(_e204) + 0.5f) / _e50))) * _e116) * _e215) - _e118);
                    let _e363 = sqrt((((_e356 * _e356) + (_e357 * _e357)) + (_e269 * _e269)));
                    if (_e363 > 0f) {
                        phi_754_ = vec3<f32>((_e356 / _e363), (_e357 / _e363), (_e269 / _e363));
                    } else {
                        phi_754_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e370 = phi_754_;
                    let _e371 = (((((2f * ((f32(_e234) + 0.5f) / _e40)) - 1f) * _e107) * _e252) - _e109);
                    let _e372 = ((((1f - (2f * ((f32(_e241) + 0.5f) / _e50))) * _e116) * _e252) - _e118);
                    let _e378 = sqrt((((_e371 * _e371) + (_e372 * _e372)) + (_e270 * _e270)));
                    if (_e378 > 0f) {
                        phi_772_ = vec3<f32>((_e371 / _e378), (_e372 / _e378), (_e270 / _e378));
                    } else {
                        phi_772_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e385 = phi_772_;
                    let _e402 = ((_e307 * _e319) + 0.01f);
                    if (_e402 > 0f) {
                        phi_805_ = select(1f, _e402, (_e402 < 1f));
                    } else {
                        phi_805_ = 0f;
                    }
                    let _e407 = phi_805_;
                    let _e424 = ((_e319 * _e313) + 0.01f);
                    if (_e424 > 0f) {
                        phi_841_ = select(1f, _e424, (_e424 < 1f));
                    } else {
                        phi_841_ = 0f;
                    }
                    let _e429 = phi_841_;
                    let _e449 = ((_e313 * _e325) + 0.01f);
                    if (_e449 > 0f) {
                        phi_880_ = select(1f, _e449, (_e449 < 1f));
                    } else {
                        phi_880_ = 0f;
                    }
                    let _e454 = phi_880_;
                    let _e471 = ((_e325 * _e307) + 0.01f);
                    if (_e471 > 0f) {
                        phi_919_ = select(1f, _e471, (_e471 < 1f));
                    } else {
                        phi_919_ = 0f;
                    }
                    let _e476 = phi_919_;
                    let _e480 = ((((((_e340.y * _e370.z) - (_e370.y * _e340.z)) * _e407) + (((_e370.y * _e355.z) - (_e355.y * _e370.z)) * _e429)) + (((_e355.y * _e385.z) - (_e385.y * _e355.z)) * _e454)) + (((_e385.y * _e340.z) - (_e340.y * _e385.z)) * _e476));
                    let _e481 = ((((((_e340.z * _e370.x) - (_e370.z * _e340.x)) * _e407) + (((_e370.z * _e355.x) - (_e355.z * _e370.x)) * _e429)) + (((_e355.z * _e385.x) - (_e385.z * _e355.x)) * _e454)) + (((_e385.z * _e340.x) - (_e340.z * _e385.x)) * _e476));
                    let _e482 = ((((((_e340.x * _e370.y) - (_e370.x * _e340.y)) * _e407) + (((_e370.x * _e355.y) - (_e355.x * _e370.y)) * _e429)) + (((_e355.x * _e385.y) - (_e385.x * _e355.y)) * _e454)) + (((_e385.x * _e340.y) - (_e340.x * _e385.y)) * _e476));
                    let _e488 = sqrt((((_e480 * _e480) + (_e481 * _e481)) + (_e482 * _e482)));
                    if (_e488 > 0f) {
                        phi_940_ = vec3<f32>((_e480 / _e488), (_e481 / _e488), (_e482 / _e488));
                    } else {
                        phi_940_ = vec3<f32>(0f, 0f, 0f);
                    }
                    let _e495 = phi_940_;
                    let _e499 = -(_e495.z);
                    let _e504 = ((abs(_e495.x) + abs(_e495.y)) + abs(_e499));
                    let _e505 = (_e495.x / _e504);
                    let _e506 = (_e495.y / _e504);
                    if (_e499 < 0f) {
                        phi_974_ = vec2<f32>(((1f - abs(_e506)) * select(1f, -1f, (_e505 < 0f))), ((1f - abs(_e505)) * select(1f, -1f, (_e506 < 0f))));
                    } else {
                        phi_974_ = vec2<f32>(_e505, _e506);
                    }
                    let _e521 = phi_974_;
                    if (_e521.x != _e521.x) {
                        phi_990_ = 0f;
                    } else {
                        if (_e521.x > -1f) {
                            phi_989_ = select(1f, _e521.x, (_e521.x < 1f));
                        } else {
                            phi_989_ = -1f;
                        }
                        let _e528 = phi_989_;
                        phi_990_ = _e528;
                    }
                    let _e530 = phi_990_;
                    let _e535 = ((_e530 * 127f) + (0.5f * select(1f, -1f, (_e530 < 0f))));
                    if (_e521.y != _e521.y) {
                        phi_1025_ = 0f;
                    } else {
                        if (_e521.y > -1f) {
                            phi_1024_ = select(1f, _e521.y, (_e521.y < 1f));
                        } else {
                            phi_1024_ = -1f;
                        }
                        let _e551 = phi_1024_;
                        phi_1025_ = _e551;
                    }
                    let _e553 = phi_1025_;
                    let _e558 = ((_e553 * 127f) + (0.5f * select(1f, -1f, (_e553 < 0f))));
                    let _e572 = ((_e31.y * _e45) + _e31.x);
                    if (_e572 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    normals.member[_e572] = ((bitcast<u32>(select(0i, select(select(i32(_e535), i32(-2147483648), (_e535 < -2147483600f)), 2147483647i, (_e535 > 2147483500f)), (_e535 == _e535))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e558), i32(-2147483648), (_e558 < -2147483600f)), 2147483647i, (_e558 > 2147483500f)), (_e558 == _e558))) & 255u) << bitcast<u32>(8i)));
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
