#!/bin/bash
# Time and peak memory of the spatial blocks (docs/scale-out.md): one process, --blocks 4 in
# one process, mpirun -np 2 and -np 4 (one block per process; 4 oversubscribed on 2 cores),
# each process measured by /usr/bin/time -v: wall time, processor time (user + system: what
# a loaded machine changes least) and peak resident memory; each .pvtp written is checked
# by `molsurf check`. Usage: bench/scale_out.sh STRUCTURE [MOLSURF] [RUNS]
# RUNS: some of "one blocks4 np2 np4" (default: all).
set -euo pipefail
structure="$1"
molsurf="${2:-build/release/molsurf}"
runs="${3:-one blocks4 np2 np4}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/time_per_process.sh"
abs="$(realpath "$structure")"
bin="$(realpath "$molsurf")"
checked() {  # the surface of an index, valid by molsurf check
  "$bin" check "$work/$1" > /dev/null || { echo "$1: not valid"; exit 1; }
}
for r in $runs; do
  case "$r" in
    one) run "one process" /usr/bin/time -v "$bin" "$abs" -o one.vtp -q ;;
    blocks4) run "--blocks 4" /usr/bin/time -v "$bin" "$abs" --blocks 4 -o blocks.pvtp -q && checked blocks.pvtp ;;
    np2|np4)
      n="${r#np}"
      run "mpirun -np $n" mpirun --oversubscribe --allow-run-as-root -np "$n" "${timed_rank[@]}" "$bin" "$abs" \
        -o "mpi$n.pvtp" -q && checked "mpi$n.pvtp" ;;
    *) echo "unknown run '$r' (one blocks4 np2 np4)"; exit 2 ;;
  esac
done
