//! The AO techniques a user picks by name, their options, and one run of a technique on a given
//! G-buffer (the same G-buffer for every technique of a comparison).

use crate::frame::Frame;
use aokit_shaders::common::tables::JitterTable;
use aokit_shaders::glam::UVec2;
use aokit_shaders::graph::{FrameDesc, Graph};
use aokit_shaders::groundtruth::GroundTruthParams;
use aokit_shaders::gtao::GtaoParams;
use aokit_shaders::svao::Secondary;

/// XeGTAO's settings and presets (spec gtao-raymarch-hybrid §2.1–§2.2), beside its kernels.
pub use aokit_shaders::gtao::settings::{GtaoSettings as GtaoOptions, Quality as GtaoPreset};
/// The ray-marched SSAO's settings (spec gtao-raymarch-hybrid §3.2), beside its kernels.
pub use aokit_shaders::raymarch::settings::RaymarchSettings as RaymarchOptions;
/// The stenciled family's settings (spec svao-raysd §2), beside their kernels.
pub use aokit_shaders::svao::settings::{SvaoSettings as SdOptions, sd_low_res};

/// Stenciled-family options as JSON for reports.
pub fn describe_sd(o: &SdOptions) -> serde_json::Value {
    serde_json::json!({
        "sd_res": match o.divisor { 1 => "full", 2 => "half", _ => "quarter" },
        "sd_layers": o.layers, "max_count": o.max_count.max(o.layers), "cutoff": o.cutoff,
        "interval": o.interval, "jitter": format!("{:?}", o.jitter).to_lowercase(),
        "sd_guard": o.guard, "primary": if o.dual { "dual" } else { "single" },
        "peel_separation": o.peel_separation,
        "kernel": if o.hbao { "hbao" } else { "vao" }, "sd_source": if o.raster { "raster" } else { "ray" },
    })
}

/// XeGTAO options as JSON for reports.
pub fn describe_gtao(o: &GtaoOptions) -> serde_json::Value {
    let (slices, steps) = o.quality.slices_steps();
    serde_json::json!({
        "preset": format!("{:?}", o.quality).to_lowercase(), "slices": slices, "steps": steps,
        "denoise_passes": o.denoise_passes, "radius_multiplier": o.radius_multiplier,
        "falloff_range": o.falloff_range, "sample_distribution_power": o.sample_distribution_power,
        "thin_occluder_compensation": o.thin_occluder_compensation,
        "final_value_power": o.final_value_power, "depth_mip_sampling_offset": o.depth_mip_sampling_offset,
        "normals": if o.normals_from_depth { "depth" } else { "gbuffer" },
    })
}

/// The ground truth's settings (spec gtao-raymarch-hybrid §5), beside its kernels.
pub use aokit_shaders::groundtruth::settings::GroundTruthSettings;
/// The hybrid AO's settings and variants (spec gtao-raymarch-hybrid §4.1), beside its kernels.
pub use aokit_shaders::hybrid::settings::HybridSettings as HybridOptions;

