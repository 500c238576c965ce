// The "Figure and export" panel: the look of what is exported (checkerboard density, the paths' width,
// colour and visibility; the base plane has its own toggle above), the figure mode button, and the
// exports — the 3D view and the figure grid as PNG, the UV layout as PNG and SVG — at a chosen
// resolution (1× / 2× / 4× the CSS size) and background (dark, light, transparent).

import { createFigureMode } from './figure-mode.js';
import { BACKGROUNDS, download, fittingScale, pngBlob, renderToCanvas } from './image-export.js';
import { layoutSvg } from './layout-svg.js';
import { drawLayout, layoutExportSize } from './uv-layout.js';

const $ = (id) => document.getElementById(id);
const LAYOUT_EXPORT_WIDTH = 720; // CSS pixels of an exported UV layout (the PNG is this × the scale)

/**
 * session: session.js; view: scene.js; surface: surface-view.js; paths: path-view.js; param: what
 * createParamView returns (options, currentLayout, exportName, setCheckerCells).
 */
export function createExportPanel({ session, view, surface, paths, param }) {
  const scale = () => Number($('export-scale').value) || 1;
  const theme = () => $('export-background').value;

  function setButtons() {
    $('figure-button').disabled = !surface.mesh;
    $('export-view-button').disabled = !surface.mesh;
    $('export-figure-button').disabled = !figure.complete;
  }

  const figure = createFigureMode({
    session,
    view,
    surface,
    options: param.options,
    checkerCells: () => param.checkerCells,
    onChange: () => setButtons(),
  });

  /** Says in the panel what was saved (details.note: why the scale shrank). */
  function saved(name, details = {}) {
    $('export-status').textContent = `Saved ${name}${details.note ? ` (${details.note})` : ''}`;
  }

  function failed(what, err) {
    $('export-status').textContent = `Could not export the ${what}: ${err.message}`;
  }

  /** Says what is being drawn and lets the browser show it before the (synchronous) render. */
  function working(what) {
    $('export-status').textContent = `Rendering the ${what} at ${scale()}×…`;
    return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
  }

  /** Fits the wanted scale to the GPU; returns it and a note when it had to shrink. */
  function usableScale(width, height) {
    const wanted = scale();
    const usable = fittingScale(width, height, wanted);
    return { usable, note: usable < wanted ? `${usable.toFixed(2)}×: the GPU draws no larger image` : '' };
  }

  async function exportView() {
    try {
      await working('3D view');
      const { clientWidth: width, clientHeight: height } = view.canvas;
      const { usable, note } = usableScale(width, height);
      const canvas = renderToCanvas(view.scene, view.camera, {
        width,
        height,
        scale: usable,
        background: BACKGROUNDS[theme()],
      });
      const name = `${(session.label || 'mesh').replace(/\.[^.]+$/, '').replace(/[^\w.-]+/g, '_')}-view-${scale()}x.png`;
      download(await pngBlob(canvas), name);
      saved(name, { note });
    } catch (err) {
      failed('3D view', err);
    }
  }

  async function exportFigure() {
    if (!figure.complete) return;
    try {
      await working('figure');
      const canvas = figure.compose({ scale: scale(), theme: theme() });
      const name = `${figure.name.replace(/[^\w.-]+/g, '_')}-figure-${scale()}x.png`;
      download(await pngBlob(canvas), name);
      saved(name);
    } catch (err) {
      failed('figure', err);
    }
  }

  async function exportLayoutPng() {
    const layout = param.currentLayout();
    if (!layout) return;
    try {
      const canvas = document.createElement('canvas');
      const size = layoutExportSize(layout, LAYOUT_EXPORT_WIDTH);
      drawLayout(canvas, layout, '', { size: { ...size, scale: scale() }, theme: theme() });
      const name = `${param.exportName()}-uv-layout.png`;
      download(await pngBlob(canvas), name);
      saved(name);
    } catch (err) {
      failed('layout', err);
    }
  }

  function exportLayoutSvg() {
    const layout = param.currentLayout();
    if (!layout) return;
    try {
      const text = layoutSvg(layout, { width: LAYOUT_EXPORT_WIDTH, theme: theme() });
      const name = `${param.exportName()}-uv-layout.svg`;
      download(new Blob([text], { type: 'image/svg+xml' }), name);
      saved(name);
    } catch (err) {
      failed('layout', err);
    }
  }

  // ---------------------------------------------------------------- controls

  $('figure-button').addEventListener('click', () => figure.open());
  $('export-view-button').addEventListener('click', () => exportView());
  $('export-figure-button').addEventListener('click', () => exportFigure());
  $('export-png-button').addEventListener('click', () => exportLayoutPng());
  $('export-svg-button').addEventListener('click', () => exportLayoutSvg());
  $('checker-cells').addEventListener('change', (event) => {
    param.setCheckerCells(Number(event.target.value));
    figure.redraw();
  });
  const pathStyle = () =>
    paths.setStyle({
      visible: $('paths-toggle').checked,
      width: Number($('path-width').value),
      color: $('path-color').value,
    });
  for (const id of ['paths-toggle', 'path-width', 'path-color']) $(id).addEventListener('input', pathStyle);
  session.addEventListener('meshchange', () => setButtons());
  session.addEventListener('meshready', () => setButtons());
  setButtons();

  return { figure };
}
