//! `assets/include/aokit_constants.h`: every technique's constants expressions
//! (`techniques[].constants[].expr`) translated to C functions, so a C or C++ engine fills its
//! push constants and records from the contract without writing a formula: per technique a
//! settings struct (choices as indices, with their names as constants), its defaults, and one
//! function per constants struct it uses. The C follows the grammar's arithmetic
//! (`assets/README.md`, "Expressions"): integers in `int64_t`, reals in `float` rounded per
//! operation (compile with `-ffp-contract=off`, which `-std=c11` implies for GCC), `sin`, `cos`,
//! `tan`, `pow` in `double` rounded once.

use crate::manifest::{ConstantManifest, Manifest, SettingManifest};

/// A translated expression: its C text and its type.
#[derive(Clone, Debug)]
struct C {
    code: String,
    ty: Ty,
}

#[derive(Clone, Debug, PartialEq)]
enum Ty {
    Int,
    Real,
    Bool,
    /// A name known when translating (a literal or a fixed setting's value).
    Text(String),
    /// A choice setting's value: its index in `s->key`.
    Choice(String),
    Vec(usize),
    UVec2,
    Mat4,
}

/// The C identifier of a setting key (`sd-res` → `sd_res`).
fn ident(key: &str) -> String {
    key.replace('-', "_")
}

fn upper(name: &str) -> String {
    name.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_uppercase() } else { '_' }).collect()
}

struct Translator<'a> {
    tokens: Vec<String>,
    at: usize,
    settings: &'a [SettingManifest],
    text: &'a str,
}

