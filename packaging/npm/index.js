// The opencrg npm package: OpenCRG roads and OpenDRIVE maps in WebAssembly. The module
// loads its .wasm itself (in Node from its file, in browsers by fetch), so a plain
// `import` is all it takes.
import init, { initSync, ContactPoint, OdrMap, Road, iso8608Classes } from './opencrg.js';

const wasm = new URL('./opencrg_bg.wasm', import.meta.url);
if (typeof process === 'object' && process.versions && process.versions.node) {
  const { readFileSync } = await import('node:fs');
  initSync({ module: readFileSync(wasm) });
} else {
  await init({ module_or_path: wasm });
}

export { ContactPoint, Road, iso8608Classes };
/** OpenDRIVE maps with CRG surfaces. */
export const odr = { Map: OdrMap };
