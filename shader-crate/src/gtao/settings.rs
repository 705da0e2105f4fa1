//! XeGTAO's settings, quality presets and pass graph (host side; spec gtao-raymarch-hybrid §2):
//! PrefilterDepths in two passes, optional normals from depth, MainPass, the denoise passes.
//! The denoiser's passes are shared with the techniques that reuse it (ray march, hybrid).

use super::{GtaoParams, MIP_LEVELS};
use crate::graph::{
    Diagnostics, Elem, Extent, FrameDesc, Graph, Init, Lifetime, Pass, Resource, Size, Snapshot, inputs, target_f32,
    target_u32,
};
use crate::technique::{Constant, Declaration, Setting, Settings, single_layer};

/// XeGTAO quality presets (spec gtao-raymarch-hybrid §2.2): slices × steps per side; any other
/// pair is a custom quality.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Quality {
    Low,
    Medium,
    High,
    Ultra,
}

impl Quality {
    pub const ALL: [Quality; 4] = [Quality::Low, Quality::Medium, Quality::High, Quality::Ultra];

    /// `(slices, steps per side)`.
    pub fn slices_steps(self) -> (u32, u32) {
        match self {
            Quality::Low => (1, 2),
            Quality::Medium => (2, 2),
            Quality::High => (3, 3),
            Quality::Ultra => (9, 3),
        }
    }

    /// The preset with these slices and steps, if one has them.
    pub fn of(slices: u32, steps: u32) -> Option<Quality> {
        Quality::ALL.into_iter().find(|q| q.slices_steps() == (slices, steps))
    }
}

/// Upper bounds of a custom quality (the spec's reference settings use 32 × 24, spec gtao-raymarch-hybrid §2.2; VBAO's
/// "dense" sampling is K ≥ 64 steps, spec vbao §6).
pub const MAX_SLICES: u32 = 64;
pub const MAX_STEPS: u32 = 64;

/// XeGTAO settings (spec gtao-raymarch-hybrid §2.1 defaults and UI ranges; the effect radius is the frame's AO
/// radius).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct GtaoSettings {
    /// Slices per pixel [3, High]; see [`Quality`] for the presets.
    pub slices: u32,
    /// Steps per slice side [3, High].
    pub steps: u32,
    /// Denoise passes 0 (off) … 3 (soft) \[1\].
    pub denoise_passes: u32,
    /// [1.457], range 0.3–3.
    pub radius_multiplier: f32,
    /// [0.615], range 0–1.
    pub falloff_range: f32,
    /// \[2\], range 1–3.
    pub sample_distribution_power: f32,
    /// \[0\], range 0–0.7.
    pub thin_occluder_compensation: f32,
    /// [2.2], range 0.5–5.
    pub final_value_power: f32,
    /// [3.3], range 0–30.
    pub depth_mip_sampling_offset: f32,
    /// Derive normals from depth (pass 0) instead of reading the G-buffer's \[off\].
    pub normals_from_depth: bool,
    /// Also output the bent normal, resource `bent_normals` (spec gtao-raymarch-hybrid §2.6.5, ≈ 25 % cost) \[off\].
    pub bent_normals: bool,
}

impl Default for GtaoSettings {
    fn default() -> Self {
        GtaoSettings {
            slices: 3,
            steps: 3,
            denoise_passes: 1,
            radius_multiplier: 1.457,
            falloff_range: 0.615,
            sample_distribution_power: 2.0,
            thin_occluder_compensation: 0.0,
            final_value_power: 2.2,
            depth_mip_sampling_offset: 3.30,
            normals_from_depth: false,
            bent_normals: false,
        }
    }
}

/// A settings struct built on XeGTAO's slice/step structure and passes (XeGTAO itself, VBAO):
/// the rows they share are written once, in [`rows`], generic over it.
pub trait XeGtaoBased: Sized + 'static {
    fn xegtao(&mut self) -> &mut GtaoSettings;
    fn xegtao_ref(&self) -> &GtaoSettings;
}

