//! Sponza in Bevy, lit by aokit's ambient occlusion (or Bevy's own SSAO, or none).
//!
//! ```sh
//! cd aokit-bevy   # its own workspace; --ignore-rust-version: Bevy 0.20 declares rustc 1.97.1
//! cargo run --ignore-rust-version --example bevy_sponza -- --screenshot ../assets/readme/bevy_sponza.png
//! cargo run --ignore-rust-version --example bevy_sponza --features window   # a window: T cycles, S saves
//! ```
//!
//! Without the `window` feature it renders headlessly (any Vulkan device, lavapipe included)
//! into an image and saves the screenshot. Options: `--technique SPEC` (`gtao`, `vbao:high`,
//! `groundtruth:spp=16`, `raysd`, …, `bevy` for Bevy's SSAO, `none`), `--size WxH`, `--frames N` (frames rendered
//! before the screenshot: the first ones compile pipelines). Sponza comes through aokit's scene
//! loader (fetched once by cargo, cached); `--scene NAME` picks another built-in scene.

use aokit_bevy::{AoSettings, AokitAmbientOcclusion, AokitPlugin, AokitViews, Technique};
use bevy::asset::RenderAssetUsages;
use bevy::camera::RenderTarget;
use bevy::core_pipeline::prepass::{DepthPrepass, NormalPrepass};
use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::image::Image;
use bevy::light::GlobalAmbientLight;
use bevy::mesh::PrimitiveTopology;
use bevy::prelude::*;
use bevy::render::render_resource::TextureFormat;
use bevy::render::settings::{InstanceFlags, WgpuSettings};
use bevy::render::view::screenshot::{Screenshot, ScreenshotCaptured};
use bevy::render::{RenderApp, RenderPlugin};
use std::path::PathBuf;

/// The techniques the example cycles through (`T` in a window), in order.
const CYCLE: [&str; 7] = ["gtao:high", "vbao:high", "hbao", "vao", "raysd", "bevy", "none"];

/// The ambient light's brightness. It is the scene's only light: AO darkens indirect light only
/// (as Bevy's SSAO does), so the image shows the AO and nothing else.
const AMBIENT: f32 = 3000.0;

struct Options {
    scene: String,
    technique: String,
    size: UVec2,
    frames: u32,
    screenshot: Option<PathBuf>,
}

fn options() -> Result<Options, String> {
    let mut o = Options {
        scene: "sponza".into(),
        technique: "gtao:high".into(),
        size: uvec2(960, 540),
        frames: 12,
        screenshot: None,
    };
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let mut value = || args.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--scene" => o.scene = value()?,
            "--technique" => o.technique = value()?,
            "--size" => {
                let v = value()?;
                let (w, h) = v.split_once('x').ok_or(format!("--size {v}: expected WxH"))?;
                let parse = |s: &str| s.parse::<u32>().ok().filter(|&n| (16..=8192).contains(&n));
                o.size = uvec2(
                    parse(w).ok_or(format!("--size {v}: bad width"))?,
                    parse(h).ok_or(format!("--size {v}: bad height"))?,
                );
            }
            "--frames" => o.frames = value()?.parse().map_err(|_| "--frames: expected a count".to_string())?,
            "--screenshot" => o.screenshot = Some(value()?.into()),
            other => {
                return Err(format!("unknown option {other} (--scene, --technique, --size, --frames, --screenshot)"));
            }
        }
    }
    if cfg!(not(feature = "window")) && o.screenshot.is_none() {
        return Err(
            "built without the `window` feature: pass --screenshot PATH (headless), or run with --features window"
                .into(),
        );
    }
    Ok(o)
}

/// The camera component for a technique spec: an aokit technique at its preset (`gtao:high`)
/// or with its defaults (`hbao`), Bevy's SSAO (`bevy`), or no AO (`none`).
fn ambient_occlusion(spec: &str, radius: f32) -> Result<Option<AokitAmbientOcclusion>, String> {
    Ok(match spec {
        "none" => None,
        "bevy" => Some(AokitAmbientOcclusion::bevy()),
        _ => {
            // `name:preset`, or a technique spec with settings (`name:key=value,…`).
            let technique = match spec.split_once(':') {
                Some((name, preset)) if !preset.contains('=') => Technique::preset(name, preset)?,
                _ => Technique::parse(spec)?,
            };
            Some(AokitAmbientOcclusion::new(AoSettings::new(technique).radius(radius)))
        }
    })
}

/// The scene as one flat-shaded Bevy mesh, its default camera and AO radius.
#[derive(Resource)]
struct SceneSetup {
    /// Taken by `setup` into `Assets<Mesh>`.
    mesh: Option<Mesh>,
    eye: Vec3,
    target: Vec3,
    fov_deg: f32,
    radius: f32,
}

