//! Ray tracing on Vulkan: one BLAS over the scene's triangle soup, a one-instance TLAS, and the
//! ground-truth ray-tracing pipeline (raygen + miss + any-hit for alpha-masked geometry) with
//! its shader binding table (layout per `shared/notes/lavapipe-rt.md`).

use crate::descriptors::Descriptor;
use crate::{Buffer, Gpu, GpuError};
use aokit_shaders::common::alpha::AlphaMaskHeader;
use aokit_shaders::glam::Vec2;
use ash::vk;
use gpu_allocator::MemoryLocation;

impl Gpu {
    fn device_address(&self, buffer: &Buffer) -> u64 {
        unsafe { self.device.get_buffer_device_address(&vk::BufferDeviceAddressInfo::default().buffer(buffer.raw)) }
    }

    /// Build an acceleration structure of `ty` from `geometry` with `primitives` primitives.
    fn build_acceleration_structure(
        &self,
        ty: vk::AccelerationStructureTypeKHR,
        geometry: vk::AccelerationStructureGeometryKHR,
        primitives: u32,
    ) -> Result<(vk::AccelerationStructureKHR, Buffer), GpuError> {
        let rt = self.ray_tracing()?;
        let geometries = [geometry];
        let mut info = vk::AccelerationStructureBuildGeometryInfoKHR::default()
            .ty(ty)
            .flags(vk::BuildAccelerationStructureFlagsKHR::PREFER_FAST_TRACE)
            .mode(vk::BuildAccelerationStructureModeKHR::BUILD)
            .geometries(&geometries);
        let mut sizes = vk::AccelerationStructureBuildSizesInfoKHR::default();
        unsafe {
            rt.acceleration.get_acceleration_structure_build_sizes(
                vk::AccelerationStructureBuildTypeKHR::DEVICE,
                &info,
                &[primitives],
                &mut sizes,
            )
        };
        let storage = self.create_buffer(
            sizes.acceleration_structure_size,
            vk::BufferUsageFlags::ACCELERATION_STRUCTURE_STORAGE_KHR | vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS,
            MemoryLocation::GpuOnly,
        )?;
        let align = rt.limits.scratch_alignment.max(1) as u64;
        let scratch = self.create_buffer(
            sizes.build_scratch_size + align,
            vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS,
            MemoryLocation::GpuOnly,
        )?;
        let created = unsafe {
            rt.acceleration.create_acceleration_structure(
                &vk::AccelerationStructureCreateInfoKHR::default()
                    .buffer(storage.raw)
                    .size(sizes.acceleration_structure_size)
                    .ty(ty),
                None,
            )
        };
        let result = created.map_err(GpuError::from).and_then(|handle| {
            info = info.dst_acceleration_structure(handle).scratch_data(vk::DeviceOrHostAddressKHR {
                device_address: self.device_address(&scratch).next_multiple_of(align),
            });
            let range = [vk::AccelerationStructureBuildRangeInfoKHR::default().primitive_count(primitives)];
            self.submit(|cb| unsafe {
                rt.acceleration.cmd_build_acceleration_structures(cb, &[info], &[&range]);
                let barrier = vk::MemoryBarrier::default()
                    .src_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_WRITE_KHR)
                    .dst_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_READ_KHR);
                self.device.cmd_pipeline_barrier(
                    cb,
                    vk::PipelineStageFlags::ACCELERATION_STRUCTURE_BUILD_KHR,
                    vk::PipelineStageFlags::ACCELERATION_STRUCTURE_BUILD_KHR
                        | vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR,
                    vk::DependencyFlags::empty(),
                    &[barrier],
                    &[],
                    &[],
                );
            })
            .map(|_| handle)
            .inspect_err(|_| unsafe { rt.acceleration.destroy_acceleration_structure(handle, None) })
        });
        self.free_buffer(scratch);
        match result {
            Ok(handle) => Ok((handle, storage)),
            Err(e) => {
                self.free_buffer(storage);
                Err(e)
            }
        }
    }
}

