//! Settings and pass graph of the ground truth (host side; spec gtao-raymarch-hybrid §5): one
//! ray-generation pass over the inner image.

use super::{GroundTruthFrame, GroundTruthParams};
use crate::graph::{Extent, FrameDesc, Graph, Pass, RAY_COUNT, inputs, ray_counter, record, target_f32};
use crate::kernel::Kernel;
use crate::technique::{Constant, Declaration, Setting, Settings, single_layer};

/// Ground-truth settings \[defaults\].
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct GroundTruthSettings {
    /// Rays per pixel \[512\].
    pub spp: u32,
    /// Uniform hemisphere sampling weighted by cos θ instead of cosine-weighted sampling \[off\].
    pub uniform: bool,
}

impl Default for GroundTruthSettings {
    fn default() -> Self {
        GroundTruthSettings { spp: 512, uniform: false }
    }
}

/// The ground truth's ray-tracing shaders: ray generation, miss, any-hit.
pub const SHADERS: [&Kernel; 3] =
    [&super::rt::groundtruth_rgen::ENTRY, &super::rt::groundtruth_miss::ENTRY, &super::rt::groundtruth_ahit::ENTRY];

impl Settings for GroundTruthSettings {
    const ROWS: &'static [Setting<Self>] = &[
        Setting::<Self>::count("spp", 1, 65536, |s| &mut s.spp).help("Ground truth: rays per pixel"),
        Setting::<Self>::switch("sampling", &["cosine", "uniform"], |s| &mut s.uniform)
            .only_switch("uniform", "uniform")
            .help("Ground truth: cosine-weighted hemisphere sampling; --uniform samples uniformly, weighted by cos θ"),
    ];
}

/// World-space ray-traced AO (spec gtao-raymarch-hybrid §5).
pub static GROUNDTRUTH: Declaration<GroundTruthSettings> = Declaration {
    name: "groundtruth",
    summary: "world-space ray-traced AO, the reference (spec gtao-raymarch-hybrid §5)",
    keys: &["spp", "sampling"],
    defaults: GroundTruthSettings::default,
    graph: |s, frame| Ok(s.graph(frame)),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[],
    tables: &[],
};

/// How [`GroundTruthSettings::frame`] fills `GroundTruthFrame` and `GroundTruthParams`, then the
/// camera's rows.
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("GroundTruthFrame.camera", "the frame's Camera (Camera and ViewParams rows)")
        .expr("Camera"),
        Constant::new("GroundTruthFrame.params", "the technique's GroundTruthParams (GroundTruthParams rows)")
        .expr("GroundTruthParams"),
        Constant::new(
            "GroundTruthFrame.noise_frame",
            "the frame index (FrameDesc::frame_index; 0 for a single frame): the samples' rotation frame_rotation(f mod 64)",
        )
        .expr("frame"),
        Constant::new("GroundTruthFrame._pad0", "0")
        .expr("0"),
        Constant::new("GroundTruthFrame._pad1", "0")
        .expr("0"),
        Constant::new("GroundTruthFrame._pad2", "0")
        .expr("0"),
        Constant::new(
            "GroundTruthParams.radius",
            "R: the frame's world-space AO radius, the rays' length (world units)"
        )
        .expr("radius"),
        Constant::new("GroundTruthParams.exponent", "e: the frame's AO exponent (the AO is V^e)")
        .expr("exponent"),
        Constant::new("GroundTruthParams.samples", "`spp`: rays per pixel [512]")
        .expr("`spp`"),
        Constant::new("GroundTruthParams.uniform", "`sampling`: cosine 0, uniform 1 [cosine 0]")
        .expr("index(`sampling`)"),
    ],
    crate::common::camera::CONSTANTS,
];

impl GroundTruthSettings {
    /// The kernel's record: the frame's radius and exponent.
    pub fn frame(&self, frame: &FrameDesc) -> GroundTruthFrame {
        GroundTruthFrame {
            camera: frame.camera,
            params: GroundTruthParams {
                radius: frame.radius,
                exponent: frame.exponent,
                samples: self.spp,
                uniform: self.uniform as u32,
            },
            noise_frame: frame.frame_index,
            _pad0: 0,
            _pad1: 0,
            _pad2: 0,
        }
    }

    /// Rays per frame over the inner image.
    pub fn graph(&self, frame: &FrameDesc) -> Graph {
        let resources = vec![
            record("groundtruth_frame", std::slice::from_ref(&self.frame(frame)), "camera + GroundTruthParams"),
            target_f32("ao", 1.0, "ray-traced AO (spec gtao-raymarch-hybrid §5), 1 = unoccluded"),
            ray_counter(),
        ];
        let bindings = super::rq::groundtruth_rq::Bindings {
            frame: "groundtruth_frame",
            tlas: inputs::SCENE_TLAS,
            depth: inputs::LINEAR_DEPTH,
            normals: inputs::VIEW_NORMALS,
            ao: "ao",
            uvs: inputs::SCENE_UVS,
            materials: inputs::SCENE_MATERIALS,
            mask_headers: inputs::SCENE_MASK_HEADERS,
            mask_texels: inputs::SCENE_MASK_TEXELS,
            ray_count: RAY_COUNT,
        };
        let passes = vec![Pass::ray_traced("groundtruth", SHADERS, bindings, Extent::Inner)];
        Graph {
            resources,
            passes,
            output: "ao",
            raw_output: "ao",
            snapshots: Vec::new(),
            view: frame.camera.view,
            diagnostics: Default::default(),
        }
    }
}
