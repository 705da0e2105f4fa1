//! The engine API ([`AoEffect`]); its documentation is the crate's (`lib.rs`).

use crate::graph::{AoContext, EngineFrame, check_device};
use crate::{AoImage, EngineImage, ExternalDevice, Gpu, GpuError, SceneAccel};
pub use aokit_shaders::engine::{AoSettings, DepthConvention, EngineCamera, SceneGeometry, engine_camera};
use aokit_shaders::engine::{engine_frame, probe_frame};
use aokit_shaders::glam::{Mat4, UVec2};
use aokit_shaders::graph::{FrameDesc, Graph, PassKind, RtMode};
use ash::vk;
use std::sync::Arc;

/// Why the effect could not be made or a frame could not be recorded. When `record` returns an
/// error nothing was recorded into the command buffer, unless a device allocation (a buffer,
/// descriptor pool or query pool made for the frame) failed part-way: then discard the command
/// buffer.
#[derive(Debug, thiserror::Error)]
pub enum AoError {
    /// The settings are out of range, or name a technique or setting that does not exist.
    #[error("settings: {0}")]
    Settings(String),
    /// The projection or view matrix cannot be the camera of a depth image aokit reads.
    #[error("projection: {0}")]
    Projection(String),
    /// `record` before the first `resize`.
    #[error("the effect has no size yet: call AoEffect::resize(width, height) before the first record")]
    NotResized,
    /// The frame lacks an image or the scene that the technique reads, or the technique needs
    /// something the engine API cannot take.
    #[error("frame: {0}")]
    Frame(String),
    /// Vulkan or the device: a missing extension, feature or limit, or a failed call.
    #[error(transparent)]
    Gpu(#[from] GpuError),
}

/// One frame of the engine: its images, its camera and its place in a sequence. Made with
/// [`AoFrame::new`] and the builder methods.
#[derive(Copy, Clone, Debug)]
pub struct AoFrame<'a> {
    /// The depth image (hardware depth in `depth_convention`, or linear depth).
    pub depth: EngineImage,
    /// What `depth` stores.
    pub depth_convention: DepthConvention,
    /// View-space normals `n·0.5 + 0.5` in RGB; `None`: derived from depth (XeGTAO's normals
    /// pass, gtao-raymarch-hybrid §2.4).
    pub normals: Option<EngineImage>,
    /// The depth-peeled second layer of the dual-depth techniques (svao-raysd §11): same format
    /// and convention as `depth`, the nearest surface at least the technique's peel separation
    /// behind it, cleared where there is none.
    pub second_depth: Option<EngineImage>,
    /// Where the AO goes (1 = unoccluded).
    pub output: AoImage,
    /// The projection the depth image was rendered with: right-handed view space looking down
    /// −Z, Vulkan clip depth `[0, 1]`, symmetric frustum (pass the unjittered matrix), row 0 of
    /// the images at the top of the view (a Y-flipped projection or a negative viewport height).
    pub projection: Mat4,
    /// World → view.
    pub view: Mat4,
    /// The frame's index in a sequence: every stochastic technique's noise takes it \[0\].
    pub frame_index: u32,
    /// The previous frame's world → view, for the temporal accumulation's reprojection; `None`
    /// on a first frame or after a cut.
    pub previous_view: Option<Mat4>,
    /// The scene, for techniques that trace rays.
    pub scene: Option<&'a AoScene>,
}

impl<'a> AoFrame<'a> {
    /// A frame of `depth` (in `depth_convention`) into `output`, seen through `projection` and
    /// `view`; normals derived from depth, frame index 0, no previous view, no scene.
    pub fn new(
        depth: EngineImage,
        depth_convention: DepthConvention,
        output: AoImage,
        projection: Mat4,
        view: Mat4,
    ) -> AoFrame<'a> {
        AoFrame {
            depth,
            depth_convention,
            normals: None,
            second_depth: None,
            output,
            projection,
            view,
            frame_index: 0,
            previous_view: None,
            scene: None,
        }
    }

    /// With the engine's view-space normals.
    pub fn normals(self, normals: EngineImage) -> AoFrame<'a> {
        AoFrame { normals: Some(normals), ..self }
    }

    /// With the depth-peeled second layer.
    pub fn second_depth(self, second_depth: EngineImage) -> AoFrame<'a> {
        AoFrame { second_depth: Some(second_depth), ..self }
    }

    /// As frame `index` of a sequence whose previous frame was seen through `previous_view`.
    pub fn temporal(self, index: u32, previous_view: Option<Mat4>) -> AoFrame<'a> {
        AoFrame { frame_index: index, previous_view, ..self }
    }

    /// With the scene for ray-traced techniques.
    pub fn scene(self, scene: &'a AoScene) -> AoFrame<'a> {
        AoFrame { scene: Some(scene), ..self }
    }
}

