//! `assets/spirv/manifest.json`: what an engine needs to use the SPIR-V without Rust — entry
//! points, stages, descriptor bindings, push-constant sizes — plus the hash of the shader
//! sources the modules were built from.

use crate::MANIFEST_JSON;
use aokit_shaders::contract::PLAIN_TYPES;
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    /// The schema of this file (`assets/README.md`): `aokit-manifest/3`.
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
    /// The data tables `data` resources take their words from (`contents.table`).
    #[serde(default)]
    pub tables: Vec<TableManifest>,
    /// The modules between an engine's images and aokit's buffers.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub adapters: Option<AdaptersManifest>,
    /// How any technique's published graph runs at half resolution.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub half_resolution: Option<HalfResolutionManifest>,
    /// How any technique's published graph accumulates its AO over frames.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temporal: Option<TemporalManifest>,
}

/// The temporal accumulation appended to any published graph (`aokit_shaders::temporal`,
/// `docs/temporal.md`): two passes after the variant's, a record and the history.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TemporalManifest {
    /// The recipe in one paragraph (`assets/README.md`, "Temporal accumulation").
    pub doc: String,
    /// Its own settings (`TemporalFrame.alpha`, `TemporalFrame.depth_tolerance`).
    pub settings: Vec<SettingManifest>,
    /// `(name, previous frame's name)`: `previous(Camera)` evaluates the `Camera` rows with the
    /// second names' values in place of the first.
    pub previous_names: Vec<(String, String)>,
    /// Added to the variant's resources (the record, the output and the persistent history).
    pub resources: Vec<ResourceManifest>,
    /// After the variant's passes; [`OUTPUT_PLACEHOLDER`] stands for the
    /// variant's `output`.
    pub after: Vec<PassManifest>,
    /// The accumulated AO (f32 per full-target texel).
    pub output: String,
    /// `TemporalFrame` (the record of `after`'s passes) and the structs inside it.
    pub constants: Vec<ConstantManifest>,
}

/// Half resolution as a transform of any published variant (`aokit_shaders::halfres`, spec
/// half-resolution §1): the variant evaluated with the half frame's names, its G-buffer inputs
/// renamed to the downsample's outputs, between the downsample and the upsample.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct HalfResolutionManifest {
    /// The recipe in one paragraph (`assets/README.md`, "Half resolution", states it in full).
    pub doc: String,
    /// The transform's own settings (`HalfParams.pick`, `HalfParams.plane_tolerance`).
    pub settings: Vec<SettingManifest>,
    /// `(name, expression of the full frame's names)`: evaluate the variant's sizes, dispatches,
    /// contents and constants with these names instead of the full target's (each expression
    /// evaluated with the full frame's values).
    pub half_names: Vec<(String, String)>,
    /// What the frame must satisfy (refused otherwise).
    pub requires: String,
    /// Inputs a variant must not read (the downsample does not reduce them).
    pub refused_inputs: Vec<String>,
    /// `(input, resource)`: the variant's bindings of these inputs bind the downsample's outputs.
    pub renamed_inputs: Vec<(String, String)>,
    /// Added to the variant's resources (sizes in the full frame's names).
    pub resources: Vec<ResourceManifest>,
    /// Before the variant's passes.
    pub before: Vec<PassManifest>,
    /// After them; [`OUTPUT_PLACEHOLDER`] stands for the variant's `output`.
    pub after: Vec<PassManifest>,
    /// The wrapped graph's output (f32 per full-target texel).
    pub output: String,
    /// `HalfParams` (the push constants of `before` and `after`) and the `ViewParams` inside it,
    /// as expressions of `settings` and the full frame; `half(ViewParams)` is the `ViewParams`
    /// rows evaluated with `half_names`.
    pub constants: Vec<ConstantManifest>,
}

/// The name that the `after` passes of `half_resolution` and `temporal` give the wrapped
/// variant's `output`.
pub const OUTPUT_PLACEHOLDER: &str = "<output>";

/// The adapter modules (`aokit_shaders::adapters`): their settings, modules and constants.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AdaptersManifest {
    /// The engine's side: its depth convention and its projection's planes.
    pub settings: Vec<SettingManifest>,
    pub modules: Vec<AdapterModuleManifest>,
    /// `ImportParams` (the push constants of every adapter module) and the `ViewParams` inside
    /// it, as expressions of `settings` and the frame.
    pub constants: Vec<ConstantManifest>,
}

/// One adapter module.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AdapterModuleManifest {
    pub entry: String,
    /// Invocations `[x, y]` (integer expressions of `W H w h`).
    pub dispatch: [String; 2],
    /// `(slot, what it binds)`: an engine image, or the technique graphs' input or output.
    pub bindings: Vec<(u32, String)>,
    pub doc: String,
}

/// A table of values (`aokit_shaders::technique::Table`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TableManifest {
    pub name: String,
    /// The element type (`Vec2`: two f32 per element, as the module's binding holds them).
    pub elem: String,
    pub doc: String,
    /// Every element's components, in order (binary32 values, shortest decimal form).
    pub values: Vec<f32>,
}

