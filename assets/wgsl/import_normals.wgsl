struct type_5 {
    member: vec2<f32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_7 {
    member: array<u32>,
}

struct type_17 {
    member: type_5,
    member_1: vec2<u32>,
    member_2: u32,
    member_3: f32,
    member_4: f32,
    member_5: u32,
}

struct type_18 {
    member: type_17,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage, read_write> normals: type_7;
@group(0) @binding(2) 
var<uniform> params: type_18;
@group(0) @binding(0) 
var engine_normals: texture_2d<f32>;

fn function_() {
    var phi_91_: bool;
    var phi_175_: vec2<f32>;
    var phi_191_: f32;
    var phi_226_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e24 = id_1;
            let _e33 = params.member.member.member[0u];
            let _e38 = select(select(u32(_e33), 0u, (_e33 < 0f)), 4294967295u, (_e33 > 4294967000f));
            let _e43 = params.member.member.member[1u];
            if (_e24.x < _e38) {
                phi_91_ = (_e24.y < select(select(u32(_e43), 0u, (_e43 < 0f)), 4294967295u, (_e43 > 4294967000f)));
            } else {
                phi_91_ = false;
            }
            let _e52 = phi_91_;
            if _e52 {
                let _e56 = params.member.member.member_4;
                let _e61 = (select(_e56, _e24.x, (_e24.x > _e56)) - _e56);
                let _e62 = (select(_e56, _e24.y, (_e24.y > _e56)) - _e56);
                let _e66 = params.member.member_1[0u];
                let _e70 = params.member.member_1[1u];
                let _e71 = (_e66 - 1u);
                let _e72 = (_e70 - 1u);
                let _e80 = textureLoad(engine_normals, vec2<i32>(bitcast<i32>(select(_e71, _e61, (_e61 < _e71))), bitcast<i32>(select(_e72, _e62, (_e62 < _e72)))), 0u);
                let _e87 = ((_e80.x * 2f) - 1f);
                let _e88 = ((_e80.y * 2f) - 1f);
                let _e89 = ((_e80.z * 2f) - 1f);
                let _e94 = ((abs(_e87) + abs(_e88)) + abs(_e89));
                let _e95 = (_e87 / _e94);
                let _e96 = (_e88 / _e94);
                if (_e89 < 0f) {
                    phi_175_ = vec2<f32>(((1f - abs(_e96)) * select(1f, -1f, (_e95 < 0f))), ((1f - abs(_e95)) * select(1f, -1f, (_e96 < 0f))));
                } else {
                    phi_175_ = vec2<f32>(_e95, _e96);
                }
                let _e111 = phi_175_;
                if (_e111.x != _e111.x) {
                    phi_191_ = 0f;
                } else {
                    phi_191_ = select(-1f, select(1f, _e111.x, (_e111.x < 1f)), (_e111.x > -1f));
                }
                let _e119 = phi_191_;
                let _e124 = ((_e119 * 127f) + (0.5f * select(1f, -1f, (_e119 < 0f))));
                if (_e111.y != _e111.y) {
                    phi_226_ = 0f;
                } else {
                    phi_226_ = select(-1f, select(1f, _e111.y, (_e111.y < 1f)), (_e111.y > -1f));
                }
                let _e141 = phi_226_;
                let _e146 = ((_e141 * 127f) + (0.5f * select(1f, -1f, (_e141 < 0f))));
                let _e160 = ((_e24.y * _e38) + _e24.x);
                if (_e160 < arrayLength((&normals.member))) {
                } else {
                    break;
                }
                normals.member[_e160] = ((bitcast<u32>(select(0i, select(select(i32(_e124), i32(-2147483648), (_e124 < -2147483600f)), 2147483647i, (_e124 > 2147483500f)), (_e124 == _e124))) & 255u) | ((bitcast<u32>(select(0i, select(select(i32(_e146), i32(-2147483648), (_e146 < -2147483600f)), 2147483647i, (_e146 > 2147483500f)), (_e146 == _e146))) & 255u) << bitcast<u32>(8i)));
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn import_normals(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
