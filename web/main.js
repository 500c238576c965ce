// The page's wiring: it creates the views and connects them to the session and the controls. All
// geometry happens in the package's worker (straightest/worker, which owns the WASM module); the
// modules here only draw its arrays, pick points on the mesh and orchestrate the requests:
//   scene.js        renderer, camera, controls, render scheduling, framing, up axis, view presets
//   up-axis.js      which axis points up when a mesh opens (the Up menu's auto)
//   surface-view.js the mesh on display and what colours it
//   path-view.js    path lines, markers, base plane, the hovered path's cutting plane
//   picking.js      hovering paths (tooltip) and clicking the surface
//   heat-distance.js, colormap.js   the distance colours; every colour scale
//   panels.js       info, path statistics, errors, status line and page state
//   session.js      load / cancel / reload, "latest request wins" (latest.js)
//   requests.js     each request as a few calls to straightest/worker, with its progress stages
//   geodesic-compare.js  cutting plane, shot (IVP) and exact geodesics to the last added destination
//   exact-ratio.js  straightest ÷ exact over every boundary target (plot and table)
//   keyboard.js, point-entry.js   the view from the keyboard; typed source and destinations
//   hints.js        what to try when traces fail or the measured boundary stretches more than the circle
//   param-view.js   the parameterization (with param-stats.js, param-texture.js, stretch-view.js,
//                   compare-view.js, uv-layout.js)
//   export-panel.js figure mode (figure-mode.js) and the image exports (image-export.js, layout-svg.js)
//   atlas-mode.js   the Atlas mode: charts on the mesh, the packed layout beside the view (atlas-layout.js),
//                   its metrics and downloads (atlas-export.js)
//   progress-view.js the progress panel and Cancel
// At the end, window.__straightest: what the page has on display as plain data, from the modules'
// status() and getters (the browser tests read it; docs/PAGE.md).
//
// After a mesh loads, the page asks the worker for the straightest paths from the default source to
// every boundary vertex and draws them (the paper's Figure 1 view); clicking the mesh moves the
// source, shift-clicking adds a destination, on every kind of mesh. A closed surface has no boundary:
// nothing is traced until a destination is added; both ways round each section are drawn. Once the paths are drawn, the parameterization view
// flattens the mesh.

import { createAtlasMode } from './atlas-mode.js';
import { createExactRatio } from './exact-ratio.js';
import { createGeodesicCompare } from './geodesic-compare.js';
import { createHeatDistance } from './heat-distance.js';
import { poorResultHint, renderHint } from './hints.js';
import { createKeyboard } from './keyboard.js';
import { latest } from './latest.js';
import {
  clearError,
  getIndexBase,
  setIndexBase,
  setState,
  setStatus,
  showError,
  showInfo,
  showPathStats,
  shownError,
} from './panels.js';
import { indexBaseOf } from './data-export.js';
import { createParamView } from './param-view.js';
import { createExportPanel } from './export-panel.js';
import { createPathView } from './path-view.js';
import { createPicking, surfacePosition } from './picking.js';
import { createPointEntry } from './point-entry.js';
import { createProgressView } from './progress-view.js';
import { createView } from './scene.js';
import { autoUpAxis } from './up-axis.js';
import { createSession } from './session.js';
import { createSurfaceView } from './surface-view.js';
import { makePanelsCollapsible } from './collapsible.js';
import { pageModes } from './modes.js';
import { summarizePaths } from './results-summary.js';
import { createUrlSync } from './url-sync.js';
import { createDataDownloads } from './data-downloads.js';
import { isCancelled } from './requests.js';

const $ = (id) => document.getElementById(id);

