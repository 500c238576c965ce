// The "real patches" section of docs/RESULTS.md: every patch of scripts/patches.sh (geodesic balls cut
// from CGAL's closed sample meshes) parameterized under every boundary by build/native/real_patches,
// one row per patch, and the counts that say how the measured boundary does against the circle.
// Used by scripts/results.mjs; `node scripts/real-patches.mjs` prints the section alone.
import { execFileSync } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';

const root = fileURLToPath(new URL('..', import.meta.url));
const boundaries = ['circle', 'measured', 'square', 'free'];

const l2Of = (r) => (r && !r.error && r.l2 !== null ? r.l2 : Infinity);

function cell(r) {
  if (!r) return 'n/a';
  if (r.error) return `error: ${r.error}`;
  if (r.bijective) return fmtL2(r.l2);
  const why = [
    ['flipped', r.flipped],
    ['degenerate', r.degenerate],
    ['overlaps', r.overlaps],
  ]
    .filter(([, n]) => n > 0)
    .map(([what, n]) => `${n} ${what}`);
  return `∞ (${why.join(', ')})`;
}

const freeRun = (r) =>
  !r || r.error || !r.init ? '–' : `${r.init}, ${r.iterations}${r.untangled ? ', untangled' : ''}`;

const fmtL2 = (x) => (!Number.isFinite(x) ? '∞' : x < 100 ? x.toFixed(3) : x.toPrecision(3));

const ear = (r) => (!r || r.error || r.worst_ear === null ? '–' : r.worst_ear.toPrecision(2));

/// Runs build/native/real_patches on `files` (any disk meshes) and returns one JSON object per mesh.
export function runRealPatches(files) {
  const tool = join(root, 'build/native/real_patches');
  const out = execFileSync(tool, files, { encoding: 'utf8', maxBuffer: 1 << 26, stdio: ['ignore', 'pipe', 'ignore'] });
  return out
    .split('\n')
    .filter((line) => line.startsWith('{'))
    .map((line) => JSON.parse(line));
}

/// Runs real_patches on the patch set (building it with scripts/patches.sh when it is missing) and
/// returns the patches' JSON objects.
export function measurePatches() {
  const dir = join(root, 'build/data/patches');
  const tool = join(root, 'build/native/real_patches');
  if (!existsSync(tool) || !existsSync(dir) || !readdirSync(dir).some((f) => f.endsWith('.off'))) {
    execFileSync('bash', [join(root, 'scripts/patches.sh')], { stdio: ['ignore', 'inherit', 'inherit'] });
  }
  return runRealPatches(
    readdirSync(dir)
      .filter((f) => f.endsWith('.off'))
      .sort()
      .map((f) => join(dir, f)),
  );
}

const median = (xs) => {
  const sorted = [...xs].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
};

