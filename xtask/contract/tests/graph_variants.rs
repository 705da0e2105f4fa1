//! Every technique's published graphs (`techniques[].variants`, `aokit_contract::graphs`) are the
//! graphs the Rust declarations build, at any settings: for the defaults and each setting at each
//! of the manifest's tried values, on two frames, the variant whose `when` matches the
//! structural settings has the graph's resources, passes and bindings, its size and dispatch
//! expressions evaluate (with the settings, `W H w h`) to what the executors allocate and
//! dispatch, and its table contents give the data words bit for bit. Derived independently:
//! expressions through `aokit_contract::expr`, tables from their declarations.

use aokit_contract::constants::{FrameInputs, evaluate_struct, half_inputs, inputs, push_struct, record_struct};
use aokit_contract::expr::{Inputs, Value, eval};
use aokit_contract::graphs::{matching, variants};
use aokit_contract::manifest::constants::settings_tried;
use aokit_contract::manifest::{Manifest, PassManifest, ResourceManifest, half_resolution, reference_frame, tables};
use aokit_shaders::graph::{Elem, Graph, Init, Lifetime};
use aokit_shaders::technique::Registered;
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

/// What a published transform says a graph is: its resources (with the inputs their sizes are
/// evaluated with) and passes (bindings already renamed, the inputs of their dispatches, whether
/// a barrier comes first, the declaration and inputs of their constants).
struct Expected<'a> {
    resources: Vec<(&'a ResourceManifest, &'a Inputs)>,
    passes: Vec<ExpectedPass<'a>>,
    output: String,
}

struct ExpectedPass<'a> {
    pass: PassManifest,
    sizes: &'a Inputs,
    barrier: bool,
    owner: &'static dyn Registered,
    constants: &'a Inputs,
}

