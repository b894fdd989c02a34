#!/usr/bin/python3
"""Renders a molsurf surface coloured by chain to a PNG (VTK's Python, off screen).

Usage (from the project root, after scripts/setup.sh):
    xvfb-run -a /usr/bin/python3 scripts/render_surface.py data/pdb/2hhb.pdb docs/images/2hhb_chains.png
    xvfb-run -a /usr/bin/python3 scripts/render_surface.py --surface ses data/pdb/1crn.pdb docs/images/1crn_ses.png

The surface is computed by the molsurf module with the command line's defaults; each face takes the
colour of its atom's chain, so the picture shows which chain owns which part of the surface.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "release", "python"))
import molsurf  # noqa: E402
import vtk  # noqa: E402
from vtk.util import numpy_support  # noqa: E402

# Colour-blind-safe qualitative palette (Okabe–Ito), cycled for more chains.
PALETTE = np.array([
    (0.90, 0.62, 0.00), (0.34, 0.71, 0.91), (0.00, 0.62, 0.45), (0.94, 0.89, 0.26),
    (0.00, 0.45, 0.70), (0.84, 0.37, 0.00), (0.80, 0.47, 0.65), (0.60, 0.60, 0.60)])


def polydata(vertices, faces, colours):
    points = vtk.vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(vertices, dtype=np.float64), deep=True))
    cells = np.hstack([np.full((len(faces), 1), 3, dtype=np.int64), faces.astype(np.int64)]).ravel()
    polys = vtk.vtkCellArray()
    polys.SetCells(len(faces), numpy_support.numpy_to_vtkIdTypeArray(cells, deep=True))
    rgb = numpy_support.numpy_to_vtk((colours * 255).astype(np.uint8), deep=True)
    rgb.SetName("chain colour")
    out = vtk.vtkPolyData()
    out.SetPoints(points)
    out.SetPolys(polys)
    out.GetCellData().SetScalars(rgb)
    return out


def render(poly, png, size=(1000, 800), azimuth=30.0, elevation=20.0):
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(poly)
    mapper.SetScalarModeToUseCellData()
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetSpecular(0.2)
    actor.GetProperty().SetSpecularPower(20)
    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1, 1, 1)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()
    camera.Zoom(1.5)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("structure", help="PDB, mmCIF, PQR or .xyzr file")
    parser.add_argument("png", help="picture to write")
    parser.add_argument("--probe", type=float, default=1.4, help="probe radius, Å (default 1.4)")
    parser.add_argument("--surface", choices=("sas", "ses", "vdw"), default="sas",
                        help="which surface (default sas; ses: solvent excluded)")
    args = parser.parse_args()

    structure = molsurf.read_structure(args.structure)
    surface = molsurf.surface(structure, probe=args.probe, surface=args.surface)
    chains = np.asarray(structure.chains)
    names, chain_index = np.unique(chains, return_inverse=True)
    face_chain = chain_index[np.asarray(surface.atom_of_face)]
    colours = PALETTE[face_chain % len(PALETTE)]
    render(polydata(np.asarray(surface.vertices), np.asarray(surface.faces), colours), args.png)
    legend = ", ".join(f"{n}: {tuple(int(255 * c) for c in PALETTE[i % len(PALETTE)])}" for i, n in enumerate(names))
    print(f"{args.png}: {len(surface.faces)} faces, area {surface.area:.1f} Å², chains {legend}")


if __name__ == "__main__":
    main()
