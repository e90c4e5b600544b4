// The npm package's speed in Node: uvToZ on a road (one call over N points, a contact
// point of the call's own) and map.ground on a map, both over the points of files that
// bench/wasm_native.c reads too (written here the first time). Prints ns per point, of
// the second call and of the first.
//   node wasm_speed.mjs PACKAGE ROAD MAP DIR
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [pkg, roadFile, mapFile, dir] = process.argv.slice(2);
const { Road, odr } = await import(pathToFileURL(join(pkg, 'index.js')).href);
const N = 1_000_000;
let seed = 12345;
const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);

const road = Road.fromBytes(readFileSync(roadFile), roadFile);
road.applyModifiers();
const map = odr.Map.fromBytes(readFileSync(mapFile), {}, mapFile);
const points = (name, make) => {
  const path = join(dir, name);
  if (!existsSync(path)) writeFileSync(path, make());
  const b = readFileSync(path);
  const all = new Float64Array(b.buffer, b.byteOffset, b.length / 8);
  return [all.subarray(0, all.length / 2), all.subarray(all.length / 2)];
};
const [u, v] = points('road_points.f64', () => {
  const [[u0, u1], [v0, v1]] = [road.uRange, road.vRange];
  const out = new Float64Array(2 * N);
  for (let i = 0; i < N; i++) [out[i], out[N + i]] = [u0 + random() * (u1 - u0), v0 + random() * (v1 - v0)];
  return out;
});
const ids = map.roadIds;
const lengths = map.roadLengths;
const [x, y] = points('map_points.f64', () => {
  // Points on the map's roads: a random road, s, and t within 3 m of its reference line.
  const out = new Float64Array(2 * (N / 10));
  for (let i = 0; i < N / 10; i++) {
    const k = Math.floor(random() * ids.length);
    const [px, py] = map.stToXyz(ids[k], random() * lengths[k], (random() - 0.5) * 6);
    [out[i], out[N / 10 + i]] = [px, py];
  }
  return out;
});
// Each call timed twice: the first runs on V8's baseline code of the .wasm (optimised
// code replaces it in the background) and grows the module's memory; the second is what a
// longer session sees.
const timed = (f, n) => {
  const t = performance.now();
  const answer = f();
  return [answer, ((performance.now() - t) * 1e6) / n];
};
const [, roadFirst] = timed(() => road.uvToZ(u, v), N);
const [z, roadNs] = timed(() => road.uvToZ(u, v), N);
const [, mapFirst] = timed(() => map.ground(x, y), x.length);
const [g, mapNs] = timed(() => map.ground(x, y), x.length);
let [sz, sg] = [0, 0];
for (const h of z) if (Number.isFinite(h)) sz += h;
for (const h of g.z) if (Number.isFinite(h)) sg += h;
console.log(`wasm: ${roadNs.toFixed(1)} ns per uvToZ point, ${mapNs.toFixed(1)} ns per map.ground point (sums ${sz.toFixed(3)} ${sg.toFixed(3)}); first calls ${roadFirst.toFixed(1)}, ${mapFirst.toFixed(1)}`);
