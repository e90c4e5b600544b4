// The page: opens a CRG file, or an OpenDRIVE map with its CRG files, in the browser (the
// npm package's WebAssembly), shows what `opencrg info` / `odr info` say and a top view
// coloured by height, and reads the surface where it is clicked. `?road=URL&probe=X,Y`
// opens a road or map by URL (a map's CRG files relative to it) and writes the answer at
// x/y into #probe: "z u v" for a CRG file, "z friction road s t" for a map.
import { ContactPoint, Road, drawing, iso8608Classes, odr } from './index.js';

const $ = (id) => document.getElementById(id);
let shown = null; // { kind: 'road', road, cp } or { kind: 'map', map }; the view's frame

function fail(e) {
  $('error').textContent = e instanceof Error ? e.message : String(e);
}

/** Opens files: `{name: Uint8Array}`; how long reading and drawing took goes to #timing. */
function open(files) {
  const started = performance.now();
  $('error').textContent = '';
  const names = Object.keys(files);
  const xodr = names.find((n) => n.toLowerCase().endsWith('.xodr'));
  let next;
  if (xodr) {
    const crg = Object.fromEntries(names.filter((n) => n !== xodr).map((n) => [n, files[n]]));
    const map = odr.Map.fromBytes(files[xodr], crg, xodr);
    next = { kind: 'map', map, name: xodr };
    $('info').textContent = map.info() + findings(map.check());
  } else {
    const name = names.find((n) => n.toLowerCase().endsWith('.crg')) ?? names[0];
    if (!name) throw new Error('no file given');
    const road = Road.fromBytes(files[name], name, { files });
    let warning = '';
    try {
      road.check();
    } catch (e) {
      warning = `\ncheck: ${e.message}`;
    }
    road.applyModifiers();
    next = { kind: 'road', road, cp: new ContactPoint(road), name };
    $('info').textContent = road.info(name) + warning;
  }
  const read = performance.now();
  shown = next;
  draw();
  if (shown.kind === 'road') {
    const [u0, u1] = shown.road.uRange;
    sections(0.5 * (u0 + u1), 0);
    rough();
  }
  $('road-only').style.display = shown.kind === 'road' ? '' : 'none';
  $('timing').textContent = `read ${(read - started).toFixed(0)} ms, drawn ${(performance.now() - read).toFixed(0)} ms`;
}

function findings(list) {
  return list.length ? `\nfindings:\n${list.join('\n')}` : '';
}

/** The x/y extent of what is shown: [x0, x1, y0, y1]. */
function extent() {
  const xs = [];
  const ys = [];
  if (shown.kind === 'road') {
    const [u0, u1] = shown.road.uRange;
    const [v0, v1] = shown.road.vRange;
    const n = 400;
    const u = Float64Array.from({ length: 2 * n }, (_, i) => u0 + ((u1 - u0) * (i % n)) / (n - 1));
    const v = Float64Array.from({ length: 2 * n }, (_, i) => (i < n ? v0 : v1));
    const [x, y] = shown.road.uvToXy(u, v);
    xs.push(...x);
    ys.push(...y);
  } else {
    const ids = shown.map.roadIds;
    const lengths = shown.map.roadLengths;
    ids.forEach((id, k) => {
      const n = 50;
      const s = Float64Array.from({ length: n }, (_, i) => (lengths[k] * i) / (n - 1));
      const [x, y] = shown.map.stToXyz(id, s, new Float64Array(n));
      for (let i = 0; i < n; i++) if (Number.isFinite(x[i])) (xs.push(x[i]), ys.push(y[i]));
    });
  }
  const pad = 0.04;
  const least = (a) => a.reduce((m, v) => Math.min(m, v), Infinity);
  const most = (a) => a.reduce((m, v) => Math.max(m, v), -Infinity);
  let [x0, x1, y0, y1] = [least(xs), most(xs), least(ys), most(ys)];
  const [dx, dy] = [x1 - x0 || 1, y1 - y0 || 1];
  return [x0 - pad * dx - 10, x1 + pad * dx + 10, y0 - pad * dy - 10, y1 + pad * dy + 10];
}

