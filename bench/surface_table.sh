#!/usr/bin/env bash
# Solvent-accessible surfaces of a list of structures: one molsurf process per structure,
# timed by /usr/bin/time -v (wall clock, CPU time, peak RSS), with the numbers of the
# molsurf JSON report, printed as one aligned table (or Markdown). Optionally FreeSASA's
# total SASA and wall time beside ours.
#
# Usage: bench/surface_table.sh [OPTIONS] [STRUCTURE...]
#   STRUCTURE         a file, or a name in data/pdb (1crn, 2hhb, 7cth, 4yvs, 2btv, capsid = 1f2n_assembly1)
#                     default: 1crn 1ubq 2hhb 7cth
#   --all             the default list plus 4yvs 2btv capsid
#   --molsurf PATH    molsurf binary (default: build/release/molsurf)
#   --density D       icosphere density, vertices per A^2 (default 2)
#   --threads N       molsurf --threads (default: all cores, i.e. molsurf's default)
#   --timeout S       per-structure wall-clock limit in seconds (default 1800): the run is
#                     stopped (TERM, KILL 10 s later) and its row says "timeout"
#   --mem-limit MB    address-space limit per run (ulimit -v, default 3/4 of RAM) so that a run
#                     that grows too large fails instead of waking the OOM killer; 0 = none
#   --freesasa        also run FreeSASA (Lee & Richards) on the same atoms (waters dropped,
#                     HETATM kept, as molsurf's defaults) and print its area, time and the
#                     relative difference of our area
#   --freesasa-resolution N   FreeSASA --resolution (default: FreeSASA's, 20 slices)
#   --markdown        print a Markdown table
#   --tsv             print tab-separated raw values (for other scripts, e.g. density_table.sh)
#   --keep DIR        keep the outputs (meshes, JSON, time logs) in DIR instead of a temporary dir
#   -h, --help
#
# Every run writes the mesh (.ply) and the JSON report with --no-check; "surface s" is the
# JSON's seconds.surface, "cleanup s" its seconds.cleanup (surface improvement, when the
# binary has that step), "wall s" the whole process (read + surface + write + exit), "cpu s"
# user + system time of the process, "RSS MB" its peak resident set size.
set -u -o pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$script_dir/.." && pwd)

molsurf="$root/build/release/molsurf"
density=2
threads=""
timeout_s=1800
mem_total_kb=$(awk '/^MemTotal:/ {print $2}' /proc/meminfo 2>/dev/null || echo 0)
mem_limit_mb=$(( mem_total_kb * 3 / 4 / 1024 ))
use_freesasa=0
fs_resolution=""
mode=plain
keep_dir=""
all=0
structures=()

die() { echo "surface_table.sh: $*" >&2; exit 2; }
usage() { sed -n '2,/^set -u/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while (($#)); do
  case "$1" in
    --all) all=1 ;;
    --molsurf) molsurf=${2:?}; shift ;;
    --molsurf=*) molsurf=${1#*=} ;;
    --density) density=${2:?}; shift ;;
    --density=*) density=${1#*=} ;;
    --threads) threads=${2:?}; shift ;;
    --threads=*) threads=${1#*=} ;;
    --timeout) timeout_s=${2:?}; shift ;;
    --timeout=*) timeout_s=${1#*=} ;;
    --mem-limit) mem_limit_mb=${2:?}; shift ;;
    --mem-limit=*) mem_limit_mb=${1#*=} ;;
    --freesasa) use_freesasa=1 ;;
    --freesasa-resolution) fs_resolution=${2:?}; shift ;;
    --freesasa-resolution=*) fs_resolution=${1#*=} ;;
    --markdown) mode=markdown ;;
    --tsv) mode=tsv ;;
    --keep) keep_dir=${2:?}; shift ;;
    --keep=*) keep_dir=${1#*=} ;;
    -h|--help) usage; exit 0 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) structures+=("$1") ;;
  esac
  shift
done

[[ -x "$molsurf" ]] || die "molsurf binary not found or not executable: $molsurf (use --molsurf PATH)"
[[ "$timeout_s" =~ ^[0-9]+([.][0-9]+)?$ ]] || die "--timeout wants seconds"
[[ "$mem_limit_mb" =~ ^[0-9]+$ ]] || die "--mem-limit wants megabytes"
command -v timeout >/dev/null || die "coreutils 'timeout' is required"
if command -v jq >/dev/null; then json_tool=jq
elif command -v python3 >/dev/null; then json_tool=python3
else die "jq or python3 is required to read the JSON report"; fi
if ((use_freesasa)); then command -v freesasa >/dev/null || die "--freesasa: freesasa not found"; fi

