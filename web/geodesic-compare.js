// The three geodesics of issue 17 side by side, from the path source to the last added destination
// (snapped to the vertex of its face nearest to the picked point: exact shortest paths end at
// vertices): the cutting-plane straightest path, the Polthier–Schmies straightest geodesic shot
// toward it (an initial value problem: it may miss), and the exact shortest path. Each is drawn in
// its own colour over the paths, with a table of their lengths and the shot's miss distance. What it
// has on display, as plain data, is status() (main.js puts it in the page's observable state as
// geodesics, docs/PAGE.md).

import * as THREE from 'three';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { latest } from './latest.js';
import { isCancelled } from './requests.js';
import { statusWords } from './data-export.js';
import { describePoint } from './panels.js';

const $ = (id) => document.getElementById(id);
/** Six significant digits: the three lengths often agree in the first few. */
const formatNumber = (x) => (Number.isFinite(x) ? String(Number(x.toPrecision(6))) : String(x));

// The colours of the legend (style.css: .swatch.line.geo-*).
const PLANE_COLOR = 0x19d3f0;
const SHOT_COLOR = 0xff9f1c;
const EXACT_COLOR = 0x2ecc71;
const materials = {
  plane: new LineMaterial({ color: PLANE_COLOR, linewidth: 3.5 }),
  shot: new LineMaterial({ color: SHOT_COLOR, linewidth: 3, dashed: true }),
  exact: new LineMaterial({ color: EXACT_COLOR, linewidth: 3 }),
};

/** The picked point's vertex, or the vertex of its face with the largest barycentric coordinate. */
function nearestVertex(surfaceMesh, { vertex, face, bary }) {
  if (vertex !== undefined) return vertex; // typed as a vertex number
  const index = surfaceMesh.geometry.index;
  const k = bary.indexOf(Math.max(...bary));
  return index.getX(3 * face + k);
}

/**
 * session: session.js; view: scene.js; surface: surface-view.js; wanted(): whether the comparison
 * toggle is on.
 */
export function createGeodesicCompare({ session, view, surface, wanted }) {
  const group = new THREE.Group();
  view.scene.add(group);
  const runs = latest();
  let last = null; // { source, destination } of the paths on display
  let compared = null; // the comparison on display, for status()

  function clear() {
    runs.supersede();
    for (const child of [...group.children]) {
      group.remove(child);
      child.geometry.dispose();
    }
    $('geodesic-compare').hidden = true;
    compared = null;
    view.requestRender();
  }

  function line(points, material) {
    if (points.length < 6) return null;
    const object = new Line2(new LineGeometry().setPositions(points), material);
    if (material.dashed) object.computeLineDistances();
    object.renderOrder = 2;
    return object;
  }

  function showTable(reply, vertex) {
    const { exact, plane, shot } = reply;
    $('geo-target').textContent = describePoint(vertex);
    $('geo-plane-length').textContent = formatNumber(plane.length);
    $('geo-plane-note').textContent = statusWords(plane.status);
    $('geo-plane-note').title = plane.status; // the core's code
    // The shot walks a length it is given (the plane path's, or the exact distance when that failed):
    // an input, not a result — shown muted, the miss distance beside it is the result.
    $('geo-shot-length').textContent = formatNumber(shot.length);
    $('geo-shot-length').className = 'muted';
    $('geo-shot-length').title =
      plane.status === 'reached'
        ? 'the length the shot was given: the cutting-plane path’s (equal by construction)'
        : 'the length the shot was given: the exact distance';
    $('geo-shot-note').textContent = `misses by ${formatNumber(shot.missDistance)} (${statusWords(shot.status)})`;
    $('geo-shot-note').title = shot.status;
    $('geo-exact-length').textContent = formatNumber(exact.distance);
    $('geo-exact-note').textContent =
      Number.isFinite(exact.distance) && exact.distance > 0
        ? `plane ÷ exact ${(plane.length / exact.distance).toFixed(4)}`
        : '';
    $('geodesic-compare').hidden = false;
  }

  /** Compares the geodesics from `source` (a SurfacePoint) to `destination` ({ point }) or clears. */
  async function update(source, destination) {
    last = { source, destination };
    clear();
    if (!wanted() || !destination || !surface.mesh) return;
    const vertex = nearestVertex(surface.mesh, destination.point);
    const run = runs.begin(session.meshes);
    try {
      const reply = await session.request('geodesics', { source, target: { vertex } });
      if (run.stale()) return;
      materials.shot.dashSize = 0.012 * view.scale;
      materials.shot.gapSize = 0.006 * view.scale;
      const drawn = [
        line(reply.plane.points, materials.plane),
        line(reply.shot.points, materials.shot),
        line(reply.exact.points, materials.exact),
      ];
      group.add(...drawn.filter(Boolean));
      showTable(reply, vertex);
      compared = {
        target: vertex,
        planeLength: reply.plane.length,
        planeStatus: reply.plane.status,
        shotLength: reply.shot.length,
        shotStatus: reply.shot.status,
        missDistance: reply.shot.missDistance,
        exactLength: reply.exact.distance,
        drawn: { plane: !!drawn[0], shot: !!drawn[1], exact: !!drawn[2] },
      };
      view.requestRender();
    } catch (err) {
      if (run.stale() || isCancelled(err)) return;
      $('geodesic-compare').hidden = false;
      $('geo-target').textContent = `could not compare: ${err.message}`;
    }
  }

  return {
    update,
    clear,
    /** The toggle changed: show the comparison for the paths on display again, or hide it. */
    refresh() {
      if (last) update(last.source, last.destination);
    },
    /**
     * The comparison on display: { target (vertex), planeLength, planeStatus, shotLength, shotStatus,
     * missDistance, exactLength, drawn: { plane, shot, exact } (whether each line was drawn) }, or null.
     */
    status: () => compared,
  };
}
