//! A technique's pass graphs as the manifest publishes them: for every combination of its
//! structural settings (those that change passes or resources), one graph whose sizes,
//! dispatches and data contents are expressions of the remaining settings
//! ([`aokit_shaders::technique::Formula`]), so an engine builds the exact graph for any legal
//! settings. Generation fails where a setting changes a graph in a way the published form does
//! not express.

use crate::constants::{expression, record_struct};
use crate::manifest::constants::values_tried;
use crate::manifest::{ContentsManifest, PassManifest, ResourceManifest, VariantManifest};
use aokit_shaders::graph::{Access, Elem, FrameDesc, Graph, Init, Lifetime, PassKind};
use aokit_shaders::technique::{Configured, Kind, Registered};
use std::collections::BTreeMap;

/// The widest range of a count setting that may be structural (each value its own graph).
const MAX_STRUCTURAL_COUNTS: u32 = 16;

/// `t`'s formula for `of`, its fixed settings substituted.
fn formula(t: &dyn Registered, of: &str) -> Option<String> {
    t.formulas().iter().find(|f| f.of == of).map(|f| expression(t, f.expr))
}

/// `graph` (of technique `t`) in the manifest's form, `when` empty.
pub fn publish(t: &dyn Registered, graph: &Graph) -> Result<VariantManifest, String> {
    let mut resources = Vec::new();
    for r in &graph.resources {
        let contents = match &r.init {
            Init::Data(_) => {
                // A record: bound where a module's binding holds a shared struct.
                let record = graph.passes.iter().find_map(|p| {
                    let b = p.bindings.iter().find(|b| b.resource == r.name)?;
                    record_struct(p, b.slot).map(String::from)
                });
                let part = |p: &str| formula(t, &format!("{}.{p}", r.name));
                let contents =
                    ContentsManifest { record, table: part("table"), first: part("first"), count: part("count") };
                if contents.record.is_none() && (contents.table.is_none() || contents.count.is_none()) {
                    return Err(format!(
                        "{}: data resource {} is neither a record nor has `{0}.table`/`.count` formulas",
                        t.name(),
                        r.name
                    ));
                }
                Some(contents)
            }
            _ => None,
        };
        resources.push(ResourceManifest {
            name: r.name.into(),
            elem: match r.elem {
                Elem::F32 => "f32",
                Elem::U32 => "u32",
            }
            .into(),
            size: formula(t, r.name).unwrap_or_else(|| r.size.formula()),
            lifetime: match r.lifetime {
                Lifetime::PerFrame => "per_frame",
                Lifetime::Persistent => "persistent",
            }
            .into(),
            init: match &r.init {
                Init::Fill(bits) => format!("fill {bits:#010x}"),
                Init::Data(_) => "data".into(),
                Init::Undefined => "undefined".into(),
            },
            contents,
            doc: r.doc.into(),
        });
    }
    let access = |a: Access| match a {
        Access::Read => "read",
        Access::Write => "write",
        Access::ReadWrite => "read_write",
    };
    let passes = graph
        .passes
        .iter()
        .zip(graph.barriers())
        .map(|(p, barrier_before)| {
            let (kind, stages, ray_query) = match p.kind {
                PassKind::Compute => ("compute", vec![], None),
                PassKind::RayTracing { miss, any_hit, query } => {
                    ("ray_tracing", vec![miss.entry.into(), any_hit.entry.into()], Some(query.entry.into()))
                }
                PassKind::Raster { vertex } => ("raster", vec![vertex.entry.into()], None),
            };
            let [x, y] = p.dispatch.formula();
            let axis = |a: &str, f: String| formula(t, &format!("{}.{a}", p.label)).unwrap_or(f);
            PassManifest {
                label: p.label.into(),
                entry: p.entry().into(),
                kind: kind.into(),
                stages,
                ray_query,
                bindings: p.bindings.iter().map(|b| (b.slot, b.resource.into(), access(b.access).into())).collect(),
                dispatch: [axis("x", x), axis("y", y)],
                barrier_before,
            }
        })
        .collect();
    Ok(VariantManifest {
        when: Vec::new(),
        inputs: graph.inputs().into_iter().map(Into::into).collect(),
        resources,
        passes,
        output: graph.output.into(),
    })
}

/// The variants whose `when` holds an entry that `values` (`(key, value)` of a technique's
/// settings, as `Configured::values`) match: exactly one for legal settings.
pub fn matching<'a>(variants: &'a [VariantManifest], values: &[(&str, String)]) -> Vec<&'a VariantManifest> {
    let value = |k: &str| values.iter().find(|(vk, _)| *vk == k).map(|(_, v)| v.as_str());
    variants.iter().filter(|v| v.when.iter().any(|w| w.iter().all(|(k, x)| value(k) == Some(x)))).collect()
}

/// `t` with `values` set in order (`None`: refused or not runnable).
fn configured(t: &'static dyn Registered, values: &[(String, String)]) -> Option<Box<dyn Configured>> {
    let mut c = t.configure();
    for (k, v) in values {
        c.set(k, v).ok()?;
    }
    c.validate().ok()?;
    Some(c)
}