fn load_scene(name: &str) -> Result<SceneSetup, String> {
    let builtin = aokit::scene::builtin::find(name).ok_or_else(|| {
        let names: Vec<_> = aokit::scene::builtin::builtin_scenes().iter().map(|s| s.name).collect();
        format!("no built-in scene {name} (there are: {})", names.join(", "))
    })?;
    let scene = builtin.load().map_err(|e| e.to_string())?;
    let mut positions = Vec::with_capacity(scene.triangles.len() * 3);
    let mut normals = Vec::with_capacity(scene.triangles.len() * 3);
    for t in &scene.triangles {
        let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero().to_array();
        positions.extend(t.iter().map(|p| p.to_array()));
        normals.extend([n; 3]);
    }
    let mesh = Mesh::new(PrimitiveTopology::TriangleList, RenderAssetUsages::default())
        .with_inserted_attribute(Mesh::ATTRIBUTE_POSITION, positions)
        .with_inserted_attribute(Mesh::ATTRIBUTE_NORMAL, normals);
    let camera = builtin.cameras[0];
    Ok(SceneSetup {
        mesh: Some(mesh),
        eye: Vec3::from_array(camera.eye.to_array()),
        target: Vec3::from_array(camera.target.to_array()),
        fov_deg: camera.fov_deg,
        radius: builtin.radius,
    })
}

#[derive(Resource)]
struct Run {
    technique: usize,
    techniques: Vec<String>,
    frames_left: u32,
    screenshot: Option<PathBuf>,
    target: Option<Handle<Image>>,
}

fn main() {
    let (options, scene) = match options().and_then(|o| Ok((load_scene(&o.scene)?, o))) {
        Ok((scene, o)) => (o, scene),
        Err(e) => {
            eprintln!("bevy_sponza: {e}");
            std::process::exit(2);
        }
    };
    if let Err(e) = ambient_occlusion(&options.technique, scene.radius) {
        eprintln!("bevy_sponza: --technique {}: {e}", options.technique);
        std::process::exit(2);
    }
    let mut techniques: Vec<String> = CYCLE.iter().map(|s| s.to_string()).collect();
    if !techniques.contains(&options.technique) {
        techniques.insert(0, options.technique.clone());
    }
    let technique = techniques.iter().position(|t| *t == options.technique).unwrap_or(0);
    let mut app = App::new();
    // Both branches compile in every build (CI builds the headless one); the window needs winit.
    let window = if cfg!(feature = "window") {
        bevy::window::WindowPlugin {
            primary_window: Some(bevy::window::Window {
                title: "aokit in Bevy: T cycles the technique, S saves a screenshot".into(),
                resolution: (options.size.x, options.size.y).into(),
                ..default()
            }),
            ..default()
        }
    } else {
        bevy::window::WindowPlugin {
            primary_window: None,
            exit_condition: bevy::window::ExitCondition::DontExit,
            ..default()
        }
    };
    // Debian's Khronos validation layer (which wgpu turns on in debug builds) predates the SPIR-V
    // naga writes for Bevy's shaders and reports every one of them; WGPU_VALIDATION=1 turns it on.
    let mut wgpu = WgpuSettings::default();
    wgpu.instance_flags.remove(InstanceFlags::VALIDATION);
    wgpu.instance_flags = wgpu.instance_flags.with_env();
    let render = RenderPlugin { render_creation: wgpu.into(), ..default() };
    app.add_plugins((DefaultPlugins.set(window).set(render), AokitPlugin))
        .insert_resource(GlobalAmbientLight {
            color: Color::WHITE,
            brightness: AMBIENT,
            affects_lightmapped_meshes: true,
        })
        .insert_resource(Run {
            technique,
            techniques,
            frames_left: options.frames,
            screenshot: options.screenshot.clone(),
            target: None,
        })
        .insert_resource(scene)
        .insert_resource(Size(options.size))
        .add_systems(Startup, setup)
        .add_systems(Update, (cycle_technique, screenshot_when_ready));
    if cfg!(feature = "window") {
        app.run();
    } else {
        // Headless: step frames until the screenshot is written.
        let path = options.screenshot.clone().expect("headless runs have a screenshot path");
        let _ = std::fs::remove_file(&path);
        app.finish();
        app.cleanup();
        while app.world().resource::<Run>().screenshot.is_some() || app.world().resource::<Run>().frames_left > 0 {
            app.update();
        }
        // The capture arrives a frame or two after it is requested.
        for _ in 0..8 {
            app.update();
            if path.exists() {
                break;
            }
        }
        if !path.exists() {
            eprintln!("bevy_sponza: no screenshot written to {} after 8 frames", path.display());
            std::process::exit(1);
        }
        // The screenshot must show aokit's AO where an aokit technique was asked for (a refused
        // one leaves Bevy's SSAO, with the reason logged above).
        let aokit_asked = !matches!(options.technique.as_str(), "bevy" | "none");
        let ran = app.sub_app(RenderApp).world().resource::<AokitViews>().recorded_frames().count() > 0;
        if aokit_asked && !ran {
            eprintln!(
                "bevy_sponza: aokit did not run for the camera ({}); the screenshot shows Bevy's SSAO",
                options.technique
            );
            std::process::exit(1);
        }
    }
}