impl Translator<'_> {
    fn error(&self, what: &str) -> String {
        format!("'{}': {what}", self.text)
    }

    fn eat(&mut self, t: &str) -> bool {
        let hit = self.tokens.get(self.at).is_some_and(|x| x == t);
        self.at += hit as usize;
        hit
    }

    fn expect(&mut self, t: &str) -> Result<(), String> {
        if self.eat(t) { Ok(()) } else { Err(self.error(&format!("expected '{t}'"))) }
    }

    fn real(&self, c: &C) -> Result<String, String> {
        match c.ty {
            Ty::Int => Ok(format!("(float)({})", c.code)),
            Ty::Real => Ok(c.code.clone()),
            _ => Err(self.error(&format!("{:?} is not a number", c.ty))),
        }
    }

    fn boolean(&self, c: &C) -> Result<String, String> {
        match c.ty {
            Ty::Bool => Ok(c.code.clone()),
            _ => Err(self.error("expected a truth value")),
        }
    }

    fn or(&mut self) -> Result<C, String> {
        let mut a = self.and()?;
        while self.eat("||") {
            let b = self.and()?;
            a = C { code: format!("({} || {})", self.boolean(&a)?, self.boolean(&b)?), ty: Ty::Bool };
        }
        Ok(a)
    }

    fn and(&mut self) -> Result<C, String> {
        let mut a = self.comparison()?;
        while self.eat("&&") {
            let b = self.comparison()?;
            a = C { code: format!("({} && {})", self.boolean(&a)?, self.boolean(&b)?), ty: Ty::Bool };
        }
        Ok(a)
    }

    /// The index of `name` among choice setting `key`'s names.
    fn choice_index(&self, key: &str, name: &str) -> Result<usize, String> {
        let s = self.settings.iter().find(|s| s.key == key).ok_or_else(|| self.error(&format!("no setting {key}")))?;
        s.choices.iter().position(|c| c == name).ok_or_else(|| self.error(&format!("{key} has no choice {name}")))
    }

    fn comparison(&mut self) -> Result<C, String> {
        let a = self.sum()?;
        let op = match self.tokens.get(self.at).map(String::as_str) {
            Some(op @ ("==" | "!=" | "<" | "<=" | ">" | ">=")) => op.to_string(),
            _ => return Ok(a),
        };
        self.at += 1;
        let b = self.sum()?;
        let code = match (&a.ty, &b.ty) {
            (Ty::Text(x), Ty::Text(y)) => if (x == y) == (op == "==") { "1" } else { "0" }.to_string(),
            (Ty::Choice(k), Ty::Text(n)) | (Ty::Text(n), Ty::Choice(k)) => {
                format!(
                    "({} {op} {}u)",
                    if matches!(a.ty, Ty::Choice(_)) { &a.code } else { &b.code },
                    self.choice_index(k, n)?
                )
            }
            (Ty::Int, Ty::Int) | (Ty::Bool, Ty::Bool) => format!("({} {op} {})", a.code, b.code),
            _ => format!("({} {op} {})", self.real(&a)?, self.real(&b)?),
        };
        Ok(C { code, ty: Ty::Bool })
    }

    fn arithmetic(&self, op: &str, a: C, b: C) -> Result<C, String> {
        if a.ty == Ty::Int && b.ty == Ty::Int && op != "/" {
            return Ok(C { code: format!("({} {op} {})", a.code, b.code), ty: Ty::Int });
        }
        Ok(C { code: format!("({} {op} {})", self.real(&a)?, self.real(&b)?), ty: Ty::Real })
    }

    fn sum(&mut self) -> Result<C, String> {
        let mut a = self.product()?;
        while let Some(op) = self.tokens.get(self.at).filter(|t| *t == "+" || *t == "-").cloned() {
            self.at += 1;
            let b = self.product()?;
            a = self.arithmetic(&op, a, b)?;
        }
        Ok(a)
    }

    fn product(&mut self) -> Result<C, String> {
        let mut a = self.unary()?;
        while let Some(op) = self.tokens.get(self.at).filter(|t| *t == "*" || *t == "/").cloned() {
            self.at += 1;
            let b = self.unary()?;
            a = self.arithmetic(&op, a, b)?;
        }
        Ok(a)
    }

    fn unary(&mut self) -> Result<C, String> {
        if self.eat("-") {
            let v = self.unary()?;
            return match v.ty {
                Ty::Int | Ty::Real => Ok(C { code: format!("(-{})", v.code), ty: v.ty }),
                _ => Err(self.error("cannot negate")),
            };
        }
        if self.eat("!") {
            let v = self.unary()?;
            return Ok(C { code: format!("(!{})", self.boolean(&v)?), ty: Ty::Bool });
        }
        let mut v = self.primary()?;
        while self.eat(".") {
            let name = self.tokens.get(self.at).cloned().unwrap_or_default();
            self.at += 1;
            let i = ["x", "y", "z", "w"].iter().position(|c| *c == name).ok_or_else(|| self.error("bad component"))?;
            v = match v.ty {
                Ty::Vec(_) => C { code: format!("{}.v[{i}]", v.code), ty: Ty::Real },
                Ty::UVec2 => C { code: format!("(int64_t){}.v[{i}]", v.code), ty: Ty::Int },
                _ => return Err(self.error("a component of a non-vector")),
            };
        }
        Ok(v)
    }

    fn primary(&mut self) -> Result<C, String> {
        let token = self.tokens.get(self.at).cloned().ok_or_else(|| self.error("unexpected end"))?;
        self.at += 1;
        if token == "(" {
            let v = self.or()?;
            self.expect(")")?;
            return Ok(v);
        }
        if let Some(key) = token.strip_prefix('`').and_then(|t| t.strip_suffix('`')) {
            let s =
                self.settings.iter().find(|s| s.key == key).ok_or_else(|| self.error(&format!("no setting {key}")))?;
            let field = format!("s->{}", ident(key));
            return Ok(match s.kind.as_str() {
                "count" => C { code: format!("(int64_t){field}"), ty: Ty::Int },
                "number" => C { code: field, ty: Ty::Real },
                _ => C { code: field, ty: Ty::Choice(key.into()) },
            });
        }
        if let Some(text) = token.strip_prefix('"').and_then(|t| t.strip_suffix('"')) {
            return Ok(C { code: String::new(), ty: Ty::Text(text.into()) });
        }
        if token.starts_with(|c: char| c.is_ascii_digit()) {
            return Ok(if token.contains(['.', 'e']) {
                let v: f32 = token.parse().map_err(|_| self.error("bad number"))?;
                // The binary32 value, exactly.
                C { code: float_literal(v), ty: Ty::Real }
            } else {
                C { code: format!("INT64_C({token})"), ty: Ty::Int }
            });
        }
        if token == "true" || token == "false" {
            return Ok(C { code: if token == "true" { "1" } else { "0" }.into(), ty: Ty::Bool });
        }
        if self.tokens.get(self.at).is_some_and(|t| t == "(") {
            return self.call(&token);
        }
        let (code, ty) = match token.as_str() {
            "W" => ("(int64_t)(f->w + 2u * f->g)".into(), Ty::Int),
            "H" => ("(int64_t)(f->h + 2u * f->g)".into(), Ty::Int),
            "pass" => ("(int64_t)pass".into(), Ty::Int),
            name => match frame_field(name) {
                Some((field, FieldTy::Vec3)) => (format!("aokit__vec3(f->{field})"), Ty::Vec(3)),
                Some((field, FieldTy::Real)) => (format!("f->{field}"), Ty::Real),
                Some((field, FieldTy::Count)) => (format!("(int64_t)f->{field}"), Ty::Int),
                Some((field, FieldTy::Flag)) => (format!("(f->{field} != 0u)"), Ty::Bool),
                None => return Err(self.error(&format!("unknown name {token}"))),
            },
        };
        Ok(C { code, ty })
    }

    fn call(&mut self, name: &str) -> Result<C, String> {
        self.expect("(")?;
        if name == "index" {
            let token = self.tokens.get(self.at).cloned().unwrap_or_default();
            let key = token.strip_prefix('`').and_then(|t| t.strip_suffix('`')).ok_or_else(|| self.error("index"))?;
            self.at += 1;
            self.expect(")")?;
            return Ok(C { code: format!("(int64_t)s->{}", ident(key)), ty: Ty::Int });
        }
        let mut args = Vec::new();
        if !self.eat(")") {
            loop {
                args.push(self.or()?);
                if self.eat(")") {
                    break;
                }
                self.expect(",")?;
            }
        }
        let reals = |t: &Self, args: &[C]| args.iter().map(|a| t.real(a)).collect::<Result<Vec<_>, _>>();
        let same = |a: &C, b: &C| a.ty == b.ty || matches!((&a.ty, &b.ty), (Ty::Int | Ty::Real, Ty::Int | Ty::Real));
        Ok(match (name, args.as_slice()) {
            ("select", [c, a, b]) if same(a, b) => {
                let c = self.boolean(c)?;
                if a.ty == b.ty {
                    C { code: format!("({c} ? {} : {})", a.code, b.code), ty: a.ty.clone() }
                } else {
                    C { code: format!("({c} ? {} : {})", self.real(a)?, self.real(b)?), ty: Ty::Real }
                }
            }
            ("pick", [i, rest @ ..]) if !rest.is_empty() && rest.iter().all(|r| same(r, &rest[0])) => {
                let index = match i.ty {
                    Ty::Int => i.code.clone(),
                    _ => return Err(self.error("pick: an integer index")),
                };
                let all_int = rest.iter().all(|r| r.ty == Ty::Int);
                let value = |r: &C| if all_int { Ok(r.code.clone()) } else { self.real(r) };
                let mut code = value(&rest[rest.len() - 1])?;
                for (k, r) in rest.iter().enumerate().rev().skip(1) {
                    code = format!("({index} == {k} ? {} : {code})", value(r)?);
                }
                C { code, ty: if all_int { Ty::Int } else { Ty::Real } }
            }
            ("f32", [v]) => C { code: self.real(v)?, ty: Ty::Real },
            ("u32", [v]) => match v.ty {
                Ty::Bool => C { code: format!("(int64_t)({})", v.code), ty: Ty::Int },
                _ => C { code: format!("aokit__u32({})", self.real(v)?), ty: Ty::Int },
            },
            ("div_ceil" | "div_floor", [a, b]) if a.ty == Ty::Int && b.ty == Ty::Int => {
                C { code: format!("aokit__{name}({}, {})", a.code, b.code), ty: Ty::Int }
            }
            ("min" | "max", [a, b]) if a.ty == Ty::Int && b.ty == Ty::Int => {
                C { code: format!("aokit__i{name}({}, {})", a.code, b.code), ty: Ty::Int }
            }
            ("min" | "max", [_, _]) => {
                let r = reals(self, &args)?;
                C { code: format!("aokit__f{name}({}, {})", r[0], r[1]), ty: Ty::Real }
            }
            ("floor" | "ceil" | "sqrt", [v]) if v.ty == Ty::Int && name != "sqrt" => v.clone(),
            ("floor" | "ceil" | "sqrt", [v]) => C { code: format!("{name}f({})", self.real(v)?), ty: Ty::Real },
            ("sin" | "cos" | "tan", [v]) => {
                C { code: format!("(float){name}((double){})", self.real(v)?), ty: Ty::Real }
            }
            ("pow", [a, b]) => {
                C { code: format!("(float)pow((double){}, (double){})", self.real(a)?, self.real(b)?), ty: Ty::Real }
            }
            ("vec2" | "vec3" | "vec4", _) if args.len() == name[3..].parse::<usize>().unwrap_or(0) => {
                let r = reals(self, &args)?;
                C { code: format!("aokit__{name}f({})", r.join(", ")), ty: Ty::Vec(args.len()) }
            }
            ("uvec2", [a, b]) if a.ty == Ty::Int && b.ty == Ty::Int => {
                C { code: format!("aokit__uvec2({}, {})", a.code, b.code), ty: Ty::UVec2 }
            }
            ("normalize", [v]) if v.ty == Ty::Vec(3) => {
                C { code: format!("aokit__normalize({})", v.code), ty: Ty::Vec(3) }
            }
            ("cross", [a, b]) if a.ty == Ty::Vec(3) && b.ty == Ty::Vec(3) => {
                C { code: format!("aokit__cross({}, {})", a.code, b.code), ty: Ty::Vec(3) }
            }
            ("look_at", [e, t, u]) if [e, t, u].iter().all(|v| v.ty == Ty::Vec(3)) => {
                C { code: format!("aokit__look_at({}, {}, {})", e.code, t.code, u.code), ty: Ty::Mat4 }
            }
            ("inverse_rigid", [m]) if m.ty == Ty::Mat4 => {
                C { code: format!("aokit__inverse_rigid({})", m.code), ty: Ty::Mat4 }
            }
            _ => {
                return Err(
                    self.error(&format!("{name}: arguments {:?}", args.iter().map(|a| &a.ty).collect::<Vec<_>>()))
                );
            }
        })
    }
}

