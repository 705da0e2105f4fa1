// `aokit web`'s page: the screen-space techniques run in the browser through WebGPU on the
// exported G-buffer, with settings controls generated from the manifest and a difference view
// against cpu-sim's AO. `?test=1`: every technique runs once at its defaults and its AO is
// POSTed to /result/<technique> (docs/web.md). Plain ES module, no build step.

import { Runner, constantBytes, cropInner, dataOf, expressionInputs, fieldBytes, readStruct, sameValue, structOf, unsupported, variantOf } from './graph.js';

const params = new URLSearchParams(location.search);
const TEST = params.get('test') === '1';
// Tests: keep the load event (and a headless browser's screenshot) waiting until the server
// has every result; the test server answers /hold after /done.
if (TEST) {
  const hold = new Image();
  hold.src = '/hold';
  hold.alt = '';
  hold.style.display = 'none';
  document.body.appendChild(hold);
}

const $ = (id) => document.getElementById(id);
const status = (text, error = false) => {
  $('status').textContent = text;
  $('status').className = error ? 'error' : '';
};

async function fetchOk(path) {
  const r = await fetch(path);
  if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
  return r;
}
const json = async (path) => (await fetchOk(path)).json();
const bytes = async (path) => new Uint8Array(await (await fetchOk(path)).arrayBuffer());

/** Everything the page loads once. */
async function load() {
  const web = await json('web.json');
  if (web.format !== 'aokit-web/2') throw new Error(`web.json: unknown format ${web.format}`);
  const [manifest, exported, camera, depth, normals] = await Promise.all([
    json(web.files.manifest),
    json(web.files.export),
    bytes(web.files.camera),
    bytes(web.files.depth),
    bytes(web.files.normals),
  ]);
  const view = fieldBytes(manifest, 'Camera', 'view', camera);
  const v = readStruct(manifest, 'ViewParams', view);
  const [W, H] = v.res;
  const size = { W, H, guard: v.guard, w: W - 2 * v.guard, h: H - 2 * v.guard };
  if (depth.length !== 4 * W * H || normals.length !== 4 * W * H) throw new Error('the G-buffer does not cover the camera\'s target');
  const references = new Map();
  await Promise.all(web.techniques.map(async (t) => {
    references.set(t.name, new Float32Array((await bytes(t.reference.file)).buffer));
  }));
  return { web, manifest, exported, view, size, depth, normals, references };
}

/** The settings of technique `t` (manifest entry) at their defaults, key → string. */
const defaults = (t) => Object.fromEntries(t.settings.map((s) => [s.key, s.default]));

class Page {
  constructor(ctx, device, adapterName) {
    Object.assign(this, ctx);
    this.device = device;
    this.adapterName = adapterName;
    this.runner = new Runner(device, this.manifest, new URL(this.web.files.wgsl, location.href));
    this.runner.setInput('linear_depth', this.depth);
    this.runner.setInput('view_normals', this.normals);
    this.settings = {};
    this.generation = 0;
    this.last = null;
  }

  technique(name) {
    const m = this.manifest.techniques.find((t) => t.name === name);
    const w = this.web.techniques.find((t) => t.name === name);
    if (!m || !w) throw new Error(`technique ${name} is not in the manifest and web.json`);
    return { m, w };
  }

  /** Select a technique with its default settings and build its controls. */
  select(name) {
    this.name = name;
    $('technique').value = name;
    const { m } = this.technique(name);
    this.settings = defaults(m);
    $('summary').textContent = m.summary;
    this.buildControls(m);
  }

