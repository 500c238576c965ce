// node scripts/atlas-figure.mjs [NAME ...] — side-by-side SVG of our packed atlas and xatlas's for CGAL sample
// meshes (default: elephant bull), written to docs/atlas-NAME.svg. Needs build/native/straightest and
// build/native/atlas_compare (scripts/bench-atlas.mjs builds them and extracts the meshes to build/data).
//
// Ours: `straightest atlas MESH -o OBJ` at its defaults (padding 2); xatlas: bench/atlas/xatlas-run.mjs at its
// defaults (padding 0; reused from build/bench/atlas when scripts/bench-atlas.mjs left it there). Both layouts
// are drawn in their own [0,1]² (the atlas's width × height), one colour per chart: a chart is a set of faces
// joined across edges whose two corners have the same uv on both sides. Each chart is filled through its
// boundary loops (even-odd rule) and outlined; a chart whose signed uv area is negative (clockwise: the
// mirror image of the surface) is hatched. The captions' numbers are measureAtlas's (the CLI's JSON for
// ours, atlas_compare's for xatlas). Also writes docs/RESULTS.md's section "Texture atlas vs xatlas" (the
// figures, and a summary of scripts/bench-atlas.mjs's last run when build/bench/atlas/runs.jsonl exists);
// scripts/results.mjs keeps that section when it rewrites the file.
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { mergeSections } from './doc-sections.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const names = process.argv.slice(2).length > 0 ? process.argv.slice(2) : ['elephant', 'bull'];
const outDir = join(root, 'build/bench/atlas');
mkdirSync(outDir, { recursive: true });

/** Ours: faces (vertex indices, as written) and per-corner uv from the CLI's OBJ with f v/vt. */
function readObjAtlas(path) {
  const uv = [];
  const faces = [];
  const cornerUv = [];
  for (const line of readFileSync(path, 'utf8').split('\n')) {
    const [tag, ...rest] = line.trim().split(/\s+/);
    if (tag === 'vt') uv.push([Number(rest[0]), Number(rest[1])]);
    if (tag === 'f') {
      for (const c of rest) {
        const [v, t] = c.split('/').map((x) => Number(x) - 1);
        faces.push(v);
        cornerUv.push(uv[t]);
      }
    }
  }
  return { faces, cornerUv };
}

/** xatlas: faces and per-corner uv from xatlas-run.mjs's JSON. */
function readXatlasAtlas(path) {
  const j = JSON.parse(readFileSync(path, 'utf8'));
  const cornerUv = [];
  for (let c = 0; c < j.indices.length; ++c) cornerUv.push([j.cornerUv[2 * c], j.cornerUv[2 * c + 1]]);
  return { faces: j.indices, cornerUv, width: j.width, height: j.height };
}

const same = (p, q) => p[0] === q[0] && p[1] === q[1];