/// `v` as a C/C++ float literal that rounds back to exactly `v` (Rust's shortest round-trip
/// decimal; C and C++ round decimal literals correctly).
fn float_literal(v: f32) -> String {
    format!("{v:?}f")
}

/// How an `aokit_frame_inputs` field is declared.
#[derive(Clone, Copy, PartialEq)]
enum FieldTy {
    /// `float name[3]`.
    Vec3,
    /// `float`.
    Real,
    /// `uint32_t`, read as a whole number.
    Count,
    /// `uint32_t`, read as a boolean.
    Flag,
}

/// The `aokit_frame_inputs` field that an expression name reads (assets/README.md,
/// "Expressions"), and its type: the one table the expressions' names, the previous frame's copy
/// (`temporal.previous_names`) and the half frame (`half_resolution.half_names`) go through.
/// `W`, `H` and `pass` are not fields.
fn frame_field(name: &str) -> Option<(&'static str, FieldTy)> {
    Some(match name {
        "eye" => ("eye", FieldTy::Vec3),
        "target" => ("target", FieldTy::Vec3),
        "up" => ("up", FieldTy::Vec3),
        "fov_y" => ("fov_y", FieldTy::Real),
        // `near` and `far` are macros on some C platforms.
        "near" => ("near_plane", FieldTy::Real),
        "far" => ("far_plane", FieldTy::Real),
        "radius" => ("radius", FieldTy::Real),
        "exponent" => ("exponent", FieldTy::Real),
        "thickness" => ("thickness", FieldTy::Real),
        "w" => ("w", FieldTy::Count),
        "h" => ("h", FieldTy::Count),
        "g" => ("g", FieldTy::Count),
        "frame" => ("frame", FieldTy::Count),
        "has_previous" => ("has_previous", FieldTy::Flag),
        "previous_eye" => ("previous_eye", FieldTy::Vec3),
        "previous_target" => ("previous_target", FieldTy::Vec3),
        "previous_up" => ("previous_up", FieldTy::Vec3),
        "previous_fov_y" => ("previous_fov_y", FieldTy::Real),
        "previous_near" => ("previous_near", FieldTy::Real),
        "previous_far" => ("previous_far", FieldTy::Real),
        _ => return None,
    })
}

