#!/usr/bin/env bash
# Rebuilds the real-patch set: 41 disk-topology patches (1k–14k vertices) cut as geodesic balls from 12
# closed genus-0 sample meshes of CGAL (libcgal-demo's data archive; no CGAL library is needed): a scan
# (bunny00), a CAD part (fandisk) and models with protrusions (armadillo, bull, camel, man, homer, bear,
# diplodocus, dino, cow, triceratops). The cutter is bench/cut_patches.cpp (built on the core: heat-method
# geodesic distance, TriMesh's disk check); its header says how seeds, radii and the kept patches are
# chosen. The set is deterministic: the same archive gives the same files.
#
# Writes build/data/patches/MESH-seedK-rR.off (K: the seed's rank, extremities at even K, R: the radius
# in percent of the bounding-box diagonal) and build/data/patches/patches.txt (name, vertices, faces,
# boundary vertices, degenerate faces). Takes ~4 s after the native build (~1 min from scratch).
#
# Environment:
#   PATCHES_DIR=build/data/patches   where the patches go
#   PATCHES_COPY=                    also copy them there, replacing the .off files it holds
source "$(dirname "$0")/common.sh"

MESHES="bunny00 armadillo bull camel man homer fandisk bear diplodocus dino cow triceratops"
RADII=0.08,0.12,0.18,0.25,0.35  # fractions of the bounding-box diagonal
ARCHIVE=/usr/share/doc/libcgal-dev/data.tar.gz
out=${PATCHES_DIR:-build/data/patches}

bash scripts/setup.sh libcgal-demo >&2
configure_preset native
cmake --build --preset native --target cut_patches real_patches >/dev/null

mkdir -p build/data "$out"
files=()
for name in $MESHES; do
  file=build/data/data/meshes/$name.off
  [ -f "$file" ] || tar xzf "$ARCHIVE" -C build/data "data/meshes/$name.off"
  files+=("$file")
done

t0=$(now_ms)
rm -f "$out"/*.off
build/native/cut_patches --out "$out" --seeds 6 --per-mesh 4 --radii "$RADII" "${files[@]}" \
  2>"$out/rejected.txt" >"$out/patches.txt"
echo "patches: $(wc -l <"$out/patches.txt") patches in $out ($(elapsed "$t0") s)" >&2
if [ -n "${PATCHES_COPY:-}" ]; then
  mkdir -p "$PATCHES_COPY"
  rm -f "$PATCHES_COPY"/*.off
  cp "$out"/*.off "$out/patches.txt" "$PATCHES_COPY"/
  echo "patches: copied to $PATCHES_COPY" >&2
fi
