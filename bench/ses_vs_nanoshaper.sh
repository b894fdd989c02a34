#!/usr/bin/env bash
# The solvent-excluded surface of molsurf (`--surface ses`) against NanoShaper's (ray casting
# on a grid + marching cubes), side by side on the same atoms: whole-process time, faces,
# area and volume, and whether NanoShaper's mesh passes `molsurf check`. One Markdown table
# per structure, and a table of time ratios (NanoShaper ÷ molsurf) taken in the same run.
#
# Usage: NANOSHAPER=/path/to/NanoShaper bench/ses_vs_nanoshaper.sh [OPTIONS] [STRUCTURE...]
#   STRUCTURE        a structure file molsurf reads (default: data/pdb/1crn.pdb data/pdb/2hhb.pdb)
#   --runs N         timed runs per command (default 3); the median is reported
#   --densities "D…" molsurf --density values (default "1 2 4")
#   --scales "S…"    NanoShaper Grid_scale values, grid points per angstrom (default "1 2 4")
#   --probe R        probe radius in angstrom for both (default 1.4)
#   --threads N      threads for both (default: nproc); molsurf --threads, NanoShaper Number_thread
#   --molsurf PATH   molsurf binary (default: build/release/molsurf)
#   --keep DIR       keep the work files (meshes, configurations, logs) in DIR
#   -h, --help
#
# The same atoms for both tools: molsurf selects the atoms of STRUCTURE with its defaults
# (first model, no water, no hydrogens, hetero atoms kept) and gives each its ProtOr radius;
# one untimed `molsurf --areas-only --per-atom A.csv --sasa-structure A.pdb` writes them
# (coordinates from A.pdb, radii from A.csv, in the same order), and both tools then read the
# same .xyzr file. Commands timed (all runs interleaved, one command after the other, so that
# the machine's drift affects all alike; each writes an .off mesh):
#   molsurf -q --surface ses --probe R --density D --threads N -o ms.off --json ms.json A.xyzr
#   NanoShaper conf.prm     (Surface = ses, Grid_scale = S, Probe_Radius = R, Number_thread = N,
#                            Build_status_map, Accurate_Triangulation, Triangulation = true,
#                            Smooth_Mesh, Compute_Vertex_Normals, Cavity_Detection_Filling = false:
#                            plain OFF, cavities kept as molsurf keeps them; the rest as in
#                            NanoShaper 1.5's tests/1crn_ses configuration)
# Timed: wall seconds (bash's clock), CPU seconds (user + sys) and peak memory
# (/usr/bin/time); the CPU time is the steadier figure on a busy machine. "comp." counts
# closed components (outer surface and cavities: molsurf's JSON, `molsurf check` for
# NanoShaper). Reported: "area"/"volume" as each tool prints them (molsurf's JSON area and
# volume; NanoShaper's "Total, grid conformant, surface area" and its "Estimated volume",
# which comes from the grid before triangulation), and "mesh
# area"/"mesh volume" computed by this script from each tool's .off file in the same way
# (sum of triangle areas; signed volume by the divergence theorem). "check" is
# `molsurf check` on the last run's mesh (molsurf's own surfaces are checked before they are
# written; NanoShaper's get the same exact test here). NanoShaper writes OFF vertices with
# three decimals (printf %.3f, Surface.cpp), so vertices closer than 0.001 A land on the same
# point and their faces become degenerate (the "degenerate faces" its meshes fail on; in
# 1crn at grid scale 2 all 18 are such, none repeats an index). Its binary PLY
# (Save_Mesh_PLY_Format, needs -DENABLE_PLY=ON) keeps float precision; not used here.
#
# NANOSHAPER names a NanoShaper binary (GPL; not part of molsurf, and nothing here builds or
# installs it; the figures in docs/ses.md are NanoShaper 1.5's, built against Debian's CGAL 5.5).
# CI does not run this script.
set -u -o pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$script_dir/.." && pwd)

runs=3
densities="1 2 4"
scales="1 2 4"
probe=1.4
threads=$(nproc 2>/dev/null || echo 1)
molsurf="$root/build/release/molsurf"
keep=""
structures=()

die() { echo "ses_vs_nanoshaper.sh: $*" >&2; exit 2; }
usage() { sed -n '2,/^set -u/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while (($#)); do
  case "$1" in
    --runs) runs=${2:?}; shift ;;
    --runs=*) runs=${1#*=} ;;
    --densities) densities=${2:?}; shift ;;
    --densities=*) densities=${1#*=} ;;
    --scales) scales=${2:?}; shift ;;
    --scales=*) scales=${1#*=} ;;
    --probe) probe=${2:?}; shift ;;
    --probe=*) probe=${1#*=} ;;
    --threads) threads=${2:?}; shift ;;
    --threads=*) threads=${1#*=} ;;
    --molsurf) molsurf=${2:?}; shift ;;
    --molsurf=*) molsurf=${1#*=} ;;
    --keep) keep=${2:?}; shift ;;
    --keep=*) keep=${1#*=} ;;
    -h|--help) usage; exit 0 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) structures+=("$1") ;;
  esac
  shift