impl XeGtaoBased for GtaoSettings {
    fn xegtao(&mut self) -> &mut GtaoSettings {
        self
    }
    fn xegtao_ref(&self) -> &GtaoSettings {
        self
    }
}

/// The rows of XeGTAO's settings (spec gtao-raymarch-hybrid §2.1, its UI ranges) for any
/// [`XeGtaoBased`] settings struct; `flag` is the command-line flag, which differs per technique.
pub mod rows {
    use super::{MAX_SLICES, MAX_STEPS, Quality, XeGtaoBased};
    use crate::technique::Setting;

    fn preset_index<S: XeGtaoBased>(s: &S) -> usize {
        let x = s.xegtao_ref();
        Quality::of(x.slices, x.steps).map_or(4, |q| q as usize)
    }

    fn set_preset<S: XeGtaoBased>(s: &mut S, i: usize) {
        // `custom` keeps the slices and steps set (by the slices/steps flags).
        if let Some(q) = Quality::ALL.get(i) {
            let x = s.xegtao();
            (x.slices, x.steps) = q.slices_steps();
        }
    }

    macro_rules! field {
        ($name:ident, $ty:ty, $field:ident) => {
            fn $name<S: XeGtaoBased>(s: &mut S) -> &mut $ty {
                &mut s.xegtao().$field
            }
        };
    }
    field!(slices_of, u32, slices);
    field!(steps_of, u32, steps);
    field!(denoise_of, u32, denoise_passes);
    field!(radius_multiplier_of, f32, radius_multiplier);
    field!(falloff_of, f32, falloff_range);
    field!(sample_power_of, f32, sample_distribution_power);
    field!(thin_of, f32, thin_occluder_compensation);
    field!(final_power_of, f32, final_value_power);
    field!(mip_offset_of, f32, depth_mip_sampling_offset);
    field!(normals_of, bool, normals_from_depth);
    field!(bent_normals_of, bool, bent_normals);

    pub const fn preset<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::choice(
            "preset",
            &["low", "medium", "high", "ultra", "custom"],
            preset_index::<S>,
            set_preset::<S>,
        )
        .flag(flag)
        .help("XeGTAO quality preset: slices × steps per side 1×2, 2×2, 3×3, 9×3 or custom (gtao-raymarch-hybrid §2.2)")
    }
    pub const fn slices<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::count("slices", 1, MAX_SLICES, slices_of::<S>)
            .flag(flag)
            .help("XeGTAO slices per pixel (set after the preset: a pair no preset has is custom)")
    }
    pub const fn steps<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::count("steps", 1, MAX_STEPS, steps_of::<S>)
            .flag(flag)
            .help("XeGTAO steps per slice side (set after the preset)")
    }
    pub const fn denoise<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::count("denoise", 0, 3, denoise_of::<S>)
            .flag(flag)
            .help("XeGTAO denoise passes (0 off, 1 sharp, 2 medium, 3 soft; spec gtao-raymarch-hybrid §2.7)")
    }
    pub const fn radius_multiplier<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::number("radius-multiplier", 0.3, 3.0, radius_multiplier_of::<S>)
            .flag(flag)
            .help("XeGTAO RadiusMultiplier (effective radius = --radius × this)")
    }
    pub const fn falloff_range<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::number("falloff-range", 0.0, 1.0, falloff_of::<S>)
            .flag(flag)
            .help("XeGTAO FalloffRange (fraction of the radius over which samples fade)")
    }
    pub const fn sample_power<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::number("sample-power", 1.0, 3.0, sample_power_of::<S>)
            .flag(flag)
            .help("XeGTAO SampleDistributionPower")
    }
    pub const fn thin_occluder<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::number("thin-occluder", 0.0, 0.7, thin_of::<S>).flag(flag).help("XeGTAO ThinOccluderCompensation")
    }
    pub const fn final_power<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::number("final-power", 0.5, 5.0, final_power_of::<S>).flag(flag).help("XeGTAO FinalValuePower")
    }
    pub const fn mip_offset<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::number("mip-offset", 0.0, 30.0, mip_offset_of::<S>)
            .flag(flag)
            .help("XeGTAO DepthMIPSamplingOffset")
    }
    pub const fn bent_normals<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::switch("bent-normals", &["off", "on"], bent_normals_of::<S>)
            .flag(flag)
            .help("XeGTAO: also output the bent normal, RGBA8 beside the AO (gtao-raymarch-hybrid §2.6.5, ≈25 % cost)")
    }
    pub const fn normals<S: XeGtaoBased>(flag: &'static str) -> Setting<S> {
        Setting::<S>::switch("normals", &["gbuffer", "depth"], normals_of::<S>)
            .flag(flag)
            .help("XeGTAO normals: the G-buffer's, or derived from depth (pass 0, spec gtao-raymarch-hybrid §2.4)")
    }
}

