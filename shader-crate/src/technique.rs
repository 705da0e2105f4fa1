//! A technique as data (host side): its settings described row by row — key, command-line flag,
//! range or choices, help, and where the value lives in the settings struct — and its
//! declaration (name, default settings, pass graph). The registry ([`crate::techniques`]) lists
//! the declarations; the CLI's flags and help, the `technique:key=value` overrides, validation,
//! report labels and the options in the JSON reports are all read from these rows, so nothing
//! about a setting is written twice.

use crate::graph::{FrameDesc, Graph};
pub use crate::halfres::settings::Resolution;

/// The key (`technique:resolution=half`) and command-line flag (`--resolution half`) of the
/// resolution every technique takes ([`Technique::with_resolution`]).
pub const RESOLUTION_KEY: &str = "resolution";
use core::any::Any;
use core::fmt::Debug;

/// What values a setting takes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Kind {
    /// A whole number in `min..=max`.
    Count { min: u32, max: u32 },
    /// A real number in `min..=max`.
    Number { min: f32, max: f32 },
    /// One of these names.
    Choice(&'static [&'static str]),
}

impl Kind {
    /// The accepted values in words, e.g. `1–8`, `≥ 0`, `full|half|quarter`.
    pub fn accepted(&self) -> String {
        fn range<T: PartialEq + core::fmt::Display>(min: T, max: T, unbounded: T) -> String {
            if max == unbounded { format!("≥ {min}") } else { format!("{min}–{max}") }
        }
        match *self {
            Kind::Count { min, max } => range(min, max, u32::MAX),
            Kind::Number { min, max } => range(min, max, f32::MAX),
            Kind::Choice(names) => names.join("|"),
        }
    }
}

/// Where a setting's value lives in the settings struct `S`.
pub enum Field<S> {
    Count(fn(&mut S) -> &mut u32),
    Number(fn(&mut S) -> &mut f32),
    /// A two-way choice stored as a bool (`names[1]` = true).
    Switch(fn(&mut S) -> &mut bool),
    /// A choice stored any other way: the index of the current name, and how to store one.
    Choice {
        get: fn(&S) -> usize,
        set: fn(&mut S, usize),
    },
}

/// One setting of a settings struct `S`.
pub struct Setting<S> {
    /// The key in `technique:key=value` overrides and in the reports' options.
    pub key: &'static str,
    /// The command-line flag taking a value (`--flag <value>`), if any.
    pub flag: Option<&'static str>,
    /// A value-less command-line flag and the value it sets (e.g. `--no-interval` → `off`).
    pub switch: Option<(&'static str, &'static str)>,
    pub help: &'static str,
    pub kind: Kind,
    pub field: Field<S>,
}

impl<S> Setting<S> {
    /// A whole number in `min..=max` (use `u32::MAX` for no upper bound); flag `--key`.
    pub const fn count(key: &'static str, min: u32, max: u32, field: fn(&mut S) -> &mut u32) -> Self {
        Self::new(key, Kind::Count { min, max }, Field::Count(field))
    }

    /// A real number in `min..=max` (use `f32::MAX` for no upper bound); flag `--key`.
    pub const fn number(key: &'static str, min: f32, max: f32, field: fn(&mut S) -> &mut f32) -> Self {
        Self::new(key, Kind::Number { min, max }, Field::Number(field))
    }

    /// A bool written as one of two names (`names[1]` = true); flag `--key`.
    pub const fn switch(key: &'static str, names: &'static [&'static str; 2], field: fn(&mut S) -> &mut bool) -> Self {
        Self::new(key, Kind::Choice(names), Field::Switch(field))
    }

    /// One of `names`, stored through `get`/`set` (index into `names`); flag `--key`.
    pub const fn choice(
        key: &'static str,
        names: &'static [&'static str],
        get: fn(&S) -> usize,
        set: fn(&mut S, usize),
    ) -> Self {
        Self::new(key, Kind::Choice(names), Field::Choice { get, set })
    }

