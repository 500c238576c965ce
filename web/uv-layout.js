// Drawing helpers of the parameterization view (no three.js, no geometry): the colour scale of the
// per-face stretch, the checkerboard texture's canvas and the 2D UV-layout canvas. Everything drawn
// here comes from the worker's arrays as they are; the page computes no uv or stretch itself.

/** Colours of the boundary polygons in the layout (and its legend), per boundary. */
export const BOUNDARY_COLORS = {
  measured: '#f0b429', // the paper's boundary: the accent gold
  circle: '#4ea8ff',
  square: '#5fd08a',
};

export const LAYOUT_BACKGROUND = '#101318';

// Per-face L2 stretch, 1 (an isometry: good) … ≥ 2 (bad): green → yellow → red (ColorBrewer RdYlGn,
// reversed); flipped or degenerate faces (infinite stretch) are magenta.
const STRETCH_STOPS = [[26, 152, 80], [145, 207, 96], [254, 224, 139], [252, 141, 89], [215, 48, 39]];
export const STRETCH_INFINITE = [255, 0, 255];
export const STRETCH_MIN = 1;
export const STRETCH_MAX = 2;

/** The stretch colour as [r, g, b] in 0…255. */
export function stretchRgb(stretch) {
  if (!Number.isFinite(stretch)) return STRETCH_INFINITE;
  const t = Math.min(Math.max((stretch - STRETCH_MIN) / (STRETCH_MAX - STRETCH_MIN), 0), 1);
  const x = t * (STRETCH_STOPS.length - 1);
  const k = Math.min(Math.floor(x), STRETCH_STOPS.length - 2);
  const f = x - k;
  return STRETCH_STOPS[k].map((c, i) => Math.round(c + f * (STRETCH_STOPS[k + 1][i] - c)));
}

