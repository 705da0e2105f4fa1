//! PrefilterDepths (spec gtao-raymarch-hybrid §2.5): MIP 0 is the working depth, clamped to the
//! fp16 range as the reference does in every build; each further level filters 2×2 texels of
//! the level above with a weighted average that prefers the farthest sample.

use super::main_pass::Falloff;
use super::{GtaoParams, mip_offset, mip_size};
use crate::common::lanes::Lanes;
use crate::common::math::depth_or_far;
use crate::common::read::read;
use crate::glam::{UVec2, uvec2};

/// Largest working depth (the fp16 maximum, spec gtao-raymarch-hybrid §2.5 step 1, §7.6).
pub const MAX_WORKING_DEPTH: f32 = 65504.0;

/// Depth MIP filter (spec gtao-raymarch-hybrid §2.5): `R' = 0.75·R·mult`, `w_i = sat((R' − (dmax − d_i)) /
/// (FalloffRange·R'))` (as XeGTAO evaluates it, [`Falloff`]), result `Σ w_i·d_i / Σ w_i`; a step
/// function when FalloffRange = 0.
#[inline]
pub fn mip_filter(d: [f32; 4], params: &GtaoParams) -> f32 {
    let r = 0.75 * params.effective_radius();
    let dmax = Lanes::max(Lanes::max(d[0], d[1]), Lanes::max(d[2], d[3]));
    let falloff = Falloff::new(r, params.falloff_range * r);
    let (mut sum, mut weights) = (0.0, 0.0);
    let mut i = 0;
    while i < 4 {
        let w = falloff.weight(dmax - d[i]);
        sum += w * d[i];
        weights += w;
        i += 1;
    }
    sum / weights
}

/// Texel `t` of MIP `params.pass`. Level 0 reads the linear G-buffer `depth` (unusable depths
/// read as the far plane) and clamps to [0, 65504]; level k ≥ 1 filters MIP k−1 in `mips`.
#[inline]
pub fn prefilter_texel(params: &GtaoParams, depth: &[f32], mips: &[f32], t: UVec2) -> f32 {
    let view = &params.view;
    let full = view.size();
    let k = params.pass;
    if k == 0 {
        let d = depth_or_far(unsafe { read(depth, (t.y * full.x + t.x) as usize) }, view.far);
        return crate::common::math::clamp(d, 0.0, MAX_WORKING_DEPTH);
    }
    let above = mip_size(full, k - 1);
    let base = mip_offset(full, k - 1);
    let s = uvec2(2 * t.x, 2 * t.y);
    let d = [
        texel(mips, base, above, s.x, s.y),
        texel(mips, base, above, s.x + 1, s.y),
        texel(mips, base, above, s.x, s.y + 1),
        texel(mips, base, above, s.x + 1, s.y + 1),
    ];
    mip_filter(d, params)
}

/// Texel (x, y), clamped to the level's size, of the level at `base` in the chain.
#[inline]
fn texel(mips: &[f32], base: usize, size: UVec2, x: u32, y: u32) -> f32 {
    unsafe { read(mips, base + (y.min(size.y - 1) * size.x + x.min(size.x - 1)) as usize) }
}