    const fn new(key: &'static str, kind: Kind, field: Field<S>) -> Self {
        Setting { key, flag: Some(key), switch: None, help: "", kind, field }
    }

    /// The command-line flag taking a value, when it is not the key.
    pub const fn flag(self, flag: &'static str) -> Self {
        Setting { flag: Some(flag), ..self }
    }

    /// Only a value-less flag on the command line: `--flag` sets `value`.
    pub const fn only_switch(self, flag: &'static str, value: &'static str) -> Self {
        Setting { flag: None, switch: Some((flag, value)), ..self }
    }

    /// A value-less flag besides the value flag: `--flag` sets `value`.
    pub const fn and_switch(self, flag: &'static str, value: &'static str) -> Self {
        Setting { switch: Some((flag, value)), ..self }
    }

    pub const fn help(self, help: &'static str) -> Self {
        Setting { help, ..self }
    }

    /// The value as text (a name for choices).
    pub fn get(&self, settings: &S) -> String
    where
        S: Copy,
    {
        let mut s = *settings;
        match (&self.field, self.kind) {
            (Field::Count(f), _) => f(&mut s).to_string(),
            (Field::Number(f), _) => f(&mut s).to_string(),
            (Field::Switch(f), Kind::Choice(names)) => names[*f(&mut s) as usize].to_string(),
            (Field::Choice { get, .. }, Kind::Choice(names)) => names.get(get(&s)).copied().unwrap_or("?").to_string(),
            _ => unreachable!("a switch or choice is declared with Kind::Choice"),
        }
    }

    /// Parse and store `value`; out-of-range values and unknown names are refused (the message
    /// names the setting's key).
    pub fn set(&self, settings: &mut S, value: &str) -> Result<(), String> {
        let bad = || format!("{} {value}: expected {}", self.key, self.kind.accepted());
        match (&self.field, self.kind) {
            (Field::Count(f), Kind::Count { min, max }) => {
                let v: u32 = value.trim().parse().map_err(|_| bad())?;
                *f(settings) = if (min..=max).contains(&v) { v } else { return Err(bad()) };
            }
            (Field::Number(f), Kind::Number { min, max }) => {
                let v: f32 = value.trim().parse().map_err(|_| bad())?;
                *f(settings) = if v.is_finite() && (min..=max).contains(&v) { v } else { return Err(bad()) };
            }
            (field, Kind::Choice(names)) => {
                let i = names.iter().position(|n| *n == value.trim()).ok_or_else(bad)?;
                match field {
                    Field::Switch(f) => *f(settings) = i == 1,
                    Field::Choice { set, .. } => set(settings, i),
                    _ => unreachable!("numbers are declared with Count or Number"),
                }
            }
            _ => unreachable!("a count is declared with Kind::Count, a number with Kind::Number"),
        }
        Ok(())
    }

    /// Whether the stored value is inside the declared range (choices always are, by type,
    /// unless `get` cannot name the stored value).
    pub fn in_range(&self, settings: &S) -> Result<(), String>
    where
        S: Copy,
    {
        let mut s = *settings;
        let ok = match (&self.field, self.kind) {
            (Field::Count(f), Kind::Count { min, max }) => (min..=max).contains(f(&mut s)),
            (Field::Number(f), Kind::Number { min, max }) => {
                let v = *f(&mut s);
                v.is_finite() && (min..=max).contains(&v)
            }
            (Field::Choice { get, .. }, Kind::Choice(names)) => get(&s) < names.len(),
            _ => true,
        };
        if ok { Ok(()) } else { Err(format!("{} {}: expected {}", self.key, self.get(&s), self.kind.accepted())) }
    }

    /// The value as JSON-ready text: numbers bare, names quoted.
    pub fn json(&self, settings: &S) -> String
    where
        S: Copy,
    {
        match self.kind {
            Kind::Choice(_) => format!("\"{}\"", self.get(settings)),
            _ => self.get(settings),
        }
    }
}

