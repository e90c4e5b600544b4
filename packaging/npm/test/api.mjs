// The npm package's API in Node: numbers and arrays in and out, NaN and `refused` where
// the library refuses, options and modifiers by keyword in any case, errors that are
// `Error`s with the command's message (and the next load works), a road's file
// references from the files given, and the same answers as the opencrg command.
//   OPENCRG_CLI=target/release/opencrg node api.mjs PACKAGE EXAMPLES
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [pkg, examples] = process.argv.slice(2);
const opencrg = await import(pathToFileURL(join(pkg, 'index.js')).href);
const { Road, ContactPoint, drawing, evaluations, iso8608Classes, odr } = opencrg;
const { CrgError, FormatError, NotFoundError, CheckError, RequestError, OutOfRangeError, TooLargeError } = opencrg;
// The error classes tell what is thrown apart, as Python's: `kind` and its parents only.
const kindOf = (f, kind, others) => {
  try {
    f();
  } catch (e) {
    assert.ok(e instanceof Error && e instanceof CrgError && e instanceof kind, `${e.name}: ${e.message}`);
    others.forEach((other) => assert.ok(!(e instanceof other), `${e.name} is not a ${other.name}`));
    return e;
  }
  assert.fail(`no ${kind.name} thrown`);
};
const cli = (args, input) => execFileSync(process.env.OPENCRG_CLI, args, { input, encoding: 'utf8' });
const bytes = readFileSync(join(examples, 'demo_road.crg'));

// A damaged file: an Error with the command's message; the next load works.
const garbage = new Uint8Array([0, 1, 2, 36, 36, 36, 36, 10, 120]);
assert.throws(() => Road.fromBytes(garbage, 'garbage.crg'), (e) => e instanceof Error && /garbage\.crg/.test(e.message));
kindOf(() => Road.fromBytes(garbage, 'garbage.crg'), FormatError, [RequestError, CheckError, NotFoundError]);
const road = Road.fromBytes(bytes, 'demo_road.crg');
road.check();
road.applyModifiers();
assert.deepEqual([...road.uRange], [0, 120]);
assert.equal(road.closedTrack, null);
assert.equal(road.header.format, 'LRFI');
assert.equal(road.grid.length, 241 * 25);
assert.match(road.info('demo_road.crg'), /241 cross sections x 25 long sections/);

// Numbers in, numbers out; arrays in, Float64Arrays out; the command's answers.
const u = Float64Array.from({ length: 50 }, (_, i) => -5 + i * 2.7);
const v = Float64Array.from({ length: 50 }, (_, i) => -3.5 + (i % 15) * 0.5);
const z = road.uvToZ(u, v);
assert.ok(z instanceof Float64Array && z.length === 50);
assert.equal(typeof road.uvToZ(10, 0.5), 'number');
const lines = cli(['eval', join(examples, 'demo_road.crg')], [...u].map((a, i) => `${a} ${v[i]}\n`).join(''));
const rows = lines.trim().split('\n').slice(1).map((l) => l.split(',').map(Number));
// (Within 1e-9 m: the platform's sine and cosine may differ from glibc's in the last bit,
// see docs/web.md.)
const close = (a, b) => assert.ok(Math.abs(a - b) <= 1e-9 || (Number.isNaN(a) && Number.isNaN(b)), `${a} against ${b}`);
const [x, y] = road.uvToXy(u, v);
rows.forEach(([, , cx, cy, cz], i) => {
  close(x[i], cx);
  close(y[i], cy);
  close(z[i], cz);
});

// Every evaluation of the library's list is a method of roads and contact points, declared
// in the types of both.
const types = readFileSync(join(pkg, 'index.d.ts'), 'utf8');
assert.equal(evaluations().length, 8);
for (const { name, inputs, outputs } of evaluations()) {
  assert.equal(typeof Road.prototype[name], 'function', name);
  assert.equal(typeof ContactPoint.prototype[name], 'function', name);
  assert.equal(types.split(`  ${name}<T extends Coordinates>(${inputs[0]}: T, ${inputs[1]}: Like<T>`).length, 3, name);
  const answer = road[name](10.5, 0.25);
  assert.equal(outputs.length === 1 ? typeof answer : answer.length, outputs.length === 1 ? 'number' : outputs.length, name);
}
// xyToNormal: uvToNormal at the point's u/v.
for (const [px, py] of [[20, 3], [55.5, -1], [100, 1.5]]) {
  const [pu, pv] = road.xyToUv(px, py);
  assert.deepEqual(road.xyToNormal(px, py), road.uvToNormal(pu, pv));
}

