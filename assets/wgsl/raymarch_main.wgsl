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

struct type_20 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
    member_5: u32,
    member_6: u32,
    member_7: u32,
    member_8: u32,
}

struct type_21 {
    member: type_20,
}

struct type_24 {
    member: array<vec2<f32>>,
}

struct type_26 {
    member: vec2<u32>,
    member_1: vec3<f32>,
    member_2: vec3<f32>,
    member_3: f32,
    member_4: f32,
    member_5: f32,
}

struct type_27 {
    member: u32,
    member_1: type_26,
}

struct type_28 {
    member: u32,
    member_1: type_27,
}

struct type_29 {
    member: f32,
    member_1: u32,
    member_2: u32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(0) 
var<storage> depth: type_7;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;
@group(0) @binding(6) 
var<uniform> params: type_21;
@group(0) @binding(2) 
var<storage> kernel: type_24;
@group(0) @binding(4) 
var<storage, read_write> terms: type_10;
@group(0) @binding(5) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_1648_: bool;
    var phi_1663_: bool;
    var phi_1678_: bool;
    var phi_1693_: bool;
    var phi_1724_: f32;
    var phi_1728_: f32;
    var phi_1729_: bool;
    var phi_1751_: u32;
    var phi_1778_: f32;
    var phi_1782_: f32;
    var phi_1783_: bool;
    var phi_1805_: u32;
    var phi_1832_: f32;
    var phi_1836_: f32;
    var phi_1837_: bool;
    var phi_1859_: u32;
    var phi_1886_: f32;
    var phi_1890_: f32;
    var phi_1891_: bool;
    var phi_1913_: u32;
    var phi_1924_: bool;
    var phi_1939_: bool;
    var phi_783_: vec2<f32>;
    var phi_814_: vec3<f32>;
    var phi_820_: u32;
    var phi_823_: u32;
    var phi_825_: u32;
    var phi_827_: u32;
    var phi_856_: u32;
    var phi_857_: u32;
    var phi_858_: u32;
    var phi_859_: u32;
    var phi_821_: u32;
    var phi_824_: u32;
    var phi_826_: u32;
    var phi_828_: u32;
    var local: u32;
    var phi_890_: type_28;
    var phi_2114_: bool;
    var phi_925_: u32;
    var phi_928_: f32;
    var phi_1954_: bool;
    var phi_1074_: u32;
    var phi_1077_: f32;
    var phi_1079_: bool;
    var phi_1081_: bool;
    var phi_1083_: f32;
    var phi_1085_: f32;
    var phi_1189_: u32;
    var phi_1210_: u32;
    var phi_1299_: u32;
    var phi_1330_: u32;
    var phi_2037_: bool;
    var phi_2052_: bool;
    var phi_2013_: vec2<f32>;
    var phi_1470_: u32;
    var phi_1472_: u32;
    var phi_1473_: f32;
    var phi_1474_: bool;
    var phi_1475_: bool;
    var phi_1476_: f32;
    var phi_1479_: bool;
    var phi_1480_: bool;
    var phi_1075_: u32;
    var phi_1078_: f32;
    var phi_1080_: bool;
    var phi_1082_: bool;
    var phi_1084_: f32;
    var phi_1086_: f32;
    var phi_1484_: bool;
    var phi_1486_: bool;
    var phi_1487_: bool;
    var phi_2066_: bool;
    var phi_1636_: bool;
    var phi_1635_: bool;
    var phi_1634_: bool;
    var phi_1633_: bool;
    var phi_1631_: f32;
    var local_1: f32;
    var local_2: bool;
    var local_3: f32;
    var local_4: bool;
    var phi_1527_: f32;
    var phi_2204_: bool;
    var phi_926_: u32;
    var phi_929_: f32;
    var phi_2203_: bool;
    var local_5: f32;
    var phi_1598_: type_29;

