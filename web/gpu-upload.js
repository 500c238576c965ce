// Geometry reaches the GPU in slices, a few per animation frame, instead of in the single bufferData
// call three.js makes on the first frame that draws it. A browser hands buffer data to its GPU process
// through a bounded transfer buffer, so that one call keeps the main thread until the whole copy is
// through — for a 1M-vertex mesh (~50 MB of positions, normals and indices) a long freeze, longer
// still when the copy queues behind frames the GPU has not finished.
//
// upload(geometry) makes a twin of a BufferGeometry whose attributes are GLBufferAttributes over
// buffers this module fills: the twin can be drawn once `ready` (a small geometry is ready at once;
// a large one after some frames). Each frame's slices wait until the GPU has finished the frames
// queued before them (a fence), so they never queue behind a slow frame. The source geometry keeps
// its arrays (picking, exports, colours read them); only the twin is drawn.

import * as THREE from 'three';

const SLICE_BYTES = 1 << 20; // one bufferSubData call
const FRAME_BUDGET_MS = 8; // the slices of one frame stop once this much time went into them
const AT_ONCE_BYTES = 2 << 20; // a geometry up to this size is uploaded within upload()

/** The GL type and element size of a typed array (as three.js's WebGLAttributes chooses them). */
function glTypeOf(gl, array) {
  if (array instanceof Float32Array) return [gl.FLOAT, 4];
  if (array instanceof Uint32Array) return [gl.UNSIGNED_INT, 4];
  if (array instanceof Int32Array) return [gl.INT, 4];
  if (array instanceof Uint16Array) return [gl.UNSIGNED_SHORT, 2];
  if (array instanceof Int16Array) return [gl.SHORT, 2];
  if (array instanceof Int8Array) return [gl.BYTE, 1];
  if (array instanceof Uint8Array || array instanceof Uint8ClampedArray) return [gl.UNSIGNED_BYTE, 1];
  throw new Error(`cannot upload a ${array?.constructor?.name ?? typeof array}`);
}

