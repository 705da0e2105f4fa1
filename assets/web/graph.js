// aokit's contract in the browser: the manifest's graphs and struct layouts, every constants
// struct computed from the manifest's expressions, and a technique's pass graph run through
// WebGPU from the WGSL files. Nothing here names a technique.
// Plain ES module, no build step, no dependencies. Formats: assets/README.md, docs/web.md.

// ---------------------------------------------------------------------------------------------
// Structs: the manifest's `structs` (size, field offsets, Rust types) read and written with a
// DataView, little-endian. Fields named `_…` are padding (written 0).

const VECTORS = { Vec2: ['f32', 2], Vec3: ['f32', 3], Vec4: ['f32', 4], UVec2: ['u32', 2], UVec3: ['u32', 3],
  UVec4: ['u32', 4], IVec2: ['i32', 2], IVec3: ['i32', 3], IVec4: ['i32', 4], Mat4: ['f32', 16] };

function scalar(dv, offset, ty, value, write) {
  switch (ty) {
    case 'f32': return write ? dv.setFloat32(offset, value, true) : dv.getFloat32(offset, true);
    case 'u32': return write ? dv.setUint32(offset, value >>> 0, true) : dv.getUint32(offset, true);
    case 'i32': return write ? dv.setInt32(offset, value | 0, true) : dv.getInt32(offset, true);
    default: throw new Error(`not a scalar type: ${ty}`);
  }
}

export function structOf(manifest, name) {
  const s = manifest.structs.find((s) => s.name === name);
  if (!s) throw new Error(`struct ${name} is not in the manifest`);
  return s;
}

function fieldIo(manifest, dv, offset, ty, size, value, write) {
  if (ty in VECTORS) {
    const [t, n] = VECTORS[ty];
    if (write && (!Array.isArray(value) && !ArrayBuffer.isView(value) || value.length !== n)) {
      throw new Error(`${ty} takes ${n} components`);
    }
    const out = [];
    for (let k = 0; k < n; k++) out.push(scalar(dv, offset + 4 * k, t, write ? value[k] : 0, write));
    return out;
  }
  const array = /^\[(\w+); *(\d+)\]$/.exec(ty);
  if (array) {
    const n = Number(array[2]);
    const step = size / n;
    const out = [];
    for (let k = 0; k < n; k++) {
      out.push(fieldIo(manifest, dv, offset + k * step, array[1], step, write ? value[k] : 0, write));
    }
    return out;
  }
  if (ty === 'f32' || ty === 'u32' || ty === 'i32') return scalar(dv, offset, ty, value, write);
  // Another struct: its bytes (Uint8Array) or its fields.
  const s = structOf(manifest, ty);
  if (!write) return readStruct(manifest, ty, new Uint8Array(dv.buffer, dv.byteOffset + offset, s.size));
  const bytes = value instanceof Uint8Array ? value : writeStruct(manifest, ty, value);
  if (bytes.length !== s.size) throw new Error(`${ty}: ${bytes.length} bytes for a ${s.size}-byte struct`);
  new Uint8Array(dv.buffer, dv.byteOffset + offset, s.size).set(bytes);
  return undefined;
}

/** The bytes of struct `name` with `values` (every field but padding must be given). */
export function writeStruct(manifest, name, values) {
  const s = structOf(manifest, name);
  const bytes = new Uint8Array(s.size);
  const dv = new DataView(bytes.buffer);
  for (const key of Object.keys(values)) {
    if (!s.fields.some((f) => f.name === key)) throw new Error(`${name} has no field '${key}'`);
  }
  for (const f of s.fields) {
    const v = values[f.name];
    if (v === undefined) {
      if (f.name.startsWith('_')) continue;
      throw new Error(`${name}.${f.name}: no value`);
    }
    fieldIo(manifest, dv, f.offset, f.ty, f.size, v, true);
  }
  return bytes;
}

/** Struct `name` read from `bytes`: {field: number | array | nested object}. */
export function readStruct(manifest, name, bytes) {
  const s = structOf(manifest, name);
  const dv = new DataView(bytes.buffer, bytes.byteOffset, s.size);
  const out = {};
  for (const f of s.fields) out[f.name] = fieldIo(manifest, dv, f.offset, f.ty, f.size, undefined, false);
  return out;
}