/** Heights at points (NaN off the road). */
function heights(x, y) {
  if (shown.kind === 'map') return shown.map.ground(x, y).z;
  const [u, v] = shown.cp.xyToUv(x, y);
  const z = shown.cp.xyToZ(x, y);
  const [u0, u1] = shown.road.uRange;
  const [v0, v1] = shown.road.vRange;
  return z.map((h, i) => (u[i] >= u0 && u[i] <= u1 && v[i] >= v0 && v[i] <= v1 ? h : NaN));
}

/** The colours of values `t` in 0..1 by the command's elevation colours: [r, g, b]s. */
function colours(t) {
  const rgb = drawing.elevationColours(Float64Array.from(t));
  return Array.from({ length: t.length }, (_, i) => [rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]]);
}

function draw() {
  const canvas = $('top');
  const g = canvas.getContext('2d');
  const [W, H, left, bottom] = [canvas.width, canvas.height, 70, 40];
  const [pw, ph] = [W - left - 120, H - bottom - 10];
  let [x0, x1, y0, y1] = extent();
  const m = Math.max((x1 - x0) / pw, (y1 - y0) / ph);
  [x1, y1] = [x0 + m * pw, y0 + m * ph];
  shown.frame = { x0, y1, m, left, top: 10, pw, ph };
  // One point a pixel, as `opencrg render` draws its top view.
  const step = 1;
  const [nx, ny] = [Math.ceil(pw / step), Math.ceil(ph / step)];
  const x = new Float64Array(nx * ny);
  const y = new Float64Array(nx * ny);
  for (let r = 0; r < ny; r++) {
    for (let c = 0; c < nx; c++) {
      // Rows in turn, each the other way, so that a search follows its neighbour.
      const cc = r % 2 ? nx - 1 - c : c;
      x[r * nx + c] = x0 + (cc + 0.5) * step * m;
      y[r * nx + c] = y1 - (r + 0.5) * step * m;
    }
  }
  const z = heights(x, y);
  let [lo, hi] = [Infinity, -Infinity];
  for (const h of z) if (Number.isFinite(h)) [lo, hi] = [Math.min(lo, h), Math.max(hi, h)];
  if (lo > hi) [lo, hi] = [0, 1];
  g.fillStyle = '#fff';
  g.fillRect(0, 0, W, H);
  const image = g.createImageData(pw, ph);
  const rgb = drawing.elevationColours(z.map((h) => (h - lo) / (hi - lo || 1)));
  for (let r = 0; r < ny; r++) {
    for (let c = 0; c < nx; c++) {
      const h = z[r * nx + c];
      if (!Number.isFinite(h)) continue;
      const cc = r % 2 ? nx - 1 - c : c;
      const k = 3 * (r * nx + c);
      const [R, G, B] = [rgb[k], rgb[k + 1], rgb[k + 2]];
      for (let dy = 0; dy < step; dy++) {
        for (let dx = 0; dx < step; dx++) {
          const [px, py] = [cc * step + dx, r * step + dy];
          if (px >= pw || py >= ph) continue;
          const o = 4 * (py * pw + px);
          [image.data[o], image.data[o + 1], image.data[o + 2], image.data[o + 3]] = [R, G, B, 255];
        }
      }
    }
  }
  g.putImageData(image, left, 10);
  axes(g, { x0, x1, y0, y1, left, top: 10, pw, ph });
  bar(g, lo, hi, left + pw + 20, 10, ph);
}

/** Linear axes: ticks at round steps, labelled with their values. */
const LINEAR = { ticks: (a, b) => Array.from(drawing.ticks(a, b, 7)), label: drawing.tickLabel };
/** Axes over log10 of the values: a tick at each decade. */
const DECADES = {
  ticks: (a, b) => Array.from({ length: Math.max(0, Math.floor(b) - Math.ceil(a) + 1) }, (_, i) => Math.ceil(a) + i),
  label: (d) => drawing.decadeLabel(10 ** d),
};

