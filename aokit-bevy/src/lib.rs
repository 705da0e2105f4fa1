//! aokit's ambient-occlusion techniques in Bevy: [`AokitPlugin`] and the camera component
//! [`AokitAmbientOcclusion`] light a Bevy scene with any aokit technique.
//!
//! Bevy's PBR lighting already reads an ambient-occlusion texture — the one Bevy's own SSAO
//! ([`ScreenSpaceAmbientOcclusion`]) writes and binds for the main pass. The plugin writes
//! aokit's AO into that very texture instead: the component requires Bevy's SSAO component
//! (so Bevy allocates the texture, binds it and compiles its materials with AO), and where aokit
//! runs, Bevy's own SSAO passes are skipped for that view. The AO comes from
//! [`aokit_wgpu::AoEffect`] on Bevy's render device, recorded into Bevy's command encoder
//! between the prepass and the main pass, from Bevy's depth prepass (`Depth32Float`, reversed
//! infinite Z); normals are derived from that depth (Bevy's prepass normals are world-space).
//!
//! ```no_run
//! use aokit_bevy::{AokitAmbientOcclusion, AokitPlugin};
//! use bevy::prelude::*;
//!
//! fn setup(mut commands: Commands) {
//!     commands.spawn((
//!         Camera3d::default(),
//!         // A technique at one of its presets; `AokitAmbientOcclusion::bevy()` is Bevy's own SSAO.
//!         AokitAmbientOcclusion::preset("gtao", "high").unwrap(),
//!     ));
//! }
//! # fn main() {
//! App::new().add_plugins((DefaultPlugins, AokitPlugin)).add_systems(Startup, setup).run();
//! # }
//! ```
//!
//! AO only darkens indirect light (Bevy's ambient light and environment maps), as Bevy's SSAO
//! does. Ray-traced techniques (`raysd`, `hbao-sd`, `hybrid`, `raysvao`, `groundtruth`) trace the
//! triangles of every visible `Mesh3d` (world space, rebuilt when meshes or transforms change)
//! where Bevy's device has ray queries (wgpu's Vulkan back-end on a device with ray queries);
//! elsewhere they are refused with one logged line and the view keeps Bevy's own SSAO.

use aokit_shaders::engine::{SceneGeometry, probe_frame};
use aokit_wgpu::{AoEffect, AoFrame, AoScene, DepthConvention, glam};
pub use aokit_wgpu::{AoError, AoSettings, Technique};
use bevy::app::{App, Plugin, PostUpdate};
use bevy::asset::{AssetEvent, AssetId, Assets};
use bevy::camera::visibility::{InheritedVisibility, VisibilitySystems};
use bevy::camera::{Camera, Camera3d};
use bevy::core_pipeline::prepass::ViewPrepassTextures;
use bevy::core_pipeline::{Core3d, Core3dSystems};
use bevy::ecs::prelude::*;
use bevy::log::{error, warn};
use bevy::mesh::{Indices, Mesh, Mesh3d, PrimitiveTopology, VertexAttributeValues};
use bevy::pbr::{ScreenSpaceAmbientOcclusion, ScreenSpaceAmbientOcclusionResources, SsaoPipelineId};
use bevy::platform::collections::HashMap;
use bevy::render::camera::{ExtractedCamera, TemporalJitter};
use bevy::render::render_resource::{TextureFormat, TextureUsages};
use bevy::render::renderer::{RenderAdapter, RenderContext, RenderDevice, RenderQueue, ViewQuery, render_system};
use bevy::render::sync_world::RenderEntity;
use bevy::render::view::{ExtractedView, Msaa};
use bevy::render::{Extract, ExtractSchedule, Render, RenderApp, RenderSystems};
use bevy::transform::components::GlobalTransform;
use std::sync::Arc;

/// Adds aokit's ambient occlusion to every 3D camera with an [`AokitAmbientOcclusion`].
pub struct AokitPlugin;

