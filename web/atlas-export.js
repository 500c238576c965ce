// The atlas out of the page: the mesh with the atlas uv as OBJ (written by the core: mesh.toOBJ(cornerUv),
// one vt per distinct corner uv, `f v/vt`) and as GLB (three's GLTFExporter on the seam-split geometry the
// 3D view draws: TEXCOORD_0 is the atlas uv), and the packed layout as PNG (at the atlas's resolution) and
// SVG (one path per chart). Each returns the name of the file it saved.

import { atlasCanvas, atlasSvg } from './atlas-layout.js';
import { download, pngBlob } from './image-export.js';
import { glbFromGeometry } from './mesh-files.js';

/**
 * session: session.js (the OBJ is written in the worker); shown(): the atlas on display as
 * { reply, geometry (seam-split, with uv), paths (atlas-layout.js's chartPaths) } or null;
 * baseName(): the file names' stem ("torus-atlas").
 */
export function createAtlasExport({ session, shown, baseName }) {
  async function obj() {
    const { reply } = shown();
    const { text } = await session.request('exportObj', { uv: reply.cornerUv });
    const name = `${baseName()}.obj`;
    download(new Blob([text], { type: 'text/plain' }), name);
    return name;
  }

  async function glb() {
    const name = baseName();
    const buffer = await glbFromGeometry(shown().geometry, name);
    download(new Blob([buffer], { type: 'model/gltf-binary' }), `${name}.glb`);
    return `${name}.glb`;
  }

  async function png() {
    const { reply, paths } = shown();
    const blob = await pngBlob(atlasCanvas({ paths, width: reply.width, height: reply.height }));
    const name = `${baseName()}-layout.png`;
    download(blob, name);
    return name;
  }

  function svg() {
    const { reply } = shown();
    const text = atlasSvg(
      reply,
      `${session.label || 'mesh'} — texture atlas, ${reply.charts} charts, ` +
        `${reply.width} × ${reply.height} texels`,
    );
    const name = `${baseName()}-layout.svg`;
    download(new Blob([text], { type: 'image/svg+xml' }), name);
    return name;
  }

  return { obj, glb, png, svg };
}
