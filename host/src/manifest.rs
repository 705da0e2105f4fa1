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
