//! Half resolution as a transform of any technique's graph (host side, spec half-resolution):
//! the technique's graph is built for the half-resolution frame, its extents are re-expressed on
//! the full target ([`crate::graph::Extent::halved`]), its G-buffer inputs are replaced by the
//! downsample's, and the upsample brings its output back to the full target.

use super::{HalfParams, PICK_CHECKERBOARD, PICK_NEAREST};
use crate::common::ViewParams;
use crate::graph::{
    Diagnostics, Elem, Extent, FrameDesc, Graph, Init, Lifetime, Pass, Resource, Size, inputs, target_f32,
};
use crate::technique::{Constant, Declaration, Setting, Settings, single_layer};

/// Default plane tolerance `τ` of the upsample, in pixel footprints (spec half-resolution §3.2):
/// about twice the largest distance, 0.71 footprints, of a tap on the pixel's own plane.
pub const PLANE_TOLERANCE: f32 = 1.5;

/// The half-resolution depth and normals the downsample writes.
pub const HALF_DEPTH: &str = "half_linear_depth";
pub const HALF_NORMALS: &str = "half_view_normals";
/// The upsampled AO, on the full target: the graph's output when the technique runs at half
/// resolution.
pub const OUTPUT: &str = "half_upsampled_ao";

/// Which pixel of each 2×2 block the downsample keeps (spec half-resolution §2).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Pick {
    /// The nearest on even texels, the farthest on odd ones: both sides of a depth edge survive.
    Checkerboard,
    /// Always the nearest.
    Nearest,
}

/// The upsample's and the downsample's settings \[defaults\].
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct HalfSettings {
    /// \[`Pick::Checkerboard`\]
    pub pick: Pick,
    /// Plane tolerance `τ` in pixel footprints, in (0, ∞]; ∞ turns the plane weight off (the
    /// taps on background still get none) \[[`PLANE_TOLERANCE`]\].
    pub plane_tolerance: f32,
}

impl Default for HalfSettings {
    fn default() -> Self {
        HalfSettings { pick: Pick::Checkerboard, plane_tolerance: PLANE_TOLERANCE }
    }
}

impl HalfSettings {
    /// The upsample with its plane weight off: bilinear over the taps that are not background
    /// (what the edge test must tell apart).
    pub fn bilinear() -> HalfSettings {
        HalfSettings { plane_tolerance: f32::INFINITY, ..HalfSettings::default() }
    }

    /// τ > 0.
    pub fn validate(&self) -> Result<(), String> {
        if self.plane_tolerance.is_nan() || self.plane_tolerance <= 0.0 {
            return Err(format!("half-resolution plane tolerance {}: expected a number > 0", self.plane_tolerance));
        }
        Ok(())
    }
}

/// The picks by name, in the order of [`Pick`]'s variants (the `pick` setting).
const PICKS: [&str; 2] = ["checkerboard", "nearest"];

impl Settings for HalfSettings {
    const ROWS: &'static [Setting<Self>] = &[
        Setting::<Self>::choice("pick", &PICKS, |s| s.pick as usize, |s, i| {
            s.pick = [Pick::Checkerboard, Pick::Nearest][i]
        })
        .help("Which pixel of each 2×2 block the downsample keeps (HalfParams.pick: checkerboard 0, nearest 1; spec half-resolution §2)"),
        Setting::<Self>::number("plane-tolerance", 0.0, f32::MAX, |s| &mut s.plane_tolerance)
            .help("The upsample's plane tolerance τ in pixel footprints, > 0; the largest (3.4e38) turns the plane weight off (spec half-resolution §3)"),
    ];

    fn check(&self) -> Result<(), String> {
        HalfSettings::validate(self)
    }
}

/// How the half-resolution frame's names follow from the full target's (spec half-resolution
/// §1): `(name, expression of the full frame's names)`. A technique's graph and constants at half
/// resolution are its published ones evaluated with these names; the rest of the frame (camera,
/// planes, field of view) is the same.
pub const HALF_NAMES: [(&str, &str); 5] = [
    ("W", "div_floor(W, 2)"),
    ("H", "div_floor(H, 2)"),
    ("w", "div_floor(w, 2)"),
    ("h", "div_floor(h, 2)"),
    ("g", "div_floor(g, 2)"),
];

