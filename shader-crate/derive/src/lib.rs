//! The two macros that make `aokit-shaders`' interfaces data, so nothing about them is written
//! twice (the generated code names `crate::contract` and `crate::kernel`: it is used only inside
//! `aokit-shaders`):
//!
//! - `#[derive(Layout)]` for the `#[repr(C)]` structs the kernels share with the host (push
//!   constants, buffer records): implements `crate::contract::Layout` with the struct's name,
//!   doc comment, size and alignment, and per field its name, Rust type, byte offset
//!   (`offset_of!`, so the compiler's layout, not a re-computation) and doc comment. Host only.
//! - `#[kernel]` on an entry point: its bindings, push constants and stage as a
//!   `crate::kernel::Kernel`, typed slot constants, a `Bindings` struct for the pass graphs and,
//!   where it can, a CPU driver (see `aokit_shaders::kernel`). The function itself is left as
//!   written, so the SPIR-V does not change.

mod kernel;

use proc_macro::TokenStream;
use quote::quote;
use syn::{Attribute, Data, DeriveInput, Expr, ExprLit, Fields, Lit, Meta, parse_macro_input};

/// Declares an entry point's interface from its signature; put it above `#[spirv(…)]`. See the
/// `aokit_shaders::kernel` module. A `&mut [T]` binding the kernel also reads is marked
/// `#[read_write]` (the marker is removed from the function).
#[proc_macro_attribute]
pub fn kernel(attr: TokenStream, item: TokenStream) -> TokenStream {
    kernel::expand(attr.into(), item.into()).unwrap_or_else(|e| e.to_compile_error()).into()
}

/// The `///` lines of `attrs`, trimmed and joined with spaces.
fn doc(attrs: &[Attribute]) -> String {
    let lines: Vec<String> = attrs
        .iter()
        .filter_map(|a| match &a.meta {
            Meta::NameValue(nv) if nv.path.is_ident("doc") => match &nv.value {
                Expr::Lit(ExprLit { lit: Lit::Str(s), .. }) => Some(s.value().trim().to_string()),
                _ => None,
            },
            _ => None,
        })
        .collect();
    lines.join(" ").trim().to_string()
}

/// `a::b::C` → `C` wherever a path appears in a type's text (`[crate::glam::Vec2;4]` → `[Vec2;4]`).
pub(crate) fn strip_paths(text: &str) -> String {
    let mut out = String::new();
    let mut word = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c.is_alphanumeric() || c == '_' {
            word.push(c);
        } else if c == ':' && chars.peek() == Some(&':') {
            chars.next();
            word.clear();
        } else {
            out.push_str(&word);
            word.clear();
            out.push(c);
        }
    }
    out + &word
}

#[proc_macro_derive(Layout)]
pub fn derive_layout(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    let name = &input.ident;
    let fields = match &input.data {
        Data::Struct(s) => match &s.fields {
            Fields::Named(f) => &f.named,
            _ => return quote!(compile_error!("derive(Layout) needs named fields");).into(),
        },
        _ => return quote!(compile_error!("derive(Layout) is for structs");).into(),
    };
    let entries = fields.iter().map(|f| {
        let ident = f.ident.as_ref().expect("named");
        let ty = &f.ty;
        // The type as written, without paths (`crate::glam::Mat4` → `Mat4`).
        let ty_text = strip_paths(&quote!(#ty).to_string().replace(' ', ""));
        let field_doc = doc(&f.attrs);
        quote! {
            crate::contract::Field {
                name: stringify!(#ident),
                ty: #ty_text,
                offset: ::core::mem::offset_of!(#name, #ident),
                size: ::core::mem::size_of::<#ty>(),
                doc: #field_doc,
                nested: <#ty as crate::contract::Layout>::layout,
            }
        }
    });
    let struct_doc = doc(&input.attrs);
    quote! {
        impl crate::contract::Layout for #name {
            fn layout() -> Option<crate::contract::StructLayout> {
                Some(crate::contract::StructLayout {
                    name: stringify!(#name),
                    doc: #struct_doc,
                    size: ::core::mem::size_of::<#name>(),
                    align: ::core::mem::align_of::<#name>(),
                    fields: vec![#(#entries),*],
                })
            }
        }
    }
    .into()
}
