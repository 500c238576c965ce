// The mesh on display: its surface and wireframe overlay (one shared geometry) and what colours the
// surface — the heat-distance vertex colours, else the parameterization's texture, else the plain
// mesh colour. Other views set those through setColors() and setTexture().

import * as THREE from 'three';

const MESH_COLOR = 0xd9b982;
const WIRE_COLOR = 0x1d2430;

export function createSurfaceView(view) {
  const material = new THREE.MeshStandardMaterial({
    color: MESH_COLOR,
    roughness: 0.75,
    metalness: 0.0,
    side: THREE.DoubleSide,
    polygonOffset: true, // keeps the wireframe overlay and the paths (which lie on the faces) on top
    polygonOffsetFactor: 1.5,
    polygonOffsetUnits: 2,
  });
  const wireMaterial = new THREE.MeshBasicMaterial({
    color: WIRE_COLOR,
    wireframe: true,
    transparent: true,
    opacity: 0.55,
  });

  let surface = null; // THREE.Mesh of the current geometry
  let wireframe = null; // overlay sharing the same geometry
  let wireframeVisible = false;
  let texture = null; // the map the parameterization view asks for (used without vertex colours)

  /** Sets the material from what colours the surface (see the opening comment). */
  function updateMaterial() {
    const map = material.vertexColors ? null : texture;
    if (material.map !== map) {
      material.map = map;
      material.needsUpdate = true;
    }
    material.color.set(material.vertexColors || map ? 0xffffff : MESH_COLOR);
    view.requestRender();
  }

  function remove() {
    if (!surface) return;
    view.scene.remove(surface, wireframe);
    surface.geometry.dispose();
    surface = wireframe = null;
  }

  /** Per-vertex colours (linear RGB floats) over the texture, or null for none. */
  function setColors(colors) {
    if (!colors && !material.vertexColors) return; // nothing to drop (and no material rebuild)
    if (colors) {
      surface?.geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    } else {
      surface?.geometry.deleteAttribute('color');
    }
    material.vertexColors = colors !== null;
    material.needsUpdate = true;
    updateMaterial();
  }

  return {
    /** The THREE.Mesh on display (indexed geometry), or null. */
    get mesh() {
      return surface;
    },
    get hasColors() {
      return material.vertexColors;
    },

    /** Replaces the displayed mesh by the worker's arrays (the vertex colours are dropped). */
    show(positions, indices, normals) {
      remove();
      if (material.vertexColors) setColors(null);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
      geometry.setIndex(new THREE.BufferAttribute(indices, 1));
      geometry.computeBoundingSphere();
      surface = new THREE.Mesh(geometry, material);
      wireframe = new THREE.Mesh(geometry, wireMaterial);
      wireframe.visible = wireframeVisible;
      view.scene.add(surface, wireframe);
    },

    /** Nothing on display. */
    remove() {
      if (material.vertexColors) setColors(null);
      remove();
      view.requestRender();
    },

    setColors,

    /** The parameterization's map (null for none); shown unless vertex colours are set. */
    setTexture(map) {
      texture = map;
      updateMaterial();
    },

    setWireframe(visible) {
      wireframeVisible = visible;
      if (wireframe) wireframe.visible = visible;
      view.requestRender();
    },

    setFlatShading(flat) {
      material.flatShading = flat;
      material.needsUpdate = true;
      view.requestRender();
    },
  };
}