/// How [`half_params`] fills `HalfParams`, then the camera's rows. `half(ViewParams)` is the
/// `ViewParams` rows evaluated with the names of [`HALF_NAMES`].
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("HalfParams.view", "the frame's ViewParams (ViewParams rows): the full target").expr("ViewParams"),
        Constant::new(
            "HalfParams.half",
            "the ViewParams rows with W, H, w, h, g halved (half_resolution.half_names): res (W/2, H/2), guard g/2, the same frustum"
        )
        .expr("half(ViewParams)"),
        Constant::new("HalfParams.pick", "`pick`: checkerboard 0, nearest 1").expr("index(`pick`)"),
        Constant::new("HalfParams.plane_tolerance", "`plane-tolerance` τ [1.5]").expr("`plane-tolerance`"),
        Constant::new("HalfParams._pad0", "0").expr("0"),
        Constant::new("HalfParams._pad1", "0").expr("0"),
    ],
    crate::common::camera::CONSTANTS,
];

/// Half resolution as a declaration, for the manifest's settings and constants (never in the
/// registry: it wraps a technique's graph, [`at_resolution`]; its own graph function refuses).
pub static HALF_RESOLUTION: Declaration<HalfSettings> = Declaration {
    name: "half-resolution",
    summary: "any technique that reads no depth-peeled second layer, at half resolution between a depth/normal downsample and an edge-aware upsample",
    keys: &["pick", "plane-tolerance"],
    defaults: HalfSettings::default,
    graph: |_, _| Err("half resolution wraps a technique's graph (at_resolution); it has none of its own".into()),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[],
    tables: &[],
};

/// What [`Resolution::name`] puts between a half resolution's pick and a non-default plane
/// tolerance.
const TAU_SUFFIX: &str = "-tau";

/// The resolution a technique runs at.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub enum Resolution {
    /// The full target.
    #[default]
    Full,
    /// Half the target in each axis, upsampled to it.
    Half(HalfSettings),
}