/// The graph of a technique for the settings of one or more `when` entries.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VariantManifest {
    /// The settings this graph is for: one entry per combination of the technique's structural
    /// settings (those that change its passes or resources), `key → value`; every other setting
    /// may take any legal value (sizes, dispatches and contents are expressions of them).
    pub when: Vec<std::collections::BTreeMap<String, String>>,
    pub inputs: Vec<String>,
    pub resources: Vec<ResourceManifest>,
    pub passes: Vec<PassManifest>,
    pub output: String,
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
    /// The keys of the settings that change the graph's passes or resources.
    #[serde(default)]
    pub structural: Vec<String>,
    /// The graph for every combination of the structural settings (the one above is the
    /// defaults' variant).
    #[serde(default)]
    pub variants: Vec<VariantManifest>,
    /// How each field of the constants structs the passes use (push-constant blocks, records
    /// bound as storage buffers, the structs they hold) is computed from the settings and the
    /// camera: every field of every such struct, structs in [`Manifest::structs`] order.
    #[serde(default)]
    pub constants: Vec<ConstantManifest>,
}

/// One field of a constants struct and its formula (`aokit_shaders::technique::Constant`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConstantManifest {
    /// The struct, in [`Manifest::structs`].
    #[serde(rename = "struct")]
    pub struct_name: String,
    pub field: String,
    /// Byte offset of the field in its struct, and its type (as in [`Manifest::structs`]).
    pub offset: u32,
    #[serde(rename = "type")]
    pub ty: String,
    /// The value as an expression of the grammar `assets/README.md` defines ("Expressions"):
    /// the technique's settings in backticks, the frame's named inputs, arithmetic and builtins;
    /// a field of struct type has the struct's name. Settings the technique does not read are
    /// already replaced by their fixed values.
    pub expr: String,
    /// The same in words, with units and the paper sections.
    pub doc: String,
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
    /// Choice settings that set others (XeGTAO's `preset` sets `slices` and `steps`): per
    /// choice, the settings it sets (`custom`: none). Apply in the order of `settings`.
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub sets: std::collections::BTreeMap<String, std::collections::BTreeMap<String, String>>,
}

/// One storage buffer of a graph.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResourceManifest {
    pub name: String,
    /// "f32" or "u32" (records are `u32` words holding the struct the binding names).
    pub elem: String,
    /// Element count as an integer expression (the constants' grammar) of the full target
    /// `W×H`, the inner image `w×h` and the technique's settings.
    pub size: String,
    /// "per_frame" (initialised every frame) or "persistent".
    pub lifetime: String,
    /// "fill 0x3f800000" (every element these bits, here 1.0f), "data" (a record or table the
    /// host writes each frame: the module binding's struct), "undefined" (written before read).
    pub init: String,
    /// "data" resources: what the words are.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contents: Option<ContentsManifest>,
    pub doc: String,
}

/// The words of a `data` resource: a record of a struct filled from the technique's constants,
/// or elements `first .. first + count` of a table (expressions of the settings).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ContentsManifest {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub record: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub table: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub count: Option<String>,
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
    /// "ray_tracing" passes: the compute module of the same pass with ray queries
    /// (`VK_KHR_ray_query`; the same bindings, workgroups over the same launch size).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ray_query: Option<String>,
    /// `(slot, resource or input, "read" | "write" | "read_write")`.
    pub bindings: Vec<(u32, String, String)>,
    /// Invocations `[x, y]` as integer expressions like `size` (compute: divide by the
    /// workgroup size, rounding up).
    pub dispatch: [String; 2],
    /// A memory barrier (shader writes → shader reads and writes) comes before this pass.
    pub barrier_before: bool,
}

impl PassManifest {
    /// This pass as a wrapped graph runs it: its bindings of [`OUTPUT_PLACEHOLDER`] bound to the
    /// wrapped variant's `output`, those of `renamed`'s inputs (`(input, resource)`, as
    /// `half_resolution.renamed_inputs`) to their resources.
    pub fn bound(&self, output: &str, renamed: &[(String, String)]) -> PassManifest {
        let mut pass = self.clone();
        for b in &mut pass.bindings {
            if b.1 == OUTPUT_PLACEHOLDER {
                b.1 = output.into();
            } else if let Some((_, to)) = renamed.iter().find(|(from, _)| *from == b.1) {
                b.1 = to.clone();
            }
        }
        pass
    }
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
    /// Its specialization constants (all `u32`, default 0): `specialized` set to 1 makes the
    /// others hold the push-constant fields of their names (a float's bits), fixed at pipeline
    /// creation; left at 0 the module reads its push constants (`assets/README.md`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub specialization: Vec<SpecConstantManifest>,
}

/// One specialization constant of a module.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpecConstantManifest {
    /// The `SpecId` (Vulkan `VkSpecializationMapEntry::constantID`, WGSL `@id`).
    pub id: u32,
    /// `specialized`, or the push-constant field it holds.
    pub name: String,
}

/// A module's WGSL translation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct WgslManifest {
    /// `<entry>.wgsl` in `assets/wgsl/`.
    pub file: String,
    /// The binding (group 0) of the uniform buffer holding the push-constant struct.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub constants_binding: Option<u32>,
    /// The entry point's name in the WGSL, where it differs from the module's (naga renames
    /// names that end in a digit, e.g. `svao_pass1_`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entry_point: Option<String>,
}

