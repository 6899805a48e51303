#!/usr/bin/python3
"""Deformation of adaptive micro planar patches (seed 002, figures 3 to 5), rendered to a PNG.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/patch_deformation.py OUT.png

A 24 x 24 planar patch (1,152 triangles). Left: a functional (Gaussian) bump,
refined only around it; middle: a box range pushed up, refined along the box
border; right: the same box after smoothing. Edges are drawn so the
refinement (1-to-4 splits and transition triangles) shows.
"""
import sys

import latticekit
from latticekit.rendering import save_png
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def panel(kind):
    plane = vtkPlaneSource()
    plane.SetResolution(24, 24)
    tri = vtkTriangleFilter()
    tri.SetInputConnection(plane.GetOutputPort())
    deform = latticekit.vtkLKPatchDeformationFilter()
    deform.SetInputConnection(tri.GetOutputPort())
    deform.SetMaxLevel(3)
    if kind == "functional":
        deform.AddFunctionalDeformation(0.0, 0.0, 0.0, 0.25, 30.0, 0.35)
    else:
        deform.AddRangeDeformation(-0.2, 0.2, -0.2, 0.2, -1, 1, 0, 0, 0.15)
    if kind == "smoothed":
        deform.AddSmoothingDeformation(0.0, 0.0, 0.0, 0.4, 12)
    deform.Update()
    return deform.GetOutput()


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1500, 500)
    for i, kind in enumerate(("functional", "range", "smoothed")):
        out = panel(kind)
        ren = vtkRenderer()
        ren.SetViewport(i / 3.0, 0, (i + 1) / 3.0, 1)
        ren.SetBackground(1, 1, 1)
        m = vtkPolyDataMapper()
        m.SetInputData(out)
        m.ScalarVisibilityOff()
        a = vtkActor()
        a.SetMapper(m)
        a.GetProperty().SetColor(0.6, 0.75, 0.9)
        a.GetProperty().EdgeVisibilityOn()
        a.GetProperty().SetEdgeColor(0.15, 0.15, 0.3)
        ren.AddActor(a)
        cam = ren.GetActiveCamera()
        cam.SetPosition(0.9, -1.3, 1.0)
        cam.SetFocalPoint(0, 0, 0)
        cam.SetViewUp(0, 0, 1)
        ren.ResetCamera()
        cam.Zoom(1.3)
        window.AddRenderer(ren)
        levels = out.GetCellData().GetArray("Level").GetRange()
        print(f"{kind}: {out.GetNumberOfPolys()} triangles, levels {int(levels[0])}-{int(levels[1])}, "
              f"z {out.GetBounds()[4]:.3f} to {out.GetBounds()[5]:.3f}")
    save_png(window, argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
