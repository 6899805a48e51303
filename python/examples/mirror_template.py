#!/usr/bin/python3
"""CT (or label map) -> bone surface -> its plane of symmetry and mirror image
-> where the bone departs from its mirror (Metro colours), from Python.

usage: PYTHONPATH=build/python /usr/bin/python3 python/examples/mirror_template.py INPUT [OUT_FOLDER]

The mirror image is the template of mirror-image planning: the healthy side,
mirrored onto the side to rebuild. OUT_FOLDER gets mirror.stl (to print and
bend a plate on) and asymmetry.vtp (the bone with each point's distance to
the mirror image, "Distance", for a viewer's colour map).
"""
import os
import sys

import latticekit
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(argv[1])

    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.SetIsoValue(300)  # HU; label maps are detected and use 0.5

    mirror = latticekit.vtkLKSymmetryPlaneFilter()
    mirror.SetInputConnection(bone.GetOutputPort())
    mirror.SetInitialNormal(1, 0, 0)  # the patient's left-right axis (LPS and RAS)

    asymmetry = latticekit.vtkLKMetroFilter()
    asymmetry.SetInputConnection(bone.GetOutputPort())
    asymmetry.SetTargetConnection(mirror.GetOutputPort())
    asymmetry.Update()
    if asymmetry.GetOutput().GetNumberOfPoints() == 0:
        print("error: the pipeline failed (see the messages above)", file=sys.stderr)
        return 1

    origin, normal = mirror.GetPlaneOrigin(), mirror.GetPlaneNormal()
    print("plane of symmetry: through (%.2f, %.2f, %.2f), normal (%.4f, %.4f, %.4f)" % (origin + normal))
    print("bone to its mirror image: mean %.2f mm, largest %.2f mm; the plane was fitted to %.0f %% of the bone"
          % (mirror.GetMeanDistance(), mirror.GetMaximumDistance(), 100.0 * mirror.GetKeptFraction()))
    fields = asymmetry.GetOutput().GetFieldData()
    print("Metro, both ways: mean %.3f mm, max %.3f mm"
          % (fields.GetArray("Hausdorff_Mean").GetValue(0), fields.GetArray("Hausdorff_Max").GetValue(0)))
    if len(argv) > 2:
        os.makedirs(argv[2], exist_ok=True)
        stl = vtkSTLWriter()
        stl.SetInputConnection(mirror.GetOutputPort())
        stl.SetFileTypeToBinary()
        stl.SetFileName(os.path.join(argv[2], "mirror.stl"))
        stl.Write()
        vtp = vtkXMLPolyDataWriter()
        vtp.SetInputConnection(asymmetry.GetOutputPort())
        vtp.SetFileName(os.path.join(argv[2], "asymmetry.vtp"))
        vtp.Write()
        print("wrote", stl.GetFileName(), "and", vtp.GetFileName())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