/// The scene on the device for ray tracing: the TLAS (aokit's own BLAS + TLAS, or the caller's
/// TLAS) and the per-triangle attributes the any-hit shaders read.
pub struct SceneAccel {
    /// aokit's BLAS and TLAS with their storage; `None` when the TLAS is the caller's.
    owned: Option<[(vk::AccelerationStructureKHR, Buffer); 2]>,
    tlas: vk::AccelerationStructureKHR,
    uvs: Buffer,
    materials: Buffer,
    mask_headers: Buffer,
    mask_texels: Buffer,
    /// Wall time of the build in milliseconds (0 for the engine's TLAS).
    pub build_ms: f64,
    generation: u64,
}

impl SceneAccel {
    /// The alpha-test buffer bound as graph input `name` (`aokit_shaders::graph::inputs`).
    pub(crate) fn alpha_buffer(&self, name: &str) -> Option<&Buffer> {
        use aokit_shaders::graph::inputs;
        Some(match name {
            inputs::SCENE_UVS => &self.uvs,
            inputs::SCENE_MATERIALS => &self.materials,
            inputs::SCENE_MASK_HEADERS => &self.mask_headers,
            inputs::SCENE_MASK_TEXELS => &self.mask_texels,
            _ => return None,
        })
    }

    /// A number no other acceleration structure built in this process has (a destroyed TLAS's
    /// handle may be reused by the next one; descriptor sets must not be).
    pub(crate) fn identity(&self) -> u64 {
        self.generation
    }

