// Drawing helpers of the parameterization view (no geometry): the checkerboard texture's canvas and
// the 2D UV-layout canvas. Everything drawn here comes from the worker's arrays as they are; the
// page computes no uv or stretch itself (the colour scales are colormap.js).

import * as THREE from 'three';
import { BOUNDARY_COLORS, STRETCH_INFINITE, stretchRgb } from './colormap.js';
import { drawRaster, rasterFrame, rasterImage, sameFrame } from './uv-raster.js';

/** The seam of a cut mesh, in the layout and on the surface (param-view.js). */
export const SEAM_COLOR = '#ff4fd8';

/** A texture set up to be seen on the mesh through its uv: sRGB, the renderer's anisotropy, no wrapping. */
export function surfaceTexture(texture, anisotropy) {
  texture.colorSpace = THREE.SRGBColorSpace;
  texture.anisotropy = anisotropy;
  texture.wrapS = texture.wrapT = THREE.ClampToEdgeWrapping;
  texture.needsUpdate = true;
  return texture;
}

/**
 * The checkerboard of the texture: `cells` × `cells` squares, light and dark, with a thin darker
 * line every 4 cells so the scale of the map reads at a glance.
 */
export function checkerboardCanvas(size = 1024, cells = 16) {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  const ctx = canvas.getContext('2d', { willReadFrequently: true }); // read back once, for WebGL
  const cell = size / cells;
  ctx.fillStyle = '#f3ead8';
  ctx.fillRect(0, 0, size, size);
  ctx.fillStyle = '#5b4a3c';
  for (let i = 0; i < cells; i++) {
    for (let j = 0; j < cells; j++) if ((i + j) % 2) ctx.fillRect(i * cell, j * cell, cell, cell);
  }
  ctx.strokeStyle = 'rgba(40, 28, 20, 0.55)';
  ctx.lineWidth = Math.max(2, size / 512);
  ctx.beginPath();
  for (let k = 0; k <= cells; k += 4) {
    const x = Math.min(Math.max(k * cell, 1), size - 1);
    ctx.moveTo(x, 0);
    ctx.lineTo(x, size);
    ctx.moveTo(0, x);
    ctx.lineTo(size, x);
  }
  ctx.stroke();
  return canvas;
}

// ------------------------------------------------------------------ the 2D layout

export const MARGIN = 12; // CSS pixels around the unit square
const LEGEND_HEIGHT = 58; // CSS pixels below it on screen: the boundary legend, a caption and a key
export const LINE_HEIGHT = 15; // CSS pixels per legend line of an export (wrapped, never cut)
// Above this many faces the triangles are filled pixel by pixel (uv-raster.js) instead of stroked
// one by one: at that density the edges would be a solid fill anyway, and stroking millions
// of sub-pixel triangles would block the page for seconds.
export const RASTER_FACES = 50_000;

/**
 * The layout's colours per background: 'dark' (the page), 'light' (print) and 'transparent' (the light
 * palette's ink on no background). rasterFill: the thin edge colour over the background, as the strokes
 * blend (the fill of a dense mesh).
 */
export const LAYOUT_THEMES = {
  dark: {
    background: '#101318',
    grid: 'rgba(141, 150, 165, 0.16)',
    frame: 'rgba(141, 150, 165, 0.45)',
    edges: 'rgba(214, 221, 232, 0.42)',
    heatEdges: 'rgba(16, 19, 24, 0.35)',
    halo: 'rgba(0, 0, 0, 0.55)',
    strong: '#e4e7ec',
    label: '#a3abb8',
    text: '#c3c9d3',
    muted: '#8d96a5',
    rasterFill: [99, 104, 111],
  },
  light: {
    background: '#ffffff',
    grid: 'rgba(60, 70, 85, 0.14)',
    frame: 'rgba(60, 70, 85, 0.5)',
    edges: 'rgba(30, 36, 46, 0.42)',
    heatEdges: 'rgba(16, 19, 24, 0.3)',
    halo: 'rgba(255, 255, 255, 0.8)',
    strong: '#11151b',
    label: '#3d4552',
    text: '#2a303a',
    muted: '#5b6472',
    rasterFill: [150, 155, 162],
  },
};
LAYOUT_THEMES.transparent = { ...LAYOUT_THEMES.light, background: null };

