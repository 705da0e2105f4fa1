//! The AO techniques a user picks by name, their options, and one run of a technique on a given
//! G-buffer (the same G-buffer for every technique of a comparison).

use crate::frame::Frame;
use aokit_shaders::common::tables::JitterTable;
use aokit_shaders::glam::{UVec2, uvec2};
use aokit_shaders::groundtruth::GroundTruthParams;
use aokit_shaders::gtao::GtaoParams;
use aokit_shaders::hybrid::{HybridFrame, HybridParams};
use aokit_shaders::raymarch::{Contribution, RaymarchParams};
use aokit_shaders::svao::{Secondary, SvaoFrame, SvaoParams};
use aokit_shaders::vao::VaoParams;
use aokit_shaders::vao::kernel::{KERNEL_HBAO, KERNEL_VAO};

/// Options of the ray-traced stochastic depth map (spec svao-raysd §2 defaults).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct SdOptions {
    /// SD-map resolution divisor: 1 (full), 2 (½) or 4 (¼, default).
    pub divisor: u32,
    /// Layers N: 1, 2, 4 (default) or 8.
    pub layers: u32,
    /// MAX_COUNT of the reservoir any-hit (default 8; raised to N when smaller).
    pub max_count: u32,
    /// Radius cutoff in full-res pixels (default 6).
    pub cutoff: f32,
    /// Ray-interval optimisation (default on).
    pub interval: bool,
    /// Jitter table (default: the reference's scrambled table).
    pub jitter: JitterTable,
    /// SD guard band in full-res pixels (default 512, i.e. 128 SD texels at ¼).
    pub guard: u32,
    /// Primary depth mode of the VAO family: dual depth adds a depth-peeled second layer
    /// (spec svao-raysd §11) [single].
    pub dual: bool,
    /// Minimum separation of the peeled layer [0.01, as SVAO.py].
    pub peel_separation: f32,
    /// The HBAO+ kernel instead of VAO's (spec §4.5; the radius is scaled by 1.5 as the
    /// reference's UI does: 0.2 → 0.3) [VAO].
    pub hbao: bool,
    /// Where the SD map comes from: ray tracing (Ray-SD) or the raster coverage-mask baseline
    /// (spec §8: no SD guard band, no jitter) [ray].
    pub raster: bool,
}

impl Default for SdOptions {
    fn default() -> Self {
        SdOptions {
            divisor: 4,
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
        }
    }
}

impl SdOptions {
    /// Reject options the kernels do not support, with a message naming the option.
    pub fn validate(&self) -> Result<(), String> {
        if ![1, 2, 4].contains(&self.divisor) {
            return Err(format!("--sd-res: divisor {} is not 1 (full), 2 (half) or 4 (quarter)", self.divisor));
        }
        if ![1, 2, 4, 8].contains(&self.layers) {
            return Err(format!("--sd-layers {} is not 1, 2, 4 or 8", self.layers));
        }
        if self.max_count == 0 {
            return Err("--max-count must be at least 1".into());
        }
        if !(self.peel_separation.is_finite() && self.peel_separation >= 0.0) {
            return Err(format!("--peel-separation {} must be a non-negative distance", self.peel_separation));
        }
        if !(self.cutoff.is_finite() && self.cutoff >= 0.0) {
            return Err(format!("--cutoff {} must be a non-negative number of pixels", self.cutoff));
        }
        Ok(())
    }

    /// The options as JSON for reports.
    pub fn describe(&self) -> serde_json::Value {
        serde_json::json!({
            "sd_res": match self.divisor { 1 => "full", 2 => "half", _ => "quarter" },
            "sd_layers": self.layers, "max_count": self.max_count.max(self.layers), "cutoff": self.cutoff,
            "interval": self.interval, "jitter": format!("{:?}", self.jitter).to_lowercase(),
            "sd_guard": self.guard, "primary": if self.dual { "dual" } else { "single" },
            "kernel": if self.hbao { "hbao" } else { "vao" }, "sd_source": if self.raster { "raster" } else { "ray" },
        })
    }
}

