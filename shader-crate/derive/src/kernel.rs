//! `#[kernel]`: an entry point's interface read from its signature (see `aokit_shaders::kernel`).

use proc_macro2::{Span, TokenStream};
use quote::{ToTokens, format_ident, quote};
use syn::{Error, FnArg, Ident, ItemFn, Pat, Type};

/// What a parameter of an entry point is.
enum Param {
    /// `#[spirv(global_invocation_id)]`.
    InvocationId,
    /// `#[spirv(push_constant)] p: &T`.
    PushConstants(Type),
    Binding(Binding),
    /// `#[spirv(spec_constant(id = N))] name: u32`: the CPU driver passes its default, 0.
    SpecConstant {
        id: u32,
        name: Ident,
    },
    /// Any other built-in, payload or attribute: no CPU driver is generated.
    Other,
}

struct Binding {
    slot: u32,
    name: Ident,
    /// `StorageBuffer`, `Image` or `AccelerationStructure`.
    kind: &'static str,
    /// `Read`, `Write` or `ReadWrite`.
    access: &'static str,
    /// The storage buffer's element type.
    element: Option<Type>,
    /// The type as the manifest writes it (`[f32]`, `Image!(2D,type=f32,sampled)`).
    rust_type: String,
}

/// The tokens of a `spirv(…)` attribute as text.
fn spirv_text(attr: &syn::Attribute) -> Option<String> {
    match &attr.meta {
        syn::Meta::List(l) if l.path.is_ident("spirv") => Some(l.tokens.to_string()),
        _ => None,
    }
}

/// The integer after `key =` in attribute text.
fn number_after(text: &str, key: &str) -> Option<u32> {
    let rest = text.split(key).nth(1)?.trim_start().strip_prefix('=')?.trim_start();
    rest.split(|c: char| !c.is_ascii_digit()).next()?.parse().ok()
}

const STAGES: [(&str, &str); 6] = [
    ("compute", "Compute"),
    ("vertex", "Vertex"),
    ("fragment", "Fragment"),
    ("ray_generation", "RayGeneration"),
    ("miss", "Miss"),
    ("any_hit", "AnyHit"),
];

