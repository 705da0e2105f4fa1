//! The committed SPIR-V modules (one per entry point), embedded at compile time.

/// `assets/spirv/manifest.json`: entry points, bindings, push constants and the source hash.
pub const MANIFEST: &str = include_str!("../../assets/spirv/manifest.json");

macro_rules! spv {
    ($name:literal) => {
        include_bytes!(concat!("../../assets/spirv/", $name, ".spv"))
    };
}

pub const VAO_MAIN: &[u8] = spv!("vao_main");
pub const BLUR_MAIN: &[u8] = spv!("blur_main");
pub const GBUFFER_VS: &[u8] = spv!("gbuffer_vs");
pub const GBUFFER_FS: &[u8] = spv!("gbuffer_fs");
pub const GBUFFER_PEEL_FS: &[u8] = spv!("gbuffer_peel_fs");
pub const GROUNDTRUTH_RGEN: &[u8] = spv!("groundtruth_rgen");
pub const GROUNDTRUTH_MISS: &[u8] = spv!("groundtruth_miss");
pub const GROUNDTRUTH_AHIT: &[u8] = spv!("groundtruth_ahit");
pub const SVAO_PASS1: &[u8] = spv!("svao_pass1");
pub const RAYSD_PASS2: &[u8] = spv!("raysd_pass2");
pub const RAYSD_RGEN: &[u8] = spv!("raysd_rgen");
pub const RAYSD_MISS: &[u8] = spv!("raysd_miss");
pub const RAYSD_AHIT: &[u8] = spv!("raysd_ahit");
pub const RAYSVAO_RGEN: &[u8] = spv!("raysvao_rgen");
pub const RAYSVAO_MISS: &[u8] = spv!("raysvao_miss");
pub const RAYSVAO_AHIT: &[u8] = spv!("raysvao_ahit");
pub const GTAO_PREFILTER: &[u8] = spv!("gtao_prefilter");
pub const GTAO_NORMALS: &[u8] = spv!("gtao_normals");
pub const GTAO_MAIN: &[u8] = spv!("gtao_main");
pub const GTAO_DENOISE: &[u8] = spv!("gtao_denoise");
pub const VBAO_MAIN: &[u8] = spv!("vbao_main");
pub const RAYMARCH_MAIN: &[u8] = spv!("raymarch_main");
pub const HYBRID_RGEN: &[u8] = spv!("hybrid_rgen");
pub const RAYSD_RQ: &[u8] = spv!("raysd_rq");
pub const RAYSVAO_RQ: &[u8] = spv!("raysvao_rq");
pub const GROUNDTRUTH_RQ: &[u8] = spv!("groundtruth_rq");
pub const HYBRID_RQ: &[u8] = spv!("hybrid_rq");
pub const RASTERSD_FS: &[u8] = spv!("rastersd_fs");
pub const IMPORT_DEPTH: &[u8] = spv!("import_depth");
pub const IMPORT_NORMALS: &[u8] = spv!("import_normals");
pub const EXPORT_AO_R32F: &[u8] = spv!("export_ao_r32f");
pub const EXPORT_AO_R16F: &[u8] = spv!("export_ao_r16f");
pub const EXPORT_AO_R8: &[u8] = spv!("export_ao_r8");
pub const TEMPORAL_BLEND: &[u8] = spv!("temporal_blend");
pub const TEMPORAL_STORE: &[u8] = spv!("temporal_store");

/// Every module by entry-point name.
pub const ALL: &[(&str, &[u8])] = &[
    ("vao_main", VAO_MAIN),
    ("blur_main", BLUR_MAIN),
    ("gbuffer_vs", GBUFFER_VS),
    ("gbuffer_fs", GBUFFER_FS),
    ("gbuffer_peel_fs", GBUFFER_PEEL_FS),
    ("groundtruth_rgen", GROUNDTRUTH_RGEN),
    ("groundtruth_miss", GROUNDTRUTH_MISS),
    ("groundtruth_ahit", GROUNDTRUTH_AHIT),
    ("svao_pass1", SVAO_PASS1),
    ("raysd_pass2", RAYSD_PASS2),
    ("raysd_rgen", RAYSD_RGEN),
    ("raysd_miss", RAYSD_MISS),
    ("raysd_ahit", RAYSD_AHIT),
    ("raysvao_rgen", RAYSVAO_RGEN),
    ("raysvao_miss", RAYSVAO_MISS),
    ("raysvao_ahit", RAYSVAO_AHIT),
    ("gtao_prefilter", GTAO_PREFILTER),
    ("gtao_normals", GTAO_NORMALS),
    ("gtao_main", GTAO_MAIN),
    ("gtao_denoise", GTAO_DENOISE),
    ("vbao_main", VBAO_MAIN),
    ("raymarch_main", RAYMARCH_MAIN),
    ("hybrid_rgen", HYBRID_RGEN),
    ("raysd_rq", RAYSD_RQ),
    ("raysvao_rq", RAYSVAO_RQ),
    ("groundtruth_rq", GROUNDTRUTH_RQ),
    ("hybrid_rq", HYBRID_RQ),
    ("rastersd_fs", RASTERSD_FS),
    ("import_depth", IMPORT_DEPTH),
    ("import_normals", IMPORT_NORMALS),
    ("export_ao_r32f", EXPORT_AO_R32F),
    ("export_ao_r16f", EXPORT_AO_R16F),
    ("export_ao_r8", EXPORT_AO_R8),
    ("temporal_blend", TEMPORAL_BLEND),
    ("temporal_store", TEMPORAL_STORE),
];

/// SPIR-V words of a module (validates the magic number and alignment).
pub fn words(bytes: &[u8]) -> Vec<u32> {
    ash::util::read_spv(&mut std::io::Cursor::new(bytes)).expect("committed SPIR-V is well-formed")
}
