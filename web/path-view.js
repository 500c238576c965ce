// The straightest paths in the 3D view: the path lines (fat and pickable, or plain for many paths),
// on a closed surface the other arc of each section (dimmed), the source and added-destination
// markers, the base plane disc at the source, and the hovered path's highlight with its cutting
// plane. It draws the worker's 'paths' reply as it is.

import * as THREE from 'three';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { plainPathGeometry } from './plain-lines.js';
import { nextTask } from './slices.js';

const PATH_COLOR = 0x1f4fb8; // reached paths
const OTHER_ARC_COLOR = 0x7f9bd6; // closed surfaces: the other, longer way round the section (dimmed)
const FAILED_COLOR = 0xe5484d; // partial paths of failed traces (dashed)
const HIGHLIGHT_COLOR = 0x19d3f0; // the hovered path and its cutting plane
const FAILED_HIGHLIGHT_COLOR = 0xff9a8f; // the hovered path when its trace failed
const SOURCE_COLOR = 0xffffff;
const ADDED_COLOR = 0xc15cff; // destinations added with shift+click
const BASE_PLANE_COLOR = 0x9cc2ff;

// Above this many path segments the paths are plain 1-pixel LineSegments over some of the worker's
// points (plain-lines.js; fat lines take a quad and 6 floats per segment) and hovering them is off
// (picking would walk every segment and the surface on each pointer move).
const FAT_LINE_SEGMENTS = 100_000;

// Thin, slightly transparent lines: up to a few hundred paths meet at the source.
const reachedMaterial = new LineMaterial({
  color: PATH_COLOR,
  linewidth: 1,
  transparent: true,
  opacity: 0.75,
});
const failedMaterial = new LineMaterial({ color: FAILED_COLOR, linewidth: 1.8, dashed: true });
const otherArcMaterial = new LineMaterial({
  color: OTHER_ARC_COLOR,
  linewidth: 1.5,
  transparent: true,
  opacity: 0.55,
  dashed: true,
});
const highlightMaterial = new LineMaterial({ color: HIGHLIGHT_COLOR, linewidth: 4.5 });
const sourceMaterial = new THREE.MeshStandardMaterial({
  color: SOURCE_COLOR,
  emissive: 0x555555,
  roughness: 0.4,
});
const addedMaterial = new THREE.MeshStandardMaterial({
  color: ADDED_COLOR,
  emissive: 0x3a1050,
  roughness: 0.4,
});
const basePlaneMaterial = new THREE.MeshBasicMaterial({
  color: BASE_PLANE_COLOR,
  transparent: true,
  opacity: 0.1,
  side: THREE.DoubleSide,
  depthWrite: false,
});
const basePlaneRimMaterial = new THREE.LineBasicMaterial({
  color: BASE_PLANE_COLOR,
  transparent: true,
  opacity: 0.45,
  depthWrite: false,
});
const cutPlaneMaterial = new THREE.MeshBasicMaterial({
  color: HIGHLIGHT_COLOR,
  transparent: true,
  opacity: 0.16,
  side: THREE.DoubleSide,
  depthWrite: false,
});
const cutPlaneRimMaterial = new THREE.LineBasicMaterial({
  color: HIGHLIGHT_COLOR,
  transparent: true,
  opacity: 0.6,
  depthWrite: false,
});
const markerGeometry = new THREE.SphereGeometry(1, 24, 16); // scaled per marker
// The plain-line fallback for many paths (see FAT_LINE_SEGMENTS): 1 pixel, failed paths solid red;
// lighter than the fat lines, as thousands of them cover the surface.
// They write no depth: where thousands of translucent lines meet, a line drawn first would otherwise
// hide the later ones behind it by a hair (the same surface), and one side of the source would show a
// single faint line per pixel where the other shows them all.
const plainReachedMaterial = new THREE.LineBasicMaterial({
  color: PATH_COLOR,
  transparent: true,
  opacity: 0.4,
  depthWrite: false,
});
const plainFailedMaterial = new THREE.LineBasicMaterial({ color: FAILED_COLOR });

