// The per-face stretch heat map on the 3D mesh. Per-face colours need a copy of the mesh without
// shared corners: a non-indexed geometry with the surface's positions and normals and one colour per
// face. It replaces the surface while the heat map is on (the surface stays pickable: ray casts
// ignore visibility). Normals and colours are stored as normalized integers (a 1M-vertex mesh's
// copy is ~110 MB instead of ~220 MB), and a large mesh is copied in slices of STRETCH_SLICE_FACES
// faces, one task each, so the page stays responsive meanwhile.

import * as THREE from 'three';
import { STRETCH_INFINITE, stretchGradient, stretchIndex, stretchTable } from './colormap.js';
import { latest } from './latest.js';

const $ = (id) => document.getElementById(id);

const STRETCH_SLICE_FACES = 200_000;

/** view: scene.js; surface: surface-view.js; onError(err): building the copy failed. */
export function createStretchView({ view, surface, onError }) {
  const material = new THREE.MeshStandardMaterial({
    vertexColors: true,
    roughness: 0.8,
    metalness: 0,
    side: THREE.DoubleSide,
    polygonOffset: true, // as the surface: the wireframe and the paths stay on top
    polygonOffsetFactor: 1.5,
    polygonOffsetUnits: 2,
  });
  let faceStretch = null; // the stretch per face of the parameterization on display
  let wanted = false; // the heat map should show (the toggle)
  let copy = null; // the heat-map copy of the surface, once built
  const builds = latest(); // a copy still being built is dropped when the data changes
  let building = false; // a large mesh's copy is being built, slice by slice

  $('stretch-legend').querySelector('.ramp').style.background = stretchGradient();
  $('stretch-legend').querySelector('.infinite').style.background = `rgb(${STRETCH_INFINITE.join(',')})`;

  /** Builds the heat-map copy of the surface (in slices when large), then shows it if still wanted. */
  async function build() {
    const current = builds.begin();
    let sliced = false;
    const mesh = surface.mesh;
    const { index, attributes } = mesh.geometry;
    if (!attributes.normal) mesh.geometry.computeVertexNormals();
    const corners = index.array;
    const position = attributes.position.array;
    const normal = attributes.normal.array;
    const faces = corners.length / 3;
    const positions = new Float32Array(9 * faces);
    const normals = new Int16Array(9 * faces);
    const colors = new Uint8Array(9 * faces);
    const table = stretchTable('linear');
    const stretch = faceStretch;
    for (let slice = 0; slice < faces; slice += STRETCH_SLICE_FACES) {
      if (slice > 0) {
        sliced = building = true;
        await new Promise((resolve) => setTimeout(resolve)); // let the page breathe between slices
        if (current.stale()) return; // the mesh or the parameterization changed
      }
      const end = Math.min(faces, slice + STRETCH_SLICE_FACES);
      for (let f = slice; f < end; f++) {
        const t = stretchIndex(stretch[f]);
        for (let k = 0; k < 3; k++) {
          const v = corners[3 * f + k];
          const to = 9 * f + 3 * k;
          for (let c = 0; c < 3; c++) {
            positions[to + c] = position[3 * v + c];
            normals[to + c] = Math.round(32767 * Math.min(Math.max(normal[3 * v + c], -1), 1));
            colors[to + c] = table[3 * t + c];
          }
        }
      }
    }
    if (sliced) {
      await view.gpuIdle(); // its upload (~110 MB for 1M vertices) must not queue behind slow frames
      if (current.stale()) return;
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3, true));
    geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3, true));
    copy = new THREE.Mesh(geometry, material);
    view.scene.add(copy);
    building = false;
    if (sliced) apply();
  }

  function removeCopy() {
    builds.supersede();
    building = false;
    if (!copy) return;
    view.scene.remove(copy);
    copy.geometry.dispose();
    copy = null;
  }

  /**
   * Shows the heat map or the (textured) surface. A large mesh's heat map comes a moment later (its
   * copy is built in slices; the surface stays until then).
   */
  function apply() {
    const mesh = surface.mesh;
    let heat = wanted && faceStretch !== null && mesh !== null;
    if (heat && !copy) {
      if (!building) {
        // Synchronous for a small mesh (one slice); a large one shows when its last slice is done.
        build().catch((err) => {
          building = false;
          onError(err);
        });
      }
      heat = copy !== null;
    }
    if (copy) copy.visible = heat;
    if (mesh) mesh.visible = !heat;
    material.flatShading = $('flat-toggle').checked;
    material.needsUpdate = true;
    $('stretch-legend').hidden = !heat;
    view.requestRender();
  }

  return {
    /** The stretch per face of the parameterization on display (null: none); shown if wanted. */
    setStretch(stretch) {
      removeCopy(); // rebuilt from the new stretch if the heat map is on
      faceStretch = stretch;
    },
    /** Shows the heat map (if there is a stretch) or the surface. */
    show(on) {
      wanted = on;
      apply();
    },
  };
}
