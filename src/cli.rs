//! Command-line pieces shared by the `aokit` tool and the examples (feature `cli`): the scene,
//! camera and AO-parameter flags and their resolution into a [`Frame`], and the techniques'
//! settings flags generated from the registry.

use crate::frame::{CameraChoice, Frame, FrameRequest};
use crate::scene::Scene;
use crate::scene::builtin::{self, BuiltinScene};
use crate::technique::{CliSettings, Row, TECHNIQUES, Technique};
use aokit_shaders::glam::Vec3;
use aokit_shaders::technique::{Kind, RESOLUTION_KEY};
use std::path::Path;

/// The scene, the output size, the camera and the AO parameters (`aokit render`'s flags).
#[derive(clap::Args, Clone, Debug)]
#[command(allow_negative_numbers = true)]
pub struct SceneArgs {
    /// Built-in scene name (see `aokit scenes`) or a path to .obj/.gltf/.glb/.ply[.gz].
    #[arg(long)]
    pub scene: String,
    /// Output width in pixels (the guard band is added around it).
    #[arg(long, default_value_t = 1920)]
    pub width: u32,
    #[arg(long, default_value_t = 1080)]
    pub height: u32,
    /// Camera preset of a built-in scene, or `auto` to frame the scene's bounds.
    #[arg(long)]
    pub camera: Option<String>,
    /// Explicit camera position (x,y,z); needs --target.
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, requires = "target")]
    pub eye: Option<Vec3>,
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, requires = "eye")]
    pub target: Option<Vec3>,
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, default_value = "0,1,0")]
    pub up: Vec3,
    /// Vertical field of view of the output image in degrees.
    #[arg(long)]
    pub fov: Option<f32>,
    /// World-space AO radius (default: per built-in scene, else 2 % of the bounding-box diagonal).
    #[arg(long)]
    pub radius: Option<f32>,
    /// AO exponent (spec default 2; the papers' figures use 4).
    #[arg(long, default_value_t = 2.0)]
    pub exponent: f32,
    /// Halo thickness τ (spec svao-raysd §4.3).
    #[arg(long, default_value_t = 0.0)]
    pub thickness: f32,
}

/// `x,y,z` as a vector.
pub fn parse_vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<f32> =
        s.split(',').map(|p| p.trim().parse::<f32>().map_err(|e| format!("'{p}': {e}"))).collect::<Result<_, _>>()?;
    match parts[..] {
        [x, y, z] => Ok(Vec3::new(x, y, z)),
        _ => Err(format!("expected x,y,z, got '{s}'")),
    }
}

/// A built-in scene by name, or a scene file.
pub fn load_scene(spec: &str) -> Result<(Scene, Option<&'static BuiltinScene>), String> {
    if let Some(b) = builtin::find(spec) {
        return Ok((b.load().map_err(|e| e.to_string())?, Some(b)));
    }
    let path = Path::new(spec);
    if !path.exists() {
        let names: Vec<_> = builtin::builtin_scenes().iter().map(|s| s.name).collect();
        return Err(format!("'{spec}' is neither a built-in scene ({}) nor an existing file", names.join(", ")));
    }
    Ok((Scene::load(path).map_err(|e| e.to_string())?, None))
}

impl SceneArgs {
    /// Load the scene and resolve the camera and AO parameters with a guard band of `guard`
    /// pixels.
    pub fn resolve(&self, guard: u32) -> Result<(Scene, Frame), String> {
        let (scene, builtin) = load_scene(&self.scene)?;
        let fov_default = builtin.map_or(60.0, |b| b.cameras[0].fov_deg);
        let camera = match (&self.eye, &self.target, self.camera.as_deref()) {
            (Some(eye), Some(target), _) => CameraChoice::Explicit {
                eye: *eye,
                target: *target,
                up: self.up,
                fov_deg: self.fov.unwrap_or(fov_default),
            },
            (_, _, Some("auto")) => CameraChoice::Auto { fov_deg: self.fov.unwrap_or(60.0) },
            (_, _, None) if builtin.is_none() => CameraChoice::Auto { fov_deg: self.fov.unwrap_or(60.0) },
            (_, _, name) => CameraChoice::Preset { name: name.map(str::to_string), fov_deg: self.fov },
        };
        let request = FrameRequest {
            width: self.width,
            height: self.height,
            guard,
            camera,
            radius: self.radius,
            exponent: self.exponent,
            thickness: self.thickness,
        };
        let frame = Frame::resolve(&scene, builtin, &request).map_err(|e| e.to_string())?;
        Ok((scene, frame))
    }
}

/// Every registered technique's settings as command-line flags. The flags, their help, ranges,
/// choices and defaults are read from the settings rows beside the kernels
/// (`aokit_shaders::technique::Setting`), so none is written here. A flag applies to every
/// technique of the command that reads it; a flag no technique of the command reads is an error.
#[derive(Clone, Debug, Default)]
pub struct TechniqueArgs {
    /// The flags given on the command line.
    pub given: CliSettings,
}

/// A command-line flag and the rows (one per technique) it sets.
struct FlagDecl {
    name: &'static str,
    /// `None`: a value flag; `Some(value)`: a switch setting `value`.
    switch: Option<&'static str>,
    row: Row,
    techniques: Vec<&'static str>,
}

/// The flags of every technique in the registry, in registry order; techniques sharing a flag
/// share its settings row.
fn flags() -> Vec<FlagDecl> {
    let mut flags: Vec<FlagDecl> = Vec::new();
    for t in TECHNIQUES {
        for row in t.rows() {
            let spellings = row.flag.map(|f| (f, None)).into_iter().chain(row.switch.map(|(f, v)| (f, Some(v))));
            for (name, switch) in spellings {
                match flags.iter_mut().find(|f| f.name == name) {
                    Some(f) => {
                        assert!(
                            f.row.settings_type == row.settings_type && f.row.key == row.key,
                            "--{name} is declared by two different settings ({} and {})",
                            f.row.settings_type,
                            row.settings_type
                        );
                        f.techniques.push(t.name());
                    }
                    None => flags.push(FlagDecl { name, switch, row: row.clone(), techniques: vec![t.name()] }),
                }
            }
        }
    }
    flags
}

