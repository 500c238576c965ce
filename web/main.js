// The page's main thread: renders with three.js and runs the UI. All geometry happens in the worker
// (worker.js), which owns the straightest WASM module; this file only turns its arrays into
// three.js buffers.
//
// After a mesh loads, the page asks the worker for the straightest paths from the default source to
// every boundary vertex and draws them (the paper's Figure 1 view); clicking the mesh moves the
// source, shift-clicking adds a destination. The page computes no distances or paths itself: it
// only draws the worker's arrays, picks points on the mesh and orchestrates the requests.
// Once the paths are drawn, the parameterization view (param-view.js) flattens the mesh; it owns
// the panels, the texture and the stretch heat map of the parameterization.
//
// Long work: the worker reports every stage's progress (progress-view.js shows the bars) and Cancel
// restarts the worker (worker-client.js) and reloads the mesh on display into the new one. Large
// meshes (LARGE_MESH_VERTICES) are not parameterized automatically, and many paths are drawn as
// plain lines (FAT_LINE_SEGMENTS) without hover picking, so the main thread never has long work.
//
// Test hooks: document.body.dataset.state is 'loading' | 'ready' | 'error' ('ready' once the mesh
// and its paths are drawn), and window.__straightest holds { state, samples, lastInfo, lastError,
// renders, background, traces, paths: { count, reached, source, traceMs, plain }, cancels } and the
// hooks of the parameterization view (param, paramError, parameterizations, compare: see
// param-view.js) and of the progress panel (progress: see progress-view.js).

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { createParamView } from './param-view.js';
import { createProgressView } from './progress-view.js';
import { createWorkerClient, isCancelled, workerError } from './worker-client.js';

const BACKGROUND = 0x14171c;
const MESH_COLOR = 0xd9b982;
const WIRE_COLOR = 0x1d2430;
const PATH_COLOR = 0x1f4fb8; // reached paths
const FAILED_COLOR = 0xe5484d; // partial paths of failed traces (dashed)
const HIGHLIGHT_COLOR = 0x19d3f0; // the hovered path and its cutting plane
const FAILED_HIGHLIGHT_COLOR = 0xff9a8f; // the hovered path when its trace failed
const SOURCE_COLOR = 0xffffff;
const ADDED_COLOR = 0xc15cff; // destinations added with shift+click
const BASE_PLANE_COLOR = 0x9cc2ff;

// Above this many vertices the page does not parameterize automatically after loading (seconds of
// work per solve; the button runs it, with progress and Cancel) and skips the layout's overlay
// polygons of the other two boundaries (another solve each).
const LARGE_MESH_VERTICES = 300_000;
// Above this many path segments the paths are plain 1-pixel LineSegments over the worker's points
// (fat lines take a quad and 6 floats per segment) and hovering them is off (picking would walk
// every segment and the surface on each pointer move).
const FAT_LINE_SEGMENTS = 100_000;
// Plain lines draw at most about this many points: every k-th point of each path (and its last).
// Beyond that the points are closer than a pixel, and uploading and drawing them would only cost
// time (a 1M-vertex mesh's boundary paths have ~5M points).
const PLAIN_LINE_POINTS = 250_000;

const $ = (id) => document.getElementById(id);

const hooks = {
  state: 'loading',
  samples: [],
  lastInfo: null,
  lastError: null,
  renders: 0,
  background: [(BACKGROUND >> 16) & 255, (BACKGROUND >> 8) & 255, BACKGROUND & 255],
  traces: 0, // completed path traces
  paths: null, // { count, reached, source, traceMs, plain } of the paths on display
  cancels: 0, // completed cancellations (the worker restarted and has the mesh again)
};
window.__straightest = hooks;

function setState(state) {
  hooks.state = state;
  document.body.dataset.state = state;
}

// ------------------------------------------------------------------ worker client

const MODULE_URL = import.meta.resolve('straightest'); // the worker imports the npm package from here

const progressView = createProgressView({ hooks, onCancel: () => cancelWork() });
const client = createWorkerClient({
  url: new URL('./worker.js', import.meta.url),
  observer: progressView,
});

/**
 * Sends a request to the worker; resolves with its reply, rejects with an Error (+ category;
 * 'cancelled' when Cancel stopped it). onProgress receives the 'progress' messages before the reply.
 */
function request(type, payload = {}, transfer = [], onProgress = null) {
  return client.request(type, payload, transfer, onProgress);
}

// ------------------------------------------------------------------ scene

const canvas = $('view-canvas');
const viewport = $('viewport');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.setClearColor(BACKGROUND);

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
camera.up.set(0, 0, 1); // the samples are height fields z = h(x, y)
camera.position.set(2, -3, 2);
scene.add(camera);

scene.add(new THREE.HemisphereLight(0xdde6ff, 0x2a2418, 0.7));
const headlight = new THREE.DirectionalLight(0xffffff, 2.6);
headlight.position.set(1, 1.5, 0.3); // relative to the camera (upper right): follows the view
camera.add(headlight);
camera.add(headlight.target);
headlight.target.position.set(0, 0, -1);

const controls = new OrbitControls(camera, canvas);
controls.addEventListener('change', () => requestRender());

const surfaceMaterial = new THREE.MeshStandardMaterial({
  color: MESH_COLOR,
  roughness: 0.75,
  metalness: 0.0,
  side: THREE.DoubleSide,
  polygonOffset: true, // keeps the wireframe overlay and the paths (which lie on the faces) on top
  polygonOffsetFactor: 1.5,
  polygonOffsetUnits: 2,
});
const wireMaterial = new THREE.MeshBasicMaterial({
  color: WIRE_COLOR,
  wireframe: true,
  transparent: true,
  opacity: 0.55,
});