/** The bytes of field `field` of struct `name` within `bytes`. */
export function fieldBytes(manifest, name, field, bytes) {
  const f = structOf(manifest, name).fields.find((f) => f.name === field);
  if (!f) throw new Error(`${name} has no field ${field}`);
  return bytes.slice(f.offset, f.offset + f.size);
}

// ---------------------------------------------------------------------------------------------
// Expressions: the grammar of the constants (`techniques[].constants[].expr`, assets/README.md,
// "Expressions"). Integers exact; reals binary32, rounded (Math.fround) after every operation,
// left to right; sin, cos, tan, pow in binary64 rounded once. Values are {t, v}: t = 'int',
// 'real', 'bool', 'text', 'vec' (reals), 'ivec' (integers) or 'mat' (16 reals, column-major).

const fr = Math.fround;
const EXPR_TOKEN = /\s*(\d+(?:\.\d*)?(?:e[+-]?\d+)?|[A-Za-z_]\w*|`[^`]*`|"[^"]*"|==|!=|<=|>=|&&|\|\||[+\-*/()<>,.!])/y;

const isNum = (x) => x.t === 'int' || x.t === 'real';
const realOf = (x) => {
  if (!isNum(x)) throw new Error(`expected a number, got ${x.t}`);
  return fr(x.v);
};
const vec3Of = (x) => {
  if (x.t !== 'vec' || x.v.length !== 3) throw new Error(`expected a vec3, got ${x.t}`);
  return x.v;
};
const dot3 = (a, b) => fr(fr(fr(a[0] * b[0]) + fr(a[1] * b[1])) + fr(a[2] * b[2]));
const normalize3 = (v) => {
  const r = fr(1 / fr(Math.sqrt(dot3(v, v))));
  return v.map((c) => fr(c * r));
};
const cross3 = (a, b) => [
  fr(fr(a[1] * b[2]) - fr(b[1] * a[2])),
  fr(fr(a[2] * b[0]) - fr(b[2] * a[0])),
  fr(fr(a[0] * b[1]) - fr(b[0] * a[1])),
];
function lookAt(eye, target, up) {
  const d = normalize3([fr(target[0] - eye[0]), fr(target[1] - eye[1]), fr(target[2] - eye[2])]);
  const r = normalize3(cross3(d, up));
  const u = cross3(r, d);
  return [r[0], r[1], r[2], 0, u[0], u[1], u[2], 0, -d[0], -d[1], -d[2], 0, eye[0], eye[1], eye[2], 1];
}
function inverseRigid(m) {
  const c = (i) => [m[4 * i], m[4 * i + 1], m[4 * i + 2]];
  const [c0, c1, c2, t] = [c(0), c(1), c(2), c(3)];
  return [c0[0], c1[0], c2[0], 0, c0[1], c1[1], c2[1], 0, c0[2], c1[2], c2[2], 0, -dot3(c0, t), -dot3(c1, t), -dot3(c2, t), 1];
}

const BUILTINS = {
  select: (c, a, b) => {
    if (c.t !== 'bool') throw new Error('select: the condition is not a truth value');
    return c.v ? a : b;
  },
  pick: (i, ...values) => {
    if (i.t !== 'int' || i.v < 0 || i.v >= values.length) throw new Error('pick: index out of range');
    return values[i.v];
  },
  f32: (x) => ({ t: 'real', v: realOf(x) }),
  u32: (x) => ({ t: 'int', v: x.t === 'bool' ? Number(x.v) : Math.min(4294967295, Math.max(0, Math.trunc(realOf(x)))) }),
  div_ceil: (a, b) => ({ t: 'int', v: Math.ceil(a.v / b.v) }),
  div_floor: (a, b) => ({ t: 'int', v: Math.floor(a.v / b.v) }),
  min: (a, b) => (a.t === 'int' && b.t === 'int' ? { t: 'int', v: Math.min(a.v, b.v) } : { t: 'real', v: Math.min(realOf(a), realOf(b)) }),
  max: (a, b) => (a.t === 'int' && b.t === 'int' ? { t: 'int', v: Math.max(a.v, b.v) } : { t: 'real', v: Math.max(realOf(a), realOf(b)) }),
  floor: (x) => (x.t === 'int' ? x : { t: 'real', v: Math.floor(realOf(x)) }),
  ceil: (x) => (x.t === 'int' ? x : { t: 'real', v: Math.ceil(realOf(x)) }),
  sqrt: (x) => ({ t: 'real', v: fr(Math.sqrt(realOf(x))) }),
  sin: (x) => ({ t: 'real', v: fr(Math.sin(realOf(x))) }),
  cos: (x) => ({ t: 'real', v: fr(Math.cos(realOf(x))) }),
  tan: (x) => ({ t: 'real', v: fr(Math.tan(realOf(x))) }),
  pow: (a, b) => ({ t: 'real', v: fr(Math.pow(realOf(a), realOf(b))) }),
  vec2: (...a) => ({ t: 'vec', v: a.map(realOf) }),
  vec3: (...a) => ({ t: 'vec', v: a.map(realOf) }),
  vec4: (...a) => ({ t: 'vec', v: a.map(realOf) }),
  uvec2: (a, b) => ({ t: 'ivec', v: [a.v, b.v] }),
  normalize: (v) => ({ t: 'vec', v: normalize3(vec3Of(v)) }),
  cross: (a, b) => ({ t: 'vec', v: cross3(vec3Of(a), vec3Of(b)) }),
  look_at: (e, t, u) => ({ t: 'mat', v: lookAt(vec3Of(e), vec3Of(t), vec3Of(u)) }),
  inverse_rigid: (m) => ({ t: 'mat', v: inverseRigid(m.v) }),
};

function arithmetic(op, a, b) {
  const f = (x, y) => fr(op === '+' ? x + y : op === '-' ? x - y : op === '*' ? x * y : x / y);
  if (a.t === 'int' && b.t === 'int' && op !== '/') return { t: 'int', v: op === '+' ? a.v + b.v : op === '-' ? a.v - b.v : a.v * b.v };
  if (a.t === 'vec' && b.t === 'vec' && a.v.length === b.v.length) return { t: 'vec', v: a.v.map((x, k) => f(x, b.v[k])) };
  if (a.t === 'vec' && isNum(b)) return { t: 'vec', v: a.v.map((x) => f(x, realOf(b))) };
  return { t: 'real', v: f(realOf(a), realOf(b)) };
}

/**
 * Evaluate expression `text`. `inputs`: {settings: key → value ({t, v}), choices: key → [names],
 * names: name → value} (W, H, w, h, g, eye, target, up, fov_y, near, far, radius, exponent,
 * thickness, frame, pass).
 */
export function evalExpr(text, inputs) {
  const t = [];
  EXPR_TOKEN.lastIndex = 0;
  while (EXPR_TOKEN.lastIndex < text.length) {
    if (/^\s*$/.test(text.slice(EXPR_TOKEN.lastIndex))) break;
    const at = EXPR_TOKEN.lastIndex;
    const m = EXPR_TOKEN.exec(text);
    if (!m) throw new Error(`expression '${text}': cannot read at ${at}`);
    t.push(m[1]);
  }
  let i = 0;
  const fail = (what) => new Error(`expression '${text}': ${what}`);
  const eat = (tok) => (t[i] === tok ? (i++, true) : false);
  const expect = (tok) => {
    if (!eat(tok)) throw fail(`expected '${tok}' at token ${i}`);
  };
  const truth = (v) => {
    if (v.t !== 'bool') throw fail('expected a truth value');
    return v.v;
  };
  const or = () => {
    let a = and();
    while (eat('||')) {
      const b = and();
      a = { t: 'bool', v: truth(a) || truth(b) };
    }
    return a;
  };
  const and = () => {
    let a = comparison();
    while (eat('&&')) {
      const b = comparison();
      a = { t: 'bool', v: truth(a) && truth(b) };
    }
    return a;
  };
  const comparison = () => {
    const a = sum();
    const op = t[i];
    if (!['==', '!=', '<', '<=', '>', '>='].includes(op)) return a;
    i++;
    const b = sum();
    let x;
    let y;
    if (a.t === 'int' && b.t === 'int') [x, y] = [a.v, b.v];
    else if ((a.t === 'text' && b.t === 'text') || (a.t === 'bool' && b.t === 'bool')) {
      if (op !== '==' && op !== '!=') throw fail(`cannot order ${a.t}s`);
      [x, y] = [a.v, b.v];
    } else [x, y] = [realOf(a), realOf(b)];
    const r = { '==': x === y, '!=': x !== y, '<': x < y, '<=': x <= y, '>': x > y, '>=': x >= y }[op];
    return { t: 'bool', v: r };
  };
  const sum = () => {
    let a = product();
    while (t[i] === '+' || t[i] === '-') {
      const op = t[i++];
      a = arithmetic(op, a, product());
    }
    return a;
  };
  const product = () => {
    let a = unary();
    while (t[i] === '*' || t[i] === '/') {
      const op = t[i++];
      a = arithmetic(op, a, unary());
    }
    return a;
  };
  const unary = () => {
    if (eat('-')) {
      const v = unary();
      if (v.t === 'int' || v.t === 'real') return { t: v.t, v: -v.v };
      if (v.t === 'vec') return { t: 'vec', v: v.v.map((x) => -x) };
      throw fail(`cannot negate a ${v.t}`);
    }
    if (eat('!')) return { t: 'bool', v: !truth(unary()) };
    let v = primary();
    while (eat('.')) {
      const k = 'xyzw'.indexOf(t[i++]);
      if (k < 0 || !(v.t === 'vec' || v.t === 'ivec') || k >= v.v.length) throw fail('bad component');
      v = { t: v.t === 'vec' ? 'real' : 'int', v: v.v[k] };
    }
    return v;
  };
  const primary = () => {
    const tok = t[i++];
    if (tok === undefined) throw fail('unexpected end');
    if (tok === '(') {
      const v = or();
      expect(')');
      return v;
    }
    if (tok.startsWith('`')) {
      const key = tok.slice(1, -1);
      if (!(key in inputs.settings)) throw fail(`no setting \`${key}\``);
      return inputs.settings[key];
    }
    if (tok.startsWith('"')) return { t: 'text', v: tok.slice(1, -1) };
    if (/^\d/.test(tok)) return /[.e]/.test(tok) ? { t: 'real', v: fr(Number(tok)) } : { t: 'int', v: Number(tok) };
    if (tok === 'true' || tok === 'false') return { t: 'bool', v: tok === 'true' };
    if (t[i] === '(') {
      expect('(');
      if (tok === 'index') {
        const key = (t[i++] ?? '').slice(1, -1);
        expect(')');
        const value = inputs.settings[key];
        const names = inputs.choices[key];
        if (!value || !names) throw fail(`index: \`${key}\` is not a choice setting`);
        return { t: 'int', v: names.indexOf(value.v) };
      }
      const args = [];
      if (!eat(')')) {
        do args.push(or()); while (eat(','));
        expect(')');
      }
      if (!(tok in BUILTINS)) throw fail(`unknown function ${tok}`);
      return BUILTINS[tok](...args);
    }
    if (tok in inputs.names) return inputs.names[tok];
    throw fail(`unknown name '${tok}'`);
  };
  const v = or();
  if (i !== t.length) throw fail(`trailing '${t[i]}'`);
  return v;
}

