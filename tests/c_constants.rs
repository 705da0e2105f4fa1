//! `assets/include/aokit_constants.h` — the constants' expressions translated to C — gives the
//! bytes the Rust builders put into the graphs: a C program generated here fills, for every
//! technique at its defaults and with each setting at each tried value, every push-constant
//! block and record the technique's graph carries (each pass with its index among its module's
//! passes), on a frame with odd sizes, and prints them; they must equal the graph's bytes. So must
//! the adapters' `ImportParams`, the temporal accumulation's `TemporalFrame` (with a previous
//! camera and without) and half resolution's `HalfParams` (on the frame made even).
//! Needs a C and a C++ compiler (gcc, g++; a missing one fails unless the run allows its skip:
//! tests/common/skip.rs).

mod common;

use aokit_contract::constants::{FrameInputs, push_struct, record_struct};
use aokit_contract::manifest::constants::settings_tried;
use aokit_contract::manifest::{Manifest, SettingManifest};
use aokit_shaders::graph::Init;
use aokit_shaders::techniques::TECHNIQUES;
use std::fmt::Write;
use std::path::PathBuf;
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A binary32 as an exact C literal.
fn c_float(v: f32) -> String {
    format!("{:?}f", v as f64).replace("inf", "INFINITY")
}

/// Opens a block declaring `{prefix}_settings s` at its defaults with `values` set, as C literals
/// of `listed`'s kinds (counts `8u`, numbers exact floats, choices their index).
fn open_settings(c: &mut String, prefix: &str, listed: &[SettingManifest], values: &[(&str, String)]) {
    writeln!(c, "    {{\n        {prefix}_settings s = {prefix}_defaults();").unwrap();
    for (key, value) in values {
        let row = listed.iter().find(|s| s.key == *key).unwrap();
        let literal = match row.kind.as_str() {
            "count" => format!("{value}u"),
            "number" => c_float(value.parse().unwrap()),
            _ => format!("{}u", row.choices.iter().position(|c| c == value).unwrap()),
        };
        writeln!(c, "        s.{} = {literal};", key.replace('-', "_")).unwrap();
    }
}

/// A call of `{prefix}_{name}` with `s`, the frame inputs `frame` and `pass`, whose result is
/// printed as `what` and hex; `bytes` (the Rust builder's) is the line expected.
fn dump_call(
    c: &mut String,
    expected: &mut Vec<String>,
    (prefix, name, frame, pass): (&str, &str, &str, usize),
    what: &str,
    bytes: &[u8],
) {
    writeln!(
        c,
        "        {{ aokit_{name} out; memset(&out, 0, sizeof out); {prefix}_{name}(&s, &{frame}, {pass}u, &out); dump(\"{what}\", &out, sizeof out); }}"
    )
    .unwrap();
    expected.push(format!("{what} {}", bytes.iter().map(|b| format!("{b:02x}")).collect::<String>()));
}

