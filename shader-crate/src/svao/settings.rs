//! Settings and pass graph of the stenciled VAO family (host side): dual-depth VAO and HBAO+
//! (pass 1 alone), Ray-SD / HBAO-SD (pass 1 → ray-traced SD map → pass 2), Ray-SVAO (pass 1 →
//! rays per flagged sample) — spec svao-raysd §3, §5, §7, §9, §10, §11 — each followed by the
//! blur (svao-raysd §12).

use super::{Secondary, SvaoFrame, SvaoParams};
use crate::blur::graph::blur_passes;
use crate::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR};
use crate::common::gbuffer_read::GBufferSlices;
use crate::common::tables::{AO_SAMPLES, JitterTable, KERNEL_SAMPLE_COUNTS};
use crate::glam::{UVec2, uvec2};
use crate::graph::{
    Diagnostics, Elem, Executed, Extent, FrameDesc, Graph, Init, Lifetime, Pass, RAY_COUNT, Refinement,
    RefinementDecoder, Resource, Size, Snapshot, inputs, ray_counter, record, target_f32, target_u32,
};
use crate::technique::{Constant, Declaration, Formula, Setting, Settings};
use crate::vao::kernel::{KERNEL_HBAO, KERNEL_VAO};
use crate::vao::settings::vao_params;

/// Options of the stenciled pipeline and its stochastic depth map (spec svao-raysd §2 defaults
/// in brackets).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct SvaoSettings {
    /// SD-map resolution divisor: 1 (full), 2 (½), 4 (¼), 8 (⅛) or 16 (1/16) \[4\] (spec svao-raysd §2).
    pub divisor: u32,
    /// AO samples per pixel N of both AO passes: 8, 16 or 32 \[8\] (spec svao-raysd §2, §4.2).
    pub samples: u32,
    /// Layers N: 1, 2, 4 or 8 \[4\].
    pub layers: u32,
    /// MAX_COUNT of the reservoir any-hit; raised to N when smaller \[8\].
    pub max_count: u32,
    /// Radius cutoff in full-res pixels: closer samples are never refined (svao-raysd §4.4) \[6\].
    pub cutoff: f32,
    /// Ray-interval optimisation (svao-raysd §6) \[on\].
    pub interval: bool,
    /// SD jitter table (svao-raysd §7.2) [the reference's scrambled table].
    pub jitter: JitterTable,
    /// SD guard band in full-res pixels (svao-raysd §3) [512, i.e. 128 SD texels at ¼].
    pub guard: u32,
    /// Dual depth: a depth-peeled second layer (svao-raysd §11) \[single\].
    pub dual: bool,
    /// Minimum separation of the peeled layer beyond the first, view depth [0.01, as SVAO.py].
    pub peel_separation: f32,
    /// The HBAO+ kernel instead of VAO's (svao-raysd §4.5); the radius is scaled by 1.5 as the reference's
    /// UI does (0.2 → 0.3) \[VAO\].
    pub hbao: bool,
    /// The SD map from the raster coverage-mask baseline (svao-raysd §8: no SD guard band, no jitter)
    /// instead of ray tracing \[ray\].
    pub raster: bool,
    /// What refines pass 1's flagged samples: fixed by each technique of the family (no
    /// technique reads the `refinement` key), so its constants' expressions read it too.
    pub refinement: Secondary,
}

impl Default for SvaoSettings {
    fn default() -> Self {
        SvaoSettings {
            divisor: 4,
            samples: AO_SAMPLES,
            layers: 4,
            max_count: 8,
            cutoff: 6.0,
            interval: true,
            jitter: JitterTable::Scrambled,
            guard: 512,
            dual: false,
            peel_separation: 0.01,
            hbao: false,
            raster: false,
            refinement: Secondary::Disabled,
        }
    }
}

/// Low-res SD size `ceil(W/div) × ceil(H/div)` of a full target (spec svao-raysd §3).
pub fn sd_low_res(full: UVec2, divisor: u32) -> UVec2 {
    uvec2(full.x.div_ceil(divisor), full.y.div_ceil(divisor))
}

/// A settings struct holding an SD map's settings (the stenciled family's own, and `vbao-sd`'s):
/// the SD map's rows are written once, in [`sd_rows`], generic over it.
pub trait SdMapBased: Sized + 'static {
    fn sd(&mut self) -> &mut SvaoSettings;
    fn sd_ref(&self) -> &SvaoSettings;
}

