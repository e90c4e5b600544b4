// The conformance suite's client (../shared/conformance/oracle.c) in JavaScript, on the
// npm package: the same questions, printed the same way, for compare.py.
//   node conformance.mjs PACKAGE CONFORMANCE OUT [current|2.0.1]
import { existsSync, readFileSync, readdirSync, writeFileSync, mkdirSync } from 'node:fs';
import { join, relative, sep } from 'node:path';
import { pathToFileURL } from 'node:url';

const [pkg, suite, out, profile = 'current'] = process.argv.slice(2);
const { Road, ContactPoint } = await import(pathToFileURL(join(pkg, 'index.js')).href);
mkdirSync(out, { recursive: true });

// Every sample file, by its path under the suite, in subfolders too (a CRG file's
// references are found beside it among these, as the C client finds them from the
// file's folder).
const files = {};
for (const dir of ['crg-txt', 'crg-bin']) {
  if (!existsSync(join(suite, dir))) continue;
  for (const entry of readdirSync(join(suite, dir), { recursive: true, withFileTypes: true })) {
    if (!entry.isFile()) continue;
    const path = join(entry.parentPath ?? entry.path, entry.name);
    files[relative(suite, path).split(sep).join('/')] = readFileSync(path);
  }
}

const pr = (d) => (Number.isNaN(d) ? ' nan' : ` ${d}`);

function run(file, nu, nv, settings) {
  const lines = [];
  let road;
  try {
    road = Road.fromBytes(files[file] ?? new Uint8Array(), file, { compat: profile, files });
  } catch {
    return 'load 0\n';
  }
  lines.push('load 1');
  try {
    road.check();
    lines.push('check 1');
  } catch {
    lines.push('check 0');
  }
  const mods = settings.filter((s) => s.startsWith('mod:'));
  const opts = settings.filter((s) => s.startsWith('opt:'));
  const split = (s) => {
    const [name, value] = s.slice(4).split('=');
    return [name, Number.parseFloat(value)];
  };
  if (mods.length) road.clearModifiers();
  for (const s of mods) road.setModifier(...split(s));
  road.applyModifiers();
  const cp = new ContactPoint(road, Object.fromEntries(opts.map(split)));
  lines.push('cp 1');
  const [umin, umax] = road.uRange;
  const [vmin, vmax] = road.vRange;
  const [uinc, vinc] = road.increments;
  const [closed, cmin, cmax] = road.closedTrackReport;
  lines.push(`urange 1${pr(umin)}${pr(umax)}`, `vrange 1${pr(vmin)}${pr(vmax)}`, `incs 1${pr(uinc)}${pr(vinc)}`);
  lines.push(`closed 1 ${closed}${pr(cmin)}${pr(cmax)}`);
  const L = umax - umin;
  const W = vmax - vmin;
  const rc = () => 1 - cp.refused[0];
  for (let a = 0; a <= nu; a++) {
    for (let b = 0; b <= nv; b++) {
      const u = umin - 0.3 * L + (1.6 * L * a) / nu;
      const v = vmin - 0.4 * W + (1.8 * W * b) / nv;
      const [x, y] = cp.uvToXy(u, v);
      const r1 = rc();
      const z = cp.uvToZ(u, v);
      const r2 = rc();
      const [phi, curv] = cp.uvToPk(u, v);
      const r3 = rc();
      let [u2, v2, z2, phi2, curv2, r4, r5, r6] = [NaN, NaN, NaN, NaN, NaN, 0, 0, 0];
      if (r1) {
        [u2, v2] = cp.xyToUv(x, y);
        r4 = rc();
        z2 = cp.xyToZ(x, y);
        r5 = rc();
        [phi2, curv2] = cp.xyToPk(x, y);
        r6 = rc();
      }
      lines.push(
        `q${pr(u)}${pr(v)} | ${r1}${pr(x)}${pr(y)} | ${r2}${pr(z)} | ${r3}${pr(phi)}${pr(curv)}` +
          ` | ${r4}${pr(u2)}${pr(v2)} | ${r5}${pr(z2)} | ${r6}${pr(phi2)}${pr(curv2)}`,
      );
    }
  }
  return `${lines.join('\n')}\n`;
}

for (const line of readFileSync(join(suite, 'cases.txt'), 'utf8').split('\n')) {
  if (!line.trim() || line.startsWith('#')) continue;
  const [name, file, nu, nv, ...settings] = line.trim().split(/\s+/);
  writeFileSync(join(out, `${name}.txt`), run(file, Number(nu), Number(nv), settings));
}