#[test]
fn generated_c_constants_equal_the_rust_builders_bytes() {
    let manifest = Manifest::committed();
    let header = std::fs::read_to_string(root().join("assets/include/aokit_constants.h")).unwrap();
    assert_eq!(header, manifest.c_constants_header().unwrap(), "aokit_constants.h is stale: run the xtask");
    if common::skip::without_tool(common::skip::C_COMPILER, "cc", "apt-get install gcc") {
        return;
    }
    let frame = FrameInputs::examples()[1];
    let v = |x: aokit_shaders::glam::Vec3| format!("{{{}, {}, {}}}", c_float(x.x), c_float(x.y), c_float(x.z));
    let mut c = String::from("#include <stdio.h>\n#include <string.h>\n#include \"aokit_constants.h\"\n");
    c += "static void dump(const char *what, const void *p, size_t n) {\n    printf(\"%s \", what);\n";
    c += "    for (size_t i = 0; i < n; i++) printf(\"%02x\", ((const unsigned char *)p)[i]);\n    printf(\"\\n\");\n}\n";
    c += "int main(void) {\n";
    writeln!(
        c,
        "    aokit_frame_inputs f = {{{}, {}, {}, {}, {}, {}, {}u, {}u, {}u, {}, {}, {}, {}u, 0u, {{0.0f, 0.0f, 0.0f}}, {{0.0f, 0.0f, 0.0f}}, {{0.0f, 0.0f, 0.0f}}, 0.0f, 0.0f, 0.0f}};",
        v(frame.eye),
        v(frame.target),
        v(frame.up),
        c_float(frame.fov_y),
        c_float(frame.near),
        c_float(frame.far),
        frame.inner.x,
        frame.inner.y,
        frame.guard,
        c_float(frame.radius),
        c_float(frame.exponent),
        c_float(frame.thickness),
        frame.frame_index
    )
    .unwrap();
    let mut expected = Vec::new();
    for &t in TECHNIQUES {
        let listed = manifest.techniques.iter().find(|m| m.name == t.name()).unwrap();
        let variants = settings_tried(t);
        let p = format!("aokit_{}", t.name().replace('-', "_"));
        for values in variants {
            let mut configured = t.configure();
            values.iter().for_each(|(k, val)| configured.set(k, val).unwrap());
            let Ok(graph) = configured.graph(&frame.frame_desc()) else { continue };
            open_settings(&mut c, &p, &listed.settings, &values);
            for (i, pass) in graph.passes.iter().enumerate() {
                let index = graph.passes[..i].iter().filter(|q| q.entry() == pass.entry()).count();
                let mut blocks = Vec::new();
                if let Some(name) = push_struct(pass) {
                    blocks.push((name, index, pass.push_constants.clone()));
                }
                for b in &pass.bindings {
                    let Some(Init::Data(words)) = graph.resource(b.resource).map(|r| &r.init) else { continue };
                    if let Some(name) = record_struct(pass, b.slot) {
                        blocks.push((name, 0, words.iter().flat_map(|w| w.to_le_bytes()).collect()));
                    }
                }
                for (name, index, bytes) in blocks {
                    let what = format!("{}:{values:?}:{i}:{name}", t.name()).replace(['"', ' '], "");
                    dump_call(&mut c, &mut expected, (&p, name, "f", index), &what, &bytes);
                }
            }
            c += "    }\n";
        }
    }
    // The adapters' ImportParams, against AdapterSettings::params.
    {
        use aokit_shaders::adapters::settings::{ADAPTERS, AdapterSettings};
        use aokit_shaders::technique::Registered;
        let t: &'static dyn Registered = &ADAPTERS;
        let listed = manifest.adapters.as_ref().expect("the manifest's adapters");
        let variants = settings_tried(t);
        for values in variants {
            let mut configured = t.configure();
            values.iter().for_each(|(k, val)| configured.set(k, val).unwrap());
            let settings = configured.settings().downcast_ref::<AdapterSettings>().unwrap();
            let bytes = bytemuck::bytes_of(&settings.params(&frame.frame_desc())).to_vec();
            open_settings(&mut c, "aokit_adapters", &listed.settings, &values);
            let what = format!("adapters:{values:?}:ImportParams").replace(['"', ' '], "");
            dump_call(&mut c, &mut expected, ("aokit_adapters", "ImportParams", "f", 0), &what, &bytes);
            c += "    }\n";
        }
    }
    // The temporal accumulation's TemporalFrame, against `TemporalSettings::frame`, on the
    // frame with a previous camera (has_previous 1) and without (0).
    {
        use aokit_shaders::technique::Registered;
        use aokit_shaders::temporal::settings::{TEMPORAL, TemporalSettings};
        let t: &'static dyn Registered = &TEMPORAL;
        let listed = manifest.temporal.as_ref().expect("the manifest's temporal");
        let previous = frame.previous.expect("the example frame has a previous camera");
        writeln!(
            c,
            "    aokit_frame_inputs fp = f; fp.has_previous = 1u; fp.previous_fov_y = {}; fp.previous_near = {}; fp.previous_far = {};",
            c_float(previous.fov_y),
            c_float(previous.near),
            c_float(previous.far)
        )
        .unwrap();
        for (name, value) in [("eye", previous.eye), ("target", previous.target), ("up", previous.up)] {
            for (i, x) in value.to_array().iter().enumerate() {
                writeln!(c, "    fp.previous_{name}[{i}] = {};", c_float(*x)).unwrap();
            }
        }
        for values in settings_tried(t) {
            let mut configured = t.configure();
            values.iter().for_each(|(k, val)| configured.set(k, val).unwrap());
            let settings = configured.settings().downcast_ref::<TemporalSettings>().unwrap();
            open_settings(&mut c, "aokit_temporal", &listed.settings, &values);
            let without = aokit_shaders::graph::FrameDesc { previous_camera: None, ..frame.frame_desc() };
            for (inputs, desc) in [("fp", frame.frame_desc()), ("f", without)] {
                let what = format!("temporal:{values:?}:{inputs}:TemporalFrame").replace(['"', ' '], "");
                let bytes = bytemuck::bytes_of(&settings.frame(&desc)).to_vec();
                dump_call(&mut c, &mut expected, ("aokit_temporal", "TemporalFrame", inputs, 0), &what, &bytes);
            }
            c += "    }\n";
        }
    }
    // Half resolution's HalfParams (its `half` from the halved frame), against `half_params`, on
    // the frame made even (half resolution refuses odd sizes).
    {
        use aokit_shaders::halfres::settings::{HALF_RESOLUTION, HalfSettings, half_params};
        use aokit_shaders::technique::Registered;
        let t: &'static dyn Registered = &HALF_RESOLUTION;
        let listed = manifest.half_resolution.as_ref().expect("the manifest's half_resolution");
        let even =
            FrameInputs { inner: frame.inner + (frame.inner & 1), guard: frame.guard + (frame.guard & 1), ..frame };
        writeln!(
            c,
            "    aokit_frame_inputs fe = f; fe.w = {}u; fe.h = {}u; fe.g = {}u;",
            even.inner.x, even.inner.y, even.guard
        )
        .unwrap();
        for values in settings_tried(t) {
            let mut configured = t.configure();
            values.iter().for_each(|(k, val)| configured.set(k, val).unwrap());
            let settings = configured.settings().downcast_ref::<HalfSettings>().unwrap();
            let params = half_params(settings, &even.frame_desc().camera.view).unwrap();
            open_settings(&mut c, "aokit_half_resolution", &listed.settings, &values);
            let what = format!("half_resolution:{values:?}:HalfParams").replace(['"', ' '], "");
            let bytes = bytemuck::bytes_of(&params);
            dump_call(&mut c, &mut expected, ("aokit_half_resolution", "HalfParams", "fe", 0), &what, bytes);
            c += "    }\n";
        }
        // A technique's own constants at half resolution: its functions with the half frame's
        // inputs (aokit_half_frame_inputs) give the push constants of its passes in the graph
        // at_resolution builds; the odd frame is refused.
        use aokit_shaders::halfres::settings::{Resolution, at_resolution};
        let gtao = aokit_shaders::techniques::find("gtao").unwrap();
        let graph = at_resolution(Resolution::half(), &even.frame_desc(), |d| gtao.configure().graph(d)).unwrap();
        let main = graph.passes.iter().find(|p| p.entry() == "gtao_main").unwrap();
        c += "    {\n        aokit_frame_inputs fh, unchanged;\n";
        c += "        printf(\"half_frame_inputs %d %d\\n\", aokit_half_frame_inputs(&f, &unchanged), aokit_half_frame_inputs(&fe, &fh));\n";
        expected.push("half_frame_inputs 0 1".into());
        c += "        aokit_gtao_settings s = aokit_gtao_defaults();\n";
        dump_call(
            &mut c,
            &mut expected,
            ("aokit_gtao", "GtaoParams", "fh", 0),
            "gtao:half:GtaoParams",
            &main.push_constants,
        );
        c += "    }\n";
    }
    c += "    return 0;\n}\n";
    let dir = std::env::temp_dir().join(format!("aokit-c-constants-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("check.c"), &c).unwrap();
    let exe = dir.join("check");
    let out = Command::new("cc")
        .args(["-std=c11", "-O2", "-Wall", "-Wextra", "-Werror", "-I"])
        .arg(root().join("assets/include"))
        .arg(dir.join("check.c"))
        .arg("-o")
        .arg(&exe)
        .arg("-lm")
        .output()
        .unwrap();
    assert!(out.status.success(), "the generated C does not compile:\n{}", String::from_utf8_lossy(&out.stderr));
    let run = Command::new(&exe).output().unwrap();
    assert!(run.status.success());
    let got: Vec<String> = String::from_utf8(run.stdout).unwrap().lines().map(String::from).collect();
    assert_eq!(got.len(), expected.len(), "one line per block");
    let wrong: Vec<String> =
        got.iter().zip(&expected).filter(|(g, e)| g != e).map(|(g, e)| format!("C    {g}\nRust {e}")).collect();
    eprintln!("{} blocks compared", expected.len());
    assert!(
        wrong.is_empty(),
        "{} of {} blocks differ:\n{}",
        wrong.len(),
        expected.len(),
        wrong[..wrong.len().min(5)].join("\n")
    );
    assert!(expected.len() > 500, "{} blocks", expected.len());
    // C++ engines include it too (C++11: no hexadecimal float literals, designated initializers).
    std::fs::write(dir.join("check.cpp"), "#include \"aokit_constants.h\"\nint main() { return 0; }\n").unwrap();
    if !common::skip::without_tool(common::skip::CXX_COMPILER, "c++", "apt-get install g++") {
        let out = Command::new("c++")
            .args(["-std=c++11", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", "-I"])
            .arg(root().join("assets/include"))
            .arg(dir.join("check.cpp"))
            .output()
            .unwrap();
        assert!(out.status.success(), "aokit_constants.h in C++:\n{}", String::from_utf8_lossy(&out.stderr));
    }
    let _ = std::fs::remove_dir_all(&dir);
}
