// The packed npm package as consumers use it: `npm pack`, then the tarball installed (offline: it has
// no dependencies) into a fresh project in which
//   - Node ESM imports 'straightest', 'straightest/inline', 'straightest/three' and the .wasm's export,
//     also where a `window` is defined (jsdom-style);
//   - TypeScript (strict, declarations checked) compiles tests/types/usage.ts with moduleResolution
//     bundler and node16 (TypeScript 7) and node (node10, TypeScript 5.9: 7 no longer has it);
//   - esbuild and Vite bundle browser apps (tests/package/app) without configuration, and headless
//     Chromium runs them: Vite's on the main thread, in a module worker and through straightest/worker
//     (transferred results, progress, cancel), esbuild's with the .wasm
//     copied next to the bundle, and the single-file variant (straightest/inline).
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { cpSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium } from '../package/chromium.mjs';

const root = fileURLToPath(new URL('../..', import.meta.url));
// The facts the consumers must find: the repository's own build, loaded directly.
const { createStraightest } = await import('../../wasm/index.js');
const reference = await createStraightest();
const capVertices = reference.sample('cap').info().vertices;
const mountainVertices = reference.sample('mountain').info().vertices;
const fixtures = join(root, 'tests/package');
const TIMEOUT = 300_000; // liveness only: a loaded 2-core machine is slow, never wrong
let dir, project, tarball;