    switch bitcast<i32>(0u) {
        default: {
            let _e59 = id_1;
            let _e63 = arrayLength((&kernel.member));
            let _e74 = params.member.member.member[0u];
            let _e79 = select(select(u32(_e74), 0u, (_e74 < 0f)), 4294967295u, (_e74 > 4294967000f));
            let _e84 = params.member.member.member[1u];
            let _e89 = select(select(u32(_e84), 0u, (_e84 < 0f)), 4294967295u, (_e84 > 4294967000f));
            if (_e59.x >= _e79) {
            } else {
                if (_e59.y >= _e89) {
                } else {
                    let _e95 = ((_e59.y * _e79) + _e59.x);
                    let _e98 = depth.member[_e95];
                    let _e102 = params.member.member.member_3;
                    let _e105 = select(false, (_e98 < _e102), (_e98 > 0f));
                    let _e106 = select(_e102, _e98, _e105);
                    let _e107 = bitcast<i32>(_e59.x);
                    let _e108 = (_e107 + -1i);
                    let _e110 = select(0i, _e108, (0i < _e108));
                    let _e112 = (bitcast<i32>(_e79) - 1i);
                    let _e116 = bitcast<i32>(_e59.y);
                    let _e118 = select(0i, _e116, (0i < _e116));
                    let _e120 = (bitcast<i32>(_e89) - 1i);
                    let _e124 = (bitcast<u32>(select(_e118, _e120, (_e120 < _e118))) * _e79);
                    let _e128 = depth.member[(_e124 + bitcast<u32>(select(_e110, _e112, (_e112 < _e110))))];
                    let _e133 = (_e107 + 1i);
                    let _e135 = select(0i, _e133, (0i < _e133));
                    let _e142 = depth.member[(_e124 + bitcast<u32>(select(_e135, _e112, (_e112 < _e135))))];
                    let _e148 = select(0i, _e107, (0i < _e107));
                    let _e151 = bitcast<u32>(select(_e148, _e112, (_e112 < _e148)));
                    let _e152 = (_e116 + -1i);
                    let _e154 = select(0i, _e152, (0i < _e152));
                    let _e162 = depth.member[((bitcast<u32>(select(_e154, _e120, (_e120 < _e154))) * _e79) + _e151)];
                    let _e167 = (_e116 + 1i);
                    let _e169 = select(0i, _e167, (0i < _e167));
                    let _e177 = depth.member[((bitcast<u32>(select(_e169, _e120, (_e120 < _e169))) * _e79) + _e151)];
                    let _e182 = (select(_e102, _e128, select(false, (_e128 < _e102), (_e128 > 0f))) - _e106);
                    let _e183 = (select(_e102, _e142, select(false, (_e142 < _e102), (_e142 > 0f))) - _e106);
                    let _e184 = (select(_e102, _e162, select(false, (_e162 < _e102), (_e162 > 0f))) - _e106);
                    let _e185 = (select(_e102, _e177, select(false, (_e177 < _e102), (_e177 > 0f))) - _e106);
                    let _e187 = ((_e183 - _e182) * 0.5f);
                    let _e189 = ((_e185 - _e184) * 0.5f);
                    let _e190 = (_e106 * 0.011f);
                    let _e192 = abs(_e182);
                    let _e193 = abs((_e182 + _e187));
                    if (_e192 != _e192) {
                        phi_1648_ = true;
                    } else {
                        phi_1648_ = (_e193 <= _e192);
                    }
                    let _e197 = phi_1648_;
                    let _e200 = (1.25f - (select(_e192, _e193, _e197) / _e190));
                    let _e204 = select(0f, select(1f, _e200, (_e200 < 1f)), (_e200 > 0f));
                    let _e206 = abs(_e183);
                    let _e207 = abs((_e183 - _e187));
                    if (_e206 != _e206) {
                        phi_1663_ = true;
                    } else {
                        phi_1663_ = (_e207 <= _e206);
                    }
                    let _e211 = phi_1663_;
                    let _e214 = (1.25f - (select(_e206, _e207, _e211) / _e190));
                    let _e218 = select(0f, select(1f, _e214, (_e214 < 1f)), (_e214 > 0f));
                    let _e220 = abs(_e184);
                    let _e221 = abs((_e184 + _e189));
                    if (_e220 != _e220) {
                        phi_1678_ = true;
                    } else {
                        phi_1678_ = (_e221 <= _e220);
                    }
                    let _e225 = phi_1678_;
                    let _e228 = (1.25f - (select(_e220, _e221, _e225) / _e190));
                    let _e232 = select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f));
                    let _e234 = abs(_e185);
                    let _e235 = abs((_e185 - _e189));
                    if (_e234 != _e234) {
                        phi_1693_ = true;
                    } else {
                        phi_1693_ = (_e235 <= _e234);
                    }
                    let _e239 = phi_1693_;
                    let _e242 = (1.25f - (select(_e234, _e235, _e239) / _e190));
                    let _e246 = select(0f, select(1f, _e242, (_e242 < 1f)), (_e242 > 0f));
                    let _e251 = (select(0f, select(1f, _e204, (_e204 < 1f)), (_e204 > 0f)) * 2.9f);
                    let _e253 = floor((_e251 + 0.5f));
                    if ((_e253 - _e251) == 0.5f) {
                        let _e259 = ((floor((_e253 * 0.5f)) * 2f) != _e253);
                        if _e259 {
                            phi_1724_ = (_e253 - 1f);
                        } else {
                            phi_1724_ = f32();
                        }
                        let _e262 = phi_1724_;
                        phi_1728_ = _e262;
                        phi_1729_ = select(true, false, _e259);
                    } else {
                        phi_1728_ = f32();
                        phi_1729_ = true;
                    }
                    let _e265 = phi_1728_;
                    let _e267 = phi_1729_;
                    let _e268 = select(_e265, _e253, _e267);
                    if (_e268 > 0f) {
                        let _e274 = select(select(u32(_e268), 0u, (_e268 < 0f)), 4294967295u, (_e268 > 4294967000f));
                        phi_1751_ = select(_e274, 3u, (3u < _e274));
                    } else {
                        phi_1751_ = 0u;
                    }
                    let _e278 = phi_1751_;
                    let _e284 = (select(0f, select(1f, _e218, (_e218 < 1f)), (_e218 > 0f)) * 2.9f);
                    let _e286 = floor((_e284 + 0.5f));
                    if ((_e286 - _e284) == 0.5f) {
                        let _e292 = ((floor((_e286 * 0.5f)) * 2f) != _e286);
                        if _e292 {
                            phi_1778_ = (_e286 - 1f);
                        } else {
                            phi_1778_ = f32();
                        }
                        let _e295 = phi_1778_;
                        phi_1782_ = _e295;
                        phi_1783_ = select(true, false, _e292);
                    } else {
                        phi_1782_ = f32();
                        phi_1783_ = true;
                    }
                    let _e298 = phi_1782_;
                    let _e300 = phi_1783_;
                    let _e301 = select(_e298, _e286, _e300);
                    if (_e301 > 0f) {
                        let _e307 = select(select(u32(_e301), 0u, (_e301 < 0f)), 4294967295u, (_e301 > 4294967000f));
                        phi_1805_ = select(_e307, 3u, (3u < _e307));
                    } else {
                        phi_1805_ = 0u;
                    }
                    let _e311 = phi_1805_;
                    let _e318 = (select(0f, select(1f, _e232, (_e232 < 1f)), (_e232 > 0f)) * 2.9f);
                    let _e320 = floor((_e318 + 0.5f));
                    if ((_e320 - _e318) == 0.5f) {
                        let _e326 = ((floor((_e320 * 0.5f)) * 2f) != _e320);
                        if _e326 {
                            phi_1832_ = (_e320 - 1f);
                        } else {
                            phi_1832_ = f32();
                        }
                        let _e329 = phi_1832_;
                        phi_1836_ = _e329;
                        phi_1837_ = select(true, false, _e326);
                    } else {
                        phi_1836_ = f32();
                        phi_1837_ = true;
                    }
                    let _e332 = phi_1836_;
                    let _e334 = phi_1837_;
                    let _e335 = select(_e332, _e320, _e334);
                    if (_e335 > 0f) {
                        let _e341 = select(select(u32(_e335), 0u, (_e335 < 0f)), 4294967295u, (_e335 > 4294967000f));
                        phi_1859_ = select(_e341, 3u, (3u < _e341));
                    } else {
                        phi_1859_ = 0u;
                    }
                    let _e345 = phi_1859_;
                    let _e352 = (select(0f, select(1f, _e246, (_e246 < 1f)), (_e246 > 0f)) * 2.9f);
                    let _e354 = floor((_e352 + 0.5f));
                    if ((_e354 - _e352) == 0.5f) {
                        let _e360 = ((floor((_e354 * 0.5f)) * 2f) != _e354);
                        if _e360 {
                            phi_1886_ = (_e354 - 1f);
                        } else {
                            phi_1886_ = f32();
                        }
                        let _e363 = phi_1886_;
                        phi_1890_ = _e363;
                        phi_1891_ = select(true, false, _e360);
                    } else {
                        phi_1890_ = f32();
                        phi_1891_ = true;
                    }
                    let _e366 = phi_1890_;
                    let _e368 = phi_1891_;
                    let _e369 = select(_e366, _e354, _e368);
                    if (_e369 > 0f) {
                        let _e375 = select(select(u32(_e369), 0u, (_e369 < 0f)), 4294967295u, (_e369 > 4294967000f));
                        phi_1913_ = select(_e375, 3u, (3u < _e375));
                    } else {
                        phi_1913_ = 0u;
                    }
                    let _e379 = phi_1913_;
                    let _e380 = ((((64u * _e278) + (16u * _e311)) + (4u * _e345)) + _e379);
                    if _e105 {
                        let _e393 = params.member.member.member_1[0u];
                        let _e395 = ((((((f32(_e59.x) + 0.5f) / _e74) * 2f) - 1f) * _e393) * _e98);
                        let _e402 = params.member.member.member_1[1u];
                        let _e404 = ((((((f32(_e59.y) + 0.5f) / _e84) * -2f) + 1f) * _e402) * _e98);
                        let _e408 = normals.member[_e95];
                        let _e416 = (f32((bitcast<i32>(((_e408 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e416 != _e416) {
                            phi_1924_ = true;
                        } else {
                            phi_1924_ = (-1f >= _e416);
                        }
                        let _e420 = phi_1924_;
                        let _e421 = select(_e416, -1f, _e420);
                        let _e431 = (f32((bitcast<i32>((((_e408 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                        if (_e431 != _e431) {
                            phi_1939_ = true;
                        } else {
                            phi_1939_ = (-1f >= _e431);
                        }
                        let _e435 = phi_1939_;
                        let _e436 = select(_e431, -1f, _e435);
                        let _e439 = (1f - abs(_e421));
                        let _e440 = abs(_e436);
                        let _e441 = (_e439 - _e440);
                        if (_e441 < 0f) {
                            phi_783_ = vec2<f32>(((1f - _e440) * select(1f, -1f, (_e421 < 0f))), (_e439 * select(1f, -1f, (_e436 < 0f))));
                        } else {
                            phi_783_ = vec2<f32>(_e421, _e436);
                        }
                        let _e452 = phi_783_;
                        let _e461 = (1f / sqrt((((_e452.x * _e452.x) + (_e452.y * _e452.y)) + (_e441 * _e441))));
                        let _e462 = (_e452.x * _e461);
                        let _e463 = (_e452.y * _e461);
                        let _e464 = (_e441 * _e461);
                        let _e465 = -(_e464);
                        if ((((_e462 * -(_e395)) + (_e463 * -(_e404))) + (_e465 * -(_e98))) < 0f) {
                            phi_814_ = vec3<f32>(-(_e462), -(_e463), _e464);
                        } else {
                            phi_814_ = vec3<f32>(_e462, _e463, _e465);
                        }
                        let _e480 = phi_814_;
                        let _e483 = params.member.member_8;
                        phi_820_ = (_e59.y & 63u);
                        phi_823_ = (_e59.x & 63u);
                        phi_825_ = 32u;
                        phi_827_ = 0u;
                        loop {
                            let _e487 = phi_820_;
                            let _e489 = phi_823_;
                            let _e491 = phi_825_;
                            let _e493 = phi_827_;
                            local = _e493;
                            let _e494 = (_e491 > 0u);
                            if _e494 {
                                let _e497 = select(0u, 1u, ((_e489 & _e491) != 0u));
                                let _e500 = select(0u, 1u, ((_e487 & _e491) != 0u));
                                if (_e500 == 0u) {
                                    if (_e497 == 1u) {
                                        phi_856_ = (63u - _e487);
                                        phi_857_ = (63u - _e489);
                                    } else {
                                        phi_856_ = _e487;
                                        phi_857_ = _e489;
                                    }
                                    let _e511 = phi_856_;
                                    let _e513 = phi_857_;
                                    phi_858_ = _e513;
                                    phi_859_ = _e511;
                                } else {
                                    phi_858_ = _e487;
                                    phi_859_ = _e489;
                                }
                                let _e515 = phi_858_;
                                let _e517 = phi_859_;
                                phi_821_ = _e515;
                                phi_824_ = _e517;
                                phi_826_ = (_e491 / 2u);
                                phi_828_ = (_e493 + ((_e491 * _e491) * ((3u * _e497) ^ _e500)));
                            } else {
                                phi_821_ = u32();
                                phi_824_ = u32();
                                phi_826_ = u32();
                                phi_828_ = u32();
                            }
                            let _e520 = phi_821_;
                            let _e522 = phi_824_;
                            let _e524 = phi_826_;
                            let _e526 = phi_828_;
                            continue;
                            continuing {
                                phi_820_ = _e520;
                                phi_823_ = _e522;
                                phi_825_ = _e524;
                                phi_827_ = _e526;
                                break if !(_e494);
                            }
                        }
                        let _e531 = local;
                        let _e533 = f32((_e531 + (288u * (_e483 % 64u))));
                        let _e535 = (0.5f + (_e533 * 0.7548777f));
                        let _e539 = (0.5f + (_e533 * 0.5698403f));
                        let _e542 = (6.2831855f * (_e535 - floor(_e535)));
                        phi_890_ = type_28(_e380, type_27(1u, type_26(vec2<u32>(_e59.x, _e59.y), vec3<f32>(_e395, _e404, _e98), _e480, sin(_e542), cos(_e542), (_e539 - floor(_e539)))));
                    } else {
                        phi_890_ = type_28(_e380, type_27(0u, type_27().member_1));
                    }
                    let _e554 = phi_890_;
                    if (bitcast<i32>(_e554.member_1.member) != 0i) {
                        let _e563 = params.member.member_5;
                        let _e565 = select(_e563, 64u, (64u < _e563));
                        let _e567 = select(_e565, _e63, (_e63 < _e565));
                        let _e569 = select(1u, _e567, (1u < _e567));
                        let _e572 = params.member.member_6;
                        let _e574 = select(1u, _e572, (1u < _e572));
                        phi_2114_ = false;
                        phi_925_ = 0u;
                        phi_928_ = 0f;
                        loop {
                            let _e576 = phi_2114_;
                            let _e578 = phi_925_;
                            let _e580 = phi_928_;
                            local_5 = _e580;
                            let _e581 = (_e578 < _e569);
                            if _e581 {
                                if (_e578 < _e63) {
                                } else {
                                    phi_2203_ = true;
                                    break;
                                }
                                let _e586 = kernel.member[_e578][0u];
                                let _e590 = kernel.member[_e578][1u];
                                let _e595 = ((_e554.member_1.member_1.member_4 * _e586) - (_e554.member_1.member_1.member_3 * _e590));
                                let _e598 = ((_e554.member_1.member_1.member_3 * _e586) + (_e554.member_1.member_1.member_4 * _e590));
                                let _e603 = ((1f - (_e595 * _e595)) - (_e598 * _e598));
                                if (_e603 != _e603) {
                                    phi_1954_ = true;
                                } else {
                                    phi_1954_ = (0f >= _e603);
                                }
                                let _e607 = phi_1954_;
                                let _e609 = sqrt(select(_e603, 0f, _e607));
                                let _e610 = -(_e609);
                                let _e614 = (-1f * _e554.member_1.member_1.member_2.z);
                                let _e615 = (-1f * _e554.member_1.member_1.member_2.x);
                                let _e617 = (1f / (_e614 + 1f));
                                let _e618 = (_e617 * _e554.member_1.member_1.member_2.y);
                                let _e622 = (_e618 * _e615);
                                let _e642 = (_e614 > 0.9997f);
                                let _e643 = (_e614 < -0.9997f);
                                let _e653 = params.member.member_1;
                                let _e657 = params.member.member_3;
                                let _e660 = params.member.member_4;
                                phi_1074_ = 1u;
                                phi_1077_ = _e653;
                                phi_1079_ = false;
                                phi_1081_ = true;
                                phi_1083_ = 0f;
                                phi_1085_ = 0f;
                                loop {
                                    let _e666 = phi_1074_;
                                    let _e668 = phi_1077_;
                                    let _e670 = phi_1079_;
                                    let _e672 = phi_1081_;
                                    let _e674 = phi_1083_;
                                    let _e676 = phi_1085_;
                                    local_1 = _e668;
                                    local_2 = _e670;
                                    local_3 = _e668;
                                    local_4 = _e670;
                                    let _e677 = (_e666 <= _e574);
                                    if _e677 {
                                        let _e683 = (((-(_e554.member_1.member_1.member_5) + f32(_e666)) * _e653) / f32(_e574));
                                        let _e688 = (_e554.member_1.member_1.member_1.x + (select(select(((((_e614 + (_e618 * _e554.member_1.member_1.member_2.y)) * _e595) + (_e622 * _e598)) + (_e615 * _e610)), _e595, _e643), _e595, _e642) * _e683));
                                        let _e690 = (_e554.member_1.member_1.member_1.y + (select(select((((_e622 * _e595) + ((_e614 + ((_e617 * _e615) * _e615)) * _e598)) + (-(_e554.member_1.member_1.member_2.y) * _e610)), -(_e598), _e643), _e598, _e642) * _e683));
                                        let _e692 = (_e554.member_1.member_1.member_1.z + (select(select((((_e554.member_1.member_1.member_2.x * _e595) + (_e554.member_1.member_1.member_2.y * _e598)) + (_e614 * _e610)), _e609, _e643), _e610, _e642) * _e683));
                                        let _e698 = params.member.member.member_1[0u];
                                        let _e701 = (((_e688 * 0.5f) / (_e692 * _e698)) + 0.5f);
                                        let _e707 = params.member.member.member_1[1u];
                                        let _e710 = (0.5f - ((_e690 * 0.5f) / (_e692 * _e707)));
                                        let _e720 = select(false, select(false, select(false, select(false, (_e710 <= 1f), (_e710 >= 0f)), select(false, (_e701 <= 1f), (_e701 >= 0f))), (_e692 > 0f)), _e672);
                                        if _e720 {
                                            let _e721 = (_e701 * _e74);
                                            if (_e721 > 0f) {
                                                let _e727 = select(select(u32(_e721), 0u, (_e721 < 0f)), 4294967295u, (_e721 > 4294967000f));
                                                let _e728 = (_e79 - 1u);
                                                phi_1189_ = select(_e727, _e728, (_e728 < _e727));
                                            } else {
                                                phi_1189_ = 0u;
                                            }
                                            let _e732 = phi_1189_;
                                            let _e733 = (_e710 * _e84);
                                            if (_e733 > 0f) {
                                                let _e739 = select(select(u32(_e733), 0u, (_e733 < 0f)), 4294967295u, (_e733 > 4294967000f));
                                                let _e740 = (_e89 - 1u);
                                                phi_1210_ = select(_e739, _e740, (_e740 < _e739));
                                            } else {
                                                phi_1210_ = 0u;
                                            }
                                            let _e744 = phi_1210_;
                                            let _e749 = depth.member[((_e744 * _e79) + _e732)];
                                            let _e753 = select(_e102, _e749, select(false, (_e749 < _e102), (_e749 > 0f)));
                                            let _e756 = (((_e701 * 2f) - 1f) * _e698);
                                            let _e760 = (((_e710 * -2f) + 1f) * _e707);
                                            let _e762 = (_e688 - (_e756 * _e753));
                                            let _e763 = (_e690 - (_e760 * _e753));
                                            let _e764 = (_e692 - _e753);
                                            let _e770 = sqrt((((_e762 * _e762) + (_e763 * _e763)) + (_e764 * _e764)));
                                            let _e775 = (select(0f, select(1f, _e701, (_e701 < 1f)), (_e701 > 0f)) * _e74);
                                            if (_e775 > 0f) {
                                                let _e781 = select(select(u32(_e775), 0u, (_e775 < 0f)), 4294967295u, (_e775 > 4294967000f));
                                                let _e782 = (_e79 - 1u);
                                                phi_1299_ = select(_e781, _e782, (_e782 < _e781));
                                            } else {
                                                phi_1299_ = 0u;
                                            }
                                            let _e786 = phi_1299_;
                                            let _e791 = (select(0f, select(1f, _e710, (_e710 < 1f)), (_e710 > 0f)) * _e84);
                                            if (_e791 > 0f) {
                                                let _e797 = select(select(u32(_e791), 0u, (_e791 < 0f)), 4294967295u, (_e791 > 4294967000f));
                                                let _e798 = (_e89 - 1u);
                                                phi_1330_ = select(_e797, _e798, (_e798 < _e797));
                                            } else {
                                                phi_1330_ = 0u;
                                            }
                                            let _e802 = phi_1330_;
                                            let _e820 = ((_e802 * _e79) + _e786);
                                            if (_e820 < arrayLength((&normals.member))) {
                                            } else {
                                                phi_2066_ = true;
                                                phi_1636_ = bool();
                                                phi_1635_ = bool();
                                                phi_1634_ = bool();
                                                phi_1633_ = bool();
                                                phi_1631_ = f32();
                                                break;
                                            }
                                            let _e824 = normals.member[_e820];
                                            let _e832 = (f32((bitcast<i32>(((_e824 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e832 != _e832) {
                                                phi_2037_ = true;
                                            } else {
                                                phi_2037_ = (-1f >= _e832);
                                            }
                                            let _e836 = phi_2037_;
                                            let _e837 = select(_e832, -1f, _e836);
                                            let _e847 = (f32((bitcast<i32>((((_e824 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                                            if (_e847 != _e847) {
                                                phi_2052_ = true;
                                            } else {
                                                phi_2052_ = (-1f >= _e847);
                                            }
                                            let _e851 = phi_2052_;
                                            let _e852 = select(_e847, -1f, _e851);
                                            let _e855 = (1f - abs(_e837));
                                            let _e856 = abs(_e852);
                                            let _e857 = (_e855 - _e856);
                                            if (_e857 < 0f) {
                                                phi_2013_ = vec2<f32>(((1f - _e856) * select(1f, -1f, (_e837 < 0f))), (_e855 * select(1f, -1f, (_e852 < 0f))));
                                            } else {
                                                phi_2013_ = vec2<f32>(_e837, _e852);
                                            }
                                            let _e868 = phi_2013_;
                                            let _e877 = (1f / sqrt((((_e868.x * _e868.x) + (_e868.y * _e868.y)) + (_e857 * _e857))));
                                            let _e878 = (_e868.x * _e877);
                                            let _e879 = (_e868.y * _e877);
                                            let _e881 = -((_e857 * _e877));
                                            let _e885 = (((_e878 * _e756) + (_e879 * _e760)) + _e881);
                                            let _e894 = select(((((_e878 * ((((((f32(_e786) + 0.5f) * (1f / _e74)) * 2f) - 1f) * _e698) * _e753)) + (_e879 * ((((((f32(_e802) + 0.5f) * (1f / _e84)) * -2f) + 1f) * _e707) * _e753))) + (_e881 * _e753)) / _e885), _e753, (abs(_e885) < 0.001f));
                                            let _e904 = select(select(((_e692 - _e894) > _e660), true, (_e692 < (_e894 * (1f + _e657)))), true, select(false, (_e802 == _e554.member_1.member_1.member.y), (_e786 == _e554.member_1.member_1.member.x)));
                                            let _e906 = select(false, !(_e904), _e720);
                                            let _e907 = (_e674 + _e770);
                                            let _e916 = select(false, _e904, _e720);
                                            if _e916 {
                                                phi_1470_ = (_e666 + 1u);
                                            } else {
                                                phi_1470_ = u32();
                                            }
                                            let _e919 = phi_1470_;
                                            phi_1472_ = _e919;
                                            phi_1473_ = select(_e668, select((_e676 + ((_e674 * (_e683 - _e676)) / _e907)), _e676, (_e907 < 0.000001f)), _e906);
                                            phi_1474_ = select(_e906, true, _e670);
                                            phi_1475_ = _e916;
                                            phi_1476_ = _e770;
                                            phi_1479_ = _e916;
                                            phi_1480_ = select(true, false, _e916);
                                        } else {
                                            phi_1472_ = u32();
                                            phi_1473_ = f32();
                                            phi_1474_ = bool();
                                            phi_1475_ = bool();
                                            phi_1476_ = f32();
                                            phi_1479_ = false;
                                            phi_1480_ = false;
                                        }
                                        let _e922 = phi_1472_;
                                        let _e924 = phi_1473_;
                                        let _e926 = phi_1474_;
                                        let _e928 = phi_1475_;
                                        let _e930 = phi_1476_;
                                        let _e932 = phi_1479_;
                                        let _e934 = phi_1480_;
                                        phi_1075_ = _e922;
                                        phi_1078_ = _e924;
                                        phi_1080_ = _e926;
                                        phi_1082_ = _e928;
                                        phi_1084_ = _e930;
                                        phi_1086_ = _e683;
                                        phi_1484_ = _e932;
                                        phi_1486_ = _e934;
                                        phi_1487_ = select(true, false, _e720);
                                    } else {
                                        phi_1075_ = u32();
                                        phi_1078_ = f32();
                                        phi_1080_ = bool();
                                        phi_1082_ = bool();
                                        phi_1084_ = f32();
                                        phi_1086_ = f32();
                                        phi_1484_ = false;
                                        phi_1486_ = false;
                                        phi_1487_ = false;
                                    }
                                    let _e937 = phi_1075_;
                                    let _e939 = phi_1078_;
                                    let _e941 = phi_1080_;
                                    let _e943 = phi_1082_;
                                    let _e945 = phi_1084_;
                                    let _e947 = phi_1086_;
                                    let _e949 = phi_1484_;
                                    let _e951 = phi_1486_;
                                    let _e953 = phi_1487_;
                                    continue;
                                    continuing {
                                        phi_1074_ = _e937;
                                        phi_1077_ = _e939;
                                        phi_1079_ = _e941;
                                        phi_1081_ = _e943;
                                        phi_1083_ = _e945;
                                        phi_1085_ = _e947;
                                        phi_2066_ = _e576;
                                        phi_1636_ = _e953;
                                        phi_1635_ = _e951;
                                        phi_1634_ = select(true, false, _e677);
                                        phi_1633_ = _e941;
                                        phi_1631_ = _e939;
                                        break if !(_e949);
                                    }
                                }
                                let _e957 = phi_2066_;
                                let _e959 = phi_1636_;
                                let _e961 = phi_1635_;
                                let _e963 = phi_1634_;
                                let _e965 = phi_1633_;
                                let _e967 = phi_1631_;
                                phi_2203_ = _e957;
                                if _e957 {
                                    break;
                                }
                                let _e968 = select(_e961, false, _e963);
                                let _e970 = select(select(_e959, false, _e963), false, _e968);
                                let _e972 = local_1;
                                let _e975 = local_2;
                                let _e977 = select(_e968, true, _e970);
                                let _e979 = local_3;
                                let _e982 = local_4;
                                let _e986 = params.member.member_7;
                                if (_e986 == 1u) {
                                    phi_1527_ = 0f;
                                } else {
                                    let _e988 = (select(_e979, select(_e967, _e972, _e970), _e977) / _e653);
                                    phi_1527_ = select(0f, select(1f, _e988, (_e988 < 1f)), (_e988 > 0f));
                                }
                                let _e994 = phi_1527_;
                                phi_2204_ = _e957;
                                phi_926_ = (_e578 + 1u);
                                phi_929_ = (_e580 + select(1f, _e994, select(_e982, select(_e965, _e975, _e970), _e977)));
                            } else {
                                phi_2204_ = _e576;
                                phi_926_ = u32();
                                phi_929_ = f32();
                            }
                            let _e999 = phi_2204_;
                            let _e1001 = phi_926_;
                            let _e1003 = phi_929_;
                            continue;
                            continuing {
                                phi_2114_ = _e999;
                                phi_925_ = _e1001;
                                phi_928_ = _e1003;
                                phi_2203_ = _e999;
                                break if !(_e581);
                            }
                        }
                        let _e1006 = phi_2203_;
                        if _e1006 {
                            break;
                        }
                        let _e1009 = local_5;
                        let _e1013 = params.member.member_2;
                        let _e1014 = pow((_e1009 / f32(_e569)), _e1013);
                        let _e1015 = (_e1014 * 0.6666667f);
                        let _e1021 = ((select(0f, select(1f, _e1015, (_e1015 < 1f)), (_e1015 > 0f)) * 255f) + 0.5f);
                        phi_1598_ = type_29(_e1014, select(select(u32(_e1021), 0u, (_e1021 < 0f)), 4294967295u, (_e1021 > 4294967000f)), _e554.member);
                    } else {
                        phi_1598_ = type_29(1f, 170u, _e554.member);
                    }
                    let _e1030 = phi_1598_;
                    if (_e95 < arrayLength((&ao.member))) {
                    } else {
                        break;
                    }
                    ao.member[_e95] = _e1030.member;
                    if (_e95 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e95] = _e1030.member_1;
                    if (_e95 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e95] = _e1030.member_2;
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn raymarch_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
