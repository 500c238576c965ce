// The page's client of the geometry worker (worker.js, which documents the protocol): numbered
// requests, their replies and 'progress' messages routed back to them, and restart() — the only way
// to stop work that runs inside a synchronous WASM call: terminate the worker, reject its pending
// requests as 'cancelled' and start a new one (which must be sent 'init' again).
//
// Every worker instance has its own listeners and its own map of pending requests, so nothing an
// old worker still had queued can reach the page after a restart.

/** An Error with the worker's (or the core's) machine-readable category. */
export function workerError(message, category) {
  const err = new Error(message);
  err.category = category;
  return err;
}

export function isCancelled(err) {
  return err?.category === 'cancelled';
}

/**
 * url: the worker script; observer (optional): begin(type, payload) → { update(progressMessage),
 * end() } or null, told about every request (the progress panel).
 */
export function createWorkerClient({ url, observer = null }) {
  let current = null; // { worker, pending: Map(id -> { resolve, reject, onProgress, task }) }
  let nextId = 1;

  function settle(entry) {
    entry.task?.end();
  }

  /** Rejects every pending request of `instance` (it will never answer them). */
  function failAll(instance, message, category) {
    for (const entry of instance.pending.values()) {
      settle(entry);
      entry.reject(workerError(message, category));
    }
    instance.pending.clear();
  }

  function start() {
    const worker = new Worker(url, { type: 'module' });
    const instance = { worker, pending: new Map() };
    worker.addEventListener('message', ({ data }) => {
      if (instance !== current) return; // a terminated worker's last words
      const entry = instance.pending.get(data.id);
      if (!entry) return;
      if (data.type === 'progress') {
        entry.task?.update(data);
        entry.onProgress?.(data);
        return;
      }
      instance.pending.delete(data.id);
      settle(entry);
      if (data.type === 'error') entry.reject(workerError(data.message, data.category));
      else entry.resolve(data);
    });
    worker.addEventListener('error', (event) => {
      event.preventDefault();
      if (instance !== current) return;
      failAll(instance, `the geometry worker failed: ${event.message || 'script error'}`, 'worker');
    });
    worker.addEventListener('messageerror', () => {
      if (instance === current) failAll(instance, 'a worker message could not be read', 'worker');
    });
    current = instance;
  }

  start();

  return {
    /**
     * Sends a request to the worker; resolves with its reply, rejects with an Error (+ category).
     * onProgress receives the 'progress' messages the worker sends before the reply.
     */
    request(type, payload = {}, transfer = [], onProgress = null) {
      const instance = current;
      const id = nextId++;
      return new Promise((resolve, reject) => {
        const task = observer?.begin(type, payload) ?? null;
        instance.pending.set(id, { resolve, reject, onProgress, task });
        instance.worker.postMessage({ id, type, ...payload }, transfer);
      });
    },

    /** Stops whatever the worker is doing: its pending requests reject with category 'cancelled'. */
    restart() {
      const old = current;
      old.worker.terminate();
      start(); // `current` moves on first: the rejections below see the new worker
      failAll(old, 'cancelled', 'cancelled');
    },

    /** Number of requests waiting for a reply. */
    get pending() {
      return current.pending.size;
    },
  };
}
