//! Settings and pass graph of the Poisson-disk ray-marched SSAO (host side; spec
//! gtao-raymarch-hybrid §3): the march, then optionally XeGTAO's denoiser.

use super::{Contribution, MAX_DIRECTIONS, RaymarchParams};
use crate::graph::{Extent, FrameDesc, Graph, Pass, inputs, record, target_f32, target_u32};
use crate::gtao::settings::with_denoiser;
use crate::technique::{Constant, Declaration, Formula, Setting, Settings, Table, single_layer};

/// Relative depth bias κ (spec gtao-raymarch-hybrid §3.2).
pub const DEPTH_BIAS: f32 = 0.0008;

/// Options of the ray-marched SSAO (spec gtao-raymarch-hybrid §3.2 defaults in brackets).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RaymarchSettings {
    /// Directions N (8, 16 or 24 in the paper; 1–64) \[16\].
    pub directions: u32,
    /// Steps per direction \[8\].
    pub steps: u32,
    /// Contrast exponent α \[1\].
    pub alpha: f32,
    /// Eq. 2 reading: binary (c = 0 on a hit) instead of linear (c = Δ̃/R) \[linear\].
    pub binary: bool,
    /// Vogel spiral instead of the best-candidate Poisson disk \[off\].
    pub vogel: bool,
    /// XeGTAO denoise passes afterwards, 0–3 \[0\].
    pub denoise_passes: u32,
}

impl Default for RaymarchSettings {
    fn default() -> Self {
        RaymarchSettings { directions: 16, steps: 8, alpha: 1.0, binary: false, vogel: false, denoise_passes: 0 }
    }
}

impl Settings for RaymarchSettings {
    const ROWS: &'static [Setting<Self>] = &[
        Setting::<Self>::count("directions", 1, MAX_DIRECTIONS, |s| &mut s.directions)
            .flag("rm-directions")
            .help("Ray-marched SSAO: directions N (the paper uses 8, 16, 24; spec gtao-raymarch-hybrid §3.2)"),
        Setting::<Self>::count("steps", 1, 256, |s| &mut s.steps)
            .flag("rm-steps")
            .help("Ray-marched SSAO: steps per direction"),
        Setting::<Self>::number("alpha", 0.0, f32::MAX, |s| &mut s.alpha)
            .flag("rm-alpha")
            .help("Ray-marched SSAO: contrast exponent α of Eq. 2"),
        Setting::<Self>::switch("contribution", &["linear", "binary"], |s| &mut s.binary)
            .flag("rm-contribution")
            .help("Ray-marched SSAO: reading of Eq. 2 (linear: visible distance / R; binary: 0 on a hit)"),
        Setting::<Self>::switch("kernel", &["best-candidate", "vogel"], |s| &mut s.vogel)
            .only_switch("rm-vogel", "vogel")
            .help("Ray-marched SSAO: Poisson disk (spec gtao-raymarch-hybrid §3.3); --rm-vogel uses a Vogel spiral"),
        Setting::<Self>::count("denoise", 0, 3, |s| &mut s.denoise_passes)
            .flag("rm-denoise")
            .help("Ray-marched SSAO: XeGTAO denoise passes afterwards"),
    ];
}

/// The Poisson-disk ray-marched SSAO (spec gtao-raymarch-hybrid §3).
pub static RAYMARCH: Declaration<RaymarchSettings> = Declaration {
    name: "raymarch",
    summary: "Poisson-disk ray-marched SSAO, optionally denoised (spec gtao-raymarch-hybrid §3)",
    keys: &["directions", "steps", "alpha", "contribution", "kernel", "denoise"],
    defaults: RaymarchSettings::default,
    graph: |s, frame| Ok(s.graph(frame)),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[
        Formula { of: "raymarch_kernel", expr: "2 * `directions`" },
        Formula { of: "raymarch_kernel.table", expr: "pick(index(`kernel`), \"best_candidate\", \"vogel\")" },
        Formula {
            of: "raymarch_kernel.first",
            expr: "select(`kernel` == \"vogel\", div_floor(`directions` * (`directions` - 1), 2), 0)",
        },
        Formula { of: "raymarch_kernel.count", expr: "`directions`" },
    ],
    tables: &[
        Table {
            name: "best_candidate",
            elem: "Vec2",
            doc: "the best-candidate Poisson disk of MAX_DIRECTIONS points (spec gtao-raymarch-hybrid §3.3); \
                  N directions use its first N points (point i does not depend on N)",
            values: || flat(&super::kernel::best_candidate(MAX_DIRECTIONS as usize)),
        },
        Table {
            name: "vogel",
            elem: "Vec2",
            doc: "the Vogel spirals of N = 1, 2, …, MAX_DIRECTIONS points one after another (spec \
                  gtao-raymarch-hybrid §3.3): N's starts at element N·(N − 1)/2",
            values: || (1..=MAX_DIRECTIONS as usize).flat_map(|n| flat(&super::kernel::vogel(n))).collect(),
        },
    ],
};