impl clap::Args for TechniqueArgs {
    fn augment_args(mut cmd: clap::Command) -> clap::Command {
        for f in flags() {
            let applies = format!("[{}]", f.techniques.join(", "));
            let arg = clap::Arg::new(f.name).long(f.name).help_heading("Technique settings");
            let arg = match (f.switch, f.row.kind) {
                (Some(_), _) => {
                    let arg = arg.action(clap::ArgAction::SetTrue).help(format!("{} {applies}", f.row.help));
                    // A switch and the value flag of the same setting contradict each other.
                    match f.row.flag {
                        Some(value_flag) => arg.conflicts_with(value_flag),
                        None => arg,
                    }
                }
                (None, Kind::Choice(names)) => arg
                    .value_parser(clap::builder::PossibleValuesParser::new(names))
                    .default_value(f.row.default.clone())
                    .help(format!("{} {applies}", f.row.help)),
                (None, kind) => arg
                    .value_name(if matches!(kind, Kind::Count { .. }) { "N" } else { "X" })
                    .allow_negative_numbers(true)
                    .default_value(f.row.default.clone())
                    .help(format!("{} ({}) {applies}", f.row.help, kind.accepted())),
            };
            cmd = cmd.arg(arg);
        }
        // The resolution every technique takes (not a settings row: it transforms the graph).
        let names = aokit_shaders::technique::Resolution::NAMES;
        cmd.arg(
            clap::Arg::new(RESOLUTION_KEY)
                .long(RESOLUTION_KEY)
                .help_heading("Technique settings")
                // The names, and a half one with its plane tolerance (`half-tau3`): what the
                // `resolution=` key takes.
                .value_parser(|s: &str| aokit_shaders::technique::Resolution::parse(s).map(|_| s.to_string()))
                .default_value(names[0])
                .help(format!(
                    "Run at the full target, or at half resolution with an edge-aware upsample \
                     (docs/algorithms/half-resolution.md; half-nearest keeps the nearest pixel of each 2×2 block; \
                     -tau<τ> after a half one sets the upsample's plane tolerance) ({}) [every technique]",
                    names.join("|")
                )),
        )
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl clap::FromArgMatches for TechniqueArgs {
    fn from_arg_matches(matches: &clap::ArgMatches) -> Result<Self, clap::Error> {
        let mut args = TechniqueArgs::default();
        args.update_from_arg_matches(matches)?;
        Ok(args)
    }

    /// Only flags the user typed: the defaults are the techniques' own.
    fn update_from_arg_matches(&mut self, matches: &clap::ArgMatches) -> Result<(), clap::Error> {
        if matches.value_source(RESOLUTION_KEY) == Some(clap::parser::ValueSource::CommandLine) {
            self.given.0.push((RESOLUTION_KEY.to_string(), matches.get_one::<String>(RESOLUTION_KEY).cloned()));
        }
        for f in flags() {
            if matches.value_source(f.name) != Some(clap::parser::ValueSource::CommandLine) {
                continue;
            }
            let value = match f.switch {
                Some(_) => None,
                None => matches.get_one::<String>(f.name).cloned(),
            };
            self.given.0.push((f.name.to_string(), value));
        }
        Ok(())
    }
}

impl TechniqueArgs {
    /// The techniques of `specs` (`name[:key=value…]`) with the given flags applied; refuses
    /// a flag none of them reads.
    pub fn techniques(&self, specs: &[&str]) -> Result<Vec<Technique>, String> {
        let techniques = specs.iter().map(|s| self.given.technique(s)).collect::<Result<Vec<_>, _>>()?;
        let unused = self.given.unused(&techniques.iter().collect::<Vec<_>>());
        if !unused.is_empty() {
            let names: Vec<_> = techniques.iter().map(|t| t.name()).collect();
            return Err(format!("{} not read by {} (see `aokit techniques`)", unused.join(", "), names.join(", ")));
        }
        Ok(techniques)
    }

    /// One technique.
    pub fn technique(&self, spec: &str) -> Result<Technique, String> {
        Ok(self.techniques(&[spec])?.remove(0))
    }
}

/// The registry as text: every technique, its summary and its settings (key, accepted values,
/// default, flag).
pub fn list_techniques() -> String {
    let mut out = String::new();
    for t in TECHNIQUES {
        out += &format!("{:12} {}\n", t.name(), t.summary());
        let defaults = t.configure().values();
        for row in t.rows() {
            let default = defaults.iter().find(|(k, _)| *k == row.key).map_or(String::new(), |(_, v)| v.clone());
            let flag = match (row.flag, row.switch) {
                (Some(f), Some((s, v))) => format!("--{f}, --{s} (= {v})"),
                (Some(f), None) => format!("--{f}"),
                (None, Some((s, v))) => format!("--{s} (= {v})"),
                (None, None) => String::new(),
            };
            out += &format!("    {:18} {:28} [{default}]  {flag}\n", row.key, row.kind.accepted());
        }
    }
    let names = aokit_shaders::technique::Resolution::NAMES;
    out += &format!(
        "every technique also takes\n    {RESOLUTION_KEY:18} {:28} [{}]  --{RESOLUTION_KEY}  \
         (docs/algorithms/half-resolution.md; a half one may end in -tau<τ>)\n",
        names.join("|"),
        names[0]
    );
    out
}