/** The value of a setting as an expression reads it: counts integers, numbers binary32, choices names. */
export function settingValue(row, text) {
  if (row.kind === 'count') return { t: 'int', v: Number(text) };
  if (row.kind === 'number') return { t: 'real', v: fr(Number(text)) };
  return { t: 'text', v: String(text) };
}

/**
 * The inputs of technique `t`'s expressions (manifest entry) with `settings` (key → string) and
 * `frame` = {eye, target, up, fov_y (radians), near, far, inner: [w, h], guard, radius, exponent,
 * thickness, frame_index}.
 */
export function expressionInputs(t, settings, frame) {
  const out = { settings: {}, choices: {}, names: {} };
  for (const row of t.settings) {
    out.settings[row.key] = settingValue(row, settings[row.key] ?? row.default);
    if (row.kind === 'choice') out.choices[row.key] = row.choices;
  }
  const [w, h] = frame.inner;
  const g = frame.guard;
  const vec = (v) => ({ t: 'vec', v: v.map(fr) });
  const real = (v) => ({ t: 'real', v: fr(v) });
  Object.assign(out.names, {
    W: { t: 'int', v: w + 2 * g }, H: { t: 'int', v: h + 2 * g }, w: { t: 'int', v: w }, h: { t: 'int', v: h }, g: { t: 'int', v: g },
    eye: vec(frame.eye), target: vec(frame.target), up: vec(frame.up), fov_y: real(frame.fov_y), near: real(frame.near),
    far: real(frame.far), radius: real(frame.radius), exponent: real(frame.exponent), thickness: real(frame.thickness),
    frame: { t: 'int', v: frame.frame_index ?? 0 },
  });
  return out;
}

