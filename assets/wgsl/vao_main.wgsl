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
    var phi_582_: bool;
    var phi_584_: bool;
    var phi_585_: bool;
    var phi_586_: bool;
    var phi_587_: bool;
    var phi_929_: type_35;
    var phi_938_: u32;
    var phi_941_: f32;
    var phi_939_: u32;
    var phi_942_: f32;
    var phi_1360_: bool;
    var local_4: f32;
    var phi_1352_: f32;

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
                        phi_582_ = ((_e311 + _e309) < _e331);
                    } else {
                        phi_582_ = bool();
                    }
                    let _e339 = phi_582_;
                    phi_584_ = _e339;
                    phi_585_ = select(true, false, _e335);
                } else {
                    phi_584_ = bool();
                    phi_585_ = true;
                }
                let _e342 = phi_584_;
                let _e344 = phi_585_;
                phi_586_ = _e342;
                phi_587_ = _e344;
            } else {
                phi_586_ = bool();
                phi_587_ = true;
            }
            let _e346 = phi_586_;
            let _e348 = phi_587_;
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
                let _e417 = f32(bitcast<i32>((_e414 & 255u)));
                let _e421 = (select(_e417, (_e417 - 256f), (_e417 >= 128f)) * 0.007874016f);
                let _e424 = select(-1f, _e421, ((_e421 > -1f) || false));
                let _e429 = f32(bitcast<i32>(((_e414 >> bitcast<u32>(8u)) & 255u)));
                let _e433 = (select(_e429, (_e429 - 256f), (_e429 >= 128f)) * 0.007874016f);
                let _e436 = select(-1f, _e433, ((_e433 > -1f) || false));
                let _e438 = (1f - abs(_e424));
                let _e439 = abs(_e436);
                let _e440 = (_e438 - _e439);
                let _e441 = (_e440 < 0f);
                let _e449 = select(_e424, ((1f - _e439) * select(1f, -1f, (_e424 < 0f))), _e441);
                let _e450 = select(_e436, (_e438 * select(1f, -1f, (_e436 < 0f))), _e441);
                let _e457 = (1f / sqrt((((_e449 * _e449) + (_e450 * _e450)) + (_e440 * _e440))));
                let _e458 = (_e449 * _e457);
                let _e459 = (_e450 * _e457);
                let _e460 = (_e440 * _e457);
                let _e466 = ((((_e408 * _e458) + (_e410 * _e459)) + (_e411 * _e460)) > 0f);
                let _e470 = select(_e458, -(_e458), _e466);
                let _e471 = select(_e459, -(_e459), _e466);
                let _e472 = select(_e460, -(_e460), _e466);
                local_3 = array<array<array<f32, 2>, 4>, 4>(array<array<f32, 2>, 4>(array<f32, 2>(0f, 1f), array<f32, 2>(0.012909942f, -0.9999167f), array<f32, 2>(0.69159436f, 0.7222861f), array<f32, 2>(-0.7000154f, -0.7141277f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.99997514f, -0.0070477454f), array<f32, 2>(0.9998238f, 0.018771695f), array<f32, 2>(-0.7100116f, 0.70418996f), array<f32, 2>(0.7182193f, -0.6958169f)), array<array<f32, 2>, 4>(array<f32, 2>(0.91594595f, 0.40130165f), array<f32, 2>(-0.92058814f, -0.39053485f), array<f32, 2>(0.36117664f, 0.93249744f), array<f32, 2>(-0.3720851f, -0.92819864f)), array<array<f32, 2>, 4>(array<f32, 2>(-0.38513124f, 0.9228618f), array<f32, 2>(0.39592505f, -0.9182828f), array<f32, 2>(-0.9260013f, 0.37752023f), array<f32, 2>(0.930364f, -0.36663717f)));
                let _e474 = (_e311 % 4u);
                if (_e474 < 4u) {
                } else {
                    break;
                }
                let _e476 = (_e310 % 4u);
                if (_e476 < 4u) {
                } else {
                    break;
                }
                let _e480 = local_3[_e474][_e476];
                let _e490 = sqrt((((_e408 * _e408) + (_e410 * _e410)) + (_e411 * _e411)));
                let _e491 = (-(_e408) / _e490);
                let _e492 = (-(_e410) / _e490);
                let _e493 = (_e367 / _e490);
                let _e496 = -((_e480[1] * _e493));
                let _e497 = (_e493 * _e480[0]);
                let _e500 = ((_e491 * _e480[1]) - (_e480[0] * _e492));
                let _e507 = (1f / sqrt((((_e496 * _e496) + (_e497 * _e497)) + (_e500 * _e500))));
                let _e508 = (_e496 * _e507);
                let _e509 = (_e497 * _e507);
                let _e510 = (_e500 * _e507);
                let _e514 = ((_e509 * _e493) - (_e492 * _e510));
                let _e517 = ((_e510 * _e491) - (_e493 * _e508));
                let _e520 = ((_e508 * _e492) - (_e491 * _e509));
                let _e536 = (((_e470 * _e491) + (_e471 * _e492)) + (_e472 * _e493));
                let _e540 = abs(_e536);
                if select(false, !((_e392 < 0.5f)), select(false, (_e367 < _e396), (_e367 > 0f))) {
                    phi_929_ = type_35(1u, type_34(vec2<u32>(_e310, _e311), vec2<f32>(_e361, _e365), select(_e354, ((_e354 * _e357) / _e387), _e388), _e392, vec3<f32>(_e408, _e410, _e411), vec3<f32>(_e470, _e471, _e472), vec3<f32>(_e491, _e492, _e493), vec3<f32>(_e514, _e517, _e520), vec3<f32>(_e508, _e509, _e510), vec3<f32>((((_e470 * _e514) + (_e471 * _e517)) + (_e472 * _e520)), (((_e470 * _e508) + (_e471 * _e509)) + (_e472 * _e510)), _e536), (1f / (select(1f, -1f, (_e536 < 0f)) * select(0.0001f, _e540, ((_e540 > 0.0001f) || false))))));
                } else {
                    phi_929_ = type_35(0u, type_35().member_1);
                }
                let _e554 = phi_929_;
                if (bitcast<i32>(_e554.member) != 0i) {
                    phi_938_ = 0u;
                    phi_941_ = 0f;
                    loop {
                        let _e560 = phi_938_;
                        let _e562 = phi_941_;
                        local_4 = _e562;
                        let _e563 = (_e560 < 8u);
                        if _e563 {
                            local = array<array<f32, 2>, 56>(array<f32, 2>(0f, 1f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(0f, 1f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(0f, 1f), array<f32, 2>(0.195054f, 0.9807925f), array<f32, 2>(0.382615f, 0.9239079f), array<f32, 2>(0.55547786f, 0.83153135f), array<f32, 2>(0.707002f, 0.70721155f), array<f32, 2>(0.8313667f, 0.5557242f), array<f32, 2>(0.92379445f, 0.38288876f), array<f32, 2>(0.98073465f, 0.19534461f), array<f32, 2>(0.99999994f, 0.0002963268f), array<f32, 2>(0.9808503f, -0.19476335f), array<f32, 2>(0.92402124f, -0.3823412f), array<f32, 2>(0.8316959f, -0.5552314f), array<f32, 2>(0.707421f, -0.7067924f), array<f32, 2>(0.55597055f, -0.831202f), array<f32, 2>(0.38316247f, -0.92368096f), array<f32, 2>(0.19563523f, -0.9806767f), array<f32, 2>(0.0005926536f, -0.9999998f), array<f32, 2>(-0.19447269f, -0.9809079f), array<f32, 2>(-0.38206735f, -0.9241345f), array<f32, 2>(-0.5549849f, -0.8318604f), array<f32, 2>(-0.7065827f, -0.7076304f), array<f32, 2>(-0.8310372f, -0.55621684f), array<f32, 2>(-0.92356735f, -0.38343617f), array<f32, 2>(-0.9806187f, -0.19592582f), array<f32, 2>(-0.9999996f, -0.0008889803f), array<f32, 2>(-0.9809655f, 0.19418201f), array<f32, 2>(-0.9242476f, 0.3817935f), array<f32, 2>(-0.8320248f, 0.5547384f), array<f32, 2>(-0.7078398f, 0.70637304f), array<f32, 2>(-0.55646306f, 0.83087236f), array<f32, 2>(-0.38370985f, 0.9234537f), array<f32, 2>(-0.19621639f, 0.9805606f));
                            let _e564 = (_e560 < 56u);
                            if _e564 {
                            } else {
                                phi_1360_ = true;
                                break;
                            }
                            let _e566 = local[_e560];
                            local_1 = array<f32, 56>(0.917883f, 0.564429f, 0.734504f, 0.359545f, 0.820004f, 0.470149f, 0.650919f, 0.205215f, 0.9490982f, 0.5865639f, 0.7554682f, 0.38954395f, 0.84255606f, 0.4948004f, 0.6719197f, 0.252031f, 0.8908589f, 0.54182106f, 0.7136428f, 0.32724136f, 0.798092f, 0.44453403f, 0.6297374f, 0.14471826f, 0.96824586f, 0.5974803f, 0.7660169f, 0.40384725f, 0.8541535f, 0.5068159f, 0.6823727f, 0.27260765f, 0.90401816f, 0.55318946f, 0.72406566f, 0.34372202f, 0.80898184f, 0.45747337f, 0.6403549f, 0.17748062f, 0.9327351f, 0.57555f, 0.7449678f, 0.37479568f, 0.83118564f, 0.48258433f, 0.6614378f, 0.22975244f, 0.87823313f, 0.5303115f, 0.7032256f, 0.30999523f, 0.7873134f, 0.4313043f, 0.61905813f, 0.10219581f);
                            if _e564 {
                            } else {
                                phi_1360_ = true;
                                break;
                            }
                            let _e570 = local_1[_e560];
                            let _e572 = (_e554.member_1.member_2 * _e570);
                            let _e573 = (_e572 * _e566[0]);
                            let _e574 = (_e572 * _e566[1]);
                            local_2 = array<f32, 56>(0.39685115f, 0.82548165f, 0.67860436f, 0.93312776f, 0.57235783f, 0.8825871f, 0.75914717f, 0.9787169f, 0.31498024f, 0.80990297f, 0.65518534f, 0.9210079f, 0.5386087f, 0.86900663f, 0.740624f, 0.96771914f, 0.45428014f, 0.84049386f, 0.7005098f, 0.9449408f, 0.6025356f, 0.89576197f, 0.7768081f, 0.9894729f, 0.2499999f, 0.8018836f, 0.6428204f, 0.91482645f, 0.52002096f, 0.8620543f, 0.7310045f, 0.9621253f, 0.42749405f, 0.8330555f, 0.68973106f, 0.9390714f, 0.58783364f, 0.88922334f, 0.76807916f, 0.9841243f, 0.3605624f, 0.8177666f, 0.6671004f, 0.92710745f, 0.555995f, 0.8758495f, 0.75f, 0.9732491f, 0.47823274f, 0.8478029f, 0.71096677f, 0.95073813f, 0.616553f, 0.90220654f, 0.78534514f, 0.9947643f);
                            if _e564 {
                            } else {
                                phi_1360_ = true;
                                break;
                            }
                            let _e576 = local_2[_e560];
                            let _e577 = (_e554.member_1.member_2 * _e576);
                            let _e586 = (-(((_e573 * _e554.member_1.member_9.x) + (_e574 * _e554.member_1.member_9.y))) * _e554.member_1.member_10);
                            let _e587 = -(_e577);
                            let _e591 = select(_e587, select(_e577, _e586, (_e586 < _e577)), (_e586 > _e587));
                            let _e592 = (_e577 - _e591);
                            let _e619 = (-0.5f / ((_e554.member_1.member_4.z + (_e554.member_1.member_7.z * _e573)) + (_e554.member_1.member_8.z * _e574)));
                            let _e622 = (((((_e554.member_1.member_4.x + (_e554.member_1.member_7.x * _e573)) + (_e554.member_1.member_8.x * _e574)) * _e619) / _e372) + 0.5f);
                            let _e625 = (0.5f - ((((_e554.member_1.member_4.y + (_e554.member_1.member_7.y * _e573)) + (_e554.member_1.member_8.y * _e574)) * _e619) / _e377));
                            let _e630 = (select(0f, select(1f, _e622, (_e622 < 1f)), (_e622 > 0f)) * _e316);
                            let _e633 = f32(bitcast<i32>((_e321 - 1u)));
                            let _e641 = (bitcast<u32>((floor(select(0f, select(_e633, _e630, (_e630 < _e633)), (_e630 > 0f))) + 8388608f)) - 1258291200u);
                            let _e646 = (select(0f, select(1f, _e625, (_e625 < 1f)), (_e625 > 0f)) * _e326);
                            let _e649 = f32(bitcast<i32>((_e331 - 1u)));
                            let _e657 = (bitcast<u32>((floor(select(0f, select(_e649, _e646, (_e646 < _e649)), (_e646 > 0f))) + 8388608f)) - 1258291200u);
                            let _e668 = depth.member[((_e657 * _e321) + _e641)];
                            let _e682 = select(_e396, _e668, select(false, (_e668 < _e396), (_e668 > 0f)));
                            let _e703 = ((((((((((f32(bitcast<i32>(_e641)) + 0.5f) * (1f / _e316)) * 2f) - 1f) * _e682) * _e372) - _e554.member_1.member_4.x) * _e554.member_1.member_6.x) + ((((((((f32(bitcast<i32>(_e657)) + 0.5f) * (1f / _e326)) * -2f) + 1f) * _e682) * _e377) - _e554.member_1.member_4.y) * _e554.member_1.member_6.y)) + ((-(_e682) - _e554.member_1.member_4.z) * _e554.member_1.member_6.z));
                            let _e708 = params.member.member_3;
                            let _e714 = (_e577 - select(_e703, _e591, ((_e591 > _e703) || (_e703 != _e703))));
                            let _e721 = ((_e703 - (_e554.member_1.member_2 * (1f + _e708))) * (1f / _e577));
                            phi_939_ = (_e560 + 1u);
                            phi_942_ = (_e562 + select(0f, select(((select(0f, _e714, ((_e714 > 0f) || false)) + (select(0f, select(1f, _e721, (_e721 < 1f)), (_e721 > 0f)) * _e592)) * (0.5f / _e577)), (_e592 / (_e577 * 2f)), select(false, (_e657 == _e554.member_1.member.y), (_e641 == _e554.member_1.member.x))), (_e592 > (_e577 * 0.2f))));
                        } else {
                            phi_939_ = u32();
                            phi_942_ = f32();
                        }
                        let _e735 = phi_939_;
                        let _e737 = phi_942_;
                        continue;
                        continuing {
                            phi_938_ = _e735;
                            phi_941_ = _e737;
                            phi_1360_ = false;
                            break if !(_e563);
                        }
                    }
                    let _e740 = phi_1360_;
                    if _e740 {
                        break;
                    }
                    let _e742 = local_4;
                    let _e743 = (0.25f * _e742);
                    let _e750 = params.member.member_2;
                    phi_1352_ = pow(select(0f, select(1f, _e743, (_e743 < 1f)), (_e743 > 0f)), _e750);
                } else {
                    phi_1352_ = 1f;
                }
                let _e753 = phi_1352_;
                ao.member[_e351] = _e753;
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