impl SdMapBased for SvaoSettings {
    fn sd(&mut self) -> &mut SvaoSettings {
        self
    }
    fn sd_ref(&self) -> &SvaoSettings {
        self
    }
}

/// The SD map's settings rows (spec svao-raysd §2, §3, §7), generic over where the settings live;
/// the flag is the caller's (flags are shared only within one settings type).
pub mod sd_rows {
    use super::{SD_RES_NAMES, SdMapBased, sd_res_index};
    use crate::technique::Setting;

    fn get_res<S: SdMapBased>(s: &S) -> usize {
        sd_res_index(s.sd_ref().divisor)
    }
    fn set_res<S: SdMapBased>(s: &mut S, i: usize) {
        s.sd().divisor = 1 << i;
    }
    fn layers_of<S: SdMapBased>(s: &mut S) -> &mut u32 {
        &mut s.sd().layers
    }
    fn max_count_of<S: SdMapBased>(s: &mut S) -> &mut u32 {
        &mut s.sd().max_count
    }
    fn guard_of<S: SdMapBased>(s: &mut S) -> &mut u32 {
        &mut s.sd().guard
    }

    pub const fn sd_res<S: SdMapBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::choice("sd-res", &SD_RES_NAMES, get_res::<S>, set_res::<S>)
            .flag(flag)
            .help("SD map resolution (divisor 1, 2, 4, 8, 16; spec svao-raysd §2, §3)")
    }

    pub const fn sd_layers<S: SdMapBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::count("sd-layers", 1, 8, layers_of::<S>)
            .flag(flag)
            .help("SD layers N: 1, 2, 4 or 8 (spec svao-raysd §7)")
    }

    pub const fn max_count<S: SdMapBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::count("max-count", 1, 1024, max_count_of::<S>)
            .flag(flag)
            .help("Reservoir MAX_COUNT of the SD any-hit (raised to N when smaller; spec svao-raysd §7)")
    }

    pub const fn sd_guard<S: SdMapBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::count("sd-guard", 0, 4096, guard_of::<S>)
            .flag(flag)
            .help("SD guard band in full-resolution pixels")
    }
}

impl Settings for SvaoSettings {
    const ROWS: &'static [Setting<Self>] = &[
        sd_rows::sd_res::<Self>("sd-res"),
        sd_rows::sd_layers::<Self>("sd-layers"),
        sd_rows::max_count::<Self>("max-count"),
        Setting::<Self>::number("cutoff", 0.0, f32::MAX, |s| &mut s.cutoff)
            .help("Radius cutoff in pixels: closer samples are never refined (spec svao-raysd §4.4)"),
        Setting::<Self>::switch("interval", &["off", "on"], |s| &mut s.interval)
            .only_switch("no-interval", "off")
            .help("Ray-interval optimisation (spec svao-raysd §6); --no-interval traces every SD texel over its full range"),
        Setting::<Self>::choice("jitter", &["none", "scrambled", "paper"], |s| s.jitter as usize, |s, i| {
            s.jitter = [JitterTable::None, JitterTable::Scrambled, JitterTable::Paper][i]
        })
        .and_switch("no-jitter", "none")
        .help("SD jitter table (spec svao-raysd §7.2); --no-jitter traces through texel centres"),
        sd_rows::sd_guard::<Self>("sd-guard"),
        Setting::<Self>::switch("primary", &["single", "dual"], |s| &mut s.dual)
            .help("Primary depth: the depth buffer, or dual depth with a depth-peeled second layer (spec svao-raysd §11)"),
        Setting::<Self>::number("peel-separation", 0.0, f32::MAX, |s| &mut s.peel_separation)
            .help("Minimum view-depth separation of the peeled second layer (world units)"),
        Setting::<Self>::switch("kernel", &["vao", "hbao"], |s| &mut s.hbao)
            .help("AO kernel: VAO's halo model, or HBAO+ with the radius × 1.5 (spec svao-raysd §4.5)"),
        Setting::<Self>::switch("sd-source", &["ray", "raster"], |s| &mut s.raster)
            .help("SD map: ray-traced, or the raster coverage-mask baseline (spec svao-raysd §8)"),
        Setting::<Self>::choice("ao-samples", &["8", "16", "32"], |s| sample_set(s.samples) as usize, |s, i| {
            s.samples = AO_SAMPLES << i
        })
        .help("AO samples per pixel N of the VAO/HBAO+ kernel: ψ = VdC(N + i) (spec svao-raysd §2, §4.2, §4.5)"),
        Setting::<Self>::choice("refinement", &["none", "sd-map", "rays"], |s| s.refinement as usize, |s, i| {
            s.refinement = [Secondary::Disabled, Secondary::StochasticDepth, Secondary::Raytraced][i]
        })
        .help("What refines pass 1 (fixed by the technique: vao and hbao none, raysd, hbao-sd and sdsvao the SD map, raysvao rays)"),
    ];

    fn check(&self) -> Result<(), String> {
        if !(self.divisor.is_power_of_two() && self.divisor <= 16) {
            return Err(format!(
                "sd-res: divisor {} is not 1 (full), 2 (half), 4 (quarter), 8 (eighth) or 16 (sixteenth)",
                self.divisor
            ));
        }
        if !KERNEL_SAMPLE_COUNTS.contains(&self.samples) {
            return Err(format!("ao-samples {} is not 8, 16 or 32", self.samples));
        }
        if !self.layers.is_power_of_two() {
            return Err(format!("sd-layers {} is not 1, 2, 4 or 8", self.layers));
        }
        Ok(())
    }
}

