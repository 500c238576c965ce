// The parameterization on the 3D surface: its texture (the checkerboard or the user's image) and the
// seam a cut mesh was opened along, drawn as lines. param-view.js decides what is on display; this
// module owns the three.js objects that show it. A cut mesh's texture goes on a seam-split twin of the
// surface (surface-view.js), made here from the arrays the page already holds.

import * as THREE from 'three';
import { toSeamSplitGeometry } from 'straightest/three';
import { SEAM_COLOR, checkerboardCanvas, surfaceTexture } from './uv-layout.js';

const $ = (id) => document.getElementById(id);

/** view: scene.js; surface: surface-view.js; showNote(text, kind): the parameterization panel's note. */
export function createParamTexture({ view, surface, showNote }) {
  const maxAnisotropy = view.renderer.capabilities.getMaxAnisotropy();
  let checkerTexture = null; // made when first shown
  let checkerCells = 16; // squares per side of the checkerboard (the export panel's density)
  let imageTexture = null; // the user's image, once loaded
  let split = null; // the seam-split twin of a cut mesh on display, or null
  let hasUv = false; // a parameterization is on display

  const configureTexture = (texture) => surfaceTexture(texture, maxAnisotropy);

  /** The map of the surface: null without a uv on the mesh or with texture 'none'. */
  function texture() {
    if (!hasUv) return null;
    const choice = $('texture-select').value;
    if (choice === 'checker') {
      checkerTexture ??= configureTexture(new THREE.CanvasTexture(checkerboardCanvas(1024, checkerCells)));
      return checkerTexture;
    }
    if (choice === 'image') return imageTexture;
    return null;
  }

  function update() {
    surface.setTexture(texture(), split);
  }

  async function loadImage(file) {
    const url = URL.createObjectURL(file);
    try {
      const loaded = await new THREE.TextureLoader().loadAsync(url);
      configureTexture(loaded);
      imageTexture?.dispose();
      imageTexture = loaded;
      const option = $('texture-select').querySelector('option[value="image"]');
      option.disabled = false;
      option.textContent = `Image: ${file.name}`;
      $('texture-select').value = 'image';
      showNote('');
      update();
    } catch {
      showNote(`“${file.name}” is not an image the browser can read.`);
    } finally {
      URL.revokeObjectURL(url);
    }
  }

  // ---------------------------------------------------------------- the seam on the surface

  const seamMaterial = new THREE.LineBasicMaterial({ color: SEAM_COLOR, depthTest: true });
  let seamLines = null; // THREE.LineSegments of the seam on display

  function showSeam(seam) {
    hideSeam();
    const geometry = surface.mesh?.geometry;
    if (!geometry || !seam?.length) return;
    const position = geometry.getAttribute('position');
    const points = new Float32Array(3 * seam.length);
    seam.forEach((v, i) => {
      points[3 * i] = position.getX(v);
      points[3 * i + 1] = position.getY(v);
      points[3 * i + 2] = position.getZ(v);
    });
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', new THREE.BufferAttribute(points, 3));
    seamLines = new THREE.LineSegments(lines, seamMaterial);
    seamLines.renderOrder = 2; // over the surface, whose polygon offset pushes it back
    view.scene.add(seamLines);
    view.requestRender();
  }

  function hideSeam() {
    if (!seamLines) return;
    view.scene.remove(seamLines);
    seamLines.geometry.dispose();
    seamLines = null;
    view.requestRender();
  }

  /**
   * A cut mesh's texture geometry: its surface split along the seam, one vertex per mesh vertex and
   * corner uv (the arrays the page already holds stand in for the core's mesh).
   */
  function splitGeometry(reply) {
    const geometry = surface.mesh.geometry;
    return toSeamSplitGeometry(
      {
        positions: () => geometry.getAttribute('position').array,
        vertexNormals: () => geometry.getAttribute('normal').array,
        indices: () => geometry.index.array,
      },
      reply,
    );
  }

  $('texture-select').addEventListener('change', () => update());
  $('texture-input').addEventListener('change', (event) => {
    const [file] = event.target.files;
    if (file) loadImage(file);
    event.target.value = '';
  });

  return {
    /**
     * A parameterization's reply goes on the surface (its seam drawn, a cut mesh split along it), or
     * none (null). Returns the split twin (null for a disk), which the GLB export takes.
     */
    show(reply) {
      hasUv = reply !== null;
      split = reply && reply.cut !== 'disk' ? splitGeometry(reply) : null;
      if (reply) showSeam(reply.seam);
      else hideSeam();
      return split;
    },
    update,
    get checkerCells() {
      return checkerCells;
    },
    /** The checkerboard's squares per side (the texture on the mesh is made again). */
    setCheckerCells(cells) {
      checkerCells = cells;
      checkerTexture?.dispose();
      checkerTexture = null;
      update();
    },
  };
}