/// The statements that copy the previous frame's camera into `previous` (an
/// `aokit_frame_inputs` copied from `f`): `previous.<name> = f-><previous name>` for each pair of
/// the manifest's `temporal.previous_names`, the same type on both sides.
fn previous_copy(names: &[(String, String)], indent: &str) -> Result<String, String> {
    let mut vectors = String::new();
    let mut scalars = String::new();
    for (name, previous) in names {
        let field = |n: &str| frame_field(n).ok_or_else(|| format!("temporal.previous_names: no frame field `{n}`"));
        let ((to, ty), (from, from_ty)) = (field(name)?, field(previous)?);
        if ty != from_ty {
            return Err(format!("temporal.previous_names: `{name}` and `{previous}` differ in type"));
        }
        match ty {
            FieldTy::Vec3 => vectors += &format!("{indent}    previous.{to}[i] = f->{from}[i];\n"),
            _ => scalars += &format!("{indent}previous.{to} = f->{from};\n"),
        }
    }
    let vectors = if vectors.is_empty() {
        vectors
    } else {
        format!("{indent}for (int i = 0; i < 3; i++) {{\n{vectors}{indent}}}\n")
    };
    Ok(vectors + &scalars)
}

/// The statements that set `out` (a copy of `f`) to the half frame: `out-><name> = <expression>`
/// for each name of the manifest's `half_resolution.half_names` that is a field (`W` and `H`
/// are not: they follow from w, h and g).
fn half_assignments(names: &[(String, String)]) -> Result<String, String> {
    let mut h = String::new();
    for (name, expr) in names {
        match frame_field(name) {
            Some((field, FieldTy::Count)) => {
                let value = translate(expr, &[]).map_err(|e| format!("half_resolution.half_names {name}: {e}"))?;
                if value.ty != Ty::Int {
                    return Err(format!("half_resolution.half_names {name}: `{expr}` is not a whole number"));
                }
                h += &format!("    out->{field} = (uint32_t){};\n", value.code);
            }
            Some(_) => return Err(format!("half_resolution.half_names: `{name}` is not a pixel count")),
            None if name == "W" || name == "H" => {}
            None => return Err(format!("half_resolution.half_names: no frame field `{name}`")),
        }
    }
    Ok(h)
}

