#!/usr/bin/env bash
# The surface job stage by stage, on one and two threads, beside FreeSASA on the same
# spheres: one Markdown table.
#
# For each structure and each thread count, bench/surface_stage_times runs compute_surface
# (the whole job: union, cleanup, check, measures; the file is read once, before timing)
# REPEAT times in one process and prints the median of each stage and the process's peak
# memory. In the same run, FreeSASA (Lee & Richards) computes the SASA of the same spheres:
# the atoms as molsurf selected them, each with molsurf's van der Waals radius in the
# occupancy column (`--radius-from-occupancy`), the same probe (`--probe-radius`), the
# same thread count, at 20 and at 200 slices per atom; its time is the median wall time
# of the whole `freesasa` process (reading a small PDB is part of it).
#
# Usage: bench/surface_stage_table.sh [OPTIONS] [STRUCTURE...]
#   STRUCTURE           a file, or a name in data/pdb (1crn 1ubq 2hhb 7cth 2btv);
#                       default: 1crn 1ubq 2hhb 7cth 2btv
#   --capsid            also the whole capsid (1f2n_assembly1.cif.gz, 272 k atoms; minutes per
#                       run, several GB): always one run per setting, whatever --repeat says
#   --repeat N          runs per setting, medians reported (default 5)
#   --threads "A B"     thread counts to compare (default "1 2")
#   --probe P           probe radius (default 1.4); --density D icosphere density (default 2)
#   --build DIR         build directory holding bench/surface_stage_times (default: build/release)
#   --no-freesasa       molsurf only
#   -h, --help
#
# FreeSASA is the Debian package `freesasa` (2.1.2 in Debian 12); it is installed with
# apt-get when missing (sudo when not root). Columns: "speed-up" is the total on the
# first thread count over this row's; "÷FS20", "÷FS200" are molsurf's total over
# FreeSASA's time at 20 / 200 slices; "diff %" is molsurf's area against FreeSASA's at
# 200 slices.
set -u -o pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$script_dir/.." && pwd)

repeat=5
thread_counts="1 2"
probe=1.4
density=2
build_dir="$root/build/release"
use_freesasa=1
capsid=0
structures=()

die() { echo "surface_stage_table.sh: $*" >&2; exit 2; }
usage() { sed -n '2,/^set -u/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while (($#)); do
  case "$1" in
    --capsid) capsid=1 ;;
    --repeat) repeat=${2:?}; shift ;;
    --threads) thread_counts=${2:?}; shift ;;
    --probe) probe=${2:?}; shift ;;
    --density) density=${2:?}; shift ;;
    --build) build_dir=${2:?}; shift ;;
    --no-freesasa) use_freesasa=0 ;;
    -h|--help) usage; exit 0 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) structures+=("$1") ;;
  esac
  shift