/** renderer: the THREE.WebGLRenderer whose context the buffers belong to. */
export function createGpuUpload(renderer) {
  const gl = renderer.getContext();
  const queue = []; // { job, buffer, target, array, offset } still to send, in order
  let pumping = false;
  let fence = null; // after the last frame's slices: the next slices wait until the GPU passed it

  /** Sends one slice of the first queued buffer; returns the bytes sent. */
  function sendSlice() {
    const item = queue[0];
    const { array, target } = item;
    const count = Math.min(Math.floor(SLICE_BYTES / array.BYTES_PER_ELEMENT), array.length - item.offset);
    gl.bindBuffer(target, item.buffer);
    gl.bufferSubData(target, item.offset * array.BYTES_PER_ELEMENT, array, item.offset, count);
    item.offset += count;
    if (item.offset === array.length) {
      queue.shift();
      item.job.pending -= 1;
      if (item.job.pending === 0) item.job.finish();
    }
    return count * array.BYTES_PER_ELEMENT;
  }

  /** Sends slices until `budget` bytes or FRAME_BUDGET_MS went by (at least one slice). */
  function sendSlices(budget = Infinity) {
    const start = performance.now();
    gl.bindVertexArray(null); // an element buffer bound now would otherwise join three.js's bound VAO
    let sent = 0;
    while (queue.length && sent < budget) {
      sent += sendSlice();
      if (performance.now() - start > FRAME_BUDGET_MS) break;
    }
    renderer.resetState(); // three.js's cache of the bound buffers and VAO no longer holds
  }

  function gpuPassedFence() {
    if (!fence) return true;
    if (gl.isContextLost() || gl.getSyncParameter(fence, gl.SYNC_STATUS) === gl.SIGNALED) {
      gl.deleteSync(fence);
      fence = null;
      return true;
    }
    return false;
  }

  function pump() {
    if (!queue.length) {
      pumping = false;
      return;
    }
    if (gpuPassedFence()) {
      sendSlices();
      fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
    }
    requestAnimationFrame(pump);
  }

  /** Creates a buffer of `array`'s size (no data yet) and queues its slices for `job`. */
  function allocate(job, array, target) {
    const buffer = gl.createBuffer();
    gl.bindVertexArray(null);
    gl.bindBuffer(target, buffer);
    gl.bufferData(target, array.byteLength, gl.STATIC_DRAW);
    job.buffers.push(buffer);
    job.pending += 1;
    queue.push({ job, buffer, target, array, offset: 0 });
    return buffer;
  }

  function glAttribute(job, source, target) {
    const { array } = source;
    const [type, size] = glTypeOf(gl, array);
    const buffer = allocate(job, array, target);
    return new THREE.GLBufferAttribute(buffer, type, source.itemSize, size, source.count, source.normalized);
  }

  /**
   * Allocates and queues the buffers `fill(job)` creates: { job, ready, done (a Promise of true once
   * every buffer is filled, false if dropped first), dispose() }. Sent at once when nothing else waits
   * and they are small.
   */
  function uploadJob(fill) {
    let settle;
    const done = new Promise((resolve) => {
      settle = resolve;
    });
    const job = { buffers: [], pending: 0, finish: null, disposed: false };
    const handle = {
      ready: false,
      done,
      dispose() {
        if (job.disposed) return;
        job.disposed = true;
        for (let i = queue.length - 1; i >= 0; i--) if (queue[i].job === job) queue.splice(i, 1);
        for (const buffer of job.buffers) gl.deleteBuffer(buffer); // (deleting a deleted buffer does nothing)
        settle(handle.ready);
      },
    };
    job.finish = () => {
      handle.ready = true;
      settle(true);
    };
    const waiting = queue.length;
    fill(job);
    renderer.resetState();
    if (job.pending === 0) job.finish();
    const bytes = queue.slice(waiting).reduce((total, item) => total + item.array.byteLength, 0);
    if (waiting === 0 && bytes <= AT_ONCE_BYTES) sendSlices(); // drawn in the frame that asked for it
    if (queue.length && !pumping) {
      pumping = true;
      requestAnimationFrame(pump);
    }
    return handle;
  }

  return {
    /**
     * The twin of `geometry` (a BufferGeometry of BufferAttributes) with the attributes `names` (all
     * by default), its index and its groups, drawable once uploaded: { geometry, ready, done, dispose() } (see
     * uploadJob; dispose() also frees what three.js made for the twin). Its bounding sphere is the
     * source's (computed from the arrays if it has none: a GLBufferAttribute cannot give one).
     */
    upload(geometry, names = Object.keys(geometry.attributes)) {
      const twin = new THREE.BufferGeometry();
      if (!geometry.boundingSphere) geometry.computeBoundingSphere();
      twin.boundingSphere = geometry.boundingSphere.clone();
      for (const { start, count, materialIndex } of geometry.groups) twin.addGroup(start, count, materialIndex);
      const handle = uploadJob((job) => {
        for (const name of names) {
          twin.setAttribute(name, glAttribute(job, geometry.getAttribute(name), gl.ARRAY_BUFFER));
        }
        if (geometry.index) twin.setIndex(glAttribute(job, geometry.index, gl.ELEMENT_ARRAY_BUFFER));
      });
      const dropBuffers = handle.dispose;
      handle.geometry = twin;
      handle.dispose = () => {
        dropBuffers();
        twin.dispose(); // three.js forgets the buffers it drew from
      };
      return handle;
    },

    /**
     * One attribute (a BufferAttribute) on its own: { attribute (the GLBufferAttribute to put on a
     * twin once ready), ready, done, dispose() }.
     */
    uploadAttribute(source) {
      let attribute = null;
      const handle = uploadJob((job) => {
        attribute = glAttribute(job, source, gl.ARRAY_BUFFER);
      });
      handle.attribute = attribute;
      return handle;
    },
  };
}
