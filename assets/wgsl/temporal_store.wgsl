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

struct type_12 {
    member: vec4<f32>,
    member_1: vec4<f32>,
    member_2: vec4<f32>,
    member_3: vec4<f32>,
}

struct type_13 {
    member: type_12,
    member_1: type_12,
    member_2: type_5,
}

struct type_14 {
    member: type_13,
    member_1: type_13,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_16 {
    member: array<type_14>,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> depth: type_7;
@group(0) @binding(0) 
var<storage> frame: type_16;
@group(0) @binding(2) 
var<storage> accumulated: type_7;
@group(0) @binding(3) 
var<storage, read_write> history_ao: type_7;
@group(0) @binding(4) 
var<storage, read_write> history_depth: type_7;

fn function_() {
    switch bitcast<i32>(0u) {
        default: {
            let _e13 = id_1;
            if (0u < arrayLength((&frame.member))) {
            } else {
                break;
            }
            let _e31 = frame.member[0u].member.member_2.member[0u];
            let _e36 = select(select(u32(_e31), 0u, (_e31 < 0f)), 4294967295u, (_e31 > 4294967000f));
            let _e43 = frame.member[0u].member.member_2.member[1u];
            if (_e13.x >= _e36) {
            } else {
                if (_e13.y >= select(select(u32(_e43), 0u, (_e43 < 0f)), 4294967295u, (_e43 > 4294967000f))) {
                } else {
                    let _e54 = ((_e13.y * _e36) + _e13.x);
                    if (_e54 < arrayLength((&accumulated.member))) {
                    } else {
                        break;
                    }
                    let _e58 = accumulated.member[_e54];
                    if (_e54 < arrayLength((&history_ao.member))) {
                    } else {
                        break;
                    }
                    history_ao.member[_e54] = _e58;
                    if (_e54 < arrayLength((&depth.member))) {
                    } else {
                        break;
                    }
                    let _e65 = depth.member[_e54];
                    if (_e54 < arrayLength((&history_depth.member))) {
                    } else {
                        break;
                    }
                    history_depth.member[_e54] = _e65;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn temporal_store(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
