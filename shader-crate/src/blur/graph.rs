//! The blur's passes for a technique's graph (host side).

use super::BlurParams;
use crate::glam::uvec2;
use crate::graph::{Extent, FrameDesc, Pass, Resource, inputs, target_f32};

/// Depth-aware blur sharpness (spec svao-raysd §12).
pub const SHARPNESS: f32 = 16.0;

/// Push constants of one blur direction.
pub fn blur_params(frame: &FrameDesc, direction: crate::glam::UVec2) -> BlurParams {
    BlurParams { view: frame.camera.view, direction, sharpness: SHARPNESS, _pad: 0 }
}

/// The cross-bilateral blur (spec svao-raysd §12) of `input` into `output`: horizontal into a
/// scratch image, then vertical. Returns the resources it adds (`output` and its scratch) and
/// its two passes.
pub fn blur_passes(frame: &FrameDesc, input: &'static str, output: &'static str) -> (Vec<Resource>, Vec<Pass>) {
    const SCRATCH: &str = "blur_horizontal";
    let resources = vec![
        target_f32(SCRATCH, 1.0, "AO after the horizontal blur"),
        target_f32(output, 1.0, "AO after the cross-bilateral blur (spec svao-raysd §12)"),
    ];
    let pass = |from, to, direction| {
        let bindings = super::blur_main::Bindings { ao_in: from, depth: inputs::LINEAR_DEPTH, ao_out: to };
        Pass::compute("blur", bindings, Extent::Inner, bytemuck::bytes_of(&blur_params(frame, direction)))
    };
    (resources, vec![pass(input, SCRATCH, uvec2(1, 0)), pass(SCRATCH, output, uvec2(0, 1))])
}
