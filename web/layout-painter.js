// The UV layout panel's canvas, drawn without a long task on the page's main thread: a dense
// layout's triangles (uv-layout.js's isDense) are filled in slices first (uv-raster.js), and the
// whole picture is drawn once they are in, so the canvas goes from the previous picture to the new
// one at once. A newer drawing supersedes one still filling. Exports draw at once (drawLayout).

import { drawLayout, isDense, layoutRaster } from './uv-layout.js';
import { nextTask } from './slices.js';
import { rasterImageInSlices } from './uv-raster.js';

/** canvas: the on-screen layout canvas; draw(layout, message) as drawLayout(canvas, layout, message). */
export function createLayoutPainter(canvas) {
  let filling = null; // the AbortController of the drawing whose triangles are being filled

  async function draw(layout, message) {
    filling?.abort();
    filling = null;
    if (!layout || !isDense(layout)) {
      drawLayout(canvas, layout, message);
      return;
    }
    const controller = new AbortController();
    filling = controller;
    const { frame, fill } = layoutRaster(canvas);
    try {
      const image = await rasterImageInSlices(layout, frame, fill, controller.signal);
      await nextTask(); // the drawing in a task of its own, not after the last slice's
      controller.signal.throwIfAborted();
      drawLayout(canvas, layout, message, { raster: { frame, image } });
    } catch (err) {
      if (!controller.signal.aborted) throw err;
    } finally {
      if (filling === controller) filling = null;
    }
  }

  return {
    draw,
    /** Whether a dense layout's triangles are still being filled (the canvas shows the previous picture). */
    get filling() {
      return filling !== null;
    },
  };
}
