//! `assets/spirv/manifest.json`: what an engine needs to use the SPIR-V without Rust — entry
//! points, stages, descriptor bindings, push-constant sizes — plus the hash of the shader
//! sources the modules were built from.

use aokit_shaders::contract::PLAIN_TYPES;
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    /// The schema of this file (`assets/README.md`): `aokit-manifest/2`.
    #[serde(default)]
    pub schema: String,
    /// [`crate::spirv_hash::shader_source_hash`] of the sources the modules were built from.
    pub source_hash: String,
    /// rust-gpu target triple.
    pub target: String,
    /// rust-gpu (spirv-std) version.
    pub rust_gpu: String,
    pub modules: Vec<ModuleManifest>,
    /// Every struct the kernels share with the host (push constants, buffer records), from
    /// `aokit_shaders::contract`.
    #[serde(default)]
    pub structs: Vec<StructManifest>,
    /// Every technique of the registry: its settings and, at its default settings, its pass
    /// graph.
    #[serde(default)]
    pub techniques: Vec<TechniqueManifest>,
}

/// One technique (`aokit_shaders::techniques`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TechniqueManifest {
    pub name: String,
    pub summary: String,
    pub settings: Vec<SettingManifest>,
    /// What the graph reads besides its own resources (`aokit_shaders::graph::inputs`).
    pub inputs: Vec<String>,
    pub resources: Vec<ResourceManifest>,
    pub passes: Vec<PassManifest>,
    /// The resource holding the final AO (`f32` per full-target texel, 1 = unoccluded).
    pub output: String,
}

/// One setting (`aokit_shaders::technique::Setting`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SettingManifest {
    /// Key of `technique:key=value` and of the reports' options.
    pub key: String,
    /// `aokit`'s flag taking a value, and a value-less flag with the value it sets.
    pub flag: Option<String>,
    pub switch: Option<(String, String)>,
    /// "count" (whole number), "number" or "choice".
    pub kind: String,
    /// Range of counts and numbers (`max` absent: unbounded).
    pub min: Option<f64>,
    pub max: Option<f64>,
    pub choices: Vec<String>,
    pub default: String,
    pub help: String,
}

/// One storage buffer of a graph.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResourceManifest {
    pub name: String,
    /// "f32" or "u32" (records are `u32` words holding the struct the binding names).
    pub elem: String,
    /// Element count as a formula of the full target `W×H` and inner image `w×h`: `·`
    /// multiplies, `ceil`, `floor`, `max`; records and tables a number.
    pub size: String,
    /// "per_frame" (initialised every frame) or "persistent".
    pub lifetime: String,
    /// "fill 0x3f800000" (every element these bits, here 1.0f), "data" (a record or table the
    /// host writes each frame: the module binding's struct), "undefined" (written before read).
    pub init: String,
    pub doc: String,
}

/// One dispatch, in graph order.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PassManifest {
    /// Timing label.
    pub label: String,
    /// The module ("raster": the fragment module; "ray_tracing": the ray-generation module).
    pub entry: String,
    /// "compute", "ray_tracing" (with `miss`, `any_hit`) or "raster" (with `vertex`).
    pub kind: String,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<String>,
    /// `(slot, resource or input, "read" | "write" | "read_write")`.
    pub bindings: Vec<(u32, String, String)>,
    /// Invocations `[x, y]` as formulas (compute: divide by the workgroup size, rounding up).
    pub dispatch: [String; 2],
    /// A memory barrier (shader writes → shader reads and writes) comes before this pass.
    pub barrier_before: bool,
}

/// A `#[repr(C)]` struct: size, alignment, fields with byte offsets.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StructManifest {
    pub name: String,
    pub doc: String,
    pub size: u32,
    pub align: u32,
    pub fields: Vec<FieldManifest>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FieldManifest {
    pub name: String,
    /// The Rust type: a scalar (`f32`, `u32`, `i32`), a glam vector or matrix (`Vec2`, `UVec2`,
    /// `Mat4`, …: f32/u32 components, column-major matrices), an array, or another struct here.
    pub ty: String,
    pub offset: u32,
    pub size: u32,
    /// Meaning and unit.
    pub doc: String,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModuleManifest {
    pub entry_point: String,
    pub file: String,
    /// "compute", "vertex", "fragment", or a ray-tracing stage.
    pub stage: String,
    /// Compute workgroup size.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub workgroup_size: Option<[u32; 3]>,
    pub bindings: Vec<BindingManifest>,
    pub push_constant_bytes: u32,
    /// The struct of the push-constant block (in [`Manifest::structs`]), if the entry point has
    /// one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub push_constants: Option<String>,
    /// The module as WGSL (`assets/wgsl/`), for compute modules WebGPU core can run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wgsl: Option<WgslManifest>,
}

/// A module's WGSL translation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct WgslManifest {
    /// `<entry>.wgsl` in `assets/wgsl/`.
    pub file: String,
    /// The binding (group 0) of the uniform buffer holding the push-constant struct.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub constants_binding: Option<u32>,
}

