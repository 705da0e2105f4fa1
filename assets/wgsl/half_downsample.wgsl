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
    member_1: type_5,
    member_2: u32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_19 {
    member: type_18,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(4) 
var<uniform> params: type_19;
@group(0) @binding(2) 
var<storage, read_write> half_depth: type_7;
@group(0) @binding(3) 
var<storage, read_write> half_normals: type_10;

fn function_() {
    let _e25 = id_1;
    let _e32 = params.member.member_1.member[0u];
    let _e37 = select(select(u32(_e32), 0u, (_e32 < 0f)), 4294967295u, (_e32 > 4294967000f));
    let _e42 = params.member.member_1.member[1u];
    if (_e25.x >= _e37) {
    } else {
        if (_e25.y >= select(select(u32(_e42), 0u, (_e42 < 0f)), 4294967295u, (_e42 > 4294967000f))) {
        } else {
            let _e50 = (_e25.x + _e25.x);
            let _e51 = (_e25.y + _e25.y);
            let _e56 = params.member.member.member[0u];
            let _e61 = select(select(u32(_e56), 0u, (_e56 < 0f)), 4294967295u, (_e56 > 4294967000f));
            let _e62 = (_e51 * _e61);
            let _e66 = depth.member[(_e62 + _e50)];
            let _e67 = (_e50 + 1u);
            let _e71 = depth.member[(_e62 + _e67)];
            let _e72 = (_e51 + 1u);
            let _e73 = (_e72 * _e61);
            let _e77 = depth.member[(_e73 + _e50)];
            let _e81 = depth.member[(_e73 + _e67)];
            let _e87 = params.member.member_2;
            let _e89 = select(false, (_e87 == 0u), (((_e25.x + _e25.y) & 1u) == 1u));
            let _e92 = !(_e89);
            let _e95 = select(select(false, (_e71 < _e66), _e92), true, select(false, (_e71 > _e66), _e89));
            let _e97 = select(_e66, _e71, _e95);
            let _e102 = select(select(false, (_e77 < _e97), _e92), true, select(false, (_e77 > _e97), _e89));
            let _e105 = select(_e97, _e77, _e102);
            let _e110 = select(select(false, (_e81 < _e105), _e92), true, select(false, (_e81 > _e105), _e89));
            let _e111 = select(select(select(_e50, _e67, _e95), _e50, _e102), _e67, _e110);
            let _e112 = select(select(_e51, _e72, _e102), _e72, _e110);
            let _e113 = select(_e105, _e81, _e110);
            let _e118 = normals.member[((_e112 * _e61) + _e111)];
            let _e121 = f32(bitcast<i32>((_e118 & 255u)));
            let _e125 = (select(_e121, (_e121 - 256f), (_e121 >= 128f)) * 0.007874016f);
            let _e128 = select(-1f, _e125, ((_e125 > -1f) || false));
            let _e133 = f32(bitcast<i32>(((_e118 >> bitcast<u32>(8u)) & 255u)));
            let _e137 = (select(_e133, (_e133 - 256f), (_e133 >= 128f)) * 0.007874016f);
            let _e140 = select(-1f, _e137, ((_e137 > -1f) || false));
            let _e142 = (1f - abs(_e128));
            let _e143 = abs(_e140);
            let _e144 = (_e142 - _e143);
            let _e145 = (_e144 < 0f);
            let _e153 = select(_e128, ((1f - _e143) * select(1f, -1f, (_e128 < 0f))), _e145);
            let _e154 = select(_e140, (_e142 * select(1f, -1f, (_e140 < 0f))), _e145);
            let _e161 = (1f / sqrt((((_e153 * _e153) + (_e154 * _e154)) + (_e144 * _e144))));
            let _e162 = (_e153 * _e161);
            let _e163 = (_e154 * _e161);
            let _e164 = (_e144 * _e161);
            let _e169 = params.member.member.member_1[0u];
            let _e174 = params.member.member.member_1[1u];
            let _e179 = params.member.member.member[1u];
            let _e185 = (2f * _e169);
            let _e191 = (2f * _e174);
            let _e216 = ((((_e162 * (((f32(bitcast<i32>(_e111)) + 0.5f) * (_e185 / _e56)) - _e169)) + (_e163 * (-(((f32(bitcast<i32>(_e112)) + 0.5f) * (_e191 / _e179))) + _e174))) - _e164) / (((_e162 * (((f32(bitcast<i32>(_e25.x)) + 0.5f) * (_e185 / _e32)) - _e169)) + (_e163 * (-(((f32(bitcast<i32>(_e25.y)) + 0.5f) * (_e191 / _e42))) + _e174))) - _e164));
            let _e220 = params.member.member.member_3;
            let _e231 = ((_e25.y * _e37) + _e25.x);
            half_depth.member[_e231] = select(_e113, (_e113 * _e216), select(false, (abs((_e216 - 1f)) <= 0.1f), select(false, (_e113 < _e220), (_e113 > 0f))));
            half_normals.member[_e231] = _e118;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn half_downsample(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
