// The consumer tests' static server (tests/js/*.test.mjs): serves a built app's folder on 127.0.0.1,
// optionally cross-origin isolated (COOP/COEP, as a deployment that wants threads sends), and with
// faults a real deployment has: a file answered by an HTML page (a single-page app's fallback for a
// file the bundler did not emit) or left hanging (a request that never completes).
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize } from 'node:path';

const MIME = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.mjs': 'text/javascript',
  '.css': 'text/css',
  '.wasm': 'application/wasm',
};
const ISOLATION = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };
const FALLBACK_PAGE = '<!doctype html><title>app</title><p>the app';

/**
 * Serves `folder`; resolves with { url, close }. Options: isolated (send COOP/COEP), fault(path, n) →
 * 'html' | 'hang' | null for the n-th request (from 1) of a path.
 */
export function serve(folder, { isolated = false, fault = () => null } = {}) {
  const counts = new Map();
  const hanging = new Set();
  const server = createServer((req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)).replace(/^(\.\.[/\\])+/, '');
    const headers = isolated ? { ...ISOLATION } : {};
    if (path === '/favicon.ico') return res.writeHead(204, headers).end();
    counts.set(path, (counts.get(path) ?? 0) + 1);
    const what = fault(path, counts.get(path));
    if (what === 'hang') return hanging.add(res);
    let body;
    try {
      body = what === 'html' ? null : readFileSync(join(folder, path.endsWith('/') ? path + 'index.html' : path));
    } catch {
      body = null;
    }
    if (body === null) return res.writeHead(200, { ...headers, 'content-type': 'text/html' }).end(FALLBACK_PAGE);
    res.writeHead(200, { ...headers, 'content-type': MIME[extname(path)] ?? 'application/octet-stream' }).end(body);
  });
  return new Promise((resolve) =>
    server.listen(0, '127.0.0.1', () =>
      resolve({
        url: `http://127.0.0.1:${server.address().port}`,
        close() {
          for (const res of hanging) res.destroy();
          server.close();
        },
      }),
    ),
  );
}