let surface = null; // THREE.Mesh of the current geometry
let wireframe = null; // overlay sharing the same geometry
let meshGeneration = 0; // incremented per displayed mesh; replies for an older mesh are dropped
let sceneScale = 1; // bounding-box diagonal of the current mesh: sizes markers and planes

let scheduledFrame = 0; // requestAnimationFrame id of a pending render, 0 if none
function render() {
  cancelAnimationFrame(scheduledFrame); // rendering now makes a pending frame redundant
  scheduledFrame = 0;
  renderer.render(scene, camera);
  hooks.renders += 1;
}
function requestRender() {
  if (!scheduledFrame) scheduledFrame = requestAnimationFrame(render);
}

/**
 * Resolves once the GPU has finished the frames queued so far (polled, never waited for). A large
 * upload waits for it: WebGL hands buffers to the GPU process through a bounded transfer buffer, so
 * an upload queued behind slow frames (seconds each with a software renderer and a million-vertex
 * mesh) would block the main thread until they are done.
 */
function gpuIdle() {
  const gl = renderer.getContext();
  const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  gl.flush();
  return new Promise((resolve) => {
    const poll = () => {
      if (!fence || gl.isContextLost() || gl.getSyncParameter(fence, gl.SYNC_STATUS) === gl.SIGNALED) {
        if (fence) gl.deleteSync(fence);
        resolve();
      } else {
        setTimeout(poll, 30);
      }
    };
    poll();
  });
}

function resize() {
  const { clientWidth: w, clientHeight: h } = viewport;
  if (w === 0 || h === 0) return;
  renderer.setSize(w, h, false);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
  requestRender();
}
new ResizeObserver(resize).observe(viewport);
resize();

/** Replaces the displayed mesh by the worker's arrays. */
function showMesh(positions, indices, normals) {
  removeSurface();
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  geometry.setIndex(new THREE.BufferAttribute(indices, 1));
  geometry.computeBoundingSphere();
  if (surfaceMaterial.vertexColors) resetSurfaceColor(); // the next trace recolours if asked
  clearPaths(); // they belong to the previous mesh
  surface = new THREE.Mesh(geometry, surfaceMaterial);
  wireframe = new THREE.Mesh(geometry, wireMaterial);
  wireframe.visible = $('wireframe-toggle').checked;
  scene.add(surface, wireframe);
  meshGeneration += 1;
  paramView.meshChanged();
}

function removeSurface() {
  if (!surface) return;
  scene.remove(surface, wireframe);
  surface.geometry.dispose();
  surface = wireframe = null;
}

/** Nothing on display (after cancelling the reload of the mesh into a restarted worker). */
function dropMesh() {
  if (surfaceMaterial.vertexColors) resetSurfaceColor();
  clearPaths();
  removeSurface();
  meshGeneration += 1;
  meshLabel = '';
  meshStatus = '';
  displayed = null;
  hooks.lastInfo = null;
  hooks.paths = null;
  paramView.meshChanged();
  requestRender();
}

/** True for meshes the page does not parameterize on its own (see LARGE_MESH_VERTICES). */
function largeMesh() {
  return (hooks.lastInfo?.vertices ?? 0) > LARGE_MESH_VERTICES;
}

/**
 * Sets the surface material from what colours the surface: the heat-distance vertex colours, else
 * the parameterization's texture (if any), else the plain mesh colour.
 */
function updateSurfaceMaterial() {
  const map = surfaceMaterial.vertexColors ? null : paramView.texture();
  if (surfaceMaterial.map !== map) {
    surfaceMaterial.map = map;
    surfaceMaterial.needsUpdate = true;
  }
  surfaceMaterial.color.set(surfaceMaterial.vertexColors || map ? 0xffffff : MESH_COLOR);
  requestRender();
}

/** Points the camera at the bounding box, from the front-right and above, so it fills the view. */
function frameBox(bbox) {
  const min = new THREE.Vector3(...bbox.min);
  const max = new THREE.Vector3(...bbox.max);
  const center = min.clone().add(max).multiplyScalar(0.5);
  const radius = Math.max(max.distanceTo(min) / 2, 1e-6);
  const halfFov = THREE.MathUtils.degToRad(camera.fov / 2);
  const fit = Math.min(halfFov, Math.atan(Math.tan(halfFov) * camera.aspect));
  sceneScale = 2 * radius;
  const distance = (radius / Math.sin(fit)) * 0.95;
  const direction = new THREE.Vector3(0.55, -1.0, 0.75).normalize();
  camera.position.copy(center).addScaledVector(direction, distance);
  camera.near = distance / 100;
  camera.far = distance * 100;
  camera.updateProjectionMatrix();
  controls.target.copy(center);
  controls.update();
}

// ------------------------------------------------------------------ parameterization view

const paramView = createParamView({
  request,
  hooks,
  scene,
  renderer,
  surface: () => surface,
  generation: () => meshGeneration,
  label: () => meshLabel,
  pathSource: () => pathRequest.source,
  large: () => largeMesh(),
  largeLimit: LARGE_MESH_VERTICES,
  gpuIdle,
  surfaceChanged: () => updateSurfaceMaterial(),
  requestRender,
});

// ------------------------------------------------------------------ panels

function formatNumber(x) {
  if (!Number.isFinite(x)) return String(x);
  return Number.isInteger(x) ? String(x) : String(Number(x.toPrecision(3)));
}

