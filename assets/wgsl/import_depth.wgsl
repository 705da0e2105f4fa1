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
@group(0) @binding(2) 
var<uniform> params: type_18;
@group(0) @binding(1) 
var<storage, read_write> depth: type_7;
@group(0) @binding(0) 
var engine_depth: texture_2d<f32>;

fn function_() {
    var phi_80_: bool;
    var phi_141_: f32;
    var phi_155_: f32;
    var phi_165_: f32;
    var phi_175_: f32;
    var phi_176_: f32;
    var phi_177_: f32;
    var phi_178_: f32;
    var phi_188_: bool;

    switch bitcast<i32>(0u) {
        default: {
            let _e18 = id_1;
            let _e27 = params.member.member.member[0u];
            let _e32 = select(select(u32(_e27), 0u, (_e27 < 0f)), 4294967295u, (_e27 > 4294967000f));
            let _e37 = params.member.member.member[1u];
            if (_e18.x < _e32) {
                phi_80_ = (_e18.y < select(select(u32(_e37), 0u, (_e37 < 0f)), 4294967295u, (_e37 > 4294967000f)));
            } else {
                phi_80_ = false;
            }
            let _e46 = phi_80_;
            if _e46 {
                let _e50 = params.member.member.member_4;
                let _e55 = (select(_e50, _e18.x, (_e18.x > _e50)) - _e50);
                let _e56 = (select(_e50, _e18.y, (_e18.y > _e50)) - _e50);
                let _e60 = params.member.member_1[0u];
                let _e64 = params.member.member_1[1u];
                let _e65 = (_e60 - 1u);
                let _e66 = (_e64 - 1u);
                let _e74 = textureLoad(engine_depth, vec2<i32>(bitcast<i32>(select(_e65, _e55, (_e55 < _e65))), bitcast<i32>(select(_e66, _e56, (_e56 < _e66)))), 0u);
                let _e78 = params.member.member_2;
                let _e81 = params.member.member_3;
                let _e84 = params.member.member_4;
                if (_e78 == 0u) {
                    if (_e74.x < 1f) {
                        phi_141_ = ((_e81 * _e84) / (_e84 - (_e74.x * (_e84 - _e81))));
                    } else {
                        phi_141_ = -1f;
                    }
                    let _e93 = phi_141_;
                    phi_178_ = _e93;
                } else {
                    if (_e78 == 1u) {
                        if (_e74.x > 0f) {
                            phi_155_ = ((_e81 * _e84) / (_e81 + (_e74.x * (_e84 - _e81))));
                        } else {
                            phi_155_ = -1f;
                        }
                        let _e102 = phi_155_;
                        phi_177_ = _e102;
                    } else {
                        if (_e78 == 2u) {
                            if (_e74.x > 0f) {
                                phi_165_ = (_e81 / _e74.x);
                            } else {
                                phi_165_ = -1f;
                            }
                            let _e107 = phi_165_;
                            phi_176_ = _e107;
                        } else {
                            if (_e78 == 3u) {
                                phi_175_ = select(-1f, _e74.x, (_e74.x < _e84));
                            } else {
                                phi_175_ = -1f;
                            }
                            let _e112 = phi_175_;
                            phi_176_ = _e112;
                        }
                        let _e114 = phi_176_;
                        phi_177_ = _e114;
                    }
                    let _e116 = phi_177_;
                    phi_178_ = _e116;
                }
                let _e118 = phi_178_;
                if (_e118 > 0f) {
                    phi_188_ = select(true, false, (_e118 < 0x1.fffffep+127f));
                } else {
                    phi_188_ = true;
                }
                let _e123 = phi_188_;
                let _e124 = select(_e118, 0x1.fffffep+127f, _e123);
                let _e128 = params.member.member.member_3;
                let _e132 = ((_e18.y * _e32) + _e18.x);
                if (_e132 < arrayLength((&depth.member))) {
                } else {
                    break;
                }
                depth.member[_e132] = select(_e128, _e124, (_e124 < _e128));
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn import_depth(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
