// The packed package built by each bundler docs/API.md gives advice for, as a consumer builds it, and
// run in Chromium (tests/package/bundlers/app, served by tests/package/serve.mjs):
//   - Vite and webpack production builds, served cross-origin isolated, start the threaded module on the
//     main thread and in straightest/worker; Vite's build with the threaded loader answered by an HTML
//     page, or left hanging for the workers, still resolves — on one thread, with the reason;
//   - straightest/single built by Vite and webpack emits one .wasm and none of the threaded assets;
//   - Parcel builds straightest, straightest/inline and straightest/worker with nothing but the package
//     exports switch Parcel documents, and without Node polyfills;
//   - esbuild with straightest/worker (worker-entry bundled, createWorker), `await using` on a worker
//     mesh and the worker, and a missing worker script named with its status;
//   - Rollup with @rollup/plugin-node-resolve and the .wasm copied.
// webpack, Parcel and Rollup are not the repository's dependencies: tests/package/bundlers/package.json
// (and its lockfile) is installed once under build/consumer-bundlers/ and again when the lockfile
// changes. Without the npm registry, those builds are skipped, saying why; Vite and esbuild still run.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { serve } from '../package/serve.mjs';
import { launchChromium, openApp } from '../package/chromium.mjs';

const root = fileURLToPath(new URL('../..', import.meta.url));
const spec = join(root, 'tests/package/bundlers');
const work = join(root, 'build/consumer-bundlers');
const app = join(work, 'app');
const out = join(work, 'out');
const TIMEOUT = 600_000; // liveness only: an install or a build on a loaded 2-core machine is slow, never wrong
let browser;
let unavailable = null; // why webpack, Parcel and Rollup are missing, or null

function run(command, args, cwd, timeout = TIMEOUT) {
  return execFileSync(command, args, { cwd, encoding: 'utf8', timeout, stdio: ['ignore', 'pipe', 'pipe'] });
}

/** Installs the bundlers (npm ci) unless the installed tree is the lockfile's; null, or why they are missing. */
function installBundlers() {
  const lock = readFileSync(join(spec, 'package-lock.json'), 'utf8');
  const stamp = join(work, 'node_modules/.straightest-lockfile');
  if (existsSync(stamp) && readFileSync(stamp, 'utf8') === lock) return null;
  mkdirSync(work, { recursive: true });
  for (const f of ['package.json', 'package-lock.json']) cpSync(join(spec, f), join(work, f));
  try {
    run('npm', ['ci', '--no-audit', '--no-fund', '--loglevel=error'], work);
  } catch (error) {
    try {
      run('npm', ['ping', '--loglevel=error'], work, 60_000);
    } catch {
      return `the npm registry is unreachable (npm ping failed), so webpack, Parcel and Rollup could not be installed`;
    }
    throw error;
  }
  writeFileSync(stamp, lock);
  return null;
}

