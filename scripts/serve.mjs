#!/usr/bin/env node
// Static file server for the straightest web page: serves the repository root on 127.0.0.1 so the
// page (/web/index.html), the npm package (/wasm/...) and three.js (/node_modules/three/...) share
// one origin. No dependencies (node:http only). `/` redirects to /web/index.html. Every response
// carries COOP/COEP (ISOLATION_HEADERS), so the page and its workers are cross-origin isolated and
// share memory: the package then runs its threaded WebAssembly module.
//
//   node scripts/serve.mjs [--port N]      (or PORT=N; default 8080)
//
// As a module: `startServer({ port, root, host })` resolves to the listening http.Server
// (port 0 picks a free port: read it from `server.address().port`).

import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
export const REPO_ROOT = path.resolve(here, '..');

const MIME_TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.wasm': 'application/wasm',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
  '.obj': 'text/plain; charset=utf-8',
  '.off': 'text/plain; charset=utf-8',
  '.ts': 'text/plain; charset=utf-8',
};

function mimeType(filePath) {
  return MIME_TYPES[path.extname(filePath).toLowerCase()] ?? 'application/octet-stream';
}

// Cross-origin isolation (crossOriginIsolated, SharedArrayBuffer): this origin only, in windows and
// in what it embeds; everything the page loads is same-origin, so nothing needs a CORP header.
export const ISOLATION_HEADERS = {
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
};

function send(res, status, body, headers = {}) {
  res.writeHead(status, { 'Content-Type': 'text/plain; charset=utf-8', ...ISOLATION_HEADERS, ...headers });
  res.end(body);
}

/** Maps a URL path to a file under root, or null if it would escape root. */
function resolveInside(root, urlPath) {
  let decoded;
  try {
    decoded = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  if (decoded.includes('\0')) return null;
  const segments = decoded.split(/[\\/]+/);
  if (segments.includes('..')) return null;
  const filePath = path.resolve(root, '.' + path.posix.normalize('/' + segments.join('/')));
  if (filePath !== root && !filePath.startsWith(root + path.sep)) return null;
  return filePath;
}

function handle(root, req, res) {
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    send(res, 405, 'method not allowed\n', { Allow: 'GET, HEAD' });
    return;
  }
  // Keep the raw path: `new URL` would silently collapse `..` segments, hiding traversal attempts.
  const rawPath = (req.url ?? '/').split(/[?#]/, 1)[0];
  if (rawPath === '/' || rawPath === '') {
    res.writeHead(302, { Location: '/web/index.html', ...ISOLATION_HEADERS });
    res.end();
    return;
  }
  let filePath = resolveInside(root, rawPath);
  if (filePath === null) {
    send(res, 403, 'forbidden\n');
    return;
  }
  fs.stat(filePath, (err, stat) => {
    if (!err && stat.isDirectory()) {
      if (!rawPath.endsWith('/')) {
        res.writeHead(301, { Location: rawPath + '/', ...ISOLATION_HEADERS });
        res.end();
        return;
      }
      filePath = path.join(filePath, 'index.html');
      stat = fs.existsSync(filePath) ? fs.statSync(filePath) : null;
    }
    if (err || !stat || !stat.isFile()) {
      send(res, 404, `not found: ${rawPath}\n`);
      return;
    }
    res.writeHead(200, {
      ...ISOLATION_HEADERS,
      'Content-Type': mimeType(filePath),
      'Content-Length': stat.size,
      'Cache-Control': 'no-cache',
    });
    if (req.method === 'HEAD') {
      res.end();
      return;
    }
    const stream = fs.createReadStream(filePath);
    stream.on('error', () => res.destroy());
    stream.pipe(res);
  });
}

/**
 * Starts the static server. Resolves to the listening http.Server.
 * @param {{port?: number, root?: string, host?: string}} [options]
 */
export function startServer({ port = 8080, root = REPO_ROOT, host = '127.0.0.1' } = {}) {
  const absRoot = path.resolve(root);
  const server = http.createServer((req, res) => handle(absRoot, req, res));
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      server.off('error', reject);
      resolve(server);
    });
  });
}

function portFromArgs(argv, env) {
  const i = argv.indexOf('--port');
  let value = env.PORT ?? '8080';
  if (i >= 0) value = argv[i + 1];
  const eq = argv.find((a) => a.startsWith('--port='));
  if (eq) value = eq.slice('--port='.length);
  const port = Number(value);
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    throw new Error(`invalid port: ${value}`);
  }
  return port;
}

const isMain = process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href;
if (isMain) {
  try {
    const server = await startServer({ port: portFromArgs(process.argv.slice(2), process.env) });
    const { port } = server.address();
    console.log(`straightest: serving http://127.0.0.1:${port}/ (Ctrl-C to stop)`);
    const stop = () => {
      server.close(() => process.exit(0));
      server.closeAllConnections();
    };
    process.on('SIGINT', stop);
    process.on('SIGTERM', stop);
  } catch (err) {
    console.error(`straightest: cannot start server: ${err.message}`);
    process.exit(1);
  }
}