/// Compute modules without a WGSL translation, and why.
#[cfg(feature = "reflect")]
pub const NOT_WGSL: [(&str, &str); 2] = [
    ("export_ao_r16f", "WebGPU core has no r16float storage textures: use export_ao_r32f"),
    ("export_ao_r8", "WebGPU core has no r8unorm storage textures: use export_ao_r32f"),
];

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BindingManifest {
    pub set: u32,
    pub binding: u32,
    /// "storage_buffer", "uniform_buffer", "image", "acceleration_structure", …
    pub kind: String,
    pub writable: bool,
    /// The kernel's parameter name (SPIR-V `OpName`).
    #[serde(default)]
    pub name: String,
    /// The kernel's Rust type of the binding: `[f32]`, `[u32]`, `[Vec2]` (runtime arrays),
    /// a record struct of [`Manifest::structs`] (`SvaoFrame`), an image or the TLAS.
    #[serde(default)]
    pub rust_type: String,
}

impl Manifest {
    /// The committed manifest.
    pub fn committed() -> Manifest {
        serde_json::from_str(crate::modules::MANIFEST).expect("committed manifest.json parses")
    }
}

/// naga-based validation and reflection (feature `reflect`). naga reads compute and graphics
/// modules; it cannot read ray-tracing modules.
#[cfg(feature = "reflect")]
pub mod reflect {
    use super::{BindingManifest, ModuleManifest};
    use naga::{AddressSpace, ShaderStage, StorageAccess, TypeInner};

    /// Parse with naga's SPIR-V front end and run naga's validator.
    pub fn validate(bytes: &[u8]) -> Result<naga::Module, String> {
        let options = naga::front::spv::Options {
            adjust_coordinate_space: false,
            strict_capabilities: false,
            block_ctx_dump_prefix: None,
        };
        let module = naga::front::spv::parse_u8_slice(bytes, &options).map_err(|e| format!("naga spv-in: {e}"))?;
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::all())
            .validate(&module)
            .map_err(|e| format!("naga validation: {:?}", e.into_inner()))?;
        Ok(module)
    }

    /// Describe a module: naga for compute and raster modules (validated too), the SPIR-V
    /// words directly for ray-tracing modules, which naga cannot read.
    pub fn reflect_any(file: &str, bytes: &[u8]) -> Result<ModuleManifest, String> {
        if super::words::is_ray_tracing(bytes)? { super::words::reflect(file, bytes) } else { reflect(file, bytes) }
    }

    /// Describe the module's single entry point.
    pub fn reflect(file: &str, bytes: &[u8]) -> Result<ModuleManifest, String> {
        let module = validate(bytes)?;
        let [entry] = &module.entry_points[..] else {
            return Err(format!("{file}: expected exactly one entry point, found {}", module.entry_points.len()));
        };
        let stage = match entry.stage {
            ShaderStage::Compute => "compute",
            ShaderStage::Vertex => "vertex",
            ShaderStage::Fragment => "fragment",
            _ => "other",
        };
        let mut bindings = Vec::new();
        let mut push_constant_bytes = 0;
        for (_, var) in module.global_variables.iter() {
            let size = module.types[var.ty].inner.size(module.to_ctx());
            match var.space {
                AddressSpace::Immediate => push_constant_bytes += size,
                _ => {
                    let Some(b) = &var.binding else { continue };
                    let (kind, writable) = match var.space {
                        AddressSpace::Storage { access } => ("storage_buffer", access.contains(StorageAccess::STORE)),
                        AddressSpace::Uniform => ("uniform_buffer", false),
                        _ => match module.types[var.ty].inner {
                            TypeInner::Sampler { .. } => ("sampler", false),
                            TypeInner::Image { .. } => ("image", false),
                            _ => ("other", false),
                        },
                    };
                    let name = var.name.clone().unwrap_or_default();
                    let (set, binding, kind) = (b.group, b.binding, kind.into());
                    bindings.push(BindingManifest { set, binding, kind, writable, name, rust_type: String::new() });
                }
            }
        }
        bindings.sort_by_key(|b| (b.set, b.binding));
        Ok(ModuleManifest {
            entry_point: entry.name.clone(),
            file: file.into(),
            stage: stage.into(),
            workgroup_size: (entry.stage == ShaderStage::Compute).then_some(entry.workgroup_size),
            bindings,
            push_constant_bytes,
            push_constants: None,
            wgsl: None,
        })
    }
}