/// Compute modules without a WGSL translation, and why.
pub const NOT_WGSL: [(&str, &str); 2] = [
    ("export_ao_r16f", "WebGPU core has no r16float storage textures: use export_ao_r32f"),
    ("export_ao_r8", "WebGPU core has no r8unorm storage textures: use export_ao_r32f"),
];

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BindingManifest {
    pub set: u32,
    pub binding: u32,
    /// "storage_buffer", "uniform_buffer", "storage_image", "sampled_image" (read with
    /// `OpImageFetch`, no sampler), "acceleration_structure".
    pub kind: String,
    /// The module writes it (storage buffers: no `NonWritable` decoration; storage images: the
    /// image is not `readonly`).
    pub writable: bool,
    /// The kernel's parameter name (SPIR-V `OpName`).
    #[serde(default)]
    pub name: String,
    /// The kernel's Rust type of the binding: `[f32]`, `[u32]`, `[Vec2]` (runtime arrays),
    /// a record struct of [`Manifest::structs`] (`SvaoFrame`), an image or the TLAS.
    #[serde(default)]
    pub rust_type: String,
    /// Storage images: the texel format the module declares, as WebGPU names it (`r32float`,
    /// `r16float`, `r8unorm`; Vulkan `R32_SFLOAT`, `R16_SFLOAT`, `R8_UNORM`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub format: Option<String>,
    /// Sampled images: the sample type (`float`: a depth image's or a colour image's first
    /// channels read as floats; WebGPU `unfilterable-float` suffices, no sampler is used).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sample_type: Option<String>,
}

impl Manifest {
    /// The committed manifest.
    pub fn committed() -> Manifest {
        serde_json::from_str(MANIFEST_JSON).expect("committed manifest.json parses")
    }
}

/// naga-based validation and reflection (feature `reflect`). naga reads compute and graphics
/// modules; it cannot read ray-tracing modules.
#[cfg(feature = "reflect")]
pub mod reflect {
    use super::{BindingManifest, ModuleManifest, SpecConstantManifest};
    use naga::{AddressSpace, ImageClass, ScalarKind, ShaderStage, StorageAccess, TypeInner};

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
                    let (mut format, mut sample_type) = (None, None);
                    let (kind, writable) = match var.space {
                        AddressSpace::Storage { access } => ("storage_buffer", access.contains(StorageAccess::STORE)),
                        AddressSpace::Uniform => ("uniform_buffer", false),
                        _ => match module.types[var.ty].inner {
                            TypeInner::Sampler { .. } => ("sampler", false),
                            TypeInner::Image { class: ImageClass::Storage { format: f, access }, .. } => {
                                // naga's names are WebGPU's texel formats (`R32Float` → r32float).
                                format = Some(format!("{f:?}").to_lowercase());
                                ("storage_image", access.contains(StorageAccess::STORE))
                            }
                            TypeInner::Image { class, .. } => {
                                sample_type = Some(match class {
                                    ImageClass::Sampled { kind: ScalarKind::Float, .. } => "float",
                                    ImageClass::Sampled { kind: ScalarKind::Sint, .. } => "sint",
                                    ImageClass::Sampled { kind: ScalarKind::Uint, .. } => "uint",
                                    ImageClass::Depth { .. } => "depth",
                                    _ => "other",
                                });
                                ("sampled_image", false)
                            }
                            _ => ("other", false),
                        },
                    };
                    let name = var.name.clone().unwrap_or_default();
                    let (set, binding, kind) = (b.group, b.binding, kind.into());
                    let sample_type = sample_type.map(Into::into);
                    let rust_type = String::new();
                    bindings.push(BindingManifest {
                        set,
                        binding,
                        kind,
                        writable,
                        name,
                        rust_type,
                        format,
                        sample_type,
                    });
                }
            }
        }
        bindings.sort_by_key(|b| (b.set, b.binding));
        // The SpecIds (names come from the kernel's declaration).
        let mut specialization: Vec<SpecConstantManifest> = module
            .overrides
            .iter()
            .filter_map(|(_, o)| o.id.map(|id| SpecConstantManifest { id: id.into(), name: String::new() }))
            .collect();
        specialization.sort_by_key(|c| c.id);
        Ok(ModuleManifest {
            entry_point: entry.name.clone(),
            file: file.into(),
            stage: stage.into(),
            workgroup_size: (entry.stage == ShaderStage::Compute).then_some(entry.workgroup_size),
            bindings,
            push_constant_bytes,
            push_constants: None,
            wgsl: None,
            specialization,
        })
    }
}

/// A minimal reader of SPIR-V words: entry point, execution model and descriptor bindings of
/// ray-tracing modules (SPIR-V spec §2.3 physical layout, §3 enumerants).
pub mod words {
    use super::{BindingManifest, ModuleManifest};
    use std::collections::HashMap;

    const OP_NAME: u32 = 5;
    const OP_ENTRY_POINT: u32 = 15;
    const OP_EXECUTION_MODE: u32 = 16;
    const OP_CAPABILITY: u32 = 17;
    const EXECUTION_MODE_LOCAL_SIZE: u32 = 17;
    const CAPABILITY_RAY_QUERY: u32 = 4472;
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

    /// Does the module declare the RayTracingKHR or RayQueryKHR capability (which naga's SPIR-V
    /// front end cannot read)?
    pub fn is_ray_tracing(bytes: &[u8]) -> Result<bool, String> {
        Ok(instructions(bytes)?.iter().any(|(op, a)| {
            *op == OP_CAPABILITY && matches!(a.first(), Some(&(CAPABILITY_RAY_TRACING | CAPABILITY_RAY_QUERY)))
        }))
    }

