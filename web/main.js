// The page's main thread: renders with three.js and runs the UI. All geometry happens in the worker
// (worker.js), which owns the straightest WASM module; this file only turns its arrays into
// three.js buffers.
//
// Test hooks: document.body.dataset.state is 'loading' | 'ready' | 'error', and window.__straightest
// holds { state, samples, lastInfo, lastError, renders, background }.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const BACKGROUND = 0x14171c;
const MESH_COLOR = 0xd9b982;
const WIRE_COLOR = 0x1d2430;

const $ = (id) => document.getElementById(id);

const hooks = {
  state: 'loading',
  samples: [],
  lastInfo: null,
  lastError: null,
  renders: 0,
  background: [(BACKGROUND >> 16) & 255, (BACKGROUND >> 8) & 255, BACKGROUND & 255],
};
window.__straightest = hooks;

function setState(state) {
  hooks.state = state;
  document.body.dataset.state = state;
}

// ------------------------------------------------------------------ worker client

const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
const pending = new Map(); // request id -> { resolve, reject }
let nextId = 1;

/** Sends a request to the worker; resolves with its reply, rejects with an Error (+ category). */
function request(type, payload = {}, transfer = []) {
  const id = nextId++;
  return new Promise((resolve, reject) => {
    pending.set(id, { resolve, reject });
    worker.postMessage({ id, type, ...payload }, transfer);
  });
}

worker.addEventListener('message', ({ data }) => {
  const entry = pending.get(data.id);
  if (!entry) return;
  pending.delete(data.id);
  if (data.type === 'error') {
    const err = new Error(data.message);
    err.category = data.category;
    entry.reject(err);
  } else {
    entry.resolve(data);
  }
});

function failAllPending(message) {
  for (const { reject } of pending.values()) {
    const err = new Error(message);
    err.category = 'worker';
    reject(err);
  }
  pending.clear();
}
worker.addEventListener('error', (event) => {
  event.preventDefault();
  failAllPending(`the geometry worker failed to start: ${event.message || 'script error'}`);
});
worker.addEventListener('messageerror', () => failAllPending('a worker message could not be read'));

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
  polygonOffset: true, // keeps the wireframe overlay on top of the faces
  polygonOffsetFactor: 1,
  polygonOffsetUnits: 1,
});
const wireMaterial = new THREE.MeshBasicMaterial({
  color: WIRE_COLOR,
  wireframe: true,
  transparent: true,
  opacity: 0.55,
});

let surface = null; // THREE.Mesh of the current geometry
let wireframe = null; // overlay sharing the same geometry

let renderScheduled = false;
function render() {
  renderScheduled = false;
  renderer.render(scene, camera);
  hooks.renders += 1;
}
function requestRender() {
  if (renderScheduled) return;
  renderScheduled = true;
  requestAnimationFrame(render);
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
function showMesh(positions, indices) {
  if (surface) {
    scene.remove(surface, wireframe);
    surface.geometry.dispose();
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setIndex(new THREE.BufferAttribute(indices, 1));
  geometry.computeVertexNormals();
  geometry.computeBoundingSphere();
  surface = new THREE.Mesh(geometry, surfaceMaterial);
  wireframe = new THREE.Mesh(geometry, wireMaterial);
  wireframe.visible = $('wireframe-toggle').checked;
  scene.add(surface, wireframe);
}

/** Points the camera at the bounding box, from the front-right and above, so it fills the view. */
function frameBox(bbox) {
  const min = new THREE.Vector3(...bbox.min);
  const max = new THREE.Vector3(...bbox.max);
  const center = min.clone().add(max).multiplyScalar(0.5);
  const radius = Math.max(max.distanceTo(min) / 2, 1e-6);
  const halfFov = THREE.MathUtils.degToRad(camera.fov / 2);
  const fit = Math.min(halfFov, Math.atan(Math.tan(halfFov) * camera.aspect));
  const distance = (radius / Math.sin(fit)) * 0.95;
  const direction = new THREE.Vector3(0.55, -1.0, 0.75).normalize();
  camera.position.copy(center).addScaledVector(direction, distance);
  camera.near = distance / 100;
  camera.far = distance * 100;
  camera.updateProjectionMatrix();
  controls.target.copy(center);
  controls.update();
}

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

function showError(err, what) {
  hooks.lastError = { message: err.message, category: err.category ?? 'error' };
  $('error-title').textContent = `Could not load ${what}`;
  $('error-message').textContent = err.message;
  $('error-category').textContent = err.category ?? 'error';
  $('error-panel').hidden = false;
  $('status').textContent = 'Error — see above';
  setState('error');
}

function clearError() {
  $('error-panel').hidden = true;
}

// ------------------------------------------------------------------ loading

let latestLoad = 0; // only the most recent load may update the view
let shownSample = ''; // the sample on display ('' for a file), restored in the select after an error

async function load(what, send, sample = '') {
  const ticket = ++latestLoad;
  setState('loading');
  $('status').textContent = `Loading ${what}…`;
  try {
    const reply = await send();
    if (ticket !== latestLoad) return;
    showMesh(reply.positions, reply.indices);
    frameBox(reply.info.bbox);
    showInfo(reply.info, reply.label);
    clearError();
    hooks.lastInfo = reply.info;
    hooks.lastError = null;
    shownSample = sample;
    render();
    $('status').textContent =
      `${reply.label}: ${reply.info.vertices} vertices, ${reply.info.faces} faces ` +
      `(${reply.timeMs.toFixed(0)} ms in the worker)`;
    setState('ready');
  } catch (err) {
    if (ticket !== latestLoad) return;
    $('sample-select').value = shownSample;
    showError(err, what);
  }
}

function loadSample(name) {
  return load(`sample “${name}”`, () => request('sample', { name }), name);
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
  return load(`“${file.name}”`, async () => {
    const bytes = await file.arrayBuffer();
    return request('file', { name: file.name, format: formatFromName(file.name), bytes }, [bytes]);
  });
}

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
    const { samples } = await request('init', { moduleUrl: import.meta.resolve('straightest') });
    hooks.samples = samples;
    const select = $('sample-select');
    select.replaceChildren(...samples.map((name) => new Option(name, name)));
    select.value = samples.includes('mountain') ? 'mountain' : samples[0];
    select.disabled = false;
    await loadSample(select.value);
  } catch (err) {
    showError(err, 'the straightest module');
  }
}

start();
