//! Every technique's published graphs (`techniques[].variants`, `aokit_contract::graphs`) are the
//! graphs the Rust declarations build, at any settings: for the defaults and each setting at each
//! of the manifest's tried values, on two frames, the variant whose `when` matches the
//! structural settings has the graph's resources, passes and bindings, its size and dispatch
//! expressions evaluate (with the settings, `W H w h`) to what the executors allocate and
//! dispatch, and its table contents give the data words bit for bit. Derived independently:
//! expressions through `aokit_contract::expr`, tables from their declarations.

use aokit_contract::constants::{FrameInputs, inputs};
use aokit_contract::expr::{Value, eval};
use aokit_contract::graphs::{matching, variants};
use aokit_contract::manifest::constants::settings_tried;
use aokit_contract::manifest::tables;
use aokit_shaders::graph::Init;
use aokit_shaders::techniques::TECHNIQUES;

fn int(text: &str, inputs: &aokit_contract::expr::Inputs) -> Result<i64, String> {
    match eval(text, inputs)? {
        Value::Int(i) => Ok(i),
        v => Err(format!("'{text}' is {v:?}, not an integer")),
    }
}

#[test]
fn published_graphs_are_the_declarations_at_every_tried_setting() {
    let tables = tables().unwrap();
    let reference = aokit_contract::manifest::reference_frame(aokit_shaders::glam::UVec2::new(1920, 1080), 64);
    let (mut checked, mut words) = (0, 0);
    let mut failures = Vec::new();
    let mut formulas_used = std::collections::BTreeSet::new();
    for &t in TECHNIQUES {
        let (structural, published) = variants(t, &reference).unwrap();
        // Every variant's `when` names exactly the structural settings.
        assert!(
            published
                .iter()
                .flat_map(|v| &v.when)
                .all(|w| w.len() == structural.len() && structural.iter().all(|k| w.contains_key(k))),
            "{}: a variant's `when` names other settings than {structural:?}",
            t.name()
        );
        let settings = settings_tried(t);
        for values in &settings {
            let mut c = t.configure();
            values.iter().for_each(|(k, v)| c.set(k, v).unwrap());
            let matching = matching(&published, values);
            let [variant] = matching[..] else {
                failures.push(format!("{} {values:?}: {} variants match", t.name(), matching.len()));
                continue;
            };
            for frame in FrameInputs::examples() {
                let Ok(graph) = c.graph(&frame.frame_desc()) else { continue };
                let view = graph.view;
                let mut ins = inputs(&t.rows(), values, &frame).unwrap();
                // Sizes and dispatches see no camera, only the target.
                ins.names.retain(|k, _| ["W", "H", "w", "h", "g"].contains(&k.as_str()));
                let fail =
                    |what: String| format!("{} {values:?} {}x{}: {what}", t.name(), frame.inner.x, frame.inner.y);
                let names: Vec<_> = graph.resources.iter().map(|r| r.name).collect();
                let listed: Vec<_> = variant.resources.iter().map(|r| r.name.as_str()).collect();
                if names != listed {
                    failures.push(fail(format!("resources {listed:?}, the graph's {names:?}")));
                    continue;
                }
                for (m, r) in variant.resources.iter().zip(&graph.resources) {
                    match int(&m.size, &ins) {
                        Ok(n) if n == r.len(&view) as i64 => checked += 1,
                        other => failures.push(fail(format!(
                            "{} size '{}' = {other:?}, allocated {}",
                            r.name,
                            m.size,
                            r.len(&view)
                        ))),
                    }
                    let (Init::Data(data), Some(contents)) = (&r.init, &m.contents) else { continue };
                    let Some(table) = &contents.table else { continue };
                    let got = eval(table, &ins).and_then(|name| {
                        let Value::Text(name) = name else { return Err(format!("table {name:?}")) };
                        let table = tables.iter().find(|t| t.name == name).ok_or(format!("no table {name}"))?;
                        let first = contents.first.as_deref().map_or(Ok(0), |f| int(f, &ins))? as usize;
                        let count = int(contents.count.as_deref().unwrap_or("0"), &ins)? as usize;
                        let per = if table.elem == "Vec2" { 2 } else { 1 };
                        let values = table.values.get(first * per..(first + count) * per).ok_or("out of the table")?;
                        Ok(values.iter().map(|v| v.to_bits()).collect::<Vec<u32>>())
                    });
                    match got {
                        Ok(w) if w == *data => words += w.len(),
                        other => failures.push(fail(format!("{} contents {other:?}", r.name))),
                    }
                }
                let entries: Vec<_> = graph.passes.iter().map(|p| (p.label, p.entry())).collect();
                let listed: Vec<_> = variant.passes.iter().map(|p| (p.label.as_str(), p.entry.as_str())).collect();
                if entries != listed {
                    failures.push(fail(format!("passes {listed:?}, the graph's {entries:?}")));
                    continue;
                }
                for (m, p) in variant.passes.iter().zip(&graph.passes) {
                    let bindings: Vec<_> = p.bindings.iter().map(|b| (b.slot, b.resource.to_string())).collect();
                    let listed: Vec<_> = m.bindings.iter().map(|b| (b.0, b.1.clone())).collect();
                    if bindings != listed {
                        failures.push(fail(format!("{} bindings {listed:?}, the graph's {bindings:?}", p.label)));
                    }
                    let n = p.invocations(&view);
                    let got = (int(&m.dispatch[0], &ins), int(&m.dispatch[1], &ins));
                    if got != (Ok(n.x as i64), Ok(n.y as i64)) {
                        failures
                            .push(fail(format!("{} dispatch {:?} = {got:?}, the graph's {n}", p.label, m.dispatch)));
                    }
                    checked += 1;
                }
            }
        }
        // Every formula of the technique's declaration names something one of its graphs has.
        for f in t.formulas() {
            let (name, part) = f.of.split_once('.').unwrap_or((f.of, ""));
            if published.iter().any(|v| match part {
                "" | "table" | "first" | "count" => v.resources.iter().any(|r| r.name == name),
                _ => v.passes.iter().any(|p| p.label == name),
            }) {
                formulas_used.insert(f.of);
            }
        }
    }
    let unused: Vec<_> =
        TECHNIQUES.iter().flat_map(|t| t.formulas()).filter(|f| !formulas_used.contains(f.of)).collect();
    assert!(unused.is_empty(), "formulas that describe nothing: {unused:?}");
    eprintln!("{checked} sizes and dispatches, {words} table words checked");
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
    assert!(checked > 1000 && words > 0, "{checked} checked, {words} words");
}