/// A minimal reader of SPIR-V words: entry point, execution model and descriptor bindings of
/// ray-tracing modules (SPIR-V spec §2.3 physical layout, §3 enumerants).
#[cfg(feature = "reflect")]
pub mod words {
    use super::{BindingManifest, ModuleManifest};
    use std::collections::HashMap;

    const OP_NAME: u32 = 5;
    const OP_ENTRY_POINT: u32 = 15;
    const OP_CAPABILITY: u32 = 17;
    const OP_VARIABLE: u32 = 59;
    const OP_DECORATE: u32 = 71;
    const CAPABILITY_RAY_TRACING: u32 = 4479;
    const DECORATION_NON_WRITABLE: u32 = 24;
    const DECORATION_BINDING: u32 = 33;
    const DECORATION_DESCRIPTOR_SET: u32 = 34;
    const STORAGE_UNIFORM_CONSTANT: u32 = 0;
    const STORAGE_PUSH_CONSTANT: u32 = 9;
    const STORAGE_BUFFER: u32 = 12;

    fn instructions(bytes: &[u8]) -> Result<Vec<(u32, Vec<u32>)>, String> {
        if !bytes.len().is_multiple_of(4) || bytes.len() < 20 {
            return Err("not a SPIR-V module".into());
        }
        let w: Vec<u32> = bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
        if w[0] != 0x0723_0203 {
            return Err("bad SPIR-V magic number".into());
        }
        let mut out = Vec::new();
        let mut i = 5;
        while i < w.len() {
            let (count, op) = ((w[i] >> 16) as usize, w[i] & 0xFFFF);
            if count == 0 || i + count > w.len() {
                return Err(format!("malformed instruction at word {i}"));
            }
            out.push((op, w[i + 1..i + count].to_vec()));
            i += count;
        }
        Ok(out)
    }

    /// Does the module declare the RayTracingKHR capability?
    pub fn is_ray_tracing(bytes: &[u8]) -> Result<bool, String> {
        Ok(instructions(bytes)?
            .iter()
            .any(|(op, a)| *op == OP_CAPABILITY && a.first() == Some(&CAPABILITY_RAY_TRACING)))
    }