done

if [[ -z "${NANOSHAPER:-}" ]]; then
  echo "ses_vs_nanoshaper.sh: set NANOSHAPER to the NanoShaper binary, e.g." >&2
  echo "  NANOSHAPER=/work/peers/nanoshaper/build/NanoShaper $0" >&2
  echo "(molsurf neither builds nor installs it: see the comment at the top of this script)" >&2
  exit 2
fi
[[ -x "$NANOSHAPER" ]] || die "NANOSHAPER=$NANOSHAPER is not an executable file"
NANOSHAPER=$(cd "$(dirname "$NANOSHAPER")" && pwd)/$(basename "$NANOSHAPER")
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || die "--runs wants a positive whole number"
[[ "$threads" =~ ^[1-9][0-9]*$ ]] || die "--threads wants a positive whole number"
[[ -x "$molsurf" ]] || die "molsurf binary not found: $molsurf (build it, or give --molsurf PATH)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time not found (Debian: apt-get install time)"
command -v python3 >/dev/null || die "python3 not found"
((${#structures[@]})) || structures=("$root/data/pdb/1crn.pdb" "$root/data/pdb/2hhb.pdb")
read -r -a density_list <<<"$densities"
read -r -a scale_list <<<"$scales"

if [[ -n "$keep" ]]; then
  mkdir -p "$keep" || die "cannot make $keep"
  work=$(cd "$keep" && pwd)
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/ses_vs_nanoshaper.XXXXXX") || die "mktemp failed"
  trap 'rm -rf "$work"' EXIT
fi
trap 'echo "ses_vs_nanoshaper.sh: interrupted" >&2; exit 130' INT TERM

# Mesh area and signed volume of an OFF file (OFF, OFF+N, OFF+A, ...: the first three numbers
# of each vertex line are its position), in plain Python (no NumPy needed).
mesh_measures() {
  python3 - "$1" <<'EOF'
import math, sys
with open(sys.argv[1]) as f:
    head = f.readline()
    if not head.startswith("OFF"):
        sys.exit("not an OFF file")
    line = f.readline()
    while not line.strip() or line.lstrip().startswith("#"):
        line = f.readline()
    nv, nf = (int(t) for t in line.split()[:2])
    vs = []
    while len(vs) < nv:
        t = f.readline().split()
        if t and not t[0].startswith("#"):
            vs.append((float(t[0]), float(t[1]), float(t[2])))
    area = vol = 0.0
    done = 0
    while done < nf:
        t = f.readline().split()
        if not t or t[0].startswith("#"):
            continue
        k = int(t[0]); idx = [int(x) for x in t[1:1 + k]]
        a = vs[idx[0]]
        for j in range(1, k - 1):  # fan
            b = vs[idx[j]]; c = vs[idx[j + 1]]
            ux, uy, uz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
            wx, wy, wz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
            nx, ny, nz = uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx
            area += 0.5 * math.sqrt(nx * nx + ny * ny + nz * nz)
            vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
        done += 1
print(f"{nv} {nf} {area:.6f} {vol:.6f}")
EOF
}

median() { sort -g | awk '{v[NR] = $1} END {if (NR == 0) exit 1; print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# NanoShaper's configuration: Surface = ses at grid scale $1, in directory $2.
ns_config() {
  cat >"$2/conf.prm" <<EOF
# written by molsurf bench/ses_vs_nanoshaper.sh (after NanoShaper 1.5 tests/1crn_ses)
Operative_Mode = normal
XYZR_FileName = atoms.xyzr
Surface = ses
Grid_scale = $1
Grid_perfil = 90.0
Probe_Radius = $probe
Number_thread = $threads
Build_epsilon_maps = false
Build_status_map = true
Cavity_Detection_Filling = false
Keep_Water_Shaped_Cavities = false
Accurate_Triangulation = true
Triangulation = true
Smooth_Mesh = false
Compute_Vertex_Normals = false
Save_Mesh_MSMS_Format = false
Save_PovRay = false
Save_Status_map = false
Check_duplicated_vertices = false
Patch_Based_Algorithm = true
Analytical_Ray_Vs_Torus_Intersection = true
Load_Balancing = true
Force_Serial_Build = false
Optimize_Grids = true
Max_mesh_auxiliary_grid_size = 1000
Max_mesh_auxiliary_grid_2d_size = 2000
Max_ses_patches_auxiliary_grid_size = 1000
Max_ses_patches_auxiliary_grid_2d_size = 2000
Max_skin_patches_auxiliary_grid_size = 1000
Max_skin_patches_auxiliary_grid_2d_size = 2000
EOF
}

# timed DIR TAG CMD...: runs CMD in DIR (stdout, stderr to DIR/TAG.out, .err); writes
# DIR/TAG.time, "wall user sys maxrss_kB": wall from bash's EPOCHREALTIME (microseconds),
# the rest from /usr/bin/time (its %e has only 10 ms steps); fails if CMD fails.
timed() {
  local dir=$1 tag=$2 t0 t1 rc; shift 2
  t0=$EPOCHREALTIME
  (cd "$dir" && /usr/bin/time -o "$tag.rus" -f "%U %S %M" "$@" >"$tag.out" 2>"$tag.err"); rc=$?
  t1=$EPOCHREALTIME
  ((rc == 0)) || return "$rc"
  awk -v a="$t0" -v b="$t1" '{printf "%.4f %s\n", b - a, $0}' "$dir/$tag.rus" >"$dir/$tag.time"
}

cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null)
ms_version=$("$molsurf" --version 2>/dev/null | head -n 1)
echo "molsurf --surface ses against NanoShaper (SES, ray casting + marching cubes) on the same atoms (.xyzr"
echo "with molsurf's ProtOr radii), probe $probe Å, $threads thread(s) each; whole process, median of $runs"
echo "runs, all commands interleaved; $(nproc) cores${cpu:+ ($cpu)}, load average at start $(cut -d' ' -f1-3 /proc/loadavg)."
echo "molsurf: $molsurf${ms_version:+ ($ms_version)}; NanoShaper: $NANOSHAPER."
echo

for s in "${structures[@]}"; do
  [[ -f "$s" ]] || { [[ -f "$root/$s" ]] && s="$root/$s"; }
  [[ -f "$s" ]] || { echo "ses_vs_nanoshaper.sh: no structure '$s'" >&2; continue; }
  name=$(basename "$s"); name=${name%.gz}; name=${name%.*}
  dir="$work/$name"; mkdir -p "$dir"

  # The atoms, with molsurf's radii, as .xyzr (untimed).
  if ! "$molsurf" --areas-only -q --per-atom "$dir/atoms.csv" --sasa-structure "$dir/atoms.pdb" "$s" \
    >"$dir/atoms.log" 2>&1; then
    echo "ses_vs_nanoshaper.sh: $name: molsurf could not read it" >&2; tail -n 3 "$dir/atoms.log" >&2; continue
  fi
  natoms=$(python3 - "$dir/atoms.pdb" "$dir/atoms.csv" "$dir/atoms.xyzr" <<'EOF'
import csv, sys
xyz = [(l[30:38], l[38:46], l[46:54]) for l in open(sys.argv[1])
       if l.startswith(("ATOM  ", "HETATM"))]
radii = [row["radius"] for row in csv.DictReader(open(sys.argv[2]))]
if len(xyz) != len(radii):
    sys.exit(f"{len(xyz)} atoms in the structure written, {len(radii)} radii")
with open(sys.argv[3], "w") as out:
    for (x, y, z), r in zip(xyz, radii):
        out.write(f"{float(x):.3f} {float(y):.3f} {float(z):.3f} {float(r):.3f}\n")
print(len(xyz))
EOF
  ) || { echo "ses_vs_nanoshaper.sh: $name: cannot make the .xyzr" >&2; continue; }

  tags=()
  for d in "${density_list[@]}"; do tags+=("ms_d$d"); done
  for g in "${scale_list[@]}"; do
    tags+=("ns_g$g"); mkdir -p "$dir/ns_g$g"; ns_config "$g" "$dir/ns_g$g"
    ln -sf ../atoms.xyzr "$dir/ns_g$g/atoms.xyzr"
  done
  declare -A failed=()
  echo "ses_vs_nanoshaper.sh: $name ($natoms atoms): $runs timed run(s) of ${#tags[@]} commands, interleaved" >&2
  for ((i = 1; i <= runs; ++i)); do
    for t in "${tags[@]}"; do
      [[ -n "${failed[$t]:-}" ]] && continue
      echo "ses_vs_nanoshaper.sh:   run $i: $t" >&2
      if [[ $t == ms_d* ]]; then
        timed "$dir" "$t.run$i" "$molsurf" -q --surface ses --probe "$probe" --density "${t#ms_d}" \
          --threads "$threads" -o "$t.off" --json "$t.json" atoms.xyzr
      else
        timed "$dir/$t" "run$i" "$NANOSHAPER" conf.prm
      fi || { failed[$t]=1; echo "ses_vs_nanoshaper.sh: $name: $t failed (run $i); see $dir" >&2; }
    done
  done

  # Gather: one line per command, "tag wall cpu mem faces components area volume mesh_area mesh_volume check".
  results="$dir/results.txt"; : >"$results"
  for t in "${tags[@]}"; do
    if [[ -n "${failed[$t]:-}" ]]; then echo "$t failed" >>"$results"; continue; fi
    if [[ $t == ms_d* ]]; then tdir=$dir; tpre="$t.run"; off="$dir/$t.off"; else tdir="$dir/$t"; tpre=run; off="$dir/$t/triangulatedSurf.off"; fi
    wall=$(for ((i = 1; i <= runs; ++i)); do awk '{print $1}' "$tdir/$tpre$i.time"; done | median)
    cpus=$(for ((i = 1; i <= runs; ++i)); do awk '{print $2 + $3}' "$tdir/$tpre$i.time"; done | median)
    mem=$(for ((i = 1; i <= runs; ++i)); do awk '{print $4 / 1024}' "$tdir/$tpre$i.time"; done | median)
    read -r _nv nf marea mvol < <(mesh_measures "$off") || { echo "$t failed" >>"$results"; continue; }
    if [[ $t == ms_d* ]]; then
      read -r area vol comps < <(python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); print(j["area"], j["volume"], len(j["components"]))' "$dir/$t.json")
      check="valid (own)"
    else
      out="$tdir/run$runs.out"
      area=$(sed -n 's/.*grid conformant, surface area is \([0-9.eE+-]*\).*/\1/p' "$out" | tail -n 1)
      vol=$(sed -n 's/.*Estimated volume \([0-9.eE+-]*\).*/\1/p' "$out" | tail -n 1)
      "$molsurf" check "$off" >"$tdir/check.txt" 2>&1; rc=$?
      comps=$(awk '$1 == "components" {print $2; exit}' "$tdir/check.txt")
      if ((rc == 0)); then check=valid; else
        check="INVALID: $(sed -n '/^INVALID/,$ s/^ *- //p' "$tdir/check.txt" | sed 's/:.*//; s/|/\//g' | paste -sd ';' | sed 's/;/; /g')"
      fi
    fi
    echo "$t $wall $cpus $mem $nf ${comps:-?} ${area:-nan} ${vol:-nan} $marea $mvol $check" >>"$results"
  done
  unset failed

  python3 - "$name" "$natoms" "$results" <<'EOF'
import sys
name, natoms, path = sys.argv[1], sys.argv[2], sys.argv[3]
rows = []
for line in open(path):
    t = line.split(maxsplit=10)
    rows.append(t)
def setting(tag):
    return ("molsurf", f"density {tag[4:]}") if tag.startswith("ms_d") else ("NanoShaper", f"grid scale {tag[4:]}")
ms = [r for r in rows if r[0].startswith("ms_d") and r[1] != "failed"]
print(f"### {name} ({natoms} atoms)\n")
print("| tool | setting | faces | comp. | area Å² | volume Å³ | mesh area Å² | mesh volume Å³ | wall s | CPU s | peak MiB | check |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
for r in rows:
    tool, st = setting(r[0])
    if r[1] == "failed":
        print(f"| {tool} | {st} | failed | | | | | | | | | |"); continue
    _, wall, cpu, mem, nf, comps, area, vol, ma, mv, check = r
    print(f"| {tool} | {st} | {int(nf):,} | {comps} | {float(area):.1f} | {float(vol):.1f} | {float(ma):.1f} | {float(mv):.1f} "
          f"| {float(wall):.3f} | {float(cpu):.3f} | {float(mem):.0f} | {check.strip()} |".replace(",", " "))
ns = [r for r in rows if r[0].startswith("ns_g") and r[1] != "failed"]
if ms and ns:
    print(f"\nNanoShaper time ÷ molsurf time, {name}: wall (CPU), medians of the same run\n")
    print("| NanoShaper | " + " | ".join(f"÷ molsurf {setting(m[0])[1]}" for m in ms) + " |")
    print("|---|" + "---:|" * len(ms))
    for n in ns:
        cells = [f"{float(n[1]) / float(m[1]):.3f} ({float(n[2]) / float(m[2]):.3f})" for m in ms]
        print(f"| {setting(n[0])[1]} | " + " | ".join(cells) + " |")
print()
EOF
done
