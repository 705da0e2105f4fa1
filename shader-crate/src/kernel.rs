//! Entry points as data (host side): what each kernel's signature declares — stage, workgroup
//! size, push-constant struct and, per binding, slot, name, Rust type, kind and access.
//!
//! Every entry point carries `#[crate::kernel]` above its `#[spirv(…)]` attribute. The attribute
//! (`aokit-contract-derive`) reads the parameters and generates, beside the function, a module
//! of the same name holding:
//!
//! - `ENTRY`, the entry point's [`Kernel`] (also listed in [`KERNELS`]);
//! - one typed [`Slot`] constant per binding (`vao_main::DEPTH: Slot<f32>`), which the CPU
//!   drivers read and write through ([`KernelIo`]);
//! - `Bindings`, a struct with one field per binding naming the graph resource bound there: a
//!   graph that forgets a binding or names one the kernel lacks does not compile, and slots and
//!   accesses come from the signature ([`EntryBindings`]);
//! - for compute kernels whose parameters are only the invocation id, push constants and
//!   storage buffers, a CPU driver that calls the entry point itself once per invocation
//!   ([`Kernel::cpu`]), so a new screen-space kernel runs on the CPU without any other code.
//!
//! So a binding is written once — in the kernel's parameter list — and the graph, both
//! executors, the manifest and the contract's struct list ([`crate::contract::shared_structs`])
//! read it from there.
//!
//! Access is the parameter's mutability: `&[T]` is read, `&mut [T]` written; a `&mut [T]` that
//! the kernel also reads (accumulation, atomics) carries `#[read_write]`. A storage image is
//! written when its type says `sampled = false`.

use crate::contract::StructLayout;
use crate::graph::{Access, Binding};

/// The pipeline stage of an entry point.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Stage {
    Compute,
    Vertex,
    Fragment,
    RayGeneration,
    Miss,
    AnyHit,
}

impl Stage {
    /// The name the manifest uses (`compute`, `ray_generation`, …).
    pub fn name(self) -> &'static str {
        match self {
            Stage::Compute => "compute",
            Stage::Vertex => "vertex",
            Stage::Fragment => "fragment",
            Stage::RayGeneration => "ray_generation",
            Stage::Miss => "miss",
            Stage::AnyHit => "any_hit",
        }
    }
}

/// A type's layout as a shared struct (`crate::contract::Layout::layout`); `None` for plain
/// types.
pub type LayoutOf = fn() -> Option<StructLayout>;

/// What a binding is.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum BindingKind {
    /// A storage buffer of elements of the declared type.
    StorageBuffer,
    /// A sampled or storage image.
    Image,
    /// The scene's top-level acceleration structure.
    AccelerationStructure,
}

/// One binding of descriptor set 0 as the entry point declares it.
#[derive(Copy, Clone, Debug)]
pub struct BindingDecl {
    pub slot: u32,
    /// The parameter's name.
    pub name: &'static str,
    /// The parameter's type without the reference and paths (`[f32]`, `[SvaoFrame]`,
    /// `AccelerationStructure`, `Image!(2D,type=f32,sampled)`).
    pub rust_type: &'static str,
    pub kind: BindingKind,
    pub access: Access,
    /// The element's layout where a storage buffer holds records of a shared struct.
    pub element: LayoutOf,
}

/// A specialization constant of an entry point, `#[spirv(spec_constant(id = N))] name: u32`
/// (default 0). The one named [`SPECIALIZED`] is 0 unless an executor fixes the others at
/// pipeline creation, when it is 1; every other one is named after a field of the push-constant
/// struct (found in nested structs too) and then holds that field's 4 bytes, so a driver folds
/// what the push constants would otherwise say at every dispatch (loop counts, modes, exponents).
/// Left at 0 (cpu-sim, WGSL overrides at their defaults) the kernel reads its push constants:
/// the result is the same either way.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct SpecConstantDecl {
    /// The `SpecId`.
    pub id: u32,
    /// The parameter's name: [`SPECIALIZED`] or a push-constant field.
    pub name: &'static str,
}

