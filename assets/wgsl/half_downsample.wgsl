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

struct type_19 {
    member: type_5,
    member_1: type_5,
    member_2: u32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_20 {
    member: type_19,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(4) 
var<uniform> params: type_20;
@group(0) @binding(2) 
var<storage, read_write> half_depth: type_7;
@group(0) @binding(3) 
var<storage, read_write> half_normals: type_10;

fn function_() {
    var phi_109_: bool;
    var phi_130_: u32;
    var phi_133_: f32;
    var phi_135_: vec2<u32>;
    var phi_173_: bool;
    var phi_184_: bool;
    var phi_185_: bool;
    var phi_191_: vec2<u32>;
    var phi_131_: u32;
    var phi_134_: f32;
    var phi_136_: vec2<u32>;
    var local: vec2<u32>;
    var local_1: vec2<u32>;
    var phi_381_: bool;

    let _e31 = id_1;
    let _e38 = params.member.member_1.member[0u];
    let _e43 = select(select(u32(_e38), 0u, (_e38 < 0f)), 4294967295u, (_e38 > 4294967000f));
    let _e48 = params.member.member_1.member[1u];
    if (_e31.x >= _e43) {
    } else {
        if (_e31.y >= select(select(u32(_e48), 0u, (_e48 < 0f)), 4294967295u, (_e48 > 4294967000f))) {
        } else {
            let _e58 = params.member.member_2;
            if (_e58 == 0u) {
                phi_109_ = (((_e31.x + _e31.y) & 1u) == 1u);
            } else {
                phi_109_ = false;
            }
            let _e64 = phi_109_;
            let _e65 = (2u * _e31.x);
            let _e66 = (2u * _e31.y);
            let _e72 = params.member.member.member[0u];
            let _e77 = select(select(u32(_e72), 0u, (_e72 < 0f)), 4294967295u, (_e72 > 4294967000f));
            let _e82 = depth.member[((_e66 * _e77) + _e65)];
            phi_130_ = 1u;
            phi_133_ = _e82;
            phi_135_ = vec2<u32>(_e65, _e66);
            loop {
                let _e84 = phi_130_;
                let _e86 = phi_133_;
                let _e88 = phi_135_;
                local = _e88;
                local_1 = _e88;
                let _e89 = (_e84 < 4u);
                if _e89 {
                    let _e93 = (_e65 + (_e84 & 1u));
                    let _e94 = (_e66 + (_e84 >> bitcast<u32>(1i)));
                    let _e99 = depth.member[((_e94 * _e77) + _e93)];
                    if _e64 {
                        phi_173_ = select(true, false, (_e99 > _e86));
                    } else {
                        phi_173_ = true;
                    }
                    let _e103 = phi_173_;
                    if _e103 {
                        if _e64 {
                            phi_184_ = false;
                        } else {
                            phi_184_ = (_e99 < _e86);
                        }
                        let _e106 = phi_184_;
                        phi_185_ = _e106;
                    } else {
                        phi_185_ = true;
                    }
                    let _e108 = phi_185_;
                    if _e108 {
                        phi_191_ = vec2<u32>(_e93, _e94);
                    } else {
                        phi_191_ = _e88;
                    }
                    let _e111 = phi_191_;
                    phi_131_ = (_e84 + 1u);
                    phi_134_ = select(_e86, _e99, _e108);
                    phi_136_ = _e111;
                } else {
                    phi_131_ = u32();
                    phi_134_ = f32();
                    phi_136_ = vec2<u32>();
                }
                let _e115 = phi_131_;
                let _e117 = phi_134_;
                let _e119 = phi_136_;
                continue;
                continuing {
                    phi_130_ = _e115;
                    phi_133_ = _e117;
                    phi_135_ = _e119;
                    break if !(_e89);
                }
            }
            let _e122 = local;
            let _e125 = local_1;
            let _e128 = ((_e125.y * _e77) + _e122.x);
            let _e131 = depth.member[_e128];
            let _e134 = normals.member[_e128];
            let _e137 = f32(bitcast<i32>((_e134 & 255u)));
            let _e141 = (select(_e137, (_e137 - 256f), (_e137 >= 128f)) * 0.007874016f);
            let _e144 = select(-1f, _e141, ((_e141 > -1f) || false));
            let _e149 = f32(bitcast<i32>(((_e134 >> bitcast<u32>(8u)) & 255u)));
            let _e153 = (select(_e149, (_e149 - 256f), (_e149 >= 128f)) * 0.007874016f);
            let _e156 = select(-1f, _e153, ((_e153 > -1f) || false));
            let _e158 = (1f - abs(_e144));
            let _e159 = abs(_e156);
            let _e160 = (_e158 - _e159);
            let _e161 = (_e160 < 0f);
            let _e169 = select(_e144, ((1f - _e159) * select(1f, -1f, (_e144 < 0f))), _e161);
            let _e170 = select(_e156, (_e158 * select(1f, -1f, (_e156 < 0f))), _e161);
            let _e177 = (1f / sqrt((((_e169 * _e169) + (_e170 * _e170)) + (_e160 * _e160))));
            let _e178 = (_e169 * _e177);
            let _e179 = (_e170 * _e177);
            let _e180 = (_e160 * _e177);
            let _e197 = params.member.member_1.member_1[0u];
            let _e203 = params.member.member_1.member_1[1u];
            let _e221 = params.member.member.member[1u];
            let _e232 = params.member.member.member_1[0u];
            let _e239 = params.member.member.member_1[1u];
            let _e247 = ((((_e178 * ((((((f32(bitcast<i32>(_e122.x)) + 0.5f) / _e72) * 2f) - 1f) * _e131) * _e232)) + (_e179 * ((((((f32(bitcast<i32>(_e125.y)) + 0.5f) / _e221) * -2f) + 1f) * _e131) * _e239))) + (_e180 * -(_e131))) / (((_e178 * (((((f32(bitcast<i32>(_e31.x)) + 0.5f) / _e38) * 2f) - 1f) * _e197)) + (_e179 * (((((f32(bitcast<i32>(_e31.y)) + 0.5f) / _e48) * -2f) + 1f) * _e203))) + (_e180 * -1f)));
            let _e251 = params.member.member.member_3;
            if select(false, (_e131 < _e251), (_e131 > 0f)) {
                phi_381_ = select(true, false, (abs((_e247 - _e131)) <= (0.1f * _e131)));
            } else {
                phi_381_ = true;
            }
            let _e261 = phi_381_;
            let _e264 = ((_e31.y * _e43) + _e31.x);
            half_depth.member[_e264] = select(_e247, _e131, _e261);
            half_normals.member[_e264] = _e134;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn half_downsample(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
