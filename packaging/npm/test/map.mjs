// A shared map (esmini's curves_elevation.xodr) with CRG records of this test's own in
// every mode and orientation, elevation and friction, read from bytes by the npm package
// in Node, against `opencrg odr eval` on the same files: z, s, t and friction at points
// along the road and beside it.
//   OPENCRG_CLI=target/release/opencrg node map.mjs PACKAGE SHARED_OPENDRIVE WORK
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [pkg, shared, work] = process.argv.slice(2);
const { odr } = await import(pathToFileURL(join(pkg, 'index.js')).href);
const cli = (args, input) =>
  execFileSync(process.env.OPENCRG_CLI, args.map(String), { input, encoding: 'utf8', stdio: ['pipe', 'pipe', 'ignore'] });
mkdirSync(work, { recursive: true });

function line(name, x0, y0, heading, length, bend = 0, climb = 0) {
  const rows = ['x,y,z'];
  let [x, y, h] = [x0, y0, heading];
  for (let k = 0; k <= length; k++) {
    rows.push(`${x},${y},${climb * k}`);
    [x, y, h] = [x + Math.cos(h), y + Math.sin(h), h + bend];
  }
  writeFileSync(join(work, `${name}.csv`), `${rows.join('\n')}\n`);
  return join(work, `${name}.csv`);
}
const generate = (name, refline, width, inc, surface) =>
  cli(['generate', join(work, `${name}.crg`), '--refline', refline, '--width', width, '--u-inc', inc, '--v-inc', inc, '--surface', surface]);
generate('rough', line('rough', 230, 150, 1.2, 60, 0.004, 0.02), 6, 0.1, '0.004*sin(u*3.1)*cos(v*1.7)+0.002*cos(u*11)');
generate('flat', line('flat', -40, 25, 0.3, 60), 6, 0.1, '0.005*sin(u*2.3)+0.003*cos(v*5)');
generate('grip', line('grip', 0, 0, 0, 40), 8, 0.5, '0.7+0.1*sin(u)*cos(v)');

const friction = '<CRG file="grip.crg" sStart="105" sEnd="150" purpose="friction" mode="attached0" sOffset="105"/>';
const modes = {
  attached: 'file="flat.crg" mode="attached" orientation="same" sOffset="100" tOffset="0.25"',
  attached_opposite: 'file="flat.crg" mode="attached" orientation="opposite" sOffset="160" tOffset="-0.5"',
  attached0: 'file="rough.crg" mode="attached0" orientation="same" sOffset="100" zScale="0.5" zOffset="0.2"',
  genuine: 'file="rough.crg" mode="genuine" sOffset="100" tOffset="0.5" hOffset="0.05"',
  global: 'file="flat.crg" mode="global" xOffset="140" yOffset="-25" hOffset="-0.2" zScale="2"',
};
const files = Object.fromEntries(['rough', 'flat', 'grip'].map((n) => [`${n}.crg`, readFileSync(join(work, `${n}.crg`))]));
const base = readFileSync(join(shared, 'esmini/curves_elevation.xodr'), 'utf8');
const at = base.lastIndexOf('</road>');
let [compared, exact, worst] = [0, 0, 0];
for (const [mode, attributes] of Object.entries(modes)) {
  const record = `<CRG sStart="100" sEnd="160" purpose="elevation" ${attributes}/>`;
  const path = join(work, `${mode}.xodr`);
  writeFileSync(path, `${base.slice(0, at)}<surface>${record}${friction}</surface>\n${base.slice(at)}`);
  const map = odr.Map.fromBytes(readFileSync(path), files, `${mode}.xodr`);
  assert.deepEqual(map.check(), [], mode);
  const n = 400;
  const s = Float64Array.from({ length: n }, (_, i) => 95 + i * 0.17);
  const t = Float64Array.from({ length: n }, (_, i) => -3 + (i % 13) * 0.5);
  const [x, y] = map.stToXyz('1', s, t);
  const g = map.ground(x, y);
  const native = cli(['odr', 'eval', path], [...x].map((a, i) => `${a} ${y[i]}\n`).join('')).trim().split('\n');
  let [met, gripped] = [0, 0];
  native.forEach((row, i) => {
    const [z, mu, road, ss, tt] = row.split(' ');
    assert.equal(road === '-' ? -1 : map.roadIds.indexOf(road), g.road[i], `${mode} point ${i}: road`);
    for (const [ours, theirs] of [[g.z[i], z], [g.friction[i], mu], [g.s[i], ss], [g.t[i], tt]]) {
      const want = theirs === 'nan' ? NaN : Number(theirs);
      const d = Number.isNaN(want) && Number.isNaN(ours) ? 0 : Math.abs(ours - want);
      assert.ok(d <= 1e-9, `${mode} point ${i}: ${ours} against ${want}`);
      [compared, exact, worst] = [compared + 1, exact + (d === 0), Math.max(worst, d)];
    }
    met += s[i] >= 100 && s[i] <= 160;
    gripped += mu !== 'nan';
  });
  assert.ok(met > 100 && gripped > 100, `${mode}: the records were met`);
}
console.log(`npm package maps: ${compared} values in 5 modes as opencrg odr eval gives them, ${exact} to the bit, the largest difference ${worst.toExponential(2)}`);