/// Translate `expr` (of a technique with `settings`) to C.
fn translate(expr: &str, settings: &[SettingManifest]) -> Result<C, String> {
    let tokens = crate::expr::tokens(expr)?;
    let mut t = Translator { tokens, at: 0, settings, text: expr };
    let c = t.or()?;
    if t.at != t.tokens.len() {
        return Err(t.error("trailing tokens"));
    }
    Ok(c)
}

/// The C assignment of a field of type `ty` from `value`.
fn store(target: &str, ty: &str, value: &C, settings: &[SettingManifest], expr: &str) -> Result<String, String> {
    let bad = || format!("'{expr}': a {ty} field from {:?}", value.ty);
    let real = |c: &C| Translator { tokens: vec![], at: 0, settings, text: expr }.real(c);
    Ok(match (ty, &value.ty) {
        ("f32", Ty::Int | Ty::Real) => format!("{target} = {};", real(value)?),
        ("u32", Ty::Int | Ty::Bool) => format!("{target} = (uint32_t)({});", value.code),
        ("i32", Ty::Int) => format!("{target} = (int32_t)({});", value.code),
        ("Vec2", Ty::Vec(2))
        | ("Vec3", Ty::Vec(3))
        | ("Vec4", Ty::Vec(4))
        | ("UVec2", Ty::UVec2)
        | ("Mat4", Ty::Mat4) => {
            format!("{target} = {};", value.code)
        }
        _ => return Err(bad()),
    })
}

