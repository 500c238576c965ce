// Mesh files the core does not read on the page, through three.js's own loaders and exporter: STL, PLY
// and glTF/GLB in (one BufferGeometry of positions, which requests.js welds into a straightest mesh with
// meshFromBufferGeometry), glTF binary out (the textured surface with its uv). OBJ and OFF go to the
// core as bytes. A glTF scene with several meshes is merged into one, each mesh placed by its world
// transform (the scene as it is drawn); points and lines are left out.
import * as THREE from 'three';
import { STLLoader } from 'three/addons/loaders/STLLoader.js';
import { PLYLoader } from 'three/addons/loaders/PLYLoader.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';

/** The extensions read here (three's loaders), in the file input's accept list with the core's. */
export const THREE_FORMATS = ['.stl', '.ply', '.gltf', '.glb'];

/** An Error a person can read, with the category the page's error display expects. */
function fileError(message) {
  return Object.assign(new Error(message), { category: 'unsupported_format' });
}

/** The format three reads this file name in, or null when the core reads it (OBJ, OFF, anything else). */
export function threeFormatOf(name) {
  const extension = /\.[^.]+$/.exec(String(name).toLowerCase())?.[0];
  return THREE_FORMATS.includes(extension) ? extension.slice(1) : null;
}

/**
 * The file's triangles as one BufferGeometry (position, index), with a note on what was merged or left
 * out (empty when nothing was). Rejects with a readable Error for a file three cannot read.
 */
export async function geometryFromFile(name, bytes, format = threeFormatOf(name)) {
  try {
    if (format === 'stl') return { geometry: new STLLoader().parse(bytes), note: '' };
    if (format === 'ply') {
      const geometry = new PLYLoader().parse(bytes);
      if (!geometry.index) throw fileError(`“${name}” has no faces (a PLY point cloud?): there is no surface`);
      return { geometry, note: '' };
    }
    if (format === 'gltf' || format === 'glb') return await gltfGeometry(name, bytes);
  } catch (err) {
    if (err.category) throw err;
    throw fileError(`Could not read “${name}” as ${format.toUpperCase()}: ${err.message ?? err}`);
  }
  throw fileError(`“${name}”: not an STL, PLY or glTF file`);
}

function gltfGeometry(name, bytes) {
  return new Promise((resolve, reject) => {
    const failed = (err) => {
      const text = String(err?.message ?? err);
      if (/DRACOLoader|KTX2Loader|MeshoptDecoder/.test(text)) {
        reject(
          fileError(
            `“${name}” uses compression the page does not decode (${text.replace(/^THREE\.GLTFLoader: /, '')}); ` +
              'export it uncompressed',
          ),
        );
      } else if (/fetch|load buffer|Failed to load/i.test(text)) {
        reject(
          fileError(`“${name}” refers to other files (a .gltf with a separate .bin?): drop a single .glb instead`),
        );
      } else {
        reject(fileError(`Could not read “${name}” as glTF: ${text}`));
      }
    };
    try {
      new GLTFLoader().parse(
        bytes,
        '',
        (gltf) => {
          try {
            resolve(mergeScene(name, gltf.scene));
          } catch (err) {
            reject(err);
          }
        },
        failed,
      );
    } catch (err) {
      failed(err);
    }
  });
}

/** Every triangle mesh of the scene in world coordinates, as one indexed geometry. */
function mergeScene(name, scene) {
  scene.updateMatrixWorld(true);
  const positions = [];
  const indices = [];
  let meshes = 0;
  let skipped = 0;
  const point = new THREE.Vector3();
  scene.traverse((object) => {
    if (!object.isMesh) {
      if (object.isPoints || object.isLine) skipped += 1;
      return;
    }
    const geometry = object.geometry;
    const position = geometry.getAttribute('position');
    if (!position) {
      skipped += 1;
      return;
    }
    const first = positions.length / 3;
    for (let i = 0; i < position.count; ++i) {
      point.fromBufferAttribute(position, i).applyMatrix4(object.matrixWorld);
      positions.push(point.x, point.y, point.z);
    }
    const index = geometry.getIndex();
    const count = index ? index.count : position.count;
    for (let c = 0; c < count; ++c) indices.push(first + (index ? index.getX(c) : c));
    meshes += 1;
  });
  if (meshes === 0) throw fileError(`“${name}” has no triangle mesh (a glTF scene of points, lines or cameras only?)`);
  const merged = new THREE.BufferGeometry();
  merged.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  merged.setIndex(indices);
  const notes = [];
  if (meshes > 1) notes.push(`${meshes} glTF meshes merged, each placed by its world transform`);
  if (skipped > 0) notes.push(`${skipped} point or line objects left out`);
  return { geometry: merged, note: notes.join('; ') };
}

/**
 * The textured surface as a binary glTF (GLB): positions, normals and the uv of `geometry` (a
 * parameterized surface or its seam-split twin), one material. Resolves to an ArrayBuffer.
 */
export function glbFromGeometry(geometry, name = 'straightest') {
  const exported = new THREE.BufferGeometry();
  for (const attribute of ['position', 'normal', 'uv']) {
    const source = geometry.getAttribute(attribute);
    if (source) exported.setAttribute(attribute, source.clone());
  }
  if (geometry.index) exported.setIndex(geometry.index.clone());
  const mesh = new THREE.Mesh(exported, new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.8 }));
  mesh.name = name;
  return new Promise((resolve, reject) => {
    new GLTFExporter().parse(
      mesh,
      (result) => {
        exported.dispose();
        resolve(result);
      },
      (err) => reject(err instanceof Error ? err : new Error(String(err))),
      { binary: true },
    );
  });
}
