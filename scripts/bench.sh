#!/usr/bin/env bash
# npm run bench: builds native and WASM, runs the CGAL comparison (bench-only, needs libcgal-dev) and
# every stage on every mesh, and writes docs/BENCHMARKS.md. Prints numbers; never fails on time.
source "$(dirname "$0")/common.sh"
ensure_system_packages
bash scripts/setup.sh libcgal-demo >/dev/null
mkdir -p build/data
[ -f build/data/data/meshes/nefertiti.off ] || tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C build/data data/meshes/nefertiti.off
bash scripts/build.sh native >/dev/null
bash scripts/build.sh wasm >/dev/null
if [ -f scripts/bench-cgal.sh ] && [ "${SKIP_CGAL:-}" != 1 ]; then
  bash scripts/bench-cgal.sh || echo "bench: the CGAL comparison failed (see above); continuing without it"
fi
node scripts/bench.mjs