/// A settings struct described row by row.
pub trait Settings: Copy + Default + PartialEq + Debug + Send + Sync + 'static {
    /// Every setting, in the order they are applied.
    const ROWS: &'static [Setting<Self>];

    /// Constraints beyond each row's range (e.g. a power of two).
    fn check(&self) -> Result<(), String> {
        Ok(())
    }

    /// Every row's range, then [`Settings::check`]; the message names the setting.
    fn validate(&self) -> Result<(), String> {
        for row in Self::ROWS {
            row.in_range(self)?;
        }
        self.check()
    }
}

/// One technique: its name, which settings it reads, its defaults and its pass graph.
pub struct Declaration<S: 'static> {
    /// The name users pick it by (`--technique`, `--techniques`).
    pub name: &'static str,
    /// One line for listings and help.
    pub summary: &'static str,
    /// The rows of `S::ROWS` this technique reads; the others stay at `defaults` (a variant's
    /// fixed settings, e.g. the HBAO+ kernel of hbao-sd).
    pub keys: &'static [&'static str],
    pub defaults: fn() -> S,
    /// The pass graph for a frame.
    pub graph: fn(&S, &FrameDesc) -> Result<Graph, String>,
    /// The separation of the depth-peeled second layer the graph reads, if it reads one.
    pub second_layer: fn(&S) -> Option<f32>,
    /// How every field of the constants structs its passes use (push constants, records bound as
    /// storage buffers, and the structs they contain) is computed from the settings and the
    /// camera: the manifest's `constants`. Declared beside the code that fills the structs,
    /// joined with [`join_constants!`](crate::join_constants) (the camera's rows are
    /// [`crate::common::camera::CONSTANTS`]).
    pub constants: &'static [Constant],
    /// The graph's shape where the settings change it beyond the structure: sizes, dispatches
    /// and data contents as expressions of the settings (the manifest's `size`, `dispatch`,
    /// `contents`); everything not listed prints from the graph itself.
    pub formulas: &'static [Formula],
    /// The data tables the `contents` formulas take their values from.
    pub tables: &'static [Table],
}

/// A size, dispatch or data-contents formula of a graph that depends on the settings, in the
/// grammar of the constants' expressions (`assets/README.md`, "Expressions").
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Formula {
    /// What it gives: `<resource>` its element count; `<pass label>.x` / `.y` the pass's
    /// invocations; `<resource>.table` (a table's name), `.first` and `.count` (elements) the
    /// words of a `data` resource: elements `first .. first + count` of that table.
    pub of: &'static str,
    pub expr: &'static str,
}

/// A table of values a `data` resource is filled from ([`Formula`]'s `.table`).
#[derive(Copy, Clone, Debug)]
pub struct Table {
    pub name: &'static str,
    /// The element type (`Vec2`: two f32 per element).
    pub elem: &'static str,
    pub doc: &'static str,
    /// Every element's components, in order.
    pub values: fn() -> Vec<f32>,
}

/// How an engine computes one field of a constants struct (a push-constant block or a record
/// in a storage buffer, `crate::contract::shared_structs`) from the settings and the camera.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Constant {
    /// `Struct.field`, e.g. `SvaoParams.sd_low_res`; a field whose type is another shared
    /// struct has a row too (that struct's rows say the rest).
    pub field: &'static str,
    /// What the code writes there, in words and symbols: the setting keys in backticks
    /// (`` `sd-res` ``), choices with their numeric values, the frame's quantities (`W×H` full
    /// target, `w×h` inner image, `g` guard band, R radius, e exponent, τ thickness) and units;
    /// `[x]` is the value where the technique does not read the key (its default).
    pub formula: &'static str,
    /// The same as a machine-evaluable expression in the grammar of `assets/README.md`
    /// ("Expressions"); empty where not written yet. A field whose type is a shared struct has
    /// that struct's name (its rows say the rest).
    pub expr: &'static str,
}

impl Constant {
    pub const fn new(field: &'static str, formula: &'static str) -> Self {
        Constant { field, formula, expr: "" }
    }

    /// The row with its expression ([`Constant::expr`]).
    pub const fn expr(self, expr: &'static str) -> Self {
        Constant { expr, ..self }
    }