/// The `sd-res` names of the SD divisors 1, 2, 4, 8, 16 (spec svao-raysd §2), in that order.
const SD_RES_NAMES: [&str; 5] = ["full", "half", "quarter", "eighth", "sixteenth"];

/// The index of an SD divisor in [`SD_RES_NAMES`] (5 = none of them).
fn sd_res_index(divisor: u32) -> usize {
    match divisor {
        1 | 2 | 4 | 8 | 16 => divisor.trailing_zeros() as usize,
        _ => SD_RES_NAMES.len(),
    }
}

/// `SvaoParams::sample_set` of a sample count: 8 → 0, 16 → 1, 32 → 2 (3 = none of them).
fn sample_set(samples: u32) -> u32 {
    match samples {
        8 | 16 | 32 => (samples / AO_SAMPLES).trailing_zeros(),
        _ => 3,
    }
}

/// The second layer a dual-depth run reads.
fn dual_layer(s: &SvaoSettings) -> Option<f32> {
    s.dual.then_some(s.peel_separation)
}

/// A declaration of the stenciled family: every variant reads the dual-depth layer when its
/// settings say so and counts its rays from its buffers.
pub const fn stenciled(
    name: &'static str,
    summary: &'static str,
    keys: &'static [&'static str],
    defaults: fn() -> SvaoSettings,
    graph: fn(&SvaoSettings, &FrameDesc) -> Result<Graph, String>,
) -> Declaration<SvaoSettings> {
    Declaration {
        name,
        summary,
        keys,
        defaults,
        graph,
        second_layer: dual_layer,
        constants: CONSTANTS,
        formulas: SD_MAP_FORMULAS,
        tables: &[],
    }
}