/// The specialization constant that switches the others on (see [`SpecConstantDecl`]).
pub const SPECIALIZED: &str = "specialized";

/// An entry point as its signature declares it.
#[derive(Debug)]
pub struct Kernel {
    /// The SPIR-V entry point (and module) name.
    pub entry: &'static str,
    pub stage: Stage,
    /// Workgroup size (compute); `[1, 1, 1]` for other stages.
    pub threads: [u32; 3],
    /// The push-constant struct's name and layout.
    pub push_constants: Option<(&'static str, LayoutOf)>,
    /// In slot order.
    pub bindings: &'static [BindingDecl],
    /// Its specialization constants, in the order declared (see [`SpecConstantDecl`]).
    pub specialization: &'static [SpecConstantDecl],
    /// Runs a dispatch of `[x, y]` invocations on the CPU, calling the entry point itself once
    /// per invocation id over the bindings of [`KernelIo`]: generated for compute kernels that
    /// take only the invocation id, push constants and storage buffers.
    pub cpu: Option<fn(&mut dyn KernelIo, [u32; 2])>,
}

impl Kernel {
    /// The declared binding at `slot`.
    pub fn binding(&self, slot: u32) -> Option<&BindingDecl> {
        self.bindings.iter().find(|b| b.slot == slot)
    }

    /// Size in bytes of the push-constant block (0 without one).
    pub fn push_constant_bytes(&self) -> u32 {
        self.push_constants.and_then(|(_, layout)| layout()).map_or(0, |l| l.size as u32)
    }

    /// `(SpecId, value)` of each specialization constant for a dispatch with push constants
    /// `push`: [`SPECIALIZED`] is 1, every other one the 4 bytes of its push-constant field (see
    /// [`SpecConstantDecl`]). Empty when the kernel declares none; an executor makes one pipeline
    /// per distinct list.
    pub fn specialization_for(&self, push: &[u8]) -> Result<Vec<(u32, u32)>, String> {
        if self.specialization.is_empty() {
            return Ok(Vec::new());
        }
        let layout = self.push_constants.and_then(|(_, layout)| layout());
        self.specialization
            .iter()
            .map(|c| {
                if c.name == SPECIALIZED {
                    return Ok((c.id, 1));
                }
                let offset = layout.as_ref().and_then(|l| field_offset(l, c.name)).ok_or_else(|| {
                    format!("'{}': spec constant {} names no 4-byte push-constant field", self.entry, c.name)
                })?;
                let bytes = push.get(offset..offset + 4).ok_or_else(|| {
                    format!(
                        "'{}': {} push-constant bytes, spec constant {} reads {offset}..",
                        self.entry,
                        push.len(),
                        c.name
                    )
                })?;
                Ok((c.id, u32::from_le_bytes(bytes.try_into().expect("4 bytes"))))
            })
            .collect()
    }

    /// One past the highest binding slot: the length of the descriptor-set layout.
    pub fn slot_count(&self) -> u32 {
        self.bindings.iter().map(|b| b.slot + 1).max().unwrap_or(0)
    }

    /// The kernel called `entry`.
    pub fn find(entry: &str) -> Option<&'static Kernel> {
        KERNELS.iter().copied().find(|k| k.entry == entry)
    }

    /// Every kernel, sorted by entry name.
    pub fn all() -> Vec<&'static Kernel> {
        let mut all: Vec<&'static Kernel> = KERNELS.to_vec();
        all.sort_by_key(|k| k.entry);
        all
    }
}

impl PartialEq for Kernel {
    /// Entry names are unique ([`KERNELS`] is checked for it), so a kernel is its name.
    fn eq(&self, other: &Kernel) -> bool {
        self.entry == other.entry
    }
}

/// Byte offset of the 4-byte field `name` in `layout` or in a struct nested in it (depth first).
fn field_offset(layout: &StructLayout, name: &str) -> Option<usize> {
    layout.fields.iter().find_map(|f| match (f.name == name && f.size == 4, (f.nested)()) {
        (true, _) => Some(f.offset),
        (false, Some(nested)) => field_offset(&nested, name).map(|o| f.offset + o),
        (false, None) => None,
    })
}