function showInfo(info, label) {
  $('info-source').textContent = label ? `— ${label}` : '';
  $('info-vertices').textContent = formatNumber(info.vertices);
  $('info-faces').textContent = formatNumber(info.faces);
  $('info-edges').textContent = formatNumber(info.edges);
  const loops = info.boundaryLoops ?? [];
  $('info-boundary').textContent =
    loops.length === 0 ? '0 (closed)' : `${loops.length} (${loops.join(', ')} edges)`;
  $('info-euler').textContent = formatNumber(info.eulerCharacteristic);
  $('info-components').textContent = formatNumber(info.components);
  $('info-degenerate').textContent = formatNumber(info.degenerateFaces);
  $('info-reoriented').textContent = formatNumber(info.reorientedFaces);
  $('info-unreferenced').textContent = formatNumber(info.unreferencedVertices);
  const { min, max } = info.bbox;
  $('info-bbox').textContent = min.map((m, i) => formatNumber(max[i] - m)).join(' × ');

  const list = $('info-problems');
  list.replaceChildren();
  const problems = info.problems ?? [];
  for (const text of problems.length ? problems : ['none']) {
    const item = document.createElement('li');
    item.textContent = text;
    if (!problems.length) item.className = 'muted';
    list.append(item);
  }
}

// What to do about an error, per category, below the core's own message.
const ERROR_HINTS = {
  too_large: 'The browser could not give this mesh enough memory: WebAssembly memory is limited to ' +
    '4 GB, and a mesh takes about 1.3 GB per million vertices once parameterized. Try a smaller or ' +
    'decimated mesh.',
  worker: 'Reload the page to start a new geometry worker.',
};

function showError(err, title) {
  hooks.lastError = { message: err.message, category: err.category ?? 'error' };
  $('error-title').textContent = title;
  $('error-message').textContent = err.message;
  $('error-category').textContent = err.category ?? 'error';
  const hint = ERROR_HINTS[err.category] ?? '';
  $('error-hint').textContent = hint;
  $('error-hint').hidden = !hint;
  $('error-panel').hidden = false;
  $('status').textContent = 'Error — see above';
  setState('error');
}

function clearError() {
  $('error-panel').hidden = true;
}

// ------------------------------------------------------------------ loading

let latestLoad = 0; // only the most recent load may update the view
let displayed = null; // where the mesh on display came from: { sample } or { file } (see reloadInto)
let meshStatus = ''; // the status line of the mesh on display
let meshLabel = ''; // the sample or file name of the mesh on display

/**
 * Loads a mesh with send(current) (current() is false once a newer load or a cancel took over)
 * and shows it, its paths and (unless it is large) its parameterization. origin: { sample } or
 * { file }, kept to reload the mesh after a cancel.
 */
async function load(what, send, origin) {
  const ticket = ++latestLoad;
  const current = () => ticket === latestLoad;
  setState('loading');
  $('status').textContent = `Loading ${what}…`;
  try {
    const reply = await send(current);
    if (!current()) return;
    meshLabel = reply.label;
    hooks.lastInfo = reply.info;
    showMesh(reply.positions, reply.indices, reply.normals);
    frameBox(reply.info.bbox);
    showInfo(reply.info, reply.label);
    clearError();
    hooks.lastError = null;
    displayed = origin;
    meshStatus =
      `${reply.label}: ${reply.info.vertices} vertices, ${reply.info.faces} faces ` +
      `(${reply.timeMs.toFixed(0)} ms in the worker)`;
    $('status').textContent = meshStatus;
    requestRender(); // shows the mesh if tracing takes longer than a frame
    resetPathRequest();
    await tracePaths(); // sets the state ('ready' once the paths are drawn)
    // Then the parameterization, so it does not delay the first view of the mesh and its paths.
    if (current()) await paramView.meshReady();
  } catch (err) {
    if (!current() || isCancelled(err)) return;
    $('sample-select').value = displayed?.sample ?? '';
    showError(err, `Could not load ${what}`);
  }
}

function loadSample(name) {
  return load(`sample “${name}”`, () => request('sample', { name }), { sample: name });
}

function formatFromName(name) {
  const ext = /\.([^.]+)$/.exec(name)?.[1]?.toLowerCase();
  return ext === 'obj' || ext === 'off' ? ext : 'auto';
}

async function loadFile(file) {
  const select = $('sample-select');
  if (!select.querySelector('option[value=""]')) {
    select.prepend(new Option('(local file)', ''));
    select.options[0].disabled = true;
  }
  select.value = '';
  return load(`“${file.name}”`, async (current) => {
    const bytes = await file.arrayBuffer();
    if (!current()) throw workerError('cancelled', 'cancelled'); // do not send it to a new worker
    return request('file', { name: file.name, format: formatFromName(file.name), bytes }, [bytes]);
  }, { file });
}

// ------------------------------------------------------------------ cancelling

let restoring = false; // the mesh on display is being reloaded into a restarted worker
let latestReload = 0;

/**
 * Cancel: the worker is busy inside a synchronous WASM call and cannot read a message, so it is
 * terminated and a new one loads the mesh on display again. Every pending request rejects as
 * 'cancelled', and the tickets below make sure that nothing they started goes on.
 */
function cancelWork() {
  const wasRestoring = restoring;
  client.restart();
  latestLoad += 1; // a load in flight stops (no paths, no parameterization after it)
  latestTrace += 1;
  latestHeat += 1;
  paramView.cancelled();
  if (wasRestoring) dropMesh(); // cancelling the reload itself: nothing is left in the worker
  if ($('heat-toggle').checked && !surfaceMaterial.vertexColors) $('heat-toggle').checked = false;
  $('sample-select').value = displayed?.sample ?? '';
  reloadInto();
}

