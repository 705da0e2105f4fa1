//! wgpu's adapter on the Vulkan back-end (lavapipe here), for the tests that drive wgpu.

/// The Vulkan adapter wgpu picks; `None` (after `skip::cannot_run`, which fails unless the run
/// allows the skip) when there is none.
pub fn vulkan() -> Option<wgpu::Adapter> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::VULKAN,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    match pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default())) {
        Ok(adapter) => Some(adapter),
        Err(e) => {
            super::skip::cannot_run(
                super::skip::VULKAN,
                &format!("no Vulkan adapter for wgpu ({e}; apt-get install mesa-vulkan-drivers)"),
            );
            None
        }
    }
}
