// The "every manifold mesh" section of docs/RESULTS.md: each of CGAL's sample meshes that is not a single
// disk (closed surfaces of any genus, several boundary loops, several components) parameterized by the
// native CLI after cutting it to a disk (core/include/straightest/disk_cut.hpp), with a fixed boundary
// (measured, shape-preserving weights) and the free one. One row per mesh: its topology, how it was cut,
// the seam, L2 / L∞ stretch, bijectivity and time. Meshes the loader refuses (non-manifold) are listed
// with their error. Used by scripts/results.mjs; `node scripts/manifold-results.mjs` prints the section.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { basename, join } from 'node:path';

const root = fileURLToPath(new URL('..', import.meta.url));
const cli = join(root, 'build/native/straightest');
const dataDir = join(root, 'build/data');
const cgalArchive = '/usr/share/doc/libcgal-dev/data.tar.gz';
// Free refinement stops here and reports converged: false (its map stays bijective); keeps the run short.
const FREE_BUDGET_MS = 20000;

/// Runs the CLI; its JSON, or {error} from --json-errors (bad input) or a crash (never expected).
function run(args) {
  try {
    return JSON.parse(execFileSync(cli, [...args, '--json-errors'], { encoding: 'utf8', maxBuffer: 1 << 28 }));
  } catch (e) {
    const out = e.stdout?.toString() ?? '';
    if (out.startsWith('{')) return JSON.parse(out);
    return { error: `exit ${e.status}: ${e.stderr?.toString().trim().split('\n').pop()}` };
  }
}

/// Every .off of CGAL's sample meshes (extracted from libcgal-dev's archive on first use), sorted.
export function cgalMeshFiles() {
  const dir = join(dataDir, 'data/meshes');
  if (!existsSync(dir) || readdirSync(dir).filter((f) => f.endsWith('.off')).length < 100) {
    if (!existsSync(cgalArchive)) return [];
    mkdirSync(dataDir, { recursive: true });
    execFileSync('tar', ['xzf', cgalArchive, '-C', dataDir, 'data/meshes']);
  }
  return readdirSync(dir)
    .filter((f) => f.endsWith('.off'))
    .sort()
    .map((f) => join(dir, f));
}

/// One mesh: its info and, unless it is a single disk, its measured and free parameterizations.
function measure(file) {
  const name = basename(file, '.off');
  const info = run(['info', file]);
  if (info.error) return { name, error: info.error };
  const disk = info.boundary_loops.length === 1 && info.components === 1 && info.euler_characteristic === 1;
  if (disk) return null;
  const measured = run(['param', file, '--boundary', 'measured']);
  const free = run(['param', file, '--boundary', 'free', '--time-budget-ms', String(FREE_BUDGET_MS)]);
  return { name, info, measured, free };
}

export function measureManifolds(files = cgalMeshFiles()) {
  return files.map(measure).filter(Boolean);
}

const fmt = (x) =>
  x === null || x === undefined || !Number.isFinite(x) ? '∞' : x < 100 ? x.toFixed(3) : x.toPrecision(3);

function stretch(p) {
  if (p.error) return { cell: `error: ${p.error}`, ok: false };
  if (!p.bijective) {
    const why = [
      ['flipped', p.flipped],
      ['degenerate', p.degenerate],
      ['overlaps', p.overlaps],
    ]
      .filter(([, n]) => n > 0)
      .map(([what, n]) => `${n} ${what}`);
    return { cell: `∞ (${why.join(', ')})`, ok: false };
  }
  return { cell: `${fmt(p.stretch.l2)} / ${fmt(p.stretch.linf)}`, ok: true };
}

const seconds = (p) => (p.error ? '–' : (p.timings_ms.total / 1000).toFixed(2));

function cutCell(p) {
  if (p.error) return '–';
  const filled = p.filled_loops?.length ? `, ${p.filled_loops.length} filled` : '';
  const parts = p.components > 1 ? `, largest of ${p.components}` : '';
  return `${p.cut}${filled}${parts}`;
}

export function manifoldSection(rows) {
  const refused = rows.filter((r) => r.error);
  const done = rows.filter((r) => !r.error);
  const table = done.map(({ name, info, measured, free }) => {
    const m = stretch(measured);
    const f = stretch(free);
    const p = measured.error ? free : measured;
    const seam = p.error ? '–' : p.seam_length > 0 ? p.seam_length.toPrecision(3) : '0';
    return (
      `| ${name} | ${info.vertices} | ${info.boundary_loops.length} | ${p.error ? '–' : p.genus} | ${cutCell(p)} | ` +
      `${seam} | ${m.cell} | ${seconds(measured)} | ${f.cell} | ${free.error ? '–' : free.converged ? 'yes' : 'no'} | ` +
      `${seconds(free)} |`
    );
  });
  const count = (pick) => done.filter((r) => stretch(r[pick]).ok).length;
  return `## Every manifold mesh: CGAL's closed and multi-loop meshes

Every sample mesh of CGAL's data that is not a single disk (${done.length} meshes), parameterized after
cutting it to a disk: holes filled virtually (the longest loop stays the outer boundary), a closed genus-0
surface cut along the shortest edge path between two far-apart vertices, a surface of genus ≥ 1 cut along a
tree–cotree cut graph (\`cut\`: fill, path, cut-graph; core/include/straightest/disk_cut.hpp). Stretch is
L2 / L∞ over the real faces only; *measured* is the fixed measured boundary with shape-preserving weights,
*free* its refinement (time budget ${FREE_BUDGET_MS / 1000} s; *converged* no means the budget or the
iteration cap stopped it, with a bijective map all the same). Seam length is in the mesh's units.

Bijective: measured ${count('measured')} of ${done.length}, free ${count('free')} of ${done.length}.

| mesh | vertices | loops | genus | cut | seam length | measured L2 / L∞ | s | free L2 / L∞ | converged | s |
|---|---:|---:|---:|---|---:|---:|---:|---:|---|---:|
${table.join('\n')}
${refused.length ? `\nRefused by the loader (${refused.length}), with its message:\n\n${refused.map((r) => `- ${r.name}: ${r.error}`).join('\n')}\n` : ''}`;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  process.stdout.write(manifoldSection(measureManifolds()));
}
