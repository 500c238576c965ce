// The Atlas mode (a tab over the view, modes.js): the texture atlas of the mesh on display, made in the
// worker by the package's mesh.atlas(). The 3D view shows the mesh split along the atlas's seams with
// each chart in its colour (or a checkerboard or the user's image through the atlas uv) and the seams
// drawn; the side slot beside the view shows the packed layout in the same colours (atlas-layout.js);
// the sidebar's Atlas panel has the options, the core's metrics and the downloads (atlas-export.js).
//
// The atlas's objects live on their own camera layer: entering the mode makes the camera see only that
// layer, so whatever the surface mode draws (surface, wireframe, paths, planes; added at any time) is
// hidden without being touched, and comes back as it was on leaving.
//
// An atlas is made on entering the mode (once per mesh; a large mesh waits for the button), and again
// when an option changes. Progress and Cancel are the page's (progress-view.js, session.js); a new mesh
// drops the atlas on display.
//
// What it has on display, as plain data, is status() (main.js puts it in the page's observable state:
// atlas, atlasError, atlases; docs/PAGE.md).

import * as THREE from 'three';
import { toSeamSplitGeometry } from 'straightest/three';
import { pageModes } from './modes.js';
import { latest } from './latest.js';
import { isCancelled } from './requests.js';
import { SEAM_COLOR, checkerboardCanvas, surfaceTexture } from './uv-layout.js';
import { chartColor, chartCss, chartPaths, drawAtlasLayout } from './atlas-layout.js';
import { createAtlasExport } from './atlas-export.js';
import { formatCount, formatMetric, formatMs, formatPercent } from './param-format.js';
import { summarizeAtlas } from './results-summary.js';

const $ = (id) => document.getElementById(id);

const ATLAS_LAYER = 1; // the camera layer of the atlas's objects (the surface mode draws on layer 0)
// Above this many vertices entering the mode does not make the atlas unasked (the button does).
const LARGE_MESH_VERTICES = 300_000;
const RERUN_DELAY_MS = 300; // an option's change makes the atlas again once the options stay put this long
const CHECKER_CELLS = 32; // the checkerboard over the whole atlas: every chart at one texel density, so equal squares

/** The options in the panel, or { error, field } when one is not a value the atlas takes. */
export function readAtlasOptions({ maxStretch, minHullFill = '0.75', resolution, padding }) {
  const given = (text) => (String(text).trim() ? `“${text}”` : 'empty or not a number');
  const stretch = Number(maxStretch);
  if (!(String(maxStretch).trim() && stretch > 1 && stretch <= 10)) {
    return {
      error: `Max stretch must be above 1 and at most 10 (1.02 keeps charts nearly isometric); it is ${given(maxStretch)}.`,
      field: 'atlas-max-stretch',
    };
  }
  const fill = Number(minHullFill);
  if (!(String(minHullFill).trim() && fill >= 0 && fill <= 1)) {
    return {
      error: `Min hull fill must be from 0 to 1 (0.75 splits concave charts so they pack tighter); it is ${given(minHullFill)}.`,
      field: 'atlas-min-hull-fill',
    };
  }
  const pad = Number(padding);
  if (!(String(padding).trim() && Number.isInteger(pad) && pad >= 0 && pad <= 64)) {
    return {
      error: `Padding must be a whole number of texels from 0 to 64; it is ${given(padding)}.`,
      field: 'atlas-padding',
    };
  }
  return { options: { maxStretch: stretch, minHullFill: fill, resolution: Number(resolution), padding: pad } };
}

