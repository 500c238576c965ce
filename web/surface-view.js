// The mesh on display: its surface and wireframe overlay (one shared geometry) and what colours the
// surface — the heat-distance vertex colours, else the parameterization's texture, else the plain
// mesh colour. Other views set those through setColors() and setTexture().
//
// A cut mesh's texture (its uv differ on the two sides of the seam) is drawn on a seam-split twin of
// the surface (one vertex per mesh vertex and corner uv, from the parameterization view): a child of
// the surface, so whatever hides the surface hides it too, while the surface itself keeps its indexed
// geometry (picking, vertex colours, the wireframe) and draws nothing meanwhile.

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
  let twin = null; // the seam-split textured twin of a cut mesh (a child of the surface), or null
  const nothing = new THREE.MeshBasicMaterial({ visible: false }); // the surface's while the twin draws

  /** Sets the material from what colours the surface (see the opening comment). */
  function updateMaterial() {
    const map = material.vertexColors ? null : texture;
    if (material.map !== map) {
      material.map = map;
      material.needsUpdate = true;
    }
    material.color.set(material.vertexColors || map ? 0xffffff : MESH_COLOR);
    const twinDraws = twin !== null && map !== null;
    if (twin) twin.visible = twinDraws;
    if (surface) surface.material = twinDraws ? nothing : material; // ray casts still hit the surface
    view.requestRender();
  }

  function removeTwin() {
    if (!twin) return;
    twin.removeFromParent();
    twin.geometry.dispose();
    twin = null;
  }

  function remove() {
    removeTwin();
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

    /**
     * The parameterization's map (null for none); shown unless vertex colours are set. splitGeometry:
     * a cut mesh's seam-split geometry carrying the uv (null: the surface's own uv attribute).
     */
    setTexture(map, splitGeometry = null) {
      texture = map;
      if (splitGeometry !== twin?.geometry) {
        removeTwin();
        if (splitGeometry && surface) {
          twin = new THREE.Mesh(splitGeometry, material);
          twin.raycast = () => {}; // picking reads the surface's own faces
          surface.add(twin);
        }
      }
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
