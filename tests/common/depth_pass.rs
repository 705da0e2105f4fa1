//! An application's depth pass, as the tests and benchmarks stand in for it: a full-screen
//! triangle writing given values as `frag_depth` into a `Depth32Float` texture (WebGPU copies
//! nothing into a depth texture, so a render pass is how an application's depth gets there).
//! Self-contained (wgpu and bytemuck only): the peers benchmark includes it by path.

use wgpu::util::DeviceExt;

const DEPTH_PASS_WGSL: &str = "
@group(0) @binding(0) var<storage, read> depth: array<f32>;
@group(0) @binding(1) var<uniform> width: vec4<u32>;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let p = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4<f32>(p * 2.0 - 1.0, 0.0, 1.0);
}
@fragment fn fs(@builtin(position) p: vec4<f32>) -> @builtin(frag_depth) f32 {
    return depth[u32(p.y) * width.x + u32(p.x)];
}
";

/// Record into `encoder` a depth pass that writes `values` (row-major, `width` per row, one per
/// texel of the view) into `depth`, a view of a `Depth32Float` texture with `RENDER_ATTACHMENT`.
pub fn record(
    device: &wgpu::Device,
    encoder: &mut wgpu::CommandEncoder,
    depth: &wgpu::TextureView,
    values: &[f32],
    width: u32,
) {
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("depth pass"),
        source: wgpu::ShaderSource::Wgsl(DEPTH_PASS_WGSL.into()),
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("depth pass"),
        layout: None,
        vertex: wgpu::VertexState {
            module: &shader,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: Default::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: wgpu::TextureFormat::Depth32Float,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &shader,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[],
        }),
        multiview_mask: None,
        cache: None,
    });
    let values = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("depth values"),
        contents: bytemuck::cast_slice(values),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let width = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("depth width"),
        contents: bytemuck::cast_slice(&[width, 0, 0, 0]),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("depth pass"),
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: values.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 1, resource: width.as_entire_binding() },
        ],
    });
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("depth pass"),
        color_attachments: &[],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(0.0), store: wgpu::StoreOp::Store }),
            stencil_ops: None,
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    });
    pass.set_pipeline(&pipeline);
    pass.set_bind_group(0, &group, &[]);
    pass.draw(0..3, 0..1);
}