export const FONT = 'system-ui, sans-serif';
/** The key below an edge drawing: what the lines are (a dense mesh: what the grey fill is). */
export function layoutKey(faces) {
  return faces > RASTER_FACES
    ? `grey: ${faces.toLocaleString('en-US')} faces, filled (too many edges to draw)`
    : 'thin lines: mesh edges · dashed square: the uv frame [0,1]²';
}

/**
 * The canvas' CSS size and its device pixels per CSS pixel: its CSS size on screen (at least 2× for
 * a crisp picture), or an export's `size` ({ width, height, scale } in CSS pixels and device pixels
 * per CSS pixel).
 */
function canvasSize(canvas, size) {
  const width = size?.width ?? (canvas.clientWidth || 300);
  const height = size?.height ?? (canvas.clientHeight || Math.round(width + LEGEND_HEIGHT));
  const scale = size?.scale ?? Math.max(window.devicePixelRatio || 1, 2);
  return { width, height, scale };
}

/** The canvas' backing store for canvasSize(), and its context scaled to CSS pixels. */
function fitCanvas(canvas, size) {
  const { width, height, scale } = canvasSize(canvas, size);
  const [w, h] = [Math.round(width * scale), Math.round(height * scale)];
  if (canvas.width !== w || canvas.height !== h) [canvas.width, canvas.height] = [w, h];
  // A CPU-backed canvas: its thousands of thin strokes draw faster in software than through a
  // (possibly software-emulated) GPU, and the PNG export and the tests read it back.
  const ctx = canvas.getContext('2d', { willReadFrequently: true });
  ctx.setTransform(scale, 0, 0, scale, 0, 0);
  return { ctx, width, height, scale };
}

/**
 * The uv frame [0,1]² in CSS pixels (x0, y0, side), as large as fits with the aspect ratio kept. An
 * export's frame takes the whole width (its height was made to fit the legend).
 */
function frameSquare(width, height, exported) {
  const legend = exported ? height - width : LEGEND_HEIGHT;
  const side = Math.max(10, Math.min(width - 2 * MARGIN, height - legend - 2 * MARGIN));
  return { x0: (width - side) / 2, y0: MARGIN, side };
}

/** Whether `layout`'s triangles are filled pixel by pixel (uv-raster.js) rather than stroked. */
export function isDense(layout) {
  return layout.cornerUv.length / 6 > RASTER_FACES;
}

/**
 * Where drawLayout(canvas, …, options) puts a dense layout's image and the colour it fills the
 * triangles with: { frame (uv-raster.js's rasterFrame), fill }, to fill the image beforehand.
 */
export function layoutRaster(canvas, { size = null, theme = 'dark' } = {}) {
  const { width, height, scale } = canvasSize(canvas, size);
  const { x0, y0, side } = frameSquare(width, height, size !== null);
  return { frame: rasterFrame(scale, x0, y0, side), fill: themeOf(theme).rasterFill };
}

const themeOf = (theme) => LAYOUT_THEMES[theme] ?? LAYOUT_THEMES.dark;

/**
 * The legend's text lines at `width` (CSS pixels): the title and the caption, and the key (none with
 * the heat map, whose key is a colour ramp), each wrapped at word boundaries when `wrap` (exports)
 * or cut with an ellipsis (the small on-screen canvas).
 */
