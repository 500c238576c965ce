// Images out of the page: rendering a three.js scene at a chosen resolution and background into a 2D
// canvas (one offscreen WebGLRenderer, made on first use, so the view on screen never changes size or
// colour for an export), and saving blobs as downloads. The figure view and the export panel use it.

import * as THREE from 'three';

/** The 3D background of each export choice (null: transparent). */
export const BACKGROUNDS = { dark: 0x14171c, light: 0xffffff, transparent: null };

let offscreen = null; // the export renderer: alpha for transparent backgrounds, its pixels kept for reading

function exportRenderer() {
  offscreen ??= new THREE.WebGLRenderer({ antialias: true, alpha: true, preserveDrawingBuffer: true });
  return offscreen;
}

/** The largest image side the export renderer can draw (the GPU's renderbuffer and viewport limits). */
export function maxImageSide() {
  const gl = exportRenderer().getContext();
  const [viewportWidth, viewportHeight] = gl.getParameter(gl.MAX_VIEWPORT_DIMS);
  return Math.min(gl.getParameter(gl.MAX_RENDERBUFFER_SIZE), viewportWidth, viewportHeight);
}

/**
 * The largest scale ≤ `scale` at which an image of width × height CSS pixels fits the GPU's limits
 * (a 4× export of a wide view may not).
 */
export function fittingScale(width, height, scale) {
  return Math.min(scale, maxImageSide() / Math.max(width, height, 1));
}

/**
 * Renders `scene` from `camera` into a new canvas of width × height CSS pixels at `scale` device
 * pixels each, on `background` (a BACKGROUNDS value). Fat lines (LineMaterial) keep their width in
 * CSS pixels, so a 2× image looks like the screen, twice as sharp.
 */
export function renderToCanvas(scene, camera, { width, height, scale = 1, background = BACKGROUNDS.dark }) {
  const renderer = exportRenderer();
  renderer.setPixelRatio(scale);
  renderer.setSize(width, height, false);
  renderer.setClearColor(background ?? 0x000000, background === null ? 0 : 1);
  renderer.render(scene, camera);
  const out = document.createElement('canvas');
  out.width = renderer.domElement.width;
  out.height = renderer.domElement.height;
  out.getContext('2d').drawImage(renderer.domElement, 0, 0);
  return out;
}

/** The canvas as a PNG blob. */
export function pngBlob(canvas) {
  return new Promise((resolve, reject) => {
    canvas.toBlob(
      (blob) => (blob ? resolve(blob) : reject(new Error('the browser could not encode the PNG'))),
      'image/png',
    );
  });
}

/** Saves `blob` under `name` through a temporary download link. */
export function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 30_000);
}
