#!/usr/bin/python3
"""Renders a cut through a tetrahedral volume mesh (gmsh .msh) to a PNG (VTK's Python, off screen).

Usage (from the project root, after scripts/setup.sh):
    build/release/molsurf data/pdb/2hhb.pdb --volume-mesh /tmp/2hhb.vol.msh
    xvfb-run -a /usr/bin/python3 scripts/render_volume_slice.py /tmp/2hhb.vol.msh docs/images/2hhb_volume_slice.png

The tetrahedra on one side of the plane through the mesh's centre (normal along x, or --normal) are
drawn whole ("crinkle" cut, so the elements themselves are visible), coloured by their physical
region; their edges are drawn thin. The file is read with meshio, as a FEM user would read it.
"""
import argparse

import meshio
import numpy as np
import vtk
from vtk.util import numpy_support

REGION_COLOURS = [(0.85, 0.90, 0.98), (0.90, 0.62, 0.00), (0.00, 0.62, 0.45), (0.80, 0.47, 0.65),
                  (0.34, 0.71, 0.91), (0.94, 0.89, 0.26)]


def tetrahedra(mesh):
    """All tetrahedra of the mesh and each one's physical region (0 when the file has none)."""
    blocks, regions = [], []
    physical = mesh.cell_data.get("gmsh:physical")
    for i, block in enumerate(mesh.cells):
        if block.type != "tetra":
            continue
        blocks.append(block.data)
        regions.append(physical[i] if physical is not None else np.zeros(len(block.data), dtype=int))
    if not blocks:
        raise SystemExit("the file holds no tetrahedra")
    return np.vstack(blocks), np.concatenate(regions)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("msh")
    parser.add_argument("png")
    parser.add_argument("--normal", default="1,0,0", help="normal of the cutting plane (default 1,0,0)")
    args = parser.parse_args()

    mesh = meshio.read(args.msh)
    points = np.asarray(mesh.points, dtype=np.float64)
    tets, region = tetrahedra(mesh)
    normal = np.array([float(x) for x in args.normal.split(",")])
    centre = points[np.unique(tets)].mean(axis=0)
    centroids = points[tets].mean(axis=1)
    keep = (centroids - centre) @ normal < 0
    tets, region = tets[keep], region[keep]

    vtk_points = vtk.vtkPoints()
    vtk_points.SetData(numpy_support.numpy_to_vtk(points, deep=True))
    cells = np.hstack([np.full((len(tets), 1), 4, dtype=np.int64), tets.astype(np.int64)]).ravel()
    cell_array = vtk.vtkCellArray()
    cell_array.SetCells(len(tets), numpy_support.numpy_to_vtkIdTypeArray(cells, deep=True))
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(vtk_points)
    grid.SetCells(vtk.VTK_TETRA, cell_array)
    names = np.unique(region)
    colour_of = {name: REGION_COLOURS[i % len(REGION_COLOURS)] for i, name in enumerate(names)}
    rgb = np.array([colour_of[r] for r in region]) * 255
    scalars = numpy_support.numpy_to_vtk(rgb.astype(np.uint8), deep=True)
    grid.GetCellData().SetScalars(scalars)

    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(grid)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.SetScalarModeToUseCellData()
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    edges = vtk.vtkExtractEdges()
    edges.SetInputConnection(surface.GetOutputPort())
    edge_mapper = vtk.vtkPolyDataMapper()
    edge_mapper.SetInputConnection(edges.GetOutputPort())
    edge_mapper.ScalarVisibilityOff()
    edge_actor = vtk.vtkActor()
    edge_actor.SetMapper(edge_mapper)
    edge_actor.GetProperty().SetColor(0.25, 0.25, 0.25)
    edge_actor.GetProperty().SetOpacity(0.35)

    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddActor(edge_actor)
    renderer.SetBackground(1, 1, 1)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + 4 * np.ptp(points, axis=0).max() * normal / np.linalg.norm(normal)))
    camera.SetViewUp(0, 0, 1) if abs(normal[2]) < 0.9 else camera.SetViewUp(0, 1, 0)
    camera.Azimuth(20)
    camera.Elevation(15)
    renderer.ResetCamera()
    camera.Zoom(1.3)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(1000, 800)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"{args.png}: {len(tets)} of {keep.size} tetrahedra drawn; regions {list(names)}")


if __name__ == "__main__":
    main()
