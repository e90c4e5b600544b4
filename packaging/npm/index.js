// The opencrg npm package: OpenCRG roads and OpenDRIVE maps in WebAssembly. The module
// loads its .wasm itself (in Node from its file, in browsers by fetch), so a plain
// `import` is all it takes.
import init, {
  initSync,
  ContactPoint,
  OdrMap,
  Road,
  decadeLabel,
  elevationColours,
  evaluations,
  figureColours,
  iso8608Classes,
  tickLabel,
  ticks,
} from './opencrg.js';

const wasm = new URL('./opencrg_bg.wasm', import.meta.url);
if (typeof process === 'object' && process.versions && process.versions.node) {
  const { readFileSync } = await import('node:fs');
  initSync({ module: readFileSync(wasm) });
} else {
  await init({ module_or_path: wasm });
}

// The evaluation calls, from the library's one list: road.uvToZ(u, v, options),
// contactPoint.xyToNormal(x, y), ...
evaluations().forEach(({ name }, index) => {
  Road.prototype[name] = function (a, b, options) {
    return this.evaluate(index, a, b, options);
  };
  ContactPoint.prototype[name] = function (a, b) {
    return this.evaluate(index, a, b);
  };
});

// What the library throws: Errors whose `name` is one of these classes' (as Python's
// exception classes): a file that is not found or not read, a file's content, a failed
// check, a request refused (too large for the memory limit, a value out of range).
const parent = {
  CrgError: null,
  NotFoundError: 'CrgError',
  IoError: 'CrgError',
  FormatError: 'CrgError',
  CheckError: 'CrgError',
  RequestError: 'CrgError',
  TooLargeError: 'RequestError',
  OutOfRangeError: 'RequestError',
};
const isKind = (name, kind) => {
  for (let n = name; n; n = parent[n]) if (n === kind) return true;
  return false;
};
const errorClass = (kind) => {
  const c = class extends Error {
    constructor(message) {
      super(message);
      this.name = kind;
    }
    static [Symbol.hasInstance](e) {
      return e instanceof Error && isKind(e.name, kind);
    }
  };
  Object.defineProperty(c, 'name', { value: kind });
  return c;
};
export const CrgError = errorClass('CrgError');
export const NotFoundError = errorClass('NotFoundError');
export const IoError = errorClass('IoError');
export const FormatError = errorClass('FormatError');
export const CheckError = errorClass('CheckError');
export const RequestError = errorClass('RequestError');
export const TooLargeError = errorClass('TooLargeError');
export const OutOfRangeError = errorClass('OutOfRangeError');

export { ContactPoint, Road, evaluations, iso8608Classes };
/** OpenDRIVE maps with CRG surfaces. */
export const odr = { Map: OdrMap, crgFilesOf: OdrMap.crgFilesOf };
/** The drawing rules of the command's figures: colours, ticks and their labels. */
export const drawing = { elevationColours, ticks, tickLabel, decadeLabel, figureColours };