/** The frame `f` ({x0, x1, y0, y1, left, top, pw, ph}) with ticks and labels on `scale`. */
function axes(g, f, xLabel = 'x [m]', yLabel = 'y [m]', scale = LINEAR) {
  g.strokeStyle = '#444';
  g.fillStyle = '#222';
  g.font = '12px sans-serif';
  g.strokeRect(f.left, f.top, f.pw, f.ph);
  g.textAlign = 'center';
  for (const t of scale.ticks(f.x0, f.x1)) {
    const [px] = pixel(f, t, f.y0);
    g.beginPath(), g.moveTo(px, f.top + f.ph), g.lineTo(px, f.top + f.ph + 5), g.stroke();
    g.fillText(scale.label(t), px, f.top + f.ph + 18);
  }
  g.fillText(xLabel, f.left + f.pw / 2, f.top + f.ph + 34);
  g.textAlign = 'right';
  for (const t of scale.ticks(f.y0, f.y1)) {
    const [, py] = pixel(f, f.x0, t);
    g.beginPath(), g.moveTo(f.left - 5, py), g.lineTo(f.left, py), g.stroke();
    g.fillText(scale.label(t), f.left - 8, py + 4);
  }
  g.save(), g.translate(14, f.top + f.ph / 2), g.rotate(-Math.PI / 2), g.textAlign = 'center';
  g.fillText(yLabel, 0, 0), g.restore();
}

/** The pixel of (x, y) in the frame `f`. */
function pixel(f, x, y) {
  return [f.left + ((x - f.x0) / (f.x1 - f.x0)) * f.pw, f.top + ((f.y1 - y) / (f.y1 - f.y0)) * f.ph];
}

function bar(g, lo, hi, x, top, h) {
  const shades = colours(Array.from({ length: h }, (_, i) => 1 - i / h));
  for (let i = 0; i < h; i++) {
    const [R, G, B] = shades[i];
    g.fillStyle = `rgb(${R},${G},${B})`;
    g.fillRect(x, top + i, 16, 1);
  }
  g.fillStyle = '#222';
  g.textAlign = 'left';
  g.fillText(`${hi.toFixed(3)} m`, x + 20, top + 10);
  g.fillText(`${lo.toFixed(3)} m`, x + 20, top + h);
  g.fillText('z', x + 4, top + h + 16);
}

/** A line chart with axes: `xs`, `ys` (NaN: gaps). */
function chart(canvas, xs, ys, xLabel, title) {
  const g = canvas.getContext('2d');
  const [W, H, left, top, right, bottom] = [canvas.width, canvas.height, 64, 24, 12, 36];
  const [pw, ph] = [W - left - right, H - top - bottom];
  let [lo, hi] = [Infinity, -Infinity];
  for (const y of ys) if (Number.isFinite(y)) [lo, hi] = [Math.min(lo, y), Math.max(hi, y)];
  if (lo > hi) [lo, hi] = [0, 1];
  if (hi - lo < 1e-6) [lo, hi] = [lo - 0.001, hi + 0.001];
  const [x0, x1] = [xs[0], xs[xs.length - 1]];
  g.fillStyle = '#fff';
  g.fillRect(0, 0, W, H);
  g.fillStyle = '#222';
  g.font = '12px sans-serif';
  g.textAlign = 'left';
  g.fillText(title, left, 16);
  const f = { x0, x1, y0: lo, y1: hi, left, top, pw, ph };
  axes(g, f, xLabel, 'z [m]');
  polyline(g, f, Array.from(xs, (x, i) => (Number.isFinite(ys[i]) ? [x, ys[i]] : null)), '#1f5fa8', 1.5);
}

