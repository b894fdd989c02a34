#!/usr/bin/env bash
# How the solvent-accessible surface converges with icosphere density, and what it costs:
# one structure at several densities (each a separate molsurf process, run and timed by
# bench/surface_table.sh), with the area difference to the densest run and to FreeSASA.
#
# Usage: bench/density_table.sh [OPTIONS] [STRUCTURE]
#   STRUCTURE          file or name in data/pdb (default 1crn)
#   --densities "D..." densities in vertices per A^2 (default "0.5 1 2 4 8")
#   --molsurf PATH     molsurf binary (default: build/release/molsurf)
#   --threads N        molsurf --threads (default: all cores)
#   --timeout S        per-run limit in seconds (default 1800); later densities are skipped
#                      once one run times out or fails
#   --mem-limit MB     per-run address-space limit (see surface_table.sh)
#   --freesasa-resolution N  FreeSASA Lee & Richards slices per atom for the reference
#                      (default 1000: converged to ~0.01 %; FreeSASA's own default is 20)
#   --no-freesasa      no FreeSASA column
#   --markdown         Markdown table
#   -h, --help
#
# Columns: faces, vertices, area (A^2), volume (A^3), surface seconds (JSON seconds.surface),
# wall seconds, peak RSS, and the relative area and volume differences (%) to the densest
# run, and the area difference to FreeSASA's total SASA of the same atoms.
set -u -o pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
structure=1crn
densities="0.5 1 2 4 8"
pass=()
fs_res=1000
use_fs=1
markdown=0

die() { echo "density_table.sh: $*" >&2; exit 2; }
while (($#)); do
  case "$1" in
    --densities) densities=${2:?}; shift ;;
    --densities=*) densities=${1#*=} ;;
    --molsurf|--threads|--timeout|--mem-limit) pass+=("$1" "${2:?}"); shift ;;
    --molsurf=*|--threads=*|--timeout=*|--mem-limit=*) pass+=("$1") ;;
    --freesasa-resolution) fs_res=${2:?}; shift ;;
    --freesasa-resolution=*) fs_res=${1#*=} ;;
    --no-freesasa) use_fs=0 ;;
    --markdown) markdown=1 ;;
    -h|--help) sed -n '2,/^set -u/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) structure=$1 ;;
  esac
  shift
done

# split_tsv LINE: fields into the array f, keeping empty ones (a tab in IFS would merge them)
split_tsv() { IFS=$'\x1f' read -r -a f <<<"${1//$'\t'/$'\x1f'}"; }

table="$script_dir/surface_table.sh"
[[ -x "$table" ]] || die "needs $table"

# FreeSASA runs once, with the first density (surface_table.sh selects the same atoms).
lines=()
fs_area=""; fs_atoms=""; fs_wall=""
first=1
for d in $densities; do
  extra=()
  if ((use_fs && first)); then extra=(--freesasa --freesasa-resolution "$fs_res"); fi
  out=$("$table" --tsv "${pass[@]}" "${extra[@]}" --density "$d" "$structure") || die "surface_table.sh failed"
  row=$(printf '%s\n' "$out" | sed -n 2p)
  lines+=("$d"$'\t'"$row")
  if ((use_fs && first)); then
    split_tsv "$row"
    fs_area=${f[14]:-}; fs_atoms=${f[15]:-}; fs_wall=${f[16]:-}
  fi
  first=0
  status=$(printf '%s\n' "$row" | cut -f2)
  if [[ "$status" != ok ]]; then echo "density_table.sh: density $d: $status; skipping denser runs" >&2; break; fi
done

# the densest successful run is the reference
ref_area=""; ref_vol=""; ref_d=""
for l in "${lines[@]}"; do
  split_tsv "$l"
  [[ "${f[2]}" == ok ]] && { ref_d=${f[0]}; ref_area=${f[6]}; ref_vol=${f[7]}; }
done

{
  echo -e "density\tfaces\tvertices\tarea A^2\tvolume A^3\tsurface s\twall s\tRSS MB\tarea vs densest %\tvolume vs densest %\tarea vs FreeSASA %"
  for l in "${lines[@]}"; do
    split_tsv "$l"
    # f: 0 density, 1 name, 2 status, 3 atoms, 4 faces, 5 vertices, 6 area, 7 volume, 8 outer,
    #    9 cavities, 10 surface_s, 11 wall_s, 12 cpu_s, 13 rss_mb, 14 threads, ...
    if [[ "${f[2]}" == ok ]]; then
      awk -v OFS='\t' -v d="${f[0]}" -v fa="${f[4]}" -v ve="${f[5]}" -v a="${f[6]}" -v v="${f[7]}" \
          -v s="${f[10]}" -v w="${f[11]}" -v r="${f[13]}" -v ra="$ref_area" -v rv="$ref_vol" -v fs="$fs_area" 'BEGIN {
        dfs = (fs ~ /^[0-9.]+$/) ? sprintf("%+.3f", 100 * (a - fs) / fs) : ""
        print d, fa, ve, sprintf("%.2f", a), sprintf("%.2f", v), sprintf("%.2f", s), sprintf("%.2f", w), r,
              sprintf("%+.3f", 100 * (a - ra) / ra), sprintf("%+.3f", 100 * (v - rv) / rv), dfs }'
    else
      echo -e "${f[0]}\t${f[2]}\t\t\t\t\t${f[11]:-}\t${f[13]:-}\t\t\t"
    fi
  done
} | awk -F'\t' -v md="$markdown" '
  { n = NR; for (i = 1; i <= NF; i++) { c[NR, i] = $i; if (length($i) > w[i]) w[i] = length($i) } if (NF > nf) nf = NF }
  END {
    for (r = 1; r <= n; r++) {
      line = md ? "|" : ""
      for (i = 1; i <= nf; i++) {
        v = c[r, i]
        if (md) { if (r == 1) { sub(/A\^2/, "Å²", v); sub(/A\^3/, "Å³", v) } line = line " " v " |" }
        else line = line (i > 1 ? "  " : "") sprintf("%" w[i] "s", v)
      }
      print line
      if (r == 1 && md) { line = "|"; for (i = 1; i <= nf; i++) line = line "---:|"; print line }
    }
  }'

name=$(basename "$structure"); name=${name%.gz}; name=${name%.*}
echo
echo "structure: $name${ref_d:+; densest run: density $ref_d}"
if ((use_fs)) && [[ -n "$fs_area" ]]; then
  echo "FreeSASA 2.1.2 (Lee & Richards, $fs_res slices, same atoms: $fs_atoms): $fs_area A^2 in $fs_wall s"
fi