    /// Entry point, stage, workgroup size and descriptor bindings of a ray-tracing or ray-query
    /// module.
    pub fn reflect(file: &str, bytes: &[u8]) -> Result<ModuleManifest, String> {
        let ins = instructions(bytes)?;
        let entries: Vec<_> = ins.iter().filter(|(op, _)| *op == OP_ENTRY_POINT).collect();
        let [(_, entry)] = &entries[..] else {
            return Err(format!("{file}: expected exactly one entry point, found {}", entries.len()));
        };
        let stage = match entry[0] {
            5 => "compute",
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
        let mut workgroup_size = None;
        for (op, a) in &ins {
            if *op == OP_EXECUTION_MODE && a.len() >= 5 && a[1] == EXECUTION_MODE_LOCAL_SIZE {
                workgroup_size = Some([a[2], a[3], a[4]]);
            }
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
            let rust_type = String::new();
            let (format, sample_type) = (None, None);
            bindings.push(BindingManifest { set: s, binding: b, kind, writable, name, rust_type, format, sample_type });
        }
        bindings.sort_by_key(|b| (b.set, b.binding));
        Ok(ModuleManifest {
            entry_point,
            file: file.into(),
            stage: stage.into(),
            workgroup_size,
            bindings,
            push_constant_bytes: 0,
            push_constants: None,
            wgsl: None,
            specialization: Vec::new(),
        })
    }
}

#[cfg(feature = "reflect")]
impl Manifest {
    /// Translate every compute module (but [`NOT_WGSL`] and the ray-query variants, which
    /// naga's SPIR-V front end cannot read and WebGPU cannot run) of `spirv_dir` to WGSL
    /// (`crate::wgsl`, feature `reflect`), note it in the module entries, and return `(file, source)` to write into
    /// `assets/wgsl/`.
    pub fn add_wgsl(&mut self, spirv_dir: &std::path::Path) -> Result<Vec<(String, String)>, String> {
        let mut out = Vec::new();
        for m in &mut self.modules {
            if m.stage != "compute" || NOT_WGSL.iter().any(|(e, _)| *e == m.entry_point) {
                continue;
            }
            let bytes = std::fs::read(spirv_dir.join(&m.file)).map_err(|e| format!("{}: {e}", m.file))?;
            if words::is_ray_tracing(&bytes)? {
                continue;
            }
            let w = crate::wgsl::from_spirv(&bytes).map_err(|e| format!("{}: {e}", m.entry_point))?;
            let file = format!("{}.wgsl", m.entry_point);
            let entry_point = (w.entry_point != m.entry_point).then_some(w.entry_point);
            m.wgsl = Some(WgslManifest { file: file.clone(), constants_binding: w.constants_binding, entry_point });
            out.push((file, w.source));
        }
        Ok(out)
    }

