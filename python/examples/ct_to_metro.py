#!/usr/bin/python3
"""CT (or label map) -> bone surface -> simplified copy -> Metro error, from Python.

usage: PYTHONPATH=build/python /usr/bin/python3 python/examples/ct_to_metro.py INPUT [OUT.vtp]

latticekit filters and plain VTK filters share one pipeline.
"""
import sys

import latticekit
from vtkmodules.vtkFiltersCore import vtkQuadricDecimation
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

    simplified = vtkQuadricDecimation()
    simplified.SetInputConnection(bone.GetOutputPort())
    simplified.SetTargetReduction(0.9)

    metro = latticekit.vtkLKMetroFilter()
    metro.SetInputConnection(bone.GetOutputPort())
    metro.SetTargetConnection(simplified.GetOutputPort())
    metro.Update()
    if metro.GetOutput().GetNumberOfPoints() == 0:
        print("error: the pipeline failed (see the messages above)", file=sys.stderr)
        return 1

    fields = metro.GetOutput().GetFieldData()
    value = lambda name: fields.GetArray(name).GetValue(0)
    print("surface: %d triangles, simplified: %d triangles"
          % (bone.GetOutput().GetNumberOfPolys(), simplified.GetOutput().GetNumberOfPolys()))
    print("bbox diagonal %.3f mm" % value("BoundingBoxDiagonal"))
    for label, prefix in (("surface -> copy", "AtoB"), ("copy -> surface", "BtoA"),
                          ("symmetric", "Hausdorff")):
        print("%-16s max %.4f (%.3f%%)  mean %.4f (%.4f%%)  RMS %.4f (%.4f%%)" % (
            label, value(prefix + "_Max"), value(prefix + "_MaxPercent"),
            value(prefix + "_Mean"), value(prefix + "_MeanPercent"),
            value(prefix + "_RMS"), value(prefix + "_RMSPercent")))
    if len(argv) > 2:
        writer = vtkXMLPolyDataWriter()
        writer.SetInputConnection(metro.GetOutputPort())
        writer.SetFileName(argv[2])
        writer.Write()
        print("wrote", argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