/** The road's sections along u at `v` and across v at `u`. */
function sections(u, v) {
  const [u0, u1] = shown.road.uRange;
  const [v0, v1] = shown.road.vRange;
  const n = 600;
  const us = Float64Array.from({ length: n }, (_, i) => u0 + ((u1 - u0) * i) / (n - 1));
  const vs = Float64Array.from({ length: n }, (_, i) => v0 + ((v1 - v0) * i) / (n - 1));
  chart($('along'), us, shown.road.uvToZ(us, new Float64Array(n).fill(v)), 'u [m]', `along u at v = ${v.toFixed(3)} m`);
  chart($('across'), vs, shown.road.uvToZ(new Float64Array(n).fill(u), vs), 'v [m]', `across v at u = ${u.toFixed(3)} m`);
}

/** The roughness of the default tracks, as `opencrg roughness` gives it: a table and the
 * command's figure (the densities among the ISO 8608 class bands, the IRI along u). */
function rough() {
  try {
    const tracks = shown.road.roughness();
    const lines = ['track v [m]   IRI [m/km]   ISO 8608   Gd(n0) [m³]'];
    for (const t of tracks) {
      lines.push(`${t.v.toFixed(2).padStart(11)}   ${t.iri.toFixed(3).padStart(10)}   ${t.iso8608.padStart(8)}   ${t.gdN0.toExponential(3)}`);
    }
    $('roughness').textContent = lines.join('\n');
    roughnessFigure($('rough'), tracks);
  } catch (e) {
    $('roughness').textContent = `roughness: ${e.message}`;
  }
}

const { tracks: TRACK_COLOURS, reference: REFERENCE_GREY } = drawing.figureColours();

/** A line through `points` ([x, y] in the frame's units; null: a gap), clipped to it. */
function polyline(g, f, points, colour, width) {
  g.save();
  g.beginPath(), g.rect(f.left, f.top, f.pw, f.ph), g.clip();
  g.strokeStyle = colour;
  g.lineWidth = width;
  g.beginPath();
  let pen = false;
  for (const p of points) {
    if (!p) {
      pen = false;
      continue;
    }
    const [px, py] = pixel(f, p[0], p[1]);
    pen ? g.lineTo(px, py) : g.moveTo(px, py);
    pen = true;
  }
  g.stroke();
  g.restore();
}

/** Each track's name in its colour, top right inside the frame. */
function legend(g, f, names) {
  g.font = '12px sans-serif';
  g.textAlign = 'left';
  const w = Math.max(...names.map((n) => g.measureText(n).width)) + 44;
  const [x, y] = [f.left + f.pw - w - 8, f.top + 8];
  g.fillStyle = 'rgba(255,255,255,0.9)';
  g.fillRect(x, y, w, 18 * names.length + 6);
  names.forEach((name, i) => {
    g.strokeStyle = TRACK_COLOURS[i % TRACK_COLOURS.length];
    g.lineWidth = 2;
    g.beginPath(), g.moveTo(x + 6, y + 14 + 18 * i), g.lineTo(x + 30, y + 14 + 18 * i), g.stroke();
    g.fillStyle = '#222';
    g.fillText(name, x + 36, y + 18 + 18 * i);
  });
  g.lineWidth = 1;
}

/** The figure of `opencrg roughness --plot`: above, each track's displacement PSD on
 * log-log axes among the ISO 8608 class bands (lines of slope -2 through the class limits
 * at n0, the letters between them); below, the IRI per segment as steps along u. */