impl Settings for GtaoSettings {
    /// XeGTAO's UI ranges (spec gtao-raymarch-hybrid §2.1).
    const ROWS: &'static [Setting<Self>] = &[
        rows::preset::<Self>("preset"),
        rows::slices::<Self>("gtao-slices"),
        rows::steps::<Self>("gtao-steps"),
        rows::denoise::<Self>("gtao-denoise"),
        rows::radius_multiplier::<Self>("gtao-radius-multiplier"),
        rows::falloff_range::<Self>("gtao-falloff-range"),
        rows::sample_power::<Self>("gtao-sample-power"),
        rows::thin_occluder::<Self>("gtao-thin-occluder"),
        rows::final_power::<Self>("gtao-final-power"),
        rows::mip_offset::<Self>("gtao-mip-offset"),
        rows::normals::<Self>("gtao-normals"),
        rows::bent_normals::<Self>("gtao-bent-normals"),
    ];
}

/// XeGTAO (spec gtao-raymarch-hybrid §2).
pub static GTAO: Declaration<GtaoSettings> = Declaration {
    name: "gtao",
    summary: "XeGTAO: depth MIPs, horizon search over slices, denoiser (spec gtao-raymarch-hybrid §2)",
    keys: &[
        "preset",
        "slices",
        "steps",
        "denoise",
        "radius-multiplier",
        "falloff-range",
        "sample-power",
        "thin-occluder",
        "final-power",
        "mip-offset",
        "normals",
        "bent-normals",
    ],
    defaults: GtaoSettings::default,
    graph: |s, frame| Ok(s.graph(frame)),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[],
    tables: &[],
};

/// How [`GtaoSettings::params`] and [`GtaoSettings::graph`] fill `GtaoParams` (XeGTAO's
/// `GTAOUpdateConstants`), then the camera's rows.
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("GtaoParams.falloff_range", "`falloff-range` [0.615]").expr("`falloff-range`"),
        Constant::new("GtaoParams.thin_occluder_compensation", "`thin-occluder` [0]").expr("`thin-occluder`"),
        Constant::new("GtaoParams.final_value_power", "`final-power` [2.2]").expr("`final-power`"),
        Constant::new(
            "GtaoParams.pass",
            "per pass: gtao_prefilter: 0 for MIPs 0–1 (one invocation per 2×2 texels), then 1 for MIPs \
             2–4 (one per 16×16); gtao_normals and gtao_main: 0; gtao_denoise: the pass index i = 0 … max(1, `denoise`) − 1",
        )
        .expr("pass"),
        Constant::new("GtaoParams.bent_normals", "`bent-normals`: off 0, on 1 [0]").expr("index(`bent-normals`)"),
    ],
    XEGTAO_STRUCTURE,
    crate::common::camera::CONSTANTS,
];

