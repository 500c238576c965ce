// The parameterization part of the page: the "Parameterization", "UV layout" and "Compare" panels,
// the texture on the 3D mesh (a checkerboard or the user's image) and the per-face stretch heat map.
// The worker computes everything (uv, stretch, metrics, the comparison, the OBJ text); this module
// only shows its arrays: it sets them as three.js attributes, draws the 2D layout and fills tables.
//
// main.js creates the view once with createParamView(context) and tells it when the mesh changes
// (meshChanged, right after the new geometry is shown), when the mesh's paths are drawn
// (meshReady: the automatic first parameterization, kept out of the initial load; large meshes
// only get a note, the button runs it) and when Cancel stopped the worker (cancelled).
//
// Test hooks (on window.__straightest): param = { boundary, weights, l2, linf, bijective, flipped }
// after each parameterization (null before and after a failure), paramError = { message, category }
// of the last failure, parameterizations (a counter), compare = the rows of the last comparison.

import * as THREE from 'three';
import { applyUV } from 'straightest/three';
import { isCancelled } from './worker-client.js';
import {
  BOUNDARY_COLORS, STRETCH_INFINITE, STRETCH_MAX, STRETCH_MIN, checkerboardCanvas, drawLayout, stretchGradient,
  stretchRgb,
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
 *            generation(), label(), pathSource(), large(), largeLimit, gpuIdle(),
 *            surfaceChanged(), requestRender() }
 * surface() is the THREE.Mesh on display (indexed geometry), generation() changes with every mesh,
 * pathSource() is the source of the straightest paths ('auto' or a SurfacePoint), large() says
 * whether the mesh has more than largeLimit vertices (no automatic run, no overlay polygons),
 * gpuIdle() resolves when the GPU has caught up (before a large upload) and surfaceChanged() makes
 * main.js reapply the surface material (it asks texture() for the map).
 */
