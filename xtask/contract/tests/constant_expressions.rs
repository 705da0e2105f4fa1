//! Every technique's constants as its expressions compute them (`aokit_contract::constants`,
//! the grammar of `assets/README.md`, "Expressions") equal, bit for bit, the push constants and
//! records the Rust builders put into its graph: at its defaults and with each setting at each
//! of the manifest's tried values, for two frames (different cameras, sizes, guard bands, AO
//! parameters and frame indices). A reworded or mistyped expression, or a builder changed
//! without its expression, fails here naming the struct and field.

use aokit_contract::constants::{FrameInputs, check};
use aokit_contract::manifest::constants::settings_tried;
use aokit_shaders::techniques::TECHNIQUES;

#[test]
fn expressions_reproduce_the_builders_bit_for_bit() {
    let mut failures = Vec::new();
    let mut compared = 0;
    for &t in TECHNIQUES {
        let variants = settings_tried(t);
        let mut missing = None;
        for values in &variants {
            let mut c = t.configure();
            for (k, v) in values {
                c.set(k, v).expect("a value tried above");
            }
            for frame in FrameInputs::examples() {
                let Ok(graph) = c.graph(&frame.frame_desc()) else { continue };
                match check(t, values, &frame, &graph) {
                    Ok(checked) => compared += checked.len(),
                    Err(e) if e.contains("no expression") => missing = missing.or(Some(e)),
                    Err(e) => failures.push(format!("{} {values:?}: {e}", t.name())),
                }
            }
        }
        if let Some(e) = missing {
            failures.push(format!("{}: {e}", t.name()));
        }
    }
    eprintln!("compared {compared} structs");
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
    assert!(compared > 0, "nothing compared");
}

/// The adapters' `ImportParams` from their expressions equal `AdapterSettings::params`, at the
/// defaults and each setting at each tried value, on both frames.
#[test]
fn adapter_expressions_reproduce_the_import_params() {
    use aokit_contract::constants::{evaluate_struct, inputs};
    use aokit_shaders::adapters::settings::{ADAPTERS, AdapterSettings};
    use aokit_shaders::technique::Registered;
    let t: &'static dyn Registered = &ADAPTERS;
    let mut checked = 0;
    let variants = settings_tried(t);
    for values in &variants {
        let mut c = t.configure();
        values.iter().for_each(|(k, v)| c.set(k, v).unwrap());
        let settings = c.settings().downcast_ref::<AdapterSettings>().unwrap();
        for frame in FrameInputs::examples() {
            let built = settings.params(&frame.frame_desc());
            let ours = evaluate_struct(t, "ImportParams", &inputs(&t.rows(), values, &frame).unwrap()).unwrap();
            assert_eq!(ours, bytemuck::bytes_of(&built), "{values:?}");
            checked += 1;
        }
    }
    assert!(checked >= 10, "{checked}");
}
