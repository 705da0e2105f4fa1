//! Helpers shared by the integration tests.
#![allow(dead_code)]

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::VulkanRenderer;
use aokit::scene::Scene;
use aokit::scene::builtin;
use aokit_vulkan::GpuOptions;

/// Open the Vulkan back-end with the Khronos validation layer. Vulkan tests must not pass by
/// silently skipping: without a device they fail, unless AOKIT_SKIP_VULKAN=1 says to skip.
pub fn vulkan() -> Option<VulkanRenderer> {
    if std::env::var_os("AOKIT_SKIP_VULKAN").is_some_and(|v| v == "1") {
        eprintln!("AOKIT_SKIP_VULKAN=1: skipping a Vulkan test");
        return None;
    }
    match VulkanRenderer::new(&GpuOptions { validation: true }) {
        Ok(r) => Some(r),
        Err(e) => panic!("Vulkan with validation is required for this test ({e}); set AOKIT_SKIP_VULKAN=1 to skip"),
    }
}

/// Fail on any validation warning or error.
pub fn assert_validation_clean(r: &VulkanRenderer) {
    let messages = r.gpu.validation_messages();
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}

/// A built-in scene (fetched and cached on first use) with its default camera.
pub fn builtin_frame(name: &str, width: u32, height: u32, guard: u32) -> (Scene, Frame) {
    let b = builtin::find(name).expect("built-in scene");
    let scene = b.load().unwrap_or_else(|e| panic!("{e}"));
    let req = FrameRequest {
        width,
        height,
        guard,
        camera: CameraChoice::Preset { name: None, fov_deg: None },
        radius: None,
        exponent: 2.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, Some(b), &req).unwrap();
    (scene, frame)
}