/// XeGTAO quality presets (spec gtao-raymarch-hybrid §2.2): slices × steps per side.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum GtaoPreset {
    Low,
    Medium,
    High,
    Ultra,
}

impl GtaoPreset {
    /// `(slices, steps per side)`.
    pub fn slices_steps(self) -> (u32, u32) {
        match self {
            GtaoPreset::Low => (1, 2),
            GtaoPreset::Medium => (2, 2),
            GtaoPreset::High => (3, 3),
            GtaoPreset::Ultra => (9, 3),
        }
    }

    pub fn parse(s: &str) -> Result<GtaoPreset, String> {
        Ok(match s {
            "low" => GtaoPreset::Low,
            "medium" => GtaoPreset::Medium,
            "high" => GtaoPreset::High,
            "ultra" => GtaoPreset::Ultra,
            _ => return Err(format!("preset '{s}' is not low, medium, high or ultra")),
        })
    }
}

/// XeGTAO settings (spec §2.1 defaults; the effect radius is the frame's AO radius).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct GtaoOptions {
    pub preset: GtaoPreset,
    /// 0 (off) … 3 (soft) [1].
    pub denoise_passes: u32,
    pub radius_multiplier: f32,
    pub falloff_range: f32,
    pub sample_distribution_power: f32,
    pub thin_occluder_compensation: f32,
    pub final_value_power: f32,
    pub depth_mip_sampling_offset: f32,
    /// Derive normals from depth (pass 0) instead of using the G-buffer's.
    pub normals_from_depth: bool,
}

impl Default for GtaoOptions {
    fn default() -> Self {
        GtaoOptions {
            preset: GtaoPreset::High,
            denoise_passes: 1,
            radius_multiplier: 1.457,
            falloff_range: 0.615,
            sample_distribution_power: 2.0,
            thin_occluder_compensation: 0.0,
            final_value_power: 2.2,
            depth_mip_sampling_offset: 3.30,
            normals_from_depth: false,
        }
    }
}

impl GtaoOptions {
    /// Reject settings outside XeGTAO's UI ranges (spec §2.1), naming the setting.
    pub fn validate(&self) -> Result<(), String> {
        let check = |name: &str, v: f32, lo: f32, hi: f32| {
            if v.is_finite() && (lo..=hi).contains(&v) {
                Ok(())
            } else {
                Err(format!("{name} {v} is outside [{lo}, {hi}]"))
            }
        };
        check("--gtao-radius-multiplier", self.radius_multiplier, 0.3, 3.0)?;
        check("--gtao-falloff-range", self.falloff_range, 0.0, 1.0)?;
        check("--gtao-sample-power", self.sample_distribution_power, 1.0, 3.0)?;
        check("--gtao-thin-occluder", self.thin_occluder_compensation, 0.0, 0.7)?;
        check("--gtao-final-power", self.final_value_power, 0.5, 5.0)?;
        check("--gtao-mip-offset", self.depth_mip_sampling_offset, 0.0, 30.0)?;
        if self.denoise_passes > 3 {
            return Err(format!("--gtao-denoise {} is not 0–3", self.denoise_passes));
        }
        Ok(())
    }

    pub fn describe(&self) -> serde_json::Value {
        let (slices, steps) = self.preset.slices_steps();
        serde_json::json!({
            "preset": format!("{:?}", self.preset).to_lowercase(), "slices": slices, "steps": steps,
            "denoise_passes": self.denoise_passes, "radius_multiplier": self.radius_multiplier,
            "falloff_range": self.falloff_range, "sample_distribution_power": self.sample_distribution_power,
            "thin_occluder_compensation": self.thin_occluder_compensation,
            "final_value_power": self.final_value_power, "depth_mip_sampling_offset": self.depth_mip_sampling_offset,
            "normals": if self.normals_from_depth { "depth" } else { "gbuffer" },
        })
    }
}

