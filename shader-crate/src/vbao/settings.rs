//! VBAO's settings and pass graph (host side; spec vbao): XeGTAO's slice/step settings and
//! passes (`crate::gtao::settings`), the bitmask's thickness, gate, sector rule and weighting.

use super::{RULE_PAPER, RULE_TOUCH, VbaoParams, WEIGHT_COSINE_BLENDER, WEIGHT_COSINE_EXACT, WEIGHT_UNIFORM};
use crate::graph::{Extent, FrameDesc, Graph, Pass};
use crate::gtao::settings::{GtaoSettings, MainPassResources, XeGtaoBased, rows, xegtao_graph};
use crate::svao::Secondary;
use crate::svao::settings::{SdMapBased, SvaoSettings, sd_rows};
use crate::technique::{Constant, Declaration, Setting, Settings, single_layer};

/// Where samples stop counting (spec vbao §2.1).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Gate {
    /// Every sample counts (Bevy, SSRT3, Filament).
    Off,
    /// R_g = R, the effective radius `Radius·RadiusMultiplier` [aokit's default].
    Effective,
    /// R_g = Radius, the ground truth's ray length (for comparisons against it).
    Radius,
}

/// VBAO settings (spec vbao §5 "Ours": XeGTAO presets and R, N = 32, T as Bevy's, `Paper`
/// rule, `Uniform` weighting, gate on; FinalValuePower 1, spec vbao §4).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct VbaoSettings {
    /// XeGTAO's slice/step structure, radius multiplier, sample distribution, MIP offset,
    /// final power, denoiser and normals (falloff and thin-occluder compensation are unread).
    pub xegtao: GtaoSettings,
    /// Thickness T as a fraction of the frame's AO radius [0.5]. Bevy's T = 0.25 at its radius
    /// 0.5 (spec vbao §5); aokit scales it with the radius so scenes of any unit behave alike.
    pub thickness: f32,
    pub gate: Gate,
    /// Count every touched sector (`touch`) instead of the paper's ⌈N·(hi − lo)⌉ (spec vbao §3).
    pub touch: bool,
    /// `WEIGHT_UNIFORM`, `WEIGHT_COSINE_BLENDER` or `WEIGHT_COSINE_EXACT` (spec vbao §4).
    pub weighting: u32,
    /// The SD map `vbao-sd` traces (spec vbao §8; its `sd-res`, `sd-layers`, `max-count` and
    /// `sd-guard` rows, the rest at Ray-SD's defaults); unread by `vbao`.
    pub sd: SvaoSettings,
}

impl Default for VbaoSettings {
    fn default() -> Self {
        VbaoSettings {
            xegtao: GtaoSettings { final_value_power: 1.0, ..GtaoSettings::default() },
            thickness: 0.5,
            gate: Gate::Effective,
            touch: false,
            weighting: WEIGHT_UNIFORM,
            sd: SvaoSettings { refinement: Secondary::StochasticDepth, ..SvaoSettings::default() },
        }
    }
}

impl SdMapBased for VbaoSettings {
    fn sd(&mut self) -> &mut SvaoSettings {
        &mut self.sd
    }
    fn sd_ref(&self) -> &SvaoSettings {
        &self.sd
    }
}

impl XeGtaoBased for VbaoSettings {
    fn xegtao(&mut self) -> &mut GtaoSettings {
        &mut self.xegtao
    }
    fn xegtao_ref(&self) -> &GtaoSettings {
        &self.xegtao
    }
}

const WEIGHTINGS: [&str; 3] = ["uniform", "cosine-blender", "cosine-exact"];
const GATES: [&str; 3] = ["off", "effective", "radius"];

impl Settings for VbaoSettings {
    const ROWS: &'static [Setting<Self>] = &[
        rows::preset::<Self>("vbao-preset"),
        rows::slices::<Self>("vbao-slices"),
        rows::steps::<Self>("vbao-steps"),
        rows::denoise::<Self>("vbao-denoise"),
        rows::radius_multiplier::<Self>("vbao-radius-multiplier"),
        rows::sample_power::<Self>("vbao-sample-power"),
        rows::final_power::<Self>("vbao-final-power"),
        rows::mip_offset::<Self>("vbao-mip-offset"),
        rows::normals::<Self>("vbao-normals"),
        Setting::<Self>::number("thickness", 0.0, 100.0, |s| &mut s.thickness)
            .flag("vbao-thickness")
            .help("VBAO sample thickness T as a multiple of the AO radius (spec vbao §2.2)"),
        Setting::<Self>::choice("gate", &GATES, |s| s.gate as usize, |s, i| {
            s.gate = [Gate::Off, Gate::Effective, Gate::Radius][i];
        })
        .flag("vbao-gate")
        .help("VBAO: skip samples beyond the effective radius, beyond --radius, or none (spec vbao §2.1)"),
        Setting::<Self>::switch("sectors", &["paper", "touch"], |s| &mut s.touch)
            .flag("vbao-sectors")
            .help("VBAO sector rule: the paper's ⌈N·(hi−lo)⌉ from ⌊N·lo⌋, or every touched sector (spec vbao §3)"),
        Setting::<Self>::choice("weighting", &WEIGHTINGS, |s| s.weighting as usize, |s, i| s.weighting = i as u32)
            .flag("vbao-weighting")
            .help("VBAO visibility of a mask: uniform in slice angle, Blender's cosine groups, or exact cosine (spec vbao §4)"),
        sd_rows::sd_res::<Self>("vbao-sd-res"),
        sd_rows::sd_layers::<Self>("vbao-sd-layers"),
        sd_rows::max_count::<Self>("vbao-max-count"),
        sd_rows::sd_guard::<Self>("vbao-sd-guard"),
    ];

    fn check(&self) -> Result<(), String> {
        self.sd.check()
    }
}

