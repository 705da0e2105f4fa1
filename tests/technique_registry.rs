//! The registry and the settings rows: every declared key has a row, every row round-trips and
//! refuses out-of-range values, every setting a technique accepts changes its pass graph (so it
//! takes effect on both back-ends, which run the same graph), and the command line's flags come
//! from the rows (unique, applied only to the techniques that read them, unused ones refused).

mod common;

use aokit::cli::TechniqueArgs;
use aokit::technique::{Describe, Row, TECHNIQUES, Technique};
use aokit_shaders::graph::FrameDesc;
use aokit_shaders::technique::Kind;
use clap::{Args, FromArgMatches};

fn frame() -> FrameDesc {
    common::builtin_frame("cornell", 96, 64, 8).1.desc()
}

/// A legal value of `row` other than `current`.
fn another_value(row: &Row, current: &str) -> String {
    match row.kind {
        Kind::Choice(names) => names.iter().find(|n| **n != current).expect("two names").to_string(),
        Kind::Count { min, max } => {
            let v: u32 = current.parse().unwrap();
            // Powers of two stay powers of two (the SD layers).
            if v > min { min.max(v / 2) } else { (v * 2).max(min + 1).min(max) }.to_string()
        }
        Kind::Number { min, max } => {
            let v: f32 = current.parse().unwrap();
            let other = if v > min {
                min
            } else if max == f32::MAX {
                v * 2.0 + 1.0
            } else {
                max
            };
            other.to_string()
        }
    }
}

/// The graph and second layer as one comparable text.
fn effect(t: &Technique, frame: &FrameDesc) -> String {
    format!("{:?} {:?}", t.graph(frame).unwrap(), t.second_layer())
}

#[test]
fn every_declared_key_has_a_row_and_names_are_unique() {
    let mut names: Vec<_> = TECHNIQUES.iter().map(|t| t.name()).collect();
    // The techniques aokit ships are all registered (a new one needs no edit here).
    let shipped = [
        "vao",
        "hbao",
        "raysd",
        "hbao-sd",
        "sdsvao",
        "raysvao",
        "gtao",
        "vbao",
        "vbao-sd",
        "raymarch",
        "hybrid",
        "groundtruth",
    ];
    for name in shipped {
        assert!(names.contains(&name), "{name} is not registered: {names:?}");
    }
    names.sort();
    names.dedup();
    assert_eq!(names.len(), TECHNIQUES.len(), "a name is registered twice");
    for t in TECHNIQUES {
        let rows = t.rows();
        let keys: Vec<_> = rows.iter().map(|r| r.key).collect();
        assert_eq!(keys, t.keys(), "{}: a declared key has no settings row", t.name());
        for row in &rows {
            assert!(!row.help.is_empty(), "{}: {} has no help", t.name(), row.key);
            assert!(row.flag.is_some() || row.switch.is_some(), "{}: {} has no flag", t.name(), row.key);
        }
        // The defaults are legal.
        Technique::named(t.name()).unwrap().set("x", "1").unwrap_err();
        Technique::parse(t.name()).unwrap();
    }
}