/** Initializes the restarted worker and loads the mesh on display into it again. */
async function reloadInto() {
  const origin = displayed;
  const ticket = ++latestReload;
  restoring = true;
  setState('loading');
  $('status').textContent = 'Cancelled — restarting the geometry worker…';
  try {
    await request('init', { moduleUrl: MODULE_URL });
    if (origin?.sample) {
      await request('sample', { name: origin.sample, restore: true });
    } else if (origin?.file) {
      const bytes = await origin.file.arrayBuffer();
      if (origin !== displayed) return;
      const { name } = origin.file;
      await request('file', { name, format: formatFromName(name), bytes, restore: true }, [bytes]);
    }
    if (origin !== displayed) return;
    hooks.cancels += 1;
    clearError();
    $('status').textContent = origin
      ? `Cancelled. ${meshStatus}`
      : 'Cancelled: no mesh loaded — choose a sample or open a file.';
    setState('ready');
  } catch (err) {
    if (isCancelled(err) || origin !== displayed) return; // a newer cancel or load took over
    showError(err, 'Could not restart the geometry worker');
  } finally {
    if (ticket === latestReload) restoring = false;
  }
}

// ------------------------------------------------------------------ straightest paths

// What the next trace asks for: the source ('auto' = the default source) and the destinations
// (the boundary vertices if the toggle is on, plus the points added with shift+click).
const pathRequest = {
  source: 'auto',
  added: [], // [{ point: {face, bary}, position: THREE.Vector3 }]
};
let shown = null; // the 'paths' reply on display and the objects drawn for it (see showPaths)
let latestTrace = 0; // only the most recent trace may update the view
let latestHeat = 0; // likewise for the heat-distance colours

const pathGroup = new THREE.Group(); // everything drawn for the current paths; rebuilt per trace
scene.add(pathGroup);

// Thin, slightly transparent lines: up to a few hundred paths meet at the source.
const reachedMaterial = new LineMaterial({
  color: PATH_COLOR, linewidth: 1, transparent: true, opacity: 0.75,
});
const failedMaterial = new LineMaterial({ color: FAILED_COLOR, linewidth: 1.8, dashed: true });
const highlightMaterial = new LineMaterial({ color: HIGHLIGHT_COLOR, linewidth: 4.5 });
const sourceMaterial = new THREE.MeshStandardMaterial({
  color: SOURCE_COLOR, emissive: 0x555555, roughness: 0.4,
});
const addedMaterial = new THREE.MeshStandardMaterial({
  color: ADDED_COLOR, emissive: 0x3a1050, roughness: 0.4,
});
const basePlaneMaterial = new THREE.MeshBasicMaterial({
  color: BASE_PLANE_COLOR, transparent: true, opacity: 0.1, side: THREE.DoubleSide, depthWrite: false,
});
const basePlaneRimMaterial = new THREE.LineBasicMaterial({
  color: BASE_PLANE_COLOR, transparent: true, opacity: 0.45, depthWrite: false,
});
const cutPlaneMaterial = new THREE.MeshBasicMaterial({
  color: HIGHLIGHT_COLOR, transparent: true, opacity: 0.16, side: THREE.DoubleSide, depthWrite: false,
});
const cutPlaneRimMaterial = new THREE.LineBasicMaterial({
  color: HIGHLIGHT_COLOR, transparent: true, opacity: 0.6, depthWrite: false,
});
const markerGeometry = new THREE.SphereGeometry(1, 24, 16); // scaled per marker
// The plain-line fallback for many paths (see FAT_LINE_SEGMENTS): 1 pixel, failed paths solid red;
// lighter than the fat lines, as thousands of them cover the surface.
const plainReachedMaterial = new THREE.LineBasicMaterial({ color: PATH_COLOR, transparent: true, opacity: 0.4 });
const plainFailedMaterial = new THREE.LineBasicMaterial({ color: FAILED_COLOR });

/**
 * Builds the plain-line shaders while the GPU is idle: a program's first use waits for the GPU to
 * finish its queued work, which with a software renderer can be a large mesh's frame of seconds.
 */
function prewarmPlainLines() {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
  geometry.setIndex([0, 1]);
  const warm = new THREE.Scene();
  warm.add(new THREE.LineSegments(geometry, plainReachedMaterial), new THREE.LineSegments(geometry, plainFailedMaterial));
  renderer.render(warm, camera);
  geometry.dispose();
  requestRender(); // the real scene replaces the warm-up frame
}
prewarmPlainLines();

/** Removes and frees everything in `group` (shared materials and the marker geometry stay). */
function clearGroup(group) {
  for (const child of [...group.children]) {
    group.remove(child);
    child.traverse((node) => {
      if (node.geometry && node.geometry !== markerGeometry) node.geometry.dispose();
    });
  }
}

function marker(position, material, radius) {
  const sphere = new THREE.Mesh(markerGeometry, material);
  sphere.position.copy(position);
  sphere.scale.setScalar(radius);
  sphere.renderOrder = 2;
  return sphere;
}

/** Number of segments of the listed paths. */
function segmentCount({ offsets }, paths) {
  let count = 0;
  for (const i of paths) count += Math.max(0, offsets[i + 1] - offsets[i] - 1);
  return count;
}

/**
 * Many paths: plain LineSegments, one per [paths, material] group, over one shared position
 * attribute holding every `stride`-th point of each path and its last (see PLAIN_LINE_POINTS), with
 * an index pair per segment. No picking data. Returns { lines, stride }.
 */
