// npm run results: repeats the paper's Table 1 experiment (texture stretch of Floater's
// shape-preserving parameterization with a circle boundary vs the measured boundary, and the free
// boundary refined from it) on Nefertiti (CGAL's sample data, Debian package libcgal-demo) and on the
// generated Mountain and Face samples, and writes docs/RESULTS.md, with the real-patch table
// (scripts/real-patches.mjs) and every non-disk CGAL mesh cut and parameterized
// (scripts/manifold-results.mjs). Every number in that file comes from this run of the native CLI and
// tools.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { mergeSections } from './doc-sections.mjs';
import { manifoldSection, measureManifolds } from './manifold-results.mjs';
import { measurePatches, realPatchesSection, runRealPatches, startComparison } from './real-patches.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const cli = join(root, 'build/native/straightest');
const dataDir = join(root, 'build/data');
const cgalArchive = '/usr/share/doc/libcgal-dev/data.tar.gz';

function run(args) {
  return JSON.parse(execFileSync(cli, args, { encoding: 'utf8', maxBuffer: 1 << 28 }));
}

/// A mesh of CGAL's sample data (extracted from libcgal-dev's archive on first use), or null.
function cgalMesh(name) {
  const file = join(dataDir, `data/meshes/${name}.off`);
  if (!existsSync(file)) {
    if (!existsSync(cgalArchive)) return null;
    mkdirSync(dataDir, { recursive: true });
    execFileSync('tar', ['xzf', cgalArchive, '-C', dataDir, `data/meshes/${name}.off`]);
  }
  return file;
}
const nefertiti = () => cgalMesh('nefertiti');

const models = [
  { name: 'Nefertiti', mesh: nefertiti(), paper: { circle: 1.165, measured: 1.152 } },
  { name: 'Face (generated sample)', mesh: 'sample:face', paper: { circle: 1.591, measured: 1.341 } },
  { name: 'Mountain (generated sample)', mesh: 'sample:mountain', paper: { circle: 1.552, measured: 1.436 } },
];

const fmt = (x, digits = 3) => (x === null || x === undefined ? '∞' : x.toFixed(digits));
const rows = [];
const detail = [];
for (const model of models) {
  if (!model.mesh) {
    rows.push(`| ${model.name} | – | not available (install libcgal-demo) | | | | | | | | | |`);
    continue;
  }
  const info = run(['info', model.mesh]);
  const results = {};
  for (const boundary of ['circle', 'measured', 'square', 'free']) {
    results[boundary] = run(['param', model.mesh, '--boundary', boundary, '--weights', 'shape-preserving']);
  }
  const c = results.circle;
  const m = results.measured;
  const f = results.free;
  const change = c.stretch.l2 && m.stretch.l2 ? (100 * (m.stretch.l2 - c.stretch.l2)) / c.stretch.l2 : NaN;
  rows.push(
    `| ${model.name} | ${info.vertices} | ${fmt(c.stretch.l2)} | ${fmt(m.stretch.l2)} | ${change.toFixed(1)}% | ` +
      `${fmt(c.stretch.linf, 2)} | ${fmt(m.stretch.linf, 2)} | ${fmt(f.stretch.l2)} | ${fmt(f.stretch.linf, 2)} | ` +
      `${f.init}, ${f.iterations} | ${m.fallbacks} | ${model.paper.circle} → ${model.paper.measured} |`,
  );
  for (const weights of ['shape-preserving', 'mean-value', 'cotan', 'uniform']) {
    const cells = ['circle', 'measured', 'square', 'free'].map((b) => {
      const r =
        weights === 'shape-preserving' ? results[b] : run(['param', model.mesh, '--boundary', b, '--weights', weights]);
      return `${fmt(r.stretch.l2)} / ${fmt(r.stretch.linf, 2)}${r.flipped ? ` (${r.flipped} flipped)` : ''}`;
    });
    detail.push(`| ${model.name} | ${weights} | ${cells.join(' | ')} |`);
  }
  process.stdout.write(
    `${model.name}: circle ${fmt(c.stretch.l2)} → measured ${fmt(m.stretch.l2)}, free ${fmt(f.stretch.l2)}\n`,
  );
}

