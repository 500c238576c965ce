// A generated Markdown document's sections merged into the one on disk: docs/BENCHMARKS.md is written
// by several scripts (scripts/bench.mjs most of it, scripts/bench-wasm-threads.mjs one section) and
// holds hand-measured sections too, so a script replaces only the sections it generates.

/** The text before the first `## ` heading, then one entry per `## ` section (`### ` stays inside). */
export function splitSections(markdown) {
  const parts = markdown.split(/\n(?=## )/);
  const head = parts[0].startsWith('## ') ? '' : parts.shift();
  return {
    head,
    sections: parts.map((text) => ({
      title: text.slice(3, text.indexOf('\n') < 0 ? undefined : text.indexOf('\n')).trim(),
      text,
    })),
  };
}

/**
 * `existing` with each of `generated`'s sections in place of the one of the same name (sameName(a, b)
 * compares two titles; by default they are equal), its head replaced when `generated` has one, and
 * the generated sections it did not have appended in their order. Every other section stays as it was.
 */
export function mergeSections(existing, generated, sameName = (a, b) => a === b) {
  const old = splitSections(existing);
  const fresh = splitSections(generated);
  const used = new Set();
  const body = old.sections.map((section) => {
    const i = fresh.sections.findIndex((s, k) => !used.has(k) && sameName(s.title, section.title));
    if (i < 0) return section.text;
    used.add(i);
    return fresh.sections[i].text;
  });
  const added = fresh.sections.filter((_, k) => !used.has(k)).map((s) => s.text);
  // Split removed one newline before each heading; every part but the last ends with a blank line.
  const parts = [fresh.head || old.head, ...body, ...added].filter((t) => t !== '').map((t) => t.replace(/\n*$/, '\n'));
  return parts.join('\n');
}
