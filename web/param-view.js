// The parameterization part of the page: the "Parameterization" and "UV layout" panels, the texture
// on the 3D mesh, the exports, and the automatic first run once a mesh's paths are drawn. The worker
// computes everything (uv, stretch, metrics, the boundary polygons, the OBJ text); this module
// decides what is on display and when. The texture and seam on the mesh are param-texture.js, the
// stats' words param-stats.js, the stretch heat map stretch-view.js, the comparison table
// compare-view.js, the layout drawing uv-layout.js.
//
// It follows the session's events: 'meshchange' (everything shown belongs to the previous mesh),
// 'meshready' (the automatic parameterization; large meshes only get a note, the button runs it)
// and 'cancel' (the worker was restarted: a run in flight will not come).
//
// A mesh that is not a disk comes back cut or filled (the core's `cut`): a closed or higher-genus mesh
// has its seam drawn on the surface and, as the disk's boundary, in the layout; its texture goes on a
// seam-split twin of the surface (param-texture.js); filled holes get a note.
//
// What it has on display, as plain data, is status() (main.js puts it in the page's observable
// state, window.__straightest: param, paramError, parameterizations, paramHint, defaultBoundary, and
// the Compare table's compare and compareHint).

import { applyUV } from 'straightest/three';
import { latest } from './latest.js';
import { createCompareView } from './compare-view.js';
import { createStretchView } from './stretch-view.js';
import { WEIGHT_LABELS, formatCount, formatMetric } from './param-format.js';
import { createLayoutPainter } from './layout-painter.js';
import { clearStats, cutNote, showStats } from './param-stats.js';
import { createParamTexture } from './param-texture.js';
import { isCancelled } from './requests.js';
import { parameterizationHint, renderHint } from './hints.js';
import { download } from './image-export.js';
import { glbFromGeometry } from './mesh-files.js';
import { summarizeParameterization } from './results-summary.js';
import { defaultBoundary } from './mesh-defaults.js';

const $ = (id) => document.getElementById(id);

// Above this many vertices the page does not parameterize automatically after loading (seconds of
// work per solve; the button runs it, with progress and Cancel).
const LARGE_MESH_VERTICES = 300_000;
// Changing Boundary, Weights or "Center at the path source" runs the parameterization again once the
// options have stayed put this long (stepping through a menu with the arrow keys runs only the last).
const RERUN_DELAY_MS = 300;

/** The boundary menu's words for the core's kinds (st.boundaryKinds) and 'auto'. */
const BOUNDARY_CHOICES = {
  measured: ['measured', 'straightest distances and angles from the center, made convex (the paper)'],
  circle: ['circle', 'the unit circle by boundary arc length'],
  square: ['square', 'the unit square by boundary arc length'],
  free: [
    'free (refined)',
    "the measured map (the circle's when that folds) refined with the boundary free to " +
      'move: less distortion, never folds',
  ],
  auto: ['auto (best)', 'every boundary, keeping the least L2 stretch'],
};

/**
 * session: session.js (request, events, the mesh on display); view: scene.js; surface:
 * surface-view.js; pathSource(): the source of the straightest paths ('auto' or a SurfacePoint);
 * onShown(): a parameterization is on display (the URL follows its options).
 */
