#!/usr/bin/env bash
# npm run bench: builds native and WASM, runs the CGAL comparison (bench-only, needs libcgal-dev) and
# every stage on every mesh, and writes docs/BENCHMARKS.md. Prints numbers; never fails on time.
source "$(dirname "$0")/common.sh"
ensure_system_packages
bash scripts/setup.sh libcgal-demo >/dev/null
mkdir -p build/data
[ -f build/data/data/meshes/nefertiti.off ] || tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C build/data data/meshes/nefertiti.off
bash scripts/build.sh all >/dev/null  # native, and WASM with its benchmarks
mkdir -p build/bench
rm -f build/bench/cgal.md
if [ "${SKIP_CGAL:-}" != 1 ]; then
  # bench-only: CGAL 5.5 from Debian, never a dependency of the library or the npm package
  bash scripts/bench-cgal.sh > build/bench/cgal.md.tmp && mv build/bench/cgal.md.tmp build/bench/cgal.md \
    || echo "bench: the CGAL comparison failed (see above); continuing without it"
fi
node scripts/bench.mjs
