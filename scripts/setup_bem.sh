#!/usr/bin/env bash
# Installs what the BEM consumer test (tests/consumers/bem_solvation.py, ctest label `long`,
# docs/bem.md) needs on Debian 12, idempotent: numba, scipy and numpy for the boundary-element
# solver, meshio, pdb2pqr (charges and radii, AMBER) and APBS (the finite-difference reference).
# All from Debian's archive; nothing else is downloaded. molsurf itself: scripts/setup.sh.
# Usage: scripts/setup_bem.sh
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(python3-numpy python3-scipy python3-numba python3-meshio python3-pytest pdb2pqr apbs)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup_bem: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Report what the test will use (its numba kernels compile on first use, cached under /tmp).
/usr/bin/python3 -c "import numba, scipy, numpy; print('setup_bem: numba', numba.__version__, 'scipy', scipy.__version__, 'numpy', numpy.__version__)"
command -v apbs >/dev/null && command -v pdb2pqr >/dev/null && echo "setup_bem: apbs and pdb2pqr found"
