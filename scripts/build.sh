#!/usr/bin/env bash
# Builds the native library, CLI and tests (build/native) and/or the WASM module and tests
# (build/wasm), then copies the module into the npm package (wasm/dist). Usage: build.sh native|wasm|all
source "$(dirname "$0")/common.sh"
target="${1:-all}"
if [ "$target" = native ] || [ "$target" = all ]; then
  cmake --preset native >/dev/null
  cmake --build --preset native
fi
if [ "$target" = wasm ] || [ "$target" = all ]; then
  cmake --preset wasm >/dev/null
  cmake --build --preset wasm
  mkdir -p wasm/dist
  cp build/wasm/straightest-core.mjs build/wasm/straightest-core.wasm wasm/dist/
fi
