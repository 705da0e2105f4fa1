//! The AO techniques a user picks by name, their options, and one run of a technique on a given
//! G-buffer (the same G-buffer for every technique of a comparison).

use crate::frame::Frame;
use aokit_shaders::graph::Refinement;
use aokit_shaders::groundtruth::GroundTruthParams;
use aokit_shaders::gtao::GtaoParams;

/// XeGTAO's settings and presets (spec gtao-raymarch-hybrid §2.1–§2.2), beside its kernels.
pub use aokit_shaders::gtao::settings::{GtaoSettings as GtaoOptions, Quality as GtaoPreset};
/// The ray-marched SSAO's settings (spec gtao-raymarch-hybrid §3.2), beside its kernels.
pub use aokit_shaders::raymarch::settings::RaymarchSettings as RaymarchOptions;
/// The stenciled family's settings (spec svao-raysd §2), beside their kernels.
pub use aokit_shaders::svao::settings::{SvaoSettings as SdOptions, sd_low_res};

/// The ground truth's settings (spec gtao-raymarch-hybrid §5), beside its kernels.
pub use aokit_shaders::groundtruth::settings::GroundTruthSettings;
/// The hybrid AO's settings and variants (spec gtao-raymarch-hybrid §4.1), beside its kernels.
pub use aokit_shaders::hybrid::settings::HybridSettings as HybridOptions;
/// The registry and the declarations' types.
pub use aokit_shaders::technique::{Declaration, Row, Settings};
pub use aokit_shaders::techniques::TECHNIQUES;

pub use aokit_shaders::technique::Technique;

/// Settings given on the command line: `(flag, value)`, no value for a value-less switch. They
/// apply to every technique that has the flag, in the order of the technique's settings rows.
#[derive(Clone, Debug, Default)]
pub struct CliSettings(pub Vec<(String, Option<String>)>);

impl CliSettings {
    /// The flags that none of `techniques` reads (a flag that would silently do nothing).
    pub fn unused(&self, techniques: &[&Technique]) -> Vec<String> {
        let reads = |flag: &str| {
            flag == aokit_shaders::technique::RESOLUTION_KEY
                || techniques
                    .iter()
                    .any(|t| t.rows().iter().any(|r| r.flag == Some(flag) || r.switch.is_some_and(|s| s.0 == flag)))
        };
        self.0.iter().filter(|(f, _)| !reads(f)).map(|(f, _)| format!("--{f}")).collect()
    }

    /// The technique `spec` (`name[:key=value…]`) with these flags applied first.
    pub fn technique(&self, spec: &str) -> Result<Technique, String> {
        Technique::parse_with_flags(spec, &self.0)
    }
}

/// The reference of a comparison: `--resolution` applies to the techniques compared, not to what
/// they are scored against, so the reference runs at full resolution unless its own spec sets
/// the key (`name:…:resolution=…`).
pub fn reference_at_full_resolution(reference: Technique, spec: &str) -> Technique {
    let key = format!("{}=", aokit_shaders::technique::RESOLUTION_KEY);
    let explicit = spec.split(':').skip(1).any(|setting| setting.trim_start().starts_with(&key));
    if explicit { reference } else { reference.with_resolution(aokit_shaders::technique::Resolution::Full) }
}

/// Build each technique's graph for `frame` once, before any work: a refusal (half resolution of
/// an odd target, of a technique reading the peeled second layer, …) is one line naming the
/// technique, where the renderers would otherwise stop at it mid-run.
pub fn check_graphs<'a>(techniques: impl IntoIterator<Item = &'a Technique>, frame: &Frame) -> Result<(), String> {
    for t in techniques {
        t.graph(&frame.desc()).map_err(|e| format!("{}: {e}", t.label()))?;
    }
    Ok(())
}

/// A technique's settings as JSON for reports.
pub trait Describe {
    /// Every setting the technique reads, as JSON (`snake_case` keys).
    fn describe(&self) -> serde_json::Value;
}

impl Describe for Technique {
    fn describe(&self) -> serde_json::Value {
        serde_json::from_str(&self.json()).expect("the settings rows write valid JSON")
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
    /// The stenciled family's refinement and buffers, for the report's images (what its graph
    /// declares: `Graph::diagnostics`).
    pub debug: Option<Refinement>,
    /// Vulkan graph techniques: wall time of the technique's one command buffer from submit to
    /// fence, ms (compare with the sum of its pass timestamps: host round trips show as the gap).
    pub frame_ms: Option<f64>,
    /// XeGTAO with `bent-normals on`: per full-target pixel, RGBA8 in a u32 — rgb the unit bent
    /// normal in the G-buffer's right-handed view space ·0.5 + 0.5, a the visibility ·255
    /// (spec gtao-raymarch-hybrid §2.6.5). Empty otherwise.
    pub bent_normals: Vec<u32>,
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
            bent_normals: Vec::new(),
        }
    }

    pub fn total_ms(&self) -> f64 {
        self.passes.iter().map(|(_, ms)| ms).sum()
    }
}