/// The differences between `graph` (built by the Rust transform) and `expected`: resource names
/// and sizes, passes, bindings, dispatches, barriers, the output, and every push-constant block
/// and record bit for bit. Returns how many structs matched.
fn compare(graph: &Graph, expected: &Expected, failures: &mut Vec<String>, fail: &dyn Fn(String) -> String) -> usize {
    let view = graph.view;
    let names: Vec<_> = graph.resources.iter().map(|r| r.name).collect();
    let listed: Vec<_> = expected.resources.iter().map(|(r, _)| r.name.as_str()).collect();
    if names != listed {
        failures.push(fail(format!("resources {listed:?}, the transform's {names:?}")));
        return 0;
    }
    for ((m, ins), r) in expected.resources.iter().zip(&graph.resources) {
        if int(&m.size, ins) != Ok(r.len(&view) as i64) {
            failures.push(fail(format!("{} size '{}', allocated {}", r.name, m.size, r.len(&view))));
        }
        let elem = match r.elem {
            Elem::F32 => "f32",
            Elem::U32 => "u32",
        };
        let lifetime = match r.lifetime {
            Lifetime::PerFrame => "per_frame",
            Lifetime::Persistent => "persistent",
        };
        let init = match &r.init {
            Init::Fill(bits) => format!("fill {bits:#010x}"),
            Init::Data(_) => "data".into(),
            Init::Undefined => "undefined".into(),
        };
        if (m.elem.as_str(), m.lifetime.as_str(), &m.init) != (elem, lifetime, &init) {
            failures.push(fail(format!(
                "{}: {} {} {}, the transform's {elem} {lifetime} {init}",
                r.name, m.elem, m.lifetime, m.init
            )));
        }
    }
    if graph.output != expected.output {
        failures.push(fail(format!("output {}, the transform's {}", expected.output, graph.output)));
    }
    let entries: Vec<_> = graph.passes.iter().map(|p| (p.label, p.entry())).collect();
    let listed: Vec<_> = expected.passes.iter().map(|e| (e.pass.label.as_str(), e.pass.entry.as_str())).collect();
    if entries != listed {
        failures.push(fail(format!("passes {listed:?}, the transform's {entries:?}")));
        return 0;
    }
    let barriers = graph.barriers();
    let mut structs = 0;
    for (i, (e, p)) in expected.passes.iter().zip(&graph.passes).enumerate() {
        let bindings: Vec<_> = p.bindings.iter().map(|b| (b.slot, b.resource.to_string())).collect();
        let listed: Vec<_> = e.pass.bindings.iter().map(|b| (b.0, b.1.clone())).collect();
        if bindings != listed {
            failures.push(fail(format!("{} bindings {listed:?}, the transform's {bindings:?}", p.label)));
        }
        let inv = p.invocations(&view);
        let got = (int(&e.pass.dispatch[0], e.sizes), int(&e.pass.dispatch[1], e.sizes));
        if got != (Ok(inv.x as i64), Ok(inv.y as i64)) {
            failures.push(fail(format!("{} dispatch {:?}, the transform's {inv}", p.label, e.pass.dispatch)));
        }
        if barriers[i] != e.barrier {
            failures.push(fail(format!("{} barrier {}, the transform's {}", p.label, e.barrier, barriers[i])));
        }
        let index = graph.passes[..i].iter().filter(|q| q.entry() == p.entry()).count();
        let mut ins = e.constants.clone();
        ins.names.insert("pass".into(), Value::Int(index as i64));
        let mut blocks: Vec<(&str, &[u8])> = Vec::new();
        if let Some(name) = push_struct(p) {
            blocks.push((name, &p.push_constants));
        }
        for b in &p.bindings {
            let Some(Init::Data(words)) = graph.resource(b.resource).map(|r| &r.init) else { continue };
            if let Some(name) = record_struct(p, b.slot) {
                blocks.push((name, bytemuck::cast_slice(words)));
            }
        }
        for (name, built) in blocks {
            match evaluate_struct(e.owner, name, &ins) {
                Ok(ours) if built.get(..ours.len()) == Some(&ours[..]) => structs += 1,
                Ok(ours) => {
                    let word = |b: &[u8], at: usize| b.get(at..at + 4).map(|w| w.to_vec());
                    let at = (0..ours.len()).step_by(4).find(|&at| word(&ours, at) != word(built, at));
                    let at = at.unwrap_or(ours.len());
                    failures.push(fail(format!(
                        "{} {name}: byte {at}: expressions {:?}, built {:?}",
                        p.label,
                        word(&ours, at),
                        word(built, at)
                    )));
                }
                Err(err) => failures.push(fail(format!("{} {name}: {err}", p.label))),
            }
        }
    }
    structs
}

/// The technique's tried settings with the transform's defaults, then its defaults with each of
/// the transform's tried settings.
fn cases(t: &'static dyn Registered, transform: &'static dyn Registered) -> Vec<(Settings, Settings)> {
    let own = settings_tried(t);
    let theirs = settings_tried(transform);
    own.iter()
        .map(|v| (v.clone(), theirs[0].clone()))
        .chain(theirs.iter().skip(1).map(|h| (own[0].clone(), h.clone())))
        .collect()
}

type Settings = Vec<(&'static str, String)>;

/// One case of a transform's test: a technique configured at `values`, the transform's settings
/// at `transform_values`, and the technique's published variant they select.
struct Case<'a, S> {
    t: &'static dyn Registered,
    values: &'a Settings,
    transform_values: &'a Settings,
    configured: Box<dyn aokit_shaders::technique::Configured>,
    settings: S,
    variant: &'a aokit_contract::manifest::VariantManifest,
}

