// The page's figures, drawn on canvases by the command's drawing rules (the npm package's
// `drawing`): axes with ticks at round steps, line charts, the elevation colours and
// their bar, and the roughness figure of `opencrg roughness --plot`. No state: each
// function draws what it is given.
import { drawing, iso8608Classes } from './index.js';

/** The tracks' colours in turn, and the grey of reference lines (CSS colours). */
export const { tracks: TRACK_COLOURS, reference: REFERENCE_GREY } = drawing.figureColours();

/** The colours of values `t` in 0..1 by the command's elevation colours: [r, g, b]s. */
export function colours(t) {
  const rgb = drawing.elevationColours(Float64Array.from(t));
  return Array.from({ length: t.length }, (_, i) => [rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]]);
}

/** Linear axes: ticks at round steps, labelled with their values. */
export const LINEAR = { ticks: (a, b) => Array.from(drawing.ticks(a, b, 7)), label: drawing.tickLabel };
/** Axes over log10 of the values: a tick at each decade. */
export const DECADES = {
  ticks: (a, b) => Array.from({ length: Math.max(0, Math.floor(b) - Math.ceil(a) + 1) }, (_, i) => Math.ceil(a) + i),
  label: (d) => drawing.decadeLabel(10 ** d),
};

/** The frame `f` ({x0, x1, y0, y1, left, top, pw, ph}) with ticks and labels on `scale`. */
export function axes(g, f, xLabel = 'x [m]', yLabel = 'y [m]', scale = LINEAR) {
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
export function pixel(f, x, y) {
  return [f.left + ((x - f.x0) / (f.x1 - f.x0)) * f.pw, f.top + ((f.y1 - y) / (f.y1 - f.y0)) * f.ph];
}

export function bar(g, lo, hi, x, top, h) {
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
export function chart(canvas, xs, ys, xLabel, title) {
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

/** A line through `points` ([x, y] in the frame's units; null: a gap), clipped to it. */
export function polyline(g, f, points, colour, width) {
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
export function legend(g, f, names) {
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
export function roughnessFigure(canvas, tracks, name) {
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
  g.fillText(`${name}: displacement PSD and ISO 8608 classes`, left, 24);
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