/// Options of the Poisson-disk ray-marched SSAO (spec gtao-raymarch-hybrid §3.2).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RaymarchOptions {
    /// Directions N (8, 16 or 24 in the paper) [16].
    pub directions: u32,
    /// Steps per direction [8].
    pub steps: u32,
    /// Contrast exponent α [1].
    pub alpha: f32,
    /// Eq. 2 reading: `Binary` (c = 0 on a hit) or `Linear` (c = Δ̃/R) [linear].
    pub binary: bool,
    /// Vogel spiral instead of the best-candidate Poisson disk.
    pub vogel: bool,
    /// XeGTAO denoise passes afterwards [0].
    pub denoise_passes: u32,
}

impl Default for RaymarchOptions {
    fn default() -> Self {
        RaymarchOptions { directions: 16, steps: 8, alpha: 1.0, binary: false, vogel: false, denoise_passes: 0 }
    }
}

/// Options of the hybrid AO (spec §4.1): rays per pixel and the world-ray weight.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct HybridOptions {
    pub screen_rays: u32,
    pub world_rays: u32,
    /// Weight of the world rays [2/3].
    pub world_weight: f32,
    /// Steps of a screen ray [16].
    pub screen_steps: u32,
    /// XeGTAO denoise passes [3].
    pub denoise_passes: u32,
}

impl Default for HybridOptions {
    fn default() -> Self {
        HybridOptions { screen_rays: 1, world_rays: 1, world_weight: 2.0 / 3.0, screen_steps: 16, denoise_passes: 3 }
    }
}

impl HybridOptions {
    /// The paper's variants: `mixed` (1 screen + 1 world, w = 2/3), `world` (2 world rays),
    /// `screen` (2 screen rays).
    pub fn variant(name: &str) -> Result<HybridOptions, String> {
        let d = HybridOptions::default();
        Ok(match name {
            "mixed" => d,
            "world" => HybridOptions { screen_rays: 0, world_rays: 2, world_weight: 1.0, ..d },
            "screen" => HybridOptions { screen_rays: 2, world_rays: 0, world_weight: 0.0, ..d },
            _ => return Err(format!("hybrid variant '{name}' is not mixed, world or screen")),
        })
    }
}

/// An AO technique.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Technique {
    /// Plain VAO on the depth buffer (spec §4–§5).
    Vao,
    /// Plain VAO on dual depth: the depth buffer plus a depth-peeled second layer (spec §11).
    VaoDual { peel_separation: f32 },
    /// The HBAO+ kernel on single or dual depth (spec §4.5, §11), no refinement.
    Hbao { dual: bool, peel_separation: f32 },
    /// Stenciled VAO refined from the ray-traced stochastic depth map (spec §3, §5, §7, §9).
    RaySd(SdOptions),
    /// Stenciled VAO refined by one ray per flagged sample (spec §10), the Ray-SD reference.
    RaySvao { cutoff: f32, dual: bool },
    /// World-space ray-traced AO (spec gtao-raymarch-hybrid §5).
    GroundTruth { spp: u32, uniform: bool },
    /// XeGTAO (spec gtao-raymarch-hybrid §2).
    Gtao(GtaoOptions),
    /// Poisson-disk ray-marched SSAO (spec §3).
    Raymarch(RaymarchOptions),
    /// Hybrid screen + world-ray AO (spec §4).
    Hybrid(HybridOptions),
}

