#!/bin/bash
# `molsurf batch` into an output folder that already holds many files, as a sweep's folder does
# late in the sweep (docs/batch.md, "Large output folders"): K copies of a structure,
# --areas-only, -j 2, into a folder of F empty files, each run from a folder without their
# reports. Prints the median wall and processor seconds of R runs for each molsurf given.
# Usage: bench/batch_large_folder.sh STRUCTURE K F R [MOLSURF...]   (e.g. data/pdb/1crn.pdb 40 200000 5;
# MOLSURF defaults to build/release/molsurf)
set -euo pipefail
structure="$(realpath "$1")"
copies="${2:-40}"
fillers="${3:-200000}"
runs="${4:-5}"
shift 4 || { echo "usage: $0 STRUCTURE K F R [MOLSURF...]" >&2; exit 2; }
(($# > 0)) || set -- build/release/molsurf
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/in" "$work/out"
for ((k = 0; k < copies; ++k)); do cp "$structure" "$work/in/s$k.${structure##*.}"; done
/usr/bin/python3 -c "
import sys
for i in range(int(sys.argv[2])): open(f'{sys.argv[1]}/filler{i:07d}.json', 'w').close()" "$work/out" "$fillers"

median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

printf '%-60s %8s %8s\n' "molsurf ($copies jobs into $fillers files)" "wall s" "cpu s"
for molsurf in "$@"; do
  bin="$(realpath "$molsurf")"
  : > "$work/times"
  for ((r = 0; r <= runs; ++r)); do  # run 0 warms the caches and is not counted
    rm -f "$work"/out/s*.json "$work"/out/manifest.tsv "$work"/out/summary.*
    /usr/bin/time -f "%e %U %S" -o "$work/time" "$bin" batch "$work/in" -o "$work/out" -j 2 -q || true
    ((r > 0)) && cat "$work/time" >> "$work/times"
  done
  wall=$(awk '{print $1}' "$work/times" | median)
  cpu=$(awk '{print $2 + $3}' "$work/times" | median)
  printf '%-60s %8.2f %8.2f\n' "$molsurf" "$wall" "$cpu"
done
