#!/usr/bin/python3
"""CT (or label map) -> bone surface -> the cutting guide of a plane cut, from Python.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/cutting_guide.py \\
           INPUT OX OY OZ NX NY NZ OUT_FOLDER [--other-side]

The cut's plane passes through (OX, OY, OZ) with normal (NX, NY, NZ), patient
mm as the surface is. The guide is a shell on the bone across that plane,
with a slot for the saw blade; it goes on the side the bone's section there
is thin across, away from the bone round the cut (a mandible's outer side),
or on the other side with --other-side. OUT_FOLDER gets guide.stl (to print),
guide.vtp (with the guide's facts in its field data) and guide.png (the
guide on the bone, seen from the side it goes on).
"""
import os
import sys

import latticekit
from latticekit.rendering import save_png
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the render window's back end)


def main(argv):
    if len(argv) < 9:
        print(__doc__)
        return 2
    try:
        origin = [float(v) for v in argv[2:5]]
        normal = [float(v) for v in argv[5:8]]
    except ValueError:
        print("error: the plane needs six numbers: OX OY OZ NX NY NZ", file=sys.stderr)
        return 2
    folder = argv[8]
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(argv[1])

    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.SetIsoValue(300)  # HU; label maps are detected and use 0.5

    guide = latticekit.vtkLKCuttingGuideFilter()
    guide.SetInputConnection(bone.GetOutputPort())
    guide.SetPlaneOrigin(origin)
    guide.SetPlaneNormal(normal)
    guide.SetOtherSide("--other-side" in argv[9:])
    guide.Update()
    if guide.GetOutput().GetNumberOfCells() == 0:
        print("error: no guide was made (see the messages above)", file=sys.stderr)
        return 1

    approach = guide.GetApproachUsed()
    print("cutting guide: slot %.1f mm long and %.1f mm wide, walls %.1f mm thick, %d screw holes of %.1f mm, "
          "on %.0f mm^2 of bone; put on along (%.3f, %.3f, %.3f); %.0f mm^3"
          % (guide.GetSlotLength(), guide.GetSlotWidth(), guide.GetThickness(), guide.GetNumberOfScrewHoles(),
             guide.GetScrewHoleDiameter(), guide.GetContactArea(), -approach[0], -approach[1], -approach[2],
             guide.GetVolume()))

    os.makedirs(folder, exist_ok=True)
    stl = vtkSTLWriter()
    stl.SetInputConnection(guide.GetOutputPort())
    stl.SetFileTypeToBinary()
    stl.SetFileName(os.path.join(folder, "guide.stl"))
    vtp = vtkXMLPolyDataWriter()
    vtp.SetInputConnection(guide.GetOutputPort())
    vtp.SetFileName(os.path.join(folder, "guide.vtp"))
    if stl.Write() != 1 or vtp.Write() != 1:
        print("error: cannot write the guide's files in %r" % folder, file=sys.stderr)
        return 1

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for source, colour in ((bone, (0.93, 0.87, 0.72)), (guide, (0.0, 0.55, 0.6))):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(colour)
        renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    # From the side the guide goes on; z up (the head, in LPS and RAS)
    # unless the guide is put on from above or below.
    camera = renderer.GetActiveCamera()
    bounds = guide.GetOutput().GetBounds()
    centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
    camera.SetFocalPoint(centre)
    camera.SetPosition([centre[k] + 200 * approach[k] for k in range(3)])
    camera.SetViewUp((0, 0, 1) if abs(approach[2]) < 0.9 else (0, 1, 0))
    renderer.ResetCamera(bounds)
    camera.Zoom(0.5)
    save_png(window, os.path.join(folder, "guide.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
