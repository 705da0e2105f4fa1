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
}

struct type_19 {
    member: type_18,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(4) 
var<uniform> params: type_19;
@group(0) @binding(0) 
var<storage> terms_in: type_10;
@group(0) @binding(1) 
var<storage> edges: type_10;
@group(0) @binding(2) 
var<storage, read_write> terms_out: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;

fn function_() {
    var phi_140_: f32;
    var phi_158_: i32;
    var phi_177_: i32;
    var phi_196_: i32;
    var phi_215_: i32;
    var phi_234_: i32;
    var phi_253_: i32;
    var phi_272_: i32;
    var phi_291_: i32;
    var phi_415_: f32;
    var phi_428_: f32;
    var phi_439_: f32;
    var phi_450_: f32;
    var phi_461_: f32;
    var phi_559_: i32;
    var phi_578_: i32;
    var phi_610_: i32;
    var phi_629_: i32;
    var phi_661_: i32;
    var phi_680_: i32;
    var phi_712_: i32;
    var phi_731_: i32;
    var phi_782_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e33 = id_1;
            let _e35 = arrayLength((&terms_in.member));
            let _e37 = arrayLength((&edges.member));
            let _e46 = params.member.member.member[0u];
            let _e51 = select(select(u32(_e46), 0u, (_e46 < 0f)), 4294967295u, (_e46 > 4294967000f));
            let _e56 = params.member.member.member[1u];
            let _e61 = select(select(u32(_e56), 0u, (_e56 < 0f)), 4294967295u, (_e56 > 4294967000f));
            if (_e33.x >= _e51) {
            } else {
                if (_e33.y >= _e61) {
                } else {
                    let _e68 = params.member.member_10;
                    let _e73 = params.member.member_12;
                    let _e75 = ((_e73 + 1u) >= select(1u, _e68, (1u < _e68)));
                    if (_e68 == 0u) {
                        phi_140_ = 10000f;
                    } else {
                        phi_140_ = select(0.24000001f, 1.2f, _e75);
                    }
                    let _e79 = phi_140_;
                    let _e80 = bitcast<i32>(_e33.x);
                    let _e81 = (_e80 + -1i);
                    let _e83 = (bitcast<i32>(_e51) - 1i);
                    let _e84 = (0i <= _e83);
                    if _e84 {
                    } else {
                        break;
                    }
                    let _e85 = (_e81 < 0i);
                    if _e85 {
                        phi_158_ = 0i;
                    } else {
                        phi_158_ = select(_e81, _e83, (_e81 > _e83));
                    }
                    let _e89 = phi_158_;
                    let _e91 = bitcast<i32>(_e33.y);
                    let _e93 = (bitcast<i32>(_e61) - 1i);
                    let _e94 = (0i <= _e93);
                    if _e94 {
                    } else {
                        break;
                    }
                    let _e95 = (_e91 < 0i);
                    if _e95 {
                        phi_177_ = 0i;
                    } else {
                        phi_177_ = select(_e91, _e93, (_e91 > _e93));
                    }
                    let _e99 = phi_177_;
                    let _e101 = (_e80 + 1i);
                    if _e84 {
                    } else {
                        break;
                    }
                    let _e102 = (_e101 < 0i);
                    if _e102 {
                        phi_196_ = 0i;
                    } else {
                        phi_196_ = select(_e101, _e83, (_e101 > _e83));
                    }
                    let _e106 = phi_196_;
                    if _e94 {
                    } else {
                        break;
                    }
                    if _e95 {
                        phi_215_ = 0i;
                    } else {
                        phi_215_ = select(_e91, _e93, (_e91 > _e93));
                    }
                    let _e111 = phi_215_;
                    if _e84 {
                    } else {
                        break;
                    }
                    let _e113 = (_e80 < 0i);
                    if _e113 {
                        phi_234_ = 0i;
                    } else {
                        phi_234_ = select(_e80, _e83, (_e80 > _e83));
                    }
                    let _e117 = phi_234_;
                    let _e119 = (_e91 + -1i);
                    if _e94 {
                    } else {
                        break;
                    }
                    let _e120 = (_e119 < 0i);
                    if _e120 {
                        phi_253_ = 0i;
                    } else {
                        phi_253_ = select(_e119, _e93, (_e119 > _e93));
                    }
                    let _e124 = phi_253_;
                    if _e84 {
                    } else {
                        break;
                    }
                    if _e113 {
                        phi_272_ = 0i;
                    } else {
                        phi_272_ = select(_e80, _e83, (_e80 > _e83));
                    }
                    let _e129 = phi_272_;
                    let _e131 = (_e91 + 1i);
                    if _e94 {
                    } else {
                        break;
                    }
                    let _e132 = (_e131 < 0i);
                    if _e132 {
                        phi_291_ = 0i;
                    } else {
                        phi_291_ = select(_e131, _e93, (_e131 > _e93));
                    }
                    let _e136 = phi_291_;
                    let _e139 = ((bitcast<u32>(_e99) * _e51) + bitcast<u32>(_e89));
                    if (_e139 < _e37) {
                    } else {
                        break;
                    }
                    let _e143 = edges.member[_e139];
                    let _e158 = ((bitcast<u32>(_e111) * _e51) + bitcast<u32>(_e106));
                    if (_e158 < _e37) {
                    } else {
                        break;
                    }
                    let _e162 = edges.member[_e158];
                    let _e177 = ((bitcast<u32>(_e124) * _e51) + bitcast<u32>(_e117));
                    if (_e177 < _e37) {
                    } else {
                        break;
                    }
                    let _e181 = edges.member[_e177];
                    let _e196 = ((bitcast<u32>(_e136) * _e51) + bitcast<u32>(_e129));
                    if (_e196 < _e37) {
                    } else {
                        break;
                    }
                    let _e200 = edges.member[_e196];
                    let _e217 = ((_e33.y * _e51) + _e33.x);
                    if (_e217 < _e37) {
                    } else {
                        break;
                    }
                    let _e221 = edges.member[_e217];
                    let _e240 = ((f32(((_e221 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f) * (f32(((_e143 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f));
                    let _e241 = ((f32(((_e221 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f) * (f32(((_e162 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f));
                    let _e242 = ((f32(((_e221 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f) * (f32((_e181 & 3u)) * 0.33333334f));
                    let _e243 = ((f32((_e221 & 3u)) * 0.33333334f) * (f32(((_e200 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f));
                    let _e247 = (1.5f - (((_e240 + _e241) + _e242) + _e243));
                    if (_e247 > 0f) {
                        phi_415_ = select(1f, _e247, (_e247 < 1f));
                    } else {
                        phi_415_ = 0f;
                    }
                    let _e252 = phi_415_;
                    let _e253 = (_e252 * 0.33333334f);
                    let _e254 = (_e240 + _e253);
                    if (_e254 > 0f) {
                        phi_428_ = select(1f, _e254, (_e254 < 1f));
                    } else {
                        phi_428_ = 0f;
                    }
                    let _e259 = phi_428_;
                    let _e260 = (_e241 + _e253);
                    if (_e260 > 0f) {
                        phi_439_ = select(1f, _e260, (_e260 < 1f));
                    } else {
                        phi_439_ = 0f;
                    }
                    let _e265 = phi_439_;
                    let _e266 = (_e242 + _e253);
                    if (_e266 > 0f) {
                        phi_450_ = select(1f, _e266, (_e266 < 1f));
                    } else {
                        phi_450_ = 0f;
                    }
                    let _e271 = phi_450_;
                    let _e272 = (_e243 + _e253);
                    if (_e272 > 0f) {
                        phi_461_ = select(1f, _e272, (_e272 < 1f));
                    } else {
                        phi_461_ = 0f;
                    }
                    let _e277 = phi_461_;
                    let _e281 = (0.425f * ((_e259 * (f32(((_e143 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f)) + (_e271 * (f32(((_e181 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f))));
                    let _e285 = (0.425f * ((_e271 * (f32(((_e181 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f)) + (_e265 * (f32(((_e162 >> bitcast<u32>(2i)) & 3u)) * 0.33333334f))));
                    let _e289 = (0.425f * ((_e277 * (f32(((_e200 >> bitcast<u32>(6i)) & 3u)) * 0.33333334f)) + (_e259 * (f32((_e143 & 3u)) * 0.33333334f))));
                    let _e293 = (0.425f * ((_e265 * (f32((_e162 & 3u)) * 0.33333334f)) + (_e277 * (f32(((_e200 >> bitcast<u32>(4i)) & 3u)) * 0.33333334f))));
                    if (_e217 < _e35) {
                    } else {
                        break;
                    }
                    let _e297 = terms_in.member[_e217];
                    if (_e139 < _e35) {
                    } else {
                        break;
                    }
                    let _e304 = terms_in.member[_e139];
                    if (_e158 < _e35) {
                    } else {
                        break;
                    }
                    let _e312 = terms_in.member[_e158];
                    if (_e177 < _e35) {
                    } else {
                        break;
                    }
                    let _e320 = terms_in.member[_e177];
                    if (_e196 < _e35) {
                    } else {
                        break;
                    }
                    let _e328 = terms_in.member[_e196];
                    if _e84 {
                    } else {
                        break;
                    }
                    if _e85 {
                        phi_559_ = 0i;
                    } else {
                        phi_559_ = select(_e81, _e83, (_e81 > _e83));
                    }
                    let _e336 = phi_559_;
                    if _e94 {
                    } else {
                        break;
                    }
                    if _e120 {
                        phi_578_ = 0i;
                    } else {
                        phi_578_ = select(_e119, _e93, (_e119 > _e93));
                    }
                    let _e341 = phi_578_;
                    let _e344 = ((bitcast<u32>(_e341) * _e51) + bitcast<u32>(_e336));
                    if (_e344 < _e35) {
                    } else {
                        break;
                    }
                    let _e348 = terms_in.member[_e344];
                    if _e84 {
                    } else {
                        break;
                    }
                    if _e102 {
                        phi_610_ = 0i;
                    } else {
                        phi_610_ = select(_e101, _e83, (_e101 > _e83));
                    }
                    let _e356 = phi_610_;
                    if _e94 {
                    } else {
                        break;
                    }
                    if _e120 {
                        phi_629_ = 0i;
                    } else {
                        phi_629_ = select(_e119, _e93, (_e119 > _e93));
                    }
                    let _e361 = phi_629_;
                    let _e364 = ((bitcast<u32>(_e361) * _e51) + bitcast<u32>(_e356));
                    if (_e364 < _e35) {
                    } else {
                        break;
                    }
                    let _e368 = terms_in.member[_e364];
                    if _e84 {
                    } else {
                        break;
                    }
                    if _e85 {
                        phi_661_ = 0i;
                    } else {
                        phi_661_ = select(_e81, _e83, (_e81 > _e83));
                    }
                    let _e376 = phi_661_;
                    if _e94 {
                    } else {
                        break;
                    }
                    if _e132 {
                        phi_680_ = 0i;
                    } else {
                        phi_680_ = select(_e131, _e93, (_e131 > _e93));
                    }
                    let _e381 = phi_680_;
                    let _e384 = ((bitcast<u32>(_e381) * _e51) + bitcast<u32>(_e376));
                    if (_e384 < _e35) {
                    } else {
                        break;
                    }
                    let _e388 = terms_in.member[_e384];
                    if _e84 {
                    } else {
                        break;
                    }
                    if _e102 {
                        phi_712_ = 0i;
                    } else {
                        phi_712_ = select(_e101, _e83, (_e101 > _e83));
                    }
                    let _e396 = phi_712_;
                    if _e94 {
                    } else {
                        break;
                    }
                    if _e132 {
                        phi_731_ = 0i;
                    } else {
                        phi_731_ = select(_e131, _e93, (_e131 > _e93));
                    }
                    let _e401 = phi_731_;
                    let _e404 = ((bitcast<u32>(_e401) * _e51) + bitcast<u32>(_e396));
                    if (_e404 < _e35) {
                    } else {
                        break;
                    }
                    let _e408 = terms_in.member[_e404];
                    let _e421 = ((((((((((_e79 * (f32(_e297) * 0.003921569f)) + (_e259 * (f32(_e304) * 0.003921569f))) + (_e265 * (f32(_e312) * 0.003921569f))) + (_e271 * (f32(_e320) * 0.003921569f))) + (_e277 * (f32(_e328) * 0.003921569f))) + (_e281 * (f32(_e348) * 0.003921569f))) + (_e285 * (f32(_e368) * 0.003921569f))) + (_e289 * (f32(_e388) * 0.003921569f))) + (_e293 * (f32(_e408) * 0.003921569f))) / ((((((((_e79 + _e259) + _e265) + _e271) + _e277) + _e281) + _e285) + _e289) + _e293));
                    if _e75 {
                        let _e423 = ((_e421 * 382.5f) + 0.5f);
                        let _e428 = select(select(u32(_e423), 0u, (_e423 < 0f)), 4294967295u, (_e423 > 4294967000f));
                        phi_782_ = select(_e428, 255u, (255u < _e428));
                    } else {
                        let _e432 = ((_e421 * 255f) + 0.5f);
                        phi_782_ = select(select(u32(_e432), 0u, (_e432 < 0f)), 4294967295u, (_e432 > 4294967000f));
                    }
                    let _e439 = phi_782_;
                    if (_e217 < arrayLength((&terms_out.member))) {
                    } else {
                        break;
                    }
                    terms_out.member[_e217] = _e439;
                    if _e75 {
                        if (_e217 < arrayLength((&ao.member))) {
                        } else {
                            break;
                        }
                        ao.member[_e217] = (f32(_e439) * 0.003921569f);
                    }
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_denoise(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
