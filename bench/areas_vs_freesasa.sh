#!/usr/bin/env bash
# Whole-process wall time of `molsurf --areas-only` (the exact areas and volumes of the
# union of the true spheres, no mesh) against FreeSASA's Lee & Richards at 20 slices per
# atom (its default) and at 200: the median of N runs after warm-up runs, the three
# commands interleaved (molsurf, FS-20, FS-200, molsurf, ...) so that machine drift
# affects all three alike. One Markdown table.
#
# Usage: bench/areas_vs_freesasa.sh [OPTIONS] [STRUCTURE...]
#   STRUCTURE        a file, or a name in data/pdb (1crn, 2hhb, 7cth, capsid = 1f2n_assembly1)
#                    default: 1crn 2hhb 7cth capsid
#   --runs N         timed runs per command (default 7); the median is reported
#   --warmup N       untimed runs per command first (default 1)
#   --molsurf PATH   molsurf binary (default: build/release/molsurf)
#   --threads N      threads for both tools (default: all cores, nproc); molsurf --threads N,
#                    freesasa --n-threads=N
#   -h, --help
#
# The same atoms for both tools, as far as their selection options allow: both read the
# same file (a gzipped one is decompressed to a temporary file first, outside the timing,
# since FreeSASA 2.1.2 reads no gzip); HETATM records are left out by both (FreeSASA's
# default; molsurf --no-hetatm), which also drops the waters; hydrogens are skipped by both
# (their defaults); the first model. The atom column shows both counts when they differ
# (alternate conformers: FreeSASA keeps the first, molsurf the most occupied, so counts can
# differ by a few atoms). Radii: each tool's own ProtOr table (FreeSASA's classifier,
# molsurf's data/radii), probe 1.4 A; the last two columns are the areas each reported, for
# orientation only (the per-atom comparison with identical radii is bench/freesasa_accuracy).
# Commands timed (output to files in a temporary directory, not parsed until the end):
#   molsurf --areas-only -q --no-hetatm --threads N FILE
#   freesasa --lee-richards --resolution=20  --n-threads=N [--cif] FILE
#   freesasa --lee-richards --resolution=200 --n-threads=N [--cif] FILE
# FreeSASA is the Debian package `freesasa` (2.1.2 in Debian 12; scripts/setup.sh installs it).
set -u -o pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$script_dir/.." && pwd)

runs=7
warmup=1
molsurf="$root/build/release/molsurf"
threads=$(nproc 2>/dev/null || echo 1)
structures=()

