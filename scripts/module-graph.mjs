// Prints the core's module graph from its #include lines: one "module → module" edge per pair, with the
// number of includes behind it, and exits 1 if an edge points against the layering of
// cmake/StraightestModules.cmake (which the build enforces too: a module's include path holds only the
// modules below it).
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';

const root = new URL('..', import.meta.url).pathname;
const core = join(root, 'core');

function filesUnder(dir) {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return filesUnder(path);
    return /\.(cpp|hpp)$/.test(name) ? [path] : [];
  });
}

function declaredLayers() {
  const text = readFileSync(join(root, 'cmake/StraightestModules.cmake'), 'utf8');
  const deps = new Map();
  for (const [, module, list] of text.matchAll(/set\(STRAIGHTEST_DEPS_(\w+) ([^)]*)\)/g))
    deps.set(module, list.replace(/"/g, '').split(/\s+/).filter(Boolean));
  return deps;
}

function reachable(deps, from) {
  const seen = new Set();
  const stack = [...(deps.get(from) ?? [])];
  while (stack.length) {
    const m = stack.pop();
    if (!seen.has(m)) {
      seen.add(m);
      stack.push(...(deps.get(m) ?? []));
    }
  }
  return seen;
}

const deps = declaredLayers();
const modules = readdirSync(core).filter((m) => deps.has(m));
const edges = new Map();
for (const module of modules) {
  for (const file of filesUnder(join(core, module))) {
    for (const [, target] of readFileSync(file, 'utf8').matchAll(/#include "straightest\/(\w+)\//g)) {
      if (target === module) continue;
      const key = `${module} → ${target}`;
      edges.set(key, (edges.get(key) ?? 0) + 1);
    }
  }
}
let wrong = 0;
for (const [edge, count] of [...edges].sort()) {
  const [from, to] = edge.split(' → ');
  const allowed = reachable(deps, from).has(to);
  if (!allowed) wrong += 1;
  console.log(`${edge.padEnd(24)} ${String(count).padStart(3)}${allowed ? '' : '  AGAINST THE LAYERS'}`);
}
console.log(`${modules.length} modules (${relative(root, core)}/), ${edges.size} edges, ${wrong} against the layers`);
process.exit(wrong ? 1 : 0);
