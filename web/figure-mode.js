// Figure mode: the paper's Figures 3 and 4 in one click — the mesh on display parameterized with each
// boundary (square, circle, measured, and free where the core offers it), side by side over the 3D
// view, each textured with the checkerboard from the same viewpoint, its L2 and L∞ stretch under it
// and its UV layout beneath; and the same grid composed into one image for export. The worker does
// every parameterization (the page's 'parameterize' request, one per boundary, with the options of
// the Parameterization panel); here they are only drawn. The 3D images are offscreen renders
// (image-export.js), so the main view is untouched and shows again as it was when figure mode closes.
//
// What it has shown, as plain data, is status() (main.js puts it in the page's observable state as
// figure, docs/PAGE.md).

import * as THREE from 'three';
import { applyUV, toSeamSplitGeometry } from 'straightest/three';
import { latest } from './latest.js';
import { isCancelled } from './requests.js';
import { BACKGROUNDS, renderToCanvas } from './image-export.js';
import { WEIGHT_LABELS, formatMetric } from './param-format.js';
import { LAYOUT_THEMES, checkerboardCanvas, drawLayout, layoutExportSize } from './uv-layout.js';

/** The panels' order, as the paper lays them out: fixed boundaries first, then the measured one. */
const FIGURE_ORDER = ['square', 'circle', 'measured', 'free'];
const EXPORT_PANEL_WIDTH = 360; // CSS pixels per panel of the exported grid
const TEXT_COLORS = {
  dark: ['#e4e7ec', '#a3abb8'],
  light: ['#11151b', '#3d4552'],
  transparent: ['#11151b', '#3d4552'],
};

/**
 * session: session.js; view: scene.js (its camera gives the viewpoint, its viewport holds the grid);
 * surface: surface-view.js (the mesh's geometry); options(): { source, weights } of the runs;
 * checkerCells(): the checkerboard's cells per side; onChange(): figure mode opened, closed or
 * finished (the export buttons may change).
 */