/// The `GtaoParams` rows every technique built on XeGTAO's passes shares (XeGTAO, VBAO): the
/// view, the radius, the slice/step structure, the sampling and the noise.
pub const XEGTAO_STRUCTURE: &[Constant] = &[
    Constant::new("GtaoParams.view", "the frame's ViewParams (ViewParams rows)").expr("ViewParams"),
    Constant::new("GtaoParams.radius", "R: the frame's world-space AO radius (world units), XeGTAO's EffectRadius")
        .expr("radius"),
    Constant::new("GtaoParams.radius_multiplier", "`radius-multiplier` [1.457]").expr("`radius-multiplier`"),
    Constant::new("GtaoParams.sample_distribution_power", "`sample-power` [2]").expr("`sample-power`"),
    Constant::new("GtaoParams.depth_mip_sampling_offset", "`mip-offset` [3.3]").expr("`mip-offset`"),
    Constant::new(
        "GtaoParams.slices",
        "`slices`, which `preset` sets first: low 1, medium 2, high 3, ultra 9 (custom keeps it) [3]",
    )
    .expr("`slices`"),
    Constant::new(
        "GtaoParams.steps",
        "`steps`, which `preset` sets first: low 2, medium 2, high 3, ultra 3 (custom keeps it) [3]",
    )
    .expr("`steps`"),
    Constant::new("GtaoParams.denoise_passes", "`denoise` (0 still runs one denoise pass) [1]").expr("`denoise`"),
    Constant::new(
        "GtaoParams.noise_frame",
        "the frame index (FrameDesc::frame_index; 0 for a single frame): XeGTAO's NoiseIndex, taken mod 64 by \
         the noise (spec gtao-raymarch-hybrid §1.6)",
    )
    .expr("frame"),
    Constant::new("GtaoParams._pad", "0").expr("0"),
];

/// How [`with_denoiser`] fills `GtaoParams` for the techniques that reuse XeGTAO's denoiser
/// (the ray march, the hybrid: their `denoise` key): XeGTAO's defaults but the pass count.
pub const DENOISER: &[Constant] = &[
    Constant::new("GtaoParams.view", "the frame's ViewParams (ViewParams rows)").expr("ViewParams"),
    Constant::new("GtaoParams.radius", "R: the frame's world-space AO radius (world units; unread by the denoiser)")
        .expr("radius"),
    Constant::new("GtaoParams.radius_multiplier", "1.457 (XeGTAO's default; unread by the denoiser)").expr("1.457"),
    Constant::new("GtaoParams.falloff_range", "0.615 (XeGTAO's default; unread by the denoiser)").expr("0.615"),
    Constant::new("GtaoParams.sample_distribution_power", "2 (XeGTAO's default; unread by the denoiser)").expr("2.0"),
    Constant::new("GtaoParams.thin_occluder_compensation", "0 (XeGTAO's default; unread by the denoiser)").expr("0.0"),
    Constant::new("GtaoParams.final_value_power", "2.2 (XeGTAO's default; unread by the denoiser)").expr("2.2"),
    Constant::new("GtaoParams.depth_mip_sampling_offset", "3.3 (XeGTAO's default; unread by the denoiser)").expr("3.3"),
    Constant::new("GtaoParams.slices", "3 (XeGTAO's default; unread by the denoiser)").expr("3"),
    Constant::new("GtaoParams.steps", "3 (XeGTAO's default; unread by the denoiser)").expr("3"),
    Constant::new(
        "GtaoParams.denoise_passes",
        "`denoise`: the denoise passes, 1–3 (0: no denoiser, the technique's AO is final)",
    )
    .expr("`denoise`"),
    Constant::new("GtaoParams.noise_frame", "the frame index (FrameDesc::frame_index; unread by the denoiser)")
        .expr("frame"),
    Constant::new("GtaoParams.pass", "per pass: the denoise pass index i = 0 … `denoise` − 1").expr("pass"),
    Constant::new("GtaoParams.bent_normals", "0 (no bent normals)").expr("0"),
    Constant::new("GtaoParams._pad", "0").expr("0"),
];

impl GtaoSettings {
    /// The kernels' constants (XeGTAO's `GTAOUpdateConstants`) for a frame.
    pub fn params(&self, frame: &FrameDesc) -> GtaoParams {
        let (slices, steps) = (self.slices, self.steps);
        GtaoParams {
            view: frame.camera.view,
            radius: frame.radius,
            radius_multiplier: self.radius_multiplier,
            falloff_range: self.falloff_range,
            sample_distribution_power: self.sample_distribution_power,
            thin_occluder_compensation: self.thin_occluder_compensation,
            final_value_power: self.final_value_power,
            depth_mip_sampling_offset: self.depth_mip_sampling_offset,
            slices,
            steps,
            denoise_passes: self.denoise_passes,
            // XeGTAO's NoiseIndex (spec gtao-raymarch-hybrid §1.6): the frame's index in its sequence.
            noise_frame: frame.frame_index,
            pass: 0,
            bent_normals: self.bent_normals as u32,
            _pad: 0,
        }
    }

