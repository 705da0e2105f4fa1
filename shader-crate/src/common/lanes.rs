//! Lane-generic arithmetic, so that one kernel source runs one pixel per invocation on the GPU
//! and several pixels per call on the CPU (SIMD across pixels without a second copy
//! of any kernel).
//!
//! A kernel function written over `L: Lanes` uses `L` where it used `f32`, `L::V2`/`L::V3`
//! where it used `Vec2`/`Vec3`, and [`Lanes::select`] where it branched on a per-pixel value.
//! With `L = f32` (SPIR-V and scalar CPU code) the types are `f32`, glam's `Vec2` and `Vec3`,
//! and every operation is the one the scalar code used, so nothing changes bit for bit. On the
//! CPU, [`CpuLanes`] ([`F32x16`]) holds sixteen pixels' values (`wide::f32x16`: two 256-bit
//! vectors on the default x86-64-v3 build); its transcendentals are `wide`'s polynomials, within
//! a few ulp of libm's.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::screen_space::clamp_index;
use crate::glam::{UVec2, Vec2, Vec3, vec2, vec3};
use core::ops::{Add, BitAnd, BitOr, BitXor, Div, Mul, Neg, Shr, Sub};

/// A number per lane: `f32` (one pixel) or a vector of pixels' values.
pub trait Lanes:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Add<f32, Output = Self>
    + Sub<f32, Output = Self>
    + Mul<f32, Output = Self>
    + Div<f32, Output = Self>
{
    /// Pixels per value.
    const LANES: usize;
    /// A per-lane condition.
    type Mask: Copy;
    /// A texel (or pixel) per lane: `UVec2` for `f32`.
    type U2: Copy;
    /// Two-component vector of lanes (`Vec2` for `f32`).
    type V2: LaneVec2<Self>;
    /// Three-component vector of lanes (`Vec3` for `f32`).
    type V3: LaneVec3<Self>;
    /// A whole number per lane, e.g. an index into a buffer (`u32` for `f32`).
    type Index: Copy
        + Add<Output = Self::Index>
        + Mul<Output = Self::Index>
        + Shr<u32, Output = Self::Index>
        + BitAnd<Output = Self::Index>
        + BitOr<Output = Self::Index>
        + BitXor<Output = Self::Index>;

    fn splat(v: f32) -> Self;
    /// The value whose lane `i` is `f(i)`.
    fn from_lanes(f: impl Fn(usize) -> f32) -> Self;
    /// Lane `i`.
    fn lane(self, i: usize) -> f32;
    /// `data[index(i)]` in lane `i` (a gather; `index` must capture values only, no slices:
    /// SPIR-V has no pointers to pointers).
    fn gather(data: &[f32], index: impl Fn(usize) -> usize) -> Self;
    fn sqrt(self) -> Self;
    /// `1/√x` for normal `x > 0`: GLSL.std.450 InverseSqrt on SPIR-V (one instruction on a GPU,
    /// where a square root and a division are two and more), `1/√x` natively, on the CPU's lanes
    /// within 4 ulp (3 measured on Zen 3) and ∞ for a subnormal x. `±∞` for ±0 and +0 for +∞
    /// natively, undefined on the GPU for x ≤ 0 (GLSL). The kernels take it of squared lengths,
    /// for a length and a direction at once: `|d| = |d|²·(1/|d|)`.
    fn inverse_sqrt(self) -> Self;
    /// `self·a + b`, natively with one rounding (`vfmadd`; a software `fmaf` on a CPU without
    /// FMA), so the CPU's scalar and lane versions of a polynomial agree bit for bit. On SPIR-V
    /// GLSL.std.450 Fma, fused on GPUs with an FMA unit (Vulkan also allows a multiply and an
    /// add).
    fn mul_add(self, a: Self, b: Self) -> Self;
    fn abs(self) -> Self;
    /// `max` and `min` return `other` where `self` is NaN (as `f32::max`/`min` do for one NaN).
    fn max(self, other: Self) -> Self;
    fn min(self, other: Self) -> Self;
    fn sin(self) -> Self;
    fn acos(self) -> Self;
    fn cos(self) -> Self;
    /// `(sin, cos)`, one evaluation on the CPU's lanes.
    fn sin_cos(self) -> (Self, Self);
    fn log2(self) -> Self;
    fn exp2(self) -> Self;
    fn powf(self, p: f32) -> Self;
    fn floor(self) -> Self;
    /// Round half to even.
    fn round_even(self) -> Self;
    /// The float whose bits are `f(bits(x))`, per lane.
    fn map_bits(self, f: impl Fn(u32) -> u32) -> Self;
    fn gt(self, other: Self) -> Self::Mask;
    fn lt(self, other: Self) -> Self::Mask;
    fn ge(self, other: Self) -> Self::Mask;
    fn le(self, other: Self) -> Self::Mask;
    /// `if m { a } else { b }` per lane.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// `x > lo ? (x < hi ? x : hi) : lo` per lane for `lo < hi` or both +0 (NaN → `lo`): the
    /// kernels' clamp to constant bounds ([`crate::common::math::clamp`]).
    fn clamp_between(self, lo: Self, hi: Self) -> Self;
    fn and(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    fn or(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    fn not(a: Self::Mask) -> Self::Mask;
    /// The same condition in every lane.
    fn mask_splat(b: bool) -> Self::Mask;
    /// Lane `i` of a condition.
    fn mask_lane(m: Self::Mask, i: usize) -> bool;
    /// Lane `i`'s texel.
    fn texel_lane(t: Self::U2, i: usize) -> UVec2;
    /// Is the condition true in any lane?
    fn any(m: Self::Mask) -> bool;
    /// The texel `(x, y)` per lane.
    fn texel(x: Self::Index, y: Self::Index) -> Self::U2;
    fn texel_x(t: Self::U2) -> Self::Index;
    fn texel_y(t: Self::U2) -> Self::Index;
    /// `i as f32` per lane.
    fn index_to_float(i: Self::Index) -> Self;
    fn index_eq(a: Self::Index, b: Self::Index) -> Self::Mask;
    /// `n` in every lane.
    fn index_splat(n: u32) -> Self::Index;
    /// `max(n ≫ k, 1)` per lane: the extent of MIP `k` (< 32) of an `n`-texel side.
    fn index_mip_extent(n: u32, k: Self::Index) -> Self::Index;
    /// `if m { a } else { b }` per lane.
    fn index_select(m: Self::Mask, a: Self::Index, b: Self::Index) -> Self::Index;
    /// `clamp(⌊self⌋, 0, n − 1)` per lane (NaN → 0), as [`clamp_index`] computes it: a
    /// clamp-to-edge texel coordinate, or a float rounded into an n-valued integer.
    fn floor_index(self, n: Self::Index) -> Self::Index;
    /// `clamp(i + d, 0, n − 1)` per lane (a clamp-to-edge neighbour's coordinate).
    fn index_offset_clamped(i: Self::Index, d: i32, n: u32) -> Self::Index;
    /// `data[i]` in each lane.
    fn gather_index(data: &[f32], i: Self::Index) -> Self;
    /// The word `data[i]` in each lane.
    fn gather_word(data: &[u32], i: Self::Index) -> Self::Index;
    /// `count` ones from bit `start` per lane, without any shift of 32 or more (undefined in
    /// SPIR-V, a panic in debug Rust): 0 where `start` ≥ 32 or `count` = 0, every bit from
    /// `start` where `count` ≥ 32.
    fn index_bit_run(start: Self::Index, count: Self::Index) -> Self::Index;
    /// The vector whose lane `i` is `f(i)`, one call of `f` per lane.
    fn v2_from_lanes(f: impl Fn(usize) -> Vec2) -> Self::V2;
    /// Lane `k` of an index.
    fn index_lane(i: Self::Index, k: usize) -> u32;
}

/// Do the lanes' texels `a` and `b` coincide?
#[inline]
pub fn texel_eq<L: Lanes>(a: L::U2, b: L::U2) -> L::Mask {
    L::and(L::index_eq(L::texel_x(a), L::texel_x(b)), L::index_eq(L::texel_y(a), L::texel_y(b)))
}

/// The row-major index `y·width + x` of each lane's texel.
#[inline]
pub fn row_major_index<L: Lanes>(p: L::U2, width: u32) -> L::Index {
    L::texel_y(p) * L::index_splat(width) + L::texel_x(p)
}

/// `if m { a } else { b }` per lane for vectors.
#[inline]
pub fn select_v3<L: Lanes>(m: L::Mask, a: L::V3, b: L::V3) -> L::V3 {
    L::V3::new(L::select(m, a.x(), b.x()), L::select(m, a.y(), b.y()), L::select(m, a.z(), b.z()))
}

/// Two lanes-valued components.
pub trait LaneVec2<L>: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<L, Output = Self> {
    fn new(x: L, y: L) -> Self;
    fn x(self) -> L;
    fn y(self) -> L;
    fn length(self) -> L;
}

/// Three lanes-valued components.
pub trait LaneVec3<L>:
    Copy + Add<Output = Self> + Sub<Output = Self> + Neg<Output = Self> + Mul<L, Output = Self> + Div<L, Output = Self>
{
    fn new(x: L, y: L, z: L) -> Self;
    fn x(self) -> L;
    fn y(self) -> L;
    fn z(self) -> L;
    fn dot(self, o: Self) -> L;
    fn cross(self, o: Self) -> Self;
    fn length(self) -> L;
    /// `v·(1/|v|)`.
    fn normalize(self) -> Self;
}

/// The f32 result of GLSL.std.450 extended instruction `$op` (a number of the GLSL.std.450
/// specification) applied to the f32 operands.
#[cfg(target_arch = "spirv")]
macro_rules! glsl_std_450 {
    ($op:literal, $($x:ident),+) => {{
        let mut r = 0.0f32;
        // SAFETY: a pure float operation that stores its result in `r`.
        unsafe {
            core::arch::asm!(
                "%glsl = OpExtInstImport \"GLSL.std.450\"",
                concat!("%r = OpExtInst typeof*{r} %glsl ", $op $(, " {", stringify!($x), "}")+),
                "OpStore {r} %r",
                $($x = in(reg) $x,)+
                r = in(reg) &mut r,
            );
        }
        r
    }};
}

impl Lanes for f32 {
    const LANES: usize = 1;
    type Mask = bool;
    type U2 = UVec2;
    type V2 = Vec2;
    type V3 = Vec3;
    type Index = u32;

    #[inline]
    fn splat(v: f32) -> Self {
        v
    }
    #[inline]
    fn from_lanes(f: impl Fn(usize) -> f32) -> Self {
        f(0)
    }
    #[inline]
    fn lane(self, _i: usize) -> f32 {
        self
    }
    #[inline]
    fn gather(data: &[f32], index: impl Fn(usize) -> usize) -> Self {
        data[index(0)]
    }
    #[inline]
    fn sqrt(self) -> Self {
        Float::sqrt(self)
    }
    #[inline]
    fn inverse_sqrt(self) -> Self {
        #[cfg(target_arch = "spirv")]
        let r = glsl_std_450!(32, self); // InverseSqrt
        #[cfg(not(target_arch = "spirv"))]
        let r = 1.0 / self.sqrt();
        r
    }
    #[inline]
    fn mul_add(self, a: f32, b: f32) -> f32 {
        #[cfg(target_arch = "spirv")]
        let r = glsl_std_450!(50, self, a, b); // Fma
        #[cfg(not(target_arch = "spirv"))]
        let r = f32::mul_add(self, a, b);
        r
    }
    #[inline]
    fn abs(self) -> Self {
        Float::abs(self)
    }
    /// IEEE 754 maxNum (a NaN operand gives the other) as a compare and a select: `f32::max`
    /// compiles to a branch per call through rust-gpu.
    #[inline]
    fn max(self, other: Self) -> Self {
        #[allow(clippy::eq_op)]
        let keep = (self > other) | (other != other);
        if keep { self } else { other }
    }
    /// IEEE 754 minNum, branch-free like [`Lanes::max`].
    #[inline]
    fn min(self, other: Self) -> Self {
        #[allow(clippy::eq_op)]
        let keep = (self < other) | (other != other);
        if keep { self } else { other }
    }
    #[inline]
    fn acos(self) -> Self {
        Float::acos(self)
    }
    #[inline]
    fn sin(self) -> Self {
        Float::sin(self)
    }
    #[inline]
    fn cos(self) -> Self {
        Float::cos(self)
    }
    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        (Float::sin(self), Float::cos(self))
    }
    #[inline]
    fn log2(self) -> Self {
        Float::log2(self)
    }
    #[inline]
    fn exp2(self) -> Self {
        Float::exp2(self)
    }
    #[inline]
    fn powf(self, p: f32) -> Self {
        Float::powf(self, p)
    }
    #[inline]
    fn floor(self) -> Self {
        crate::common::math::floor(self)
    }
    #[inline]
    fn round_even(self) -> Self {
        crate::common::denoise_terms::round_even(self)
    }
    #[inline]
    fn map_bits(self, f: impl Fn(u32) -> u32) -> Self {
        f32::from_bits(f(self.to_bits()))
    }
    #[inline]
    fn gt(self, other: Self) -> bool {
        self > other
    }
    #[inline]
    fn lt(self, other: Self) -> bool {
        self < other
    }
    #[inline]
    fn ge(self, other: Self) -> bool {
        self >= other
    }
    #[inline]
    fn le(self, other: Self) -> bool {
        self <= other
    }
    #[inline]
    fn select(m: bool, a: Self, b: Self) -> Self {
        if m { a } else { b }
    }
    /// [`crate::common::math::clamp_lanes`]'s compares and selects (branch-free on the GPU).
    #[inline]
    fn clamp_between(self, lo: f32, hi: f32) -> f32 {
        crate::common::math::clamp_lanes(self, lo, hi)
    }
    #[inline]
    fn and(a: bool, b: bool) -> bool {
        a && b
    }
    #[inline]
    fn or(a: bool, b: bool) -> bool {
        a || b
    }
    #[inline]
    fn not(a: bool) -> bool {
        !a
    }
    #[inline]
    fn mask_splat(b: bool) -> bool {
        b
    }
    #[inline]
    fn mask_lane(m: bool, _i: usize) -> bool {
        m
    }
    #[inline]
    fn texel_lane(t: UVec2, _i: usize) -> UVec2 {
        t
    }
    #[inline]
    fn any(m: bool) -> bool {
        m
    }
    #[inline]
    fn texel(x: u32, y: u32) -> UVec2 {
        UVec2::new(x, y)
    }
    #[inline]
    fn texel_x(t: UVec2) -> u32 {
        t.x
    }
    #[inline]
    fn texel_y(t: UVec2) -> u32 {
        t.y
    }
    #[inline]
    fn index_to_float(i: u32) -> f32 {
        crate::common::math::u32_to_f32(i)
    }
    #[inline]
    fn index_eq(a: u32, b: u32) -> bool {
        a == b
    }
    #[inline]
    fn index_splat(n: u32) -> u32 {
        n
    }
    #[inline]
    fn index_mip_extent(n: u32, k: u32) -> u32 {
        (n >> k).max(1)
    }
    #[inline]
    fn index_select(m: bool, a: u32, b: u32) -> u32 {
        if m { a } else { b }
    }
    #[inline]
    fn floor_index(self, n: u32) -> u32 {
        clamp_index(self, n)
    }
    #[inline]
    fn index_offset_clamped(i: u32, d: i32, n: u32) -> u32 {
        // max/min, not `clamp`: `clamp` asserts min ≤ max, a panic branch on the GPU.
        (i as i32 + d).max(0).min(n as i32 - 1) as u32
    }
    #[inline]
    fn gather_index(data: &[f32], i: u32) -> f32 {
        unsafe { crate::common::read::read(data, i as usize) }
    }
    #[inline]
    fn gather_word(data: &[u32], i: u32) -> u32 {
        unsafe { crate::common::read::read(data, i as usize) }
    }
    #[inline]
    fn index_bit_run(start: u32, count: u32) -> u32 {
        if start >= 32 || count == 0 {
            return 0;
        }
        let ones = if count >= 32 { 0xFFFF_FFFF } else { (1u32 << count) - 1 };
        ones << start
    }
    #[inline]
    fn v2_from_lanes(f: impl Fn(usize) -> Vec2) -> Vec2 {
        f(0)
    }
    #[inline]
    fn index_lane(i: u32, _k: usize) -> u32 {
        i
    }
}

impl LaneVec2<f32> for Vec2 {
    #[inline]
    fn new(x: f32, y: f32) -> Self {
        vec2(x, y)
    }
    #[inline]
    fn x(self) -> f32 {
        self.x
    }
    #[inline]
    fn y(self) -> f32 {
        self.y
    }
    #[inline]
    fn length(self) -> f32 {
        Vec2::length(self)
    }
}

impl LaneVec3<f32> for Vec3 {
    #[inline]
    fn new(x: f32, y: f32, z: f32) -> Self {
        vec3(x, y, z)
    }
    #[inline]
    fn x(self) -> f32 {
        self.x
    }
    #[inline]
    fn y(self) -> f32 {
        self.y
    }
    #[inline]
    fn z(self) -> f32 {
        self.z
    }
    #[inline]
    fn dot(self, o: Self) -> f32 {
        Vec3::dot(self, o)
    }
    #[inline]
    fn cross(self, o: Self) -> Self {
        Vec3::cross(self, o)
    }
    #[inline]
    fn length(self) -> f32 {
        Vec3::length(self)
    }
    #[inline]
    fn normalize(self) -> Self {
        Vec3::normalize(self)
    }
}

/// The vector whose lane `i` is `f(i)`.
#[inline(always)]
pub fn v3_from_lanes<L: Lanes>(f: impl Fn(usize) -> Vec3) -> L::V3 {
    L::V3::new(L::from_lanes(|i| f(i).x), L::from_lanes(|i| f(i).y), L::from_lanes(|i| f(i).z))
}

#[cfg(not(target_arch = "spirv"))]
pub use x16::{F32x16, U2x16, V2x16, V3x16};

/// The lanes cpu-sim runs every lane-generic kernel on: sixteen consecutive pixels of a row per
/// call. On x86-64-v3 (AVX2, the default build) an [`F32x16`] is two 256-bit vectors whose
/// operations are independent, so each half's long dependency chains (the polynomials of
/// `sin`/`acos`, the gathers, the divisions) overlap the other's: XeGTAO's main pass took about
/// 40 % less time than on eight lanes (one vector) on the benchmark host, single-threaded
/// (`docs/benchmarks.md`, "cpu-sim vs lavapipe").
#[cfg(not(target_arch = "spirv"))]
pub type CpuLanes = F32x16;

/// The number of pixels cpu-sim shades per call of a lane-generic kernel: `CpuLanes::LANES`
/// as a plain constant, for array lengths (`[bool; CPU_LANES]`) and loop steps.
#[cfg(not(target_arch = "spirv"))]
pub const CPU_LANES: usize = 16;

#[cfg(not(target_arch = "spirv"))]
const _: () = assert!(<CpuLanes as Lanes>::LANES == CPU_LANES);

/// `core::array::from_fn`, always inlined: `[f(0), f(1), …]` written as a loop the optimiser
/// unrolls. `from_fn` itself is not inlined at sixteen lanes, which left a call (and the vector
/// assembled through memory) in every gather of cpu-sim's kernels.
#[cfg(not(target_arch = "spirv"))]
#[inline(always)]
pub fn array_from_fn_inlined<T: Copy + Default, const N: usize>(f: impl Fn(usize) -> T) -> [T; N] {
    let mut out = [T::default(); N];
    for (i, o) in out.iter_mut().enumerate() {
        *o = f(i);
    }
    out
}

/// Sixteen lanes on the CPU over `wide`'s vectors: [`F32x16`] (one `f32` variable of sixteen
/// pixels), [`U2x16`] (texels), [`V2x16`], [`V3x16`]. Two 256-bit vectors with AVX2 (the default
/// build), four 128-bit ones on the x86-64 baseline, one 512-bit vector with AVX-512. The same
/// code over `f32x8`/`i32x8` with 8 lanes gives the eight-lane types that `docs/benchmarks.md`
/// compares against.
#[cfg(not(target_arch = "spirv"))]
mod x16 {
    use super::{LaneVec2, LaneVec3, Lanes};
    use crate::glam::{UVec2, Vec2};
    use core::ops::{Add, Div, Mul, Neg, Sub};
    use wide::{f32x16, i32x16};

    /// The values of one `f32` variable at sixteen pixels.
    #[derive(Copy, Clone, Debug, PartialEq)]
    pub struct F32x16(pub f32x16);

    macro_rules! binary {
        ($tr:ident, $method:ident, $op:tt) => {
            impl $tr for F32x16 {
                type Output = F32x16;
                #[inline(always)]
                fn $method(self, o: F32x16) -> F32x16 {
                    F32x16(self.0 $op o.0)
                }
            }
            impl $tr<f32> for F32x16 {
                type Output = F32x16;
                #[inline(always)]
                fn $method(self, o: f32) -> F32x16 {
                    F32x16(self.0 $op f32x16::splat(o))
                }
            }
        };
    }
    binary!(Add, add, +);
    binary!(Sub, sub, -);
    binary!(Mul, mul, *);
    binary!(Div, div, /);

    impl Neg for F32x16 {
        type Output = F32x16;
        #[inline(always)]
        fn neg(self) -> F32x16 {
            F32x16(-self.0)
        }
    }

    impl Lanes for F32x16 {
        const LANES: usize = 16;
        type Mask = f32x16;
        type U2 = U2x16;
        type V2 = V2x16;
        type V3 = V3x16;
        type Index = i32x16;

        #[inline(always)]
        fn splat(v: f32) -> Self {
            F32x16(f32x16::splat(v))
        }
        #[inline(always)]
        fn from_lanes(f: impl Fn(usize) -> f32) -> Self {
            F32x16(f32x16::new(crate::common::lanes::array_from_fn_inlined(f)))
        }
        #[inline(always)]
        fn lane(self, i: usize) -> f32 {
            self.0.as_array()[i]
        }
        #[inline(always)]
        fn gather(data: &[f32], index: impl Fn(usize) -> usize) -> Self {
            F32x16(f32x16::new(crate::common::lanes::array_from_fn_inlined(|i| data[index(i)])))
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            F32x16(self.0.sqrt())
        }
        /// `vfmadd` where the build targets FMA (x86-64-v3, the default); elsewhere the
        /// scalar fused multiply-add per lane (`wide` would round twice), so one rounding
        /// either way, as the scalar version.
        #[inline(always)]
        fn mul_add(self, a: Self, b: Self) -> Self {
            #[cfg(target_feature = "fma")]
            let r = F32x16(self.0.mul_add(a.0, b.0));
            #[cfg(not(target_feature = "fma"))]
            let r = {
                let (x, a, b) = (self.0.to_array(), a.0.to_array(), b.0.to_array());
                F32x16(f32x16::new(crate::common::lanes::array_from_fn_inlined(|i| x[i].mul_add(a[i], b[i]))))
            };
            r
        }
        /// `vrsqrtps` (relative error ≤ 1.5·2⁻¹²) and one Newton–Raphson step
        /// `y·(1.5 − 0.5·x·y²)`: a few ulp, without the square root's and the division's
        /// latency. Where the step has no meaning (x = ±0 or +∞, and subnormal x, which
        /// `vrsqrtps` takes as 0) the estimate ±∞ or +0 stands, as `1/√x` gives it (but ∞ for a
        /// subnormal x).
        #[inline(always)]
        fn inverse_sqrt(self) -> Self {
            let y = self.0.recip_sqrt();
            let refined = y * (f32x16::splat(1.5) - f32x16::splat(0.5) * self.0 * y * y);
            let exact_estimate = y.simd_eq(f32x16::ZERO) | y.abs().simd_eq(f32x16::splat(f32::INFINITY));
            F32x16(wide::Select::select(exact_estimate, y, refined))
        }
        #[inline(always)]
        fn abs(self) -> Self {
            F32x16(self.0.abs())
        }
        #[inline(always)]
        fn max(self, o: Self) -> Self {
            F32x16(self.0.max(o.0))
        }
        #[inline(always)]
        fn min(self, o: Self) -> Self {
            F32x16(self.0.min(o.0))
        }
        #[inline(always)]
        fn acos(self) -> Self {
            F32x16(self.0.acos())
        }
        #[inline(always)]
        fn sin(self) -> Self {
            F32x16(self.0.sin_cos().0)
        }
        #[inline(always)]
        fn cos(self) -> Self {
            F32x16(self.0.sin_cos().1)
        }
        #[inline(always)]
        fn sin_cos(self) -> (Self, Self) {
            let (s, c) = self.0.sin_cos();
            (F32x16(s), F32x16(c))
        }
        #[inline(always)]
        fn exp2(self) -> Self {
            F32x16(self.0.exp2())
        }
        #[inline(always)]
        fn log2(self) -> Self {
            F32x16(self.0.ln() * f32x16::splat(core::f32::consts::LOG2_E))
        }
        #[inline(always)]
        fn powf(self, p: f32) -> Self {
            F32x16(self.0.powf_simd(f32x16::splat(p)))
        }
        #[inline(always)]
        fn floor(self) -> Self {
            F32x16(self.0.floor())
        }
        #[inline(always)]
        fn round_even(self) -> Self {
            F32x16(self.0.round_ties_even())
        }
        #[inline(always)]
        fn map_bits(self, f: impl Fn(u32) -> u32) -> Self {
            let a = self.0.to_array();
            F32x16(f32x16::new(crate::common::lanes::array_from_fn_inlined(|i| f32::from_bits(f(a[i].to_bits())))))
        }
        #[inline(always)]
        fn gt(self, o: Self) -> f32x16 {
            self.0.simd_gt(o.0)
        }
        #[inline(always)]
        fn lt(self, o: Self) -> f32x16 {
            self.0.simd_lt(o.0)
        }
        #[inline(always)]
        fn ge(self, o: Self) -> f32x16 {
            self.0.simd_ge(o.0)
        }
        #[inline(always)]
        fn le(self, o: Self) -> f32x16 {
            self.0.simd_le(o.0)
        }
        #[inline(always)]
        fn select(m: f32x16, a: Self, b: Self) -> Self {
            // `vblendvps` (one instruction); the masks are whole lanes of ones or zeros, so it
            // picks as `bitselect`'s and/andnot/or would.
            F32x16(wide::Select::select(m, a.0, b.0))
        }
        /// On x86-64 `minps(maxps(x, lo), hi)`: `maxps` returns its second operand for a NaN
        /// or equal pair, so NaN → lo and x = lo → lo (±0 included), then `minps` keeps x below
        /// hi and returns hi for x = hi: the compares-and-selects' value, bit for bit, in two
        /// instructions. Elsewhere (`wide`'s `fast_max` propagates NaN on aarch64) the compares
        /// and selects.
        #[inline(always)]
        fn clamp_between(self, lo: Self, hi: Self) -> Self {
            #[cfg(target_arch = "x86_64")]
            let c = F32x16(self.0.fast_max(lo.0).fast_min(hi.0));
            #[cfg(not(target_arch = "x86_64"))]
            let c = crate::common::math::clamp_lanes(self, lo, hi);
            c
        }
        #[inline(always)]
        fn and(a: f32x16, b: f32x16) -> f32x16 {
            a & b
        }
        #[inline(always)]
        fn or(a: f32x16, b: f32x16) -> f32x16 {
            a | b
        }
        #[inline(always)]
        fn not(a: f32x16) -> f32x16 {
            !a
        }
        #[inline(always)]
        fn mask_splat(b: bool) -> f32x16 {
            f32x16::splat(if b { f32::from_bits(u32::MAX) } else { 0.0 })
        }
        #[inline(always)]
        fn mask_lane(m: f32x16, i: usize) -> bool {
            m.as_array()[i].to_bits() != 0
        }
        #[inline(always)]
        fn texel_lane(t: U2x16, i: usize) -> UVec2 {
            UVec2::new(t.x.as_array()[i] as u32, t.y.as_array()[i] as u32)
        }
        #[inline(always)]
        fn any(m: f32x16) -> bool {
            m.any()
        }
        #[inline(always)]
        fn texel(x: i32x16, y: i32x16) -> U2x16 {
            U2x16 { x, y }
        }
        #[inline(always)]
        fn texel_x(t: U2x16) -> i32x16 {
            t.x
        }
        #[inline(always)]
        fn texel_y(t: U2x16) -> i32x16 {
            t.y
        }
        #[inline(always)]
        fn index_to_float(i: i32x16) -> Self {
            F32x16(i.round_float())
        }
        #[inline(always)]
        fn index_eq(a: i32x16, b: i32x16) -> f32x16 {
            bytemuck::cast::<i32x16, f32x16>(a.simd_eq(b))
        }
        #[inline(always)]
        fn index_splat(n: u32) -> i32x16 {
            i32x16::splat(n as i32)
        }
        #[inline(always)]
        fn index_mip_extent(n: u32, k: i32x16) -> i32x16 {
            i32x16::splat(n as i32).unbounded_shr(bytemuck::cast(k)).max(i32x16::splat(1))
        }
        #[inline(always)]
        fn index_select(m: f32x16, a: i32x16, b: i32x16) -> i32x16 {
            wide::Select::<i32x16>::select(m, a, b)
        }
        /// `maxps(x, 0)` takes 0 for a NaN `x`; clamped below `n`, the truncation is exact.
        #[inline(always)]
        fn floor_index(self, n: i32x16) -> i32x16 {
            let last = (n - i32x16::splat(1)).round_float();
            self.0.fast_max(f32x16::ZERO).fast_min(last).fast_trunc_int()
        }
        #[inline(always)]
        fn index_offset_clamped(i: i32x16, d: i32, n: u32) -> i32x16 {
            (i + i32x16::splat(d)).max(i32x16::ZERO).min(i32x16::splat(n as i32 - 1))
        }
        /// AVX2's variable shifts give 0 for shifts of 32 or more, so `(1 ≪ count) − 1` is all
        /// ones for count = 32.
        #[inline(always)]
        fn index_bit_run(start: i32x16, count: i32x16) -> i32x16 {
            let one = i32x16::splat(1);
            let ones = one.unbounded_shl(bytemuck::cast(count)) - one;
            ones.unbounded_shl(bytemuck::cast(start))
        }
        #[inline(always)]
        fn v2_from_lanes(f: impl Fn(usize) -> Vec2) -> V2x16 {
            let v: [Vec2; 16] = crate::common::lanes::array_from_fn_inlined(f);
            V2x16 { x: F32x16::from_lanes(|i| v[i].x), y: F32x16::from_lanes(|i| v[i].y) }
        }
        #[inline(always)]
        fn index_lane(i: i32x16, k: usize) -> u32 {
            i.as_array()[k] as u32
        }
        #[inline(always)]
        fn gather_word(data: &[u32], i: i32x16) -> i32x16 {
            bytemuck::cast(gather_lanes(data, i))
        }
        #[inline(always)]
        fn gather_index(data: &[f32], i: i32x16) -> Self {
            F32x16(f32x16::new(gather_lanes(data, i)))
        }
    }

    /// `data[i]` for each lane's index (a panic where one is outside `data`, as indexing).
    /// Consecutive indices `k, k + 1, …` in every lane — a row of pixels — are one load after
    /// one compare of the vector; others are one load per lane.
    #[inline(always)]
    fn gather_lanes<T: Copy + Default>(data: &[T], i: i32x16) -> [T; 16] {
        let first = i.as_array()[0];
        let run = i32x16::splat(first) + i32x16::new(crate::common::lanes::array_from_fn_inlined(|k| k as i32));
        let consecutive = first >= 0 && bytemuck::cast::<i32x16, f32x16>(run.simd_eq(i)).all();
        if let Some(row) = consecutive.then(|| data.get(first as usize..first as usize + 16)).flatten() {
            return row.try_into().expect("a full row of lanes");
        }
        let i = i.to_array();
        crate::common::lanes::array_from_fn_inlined(|k| data[i[k] as usize])
    }

    /// Sixteen texels (or pixels).
    #[derive(Copy, Clone, Debug, PartialEq)]
    pub struct U2x16 {
        pub x: i32x16,
        pub y: i32x16,
    }

    impl U2x16 {
        /// Lane `i` from `each[i]`.
        #[inline(always)]
        pub fn from_texels(each: &[UVec2; 16]) -> Self {
            U2x16 {
                x: i32x16::new(crate::common::lanes::array_from_fn_inlined(|k| each[k].x as i32)),
                y: i32x16::new(crate::common::lanes::array_from_fn_inlined(|k| each[k].y as i32)),
            }
        }
    }

    /// Sixteen `Vec2`s.
    #[derive(Copy, Clone, Debug)]
    pub struct V2x16 {
        pub x: F32x16,
        pub y: F32x16,
    }

    impl Add for V2x16 {
        type Output = Self;
        #[inline(always)]
        fn add(self, o: Self) -> Self {
            V2x16 { x: self.x + o.x, y: self.y + o.y }
        }
    }
    impl Sub for V2x16 {
        type Output = Self;
        #[inline(always)]
        fn sub(self, o: Self) -> Self {
            V2x16 { x: self.x - o.x, y: self.y - o.y }
        }
    }
    impl Mul<F32x16> for V2x16 {
        type Output = Self;
        #[inline(always)]
        fn mul(self, s: F32x16) -> Self {
            V2x16 { x: self.x * s, y: self.y * s }
        }
    }
    impl LaneVec2<F32x16> for V2x16 {
        #[inline(always)]
        fn new(x: F32x16, y: F32x16) -> Self {
            V2x16 { x, y }
        }
        #[inline(always)]
        fn x(self) -> F32x16 {
            self.x
        }
        #[inline(always)]
        fn y(self) -> F32x16 {
            self.y
        }
        #[inline(always)]
        fn length(self) -> F32x16 {
            (self.x * self.x + self.y * self.y).sqrt()
        }
    }

    /// Sixteen `Vec3`s.
    #[derive(Copy, Clone, Debug)]
    pub struct V3x16 {
        pub x: F32x16,
        pub y: F32x16,
        pub z: F32x16,
    }

    impl Add for V3x16 {
        type Output = Self;
        #[inline(always)]
        fn add(self, o: Self) -> Self {
            V3x16 { x: self.x + o.x, y: self.y + o.y, z: self.z + o.z }
        }
    }
    impl Sub for V3x16 {
        type Output = Self;
        #[inline(always)]
        fn sub(self, o: Self) -> Self {
            V3x16 { x: self.x - o.x, y: self.y - o.y, z: self.z - o.z }
        }
    }
    impl Neg for V3x16 {
        type Output = Self;
        #[inline(always)]
        fn neg(self) -> Self {
            V3x16 { x: -self.x, y: -self.y, z: -self.z }
        }
    }
    impl Mul<F32x16> for V3x16 {
        type Output = Self;
        #[inline(always)]
        fn mul(self, s: F32x16) -> Self {
            V3x16 { x: self.x * s, y: self.y * s, z: self.z * s }
        }
    }
    impl Div<F32x16> for V3x16 {
        type Output = Self;
        #[inline(always)]
        fn div(self, s: F32x16) -> Self {
            V3x16 { x: self.x / s, y: self.y / s, z: self.z / s }
        }
    }
    impl LaneVec3<F32x16> for V3x16 {
        #[inline(always)]
        fn new(x: F32x16, y: F32x16, z: F32x16) -> Self {
            V3x16 { x, y, z }
        }
        #[inline(always)]
        fn x(self) -> F32x16 {
            self.x
        }
        #[inline(always)]
        fn y(self) -> F32x16 {
            self.y
        }
        #[inline(always)]
        fn z(self) -> F32x16 {
            self.z
        }
        #[inline(always)]
        fn dot(self, o: Self) -> F32x16 {
            self.x * o.x + self.y * o.y + self.z * o.z
        }
        #[inline(always)]
        fn cross(self, o: Self) -> Self {
            V3x16 { x: self.y * o.z - o.y * self.z, y: self.z * o.x - o.z * self.x, z: self.x * o.y - o.x * self.y }
        }
        #[inline(always)]
        fn length(self) -> F32x16 {
            self.dot(self).sqrt()
        }
        #[inline(always)]
        fn normalize(self) -> Self {
            self * (F32x16::splat(1.0) / self.length())
        }
    }
}