/** The bytes of struct `name` from technique `t`'s constants (its `expr` per field) for `inputs`
 *  (with `names.pass` set for the pass). */
export function constantBytes(manifest, t, name, inputs) {
  const s = structOf(manifest, name);
  const bytes = new Uint8Array(s.size);
  const dv = new DataView(bytes.buffer);
  for (const f of s.fields) {
    const c = t.constants.find((c) => c.struct === name && c.field === f.name);
    if (!c) throw new Error(`${t.name}: no constant ${name}.${f.name}`);
    if (manifest.structs.some((x) => x.name === f.ty)) {
      bytes.set(constantBytes(manifest, t, f.ty, inputs), f.offset);
      continue;
    }
    const v = evalExpr(c.expr, inputs);
    const put = (k, ty, x) => {
      if (ty === 'f32') dv.setFloat32(f.offset + 4 * k, x, true);
      else if (ty === 'i32') dv.setInt32(f.offset + 4 * k, x, true);
      else dv.setUint32(f.offset + 4 * k, x, true);
    };
    const want = { f32: ['real', 1], u32: ['int', 1], i32: ['int', 1], Vec2: ['vec', 2], Vec3: ['vec', 3], Vec4: ['vec', 4], UVec2: ['ivec', 2], Mat4: ['mat', 16] }[f.ty];
    if (!want) throw new Error(`${name}.${f.name}: type ${f.ty} is not in the grammar`);
    const [kind, n] = want;
    const scalarTy = f.ty === 'i32' ? 'i32' : f.ty === 'u32' || f.ty === 'UVec2' ? 'u32' : 'f32';
    if (n === 1) {
      let x;
      if (kind === 'real') x = realOf(v);
      else if (v.t === 'int') x = v.v;
      else if (v.t === 'bool') x = Number(v.v);
      else throw new Error(`${name}.${f.name}: ${f.ty} from a ${v.t} (${c.expr})`);
      put(0, scalarTy, x);
    } else {
      if (v.t !== kind || v.v.length !== n) throw new Error(`${name}.${f.name}: ${f.ty} from a ${v.t} (${c.expr})`);
      v.v.forEach((x, k) => put(k, scalarTy, x));
    }
  }
  return bytes;
}

