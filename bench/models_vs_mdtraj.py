#!/usr/bin/env python3
"""Every model of an NMR ensemble in one call: molsurf.areas() against MDTraj's shrake_rupley.

Both tools get the same atoms (MDTraj's topology, hydrogens included), the same radii (MDTraj's
per-element radii, passed to molsurf) and the same probe (1.4 A); the frames are MDTraj's
coordinates (nm, times 10 for molsurf). MDTraj samples 960 points per atom (its default) and
runs on all cores (OpenMP); molsurf gives the exact areas of the true spheres on the threads asked
for. The table gives medians of in-process calls (loading excluded) and the largest per-atom
difference, which is MDTraj's sampling error.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/models_vs_mdtraj.py [STRUCTURE] [--repeats N]

Needs python3-mdtraj (Debian). Default structure: data/pdb/1j8k.cif (20 models), converted to
PDB through gemmi for MDTraj's reader.
"""
import argparse
import pathlib
import statistics
import tempfile
import time

import numpy as np

import gemmi
import mdtraj
import molsurf


def load_models(path):
    """An MDTraj trajectory of every model in `path` (PDB written through gemmi when it is mmCIF)."""
    if path.suffix in (".pdb", ".ent"):
        return mdtraj.load(str(path))
    st = gemmi.read_structure(str(path))
    st.setup_entities()
    with tempfile.TemporaryDirectory() as tmp:
        pdb = pathlib.Path(tmp) / (path.stem + ".pdb")
        st.write_pdb(str(pdb))
        return mdtraj.load(str(pdb))


def median_seconds(call, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def main():
    root = pathlib.Path(__file__).resolve().parents[1]
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("structure", nargs="?", type=pathlib.Path, default=root / "data" / "pdb" / "1j8k.cif")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--probe", type=float, default=1.4, help="A (default 1.4)")
    args = parser.parse_args()

    traj = load_models(args.structure)
    # MDTraj's radii (nm) for its own atoms, in A for molsurf.
    radii = np.array([mdtraj.geometry.sasa._ATOMIC_RADII[a.element.symbol] for a in traj.topology.atoms]) * 10
    xyz = traj.xyz.astype(np.float64) * 10

    t_md, md_area = median_seconds(lambda: mdtraj.shrake_rupley(traj, probe_radius=args.probe / 10), args.repeats)
    md_area = md_area * 100  # nm^2 -> A^2
    rows = [("MDTraj shrake_rupley (960 points, OpenMP)", t_md)]
    for threads in (1, 0):
        t, res = median_seconds(lambda: molsurf.areas(coords=xyz, radii=radii, probe=args.probe, threads=threads),
                                args.repeats)
        rows.append((f"molsurf.areas, exact ({res.threads} thread{'s' if res.threads > 1 else ''})", t))
        ms_area = res.area_per_atom
    diff = np.abs(md_area - ms_area)
    total_md, total_ms = md_area.sum(axis=1), ms_area.sum(axis=1)

    print(f"{args.structure.name}: {traj.n_frames} models, {traj.n_atoms} atoms, probe {args.probe} A, "
          f"median of {args.repeats}")
    print(f"| {'method':<44} | {'seconds':>8} | {'vs MDTraj':>9} |")
    print(f"|{'-' * 46}|{'-' * 10}|{'-' * 11}|")
    for name, t in rows:
        print(f"| {name:<44} | {t:8.3f} | {t / t_md:9.2f} |")
    print(f"per-atom |MDTraj - molsurf|: median {np.median(diff):.3f}, p95 {np.percentile(diff, 95):.3f}, "
          f"max {diff.max():.3f} A^2")
    print(f"total per model: MDTraj - molsurf from {(total_md - total_ms).min():+.1f} to "
          f"{(total_md - total_ms).max():+.1f} A^2 (molsurf {total_ms.mean():.1f} A^2 on average)")


if __name__ == "__main__":
    main()
