#!/usr/bin/env python3
"""The mesh's cavities against the true spheres' (docs/accuracy.md, "Cavities").

For each structure, runs molsurf (mesh and --json) and reads its report: the true cavities
(shells of the arrangement), the mesh's cavities, those matched, the mesh voids no true cavity
explains (artefacts) and the true cavities the facets open; and the facets' own volume of each
matched cavity against the true one.

Usage: bench/cavity_table.py [--probe P] [--density D] STRUCTURE...
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MOLSURF = os.path.join(ROOT, "build", "release", "molsurf")


def report(path, probe, density):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "report.json")
        subprocess.run([MOLSURF, "-q", "--probe", str(probe), "--density", str(density), "-o",
                        os.path.join(tmp, "s.vtp"), "--json", out, path], check=True)
        with open(out) as f:
            return json.load(f)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--probe", type=float, default=1.4)
    parser.add_argument("--density", type=float, default=2)
    parser.add_argument("structures", nargs="+")
    args = parser.parse_args()
    print(f"probe {args.probe} A, density {args.density}\n")
    print("| structure | true cavities | mesh cavities | matched | mesh artefacts | opened by the facets "
          "| matched: facets' volume error median / max |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for path in args.structures:
        r = report(path, args.probe, args.density)
        shells, comps = r["shells"], r["components"]
        true_cavities = [s for s in shells if s["kind"] == "cavity"]
        mesh_cavities = [c for c in comps if c["kind"] == "cavity"]
        matched = [s for s in true_cavities if s["mesh_component"] is not None
                   and comps[s["mesh_component"]]["kind"] == "cavity"]
        errors = sorted(abs(comps[s["mesh_component"]]["volume"] / s["volume"] - 1) for s in matched if s["volume"] > 0)
        artefacts = sum(1 for c in comps if c.get("artefact"))
        opened = len(true_cavities) - len(matched)
        med = f"{100 * errors[len(errors) // 2]:.1f} % / {100 * errors[-1]:.1f} %" if errors else "-"
        print(f"| {os.path.basename(path)} | {len(true_cavities)} | {len(mesh_cavities)} | {len(matched)} "
              f"| {artefacts} | {opened} | {med} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
