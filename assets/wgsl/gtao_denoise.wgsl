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
    var phi_175_: f32;
    var phi_749_: f32;
    var phi_767_: u32;
    var phi_812_: f32;
    var phi_1553_: vec3<f32>;
    var phi_1603_: type_22;
    var phi_1604_: type_22;
    var phi_1606_: type_22;
    var phi_1607_: type_22;
    var phi_1608_: bool;
    var phi_1612_: type_22;

    switch bitcast<i32>(0u) {
        default: {
            let _e44 = id_1;
            let _e53 = params.member.member.member[0u];
            let _e58 = select(select(u32(_e53), 0u, (_e53 < 0f)), 4294967295u, (_e53 > 4294967000f));
            let _e63 = params.member.member.member[1u];
            let _e68 = select(select(u32(_e63), 0u, (_e63 < 0f)), 4294967295u, (_e63 > 4294967000f));
            if (_e44.x >= _e58) {
            } else {
                if (_e44.y >= _e68) {
                } else {
                    let _e75 = params.member.member_12;
                    let _e79 = params.member.member_10;
                    let _e82 = ((_e75 + 1u) >= select(1u, _e79, (1u < _e79)));
                    let _e85 = params.member.member_13;
                    if (_e85 == 0u) {
                        if (_e79 == 0u) {
                            phi_175_ = 10000f;
                        } else {
                            phi_175_ = select(0.24000001f, 1.2f, _e82);
                        }
                        let _e90 = phi_175_;
                        let _e91 = bitcast<i32>(_e44.x);
                        let _e92 = (_e91 + -1i);
                        let _e94 = select(0i, _e92, (0i < _e92));
                        let _e96 = (bitcast<i32>(_e58) - 1i);
                        let _e99 = bitcast<u32>(select(_e94, _e96, (_e96 < _e94)));
                        let _e100 = bitcast<i32>(_e44.y);
                        let _e102 = select(0i, _e100, (0i < _e100));
                        let _e104 = (bitcast<i32>(_e68) - 1i);
                        let _e108 = (_e91 + 1i);
                        let _e110 = select(0i, _e108, (0i < _e108));
                        let _e113 = bitcast<u32>(select(_e110, _e96, (_e96 < _e110)));
                        let _e115 = select(0i, _e91, (0i < _e91));
                        let _e118 = bitcast<u32>(select(_e115, _e96, (_e96 < _e115)));
                        let _e119 = (_e100 + -1i);
                        let _e121 = select(0i, _e119, (0i < _e119));
                        let _e125 = (_e100 + 1i);
                        let _e127 = select(0i, _e125, (0i < _e125));
                        let _e131 = (bitcast<u32>(select(_e102, _e104, (_e104 < _e102))) * _e58);
                        let _e132 = (_e131 + _e99);
                        let _e135 = edges.member[_e132];
                        let _e149 = (_e131 + _e113);
                        let _e152 = edges.member[_e149];
                        let _e166 = (bitcast<u32>(select(_e121, _e104, (_e104 < _e121))) * _e58);
                        let _e167 = (_e166 + _e118);
                        let _e170 = edges.member[_e167];
                        let _e184 = (bitcast<u32>(select(_e127, _e104, (_e104 < _e127))) * _e58);
                        let _e185 = (_e184 + _e118);
                        let _e188 = edges.member[_e185];
                        let _e205 = ((_e44.y * _e58) + _e44.x);
                        let _e208 = edges.member[_e205];
                        let _e227 = ((f32(((_e208 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e135 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                        let _e228 = ((f32(((_e208 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e152 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                        let _e229 = ((f32(((_e208 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e170 & 3u)) * 0.33333334f));
                        let _e230 = ((f32((_e208 & 3u)) * 0.33333334f) * (f32(((_e188 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                        let _e234 = (1.5f - (((_e227 + _e228) + _e229) + _e230));
                        let _e239 = (select(0f, select(1f, _e234, (_e234 < 1f)), (_e234 > 0f)) * 0.33333334f);
                        let _e240 = (_e227 + _e239);
                        let _e244 = select(0f, select(1f, _e240, (_e240 < 1f)), (_e240 > 0f));
                        let _e245 = (_e228 + _e239);
                        let _e249 = select(0f, select(1f, _e245, (_e245 < 1f)), (_e245 > 0f));
                        let _e250 = (_e229 + _e239);
                        let _e254 = select(0f, select(1f, _e250, (_e250 < 1f)), (_e250 > 0f));
                        let _e255 = (_e230 + _e239);
                        let _e259 = select(0f, select(1f, _e255, (_e255 < 1f)), (_e255 > 0f));
                        let _e263 = (((_e244 * (f32(((_e135 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e254 * (f32(((_e170 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e267 = (((_e254 * (f32(((_e170 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e249 * (f32(((_e152 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e271 = (((_e259 * (f32(((_e188 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e244 * (f32((_e135 & 3u)) * 0.33333334f))) * 0.425f);
                        let _e275 = (((_e249 * (f32((_e152 & 3u)) * 0.33333334f)) + (_e259 * (f32(((_e188 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e286 = terms_in.member[_e205];
                        let _e292 = terms_in.member[_e132];
                        let _e299 = terms_in.member[_e149];
                        let _e306 = terms_in.member[_e167];
                        let _e313 = terms_in.member[_e185];
                        let _e321 = terms_in.member[(_e166 + _e99)];
                        let _e329 = terms_in.member[(_e166 + _e113)];
                        let _e337 = terms_in.member[(_e184 + _e99)];
                        let _e345 = terms_in.member[(_e184 + _e113)];
                        let _e350 = (((((((((((f32(_e286) * 0.003921569f) * _e90) + ((f32(_e292) * 0.003921569f) * _e244)) + ((f32(_e299) * 0.003921569f) * _e249)) + ((f32(_e306) * 0.003921569f) * _e254)) + ((f32(_e313) * 0.003921569f) * _e259)) + ((f32(_e321) * 0.003921569f) * _e263)) + ((f32(_e329) * 0.003921569f) * _e267)) + ((f32(_e337) * 0.003921569f) * _e271)) + ((f32(_e345) * 0.003921569f) * _e275)) / ((((((((_e90 + _e244) + _e249) + _e254) + _e259) + _e263) + _e267) + _e271) + _e275));
                        if _e82 {
                            phi_749_ = ((_e350 * 382.5f) + 0.5f);
                        } else {
                            phi_749_ = ((_e350 * 255f) + 0.5f);
                        }
                        let _e356 = phi_749_;
                        if (_e356 > 0f) {
                            let _e362 = select(select(u32(_e356), 0u, (_e356 < 0f)), 4294967295u, (_e356 > 4294967000f));
                            phi_767_ = select(_e362, 255u, (255u < _e362));
                        } else {
                            phi_767_ = 0u;
                        }
                        let _e366 = phi_767_;
                        phi_1606_ = type_22(_e366, (f32(_e366) * 0.003921569f), _e82);
                        phi_1607_ = type_22();
                        phi_1608_ = true;
                    } else {
                        if (_e79 == 0u) {
                            phi_812_ = 10000f;
                        } else {
                            phi_812_ = select(0.24000001f, 1.2f, _e82);
                        }
                        let _e373 = phi_812_;
                        let _e374 = bitcast<i32>(_e44.x);
                        let _e375 = (_e374 + -1i);
                        let _e377 = select(0i, _e375, (0i < _e375));
                        let _e379 = (bitcast<i32>(_e58) - 1i);
                        let _e382 = bitcast<u32>(select(_e377, _e379, (_e379 < _e377)));
                        let _e383 = bitcast<i32>(_e44.y);
                        let _e385 = select(0i, _e383, (0i < _e383));
                        let _e387 = (bitcast<i32>(_e68) - 1i);
                        let _e391 = (_e374 + 1i);
                        let _e393 = select(0i, _e391, (0i < _e391));
                        let _e396 = bitcast<u32>(select(_e393, _e379, (_e379 < _e393)));
                        let _e398 = select(0i, _e374, (0i < _e374));
                        let _e401 = bitcast<u32>(select(_e398, _e379, (_e379 < _e398)));
                        let _e402 = (_e383 + -1i);
                        let _e404 = select(0i, _e402, (0i < _e402));
                        let _e408 = (_e383 + 1i);
                        let _e410 = select(0i, _e408, (0i < _e408));
                        let _e414 = (bitcast<u32>(select(_e385, _e387, (_e387 < _e385))) * _e58);
                        let _e415 = (_e414 + _e382);
                        let _e418 = edges.member[_e415];
                        let _e432 = (_e414 + _e396);
                        let _e435 = edges.member[_e432];
                        let _e449 = (bitcast<u32>(select(_e404, _e387, (_e387 < _e404))) * _e58);
                        let _e450 = (_e449 + _e401);
                        let _e453 = edges.member[_e450];
                        let _e467 = (bitcast<u32>(select(_e410, _e387, (_e387 < _e410))) * _e58);
                        let _e468 = (_e467 + _e401);
                        let _e471 = edges.member[_e468];
                        let _e488 = ((_e44.y * _e58) + _e44.x);
                        let _e491 = edges.member[_e488];
                        let _e510 = ((f32(((_e491 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e418 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                        let _e511 = ((f32(((_e491 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e435 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                        let _e512 = ((f32(((_e491 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e453 & 3u)) * 0.33333334f));
                        let _e513 = ((f32((_e491 & 3u)) * 0.33333334f) * (f32(((_e471 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                        let _e517 = (1.5f - (((_e510 + _e511) + _e512) + _e513));
                        let _e522 = (select(0f, select(1f, _e517, (_e517 < 1f)), (_e517 > 0f)) * 0.33333334f);
                        let _e523 = (_e510 + _e522);
                        let _e527 = select(0f, select(1f, _e523, (_e523 < 1f)), (_e523 > 0f));
                        let _e528 = (_e511 + _e522);
                        let _e532 = select(0f, select(1f, _e528, (_e528 < 1f)), (_e528 > 0f));
                        let _e533 = (_e512 + _e522);
                        let _e537 = select(0f, select(1f, _e533, (_e533 < 1f)), (_e533 > 0f));
                        let _e538 = (_e513 + _e522);
                        let _e542 = select(0f, select(1f, _e538, (_e538 < 1f)), (_e538 > 0f));
                        let _e546 = (((_e527 * (f32(((_e418 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e537 * (f32(((_e453 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e550 = (((_e537 * (f32(((_e453 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e532 * (f32(((_e435 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e554 = (((_e542 * (f32(((_e471 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e527 * (f32((_e418 & 3u)) * 0.33333334f))) * 0.425f);
                        let _e558 = (((_e532 * (f32((_e435 & 3u)) * 0.33333334f)) + (_e542 * (f32(((_e471 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                        let _e566 = ((((((((_e373 + _e527) + _e532) + _e537) + _e542) + _e546) + _e550) + _e554) + _e558);
                        let _e569 = terms_in.member[_e488];
                        let _e593 = terms_in.member[_e415];
                        let _e621 = terms_in.member[_e432];
                        let _e649 = terms_in.member[_e450];
                        let _e677 = terms_in.member[_e468];
                        let _e706 = terms_in.member[(_e449 + _e382)];
                        let _e735 = terms_in.member[(_e449 + _e396)];
                        let _e764 = terms_in.member[(_e467 + _e382)];
                        let _e793 = terms_in.member[(_e467 + _e396)];
                        let _e819 = (((((((((((f32((_e569 & 255u)) * 0.003921569f) * _e373) + ((f32((_e593 & 255u)) * 0.003921569f) * _e527)) + ((f32((_e621 & 255u)) * 0.003921569f) * _e532)) + ((f32((_e649 & 255u)) * 0.003921569f) * _e537)) + ((f32((_e677 & 255u)) * 0.003921569f) * _e542)) + ((f32((_e706 & 255u)) * 0.003921569f) * _e546)) + ((f32((_e735 & 255u)) * 0.003921569f) * _e550)) + ((f32((_e764 & 255u)) * 0.003921569f) * _e554)) + ((f32((_e793 & 255u)) * 0.003921569f) * _e558)) / _e566);
                        let _e820 = (((((((((((f32(((_e569 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e373) + ((f32(((_e593 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e527)) + ((f32(((_e621 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e532)) + ((f32(((_e649 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e537)) + ((f32(((_e677 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e542)) + ((f32(((_e706 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e546)) + ((f32(((_e735 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e550)) + ((f32(((_e764 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e554)) + ((f32(((_e793 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e558)) / _e566);
                        let _e821 = (((((((((((f32(((_e569 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e373) + ((f32(((_e593 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e527)) + ((f32(((_e621 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e532)) + ((f32(((_e649 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e537)) + ((f32(((_e677 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e542)) + ((f32(((_e706 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e546)) + ((f32(((_e735 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e550)) + ((f32(((_e764 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e554)) + ((f32(((_e793 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e558)) / _e566);
                        let _e822 = (((((((((((f32((_e569 >> bitcast<u32>(24i))) * 0.003921569f) * _e373) + ((f32((_e593 >> bitcast<u32>(24i))) * 0.003921569f) * _e527)) + ((f32((_e621 >> bitcast<u32>(24i))) * 0.003921569f) * _e532)) + ((f32((_e649 >> bitcast<u32>(24i))) * 0.003921569f) * _e537)) + ((f32((_e677 >> bitcast<u32>(24i))) * 0.003921569f) * _e542)) + ((f32((_e706 >> bitcast<u32>(24i))) * 0.003921569f) * _e546)) + ((f32((_e735 >> bitcast<u32>(24i))) * 0.003921569f) * _e550)) + ((f32((_e764 >> bitcast<u32>(24i))) * 0.003921569f) * _e554)) + ((f32((_e793 >> bitcast<u32>(24i))) * 0.003921569f) * _e558)) / _e566);
                        if _e82 {
                            let _e826 = ((_e819 * 2f) - 1f);
                            let _e827 = ((_e820 * 2f) - 1f);
                            let _e828 = ((_e821 * 2f) - 1f);
                            let _e834 = sqrt((((_e826 * _e826) + (_e827 * _e827)) + (_e828 * _e828)));
                            if (_e834 > 0f) {
                                phi_1553_ = vec3<f32>((_e826 / _e834), (_e827 / _e834), (_e828 / _e834));
                            } else {
                                phi_1553_ = vec3<f32>(0f, 0f, -1f);
                            }
                            let _e841 = phi_1553_;
                            let _e843 = ((_e822 * 382.5f) + 0.5f);
                            let _e848 = select(select(u32(_e843), 0u, (_e843 < 0f)), 4294967295u, (_e843 > 4294967000f));
                            let _e852 = (f32(select(_e848, 255u, (255u < _e848))) * 0.003921569f);
                            let _e859 = ((_e841.x * 0.5f) + 0.5f);
                            let _e860 = ((_e841.y * 0.5f) + 0.5f);
                            let _e861 = ((_e841.z * -0.5f) + 0.5f);
                            let _e867 = ((select(0f, select(1f, _e859, (_e859 < 1f)), (_e859 > 0f)) * 255f) + 0.5f);
                            let _e878 = ((select(0f, select(1f, _e860, (_e860 < 1f)), (_e860 > 0f)) * 255f) + 0.5f);
                            let _e892 = ((select(0f, select(1f, _e861, (_e861 < 1f)), (_e861 > 0f)) * 255f) + 0.5f);
                            let _e906 = ((select(0f, select(1f, _e852, (_e852 < 1f)), (_e852 > 0f)) * 255f) + 0.5f);
                            phi_1603_ = type_22((((select(select(u32(_e867), 0u, (_e867 < 0f)), 4294967295u, (_e867 > 4294967000f)) | (select(select(u32(_e878), 0u, (_e878 < 0f)), 4294967295u, (_e878 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e892), 0u, (_e892 < 0f)), 4294967295u, (_e892 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e906), 0u, (_e906 < 0f)), 4294967295u, (_e906 > 4294967000f)) << bitcast<u32>(24i))), _e852, _e82);
                            phi_1604_ = type_22();
                        } else {
                            let _e921 = ((select(0f, select(1f, _e819, (_e819 < 1f)), (_e819 > 0f)) * 255f) + 0.5f);
                            let _e932 = ((select(0f, select(1f, _e820, (_e820 < 1f)), (_e820 > 0f)) * 255f) + 0.5f);
                            let _e946 = ((select(0f, select(1f, _e821, (_e821 < 1f)), (_e821 > 0f)) * 255f) + 0.5f);
                            let _e960 = ((select(0f, select(1f, _e822, (_e822 < 1f)), (_e822 > 0f)) * 255f) + 0.5f);
                            phi_1603_ = type_22();
                            phi_1604_ = type_22((((select(select(u32(_e921), 0u, (_e921 < 0f)), 4294967295u, (_e921 > 4294967000f)) | (select(select(u32(_e932), 0u, (_e932 < 0f)), 4294967295u, (_e932 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e946), 0u, (_e946 < 0f)), 4294967295u, (_e946 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e960), 0u, (_e960 < 0f)), 4294967295u, (_e960 > 4294967000f)) << bitcast<u32>(24i))), 0f, _e82);
                        }
                        let _e971 = phi_1603_;
                        let _e973 = phi_1604_;
                        phi_1606_ = _e973;
                        phi_1607_ = _e971;
                        phi_1608_ = select(true, false, _e82);
                    }
                    let _e976 = phi_1606_;
                    let _e978 = phi_1607_;
                    let _e980 = phi_1608_;
                    if _e980 {
                        phi_1612_ = _e976;
                    } else {
                        phi_1612_ = _e978;
                    }
                    let _e982 = phi_1612_;
                    let _e984 = ((_e44.y * _e58) + _e44.x);
                    if (_e984 < arrayLength((&terms_out.member))) {
                    } else {
                        break;
                    }
                    terms_out.member[_e984] = _e982.member;
                    if _e982.member_2 {
                        if (_e984 < arrayLength((&ao.member))) {
                        } else {
                            break;
                        }
                        ao.member[_e984] = _e982.member_1;
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