/// How [`SvaoSettings::frame`] and [`SvaoSettings::graph`] fill `SvaoFrame`, `SvaoParams` and
/// the raster SD pass's `RasterParams`; with VAO's and the blur's rows
/// ([`crate::vao::settings::CONSTANTS`]) and the camera's, the table of the whole stenciled
/// family: vao, hbao, raysd, hbao-sd, sdsvao, raysvao.
pub const SVAO: &[Constant] = &[
    Constant::new("SvaoFrame.camera", "the frame's Camera (Camera and ViewParams rows)")
        .expr("Camera"),
    Constant::new("SvaoFrame.params", "the technique's SvaoParams (SvaoParams rows)")
        .expr("SvaoParams"),
    Constant::new("SvaoParams.vao", "VaoParams as for vao_main (VaoParams rows: radius R·1.5 when `kernel` = hbao)")
        .expr("VaoParams"),
    Constant::new(
        "SvaoParams.secondary",
        "Secondary, fixed by the technique: 0 Disabled (hbao, and vao with dual depth, the HBAO+ kernel or \
         16/32 `ao-samples`: pass 1 alone finalizes every pixel), 1 StochasticDepth (raysd, hbao-sd, sdsvao: pass 2 reads the SD \
         map), 2 Raytraced (raysvao: one ray per flagged sample)",
    )
        .expr("index(`refinement`)"),
    Constant::new("SvaoParams.interval", "`interval`: off 0, on 1 [on]")
        .expr("index(`interval`)"),
    Constant::new("SvaoParams.cutoff", "`cutoff`: radius cutoff in full-resolution pixels [6]")
        .expr("`cutoff`"),
    Constant::new(
        "SvaoParams.sd_guard",
        "SD guard band in SD texels: floor(`sd-guard`/div), div = 1, 2, 4, 8, 16 for `sd-res` full, half, \
         quarter, eighth, sixteenth [floor(512/4) = 128]; 0 when `sd-source` = raster (always in sdsvao) and without an SD map \
         (Secondary ≠ 1)",
    )
        .expr("select(`refinement` == \"sd-map\" && `sd-source` == \"ray\", div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16)), 0)"),
    Constant::new(
        "SvaoParams.sd_low_res",
        "(ceil(W/div), ceil(H/div)) SD texels, div = 1, 2, 4, 8, 16 for `sd-res` full, half, quarter, \
         eighth, sixteenth [4], W×H the full target incl. its guard band; (1, 1) without an SD map (Secondary ≠ 1)",
    )
        .expr("select(`refinement` == \"sd-map\", uvec2(div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)), div_ceil(H, pick(index(`sd-res`), 1, 2, 4, 8, 16))), uvec2(1, 1))"),
    Constant::new("SvaoParams.sd_layers", "N = `sd-layers` [4]")
        .expr("`sd-layers`"),
    Constant::new("SvaoParams.max_count", "max(`max-count`, `sd-layers`) [max(8, 4) = 8]")
        .expr("max(`max-count`, `sd-layers`)"),
    Constant::new(
        "SvaoParams.jitter",
        "JitterTable of `jitter`: none 0, scrambled 1, paper 2 [scrambled 1]; 0 when `sd-source` = raster \
         (always in sdsvao)",
    )
        .expr("select(`sd-source` == \"raster\", 0, index(`jitter`))"),
    Constant::new("SvaoParams.dual", "`primary`: single 0, dual 1 [single 0]")
        .expr("index(`primary`)"),
    Constant::new("SvaoParams.kernel", "`kernel`: vao 0 (KERNEL_VAO), hbao 1 (KERNEL_HBAO); hbao and hbao-sd: 1")
        .expr("index(`kernel`)"),
    Constant::new(
        "SvaoParams.sample_set",
        "`ao-samples`: 8 → 0, 16 → 1, 32 → 2 (N = 8·2^sample_set samples per pixel) [8 → 0]",
    )
        .expr("index(`ao-samples`)"),
    Constant::new(
        "SvaoParams.noise_frame",
        "the frame index (FrameDesc::frame_index; 0 for a single frame): rotates the SD maps' hashes by \
         frame_rotation(f mod 64) and offsets the jitter index by f mod 16",
    )
        .expr("frame"),
    Constant::new("SvaoParams._pad0", "0")
        .expr("0"),
    Constant::new("SvaoParams._pad1", "0")
        .expr("0"),
    Constant::new("SvaoParams._pad2", "0")
        .expr("0"),
    Constant::new(
        "RasterParams.world_to_view",
        "Camera.world_to_view of the frame (pushed to gbuffer_vs by the raster SD pass, sd_map_raster)",
    )
        .expr("inverse_rigid(look_at(eye, target, up))"),
    Constant::new("RasterParams.view", "the frame's ViewParams (ViewParams rows); the pass's viewport is the SD map")
        .expr("ViewParams"),
    Constant::new("RasterParams.peel_separation", "0 (the SD map's pass peels nothing)")
        .expr("0.0"),
    Constant::new("RasterParams._pad0", "0")
        .expr("0"),
    Constant::new("RasterParams._pad1", "0")
        .expr("0"),
    Constant::new("RasterParams._pad2", "0")
        .expr("0"),
];

