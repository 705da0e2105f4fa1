//! A technique's constants structs computed from the expressions of its rows
//! ([`aokit_shaders::technique::Constant::expr`], the grammar of [`crate::expr`]): what an
//! engine without Rust does, and what `tests/constant_expressions.rs` compares, byte for byte,
//! with the push constants and records the Rust builders put into the technique's graph.

use crate::expr::{self, Inputs, Value};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::contract::{StructLayout, shared_structs};
use aokit_shaders::glam::{UVec2, Vec3};
use aokit_shaders::graph::{FrameDesc, Graph, Init, Pass};
use aokit_shaders::technique::{Kind, Registered, Row};

/// What an engine knows of a frame: the camera as eye/target/up and vertical field of view of
/// the INNER image, the image sizes, the AO parameters and the frame's index.
#[derive(Copy, Clone, Debug)]
pub struct FrameInputs {
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    /// Radians.
    pub fov_y: f32,
    pub inner: UVec2,
    pub guard: u32,
    pub near: f32,
    pub far: f32,
    pub radius: f32,
    pub exponent: f32,
    pub thickness: f32,
    pub frame_index: u32,
    /// The previous frame's camera (same image sizes), for the temporal accumulation; `None` on
    /// a first frame.
    pub previous: Option<PreviousView>,
}

/// The previous frame's camera as an engine knows it (the names `previous_eye`, … of
/// `assets/README.md`, "Temporal accumulation").
#[derive(Copy, Clone, Debug)]
pub struct PreviousView {
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    /// Radians.
    pub fov_y: f32,
    pub near: f32,
    pub far: f32,
}

impl FrameInputs {
    /// Two frames the checks use: different cameras, image sizes, guard bands, AO parameters
    /// and frame indices (a 1920×1080 frame with a 64-pixel guard band, and a small odd one).
    pub fn examples() -> [FrameInputs; 2] {
        [
            FrameInputs {
                eye: Vec3::new(0.0, 1.0, 5.0),
                target: Vec3::ZERO,
                up: Vec3::Y,
                fov_y: 1.0,
                inner: UVec2::new(1920, 1080),
                guard: 64,
                near: 0.1,
                far: 100.0,
                radius: 0.5,
                exponent: 2.0,
                thickness: 0.0,
                frame_index: 0,
                previous: None,
            },
            FrameInputs {
                eye: Vec3::new(3.7, -2.1, 0.4),
                target: Vec3::new(-1.0, 0.5, -7.3),
                up: Vec3::new(0.1, 1.0, 0.05),
                fov_y: 0.83,
                inner: UVec2::new(97, 63),
                guard: 13,
                near: 0.05,
                far: 40.0,
                radius: 0.37,
                exponent: 1.7,
                thickness: 0.02,
                frame_index: 5,
                previous: Some(PreviousView {
                    eye: Vec3::new(3.9, -2.0, 0.6),
                    target: Vec3::new(-0.8, 0.4, -7.0),
                    up: Vec3::new(0.12, 1.0, 0.04),
                    fov_y: 0.85,
                    near: 0.06,
                    far: 41.0,
                }),
            },
        ]
    }

    /// The frame the Rust builders take.
    pub fn frame_desc(&self) -> FrameDesc {
        let camera =
            Camera::look_at(self.eye, self.target, self.up, self.fov_y, self.inner, self.guard, self.near, self.far);
        let previous = self
            .previous
            .map(|p| Camera::look_at(p.eye, p.target, p.up, p.fov_y, self.inner, self.guard, p.near, p.far));
        FrameDesc {
            frame_index: self.frame_index,
            previous_camera: previous,
            ..FrameDesc::new(camera, self.radius, self.exponent, self.thickness)
        }
    }

