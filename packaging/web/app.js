// The page: opens a CRG file, or an OpenDRIVE map with its CRG files, in the browser (the
// npm package's WebAssembly), shows what `opencrg info` / `odr info` say and a top view
// coloured by height, and reads the surface where it is clicked. `?road=URL&probe=X,Y`
// opens a road or map by URL (a map's CRG files relative to it) and writes the answer at
// x/y into #probe: "z u v" for a CRG file, "z friction road s t" for a map. What is open
// lives in `page` below, nowhere else; figures.js draws, shown.js reads the road or map.
import { odr } from './index.js';
import { roughnessFigure } from './figures.js';
import { answer, drawTop, open, roughness, sections, viewPage } from './shown.js';

const $ = (id) => document.getElementById(id);

/** The page's parts wired to what is open: `show(files)` opens and draws. */
function page() {
  let shown = null; // what is open (shown.js)
  let frame = null; // where x/y lie on the top view

  const fail = (e) => {
    $('error').textContent = e instanceof Error ? e.message : String(e);
  };

  /** Opens files (`{name: Uint8Array}`); how long reading and drawing took goes to #timing. */
  const show = (files) => {
    const started = performance.now();
    $('error').textContent = '';
    const [next, info] = open(files);
    $('info').textContent = info;
    const read = performance.now();
    shown = next;
    frame = drawTop(shown, $('top'));
    if (shown.kind === 'road') {
      const [u0, u1] = shown.road.uRange;
      sections(shown, $('along'), $('across'), 0.5 * (u0 + u1), 0);
      try {
        const [table, tracks] = roughness(shown);
        $('roughness').textContent = table;
        roughnessFigure($('rough'), tracks, shown.name);
      } catch (e) {
        $('roughness').textContent = `roughness: ${e.message}`;
      }
    }
    $('road-only').style.display = shown.kind === 'road' ? '' : 'none';
    $('timing').textContent = `read ${(read - started).toFixed(0)} ms, drawn ${(performance.now() - read).toFixed(0)} ms`;
  };

  /** The 3D view of `opencrg view` / `opencrg odr view` (the same page) in the frame. */
  const show3d = () => {
    const view = $('view3d');
    try {
      view.srcdoc = viewPage(shown);
      view.style.display = '';
      $('top').style.display = 'none';
    } catch (e) {
      fail(e);
    }
  };

  $('show-3d').addEventListener('click', () => shown && show3d());
  $('show-top').addEventListener('click', () => {
    $('view3d').style.display = 'none';
    $('top').style.display = '';
  });

  $('top').addEventListener('click', (event) => {
    if (!shown) return;
    const rect = event.target.getBoundingClientRect();
    const f = frame;
    const px = ((event.clientX - rect.left) * event.target.width) / rect.width - f.left;
    const py = ((event.clientY - rect.top) * event.target.height) / rect.height - f.top;
    const [x, y] = [f.x0 + px * f.m, f.y1 - py * f.m];
    const a = answer(shown, x, y).split(' ');
    if (shown.kind === 'road' && Number.isFinite(+a[1])) sections(shown, $('along'), $('across'), +a[1], +a[2]);
    $('readout').textContent =
      shown.kind === 'road'
        ? `x ${x.toFixed(3)} y ${y.toFixed(3)} z ${(+a[0]).toFixed(4)} u ${(+a[1]).toFixed(3)} v ${(+a[2]).toFixed(3)}`
        : `x ${x.toFixed(3)} y ${y.toFixed(3)} z ${(+a[0]).toFixed(4)} friction ${a[1]} road ${a[2]} s ${(+a[3]).toFixed(3)} t ${(+a[4]).toFixed(3)}`;
  });

  const read = async (fileList) => {
    const files = {};
    for (const f of fileList) files[f.webkitRelativePath || f.name] = new Uint8Array(await f.arrayBuffer());
    return files;
  };
  for (const id of ['files', 'folder']) {
    $(id).addEventListener('change', async (e) => {
      try {
        show(await read(e.target.files));
      } catch (err) {
        fail(err);
      }
    });
  }
  const drop = $('drop');
  drop.addEventListener('dragover', (e) => (e.preventDefault(), drop.classList.add('over')));
  drop.addEventListener('dragleave', () => drop.classList.remove('over'));
  drop.addEventListener('drop', async (e) => {
    e.preventDefault();
    drop.classList.remove('over');
    try {
      show(await read(e.dataTransfer.files));
    } catch (err) {
      fail(err);
    }
  });

  /** `?road=URL&probe=X,Y` (`&view=3d`: the 3D view first). */
  const fromAddress = async (params) => {
    const started = performance.now();
    try {
      const url = new URL(params.get('road'), location.href);
      const fetchBytes = async (u) => {
        const r = await fetch(u);
        if (!r.ok) throw new Error(`${u}: ${r.status} ${r.statusText}`);
        return new Uint8Array(await r.arrayBuffer());
      };
      const name = decodeURIComponent(url.pathname.split('/').pop());
      const files = { [name]: await fetchBytes(url) };
      if (name.toLowerCase().endsWith('.xodr')) {
        for (const file of odr.crgFilesOf(files[name], name)) {
          files[file] = await fetchBytes(new URL(file, url));
        }
      }
      const fetched = performance.now();
      show(files);
      $('timing').textContent = `fetched ${(fetched - started).toFixed(0)} ms, ${$('timing').textContent}`;
      if (params.get('view') === '3d') show3d();
      if (params.get('probe')) {
        const [x, y] = params.get('probe').split(',').map(Number);
        $('probe').textContent = answer(shown, x, y);
      }
    } catch (err) {
      fail(err);
    }
  };
  const params = new URLSearchParams(location.search);
  if (params.get('road')) fromAddress(params);
}

page();
