// The parameterization part of the page: the "Parameterization", "UV layout" and "Compare" panels,
// the texture on the 3D mesh (a checkerboard or the user's image) and the per-face stretch heat map.
// The worker computes everything (uv, stretch, metrics, the comparison, the OBJ text); this module
// only shows its arrays: it sets them as three.js attributes, draws the 2D layout and fills tables.
//
// main.js creates the view once with createParamView(context) and tells it when the mesh changes
// (meshChanged, right after the new geometry is shown) and when the mesh's paths are drawn
// (meshReady: the automatic first parameterization, kept out of the initial load).
//
// Test hooks (on window.__straightest): param = { boundary, weights, l2, linf, bijective, flipped }
// after each parameterization (null before and after a failure), paramError = { message, category }
// of the last failure, parameterizations (a counter), compare = the rows of the last comparison.

import * as THREE from 'three';
import { applyUV } from 'straightest/three';
import {
  BOUNDARY_COLORS, STRETCH_INFINITE, checkerboardCanvas, drawLayout, stretchGradient, stretchRgb,
} from './uv-layout.js';

const $ = (id) => document.getElementById(id);

const WEIGHT_LABELS = {
  'shape-preserving': 'shape-preserving',
  'mean-value': 'mean value',
  cotan: 'cotan',
  uniform: 'uniform',
};

/** Metrics close to 1 differ in the third decimal: four significant digits; ∞ for Infinity. */
function formatMetric(x) {
  if (x === Infinity) return '∞';
  if (!Number.isFinite(x)) return String(x);
  if (Math.abs(x) >= 1000) return x.toFixed(0);
  return x.toPrecision(4);
}

function formatMs(ms, unit = ' ms') {
  return (ms >= 100 ? ms.toFixed(0) : ms.toFixed(1)) + unit;
}

/** Saves `blob` under `name` through a temporary download link. */
function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 30_000);
}

/**
 * context: { request(type, payload, transfer, onProgress), hooks, scene, renderer, surface(),
 *            generation(), label(), pathSource(), surfaceChanged(), requestRender() }
 * surface() is the THREE.Mesh on display (indexed geometry), generation() changes with every mesh,
 * pathSource() is the source of the straightest paths ('auto' or a SurfacePoint) and
 * surfaceChanged() makes main.js reapply the surface material (it asks texture() for the map).
 */
