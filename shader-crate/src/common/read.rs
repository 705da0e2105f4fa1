//! Storage-buffer reads and writes without a bounds check on the GPU.
//!
//! rust-gpu keeps Rust's bounds check on every slice index: a compare and a branch to the entry
//! point's silent exit (`ShaderPanicStrategy::SilentExit`) per read, which made XeGTAO's main
//! pass four times the basic blocks of Intel's own shader (issue 26). The kernels' indexes are in
//! range by construction (pixel and texel coordinates clamped to the image, row-major with the
//! image's width, buffers of the full target's size), so on SPIR-V `read` and `write` index
//! unchecked. On the CPU they stay checked, and cpu-sim's lane kernels index with the same
//! formulas through checked slice indexing: the CPU tests (exhaustive, agreement, fuzz) panic on
//! an index out of range. What the GPU no longer does is exit silently when an engine binds a
//! buffer smaller than the target (`assets/README.md` states the sizes).

/// `data[i]` (checked on the CPU only).
///
/// # Safety
/// `i < data.len()`: on SPIR-V a larger index reads outside the buffer.
#[inline(always)]
pub(crate) unsafe fn read<T: Copy>(data: &[T], i: usize) -> T {
    #[cfg(target_arch = "spirv")]
    {
        use spirv_std::arch::IndexUnchecked;
        // SAFETY: the caller keeps `i` in range (see the module docs); the CPU build of the
        // same code checks every index.
        unsafe { *data.index_unchecked(i) }
    }
    #[cfg(not(target_arch = "spirv"))]
    {
        data[i]
    }
}

/// `data[i] = value` (checked on the CPU only).
///
/// # Safety
/// `i < data.len()`: on SPIR-V a larger index writes outside the buffer.
#[inline(always)]
pub(crate) unsafe fn write<T: Copy>(data: &mut [T], i: usize, value: T) {
    #[cfg(target_arch = "spirv")]
    {
        use spirv_std::arch::IndexUnchecked;
        // SAFETY: as for `read`.
        unsafe { *data.index_unchecked_mut(i) = value }
    }
    #[cfg(not(target_arch = "spirv"))]
    {
        data[i] = value;
    }
}

/// A buffer of `f32` texels that the invocations of one dispatch read and write at disjoint
/// indices, possibly side by side: a storage buffer on SPIR-V (`&mut [f32]`, unchecked as
/// `read`), `&[AtomicU32]` with relaxed accesses (plain moves) on the CPU, where cpu-sim runs
/// the same invocations on several threads.
pub trait TexelBuffer {
    /// The texel at `i`.
    fn load(&self, i: usize) -> f32;
    /// Writes `value` at `i`.
    fn store(&mut self, i: usize, value: f32);
}

impl TexelBuffer for &mut [f32] {
    #[inline(always)]
    fn load(&self, i: usize) -> f32 {
        // SAFETY: the kernels index in range (module docs); checked on the CPU.
        unsafe { read(self, i) }
    }
    #[inline(always)]
    fn store(&mut self, i: usize, value: f32) {
        // SAFETY: as for `load`.
        unsafe { write(self, i, value) }
    }
}

#[cfg(not(target_arch = "spirv"))]
impl TexelBuffer for &[core::sync::atomic::AtomicU32] {
    #[inline(always)]
    fn load(&self, i: usize) -> f32 {
        f32::from_bits(self[i].load(core::sync::atomic::Ordering::Relaxed))
    }
    #[inline(always)]
    fn store(&mut self, i: usize, value: f32) {
        self[i].store(value.to_bits(), core::sync::atomic::Ordering::Relaxed)
    }
}
