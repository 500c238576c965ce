// The mesh on display: its surface and wireframe overlay and what colours the surface — the
// heat-distance vertex colours, else the parameterization's texture, else the plain mesh colour. Other
// views set those through setColors() and setTexture().
//
// The surface (`mesh`) holds the mesh's arrays — picking, the exports and the other views read them —
// and draws nothing itself (ARRAYS_LAYER): its child `drawn` does, a twin whose GPU buffers gpu-upload.js fills a
// slice per frame (a large mesh appears a few frames after it loaded, and its colours or uv after they
// were set, the main thread never blocked by the copy). The wireframe overlay draws the arrays directly.
//
// A cut mesh's texture (its uv differ on the two sides of the seam) is drawn on a seam-split twin of
// the surface (one vertex per mesh vertex and corner uv, from the parameterization view): also a child
// of the surface, so whatever hides the surface hides it too, while `drawn` is hidden meanwhile.

import * as THREE from 'three';

const MESH_COLOR = 0xd9b982;
const WIRE_COLOR = 0x1d2430;
const MIRRORED = ['uv', 'color']; // the attributes other views set on the surface, copied to `drawn`
// The surface's own layer, which no camera draws: three.js uploads the geometry of every mesh on a
// drawn layer, even one whose material is invisible. Its children (on layer 0) are drawn; ray casts
// that want the surface enable this layer (picking.js).
export const ARRAYS_LAYER = 31;

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

  const { gpu } = view;
  let surface = null; // THREE.Mesh of the current geometry (its arrays; draws nothing)
  let drawn = null; // { mesh, upload, mirrored: Map(name → { source, handle }) }: what draws it
  let wireframe = null; // overlay sharing the surface's geometry
  let wireframeVisible = false;
  let colored = false; // vertex colours were set (they show once on the GPU)
  let texture = null; // the map the parameterization view asks for (used without vertex colours)
  let twin = null; // the seam-split textured twin of a cut mesh (a child of the surface), or null
  // The surface's own material: never drawn, but ray casts read its side.
  const nothing = new THREE.MeshBasicMaterial({ visible: false, side: THREE.DoubleSide });

  /** Whether `drawn` has the attribute `name` on the GPU. */
  const onGpu = (name) => drawn?.mesh.geometry.getAttribute(name) !== undefined;

  /** Sets the material from what colours the surface (see the opening comment). */
  function updateMaterial() {
    const withColors = colored && onGpu('color');
    if (material.vertexColors !== withColors) {
      material.vertexColors = withColors;
      material.needsUpdate = true;
    }
    const map = withColors ? null : texture;
    const twinDraws = twin !== null && map !== null;
    const shownMap = twinDraws || onGpu('uv') ? map : null; // a disk's map waits for its uv
    if (material.map !== shownMap) {
      material.map = shownMap;
      material.needsUpdate = true;
    }
    material.color.set(withColors || shownMap ? 0xffffff : MESH_COLOR);
    if (twin) twin.visible = twinDraws;
    if (drawn) drawn.mesh.visible = !twinDraws;
    view.requestRender();
  }

  /** Copies the surface's uv and colours to `drawn` (they change on the surface's geometry). */
  function mirror() {
    if (!drawn) return;
    const { mesh, mirrored } = drawn;
    for (const name of MIRRORED) {
      const source = surface.geometry.getAttribute(name) ?? null;
      const copy = mirrored.get(name);
      if ((copy?.source ?? null) === source) continue;
      if (copy) {
        mesh.geometry.deleteAttribute(name);
        copy.handle.dispose();
        mirrored.delete(name);
      }
      if (!source) continue;
      const handle = gpu.uploadAttribute(source);
      mirrored.set(name, { source, handle });
      const place = () => {
        if (drawn?.mirrored.get(name)?.handle !== handle) return; // replaced or dropped meanwhile
        mesh.geometry.setAttribute(name, handle.attribute);
        updateMaterial();
      };
      if (handle.ready) mesh.geometry.setAttribute(name, handle.attribute);
      else handle.done.then((uploaded) => uploaded && place());
    }
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
    for (const { handle } of drawn.mirrored.values()) handle.dispose();
    drawn.upload.dispose();
    drawn = null;
    view.scene.remove(surface, wireframe);
    surface.geometry.dispose();
    surface = wireframe = null;
  }

  /** Per-vertex colours (linear RGB floats) over the texture, or null for none. */
  function setColors(colors) {
    if (!colors && !colored) return; // nothing to drop (and no material rebuild)
    if (colors) {
      surface?.geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    } else {
      surface?.geometry.deleteAttribute('color');
    }
    colored = colors !== null;
    mirror();
    updateMaterial();
  }

  /** The surface of the arrays and the twin that draws it (once its buffers are on the GPU). */
  function build(positions, indices, normals, bbox) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
    geometry.setIndex(new THREE.BufferAttribute(indices, 1));
    if (bbox) {
      // The bounds from the mesh's box: computing them walks every vertex on the main thread.
      geometry.boundingBox = new THREE.Box3(new THREE.Vector3(...bbox.min), new THREE.Vector3(...bbox.max));
      geometry.boundingSphere = geometry.boundingBox.getBoundingSphere(new THREE.Sphere());
    }
    surface = new THREE.Mesh(geometry, nothing);
    surface.layers.set(ARRAYS_LAYER);
    wireframe = new THREE.Mesh(geometry, wireMaterial);
    wireframe.visible = wireframeVisible;
    const upload = gpu.upload(geometry, ['position', 'normal']);
    const mesh = new THREE.Mesh(upload.geometry, material);
    mesh.raycast = () => {}; // picking reads the surface's own faces
    drawn = { mesh, upload, mirrored: new Map() };
    const shown = drawn;
    const place = () => {
      if (drawn !== shown) return; // another mesh came meanwhile
      surface.add(mesh);
      updateMaterial();
    };
    if (upload.ready) place();
    else upload.done.then((uploaded) => uploaded && place());
    view.scene.add(surface, wireframe);
  }

  return {
    /** The THREE.Mesh on display (indexed geometry with the mesh's arrays), or null. */
    get mesh() {
      return surface;
    },
    /** Whether vertex colours were set (they may still be on their way to the GPU). */
    get hasColors() {
      return colored;
    },

    /**
     * Replaces the displayed mesh by the worker's arrays (the vertex colours are dropped); bbox: the
     * mesh's { min, max } (its bounds, not computed again), or null.
     */
    show(positions, indices, normals, bbox = null) {
      remove();
      if (colored) setColors(null);
      build(positions, indices, normals, bbox);
    },

    /** Nothing on display. */
    remove() {
      if (colored) setColors(null);
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
      mirror();
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
