#!/usr/bin/env python3
"""Per-residue solvent-accessible surface area over the models of an NMR ensemble.

The structure is read once with gemmi; each model's areas are computed from memory (no file
written) by molsurf.areas(): the exact areas of the true spheres, with no mesh (as
`molsurf --areas-only`; molsurf.surface(...).area_per_residue gives the same numbers and a mesh
too). The plot shows the mean area of every residue over the models and its range; a CSV table
holds the numbers (areas in square angstrom).

    PYTHONPATH=build/release/python python3 examples/residue_sasa_nmr.py [STRUCTURE [PREFIX]] [--models N]

Defaults: data/pdb/1j8k.cif (fibronectin EDA domain, 20 models), writing 1j8k_residue_sasa.png
and 1j8k_residue_sasa.csv in the current directory; --models takes only the first N models.
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import gemmi  # noqa: E402
import molsurf  # noqa: E402


def main():
    root = pathlib.Path(__file__).resolve().parents[1]
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("structure", nargs="?", type=pathlib.Path, default=root / "data" / "pdb" / "1j8k.cif")
    parser.add_argument("prefix", nargs="?", help="output files: PREFIX.png and PREFIX.csv")
    parser.add_argument("--models", type=int, help="only the first N models")
    args = parser.parse_args()
    path = args.structure
    prefix = args.prefix or path.name.split(".")[0] + "_residue_sasa"

    st = gemmi.read_structure(str(path))
    models = [int(model.name) for model in st][: args.models]
    tables = [molsurf.areas(st, model=number).area_per_residue for number in models]
    residues = tables[0]
    for table in tables[1:]:  # NMR models share their residues
        assert np.array_equal(table[["chain", "residue_number"]], residues[["chain", "residue_number"]])
    area = np.array([table["area"] for table in tables])  # models x residues, A^2

    mean, low, high = area.mean(axis=0), area.min(axis=0), area.max(axis=0)
    number = residues["residue_number"]
    figure, axes = plt.subplots(figsize=(10, 4))
    axes.fill_between(number, low, high, step="mid", alpha=0.3, label=f"range over {len(models)} models")
    axes.step(number, mean, where="mid", label="mean")
    axes.set_xlabel("residue number")
    axes.set_ylabel("SASA (Å²)")
    axes.set_title(f"{path.name}: solvent-accessible area per residue (probe 1.4 Å)")
    axes.legend()
    figure.tight_layout()
    figure.savefig(prefix + ".png", dpi=100)

    with open(prefix + ".csv", "w") as out:
        out.write("chain,residue_name,residue_number,mean_area,min_area,max_area\n")
        for r, m, lo, hi in zip(residues, mean, low, high):
            out.write(f"{r['chain']},{r['residue_name']},{r['residue_number']},{m:.4f},{lo:.4f},{hi:.4f}\n")
    most = np.argsort(mean)[::-1][:3]
    print(f"{path.name}: {len(models)} models, {len(residues)} residues; most exposed: "
          + ", ".join(f"{residues['residue_name'][i]} {residues['residue_number'][i]} ({mean[i]:.1f} Å²)" for i in most))
    print(f"written: {prefix}.png, {prefix}.csv")


if __name__ == "__main__":
    main()