function plainPathLines(reply, groups) {
  const { points, offsets, count } = reply;
  const stride = Math.max(1, Math.ceil(offsets[count] / PLAIN_LINE_POINTS));
  // start[i]: the first kept point of path i; a path of n ≥ 2 points keeps ⌈(n−1)/stride⌉ + 1.
  const start = new Uint32Array(count + 1);
  for (let i = 0; i < count; i++) {
    const n = offsets[i + 1] - offsets[i];
    start[i + 1] = start[i] + (n < 2 ? n : Math.ceil((n - 1) / stride) + 1);
  }
  const kept = new Float32Array(3 * start[count]);
  const copy = (from, to) => {
    kept[3 * to] = points[3 * from];
    kept[3 * to + 1] = points[3 * from + 1];
    kept[3 * to + 2] = points[3 * from + 2];
  };
  for (let i = 0; i < count; i++) {
    const [first, end] = [offsets[i], offsets[i + 1]];
    let to = start[i];
    for (let j = first; j < end; j += stride) copy(j, to++);
    if (to < start[i + 1]) copy(end - 1, to); // the last point, when the stride skipped it
  }
  const positions = new THREE.BufferAttribute(kept, 3);
  const lines = [];
  for (const [paths, material] of groups) {
    let segments = 0;
    for (const i of paths) segments += Math.max(0, start[i + 1] - start[i] - 1);
    if (segments === 0) continue;
    const index = new Uint32Array(2 * segments);
    let s = 0;
    for (const i of paths) {
      for (let j = start[i]; j + 1 < start[i + 1]; j++) {
        index[s++] = j;
        index[s++] = j + 1;
      }
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', positions);
    geometry.setIndex(new THREE.BufferAttribute(index, 1));
    const object = new THREE.LineSegments(geometry, material);
    object.renderOrder = 1;
    lines.push(object);
  }
  return { lines, stride };
}

/**
 * One LineSegments2 holding every segment of the listed paths, and for each segment the path it
 * belongs to (to name the path under the cursor).
 */
function pathLines(reply, paths, material) {
  const { points, offsets } = reply;
  const count = segmentCount(reply, paths);
  if (count === 0) return null;
  const segments = new Float32Array(6 * count);
  const owner = new Uint32Array(count);
  let s = 0;
  for (const i of paths) {
    for (let j = offsets[i]; j + 1 < offsets[i + 1]; j++, s++) {
      segments.set(points.subarray(3 * j, 3 * j + 6), 6 * s);
      owner[s] = i;
    }
  }
  const geometry = new LineSegmentsGeometry().setPositions(segments);
  const lines = new LineSegments2(geometry, material);
  if (material.dashed) lines.computeLineDistances();
  lines.userData.owner = owner;
  lines.renderOrder = 1;
  return lines;
}

/** A translucent quad at `origin` with edges along unit vectors u, v over [u0,u1]×[v0,v1], plus its rim. */
function planeQuad(origin, u, v, [u0, u1], [v0, v1], fill, rim) {
  const corners = [[u0, v0], [u1, v0], [u1, v1], [u0, v1]].map(([a, b]) =>
    origin.clone().addScaledVector(u, a).addScaledVector(v, b));
  const geometry = new THREE.BufferGeometry().setFromPoints(corners);
  geometry.setIndex([0, 1, 2, 0, 2, 3]);
  const group = new THREE.Group();
  const quad = new THREE.Mesh(geometry, fill);
  const outline = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(corners), rim);
  quad.renderOrder = outline.renderOrder = 3;
  group.add(quad, outline);
  return group;
}

/** The base plane at the source: a translucent disc perpendicular to the base normal. */
function basePlaneDisc(origin, normal) {
  const radius = 0.42 * sceneScale;
  const group = new THREE.Group();
  const disc = new THREE.Mesh(new THREE.CircleGeometry(radius, 96), basePlaneMaterial);
  const rimPoints = new THREE.EllipseCurve(0, 0, radius, radius).getPoints(96)
    .map((p) => new THREE.Vector3(p.x, p.y, 0));
  const rim = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(rimPoints), basePlaneRimMaterial);
  disc.renderOrder = rim.renderOrder = 3;
  group.add(disc, rim);
  group.position.copy(origin);
  group.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
  group.visible = $('base-toggle').checked;
  return group;
}

function clearPaths() {
  hideTooltip();
  clearGroup(pathGroup);
  shown = null;
}

/** Replaces the drawn paths, markers and base plane by the worker's 'paths' reply. */
function showPaths(reply) {
  const source = new THREE.Vector3(...reply.sourcePosition);
  const normal = new THREE.Vector3(...reply.normal).normalize();
  const reached = [];
  const failed = [];
  reply.statuses.forEach((status, i) => (status === 'reached' ? reached : failed).push(i));

  failedMaterial.dashSize = 0.012 * sceneScale;
  failedMaterial.gapSize = 0.008 * sceneScale;
  let lines;
  let stride = 1;
  const plain = segmentCount(reply, reply.statuses.keys()) > FAT_LINE_SEGMENTS;
  if (plain) {
    ({ lines, stride } = plainPathLines(reply, [[reached, plainReachedMaterial], [failed, plainFailedMaterial]]));
  } else {
    lines = [pathLines(reply, reached, reachedMaterial), pathLines(reply, failed, failedMaterial)]
      .filter(Boolean);
  }
  const basePlane = basePlaneDisc(source, normal);
  const highlight = new Line2(new LineGeometry(), highlightMaterial);
  highlight.visible = false;
  highlight.renderOrder = 2;
  const cutPlane = new THREE.Group();
  pathGroup.add(...lines, basePlane, highlight, cutPlane, marker(source, sourceMaterial, 0.011 * sceneScale));
  for (const { position } of pathRequest.added) {
    pathGroup.add(marker(position, addedMaterial, 0.008 * sceneScale));
  }
  // Plain lines have no picking data; so many paths lie on a large mesh whose surface would be
  // ray cast on every pointer move.
  const pickable = plain ? [] : lines;
  shown = { reply, source, normal, lines: pickable, plain, stride, basePlane, highlight, cutPlane, hovered: -1 };
}

/**
 * Highlights path i (or nothing for -1) and draws its cutting plane: the plane through the source S
 * spanned by the base normal n and the direction to the destination D, as a quad covering the path.
 */