    /// Entry point, stage and descriptor bindings of a ray-tracing module.
    pub fn reflect(file: &str, bytes: &[u8]) -> Result<ModuleManifest, String> {
        let ins = instructions(bytes)?;
        let entries: Vec<_> = ins.iter().filter(|(op, _)| *op == OP_ENTRY_POINT).collect();
        let [(_, entry)] = &entries[..] else {
            return Err(format!("{file}: expected exactly one entry point, found {}", entries.len()));
        };
        let stage = match entry[0] {
            5313 => "ray_generation",
            5314 => "intersection",
            5315 => "any_hit",
            5316 => "closest_hit",
            5317 => "miss",
            5318 => "callable",
            m => return Err(format!("{file}: execution model {m} is not a ray-tracing stage")),
        };
        let name: Vec<u8> = entry[2..].iter().flat_map(|w| w.to_le_bytes()).take_while(|&b| b != 0).collect();
        let entry_point = String::from_utf8(name).map_err(|e| e.to_string())?;
        let (mut set, mut binding, mut read_only) = (HashMap::new(), HashMap::new(), HashMap::new());
        let mut names = HashMap::new();
        for (op, a) in &ins {
            if *op == OP_NAME && a.len() >= 2 {
                let bytes: Vec<u8> = a[1..].iter().flat_map(|w| w.to_le_bytes()).take_while(|&b| b != 0).collect();
                names.insert(a[0], String::from_utf8_lossy(&bytes).into_owned());
            }
            if *op == OP_DECORATE && a.len() >= 2 {
                match (a[1], a.get(2)) {
                    (DECORATION_DESCRIPTOR_SET, Some(&v)) => _ = set.insert(a[0], v),
                    (DECORATION_BINDING, Some(&v)) => _ = binding.insert(a[0], v),
                    (DECORATION_NON_WRITABLE, _) => _ = read_only.insert(a[0], ()),
                    _ => {}
                }
            }
        }
        let mut bindings = Vec::new();
        for (op, a) in &ins {
            if *op != OP_VARIABLE || a.len() < 3 {
                continue;
            }
            let (id, class) = (a[1], a[2]);
            if class == STORAGE_PUSH_CONSTANT {
                return Err(format!("{file}: push constants in ray-tracing modules are not reflected yet"));
            }
            let (Some(&s), Some(&b)) = (set.get(&id), binding.get(&id)) else { continue };
            let (kind, writable) = match class {
                STORAGE_BUFFER => ("storage_buffer", !read_only.contains_key(&id)),
                STORAGE_UNIFORM_CONSTANT => ("acceleration_structure", false),
                _ => ("other", false),
            };
            let name = names.get(&id).cloned().unwrap_or_default();
            let kind = kind.into();
            bindings.push(BindingManifest { set: s, binding: b, kind, writable, name, rust_type: String::new() });
        }
        bindings.sort_by_key(|b| (b.set, b.binding));
        Ok(ModuleManifest {
            entry_point,
            file: file.into(),
            stage: stage.into(),
            workgroup_size: None,
            bindings,
            push_constant_bytes: 0,
            push_constants: None,
            wgsl: None,
        })
    }
}

/// The kernels' entry-point signatures read from the shader crate's Rust source (feature
/// `reflect`): which struct is a module's push-constant block and each binding's parameter name
/// and Rust type — what the SPIR-V does not name.
#[cfg(feature = "reflect")]
pub mod source {
    use quote::ToTokens;
    use std::path::Path;

    /// One entry point's interface as written in Rust.
    #[derive(Clone, Debug, PartialEq)]
    pub struct EntrySignature {
        pub entry: String,
        /// The push-constant parameter's type name.
        pub push_constants: Option<String>,
        /// `(set, binding, parameter name, Rust type without the reference)`.
        pub bindings: Vec<(u32, u32, String, String)>,
    }

    const STAGES: [&str; 8] =
        ["compute", "fragment", "vertex", "ray_generation", "any_hit", "miss", "closest_hit", "intersection"];