// CGAL's sample disks, and their measured L2 before the measured boundary's repair (ears
// lifted, heat-method radii for failed traces, outliers, the paper's base normal), recorded once with
// the CLI on main at e8ea5a3 (the code before that repair is gone, so these cannot be regenerated).
const cgalDisks = [
  ['nefertiti', 1.0173],
  ['three_peaks', 2.4136],
  ['mushroom', 9.5905],
  ['lion-head', 9.3],
  ['mannequin-devil', 23.2316],
  ['plane', 1.0],
  ['cylinder', 1.0017],
  ['patch-01', 1.1827],
  ['patch-13', 1.0],
  ['patch-20', 1.118],
  ['patch-21', 1.0],
  ['patch-23', 1.0],
  ['patch-30', 1.1176],
];
// The plane-like disks (height fields over a plane, and the cylinder) whose measured map must stay at
// least as good as before the repair.
const planeLike = new Set([
  'plane',
  'cylinder',
  'patch-01',
  'patch-13',
  'patch-20',
  'patch-21',
  'patch-23',
  'patch-30',
]);
const before = new Map(cgalDisks);
const diskFiles = cgalDisks.map(([name]) => cgalMesh(name)).filter(Boolean);
const disks = diskFiles.length ? runRealPatches(diskFiles) : [];
const l2 = (r) => (r && !r.error && r.l2 !== null ? r.l2 : Infinity);
const fmt4 = (x) => (Number.isFinite(x) ? x.toFixed(4) : '∞');
const diskRows = disks.map((d) => {
  const f = d.free;
  return (
    `| ${d.patch} | ${d.vertices} | ${fmt4(l2(d.circle))} | ${before.get(d.patch).toFixed(4)} | ${fmt4(l2(d.measured))} | ` +
    `${d.measured.fallbacks} / ${d.measured.outliers} | ${fmt4(l2(f))} | ${f.init}, ${f.iterations} |`
  );
});
// "At least as good": not above the recorded value beyond its 4 printed digits.
const notWorse = disks
  .filter((d) => planeLike.has(d.patch))
  .filter((d) => l2(d.measured) <= before.get(d.patch) + 5e-5);
const nef = disks.find((d) => d.patch === 'nefertiti');
const patches = measurePatches();

const text = `# Results: measured boundary vs circle (the paper's Table 1)

Generated by \`npm run results\` (scripts/results.mjs) with the native CLI on ${new Date().toISOString().slice(0, 10)};
every number below comes from that run. Parameterization: Floater's shape-preserving weights, source =
the default "center of the mesh" (interior vertex farthest from the boundary). Stretch is Sander et al.'s
L2 / L∞ texture stretch, normalized so that an isometry scores 1.

| model | vertices | circle L2 | measured L2 | change | circle L∞ | measured L∞ | free L2 | free L∞ | free: start, iterations | failed traces (fallback radius) | paper (circle → measured) |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---|
${rows.join('\n')}

All boundaries and weights (L2 / L∞; flipped triangles are counted, and make the stretch ∞):

| model | weights | circle | measured | square | free |
|---|---|---|---|---|---|
${detail.join('\n')}

## Reading these numbers

- **Nefertiti** is the paper's 299-vertex model (CGAL's \`data/meshes/nefertiti.off\`). The direction of the
  paper's result reproduces: the measured boundary lowers L2 stretch compared with the circle. The absolute
  values differ from the paper's 1.165 → 1.152. Likely reasons, none of which the paper pins down: the
  normalization of the stretch (we scale so that an isometry scores 1, following Sander et al.'s
  definition with the total 2D and 3D areas), the choice of the center S, the circle's parameterization
  (we place boundary vertices by 3D arc length), and how the measured polygon is made convex.
- **Face** and **Mountain** are *generated* stand-ins (\`sample:face\`, \`sample:mountain\`): the paper's
  models are not available, so the paper's columns for them are quoted only for orientation; our meshes
  are different surfaces and their numbers are not comparable.
- **Free** (not in the paper): the measured map, or the circle's when the measured one is not bijective
  (*start*), refined by SLIM on the symmetric Dirichlet energy with every vertex free, boundary included,
  and a line search that never lets a triangle flip or collapse (core/include/straightest/free_boundary.hpp);
  *iterations* until the relative energy decrease stops. It is not a convex-boundary map, so it is not
  bound by the paper's comparison: it is the lowest-distortion map we make without folding.
- The measured boundary is not always the best choice; \`--boundary auto\` computes all four and keeps the
  least stretched bijective one.

${realPatchesSection(patches)}\n${measuredSection()}\n${freeStartSection()}\n${manifoldSection(measureManifolds())}`;
mkdirSync(join(root, 'docs'), { recursive: true });
// Sections written by other scripts (scripts/atlas-figure.mjs's "Texture atlas vs xatlas") stay.
const resultsFile = join(root, 'docs/RESULTS.md');
writeFileSync(resultsFile, existsSync(resultsFile) ? mergeSections(readFileSync(resultsFile, 'utf8'), text) : text);
process.stdout.write('wrote docs/RESULTS.md\n');

