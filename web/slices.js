// Work too long for one task on the page's main thread, cut into slices: after each slice that
// used up its time budget the loop yields, so the browser can draw frames and answer input before the
// next one (issue 31: a task long enough to be felt freezes the page). Only the page's own loops
// over a large mesh's arrays are cut; the geometry itself runs in the worker.

// A slice's time budget: well under what is felt as a freeze, long enough that the yields cost little.
const SLICE_MS = 12;

/**
 * Resolves in a later task. scheduler.yield() where the browser has it: the rest of the work comes
 * before tasks queued meanwhile, so it is not delayed by them. Else a message posted to itself (a
 * chain of setTimeout(0) is clamped to several milliseconds per step).
 */
export function nextTask() {
  if (globalThis.scheduler?.yield) return globalThis.scheduler.yield();
  return new Promise((resolve) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = () => {
      channel.port1.close();
      resolve();
    };
    channel.port2.postMessage(null);
  });
}

/**
 * Calls work(from, to) over [0, count) in chunks of `chunk` items, awaiting pause() (nextTask by
 * default) whenever the current slice has taken its budget. A pause() that rejects stops the loop
 * with its error (a cancelled request).
 */
export async function inSlices(count, work, { chunk = 1 << 14, pause = nextTask } = {}) {
  let sliceStart = performance.now();
  for (let from = 0; from < count; from += chunk) {
    const to = Math.min(count, from + chunk);
    work(from, to);
    if (to < count && performance.now() - sliceStart > SLICE_MS) {
      await pause();
      sliceStart = performance.now();
    }
  }
}