/// Helpers every generated function uses: the grammar's builtins with its arithmetic.
const HELPERS: &str = r#"static inline int64_t aokit__div_ceil(int64_t a, int64_t b) { return a / b + (a % b != 0 && (a < 0) == (b < 0)); }
static inline int64_t aokit__div_floor(int64_t a, int64_t b) { return a / b - (a % b != 0 && (a < 0) != (b < 0)); }
static inline int64_t aokit__imin(int64_t a, int64_t b) { return a < b ? a : b; }
static inline int64_t aokit__imax(int64_t a, int64_t b) { return a > b ? a : b; }
static inline float aokit__fmin(float a, float b) { return a < b ? a : b; }
static inline float aokit__fmax(float a, float b) { return a > b ? a : b; }
static inline int64_t aokit__u32(float x) { return x <= 0.0f ? 0 : x >= 4294967295.0f ? INT64_C(4294967295) : (int64_t)x; }
static inline aokit_vec2 aokit__vec2f(float x, float y) { aokit_vec2 r = {{x, y}}; return r; }
static inline aokit_vec3 aokit__vec3f(float x, float y, float z) { aokit_vec3 r = {{x, y, z}}; return r; }
static inline aokit_vec4 aokit__vec4f(float x, float y, float z, float w) { aokit_vec4 r = {{x, y, z, w}}; return r; }
static inline aokit_vec3 aokit__vec3(const float v[3]) { return aokit__vec3f(v[0], v[1], v[2]); }
static inline aokit_uvec2 aokit__uvec2(int64_t x, int64_t y) { aokit_uvec2 r = {{(uint32_t)x, (uint32_t)y}}; return r; }
/* dot(a, b) = (a.x·b.x + a.y·b.y) + a.z·b.z; normalize(v) = v·(1/sqrt(dot(v, v))). */
static inline float aokit__dot(aokit_vec3 a, aokit_vec3 b) { float xy = a.v[0] * b.v[0] + a.v[1] * b.v[1]; return xy + a.v[2] * b.v[2]; }
static inline aokit_vec3 aokit__normalize(aokit_vec3 v) { float r = 1.0f / sqrtf(aokit__dot(v, v)); return aokit__vec3f(v.v[0] * r, v.v[1] * r, v.v[2] * r); }
static inline aokit_vec3 aokit__cross(aokit_vec3 a, aokit_vec3 b) {
    return aokit__vec3f(a.v[1] * b.v[2] - b.v[1] * a.v[2], a.v[2] * b.v[0] - b.v[2] * a.v[0], a.v[0] * b.v[1] - b.v[0] * a.v[1]);
}
/* look_at(E, T, U): view → world, columns (r, 0), (u, 0), (−d, 0), (E, 1). */
static inline aokit_mat4 aokit__look_at(aokit_vec3 e, aokit_vec3 t, aokit_vec3 u) {
    aokit_vec3 d = aokit__normalize(aokit__vec3f(t.v[0] - e.v[0], t.v[1] - e.v[1], t.v[2] - e.v[2]));
    aokit_vec3 r = aokit__normalize(aokit__cross(d, u));
    aokit_vec3 up = aokit__cross(r, d);
    aokit_mat4 m = {{r.v[0], r.v[1], r.v[2], 0.0f, up.v[0], up.v[1], up.v[2], 0.0f,
                     -d.v[0], -d.v[1], -d.v[2], 0.0f, e.v[0], e.v[1], e.v[2], 1.0f}};
    return m;
}
/* inverse_rigid([R | t]): Rᵀ, −Rᵀ·t. */
static inline aokit_mat4 aokit__inverse_rigid(aokit_mat4 m) {
    aokit_vec3 c0 = aokit__vec3(&m.v[0]), c1 = aokit__vec3(&m.v[4]), c2 = aokit__vec3(&m.v[8]), t = aokit__vec3(&m.v[12]);
    aokit_mat4 r = {{c0.v[0], c1.v[0], c2.v[0], 0.0f, c0.v[1], c1.v[1], c2.v[1], 0.0f,
                     c0.v[2], c1.v[2], c2.v[2], 0.0f, -aokit__dot(c0, t), -aokit__dot(c1, t), -aokit__dot(c2, t), 1.0f}};
    return r;
}
"#;

/// A setting's C type, value and doc in the settings struct.
fn setting_field(s: &SettingManifest) -> (String, String) {
    match s.kind.as_str() {
        "count" => ("uint32_t".into(), format!("{}u", s.default)),
        "number" => {
            let v: f32 = s.default.parse().unwrap_or_default();
            ("float".into(), float_literal(v))
        }
        _ => ("uint32_t".into(), format!("{}u", s.choices.iter().position(|c| *c == s.default).unwrap_or(0))),
    }
}

/// What [`technique`] generates from: a technique's (or the adapters') name, summary, settings
/// and constants.
struct Source<'a> {
    name: &'a str,
    summary: &'a str,
    settings: &'a [SettingManifest],
    constants: &'a [ConstantManifest],
}

