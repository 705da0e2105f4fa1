//! The constants' expressions (`techniques[].constants[].expr` of the manifest): a parser and an
//! evaluator of the grammar `assets/README.md` ("Expressions") defines. Engines that do not
//! link Rust evaluate the same text with their own evaluator (`assets/web/graph.js` is one);
//! this one checks every expression against the Rust builders (`tests/constant_expressions.rs`).
//!
//! Arithmetic follows the grammar's rules exactly: integers are exact, reals are IEEE-754
//! binary32 rounded after every operation, evaluated left to right as written; `sin`, `cos`,
//! `tan`, `pow` are computed in binary64 and rounded once to binary32.

use std::collections::HashMap;

/// A value: an exact integer, a binary32 real, a truth value, a choice's name, a vector of
/// reals or of integers (2–4 components), a 4×4 matrix of reals (column-major).
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Int(i64),
    Real(f32),
    Bool(bool),
    Text(String),
    Vector(Vec<f32>),
    IntVector(Vec<i64>),
    Matrix([f32; 16]),
}

/// What an expression may name: settings by key (in backticks), the frame's quantities by
/// name, and each choice setting's list of names (for `index`).
#[derive(Clone, Debug, Default)]
pub struct Inputs {
    pub settings: HashMap<String, Value>,
    pub choices: HashMap<String, Vec<String>>,
    pub names: HashMap<String, Value>,
}

/// Evaluate `text` with `inputs`.
pub fn eval(text: &str, inputs: &Inputs) -> Result<Value, String> {
    let tokens = tokenize(text)?;
    let mut p = Parser { tokens, at: 0, inputs, text };
    let v = p.expr()?;
    if p.at != p.tokens.len() {
        return Err(format!("'{text}': unexpected '{}'", p.tokens[p.at]));
    }
    Ok(v)
}

/// Check that `text` is an expression of the grammar (names and types are checked when it is
/// evaluated): every token known, parentheses balanced.
pub fn parse(text: &str) -> Result<(), String> {
    let tokens = tokenize(text)?;
    let mut depth = 0i32;
    for t in &tokens {
        depth += (t == "(") as i32 - (t == ")") as i32;
        if depth < 0 {
            return Err(format!("'{text}': unbalanced ')'"));
        }
    }
    if depth != 0 {
        return Err(format!("'{text}': unbalanced '('"));
    }
    Ok(())
}

/// The tokens of `text` (numbers, names, settings in backticks, quoted names, operators).
pub fn tokens(text: &str) -> Result<Vec<String>, String> {
    tokenize(text)
}

/// The setting keys `text` names (in backticks).
pub fn settings_named(text: &str) -> Vec<&str> {
    text.split('`').skip(1).step_by(2).collect()
}

fn tokenize(text: &str) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let start = i;
        if c.is_whitespace() {
            i += 1;
            continue;
        } else if c.is_ascii_digit() {
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            if i < chars.len() && chars[i] == 'e' {
                i += 1;
                if i < chars.len() && (chars[i] == '-' || chars[i] == '+') {
                    i += 1;
                }
                while i < chars.len() && chars[i].is_ascii_digit() {
                    i += 1;
                }
            }
        } else if c.is_alphabetic() || c == '_' {
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
        } else if c == '`' || c == '"' {
            i += 1;
            while i < chars.len() && chars[i] != c {
                i += 1;
            }
            if i == chars.len() {
                return Err(format!("'{text}': unclosed {c}"));
            }
            i += 1;
        } else if i + 1 < chars.len()
            && ["==", "!=", "<=", ">=", "&&", "||"].contains(&&*format!("{c}{}", chars[i + 1]))
        {
            i += 2;
        } else if "+-*/()<>,.!".contains(c) {
            i += 1;
        } else {
            return Err(format!("'{text}': unexpected character '{c}'"));
        }
        out.push(chars[start..i].iter().collect());
    }
    Ok(out)
}