/// The SD map's size and dispatch (spec svao-raysd §3: `ceil(W/div) + 2·guard` texels per
/// side, the guard band `floor(sd-guard/div)` SD texels, none for the raster map) as expressions
/// of the settings; without an SD map the ray-interval buffers are one word.
pub const SD_MAP_FORMULAS: &[Formula] = {
    const X: &str = "div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * select(`sd-source` == \"ray\", \
                     div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16)), 0)";
    const Y: &str = "div_ceil(H, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * select(`sd-source` == \"ray\", \
                     div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16)), 0)";
    const TEXELS: &str = "select(`refinement` == \"sd-map\", (div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * \
                          select(`sd-source` == \"ray\", div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16)), 0)) \
                          * (div_ceil(H, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * select(`sd-source` == \"ray\", \
                          div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16)), 0)), 1)";
    &[
        Formula { of: "ray_min", expr: TEXELS },
        Formula { of: "ray_max", expr: TEXELS },
        Formula {
            of: "sd_map",
            expr: "(div_ceil(W, pick(index(`sd-res`), 1, 2, 4, 8, 16)) + 2 * select(`sd-source` == \"ray\", \
                   div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, 8, 16)), 0)) * (div_ceil(H, pick(index(`sd-res`), \
                   1, 2, 4, 8, 16)) + 2 * select(`sd-source` == \"ray\", div_floor(`sd-guard`, pick(index(`sd-res`), 1, 2, 4, \
                   8, 16)), 0)) * `sd-layers`",
        },
        Formula { of: "sd_map.x", expr: X },
        Formula { of: "sd_map.y", expr: Y },
        Formula { of: "sd_map_raster.x", expr: X },
        Formula { of: "sd_map_raster.y", expr: Y },
    ]
};

/// The stenciled family's constants: [`SVAO`], VAO's and the blur's, the camera's.
pub const CONSTANTS: &[Constant] =
    crate::join_constants![SVAO, crate::vao::settings::CONSTANTS, crate::common::camera::CONSTANTS];

/// Ray-SD's SD-map trace (spec svao-raysd §7) over `extent` (the SD texels): the pipeline's
/// raygen, miss and any-hit, or its ray-query variant, reading the record `svao_frame`, the
/// G-buffer, the intervals `ray_min` / `ray_max`, writing `sd_map` and counting its rays; what
/// the stenciled family and `vbao-sd` trace.
pub fn sd_map_pass(extent: Extent) -> Pass {
    let bindings = crate::raysd::rq::raysd_rq::Bindings {
        frame: "svao_frame",
        tlas: inputs::SCENE_TLAS,
        depth: inputs::LINEAR_DEPTH,
        normals: inputs::VIEW_NORMALS,
        ray_min: "ray_min",
        ray_max: "ray_max",
        sd_map: "sd_map",
        uvs: inputs::SCENE_UVS,
        materials: inputs::SCENE_MATERIALS,
        mask_headers: inputs::SCENE_MASK_HEADERS,
        mask_texels: inputs::SCENE_MASK_TEXELS,
        ray_count: RAY_COUNT,
    };
    use crate::raysd::rt::{raysd_ahit, raysd_miss, raysd_rgen};
    let shaders = [&raysd_rgen::ENTRY, &raysd_miss::ENTRY, &raysd_ahit::ENTRY];
    Pass::ray_traced("sd_map", shaders, bindings, extent)
}

/// Pass 1, refined as [`SvaoSettings::refinement`] says: not at all (every pixel final, spec
/// svao-raysd §5), from a stochastic depth map, ray-traced or raster (spec svao-raysd §7–§9), or
/// by one ray per flagged sample (spec svao-raysd §10).
pub fn refined(s: &SvaoSettings, frame: &FrameDesc) -> Result<Graph, String> {
    s.graph(frame, s.refinement)
}

/// VAO's pass 1 alone with the HBAO+ kernel, on single or dual depth (spec svao-raysd §4.5, §11).
pub static HBAO: Declaration<SvaoSettings> = stenciled(
    "hbao",
    "HBAO+ kernel on single or dual depth, no refinement (spec svao-raysd §4.5, §11)",
    &["primary", "peel-separation", "ao-samples"],
    || SvaoSettings { hbao: true, ..Default::default() },
    refined,
);

