// The page's session with the geometry worker (requests.js over straightest/worker): starting it,
// loading a mesh (a sample or a file), Cancel (the worker is replaced and the mesh on display rebuilt
// in the new one), and which reply is still wanted — every kind of request follows "latest request
// wins" (latest.js).
//
// The mesh on display is described here (label, info, where it came from); what is drawn for it is
// the display's business: load() hands the reply to display.showMesh() and then awaits
// display.showPaths(). Views that depend on the mesh listen to the session's events:
//   'meshchange'  a new mesh is on display (or none, after cancelling its reload)
//   'meshready'   its paths are drawn (time for the follow-up work, e.g. parameterizing)
//   'cancel'      Cancel stopped the worker: whatever it was computing will not come
// What it knows, as plain data, is its getters (info, samples, threads, cancels; main.js puts them in
// the page's observable state, docs/PAGE.md).

import { latest } from './latest.js';
import { clearError, setState, setStatus, showError, showThreads } from './panels.js';
import { createRequests, isCancelled } from './requests.js';

const $ = (id) => document.getElementById(id);

/**
 * observer: the progress view (told about every request); display: { showMesh(reply),
 * dropMesh(), showPaths(): Promise } of main.js.
 */
export function createSession({ observer, display }) {
  const events = new EventTarget();
  const emit = (type) => events.dispatchEvent(new Event(type));
  const requests = createRequests({ observer });

  const loads = latest(); // only the most recent load may update the view
  const reloads = latest(); // the reloads into a restarted worker
  const meshes = latest(); // advances with every mesh on display: replies for an older mesh are stale
  let restoring = false; // the mesh on display is being reloaded into a restarted worker
  let displayed = null; // where the mesh on display came from: { sample } or { file } (see reloadInto)
  let label = ''; // the sample or file name of the mesh on display
  let status = ''; // the status line of the mesh on display
  let boundaryKinds = []; // the worker's names of the parameterization's boundaries
  let info = null; // mesh.info() of the mesh on display
  let samples = []; // the sample names the worker offers
  let threads = 0; // the threads the worker's WebAssembly module runs on
  let cancels = 0; // completed cancellations (the worker restarted and has the mesh again)

  /**
   * Runs a request (requests.js); resolves with its reply, rejects with an Error (+ category;
   * 'cancelled' when Cancel stopped it). onProgress receives its progress ({ stage, fraction, … }).
   */
  function request(type, payload = {}, onProgress = null) {
    return requests.request(type, payload, onProgress);
  }

  /**
   * Loads a mesh with send(load) (load.stale() once a newer load or a cancel took over) and shows
   * it and its paths. origin: { sample } or { file }, kept to reload the mesh after a cancel.
   */
  async function load(what, send, origin) {
    const current = loads.begin();
    setState('loading');
    setStatus(`Loading ${what}…`);
    try {
      const reply = await send(current);
      if (current.stale()) {
        reply.mesh.delete().catch(() => {});
        return;
      }
      requests.adopt(reply.mesh, reply.info);
      label = reply.label;
      info = reply.info;
      meshes.supersede();
      display.showMesh(reply, origin);
      emit('meshchange');
      clearError({ forget: true });
      displayed = origin;
      status =
        `${reply.label}${reply.note ? ` (${reply.note})` : ''}: ${reply.info.vertices} vertices, ` +
        `${reply.info.faces} faces ` +
        `(${reply.timeMs.toFixed(0)} ms in the worker)`;
      setStatus(status);
      await display.showPaths(); // sets the state ('ready' once the paths are drawn)
      // Then the follow-up work, so it does not delay the first view of the mesh and its paths.
      if (!current.stale()) emit('meshready');
    } catch (err) {
      if (current.stale() || isCancelled(err)) return;
      $('sample-select').value = displayed?.sample ?? '';
      showError(err, `Could not load ${what}`);
    }
  }

  function loadSample(name) {
    return load(`sample “${name}”`, () => request('sample', { name }), { sample: name });
  }

  async function loadFile(file) {
    const select = $('sample-select');
    if (!select.querySelector('option[value=""]')) {
      select.prepend(new Option('(local file)', ''));
      select.options[0].disabled = true;
    }
    select.value = '';
    return load(`“${file.name}”`, () => request('file', { name: file.name, file }), { file });
  }

  /** Nothing on display (after cancelling the reload of the mesh into a restarted worker). */
  function dropMesh() {
    requests.drop();
    meshes.supersede();
    display.dropMesh();
    label = '';
    status = '';
    displayed = null;
    info = null;
    emit('meshchange');
  }

  /**
   * Cancel: the worker is busy inside a synchronous WASM call and cannot read a message, so it is
   * terminated and a new one builds the mesh on display again. Every pending request rejects as
   * 'cancelled', and every request begun before is stale from now on.
   */
  function cancel() {
    const wasRestoring = restoring;
    requests.cancel();
    loads.supersede(); // a load in flight stops (no paths, no follow-up work after it)
    emit('cancel');
    if (wasRestoring) dropMesh(); // cancelling the reload itself: nothing is left in the worker
    $('sample-select').value = displayed?.sample ?? '';
    reloadInto();
  }

  /** Builds the mesh on display again in the restarted worker (from what made it). */
  async function reloadInto() {
    const origin = displayed;
    const current = reloads.begin();
    restoring = true;
    setState('loading');
    setStatus('Cancelled — restarting the geometry worker…');
    try {
      if (origin) await requests.restore(origin.sample ? 'sample' : 'file', origin.sample ?? origin.file.name);
      if (origin !== displayed) return;
      cancels += 1;
      clearError();
      setStatus(origin ? `Cancelled. ${status}` : 'Cancelled: no mesh loaded — choose a sample or open a file.');
      setState('ready');
    } catch (err) {
      if (isCancelled(err) || origin !== displayed) return; // a newer cancel or load took over
      showError(err, 'Could not restart the geometry worker');
    } finally {
      if (!current.stale()) restoring = false;
    }
  }

  /**
   * Starts the worker, lists its samples and loads one: preferredSample(samples) if it names one (a
   * shared link's), else mountain.
   */
  async function start(preferredSample = () => null) {
    setState('loading');
    try {
      const ready = await requests.start();
      samples = ready.samples;
      boundaryKinds = ready.boundaryKinds;
      threads = ready.threads;
      showThreads(ready.threads);
      const select = $('sample-select');
      select.replaceChildren(...samples.map((name) => new Option(name, name)));
      select.value = preferredSample(samples) ?? (samples.includes('mountain') ? 'mountain' : samples[0]);
      select.disabled = false;
      await loadSample(select.value);
    } catch (err) {
      showError(err, 'Could not load the straightest module');
    }
  }

  return {
    request,
    start,
    loadSample,
    loadFile,
    cancel,
    addEventListener: events.addEventListener.bind(events),
    /** The channel of meshes on display: requests watch it (latest.js) to drop replies for an older mesh. */
    meshes,
    /** Where the mesh on display came from: { sample } or { file } (a File), or null. */
    get origin() {
      return displayed;
    },
    /** The sample or file name of the mesh on display ('' for none). */
    get label() {
      return label;
    },
    /** The status line of the mesh on display. */
    get status() {
      return status;
    },
    /** The boundary kinds of the parameterization ('auto' aside), in the core's order. */
    get boundaryKinds() {
      return boundaryKinds;
    },
    /** mesh.info() of the mesh on display, or null. */
    get info() {
      return info;
    },
    /** The sample names the worker offers ([] until it started). */
    get samples() {
      return samples;
    },
    /** The threads the worker's WebAssembly module runs on (1: the single-threaded module; 0 until it started). */
    get threads() {
      return threads;
    },
    /** How many cancellations completed (the worker restarted and has the mesh again). */
    get cancels() {
      return cancels;
    },
  };
}