/// The scene on the device for ray tracing: aokit's acceleration structure (or the engine's
/// TLAS) and the tables the any-hit alpha test reads. Freed when dropped (after the device
/// finished the frames that used it).
pub struct AoScene {
    gpu: Arc<Gpu>,
    accel: Option<SceneAccel>,
}

impl AoScene {
    fn accel(&self) -> &SceneAccel {
        self.accel.as_ref().expect("present until dropped")
    }
}

impl std::fmt::Debug for AoScene {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AoScene").finish_non_exhaustive()
    }
}

impl Drop for AoScene {
    fn drop(&mut self) {
        if let Some(accel) = self.accel.take() {
            accel.destroy(&self.gpu);
        }
    }
}

/// The graph built for the last frame and what it was built from.
struct BuiltGraph {
    desc: FrameDesc,
    graph: Graph,
}

/// Ambient occlusion on the engine's device (see the crate documentation).
pub struct AoEffect {
    /// Declared before `gpu`: dropped (and so freed) first.
    context: AoContext<Arc<Gpu>>,
    gpu: Arc<Gpu>,
    settings: AoSettings,
    size: Option<UVec2>,
    built: Option<BuiltGraph>,
}

impl std::fmt::Debug for AoEffect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AoEffect").field("settings", &self.settings).field("size", &self.size).finish_non_exhaustive()
    }
}

impl AoEffect {
    /// The effect on the engine's device (see [`ExternalDevice`] for the extensions and features
    /// it must have been created with) running `settings`.
    /// A technique the effect cannot run on this device (a raster pass, ray tracing the device
    /// lacks) is refused here, not at the first `record`.
    pub fn new(device: ExternalDevice, settings: AoSettings) -> Result<AoEffect, AoError> {
        settings.check().map_err(AoError::Settings)?;
        let gpu = Arc::new(Gpu::from_external(device)?);
        let effect = AoEffect { context: AoContext::new(gpu.clone()), gpu, settings, size: None, built: None };
        effect.build_graph(&effect.settings, &effect.probe_desc(&effect.settings))?;
        Ok(effect)
    }

