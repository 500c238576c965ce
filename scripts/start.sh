#!/usr/bin/env bash
# npm start: install what is missing, build only the WASM module the page needs (no tests, no
# benchmarks: those stay in npm test), serve the page on http://127.0.0.1:8080
source "$(dirname "$0")/common.sh"
ensure_system_packages
ensure_node_modules
# The one slow step of a first start, announced so that a silent compiler is not taken for a hang; the
# estimate is a first build measured on a busy 2-core machine (a rebuild with nothing changed takes seconds).
echo "building the WebAssembly modules, single-threaded and threaded (~10 min the first time, seconds after that)"
t=$(now_ms)
bash scripts/build.sh module
echo "built the WebAssembly module in $(elapsed "$t") s"
exec node scripts/serve.mjs "$@"
