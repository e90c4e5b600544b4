// The guide's example (docs/web.md) runs as written, importing the package by its name.
//   node guide.mjs PACKAGE REPO WORK
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, symlinkSync, writeFileSync, rmSync } from 'node:fs';
import { join, resolve } from 'node:path';

const [pkg, repo, work] = process.argv.slice(2).map((p) => resolve(p));
const text = readFileSync(join(repo, 'docs/web.md'), 'utf8');
const code = text.slice(text.indexOf('## The npm package')).match(/```js\n([\s\S]*?)```/)[1];
rmSync(work, { recursive: true, force: true });
mkdirSync(join(work, 'node_modules'), { recursive: true });
symlinkSync(pkg, join(work, 'node_modules', 'opencrg'));
writeFileSync(join(work, 'example.mjs'), code);
const out = execFileSync('node', [join(work, 'example.mjs')], { cwd: repo, encoding: 'utf8' });
if (!out.includes('road: 0') || !out.includes('NaN Uint8Array(1) [ 1 ]')) throw new Error(`unexpected output:\n${out}`);
console.log('the guide\'s npm example runs');
