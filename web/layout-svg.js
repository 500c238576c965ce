// The UV layout as an SVG document: the same drawing as uv-layout.js's canvas (frame, mesh edges or
// the stretch fill, the boundary polygons, the legend with its whole caption wrapped), as vectors and
// text a paper's figure can be edited from. A mesh too dense to stroke (RASTER_FACES) has its
// triangles embedded as one raster image under the vector polygons and text.

import { BOUNDARY_COLORS, STRETCH_INFINITE, stretchRgb } from './colormap.js';
import {
  FONT,
  LAYOUT_THEMES,
  LINE_HEIGHT,
  MARGIN,
  RASTER_FACES,
  SEAM_COLOR,
  layoutExportSize,
  legendText,
  rasterLayer,
} from './uv-layout.js';

const escapeXml = (text) => String(text).replace(/[<>&'"]/g, (c) => `&#${c.charCodeAt(0)};`);
const num = (x) => (Math.round(x * 100) / 100).toString();

/** Where the square of uv [0,1]² lies in the picture: px(u), py(v) in CSS pixels. */
function squareAt(side) {
  const x0 = MARGIN;
  const y0 = MARGIN;
  return { x0, y0, side, px: (u) => num(x0 + u * side), py: (v) => num(y0 + (1 - v) * side) };
}

/** The quarter grid and the dashed frame of the uv square. */
function frameSvg({ px, py, side }, colors) {
  const grid = [];
  for (let k = 1; k < 4; k++) {
    grid.push(`M${px(k / 4)} ${py(0)}V${py(1)}`, `M${px(0)} ${py(k / 4)}H${px(1)}`);
  }
  return [
    `<path d="${grid.join('')}" stroke="${colors.grid}" fill="none"/>`,
    `<rect x="${px(0)}" y="${py(1)}" width="${num(side)}" height="${num(side)}" fill="none" ` +
      `stroke="${colors.frame}" stroke-dasharray="3 3"/>`,
  ];
}

/** The triangles: stroked (and filled by stretch for the heat map), or one raster image when too dense. */
function facesSvg(layout, square, theme, colors) {
  const { cornerUv, faceStretch, heat } = layout;
  const { x0, y0, side, px, py } = square;
  const faces = cornerUv.length / 6;
  if (faces > RASTER_FACES) {
    const image = rasterLayer(layout, side, 2, theme).toDataURL('image/png');
    return [`<image x="${x0}" y="${y0}" width="${num(side)}" height="${num(side)}" href="${image}"/>`];
  }
  const triangle = (f) => {
    const corners = [0, 1, 2].map((k) => `${px(cornerUv[6 * f + 2 * k])} ${py(cornerUv[6 * f + 2 * k + 1])}`);
    return `M${corners.join('L')}Z`;
  };
  const inLayout = (f) => Number.isFinite(cornerUv[6 * f]);
  const out = [];
  if (heat) {
    out.push('<g stroke-width="0.6">');
    for (let f = 0; f < faces; f++) {
      if (!inLayout(f)) continue;
      const color = `rgb(${stretchRgb(faceStretch[f]).join(',')})`;
      out.push(`<path d="${triangle(f)}" fill="${color}" stroke="${color}"/>`);
    }
    out.push('</g>');
  }
  const edges = [];
  for (let f = 0; f < faces; f++) if (inLayout(f)) edges.push(triangle(f));
  out.push(
    `<path d="${edges.join('')}" fill="none" stroke="${heat ? colors.heatEdges : colors.edges}" ` +
      'stroke-width="0.5" stroke-linejoin="round"/>',
  );
  return out;
}

/** The other boundaries dashed, the chosen one (or the seam) bold over a halo. */
function boundariesSvg({ overlays, boundary, seam }, { px, py }, colors) {
  const polygonPath = (polygon) => {
    const points = [];
    for (let i = 0; i < polygon.length; i += 2) points.push(`${px(polygon[i])} ${py(polygon[i + 1])}`);
    return `M${points.join('L')}Z`;
  };
  const out = [];
  for (const { boundary: kind, polygon } of overlays) {
    if (!polygon || kind === boundary) continue;
    out.push(
      `<path d="${polygonPath(polygon)}" fill="none" stroke="${BOUNDARY_COLORS[kind]}" stroke-width="1.4" ` +
        'stroke-dasharray="5 3" stroke-linejoin="round"/>',
    );
  }
  const chosen = overlays.find((o) => o.boundary === boundary && o.polygon);
  if (chosen) {
    const d = polygonPath(chosen.polygon);
    out.push(`<path d="${d}" fill="none" stroke="${colors.halo}" stroke-width="5" stroke-linejoin="round"/>`);
    out.push(
      `<path d="${d}" fill="none" stroke="${seam ? SEAM_COLOR : BOUNDARY_COLORS[boundary]}" ` +
        'stroke-width="3" stroke-linejoin="round"/>',
    );
  }
  return out;
}

/** The legend's first row: a swatch and a label per boundary, from x0 at y. */
function swatchesSvg({ overlays, boundary, seam }, x0, y, measure, colors) {
  const out = [];
  let cx = x0;
  for (const { boundary: kind, polygon } of overlays) {
    const isChosen = kind === boundary;
    const label = polygon ? `${kind}${isChosen && seam ? ' = seam' : ''}` : `${kind} (failed)`;
    const stroke = isChosen && seam ? SEAM_COLOR : BOUNDARY_COLORS[kind];
    out.push(
      `<g opacity="${polygon ? 1 : 0.4}"><path d="M${num(cx)} ${y + 6}h18" stroke="${stroke}" ` +
        `stroke-width="${isChosen ? 3 : 1.4}"${isChosen ? '' : ' stroke-dasharray="5 3"'}/>` +
        `<text x="${num(cx + 23)}" y="${y + 6}" dominant-baseline="middle" font-size="11.5" ` +
        `font-weight="${isChosen ? 600 : 400}" fill="${isChosen ? colors.strong : colors.label}">` +
        `${escapeXml(label)}</text></g>`,
    );
    measure.font = `${isChosen ? 600 : 400} 11.5px ${FONT}`;
    cx += 23 + measure.measureText(label).width + 14;
  }
  return out;
}

/** The heat map's key on the line at y: the stretch ramp from 1 to ≥ 2 and the flipped swatch. */
function heatKeySvg(x0, y, measure, colors) {
  const label = (x, text) =>
    `<text x="${num(x)}" y="${num(y)}" dominant-baseline="middle" font-size="11" fill="${colors.muted}">` +
    `${text}</text>`;
  const stops = Array.from(
    { length: 9 },
    (_, i) => `<stop offset="${i / 8}" stop-color="rgb(${stretchRgb(1 + i / 8).join(',')})"/>`,
  ).join('');
  measure.font = `11px ${FONT}`;
  const rampX = x0 + measure.measureText('L2 stretch: 1').width + 5;
  const flippedX = rampX + 65 + measure.measureText('≥ 2').width + 8;
  return [
    `<defs><linearGradient id="stretch-ramp">${stops}</linearGradient></defs>`,
    label(x0, 'L2 stretch: 1'),
    `<rect x="${num(rampX)}" y="${num(y - 4)}" width="60" height="8" fill="url(#stretch-ramp)"/>`,
    label(rampX + 65, '≥ 2'),
    `<rect x="${num(flippedX)}" y="${num(y - 4)}" width="8" height="8" ` +
      `fill="rgb(${STRETCH_INFINITE.join(',')})"/>`,
    label(flippedX + 13, 'flipped'),
  ];
}

/** The legend under the square: swatches, then the wrapped title, caption and key (measured as the canvas draws them). */
function legendSvg(layout, { x0, y0, side }, colors) {
  const measure = document.createElement('canvas').getContext('2d');
  const text = legendText(measure, { ...layout, faces: layout.cornerUv.length / 6 }, side, true);
  let y = y0 + side + 10;
  const out = swatchesSvg(layout, x0, y, measure, colors);
  y += 22;
  const lines = (list, size, weight, color) => {
    for (const line of list) {
      out.push(
        `<text x="${x0}" y="${num(y)}" dominant-baseline="middle" font-size="${size}" font-weight="${weight}" ` +
          `fill="${color}">${escapeXml(line)}</text>`,
      );
      y += LINE_HEIGHT;
    }
  };
  lines(text.title, 12, 600, colors.strong);
  lines(text.caption, 11, 400, colors.text);
  if (layout.heat) out.push(...heatKeySvg(x0, y, measure, colors));
  else lines(text.key, 11, 400, colors.muted);
  return out;
}

/**
 * The layout (drawLayout's `layout`) as SVG text `width` CSS pixels wide on the `theme`'s background.
 */
export function layoutSvg(layout, { width = 720, theme = 'light' } = {}) {
  const colors = LAYOUT_THEMES[theme] ?? LAYOUT_THEMES.light;
  const { height } = layoutExportSize(layout, width);
  const square = squareAt(width - 2 * MARGIN);
  const head = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" ` +
      `font-family="${FONT}">`,
  ];
  if (colors.background) head.push(`<rect width="100%" height="100%" fill="${colors.background}"/>`);
  // (concat, not push(...parts): a layout just under RASTER_FACES has more paths than a call takes arguments)
  const out = head.concat(
    frameSvg(square, colors),
    facesSvg(layout, square, theme, colors),
    boundariesSvg(layout, square, colors),
    legendSvg(layout, square, colors),
    ['</svg>'],
  );
  return `${out.join('\n')}\n`;
}
