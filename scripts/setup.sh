#!/usr/bin/env bash
# Installs the system packages straightest needs (Debian 12), only those that are missing.
# Idempotent: when everything is present it only checks and returns in about a second.
# Extra package names given as arguments are installed too (e.g. `setup.sh libcgal-demo` for CGAL's
# sample meshes, used by `npm run results`).
set -euo pipefail

packages=(cmake ninja-build g++ make clang libclang-rt-14-dev clang-format emscripten libeigen3-dev libfast-float-dev nlohmann-json3-dev googletest chromium chromium-headless-shell nodejs "$@")

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    # nodejs may come from another source (nodesource or a tarball): accept a working node >= 20.
    if [ "$p" = nodejs ] && command -v node >/dev/null && \
       [ "$(node -p 'process.versions.node.split(".")[0]')" -ge 20 ]; then continue; fi
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all system packages present"
  exit 0
fi

echo "setup: installing missing packages: ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then SUDO=sudo; else
    echo "setup: not root and no sudo; run as root:" >&2
    echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
