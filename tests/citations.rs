//! Every `§` citation resolves inside the repository.
//!
//! The code cites the algorithm documents of `docs/algorithms/` as `spec NAME §N.M`, `NAME §N.M` or
//! `NAME spec §N.M` (NAME = `svao-raysd`, `gtao-raymarch-hybrid`, `vbao`, `half-resolution`), also with ranges
//! (`§4–§5`, `§4.1–4.3`) and lists (`§2, §5`, `§2.5 step 1, §7.6`); see `docs/algorithms/README.md`.
//! This test walks the repository's text files and checks that
//! * every cited section has a heading `§N.M …` in `docs/algorithms/NAME.md` (inside those documents
//!   a bare `§N.M` means a section of the same document);
//! * no file points outside the repository (to the team's folder beside it: `OUTSIDE` below);
//! * every `§` in the sources (see [`STRICT_DIRS`]) belongs to a citation that names its document:
//!   one of the specs or an external document of [`EXTERNAL`].
//!
//! Only std: the files come from `git ls-files` (tracked plus untracked, not ignored), or from a
//! directory walk where git is unavailable.

/// Paths that lead out of the repository, spelled in pieces so this file does not match itself.
const OUTSIDE: [&str; 2] = [concat!("..", "/", "shared"), concat!("shared", "/", "spec")];
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The algorithm documents, `docs/algorithms/<name>.md`.
const SPECS: [&str; 4] = ["svao-raysd", "gtao-raymarch-hybrid", "vbao", "half-resolution"];

/// External documents whose sections the code cites with `§`, as the citation names them: the Khronos
/// specifications (Vulkan, OpenGL, SPIR-V), the W3C WGSL and Khronos glTF 2.0 specifications, the two
/// papers of svao-raysd cited by their own section numbers, and Numerical Recipes (tests). Their
/// section numbers are not checked. Between the name and the `§` only `'s` and ` (` may stand
/// (`Vulkan spec's (§"Descriptor Types"`); a section is a number or a quoted title.
const EXTERNAL: [&str; 8] = [
    "Vulkan spec",
    "OpenGL 4.6 core spec",
    "SPIR-V spec",
    "WGSL",
    "glTF 2.0",
    "SVAO paper",
    "Ray-SD paper",
    "Numerical Recipes",
];

/// Where every `§` must belong to a citation that names its document. Not the generated files
/// (`assets/`: regenerated from the Rust sources) and not the prose docs outside `docs/algorithms/`.
const STRICT_DIRS: [&str; 10] = [
    "shader-crate/src/",
    "cpu-sim/src/",
    "host/src/",
    "src/",
    "tests/",
    "examples/",
    "bench/",
    "benches/",
    "xtask/src/",
    "xtask/contract/src/",
];

/// Directories walked when git is unavailable (plus the top-level files below).
const FALLBACK_DIRS: [&str; 9] = [
    "src",
    "shader-crate/src",
    "cpu-sim/src",
    "host/src",
    "xtask/src",
    "xtask/contract/src",
    "tests",
    "examples",
    "docs",
];
const FALLBACK_FILES: [&str; 2] = ["README.md", "CONTRIBUTING.md"];

/// This file: it spells out the forbidden strings and example citations.
const SELF: &str = "tests/citations.rs";

/// Fewer checked citations than this means the scanner lost them, not that the tree is clean.
const MIN_CITATIONS: usize = 300;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Repository-relative paths of the text files to scan.
fn files(root: &Path) -> Vec<String> {
    let git = Command::new("git")
        .args(["ls-files", "-z", "--cached", "--others", "--exclude-standard"])
        .current_dir(root)
        .output();
    let mut paths: Vec<String> = match git {
        Ok(out) if out.status.success() => {
            String::from_utf8_lossy(&out.stdout).split('\0').filter(|p| !p.is_empty()).map(str::to_owned).collect()
        }
        _ => {
            let mut paths = Vec::new();
            for dir in FALLBACK_DIRS {
                walk(root, Path::new(dir), &mut paths);
            }
            paths.extend(FALLBACK_FILES.iter().map(|f| f.to_string()));
            paths
        }
    };
    let skipped = |p: &str| p.starts_with("fuzz/corpus/") || (p.starts_with("assets/spirv/") && p.ends_with(".spv"));
    paths.retain(|p| !skipped(p));
    paths.sort();
    paths.dedup();
    paths
}