/// An AO technique.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Technique {
    /// Plain VAO on the depth buffer (spec svao-raysd §4–§5).
    Vao,
    /// Plain VAO on dual depth: the depth buffer plus a depth-peeled second layer (spec svao-raysd §11).
    VaoDual { peel_separation: f32 },
    /// The HBAO+ kernel on single or dual depth (spec svao-raysd §4.5, §11), no refinement.
    Hbao { dual: bool, peel_separation: f32 },
    /// Stenciled VAO refined from the ray-traced stochastic depth map (spec svao-raysd §3, §5, §7, §9).
    RaySd(SdOptions),
    /// Stenciled VAO refined by one ray per flagged sample (spec svao-raysd §10), the Ray-SD reference.
    RaySvao { cutoff: f32, dual: bool, peel_separation: f32 },
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
                "preset" => gtao.quality = GtaoPreset::parse(value)?,
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
        let in_spec = |e: String| format!("'{spec}': {e}");
        sd.validate().map_err(in_spec)?;
        gtao.validate().map_err(in_spec)?;
        raymarch.validate().map_err(in_spec)?;
        hybrid.validate().map_err(in_spec)?;
        GroundTruthSettings { spp, uniform }.validate().map_err(in_spec)?;
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
            "raysvao" => Technique::RaySvao { cutoff: sd.cutoff, dual: sd.dual, peel_separation: sd.peel_separation },
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
            if o.quality != d.quality {
                label += &format!("_{:?}", o.quality).to_lowercase();
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

    /// Whether the technique's output goes through the bilateral blur (spec svao-raysd §3 pass 5, §12).
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

    /// The technique's pass graph for a frame (`None` only for settings the kernels refuse,
    /// which `parse` rejects first).
    pub fn graph(&self, frame: &FrameDesc) -> Option<Graph> {
        let sd = |o: SdOptions, secondary| o.graph(frame, secondary).ok();
        let d = SdOptions::default();
        match *self {
            Technique::Vao => Some(aokit_shaders::vao::settings::graph(frame)),
            Technique::VaoDual { peel_separation } => {
                sd(SdOptions { dual: true, peel_separation, ..d }, Secondary::Disabled)
            }
            Technique::Hbao { dual, peel_separation } => {
                sd(SdOptions { dual, peel_separation, hbao: true, ..d }, Secondary::Disabled)
            }
            Technique::RaySd(o) => sd(o, Secondary::StochasticDepth),
            Technique::RaySvao { cutoff, dual, peel_separation } => {
                sd(SdOptions { cutoff, dual, peel_separation, ..d }, Secondary::Raytraced)
            }
            Technique::Gtao(o) => Some(o.graph(frame)),
            Technique::Raymarch(o) => Some(o.graph(frame)),
            Technique::GroundTruth { spp, uniform } => Some(GroundTruthSettings { spp, uniform }.graph(frame)),
            Technique::Hybrid(o) => Some(o.graph(frame)),
        }
    }

    /// World-space rays a frame traces, where the count follows from the settings (ground
    /// truth, hybrid); the stenciled family counts its rays from its buffers.
    pub fn rays(&self, frame: &FrameDesc) -> Option<u64> {
        match *self {
            Technique::GroundTruth { spp, uniform } => Some(GroundTruthSettings { spp, uniform }.rays(frame)),
            Technique::Hybrid(o) => Some(o.rays(frame)),
            _ => None,
        }
    }

    /// The separation of the depth-peeled second layer, for techniques that read one (spec
    /// svao-raysd §11).
    pub fn second_layer(&self) -> Option<f32> {
        match *self {
            Technique::VaoDual { peel_separation } => Some(peel_separation),
            Technique::Hbao { dual: true, peel_separation }
            | Technique::RaySvao { dual: true, peel_separation, .. } => Some(peel_separation),
            Technique::RaySd(o) if o.dual => Some(o.peel_separation),
            _ => None,
        }
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
            Technique::RaySd(o) => describe_sd(o),
            Technique::RaySvao { cutoff, dual, peel_separation } => serde_json::json!({
                "cutoff": cutoff, "primary": if *dual { "dual" } else { "single" }, "peel_separation": peel_separation,
            }),
            Technique::GroundTruth { spp, uniform } => serde_json::json!({ "spp": spp, "uniform": uniform }),
            Technique::Gtao(o) => describe_gtao(o),
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
#[derive(Copy, Clone, Debug)]
pub struct TechniqueDefaults {
    pub sd: SdOptions,
    pub gtao: GtaoOptions,
    pub raymarch: RaymarchOptions,
    pub hybrid: HybridOptions,
    pub spp: u32,
    pub uniform: bool,
}

impl Default for TechniqueDefaults {
    /// Every technique's own defaults.
    fn default() -> Self {
        let gt = GroundTruthSettings::default();
        TechniqueDefaults {
            sd: Default::default(),
            gtao: Default::default(),
            raymarch: Default::default(),
            hybrid: Default::default(),
            spp: gt.spp,
            uniform: gt.uniform,
        }
    }
}

impl Frame {
    /// XeGTAO parameters with this frame's radius as the effect radius.
    pub fn gtao_params(&self, o: &GtaoOptions) -> GtaoParams {
        o.params(&self.desc())
    }

    /// XeGTAO parameters for running only its denoiser (`passes` passes) after another technique.
    pub fn denoise_params(&self, passes: u32) -> GtaoParams {
        self.gtao_params(&GtaoOptions { denoise_passes: passes, ..Default::default() })
    }

    /// Ground-truth parameters with this frame's radius and exponent.
    pub fn ground_truth_params(&self, spp: u32, uniform: bool) -> GroundTruthParams {
        GroundTruthSettings { spp, uniform }.frame(&self.desc()).params
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
    /// Vulkan graph techniques: wall time of the technique's one command buffer from submit to
    /// fence, ms (compare with the sum of its pass timestamps: host round trips show as the gap).
    pub frame_ms: Option<f64>,
}

impl TechniqueRun {
    /// A run without rays, refinement or diagnostics.
    pub fn plain(ao: Vec<f32>, ao_final: Vec<f32>, passes: Vec<(&'static str, f64)>) -> TechniqueRun {
        TechniqueRun {
            ao,
            ao_final,
            passes,
            rays: 0,
            refined_samples: 0,
            interval_sum: None,
            debug: None,
            frame_ms: None,
        }
    }

    pub fn total_ms(&self) -> f64 {
        self.passes.iter().map(|(_, ms)| ms).sum()
    }
}