    /// The names an expression reads (`assets/README.md`, "Expressions"), without `pass`.
    fn names(&self) -> Vec<(&'static str, Value)> {
        let v = |v: Vec3| Value::Vector(v.to_array().to_vec());
        let (w, h, g) = (self.inner.x as i64, self.inner.y as i64, self.guard as i64);
        let previous = self.previous.unwrap_or(PreviousView {
            eye: self.eye,
            target: self.target,
            up: self.up,
            fov_y: self.fov_y,
            near: self.near,
            far: self.far,
        });
        vec![
            ("W", Value::Int(w + 2 * g)),
            ("H", Value::Int(h + 2 * g)),
            ("w", Value::Int(w)),
            ("h", Value::Int(h)),
            ("g", Value::Int(g)),
            ("eye", v(self.eye)),
            ("target", v(self.target)),
            ("up", v(self.up)),
            ("fov_y", Value::Real(self.fov_y)),
            ("near", Value::Real(self.near)),
            ("far", Value::Real(self.far)),
            ("radius", Value::Real(self.radius)),
            ("exponent", Value::Real(self.exponent)),
            ("thickness", Value::Real(self.thickness)),
            ("frame", Value::Int(self.frame_index as i64)),
            // The previous frame's camera; this frame's on a first frame (`has_previous` false).
            ("previous_eye", v(previous.eye)),
            ("previous_target", v(previous.target)),
            ("previous_up", v(previous.up)),
            ("previous_fov_y", Value::Real(previous.fov_y)),
            ("previous_near", Value::Real(previous.near)),
            ("previous_far", Value::Real(previous.far)),
            ("has_previous", Value::Bool(self.previous.is_some())),
        ]
    }
}

/// A setting's value as an expression reads it: counts exact, numbers binary32, choices names.
fn setting_value(kind: Kind, text: &str) -> Result<Value, String> {
    Ok(match kind {
        Kind::Count { .. } => Value::Int(text.parse().map_err(|_| format!("count {text}"))?),
        Kind::Number { .. } => Value::Real(text.parse().map_err(|_| format!("number {text}"))?),
        Kind::Choice(_) => Value::Text(text.into()),
    })
}

/// The setting as a literal of the grammar (counts `8`, numbers `f32(6)`, choices `"hbao"`).
fn literal(kind: Kind, text: &str) -> String {
    match kind {
        Kind::Count { .. } => text.into(),
        Kind::Number { .. } => format!("f32({text})"),
        Kind::Choice(_) => format!("\"{text}\""),
    }
}

/// `row`'s expression as the manifest publishes it for `t`: the settings of its settings type
/// that `t` does not read replaced by their fixed values (`index(`key`)` by the index), so no
/// expression names a setting the technique does not have. Empty: no expression yet.
pub fn expression(t: &dyn Registered, expr: &str) -> String {
    let mut out = expr.to_string();
    for (row, value) in t.fixed() {
        if let Kind::Choice(names) = row.kind {
            let i = names.iter().position(|n| *n == value).unwrap_or(0);
            out = out.replace(&format!("index(`{}`)", row.key), &i.to_string());
        }
        out = out.replace(&format!("`{}`", row.key), &literal(row.kind, &value));
    }
    out
}

/// The inputs of `t`'s expressions with `values` (its settings, `(key, text)`) and `frame`.
pub fn inputs(rows: &[Row], values: &[(&str, String)], frame: &FrameInputs) -> Result<Inputs, String> {
    let mut inputs = Inputs::default();
    for (key, text) in values {
        let row = rows.iter().find(|r| r.key == *key).ok_or_else(|| format!("no setting {key}"))?;
        inputs.settings.insert(key.to_string(), setting_value(row.kind, text)?);
        if let Kind::Choice(names) = row.kind {
            inputs.choices.insert(key.to_string(), names.iter().map(|n| n.to_string()).collect());
        }
    }
    for (name, value) in frame.names() {
        inputs.names.insert(name.into(), value);
    }
    Ok(inputs)
}

/// The bytes of struct `name` from `t`'s expressions: every field at its offset, nested structs
/// from their own rows. Fails naming the field whose expression is missing, wrong or of the
/// wrong type.
pub fn evaluate_struct(t: &dyn Registered, name: &str, inputs: &Inputs) -> Result<Vec<u8>, String> {
    let layouts = shared_structs();
    let layout = layouts.iter().find(|s| s.name == name).ok_or_else(|| format!("{name} is not a shared struct"))?;
    let mut out = vec![0u8; layout.size];
    write_struct(t, layout, &layouts, inputs, &mut out)?;
    Ok(out)
}