if ((${#structures[@]} == 0)); then structures=(1crn 1ubq 2hhb 7cth); fi
if ((all)); then structures+=(4yvs 2btv capsid); fi

# A name -> a file in data/pdb.
resolve() {
  local s=$1 d="$root/data/pdb" c
  [[ "$s" == capsid ]] && s=1f2n_assembly1
  if [[ -f "$s" ]]; then echo "$s"; return 0; fi
  for c in "$d/$s" "$d/$s.pdb" "$d/$s.cif" "$d/$s.pdb.gz" "$d/$s.cif.gz"; do
    [[ -f "$c" ]] && { echo "$c"; return 0; }
  done
  return 1
}

# json FILE EXPR: EXPR is a jq path such as .seconds.surface
json() {
  if [[ $json_tool == jq ]]; then jq -r "$2 // empty" "$1" 2>/dev/null
  else python3 - "$1" "$2" <<'EOF' 2>/dev/null
import json, sys
v = json.load(open(sys.argv[1]))
expr = sys.argv[2]
if expr.startswith('[') or '|' in expr:
    sys.exit(1)
for k in [k for k in expr.split('.') if k]:
    v = v[k]
print(v)
EOF
  fi
}
count_components() { # FILE KIND
  if [[ $json_tool == jq ]]; then jq -r "[.components[]? | select(.kind == \"$2\")] | length" "$1" 2>/dev/null
  else python3 -c "import json,sys; print(sum(1 for c in json.load(open(sys.argv[1])).get('components',[]) if c.get('kind')==sys.argv[2]))" "$1" "$2" 2>/dev/null; fi
}

if [[ -n "$keep_dir" ]]; then mkdir -p "$keep_dir" || die "cannot create $keep_dir"; work=$keep_dir
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/surface_table.XXXXXX") || die "mktemp failed"
  trap 'rm -rf "$work"' EXIT
fi
trap 'echo "surface_table.sh: interrupted" >&2; exit 130' INT TERM

have_gnu_time=0   # SURFACE_TABLE_NO_GNU_TIME=1 forces the /proc fallback (to test it)
[[ -z "${SURFACE_TABLE_NO_GNU_TIME:-}" && -x /usr/bin/time ]] && /usr/bin/time -v true >/dev/null 2>&1 && have_gnu_time=1

# User + system seconds of this shell's waited-for children so far (bash's times builtin).
children_cpu() { # run as a builtin in this shell (not in a pipe, whose subshell has its own counters)
  times >"$work/.times"
  awk 'NR == 2 {t = 0; for (i = 1; i <= 2; i++) {split($i, p, "m"); sub(/s$/, "", p[2]); t += p[1] * 60 + p[2]} print t}' "$work/.times"
}

# measure TAG CMD...: runs CMD under timeout and the memory limit; sets m_rc m_wall m_cpu m_rss_kb.
# With GNU time, time wraps timeout, and wait4() reports the peak RSS of the largest waited-for
# descendant, i.e. of CMD. Without it, the wall clock comes from date and the peak RSS from
# polling VmHWM in /proc (sampled every 0.1 s, so a lower bound for short peaks).
measure() {
  local tag=$1; shift
  local tlog="$work/$tag.time"
  m_rc=0 m_wall="" m_cpu="" m_rss_kb=""
  if ((have_gnu_time)); then
    (
      ((mem_limit_mb > 0)) && ulimit -v $((mem_limit_mb * 1024))
      exec /usr/bin/time -v -o "$tlog" timeout -k 10 "$timeout_s" "$@"
    ) >"$work/$tag.out" 2>"$work/$tag.err"
    m_rc=$?
    m_wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; print s}' "$tlog")
    m_cpu=$(awk -F': ' '/User time \(seconds\)/ {u = $2} /System time \(seconds\)/ {s = $2} END {if (u != "") print u + s}' "$tlog")
    m_rss_kb=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$tlog")
  else
    local t0 t1 pid child hwm peak=0 c0 c1
    children_cpu >"$work/.c0"; c0=$(<"$work/.c0")
    t0=$(date +%s.%N)
    (
      ((mem_limit_mb > 0)) && ulimit -v $((mem_limit_mb * 1024))
      exec timeout -k 10 "$timeout_s" "$@"
    ) >"$work/$tag.out" 2>"$work/$tag.err" &
    pid=$!
    while kill -0 "$pid" 2>/dev/null; do
      for child in $pid $(cat /proc/"$pid"/task/*/children 2>/dev/null); do
        hwm=$(awk '/^VmHWM:/ {print $2}' /proc/"$child"/status 2>/dev/null)
        [[ -n "$hwm" ]] && ((hwm > peak)) && peak=$hwm
      done
      sleep 0.1
    done
    wait "$pid"; m_rc=$?
    t1=$(date +%s.%N)
    m_wall=$(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.2f", b - a}')
    m_rss_kb=$peak
    children_cpu >"$work/.c1"; c1=$(<"$work/.c1")
    m_cpu=$(awk -v a="$c0" -v b="$c1" 'BEGIN {printf "%.2f", b - a}')
  fi
  # GNU time exits with 128+N when the command died of signal N; timeout returns 124 (137 after KILL).
  if grep -q 'Command terminated by signal' "$tlog" 2>/dev/null && ((m_rc < 128)); then m_rc=$((128 + $(grep -o 'signal [0-9]*' "$tlog" | grep -o '[0-9]*'))); fi
  return 0
}

# Why a run failed, in a few words.
failure() { # RC ERRFILE
  local rc=$1 err=$2
  if ((rc == 124 || rc == 137)) && ! grep -qi 'bad_alloc\|out of memory\|cannot allocate' "$err" 2>/dev/null; then echo timeout
  elif grep -qi 'bad_alloc\|out of memory\|cannot allocate' "$err" 2>/dev/null; then echo "out of memory"
  elif ((rc > 128)); then echo "killed (signal $((rc - 128)))"
  else echo "failed (exit $rc)"; fi
}

fmt() { # PRINTF-FORMAT VALUE: empty and non-numeric values are printed as they are
  if [[ "$2" =~ ^[-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]]; then LC_ALL=C printf "$1" "$2"; else printf '%s' "$2"; fi
}

header=(structure atoms faces vertices "area A^2" "volume A^3" "comp out/cav" "surface s" "cleanup s" "wall s" "cpu s" "RSS MB" threads)
((use_freesasa)) && header+=("FreeSASA A^2" "FS atoms" "FS wall s" "diff %")
rows=()
tsv_rows=()

for s in "${structures[@]}"; do
  name=$(basename "$s"); name=${name%.gz}; name=${name%.*}
  file=$(resolve "$s") || { echo "surface_table.sh: no structure '$s' (in $root/data/pdb)" >&2; rows+=("$name"$'\t'"not found"); tsv_rows+=("$name"$'\t'"not found"); continue; }
  tag=$name
  args=("$file" -q -o "$work/$tag.ply" --json "$work/$tag.json" --no-check --density "$density")
  [[ -n "$threads" ]] && args+=(--threads "$threads")
  rm -f "$work/$tag.json"
  measure "$tag" "$molsurf" "${args[@]}"
  rc=$m_rc; ms_wall=$m_wall; ms_cpu=$m_cpu
  wall=$(fmt %.2f "$m_wall"); cpu=$(fmt %.2f "$m_cpu")
  rss=""; [[ -n "$m_rss_kb" ]] && rss=$(fmt %.0f "$(awk -v k="$m_rss_kb" 'BEGIN {print k / 1024}')")
  j="$work/$tag.json"
  if ((rc == 0)) && [[ -s "$j" ]]; then
    atoms=$(json "$j" .input.atoms); faces=$(json "$j" .faces); verts=$(json "$j" .vertices)
    area=$(json "$j" .area); vol=$(json "$j" .volume)
    outer=$(count_components "$j" outer); cav=$(count_components "$j" cavity)
    surf=$(json "$j" .seconds.surface); clean=$(json "$j" .seconds.cleanup); thr=$(json "$j" .threads)
    status=ok
  else
    atoms=""; faces=""; verts=""; area=""; vol=""; outer=""; cav=""; surf=""; clean=""
    thr=${threads:-$(nproc 2>/dev/null)}
    status=$(failure "$rc" "$work/$tag.err")
    echo "surface_table.sh: $name: $status; stderr tail:" >&2
    tail -n 3 "$work/$tag.err" >&2 2>/dev/null
  fi

  fs_area=""; fs_atoms=""; fs_wall=""; diff=""
  if ((use_freesasa)); then
    # Same atoms as molsurf's defaults: first model, no water, no hydrogen, HETATM kept.
    fin="$work/$tag.fs.${file##*.}"
    src=$file
    if [[ "$file" == *.gz ]]; then fin="$work/$tag.fs.$(basename "${file%.gz}" | sed 's/.*\.//')"; fi
    (if [[ "$file" == *.gz ]]; then gzip -dc "$file"; else cat "$file"; fi) |
      awk '
        /^(ATOM  |HETATM)/ && (substr($0, 18, 3) ~ /^(HOH|WAT|DOD)$/) {next}      # PDB columns
        ($1 == "ATOM" || $1 == "HETATM") && / (HOH|WAT|DOD) / {next}              # mmCIF atom_site rows
        {print}' >"$fin"
    fs_args=(--hetatm --no-warnings)
    [[ "$fin" == *.cif ]] && fs_args+=(--cif)
    [[ -n "$fs_resolution" ]] && fs_args+=(--resolution="$fs_resolution")
    [[ -n "$threads" ]] && fs_args+=(--n-threads="$threads")
    [[ -z "$threads" ]] && fs_args+=(--n-threads="$(nproc 2>/dev/null || echo 1)")
    measure "$tag.freesasa" freesasa "${fs_args[@]}" "$fin"
    if ((m_rc == 0)); then
      fs_area=$(awk '/^Total *:/ {print $3; exit}' "$work/$tag.freesasa.out")
      fs_atoms=$(awk '/^atoms *:/ {print $3; exit}' "$work/$tag.freesasa.out")
      fs_wall=$(fmt %.2f "$m_wall")
      [[ -n "$area" && -n "$fs_area" ]] && diff=$(awk -v a="$area" -v b="$fs_area" 'BEGIN {printf "%+.2f", 100 * (a - b) / b}')
    else
      fs_area=$(failure "$m_rc" "$work/$tag.freesasa.err")
    fi
    rm -f "$fin"
  fi
  rm -f "$work/$tag.ply"   # meshes can be large; the JSON and time logs stay (with --keep)

  # raw values for --tsv
  tsv_rows+=("$(IFS=$'\t'; echo "$name	$status	${atoms}	${faces}	${verts}	${area}	${vol}	${outer}	${cav}	${surf}	${ms_wall}	${ms_cpu}	${rss}	${thr}	${fs_area}	${fs_atoms}	${fs_wall}	${diff}")")

  if [[ $status == ok ]]; then
    row=("$name" "$atoms" "$faces" "$verts" "$(fmt %.1f "$area")" "$(fmt %.1f "$vol")" "$outer/$cav" "$(fmt %.2f "$surf")" "$(fmt %.2f "$clean")" "$wall" "$cpu" "$rss" "$thr")
  else
    row=("$name" "$status" "" "" "" "" "" "" "" "$wall" "$cpu" "$rss" "$thr")
  fi
  ((use_freesasa)) && row+=("$(fmt %.1f "$fs_area")" "$fs_atoms" "$fs_wall" "$diff")
  rows+=("$(IFS=$'\t'; echo "${row[*]}")")
done

if [[ $mode == tsv ]]; then
  echo -e "structure\tstatus\tatoms\tfaces\tvertices\tarea\tvolume\touter\tcavities\tsurface_s\twall_s\tcpu_s\trss_mb\tthreads\tfreesasa_area\tfreesasa_atoms\tfreesasa_wall_s\tdiff_pct"
  printf '%s\n' "${tsv_rows[@]}"
  exit 0
fi

{
  (IFS=$'\t'; echo "${header[*]}")
  printf '%s\n' "${rows[@]}"
} | awk -F'\t' -v md=$([[ $mode == markdown ]] && echo 1 || echo 0) '
  { n = NR; for (i = 1; i <= NF; i++) { c[NR, i] = $i; if (length($i) > w[i]) w[i] = length($i) } if (NF > nf) nf = NF }
  END {
    for (r = 1; r <= n; r++) {
      line = md ? "|" : ""
      for (i = 1; i <= nf; i++) {
        v = c[r, i]
        if (md) {
          if (r == 1 && v ~ /A\^2/) sub(/A\^2/, "Å²", v); if (r == 1 && v ~ /A\^3/) sub(/A\^3/, "Å³", v)
          line = line " " v " |"
        } else {
          f = (i == 1 || r == 1 && 0) ? "%-" w[i] "s" : "%" w[i] "s"
          line = line (i > 1 ? "  " : "") sprintf(f, v)
        }
      }
      print line
      if (r == 1 && md) { line = "|"; for (i = 1; i <= nf; i++) line = line (i == 1 ? "---|" : "---:|"); print line }
    }
  }'
