//! One wrapper per atomic operation: `spirv_std::arch` on SPIR-V, `AtomicU32` on the CPU
//! (design: "GPU-only intrinsics behind one-line wrappers").

/// A buffer of `u32` that supports atomic min/max at an index. The SPIR-V entry points implement
/// it for `&mut [u32]` storage buffers, the CPU simulator for `&[AtomicU32]`.
pub trait AtomicU32Buffer {
    /// `slot[i] = min(slot[i], v)`; returns the previous value.
    fn atomic_min(&mut self, i: usize, v: u32) -> u32;
    /// `slot[i] = max(slot[i], v)`; returns the previous value.
    fn atomic_max(&mut self, i: usize, v: u32) -> u32;
    /// `slot[i] = slot[i] + v` (wrapping); returns the previous value.
    fn atomic_add(&mut self, i: usize, v: u32) -> u32;
    /// A relaxed read of `slot[i]` (possibly stale): lets a caller skip an atomic min/max the
    /// value already satisfies (values only move one way, so a stale read only costs an atomic).
    fn peek(&self, i: usize) -> u32;
}

/// Add `n` rays to a 64-bit ray counter held as two `u32` words (low, high): the invocation
/// whose addition wraps the low word carries one into the high word, so concurrent additions
/// sum exactly. What every ray-traced kernel does with the rays it traced.
#[inline]
pub fn count_rays<B: AtomicU32Buffer>(counter: &mut B, n: u32) {
    if n == 0 {
        return;
    }
    let old = counter.atomic_add(0, n);
    if old.wrapping_add(n) < old {
        counter.atomic_add(1, 1);
    }
}

/// Device-scope atomics on a storage buffer. Natively (where the entry points also compile) the
/// exclusive borrow makes plain min/max equivalent.
impl AtomicU32Buffer for &mut [u32] {
    #[cfg(not(target_arch = "spirv"))]
    fn peek(&self, i: usize) -> u32 {
        self[i]
    }
    /// An atomic load (relaxed, device scope): other invocations write the slot concurrently,
    /// and a plain load racing with their atomics has no defined value in Vulkan's memory model.
    #[cfg(target_arch = "spirv")]
    fn peek(&self, i: usize) -> u32 {
        use spirv_std::memory::{Scope, Semantics};
        unsafe { spirv_std::arch::atomic_load::<u32, { Scope::Device as u32 }, { Semantics::NONE.bits() }>(&self[i]) }
    }
    #[cfg(not(target_arch = "spirv"))]
    fn atomic_min(&mut self, i: usize, v: u32) -> u32 {
        let old = self[i];
        self[i] = old.min(v);
        old
    }
    #[cfg(not(target_arch = "spirv"))]
    fn atomic_max(&mut self, i: usize, v: u32) -> u32 {
        let old = self[i];
        self[i] = old.max(v);
        old
    }
    #[cfg(not(target_arch = "spirv"))]
    fn atomic_add(&mut self, i: usize, v: u32) -> u32 {
        let old = self[i];
        self[i] = old.wrapping_add(v);
        old
    }
    #[cfg(target_arch = "spirv")]
    fn atomic_min(&mut self, i: usize, v: u32) -> u32 {
        use spirv_std::memory::{Scope, Semantics};
        unsafe {
            spirv_std::arch::atomic_u_min::<u32, { Scope::Device as u32 }, { Semantics::NONE.bits() }>(&mut self[i], v)
        }
    }
    #[cfg(target_arch = "spirv")]
    fn atomic_max(&mut self, i: usize, v: u32) -> u32 {
        use spirv_std::memory::{Scope, Semantics};
        unsafe {
            spirv_std::arch::atomic_u_max::<u32, { Scope::Device as u32 }, { Semantics::NONE.bits() }>(&mut self[i], v)
        }
    }
    #[cfg(target_arch = "spirv")]
    fn atomic_add(&mut self, i: usize, v: u32) -> u32 {
        use spirv_std::memory::{Scope, Semantics};
        unsafe {
            spirv_std::arch::atomic_i_add::<u32, { Scope::Device as u32 }, { Semantics::NONE.bits() }>(&mut self[i], v)
        }
    }
}

#[cfg(not(target_arch = "spirv"))]
impl AtomicU32Buffer for &[core::sync::atomic::AtomicU32] {
    fn peek(&self, i: usize) -> u32 {
        self[i].load(core::sync::atomic::Ordering::Relaxed)
    }
    fn atomic_min(&mut self, i: usize, v: u32) -> u32 {
        self[i].fetch_min(v, core::sync::atomic::Ordering::Relaxed)
    }
    fn atomic_max(&mut self, i: usize, v: u32) -> u32 {
        self[i].fetch_max(v, core::sync::atomic::Ordering::Relaxed)
    }
    fn atomic_add(&mut self, i: usize, v: u32) -> u32 {
        self[i].fetch_add(v, core::sync::atomic::Ordering::Relaxed)
    }
}