#[derive(Resource)]
struct Size(UVec2);

#[derive(Component)]
struct ViewCamera;

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut images: ResMut<Assets<Image>>,
    mut scene: ResMut<SceneSetup>,
    mut run: ResMut<Run>,
    size: Res<Size>,
) {
    let mesh = meshes.add(scene.mesh.take().expect("setup runs once"));
    let material = materials.add(StandardMaterial {
        base_color: Color::srgb(0.8, 0.78, 0.74),
        perceptual_roughness: 1.0,
        ..default()
    });
    commands.spawn((Mesh3d(mesh), MeshMaterial3d(material)));
    let mut camera = commands.spawn((
        Camera3d::default(),
        Tonemapping::Reinhard,
        Projection::Perspective(PerspectiveProjection { fov: scene.fov_deg.to_radians(), ..default() }),
        Transform::from_translation(scene.eye).looking_at(scene.target, Vec3::Y),
        ViewCamera,
    ));
    if cfg!(not(feature = "window")) {
        let image = Image::new_target_texture(size.0.x, size.0.y, TextureFormat::Rgba8UnormSrgb, None);
        let handle = images.add(image);
        camera.insert(RenderTarget::Image(handle.clone().into()));
        run.target = Some(handle);
    }
    let spec = run.techniques[run.technique].clone();
    // The same prepasses and no MSAA with every choice, so that `none` differs only by the AO.
    camera.insert((DepthPrepass, NormalPrepass, Msaa::Off));
    if let Some(ao) = ambient_occlusion(&spec, scene.radius).expect("checked in main") {
        camera.insert(ao);
    }
    info!("bevy_sponza: {spec}");
}

/// `T` (in a window): the next technique of the cycle.
fn cycle_technique(
    keys: Option<Res<ButtonInput<KeyCode>>>,
    mut run: ResMut<Run>,
    scene: Res<SceneSetup>,
    cameras: Query<Entity, With<ViewCamera>>,
    mut commands: Commands,
) {
    let Some(keys) = keys else { return };
    if keys.just_pressed(KeyCode::KeyS) {
        run.screenshot =
            Some(PathBuf::from(format!("bevy_sponza_{}.png", run.techniques[run.technique].replace(':', "_"))));
    }
    if !keys.just_pressed(KeyCode::KeyT) {
        return;
    }
    run.technique = (run.technique + 1) % run.techniques.len();
    let spec = run.techniques[run.technique].clone();
    for camera in &cameras {
        let mut camera = commands.entity(camera);
        match ambient_occlusion(&spec, scene.radius) {
            Ok(Some(ao)) => {
                camera.insert(ao);
            }
            Ok(None) => {
                camera.remove::<(AokitAmbientOcclusion, bevy::pbr::ScreenSpaceAmbientOcclusion)>();
            }
            Err(e) => error!("bevy_sponza: {spec}: {e}"),
        }
    }
    info!("bevy_sponza: {spec}");
}

/// Take the requested screenshot once the first frames (pipeline compilation) are through.
fn screenshot_when_ready(mut run: ResMut<Run>, mut commands: Commands) {
    if run.frames_left > 0 {
        run.frames_left -= 1;
        return;
    }
    let Some(path) = run.screenshot.take() else { return };
    let target = match &run.target {
        Some(image) => Screenshot::image(image.clone()),
        None => Screenshot::primary_window(),
    };
    commands.spawn(target).observe(move |captured: On<ScreenshotCaptured>| {
        let image = captured.image.clone();
        match image.try_into_dynamic() {
            Ok(image) => match image.to_rgb8().save(&path) {
                Ok(()) => info!("bevy_sponza: wrote {}", path.display()),
                Err(e) => error!("bevy_sponza: {}: {e}", path.display()),
            },
            Err(e) => error!("bevy_sponza: the screenshot: {e:?}"),
        }
    });
}