/// The measured boundary's repair: what changed, the real patches' counts before and after,
/// CGAL's disks before and after, and the targets on those disks.
function measuredSection() {
  const both = patches.filter((p) => Number.isFinite(l2(p.circle)) && Number.isFinite(l2(p.measured)));
  const after = {
    worse: both.filter((p) => l2(p.measured) > l2(p.circle)).length,
    muchWorse: both.filter((p) => l2(p.measured) > 1.25 * l2(p.circle)).length,
    better: both.filter((p) => l2(p.measured) < l2(p.circle)).length,
    ears: patches.filter((p) => p.measured?.worst_ear !== null && p.measured?.worst_ear < 1e-2).length,
    worstEar: Math.min(...patches.map((p) => p.measured?.worst_ear ?? Infinity)),
  };
  const yes = (ok) => (ok ? '**met**' : '**missed**');
  const worsePlane = disks.filter((d) => planeLike.has(d.patch) && !notWorse.includes(d));
  return `## Measured boundary before/after its repair

"Before" is the measured boundary on main at e8ea5a3 (radial projection of the measured points onto their
convex hull plus a chord bulge, edge-graph radii for failed traces, the area-weighted normal whenever the
paper's base normal was shorter than 0.05), recorded once with the CLI; "after" is this run. What changed
(core/include/straightest/boundary_map.hpp):

- **Ears and pockets are lifted.** Every ear, and every pocket (the ≤ 16 faces a chord cuts off the disk), whose
  corners' triangle is below \`kEarAreaFraction\` = 0.1 of its 3D area × the map's scale has its apex moved
  radially outward, far enough for it to hold once its neighbours are projected onto the new hull; project,
  repeat until none is below (points only move out; an ear lift never more than doubles the apex's radius, so
  an ear spanning half a turn is left as it is). An ear already above the bound moves nothing, so a flat convex
  patch still reproduces itself exactly. (0.05 and 0.25 were measured too: 0.25 no longer settles on every patch
  and leaves an ear at 4e-3; 0.05 leaves one patch above 1.25× the circle.)
- **Failed traces** get the heat-method distance clamped to [straight-line distance, edge-graph distance] (the heat
  method alone fell to 0.4× the graph distance on coarse patches, below the straight line); the edge-graph
  distance is computed only when a trace is longer than 1.5× its straight line.
- **Outliers**: a reached trace longer than 1.5× the edge-graph distance (an upper bound of the geodesic distance)
  is counted in \`outliers\` and gets the same radius.
- **Base normal**: the paper's mean of the virtual faces' normals unless |sum| ≤ 1e-12 × the sum of their lengths
  (rounding noise); closed meshes report \`base_fallback: true\`.

| real patches (${patches.length}; ${both.length} where circle and measured maps are bijective) | before | after |
|---|---:|---:|
| measured L2 > circle L2 | 28 | ${after.worse} |
| measured L2 > 1.25 × circle L2 | 12 | ${after.muchWorse} |
| measured L2 < circle L2 | 7 | ${after.better} |
| patches with a measured ear below 1e-2 of the mean ratio | 17 | ${after.ears} |
| worst measured ear ratio over all patches | 6.3e-05 | ${after.worstEar.toPrecision(2)} |

(The per-patch "after" numbers are the real-patch table above; before the repair the worst cases were
bull-seed1-r18 at 85× the circle's L2, bunny00-seed1-r35 at 39× and bunny00-seed1-r12 at 37×, all from
collapsed ears.)

CGAL's sample disks (\`build/native/real_patches\` on \`data/meshes/NAME.off\`; L2 with shape-preserving weights;
failed traces and outliers of the measured map; the free map, its start and iterations):

| mesh | vertices | circle | measured before | measured after | failed / outliers | free | free: start, iterations |
|---|---:|---:|---:|---:|---:|---:|---|
${diskRows.join('\n')}

Targets on CGAL's disks:

- Nefertiti ≤ 1.018: ${nef ? `${yes(l2(nef.measured) <= 1.018)} (${fmt4(l2(nef.measured))})` : 'not measured (no CGAL data)'}
- plane-like disks (${[...planeLike].join(', ')}) at least as good as before: ${yes(worsePlane.length === 0)}${
    worsePlane.length
      ? ` (worse: ${worsePlane.map((d) => `${d.patch} ${fmt4(l2(d.measured))} vs ${before.get(d.patch).toFixed(4)}`).join(', ')})`
      : ` (${notWorse.length} of ${planeLike.size} equal or lower)`
  }
`;
}

/// What the measured start buys the free boundary, on CGAL's disks and the real patches.
function freeStartSection() {
  return `## The free boundary: measured start vs circle start

${startComparison([...disks, ...patches])}`;
}