export function legendText(ctx, { title, caption, heat, faces }, width, wrap) {
  const lines = (text, font) => {
    if (!text) return [];
    ctx.font = font;
    return wrap ? wrapLines(ctx, text, width) : [fitText(ctx, text, width)];
  };
  return {
    title: lines(title, `600 12px ${FONT}`),
    caption: lines(caption, `11px ${FONT}`),
    key: heat ? [] : lines(layoutKey(faces), `11px ${FONT}`),
  };
}

/**
 * The CSS size of an export of `layout` `width` wide: the square frame and the legend below it with
 * every line wrapped (see drawLayout's `size`).
 */
export function layoutExportSize(layout, width) {
  const ctx = document.createElement('canvas').getContext('2d');
  const faces = layout.cornerUv.length / 6;
  const side = width - 2 * MARGIN;
  const text = legendText(ctx, { ...layout, faces }, side, true);
  const lines = text.title.length + text.caption.length + Math.max(text.key.length, layout.heat ? 1 : 0);
  return { width, height: Math.ceil(side + 2 * MARGIN + 10 + 16 + lines * LINE_HEIGHT + 4) };
}

/**
 * Draws a parameterization's layout:
 *   layout = { cornerUv, faceStretch, overlays: [{ boundary, polygon, error }], boundary,
 *              heat: boolean, caption: string, seam: boolean, title?: string }
 * — the triangles' uv edges thinly (filled with their stretch colour when `heat`), the polygons of
 * the other boundaries dashed, the chosen boundary's polygon bold, and a legend. cornerUv has u, v
 * per face corner (a cut mesh's seam vertices have one per side; NaN: a face left out). `seam`: the
 * mesh was cut open, so the chosen polygon (the disk's boundary) is the seam: drawn in the seam's
 * colour and named so. With `layout` null, draws the empty frame and `message`.
 * options: size (an export: { width, height, scale }, see layoutExportSize; its legend lines wrap
 * instead of being cut), theme (a LAYOUT_THEMES key) and raster ({ frame, image }: a dense layout's
 * triangles filled beforehand, uv-raster.js, for layoutRaster()'s frame; filled here when missing or
 * made for another frame).
 */
export function drawLayout(canvas, layout, message = '', { size = null, theme = 'dark', raster = null } = {}) {
  const colors = themeOf(theme);
  const { ctx, width, height, scale } = fitCanvas(canvas, size);
  ctx.clearRect(0, 0, width, height);
  if (colors.background) {
    ctx.fillStyle = colors.background;
    ctx.fillRect(0, 0, width, height);
  }

  // The uv frame [0,1]² (frameSquare); v points up.
  const { x0, y0, side } = frameSquare(width, height, size !== null);
  const px = (u) => x0 + u * side;
  const py = (v) => y0 + (1 - v) * side;

  ctx.strokeStyle = colors.grid;
  ctx.lineWidth = 1;
  ctx.beginPath();
  for (let k = 1; k < 4; k++) {
    ctx.moveTo(px(k / 4), py(0));
    ctx.lineTo(px(k / 4), py(1));
    ctx.moveTo(px(0), py(k / 4));
    ctx.lineTo(px(1), py(k / 4));
  }
  ctx.stroke();
  ctx.strokeStyle = colors.frame;
  ctx.setLineDash([3, 3]);
  ctx.strokeRect(px(0), py(1), side, side);
  ctx.setLineDash([]);

  if (!layout) {
    if (message) {
      ctx.fillStyle = colors.muted;
      ctx.font = `12.5px ${FONT}`;
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      wrapText(ctx, message, width / 2, y0 + side / 2, side - 24, 17);
    }
    return;
  }

  const { cornerUv, overlays, boundary, seam } = layout;
  const faces = cornerUv.length / 6;
  if (isDense(layout)) {
    const frame = rasterFrame(scale, x0, y0, side);
    const filled =
      raster && sameFrame(raster.frame, frame) ? raster.image : rasterImage(layout, frame, colors.rasterFill);
    drawRaster(ctx, filled, frame);
  } else {
    drawTriangles(ctx, layout, px, py, colors);
  }

  // The boundary polygons: the others dashed and thin, the chosen one bold on top.
  const polygonPath = (polygon) => {
    ctx.beginPath();
    for (let i = 0; i < polygon.length; i += 2) ctx[i ? 'lineTo' : 'moveTo'](px(polygon[i]), py(polygon[i + 1]));
    ctx.closePath();
  };
  ctx.lineJoin = 'round';
  for (const { boundary: kind, polygon } of overlays) {
    if (!polygon || kind === boundary) continue;
    ctx.strokeStyle = BOUNDARY_COLORS[kind];
    ctx.lineWidth = 1.4;
    ctx.setLineDash([5, 3]);
    polygonPath(polygon);
    ctx.stroke();
  }
  ctx.setLineDash([]);
  const chosen = overlays.find((o) => o.boundary === boundary && o.polygon);
  if (chosen) {
    ctx.strokeStyle = colors.halo; // a halo keeps the bold line readable on any fill
    ctx.lineWidth = 5;
    polygonPath(chosen.polygon);
    ctx.stroke();
    ctx.strokeStyle = seam ? SEAM_COLOR : BOUNDARY_COLORS[boundary];
    ctx.lineWidth = 3;
    ctx.stroke();
  }

  const text = legendText(ctx, { ...layout, faces }, side, size !== null);
  drawLegend(ctx, { ...layout, text, colors }, x0, y0 + side + 10);
}

