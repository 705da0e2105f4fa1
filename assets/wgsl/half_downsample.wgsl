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
    var phi_132_: u32;
    var phi_135_: f32;
    var phi_137_: vec2<u32>;
    var phi_133_: u32;
    var phi_136_: f32;
    var phi_138_: vec2<u32>;
    var local: vec2<u32>;
    var local_1: vec2<u32>;

    let _e30 = id_1;
    let _e37 = params.member.member_1.member[0u];
    let _e42 = select(select(u32(_e37), 0u, (_e37 < 0f)), 4294967295u, (_e37 > 4294967000f));
    let _e47 = params.member.member_1.member[1u];
    if (_e30.x >= _e42) {
    } else {
        if (_e30.y >= select(select(u32(_e47), 0u, (_e47 < 0f)), 4294967295u, (_e47 > 4294967000f))) {
        } else {
            let _e60 = params.member.member_2;
            let _e62 = select(false, (_e60 == 0u), (((_e30.x + _e30.y) & 1u) == 1u));
            let _e63 = (_e30.x + _e30.x);
            let _e64 = (_e30.y + _e30.y);
            let _e70 = params.member.member.member[0u];
            let _e75 = select(select(u32(_e70), 0u, (_e70 < 0f)), 4294967295u, (_e70 > 4294967000f));
            let _e80 = depth.member[((_e64 * _e75) + _e63)];
            phi_132_ = 1u;
            phi_135_ = _e80;
            phi_137_ = vec2<u32>(_e63, _e64);
            loop {
                let _e82 = phi_132_;
                let _e84 = phi_135_;
                let _e86 = phi_137_;
                local = _e86;
                local_1 = _e86;
                let _e87 = (_e82 < 4u);
                if _e87 {
                    let _e89 = (_e63 + (_e82 & 1u));
                    let _e92 = (_e64 + (_e82 >> bitcast<u32>(1i)));
                    let _e97 = depth.member[((_e92 * _e75) + _e89)];
                    let _e103 = select(select(false, (_e97 < _e84), !(_e62)), true, select(false, (_e97 > _e84), _e62));
                    phi_133_ = (_e82 + 1u);
                    phi_136_ = select(_e84, _e97, _e103);
                    phi_138_ = vec2<u32>(select(_e86.x, _e89, _e103), select(_e86.y, _e92, _e103));
                } else {
                    phi_133_ = u32();
                    phi_136_ = f32();
                    phi_138_ = vec2<u32>();
                }
                let _e112 = phi_133_;
                let _e114 = phi_136_;
                let _e116 = phi_138_;
                continue;
                continuing {
                    phi_132_ = _e112;
                    phi_135_ = _e114;
                    phi_137_ = _e116;
                    break if !(_e87);
                }
            }
            let _e119 = local;
            let _e122 = local_1;
            let _e125 = ((_e122.y * _e75) + _e119.x);
            let _e128 = depth.member[_e125];
            let _e131 = normals.member[_e125];
            let _e134 = f32(bitcast<i32>((_e131 & 255u)));
            let _e138 = (select(_e134, (_e134 - 256f), (_e134 >= 128f)) * 0.007874016f);
            let _e141 = select(-1f, _e138, ((_e138 > -1f) || false));
            let _e146 = f32(bitcast<i32>(((_e131 >> bitcast<u32>(8u)) & 255u)));
            let _e150 = (select(_e146, (_e146 - 256f), (_e146 >= 128f)) * 0.007874016f);
            let _e153 = select(-1f, _e150, ((_e150 > -1f) || false));
            let _e155 = (1f - abs(_e141));
            let _e156 = abs(_e153);
            let _e157 = (_e155 - _e156);
            let _e158 = (_e157 < 0f);
            let _e166 = select(_e141, ((1f - _e156) * select(1f, -1f, (_e141 < 0f))), _e158);
            let _e167 = select(_e153, (_e155 * select(1f, -1f, (_e153 < 0f))), _e158);
            let _e174 = (1f / sqrt((((_e166 * _e166) + (_e167 * _e167)) + (_e157 * _e157))));
            let _e175 = (_e166 * _e174);
            let _e176 = (_e167 * _e174);
            let _e177 = (_e157 * _e174);
            let _e182 = params.member.member.member_1[0u];
            let _e187 = params.member.member.member_1[1u];
            let _e192 = params.member.member.member[1u];
            let _e198 = (2f * _e182);
            let _e204 = (2f * _e187);
            let _e229 = ((((_e175 * (((f32(bitcast<i32>(_e119.x)) + 0.5f) * (_e198 / _e70)) - _e182)) + (_e176 * (-(((f32(bitcast<i32>(_e122.y)) + 0.5f) * (_e204 / _e192))) + _e187))) - _e177) / (((_e175 * (((f32(bitcast<i32>(_e30.x)) + 0.5f) * (_e198 / _e37)) - _e182)) + (_e176 * (-(((f32(bitcast<i32>(_e30.y)) + 0.5f) * (_e204 / _e47))) + _e187))) - _e177));
            let _e233 = params.member.member.member_3;
            let _e244 = ((_e30.y * _e42) + _e30.x);
            half_depth.member[_e244] = select(_e128, (_e128 * _e229), select(false, (abs((_e229 - 1f)) <= 0.1f), select(false, (_e128 < _e233), (_e128 > 0f))));
            half_normals.member[_e244] = _e131;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn half_downsample(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