function roughnessFigure(canvas, tracks) {
  const g = canvas.getContext('2d');
  const { n0, limits, classes } = iso8608Classes();
  const [W, left, right] = [canvas.width, 92, 28];
  g.fillStyle = '#fff';
  g.fillRect(0, 0, W, canvas.height);
  const densities = tracks.flatMap((t) => t.bands.map((b) => b[1])).filter((d) => d > 0);
  const top = { x0: -2, x1: 1, left, top: 44, pw: W - left - right, ph: 400 };
  top.y0 = Math.floor(Math.log10(Math.min(1e-9, ...densities)));
  top.y1 = Math.ceil(Math.log10(Math.max(1e-1, ...densities)));
  g.fillStyle = '#222';
  g.font = '14px sans-serif';
  g.textAlign = 'left';
  g.fillText(`${shown.name}: displacement PSD and ISO 8608 classes`, left, 24);
  axes(g, top, 'n [cycles/m]', 'Gd(n) [m³]', DECADES);
  // Gd(n) = Gd(n0) (n / n0)^-2, in log10: a line of slope -2 through (log n0, log Gd(n0)).
  const band = (at) => [[top.x0, at - 2 * (top.x0 - Math.log10(n0))], [top.x1, at - 2 * (top.x1 - Math.log10(n0))]];
  for (const l of limits) polyline(g, top, band(Math.log10(l)), REFERENCE_GREY, 1);
  const half = Math.log10(4) / 2;
  const middles = [Math.log10(limits[0]) - half, ...limits.slice(1).map((l, k) => (Math.log10(limits[k]) + Math.log10(l)) / 2), Math.log10(limits[limits.length - 1]) + half];
  g.fillStyle = REFERENCE_GREY;
  g.textAlign = 'center';
  [...classes].forEach((letter, k) => {
    const at = [2, 1, 5, 0.5, 0.2, 0.1, 0.05, 0.02]
      .map((n) => [Math.log10(n), middles[k] - 2 * (Math.log10(n) - Math.log10(n0))])
      .find(([, d]) => d > top.y0 + 0.3 && d < top.y1 - 0.3);
    if (at) {
      const [px, py] = pixel(top, at[0], at[1]);
      g.fillText(letter, px, py + 4);
    }
  });
  tracks.forEach((t, i) => {
    const points = t.bands.filter((b) => b[1] > 0).map(([n, d]) => [Math.log10(n), Math.log10(d)]);
    const colour = TRACK_COLOURS[i % TRACK_COLOURS.length];
    polyline(g, top, points, colour, 2);
    g.fillStyle = colour;
    for (const [x, y] of points) {
      const [px, py] = pixel(top, x, y);
      g.beginPath(), g.arc(px, py, 3, 0, 2 * Math.PI), g.fill();
    }
  });
  legend(g, top, tracks.map((t) => `v = ${t.v} m (class ${t.iso8608})`));
  // The IRI per segment: steps along u; a segment without data breaks the line.
  const segments = tracks.flatMap((t) => t.segments);
  const u0 = Math.min(...segments.map((s) => s.uStart));
  const u1 = Math.max(...segments.map((s) => s.uEnd));
  const most = Math.max(0, ...segments.map((s) => s.iri ?? 0));
  const low = { x0: u0, x1: u1 > u0 ? u1 : u0 + 1, y0: 0, y1: most > 0 ? most * 1.15 : 1, left, top: 540, pw: W - left - right, ph: canvas.height - 540 - 44 };
  g.fillStyle = '#222';
  g.font = '14px sans-serif';
  g.textAlign = 'left';
  const length = tracks[0]?.segments[0] ? tracks[0].segments[0].uEnd - tracks[0].segments[0].uStart : 0;
  g.fillText(`IRI per ${+length.toFixed(3)} m segment`, left, 520);
  axes(g, low, 'u [m]', 'IRI [m/km]');
  tracks.forEach((t, i) => {
    const steps = t.segments.flatMap((s) => (s.iri === null ? [null] : [[s.uStart, s.iri], [s.uEnd, s.iri]]));
    polyline(g, low, steps, TRACK_COLOURS[i % TRACK_COLOURS.length], 2);
  });
  legend(g, low, tracks.map((t) => `v = ${t.v} m`));
}

/** The answer at (x, y): "z u v" for a road, "z friction road s t" for a map. */
function answer(x, y) {
  if (shown.kind === 'road') {
    const cp = new ContactPoint(shown.road);
    const [u, v] = cp.xyToUv(x, y);
    const z = cp.xyToZ(x, y);
    return `${z} ${u} ${v}`;
  }
  const g = shown.map.ground(x, y);
  const road = g.road >= 0 ? shown.map.roadIds[g.road] : '-';
  return `${g.z} ${g.friction} ${road} ${g.s} ${g.t}`;
}