/// Every value of a structural setting.
fn all_values(t: &dyn Registered, key: &str, kind: Kind) -> Result<Vec<String>, String> {
    match kind {
        Kind::Choice(names) => Ok(names.iter().map(|n| n.to_string()).collect()),
        Kind::Count { min, max } if max - min < MAX_STRUCTURAL_COUNTS => {
            Ok((min..=max).map(|v| v.to_string()).collect())
        }
        _ => Err(format!(
            "{}: `{key}` changes the graph's structure but takes too many values to publish a graph per value: \
             express what it changes as a Formula (sizes, dispatches, contents)",
            t.name()
        )),
    }
}

/// The structural settings of `t` and its graph for every combination of them, for `frame`.
/// Fails where a non-structural setting (at any tried value, in any combination) changes the
/// published graph: then its effect is not captured by the formulas.
pub fn variants(t: &'static dyn Registered, frame: &FrameDesc) -> Result<(Vec<String>, Vec<VariantManifest>), String> {
    let graph_of = |values: &[(String, String)]| -> Option<Result<VariantManifest, String>> {
        let c = configured(t, values)?;
        let graph = c.graph(frame).ok()?;
        Some(publish(t, &graph))
    };
    let rows = t.rows();
    let defaults: Vec<(String, String)> = t.configure().values().into_iter().map(|(k, v)| (k.into(), v)).collect();
    let base = graph_of(&[]).ok_or_else(|| format!("{}: no graph at the defaults", t.name()))??;
    let mut structural = Vec::new();
    for r in &rows {
        let default = &defaults.iter().find(|(k, _)| k == r.key).expect("a value per row").1;
        for value in values_tried(r.kind, default) {
            if let Some(g) = graph_of(&[(r.key.into(), value)])
                && g? != base
                && !structural.contains(&r.key)
            {
                structural.push(r.key);
            }
        }
    }
    // Every combination of the structural settings' values (the others at their defaults).
    let mut combos: Vec<Vec<(String, String)>> = vec![Vec::new()];
    for r in rows.iter().filter(|r| structural.contains(&r.key)) {
        let values = all_values(t, r.key, r.kind)?;
        combos = combos
            .into_iter()
            .flat_map(|c| values.iter().map(move |v| [c.clone(), vec![(r.key.to_string(), v.clone())]].concat()))
            .collect();
    }
    let mut out: Vec<VariantManifest> = Vec::new();
    for combo in combos {
        let Some(graph) = graph_of(&combo) else { continue };
        let graph = graph?;
        // Within the combination every other setting leaves the published graph alone.
        for r in rows.iter().filter(|r| !structural.contains(&r.key)) {
            let default = &defaults.iter().find(|(k, _)| k == r.key).expect("a value per row").1;
            for value in values_tried(r.kind, default) {
                let values = [combo.clone(), vec![(r.key.to_string(), value.clone())]].concat();
                if let Some(g) = graph_of(&values)
                    && g? != graph
                {
                    return Err(format!(
                        "{}: {}={value} changes the graph at {combo:?} in a way its formulas do not express",
                        t.name(),
                        r.key
                    ));
                }
            }
        }
        let when: BTreeMap<String, String> = combo.into_iter().collect();
        match out.iter_mut().find(|v| VariantManifest { when: Vec::new(), ..(*v).clone() } == graph) {
            Some(v) => v.when.push(when),
            None => out.push(VariantManifest { when: vec![when], ..graph }),
        }
    }
    Ok((structural.into_iter().map(Into::into).collect(), out))
}

/// The words of a `data` resource of technique `t` from its `contents`: a record's struct from
/// the constants' expressions (`pass` 0), or a table's elements `first .. first + count`.
pub fn data_words(
    t: &dyn Registered,
    contents: &ContentsManifest,
    inputs: &crate::expr::Inputs,
    tables: &[crate::manifest::TableManifest],
) -> Result<Vec<u32>, String> {
    use crate::expr::{Value, eval};
    if let Some(record) = &contents.record {
        let mut inputs = inputs.clone();
        inputs.names.insert("pass".into(), Value::Int(0));
        let bytes = crate::constants::evaluate_struct(t, record, &inputs)?;
        return Ok(bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect());
    }
    let int = |text: Option<&String>| -> Result<usize, String> {
        match text.map(|t| eval(t, inputs)).transpose()? {
            None => Ok(0),
            Some(Value::Int(i)) if i >= 0 => Ok(i as usize),
            Some(v) => Err(format!("{v:?} is not a count")),
        }
    };
    let Some(Value::Text(name)) = contents.table.as_ref().map(|t| eval(t, inputs)).transpose()? else {
        return Err("contents without a record or a table".into());
    };
    let table = tables.iter().find(|x| x.name == name).ok_or_else(|| format!("no table {name}"))?;
    let per = match table.elem.as_str() {
        "Vec2" => 2,
        "Vec3" => 3,
        "Vec4" => 4,
        _ => 1,
    };
    let (first, count) = (int(contents.first.as_ref())?, int(contents.count.as_ref())?);
    let values = table.values.get(first * per..(first + count) * per).ok_or_else(|| format!("outside table {name}"))?;
    Ok(values.iter().map(|v| v.to_bits()).collect())
}
