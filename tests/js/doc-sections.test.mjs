// scripts/doc-sections.mjs: the benchmark scripts rewrite only their own sections of docs/BENCHMARKS.md.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { mergeSections, splitSections } from '../../scripts/doc-sections.mjs';

const existing = `# Benchmarks

Generated on day 1.

## Stages (ms)

old stages

## Threads

hand-measured

### Stop 25

kept too

## Against CGAL 5.5.1-2 (native)

old CGAL table
`;

test('a generated section replaces its namesake in place; the head is replaced; hand-written sections stay', () => {
  const generated =
    '# Benchmarks\n\nGenerated on day 2.\n\n## Stages (ms)\n\nnew stages\n\n## Loading files\n\nnew loading\n';
  assert.equal(
    mergeSections(existing, generated),
    `# Benchmarks

Generated on day 2.

## Stages (ms)

new stages

## Threads

hand-measured

### Stop 25

kept too

## Against CGAL 5.5.1-2 (native)

old CGAL table

## Loading files

new loading
`,
  );
});

test('a section alone keeps the head, and names can be matched by a rule', () => {
  const cgal = (title) => title.startsWith('Against CGAL');
  const merged = mergeSections(
    existing,
    '## Against CGAL 5.6 (native)\n\nnew CGAL table\n',
    (a, b) => a === b || (cgal(a) && cgal(b)),
  );
  assert.ok(merged.startsWith('# Benchmarks\n\nGenerated on day 1.\n'));
  assert.ok(merged.includes('## Against CGAL 5.6 (native)\n\nnew CGAL table\n') && !merged.includes('old CGAL table'));
  assert.ok(merged.includes('### Stop 25\n\nkept too\n'));
});

test('merging the benchmarks document into itself changes nothing', () => {
  const doc = readFileSync(new URL('../../docs/BENCHMARKS.md', import.meta.url), 'utf8');
  assert.equal(mergeSections(doc, doc), doc);
  assert.ok(splitSections(doc).sections.some((s) => s.title === 'Threads in WebAssembly'));
});