/** The packed package, installed as npm would (it has no dependencies): extracted into node_modules. */
function installPackage() {
  const dir = mkdtempSync(join(tmpdir(), 'straightest-pack-'));
  try {
    run('npm', ['pack', '--pack-destination', dir, '--loglevel=error'], root);
    const tarball = readdirSync(dir).find((f) => f.endsWith('.tgz'));
    run('tar', ['xzf', join(dir, tarball), '-C', dir]);
    const target = join(work, 'node_modules/straightest');
    rmSync(target, { recursive: true, force: true });
    mkdirSync(join(work, 'node_modules'), { recursive: true });
    cpSync(join(dir, 'package'), target, { recursive: true });
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** Imports a bundler installed under build/consumer-bundlers. */
const bundler = (name) => import(pathToFileURL(join(work, 'node_modules', name)).href + '/' + mainOf(name));

function mainOf(name) {
  const manifest = JSON.parse(readFileSync(join(work, 'node_modules', name, 'package.json'), 'utf8'));
  const exported = manifest.exports?.['.'];
  const entry =
    typeof exported === 'string' ? exported : (exported?.import?.default ?? exported?.import ?? exported?.default);
  return (typeof entry === 'string' ? entry : (manifest.main ?? 'index.js')).replace(/^\.\//, '');
}

function page(dir, entry) {
  writeFileSync(join(dir, `${entry}.html`), `<!doctype html><script type="module" src="./${entry}.js"></script>`);
}

const wasmFile = () => join(work, 'node_modules/straightest/wasm/dist/straightest-core.wasm');

before(async () => {
  mkdirSync(work, { recursive: true });
  unavailable = installBundlers();
  installPackage();
  rmSync(app, { recursive: true, force: true });
  rmSync(out, { recursive: true, force: true });
  cpSync(join(spec, 'app'), app, { recursive: true });
  browser = await launchChromium();
});

after(async () => {
  await browser?.close();
});

/** Opens `entry`.html of a built folder, served with the options; the app's result and the page's errors. */
async function load(folder, entry, options = {}) {
  const server = await serve(folder, options);
  try {
    return await openApp(browser, `${server.url}/${entry}.html`);
  } finally {
    server.close();
  }
}

/** The threads app's result when the threaded module runs everywhere. */
function assertThreads({ result, errors }, what) {
  assert.deepEqual(errors, [], `${what}: page errors`);
  assert.equal(result.error, undefined, `${what}: ${result.error}`);
  assert.equal(result.isolated, true);
  for (const side of ['main', 'worker']) {
    assert.ok(
      result[side].threads > 1,
      `${what} ${side}: ${result[side].threads} threads (${result[side].threadsUnavailable})`,
    );
    assert.equal(result[side].threadsUnavailable, null);
    assert.equal(result[side].bijective, true);
  }
}

/** The threads app's result when the threaded module cannot start: one thread, and why. */
function assertFellBack({ result }, reason, what) {
  assert.equal(result.error, undefined, `${what}: ${result.error}`);
  for (const side of ['main', 'worker']) {
    assert.equal(result[side].threads, 1, `${what} ${side}`);
    assert.match(result[side].threadsUnavailable, reason, `${what} ${side}`);
    assert.equal(result[side].bijective, true);
  }
}

test(
  'Vite: threads start under COOP/COEP; a loader served as HTML or hanging falls back with the reason',
  { timeout: TIMEOUT },
  async () => {
    const vite = await import('vite');
    const warnings = [];
    const logger = vite.createLogger('warn');
    logger.warn = (message) => warnings.push(message);
    logger.warnOnce = (message) => warnings.push(message);
    await vite.build({
      root: app,
      configFile: false,
      logLevel: 'warn',
      customLogger: logger,
      build: { outDir: join(out, 'vite'), emptyOutDir: true, rollupOptions: { input: join(app, 'threads.html') } },
    });
    assert.deepEqual(warnings, [], 'Vite warned');
    const folder = join(out, 'vite');
    assertThreads(await load(folder, 'threads', { isolated: true }), 'vite');
    // Not isolated: one thread, the documented reason.
    const plain = await load(folder, 'threads');
    assert.equal(plain.result.main.threads, 1);
    assert.match(plain.result.main.threadsUnavailable, /not cross-origin isolated/);
    // The threaded loader (the only .mjs Vite emits) answered by the app's HTML page, as a single-page
    // app's fallback answers a file the deployment lacks: at once, on one thread.
    const loader = (path) => path.endsWith('.mjs');
    const html = await load(folder, 'threads', { isolated: true, fault: (path) => (loader(path) ? 'html' : null) });
    assertFellBack(html, /could not be started/, 'loader as HTML');
    assert.ok(
      html.warnings.some((w) => /straightest: running on one thread/.test(w)),
      'said once on the console',
    );
    // The loader served to the page but never to the threads' workers: the bound, then one thread.
    const hang = await load(folder, 'threads', {
      isolated: true,
      fault: (path, n) => (loader(path) && n > 1 ? 'hang' : null),
    });
    assertFellBack(hang, /did not start within 10 s/, 'hanging loader');
  },
);

test('webpack: a production build served cross-origin isolated starts threads', { timeout: TIMEOUT }, async (t) => {
  if (unavailable) return t.skip(unavailable);
  const { default: webpack } = await bundler('webpack');
  const stats = await new Promise((resolve, reject) =>
    webpack(
      {
        mode: 'production',
        context: app,
        entry: { threads: './threads.js' },
        output: { path: join(out, 'webpack'), clean: true },
        performance: { hints: false },
      },
      (error, result) => (error ? reject(error) : resolve(result)),
    ),
  );
  assert.equal(stats.hasErrors(), false, stats.toString('errors-only'));
  assert.deepEqual(stats.toJson({ all: false, warnings: true }).warnings, [], 'webpack warned');
  page(join(out, 'webpack'), 'threads');
  assertThreads(await load(join(out, 'webpack'), 'threads', { isolated: true }), 'webpack');
});

/** Every file under `folder`, relative to it. */
function filesUnder(folder) {
  return readdirSync(folder, { recursive: true }).map(String);
}

test(
  'Vite and webpack: straightest/single emits one .wasm and none of the threaded assets, and runs',
  { timeout: TIMEOUT },
  async (t) => {
    const vite = await import('vite');
    const viteOut = join(out, 'vite-single');
    await vite.build({
      root: app,
      configFile: false,
      logLevel: 'warn',
      build: { outDir: viteOut, emptyOutDir: true, rollupOptions: { input: join(app, 'single.html') } },
    });
    const folders = [viteOut];
    if (!unavailable) {
      const { default: webpack } = await bundler('webpack');
      const webpackOut = join(out, 'webpack-single');
      const config = { mode: 'production', context: app, entry: { single: './single.js' } };
      const stats = await new Promise((resolve, reject) =>
        webpack({ ...config, output: { path: webpackOut, clean: true }, performance: { hints: false } }, (e, r) =>
          e ? reject(e) : resolve(r),
        ),
      );
      assert.equal(stats.hasErrors(), false, stats.toString('errors-only'));
      page(webpackOut, 'single');
      folders.push(webpackOut);
    } else {
      t.diagnostic(`webpack not checked: ${unavailable}`);
    }
    for (const folder of folders) {
      const files = filesUnder(folder);
      assert.equal(files.filter((f) => f.endsWith('.wasm')).length, 1, `${folder}: ${files}`);
      assert.deepEqual(
        files.filter((f) => /thread|worker/i.test(f)),
        [],
        `${folder} holds threaded assets`,
      );
      const { result, errors } = await load(folder, 'single', { isolated: true });
      assert.deepEqual(errors, []);
      assert.deepEqual([result.threads, result.bijective], [1, true], folder);
      assert.match(result.threadsUnavailable, /single-threaded module only/);
    }
  },
);

test(
  'Parcel builds straightest, straightest/inline and straightest/worker, without Node polyfills',
  { timeout: TIMEOUT },
  async (t) => {
    if (unavailable) return t.skip(unavailable);
    const { Parcel } = await bundler('@parcel/core');
    const parcel = new Parcel({
      entries: ['threads.html', 'inline.html', 'worker-only.html'].map((f) => join(app, f)),
      defaultConfig: join(work, 'node_modules/@parcel/config-default/index.json'),
      mode: 'production',
      shouldDisableCache: true,
      shouldAutoInstall: false,
      logLevel: 'warn',
      defaultTargetOptions: { distDir: join(out, 'parcel'), publicUrl: './' },
    });
    const { bundleGraph } = await parcel.run();
    assert.ok(bundleGraph.getBundles().length > 0);
    const folder = join(out, 'parcel');
    // Parcel rebuilds the threaded loader as a bundle of its own, without its export: one thread, and why.
    assertFellBack(await load(folder, 'threads', { isolated: true }), /exports no factory/, 'parcel');
    const inline = await load(folder, 'inline');
    assert.deepEqual(inline.errors, []);
    assert.deepEqual([inline.result.threads, inline.result.bijective], [1, true]);
    const worker = await load(folder, 'worker-only');
    assert.deepEqual(worker.errors, []);
    assert.deepEqual(worker.result.bijective, true);
  },
);

test(
  'esbuild: straightest/worker with worker-entry bundled, `await using`, a missing worker named',
  { timeout: TIMEOUT },
  async () => {
    const esbuild = await import('esbuild');
    const folder = join(out, 'esbuild');
    const built = await esbuild.build({
      entryPoints: [
        { in: join(app, 'esbuild-worker.js'), out: 'esbuild-worker' },
        { in: join(work, 'node_modules/straightest/wasm/worker-entry.js'), out: 'worker-entry' },
        { in: join(app, 'plain.js'), out: 'plain' },
      ],
      absWorkingDir: work,
      bundle: true,
      platform: 'browser',
      format: 'esm',
      outdir: folder,
      logLevel: 'silent',
    });
    assert.deepEqual(built.warnings, [], 'esbuild warned');
    cpSync(wasmFile(), join(folder, 'straightest-core.wasm'));
    for (const entry of ['esbuild-worker', 'plain']) page(folder, entry);
    const { result } = await load(folder, 'esbuild-worker');
    assert.equal(result.error, undefined, result.error);
    assert.equal(result.meshDeleted, true, '`await using` deleted the mesh');
    assert.ok(result.vertices > 0);
    assert.equal(result.missing.rejected, true);
    assert.equal(result.missing.category, 'io');
    assert.match(result.missing.message, /no-such-worker\.js: HTTP 200 OK, text\/html/);
    const plain = await load(folder, 'plain', { isolated: true });
    assert.deepEqual([plain.result.threads, plain.result.bijective], [1, true]);
    assert.match(plain.result.threadsUnavailable, /wasmUrl/);
  },
);

test('Rollup with @rollup/plugin-node-resolve and the .wasm copied', { timeout: TIMEOUT }, async (t) => {
  if (unavailable) return t.skip(unavailable);
  const { rollup } = await bundler('rollup');
  const { nodeResolve } = await bundler('@rollup/plugin-node-resolve');
  const warnings = [];
  const bundle = await rollup({
    input: join(app, 'plain.js'),
    plugins: [nodeResolve({ browser: true })],
    onwarn: (warning) => warnings.push(String(warning.message)),
  });
  const folder = join(out, 'rollup');
  await bundle.write({ dir: folder, format: 'es' });
  await bundle.close();
  assert.deepEqual(warnings, [], 'Rollup warned');
  cpSync(wasmFile(), join(folder, 'straightest-core.wasm'));
  page(folder, 'plain');
  const { result, errors } = await load(folder, 'plain');
  assert.deepEqual(errors, []);
  assert.deepEqual([result.threads, result.bijective], [1, true]);
});