#[test]
fn every_setting_round_trips_refuses_bad_values_and_changes_the_graph() {
    let frame = frame();
    let mut settings = 0;
    for t in TECHNIQUES {
        for row in t.rows() {
            let base = Technique::named(t.name()).unwrap();
            // A setting of the dual-depth layer only matters on dual depth.
            let mut context = base.clone();
            if row.key == "peel-separation" {
                context.set("primary", "dual").unwrap();
            }
            let current = context.describe()[row.key.replace('-', "_")].to_string().trim_matches('"').to_string();
            let mut changed = context.clone();
            let value = another_value(&row, &current);
            changed.set(row.key, &value).unwrap_or_else(|e| panic!("{} {}={value}: {e}", t.name(), row.key));
            let read_back = changed.describe()[row.key.replace('-', "_")].to_string();
            assert_eq!(read_back.trim_matches('"'), value, "{} {}", t.name(), row.key);
            assert_ne!(
                effect(&changed, &frame),
                effect(&context, &frame),
                "{}: {}={value} is accepted but changes nothing",
                t.name(),
                row.key
            );
            assert!(changed.label().contains(&format!("_{}-{value}", row.key)), "{}", changed.label());
            // Setting the current value back restores the graph.
            changed.set(row.key, &current).unwrap();
            assert_eq!(effect(&changed, &frame), effect(&context, &frame), "{} {}", t.name(), row.key);
            // Out of range, not a number, not a name: refused with a message naming the flag.
            let bad: Vec<String> = match row.kind {
                Kind::Choice(_) => vec!["no-such-name".into()],
                Kind::Count { min, max } => {
                    let mut v = vec!["x".into(), "-1".into(), "1.5".into()];
                    if max < u32::MAX {
                        v.push((max + 1).to_string());
                    }
                    if min > 0 {
                        v.push((min - 1).to_string());
                    }
                    v
                }
                Kind::Number { min, max } => {
                    let mut v = vec!["x".into(), "NaN".into(), "inf".into(), (min - 1.0).to_string()];
                    if max < f32::MAX {
                        v.push((max + 0.5).to_string());
                    }
                    v
                }
            };
            for b in bad {
                let e = base.clone().set(row.key, &b).expect_err(&format!("{} {}={b} accepted", t.name(), row.key));
                // The library names the setting by its key (no command-line flag).
                assert!(e.starts_with(&format!("{} ", row.key)) && !e.contains('\n'), "{e}");
            }
            settings += 1;
        }
    }
    assert!(settings >= 40, "{settings} settings checked");
}

/// The comparison above can fail: a setting whose value never reaches the graph is caught.
#[test]
fn a_setting_that_does_not_reach_the_graph_is_caught() {
    let frame = frame();
    let base = Technique::named("raysd").unwrap();
    let mut changed = base.clone();
    changed.set("sd-layers", "8").unwrap();
    assert_ne!(effect(&changed, &frame), effect(&base, &frame));
    // And a value that does not reach it shows as no change: the peel separation of single
    // depth (it only matters with primary=dual, which the test above switches on).
    let single = Technique::named("vao").unwrap();
    let mut separated = single.clone();
    separated.set("peel-separation", "0.5").unwrap();
    assert_eq!(effect(&separated, &frame), effect(&single, &frame));
    // `kernel` is fixed for hbao-sd: the technique refuses it instead of ignoring it.
    let e = Technique::named("hbao-sd").unwrap().set("kernel", "vao").unwrap_err();
    assert!(e.contains("hbao-sd has no option 'kernel'"), "{e}");
}

fn parse_cli(args: &[&str]) -> Result<TechniqueArgs, clap::Error> {
    let cmd = TechniqueArgs::augment_args(clap::Command::new("aokit").no_binary_name(true));
    cmd.try_get_matches_from(args).and_then(|m| TechniqueArgs::from_arg_matches(&m))
}