    /// The TLAS as a descriptor.
    pub(crate) fn tlas_descriptor(&self) -> Descriptor<'static> {
        Descriptor::Tlas(self.tlas)
    }

    /// `positions`: three corners per triangle. Geometry is marked opaque unless some material
    /// has an alpha mask (then every triangle runs the any-hit alpha test).
    pub fn build(
        gpu: &Gpu,
        positions: &[[f32; 3]],
        uvs: &[Vec2],
        materials: &[u32],
        masks: &(Vec<AlphaMaskHeader>, Vec<f32>),
    ) -> Result<SceneAccel, GpuError> {
        let triangles = (positions.len() / 3) as u32;
        if triangles == 0 || uvs.len() != positions.len() || materials.len() != triangles as usize {
            return Err(GpuError::Input(format!(
                "ray-tracing scene: {} corners, {} uvs, {} materials",
                positions.len(),
                uvs.len(),
                materials.len()
            )));
        }
        let start = std::time::Instant::now();
        let input = vk::BufferUsageFlags::ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_KHR
            | vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS;
        let vertices = gpu.upload(positions, input)?;
        let masked = masks.0.iter().any(|h| h.width > 0);
        let flags = if masked { vk::GeometryFlagsKHR::empty() } else { vk::GeometryFlagsKHR::OPAQUE };
        let triangles_data = vk::AccelerationStructureGeometryTrianglesDataKHR::default()
            .vertex_format(vk::Format::R32G32B32_SFLOAT)
            .vertex_data(vk::DeviceOrHostAddressConstKHR { device_address: gpu.device_address(&vertices) })
            .vertex_stride(12)
            .max_vertex(positions.len() as u32 - 1)
            .index_type(vk::IndexType::NONE_KHR);
        let geometry = vk::AccelerationStructureGeometryKHR::default()
            .geometry_type(vk::GeometryTypeKHR::TRIANGLES)
            .geometry(vk::AccelerationStructureGeometryDataKHR { triangles: triangles_data })
            .flags(flags);
        let blas =
            gpu.build_acceleration_structure(vk::AccelerationStructureTypeKHR::BOTTOM_LEVEL, geometry, triangles);
        gpu.free_buffer(vertices);
        let blas = blas?;
        let rt = gpu.ray_tracing()?;
        let blas_address = unsafe {
            rt.acceleration.get_acceleration_structure_device_address(
                &vk::AccelerationStructureDeviceAddressInfoKHR::default().acceleration_structure(blas.0),
            )
        };
        let instance = vk::AccelerationStructureInstanceKHR {
            transform: vk::TransformMatrixKHR { matrix: [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0] },
            instance_custom_index_and_mask: vk::Packed24_8::new(0, 0xff),
            instance_shader_binding_table_record_offset_and_flags: vk::Packed24_8::new(
                0,
                vk::GeometryInstanceFlagsKHR::TRIANGLE_FACING_CULL_DISABLE.as_raw() as u8,
            ),
            acceleration_structure_reference: vk::AccelerationStructureReferenceKHR { device_handle: blas_address },
        };
        let instance_bytes = unsafe {
            std::slice::from_raw_parts(
                &instance as *const _ as *const u8,
                size_of::<vk::AccelerationStructureInstanceKHR>(),
            )
        };
        let instances = gpu.upload(instance_bytes, input)?;
        let instances_data = vk::AccelerationStructureGeometryInstancesDataKHR::default()
            .data(vk::DeviceOrHostAddressConstKHR { device_address: gpu.device_address(&instances) });
        let geometry = vk::AccelerationStructureGeometryKHR::default()
            .geometry_type(vk::GeometryTypeKHR::INSTANCES)
            .geometry(vk::AccelerationStructureGeometryDataKHR { instances: instances_data });
        let tlas = gpu.build_acceleration_structure(vk::AccelerationStructureTypeKHR::TOP_LEVEL, geometry, 1);
        gpu.free_buffer(instances);
        let tlas = match tlas {
            Ok(t) => t,
            Err(e) => {
                unsafe { rt.acceleration.destroy_acceleration_structure(blas.0, None) };
                gpu.free_buffer(blas.1);
                return Err(e);
            }
        };
        let mut accel = match SceneAccel::with_tables(gpu, tlas.0, uvs, materials, masks) {
            Ok(a) => a,
            Err(e) => {
                for (handle, storage) in [blas, tlas] {
                    unsafe { rt.acceleration.destroy_acceleration_structure(handle, None) };
                    gpu.free_buffer(storage);
                }
                return Err(e);
            }
        };
        accel.owned = Some([blas, tlas]);
        accel.build_ms = start.elapsed().as_secs_f64() * 1e3;
        Ok(accel)
    }

    /// The caller's own TLAS (an engine's), with the per-triangle tables its any-hit alpha test
    /// reads. aokit never builds, updates or destroys `tlas`; it must stay valid while graphs
    /// that trace rays are recorded with this scene and until those command buffers complete.
    ///
    /// Conventions the TLAS must follow (what aokit's own TLAS does):
    /// - triangle geometry, one geometry per BLAS; `uvs` has 3 corners per triangle and
    ///   `materials` one material per triangle, over every BLAS's triangles concatenated;
    /// - every instance's custom index is the index of its BLAS's first triangle in those
    ///   tables (the any-hit reads triangle `InstanceCustomIndex + PrimitiveId`; 24 bits, so
    ///   at most 2^24 triangles; a triangle beyond the tables is treated as opaque);
    /// - a non-zero instance mask (aokit traces with cull mask 0xff) and SBT record offset 0
    ///   (aokit's pipelines have one hit group); facing does not matter (rays do not cull);
    /// - geometry with alpha-masked materials neither `OPAQUE` nor in an instance flagged
    ///   `FORCE_OPAQUE` (the ground truth and hybrid skip the any-hit, and so the alpha test,
    ///   on opaque triangles); Ray-SD's stochastic depth map and Ray-SVAO trace with
    ///   `NO_OPAQUE`, so their any-hit sees every triangle anyway.
    pub fn from_engine_tlas(
        gpu: &Gpu,
        tlas: vk::AccelerationStructureKHR,
        uvs: &[Vec2],
        materials: &[u32],
        masks: &(Vec<AlphaMaskHeader>, Vec<f32>),
    ) -> Result<SceneAccel, GpuError> {
        gpu.ray_tracing()?;
        if tlas == vk::AccelerationStructureKHR::null() || materials.is_empty() || uvs.len() != 3 * materials.len() {
            return Err(GpuError::Input(format!(
                "engine TLAS: {} uvs for {} materials (3 corners per triangle), TLAS {}",
                uvs.len(),
                materials.len(),
                if tlas == vk::AccelerationStructureKHR::null() { "null" } else { "given" }
            )));
        }
        SceneAccel::with_tables(gpu, tlas, uvs, materials, masks)
    }

    /// `tlas` (not owned) and the tables uploaded.
    fn with_tables(
        gpu: &Gpu,
        tlas: vk::AccelerationStructureKHR,
        uvs: &[Vec2],
        materials: &[u32],
        masks: &(Vec<AlphaMaskHeader>, Vec<f32>),
    ) -> Result<SceneAccel, GpuError> {
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let mut uploaded = Vec::new();
        let tables: [&[u8]; 4] = [
            bytemuck::cast_slice(uvs),
            bytemuck::cast_slice(materials),
            bytemuck::cast_slice(&masks.0),
            bytemuck::cast_slice(&masks.1),
        ];
        for bytes in tables {
            // Empty tables (no masks) still bind a buffer.
            let padded: &[u8] = if bytes.is_empty() { &[0; 4] } else { bytes };
            match gpu.upload(padded, storage) {
                Ok(b) => uploaded.push(b),
                Err(e) => {
                    uploaded.into_iter().for_each(|b| gpu.free_buffer(b));
                    return Err(e);
                }
            }
        }
        let [uvs, materials, mask_headers, mask_texels] = <[Buffer; 4]>::try_from(uploaded).ok().expect("four tables");
        static BUILT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
        Ok(SceneAccel {
            owned: None,
            tlas,
            uvs,
            materials,
            mask_headers,
            mask_texels,
            build_ms: 0.0,
            generation: BUILT.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
        })
    }

    /// Frees aokit's buffers and its own BLAS/TLAS (never the caller's TLAS).
    pub fn destroy(self, gpu: &Gpu) {
        for (handle, storage) in self.owned.into_iter().flatten() {
            if let Some(rt) = &gpu.ray_tracing {
                unsafe { rt.acceleration.destroy_acceleration_structure(handle, None) };
            }
            gpu.free_buffer(storage);
        }
        for b in [self.uvs, self.materials, self.mask_headers, self.mask_texels] {
            gpu.free_buffer(b);
        }
    }
}