    /// `spirv(...)` attribute tokens as text, if `attr` is one.
    fn spirv_attr(attr: &syn::Attribute) -> Option<String> {
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

    fn entry_of(f: &syn::ItemFn) -> Option<EntrySignature> {
        let attr = f.attrs.iter().filter_map(spirv_attr).find(|a| {
            let first = a.split(|c: char| !(c.is_alphanumeric() || c == '_')).next().unwrap_or("");
            STAGES.contains(&first)
        })?;
        let entry = attr
            .split("entry_point_name")
            .nth(1)
            .and_then(|r| r.split('"').nth(1))
            .map_or_else(|| f.sig.ident.to_string(), str::to_string);
        let mut sig = EntrySignature { entry, push_constants: None, bindings: Vec::new() };
        for input in &f.sig.inputs {
            let syn::FnArg::Typed(p) = input else { continue };
            let Some(text) = p.attrs.iter().filter_map(spirv_attr).next() else { continue };
            let name = p.pat.to_token_stream().to_string();
            let ty = p.ty.to_token_stream().to_string().replace(' ', "");
            // `&'a mut [f32]` → `[f32]`.
            let ty = ty.trim_start_matches('&');
            let ty = match ty.strip_prefix('\'') {
                Some(rest) => rest.trim_start_matches(|c: char| c.is_alphanumeric() || c == '_'),
                None => ty,
            };
            let ty = ty.trim_start_matches("mut").to_string();
            if text.contains("push_constant") {
                sig.push_constants = Some(ty);
            } else if let (Some(set), Some(binding)) =
                (number_after(&text, "descriptor_set"), number_after(&text, "binding"))
            {
                sig.bindings.push((set, binding, name, ty));
            }
        }
        Some(sig)
    }

    /// A one-arm `macro_rules!` whose arm is an entry point: its metavariables and body.
    struct EntryMacro {
        name: String,
        params: Vec<String>,
        body: String,
    }

    /// `macro_rules! m { ($a:ident, $b:tt, …) => { …fn… }; }` as an [`EntryMacro`].
    fn entry_macro(m: &syn::ItemMacro) -> Option<EntryMacro> {
        let name = m.ident.as_ref()?.to_string();
        if !m.mac.path.is_ident("macro_rules") {
            return None;
        }
        let mut tokens = m.mac.tokens.clone().into_iter();
        let pattern = match tokens.next()? {
            proc_macro2::TokenTree::Group(g) => g.stream().to_string(),
            _ => return None,
        };
        let body = tokens.find_map(|t| match t {
            proc_macro2::TokenTree::Group(g) => Some(g.stream().to_string()),
            _ => None,
        })?;
        let params = pattern.split(',').filter_map(|p| Some(p.split(':').next()?.trim().replace(' ', ""))).collect();
        body.contains("spirv").then_some(EntryMacro { name, params, body })
    }

    fn items(items: &[syn::Item], out: &mut Vec<EntrySignature>) {
        let macros: Vec<EntryMacro> = items
            .iter()
            .filter_map(|i| match i {
                syn::Item::Macro(m) => entry_macro(m),
                _ => None,
            })
            .collect();
        for item in items {
            match item {
                syn::Item::Fn(f) => out.extend(entry_of(f)),
                syn::Item::Mod(m) => {
                    if let Some((_, inner)) = &m.content {
                        self::items(inner, out);
                    }
                }
                // An invocation of an entry-point macro: its body with the arguments substituted.
                syn::Item::Macro(m) => {
                    let Some(mac) = macros.iter().find(|d| m.mac.path.is_ident(&d.name)) else { continue };
                    let args: Vec<String> = m.mac.tokens.to_string().split(',').map(|a| a.trim().to_string()).collect();
                    let mut body = mac.body.clone();
                    for (param, arg) in mac.params.iter().zip(&args) {
                        body = body.replace(&param.replacen('$', "$ ", 1), arg).replace(param.as_str(), arg);
                    }
                    if let Ok(f) = syn::parse_str::<syn::ItemFn>(&body) {
                        out.extend(entry_of(&f));
                    }
                }
                _ => {}
            }
        }
    }

    /// Every entry point under `src` (the shader crate's `src/`).
    pub fn entry_points(src: &Path) -> Result<Vec<EntrySignature>, String> {
        let mut files = Vec::new();
        let mut dirs = vec![src.to_path_buf()];
        while let Some(dir) = dirs.pop() {
            for e in std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))? {
                let path = e.map_err(|e| e.to_string())?.path();
                if path.is_dir() {
                    dirs.push(path);
                } else if path.extension().is_some_and(|x| x == "rs") {
                    files.push(path);
                }
            }
        }
        files.sort();
        let mut out = Vec::new();
        for path in files {
            let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
            let file = syn::parse_file(&text).map_err(|e| format!("{}: {e}", path.display()))?;
            items(&file.items, &mut out);
        }
        Ok(out)
    }
}

#[cfg(feature = "reflect")]
impl Manifest {
    /// Translate every compute module (but [`NOT_WGSL`]) of `spirv_dir` to WGSL
    /// (`crate::wgsl`), note it in the module entries, and return `(file, source)` to write into
    /// `assets/wgsl/`.
    pub fn add_wgsl(&mut self, spirv_dir: &std::path::Path) -> Result<Vec<(String, String)>, String> {
        let mut out = Vec::new();
        for m in &mut self.modules {
            if m.stage != "compute" || NOT_WGSL.iter().any(|(e, _)| *e == m.entry_point) {
                continue;
            }
            let bytes = std::fs::read(spirv_dir.join(&m.file)).map_err(|e| format!("{}: {e}", m.file))?;
            let w = crate::wgsl::from_spirv(&bytes).map_err(|e| format!("{}: {e}", m.entry_point))?;
            let file = format!("{}.wgsl", m.entry_point);
            m.wgsl = Some(WgslManifest { file: file.clone(), constants_binding: w.constants_binding });
            out.push((file, w.source));
        }
        Ok(out)
    }