/** Removes and frees everything in `group` (shared materials and the marker geometry stay). */
function clearGroup(group) {
  for (const child of [...group.children]) {
    group.remove(child);
    child.traverse((node) => {
      if (node.geometry && node.geometry !== markerGeometry) node.geometry.dispose();
    });
  }
}

function marker(position, material, radius) {
  const sphere = new THREE.Mesh(markerGeometry, material);
  sphere.position.copy(position);
  sphere.scale.setScalar(radius);
  sphere.renderOrder = 2;
  return sphere;
}

/** Number of segments of the listed paths. */
function segmentCount({ offsets }, paths) {
  let count = 0;
  for (const i of paths) count += Math.max(0, offsets[i + 1] - offsets[i] - 1);
  return count;
}

/** The indices of the paths of `reply` that reached their destination, and of those that did not. */
function byStatus(reply) {
  const reached = [];
  const failed = [];
  reply.statuses.forEach((status, i) => (status === 'reached' ? reached : failed).push(i));
  return { reached, failed };
}

/**
 * One LineSegments2 holding every segment of the listed paths, and for each segment the path it
 * belongs to (userData.owner: to name the path under the cursor).
 */
function pathLines(reply, paths, material) {
  const { points, offsets } = reply;
  const count = segmentCount(reply, paths);
  if (count === 0) return null;
  const segments = new Float32Array(6 * count);
  const owner = new Uint32Array(count);
  let s = 0;
  for (const i of paths) {
    for (let j = offsets[i]; j + 1 < offsets[i + 1]; j++, s++) {
      segments.set(points.subarray(3 * j, 3 * j + 6), 6 * s);
      owner[s] = i;
    }
  }
  const geometry = new LineSegmentsGeometry().setPositions(segments);
  const lines = new LineSegments2(geometry, material);
  if (material.dashed) lines.computeLineDistances();
  lines.userData.owner = owner;
  lines.renderOrder = 1;
  return lines;
}

/** A translucent quad at `origin` with edges along unit vectors u, v over [u0,u1]×[v0,v1], plus its rim. */
function planeQuad(origin, u, v, [u0, u1], [v0, v1], fill, rim) {
  const corners = [
    [u0, v0],
    [u1, v0],
    [u1, v1],
    [u0, v1],
  ].map(([a, b]) => origin.clone().addScaledVector(u, a).addScaledVector(v, b));
  const geometry = new THREE.BufferGeometry().setFromPoints(corners);
  geometry.setIndex([0, 1, 2, 0, 2, 3]);
  const group = new THREE.Group();
  const quad = new THREE.Mesh(geometry, fill);
  const outline = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(corners), rim);
  quad.renderOrder = outline.renderOrder = 3;
  group.add(quad, outline);
  return group;
}

/** The base plane at the source: a translucent disc of `radius` perpendicular to the base normal. */
function basePlaneDisc(origin, normal, radius) {
  const group = new THREE.Group();
  const disc = new THREE.Mesh(new THREE.CircleGeometry(radius, 96), basePlaneMaterial);
  const rimPoints = new THREE.EllipseCurve(0, 0, radius, radius)
    .getPoints(96)
    .map((p) => new THREE.Vector3(p.x, p.y, 0));
  const rim = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(rimPoints), basePlaneRimMaterial);
  disc.renderOrder = rim.renderOrder = 3;
  group.add(disc, rim);
  group.position.copy(origin);
  group.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
  return group;
}

/**
 * view: the 3D view (scene.js). onClear(): the drawn paths are about to go (hovering ends).
 */