    /// Prefilter (5 MIP levels) → [normals from depth] → main pass → denoise.
    pub fn graph(&self, frame: &FrameDesc) -> Graph {
        let params = self.params(frame);
        let main = |r: MainPassResources| {
            let bindings =
                super::gtao_main::Bindings { mips: r.mips, normals: r.normals, terms: r.terms, edges: r.edges };
            (Vec::new(), vec![Pass::compute("gtao_main", bindings, Extent::Full, bytemuck::bytes_of(&params))])
        };
        xegtao_graph(frame, &params, self.normals_from_depth, main)
    }
}

/// The resources of XeGTAO's main pass: it reads the MIP chain and the normals, writes the AO
/// terms and the edges.
pub struct MainPassResources {
    pub mips: &'static str,
    pub normals: &'static str,
    pub terms: &'static str,
    pub edges: &'static str,
}

/// The packed working-depth MIP chain, the main pass's AO terms and its edges.
const MIPS: &str = "gtao_mips";
const TERMS: &str = "gtao_terms";
const EDGES: &str = "gtao_edges";

/// XeGTAO's passes around a main pass (spec gtao-raymarch-hybrid §2.3–§2.7): PrefilterDepths
/// in two passes (MIPs 0–1, MIPs 2–4) → [normals from depth] → `main` (the main pass over [`MainPassResources`]) →
/// the denoiser. XeGTAO's own main pass and VBAO's bitmask main pass (spec vbao §1) plug in
/// here; `main` gives the passes that fill the terms and edges and any resources of their own
/// (vbao-sd's request pass, SD map and main pass, spec vbao §8).
pub fn xegtao_graph(
    frame: &FrameDesc,
    params: &GtaoParams,
    normals_from_depth: bool,
    main: impl FnOnce(MainPassResources) -> (Vec<Resource>, Vec<Pass>),
) -> Graph {
    let params = *params;
    let mips = Resource {
        name: MIPS,
        elem: Elem::F32,
        size: Size::MipChain { first: 0, levels: MIP_LEVELS },
        init: Init::Undefined,
        lifetime: Lifetime::PerFrame,
        doc: "packed 5-level working-depth MIP chain (spec gtao-raymarch-hybrid §2.3)",
    };
    let mut resources = vec![
        mips,
        target_u32(TERMS, 0, "MainPass AO terms, 0–255 (spec gtao-raymarch-hybrid §2.6)"),
        target_u32(EDGES, 0, "packed depth edges, the denoiser's input (gtao-raymarch-hybrid §2.6.1, §2.7)"),
    ];
    let mut passes = Vec::new();
    for (pass, divisor) in (0..).zip(super::PREFILTER_BLOCK) {
        let p = GtaoParams { pass, ..params };
        let bindings = super::gtao_prefilter::Bindings { depth: inputs::LINEAR_DEPTH, mips: MIPS };
        let blocks = Extent::Reduced { divisor, border: 0 };
        passes.push(Pass::compute("gtao_prefilter", bindings, blocks, bytemuck::bytes_of(&p)));
    }
    let bytes = bytemuck::bytes_of(&params);
    let normals = if normals_from_depth {
        resources.push(target_u32("gtao_normals", 0, "view normals derived from depth (gtao-raymarch-hybrid §2.4)"));
        let bindings = super::gtao_normals::Bindings { depth: inputs::LINEAR_DEPTH, normals: "gtao_normals" };
        passes.push(Pass::compute("gtao_normals", bindings, Extent::Full, bytes));
        "gtao_normals"
    } else {
        inputs::VIEW_NORMALS
    };
    let (r, p) = main(MainPassResources { mips: MIPS, normals, terms: TERMS, edges: EDGES });
    resources.extend(r);
    passes.extend(p);
    let (r, p) = denoise_passes(&params, TERMS, EDGES, "ao_final", "gtao_denoise");
    resources.extend(r);
    passes.extend(p);
    let mut snapshots = Vec::new();
    if params.bent_normals != 0 {
        // The last denoise pass leaves the packed bent normals in its output terms.
        let last = passes.len() - 1;
        resources.push(target_u32(BENT_NORMALS, 0, BENT_NORMALS_DOC));
        snapshots.push(Snapshot { after: last, from: passes[last].bindings[2].resource, to: BENT_NORMALS });
    }
    let bent_normals = (params.bent_normals != 0).then_some(BENT_NORMALS);
    let diagnostics = Diagnostics { bent_normals, ..Default::default() };
    Graph {
        resources,
        passes,
        output: "ao_final",
        raw_output: "ao_final",
        snapshots,
        view: frame.camera.view,
        diagnostics,
    }
}

