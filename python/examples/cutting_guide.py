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
from latticekit.rendering import save_part_on_bone
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


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

    # From the side the guide goes on.
    save_part_on_bone(bone, guide, approach, os.path.join(folder, "guide.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
