// The opencrg npm package: OpenCRG roads and OpenDRIVE maps in WebAssembly. The module
// loads its .wasm itself (in Node from its file, in browsers by fetch), so a plain
// `import` is all it takes.
import init, { initSync, ContactPoint, OdrMap, Road, evaluations, iso8608Classes } from './opencrg.js';

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

export { ContactPoint, Road, evaluations, iso8608Classes };
/** OpenDRIVE maps with CRG surfaces. */
export const odr = { Map: OdrMap };