/// `inputs` with the half-resolution frame's names (`half_resolution.half_names`,
/// [`aokit_shaders::halfres::settings::HALF_NAMES`]): `W H w h g` halved, everything else as is.
pub fn half_inputs(inputs: &Inputs) -> Result<Inputs, String> {
    let mut half = inputs.clone();
    for (name, text) in aokit_shaders::halfres::settings::HALF_NAMES {
        half.names.insert(name.into(), expr::eval(text, inputs)?);
    }
    Ok(half)
}

/// `inputs` with the previous frame's camera in place of this frame's (`temporal.previous_names`,
/// [`aokit_shaders::temporal::settings::PREVIOUS_NAMES`]): `eye` takes `previous_eye`'s value, ….
pub fn previous_inputs(inputs: &Inputs) -> Result<Inputs, String> {
    let mut previous = inputs.clone();
    for (name, from) in aokit_shaders::temporal::settings::PREVIOUS_NAMES {
        let value = inputs.names.get(from).ok_or_else(|| format!("no input {from}"))?.clone();
        previous.names.insert(name.into(), value);
    }
    Ok(previous)
}

fn write_struct(
    t: &dyn Registered,
    layout: &StructLayout,
    layouts: &[StructLayout],
    inputs: &Inputs,
    out: &mut [u8],
) -> Result<(), String> {
    for f in &layout.fields {
        let path = format!("{}.{}", layout.name, f.name);
        let row = t.constants().iter().find(|c| c.field == path).ok_or_else(|| format!("{path}: no row"))?;
        if row.expr.is_empty() {
            return Err(format!("{path}: no expression"));
        }
        let text = expression(t, row.expr);
        let bytes = &mut out[f.offset..f.offset + f.size];
        if let Some(nested) = layouts.iter().find(|s| s.name == f.ty) {
            if text == f.ty {
                write_struct(t, nested, layouts, inputs, bytes)?;
            } else if text == format!("half({})", f.ty) {
                write_struct(t, nested, layouts, &half_inputs(inputs).map_err(|e| format!("{path}: {e}"))?, bytes)?;
            } else if text == format!("previous({})", f.ty) {
                write_struct(t, nested, layouts, &previous_inputs(inputs).map_err(|e| format!("{path}: {e}"))?, bytes)?;
            } else {
                return Err(format!("{path}: a {0} field's expression is `{0}`, `half({0})` or `previous({0})`", f.ty));
            }
            continue;
        }
        let value = expr::eval(&text, inputs).map_err(|e| format!("{path}: {e}"))?;
        let words: Vec<u32> = match (f.ty, &value) {
            ("f32", Value::Real(r)) => vec![r.to_bits()],
            ("f32", Value::Int(i)) => vec![(*i as f32).to_bits()],
            ("u32", Value::Int(i)) if (0..=u32::MAX as i64).contains(i) => vec![*i as u32],
            ("u32", Value::Bool(b)) => vec![*b as u32],
            ("i32", Value::Int(i)) if (i32::MIN as i64..=i32::MAX as i64).contains(i) => vec![*i as i32 as u32],
            ("Vec2" | "Vec3" | "Vec4", Value::Vector(c)) if c.len() == f.size / 4 => {
                c.iter().map(|r| r.to_bits()).collect()
            }
            ("UVec2" | "UVec3" | "UVec4", Value::IntVector(c)) if c.len() == f.size / 4 => {
                c.iter().map(|&i| i as u32).collect()
            }
            ("Mat4", Value::Matrix(m)) => m.iter().map(|r| r.to_bits()).collect(),
            _ => return Err(format!("{path}: {} from `{text}` = {value:?}", f.ty)),
        };
        bytes.copy_from_slice(bytemuck::cast_slice(&words));
    }
    Ok(())
}

