# Sourced by the block benches (scale_out.sh, block_memory.sh), with $work set to their
# scratch folder. run LABEL COMMAND...: runs the command there, each process under
# /usr/bin/time -v, and prints one line per process: wall and processor (user + system)
# seconds and peak resident memory. A failed command prints its output and stops the bench.
run() {
  local label="$1"; shift
  (cd "$work" && "$@" > /dev/null 2> time.txt) || { cat "$work/time.txt"; exit 1; }
  awk -v label="$label" '
    /User time/ { cpu = $NF }
    /System time/ { cpu += $NF }
    /Elapsed \(wall clock\)/ { n = split($NF, t, ":"); s = (n == 3) ? t[1] * 3600 + t[2] * 60 + t[3] : t[1] * 60 + t[2] }
    /Maximum resident set size/ { printf "%-28s wall %7.1f s  cpu %7.1f s  peak %7.0f MB\n", label, s, cpu, $NF / 1024 }' "$work/time.txt"
}