  /** Controls generated from the manifest's settings rows: presets (choices that set other
   *  settings, their `sets`) first, then the rest in the manifest's order. */
  buildControls(m) {
    const box = $('settings');
    box.replaceChildren();
    const preset = (s) => Object.keys(s.sets ?? {}).length > 0;
    const rows = [...m.settings.filter(preset), ...m.settings.filter((s) => !preset(s))];
    for (const s of rows) {
      const label = document.createElement('label');
      label.title = s.help;
      const name = document.createElement('span');
      name.textContent = s.key;
      let input;
      if (s.kind === 'choice') {
        input = document.createElement('select');
        for (const c of s.choices) input.add(new Option(c, c));
      } else {
        input = document.createElement('input');
        input.type = 'number';
        input.step = s.kind === 'count' ? '1' : 'any';
        if (s.min !== null) input.min = s.min;
        if (s.max !== null) input.max = s.max;
      }
      input.id = `setting-${s.key}`;
      input.value = this.settings[s.key];
      input.addEventListener('change', () => this.change(s, input));
      const range = document.createElement('small');
      range.textContent = s.kind === 'choice' ? '' : s.max === null ? `≥ ${s.min}` : `${s.min}–${s.max}`;
      label.append(name, input, range);
      box.append(label);
    }
  }

  /** A control changed: check the value against the row, apply presets, re-run. */
  change(row, input, rerun = true) {
    const { m } = this.technique(this.name);
    let value = input.value.trim();
    if (row.kind !== 'choice') {
      const v = Number(value);
      const bad = value === '' || !Number.isFinite(v) || (row.kind === 'count' && !Number.isInteger(v))
        || (row.min !== null && v < row.min) || (row.max !== null && v > row.max);
      if (bad) {
        status(`${row.key} ${value}: expected ${row.kind === 'count' ? 'a whole number' : 'a number'} in ${row.min ?? '−∞'}–${row.max ?? '∞'}`, true);
        input.value = this.settings[row.key];
        return false;
      }
      value = String(v);
    }
    this.settings[row.key] = value;
    // A preset sets other settings; a setting a preset sets shows the preset it now matches.
    if (row.sets) Object.assign(this.settings, row.sets[value] ?? {});
    for (const p of m.settings.filter((s) => s.sets && s.key !== row.key)) {
      const entries = Object.entries(p.sets);
      const hit = entries.find(([, set]) => Object.keys(set).length > 0
        && Object.entries(set).every(([k, v]) => sameValue(m.settings.find((s) => s.key === k), this.settings[k], v)));
      const none = entries.find(([, set]) => Object.keys(set).length === 0);
      if (hit || none) this.settings[p.key] = (hit ?? none)[0];
    }
    for (const s of m.settings) $(`setting-${s.key}`).value = this.settings[s.key];
    if (rerun) this.rerun();
    return true;
  }

