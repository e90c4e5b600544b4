// A road or a map opened in the page, and what is drawn and read of it: a `shown` is
// `{kind: 'road', road, cp, name}` or `{kind: 'map', map, name}`. No state of its own:
// each function works on the `shown` it is given.
import { ContactPoint, Road, drawing, odr } from './index.js';
import { axes, bar, chart } from './figures.js';

/** Opens files (`{name: Uint8Array}`): the map among them with the others as its CRG
 * files, or the CRG file; `[shown, info]`, info being what the command's `info` says. */
export function open(files) {
  const names = Object.keys(files);
  const xodr = names.find((n) => n.toLowerCase().endsWith('.xodr'));
  if (xodr) {
    const crg = Object.fromEntries(names.filter((n) => n !== xodr).map((n) => [n, files[n]]));
    const map = odr.Map.fromBytes(files[xodr], crg, xodr);
    const found = map.check();
    return [{ kind: 'map', map, name: xodr }, map.info() + (found.length ? `\nfindings:\n${found.join('\n')}` : '')];
  }
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
  return [{ kind: 'road', road, cp: new ContactPoint(road), name }, road.info(name) + warning];
}

/** The x/y extent of what is shown: [x0, x1, y0, y1]. */
function extent(shown) {
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
function heights(shown, x, y) {
  if (shown.kind === 'map') return shown.map.ground(x, y).z;
  const [u, v] = shown.cp.xyToUv(x, y);
  const z = shown.cp.xyToZ(x, y);
  const [u0, u1] = shown.road.uRange;
  const [v0, v1] = shown.road.vRange;
  return z.map((h, i) => (u[i] >= u0 && u[i] <= u1 && v[i] >= v0 && v[i] <= v1 ? h : NaN));
}

/** The top view coloured by height on `canvas`; its frame: where x/y lie on it. */
export function drawTop(shown, canvas) {
  const g = canvas.getContext('2d');
  const [W, H, left, bottom] = [canvas.width, canvas.height, 70, 40];
  const [pw, ph] = [W - left - 120, H - bottom - 10];
  let [x0, x1, y0, y1] = extent(shown);
  const m = Math.max((x1 - x0) / pw, (y1 - y0) / ph);
  [x1, y1] = [x0 + m * pw, y0 + m * ph];
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
  const z = heights(shown, x, y);
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
  return { x0, y1, m, left, top: 10, pw, ph };
}

/** The road's sections along u at `v` (on `along`) and across v at `u` (on `across`). */
export function sections(shown, along, across, u, v) {
  const [u0, u1] = shown.road.uRange;
  const [v0, v1] = shown.road.vRange;
  const n = 600;
  const us = Float64Array.from({ length: n }, (_, i) => u0 + ((u1 - u0) * i) / (n - 1));
  const vs = Float64Array.from({ length: n }, (_, i) => v0 + ((v1 - v0) * i) / (n - 1));
  chart(along, us, shown.road.uvToZ(us, new Float64Array(n).fill(v)), 'u [m]', `along u at v = ${v.toFixed(3)} m`);
  chart(across, vs, shown.road.uvToZ(new Float64Array(n).fill(u), vs), 'v [m]', `across v at u = ${u.toFixed(3)} m`);
}

/** The roughness of the default tracks as `opencrg roughness` gives it: `[table, tracks]`. */
export function roughness(shown) {
  const tracks = shown.road.roughness();
  const lines = ['track v [m]   IRI [m/km]   ISO 8608   Gd(n0) [m³]'];
  for (const t of tracks) {
    lines.push(`${t.v.toFixed(2).padStart(11)}   ${t.iri.toFixed(3).padStart(10)}   ${t.iso8608.padStart(8)}   ${t.gdN0.toExponential(3)}`);
  }
  return [lines.join('\n'), tracks];
}

/** The answer at (x, y): "z u v" for a road, "z friction road s t" for a map. */
export function answer(shown, x, y) {
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

/** The 3D view of `opencrg view` / `opencrg odr view`: one HTML page. */
export function viewPage(shown) {
  return shown.kind === 'road' ? shown.road.viewPage(shown.name) : shown.map.viewPage(shown.name);
}
