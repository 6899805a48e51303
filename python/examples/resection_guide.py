#!/usr/bin/python3
"""CT (or label map) -> bone surface -> a resection guide for two plane cuts, from Python.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/resection_guide.py \\
           INPUT OX OY OZ NX NY NZ OX OY OZ NX NY NZ OUT_FOLDER

Two cuts' planes, each through (OX, OY, OZ) with normal (NX, NY, NZ), patient
mm as the surface is (a segment of bone taken out between them). Each gets a
cutting guide with a slot for the saw blade and its number, 1 or 2, raised on
it (vtkLKCuttingGuideFilter), and
vtkLKGuideBarFilter joins the two by a bar in front of the bone into one
part, so the two slots keep the distance and angle of the plan. OUT_FOLDER
gets resection_guide.stl (to print), resection_guide.vtp (the bar's facts in
its field data) and resection_guide.png (the part on the bone, from the
front of the bar).
"""
import os
import sys

import latticekit
from latticekit.rendering import save_part_on_bone
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def main(argv):
    if len(argv) < 15:
        print(__doc__)
        return 2
    try:
        numbers = [float(v) for v in argv[2:14]]
    except ValueError:
        print("error: each plane needs six numbers: OX OY OZ NX NY NZ", file=sys.stderr)
        return 2
    folder = argv[14]
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(argv[1])
    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.SetIsoValue(300)  # HU; label maps are detected and use 0.5

    bar = latticekit.vtkLKGuideBarFilter()
    bar.SetInputConnection(0, bone.GetOutputPort())
    guides = []  # kept alive: a connection does not hold its producer
    for k in range(2):
        guide = latticekit.vtkLKCuttingGuideFilter()
        guide.SetInputConnection(bone.GetOutputPort())
        guide.SetPlaneOrigin(numbers[6 * k:6 * k + 3])
        guide.SetPlaneNormal(numbers[6 * k + 3:6 * k + 6])
        guide.SetLabel(str(k + 1))  # raised on it: which cut is which
        bar.AddGuideConnection(guide.GetOutputPort())
        guides.append(guide)
    bar.Update()
    if bar.GetOutput().GetNumberOfCells() == 0:
        print("error: no resection guide was made (see the messages above)", file=sys.stderr)
        return 1
    for k, guide in enumerate(guides):
        print("cutting guide %d: slot %.1f mm long, %.0f mm^3" % (k + 1, guide.GetSlotLength(), guide.GetVolume()))
    print("resection guide: a bar of %.1f mm, %.0f mm long and %.1f mm clear of the bone between the guides; "
          "%.0f mm^3 in one part" % (bar.GetBarDiameter(), bar.GetBarLength(), bar.GetBarGap(), bar.GetVolume()))

    os.makedirs(folder, exist_ok=True)
    stl = vtkSTLWriter()
    stl.SetInputConnection(bar.GetOutputPort())
    stl.SetFileTypeToBinary()
    stl.SetFileName(os.path.join(folder, "resection_guide.stl"))
    vtp = vtkXMLPolyDataWriter()
    vtp.SetInputConnection(bar.GetOutputPort())
    vtp.SetFileName(os.path.join(folder, "resection_guide.vtp"))
    if stl.Write() != 1 or vtp.Write() != 1:
        print("error: cannot write the guide's files in %r" % folder, file=sys.stderr)
        return 1

    # From the guides' mean approach (the front of the bar).
    approach = [sum(g.GetApproachUsed()[k] for g in guides) for k in range(3)]
    save_part_on_bone(bone, bar, approach, os.path.join(folder, "resection_guide.png"), zoom=0.8)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