/// The element layout of a binding that is no storage buffer.
pub fn no_layout() -> Option<StructLayout> {
    None
}

/// Every entry point of the crate: each `#[crate::kernel]` adds its own (collected at link time,
/// so no list is written by hand).
#[linkme::distributed_slice]
pub static KERNELS: [&'static Kernel];

/// The element type of a slot that is no storage buffer (an image, the acceleration structure):
/// nothing the CPU can read or write through it.
#[derive(Copy, Clone, Debug)]
pub enum Opaque {}

/// A binding slot whose storage buffer holds `T` ([`Opaque`] for images and acceleration
/// structures).
pub struct Slot<T> {
    pub slot: u32,
    _element: core::marker::PhantomData<fn() -> T>,
}

impl<T> Slot<T> {
    pub const fn new(slot: u32) -> Self {
        Slot { slot, _element: core::marker::PhantomData }
    }
}

impl<T> Clone for Slot<T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for Slot<T> {}

/// The generated `Bindings` struct of an entry point: which graph resource each of its bindings
/// is.
pub trait EntryBindings {
    /// The entry point's declaration.
    fn declaration(&self) -> &'static Kernel;
    /// The resources in the order of [`Kernel::bindings`].
    fn resources(&self) -> Vec<&'static str>;

    /// The graph's bindings: each resource at its declared slot with its declared access.
    fn slots(&self) -> Vec<Binding> {
        self.declaration()
            .bindings
            .iter()
            .zip(self.resources())
            .map(|(decl, resource)| Binding { slot: decl.slot, resource, access: decl.access })
            .collect()
    }
}

/// A CPU executor's view of one pass's bindings, as the generated CPU drivers use it.
pub trait KernelIo {
    /// The push-constant bytes, the words of each slot of `reads` (read-only bindings) and of
    /// each slot of `writes` (written bindings), in the order asked.
    fn buffers(&mut self, reads: &[u32], writes: &[u32]) -> (&[u8], Vec<&[u32]>, Vec<&mut [u32]>);
}

/// Support for the generated CPU drivers.
pub mod cpu {
    /// The push constants as `T`.
    pub fn push<T: bytemuck::Pod>(bytes: &[u8]) -> T {
        bytemuck::pod_read_unaligned(&bytes[..size_of::<T>()])
    }

    /// A read-only buffer as `T`s: borrowed where the words are aligned for `T`, copied
    /// otherwise (records with 16-byte vectors).
    pub fn read<T: bytemuck::Pod>(words: &[u32]) -> std::borrow::Cow<'_, [T]> {
        let bytes: &[u8] = bytemuck::cast_slice(words);
        let whole = bytes.len() / size_of::<T>() * size_of::<T>();
        match bytemuck::try_cast_slice(&bytes[..whole]) {
            Ok(slice) => std::borrow::Cow::Borrowed(slice),
            Err(_) => {
                let mut copy = vec![<T as bytemuck::Zeroable>::zeroed(); whole / size_of::<T>()];
                bytemuck::cast_slice_mut::<T, u8>(&mut copy).copy_from_slice(&bytes[..whole]);
                std::borrow::Cow::Owned(copy)
            }
        }
    }

    /// A written buffer as `T`s: elements of at most 4-byte alignment (checked when the driver
    /// compiles), as many as the words hold.
    pub fn write<T: bytemuck::Pod>(words: &mut [u32]) -> &mut [T] {
        const {
            assert!(
                align_of::<T>() <= 4,
                "a written storage buffer of 16-byte-aligned records has no generated CPU driver"
            )
        };
        let bytes: &mut [u8] = bytemuck::cast_slice_mut(words);
        let whole = bytes.len() / size_of::<T>() * size_of::<T>();
        bytemuck::cast_slice_mut(&mut bytes[..whole])
    }
}
