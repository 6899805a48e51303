#!/usr/bin/python3
"""Homogenized Loop subdivision (seed 001, figs. 6 to 8), rendered to a PNG.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/homogenized_loop.py OUT.png [WEIGHT]

An octahedron-like control mesh (a cube's triangulated surface) subdivided four
times: plain Loop, then a weight on one vertex, on a ring of edges, and on one
face (default weight 6). The control mesh is drawn as a wire cage.
"""
import sys

import latticekit
from latticekit.rendering import edge_actor, save_png
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def cube():
    points, polys = vtkPoints(), vtkCellArray()
    for p in CORNERS:
        points.InsertNextPoint(p)
    for a, b, c, d in QUADS:
        for tri in ((a, b, c), (a, c, d)):
            polys.InsertNextCell(3)
            for i in tri:
                polys.InsertCellPoint(i)
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def weights(name, n, index, value):
    a = vtkDoubleArray()
    a.SetName(name)
    a.SetNumberOfTuples(n)
    a.Fill(1.0)
    if index is not None:
        a.SetValue(index, value)
    return a


def panel(kind, w):
    mesh = cube()
    if kind == "vertex":
        mesh.GetPointData().AddArray(weights("LoopWeight", 8, 6, w))
    elif kind == "edge":
        lines = vtkCellArray()
        lines.InsertNextCell(5)  # the top square's ring of edges
        for i in (4, 5, 6, 7, 4):
            lines.InsertCellPoint(i)
        mesh.SetLines(lines)
        mesh.GetCellData().AddArray(weights("LoopWeight", mesh.GetNumberOfCells(), 0, w))
    elif kind == "face":
        a = weights("LoopWeight", 12, None, w)
        a.SetValue(2, w)  # both triangles of the top face
        a.SetValue(3, w)
        mesh.GetCellData().AddArray(a)
    loop = latticekit.vtkLKHomogenizedLoopFilter()
    loop.SetInputData(mesh)
    loop.SetNumberOfSubdivisions(4)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(loop.GetOutputPort())
    return mesh, normals


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    w = float(argv[2]) if len(argv) > 2 else 6.0
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1600, 420)
    for i, kind in enumerate(["plain", "vertex", "edge", "face"]):
        mesh, surface = panel(kind, w)
        ren = vtkRenderer()
        ren.SetViewport(i / 4.0, 0, (i + 1) / 4.0, 1)
        ren.SetBackground(1, 1, 1)
        m = vtkPolyDataMapper()
        m.SetInputConnection(surface.GetOutputPort())
        m.ScalarVisibilityOff()
        a = vtkActor()
        a.SetMapper(m)
        a.GetProperty().SetColor(0.55, 0.7, 0.9)
        ren.AddActor(a)
        ren.AddActor(edge_actor(mesh))
        cam = ren.GetActiveCamera()
        cam.SetPosition(2.6, -1.8, 2.2)
        cam.SetFocalPoint(0.5, 0.5, 0.5)
        cam.SetViewUp(0, 0, 1)
        ren.ResetCamera()
        window.AddRenderer(ren)
        print(kind, "weight", 1.0 if kind == "plain" else w)
    save_png(window, argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