fn walk(root: &Path, rel: &Path, out: &mut Vec<String>) {
    let Ok(entries) = std::fs::read_dir(root.join(rel)) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name();
        if name == "target" {
            continue;
        }
        let rel = rel.join(&name);
        match entry.file_type() {
            Ok(t) if t.is_dir() => walk(root, &rel, out),
            Ok(t) if t.is_file() => out.push(rel.to_string_lossy().replace('\\', "/")),
            _ => {}
        }
    }
}

/// One cited section: the document (a spec name) and the section number, e.g. `("vbao", "6.2")`.
struct Cite {
    spec: &'static str,
    section: String,
    at: usize,
}

/// The result of scanning one file.
#[derive(Default)]
struct Scan {
    /// Sections of the specs cited (range ends included).
    cites: Vec<Cite>,
    /// Char positions of every `§` that belongs to a citation naming its document.
    named: BTreeSet<usize>,
}

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '-'
}

fn starts_with_at(text: &[char], at: usize, s: &str) -> bool {
    (at..).zip(s.chars()).all(|(i, c)| text.get(i) == Some(&c))
}

/// A section number `N(.M)*` at `at`: its text and the position after it.
fn number(text: &[char], at: usize) -> Option<(String, usize)> {
    let mut i = at;
    let mut s = String::new();
    loop {
        let start = i;
        while text.get(i).is_some_and(|c| c.is_ascii_digit()) {
            s.push(text[i]);
            i += 1;
        }
        if i == start {
            return None;
        }
        // A '.' continues the number only before a digit (not in `§15.k` or at a sentence's end).
        if text.get(i) == Some(&'.') && text.get(i + 1).is_some_and(|c| c.is_ascii_digit()) {
            s.push('.');
            i += 1;
        } else {
            return Some((s, i));
        }
    }
}

/// A quoted section title `"…"` at `at` (external documents only): the position after it.
fn quoted(text: &[char], at: usize) -> Option<usize> {
    if text.get(at) != Some(&'"') {
        return None;
    }
    (at + 1..text.len().min(at + 200)).find(|&i| text[i] == '"').map(|i| i + 1)
}

fn skip_spaces(text: &[char], mut i: usize) -> usize {
    while text.get(i).is_some_and(|&c| c == ' ' || c == '\u{a0}') {
        i += 1;
    }
    i
}

/// From `at` (just after a section), the position of the next `§` of the same list, if any:
/// an optional qualifier (`step 7`, `"Bug"`, `` `nz` ``, `physical layout`: up to 60 chars without
/// `§ ( ) [ ] ; : .` or a line break), then a separator (`,`, `and`, `or`, `/`, possibly across
/// a line break and a comment marker), then `§`.
fn next_in_list(text: &[char], at: usize) -> Option<usize> {
    let mut i = at;
    let mut len = 0;
    while let Some(&c) = text.get(i) {
        if matches!(c, '§' | '(' | ')' | '[' | ']' | ';' | ':' | '.' | '\n') || len > 60 {
            break;
        }
        if c == ',' || c == '/' {
            break;
        }
        if c == ' ' && (starts_with_at(text, i, " and ") || starts_with_at(text, i, " or ")) {
            break;
        }
        i += 1;
        len += 1;
    }
    i = skip_spaces(text, i);
    let mut separated = false;
    if matches!(text.get(i), Some(',') | Some('/')) {
        i += 1;
        separated = true;
    }
    i = skip_spaces(text, i);
    for word in ["and ", "or "] {
        if starts_with_at(text, i, word) {
            i += word.len();
            separated = true;
            break;
        }
    }
    if !separated {
        return None;
    }
    let i = skip_break(text, i);
    (text.get(i) == Some(&'§')).then_some(i)
}

/// Skip spaces and at most one line break followed by a comment marker (`//!`, `///`, `//`, `*`,
/// `#`): a citation wrapped onto the next comment line.
fn skip_break(text: &[char], at: usize) -> usize {
    let i = skip_spaces(text, at);
    if text.get(i) != Some(&'\n') {
        return i;
    }
    let mut j = i + 1;
    while text.get(j).is_some_and(|&c| c == ' ' || c == '\t') {
        j += 1;
    }
    for marker in ["//!", "///", "//", "*", "#"] {
        if starts_with_at(text, j, marker) {
            j += marker.chars().count();
            break;
        }
    }
    let j = skip_spaces(text, j);
    if text.get(j) == Some(&'§') { j } else { i }
}

