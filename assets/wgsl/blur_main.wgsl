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

struct type_16 {
    member: type_5,
    member_1: vec2<u32>,
    member_2: f32,
    member_3: u32,
}

struct type_17 {
    member: type_16,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(3) 
var<uniform> params: type_17;
@group(0) @binding(0) 
var<storage> ao_in: type_7;
@group(0) @binding(1) 
var<storage> depth: type_7;
@group(0) @binding(2) 
var<storage, read_write> ao_out: type_7;

fn function_() {
    var phi_134_: bool;
    var phi_136_: bool;
    var phi_137_: bool;
    var phi_138_: bool;
    var phi_139_: bool;
    var phi_1450_: bool;
    var phi_282_: i32;
    var phi_285_: f32;
    var phi_287_: f32;
    var phi_297_: i32;
    var phi_300_: f32;
    var phi_302_: f32;
    var phi_298_: i32;
    var phi_301_: f32;
    var phi_303_: f32;
    var phi_1437_: bool;
    var phi_1473_: bool;
    var phi_283_: i32;
    var phi_286_: f32;
    var phi_288_: f32;
    var phi_1472_: bool;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e25 = id_1;
            let _e27 = arrayLength((&ao_in.member));
            let _e29 = arrayLength((&depth.member));
            let _e35 = params.member.member.member_4;
            let _e36 = (_e25.x + _e35);
            let _e37 = (_e25.y + _e35);
            let _e44 = params.member.member.member[0u];
            let _e49 = select(select(u32(_e44), 0u, (_e44 < 0f)), 4294967295u, (_e44 > 4294967000f));
            let _e54 = params.member.member.member[1u];
            if (_e36 >= _e35) {
                if (_e37 >= _e35) {
                    let _e63 = ((_e36 + _e35) < _e49);
                    if _e63 {
                        phi_134_ = ((_e37 + _e35) < select(select(u32(_e54), 0u, (_e54 < 0f)), 4294967295u, (_e54 > 4294967000f)));
                    } else {
                        phi_134_ = bool();
                    }
                    let _e67 = phi_134_;
                    phi_136_ = _e67;
                    phi_137_ = select(true, false, _e63);
                } else {
                    phi_136_ = bool();
                    phi_137_ = true;
                }
                let _e70 = phi_136_;
                let _e72 = phi_137_;
                phi_138_ = _e70;
                phi_139_ = _e72;
            } else {
                phi_138_ = bool();
                phi_139_ = true;
            }
            let _e74 = phi_138_;
            let _e76 = phi_139_;
            if select(_e74, false, _e76) {
                let _e80 = params.member.member;
                let _e84 = params.member.member_1[0u];
                let _e88 = params.member.member_1[1u];
                let _e89 = bitcast<i32>(_e84);
                let _e90 = bitcast<i32>(_e88);
                let _e94 = bitcast<i32>(_e36);
                let _e95 = bitcast<i32>(_e37);
                let _e96 = bitcast<i32>(_e80.member_4);
                let _e102 = select(select(u32(_e80.member.x), 0u, (_e80.member.x < 0f)), 4294967295u, (_e80.member.x > 4294967000f));
                let _e112 = select(_e96, _e94, (_e96 < _e94));
                let _e114 = ((bitcast<i32>(_e102) - _e96) - 1i);
                let _e119 = select(_e96, _e95, (_e96 < _e95));
                let _e121 = ((bitcast<i32>(select(select(u32(_e80.member.y), 0u, (_e80.member.y < 0f)), 4294967295u, (_e80.member.y > 4294967000f))) - _e96) - 1i);
                let _e126 = ((bitcast<u32>(select(_e119, _e121, (_e121 < _e119))) * _e102) + bitcast<u32>(select(_e112, _e114, (_e114 < _e112))));
                if (_e126 < _e27) {
                } else {
                    break;
                }
                let _e130 = ao_in.member[_e126];
                if (_e126 < _e29) {
                } else {
                    break;
                }
                let _e134 = depth.member[_e126];
                let _e137 = (_e94 + (_e89 * -1i));
                let _e138 = (_e95 + (_e90 * -1i));
                let _e140 = select(_e96, _e137, (_e96 < _e137));
                let _e145 = select(_e96, _e138, (_e96 < _e138));
                let _e150 = ((bitcast<u32>(select(_e145, _e121, (_e121 < _e145))) * _e102) + bitcast<u32>(select(_e140, _e114, (_e114 < _e140))));
                if (_e150 < _e29) {
                } else {
                    break;
                }
                let _e154 = depth.member[_e150];
                let _e155 = (_e134 - _e154);
                let _e156 = (_e94 + _e89);
                let _e157 = (_e95 + _e90);
                let _e159 = select(_e96, _e156, (_e96 < _e156));
                let _e164 = select(_e96, _e157, (_e96 < _e157));
                let _e169 = ((bitcast<u32>(select(_e164, _e121, (_e121 < _e164))) * _e102) + bitcast<u32>(select(_e159, _e114, (_e114 < _e159))));
                if (_e169 < _e29) {
                } else {
                    break;
                }
                let _e173 = depth.member[_e169];
                let _e174 = (_e173 - _e134);
                let _e181 = params.member.member_2;
                phi_1450_ = false;
                phi_282_ = 1i;
                phi_285_ = 1f;
                phi_287_ = _e130;
                loop {
                    let _e185 = phi_1450_;
                    let _e187 = phi_282_;
                    let _e189 = phi_285_;
                    let _e191 = phi_287_;
                    local = _e191;
                    local_1 = _e189;
                    let _e192 = (_e187 <= 4i);
                    if _e192 {
                        let _e193 = f32(_e187);
                        phi_297_ = -1i;
                        phi_300_ = _e189;
                        phi_302_ = _e191;
                        loop {
                            let _e195 = phi_297_;
                            let _e197 = phi_300_;
                            let _e199 = phi_302_;
                            local_2 = _e197;
                            local_3 = _e199;
                            let _e200 = (_e195 <= 1i);
                            if _e200 {
                                let _e201 = (_e195 * _e187);
                                let _e204 = (_e94 + (_e89 * _e201));
                                let _e205 = (_e95 + (_e90 * _e201));
                                let _e207 = select(_e96, _e204, (_e96 < _e204));
                                let _e212 = select(_e96, _e205, (_e96 < _e205));
                                let _e217 = ((bitcast<u32>(select(_e212, _e121, (_e121 < _e212))) * _e102) + bitcast<u32>(select(_e207, _e114, (_e114 < _e207))));
                                if (_e217 < _e29) {
                                } else {
                                    phi_1437_ = true;
                                    break;
                                }
                                let _e221 = depth.member[_e217];
                                let _e228 = (abs(((_e221 - ((select(_e174, _e155, (abs(_e155) < abs(_e174))) * f32(_e195)) * _e193)) - _e134)) * ((_e181 * 12f) / _e134));
                                let _e234 = exp2((((-(_e193) * _e193) * 0.08f) - (_e228 * _e228)));
                                let _e235 = (_e234 > 0f);
                                if (_e217 < _e27) {
                                } else {
                                    phi_1437_ = true;
                                    break;
                                }
                                let _e239 = ao_in.member[_e217];
                                phi_298_ = (_e195 + 2i);
                                phi_301_ = select(_e197, (_e197 + _e234), _e235);
                                phi_303_ = select(_e199, (_e199 + (_e234 * _e239)), _e235);
                            } else {
                                phi_298_ = i32();
                                phi_301_ = f32();
                                phi_303_ = f32();
                            }
                            let _e247 = phi_298_;
                            let _e249 = phi_301_;
                            let _e251 = phi_303_;
                            continue;
                            continuing {
                                phi_297_ = _e247;
                                phi_300_ = _e249;
                                phi_302_ = _e251;
                                phi_1437_ = _e185;
                                break if !(_e200);
                            }
                        }
                        let _e254 = phi_1437_;
                        phi_1472_ = _e254;
                        if _e254 {
                            break;
                        }
                        phi_1473_ = _e254;
                        phi_283_ = (_e187 + 1i);
                        let _e298 = local_2;
                        phi_286_ = _e298;
                        let _e301 = local_3;
                        phi_288_ = _e301;
                    } else {
                        phi_1473_ = _e185;
                        phi_283_ = i32();
                        phi_286_ = f32();
                        phi_288_ = f32();
                    }
                    let _e257 = phi_1473_;
                    let _e259 = phi_283_;
                    let _e261 = phi_286_;
                    let _e263 = phi_288_;
                    continue;
                    continuing {
                        phi_1450_ = _e257;
                        phi_282_ = _e259;
                        phi_285_ = _e261;
                        phi_287_ = _e263;
                        phi_1472_ = _e257;
                        break if !(_e192);
                    }
                }
                let _e266 = phi_1472_;
                if _e266 {
                    break;
                }
                let _e271 = local;
                let _e273 = local_1;
                ao_out.member[((_e37 * _e49) + _e36)] = select(_e130, (_e271 / _e273), select(false, (_e134 < _e80.member_3), (_e134 > 0f)));
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn blur_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