    /// Version 2 of the manifest from the reflected modules: binding names and Rust types and
    /// push-constant structs from the entry points' declarations (`aokit_shaders::kernel`), the
    /// shared structs from `aokit_shaders::contract`. Fails where a module's binding is not
    /// declared or its writability differs from the declaration, where its push constants or
    /// record have no struct, or a struct's size differs from the module's block.
    pub fn complete(mut self) -> Result<Manifest, String> {
        self.schema = "aokit-manifest/3".into();
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
        self.tables = tables()?;
        self.adapters = Some(adapters(&self.structs)?);
        self.half_resolution = Some(half_resolution(&self.structs)?);
        self.temporal = Some(temporal(&self.structs)?);
        for m in &mut self.modules {
            let kernel = aokit_shaders::kernel::Kernel::find(&m.entry_point)
                .ok_or_else(|| format!("{}: no #[kernel] entry point of that name", m.entry_point))?;
            m.push_constants = kernel.push_constants.map(|(name, _)| name.to_string());
            let mut declared: Vec<u32> = kernel.specialization.iter().map(|c| c.id).collect();
            declared.sort();
            let in_module: Vec<u32> = m.specialization.iter().map(|c| c.id).collect();
            if declared != in_module {
                return Err(format!(
                    "{}: the kernel declares spec constants {declared:?}, the module has {in_module:?}",
                    m.entry_point
                ));
            }
            m.specialization =
                kernel.specialization.iter().map(|c| SpecConstantManifest { id: c.id, name: c.name.into() }).collect();
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
                let decl = kernel.binding(b.binding).filter(|_| b.set == 0).ok_or_else(|| {
                    format!("{}: binding {} is not declared by the entry point", m.entry_point, b.binding)
                })?;
                // The declaration (the Rust signature) and the compiled module agree on what a
                // storage buffer is and whether the kernel may write it.
                if matches!(b.kind.as_str(), "storage_buffer" | "storage_image") && decl.access.writes() != b.writable {
                    return Err(format!(
                        "{}: binding {} ({}) is declared {:?}, the module's is {}",
                        m.entry_point,
                        b.binding,
                        decl.name,
                        decl.access,
                        if b.writable { "writable" } else { "read-only" }
                    ));
                }
                if b.name.is_empty() {
                    b.name = decl.name.into();
                }
                b.rust_type = decl.rust_type.into();
                // A storage buffer holds plain elements or records of a shared struct.
                let element = decl.rust_type.trim_start_matches('[').trim_end_matches(']');
                let plain = PLAIN_TYPES.iter().any(|p| p.name == element);
                if b.kind == "storage_buffer" && !plain && !self.structs.iter().any(|s| s.name == element) {
                    return Err(format!(
                        "{}: {element} is not in aokit_shaders::contract::shared_structs",
                        m.entry_point
                    ));
                }
            }
        }
        for (tm, &t) in self.techniques.iter_mut().zip(aokit_shaders::techniques::TECHNIQUES) {
            tm.constants = constants::of(t, &self.modules, &self.structs)?;
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
    aokit_shaders::graph::FrameDesc::new(camera, 0.5, 2.0, 0.0)
}

/// What each choice of setting `key` sets besides itself: the settings that come out the same
/// whichever value they had before (from the defaults and from every other choice's state), for
/// the choices that change any.
#[cfg(feature = "reflect")]
fn presets(
    t: &'static dyn aokit_shaders::technique::Registered,
    key: &str,
    kind: aokit_shaders::technique::Kind,
) -> std::collections::BTreeMap<String, std::collections::BTreeMap<String, String>> {
    use std::collections::BTreeMap;
    let aokit_shaders::technique::Kind::Choice(names) = kind else { return BTreeMap::new() };
    let after = |from: Option<&str>, choice: &str| -> Option<Vec<(&'static str, String)>> {
        let mut c = t.configure();
        if let Some(f) = from {
            c.set(key, f).ok()?;
        }
        c.set(key, choice).ok()?;
        Some(c.values().into_iter().filter(|(k, _)| *k != key).collect())
    };
    let starts: Vec<Option<&str>> = std::iter::once(None).chain(names.iter().map(|n| Some(*n))).collect();
    let mut out = BTreeMap::new();
    for choice in names {
        let Some(state) = after(None, choice) else { continue };
        let sets: BTreeMap<String, String> = state
            .into_iter()
            .filter(|(k, v)| {
                let changed = names
                    .iter()
                    .any(|other| after(None, other).is_some_and(|s| s.iter().any(|(ok, ov)| ok == k && ov != v)));
                changed
                    && starts
                        .iter()
                        .all(|f| after(*f, choice).is_some_and(|s| s.iter().any(|(sk, sv)| sk == k && sv == v)))
            })
            .map(|(k, v)| (k.to_string(), v))
            .collect();
        out.insert(choice.to_string(), sets);
    }
    if out.values().all(BTreeMap::is_empty) { BTreeMap::new() } else { out }
}

/// Every technique's data tables, each once.
pub fn tables() -> Result<Vec<TableManifest>, String> {
    let mut out: Vec<TableManifest> = Vec::new();
    for t in aokit_shaders::techniques::TECHNIQUES {
        for table in t.tables() {
            let m = TableManifest {
                name: table.name.into(),
                elem: table.elem.into(),
                doc: table.doc.into(),
                values: (table.values)(),
            };
            match out.iter().find(|o| o.name == m.name) {
                Some(o) if *o != m => return Err(format!("two tables named {}", m.name)),
                Some(_) => {}
                None => out.push(m),
            }
        }
    }
    Ok(out)
}

/// The settings rows of `t` with its defaults and, for presets, what each choice sets.
#[cfg(feature = "reflect")]
fn settings_of(t: &'static dyn aokit_shaders::technique::Registered) -> Vec<SettingManifest> {
    use aokit_shaders::technique::Kind;
    let defaults = t.configure().values();
    t.rows()
        .into_iter()
        .map(|r| {
            let (kind, min, max, choices) = match r.kind {
                Kind::Count { min, max } => ("count", Some(min as f64), (max < u32::MAX).then_some(max as f64), vec![]),
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
                sets: presets(t, r.key, r.kind),
            }
        })
        .collect()
}

/// The adapter modules: their settings (the engine's depth convention and planes), their
/// dispatch and bindings, and `ImportParams` as expressions.
#[cfg(feature = "reflect")]
fn adapters(structs: &[StructManifest]) -> Result<AdaptersManifest, String> {
    use aokit_shaders::adapters::settings::{ADAPTERS, MODULES};
    let t: &'static dyn aokit_shaders::technique::Registered = &ADAPTERS;
    let constants = constants_of(t, structs, &["ViewParams", "ImportParams"])?;
    let modules = MODULES
        .iter()
        .map(|m| AdapterModuleManifest {
            entry: m.entry.into(),
            dispatch: m.dispatch.map(Into::into),
            bindings: m.bindings.iter().map(|(slot, what)| (*slot, what.to_string())).collect(),
            doc: m.doc.into(),
        })
        .collect();
    Ok(AdaptersManifest { settings: settings_of(t), modules, constants })
}

/// The rows of `t` for every field of `names` (in order), as published.
#[cfg(feature = "reflect")]
fn constants_of(
    t: &'static dyn aokit_shaders::technique::Registered,
    structs: &[StructManifest],
    names: &[&str],
) -> Result<Vec<ConstantManifest>, String> {
    let mut constants = Vec::new();
    for name in names {
        let s = structs.iter().find(|s| s.name == *name).ok_or_else(|| format!("no struct {name}"))?;
        for f in &s.fields {
            let path = format!("{name}.{}", f.name);
            let row =
                t.constants().iter().find(|c| c.field == path).ok_or_else(|| format!("{}: no row {path}", t.name()))?;
            constants.push(ConstantManifest {
                struct_name: s.name.clone(),
                field: f.name.clone(),
                offset: f.offset,
                ty: f.ty.clone(),
                expr: crate::constants::expression(t, row.expr),
                doc: row.formula.into(),
            });
        }
    }
    Ok(constants)
}

/// The temporal accumulation: its settings and constants from
/// `aokit_shaders::temporal::settings::TEMPORAL`, its resources and passes from `accumulate`
/// after `gtao`'s graph at the defaults (the ones it adds, whatever it follows).
#[cfg(feature = "reflect")]
pub fn temporal(structs: &[StructManifest]) -> Result<TemporalManifest, String> {
    use aokit_shaders::temporal::settings::{
        HISTORY_AO, HISTORY_DEPTH, OUTPUT, PREVIOUS_NAMES, RECORD, TEMPORAL, TemporalSettings, accumulate,
    };
    let t: &'static dyn aokit_shaders::technique::Registered = &TEMPORAL;
    let constants = constants_of(t, structs, &["ViewParams", "Camera", "TemporalFrame"])?;
    let wrapped: &'static dyn aokit_shaders::technique::Registered = &aokit_shaders::gtao::settings::GTAO;
    let mut frame = reference_frame(aokit_shaders::glam::UVec2::new(1920, 1080), 64);
    frame.temporal = Some(TemporalSettings::default());
    let c = wrapped.configure();
    let inner = c.graph(&frame)?;
    let (inner_output, inner_passes) = (inner.output, inner.passes.len());
    let published = crate::graphs::publish(wrapped, &accumulate(inner, &frame)?)?;
    let ours = [RECORD, OUTPUT, HISTORY_AO, HISTORY_DEPTH];
    let resources = published.resources.iter().filter(|r| ours.contains(&r.name.as_str())).cloned().collect();
    let mut after: Vec<PassManifest> = published.passes[inner_passes..].to_vec();
    for b in after.iter_mut().flat_map(|p| &mut p.bindings) {
        if b.1 == inner_output {
            b.1 = OUTPUT_PLACEHOLDER.into();
        }
    }
    Ok(TemporalManifest {
        doc: "any technique's variant followed by the temporal accumulation (docs/temporal.md): `after` appended \
              (its first pass with a barrier before it), `resources` added (`persistent` ones kept across frames, \
              filled once), the AO read from `output`"
            .into(),
        settings: settings_of(t).into_iter().map(|s| SettingManifest { flag: None, ..s }).collect(),
        previous_names: PREVIOUS_NAMES.iter().map(|(n, p)| (n.to_string(), p.to_string())).collect(),
        resources,
        after,
        output: OUTPUT.into(),
        constants,
    })
}

/// The half-resolution transform: its settings and constants from
/// `aokit_shaders::halfres::settings::HALF_RESOLUTION`, its resources and passes from
/// `at_resolution` around `gtao`'s graph at the defaults (the passes it adds, whatever it wraps).
#[cfg(feature = "reflect")]
pub fn half_resolution(structs: &[StructManifest]) -> Result<HalfResolutionManifest, String> {
    use aokit_shaders::graph::inputs;
    use aokit_shaders::halfres::settings::{
        HALF_DEPTH, HALF_NAMES, HALF_NORMALS, HALF_RESOLUTION, OUTPUT, Resolution, at_resolution,
    };
    let t: &'static dyn aokit_shaders::technique::Registered = &HALF_RESOLUTION;
    let constants = constants_of(t, structs, &["ViewParams", "HalfParams"])?;
    let wrapped: &'static dyn aokit_shaders::technique::Registered = &aokit_shaders::gtao::settings::GTAO;
    let frame = reference_frame(aokit_shaders::glam::UVec2::new(1920, 1080), 64);
    let c = wrapped.configure();
    let graph = at_resolution(Resolution::half(), &frame, |f| c.graph(f))?;
    let inner_output = c.graph(&frame)?.output;
    let published = crate::graphs::publish(wrapped, &graph)?;
    let ours = [HALF_DEPTH, HALF_NORMALS, OUTPUT];
    let resources = published.resources.iter().filter(|r| ours.contains(&r.name.as_str())).cloned().collect();
    let (first, mut last) = match &published.passes[..] {
        [first, .., last] if first.entry == "half_downsample" && last.entry == "half_upsample" => {
            (first.clone(), last.clone())
        }
        _ => {
            return Err(
                "half resolution: the wrapped graph does not start with half_downsample and end with half_upsample"
                    .into(),
            );
        }
    };
    // The upsample's `half_ao` (its slot in the kernel's declaration) reads the variant's output.
    let slot = aokit_shaders::kernel::Kernel::find("half_upsample")
        .and_then(|k| k.bindings.iter().find(|b| b.name == "half_ao").map(|b| b.slot))
        .ok_or("half_upsample declares no half_ao binding")?;
    for b in last.bindings.iter_mut().filter(|b| b.0 == slot) {
        if b.1 != inner_output {
            return Err(format!("half_upsample's half_ao binds {}, not the wrapped output {inner_output}", b.1));
        }
        b.1 = OUTPUT_PLACEHOLDER.into();
    }
    Ok(HalfResolutionManifest {
        doc: "any technique's variant at half resolution (spec half-resolution, docs/algorithms/half-resolution.md): \
              `before`, the variant evaluated with `half_names` and its inputs renamed, `after`; the variant's \
              first pass and `after` have a barrier before them, the variant's other passes keep theirs"
            .into(),
        // No flag of its own: `aokit` takes both as `--resolution half|half-nearest[-tau<τ>]`.
        settings: settings_of(t).into_iter().map(|s| SettingManifest { flag: None, ..s }).collect(),
        half_names: HALF_NAMES.iter().map(|(n, e)| (n.to_string(), e.to_string())).collect(),
        requires: "W, H and g even; at least 2×2 pixels inside the guard band (W ≥ 2g + 2, H ≥ 2g + 2)".into(),
        refused_inputs: vec![inputs::SECOND_DEPTH.into()],
        renamed_inputs: vec![
            (inputs::LINEAR_DEPTH.into(), HALF_DEPTH.into()),
            (inputs::VIEW_NORMALS.into(), HALF_NORMALS.into()),
        ],
        resources,
        before: vec![first],
        after: vec![last],
        output: OUTPUT.into(),
        constants,
    })
}

/// The registry's techniques: settings, the graph at the defaults and every variant.
#[cfg(feature = "reflect")]
fn techniques() -> Result<Vec<TechniqueManifest>, String> {
    let frame = reference_frame(aokit_shaders::glam::UVec2::new(1920, 1080), 64);
    let mut out = Vec::new();
    for t in aokit_shaders::techniques::TECHNIQUES {
        let configured = t.configure();
        let settings = settings_of(*t);
        let (structural, variants) = crate::graphs::variants(*t, &frame)?;
        let defaults = crate::graphs::publish(*t, &configured.graph(&frame)?)?;
        out.push(TechniqueManifest {
            name: t.name().into(),
            summary: t.summary().into(),
            settings,
            inputs: defaults.inputs,
            resources: defaults.resources,
            passes: defaults.passes,
            output: defaults.output,
            structural,
            variants,
            constants: Vec::new(),
        });
    }
    Ok(out)
}

/// The techniques' `constants`: which constants structs a technique's passes
/// use, and every field of them with its formula from the technique's declaration.
pub mod constants {
    use super::{ConstantManifest, ModuleManifest, StructManifest};
    use aokit_shaders::graph::{Graph, Init, Pass, PassKind};
    use aokit_shaders::technique::{Kind, Registered};

