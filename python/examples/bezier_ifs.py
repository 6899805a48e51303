#!/usr/bin/python3
"""Bezier curves and surfaces drawn by iterated function systems (seed 003), to a PNG.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/bezier_ifs.py OUT.png

Left: a cubic curve by the deterministic algorithm at depths 1, 2 and 6 (split at
t = 0.3), over its control polygon. Middle: the quadratic curve of the paper's
fig. 3 by its direct planar IFS (chaos game). Right: a bicubic patch by the chaos
game with map probabilities 0.1, 0.2, 0.3, 0.4, coloured by the hit density (the
invariant measure as a texture).
"""
import sys

import latticekit
from latticekit.rendering import save_png
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def points(coords, polygon=False):
    pd = vtkPolyData()
    p = vtkPoints()
    for c in coords:
        p.InsertNextPoint(c)
    pd.SetPoints(p)
    if polygon:
        lines = vtkCellArray()
        lines.InsertNextCell(len(coords))
        for i in range(len(coords)):
            lines.InsertCellPoint(i)
        pd.SetLines(lines)
    return pd


def actor(source, color, width=1.0, point_size=1.0, scalars=None, scalar_range=None):
    m = vtkPolyDataMapper()
    if hasattr(source, "GetOutputPort"):
        m.SetInputConnection(source.GetOutputPort())
    else:
        m.SetInputData(source)
    if scalars:
        m.SetScalarModeToUsePointFieldData()
        m.SelectColorArray(scalars)
        m.SetScalarRange(*scalar_range)
        m.ScalarVisibilityOn()
    else:
        m.ScalarVisibilityOff()
    a = vtkActor()
    a.SetMapper(m)
    a.GetProperty().SetColor(color)
    a.GetProperty().SetLineWidth(width)
    a.GetProperty().SetPointSize(point_size)
    return a


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1500, 500)
    renderers = []
    for i in range(3):
        r = vtkRenderer()
        r.SetViewport(i / 3.0, 0, (i + 1) / 3.0, 1)
        r.SetBackground(1, 1, 1)
        window.AddRenderer(r)
        renderers.append(r)

    cubic = [(0, 0, 0), (1, 2, 0), (3, 2, 0), (4, 0, 0)]
    renderers[0].AddActor(actor(points(cubic, True), (0.6, 0.6, 0.6)))
    for depth, color, offset in ((1, (0.9, 0.6, 0.1), 0), (2, (0.2, 0.6, 0.2), 0), (6, (0.1, 0.2, 0.8), 0)):
        ifs = latticekit.vtkLKBezierIFSFilter()
        ifs.SetInputData(points(cubic))
        ifs.SetSplitParameter(0.3)
        ifs.SetDepth(depth)
        renderers[0].AddActor(actor(ifs, color, width=3.0 if depth == 6 else 2.0))

    quadratic = [(0.1, 0.98, 0), (1.05, 1.7, 0), (2.1, 0.2, 0)]
    renderers[1].AddActor(actor(points(quadratic, True), (0.6, 0.6, 0.6)))
    planar = latticekit.vtkLKBezierIFSFilter()
    planar.SetInputData(points(quadratic))
    planar.SetShapeToQuadraticPlanar()
    planar.SetAlgorithmToChaosGame()
    planar.SetNumberOfPoints(20000)
    renderers[1].AddActor(actor(planar, (0.8, 0.1, 0.1), point_size=2.0))

    net = [(i, j, 1.5 if i in (1, 2) and j in (1, 2) else 0.0) for i in range(4) for j in range(4)]
    surface = latticekit.vtkLKBezierIFSFilter()
    surface.SetInputData(points(net))
    surface.SetShapeToSurface()
    surface.SetAlgorithmToChaosGame()
    surface.SetNumberOfPoints(400000)
    surface.SetDensityBins(32)
    p = vtkDoubleArray()
    for v in (0.1, 0.2, 0.3, 0.4):
        p.InsertNextValue(v)
    surface.SetProbabilities(p)
    surface.Update()
    dmin, dmax = surface.GetOutput().GetPointData().GetArray("HitDensity").GetRange()
    renderers[2].AddActor(actor(surface, (0.2, 0.2, 0.2), point_size=1.5, scalars="HitDensity",
                                scalar_range=(0.0, min(dmax, 4.0))))
    cam = renderers[2].GetActiveCamera()
    cam.SetPosition(-2.5, -4.0, 6.0)
    cam.SetFocalPoint(1.5, 1.5, 0.5)
    cam.SetViewUp(0, 0, 1)
    for r in renderers:
        r.ResetCamera()
    print("hit density from %.3f to %.3f of the mean" % (dmin, dmax))
    save_png(window, argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