    /// `(struct, field)` of [`Constant::field`].
    pub fn path(&self) -> (&'static str, &'static str) {
        self.field.split_once('.').unwrap_or((self.field, ""))
    }

    /// Does the formula name setting `key` (in backticks)?
    pub fn mentions(&self, key: &str) -> bool {
        self.formula.contains(&format!("`{key}`"))
    }
}

/// The rows of `tables` one after another, `N` of them in all (see [`join_constants!`](crate::join_constants)).
pub const fn join<const N: usize>(tables: &[&[Constant]]) -> [Constant; N] {
    let mut out = [Constant::new("", ""); N];
    let (mut n, mut t) = (0, 0);
    while t < tables.len() {
        let mut i = 0;
        while i < tables[t].len() {
            out[n] = tables[t][i];
            (n, i) = (n + 1, i + 1);
        }
        t += 1;
    }
    assert!(n == N, "join: N is not the number of rows");
    out
}

/// Constant tables joined into one `&'static [Constant]`, e.g.
/// `join_constants![SVAO, crate::vao::settings::CONSTANTS, crate::common::camera::CONSTANTS]`.
#[macro_export]
macro_rules! join_constants {
    ($($table:expr),+ $(,)?) => {
        &$crate::technique::join::<{ 0 $(+ $table.len())+ }>(&[$($table),+])
    };
}

/// A technique with its settings, behind one type for every settings struct.
pub trait Configured: Send + Sync + Debug {
    fn name(&self) -> &'static str;
    /// The settings the technique reads, without their types (its declaration's rows).
    fn rows(&self) -> Vec<Row>;
    /// `(key, value as text)` of every setting the technique reads, in declaration order.
    fn values(&self) -> Vec<(&'static str, String)>;
    /// The options as a JSON object text (`snake_case` keys; numbers bare, names quoted).
    fn json(&self) -> String;
    /// `(key, value)` of the settings that differ from the technique's defaults.
    fn changed(&self) -> Vec<(&'static str, String)>;
    /// Set a setting by key; a key the technique does not read is refused.
    fn set(&mut self, key: &str, value: &str) -> Result<(), String>;
    fn validate(&self) -> Result<(), String>;
    /// The declaration's graph for `frame` (the resolution and the temporal accumulation are
    /// [`Technique::graph`]'s).
    fn graph(&self, frame: &FrameDesc) -> Result<Graph, String>;
    fn second_layer(&self) -> Option<f32>;
    /// The settings struct, for callers that know its type.
    fn settings(&self) -> &dyn Any;
    fn clone_box(&self) -> Box<dyn Configured>;
}

/// An entry of the registry: a declaration for any settings struct.
pub trait Registered: Sync {
    fn name(&self) -> &'static str;
    fn summary(&self) -> &'static str;
    /// The keys of the settings it reads.
    fn keys(&self) -> &'static [&'static str];
    /// The technique at its defaults.
    fn configure(&'static self) -> Box<dyn Configured>;
    /// The settings the technique reads, without their types.
    fn rows(&self) -> Vec<Row>;
    /// How each field of its constants structs is computed ([`Declaration::constants`]).
    fn constants(&self) -> &'static [Constant];
    /// `(key, value)` of the settings of its settings type that it does not read: fixed by the
    /// declaration (e.g. hbao's `kernel` = hbao), substituted into its constants' expressions.
    fn fixed(&self) -> Vec<(Row, String)>;
    /// [`Declaration::formulas`].
    fn formulas(&self) -> &'static [Formula];
    /// [`Declaration::tables`].
    fn tables(&self) -> &'static [Table];
}

/// A setting without its settings type: what the CLI needs to declare a flag.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub key: &'static str,
    pub flag: Option<&'static str>,
    pub switch: Option<(&'static str, &'static str)>,
    pub help: &'static str,
    pub kind: Kind,
    /// The settings type's own default (`S::default()`), as text.
    pub default: String,
    /// The settings type, so that techniques sharing a flag can be checked to share the row.
    pub settings_type: &'static str,
}

impl<S: Settings> Declaration<S> {
    fn rows_read(&self) -> impl Iterator<Item = &'static Setting<S>> + '_ {
        S::ROWS.iter().filter(|r| self.keys.contains(&r.key))
    }
}

/// `setting` without its settings type.
fn row_of<S: Settings>(setting: &Setting<S>) -> Row {
    Row {
        key: setting.key,
        flag: setting.flag,
        switch: setting.switch,
        help: setting.help,
        kind: setting.kind,
        default: setting.get(&S::default()),
        settings_type: core::any::type_name::<S>(),
    }
}

/// A declaration with its settings.
struct Instance<S: 'static> {
    declaration: &'static Declaration<S>,
    settings: S,
}

