// aokit's contract in the browser: the manifest's formulas and struct layouts, the constants of
// each push-constant struct, and a technique's pass graph run through WebGPU from the WGSL files.
// Plain ES module, no build step, no dependencies. Formats: assets/README.md, docs/web.md.

// ---------------------------------------------------------------------------------------------
// Formulas: `W×H` the full target, `w×h` the inner image, numbers, + - · * /, ceil, floor, max,
// min and parentheses (assets/README.md, "Formulas").

const TOKEN = /\s*(\d+(?:\.\d+)?(?:e[+-]?\d+)?|[A-Za-z_]\w*|[+\-*/·(),])/y;

function tokenize(text) {
  const out = [];
  TOKEN.lastIndex = 0;
  while (TOKEN.lastIndex < text.length) {
    if (/^\s*$/.test(text.slice(TOKEN.lastIndex))) break;
    const at = TOKEN.lastIndex;
    const m = TOKEN.exec(text);
    if (!m) throw new Error(`formula '${text}': cannot read at ${at}`);
    out.push(m[1]);
  }
  return out;
}

const FUNCTIONS = {
  ceil: (a) => Math.ceil(a),
  floor: (a) => Math.floor(a),
  max: (...a) => Math.max(...a),
  min: (...a) => Math.min(...a),
};

/** Evaluate a size or dispatch formula with `vars` = {W, H, w, h}. */
export function evalFormula(text, vars) {
  const t = tokenize(String(text));
  let i = 0;
  const peek = () => t[i];
  const take = (want) => {
    const tok = t[i++];
    if (want !== undefined && tok !== want) throw new Error(`formula '${text}': expected '${want}', got '${tok}'`);
    return tok;
  };
  const expr = () => {
    let v = term();
    while (peek() === '+' || peek() === '-') v = take() === '+' ? v + term() : v - term();
    return v;
  };
  const term = () => {
    let v = factor();
    while (peek() === '·' || peek() === '*' || peek() === '/') v = take() === '/' ? v / factor() : v * factor();
    return v;
  };
  const factor = () => {
    const tok = take();
    if (tok === undefined) throw new Error(`formula '${text}': unexpected end`);
    if (tok === '(') {
      const v = expr();
      take(')');
      return v;
    }
    if (tok === '-') return -factor();
    if (/^\d/.test(tok)) return Number(tok);
    if (tok in FUNCTIONS) {
      take('(');
      const args = [expr()];
      while (peek() === ',') {
        take(',');
        args.push(expr());
      }
      take(')');
      return FUNCTIONS[tok](...args);
    }
    if (tok in vars) return vars[tok];
    throw new Error(`formula '${text}': unknown name '${tok}'`);
  };
  const v = expr();
  if (i !== t.length) throw new Error(`formula '${text}': trailing '${t[i]}'`);
  return v;
}

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
// Constants. The manifest gives each push-constant struct's layout and its fields' meaning in
// words; what fills each field is here, from the Rust functions beside the kernels (docs/web.md,
// "What the page takes from the Rust sources"). `c` holds: view (ViewParams bytes of camera.bin),
// frame (export.json: radius, exponent, thickness), settings (the technique's, key → string),
// gtao (XeGTAO's settings for its passes), entry, occurrence (index of this pass among the
// graph's passes of the same entry).

const num = (v) => Number(v);

