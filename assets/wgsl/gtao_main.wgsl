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

struct type_24 {
    member: f32,
    member_1: vec3<f32>,
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
    var phi_190_: type_20;
    var phi_722_: f32;
    var phi_748_: u32;
    var phi_751_: vec3<f32>;
    var phi_753_: f32;
    var phi_923_: u32;
    var phi_926_: f32;
    var phi_928_: f32;
    var phi_981_: f32;
    var phi_1276_: f32;
    var phi_1297_: f32;
    var phi_1336_: f32;
    var phi_1357_: f32;
    var phi_924_: u32;
    var phi_927_: f32;
    var phi_929_: f32;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_1587_: vec3<f32>;
    var phi_749_: u32;
    var phi_752_: vec3<f32>;
    var phi_754_: f32;
    var local_4: f32;
    var local_5: vec3<f32>;
    var phi_1594_: type_24;
    var phi_2310_: bool;
    var phi_1644_: vec3<f32>;
    var phi_1665_: u32;
    var phi_1705_: u32;
    var phi_1706_: u32;

    let _e96 = id_1;
    if (override_type == 0u) {
        let _e99 = params.member;
        phi_190_ = _e99;
    } else {
        let _e108 = params.member.member;
        let _e111 = params.member.member_1;
        let _e114 = params.member.member_10;
        let _e117 = params.member.member_11;
        let _e120 = params.member.member_12;
        let _e123 = params.member.member_14;
        phi_190_ = type_20(_e108, _e111, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e114, _e117, _e120, override_type_9, _e123);
    }
    let _e126 = phi_190_;
    let _e134 = select(select(u32(_e126.member.member.x), 0u, (_e126.member.member.x < 0f)), 4294967295u, (_e126.member.member.x > 4294967000f));
    let _e142 = select(select(u32(_e126.member.member.y), 0u, (_e126.member.member.y < 0f)), 4294967295u, (_e126.member.member.y > 4294967000f));
    if (_e96.x >= _e134) {
    } else {
        if (_e96.y >= _e142) {
        } else {
            let _e148 = ((_e96.y * _e134) + _e96.x);
            let _e151 = mips.member[_e148];
            let _e152 = bitcast<i32>(_e96.x);
            let _e153 = (_e152 + -1i);
            let _e155 = select(0i, _e153, (0i < _e153));
            let _e157 = (bitcast<i32>(_e134) - 1i);
            let _e161 = bitcast<i32>(_e96.y);
            let _e163 = select(0i, _e161, (0i < _e161));
            let _e165 = (bitcast<i32>(_e142) - 1i);
            let _e169 = (bitcast<u32>(select(_e163, _e165, (_e165 < _e163))) * _e134);
            let _e173 = mips.member[(_e169 + bitcast<u32>(select(_e155, _e157, (_e157 < _e155))))];
            let _e174 = (_e152 + 1i);
            let _e176 = select(0i, _e174, (0i < _e174));
            let _e183 = mips.member[(_e169 + bitcast<u32>(select(_e176, _e157, (_e157 < _e176))))];
            let _e185 = select(0i, _e152, (0i < _e152));
            let _e188 = bitcast<u32>(select(_e185, _e157, (_e157 < _e185)));
            let _e189 = (_e161 + -1i);
            let _e191 = select(0i, _e189, (0i < _e189));
            let _e199 = mips.member[((bitcast<u32>(select(_e191, _e165, (_e165 < _e191))) * _e134) + _e188)];
            let _e200 = (_e161 + 1i);
            let _e202 = select(0i, _e200, (0i < _e200));
            let _e210 = mips.member[((bitcast<u32>(select(_e202, _e165, (_e165 < _e202))) * _e134) + _e188)];
            let _e211 = (_e173 - _e151);
            let _e212 = (_e183 - _e151);
            let _e213 = (_e199 - _e151);
            let _e214 = (_e210 - _e151);
            let _e216 = ((_e212 - _e211) * 0.5f);
            let _e218 = ((_e214 - _e213) * 0.5f);
            let _e219 = (_e151 * 0.011f);
            let _e221 = abs(_e211);
            let _e222 = abs((_e211 + _e216));
            let _e228 = (1.25f - (select(_e222, _e221, ((_e221 < _e222) || (_e222 != _e222))) / _e219));
            let _e232 = select(0f, select(1f, _e228, (_e228 < 1f)), (_e228 > 0f));
            let _e234 = abs(_e212);
            let _e235 = abs((_e212 - _e216));
            let _e241 = (1.25f - (select(_e235, _e234, ((_e234 < _e235) || (_e235 != _e235))) / _e219));
            let _e245 = select(0f, select(1f, _e241, (_e241 < 1f)), (_e241 > 0f));
            let _e247 = abs(_e213);
            let _e248 = abs((_e213 + _e218));
            let _e254 = (1.25f - (select(_e248, _e247, ((_e247 < _e248) || (_e248 != _e248))) / _e219));
            let _e258 = select(0f, select(1f, _e254, (_e254 < 1f)), (_e254 > 0f));
            let _e260 = abs(_e214);
            let _e261 = abs((_e214 - _e218));
            let _e267 = (1.25f - (select(_e261, _e260, ((_e260 < _e261) || (_e261 != _e261))) / _e219));
            let _e271 = select(0f, select(1f, _e267, (_e267 < 1f)), (_e267 > 0f));
            let _e277 = round((select(0f, select(1f, _e232, (_e232 < 1f)), (_e232 > 0f)) * 2.9f));
            let _e292 = round((select(0f, select(1f, _e245, (_e245 < 1f)), (_e245 > 0f)) * 2.9f));
            let _e308 = round((select(0f, select(1f, _e258, (_e258 < 1f)), (_e258 > 0f)) * 2.9f));
            let _e324 = round((select(0f, select(1f, _e271, (_e271 < 1f)), (_e271 > 0f)) * 2.9f));
            let _e336 = ((f32(_e152) + 0.5f) / _e126.member.member.x);
            let _e339 = ((f32(_e161) + 0.5f) / _e126.member.member.y);
            let _e340 = (_e151 * 0.99999f);
            let _e347 = ((((_e336 * 2f) - 1f) * _e126.member.member_1.x) * _e340);
            let _e354 = ((((_e339 * -2f) + 1f) * _e126.member.member_1.y) * _e340);
            let _e355 = -(_e347);
            let _e356 = -(_e354);
            let _e357 = (_e151 * -0.99999f);
            let _e364 = (1f / sqrt((((_e355 * _e355) + (_e356 * _e356)) + (_e357 * _e357))));
            let _e365 = (_e355 * _e364);
            let _e366 = (_e356 * _e364);
            let _e367 = (_e357 * _e364);
            let _e370 = normals.member[_e148];
            let _e373 = f32(bitcast<i32>((_e370 & 255u)));
            let _e377 = (select(_e373, (_e373 - 256f), (_e373 >= 128f)) * 0.007874016f);
            let _e380 = select(-1f, _e377, ((_e377 > -1f) || false));
            let _e385 = f32(bitcast<i32>(((_e370 >> bitcast<u32>(8u)) & 255u)));
            let _e389 = (select(_e385, (_e385 - 256f), (_e385 >= 128f)) * 0.007874016f);
            let _e392 = select(-1f, _e389, ((_e389 > -1f) || false));
            let _e394 = (1f - abs(_e380));
            let _e395 = abs(_e392);
            let _e396 = (_e394 - _e395);
            let _e397 = (_e396 < 0f);
            let _e405 = select(_e380, ((1f - _e395) * select(1f, -1f, (_e380 < 0f))), _e397);
            let _e406 = select(_e392, (_e394 * select(1f, -1f, (_e392 < 0f))), _e397);
            let _e413 = (1f / sqrt((((_e405 * _e405) + (_e406 * _e406)) + (_e396 * _e396))));
            let _e414 = (_e405 * _e413);
            let _e415 = (_e406 * _e413);
            let _e416 = (_e396 * _e413);
            let _e417 = -(_e416);
            let _e423 = ((((_e414 * _e365) + (_e415 * _e366)) + (_e417 * _e367)) < 0f);
            let _e426 = select(_e414, -(_e414), _e423);
            let _e427 = select(_e415, -(_e415), _e423);
            let _e428 = select(_e417, _e416, _e423);
            let _e432 = (_e126.member_1 * _e126.member_2);
            let _e436 = (_e432 / (((_e151 * 1.99998f) * _e126.member.member_1.x) / _e126.member.member.x));
            let _e439 = (_e96.x & 63u);
            let _e440 = (_e96.y & 63u);
            let _e443 = select(0u, 1u, ((_e439 & 32u) != 0u));
            let _e446 = select(0u, 1u, ((_e440 & 32u) != 0u));
            let _e450 = (_e446 == 0u);
            let _e452 = (_e450 && (_e443 == 1u));
            let _e455 = select(_e439, (63u - _e439), _e452);
            let _e456 = select(_e440, (63u - _e440), _e452);
            let _e457 = select(_e455, _e456, _e450);
            let _e458 = select(_e456, _e455, _e450);
            let _e461 = select(0u, 1u, ((_e457 & 16u) != 0u));
            let _e464 = select(0u, 1u, ((_e458 & 16u) != 0u));
            let _e469 = (_e464 == 0u);
            let _e471 = (_e469 && (_e461 == 1u));
            let _e474 = select(_e457, (63u - _e457), _e471);
            let _e475 = select(_e458, (63u - _e458), _e471);
            let _e476 = select(_e474, _e475, _e469);
            let _e477 = select(_e475, _e474, _e469);
            let _e480 = select(0u, 1u, ((_e476 & 8u) != 0u));
            let _e483 = select(0u, 1u, ((_e477 & 8u) != 0u));
            let _e488 = (_e483 == 0u);
            let _e490 = (_e488 && (_e480 == 1u));
            let _e493 = select(_e476, (63u - _e476), _e490);
            let _e494 = select(_e477, (63u - _e477), _e490);
            let _e495 = select(_e493, _e494, _e488);
            let _e496 = select(_e494, _e493, _e488);
            let _e499 = select(0u, 1u, ((_e495 & 4u) != 0u));
            let _e502 = select(0u, 1u, ((_e496 & 4u) != 0u));
            let _e507 = (_e502 == 0u);
            let _e509 = (_e507 && (_e499 == 1u));
            let _e512 = select(_e495, (63u - _e495), _e509);
            let _e513 = select(_e496, (63u - _e496), _e509);
            let _e514 = select(_e512, _e513, _e507);
            let _e515 = select(_e513, _e512, _e507);
            let _e518 = select(0u, 1u, ((_e514 & 2u) != 0u));
            let _e521 = select(0u, 1u, ((_e515 & 2u) != 0u));
            let _e526 = (_e521 == 0u);
            let _e528 = (_e526 && (_e518 == 1u));
            let _e531 = select(_e514, (63u - _e514), _e528);
            let _e532 = select(_e515, (63u - _e515), _e528);
            let _e548 = f32(bitcast<i32>((((((((1024u * ((3u * _e443) ^ _e446)) + (256u * ((3u * _e461) ^ _e464))) + (64u * ((3u * _e480) ^ _e483))) + (16u * ((3u * _e499) ^ _e502))) + (4u * ((3u * _e518) ^ _e521))) + ((3u * select(0u, 1u, ((select(_e531, _e532, _e526) & 1u) != 0u))) ^ select(0u, 1u, ((select(_e532, _e531, _e526) & 1u) != 0u)))) + (288u * (_e126.member_11 % 64u)))));
            let _e550 = (0.5f + (_e548 * 0.7548777f));
            let _e554 = (0.5f + (_e548 * 0.5698403f));
            let _e560 = exp2(((2f * _e126.member_7) + 1f));
            let _e565 = select(false, (_e151 < _e126.member.member_3), (_e151 > 0f));
            if _e565 {
                let _e567 = (_e126.member_3 * _e432);
                let _e568 = (_e567 <= 0f);
                if _e568 {
                    phi_722_ = 0f;
                } else {
                    phi_722_ = (1f / _e567);
                }
                let _e571 = phi_722_;
                let _e572 = -(_e571);
                let _e573 = (_e432 * _e571);
                let _e575 = ((10f - _e436) * 0.01f);
                let _e583 = select(1u, _e126.member_8, (1u < _e126.member_8));
                phi_748_ = 0u;
                phi_751_ = vec3<f32>(0f, 0f, 0f);
                phi_753_ = (select(0f, select(1f, _e575, (_e575 < 1f)), (_e575 > 0f)) * 0.5f);
                loop {
                    let _e585 = phi_748_;
                    let _e587 = phi_751_;
                    let _e589 = phi_753_;
                    local_4 = _e589;
                    local_5 = _e587;
                    let _e590 = (_e585 < _e583);
                    if _e590 {
                        let _e597 = ((((_e550 - floor(_e550)) + f32(bitcast<i32>(_e585))) * 3.1415927f) / f32(bitcast<i32>(_e583)));
                        let _e598 = sin(_e597);
                        let _e599 = cos(_e597);
                        let _e605 = ((_e599 * _e365) + (_e598 * _e366));
                        let _e609 = (_e599 - (_e365 * _e605));
                        let _e610 = (_e598 - (_e366 * _e605));
                        let _e611 = -((_e367 * _e605));
                        let _e614 = ((_e610 * _e367) - (_e366 * _e611));
                        let _e617 = ((_e611 * _e365) - (_e367 * _e609));
                        let _e620 = ((_e609 * _e366) - (_e365 * _e610));
                        let _e627 = (1f / sqrt((((_e614 * _e614) + (_e617 * _e617)) + (_e620 * _e620))));
                        let _e628 = (_e614 * _e627);
                        let _e629 = (_e617 * _e627);
                        let _e630 = (_e620 * _e627);
                        let _e635 = (((_e426 * _e628) + (_e427 * _e629)) + (_e428 * _e630));
                        let _e639 = (_e426 - (_e628 * _e635));
                        let _e640 = (_e427 - (_e629 * _e635));
                        let _e641 = (_e428 - (_e630 * _e635));
                        let _e647 = sqrt((((_e639 * _e639) + (_e640 * _e640)) + (_e641 * _e641)));
                        let _e652 = (((_e609 * _e639) + (_e610 * _e640)) + (_e611 * _e641));
                        let _e662 = ((((_e639 * _e365) + (_e640 * _e366)) + (_e641 * _e367)) / _e647);
                        let _e666 = select(0f, select(1f, _e662, (_e662 < 1f)), (_e662 > 0f));
                        let _e667 = abs(_e666);
                        let _e678 = (((_e667 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e667))) >> bitcast<u32>(1i))))));
                        let _e682 = (select(select(0f, -1f, (_e652 < 0f)), 1f, (_e652 > 0f)) * select((3.141593f - _e678), _e678, (_e666 >= 0f)));
                        let _e685 = select(1u, _e126.member_9, (1u < _e126.member_9));
                        let _e687 = cos((_e682 + 1.5707964f));
                        let _e689 = cos((_e682 - 1.5707964f));
                        phi_923_ = 0u;
                        phi_926_ = _e689;
                        phi_928_ = _e687;
                        loop {
                            let _e692 = phi_923_;
                            let _e694 = phi_926_;
                            let _e696 = phi_928_;
                            local = _e694;
                            local_1 = _e694;
                            local_2 = _e696;
                            local_3 = _e696;
                            let _e697 = (_e692 < _e685);
                            if _e697 {
                                let _e703 = ((_e554 - floor(_e554)) + (f32(bitcast<i32>((_e585 + (_e692 * _e685)))) * 0.618034f));
                                let _e712 = (((_e703 - floor(_e703)) + f32(bitcast<i32>(_e692))) * (1f / f32(bitcast<i32>(_e685))));
                                if (_e126.member_4 == 2f) {
                                    phi_981_ = (_e712 * _e712);
                                } else {
                                    phi_981_ = pow(_e712, _e126.member_4);
                                }
                                let _e718 = phi_981_;
                                let _e719 = (_e718 + (1.3f / _e436));
                                let _e720 = ((_e599 * _e436) * _e719);
                                let _e721 = ((-(_e598) * _e436) * _e719);
                                let _e724 = ((_e720 * _e720) + (_e721 * _e721));
                                let _e729 = (select(1u, _e134, (1u < _e134)) * select(1u, _e142, (1u < _e142)));
                                let _e730 = (_e724 > _e560);
                                let _e734 = (_e134 >> bitcast<u32>(1u));
                                let _e738 = (_e142 >> bitcast<u32>(1u));
                                let _e742 = (_e729 + (select(1u, _e734, (1u < _e734)) * select(1u, _e738, (1u < _e738))));
                                let _e744 = (_e724 > (_e560 * 4f));
                                let _e748 = (_e134 >> bitcast<u32>(2u));
                                let _e752 = (_e142 >> bitcast<u32>(2u));
                                let _e756 = (_e742 + (select(1u, _e748, (1u < _e748)) * select(1u, _e752, (1u < _e752))));
                                let _e758 = (_e724 > (_e560 * 16f));
                                let _e762 = (_e134 >> bitcast<u32>(3u));
                                let _e766 = (_e142 >> bitcast<u32>(3u));
                                let _e772 = (_e724 > (_e560 * 64f));
                                let _e774 = select(select(select(select(0u, _e729, _e730), _e742, _e744), _e756, _e758), (_e756 + (select(1u, _e762, (1u < _e762)) * select(1u, _e766, (1u < _e766)))), _e772);
                                let _e775 = (select(select(select(select(0u, 1u, _e730), 2u, _e744), 3u, _e758), 4u, _e772) & 31u);
                                let _e777 = (_e134 >> bitcast<u32>(_e775));
                                let _e779 = select(1u, _e777, (1u < _e777));
                                let _e781 = (_e142 >> bitcast<u32>(_e775));
                                let _e783 = select(1u, _e781, (1u < _e781));
                                let _e786 = (round(_e720) * (1f / _e126.member.member.x));
                                let _e789 = (round(_e721) * (1f / _e126.member.member.y));
                                let _e790 = (_e336 + _e786);
                                let _e791 = (_e339 + _e789);
                                let _e792 = (_e336 - _e786);
                                let _e793 = (_e339 - _e789);
                                let _e795 = f32(bitcast<i32>(_e779));
                                let _e796 = (_e790 * _e795);
                                let _e799 = f32(bitcast<i32>((_e779 - 1u)));
                                let _e809 = f32(bitcast<i32>(_e783));
                                let _e810 = (_e791 * _e809);
                                let _e813 = f32(bitcast<i32>((_e783 - 1u)));
                                let _e827 = mips.member[((_e774 + ((bitcast<u32>((floor(select(0f, select(_e813, _e810, (_e810 < _e813)), (_e810 > 0f))) + 8388608f)) - 1258291200u) * _e779)) + (bitcast<u32>((floor(select(0f, select(_e799, _e796, (_e796 < _e799)), (_e796 > 0f))) + 8388608f)) - 1258291200u))];
                                let _e836 = (_e792 * _e795);
                                let _e845 = (_e793 * _e809);
                                let _e859 = mips.member[((_e774 + ((bitcast<u32>((floor(select(0f, select(_e813, _e845, (_e845 < _e813)), (_e845 > 0f))) + 8388608f)) - 1258291200u) * _e779)) + (bitcast<u32>((floor(select(0f, select(_e799, _e836, (_e836 < _e799)), (_e836 > 0f))) + 8388608f)) - 1258291200u))];
                                let _e868 = (((((_e790 * 2f) - 1f) * _e126.member.member_1.x) * _e827) - _e347);
                                let _e869 = (((((_e791 * -2f) + 1f) * _e126.member.member_1.y) * _e827) - _e354);
                                let _e870 = (_e827 - _e340);
                                let _e873 = ((_e868 * _e868) + (_e869 * _e869));
                                let _e876 = sqrt((_e873 + (_e870 * _e870)));
                                let _e883 = (_e126.member_5 == 0f);
                                if _e883 {
                                    phi_1276_ = _e876;
                                } else {
                                    let _e885 = (_e870 * (1f + _e126.member_5));
                                    phi_1276_ = sqrt((_e873 + (_e885 * _e885)));
                                }
                                let _e890 = phi_1276_;
                                if _e568 {
                                    phi_1297_ = select(0f, 1f, (_e890 <= _e432));
                                } else {
                                    let _e894 = ((_e890 * _e572) + _e573);
                                    phi_1297_ = select(0f, select(1f, _e894, (_e894 < 1f)), (_e894 > 0f));
                                }
                                let _e900 = phi_1297_;
                                let _e903 = (_e687 + ((((((_e868 * _e365) + (_e869 * _e366)) + (_e870 * _e367)) / _e876) - _e687) * _e900));
                                let _e904 = (((((_e792 * 2f) - 1f) * _e126.member.member_1.x) * _e859) - _e347);
                                let _e905 = (((((_e793 * -2f) + 1f) * _e126.member.member_1.y) * _e859) - _e354);
                                let _e906 = (_e859 - _e340);
                                let _e909 = ((_e904 * _e904) + (_e905 * _e905));
                                let _e912 = sqrt((_e909 + (_e906 * _e906)));
                                if _e883 {
                                    phi_1336_ = _e912;
                                } else {
                                    let _e920 = (_e906 * (1f + _e126.member_5));
                                    phi_1336_ = sqrt((_e909 + (_e920 * _e920)));
                                }
                                let _e925 = phi_1336_;
                                if _e568 {
                                    phi_1357_ = select(0f, 1f, (_e925 <= _e432));
                                } else {
                                    let _e929 = ((_e925 * _e572) + _e573);
                                    phi_1357_ = select(0f, select(1f, _e929, (_e929 < 1f)), (_e929 > 0f));
                                }
                                let _e935 = phi_1357_;
                                let _e938 = (_e689 + ((((((_e904 * _e365) + (_e905 * _e366)) + (_e906 * _e367)) / _e912) - _e689) * _e935));
                                phi_924_ = (_e692 + 1u);
                                phi_927_ = select(_e938, _e694, ((_e694 > _e938) || (_e938 != _e938)));
                                phi_929_ = select(_e903, _e696, ((_e696 > _e903) || (_e903 != _e903)));
                            } else {
                                phi_924_ = u32();
                                phi_927_ = f32();
                                phi_929_ = f32();
                            }
                            let _e949 = phi_924_;
                            let _e951 = phi_927_;
                            let _e953 = phi_929_;
                            continue;
                            continuing {
                                phi_923_ = _e949;
                                phi_926_ = _e951;
                                phi_928_ = _e953;
                                break if !(_e697);
                            }
                        }
                        let _e956 = local;
                        let _e957 = abs(_e956);
                        let _e968 = (((_e957 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e957))) >> bitcast<u32>(1i))))));
                        let _e970 = local_1;
                        let _e973 = select((3.141593f - _e968), _e968, (_e970 >= 0f));
                        let _e974 = -(_e973);
                        let _e976 = local_2;
                        let _e977 = abs(_e976);
                        let _e988 = (((_e977 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e977))) >> bitcast<u32>(1i))))));
                        let _e990 = local_3;
                        let _e993 = select((3.141593f - _e988), _e988, (_e990 >= 0f));
                        let _e996 = (_e647 + ((1f - _e647) * 0.05f));
                        let _e997 = (_e973 * -2f);
                        let _e998 = sin(_e682);
                        let _e1004 = (_e993 * 2f);
                        if (_e126.member_13 == 0u) {
                            phi_1587_ = _e587;
                        } else {
                            let _e1020 = ((_e973 * -3f) - _e682);
                            let _e1028 = ((_e993 * 3f) - _e682);
                            let _e1033 = (_e974 + _e682);
                            let _e1035 = (_e993 + _e682);
                            let _e1040 = (((((((sin((_e974 - _e682)) * 6f) - sin(_e1020)) + (sin((_e993 - _e682)) * 6f)) - sin(_e1028)) + (_e998 * 16f)) - ((sin(_e1033) + sin(_e1035)) * 3f)) * 0.083333336f);
                            let _e1052 = (((-(cos(_e1020)) - cos(_e1028)) + (cos(_e682) * 8f)) - ((cos(_e1033) + cos(_e1035)) * 3f));
                            let _e1053 = (_e599 * _e1040);
                            let _e1054 = (_e598 * _e1040);
                            let _e1055 = (_e1052 * -0.083333336f);
                            let _e1056 = (-1f * _e367);
                            let _e1057 = (-1f * _e365);
                            let _e1059 = (1f / (_e1056 + 1f));
                            let _e1060 = (_e1059 * _e366);
                            let _e1064 = (_e1060 * _e1057);
                            let _e1085 = (_e1056 > 0.9997f);
                            let _e1086 = (_e1056 < -0.9997f);
                            phi_1587_ = (_e587 + vec3<f32>((select(select(((((_e1056 + (_e1060 * _e366)) * _e1053) + (_e1064 * _e1054)) + (_e1057 * _e1055)), _e1053, _e1086), _e1053, _e1085) * _e996), (select(select((((_e1064 * _e1053) + ((_e1056 + ((_e1059 * _e1057) * _e1057)) * _e1054)) + (-(_e366) * _e1055)), -(_e1054), _e1086), _e1054, _e1085) * _e996), (select(select((((_e365 * _e1053) + (_e366 * _e1054)) + (_e1056 * _e1055)), (_e1052 * 0.083333336f), _e1086), _e1055, _e1085) * _e996)));
                        }
                        let _e1099 = phi_1587_;
                        phi_749_ = (_e585 + 1u);
                        phi_752_ = _e1099;
                        phi_754_ = (_e589 + ((0.25f * (((_e666 + (_e997 * _e998)) - cos((_e997 - _e682))) + ((_e666 + (_e1004 * _e998)) - cos((_e1004 - _e682))))) * _e996));
                    } else {
                        phi_749_ = u32();
                        phi_752_ = vec3<f32>();
                        phi_754_ = f32();
                    }
                    let _e1102 = phi_749_;
                    let _e1104 = phi_752_;
                    let _e1106 = phi_754_;
                    continue;
                    continuing {
                        phi_748_ = _e1102;
                        phi_751_ = _e1104;
                        phi_753_ = _e1106;
                        break if !(_e590);
                    }
                }
                let _e1111 = local_4;
                let _e1114 = local_5;
                phi_1594_ = type_24((_e1111 / f32(bitcast<i32>(_e583))), _e1114);
            } else {
                phi_1594_ = type_24(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1117 = phi_1594_;
            if _e565 {
                let _e1121 = pow(_e1117.member, _e126.member_6);
                if (_e1121 != _e1121) {
                    phi_2310_ = true;
                } else {
                    phi_2310_ = (0.03f >= _e1121);
                }
                let _e1125 = phi_2310_;
                let _e1126 = select(_e1121, 0.03f, _e1125);
                if (_e126.member_13 == 0u) {
                    let _e1129 = (_e1126 * 0.6666667f);
                    phi_1665_ = (bitcast<u32>((floor(((select(0f, select(1f, _e1129, (_e1129 < 1f)), (_e1129 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                } else {
                    let _e1148 = sqrt((((_e1117.member_1.x * _e1117.member_1.x) + (_e1117.member_1.y * _e1117.member_1.y)) + (_e1117.member_1.z * _e1117.member_1.z)));
                    if (_e1148 > 0f) {
                        phi_1644_ = (_e1117.member_1 / vec3(_e1148));
                    } else {
                        phi_1644_ = vec3<f32>(_e426, _e427, _e428);
                    }
                    let _e1153 = phi_1644_;
                    let _e1154 = (_e1126 * 0.6666667f);
                    let _e1161 = ((_e1153.x * 0.5f) + 0.5f);
                    let _e1162 = ((_e1153.y * 0.5f) + 0.5f);
                    let _e1163 = ((_e1153.z * 0.5f) + 0.5f);
                    phi_1665_ = ((((bitcast<u32>((floor(((select(0f, select(1f, _e1161, (_e1161 < 1f)), (_e1161 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1162, (_e1162 < 1f)), (_e1162 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(8i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1163, (_e1163 < 1f)), (_e1163 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1154, (_e1154 < 1f)), (_e1154 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1214 = phi_1665_;
                phi_1706_ = _e1214;
            } else {
                if (_e126.member_13 == 0u) {
                    phi_1705_ = (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u);
                } else {
                    let _e1224 = (bitcast<u32>((floor(128f) + 8388608f)) - 1258291200u);
                    phi_1705_ = (((_e1224 | (_e1224 << bitcast<u32>(8i))) | ((bitcast<u32>((floor(0.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1243 = phi_1705_;
                phi_1706_ = _e1243;
            }
            let _e1245 = phi_1706_;
            terms.member[_e148] = _e1245;
            edges.member[_e148] = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e277, (_e277 < 3f)), (_e277 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e292, (_e292 < 3f)), (_e292 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e308, (_e308 < 3f)), (_e308 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e324, (_e324 < 3f)), (_e324 > 0f))) + 8388608f)) - 1258291200u));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