/** The triangles as canvas paths: filled with their stretch colour when `heat`, then their edges. */
function drawTriangles(ctx, { cornerUv, faceStretch, heat }, px, py, colors) {
  const faces = cornerUv.length / 6;
  const u = (f, k) => cornerUv[6 * f + 2 * k];
  const v = (f, k) => cornerUv[6 * f + 2 * k + 1];
  if (heat) {
    // One fill per face in its stretch colour, stroked with the same colour so no seams show.
    ctx.lineWidth = 0.6;
    for (let f = 0; f < faces; f++) {
      const color = `rgb(${stretchRgb(faceStretch[f]).join(',')})`;
      ctx.fillStyle = ctx.strokeStyle = color;
      ctx.beginPath();
      for (let k = 0; k < 3; k++) ctx[k ? 'lineTo' : 'moveTo'](px(u(f, k)), py(v(f, k)));
      ctx.closePath();
      ctx.fill();
      ctx.stroke();
    }
  }

  // The mesh edges in uv: one path, so shared edges are not drawn twice as dark. Each triangle ends
  // with a line back to its first corner, not closePath(): in Chromium each closePath() takes time in
  // proportion to the path so far, so one path of many triangles would cost their number squared (a
  // long task on the page's main thread from a few thousand faces on).
  ctx.strokeStyle = heat ? colors.heatEdges : colors.edges;
  ctx.lineWidth = 0.5;
  ctx.beginPath();
  for (let f = 0; f < faces; f++) {
    if (!Number.isFinite(u(f, 0))) continue; // a face left out of the parameterization
    for (let k = 0; k <= 3; k++) ctx[k ? 'lineTo' : 'moveTo'](px(u(f, k % 3)), py(v(f, k % 3)));
  }
  ctx.stroke();
}

/**
 * A dense layout's triangles alone, filled into a transparent canvas of side × side CSS pixels at
 * `scale` (the SVG export embeds it: a million triangles would make an unreadable file).
 */
export function rasterLayer(layout, side, scale, theme = 'dark') {
  const canvas = document.createElement('canvas');
  const { ctx } = fitCanvas(canvas, { width: side, height: side, scale });
  const frame = rasterFrame(scale, 0, 0, side);
  drawRaster(ctx, rasterImage(layout, frame, themeOf(theme).rasterFill), frame);
  return canvas;
}

/**
 * Below the frame: a swatch per boundary polygon (the chosen one bold), the title and caption lines,
 * and the key of the fill (the stretch scale) or of the lines (text: legendText's lines).
 */