export function createParamView({ session, view, surface, pathSource, onShown = () => {} }) {
  let shown = null; // { reply } of the parameterization on display (for the current mesh)
  const runs = latest(); // only the most recent parameterize request may update the view
  let running = false; // a parameterize request is in flight
  // The Boundary menu follows each new mesh's default (mesh-defaults.js) until the user picks one
  // (the menu, a Compare row, a shared link); from then on the choice stays across meshes.
  let boundaryChosen = false;
  // What is on display, for status(): the metrics of the parameterization (null before and after a
  // failure), the last failure's { message, category }, how many were shown, the hint's text, and the
  // boundary the mesh opened with ({ boundary, reason, applied }).
  const status = { param: null, paramError: null, parameterizations: 0, paramHint: null, defaultBoundary: null };

  const large = () => (session.info?.vertices ?? 0) > LARGE_MESH_VERTICES;

  const surfaceTexture = createParamTexture({ view, surface, showNote });
  const updateTexture = () => surfaceTexture.update();

  const stretch = createStretchView({
    view,
    surface,
    onError: (err) => showNote(`Could not build the stretch heat map: ${err.message}`, 'error'),
  });
  const showStretch = () => stretch.show($('stretch-toggle').checked);

  // ---------------------------------------------------------------- panels

  /** The boundary menu from the core's kinds (once the worker has named them), keeping the choice. */
  function fillBoundaryMenu() {
    const select = $('boundary-select');
    const kinds = session.boundaryKinds;
    if (!kinds.length || select.options.length === kinds.length + 1) return;
    const chosen = select.value;
    select.replaceChildren(
      ...[...kinds, 'auto'].map((kind) => {
        const [label, title] = BOUNDARY_CHOICES[kind] ?? [kind, ''];
        const option = new Option(label, kind);
        option.title = title;
        return option;
      }),
    );
    select.value = [...kinds, 'auto'].includes(chosen) ? chosen : kinds[0];
  }

  /** A new mesh: its default boundary, unless the user chose one; says why when it is not measured. */
  function applyDefaultBoundary() {
    const select = $('boundary-select');
    const why = $('param-why');
    const kinds = [...select.options].map((o) => o.value);
    const { boundary, reason } = defaultBoundary(session.info, kinds);
    status.defaultBoundary = { boundary, reason, applied: !boundaryChosen };
    if (boundaryChosen) {
      why.hidden = true;
      return;
    }
    select.value = boundary;
    why.textContent = reason;
    why.hidden = !reason;
  }

  function showNote(text, kind = 'note') {
    const note = $('param-message');
    note.textContent = text;
    note.className = kind;
    note.hidden = !text;
  }

  // ---------------------------------------------------------------- the 2D layout

  const uvCanvas = $('uv-canvas');
  const painter = createLayoutPainter(uvCanvas); // a dense layout is filled in slices, then drawn
  let layoutMessage = 'No parameterization yet.';

  /** The layout on display as drawLayout takes it (title: for exports), or null. */
  function currentLayout() {
    if (!shown) return null;
    const { reply } = shown;
    return {
      cornerUv: reply.cornerUv,
      seam: reply.cut === 'path' || reply.cut === 'cut-graph',
      faceStretch: reply.faceStretch,
      overlays: reply.overlays,
      boundary: reply.boundary,
      heat: $('stretch-toggle').checked,
      title: `${session.label || 'mesh'} — ${reply.boundary} boundary`,
      caption:
        `${reply.init ? `free from ${reply.init} · ` : ''}${WEIGHT_LABELS[reply.weights]} · ` +
        `L2 ${formatMetric(reply.stretch.l2)} · ` +
        `L∞ ${formatMetric(reply.stretch.linf)}${reply.bijective ? '' : ' · not bijective'}`,
    };
  }

  function redrawLayout() {
    const layout = currentLayout();
    painter.draw(layout && { ...layout, title: '' }, layoutMessage);
  }
  new ResizeObserver(() => redrawLayout()).observe(uvCanvas);

  // ---------------------------------------------------------------- parameterize

  /** The center of the measured boundary: the default source, or the paths' source if ticked. */
  function sourceOption() {
    return $('param-source-toggle').checked ? pathSource() : 'auto';
  }

  function setButtons() {
    const hasMesh = surface.mesh !== null;
    $('param-button').disabled = !hasMesh;
    $('compare-button').disabled = !hasMesh || status.paramError?.category === 'topology';
    $('export-obj-button').disabled = !shown;
    $('export-glb-button').disabled = !shown;
    $('export-png-button').disabled = !shown;
    $('export-svg-button').disabled = !shown;
  }

  const compare = createCompareView({
    session,
    source: sourceOption,
    current: () => shown?.reply ?? null,
    onChoose(boundary, weights) {
      boundaryChosen = true;
      $('param-why').hidden = true;
      $('boundary-select').value = boundary;
      $('weights-select').value = weights;
      parameterize();
    },
    onSettled: setButtons,
  });

  async function parameterize() {
    if (!surface.mesh) return;
    const request = runs.begin(session.meshes);
    const options = {
      source: sourceOption(),
      boundary: $('boundary-select').value,
      weights: $('weights-select').value,
    };
    showNote('Parameterizing…', 'busy');
    $('param-panel').dataset.state = 'running';
    running = true;
    try {
      const reply = await session.request('parameterize', options);
      if (request.stale()) return;
      show(reply, options.boundary, options.weights);
    } catch (err) {
      if (request.stale() || isCancelled(err)) return;
      showFailure(err);
    } finally {
      if (!request.stale()) running = false;
    }
  }

  function show(reply, requested, requestedWeights = reply.weights) {
    const cut = reply.cut !== 'disk';
    if (cut) surface.mesh.geometry.deleteAttribute('uv');
    else applyUV(surface.mesh.geometry, reply.uv);
    shown = { reply, requested, requestedWeights, split: surfaceTexture.show(reply) };
    stretch.setStretch(reply.faceStretch);
    status.param = {
      boundary: reply.boundary,
      weights: reply.weights,
      l2: reply.stretch.l2,
      linf: reply.stretch.linf,
      bijective: reply.bijective,
      flipped: reply.flipped,
      overlaps: reply.overlaps,
      init: reply.init,
      iterations: reply.iterations,
      cut: reply.cut,
      seamEdges: reply.seamEdges,
      genus: reply.genus,
      filledLoops: [...reply.filledLoops],
      components: reply.components,
    };
    status.paramError = null;
    status.parameterizations += 1;
    showStats(reply, requested);
    summarizeParameterization(reply, requested);
    const failed = reply.overlays.filter((o) => o.error);
    showNote(
      [
        cutNote(reply, session.info?.boundaryLoops),
        ...failed.map((o) => `The ${o.boundary} boundary failed: ${o.error}`),
      ]
        .filter(Boolean)
        .join(' '),
    );
    showHint(parameterizationHint(reply, requested, session.boundaryKinds));
    $('param-panel').dataset.state = 'done';
    updateTexture();
    showStretch();
    redrawLayout();
    compare.markCurrent();
    setButtons();
    onShown();
  }

  function showFailure(err) {
    forget();
    status.paramError = { message: err.message, category: err.category ?? 'error' };
    clearStats();
    $('param-stats').hidden = true;
    $('param-method').hidden = true;
    showNote(`Cannot parameterize: ${err.message}`, 'error');
    $('param-panel').dataset.state = 'error';
    layoutMessage =
      err.category === 'topology'
        ? 'This mesh could not be made a disk (see above).'
        : 'The parameterization failed (see above).';
    updateTexture();
    showStretch();
    redrawLayout();
    setButtons();
  }

  /** The poor-result hint under the stats (hints.js decides), or none. */
  function showHint(hint) {
    renderHint($('param-hint'), hint);
    status.paramHint = hint?.text ?? null;
  }

  /** Drops the parameterization on display (the uv attribute, the heat map, the hook, the hint). */
  function forget() {
    showHint(null);
    shown = null;
    summarizeParameterization(null);
    surfaceTexture.show(null);
    status.param = null;
    stretch.setStretch(null);
    surface.mesh?.geometry.deleteAttribute('uv');
  }

  // ---------------------------------------------------------------- exports

  function baseName() {
    return (session.label || 'mesh').replace(/\.[^.]+$/, '').replace(/[^\w.-]+/g, '_');
  }

  async function exportObj() {
    if (!shown) return;
    const { reply } = shown;
    try {
      // A cut or filled mesh: a vt per corner uv, so the seam splits in the file too.
      const { text } = await session.request('exportObj', { uv: reply.cut === 'disk' ? reply.uv : reply.cornerUv });
      download(new Blob([text], { type: 'text/plain' }), `${exportName(reply)}.obj`);
    } catch (err) {
      if (!isCancelled(err)) showNote(`Could not export the OBJ: ${err.message}`, 'error');
    }
  }

  /** The export's file name: the mesh, its boundary and its weights ("lion-measured-shape-preserving"). */
  function exportName(reply) {
    return `${baseName()}-${reply.boundary}-${reply.weights}`;
  }

  /** The textured surface (the seam-split twin of a cut mesh) as GLB, through three's GLTFExporter. */
  async function exportGlb() {
    if (!shown || !surface.mesh) return;
    const name = exportName(shown.reply);
    try {
      const buffer = await glbFromGeometry(shown.split ?? surface.mesh.geometry, name);
      download(new Blob([buffer], { type: 'model/gltf-binary' }), `${name}.glb`);
    } catch (err) {
      showNote(`Could not export the GLB: ${err.message}`, 'error');
    }
  }

  // ---------------------------------------------------------------- re-running on option changes

  let rerunTimer = 0;

  /**
   * The options changed: what is shown must follow them. A run in flight with the old options is
   * superseded at once (latest wins: its reply is dropped, never shown) and the new run starts after
   * RERUN_DELAY_MS without a change. The worker is not restarted for it: that also stops the paths
   * and the mesh reload, and is the Cancel button's job. A large mesh is never parameterized
   * unasked (as on load): it gets a note instead.
   */
  function optionsChanged() {
    clearTimeout(rerunTimer);
    if (!surface.mesh) return;
    if (large()) {
      showNote('The options changed: press Parameterize to run them on this large mesh.', 'note');
      return;
    }
    runs.supersede();
    showNote('Parameterizing…', 'busy');
    rerunTimer = setTimeout(() => parameterize(), RERUN_DELAY_MS);
  }

  // ---------------------------------------------------------------- the session's events

  /** A new mesh is on display: everything shown belongs to the previous one. */
  session.addEventListener('meshchange', () => {
    clearTimeout(rerunTimer); // the options' re-run was for the previous mesh
    fillBoundaryMenu();
    if (surface.mesh) applyDefaultBoundary();
    runs.supersede();
    running = false;
    forget();
    status.paramError = null;
    clearStats();
    showNote('');
    delete $('param-panel').dataset.state;
    compare.clear();
    layoutMessage = surface.mesh ? 'Parameterizing…' : 'No mesh loaded.';
    updateTexture(); // no uv yet: no texture
    showStretch();
    redrawLayout();
    setButtons();
  });

  /** The mesh's paths are drawn: the automatic parameterization (a non-disk shows why not). */
  session.addEventListener('meshready', () => {
    if (!large()) {
      parameterize();
      return;
    }
    const vertices = session.info?.vertices ?? 0;
    showNote(
      `Large mesh (${formatCount(vertices)} vertices, more than ` +
        `${formatCount(LARGE_MESH_VERTICES)}): it is not parameterized automatically. ` +
        'Press Parameterize to run it — it takes a while, the progress shows over the view and ' +
        'Cancel stops it.',
      'note',
    );
    layoutMessage = 'Press Parameterize to flatten this large mesh.';
    redrawLayout();
  });

  /** Cancel stopped the worker: whatever it was computing here will not come. */
  session.addEventListener('cancel', () => {
    runs.supersede();
    compare.cancelled();
    if (running) {
      running = false;
      showNote('Parameterization cancelled.', 'note');
      if (shown) {
        // The menus say what is on display again, not the options of the run that was stopped.
        $('boundary-select').value = shown.requested;
        $('weights-select').value = shown.requestedWeights;
        $('param-panel').dataset.state = 'done';
      } else {
        delete $('param-panel').dataset.state;
        layoutMessage = 'Cancelled — press Parameterize to run it.';
        redrawLayout();
      }
    }
    setButtons();
  });

  // ---------------------------------------------------------------- controls

  $('param-button').addEventListener('click', () => {
    clearTimeout(rerunTimer); // runs now what a pending re-run would have
    parameterize();
  });
  for (const id of ['boundary-select', 'weights-select', 'param-source-toggle']) {
    $(id).addEventListener('change', () => optionsChanged());
  }
  $('boundary-select').addEventListener('change', () => {
    boundaryChosen = true;
    $('param-why').hidden = true;
  });
  $('export-obj-button').addEventListener('click', () => exportObj());
  $('export-glb-button').addEventListener('click', () => exportGlb());
  // The stretch heat map and the heat distances colour the same surface: one at a time.
  $('stretch-toggle').addEventListener('change', (event) => {
    const heatDistance = $('heat-toggle');
    if (event.target.checked && heatDistance.checked) {
      heatDistance.checked = false;
      heatDistance.dispatchEvent(new Event('change'));
    }
    showStretch();
    redrawLayout();
  });
  $('heat-toggle').addEventListener('change', (event) => {
    if (event.target.checked && $('stretch-toggle').checked) {
      $('stretch-toggle').checked = false;
      showStretch();
      redrawLayout();
    }
  });
  $('flat-toggle').addEventListener('change', () => showStretch());

  clearStats();
  setButtons();
  redrawLayout();

  return {
    /** What is on display (a copy: see `status` above), with the Compare table's rows and hint. */
    status: () => ({ ...status, layoutFilling: painter.filling, compare: compare.rows, compareHint: compare.hint }),
    /** Sets the Boundary menu as the user's choice (a shared link): it no longer follows each mesh's default. */
    chooseBoundary(boundary) {
      fillBoundaryMenu();
      if (![...$('boundary-select').options].some((o) => o.value === boundary)) return;
      $('boundary-select').value = boundary;
      boundaryChosen = true;
      $('param-why').hidden = true;
    },
    /** Whether the Boundary menu is the user's choice (else each mesh's default). */
    get boundaryChosen() {
      return boundaryChosen;
    },
    /** The Compare table's rows on display, or null. */
    compareRows: () => compare.rows,
    /** The options of the runs on display: { source, weights } (the figure uses the same). */
    options: () => ({ source: sourceOption(), weights: $('weights-select').value }),
    currentLayout,
    /** The base of export file names: the mesh, the boundary and the weights on display. */
    exportName: () => `${baseName()}-${shown?.reply.boundary ?? 'none'}-${shown?.reply.weights ?? ''}`,
    get checkerCells() {
      return surfaceTexture.checkerCells;
    },
    /** The checkerboard's squares per side (the texture on the mesh is made again). */
    setCheckerCells: (cells) => surfaceTexture.setCheckerCells(cells),
  };
}