/// Stenciled VAO refined from the ray-traced stochastic depth map (spec svao-raysd §3, §5, §7, §9).
pub static RAYSD: Declaration<SvaoSettings> = stenciled(
    "raysd",
    "stenciled VAO refined from a ray-traced stochastic depth map (spec svao-raysd §3, §5, §7, §9)",
    &[
        "sd-res",
        "sd-layers",
        "max-count",
        "cutoff",
        "interval",
        "jitter",
        "sd-guard",
        "primary",
        "peel-separation",
        "kernel",
        "sd-source",
        "ao-samples",
    ],
    || SvaoSettings { refinement: Secondary::StochasticDepth, ..Default::default() },
    refined,
);

/// Ray-SD with the HBAO+ kernel in both AO passes (spec svao-raysd §4.5).
pub static HBAO_SD: Declaration<SvaoSettings> = stenciled(
    "hbao-sd",
    "Ray-SD with the HBAO+ kernel (spec svao-raysd §4.5, §9)",
    &[
        "sd-res",
        "sd-layers",
        "max-count",
        "cutoff",
        "interval",
        "jitter",
        "sd-guard",
        "primary",
        "peel-separation",
        "ao-samples",
    ],
    || SvaoSettings { hbao: true, refinement: Secondary::StochasticDepth, ..Default::default() },
    refined,
);

/// Stenciled VAO refined from the raster coverage-mask SD map (spec svao-raysd §8; no SD guard
/// band, no jitter).
pub static SDSVAO: Declaration<SvaoSettings> = stenciled(
    "sdsvao",
    "stenciled VAO refined from the raster coverage-mask SD map (spec svao-raysd §8)",
    &["sd-res", "sd-layers", "max-count", "cutoff", "interval", "primary", "peel-separation", "kernel", "ao-samples"],
    || SvaoSettings { raster: true, refinement: Secondary::StochasticDepth, ..Default::default() },
    refined,
);

/// Stenciled VAO refined by one ray per flagged sample (spec svao-raysd §10), the Ray-SD reference;
/// with `kernel` = hbao the HBAO+ variant (first hit per ray, max combination, svao-raysd §4.5, §10).
pub static RAYSVAO: Declaration<SvaoSettings> = stenciled(
    "raysvao",
    "stenciled VAO or HBAO+ refined by one ray per flagged sample, the Ray-SD reference (spec svao-raysd §10)",
    &["cutoff", "primary", "peel-separation", "kernel", "ao-samples"],
    || SvaoSettings { refinement: Secondary::Raytraced, ..Default::default() },
    refined,
);

impl SvaoSettings {
    /// The SVAO record (the kernels' constants) for a secondary source: Ray-SD, Ray-SVAO (no
    /// SD map, no guard) or none (pass 1 finalizes every pixel).
    pub fn frame(&self, frame: &FrameDesc, secondary: Secondary) -> SvaoFrame {
        let full = frame.size();
        let is_sd = secondary == Secondary::StochasticDepth;
        // The raster SD map has no guard band and no jitter (spec svao-raysd §3, §8).
        let guard = if self.raster { 0 } else { self.guard / self.divisor };
        let (low, guard) = if is_sd { (sd_low_res(full, self.divisor), guard) } else { (uvec2(1, 1), 0) };
        SvaoFrame {
            camera: frame.camera,
            params: SvaoParams {
                // The reference's UI scales R by 1.5 for the HBAO+ kernel (spec svao-raysd §2, §4.5).
                vao: crate::vao::VaoParams {
                    radius: frame.radius * if self.hbao { 1.5 } else { 1.0 },
                    ..vao_params(frame)
                },
                secondary: secondary as u32,
                interval: self.interval as u32,
                cutoff: self.cutoff,
                sd_guard: guard,
                sd_low_res: low,
                sd_layers: self.layers,
                max_count: self.max_count.max(self.layers),
                jitter: if self.raster { JitterTable::None as u32 } else { self.jitter as u32 },
                dual: self.dual as u32,
                kernel: if self.hbao { KERNEL_HBAO } else { KERNEL_VAO },
                sample_set: sample_set(self.samples),
                noise_frame: frame.frame_index,
                _pad0: 0,
                _pad1: 0,
                _pad2: 0,
            },
        }
    }