function drawLegend(ctx, { overlays, boundary, heat, seam, text, colors }, x, y) {
  ctx.textBaseline = 'middle';
  ctx.textAlign = 'left';
  let cx = x;
  for (const { boundary: kind, polygon } of overlays) {
    const isChosen = kind === boundary;
    ctx.strokeStyle = isChosen && seam ? SEAM_COLOR : BOUNDARY_COLORS[kind];
    ctx.globalAlpha = polygon ? 1 : 0.4;
    ctx.lineWidth = isChosen ? 3 : 1.4;
    ctx.setLineDash(isChosen ? [] : [5, 3]);
    ctx.beginPath();
    ctx.moveTo(cx, y + 6);
    ctx.lineTo(cx + 18, y + 6);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.font = `${isChosen ? 600 : 400} 11.5px ${FONT}`;
    ctx.fillStyle = isChosen ? colors.strong : colors.label;
    const label = polygon ? `${kind}${isChosen && seam ? ' = seam' : ''}` : `${kind} (failed)`;
    ctx.fillText(label, cx + 23, y + 6);
    ctx.globalAlpha = 1;
    cx += 23 + ctx.measureText(label).width + 14;
  }

  let lineY = y + 22;
  const lines = (list, font, color) => {
    ctx.font = font;
    ctx.fillStyle = color;
    for (const line of list) {
      ctx.fillText(line, x, lineY);
      lineY += LINE_HEIGHT;
    }
  };
  lines(text.title, `600 12px ${FONT}`, colors.strong);
  lines(text.caption, `11px ${FONT}`, colors.text);
  if (!heat) {
    lines(text.key, `11px ${FONT}`, colors.muted);
    return;
  }
  // The stretch scale: "L2 stretch: 1 [ramp] ≥ 2 ■ flipped".
  const keyY = lineY;
  let kx = x;
  const word = (t) => {
    ctx.fillStyle = colors.muted;
    ctx.fillText(t, kx, keyY);
    kx += ctx.measureText(t).width + 5;
  };
  word('L2 stretch:');
  word('1');
  const rampWidth = 60;
  const ramp = ctx.createLinearGradient(kx, 0, kx + rampWidth, 0);
  for (let i = 0; i <= 8; i++) ramp.addColorStop(i / 8, `rgb(${stretchRgb(1 + i / 8).join(',')})`);
  ctx.fillStyle = ramp;
  ctx.fillRect(kx, keyY - 4, rampWidth, 8);
  kx += rampWidth + 5;
  word('≥ 2');
  ctx.fillStyle = `rgb(${STRETCH_INFINITE.join(',')})`;
  ctx.fillRect(kx + 3, keyY - 4, 8, 8);
  kx += 16;
  word('flipped');
}

/** `text` shortened with an ellipsis to fit `width`. */
function fitText(ctx, text, width) {
  if (ctx.measureText(text).width <= width) return text;
  let end = text.length;
  while (end > 0 && ctx.measureText(`${text.slice(0, end)}…`).width > width) end--;
  return `${text.slice(0, end)}…`;
}

/** `text` broken at word boundaries into lines no wider than `width` (a longer word stays whole). */
export function wrapLines(ctx, text, width) {
  const lines = [];
  let line = '';
  for (const word of text.split(/\s+/)) {
    const next = line ? `${line} ${word}` : word;
    if (line && ctx.measureText(next).width > width) {
      lines.push(line);
      line = word;
    } else {
      line = next;
    }
  }
  if (line) lines.push(line);
  return lines;
}

/** Centered text wrapped at word boundaries to `width`, lines `lineHeight` apart around y. */
function wrapText(ctx, text, x, y, width, lineHeight) {
  const lines = wrapLines(ctx, text, width);
  const top = y - ((lines.length - 1) * lineHeight) / 2;
  lines.forEach((l, i) => ctx.fillText(l, x, top + i * lineHeight));
}
