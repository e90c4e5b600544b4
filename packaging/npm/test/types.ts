// Every documented call of the npm package, type-checked against its index.d.ts
// (`tsc --strict --noEmit`, test.sh): a declaration that is missing or that disagrees with
// the guide's use (docs/web.md) fails here. Never run: it only has to compile.
import { ContactPoint, Road, drawing, evaluations, iso8608Classes, odr } from './index.js';
import { CheckError, CrgError, FormatError, IoError, NotFoundError } from './index.js';
import { OutOfRangeError, RequestError, TooLargeError } from './index.js';

declare const bytes: Uint8Array;

const road: Road = Road.fromBytes(bytes, 'demo_road.crg', { compat: '2.0.1', files: { 'a.crg': bytes } });
road.check();
road.setModifier('SCALE_Z_GRID', 2);
road.clearModifiers();
road.applyModifiers();
const ranges: Float64Array[] = [road.uRange, road.vRange, road.increments, road.closedTrackReport, road.v];
const closed: Float64Array | null = road.closedTrack;
const grid: Float32Array = road.grid;
const format: unknown = road.header.format;
const text: string = road.info('demo_road.crg') + road.viewPage('demo_road.crg', 1000);

// Numbers in, numbers out; arrays in, Float64Arrays out; with options for the call.
const z: number = road.uvToZ(10, 0.5, { BORDER_MODE_U: 0 });
const zs: Float64Array = road.xyToZ(new Float64Array([1, 2]), [3, 4]);
const [x, y]: [number, number] = road.uvToXy(10, 0.5);
const [u, v]: [Float64Array, Float64Array] = road.xyToUv([1], [2]);
const [phi, curv]: [number, number] = road.uvToPk(10, 0.5);
const pk: [number, number] = road.xyToPk(x, y, { CURV_MODE: 1 });
const [nz, nx, ny, nn]: [number, number, number, number] = road.uvToNormal(10, 0.5);
const normals: Float64Array[] = road.xyToNormal(zs, zs);
const any: number | Float64Array | Array<number | Float64Array> = road.evaluate(0, 10, 0.5);

const cp = new ContactPoint(road, { border_mode_v: 0 });
cp.setOption('REFLINE_CONTINUATION', 1);
const options: Record<string, number> = cp.options;
const refused: Uint8Array = cp.refused;
const cpAnswers: number[] = [
  cp.uvToZ(1, 2),
  cp.xyToZ(1, 2),
  ...cp.uvToXy(1, 2),
  ...cp.xyToUv(1, 2),
  ...cp.uvToPk(1, 2),
  ...cp.xyToPk(1, 2),
  ...cp.uvToNormal(1, 2),
  ...cp.xyToNormal(1, 2),
];
cp.free();

const rough = road.roughness([-0.85, 0, 0.85], 100);
const first: number | null = rough[0].segments[0].iri;
const band: [number, number] = rough[0].bands[0];
const classes: string = iso8608Classes().classes + rough[0].iso8608;
const calls: string[] = evaluations().map((e) => e.name + e.inputs.join() + e.outputs.join());

const map = odr.Map.fromBytes(bytes, { 'demo_road.crg': bytes }, 'demo_map.xodr');
const ground = map.ground(20, -2);
const at: number[] = [ground.z, ground.friction, ground.road, ground.lane, ground.s, ground.t];
const many: Float64Array = map.ground([20], [-2]).z;
const [mx, my, mz]: [number, number, number] = map.normal(20, -2);
const surface: [Float64Array, Float64Array, Float64Array] = map.stToXyz('1', [1, 2], [0, 0]);
const findings: string[] = map.check();
const ids: string[] = map.roadIds;
const lengths: Float64Array = map.roadLengths;
const mapText: string = map.info() + map.viewPage('demo_map.xodr', 0.01);
const named: string[] = odr.crgFilesOf(bytes, 'demo_map.xodr');

const rgb: Uint8Array = drawing.elevationColours(new Float64Array([0, 0.5, 1]));
const steps: Float64Array = drawing.ticks(0, 10, 6);
const labels: string = drawing.tickLabel(0.5) + drawing.decadeLabel(1e-6);
const css: string[] = drawing.figureColours().tracks.concat(drawing.figureColours().reference);
map.free();
road.free();

// Errors told apart by class.
let kind = '';
try {
  Road.fromBytes(bytes);
} catch (e) {
  if (e instanceof FormatError || e instanceof NotFoundError || e instanceof IoError) kind = `file: ${e.message}`;
  else if (e instanceof CheckError) kind = 'check';
  else if (e instanceof OutOfRangeError || e instanceof TooLargeError) kind = e.name;
  else if (e instanceof RequestError || e instanceof CrgError) kind = e.message;
}

// @ts-expect-error: a number for each coordinate, or arrays for both
road.uvToZ('10', 0.5);
// @ts-expect-error: the library's calls only
road.uvToFriction(10, 0.5);

export const used = [ranges, closed, grid, format, text, z, u, v, phi, curv, pk, nz, nx, ny, nn, normals, any];
export const alsoUsed = [options, refused, cpAnswers, first, band, classes, calls, at, many, mx, my, mz];
export const mapUsed = [surface, findings, ids, lengths, mapText, kind];