/** session: session.js; view: scene.js; surface: surface-view.js (the mesh's arrays on display). */
export function createAtlasMode({ session, view, surface }) {
  let shown = null; // { reply, geometry (seam-split, uv + chart colours), paths (Path2D per chart) }
  let running = false; // an atlas request is in flight
  let wanted = false; // the mode is on (its tab selected)
  const runs = latest(); // only the most recent atlas request may update the view
  let rerunTimer = 0;
  // For status(): the metrics of the atlas on display (null when none), its last failure's { message,
  // category } (null once one is shown or the mesh changes), and how many atlases were shown.
  const status = { atlas: null, atlasError: null, atlases: 0 };

  // ---------------------------------------------------------------- 3D objects (on ATLAS_LAYER)

  const material = new THREE.MeshStandardMaterial({
    roughness: 0.75,
    metalness: 0,
    side: THREE.DoubleSide,
    polygonOffset: true,
    polygonOffsetFactor: 1.5,
    polygonOffsetUnits: 2, // the seams on top
  });
  const seamMaterial = new THREE.LineBasicMaterial({ color: SEAM_COLOR });
  const group = new THREE.Group();
  group.layers.set(ATLAS_LAYER);
  view.scene.add(group);
  let meshObject = null;
  let seamObject = null;

  function onLayer(object) {
    object.layers.set(ATLAS_LAYER);
    group.add(object);
    return object;
  }

  function clearObjects() {
    for (const object of [meshObject, seamObject]) {
      if (!object) continue;
      group.remove(object);
      object.geometry.dispose();
    }
    meshObject = seamObject = null;
    view.requestRender();
  }

  /** The surface split along the atlas's seams (one vertex per mesh vertex and corner uv), coloured by chart. */
  function atlasGeometry(reply) {
    const geometry = surface.mesh.geometry;
    const split = toSeamSplitGeometry(
      {
        positions: () => geometry.getAttribute('position').array,
        vertexNormals: () => geometry.getAttribute('normal').array,
        indices: () => geometry.index.array,
      },
      reply,
    );
    // A split vertex belongs to one chart (charts never share a uv), so per-vertex colours are per chart.
    const linear = new Float32Array(3 * reply.charts); // each chart's colour in the renderer's linear space
    const color = new THREE.Color();
    for (let k = 0; k < reply.charts; k++) {
      const [r, g, b] = chartColor(k);
      color.setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace).toArray(linear, 3 * k);
    }
    const index = split.index.array;
    const colors = new Float32Array(3 * split.getAttribute('position').count);
    for (let c = 0; c < index.length; c++) {
      const k = 3 * reply.chartOfFace[Math.floor(c / 3)];
      colors.set(linear.subarray(k, k + 3), 3 * index[c]);
    }
    split.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    return split;
  }

  /** The seam edges (vertex pairs of the mesh) as lines on the surface. */
  function seamGeometry(seam) {
    const position = surface.mesh.geometry.getAttribute('position');
    const points = new Float32Array(3 * seam.length);
    seam.forEach((v, i) => points.set([position.getX(v), position.getY(v), position.getZ(v)], 3 * i));
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', new THREE.BufferAttribute(points, 3));
    return lines;
  }

  // ---------------------------------------------------------------- textures

  const maxAnisotropy = view.renderer.capabilities.getMaxAnisotropy();
  let checkerTexture = null;
  let imageTexture = null;

  const configureTexture = (texture) => surfaceTexture(texture, maxAnisotropy);

  /** The material from the Show menu: chart colours, or the checkerboard / image through the atlas uv. */
  function updateMaterial() {
    const display = $('atlas-display').value;
    let map = null;
    if (display === 'checker')
      map = checkerTexture ??= configureTexture(new THREE.CanvasTexture(checkerboardCanvas(1024, CHECKER_CELLS)));
    if (display === 'image') map = imageTexture;
    material.vertexColors = map === null;
    material.map = map;
    material.needsUpdate = true;
    if (seamObject) seamObject.visible = $('atlas-seams-toggle').checked;
    view.requestRender();
  }

  async function loadImage(file) {
    const url = URL.createObjectURL(file);
    try {
      const loaded = configureTexture(await new THREE.TextureLoader().loadAsync(url));
      imageTexture?.dispose();
      imageTexture = loaded;
      const option = $('atlas-display').querySelector('option[value="image"]');
      option.disabled = false;
      option.textContent = `Image: ${file.name}`;
      $('atlas-display').value = 'image';
      updateMaterial();
    } catch {
      showNote(`“${file.name}” is not an image the browser can read.`, 'error');
    } finally {
      URL.revokeObjectURL(url);
    }
  }

  // ---------------------------------------------------------------- panel and layout

  const layoutCanvas = $('atlas-canvas');
  let layoutMessage = 'No atlas yet.';

  function redrawLayout() {
    if (!wanted) return; // the side slot is hidden: nothing to size the canvas by
    const atlas = shown && { paths: shown.paths, width: shown.reply.width, height: shown.reply.height };
    drawAtlasLayout(layoutCanvas, atlas, layoutMessage);
  }
  new ResizeObserver(() => redrawLayout()).observe(layoutCanvas);

  function showNote(text, kind = 'note') {
    const note = $('atlas-message');
    note.textContent = text;
    note.className = kind;
    note.hidden = !text;
  }

  function setStat(field, text, className = '', title = '') {
    const dd = $(`atlas-${field}`);
    dd.textContent = text;
    dd.className = className;
    if (title) dd.title = title;
    else dd.removeAttribute('title');
  }

  function clearStats() {
    for (const field of [
      'charts',
      'l2',
      'linf',
      'utilization',
      'flipped',
      'mirrored',
      'overlaps',
      'gap',
      'seam',
      'size',
      'time',
    ]) {
      setStat(field, '–');
    }
    $('atlas-side-size').textContent = '';
    $('atlas-caption').textContent = '';
  }

  /** The core's metrics, as the page writes numbers (param-format.js); zero is good for the counts. */
  function showStats(reply) {
    const count = (field, n, title) => setStat(field, formatCount(n), n ? 'bad' : 'good', title);
    setStat(
      'charts',
      formatCount(reply.charts),
      '',
      `${reply.splits} splits, ${reply.merges} merges` +
        `${reply.nonDiskCharts ? `; ${reply.nonDiskCharts} charts are not disks` : ''}` +
        `${reply.capped ? '; the chart cap stopped a split (a chart may exceed the max stretch)' : ''}`,
    );
    setStat('l2', formatMetric(reply.stretch.l2), 'strong', `L2 stretch ${reply.stretch.l2}`);
    setStat('linf', formatMetric(reply.stretch.linf), '', `L∞ stretch ${reply.stretch.linf}`);
    setStat('utilization', formatPercent(reply.utilization), '', `uv area ÷ atlas area = ${reply.utilization}`);
    count('flipped', reply.flipped, `${reply.degenerate} degenerate faces`);
    count('mirrored', reply.mirrored, 'charts whose uv is wound against their 3D faces');
    count('overlaps', reply.overlaps, 'pairs of charts that overlap (an independent check of the uv)');
    setStat(
      'gap',
      formatMetric(reply.minGapTexels),
      reply.paddingViolations ? 'bad' : '',
      `${reply.paddingViolations} pairs of charts closer than the padding`,
    );
    setStat(
      'seam',
      `${formatCount(reply.seamEdges)} · ${formatMetric(reply.seamLength)}`,
      '',
      'mesh edges whose two sides have different uv, and their 3D length',
    );
    setStat(
      'size',
      `${reply.width} × ${reply.height} · ${formatMetric(reply.texelsPerUnit)}`,
      '',
      'the atlas in texels, and texels per unit of 3D length',
    );
    const t = reply.timings;
    setStat(
      'time',
      `${formatMs(t.charts, '')} / ${formatMs(t.pack, '')} / ${formatMs(t.measure, '')} / ${formatMs(t.total)}`,
      '',
      `${formatMs(reply.timeMs)} in the worker, with the transfer`,
    );
    $('atlas-side-size').textContent = `${reply.width} × ${reply.height}`;
    $('atlas-caption').textContent =
      `${formatCount(reply.charts)} charts · ${formatPercent(reply.utilization)} used · ` +
      `L2 ${formatMetric(reply.stretch.l2)} · padding ${shown.options.padding} texels`;
  }

  function setButtons() {
    $('atlas-button').disabled = !surface.mesh;
    for (const id of ['atlas-obj-button', 'atlas-glb-button', 'atlas-png-button', 'atlas-svg-button'])
      $(id).disabled = !shown;
  }

  // ---------------------------------------------------------------- making the atlas

  /** The options in the panel, marking a field that is not valid (null then, with the error shown). */
  function options() {
    for (const id of ['atlas-max-stretch', 'atlas-min-hull-fill', 'atlas-padding'])
      $(id).removeAttribute('aria-invalid');
    const read = readAtlasOptions({
      maxStretch: $('atlas-max-stretch').value,
      minHullFill: $('atlas-min-hull-fill').value,
      resolution: $('atlas-resolution').value,
      padding: $('atlas-padding').value,
    });
    if (!read.error) return read.options;
    $(read.field).setAttribute('aria-invalid', 'true');
    showNote(read.error, 'error');
    status.atlasError = { message: read.error, category: 'invalid_argument' };
    return null;
  }

  async function make() {
    clearTimeout(rerunTimer);
    if (!surface.mesh) return;
    const chosen = options();
    if (!chosen) return;
    const request = runs.begin(session.meshes);
    running = true;
    showNote('Making the atlas…', 'busy');
    $('atlas-panel').dataset.state = 'running';
    try {
      const reply = await session.request('atlas', chosen);
      if (request.stale()) return;
      show(reply, chosen);
    } catch (err) {
      if (request.stale() || isCancelled(err)) return;
      showFailure(err);
    } finally {
      if (!request.stale()) running = false;
    }
  }

  function show(reply, chosen) {
    forget();
    const geometry = atlasGeometry(reply);
    shown = { reply, geometry, options: chosen, paths: chartPaths(reply) };
    meshObject = onLayer(new THREE.Mesh(geometry, material));
    seamObject = onLayer(new THREE.LineSegments(seamGeometry(reply.seam), seamMaterial));
    seamObject.renderOrder = 2;
    updateMaterial();
    status.atlas = {
      charts: reply.charts,
      l2: reply.stretch.l2,
      linf: reply.stretch.linf,
      utilization: reply.utilization,
      width: reply.width,
      height: reply.height,
      texelsPerUnit: reply.texelsPerUnit,
      seamEdges: reply.seamEdges,
      seamLength: reply.seamLength,
      flipped: reply.flipped,
      mirrored: reply.mirrored,
      overlaps: reply.overlaps,
      degenerate: reply.degenerate,
      nonDiskCharts: reply.nonDiskCharts,
      minGapTexels: reply.minGapTexels,
      paddingViolations: reply.paddingViolations,
      capped: reply.capped,
      options: chosen,
      colors: Array.from({ length: reply.charts }, (_, k) => chartCss(k)),
    };
    status.atlasError = null;
    status.atlases += 1;
    showStats(reply);
    summarizeAtlas(reply);
    showNote(reply.capped ? 'The chart cap stopped a split: some chart may stretch more than the max stretch.' : '');
    $('atlas-panel').dataset.state = 'done';
    redrawLayout();
    setButtons();
  }

  function showFailure(err) {
    forget();
    status.atlasError = { message: err.message, category: err.category ?? 'error' };
    showNote(`Cannot make the atlas: ${err.message}`, 'error');
    $('atlas-panel').dataset.state = 'error';
    layoutMessage = 'The atlas failed (see the Atlas panel).';
    redrawLayout();
    setButtons();
  }

  /** Drops the atlas on display. */
  function forget() {
    clearObjects();
    shown = null;
    status.atlas = null;
    summarizeAtlas(null);
    clearStats();
  }

  /** Makes the atlas unless one is on display or coming, or the mesh is large (a note says to press the button). */
  function makeIfWanted() {
    if (!wanted || !surface.mesh || shown || running) return;
    if ((session.info?.vertices ?? 0) > LARGE_MESH_VERTICES) {
      showNote(
        `Large mesh (${formatCount(session.info.vertices)} vertices): press Make atlas to run it — ` +
          'the progress shows over the view and Cancel stops it.',
      );
      layoutMessage = 'Press Make atlas.';
      redrawLayout();
      return;
    }
    make();
  }

  function optionsChanged() {
    clearTimeout(rerunTimer);
    if (!wanted || !surface.mesh) return;
    runs.supersede(); // the run with the old options is dropped when it comes
    running = false;
    rerunTimer = setTimeout(() => make(), RERUN_DELAY_MS);
  }

  // ---------------------------------------------------------------- the mode and the session's events

  pageModes().register({
    id: 'atlas',
    label: 'Atlas',
    side: true,
    enter() {
      wanted = true;
      view.scene.traverse((object) => {
        if (object.isLight) object.layers.enable(ATLAS_LAYER);
      });
      view.camera.layers.set(ATLAS_LAYER);
      view.requestRender();
      redrawLayout();
      makeIfWanted();
    },
    leave() {
      wanted = false;
      view.camera.layers.set(0);
      view.requestRender();
    },
  });

  session.addEventListener('meshchange', () => {
    clearTimeout(rerunTimer);
    runs.supersede();
    running = false;
    forget();
    status.atlasError = null;
    showNote('');
    delete $('atlas-panel').dataset.state;
    layoutMessage = surface.mesh ? 'Making the atlas…' : 'No mesh loaded.';
    redrawLayout();
    setButtons();
  });
  session.addEventListener('meshready', () => makeIfWanted());
  session.addEventListener('cancel', () => {
    runs.supersede();
    if (!running) return;
    running = false;
    showNote('Atlas cancelled — press Make atlas to run it again.');
    $('atlas-panel').dataset.state = shown ? 'done' : 'cancelled';
    if (!shown) {
      layoutMessage = 'Cancelled.';
      redrawLayout();
    }
  });

  // ---------------------------------------------------------------- controls

  const baseName = () => `${(session.label || 'mesh').replace(/\.[^.]+$/, '').replace(/[^\w.-]+/g, '_')}-atlas`;
  const exports = createAtlasExport({ session, shown: () => shown, baseName });
  for (const [id, run, what] of [
    ['atlas-obj-button', exports.obj, 'OBJ'],
    ['atlas-glb-button', exports.glb, 'GLB'],
    ['atlas-png-button', exports.png, 'PNG'],
    ['atlas-svg-button', exports.svg, 'SVG'],
  ]) {
    $(id).addEventListener('click', async () => {
      if (!shown) return;
      $('atlas-export-status').textContent = '';
      try {
        const name = await run();
        $('atlas-export-status').textContent = `Saved ${name}.`;
      } catch (err) {
        if (!isCancelled(err)) $('atlas-export-status').textContent = `Could not export the ${what}: ${err.message}`;
      }
    });
  }
  $('atlas-button').addEventListener('click', () => make());
  for (const id of ['atlas-max-stretch', 'atlas-min-hull-fill', 'atlas-resolution', 'atlas-padding']) {
    $(id).addEventListener('change', () => optionsChanged());
  }
  $('atlas-display').addEventListener('change', () => updateMaterial());
  $('atlas-seams-toggle').addEventListener('change', () => updateMaterial());
  $('atlas-image-input').addEventListener('change', (event) => {
    const [file] = event.target.files;
    if (file) loadImage(file);
    event.target.value = '';
  });

  clearStats();
  setButtons();

  return {
    /** What is on display: { atlas, atlasError, atlases } (a copy: see `status` above). */
    status: () => ({ ...status }),
  };
}
