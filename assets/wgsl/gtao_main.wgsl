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
    var phi_177_: type_20;
    var phi_822_: f32;
    var phi_848_: u32;
    var phi_851_: vec3<f32>;
    var phi_853_: f32;
    var phi_1021_: u32;
    var phi_1024_: f32;
    var phi_1026_: f32;
    var phi_1083_: f32;
    var phi_1084_: f32;
    var phi_1380_: f32;
    var phi_1401_: f32;
    var phi_1441_: f32;
    var phi_1462_: f32;
    var phi_1022_: u32;
    var phi_1025_: f32;
    var phi_1027_: f32;
    var local: f32;
    var local_1: f32;
    var local_2: f32;
    var local_3: f32;
    var phi_1692_: vec3<f32>;
    var phi_849_: u32;
    var phi_852_: vec3<f32>;
    var phi_854_: f32;
    var local_4: f32;
    var local_5: vec3<f32>;
    var phi_1699_: type_24;
    var phi_1713_: f32;
    var phi_1714_: f32;
    var phi_1766_: vec3<f32>;
    var phi_1787_: u32;
    var phi_1827_: u32;
    var phi_1828_: u32;

    let _e94 = id_1;
    if (override_type == 0u) {
        let _e97 = params.member;
        phi_177_ = _e97;
    } else {
        let _e106 = params.member.member;
        let _e109 = params.member.member_1;
        let _e112 = params.member.member_10;
        let _e115 = params.member.member_11;
        let _e118 = params.member.member_12;
        let _e121 = params.member.member_14;
        phi_177_ = type_20(_e106, _e109, bitcast<f32>(override_type_5), bitcast<f32>(override_type_4), bitcast<f32>(override_type_2), bitcast<f32>(override_type_1), bitcast<f32>(override_type_3), bitcast<f32>(override_type_6), override_type_7, override_type_8, _e112, _e115, _e118, override_type_9, _e121);
    }
    let _e124 = phi_177_;
    let _e132 = select(select(u32(_e124.member.member.x), 0u, (_e124.member.member.x < 0f)), 4294967295u, (_e124.member.member.x > 4294967000f));
    let _e140 = select(select(u32(_e124.member.member.y), 0u, (_e124.member.member.y < 0f)), 4294967295u, (_e124.member.member.y > 4294967000f));
    if (_e94.x >= _e132) {
    } else {
        if (_e94.y >= _e140) {
        } else {
            let _e146 = ((_e94.y * _e132) + _e94.x);
            let _e149 = mips.member[_e146];
            let _e150 = bitcast<i32>(_e94.x);
            let _e151 = (_e150 + -1i);
            let _e153 = select(0i, _e151, (0i < _e151));
            let _e155 = (bitcast<i32>(_e132) - 1i);
            let _e159 = bitcast<i32>(_e94.y);
            let _e161 = select(0i, _e159, (0i < _e159));
            let _e163 = (bitcast<i32>(_e140) - 1i);
            let _e167 = (bitcast<u32>(select(_e161, _e163, (_e163 < _e161))) * _e132);
            let _e171 = mips.member[(_e167 + bitcast<u32>(select(_e153, _e155, (_e155 < _e153))))];
            let _e172 = (_e150 + 1i);
            let _e174 = select(0i, _e172, (0i < _e172));
            let _e181 = mips.member[(_e167 + bitcast<u32>(select(_e174, _e155, (_e155 < _e174))))];
            let _e183 = select(0i, _e150, (0i < _e150));
            let _e186 = bitcast<u32>(select(_e183, _e155, (_e155 < _e183)));
            let _e187 = (_e159 + -1i);
            let _e189 = select(0i, _e187, (0i < _e187));
            let _e197 = mips.member[((bitcast<u32>(select(_e189, _e163, (_e163 < _e189))) * _e132) + _e186)];
            let _e198 = (_e159 + 1i);
            let _e200 = select(0i, _e198, (0i < _e198));
            let _e208 = mips.member[((bitcast<u32>(select(_e200, _e163, (_e163 < _e200))) * _e132) + _e186)];
            let _e209 = (_e171 - _e149);
            let _e210 = (_e181 - _e149);
            let _e211 = (_e197 - _e149);
            let _e212 = (_e208 - _e149);
            let _e214 = ((_e210 - _e209) * 0.5f);
            let _e216 = ((_e212 - _e211) * 0.5f);
            let _e217 = (_e149 * 0.011f);
            let _e219 = abs(_e209);
            let _e220 = abs((_e209 + _e214));
            let _e226 = (1.25f - (select(_e220, _e219, ((_e219 < _e220) || (_e220 != _e220))) / _e217));
            let _e230 = select(0f, select(1f, _e226, (_e226 < 1f)), (_e226 > 0f));
            let _e232 = abs(_e210);
            let _e233 = abs((_e210 - _e214));
            let _e239 = (1.25f - (select(_e233, _e232, ((_e232 < _e233) || (_e233 != _e233))) / _e217));
            let _e243 = select(0f, select(1f, _e239, (_e239 < 1f)), (_e239 > 0f));
            let _e245 = abs(_e211);
            let _e246 = abs((_e211 + _e216));
            let _e252 = (1.25f - (select(_e246, _e245, ((_e245 < _e246) || (_e246 != _e246))) / _e217));
            let _e256 = select(0f, select(1f, _e252, (_e252 < 1f)), (_e252 > 0f));
            let _e258 = abs(_e212);
            let _e259 = abs((_e212 - _e216));
            let _e265 = (1.25f - (select(_e259, _e258, ((_e258 < _e259) || (_e259 != _e259))) / _e217));
            let _e269 = select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f));
            let _e275 = round((select(0f, select(1f, _e230, (_e230 < 1f)), (_e230 > 0f)) * 2.9f));
            let _e290 = round((select(0f, select(1f, _e243, (_e243 < 1f)), (_e243 > 0f)) * 2.9f));
            let _e306 = round((select(0f, select(1f, _e256, (_e256 < 1f)), (_e256 > 0f)) * 2.9f));
            let _e322 = round((select(0f, select(1f, _e269, (_e269 < 1f)), (_e269 > 0f)) * 2.9f));
            let _e334 = ((f32(_e150) + 0.5f) / _e124.member.member.x);
            let _e337 = ((f32(_e159) + 0.5f) / _e124.member.member.y);
            let _e338 = (_e149 * 0.99999f);
            let _e345 = ((((_e334 * 2f) - 1f) * _e124.member.member_1.x) * _e338);
            let _e352 = ((((_e337 * -2f) + 1f) * _e124.member.member_1.y) * _e338);
            let _e353 = -(_e345);
            let _e354 = -(_e352);
            let _e355 = (_e149 * -0.99999f);
            let _e362 = (1f / sqrt((((_e353 * _e353) + (_e354 * _e354)) + (_e355 * _e355))));
            let _e363 = (_e353 * _e362);
            let _e364 = (_e354 * _e362);
            let _e365 = (_e355 * _e362);
            let _e368 = normals.member[_e146];
            let _e371 = f32(bitcast<i32>((_e368 & 255u)));
            let _e375 = (select(_e371, (_e371 - 256f), (_e371 >= 128f)) * 0.007874016f);
            let _e378 = select(-1f, _e375, ((_e375 > -1f) || false));
            let _e383 = f32(bitcast<i32>(((_e368 >> bitcast<u32>(8u)) & 255u)));
            let _e387 = (select(_e383, (_e383 - 256f), (_e383 >= 128f)) * 0.007874016f);
            let _e390 = select(-1f, _e387, ((_e387 > -1f) || false));
            let _e392 = (1f - abs(_e378));
            let _e393 = abs(_e390);
            let _e394 = (_e392 - _e393);
            let _e395 = (_e394 < 0f);
            let _e403 = select(_e378, ((1f - _e393) * select(1f, -1f, (_e378 < 0f))), _e395);
            let _e404 = select(_e390, (_e392 * select(1f, -1f, (_e390 < 0f))), _e395);
            let _e411 = (1f / sqrt((((_e403 * _e403) + (_e404 * _e404)) + (_e394 * _e394))));
            let _e412 = (_e403 * _e411);
            let _e413 = (_e404 * _e411);
            let _e414 = (_e394 * _e411);
            let _e415 = -(_e414);
            let _e421 = ((((_e412 * _e363) + (_e413 * _e364)) + (_e415 * _e365)) < 0f);
            let _e424 = select(_e412, -(_e412), _e421);
            let _e425 = select(_e413, -(_e413), _e421);
            let _e426 = select(_e415, _e414, _e421);
            let _e430 = (_e124.member_1 * _e124.member_2);
            let _e434 = (_e430 / (((_e149 * 1.99998f) * _e124.member.member_1.x) / _e124.member.member.x));
            let _e437 = (_e94.x & 63u);
            let _e438 = (_e94.y & 63u);
            let _e441 = ((_e437 >> bitcast<u32>(5u)) & 1u);
            let _e444 = ((_e438 >> bitcast<u32>(5u)) & 1u);
            let _e448 = (_e444 ^ 1u);
            let _e450 = ((_e441 & _e448) * 63u);
            let _e451 = (_e437 ^ _e450);
            let _e452 = (_e438 ^ _e450);
            let _e454 = ((_e451 ^ _e452) * _e448);
            let _e455 = (_e451 ^ _e454);
            let _e456 = (_e452 ^ _e454);
            let _e459 = ((_e455 >> bitcast<u32>(4u)) & 1u);
            let _e462 = ((_e456 >> bitcast<u32>(4u)) & 1u);
            let _e467 = (_e462 ^ 1u);
            let _e469 = ((_e459 & _e467) * 63u);
            let _e470 = (_e455 ^ _e469);
            let _e471 = (_e456 ^ _e469);
            let _e473 = ((_e470 ^ _e471) * _e467);
            let _e474 = (_e470 ^ _e473);
            let _e475 = (_e471 ^ _e473);
            let _e478 = ((_e474 >> bitcast<u32>(3u)) & 1u);
            let _e481 = ((_e475 >> bitcast<u32>(3u)) & 1u);
            let _e486 = (_e481 ^ 1u);
            let _e488 = ((_e478 & _e486) * 63u);
            let _e489 = (_e474 ^ _e488);
            let _e490 = (_e475 ^ _e488);
            let _e492 = ((_e489 ^ _e490) * _e486);
            let _e493 = (_e489 ^ _e492);
            let _e494 = (_e490 ^ _e492);
            let _e497 = ((_e493 >> bitcast<u32>(2u)) & 1u);
            let _e500 = ((_e494 >> bitcast<u32>(2u)) & 1u);
            let _e505 = (_e500 ^ 1u);
            let _e507 = ((_e497 & _e505) * 63u);
            let _e508 = (_e493 ^ _e507);
            let _e509 = (_e494 ^ _e507);
            let _e511 = ((_e508 ^ _e509) * _e505);
            let _e512 = (_e508 ^ _e511);
            let _e513 = (_e509 ^ _e511);
            let _e516 = ((_e512 >> bitcast<u32>(1u)) & 1u);
            let _e519 = ((_e513 >> bitcast<u32>(1u)) & 1u);
            let _e524 = (_e519 ^ 1u);
            let _e526 = ((_e516 & _e524) * 63u);
            let _e527 = (_e512 ^ _e526);
            let _e528 = (_e513 ^ _e526);
            let _e530 = ((_e527 ^ _e528) * _e524);
            let _e542 = f32(bitcast<i32>((((((((((_e441 * 3u) ^ _e444) * 1024u) + (((_e459 * 3u) ^ _e462) * 256u)) + (((_e478 * 3u) ^ _e481) * 64u)) + (((_e497 * 3u) ^ _e500) * 16u)) + (((_e516 * 3u) ^ _e519) * 4u)) + ((((_e527 ^ _e530) & 1u) * 3u) ^ ((_e528 ^ _e530) & 1u))) + (288u * (_e124.member_11 % 64u)))));
            let _e544 = ((_e542 * 0.7548777f) + 0.5f);
            let _e548 = ((_e542 * 0.5698403f) + 0.5f);
            let _e554 = exp2(((2f * _e124.member_7) + 1f));
            let _e559 = select(false, (_e149 < _e124.member.member_3), (_e149 > 0f));
            if _e559 {
                let _e561 = (_e124.member_3 * _e430);
                let _e562 = (_e561 <= 0f);
                if _e562 {
                    phi_822_ = 0f;
                } else {
                    phi_822_ = (1f / _e561);
                }
                let _e565 = phi_822_;
                let _e566 = -(_e565);
                let _e567 = (_e430 * _e565);
                let _e569 = ((10f - _e434) * 0.01f);
                let _e577 = select(1u, _e124.member_8, (1u < _e124.member_8));
                phi_848_ = 0u;
                phi_851_ = vec3<f32>(0f, 0f, 0f);
                phi_853_ = (select(0f, select(1f, _e569, (_e569 < 1f)), (_e569 > 0f)) * 0.5f);
                loop {
                    let _e579 = phi_848_;
                    let _e581 = phi_851_;
                    let _e583 = phi_853_;
                    local_4 = _e583;
                    local_5 = _e581;
                    let _e584 = (_e579 < _e577);
                    if _e584 {
                        let _e591 = ((((_e544 - floor(_e544)) + f32(bitcast<i32>(_e579))) * 3.1415927f) / f32(bitcast<i32>(_e577)));
                        let _e592 = sin(_e591);
                        let _e593 = cos(_e591);
                        let _e599 = ((_e593 * _e363) + (_e592 * _e364));
                        let _e603 = (_e593 - (_e363 * _e599));
                        let _e604 = (_e592 - (_e364 * _e599));
                        let _e605 = -((_e365 * _e599));
                        let _e608 = ((_e604 * _e365) - (_e364 * _e605));
                        let _e611 = ((_e605 * _e363) - (_e365 * _e603));
                        let _e614 = ((_e603 * _e364) - (_e363 * _e604));
                        let _e621 = (1f / sqrt((((_e608 * _e608) + (_e611 * _e611)) + (_e614 * _e614))));
                        let _e622 = (_e608 * _e621);
                        let _e623 = (_e611 * _e621);
                        let _e624 = (_e614 * _e621);
                        let _e629 = (((_e424 * _e622) + (_e425 * _e623)) + (_e426 * _e624));
                        let _e633 = (_e424 - (_e622 * _e629));
                        let _e634 = (_e425 - (_e623 * _e629));
                        let _e635 = (_e426 - (_e624 * _e629));
                        let _e641 = sqrt((((_e633 * _e633) + (_e634 * _e634)) + (_e635 * _e635)));
                        let _e646 = (((_e603 * _e633) + (_e604 * _e634)) + (_e605 * _e635));
                        let _e656 = ((((_e633 * _e363) + (_e634 * _e364)) + (_e635 * _e365)) / _e641);
                        let _e660 = select(0f, select(1f, _e656, (_e656 < 1f)), (_e656 > 0f));
                        let _e661 = abs(_e660);
                        let _e672 = (((_e661 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e661))) >> bitcast<u32>(1i))))));
                        let _e676 = (select(select(0f, -1f, (_e646 < 0f)), 1f, (_e646 > 0f)) * select((3.141593f - _e672), _e672, (_e660 >= 0f)));
                        let _e679 = select(1u, _e124.member_9, (1u < _e124.member_9));
                        let _e680 = sin(_e676);
                        let _e681 = -(_e680);
                        phi_1021_ = 0u;
                        phi_1024_ = _e680;
                        phi_1026_ = _e681;
                        loop {
                            let _e684 = phi_1021_;
                            let _e686 = phi_1024_;
                            let _e688 = phi_1026_;
                            local = _e686;
                            local_1 = _e686;
                            local_2 = _e688;
                            local_3 = _e688;
                            let _e689 = (_e684 < _e679);
                            if _e689 {
                                let _e695 = ((_e548 - floor(_e548)) + (f32(bitcast<i32>((_e579 + (_e684 * _e679)))) * 0.618034f));
                                let _e704 = (((_e695 - floor(_e695)) + f32(bitcast<i32>(_e684))) * (1f / f32(bitcast<i32>(_e679))));
                                if (_e124.member_4 == 2f) {
                                    phi_1084_ = (_e704 * _e704);
                                } else {
                                    if (_e124.member_4 == 1f) {
                                        phi_1083_ = _e704;
                                    } else {
                                        phi_1083_ = pow(_e704, _e124.member_4);
                                    }
                                    let _e711 = phi_1083_;
                                    phi_1084_ = _e711;
                                }
                                let _e713 = phi_1084_;
                                let _e714 = (_e713 + (1.3f / _e434));
                                let _e715 = ((_e593 * _e434) * _e714);
                                let _e716 = ((-(_e592) * _e434) * _e714);
                                let _e719 = ((_e715 * _e715) + (_e716 * _e716));
                                let _e724 = (select(1u, _e132, (1u < _e132)) * select(1u, _e140, (1u < _e140)));
                                let _e725 = (_e719 > _e554);
                                let _e729 = (_e132 >> bitcast<u32>(1u));
                                let _e733 = (_e140 >> bitcast<u32>(1u));
                                let _e737 = (_e724 + (select(1u, _e729, (1u < _e729)) * select(1u, _e733, (1u < _e733))));
                                let _e739 = (_e719 > (_e554 * 4f));
                                let _e743 = (_e132 >> bitcast<u32>(2u));
                                let _e747 = (_e140 >> bitcast<u32>(2u));
                                let _e751 = (_e737 + (select(1u, _e743, (1u < _e743)) * select(1u, _e747, (1u < _e747))));
                                let _e753 = (_e719 > (_e554 * 16f));
                                let _e757 = (_e132 >> bitcast<u32>(3u));
                                let _e761 = (_e140 >> bitcast<u32>(3u));
                                let _e767 = (_e719 > (_e554 * 64f));
                                let _e769 = select(select(select(select(0u, _e724, _e725), _e737, _e739), _e751, _e753), (_e751 + (select(1u, _e757, (1u < _e757)) * select(1u, _e761, (1u < _e761)))), _e767);
                                let _e770 = (select(select(select(select(0u, 1u, _e725), 2u, _e739), 3u, _e753), 4u, _e767) & 31u);
                                let _e772 = (_e132 >> bitcast<u32>(_e770));
                                let _e774 = select(1u, _e772, (1u < _e772));
                                let _e776 = (_e140 >> bitcast<u32>(_e770));
                                let _e778 = select(1u, _e776, (1u < _e776));
                                let _e781 = (round(_e715) * (1f / _e124.member.member.x));
                                let _e784 = (round(_e716) * (1f / _e124.member.member.y));
                                let _e785 = (_e334 + _e781);
                                let _e786 = (_e337 + _e784);
                                let _e787 = (_e334 - _e781);
                                let _e788 = (_e337 - _e784);
                                let _e790 = f32(bitcast<i32>(_e774));
                                let _e791 = (_e785 * _e790);
                                let _e794 = f32(bitcast<i32>((_e774 - 1u)));
                                let _e804 = f32(bitcast<i32>(_e778));
                                let _e805 = (_e786 * _e804);
                                let _e808 = f32(bitcast<i32>((_e778 - 1u)));
                                let _e822 = mips.member[((_e769 + ((bitcast<u32>((floor(select(0f, select(_e808, _e805, (_e805 < _e808)), (_e805 > 0f))) + 8388608f)) - 1258291200u) * _e774)) + (bitcast<u32>((floor(select(0f, select(_e794, _e791, (_e791 < _e794)), (_e791 > 0f))) + 8388608f)) - 1258291200u))];
                                let _e831 = (_e787 * _e790);
                                let _e840 = (_e788 * _e804);
                                let _e854 = mips.member[((_e769 + ((bitcast<u32>((floor(select(0f, select(_e808, _e840, (_e840 < _e808)), (_e840 > 0f))) + 8388608f)) - 1258291200u) * _e774)) + (bitcast<u32>((floor(select(0f, select(_e794, _e831, (_e831 < _e794)), (_e831 > 0f))) + 8388608f)) - 1258291200u))];
                                let _e863 = (((((_e785 * 2f) - 1f) * _e124.member.member_1.x) * _e822) - _e345);
                                let _e864 = (((((_e786 * -2f) + 1f) * _e124.member.member_1.y) * _e822) - _e352);
                                let _e865 = (_e822 - _e338);
                                let _e868 = ((_e863 * _e863) + (_e864 * _e864));
                                let _e870 = (_e868 + (_e865 * _e865));
                                let _e871 = inverseSqrt(_e870);
                                let _e879 = (_e124.member_5 == 0f);
                                if _e879 {
                                    phi_1380_ = (_e870 * _e871);
                                } else {
                                    let _e881 = (_e865 * (1f + _e124.member_5));
                                    phi_1380_ = sqrt((_e868 + (_e881 * _e881)));
                                }
                                let _e886 = phi_1380_;
                                if _e562 {
                                    phi_1401_ = select(0f, 1f, (_e886 <= _e430));
                                } else {
                                    let _e890 = ((_e886 * _e566) + _e567);
                                    phi_1401_ = select(0f, select(1f, _e890, (_e890 < 1f)), (_e890 > 0f));
                                }
                                let _e896 = phi_1401_;
                                let _e899 = (_e681 + ((((((_e863 * _e363) + (_e864 * _e364)) + (_e865 * _e365)) * _e871) - _e681) * _e896));
                                let _e900 = (((((_e787 * 2f) - 1f) * _e124.member.member_1.x) * _e854) - _e345);
                                let _e901 = (((((_e788 * -2f) + 1f) * _e124.member.member_1.y) * _e854) - _e352);
                                let _e902 = (_e854 - _e338);
                                let _e905 = ((_e900 * _e900) + (_e901 * _e901));
                                let _e907 = (_e905 + (_e902 * _e902));
                                let _e908 = inverseSqrt(_e907);
                                if _e879 {
                                    phi_1441_ = (_e907 * _e908);
                                } else {
                                    let _e917 = (_e902 * (1f + _e124.member_5));
                                    phi_1441_ = sqrt((_e905 + (_e917 * _e917)));
                                }
                                let _e922 = phi_1441_;
                                if _e562 {
                                    phi_1462_ = select(0f, 1f, (_e922 <= _e430));
                                } else {
                                    let _e926 = ((_e922 * _e566) + _e567);
                                    phi_1462_ = select(0f, select(1f, _e926, (_e926 < 1f)), (_e926 > 0f));
                                }
                                let _e932 = phi_1462_;
                                let _e935 = (_e680 + ((((((_e900 * _e363) + (_e901 * _e364)) + (_e902 * _e365)) * _e908) - _e680) * _e932));
                                phi_1022_ = (_e684 + 1u);
                                phi_1025_ = select(_e935, _e686, ((_e686 > _e935) || (_e935 != _e935)));
                                phi_1027_ = select(_e899, _e688, ((_e688 > _e899) || (_e899 != _e899)));
                            } else {
                                phi_1022_ = u32();
                                phi_1025_ = f32();
                                phi_1027_ = f32();
                            }
                            let _e946 = phi_1022_;
                            let _e948 = phi_1025_;
                            let _e950 = phi_1027_;
                            continue;
                            continuing {
                                phi_1021_ = _e946;
                                phi_1024_ = _e948;
                                phi_1026_ = _e950;
                                break if !(_e689);
                            }
                        }
                        let _e953 = local;
                        let _e954 = abs(_e953);
                        let _e965 = (((_e954 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e954))) >> bitcast<u32>(1i))))));
                        let _e967 = local_1;
                        let _e970 = select((3.141593f - _e965), _e965, (_e967 >= 0f));
                        let _e971 = -(_e970);
                        let _e973 = local_2;
                        let _e974 = abs(_e973);
                        let _e985 = (((_e974 * -0.156583f) + 1.570796f) * bitcast<f32>((532487669u + bitcast<u32>((bitcast<i32>(bitcast<u32>((1f - _e974))) >> bitcast<u32>(1i))))));
                        let _e987 = local_3;
                        let _e990 = select((3.141593f - _e985), _e985, (_e987 >= 0f));
                        let _e993 = (_e641 + ((1f - _e641) * 0.05f));
                        let _e994 = (_e970 * -2f);
                        let _e1000 = (_e990 * 2f);
                        if (_e124.member_13 == 0u) {
                            phi_1692_ = _e581;
                        } else {
                            let _e1016 = ((_e970 * -3f) - _e676);
                            let _e1024 = ((_e990 * 3f) - _e676);
                            let _e1029 = (_e971 + _e676);
                            let _e1031 = (_e990 + _e676);
                            let _e1036 = (((((((sin((_e971 - _e676)) * 6f) - sin(_e1016)) + (sin((_e990 - _e676)) * 6f)) - sin(_e1024)) + (_e680 * 16f)) - ((sin(_e1029) + sin(_e1031)) * 3f)) * 0.083333336f);
                            let _e1048 = (((-(cos(_e1016)) - cos(_e1024)) + (cos(_e676) * 8f)) - ((cos(_e1029) + cos(_e1031)) * 3f));
                            let _e1049 = (_e593 * _e1036);
                            let _e1050 = (_e592 * _e1036);
                            let _e1051 = (_e1048 * -0.083333336f);
                            let _e1052 = (-1f * _e365);
                            let _e1053 = (-1f * _e363);
                            let _e1055 = (1f / (_e1052 + 1f));
                            let _e1056 = (_e1055 * _e364);
                            let _e1060 = (_e1056 * _e1053);
                            let _e1081 = (_e1052 > 0.9997f);
                            let _e1082 = (_e1052 < -0.9997f);
                            phi_1692_ = (_e581 + vec3<f32>((select(select(((((_e1052 + (_e1056 * _e364)) * _e1049) + (_e1060 * _e1050)) + (_e1053 * _e1051)), _e1049, _e1082), _e1049, _e1081) * _e993), (select(select((((_e1060 * _e1049) + ((_e1052 + ((_e1055 * _e1053) * _e1053)) * _e1050)) + (-(_e364) * _e1051)), -(_e1050), _e1082), _e1050, _e1081) * _e993), (select(select((((_e363 * _e1049) + (_e364 * _e1050)) + (_e1052 * _e1051)), (_e1048 * 0.083333336f), _e1082), _e1051, _e1081) * _e993)));
                        }
                        let _e1095 = phi_1692_;
                        phi_849_ = (_e579 + 1u);
                        phi_852_ = _e1095;
                        phi_854_ = (_e583 + ((0.25f * (((_e660 + (_e994 * _e680)) - cos((_e994 - _e676))) + ((_e660 + (_e1000 * _e680)) - cos((_e1000 - _e676))))) * _e993));
                    } else {
                        phi_849_ = u32();
                        phi_852_ = vec3<f32>();
                        phi_854_ = f32();
                    }
                    let _e1098 = phi_849_;
                    let _e1100 = phi_852_;
                    let _e1102 = phi_854_;
                    continue;
                    continuing {
                        phi_848_ = _e1098;
                        phi_851_ = _e1100;
                        phi_853_ = _e1102;
                        break if !(_e584);
                    }
                }
                let _e1107 = local_4;
                let _e1110 = local_5;
                phi_1699_ = type_24((_e1107 / f32(bitcast<i32>(_e577))), _e1110);
            } else {
                phi_1699_ = type_24(1f, vec3<f32>(0f, 0f, 0f));
            }
            let _e1113 = phi_1699_;
            if (_e124.member_6 == 2f) {
                phi_1714_ = (_e1113.member * _e1113.member);
            } else {
                if (_e124.member_6 == 1f) {
                    phi_1713_ = _e1113.member;
                } else {
                    phi_1713_ = pow(_e1113.member, _e124.member_6);
                }
                let _e1122 = phi_1713_;
                phi_1714_ = _e1122;
            }
            let _e1124 = phi_1714_;
            let _e1127 = select(0.03f, _e1124, ((_e1124 > 0.03f) || false));
            if _e559 {
                if (_e124.member_13 == 0u) {
                    let _e1130 = (_e1127 * 0.6666667f);
                    phi_1787_ = (bitcast<u32>((floor(((select(0f, select(1f, _e1130, (_e1130 < 1f)), (_e1130 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u);
                } else {
                    let _e1149 = sqrt((((_e1113.member_1.x * _e1113.member_1.x) + (_e1113.member_1.y * _e1113.member_1.y)) + (_e1113.member_1.z * _e1113.member_1.z)));
                    if (_e1149 > 0f) {
                        phi_1766_ = (_e1113.member_1 / vec3(_e1149));
                    } else {
                        phi_1766_ = vec3<f32>(_e424, _e425, _e426);
                    }
                    let _e1154 = phi_1766_;
                    let _e1155 = (_e1127 * 0.6666667f);
                    let _e1162 = ((_e1154.x * 0.5f) + 0.5f);
                    let _e1163 = ((_e1154.y * 0.5f) + 0.5f);
                    let _e1164 = ((_e1154.z * 0.5f) + 0.5f);
                    phi_1787_ = ((((bitcast<u32>((floor(((select(0f, select(1f, _e1162, (_e1162 < 1f)), (_e1162 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1163, (_e1163 < 1f)), (_e1163 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(8i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1164, (_e1164 < 1f)), (_e1164 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e1155, (_e1155 < 1f)), (_e1155 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1215 = phi_1787_;
                phi_1828_ = _e1215;
            } else {
                if (_e124.member_13 == 0u) {
                    phi_1827_ = (bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u);
                } else {
                    let _e1225 = (bitcast<u32>((floor(128f) + 8388608f)) - 1258291200u);
                    phi_1827_ = (((_e1225 | (_e1225 << bitcast<u32>(8i))) | ((bitcast<u32>((floor(0.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(170.5f) + 8388608f)) - 1258291200u) << bitcast<u32>(24i)));
                }
                let _e1244 = phi_1827_;
                phi_1828_ = _e1244;
            }
            let _e1246 = phi_1828_;
            terms.member[_e146] = _e1246;
            edges.member[_e146] = ((((64u * (bitcast<u32>((floor(select(0f, select(3f, _e275, (_e275 < 3f)), (_e275 > 0f))) + 8388608f)) - 1258291200u)) + (16u * (bitcast<u32>((floor(select(0f, select(3f, _e290, (_e290 < 3f)), (_e290 > 0f))) + 8388608f)) - 1258291200u))) + (4u * (bitcast<u32>((floor(select(0f, select(3f, _e306, (_e306 < 3f)), (_e306 > 0f))) + 8388608f)) - 1258291200u))) + (bitcast<u32>((floor(select(0f, select(3f, _e322, (_e322 < 3f)), (_e322 > 0f))) + 8388608f)) - 1258291200u));
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_main(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
