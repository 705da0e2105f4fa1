//! The temporal accumulation as passes appended to any technique's graph (host side): the
//! frame asks for it ([`FrameDesc::temporal`]) and carries the previous camera
//! ([`FrameDesc::previous_camera`]); the history lives in persistent resources.

use super::TemporalFrame;
use crate::graph::{Elem, Extent, FrameDesc, Graph, Init, Lifetime, Pass, Resource, Size, inputs, record};
use crate::technique::{Constant, Declaration, Setting, Settings, single_layer};

/// The accumulation's settings \[defaults\].
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct TemporalSettings {
    /// Weight α of the current frame in the exponential blend [0.1]: the history's weight
    /// decays by 1 − α per frame, ≈ 1/α frames of memory.
    pub alpha: f32,
    /// Relative depth tolerance ε of the history test [`DEPTH_TOLERANCE`].
    pub depth_tolerance: f32,
}

/// Default relative depth tolerance ε (docs/temporal.md): a texel the reprojected point falls in
/// (the instability's read) or next to (the bilinear taps) holds the depth up to ½–1 px away,
/// which on a surface seen 80° from its normal is ~1–2 % of the depth at 360 rows and 60° field
/// of view; 5 % keeps such surfaces (on Sponza's orbit 95.5 % of the inner pixels are valid in
/// both frames at ε = 0.005, 96.9 % at 0.05, 97.1 % at 0.3) and still rejects an occluder and
/// the surface behind it when they are more than 5 % apart in depth.
pub const DEPTH_TOLERANCE: f32 = 0.05;

impl Default for TemporalSettings {
    fn default() -> Self {
        TemporalSettings { alpha: 0.1, depth_tolerance: DEPTH_TOLERANCE }
    }
}

impl TemporalSettings {
    /// α ∈ (0, 1], ε ∈ (0, 1].
    pub fn validate(&self) -> Result<(), String> {
        if !(self.alpha > 0.0 && self.alpha <= 1.0) {
            return Err(format!("temporal alpha {}: expected a number in (0, 1]", self.alpha));
        }
        if !(self.depth_tolerance > 0.0 && self.depth_tolerance <= 1.0) {
            return Err(format!("temporal depth tolerance {}: expected a number in (0, 1]", self.depth_tolerance));
        }
        Ok(())
    }

    /// The kernels' record: history only with a previous camera of the same target size (the
    /// history buffers are this target's).
    pub fn frame(&self, frame: &FrameDesc) -> TemporalFrame {
        let previous = frame.previous_camera.filter(|c| c.view.size() == frame.camera.view.size());
        TemporalFrame {
            camera: frame.camera,
            previous: previous.unwrap_or(frame.camera),
            alpha: self.alpha,
            depth_tolerance: self.depth_tolerance,
            history: previous.is_some() as u32,
            _pad: 0,
        }
    }
}

impl Settings for TemporalSettings {
    const ROWS: &'static [Setting<Self>] = &[
        Setting::<Self>::number("alpha", 0.0, 1.0, |s| &mut s.alpha)
            .help("Weight α of the current frame in the exponential blend, (0, 1]: ≈ 1/α frames of memory (TemporalFrame.alpha)"),
        Setting::<Self>::number("depth-tolerance", 0.0, 1.0, |s| &mut s.depth_tolerance)
            .help("Relative depth tolerance ε of the history test, (0, 1] (TemporalFrame.depth_tolerance; docs/temporal.md)"),
    ];

    fn check(&self) -> Result<(), String> {
        TemporalSettings::validate(self)
    }
}

/// The previous frame's camera names the expressions read (`assets/README.md`, "Temporal
/// accumulation"): `(this frame's name, the previous frame's)`. `previous(Camera)` is the
/// `Camera` rows evaluated with the second names in place of the first.
pub const PREVIOUS_NAMES: [(&str, &str); 6] = [
    ("eye", "previous_eye"),
    ("target", "previous_target"),
    ("up", "previous_up"),
    ("fov_y", "previous_fov_y"),
    ("near", "previous_near"),
    ("far", "previous_far"),
];

