//! The structs the kernels share with the host as data (host side): name, doc comment, size,
//! alignment and per field its name, Rust type, byte offset and doc comment, from
//! `#[derive(Layout)]` (`aokit-contract-derive`: the compiler's offsets, the source's doc
//! comments). The xtask turns them into `assets/include/aokit.h` and the manifest's constant
//! blocks, so an engine reads each push-constant block and buffer record from one source.

use crate::glam::{IVec2, Mat4, UVec2, UVec3, UVec4, Vec2, Vec3, Vec4};

/// One field of a shared struct.
#[derive(Clone, Debug)]
pub struct Field {
    pub name: &'static str,
    /// The Rust type as written (`f32`, `UVec2`, `ViewParams`, …).
    pub ty: &'static str,
    /// Byte offset in the struct (`core::mem::offset_of!`).
    pub offset: usize,
    pub size: usize,
    /// The field's doc comment: meaning and unit.
    pub doc: &'static str,
    /// The field's own layout where its type is a shared struct.
    pub nested: fn() -> Option<StructLayout>,
}

/// A `#[repr(C)]` struct shared by kernels and host.
#[derive(Clone, Debug)]
pub struct StructLayout {
    pub name: &'static str,
    pub doc: &'static str,
    pub size: usize,
    pub align: usize,
    pub fields: Vec<Field>,
}

/// A type's layout as a shared struct; `None` for scalars, vectors and matrices.
pub trait Layout {
    fn layout() -> Option<StructLayout>;
}

/// A scalar, vector or matrix type of shared structs.
#[derive(Copy, Clone, Debug)]
pub struct PlainType {
    /// The Rust name (`f32`, `Vec2`, `Mat4`, …).
    pub name: &'static str,
    /// The C type of one component.
    pub c_component: &'static str,
    /// Components (matrices: column-major, 16 for `Mat4`).
    pub components: usize,
    /// Rust's size and alignment, which a C declaration must match.
    pub size: usize,
    pub align: usize,
}

/// The plain types, each with its [`Layout`] (none) and its [`PlainType`] entry from one list.
macro_rules! plain {
    ($(($t:ident, $c:literal, $n:literal)),* $(,)?) => {
        $(impl Layout for $t { fn layout() -> Option<StructLayout> { None } })*
        /// Every plain type a shared struct may hold.
        pub const PLAIN_TYPES: &[PlainType] = &[$(PlainType {
            name: stringify!($t),
            c_component: $c,
            components: $n,
            size: size_of::<$t>(),
            align: align_of::<$t>(),
        }),*];
    };
}
plain!(
    (f32, "float", 1),
    (u32, "uint32_t", 1),
    (i32, "int32_t", 1),
    (Vec2, "float", 2),
    (Vec3, "float", 3),
    (Vec4, "float", 4),
    (UVec2, "uint32_t", 2),
    (UVec3, "uint32_t", 3),
    (UVec4, "uint32_t", 4),
    (IVec2, "int32_t", 2),
    (Mat4, "float", 16),
);

impl<T: Layout, const N: usize> Layout for [T; N] {
    fn layout() -> Option<StructLayout> {
        None
    }
}

/// Every struct an engine passes to the kernels (push constants, records in storage buffers),
/// with the structs they contain before them: the push-constant blocks and buffer elements that
/// the entry points declare ([`crate::kernel::KERNELS`], in entry-name order), so the list is
/// derived, never typed by hand.
pub fn shared_structs() -> Vec<StructLayout> {
    let roots = crate::kernel::Kernel::all().into_iter().flat_map(|k| {
        let push = k.push_constants.map(|(_, layout)| layout);
        push.into_iter().chain(k.bindings.iter().map(|b| b.element))
    });
    let mut out: Vec<StructLayout> = Vec::new();
    fn add(layout: StructLayout, out: &mut Vec<StructLayout>) {
        if out.iter().any(|s| s.name == layout.name) {
            return;
        }
        for f in &layout.fields {
            if let Some(inner) = (f.nested)() {
                add(inner, out);
            }
        }
        out.push(layout);
    }
    for layout in roots.filter_map(|root| root()) {
        add(layout, &mut out);
    }
    out
}