function highlightPath(i) {
  if (!shown || shown.hovered === i) return;
  const { reply, source, normal, highlight, cutPlane } = shown;
  shown.hovered = i;
  clearGroup(cutPlane);
  highlight.visible = false;
  requestRender();
  if (i < 0) return;

  const path = reply.points.subarray(3 * reply.offsets[i], 3 * reply.offsets[i + 1]);
  if (path.length >= 6) {
    highlight.geometry.dispose();
    highlight.geometry = new LineGeometry().setPositions(path);
    highlightMaterial.color.set(reply.statuses[i] === 'reached' ? HIGHLIGHT_COLOR : FAILED_HIGHLIGHT_COLOR);
    highlight.visible = true;
  }
  // D: the target's position, or the end of the path when the worker could not place it.
  const target = reply.targetPositions.subarray(3 * i, 3 * i + 3);
  const destination = Number.isFinite(target[0])
    ? new THREE.Vector3(...target)
    : new THREE.Vector3(...path.subarray(path.length - 3));
  const along = destination.clone().sub(source);
  along.addScaledVector(normal, -along.dot(normal)); // in-plane direction, perpendicular to n
  if (along.length() < 1e-9 * sceneScale) return; // D − S parallel to n: no plane to draw
  along.normalize();
  // Extent of the quad: the path and D in the (along, n) coordinates of the plane, plus a margin.
  const uRange = [0, 0];
  const vRange = [0, 0];
  const extend = (p) => {
    const d = p.clone().sub(source);
    const [a, b] = [d.dot(along), d.dot(normal)];
    uRange[0] = Math.min(uRange[0], a); uRange[1] = Math.max(uRange[1], a);
    vRange[0] = Math.min(vRange[0], b); vRange[1] = Math.max(vRange[1], b);
  };
  extend(destination);
  const p = new THREE.Vector3();
  for (let j = 0; j < path.length; j += 3) extend(p.set(path[j], path[j + 1], path[j + 2]));
  const margin = 0.04 * sceneScale;
  uRange[0] -= margin; uRange[1] += margin;
  vRange[0] -= margin; vRange[1] += margin;
  cutPlane.add(planeQuad(source, along, normal, uRange, vRange, cutPlaneMaterial, cutPlaneRimMaterial));
}

/** 'vertex 12', 'face 34 (0.20, 0.30, 0.50)' (or just 'face 34' without the coordinates), … */
function describePoint(point, withCoordinates = true) {
  if (typeof point === 'number') return `vertex ${point}`;
  if (typeof point?.vertex === 'number') return `vertex ${point.vertex}`;
  if (typeof point?.face === 'number') {
    const bary = point.bary.map((b) => b.toFixed(2)).join(', ');
    return withCoordinates ? `face ${point.face} (${bary})` : `face ${point.face}`;
  }
  if (typeof point?.halfedge === 'number') {
    return withCoordinates ? `halfedge ${point.halfedge} (t = ${point.t.toFixed(2)})` : `halfedge ${point.halfedge}`;
  }
  return String(point);
}

/** Fills the stats panel from a 'paths' reply. */
function showStats(reply) {
  const { count, reached, statuses, lengths, facesCrossed, timings } = reply;
  const isDefault = pathRequest.source === 'auto';
  const source = $('stats-source');
  source.textContent = describePoint(reply.source, false) + (isDefault ? ' (default)' : '');
  source.title = describePoint(reply.source);
  const useBoundary = $('boundary-toggle').checked && !closedMesh();
  const boundaryCount = count - pathRequest.added.length;
  const parts = [];
  if (useBoundary) parts.push(`${boundaryCount} boundary`);
  if (pathRequest.added.length) parts.push(`${pathRequest.added.length} added`);
  $('stats-targets').textContent = parts.join(' + ') || 'none';
  $('stats-paths').textContent = String(count);
  $('stats-reached').textContent = count ? `${reached} (${((100 * reached) / count).toFixed(0)}%)` : '0';
  $('stats-failed').textContent = String(count - reached);

  const failures = new Map();
  for (const status of statuses) if (status !== 'reached') failures.set(status, (failures.get(status) ?? 0) + 1);
  const list = $('stats-failures');
  list.replaceChildren(...[...failures].map(([status, n]) => {
    const item = document.createElement('li');
    item.innerHTML = `<code></code> <span></span>`;
    item.firstChild.textContent = status;
    item.lastChild.textContent = `${n}`;
    return item;
  }));
  list.hidden = failures.size === 0;

  let sum = 0;
  let max = 0;
  statuses.forEach((status, i) => {
    if (status !== 'reached') return;
    sum += lengths[i];
    max = Math.max(max, lengths[i]);
  });
  $('stats-length').textContent = reached ? `${formatNumber(sum / reached)} / ${formatNumber(max)}` : '–';
  const faces = facesCrossed.reduce((a, b) => a + b, 0);
  const facesMax = facesCrossed.reduce((a, b) => Math.max(a, b), 0);
  $('stats-faces').textContent = count ? `${faces} / ${facesMax}` : '–';
  const time = $('stats-time');
  time.textContent = `${timings.trace.toFixed(1)} ms`;
  time.title = `tracing ${timings.trace.toFixed(2)} ms, setup ${timings.prepare.toFixed(2)} ms ` +
    `(${reply.timeMs.toFixed(1)} ms in the worker in all)`;
  $('stats-traces').textContent = String(hooks.traces);

  const notes = [];
  if (closedMesh()) {
    notes.push('Closed mesh: no boundary, so no paths by default. Shift+click the mesh to add destinations.');
  } else if (count === 0) {
    notes.push('No destinations: tick “Boundary destinations” or shift+click the mesh to add some.');
  }
  if (reply.baseNote) notes.push(`Base plane: ${reply.baseNote}.`);
  if (shown?.plain) {
    const every = shown.stride > 1 ? ` through 1 point in ${shown.stride}` : '';
    notes.push(`${(reply.points.length / 3).toLocaleString('en-US')} path points: drawn as thin plain ` +
      `lines${every} (failed ones solid red), and hovering a path is off.`);
  }
  $('stats-note').textContent = notes.join(' ');
  $('stats-note').hidden = notes.length === 0;
  $('clear-targets-button').disabled = pathRequest.added.length === 0;
}

