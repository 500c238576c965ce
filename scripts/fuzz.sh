#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz/, clang + ASan + UBSan) in the sanitize preset's tree
# (build/sanitize, whose instrumented core the sanitized suite uses too) and runs each one:
# first every saved regression input once (tests/fuzz/regressions/<harness>/), then SECONDS of fuzzing
# (default 30) over a temporary copy of its seed corpus (tests/fuzz/corpus/<harness>/) plus the
# regression inputs, so the repository is never modified. A harness passes when its regression inputs
# pass and fuzzing found no crash, timeout, leak or out-of-memory. New crash inputs are kept in
# build/fuzz/artifacts/<harness>/ (reproduce: build/sanitize/<harness> FILE). Harnesses run side by side,
# one per core (FUZZ_JOBS=N to change).
#
#   scripts/fuzz.sh [SECONDS]            every harness
#   FUZZ_HARNESSES="fuzz_obj fuzz_off" scripts/fuzz.sh 600
#   FUZZ_SEED=1 scripts/fuzz.sh          fixed libFuzzer seed (npm test uses 1, so CI's smoke run
#                                        explores the same inputs first every time); default random
#
# Needs clang, libclang-rt-14-dev, cmake, Eigen and fast_float (scripts/setup.sh installs them).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

SECONDS_EACH="${1:-30}"
if ! [[ "$SECONDS_EACH" =~ ^[0-9]+$ ]] || [ "$SECONDS_EACH" -lt 1 ]; then
  echo "usage: scripts/fuzz.sh [SECONDS]   (seconds of fuzzing per harness, default 30)" >&2
  exit 2
fi
HARNESSES=(${FUZZ_HARNESSES:-fuzz_obj fuzz_off fuzz_ply fuzz_stl fuzz_trimesh fuzz_trace fuzz_param fuzz_atlas})
BUILD="$ROOT/build/sanitize"     # the harnesses: the sanitize preset's tree, shared with the sanitized suite
ARTIFACTS="$ROOT/build/fuzz/artifacts"
FUZZ_DIR="$ROOT/tests/fuzz"

if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ not found (run scripts/setup.sh: it installs clang and libclang-rt-14-dev)" >&2
  exit 1
fi

start=$(now_ms)
mkdir -p "$ARTIFACTS"
configure_preset sanitize
echo "fuzz: building harnesses in build/sanitize"
cmake --build "$BUILD" -j"$(nproc)" --target "${HARNESSES[@]}" >"$ARTIFACTS/../build.log" 2>&1 || {
  tail -40 "$ARTIFACTS/../build.log" >&2
  echo "fuzz: build failed (full log: build/fuzz/build.log)" >&2
  exit 1
}
echo "fuzz: built in $(elapsed "$start") s"

export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/straightest-fuzz.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

# The lines of a libFuzzer log that say what went wrong.
show_failure() {
  { grep -E -A1 "INVARIANT VIOLATED" "$1" | head -2
    grep -E -m3 "runtime error|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|^SUMMARY:" "$1"; } | sed 's/^/    /' || true
}

# One harness: regression inputs, then fuzzing. Prints what it found; its last line in
# $WORK/$h/result is "pass|fail SUMMARY".
run_harness() {
  local h=$1 bin="$BUILD/$1"
  if [ ! -x "$bin" ]; then
    echo "fuzz: no harness $h" >&2
    mkdir -p "$WORK/$h"; echo "fail $h: not built" >"$WORK/$h/result"
    return
  fi
  local artifacts="$ARTIFACTS/$h"
  mkdir -p "$artifacts" "$WORK/$h/corpus"
  local before; before=$(find "$artifacts" -type f | wc -l)

  # 1. Regression inputs, one process each so every failure is named.
  local regressions_failed=0 regressions=0 input
  if [ -d "$FUZZ_DIR/regressions/$h" ]; then
    for input in "$FUZZ_DIR/regressions/$h"/*; do
      [ -f "$input" ] || continue
      regressions=$((regressions + 1))
      if "$bin" "$input" >"$WORK/$h/regression.log" 2>&1; then
        cp "$input" "$WORK/$h/corpus/"
      else
        regressions_failed=$((regressions_failed + 1))
        echo "fuzz: $h: regression input ${input#"$ROOT"/} FAILS:"
        show_failure "$WORK/$h/regression.log"
      fi
    done
  fi

  # 2. Fuzzing over a scratch copy of the seed corpus (plus the passing regression inputs).
  cp -R "$FUZZ_DIR/corpus/$h/." "$WORK/$h/corpus/" 2>/dev/null || true
  local options=()
  [ -n "${FUZZ_SEED:-}" ] && options+=("-seed=$FUZZ_SEED")
  [ -f "$FUZZ_DIR/${h#fuzz_}.dict" ] && options+=("-dict=$FUZZ_DIR/${h#fuzz_}.dict")
  echo "fuzz: $h: $regressions regression inputs ($regressions_failed failing), fuzzing ${SECONDS_EACH} s"
  touch "$WORK/$h/started"
  local rc=0
  "$bin" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "${options[@]}" "$WORK/$h/corpus" >"$WORK/$h/fuzz.log" 2>&1 || rc=$?
  local runs crashes line
  runs=$(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$WORK/$h/fuzz.log" | grep -o '[0-9]*$' || true)
  crashes=$(( $(find "$artifacts" -type f | wc -l) - before ))
  if [ "$rc" -ne 0 ] && [ "$crashes" -eq 0 ]; then crashes=1; fi
  line="$h: ${runs:-0} runs, $crashes crashes"
  [ "$regressions_failed" -gt 0 ] && line+=", $regressions_failed failing regression inputs"
  if [ "$crashes" -gt 0 ]; then
    cp "$WORK/$h/fuzz.log" "$artifacts/last-failure.log"
    echo "fuzz: $h: fuzzing failed:"
    show_failure "$WORK/$h/fuzz.log"
    find "$artifacts" -type f -newer "$WORK/$h/started" ! -name 'last-failure.log' | sed "s|^$ROOT/|    input kept: |"
    echo "    log: ${artifacts#"$ROOT"/}/last-failure.log (reproduce: build/sanitize/$h INPUT)"
  fi
  if [ "$crashes" -eq 0 ] && [ "$regressions_failed" -eq 0 ]; then
    echo "pass $line" >"$WORK/$h/result"
  else
    echo "fail $line" >"$WORK/$h/result"
  fi
}

# The harnesses run side by side, one per core (each libFuzzer process is single-threaded: the same
# SECONDS of fuzzing each, in less wall time); each one's messages are printed together when it ends.
JOBS="${FUZZ_JOBS:-$(nproc)}"
running=0
for h in "${HARNESSES[@]}"; do
  mkdir -p "$WORK/$h"
  (run_harness "$h" >"$WORK/$h/console" 2>&1; cat "$WORK/$h/console") &
  running=$((running + 1))
  if [ "$running" -ge "$JOBS" ]; then wait -n || true; running=$((running - 1)); fi
done
wait || true

passed=0
failed=0
summary=()
for h in "${HARNESSES[@]}"; do
  result=$(cat "$WORK/$h/result" 2>/dev/null || echo "fail $h: no result")
  if [ "${result%% *}" = pass ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
  summary+=("${result#* }")
done

echo
for line in "${summary[@]}"; do echo "$line"; done
echo "fuzz: total $(elapsed "$start") s"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