impl Technique {
    /// The name the CLI uses.
    pub fn name(&self) -> &'static str {
        match self {
            Technique::Vao | Technique::VaoDual { .. } => "vao",
            Technique::Hbao { .. } => "hbao",
            Technique::RaySd(o) if o.raster => "sdsvao",
            Technique::RaySd(o) if o.hbao => "hbao-sd",
            Technique::RaySd(_) => "raysd",
            Technique::RaySvao { .. } => "raysvao",
            Technique::GroundTruth { .. } => "groundtruth",
            Technique::Gtao(_) => "gtao",
            Technique::Raymarch(_) => "raymarch",
            Technique::Hybrid(_) => "hybrid",
        }
    }

    /// Techniques from their CLI names, with shared options.
    /// Per-technique overrides follow the name as `:key=value` (keys `sd-res`
    /// full|half|quarter, `sd-layers`, `max-count`, `cutoff`, `interval` on|off, `jitter`
    /// none|scrambled|paper, `sd-guard`, `spp`), e.g. `raysd:sd-layers=8:interval=off`.
    pub fn parse(spec: &str, defaults: &TechniqueDefaults) -> Result<Technique, String> {
        let mut parts = spec.trim().split(':');
        let name = parts.next().unwrap_or_default();
        let TechniqueDefaults { mut sd, mut gtao, mut raymarch, mut hybrid, mut spp, uniform } = *defaults;
        for part in parts {
            let (key, value) = part.split_once('=').ok_or_else(|| format!("'{part}' in '{spec}' is not key=value"))?;
            let bad = |what: &str| format!("{key}={value} in '{spec}': expected {what}");
            let number = |what: &str| value.parse::<u32>().map_err(|_| bad(what));
            match key {
                "sd-res" => {
                    sd.divisor = match value {
                        "full" => 1,
                        "half" => 2,
                        "quarter" => 4,
                        _ => return Err(bad("full, half or quarter")),
                    }
                }
                "sd-layers" => sd.layers = number("1, 2, 4 or 8")?,
                "max-count" => sd.max_count = number("a count")?,
                "cutoff" => sd.cutoff = value.parse().map_err(|_| bad("pixels"))?,
                "interval" => {
                    sd.interval = match value {
                        "on" => true,
                        "off" => false,
                        _ => return Err(bad("on or off")),
                    }
                }
                "jitter" => {
                    sd.jitter = match value {
                        "none" => JitterTable::None,
                        "scrambled" => JitterTable::Scrambled,
                        "paper" => JitterTable::Paper,
                        _ => return Err(bad("none, scrambled or paper")),
                    }
                }
                "sd-guard" => sd.guard = number("pixels")?,
                "sd-source" => {
                    sd.raster = match value {
                        "raster" => true,
                        "ray" => false,
                        _ => return Err(bad("raster or ray")),
                    }
                }
                "kernel" => {
                    sd.hbao = match value {
                        "hbao" => true,
                        "vao" => false,
                        _ => return Err(bad("vao or hbao")),
                    }
                }
                "primary" => {
                    sd.dual = match value {
                        "dual" => true,
                        "single" => false,
                        _ => return Err(bad("single or dual")),
                    }
                }
                "spp" => spp = number("rays per pixel")?,
                "preset" => gtao.preset = GtaoPreset::parse(value)?,
                "denoise" => gtao.denoise_passes = number("0–3")?,
                "normals" => {
                    gtao.normals_from_depth = match value {
                        "depth" => true,
                        "gbuffer" => false,
                        _ => return Err(bad("depth or gbuffer")),
                    }
                }
                "final-power" => gtao.final_value_power = value.parse().map_err(|_| bad("a power"))?,
                "directions" => raymarch.directions = number("a count")?,
                "steps" => raymarch.steps = number("a count")?,
                "alpha" => raymarch.alpha = value.parse().map_err(|_| bad("an exponent"))?,
                "contribution" => {
                    raymarch.binary = match value {
                        "binary" => true,
                        "linear" => false,
                        _ => return Err(bad("binary or linear")),
                    }
                }
                "variant" => {
                    hybrid = HybridOptions { denoise_passes: hybrid.denoise_passes, ..HybridOptions::variant(value)? }
                }
                "world-weight" => hybrid.world_weight = value.parse().map_err(|_| bad("a weight in [0, 1]"))?,
                _ => return Err(format!("unknown option '{key}' in '{spec}'")),
            }
        }
        sd.validate()?;
        gtao.validate()?;
        if !(1..=aokit_shaders::raymarch::MAX_DIRECTIONS).contains(&raymarch.directions) || raymarch.steps == 0 {
            return Err(format!("'{spec}': raymarch needs 1–64 directions and at least 1 step"));
        }
        if !(0.0..=1.0).contains(&hybrid.world_weight) || hybrid.screen_rays + hybrid.world_rays == 0 {
            return Err(format!("'{spec}': hybrid needs a world weight in [0, 1] and at least one ray"));
        }
        if spp == 0 {
            return Err(format!("'{spec}': spp must be at least 1"));
        }
        Ok(match name {
            "vao" | "hbao" if sd.hbao || name == "hbao" => {
                Technique::Hbao { dual: sd.dual, peel_separation: sd.peel_separation }
            }
            "vao" if sd.dual => Technique::VaoDual { peel_separation: sd.peel_separation },
            "vao" => Technique::Vao,
            "raysd" | "hbao-sd" => Technique::RaySd(SdOptions { hbao: sd.hbao || name == "hbao-sd", ..sd }),
            "sdsvao" => Technique::RaySd(SdOptions { raster: true, ..sd }),
            "raysvao" if sd.hbao => {
                return Err("raysvao traces the VAO halo model only; the HBAO+ kernel runs as hbao or hbao-sd".into());
            }
            "raysvao" => Technique::RaySvao { cutoff: sd.cutoff, dual: sd.dual },
            "groundtruth" => Technique::GroundTruth { spp, uniform },
            "gtao" => Technique::Gtao(gtao),
            "raymarch" => Technique::Raymarch(raymarch),
            "hybrid" => Technique::Hybrid(hybrid),
            other => {
                return Err(format!(
                    "unknown technique '{other}' (known: vao, hbao, raysd, hbao-sd, sdsvao, raysvao, gtao, raymarch, hybrid, groundtruth)"
                ));
            }
        })
    }

    /// A label for tables and file names: the name plus the options that differ from
    /// `defaults`, e.g. `raysd_n8`.
    pub fn label(&self, defaults: &SdOptions) -> String {
        let mut label = self.name().to_string();
        if matches!(
            self,
            Technique::VaoDual { .. } | Technique::Hbao { dual: true, .. } | Technique::RaySvao { dual: true, .. }
        ) {
            label += "_dual";
        }
        if let Technique::Gtao(o) = self {
            let d = GtaoOptions::default();
            if o.preset != d.preset {
                label += &format!("_{:?}", o.preset).to_lowercase();
            }
            if o.denoise_passes != d.denoise_passes {
                label += &format!("_denoise{}", o.denoise_passes);
            }
            if o.normals_from_depth {
                label += "_depthnormals";
            }
        }
        if let Technique::Raymarch(o) = self {
            let d = RaymarchOptions::default();
            if o.directions != d.directions {
                label += &format!("_n{}", o.directions);
            }
            if o.binary {
                label += "_binary";
            }
        }
        if let Technique::Hybrid(o) = self {
            match (o.screen_rays, o.world_rays) {
                (0, _) => label += "_world",
                (_, 0) => label += "_screen",
                _ => {}
            }
        }
        if let Technique::RaySd(o) = self {
            let d = defaults;
            for (differs, text) in [
                (o.divisor != d.divisor, format!("_div{}", o.divisor)),
                (o.layers != d.layers, format!("_n{}", o.layers)),
                (o.max_count != d.max_count, format!("_max{}", o.max_count)),
                (o.cutoff != d.cutoff, format!("_cut{}", o.cutoff)),
                (o.interval != d.interval, format!("_interval{}", if o.interval { "on" } else { "off" })),
                (o.jitter != d.jitter, format!("_jitter{:?}", o.jitter).to_lowercase()),
                (o.guard != d.guard, format!("_guard{}", o.guard)),
                (o.dual != d.dual, if o.dual { "_dual".into() } else { "_single".into() }),
            ] {
                if differs {
                    label += &text;
                }
            }
        }
        label
    }

    /// Whether the technique's output goes through the bilateral blur (spec §3 step 5).
    pub fn blurred(&self) -> bool {
        matches!(
            self,
            Technique::Vao
                | Technique::VaoDual { .. }
                | Technique::Hbao { .. }
                | Technique::RaySd(_)
                | Technique::RaySvao { .. }
        )
    }

    /// Options as JSON for reports.
    pub fn describe(&self) -> serde_json::Value {
        match self {
            Technique::Vao => serde_json::json!({ "primary": "single" }),
            Technique::VaoDual { peel_separation } => {
                serde_json::json!({ "primary": "dual", "peel_separation": peel_separation })
            }
            Technique::Hbao { dual, peel_separation } => serde_json::json!({
                "kernel": "hbao", "primary": if *dual { "dual" } else { "single" }, "peel_separation": peel_separation,
            }),
            Technique::RaySd(o) => o.describe(),
            Technique::RaySvao { cutoff, dual } => {
                serde_json::json!({ "cutoff": cutoff, "primary": if *dual { "dual" } else { "single" } })
            }
            Technique::GroundTruth { spp, uniform } => serde_json::json!({ "spp": spp, "uniform": uniform }),
            Technique::Gtao(o) => o.describe(),
            Technique::Raymarch(o) => serde_json::json!({
                "directions": o.directions, "steps": o.steps, "alpha": o.alpha,
                "contribution": if o.binary { "binary" } else { "linear" },
                "kernel": if o.vogel { "vogel" } else { "best-candidate" }, "denoise_passes": o.denoise_passes,
            }),
            Technique::Hybrid(o) => serde_json::json!({
                "screen_rays": o.screen_rays, "world_rays": o.world_rays, "world_weight": o.world_weight,
                "screen_steps": o.screen_steps, "denoise_passes": o.denoise_passes,
            }),
        }
    }
}