makePanelsCollapsible($('side-panel'));
pageModes(); // the tabs over the view: the 3D surface, and the modes added later register there (Atlas)
const view = createView({ canvas: $('view-canvas'), viewport: $('viewport') });
const surface = createSurfaceView(view);
let picking = null; // created below: hovering needs the path view, the path view tells it when paths go
let geodesics = null; // created below (it needs the session); cleared with the paths
const paths = createPathView(view, {
  onClear: () => {
    picking?.hide();
    geodesics?.clear();
  },
});
picking = createPicking({
  view,
  surface,
  paths,
  tooltip: $('path-tooltip'),
  onPick: (picked, add) => {
    // As the panel says, on every mesh: a click moves the source, shift+click adds a destination (a
    // closed surface, which has no boundary destinations, says so in its note). The "Clicks add
    // destinations" toggle is shift+click for touch screens.
    if (add || $('pick-destination-toggle').checked) pathRequest.added.push(picked);
    else pathRequest.source = picked.point;
    tracePaths();
  },
});

const progressView = createProgressView({ onCancel: () => session.cancel() });
const session = createSession({
  observer: progressView,
  display: {
    showMesh({ positions, indices, normals, info, label }, origin) {
      setIndexBase(indexBaseOf(label, !!origin?.file)); // messages number vertices as the file does
      heat.reset();
      paths.clear(); // they belong to the previous mesh
      shownPaths = null;
      summarizePaths(null);
      exactRatio.clear();
      renderHint($('paths-hint'), null);
      surface.show(positions, indices, normals, info.bbox);
      document.body.dataset.mesh = label; // hides the loading overlay over the view
      setUpAxis(info.bbox);
      view.frameBox(info.bbox);
      showInfo(info, label);
      view.requestRender(); // shows the mesh if tracing takes longer than a frame
      resetPathRequest();
      restorePoints(urlSync.meshShown(label, info)); // a shared link's source and destinations
    },
    dropMesh() {
      heat.reset();
      $('heat-toggle').checked = false;
      paths.clear();
      shownPaths = null;
      pathsStatus = null;
      summarizePaths(null);
      exactRatio.clear();
      renderHint($('paths-hint'), null);
      surface.remove();
      delete document.body.dataset.mesh;
    },
    showPaths: () => tracePaths(),
  },
});
geodesics = createGeodesicCompare({ session, view, surface, wanted: () => $('geodesic-toggle').checked });
const exactRatio = createExactRatio({ session, source: () => pathRequest.source });
createKeyboard(view);
createPointEntry({
  counts: () =>
    surface.mesh && session.info
      ? { vertices: session.info.vertices, faces: session.info.faces, base: getIndexBase() }
      : null,
  apply({ source, destinations }) {
    if (source) pathRequest.source = source;
    for (const point of destinations) pathRequest.added.push({ point, position: surfacePosition(surface.mesh, point) });
    tracePaths();
  },
});
const heat = createHeatDistance({ session, surface, paths, wanted: () => $('heat-toggle').checked });
const param = createParamView({
  session,
  view,
  surface,
  pathSource: () => pathRequest.source,
  onShown: () => urlSync.save(),
});
const exportPanel = createExportPanel({ session, view, surface, paths, param });
const atlasMode = createAtlasMode({ session, view, surface });
createDataDownloads({
  session,
  paths: () => shownPaths,
  source: () => pathRequest.source,
  compareRows: () => param.compareRows(),
  exactRows: () => exactRatio.rows,
});
const urlSync = createUrlSync({
  session,
  param,
  points: () => ({ source: pathRequest.source, destinations: pathRequest.added.map(({ point }) => point) }),
});

// ------------------------------------------------------------------ straightest paths

// What the next trace asks for: the source ('auto' = the default source) and the destinations
// (the boundary vertices if the toggle is on, plus the points added with shift+click).
const pathRequest = {
  source: 'auto',
  added: [], // [{ point: {face, bary}, position: THREE.Vector3 }]
};
const traces = latest(); // only the most recent trace may update the view
let shownPaths = null; // the 'paths' reply on display (the data downloads)
// What the paths show, for the page's observable state (docs/PAGE.md): the traces completed, the
// paths on display (kept until the next trace or until no mesh is left) and the hint under them.
let traceCount = 0;
let pathsStatus = null;
let pathsHint = null;

function closedMesh() {
  return (session.info?.boundaryLoops ?? []).length === 0;
}