function closedMesh() {
  return (hooks.lastInfo?.boundaryLoops ?? []).length === 0;
}

/** The 'targets' of the next 'paths' request (see the protocol in worker.js). */
function currentTargets() {
  const added = pathRequest.added.map(({ point }) => point);
  if (!$('boundary-toggle').checked) return added;
  return added.length ? ['boundary', ...added] : 'boundary';
}

/** Back to the default source and the boundary destinations. */
function resetPathRequest() {
  pathRequest.source = 'auto';
  pathRequest.added = [];
  hideTooltip();
}

/** Asks the worker for the paths of `pathRequest` and draws them; the page is 'ready' afterwards. */
async function tracePaths() {
  if (!surface) return;
  const ticket = ++latestTrace;
  const generation = meshGeneration;
  const stale = () => ticket !== latestTrace || generation !== meshGeneration;
  setState('loading');
  $('status').textContent = 'Tracing straightest paths…';
  let stage = 'trace the straightest paths';
  try {
    const reply = await request('paths', { source: pathRequest.source, targets: currentTargets() });
    if (stale()) return;
    hooks.traces += 1;
    clearPaths();
    showPaths(reply);
    showStats(reply);
    hooks.paths = {
      count: reply.count,
      reached: reply.reached,
      source: reply.source,
      traceMs: reply.timings.trace,
      plain: shown.plain,
    };
    stage = 'compute the heat distances';
    if ($('heat-toggle').checked) await showHeat();
    if (stale()) return;
    clearError();
    render();
    $('status').textContent = reply.count
      ? `${meshStatus} · ${reply.count} paths in ${reply.timeMs.toFixed(0)} ms`
      : meshStatus;
    setState('ready');
  } catch (err) {
    if (stale() || isCancelled(err)) return;
    showError(err, `Could not ${stage}`);
  }
}

// ------------------------------------------------------------------ heat-distance colours

// A sequential colormap (light → dark) with darker bands every 1/12 of the range, so the level
// sets of the distance show; the paths (blue) stay readable on top.
const HEAT_STOPS = [0xfff1c7, 0xf6c37a, 0xe98b57, 0xc9574f, 0x8f3558, 0x4f2456].map((c) => new THREE.Color(c));
const HEAT_BANDS = 12;
const UNREACHABLE_COLOR = new THREE.Color(0x555a63);

function heatColor(t, target) {
  const x = Math.min(Math.max(t, 0), 1) * (HEAT_STOPS.length - 1);
  const k = Math.min(Math.floor(x), HEAT_STOPS.length - 2);
  target.lerpColors(HEAT_STOPS[k], HEAT_STOPS[k + 1], x - k);
  const band = (t * HEAT_BANDS) % 1;
  if (band < 0.12) target.multiplyScalar(0.82); // a thin darker stripe at each band start
  return target;
}

/** Colours the surface by heat-method distance from the shown source (computed by the worker). */
async function showHeat() {
  if (!surface || !shown) return;
  const ticket = ++latestHeat;
  const generation = meshGeneration;
  const reply = await request('distances', { source: shown.reply.source });
  if (ticket !== latestHeat || generation !== meshGeneration || !$('heat-toggle').checked) return;
  const { distances, max } = reply;
  const colors = new Float32Array(3 * distances.length);
  const color = new THREE.Color();
  distances.forEach((d, v) => {
    (Number.isFinite(d) ? heatColor(max > 0 ? d / max : 0, color) : UNREACHABLE_COLOR)
      .toArray(colors, 3 * v);
  });
  surface.geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
  surfaceMaterial.vertexColors = true;
  surfaceMaterial.needsUpdate = true;
  updateSurfaceMaterial(); // the heat colours replace the texture
  $('heat-max').textContent = formatNumber(max);
  $('heat-legend').hidden = false;
  requestRender();
}

/** Back to the plain mesh colour (the distances of the current mesh are dropped). */
function resetSurfaceColor() {
  latestHeat += 1;
  surface?.geometry.deleteAttribute('color');
  surfaceMaterial.vertexColors = false;
  surfaceMaterial.needsUpdate = true;
  updateSurfaceMaterial();
  $('heat-legend').hidden = true;
}

// ------------------------------------------------------------------ picking and hovering

const raycaster = new THREE.Raycaster();
raycaster.params.Line2 = { threshold: 6 }; // pixels around a path that count as "on" it
const pointer = new THREE.Vector2();

/** Sets the raycaster from a pointer event on the canvas. */
function aimAt(event) {
  const rect = canvas.getBoundingClientRect();
  pointer.set(
    ((event.clientX - rect.left) / rect.width) * 2 - 1,
    -((event.clientY - rect.top) / rect.height) * 2 + 1,
  );
  raycaster.setFromCamera(pointer, camera);
  raycaster.camera = camera;
}

/** The surface under the pointer as { hit, point: {face, bary} }, or null. */
function pickSurface() {
  if (!surface) return null;
  const [hit] = raycaster.intersectObject(surface, false);
  if (!hit || hit.faceIndex == null) return null;
  const { index, attributes } = surface.geometry;
  const corner = (k) => new THREE.Vector3().fromBufferAttribute(attributes.position, index.getX(3 * hit.faceIndex + k));
  const bary = THREE.Triangle.getBarycoord(hit.point, corner(0), corner(1), corner(2), new THREE.Vector3());
  if (!bary) return null; // a degenerate triangle
  // Clamp the rounding noise so the point is inside the face, then renormalize.
  const b = bary.toArray().map((x) => Math.max(x, 0));
  const total = b[0] + b[1] + b[2];
  return { hit, point: { face: hit.faceIndex, bary: b.map((x) => x / total) } };
}