function run(command, args, cwd) {
  return execFileSync(command, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

before(() => {
  dir = mkdtempSync(join(tmpdir(), 'straightest-consumer-'));
  run('npm', ['pack', '--pack-destination', dir, '--loglevel=error'], root);
  tarball = join(
    dir,
    readdirSync(dir).find((f) => f.endsWith('.tgz')),
  );
  project = join(dir, 'project');
  mkdirSync(project);
  writeFileSync(join(project, 'package.json'), JSON.stringify({ name: 'consumer', private: true, type: 'module' }));
  run('npm', ['install', '--offline', '--no-audit', '--no-fund', '--loglevel=error', tarball], project);
  // three (an optional peer dependency) and its types, as a three.js project has them.
  mkdirSync(join(project, 'node_modules/@types'), { recursive: true });
  symlinkSync(join(root, 'node_modules/three'), join(project, 'node_modules/three'), 'dir');
  symlinkSync(join(root, 'node_modules/@types/three'), join(project, 'node_modules/@types/three'), 'dir');
  cpSync(join(fixtures, 'app'), join(project, 'app'), { recursive: true });
  for (const f of ['node-main.mjs', 'jsdom-main.mjs']) cpSync(join(fixtures, f), join(project, f));
  cpSync(join(root, 'tests/types/usage.ts'), join(project, 'usage.ts'));
});

after(() => {
  if (dir && !process.env.KEEP_CONSUMER) rmSync(dir, { recursive: true, force: true });
});

test('the tarball holds the module, its types, the inline variant and the license, and no C++', () => {
  const files = run('tar', ['tzf', tarball], dir);
  for (const f of [
    'wasm/dist/straightest-core.wasm',
    'wasm/dist/straightest-core.mjs',
    'wasm/dist/straightest-core-embedded.js',
    'wasm/index.d.ts',
    'wasm/inline.js',
    'wasm/single.js',
    'wasm/single.d.ts',
    'wasm/three.d.ts',
    'wasm/worker.js',
    'wasm/worker-entry.js',
    'LICENSE',
    'README.md',
  ]) {
    assert.ok(files.includes(`package/${f}`), `${f} is not in the package`);
  }
  assert.doesNotMatch(files, /package\/core\//, 'C++ sources do not belong in the npm package');
});

test('Node ESM: the package, straightest/inline, straightest/three and the .wasm export', { timeout: TIMEOUT }, () => {
  const facts = JSON.parse(run(process.execPath, ['node-main.mjs'], project));
  assert.equal(facts.vertices, capVertices);
  assert.equal(facts.bijective, true);
  assert.equal(facts.inlineVertices, capVertices);
  assert.equal(facts.sameErrorClass, true);
  assert.deepEqual([facts.weldedVertices, facts.weldedComponents], [25, 1]);
  assert.equal(facts.wasmMagic, '0061736d');
  assert.equal(facts.missing.isStraightestError, true);
  assert.equal(facts.missing.category, 'io');
  assert.match(facts.missing.message, /http:\/\/127\.0\.0\.1:9\/straightest-core\.wasm/);
});

test('a jsdom-style environment (window defined in Node) loads the module from disk', { timeout: TIMEOUT }, () => {
  const facts = JSON.parse(run(process.execPath, ['jsdom-main.mjs'], project));
  assert.equal(facts.vertices, mountainVertices);
  assert.ok(facts.reached > 0);
});

test(
  'TypeScript strict compiles a usage of the whole API with bundler, node16 and node resolution',
  { timeout: TIMEOUT },
  () => {
    const base = {
      strict: true,
      noEmit: true,
      target: 'es2022',
      lib: ['es2022', 'esnext.disposable', 'dom'],
      types: [],
      skipLibCheck: false,
      noUnusedLocals: true,
      noUnusedParameters: true,
    };
    // The declarations themselves are checked once (bundler, no skipLibCheck: that also checks three's
    // 480 declaration files, most of the time here); node16 and node10 check how the package resolves
    // (exports, typesVersions) and the usage against it. TypeScript 7 no longer has node10: 5.9 checks it.
    const configs = [
      ['bundler', { module: 'esnext', moduleResolution: 'bundler' }, 'node_modules/.bin/tsc'],
      ['node16', { module: 'node16', moduleResolution: 'node16', skipLibCheck: true }, 'node_modules/.bin/tsc'],
      [
        'node',
        { module: 'commonjs', moduleResolution: 'node', skipLibCheck: true },
        'node_modules/typescript5/bin/tsc',
      ],
    ];
    for (const [name, options, tsc] of configs) {
      const config = join(project, `tsconfig.${name}.json`);
      writeFileSync(config, JSON.stringify({ compilerOptions: { ...base, ...options }, files: ['usage.ts'] }));
      try {
        run(join(root, tsc), ['-p', config], project);
      } catch (e) {
        assert.fail(`moduleResolution ${name}:\n${e.stdout}${e.stderr}`);
      }
    }
  },
);

const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.wasm': 'application/wasm' };

/** Serves `folder` on 127.0.0.1 (a free port); resolves with { server, url }. */
function serve(folder) {
  const server = createServer((req, res) => {
    if (req.url === '/favicon.ico') return res.writeHead(204).end();
    const path = normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)).replace(/^(\.\.[/\\])+/, '');
    try {
      const body = readFileSync(join(folder, path));
      res.writeHead(200, { 'content-type': MIME[extname(path)] ?? 'application/octet-stream' }).end(body);
    } catch {
      res.writeHead(404, { 'content-type': 'text/html' }).end('<!doctype html><title>not found</title>');
    }
  });
  return new Promise((resolve) =>
    server.listen(0, '127.0.0.1', () => resolve({ server, url: `http://127.0.0.1:${server.address().port}` })),
  );
}

test(
  'esbuild and Vite bundle the package for the browser without configuration, and Chromium runs them',
  { timeout: TIMEOUT },
  async () => {
    const out = join(project, 'out');
    // esbuild: the .wasm copied next to the bundle, and the inline variant.
    const esbuild = await import('esbuild');
    const built = await esbuild.build({
      entryPoints: ['app/esbuild-main.js', 'app/inline-main.js'],
      absWorkingDir: project,
      bundle: true,
      platform: 'browser',
      format: 'esm',
      outdir: join(out, 'esbuild'),
      logLevel: 'silent',
    });
    assert.deepEqual(built.warnings, [], 'esbuild warned');
    cpSync(
      join(project, 'node_modules/straightest/wasm/dist/straightest-core.wasm'),
      join(out, 'esbuild/straightest-core.wasm'),
    );
    for (const page of ['esbuild-main', 'inline-main']) {
      writeFileSync(
        join(out, `esbuild/${page}.html`),
        `<!doctype html><script type="module" src="./${page}.js"></script>`,
      );
    }
    // Vite: its production build, no config file.
    const vite = await import('vite');
    const warnings = [];
    const logger = vite.createLogger('warn');
    logger.warn = (message) => warnings.push(message);
    logger.warnOnce = (message) => warnings.push(message);
    await vite.build({
      root: join(project, 'app'),
      configFile: false,
      logLevel: 'warn',
      customLogger: logger,
      build: { outDir: join(out, 'vite'), emptyOutDir: true },
    });
    assert.deepEqual(warnings, [], 'Vite warned');

    const servers = { vite: await serve(join(out, 'vite')), esbuild: await serve(join(out, 'esbuild')) };
    const browser = await launchChromium();
    try {
      const results = {};
      for (const page of ['vite/index.html', 'esbuild/esbuild-main.html', 'esbuild/inline-main.html']) {
        const [bundler, file] = page.split('/');
        const tab = await browser.newPage();
        const errors = [];
        tab.on('pageerror', (e) => errors.push(String(e)));
        tab.on('console', (m) => {
          if (m.type() === 'error') errors.push(m.text());
        });
        await tab.goto(`${servers[bundler].url}/${file}`);
        await tab
          .waitForFunction(() => globalThis.__result, null, { timeout: 90_000 })
          .catch((e) => assert.fail(`${page}: no result (${e.message}); ${errors.join('; ')}`));
        results[page] = await tab.evaluate(() => globalThis.__result);
        assert.deepEqual(errors, [], `${page}: page errors`);
        await tab.close();
      }
      assert.deepEqual(results['vite/index.html'].main, { vertices: capVertices, bijective: true });
      assert.equal(results['vite/index.html'].worker.vertices, mountainVertices);
      assert.ok(results['vite/index.html'].worker.reached > 0);
      const helper = results['vite/index.html'].helper;
      assert.deepEqual(
        [helper.vertices, helper.uvIsFloat32, helper.uvLength, helper.bijective],
        [capVertices, true, 2 * capVertices, true],
      );
      assert.ok(helper.stages.includes('solve'), `progress stages: ${helper.stages}`);
      assert.equal(helper.afterCancel, 'cancelled');
      // The name lists are the module's, read in the worker; the file-name rule is the core's.
      assert.equal(helper.format, 'off');
      assert.deepEqual(
        [helper.samples, helper.boundaryKinds, helper.weightKinds],
        [reference.sampleNames(), reference.boundaryKinds, reference.weightKinds],
      );
      // shootGeodesic and exactShortestPaths through the worker give what they give on the main thread.
      const cap = reference.sample('cap');
      const target = helper.geodesics.target;
      const shot = cap.shootGeodesic({ toward: { vertex: target } });
      const exact = cap.exactShortestPaths({ targets: [target] });
      cap.delete();
      assert.deepEqual(helper.geodesics, {
        target,
        shotLength: shot.length,
        missDistance: shot.missDistance,
        shotPoints: true,
        exactDistance: exact.distances[0],
        exactPoints: true,
      });
      assert.ok(helper.geodesics.exactDistance <= shot.straightestDistance + 1e-9);
      assert.deepEqual(results['esbuild/esbuild-main.html'], { vertices: capVertices, bijective: true });
      assert.deepEqual(results['esbuild/inline-main.html'], { vertices: capVertices, bijective: true });
    } finally {
      await browser.close();
      for (const { server } of Object.values(servers)) server.close();
    }
  },
);
