#!/bin/bash
# Time and peak memory of the spatial blocks (docs/scale-out.md): one process, --blocks N in
# one process, and mpirun -np 2 (one block per process), each process measured by
# /usr/bin/time -v: wall time, processor time (user + system: what a loaded machine changes
# least) and peak resident memory. Usage: bench/scale_out.sh STRUCTURE [MOLSURF]
set -euo pipefail
structure="$1"
molsurf="${2:-build/release/molsurf}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
run() {  # label, then the command; prints wall and processor seconds and peak RSS of each process
  local label="$1"; shift
  (cd "$work" && "$@" > /dev/null 2> time.txt) || { cat "$work/time.txt"; exit 1; }
  awk -v label="$label" '
    /User time/ { cpu = $NF }
    /System time/ { cpu += $NF }
    /Elapsed \(wall clock\)/ { n = split($NF, t, ":"); s = (n == 3) ? t[1] * 3600 + t[2] * 60 + t[3] : t[1] * 60 + t[2] }
    /Maximum resident set size/ { printf "%-28s wall %7.1f s  cpu %7.1f s  peak %7.0f MB\n", label, s, cpu, $NF / 1024 }' "$work/time.txt"
}
abs="$(realpath "$structure")"
bin="$(realpath "$molsurf")"
run "one process" /usr/bin/time -v "$bin" "$abs" -o one.vtp -q
run "--blocks 4" /usr/bin/time -v "$bin" "$abs" --blocks 4 -o blocks.pvtp -q
run "mpirun -np 2 (per rank)" mpirun --oversubscribe --allow-run-as-root -np 2 /usr/bin/time -v "$bin" "$abs" -o mpi.pvtp -q
