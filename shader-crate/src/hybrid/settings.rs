//! Settings, the paper's variants and the pass graph of the hybrid AO (host side; spec
//! gtao-raymarch-hybrid §4): one ray-generation pass (screen rays marched, world rays traced),
//! then XeGTAO's denoiser.

use super::{HybridFrame, HybridParams};
use crate::graph::{Access, Binding, FrameDesc, Graph, Pass, PassKind, inputs, record, slots, target_f32, target_u32};
use crate::gtao::settings::with_denoiser;
use crate::raymarch::settings::DEPTH_BIAS;

/// Rays per pixel and the world-ray weight (spec §4.1 defaults in brackets).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct HybridSettings {
    /// Screen-space rays per pixel [1].
    pub screen_rays: u32,
    /// World-space rays per pixel [1].
    pub world_rays: u32,
    /// Weight of the world rays, 0–1 [2/3].
    pub world_weight: f32,
    /// Steps of a screen ray [16].
    pub screen_steps: u32,
    /// XeGTAO denoise passes, 0–3 [3].
    pub denoise_passes: u32,
}

impl Default for HybridSettings {
    fn default() -> Self {
        HybridSettings { screen_rays: 1, world_rays: 1, world_weight: 2.0 / 3.0, screen_steps: 16, denoise_passes: 3 }
    }
}

impl HybridSettings {
    /// The paper's variants (spec §4.2, last paragraph): `mixed` (1 screen + 1 world, w = 2/3), `world` (2 world
    /// rays), `screen` (2 screen rays).
    pub fn variant(name: &str) -> Result<HybridSettings, String> {
        let d = HybridSettings::default();
        Ok(match name {
            "mixed" => d,
            "world" => HybridSettings { screen_rays: 0, world_rays: 2, world_weight: 1.0, ..d },
            "screen" => HybridSettings { screen_rays: 2, world_rays: 0, world_weight: 0.0, ..d },
            _ => return Err(format!("hybrid variant '{name}' is not mixed, world or screen")),
        })
    }

    pub fn validate(&self) -> Result<(), String> {
        if !(0.0..=1.0).contains(&self.world_weight) || self.screen_rays + self.world_rays == 0 {
            return Err("hybrid needs a world weight in [0, 1] and at least one ray".into());
        }
        if self.denoise_passes > 3 {
            return Err(format!("--hybrid-denoise {} is not 0–3", self.denoise_passes));
        }
        Ok(())
    }

    /// The kernel's record for a frame.
    pub fn frame(&self, frame: &FrameDesc) -> HybridFrame {
        HybridFrame {
            camera: frame.camera,
            params: HybridParams {
                radius: frame.radius,
                world_weight: self.world_weight,
                depth_bias: DEPTH_BIAS,
                screen_rays: self.screen_rays,
                world_rays: self.world_rays,
                screen_steps: self.screen_steps,
                noise_frame: 0,
                _pad: 0,
            },
        }
    }

    /// Rays per frame over the inner image.
    pub fn rays(&self, frame: &FrameDesc) -> u64 {
        let inner = frame.inner();
        (self.screen_rays + self.world_rays) as u64 * inner.x as u64 * inner.y as u64
    }

    /// Rays → [denoise].
    pub fn graph(&self, frame: &FrameDesc) -> Graph {
        let resources = vec![
            record("hybrid_frame", std::slice::from_ref(&self.frame(frame)), "camera + HybridParams"),
            target_f32(frame, "ao", 1.0, "blended screen/world visibility (spec §4.2 step 5), 1 = unoccluded"),
            target_u32(frame, "ao_terms", 0, "the AO as the denoiser's 0–255 terms"),
            target_u32(frame, "ao_edges", 0, "packed depth edges for the denoiser"),
        ];
        let mut bindings = slots(&[
            ("hybrid_frame", Access::Read),
            (inputs::SCENE_TLAS, Access::Read),
            (inputs::LINEAR_DEPTH, Access::Read),
            (inputs::VIEW_NORMALS, Access::Read),
            ("ao", Access::Write),
        ]);
        bindings.extend(crate::groundtruth::settings::alpha_bindings(5));
        bindings.push(Binding { slot: 9, resource: "ao_terms", access: Access::Write });
        bindings.push(Binding { slot: 10, resource: "ao_edges", access: Access::Write });
        let passes = vec![Pass {
            label: "hybrid_rays",
            entry: "hybrid_rgen",
            kind: PassKind::RayTracing { miss: "groundtruth_miss", any_hit: "groundtruth_ahit" },
            bindings,
            invocations: frame.size(),
            push_constants: Vec::new(),
        }];
        with_denoiser(frame, resources, passes, self.denoise_passes)
    }
}
