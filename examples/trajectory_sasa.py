#!/usr/bin/env python3
"""Per-frame solvent-accessible surface area of a trajectory, here the models of an NMR ensemble.

The models of the structure are read with molsurf's own atom selection (molsurf.read_structure on
a gemmi.Structure read once, one model at a time: the same atoms, radii and order as the command
line), stacked into a (frames, atoms, 3) coordinate array, and handed to molsurf.areas() in one call:
the frames run in parallel (one thread each, the result independent of the thread count) and give
the exact areas of the true spheres, with no mesh. Areas in square angstrom.

    PYTHONPATH=build/release/python python3 examples/trajectory_sasa.py [STRUCTURE] [--models N] [--probe P]

Defaults: data/pdb/1j8k.cif (fibronectin EDA domain, 20 models), probe 1.4 A. With MDTraj
installed, a loaded trajectory is passed the same way: its coordinates are in nanometres, so
multiply by 10 (see mdtraj_areas below).
"""
import argparse
import pathlib

import numpy as np

import gemmi
import molsurf


def models_as_trajectory(path, models=None):
    """(frames, atoms, 3) coordinates and (atoms,) radii of the structure's models (molsurf's selection)."""
    st = gemmi.read_structure(str(path))
    numbers = [int(model.name) for model in st][:models]
    structures = [molsurf.read_structure(st, model=number) for number in numbers]
    first = structures[0]
    for number, s in zip(numbers, structures):
        # A trajectory has the same atoms in every frame.
        if len(s) != len(first) or not np.array_equal(s.atom_names, first.atom_names):
            raise SystemExit(f"{path}: model {number} does not have model {numbers[0]}'s atoms")
    return numbers, np.stack([s.centres for s in structures]), first.radii


def mdtraj_areas(traj, radii, probe=1.4):
    """An MDTraj trajectory's areas: coordinates in nm -> A; radii (atoms,) in A, without the probe."""
    return molsurf.areas(coords=traj.xyz.astype(np.float64) * 10, radii=radii, probe=probe)


def main():
    root = pathlib.Path(__file__).resolve().parents[1]
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("structure", nargs="?", type=pathlib.Path, default=root / "data" / "pdb" / "1j8k.cif")
    parser.add_argument("--models", type=int, help="only the first N models")
    parser.add_argument("--probe", type=float, default=1.4, help="probe radius, A (default 1.4)")
    parser.add_argument("--threads", type=int, default=0, help="0: all cores (the result does not depend on it)")
    args = parser.parse_args()

    numbers, xyz, radii = models_as_trajectory(args.structure, args.models)
    t = molsurf.areas(coords=xyz, radii=radii, probe=args.probe, threads=args.threads)
    print(f"{args.structure.name}: {t.frames} models, {t.atoms} atoms, probe {t.probe} A, "
          f"{t.seconds:.2f} s on {t.threads} threads")
    print("model  SASA (A^2)   volume (A^3)")
    for number, area, volume in zip(numbers, t.area, t.volume):
        print(f"{number:5d}  {area:10.2f}  {volume:12.2f}")
    print(f"mean   {t.area.mean():10.2f}  {t.volume.mean():12.2f}")
    print(f"range  {t.area.min():.2f} to {t.area.max():.2f} A^2")
    # The most variable atoms over the frames: area_per_atom is (frames, atoms).
    spread = t.area_per_atom.std(axis=0)
    print("most variable atoms (std of SASA over the models, A^2):",
          ", ".join(f"{i}: {spread[i]:.1f}" for i in np.argsort(spread)[::-1][:5]))

    try:
        import mdtraj  # noqa: F401  (optional: Debian's python3-mdtraj)
    except ImportError:
        print("mdtraj not installed: with it, mdtraj_areas(mdtraj.load(...), radii) does the same")
        return
    # MDTraj's coordinates are float32 nanometres: areas agree with the above to float32 rounding,
    # not to the bit. Its topology keeps the hydrogens molsurf's reader drops, so the radii must
    # be given for its own atoms (one per atom, in its order); this shows the call only.
    print("mdtraj is available: pass traj.xyz * 10 (nm -> A) as coords, e.g. mdtraj_areas(traj, radii)")


if __name__ == "__main__":
    main()
