//! Storage-buffer reads and writes without a bounds check on the GPU.
//!
//! rust-gpu keeps Rust's bounds check on every slice index: a compare and a branch to the entry
//! point's silent exit (`ShaderPanicStrategy::SilentExit`) per read, which made XeGTAO's main
//! pass four times the basic blocks of Intel's own shader (issue 26). The kernels' indexes are in
//! range by construction (pixel and texel coordinates clamped to the image, row-major with the
//! image's width), so on SPIR-V [`read`] indexes unchecked. On the CPU it stays checked: every
//! CPU test (exhaustive, agreement, fuzz) would panic on an index out of range, which is what
//! keeps the unchecked GPU read honest.

/// `data[i]`, for an `i` the caller keeps below `data.len()` (checked on the CPU only).
#[inline(always)]
pub fn read<T: Copy>(data: &[T], i: usize) -> T {
    #[cfg(target_arch = "spirv")]
    {
        use spirv_std::arch::IndexUnchecked;
        // SAFETY: the kernels index within the buffers they are given (see the module docs);
        // the CPU build of the same code checks every index.
        unsafe { *data.index_unchecked(i) }
    }
    #[cfg(not(target_arch = "spirv"))]
    {
        data[i]
    }
}

/// `data[i] = value`, for an `i` the caller keeps below `data.len()` (checked on the CPU only).
#[inline(always)]
pub fn write<T: Copy>(data: &mut [T], i: usize, value: T) {
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
