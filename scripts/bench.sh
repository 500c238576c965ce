#!/usr/bin/env bash
# Benchmarks, native and WASM (Node): prints tables, never fails on time.
source "$(dirname "$0")/common.sh"
ensure_system_packages
bash scripts/build.sh native >/dev/null
bash scripts/build.sh wasm >/dev/null
echo "## Straightest paths: all boundary vertices from the default source (height fields)"
echo
build/native/bench_paths native "${REPEATS:-5}"
node --no-experimental-fetch build/wasm/bench_paths.js wasm "${REPEATS:-5}" | tail -n +3
echo
echo "## Measured-boundary parameterization (shape-preserving), per stage and solver"
echo
build/native/bench_param native "${MAX_N:-1000}"
node --no-experimental-fetch build/wasm/bench_param.js wasm "${MAX_N:-1000}" | tail -n +3
