#!/usr/bin/python3
"""CT (or label map) -> bone surface -> a resection guide for two or more plane cuts, from Python.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/resection_guide.py \\
           INPUT OX OY OZ NX NY NZ OX OY OZ NX NY NZ [OX OY OZ NX NY NZ ...] OUT_FOLDER

The cuts' planes, each through (OX, OY, OZ) with normal (NX, NY, NZ), patient
mm as the surface is, in their order along the bone (a segment of bone taken
out between two of them; a chin cut between two body cuts). Each gets a
cutting guide with a slot for the saw blade and its number raised on it
(vtkLKCuttingGuideFilter; told of the other cuts' planes, its number and its
screw holes keep clear of their guides and saws), and vtkLKGuideBarFilter
joins them (guides that overlap merged into one block), each to the
next, by bars in front of the bone into one part, so the slots keep the
distances and angles of the plan. The part is rigid: it goes on along one
direction, which the filter finds and this prints. OUT_FOLDER gets
resection_guide.stl (to print), resection_guide.vtp (the bars' facts in its
field data) and resection_guide.png (the part on the bone, seen from the
direction it goes on along).
"""
import os
import sys

import latticekit
from latticekit.rendering import save_part_on_bone
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPlaneCollection
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def main(argv):
    if len(argv) < 15 or (len(argv) - 3) % 6 != 0:
        print(__doc__)
        return 2
    try:
        numbers = [float(v) for v in argv[2:-1]]
    except ValueError:
        print("error: each plane needs six numbers: OX OY OZ NX NY NZ", file=sys.stderr)
        return 2
    folder = argv[-1]
    planes = len(numbers) // 6
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(argv[1])
    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.SetIsoValue(300)  # HU; label maps are detected and use 0.5

    bar = latticekit.vtkLKGuideBarFilter()
    bar.SetInputConnection(0, bone.GetOutputPort())
    guides = []  # kept alive: a connection does not hold its producer
    for k in range(planes):
        guide = latticekit.vtkLKCuttingGuideFilter()
        guide.SetInputConnection(bone.GetOutputPort())
        guide.SetPlaneOrigin(numbers[6 * k:6 * k + 3])
        guide.SetPlaneNormal(numbers[6 * k + 3:6 * k + 6])
        guide.SetLabel(str(k + 1))  # raised on it: which cut is which
        others = vtkPlaneCollection()
        for j in range(planes):
            if j != k:
                plane = vtkPlane()
                plane.SetOrigin(numbers[6 * j:6 * j + 3])
                plane.SetNormal(numbers[6 * j + 3:6 * j + 6])
                others.AddItem(plane)
        guide.SetOtherCutPlanes(others)
        bar.AddGuideConnection(guide.GetOutputPort())
        guides.append(guide)
    bar.Update()
    if bar.GetOutput().GetNumberOfCells() == 0:
        print("error: no resection guide was made (see the messages above)", file=sys.stderr)
        return 1
    for k, guide in enumerate(guides):
        print("cutting guide %d: slot %.1f mm long, %.0f mm^3" % (k + 1, guide.GetSlotLength(), guide.GetVolume()))
    lengths = " and ".join("%.0f" % bar.GetBarLength(b) for b in range(bar.GetNumberOfBars()))
    one = bar.GetNumberOfBars() == 1
    joins = []
    if bar.GetNumberOfBars() > 0:
        joins.append("%s of %.1f mm, %s mm long and %s%.1f mm clear of the bone between the guides" % (
            "a bar" if one else "%d bars" % bar.GetNumberOfBars(), bar.GetBarDiameter(), lengths,
            "" if one else "at least ", bar.GetBarGap()))
    merged = ["%d and %d" % (k + 1, k + 2) for k in range(planes - 1) if bar.GetMerged(k)]
    if merged:  # guides that overlap: one block with both slots
        joins.append("guides %s merged into one block" % ", ".join(merged))
    print("resection guide: %s; %.0f mm^3 in one part" % ("; ".join(joins), bar.GetVolume()))
    approach = bar.GetApproachUsed()  # away from the bone: the part goes on the other way
    print("put on along (%.3f, %.3f, %.3f): its contact %.1f degrees %s square to that%s" % (
        -approach[0], -approach[1], -approach[2], abs(bar.GetInsertionMargin()),
        "short of" if bar.GetInsertionMargin() >= 0 else "past",
        "" if bar.GetUndercutArea() == 0 else " over %.1f mm^2 (an undercut: trim there if it binds)"
        % bar.GetUndercutArea()))

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

    # From the direction the part goes on along (the front of the bars).
    save_part_on_bone(bone, bar, approach, os.path.join(folder, "resection_guide.png"), zoom=0.8)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