die() { echo "areas_vs_freesasa.sh: $*" >&2; exit 2; }
usage() { sed -n '2,/^set -u/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while (($#)); do
  case "$1" in
    --runs) runs=${2:?}; shift ;;
    --runs=*) runs=${1#*=} ;;
    --warmup) warmup=${2:?}; shift ;;
    --warmup=*) warmup=${1#*=} ;;
    --molsurf) molsurf=${2:?}; shift ;;
    --molsurf=*) molsurf=${1#*=} ;;
    --threads) threads=${2:?}; shift ;;
    --threads=*) threads=${1#*=} ;;
    -h|--help) usage; exit 0 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) structures+=("$1") ;;
  esac
  shift
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || die "--runs wants a positive whole number"
[[ "$warmup" =~ ^[0-9]+$ ]] || die "--warmup wants a whole number"
[[ "$threads" =~ ^[1-9][0-9]*$ ]] || die "--threads wants a positive whole number"
[[ -x "$molsurf" ]] || die "molsurf binary not found: $molsurf (build it, or give --molsurf PATH)"
command -v freesasa >/dev/null || die "freesasa not found (Debian: apt-get install freesasa; scripts/setup.sh installs it)"
((${#structures[@]})) || structures=(1crn 2hhb 7cth capsid)

# A name in data/pdb, or a path.
resolve() {
  local s=$1 c
  [[ "$s" == capsid ]] && s=1f2n_assembly1
  if [[ -f "$s" ]]; then echo "$s"; return 0; fi
  for c in "$root/data/pdb/$s"{,.pdb,.cif,.cif.gz,.pdb.gz}; do [[ -f "$c" ]] && { echo "$c"; return 0; }; done
  return 1
}

work=$(mktemp -d "${TMPDIR:-/tmp}/areas_vs_freesasa.XXXXXX") || die "mktemp failed"
trap 'rm -rf "$work"' EXIT
trap 'echo "areas_vs_freesasa.sh: interrupted" >&2; exit 130' INT TERM

median() { sort -g | awk '{v[NR] = $1} END {if (NR == 0) exit 1; print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# timed TAG CMD...: runs CMD (stdout and stderr to files); prints its wall seconds, or fails.
timed() {
  local tag=$1 t0 t1; shift
  t0=$EPOCHREALTIME
  "$@" >"$work/$tag.out" 2>"$work/$tag.err" || { echo "areas_vs_freesasa.sh: failed: $*" >&2; tail -n 3 "$work/$tag.err" >&2; return 1; }
  t1=$EPOCHREALTIME
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.4f\n", b - a}'
}

rows=()
for s in "${structures[@]}"; do
  file=$(resolve "$s") || { echo "areas_vs_freesasa.sh: no structure '$s'" >&2; continue; }
  name=$s; [[ $s == capsid ]] || { name=$(basename "$file"); name=${name%.gz}; name=${name%.*}; }
  input=$file
  if [[ "$file" == *.gz ]]; then
    input="$work/$(basename "${file%.gz}")"
    gzip -dc "$file" >"$input" || die "cannot decompress $file"
  fi
  fs_format=(); [[ "$input" == *.cif ]] && fs_format=(--cif)

  ms_cmd=("$molsurf" --areas-only -q --no-hetatm --threads "$threads" "$input")
  fs20_cmd=(freesasa --lee-richards --resolution=20 --n-threads="$threads" "${fs_format[@]}" "$input")
  fs200_cmd=(freesasa --lee-richards --resolution=200 --n-threads="$threads" "${fs_format[@]}" "$input")

  # Untimed: molsurf's atom count and area (its JSON report).
  "$molsurf" --areas-only -q --no-hetatm --threads "$threads" --json "$work/$name.json" "$input" \
    >/dev/null 2>"$work/$name.json.err" || { echo "areas_vs_freesasa.sh: $name: molsurf failed" >&2; tail -n 3 "$work/$name.json.err" >&2; continue; }
  read -r ms_atoms ms_area < <(python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); print(j["input"]["atoms"], j["area"])' "$work/$name.json") ||
    die "cannot read $work/$name.json"

  ms=(); f20=(); f200=(); failed=0
  echo "areas_vs_freesasa.sh: $name: $warmup warm-up + $runs timed run(s) of each command, interleaved" >&2
  for ((i = 0; i < warmup + runs; ++i)); do
    a=$(timed ms "${ms_cmd[@]}") || { failed=1; break; }
    b=$(timed fs20 "${fs20_cmd[@]}") || { failed=1; break; }
    c=$(timed fs200 "${fs200_cmd[@]}") || { failed=1; break; }
    ((i < warmup)) && continue
    ms+=("$a"); f20+=("$b"); f200+=("$c")
  done
  if ((failed)); then rows+=("| $name | failed | | | | | | | |"); continue; fi

  fs_atoms=$(awk '/^atoms *:/ {print $3; exit}' "$work/fs20.out")
  fs200_area=$(awk '/^Total *:/ {print $3; exit}' "$work/fs200.out")
  m=$(printf '%s\n' "${ms[@]}" | median); m20=$(printf '%s\n' "${f20[@]}" | median); m200=$(printf '%s\n' "${f200[@]}" | median)
  atoms=$ms_atoms; [[ "$fs_atoms" == "$ms_atoms" ]] || atoms="$ms_atoms / $fs_atoms"
  rows+=("$(awk -v name="$name" -v atoms="$atoms" -v m="$m" -v a="$m20" -v b="$m200" -v ma="$ms_area" -v fa="$fs200_area" 'BEGIN {
    printf "| %s | %s | %.3f | %.3f | %.3f | %.2f | %.2f | %.1f | %.1f |", name, atoms, m, a, b, m / a, m / b, ma, fa }')")
  rm -f "$work"/*.cif "$work"/*.pdb
done

cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null)
echo "Whole-process wall time, median of $runs runs after $warmup warm-up run(s), the three commands interleaved;"
echo "$(nproc) cores${cpu:+ ($cpu)}. molsurf: \`--areas-only -q --no-hetatm --threads $threads\` (exact, no mesh)."
echo "FreeSASA $(freesasa --version 2>/dev/null | awk 'NR == 1 {print $NF}'): \`--lee-richards --resolution=20|200 --n-threads=$threads\` (HETATM left out, its default)."
echo "Atoms: molsurf's count (/ FreeSASA's when different). Probe 1.4 Å; radii: each tool's ProtOr."
echo
echo "| structure | atoms | molsurf s | FreeSASA-20 s | FreeSASA-200 s | molsurf ÷ FS-20 | molsurf ÷ FS-200 | molsurf area Å² | FS-200 area Å² |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
printf '%s\n' "${rows[@]}"