/// Every technique's published variant at each of [`cases`] with `transform`, configured
/// ([`Case`]); a technique whose settings select not exactly one variant is a failure.
fn each_case<S: Copy + 'static>(
    transform: &'static dyn Registered,
    frame: &FrameInputs,
    failures: &mut Vec<String>,
    mut check: impl FnMut(Case<S>, &mut Vec<String>),
) {
    for &t in TECHNIQUES {
        let (_, published) = variants(t, &reference_frame(frame.inner, frame.guard)).unwrap();
        for (values, transform_values) in cases(t, transform) {
            let mut configured = t.configure();
            values.iter().for_each(|(k, v)| configured.set(k, v).unwrap());
            let mut tc = transform.configure();
            transform_values.iter().for_each(|(k, v)| tc.set(k, v).unwrap());
            let settings = *tc.settings().downcast_ref::<S>().unwrap();
            let [variant] = matching(&published, &values)[..] else {
                failures.push(format!("{} {values:?}: not one variant", t.name()));
                continue;
            };
            let case = Case { t, values: &values, transform_values: &transform_values, configured, settings, variant };
            check(case, failures);
        }
    }
}

/// The manifest's half-resolution transform (`half_resolution`) applied to every technique's
/// published variant is the graph `at_resolution` builds, at the technique's tried settings and
/// the transform's, on two even frames ([`compare`]) — the variant's expressions evaluated with
/// the transform's `frame` names, `HalfParams` from its own rows. A variant reading an input the
/// transform refuses must be refused by `at_resolution` too.
#[test]
fn half_resolution_transform_is_at_resolution_for_every_variant() {
    use aokit_shaders::halfres::settings::{HALF_RESOLUTION, HalfSettings, Resolution, at_resolution};
    let committed = Manifest::committed();
    let half = half_resolution(&committed.structs).unwrap();
    assert_eq!(Some(&half), committed.half_resolution.as_ref(), "the committed half_resolution section is stale");
    let ht: &'static dyn Registered = &HALF_RESOLUTION;
    // Both example frames with an even target and guard band (the second one's are odd).
    let frames = FrameInputs::examples().map(|f| FrameInputs {
        inner: f.inner + (f.inner & 1),
        guard: f.guard + (f.guard & 1),
        ..f
    });
    // What `requires` states: an odd W or H and an odd guard band are refused.
    let gtao = || aokit_shaders::techniques::find("gtao").unwrap().configure();
    for (inner, guard) in [((97, 64), 16), ((96, 63), 16), ((96, 64), 13)] {
        let frame = FrameInputs { inner: inner.into(), guard, ..frames[0] };
        let built = at_resolution(Resolution::half(), &frame.frame_desc(), |f| gtao().graph(f));
        assert!(built.is_err(), "{inner:?} with a guard band of {guard}: {}", half.requires);
    }
    let (mut graphs, mut structs, mut refused) = (0, 0, 0);
    let mut failures = Vec::new();
    each_case::<HalfSettings>(ht, &frames[0], &mut failures, |case, failures| {
        let Case { t, values, transform_values: half_values, configured: c, settings, variant } = case;
        for frame in &frames {
            let fail = |what: String| {
                format!("{} {values:?} {half_values:?} {}x{}: {what}", t.name(), frame.inner.x, frame.inner.y)
            };
            let built = at_resolution(Resolution::Half(settings), &frame.frame_desc(), |f| c.graph(f));
            if variant.inputs.iter().any(|i| half.refused_inputs.contains(i)) {
                match built {
                    Err(_) => refused += 1,
                    Ok(_) => failures.push(fail("reads a refused input, yet at_resolution built it".into())),
                }
                continue;
            }
            let graph = match built {
                Ok(g) => g,
                Err(e) => {
                    failures.push(fail(format!("at_resolution refused: {e}")));
                    continue;
                }
            };
            let full = inputs(&t.rows(), values, frame).unwrap();
            let halved = half_inputs(&full).unwrap();
            let transform = inputs(&ht.rows(), half_values, frame).unwrap();
            // Before, the variant's passes with its inputs renamed (the first with a barrier),
            // after.
            let ours = |p: &PassManifest| ExpectedPass {
                pass: p.bound(&variant.output, &[]),
                sizes: &full,
                barrier: p.barrier_before,
                owner: ht,
                constants: &transform,
            };
            let wrapped = variant.passes.iter().enumerate().map(|(i, p)| ExpectedPass {
                pass: p.bound(&variant.output, &half.renamed_inputs),
                sizes: &halved,
                barrier: i == 0 || p.barrier_before,
                owner: t,
                constants: &halved,
            });
            let expected = Expected {
                resources: variant
                    .resources
                    .iter()
                    .map(|r| (r, &halved))
                    .chain(half.resources.iter().map(|r| (r, &full)))
                    .collect(),
                passes: half.before.iter().map(ours).chain(wrapped).chain(half.after.iter().map(ours)).collect(),
                output: half.output.clone(),
            };
            structs += compare(&graph, &expected, failures, &fail);
            graphs += 1;
        }
    });
    eprintln!("{graphs} half-resolution graphs, {structs} structs, {refused} refused");
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures[..failures.len().min(20)].join("\n"));
    assert!(graphs > 100 && structs > graphs && refused > 0, "{graphs} graphs, {structs} structs, {refused} refused");
}