struct Parser<'a> {
    tokens: Vec<String>,
    at: usize,
    inputs: &'a Inputs,
    text: &'a str,
}

fn real(v: &Value) -> Option<f32> {
    match *v {
        Value::Int(i) => Some(i as f32),
        Value::Real(r) => Some(r),
        _ => None,
    }
}

impl Parser<'_> {
    fn peek(&self) -> Option<&str> {
        self.tokens.get(self.at).map(String::as_str)
    }

    fn eat(&mut self, token: &str) -> bool {
        let hit = self.peek() == Some(token);
        self.at += hit as usize;
        hit
    }

    fn expect(&mut self, token: &str) -> Result<(), String> {
        if self.eat(token) { Ok(()) } else { Err(self.error(&format!("expected '{token}'"))) }
    }

    fn error(&self, what: &str) -> String {
        format!("'{}': {what} at token {}", self.text, self.at)
    }

    fn expr(&mut self) -> Result<Value, String> {
        let mut a = self.and()?;
        while self.eat("||") {
            let b = self.and()?;
            a = Value::Bool(self.truth(&a)? || self.truth(&b)?);
        }
        Ok(a)
    }

    fn and(&mut self) -> Result<Value, String> {
        let mut a = self.comparison()?;
        while self.eat("&&") {
            let b = self.comparison()?;
            a = Value::Bool(self.truth(&a)? && self.truth(&b)?);
        }
        Ok(a)
    }

    fn truth(&self, v: &Value) -> Result<bool, String> {
        match v {
            Value::Bool(b) => Ok(*b),
            _ => Err(self.error("expected a truth value")),
        }
    }

    fn comparison(&mut self) -> Result<Value, String> {
        let a = self.sum()?;
        let Some(op) = self.peek().filter(|t| ["==", "!=", "<", "<=", ">", ">="].contains(t)).map(String::from) else {
            return Ok(a);
        };
        self.at += 1;
        let b = self.sum()?;
        let ordering = match (&a, &b) {
            (Value::Int(x), Value::Int(y)) => x.partial_cmp(y),
            (Value::Text(x), Value::Text(y)) if op == "==" || op == "!=" => Some(x.cmp(y)),
            (Value::Bool(x), Value::Bool(y)) if op == "==" || op == "!=" => Some(x.cmp(y)),
            _ => match (real(&a), real(&b)) {
                (Some(x), Some(y)) => x.partial_cmp(&y),
                _ => return Err(self.error(&format!("cannot compare {a:?} {op} {b:?}"))),
            },
        };
        use std::cmp::Ordering::*;
        let r = match (op.as_str(), ordering) {
            ("==", o) => o == Some(Equal),
            ("!=", o) => o != Some(Equal),
            ("<", o) => o == Some(Less),
            ("<=", o) => matches!(o, Some(Less | Equal)),
            (">", o) => o == Some(Greater),
            (_, o) => matches!(o, Some(Greater | Equal)),
        };
        Ok(Value::Bool(r))
    }

    fn sum(&mut self) -> Result<Value, String> {
        let mut a = self.product()?;
        loop {
            let op = match self.peek() {
                Some(t @ ("+" | "-")) => t.to_string(),
                _ => return Ok(a),
            };
            self.at += 1;
            let b = self.product()?;
            a = self.arithmetic(&op, a, b)?;
        }
    }

    fn product(&mut self) -> Result<Value, String> {
        let mut a = self.unary()?;
        loop {
            let op = match self.peek() {
                Some(t @ ("*" | "/")) => t.to_string(),
                _ => return Ok(a),
            };
            self.at += 1;
            let b = self.unary()?;
            a = self.arithmetic(&op, a, b)?;
        }
    }

    /// `+ - * /` on integers (exact; `/` is binary32 division of the converted operands),
    /// reals and vectors of reals (componentwise, a scalar applied to every component).
    fn arithmetic(&self, op: &str, a: Value, b: Value) -> Result<Value, String> {
        let f = |x: f32, y: f32| match op {
            "+" => x + y,
            "-" => x - y,
            "*" => x * y,
            _ => x / y,
        };
        Ok(match (&a, &b) {
            (Value::Int(x), Value::Int(y)) if op != "/" => Value::Int(match op {
                "+" => x + y,
                "-" => x - y,
                _ => x * y,
            }),
            (Value::Vector(x), Value::Vector(y)) if x.len() == y.len() => {
                Value::Vector(x.iter().zip(y).map(|(x, y)| f(*x, *y)).collect())
            }
            (Value::Vector(x), s) if real(s).is_some() => {
                let s = real(s).unwrap_or_default();
                Value::Vector(x.iter().map(|x| f(*x, s)).collect())
            }
            _ => match (real(&a), real(&b)) {
                (Some(x), Some(y)) => Value::Real(f(x, y)),
                _ => return Err(self.error(&format!("cannot compute {a:?} {op} {b:?}"))),
            },
        })
    }

    fn unary(&mut self) -> Result<Value, String> {
        if self.eat("-") {
            return match self.unary()? {
                Value::Int(i) => Ok(Value::Int(-i)),
                Value::Real(r) => Ok(Value::Real(-r)),
                Value::Vector(v) => Ok(Value::Vector(v.iter().map(|x| -x).collect())),
                v => Err(self.error(&format!("cannot negate {v:?}"))),
            };
        }
        if self.eat("!") {
            let v = self.unary()?;
            return Ok(Value::Bool(!self.truth(&v)?));
        }
        let mut v = self.primary()?;
        while self.eat(".") {
            let name = self.peek().unwrap_or_default().to_string();
            self.at += 1;
            let i = ["x", "y", "z", "w"]
                .iter()
                .position(|c| *c == name)
                .ok_or_else(|| self.error("expected x, y, z or w"))?;
            v = match v {
                Value::Vector(c) if i < c.len() => Value::Real(c[i]),
                Value::IntVector(c) if i < c.len() => Value::Int(c[i]),
                v => return Err(self.error(&format!("{v:?} has no component {name}"))),
            };
        }
        Ok(v)
    }

    fn primary(&mut self) -> Result<Value, String> {
        let token = self.peek().ok_or_else(|| self.error("unexpected end"))?.to_string();
        self.at += 1;
        if token == "(" {
            let v = self.expr()?;
            self.expect(")")?;
            return Ok(v);
        }
        if let Some(key) = token.strip_prefix('`').and_then(|t| t.strip_suffix('`')) {
            return self.inputs.settings.get(key).cloned().ok_or_else(|| self.error(&format!("no setting `{key}`")));
        }
        if let Some(text) = token.strip_prefix('"').and_then(|t| t.strip_suffix('"')) {
            return Ok(Value::Text(text.into()));
        }
        if token.starts_with(|c: char| c.is_ascii_digit()) {
            return if token.contains(['.', 'e']) {
                token.parse::<f32>().map(Value::Real).map_err(|_| self.error("bad number"))
            } else {
                token.parse::<i64>().map(Value::Int).map_err(|_| self.error("bad number"))
            };
        }
        match token.as_str() {
            "true" => return Ok(Value::Bool(true)),
            "false" => return Ok(Value::Bool(false)),
            _ => {}
        }
        if self.peek() == Some("(") {
            return self.call(&token);
        }
        self.inputs.names.get(&token).cloned().ok_or_else(|| self.error(&format!("unknown name '{token}'")))
    }

    fn call(&mut self, name: &str) -> Result<Value, String> {
        self.expect("(")?;
        // `index(`key`)`: the position of the choice's value in its list of names.
        if name == "index" {
            let token = self.peek().unwrap_or_default().to_string();
            let key = token
                .strip_prefix('`')
                .and_then(|t| t.strip_suffix('`'))
                .ok_or_else(|| self.error("index takes a setting"))?;
            self.at += 1;
            self.expect(")")?;
            let value = self.inputs.settings.get(key).ok_or_else(|| self.error(&format!("no setting `{key}`")))?;
            let names = self.inputs.choices.get(key).ok_or_else(|| self.error(&format!("`{key}` is not a choice")))?;
            let Value::Text(value) = value else { return Err(self.error("a choice's value is a name")) };
            let i = names.iter().position(|n| n == value).ok_or_else(|| self.error("value not among the choices"))?;
            return Ok(Value::Int(i as i64));
        }
        let mut args = Vec::new();
        if !self.eat(")") {
            loop {
                args.push(self.expr()?);
                if self.eat(")") {
                    break;
                }
                self.expect(",")?;
            }
        }
        self.builtin(name, args)
    }

    fn builtin(&self, name: &str, args: Vec<Value>) -> Result<Value, String> {
        let bad = || self.error(&format!("{name}: bad arguments {args:?}"));
        let reals = || args.iter().map(real).collect::<Option<Vec<f32>>>().ok_or_else(bad);
        let vector = |v: &Value| match v {
            Value::Vector(c) if c.len() == 3 => Ok([c[0], c[1], c[2]]),
            _ => Err(bad()),
        };
        let wide = |f: fn(f64) -> f64| -> Result<Value, String> {
            let [x] = reals()?[..] else { return Err(bad()) };
            Ok(Value::Real(f(x as f64) as f32))
        };
        Ok(match (name, args.as_slice()) {
            ("select", [c, a, b]) => {
                if self.truth(c)? {
                    a.clone()
                } else {
                    b.clone()
                }
            }
            // `pick(i, v0, v1, …)`: the i-th of the values (a choice table).
            ("pick", [Value::Int(i), rest @ ..]) if (0..rest.len() as i64).contains(i) => rest[*i as usize].clone(),
            ("f32", [v]) => Value::Real(real(v).ok_or_else(bad)?),
            ("u32", [Value::Bool(b)]) => Value::Int(*b as i64),
            ("u32", [v]) => Value::Int(real(v).ok_or_else(bad)? as u32 as i64),
            ("div_ceil", [Value::Int(a), Value::Int(b)]) if *b > 0 => {
                Value::Int(a.div_euclid(*b) + (a.rem_euclid(*b) != 0) as i64)
            }
            ("div_floor", [Value::Int(a), Value::Int(b)]) if *b > 0 => Value::Int(a.div_euclid(*b)),
            ("min" | "max", [Value::Int(a), Value::Int(b)]) => {
                Value::Int(if name == "min" { *a.min(b) } else { *a.max(b) })
            }
            ("min" | "max", [_, _]) => {
                let [a, b] = reals()?[..] else { return Err(bad()) };
                Value::Real(if name == "min" { a.min(b) } else { a.max(b) })
            }
            ("floor" | "ceil", [Value::Int(i)]) => Value::Int(*i),
            ("floor", [_]) => Value::Real(reals()?[0].floor()),
            ("ceil", [_]) => Value::Real(reals()?[0].ceil()),
            ("sqrt", [_]) => Value::Real(reals()?[0].sqrt()),
            ("sin", [_]) => wide(f64::sin)?,
            ("cos", [_]) => wide(f64::cos)?,
            ("tan", [_]) => wide(f64::tan)?,
            ("pow", [_, _]) => {
                let [a, b] = reals()?[..] else { return Err(bad()) };
                Value::Real((a as f64).powf(b as f64) as f32)
            }
            ("vec2" | "vec3" | "vec4", _) if args.len() == name[3..].parse::<usize>().unwrap_or(0) => {
                Value::Vector(reals()?)
            }
            ("uvec2", [Value::Int(a), Value::Int(b)]) => Value::IntVector(vec![*a, *b]),
            ("normalize", [v]) => Value::Vector(normalize(vector(v)?).to_vec()),
            ("cross", [a, b]) => Value::Vector(cross(vector(a)?, vector(b)?).to_vec()),
            ("look_at", [eye, target, up]) => Value::Matrix(look_at(vector(eye)?, vector(target)?, vector(up)?)),
            ("inverse_rigid", [Value::Matrix(m)]) => Value::Matrix(inverse_rigid(m)),
            _ => return Err(bad()),
        })
    }
}

