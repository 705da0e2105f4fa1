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

struct type_23 {
    member: f32,
    member_1: f32,
    member_2: u32,
    member_3: u32,
    member_4: type_21,
}

struct type_24 {
    member: type_23,
}

struct type_26 {
    member: u32,
    member_1: f32,
}

@id(0) override override_type: u32 = 0u;
@id(4) override override_type_1: u32 = 0u;
@id(5) override override_type_2: u32 = 0u;
@id(6) override override_type_3: u32 = 0u;
@id(7) override override_type_4: u32 = 0u;
@id(8) override override_type_5: u32 = 0u;
@id(9) override override_type_6: u32 = 0u;
@id(1) override override_type_7: u32 = 0u;
@id(2) override override_type_8: u32 = 0u;
@id(3) override override_type_9: u32 = 0u;
@id(10) override override_type_10: u32 = 0u;
@id(11) override override_type_11: u32 = 0u;

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
var<uniform> params: type_24;

fn function_() {
    var local: array<type_26, 4>;
    var phi_523_: type_21;
    var phi_530_: u32;
    var phi_537_: u32;
    var phi_2926_: bool;
    var phi_2941_: bool;
    var phi_2902_: vec2<f32>;
    var phi_3326_: bool;
    var phi_996_: u32;
    var phi_999_: f32;
    var phi_1001_: f32;
    var phi_1194_: u32;
    var phi_1197_: u32;
    var phi_1250_: f32;
    var phi_1663_: bool;
    var phi_2010_: f32;
    var phi_2060_: u32;
    var phi_2063_: u32;
    var phi_2064_: u32;
    var phi_2065_: bool;
    var phi_2079_: u32;
    var phi_2099_: bool;
    var phi_2446_: f32;
    var phi_2496_: u32;
    var phi_2499_: u32;
    var phi_2500_: u32;
    var phi_2501_: bool;
    var phi_2515_: u32;
    var phi_1195_: u32;
    var phi_1198_: u32;
    var local_1: u32;
    var phi_2596_: u32;
    var phi_2599_: f32;
    var local_2: u32;
    var phi_2597_: u32;
    var phi_2600_: f32;
    var phi_3205_: bool;
    var local_3: f32;
    var phi_3418_: bool;
    var phi_2649_: f32;
    var phi_2650_: f32;
    var phi_2544_: u32;
    var phi_2547_: f32;
    var phi_2549_: f32;
    var local_4: u32;
    var phi_2545_: u32;
    var phi_2548_: f32;
    var phi_2550_: f32;
    var local_5: f32;
    var phi_3412_: bool;
    var phi_2651_: f32;
    var phi_2652_: f32;
    var phi_3411_: bool;
    var phi_997_: u32;
    var phi_1000_: f32;
    var phi_1002_: f32;
    var phi_3410_: bool;
    var local_6: f32;
    var local_7: f32;
    var local_8: f32;
    var phi_2660_: f32;
    var phi_3179_: bool;
    var phi_2701_: u32;

    switch bitcast<i32>(0u) {
        default: {
            let _e110 = id_1;
            let _e113 = (override_type == 0u);
            if _e113 {
                let _e145 = params.member.member_4;
                phi_523_ = _e145;
            } else {
                let _e123 = params.member.member_4.member;
                let _e127 = params.member.member_4.member_1;
                let _e131 = params.member.member_4.member_10;
                let _e135 = params.member.member_4.member_11;
                let _e139 = params.member.member_4.member_12;
                let _e143 = params.member.member_4.member_14;
                phi_523_ = type_21(_e123, _e127, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e131, _e135, _e139, override_type_9, _e143);
            }
            let _e147 = phi_523_;
            if _e113 {
                let _e150 = params.member.member_2;
                phi_530_ = _e150;
            } else {
                phi_530_ = override_type_10;
            }
            let _e152 = phi_530_;
            if _e113 {
                let _e155 = params.member.member_3;
                phi_537_ = _e155;
            } else {
                phi_537_ = override_type_11;
            }
            let _e157 = phi_537_;
            let _e160 = params.member.member;
            let _e163 = params.member.member_1;
            let _e171 = select(select(u32(_e147.member.member.x), 0u, (_e147.member.member.x < 0f)), 4294967295u, (_e147.member.member.x > 4294967000f));
            let _e179 = select(select(u32(_e147.member.member.y), 0u, (_e147.member.member.y < 0f)), 4294967295u, (_e147.member.member.y > 4294967000f));
            if (_e110.x >= _e171) {
            } else {
                if (_e110.y >= _e179) {
                } else {
                    let _e185 = ((_e110.y * _e171) + _e110.x);
                    let _e188 = mips.member[_e185];
                    let _e189 = bitcast<i32>(_e110.x);
                    let _e190 = (_e189 + -1i);
                    let _e192 = select(0i, _e190, (0i < _e190));
                    let _e194 = (bitcast<i32>(_e171) - 1i);
                    let _e198 = bitcast<i32>(_e110.y);
                    let _e200 = select(0i, _e198, (0i < _e198));
                    let _e202 = (bitcast<i32>(_e179) - 1i);
                    let _e206 = (bitcast<u32>(select(_e200, _e202, (_e202 < _e200))) * _e171);
                    let _e210 = mips.member[(_e206 + bitcast<u32>(select(_e192, _e194, (_e194 < _e192))))];
                    let _e211 = (_e189 + 1i);
                    let _e213 = select(0i, _e211, (0i < _e211));
                    let _e220 = mips.member[(_e206 + bitcast<u32>(select(_e213, _e194, (_e194 < _e213))))];
                    let _e222 = select(0i, _e189, (0i < _e189));
                    let _e225 = bitcast<u32>(select(_e222, _e194, (_e194 < _e222)));
                    let _e226 = (_e198 + -1i);
                    let _e228 = select(0i, _e226, (0i < _e226));
                    let _e236 = mips.member[((bitcast<u32>(select(_e228, _e202, (_e202 < _e228))) * _e171) + _e225)];
                    let _e237 = (_e198 + 1i);
                    let _e239 = select(0i, _e237, (0i < _e237));
                    let _e247 = mips.member[((bitcast<u32>(select(_e239, _e202, (_e202 < _e239))) * _e171) + _e225)];
                    let _e248 = (_e210 - _e188);
                    let _e249 = (_e220 - _e188);
                    let _e250 = (_e236 - _e188);
                    let _e251 = (_e247 - _e188);
                    let _e253 = ((_e249 - _e248) * 0.5f);
                    let _e255 = ((_e251 - _e250) * 0.5f);
                    let _e256 = (_e188 * 0.011f);
                    let _e258 = abs(_e248);
                    let _e259 = abs((_e248 + _e253));
                    let _e265 = (1.25f - (select(_e259, _e258, ((_e258 < _e259) || (_e259 != _e259))) / _e256));
                    let _e269 = select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f));
                    let _e271 = abs(_e249);
                    let _e272 = abs((_e249 - _e253));
                    let _e278 = (1.25f - (select(_e272, _e271, ((_e271 < _e272) || (_e272 != _e272))) / _e256));
                    let _e282 = select(0f, select(1f, _e278, (_e278 < 1f)), (_e278 > 0f));
                    let _e284 = abs(_e250);
                    let _e285 = abs((_e250 + _e255));
                    let _e291 = (1.25f - (select(_e285, _e284, ((_e284 < _e285) || (_e285 != _e285))) / _e256));
                    let _e295 = select(0f, select(1f, _e291, (_e291 < 1f)), (_e291 > 0f));
                    let _e297 = abs(_e251);
                    let _e298 = abs((_e251 - _e255));
                    let _e304 = (1.25f - (select(_e298, _e297, ((_e297 < _e298) || (_e298 != _e298))) / _e256));
                    let _e308 = select(0f, select(1f, _e304, (_e304 < 1f)), (_e304 > 0f));
                    let _e314 = round((select(0f, select(1f, _e269, (_e269 < 1f)), (_e269 > 0f)) * 2.9f));
                    let _e316 = select(0f, _e314, (_e314 > 0f));
                    let _e329 = round((select(0f, select(1f, _e282, (_e282 < 1f)), (_e282 > 0f)) * 2.9f));
                    let _e331 = select(0f, _e329, (_e329 > 0f));
                    let _e345 = round((select(0f, select(1f, _e295, (_e295 < 1f)), (_e295 > 0f)) * 2.9f));
                    let _e347 = select(0f, _e345, (_e345 > 0f));
                    let _e361 = round((select(0f, select(1f, _e308, (_e308 < 1f)), (_e308 > 0f)) * 2.9f));
                    let _e363 = select(0f, _e361, (_e361 > 0f));
                    let _e373 = ((f32(_e189) + 0.5f) / _e147.member.member.x);
                    let _e376 = ((f32(_e198) + 0.5f) / _e147.member.member.y);
                    let _e377 = (_e188 * 0.99999f);
                    let _e384 = ((((_e373 * 2f) - 1f) * _e147.member.member_1.x) * _e377);
                    let _e391 = ((((_e376 * -2f) + 1f) * _e147.member.member_1.y) * _e377);
                    let _e392 = -(_e384);
                    let _e393 = -(_e391);
                    let _e394 = (_e188 * -0.99999f);
                    let _e401 = (1f / sqrt((((_e392 * _e392) + (_e393 * _e393)) + (_e394 * _e394))));
                    let _e402 = (_e392 * _e401);
                    let _e403 = (_e393 * _e401);
                    let _e404 = (_e394 * _e401);
                    let _e407 = normals.member[_e185];
                    let _e415 = (f32((bitcast<i32>(((_e407 & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e415 != _e415) {
                        phi_2926_ = true;
                    } else {
                        phi_2926_ = (-1f >= _e415);
                    }
                    let _e419 = phi_2926_;
                    let _e420 = select(_e415, -1f, _e419);
                    let _e430 = (f32((bitcast<i32>((((_e407 >> bitcast<u32>(8i)) & 255u) << bitcast<u32>(24i))) >> bitcast<u32>(24i))) * 0.007874016f);
                    if (_e430 != _e430) {
                        phi_2941_ = true;
                    } else {
                        phi_2941_ = (-1f >= _e430);
                    }
                    let _e434 = phi_2941_;
                    let _e435 = select(_e430, -1f, _e434);
                    let _e438 = (1f - abs(_e420));
                    let _e439 = abs(_e435);
                    let _e440 = (_e438 - _e439);
                    if (_e440 < 0f) {
                        phi_2902_ = vec2<f32>(((1f - _e439) * select(1f, -1f, (_e420 < 0f))), (_e438 * select(1f, -1f, (_e435 < 0f))));
                    } else {
                        phi_2902_ = vec2<f32>(_e420, _e435);
                    }
                    let _e451 = phi_2902_;
                    let _e460 = (1f / sqrt((((_e451.x * _e451.x) + (_e451.y * _e451.y)) + (_e440 * _e440))));
                    let _e461 = (_e451.x * _e460);
                    let _e462 = (_e451.y * _e460);
                    let _e463 = (_e440 * _e460);
                    let _e464 = -(_e463);
                    let _e470 = ((((_e461 * _e402) + (_e462 * _e403)) + (_e464 * _e404)) < 0f);
                    let _e473 = select(_e461, -(_e461), _e470);
                    let _e474 = select(_e462, -(_e462), _e470);
                    let _e475 = select(_e464, _e463, _e470);
                    let _e482 = ((_e147.member_1 * _e147.member_2) / (((_e188 * 1.99998f) * _e147.member.member_1.x) / _e147.member.member.x));
                    let _e485 = (_e110.x & 63u);
                    let _e486 = (_e110.y & 63u);
                    let _e489 = select(0u, 1u, ((_e485 & 32u) != 0u));
                    let _e492 = select(0u, 1u, ((_e486 & 32u) != 0u));
                    let _e496 = (_e492 == 0u);
                    let _e498 = (_e496 && (_e489 == 1u));
                    let _e501 = select(_e485, (63u - _e485), _e498);
                    let _e502 = select(_e486, (63u - _e486), _e498);
                    let _e503 = select(_e501, _e502, _e496);
                    let _e504 = select(_e502, _e501, _e496);
                    let _e507 = select(0u, 1u, ((_e503 & 16u) != 0u));
                    let _e510 = select(0u, 1u, ((_e504 & 16u) != 0u));
                    let _e515 = (_e510 == 0u);
                    let _e517 = (_e515 && (_e507 == 1u));
                    let _e520 = select(_e503, (63u - _e503), _e517);
                    let _e521 = select(_e504, (63u - _e504), _e517);
                    let _e522 = select(_e520, _e521, _e515);
                    let _e523 = select(_e521, _e520, _e515);
                    let _e526 = select(0u, 1u, ((_e522 & 8u) != 0u));
                    let _e529 = select(0u, 1u, ((_e523 & 8u) != 0u));
                    let _e534 = (_e529 == 0u);
                    let _e536 = (_e534 && (_e526 == 1u));
                    let _e539 = select(_e522, (63u - _e522), _e536);
                    let _e540 = select(_e523, (63u - _e523), _e536);
                    let _e541 = select(_e539, _e540, _e534);
                    let _e542 = select(_e540, _e539, _e534);
                    let _e545 = select(0u, 1u, ((_e541 & 4u) != 0u));
                    let _e548 = select(0u, 1u, ((_e542 & 4u) != 0u));
                    let _e553 = (_e548 == 0u);
                    let _e555 = (_e553 && (_e545 == 1u));
                    let _e558 = select(_e541, (63u - _e541), _e555);
                    let _e559 = select(_e542, (63u - _e542), _e555);
                    let _e560 = select(_e558, _e559, _e553);
                    let _e561 = select(_e559, _e558, _e553);
                    let _e564 = select(0u, 1u, ((_e560 & 2u) != 0u));
                    let _e567 = select(0u, 1u, ((_e561 & 2u) != 0u));
                    let _e572 = (_e567 == 0u);
                    let _e574 = (_e572 && (_e564 == 1u));
                    let _e577 = select(_e560, (63u - _e560), _e574);
                    let _e578 = select(_e561, (63u - _e561), _e574);
                    let _e594 = f32(bitcast<i32>((((((((1024u * ((3u * _e489) ^ _e492)) + (256u * ((3u * _e507) ^ _e510))) + (64u * ((3u * _e526) ^ _e529))) + (16u * ((3u * _e545) ^ _e548))) + (4u * ((3u * _e564) ^ _e567))) + ((3u * select(0u, 1u, ((select(_e577, _e578, _e572) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e578, _e577, _e572) & 1u) != 0u)))) + (288u * (_e147.member_11 % 64u)))));
                    let _e596 = (0.5f + (_e594 * 0.7548777f));
                    let _e600 = (0.5f + (_e594 * 0.5698403f));
                    let _e607 = select(false, (_e188 < _e147.member.member_3), (_e188 > 0f));
                    if _e607 {
                        let _e610 = select(1u, _e147.member_8, (1u < _e147.member_8));
                        phi_3326_ = false;
                        phi_996_ = 0u;
                        phi_999_ = 0f;
                        phi_1001_ = 0f;
                        loop {
                            let _e612 = phi_3326_;
                            let _e614 = phi_996_;
                            let _e616 = phi_999_;
                            let _e618 = phi_1001_;
                            local_6 = _e616;
                            local_7 = _e618;
                            local_8 = _e616;
                            let _e619 = (_e614 < _e610);
                            if _e619 {
                                let _e626 = ((((_e596 - floor(_e596)) + f32(bitcast<i32>(_e614))) * 3.1415927f) / f32(bitcast<i32>(_e610)));
                                let _e627 = sin(_e626);
                                let _e628 = cos(_e626);
                                let _e634 = ((_e628 * _e402) + (_e627 * _e403));
                                let _e638 = (_e628 - (_e402 * _e634));
                                let _e639 = (_e627 - (_e403 * _e634));
                                let _e640 = -((_e404 * _e634));
                                let _e643 = ((_e639 * _e404) - (_e403 * _e640));
                                let _e646 = ((_e640 * _e402) - (_e404 * _e638));
                                let _e649 = ((_e638 * _e403) - (_e402 * _e639));
                                let _e656 = (1f / sqrt((((_e643 * _e643) + (_e646 * _e646)) + (_e649 * _e649))));
                                let _e657 = (_e643 * _e656);
                                let _e658 = (_e646 * _e656);
                                let _e659 = (_e649 * _e656);
                                let _e664 = (((_e473 * _e657) + (_e474 * _e658)) + (_e475 * _e659));
                                let _e668 = (_e473 - (_e657 * _e664));
                                let _e669 = (_e474 - (_e658 * _e664));
                                let _e670 = (_e475 - (_e659 * _e664));
                                let _e676 = sqrt((((_e668 * _e668) + (_e669 * _e669)) + (_e670 * _e670)));
                                let _e681 = (((_e638 * _e668) + (_e639 * _e669)) + (_e640 * _e670));
                                let _e691 = ((((_e668 * _e402) + (_e669 * _e403)) + (_e670 * _e404)) / _e676);
                                let _e695 = select(0f, select(1f, _e691, (_e691 < 1f)), (_e691 > 0f));
                                let _e696 = abs(_e695);
                                let _e714 = (((((((((((((((_e696 * -0.0012624911f) + 0.00667009f) * _e696) - 0.017088126f) * _e696) + 0.03089188f) * _e696) - 0.050174303f) * _e696) + 0.08897899f) * _e696) - 0.2145988f) * _e696) + 1.5707963f) * sqrt((1f - _e696)));
                                let _e717 = (select(select(0f, -1f, (_e681 < 0f)), 1f, (_e681 > 0f)) * select((3.1415927f - _e714), _e714, (_e695 >= 0f)));
                                let _e720 = select(1u, _e147.member_9, (1u < _e147.member_9));
                                phi_1194_ = 0u;
                                phi_1197_ = 0u;
                                loop {
                                    let _e722 = phi_1194_;
                                    let _e724 = phi_1197_;
                                    local_1 = _e724;
                                    local_2 = _e724;
                                    local_4 = _e724;
                                    let _e725 = (_e722 < _e720);
                                    if _e725 {
                                        let _e731 = ((_e600 - floor(_e600)) + (f32(bitcast<i32>((_e614 + (_e722 * _e720)))) * 0.618034f));
                                        let _e740 = (((_e731 - floor(_e731)) + f32(bitcast<i32>(_e722))) * (1f / f32(bitcast<i32>(_e720))));
                                        if (_e147.member_4 == 2f) {
                                            phi_1250_ = (_e740 * _e740);
                                        } else {
                                            phi_1250_ = pow(_e740, _e147.member_4);
                                        }
                                        let _e746 = phi_1250_;
                                        let _e747 = (_e746 + (1.3f / _e482));
                                        let _e748 = ((_e628 * _e482) * _e747);
                                        let _e749 = ((-(_e627) * _e482) * _e747);
                                        let _e756 = (log2(sqrt(((_e748 * _e748) + (_e749 * _e749)))) - _e147.member_7);
                                        let _e763 = (-1f - floor((-0.5f - select(0f, select(5f, _e756, (_e756 < 5f)), (_e756 > 0f)))));
                                        let _e766 = (round(_e748) * (1f / _e147.member.member.x));
                                        let _e769 = (round(_e749) * (1f / _e147.member.member.y));
                                        let _e770 = (_e373 + _e766);
                                        let _e771 = (_e376 + _e769);
                                        let _e772 = (_e373 - _e766);
                                        let _e773 = (_e376 - _e769);
                                        let _e775 = select(0f, _e763, (_e763 > 0f));
                                        let _e782 = ((bitcast<u32>((floor(select(4f, _e775, (_e775 < 4f))) + 8388608f)) - 1258291200u) & 31u);
                                        let _e784 = (_e171 >> bitcast<u32>(_e782));
                                        let _e786 = select(1u, _e784, (1u < _e784));
                                        let _e788 = (_e179 >> bitcast<u32>(_e782));
                                        let _e790 = select(1u, _e788, (1u < _e788));
                                        let _e795 = (select(1u, _e171, (1u < _e171)) * select(1u, _e179, (1u < _e179)));
                                        let _e799 = (_e171 >> bitcast<u32>(1u));
                                        let _e803 = (_e179 >> bitcast<u32>(1u));
                                        let _e807 = (_e795 + (select(1u, _e799, (1u < _e799)) * select(1u, _e803, (1u < _e803))));
                                        let _e811 = (_e171 >> bitcast<u32>(2u));
                                        let _e815 = (_e179 >> bitcast<u32>(2u));
                                        let _e819 = (_e807 + (select(1u, _e811, (1u < _e811)) * select(1u, _e815, (1u < _e815))));
                                        let _e823 = (_e171 >> bitcast<u32>(3u));
                                        let _e827 = (_e179 >> bitcast<u32>(3u));
                                        let _e833 = select(select(select(select(0u, _e795, (_e763 >= 1f)), _e807, (_e763 >= 2f)), _e819, (_e763 >= 3f)), (_e819 + (select(1u, _e823, (1u < _e823)) * select(1u, _e827, (1u < _e827)))), (_e763 >= 4f));
                                        let _e835 = f32(bitcast<i32>(_e786));
                                        let _e836 = (_e770 * _e835);
                                        let _e839 = f32(bitcast<i32>((_e786 - 1u)));
                                        let _e841 = select(0f, _e836, (_e836 > 0f));
                                        let _e849 = f32(bitcast<i32>(_e790));
                                        let _e850 = (_e771 * _e849);
                                        let _e853 = f32(bitcast<i32>((_e790 - 1u)));
                                        let _e855 = select(0f, _e850, (_e850 > 0f));
                                        let _e867 = mips.member[((_e833 + ((bitcast<u32>((floor(select(_e853, _e855, (_e855 < _e853))) + 8388608f)) - 1258291200u) * _e786)) + (bitcast<u32>((floor(select(_e839, _e841, (_e841 < _e839))) + 8388608f)) - 1258291200u))];
                                        let _e876 = (_e772 * _e835);
                                        let _e878 = select(0f, _e876, (_e876 > 0f));
                                        let _e885 = (_e773 * _e849);
                                        let _e887 = select(0f, _e885, (_e885 > 0f));
                                        let _e899 = mips.member[((_e833 + ((bitcast<u32>((floor(select(_e853, _e887, (_e887 < _e853))) + 8388608f)) - 1258291200u) * _e786)) + (bitcast<u32>((floor(select(_e839, _e878, (_e878 < _e839))) + 8388608f)) - 1258291200u))];
                                        let _e908 = (((((_e770 * 2f) - 1f) * _e147.member.member_1.x) * _e867) - _e384);
                                        let _e909 = (((((_e771 * -2f) + 1f) * _e147.member.member_1.y) * _e867) - _e391);
                                        let _e910 = (_e867 - _e377);
                                        let _e911 = (_e163 > 0f);
                                        if _e911 {
                                            phi_1663_ = (sqrt((((_e908 * _e908) + (_e909 * _e909)) + (_e910 * _e910))) > _e163);
                                        } else {
                                            phi_1663_ = false;
                                        }
                                        let _e920 = phi_1663_;
                                        if !(_e920) {
                                            let _e926 = (((_e908 * _e402) + (_e909 * _e403)) + (_e910 * _e404));
                                            let _e930 = (_e908 - (_e402 * _e926));
                                            let _e931 = (_e909 - (_e403 * _e926));
                                            let _e932 = (_e910 - (_e404 * _e926));
                                            let _e941 = ((_e931 * _e404) - (_e403 * _e932));
                                            let _e944 = ((_e932 * _e402) - (_e404 * _e930));
                                            let _e947 = ((_e930 * _e403) - (_e402 * _e931));
                                            let _e954 = (1f / sqrt((((_e941 * _e941) + (_e944 * _e944)) + (_e947 * _e947))));
                                            let _e955 = (_e941 * _e954);
                                            let _e956 = (_e944 * _e954);
                                            let _e957 = (_e947 * _e954);
                                            let _e962 = (((_e473 * _e955) + (_e474 * _e956)) + (_e475 * _e957));
                                            let _e966 = (_e473 - (_e955 * _e962));
                                            let _e967 = (_e474 - (_e956 * _e962));
                                            let _e968 = (_e475 - (_e957 * _e962));
                                            let _e974 = sqrt((((_e966 * _e966) + (_e967 * _e967)) + (_e968 * _e968)));
                                            let _e980 = ((((_e966 * _e402) + (_e967 * _e403)) + (_e968 * _e404)) / _e974);
                                            let _e984 = select(0f, select(1f, _e980, (_e980 < 1f)), (_e980 > 0f));
                                            let _e985 = abs(_e984);
                                            let _e1002 = (((((((((((((((_e985 * -0.0012624911f) + 0.00667009f) * _e985) - 0.017088126f) * _e985) + 0.03089188f) * _e985) - 0.050174303f) * _e985) + 0.08897899f) * _e985) - 0.2145988f) * _e985) + 1.5707963f) * sqrt((1f - _e985)));
                                            let _e1005 = select((3.1415927f - _e1002), _e1002, (_e984 >= 0f));
                                            let _e1013 = select(_e1005, -(_e1005), ((((_e930 * _e966) + (_e931 * _e967)) + (_e932 * _e968)) < 0f));
                                            let _e1014 = (0.02f / _e974);
                                            let _e1017 = select(0.19634955f, _e1014, ((_e1014 < 0.19634955f) || false));
                                            let _e1021 = (_e908 - (_e402 * _e160));
                                            let _e1022 = (_e909 - (_e403 * _e160));
                                            let _e1023 = (_e910 - (_e404 * _e160));
                                            let _e1030 = (1f / sqrt((((_e908 * _e908) + (_e909 * _e909)) + (_e910 * _e910))));
                                            let _e1038 = ((((_e908 * _e1030) * _e402) + ((_e909 * _e1030) * _e403)) + ((_e910 * _e1030) * _e404));
                                            let _e1042 = select(-1f, select(1f, _e1038, (_e1038 < 1f)), (_e1038 > -1f));
                                            let _e1043 = abs(_e1042);
                                            let _e1060 = (((((((((((((((_e1043 * -0.0012624911f) + 0.00667009f) * _e1043) - 0.017088126f) * _e1043) + 0.03089188f) * _e1043) - 0.050174303f) * _e1043) + 0.08897899f) * _e1043) - 0.2145988f) * _e1043) + 1.5707963f) * sqrt((1f - _e1043)));
                                            let _e1067 = ((((select((3.1415927f - _e1060), _e1060, (_e1042 >= 0f)) + _e1017) - _e1013) + 1.5707964f) * 0.31830987f);
                                            let _e1071 = select(0f, select(1f, _e1067, (_e1067 < 1f)), (_e1067 > 0f));
                                            let _e1078 = (1f / sqrt((((_e1021 * _e1021) + (_e1022 * _e1022)) + (_e1023 * _e1023))));
                                            let _e1086 = ((((_e1021 * _e1078) * _e402) + ((_e1022 * _e1078) * _e403)) + ((_e1023 * _e1078) * _e404));
                                            let _e1090 = select(-1f, select(1f, _e1086, (_e1086 < 1f)), (_e1086 > -1f));
                                            let _e1091 = abs(_e1090);
                                            let _e1108 = (((((((((((((((_e1091 * -0.0012624911f) + 0.00667009f) * _e1091) - 0.017088126f) * _e1091) + 0.03089188f) * _e1091) - 0.050174303f) * _e1091) + 0.08897899f) * _e1091) - 0.2145988f) * _e1091) + 1.5707963f) * sqrt((1f - _e1091)));
                                            let _e1115 = ((((select((3.1415927f - _e1108), _e1108, (_e1090 >= 0f)) + _e1017) - _e1013) + 1.5707964f) * 0.31830987f);
                                            let _e1119 = select(0f, select(1f, _e1115, (_e1115 < 1f)), (_e1115 > 0f));
                                            let _e1121 = (_e1119 != _e1119);
                                            let _e1123 = select(_e1119, _e1071, ((_e1071 < _e1119) || _e1121));
                                            let _e1126 = select(_e1119, _e1071, ((_e1071 > _e1119) || _e1121));
                                            let _e1128 = floor((_e1123 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1136 = -(floor((_e1126 * -32f)));
                                                let _e1141 = (select(32f, _e1136, ((_e1136 < 32f) || false)) - _e1128);
                                                phi_2010_ = select(select(0f, _e1141, ((_e1141 > 0f) || false)), 0f, (_e1126 <= _e1123));
                                            } else {
                                                phi_2010_ = -(floor(((_e1126 - _e1123) * -32f)));
                                            }
                                            let _e1147 = phi_2010_;
                                            let _e1149 = select(0f, _e1128, (_e1128 > 0f));
                                            let _e1155 = (bitcast<u32>((floor(select(32f, _e1149, (_e1149 < 32f))) + 8388608f)) - 1258291200u);
                                            let _e1157 = select(0f, _e1147, (_e1147 > 0f));
                                            let _e1163 = (bitcast<u32>((floor(select(32f, _e1157, (_e1157 < 32f))) + 8388608f)) - 1258291200u);
                                            if (_e1155 >= 32u) {
                                                phi_2064_ = u32();
                                                phi_2065_ = true;
                                            } else {
                                                let _e1165 = (_e1163 == 0u);
                                                if _e1165 {
                                                    phi_2063_ = u32();
                                                } else {
                                                    if (_e1163 >= 32u) {
                                                        phi_2060_ = 4294967295u;
                                                    } else {
                                                        phi_2060_ = ((1u << bitcast<u32>((_e1163 & 31u))) - 1u);
                                                    }
                                                    let _e1172 = phi_2060_;
                                                    phi_2063_ = (_e1172 << bitcast<u32>((_e1155 & 31u)));
                                                }
                                                let _e1177 = phi_2063_;
                                                phi_2064_ = _e1177;
                                                phi_2065_ = _e1165;
                                            }
                                            let _e1179 = phi_2064_;
                                            let _e1181 = phi_2065_;
                                            phi_2079_ = select(select(select(_e1179, 0u, _e1181), 0u, (sqrt((((_e930 * _e930) + (_e931 * _e931)) + (_e932 * _e932))) <= 0f)), 0u, _e920);
                                        } else {
                                            phi_2079_ = 0u;
                                        }
                                        let _e1187 = phi_2079_;
                                        let _e1189 = (((((_e772 * 2f) - 1f) * _e147.member.member_1.x) * _e899) - _e384);
                                        let _e1190 = (((((_e773 * -2f) + 1f) * _e147.member.member_1.y) * _e899) - _e391);
                                        let _e1191 = (_e899 - _e377);
                                        if _e911 {
                                            phi_2099_ = (sqrt((((_e1189 * _e1189) + (_e1190 * _e1190)) + (_e1191 * _e1191))) > _e163);
                                        } else {
                                            phi_2099_ = false;
                                        }
                                        let _e1200 = phi_2099_;
                                        if !(_e1200) {
                                            let _e1206 = (((_e1189 * _e402) + (_e1190 * _e403)) + (_e1191 * _e404));
                                            let _e1210 = (_e1189 - (_e402 * _e1206));
                                            let _e1211 = (_e1190 - (_e403 * _e1206));
                                            let _e1212 = (_e1191 - (_e404 * _e1206));
                                            let _e1221 = ((_e1211 * _e404) - (_e403 * _e1212));
                                            let _e1224 = ((_e1212 * _e402) - (_e404 * _e1210));
                                            let _e1227 = ((_e1210 * _e403) - (_e402 * _e1211));
                                            let _e1234 = (1f / sqrt((((_e1221 * _e1221) + (_e1224 * _e1224)) + (_e1227 * _e1227))));
                                            let _e1235 = (_e1221 * _e1234);
                                            let _e1236 = (_e1224 * _e1234);
                                            let _e1237 = (_e1227 * _e1234);
                                            let _e1242 = (((_e473 * _e1235) + (_e474 * _e1236)) + (_e475 * _e1237));
                                            let _e1246 = (_e473 - (_e1235 * _e1242));
                                            let _e1247 = (_e474 - (_e1236 * _e1242));
                                            let _e1248 = (_e475 - (_e1237 * _e1242));
                                            let _e1254 = sqrt((((_e1246 * _e1246) + (_e1247 * _e1247)) + (_e1248 * _e1248)));
                                            let _e1260 = ((((_e1246 * _e402) + (_e1247 * _e403)) + (_e1248 * _e404)) / _e1254);
                                            let _e1264 = select(0f, select(1f, _e1260, (_e1260 < 1f)), (_e1260 > 0f));
                                            let _e1265 = abs(_e1264);
                                            let _e1282 = (((((((((((((((_e1265 * -0.0012624911f) + 0.00667009f) * _e1265) - 0.017088126f) * _e1265) + 0.03089188f) * _e1265) - 0.050174303f) * _e1265) + 0.08897899f) * _e1265) - 0.2145988f) * _e1265) + 1.5707963f) * sqrt((1f - _e1265)));
                                            let _e1285 = select((3.1415927f - _e1282), _e1282, (_e1264 >= 0f));
                                            let _e1293 = select(_e1285, -(_e1285), ((((_e1210 * _e1246) + (_e1211 * _e1247)) + (_e1212 * _e1248)) < 0f));
                                            let _e1294 = (0.02f / _e1254);
                                            let _e1297 = select(0.19634955f, _e1294, ((_e1294 < 0.19634955f) || false));
                                            let _e1301 = (_e1189 - (_e402 * _e160));
                                            let _e1302 = (_e1190 - (_e403 * _e160));
                                            let _e1303 = (_e1191 - (_e404 * _e160));
                                            let _e1310 = (1f / sqrt((((_e1189 * _e1189) + (_e1190 * _e1190)) + (_e1191 * _e1191))));
                                            let _e1318 = ((((_e1189 * _e1310) * _e402) + ((_e1190 * _e1310) * _e403)) + ((_e1191 * _e1310) * _e404));
                                            let _e1322 = select(-1f, select(1f, _e1318, (_e1318 < 1f)), (_e1318 > -1f));
                                            let _e1323 = abs(_e1322);
                                            let _e1340 = (((((((((((((((_e1323 * -0.0012624911f) + 0.00667009f) * _e1323) - 0.017088126f) * _e1323) + 0.03089188f) * _e1323) - 0.050174303f) * _e1323) + 0.08897899f) * _e1323) - 0.2145988f) * _e1323) + 1.5707963f) * sqrt((1f - _e1323)));
                                            let _e1347 = ((((select((3.1415927f - _e1340), _e1340, (_e1322 >= 0f)) + _e1297) - _e1293) + 1.5707964f) * 0.31830987f);
                                            let _e1358 = (1f / sqrt((((_e1301 * _e1301) + (_e1302 * _e1302)) + (_e1303 * _e1303))));
                                            let _e1366 = ((((_e1301 * _e1358) * _e402) + ((_e1302 * _e1358) * _e403)) + ((_e1303 * _e1358) * _e404));
                                            let _e1370 = select(-1f, select(1f, _e1366, (_e1366 < 1f)), (_e1366 > -1f));
                                            let _e1371 = abs(_e1370);
                                            let _e1388 = (((((((((((((((_e1371 * -0.0012624911f) + 0.00667009f) * _e1371) - 0.017088126f) * _e1371) + 0.03089188f) * _e1371) - 0.050174303f) * _e1371) + 0.08897899f) * _e1371) - 0.2145988f) * _e1371) + 1.5707963f) * sqrt((1f - _e1371)));
                                            let _e1395 = ((((select((3.1415927f - _e1388), _e1388, (_e1370 >= 0f)) + _e1297) - _e1293) + 1.5707964f) * 0.31830987f);
                                            let _e1400 = (1f - select(0f, select(1f, _e1347, (_e1347 < 1f)), (_e1347 > 0f)));
                                            let _e1401 = (1f - select(0f, select(1f, _e1395, (_e1395 < 1f)), (_e1395 > 0f)));
                                            let _e1403 = (_e1401 != _e1401);
                                            let _e1405 = select(_e1401, _e1400, ((_e1400 < _e1401) || _e1403));
                                            let _e1408 = select(_e1401, _e1400, ((_e1400 > _e1401) || _e1403));
                                            let _e1410 = floor((_e1405 * 32f));
                                            if (_e157 == 1u) {
                                                let _e1418 = -(floor((_e1408 * -32f)));
                                                let _e1423 = (select(32f, _e1418, ((_e1418 < 32f) || false)) - _e1410);
                                                phi_2446_ = select(select(0f, _e1423, ((_e1423 > 0f) || false)), 0f, (_e1408 <= _e1405));
                                            } else {
                                                phi_2446_ = -(floor(((_e1408 - _e1405) * -32f)));
                                            }
                                            let _e1429 = phi_2446_;
                                            let _e1431 = select(0f, _e1410, (_e1410 > 0f));
                                            let _e1437 = (bitcast<u32>((floor(select(32f, _e1431, (_e1431 < 32f))) + 8388608f)) - 1258291200u);
                                            let _e1439 = select(0f, _e1429, (_e1429 > 0f));
                                            let _e1445 = (bitcast<u32>((floor(select(32f, _e1439, (_e1439 < 32f))) + 8388608f)) - 1258291200u);
                                            if (_e1437 >= 32u) {
                                                phi_2500_ = u32();
                                                phi_2501_ = true;
                                            } else {
                                                let _e1447 = (_e1445 == 0u);
                                                if _e1447 {
                                                    phi_2499_ = u32();
                                                } else {
                                                    if (_e1445 >= 32u) {
                                                        phi_2496_ = 4294967295u;
                                                    } else {
                                                        phi_2496_ = ((1u << bitcast<u32>((_e1445 & 31u))) - 1u);
                                                    }
                                                    let _e1454 = phi_2496_;
                                                    phi_2499_ = (_e1454 << bitcast<u32>((_e1437 & 31u)));
                                                }
                                                let _e1459 = phi_2499_;
                                                phi_2500_ = _e1459;
                                                phi_2501_ = _e1447;
                                            }
                                            let _e1461 = phi_2500_;
                                            let _e1463 = phi_2501_;
                                            phi_2515_ = select(select(select(_e1461, 0u, _e1463), 0u, (sqrt((((_e1210 * _e1210) + (_e1211 * _e1211)) + (_e1212 * _e1212))) <= 0f)), 0u, _e1200);
                                        } else {
                                            phi_2515_ = 0u;
                                        }
                                        let _e1469 = phi_2515_;
                                        phi_1195_ = (_e722 + 1u);
                                        phi_1198_ = ((_e724 | _e1187) | _e1469);
                                    } else {
                                        phi_1195_ = u32();
                                        phi_1198_ = u32();
                                    }
                                    let _e1473 = phi_1195_;
                                    let _e1475 = phi_1198_;
                                    continue;
                                    continuing {
                                        phi_1194_ = _e1473;
                                        phi_1197_ = _e1475;
                                        break if !(_e725);
                                    }
                                }
                                if (_e152 == 2u) {
                                    let _e1535 = (_e717 - 1.5707964f);
                                    let _e1536 = (_e1535 * 2f);
                                    let _e1537 = sin(_e717);
                                    let _e1542 = ((_e695 + (_e1536 * _e1537)) - cos((_e1536 - _e717)));
                                    phi_2544_ = 0u;
                                    phi_2547_ = select((_e1542 * 0.25f), (_e1542 * -0.25f), (_e1535 < 0f));
                                    phi_2549_ = 0f;
                                    loop {
                                        let _e1548 = phi_2544_;
                                        let _e1550 = phi_2547_;
                                        let _e1552 = phi_2549_;
                                        local_5 = _e1552;
                                        let _e1553 = (_e1548 < 32u);
                                        if _e1553 {
                                            let _e1554 = (_e1548 + 1u);
                                            let _e1558 = (_e1535 + (f32(bitcast<i32>(_e1554)) * 0.09817477f));
                                            let _e1559 = (_e1558 * 2f);
                                            let _e1564 = ((_e695 + (_e1559 * _e1537)) - cos((_e1559 - _e717)));
                                            let _e1568 = select((_e1564 * 0.25f), (_e1564 * -0.25f), (_e1558 < 0f));
                                            let _e1571 = local_4;
                                            phi_2545_ = _e1554;
                                            phi_2548_ = _e1568;
                                            phi_2550_ = select(_e1552, (_e1552 + (_e1568 - _e1550)), (((_e1571 >> bitcast<u32>((_e1548 & 31u))) & 1u) == 0u));
                                        } else {
                                            phi_2545_ = u32();
                                            phi_2548_ = f32();
                                            phi_2550_ = f32();
                                        }
                                        let _e1580 = phi_2545_;
                                        let _e1582 = phi_2548_;
                                        let _e1584 = phi_2550_;
                                        continue;
                                        continuing {
                                            phi_2544_ = _e1580;
                                            phi_2547_ = _e1582;
                                            phi_2549_ = _e1584;
                                            break if !(_e1553);
                                        }
                                    }
                                    let _e1587 = local_5;
                                    phi_3412_ = _e612;
                                    phi_2651_ = (_e616 + 1f);
                                    phi_2652_ = (_e618 + ((_e676 + ((1f - _e676) * 0.05f)) * _e1587));
                                } else {
                                    if (_e152 == 1u) {
                                        phi_2596_ = 0u;
                                        phi_2599_ = 0f;
                                        loop {
                                            let _e1490 = phi_2596_;
                                            let _e1492 = phi_2599_;
                                            local_3 = _e1492;
                                            let _e1493 = (_e1490 < 4u);
                                            if _e1493 {
                                                local = array<type_26, 4>(type_26(4026531855u, 0.0095061f), type_26(251658480u, 0.0270951f), type_26(15732480u, 0.0405571f), type_26(1044480u, 0.0478421f));
                                                if _e1493 {
                                                } else {
                                                    phi_3205_ = true;
                                                    break;
                                                }
                                                let _e1496 = local[_e1490].member;
                                                let _e1499 = local[_e1490].member_1;
                                                let _e1501 = local_2;
                                                phi_2597_ = (_e1490 + 1u);
                                                phi_2600_ = (_e1492 + (f32(bitcast<i32>(countOneBits((_e1501 & _e1496)))) * _e1499));
                                            } else {
                                                phi_2597_ = u32();
                                                phi_2600_ = f32();
                                            }
                                            let _e1510 = phi_2597_;
                                            let _e1512 = phi_2600_;
                                            continue;
                                            continuing {
                                                phi_2596_ = _e1510;
                                                phi_2599_ = _e1512;
                                                phi_3205_ = _e612;
                                                break if !(_e1493);
                                            }
                                        }
                                        let _e1515 = phi_3205_;
                                        phi_3410_ = _e1515;
                                        if _e1515 {
                                            break;
                                        }
                                        let _e1517 = local_3;
                                        let _e1518 = (1f - _e1517);
                                        phi_3418_ = _e1515;
                                        phi_2649_ = (_e616 + _e676);
                                        phi_2650_ = (_e618 + (_e676 * select(0f, select(1f, _e1518, (_e1518 < 1f)), (_e1518 > 0f))));
                                    } else {
                                        let _e1480 = local_1;
                                        phi_3418_ = _e612;
                                        phi_2649_ = (_e616 + 1f);
                                        phi_2650_ = (_e618 + ((f32(bitcast<i32>(countOneBits((_e1480 & 4294967295u)))) * -0.03125f) + 1f));
                                    }
                                    let _e1527 = phi_3418_;
                                    let _e1529 = phi_2649_;
                                    let _e1531 = phi_2650_;
                                    phi_3412_ = _e1527;
                                    phi_2651_ = _e1529;
                                    phi_2652_ = _e1531;
                                }
                                let _e1592 = phi_3412_;
                                let _e1594 = phi_2651_;
                                let _e1596 = phi_2652_;
                                phi_3411_ = _e1592;
                                phi_997_ = (_e614 + 1u);
                                phi_1000_ = _e1594;
                                phi_1002_ = _e1596;
                            } else {
                                phi_3411_ = _e612;
                                phi_997_ = u32();
                                phi_1000_ = f32();
                                phi_1002_ = f32();
                            }
                            let _e1599 = phi_3411_;
                            let _e1601 = phi_997_;
                            let _e1603 = phi_1000_;
                            let _e1605 = phi_1002_;
                            continue;
                            continuing {
                                phi_3326_ = _e1599;
                                phi_996_ = _e1601;
                                phi_999_ = _e1603;
                                phi_1001_ = _e1605;
                                phi_3410_ = _e1599;
                                break if !(_e619);
                            }
                        }
                        let _e1608 = phi_3410_;
                        if _e1608 {
                            break;
                        }
                        let _e1610 = local_6;
                        let _e1613 = local_7;
                        let _e1615 = local_8;
                        phi_2660_ = select(1f, (_e1613 / _e1615), (_e1610 > 0f));
                    } else {
                        phi_2660_ = 1f;
                    }
                    let _e1619 = phi_2660_;
                    if _e607 {
                        let _e1625 = pow(_e1619, _e147.member_6);
                        if (_e1625 != _e1625) {
                            phi_3179_ = true;
                        } else {
                            phi_3179_ = (0.03f >= _e1625);
                        }
                        let _e1629 = phi_3179_;
                        let _e1631 = (select(_e1625, 0.03f, _e1629) * 0.6666667f);
                        phi_2701_ = (bitcast<u32>((floor(((select(0f, select(1f, _e1631, (_e1631 < 1f)), (_e1631 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                    } else {
                        phi_2701_ = (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u);
                    }
                    let _e1643 = phi_2701_;
                    terms.member[_e185] = _e1643;
                    edges.member[_e185] = ((((64u * (bitcast<u32>((floor(select(3f, _e316, (_e316 < 3f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(3f, _e331, (_e331 < 3f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(3f, _e347, (_e347 < 3f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(3f, _e363, (_e363 < 3f))) + 8388608f)) - 1258291200u));
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