/** The 'targets' of the next 'paths' request (see requests.js). */
function currentTargets() {
  const added = pathRequest.added.map(({ point }) => point);
  if (!$('boundary-toggle').checked) return added;
  return added.length ? ['boundary', ...added] : 'boundary';
}

/** Back to the default source and the boundary destinations. */
function resetPathRequest() {
  pathRequest.source = 'auto';
  pathRequest.added = [];
  picking.hide();
}

/** Takes a shared link's { source, destinations } (or null) for the mesh just shown. */
function restorePoints(points) {
  if (!points) return;
  pathRequest.source = points.source;
  pathRequest.added = points.destinations.map((point) => ({ point, position: surfacePosition(surface.mesh, point) }));
}

/** Asks the worker for the paths of `pathRequest` and draws them; the page is 'ready' afterwards. */
async function tracePaths() {
  if (!surface.mesh) return;
  const current = traces.begin(session.meshes);
  setState('loading');
  setStatus('Tracing straightest paths…');
  let stage = 'trace the straightest paths';
  try {
    const reply = await session.request('paths', { source: pathRequest.source, targets: currentTargets() });
    if (current.stale()) return;
    const prepared = await paths.prepare(reply, () => current.stale()); // (many paths: in slices)
    if (current.stale()) return;
    traceCount += 1;
    paths.show(
      reply,
      pathRequest.added.map(({ position }) => position),
      prepared,
    );
    shownPaths = reply;
    const { plain, stride } = paths.shown;
    showPathStats(
      reply,
      {
        isDefault: pathRequest.source === 'auto',
        boundary: $('boundary-toggle').checked,
        added: pathRequest.added.length,
        closed: closedMesh(),
      },
      { plain, stride },
      traceCount,
    );
    summarizePaths(reply);
    pathsStatus = {
      count: reply.count,
      reached: reply.reached,
      source: reply.source,
      traceMs: reply.timings.trace,
      plain,
      otherArcs: paths.shown.otherArcs,
      arcs:
        reply.count <= 16
          ? Array.from(reply.lengths, (length, i) => ({
              status: reply.statuses[i],
              length,
              other: reply.otherArcLengths[i],
              backward: reply.backward[i] === 1,
            }))
          : null,
    };
    geodesics.update(reply.source, pathRequest.added.at(-1) ?? null); // reports its own failure
    exactRatio.sourceChanged(reply.source);
    showPathsHint(reply);
    urlSync.save();
    stage = 'compute the heat distances';
    if ($('heat-toggle').checked) await heat.show();
    if (current.stale()) return;
    clearError();
    view.render();
    setStatus(
      reply.count ? `${session.status} · ${reply.count} paths in ${reply.timeMs.toFixed(0)} ms` : session.status,
    );
    setState('ready');
  } catch (err) {
    if (current.stale() || isCancelled(err)) return;
    showError(err, `Could not ${stage}`);
  }
}

/** The hint under the paths when straightest paths to the boundary failed (hints.js decides). */
function showPathsHint(reply) {
  const boundaryTargets = $('boundary-toggle').checked && !closedMesh() ? reply.count - pathRequest.added.length : 0;
  const failed = reply.statuses.slice(0, boundaryTargets).filter((status) => status !== 'reached').length;
  const hint = poorResultHint({
    failedTraces: failed,
    traces: boundaryTargets,
    freeAvailable: session.boundaryKinds.includes('free'),
  });
  renderHint($('paths-hint'), hint);
  pathsHint = hint?.text ?? null;
}

session.addEventListener('cancel', () => {
  traces.supersede();
  exactRatio.cancelled();
  heat.cancel();
  if ($('heat-toggle').checked && !surface.hasColors) $('heat-toggle').checked = false;
});

// ------------------------------------------------------------------ controls

$('sample-select').addEventListener('change', (event) => {
  // (Another mesh than a shared link's: urlSync.meshShown drops the link's points when it shows.)
  if (event.target.value) session.loadSample(event.target.value);
});

$('file-input').addEventListener('change', (event) => {
  const [file] = event.target.files;
  if (file) session.loadFile(file);
  event.target.value = ''; // choosing the same file again still fires 'change'
});