/** The path under the pointer (not hidden behind the surface), or -1. */
function pickPath() {
  if (!shown || shown.lines.length === 0) return -1;
  const surfaceHit = surface ? raycaster.intersectObject(surface, false)[0] : null;
  const limit = surfaceHit ? surfaceHit.distance + 0.01 * sceneScale : Infinity;
  let best = -1;
  let bestAngle = Infinity;
  for (const hit of raycaster.intersectObjects(shown.lines, false)) {
    const depth = raycaster.ray.origin.distanceTo(hit.pointOnLine);
    if (depth > limit) continue;
    const angle = raycaster.ray.distanceToPoint(hit.pointOnLine) / depth; // off the ray, as seen
    if (angle < bestAngle) {
      bestAngle = angle;
      best = hit.object.userData.owner[hit.faceIndex];
    }
  }
  return best;
}

const tooltip = $('path-tooltip');

function showTooltip(i, event) {
  const { reply } = shown;
  const status = reply.statuses[i];
  tooltip.replaceChildren();
  const title = document.createElement('strong');
  title.textContent = `Path ${i + 1} of ${reply.count} → ${describePoint(reply.targets[i])}`;
  const state = document.createElement('span');
  state.className = status === 'reached' ? 'reached' : 'failed';
  state.textContent = status === 'reached' ? 'reached' : `${status} (partial path)`;
  const details = document.createElement('span');
  details.textContent =
    `length ${formatNumber(reply.lengths[i])} · ${reply.facesCrossed[i]} faces crossed`;
  tooltip.append(title, state, details);
  const rect = viewport.getBoundingClientRect();
  const x = event.clientX - rect.left;
  const y = event.clientY - rect.top;
  tooltip.hidden = false;
  // Keep the tooltip inside the view: flip to the left/top near the right/bottom edge.
  const left = x + 14 + tooltip.offsetWidth > rect.width ? x - 14 - tooltip.offsetWidth : x + 14;
  const top = y + 14 + tooltip.offsetHeight > rect.height ? y - 14 - tooltip.offsetHeight : y + 14;
  tooltip.style.left = `${Math.max(0, left)}px`;
  tooltip.style.top = `${Math.max(0, top)}px`;
}

function hideTooltip() {
  tooltip.hidden = true;
  canvas.classList.remove('over-path');
  if (shown) highlightPath(-1);
}

let hoverEvent = null; // the latest pointer move, handled once per frame
canvas.addEventListener('pointermove', (event) => {
  if (event.buttons !== 0) return; // orbiting
  if (!hoverEvent) requestAnimationFrame(handleHover);
  hoverEvent = event;
});
canvas.addEventListener('pointerleave', () => {
  hoverEvent = null;
  hideTooltip();
});

function handleHover() {
  const event = hoverEvent;
  hoverEvent = null;
  if (!event || !shown) return;
  aimAt(event);
  const i = pickPath();
  if (i < 0) {
    hideTooltip();
    return;
  }
  highlightPath(i);
  showTooltip(i, event);
  canvas.classList.add('over-path');
}

// A click (press and release without dragging) on the mesh moves the source; shift+click adds a
// destination. Drags belong to the orbit controls.
let pressed = null;
canvas.addEventListener('pointerdown', (event) => {
  pressed = event.button === 0 ? { x: event.clientX, y: event.clientY } : null;
});
canvas.addEventListener('pointerup', (event) => {
  if (!pressed || event.button !== 0) return;
  const moved = Math.hypot(event.clientX - pressed.x, event.clientY - pressed.y);
  pressed = null;
  if (moved > 4) return;
  aimAt(event);
  const picked = pickSurface();
  if (!picked) return;
  if (event.shiftKey) {
    pathRequest.added.push({ point: picked.point, position: picked.hit.point.clone() });
  } else {
    pathRequest.source = picked.point;
  }
  tracePaths();
});

// ------------------------------------------------------------------ UI wiring

$('sample-select').addEventListener('change', (event) => {
  if (event.target.value) loadSample(event.target.value);
});

$('file-input').addEventListener('change', (event) => {
  const [file] = event.target.files;
  if (file) loadFile(file);
  event.target.value = ''; // choosing the same file again still fires 'change'
});

$('wireframe-toggle').addEventListener('change', (event) => {
  if (wireframe) wireframe.visible = event.target.checked;
  requestRender();
});

$('flat-toggle').addEventListener('change', (event) => {
  surfaceMaterial.flatShading = event.target.checked;
  surfaceMaterial.needsUpdate = true;
  requestRender();
});

$('boundary-toggle').addEventListener('change', () => tracePaths());

$('base-toggle').addEventListener('change', (event) => {
  if (shown) shown.basePlane.visible = event.target.checked;
  requestRender();
});

$('heat-toggle').addEventListener('change', (event) => {
  if (event.target.checked) {
    showHeat().catch((err) => {
      if (!isCancelled(err)) showError(err, 'Could not compute the heat distances');
    });
  } else {
    resetSurfaceColor();
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
  if (file) loadFile(file);
});

// ------------------------------------------------------------------ start

async function start() {
  setState('loading');
  try {
    const { samples } = await request('init', { moduleUrl: MODULE_URL });
    hooks.samples = samples;
    const select = $('sample-select');
    select.replaceChildren(...samples.map((name) => new Option(name, name)));
    select.value = samples.includes('mountain') ? 'mountain' : samples[0];
    select.disabled = false;
    await loadSample(select.value);
  } catch (err) {
    showError(err, 'Could not load the straightest module');
  }
}

start();
