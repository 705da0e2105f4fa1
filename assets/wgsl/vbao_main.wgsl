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

struct type_21 {
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

struct type_22 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
}

struct type_23 {
    member: type_22,
}

struct type_25 {
    member: u32,
    member_1: f32,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(1) 
var<storage> normals: type_10;
@group(0) @binding(0) 
var<storage> mips: type_7;
@group(0) @binding(2) 
var<storage, read_write> terms: type_10;
@group(0) @binding(3) 
var<storage, read_write> edges: type_10;
@group(0) @binding(4) 
var<uniform> params: type_23;

fn function_() {
    var local: array<type_25, 4>;
    var phi_491_: i32;
    var phi_510_: i32;
    var phi_551_: i32;
    var phi_570_: i32;
    var phi_611_: i32;
    var phi_630_: i32;
    var phi_671_: i32;
    var phi_690_: i32;
    var phi_2614_: bool;
    var phi_2629_: bool;
    var phi_2644_: bool;
    var phi_2659_: bool;
    var phi_2690_: f32;
    var phi_2694_: f32;
    var phi_2695_: bool;
    var phi_2717_: u32;
    var phi_2744_: f32;
    var phi_2748_: f32;
    var phi_2749_: bool;
    var phi_2771_: u32;
    var phi_2798_: f32;
    var phi_2802_: f32;
    var phi_2803_: bool;
    var phi_2825_: u32;
    var phi_2852_: f32;
    var phi_2856_: f32;
    var phi_2857_: bool;
    var phi_2879_: u32;
    var phi_2958_: bool;
    var phi_2973_: bool;
    var phi_2934_: vec2<f32>;
    var phi_2990_: u32;
    var phi_2991_: u32;
    var phi_2992_: u32;
    var phi_2993_: u32;
    var phi_3016_: u32;
    var phi_3017_: u32;
    var phi_3020_: u32;
    var phi_3021_: u32;
    var phi_3025_: u32;
    var phi_3026_: u32;
    var phi_3027_: u32;
    var phi_3028_: u32;
    var local_1: u32;
    var phi_3375_: bool;
    var phi_942_: u32;
    var phi_945_: f32;
    var phi_947_: f32;
    var phi_1142_: u32;
    var phi_1145_: u32;
    var phi_1199_: f32;
    var phi_1244_: f32;
    var phi_1246_: f32;
    var phi_1247_: bool;
    var phi_1270_: f32;
    var phi_1272_: f32;
    var phi_1273_: bool;
    var phi_1306_: u32;
    var phi_1322_: u32;
    var phi_1325_: u32;
    var phi_1323_: u32;
    var phi_1326_: u32;
    var phi_1370_: u32;
    var phi_1389_: u32;
    var local_2: u32;
    var phi_1433_: u32;
    var phi_1449_: u32;
    var phi_1452_: u32;
    var phi_1450_: u32;
    var phi_1453_: u32;
    var phi_1497_: u32;
    var phi_1516_: u32;
    var local_3: u32;
    var phi_1565_: bool;
    var phi_3062_: bool;
    var phi_3077_: bool;
    var phi_3092_: bool;
    var phi_3107_: bool;
    var phi_3122_: bool;
    var phi_1886_: f32;
    var phi_1904_: u32;
    var phi_1922_: u32;
    var phi_1938_: u32;
    var phi_1941_: u32;
    var phi_1942_: u32;
    var phi_1943_: bool;
    var phi_1957_: u32;
    var phi_1981_: bool;
    var phi_3137_: bool;
    var phi_3152_: bool;
    var phi_3167_: bool;
    var phi_3182_: bool;
    var phi_3197_: bool;
    var phi_2302_: f32;
    var phi_2320_: u32;
    var phi_2338_: u32;
    var phi_2354_: u32;
    var phi_2357_: u32;
    var phi_2358_: u32;
    var phi_2359_: bool;
    var phi_2373_: u32;
    var phi_1143_: u32;
    var phi_1146_: u32;
    var phi_3256_: bool;
    var local_4: u32;
    var phi_2457_: u32;
    var phi_2460_: f32;
    var local_5: u32;
    var phi_2458_: u32;
    var phi_2461_: f32;
    var phi_3456_: bool;
    var local_6: f32;
    var phi_3467_: bool;
    var phi_2510_: f32;
    var phi_2511_: f32;
    var phi_2404_: u32;
    var phi_2407_: f32;
    var phi_2409_: f32;
    var local_7: u32;
    var phi_2405_: u32;
    var phi_2408_: f32;
    var phi_2410_: f32;
    var local_8: f32;
    var phi_3461_: bool;
    var phi_2512_: f32;
    var phi_2513_: f32;
    var phi_3460_: bool;
    var phi_943_: u32;
    var phi_946_: f32;
    var phi_948_: f32;
    var phi_3459_: bool;
    var local_9: f32;
    var local_10: f32;
    var local_11: f32;
    var phi_2521_: f32;
    var phi_3230_: bool;
    var phi_2570_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e92 = id_1;
            let _e95 = arrayLength((&mips.member));
            let _e107 = params.member.member_4.member.member[0u];
            let _e112 = select(select(u32(_e107), 0u, (_e107 < 0f)), 4294967295u, (_e107 > 4294967000f));
            let _e118 = params.member.member_4.member.member[1u];
            let _e123 = select(select(u32(_e118), 0u, (_e118 < 0f)), 4294967295u, (_e118 > 4294967000f));
            if (_e92.x >= _e112) {
            } else {
                if (_e92.y >= _e123) {
                } else {
                    let _e129 = ((_e92.y * _e112) + _e92.x);
                    if (_e129 < _e95) {
                    } else {
                        break;
                    }
                    let _e132 = mips.member[_e129];
                    let _e133 = bitcast<i32>(_e92.x);
                    let _e134 = (_e133 + -1i);
                    let _e136 = (bitcast<i32>(_e112) - 1i);
                    let _e137 = (0i <= _e136);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e134 < 0i) {
                        phi_491_ = 0i;
                    } else {
                        phi_491_ = select(_e134, _e136, (_e134 > _e136));
                    }
                    let _e142 = phi_491_;
                    let _e144 = bitcast<i32>(_e92.y);
                    let _e146 = (bitcast<i32>(_e123) - 1i);
                    let _e147 = (0i <= _e146);
                    if _e147 {
                    } else {
                        break;
                    }
                    let _e148 = (_e144 < 0i);
                    if _e148 {
                        phi_510_ = 0i;
                    } else {
                        phi_510_ = select(_e144, _e146, (_e144 > _e146));
                    }
                    let _e152 = phi_510_;
                    let _e155 = ((bitcast<u32>(_e152) * _e112) + bitcast<u32>(_e142));
                    if (_e155 < _e95) {
                    } else {
                        break;
                    }
                    let _e158 = mips.member[_e155];
                    let _e159 = (_e133 + 1i);
                    if _e137 {
                    } else {
                        break;
                    }
                    if (_e159 < 0i) {
                        phi_551_ = 0i;
                    } else {
                        phi_551_ = select(_e159, _e136, (_e159 > _e136));
                    }
                    let _e164 = phi_551_;
                    if _e147 {
                    } else {
                        break;
                    }
                    if _e148 {
                        phi_570_ = 0i;
                    } else {
                        phi_570_ = select(_e144, _e146, (_e144 > _e146));
                    }
                    let _e169 = phi_570_;
                    let _e172 = ((bitcast<u32>(_e169) * _e112) + bitcast<u32>(_e164));
                    if (_e172 < _e95) {
                    } else {
                        break;
                    }
                    let _e175 = mips.member[_e172];
                    if _e137 {
                    } else {
                        break;
                    }
                    let _e176 = (_e133 < 0i);
                    if _e176 {
                        phi_611_ = 0i;
                    } else {
                        phi_611_ = select(_e133, _e136, (_e133 > _e136));
                    }
                    let _e180 = phi_611_;
                    let _e182 = (_e144 + -1i);
                    if _e147 {
                    } else {
                        break;
                    }
                    if (_e182 < 0i) {
                        phi_630_ = 0i;
                    } else {
                        phi_630_ = select(_e182, _e146, (_e182 > _e146));
                    }
                    let _e187 = phi_630_;
                    let _e190 = ((bitcast<u32>(_e187) * _e112) + bitcast<u32>(_e180));
                    if (_e190 < _e95) {
                    } else {
                        break;
                    }
                    let _e193 = mips.member[_e190];
                    if _e137 {
                    } else {
                        break;
                    }
                    if _e176 {
                        phi_671_ = 0i;
                    } else {
                        phi_671_ = select(_e133, _e136, (_e133 > _e136));
                    }
                    let _e197 = phi_671_;
                    let _e199 = (_e144 + 1i);
                    if _e147 {
                    } else {
                        break;
                    }
                    if (_e199 < 0i) {
                        phi_690_ = 0i;
                    } else {
                        phi_690_ = select(_e199, _e146, (_e199 > _e146));
                    }
                    let _e204 = phi_690_;
                    let _e207 = ((bitcast<u32>(_e204) * _e112) + bitcast<u32>(_e197));
                    if (_e207 < _e95) {
                    } else {
                        break;
                    }
                    let _e210 = mips.member[_e207];
                    let _e211 = (_e158 - _e132);
                    let _e212 = (_e175 - _e132);
                    let _e213 = (_e193 - _e132);
                    let _e214 = (_e210 - _e132);
                    let _e216 = ((_e212 - _e211) * 0.5f);
                    let _e218 = ((_e214 - _e213) * 0.5f);
                    let _e219 = (_e132 * 0.011f);
                    let _e221 = abs(_e211);
                    let _e222 = abs((_e211 + _e216));
                    if (_e221 != _e221) {
                        phi_2614_ = true;
                    } else {
                        phi_2614_ = (_e222 <= _e221);
                    }
                    let _e226 = phi_2614_;
                    let _e229 = (1.25f - (select(_e221, _e222, _e226) / _e219));
                    let _e233 = select(0f, select(1f, _e229, (_e229 < 1f)), (_e229 > 0f));
                    let _e235 = abs(_e212);
                    let _e236 = abs((_e212 - _e216));
                    if (_e235 != _e235) {
                        phi_2629_ = true;
                    } else {
                        phi_2629_ = (_e236 <= _e235);
                    }
                    let _e240 = phi_2629_;
                    let _e243 = (1.25f - (select(_e235, _e236, _e240) / _e219));
                    let _e247 = select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f));
                    let _e249 = abs(_e213);
                    let _e250 = abs((_e213 + _e218));
                    if (_e249 != _e249) {
                        phi_2644_ = true;
                    } else {
                        phi_2644_ = (_e250 <= _e249);
                    }
                    let _e254 = phi_2644_;
                    let _e257 = (1.25f - (select(_e249, _e250, _e254) / _e219));
                    let _e261 = select(0f, select(1f, _e257, (_e257 < 1f)), (_e257 > 0f));
                    let _e263 = abs(_e214);
                    let _e264 = abs((_e214 - _e218));
                    if (_e263 != _e263) {
                        phi_2659_ = true;
                    } else {
                        phi_2659_ = (_e264 <= _e263);
                    }
                    let _e268 = phi_2659_;
                    let _e271 = (1.25f - (select(_e263, _e264, _e268) / _e219));
                    let _e275 = select(0f, select(1f, _e271, (_e271 < 1f)), (_e271 > 0f));
                    let _e280 = (select(0f, select(1f, _e233, (_e233 < 1f)), (_e233 > 0f)) * 2.9f);
                    let _e282 = floor((_e280 + 0.5f));
                    if ((_e282 - _e280) == 0.5f) {
                        let _e288 = ((floor((_e282 * 0.5f)) * 2f) != _e282);
                        if _e288 {
                            phi_2690_ = (_e282 - 1f);
                        } else {
                            phi_2690_ = f32();
                        }
                        let _e291 = phi_2690_;
                        phi_2694_ = _e291;
                        phi_2695_ = select(true, false, _e288);
                    } else {
                        phi_2694_ = f32();
                        phi_2695_ = true;
                    }
                    let _e294 = phi_2694_;
                    let _e296 = phi_2695_;
                    let _e297 = select(_e294, _e282, _e296);
                    if (_e297 > 0f) {
                        let _e303 = select(select(u32(_e297), 0u, (_e297 < 0f)), 4294967295u, (_e297 > 4294967000f));
                        phi_2717_ = select(_e303, 3u, (3u < _e303));
                    } else {
                        phi_2717_ = 0u;
                    }
                    let _e307 = phi_2717_;
                    let _e313 = (select(0f, select(1f, _e247, (_e247 < 1f)), (_e247 > 0f)) * 2.9f);
                    let _e315 = floor((_e313 + 0.5f));
                    if ((_e315 - _e313) == 0.5f) {
                        let _e321 = ((floor((_e315 * 0.5f)) * 2f) != _e315);
                        if _e321 {
                            phi_2744_ = (_e315 - 1f);
                        } else {
                            phi_2744_ = f32();
                        }
                        let _e324 = phi_2744_;
                        phi_2748_ = _e324;
                        phi_2749_ = select(true, false, _e321);
                    } else {
                        phi_2748_ = f32();
                        phi_2749_ = true;
                    }
                    let _e327 = phi_2748_;
                    let _e329 = phi_2749_;
                    let _e330 = select(_e327, _e315, _e329);
                    if (_e330 > 0f) {
                        let _e336 = select(select(u32(_e330), 0u, (_e330 < 0f)), 4294967295u, (_e330 > 4294967000f));
                        phi_2771_ = select(_e336, 3u, (3u < _e336));
                    } else {
                        phi_2771_ = 0u;
                    }
                    let _e340 = phi_2771_;
                    let _e347 = (select(0f, select(1f, _e261, (_e261 < 1f)), (_e261 > 0f)) * 2.9f);
                    let _e349 = floor((_e347 + 0.5f));
                    if ((_e349 - _e347) == 0.5f) {
                        let _e355 = ((floor((_e349 * 0.5f)) * 2f) != _e349);
                        if _e355 {
                            phi_2798_ = (_e349 - 1f);
                        } else {
                            phi_2798_ = f32();
                        }
                        let _e358 = phi_2798_;
                        phi_2802_ = _e358;
                        phi_2803_ = select(true, false, _e355);
                    } else {
                        phi_2802_ = f32();
                        phi_2803_ = true;
                    }
                    let _e361 = phi_2802_;
                    let _e363 = phi_2803_;
                    let _e364 = select(_e361, _e349, _e363);
                    if (_e364 > 0f) {
                        let _e370 = select(select(u32(_e364), 0u, (_e364 < 0f)), 4294967295u, (_e364 > 4294967000f));
                        phi_2825_ = select(_e370, 3u, (3u < _e370));
                    } else {
                        phi_2825_ = 0u;
                    }
                    let _e374 = phi_2825_;
                    let _e381 = (select(0f, select(1f, _e275, (_e275 < 1f)), (_e275 > 0f)) * 2.9f);
                    let _e383 = floor((_e381 + 0.5f));
                    if ((_e383 - _e381) == 0.5f) {
                        let _e389 = ((floor((_e383 * 0.5f)) * 2f) != _e383);
                        if _e389 {
                            phi_2852_ = (_e383 - 1f);
                        } else {
                            phi_2852_ = f32();
                        }
                        let _e392 = phi_2852_;
                        phi_2856_ = _e392;
                        phi_2857_ = select(true, false, _e389);
                    } else {
                        phi_2856_ = f32();
                        phi_2857_ = true;
                    }
                    let _e395 = phi_2856_;
                    let _e397 = phi_2857_;
                    let _e398 = select(_e395, _e383, _e397);
                    if (_e398 > 0f) {
                        let _e404 = select(select(u32(_e398), 0u, (_e398 < 0f)), 4294967295u, (_e398 > 4294967000f));
                        phi_2879_ = select(_e404, 3u, (3u < _e404));
                    } else {
                        phi_2879_ = 0u;
                    }
                    let _e408 = phi_2879_;
                    let _e412 = ((f32(_e92.x) + 0.5f) / _e107);
                    let _e415 = ((f32(_e92.y) + 0.5f) / _e118);
                    let _e416 = (_e132 * 0.99999f);
                    let _e424 = params.member.member_4.member.member_1[0u];
                    let _e426 = ((((_e412 * 2f) - 1f) * _e424) * _e416);
                    let _e434 = params.member.member_4.member.member_1[1u];
                    let _e436 = ((((_e415 * -2f) + 1f) * _e434) * _e416);
                    let _e437 = -(_e426);
                    let _e438 = -(_e436);
                    let _e439 = (_e132 * -0.99999f);
                    let _e446 = (1f / sqrt((((_e437 * _e437) + (_e438 * _e438)) + (_e439 * _e439))));
                    let _e447 = (_e437 * _e446);
                    let _e448 = (_e438 * _e446);
                    let _e449 = (_e439 * _e446);
                    if (_e129 < arrayLength((&normals.member))) {
                    } else {
                        break;
                    }
                    let _e453 = normals.member[_e129];
                    let _e461 = (f32((bitcast<i32>(((_e453 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e461 != _e461) {
                        phi_2958_ = true;
                    } else {
                        phi_2958_ = (-1f >= _e461);
                    }
                    let _e465 = phi_2958_;
                    let _e466 = select(_e461, -1f, _e465);
                    let _e476 = (f32((bitcast<i32>((((_e453 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e476 != _e476) {
                        phi_2973_ = true;
                    } else {
                        phi_2973_ = (-1f >= _e476);
                    }
                    let _e480 = phi_2973_;
                    let _e481 = select(_e476, -1f, _e480);
                    let _e484 = (1f - abs(_e466));
                    let _e485 = abs(_e481);
                    let _e486 = (_e484 - _e485);
                    if (_e486 < 0f) {
                        phi_2934_ = vec2<f32>(((1f - _e485) * select(1f, -1f, (_e466 < 0f))), (_e484 * select(1f, -1f, (_e481 < 0f))));
                    } else {
                        phi_2934_ = vec2<f32>(_e466, _e481);
                    }
                    let _e497 = phi_2934_;
                    let _e506 = (1f / sqrt((((_e497.x * _e497.x) + (_e497.y * _e497.y)) + (_e486 * _e486))));
                    let _e507 = (_e497.x * _e506);
                    let _e508 = (_e497.y * _e506);
                    let _e509 = (_e486 * _e506);
                    let _e510 = -(_e509);
                    let _e516 = ((((_e507 * _e447) + (_e508 * _e448)) + (_e510 * _e449)) < 0f);
                    let _e519 = select(_e507, -(_e507), _e516);
                    let _e520 = select(_e508, -(_e508), _e516);
                    let _e521 = select(_e510, _e509, _e516);
                    let _e525 = params.member.member_4.member_1;
                    let _e529 = params.member.member_4.member_2;
                    let _e534 = ((_e525 * _e529) / (((_e132 * 1.99998f) * _e424) / _e107));
                    let _e539 = params.member.member_4.member_11;
                    phi_2990_ = (_e92.y & 63u);
                    phi_2991_ = (_e92.x & 63u);
                    phi_2992_ = 32u;
                    phi_2993_ = 0u;
                    loop {
                        let _e543 = phi_2990_;
                        let _e545 = phi_2991_;
                        let _e547 = phi_2992_;
                        let _e549 = phi_2993_;
                        local_1 = _e549;
                        let _e550 = (_e547 > 0u);
                        if _e550 {
                            let _e553 = select(0u, 1u, ((_e545 & _e547) != 0u));
                            let _e556 = select(0u, 1u, ((_e543 & _e547) != 0u));
                            if (_e556 == 0u) {
                                if (_e553 == 1u) {
                                    phi_3016_ = (63u - _e543);
                                    phi_3017_ = (63u - _e545);
                                } else {
                                    phi_3016_ = _e543;
                                    phi_3017_ = _e545;
                                }
                                let _e567 = phi_3016_;
                                let _e569 = phi_3017_;
                                phi_3020_ = _e569;
                                phi_3021_ = _e567;
                            } else {
                                phi_3020_ = _e543;
                                phi_3021_ = _e545;
                            }
                            let _e571 = phi_3020_;
                            let _e573 = phi_3021_;
                            phi_3025_ = _e571;
                            phi_3026_ = _e573;
                            phi_3027_ = (_e547 / 2u);
                            phi_3028_ = (_e549 + ((_e547 * _e547) * ((3u * _e553) ^ _e556)));
                        } else {
                            phi_3025_ = u32();
                            phi_3026_ = u32();
                            phi_3027_ = u32();
                            phi_3028_ = u32();
                        }
                        let _e576 = phi_3025_;
                        let _e578 = phi_3026_;
                        let _e580 = phi_3027_;
                        let _e582 = phi_3028_;
                        continue;
                        continuing {
                            phi_2990_ = _e576;
                            phi_2991_ = _e578;
                            phi_2992_ = _e580;
                            phi_2993_ = _e582;
                            break if !(_e550);
                        }
                    }
                    let _e587 = local_1;
                    let _e589 = f32((_e587 + (288u * (_e539 % 64u))));
                    let _e591 = (0.5f + (_e589 * 0.7548777f));
                    let _e595 = (0.5f + (_e589 * 0.5698403f));
                    let _e602 = params.member.member_4.member.member_3;
                    let _e605 = select(false, (_e132 < _e602), (_e132 > 0f));
                    if _e605 {
                        let _e609 = params.member.member_4.member_8;
                        let _e611 = select(1u, _e609, (1u < _e609));
                        phi_3375_ = false;
                        phi_942_ = 0u;
                        phi_945_ = 0f;
                        phi_947_ = 0f;
                        loop {
                            let _e613 = phi_3375_;
                            let _e615 = phi_942_;
                            let _e617 = phi_945_;
                            let _e619 = phi_947_;
                            local_9 = _e617;
                            local_10 = _e619;
                            local_11 = _e617;
                            let _e620 = (_e615 < _e611);
                            if _e620 {
                                let _e625 = ((((_e591 - floor(_e591)) + f32(_e615)) * 3.1415927f) / f32(_e611));
                                let _e626 = sin(_e625);
                                let _e627 = cos(_e625);
                                let _e633 = ((_e627 * _e447) + (_e626 * _e448));
                                let _e637 = (_e627 - (_e447 * _e633));
                                let _e638 = (_e626 - (_e448 * _e633));
                                let _e639 = -((_e449 * _e633));
                                let _e642 = ((_e638 * _e449) - (_e448 * _e639));
                                let _e645 = ((_e639 * _e447) - (_e449 * _e637));
                                let _e648 = ((_e637 * _e448) - (_e447 * _e638));
                                let _e655 = (1f / sqrt((((_e642 * _e642) + (_e645 * _e645)) + (_e648 * _e648))));
                                let _e656 = (_e642 * _e655);
                                let _e657 = (_e645 * _e655);
                                let _e658 = (_e648 * _e655);
                                let _e663 = (((_e519 * _e656) + (_e520 * _e657)) + (_e521 * _e658));
                                let _e667 = (_e519 - (_e656 * _e663));
                                let _e668 = (_e520 - (_e657 * _e663));
                                let _e669 = (_e521 - (_e658 * _e663));
                                let _e675 = sqrt((((_e667 * _e667) + (_e668 * _e668)) + (_e669 * _e669)));
                                let _e680 = (((_e637 * _e667) + (_e638 * _e668)) + (_e639 * _e669));
                                let _e690 = ((((_e667 * _e447) + (_e668 * _e448)) + (_e669 * _e449)) / _e675);
                                let _e694 = select(0f, select(1f, _e690, (_e690 < 1f)), (_e690 > 0f));
                                let _e695 = abs(_e694);
                                let _e713 = (((((((((((((((_e695 * -0.0012624911f) + 0.00667009f) * _e695) - 0.017088126f) * _e695) + 0.03089188f) * _e695) - 0.050174303f) * _e695) + 0.08897899f) * _e695) - 0.2145988f) * _e695) + 1.5707963f) * sqrt((1f - _e695)));
                                let _e716 = (select(select(0f, -1f, (_e680 < 0f)), 1f, (_e680 > 0f)) * select((3.1415927f - _e713), _e713, (_e694 >= 0f)));
                                let _e720 = params.member.member_4.member_9;
                                let _e722 = select(1u, _e720, (1u < _e720));
                                phi_1142_ = 0u;
                                phi_1145_ = 0u;
                                loop {
                                    let _e724 = phi_1142_;
                                    let _e726 = phi_1145_;
                                    local_4 = _e726;
                                    local_5 = _e726;
                                    local_7 = _e726;
                                    let _e727 = (_e724 < _e722);
                                    if _e727 {
                                        let _e732 = ((_e595 - floor(_e595)) + (f32((_e615 + (_e724 * _e722))) * 0.618034f));
                                        let _e738 = (((_e732 - floor(_e732)) + f32(_e724)) / f32(_e722));
                                        let _e742 = params.member.member_4.member_4;
                                        if (_e742 == 2f) {
                                            phi_1199_ = (_e738 * _e738);
                                        } else {
                                            phi_1199_ = pow(_e738, _e742);
                                        }
                                        let _e747 = phi_1199_;
                                        let _e748 = (_e747 + (1.3f / _e534));
                                        let _e749 = ((_e627 * _e534) * _e748);
                                        let _e750 = ((-(_e626) * _e534) * _e748);
                                        let _e759 = params.member.member_4.member_7;
                                        let _e760 = (log2(sqrt(((_e749 * _e749) + (_e750 * _e750)))) - _e759);
                                        let _e767 = (-1f - floor((-0.5f - select(0f, select(5f, _e760, (_e760 < 5f)), (_e760 > 0f)))));
                                        let _e769 = floor((_e749 + 0.5f));
                                        if ((_e769 - _e749) == 0.5f) {
                                            let _e775 = ((floor((_e769 * 0.5f)) * 2f) != _e769);
                                            if _e775 {
                                                phi_1244_ = (_e769 - 1f);
                                            } else {
                                                phi_1244_ = f32();
                                            }
                                            let _e778 = phi_1244_;
                                            phi_1246_ = _e778;
                                            phi_1247_ = select(true, false, _e775);
                                        } else {
                                            phi_1246_ = f32();
                                            phi_1247_ = true;
                                        }
                                        let _e781 = phi_1246_;
                                        let _e783 = phi_1247_;
                                        let _e785 = (select(_e781, _e769, _e783) / _e107);
                                        let _e787 = floor((_e750 + 0.5f));
                                        if ((_e787 - _e750) == 0.5f) {
                                            let _e793 = ((floor((_e787 * 0.5f)) * 2f) != _e787);
                                            if _e793 {
                                                phi_1270_ = (_e787 - 1f);
                                            } else {
                                                phi_1270_ = f32();
                                            }
                                            let _e796 = phi_1270_;
                                            phi_1272_ = _e796;
                                            phi_1273_ = select(true, false, _e793);
                                        } else {
                                            phi_1272_ = f32();
                                            phi_1273_ = true;
                                        }
                                        let _e799 = phi_1272_;
                                        let _e801 = phi_1273_;
                                        let _e803 = (select(_e799, _e787, _e801) / _e118);
                                        let _e804 = (_e412 + _e785);
                                        let _e805 = (_e415 + _e803);
                                        let _e806 = (_e412 - _e785);
                                        let _e807 = (_e415 - _e803);
                                        let _e808 = (_e767 > 0f);
                                        if _e808 {
                                            let _e813 = select(select(u32(_e767), 0u, (_e767 < 0f)), 4294967295u, (_e767 > 4294967000f));
                                            phi_1306_ = select(_e813, 4u, (4u < _e813));
                                        } else {
                                            phi_1306_ = 0u;
                                        }
                                        let _e817 = phi_1306_;
                                        let _e818 = (_e817 & 31u);
                                        let _e820 = (_e112 >> bitcast<u32>(_e818));
                                        let _e822 = select(1u, _e820, (1u < _e820));
                                        let _e824 = (_e123 >> bitcast<u32>(_e818));
                                        let _e826 = select(1u, _e824, (1u < _e824));
                                        phi_1322_ = 0u;
                                        phi_1325_ = 0u;
                                        loop {
                                            let _e828 = phi_1322_;
                                            let _e830 = phi_1325_;
                                            local_2 = _e830;
                                            let _e831 = (_e828 < _e817);
                                            if _e831 {
                                                let _e832 = (_e828 & 31u);
                                                let _e834 = (_e112 >> bitcast<u32>(_e832));
                                                let _e838 = (_e123 >> bitcast<u32>(_e832));
                                                phi_1323_ = (_e828 + 1u);
                                                phi_1326_ = (_e830 + (select(1u, _e834, (1u < _e834)) * select(1u, _e838, (1u < _e838))));
                                            } else {
                                                phi_1323_ = u32();
                                                phi_1326_ = u32();
                                            }
                                            let _e845 = phi_1323_;
                                            let _e847 = phi_1326_;
                                            continue;
                                            continuing {
                                                phi_1322_ = _e845;
                                                phi_1325_ = _e847;
                                                break if !(_e831);
                                            }
                                        }
                                        let _e851 = (_e804 * f32(_e822));
                                        if (_e851 > 0f) {
                                            let _e857 = select(select(u32(_e851), 0u, (_e851 < 0f)), 4294967295u, (_e851 > 4294967000f));
                                            let _e858 = (_e822 - 1u);
                                            phi_1370_ = select(_e857, _e858, (_e858 < _e857));
                                        } else {
                                            phi_1370_ = 0u;
                                        }
                                        let _e862 = phi_1370_;
                                        let _e863 = (_e805 * f32(_e826));
                                        if (_e863 > 0f) {
                                            let _e869 = select(select(u32(_e863), 0u, (_e863 < 0f)), 4294967295u, (_e863 > 4294967000f));
                                            let _e870 = (_e826 - 1u);
                                            phi_1389_ = select(_e869, _e870, (_e870 < _e869));
                                        } else {
                                            phi_1389_ = 0u;
                                        }
                                        let _e874 = phi_1389_;
                                        let _e877 = local_2;
                                        let _e879 = ((_e877 + (_e874 * _e822)) + _e862);
                                        if (_e879 < _e95) {
                                        } else {
                                            phi_3256_ = true;
                                            break;
                                        }
                                        let _e883 = mips.member[_e879];
                                        if _e808 {
                                            let _e896 = select(select(u32(_e767), 0u, (_e767 < 0f)), 4294967295u, (_e767 > 4294967000f));
                                            phi_1433_ = select(_e896, 4u, (4u < _e896));
                                        } else {
                                            phi_1433_ = 0u;
                                        }
                                        let _e900 = phi_1433_;
                                        let _e901 = (_e900 & 31u);
                                        let _e903 = (_e112 >> bitcast<u32>(_e901));
                                        let _e905 = select(1u, _e903, (1u < _e903));
                                        let _e907 = (_e123 >> bitcast<u32>(_e901));
                                        let _e909 = select(1u, _e907, (1u < _e907));
                                        phi_1449_ = 0u;
                                        phi_1452_ = 0u;
                                        loop {
                                            let _e911 = phi_1449_;
                                            let _e913 = phi_1452_;
                                            local_3 = _e913;
                                            let _e914 = (_e911 < _e900);
                                            if _e914 {
                                                let _e915 = (_e911 & 31u);
                                                let _e917 = (_e112 >> bitcast<u32>(_e915));
                                                let _e921 = (_e123 >> bitcast<u32>(_e915));
                                                phi_1450_ = (_e911 + 1u);
                                                phi_1453_ = (_e913 + (select(1u, _e917, (1u < _e917)) * select(1u, _e921, (1u < _e921))));
                                            } else {
                                                phi_1450_ = u32();
                                                phi_1453_ = u32();
                                            }
                                            let _e928 = phi_1450_;
                                            let _e930 = phi_1453_;
                                            continue;
                                            continuing {
                                                phi_1449_ = _e928;
                                                phi_1452_ = _e930;
                                                break if !(_e914);
                                            }
                                        }
                                        let _e934 = (_e806 * f32(_e905));
                                        if (_e934 > 0f) {
                                            let _e940 = select(select(u32(_e934), 0u, (_e934 < 0f)), 4294967295u, (_e934 > 4294967000f));
                                            let _e941 = (_e905 - 1u);
                                            phi_1497_ = select(_e940, _e941, (_e941 < _e940));
                                        } else {
                                            phi_1497_ = 0u;
                                        }
                                        let _e945 = phi_1497_;
                                        let _e946 = (_e807 * f32(_e909));
                                        if (_e946 > 0f) {
                                            let _e952 = select(select(u32(_e946), 0u, (_e946 < 0f)), 4294967295u, (_e946 > 4294967000f));
                                            let _e953 = (_e909 - 1u);
                                            phi_1516_ = select(_e952, _e953, (_e953 < _e952));
                                        } else {
                                            phi_1516_ = 0u;
                                        }
                                        let _e957 = phi_1516_;
                                        let _e960 = local_3;
                                        let _e962 = ((_e960 + (_e957 * _e905)) + _e945);
                                        if (_e962 < _e95) {
                                        } else {
                                            phi_3256_ = true;
                                            break;
                                        }
                                        let _e966 = mips.member[_e962];
                                        let _e975 = (((((_e804 * 2f) - 1f) * _e424) * _e883) - _e426);
                                        let _e976 = (((((_e805 * -2f) + 1f) * _e434) * _e883) - _e436);
                                        let _e977 = (_e883 - _e416);
                                        let _e980 = params.member.member_1;
                                        let _e981 = (_e980 > 0f);
                                        if _e981 {
                                            phi_1565_ = (sqrt((((_e975 * _e975) + (_e976 * _e976)) + (_e977 * _e977))) > _e980);
                                        } else {
                                            phi_1565_ = false;
                                        }
                                        let _e990 = phi_1565_;
                                        if !(_e990) {
                                            let _e994 = params.member.member;
                                            let _e997 = params.member.member_3;
                                            let _e1002 = (((_e975 * _e447) + (_e976 * _e448)) + (_e977 * _e449));
                                            let _e1006 = (_e975 - (_e447 * _e1002));
                                            let _e1007 = (_e976 - (_e448 * _e1002));
                                            let _e1008 = (_e977 - (_e449 * _e1002));
                                            let _e1017 = ((_e1007 * _e449) - (_e448 * _e1008));
                                            let _e1020 = ((_e1008 * _e447) - (_e449 * _e1006));
                                            let _e1023 = ((_e1006 * _e448) - (_e447 * _e1007));
                                            let _e1030 = (1f / sqrt((((_e1017 * _e1017) + (_e1020 * _e1020)) + (_e1023 * _e1023))));
                                            let _e1031 = (_e1017 * _e1030);
                                            let _e1032 = (_e1020 * _e1030);
                                            let _e1033 = (_e1023 * _e1030);
                                            let _e1038 = (((_e519 * _e1031) + (_e520 * _e1032)) + (_e521 * _e1033));
                                            let _e1042 = (_e519 - (_e1031 * _e1038));
                                            let _e1043 = (_e520 - (_e1032 * _e1038));
                                            let _e1044 = (_e521 - (_e1033 * _e1038));
                                            let _e1050 = sqrt((((_e1042 * _e1042) + (_e1043 * _e1043)) + (_e1044 * _e1044)));
                                            let _e1056 = ((((_e1042 * _e447) + (_e1043 * _e448)) + (_e1044 * _e449)) / _e1050);
                                            let _e1060 = select(0f, select(1f, _e1056, (_e1056 < 1f)), (_e1056 > 0f));
                                            let _e1061 = abs(_e1060);
                                            let _e1078 = (((((((((((((((_e1061 * -0.0012624911f) + 0.00667009f) * _e1061) - 0.017088126f) * _e1061) + 0.03089188f) * _e1061) - 0.050174303f) * _e1061) + 0.08897899f) * _e1061) - 0.2145988f) * _e1061) + 1.5707963f) * sqrt((1f - _e1061)));
                                            let _e1081 = select((3.1415927f - _e1078), _e1078, (_e1060 >= 0f));
                                            let _e1089 = select(_e1081, -(_e1081), ((((_e1006 * _e1042) + (_e1007 * _e1043)) + (_e1008 * _e1044)) < 0f));
                                            let _e1090 = (0.02f / _e1050);
                                            if (_e1090 != _e1090) {
                                                phi_3062_ = true;
                                            } else {
                                                phi_3062_ = (0.19634955f <= _e1090);
                                            }
                                            let _e1094 = phi_3062_;
                                            let _e1095 = select(_e1090, 0.19634955f, _e1094);
                                            let _e1099 = (_e975 - (_e447 * _e994));
                                            let _e1100 = (_e976 - (_e448 * _e994));
                                            let _e1101 = (_e977 - (_e449 * _e994));
                                            let _e1108 = (1f / sqrt((((_e975 * _e975) + (_e976 * _e976)) + (_e977 * _e977))));
                                            let _e1116 = ((((_e975 * _e1108) * _e447) + ((_e976 * _e1108) * _e448)) + ((_e977 * _e1108) * _e449));
                                            let _e1120 = select(-1f, select(1f, _e1116, (_e1116 < 1f)), (_e1116 > -1f));
                                            let _e1121 = abs(_e1120);
                                            let _e1138 = (((((((((((((((_e1121 * -0.0012624911f) + 0.00667009f) * _e1121) - 0.017088126f) * _e1121) + 0.03089188f) * _e1121) - 0.050174303f) * _e1121) + 0.08897899f) * _e1121) - 0.2145988f) * _e1121) + 1.5707963f) * sqrt((1f - _e1121)));
                                            let _e1145 = ((((select((3.1415927f - _e1138), _e1138, (_e1120 >= 0f)) + _e1095) - _e1089) + 1.5707964f) * 0.31830987f);
                                            let _e1149 = select(0f, select(1f, _e1145, (_e1145 < 1f)), (_e1145 > 0f));
                                            let _e1156 = (1f / sqrt((((_e1099 * _e1099) + (_e1100 * _e1100)) + (_e1101 * _e1101))));
                                            let _e1164 = ((((_e1099 * _e1156) * _e447) + ((_e1100 * _e1156) * _e448)) + ((_e1101 * _e1156) * _e449));
                                            let _e1168 = select(-1f, select(1f, _e1164, (_e1164 < 1f)), (_e1164 > -1f));
                                            let _e1169 = abs(_e1168);
                                            let _e1186 = (((((((((((((((_e1169 * -0.0012624911f) + 0.00667009f) * _e1169) - 0.017088126f) * _e1169) + 0.03089188f) * _e1169) - 0.050174303f) * _e1169) + 0.08897899f) * _e1169) - 0.2145988f) * _e1169) + 1.5707963f) * sqrt((1f - _e1169)));
                                            let _e1193 = ((((select((3.1415927f - _e1186), _e1186, (_e1168 >= 0f)) + _e1095) - _e1089) + 1.5707964f) * 0.31830987f);
                                            let _e1197 = select(0f, select(1f, _e1193, (_e1193 < 1f)), (_e1193 > 0f));
                                            let _e1198 = (_e1149 != _e1149);
                                            if _e1198 {
                                                phi_3077_ = true;
                                            } else {
                                                phi_3077_ = (_e1197 <= _e1149);
                                            }
                                            let _e1201 = phi_3077_;
                                            let _e1202 = select(_e1149, _e1197, _e1201);
                                            if _e1198 {
                                                phi_3092_ = true;
                                            } else {
                                                phi_3092_ = (_e1197 >= _e1149);
                                            }
                                            let _e1205 = phi_3092_;
                                            let _e1206 = select(_e1149, _e1197, _e1205);
                                            let _e1208 = floor((_e1202 * 32f));
                                            if (_e997 == 1u) {
                                                let _e1216 = -(floor((_e1206 * -32f)));
                                                if (_e1216 != _e1216) {
                                                    phi_3107_ = true;
                                                } else {
                                                    phi_3107_ = (32f <= _e1216);
                                                }
                                                let _e1220 = phi_3107_;
                                                let _e1223 = (select(_e1216, 32f, _e1220) - _e1208);
                                                if (_e1223 != _e1223) {
                                                    phi_3122_ = true;
                                                } else {
                                                    phi_3122_ = (0f >= _e1223);
                                                }
                                                let _e1227 = phi_3122_;
                                                phi_1886_ = select(select(_e1223, 0f, _e1227), 0f, (_e1206 <= _e1202));
                                            } else {
                                                phi_1886_ = -(floor(((_e1206 - _e1202) * -32f)));
                                            }
                                            let _e1231 = phi_1886_;
                                            if (_e1208 > 0f) {
                                                let _e1237 = select(select(u32(_e1208), 0u, (_e1208 < 0f)), 4294967295u, (_e1208 > 4294967000f));
                                                phi_1904_ = select(_e1237, 32u, (32u < _e1237));
                                            } else {
                                                phi_1904_ = 0u;
                                            }
                                            let _e1241 = phi_1904_;
                                            if (_e1231 > 0f) {
                                                let _e1247 = select(select(u32(_e1231), 0u, (_e1231 < 0f)), 4294967295u, (_e1231 > 4294967000f));
                                                phi_1922_ = select(_e1247, 32u, (32u < _e1247));
                                            } else {
                                                phi_1922_ = 0u;
                                            }
                                            let _e1251 = phi_1922_;
                                            if (_e1241 >= 32u) {
                                                phi_1942_ = u32();
                                                phi_1943_ = true;
                                            } else {
                                                let _e1253 = (_e1251 == 0u);
                                                if _e1253 {
                                                    phi_1941_ = u32();
                                                } else {
                                                    if (_e1251 >= 32u) {
                                                        phi_1938_ = 4294967295u;
                                                    } else {
                                                        phi_1938_ = ((1u << bitcast<u32>((_e1251 & 31u))) - 1u);
                                                    }
                                                    let _e1260 = phi_1938_;
                                                    phi_1941_ = (_e1260 << bitcast<u32>((_e1241 & 31u)));
                                                }
                                                let _e1265 = phi_1941_;
                                                phi_1942_ = _e1265;
                                                phi_1943_ = _e1253;
                                            }
                                            let _e1267 = phi_1942_;
                                            let _e1269 = phi_1943_;
                                            phi_1957_ = select(select(select(_e1267, 0u, _e1269), 0u, (sqrt((((_e1006 * _e1006) + (_e1007 * _e1007)) + (_e1008 * _e1008))) <= 0f)), 0u, _e990);
                                        } else {
                                            phi_1957_ = 0u;
                                        }
                                        let _e1275 = phi_1957_;
                                        let _e1277 = (((((_e806 * 2f) - 1f) * _e424) * _e966) - _e426);
                                        let _e1278 = (((((_e807 * -2f) + 1f) * _e434) * _e966) - _e436);
                                        let _e1279 = (_e966 - _e416);
                                        if _e981 {
                                            phi_1981_ = (sqrt((((_e1277 * _e1277) + (_e1278 * _e1278)) + (_e1279 * _e1279))) > _e980);
                                        } else {
                                            phi_1981_ = false;
                                        }
                                        let _e1288 = phi_1981_;
                                        if !(_e1288) {
                                            let _e1292 = params.member.member;
                                            let _e1295 = params.member.member_3;
                                            let _e1300 = (((_e1277 * _e447) + (_e1278 * _e448)) + (_e1279 * _e449));
                                            let _e1304 = (_e1277 - (_e447 * _e1300));
                                            let _e1305 = (_e1278 - (_e448 * _e1300));
                                            let _e1306 = (_e1279 - (_e449 * _e1300));
                                            let _e1315 = ((_e1305 * _e449) - (_e448 * _e1306));
                                            let _e1318 = ((_e1306 * _e447) - (_e449 * _e1304));
                                            let _e1321 = ((_e1304 * _e448) - (_e447 * _e1305));
                                            let _e1328 = (1f / sqrt((((_e1315 * _e1315) + (_e1318 * _e1318)) + (_e1321 * _e1321))));
                                            let _e1329 = (_e1315 * _e1328);
                                            let _e1330 = (_e1318 * _e1328);
                                            let _e1331 = (_e1321 * _e1328);
                                            let _e1336 = (((_e519 * _e1329) + (_e520 * _e1330)) + (_e521 * _e1331));
                                            let _e1340 = (_e519 - (_e1329 * _e1336));
                                            let _e1341 = (_e520 - (_e1330 * _e1336));
                                            let _e1342 = (_e521 - (_e1331 * _e1336));
                                            let _e1348 = sqrt((((_e1340 * _e1340) + (_e1341 * _e1341)) + (_e1342 * _e1342)));
                                            let _e1354 = ((((_e1340 * _e447) + (_e1341 * _e448)) + (_e1342 * _e449)) / _e1348);
                                            let _e1358 = select(0f, select(1f, _e1354, (_e1354 < 1f)), (_e1354 > 0f));
                                            let _e1359 = abs(_e1358);
                                            let _e1376 = (((((((((((((((_e1359 * -0.0012624911f) + 0.00667009f) * _e1359) - 0.017088126f) * _e1359) + 0.03089188f) * _e1359) - 0.050174303f) * _e1359) + 0.08897899f) * _e1359) - 0.2145988f) * _e1359) + 1.5707963f) * sqrt((1f - _e1359)));
                                            let _e1379 = select((3.1415927f - _e1376), _e1376, (_e1358 >= 0f));
                                            let _e1387 = select(_e1379, -(_e1379), ((((_e1304 * _e1340) + (_e1305 * _e1341)) + (_e1306 * _e1342)) < 0f));
                                            let _e1388 = (0.02f / _e1348);
                                            if (_e1388 != _e1388) {
                                                phi_3137_ = true;
                                            } else {
                                                phi_3137_ = (0.19634955f <= _e1388);
                                            }
                                            let _e1392 = phi_3137_;
                                            let _e1393 = select(_e1388, 0.19634955f, _e1392);
                                            let _e1397 = (_e1277 - (_e447 * _e1292));
                                            let _e1398 = (_e1278 - (_e448 * _e1292));
                                            let _e1399 = (_e1279 - (_e449 * _e1292));
                                            let _e1406 = (1f / sqrt((((_e1277 * _e1277) + (_e1278 * _e1278)) + (_e1279 * _e1279))));
                                            let _e1414 = ((((_e1277 * _e1406) * _e447) + ((_e1278 * _e1406) * _e448)) + ((_e1279 * _e1406) * _e449));
                                            let _e1418 = select(-1f, select(1f, _e1414, (_e1414 < 1f)), (_e1414 > -1f));
                                            let _e1419 = abs(_e1418);
                                            let _e1436 = (((((((((((((((_e1419 * -0.0012624911f) + 0.00667009f) * _e1419) - 0.017088126f) * _e1419) + 0.03089188f) * _e1419) - 0.050174303f) * _e1419) + 0.08897899f) * _e1419) - 0.2145988f) * _e1419) + 1.5707963f) * sqrt((1f - _e1419)));
                                            let _e1443 = ((((select((3.1415927f - _e1436), _e1436, (_e1418 >= 0f)) + _e1393) - _e1387) + 1.5707964f) * 0.31830987f);
                                            let _e1454 = (1f / sqrt((((_e1397 * _e1397) + (_e1398 * _e1398)) + (_e1399 * _e1399))));
                                            let _e1462 = ((((_e1397 * _e1454) * _e447) + ((_e1398 * _e1454) * _e448)) + ((_e1399 * _e1454) * _e449));
                                            let _e1466 = select(-1f, select(1f, _e1462, (_e1462 < 1f)), (_e1462 > -1f));
                                            let _e1467 = abs(_e1466);
                                            let _e1484 = (((((((((((((((_e1467 * -0.0012624911f) + 0.00667009f) * _e1467) - 0.017088126f) * _e1467) + 0.03089188f) * _e1467) - 0.050174303f) * _e1467) + 0.08897899f) * _e1467) - 0.2145988f) * _e1467) + 1.5707963f) * sqrt((1f - _e1467)));
                                            let _e1491 = ((((select((3.1415927f - _e1484), _e1484, (_e1466 >= 0f)) + _e1393) - _e1387) + 1.5707964f) * 0.31830987f);
                                            let _e1496 = (1f - select(0f, select(1f, _e1443, (_e1443 < 1f)), (_e1443 > 0f)));
                                            let _e1497 = (1f - select(0f, select(1f, _e1491, (_e1491 < 1f)), (_e1491 > 0f)));
                                            let _e1498 = (_e1496 != _e1496);
                                            if _e1498 {
                                                phi_3152_ = true;
                                            } else {
                                                phi_3152_ = (_e1497 <= _e1496);
                                            }
                                            let _e1501 = phi_3152_;
                                            let _e1502 = select(_e1496, _e1497, _e1501);
                                            if _e1498 {
                                                phi_3167_ = true;
                                            } else {
                                                phi_3167_ = (_e1497 >= _e1496);
                                            }
                                            let _e1505 = phi_3167_;
                                            let _e1506 = select(_e1496, _e1497, _e1505);
                                            let _e1508 = floor((_e1502 * 32f));
                                            if (_e1295 == 1u) {
                                                let _e1516 = -(floor((_e1506 * -32f)));
                                                if (_e1516 != _e1516) {
                                                    phi_3182_ = true;
                                                } else {
                                                    phi_3182_ = (32f <= _e1516);
                                                }
                                                let _e1520 = phi_3182_;
                                                let _e1523 = (select(_e1516, 32f, _e1520) - _e1508);
                                                if (_e1523 != _e1523) {
                                                    phi_3197_ = true;
                                                } else {
                                                    phi_3197_ = (0f >= _e1523);
                                                }
                                                let _e1527 = phi_3197_;
                                                phi_2302_ = select(select(_e1523, 0f, _e1527), 0f, (_e1506 <= _e1502));
                                            } else {
                                                phi_2302_ = -(floor(((_e1506 - _e1502) * -32f)));
                                            }
                                            let _e1531 = phi_2302_;
                                            if (_e1508 > 0f) {
                                                let _e1537 = select(select(u32(_e1508), 0u, (_e1508 < 0f)), 4294967295u, (_e1508 > 4294967000f));
                                                phi_2320_ = select(_e1537, 32u, (32u < _e1537));
                                            } else {
                                                phi_2320_ = 0u;
                                            }
                                            let _e1541 = phi_2320_;
                                            if (_e1531 > 0f) {
                                                let _e1547 = select(select(u32(_e1531), 0u, (_e1531 < 0f)), 4294967295u, (_e1531 > 4294967000f));
                                                phi_2338_ = select(_e1547, 32u, (32u < _e1547));
                                            } else {
                                                phi_2338_ = 0u;
                                            }
                                            let _e1551 = phi_2338_;
                                            if (_e1541 >= 32u) {
                                                phi_2358_ = u32();
                                                phi_2359_ = true;
                                            } else {
                                                let _e1553 = (_e1551 == 0u);
                                                if _e1553 {
                                                    phi_2357_ = u32();
                                                } else {
                                                    if (_e1551 >= 32u) {
                                                        phi_2354_ = 4294967295u;
                                                    } else {
                                                        phi_2354_ = ((1u << bitcast<u32>((_e1551 & 31u))) - 1u);
                                                    }
                                                    let _e1560 = phi_2354_;
                                                    phi_2357_ = (_e1560 << bitcast<u32>((_e1541 & 31u)));
                                                }
                                                let _e1565 = phi_2357_;
                                                phi_2358_ = _e1565;
                                                phi_2359_ = _e1553;
                                            }
                                            let _e1567 = phi_2358_;
                                            let _e1569 = phi_2359_;
                                            phi_2373_ = select(select(select(_e1567, 0u, _e1569), 0u, (sqrt((((_e1304 * _e1304) + (_e1305 * _e1305)) + (_e1306 * _e1306))) <= 0f)), 0u, _e1288);
                                        } else {
                                            phi_2373_ = 0u;
                                        }
                                        let _e1575 = phi_2373_;
                                        phi_1143_ = (_e724 + 1u);
                                        phi_1146_ = ((_e726 | _e1275) | _e1575);
                                    } else {
                                        phi_1143_ = u32();
                                        phi_1146_ = u32();
                                    }
                                    let _e1579 = phi_1143_;
                                    let _e1581 = phi_1146_;
                                    continue;
                                    continuing {
                                        phi_1142_ = _e1579;
                                        phi_1145_ = _e1581;
                                        phi_3256_ = _e613;
                                        break if !(_e727);
                                    }
                                }
                                let _e1584 = phi_3256_;
                                phi_3459_ = _e1584;
                                if _e1584 {
                                    break;
                                }
                                let _e1587 = params.member.member_2;
                                if (_e1587 == 2u) {
                                    let _e1644 = (_e716 - 1.5707964f);
                                    let _e1645 = (_e1644 * 2f);
                                    let _e1646 = sin(_e716);
                                    let _e1651 = ((_e694 + (_e1645 * _e1646)) - cos((_e1645 - _e716)));
                                    phi_2404_ = 0u;
                                    phi_2407_ = select((_e1651 * 0.25f), (_e1651 * -0.25f), (_e1644 < 0f));
                                    phi_2409_ = 0f;
                                    loop {
                                        let _e1657 = phi_2404_;
                                        let _e1659 = phi_2407_;
                                        let _e1661 = phi_2409_;
                                        local_8 = _e1661;
                                        let _e1662 = (_e1657 < 32u);
                                        if _e1662 {
                                            let _e1663 = (_e1657 + 1u);
                                            let _e1666 = (_e1644 + (f32(_e1663) * 0.09817477f));
                                            let _e1667 = (_e1666 * 2f);
                                            let _e1672 = ((_e694 + (_e1667 * _e1646)) - cos((_e1667 - _e716)));
                                            let _e1676 = select((_e1672 * 0.25f), (_e1672 * -0.25f), (_e1666 < 0f));
                                            let _e1679 = local_7;
                                            phi_2405_ = _e1663;
                                            phi_2408_ = _e1676;
                                            phi_2410_ = select(_e1661, (_e1661 + (_e1676 - _e1659)), (((_e1679 >> bitcast<u32>((_e1657 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2405_ = u32();
                                            phi_2408_ = f32();
                                            phi_2410_ = f32();
                                        }
                                        let _e1688 = phi_2405_;
                                        let _e1690 = phi_2408_;
                                        let _e1692 = phi_2410_;
                                        continue;
                                        continuing {
                                            phi_2404_ = _e1688;
                                            phi_2407_ = _e1690;
                                            phi_2409_ = _e1692;
                                            break if !(_e1662);
                                        }
                                    }
                                    let _e1695 = local_8;
                                    phi_3461_ = _e1584;
                                    phi_2512_ = (_e617 + 1f);
                                    phi_2513_ = (_e619 + ((_e675 + ((1f - _e675) * 0.05f)) * _e1695));
                                } else {
                                    if (_e1587 == 1u) {
                                        phi_2457_ = 0u;
                                        phi_2460_ = 0f;
                                        loop {
                                            let _e1600 = phi_2457_;
                                            let _e1602 = phi_2460_;
                                            local_6 = _e1602;
                                            let _e1603 = (_e1600 < 4u);
                                            if _e1603 {
                                                local = array<type_25, 4>(type_25(4026531855u, 0.0095061f), type_25(251658480u, 0.0270951f), type_25(15732480u, 0.0405571f), type_25(1044480u, 0.0478421f));
                                                if _e1603 {
                                                } else {
                                                    phi_3456_ = true;
                                                    break;
                                                }
                                                let _e1606 = local[_e1600].member;
                                                let _e1609 = local[_e1600].member_1;
                                                let _e1611 = local_5;
                                                phi_2458_ = (_e1600 + 1u);
                                                phi_2461_ = (_e1602 + (f32(countOneBits((_e1611 & _e1606))) * _e1609));
                                            } else {
                                                phi_2458_ = u32();
                                                phi_2461_ = f32();
                                            }
                                            let _e1619 = phi_2458_;
                                            let _e1621 = phi_2461_;
                                            continue;
                                            continuing {
                                                phi_2457_ = _e1619;
                                                phi_2460_ = _e1621;
                                                phi_3456_ = _e1584;
                                                break if !(_e1603);
                                            }
                                        }
                                        let _e1624 = phi_3456_;
                                        phi_3459_ = _e1624;
                                        if _e1624 {
                                            break;
                                        }
                                        let _e1626 = local_6;
                                        let _e1627 = (1f - _e1626);
                                        phi_3467_ = _e1624;
                                        phi_2510_ = (_e617 + _e675);
                                        phi_2511_ = (_e619 + (_e675 * select(0f, select(1f, _e1627, (_e1627 < 1f)), (_e1627 > 0f))));
                                    } else {
                                        let _e1591 = local_4;
                                        phi_3467_ = _e1584;
                                        phi_2510_ = (_e617 + 1f);
                                        phi_2511_ = (_e619 + ((f32(countOneBits((_e1591 & 4294967295u))) * -0.03125f) + 1f));
                                    }
                                    let _e1636 = phi_3467_;
                                    let _e1638 = phi_2510_;
                                    let _e1640 = phi_2511_;
                                    phi_3461_ = _e1636;
                                    phi_2512_ = _e1638;
                                    phi_2513_ = _e1640;
                                }
                                let _e1700 = phi_3461_;
                                let _e1702 = phi_2512_;
                                let _e1704 = phi_2513_;
                                phi_3460_ = _e1700;
                                phi_943_ = (_e615 + 1u);
                                phi_946_ = _e1702;
                                phi_948_ = _e1704;
                            } else {
                                phi_3460_ = _e613;
                                phi_943_ = u32();
                                phi_946_ = f32();
                                phi_948_ = f32();
                            }
                            let _e1707 = phi_3460_;
                            let _e1709 = phi_943_;
                            let _e1711 = phi_946_;
                            let _e1713 = phi_948_;
                            continue;
                            continuing {
                                phi_3375_ = _e1707;
                                phi_942_ = _e1709;
                                phi_945_ = _e1711;
                                phi_947_ = _e1713;
                                phi_3459_ = _e1707;
                                break if !(_e620);
                            }
                        }
                        let _e1716 = phi_3459_;
                        if _e1716 {
                            break;
                        }
                        let _e1718 = local_9;
                        let _e1721 = local_10;
                        let _e1723 = local_11;
                        phi_2521_ = select(1f, (_e1721 / _e1723), (_e1718 > 0f));
                    } else {
                        phi_2521_ = 1f;
                    }
                    let _e1727 = phi_2521_;
                    if _e605 {
                        let _e1731 = params.member.member_4.member_6;
                        let _e1732 = pow(_e1727, _e1731);
                        if (_e1732 != _e1732) {
                            phi_3230_ = true;
                        } else {
                            phi_3230_ = (0.03f >= _e1732);
                        }
                        let _e1736 = phi_3230_;
                        let _e1738 = (select(_e1732, 0.03f, _e1736) * 0.6666667f);
                        let _e1744 = ((select(0f, select(1f, _e1738, (_e1738 < 1f)), (_e1738 > 0f)) * 255f) + 0.5f);
                        phi_2570_ = select(select(u32(_e1744), 0u, (_e1744 < 0f)), 4294967295u, (_e1744 > 4294967000f));
                    } else {
                        phi_2570_ = 170u;
                    }
                    let _e1751 = phi_2570_;
                    if (_e129 < arrayLength((&terms.member))) {
                    } else {
                        break;
                    }
                    terms.member[_e129] = _e1751;
                    if (_e129 < arrayLength((&edges.member))) {
                    } else {
                        break;
                    }
                    edges.member[_e129] = ((((64u * _e307) + (16u * _e340)) + (4u * _e374)) + _e408);
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vbao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
