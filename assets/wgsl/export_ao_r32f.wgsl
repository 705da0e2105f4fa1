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

struct type_14 {
    member: type_5,
    member_1: vec2<u32>,
    member_2: u32,
    member_3: f32,
    member_4: f32,
    member_5: u32,
}

struct type_15 {
    member: type_14,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(2) 
var<uniform> params: type_15;
@group(0) @binding(0) 
var<storage> ao: type_7;
@group(0) @binding(1) 
var out: texture_storage_2d<r32float,read_write>;

fn function_() {
    var phi_56_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e13 = id_1;
            let _e21 = params.member.member_1[0u];
            let _e25 = params.member.member_1[1u];
            if (_e13.x < _e21) {
                phi_56_ = (_e13.y < _e25);
            } else {
                phi_56_ = false;
            }
            let _e29 = phi_56_;
            if _e29 {
                let _e33 = params.member.member.member_4;
                let _e34 = (_e13.x + _e33);
                let _e35 = (_e13.y + _e33);
                let _e40 = params.member.member.member[0u];
                let _e45 = select(select(u32(_e40), 0u, (_e40 < 0f)), 4294967295u, (_e40 > 4294967000f));
                let _e50 = params.member.member.member[1u];
                let _e56 = (_e45 - 1u);
                let _e57 = (select(select(u32(_e50), 0u, (_e50 < 0f)), 4294967295u, (_e50 > 4294967000f)) - 1u);
                let _e63 = ((select(_e57, _e35, (_e35 < _e57)) * _e45) + select(_e56, _e34, (_e34 < _e56)));
                if (_e63 < arrayLength((&ao.member))) {
                } else {
                    break;
                }
                let _e67 = ao.member[_e63];
                textureStore(out, vec2<u32>(_e13.x, _e13.y), vec4(select(0f, select(1f, _e67, (_e67 < 1f)), (_e67 > 0f))));
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn export_ao_r32f(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