// ---------------------------------------------------------------------------------------------
// Graphs and data for any settings: the technique's variant whose `when` holds the settings'
// structural values, and the words of its `data` resources (records from the constants, tables
// from the manifest's `tables`).

/** Whether two setting values are the same (numbers compared as numbers). */
export function sameValue(row, a, b) {
  return row.kind === 'choice' ? a === b : Number(a) === Number(b);
}

/** The graph of technique `t` (manifest entry) for `settings` (key → string). */
export function variantOf(t, settings) {
  const rows = (key) => t.settings.find((s) => s.key === key);
  const v = t.variants.find((v) => v.when.some((w) => Object.entries(w).every(([k, x]) => sameValue(rows(k), settings[k], x))));
  if (!v) throw new Error(`${t.name}: no graph in the manifest for these settings`);
  return v;
}

/** The words of every `data` resource of `graph`. */
export function dataOf(manifest, t, graph, inputs) {
  const out = {};
  for (const r of graph.resources.filter((r) => r.init === 'data')) {
    const c = r.contents ?? {};
    if (c.record) {
      inputs.names.pass = { t: 'int', v: 0 };
      const bytes = constantBytes(manifest, t, c.record, inputs);
      out[r.name] = new Uint32Array(bytes.buffer);
      continue;
    }
    const name = evalExpr(c.table, inputs);
    const table = manifest.tables.find((x) => x.name === name.v);
    if (!table) throw new Error(`${r.name}: no table ${name.v}`);
    const per = { Vec2: 2, Vec3: 3, Vec4: 4 }[table.elem] ?? 1;
    const first = c.first ? evalExpr(c.first, inputs).v : 0;
    const n = evalExpr(c.count, inputs).v;
    const values = table.values.slice(first * per, (first + n) * per);
    if (values.length !== n * per) throw new Error(`${r.name}: elements ${first}…${first + n} are outside table ${table.name}`);
    out[r.name] = new Uint32Array(Float32Array.from(values).buffer);
  }
  return out;
}

