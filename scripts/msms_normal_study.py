#!/usr/bin/python3
"""How well the vertex normals of a molsurf MSMS file serve a reader that builds each
element's normal from its three vertex normals (TABI-PB's centroid-collocation reader
does: the normalized mean), against the face's own normal, for several rules of what a
vertex normal is. Used for the figures in docs/formats.md.

    scripts/msms_normal_study.py MOLSURF STRUCTURE [MOLSURF OPTIONS...]

Runs MOLSURF on the structure as an .xyzr sphere list (the atoms' centres are needed; a
.pdb or .cif is converted with gemmi, Bondi radii by element, hydrogens and waters
dropped) and prints, per rule, the median angle, the area-weighted mean and the share of
faces off by more than 20 degrees.
"""
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np


def unit(x):
    return x / np.linalg.norm(x, axis=1)[:, None]


def degrees(a, b):
    return np.degrees(np.arccos(np.clip(np.sum(a * b, axis=1), -1, 1)))


def to_xyzr(structure, xyzr):
    import gemmi
    bondi = {"C": 1.70, "N": 1.55, "O": 1.52, "S": 1.80, "P": 1.80, "FE": 1.80}
    st = gemmi.read_structure(str(structure))
    st.remove_hydrogens()
    st.remove_waters()
    with open(xyzr, "w") as out:
        for cra in st[0].all():
            p = cra.atom.pos
            out.write(f"{p.x} {p.y} {p.z} {bondi.get(cra.atom.element.name.upper(), 1.70)}\n")
    return xyzr


def main():
    molsurf, structure = sys.argv[1], Path(sys.argv[2])
    options = sys.argv[3:]  # e.g. --density 4
    with tempfile.TemporaryDirectory() as directory:
        stem = Path(directory) / "s"
        if structure.suffix != ".xyzr":
            structure = to_xyzr(structure, Path(directory) / "atoms.xyzr")
        atoms = np.loadtxt(structure, usecols=(0, 1, 2))
        subprocess.run([molsurf, str(structure), *options, "-o", f"{stem}.vert", "-q"], check=True)
        rows = np.loadtxt(f"{stem}.vert", skiprows=3, usecols=range(6))
        faces = np.loadtxt(f"{stem}.face", skiprows=3, dtype=int)
    points, written = rows[:, :3], unit(rows[:, 3:6])
    triangle, tag = faces[:, :3] - 1, faces[:, 4] - 1
    area_vector = np.cross(points[triangle[:, 1]] - points[triangle[:, 0]],
                           points[triangle[:, 2]] - points[triangle[:, 0]]) / 2
    area = np.linalg.norm(area_vector, axis=1)
    face_normal = area_vector / area[:, None]

    patches = [set() for _ in points]
    for f, t in enumerate(triangle):
        for v in t:
            patches[v].add(tag[f])
    inside = np.array([len(p) == 1 for p in patches])

    area_weighted = np.zeros_like(points)
    np.add.at(area_weighted, triangle.ravel(), np.repeat(area_vector, 3, axis=0))
    area_weighted = unit(area_weighted)
    angle_weighted = np.zeros_like(points)
    for k in range(3):
        u = points[triangle[:, (k + 1) % 3]] - points[triangle[:, k]]
        w = points[triangle[:, (k + 2) % 3]] - points[triangle[:, k]]
        angle = np.arctan2(np.linalg.norm(np.cross(u, w), axis=1), np.sum(u * w, axis=1))
        np.add.at(angle_weighted, triangle[:, k], face_normal * angle[:, None])
    angle_weighted = unit(angle_weighted)
    radial_sum = unit(np.array([sum(unit((points[v] - atoms[list(p)]))) for v, p in enumerate(patches)]))

    print(f"{len(triangle)} faces; vertices inside one atom's patch {100 * inside.mean():.1f} %, on seams "
          f"{100 * (1 - inside.mean()):.1f} %; faces with a seam vertex "
          f"{100 * np.mean(~inside[triangle].all(axis=1)):.1f} %")
    print(f"{'vertex normal':44s} {'median':>7s} {'area-wtd mean':>14s} {'> 20 deg':>9s}")
    for name, normal in [("as written (sphere's in a patch, area-weighted on seams)", written),
                         ("area-weighted everywhere", area_weighted),
                         ("angle-weighted everywhere", angle_weighted),
                         ("sum of the atoms' radial directions", radial_sum)]:
        error = degrees(unit(normal[triangle].sum(axis=1)), face_normal)
        print(f"{name[:44]:44s} {np.median(error):6.2f}° {np.average(error, weights=area):13.2f}° "
              f"{100 * np.mean(error > 20):8.1f}%")


if __name__ == "__main__":
    main()
