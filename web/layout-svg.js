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

/**
 * The layout (drawLayout's `layout`) as SVG text `width` CSS pixels wide on the `theme`'s background.
 */
export function layoutSvg(layout, { width = 720, theme = 'light' } = {}) {
  const colors = LAYOUT_THEMES[theme] ?? LAYOUT_THEMES.light;
  const { height } = layoutExportSize(layout, width);
  const side = width - 2 * MARGIN;
  const x0 = MARGIN;
  const y0 = MARGIN;
  const px = (u) => num(x0 + u * side);
  const py = (v) => num(y0 + (1 - v) * side);
  const { cornerUv, faceStretch, overlays, boundary, seam, heat } = layout;
  const faces = cornerUv.length / 6;
  const out = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" ` +
      `font-family="${FONT}">`,
  ];
  if (colors.background) out.push(`<rect width="100%" height="100%" fill="${colors.background}"/>`);

  const grid = [];
  for (let k = 1; k < 4; k++) {
    grid.push(`M${px(k / 4)} ${py(0)}V${py(1)}`, `M${px(0)} ${py(k / 4)}H${px(1)}`);
  }
  out.push(`<path d="${grid.join('')}" stroke="${colors.grid}" fill="none"/>`);
  out.push(
    `<rect x="${px(0)}" y="${py(1)}" width="${num(side)}" height="${num(side)}" fill="none" ` +
      `stroke="${colors.frame}" stroke-dasharray="3 3"/>`,
  );

  const triangle = (f) => {
    const corners = [0, 1, 2].map((k) => `${px(cornerUv[6 * f + 2 * k])} ${py(cornerUv[6 * f + 2 * k + 1])}`);
    return `M${corners.join('L')}Z`;
  };
  const inLayout = (f) => Number.isFinite(cornerUv[6 * f]);
  if (faces > RASTER_FACES) {
    const image = rasterLayer(layout, side, 2, theme).toDataURL('image/png');
    out.push(`<image x="${x0}" y="${y0}" width="${num(side)}" height="${num(side)}" href="${image}"/>`);
  } else {
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
  }

  const polygonPath = (polygon) => {
    const points = [];
    for (let i = 0; i < polygon.length; i += 2) points.push(`${px(polygon[i])} ${py(polygon[i + 1])}`);
    return `M${points.join('L')}Z`;
  };
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

  // The legend: swatches, then the wrapped title, caption and key (measured as the canvas draws them).
  const measure = document.createElement('canvas').getContext('2d');
  const text = legendText(measure, { ...layout, faces }, side, true);
  let y = y0 + side + 10;
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
  if (!heat) {
    lines(text.key, 11, 400, colors.muted);
  } else {
    const stops = Array.from(
      { length: 9 },
      (_, i) => `<stop offset="${i / 8}" stop-color="rgb(${stretchRgb(1 + i / 8).join(',')})"/>`,
    ).join('');
    out.push(`<defs><linearGradient id="stretch-ramp">${stops}</linearGradient></defs>`);
    out.push(
      `<text x="${x0}" y="${num(y)}" dominant-baseline="middle" font-size="11" fill="${colors.muted}">` +
        'L2 stretch: 1</text>',
    );
    measure.font = `11px ${FONT}`;
    const rampX = x0 + measure.measureText('L2 stretch: 1').width + 5;
    out.push(`<rect x="${num(rampX)}" y="${num(y - 4)}" width="60" height="8" fill="url(#stretch-ramp)"/>`);
    out.push(
      `<text x="${num(rampX + 65)}" y="${num(y)}" dominant-baseline="middle" font-size="11" ` +
        `fill="${colors.muted}">≥ 2</text>`,
    );
    const flippedX = rampX + 65 + measure.measureText('≥ 2').width + 8;
    out.push(
      `<rect x="${num(flippedX)}" y="${num(y - 4)}" width="8" height="8" ` +
        `fill="rgb(${STRETCH_INFINITE.join(',')})"/>`,
    );
    out.push(
      `<text x="${num(flippedX + 13)}" y="${num(y)}" dominant-baseline="middle" font-size="11" ` +
        `fill="${colors.muted}">flipped</text>`,
    );
  }
  out.push('</svg>');
  return `${out.join('\n')}\n`;
}