/** Why the browser cannot run `graph`, or null: every pass a compute module with WGSL, and
 *  no input but the exported depth and normals. */
export function unsupported(manifest, graph) {
  for (const p of graph.passes) {
    if (p.kind !== 'compute') return `pass '${p.label}' (${p.entry}) is not a compute pass`;
    if (!manifest.modules.find((m) => m.entry_point === p.entry)?.wgsl) return `module ${p.entry} has no WGSL`;
  }
  const other = graph.inputs.find((i) => i !== 'linear_depth' && i !== 'view_normals');
  return other ? `reads input '${other}', which the export does not provide to the page` : null;
}

// ---------------------------------------------------------------------------------------------
// The runner: a graph (the manifest's technique format) through WebGPU.

/** The compute entry point of a WGSL module: the manifest names the SPIR-V entry point, which
 *  naga renames in WGSL when it ends in a digit (`svao_pass1` → `svao_pass1_`); each module has
 *  exactly one. */
export function wgslEntryPoint(code, entry) {
  const names = [...code.matchAll(/@compute\s+@workgroup_size\([^)]*\)\s*fn\s+(\w+)/g)].map((m) => m[1]);
  if (names.includes(entry)) return entry;
  if (names.length === 1) return names[0];
  throw new Error(`the WGSL of ${entry} has compute entry points ${names.join(', ') || '(none)'}`);
}

const STORAGE = () => GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST;

export class Runner {
  /** `base`: URL of the folder holding the WGSL files. */
  constructor(device, manifest, base) {
    this.device = device;
    this.manifest = manifest;
    this.base = base;
    this.shaders = new Map();
    this.pipelines = new Map();
    this.inputs = new Map();
  }

  /** An input buffer (linear_depth, view_normals) from its words. */
  setInput(name, words) {
    const buffer = this.device.createBuffer({ label: name, size: Math.max(4, words.byteLength), usage: STORAGE() });
    this.device.queue.writeBuffer(buffer, 0, words);
    this.inputs.set(name, buffer);
  }

  module(entry) {
    const m = this.manifest.modules.find((m) => m.entry_point === entry);
    if (!m) throw new Error(`module ${entry} is not in the manifest`);
    if (!m.wgsl) throw new Error(`module ${entry} has no WGSL`);
    return m;
  }

  async pipeline(entry) {
    if (this.pipelines.has(entry)) return this.pipelines.get(entry);
    const m = this.module(entry);
    let shader = this.shaders.get(m.wgsl.file);
    if (!shader) {
      const code = await (await fetch(new URL(m.wgsl.file, this.base))).text();
      shader = this.device.createShaderModule({ label: m.wgsl.file, code });
      const errors = (await shader.getCompilationInfo()).messages.filter((msg) => msg.type === 'error');
      if (errors.length) {
        throw new Error(`${m.wgsl.file} does not compile here: ${errors.map((e) => `${e.lineNum}:${e.linePos} ${e.message}`).join('; ')}`);
      }
      shader.aokitCode = code;
      this.shaders.set(m.wgsl.file, shader);
    }
    const entryPoint = m.wgsl.entry_point ?? wgslEntryPoint(shader.aokitCode, entry);
    const p = this.device.createComputePipelineAsync({ label: entry, layout: 'auto', compute: { module: shader, entryPoint } });
    this.pipelines.set(entry, p);
    return p;
  }