// The Up menu: auto (up-axis.js's rule, its choice shown in the option) or x / y / z.
function setUpAxis(bbox) {
  const select = $('up-select');
  const auto = autoUpAxis(bbox, $('sample-select').value !== ''); // '' while a file is on display
  select.options[0].textContent = `auto (${auto})`;
  view.setUpAxis(select.value === 'auto' ? auto : select.value);
}
$('up-select').addEventListener('change', () => {
  if (session.info) setUpAxis(session.info.bbox);
});
$('fit-button').addEventListener('click', () => view.fit());
$('view-reset-button').addEventListener('click', () => view.resetView());
for (const preset of ['top', 'front', 'side']) {
  $(`view-${preset}-button`).addEventListener('click', () => view.viewFrom(preset));
}

$('wireframe-toggle').addEventListener('change', (event) => surface.setWireframe(event.target.checked));
$('flat-toggle').addEventListener('change', (event) => surface.setFlatShading(event.target.checked));
$('boundary-toggle').addEventListener('change', () => tracePaths());
$('geodesic-toggle').addEventListener('change', () => geodesics.refresh());
$('base-toggle').addEventListener('change', (event) => paths.setBaseVisible(event.target.checked));

$('heat-toggle').addEventListener('change', (event) => {
  if (event.target.checked) {
    heat.show().catch((err) => {
      if (!isCancelled(err)) showError(err, 'Could not compute the heat distances');
    });
  } else {
    heat.reset();
  }
});

$('reset-button').addEventListener('click', () => {
  resetPathRequest();
  $('boundary-toggle').checked = true;
  tracePaths();
});

$('clear-targets-button').addEventListener('click', () => {
  pathRequest.added = [];
  tracePaths();
});

const viewport = $('viewport');
const overlay = $('drop-overlay');
viewport.addEventListener('dragover', (event) => {
  event.preventDefault();
  event.dataTransfer.dropEffect = 'copy';
  overlay.hidden = false;
});
viewport.addEventListener('dragleave', (event) => {
  if (!viewport.contains(event.relatedTarget)) overlay.hidden = true;
});
viewport.addEventListener('drop', (event) => {
  event.preventDefault();
  overlay.hidden = true;
  const [file] = event.dataTransfer.files;
  if (file) session.loadFile(file);
});

// ------------------------------------------------------------------ the page's observable state

// window.__straightest: what the page has on display, as plain data read from the modules when asked
// (each keeps its own and offers a status() or getters). The browser tests read it and the DOM,
// nothing else; docs/PAGE.md lists the fields. Getters only: it is read-only.
const paramStatus = () => param.status();
const observable = {
  state: () => document.body.dataset.state,
  samples: () => session.samples,
  threads: () => session.threads,
  lastInfo: () => session.info,
  cancels: () => session.cancels,
  lastError: () => shownError(),
  renders: () => view.status().renders,
  background: () => view.status().background,
  camera: () => view.status().camera,
  progress: () => progressView.status(),
  traces: () => traceCount,
  paths: () => pathsStatus,
  pathsHint: () => pathsHint,
  geodesics: () => geodesics.status(),
  exactRatio: () => exactRatio.status(),
  param: () => paramStatus().param,
  paramError: () => paramStatus().paramError,
  parameterizations: () => paramStatus().parameterizations,
  paramHint: () => paramStatus().paramHint,
  layoutFilling: () => paramStatus().layoutFilling,
  defaultBoundary: () => paramStatus().defaultBoundary,
  compare: () => paramStatus().compare,
  compareHint: () => paramStatus().compareHint,
  figure: () => exportPanel.figure.status(),
  atlas: () => atlasMode.status().atlas,
  atlasError: () => atlasMode.status().atlasError,
  atlases: () => atlasMode.status().atlases,
};
window.__straightest = Object.defineProperties(
  {},
  Object.fromEntries(Object.entries(observable).map(([name, get]) => [name, { get, enumerable: true }])),
);

urlSync.applyOptions();
session.start((samples) => urlSync.initialSample(samples));
