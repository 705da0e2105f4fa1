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
    var phi_1955_: bool;
    var phi_1970_: bool;
    var phi_1985_: bool;
    var phi_2000_: bool;
    var phi_2031_: f32;
    var phi_2035_: f32;
    var phi_2036_: bool;
    var phi_2058_: u32;
    var phi_2085_: f32;
    var phi_2089_: f32;
    var phi_2090_: bool;
    var phi_2112_: u32;
    var phi_2139_: f32;
    var phi_2143_: f32;
    var phi_2144_: bool;
    var phi_2166_: u32;
    var phi_2193_: f32;
    var phi_2197_: f32;
    var phi_2198_: bool;
    var phi_2220_: u32;
    var phi_2299_: bool;
    var phi_2314_: bool;
    var phi_2275_: vec2<f32>;
    var phi_2331_: u32;
    var phi_2332_: u32;
    var phi_2333_: u32;
    var phi_2334_: u32;
    var phi_2357_: u32;
    var phi_2358_: u32;
    var phi_2361_: u32;
    var phi_2362_: u32;
    var phi_2366_: u32;
    var phi_2367_: u32;
    var phi_2368_: u32;
    var phi_2369_: u32;
    var local: u32;
    var phi_767_: u32;
    var phi_770_: vec3<f32>;
    var phi_772_: f32;
    var phi_943_: u32;
    var phi_946_: f32;
    var phi_948_: f32;
    var phi_1002_: f32;
    var phi_1047_: f32;
    var phi_1049_: f32;
    var phi_1050_: bool;
    var phi_1073_: f32;
    var phi_1075_: f32;
    var phi_1076_: bool;
    var phi_1109_: u32;
    var phi_1125_: u32;
    var phi_1128_: u32;
    var phi_1126_: u32;
    var phi_1129_: u32;
    var phi_1173_: u32;
    var phi_1192_: u32;
    var local_1: u32;
    var phi_1231_: u32;
    var phi_1247_: u32;
    var phi_1250_: u32;
    var phi_1248_: u32;
    var phi_1251_: u32;
    var phi_1295_: u32;
    var phi_1314_: u32;
    var local_2: u32;
    var phi_1392_: f32;
    var phi_1452_: f32;
    var phi_2403_: bool;
    var phi_2418_: bool;
    var phi_944_: u32;
    var phi_947_: f32;
    var phi_949_: f32;
    var local_3: f32;
    var local_4: f32;
    var local_5: f32;
    var local_6: f32;
    var phi_1671_: vec3<f32>;
    var phi_768_: u32;
    var phi_771_: vec3<f32>;
    var phi_773_: f32;
    var local_7: f32;
    var local_8: vec3<f32>;
    var phi_1677_: type_23;
    var phi_2445_: bool;
    var phi_1732_: vec3<f32>;
    var phi_1753_: u32;
    var phi_1798_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e84 = id_1;
            let _e96 = params.member.member.member[0u];
            let _e101 = select(select(u32(_e96), 0u, (_e96 < 0f)), 4294967295u, (_e96 > 4294967000f));
            let _e106 = params.member.member.member[1u];
            let _e111 = select(select(u32(_e106), 0u, (_e106 < 0f)), 4294967295u, (_e106 > 4294967000f));
            if (_e84.x >= _e101) {
            } else {
                if (_e84.y >= _e111) {
                } else {
                    let _e117 = ((_e84.y * _e101) + _e84.x);
                    let _e119 = mips.member[_e117];
                    let _e120 = bitcast<i32>(_e84.x);
                    let _e121 = (_e120 + -1i);
                    let _e123 = select(0i, _e121, (0i < _e121));
                    let _e125 = (bitcast<i32>(_e101) - 1i);
                    let _e129 = bitcast<i32>(_e84.y);
                    let _e131 = select(0i, _e129, (0i < _e129));
                    let _e133 = (bitcast<i32>(_e111) - 1i);
                    let _e137 = (bitcast<u32>(select(_e131, _e133, (_e133 < _e131))) * _e101);
                    let _e140 = mips.member[(_e137 + bitcast<u32>(select(_e123, _e125, (_e125 < _e123))))];
                    let _e141 = (_e120 + 1i);
                    let _e143 = select(0i, _e141, (0i < _e141));
                    let _e149 = mips.member[(_e137 + bitcast<u32>(select(_e143, _e125, (_e125 < _e143))))];
                    let _e151 = select(0i, _e120, (0i < _e120));
                    let _e154 = bitcast<u32>(select(_e151, _e125, (_e125 < _e151)));
                    let _e155 = (_e129 + -1i);
                    let _e157 = select(0i, _e155, (0i < _e155));
                    let _e164 = mips.member[((bitcast<u32>(select(_e157, _e133, (_e133 < _e157))) * _e101) + _e154)];
                    let _e165 = (_e129 + 1i);
                    let _e167 = select(0i, _e165, (0i < _e165));
                    let _e174 = mips.member[((bitcast<u32>(select(_e167, _e133, (_e133 < _e167))) * _e101) + _e154)];
                    let _e175 = (_e140 - _e119);
                    let _e176 = (_e149 - _e119);
                    let _e177 = (_e164 - _e119);
                    let _e178 = (_e174 - _e119);
                    let _e180 = ((_e176 - _e175) * 0.5f);
                    let _e182 = ((_e178 - _e177) * 0.5f);
                    let _e183 = (_e119 * 0.011f);
                    let _e185 = abs(_e175);
                    let _e186 = abs((_e175 + _e180));
                    if (_e185 != _e185) {
                        phi_1955_ = true;
                    } else {
                        phi_1955_ = (_e186 <= _e185);
                    }
                    let _e190 = phi_1955_;
                    let _e193 = (1.25f - (select(_e185, _e186, _e190) / _e183));
                    let _e197 = select(0f, select(1f, _e193, (_e193 < 1f)), (_e193 > 0f));
                    let _e199 = abs(_e176);
                    let _e200 = abs((_e176 - _e180));
                    if (_e199 != _e199) {
                        phi_1970_ = true;
                    } else {
                        phi_1970_ = (_e200 <= _e199);
                    }
                    let _e204 = phi_1970_;
                    let _e207 = (1.25f - (select(_e199, _e200, _e204) / _e183));
                    let _e211 = select(0f, select(1f, _e207, (_e207 < 1f)), (_e207 > 0f));
                    let _e213 = abs(_e177);
                    let _e214 = abs((_e177 + _e182));
                    if (_e213 != _e213) {
                        phi_1985_ = true;
                    } else {
                        phi_1985_ = (_e214 <= _e213);
                    }
                    let _e218 = phi_1985_;
                    let _e221 = (1.25f - (select(_e213, _e214, _e218) / _e183));
                    let _e225 = select(0f, select(1f, _e221, (_e221 < 1f)), (_e221 > 0f));
                    let _e227 = abs(_e178);
                    let _e228 = abs((_e178 - _e182));
                    if (_e227 != _e227) {
                        phi_2000_ = true;
                    } else {
                        phi_2000_ = (_e228 <= _e227);
                    }
                    let _e232 = phi_2000_;
                    let _e235 = (1.25f - (select(_e227, _e228, _e232) / _e183));
                    let _e239 = select(0f, select(1f, _e235, (_e235 < 1f)), (_e235 > 0f));
                    let _e244 = (select(0f, select(1f, _e197, (_e197 < 1f)), (_e197 > 0f)) * 2.9f);
                    let _e246 = floor((_e244 + 0.5f));
                    if ((_e246 - _e244) == 0.5f) {
                        let _e252 = ((floor((_e246 * 0.5f)) * 2f) != _e246);
                        if _e252 {
                            phi_2031_ = (_e246 - 1f);
                        } else {
                            phi_2031_ = f32();
                        }
                        let _e255 = phi_2031_;
                        phi_2035_ = _e255;
                        phi_2036_ = select(true, false, _e252);
                    } else {
                        phi_2035_ = f32();
                        phi_2036_ = true;
                    }
                    let _e258 = phi_2035_;
                    let _e260 = phi_2036_;
                    let _e261 = select(_e258, _e246, _e260);
                    if (_e261 > 0f) {
                        let _e267 = select(select(u32(_e261), 0u, (_e261 < 0f)), 4294967295u, (_e261 > 4294967000f));
                        phi_2058_ = select(_e267, 3u, (3u < _e267));
                    } else {
                        phi_2058_ = 0u;
                    }
                    let _e271 = phi_2058_;
                    let _e277 = (select(0f, select(1f, _e211, (_e211 < 1f)), (_e211 > 0f)) * 2.9f);
                    let _e279 = floor((_e277 + 0.5f));
                    if ((_e279 - _e277) == 0.5f) {
                        let _e285 = ((floor((_e279 * 0.5f)) * 2f) != _e279);
                        if _e285 {
                            phi_2085_ = (_e279 - 1f);
                        } else {
                            phi_2085_ = f32();
                        }
                        let _e288 = phi_2085_;
                        phi_2089_ = _e288;
                        phi_2090_ = select(true, false, _e285);
                    } else {
                        phi_2089_ = f32();
                        phi_2090_ = true;
                    }
                    let _e291 = phi_2089_;
                    let _e293 = phi_2090_;
                    let _e294 = select(_e291, _e279, _e293);
                    if (_e294 > 0f) {
                        let _e300 = select(select(u32(_e294), 0u, (_e294 < 0f)), 4294967295u, (_e294 > 4294967000f));
                        phi_2112_ = select(_e300, 3u, (3u < _e300));
                    } else {
                        phi_2112_ = 0u;
                    }
                    let _e304 = phi_2112_;
                    let _e311 = (select(0f, select(1f, _e225, (_e225 < 1f)), (_e225 > 0f)) * 2.9f);
                    let _e313 = floor((_e311 + 0.5f));
                    if ((_e313 - _e311) == 0.5f) {
                        let _e319 = ((floor((_e313 * 0.5f)) * 2f) != _e313);
                        if _e319 {
                            phi_2139_ = (_e313 - 1f);
                        } else {
                            phi_2139_ = f32();
                        }
                        let _e322 = phi_2139_;
                        phi_2143_ = _e322;
                        phi_2144_ = select(true, false, _e319);
                    } else {
                        phi_2143_ = f32();
                        phi_2144_ = true;
                    }
                    let _e325 = phi_2143_;
                    let _e327 = phi_2144_;
                    let _e328 = select(_e325, _e313, _e327);
                    if (_e328 > 0f) {
                        let _e334 = select(select(u32(_e328), 0u, (_e328 < 0f)), 4294967295u, (_e328 > 4294967000f));
                        phi_2166_ = select(_e334, 3u, (3u < _e334));
                    } else {
                        phi_2166_ = 0u;
                    }
                    let _e338 = phi_2166_;
                    let _e345 = (select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f)) * 2.9f);
                    let _e347 = floor((_e345 + 0.5f));
                    if ((_e347 - _e345) == 0.5f) {
                        let _e353 = ((floor((_e347 * 0.5f)) * 2f) != _e347);
                        if _e353 {
                            phi_2193_ = (_e347 - 1f);
                        } else {
                            phi_2193_ = f32();
                        }
                        let _e356 = phi_2193_;
                        phi_2197_ = _e356;
                        phi_2198_ = select(true, false, _e353);
                    } else {
                        phi_2197_ = f32();
                        phi_2198_ = true;
                    }
                    let _e359 = phi_2197_;
                    let _e361 = phi_2198_;
                    let _e362 = select(_e359, _e347, _e361);
                    if (_e362 > 0f) {
                        let _e368 = select(select(u32(_e362), 0u, (_e362 < 0f)), 4294967295u, (_e362 > 4294967000f));
                        phi_2220_ = select(_e368, 3u, (3u < _e368));
                    } else {
                        phi_2220_ = 0u;
                    }
                    let _e372 = phi_2220_;
                    let _e376 = ((f32(_e84.x) + 0.5f) / _e96);
                    let _e379 = ((f32(_e84.y) + 0.5f) / _e106);
                    let _e380 = (_e119 * 0.99999f);
                    let _e387 = params.member.member.member_1[0u];
                    let _e389 = ((((_e376 * 2f) - 1f) * _e387) * _e380);
                    let _e396 = params.member.member.member_1[1u];
                    let _e398 = ((((_e379 * -2f) + 1f) * _e396) * _e380);
                    let _e399 = -(_e389);
                    let _e400 = -(_e398);
                    let _e401 = (_e119 * -0.99999f);
                    let _e408 = (1f / sqrt((((_e399 * _e399) + (_e400 * _e400)) + (_e401 * _e401))));
                    let _e409 = (_e399 * _e408);
                    let _e410 = (_e400 * _e408);
                    let _e411 = (_e401 * _e408);
                    if (_e117 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e415 = normals.member[_e117];
                    let _e423 = (f32((bitcast<i32>(((_e415 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e423 != _e423) {
                        phi_2299_ = true;
                    } else {
                        phi_2299_ = (-1f >= _e423);
                    }
                    let _e427 = phi_2299_;
                    let _e428 = select(_e423, -1f, _e427);
                    let _e438 = (f32((bitcast<i32>((((_e415 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e438 != _e438) {
                        phi_2314_ = true;
                    } else {
                        phi_2314_ = (-1f >= _e438);
                    }
                    let _e442 = phi_2314_;
                    let _e443 = select(_e438, -1f, _e442);
                    let _e446 = (1f - abs(_e428));
                    let _e447 = abs(_e443);
                    let _e448 = (_e446 - _e447);
                    if (_e448 < 0f) {
                        phi_2275_ = vec2<f32>(((1f - _e447) * select(1f, -1f, (_e428 < 0f))), (_e446 * select(1f, -1f, (_e443 < 0f))));
                    } else {
                        phi_2275_ = vec2<f32>(_e428, _e443);
                    }
                    let _e459 = phi_2275_;
                    let _e468 = (1f / sqrt((((_e459.x * _e459.x) + (_e459.y * _e459.y)) + (_e448 * _e448))));
                    let _e469 = (_e459.x * _e468);
                    let _e470 = (_e459.y * _e468);
                    let _e471 = (_e448 * _e468);
                    let _e472 = -(_e471);
                    let _e478 = ((((_e469 * _e409) + (_e470 * _e410)) + (_e472 * _e411)) < 0f);
                    let _e481 = select(_e469, -(_e469), _e478);
                    let _e482 = select(_e470, -(_e470), _e478);
                    let _e483 = select(_e472, _e471, _e478);
                    let _e487 = params.member.member_1;
                    let _e490 = params.member.member_2;
                    let _e491 = (_e487 * _e490);
                    let _e495 = (_e491 / (((_e119 * 1.99998f) * _e387) / _e96));
                    let _e499 = params.member.member_11;
                    phi_2331_ = (_e84.y & 63u);
                    phi_2332_ = (_e84.x & 63u);
                    phi_2333_ = 32u;
                    phi_2334_ = 0u;
                    loop {
                        let _e503 = phi_2331_;
                        let _e505 = phi_2332_;
                        let _e507 = phi_2333_;
                        let _e509 = phi_2334_;
                        local = _e509;
                        let _e510 = (_e507 > 0u);
                        if _e510 {
                            let _e513 = select(0u, 1u, ((_e505 & _e507) != 0u));
                            let _e516 = select(0u, 1u, ((_e503 & _e507) != 0u));
                            if (_e516 == 0u) {
                                if (_e513 == 1u) {
                                    phi_2357_ = (63u - _e503);
                                    phi_2358_ = (63u - _e505);
                                } else {
                                    phi_2357_ = _e503;
                                    phi_2358_ = _e505;
                                }
                                let _e527 = phi_2357_;
                                let _e529 = phi_2358_;
                                phi_2361_ = _e529;
                                phi_2362_ = _e527;
                            } else {
                                phi_2361_ = _e503;
                                phi_2362_ = _e505;
                            }
                            let _e531 = phi_2361_;
                            let _e533 = phi_2362_;
                            phi_2366_ = _e531;
                            phi_2367_ = _e533;
                            phi_2368_ = (_e507 / 2u);
                            phi_2369_ = (_e509 + ((_e507 * _e507) * ((3u * _e513) ^ _e516)));
                        } else {
                            phi_2366_ = u32();
                            phi_2367_ = u32();
                            phi_2368_ = u32();
                            phi_2369_ = u32();
                        }
                        let _e536 = phi_2366_;
                        let _e538 = phi_2367_;
                        let _e540 = phi_2368_;
                        let _e542 = phi_2369_;
                        continue;
                        continuing {
                            phi_2331_ = _e536;
                            phi_2332_ = _e538;
                            phi_2333_ = _e540;
                            phi_2334_ = _e542;
                            break if !(_e510);
                        }
                    }
                    let _e547 = local;
                    let _e549 = f32((_e547 + (288u * (_e499 % 64u))));
                    let _e551 = (0.5f + (_e549 * 0.7548777f));
                    let _e555 = (0.5f + (_e549 * 0.5698403f));
                    let _e561 = params.member.member.member_3;
                    let _e564 = select(false, (_e119 < _e561), (_e119 > 0f));
                    if _e564 {
                        let _e567 = params.member.member_3;
                        let _e568 = (_e567 * _e491);
                        let _e570 = ((10f - _e495) * 0.01f);
                        let _e578 = params.member.member_8;
                        let _e580 = select(1u, _e578, (1u < _e578));
                        phi_767_ = 0u;
                        phi_770_ = vec3<f32>(0f, 0f, 0f);
                        phi_772_ = (select(0f, select(1f, _e570, (_e570 < 1f)), (_e570 > 0f)) * 0.5f);
                        loop {
                            let _e582 = phi_767_;
                            let _e584 = phi_770_;
                            let _e586 = phi_772_;
                            local_7 = _e586;
                            local_8 = _e584;
                            let _e587 = (_e582 < _e580);
                            if _e587 {
                                let _e592 = ((((_e551 - floor(_e551)) + f32(_e582)) * 3.1415927f) / f32(_e580));
                                let _e593 = sin(_e592);
                                let _e594 = cos(_e592);
                                let _e600 = ((_e594 * _e409) + (_e593 * _e410));
                                let _e604 = (_e594 - (_e409 * _e600));
                                let _e605 = (_e593 - (_e410 * _e600));
                                let _e606 = -((_e411 * _e600));
                                let _e609 = ((_e605 * _e411) - (_e410 * _e606));
                                let _e612 = ((_e606 * _e409) - (_e411 * _e604));
                                let _e615 = ((_e604 * _e410) - (_e409 * _e605));
                                let _e622 = (1f / sqrt((((_e609 * _e609) + (_e612 * _e612)) + (_e615 * _e615))));
                                let _e623 = (_e609 * _e622);
                                let _e624 = (_e612 * _e622);
                                let _e625 = (_e615 * _e622);
                                let _e630 = (((_e481 * _e623) + (_e482 * _e624)) + (_e483 * _e625));
                                let _e634 = (_e481 - (_e623 * _e630));
                                let _e635 = (_e482 - (_e624 * _e630));
                                let _e636 = (_e483 - (_e625 * _e630));
                                let _e642 = sqrt((((_e634 * _e634) + (_e635 * _e635)) + (_e636 * _e636)));
                                let _e647 = (((_e604 * _e634) + (_e605 * _e635)) + (_e606 * _e636));
                                let _e657 = ((((_e634 * _e409) + (_e635 * _e410)) + (_e636 * _e411)) / _e642);
                                let _e661 = select(0f, select(1f, _e657, (_e657 < 1f)), (_e657 > 0f));
                                let _e662 = abs(_e661);
                                let _e673 = (((_e662 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e662))) >> bitcast<u32>(1i))))));
                                let _e677 = (select(select(0f, -1f, (_e647 < 0f)), 1f, (_e647 > 0f)) * select((3.141593f - _e673), _e673, (_e661 >= 0f)));
                                let _e680 = params.member.member_9;
                                let _e682 = select(1u, _e680, (1u < _e680));
                                let _e684 = cos((_e677 + 1.5707964f));
                                let _e686 = cos((_e677 - 1.5707964f));
                                let _e689 = params.member.member_5;
                                phi_943_ = 0u;
                                phi_946_ = _e686;
                                phi_948_ = _e684;
                                loop {
                                    let _e691 = phi_943_;
                                    let _e693 = phi_946_;
                                    let _e695 = phi_948_;
                                    local_3 = _e693;
                                    local_4 = _e693;
                                    local_5 = _e695;
                                    local_6 = _e695;
                                    let _e696 = (_e691 < _e682);
                                    if _e696 {
                                        let _e701 = ((_e555 - floor(_e555)) + (f32((_e582 + (_e691 * _e682))) * 0.618034f));
                                        let _e707 = (((_e701 - floor(_e701)) + f32(_e691)) / f32(_e682));
                                        let _e710 = params.member.member_4;
                                        if (_e710 == 2f) {
                                            phi_1002_ = (_e707 * _e707);
                                        } else {
                                            phi_1002_ = pow(_e707, _e710);
                                        }
                                        let _e715 = phi_1002_;
                                        let _e716 = (_e715 + (1.3f / _e495));
                                        let _e717 = ((_e594 * _e495) * _e716);
                                        let _e718 = ((-(_e593) * _e495) * _e716);
                                        let _e726 = params.member.member_7;
                                        let _e727 = (log2(sqrt(((_e717 * _e717) + (_e718 * _e718)))) - _e726);
                                        let _e734 = (-1f - floor((-0.5f - select(0f, select(5f, _e727, (_e727 < 5f)), (_e727 > 0f)))));
                                        let _e736 = floor((_e717 + 0.5f));
                                        if ((_e736 - _e717) == 0.5f) {
                                            let _e742 = ((floor((_e736 * 0.5f)) * 2f) != _e736);
                                            if _e742 {
                                                phi_1047_ = (_e736 - 1f);
                                            } else {
                                                phi_1047_ = f32();
                                            }
                                            let _e745 = phi_1047_;
                                            phi_1049_ = _e745;
                                            phi_1050_ = select(true, false, _e742);
                                        } else {
                                            phi_1049_ = f32();
                                            phi_1050_ = true;
                                        }
                                        let _e748 = phi_1049_;
                                        let _e750 = phi_1050_;
                                        let _e752 = (select(_e748, _e736, _e750) / _e96);
                                        let _e754 = floor((_e718 + 0.5f));
                                        if ((_e754 - _e718) == 0.5f) {
                                            let _e760 = ((floor((_e754 * 0.5f)) * 2f) != _e754);
                                            if _e760 {
                                                phi_1073_ = (_e754 - 1f);
                                            } else {
                                                phi_1073_ = f32();
                                            }
                                            let _e763 = phi_1073_;
                                            phi_1075_ = _e763;
                                            phi_1076_ = select(true, false, _e760);
                                        } else {
                                            phi_1075_ = f32();
                                            phi_1076_ = true;
                                        }
                                        let _e766 = phi_1075_;
                                        let _e768 = phi_1076_;
                                        let _e770 = (select(_e766, _e754, _e768) / _e106);
                                        let _e771 = (_e376 + _e752);
                                        let _e772 = (_e379 + _e770);
                                        let _e773 = (_e376 - _e752);
                                        let _e774 = (_e379 - _e770);
                                        let _e775 = (_e734 > 0f);
                                        if _e775 {
                                            let _e780 = select(select(u32(_e734), 0u, (_e734 < 0f)), 4294967295u, (_e734 > 4294967000f));
                                            phi_1109_ = select(_e780, 4u, (4u < _e780));
                                        } else {
                                            phi_1109_ = 0u;
                                        }
                                        let _e784 = phi_1109_;
                                        let _e785 = (_e784 & 31u);
                                        let _e787 = (_e101 >> bitcast<u32>(_e785));
                                        let _e789 = select(1u, _e787, (1u < _e787));
                                        let _e791 = (_e111 >> bitcast<u32>(_e785));
                                        let _e793 = select(1u, _e791, (1u < _e791));
                                        phi_1125_ = 0u;
                                        phi_1128_ = 0u;
                                        loop {
                                            let _e795 = phi_1125_;
                                            let _e797 = phi_1128_;
                                            local_1 = _e797;
                                            let _e798 = (_e795 < _e784);
                                            if _e798 {
                                                let _e799 = (_e795 & 31u);
                                                let _e801 = (_e101 >> bitcast<u32>(_e799));
                                                let _e805 = (_e111 >> bitcast<u32>(_e799));
                                                phi_1126_ = (_e795 + 1u);
                                                phi_1129_ = (_e797 + (select(1u, _e801, (1u < _e801)) * select(1u, _e805, (1u < _e805))));
                                            } else {
                                                phi_1126_ = u32();
                                                phi_1129_ = u32();
                                            }
                                            let _e812 = phi_1126_;
                                            let _e814 = phi_1129_;
                                            continue;
                                            continuing {
                                                phi_1125_ = _e812;
                                                phi_1128_ = _e814;
                                                break if !(_e798);
                                            }
                                        }
                                        let _e818 = (_e771 * f32(_e789));
                                        if (_e818 > 0f) {
                                            let _e824 = select(select(u32(_e818), 0u, (_e818 < 0f)), 4294967295u, (_e818 > 4294967000f));
                                            let _e825 = (_e789 - 1u);
                                            phi_1173_ = select(_e824, _e825, (_e825 < _e824));
                                        } else {
                                            phi_1173_ = 0u;
                                        }
                                        let _e829 = phi_1173_;
                                        let _e830 = (_e772 * f32(_e793));
                                        if (_e830 > 0f) {
                                            let _e836 = select(select(u32(_e830), 0u, (_e830 < 0f)), 4294967295u, (_e830 > 4294967000f));
                                            let _e837 = (_e793 - 1u);
                                            phi_1192_ = select(_e836, _e837, (_e837 < _e836));
                                        } else {
                                            phi_1192_ = 0u;
                                        }
                                        let _e841 = phi_1192_;
                                        let _e844 = local_1;
                                        let _e849 = mips.member[((_e844 + (_e841 * _e789)) + _e829)];
                                        if _e775 {
                                            let _e862 = select(select(u32(_e734), 0u, (_e734 < 0f)), 4294967295u, (_e734 > 4294967000f));
                                            phi_1231_ = select(_e862, 4u, (4u < _e862));
                                        } else {
                                            phi_1231_ = 0u;
                                        }
                                        let _e866 = phi_1231_;
                                        let _e867 = (_e866 & 31u);
                                        let _e869 = (_e101 >> bitcast<u32>(_e867));
                                        let _e871 = select(1u, _e869, (1u < _e869));
                                        let _e873 = (_e111 >> bitcast<u32>(_e867));
                                        let _e875 = select(1u, _e873, (1u < _e873));
                                        phi_1247_ = 0u;
                                        phi_1250_ = 0u;
                                        loop {
                                            let _e877 = phi_1247_;
                                            let _e879 = phi_1250_;
                                            local_2 = _e879;
                                            let _e880 = (_e877 < _e866);
                                            if _e880 {
                                                let _e881 = (_e877 & 31u);
                                                let _e883 = (_e101 >> bitcast<u32>(_e881));
                                                let _e887 = (_e111 >> bitcast<u32>(_e881));
                                                phi_1248_ = (_e877 + 1u);
                                                phi_1251_ = (_e879 + (select(1u, _e883, (1u < _e883)) * select(1u, _e887, (1u < _e887))));
                                            } else {
                                                phi_1248_ = u32();
                                                phi_1251_ = u32();
                                            }
                                            let _e894 = phi_1248_;
                                            let _e896 = phi_1251_;
                                            continue;
                                            continuing {
                                                phi_1247_ = _e894;
                                                phi_1250_ = _e896;
                                                break if !(_e880);
                                            }
                                        }
                                        let _e900 = (_e773 * f32(_e871));
                                        if (_e900 > 0f) {
                                            let _e906 = select(select(u32(_e900), 0u, (_e900 < 0f)), 4294967295u, (_e900 > 4294967000f));
                                            let _e907 = (_e871 - 1u);
                                            phi_1295_ = select(_e906, _e907, (_e907 < _e906));
                                        } else {
                                            phi_1295_ = 0u;
                                        }
                                        let _e911 = phi_1295_;
                                        let _e912 = (_e774 * f32(_e875));
                                        if (_e912 > 0f) {
                                            let _e918 = select(select(u32(_e912), 0u, (_e912 < 0f)), 4294967295u, (_e912 > 4294967000f));
                                            let _e919 = (_e875 - 1u);
                                            phi_1314_ = select(_e918, _e919, (_e919 < _e918));
                                        } else {
                                            phi_1314_ = 0u;
                                        }
                                        let _e923 = phi_1314_;
                                        let _e926 = local_2;
                                        let _e931 = mips.member[((_e926 + (_e923 * _e871)) + _e911)];
                                        let _e940 = (((((_e771 * 2f) - 1f) * _e387) * _e849) - _e389);
                                        let _e941 = (((((_e772 * -2f) + 1f) * _e396) * _e849) - _e398);
                                        let _e942 = (_e849 - _e380);
                                        let _e945 = ((_e940 * _e940) + (_e941 * _e941));
                                        let _e948 = sqrt((_e945 + (_e942 * _e942)));
                                        let _e957 = (1f + _e689);
                                        let _e958 = (_e942 * _e957);
                                        let _e961 = sqrt((_e945 + (_e958 * _e958)));
                                        let _e962 = (_e568 > 0f);
                                        if _e962 {
                                            let _e965 = ((-(_e961) + _e491) / _e568);
                                            phi_1392_ = select(0f, select(1f, _e965, (_e965 < 1f)), (_e965 > 0f));
                                        } else {
                                            phi_1392_ = select(0f, 1f, (_e961 <= _e491));
                                        }
                                        let _e973 = phi_1392_;
                                        let _e976 = (_e684 + ((((((_e940 / _e948) * _e409) + ((_e941 / _e948) * _e410)) + ((_e942 / _e948) * _e411)) - _e684) * _e973));
                                        let _e977 = (((((_e773 * 2f) - 1f) * _e387) * _e931) - _e389);
                                        let _e978 = (((((_e774 * -2f) + 1f) * _e396) * _e931) - _e398);
                                        let _e979 = (_e931 - _e380);
                                        let _e982 = ((_e977 * _e977) + (_e978 * _e978));
                                        let _e985 = sqrt((_e982 + (_e979 * _e979)));
                                        let _e994 = (_e979 * _e957);
                                        let _e997 = sqrt((_e982 + (_e994 * _e994)));
                                        if _e962 {
                                            let _e1000 = ((-(_e997) + _e491) / _e568);
                                            phi_1452_ = select(0f, select(1f, _e1000, (_e1000 < 1f)), (_e1000 > 0f));
                                        } else {
                                            phi_1452_ = select(0f, 1f, (_e997 <= _e491));
                                        }
                                        let _e1008 = phi_1452_;
                                        let _e1011 = (_e686 + ((((((_e977 / _e985) * _e409) + ((_e978 / _e985) * _e410)) + ((_e979 / _e985) * _e411)) - _e686) * _e1008));
                                        if (_e695 != _e695) {
                                            phi_2403_ = true;
                                        } else {
                                            phi_2403_ = (_e976 >= _e695);
                                        }
                                        let _e1015 = phi_2403_;
                                        if (_e693 != _e693) {
                                            phi_2418_ = true;
                                        } else {
                                            phi_2418_ = (_e1011 >= _e693);
                                        }
                                        let _e1020 = phi_2418_;
                                        phi_944_ = (_e691 + 1u);
                                        phi_947_ = select(_e693, _e1011, _e1020);
                                        phi_949_ = select(_e695, _e976, _e1015);
                                    } else {
                                        phi_944_ = u32();
                                        phi_947_ = f32();
                                        phi_949_ = f32();
                                    }
                                    let _e1024 = phi_944_;
                                    let _e1026 = phi_947_;
                                    let _e1028 = phi_949_;
                                    continue;
                                    continuing {
                                        phi_943_ = _e1024;
                                        phi_946_ = _e1026;
                                        phi_948_ = _e1028;
                                        break if !(_e696);
                                    }
                                }
                                let _e1031 = local_3;
                                let _e1032 = abs(_e1031);
                                let _e1043 = (((_e1032 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1032))) >> bitcast<u32>(1i))))));
                                let _e1045 = local_4;
                                let _e1048 = select((3.141593f - _e1043), _e1043, (_e1045 >= 0f));
                                let _e1049 = -(_e1048);
                                let _e1051 = local_5;
                                let _e1052 = abs(_e1051);
                                let _e1063 = (((_e1052 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e1052))) >> bitcast<u32>(1i))))));
                                let _e1065 = local_6;
                                let _e1068 = select((3.141593f - _e1063), _e1063, (_e1065 >= 0f));
                                let _e1071 = (_e642 + ((1f - _e642) * 0.05f));
                                let _e1072 = (_e1048 * -2f);
                                let _e1073 = sin(_e677);
                                let _e1079 = (_e1068 * 2f);
                                let _e1091 = params.member.member_13;
                                if (_e1091 == 0u) {
                                    phi_1671_ = _e584;
                                } else {
                                    let _e1097 = ((_e1048 * -3f) - _e677);
                                    let _e1105 = ((_e1068 * 3f) - _e677);
                                    let _e1110 = (_e1049 + _e677);
                                    let _e1112 = (_e1068 + _e677);
                                    let _e1117 = (((((((sin((_e1049 - _e677)) * 6f) - sin(_e1097)) + (sin((_e1068 - _e677)) * 6f)) - sin(_e1105)) + (_e1073 * 16f)) - ((sin(_e1110) + sin(_e1112)) * 3f)) * 0.083333336f);
                                    let _e1129 = (((-(cos(_e1097)) - cos(_e1105)) + (cos(_e677) * 8f)) - ((cos(_e1110) + cos(_e1112)) * 3f));
                                    let _e1130 = (_e594 * _e1117);
                                    let _e1131 = (_e593 * _e1117);
                                    let _e1132 = (_e1129 * -0.083333336f);
                                    let _e1133 = (-1f * _e411);
                                    let _e1134 = (-1f * _e409);
                                    let _e1136 = (1f / (_e1133 + 1f));
                                    let _e1137 = (_e1136 * _e410);
                                    let _e1141 = (_e1137 * _e1134);
                                    let _e1162 = (_e1133 > 0.9997f);
                                    let _e1163 = (_e1133 < -0.9997f);
                                    phi_1671_ = (_e584 + vec3<f32>((select(select(((((_e1133 + (_e1137 * _e410)) * _e1130) + (_e1141 * _e1131)) + (_e1134 * _e1132)), _e1130, _e1163), _e1130, _e1162) * _e1071), (select(select((((_e1141 * _e1130) + ((_e1133 + ((_e1136 * _e1134) * _e1134)) * _e1131)) + (-(_e410) * _e1132)), -(_e1131), _e1163), _e1131, _e1162) * _e1071), (select(select((((_e409 * _e1130) + (_e410 * _e1131)) + (_e1133 * _e1132)), (_e1129 * 0.083333336f), _e1163), _e1132, _e1162) * _e1071)));
                                }
                                let _e1176 = phi_1671_;
                                phi_768_ = (_e582 + 1u);
                                phi_771_ = _e1176;
                                phi_773_ = (_e586 + ((0.25f * (((_e661 + (_e1072 * _e1073)) - cos((_e1072 - _e677))) + ((_e661 + (_e1079 * _e1073)) - cos((_e1079 - _e677))))) * _e1071));
                            } else {
                                phi_768_ = u32();
                                phi_771_ = vec3<f32>();
                                phi_773_ = f32();
                            }
                            let _e1179 = phi_768_;
                            let _e1181 = phi_771_;
                            let _e1183 = phi_773_;
                            continue;
                            continuing {
                                phi_767_ = _e1179;
                                phi_770_ = _e1181;
                                phi_772_ = _e1183;
                                break if !(_e587);
                            }
                        }
                        let _e1187 = local_7;
                        let _e1190 = local_8;
                        phi_1677_ = type_23((_e1187 / f32(_e580)), _e1190);
                    } else {
                        phi_1677_ = type_23(1f, vec3<f32>(0f, 0f, 0f));
                    }
                    let _e1193 = phi_1677_;
                    if _e564 {
                        let _e1198 = params.member.member_6;
                        let _e1199 = pow(_e1193.member, _e1198);
                        if (_e1199 != _e1199) {
                            phi_2445_ = true;
                        } else {
                            phi_2445_ = (0.03f >= _e1199);
                        }
                        let _e1203 = phi_2445_;
                        let _e1204 = select(_e1199, 0.03f, _e1203);
                        let _e1207 = params.member.member_13;
                        if (_e1207 == 0u) {
                            let _e1209 = (_e1204 * 0.6666667f);
                            let _e1215 = ((select(0f, select(1f, _e1209, (_e1209 < 1f)), (_e1209 > 0f)) * 255f) + 0.5f);
                            phi_1753_ = select(select(u32(_e1215), 0u, (_e1215 < 0f)), 4294967295u, (_e1215 > 4294967000f));
                        } else {
                            let _e1229 = sqrt((((_e1193.member_1.x * _e1193.member_1.x) + (_e1193.member_1.y * _e1193.member_1.y)) + (_e1193.member_1.z * _e1193.member_1.z)));
                            if (_e1229 > 0f) {
                                phi_1732_ = (_e1193.member_1 / vec3(_e1229));
                            } else {
                                phi_1732_ = vec3<f32>(_e481, _e482, _e483);
                            }
                            let _e1234 = phi_1732_;
                            let _e1235 = (_e1204 * 0.6666667f);
                            let _e1242 = ((_e1234.x * 0.5f) + 0.5f);
                            let _e1243 = ((_e1234.y * 0.5f) + 0.5f);
                            let _e1244 = ((_e1234.z * 0.5f) + 0.5f);
                            let _e1250 = ((select(0f, select(1f, _e1242, (_e1242 < 1f)), (_e1242 > 0f)) * 255f) + 0.5f);
                            let _e1261 = ((select(0f, select(1f, _e1243, (_e1243 < 1f)), (_e1243 > 0f)) * 255f) + 0.5f);
                            let _e1275 = ((select(0f, select(1f, _e1244, (_e1244 < 1f)), (_e1244 > 0f)) * 255f) + 0.5f);
                            let _e1289 = ((select(0f, select(1f, _e1235, (_e1235 < 1f)), (_e1235 > 0f)) * 255f) + 0.5f);
                            phi_1753_ = (((select(select(u32(_e1250), 0u, (_e1250 < 0f)), 4294967295u, (_e1250 > 4294967000f)) | (select(select(u32(_e1261), 0u, (_e1261 < 0f)), 4294967295u, (_e1261 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1275), 0u, (_e1275 < 0f)), 4294967295u, (_e1275 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1289), 0u, (_e1289 < 0f)), 4294967295u, (_e1289 > 4294967000f)) << bitcast<u32>(24i)));
                        }
                        let _e1299 = phi_1753_;
                        phi_1798_ = _e1299;
                    } else {
                        let _e1302 = params.member.member_13;
                        phi_1798_ = select(2852159616u, 170u, (_e1302 == 0u));
                    }
                    let _e1306 = phi_1798_;
                    if (_e117 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e117] = _e1306;
                    if (_e117 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e117] = ((((64u * _e271) + (16u * _e304)) + (4u * _e338)) + _e372);
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