/// The setting keys `vbao` reads, followed by `$extra` (`vbao-sd` adds its SD map's): one list
/// for both declarations.
macro_rules! vbao_keys {
    ($($extra:literal),* $(,)?) => {
        &[
            "preset",
            "slices",
            "steps",
            "denoise",
            "radius-multiplier",
            "sample-power",
            "final-power",
            "mip-offset",
            "normals",
            "thickness",
            "gate",
            "sectors",
            "weighting",
            $($extra),*
        ]
    };
}
pub(crate) use vbao_keys;

/// VBAO (spec vbao).
pub static VBAO: Declaration<VbaoSettings> = Declaration {
    name: "vbao",
    summary: "Visibility-bitmask AO: XeGTAO's slices with a 32-sector mask and sample thickness (spec vbao)",
    keys: vbao_keys!(),
    defaults: VbaoSettings::default,
    graph: |s, frame| Ok(s.graph(frame)),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[],
    tables: &[],
};

/// How [`VbaoSettings::params`] fills `VbaoParams` and the `GtaoParams` of its passes, then
/// the camera's rows.
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("VbaoParams.gtao", "the GtaoParams below (GtaoParams rows)").expr("GtaoParams"),
        Constant::new("VbaoParams.thickness", "T = `thickness` · R, R the frame's AO radius (world units) [0.5·R]")
            .expr("`thickness` * radius"),
        Constant::new(
            "VbaoParams.gate_radius",
            "R_g by `gate`: off 0 (no gate), effective R·`radius-multiplier`, radius R, R the frame's AO radius \
             (world units) [R·1.457]",
        )
        .expr("pick(index(`gate`), 0.0, radius * `radius-multiplier`, radius)"),
        Constant::new("VbaoParams.weighting", "`weighting`: uniform 0, cosine-blender 1, cosine-exact 2 [0]")
            .expr("index(`weighting`)"),
        Constant::new("VbaoParams.sector_rule", "`sectors`: paper 0, touch 1 [0]").expr("index(`sectors`)"),
        Constant::new("GtaoParams.falloff_range", "0.615 (unread: VBAO has no falloff, spec vbao §2.1)").expr("0.615"),
        Constant::new("GtaoParams.thin_occluder_compensation", "0 (unread by VBAO)").expr("0.0"),
        Constant::new("GtaoParams.final_value_power", "`final-power` [1]").expr("`final-power`"),
        Constant::new(
            "GtaoParams.pass",
            "per pass: gtao_prefilter: 0 for MIPs 0–1 (one invocation per 2×2 texels), then 1 for MIPs \
             2–4 (one per 16×16); gtao_normals and vbao_main: 0; gtao_denoise: the pass index i = 0 … max(1, `denoise`) − 1",
        )
        .expr("pass"),
        Constant::new("GtaoParams.bent_normals", "0 (VBAO outputs no bent normal)").expr("0"),
    ],
    crate::gtao::settings::XEGTAO_STRUCTURE,
    crate::common::camera::CONSTANTS,
];

impl VbaoSettings {
    /// The main pass's constants for a frame (its `gtao` part also drives the prefilter,
    /// normals and denoise passes).
    pub fn params(&self, frame: &FrameDesc) -> VbaoParams {
        let gtao = self.xegtao.params(frame);
        let gate_radius = match self.gate {
            Gate::Off => 0.0,
            Gate::Effective => gtao.effective_radius(),
            Gate::Radius => frame.radius,
        };
        VbaoParams {
            thickness: self.thickness * frame.radius,
            gate_radius,
            weighting: self.weighting,
            sector_rule: if self.touch { RULE_TOUCH } else { RULE_PAPER },
            gtao,
        }
    }

    /// XeGTAO's passes with VBAO's main pass (spec vbao §1).
    pub fn graph(&self, frame: &FrameDesc) -> Graph {
        let params = self.params(frame);
        let main = |r: MainPassResources| {
            let bindings =
                super::vbao_main::Bindings { mips: r.mips, normals: r.normals, terms: r.terms, edges: r.edges };
            (Vec::new(), vec![Pass::compute("vbao_main", bindings, Extent::Full, bytemuck::bytes_of(&params))])
        };
        xegtao_graph(frame, &params.gtao, self.xegtao.normals_from_depth, main)
    }
}

const _: () = assert!(WEIGHT_UNIFORM == 0 && WEIGHT_COSINE_BLENDER == 1 && WEIGHT_COSINE_EXACT == 2);