export function createParamView(context) {
  const { request, hooks, scene, renderer, requestRender } = context;
  Object.assign(hooks, { param: null, paramError: null, parameterizations: 0, compare: null });

  let shown = null; // { reply } of the parameterization on display (for the current mesh)
  let latestRun = 0; // only the most recent parameterize request may update the view
  let latestCompare = 0;

  // ---------------------------------------------------------------- textures

  const maxAnisotropy = renderer.capabilities.getMaxAnisotropy();
  let checkerTexture = null; // made when first shown
  let imageTexture = null; // the user's image, once loaded

  function configureTexture(texture) {
    texture.colorSpace = THREE.SRGBColorSpace;
    texture.anisotropy = maxAnisotropy;
    texture.wrapS = texture.wrapT = THREE.ClampToEdgeWrapping;
    texture.needsUpdate = true;
    return texture;
  }

  /** The map of the surface material: null without a uv on the mesh or with texture 'none'. */
  function texture() {
    if (!shown) return null;
    const choice = $('texture-select').value;
    if (choice === 'checker') {
      checkerTexture ??= configureTexture(new THREE.CanvasTexture(checkerboardCanvas()));
      return checkerTexture;
    }
    if (choice === 'image') return imageTexture;
    return null;
  }

  async function loadImage(file) {
    const url = URL.createObjectURL(file);
    try {
      const loaded = await new THREE.TextureLoader().loadAsync(url);
      configureTexture(loaded);
      imageTexture?.dispose();
      imageTexture = loaded;
      const option = $('texture-select').querySelector('option[value="image"]');
      option.disabled = false;
      option.textContent = `Image: ${file.name}`;
      $('texture-select').value = 'image';
      showNote('');
      context.surfaceChanged();
    } catch {
      showNote(`“${file.name}” is not an image the browser can read.`);
    } finally {
      URL.revokeObjectURL(url);
    }
  }

  // ---------------------------------------------------------------- stretch heat map (3D)

  // Per-face colours need a copy of the mesh without shared corners: a non-indexed geometry with
  // the surface's positions and normals and one colour per face. It replaces the surface while the
  // heat map is on (the surface stays pickable: ray casts ignore visibility).
  const stretchMaterial = new THREE.MeshStandardMaterial({
    vertexColors: true,
    roughness: 0.8,
    metalness: 0,
    side: THREE.DoubleSide,
    polygonOffset: true, // as the surface: the wireframe and the paths stay on top
    polygonOffsetFactor: 1.5,
    polygonOffsetUnits: 2,
  });
  let stretchMesh = null;

  function buildStretchMesh() {
    const surface = context.surface();
    const { index, attributes } = surface.geometry;
    const geometry = surface.geometry.toNonIndexed(); // positions and normals per corner
    geometry.deleteAttribute('uv');
    const faces = index.count / 3;
    const colors = new Float32Array(9 * faces);
    const color = new THREE.Color();
    const { faceStretch } = shown.reply;
    for (let f = 0; f < faces; f++) {
      const [r, g, b] = stretchRgb(faceStretch[f]);
      color.setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace);
      for (let k = 0; k < 3; k++) color.toArray(colors, 9 * f + 3 * k);
    }
    geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    if (!attributes.normal) geometry.computeVertexNormals();
    stretchMesh = new THREE.Mesh(geometry, stretchMaterial);
    scene.add(stretchMesh);
  }

  function removeStretchMesh() {
    if (!stretchMesh) return;
    scene.remove(stretchMesh);
    stretchMesh.geometry.dispose();
    stretchMesh = null;
  }

  /** Shows the heat map or the (textured) surface, as the toggle says. */
  function updateSurfaceView() {
    const surface = context.surface();
    const heat = $('stretch-toggle').checked && shown !== null && surface !== null;
    if (heat && !stretchMesh) buildStretchMesh();
    if (stretchMesh) stretchMesh.visible = heat;
    if (surface) surface.visible = !heat;
    stretchMaterial.flatShading = $('flat-toggle').checked;
    stretchMaterial.needsUpdate = true;
    $('stretch-legend').hidden = !heat;
    requestRender();
  }

  // ---------------------------------------------------------------- panels

  const statsFields = ['l2', 'linf', 'bijective', 'flips', 'fallbacks', 'angle', 'area', 'time'];

  function clearStats() {
    for (const field of statsFields) {
      const dd = $(`param-${field}`);
      dd.textContent = '–';
      dd.className = '';
      dd.removeAttribute('title');
    }
    $('param-method').textContent = '–';
    $('param-method').removeAttribute('title');
    $('param-method').hidden = false;
    $('param-stats').hidden = false;
  }

  function showNote(text, kind = 'note') {
    const note = $('param-message');
    note.textContent = text;
    note.className = kind;
    note.hidden = !text;
  }

  function showStats(reply, requested) {
    const set = (field, text, className = '', title = '') => {
      const dd = $(`param-${field}`);
      dd.textContent = text;
      dd.className = className;
      if (title) dd.title = title; else dd.removeAttribute('title');
    };
    const method = $('param-method');
    method.textContent = `${requested === 'auto' ? 'auto → ' : ''}${reply.boundary} boundary · ` +
      `${WEIGHT_LABELS[reply.weights]} weights`;
    method.title = reply.candidates.length > 1
      ? `least L2 stretch of ${reply.candidates.map((c) => `${c.boundary} ${formatMetric(c.l2)}`).join(', ')}`
      : '';
    set('l2', formatMetric(reply.stretch.l2), 'strong');
    set('linf', formatMetric(reply.stretch.linf));
    set('bijective', reply.bijective ? 'yes' : 'no', reply.bijective ? 'good' : 'bad');
    set('flips', `${reply.flipped} / ${reply.degenerate}`, reply.flipped + reply.degenerate ? 'bad' : '');
    set('fallbacks', `${reply.fallbacks} / ${reply.weightFallbacks}`, '',
      'traces of the measured boundary that used the edge-graph distance / faces whose weights fell back');
    set('angle', `${formatMetric(reply.angleDistortion.mean)} / ${formatMetric(reply.angleDistortion.max)}`);
    set('area', `${formatMetric(reply.areaDistortion.mean)} / ${formatMetric(reply.areaDistortion.max)}`);
    const t = reply.timings;
    set('time', `${formatMs(t.solve, '')} / ${formatMs(t.total)}`, '',
      `source ${formatMs(t.source)}, trace ${formatMs(t.trace)}, boundary ${formatMs(t.boundary)}, ` +
      `weights ${formatMs(t.weights)}, solve ${formatMs(t.solve)}, metrics ${formatMs(t.metrics)}; ` +
      `relative residual ${reply.residual.toExponential(1)}; ${formatMs(reply.timeMs)} in the worker ` +
      '(plus the overlay polygons)');
  }

  // ---------------------------------------------------------------- the 2D layout

  const uvCanvas = $('uv-canvas');
  let layoutMessage = 'No parameterization yet.';

  function redrawLayout() {
    if (!shown) {
      drawLayout(uvCanvas, null, layoutMessage);
      return;
    }
    const { reply } = shown;
    const indices = context.surface()?.geometry.index.array;
    if (!indices) return;
    drawLayout(uvCanvas, {
      uv: reply.uv,
      indices,
      faceStretch: reply.faceStretch,
      overlays: reply.overlays,
      boundary: reply.boundary,
      heat: $('stretch-toggle').checked,
      caption: `${WEIGHT_LABELS[reply.weights]} · L2 ${formatMetric(reply.stretch.l2)} · ` +
        `L∞ ${formatMetric(reply.stretch.linf)}${reply.bijective ? '' : ' · not bijective'}`,
    });
  }
  new ResizeObserver(() => redrawLayout()).observe(uvCanvas);

  // ---------------------------------------------------------------- parameterize

  /** The center of the measured boundary: the default source, or the paths' source if ticked. */
  function sourceOption() {
    return $('param-source-toggle').checked ? context.pathSource() : 'auto';
  }

  function setButtons() {
    const hasMesh = context.surface() !== null;
    $('param-button').disabled = !hasMesh;
    $('compare-button').disabled = !hasMesh || hooks.paramError?.category === 'topology';
    $('export-obj-button').disabled = !shown;
    $('export-png-button').disabled = !shown;
  }

  async function parameterize() {
    if (!context.surface()) return;
    const ticket = ++latestRun;
    const generation = context.generation();
    const stale = () => ticket !== latestRun || generation !== context.generation();
    const options = {
      source: sourceOption(),
      boundary: $('boundary-select').value,
      weights: $('weights-select').value,
    };
    showNote('Parameterizing…', 'busy');
    $('param-panel').dataset.state = 'running';
    try {
      const reply = await request('parameterize', options);
      if (stale()) return;
      show(reply, options.boundary);
    } catch (err) {
      if (stale()) return;
      showFailure(err);
    }
  }

  function show(reply, requested) {
    const surface = context.surface();
    applyUV(surface.geometry, reply.uv);
    removeStretchMesh(); // rebuilt from the new stretch if the heat map is on
    shown = { reply };
    hooks.param = {
      boundary: reply.boundary,
      weights: reply.weights,
      l2: reply.stretch.l2,
      linf: reply.stretch.linf,
      bijective: reply.bijective,
      flipped: reply.flipped,
    };
    hooks.paramError = null;
    hooks.parameterizations += 1;
    showStats(reply, requested);
    const failed = reply.overlays.filter((o) => o.error);
    showNote(failed.map((o) => `The ${o.boundary} boundary failed: ${o.error}`).join(' '));
    $('param-panel').dataset.state = 'done';
    context.surfaceChanged();
    updateSurfaceView();
    redrawLayout();
    markCurrentRow();
    setButtons();
  }

  function showFailure(err) {
    forget();
    hooks.paramError = { message: err.message, category: err.category ?? 'error' };
    clearStats();
    $('param-stats').hidden = true;
    $('param-method').hidden = true;
    showNote(`Cannot parameterize: ${err.message}`, 'error');
    $('param-panel').dataset.state = 'error';
    layoutMessage = err.category === 'topology'
      ? 'The parameterization needs a disk (one boundary loop).'
      : 'The parameterization failed (see above).';
    context.surfaceChanged();
    updateSurfaceView();
    redrawLayout();
    setButtons();
  }

  /** Drops the parameterization on display (the uv attribute, the heat map, the hook). */
  function forget() {
    shown = null;
    hooks.param = null;
    removeStretchMesh();
    context.surface()?.geometry.deleteAttribute('uv');
  }

  // ---------------------------------------------------------------- compare

  const BOUNDARY_ORDER = ['measured', 'circle', 'square'];

  async function compare() {
    if (!context.surface()) return;
    const ticket = ++latestCompare;
    const generation = context.generation();
    const stale = () => ticket !== latestCompare || generation !== context.generation();
    const progress = $('compare-progress');
    const status = $('compare-status');
    progress.value = 0;
    progress.hidden = false;
    status.textContent = 'starting…';
    $('compare-button').disabled = true;
    try {
      const reply = await request('compare', { source: sourceOption() }, [], ({ done, total }) => {
        if (stale()) return;
        progress.max = total;
        progress.value = done;
        status.textContent = `${done} / ${total}`;
      });
      if (stale()) return;
      hooks.compare = reply.rows;
      showTable(reply.rows);
      const total = reply.rows.reduce((sum, row) => sum + row.timeMs, 0);
      status.textContent = `${reply.rows.length} runs in ${formatMs(total)}`;
    } catch (err) {
      if (stale()) return;
      status.textContent = `failed: ${err.message}`;
    } finally {
      if (!stale()) {
        progress.hidden = true;
        setButtons();
      }
    }
  }

  function showTable(rows) {
    const table = $('compare-table');
    const body = table.tBodies[0];
    body.replaceChildren();
    // The best row: least finite L2 stretch.
    let best = null;
    for (const row of rows) if (!row.error && Number.isFinite(row.l2) && (!best || row.l2 < best.l2)) best = row;
    for (const boundary of BOUNDARY_ORDER) {
      // A header row per boundary, then its rows, one per weights.
      const header = body.insertRow();
      header.className = 'group';
      const th = document.createElement('th');
      th.scope = 'rowgroup';
      th.colSpan = 5;
      th.innerHTML = '<span class="dot"></span>';
      th.firstChild.style.background = BOUNDARY_COLORS[boundary];
      th.append(`${boundary} boundary`);
      header.append(th);
      for (const row of rows.filter((r) => r.boundary === boundary)) {
        const tr = body.insertRow();
        tr.dataset.boundary = row.boundary;
        tr.dataset.weights = row.weights;
        tr.title = row.error ?? `Show ${row.boundary} / ${WEIGHT_LABELS[row.weights]}`;
        const cells = row.error
          ? [WEIGHT_LABELS[row.weights], 'failed', '', '', formatMs(row.timeMs).replace(' ms', '')]
          : [WEIGHT_LABELS[row.weights], formatMetric(row.l2), formatMetric(row.linf),
            String(row.flipped + row.degenerate), row.timeMs.toFixed(row.timeMs >= 100 ? 0 : 1)];
        for (const text of cells) tr.insertCell().textContent = text;
        if (row === best) tr.classList.add('best');
        if (row.error) tr.classList.add('failed');
        if (!row.error && row.flipped + row.degenerate > 0) tr.cells[3].classList.add('bad');
      }
    }
    table.hidden = false;
    $('compare-legend').hidden = false;
    markCurrentRow();
  }

  /** Outlines the table row of the parameterization on display. */
  function markCurrentRow() {
    for (const tr of $('compare-table').tBodies[0].rows) {
      if (!tr.dataset.boundary) continue;
      tr.classList.toggle('current', !!shown &&
        tr.dataset.boundary === shown.reply.boundary && tr.dataset.weights === shown.reply.weights);
    }
  }

  function clearTable() {
    latestCompare += 1;
    $('compare-table').tBodies[0].replaceChildren();
    $('compare-table').hidden = true;
    $('compare-legend').hidden = true;
    $('compare-progress').hidden = true;
    $('compare-status').textContent = '';
    hooks.compare = null;
  }

  // ---------------------------------------------------------------- exports

  function baseName() {
    return (context.label() || 'mesh').replace(/\.[^.]+$/, '').replace(/[^\w.-]+/g, '_');
  }

  async function exportObj() {
    if (!shown) return;
    const { reply } = shown;
    try {
      const { text } = await request('exportObj', { uv: reply.uv });
      download(new Blob([text], { type: 'text/plain' }), `${baseName()}-${reply.boundary}-uv.obj`);
    } catch (err) {
      showNote(`Could not export the OBJ: ${err.message}`, 'error');
    }
  }

  function exportPng() {
    if (!shown) return;
    const name = `${baseName()}-${shown.reply.boundary}-uv-layout.png`;
    uvCanvas.toBlob((blob) => blob && download(blob, name), 'image/png');
  }

  // ---------------------------------------------------------------- wiring

  $('param-button').addEventListener('click', () => parameterize());
  $('compare-button').addEventListener('click', () => compare());
  $('export-obj-button').addEventListener('click', () => exportObj());
  $('export-png-button').addEventListener('click', () => exportPng());
  // A row of the comparison shows that combination.
  $('compare-table').tBodies[0].addEventListener('click', (event) => {
    const tr = event.target.closest('tr');
    if (!tr?.dataset.boundary || tr.classList.contains('failed')) return;
    $('boundary-select').value = tr.dataset.boundary;
    $('weights-select').value = tr.dataset.weights;
    parameterize();
  });
  $('texture-select').addEventListener('change', () => context.surfaceChanged());
  $('texture-input').addEventListener('change', (event) => {
    const [file] = event.target.files;
    if (file) loadImage(file);
    event.target.value = '';
  });
  // The stretch heat map and the heat distances colour the same surface: one at a time.
  $('stretch-toggle').addEventListener('change', (event) => {
    const heatDistance = $('heat-toggle');
    if (event.target.checked && heatDistance.checked) {
      heatDistance.checked = false;
      heatDistance.dispatchEvent(new Event('change'));
    }
    updateSurfaceView();
    redrawLayout();
  });
  $('heat-toggle').addEventListener('change', (event) => {
    if (event.target.checked && $('stretch-toggle').checked) {
      $('stretch-toggle').checked = false;
      updateSurfaceView();
      redrawLayout();
    }
  });
  $('flat-toggle').addEventListener('change', () => updateSurfaceView());
  $('stretch-legend').querySelector('.ramp').style.background = stretchGradient();
  $('stretch-legend').querySelector('.infinite').style.background = `rgb(${STRETCH_INFINITE.join(',')})`;

  clearStats();
  setButtons();
  redrawLayout();

  return {
    texture,

    /** A new mesh is on display: everything shown belongs to the previous one. */
    meshChanged() {
      latestRun += 1;
      forget();
      hooks.paramError = null;
      clearStats();
      showNote('');
      delete $('param-panel').dataset.state;
      clearTable();
      layoutMessage = 'Parameterizing…';
      context.surfaceChanged(); // no uv yet: no texture
      updateSurfaceView();
      redrawLayout();
      setButtons();
    },

    /** The mesh's paths are drawn: time for the automatic parameterization (a non-disk shows why not). */
    meshReady() {
      return parameterize();
    },
  };
}
