#!/usr/bin/python3
"""A lattice and its smooth surface, rendered to a PNG.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/lattice_surface.py LABELMAP_OR_CT OUT.png [VERTICES]

The bone surface is fitted with a lattice of VERTICES vertices (vtkLKLatticeFitFilter:
QEM on the rounded lattice surface, quad pairing, Ceres refinement), and
vtkLKLatticeSurfaceFilter builds its G1 Gregory-patch surface. The Metro error of
the fit is printed.
Left: the lattice (cage). Right: the smooth surface with the cage over it.
"""
import sys

import latticekit
from latticekit.rendering import save_png
from vtkmodules.vtkFiltersExtraction import vtkExtractEdges
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    vertices = int(argv[3]) if len(argv) > 3 else 500
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(argv[1])
    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.Update()
    lattice = latticekit.vtkLKLatticeFitFilter()
    lattice.SetInputConnection(bone.GetOutputPort())
    lattice.SetTargetNumberOfVertices(vertices)
    lattice.QuadPairingOn()
    lattice.RefinementOn()
    lattice.Update()
    fd = lattice.GetOutput().GetFieldData()
    print("lattice: %d vertices, %d triangles, %d quads; Metro max %.4f %%, mean %.4f %% of the diagonal" % (
        fd.GetArray("ControlVertices").GetValue(0), fd.GetArray("Triangles").GetValue(0),
        fd.GetArray("Quads").GetValue(0), fd.GetArray("Hausdorff_MaxPercent").GetValue(0),
        fd.GetArray("Hausdorff_MeanPercent").GetValue(0)))
    surface = latticekit.vtkLKLatticeSurfaceFilter()
    surface.SetInputConnection(lattice.GetOutputPort())
    surface.SetResolution(8)
    surface.Update()
    if surface.GetOutput().GetNumberOfPoints() == 0:
        print("error: no surface (see the messages above)", file=sys.stderr)
        return 1
    print("lattice: %d vertices, %d faces; surface: %d patches, %d display polygons" % (
        lattice.GetOutput().GetNumberOfPoints(), lattice.GetOutput().GetNumberOfPolys(),
        surface.GetNumberOfPatches(), surface.GetOutput().GetNumberOfPolys()))

    edges = vtkExtractEdges()
    edges.SetInputConnection(lattice.GetOutputPort())
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1400, 700)
    camera = None
    for index, show_surface in enumerate((False, True)):
        renderer = vtkRenderer()
        renderer.SetViewport(0.5 * index, 0.0, 0.5 * index + 0.5, 1.0)
        renderer.SetBackground(1, 1, 1)
        cage = vtkActor()
        cage_mapper = vtkPolyDataMapper()
        cage_mapper.SetInputConnection(edges.GetOutputPort())
        cage.SetMapper(cage_mapper)
        cage.GetProperty().SetColor(0.1, 0.1, 0.1)
        renderer.AddActor(cage)
        shape = vtkActor()
        shape_mapper = vtkPolyDataMapper()
        shape_mapper.SetInputConnection((surface if show_surface else lattice).GetOutputPort())
        shape_mapper.ScalarVisibilityOff()
        shape.SetMapper(shape_mapper)
        shape.GetProperty().SetColor(0.95, 0.85, 0.65)
        if not show_surface:
            shape.GetProperty().SetInterpolationToFlat()
        renderer.AddActor(shape)
        if camera is None:
            camera = renderer.GetActiveCamera()
            camera.SetFocalPoint(0, 0, 0)
            camera.SetPosition(0, -1, 0.6)  # LPS: from the front, a little above
            camera.SetViewUp(0, 0, 1)
            renderer.ResetCamera()
            camera.Zoom(1.3)
        else:
            renderer.SetActiveCamera(camera)
        window.AddRenderer(renderer)
    save_png(window, argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
