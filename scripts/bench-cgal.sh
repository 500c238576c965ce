#!/usr/bin/env bash
# Bench-only comparison against CGAL 5.5 (Debian libcgal-dev): exact geodesic distances
# (Surface_mesh_shortest_path) vs our straightest distances to every boundary vertex, CGAL's
# circle + mean-value parameterization vs ours (circle + mean-value, measured + shape-preserving), and
# CGAL's free-border ARAP and LSCM vs our free boundary (n/a until the core has it).
# CGAL is never a dependency of the library or the npm package: it is only built here, in build/cgal.
#
# Writes one JSON object per mesh to build/bench/cgal.jsonl and prints the markdown tables on stdout
# (progress on stderr). Never fails on a time. With PATCHES=1 it also runs the real-patch set
# (scripts/patches.sh) without the path comparison: JSON in build/bench/cgal-patches.jsonl, its tables
# after the first ones.
#
# Environment:
#   REPEATS=3            runs per measurement (median); a run longer than 30 s is not repeated
#   SP_BUDGET_S=60       a CGAL shortest-path run longer than this makes larger meshes skip it
#   CGAL_MESHES="..."    CGAL sample meshes (names in data/meshes of libcgal-demo's data archive)
#   PATCHES=0            1: also the real-patch set (41 patches, ~10 more minutes, mostly CGAL's ARAP)
#   FREE_MAX_VERTICES=30000  larger meshes skip CGAL's free-border methods (ARAP: ~40 s at 8k vertices)
#   HEIGHTFIELDS="..."   grid sizes N of the generated height fields (N² vertices)
#   JOBS=2               parallel compile jobs
# Takes 5–8 minutes on 2 cores (plus ~1.5 min for the first build): CGAL's exact geodesics on the
# 100k-vertex height field take 2.5–5.5 min and ~9.7 GB at peak, so they run once and the 1M one skips
# them (extrapolated: hours and hundreds of GB); CGAL's parameterization of the 1M mesh takes ~1.5 min.
source "$(dirname "$0")/common.sh"

# Disk-topology CGAL samples (one boundary loop, Euler characteristic 1, an interior vertex, at least 100
# vertices): the paper's Nefertiti (299 vertices), the archive's three disks with at least 5k vertices,
# then every other disk in the archive.
CGAL_MESHES=${CGAL_MESHES:-"nefertiti.off lion-head.off cylinder_locally_refined.off mannequin-devil.off \
three_peaks.off mushroom.off blob.off oblong-shuffled.off cylinder.off mesh_with_border.off plane.off \
poly2x^2+y^2-0.062500.off patch-01.off patch-13.off patch-20.off patch-21.off patch-23.off patch-30.off"}
HEIGHTFIELDS=${HEIGHTFIELDS:-"100 317 1000"}
ARCHIVE=/usr/share/doc/libcgal-dev/data.tar.gz

bash scripts/setup.sh libcgal-dev libcgal-demo >&2

# ---------------------------------------------------------------- meshes
mkdir -p build/data build/bench
meshes=()
for name in $CGAL_MESHES; do
  file=build/data/data/meshes/$name
  [ -f "$file" ] || tar xzf "$ARCHIVE" -C build/data "data/meshes/$name"
  meshes+=("$file")
done
# Increasing size, so the shortest-path time guard can use the smaller runs.
for n in $HEIGHTFIELDS; do meshes+=("heightfield:$n"); done

# ---------------------------------------------------------------- build (standalone CMake project)
t0=$(now_ms)
cmake -S bench/cgal -B build/cgal -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/cgal -j "${JOBS:-2}" >/dev/null
echo "bench-cgal: built build/cgal/bench_cgal in $(elapsed "$t0") s" >&2

# ---------------------------------------------------------------- run
t0=$(now_ms)
out=build/bench/cgal.jsonl
status=0
free=(--free-max-vertices "${FREE_MAX_VERTICES:-30000}")
build/cgal/bench_cgal --repeats "${REPEATS:-3}" --sp-budget-s "${SP_BUDGET_S:-60}" "${free[@]}" "${meshes[@]}" \
  > build/bench/cgal.out || status=$?
# JSON lines (kept even when the run failed part-way) and the table (everything else).
grep '^{' build/bench/cgal.out > "$out" || true
echo "## straightest vs CGAL $(dpkg-query -W -f='${Version}' libcgal-dev 2>/dev/null)"
echo
grep -v '^{' build/bench/cgal.out | sed '/./,$!d' || true
rm -f build/bench/cgal.out
if [ "${PATCHES:-0}" = 1 ]; then
  bash scripts/patches.sh >&2
  build/cgal/bench_cgal --repeats "${REPEATS:-3}" --skip-paths --no-lengths "${free[@]}" build/data/patches/*.off \
    > build/bench/cgal-patches.out || status=$?
  grep '^{' build/bench/cgal-patches.out > build/bench/cgal-patches.jsonl || true
  echo
  echo "## Real patches (scripts/patches.sh)"
  grep -v '^{' build/bench/cgal-patches.out | sed '/./,$!d' || true
  rm -f build/bench/cgal-patches.out
fi
echo "bench-cgal: ran in $(elapsed "$t0") s; $(wc -l < "$out") JSON lines in $out" >&2
[ "$status" -eq 0 ] || echo "bench-cgal: bench_cgal exited with status $status" >&2
exit "$status"
