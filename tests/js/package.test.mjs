// The packed npm package installs into a fresh folder and works with a plain `import` in Node.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync, readdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../..', import.meta.url));

test('npm pack gives a package a fresh folder can install and import', () => {
  const dir = mkdtempSync(join(tmpdir(), 'straightest-pack-'));
  try {
    execFileSync('npm', ['pack', '--pack-destination', dir, '--loglevel=error'], { cwd: root, stdio: 'pipe' });
    const tarball = readdirSync(dir).find((f) => f.endsWith('.tgz'));
    assert.ok(tarball, 'npm pack produced no tarball');
    const app = join(dir, 'app');
    execFileSync('mkdir', ['-p', app]);
    writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
    execFileSync('npm', ['install', '--no-audit', '--no-fund', '--loglevel=error', join(dir, tarball)], { cwd: app, stdio: 'pipe' });
    writeFileSync(join(app, 'main.js'), [
      "import { createStraightest } from 'straightest';",
      'const st = await createStraightest();',
      "const mesh = st.loadMesh('v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n', 'obj');",
      'console.log(JSON.stringify(mesh.info()));',
      'mesh.delete();',
    ].join('\n'));
    const out = execFileSync(process.execPath, ['main.js'], { cwd: app, encoding: 'utf8' });
    const info = JSON.parse(out);
    assert.equal(info.vertices, 3);
    assert.equal(info.faces, 1);
    const files = execFileSync('tar', ['tzf', join(dir, tarball)], { encoding: 'utf8' });
    assert.match(files, /package\/wasm\/dist\/straightest-core\.wasm/);
    assert.match(files, /package\/wasm\/index\.d\.ts/);
    assert.doesNotMatch(files, /package\/core\//, 'C++ sources do not belong in the npm package');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