/** The 3D view of `opencrg view` / `opencrg odr view` (the same page) in the frame. */
function show3d() {
  const frame = $('view3d');
  try {
    frame.srcdoc = shown.kind === 'road' ? shown.road.viewPage(shown.name) : shown.map.viewPage(shown.name);
    frame.style.display = '';
    $('top').style.display = 'none';
  } catch (e) {
    fail(e);
  }
}
$('show-3d').addEventListener('click', () => shown && show3d());
$('show-top').addEventListener('click', () => {
  $('view3d').style.display = 'none';
  $('top').style.display = '';
});

$('top').addEventListener('click', (event) => {
  if (!shown) return;
  const rect = event.target.getBoundingClientRect();
  const f = shown.frame;
  const px = ((event.clientX - rect.left) * event.target.width) / rect.width - f.left;
  const py = ((event.clientY - rect.top) * event.target.height) / rect.height - f.top;
  const [x, y] = [f.x0 + px * f.m, f.y1 - py * f.m];
  const a = answer(x, y).split(' ');
  if (shown.kind === 'road' && Number.isFinite(+a[1])) sections(+a[1], +a[2]);
  $('readout').textContent =
    shown.kind === 'road'
      ? `x ${x.toFixed(3)} y ${y.toFixed(3)} z ${(+a[0]).toFixed(4)} u ${(+a[1]).toFixed(3)} v ${(+a[2]).toFixed(3)}`
      : `x ${x.toFixed(3)} y ${y.toFixed(3)} z ${(+a[0]).toFixed(4)} friction ${a[1]} road ${a[2]} s ${(+a[3]).toFixed(3)} t ${(+a[4]).toFixed(3)}`;
});

async function read(fileList) {
  const files = {};
  for (const f of fileList) files[f.webkitRelativePath || f.name] = new Uint8Array(await f.arrayBuffer());
  return files;
}

for (const id of ['files', 'folder']) {
  $(id).addEventListener('change', async (e) => {
    try {
      open(await read(e.target.files));
    } catch (err) {
      fail(err);
    }
  });
}
const drop = $('drop');
drop.addEventListener('dragover', (e) => (e.preventDefault(), drop.classList.add('over')));
drop.addEventListener('dragleave', () => drop.classList.remove('over'));
drop.addEventListener('drop', async (e) => {
  e.preventDefault();
  drop.classList.remove('over');
  try {
    open(await read(e.dataTransfer.files));
  } catch (err) {
    fail(err);
  }
});

// ?road=URL&probe=X,Y (&view=3d: the 3D view first)
const params = new URLSearchParams(location.search);
if (params.get('road')) {
  const started = performance.now();
  try {
    const url = new URL(params.get('road'), location.href);
    const fetchBytes = async (u) => {
      const r = await fetch(u);
      if (!r.ok) throw new Error(`${u}: ${r.status} ${r.statusText}`);
      return new Uint8Array(await r.arrayBuffer());
    };
    const name = decodeURIComponent(url.pathname.split('/').pop());
    const files = { [name]: await fetchBytes(url) };
    if (name.toLowerCase().endsWith('.xodr')) {
      for (const file of odr.crgFilesOf(files[name], name)) {
        files[file] = await fetchBytes(new URL(file, url));
      }
    }
    const fetched = performance.now();
    open(files);
    $('timing').textContent = `fetched ${(fetched - started).toFixed(0)} ms, ${$('timing').textContent}`;
    if (params.get('view') === '3d') show3d();
    if (params.get('probe')) {
      const [x, y] = params.get('probe').split(',').map(Number);
      $('probe').textContent = answer(x, y);
    }
  } catch (err) {
    fail(err);
  }
}
