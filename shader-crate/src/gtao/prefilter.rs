//! PrefilterDepths (spec gtao-raymarch-hybrid §2.5): MIP 0 is the working depth, clamped to the
//! fp16 range as the reference does in every build; each further level filters 2×2 texels of
//! the level above with a weighted average that prefers the farthest sample.
//!
//! Two dispatches make the five levels, as XeGTAO's one dispatch makes them from registers and
//! group-shared memory (spec gtao-raymarch-hybrid §2.5): [`prefilter_near`] (pass 0) takes a 2×2
//! block of MIP 0 and its MIP 1 texel per invocation, [`prefilter_far`] (pass 1) a 4×4 block of
//! MIP 2, the 2×2 MIP 3 texels over it and their MIP 4 texel from 8×8 texels of MIP 1. Every
//! level below the first is filtered from the values the invocation holds, exactly the ones it
//! wrote: the chain equals the level-by-level [`prefilter_texel`].

use super::main_pass::Falloff;
use super::{GtaoParams, mip_offset, mip_size};
use crate::common::lanes::Lanes;
use crate::common::math::depth_or_far;
use crate::common::read::{TexelBuffer, read};
use crate::glam::{UVec2, uvec2};

const _: () = assert!(
    super::MIP_LEVELS == 5 && super::PREFILTER_BLOCK[1] == 1 << (super::MIP_LEVELS - 1),
    "prefilter_far makes MIPs 2, 3 and 4: a 16×16 block of MIP 0 is one texel of MIP 4"
);

/// Largest working depth (the fp16 maximum, spec gtao-raymarch-hybrid §2.5 step 1, §7.6).
pub const MAX_WORKING_DEPTH: f32 = 65504.0;

/// The depth MIP filter's weight (spec gtao-raymarch-hybrid §2.5): `R' = 0.75·R·mult`, `w(Δ) =
/// sat((R' − Δ) / (FalloffRange·R'))` as XeGTAO evaluates it ([`Falloff`]), made once per
/// invocation.
#[inline]
pub fn mip_falloff(params: &GtaoParams) -> Falloff {
    let r = 0.75 * params.effective_radius();
    Falloff::new(r, params.falloff_range * r)
}

/// Depth MIP filter (spec gtao-raymarch-hybrid §2.5): `w_i = w(dmax − d_i)` ([`mip_falloff`]),
/// result `Σ w_i·d_i / Σ w_i`; a step function when FalloffRange = 0. One texel or `L::LANES`.
#[inline(always)]
pub fn mip_filter<L: Lanes>(d: [L; 4], falloff: &Falloff) -> L {
    let dmax = d[0].max(d[1]).max(d[2].max(d[3]));
    let (mut sum, mut weights) = (L::splat(0.0), L::splat(0.0));
    let mut i = 0;
    while i < 4 {
        let w = falloff.weight(dmax - d[i]);
        sum = sum + w * d[i];
        weights = weights + w;
        i += 1;
    }
    sum / weights
}

/// Texel `t` of MIP `k`, level by level (the definition the two dispatches reproduce). Level 0
/// reads the linear G-buffer `depth` ([`working_depth`]); level k ≥ 1 filters the 2×2 texels of
/// MIP k−1 in `mips` (clamped to that level's size).
#[inline]
pub fn prefilter_texel(params: &GtaoParams, depth: &[f32], mips: &[f32], k: u32, t: UVec2) -> f32 {
    let full = params.view.size();
    if k == 0 {
        return working_depth(params, depth, full, t);
    }
    let above = Level::of(full, k - 1);
    let s = uvec2(2 * t.x, 2 * t.y);
    let at = |x, y| unsafe { read(mips, above.clamped(x, y)) };
    let d = [at(s.x, s.y), at(s.x + 1, s.y), at(s.x, s.y + 1), at(s.x + 1, s.y + 1)];
    mip_filter(d, &mip_falloff(params))
}

/// MIP 0 at pixel `p` (clamped to the `full` target): [`working_value`] of the linear G-buffer
/// depth.
#[inline(always)]
pub fn working_depth(params: &GtaoParams, depth: &[f32], full: UVec2, p: UVec2) -> f32 {
    let (x, y) = (p.x.min(full.x - 1), p.y.min(full.y - 1));
    working_value(unsafe { read(depth, (y * full.x + x) as usize) }, params.view.far)
}

/// The working depth of a G-buffer depth `d`: unusable depths read as the `far` plane, then
/// clamped to [0, 65504]. One texel or `L::LANES`.
#[inline(always)]
pub fn working_value<L: Lanes>(d: L, far: f32) -> L {
    crate::common::math::clamp(depth_or_far(d, far), 0.0, MAX_WORKING_DEPTH)
}

/// A level of the packed chain: its size and where it starts.
#[derive(Copy, Clone)]
struct Level {
    size: UVec2,
    offset: usize,
}

impl Level {
    /// MIP `k` of the `full` target.
    #[inline]
    fn of(full: UVec2, k: u32) -> Level {
        Level { size: mip_size(full, k), offset: mip_offset(full, k) }
    }