/// One technique's settings struct, defaults and constants functions.
fn technique(t: &Source, manifest: &Manifest) -> Result<String, String> {
    let p = format!("aokit_{}", ident(t.name));
    let mut h = format!("/* {}: {} */\n", t.name, t.summary.replace("*/", "* /"));
    for s in t.settings.iter().filter(|s| s.kind == "choice") {
        for (i, c) in s.choices.iter().enumerate() {
            h += &format!("#define {}_{}_{} {i}u\n", upper(&p), upper(&s.key), upper(c));
        }
    }
    h += &format!("typedef struct {p}_settings {{\n");
    for s in t.settings {
        let (ty, _) = setting_field(s);
        let what = if s.kind == "choice" { format!(" (index: {})", s.choices.join(", ")) } else { String::new() };
        h += &format!("    {ty} {}; /* {}{what} */\n", ident(&s.key), s.help.replace("*/", "* /"));
    }
    if t.settings.is_empty() {
        h += "    uint32_t _none;\n";
    }
    h += &format!("}} {p}_settings;\n");
    let defaults: Vec<String> = t.settings.iter().map(|s| setting_field(s).1).collect();
    let defaults = if defaults.is_empty() { "0u".to_string() } else { defaults.join(", ") };
    h += &format!("static inline {p}_settings {p}_defaults(void) {{ {p}_settings s = {{{defaults}}}; return s; }}\n");
    // The structs this technique's constants fill, contained ones first (manifest order).
    let used: Vec<&str> = manifest
        .structs
        .iter()
        .map(|s| s.name.as_str())
        .filter(|n| t.constants.iter().any(|c| c.struct_name == *n))
        .collect();
    for name in used {
        let s = manifest.structs.iter().find(|s| s.name == name).expect("a struct");
        h += &format!(
            "/* {name} of {}: `pass` is the pass's index among the graph's passes of its module (0 for records). */\n",
            t.name
        );
        h += &format!(
            "static inline void {p}_{name}(const {p}_settings *s, const aokit_frame_inputs *f, uint32_t pass, aokit_{name} *out) {{\n"
        );
        h += "    (void)s; (void)f; (void)pass;\n";
        for field in &s.fields {
            let c = t
                .constants
                .iter()
                .find(|c| c.struct_name == name && c.field == field.name)
                .ok_or_else(|| format!("{} {name}.{}: no constant", t.name, field.name))?;
            if manifest.structs.iter().any(|x| x.name == field.ty) {
                if c.expr == format!("previous({})", field.ty) {
                    // The previous frame's camera (`temporal.previous_names`) when there is one.
                    let temporal =
                        manifest.temporal.as_ref().ok_or("previous(T) without the manifest's temporal section")?;
                    h += "    {\n        aokit_frame_inputs previous = *f;\n        if (f->has_previous) {\n";
                    h += &previous_copy(&temporal.previous_names, "            ")?;
                    h += "        }\n";
                    h += &format!("        {p}_{}(s, &previous, pass, &out->{});\n    }}\n", field.ty, field.name);
                } else if c.expr == format!("half({})", field.ty) {
                    manifest
                        .half_resolution
                        .as_ref()
                        .ok_or("half(T) without the manifest's half_resolution section")?;
                    // The half-resolution frame (`half_resolution.half_names`): w, h, g halved.
                    h += &format!(
                        "    {{ aokit_frame_inputs half = *f; (void)aokit_half_frame_inputs(f, &half); {p}_{}(s, &half, pass, &out->{}); }}\n",
                        field.ty, field.name
                    );
                } else if c.expr == field.ty {
                    h += &format!("    {p}_{}(s, f, pass, &out->{});\n", field.ty, field.name);
                } else {
                    return Err(format!(
                        "{} {name}.{}: a {1} field's expression is `{1}`, `half({1})` or `previous({1})`, not `{2}`",
                        t.name, field.ty, c.expr
                    ));
                }
                continue;
            }
            let value = translate(&c.expr, t.settings).map_err(|e| format!("{} {name}.{}: {e}", t.name, field.name))?;
            h += &format!(
                "    {} /* {} */\n",
                store(&format!("out->{}", field.name), &field.ty, &value, t.settings, &c.expr)?,
                c.expr.replace("*/", "* /")
            );
        }
        h += "}\n";
    }
    Ok(h + "\n")
}

