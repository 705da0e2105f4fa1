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
    member_5: f32,
    member_6: f32,
    member_7: f32,
    member_8: u32,
    member_9: u32,
    member_10: u32,
    member_11: u32,
    member_12: u32,
    member_13: u32,
    member_14: u32,
}

struct type_21 {
    member: type_20,
}

struct type_23 {
    member: f32,
    member_1: vec3<f32>,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(4) 
var<uniform> params: type_21;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;

fn function_() {
    var phi_1933_: bool;
    var phi_1948_: bool;
    var phi_1963_: bool;
    var phi_1978_: bool;
    var phi_2009_: f32;
    var phi_2013_: f32;
    var phi_2014_: bool;
    var phi_2036_: u32;
    var phi_2063_: f32;
    var phi_2067_: f32;
    var phi_2068_: bool;
    var phi_2090_: u32;
    var phi_2117_: f32;
    var phi_2121_: f32;
    var phi_2122_: bool;
    var phi_2144_: u32;
    var phi_2171_: f32;
    var phi_2175_: f32;
    var phi_2176_: bool;
    var phi_2198_: u32;
    var phi_2277_: bool;
    var phi_2292_: bool;
    var phi_2253_: vec2<f32>;
    var phi_2309_: u32;
    var phi_2310_: u32;
    var phi_2311_: u32;
    var phi_2312_: u32;
    var phi_2335_: u32;
    var phi_2336_: u32;
    var phi_2339_: u32;
    var phi_2340_: u32;
    var phi_2344_: u32;
    var phi_2345_: u32;
    var phi_2346_: u32;
    var phi_2347_: u32;
    var local: u32;
    var phi_759_: u32;
    var phi_762_: vec3<f32>;
    var phi_764_: f32;
    var phi_935_: u32;
    var phi_938_: f32;
    var phi_940_: f32;
    var phi_994_: f32;
    var phi_1039_: f32;
    var phi_1041_: f32;
    var phi_1042_: bool;
    var phi_1065_: f32;
    var phi_1067_: f32;
    var phi_1068_: bool;
    var phi_1101_: u32;
    var phi_1117_: u32;
    var phi_1120_: u32;
    var phi_1118_: u32;
    var phi_1121_: u32;
    var phi_1165_: u32;
    var phi_1184_: u32;
    var local_1: u32;
    var phi_1223_: u32;
    var phi_1239_: u32;
    var phi_1242_: u32;
    var phi_1240_: u32;
    var phi_1243_: u32;
    var phi_1287_: u32;
    var phi_1306_: u32;
    var local_2: u32;
    var phi_1384_: f32;
    var phi_1444_: f32;
    var phi_2381_: bool;
    var phi_2396_: bool;
    var phi_936_: u32;
    var phi_939_: f32;
    var phi_941_: f32;
    var local_3: f32;
    var local_4: f32;
    var local_5: f32;
    var local_6: f32;
    var phi_1663_: vec3<f32>;
    var phi_760_: u32;
    var phi_763_: vec3<f32>;
    var phi_765_: f32;
    var local_7: f32;
    var local_8: vec3<f32>;
    var phi_1669_: type_23;
    var phi_2423_: bool;
    var phi_1724_: vec3<f32>;
    var phi_1745_: u32;
    var phi_1790_: u32;

    let _e83 = id_1;
    let _e89 = params.member.member.member[0u];
    let _e94 = select(select(u32(_e89), 0u, (_e89 < 0f)), 4294967295u, (_e89 > 4294967000f));
    let _e99 = params.member.member.member[1u];
    let _e104 = select(select(u32(_e99), 0u, (_e99 < 0f)), 4294967295u, (_e99 > 4294967000f));
    if (_e83.x >= _e94) {
    } else {
        if (_e83.y >= _e104) {
        } else {
            let _e110 = ((_e83.y * _e94) + _e83.x);
            let _e112 = mips.member[_e110];
            let _e113 = bitcast<i32>(_e83.x);
            let _e114 = (_e113 + -1i);
            let _e116 = select(0i, _e114, (0i < _e114));
            let _e118 = (bitcast<i32>(_e94) - 1i);
            let _e122 = bitcast<i32>(_e83.y);
            let _e124 = select(0i, _e122, (0i < _e122));
            let _e126 = (bitcast<i32>(_e104) - 1i);
            let _e130 = (bitcast<u32>(select(_e124, _e126, (_e126 < _e124))) * _e94);
            let _e133 = mips.member[(_e130 + bitcast<u32>(select(_e116, _e118, (_e118 < _e116))))];
            let _e134 = (_e113 + 1i);
            let _e136 = select(0i, _e134, (0i < _e134));
            let _e142 = mips.member[(_e130 + bitcast<u32>(select(_e136, _e118, (_e118 < _e136))))];
            let _e144 = select(0i, _e113, (0i < _e113));
            let _e147 = bitcast<u32>(select(_e144, _e118, (_e118 < _e144)));
            let _e148 = (_e122 + -1i);
            let _e150 = select(0i, _e148, (0i < _e148));
            let _e157 = mips.member[((bitcast<u32>(select(_e150, _e126, (_e126 < _e150))) * _e94) + _e147)];
            let _e158 = (_e122 + 1i);
            let _e160 = select(0i, _e158, (0i < _e158));
            let _e167 = mips.member[((bitcast<u32>(select(_e160, _e126, (_e126 < _e160))) * _e94) + _e147)];
            let _e168 = (_e133 - _e112);
            let _e169 = (_e142 - _e112);
            let _e170 = (_e157 - _e112);
            let _e171 = (_e167 - _e112);
            let _e173 = ((_e169 - _e168) * 0.5f);
            let _e175 = ((_e171 - _e170) * 0.5f);
            let _e176 = (_e112 * 0.011f);
            let _e178 = abs(_e168);
            let _e179 = abs((_e168 + _e173));
            if (_e178 != _e178) {
                phi_1933_ = true;
            } else {
                phi_1933_ = (_e179 <= _e178);
            }
            let _e183 = phi_1933_;
            let _e186 = (1.25f - (select(_e178, _e179, _e183) / _e176));
            let _e190 = select(0f, select(1f, _e186, (_e186 < 1f)), (_e186 > 0f));
            let _e192 = abs(_e169);
            let _e193 = abs((_e169 - _e173));
            if (_e192 != _e192) {
                phi_1948_ = true;
            } else {
                phi_1948_ = (_e193 <= _e192);
            }
            let _e197 = phi_1948_;
            let _e200 = (1.25f - (select(_e192, _e193, _e197) / _e176));
            let _e204 = select(0f, select(1f, _e200, (_e200 < 1f)), (_e200 > 0f));
            let _e206 = abs(_e170);
            let _e207 = abs((_e170 + _e175));
            if (_e206 != _e206) {
                phi_1963_ = true;
            } else {
                phi_1963_ = (_e207 <= _e206);
            }
            let _e211 = phi_1963_;
            let _e214 = (1.25f - (select(_e206, _e207, _e211) / _e176));
            let _e218 = select(0f, select(1f, _e214, (_e214 < 1f)), (_e214 > 0f));
            let _e220 = abs(_e171);
            let _e221 = abs((_e171 - _e175));
            if (_e220 != _e220) {
                phi_1978_ = true;
            } else {
                phi_1978_ = (_e221 <= _e220);
            }
            let _e225 = phi_1978_;
            let _e228 = (1.25f - (select(_e220, _e221, _e225) / _e176));
            let _e232 = select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f));
            let _e237 = (select(0f, select(1f, _e190, (_e190 < 1f)), (_e190 > 0f)) * 2.9f);
            let _e239 = floor((_e237 + 0.5f));
            if ((_e239 - _e237) == 0.5f) {
                let _e245 = ((floor((_e239 * 0.5f)) * 2f) != _e239);
                if _e245 {
                    phi_2009_ = (_e239 - 1f);
                } else {
                    phi_2009_ = f32();
                }
                let _e248 = phi_2009_;
                phi_2013_ = _e248;
                phi_2014_ = select(true, false, _e245);
            } else {
                phi_2013_ = f32();
                phi_2014_ = true;
            }
            let _e251 = phi_2013_;
            let _e253 = phi_2014_;
            let _e254 = select(_e251, _e239, _e253);
            if (_e254 > 0f) {
                let _e260 = select(select(u32(_e254), 0u, (_e254 < 0f)), 4294967295u, (_e254 > 4294967000f));
                phi_2036_ = select(_e260, 3u, (3u < _e260));
            } else {
                phi_2036_ = 0u;
            }
            let _e264 = phi_2036_;
            let _e270 = (select(0f, select(1f, _e204, (_e204 < 1f)), (_e204 > 0f)) * 2.9f);
            let _e272 = floor((_e270 + 0.5f));
            if ((_e272 - _e270) == 0.5f) {
                let _e278 = ((floor((_e272 * 0.5f)) * 2f) != _e272);
                if _e278 {
                    phi_2063_ = (_e272 - 1f);
                } else {
                    phi_2063_ = f32();
                }
                let _e281 = phi_2063_;
                phi_2067_ = _e281;
                phi_2068_ = select(true, false, _e278);
            } else {
                phi_2067_ = f32();
                phi_2068_ = true;
            }
            let _e284 = phi_2067_;
            let _e286 = phi_2068_;
            let _e287 = select(_e284, _e272, _e286);
            if (_e287 > 0f) {
                let _e293 = select(select(u32(_e287), 0u, (_e287 < 0f)), 4294967295u, (_e287 > 4294967000f));
                phi_2090_ = select(_e293, 3u, (3u < _e293));
            } else {
                phi_2090_ = 0u;
            }
            let _e297 = phi_2090_;
            let _e304 = (select(0f, select(1f, _e218, (_e218 < 1f)), (_e218 > 0f)) * 2.9f);
            let _e306 = floor((_e304 + 0.5f));
            if ((_e306 - _e304) == 0.5f) {
                let _e312 = ((floor((_e306 * 0.5f)) * 2f) != _e306);
                if _e312 {
                    phi_2117_ = (_e306 - 1f);
                } else {
                    phi_2117_ = f32();
                }
                let _e315 = phi_2117_;
                phi_2121_ = _e315;
                phi_2122_ = select(true, false, _e312);
            } else {
                phi_2121_ = f32();
                phi_2122_ = true;
            }
            let _e318 = phi_2121_;
            let _e320 = phi_2122_;
            let _e321 = select(_e318, _e306, _e320);
            if (_e321 > 0f) {
                let _e327 = select(select(u32(_e321), 0u, (_e321 < 0f)), 4294967295u, (_e321 > 4294967000f));
                phi_2144_ = select(_e327, 3u, (3u < _e327));
            } else {
                phi_2144_ = 0u;
            }
            let _e331 = phi_2144_;
            let _e338 = (select(0f, select(1f, _e232, (_e232 < 1f)), (_e232 > 0f)) * 2.9f);
            let _e340 = floor((_e338 + 0.5f));
            if ((_e340 - _e338) == 0.5f) {
                let _e346 = ((floor((_e340 * 0.5f)) * 2f) != _e340);
                if _e346 {
                    phi_2171_ = (_e340 - 1f);
                } else {
                    phi_2171_ = f32();
                }
                let _e349 = phi_2171_;
                phi_2175_ = _e349;
                phi_2176_ = select(true, false, _e346);
            } else {
                phi_2175_ = f32();
                phi_2176_ = true;
            }
            let _e352 = phi_2175_;
            let _e354 = phi_2176_;
            let _e355 = select(_e352, _e340, _e354);
            if (_e355 > 0f) {
                let _e361 = select(select(u32(_e355), 0u, (_e355 < 0f)), 4294967295u, (_e355 > 4294967000f));
                phi_2198_ = select(_e361, 3u, (3u < _e361));
            } else {
                phi_2198_ = 0u;
            }
            let _e365 = phi_2198_;
            let _e369 = ((f32(_e83.x) + 0.5f) / _e89);
            let _e372 = ((f32(_e83.y) + 0.5f) / _e99);
            let _e373 = (_e112 * 0.99999f);
            let _e380 = params.member.member.member_1[0u];
            let _e382 = ((((_e369 * 2f) - 1f) * _e380) * _e373);
            let _e389 = params.member.member.member_1[1u];
            let _e391 = ((((_e372 * -2f) + 1f) * _e389) * _e373);
            let _e392 = -(_e382);
            let _e393 = -(_e391);
            let _e394 = (_e112 * -0.99999f);
            let _e401 = (1f / sqrt((((_e392 * _e392) + (_e393 * _e393)) + (_e394 * _e394))));
            let _e402 = (_e392 * _e401);
            let _e403 = (_e393 * _e401);
            let _e404 = (_e394 * _e401);
            let _e407 = normals.member[_e110];
            let _e415 = (f32((bitcast<i32>(((_e407 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e415 != _e415) {
                phi_2277_ = true;
            } else {
                phi_2277_ = (-1f >= _e415);
            }
            let _e419 = phi_2277_;
            let _e420 = select(_e415, -1f, _e419);
            let _e430 = (f32((bitcast<i32>((((_e407 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
            if (_e430 != _e430) {
                phi_2292_ = true;
            } else {
                phi_2292_ = (-1f >= _e430);
            }
            let _e434 = phi_2292_;
            let _e435 = select(_e430, -1f, _e434);
            let _e438 = (1f - abs(_e420));
            let _e439 = abs(_e435);
            let _e440 = (_e438 - _e439);
            if (_e440 < 0f) {
                phi_2253_ = vec2<f32>(((1f - _e439) * select(1f, -1f, (_e420 < 0f))), (_e438 * select(1f, -1f, (_e435 < 0f))));
            } else {
                phi_2253_ = vec2<f32>(_e420, _e435);
            }
            let _e451 = phi_2253_;
            let _e460 = (1f / sqrt((((_e451.x * _e451.x) + (_e451.y * _e451.y)) + (_e440 * _e440))));
            let _e461 = (_e451.x * _e460);
            let _e462 = (_e451.y * _e460);
            let _e463 = (_e440 * _e460);
            let _e464 = -(_e463);
            let _e470 = ((((_e461 * _e402) + (_e462 * _e403)) + (_e464 * _e404)) < 0f);
            let _e473 = select(_e461, -(_e461), _e470);
            let _e474 = select(_e462, -(_e462), _e470);
            let _e475 = select(_e464, _e463, _e470);
            let _e479 = params.member.member_1;
            let _e482 = params.member.member_2;
            let _e483 = (_e479 * _e482);
            let _e487 = (_e483 / (((_e112 * 1.99998f) * _e380) / _e89));
            let _e491 = params.member.member_11;
            phi_2309_ = (_e83.y & 63u);
            phi_2310_ = (_e83.x & 63u);
            phi_2311_ = 32u;
            phi_2312_ = 0u;
            loop {
                let _e495 = phi_2309_;
                let _e497 = phi_2310_;
                let _e499 = phi_2311_;
                let _e501 = phi_2312_;
                local = _e501;
                let _e502 = (_e499 > 0u);
                if _e502 {
                    let _e505 = select(0u, 1u, ((_e497 & _e499) != 0u));
                    let _e508 = select(0u, 1u, ((_e495 & _e499) != 0u));
                    if (_e508 == 0u) {
                        if (_e505 == 1u) {
                            phi_2335_ = (63u - _e495);
                            phi_2336_ = (63u - _e497);
                        } else {
                            phi_2335_ = _e495;
                            phi_2336_ = _e497;
                        }
                        let _e519 = phi_2335_;
                        let _e521 = phi_2336_;
                        phi_2339_ = _e521;
                        phi_2340_ = _e519;
                    } else {
                        phi_2339_ = _e495;
                        phi_2340_ = _e497;
                    }
                    let _e523 = phi_2339_;
                    let _e525 = phi_2340_;
                    phi_2344_ = _e523;
                    phi_2345_ = _e525;
                    phi_2346_ = (_e499 / 2u);
                    phi_2347_ = (_e501 + ((_e499 * _e499) * ((3u * _e505) ^ _e508)));
                } else {
                    phi_2344_ = u32();
                    phi_2345_ = u32();
                    phi_2346_ = u32();
                    phi_2347_ = u32();
                }
                let _e528 = phi_2344_;
                let _e530 = phi_2345_;
                let _e532 = phi_2346_;
                let _e534 = phi_2347_;
                continue;
                continuing {
                    phi_2309_ = _e528;
                    phi_2310_ = _e530;
                    phi_2311_ = _e532;
                    phi_2312_ = _e534;
                    break if !(_e502);
                }
            }
            let _e539 = local;
            let _e541 = f32((_e539 + (288u * (_e491 % 64u))));
            let _e543 = (0.5f + (_e541 * 0.7548777f));
            let _e547 = (0.5f + (_e541 * 0.5698403f));
            let _e553 = params.member.member.member_3;
            let _e556 = select(false, (_e112 < _e553), (_e112 > 0f));
            if _e556 {
                let _e559 = params.member.member_3;
                let _e560 = (_e559 * _e483);
                let _e562 = ((10f - _e487) * 0.01f);
                let _e570 = params.member.member_8;
                let _e572 = select(1u, _e570, (1u < _e570));
                phi_759_ = 0u;
                phi_762_ = vec3<f32>(0f, 0f, 0f);
                phi_764_ = (select(0f, select(1f, _e562, (_e562 < 1f)), (_e562 > 0f)) * 0.5f);
                loop {
                    let _e574 = phi_759_;
                    let _e576 = phi_762_;
                    let _e578 = phi_764_;
                    local_7 = _e578;
                    local_8 = _e576;
                    let _e579 = (_e574 < _e572);
                    if _e579 {
                        let _e584 = ((((_e543 - floor(_e543)) + f32(_e574)) * 3.1415927f) / f32(_e572));
                        let _e585 = sin(_e584);
                        let _e586 = cos(_e584);
                        let _e592 = ((_e586 * _e402) + (_e585 * _e403));
                        let _e596 = (_e586 - (_e402 * _e592));
                        let _e597 = (_e585 - (_e403 * _e592));
                        let _e598 = -((_e404 * _e592));
                        let _e601 = ((_e597 * _e404) - (_e403 * _e598));
                        let _e604 = ((_e598 * _e402) - (_e404 * _e596));
                        let _e607 = ((_e596 * _e403) - (_e402 * _e597));
                        let _e614 = (1f / sqrt((((_e601 * _e601) + (_e604 * _e604)) + (_e607 * _e607))));
                        let _e615 = (_e601 * _e614);
                        let _e616 = (_e604 * _e614);
                        let _e617 = (_e607 * _e614);
                        let _e622 = (((_e473 * _e615) + (_e474 * _e616)) + (_e475 * _e617));
                        let _e626 = (_e473 - (_e615 * _e622));
                        let _e627 = (_e474 - (_e616 * _e622));
                        let _e628 = (_e475 - (_e617 * _e622));
                        let _e634 = sqrt((((_e626 * _e626) + (_e627 * _e627)) + (_e628 * _e628)));
                        let _e639 = (((_e596 * _e626) + (_e597 * _e627)) + (_e598 * _e628));
                        let _e649 = ((((_e626 * _e402) + (_e627 * _e403)) + (_e628 * _e404)) / _e634);
                        let _e653 = select(0f, select(1f, _e649, (_e649 < 1f)), (_e649 > 0f));
                        let _e654 = abs(_e653);
                        let _e665 = (((_e654 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e654))) >> bitcast<u32>(1i))))));
                        let _e669 = (select(select(0f, -1f, (_e639 < 0f)), 1f, (_e639 > 0f)) * select((3.141593f - _e665), _e665, (_e653 >= 0f)));
                        let _e672 = params.member.member_9;
                        let _e674 = select(1u, _e672, (1u < _e672));
                        let _e676 = cos((_e669 + 1.5707964f));
                        let _e678 = cos((_e669 - 1.5707964f));
                        let _e681 = params.member.member_5;
                        phi_935_ = 0u;
                        phi_938_ = _e678;
                        phi_940_ = _e676;
                        loop {
                            let _e683 = phi_935_;
                            let _e685 = phi_938_;
                            let _e687 = phi_940_;
                            local_3 = _e685;
                            local_4 = _e685;
                            local_5 = _e687;
                            local_6 = _e687;
                            let _e688 = (_e683 < _e674);
                            if _e688 {
                                let _e693 = ((_e547 - floor(_e547)) + (f32((_e574 + (_e683 * _e674))) * 0.618034f));
                                let _e699 = (((_e693 - floor(_e693)) + f32(_e683)) / f32(_e674));
                                let _e702 = params.member.member_4;
                                if (_e702 == 2f) {
                                    phi_994_ = (_e699 * _e699);
                                } else {
                                    phi_994_ = pow(_e699, _e702);
                                }
                                let _e707 = phi_994_;
                                let _e708 = (_e707 + (1.3f / _e487));
                                let _e709 = ((_e586 * _e487) * _e708);
                                let _e710 = ((-(_e585) * _e487) * _e708);
                                let _e718 = params.member.member_7;
                                let _e719 = (log2(sqrt(((_e709 * _e709) + (_e710 * _e710)))) - _e718);
                                let _e726 = (-1f - floor((-0.5f - select(0f, select(5f, _e719, (_e719 < 5f)), (_e719 > 0f)))));
                                let _e728 = floor((_e709 + 0.5f));
                                if ((_e728 - _e709) == 0.5f) {
                                    let _e734 = ((floor((_e728 * 0.5f)) * 2f) != _e728);
                                    if _e734 {
                                        phi_1039_ = (_e728 - 1f);
                                    } else {
                                        phi_1039_ = f32();
                                    }
                                    let _e737 = phi_1039_;
                                    phi_1041_ = _e737;
                                    phi_1042_ = select(true, false, _e734);
                                } else {
                                    phi_1041_ = f32();
                                    phi_1042_ = true;
                                }
                                let _e740 = phi_1041_;
                                let _e742 = phi_1042_;
                                let _e744 = (select(_e740, _e728, _e742) / _e89);
                                let _e746 = floor((_e710 + 0.5f));
                                if ((_e746 - _e710) == 0.5f) {
                                    let _e752 = ((floor((_e746 * 0.5f)) * 2f) != _e746);
                                    if _e752 {
                                        phi_1065_ = (_e746 - 1f);
                                    } else {
                                        phi_1065_ = f32();
                                    }
                                    let _e755 = phi_1065_;
                                    phi_1067_ = _e755;
                                    phi_1068_ = select(true, false, _e752);
                                } else {
                                    phi_1067_ = f32();
                                    phi_1068_ = true;
                                }
                                let _e758 = phi_1067_;
                                let _e760 = phi_1068_;
                                let _e762 = (select(_e758, _e746, _e760) / _e99);
                                let _e763 = (_e369 + _e744);
                                let _e764 = (_e372 + _e762);
                                let _e765 = (_e369 - _e744);
                                let _e766 = (_e372 - _e762);
                                let _e767 = (_e726 > 0f);
                                if _e767 {
                                    let _e772 = select(select(u32(_e726), 0u, (_e726 < 0f)), 4294967295u, (_e726 > 4294967000f));
                                    phi_1101_ = select(_e772, 4u, (4u < _e772));
                                } else {
                                    phi_1101_ = 0u;
                                }
                                let _e776 = phi_1101_;
                                let _e777 = (_e776 & 31u);
                                let _e779 = (_e94 >> bitcast<u32>(_e777));
                                let _e781 = select(1u, _e779, (1u < _e779));
                                let _e783 = (_e104 >> bitcast<u32>(_e777));
                                let _e785 = select(1u, _e783, (1u < _e783));
                                phi_1117_ = 0u;
                                phi_1120_ = 0u;
                                loop {
                                    let _e787 = phi_1117_;
                                    let _e789 = phi_1120_;
                                    local_1 = _e789;
                                    let _e790 = (_e787 < _e776);
                                    if _e790 {
                                        let _e791 = (_e787 & 31u);
                                        let _e793 = (_e94 >> bitcast<u32>(_e791));
                                        let _e797 = (_e104 >> bitcast<u32>(_e791));
                                        phi_1118_ = (_e787 + 1u);
                                        phi_1121_ = (_e789 + (select(1u, _e793, (1u < _e793)) * select(1u, _e797, (1u < _e797))));
                                    } else {
                                        phi_1118_ = u32();
                                        phi_1121_ = u32();
                                    }
                                    let _e804 = phi_1118_;
                                    let _e806 = phi_1121_;
                                    continue;
                                    continuing {
                                        phi_1117_ = _e804;
                                        phi_1120_ = _e806;
                                        break if !(_e790);
                                    }
                                }
                                let _e810 = (_e763 * f32(_e781));
                                if (_e810 > 0f) {
                                    let _e816 = select(select(u32(_e810), 0u, (_e810 < 0f)), 4294967295u, (_e810 > 4294967000f));
                                    let _e817 = (_e781 - 1u);
                                    phi_1165_ = select(_e816, _e817, (_e817 < _e816));
                                } else {
                                    phi_1165_ = 0u;
                                }
                                let _e821 = phi_1165_;
                                let _e822 = (_e764 * f32(_e785));
                                if (_e822 > 0f) {
                                    let _e828 = select(select(u32(_e822), 0u, (_e822 < 0f)), 4294967295u, (_e822 > 4294967000f));
                                    let _e829 = (_e785 - 1u);
                                    phi_1184_ = select(_e828, _e829, (_e829 < _e828));
                                } else {
                                    phi_1184_ = 0u;
                                }
                                let _e833 = phi_1184_;
                                let _e836 = local_1;
                                let _e841 = mips.member[((_e836 + (_e833 * _e781)) + _e821)];
                                if _e767 {
                                    let _e854 = select(select(u32(_e726), 0u, (_e726 < 0f)), 4294967295u, (_e726 > 4294967000f));
                                    phi_1223_ = select(_e854, 4u, (4u < _e854));
                                } else {
                                    phi_1223_ = 0u;
                                }
                                let _e858 = phi_1223_;
                                let _e859 = (_e858 & 31u);
                                let _e861 = (_e94 >> bitcast<u32>(_e859));
                                let _e863 = select(1u, _e861, (1u < _e861));
                                let _e865 = (_e104 >> bitcast<u32>(_e859));
                                let _e867 = select(1u, _e865, (1u < _e865));
                                phi_1239_ = 0u;
                                phi_1242_ = 0u;
                                loop {
                                    let _e869 = phi_1239_;
                                    let _e871 = phi_1242_;
                                    local_2 = _e871;
                                    let _e872 = (_e869 < _e858);
                                    if _e872 {
                                        let _e873 = (_e869 & 31u);
                                        let _e875 = (_e94 >> bitcast<u32>(_e873));
                                        let _e879 = (_e104 >> bitcast<u32>(_e873));
                                        phi_1240_ = (_e869 + 1u);
                                        phi_1243_ = (_e871 + (select(1u, _e875, (1u < _e875)) * select(1u, _e879, (1u < _e879))));
                                    } else {
                                        phi_1240_ = u32();
                                        phi_1243_ = u32();
                                    }
                                    let _e886 = phi_1240_;
                                    let _e888 = phi_1243_;
                                    continue;
                                    continuing {
                                        phi_1239_ = _e886;
                                        phi_1242_ = _e888;
                                        break if !(_e872);
                                    }
                                }
                                let _e892 = (_e765 * f32(_e863));
                                if (_e892 > 0f) {
                                    let _e898 = select(select(u32(_e892), 0u, (_e892 < 0f)), 4294967295u, (_e892 > 4294967000f));
                                    let _e899 = (_e863 - 1u);
                                    phi_1287_ = select(_e898, _e899, (_e899 < _e898));
                                } else {
                                    phi_1287_ = 0u;
                                }
                                let _e903 = phi_1287_;
                                let _e904 = (_e766 * f32(_e867));
                                if (_e904 > 0f) {
                                    let _e910 = select(select(u32(_e904), 0u, (_e904 < 0f)), 4294967295u, (_e904 > 4294967000f));
                                    let _e911 = (_e867 - 1u);
                                    phi_1306_ = select(_e910, _e911, (_e911 < _e910));
                                } else {
                                    phi_1306_ = 0u;
                                }
                                let _e915 = phi_1306_;
                                let _e918 = local_2;
                                let _e923 = mips.member[((_e918 + (_e915 * _e863)) + _e903)];
                                let _e932 = (((((_e763 * 2f) - 1f) * _e380) * _e841) - _e382);
                                let _e933 = (((((_e764 * -2f) + 1f) * _e389) * _e841) - _e391);
                                let _e934 = (_e841 - _e373);
                                let _e937 = ((_e932 * _e932) + (_e933 * _e933));
                                let _e940 = sqrt((_e937 + (_e934 * _e934)));
                                let _e949 = (1f + _e681);
                                let _e950 = (_e934 * _e949);
                                let _e953 = sqrt((_e937 + (_e950 * _e950)));
                                let _e954 = (_e560 > 0f);
                                if _e954 {
                                    let _e957 = ((-(_e953) + _e483) / _e560);
                                    phi_1384_ = select(0f, select(1f, _e957, (_e957 < 1f)), (_e957 > 0f));
                                } else {
                                    phi_1384_ = select(0f, 1f, (_e953 <= _e483));
                                }
                                let _e965 = phi_1384_;
                                let _e968 = (_e676 + ((((((_e932 / _e940) * _e402) + ((_e933 / _e940) * _e403)) + ((_e934 / _e940) * _e404)) - _e676) * _e965));
                                let _e969 = (((((_e765 * 2f) - 1f) * _e380) * _e923) - _e382);
                                let _e970 = (((((_e766 * -2f) + 1f) * _e389) * _e923) - _e391);
                                let _e971 = (_e923 - _e373);
                                let _e974 = ((_e969 * _e969) + (_e970 * _e970));
                                let _e977 = sqrt((_e974 + (_e971 * _e971)));
                                let _e986 = (_e971 * _e949);
                                let _e989 = sqrt((_e974 + (_e986 * _e986)));
                                if _e954 {
                                    let _e992 = ((-(_e989) + _e483) / _e560);
                                    phi_1444_ = select(0f, select(1f, _e992, (_e992 < 1f)), (_e992 > 0f));
                                } else {
                                    phi_1444_ = select(0f, 1f, (_e989 <= _e483));
                                }
                                let _e1000 = phi_1444_;
                                let _e1003 = (_e678 + ((((((_e969 / _e977) * _e402) + ((_e970 / _e977) * _e403)) + ((_e971 / _e977) * _e404)) - _e678) * _e1000));
                                if (_e687 != _e687) {
                                    phi_2381_ = true;
                                } else {
                                    phi_2381_ = (_e968 >= _e687);
                                }
                                let _e1007 = phi_2381_;
                                if (_e685 != _e685) {
                                    phi_2396_ = true;
                                } else {
                                    phi_2396_ = (_e1003 >= _e685);
                                }
                                let _e1012 = phi_2396_;
                                phi_936_ = (_e683 + 1u);
                                phi_939_ = select(_e685, _e1003, _e1012);
                                phi_941_ = select(_e687, _e968, _e1007);
                            } else {
                                phi_936_ = u32();
                                phi_939_ = f32();
                                phi_941_ = f32();
                            }
                            let _e1016 = phi_936_;
                            let _e1018 = phi_939_;
                            let _e1020 = phi_941_;
                            continue;
                            continuing {
                                phi_935_ = _e1016;
                                phi_938_ = _e1018;
                                phi_940_ = _e1020;
                                break if !(_e688);
                            }
                        }
                        let _e1023 = local_3;
                        let _e1024 = abs(_e1023);
                        let _e1035 = (((_e1024 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1024))) >> bitcast<u32>(1i))))));
                        let _e1037 = local_4;
                        let _e1040 = select((3.141593f - _e1035), _e1035, (_e1037 >= 0f));
                        let _e1041 = -(_e1040);
                        let _e1043 = local_5;
                        let _e1044 = abs(_e1043);
                        let _e1055 = (((_e1044 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1044))) >> bitcast<u32>(1i))))));
                        let _e1057 = local_6;
                        let _e1060 = select((3.141593f - _e1055), _e1055, (_e1057 >= 0f));
                        let _e1063 = (_e634 + ((1f - _e634) * 0.05f));
                        let _e1064 = (_e1040 * -2f);
                        let _e1065 = sin(_e669);
                        let _e1071 = (_e1060 * 2f);
                        let _e1083 = params.member.member_13;
                        if (_e1083 == 0u) {
                            phi_1663_ = _e576;
                        } else {
                            let _e1089 = ((_e1040 * -3f) - _e669);
                            let _e1097 = ((_e1060 * 3f) - _e669);
                            let _e1102 = (_e1041 + _e669);
                            let _e1104 = (_e1060 + _e669);
                            let _e1109 = (((((((sin((_e1041 - _e669)) * 6f) - sin(_e1089)) + (sin((_e1060 - _e669)) * 6f)) - sin(_e1097)) + (_e1065 * 16f)) - ((sin(_e1102) + sin(_e1104)) * 3f)) * 0.083333336f);
                            let _e1121 = (((-(cos(_e1089)) - cos(_e1097)) + (cos(_e669) * 8f)) - ((cos(_e1102) + cos(_e1104)) * 3f));
                            let _e1122 = (_e586 * _e1109);
                            let _e1123 = (_e585 * _e1109);
                            let _e1124 = (_e1121 * -0.083333336f);
                            let _e1125 = (-1f * _e404);
                            let _e1126 = (-1f * _e402);
                            let _e1128 = (1f / (_e1125 + 1f));
                            let _e1129 = (_e1128 * _e403);
                            let _e1133 = (_e1129 * _e1126);
                            let _e1154 = (_e1125 > 0.9997f);
                            let _e1155 = (_e1125 < -0.9997f);
                            phi_1663_ = (_e576 + vec3<f32>((select(select(((((_e1125 + (_e1129 * _e403)) * _e1122) + (_e1133 * _e1123)) + (_e1126 * _e1124)), _e1122, _e1155), _e1122, _e1154) * _e1063), (select(select((((_e1133 * _e1122) + ((_e1125 + ((_e1128 * _e1126) * _e1126)) * _e1123)) + (-(_e403) * _e1124)), -(_e1123), _e1155), _e1123, _e1154) * _e1063), (select(select((((_e402 * _e1122) + (_e403 * _e1123)) + (_e1125 * _e1124)), (_e1121 * 0.083333336f), _e1155), _e1124, _e1154) * _e1063)));
                        }
                        let _e1168 = phi_1663_;
                        phi_760_ = (_e574 + 1u);
                        phi_763_ = _e1168;
                        phi_765_ = (_e578 + ((0.25f * (((_e653 + (_e1064 * _e1065)) - cos((_e1064 - _e669))) + ((_e653 + (_e1071 * _e1065)) - cos((_e1071 - _e669))))) * _e1063));
                    } else {
                        phi_760_ = u32();
                        phi_763_ = vec3<f32>();
                        phi_765_ = f32();
                    }
                    let _e1171 = phi_760_;
                    let _e1173 = phi_763_;
                    let _e1175 = phi_765_;
                    continue;
                    continuing {
                        phi_759_ = _e1171;
                        phi_762_ = _e1173;
                        phi_764_ = _e1175;
                        break if !(_e579);
                    }
                }
                let _e1179 = local_7;
                let _e1182 = local_8;
                phi_1669_ = type_23((_e1179 / f32(_e572)), _e1182);
            } else {
                phi_1669_ = type_23(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1185 = phi_1669_;
            if _e556 {
                let _e1190 = params.member.member_6;
                let _e1191 = pow(_e1185.member, _e1190);
                if (_e1191 != _e1191) {
                    phi_2423_ = true;
                } else {
                    phi_2423_ = (0.03f >= _e1191);
                }
                let _e1195 = phi_2423_;
                let _e1196 = select(_e1191, 0.03f, _e1195);
                let _e1199 = params.member.member_13;
                if (_e1199 == 0u) {
                    let _e1201 = (_e1196 * 0.6666667f);
                    let _e1207 = ((select(0f, select(1f, _e1201, (_e1201 < 1f)), (_e1201 > 0f)) * 255f) + 0.5f);
                    phi_1745_ = select(select(u32(_e1207), 0u, (_e1207 < 0f)), 4294967295u, (_e1207 > 4294967000f));
                } else {
                    let _e1221 = sqrt((((_e1185.member_1.x * _e1185.member_1.x) + (_e1185.member_1.y * _e1185.member_1.y)) + (_e1185.member_1.z * _e1185.member_1.z)));
                    if (_e1221 > 0f) {
                        phi_1724_ = (_e1185.member_1 / vec3(_e1221));
                    } else {
                        phi_1724_ = vec3<f32>(_e473, _e474, _e475);
                    }
                    let _e1226 = phi_1724_;
                    let _e1227 = (_e1196 * 0.6666667f);
                    let _e1234 = ((_e1226.x * 0.5f) + 0.5f);
                    let _e1235 = ((_e1226.y * 0.5f) + 0.5f);
                    let _e1236 = ((_e1226.z * 0.5f) + 0.5f);
                    let _e1242 = ((select(0f, select(1f, _e1234, (_e1234 < 1f)), (_e1234 > 0f)) * 255f) + 0.5f);
                    let _e1253 = ((select(0f, select(1f, _e1235, (_e1235 < 1f)), (_e1235 > 0f)) * 255f) + 0.5f);
                    let _e1267 = ((select(0f, select(1f, _e1236, (_e1236 < 1f)), (_e1236 > 0f)) * 255f) + 0.5f);
                    let _e1281 = ((select(0f, select(1f, _e1227, (_e1227 < 1f)), (_e1227 > 0f)) * 255f) + 0.5f);
                    phi_1745_ = (((select(select(u32(_e1242), 0u, (_e1242 < 0f)), 4294967295u, (_e1242 > 4294967000f)) | (select(select(u32(_e1253), 0u, (_e1253 < 0f)), 4294967295u, (_e1253 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1267), 0u, (_e1267 < 0f)), 4294967295u, (_e1267 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1281), 0u, (_e1281 < 0f)), 4294967295u, (_e1281 > 4294967000f)) << bitcast<u32>(24i)));
                }
                let _e1291 = phi_1745_;
                phi_1790_ = _e1291;
            } else {
                let _e1294 = params.member.member_13;
                phi_1790_ = select(2852159616u, 170u, (_e1294 == 0u));
            }
            let _e1298 = phi_1790_;
            terms.member[_e110] = _e1298;
            edges.member[_e110] = ((((64u * _e264) + (16u * _e297)) + (4u * _e331)) + _e365);
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