export function createParamView(context) {
  const { request, hooks, scene, renderer, requestRender } = context;
  Object.assign(hooks, { param: null, paramError: null, parameterizations: 0, compare: null });

  let shown = null; // { reply } of the parameterization on display (for the current mesh)
  let latestRun = 0; // only the most recent parameterize request may update the view
  let latestCompare = 0;
  let running = false; // a parameterize request is in flight
  let comparing = false; // likewise for compare

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
  // heat map is on (the surface stays pickable: ray casts ignore visibility). Normals and colours
  // are stored as normalized integers (a 1M-vertex mesh's copy is ~110 MB instead of ~220 MB), and
  // a large mesh is copied in slices of STRETCH_SLICE_FACES faces, one task each, so the page
  // stays responsive meanwhile.
  const STRETCH_SLICE_FACES = 200_000;
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
  let stretchBuild = 0; // ticket of the latest heat-map copy
  let stretchBuilding = false; // a large mesh's copy is being built, slice by slice

  /** The stretch colour scale in linear RGB bytes: 256 steps of [1, 2], then ∞ (flipped). */
  let stretchColors = null;
  function stretchColorTable() {
    if (stretchColors) return stretchColors;
    stretchColors = new Uint8Array(3 * 257);
    const color = new THREE.Color();
    for (let i = 0; i <= 256; i++) {
      const [r, g, b] = i < 256 ? stretchRgb(STRETCH_MIN + (i / 255) * (STRETCH_MAX - STRETCH_MIN)) : STRETCH_INFINITE;
      color.setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace); // to the linear working space
      stretchColors.set([color.r, color.g, color.b].map((c) => Math.round(255 * c)), 3 * i);
    }
    return stretchColors;
  }

  /** Builds the heat-map copy of the surface (in slices when large), then shows it if still wanted. */
  async function buildStretchMesh() {
    const ticket = ++stretchBuild;
    let sliced = false;
    const surface = context.surface();
    const { index, attributes } = surface.geometry;
    if (!attributes.normal) surface.geometry.computeVertexNormals();
    const corners = index.array;
    const position = attributes.position.array;
    const normal = attributes.normal.array;
    const { faceStretch } = shown.reply;
    const faces = corners.length / 3;
    const positions = new Float32Array(9 * faces);
    const normals = new Int16Array(9 * faces);
    const colors = new Uint8Array(9 * faces);
    const table = stretchColorTable();
    for (let slice = 0; slice < faces; slice += STRETCH_SLICE_FACES) {
      if (slice > 0) {
        sliced = stretchBuilding = true;
        await new Promise((resolve) => setTimeout(resolve)); // let the page breathe between slices
        if (ticket !== stretchBuild) return; // the mesh or the parameterization changed
      }
      const end = Math.min(faces, slice + STRETCH_SLICE_FACES);
      for (let f = slice; f < end; f++) {
        const s = faceStretch[f];
        const t = Number.isFinite(s) ? Math.round(255 * Math.min(Math.max(s - STRETCH_MIN, 0) / (STRETCH_MAX - STRETCH_MIN), 1)) : 256;
        for (let k = 0; k < 3; k++) {
          const v = corners[3 * f + k];
          const to = 9 * f + 3 * k;
          for (let c = 0; c < 3; c++) {
            positions[to + c] = position[3 * v + c];
            normals[to + c] = Math.round(32767 * Math.min(Math.max(normal[3 * v + c], -1), 1));
            colors[to + c] = table[3 * t + c];
          }
        }
      }
    }
    if (sliced) {
      await context.gpuIdle(); // its upload (~110 MB for 1M vertices) must not queue behind slow frames
      if (ticket !== stretchBuild) return;
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3, true));
    geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3, true));
    stretchMesh = new THREE.Mesh(geometry, stretchMaterial);
    scene.add(stretchMesh);
    stretchBuilding = false;
    if (sliced) updateSurfaceView();
  }

  function removeStretchMesh() {
    stretchBuild += 1; // a copy still being built is dropped
    stretchBuilding = false;
    if (!stretchMesh) return;
    scene.remove(stretchMesh);
    stretchMesh.geometry.dispose();
    stretchMesh = null;
  }

  /**
   * Shows the heat map or the (textured) surface, as the toggle says. A large mesh's heat map comes
   * a moment later (its copy is built in slices; the surface stays until then).
   */
  function updateSurfaceView() {
    const surface = context.surface();
    let heat = $('stretch-toggle').checked && shown !== null && surface !== null;
    if (heat && !stretchMesh) {
      if (!stretchBuilding) {
        // Synchronous for a small mesh (one slice); a large one shows when its last slice is done.
        buildStretchMesh().catch((err) => {
          stretchBuilding = false;
          showNote(`Could not build the stretch heat map: ${err.message}`, 'error');
        });
      }
      heat = stretchMesh !== null;
    }
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
      overlays: !context.large(), // the other boundaries' polygons: another solve each
    };
    showNote('Parameterizing…', 'busy');
    $('param-panel').dataset.state = 'running';
    running = true;
    try {
      const reply = await request('parameterize', options);
      if (stale()) return;
      show(reply, options.boundary);
    } catch (err) {
      if (stale() || isCancelled(err)) return;
      showFailure(err);
    } finally {
      if (!stale()) running = false;
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
    const notes = failed.map((o) => `The ${o.boundary} boundary failed: ${o.error}`);
    if (reply.overlays.some((o) => o.skipped)) {
      notes.push('Large mesh: the layout shows only this boundary (the others would take a solve each).');
    }
    showNote(notes.join(' '));
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
    comparing = true;
    try {
      const reply = await request('compare', { source: sourceOption() }, [], ({ done, total }) => {
        if (stale() || done === undefined) return;
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
      if (stale() || isCancelled(err)) return;
      status.textContent = `failed: ${err.message}`;
    } finally {
      if (!stale()) {
        comparing = false;
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
      if (!isCancelled(err)) showNote(`Could not export the OBJ: ${err.message}`, 'error');
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
      running = false;
      comparing = false;
      forget();
      hooks.paramError = null;
      clearStats();
      showNote('');
      delete $('param-panel').dataset.state;
      clearTable();
      layoutMessage = context.surface() ? 'Parameterizing…' : 'No mesh loaded.';
      context.surfaceChanged(); // no uv yet: no texture
      updateSurfaceView();
      redrawLayout();
      setButtons();
    },

    /**
     * The mesh's paths are drawn: time for the automatic parameterization (a non-disk shows why
     * not). A large mesh only gets a note: each solve takes seconds there.
     */
    meshReady() {
      if (!context.large()) return parameterize();
      const vertices = context.hooks.lastInfo?.vertices ?? 0;
      showNote(`Large mesh (${vertices.toLocaleString('en-US')} vertices, more than ` +
        `${context.largeLimit.toLocaleString('en-US')}): it is not parameterized automatically. ` +
        'Press Parameterize to run it — it takes a while, the progress shows over the view and ' +
        'Cancel stops it.', 'note');
      layoutMessage = 'Press Parameterize to flatten this large mesh.';
      redrawLayout();
      return Promise.resolve();
    },

    /** Cancel stopped the worker: whatever it was computing here will not come. */
    cancelled() {
      latestRun += 1;
      latestCompare += 1;
      if (running) {
        running = false;
        showNote('Parameterization cancelled.', 'note');
        if (shown) {
          $('param-panel').dataset.state = 'done';
        } else {
          delete $('param-panel').dataset.state;
          layoutMessage = 'Cancelled — press Parameterize to run it.';
          redrawLayout();
        }
      }
      if (comparing) {
        comparing = false;
        $('compare-progress').hidden = true;
        $('compare-status').textContent = 'cancelled';
      }
      setButtons();
    },
  };
}