impl Resolution {
    /// The names the `resolution` key and the `--resolution` flag take: `full`, `half`
    /// (checkerboard pick), `half-nearest`; a half one may end in `-tau<τ>` ([`Resolution::parse`]).
    pub const NAMES: [&'static str; 3] = ["full", "half", "half-nearest"];

    /// Half resolution with the default upsample.
    pub fn half() -> Resolution {
        Resolution::Half(HalfSettings::default())
    }

    /// One of [`Resolution::NAMES`], a half one optionally followed by `-tau<τ>` (a plane
    /// tolerance other than [`PLANE_TOLERANCE`], `inf` for none: [`Resolution::name`]'s form).
    pub fn parse(name: &str) -> Result<Resolution, String> {
        let name = name.trim();
        let (base, tau) = match name.rsplit_once(TAU_SUFFIX) {
            Some((base, tau)) if base.starts_with("half") => (base, Some(tau)),
            _ => (name, None),
        };
        let mut half = match base {
            // (`full` never carries a τ: only a name starting with `half` is split above.)
            "full" => return Ok(Resolution::Full),
            "half" => HalfSettings::default(),
            "half-nearest" => HalfSettings { pick: Pick::Nearest, ..HalfSettings::default() },
            _ => {
                return Err(format!(
                    "resolution {name}: expected {} (a half one may end in {TAU_SUFFIX}<plane tolerance>)",
                    Resolution::NAMES.join("|")
                ));
            }
        };
        if let Some(tau) = tau {
            half.plane_tolerance =
                tau.parse().map_err(|_| format!("resolution {name}: plane tolerance '{tau}' is not a number"))?;
            half.validate().map_err(|e| format!("resolution {name}: {e}"))?;
        }
        Ok(Resolution::Half(half))
    }

    /// The name [`Resolution::parse`] reads back: one of [`Resolution::NAMES`], a half one
    /// followed by `-tau<τ>` when its plane tolerance is not [`PLANE_TOLERANCE`], so that labels
    /// and reports tell such a run apart.
    pub fn name(&self) -> String {
        let (base, half) = match self {
            Resolution::Full => return "full".to_string(),
            Resolution::Half(h @ HalfSettings { pick: Pick::Checkerboard, .. }) => ("half", h),
            Resolution::Half(h @ HalfSettings { pick: Pick::Nearest, .. }) => ("half-nearest", h),
        };
        if half.plane_tolerance == PLANE_TOLERANCE {
            base.to_string()
        } else {
            format!("{base}{TAU_SUFFIX}{}", half.plane_tolerance)
        }
    }
}

/// `view` at half resolution: `res/2`, guard `g/2`, the same frustum (spec half-resolution §1).
/// Refused unless `W`, `H` and `g` are even.
pub fn half_view(view: &ViewParams) -> Result<ViewParams, String> {
    let size = view.size();
    let even = size.x.is_multiple_of(2) && size.y.is_multiple_of(2) && view.guard.is_multiple_of(2);
    if !even {
        return Err(format!(
            "half resolution needs an even target and guard band: this one is {}×{} with a {}-pixel guard band",
            size.x, size.y, view.guard
        ));
    }
    if size.x < 2 * view.guard + 2 || size.y < 2 * view.guard + 2 {
        return Err(format!(
            "half resolution needs at least 2×2 pixels inside the guard band: this target is {}×{} with a {}-pixel guard band",
            size.x, size.y, view.guard
        ));
    }
    Ok(ViewParams { res: view.res * 0.5, guard: view.guard / 2, ..*view })
}

/// The push constants of the downsample and the upsample.
pub fn half_params(settings: &HalfSettings, view: &ViewParams) -> Result<HalfParams, String> {
    Ok(HalfParams {
        view: *view,
        half: half_view(view)?,
        pick: match settings.pick {
            Pick::Checkerboard => PICK_CHECKERBOARD,
            Pick::Nearest => PICK_NEAREST,
        },
        plane_tolerance: settings.plane_tolerance,
        _pad0: 0,
        _pad1: 0,
    })
}

/// The graph `build` makes for `frame`, at `resolution`: unchanged at full resolution; at half,
/// `build`'s graph for the half-resolution frame between [`super::half_downsample()`] and
/// [`super::half_upsample()`] (spec half-resolution §1). The technique's passes read the
/// downsampled depth and normals instead of the G-buffer's; its resources and dispatches keep
/// their half-target sizes as extents of the full target. Its output becomes [`OUTPUT`], which
/// is also the raw output; the diagnostics (bent normals, refinement buffers) and snapshots,
/// which reports read as full-target images, are dropped. Refused for a graph that reads the
/// depth-peeled second layer, which the downsample does not reduce.
pub fn at_resolution(
    resolution: Resolution,
    frame: &FrameDesc,
    build: impl FnOnce(&FrameDesc) -> Result<Graph, String>,
) -> Result<Graph, String> {
    let Resolution::Half(settings) = resolution else { return build(frame) };
    settings.validate()?;
    let params = half_params(&settings, &frame.camera.view)?;
    let mut half_frame = *frame;
    half_frame.camera.view = params.half;
    half_frame.temporal = None;
    half_frame.previous_camera = None;
    let mut graph = build(&half_frame)?;
    if graph.inputs().contains(&inputs::SECOND_DEPTH) {
        return Err("half resolution does not reduce the depth-peeled second layer this technique reads".into());
    }
    for r in &mut graph.resources {
        r.size = r.size.halved()?;
    }
    for pass in &mut graph.passes {
        pass.dispatch = pass.dispatch.halved()?;
        for b in &mut pass.bindings {
            b.resource = match b.resource {
                inputs::LINEAR_DEPTH => HALF_DEPTH,
                inputs::VIEW_NORMALS => HALF_NORMALS,
                other => other,
            };
        }
    }
    let half_texels = |name, elem, doc| Resource {
        name,
        elem,
        size: Size::Texels { extent: Extent::Full.halved().expect("full halves"), per_texel: 1 },
        init: Init::Undefined,
        lifetime: Lifetime::PerFrame,
        doc,
    };
    graph.resources.extend([
        half_texels(HALF_DEPTH, Elem::F32, "linear depth of the half-resolution target (half-resolution §2)"),
        half_texels(HALF_NORMALS, Elem::U32, "encoded view normals of the half-resolution target (half-resolution §2)"),
        target_f32(OUTPUT, 1.0, "the technique's AO upsampled to the full target (half-resolution §3)"),
    ]);
    let bytes = bytemuck::bytes_of(&params);
    let down = super::half_downsample::Bindings {
        depth: inputs::LINEAR_DEPTH,
        normals: inputs::VIEW_NORMALS,
        half_depth: HALF_DEPTH,
        half_normals: HALF_NORMALS,
    };
    let up = super::half_upsample::Bindings {
        depth: inputs::LINEAR_DEPTH,
        normals: inputs::VIEW_NORMALS,
        half_depth: HALF_DEPTH,
        half_ao: graph.output,
        ao: OUTPUT,
    };
    graph.passes.insert(0, Pass::compute("half_downsample", down, Extent::Full.halved()?, bytes));
    graph.passes.push(Pass::compute("half_upsample", up, Extent::Inner, bytes));
    graph.output = OUTPUT;
    graph.raw_output = OUTPUT;
    graph.snapshots.clear();
    graph.diagnostics = Diagnostics::default();
    graph.view = frame.camera.view;
    Ok(graph)
}