    /// Set the size of the engine's images (depth, normals, output) in texels. Call it before
    /// the first frame and whenever the images change; views of the old images may be
    /// destroyed once the frames that used them completed.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), AoError> {
        if width == 0 || height == 0 || width > 16384 || height > 16384 {
            return Err(AoError::Settings(format!("image size {width}×{height}: expected 1…16384 per side")));
        }
        self.size = Some(UVec2::new(width, height));
        self.built = None;
        // The new images' views may reuse the old views' handles.
        self.context.invalidate_bindings();
        Ok(())
    }

    /// Replace the settings; the next frame runs them. Settings the effect cannot run on this
    /// device are refused (and the old ones kept).
    pub fn set_settings(&mut self, settings: AoSettings) -> Result<(), AoError> {
        settings.check().map_err(AoError::Settings)?;
        self.build_graph(&settings, &self.probe_desc(&settings))?;
        self.settings = settings;
        self.built = None;
        Ok(())
    }

    /// Forget the descriptor sets that bind the engine's images and the scene, so the next frame
    /// writes new ones. Call it after destroying an image view (or a TLAS) that an earlier frame
    /// used without a [`AoEffect::resize`] (which does this too): a new view may get the old
    /// handle.
    pub fn invalidate_bindings(&mut self) {
        self.context.invalidate_bindings();
    }

    /// The settings in use.
    pub fn settings(&self) -> &AoSettings {
        &self.settings
    }

    /// Does the technique trace rays at the current size and settings (then every frame needs
    /// [`AoFrame::scene`])?
    pub fn traces_rays(&self) -> Result<bool, AoError> {
        self.size.ok_or(AoError::NotResized)?;
        let s = &self.settings;
        Ok(s.technique.graph(&self.probe_desc(s)).map_err(AoError::Settings)?.traces_rays())
    }

    /// A frame of `settings` at the effect's size seen by a nominal camera
    /// ([`aokit_shaders::engine::probe_frame`]).
    fn probe_desc(&self, s: &AoSettings) -> FrameDesc {
        probe_frame(s, self.size)
    }

    /// Build an acceleration structure of `geometry` for the ray-traced techniques (submits the
    /// build to the effect's queue and waits for it).
    pub fn build_scene(&mut self, geometry: &SceneGeometry) -> Result<AoScene, AoError> {
        let masks = (geometry.mask_headers.to_vec(), geometry.mask_texels.to_vec());
        let accel = SceneAccel::build(&self.gpu, geometry.positions, geometry.uvs, geometry.materials, &masks)?;
        Ok(AoScene { gpu: self.gpu.clone(), accel: Some(accel) })
    }

    /// Use the engine's own TLAS (triangles in its instances' order, `uvs`/`materials` per
    /// triangle of that order) for the ray-traced techniques; the engine keeps it alive.
    pub fn scene_from_tlas(
        &mut self,
        tlas: vk::AccelerationStructureKHR,
        geometry: &SceneGeometry,
    ) -> Result<AoScene, AoError> {
        let masks = (geometry.mask_headers.to_vec(), geometry.mask_texels.to_vec());
        let accel = SceneAccel::from_engine_tlas(&self.gpu, tlas, geometry.uvs, geometry.materials, &masks)?;
        Ok(AoScene { gpu: self.gpu.clone(), accel: Some(accel) })
    }

    /// Record one frame into `cmd` (a primary command buffer in the recording state, from a pool
    /// of the device's queue family): import the depth (and normals), run the technique's
    /// passes, export the AO into `frame.output`. The engine's writes of the input images must
    /// be visible to compute-shader reads before the recorded commands, and the output's
    /// compute-shader writes are made visible by the engine's barrier after them. At most
    /// three frames may be in flight.
    pub fn record(&mut self, cmd: vk::CommandBuffer, frame: &AoFrame) -> Result<(), AoError> {
        let size = self.size.ok_or(AoError::NotResized)?;
        let (desc, import) = engine_frame(
            &self.settings,
            size,
            frame.projection,
            frame.view,
            frame.depth_convention,
            frame.frame_index,
            frame.previous_view,
        )
        .map_err(AoError::Projection)?;
        if self.built.as_ref().is_none_or(|b| b.desc != desc) {
            self.built = Some(BuiltGraph { desc, graph: self.build_graph(&self.settings, &desc)? });
        }
        let graph = &self.built.as_ref().expect("built above").graph;
        // What this frame must give, checked every frame before anything is recorded.
        let name = self.settings.technique.name();
        if graph.traces_rays() && frame.scene.is_none() {
            return Err(AoError::Frame(format!(
                "{name} traces rays: give the scene (AoEffect::build_scene, AoFrame::scene)"
            )));
        }
        if self.settings.technique.second_layer().is_some() && frame.second_depth.is_none() {
            return Err(AoError::Frame(format!(
                "{name} reads a depth-peeled second layer: give AoFrame::second_depth"
            )));
        }
        let engine_frame = EngineFrame {
            depth: frame.depth,
            normals: frame.normals,
            second_depth: frame.second_depth,
            output: frame.output,
            import,
            scene: frame.scene.map(AoScene::accel),
        };
        Ok(self.context.record_engine(cmd, graph, &engine_frame)?)
    }

    /// The graph of `settings` for `desc`, checked against the device and the engine API.
    fn build_graph(&self, settings: &AoSettings, desc: &FrameDesc) -> Result<Graph, AoError> {
        let technique = &settings.technique;
        let graph = technique.graph(desc).map_err(AoError::Settings)?;
        let mode =
            settings.rt_mode.unwrap_or(if self.gpu.has_ray_tracing() { RtMode::Pipeline } else { RtMode::Query });
        let graph = graph.with_rt_mode(mode);
        let name = technique.name();
        if graph.passes.iter().any(|p| matches!(p.kind, PassKind::Raster { .. })) {
            return Err(AoError::Frame(format!(
                "{name} rasterizes the scene's triangles itself (a raster pass), which the engine API cannot take: choose a technique without raster passes"
            )));
        }
        graph.validate().map_err(AoError::Settings)?;
        check_device(&self.gpu, &graph)?;
        Ok(graph)
    }

    /// `(pass label, ms)` of the last recorded frame: call it after that frame's fence and before
    /// the next `record` (GPU timestamps; it waits for them, so before the submit it would hang).
    pub fn pass_times(&self) -> Result<Vec<(&'static str, f64)>, AoError> {
        Ok(self.context.pass_times()?)
    }

    /// The context underneath, for tests that count its descriptor pools.
    #[cfg(feature = "testing")]
    pub fn context(&self) -> &AoContext<Arc<Gpu>> {
        &self.context
    }

    /// Record the next frames with deliberate defects (aokit's own tests).
    #[cfg(feature = "testing")]
    pub fn sabotage(&mut self, sabotage: crate::Sabotage) {
        self.context.sabotage(sabotage);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_effect_is_send() {
        fn send<T: Send>() {}
        send::<AoEffect>();
        send::<AoScene>();
    }
}