impl<S: Settings> Debug for Instance<S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{} {:?}", self.declaration.name, self.settings)
    }
}

/// `technique` with `settings`; the settings it does not read are its declaration's fixed ones
/// (hbao's `kernel`, raysd's `refinement`, …), whatever `settings` holds there, so the graph
/// and the constants' expressions always see the technique's own.
pub fn configure<S: Settings>(technique: &'static Declaration<S>, mut settings: S) -> Box<dyn Configured> {
    let fixed = (technique.defaults)();
    for row in S::ROWS.iter().filter(|r| !technique.keys.contains(&r.key)) {
        row.set(&mut settings, &row.get(&fixed)).expect("a declaration's defaults are valid");
    }
    Box::new(Instance { declaration: technique, settings })
}

impl<S: Settings> Registered for Declaration<S> {
    fn name(&self) -> &'static str {
        self.name
    }

    fn summary(&self) -> &'static str {
        self.summary
    }

    fn keys(&self) -> &'static [&'static str] {
        self.keys
    }

    fn configure(&'static self) -> Box<dyn Configured> {
        configure(self, (self.defaults)())
    }

    fn rows(&self) -> Vec<Row> {
        self.rows_read().map(row_of).collect()
    }

    fn constants(&self) -> &'static [Constant] {
        self.constants
    }

    fn formulas(&self) -> &'static [Formula] {
        self.formulas
    }

    fn tables(&self) -> &'static [Table] {
        self.tables
    }

    fn fixed(&self) -> Vec<(Row, String)> {
        let defaults = (self.defaults)();
        S::ROWS.iter().filter(|r| !self.keys.contains(&r.key)).map(|r| (row_of(r), r.get(&defaults))).collect()
    }
}

impl<S: Settings> Configured for Instance<S> {
    fn name(&self) -> &'static str {
        self.declaration.name
    }

    fn rows(&self) -> Vec<Row> {
        self.declaration.rows()
    }

    fn values(&self) -> Vec<(&'static str, String)> {
        self.declaration.rows_read().map(|r| (r.key, r.get(&self.settings))).collect()
    }

    fn json(&self) -> String {
        let fields: Vec<_> = self
            .declaration
            .rows_read()
            .map(|r| format!("\"{}\":{}", r.key.replace('-', "_"), r.json(&self.settings)))
            .collect();
        format!("{{{}}}", fields.join(","))
    }

    fn changed(&self) -> Vec<(&'static str, String)> {
        let defaults = (self.declaration.defaults)();
        self.declaration
            .rows_read()
            .filter(|r| r.get(&defaults) != r.get(&self.settings))
            .map(|r| (r.key, r.get(&self.settings)))
            .collect()
    }

    fn set(&mut self, key: &str, value: &str) -> Result<(), String> {
        let row = self.declaration.rows_read().find(|r| r.key == key).ok_or_else(|| {
            let keys: Vec<_> = self.declaration.keys.to_vec();
            match keys.is_empty() {
                true => format!("{} has no options", self.declaration.name),
                false => format!("{} has no option '{key}' (it has {})", self.declaration.name, keys.join(", ")),
            }
        })?;
        row.set(&mut self.settings, value)
    }

    fn validate(&self) -> Result<(), String> {
        self.settings.validate()
    }

    fn graph(&self, frame: &FrameDesc) -> Result<Graph, String> {
        self.settings.validate()?;
        (self.declaration.graph)(&self.settings, frame)
    }

    fn second_layer(&self) -> Option<f32> {
        (self.declaration.second_layer)(&self.settings)
    }

    fn settings(&self) -> &dyn Any {
        &self.settings
    }

    fn clone_box(&self) -> Box<dyn Configured> {
        Box::new(Instance { declaration: self.declaration, settings: self.settings })
    }
}