  rerun() {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.run().catch((e) => this.fail(e)), 50);
  }

  /** A run failed: say why, and show no stale image. */
  fail(e) {
    this.last = null;
    const canvas = $('canvas');
    canvas.getContext('2d').clearRect(0, 0, canvas.width, canvas.height);
    $('agreement').textContent = '';
    $('notice').textContent = '';
    status(`${this.name}: ${e.stack || e}`, true);
  }

  /** Select `technique:key=value…` through the controls (as a user would set them). */
  configure(spec) {
    const [name, ...pairs] = spec.split(':');
    this.select(name);
    for (const pair of pairs) {
      const [key, value] = pair.split('=');
      const row = this.technique(name).m.settings.find((s) => s.key === key);
      if (!row) throw new Error(`${spec}: ${name} has no setting ${key}`);
      const input = $(`setting-${key}`);
      input.value = value;
      if (!this.change(row, input, false)) throw new Error(`${spec}: ${key}=${value} refused`);
    }
  }

  /** Run the selected technique with the current settings and show it. */
  async run() {
    const generation = ++this.generation;
    const { m } = this.technique(this.name);
    // The graph, its data and its constants from the manifest alone (assets/README.md): the
    // variant for these settings, its expressions evaluated with the exported camera and AO
    // parameters, the settings and each pass's index among its module's.
    const graph = variantOf(m, this.settings);
    const why = unsupported(this.manifest, graph);
    if (why) throw new Error(`these settings cannot run in the browser: ${why}`);
    const e = this.exported;
    const inputs = expressionInputs(m, this.settings, {
      eye: e.camera.eye, target: e.camera.target, up: e.camera.up, fov_y: e.camera.fov_y, near: e.camera.near,
      far: e.camera.far, inner: e.image, guard: e.guard_band, radius: e.radius, exponent: e.exponent,
      thickness: e.thickness, frame_index: 0,
    });
    const data = dataOf(this.manifest, m, graph, inputs);
    const constants = (pass, index, occurrence) => {
      const struct = this.runner.module(pass.entry).push_constants;
      inputs.names.pass = { t: 'int', v: occurrence };
      return constantBytes(this.manifest, m, struct, inputs);
    };
    status(`running ${this.name}…`);
    const { W, H, guard } = this.size;
    const result = await this.runner.run(graph, inputs, data, constants);
    if (generation !== this.generation) return null;
    const ao = cropInner(result.output, W, H, guard);
    this.last = { name: this.name, ao, constants: result.constants, data, settings: { ...this.settings } };
    this.draw();
    this.showConstants(m, graph, result.constants);
    const passes = graph.passes.map((p) => p.entry).join(' → ');
    status(`${this.name}: ${graph.passes.length} passes (${passes}) in ${result.ms.toFixed(1)} ms on ${this.adapterName}`);
    return this.last;
  }

  /** The constants the page computed, per pass and field, beside the manifest's expression. */
  showConstants(m, graph, constants) {
    const rows = [];
    // [path, struct, field, value] of every scalar or vector field, nested structs walked.
    const flat = (struct, value, prefix) => structOf(this.manifest, struct).fields.flatMap((f) => {
      const path = `${prefix}.${f.name}`;
      return this.manifest.structs.some((s) => s.name === f.ty) ? flat(f.ty, value[f.name], path) : [[path, struct, f.name, value[f.name]]];
    });
    constants.forEach(({ entry, bytes }, i) => {
      const struct = this.runner.module(entry).push_constants;
      if (!struct) return;
      for (const [path, owner, field, value] of flat(struct, readStruct(this.manifest, struct, bytes), struct)) {
        const expr = (m.constants ?? []).find((c) => c.struct === owner && c.field === field)?.expr ?? '';
        const text = (Array.isArray(value) ? value : [value]).map(shortest).join(', ');
        rows.push(`<tr><td>${i} ${entry}</td><td>${path}</td><td>${text}</td><td>${expr.replace(/&/g, '&amp;').replace(/</g, '&lt;')}</td></tr>`);
      }
    });
    $('constants').innerHTML = `<tr><th>pass</th><th>field</th><th>value</th><th>manifest expression</th></tr>${rows.join('')}`;
    $('constants-count').textContent = `${graph.passes.length} passes`;
  }

  /** The AO, or its signed difference from the CPU reference, on the canvas. */
  draw() {
    if (!this.last) return;
    const { w, h } = this.size;
    const canvas = $('canvas');
    canvas.width = w;
    canvas.height = h;
    const image = new ImageData(w, h);
    const px = image.data;
    const ao = this.last.ao;
    const ref = this.references.get(this.last.name);
    const diff = $('diff').checked;
    const gain = Number($('gain').value);
    let within = 0;
    let maxAbs = 0;
    let sq = 0;
    for (let i = 0; i < w * h; i++) {
      const d = ao[i] - ref[i];
      if (Math.abs(d) <= 1 / 255) within++;
      maxAbs = Math.max(maxAbs, Math.abs(d));
      sq += d * d;
      if (diff) {
        const c = Math.min(255, Math.round(Math.abs(d) * gain * 255));
        px.set(d > 0 ? [c, 0, 0, 255] : [0, 0, c, 255], 4 * i);
      } else {
        const g = Math.round(Math.min(1, Math.max(0, ao[i])) * 255);
        px.set([g, g, g, 255], 4 * i);
      }
    }
    canvas.getContext('2d').putImageData(image, 0, 0);
    const { m, w: entry } = this.technique(this.last.name);
    const changed = m.settings
      .filter((s) => !sameValue(s, this.last.settings[s.key], entry.reference.settings[s.key]))
      .map((s) => `${s.key}=${this.last.settings[s.key]}`);
    $('agreement').textContent = `vs cpu-sim (${entry.reference.file}): ${(100 * within / (w * h)).toFixed(3)} % of pixels within 1/255, `
      + `max |Δ| ${maxAbs.toExponential(2)}, MSE ${(sq / (w * h)).toExponential(2)}`;
    $('notice').textContent = changed.length
      ? `The CPU reference was made at ${this.last.name}'s defaults; these settings differ: ${changed.join(', ')}. The difference shows their effect, not an error.`
      : '';
  }
}

