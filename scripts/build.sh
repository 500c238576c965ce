#!/usr/bin/env bash
# Builds the native library, CLI, tests and benchmarks (build/native) and/or the WASM modules and
# tests (build/wasm; `all` adds the WASM benchmarks that npm run bench runs), then copies the modules
# into the npm package (wasm/dist); `sanitize` builds the native
# tests with ASan + UBSan (build/sanitize); `module` builds only the WASM modules the npm package ships
# (npm run build:wasm, npm start: no tests, no benchmarks): the single-threaded one and the threaded one
# (pthreads, in wasm/dist/threads/), which the page uses under npm start's server (cross-origin
# isolated) and the package in Node; `tsan` builds the threaded loops' tests with ThreadSanitizer
# (build/tsan). Usage: build.sh native|wasm|module|sanitize|tsan|all
# The native build treats warnings as errors (STRAIGHTEST_WERROR): npm test and CI run through here, so a
# new warning fails there instead of scrolling by; a hand-made `cmake --preset native` keeps them warnings.
source "$(dirname "$0")/common.sh"
target="${1:-all}"
if [ "$target" = native ] || [ "$target" = all ]; then
  configure_preset native -DSTRAIGHTEST_WERROR=ON
  cmake --build --preset native
fi
if [ "$target" = sanitize ]; then
  configure_preset sanitize
  cmake --build --preset sanitize --target core_tests straightest
fi
if [ "$target" = tsan ]; then  # ThreadSanitizer: the core and the threaded loops' tests only
  configure_preset tsan
  cmake --build --preset tsan
fi
if [ "$target" = wasm ] || [ "$target" = module ] || [ "$target" = all ]; then
  configure_preset wasm
  if [ "$target" = module ]; then
    cmake --build --preset wasm --target straightest_wasm straightest_wasm_threads
  elif [ "$target" = wasm ]; then  # npm test: the modules and the tests; the WASM benchmarks are for `all`
    cmake --build --preset wasm --target straightest_wasm straightest_wasm_threads core_tests
  else
    cmake --build --preset wasm
  fi
  mkdir -p wasm/dist/threads
  cp build/wasm/straightest-core.mjs build/wasm/straightest-core.wasm wasm/dist/
  # The threaded module's pthread worker script is CommonJS (Node runs it with require): its directory
  # says so, since the package's "type" is "module".
  cp build/wasm/straightest-core-threads.mjs build/wasm/straightest-core-threads.wasm \
    build/wasm/straightest-core-threads.worker.js wasm/dist/threads/
  echo '{ "type": "commonjs" }' > wasm/dist/threads/package.json
  node scripts/neutral-threads-loader.mjs wasm/dist/threads/straightest-core-threads.mjs
  # The same script as a string, which browsers start from a blob: URL (no worker file for bundlers to emit)
  node scripts/embed-worker.mjs wasm/dist/threads/straightest-core-threads.worker.js \
    wasm/dist/threads/straightest-core-threads-worker-source.mjs
  # straightest/inline's copy of the module, as base64 in an ES module
  node scripts/embed-wasm.mjs wasm/dist/straightest-core.wasm wasm/dist/straightest-core-embedded.js
fi