    /// The index in the chain of texel (x, y), clamped to the level.
    #[inline]
    fn clamped(&self, x: u32, y: u32) -> usize {
        self.offset + (y.min(self.size.y - 1) * self.size.x + x.min(self.size.x - 1)) as usize
    }

    /// Writes `value` at texel `t` if `t` lies in the level.
    #[inline]
    fn store<M: TexelBuffer>(&self, mips: &mut M, t: UVec2, value: f32) {
        if t.x < self.size.x && t.y < self.size.y {
            mips.store(self.offset + (t.y * self.size.x + t.x) as usize, value);
        }
    }

    /// The filtered texel over the 2×2 block `[top-left, top-right, bottom-left, bottom-right]`
    /// of this level: a level one texel wide (high) clamps the right (bottom) reads onto the left
    /// (top) texel, as [`prefilter_texel`] does.
    #[inline]
    fn filter_block(&self, falloff: &Falloff, d: [f32; 4]) -> f32 {
        let (narrow, short) = (self.size.x == 1, self.size.y == 1);
        let tr = if narrow { d[0] } else { d[1] };
        let bl = if short { d[0] } else { d[2] };
        let br = if narrow && short {
            d[0]
        } else if narrow {
            d[2]
        } else if short {
            d[1]
        } else {
            d[3]
        };
        mip_filter([d[0], tr, bl, br], falloff)
    }
}

/// Pass 0 at block `b` (`⌈W/2⌉ × ⌈H/2⌉` invocations): MIP 0 at `2b + {0,1}²` and MIP 1 at `b`.
#[inline]
pub fn prefilter_near<M: TexelBuffer>(params: &GtaoParams, depth: &[f32], mips: &mut M, b: UVec2) {
    let full = params.view.size();
    let (mip0, mip1) = (Level::of(full, 0), Level::of(full, 1));
    let s = uvec2(2 * b.x, 2 * b.y);
    let at = [s, uvec2(s.x + 1, s.y), uvec2(s.x, s.y + 1), uvec2(s.x + 1, s.y + 1)];
    let d = [
        working_depth(params, depth, full, at[0]),
        working_depth(params, depth, full, at[1]),
        working_depth(params, depth, full, at[2]),
        working_depth(params, depth, full, at[3]),
    ];
    let mut i = 0;
    while i < 4 {
        mip0.store(mips, at[i], d[i]);
        i += 1;
    }
    // The reads clamp to the target, so a one-pixel-wide target repeats its texel already.
    mip1.store(mips, b, mip_filter(d, &mip_falloff(params)));
}

/// Pass 1 at block `b` (`⌈W/16⌉ × ⌈H/16⌉` invocations): MIP 2 at `4b + {0…3}²`, MIP 3 at
/// `2b + {0,1}²` and MIP 4 at `b`, from MIP 1 in `mips`.
#[inline]
pub fn prefilter_far<M: TexelBuffer>(params: &GtaoParams, mips: &mut M, b: UVec2) {
    let full = params.view.size();
    let levels = [Level::of(full, 1), Level::of(full, 2), Level::of(full, 3)];
    let falloff = mip_falloff(params);
    let s = uvec2(2 * b.x, 2 * b.y);
    let d = [
        mip3_block(&levels, &falloff, mips, s),
        mip3_block(&levels, &falloff, mips, uvec2(s.x + 1, s.y)),
        mip3_block(&levels, &falloff, mips, uvec2(s.x, s.y + 1)),
        mip3_block(&levels, &falloff, mips, uvec2(s.x + 1, s.y + 1)),
    ];
    Level::of(full, 4).store(mips, b, levels[2].filter_block(&falloff, d));
}

/// MIP 2 at `2t + {0,1}²` and MIP 3 at `t` from MIP 1 (`levels`: MIPs 1, 2, 3), written;
/// returns the MIP 3 texel.
#[inline]
fn mip3_block<M: TexelBuffer>(levels: &[Level; 3], falloff: &Falloff, mips: &mut M, t: UVec2) -> f32 {
    let [mip1, mip2, mip3] = *levels;
    let s = uvec2(2 * t.x, 2 * t.y);
    let at = [s, uvec2(s.x + 1, s.y), uvec2(s.x, s.y + 1), uvec2(s.x + 1, s.y + 1)];
    let mut d = [0.0; 4];
    let mut i = 0;
    while i < 4 {
        let q = uvec2(2 * at[i].x, 2 * at[i].y);
        // MIP 1's reads clamp to its size, as prefilter_texel's do.
        let block = [
            mips.load(mip1.clamped(q.x, q.y)),
            mips.load(mip1.clamped(q.x + 1, q.y)),
            mips.load(mip1.clamped(q.x, q.y + 1)),
            mips.load(mip1.clamped(q.x + 1, q.y + 1)),
        ];
        d[i] = mip_filter(block, falloff);
        mip2.store(mips, at[i], d[i]);
        i += 1;
    }
    let value = mip2.filter_block(falloff, d);
    mip3.store(mips, t, value);
    value
}