pub fn expand(attr: TokenStream, item: TokenStream) -> Result<TokenStream, Error> {
    // `#[kernel(spirv_only)]`: the function exists only in SPIR-V (ray queries: its body cannot
    // compile natively), its declaration on the host too.
    let spirv_only = match attr.to_string().as_str() {
        "" => false,
        "spirv_only" => true,
        _ => return Err(Error::new_spanned(attr, "#[kernel] takes nothing or `spirv_only`")),
    };
    let mut f: ItemFn = syn::parse2(item)?;
    let fn_name = f.sig.ident.clone();
    let (stage_text, stage) = f
        .attrs
        .iter()
        .filter_map(spirv_text)
        .find_map(|text| {
            let first = text.split(|c: char| !(c.is_alphanumeric() || c == '_')).next().unwrap_or("").to_string();
            STAGES.iter().find(|(s, _)| *s == first).map(|(_, v)| (text.clone(), *v))
        })
        .ok_or_else(|| Error::new_spanned(&f.sig.ident, "#[kernel] goes above an entry point's #[spirv(stage(…))]"))?;
    let entry = stage_text
        .split("entry_point_name")
        .nth(1)
        .and_then(|r| r.split('"').nth(1))
        .map_or_else(|| fn_name.to_string(), str::to_string);
    // `threads(x[, y[, z]])` of a compute stage, as integer literals.
    let threads: Vec<u32> = match stage_text.split("threads (").nth(1).or_else(|| stage_text.split("threads(").nth(1)) {
        Some(rest) => {
            let inner = rest.split(')').next().unwrap_or("");
            let sizes: Result<Vec<u32>, _> = inner.split(',').map(|n| n.trim().parse()).collect();
            sizes.map_err(|_| {
                Error::new_spanned(&f.sig.ident, format!("#[kernel]: threads({inner}) is not integer literals"))
            })?
        }
        None => Vec::new(),
    };
    let threads = [0, 1, 2].map(|i| threads.get(i).copied().unwrap_or(1));

    let mut params = Vec::new();
    for input in &mut f.sig.inputs {
        let FnArg::Typed(p) = input else { return Err(Error::new_spanned(input, "an entry point takes no self")) };
        let read_write = p.attrs.iter().any(|a| a.path().is_ident("read_write"));
        p.attrs.retain(|a| !a.path().is_ident("read_write"));
        // A parameter without `#[spirv(…)]` is a stage input or output (vertex, fragment).
        let text = p.attrs.iter().filter_map(spirv_text).next().unwrap_or_default();
        let name = match &*p.pat {
            Pat::Ident(i) => i.ident.clone(),
            _ => format_ident!("unnamed"),
        };
        // The names the generated module uses for itself.
        if text.contains("descriptor_set")
            && ["entry", "registered", "cpu", "bindings"].contains(&name.to_string().as_str())
        {
            return Err(Error::new_spanned(&p.pat, "#[kernel]: this binding name is taken by the generated module"));
        }
        let (mutable, referent) = match &*p.ty {
            Type::Reference(r) => (r.mutability.is_some(), Some((*r.elem).clone())),
            _ => (false, None),
        };
        if read_write && !(mutable && text.contains("storage_buffer")) {
            return Err(Error::new_spanned(&p.pat, "#[read_write] marks a `&mut [T]` storage buffer"));
        }
        let param = if text.contains("spec_constant") {
            let id = number_after(&text, "id")
                .ok_or_else(|| Error::new_spanned(&p.pat, "a spec constant needs `spec_constant(id = N)`"))?;
            if number_after(&text, "default").is_some_and(|d| d != 0) {
                return Err(Error::new_spanned(
                    &p.pat,
                    "aokit's spec constants default to 0 (the push constants rule)",
                ));
            }
            if p.ty.to_token_stream().to_string() != "u32" {
                return Err(Error::new_spanned(&p.ty, "a spec constant is a u32 (a float field's bits)"));
            }
            Param::SpecConstant { id, name }
        } else if text.contains("push_constant") {
            Param::PushConstants(referent.ok_or_else(|| Error::new_spanned(&p.ty, "push constants are `&T`"))?)
        } else if text.trim() == "global_invocation_id" {
            Param::InvocationId
        } else if text.contains("descriptor_set") {
            let slot = number_after(&text, "binding")
                .ok_or_else(|| Error::new_spanned(&p.pat, "a descriptor binding needs `binding = N`"))?;
            if number_after(&text, "descriptor_set") != Some(0) {
                return Err(Error::new_spanned(&p.pat, "aokit binds descriptor set 0 only"));
            }
            let referent = referent.ok_or_else(|| Error::new_spanned(&p.ty, "a binding is a reference"))?;
            let rust_type = crate::strip_paths(&referent.to_token_stream().to_string().replace(' ', ""));
            let (kind, access, element) = if text.contains("storage_buffer") {
                let Type::Slice(s) = &referent else {
                    return Err(Error::new_spanned(&p.ty, "a storage buffer is `&[T]` or `&mut [T]`"));
                };
                let access = match (mutable, read_write) {
                    (false, _) => "Read",
                    (true, false) => "Write",
                    (true, true) => "ReadWrite",
                };
                ("StorageBuffer", access, Some((*s.elem).clone()))
            } else if rust_type.starts_with("Image!") {
                ("Image", if rust_type.contains("sampled=false") { "Write" } else { "Read" }, None)
            } else if rust_type == "AccelerationStructure" {
                ("AccelerationStructure", "Read", None)
            } else {
                return Err(Error::new_spanned(
                    &p.ty,
                    "#[kernel]: a binding is a storage buffer, an `Image!` or an `AccelerationStructure`",
                ));
            };
            Param::Binding(Binding { slot, name, kind, access, element, rust_type })
        } else {
            Param::Other
        };
        params.push(param);
    }

    let mut bindings: Vec<&Binding> = params
        .iter()
        .filter_map(|p| match p {
            Param::Binding(b) => Some(b),
            _ => None,
        })
        .collect();
    bindings.sort_by_key(|b| b.slot);
    for (i, b) in bindings.iter().enumerate() {
        if bindings[..i].iter().any(|c| c.slot == b.slot) {
            return Err(Error::new_spanned(&b.name, format!("binding {} is declared twice", b.slot)));
        }
    }

    let decls = bindings.iter().map(|b| {
        let Binding { slot, name, kind, access, rust_type, .. } = b;
        let name = name.to_string();
        let kind = format_ident!("{kind}");
        let access = format_ident!("{access}");
        let element = match &b.element {
            Some(t) => quote!(<#t as crate::contract::Layout>::layout),
            None => quote!(crate::kernel::no_layout),
        };
        quote! {
            crate::kernel::BindingDecl {
                slot: #slot,
                name: #name,
                rust_type: #rust_type,
                kind: crate::kernel::BindingKind::#kind,
                access: crate::graph::Access::#access,
                element: #element,
            }
        }
    });
    let slot_consts = bindings.iter().map(|b| {
        let konst = Ident::new(&b.name.to_string().to_uppercase(), b.name.span());
        let slot = b.slot;
        let element = b.element.clone().map_or_else(|| quote!(crate::kernel::Opaque), |t| t.to_token_stream());
        let doc = format!(
            "Binding `{}`: slot {slot}, `{}`, {}.",
            b.name,
            b.rust_type,
            match b.access {
                "Read" => "read",
                "Write" => "written",
                _ => "read and written",
            }
        );
        quote! {
            #[doc = #doc]
            pub const #konst: crate::kernel::Slot<#element> = crate::kernel::Slot::new(#slot);
        }
    });
    let fields: Vec<&Ident> = bindings.iter().map(|b| &b.name).collect();
    let field_docs = bindings.iter().map(|b| format!("The resource bound at slot {} (`{}`).", b.slot, b.name));
    let push = params.iter().find_map(|p| match p {
        Param::PushConstants(t) => Some(t),
        _ => None,
    });
    let push_decl = match push {
        Some(t) => {
            let text = crate::strip_paths(&t.to_token_stream().to_string().replace(' ', ""));
            quote!(Some((#text, <#t as crate::contract::Layout>::layout)))
        }
        None => quote!(None),
    };
    let specs: Vec<(u32, String)> = params
        .iter()
        .filter_map(|p| match p {
            Param::SpecConstant { id, name } => Some((*id, name.to_string())),
            _ => None,
        })
        .collect();
    for (i, (id, name)) in specs.iter().enumerate() {
        if specs[..i].iter().any(|(other, _)| other == id) {
            return Err(Error::new_spanned(&f.sig.ident, format!("spec constant id {id} ({name}) is declared twice")));
        }
    }
    let spec_decls = specs.iter().map(|(id, name)| quote!(crate::kernel::SpecConstantDecl { id: #id, name: #name }));
    let stage_ident = Ident::new(stage, Span::call_site());
    let [tx, ty, tz] = threads;

    // A CPU driver: a compute kernel of the invocation id, push constants and storage buffers.
    let drivable = !spirv_only
        && stage == "Compute"
        && params.iter().all(|p| match p {
            Param::Binding(b) => b.kind == "StorageBuffer",
            Param::Other => false,
            _ => true,
        })
        && params.iter().any(|p| matches!(p, Param::InvocationId));
    let (cpu, cpu_fn) = if drivable {
        let reads: Vec<&Binding> = bindings.iter().copied().filter(|b| b.access == "Read").collect();
        let writes: Vec<&Binding> = bindings.iter().copied().filter(|b| b.access != "Read").collect();
        let read_slots = reads.iter().map(|b| b.slot);
        let write_slots = writes.iter().map(|b| b.slot);
        let read_lets = reads.iter().map(|b| {
            let (local, t) = (format_ident!("__aokit_{}", b.name), &b.element);
            quote!(let #local = crate::kernel::cpu::read::<#t>(__aokit_reads.next().expect("a read slot"));)
        });
        let write_lets = writes.iter().map(|b| {
            let (local, t) = (format_ident!("__aokit_{}", b.name), &b.element);
            quote!(let #local: &mut [#t] = crate::kernel::cpu::write(__aokit_writes.next().expect("a written slot"));)
        });
        let push_let = push.map(|t| quote!(let __aokit_push: #t = crate::kernel::cpu::push(__aokit_push_bytes);));
        let args = params.iter().map(|p| match p {
            Param::InvocationId => quote!(crate::glam::UVec3::new(x, y, 0)),
            Param::PushConstants(_) => quote!(&__aokit_push),
            Param::SpecConstant { .. } => quote!(0u32),
            Param::Binding(b) => {
                let local = format_ident!("__aokit_{}", b.name);
                if b.access == "Read" { quote!(&#local) } else { quote!(&mut *#local) }
            }
            Param::Other => unreachable!(),
        });
        (
            quote!(Some(cpu)),
            quote! {
                /// The CPU driver: the entry point itself, once per invocation id.
                fn cpu(io: &mut dyn crate::kernel::KernelIo, invocations: [u32; 2]) {
                    let (__aokit_push_bytes, __aokit_reads, __aokit_writes) = io.buffers(&[#(#read_slots),*], &[#(#write_slots),*]);
                    let _ = __aokit_push_bytes;
                    let mut __aokit_reads = __aokit_reads.into_iter();
                    let mut __aokit_writes = __aokit_writes.into_iter();
                    #(#read_lets)*
                    #(#write_lets)*
                    #push_let
                    for y in 0..invocations[1] {
                        for x in 0..invocations[0] {
                            super::#fn_name(#(#args),*);
                        }
                    }
                }
            },
        )
    } else {
        (quote!(None), quote!())
    };

    let module_doc = format!(
        "The interface of entry point `{entry}` as its signature declares it: [`ENTRY`], one slot \
         constant per binding, and [`Bindings`] for pass graphs (`aokit_shaders::kernel`)."
    );
    let bindings_doc = format!("Which graph resource each binding of `{entry}` is.");
    let entry_doc = format!("Entry point `{entry}`.");
    let only = spirv_only.then(|| quote!(#[cfg(target_arch = "spirv")]));
    Ok(quote! {
        #only
        #f

        #[cfg(not(target_arch = "spirv"))]
        #[doc = #module_doc]
        pub mod #fn_name {
            #[allow(unused_imports)]
            use super::*;

            #(#slot_consts)*

            #[doc = #entry_doc]
            pub static ENTRY: crate::kernel::Kernel = crate::kernel::Kernel {
                entry: #entry,
                stage: crate::kernel::Stage::#stage_ident,
                threads: [#tx, #ty, #tz],
                push_constants: #push_decl,
                bindings: &[#(#decls),*],
                specialization: &[#(#spec_decls),*],
                cpu: #cpu,
            };

            #[linkme::distributed_slice(crate::kernel::KERNELS)]
            static REGISTERED: &crate::kernel::Kernel = &ENTRY;

            #[doc = #bindings_doc]
            #[derive(Copy, Clone, Debug)]
            pub struct Bindings {
                #(#[doc = #field_docs] pub #fields: &'static str,)*
            }

            impl crate::kernel::EntryBindings for Bindings {
                fn declaration(&self) -> &'static crate::kernel::Kernel {
                    &ENTRY
                }
                fn resources(&self) -> Vec<&'static str> {
                    vec![#(self.#fields),*]
                }
            }

            #cpu_fn
        }
    })
}
