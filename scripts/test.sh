#!/usr/bin/env bash
# npm test: installs what is missing, then runs every layer and prints each layer's totals:
#   lint     — scripts/lint.sh (npm run lint): C++ format, eslint, the TypeScript usage check; first, since
#              it takes under a minute and a failure there needs no build to be found
#   native   — native build (warnings are errors) + ctest (GoogleTest suite + CLI contract)
#   wasm     — WASM build + ctest running the same GoogleTest sources under Node
#   sanitize — the native suite again under AddressSanitizer + UndefinedBehaviorSanitizer
#   tsan     — the threaded loops' tests (tests/core/threads_test.cpp) under ThreadSanitizer
#   fuzz     — every libFuzzer harness (tests/fuzz): its saved regression inputs, then a smoke run of
#              FUZZ_SECONDS (default 20) seconds each with libFuzzer seed FUZZ_SEED (default 1, so
#              every run starts from the same inputs); one result per harness
#   js       — node --test on the npm API (tests/js), including installing the packed package
#   browser  — the page in headless Chromium (tests/e2e)
# Exits non-zero if any layer fails. Set LAYERS="native wasm" to run a subset.
#
# The js layer keeps about one of two cores busy (node --test runs its files one at a time): when the
# sanitize or tsan layer comes after the module is built, js runs in the background beside them (their
# builds and tests have no time limits) and is waited for before fuzz and browser, whose seconds of
# fuzzing and page timeouts want the machine to themselves. Its output is printed when it ends.
source "$(dirname "$0")/common.sh"
LAYERS="${LAYERS:-lint native wasm sanitize tsan fuzz js browser}"
LOG_DIR="$ROOT/build/test-logs"
mkdir -p "$LOG_DIR"

t=$(now_ms); ensure_system_packages; echo "setup: system packages $(elapsed "$t") s"
t=$(now_ms); ensure_node_modules; echo "setup: npm packages $(elapsed "$t") s"

summary=()
total_pass=0
total_fail=0
status=0

record() {  # layer pass fail seconds
  summary+=("$(printf '%-8s %5d passed, %3d failed  (%s s)' "$1" "$2" "$3" "$4")")
  total_pass=$((total_pass + $2))
  total_fail=$((total_fail + $3))
  if [ "$3" -ne 0 ]; then status=1; fi
}

ctest_counts() {  # log -> "pass fail" from "N% tests passed, F tests failed out of T"
  local line total failed
  line=$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$1" | tail -1 || true)
  if [ -z "$line" ]; then echo "0 1"; return; fi
  failed=$(echo "$line" | sed -E 's/.* ([0-9]+) tests? failed out of.*/\1/')
  total=$(echo "$line" | sed -E 's/.*out of ([0-9]+).*/\1/')
  echo "$((total - failed)) $failed"
}

run_layer() {  # name command... ; output to console and log; sets LAST_RC
  local name=$1; shift
  echo
  echo "=== $name ==="
  set +e
  "$@" 2>&1 | tee "$LOG_DIR/$name.log"
  LAST_RC=${PIPESTATUS[0]}
  set -e
}

js_counts() {  # -> "pass fail" from node --test's totals in js.log (LAST_RC: its exit status)
  local p f
  p=$(grep -E '^# pass [0-9]+' "$LOG_DIR/js.log" | tail -1 | awk '{print $3}')
  f=$(grep -E '^# fail [0-9]+' "$LOG_DIR/js.log" | tail -1 | awk '{print $3}')
  p=${p:-0}; f=${f:-1}
  if [ "$LAST_RC" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  echo "$p $f"
}

js_pid=""
start_js_in_background() {
  echo
  echo "=== js (in the background; its output comes when it ends) ==="
  js_start=$(now_ms)
  rm -f "$LOG_DIR/js.end"
  # Its exit status and the seconds it took (not until it is waited for), for the summary.
  { set +e; node --test tests/js/ >"$LOG_DIR/js.log" 2>&1; echo "$? $(elapsed "$js_start")" >"$LOG_DIR/js.end"; } &
  js_pid=$!
}

finish_js() {
  [ -n "$js_pid" ] || return 0
  wait "$js_pid" || true
  js_pid=""
  local seconds
  read -r LAST_RC seconds <"$LOG_DIR/js.end" || { LAST_RC=1; seconds=$(elapsed "$js_start"); }
  echo
  echo "=== js (ran in the background) ==="
  cat "$LOG_DIR/js.log"
  read -r p f < <(js_counts)
  record js "$p" "$f" "$seconds"
}

# Whether js runs in the background: a sanitize or tsan layer comes after wasm and before js.
js_background=false
seen_wasm=false
beside=false
for layer in $LAYERS; do
  case "$layer" in
    wasm) seen_wasm=true ;;
    sanitize|tsan) if $seen_wasm; then beside=true; fi ;;
    js) if $beside; then js_background=true; fi ;;
  esac
done

wasm_done=false
for layer in $LAYERS; do
  t=$(now_ms)
  case "$layer" in
    sanitize|tsan) if $js_background && $wasm_done && [ -z "${js_start:-}" ]; then start_js_in_background; fi ;;
    fuzz|browser) finish_js ;;
  esac
  if [ "$layer" = wasm ]; then wasm_done=true; fi
  case "$layer" in
    native|wasm|sanitize|tsan)
      run_layer "$layer-build" bash scripts/build.sh "$layer"
      if [ "$LAST_RC" -ne 0 ]; then record "$layer" 0 1 "$(elapsed "$t")"; continue; fi
      echo "$layer build: $(elapsed "$t") s"
      run_layer "$layer" ctest --preset "$layer"
      read -r p f < <(ctest_counts "$LOG_DIR/$layer.log")
      if [ "$LAST_RC" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
      record "$layer" "$p" "$f" "$(elapsed "$t")"
      ;;
    js)
      if $js_background; then finish_js; continue; fi
      run_layer js node --test tests/js/
      read -r p f < <(js_counts)
      record js "$p" "$f" "$(elapsed "$t")"
      ;;
    lint|fuzz|browser)
      if [ "$layer" = lint ]; then
        run_layer lint bash scripts/lint.sh
      elif [ "$layer" = fuzz ]; then
        FUZZ_SEED="${FUZZ_SEED:-1}" run_layer fuzz bash scripts/fuzz.sh "${FUZZ_SECONDS:-20}"
      else
        run_layer browser node tests/e2e/browser.test.mjs
      fi
      line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$LOG_DIR/$layer.log" | tail -1 || true)
      p=$(echo "$line" | awk '{print $1}'); f=$(echo "$line" | awk '{print $3}')
      p=${p:-0}; f=${f:-1}
      if [ "$LAST_RC" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
      record "$layer" "$p" "$f" "$(elapsed "$t")"
      ;;
    *) echo "unknown layer '$layer'" >&2; exit 2 ;;
  esac
done

finish_js

echo
echo "=== summary ==="
for line in "${summary[@]}"; do echo "$line"; done
echo "total: $total_pass passed, $total_fail failed"
exit $status
