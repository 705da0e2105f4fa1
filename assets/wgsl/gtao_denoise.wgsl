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
    var phi_765_: u32;
    var phi_810_: f32;
    var phi_1551_: vec3<f32>;
    var phi_1601_: type_22;
    var phi_1602_: type_22;
    var phi_1604_: type_22;
    var phi_1605_: type_22;
    var phi_1606_: bool;
    var phi_1610_: type_22;

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
                if (_e351 > 0f) {
                    let _e357 = select(select(u32(_e351), 0u, (_e351 < 0f)), 4294967295u, (_e351 > 4294967000f));
                    phi_765_ = select(_e357, 255u, (255u < _e357));
                } else {
                    phi_765_ = 0u;
                }
                let _e361 = phi_765_;
                phi_1604_ = type_22(_e361, (f32(_e361) * 0.003921569f), _e77);
                phi_1605_ = type_22();
                phi_1606_ = true;
            } else {
                if (_e74 == 0u) {
                    phi_810_ = 10000f;
                } else {
                    phi_810_ = select(0.24000001f, 1.2f, _e77);
                }
                let _e368 = phi_810_;
                let _e369 = bitcast<i32>(_e43.x);
                let _e370 = (_e369 + -1i);
                let _e372 = select(0i, _e370, (0i < _e370));
                let _e374 = (bitcast<i32>(_e53) - 1i);
                let _e377 = bitcast<u32>(select(_e372, _e374, (_e374 < _e372)));
                let _e378 = bitcast<i32>(_e43.y);
                let _e380 = select(0i, _e378, (0i < _e378));
                let _e382 = (bitcast<i32>(_e63) - 1i);
                let _e386 = (_e369 + 1i);
                let _e388 = select(0i, _e386, (0i < _e386));
                let _e391 = bitcast<u32>(select(_e388, _e374, (_e374 < _e388)));
                let _e393 = select(0i, _e369, (0i < _e369));
                let _e396 = bitcast<u32>(select(_e393, _e374, (_e374 < _e393)));
                let _e397 = (_e378 + -1i);
                let _e399 = select(0i, _e397, (0i < _e397));
                let _e403 = (_e378 + 1i);
                let _e405 = select(0i, _e403, (0i < _e403));
                let _e409 = (bitcast<u32>(select(_e380, _e382, (_e382 < _e380))) * _e53);
                let _e410 = (_e409 + _e377);
                let _e413 = edges.member[_e410];
                let _e427 = (_e409 + _e391);
                let _e430 = edges.member[_e427];
                let _e444 = (bitcast<u32>(select(_e399, _e382, (_e382 < _e399))) * _e53);
                let _e445 = (_e444 + _e396);
                let _e448 = edges.member[_e445];
                let _e462 = (bitcast<u32>(select(_e405, _e382, (_e382 < _e405))) * _e53);
                let _e463 = (_e462 + _e396);
                let _e466 = edges.member[_e463];
                let _e483 = ((_e43.y * _e53) + _e43.x);
                let _e486 = edges.member[_e483];
                let _e505 = ((f32(((_e486 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e413 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                let _e506 = ((f32(((_e486 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e430 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                let _e507 = ((f32(((_e486 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e448 & 3u)) * 0.33333334f));
                let _e508 = ((f32((_e486 & 3u)) * 0.33333334f) * (f32(((_e466 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                let _e512 = (1.5f - (((_e505 + _e506) + _e507) + _e508));
                let _e517 = (select(0f, select(1f, _e512, (_e512 < 1f)), (_e512 > 0f)) * 0.33333334f);
                let _e518 = (_e505 + _e517);
                let _e522 = select(0f, select(1f, _e518, (_e518 < 1f)), (_e518 > 0f));
                let _e523 = (_e506 + _e517);
                let _e527 = select(0f, select(1f, _e523, (_e523 < 1f)), (_e523 > 0f));
                let _e528 = (_e507 + _e517);
                let _e532 = select(0f, select(1f, _e528, (_e528 < 1f)), (_e528 > 0f));
                let _e533 = (_e508 + _e517);
                let _e537 = select(0f, select(1f, _e533, (_e533 < 1f)), (_e533 > 0f));
                let _e541 = (((_e522 * (f32(((_e413 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e532 * (f32(((_e448 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e545 = (((_e532 * (f32(((_e448 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e527 * (f32(((_e430 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e549 = (((_e537 * (f32(((_e466 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e522 * (f32((_e413 & 3u)) * 0.33333334f))) * 0.425f);
                let _e553 = (((_e527 * (f32((_e430 & 3u)) * 0.33333334f)) + (_e537 * (f32(((_e466 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e561 = ((((((((_e368 + _e522) + _e527) + _e532) + _e537) + _e541) + _e545) + _e549) + _e553);
                let _e564 = terms_in.member[_e483];
                let _e588 = terms_in.member[_e410];
                let _e616 = terms_in.member[_e427];
                let _e644 = terms_in.member[_e445];
                let _e672 = terms_in.member[_e463];
                let _e701 = terms_in.member[(_e444 + _e377)];
                let _e730 = terms_in.member[(_e444 + _e391)];
                let _e759 = terms_in.member[(_e462 + _e377)];
                let _e788 = terms_in.member[(_e462 + _e391)];
                let _e814 = (((((((((((f32((_e564 & 255u)) * 0.003921569f) * _e368) + ((f32((_e588 & 255u)) * 0.003921569f) * _e522)) + ((f32((_e616 & 255u)) * 0.003921569f) * _e527)) + ((f32((_e644 & 255u)) * 0.003921569f) * _e532)) + ((f32((_e672 & 255u)) * 0.003921569f) * _e537)) + ((f32((_e701 & 255u)) * 0.003921569f) * _e541)) + ((f32((_e730 & 255u)) * 0.003921569f) * _e545)) + ((f32((_e759 & 255u)) * 0.003921569f) * _e549)) + ((f32((_e788 & 255u)) * 0.003921569f) * _e553)) / _e561);
                let _e815 = (((((((((((f32(((_e564 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e368) + ((f32(((_e588 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e522)) + ((f32(((_e616 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e527)) + ((f32(((_e644 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e532)) + ((f32(((_e672 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e537)) + ((f32(((_e701 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e541)) + ((f32(((_e730 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e545)) + ((f32(((_e759 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e549)) + ((f32(((_e788 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e553)) / _e561);
                let _e816 = (((((((((((f32(((_e564 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e368) + ((f32(((_e588 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e522)) + ((f32(((_e616 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e527)) + ((f32(((_e644 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e532)) + ((f32(((_e672 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e537)) + ((f32(((_e701 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e541)) + ((f32(((_e730 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e545)) + ((f32(((_e759 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e549)) + ((f32(((_e788 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e553)) / _e561);
                let _e817 = (((((((((((f32((_e564 >> bitcast<u32>(24i))) * 0.003921569f) * _e368) + ((f32((_e588 >> bitcast<u32>(24i))) * 0.003921569f) * _e522)) + ((f32((_e616 >> bitcast<u32>(24i))) * 0.003921569f) * _e527)) + ((f32((_e644 >> bitcast<u32>(24i))) * 0.003921569f) * _e532)) + ((f32((_e672 >> bitcast<u32>(24i))) * 0.003921569f) * _e537)) + ((f32((_e701 >> bitcast<u32>(24i))) * 0.003921569f) * _e541)) + ((f32((_e730 >> bitcast<u32>(24i))) * 0.003921569f) * _e545)) + ((f32((_e759 >> bitcast<u32>(24i))) * 0.003921569f) * _e549)) + ((f32((_e788 >> bitcast<u32>(24i))) * 0.003921569f) * _e553)) / _e561);
                if _e77 {
                    let _e821 = ((_e814 * 2f) - 1f);
                    let _e822 = ((_e815 * 2f) - 1f);
                    let _e823 = ((_e816 * 2f) - 1f);
                    let _e829 = sqrt((((_e821 * _e821) + (_e822 * _e822)) + (_e823 * _e823)));
                    if (_e829 > 0f) {
                        phi_1551_ = vec3<f32>((_e821 / _e829), (_e822 / _e829), (_e823 / _e829));
                    } else {
                        phi_1551_ = vec3<f32>(0f, 0f, -1f);
                    }
                    let _e836 = phi_1551_;
                    let _e838 = ((_e817 * 382.5f) + 0.5f);
                    let _e843 = select(select(u32(_e838), 0u, (_e838 < 0f)), 4294967295u, (_e838 > 4294967000f));
                    let _e847 = (f32(select(_e843, 255u, (255u < _e843))) * 0.003921569f);
                    let _e854 = ((_e836.x * 0.5f) + 0.5f);
                    let _e855 = ((_e836.y * 0.5f) + 0.5f);
                    let _e856 = ((_e836.z * -0.5f) + 0.5f);
                    let _e862 = ((select(0f, select(1f, _e854, (_e854 < 1f)), (_e854 > 0f)) * 255f) + 0.5f);
                    let _e873 = ((select(0f, select(1f, _e855, (_e855 < 1f)), (_e855 > 0f)) * 255f) + 0.5f);
                    let _e887 = ((select(0f, select(1f, _e856, (_e856 < 1f)), (_e856 > 0f)) * 255f) + 0.5f);
                    let _e901 = ((select(0f, select(1f, _e847, (_e847 < 1f)), (_e847 > 0f)) * 255f) + 0.5f);
                    phi_1601_ = type_22((((select(select(u32(_e862), 0u, (_e862 < 0f)), 4294967295u, (_e862 > 4294967000f)) | (select(select(u32(_e873), 0u, (_e873 < 0f)), 4294967295u, (_e873 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e887), 0u, (_e887 < 0f)), 4294967295u, (_e887 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e901), 0u, (_e901 < 0f)), 4294967295u, (_e901 > 4294967000f)) << bitcast<u32>(24i))), _e847, _e77);
                    phi_1602_ = type_22();
                } else {
                    let _e916 = ((select(0f, select(1f, _e814, (_e814 < 1f)), (_e814 > 0f)) * 255f) + 0.5f);
                    let _e927 = ((select(0f, select(1f, _e815, (_e815 < 1f)), (_e815 > 0f)) * 255f) + 0.5f);
                    let _e941 = ((select(0f, select(1f, _e816, (_e816 < 1f)), (_e816 > 0f)) * 255f) + 0.5f);
                    let _e955 = ((select(0f, select(1f, _e817, (_e817 < 1f)), (_e817 > 0f)) * 255f) + 0.5f);
                    phi_1601_ = type_22();
                    phi_1602_ = type_22((((select(select(u32(_e916), 0u, (_e916 < 0f)), 4294967295u, (_e916 > 4294967000f)) | (select(select(u32(_e927), 0u, (_e927 < 0f)), 4294967295u, (_e927 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e941), 0u, (_e941 < 0f)), 4294967295u, (_e941 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e955), 0u, (_e955 < 0f)), 4294967295u, (_e955 > 4294967000f)) << bitcast<u32>(24i))), 0f, _e77);
                }
                let _e966 = phi_1601_;
                let _e968 = phi_1602_;
                phi_1604_ = _e968;
                phi_1605_ = _e966;
                phi_1606_ = select(true, false, _e77);
            }
            let _e971 = phi_1604_;
            let _e973 = phi_1605_;
            let _e975 = phi_1606_;
            if _e975 {
                phi_1610_ = _e971;
            } else {
                phi_1610_ = _e973;
            }
            let _e977 = phi_1610_;
            let _e979 = ((_e43.y * _e53) + _e43.x);
            terms_out.member[_e979] = _e977.member;
            if _e977.member_2 {
                ao.member[_e979] = _e977.member_1;
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
