//! Plain VAO's settings and pass graph (host side): VAO over the inner image (spec svao-raysd
//! §4–§5), then the cross-bilateral blur (svao-raysd §12).

use super::VaoParams;
use crate::blur::graph::blur_passes;
use crate::common::tables::AO_SAMPLES;
use crate::graph::{Extent, FrameDesc, Graph, Pass, inputs, target_f32};
use crate::svao::settings::{SvaoSettings, refined, stenciled};
use crate::technique::{Constant, Declaration};

/// Plain VAO → blur; on dual depth, with the HBAO+ kernel or with 16/32 samples, the stenciled
/// pipeline's pass 1 alone (spec svao-raysd §4.2, §4.5, §11).
pub static VAO: Declaration<SvaoSettings> = stenciled(
    "vao",
    "Volumetric AO on the depth buffer, or on dual depth (spec svao-raysd §4–§5, §11)",
    &["primary", "peel-separation", "kernel", "ao-samples"],
    SvaoSettings::default,
    |s, frame| if s.dual || s.hbao || s.samples != AO_SAMPLES { refined(s, frame) } else { Ok(graph(frame)) },
);

/// Screen-space clamp of the sampling disk in pixels (spec svao-raysd §2 default).
pub const MAX_SCREEN_RADIUS: f32 = 512.0;

/// Push constants of the VAO pass: the frame's radius, exponent and thickness.
pub fn vao_params(frame: &FrameDesc) -> VaoParams {
    VaoParams {
        view: frame.camera.view,
        radius: frame.radius,
        exponent: frame.exponent,
        thickness: frame.thickness,
        max_screen_radius: MAX_SCREEN_RADIUS,
    }
}

/// How [`vao_params`] and the blur (`crate::blur::graph::blur_params`) fill [`VaoParams`] and
/// `BlurParams`. VAO belongs to the stenciled family (dual depth and the HBAO+ kernel run its
/// pass 1), so its declaration uses the family's table, [`crate::svao::settings::CONSTANTS`],
/// which holds these rows.
pub const CONSTANTS: &[Constant] = &[
    Constant::new("VaoParams.view", "the frame's ViewParams (ViewParams rows)").expr("ViewParams"),
    Constant::new(
        "VaoParams.radius",
        "R·k, R the frame's world-space AO radius (world units), k = 1 for `kernel` = vao, k = 1.5 for \
         `kernel` = hbao (the reference UI's scaling for the HBAO+ kernel; hbao and hbao-sd: always 1.5)",
    )
    .expr("radius * pick(index(`kernel`), 1.0, 1.5)"),
    Constant::new("VaoParams.exponent", "e: the frame's AO exponent (the AO is A^e)").expr("exponent"),
    Constant::new("VaoParams.thickness", "τ: the frame's VAO thickness (world units)").expr("thickness"),
    Constant::new("VaoParams.max_screen_radius", "512 (pixels): screen-space clamp of the sampling disk").expr("512"),
    Constant::new("BlurParams.view", "the frame's ViewParams (ViewParams rows)").expr("ViewParams"),
    Constant::new(
        "BlurParams.direction",
        "per pass: (1, 0) in the first blur pass (horizontal, into blur_horizontal), (0, 1) in the second \
         (vertical, into ao_final)",
    )
    .expr("select(pass == 0, uvec2(1, 0), uvec2(0, 1))"),
    Constant::new("BlurParams.sharpness", "16 (depth sharpness of the cross-bilateral weights)").expr("16"),
    Constant::new("BlurParams._pad", "0").expr("0"),
];

/// VAO → blur.
pub fn graph(frame: &FrameDesc) -> Graph {
    let mut resources = vec![target_f32("ao", 1.0, "VAO before the blur (1 = unoccluded)")];
    let bindings = super::vao_main::Bindings { depth: inputs::LINEAR_DEPTH, normals: inputs::VIEW_NORMALS, ao: "ao" };
    let mut passes = vec![Pass::compute("vao", bindings, Extent::Inner, bytemuck::bytes_of(&vao_params(frame)))];
    let (r, p) = blur_passes(frame, "ao", "ao_final");
    resources.extend(r);
    passes.extend(p);
    Graph {
        resources,
        passes,
        output: "ao_final",
        raw_output: "ao",
        snapshots: Vec::new(),
        view: frame.camera.view,
        diagnostics: Default::default(),
    }
}
