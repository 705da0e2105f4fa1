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
    var phi_173_: f32;
    var phi_747_: f32;
    var phi_805_: f32;
    var phi_1546_: vec3<f32>;
    var phi_1596_: type_22;
    var phi_1597_: type_22;
    var phi_1599_: type_22;
    var phi_1600_: type_22;
    var phi_1601_: bool;
    var phi_1605_: type_22;

    let _e43 = id_1;
    let _e48 = params.member.member.member[0u];
    let _e53 = select(select(u32(_e48), 0u, (_e48 < 0f)), 4294967295u, (_e48 > 4294967000f));
    let _e58 = params.member.member.member[1u];
    let _e63 = select(select(u32(_e58), 0u, (_e58 < 0f)), 4294967295u, (_e58 > 4294967000f));
    if (_e43.x >= _e53) {
    } else {
        if (_e43.y >= _e63) {
        } else {
            let _e70 = params.member.member_12;
            let _e74 = params.member.member_10;
            let _e77 = ((_e70 + 1u) >= select(1u, _e74, (1u < _e74)));
            let _e80 = params.member.member_13;
            if (_e80 == 0u) {
                if (_e74 == 0u) {
                    phi_173_ = 10000f;
                } else {
                    phi_173_ = select(0.24000001f, 1.2f, _e77);
                }
                let _e85 = phi_173_;
                let _e86 = bitcast<i32>(_e43.x);
                let _e87 = (_e86 + -1i);
                let _e89 = select(0i, _e87, (0i < _e87));
                let _e91 = (bitcast<i32>(_e53) - 1i);
                let _e94 = bitcast<u32>(select(_e89, _e91, (_e91 < _e89)));
                let _e95 = bitcast<i32>(_e43.y);
                let _e97 = select(0i, _e95, (0i < _e95));
                let _e99 = (bitcast<i32>(_e63) - 1i);
                let _e103 = (_e86 + 1i);
                let _e105 = select(0i, _e103, (0i < _e103));
                let _e108 = bitcast<u32>(select(_e105, _e91, (_e91 < _e105)));
                let _e110 = select(0i, _e86, (0i < _e86));
                let _e113 = bitcast<u32>(select(_e110, _e91, (_e91 < _e110)));
                let _e114 = (_e95 + -1i);
                let _e116 = select(0i, _e114, (0i < _e114));
                let _e120 = (_e95 + 1i);
                let _e122 = select(0i, _e120, (0i < _e120));
                let _e126 = (bitcast<u32>(select(_e97, _e99, (_e99 < _e97))) * _e53);
                let _e127 = (_e126 + _e94);
                let _e130 = edges.member[_e127];
                let _e144 = (_e126 + _e108);
                let _e147 = edges.member[_e144];
                let _e161 = (bitcast<u32>(select(_e116, _e99, (_e99 < _e116))) * _e53);
                let _e162 = (_e161 + _e113);
                let _e165 = edges.member[_e162];
                let _e179 = (bitcast<u32>(select(_e122, _e99, (_e99 < _e122))) * _e53);
                let _e180 = (_e179 + _e113);
                let _e183 = edges.member[_e180];
                let _e200 = ((_e43.y * _e53) + _e43.x);
                let _e203 = edges.member[_e200];
                let _e222 = ((f32(((_e203 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e130 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                let _e223 = ((f32(((_e203 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e147 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                let _e224 = ((f32(((_e203 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e165 & 3u)) * 0.33333334f));
                let _e225 = ((f32((_e203 & 3u)) * 0.33333334f) * (f32(((_e183 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                let _e229 = (1.5f - (((_e222 + _e223) + _e224) + _e225));
                let _e234 = (select(0f, select(1f, _e229, (_e229 < 1f)), (_e229 > 0f)) * 0.33333334f);
                let _e235 = (_e222 + _e234);
                let _e239 = select(0f, select(1f, _e235, (_e235 < 1f)), (_e235 > 0f));
                let _e240 = (_e223 + _e234);
                let _e244 = select(0f, select(1f, _e240, (_e240 < 1f)), (_e240 > 0f));
                let _e245 = (_e224 + _e234);
                let _e249 = select(0f, select(1f, _e245, (_e245 < 1f)), (_e245 > 0f));
                let _e250 = (_e225 + _e234);
                let _e254 = select(0f, select(1f, _e250, (_e250 < 1f)), (_e250 > 0f));
                let _e258 = (((_e239 * (f32(((_e130 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e249 * (f32(((_e165 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e262 = (((_e249 * (f32(((_e165 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e244 * (f32(((_e147 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e266 = (((_e254 * (f32(((_e183 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e239 * (f32((_e130 & 3u)) * 0.33333334f))) * 0.425f);
                let _e270 = (((_e244 * (f32((_e147 & 3u)) * 0.33333334f)) + (_e254 * (f32(((_e183 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e281 = terms_in.member[_e200];
                let _e287 = terms_in.member[_e127];
                let _e294 = terms_in.member[_e144];
                let _e301 = terms_in.member[_e162];
                let _e308 = terms_in.member[_e180];
                let _e316 = terms_in.member[(_e161 + _e94)];
                let _e324 = terms_in.member[(_e161 + _e108)];
                let _e332 = terms_in.member[(_e179 + _e94)];
                let _e340 = terms_in.member[(_e179 + _e108)];
                let _e345 = (((((((((((f32(_e281) * 0.003921569f) * _e85) + ((f32(_e287) * 0.003921569f) * _e239)) + ((f32(_e294) * 0.003921569f) * _e244)) + ((f32(_e301) * 0.003921569f) * _e249)) + ((f32(_e308) * 0.003921569f) * _e254)) + ((f32(_e316) * 0.003921569f) * _e258)) + ((f32(_e324) * 0.003921569f) * _e262)) + ((f32(_e332) * 0.003921569f) * _e266)) + ((f32(_e340) * 0.003921569f) * _e270)) / ((((((((_e85 + _e239) + _e244) + _e249) + _e254) + _e258) + _e262) + _e266) + _e270));
                if _e77 {
                    phi_747_ = ((_e345 * 382.5f) + 0.5f);
                } else {
                    phi_747_ = ((_e345 * 255f) + 0.5f);
                }
                let _e351 = phi_747_;
                let _e353 = select(0f, _e351, (_e351 > 0f));
                let _e356 = u32(select(255f, _e353, (_e353 < 255f)));
                phi_1599_ = type_22(_e356, (f32(_e356) * 0.003921569f), _e77);
                phi_1600_ = type_22();
                phi_1601_ = true;
            } else {
                if (_e74 == 0u) {
                    phi_805_ = 10000f;
                } else {
                    phi_805_ = select(0.24000001f, 1.2f, _e77);
                }
                let _e363 = phi_805_;
                let _e364 = bitcast<i32>(_e43.x);
                let _e365 = (_e364 + -1i);
                let _e367 = select(0i, _e365, (0i < _e365));
                let _e369 = (bitcast<i32>(_e53) - 1i);
                let _e372 = bitcast<u32>(select(_e367, _e369, (_e369 < _e367)));
                let _e373 = bitcast<i32>(_e43.y);
                let _e375 = select(0i, _e373, (0i < _e373));
                let _e377 = (bitcast<i32>(_e63) - 1i);
                let _e381 = (_e364 + 1i);
                let _e383 = select(0i, _e381, (0i < _e381));
                let _e386 = bitcast<u32>(select(_e383, _e369, (_e369 < _e383)));
                let _e388 = select(0i, _e364, (0i < _e364));
                let _e391 = bitcast<u32>(select(_e388, _e369, (_e369 < _e388)));
                let _e392 = (_e373 + -1i);
                let _e394 = select(0i, _e392, (0i < _e392));
                let _e398 = (_e373 + 1i);
                let _e400 = select(0i, _e398, (0i < _e398));
                let _e404 = (bitcast<u32>(select(_e375, _e377, (_e377 < _e375))) * _e53);
                let _e405 = (_e404 + _e372);
                let _e408 = edges.member[_e405];
                let _e422 = (_e404 + _e386);
                let _e425 = edges.member[_e422];
                let _e439 = (bitcast<u32>(select(_e394, _e377, (_e377 < _e394))) * _e53);
                let _e440 = (_e439 + _e391);
                let _e443 = edges.member[_e440];
                let _e457 = (bitcast<u32>(select(_e400, _e377, (_e377 < _e400))) * _e53);
                let _e458 = (_e457 + _e391);
                let _e461 = edges.member[_e458];
                let _e478 = ((_e43.y * _e53) + _e43.x);
                let _e481 = edges.member[_e478];
                let _e500 = ((f32(((_e481 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e408 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                let _e501 = ((f32(((_e481 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e425 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                let _e502 = ((f32(((_e481 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e443 & 3u)) * 0.33333334f));
                let _e503 = ((f32((_e481 & 3u)) * 0.33333334f) * (f32(((_e461 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                let _e507 = (1.5f - (((_e500 + _e501) + _e502) + _e503));
                let _e512 = (select(0f, select(1f, _e507, (_e507 < 1f)), (_e507 > 0f)) * 0.33333334f);
                let _e513 = (_e500 + _e512);
                let _e517 = select(0f, select(1f, _e513, (_e513 < 1f)), (_e513 > 0f));
                let _e518 = (_e501 + _e512);
                let _e522 = select(0f, select(1f, _e518, (_e518 < 1f)), (_e518 > 0f));
                let _e523 = (_e502 + _e512);
                let _e527 = select(0f, select(1f, _e523, (_e523 < 1f)), (_e523 > 0f));
                let _e528 = (_e503 + _e512);
                let _e532 = select(0f, select(1f, _e528, (_e528 < 1f)), (_e528 > 0f));
                let _e536 = (((_e517 * (f32(((_e408 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e527 * (f32(((_e443 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e540 = (((_e527 * (f32(((_e443 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e522 * (f32(((_e425 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e544 = (((_e532 * (f32(((_e461 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e517 * (f32((_e408 & 3u)) * 0.33333334f))) * 0.425f);
                let _e548 = (((_e522 * (f32((_e425 & 3u)) * 0.33333334f)) + (_e532 * (f32(((_e461 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e556 = ((((((((_e363 + _e517) + _e522) + _e527) + _e532) + _e536) + _e540) + _e544) + _e548);
                let _e559 = terms_in.member[_e478];
                let _e583 = terms_in.member[_e405];
                let _e611 = terms_in.member[_e422];
                let _e639 = terms_in.member[_e440];
                let _e667 = terms_in.member[_e458];
                let _e696 = terms_in.member[(_e439 + _e372)];
                let _e725 = terms_in.member[(_e439 + _e386)];
                let _e754 = terms_in.member[(_e457 + _e372)];
                let _e783 = terms_in.member[(_e457 + _e386)];
                let _e809 = (((((((((((f32((_e559 & 255u)) * 0.003921569f) * _e363) + ((f32((_e583 & 255u)) * 0.003921569f) * _e517)) + ((f32((_e611 & 255u)) * 0.003921569f) * _e522)) + ((f32((_e639 & 255u)) * 0.003921569f) * _e527)) + ((f32((_e667 & 255u)) * 0.003921569f) * _e532)) + ((f32((_e696 & 255u)) * 0.003921569f) * _e536)) + ((f32((_e725 & 255u)) * 0.003921569f) * _e540)) + ((f32((_e754 & 255u)) * 0.003921569f) * _e544)) + ((f32((_e783 & 255u)) * 0.003921569f) * _e548)) / _e556);
                let _e810 = (((((((((((f32(((_e559 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e363) + ((f32(((_e583 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e517)) + ((f32(((_e611 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e522)) + ((f32(((_e639 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e527)) + ((f32(((_e667 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e532)) + ((f32(((_e696 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e536)) + ((f32(((_e725 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e540)) + ((f32(((_e754 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e544)) + ((f32(((_e783 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e548)) / _e556);
                let _e811 = (((((((((((f32(((_e559 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e363) + ((f32(((_e583 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e517)) + ((f32(((_e611 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e522)) + ((f32(((_e639 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e527)) + ((f32(((_e667 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e532)) + ((f32(((_e696 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e536)) + ((f32(((_e725 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e540)) + ((f32(((_e754 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e544)) + ((f32(((_e783 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e548)) / _e556);
                let _e812 = (((((((((((f32((_e559 >> bitcast<u32>(24i))) * 0.003921569f) * _e363) + ((f32((_e583 >> bitcast<u32>(24i))) * 0.003921569f) * _e517)) + ((f32((_e611 >> bitcast<u32>(24i))) * 0.003921569f) * _e522)) + ((f32((_e639 >> bitcast<u32>(24i))) * 0.003921569f) * _e527)) + ((f32((_e667 >> bitcast<u32>(24i))) * 0.003921569f) * _e532)) + ((f32((_e696 >> bitcast<u32>(24i))) * 0.003921569f) * _e536)) + ((f32((_e725 >> bitcast<u32>(24i))) * 0.003921569f) * _e540)) + ((f32((_e754 >> bitcast<u32>(24i))) * 0.003921569f) * _e544)) + ((f32((_e783 >> bitcast<u32>(24i))) * 0.003921569f) * _e548)) / _e556);
                if _e77 {
                    let _e816 = ((_e809 * 2f) - 1f);
                    let _e817 = ((_e810 * 2f) - 1f);
                    let _e818 = ((_e811 * 2f) - 1f);
                    let _e824 = sqrt((((_e816 * _e816) + (_e817 * _e817)) + (_e818 * _e818)));
                    if (_e824 > 0f) {
                        phi_1546_ = vec3<f32>((_e816 / _e824), (_e817 / _e824), (_e818 / _e824));
                    } else {
                        phi_1546_ = vec3<f32>(0f, 0f, -1f);
                    }
                    let _e831 = phi_1546_;
                    let _e833 = ((_e812 * 382.5f) + 0.5f);
                    let _e838 = select(select(u32(_e833), 0u, (_e833 < 0f)), 4294967295u, (_e833 > 4294967000f));
                    let _e842 = (f32(select(_e838, 255u, (255u < _e838))) * 0.003921569f);
                    let _e849 = ((_e831.x * 0.5f) + 0.5f);
                    let _e850 = ((_e831.y * 0.5f) + 0.5f);
                    let _e851 = ((_e831.z * -0.5f) + 0.5f);
                    let _e857 = ((select(0f, select(1f, _e849, (_e849 < 1f)), (_e849 > 0f)) * 255f) + 0.5f);
                    let _e868 = ((select(0f, select(1f, _e850, (_e850 < 1f)), (_e850 > 0f)) * 255f) + 0.5f);
                    let _e882 = ((select(0f, select(1f, _e851, (_e851 < 1f)), (_e851 > 0f)) * 255f) + 0.5f);
                    let _e896 = ((select(0f, select(1f, _e842, (_e842 < 1f)), (_e842 > 0f)) * 255f) + 0.5f);
                    phi_1596_ = type_22((((select(select(u32(_e857), 0u, (_e857 < 0f)), 4294967295u, (_e857 > 4294967000f)) | (select(select(u32(_e868), 0u, (_e868 < 0f)), 4294967295u, (_e868 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e882), 0u, (_e882 < 0f)), 4294967295u, (_e882 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e896), 0u, (_e896 < 0f)), 4294967295u, (_e896 > 4294967000f)) << bitcast<u32>(24i))), _e842, _e77);
                    phi_1597_ = type_22();
                } else {
                    let _e911 = ((select(0f, select(1f, _e809, (_e809 < 1f)), (_e809 > 0f)) * 255f) + 0.5f);
                    let _e922 = ((select(0f, select(1f, _e810, (_e810 < 1f)), (_e810 > 0f)) * 255f) + 0.5f);
                    let _e936 = ((select(0f, select(1f, _e811, (_e811 < 1f)), (_e811 > 0f)) * 255f) + 0.5f);
                    let _e950 = ((select(0f, select(1f, _e812, (_e812 < 1f)), (_e812 > 0f)) * 255f) + 0.5f);
                    phi_1596_ = type_22();
                    phi_1597_ = type_22((((select(select(u32(_e911), 0u, (_e911 < 0f)), 4294967295u, (_e911 > 4294967000f)) | (select(select(u32(_e922), 0u, (_e922 < 0f)), 4294967295u, (_e922 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e936), 0u, (_e936 < 0f)), 4294967295u, (_e936 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e950), 0u, (_e950 < 0f)), 4294967295u, (_e950 > 4294967000f)) << bitcast<u32>(24i))), 0f, _e77);
                }
                let _e961 = phi_1596_;
                let _e963 = phi_1597_;
                phi_1599_ = _e963;
                phi_1600_ = _e961;
                phi_1601_ = select(true, false, _e77);
            }
            let _e966 = phi_1599_;
            let _e968 = phi_1600_;
            let _e970 = phi_1601_;
            if _e970 {
                phi_1605_ = _e966;
            } else {
                phi_1605_ = _e968;
            }
            let _e972 = phi_1605_;
            let _e974 = ((_e43.y * _e53) + _e43.x);
            terms_out.member[_e974] = _e972.member;
            if _e972.member_2 {
                ao.member[_e974] = _e972.member_1;
            }
        }
    }
    return;
}

@compute @workgroup_size(8, 8, 1) 
fn gtao_denoise(@builtin(global_invocation_id) id: vec3<u32>) {
    id_1 = id;
    function_();
}