    /// Version 2 of the manifest from the reflected modules: binding names and Rust types and
    /// push-constant structs from the entry points' source (`shader_src`), the shared structs
    /// from `aokit_shaders::contract`. Fails where a module's push constants or record have no
    /// struct, or a struct's size differs from the module's block.
    pub fn complete(mut self, shader_src: &std::path::Path) -> Result<Manifest, String> {
        self.schema = "aokit-manifest/2".into();
        self.structs = aokit_shaders::contract::shared_structs()
            .into_iter()
            .map(|s| StructManifest {
                name: s.name.into(),
                doc: s.doc.into(),
                size: s.size as u32,
                align: s.align as u32,
                fields: s
                    .fields
                    .iter()
                    .map(|f| FieldManifest {
                        name: f.name.into(),
                        ty: f.ty.into(),
                        offset: f.offset as u32,
                        size: f.size as u32,
                        doc: f.doc.into(),
                    })
                    .collect(),
            })
            .collect();
        self.techniques = techniques()?;
        let signatures = source::entry_points(shader_src)?;
        for m in &mut self.modules {
            let sig = signatures
                .iter()
                .find(|s| s.entry == m.entry_point)
                .ok_or_else(|| format!("{}: no entry point of that name in the shader sources", m.entry_point))?;
            m.push_constants = sig.push_constants.clone();
            if let Some(name) = &m.push_constants {
                let s = self.structs.iter().find(|s| &s.name == name).ok_or_else(|| {
                    format!(
                        "{}: push constants {name} are not in aokit_shaders::contract::shared_structs",
                        m.entry_point
                    )
                })?;
                if m.push_constant_bytes != 0 && s.size != m.push_constant_bytes {
                    return Err(format!(
                        "{}: {name} is {} bytes, the module's block {}",
                        m.entry_point, s.size, m.push_constant_bytes
                    ));
                }
            }
            for b in &mut m.bindings {
                let (_, _, name, ty) = sig
                    .bindings
                    .iter()
                    .find(|(set, binding, ..)| (*set, *binding) == (b.set, b.binding))
                    .ok_or_else(|| format!("{}: binding {} not found in the source", m.entry_point, b.binding))?;
                if b.name.is_empty() {
                    b.name = name.clone();
                }
                b.rust_type = ty.clone();
                // A storage buffer holds plain elements or records of a shared struct.
                let element = ty.trim_start_matches('[').trim_end_matches(']');
                let plain = PLAIN_TYPES.iter().any(|p| p.name == element);
                if b.kind == "storage_buffer" && !plain && !self.structs.iter().any(|s| s.name == element) {
                    return Err(format!(
                        "{}: {element} is not in aokit_shaders::contract::shared_structs",
                        m.entry_point
                    ));
                }
            }
        }
        Ok(self)
    }
}

/// The C name of a manifest type: scalars, glam vectors and matrices
/// (`aokit_shaders::contract::PLAIN_TYPES`), shared structs.
fn c_type(ty: &str) -> String {
    match PLAIN_TYPES.iter().find(|p| p.name == ty) {
        Some(p) if p.components == 1 => p.c_component.into(),
        Some(p) => format!("aokit_{}", p.name.to_lowercase()),
        None => format!("aokit_{ty}"),
    }
}

/// A C identifier in upper case (`vao_main` → `VAO_MAIN`).
fn upper(name: &str) -> String {
    name.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_uppercase() } else { '_' }).collect()
}

