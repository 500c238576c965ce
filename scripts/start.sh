#!/usr/bin/env bash
# npm start: install what is missing, build the WASM module, serve the page on http://127.0.0.1:8080
source "$(dirname "$0")/common.sh"
ensure_system_packages
ensure_node_modules
bash scripts/build.sh wasm
exec node scripts/serve.mjs "$@"
