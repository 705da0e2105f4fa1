//! Settings, the paper's variants and the pass graph of the hybrid AO (host side; spec
//! gtao-raymarch-hybrid §4): one ray-generation pass (screen rays marched, world rays traced),
//! then XeGTAO's denoiser.

use super::{HybridFrame, HybridParams};
use crate::graph::{Extent, FrameDesc, Graph, Pass, RAY_COUNT, inputs, ray_counter, record, target_f32, target_u32};
use crate::gtao::settings::with_denoiser;
use crate::raymarch::settings::DEPTH_BIAS;
use crate::technique::{Constant, Declaration, Setting, Settings, single_layer};

/// Rays per pixel and the world-ray weight (spec gtao-raymarch-hybrid §4.1 defaults in brackets).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct HybridSettings {
    /// Screen-space rays per pixel \[1\].
    pub screen_rays: u32,
    /// World-space rays per pixel \[1\].
    pub world_rays: u32,
    /// Weight of the world rays, 0–1 [2/3].
    pub world_weight: f32,
    /// Steps of a screen ray \[16\].
    pub screen_steps: u32,
    /// XeGTAO denoise passes, 0–3 \[3\].
    pub denoise_passes: u32,
}

impl Default for HybridSettings {
    fn default() -> Self {
        HybridSettings { screen_rays: 1, world_rays: 1, world_weight: 2.0 / 3.0, screen_steps: 16, denoise_passes: 3 }
    }
}

impl Settings for HybridSettings {
    const ROWS: &'static [Setting<Self>] = &[
        Setting::<Self>::choice("variant", &VARIANTS, variant_index, |s, i| {
            *s = HybridSettings { denoise_passes: s.denoise_passes, screen_steps: s.screen_steps, ..variant_at(i) }
        })
        .flag("hybrid-variant")
        .help(
            "Hybrid AO: mixed (1 screen + 1 world ray, world weight 2/3), world (2 world rays), screen (2 screen rays)",
        ),
        Setting::<Self>::number("world-weight", 0.0, 1.0, |s| &mut s.world_weight)
            .flag("world-weight")
            .help("Hybrid AO: weight of the world rays (set after the variant)"),
        Setting::<Self>::count("screen-steps", 1, 256, |s| &mut s.screen_steps)
            .flag("hybrid-screen-steps")
            .help("Hybrid AO: steps of a screen ray"),
        Setting::<Self>::count("denoise", 0, 3, |s| &mut s.denoise_passes)
            .flag("hybrid-denoise")
            .help("Hybrid AO: XeGTAO denoise passes afterwards"),
    ];

    fn check(&self) -> Result<(), String> {
        if self.screen_rays + self.world_rays == 0 {
            return Err("hybrid needs at least one ray per pixel".into());
        }
        // The blend (1 − w)·mean(screen) + w·mean(world) (spec gtao-raymarch-hybrid §4.2 step 5) needs both means
        // where both weights are non-zero.
        if (self.screen_rays == 0 && self.world_weight != 1.0) || (self.world_rays == 0 && self.world_weight != 0.0) {
            return Err(format!(
                "world-weight {}: the {} variant blends nothing else (use the mixed variant to weight)",
                self.world_weight,
                if self.screen_rays == 0 { "world" } else { "screen" }
            ));
        }
        Ok(())
    }
}

/// The paper's variants (spec gtao-raymarch-hybrid §4.2, last paragraph).
const VARIANTS: [&str; 3] = ["mixed", "world", "screen"];

/// Variant `i` of [`VARIANTS`]: `mixed` (1 screen + 1 world, w = 2/3), `world` (2 world rays),
/// `screen` (2 screen rays).
fn variant_at(i: usize) -> HybridSettings {
    let d = HybridSettings::default();
    match i {
        0 => d,
        1 => HybridSettings { screen_rays: 0, world_rays: 2, world_weight: 1.0, ..d },
        _ => HybridSettings { screen_rays: 2, world_rays: 0, world_weight: 0.0, ..d },
    }
}

/// Which variant the ray counts are (screen rays only → screen, world only → world).
fn variant_index(s: &HybridSettings) -> usize {
    match (s.screen_rays, s.world_rays) {
        (0, _) => 1,
        (_, 0) => 2,
        _ => 0,
    }
}

/// The hybrid screen + world-ray AO (spec gtao-raymarch-hybrid §4).
pub static HYBRID: Declaration<HybridSettings> = Declaration {
    name: "hybrid",
    summary: "hybrid AO: screen rays marched, world rays traced, denoised (spec gtao-raymarch-hybrid §4)",
    keys: &["variant", "world-weight", "screen-steps", "denoise"],
    defaults: HybridSettings::default,
    graph: |s, frame| Ok(s.graph(frame)),
    second_layer: single_layer,
    constants: CONSTANTS,
    formulas: &[],
    tables: &[],
};

