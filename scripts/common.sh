# Shared by start.sh, test.sh and build.sh: system packages, npm packages, environment.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
export NODE_PATH=/usr/share/nodejs  # emcc's JS tools find acorn there (Debian's emscripten)

ensure_system_packages() { bash "$ROOT/scripts/setup.sh"; }

# npm ci when node_modules is missing or older than package-lock.json.
ensure_node_modules() {
  if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ] \
     || [ "${CI:-}" = true ]; then
    npm ci --no-audit --no-fund --loglevel=error
  fi
}

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
# seconds since a now_ms timestamp, one decimal
elapsed() { local d=$(( $(now_ms) - $1 )); printf '%d.%d' $((d / 1000)) $(((d % 1000) / 100)); }

# cmake --preset PRESET [ARGS...], quietly. A build directory an older checkout configured with another
# generator (the presets use Ninja) is configured afresh instead of failing.
configure_preset() {
  local preset=$1; shift
  local cache="$ROOT/build/$preset/CMakeCache.txt"
  if [ -f "$cache" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$cache"; then
    rm -rf "$cache" "$ROOT/build/$preset/CMakeFiles"
  fi
  cmake --preset "$preset" "$@" >/dev/null
}
