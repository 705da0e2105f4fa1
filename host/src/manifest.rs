//! `assets/spirv/manifest.json`: what an engine needs to use the SPIR-V without Rust — entry
//! points, stages, descriptor bindings, push-constant sizes — plus the hash of the shader
//! sources the modules were built from.

use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    /// [`crate::spirv_hash::shader_source_hash`] of the sources the modules were built from.
    pub source_hash: String,
    /// rust-gpu target triple.
    pub target: String,
    /// rust-gpu (spirv-std) version.
    pub rust_gpu: String,
    pub modules: Vec<ModuleManifest>,
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
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BindingManifest {
    pub set: u32,
    pub binding: u32,
    /// "storage_buffer", "uniform_buffer", "texture", "sampler", …
    pub kind: String,
    pub writable: bool,
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
                    bindings.push(BindingManifest { set: b.group, binding: b.binding, kind: kind.into(), writable });
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
        })
    }
}

/// A minimal reader of SPIR-V words: entry point, execution model and descriptor bindings of
/// ray-tracing modules (SPIR-V spec §2.3 physical layout, §3 enumerants).
#[cfg(feature = "reflect")]
pub mod words {
    use super::{BindingManifest, ModuleManifest};
    use std::collections::HashMap;

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
        for (op, a) in &ins {
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
            bindings.push(BindingManifest { set: s, binding: b, kind: kind.into(), writable });
        }
        bindings.sort_by_key(|b| (b.set, b.binding));
        Ok(ModuleManifest {
            entry_point,
            file: file.into(),
            stage: stage.into(),
            workgroup_size: None,
            bindings,
            push_constant_bytes: 0,
        })
    }
}
