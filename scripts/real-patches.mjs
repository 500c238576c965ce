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
  if (r.bijective) return r.l2 < 100 ? r.l2.toFixed(3) : r.l2.toPrecision(3);
  const why = [['flipped', r.flipped], ['degenerate', r.degenerate], ['overlaps', r.overlaps]]
    .filter(([, n]) => n > 0)
    .map(([what, n]) => `${n} ${what}`);
  return `∞ (${why.join(', ')})`;
}

const ear = (r) => (!r || r.error || r.worst_ear === null ? '–' : r.worst_ear.toPrecision(2));

/// Runs real_patches on the patch set (building it with scripts/patches.sh when it is missing) and
/// returns the patches' JSON objects, or null when the set cannot be made.
export function measurePatches() {
  const dir = join(root, 'build/data/patches');
  const tool = join(root, 'build/native/real_patches');
  if (!existsSync(tool) || !existsSync(dir) || !readdirSync(dir).some((f) => f.endsWith('.off'))) {
    execFileSync('bash', [join(root, 'scripts/patches.sh')], { stdio: ['ignore', 'inherit', 'inherit'] });
  }
  const files = readdirSync(dir)
    .filter((f) => f.endsWith('.off'))
    .sort()
    .map((f) => join(dir, f));
  const out = execFileSync(tool, files, { encoding: 'utf8', maxBuffer: 1 << 26, stdio: ['ignore', 'pipe', 'ignore'] });
  return out
    .split('\n')
    .filter((line) => line.startsWith('{'))
    .map((line) => JSON.parse(line));
}

/// The markdown section for the patches' results.
export function realPatchesSection(patches) {
  const rows = patches.map((p) => {
    const ratio = l2Of(p.measured) / l2Of(p.circle);
    return (
      `| ${p.patch} | ${p.vertices} | ${boundaries.map((b) => cell(p[b])).join(' | ')} | ` +
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
  const bestFixed = (p) => Math.min(l2Of(p.circle), l2Of(p.measured), l2Of(p.square));
  const freeLines = hasFree
    ? `\n- free L2 below the best fixed boundary's on **${count((p) => l2Of(p.free) < bestFixed(p))} of ${n}** patches`
    : '';
  const freeNote = hasFree
    ? 'Free: the free boundary (a fixed-boundary start refined without folding).'
    : 'Free: n/a until the core has the free boundary.';
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

- measured L2 > circle L2 on **${worse} of ${both.length}** patches where both are bijective, > 1.25× the circle on **${muchWorse}**
- bijective maps: ${bijective}
- measured map's worst ear below 1e-2 of the mean ratio on **${earBelow}** patches${freeLines}

| patch | vertices | circle L2 | measured L2 | square L2 | free L2 | measured ÷ circle | worst ear (measured) | worst ear (circle) | failed traces |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|
${rows.join('\n')}
`;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) process.stdout.write(realPatchesSection(measurePatches()));
