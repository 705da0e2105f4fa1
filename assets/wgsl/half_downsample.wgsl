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
    var phi_93_: bool;
    var phi_114_: u32;
    var phi_117_: f32;
    var phi_119_: vec2<u32>;
    var phi_157_: bool;
    var phi_168_: bool;
    var phi_169_: bool;
    var phi_175_: vec2<u32>;
    var phi_115_: u32;
    var phi_118_: f32;
    var phi_120_: vec2<u32>;
    var local: vec2<u32>;
    var local_1: vec2<u32>;

    let _e19 = id_1;
    let _e26 = params.member.member_1.member[0u];
    let _e31 = select(select(u32(_e26), 0u, (_e26 < 0f)), 4294967295u, (_e26 > 4294967000f));
    let _e36 = params.member.member_1.member[1u];
    if (_e19.x >= _e31) {
    } else {
        if (_e19.y >= select(select(u32(_e36), 0u, (_e36 < 0f)), 4294967295u, (_e36 > 4294967000f))) {
        } else {
            let _e46 = params.member.member_2;
            if (_e46 == 0u) {
                phi_93_ = (((_e19.x + _e19.y) & 1u) == 1u);
            } else {
                phi_93_ = false;
            }
            let _e52 = phi_93_;
            let _e53 = (2u * _e19.x);
            let _e54 = (2u * _e19.y);
            let _e60 = params.member.member.member[0u];
            let _e65 = select(select(u32(_e60), 0u, (_e60 < 0f)), 4294967295u, (_e60 > 4294967000f));
            let _e70 = depth.member[((_e54 * _e65) + _e53)];
            phi_114_ = 1u;
            phi_117_ = _e70;
            phi_119_ = vec2<u32>(_e53, _e54);
            loop {
                let _e72 = phi_114_;
                let _e74 = phi_117_;
                let _e76 = phi_119_;
                local = _e76;
                local_1 = _e76;
                let _e77 = (_e72 < 4u);
                if _e77 {
                    let _e81 = (_e53 + (_e72 & 1u));
                    let _e82 = (_e54 + (_e72 >> bitcast<u32>(1i)));
                    let _e87 = depth.member[((_e82 * _e65) + _e81)];
                    if _e52 {
                        phi_157_ = select(true, false, (_e87 > _e74));
                    } else {
                        phi_157_ = true;
                    }
                    let _e91 = phi_157_;
                    if _e91 {
                        if _e52 {
                            phi_168_ = false;
                        } else {
                            phi_168_ = (_e87 < _e74);
                        }
                        let _e94 = phi_168_;
                        phi_169_ = _e94;
                    } else {
                        phi_169_ = true;
                    }
                    let _e96 = phi_169_;
                    if _e96 {
                        phi_175_ = vec2<u32>(_e81, _e82);
                    } else {
                        phi_175_ = _e76;
                    }
                    let _e99 = phi_175_;
                    phi_115_ = (_e72 + 1u);
                    phi_118_ = select(_e74, _e87, _e96);
                    phi_120_ = _e99;
                } else {
                    phi_115_ = u32();
                    phi_118_ = f32();
                    phi_120_ = vec2<u32>();
                }
                let _e103 = phi_115_;
                let _e105 = phi_118_;
                let _e107 = phi_120_;
                continue;
                continuing {
                    phi_114_ = _e103;
                    phi_117_ = _e105;
                    phi_119_ = _e107;
                    break if !(_e77);
                }
            }
            let _e110 = local;
            let _e113 = local_1;
            let _e116 = ((_e113.y * _e65) + _e110.x);
            let _e118 = ((_e19.y * _e31) + _e19.x);
            let _e121 = depth.member[_e116];
            half_depth.member[_e118] = _e121;
            let _e126 = normals.member[_e116];
            half_normals.member[_e118] = _e126;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn half_downsample(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