/// What the measured start buys the free boundary: on every mesh whose free map started from the
/// measured map (a bijective one), that refinement against the same refinement from the circle's map.
export function startComparison(meshes) {
  const pairs = meshes.filter((p) => p.free?.init === 'measured' && p.free_from_circle && !p.free_from_circle.error);
  if (pairs.length === 0) return 'No mesh started from the measured map.\n';
  const rows = pairs.map((p) => {
    const m = p.free;
    const c = p.free_from_circle;
    const conv = (r) => (r.converged ? '' : ' (not converged)');
    return (
      `| ${p.patch} | ${p.vertices} | ${m.iterations}${conv(m)} | ${c.iterations}${conv(c)} | ` +
      `${m.refine_ms.toFixed(0)} | ${c.refine_ms.toFixed(0)} | ${m.ms.toFixed(0)} | ${c.ms.toFixed(0)} | ` +
      `${fmtL2(l2Of(m))} | ${fmtL2(l2Of(c))} |`
    );
  });
  const count = (pred) => pairs.filter(pred).length;
  const fewer = count((p) => p.free.iterations < p.free_from_circle.iterations);
  const faster = count((p) => p.free.ms < p.free_from_circle.ms);
  const fasterRefine = count((p) => p.free.refine_ms < p.free_from_circle.refine_ms);
  const lower = count((p) => l2Of(p.free) < l2Of(p.free_from_circle));
  const iterRatio = median(pairs.map((p) => p.free.iterations / Math.max(1, p.free_from_circle.iterations)));
  const refineRatio = median(pairs.map((p) => p.free.refine_ms / p.free_from_circle.refine_ms));
  const totalRatio = median(pairs.map((p) => p.free.ms / p.free_from_circle.ms));
  const l2Ratio = median(pairs.map((p) => l2Of(p.free) / l2Of(p.free_from_circle)));
  const sum = (f) => pairs.reduce((total, p) => total + f(p), 0);
  const l2Gap = Math.max(...pairs.map((p) => Math.abs(l2Of(p.free) / l2Of(p.free_from_circle) - 1)));
  const muchFewer = pairs.filter((p) => 3 * p.free.iterations <= p.free_from_circle.iterations);
  const verdict =
    Math.abs(iterRatio - 1) < 0.1
      ? `So the measured start buys little for the free boundary: SLIM converges in about as many iterations from
either start, to the same L2 (within ${(100 * l2Gap).toFixed(1)} %), and the measured start's tracing makes the
total ${totalRatio >= 1 ? 'slower' : 'faster'} in the median. It pays where the measured map is already near the
free optimum: ${muchFewer.map((p) => `${p.patch} (${p.free.iterations} vs ${p.free_from_circle.iterations})`).join(', ') || 'none here'}.
What the measured start gives is a better fixed map to fall back on (the tables above), not a faster refinement.`
      : `Median over these meshes: the measured start needs ${iterRatio.toFixed(2)}× the circle start's iterations.`;
  return `On the ${pairs.length} meshes whose free map started from the measured map (it is bijective there), the
same refinement was also started from the circle's map (\`real_patches\`: \`refineParameterization\` on the circle's
result; same options). *Refine* is the refinement's own time (untangling included), *total* adds the start's
solve (the measured one traces the boundary's straightest paths first), in ms, one run on a shared 2-core machine.

- fewer iterations from the measured start on **${fewer} of ${pairs.length}** (median ratio measured ÷ circle ${iterRatio.toFixed(2)})
- refinement faster on **${fasterRefine}** (median ratio ${refineRatio.toFixed(2)}); total faster on **${faster}** (median ratio ${totalRatio.toFixed(2)})
- lower final L2 from the measured start on **${lower}** (median ratio ${l2Ratio.toFixed(3)}): both are local minima of the same energy
- in all: ${sum((p) => p.free.iterations)} iterations from the measured start vs ${sum((p) => p.free_from_circle.iterations)} from the circle;
  refinement ${(sum((p) => p.free.refine_ms) / 1000).toFixed(1)} s vs ${(sum((p) => p.free_from_circle.refine_ms) / 1000).toFixed(1)} s; total ${(sum((p) => p.free.ms) / 1000).toFixed(1)} s vs ${(sum((p) => p.free_from_circle.ms) / 1000).toFixed(1)} s

${verdict}

| mesh | vertices | iterations (measured start) | iterations (circle start) | refine ms (measured) | refine ms (circle) | total ms (measured) | total ms (circle) | free L2 (measured start) | free L2 (circle start) |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|
${rows.join('\n')}
`;
}

