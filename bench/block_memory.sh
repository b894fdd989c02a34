#!/bin/bash
# Peak memory per process of the spatial blocks (docs/scale-out.md, "Memory"): one process
# without blocks, --blocks 1, 2, 4 and 8 written as .pvtp pieces, and mpirun -np 2 and -np 4
# (one block per process; -np 8 when asked), each process under /usr/bin/time -v: wall time, processor time
# (user + system) and peak resident memory (under mpirun, process by process in rank order:
# process 0 reads the structure, joins the seams and the exact areas).
# Usage: bench/block_memory.sh STRUCTURE [MOLSURF] [RUNS]
# RUNS: some of "one blocks1 blocks2 blocks4 blocks8 np2 np4 np8" (default: all but np8).
set -euo pipefail
structure="$1"
molsurf="${2:-build/release/molsurf}"
runs=" ${3:-one blocks1 blocks2 blocks4 blocks8 np2 np4} "
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/time_per_process.sh"
abs="$(realpath "$structure")"
bin="$(realpath "$molsurf")"
if [[ "$runs" == *" one "* ]]; then
  run "one process" /usr/bin/time -v "$bin" "$abs" -o one.vtp -q
fi
for n in 1 2 4 8; do
  [[ "$runs" == *" blocks$n "* ]] || continue
  run "--blocks $n" /usr/bin/time -v "$bin" "$abs" --blocks "$n" -o blocks.pvtp -q
done
for n in 2 4 8; do
  [[ "$runs" == *" np$n "* ]] || continue
  run "mpirun -np $n" mpirun --oversubscribe --allow-run-as-root -np "$n" "${timed_rank[@]}" "$bin" "$abs" -o mpi.pvtp -q
done
