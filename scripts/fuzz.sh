#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz/, clang + ASan + UBSan) into build/fuzz and runs each one:
# first every saved regression input once (tests/fuzz/regressions/<harness>/), then SECONDS of fuzzing
# (default 30) over a temporary copy of its seed corpus (tests/fuzz/corpus/<harness>/) plus the
# regression inputs, so the repository is never modified. A harness passes when its regression inputs
# pass and fuzzing found no crash, timeout, leak or out-of-memory. New crash inputs are kept in
# build/fuzz/artifacts/<harness>/ (reproduce: build/fuzz/<harness> FILE).
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
BUILD="$ROOT/build/fuzz"
FUZZ_DIR="$ROOT/tests/fuzz"

CXX_FOR_FUZZ="${FUZZ_CXX:-clang++}"
if ! command -v "$CXX_FOR_FUZZ" >/dev/null; then
  echo "fuzz: $CXX_FOR_FUZZ not found (run scripts/setup.sh: it installs clang and libclang-rt-14-dev)" >&2
  exit 1
fi

start=$(now_ms)
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S "$FUZZ_DIR" -B "$BUILD" -DCMAKE_CXX_COMPILER="$CXX_FOR_FUZZ" >/dev/null
fi
echo "fuzz: building harnesses in build/fuzz"
cmake --build "$BUILD" -j"$(nproc)" -- --no-print-directory >"$BUILD/build.log" 2>&1 || {
  tail -40 "$BUILD/build.log" >&2
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

passed=0
failed=0
summary=()
for h in "${HARNESSES[@]}"; do
  bin="$BUILD/$h"
  if [ ! -x "$bin" ]; then
    echo "fuzz: no harness $h" >&2
    failed=$((failed + 1))
    summary+=("$h: not built")
    continue
  fi
  artifacts="$BUILD/artifacts/$h"
  mkdir -p "$artifacts" "$WORK/$h/corpus"
  before=$(find "$artifacts" -type f | wc -l)

  # 1. Regression inputs, one process each so every failure is named.
  regressions_failed=0
  regressions=0
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
  options=()
  [ -n "${FUZZ_SEED:-}" ] && options+=("-seed=$FUZZ_SEED")
  [ -f "$FUZZ_DIR/${h#fuzz_}.dict" ] && options+=("-dict=$FUZZ_DIR/${h#fuzz_}.dict")
  echo "fuzz: $h: $regressions regression inputs ($regressions_failed failing), fuzzing ${SECONDS_EACH} s"
  touch "$WORK/$h/started"
  set +e
  "$bin" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "${options[@]}" "$WORK/$h/corpus" >"$WORK/$h/fuzz.log" 2>&1
  rc=$?
  set -e
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
    echo "    log: ${artifacts#"$ROOT"/}/last-failure.log (reproduce: build/fuzz/$h INPUT)"
  fi
  if [ "$crashes" -eq 0 ] && [ "$regressions_failed" -eq 0 ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
  summary+=("$line")
done

echo
for line in "${summary[@]}"; do echo "$line"; done
echo "fuzz: total $(elapsed "$start") s"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
