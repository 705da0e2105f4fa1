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

struct type_15 {
    member: type_5,
    member_1: vec2<u32>,
    member_2: f32,
    member_3: u32,
}

struct type_16 {
    member: type_15,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(3) 
var<uniform> params: type_16;
@group(0) @binding(0) 
var<storage> ao_in: type_7;
@group(0) @binding(1) 
var<storage> depth: type_7;
@group(0) @binding(2) 
var<storage, read_write> ao_out: type_7;

fn function_() {
    var phi_110_: bool;
    var phi_112_: bool;
    var phi_113_: bool;
    var phi_114_: bool;
    var phi_115_: bool;
    var phi_288_: bool;
    var phi_629_: bool;
    var phi_456_: i32;
    var phi_459_: f32;
    var phi_461_: f32;
    var phi_471_: i32;
    var phi_474_: f32;
    var phi_476_: f32;
    var phi_587_: f32;
    var phi_588_: f32;
    var phi_472_: i32;
    var phi_475_: f32;
    var phi_477_: f32;
    var phi_621_: bool;
    var phi_653_: bool;
    var phi_457_: i32;
    var phi_460_: f32;
    var phi_462_: f32;
    var phi_652_: bool;
    var local: f32;
    var local_1: f32;
    var phi_592_: f32;
    var local_2: f32;
    var local_3: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e26 = id_1;
            let _e28 = arrayLength((&ao_in.member));
            let _e30 = arrayLength((&depth.member));
            let _e38 = params.member.member.member_4;
            let _e39 = (_e26.x + _e38);
            let _e40 = (_e26.y + _e38);
            let _e45 = params.member.member.member[0u];
            let _e50 = select(select(u32(_e45), 0u, (_e45 < 0f)), 4294967295u, (_e45 > 4294967000f));
            let _e55 = params.member.member.member[1u];
            let _e60 = select(select(u32(_e55), 0u, (_e55 < 0f)), 4294967295u, (_e55 > 4294967000f));
            if (_e39 >= _e38) {
                if (_e40 >= _e38) {
                    let _e64 = ((_e39 + _e38) < _e50);
                    if _e64 {
                        phi_110_ = ((_e40 + _e38) < _e60);
                    } else {
                        phi_110_ = bool();
                    }
                    let _e68 = phi_110_;
                    phi_112_ = _e68;
                    phi_113_ = select(true, false, _e64);
                } else {
                    phi_112_ = bool();
                    phi_113_ = true;
                }
                let _e71 = phi_112_;
                let _e73 = phi_113_;
                phi_114_ = _e71;
                phi_115_ = _e73;
            } else {
                phi_114_ = bool();
                phi_115_ = true;
            }
            let _e75 = phi_114_;
            let _e77 = phi_115_;
            if select(_e75, false, _e77) {
                let _e82 = params.member.member_1[0u];
                let _e86 = params.member.member_1[1u];
                let _e87 = bitcast<i32>(_e82);
                let _e88 = bitcast<i32>(_e86);
                let _e89 = bitcast<i32>(_e39);
                let _e90 = bitcast<i32>(_e40);
                let _e91 = bitcast<i32>(_e38);
                let _e95 = select(_e91, _e89, (_e91 < _e89));
                let _e97 = ((bitcast<i32>(_e50) - _e91) - 1i);
                let _e102 = select(_e91, _e90, (_e91 < _e90));
                let _e104 = ((bitcast<i32>(_e60) - _e91) - 1i);
                let _e109 = ((bitcast<u32>(select(_e102, _e104, (_e104 < _e102))) * _e50) + bitcast<u32>(select(_e95, _e97, (_e97 < _e95))));
                if (_e109 < _e28) {
                } else {
                    break;
                }
                let _e113 = ao_in.member[_e109];
                if (_e109 < _e30) {
                } else {
                    break;
                }
                let _e117 = depth.member[_e109];
                let _e121 = params.member.member.member_3;
                if (_e117 > 0f) {
                    phi_288_ = (_e117 < _e121);
                } else {
                    phi_288_ = false;
                }
                let _e125 = phi_288_;
                if _e125 {
                    let _e128 = (_e89 + (_e87 * -1i));
                    let _e129 = (_e90 + (_e88 * -1i));
                    let _e131 = select(_e91, _e128, (_e91 < _e128));
                    let _e136 = select(_e91, _e129, (_e91 < _e129));
                    let _e141 = ((bitcast<u32>(select(_e136, _e104, (_e104 < _e136))) * _e50) + bitcast<u32>(select(_e131, _e97, (_e97 < _e131))));
                    if (_e141 < _e30) {
                    } else {
                        break;
                    }
                    let _e145 = depth.member[_e141];
                    let _e146 = (_e117 - _e145);
                    let _e147 = (_e89 + _e87);
                    let _e148 = (_e90 + _e88);
                    let _e150 = select(_e91, _e147, (_e91 < _e147));
                    let _e155 = select(_e91, _e148, (_e91 < _e148));
                    let _e160 = ((bitcast<u32>(select(_e155, _e104, (_e104 < _e155))) * _e50) + bitcast<u32>(select(_e150, _e97, (_e97 < _e150))));
                    if (_e160 < _e30) {
                    } else {
                        break;
                    }
                    let _e164 = depth.member[_e160];
                    let _e165 = (_e164 - _e117);
                    let _e172 = params.member.member_2;
                    phi_629_ = false;
                    phi_456_ = 1i;
                    phi_459_ = 1f;
                    phi_461_ = _e113;
                    loop {
                        let _e176 = phi_629_;
                        let _e178 = phi_456_;
                        let _e180 = phi_459_;
                        let _e182 = phi_461_;
                        local = _e182;
                        local_1 = _e180;
                        let _e183 = (_e178 <= 4i);
                        if _e183 {
                            let _e184 = f32(_e178);
                            phi_471_ = -1i;
                            phi_474_ = _e180;
                            phi_476_ = _e182;
                            loop {
                                let _e186 = phi_471_;
                                let _e188 = phi_474_;
                                let _e190 = phi_476_;
                                local_2 = _e188;
                                local_3 = _e190;
                                let _e191 = (_e186 <= 1i);
                                if _e191 {
                                    let _e192 = (_e186 * _e178);
                                    let _e195 = (_e89 + (_e87 * _e192));
                                    let _e196 = (_e90 + (_e88 * _e192));
                                    let _e198 = select(_e91, _e195, (_e91 < _e195));
                                    let _e203 = select(_e91, _e196, (_e91 < _e196));
                                    let _e208 = ((bitcast<u32>(select(_e203, _e104, (_e104 < _e203))) * _e50) + bitcast<u32>(select(_e198, _e97, (_e97 < _e198))));
                                    if (_e208 < _e30) {
                                    } else {
                                        phi_621_ = true;
                                        break;
                                    }
                                    let _e212 = depth.member[_e208];
                                    let _e219 = (abs(((_e212 - ((f32(_e186) * select(_e165, _e146, (abs(_e146) < abs(_e165)))) * _e184)) - _e117)) * ((_e172 * 12f) / _e117));
                                    let _e225 = exp2((((-(_e184) * _e184) * 0.08f) - (_e219 * _e219)));
                                    if (_e225 > 0f) {
                                        if (_e208 < _e28) {
                                        } else {
                                            phi_621_ = true;
                                            break;
                                        }
                                        let _e230 = ao_in.member[_e208];
                                        phi_587_ = (_e188 + _e225);
                                        phi_588_ = (_e190 + (_e225 * _e230));
                                    } else {
                                        phi_587_ = _e188;
                                        phi_588_ = _e190;
                                    }
                                    let _e235 = phi_587_;
                                    let _e237 = phi_588_;
                                    phi_472_ = (_e186 + 2i);
                                    phi_475_ = _e235;
                                    phi_477_ = _e237;
                                } else {
                                    phi_472_ = i32();
                                    phi_475_ = f32();
                                    phi_477_ = f32();
                                }
                                let _e240 = phi_472_;
                                let _e242 = phi_475_;
                                let _e244 = phi_477_;
                                continue;
                                continuing {
                                    phi_471_ = _e240;
                                    phi_474_ = _e242;
                                    phi_476_ = _e244;
                                    phi_621_ = _e176;
                                    break if !(_e191);
                                }
                            }
                            let _e247 = phi_621_;
                            phi_652_ = _e247;
                            if _e247 {
                                break;
                            }
                            phi_653_ = _e247;
                            phi_457_ = (_e178 + 1i);
                            let _e295 = local_2;
                            phi_460_ = _e295;
                            let _e298 = local_3;
                            phi_462_ = _e298;
                        } else {
                            phi_653_ = _e176;
                            phi_457_ = i32();
                            phi_460_ = f32();
                            phi_462_ = f32();
                        }
                        let _e250 = phi_653_;
                        let _e252 = phi_457_;
                        let _e254 = phi_460_;
                        let _e256 = phi_462_;
                        continue;
                        continuing {
                            phi_629_ = _e250;
                            phi_456_ = _e252;
                            phi_459_ = _e254;
                            phi_461_ = _e256;
                            phi_652_ = _e250;
                            break if !(_e183);
                        }
                    }
                    let _e259 = phi_652_;
                    if _e259 {
                        break;
                    }
                    let _e261 = local;
                    let _e263 = local_1;
                    phi_592_ = (_e261 / _e263);
                } else {
                    phi_592_ = _e113;
                }
                let _e266 = phi_592_;
                let _e268 = ((_e40 * _e50) + _e39);
                if (_e268 < arrayLength((&ao_out.member))) {
                } else {
                    break;
                }
                ao_out.member[_e268] = _e266;
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
