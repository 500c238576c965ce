// A dense uv layout's triangles (more than uv-layout.js's RASTER_FACES) filled pixel by pixel into an
// image of their own, transparent elsewhere, then drawn over the layout's frame: the filled pixels
// replace the frame's, the others leave it as drawn. Filling a million-vertex mesh's triangles takes
// longer than a task on the page's main thread should, so the image can be filled in slices
// (slices.js) before the layout is drawn with it (layout-painter.js); exports fill it at once.

import { stretchIndex, stretchTable } from './colormap.js';
import { inSlices, nextTask } from './slices.js';

/**
 * Where the frame [0,1]² (x0, y0, side in CSS pixels, `scale` device pixels per CSS pixel) lies in
 * device pixels: the image's square (left, top, size) and the map from uv into it (pixel centers at
 * integer + 0.5).
 */
export function rasterFrame(scale, x0, y0, side) {
  const left = Math.floor(x0 * scale);
  const top = Math.floor(y0 * scale);
  return {
    left,
    top,
    size: Math.ceil(side * scale) + 1,
    sx: side * scale,
    ox: x0 * scale - left,
    oy: y0 * scale - top,
  };
}

/** Whether two rasterFrame()s are the same square with the same map (an image made for one fits the other). */
export function sameFrame(a, b) {
  return ['left', 'top', 'size', 'sx', 'ox', 'oy'].every((key) => a[key] === b[key]);
}

/**
 * Fills faces [from, to) of `layout` (cornerUv, faceStretch, heat) into `image`: in their stretch
 * colour when `heat`, else in `fill` ([r, g, b]). A pixel belongs to the triangles that contain its
 * center, so a tiling leaves no holes however small its triangles are.
 */
function fillFaces(image, { cornerUv: uv, faceStretch, heat }, frame, fill, from, to) {
  const { data, width, height } = image;
  const { sx, ox, oy } = frame;
  const lut = heat ? stretchTable('srgb') : null;
  for (let f = from; f < to; f++) {
    const a = 3 * f; // corners: uv per face corner
    const b = 3 * f + 1;
    const c = 3 * f + 2;
    const ax = ox + uv[2 * a] * sx;
    const ay = oy + (1 - uv[2 * a + 1]) * sx;
    const bx = ox + uv[2 * b] * sx;
    const by = oy + (1 - uv[2 * b + 1]) * sx;
    const cx = ox + uv[2 * c] * sx;
    const cy = oy + (1 - uv[2 * c + 1]) * sx;
    const area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (!(Math.abs(area) > 0)) continue; // degenerate in uv, or NaN (a face left out)
    const sign = area > 0 ? 1 : -1;
    const eps = -1e-7 * Math.abs(area);
    const x1 = Math.max(0, Math.floor(Math.min(ax, bx, cx)));
    const x2 = Math.min(width - 1, Math.ceil(Math.max(ax, bx, cx)));
    const y1 = Math.max(0, Math.floor(Math.min(ay, by, cy)));
    const y2 = Math.min(height - 1, Math.ceil(Math.max(ay, by, cy)));
    let [r, g, bl] = fill;
    if (lut) {
      const k = 3 * stretchIndex(faceStretch[f]);
      [r, g, bl] = [lut[k], lut[k + 1], lut[k + 2]];
    }
    for (let y = y1; y <= y2; y++) {
      const py = y + 0.5;
      for (let x = x1; x <= x2; x++) {
        const px = x + 0.5;
        // Edge functions, all ≥ 0 inside (for either orientation, by `sign`).
        if (sign * ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) < eps) continue;
        if (sign * ((cx - bx) * (py - by) - (cy - by) * (px - bx)) < eps) continue;
        if (sign * ((ax - cx) * (py - cy) - (ay - cy) * (px - cx)) < eps) continue;
        const p = 4 * (y * width + x);
        data[p] = r;
        data[p + 1] = g;
        data[p + 2] = bl;
        data[p + 3] = 255;
      }
    }
  }
}

/** The image of `layout`'s triangles in `frame` (see fillFaces), filled at once. */
export function rasterImage(layout, frame, fill) {
  const image = new ImageData(frame.size, frame.size);
  fillFaces(image, layout, frame, fill, 0, layout.cornerUv.length / 6);
  return image;
}

/**
 * The same image filled in slices, a task each (slices.js); rejects with the signal's reason once
 * `signal` aborts (a newer drawing took over).
 */
export async function rasterImageInSlices(layout, frame, fill, signal) {
  const image = new ImageData(frame.size, frame.size);
  const fillRange = (from, to) => fillFaces(image, layout, frame, fill, from, to);
  const pause = async () => {
    await nextTask();
    signal.throwIfAborted();
  };
  signal.throwIfAborted();
  await inSlices(layout.cornerUv.length / 6, fillRange, { chunk: 1 << 10, pause });
  return image;
}

/** Draws `image` (made for `frame`) over the canvas of `ctx`, in device pixels. */
export function drawRaster(ctx, image, frame) {
  const scratch = document.createElement('canvas');
  scratch.width = scratch.height = frame.size;
  // CPU-backed, as the layout canvas is: drawing a GPU-backed canvas into it would move it to the GPU,
  // whose antialiasing of the lines and text drawn afterwards differs from the CPU's.
  scratch.getContext('2d', { willReadFrequently: true }).putImageData(image, 0, 0);
  ctx.save();
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.drawImage(scratch, frame.left, frame.top);
  ctx.restore();
}
