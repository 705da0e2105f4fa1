//! `aokit info`, `aokit scenes` and `aokit techniques`: what this machine and this build offer.

use aokit::scene::builtin;
use aokit_vulkan::{Gpu, GpuOptions};

/// `aokit info`: the Vulkan device aokit would use and its ray-tracing extensions.
pub fn info(validation: bool) -> Result<(), String> {
    let gpu = Gpu::new(&GpuOptions { validation, ..Default::default() }).map_err(|e| e.to_string())?;
    let info = gpu.info();
    println!("{}", serde_json::to_string(info).expect("serializable"));
    eprintln!("device: {} ({}, Vulkan {})", info.name, info.device_type, info.api_version);
    for (ext, has) in &info.ray_tracing_extensions {
        eprintln!("  {ext}: {}", if *has { "yes" } else { "no" });
    }
    Ok(())
}

/// `aokit techniques`: each technique's settings (key, accepted values, default, flag).
pub fn techniques() -> Result<(), String> {
    print!("{}", aokit::cli::list_techniques());
    Ok(())
}

/// `aokit scenes`: the built-in scenes and their camera presets.
pub fn scenes() -> Result<(), String> {
    for s in builtin::builtin_scenes() {
        let cams: Vec<_> = s.cameras.iter().map(|c| c.name).collect();
        println!("{:8} {} — cameras: {}; radius {}", s.name, s.description, cams.join(", "), s.radius);
    }
    Ok(())
}