    /// The pass graph for `secondary` (spec svao-raysd §3): pass 1, then the SD map and pass 2
    /// (Ray-SD, or the raster coverage-mask map of svao-raysd §8 when `raster`) or the per-sample rays
    /// (Ray-SVAO), then the blur.
    pub fn graph(&self, frame: &FrameDesc, secondary: Secondary) -> Result<Graph, String> {
        let svao = self.frame(frame, secondary);
        let params = &svao.params;
        // The SD map's texels: its reduced resolution plus its guard band (one texel when there
        // is no SD map).
        let sd_extent = Extent::Reduced { divisor: self.divisor, border: params.sd_guard };
        let sd_texels = |per_texel| match secondary {
            Secondary::StochasticDepth => Size::Texels { extent: sd_extent, per_texel },
            _ => Size::Words(per_texel as usize),
        };
        // Dual depth reads the peeled layer; single depth binds the depth buffer there (unread).
        let depth2 = if self.dual { inputs::SECOND_DEPTH } else { inputs::LINEAR_DEPTH };
        let per_frame =
            |name, elem, size, init, doc| Resource { name, elem, size, init, lifetime: Lifetime::PerFrame, doc };
        let mut resources = vec![
            record("svao_frame", std::slice::from_ref(&svao), "camera + SvaoParams of both AO passes and the rays"),
            target_f32("ao", 1.0, "AO: final after pass 1 where unflagged, refined by pass 2 (spec svao-raysd §5, §9)"),
            target_u32("refine_mask", 0, "per-pixel bit mask of the samples pass 1 flagged (spec svao-raysd §5)"),
            per_frame(
                "ray_min",
                Elem::U32,
                sd_texels(1),
                Init::Fill(RAY_MIN_CLEAR),
                "per-SD-texel ray tMin, float bits (svao-raysd §6)",
            ),
            per_frame(
                "ray_max",
                Elem::U32,
                sd_texels(1),
                Init::Fill(RAY_MAX_CLEAR),
                "per-SD-texel ray tMax, float bits (svao-raysd §6)",
            ),
        ];
        let (g, n) = (inputs::LINEAR_DEPTH, inputs::VIEW_NORMALS);
        let pass1 = super::svao_pass1::Bindings {
            frame: "svao_frame",
            depth: g,
            normals: n,
            ao: "ao",
            mask: "refine_mask",
            ray_min: "ray_min",
            ray_max: "ray_max",
            depth2,
        };
        let mut passes = vec![Pass::compute("ao_pass1", pass1, Extent::Inner, &[])];
        match secondary {
            Secondary::Disabled => {}
            Secondary::StochasticDepth => {
                resources.push(per_frame(
                    "sd_map",
                    Elem::F32,
                    sd_texels(params.sd_layers),
                    Init::Fill(1f32.to_bits()),
                    "N normalized depths per SD texel (spec svao-raysd §7)",
                ));
                if self.raster {
                    // The raster coverage-mask SD map (spec svao-raysd §8): the scene drawn at SD resolution.
                    let bindings = crate::rastersd::rastersd_fs::Bindings {
                        mask_headers: inputs::SCENE_MASK_HEADERS,
                        mask_texels: inputs::SCENE_MASK_TEXELS,
                        frame: "svao_frame",
                        depth: g,
                        ray_min: "ray_min",
                        ray_max: "ray_max",
                        sd_bits: "sd_map",
                    };
                    let raster = crate::gbuffer::RasterParams {
                        world_to_view: frame.camera.world_to_view,
                        view: frame.camera.view,
                        peel_separation: 0.0,
                        _pad0: 0,
                        _pad1: 0,
                        _pad2: 0,
                    };
                    let vertex = &crate::gbuffer::gbuffer_vs::ENTRY;
                    passes.push(Pass::raster(
                        "sd_map_raster",
                        vertex,
                        bindings,
                        sd_extent,
                        bytemuck::bytes_of(&raster),
                    ));
                }
                let traced = sd_map_pass(sd_extent);
                if !self.raster {
                    passes.push(traced);
                    resources.push(ray_counter());
                }
                let pass2 = crate::raysd::raysd_pass2::Bindings {
                    frame: "svao_frame",
                    depth: g,
                    normals: n,
                    ao: "ao",
                    mask: "refine_mask",
                    sd_map: "sd_map",
                    depth2,
                };
                passes.push(Pass::compute("ao_pass2", pass2, Extent::Inner, &[]));
            }
            Secondary::Raytraced => {
                let bindings = crate::raysvao::rq::raysvao_rq::Bindings {
                    frame: "svao_frame",
                    tlas: inputs::SCENE_TLAS,
                    depth: g,
                    normals: n,
                    ao: "ao",
                    mask: "refine_mask",
                    uvs: inputs::SCENE_UVS,
                    materials: inputs::SCENE_MATERIALS,
                    mask_headers: inputs::SCENE_MASK_HEADERS,
                    mask_texels: inputs::SCENE_MASK_TEXELS,
                    depth2,
                    ray_count: RAY_COUNT,
                };
                use crate::raysvao::rt::{raysvao_ahit, raysvao_miss, raysvao_rgen};
                let shaders = [&raysvao_rgen::ENTRY, &raysvao_miss::ENTRY, &raysvao_ahit::ENTRY];
                resources.push(ray_counter());
                passes.push(Pass::ray_traced("ao_pass2_rays", shaders, bindings, Extent::Inner));
            }
        }
        let (r, p) = blur_passes(frame, "ao", "ao_final");
        resources.extend(r);
        passes.extend(p);
        resources.push(target_f32("ao_pass1", 1.0, "copy of the AO after pass 1, for reports"));
        let snapshots = vec![Snapshot { after: 0, from: "ao", to: "ao_pass1" }];
        // The raster SD map traces no rays; without an SD map the ray counter counts them all.
        let refinement = if self.raster && secondary == Secondary::StochasticDepth {
            RefinementDecoder { name: "svao (raster SD map)", decode: rasterized_refinement }
        } else {
            RefinementDecoder { name: "svao", decode: traced_refinement }
        };
        let diagnostics = Diagnostics { refinement: Some(refinement), ..Default::default() };
        let view = frame.camera.view;
        Ok(Graph { resources, passes, output: "ao_final", raw_output: "ao", snapshots, view, diagnostics })
    }
}