impl Plugin for AokitPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<SceneTriangles>()
            .add_systems(PostUpdate, gather_scene_triangles.after(VisibilitySystems::VisibilityPropagate));
        // Camera3d requires MSAA (4 samples by default), which the AO texture cannot follow:
        // a camera with aokit's AO renders without it.
        app.add_observer(|add: On<Add<AokitAmbientOcclusion>>, mut commands: Commands| {
            commands.entity(add.entity).insert(Msaa::Off);
        });
    }

    /// The render world's systems, once the renderer (and Bevy's SSAO, part of `PbrPlugin`) is
    /// set up.
    fn finish(&self, app: &mut App) {
        let Some(render_app) = app.get_sub_app_mut(RenderApp) else {
            warn!("AokitPlugin: no renderer (RenderPlugin), so no ambient occlusion");
            return;
        };
        render_app
            .init_resource::<AokitViews>()
            .add_systems(ExtractSchedule, extract_ambient_occlusion)
            .add_systems(
                Render,
                (
                    prepare_effects.in_set(RenderSystems::PrepareResources),
                    // Bevy inserts each view's SSAO pipeline id in `Prepare` (with commands,
                    // ordered before `Render`); this removes it before the views render.
                    skip_bevy_ssao.in_set(RenderSystems::Render).before(render_system),
                ),
            )
            .add_systems(
                Core3d,
                record_ambient_occlusion.after(Core3dSystems::Prepass).before(Core3dSystems::MainPass),
            );
    }
}

/// Which ambient occlusion a camera gets.
#[derive(Clone, Debug)]
pub enum AoSource {
    /// An aokit technique with its settings (radius in world units of the scene).
    Aokit(AoSettings),
    /// Bevy's own `ScreenSpaceAmbientOcclusion` (visibility bitmask), as set by that component
    /// on the camera: the baseline to compare against.
    Bevy,
}

/// Ambient occlusion by aokit for a 3D camera. Requires Bevy's depth prepass (through
/// [`ScreenSpaceAmbientOcclusion`], which also makes Bevy's materials read the AO texture) and
/// `Msaa::Off`, which the plugin sets on the camera when the component is added (the AO is one
/// value per pixel, as with Bevy's SSAO).
#[derive(Component, Clone, Debug)]
#[require(ScreenSpaceAmbientOcclusion)]
pub struct AokitAmbientOcclusion {
    /// The technique (or Bevy's own SSAO).
    pub source: AoSource,
}

impl AokitAmbientOcclusion {
    /// `technique` at `preset` (e.g. `("gtao", "high")`, `("vbao", "medium")`), with aokit's
    /// default radius 0.5 and exponent 2; `aokit list` names them all.
    pub fn preset(technique: &str, preset: &str) -> Result<AokitAmbientOcclusion, String> {
        Ok(AokitAmbientOcclusion::new(AoSettings::new(Technique::preset(technique, preset)?)))
    }

    /// aokit with these settings.
    pub fn new(settings: AoSettings) -> AokitAmbientOcclusion {
        AokitAmbientOcclusion { source: AoSource::Aokit(settings) }
    }

    /// Bevy's own SSAO (its `ScreenSpaceAmbientOcclusion` component on the camera sets it up).
    pub fn bevy() -> AokitAmbientOcclusion {
        AokitAmbientOcclusion { source: AoSource::Bevy }
    }

    /// A short name for the source: the technique's label, or `bevy-ssao`.
    pub fn label(&self) -> String {
        match &self.source {
            AoSource::Aokit(s) => s.technique.label(),
            AoSource::Bevy => "bevy-ssao".into(),
        }
    }
}

impl Default for AokitAmbientOcclusion {
    /// gtao at its High preset.
    fn default() -> AokitAmbientOcclusion {
        AokitAmbientOcclusion::preset("gtao", "high").expect("gtao has a high preset")
    }
}

/// The world-space triangles of the visible meshes (`Visibility` not hidden, in view or not:
/// rays reach what the camera does not see), for ray-traced techniques; gathered in the main
/// world (`PostUpdate`) only while some camera runs a technique that traces rays, and rebuilt
/// when a mesh, its transform or its visibility changes.
#[derive(Resource, Clone, Default)]
pub struct SceneTriangles {
    /// Three corners per triangle.
    positions: Arc<Vec<[f32; 3]>>,
    /// Changes whenever the positions do.
    generation: u64,
    /// What the positions were gathered from (entity, transform, mesh asset) — a change rebuilds.
    key: Vec<(Entity, [f32; 16], AssetId<Mesh>, bool)>,
}