/// Every technique's options as set on the command line; per-technique `:key=value`
/// overrides start from these.
#[derive(Copy, Clone, Debug, Default)]
pub struct TechniqueDefaults {
    pub sd: SdOptions,
    pub gtao: GtaoOptions,
    pub raymarch: RaymarchOptions,
    pub hybrid: HybridOptions,
    pub spp: u32,
    pub uniform: bool,
}

/// Low-res SD size `ceil(W/div) × ceil(H/div)` of a full target (spec §3).
pub fn sd_low_res(full: UVec2, divisor: u32) -> UVec2 {
    uvec2(full.x.div_ceil(divisor), full.y.div_ceil(divisor))
}

impl Frame {
    /// The SVAO record for a secondary mode: Ray-SD with `sd`, Ray-SVAO (no SD map, no guard),
    /// or plain VAO.
    pub fn svao_frame(&self, secondary: Secondary, sd: &SdOptions) -> SvaoFrame {
        let full = self.camera.view.size();
        let is_sd = secondary == Secondary::StochasticDepth;
        // The raster SD map has no guard band and no jitter (spec §3, §8).
        let guard = if sd.raster { 0 } else { sd.guard / sd.divisor };
        let (low, guard) = if is_sd { (sd_low_res(full, sd.divisor), guard) } else { (uvec2(1, 1), 0) };
        SvaoFrame {
            camera: self.camera,
            params: SvaoParams {
                // The reference's UI scales R by 1.5 for the HBAO+ kernel (spec §2, §4.5).
                vao: VaoParams { radius: self.radius * if sd.hbao { 1.5 } else { 1.0 }, ..self.vao_params() },
                secondary: secondary as u32,
                interval: sd.interval as u32,
                cutoff: sd.cutoff,
                sd_guard: guard,
                sd_low_res: low,
                sd_layers: sd.layers,
                max_count: sd.max_count.max(sd.layers),
                jitter: if sd.raster { JitterTable::None as u32 } else { sd.jitter as u32 },
                dual: sd.dual as u32,
                kernel: if sd.hbao { KERNEL_HBAO } else { KERNEL_VAO },
                _pad2: 0,
            },
        }
    }