// Options by keyword in any case; a refusal is NaN, and `refused` says which.
const cp = new ContactPoint(road, { border_mode_u: 0, Border_Mode_V: 0 });
assert.ok(Number.isNaN(cp.uvToZ(-10, 0)));
assert.deepEqual([...cp.refused], [1]);
assert.ok(!Number.isNaN(cp.uvToZ(10, 0)));
assert.deepEqual([...cp.refused], [0]);
const some = cp.uvToZ(new Float64Array([10, -10, 20]), new Float64Array([0, 0, 0]));
assert.ok(!Number.isNaN(some[0]) && Number.isNaN(some[1]) && !Number.isNaN(some[2]));
assert.deepEqual([...cp.refused], [0, 1, 0]);
assert.throws(() => new ContactPoint(road, { BORDER_MODE_W: 1 }), /unknown option 'BORDER_MODE_W'/);
// A choice out of range: refused with the C API's message (Python and the FMU say the same).
assert.throws(() => new ContactPoint(road, { BORDER_MODE_V: 99 }), { message: '<border mode v> = 99 is not one of its choices 0 to 4' });
assert.throws(() => cp.setOption('refline_continuation', -1), { message: '<refline continuation mode> = -1 is not one of its choices 0 to 1' });
assert.throws(() => road.setModifier('SCALE_Q', 1), /unknown modifier 'SCALE_Q'/);
road.setModifier('scale_z_grid', 2);
assert.throws(() => road.uvToZ([1, 2], [1]), /u has 2 values, v 1/);
kindOf(() => road.uvToZ([1, 2], [1]), RequestError, [OutOfRangeError, TooLargeError, FormatError]);
kindOf(() => new ContactPoint(road, { BORDER_MODE_V: 99 }), OutOfRangeError, [TooLargeError, FormatError]);
assert.ok(!(new Error('plain') instanceof CrgError) && new OutOfRangeError('made') instanceof RequestError);

// File references from the files given.
const top = new TextEncoder().encode('$ROAD_CRG_FILE\n roads/demo_road.crg\n$\n');
const referencing = Road.fromBytes(top, 'top.crg', { files: { 'roads/demo_road.crg': bytes } });
assert.equal(referencing.grid.length, 241 * 25);
assert.throws(() => Road.fromBytes(top, 'top.crg', { files: {} }), /demo_road\.crg/);
kindOf(() => Road.fromBytes(top, 'top.crg', { files: {} }), NotFoundError, [FormatError, RequestError]);

// A map from bytes with its CRG file.
const map = odr.Map.fromBytes(readFileSync(join(examples, 'demo_map.xodr')), { 'demo_road.crg': bytes }, 'demo_map.xodr');
assert.deepEqual(map.roadIds, ['1', '2']);
assert.deepEqual(map.check(), []);
const g = map.ground(20, -2);
const [ez, ef, eroad, es, et] = cli(['odr', 'eval', join(examples, 'demo_map.xodr')], '20 -2\n').trim().split(' ');
assert.equal(map.roadIds[g.road], eroad);
[[g.z, ez], [g.friction, ef], [g.s, es], [g.t, et]].forEach(([a, b]) => close(a, Number(b)));
assert.ok(Number.isNaN(map.ground(1e6, 1e6).z));
assert.throws(() => odr.Map.fromBytes(readFileSync(join(examples, 'demo_map.xodr')), {}), /demo_road\.crg/);
// Roughness as the command gives it: IRI, PSD bands, class; the ISO 8608 classes.
const plain = Road.fromBytes(bytes, 'demo_road.crg');
plain.applyModifiers();
const rough = plain.roughness();
const expected = JSON.parse(cli(['roughness', '--json', join(examples, 'demo_road.crg')])).tracks;
assert.equal(rough.length, expected.length);
rough.forEach((t, i) => {
  close(t.iri, expected[i].iri);
  assert.equal(t.iso8608, expected[i].psd.class);
  assert.equal(t.bands.length, expected[i].psd.bands.length);
  t.bands.forEach(([n, gd], k) => {
    close(n, expected[i].psd.bands[k][0]);
    assert.ok(Math.abs(gd - expected[i].psd.bands[k][1]) <= 1e-9 * Math.abs(gd), `band ${k}`);
  });
});
const classes = iso8608Classes();
assert.equal(classes.n0, 0.1);
assert.equal(classes.classes, 'ABCDEFGH');
assert.equal(classes.limits.length, 7);
classes.limits.slice(1).forEach((l, k) => close(l / classes.limits[k], 4));
// The map's CRG files from the map crate; the drawing rules of the command's figures.
assert.deepEqual(odr.crgFilesOf(readFileSync(join(examples, 'demo_map.xodr')), 'demo_map.xodr'), ['demo_road.crg']);
assert.deepEqual([...drawing.elevationColours(new Float64Array([0, 1, -2]))], [48, 18, 59, 254, 247, 160, 48, 18, 59]);
assert.deepEqual([...drawing.ticks(0, 10, 6)], [0, 2, 4, 6, 8, 10]);
assert.equal(drawing.tickLabel(0.30000000000000004), '0.3');
assert.equal(drawing.decadeLabel(1e-6), '10\u207B\u2076');
assert.equal(drawing.figureColours().tracks[0], 'rgb(30,90,200)');
console.log('npm package API: ok');