/// The refinement of a run whose SD map (if any) was ray traced: the refined samples, the
/// buffers, and for Ray-SD the rays' summed interval length `Σ (tMax − tMin)` by the map's own
/// ray setup (spec svao-raysd §7).
fn traced_refinement(run: &Executed) -> Refinement {
    let mut r = refinement(run);
    if !r.ray_max.is_empty() {
        let frame = svao_frame(run);
        let g = GBufferSlices { depth: run.depth, normals: run.normals, width: frame.params.vao.view.size().x };
        let mut sum = 0.0f64;
        for y in 0..r.sd_size.y {
            for x in 0..r.sd_size.x {
                let q = uvec2(x, y);
                let i = frame.params.sd_index(q);
                let ray = crate::raysd::sd_ray(&g, &frame, q, r.ray_min[i], r.ray_max[i]);
                if ray.traced() {
                    sum += (ray.t_max - ray.t_min) as f64;
                }
            }
        }
        r.interval_sum = Some(sum);
    }
    r
}

/// The refinement of a run with the raster SD map (spec svao-raysd §8), which traces no rays:
/// its "rays" are the SD texels it was asked for.
fn rasterized_refinement(run: &Executed) -> Refinement {
    let r = refinement(run);
    Refinement { rays: Some(r.ray_max.iter().filter(|&&m| m != 0).count() as u64), ..r }
}

/// The frame record the graph ran with.
fn svao_frame(run: &Executed) -> SvaoFrame {
    let record = (run.words)("svao_frame").expect("a stenciled graph declares its svao_frame record");
    bytemuck::pod_read_unaligned(&bytemuck::cast_slice::<u32, u8>(&record)[..size_of::<SvaoFrame>()])
}

/// What every stenciled run reports: its refine mask, pass-1 AO and, with an SD map, the ray
/// intervals and the map.
fn refinement(run: &Executed) -> Refinement {
    let params = svao_frame(run).params;
    let mask = run.u32s("refine_mask");
    let sd = params.secondary == Secondary::StochasticDepth as u32;
    let intervals = |name| if sd { run.u32s(name) } else { Vec::new() };
    Refinement {
        refined_samples: mask.iter().map(|m| m.count_ones() as u64).sum(),
        rays: None,
        interval_sum: None,
        ao_pass1: run.f32s("ao_pass1"),
        mask,
        ray_min: intervals("ray_min"),
        ray_max: intervals("ray_max"),
        sd_size: params.sd_size(),
        sd_map: run.f32s("sd_map"),
        layers: params.sd_layers,
    }
}
