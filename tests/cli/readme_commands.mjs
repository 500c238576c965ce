// Every command example in README.md and docs/CLI.md runs as written from the repository root: each ```sh block that
// calls the CLI (build/native/straightest, replaced by --cli PATH when given) is run line by line with
// bash; a line that exits non-zero fails the test with its block's text. The comment lines under a
// command are its sample output: every JSON key they show ("key":) must be in what the command printed,
// and an "# exit N" line must be printed too. The npm example (the ```js block that reads a file) runs
// against the package itself when the WebAssembly module is built (wasm/dist), and is skipped otherwise.
// Run by ctest as `cli_readme`: node tests/cli/readme_commands.mjs --cli build/native/straightest
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const cliArg = process.argv.indexOf('--cli');
const cli = cliArg > 0 ? resolve(process.argv[cliArg + 1]) : join(root, 'build/native/straightest');
const documents = ['README.md', 'docs/CLI.md'].map((name) => ({ name, text: readFileSync(join(root, name), 'utf8') }));

/** The fenced blocks of a language in every document: their text, document and starting line. */
function blocks(language, names = documents.map((d) => d.name)) {
  const found = [];
  const fence = new RegExp('^```' + language + '\\n([\\s\\S]*?)^```', 'gm');
  for (const { name, text } of documents.filter((d) => names.includes(d.name)))
    for (const m of text.matchAll(fence))
      found.push({ text: m[1], document: name, line: text.slice(0, m.index).split('\n').length });
  return found;
}

/** A block's commands (continuation lines joined), each with the comment lines that follow it. */
function commands(text) {
  const result = [];
  let pending = '';
  for (const raw of text.split('\n')) {
    const line = raw.trimEnd();
    if (pending || !line.trimStart().startsWith('#')) {
      if (!line && !pending) continue;
      pending += line.endsWith('\\') ? line.slice(0, -1) : line;
      if (!line.endsWith('\\')) {
        result.push({ command: pending, sample: [] });
        pending = '';
      }
    } else if (result.length) {
      result[result.length - 1].sample.push(line.trimStart().slice(1));
    }
  }
  return result;
}

let ran = 0;
const failures = [];
for (const block of blocks('sh')) {
  if (!block.text.includes('build/native/straightest')) continue;
  for (const { command, sample } of commands(block.text)) {
    const shell = command.replaceAll('build/native/straightest', JSON.stringify(cli));
    const run = spawnSync('bash', ['-c', shell], { cwd: root, encoding: 'utf8', maxBuffer: 1 << 30 });
    ran += 1;
    const where = `${block.document} block at line ${block.line}:\n${block.text}\ncommand: ${command}\n`;
    if (run.status !== 0) {
      failures.push(`${where}exit ${run.status ?? run.signal}\n${(run.stderr || '').slice(0, 2000)}`);
      continue;
    }
    const shown = sample.join('\n');
    const keys = [...shown.matchAll(/"([a-z_0-9]+)":/g)].map((m) => m[1]);
    const missing = keys.filter((key) => !run.stdout.includes(`"${key}":`));
    if (missing.length) failures.push(`${where}its sample output shows keys it does not print: ${missing.join(', ')}`);
    for (const m of shown.matchAll(/^\s*(exit \d+)\s*$/gm))
      if (!run.stdout.includes(m[1])) failures.push(`${where}expected "${m[1]}" in its output`);
  }
}

// The npm example: `import … from 'straightest'` resolves to this package (a package may import itself
// by name from inside its own directory), so the file is written inside the repository.
const npmExample = blocks('js').find((b) => b.text.includes("from 'straightest'") && b.text.includes('readFileSync'));
if (!npmExample) {
  failures.push('README.md has no npm example that reads a file (```js with readFileSync)');
} else if (!existsSync(join(root, 'wasm/dist/straightest-core.wasm'))) {
  console.log('readme: npm example skipped (no wasm/dist: run scripts/build.sh wasm)');
} else {
  const dir = mkdtempSync(join(root, 'build', 'readme-'));
  const file = join(dir, 'example.mjs');
  writeFileSync(file, npmExample.text);
  const run = spawnSync(process.execPath, [file], { cwd: root, encoding: 'utf8' });
  rmSync(dir, { recursive: true, force: true });
  ran += 1;
  if (run.status !== 0)
    failures.push(
      `README.md npm example at line ${npmExample.line}:\n${npmExample.text}\nexit ${run.status}\n${run.stderr}`,
    );
}

for (const failure of failures) console.error(`FAILED: ${failure}\n`);
console.log(`readme: ${ran} commands run, ${failures.length} failures`);
process.exit(failures.length ? 1 : 0);