/// A ray-tracing pipeline of one ray-generation, one miss and one any-hit shader (a triangle
/// hit group), its descriptor set layout and its shader binding table.
pub(crate) struct RtPipeline {
    pub(crate) set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
    sbt: Buffer,
    regions: [vk::StridedDeviceAddressRegionKHR; 3],
    pub(crate) bindings: Vec<vk::DescriptorType>,
}

impl RtPipeline {
    /// `shaders`: (SPIR-V, entry point) of the ray-generation, miss and any-hit stages;
    /// `bindings`: descriptor types of set 0 in binding order.
    pub(crate) fn new(
        gpu: &Gpu,
        shaders: [(&[u8], &std::ffi::CStr); 3],
        bindings: Vec<vk::DescriptorType>,
    ) -> Result<Self, GpuError> {
        let (rt, pipelines) = gpu.ray_pipelines()?;
        let d = &gpu.device;
        let stages_all = vk::ShaderStageFlags::RAYGEN_KHR | vk::ShaderStageFlags::ANY_HIT_KHR;
        unsafe {
            let set_layout = gpu.set_layout(&bindings, stages_all)?;
            let set_layouts = [set_layout];
            let layout =
                d.create_pipeline_layout(&vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts), None)?;
            let kinds =
                [vk::ShaderStageFlags::RAYGEN_KHR, vk::ShaderStageFlags::MISS_KHR, vk::ShaderStageFlags::ANY_HIT_KHR];
            let mut modules = Vec::new();
            for (spirv, _) in &shaders {
                modules.push(gpu.shader_module(spirv)?);
            }
            let stages: Vec<_> = (0..3)
                .map(|i| {
                    vk::PipelineShaderStageCreateInfo::default().stage(kinds[i]).module(modules[i]).name(shaders[i].1)
                })
                .collect();
            let general = |stage: u32| {
                vk::RayTracingShaderGroupCreateInfoKHR::default()
                    .ty(vk::RayTracingShaderGroupTypeKHR::GENERAL)
                    .general_shader(stage)
                    .closest_hit_shader(vk::SHADER_UNUSED_KHR)
                    .any_hit_shader(vk::SHADER_UNUSED_KHR)
                    .intersection_shader(vk::SHADER_UNUSED_KHR)
            };
            let groups = [
                general(0),
                general(1),
                vk::RayTracingShaderGroupCreateInfoKHR::default()
                    .ty(vk::RayTracingShaderGroupTypeKHR::TRIANGLES_HIT_GROUP)
                    .general_shader(vk::SHADER_UNUSED_KHR)
                    .closest_hit_shader(vk::SHADER_UNUSED_KHR)
                    .any_hit_shader(2)
                    .intersection_shader(vk::SHADER_UNUSED_KHR),
            ];
            let info = vk::RayTracingPipelineCreateInfoKHR::default()
                .stages(&stages)
                .groups(&groups)
                .max_pipeline_ray_recursion_depth(1)
                .layout(layout);
            let created = pipelines.create_ray_tracing_pipelines(
                vk::DeferredOperationKHR::null(),
                vk::PipelineCache::null(),
                &[info],
                None,
            );
            for m in modules {
                d.destroy_shader_module(m, None);
            }
            let pipeline = created.map_err(|(_, e)| e)?[0];
            // Shader binding table: one record per group, each region base-aligned.
            let limits = rt.limits;
            let (hs, ha, ba) =
                (limits.handle_size as u64, limits.handle_alignment as u64, limits.base_alignment as u64);
            let stride = hs.next_multiple_of(ha);
            let region = stride.next_multiple_of(ba);
            let handles = pipelines.get_ray_tracing_shader_group_handles(pipeline, 0, 3, 3 * hs as usize)?;
            let mut table = vec![0u8; (3 * region + ba) as usize];
            let sbt = gpu.create_buffer(
                table.len() as u64,
                vk::BufferUsageFlags::SHADER_BINDING_TABLE_KHR | vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS,
                MemoryLocation::CpuToGpu,
            )?;
            let address = gpu.device_address(&sbt);
            let base = address.next_multiple_of(ba);
            for g in 0..3u64 {
                let at = (base - address + g * region) as usize;
                table[at..at + hs as usize].copy_from_slice(&handles[(g * hs) as usize..((g + 1) * hs) as usize]);
            }
            sbt.write(&table);
            let r =
                |g: u64| vk::StridedDeviceAddressRegionKHR { device_address: base + g * region, stride, size: stride };
            Ok(RtPipeline { set_layout, layout, pipeline, sbt, regions: [r(0), r(1), r(2)], bindings })
        }
    }

    /// Record `vkCmdTraceRaysKHR` over `width × height` with descriptor set `set`.
    pub(crate) fn record_trace(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        set: vk::DescriptorSet,
        width: u32,
        height: u32,
    ) -> Result<(), GpuError> {
        let (_, pipelines) = gpu.ray_pipelines()?;
        let d = &gpu.device;
        unsafe {
            d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::RAY_TRACING_KHR, self.pipeline);
            d.cmd_bind_descriptor_sets(cb, vk::PipelineBindPoint::RAY_TRACING_KHR, self.layout, 0, &[set], &[]);
            let [raygen, miss, hit] = &self.regions;
            pipelines.cmd_trace_rays(cb, raygen, miss, hit, &Default::default(), width, height, 1);
        }
        Ok(())
    }

    pub(crate) fn destroy(self, gpu: &Gpu) {
        unsafe {
            gpu.device.destroy_pipeline(self.pipeline, None);
            gpu.device.destroy_pipeline_layout(self.layout, None);
            gpu.device.destroy_descriptor_set_layout(self.set_layout, None);
        }
        gpu.free_buffer(self.sbt);
    }
}