    /// The modules a pass runs: its entry, the ray-tracing pipeline's miss and any-hit and its
    /// ray-query variant, the raster pass's vertex module.
    pub fn pass_modules(pass: &Pass) -> Vec<&'static str> {
        match pass.kind {
            PassKind::Compute => vec![pass.entry()],
            PassKind::RayTracing { miss, any_hit, query } => vec![pass.entry(), miss.entry, any_hit.entry, query.entry],
            PassKind::Raster { vertex } => vec![vertex.entry, pass.entry()],
        }
    }

    /// The shared struct a binding's Rust type holds records of (`[SvaoFrame]` → `SvaoFrame`).
    fn record_struct<'a>(rust_type: &str, structs: &'a [StructManifest]) -> Option<&'a StructManifest> {
        let element = rust_type.strip_prefix('[')?.strip_suffix(']')?;
        structs.iter().find(|s| s.name == element)
    }

    /// The constants structs of `graph`'s passes: each module's push-constant block, and the
    /// struct of every record (a `data` resource) bound where a module's binding holds a shared
    /// struct; then, recursively, the shared structs their fields are. Added to `used`.
    pub fn used_structs(
        graph: &Graph,
        modules: &[ModuleManifest],
        structs: &[StructManifest],
        used: &mut Vec<String>,
    ) -> Result<(), String> {
        let mut roots = Vec::new();
        for pass in &graph.passes {
            for name in pass_modules(pass) {
                let m = modules
                    .iter()
                    .find(|m| m.entry_point == name)
                    .ok_or_else(|| format!("pass {}: no module {name}", pass.label))?;
                roots.extend(m.push_constants.clone());
                for b in &pass.bindings {
                    let record = graph.resource(b.resource).is_some_and(|r| matches!(r.init, Init::Data(_)));
                    let binding = m.bindings.iter().find(|mb| mb.set == 0 && mb.binding == b.slot);
                    if let (true, Some(s)) = (record, binding.and_then(|mb| record_struct(&mb.rust_type, structs))) {
                        roots.push(s.name.clone());
                    }
                }
            }
        }
        while let Some(name) = roots.pop() {
            if used.contains(&name) {
                continue;
            }
            let s = structs.iter().find(|s| s.name == name).ok_or_else(|| format!("{name} is not a shared struct"))?;
            for f in &s.fields {
                let ty = f.ty.trim_start_matches('[').split(';').next().unwrap_or("").trim_end_matches(']');
                if structs.iter().any(|s| s.name == ty) {
                    roots.push(ty.to_string());
                }
            }
            used.push(name);
        }
        Ok(())
    }

    /// The values tried per setting to find every constants struct a technique can use: every
    /// choice; a count's minimum, minimum + 1, default + 1 and (bounded) maximum; a number's
    /// minimum and (bounded) maximum.
    pub fn values_tried(kind: Kind, default: &str) -> Vec<String> {
        let mut out: Vec<String> = match kind {
            Kind::Choice(names) => names.iter().map(|n| n.to_string()).collect(),
            Kind::Count { min, max } => {
                let d: u32 = default.parse().unwrap_or(min);
                let mut v = vec![min, min.saturating_add(1), d.saturating_add(1)];
                if max < u32::MAX {
                    v.push(max);
                }
                v.into_iter().filter(|&x| x <= max).map(|x| x.to_string()).collect()
            }
            Kind::Number { min, max } => {
                let mut v = vec![min.to_string()];
                if max < f32::MAX {
                    v.push(max.to_string());
                }
                v
            }
        };
        out.dedup();
        out
    }

    /// `t`'s settings (`(key, value)`, as `Configured::values`) at its defaults and with each
    /// setting at each of [`values_tried`], one at a time, where the technique accepts them:
    /// the settings every check of the published contract runs through.
    pub fn settings_tried(t: &'static dyn Registered) -> Vec<Vec<(&'static str, String)>> {
        let defaults = t.configure();
        let mut out = vec![defaults.values()];
        for (key, default) in defaults.values() {
            let row = t.rows().into_iter().find(|r| r.key == key).expect("a row per value");
            for value in values_tried(row.kind, &default) {
                let mut c = t.configure();
                if c.set(key, &value).is_ok() && c.validate().is_ok() {
                    out.push(c.values());
                }
            }
        }
        out
    }

    /// The constants structs `t` uses at its defaults and with each setting at each of
    /// [`values_tried`] (one at a time; values its checks refuse are skipped), for the frame
    /// `super::reference_frame`.
    pub fn structs_of(
        t: &'static dyn Registered,
        modules: &[ModuleManifest],
        structs: &[StructManifest],
    ) -> Result<Vec<String>, String> {
        let frame = super::reference_frame(aokit_shaders::glam::UVec2::new(1920, 1080), 64);
        let mut used = Vec::new();
        let defaults = t.configure();
        used_structs(&defaults.graph(&frame)?, modules, structs, &mut used)?;
        for (key, default) in defaults.values() {
            let row = t.rows().into_iter().find(|r| r.key == key).expect("a row per value");
            for value in values_tried(row.kind, &default) {
                let mut c = t.configure();
                if let Ok(graph) = c.set(key, &value).and_then(|_| c.graph(&frame)) {
                    used_structs(&graph, modules, structs, &mut used)?;
                }
            }
        }
        Ok(used)
    }

    /// Every field of every constants struct `t` uses with its expression and its prose,
    /// structs in `structs` order. Fails where a field has no expression or an empty prose, a
    /// row names a field that does not exist (or twice), an expression does not parse or names a
    /// setting `t` does not read (after its fixed settings are substituted), or the prose refers
    /// to a `Struct.field` or a setting key that does not exist.
    pub fn of(
        t: &'static dyn Registered,
        modules: &[ModuleManifest],
        structs: &[StructManifest],
    ) -> Result<Vec<ConstantManifest>, String> {
        let name = t.name();
        let rows = t.constants();
        let keys: Vec<&str> =
            aokit_shaders::techniques::TECHNIQUES.iter().flat_map(|t| t.rows()).map(|r| r.key).collect();
        for (i, row) in rows.iter().enumerate() {
            let (s, f) = row.path();
            let exists = structs.iter().any(|st| st.name == s && st.fields.iter().any(|x| x.name == f));
            if !exists {
                return Err(format!("{name}: constant {}: no field {f} in a shared struct {s}", row.field));
            }
            if rows[..i].iter().any(|r| r.field == row.field) {
                return Err(format!("{name}: constant {} declared twice", row.field));
            }
            if row.formula.trim().is_empty() {
                return Err(format!("{name}: constant {} has an empty formula", row.field));
            }
            let expr = crate::constants::expression(t, row.expr);
            let own: Vec<&str> = t.rows().iter().map(|r| r.key).collect();
            if let Some(key) = crate::expr::settings_named(&expr).into_iter().find(|k| !own.contains(k)) {
                return Err(format!(
                    "{name}: constant {}: its expression names `{key}`, not a setting of {name}",
                    row.field
                ));
            }
            if !row.expr.is_empty() && !structs.iter().any(|s| s.name == expr) {
                crate::expr::parse(&expr).map_err(|e| format!("{name}: constant {}: {e}", row.field))?;
            }
            // Setting keys are in backticks.
            for (j, key) in row.formula.split('`').enumerate() {
                if j % 2 == 1 && !keys.contains(&key) {
                    return Err(format!("{name}: constant {}: `{key}` is no technique's setting", row.field));
                }
            }
            // `Struct.field` references.
            let words = row.formula.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == '.'));
            for word in words {
                let Some((s, f)) = word.trim_end_matches('.').split_once('.') else { continue };
                let Some(st) = structs.iter().find(|st| st.name == s) else { continue };
                if !st.fields.iter().any(|x| x.name == f) {
                    return Err(format!(
                        "{name}: constant {}: its formula names {s}.{f}, which does not exist",
                        row.field
                    ));
                }
            }
        }
        let used = structs_of(t, modules, structs)?;
        let mut out = Vec::new();
        for s in structs.iter().filter(|s| used.contains(&s.name)) {
            for f in &s.fields {
                let row = rows.iter().find(|r| r.path() == (s.name.as_str(), f.name.as_str())).ok_or_else(|| {
                    format!(
                        "{name}: {}.{} ({}, offset {}) has no formula: its passes use {}; add a row to the \
                         technique's constants (aokit_shaders::technique::Constant)",
                        s.name, f.name, f.ty, f.offset, s.name
                    )
                })?;
                if row.expr.is_empty() {
                    return Err(format!("{name}: {}.{} has no expression (Constant::expr)", s.name, f.name));
                }
                out.push(ConstantManifest {
                    struct_name: s.name.clone(),
                    field: f.name.clone(),
                    offset: f.offset,
                    ty: f.ty.clone(),
                    expr: crate::constants::expression(t, row.expr),
                    doc: row.formula.into(),
                });
            }
        }
        Ok(out)
    }
}