export function createPathView(view, { onClear = () => {} } = {}) {
  const group = new THREE.Group(); // everything drawn for the current paths; rebuilt per trace
  view.scene.add(group);
  let shown = null; // the reply on display and the objects drawn for it (see show)
  let baseVisible = true;
  // The export panel's path style: shown or not, width (× the default widths), colour of reached paths.
  const style = { visible: true, width: 1, color: PATH_COLOR };
  const widths = new Map([reachedMaterial, failedMaterial, otherArcMaterial].map((m) => [m, m.linewidth]));

  /** Applies `style` to the materials and to the path lines on display. */
  function applyStyle() {
    for (const [material, width] of widths) material.linewidth = width * style.width;
    reachedMaterial.color.set(style.color);
    plainReachedMaterial.color.set(style.color);
    if (shown) {
      for (const line of shown.drawnLines) line.visible = style.visible;
      shown.lines = style.visible ? shown.pickableLines : []; // hidden paths are not hovered either
    }
    view.requestRender();
  }

  /**
   * Builds the plain-line shaders while the GPU is idle: a program's first use waits for the GPU to
   * finish its queued work, which with a software renderer can be a large mesh's frame of seconds.
   */
  function prewarmPlainLines() {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
    geometry.setIndex([0, 1]);
    const warm = new THREE.Scene();
    warm.add(
      new THREE.LineSegments(geometry, plainReachedMaterial),
      new THREE.LineSegments(geometry, plainFailedMaterial),
    );
    view.renderer.render(warm, view.camera);
    geometry.dispose();
    view.requestRender(); // the real scene replaces the warm-up frame
  }
  prewarmPlainLines();

  function clear() {
    onClear();
    shown?.upload?.dispose(); // (the plain lines' buffers, drawn or still on their way)
    clearGroup(group);
    shown = null;
  }

  /**
   * What show() draws of a 'paths' reply that takes a while to build, built in slices: the plain
   * lines' geometry (plain-lines.js) when there are too many segments for fat lines, else null.
   * Rejects (stops building) once stale() is true.
   */
  async function prepare(reply, stale = () => false) {
    if (segmentCount(reply, reply.statuses.keys()) <= FAT_LINE_SEGMENTS) return null;
    const { reached, failed } = byStatus(reply);
    const pause = async () => {
      await nextTask();
      if (stale()) throw new Error('a newer trace took over');
    };
    const groups = [
      [reached, plainReachedMaterial],
      [failed, plainFailedMaterial],
    ];
    return { plain: await plainPathGeometry(reply, groups, pause) };
  }

  /**
   * Replaces the drawn paths, markers and base plane by a 'paths' reply; added: positions of the
   * added destinations; prepared: prepare(reply)'s result.
   */
  function show(reply, added, prepared) {
    clear();
    const scale = view.scale;
    const source = new THREE.Vector3(...reply.sourcePosition);
    const normal = new THREE.Vector3(...reply.normal).normalize();
    const { reached, failed } = byStatus(reply);

    failedMaterial.dashSize = otherArcMaterial.dashSize = 0.012 * scale;
    failedMaterial.gapSize = otherArcMaterial.gapSize = 0.008 * scale;
    let lines;
    let stride = 1;
    let upload = null; // the plain lines' buffers, filled a slice per frame (gpu-upload.js)
    const built = prepared?.plain ?? null;
    const plain = built !== null;
    if (plain) {
      stride = built.stride;
      upload = view.gpu.upload(built.geometry);
      const object = new THREE.LineSegments(upload.geometry, built.materials);
      object.renderOrder = 1;
      lines = built.materials.length ? [object] : [];
    } else {
      lines = [pathLines(reply, reached, reachedMaterial), pathLines(reply, failed, failedMaterial)].filter(Boolean);
    }
    // Closed surfaces: the other arc of every section that closes through its destination (not with
    // plain lines: so many paths come only from boundaries, which a closed surface has none of).
    const withOtherArc = [];
    reply.otherArcLengths?.forEach((length, i) => Number.isFinite(length) && withOtherArc.push(i));
    const otherArcs =
      plain || !withOtherArc.length
        ? null
        : pathLines({ points: reply.otherPoints, offsets: reply.otherOffsets }, withOtherArc, otherArcMaterial);
    if (otherArcs) group.add(otherArcs);
    const basePlane = basePlaneDisc(source, normal, 0.42 * scale);
    basePlane.visible = baseVisible;
    const highlight = new Line2(new LineGeometry(), highlightMaterial);
    highlight.visible = false;
    highlight.renderOrder = 2;
    const cutPlane = new THREE.Group();
    const waiting = upload !== null && !upload.ready; // the plain lines join once on the GPU
    group.add(...(waiting ? [] : lines), basePlane, highlight, cutPlane, marker(source, sourceMaterial, 0.011 * scale));
    for (const position of added) group.add(marker(position, addedMaterial, 0.008 * scale));
    // Plain lines have no picking data; so many paths lie on a large mesh whose surface would be
    // ray cast on every pointer move.
    const pickable = plain ? [] : lines;
    shown = {
      drawnLines: [...lines, otherArcs].filter(Boolean),
      pickableLines: pickable,
      reply,
      source,
      normal,
      lines: pickable,
      plain,
      stride,
      basePlane,
      highlight,
      cutPlane,
      hovered: -1,
      otherArcs: otherArcs ? withOtherArc.length : 0,
      upload,
    };
    if (waiting) {
      const current = shown;
      upload.done.then((uploaded) => {
        if (!uploaded || shown !== current) return;
        group.add(...lines);
        view.requestRender();
      });
    }
    applyStyle();
  }

  /**
   * Highlights path i (or nothing for -1) and draws its cutting plane: the plane through the source
   * spanned by the base normal and the path's in-plane direction, as a quad covering the path.
   */
  function highlight(i) {
    if (!shown || shown.hovered === i) return;
    const { reply, source, normal, highlight: line, cutPlane } = shown;
    shown.hovered = i;
    clearGroup(cutPlane);
    line.visible = false;
    view.requestRender();
    if (i < 0) return;

    const path = reply.points.subarray(3 * reply.offsets[i], 3 * reply.offsets[i + 1]);
    if (path.length >= 6) {
      line.geometry.dispose();
      line.geometry = new LineGeometry().setPositions(path);
      highlightMaterial.color.set(reply.statuses[i] === 'reached' ? HIGHLIGHT_COLOR : FAILED_HIGHLIGHT_COLOR);
      line.visible = true;
    }
    const along = new THREE.Vector3().fromArray(reply.directions, 3 * i);
    if (!Number.isFinite(along.x)) return; // the destination lies along the normal: no plane to draw
    // Extent of the quad: the path and its destination in the (along, n) coordinates of the plane,
    // plus a margin.
    const uRange = [0, 0];
    const vRange = [0, 0];
    const extend = (p) => {
      const d = p.clone().sub(source);
      const [a, b] = [d.dot(along), d.dot(normal)];
      uRange[0] = Math.min(uRange[0], a);
      uRange[1] = Math.max(uRange[1], a);
      vRange[0] = Math.min(vRange[0], b);
      vRange[1] = Math.max(vRange[1], b);
    };
    const target = reply.targetPositions.subarray(3 * i, 3 * i + 3);
    if (Number.isFinite(target[0])) extend(new THREE.Vector3(...target));
    const p = new THREE.Vector3();
    for (let j = 0; j < path.length; j += 3) extend(p.set(path[j], path[j + 1], path[j + 2]));
    if (reply.otherOffsets) {
      // the quad covers the whole section on a closed surface
      const other = reply.otherPoints.subarray(3 * reply.otherOffsets[i], 3 * reply.otherOffsets[i + 1]);
      for (let j = 0; j < other.length; j += 3) extend(p.set(other[j], other[j + 1], other[j + 2]));
    }
    const margin = 0.04 * view.scale;
    uRange[0] -= margin;
    uRange[1] += margin;
    vRange[0] -= margin;
    vRange[1] += margin;
    cutPlane.add(planeQuad(source, along, normal, uRange, vRange, cutPlaneMaterial, cutPlaneRimMaterial));
  }

  return {
    prepare,
    show,
    clear,
    highlight,
    /**
     * The reply on display and what was drawn for it: { reply, lines (pickable), plain, stride,
     * otherArcs (the number of other arcs drawn), … }, or null.
     */
    get shown() {
      return shown;
    },
    /** The paths' look: { visible, width (a factor of the default widths), color } (each optional). */
    setStyle(changes) {
      Object.assign(style, changes);
      applyStyle();
    },
    setBaseVisible(visible) {
      baseVisible = visible;
      if (shown) shown.basePlane.visible = visible;
      view.requestRender();
    },
  };
}