impl SceneTriangles {
    /// World-space corners, three per triangle (what the ray-traced techniques trace).
    pub fn positions(&self) -> &[[f32; 3]] {
        &self.positions
    }
}

/// Gather [`SceneTriangles`] when a camera needs them and the meshes or their transforms changed.
fn gather_scene_triangles(
    cameras: Query<&AokitAmbientOcclusion>,
    meshes: Query<(Entity, &Mesh3d, &GlobalTransform, &InheritedVisibility)>,
    assets: Res<Assets<Mesh>>,
    mut edits: MessageReader<AssetEvent<Mesh>>,
    mut scene: ResMut<SceneTriangles>,
) {
    // A mesh asset loaded or edited since the last frame rebuilds the scene if it is in it.
    let edited: Vec<_> = edits
        .read()
        .filter_map(|e| match e {
            AssetEvent::Added { id } | AssetEvent::Modified { id } | AssetEvent::LoadedWithDependencies { id } => {
                Some(*id)
            }
            _ => None,
        })
        .collect();
    let traced = cameras.iter().any(|c| match &c.source {
        AoSource::Aokit(s) => traces_rays(s),
        AoSource::Bevy => false,
    });
    if !traced {
        return;
    }
    let visible: Vec<_> = meshes.iter().filter(|m| m.3.get()).collect();
    let key: Vec<_> = visible
        .iter()
        .map(|(e, m, t, _)| (*e, t.to_matrix().to_cols_array(), m.0.id(), assets.contains(m.0.id())))
        .collect();
    if key == scene.key && !visible.iter().any(|m| edited.contains(&m.1.0.id())) {
        return;
    }
    let mut positions = Vec::new();
    for (_, mesh, transform, _) in &visible {
        // Triangle lists only (strips, lines and points are not surfaces to trace here), in
        // their bind pose (skinning and morph targets are not applied).
        let Some(mesh) = assets.get(&mesh.0).filter(|m| m.primitive_topology() == PrimitiveTopology::TriangleList)
        else {
            continue;
        };
        let Some(VertexAttributeValues::Float32x3(vertices)) = mesh.attribute(Mesh::ATTRIBUTE_POSITION) else {
            continue;
        };
        let start = positions.len();
        let matrix = transform.to_matrix();
        let corner = |i: usize| matrix.transform_point3(vertices[i].into()).to_array();
        match mesh.indices() {
            Some(Indices::U16(ix)) => positions.extend(ix.iter().map(|&i| corner(i as usize))),
            Some(Indices::U32(ix)) => positions.extend(ix.iter().map(|&i| corner(i as usize))),
            None => positions.extend((0..vertices.len()).map(corner)),
        }
        // A mesh whose corner count is not a multiple of three drops its last partial triangle.
        positions.truncate(start + (positions.len() - start) / 3 * 3);
    }
    scene.positions = Arc::new(positions);
    scene.generation += 1;
    scene.key = key;
}

/// Does a technique at these settings trace rays (then it needs the scene's triangles)? Its
/// pass graph says so (for a nominal frame: which passes a graph has does not depend on the
/// camera).
fn traces_rays(settings: &AoSettings) -> bool {
    settings.technique.graph(&probe_frame(settings, None)).is_ok_and(|g| g.traces_rays())
}

/// A view's aokit settings, extracted into the render world.
#[derive(Component, Clone)]
struct ExtractedAokit(AoSettings);

/// The scene triangles in the render world.
#[derive(Resource, Clone, Default)]
struct ExtractedScene {
    positions: Arc<Vec<[f32; 3]>>,
    generation: u64,
}