/** Chart id per face: union of faces across edges whose corners match in uv on both sides. */
function charts({ faces, cornerUv }) {
  const nf = faces.length / 3;
  const parent = Int32Array.from({ length: nf }, (_, i) => i);
  const find = (x) => {
    while (parent[x] !== x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  const edges = new Map();
  for (let f = 0; f < nf; ++f) {
    for (let k = 0; k < 3; ++k) {
      const a = faces[3 * f + k],
        b = faces[3 * f + ((k + 1) % 3)];
      const key = `${Math.min(a, b)},${Math.max(a, b)}`;
      const list = edges.get(key) ?? [];
      list.push({ f, ca: 3 * f + k, cb: 3 * f + ((k + 1) % 3), a });
      edges.set(key, list);
    }
  }
  for (const list of edges.values()) {
    for (let i = 0; i < list.length; ++i) {
      for (let j = i + 1; j < list.length; ++j) {
        const [p, q] = [list[i], list[j]];
        const [pa, pb] = [cornerUv[p.ca], cornerUv[p.cb]];
        const [qa, qb] = p.a === q.a ? [cornerUv[q.ca], cornerUv[q.cb]] : [cornerUv[q.cb], cornerUv[q.ca]];
        if (same(pa, qa) && same(pb, qb)) parent[find(p.f)] = find(q.f);
      }
    }
  }
  const id = new Map();
  const chartOf = new Int32Array(nf);
  for (let f = 0; f < nf; ++f) {
    const r = find(f);
    if (!id.has(r)) id.set(r, id.size);
    chartOf[f] = id.get(r);
  }
  return { chartOf, count: id.size, edges };
}

/** SVG path data per chart (its boundary edges chained into loops) and whether the chart is mirrored. */
function chartPaths(atlas, w, h) {
  const { faces, cornerUv } = atlas;
  const { chartOf, count } = charts(atlas);
  const area = new Float64Array(count);
  const boundary = Array.from({ length: count }, () => new Map()); // start uv key → [end uv, ...]
  const key = (p) => `${p[0]},${p[1]}`;
  const half = new Map(); // directed uv edge "chart|a|b" present
  for (let f = 0; f < faces.length / 3; ++f) {
    const [p, q, r] = [cornerUv[3 * f], cornerUv[3 * f + 1], cornerUv[3 * f + 2]];
    area[chartOf[f]] += (q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]);
    for (const [a, b] of [
      [p, q],
      [q, r],
      [r, p],
    ])
      half.set(`${chartOf[f]}|${key(a)}|${key(b)}`, [a, b]);
  }
  for (const [k, [a, b]] of half) {
    const c = Number(k.slice(0, k.indexOf('|')));
    if (half.has(`${c}|${key(b)}|${key(a)}`)) continue; // interior edge of the chart
    const list = boundary[c].get(key(a)) ?? [];
    list.push([a, b]);
    boundary[c].set(key(a), list);
  }
  const pt = (p) => `${(p[0] * w).toFixed(1)} ${((1 - p[1]) * h).toFixed(1)}`;
  return boundary.map((starts, c) => {
    let d = '';
    for (const list of starts.values()) {
      while (list.length > 0) {
        const [a, b0] = list.pop();
        let b = b0;
        d += `M${pt(a)}`;
        const first = key(a);
        for (let guard = 0; guard < 1e6; ++guard) {
          d += `L${pt(b)}`;
          if (key(b) === first) break;
          const next = starts.get(key(b));
          if (!next || next.length === 0) break;
          b = next.pop()[1];
        }
        d += 'Z';
      }
    }
    return { d, mirrored: area[c] < 0 };
  });
}

function panel(atlas, x0, y0, size, title, caption) {
  const aspect = (atlas.width ?? 1) / (atlas.height ?? 1);
  const [w, h] = aspect >= 1 ? [size, size / aspect] : [size * aspect, size];
  const paths = chartPaths(atlas, w, h);
  let s =
    `<g transform="translate(${x0} ${y0})">\n<text x="0" y="-30" font-size="15" font-weight="bold">${title}</text>\n` +
    `<text x="0" y="-12" font-size="12">${caption}</text>\n<rect x="0" y="0" width="${w.toFixed(1)}" height="${h.toFixed(1)}" fill="#fafafa" stroke="#888"/>\n`;
  paths.forEach(({ d, mirrored }, c) => {
    const hue = (c * 137.508) % 360;
    s += `<path d="${d}" fill="hsl(${hue.toFixed(0)} 60% 68%)" fill-rule="evenodd" stroke="#333" stroke-width="0.4"/>\n`;
    if (mirrored) s += `<path d="${d}" fill="url(#hatch)" fill-rule="evenodd"/>\n`;
  });
  return `${s}</g>\n`;
}

const captions = [];
for (const name of names) {
  const mesh = join(root, 'build/data/data/meshes', `${name}.off`);
  if (!existsSync(mesh))
    execFileSync('tar', [
      'xzf',
      '/usr/share/doc/libcgal-dev/data.tar.gz',
      '-C',
      join(root, 'build/data'),
      `data/meshes/${name}.off`,
    ]);
  const obj = join(outDir, `ours-${name}.obj`);
  const ours = JSON.parse(
    execFileSync(join(root, 'build/native/straightest'), ['atlas', mesh, '-o', obj], { encoding: 'utf8' }),
  );
  const xjson = join(outDir, `xatlas-${name}-p0.json`);
  if (!existsSync(xjson))
    execFileSync(process.execPath, [join(root, 'bench/atlas/xatlas-run.mjs'), mesh, xjson], {
      stdio: ['ignore', 2, 2],
    });
  const xq = JSON.parse(
    spawnSync(join(root, 'build/native/atlas_compare'), [xjson, '--mesh', mesh], { encoding: 'utf8' }).stdout,
  );
  const oursAtlas = { ...readObjAtlas(obj), width: ours.width, height: ours.height };
  const xAtlas = readXatlasAtlas(xjson);
  const size = 440,
    gap = 40,
    top = 50;
  const pct = (m, n) => `${m} mirrored (${Math.round((100 * m) / n)} %)`;
  const svg =
    `<svg xmlns="http://www.w3.org/2000/svg" width="${2 * size + 3 * gap}" height="${size + top + gap}" font-family="sans-serif">\n` +
    '<defs><pattern id="hatch" width="5" height="5" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">' +
    '<rect width="5" height="5" fill="#000" fill-opacity="0.25"/><line x1="0" y1="0" x2="0" y2="5" stroke="#000" stroke-width="2"/></pattern></defs>\n' +
    '<rect width="100%" height="100%" fill="#fff"/>\n' +
    panel(
      oursAtlas,
      gap,
      top + 10,
      size,
      `${name}: straightest (padding 2)`,
      `${ours.charts} charts, L2 ${ours.stretch.l2.toFixed(4)}, utilization ${ours.utilization.toFixed(2)}, ${pct(ours.mirrored, ours.charts)}, ${ours.width}×${ours.height}`,
    ) +
    panel(
      xAtlas,
      2 * gap + size,
      top + 10,
      size,
      `${name}: xatlas (padding 0, hatched: mirrored)`,
      `${xq.charts} charts, L2 ${Number(xq.l2).toFixed(4)}, utilization ${xq.utilization.toFixed(2)}, ${pct(xq.mirrored_charts, xq.charts)}, ${xq.width}×${xq.height}`,
    ) +
    '</svg>\n';
  const file = join(root, 'docs', `atlas-${name}.svg`);
  writeFileSync(file, svg);
  captions.push({ name, ours, xq });
  process.stderr.write(`atlas-figure: ${file} (${(svg.length / 1024).toFixed(0)} KB)\n`);
}

/** The bench's CGAL rows (build/bench/atlas/runs.jsonl), summarized: ranges over the meshes both tools mapped. */
function benchSummary() {
  const runs = join(outDir, 'runs.jsonl');
  if (!existsSync(runs)) return '';
  const rows = readFileSync(runs, 'utf8')
    .split('\n')
    .filter(Boolean)
    .map((l) => JSON.parse(l))
    .filter(
      (r) =>
        typeof r.seconds === 'object' &&
        r.result &&
        !r.error &&
        !r.mesh.includes('/atlas/') &&
        !r.mesh.startsWith('heightfield:'),
    );
  const ours = rows.filter((r) => r.tool === 'ours' && r.padding === 2);
  const xatlas = rows.filter((r) => r.tool === 'xatlas' && r.padding === 0);
  if (ours.length === 0 || xatlas.length === 0) return '';
  const range = (xs, d) => {
    const f = xs.filter(Number.isFinite);
    return `${Math.min(...f).toFixed(d)}–${Math.max(...f).toFixed(d)}`;
  };
  const l2x = xatlas.map((r) => Number(r.result.l2));
  const inf = xatlas
    .filter((r) => !Number.isFinite(Number(r.result.l2)))
    .map((r) => r.mesh.replace(/^.*\//, '').replace(/\.off$/, ''));
  const worse = ours.filter((o) => {
    const x = xatlas.find((r) => r.mesh === o.mesh);
    return x && o.result.stretch.l2 > Number(x.result.l2);
  });
  const sum = (xs) => xs.reduce((a, b) => a + b, 0);
  return (
    `On the ${ours.length} CGAL meshes of the benchmark, our L2 stretch is ${range(
      ours.map((r) => r.result.stretch.l2),
      4,
    )} and ` +
    `xatlas's ${range(l2x, 4)}${inf.length ? ` (infinite on ${inf.join(', ')}: faces it leaves unmapped)` : ''}; ours is above xatlas's on ` +
    `${worse.length === 0 ? 'none' : worse.map((r) => r.mesh.replace(/^.*\//, '').replace(/\.off$/, '')).join(', ')}. ` +
    `We make ${range(
      ours.map((r) => r.result.charts),
      0,
    )} charts per mesh where xatlas makes ${range(
      xatlas.map((r) => r.result.charts),
      0,
    )}, ` +
    `${sum(ours.map((r) => r.result.mirrored))} of ours mirrored and ${sum(ours.map((r) => r.result.non_disk_charts))} not a disk, against ` +
    `${sum(xatlas.map((r) => r.result.mirrored_charts))} mirrored and ${sum(xatlas.map((r) => r.result.non_disk_charts))} non-disk of xatlas's ` +
    `${sum(xatlas.map((r) => r.result.charts))}. Flipped faces, ours / xatlas: ${sum(ours.map((r) => r.result.flipped))} / ${sum(xatlas.map((r) => r.result.flipped))}; ` +
    `overlaps: ${sum(ours.map((r) => r.result.overlaps))} / ${sum(xatlas.map((r) => r.result.overlaps))}. ` +
    `${sum(xatlas.map((r) => r.result.utilization)) / xatlas.length > sum(ours.map((r) => r.result.utilization)) / ours.length ? 'xatlas packs tighter' : 'We pack tighter'}: ` +
    `utilization ${range(
      xatlas.map((r) => r.result.utilization),
      2,
    )} at padding 0 for xatlas against our ` +
    `${range(
      ours.map((r) => r.result.utilization),
      2,
    )} at padding 2 (${range(
      rows.filter((r) => r.tool === 'ours' && r.padding === 0).map((r) => r.result.utilization),
      2,
    )} at padding 0). ` +
    'Times and every column per mesh: [BENCHMARKS.md, Texture atlas vs xatlas](BENCHMARKS.md#texture-atlas-vs-xatlas-scriptsbench-atlasmjs).'
  );
}

const section = `## Texture atlas vs xatlas

\`node scripts/atlas-figure.mjs\` draws our atlas (\`straightest atlas MESH\`, its defaults: padding 2, 1024²) beside
xatlas's (xatlasjs 0.2.0, its defaults: padding 0), each in its own [0,1]², one colour per chart; hatched charts
are mirrored (their uv winding is the reverse of the surface's). Both are measured by the same measureAtlas.
Our charts are flattened with the free boundary (never folded, never mirrored) and placed by rotations only;
xatlas ignores the winding, so many of its charts come out as the surface's mirror image.

${captions
  .map(
    ({ name, ours, xq }) =>
      `![${name}: our atlas and xatlas's](atlas-${name}.svg)

${name}: ours ${ours.charts} charts, L2 ${ours.stretch.l2.toFixed(4)}, L∞ ${ours.stretch.linf.toFixed(2)}, utilization ${ours.utilization.toFixed(2)}, ` +
      `${ours.mirrored} mirrored; xatlas ${xq.charts} charts, L2 ${Number(xq.l2).toFixed(4)}, L∞ ${Number(xq.linf).toFixed(2)}, ` +
      `utilization ${xq.utilization.toFixed(2)}, ${xq.mirrored_charts} mirrored.`,
  )
  .join('\n\n')}

${benchSummary()}
`;
const results = join(root, 'docs/RESULTS.md');
writeFileSync(results, mergeSections(readFileSync(results, 'utf8'), section));
process.stderr.write('atlas-figure: wrote its section of docs/RESULTS.md\n');