/// The push-constant struct of `pass`: the first of its kernels that declares one (a raster
/// pass's is its vertex module's).
pub fn push_struct(pass: &Pass) -> Option<&'static str> {
    pass.declared_by().iter().find_map(|k| k.push_constants).map(|(name, _)| name)
}

/// The shared struct whose records `pass`'s binding at `slot` holds (`[SvaoFrame]` →
/// `SvaoFrame`), from the kernels' declarations; `None` for plain elements.
pub fn record_struct(pass: &Pass, slot: u32) -> Option<&'static str> {
    pass.declared_by().iter().find_map(|k| k.binding(slot)).and_then(|d| (d.element)()).map(|s| s.name)
}

/// One comparison of [`check`]: a struct the Rust builder wrote and the expressions' bytes.
#[derive(Debug)]
pub struct Checked {
    pub pass: String,
    pub structure: String,
}

/// Compare, for `t` with `values` and `frame`, every push-constant block and every record the
/// Rust builders put into the graph with the bytes of [`evaluate_struct`]; `pass` is the
/// pass's index among the graph's passes of the same module. Returns what was compared, or the
/// first difference (struct, field, both values).
pub fn check(
    t: &'static dyn Registered,
    values: &[(&str, String)],
    frame: &FrameInputs,
    graph: &Graph,
) -> Result<Vec<Checked>, String> {
    let rows = t.rows();
    let mut inputs = inputs(&rows, values, frame)?;
    let mut checked = Vec::new();
    let layouts = shared_structs();
    for (i, pass) in graph.passes.iter().enumerate() {
        let index = graph.passes[..i].iter().filter(|p| p.entry() == pass.entry()).count();
        inputs.names.insert("pass".into(), Value::Int(index as i64));
        let mut compare = |name: &str, built: &[u8], what: String| -> Result<(), String> {
            let ours = evaluate_struct(t, name, &inputs).map_err(|e| format!("{what}: {e}"))?;
            if ours != built[..ours.len().min(built.len())] || built.len() < ours.len() {
                let layout = layouts.iter().find(|s| s.name == name).expect("evaluated above");
                return Err(format!("{what}: {}", first_difference(layout, &layouts, &ours, built)));
            }
            checked.push(Checked { pass: format!("{} {}", pass.label, pass.entry()), structure: name.into() });
            Ok(())
        };
        if let Some(name) = push_struct(pass) {
            compare(name, &pass.push_constants, format!("pass {i} ({}) push constants {name}", pass.entry()))?;
        }
        for b in &pass.bindings {
            let Some(Init::Data(words)) = graph.resource(b.resource).map(|r| &r.init) else { continue };
            if let Some(name) = record_struct(pass, b.slot) {
                let what = format!("pass {i} ({}) record {} ({name})", pass.entry(), b.resource);
                compare(name, bytemuck::cast_slice(words), what)?;
            }
        }
    }
    Ok(checked)
}

/// The first field where `ours` and `built` differ, with both values as words.
fn first_difference(layout: &StructLayout, layouts: &[StructLayout], ours: &[u8], built: &[u8]) -> String {
    for f in &layout.fields {
        let range = f.offset..f.offset + f.size;
        if ours.get(range.clone()) == built.get(range.clone()) {
            continue;
        }
        if let Some(nested) = layouts.iter().find(|s| s.name == f.ty) {
            let inner =
                first_difference(nested, layouts, &ours[range.clone()], built.get(range.clone()).unwrap_or(&[]));
            return format!("{}.{} → {inner}", layout.name, f.name);
        }
        let words = |b: Option<&[u8]>| -> Vec<String> {
            b.map(|b| {
                b.chunks_exact(4)
                    .map(|c| {
                        let w = u32::from_le_bytes([c[0], c[1], c[2], c[3]]);
                        format!("{w:#x} ({})", f32::from_bits(w))
                    })
                    .collect()
            })
            .unwrap_or_default()
        };
        return format!(
            "{}.{}: expressions {:?}, builder {:?}",
            layout.name,
            f.name,
            words(ours.get(range.clone())),
            words(built.get(range))
        );
    }
    format!("{}: lengths differ ({} vs {})", layout.name, ours.len(), built.len())
}