/// The markdown section for the patches' results.
export function realPatchesSection(patches) {
  const rows = patches.map((p) => {
    const ratio = l2Of(p.measured) / l2Of(p.circle);
    return (
      `| ${p.patch} | ${p.vertices} | ${boundaries.map((b) => cell(p[b])).join(' | ')} | ${freeRun(p.free)} | ` +
      `${Number.isFinite(ratio) ? ratio.toFixed(2) : '–'} | ${ear(p.measured)} | ${ear(p.circle)} | ` +
      `${p.measured?.fallbacks ?? '–'} |`
    );
  });
  const count = (pred) => patches.filter(pred).length;
  const n = patches.length;
  const hasFree = patches.some((p) => p.free);
  const bijective = boundaries
    .filter((b) => b !== 'free' || hasFree)
    .map((b) => `${b} ${count((p) => p[b]?.bijective)}/${n}`)
    .join(', ');
  const both = patches.filter((p) => Number.isFinite(l2Of(p.circle)) && Number.isFinite(l2Of(p.measured)));
  const worse = both.filter((p) => l2Of(p.measured) > l2Of(p.circle)).length;
  const muchWorse = both.filter((p) => l2Of(p.measured) > 1.25 * l2Of(p.circle)).length;
  const earBelow = count((p) => p.measured?.worst_ear !== null && p.measured?.worst_ear < 1e-2);
  const better = both.filter((p) => l2Of(p.measured) < l2Of(p.circle)).length;
  const ears = patches.map((p) => p.measured?.worst_ear).filter((x) => x !== null && x !== undefined);
  const worstEar = Math.min(...ears);
  const bestFixed = (p) => Math.min(l2Of(p.circle), l2Of(p.measured), l2Of(p.square));
  const yes = (ok) => (ok ? '**met**' : '**missed**');
  const freeNote = hasFree
    ? 'Free: the free boundary (a fixed-boundary start refined without folding; its start and iterations).'
    : 'Free: n/a until the core has the free boundary.';
  let targets = `### The measured boundary's targets on the real patches (from the table below)

- no ear below 1e-2 of the mean area ratio: ${yes(earBelow === 0)} (${earBelow} patches; worst ear over all patches ${worstEar.toPrecision(2)})
- measured L2 never above 1.25× the circle's: ${yes(muchWorse === 0)} (${muchWorse} of ${both.length} patches where both are bijective; worst ratio ${Math.max(...both.map((p) => l2Of(p.measured) / l2Of(p.circle))).toFixed(3)})
- measured L2 below the circle's on at least half: ${yes(2 * better >= both.length)} (${better} of ${both.length})
`;
  if (hasFree) {
    const freeBij = count((p) => p.free?.bijective);
    const bijSomewhere = patches.filter((p) => Number.isFinite(bestFixed(p)));
    const below = bijSomewhere.filter((p) => l2Of(p.free) < bestFixed(p)).length;
    const ratios = bijSomewhere.filter((p) => p.free?.bijective).map((p) => l2Of(p.free) / bestFixed(p));
    const failing = patches
      .filter((p) => !p.free?.bijective)
      .map(
        (p) =>
          `${p.patch}: ${cell(p.free)}${p.free?.untangled ? ' left by untangling' : ''}, ${p.free?.iterations ?? 0} SLIM iterations`,
      )
      .join('; ');
    targets += `
### The free boundary's targets on the real patches

- bijective on every patch (0 flipped, 0 degenerate, 0 overlaps): ${yes(freeBij === n)} (${freeBij} of ${n}${
      failing ? `; not bijective: ${failing}` : ''
    })${
      n - bijSomewhere.length > 0
        ? `; bijective on ${count((p) => !Number.isFinite(bestFixed(p)) && p.free?.bijective)} of the ${
            n - bijSomewhere.length
          } where no fixed boundary gives a bijective map`
        : ''
    }
- free L2 below the best fixed boundary's on **${below} of ${bijSomewhere.length}** patches that have a bijective fixed map;
  free ÷ best fixed L2: median ${median(ratios).toFixed(3)}, range ${Math.min(...ratios).toFixed(3)}–${Math.max(...ratios).toFixed(3)}
- started from the measured map on ${count((p) => p.free?.init === 'measured')}, from the circle's on ${count((p) => p.free?.init === 'circle')}; untangled first on ${count((p) => p.free?.untangled)}; stopped by the iteration cap or time budget (not converged) on ${count((p) => p.free && !p.free.converged)}
`;
  }
  return `## Real patches

${n} disks cut from CGAL's closed sample meshes by \`scripts/patches.sh\` (geodesic balls of several radii
around extremities and pseudo-random seeds; only manifold disks of 1k–30k vertices are kept; see
\`bench/cut_patches.cpp\`), parameterized by \`build/native/real_patches\` with shape-preserving weights and
the default source. L2 texture stretch per boundary; ∞ marks a map that is not bijective (flipped or
degenerate triangles, or a boundary that overlaps itself), with the counts. *Worst ear*: an ear is a
triangle whose three corners are all boundary vertices; its ratio is its 2D/3D area ratio divided by the
map's (total 2D area / total 3D area): 1 is an ear mapped like the map as a whole, near 0 a collapsed one
(– when the patch has no ear). *Failed traces*: boundary vertices whose straightest path did not arrive,
placed at the fallback radius. ${freeNote}

Bijective maps: ${bijective}. Measured L2 above the circle's on ${worse} of ${both.length} patches where both are bijective.

${targets}

| patch | vertices | circle L2 | measured L2 | square L2 | free L2 | free: start, iterations | measured ÷ circle | worst ear (measured) | worst ear (circle) | failed traces |
|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|
${rows.join('\n')}
`;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) process.stdout.write(realPatchesSection(measurePatches()));