/// How [`TemporalSettings::frame`] fills `TemporalFrame`, then the camera's rows.
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("TemporalFrame.camera", "this frame's Camera (Camera and ViewParams rows)").expr("Camera"),
        Constant::new(
            "TemporalFrame.previous",
            "the previous frame's Camera: the Camera rows with the previous frame's eye, target, up, fov_y, near, far \
             (temporal.previous_names); this frame's on a first frame, after a cut or a resize"
        )
        .expr("previous(Camera)"),
        Constant::new("TemporalFrame.alpha", "`alpha` α [0.1]").expr("`alpha`"),
        Constant::new("TemporalFrame.depth_tolerance", "`depth-tolerance` ε [0.05]").expr("`depth-tolerance`"),
        Constant::new(
            "TemporalFrame.history",
            "1 when the history holds the previous frame (has_previous: a previous frame of the same target size), else 0"
        )
        .expr("u32(has_previous)"),
        Constant::new("TemporalFrame._pad", "0").expr("0"),
    ],
    crate::common::camera::CONSTANTS,
];

/// The temporal accumulation as a declaration, for the manifest's settings and constants (never
/// in the registry: it follows a technique's graph, [`accumulate`]; its own graph function
/// refuses).
pub static TEMPORAL: Declaration<TemporalSettings> = Declaration {
    name: "temporal",
    summary: "any technique's AO accumulated over frames: reprojected through depth, blended with the history",
    keys: &["alpha", "depth-tolerance"],
    defaults: TemporalSettings::default,
    graph: |_, _| {
        Err("the temporal accumulation follows a technique's graph (accumulate); it has none of its own".into())
    },
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[],
    tables: &[],
};

/// The accumulated AO, the graph's output when the accumulation is on.
pub const OUTPUT: &str = "temporal_ao";
/// The history: the previous frame's accumulated AO and its depth (persistent).
pub const HISTORY_AO: &str = "temporal_history_ao";
pub const HISTORY_DEPTH: &str = "temporal_history_depth";
/// The record of the two passes.
pub const RECORD: &str = "temporal_frame";

/// `graph` with the accumulation appended when `frame.temporal` asks for it (unchanged
/// otherwise): `temporal_blend` reads the technique's output, the depth and the history and
/// writes [`OUTPUT`], the new output; `temporal_store` then copies it and the depth into the
/// history. Works for every technique: it reads only the output and the depth.
pub fn accumulate(mut graph: Graph, frame: &FrameDesc) -> Result<Graph, String> {
    let Some(settings) = frame.temporal else { return Ok(graph) };
    settings.validate()?;
    let persistent = |name, doc| Resource {
        name,
        elem: Elem::F32,
        size: Size::TARGET,
        // Depth 0 is no surface: a fresh history fails every depth test.
        init: Init::Fill(0.0f32.to_bits()),
        lifetime: Lifetime::Persistent,
        doc,
    };
    graph.resources.extend([
        record(RECORD, std::slice::from_ref(&settings.frame(frame)), "TemporalFrame: both cameras, α, ε"),
        Resource {
            name: OUTPUT,
            elem: Elem::F32,
            size: Size::TARGET,
            init: Init::Fill(1.0f32.to_bits()),
            lifetime: Lifetime::PerFrame,
            doc: "the technique's AO accumulated over frames (exponential blend with the reprojected history)",
        },
        persistent(HISTORY_AO, "the previous frame's accumulated AO (persistent)"),
        persistent(HISTORY_DEPTH, "the previous frame's linear depth (persistent)"),
    ]);
    let blend = super::temporal_blend::Bindings {
        frame: RECORD,
        depth: inputs::LINEAR_DEPTH,
        ao: graph.output,
        history_ao: HISTORY_AO,
        history_depth: HISTORY_DEPTH,
        out: OUTPUT,
    };
    let store = super::temporal_store::Bindings {
        frame: RECORD,
        depth: inputs::LINEAR_DEPTH,
        accumulated: OUTPUT,
        history_ao: HISTORY_AO,
        history_depth: HISTORY_DEPTH,
    };
    graph.passes.push(Pass::compute("temporal", blend, Extent::Full, &[]));
    graph.passes.push(Pass::compute("temporal", store, Extent::Full, &[]));
    graph.output = OUTPUT;
    Ok(graph)
}