/// How [`RaymarchSettings::params`] fills `RaymarchParams`, then the denoiser's `GtaoParams`
/// (`denoise` > 0) and the camera's rows. (`kernel` picks the Poisson-disk table
/// `raymarch_kernel`, a resource, not a constant.)
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("RaymarchParams.view", "the frame's ViewParams (ViewParams rows)").expr("ViewParams"),
        Constant::new(
            "RaymarchParams.radius",
            "R: the frame's world-space AO radius, the march distance (world units)"
        )
        .expr("radius"),
        Constant::new("RaymarchParams.alpha", "`alpha`: contrast exponent α of Eq. 2 [1]").expr("`alpha`"),
        Constant::new("RaymarchParams.depth_bias", "0.0008: relative depth bias κ").expr("0.0008"),
        Constant::new(
            "RaymarchParams.thickness",
            "f32::MAX = 3.4028235e38: depth-buffer surfaces are a pure height field"
        )
        .expr("3.4028235e38"),
        Constant::new("RaymarchParams.directions", "`directions`: N [16]").expr("`directions`"),
        Constant::new("RaymarchParams.steps", "`steps`: S per direction [8]").expr("`steps`"),
        Constant::new("RaymarchParams.contribution", "Contribution of `contribution`: linear 0, binary 1 [linear 0]")
            .expr("index(`contribution`)"),
        Constant::new(
            "RaymarchParams.noise_frame",
            "the frame index (FrameDesc::frame_index; 0 for one frame), mod 64 in the noise (gtao-raymarch-hybrid §1.6)"
        )
        .expr("frame"),
    ],
    crate::gtao::settings::DENOISER,
    crate::common::camera::CONSTANTS,
];

impl RaymarchSettings {
    /// Push constants with the frame's radius.
    pub fn params(&self, frame: &FrameDesc) -> RaymarchParams {
        RaymarchParams {
            view: frame.camera.view,
            radius: frame.radius,
            alpha: self.alpha,
            depth_bias: DEPTH_BIAS,
            thickness: f32::MAX,
            directions: self.directions,
            steps: self.steps,
            contribution: if self.binary { Contribution::Binary } else { Contribution::Linear } as u32,
            // The frame's index in its sequence: the Hilbert-R2 noise's temporal offset (gtao-raymarch-hybrid §1.6).
            noise_frame: frame.frame_index,
        }
    }

    /// The Poisson-disk kernel (spec gtao-raymarch-hybrid §3.3).
    pub fn kernel(&self) -> Vec<crate::glam::Vec2> {
        let n = self.directions as usize;
        if self.vogel { super::kernel::vogel(n) } else { super::kernel::best_candidate(n) }
    }

    /// March → \[denoise\].
    pub fn graph(&self, frame: &FrameDesc) -> Graph {
        let resources = vec![
            record("raymarch_kernel", &self.kernel(), "Poisson-disk directions (spec gtao-raymarch-hybrid §3.3)"),
            target_f32("ao", 1.0, "ray-marched accessibility (Eq. 2), 1 = unoccluded"),
            target_u32("ao_terms", 0, "the AO as the denoiser's 0–255 terms"),
            target_u32("ao_edges", 0, "packed depth edges for the denoiser"),
        ];
        let bindings = super::raymarch_main::Bindings {
            depth: inputs::LINEAR_DEPTH,
            normals: inputs::VIEW_NORMALS,
            kernel: "raymarch_kernel",
            ao: "ao",
            terms: "ao_terms",
            edges: "ao_edges",
        };
        let params = self.params(frame);
        let passes = vec![Pass::compute("raymarch", bindings, Extent::Full, bytemuck::bytes_of(&params))];
        with_denoiser(frame, resources, passes, self.denoise_passes)
    }
}

/// The components of `points`, in order.
fn flat(points: &[crate::glam::Vec2]) -> Vec<f32> {
    points.iter().flat_map(|p| [p.x, p.y]).collect()
}