impl Manifest {
    /// `assets/include/aokit_constants.h`.
    pub fn c_constants_header(&self) -> Result<String, String> {
        let mut h = String::from(
            "/* aokit_constants.h: every technique's constants structs computed from its settings and the frame,\n \
             * translated from the manifest's expressions (assets/README.md, \"Expressions\").\n \
             * GENERATED by `cargo run -p xtask -- build-spirv`; do not edit. Needs aokit.h and <math.h> (-lm).\n \
             * The arithmetic is the grammar's: compile without FMA contraction (-ffp-contract=off; GCC's\n \
             * -std=c11 implies it) and with FLT_EVAL_METHOD 0 (SSE, not x87). */\n\
             #ifndef AOKIT_CONSTANTS_H\n#define AOKIT_CONSTANTS_H\n\n#include <math.h>\n#include <stdint.h>\n#include \"aokit.h\"\n\n",
        );
        h += "/* What the expressions read of a frame. */\ntypedef struct aokit_frame_inputs {\n";
        h += "    float eye[3], target[3], up[3]; /* world space */\n";
        h += "    float fov_y; /* vertical field of view of the INNER image, radians */\n";
        h += "    float near_plane, far_plane; /* view depths, world units */\n";
        h += "    uint32_t w, h; /* inner image, pixels */\n    uint32_t g; /* guard band, pixels per side */\n";
        h += "    float radius, exponent, thickness; /* AO radius and VAO thickness (world units), AO exponent */\n";
        h += "    uint32_t frame; /* the frame's index in a sequence (0: a single frame) */\n";
        h += "    /* The previous frame's camera, for the temporal accumulation (same w, h, g): has_previous 0 on a first\n";
        h += "     * frame, after a cut or a resize (then the previous_* fields are unread). */\n";
        h += "    uint32_t has_previous;\n    float previous_eye[3], previous_target[3], previous_up[3];\n";
        h += "    float previous_fov_y, previous_near, previous_far;\n} aokit_frame_inputs;\n\n";
        h += HELPERS;
        h += "\n";
        if let Some(half) = &self.half_resolution {
            h += "/* The half-resolution frame (the manifest's half_resolution.half_names: w, h, g halved), whose inputs a\n";
            h += " * technique's constants functions take when it runs at half resolution. Returns 0, leaving *out as it\n";
            h +=
                " * was, where half resolution refuses the frame (W, H or g odd, or fewer than 2x2 pixels inside the\n";
            h += " * guard band). */\n";
            h += "static inline int aokit_half_frame_inputs(const aokit_frame_inputs *f, aokit_frame_inputs *out) {\n";
            h += "    uint32_t W = f->w + 2u * f->g, H = f->h + 2u * f->g;\n";
            h += "    if (W % 2u || H % 2u || f->g % 2u || f->w < 2u || f->h < 2u) return 0;\n";
            h += "    *out = *f;\n";
            h += &half_assignments(&half.half_names)?;
            h += "    return 1;\n}\n\n";
        }
        for t in &self.techniques {
            let source = Source { name: &t.name, summary: &t.summary, settings: &t.settings, constants: &t.constants };
            h += &technique(&source, self)?;
        }
        if let Some(a) = &self.adapters {
            let summary =
                "ImportParams, the push constants of the import_depth, import_normals and export_ao_* modules";
            let source = Source { name: "adapters", summary, settings: &a.settings, constants: &a.constants };
            h += &technique(&source, self)?;
        }
        if let Some(temporal) = &self.temporal {
            let summary = "TemporalFrame, the record of the temporal_blend and temporal_store modules";
            let source =
                Source { name: "temporal", summary, settings: &temporal.settings, constants: &temporal.constants };
            h += &technique(&source, self)?;
        }
        if let Some(half) = &self.half_resolution {
            let summary = "HalfParams, the push constants of the half_downsample and half_upsample modules";
            let source =
                Source { name: "half_resolution", summary, settings: &half.settings, constants: &half.constants };
            h += &technique(&source, self)?;
        }
        h += "#endif /* AOKIT_CONSTANTS_H */\n";
        Ok(h)
    }
}
