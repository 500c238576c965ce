// Pointing at the 3D view: hovering a path highlights it and shows its tooltip, and a click (press
// and release without dragging; drags belong to the orbit controls) on the surface picks a surface
// point — onPick({ point: {face, bary}, position: THREE.Vector3 }, add) with add true for shift+click.

import * as THREE from 'three';
import { describePoint, formatNumber } from './panels.js';
import { formatCount } from './param-format.js';
import { statusWords } from './data-export.js';

// How the tooltip names a trace status: in words (data-export.js), with the core's code after a failure.
const STATUS_TEXT = {
  reached: 'reached',
  other_component: 'destination on another loop of the section (other_component): drawn, the loop back',
};

/**
 * The 3D position of a surface point on the mesh on display (surface-view.js's mesh): { vertex } or
 * { face, bary } — for a point typed instead of clicked (its marker).
 */
export function surfacePosition(surfaceMesh, point) {
  const { index, attributes } = surfaceMesh.geometry;
  const at = (vertex) => new THREE.Vector3().fromBufferAttribute(attributes.position, vertex);
  if (point.vertex !== undefined) return at(point.vertex);
  const position = new THREE.Vector3();
  point.bary.forEach((b, k) => position.addScaledVector(at(index.getX(3 * point.face + k)), b));
  return position;
}

/** view: scene.js; surface: surface-view.js; paths: path-view.js; tooltip: the tooltip element. */
export function createPicking({ view, surface, paths, tooltip, onPick }) {
  // Only the 3D surface mode draws the paths and the surface they are picked on (the atlas mode shows
  // its own mesh on another camera layer): elsewhere hovering and clicking do nothing.
  const active = () => (document.body.dataset.mode ?? 'surface') === 'surface';
  const { canvas, viewport, camera } = view;
  const raycaster = new THREE.Raycaster();
  raycaster.layers.enableAll(); // the surface's arrays lie on a layer of their own (surface-view.js)
  raycaster.params.Line2 = { threshold: 6 }; // pixels around a path that count as "on" it
  const pointer = new THREE.Vector2();

  /** Sets the raycaster from a pointer event on the canvas. */
  function aimAt(event) {
    const rect = canvas.getBoundingClientRect();
    pointer.set(
      ((event.clientX - rect.left) / rect.width) * 2 - 1,
      -((event.clientY - rect.top) / rect.height) * 2 + 1,
    );
    raycaster.setFromCamera(pointer, camera);
    raycaster.camera = camera;
  }

  /** The surface under the pointer as { hit, point: {face, bary} }, or null. */
  function pickSurface() {
    const mesh = surface.mesh;
    if (!mesh) return null;
    const [hit] = raycaster.intersectObject(mesh, false);
    if (!hit || hit.faceIndex == null) return null;
    const { index, attributes } = mesh.geometry;
    const corner = (k) =>
      new THREE.Vector3().fromBufferAttribute(attributes.position, index.getX(3 * hit.faceIndex + k));
    const bary = THREE.Triangle.getBarycoord(hit.point, corner(0), corner(1), corner(2), new THREE.Vector3());
    if (!bary) return null; // a degenerate triangle
    // Clamp the rounding noise so the point is inside the face, then renormalize.
    const b = bary.toArray().map((x) => Math.max(x, 0));
    const total = b[0] + b[1] + b[2];
    return { hit, point: { face: hit.faceIndex, bary: b.map((x) => x / total) } };
  }

  /** The path under the pointer (not hidden behind the surface), or -1. */
  function pickPath() {
    const shown = paths.shown;
    if (!shown || shown.lines.length === 0) return -1;
    const surfaceHit = surface.mesh ? raycaster.intersectObject(surface.mesh, false)[0] : null;
    const limit = surfaceHit ? surfaceHit.distance + 0.01 * view.scale : Infinity;
    let best = -1;
    let bestAngle = Infinity;
    for (const hit of raycaster.intersectObjects(shown.lines, false)) {
      const depth = raycaster.ray.origin.distanceTo(hit.pointOnLine);
      if (depth > limit) continue;
      const angle = raycaster.ray.distanceToPoint(hit.pointOnLine) / depth; // off the ray, as seen
      if (angle < bestAngle) {
        bestAngle = angle;
        best = hit.object.userData.owner[hit.faceIndex];
      }
    }
    return best;
  }

  function showTooltip(i, event) {
    const { reply } = paths.shown;
    const status = reply.statuses[i];
    tooltip.replaceChildren();
    const title = document.createElement('strong');
    title.textContent = `Path ${i + 1} of ${reply.count} → ${describePoint(reply.targets[i])}`;
    const state = document.createElement('span');
    state.className = status === 'reached' ? 'reached' : 'failed';
    state.textContent = STATUS_TEXT[status] ?? `${statusWords(status)} (${status}; partial path)`;
    const details = document.createElement('span');
    // Closed surfaces: which way round the section the path leaves, and the other way's length.
    const other = reply.otherArcLengths?.[i];
    const arcs = Number.isFinite(other)
      ? ` · ${reply.backward[i] ? 'backward' : 'forward'}, the other way round ${formatNumber(other)}`
      : '';
    details.textContent = `length ${formatNumber(reply.lengths[i])}${arcs} · ${formatCount(reply.facesCrossed[i])} faces crossed`;
    tooltip.append(title, state, details);
    const rect = viewport.getBoundingClientRect();
    const x = event.clientX - rect.left;
    const y = event.clientY - rect.top;
    tooltip.hidden = false;
    // Keep the tooltip inside the view: flip to the left/top near the right/bottom edge.
    const left = x + 14 + tooltip.offsetWidth > rect.width ? x - 14 - tooltip.offsetWidth : x + 14;
    const top = y + 14 + tooltip.offsetHeight > rect.height ? y - 14 - tooltip.offsetHeight : y + 14;
    tooltip.style.left = `${Math.max(0, left)}px`;
    tooltip.style.top = `${Math.max(0, top)}px`;
  }

  function hide() {
    tooltip.hidden = true;
    canvas.classList.remove('over-path');
    paths.highlight(-1);
  }

  let hoverEvent = null; // the latest pointer move, handled once per frame
  function handleHover() {
    const event = hoverEvent;
    hoverEvent = null;
    if (!event || !paths.shown || !active()) return;
    aimAt(event);
    const i = pickPath();
    if (i < 0) {
      hide();
      return;
    }
    paths.highlight(i);
    showTooltip(i, event);
    canvas.classList.add('over-path');
  }
  canvas.addEventListener('pointermove', (event) => {
    if (event.buttons !== 0) return; // orbiting
    if (!hoverEvent) requestAnimationFrame(handleHover);
    hoverEvent = event;
  });
  canvas.addEventListener('pointerleave', () => {
    hoverEvent = null;
    hide();
  });

  let pressed = null;
  canvas.addEventListener('pointerdown', (event) => {
    pressed = event.button === 0 ? { x: event.clientX, y: event.clientY } : null;
  });
  canvas.addEventListener('pointerup', (event) => {
    if (!pressed || event.button !== 0) return;
    const moved = Math.hypot(event.clientX - pressed.x, event.clientY - pressed.y);
    pressed = null;
    if (moved > 4 || !active()) return;
    aimAt(event);
    const picked = pickSurface();
    if (!picked) return;
    onPick({ point: picked.point, position: picked.hit.point.clone() }, event.shiftKey);
  });

  return {
    /** Hides the tooltip and the highlight (the paths change or the pointer left). */
    hide,
  };
}
