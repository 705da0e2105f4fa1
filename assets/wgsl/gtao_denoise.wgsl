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
    var phi_128_: u32;
    var phi_896_: u32;
    var phi_1912_: f32;
    var phi_2449_: vec3<f32>;
    var phi_2497_: type_22;
    var phi_2498_: type_22;
    var phi_1236_: f32;
    var phi_1579_: f32;
    var phi_2500_: type_22;
    var phi_2501_: type_22;
    var phi_2502_: bool;
    var phi_2506_: type_22;
    var phi_897_: u32;
    var phi_292_: f32;
    var phi_812_: f32;
    var phi_852_: f32;

    let _e47 = id_1;
    let _e52 = params.member.member.member[0u];
    let _e57 = select(select(u32(_e52), 0u, (_e52 < 0f)), 4294967295u, (_e52 > 4294967000f));
    let _e62 = params.member.member.member[1u];
    let _e67 = select(select(u32(_e62), 0u, (_e62 < 0f)), 4294967295u, (_e62 > 4294967000f));
    let _e70 = (_e57 / 2u);
    if ((_e57 % 2u) > 0u) {
        phi_128_ = (_e70 + 1u);
    } else {
        phi_128_ = _e70;
    }
    let _e75 = phi_128_;
    if (_e47.x >= _e75) {
    } else {
        if (_e47.y >= _e67) {
        } else {
            let _e80 = params.member.member_12;
            let _e84 = params.member.member_10;
            let _e87 = ((_e80 + 1u) >= select(1u, _e84, (1u < _e84)));
            let _e88 = (2u * _e47.x);
            let _e90 = ((_e88 + 1u) < _e57);
            let _e91 = (_e47.y * _e57);
            let _e92 = (_e91 + _e88);
            let _e95 = params.member.member_13;
            let _e96 = (_e95 == 0u);
            if _e96 {
                let _e1076 = bitcast<i32>(_e88);
                let _e1077 = (_e1076 + -1i);
                let _e1079 = select(0i, _e1077, (0i < _e1077));
                let _e1081 = (bitcast<i32>(_e57) - 1i);
                let _e1084 = bitcast<u32>(select(_e1079, _e1081, (_e1081 < _e1079)));
                let _e1085 = (_e1076 + 1i);
                let _e1087 = select(0i, _e1085, (0i < _e1085));
                let _e1090 = bitcast<u32>(select(_e1087, _e1081, (_e1081 < _e1087)));
                let _e1091 = (_e1076 + 2i);
                let _e1093 = select(0i, _e1091, (0i < _e1091));
                let _e1096 = bitcast<u32>(select(_e1093, _e1081, (_e1081 < _e1093)));
                let _e1097 = bitcast<i32>(_e47.y);
                let _e1098 = (_e1097 + -1i);
                let _e1100 = select(0i, _e1098, (0i < _e1098));
                let _e1102 = (bitcast<i32>(_e67) - 1i);
                let _e1106 = (_e1097 + 1i);
                let _e1108 = select(0i, _e1106, (0i < _e1106));
                let _e1112 = (_e91 + _e1084);
                let _e1115 = edges.member[_e1112];
                let _e1118 = edges.member[_e92];
                let _e1119 = (_e91 + _e1090);
                let _e1122 = edges.member[_e1119];
                let _e1123 = (_e91 + _e1096);
                let _e1126 = edges.member[_e1123];
                if (_e84 == 0u) {
                    phi_292_ = 10000f;
                } else {
                    phi_292_ = select(0.24000001f, 1.2f, _e87);
                }
                let _e1130 = phi_292_;
                let _e1131 = (bitcast<u32>(select(_e1100, _e1102, (_e1102 < _e1100))) * _e57);
                let _e1132 = (_e1131 + _e88);
                let _e1135 = edges.member[_e1132];
                let _e1136 = (bitcast<u32>(select(_e1108, _e1102, (_e1102 < _e1108))) * _e57);
                let _e1137 = (_e1136 + _e88);
                let _e1140 = edges.member[_e1137];
                let _e1162 = (f32(bitcast<i32>(((_e1122 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f);
                let _e1168 = (f32(bitcast<i32>(((_e1122 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f);
                let _e1172 = (f32(bitcast<i32>((_e1122 & 3u))) * 0.33333334f);
                let _e1218 = (f32(bitcast<i32>(((_e1118 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f);
                let _e1224 = (f32(bitcast<i32>(((_e1118 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f);
                let _e1228 = (f32(bitcast<i32>((_e1118 & 3u))) * 0.33333334f);
                let _e1229 = ((f32(bitcast<i32>(((_e1118 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e1115 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f));
                let _e1230 = (_e1218 * _e1162);
                let _e1231 = (_e1224 * (f32(bitcast<i32>((_e1135 & 3u))) * 0.33333334f));
                let _e1232 = (_e1228 * (f32(bitcast<i32>(((_e1140 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f));
                let _e1236 = (1.5f - (((_e1229 + _e1230) + _e1231) + _e1232));
                let _e1241 = (select(0f, select(1f, _e1236, (_e1236 < 1f)), (_e1236 > 0f)) * 0.33333334f);
                let _e1242 = (_e1229 + _e1241);
                let _e1246 = select(0f, select(1f, _e1242, (_e1242 < 1f)), (_e1242 > 0f));
                let _e1247 = (_e1230 + _e1241);
                let _e1251 = select(0f, select(1f, _e1247, (_e1247 < 1f)), (_e1247 > 0f));
                let _e1252 = (_e1231 + _e1241);
                let _e1256 = select(0f, select(1f, _e1252, (_e1252 < 1f)), (_e1252 > 0f));
                let _e1257 = (_e1232 + _e1241);
                let _e1261 = select(0f, select(1f, _e1257, (_e1257 < 1f)), (_e1257 > 0f));
                let _e1265 = (((_e1246 * (f32(bitcast<i32>(((_e1115 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f)) + (_e1256 * (f32(bitcast<i32>(((_e1135 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f))) * 0.425f);
                let _e1269 = (((_e1256 * (f32(bitcast<i32>(((_e1135 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f)) + (_e1251 * _e1168)) * 0.425f);
                let _e1273 = (((_e1261 * (f32(bitcast<i32>(((_e1140 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f)) + (_e1246 * (f32(bitcast<i32>((_e1115 & 3u))) * 0.33333334f))) * 0.425f);
                let _e1277 = (((_e1251 * _e1172) + (_e1261 * (f32(bitcast<i32>(((_e1140 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f))) * 0.425f);
                let _e1286 = (_e1131 + _e1090);
                let _e1289 = edges.member[_e1286];
                let _e1290 = (_e1136 + _e1090);
                let _e1293 = edges.member[_e1290];
                let _e1350 = (_e1162 * _e1218);
                let _e1351 = ((f32(bitcast<i32>(((_e1122 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e1126 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f));
                let _e1352 = (_e1168 * (f32(bitcast<i32>((_e1289 & 3u))) * 0.33333334f));
                let _e1353 = (_e1172 * (f32(bitcast<i32>(((_e1293 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f));
                let _e1357 = (1.5f - (((_e1350 + _e1351) + _e1352) + _e1353));
                let _e1362 = (select(0f, select(1f, _e1357, (_e1357 < 1f)), (_e1357 > 0f)) * 0.33333334f);
                let _e1363 = (_e1350 + _e1362);
                let _e1367 = select(0f, select(1f, _e1363, (_e1363 < 1f)), (_e1363 > 0f));
                let _e1368 = (_e1351 + _e1362);
                let _e1372 = select(0f, select(1f, _e1368, (_e1368 < 1f)), (_e1368 > 0f));
                let _e1373 = (_e1352 + _e1362);
                let _e1377 = select(0f, select(1f, _e1373, (_e1373 < 1f)), (_e1373 > 0f));
                let _e1378 = (_e1353 + _e1362);
                let _e1382 = select(0f, select(1f, _e1378, (_e1378 < 1f)), (_e1378 > 0f));
                let _e1386 = (((_e1367 * _e1224) + (_e1377 * (f32(bitcast<i32>(((_e1289 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f))) * 0.425f);
                let _e1390 = (((_e1377 * (f32(bitcast<i32>(((_e1289 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f)) + (_e1372 * (f32(bitcast<i32>(((_e1126 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f))) * 0.425f);
                let _e1394 = (((_e1382 * (f32(bitcast<i32>(((_e1293 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f)) + (_e1367 * _e1228)) * 0.425f);
                let _e1398 = (((_e1372 * (f32(bitcast<i32>((_e1126 & 3u))) * 0.33333334f)) + (_e1382 * (f32(bitcast<i32>(((_e1293 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f))) * 0.425f);
                let _e1410 = terms_in.member[(_e1131 + _e1084)];
                let _e1416 = terms_in.member[_e1132];
                let _e1419 = (f32(bitcast<i32>(_e1416)) * 0.003921569f);
                let _e1422 = terms_in.member[_e1286];
                let _e1425 = (f32(bitcast<i32>(_e1422)) * 0.003921569f);
                let _e1429 = terms_in.member[(_e1131 + _e1096)];
                let _e1435 = terms_in.member[_e1112];
                let _e1441 = terms_in.member[_e92];
                let _e1444 = (f32(bitcast<i32>(_e1441)) * 0.003921569f);
                let _e1447 = terms_in.member[_e1119];
                let _e1450 = (f32(bitcast<i32>(_e1447)) * 0.003921569f);
                let _e1453 = terms_in.member[_e1123];
                let _e1460 = terms_in.member[(_e1136 + _e1084)];
                let _e1466 = terms_in.member[_e1137];
                let _e1469 = (f32(bitcast<i32>(_e1466)) * 0.003921569f);
                let _e1472 = terms_in.member[_e1290];
                let _e1475 = (f32(bitcast<i32>(_e1472)) * 0.003921569f);
                let _e1479 = terms_in.member[(_e1136 + _e1096)];
                let _e1500 = ((((((((((_e1444 * _e1130) + ((f32(bitcast<i32>(_e1435)) * 0.003921569f) * _e1246)) + (_e1450 * _e1251)) + (_e1419 * _e1256)) + (_e1469 * _e1261)) + ((f32(bitcast<i32>(_e1410)) * 0.003921569f) * _e1265)) + (_e1425 * _e1269)) + ((f32(bitcast<i32>(_e1460)) * 0.003921569f) * _e1273)) + (_e1475 * _e1277)) / ((((((((_e1130 + _e1246) + _e1251) + _e1256) + _e1261) + _e1265) + _e1269) + _e1273) + _e1277));
                let _e1518 = ((((((((((_e1450 * _e1130) + (_e1444 * _e1367)) + ((f32(bitcast<i32>(_e1453)) * 0.003921569f) * _e1372)) + (_e1425 * _e1377)) + (_e1475 * _e1382)) + (_e1419 * _e1386)) + ((f32(bitcast<i32>(_e1429)) * 0.003921569f) * _e1390)) + (_e1469 * _e1394)) + ((f32(bitcast<i32>(_e1479)) * 0.003921569f) * _e1398)) / ((((((((_e1130 + _e1367) + _e1372) + _e1377) + _e1382) + _e1386) + _e1390) + _e1394) + _e1398));
                if _e87 {
                    phi_812_ = ((_e1500 * 382.5f) + 0.5f);
                } else {
                    phi_812_ = ((_e1500 * 255f) + 0.5f);
                }
                let _e1524 = phi_812_;
                let _e1532 = (bitcast<u32>((floor(select(0f, select(255f, _e1524, (_e1524 < 255f)), (_e1524 > 0f))) + 8388608f)) - 1258291200u);
                if _e87 {
                    phi_852_ = ((_e1518 * 382.5f) + 0.5f);
                } else {
                    phi_852_ = ((_e1518 * 255f) + 0.5f);
                }
                let _e1541 = phi_852_;
                let _e1549 = (bitcast<u32>((floor(select(0f, select(255f, _e1541, (_e1541 < 255f)), (_e1541 > 0f))) + 8388608f)) - 1258291200u);
                terms_out.member[_e92] = _e1532;
                if _e87 {
                    ao.member[_e92] = (f32(bitcast<i32>(_e1532)) * 0.003921569f);
                }
                if _e90 {
                    let _e1557 = (_e92 + 1u);
                    terms_out.member[_e1557] = _e1549;
                    if _e87 {
                        ao.member[_e1557] = (f32(bitcast<i32>(_e1549)) * 0.003921569f);
                    }
                }
            } else {
                phi_896_ = 0u;
                loop {
                    let _e98 = phi_896_;
                    let _e101 = (_e98 < (1u + select(0u, 1u, _e90)));
                    if _e101 {
                        let _e102 = (_e88 + _e98);
                        if _e96 {
                            let _e751 = bitcast<i32>(_e102);
                            let _e752 = (_e751 + -1i);
                            let _e754 = select(0i, _e752, (0i < _e752));
                            let _e756 = (bitcast<i32>(_e57) - 1i);
                            let _e759 = bitcast<u32>(select(_e754, _e756, (_e756 < _e754)));
                            let _e760 = bitcast<i32>(_e47.y);
                            let _e762 = select(0i, _e760, (0i < _e760));
                            let _e764 = (bitcast<i32>(_e67) - 1i);
                            let _e768 = (_e751 + 1i);
                            let _e770 = select(0i, _e768, (0i < _e768));
                            let _e773 = bitcast<u32>(select(_e770, _e756, (_e756 < _e770)));
                            let _e775 = select(0i, _e751, (0i < _e751));
                            let _e778 = bitcast<u32>(select(_e775, _e756, (_e756 < _e775)));
                            let _e779 = (_e760 + -1i);
                            let _e781 = select(0i, _e779, (0i < _e779));
                            let _e785 = (_e760 + 1i);
                            let _e787 = select(0i, _e785, (0i < _e785));
                            if (_e84 == 0u) {
                                phi_1236_ = 10000f;
                            } else {
                                phi_1236_ = select(0.24000001f, 1.2f, _e87);
                            }
                            let _e794 = phi_1236_;
                            let _e795 = (_e91 + _e102);
                            let _e798 = edges.member[_e795];
                            let _e799 = (bitcast<u32>(select(_e762, _e764, (_e764 < _e762))) * _e57);
                            let _e800 = (_e799 + _e759);
                            let _e803 = edges.member[_e800];
                            let _e804 = (_e799 + _e773);
                            let _e807 = edges.member[_e804];
                            let _e808 = (bitcast<u32>(select(_e781, _e764, (_e764 < _e781))) * _e57);
                            let _e809 = (_e808 + _e778);
                            let _e812 = edges.member[_e809];
                            let _e813 = (bitcast<u32>(select(_e787, _e764, (_e764 < _e787))) * _e57);
                            let _e814 = (_e813 + _e778);
                            let _e817 = edges.member[_e814];
                            let _e906 = ((f32(bitcast<i32>(((_e798 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e803 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f));
                            let _e907 = ((f32(bitcast<i32>(((_e798 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e807 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f));
                            let _e908 = ((f32(bitcast<i32>(((_e798 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>((_e812 & 3u))) * 0.33333334f));
                            let _e909 = ((f32(bitcast<i32>((_e798 & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e817 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f));
                            let _e913 = (1.5f - (((_e906 + _e907) + _e908) + _e909));
                            let _e918 = (select(0f, select(1f, _e913, (_e913 < 1f)), (_e913 > 0f)) * 0.33333334f);
                            let _e919 = (_e906 + _e918);
                            let _e923 = select(0f, select(1f, _e919, (_e919 < 1f)), (_e919 > 0f));
                            let _e924 = (_e907 + _e918);
                            let _e928 = select(0f, select(1f, _e924, (_e924 < 1f)), (_e924 > 0f));
                            let _e929 = (_e908 + _e918);
                            let _e933 = select(0f, select(1f, _e929, (_e929 < 1f)), (_e929 > 0f));
                            let _e934 = (_e909 + _e918);
                            let _e938 = select(0f, select(1f, _e934, (_e934 < 1f)), (_e934 > 0f));
                            let _e942 = (((_e923 * (f32(bitcast<i32>(((_e803 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f)) + (_e933 * (f32(bitcast<i32>(((_e812 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f))) * 0.425f);
                            let _e946 = (((_e933 * (f32(bitcast<i32>(((_e812 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f)) + (_e928 * (f32(bitcast<i32>(((_e807 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f))) * 0.425f);
                            let _e950 = (((_e938 * (f32(bitcast<i32>(((_e817 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f)) + (_e923 * (f32(bitcast<i32>((_e803 & 3u))) * 0.33333334f))) * 0.425f);
                            let _e954 = (((_e928 * (f32(bitcast<i32>((_e807 & 3u))) * 0.33333334f)) + (_e938 * (f32(bitcast<i32>(((_e817 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f))) * 0.425f);
                            let _e965 = terms_in.member[_e795];
                            let _e971 = terms_in.member[_e800];
                            let _e977 = terms_in.member[_e804];
                            let _e983 = terms_in.member[_e809];
                            let _e989 = terms_in.member[_e814];
                            let _e996 = terms_in.member[(_e808 + _e759)];
                            let _e1003 = terms_in.member[(_e808 + _e773)];
                            let _e1010 = terms_in.member[(_e813 + _e759)];
                            let _e1017 = terms_in.member[(_e813 + _e773)];
                            let _e1038 = (((((((((((f32(bitcast<i32>(_e965)) * 0.003921569f) * _e794) + ((f32(bitcast<i32>(_e971)) * 0.003921569f) * _e923)) + ((f32(bitcast<i32>(_e977)) * 0.003921569f) * _e928)) + ((f32(bitcast<i32>(_e983)) * 0.003921569f) * _e933)) + ((f32(bitcast<i32>(_e989)) * 0.003921569f) * _e938)) + ((f32(bitcast<i32>(_e996)) * 0.003921569f) * _e942)) + ((f32(bitcast<i32>(_e1003)) * 0.003921569f) * _e946)) + ((f32(bitcast<i32>(_e1010)) * 0.003921569f) * _e950)) + ((f32(bitcast<i32>(_e1017)) * 0.003921569f) * _e954)) / ((((((((_e794 + _e923) + _e928) + _e933) + _e938) + _e942) + _e946) + _e950) + _e954));
                            if _e87 {
                                phi_1579_ = ((_e1038 * 382.5f) + 0.5f);
                            } else {
                                phi_1579_ = ((_e1038 * 255f) + 0.5f);
                            }
                            let _e1044 = phi_1579_;
                            let _e1052 = (bitcast<u32>((floor(select(0f, select(255f, _e1044, (_e1044 < 255f)), (_e1044 > 0f))) + 8388608f)) - 1258291200u);
                            phi_2500_ = type_22(_e1052, (f32(bitcast<i32>(_e1052)) * 0.003921569f), _e87);
                            phi_2501_ = type_22();
                            phi_2502_ = true;
                        } else {
                            let _e103 = bitcast<i32>(_e102);
                            let _e104 = (_e103 + -1i);
                            let _e106 = select(0i, _e104, (0i < _e104));
                            let _e108 = (bitcast<i32>(_e57) - 1i);
                            let _e111 = bitcast<u32>(select(_e106, _e108, (_e108 < _e106)));
                            let _e112 = bitcast<i32>(_e47.y);
                            let _e114 = select(0i, _e112, (0i < _e112));
                            let _e116 = (bitcast<i32>(_e67) - 1i);
                            let _e120 = (_e103 + 1i);
                            let _e122 = select(0i, _e120, (0i < _e120));
                            let _e125 = bitcast<u32>(select(_e122, _e108, (_e108 < _e122)));
                            let _e127 = select(0i, _e103, (0i < _e103));
                            let _e130 = bitcast<u32>(select(_e127, _e108, (_e108 < _e127)));
                            let _e131 = (_e112 + -1i);
                            let _e133 = select(0i, _e131, (0i < _e131));
                            let _e137 = (_e112 + 1i);
                            let _e139 = select(0i, _e137, (0i < _e137));
                            if (_e84 == 0u) {
                                phi_1912_ = 10000f;
                            } else {
                                phi_1912_ = select(0.24000001f, 1.2f, _e87);
                            }
                            let _e146 = phi_1912_;
                            let _e147 = (_e91 + _e102);
                            let _e150 = edges.member[_e147];
                            let _e151 = (bitcast<u32>(select(_e114, _e116, (_e116 < _e114))) * _e57);
                            let _e152 = (_e151 + _e111);
                            let _e155 = edges.member[_e152];
                            let _e156 = (_e151 + _e125);
                            let _e159 = edges.member[_e156];
                            let _e160 = (bitcast<u32>(select(_e133, _e116, (_e116 < _e133))) * _e57);
                            let _e161 = (_e160 + _e130);
                            let _e164 = edges.member[_e161];
                            let _e165 = (bitcast<u32>(select(_e139, _e116, (_e116 < _e139))) * _e57);
                            let _e166 = (_e165 + _e130);
                            let _e169 = edges.member[_e166];
                            let _e258 = ((f32(bitcast<i32>(((_e150 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e155 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f));
                            let _e259 = ((f32(bitcast<i32>(((_e150 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e159 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f));
                            let _e260 = ((f32(bitcast<i32>(((_e150 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f) * (f32(bitcast<i32>((_e164 & 3u))) * 0.33333334f));
                            let _e261 = ((f32(bitcast<i32>((_e150 & 3u))) * 0.33333334f) * (f32(bitcast<i32>(((_e169 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f));
                            let _e265 = (1.5f - (((_e258 + _e259) + _e260) + _e261));
                            let _e270 = (select(0f, select(1f, _e265, (_e265 < 1f)), (_e265 > 0f)) * 0.33333334f);
                            let _e271 = (_e258 + _e270);
                            let _e275 = select(0f, select(1f, _e271, (_e271 < 1f)), (_e271 > 0f));
                            let _e276 = (_e259 + _e270);
                            let _e280 = select(0f, select(1f, _e276, (_e276 < 1f)), (_e276 > 0f));
                            let _e281 = (_e260 + _e270);
                            let _e285 = select(0f, select(1f, _e281, (_e281 < 1f)), (_e281 > 0f));
                            let _e286 = (_e261 + _e270);
                            let _e290 = select(0f, select(1f, _e286, (_e286 < 1f)), (_e286 > 0f));
                            let _e294 = (((_e275 * (f32(bitcast<i32>(((_e155 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f)) + (_e285 * (f32(bitcast<i32>(((_e164 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f))) * 0.425f);
                            let _e298 = (((_e285 * (f32(bitcast<i32>(((_e164 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f)) + (_e280 * (f32(bitcast<i32>(((_e159 >> bitcast<u32>(2u)) & 3u))) * 0.33333334f))) * 0.425f);
                            let _e302 = (((_e290 * (f32(bitcast<i32>(((_e169 >> bitcast<u32>(6u)) & 3u))) * 0.33333334f)) + (_e275 * (f32(bitcast<i32>((_e155 & 3u))) * 0.33333334f))) * 0.425f);
                            let _e306 = (((_e280 * (f32(bitcast<i32>((_e159 & 3u))) * 0.33333334f)) + (_e290 * (f32(bitcast<i32>(((_e169 >> bitcast<u32>(4u)) & 3u))) * 0.33333334f))) * 0.425f);
                            let _e314 = ((((((((_e146 + _e275) + _e280) + _e285) + _e290) + _e294) + _e298) + _e302) + _e306);
                            let _e317 = terms_in.member[_e147];
                            let _e341 = terms_in.member[_e152];
                            let _e365 = terms_in.member[_e156];
                            let _e389 = terms_in.member[_e161];
                            let _e413 = terms_in.member[_e166];
                            let _e438 = terms_in.member[(_e160 + _e111)];
                            let _e463 = terms_in.member[(_e160 + _e125)];
                            let _e488 = terms_in.member[(_e165 + _e111)];
                            let _e513 = terms_in.member[(_e165 + _e125)];
                            let _e603 = (((((((((((f32(bitcast<i32>((_e317 & 255u))) * 0.003921569f) * _e146) + ((f32(bitcast<i32>((_e341 & 255u))) * 0.003921569f) * _e275)) + ((f32(bitcast<i32>((_e365 & 255u))) * 0.003921569f) * _e280)) + ((f32(bitcast<i32>((_e389 & 255u))) * 0.003921569f) * _e285)) + ((f32(bitcast<i32>((_e413 & 255u))) * 0.003921569f) * _e290)) + ((f32(bitcast<i32>((_e438 & 255u))) * 0.003921569f) * _e294)) + ((f32(bitcast<i32>((_e463 & 255u))) * 0.003921569f) * _e298)) + ((f32(bitcast<i32>((_e488 & 255u))) * 0.003921569f) * _e302)) + ((f32(bitcast<i32>((_e513 & 255u))) * 0.003921569f) * _e306)) / _e314);
                            let _e604 = (((((((((((f32(bitcast<i32>(((_e317 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e146) + ((f32(bitcast<i32>(((_e341 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e275)) + ((f32(bitcast<i32>(((_e365 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e280)) + ((f32(bitcast<i32>(((_e389 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e285)) + ((f32(bitcast<i32>(((_e413 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e290)) + ((f32(bitcast<i32>(((_e438 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e294)) + ((f32(bitcast<i32>(((_e463 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e298)) + ((f32(bitcast<i32>(((_e488 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e302)) + ((f32(bitcast<i32>(((_e513 >> bitcast<u32>(8i)) & 255u))) * 0.003921569f) * _e306)) / _e314);
                            let _e605 = (((((((((((f32(bitcast<i32>(((_e317 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e146) + ((f32(bitcast<i32>(((_e341 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e275)) + ((f32(bitcast<i32>(((_e365 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e280)) + ((f32(bitcast<i32>(((_e389 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e285)) + ((f32(bitcast<i32>(((_e413 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e290)) + ((f32(bitcast<i32>(((_e438 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e294)) + ((f32(bitcast<i32>(((_e463 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e298)) + ((f32(bitcast<i32>(((_e488 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e302)) + ((f32(bitcast<i32>(((_e513 >> bitcast<u32>(16i)) & 255u))) * 0.003921569f) * _e306)) / _e314);
                            let _e606 = (((((((((((f32(bitcast<i32>((_e317 >> bitcast<u32>(24i)))) * 0.003921569f) * _e146) + ((f32(bitcast<i32>((_e341 >> bitcast<u32>(24i)))) * 0.003921569f) * _e275)) + ((f32(bitcast<i32>((_e365 >> bitcast<u32>(24i)))) * 0.003921569f) * _e280)) + ((f32(bitcast<i32>((_e389 >> bitcast<u32>(24i)))) * 0.003921569f) * _e285)) + ((f32(bitcast<i32>((_e413 >> bitcast<u32>(24i)))) * 0.003921569f) * _e290)) + ((f32(bitcast<i32>((_e438 >> bitcast<u32>(24i)))) * 0.003921569f) * _e294)) + ((f32(bitcast<i32>((_e463 >> bitcast<u32>(24i)))) * 0.003921569f) * _e298)) + ((f32(bitcast<i32>((_e488 >> bitcast<u32>(24i)))) * 0.003921569f) * _e302)) + ((f32(bitcast<i32>((_e513 >> bitcast<u32>(24i)))) * 0.003921569f) * _e306)) / _e314);
                            if _e87 {
                                let _e660 = ((_e603 * 2f) - 1f);
                                let _e661 = ((_e604 * 2f) - 1f);
                                let _e662 = ((_e605 * 2f) - 1f);
                                let _e668 = sqrt((((_e660 * _e660) + (_e661 * _e661)) + (_e662 * _e662)));
                                if (_e668 > 0f) {
                                    phi_2449_ = vec3<f32>((_e660 / _e668), (_e661 / _e668), (_e662 / _e668));
                                } else {
                                    phi_2449_ = vec3<f32>(0f, 0f, -1f);
                                }
                                let _e675 = phi_2449_;
                                let _e681 = (bitcast<u32>((floor(((_e606 * 382.5f) + 0.5f)) + 8388608f)) - 1258291200u);
                                let _e686 = (f32(bitcast<i32>(select(_e681, 255u, (255u < _e681)))) * 0.003921569f);
                                let _e693 = ((_e675.x * 0.5f) + 0.5f);
                                let _e694 = ((_e675.y * 0.5f) + 0.5f);
                                let _e695 = ((_e675.z * -0.5f) + 0.5f);
                                phi_2497_ = type_22(((((bitcast<u32>((floor(((select(0f, select(1f, _e693, (_e693 < 1f)), (_e693 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) | ((bitcast<u32>((floor(((select(0f, select(1f, _e694, (_e694 < 1f)), (_e694 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(8i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e695, (_e695 < 1f)), (_e695 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e686, (_e686 < 1f)), (_e686 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(24i))), _e686, _e87);
                                phi_2498_ = type_22();
                            } else {
                                phi_2497_ = type_22();
                                phi_2498_ = type_22(((((bitcast<u32>((floor(((select(0f, select(1f, _e603, (_e603 < 1f)), (_e603 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) | ((bitcast<u32>((floor(((select(0f, select(1f, _e604, (_e604 < 1f)), (_e604 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(8i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e605, (_e605 < 1f)), (_e605 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(16i))) | ((bitcast<u32>((floor(((select(0f, select(1f, _e606, (_e606 < 1f)), (_e606 > 0f)) * 255f) + 0.5f)) + 8388608f)) - 1258291200u) << bitcast<u32>(24i))), 0f, _e87);
                            }
                            let _e747 = phi_2497_;
                            let _e749 = phi_2498_;
                            phi_2500_ = _e749;
                            phi_2501_ = _e747;
                            phi_2502_ = select(true, false, _e87);
                        }
                        let _e1058 = phi_2500_;
                        let _e1060 = phi_2501_;
                        let _e1062 = phi_2502_;
                        if _e1062 {
                            phi_2506_ = _e1058;
                        } else {
                            phi_2506_ = _e1060;
                        }
                        let _e1064 = phi_2506_;
                        let _e1065 = (_e92 + _e98);
                        terms_out.member[_e1065] = _e1064.member;
                        if _e87 {
                            ao.member[_e1065] = _e1064.member_1;
                        }
                        phi_897_ = (_e98 + 1u);
                    } else {
                        phi_897_ = u32();
                    }
                    let _e1074 = phi_897_;
                    continue;
                    continuing {
                        phi_896_ = _e1074;
                        break if !(_e101);
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