/// Parse the list of sections that starts with the `§` at `at`. `spec` is the cited document (None
/// for an external one, whose sections may also be quoted titles).
fn parse_list(text: &[char], mut at: usize, spec: Option<&'static str>, scan: &mut Scan) {
    loop {
        let after = match number(text, at + 1) {
            Some((section, mut end)) => {
                let mut sections = vec![section];
                // A range: `§4–§5`, `§4.1–4.3`, `§2.6.1-§2.6.2`.
                if matches!(text.get(end), Some('–') | Some('-')) {
                    let dash = end;
                    let mut k = dash + 1;
                    let second = text.get(k) == Some(&'§');
                    if second {
                        k += 1;
                    }
                    if let Some((last, e)) = number(text, k) {
                        if second {
                            scan.named.insert(dash + 1);
                        }
                        sections.push(last);
                        end = e;
                    }
                }
                if let Some(spec) = spec {
                    scan.cites.extend(sections.into_iter().map(|section| Cite { spec, section, at }));
                }
                end
            }
            None => match (spec, quoted(text, at + 1)) {
                (None, Some(end)) => end,
                _ => return, // not a section: the `§` stays unnamed
            },
        };
        scan.named.insert(at);
        match next_in_list(text, after) {
            Some(next) => at = next,
            None => return,
        }
    }
}

/// All citations of one file. `own`: the spec whose document this file is, for its bare `§`.
fn scan(text: &[char], own: Option<&'static str>) -> Scan {
    let mut scan = Scan::default();
    let mut i = 0;
    while i < text.len() {
        let boundary = i == 0 || !is_word(text[i - 1]);
        if boundary {
            for spec in SPECS {
                if !starts_with_at(text, i, spec) {
                    continue;
                }
                let mut k = i + spec.chars().count();
                if text.get(k).is_some_and(|&c| is_word(c)) {
                    continue;
                }
                if starts_with_at(text, k, ".md") {
                    k += 3;
                }
                if starts_with_at(text, k, " spec") && !text.get(k + 5).is_some_and(|&c| is_word(c)) {
                    k += 5;
                }
                k = skip_break(text, k);
                if text.get(k) == Some(&'§') {
                    parse_list(text, k, Some(spec), &mut scan);
                }
            }
            for ext in EXTERNAL {
                if !starts_with_at(text, i, ext) {
                    continue;
                }
                let mut k = i + ext.chars().count();
                if starts_with_at(text, k, "'s") {
                    k += 2;
                }
                k = skip_spaces(text, k);
                if text.get(k) == Some(&'(') {
                    k += 1;
                }
                if text.get(k) == Some(&'§') {
                    parse_list(text, k, None, &mut scan);
                }
            }
        }
        i += 1;
    }
    if let Some(own) = own {
        // Inside docs/algorithms/<own>.md a bare `§N` cites the same document; headings define.
        let mut line_start = 0;
        for (i, &c) in text.iter().enumerate() {
            if c == '\n' {
                line_start = i + 1;
            } else if c == '§' && !scan.named.contains(&i) && text[line_start] != '#' {
                parse_list(text, i, Some(own), &mut scan);
            }
        }
    }
    scan
}

/// Section numbers of the headings of a document (`## §4 …`, `### §4.1 …`).
fn headings(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in text.lines().filter(|l| l.starts_with('#')) {
        let chars: Vec<char> = line.chars().collect();
        for (i, &c) in chars.iter().enumerate() {
            if c == '§'
                && let Some((n, _)) = number(&chars, i + 1)
            {
                out.insert(n);
            }
        }
    }
    out
}

/// `line:column` (1-based, columns in chars) of position `at`.
fn position(text: &[char], at: usize) -> String {
    let line = 1 + text[..at].iter().filter(|&&c| c == '\n').count();
    let column = 1 + at - text[..at].iter().rposition(|&c| c == '\n').map_or(0, |p| p + 1);
    format!("{line}:{column}")
}

fn snippet(text: &[char], at: usize) -> String {
    let start = text[..at].iter().rposition(|&c| c == '\n').map_or(0, |p| p + 1);
    let end = text[at..].iter().position(|&c| c == '\n').map_or(text.len(), |p| at + p);
    text[start..end].iter().collect::<String>().trim().to_owned()
}

