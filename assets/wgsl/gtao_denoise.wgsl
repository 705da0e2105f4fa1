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

struct type_20 {
    member: type_19,
}

struct type_22 {
    member: u32,
    member_1: f32,
    member_2: bool,
}

var<private> id_1: vec3<u32>;
@group(0) @binding(4) 
var<uniform> params: type_20;
@group(0) @binding(0) 
var<storage> terms_in: type_10;
@group(0) @binding(1) 
var<storage> edges: type_10;
@group(0) @binding(2) 
var<storage, read_write> terms_out: type_10;
@group(0) @binding(3) 
var<storage, read_write> ao: type_7;

fn function_() {
    var phi_177_: f32;
    var phi_195_: i32;
    var phi_214_: i32;
    var phi_233_: i32;
    var phi_252_: i32;
    var phi_271_: i32;
    var phi_290_: i32;
    var phi_309_: i32;
    var phi_328_: i32;
    var phi_559_: i32;
    var phi_578_: i32;
    var phi_597_: i32;
    var phi_616_: i32;
    var phi_635_: i32;
    var phi_654_: i32;
    var phi_673_: i32;
    var phi_692_: i32;
    var phi_885_: f32;
    var phi_903_: u32;
    var phi_948_: f32;
    var phi_966_: i32;
    var phi_985_: i32;
    var phi_1004_: i32;
    var phi_1023_: i32;
    var phi_1042_: i32;
    var phi_1061_: i32;
    var phi_1080_: i32;
    var phi_1099_: i32;
    var phi_1330_: i32;
    var phi_1349_: i32;
    var phi_1368_: i32;
    var phi_1387_: i32;
    var phi_1406_: i32;
    var phi_1425_: i32;
    var phi_1444_: i32;
    var phi_1463_: i32;
    var phi_1823_: vec3<f32>;
    var phi_1873_: type_22;
    var phi_1874_: type_22;
    var phi_1876_: type_22;
    var phi_1877_: type_22;
    var phi_1878_: bool;
    var phi_1882_: type_22;

    switch bitcast<i32>(0u) {
        default: {
            let _e44 = id_1;
            let _e46 = arrayLength((&terms_in.member));
            let _e48 = arrayLength((&edges.member));
            let _e57 = params.member.member.member[0u];
            let _e62 = select(select(u32(_e57), 0u, (_e57 < 0f)), 4294967295u, (_e57 > 4294967000f));
            let _e67 = params.member.member.member[1u];
            let _e72 = select(select(u32(_e67), 0u, (_e67 < 0f)), 4294967295u, (_e67 > 4294967000f));
            if (_e44.x >= _e62) {
            } else {
                if (_e44.y >= _e72) {
                } else {
                    let _e79 = params.member.member_12;
                    let _e83 = params.member.member_10;
                    let _e86 = ((_e79 + 1u) >= select(1u, _e83, (1u < _e83)));
                    let _e89 = params.member.member_13;
                    if (_e89 == 0u) {
                        if (_e83 == 0u) {
                            phi_177_ = 10000f;
                        } else {
                            phi_177_ = select(0.24000001f, 1.2f, _e86);
                        }
                        let _e94 = phi_177_;
                        let _e95 = bitcast<i32>(_e44.x);
                        let _e96 = (_e95 + -1i);
                        let _e98 = (bitcast<i32>(_e62) - 1i);
                        let _e99 = (0i <= _e98);
                        if _e99 {
                        } else {
                            break;
                        }
                        let _e100 = (_e96 < 0i);
                        if _e100 {
                            phi_195_ = 0i;
                        } else {
                            phi_195_ = select(_e96, _e98, (_e96 > _e98));
                        }
                        let _e104 = phi_195_;
                        let _e106 = bitcast<i32>(_e44.y);
                        let _e108 = (bitcast<i32>(_e72) - 1i);
                        let _e109 = (0i <= _e108);
                        if _e109 {
                        } else {
                            break;
                        }
                        let _e110 = (_e106 < 0i);
                        if _e110 {
                            phi_214_ = 0i;
                        } else {
                            phi_214_ = select(_e106, _e108, (_e106 > _e108));
                        }
                        let _e114 = phi_214_;
                        let _e116 = (_e95 + 1i);
                        if _e99 {
                        } else {
                            break;
                        }
                        let _e117 = (_e116 < 0i);
                        if _e117 {
                            phi_233_ = 0i;
                        } else {
                            phi_233_ = select(_e116, _e98, (_e116 > _e98));
                        }
                        let _e121 = phi_233_;
                        if _e109 {
                        } else {
                            break;
                        }
                        if _e110 {
                            phi_252_ = 0i;
                        } else {
                            phi_252_ = select(_e106, _e108, (_e106 > _e108));
                        }
                        let _e126 = phi_252_;
                        if _e99 {
                        } else {
                            break;
                        }
                        let _e128 = (_e95 < 0i);
                        if _e128 {
                            phi_271_ = 0i;
                        } else {
                            phi_271_ = select(_e95, _e98, (_e95 > _e98));
                        }
                        let _e132 = phi_271_;
                        let _e134 = (_e106 + -1i);
                        if _e109 {
                        } else {
                            break;
                        }
                        let _e135 = (_e134 < 0i);
                        if _e135 {
                            phi_290_ = 0i;
                        } else {
                            phi_290_ = select(_e134, _e108, (_e134 > _e108));
                        }
                        let _e139 = phi_290_;
                        if _e99 {
                        } else {
                            break;
                        }
                        if _e128 {
                            phi_309_ = 0i;
                        } else {
                            phi_309_ = select(_e95, _e98, (_e95 > _e98));
                        }
                        let _e144 = phi_309_;
                        let _e146 = (_e106 + 1i);
                        if _e109 {
                        } else {
                            break;
                        }
                        let _e147 = (_e146 < 0i);
                        if _e147 {
                            phi_328_ = 0i;
                        } else {
                            phi_328_ = select(_e146, _e108, (_e146 > _e108));
                        }
                        let _e151 = phi_328_;
                        let _e154 = ((bitcast<u32>(_e114) * _e62) + bitcast<u32>(_e104));
                        if (_e154 < _e48) {
                        } else {
                            break;
                        }
                        let _e158 = edges.member[_e154];
                        let _e173 = ((bitcast<u32>(_e126) * _e62) + bitcast<u32>(_e121));
                        if (_e173 < _e48) {
                        } else {
                            break;
                        }
                        let _e177 = edges.member[_e173];
                        let _e192 = ((bitcast<u32>(_e139) * _e62) + bitcast<u32>(_e132));
                        if (_e192 < _e48) {
                        } else {
                            break;
                        }
                        let _e196 = edges.member[_e192];
                        let _e211 = ((bitcast<u32>(_e151) * _e62) + bitcast<u32>(_e144));
                        if (_e211 < _e48) {
                        } else {
                            break;
                        }
                        let _e215 = edges.member[_e211];
                        let _e232 = ((_e44.y * _e62) + _e44.x);
                        if (_e232 < _e48) {
                        } else {
                            break;
                        }
                        let _e236 = edges.member[_e232];
                        let _e255 = ((f32(((_e236 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e158 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                        let _e256 = ((f32(((_e236 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e177 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                        let _e257 = ((f32(((_e236 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e196 & 3u)) * 0.33333334f));
                        let _e258 = ((f32((_e236 & 3u)) * 0.33333334f) * (f32(((_e215 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                        let _e262 = (1.5f - (((_e255 + _e256) + _e257) + _e258));
                        let _e267 = (select(0f, select(1f, _e262, (_e262 < 1f)), (_e262 > 0f)) * 0.33333334f);
                        let _e268 = (_e255 + _e267);
                        let _e272 = select(0f, select(1f, _e268, (_e268 < 1f)), (_e268 > 0f));
                        let _e273 = (_e256 + _e267);
                        let _e277 = select(0f, select(1f, _e273, (_e273 < 1f)), (_e273 > 0f));
                        let _e278 = (_e257 + _e267);
                        let _e282 = select(0f, select(1f, _e278, (_e278 < 1f)), (_e278 > 0f));
                        let _e283 = (_e258 + _e267);
                        let _e287 = select(0f, select(1f, _e283, (_e283 < 1f)), (_e283 > 0f));
                        let _e291 = (((_e272 * (f32(((_e158 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e282 * (f32(((_e196 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e295 = (((_e282 * (f32(((_e196 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e277 * (f32(((_e177 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e299 = (((_e287 * (f32(((_e215 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e272 * (f32((_e158 & 3u)) * 0.33333334f))) * 0.425f);
                        let _e303 = (((_e277 * (f32((_e177 & 3u)) * 0.33333334f)) + (_e287 * (f32(((_e215 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                        if _e99 {
                        } else {
                            break;
                        }
                        if _e100 {
                            phi_559_ = 0i;
                        } else {
                            phi_559_ = select(_e96, _e98, (_e96 > _e98));
                        }
                        let _e315 = phi_559_;
                        if _e109 {
                        } else {
                            break;
                        }
                        if _e135 {
                            phi_578_ = 0i;
                        } else {
                            phi_578_ = select(_e134, _e108, (_e134 > _e108));
                        }
                        let _e320 = phi_578_;
                        if _e99 {
                        } else {
                            break;
                        }
                        if _e117 {
                            phi_597_ = 0i;
                        } else {
                            phi_597_ = select(_e116, _e98, (_e116 > _e98));
                        }
                        let _e325 = phi_597_;
                        if _e109 {
                        } else {
                            break;
                        }
                        if _e135 {
                            phi_616_ = 0i;
                        } else {
                            phi_616_ = select(_e134, _e108, (_e134 > _e108));
                        }
                        let _e330 = phi_616_;
                        if _e99 {
                        } else {
                            break;
                        }
                        if _e100 {
                            phi_635_ = 0i;
                        } else {
                            phi_635_ = select(_e96, _e98, (_e96 > _e98));
                        }
                        let _e335 = phi_635_;
                        if _e109 {
                        } else {
                            break;
                        }
                        if _e147 {
                            phi_654_ = 0i;
                        } else {
                            phi_654_ = select(_e146, _e108, (_e146 > _e108));
                        }
                        let _e340 = phi_654_;
                        if _e99 {
                        } else {
                            break;
                        }
                        if _e117 {
                            phi_673_ = 0i;
                        } else {
                            phi_673_ = select(_e116, _e98, (_e116 > _e98));
                        }
                        let _e345 = phi_673_;
                        if _e109 {
                        } else {
                            break;
                        }
                        if _e147 {
                            phi_692_ = 0i;
                        } else {
                            phi_692_ = select(_e146, _e108, (_e146 > _e108));
                        }
                        let _e350 = phi_692_;
                        if (_e232 < _e46) {
                        } else {
                            break;
                        }
                        let _e355 = terms_in.member[_e232];
                        if (_e154 < _e46) {
                        } else {
                            break;
                        }
                        let _e362 = terms_in.member[_e154];
                        if (_e173 < _e46) {
                        } else {
                            break;
                        }
                        let _e370 = terms_in.member[_e173];
                        if (_e192 < _e46) {
                        } else {
                            break;
                        }
                        let _e378 = terms_in.member[_e192];
                        if (_e211 < _e46) {
                        } else {
                            break;
                        }
                        let _e386 = terms_in.member[_e211];
                        let _e392 = ((bitcast<u32>(_e320) * _e62) + bitcast<u32>(_e315));
                        if (_e392 < _e46) {
                        } else {
                            break;
                        }
                        let _e396 = terms_in.member[_e392];
                        let _e402 = ((bitcast<u32>(_e330) * _e62) + bitcast<u32>(_e325));
                        if (_e402 < _e46) {
                        } else {
                            break;
                        }
                        let _e406 = terms_in.member[_e402];
                        let _e412 = ((bitcast<u32>(_e340) * _e62) + bitcast<u32>(_e335));
                        if (_e412 < _e46) {
                        } else {
                            break;
                        }
                        let _e416 = terms_in.member[_e412];
                        let _e422 = ((bitcast<u32>(_e350) * _e62) + bitcast<u32>(_e345));
                        if (_e422 < _e46) {
                        } else {
                            break;
                        }
                        let _e426 = terms_in.member[_e422];
                        let _e431 = (((((((((((f32(_e355) * 0.003921569f) * _e94) + ((f32(_e362) * 0.003921569f) * _e272)) + ((f32(_e370) * 0.003921569f) * _e277)) + ((f32(_e378) * 0.003921569f) * _e282)) + ((f32(_e386) * 0.003921569f) * _e287)) + ((f32(_e396) * 0.003921569f) * _e291)) + ((f32(_e406) * 0.003921569f) * _e295)) + ((f32(_e416) * 0.003921569f) * _e299)) + ((f32(_e426) * 0.003921569f) * _e303)) / ((((((((_e94 + _e272) + _e277) + _e282) + _e287) + _e291) + _e295) + _e299) + _e303));
                        if _e86 {
                            phi_885_ = ((_e431 * 382.5f) + 0.5f);
                        } else {
                            phi_885_ = ((_e431 * 255f) + 0.5f);
                        }
                        let _e437 = phi_885_;
                        if (_e437 > 0f) {
                            let _e443 = select(select(u32(_e437), 0u, (_e437 < 0f)), 4294967295u, (_e437 > 4294967000f));
                            phi_903_ = select(_e443, 255u, (255u < _e443));
                        } else {
                            phi_903_ = 0u;
                        }
                        let _e447 = phi_903_;
                        phi_1876_ = type_22(_e447, (f32(_e447) * 0.003921569f), _e86);
                        phi_1877_ = type_22();
                        phi_1878_ = true;
                    } else {
                        if (_e83 == 0u) {
                            phi_948_ = 10000f;
                        } else {
                            phi_948_ = select(0.24000001f, 1.2f, _e86);
                        }
                        let _e454 = phi_948_;
                        let _e455 = bitcast<i32>(_e44.x);
                        let _e456 = (_e455 + -1i);
                        let _e458 = (bitcast<i32>(_e62) - 1i);
                        let _e459 = (0i <= _e458);
                        if _e459 {
                        } else {
                            break;
                        }
                        let _e460 = (_e456 < 0i);
                        if _e460 {
                            phi_966_ = 0i;
                        } else {
                            phi_966_ = select(_e456, _e458, (_e456 > _e458));
                        }
                        let _e464 = phi_966_;
                        let _e466 = bitcast<i32>(_e44.y);
                        let _e468 = (bitcast<i32>(_e72) - 1i);
                        let _e469 = (0i <= _e468);
                        if _e469 {
                        } else {
                            break;
                        }
                        let _e470 = (_e466 < 0i);
                        if _e470 {
                            phi_985_ = 0i;
                        } else {
                            phi_985_ = select(_e466, _e468, (_e466 > _e468));
                        }
                        let _e474 = phi_985_;
                        let _e476 = (_e455 + 1i);
                        if _e459 {
                        } else {
                            break;
                        }
                        let _e477 = (_e476 < 0i);
                        if _e477 {
                            phi_1004_ = 0i;
                        } else {
                            phi_1004_ = select(_e476, _e458, (_e476 > _e458));
                        }
                        let _e481 = phi_1004_;
                        if _e469 {
                        } else {
                            break;
                        }
                        if _e470 {
                            phi_1023_ = 0i;
                        } else {
                            phi_1023_ = select(_e466, _e468, (_e466 > _e468));
                        }
                        let _e486 = phi_1023_;
                        if _e459 {
                        } else {
                            break;
                        }
                        let _e488 = (_e455 < 0i);
                        if _e488 {
                            phi_1042_ = 0i;
                        } else {
                            phi_1042_ = select(_e455, _e458, (_e455 > _e458));
                        }
                        let _e492 = phi_1042_;
                        let _e494 = (_e466 + -1i);
                        if _e469 {
                        } else {
                            break;
                        }
                        let _e495 = (_e494 < 0i);
                        if _e495 {
                            phi_1061_ = 0i;
                        } else {
                            phi_1061_ = select(_e494, _e468, (_e494 > _e468));
                        }
                        let _e499 = phi_1061_;
                        if _e459 {
                        } else {
                            break;
                        }
                        if _e488 {
                            phi_1080_ = 0i;
                        } else {
                            phi_1080_ = select(_e455, _e458, (_e455 > _e458));
                        }
                        let _e504 = phi_1080_;
                        let _e506 = (_e466 + 1i);
                        if _e469 {
                        } else {
                            break;
                        }
                        let _e507 = (_e506 < 0i);
                        if _e507 {
                            phi_1099_ = 0i;
                        } else {
                            phi_1099_ = select(_e506, _e468, (_e506 > _e468));
                        }
                        let _e511 = phi_1099_;
                        let _e514 = ((bitcast<u32>(_e474) * _e62) + bitcast<u32>(_e464));
                        if (_e514 < _e48) {
                        } else {
                            break;
                        }
                        let _e518 = edges.member[_e514];
                        let _e533 = ((bitcast<u32>(_e486) * _e62) + bitcast<u32>(_e481));
                        if (_e533 < _e48) {
                        } else {
                            break;
                        }
                        let _e537 = edges.member[_e533];
                        let _e552 = ((bitcast<u32>(_e499) * _e62) + bitcast<u32>(_e492));
                        if (_e552 < _e48) {
                        } else {
                            break;
                        }
                        let _e556 = edges.member[_e552];
                        let _e571 = ((bitcast<u32>(_e511) * _e62) + bitcast<u32>(_e504));
                        if (_e571 < _e48) {
                        } else {
                            break;
                        }
                        let _e575 = edges.member[_e571];
                        let _e592 = ((_e44.y * _e62) + _e44.x);
                        if (_e592 < _e48) {
                        } else {
                            break;
                        }
                        let _e596 = edges.member[_e592];
                        let _e615 = ((f32(((_e596 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e518 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                        let _e616 = ((f32(((_e596 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e537 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                        let _e617 = ((f32(((_e596 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e556 & 3u)) * 0.33333334f));
                        let _e618 = ((f32((_e596 & 3u)) * 0.33333334f) * (f32(((_e575 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                        let _e622 = (1.5f - (((_e615 + _e616) + _e617) + _e618));
                        let _e627 = (select(0f, select(1f, _e622, (_e622 < 1f)), (_e622 > 0f)) * 0.33333334f);
                        let _e628 = (_e615 + _e627);
                        let _e632 = select(0f, select(1f, _e628, (_e628 < 1f)), (_e628 > 0f));
                        let _e633 = (_e616 + _e627);
                        let _e637 = select(0f, select(1f, _e633, (_e633 < 1f)), (_e633 > 0f));
                        let _e638 = (_e617 + _e627);
                        let _e642 = select(0f, select(1f, _e638, (_e638 < 1f)), (_e638 > 0f));
                        let _e643 = (_e618 + _e627);
                        let _e647 = select(0f, select(1f, _e643, (_e643 < 1f)), (_e643 > 0f));
                        let _e651 = (((_e632 * (f32(((_e518 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e642 * (f32(((_e556 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e655 = (((_e642 * (f32(((_e556 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e637 * (f32(((_e537 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e659 = (((_e647 * (f32(((_e575 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e632 * (f32((_e518 & 3u)) * 0.33333334f))) * 0.425f);
                        let _e663 = (((_e637 * (f32((_e537 & 3u)) * 0.33333334f)) + (_e647 * (f32(((_e575 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e671 = ((((((((_e454 + _e632) + _e637) + _e642) + _e647) + _e651) + _e655) + _e659) + _e663);
                        if _e459 {
                        } else {
                            break;
                        }
                        if _e460 {
                            phi_1330_ = 0i;
                        } else {
                            phi_1330_ = select(_e456, _e458, (_e456 > _e458));
                        }
                        let _e675 = phi_1330_;
                        if _e469 {
                        } else {
                            break;
                        }
                        if _e495 {
                            phi_1349_ = 0i;
                        } else {
                            phi_1349_ = select(_e494, _e468, (_e494 > _e468));
                        }
                        let _e680 = phi_1349_;
                        if _e459 {
                        } else {
                            break;
                        }
                        if _e477 {
                            phi_1368_ = 0i;
                        } else {
                            phi_1368_ = select(_e476, _e458, (_e476 > _e458));
                        }
                        let _e685 = phi_1368_;
                        if _e469 {
                        } else {
                            break;
                        }
                        if _e495 {
                            phi_1387_ = 0i;
                        } else {
                            phi_1387_ = select(_e494, _e468, (_e494 > _e468));
                        }
                        let _e690 = phi_1387_;
                        if _e459 {
                        } else {
                            break;
                        }
                        if _e460 {
                            phi_1406_ = 0i;
                        } else {
                            phi_1406_ = select(_e456, _e458, (_e456 > _e458));
                        }
                        let _e695 = phi_1406_;
                        if _e469 {
                        } else {
                            break;
                        }
                        if _e507 {
                            phi_1425_ = 0i;
                        } else {
                            phi_1425_ = select(_e506, _e468, (_e506 > _e468));
                        }
                        let _e700 = phi_1425_;
                        if _e459 {
                        } else {
                            break;
                        }
                        if _e477 {
                            phi_1444_ = 0i;
                        } else {
                            phi_1444_ = select(_e476, _e458, (_e476 > _e458));
                        }
                        let _e705 = phi_1444_;
                        if _e469 {
                        } else {
                            break;
                        }
                        if _e507 {
                            phi_1463_ = 0i;
                        } else {
                            phi_1463_ = select(_e506, _e468, (_e506 > _e468));
                        }
                        let _e710 = phi_1463_;
                        if (_e592 < _e46) {
                        } else {
                            break;
                        }
                        let _e715 = terms_in.member[_e592];
                        if (_e514 < _e46) {
                        } else {
                            break;
                        }
                        let _e740 = terms_in.member[_e514];
                        if (_e533 < _e46) {
                        } else {
                            break;
                        }
                        let _e769 = terms_in.member[_e533];
                        if (_e552 < _e46) {
                        } else {
                            break;
                        }
                        let _e798 = terms_in.member[_e552];
                        if (_e571 < _e46) {
                        } else {
                            break;
                        }
                        let _e827 = terms_in.member[_e571];
                        let _e854 = ((bitcast<u32>(_e680) * _e62) + bitcast<u32>(_e675));
                        if (_e854 < _e46) {
                        } else {
                            break;
                        }
                        let _e858 = terms_in.member[_e854];
                        let _e885 = ((bitcast<u32>(_e690) * _e62) + bitcast<u32>(_e685));
                        if (_e885 < _e46) {
                        } else {
                            break;
                        }
                        let _e889 = terms_in.member[_e885];
                        let _e916 = ((bitcast<u32>(_e700) * _e62) + bitcast<u32>(_e695));
                        if (_e916 < _e46) {
                        } else {
                            break;
                        }
                        let _e920 = terms_in.member[_e916];
                        let _e947 = ((bitcast<u32>(_e710) * _e62) + bitcast<u32>(_e705));
                        if (_e947 < _e46) {
                        } else {
                            break;
                        }
                        let _e951 = terms_in.member[_e947];
                        let _e977 = (((((((((((f32((_e715 & 255u)) * 0.003921569f) * _e454) + ((f32((_e740 & 255u)) * 0.003921569f) * _e632)) + ((f32((_e769 & 255u)) * 0.003921569f) * _e637)) + ((f32((_e798 & 255u)) * 0.003921569f) * _e642)) + ((f32((_e827 & 255u)) * 0.003921569f) * _e647)) + ((f32((_e858 & 255u)) * 0.003921569f) * _e651)) + ((f32((_e889 & 255u)) * 0.003921569f) * _e655)) + ((f32((_e920 & 255u)) * 0.003921569f) * _e659)) + ((f32((_e951 & 255u)) * 0.003921569f) * _e663)) / _e671);
                        let _e978 = (((((((((((f32(((_e715 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e454) + ((f32(((_e740 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e632)) + ((f32(((_e769 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e637)) + ((f32(((_e798 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e642)) + ((f32(((_e827 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e647)) + ((f32(((_e858 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e651)) + ((f32(((_e889 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e655)) + ((f32(((_e920 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e659)) + ((f32(((_e951 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e663)) / _e671);
                        let _e979 = (((((((((((f32(((_e715 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e454) + ((f32(((_e740 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e632)) + ((f32(((_e769 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e637)) + ((f32(((_e798 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e642)) + ((f32(((_e827 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e647)) + ((f32(((_e858 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e651)) + ((f32(((_e889 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e655)) + ((f32(((_e920 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e659)) + ((f32(((_e951 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e663)) / _e671);
                        let _e980 = (((((((((((f32((_e715 >> bitcast<u32>(24i))) * 0.003921569f) * _e454) + ((f32((_e740 >> bitcast<u32>(24i))) * 0.003921569f) * _e632)) + ((f32((_e769 >> bitcast<u32>(24i))) * 0.003921569f) * _e637)) + ((f32((_e798 >> bitcast<u32>(24i))) * 0.003921569f) * _e642)) + ((f32((_e827 >> bitcast<u32>(24i))) * 0.003921569f) * _e647)) + ((f32((_e858 >> bitcast<u32>(24i))) * 0.003921569f) * _e651)) + ((f32((_e889 >> bitcast<u32>(24i))) * 0.003921569f) * _e655)) + ((f32((_e920 >> bitcast<u32>(24i))) * 0.003921569f) * _e659)) + ((f32((_e951 >> bitcast<u32>(24i))) * 0.003921569f) * _e663)) / _e671);
                        if _e86 {
                            let _e984 = ((_e977 * 2f) - 1f);
                            let _e985 = ((_e978 * 2f) - 1f);
                            let _e986 = ((_e979 * 2f) - 1f);
                            let _e992 = sqrt((((_e984 * _e984) + (_e985 * _e985)) + (_e986 * _e986)));
                            if (_e992 > 0f) {
                                phi_1823_ = vec3<f32>((_e984 / _e992), (_e985 / _e992), (_e986 / _e992));
                            } else {
                                phi_1823_ = vec3<f32>(0f, 0f, -1f);
                            }
                            let _e999 = phi_1823_;
                            let _e1001 = ((_e980 * 382.5f) + 0.5f);
                            let _e1006 = select(select(u32(_e1001), 0u, (_e1001 < 0f)), 4294967295u, (_e1001 > 4294967000f));
                            let _e1010 = (f32(select(_e1006, 255u, (255u < _e1006))) * 0.003921569f);
                            let _e1017 = ((_e999.x * 0.5f) + 0.5f);
                            let _e1018 = ((_e999.y * 0.5f) + 0.5f);
                            let _e1019 = ((_e999.z * -0.5f) + 0.5f);
                            let _e1025 = ((select(0f, select(1f, _e1017, (_e1017 < 1f)), (_e1017 > 0f)) * 255f) + 0.5f);
                            let _e1036 = ((select(0f, select(1f, _e1018, (_e1018 < 1f)), (_e1018 > 0f)) * 255f) + 0.5f);
                            let _e1050 = ((select(0f, select(1f, _e1019, (_e1019 < 1f)), (_e1019 > 0f)) * 255f) + 0.5f);
                            let _e1064 = ((select(0f, select(1f, _e1010, (_e1010 < 1f)), (_e1010 > 0f)) * 255f) + 0.5f);
                            phi_1873_ = type_22((((select(select(u32(_e1025), 0u, (_e1025 < 0f)), 4294967295u, (_e1025 > 4294967000f)) | (select(select(u32(_e1036), 0u, (_e1036 < 0f)), 4294967295u, (_e1036 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1050), 0u, (_e1050 < 0f)), 4294967295u, (_e1050 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1064), 0u, (_e1064 < 0f)), 4294967295u, (_e1064 > 4294967000f)) << bitcast<u32>(24i))), _e1010, _e86);
                            phi_1874_ = type_22();
                        } else {
                            let _e1079 = ((select(0f, select(1f, _e977, (_e977 < 1f)), (_e977 > 0f)) * 255f) + 0.5f);
                            let _e1090 = ((select(0f, select(1f, _e978, (_e978 < 1f)), (_e978 > 0f)) * 255f) + 0.5f);
                            let _e1104 = ((select(0f, select(1f, _e979, (_e979 < 1f)), (_e979 > 0f)) * 255f) + 0.5f);
                            let _e1118 = ((select(0f, select(1f, _e980, (_e980 < 1f)), (_e980 > 0f)) * 255f) + 0.5f);
                            phi_1873_ = type_22();
                            phi_1874_ = type_22((((select(select(u32(_e1079), 0u, (_e1079 < 0f)), 4294967295u, (_e1079 > 4294967000f)) | (select(select(u32(_e1090), 0u, (_e1090 < 0f)), 4294967295u, (_e1090 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e1104), 0u, (_e1104 < 0f)), 4294967295u, (_e1104 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e1118), 0u, (_e1118 < 0f)), 4294967295u, (_e1118 > 4294967000f)) << bitcast<u32>(24i))), 0f, _e86);
                        }
                        let _e1129 = phi_1873_;
                        let _e1131 = phi_1874_;
                        phi_1876_ = _e1131;
                        phi_1877_ = _e1129;
                        phi_1878_ = select(true, false, _e86);
                    }
                    let _e1134 = phi_1876_;
                    let _e1136 = phi_1877_;
                    let _e1138 = phi_1878_;
                    if _e1138 {
                        phi_1882_ = _e1134;
                    } else {
                        phi_1882_ = _e1136;
                    }
                    let _e1140 = phi_1882_;
                    let _e1142 = ((_e44.y * _e62) + _e44.x);
                    if (_e1142 < arrayLength((&terms_out.member))) {
                    } else {
                        break;
                    }
                    terms_out.member[_e1142] = _e1140.member;
                    if _e1140.member_2 {
                        if (_e1142 < arrayLength((&ao.member))) {
                        } else {
                            break;
                        }
                        ao.member[_e1142] = _e1140.member_1;
                    }
                }
            }
            break;
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_denoise(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