/// `dot(a, b) = (a.x·b.x + a.y·b.y) + a.z·b.z`.
fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `normalize(v) = v · (1 / sqrt(dot(v, v)))`.
fn normalize(v: [f32; 3]) -> [f32; 3] {
    let r = 1.0 / dot(v, v).sqrt();
    [v[0] * r, v[1] * r, v[2] * r]
}

/// `cross(a, b) = (a.y·b.z − b.y·a.z, a.z·b.x − b.z·a.x, a.x·b.y − b.x·a.y)`.
fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]]
}

/// `look_at(E, T, U)`: view → world, columns `(r, 0), (u, 0), (−d, 0), (E, 1)` with
/// `d = normalize(T − E)`, `r = normalize(cross(d, U))`, `u = cross(r, d)`.
fn look_at(eye: [f32; 3], target: [f32; 3], up: [f32; 3]) -> [f32; 16] {
    let d = normalize([target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]]);
    let r = normalize(cross(d, up));
    let u = cross(r, d);
    [r[0], r[1], r[2], 0.0, u[0], u[1], u[2], 0.0, -d[0], -d[1], -d[2], 0.0, eye[0], eye[1], eye[2], 1.0]
}

/// `inverse_rigid(M)` of `M = [R | t]` (columns `c0, c1, c2` of R, translation t): columns
/// `(c0.x, c1.x, c2.x, 0), (c0.y, c1.y, c2.y, 0), (c0.z, c1.z, c2.z, 0), (−dot(c0, t), −dot(c1, t), −dot(c2, t), 1)`.
fn inverse_rigid(m: &[f32; 16]) -> [f32; 16] {
    let c = |i: usize| [m[4 * i], m[4 * i + 1], m[4 * i + 2]];
    let t = c(3);
    let (c0, c1, c2) = (c(0), c(1), c(2));
    [
        c0[0],
        c1[0],
        c2[0],
        0.0,
        c0[1],
        c1[1],
        c2[1],
        0.0,
        c0[2],
        c1[2],
        c2[2],
        0.0,
        -dot(c0, t),
        -dot(c1, t),
        -dot(c2, t),
        1.0,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inputs() -> Inputs {
        let mut i = Inputs::default();
        i.settings.insert("kernel".into(), Value::Text("hbao".into()));
        i.choices.insert("kernel".into(), vec!["vao".into(), "hbao".into()]);
        i.settings.insert("sd-res".into(), Value::Int(4));
        i.names.insert("W".into(), Value::Int(2048));
        i.names.insert("radius".into(), Value::Real(0.5));
        i
    }

    #[test]
    fn grammar() {
        let i = inputs();
        let e = |t: &str| eval(t, &i).unwrap();
        assert_eq!(e("radius * select(`kernel` == \"hbao\", 1.5, 1)"), Value::Real(0.75));
        assert_eq!(e("index(`kernel`)"), Value::Int(1));
        assert_eq!(e("div_ceil(W, 3) + 1"), Value::Int(684));
        assert_eq!(e("W / 3"), Value::Real(2048.0f32 / 3.0));
        assert_eq!(e("u32(`sd-res` > 2 && !(W < 10))"), Value::Int(1));
        assert_eq!(e("vec2(1, 2).y * -2"), Value::Real(-4.0));
        assert!(eval("radius +", &i).is_err());
        assert!(eval("`primary`", &i).is_err());
        assert!(eval("nope(1)", &i).is_err());
    }
}