async function post(path, body) {
  const r = await fetch(path, { method: 'POST', body });
  if (!r.ok) throw new Error(`POST ${path}: HTTP ${r.status}`);
}

/** The shortest decimal that reads back as the same f32 (integers as they are). */
function shortest(v) {
  if (Number.isInteger(v)) return String(v);
  for (let p = 1; p < 17; p++) {
    const t = v.toPrecision(p);
    if (Math.fround(Number(t)) === v) return String(Number(t));
  }
  return String(v);
}

const hex = (b) => Array.from(b, (x) => x.toString(16).padStart(2, '0')).join('');

async function main() {
  status('loading…');
  const ctx = await load();
  if (!navigator.gpu) throw new Error('this browser has no WebGPU (navigator.gpu is missing)');
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw new Error('no WebGPU adapter');
  const device = await adapter.requestDevice();
  device.lost.then((info) => status(`WebGPU device lost: ${info.message}`, true));
  const info = adapter.info ?? {};
  const adapterName = [info.vendor, info.architecture, info.description].filter(Boolean).join(' ') || 'WebGPU';
  const page = new Page(ctx, device, adapterName);
  const { web, size } = ctx;
  $('scene').textContent = `${web.scene}: ${size.w}×${size.h} (guard ${size.guard}), G-buffer from the ${web.backend} back-end`;
  const select = $('technique');
  for (const t of web.techniques) select.add(new Option(t.name, t.name));
  $('skipped').textContent = web.skipped.length
    ? `Not in the browser: ${web.skipped.map((s) => `${s.name} (${s.why})`).join('; ')}.`
    : '';
  select.addEventListener('change', () => {
    page.select(select.value);
    page.rerun();
  });
  $('reset').addEventListener('click', () => {
    page.select(page.name);
    page.rerun();
  });
  $('constants-details').open = params.get('constants') === '1';
  $('diff').addEventListener('change', () => page.draw());
  $('gain').addEventListener('change', () => page.draw());
  if (TEST) {
    // Every technique once at its defaults, then the `also` configurations
    // (`technique:key=value…`, set through the controls): the inner AO and the constants.
    const also = (params.get('also') ?? '').split(',').filter(Boolean);
    for (const spec of [...web.techniques.map((t) => t.name), ...also]) {
      try {
        page.configure(spec);
        const result = await page.run();
        if (!result) throw new Error(`${spec} did not run`);
        await post(`/result/${encodeURIComponent(spec)}`, result.ao);
        await post(`/constants/${encodeURIComponent(spec)}`, JSON.stringify(result.constants.map((c) => ({ entry: c.entry, hex: hex(c.bytes) }))));
        const data = Object.fromEntries(Object.entries(result.data).map(([k, words]) => [k, hex(new Uint8Array(words.buffer))]));
        await post(`/data/${encodeURIComponent(spec)}`, JSON.stringify(data));
      } catch (e) {
        // The test decides what a failure means; the others still run.
        page.fail(e);
        await post(`/failed/${encodeURIComponent(spec)}`, String(e.stack || e));
      }
    }
    // What the screenshot shows: `show` (a spec), else the first technique.
    page.configure(params.get('show') ?? web.techniques[0].name);
    $('diff').checked = params.get('diff') === '1';
    await page.run().catch((e) => page.fail(e));
    await post('/done', JSON.stringify({ adapter: adapterName }));
  } else {
    // `?technique=gtao&preset=low&diff=1`: a technique, settings by key, the difference view.
    const name = params.get('technique') ?? web.techniques[0].name;
    const rows = page.technique(name).m.settings.filter((row) => params.has(row.key));
    page.configure([name, ...rows.map((row) => `${row.key}=${params.get(row.key)}`)].join(':'));
    $('diff').checked = params.get('diff') === '1';
    await page.run().catch((e) => page.fail(e));
  }
}

main().catch(async (e) => {
  status(`error: ${e.stack || e}`, true);
  if (TEST) await fetch('/error', { method: 'POST', body: String(e.stack || e) }).catch(() => {});
});