/// The manifest's temporal accumulation (`temporal`) appended to every technique's published
/// variant is the graph `accumulate` builds, at the technique's tried settings and the
/// accumulation's, on two frames — one with a previous camera, one without ([`compare`]):
/// `TemporalFrame` from the accumulation's rows, `previous(Camera)` with the previous frame's
/// names.
#[test]
fn temporal_accumulation_is_accumulate_for_every_variant() {
    use aokit_shaders::temporal::settings::{TEMPORAL, TemporalSettings, accumulate};
    let committed = Manifest::committed();
    let temporal = aokit_contract::manifest::temporal(&committed.structs).unwrap();
    assert_eq!(Some(&temporal), committed.temporal.as_ref(), "the committed temporal section is stale");
    let tt: &'static dyn Registered = &TEMPORAL;
    let frames = FrameInputs::examples();
    assert!(frames[0].previous.is_none() && frames[1].previous.is_some(), "a first frame and a later one");
    let (mut graphs, mut structs) = (0, 0);
    let mut failures = Vec::new();
    each_case::<TemporalSettings>(tt, &frames[0], &mut failures, |case, failures| {
        let Case { t, values, transform_values: temporal_values, configured: c, settings, variant } = case;
        for frame in &frames {
            let fail = |what: String| {
                format!("{} {values:?} {temporal_values:?} {}x{}: {what}", t.name(), frame.inner.x, frame.inner.y)
            };
            let desc = aokit_shaders::graph::FrameDesc { temporal: Some(settings), ..frame.frame_desc() };
            // Every technique takes the accumulation: a refusal is a failure.
            let graph = match c.graph(&desc).and_then(|g| accumulate(g, &desc)) {
                Ok(g) => g,
                Err(e) => {
                    failures.push(fail(format!("accumulate refused: {e}")));
                    continue;
                }
            };
            let full = inputs(&t.rows(), values, frame).unwrap();
            let transform = inputs(&tt.rows(), temporal_values, frame).unwrap();
            let own = variant.passes.iter().map(|p| ExpectedPass {
                pass: p.clone(),
                sizes: &full,
                barrier: p.barrier_before,
                owner: t,
                constants: &full,
            });
            let after = temporal.after.iter().map(|p| ExpectedPass {
                pass: p.bound(&variant.output, &[]),
                sizes: &full,
                barrier: p.barrier_before,
                owner: tt,
                constants: &transform,
            });
            let expected = Expected {
                resources: variant.resources.iter().chain(&temporal.resources).map(|r| (r, &full)).collect(),
                passes: own.chain(after).collect(),
                output: temporal.output.clone(),
            };
            structs += compare(&graph, &expected, failures, &fail);
            graphs += 1;
        }
    });
    eprintln!("{graphs} temporal graphs, {structs} structs");
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures[..failures.len().min(20)].join("\n"));
    assert!(graphs > 100 && structs > graphs, "{graphs} graphs, {structs} structs");
}
