// The packed atlas in 2D (no geometry: the worker's cornerUv and chartOfFace as they are): one colour
// per chart, on the page's canvas beside the view, as a PNG at the atlas's own resolution (a template to
// paint the texture on) and as SVG (one path per chart, in texels). The chart colours are the ones the
// 3D view paints the charts with (atlas-mode.js), so a chart reads the same in both.

import { FONT } from './uv-layout.js';

const GOLDEN = 0.6180339887498949; // hue steps of the golden ratio: neighbouring ids get far-apart hues

/** HSL (h, s, l in [0, 1]) → sRGB bytes. */
function hslBytes(h, s, l) {
  const a = s * Math.min(l, 1 - l);
  const f = (n) => {
    const k = (n + h * 12) % 12;
    return Math.round(255 * (l - a * Math.max(-1, Math.min(k - 3, 9 - k, 1))));
  };
  return [f(0), f(8), f(4)];
}

/**
 * Chart k's colour as sRGB bytes: hues by the golden ratio, three saturation/lightness levels so that
 * charts whose hues come close still differ.
 */
export function chartColor(k) {
  const level = k % 3;
  return hslBytes((k * GOLDEN) % 1, [0.62, 0.5, 0.72][level], [0.58, 0.68, 0.48][level]);
}

export const chartCss = (k) => `rgb(${chartColor(k).join(',')})`;

/** The faces of each chart (chartOfFace inverted): an array of face lists, chart by chart. */
export function facesByChart(chartOfFace, charts) {
  const lists = Array.from({ length: charts }, () => []);
  chartOfFace.forEach((chart, face) => {
    if (chart >= 0 && chart < charts) lists[chart].push(face);
  });
  return lists;
}

/**
 * One Path2D per chart in uv units ([0,1]², v up: y = 1 − v), made once per atlas and reused by every
 * redraw. Only ever filled, and a fill closes each triangle itself: no closePath(), which in Chromium
 * takes time in proportion to the path so far (a chart of many faces would cost their number squared).
 */
export function chartPaths({ cornerUv, chartOfFace, charts }) {
  return facesByChart(chartOfFace, charts).map((faces) => {
    const path = new Path2D();
    for (const f of faces) {
      path.moveTo(cornerUv[6 * f], 1 - cornerUv[6 * f + 1]);
      path.lineTo(cornerUv[6 * f + 2], 1 - cornerUv[6 * f + 3]);
      path.lineTo(cornerUv[6 * f + 4], 1 - cornerUv[6 * f + 5]);
    }
    return path;
  });
}

/** Fills each chart's path in its colour into a w × h box at (x, y) of `ctx` (in the context's units). */
function fillCharts(ctx, paths, x, y, w, h) {
  ctx.save();
  ctx.translate(x, y);
  ctx.scale(w, h);
  paths.forEach((path, k) => {
    ctx.fillStyle = chartCss(k);
    ctx.fill(path);
  });
  ctx.restore();
}

/**
 * Draws the atlas on the page's canvas, as large as fits its CSS box with the atlas's aspect ratio
 * (atlas: { paths, width, height }; null: the empty frame and `message`).
 */
export function drawAtlasLayout(canvas, atlas, message = '') {
  const cssWidth = canvas.clientWidth || 300;
  const cssHeight = canvas.clientHeight || cssWidth;
  const scale = Math.max(window.devicePixelRatio || 1, 1);
  const [w, h] = [Math.round(cssWidth * scale), Math.round(cssHeight * scale)];
  if (canvas.width !== w || canvas.height !== h) [canvas.width, canvas.height] = [w, h];
  const ctx = canvas.getContext('2d', { willReadFrequently: true }); // the tests read it back
  ctx.setTransform(scale, 0, 0, scale, 0, 0);
  ctx.clearRect(0, 0, cssWidth, cssHeight);
  const margin = 8;
  const aspect = atlas ? atlas.width / atlas.height : 1;
  const side = Math.max(10, Math.min(cssWidth - 2 * margin, (cssHeight - 2 * margin) * aspect));
  const [boxW, boxH] = [side, side / aspect];
  const x0 = (cssWidth - boxW) / 2;
  const y0 = margin;
  // The atlas's texels: the empty ones a shade lighter than the page, so the packing's gaps show.
  ctx.fillStyle = '#242a33';
  ctx.fillRect(x0, y0, boxW, boxH);
  ctx.strokeStyle = 'rgba(141, 150, 165, 0.45)';
  ctx.lineWidth = 1;
  ctx.strokeRect(x0 - 0.5, y0 - 0.5, boxW + 1, boxH + 1);
  if (atlas) {
    fillCharts(ctx, atlas.paths, x0, y0, boxW, boxH);
    return;
  }
  if (message) {
    ctx.fillStyle = '#8d96a5';
    ctx.font = `12.5px ${FONT}`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(message, x0 + boxW / 2, y0 + boxH / 2, boxW - 16);
  }
}

/**
 * The atlas as an image of its own size in texels (width × height, at most `maxSide` on its longer
 * side), charts filled on a transparent background: the template a texture is painted on.
 */
export function atlasCanvas(atlas, maxSide = 8192) {
  const shrink = Math.min(1, maxSide / Math.max(atlas.width, atlas.height));
  const canvas = document.createElement('canvas');
  canvas.width = Math.round(atlas.width * shrink);
  canvas.height = Math.round(atlas.height * shrink);
  fillCharts(canvas.getContext('2d'), atlas.paths, 0, 0, canvas.width, canvas.height);
  return canvas;
}

const num = (x) => (Math.round(x * 100) / 100).toString(); // texels to 1/100: exact enough, short

/**
 * The atlas as SVG in texel units (viewBox width × height, y down as in the image): one path per chart
 * with its colour and `data-chart` (its id), the title as the file's <title>.
 */
export function atlasSvg({ cornerUv, chartOfFace, charts, width, height }, title = '') {
  const escape = (text) =>
    String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
  const out = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}">`,
    `<title>${escape(title)}</title>`,
  ];
  facesByChart(chartOfFace, charts).forEach((faces, k) => {
    const d = faces
      .map((f) => {
        const corner = (c) =>
          `${num(cornerUv[6 * f + 2 * c] * width)} ${num((1 - cornerUv[6 * f + 2 * c + 1]) * height)}`;
        return `M${corner(0)}L${corner(1)}L${corner(2)}Z`;
      })
      .join('');
    out.push(`<path data-chart="${k}" fill="${chartCss(k)}" d="${d}"/>`);
  });
  out.push('</svg>');
  return `${out.join('\n')}\n`;
}
