#!/usr/bin/env bash
# npm run lint: the repository's habits, each a check that passes or fails —
#   format — C++ formatted as .clang-format says (clang-format --dry-run --Werror): core/, wasm/*.cpp,
#            tests/core/, tests/fuzz/*.cpp|hpp, bench/
#   prettier — JavaScript, TypeScript declarations, CSS and HTML formatted as .prettierrc.json says
#            (prettier --check): wasm/, web/, scripts/, tests/, bench/ (.prettierignore lists what is not)
#   eslint — JavaScript: wasm/, web/, scripts/, tests/js/, tests/e2e/, tests/package/ (eslint.config.js)
#   types  — the package's TypeScript declarations against a consumer's code, strict (tests/types)
# Prints one line per check and "N passed, M failed" last (scripts/test.sh reads it); exits non-zero if
# any check fails. `lint.sh --fix` reformats the C++ and JavaScript files in place instead of checking
# them (and reports what it changed); the other checks still run (eslint is not asked to fix).
source "$(dirname "$0")/common.sh"

fix=false
if [ "${1:-}" = --fix ]; then fix=true; elif [ $# -gt 0 ]; then
  echo "usage: scripts/lint.sh [--fix]" >&2
  exit 2
fi

# eslint and typescript come from npm (package.json); install them when this runs on its own.
if [ ! -x node_modules/.bin/eslint ] || [ ! -x node_modules/.bin/tsc ] || [ ! -x node_modules/.bin/prettier ]; then
  ensure_node_modules
fi
JS_GLOBS=('wasm/**/*.{js,ts}' 'web/**/*.{js,css,html}' 'scripts/**/*.mjs' 'tests/**/*.{mjs,js,ts}' 'bench/**/*.mjs'
  eslint.config.js)

cpp_files() {
  {
    find core tests/core bench -name '*.cpp' -o -name '*.hpp'
    find wasm tests/fuzz -maxdepth 1 -name '*.cpp' -o -maxdepth 1 -name '*.hpp'
  } | LC_ALL=C sort
}

passed=0
failed=0
check() {  # name command... : runs it, prints its verdict
  local name=$1; shift
  local t; t=$(now_ms)
  if "$@"; then
    passed=$((passed + 1)); echo "lint: $name ok ($(elapsed "$t") s)"
  else
    failed=$((failed + 1)); echo "lint: $name FAILED ($(elapsed "$t") s)"
  fi
}

format_check() {
  local files; mapfile -t files < <(cpp_files)
  if $fix; then
    local before after changed=0 f
    for f in "${files[@]}"; do
      before=$(cksum < "$f"); clang-format -i "$f"; after=$(cksum < "$f")
      if [ "$before" != "$after" ]; then changed=$((changed + 1)); fi
    done
    echo "format: reformatted $changed of ${#files[@]} files"
    return 0
  fi
  # One line per file that is not formatted, with how many places differ (clang-format FILE shows how).
  local out report
  out=$(clang-format --dry-run --Werror "${files[@]}" 2>&1) && return 0
  report=$(echo "$out" | grep -E '^[^ ]+:[0-9]+:[0-9]+: error:' | cut -d: -f1 | uniq -c \
           | awk '{ print "format: " $2 ": " $1 " places differ from .clang-format" }' || true)
  if [ -z "$report" ]; then echo "$out"; return 1; fi  # clang-format itself failed (missing, bad config)
  echo "$report"
  echo "format: $(echo "$report" | wc -l) of ${#files[@]} files need formatting (scripts/lint.sh --fix)"
  return 1
}

prettier_check() {
  if $fix; then
    node_modules/.bin/prettier --write --log-level warn "${JS_GLOBS[@]}" && echo "prettier: files written"
    return
  fi
  node_modules/.bin/prettier --check --log-level warn "${JS_GLOBS[@]}" && return 0
  echo "prettier: the files above differ from .prettierrc.json (scripts/lint.sh --fix)"
  return 1
}

eslint_check() {
  node_modules/.bin/eslint --max-warnings 0 wasm web scripts tests/js tests/e2e tests/package eslint.config.js
}

types_check() {
  node_modules/.bin/tsc -p tests/types
}

check format format_check
check prettier prettier_check
check eslint eslint_check
check types types_check
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
