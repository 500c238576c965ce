#!/usr/bin/env bash
# npm run results: installs CGAL's sample data (libcgal-demo) if missing, builds the native CLI, rebuilds
# the real-patch set and its tool (scripts/patches.sh, a few seconds) and regenerates docs/RESULTS.md.
source "$(dirname "$0")/common.sh"
bash scripts/setup.sh libcgal-demo
bash scripts/build.sh native >/dev/null
bash scripts/patches.sh
node scripts/results.mjs