done
[[ "$repeat" =~ ^[1-9][0-9]*$ ]] || die "--repeat wants a positive whole number"
((${#structures[@]})) || structures=(1crn 1ubq 2hhb 7cth 2btv)
((capsid)) && structures+=(capsid)

stage_times="$build_dir/bench/surface_stage_times"
[[ -x "$stage_times" ]] || die "$stage_times not found; build it:
  cmake --preset release && cmake --build --preset release --target surface_stage_times
or give the build directory with --build DIR"

# A name in data/pdb, or a path.
resolve() {
  case "$1" in
    capsid) echo "$root/data/pdb/1f2n_assembly1.cif.gz" ;;
    *)
      if [[ -f "$1" ]]; then echo "$1"; return; fi
      local f
      for f in "$root/data/pdb/$1".{pdb,cif,cif.gz,pdb.gz}; do [[ -f "$f" ]] && { echo "$f"; return; }; done
      return 1 ;;
  esac
}

if ((use_freesasa)) && ! command -v freesasa >/dev/null; then
  echo "surface_stage_table.sh: installing the Debian package freesasa" >&2
  sudo=""; (($(id -u) != 0)) && sudo=sudo
  { $sudo apt-get install -y freesasa >/dev/null 2>&1 ||
    { $sudo apt-get update >/dev/null 2>&1 && $sudo apt-get install -y freesasa >/dev/null 2>&1; }; } ||
    die "could not install freesasa (apt-get install freesasa); run with --no-freesasa to skip it"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/surface_stage_table.XXXXXX") || die "mktemp failed"
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{v[NR] = $1} END {if (NR == 0) exit 1; print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# freesasa_time PDB RESOLUTION THREADS RUNS: prints "median-wall-seconds area", or fails.
freesasa_time() {
  local pdb=$1 resolution=$2 threads=$3 runs=$4 i t0 t1 area="" times=()
  for ((i = 0; i < runs; ++i)); do
    t0=$EPOCHREALTIME
    freesasa --radius-from-occupancy --lee-richards --resolution="$resolution" --probe-radius="$probe" \
      --n-threads="$threads" --no-warnings "$pdb" >"$work/fs.out" 2>"$work/fs.err" || return 1
    t1=$EPOCHREALTIME
    times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}')")
  done
  area=$(awk '/^Total *:/ {print $3; exit}' "$work/fs.out")
  [[ -n "$area" ]] || return 1
  echo "$(printf '%s\n' "${times[@]}" | median) $area"
}

rows=()
for s in "${structures[@]}"; do
  file=$(resolve "$s") || { echo "surface_stage_table.sh: no structure '$s'" >&2; continue; }
  name=$s; [[ $s == capsid ]] || { name=$(basename "$file"); name=${name%.gz}; name=${name%.*}; }
  runs=$repeat; [[ $s == capsid ]] && runs=1
  pdb="$work/$name.radii.pdb"
  if ((use_freesasa)); then
    "$stage_times" "$file" --write-radius-pdb "$pdb" 2>"$work/err" || { cat "$work/err" >&2; continue; }
  fi
  first_total=""
  for threads in $thread_counts; do
    echo "surface_stage_table.sh: $name, $threads thread(s), $runs run(s)" >&2
    if ! line=$("$stage_times" "$file" --threads "$threads" --repeat "$runs" --probe "$probe" --density "$density" \
                2>"$work/err"); then
      echo "surface_stage_table.sh: $name: surface_stage_times failed:" >&2; tail -n 3 "$work/err" >&2
      rows+=("$name"$'\t'"failed"); continue
    fi
    IFS=$'\t' read -r atoms faces _vertices _threads _runs t_union t_cleanup t_check t_measures t_total peak area \
      _volume _method <<<"$line"
    [[ -z "$first_total" ]] && first_total=$t_total
    fs20="" fs200="" fs_area=""
    if ((use_freesasa)); then
      if r=$(freesasa_time "$pdb" 20 "$threads" "$runs"); then fs20=${r%% *}; else fs20=failed; fi
      if r=$(freesasa_time "$pdb" 200 "$threads" "$runs"); then fs200=${r%% *}; fs_area=${r#* }; else fs200=failed; fi
    fi
    rows+=("$(awk -F'\t' -v OFS='\t' -v name="$name" -v atoms="$atoms" -v threads="$threads" -v faces="$faces" \
      -v u="$t_union" -v c="$t_cleanup" -v k="$t_check" -v m="$t_measures" -v t="$t_total" -v peak="$peak" \
      -v first="$first_total" -v fs20="$fs20" -v fs200="$fs200" -v area="$area" -v fsa="$fs_area" -v runs="$runs" '
      function num(x) { return x ~ /^[0-9.eE+-]+$/ && x != "" }
      function ratio(a, b) { return num(a) && num(b) && (b > 0) ? sprintf("%.1f", a / b) : "" }
      BEGIN {
        diff = num(fsa) && (fsa > 0) ? sprintf("%+.2f", 100 * (area - fsa) / fsa) : ""
        print name, atoms, threads, runs, faces, sprintf("%.3f", u), sprintf("%.3f", c), sprintf("%.3f", k),
              sprintf("%.3f", m), sprintf("%.3f", t), peak, ratio(first, t),
              num(fs20) ? sprintf("%.3f", fs20) : fs20, num(fs200) ? sprintf("%.3f", fs200) : fs200,
              ratio(t, fs20), ratio(t, fs200), sprintf("%.1f", area), num(fsa) ? sprintf("%.1f", fsa) : "", diff
      }')")
  done
done

header="structure	atoms	threads	runs	faces	union s	cleanup s	check s	measures s	total s	peak MiB	speed-up"
header+="	FS20 s	FS200 s	÷FS20	÷FS200	area Å²	FS200 Å²	diff %"
{
  echo "$header"
  printf '%s\n' "${rows[@]}"
} | awk -F'\t' '
  NR == 1 { n = NF; line = "|"; sep = "|"; for (i = 1; i <= NF; i++) { line = line " " $i " |"; sep = sep (i == 1 ? "---|" : "---:|") }
            print line; print sep; next }
  { line = "|"; for (i = 1; i <= n; i++) line = line " " $i " |"; print line }'