    /// XeGTAO parameters with this frame's radius as the effect radius.
    pub fn gtao_params(&self, o: &GtaoOptions) -> GtaoParams {
        let (slices, steps) = o.preset.slices_steps();
        GtaoParams {
            view: self.camera.view,
            radius: self.radius,
            radius_multiplier: o.radius_multiplier,
            falloff_range: o.falloff_range,
            sample_distribution_power: o.sample_distribution_power,
            thin_occluder_compensation: o.thin_occluder_compensation,
            final_value_power: o.final_value_power,
            depth_mip_sampling_offset: o.depth_mip_sampling_offset,
            slices,
            steps,
            denoise_passes: o.denoise_passes,
            noise_frame: 0,
            pass: 0,
        }
    }

    /// Ray-marched SSAO parameters with this frame's radius.
    pub fn raymarch_params(&self, o: &RaymarchOptions) -> RaymarchParams {
        RaymarchParams {
            view: self.camera.view,
            radius: self.radius,
            alpha: o.alpha,
            depth_bias: 0.0008,
            thickness: f32::MAX,
            directions: o.directions,
            steps: o.steps,
            contribution: if o.binary { Contribution::Binary } else { Contribution::Linear } as u32,
            noise_frame: 0,
        }
    }

    /// Hybrid AO record with this frame's camera and radius.
    pub fn hybrid_frame(&self, o: &HybridOptions) -> HybridFrame {
        HybridFrame {
            camera: self.camera,
            params: HybridParams {
                radius: self.radius,
                world_weight: o.world_weight,
                depth_bias: 0.0008,
                screen_rays: o.screen_rays,
                world_rays: o.world_rays,
                screen_steps: o.screen_steps,
                noise_frame: 0,
                _pad: 0,
            },
        }
    }