impl Manifest {
    /// `assets/include/aokit.h`: every shared struct with `_Static_assert`s on its size and
    /// field offsets (the Rust compiler's), and per module its SPIR-V file, workgroup size,
    /// push-constant struct and binding indices as named constants.
    pub fn c_header(&self) -> String {
        let mut h = String::new();
        let line = |h: &mut String, s: &str| {
            h.push_str(s);
            h.push('\n');
        };
        line(&mut h, "/* aokit.h: the kernels' constants blocks, records and bindings for C and C++ engines.");
        line(&mut h, " * GENERATED by `cargo run -p xtask -- build-spirv` from the shader crate; do not edit.");
        line(&mut h, &format!(" * Schema {}, shader sources {}.", self.schema, self.source_hash));
        line(&mut h, " * Layouts are the Rust compiler's (#[repr(C)]); the _Static_asserts check that this C");
        line(&mut h, " * compiler lays them out the same. Matrices are column-major. See assets/README.md. */");
        line(&mut h, "#ifndef AOKIT_H\n#define AOKIT_H\n\n#include <stddef.h>\n#include <stdint.h>\n");
        line(&mut h, "#ifdef __cplusplus /* the C11 keywords in C++11 */");
        line(
            &mut h,
            "#define _Alignas(n) alignas(n)\n#define _Alignof(t) alignof(t)\n#define _Static_assert(c, m) static_assert(c, m)",
        );
        line(&mut h, "#endif");
        line(
            &mut h,
            "#ifdef near /* <windows.h> defines near and far as empty macros; ViewParams has fields so named */",
        );
        line(&mut h, "#undef near\n#undef far\n#endif\n");
        line(&mut h, "/* Vectors and matrices (glam). */");
        for p in PLAIN_TYPES.iter().filter(|p| p.components > 1) {
            let (name, component, n, size, align) = (p.name, p.c_component, p.components, p.size, p.align);
            let c = c_type(name);
            line(&mut h, &format!("typedef struct {c} {{ _Alignas({align}) {component} v[{n}]; }} {c};"));
            line(&mut h, &format!("_Static_assert(sizeof({c}) == {size} && _Alignof({c}) == {align}, \"{name}\");"));
        }
        line(&mut h, "");
        for s in &self.structs {
            let c = c_type(&s.name);
            line(&mut h, &format!("/* {} */", s.doc.replace("*/", "* /")));
            line(&mut h, &format!("typedef struct {c} {{"));
            for f in &s.fields {
                let (ty, array) = match f.ty.strip_prefix('[').and_then(|t| t.strip_suffix(']')) {
                    Some(inner) => {
                        let (t, n) = inner.split_once(';').unwrap_or((inner, "1"));
                        (c_type(t), format!("[{n}]"))
                    }
                    None => (c_type(&f.ty), String::new()),
                };
                let doc =
                    if f.doc.is_empty() { String::new() } else { format!(" /* {} */", f.doc.replace("*/", "* /")) };
                line(&mut h, &format!("    {ty} {}{array};{doc}", f.name));
            }
            line(&mut h, &format!("}} {c};"));
            line(&mut h, &format!("_Static_assert(sizeof({c}) == {}, \"{} size\");", s.size, s.name));
            line(&mut h, &format!("_Static_assert(_Alignof({c}) == {}, \"{} alignment\");", s.align, s.name));
            for f in &s.fields {
                line(
                    &mut h,
                    &format!(
                        "_Static_assert(offsetof({c}, {}) == {}, \"{}.{} offset\");",
                        f.name, f.offset, s.name, f.name
                    ),
                );
            }
            line(&mut h, "");
        }
        line(&mut h, "/* Modules: SPIR-V file, stage, workgroup size, push constants, bindings (set 0). */");
        for m in &self.modules {
            let p = format!("AOKIT_{}", upper(&m.entry_point));
            let push = m.push_constants.as_deref().map_or("none".to_string(), c_type);
            let group = m.workgroup_size.map_or(String::new(), |w| format!(", workgroup {}x{}x{}", w[0], w[1], w[2]));
            line(&mut h, &format!("/* {}: {} stage{group}, push constants {push} */", m.entry_point, m.stage));
            line(&mut h, &format!("#define {p}_SPV \"{}\"", m.file));
            if let Some(w) = m.workgroup_size {
                for (axis, v) in ["X", "Y", "Z"].iter().zip(w) {
                    line(&mut h, &format!("#define {p}_WORKGROUP_{axis} {v}u"));
                }
            }
            for b in &m.bindings {
                let access = if b.writable { "read-write" } else { "read-only" };
                line(
                    &mut h,
                    &format!(
                        "#define {p}_BINDING_{} {}u /* {} {}, {access} */",
                        upper(&b.name),
                        b.binding,
                        b.kind,
                        b.rust_type
                    ),
                );
            }
            line(&mut h, "");
        }
        line(&mut h, "#endif /* AOKIT_H */");
        h
    }
}

