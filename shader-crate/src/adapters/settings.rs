//! The adapters' settings, constants and modules as the manifest publishes them (host side):
//! `ImportParams` from the engine's depth convention and projection planes and the frame, and
//! how each adapter module is dispatched. Not a technique: the adapters have no pass graph of
//! storage buffers (they read and write the engine's images), so [`ADAPTERS`] is registered
//! nowhere and its graph function refuses.

use super::{DEPTH_LINEAR, DEPTH_REVERSED, DEPTH_REVERSED_INFINITE, DEPTH_STANDARD, ImportParams};
use crate::graph::FrameDesc;
use crate::technique::{Constant, Declaration, Setting, Settings, single_layer};

/// The engine's side of the import: its depth image's convention and its projection's planes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct AdapterSettings {
    /// One of [`super::depth_convention`].
    pub convention: u32,
    /// The engine projection's near plane (view depth, world units).
    pub near: f32,
    /// Its far plane (ignored by `reversed-infinite`).
    pub far: f32,
}

impl Default for AdapterSettings {
    fn default() -> Self {
        AdapterSettings { convention: DEPTH_REVERSED, near: 0.1, far: 1000.0 }
    }
}

/// The depth conventions by name, in the order of their values.
const CONVENTIONS: [&str; 4] = ["standard", "reversed", "reversed-infinite", "linear"];

impl Settings for AdapterSettings {
    const ROWS: &'static [Setting<Self>] = &[
        Setting::<Self>::choice("depth-convention", &CONVENTIONS, |s| s.convention as usize, |s, i| {
            s.convention = [DEPTH_STANDARD, DEPTH_REVERSED, DEPTH_REVERSED_INFINITE, DEPTH_LINEAR][i]
        })
        .help("The engine depth image's convention (ImportParams.depth_convention: standard 0, reversed 1, reversed-infinite 2, linear 3)"),
        Setting::<Self>::number("engine-near", 0.0, f32::MAX, |s| &mut s.near)
            .help("The engine projection's near plane (view depth, world units)"),
        Setting::<Self>::number("engine-far", 0.0, f32::MAX, |s| &mut s.far)
            .help("The engine projection's far plane (view depth, world units; unread for reversed-infinite)"),
    ];
}

impl AdapterSettings {
    /// The push constants of every adapter module for `frame`: aokit's full target, the engine
    /// images' size (the inner image) and the engine's depth convention and planes.
    pub fn params(&self, frame: &FrameDesc) -> ImportParams {
        ImportParams {
            view: frame.camera.view,
            engine_size: frame.inner(),
            depth_convention: self.convention,
            near: self.near,
            far: self.far,
            _pad: 0,
        }
    }
}

/// How [`AdapterSettings::params`] fills `ImportParams`, then the camera's rows.
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("ImportParams.view", "the frame's ViewParams (ViewParams rows): aokit's full target")
            .expr("ViewParams"),
        Constant::new("ImportParams.engine_size", "(w, h): the engine images cover the inner image")
            .expr("uvec2(w, h)"),
        Constant::new(
            "ImportParams.depth_convention",
            "`depth-convention`: standard 0, reversed 1, reversed-infinite 2, linear 3 (import only)"
        )
        .expr("index(`depth-convention`)"),
        Constant::new("ImportParams.near", "`engine-near`: the engine projection's near plane (import only)")
            .expr("`engine-near`"),
        Constant::new("ImportParams.far", "`engine-far`: the engine projection's far plane (import only)")
            .expr("`engine-far`"),
        Constant::new("ImportParams._pad", "0").expr("0"),
    ],
    crate::common::camera::CONSTANTS,
];

/// The adapters as a declaration, for the manifest's settings and constants (never in the
/// registry; its graph function refuses).
pub static ADAPTERS: Declaration<AdapterSettings> = Declaration {
    name: "adapters",
    summary: "engine images ↔ aokit's internal G-buffer and AO buffers",
    keys: &["depth-convention", "engine-near", "engine-far"],
    defaults: AdapterSettings::default,
    graph: |_, _| Err("the adapters are modules run on the engine's images, not a pass graph".into()),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[],
    tables: &[],
};

/// One adapter module: what it reads and writes and how it is dispatched.
#[derive(Copy, Clone, Debug)]
pub struct AdapterModule {
    pub entry: &'static str,
    /// Invocations `[x, y]` in the constants' grammar (compute: workgroups round up).
    pub dispatch: [&'static str; 2],
    /// What each binding is: the engine image or aokit's buffer (the technique graphs' input
    /// or output name).
    pub bindings: &'static [(u32, &'static str)],
    pub doc: &'static str,
}

/// Every adapter module (`aokit_shaders::adapters`).
pub const MODULES: &[AdapterModule] = &[
    AdapterModule {
        entry: "import_depth",
        dispatch: ["W", "H"],
        bindings: &[(0, "the engine's depth image (w×h, sampled: D32/D16/R32F…)"), (1, "linear_depth")],
        doc: "one invocation per full-target pixel: the engine depth as linear view depth (guard band: the nearest edge texel; background: ViewParams.far)",
    },
    AdapterModule {
        entry: "import_normals",
        dispatch: ["W", "H"],
        bindings: &[
            (0, "the engine's normal image (w×h, sampled: RGB = n·0.5 + 0.5, view space)"),
            (1, "view_normals"),
        ],
        doc: "one invocation per full-target pixel: the engine normal encoded octahedrally (assets/README.md, \"Normals\")",
    },
    AdapterModule {
        entry: "export_ao_r32f",
        dispatch: ["w", "h"],
        bindings: &[
            (0, "the technique's output (f32 per full-target pixel)"),
            (1, "the engine's AO image (w×h, storage r32float)"),
        ],
        doc: "one invocation per engine texel: the inner image's AO, clamped to [0, 1]",
    },
    AdapterModule {
        entry: "export_ao_r16f",
        dispatch: ["w", "h"],
        bindings: &[
            (0, "the technique's output (f32 per full-target pixel)"),
            (1, "the engine's AO image (w×h, storage r16float)"),
        ],
        doc: "as export_ao_r32f into an r16float image (Vulkan only: WebGPU core has no r16float storage textures)",
    },
    AdapterModule {
        entry: "export_ao_r8",
        dispatch: ["w", "h"],
        bindings: &[
            (0, "the technique's output (f32 per full-target pixel)"),
            (1, "the engine's AO image (w×h, storage r8unorm)"),
        ],
        doc: "as export_ao_r32f into an r8unorm image (Vulkan only: WebGPU core has no r8unorm storage textures)",
    },
];