/// How [`HybridSettings::frame`] fills `HybridFrame` and `HybridParams`, then the denoiser's
/// `GtaoParams` (`denoise` > 0) and the camera's rows.
pub const CONSTANTS: &[Constant] = crate::join_constants![
    &[
        Constant::new("HybridFrame.camera", "the frame's Camera (Camera and ViewParams rows)")
        .expr("Camera"),
        Constant::new("HybridFrame.params", "the technique's HybridParams (HybridParams rows)")
        .expr("HybridParams"),
        Constant::new("HybridParams.radius", "R: the frame's world-space AO radius, the rays' length (world units)")
        .expr("radius"),
        Constant::new(
            "HybridParams.world_weight",
            "`world-weight`, which `variant` sets first: mixed 2/3, world 1, screen 0 [2/3]",
        )
        .expr("`world-weight`"),
        Constant::new("HybridParams.depth_bias", "0.0008: relative depth bias κ of the screen march")
        .expr("0.0008"),
        Constant::new("HybridParams.screen_rays", "`variant`: mixed 1, world 0, screen 2 screen rays per pixel [1]")
        .expr("pick(index(`variant`), 1, 0, 2)"),
        Constant::new("HybridParams.world_rays", "`variant`: mixed 1, world 2, screen 0 world rays per pixel [1]")
        .expr("pick(index(`variant`), 1, 2, 0)"),
        Constant::new("HybridParams.screen_steps", "`screen-steps`: steps of a screen ray [16]")
        .expr("`screen-steps`"),
        Constant::new(
            "HybridParams.noise_frame",
            "the frame index (FrameDesc::frame_index; 0 for one frame), mod 64 in the noise (gtao-raymarch-hybrid §1.6, §4.1)",
        )
        .expr("frame"),
        Constant::new("HybridParams._pad", "0")
        .expr("0"),
    ],
    crate::gtao::settings::DENOISER,
    crate::common::camera::CONSTANTS,
];

impl HybridSettings {
    /// The paper's variants (spec gtao-raymarch-hybrid §4.2, last paragraph): `mixed` (1 screen + 1 world, w = 2/3),
    /// `world` (2 world rays), `screen` (2 screen rays).
    pub fn variant(name: &str) -> Result<HybridSettings, String> {
        match VARIANTS.iter().position(|v| *v == name) {
            Some(i) => Ok(variant_at(i)),
            None => Err(format!("hybrid variant '{name}' is not {}", VARIANTS.join(", "))),
        }
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
                // The frame's index in its sequence: the Hilbert-R2 noise's temporal offset
                // (spec gtao-raymarch-hybrid §1.6, §4.1).
                noise_frame: frame.frame_index,
                _pad: 0,
            },
        }
    }

    /// Rays → \[denoise\].
    pub fn graph(&self, frame: &FrameDesc) -> Graph {
        let resources = vec![
            record("hybrid_frame", std::slice::from_ref(&self.frame(frame)), "camera + HybridParams"),
            target_f32("ao", 1.0, "blended screen/world visibility (gtao-raymarch-hybrid §4.2 step 5), 1 = unoccluded"),
            target_u32("ao_terms", 0, "the AO as the denoiser's 0–255 terms"),
            target_u32("ao_edges", 0, "packed depth edges for the denoiser"),
            ray_counter(),
        ];
        let bindings = super::rq::hybrid_rq::Bindings {
            frame: "hybrid_frame",
            tlas: inputs::SCENE_TLAS,
            depth: inputs::LINEAR_DEPTH,
            normals: inputs::VIEW_NORMALS,
            ao: "ao",
            uvs: inputs::SCENE_UVS,
            materials: inputs::SCENE_MATERIALS,
            mask_headers: inputs::SCENE_MASK_HEADERS,
            mask_texels: inputs::SCENE_MASK_TEXELS,
            terms: "ao_terms",
            edges: "ao_edges",
            ray_count: RAY_COUNT,
        };
        // The world rays are the ground truth's: its miss and any-hit shaders.
        let [_, miss, any_hit] = crate::groundtruth::settings::SHADERS;
        let shaders = [&super::rt::hybrid_rgen::ENTRY, miss, any_hit];
        let passes = vec![Pass::ray_traced("hybrid_rays", shaders, bindings, Extent::Full)];
        with_denoiser(frame, resources, passes, self.denoise_passes)
    }
}