export function createFigureMode({ session, view, surface, options, checkerCells, onChange = () => {} }) {
  const runs = latest();
  let panels = []; // [{ boundary, reply, geometry }] of the finished runs
  let running = false;
  let shownFor = null; // { label, weights } the grid was computed for
  // For status(): { state: 'running' | 'done' | 'cancelled' | 'failed', panels: [{ boundary, l2, linf,
  // bijective, init }] in the order shown }, or null (never opened, or a new mesh).
  let outcome = null;

  // ---------------------------------------------------------------- the panels' scene

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  scene.add(camera, new THREE.HemisphereLight(0xdde6ff, 0x2a2418, 0.7));
  const headlight = new THREE.DirectionalLight(0xffffff, 2.6); // as the main view's: upper right of the camera
  headlight.position.set(1, 1.5, 0.3);
  camera.add(headlight, headlight.target);
  headlight.target.position.set(0, 0, -1);
  const material = new THREE.MeshStandardMaterial({ roughness: 0.75, metalness: 0, side: THREE.DoubleSide });
  let textureCells = 0;

  function updateTexture() {
    const cells = checkerCells();
    if (cells === textureCells) return;
    material.map?.dispose();
    const texture = new THREE.CanvasTexture(checkerboardCanvas(1024, cells));
    texture.colorSpace = THREE.SRGBColorSpace;
    texture.anisotropy = 8;
    material.map = texture;
    material.needsUpdate = true;
    textureCells = cells;
  }

  /** The geometry of a panel: the surface with the run's uv (a cut mesh: split along its seam). */
  function panelGeometry(reply) {
    const shared = surface.mesh.geometry;
    if (reply.cut !== 'disk') {
      return toSeamSplitGeometry(
        {
          positions: () => shared.getAttribute('position').array,
          vertexNormals: () => shared.getAttribute('normal').array,
          indices: () => shared.index.array,
        },
        reply,
      );
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', shared.getAttribute('position'));
    geometry.setAttribute('normal', shared.getAttribute('normal'));
    geometry.setIndex(shared.index);
    return applyUV(geometry, reply.uv);
  }

  /**
   * Looks at the mesh from where the main view looks from, its bounding sphere fitting an image of
   * `aspect` (width / height).
   */
  function placeCamera(aspect) {
    const { min, max } = session.info.bbox;
    const center = new THREE.Vector3(...min).add(new THREE.Vector3(...max)).multiplyScalar(0.5);
    const radius = Math.max(new THREE.Vector3(...max).distanceTo(new THREE.Vector3(...min)) / 2, 1e-6);
    const direction = view.camera.position.clone().sub(center);
    if (direction.lengthSq() === 0) direction.copy(view.camera.up);
    const halfFov = THREE.MathUtils.degToRad(view.camera.fov / 2);
    const fit = Math.min(halfFov, Math.atan(Math.tan(halfFov) * aspect));
    const distance = (0.92 * radius) / Math.sin(fit); // a little closer than the sphere: a box's corners rarely reach it
    camera.fov = view.camera.fov;
    camera.aspect = aspect;
    camera.up.copy(view.camera.up);
    camera.position.copy(center).addScaledVector(direction.normalize(), distance);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.lookAt(center);
    camera.updateProjectionMatrix();
  }

  /** A panel's textured mesh rendered into a new canvas (see image-export.js renderToCanvas). */
  function render3d(panel, width, height, scale, background) {
    updateTexture();
    placeCamera(width / height);
    const mesh = new THREE.Mesh(panel.geometry, material);
    scene.add(mesh);
    try {
      return renderToCanvas(scene, camera, { width, height, scale, background });
    } finally {
      scene.remove(mesh);
    }
  }

  /** A panel's layout for drawLayout: its own polygon only, the stretch in the caption. */
  function panelLayout(panel) {
    const { reply } = panel;
    return {
      cornerUv: reply.cornerUv,
      seam: reply.cut === 'path' || reply.cut === 'cut-graph',
      faceStretch: reply.faceStretch,
      overlays: reply.overlays.filter((o) => o.boundary === reply.boundary),
      boundary: reply.boundary,
      heat: false,
      caption: `${reply.init ? `from ${reply.init} · ` : ''}${reply.bijective ? 'bijective' : 'not bijective'}`,
    };
  }

  const stretchText = (reply) => `L2 ${formatMetric(reply.stretch.l2)} · L∞ ${formatMetric(reply.stretch.linf)}`;

  // ---------------------------------------------------------------- the grid over the view

  const root = document.createElement('section');
  root.id = 'figure-view';
  root.hidden = true;
  root.setAttribute('aria-label', 'Figure: the mesh under every boundary');
  root.innerHTML = `
    <header>
      <h2>Figure <span class="muted" id="figure-subtitle"></span></h2>
      <progress id="figure-progress" max="1" value="0" hidden></progress>
      <span id="figure-status" class="muted" aria-live="polite"></span>
      <button type="button" id="figure-cancel-button" hidden>Cancel</button>
      <button type="button" id="figure-close-button" title="Esc">Back to the 3D view</button>
    </header>
    <div id="figure-grid"></div>`;
  view.viewport.append(root);
  const $ = (id) => root.querySelector(`#${id}`);

  function panelElement(panel) {
    const figure = document.createElement('figure');
    figure.className = 'figure-panel';
    figure.dataset.boundary = panel.boundary;
    figure.innerHTML =
      '<canvas class="figure-3d"></canvas><figcaption><strong></strong> ' +
      '<span class="figure-stretch"></span></figcaption><canvas class="figure-uv"></canvas>';
    figure.querySelector('strong').textContent =
      `${panel.boundary}${panel.reply.init ? ` (from ${panel.reply.init})` : ''}`;
    figure.querySelector('.figure-stretch').textContent = stretchText(panel.reply);
    figure.querySelector('.figure-stretch').dataset.l2 = String(panel.reply.stretch.l2);
    return figure;
  }

  /** Draws a panel's 3D image and layout at the size its grid cell has now. */
  function drawPanel(figure, panel) {
    const image = figure.querySelector('.figure-3d');
    const width = Math.max(80, Math.floor(image.clientWidth || 240));
    const height = Math.max(80, Math.floor(image.clientHeight || width));
    const scale = Math.min(window.devicePixelRatio || 1, 2);
    const rendered = render3d(panel, width, height, scale, BACKGROUNDS.dark);
    [image.width, image.height] = [rendered.width, rendered.height];
    image.getContext('2d').drawImage(rendered, 0, 0);
    const uv = figure.querySelector('.figure-uv');
    const layout = panelLayout(panel);
    drawLayout(uv, layout, '', { size: { ...layoutExportSize(layout, width), scale: Math.max(scale, 2) } });
  }

  function redraw() {
    if (root.hidden) return;
    const figures = [...root.querySelectorAll('.figure-panel')];
    figures.forEach((figure, i) => drawPanel(figure, panels[i]));
  }
  new ResizeObserver(() => redraw()).observe(root);

  function setRunning(value, status = '') {
    running = value;
    $('figure-progress').hidden = !value;
    $('figure-cancel-button').hidden = !value;
    $('figure-status').textContent = status;
    onChange();
  }

  function forgetPanels() {
    for (const panel of panels) panel.geometry.dispose();
    panels = [];
    $('figure-grid').replaceChildren();
    outcome = null;
  }

  /** Parameterizes the mesh with every boundary of FIGURE_ORDER the core has, one after another. */
  async function run() {
    if (!surface.mesh || !session.info) return;
    const request = runs.begin(session.meshes);
    forgetPanels();
    const kinds = FIGURE_ORDER.filter((kind) => session.boundaryKinds.includes(kind));
    const { source, weights } = options();
    shownFor = { label: session.label || 'mesh', weights };
    $('figure-subtitle').textContent = `${shownFor.label} · ${WEIGHT_LABELS[weights]} weights`;
    outcome = { state: 'running', panels: [] };
    setRunning(true, `0 / ${kinds.length}`);
    const progress = $('figure-progress');
    try {
      for (const [i, boundary] of kinds.entries()) {
        let stages = null;
        const reply = await session.request('parameterize', { source, boundary, weights }, (message) => {
          if (request.stale()) return;
          stages ??= message.stages ?? null;
          const k = stages ? Math.max(stages.indexOf(message.stage), 0) : 0;
          progress.value = (i + (k + message.fraction) / (stages?.length ?? 1)) / kinds.length;
          $('figure-status').textContent = `${i + 1} / ${kinds.length}: ${boundary}`;
        });
        if (request.stale()) return;
        const panel = { boundary, reply, geometry: panelGeometry(reply) };
        panels.push(panel);
        $('figure-grid').append(panelElement(panel));
        drawPanel($('figure-grid').lastElementChild, panel);
        outcome.panels.push({
          boundary,
          l2: reply.stretch.l2,
          linf: reply.stretch.linf,
          bijective: reply.bijective,
          init: reply.init,
        });
      }
      outcome.state = 'done';
      setRunning(false, `${panels.length} boundaries`);
    } catch (err) {
      if (request.stale()) return;
      outcome.state = isCancelled(err) ? 'cancelled' : 'failed';
      setRunning(false, isCancelled(err) ? 'cancelled' : `failed: ${err.message}`);
    }
  }

  function close() {
    runs.supersede();
    root.hidden = true;
    if (running) setRunning(false);
    view.requestRender();
    onChange();
  }

  $('figure-close-button').addEventListener('click', () => close());
  root.addEventListener('keydown', (event) => {
    if (event.key === 'Escape') close();
  });
  $('figure-cancel-button').addEventListener('click', () => session.cancel());
  session.addEventListener('meshchange', () => {
    close();
    forgetPanels();
  });
  session.addEventListener('cancel', () => {
    if (!running) return;
    runs.supersede();
    if (outcome) outcome.state = 'cancelled';
    setRunning(false, 'cancelled');
  });

  // ---------------------------------------------------------------- the grid as one image

  /**
   * The finished grid composed into one canvas: a title, then per boundary a column with its 3D
   * image, its name and stretch, and its layout; `scale` device pixels per CSS pixel, on `theme`'s
   * background ('dark', 'light' or 'transparent').
   */
  function compose({ scale = 1, theme = 'light' } = {}) {
    const width = EXPORT_PANEL_WIDTH;
    const gap = 16;
    const titleHeight = 30;
    const captionHeight = 40;
    const layouts = panels.map((panel) => {
      const layout = panelLayout(panel);
      return { layout, size: layoutExportSize(layout, width) };
    });
    const layoutHeight = Math.max(...layouts.map((l) => l.size.height));
    const cssWidth = gap + panels.length * (width + gap);
    const cssHeight = titleHeight + width + captionHeight + layoutHeight + gap;
    const canvas = document.createElement('canvas');
    canvas.width = Math.round(cssWidth * scale);
    canvas.height = Math.round(cssHeight * scale);
    const ctx = canvas.getContext('2d');
    ctx.scale(scale, scale);
    const background = LAYOUT_THEMES[theme]?.background ?? null;
    if (background) {
      ctx.fillStyle = background;
      ctx.fillRect(0, 0, cssWidth, cssHeight);
    }
    const [strong, muted] = TEXT_COLORS[theme] ?? TEXT_COLORS.light;
    ctx.textBaseline = 'middle';
    ctx.fillStyle = strong;
    ctx.font = '600 14px system-ui, sans-serif';
    ctx.fillText(
      `${shownFor?.label ?? ''} · ${WEIGHT_LABELS[shownFor?.weights] ?? ''} weights`,
      gap,
      titleHeight / 2 + 4,
    );
    panels.forEach((panel, i) => {
      const x = gap + i * (width + gap);
      const image = render3d(panel, width, width, scale, BACKGROUNDS[theme] ?? null);
      ctx.drawImage(image, x, titleHeight, width, width);
      ctx.fillStyle = strong;
      ctx.font = '600 13px system-ui, sans-serif';
      ctx.fillText(`${panel.boundary} boundary`, x, titleHeight + width + 12);
      ctx.fillStyle = muted;
      ctx.font = '12.5px system-ui, sans-serif';
      ctx.fillText(stretchText(panel.reply), x, titleHeight + width + 30);
      const uv = document.createElement('canvas');
      drawLayout(uv, layouts[i].layout, '', { size: { ...layouts[i].size, scale }, theme });
      ctx.drawImage(uv, x, titleHeight + width + captionHeight, width, layouts[i].size.height);
    });
    return canvas;
  }

  return {
    /** Shows the grid over the view and computes it (again: the options or the view may have changed). */
    open() {
      root.hidden = false;
      $('figure-close-button').focus(); // Esc closes from here
      run();
      onChange();
    },
    close,
    compose,
    /** The checkerboard changed: the panels are drawn again. */
    redraw,
    get isOpen() {
      return !root.hidden;
    },
    /** Every panel is computed (the grid can be exported). */
    get complete() {
      return !running && panels.length > 0;
    },
    /** The base of export file names: the mesh and the weights. */
    get name() {
      return `${shownFor?.label ?? 'mesh'}-${shownFor?.weights ?? ''}`;
    },
    /** The grid's state and panels (a copy: see `outcome` above), or null. */
    status: () => structuredClone(outcome),
  };
}