export const CONSTANTS = {
  // aokit_shaders::vao::settings::vao_params; MAX_SCREEN_RADIUS = 512.
  VaoParams: (c) => ({
    view: c.view, radius: c.frame.radius, exponent: c.frame.exponent, thickness: c.frame.thickness,
    max_screen_radius: 512,
  }),
  // aokit_shaders::blur::graph::blur_passes: horizontal, then vertical; SHARPNESS = 16.
  BlurParams: (c) => ({ view: c.view, direction: c.occurrence % 2 === 0 ? [1, 0] : [0, 1], sharpness: 16 }),
  // GtaoSettings::params; `pass` = MIP level of a prefilter dispatch, index of a denoise pass.
  GtaoParams: (c) => ({
    view: c.view,
    radius: c.frame.radius,
    radius_multiplier: num(c.gtao['radius-multiplier']),
    falloff_range: num(c.gtao['falloff-range']),
    sample_distribution_power: num(c.gtao['sample-power']),
    thin_occluder_compensation: num(c.gtao['thin-occluder']),
    final_value_power: num(c.gtao['final-power']),
    depth_mip_sampling_offset: num(c.gtao['mip-offset']),
    slices: num(c.gtao.slices),
    steps: num(c.gtao.steps),
    denoise_passes: num(c.gtao.denoise),
    noise_frame: 0,
    pass: c.entry === 'gtao_prefilter' || c.entry === 'gtao_denoise' ? c.occurrence : 0,
    bent_normals: c.gtao['bent-normals'] === 'on' ? 1 : 0,
  }),
  // VbaoSettings::params: T = thickness·R; R_g by gate (off 0, effective R·multiplier, radius
  // R); weighting uniform 0, cosine-blender 1, cosine-exact 2; sectors paper 0, touch 1.
  VbaoParams: (c) => ({
    thickness: num(c.settings.thickness) * c.frame.radius,
    gate_radius: { off: 0, effective: c.frame.radius * num(c.settings['radius-multiplier']), radius: c.frame.radius }[c.settings.gate],
    weighting: ['uniform', 'cosine-blender', 'cosine-exact'].indexOf(c.settings.weighting),
    sector_rule: c.settings.sectors === 'touch' ? 1 : 0,
    gtao: CONSTANTS.GtaoParams(c),
  }),
  // RaymarchSettings::params; DEPTH_BIAS = 0.0008, thickness f32::MAX (a pure height field),
  // contribution Linear = 0, Binary = 1.
  RaymarchParams: (c) => ({
    view: c.view,
    radius: c.frame.radius,
    alpha: num(c.settings.alpha),
    depth_bias: 0.0008,
    thickness: 3.4028234663852886e38,
    directions: num(c.settings.directions),
    steps: num(c.settings.steps),
    contribution: c.settings.contribution === 'binary' ? 1 : 0,
    noise_frame: 0,
  }),
};

/** XeGTAO's settings for the GtaoParams of a graph of `technique`: its own for gtao; for a
 *  technique that reuses the denoiser (raymarch), gtao's defaults with its `denoise` count
 *  (aokit_shaders::gtao::settings::with_denoiser). */
export function gtaoSettings(manifest, technique, settings) {
  if (technique === 'gtao') return settings;
  const gtao = manifest.techniques.find((t) => t.name === 'gtao');
  const defaults = Object.fromEntries(gtao.settings.map((s) => [s.key, s.default]));
  // VBAO's XeGTAO settings are its own, the rest (falloff, thin occluder) stay at gtao's defaults.
  if (technique === 'vbao') return { ...defaults, ...settings };
  return { ...defaults, denoise: settings.denoise ?? defaults.denoise };
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
   * Run `graph` once. `view`: ViewParams bytes; `data`: resource name → Uint32Array for
   * resources initialised with data; `constants(pass, index, occurrence)`: the bytes of the
   * module's push-constant struct. Returns {output: Float32Array of the full target, constants:
   * [{entry, bytes}], ms}.
   */
  async run(graph, { W, H, guard }, data, constants) {
    const device = this.device;
    const vars = { W, H, w: W - 2 * guard, h: H - 2 * guard };
    device.pushErrorScope('validation');
    device.pushErrorScope('out-of-memory');
    const t0 = performance.now();
    const buffers = new Map(this.inputs);
    const owned = [];
    for (const r of graph.resources) {
      let len = evalFormula(r.size, vars);
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
      const [x, y] = pass.dispatch.map((f) => evalFormula(f, vars));
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
