#!/usr/bin/python3
"""Plots the surface's area and volume error against icosphere density (matplotlib).

Usage (from the project root, after scripts/setup.sh):
    /usr/bin/python3 scripts/plot_accuracy.py docs/images/accuracy_vs_density.png [STRUCTURE ...]

For each structure (default data/pdb/1crn.pdb and data/pdb/1ubq.pdb) and both probes (1.4 Å and 0),
build/release/bench/accuracy_table measures molsurf's surface (union and cleanup, as written) at
densities 0.5-8 against the exact union of balls; the plot shows the relative errors of the
default, area-corrected spheres (solid) and of inscribed spheres (dashed).
"""
import argparse
import os
import re
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
TABLE = os.path.join(ROOT, "build", "release", "bench", "accuracy_table")
DENSITIES = ["0.5", "1", "2", "4", "8"]
ROW = re.compile(r"^\|\s*([\d.]+)\s*\|\s*(yes|no)\s*\|\s*\d+\s*\|\s*[\d.]+\s*\|\s*([+-][\d.]+)%\s*\|"
                 r"\s*[\d.]+\s*\|\s*([+-][\d.]+)%")


def measure(structure, probe):
    """Rows of accuracy_table: {corrected: [(density, area error %, volume error %)]}."""
    out = subprocess.run([TABLE, structure, "--probe", str(probe), *DENSITIES],
                         check=True, capture_output=True, text=True).stdout
    rows = {"yes": [], "no": []}
    for line in out.splitlines():
        m = ROW.match(line)
        if m:
            rows[m.group(2)].append((float(m.group(1)), float(m.group(3)), float(m.group(4))))
    if not rows["yes"]:
        raise SystemExit(f"accuracy_table printed no rows for {structure}:\n{out}")
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("png")
    parser.add_argument("structures", nargs="*",
                        default=[os.path.join(ROOT, "data", "pdb", n) for n in ("1crn.pdb", "1ubq.pdb")])
    args = parser.parse_args()

    figure, (area_axis, volume_axis) = plt.subplots(1, 2, figsize=(10, 4.2), sharex=True)
    colours = iter(plt.rcParams["axes.prop_cycle"].by_key()["color"])
    for structure in args.structures:
        name = os.path.basename(structure).split(".")[0]
        for probe in (1.4, 0.0):
            colour = next(colours)
            rows = measure(structure, probe)
            for corrected, style in (("yes", "-"), ("no", "--")):
                d, area, volume = zip(*rows[corrected])
                label = f"{name}, probe {probe:g}" + ("" if corrected == "yes" else ", inscribed")
                area_axis.plot(d, area, style, marker="o", color=colour, label=label)
                volume_axis.plot(d, volume, style, marker="o", color=colour, label=label)
    for axis, what in ((area_axis, "area"), (volume_axis, "volume")):
        axis.set_xscale("log", base=2)
        axis.set_xticks([float(x) for x in DENSITIES], DENSITIES)
        axis.axhspan(-0.5, 0.5, color="0.9", zorder=0)
        axis.axhline(0, color="0.5", linewidth=0.8)
        axis.axvline(2, color="0.5", linewidth=0.8, linestyle=":")
        axis.set_xlabel("icosphere density (vertices per Å²; default 2)")
        axis.set_ylabel(f"{what} error against the exact union of balls (%)")
    area_axis.legend(fontsize=7)
    figure.suptitle("molsurf surface accuracy against density (grey band: the 0.5 % target)")
    figure.tight_layout()
    figure.savefig(args.png, dpi=110)
    print(args.png)


if __name__ == "__main__":
    main()
