#!/usr/bin/env bash
# Installs molsurf's system dependencies (Debian 12, idempotent) and builds the release preset,
# the Python module included (build/release/python; Debian's python3-gemmi is gemmi-dev's version,
# which lets gemmi.Structure objects pass to molsurf without a file; venv, pip, setuptools and
# wheel let the ctest `install` pip-install the module offline).
# Usage: scripts/setup.sh [release|debug]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"

# libvtk9-dev is for the tests only (VTK's reader and writer are the reference for molsurf's
# own .vtk and .vtp code; neither the library, the command nor the Python module links it).
packages=(build-essential cmake ninja-build pkg-config
  gemmi-dev tao-pegtl-dev zlib1g-dev libdeflate-dev libvtk9-dev libcli11-dev
  googletest libgtest-dev nlohmann-json3-dev libgmp-dev libmpfr-dev libcgal-dev libmimalloc-dev
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-gemmi
  python3-matplotlib python3-meshio python3-mdtraj python3-dask snakemake
  python3-venv python3-pip python3-setuptools python3-wheel
  gmsh libgmsh-dev tetgen xvfb python3-vtk9 freesasa
  libopenmpi-dev openmpi-bin)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