/** A CSS linear-gradient of the stretch scale (legends). */
export function stretchGradient() {
  const stops = STRETCH_STOPS.map((c, i) => `rgb(${c.join(',')}) ${(100 * i) / (STRETCH_STOPS.length - 1)}%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
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
    ctx.moveTo(x, 0); ctx.lineTo(x, size);
    ctx.moveTo(0, x); ctx.lineTo(size, x);
  }
  ctx.stroke();
  return canvas;
}

// ------------------------------------------------------------------ the 2D layout

const MARGIN = 12; // CSS pixels around the unit square
const LEGEND_HEIGHT = 58; // CSS pixels below it: the boundary legend, a caption and a key

/** The canvas' backing store follows its CSS size (at least 2× for a crisp PNG export). */
function fitCanvas(canvas) {
  const width = canvas.clientWidth || 300;
  const height = canvas.clientHeight || Math.round(width + LEGEND_HEIGHT);
  const scale = Math.max(window.devicePixelRatio || 1, 2);
  const [w, h] = [Math.round(width * scale), Math.round(height * scale)];
  if (canvas.width !== w || canvas.height !== h) [canvas.width, canvas.height] = [w, h];
  // A CPU-backed canvas: its thousands of thin strokes draw faster in software than through a
  // (possibly software-emulated) GPU, and the PNG export and the tests read it back.
  const ctx = canvas.getContext('2d', { willReadFrequently: true });
  ctx.setTransform(scale, 0, 0, scale, 0, 0);
  return { ctx, width, height };
}

/**
 * Draws a parameterization's layout:
 *   layout = { uv, indices, faceStretch, overlays: [{ boundary, polygon, error }], boundary,
 *              heat: boolean, caption: string }
 * — the triangles' uv edges thinly (filled with their stretch colour when `heat`), the polygons of
 * the other boundaries dashed, the chosen boundary's polygon bold, and a legend. With `layout` null,
 * draws the empty frame and `message`.
 */
export function drawLayout(canvas, layout, message = '') {
  const { ctx, width, height } = fitCanvas(canvas);
  ctx.fillStyle = LAYOUT_BACKGROUND;
  ctx.fillRect(0, 0, width, height);

  // The uv frame [0,1]², as large as fits with the aspect ratio kept; v points up.
  const side = Math.max(10, Math.min(width - 2 * MARGIN, height - LEGEND_HEIGHT - 2 * MARGIN));
  const x0 = (width - side) / 2;
  const y0 = MARGIN;
  const px = (u) => x0 + u * side;
  const py = (v) => y0 + (1 - v) * side;

  ctx.strokeStyle = 'rgba(141, 150, 165, 0.16)';
  ctx.lineWidth = 1;
  ctx.beginPath();
  for (let k = 1; k < 4; k++) {
    ctx.moveTo(px(k / 4), py(0)); ctx.lineTo(px(k / 4), py(1));
    ctx.moveTo(px(0), py(k / 4)); ctx.lineTo(px(1), py(k / 4));
  }
  ctx.stroke();
  ctx.strokeStyle = 'rgba(141, 150, 165, 0.45)';
  ctx.setLineDash([3, 3]);
  ctx.strokeRect(px(0), py(1), side, side);
  ctx.setLineDash([]);

  if (!layout) {
    if (message) {
      ctx.fillStyle = '#8d96a5';
      ctx.font = '12.5px system-ui, sans-serif';
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      wrapText(ctx, message, width / 2, y0 + side / 2, side - 24, 17);
    }
    return;
  }

  const { uv, indices, faceStretch, overlays, boundary, heat } = layout;
  const faces = indices.length / 3;
  const corner = (f, k) => indices[3 * f + k];

  if (heat) {
    // One fill per face in its stretch colour, stroked with the same colour so no seams show.
    ctx.lineWidth = 0.6;
    for (let f = 0; f < faces; f++) {
      const color = `rgb(${stretchRgb(faceStretch[f]).join(',')})`;
      ctx.fillStyle = ctx.strokeStyle = color;
      ctx.beginPath();
      for (let k = 0; k < 3; k++) {
        const v = corner(f, k);
        ctx[k ? 'lineTo' : 'moveTo'](px(uv[2 * v]), py(uv[2 * v + 1]));
      }
      ctx.closePath();
      ctx.fill();
      ctx.stroke();
    }
  }

  // The mesh edges in uv: one path, so shared edges are not drawn twice as dark.
  ctx.strokeStyle = heat ? 'rgba(16, 19, 24, 0.35)' : 'rgba(214, 221, 232, 0.42)';
  ctx.lineWidth = 0.5;
  ctx.beginPath();
  for (let f = 0; f < faces; f++) {
    for (let k = 0; k < 3; k++) {
      const v = corner(f, k);
      ctx[k ? 'lineTo' : 'moveTo'](px(uv[2 * v]), py(uv[2 * v + 1]));
    }
    ctx.closePath();
  }
  ctx.stroke();

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
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.55)'; // a dark halo keeps the bold line readable on any fill
    ctx.lineWidth = 5;
    polygonPath(chosen.polygon);
    ctx.stroke();
    ctx.strokeStyle = BOUNDARY_COLORS[boundary];
    ctx.lineWidth = 3;
    ctx.stroke();
  }

  drawLegend(ctx, layout, x0, y0 + side + 10, side);
}

/**
 * Below the frame, three lines: a swatch per boundary polygon (the chosen one bold), the caption,
 * and the key of the fill (the stretch scale) or of the lines.
 */
function drawLegend(ctx, { overlays, boundary, caption, heat }, x, y, width) {
  ctx.textBaseline = 'middle';
  ctx.textAlign = 'left';
  let cx = x;
  for (const { boundary: kind, polygon } of overlays) {
    const isChosen = kind === boundary;
    ctx.strokeStyle = BOUNDARY_COLORS[kind];
    ctx.globalAlpha = polygon ? 1 : 0.4;
    ctx.lineWidth = isChosen ? 3 : 1.4;
    ctx.setLineDash(isChosen ? [] : [5, 3]);
    ctx.beginPath();
    ctx.moveTo(cx, y + 6); ctx.lineTo(cx + 18, y + 6);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.font = `${isChosen ? 600 : 400} 11.5px system-ui, sans-serif`;
    ctx.fillStyle = isChosen ? '#e4e7ec' : '#a3abb8';
    const label = polygon ? kind : `${kind} (failed)`;
    ctx.fillText(label, cx + 23, y + 6);
    ctx.globalAlpha = 1;
    cx += 23 + ctx.measureText(label).width + 14;
  }

  ctx.font = '11px system-ui, sans-serif';
  ctx.fillStyle = '#c3c9d3';
  ctx.fillText(fitText(ctx, caption ?? '', width), x, y + 22);

  ctx.fillStyle = '#8d96a5';
  const keyY = y + 37;
  if (!heat) {
    ctx.fillText(fitText(ctx, 'thin lines: mesh edges · dashed square: the uv frame [0,1]²', width), x, keyY);
    return;
  }
  // The stretch scale: "L2 stretch: 1 [ramp] ≥ 2 ■ flipped".
  let kx = x;
  const text = (t) => {
    ctx.fillStyle = '#8d96a5';
    ctx.fillText(t, kx, keyY);
    kx += ctx.measureText(t).width + 5;
  };
  text('L2 stretch:');
  text('1');
  const rampWidth = 60;
  const ramp = ctx.createLinearGradient(kx, 0, kx + rampWidth, 0);
  for (let i = 0; i <= 8; i++) ramp.addColorStop(i / 8, `rgb(${stretchRgb(1 + i / 8).join(',')})`);
  ctx.fillStyle = ramp;
  ctx.fillRect(kx, keyY - 4, rampWidth, 8);
  kx += rampWidth + 5;
  text('≥ 2');
  ctx.fillStyle = `rgb(${STRETCH_INFINITE.join(',')})`;
  ctx.fillRect(kx + 3, keyY - 4, 8, 8);
  kx += 16;
  text('flipped');
}

/** `text` shortened with an ellipsis to fit `width`. */
function fitText(ctx, text, width) {
  if (ctx.measureText(text).width <= width) return text;
  let end = text.length;
  while (end > 0 && ctx.measureText(`${text.slice(0, end)}…`).width > width) end--;
  return `${text.slice(0, end)}…`;
}

/** Centered text wrapped at word boundaries to `width`, lines `lineHeight` apart around y. */
function wrapText(ctx, text, x, y, width, lineHeight) {
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
  const top = y - ((lines.length - 1) * lineHeight) / 2;
  lines.forEach((l, i) => ctx.fillText(l, x, top + i * lineHeight));
}