  /**
   * Run `graph` once. `inputs`: the expressions' inputs (`expressionInputs`); `data`: resource
   * name → Uint32Array for resources initialised with data; `constants(pass, index,
   * occurrence)`: the bytes of the module's push-constant struct. Returns {output: Float32Array
   * of the full target, constants: [{entry, bytes}], ms}.
   */
  async run(graph, inputs, data, constants) {
    const device = this.device;
    // Sizes and dispatches: integer expressions of the target and the settings.
    const count = (text) => {
      const v = evalExpr(text, inputs);
      if (v.t !== 'int') throw new Error(`'${text}' is not a whole number`);
      return v.v;
    };
    device.pushErrorScope('validation');
    device.pushErrorScope('out-of-memory');
    const t0 = performance.now();
    const buffers = new Map(this.inputs);
    const owned = [];
    for (const r of graph.resources) {
      let len = count(r.size);
      const words = r.init === 'data' ? data[r.name] : undefined;
      if (r.init === 'data' && !words) throw new Error(`no data for resource ${r.name}`);
      if (words) len = Math.max(len, words.length);
      const buffer = device.createBuffer({ label: r.name, size: Math.max(4, 4 * len), usage: STORAGE(), mappedAtCreation: r.init !== 'undefined' });
      if (r.init !== 'undefined') {
        const view = new Uint32Array(buffer.getMappedRange());
        const fill = /^fill (0x[0-9a-f]+)$/i.exec(r.init);
        if (fill) view.fill(Number(fill[1]));
        else if (words) view.set(words);
        else throw new Error(`resource ${r.name}: unknown init '${r.init}'`);
        buffer.unmap();
      }
      buffers.set(r.name, buffer);
      owned.push(buffer);
    }
    const encoder = device.createCommandEncoder({ label: 'aokit graph' });
    const seen = new Map();
    const written = [];
    for (const [index, pass] of graph.passes.entries()) {
      if (pass.kind !== 'compute') throw new Error(`pass ${pass.label}: ${pass.kind} passes cannot run in WebGPU`);
      const m = this.module(pass.entry);
      const occurrence = seen.get(pass.entry) ?? 0;
      seen.set(pass.entry, occurrence + 1);
      const pipeline = await this.pipeline(pass.entry);
      // Only the slots the module declares (a graph may bind unread extra slots).
      const entries = pass.bindings
        .filter(([slot]) => m.bindings.some((b) => b.binding === slot))
        .map(([slot, name]) => {
          const buffer = buffers.get(name);
          if (!buffer) throw new Error(`pass ${pass.label}: no buffer '${name}'`);
          return { binding: slot, resource: { buffer } };
        });
      if (m.push_constants) {
        const bytes = constants(pass, index, occurrence);
        if (bytes.length !== m.push_constant_bytes) {
          throw new Error(`${pass.entry}: ${bytes.length} constant bytes, the module takes ${m.push_constant_bytes}`);
        }
        written.push({ entry: pass.entry, bytes });
        if (m.wgsl.constants_binding === undefined) throw new Error(`${pass.entry}: no constants binding in its WGSL`);
        // A uniform buffer holding the push-constant struct's bytes (16-byte multiple).
        const uniform = device.createBuffer({ label: `${pass.entry} constants`, size: Math.ceil(bytes.length / 16) * 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
        device.queue.writeBuffer(uniform, 0, bytes);
        owned.push(uniform);
        entries.push({ binding: m.wgsl.constants_binding, resource: { buffer: uniform } });
      } else {
        written.push({ entry: pass.entry, bytes: new Uint8Array(0) });
      }
      const group = device.createBindGroup({ label: pass.label, layout: pipeline.getBindGroupLayout(0), entries });
      const [x, y] = pass.dispatch.map(count);
      const [gx, gy] = m.workgroup_size;
      // WebGPU orders dispatches that write and read a buffer itself: `barrier_before` needs no
      // call here.
      const cpass = encoder.beginComputePass({ label: pass.label });
      cpass.setPipeline(pipeline);
      cpass.setBindGroup(0, group);
      cpass.dispatchWorkgroups(Math.ceil(x / gx), Math.ceil(y / gy), 1);
      cpass.end();
    }
    const output = buffers.get(graph.output);
    const readback = device.createBuffer({ label: 'readback', size: output.size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    encoder.copyBufferToBuffer(output, 0, readback, 0, output.size);
    device.queue.submit([encoder.finish()]);
    const oom = await device.popErrorScope();
    const invalid = await device.popErrorScope();
    if (invalid || oom) throw new Error(`WebGPU: ${(invalid || oom).message}`);
    await readback.mapAsync(GPUMapMode.READ);
    const result = new Float32Array(readback.getMappedRange().slice(0));
    readback.unmap();
    const ms = performance.now() - t0;
    for (const b of owned) b.destroy();
    readback.destroy();
    return { output: result, constants: written, ms };
  }
}

/** The inner image of a full-target image. */
export function cropInner(full, W, H, guard) {
  const w = W - 2 * guard;
  const h = H - 2 * guard;
  const out = new Float32Array(w * h);
  for (let y = 0; y < h; y++) out.set(full.subarray((y + guard) * W + guard, (y + guard) * W + guard + w), y * w);
  return out;
}