/// The main world's 3D cameras with aokit's AO, as extraction reads them.
type AokitCameras<'w, 's> =
    Query<'w, 's, (RenderEntity, &'static Camera, &'static AokitAmbientOcclusion, &'static Msaa), With<Camera3d>>;

/// The main world's 3D cameras without aokit's AO.
type OtherCameras<'w, 's> = Query<'w, 's, RenderEntity, (With<Camera3d>, Without<AokitAmbientOcclusion>)>;

/// Copy each camera's settings into the render world (removed where the camera is inactive or
/// uses Bevy's SSAO), and the scene's triangles.
fn extract_ambient_occlusion(
    mut commands: Commands,
    cameras: Extract<AokitCameras>,
    others: Extract<OtherCameras>,
    scene: Extract<Res<SceneTriangles>>,
) {
    // Render entities persist: a camera whose component was removed drops aokit (its required
    // `ScreenSpaceAmbientOcclusion`, if still there, gives it Bevy's SSAO again).
    for entity in &others {
        commands.entity(entity).remove::<ExtractedAokit>();
    }
    for (entity, camera, ao, msaa) in &cameras {
        let mut view = commands.entity(entity);
        match &ao.source {
            AoSource::Aokit(settings) if camera.is_active && *msaa == Msaa::Off => {
                view.insert(ExtractedAokit(settings.clone()));
            }
            _ => {
                view.remove::<ExtractedAokit>();
            }
        }
    }
    commands.insert_resource(ExtractedScene { positions: scene.positions.clone(), generation: scene.generation });
}

/// What a view's last aokit frame was computed from: for tests and tools that reproduce it
/// (e.g. cpu-sim on the same depth).
#[derive(Clone, Debug)]
pub struct RecordedFrame {
    /// The settings the effect ran.
    pub settings: AoSettings,
    /// The AO texture's size (Bevy's physical viewport size).
    pub size: glam::UVec2,
    /// Bevy's `clip_from_view` (reversed infinite Z).
    pub projection: glam::Mat4,
    /// World → view.
    pub view: glam::Mat4,
    /// The frame index given to the effect (its noise).
    pub frame_index: u32,
    /// The previous frame's world → view (temporal reprojection).
    pub previous_view: Option<glam::Mat4>,
}

/// One view's effect and state in the render world.
struct ViewEffect {
    effect: AoEffect,
    /// The size the effect was last resized to (a resize rebuilds its graph: only on change).
    size: Option<glam::UVec2>,
    /// Does the technique trace rays at these settings and size (`None`: not asked yet)?
    traces: Option<bool>,
    /// The scene built for the effect, with the generation of [`ExtractedScene`] it came from.
    scene: Option<(AoScene, u64)>,
    /// A ray-traced technique without triangles to trace yet: no frame (Bevy's SSAO runs).
    waiting: bool,
    /// The empty scene was reported.
    warned_empty: bool,
    frame_index: u32,
    previous_view: Option<glam::Mat4>,
    last: Option<RecordedFrame>,
}

/// The render world's aokit effects, one per view (keyed by the view's render entity).
#[derive(Resource, Default)]
pub struct AokitViews {
    views: HashMap<Entity, ViewEffect>,
    /// Views whose settings were refused at a size, with the refusal (logged once per change).
    refused: HashMap<Entity, (AoSettings, bevy::math::UVec2, String)>,
}

impl AokitViews {
    /// The last frame recorded for the view `entity` (a render-world entity).
    pub fn recorded(&self, entity: Entity) -> Option<&RecordedFrame> {
        self.views.get(&entity)?.last.as_ref()
    }

    /// Every view's last recorded frame, by the view's render-world entity.
    pub fn recorded_frames(&self) -> impl Iterator<Item = (Entity, &RecordedFrame)> {
        self.views.iter().filter_map(|(e, v)| Some((*e, v.last.as_ref()?)))
    }

    /// Does aokit run for this view (its settings accepted by the device, and a ray-traced
    /// technique's scene there)?
    pub fn runs(&self, entity: Entity) -> bool {
        self.views.get(&entity).is_some_and(|v| !v.waiting)
    }
}

/// Create, resize and reconfigure each view's effect; drop those of views gone.
fn prepare_effects(
    views: Query<(Entity, &ExtractedAokit, &ExtractedCamera, &ExtractedView, Has<TemporalJitter>)>,
    device: Res<RenderDevice>,
    adapter: Res<RenderAdapter>,
    queue: Res<RenderQueue>,
    scene: Res<ExtractedScene>,
    mut state: ResMut<AokitViews>,
) {
    let state = &mut *state;
    state.views.retain(|e, _| views.contains(*e));
    state.refused.retain(|e, _| views.contains(*e));
    // The format of Bevy's SSAO texture, chosen as Bevy's SSAO plugin chooses it.
    let r16 = adapter
        .get_texture_format_features(TextureFormat::R16Float)
        .allowed_usages
        .contains(TextureUsages::STORAGE_BINDING);
    for (entity, ExtractedAokit(settings), camera, view, jitter) in &views {
        let Some(size) = camera.physical_viewport_size else { continue };
        if state.refused.get(&entity).is_some_and(|(s, at, _)| same(s, settings) && *at == size) {
            continue;
        }
        let result = check_view(camera, view, jitter)
            .and_then(|()| configure(state.views.remove(&entity), settings, size, &device, &queue, &scene))
            .and_then(|v| match r16 && !v.effect.runs_spirv() {
                true => Err("Bevy's SSAO texture is R16Float here, which aokit writes only from its SPIR-V (wgpu's Vulkan back-end with aokit_wgpu::SPIRV_FEATURES)".into()),
                false => Ok(v),
            });
        match result {
            Ok(view) => {
                state.refused.remove(&entity);
                state.views.insert(entity, view);
            }
            Err(why) => {
                error!("aokit: {} refused for this view, Bevy's SSAO stays: {why}", settings.technique.label());
                state.views.remove(&entity);
                state.refused.insert(entity, (settings.clone(), size, why));
            }
        }
    }
}

/// What aokit cannot take from a view, refused before Bevy's SSAO is skipped for it.
fn check_view(camera: &ExtractedCamera, view: &ExtractedView, jitter: bool) -> Result<(), String> {
    if jitter {
        return Err("the view has TemporalJitter (TAA): aokit needs the unjittered projection of the depth".into());
    }
    if view.clip_from_view.w_axis.w == 1.0 {
        return Err("an orthographic projection: aokit's techniques need a perspective one".into());
    }
    if camera.physical_viewport_size != camera.physical_target_size {
        return Err("a camera viewport smaller than its target: Bevy's depth prepass is target-sized and its SSAO texture viewport-sized".into());
    }
    Ok(())
}

/// The view's effect, made (or kept) for `settings` at `size`, its scene built when it traces rays.
fn configure(
    view: Option<ViewEffect>,
    settings: &AoSettings,
    size: bevy::math::UVec2,
    device: &RenderDevice,
    queue: &RenderQueue,
    scene: &ExtractedScene,
) -> Result<ViewEffect, String> {
    let mut view = match view {
        Some(v) => v,
        None => {
            let effect = AoEffect::new(device.wgpu_device(), queue, settings.clone()).map_err(|e| e.to_string())?;
            ViewEffect {
                effect,
                size: None,
                traces: None,
                scene: None,
                waiting: false,
                warned_empty: false,
                frame_index: 0,
                previous_view: None,
                last: None,
            }
        }
    };
    let mut changed = false;
    if !same(view.effect.settings(), settings) {
        view.effect.set_settings(settings.clone()).map_err(|e| e.to_string())?;
        view.previous_view = None;
        changed = true;
    }
    let size = glam::uvec2(size.x, size.y);
    if view.size != Some(size) {
        view.effect.resize(size.x, size.y).map_err(|e| e.to_string())?;
        view.size = Some(size);
        changed = true;
    }
    if changed || view.traces.is_none() {
        view.traces = Some(view.effect.traces_rays().map_err(|e| e.to_string())?);
    }
    if view.traces == Some(true) {
        if scene.positions.is_empty() {
            // No triangles yet (meshes still loading) or none at all: no frame until there are.
            if !view.warned_empty {
                warn!(
                    "aokit: {} traces rays and the scene has no visible mesh triangles yet",
                    settings.technique.label()
                );
                view.warned_empty = true;
            }
            view.scene = None;
            view.waiting = true;
            return Ok(view);
        }
        view.waiting = false;
        if view.scene.as_ref().is_none_or(|(_, g)| *g != scene.generation) {
            let triangles = scene.positions.len() / 3;
            let uvs = vec![glam::Vec2::ZERO; scene.positions.len()];
            let materials = vec![0u32; triangles];
            let geometry = SceneGeometry {
                positions: &scene.positions,
                uvs: &uvs,
                materials: &materials,
                mask_headers: &[],
                mask_texels: &[],
            };
            let built = view.effect.build_scene(&geometry).map_err(|e| e.to_string())?;
            view.scene = Some((built, scene.generation));
        }
    } else {
        view.scene = None;
        view.waiting = false;
    }
    Ok(view)
}

/// Are two settings the same? `AoSettings` holds only values (numbers, names, options) and
/// derives `Debug`, which prints every one of them exactly (floats round-trip), so equal
/// printouts are equal settings.
fn same(a: &AoSettings, b: &AoSettings) -> bool {
    format!("{a:?}") == format!("{b:?}")
}

/// Where aokit runs for a view, Bevy's own SSAO passes are skipped (its system finds no pipeline
/// for the view); the texture it would have written is aokit's output.
fn skip_bevy_ssao(mut commands: Commands, views: Query<Entity, With<ExtractedAokit>>, state: Res<AokitViews>) {
    for entity in &views {
        if state.runs(entity) {
            commands.entity(entity).remove::<SsaoPipelineId>();
        }
    }
}

/// Bevy's glam matrix as aokit's (the same column-major layout; the crates may use different
/// glam versions).
fn mat4(m: bevy::math::Mat4) -> glam::Mat4 {
    glam::Mat4::from_cols_array(&m.to_cols_array())
}

/// Record the view's aokit frame into Bevy's encoder: from the depth prepass into the texture
/// Bevy's PBR lighting reads as its SSAO.
pub fn record_ambient_occlusion(
    view: ViewQuery<(&ExtractedView, &ViewPrepassTextures, &ScreenSpaceAmbientOcclusionResources)>,
    mut state: ResMut<AokitViews>,
    mut ctx: RenderContext,
) {
    let entity = view.entity();
    let (extracted, prepass, ssao) = view.into_inner();
    let Some(effect) = state.views.get_mut(&entity).filter(|v| !v.waiting) else { return };
    let Some(depth) = prepass.depth_only_view() else { return };
    let projection = mat4(extracted.clip_from_view);
    let world_to_view = mat4(extracted.world_from_view.to_matrix().inverse());
    let output = &ssao.screen_space_ambient_occlusion_texture.default_view;
    let mut frame = AoFrame::new(depth, DepthConvention::ReversedInfinite, output, projection, world_to_view)
        .temporal(effect.frame_index, effect.previous_view);
    if let Some((scene, _)) = &effect.scene {
        frame = frame.scene(scene);
    }
    if let Err(e) = effect.effect.record(ctx.command_encoder(), &frame) {
        error!(
            "aokit: {} failed to record: {e}; this view's AO is dropped",
            effect.effect.settings().technique.label()
        );
        let settings = effect.effect.settings().clone();
        let size = effect.size.map_or(bevy::math::UVec2::ZERO, |s| bevy::math::uvec2(s.x, s.y));
        state.views.remove(&entity);
        state.refused.insert(entity, (settings, size, e.to_string()));
        return;
    }
    let size = ssao.screen_space_ambient_occlusion_texture.texture.size();
    effect.last = Some(RecordedFrame {
        settings: effect.effect.settings().clone(),
        size: glam::uvec2(size.width, size.height),
        projection,
        view: world_to_view,
        frame_index: effect.frame_index,
        previous_view: effect.previous_view,
    });
    effect.previous_view = Some(world_to_view);
    effect.frame_index = effect.frame_index.wrapping_add(1);
}
