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
    var phi_126_: u32;
    var phi_840_: u32;
    var phi_1826_: f32;
    var phi_2311_: vec3<f32>;
    var phi_2361_: type_22;
    var phi_2362_: type_22;
    var phi_1180_: f32;
    var phi_1498_: f32;
    var phi_2364_: type_22;
    var phi_2365_: type_22;
    var phi_2366_: bool;
    var phi_2370_: type_22;
    var phi_841_: u32;
    var phi_290_: f32;
    var phi_766_: f32;
    var phi_801_: f32;

    let _e45 = id_1;
    let _e50 = params.member.member.member[0u];
    let _e55 = select(select(u32(_e50), 0u, (_e50 < 0f)), 4294967295u, (_e50 > 4294967000f));
    let _e60 = params.member.member.member[1u];
    let _e65 = select(select(u32(_e60), 0u, (_e60 < 0f)), 4294967295u, (_e60 > 4294967000f));
    let _e68 = (_e55 / 2u);
    if ((_e55 % 2u) > 0u) {
        phi_126_ = (_e68 + 1u);
    } else {
        phi_126_ = _e68;
    }
    let _e73 = phi_126_;
    if (_e45.x >= _e73) {
    } else {
        if (_e45.y >= _e65) {
        } else {
            let _e78 = params.member.member_12;
            let _e82 = params.member.member_10;
            let _e85 = ((_e78 + 1u) >= select(1u, _e82, (1u < _e82)));
            let _e86 = (2u * _e45.x);
            let _e88 = ((_e86 + 1u) < _e55);
            let _e89 = (_e45.y * _e55);
            let _e90 = (_e89 + _e86);
            let _e93 = params.member.member_13;
            let _e94 = (_e93 == 0u);
            if _e94 {
                let _e1001 = bitcast<i32>(_e86);
                let _e1002 = (_e1001 + -1i);
                let _e1004 = select(0i, _e1002, (0i < _e1002));
                let _e1006 = (bitcast<i32>(_e55) - 1i);
                let _e1009 = bitcast<u32>(select(_e1004, _e1006, (_e1006 < _e1004)));
                let _e1010 = (_e1001 + 1i);
                let _e1012 = select(0i, _e1010, (0i < _e1010));
                let _e1015 = bitcast<u32>(select(_e1012, _e1006, (_e1006 < _e1012)));
                let _e1016 = (_e1001 + 2i);
                let _e1018 = select(0i, _e1016, (0i < _e1016));
                let _e1021 = bitcast<u32>(select(_e1018, _e1006, (_e1006 < _e1018)));
                let _e1022 = bitcast<i32>(_e45.y);
                let _e1023 = (_e1022 + -1i);
                let _e1025 = select(0i, _e1023, (0i < _e1023));
                let _e1027 = (bitcast<i32>(_e65) - 1i);
                let _e1031 = (_e1022 + 1i);
                let _e1033 = select(0i, _e1031, (0i < _e1031));
                let _e1037 = (_e89 + _e1009);
                let _e1040 = edges.member[_e1037];
                let _e1043 = edges.member[_e90];
                let _e1044 = (_e89 + _e1015);
                let _e1047 = edges.member[_e1044];
                let _e1048 = (_e89 + _e1021);
                let _e1051 = edges.member[_e1048];
                if (_e82 == 0u) {
                    phi_290_ = 10000f;
                } else {
                    phi_290_ = select(0.24000001f, 1.2f, _e85);
                }
                let _e1055 = phi_290_;
                let _e1056 = (bitcast<u32>(select(_e1025, _e1027, (_e1027 < _e1025))) * _e55);
                let _e1057 = (_e1056 + _e86);
                let _e1060 = edges.member[_e1057];
                let _e1061 = (bitcast<u32>(select(_e1033, _e1027, (_e1027 < _e1033))) * _e55);
                let _e1062 = (_e1061 + _e86);
                let _e1065 = edges.member[_e1062];
                let _e1083 = (f32(((_e1047 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f);
                let _e1088 = (f32(((_e1047 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f);
                let _e1091 = (f32((_e1047 & 3u)) * 0.33333334f);
                let _e1129 = (f32(((_e1043 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f);
                let _e1134 = (f32(((_e1043 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f);
                let _e1137 = (f32((_e1043 & 3u)) * 0.33333334f);
                let _e1138 = ((f32(((_e1043 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e1040 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                let _e1139 = (_e1129 * _e1083);
                let _e1140 = (_e1134 * (f32((_e1060 & 3u)) * 0.33333334f));
                let _e1141 = (_e1137 * (f32(((_e1065 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                let _e1145 = (1.5f - (((_e1138 + _e1139) + _e1140) + _e1141));
                let _e1150 = (select(0f, select(1f, _e1145, (_e1145 < 1f)), (_e1145 > 0f)) * 0.33333334f);
                let _e1151 = (_e1138 + _e1150);
                let _e1155 = select(0f, select(1f, _e1151, (_e1151 < 1f)), (_e1151 > 0f));
                let _e1156 = (_e1139 + _e1150);
                let _e1160 = select(0f, select(1f, _e1156, (_e1156 < 1f)), (_e1156 > 0f));
                let _e1161 = (_e1140 + _e1150);
                let _e1165 = select(0f, select(1f, _e1161, (_e1161 < 1f)), (_e1161 > 0f));
                let _e1166 = (_e1141 + _e1150);
                let _e1170 = select(0f, select(1f, _e1166, (_e1166 < 1f)), (_e1166 > 0f));
                let _e1174 = (((_e1155 * (f32(((_e1040 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e1165 * (f32(((_e1060 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e1178 = (((_e1165 * (f32(((_e1060 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e1160 * _e1088)) * 0.425f);
                let _e1182 = (((_e1170 * (f32(((_e1065 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e1155 * (f32((_e1040 & 3u)) * 0.33333334f))) * 0.425f);
                let _e1186 = (((_e1160 * _e1091) + (_e1170 * (f32(((_e1065 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e1195 = (_e1056 + _e1015);
                let _e1198 = edges.member[_e1195];
                let _e1199 = (_e1061 + _e1015);
                let _e1202 = edges.member[_e1199];
                let _e1249 = (_e1083 * _e1129);
                let _e1250 = ((f32(((_e1047 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e1051 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                let _e1251 = (_e1088 * (f32((_e1198 & 3u)) * 0.33333334f));
                let _e1252 = (_e1091 * (f32(((_e1202 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                let _e1256 = (1.5f - (((_e1249 + _e1250) + _e1251) + _e1252));
                let _e1261 = (select(0f, select(1f, _e1256, (_e1256 < 1f)), (_e1256 > 0f)) * 0.33333334f);
                let _e1262 = (_e1249 + _e1261);
                let _e1266 = select(0f, select(1f, _e1262, (_e1262 < 1f)), (_e1262 > 0f));
                let _e1267 = (_e1250 + _e1261);
                let _e1271 = select(0f, select(1f, _e1267, (_e1267 < 1f)), (_e1267 > 0f));
                let _e1272 = (_e1251 + _e1261);
                let _e1276 = select(0f, select(1f, _e1272, (_e1272 < 1f)), (_e1272 > 0f));
                let _e1277 = (_e1252 + _e1261);
                let _e1281 = select(0f, select(1f, _e1277, (_e1277 < 1f)), (_e1277 > 0f));
                let _e1285 = (((_e1266 * _e1134) + (_e1276 * (f32(((_e1198 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e1289 = (((_e1276 * (f32(((_e1198 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e1271 * (f32(((_e1051 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e1293 = (((_e1281 * (f32(((_e1202 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e1266 * _e1137)) * 0.425f);
                let _e1297 = (((_e1271 * (f32((_e1051 & 3u)) * 0.33333334f)) + (_e1281 * (f32(((_e1202 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                let _e1309 = terms_in.member[(_e1056 + _e1009)];
                let _e1314 = terms_in.member[_e1057];
                let _e1316 = (f32(_e1314) * 0.003921569f);
                let _e1319 = terms_in.member[_e1195];
                let _e1321 = (f32(_e1319) * 0.003921569f);
                let _e1325 = terms_in.member[(_e1056 + _e1021)];
                let _e1330 = terms_in.member[_e1037];
                let _e1335 = terms_in.member[_e90];
                let _e1337 = (f32(_e1335) * 0.003921569f);
                let _e1340 = terms_in.member[_e1044];
                let _e1342 = (f32(_e1340) * 0.003921569f);
                let _e1345 = terms_in.member[_e1048];
                let _e1351 = terms_in.member[(_e1061 + _e1009)];
                let _e1356 = terms_in.member[_e1062];
                let _e1358 = (f32(_e1356) * 0.003921569f);
                let _e1361 = terms_in.member[_e1199];
                let _e1363 = (f32(_e1361) * 0.003921569f);
                let _e1367 = terms_in.member[(_e1061 + _e1021)];
                let _e1387 = ((((((((((_e1337 * _e1055) + ((f32(_e1330) * 0.003921569f) * _e1155)) + (_e1342 * _e1160)) + (_e1316 * _e1165)) + (_e1358 * _e1170)) + ((f32(_e1309) * 0.003921569f) * _e1174)) + (_e1321 * _e1178)) + ((f32(_e1351) * 0.003921569f) * _e1182)) + (_e1363 * _e1186)) / ((((((((_e1055 + _e1155) + _e1160) + _e1165) + _e1170) + _e1174) + _e1178) + _e1182) + _e1186));
                let _e1405 = ((((((((((_e1342 * _e1055) + (_e1337 * _e1266)) + ((f32(_e1345) * 0.003921569f) * _e1271)) + (_e1321 * _e1276)) + (_e1363 * _e1281)) + (_e1316 * _e1285)) + ((f32(_e1325) * 0.003921569f) * _e1289)) + (_e1358 * _e1293)) + ((f32(_e1367) * 0.003921569f) * _e1297)) / ((((((((_e1055 + _e1266) + _e1271) + _e1276) + _e1281) + _e1285) + _e1289) + _e1293) + _e1297));
                if _e85 {
                    phi_766_ = ((_e1387 * 382.5f) + 0.5f);
                } else {
                    phi_766_ = ((_e1387 * 255f) + 0.5f);
                }
                let _e1411 = phi_766_;
                let _e1413 = select(0f, _e1411, (_e1411 > 0f));
                let _e1416 = u32(select(255f, _e1413, (_e1413 < 255f)));
                if _e85 {
                    phi_801_ = ((_e1405 * 382.5f) + 0.5f);
                } else {
                    phi_801_ = ((_e1405 * 255f) + 0.5f);
                }
                let _e1424 = phi_801_;
                let _e1426 = select(0f, _e1424, (_e1424 > 0f));
                let _e1429 = u32(select(255f, _e1426, (_e1426 < 255f)));
                terms_out.member[_e90] = _e1416;
                if _e85 {
                    ao.member[_e90] = (f32(_e1416) * 0.003921569f);
                }
                if _e88 {
                    let _e1436 = (_e90 + 1u);
                    terms_out.member[_e1436] = _e1429;
                    if _e85 {
                        ao.member[_e1436] = (f32(_e1429) * 0.003921569f);
                    }
                }
            } else {
                phi_840_ = 0u;
                loop {
                    let _e96 = phi_840_;
                    let _e99 = (_e96 < (1u + select(0u, 1u, _e88)));
                    if _e99 {
                        let _e100 = (_e86 + _e96);
                        if _e94 {
                            let _e705 = bitcast<i32>(_e100);
                            let _e706 = (_e705 + -1i);
                            let _e708 = select(0i, _e706, (0i < _e706));
                            let _e710 = (bitcast<i32>(_e55) - 1i);
                            let _e713 = bitcast<u32>(select(_e708, _e710, (_e710 < _e708)));
                            let _e714 = bitcast<i32>(_e45.y);
                            let _e716 = select(0i, _e714, (0i < _e714));
                            let _e718 = (bitcast<i32>(_e65) - 1i);
                            let _e722 = (_e705 + 1i);
                            let _e724 = select(0i, _e722, (0i < _e722));
                            let _e727 = bitcast<u32>(select(_e724, _e710, (_e710 < _e724)));
                            let _e729 = select(0i, _e705, (0i < _e705));
                            let _e732 = bitcast<u32>(select(_e729, _e710, (_e710 < _e729)));
                            let _e733 = (_e714 + -1i);
                            let _e735 = select(0i, _e733, (0i < _e733));
                            let _e739 = (_e714 + 1i);
                            let _e741 = select(0i, _e739, (0i < _e739));
                            if (_e82 == 0u) {
                                phi_1180_ = 10000f;
                            } else {
                                phi_1180_ = select(0.24000001f, 1.2f, _e85);
                            }
                            let _e748 = phi_1180_;
                            let _e749 = (_e89 + _e100);
                            let _e752 = edges.member[_e749];
                            let _e753 = (bitcast<u32>(select(_e716, _e718, (_e718 < _e716))) * _e55);
                            let _e754 = (_e753 + _e713);
                            let _e757 = edges.member[_e754];
                            let _e758 = (_e753 + _e727);
                            let _e761 = edges.member[_e758];
                            let _e762 = (bitcast<u32>(select(_e735, _e718, (_e718 < _e735))) * _e55);
                            let _e763 = (_e762 + _e732);
                            let _e766 = edges.member[_e763];
                            let _e767 = (bitcast<u32>(select(_e741, _e718, (_e718 < _e741))) * _e55);
                            let _e768 = (_e767 + _e732);
                            let _e771 = edges.member[_e768];
                            let _e844 = ((f32(((_e752 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e757 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                            let _e845 = ((f32(((_e752 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e761 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                            let _e846 = ((f32(((_e752 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e766 & 3u)) * 0.33333334f));
                            let _e847 = ((f32((_e752 & 3u)) * 0.33333334f) * (f32(((_e771 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                            let _e851 = (1.5f - (((_e844 + _e845) + _e846) + _e847));
                            let _e856 = (select(0f, select(1f, _e851, (_e851 < 1f)), (_e851 > 0f)) * 0.33333334f);
                            let _e857 = (_e844 + _e856);
                            let _e861 = select(0f, select(1f, _e857, (_e857 < 1f)), (_e857 > 0f));
                            let _e862 = (_e845 + _e856);
                            let _e866 = select(0f, select(1f, _e862, (_e862 < 1f)), (_e862 > 0f));
                            let _e867 = (_e846 + _e856);
                            let _e871 = select(0f, select(1f, _e867, (_e867 < 1f)), (_e867 > 0f));
                            let _e872 = (_e847 + _e856);
                            let _e876 = select(0f, select(1f, _e872, (_e872 < 1f)), (_e872 > 0f));
                            let _e880 = (((_e861 * (f32(((_e757 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e871 * (f32(((_e766 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                            let _e884 = (((_e871 * (f32(((_e766 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e866 * (f32(((_e761 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                            let _e888 = (((_e876 * (f32(((_e771 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e861 * (f32((_e757 & 3u)) * 0.33333334f))) * 0.425f);
                            let _e892 = (((_e866 * (f32((_e761 & 3u)) * 0.33333334f)) + (_e876 * (f32(((_e771 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                            let _e903 = terms_in.member[_e749];
                            let _e908 = terms_in.member[_e754];
                            let _e913 = terms_in.member[_e758];
                            let _e918 = terms_in.member[_e763];
                            let _e923 = terms_in.member[_e768];
                            let _e929 = terms_in.member[(_e762 + _e713)];
                            let _e935 = terms_in.member[(_e762 + _e727)];
                            let _e941 = terms_in.member[(_e767 + _e713)];
                            let _e947 = terms_in.member[(_e767 + _e727)];
                            let _e967 = (((((((((((f32(_e903) * 0.003921569f) * _e748) + ((f32(_e908) * 0.003921569f) * _e861)) + ((f32(_e913) * 0.003921569f) * _e866)) + ((f32(_e918) * 0.003921569f) * _e871)) + ((f32(_e923) * 0.003921569f) * _e876)) + ((f32(_e929) * 0.003921569f) * _e880)) + ((f32(_e935) * 0.003921569f) * _e884)) + ((f32(_e941) * 0.003921569f) * _e888)) + ((f32(_e947) * 0.003921569f) * _e892)) / ((((((((_e748 + _e861) + _e866) + _e871) + _e876) + _e880) + _e884) + _e888) + _e892));
                            if _e85 {
                                phi_1498_ = ((_e967 * 382.5f) + 0.5f);
                            } else {
                                phi_1498_ = ((_e967 * 255f) + 0.5f);
                            }
                            let _e973 = phi_1498_;
                            let _e975 = select(0f, _e973, (_e973 > 0f));
                            let _e978 = u32(select(255f, _e975, (_e975 < 255f)));
                            phi_2364_ = type_22(_e978, (f32(_e978) * 0.003921569f), _e85);
                            phi_2365_ = type_22();
                            phi_2366_ = true;
                        } else {
                            let _e101 = bitcast<i32>(_e100);
                            let _e102 = (_e101 + -1i);
                            let _e104 = select(0i, _e102, (0i < _e102));
                            let _e106 = (bitcast<i32>(_e55) - 1i);
                            let _e109 = bitcast<u32>(select(_e104, _e106, (_e106 < _e104)));
                            let _e110 = bitcast<i32>(_e45.y);
                            let _e112 = select(0i, _e110, (0i < _e110));
                            let _e114 = (bitcast<i32>(_e65) - 1i);
                            let _e118 = (_e101 + 1i);
                            let _e120 = select(0i, _e118, (0i < _e118));
                            let _e123 = bitcast<u32>(select(_e120, _e106, (_e106 < _e120)));
                            let _e125 = select(0i, _e101, (0i < _e101));
                            let _e128 = bitcast<u32>(select(_e125, _e106, (_e106 < _e125)));
                            let _e129 = (_e110 + -1i);
                            let _e131 = select(0i, _e129, (0i < _e129));
                            let _e135 = (_e110 + 1i);
                            let _e137 = select(0i, _e135, (0i < _e135));
                            if (_e82 == 0u) {
                                phi_1826_ = 10000f;
                            } else {
                                phi_1826_ = select(0.24000001f, 1.2f, _e85);
                            }
                            let _e144 = phi_1826_;
                            let _e145 = (_e89 + _e100);
                            let _e148 = edges.member[_e145];
                            let _e149 = (bitcast<u32>(select(_e112, _e114, (_e114 < _e112))) * _e55);
                            let _e150 = (_e149 + _e109);
                            let _e153 = edges.member[_e150];
                            let _e154 = (_e149 + _e123);
                            let _e157 = edges.member[_e154];
                            let _e158 = (bitcast<u32>(select(_e131, _e114, (_e114 < _e131))) * _e55);
                            let _e159 = (_e158 + _e128);
                            let _e162 = edges.member[_e159];
                            let _e163 = (bitcast<u32>(select(_e137, _e114, (_e114 < _e137))) * _e55);
                            let _e164 = (_e163 + _e128);
                            let _e167 = edges.member[_e164];
                            let _e240 = ((f32(((_e148 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f) * (f32(((_e153 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f));
                            let _e241 = ((f32(((_e148 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f) * (f32(((_e157 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f));
                            let _e242 = ((f32(((_e148 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f) * (f32((_e162 & 3u)) * 0.33333334f));
                            let _e243 = ((f32((_e148 & 3u)) * 0.33333334f) * (f32(((_e167 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f));
                            let _e247 = (1.5f - (((_e240 + _e241) + _e242) + _e243));
                            let _e252 = (select(0f, select(1f, _e247, (_e247 < 1f)), (_e247 > 0f)) * 0.33333334f);
                            let _e253 = (_e240 + _e252);
                            let _e257 = select(0f, select(1f, _e253, (_e253 < 1f)), (_e253 > 0f));
                            let _e258 = (_e241 + _e252);
                            let _e262 = select(0f, select(1f, _e258, (_e258 < 1f)), (_e258 > 0f));
                            let _e263 = (_e242 + _e252);
                            let _e267 = select(0f, select(1f, _e263, (_e263 < 1f)), (_e263 > 0f));
                            let _e268 = (_e243 + _e252);
                            let _e272 = select(0f, select(1f, _e268, (_e268 < 1f)), (_e268 > 0f));
                            let _e276 = (((_e257 * (f32(((_e153 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f)) + (_e267 * (f32(((_e162 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f))) * 0.425f);
                            let _e280 = (((_e267 * (f32(((_e162 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f)) + (_e262 * (f32(((_e157 >> bitcast<u32>(2u)) & 3u)) * 0.33333334f))) * 0.425f);
                            let _e284 = (((_e272 * (f32(((_e167 >> bitcast<u32>(6u)) & 3u)) * 0.33333334f)) + (_e257 * (f32((_e153 & 3u)) * 0.33333334f))) * 0.425f);
                            let _e288 = (((_e262 * (f32((_e157 & 3u)) * 0.33333334f)) + (_e272 * (f32(((_e167 >> bitcast<u32>(4u)) & 3u)) * 0.33333334f))) * 0.425f);
                            let _e296 = ((((((((_e144 + _e257) + _e262) + _e267) + _e272) + _e276) + _e280) + _e284) + _e288);
                            let _e299 = terms_in.member[_e145];
                            let _e319 = terms_in.member[_e150];
                            let _e339 = terms_in.member[_e154];
                            let _e359 = terms_in.member[_e159];
                            let _e379 = terms_in.member[_e164];
                            let _e400 = terms_in.member[(_e158 + _e109)];
                            let _e421 = terms_in.member[(_e158 + _e123)];
                            let _e442 = terms_in.member[(_e163 + _e109)];
                            let _e463 = terms_in.member[(_e163 + _e123)];
                            let _e549 = (((((((((((f32((_e299 & 255u)) * 0.003921569f) * _e144) + ((f32((_e319 & 255u)) * 0.003921569f) * _e257)) + ((f32((_e339 & 255u)) * 0.003921569f) * _e262)) + ((f32((_e359 & 255u)) * 0.003921569f) * _e267)) + ((f32((_e379 & 255u)) * 0.003921569f) * _e272)) + ((f32((_e400 & 255u)) * 0.003921569f) * _e276)) + ((f32((_e421 & 255u)) * 0.003921569f) * _e280)) + ((f32((_e442 & 255u)) * 0.003921569f) * _e284)) + ((f32((_e463 & 255u)) * 0.003921569f) * _e288)) / _e296);
                            let _e550 = (((((((((((f32(((_e299 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e144) + ((f32(((_e319 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e257)) + ((f32(((_e339 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e262)) + ((f32(((_e359 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e267)) + ((f32(((_e379 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e272)) + ((f32(((_e400 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e276)) + ((f32(((_e421 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e280)) + ((f32(((_e442 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e284)) + ((f32(((_e463 >> bitcast<u32>(8i)) & 255u)) * 0.003921569f) * _e288)) / _e296);
                            let _e551 = (((((((((((f32(((_e299 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e144) + ((f32(((_e319 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e257)) + ((f32(((_e339 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e262)) + ((f32(((_e359 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e267)) + ((f32(((_e379 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e272)) + ((f32(((_e400 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e276)) + ((f32(((_e421 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e280)) + ((f32(((_e442 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e284)) + ((f32(((_e463 >> bitcast<u32>(16i)) & 255u)) * 0.003921569f) * _e288)) / _e296);
                            let _e552 = (((((((((((f32((_e299 >> bitcast<u32>(24i))) * 0.003921569f) * _e144) + ((f32((_e319 >> bitcast<u32>(24i))) * 0.003921569f) * _e257)) + ((f32((_e339 >> bitcast<u32>(24i))) * 0.003921569f) * _e262)) + ((f32((_e359 >> bitcast<u32>(24i))) * 0.003921569f) * _e267)) + ((f32((_e379 >> bitcast<u32>(24i))) * 0.003921569f) * _e272)) + ((f32((_e400 >> bitcast<u32>(24i))) * 0.003921569f) * _e276)) + ((f32((_e421 >> bitcast<u32>(24i))) * 0.003921569f) * _e280)) + ((f32((_e442 >> bitcast<u32>(24i))) * 0.003921569f) * _e284)) + ((f32((_e463 >> bitcast<u32>(24i))) * 0.003921569f) * _e288)) / _e296);
                            if _e85 {
                                let _e610 = ((_e549 * 2f) - 1f);
                                let _e611 = ((_e550 * 2f) - 1f);
                                let _e612 = ((_e551 * 2f) - 1f);
                                let _e618 = sqrt((((_e610 * _e610) + (_e611 * _e611)) + (_e612 * _e612)));
                                if (_e618 > 0f) {
                                    phi_2311_ = vec3<f32>((_e610 / _e618), (_e611 / _e618), (_e612 / _e618));
                                } else {
                                    phi_2311_ = vec3<f32>(0f, 0f, -1f);
                                }
                                let _e625 = phi_2311_;
                                let _e627 = ((_e552 * 382.5f) + 0.5f);
                                let _e632 = select(select(u32(_e627), 0u, (_e627 < 0f)), 4294967295u, (_e627 > 4294967000f));
                                let _e636 = (f32(select(_e632, 255u, (255u < _e632))) * 0.003921569f);
                                let _e643 = ((_e625.x * 0.5f) + 0.5f);
                                let _e644 = ((_e625.y * 0.5f) + 0.5f);
                                let _e645 = ((_e625.z * -0.5f) + 0.5f);
                                let _e651 = ((select(0f, select(1f, _e643, (_e643 < 1f)), (_e643 > 0f)) * 255f) + 0.5f);
                                let _e662 = ((select(0f, select(1f, _e644, (_e644 < 1f)), (_e644 > 0f)) * 255f) + 0.5f);
                                let _e676 = ((select(0f, select(1f, _e645, (_e645 < 1f)), (_e645 > 0f)) * 255f) + 0.5f);
                                let _e690 = ((select(0f, select(1f, _e636, (_e636 < 1f)), (_e636 > 0f)) * 255f) + 0.5f);
                                phi_2361_ = type_22((((select(select(u32(_e651), 0u, (_e651 < 0f)), 4294967295u, (_e651 > 4294967000f)) | (select(select(u32(_e662), 0u, (_e662 < 0f)), 4294967295u, (_e662 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e676), 0u, (_e676 < 0f)), 4294967295u, (_e676 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e690), 0u, (_e690 < 0f)), 4294967295u, (_e690 > 4294967000f)) << bitcast<u32>(24i))), _e636, _e85);
                                phi_2362_ = type_22();
                            } else {
                                let _e558 = ((select(0f, select(1f, _e549, (_e549 < 1f)), (_e549 > 0f)) * 255f) + 0.5f);
                                let _e569 = ((select(0f, select(1f, _e550, (_e550 < 1f)), (_e550 > 0f)) * 255f) + 0.5f);
                                let _e583 = ((select(0f, select(1f, _e551, (_e551 < 1f)), (_e551 > 0f)) * 255f) + 0.5f);
                                let _e597 = ((select(0f, select(1f, _e552, (_e552 < 1f)), (_e552 > 0f)) * 255f) + 0.5f);
                                phi_2361_ = type_22();
                                phi_2362_ = type_22((((select(select(u32(_e558), 0u, (_e558 < 0f)), 4294967295u, (_e558 > 4294967000f)) | (select(select(u32(_e569), 0u, (_e569 < 0f)), 4294967295u, (_e569 > 4294967000f)) << bitcast<u32>(8i))) | (select(select(u32(_e583), 0u, (_e583 < 0f)), 4294967295u, (_e583 > 4294967000f)) << bitcast<u32>(16i))) | (select(select(u32(_e597), 0u, (_e597 < 0f)), 4294967295u, (_e597 > 4294967000f)) << bitcast<u32>(24i))), 0f, _e85);
                            }
                            let _e701 = phi_2361_;
                            let _e703 = phi_2362_;
                            phi_2364_ = _e703;
                            phi_2365_ = _e701;
                            phi_2366_ = select(true, false, _e85);
                        }
                        let _e983 = phi_2364_;
                        let _e985 = phi_2365_;
                        let _e987 = phi_2366_;
                        if _e987 {
                            phi_2370_ = _e983;
                        } else {
                            phi_2370_ = _e985;
                        }
                        let _e989 = phi_2370_;
                        let _e990 = (_e90 + _e96);
                        terms_out.member[_e990] = _e989.member;
                        if _e85 {
                            ao.member[_e990] = _e989.member_1;
                        }
                        phi_841_ = (_e96 + 1u);
                    } else {
                        phi_841_ = u32();
                    }
                    let _e999 = phi_841_;
                    continue;
                    continuing {
                        phi_840_ = _e999;
                        break if !(_e99);
                    }
                }
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