/// For declarations without a second layer.
pub fn single_layer<S>(_: &S) -> Option<f32> {
    None
}

/// An AO technique from the registry ([`crate::techniques::TECHNIQUES`]) with its settings:
/// what an engine, the CLI and the tests pick and configure.
///
/// ```
/// use aokit_shaders::technique::Technique;
/// let gtao = Technique::preset("gtao", "ultra")?;
/// let raysd = Technique::parse("raysd:sd-layers=8:interval=off")?;
/// assert_eq!(raysd.label(), "raysd_sd-layers-8_interval-off");
/// assert!(Technique::preset("vao", "high").is_err()); // vao has no presets
/// # Ok::<(), String>(())
/// ```
#[derive(Debug)]
pub struct Technique(Box<dyn Configured>, Resolution);

impl Clone for Technique {
    fn clone(&self) -> Self {
        Technique(self.0.clone_box(), self.1)
    }
}

impl Technique {
    /// `technique` with `settings` (its fixed settings, those it does not read, are the
    /// declaration's).
    pub fn new<S: Settings>(technique: &'static Declaration<S>, settings: S) -> Technique {
        Technique(configure(technique, settings), Resolution::Full)
    }

    /// The registered technique `name` at its defaults.
    pub fn named(name: &str) -> Result<Technique, String> {
        let technique = crate::techniques::find(name)
            .ok_or_else(|| format!("unknown technique '{name}' (known: {})", crate::techniques::names()))?;
        Ok(Technique(technique.configure(), Resolution::Full))
    }

    /// The registered technique `name` at quality preset `preset` (its `preset` setting, e.g.
    /// XeGTAO's `low`, `medium`, `high`, `ultra`); refused for techniques without presets.
    pub fn preset(name: &str, preset: &str) -> Result<Technique, String> {
        let mut t = Technique::named(name)?;
        if !t.rows().iter().any(|r| r.key == "preset") {
            return Err(format!("{name} has no quality presets; configure it with Technique::set"));
        }
        t.set("preset", preset)?;
        Ok(t)
    }

    /// A technique from its name followed by settings as `:key=value` with the keys of its
    /// settings rows, e.g. `raysd:sd-layers=8:interval=off`; every technique also takes
    /// `resolution=full|half|half-nearest`, a half one optionally ending in `-tau<τ>`
    /// ([`Resolution::parse`], spec half-resolution §1).
    pub fn parse(spec: &str) -> Result<Technique, String> {
        Technique::parse_with_flags(spec, &[])
    }