#[test]
fn flags_come_from_the_rows_and_apply_where_they_are_read() {
    // clap's own consistency checks (unique names, valid defaults) over the generated flags.
    TechniqueArgs::augment_args(clap::Command::new("aokit")).debug_assert();
    // Every row's flag exists and its default is the settings type's.
    let cmd = TechniqueArgs::augment_args(clap::Command::new("aokit"));
    for t in TECHNIQUES {
        for row in t.rows() {
            if let Some(flag) = row.flag {
                let arg = cmd.get_arguments().find(|a| a.get_long() == Some(flag)).expect("a flag per row");
                assert_eq!(arg.get_default_values(), [row.default.as_str()], "--{flag}");
            }
        }
    }

    let args = parse_cli(&["--sd-layers", "8", "--no-interval", "--preset", "ultra"]).unwrap();
    let ts = args.techniques(&["raysd", "gtao", "raysd:sd-layers=2"]).unwrap();
    assert_eq!(ts[0].describe()["sd_layers"], 8);
    assert_eq!(ts[0].describe()["interval"], "off");
    assert_eq!(ts[1].describe()["preset"], "ultra");
    // An override after the name wins over the flag.
    assert_eq!(ts[2].describe()["sd_layers"], 2);
    // Unset flags keep each technique's own defaults (hbao-sd's kernel is HBAO+).
    let plain = parse_cli(&[]).unwrap().techniques(&["hbao-sd", "vao"]).unwrap();
    assert!(plain[0].settings::<aokit::technique::SdOptions>().unwrap().hbao);
    assert!(!plain[1].settings::<aokit::technique::SdOptions>().unwrap().hbao);

    // A flag none of the command's techniques reads is refused, not ignored.
    let e = parse_cli(&["--sd-layers", "8"]).unwrap().techniques(&["gtao", "vao"]).unwrap_err();
    assert!(e.contains("--sd-layers not read by gtao, vao"), "{e}");
    // Bad values name the flag, on one line.
    let e = parse_cli(&["--sd-layers", "9"]).unwrap().technique("raysd").unwrap_err();
    assert!(e.contains("--sd-layers 9: expected 1–8") && !e.contains('\n'), "{e}");
    let e = parse_cli(&["--sd-layers", "3"]).unwrap().technique("raysd").unwrap_err();
    assert!(e.contains("sd-layers 3 is not 1, 2, 4 or 8"), "{e}");
    assert!(parse_cli(&["--preset", "extreme"]).is_err());
    let e = parse_cli(&[]).unwrap().technique("raysd:bogus=1").unwrap_err();
    assert!(e.contains("raysd has no option 'bogus'"), "{e}");
    let e = parse_cli(&[]).unwrap().technique("nope").unwrap_err();
    assert!(e.contains("unknown technique 'nope'") && e.contains("groundtruth"), "{e}");
    // Switches: --no-jitter and --jitter set the same setting.
    let t = parse_cli(&["--no-jitter"]).unwrap().technique("raysd").unwrap();
    assert_eq!(t.describe()["jitter"], "none");
    let t = parse_cli(&["--uniform", "--spp", "16"]).unwrap().technique("groundtruth").unwrap();
    assert_eq!((t.describe()["sampling"].as_str(), t.describe()["spp"].as_u64()), (Some("uniform"), Some(16)));
    // XeGTAO: a preset, then slices/steps on top of it make a custom quality.
    let t = parse_cli(&["--gtao-slices", "4", "--preset", "low"]).unwrap().technique("gtao").unwrap();
    let d = t.describe();
    assert_eq!((d["preset"].as_str(), d["slices"].as_u64(), d["steps"].as_u64()), (Some("custom"), Some(4), Some(2)));
    let t = parse_cli(&["--gtao-slices", "9", "--gtao-steps", "3"]).unwrap().technique("gtao").unwrap();
    assert_eq!(t.describe()["preset"], "ultra");
    // The hybrid's variant is applied before its world weight, whatever the order typed; a
    // weight the variant cannot blend (world rays only, weight 0.25) is refused.
    let t = parse_cli(&["--world-weight", "0.25", "--hybrid-variant", "mixed"]).unwrap().technique("hybrid").unwrap();
    assert_eq!((t.describe()["variant"].as_str(), t.describe()["world_weight"].as_f64()), (Some("mixed"), Some(0.25)));
    let e = parse_cli(&["--world-weight", "0.25", "--hybrid-variant", "world"]).unwrap().technique("hybrid");
    assert!(e.unwrap_err().contains("the world variant blends nothing else"));
    // Flags and overrides together in row order, an override winning over the flag of its
    // setting: the preset first, then slices on top of it.
    let args = parse_cli(&["--gtao-slices", "8"]).unwrap();
    let d = args.technique("gtao:preset=low").unwrap().describe();
    assert_eq!((d["preset"].as_str(), d["slices"].as_u64(), d["steps"].as_u64()), (Some("custom"), Some(8), Some(2)));
    let d = parse_cli(&[]).unwrap().technique("gtao:slices=4:preset=low").unwrap().describe();
    assert_eq!((d["slices"].as_u64(), d["steps"].as_u64()), (Some(4), Some(2)));
    // A switch and the value flag of one setting conflict.
    assert!(parse_cli(&["--no-jitter", "--jitter", "paper"]).is_err());
}
