struct type_5 {
    member: vec2<f32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: u32,
    member_5: u32,
}

struct type_6 {
    member: type_5,
    member_1: f32,
    member_2: f32,
    member_3: f32,
    member_4: f32,
}

struct type_7 {
    member: type_6,
}

struct type_10 {
    member: array<f32>,
}

struct type_13 {
    member: array<u32>,
}

struct type_34 {
    member: vec2<u32>,
    member_1: vec2<f32>,
    member_2: f32,
    member_3: f32,
    member_4: vec3<f32>,
    member_5: vec3<f32>,
    member_6: vec3<f32>,
    member_7: vec3<f32>,
    member_8: vec3<f32>,
    member_9: vec3<f32>,
    member_10: f32,
}

struct type_35 {
    member: u32,
    member_1: type_34,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(3) 
var<uniform> params: type_7;
@group(0) @binding(0) 
var<storage> depth: type_10;
@group(0) @binding(1) 
var<storage> normals: type_13;
@group(0) @binding(2) 
var<storage, read_write> ao: type_10;

fn function_() {
    var local: array<array<f32, 2>, 56>;
    var local_1: array<f32, 56>;
    var local_2: array<f32, 56>;
    var local_3: array<array<array<f32, 2>, 4>, 4>;
    var phi_593_: bool;
    var phi_595_: bool;
    var phi_596_: bool;
    var phi_597_: bool;
    var phi_598_: bool;
    var phi_1467_: bool;
    var phi_1482_: bool;
    var phi_1443_: vec2<f32>;
    var phi_875_: type_35;
    var phi_884_: u32;
    var phi_887_: f32;
    var phi_885_: u32;
    var phi_888_: f32;
    var phi_1496_: bool;
    var local_4: f32;
    var phi_1298_: f32;

    switch bitcast<i32>(0u) {
        default: {
            let _e301 = id_1;
            let _e309 = params.member.member.member_4;
            let _e310 = (_e301.x + _e309);
            let _e311 = (_e301.y + _e309);
            let _e316 = params.member.member.member[0u];
            let _e321 = select(select(u32(_e316), 0u, (_e316 < 0f)), 4294967295u, (_e316 > 4294967000f));
            let _e326 = params.member.member.member[1u];
            let _e331 = select(select(u32(_e326), 0u, (_e326 < 0f)), 4294967295u, (_e326 > 4294967000f));
            if (_e310 >= _e309) {
                if (_e311 >= _e309) {
                    let _e335 = ((_e310 + _e309) < _e321);
                    if _e335 {
                        phi_593_ = ((_e311 + _e309) < _e331);
                    } else {
                        phi_593_ = bool();
                    }
                    let _e339 = phi_593_;
                    phi_595_ = _e339;
                    phi_596_ = select(true, false, _e335);
                } else {
                    phi_595_ = bool();
                    phi_596_ = true;
                }
                let _e342 = phi_595_;
                let _e344 = phi_596_;
                phi_597_ = _e342;
                phi_598_ = _e344;
            } else {
                phi_597_ = bool();
                phi_598_ = true;
            }
            let _e346 = phi_597_;
            let _e348 = phi_598_;
            if select(_e346, false, _e348) {
                let _e351 = ((_e311 * _e321) + _e310);
                let _e354 = params.member.member_1;
                let _e357 = params.member.member_4;
                let _e361 = ((f32(bitcast<i32>(_e310)) + 0.5f) / _e316);
                let _e365 = ((f32(bitcast<i32>(_e311)) + 0.5f) / _e326);
                let _e367 = depth.member[_e351];
                let _e372 = params.member.member.member_1[0u];
                let _e377 = params.member.member.member_1[1u];
                let _e387 = ((((_e354 * _e316) / (_e367 * (2f * _e372))) + ((_e354 * _e326) / (_e367 * (2f * _e377)))) * 0.5f);
                let _e388 = (_e387 > _e357);
                let _e392 = select(_e387, _e357, _e388);
                let _e396 = params.member.member.member_3;
                let _e408 = ((((_e361 * 2f) - 1f) * _e367) * _e372);
                let _e410 = ((((_e365 * -2f) + 1f) * _e367) * _e377);
                let _e411 = -(_e367);
                let _e414 = normals.member[_e351];
                let _e422 = (f32((bitcast<i32>(((_e414 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e422 != _e422) {
                    phi_1467_ = true;
                } else {
                    phi_1467_ = (-1f >= _e422);
                }
                let _e426 = phi_1467_;
                let _e427 = select(_e422, -1f, _e426);
                let _e437 = (f32((bitcast<i32>((((_e414 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                if (_e437 != _e437) {
                    phi_1482_ = true;
                } else {
                    phi_1482_ = (-1f >= _e437);
                }
                let _e441 = phi_1482_;
                let _e442 = select(_e437, -1f, _e441);
                let _e445 = (1f - abs(_e427));
                let _e446 = abs(_e442);
                let _e447 = (_e445 - _e446);
                if (_e447 < 0f) {
                    phi_1443_ = vec2<f32>(((1f - _e446) * select(1f, -1f, (_e427 < 0f))), (_e445 * select(1f, -1f, (_e442 < 0f))));
                } else {
                    phi_1443_ = vec2<f32>(_e427, _e442);
                }
                let _e458 = phi_1443_;
                let _e467 = (1f / sqrt((((_e458.x * _e458.x) + (_e458.y * _e458.y)) + (_e447 * _e447))));
                let _e468 = (_e458.x * _e467);
                let _e469 = (_e458.y * _e467);
                let _e470 = (_e447 * _e467);
                let _e476 = ((((_e408 * _e468) + (_e410 * _e469)) + (_e411 * _e470)) > 0f);
                let _e480 = select(_e468, -(_e468), _e476);
                let _e481 = select(_e469, -(_e469), _e476);
                let _e482 = select(_e470, -(_e470), _e476);
                local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e484 = (_e311 % 4u);
                if (_e484 < 4u) {
                } else {
                    break;
                }
                let _e486 = (_e310 % 4u);
                if (_e486 < 4u) {
                } else {
                    break;
                }
                let _e490 = local_3[_e484][_e486];
                let _e500 = sqrt((((_e408 * _e408) + (_e410 * _e410)) + (_e411 * _e411)));
                let _e501 = (-(_e408) / _e500);
                let _e502 = (-(_e410) / _e500);
                let _e503 = (_e367 / _e500);
                let _e506 = -((_e490[1] * _e503));
                let _e507 = (_e503 * _e490[0]);
                let _e510 = ((_e501 * _e490[1]) - (_e490[0] * _e502));
                let _e517 = (1f / sqrt((((_e506 * _e506) + (_e507 * _e507)) + (_e510 * _e510))));
                let _e518 = (_e506 * _e517);
                let _e519 = (_e507 * _e517);
                let _e520 = (_e510 * _e517);
                let _e524 = ((_e519 * _e503) - (_e502 * _e520));
                let _e527 = ((_e520 * _e501) - (_e503 * _e518));
                let _e530 = ((_e518 * _e502) - (_e501 * _e519));
                let _e546 = (((_e480 * _e501) + (_e481 * _e502)) + (_e482 * _e503));
                let _e550 = abs(_e546);
                if select(false, !((_e392 < 0.5f)), select(false, (_e367 < _e396), (_e367 > 0f))) {
                    phi_875_ = type_35(1u, type_34(vec2<u32>(_e310, _e311), vec2<f32>(_e361, _e365), select(_e354, ((_e354 * _e357) / _e387), _e388), _e392, vec3<f32>(_e408, _e410, _e411), vec3<f32>(_e480, _e481, _e482), vec3<f32>(_e501, _e502, _e503), vec3<f32>(_e524, _e527, _e530), vec3<f32>(_e518, _e519, _e520), vec3<f32>((((_e480 * _e524) + (_e481 * _e527)) + (_e482 * _e530)), (((_e480 * _e518) + (_e481 * _e519)) + (_e482 * _e520)), _e546), (1f / (select(1f, -1f, (_e546 < 0f)) * select(0.0001f, _e550, ((_e550 > 0.0001f) || false))))));
                } else {
                    phi_875_ = type_35(0u, type_35().member_1);
                }
                let _e564 = phi_875_;
                if (bitcast<i32>(_e564.member) != 0i) {
                    phi_884_ = 0u;
                    phi_887_ = 0f;
                    loop {
                        let _e570 = phi_884_;
                        let _e572 = phi_887_;
                        local_4 = _e572;
                        let _e573 = (_e570 < 8u);
                        if _e573 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e574 = (_e570 < 56u);
                            if _e574 {
                            } else {
                                phi_1496_ = true;
                                break;
                            }
                            let _e576 = local[_e570];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e574 {
                            } else {
                                phi_1496_ = true;
                                break;
                            }
                            let _e580 = local_1[_e570];
                            let _e582 = (_e564.member_1.member_2 * _e580);
                            let _e583 = (_e582 * _e576[0]);
                            let _e584 = (_e582 * _e576[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e574 {
                            } else {
                                phi_1496_ = true;
                                break;
                            }
                            let _e586 = local_2[_e570];
                            let _e587 = (_e564.member_1.member_2 * _e586);
                            let _e596 = (-(((_e583 * _e564.member_1.member_9.x) + (_e584 * _e564.member_1.member_9.y))) * _e564.member_1.member_10);
                            let _e597 = -(_e587);
                            let _e601 = select(_e597, select(_e587, _e596, (_e596 < _e587)), (_e596 > _e597));
                            let _e602 = (_e587 - _e601);
                            let _e629 = (-0.5f / ((_e564.member_1.member_4.z + (_e564.member_1.member_7.z * _e583)) + (_e564.member_1.member_8.z * _e584)));
                            let _e632 = (((((_e564.member_1.member_4.x + (_e564.member_1.member_7.x * _e583)) + (_e564.member_1.member_8.x * _e584)) * _e629) / _e372) + 0.5f);
                            let _e635 = (0.5f - ((((_e564.member_1.member_4.y + (_e564.member_1.member_7.y * _e583)) + (_e564.member_1.member_8.y * _e584)) * _e629) / _e377));
                            let _e640 = (select(0f, select(1f, _e632, (_e632 < 1f)), (_e632 > 0f)) * _e316);
                            let _e643 = f32(bitcast<i32>((_e321 - 1u)));
                            let _e645 = select(0f, _e640, (_e640 > 0f));
                            let _e651 = (bitcast<u32>((floor(select(_e643, _e645, (_e645 < _e643))) + 8388608f)) - 1258291200u);
                            let _e656 = (select(0f, select(1f, _e635, (_e635 < 1f)), (_e635 > 0f)) * _e326);
                            let _e659 = f32(bitcast<i32>((_e331 - 1u)));
                            let _e661 = select(0f, _e656, (_e656 > 0f));
                            let _e667 = (bitcast<u32>((floor(select(_e659, _e661, (_e661 < _e659))) + 8388608f)) - 1258291200u);
                            let _e678 = depth.member[((_e667 * _e321) + _e651)];
                            let _e692 = select(_e396, _e678, select(false, (_e678 < _e396), (_e678 > 0f)));
                            let _e713 = ((((((((((f32(bitcast<i32>(_e651)) + 0.5f) * (1f / _e316)) * 2f) - 1f) * _e692) * _e372) - _e564.member_1.member_4.x) * _e564.member_1.member_6.x) + ((((((((f32(bitcast<i32>(_e667)) + 0.5f) * (1f / _e326)) * -2f) + 1f) * _e692) * _e377) - _e564.member_1.member_4.y) * _e564.member_1.member_6.y)) + ((-(_e692) - _e564.member_1.member_4.z) * _e564.member_1.member_6.z));
                            let _e718 = params.member.member_3;
                            let _e724 = (_e587 - select(_e713, _e601, ((_e601 > _e713) || (_e713 != _e713))));
                            let _e731 = ((_e713 - (_e564.member_1.member_2 * (1f + _e718))) * (1f / _e587));
                            phi_885_ = (_e570 + 1u);
                            phi_888_ = (_e572 + select(0f, select(((select(0f, _e724, ((_e724 > 0f) || false)) + (select(0f, select(1f, _e731, (_e731 < 1f)), (_e731 > 0f)) * _e602)) * (0.5f / _e587)), (_e602 / (_e587 * 2f)), select(false, (_e667 == _e564.member_1.member.y), (_e651 == _e564.member_1.member.x))), (_e602 > (_e587 * 0.2f))));
                        } else {
                            phi_885_ = u32();
                            phi_888_ = f32();
                        }
                        let _e745 = phi_885_;
                        let _e747 = phi_888_;
                        continue;
                        continuing {
                            phi_884_ = _e745;
                            phi_887_ = _e747;
                            phi_1496_ = false;
                            break if !(_e573);
                        }
                    }
                    let _e750 = phi_1496_;
                    if _e750 {
                        break;
                    }
                    let _e752 = local_4;
                    let _e753 = (0.25f * _e752);
                    let _e760 = params.member.member_2;
                    phi_1298_ = pow(select(0f, select(1f, _e753, (_e753 < 1f)), (_e753 > 0f)), _e760);
                } else {
                    phi_1298_ = 1f;
                }
                let _e763 = phi_1298_;
                ao.member[_e351] = _e763;
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn vao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