    /// [`Technique::parse`] after settings given by their rows' flags (`(flag, value)`, no value
    /// for a value-less switch) that apply to every technique with that flag; a `:key=value`
    /// after the name wins over the flag of the same setting. Rows are applied in declaration
    /// order (a preset before its slices and steps, a variant before its weight).
    pub fn parse_with_flags(spec: &str, flags: &[(String, Option<String>)]) -> Result<Technique, String> {
        let mut parts = spec.trim().split(':');
        let mut t = Technique::named(parts.next().unwrap_or_default())?;
        let rows = t.rows();
        let mut overrides = Vec::new();
        for (flag, value) in flags {
            if flag == RESOLUTION_KEY {
                t.1 = Resolution::parse(value.as_deref().unwrap_or_default()).map_err(|e| format!("--{e}"))?;
            }
        }
        for part in parts {
            let (key, value) = part.split_once('=').ok_or_else(|| format!("'{part}' in '{spec}' is not key=value"))?;
            if key == RESOLUTION_KEY {
                t.1 = Resolution::parse(value).map_err(|e| format!("'{spec}': {e}"))?;
                continue;
            }
            if !rows.iter().any(|r| r.key == key) {
                // The technique's own message, naming the keys it has.
                t.0.set(key, value).map_err(|e| format!("'{spec}': {e}"))?;
            }
            overrides.push((key, value));
        }
        for row in &rows {
            if let Some((_, value)) = overrides.iter().rev().find(|(k, _)| *k == row.key) {
                t.0.set(row.key, value).map_err(|e| format!("'{spec}': {e}"))?;
                continue;
            }
            for (flag, value) in flags {
                // A value flag carries its value; a switch sets the value it stands for.
                let value = match value {
                    Some(v) if row.flag == Some(flag.as_str()) => v.as_str(),
                    None => match row.switch {
                        Some((f, v)) if f == flag => v,
                        _ => continue,
                    },
                    Some(_) => continue,
                };
                // A flag's value refused is named by the flag it came with.
                t.0.set(row.key, value).map_err(|e| match e.strip_prefix(row.key) {
                    Some(rest) => format!("--{flag}{rest}"),
                    None => e,
                })?;
            }
        }
        t.0.validate().map_err(|e| format!("'{spec}': {e}"))?;
        Ok(t)
    }

    /// The registry name.
    pub fn name(&self) -> &'static str {
        self.0.name()
    }

    /// The settings the technique reads (keys, flags, help, ranges, defaults).
    pub fn rows(&self) -> Vec<Row> {
        self.0.rows()
    }

    /// `(key, value as text)` of every setting the technique reads.
    pub fn values(&self) -> Vec<(&'static str, String)> {
        self.0.values()
    }

    /// Set one setting by its key (a value out of its row's range is refused).
    pub fn set(&mut self, key: &str, value: &str) -> Result<(), String> {
        self.0.set(key, value)?;
        self.0.validate()
    }

    /// The settings struct when it is an `S`.
    pub fn settings<S: Settings>(&self) -> Option<&S> {
        self.0.settings().downcast_ref()
    }

    /// A label for tables and file names: the name plus the settings that differ from the
    /// technique's defaults, e.g. `raysd_sd-layers-8`.
    pub fn label(&self) -> String {
        let mut label = self.name().to_string();
        for (key, value) in self.0.changed() {
            label += &format!("_{key}-{value}");
        }
        if self.1 != Resolution::Full {
            label += &format!("_{RESOLUTION_KEY}-{}", self.1.name());
        }
        label
    }

    /// Every setting the technique reads as a JSON object text (`snake_case` keys), with
    /// `"resolution"` when it is not the full target.
    pub fn json(&self) -> String {
        let json = self.0.json();
        match self.1 {
            Resolution::Full => json,
            r => {
                let separator = if json == "{}" { "" } else { "," };
                format!("{}{separator}\"{RESOLUTION_KEY}\":\"{}\"}}", &json[..json.len() - 1], r.name())
            }
        }
    }

    /// The resolution it runs at ([`Resolution::Full`] unless set).
    pub fn resolution(&self) -> Resolution {
        self.1
    }

    /// The technique at `resolution` (spec half-resolution §1).
    pub fn with_resolution(mut self, resolution: Resolution) -> Technique {
        self.1 = resolution;
        self
    }

    /// The technique's pass graph for a frame: its own graph, at its resolution
    /// ([`crate::halfres::settings::at_resolution`]), followed by the temporal accumulation when
    /// the frame asks for it.
    pub fn graph(&self, frame: &FrameDesc) -> Result<Graph, String> {
        let graph = crate::halfres::settings::at_resolution(self.1, frame, |f| self.0.graph(f))?;
        crate::temporal::settings::accumulate(graph, frame)
    }

    /// The separation of the depth-peeled second layer, for techniques that read one (spec
    /// svao-raysd §11).
    pub fn second_layer(&self) -> Option<f32> {
        self.0.second_layer()
    }
}