/// The frame the technique section's graphs are built for: only their structure is written
/// (sizes and dispatches as formulas), so any valid frame gives the same section.
#[cfg(feature = "reflect")]
pub fn reference_frame(inner: aokit_shaders::glam::UVec2, guard: u32) -> aokit_shaders::graph::FrameDesc {
    use aokit_shaders::glam::Vec3;
    let camera = aokit_shaders::common::camera::Camera::look_at(
        Vec3::new(0.0, 1.0, 5.0),
        Vec3::ZERO,
        Vec3::Y,
        1.0,
        inner,
        guard,
        0.1,
        100.0,
    );
    aokit_shaders::graph::FrameDesc { camera, radius: 0.5, exponent: 2.0, thickness: 0.0 }
}

/// The registry's techniques at their defaults.
#[cfg(feature = "reflect")]
fn techniques() -> Result<Vec<TechniqueManifest>, String> {
    use aokit_shaders::graph::{Access, Elem, Init, Lifetime, PassKind};
    use aokit_shaders::technique::Kind;
    let frame = reference_frame(aokit_shaders::glam::UVec2::new(1920, 1080), 64);
    let mut out = Vec::new();
    for t in aokit_shaders::techniques::TECHNIQUES {
        let configured = t.configure();
        let defaults = configured.values();
        let settings = t
            .rows()
            .into_iter()
            .map(|r| {
                let (kind, min, max, choices) = match r.kind {
                    Kind::Count { min, max } => {
                        ("count", Some(min as f64), (max < u32::MAX).then_some(max as f64), vec![])
                    }
                    Kind::Number { min, max } => {
                        // Through the f32's shortest decimal form: 0.3, not 0.30000001192092896.
                        let exact = |v: f32| v.to_string().parse::<f64>().expect("a number");
                        ("number", Some(exact(min)), (max < f32::MAX).then_some(exact(max)), vec![])
                    }
                    Kind::Choice(names) => ("choice", None, None, names.iter().map(|n| n.to_string()).collect()),
                };
                SettingManifest {
                    key: r.key.into(),
                    flag: r.flag.map(Into::into),
                    switch: r.switch.map(|(f, v)| (f.into(), v.into())),
                    kind: kind.into(),
                    min,
                    max,
                    choices,
                    default: defaults.iter().find(|(k, _)| *k == r.key).map(|(_, v)| v.clone()).unwrap_or_default(),
                    help: r.help.into(),
                }
            })
            .collect();
        let graph = configured.graph(&frame)?;
        let resources = graph
            .resources
            .iter()
            .map(|r| ResourceManifest {
                name: r.name.into(),
                elem: match r.elem {
                    Elem::F32 => "f32",
                    Elem::U32 => "u32",
                }
                .into(),
                size: r.size.formula(),
                lifetime: match r.lifetime {
                    Lifetime::PerFrame => "per_frame",
                    Lifetime::Persistent => "persistent",
                }
                .into(),
                init: match &r.init {
                    Init::Fill(bits) => format!("fill {bits:#010x}"),
                    Init::Data(_) => "data".into(),
                    Init::Undefined => "undefined".into(),
                },
                doc: r.doc.into(),
            })
            .collect();
        let barriers = graph.barriers();
        let passes = graph
            .passes
            .iter()
            .zip(barriers)
            .map(|(p, barrier_before)| {
                let (kind, stages) = match p.kind {
                    PassKind::Compute => ("compute", vec![]),
                    PassKind::RayTracing { miss, any_hit } => ("ray_tracing", vec![miss.into(), any_hit.into()]),
                    PassKind::Raster { vertex } => ("raster", vec![vertex.into()]),
                };
                let access = |a: Access| match a {
                    Access::Read => "read",
                    Access::Write => "write",
                    Access::ReadWrite => "read_write",
                };
                PassManifest {
                    label: p.label.into(),
                    entry: p.entry.into(),
                    kind: kind.into(),
                    stages,
                    bindings: p.bindings.iter().map(|b| (b.slot, b.resource.into(), access(b.access).into())).collect(),
                    dispatch: p.dispatch.formula(),
                    barrier_before,
                }
            })
            .collect();
        out.push(TechniqueManifest {
            name: t.name().into(),
            summary: t.summary().into(),
            settings,
            inputs: graph.inputs().into_iter().map(Into::into).collect(),
            resources,
            passes,
            output: graph.output.into(),
        });
    }
    Ok(out)
}
