# Sourced by the block benches (scale_out.sh, block_memory.sh), with $work set to their
# scratch folder. run LABEL COMMAND...: runs the command there, each process under
# /usr/bin/time -v, and prints one line per process: wall and processor (user + system)
# seconds and peak resident memory. Under mpirun, "${timed_rank[@]}" before the program
# times each process into a file of its own (time.RANK), and the lines come in process order,
# each labelled with its rank. A failed command prints its output and stops the bench.
timed_rank=(/bin/sh -c 'exec /usr/bin/time -v -o "time.$OMPI_COMM_WORLD_RANK" "$@"' sh)
run() {
  local label="$1"; shift
  rm -f "$work"/time.*
  (cd "$work" && "$@" > /dev/null 2> time.txt) || { cat "$work"/time.*; exit 1; }
  local ranked=0
  if compgen -G "$work/time.[0-9]*" > /dev/null; then
    ranked=1
    ls "$work"/time.[0-9]* | sort -t. -k2 -n | xargs cat > "$work/time.txt"
  fi
  awk -v label="$label" -v ranked="$ranked" '
    /User time/ { cpu = $NF }
    /System time/ { cpu += $NF }
    /Elapsed \(wall clock\)/ { n = split($NF, t, ":"); s = (n == 3) ? t[1] * 3600 + t[2] * 60 + t[3] : t[1] * 60 + t[2] }
    /Maximum resident set size/ {
      name = ranked ? label ", process " (k++) : label
      printf "%-32s wall %7.1f s  cpu %7.1f s  peak %7.0f MB\n", name, s, cpu, $NF / 1024 }' "$work/time.txt"
}