/// Check a set of files given as `(path, contents)`; returns the number of checked citations and
/// the offences, one `path:line: …` each.
fn check(files: &[(String, String)]) -> (usize, Vec<String>) {
    let mut sections: BTreeMap<&str, BTreeSet<String>> = BTreeMap::new();
    for spec in SPECS {
        let doc = format!("docs/algorithms/{spec}.md");
        let text = files.iter().find(|(p, _)| *p == doc).map(|(_, t)| t.as_str()).unwrap_or("");
        sections.insert(spec, headings(text));
    }
    let mut offences = Vec::new();
    for spec in SPECS {
        if sections[spec].is_empty() {
            offences.push(format!("docs/algorithms/{spec}.md: missing, or no `§N` headings"));
        }
    }
    let mut checked = 0;
    for (path, text) in files {
        if path == SELF {
            continue;
        }
        for needle in OUTSIDE {
            for (line, l) in text.lines().enumerate().filter(|(_, l)| l.contains(needle)) {
                offences.push(format!("{path}:{}: points outside the repository ({needle}): {}", line + 1, l.trim()));
            }
        }
        if !text.contains('§') {
            continue;
        }
        let chars: Vec<char> = text.chars().collect();
        let own = SPECS.into_iter().find(|s| *path == format!("docs/algorithms/{s}.md"));
        let found = scan(&chars, own);
        for cite in &found.cites {
            checked += 1;
            if !sections[cite.spec].contains(&cite.section) {
                offences.push(format!(
                    "{path}:{}: {} §{} has no heading in docs/algorithms/{}.md: {}",
                    position(&chars, cite.at),
                    cite.spec,
                    cite.section,
                    cite.spec,
                    snippet(&chars, cite.at)
                ));
            }
        }
        if STRICT_DIRS.iter().any(|d| path.starts_with(d)) {
            for (i, _) in chars.iter().enumerate().filter(|(i, c)| **c == '§' && !found.named.contains(i)) {
                offences.push(format!(
                    "{path}:{}: `§` without a document name (cite `spec NAME §N`): {}",
                    position(&chars, i),
                    snippet(&chars, i)
                ));
            }
        }
    }
    (checked, offences)
}

fn repository() -> Vec<(String, String)> {
    let root = root();
    files(&root)
        .into_iter()
        .filter_map(|p| std::fs::read(root.join(&p)).ok().and_then(|b| String::from_utf8(b).ok()).map(|t| (p, t)))
        .collect()
}

#[test]
fn every_citation_resolves_inside_the_repository() {
    let files = repository();
    let (checked, offences) = check(&files);
    assert!(offences.is_empty(), "{} citation problem(s):\n{}", offences.len(), offences.join("\n"));
    assert!(checked > MIN_CITATIONS, "only {checked} citations checked (expected > {MIN_CITATIONS}): scanner broken?");
    println!("{checked} citations of {} files resolve", files.len());
}

#[test]
fn the_checker_catches_what_it_must() {
    let doc = "# x\n## §1 A\n### §1.2 B\n## §4 C\n### §4.1 D\n### §4.3 E\n".to_owned();
    let mut files: Vec<(String, String)> =
        SPECS.iter().map(|s| (format!("docs/algorithms/{s}.md"), doc.clone())).collect();
    let src = "/// (spec vbao §1.2, §4.1–4.3) and (svao-raysd §4–§4.3; Vulkan spec's (§\"Descriptor Types\")\n\
               /// gtao-raymarch-hybrid §1 step 2, §4.1,\n/// §4.3 and (OpenGL 4.6 core spec §13.8.1), wrapped (spec svao-raysd\n/// §4.1).\n";
    files.push(("shader-crate/src/ok.rs".into(), src.into()));
    let (checked, offences) = check(&files);
    assert!(offences.is_empty(), "{offences:?}");
    assert_eq!(checked, 9);

    let bad = format!("/// (spec §4.1) and (vbao §99), svao-raysd §4.2; see {}.\n", OUTSIDE[0]);
    files.push(("src/bad.rs".into(), bad));
    let (_, offences) = check(&files);
    assert_eq!(offences.len(), 4, "{offences:#?}");
    assert!(offences.iter().all(|o| o.starts_with("src/bad.rs:1:")), "{offences:#?}");
}