    /// XeGTAO parameters for running only its denoiser (`passes` passes) after another technique.
    pub fn denoise_params(&self, passes: u32) -> GtaoParams {
        self.gtao_params(&GtaoOptions { denoise_passes: passes, ..Default::default() })
    }

    /// Ground-truth parameters with this frame's radius and exponent.
    pub fn ground_truth_params(&self, spp: u32, uniform: bool) -> GroundTruthParams {
        GroundTruthParams { radius: self.radius, exponent: self.exponent, samples: spp, uniform: uniform as u32 }
    }
}

/// Diagnostic buffers of a stenciled run, for the report's images.
#[derive(Clone, Debug, Default)]
pub struct SvaoDebug {
    /// AO after pass 1 (final where `mask == 0`, the UNORM8-stored sum elsewhere).
    pub ao_pass1: Vec<f32>,
    /// Refinement mask per full-target pixel.
    pub mask: Vec<u32>,
    /// SD-size interval buffers (float bits; 0 = unset) and the SD size.
    pub ray_min: Vec<u32>,
    pub ray_max: Vec<u32>,
    pub sd_size: UVec2,
    /// SD map: `layers` normalized depths per SD texel.
    pub sd_map: Vec<f32>,
    pub layers: u32,
}

/// One technique's result on a G-buffer.
#[derive(Clone, Debug)]
pub struct TechniqueRun {
    /// AO before the blur (full target, guard band = 1).
    pub ao: Vec<f32>,
    /// Final AO: blurred where the technique blurs, else `ao`.
    pub ao_final: Vec<f32>,
    /// `(pass, ms)`: wall clock on the CPU, timestamp queries on Vulkan.
    pub passes: Vec<(&'static str, f64)>,
    /// Rays traced (SD rays, per-sample rays or ground-truth rays).
    pub rays: u64,
    /// Samples flagged for refinement in pass 1.
    pub refined_samples: u64,
    /// Ray-SD: summed interval length `Σ (tMax − tMin)` of the SD rays, world units.
    pub interval_sum: Option<f64>,
    pub debug: Option<SvaoDebug>,
}

impl TechniqueRun {
    /// A run without rays, refinement or diagnostics.
    pub fn plain(ao: Vec<f32>, ao_final: Vec<f32>, passes: Vec<(&'static str, f64)>) -> TechniqueRun {
        TechniqueRun { ao, ao_final, passes, rays: 0, refined_samples: 0, interval_sum: None, debug: None }
    }

    pub fn total_ms(&self) -> f64 {
        self.passes.iter().map(|(_, ms)| ms).sum()
    }
}