/// The optional bent-normal output of XeGTAO (`bent-normals on`).
pub const BENT_NORMALS: &str = "bent_normals";
const BENT_NORMALS_DOC: &str = "bent normals, RGBA8 in a u32: rgb = the unit bent normal in the G-buffer's \
     right-handed view space ·0.5 + 0.5, a = the visibility ·255 (spec gtao-raymarch-hybrid §2.6.5)";

/// XeGTAO's denoiser (spec gtao-raymarch-hybrid §2.7) over `terms` with `edges`: max(1,
/// `params.denoise_passes`) passes ping-ponging between two scratch images (`terms` stays
/// intact); the last pass writes the visibility into `output`.
pub fn denoise_passes(
    params: &GtaoParams,
    terms: &'static str,
    edges: &'static str,
    output: &'static str,
    label: &'static str,
) -> (Vec<Resource>, Vec<Pass>) {
    const PING: &str = "denoise_ping";
    const PONG: &str = "denoise_pong";
    let resources = vec![
        target_u32(PING, 0, "denoised AO terms (ping)"),
        target_u32(PONG, 0, "denoised AO terms (pong)"),
        target_f32(output, 1.0, "visibility after the last denoise pass (1 = unoccluded)"),
    ];
    let mut passes = Vec::new();
    let (mut from, mut to) = (terms, PING);
    for pass in 0..params.denoise_passes.max(1) {
        let p = GtaoParams { pass, ..*params };
        let bindings = super::gtao_denoise::Bindings { terms_in: from, edges, terms_out: to, ao: output };
        passes.push(Pass::compute(label, bindings, Extent::Pairs, bytemuck::bytes_of(&p)));
        (from, to) = (to, if to == PING { PONG } else { PING });
    }
    (resources, passes)
}

/// The graph of a technique that writes visibility `"ao"` plus denoiser terms `"ao_terms"` and
/// edges `"ao_edges"` (the ray march, the hybrid): its `resources` and `passes`, then XeGTAO's
/// denoiser with `denoise` passes into `"ao_final"` when `denoise > 0` (spec
/// gtao-raymarch-hybrid §3.4, §4.2: both reuse gtao-raymarch-hybrid §2.7).
pub fn with_denoiser(frame: &FrameDesc, mut resources: Vec<Resource>, mut passes: Vec<Pass>, denoise: u32) -> Graph {
    let view = frame.camera.view;
    if denoise == 0 {
        let diagnostics = Diagnostics::default();
        return Graph { resources, passes, output: "ao", raw_output: "ao", snapshots: Vec::new(), view, diagnostics };
    }
    let params = GtaoSettings { denoise_passes: denoise, ..Default::default() }.params(frame);
    let (r, p) = denoise_passes(&params, "ao_terms", "ao_edges", "ao_final", "denoise");
    resources.extend(r);
    passes.extend(p);
    let diagnostics = Diagnostics::default();
    Graph { resources, passes, output: "ao_final", raw_output: "ao", snapshots: Vec::new(), view, diagnostics }
}
