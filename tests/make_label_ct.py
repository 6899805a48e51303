#!/usr/bin/python3
"""Writes a label map as a DICOM CT series, for tests that need a DICOM CT of a
bone two cutting guides can sit on (the bundled DICOM series have none).

usage: make_label_ct.py LABELMAP FOLDER

Every labelled voxel becomes 1500 HU (bone), every other -1000 HU (air); the
volume is cropped to the labelled voxels with 25 mm round them and keeps the
label map's patient coordinates, so a plan drawn on the label map replays on
the CT (at --iso 300, the surface lies where the label map's 0.5 level does).
"""
import os
import sys

import latticekit
import vtkdicom
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkImagingCore import vtkExtractVOI, vtkImageChangeInformation, vtkImageShiftScale, vtkImageThreshold


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(argv[1])
    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.Update()
    if bone.GetOutput().GetNumberOfPoints() == 0:
        print("error: no labelled voxels in %r" % argv[1], file=sys.stderr)
        return 1
    image = reader.GetOutput()
    to_data = vtkMatrix4x4()
    vtkMatrix4x4.Invert(reader.GetPatientMatrix(), to_data)
    # The surface's bounds (patient mm) as voxel indices, 25 mm wider: room
    # for what a plan adds round the bone (guides, a bar in front of it).
    b = bone.GetOutput().GetBounds()
    origin, spacing, extent = image.GetOrigin(), image.GetSpacing(), image.GetExtent()
    low, high = [float("inf")] * 3, [-float("inf")] * 3
    for i in range(8):
        corner = to_data.MultiplyPoint((b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + ((i >> 2) & 1)], 1.0))
        for k in range(3):
            index = (corner[k] - origin[k]) / spacing[k]
            low[k], high[k] = min(low[k], index), max(high[k], index)
    voi = []
    for k in range(3):
        margin = int(25.0 / spacing[k]) + 1
        voi += [max(extent[2 * k], int(low[k]) - margin), min(extent[2 * k + 1], int(high[k]) + margin)]
    crop = vtkExtractVOI()
    crop.SetInputData(image)
    crop.SetVOI(voi)
    # Extent from 0, the origin moved to the first voxel kept: the same
    # data coordinates for every voxel, as the patient matrix needs.
    restart = vtkImageChangeInformation()
    restart.SetInputConnection(crop.GetOutputPort())
    restart.SetOutputExtentStart(0, 0, 0)
    restart.SetOutputOrigin([origin[k] + voi[2 * k] * spacing[k] for k in range(3)])
    labelled = vtkImageThreshold()
    labelled.SetInputConnection(restart.GetOutputPort())
    labelled.ThresholdByUpper(1)  # label values are whole numbers
    labelled.SetInValue(1)
    labelled.SetOutValue(0)
    labelled.ReplaceInOn()
    labelled.ReplaceOutOn()
    labelled.SetOutputScalarTypeToShort()
    hu = vtkImageShiftScale()
    hu.SetInputConnection(labelled.GetOutputPort())
    hu.SetScale(2500)
    hu.SetShift(-0.4)  # (v - 0.4) * 2500: 0 -> -1000, 1 -> 1500
    hu.SetOutputScalarTypeToShort()
    hu.Update()
    os.makedirs(argv[2], exist_ok=True)
    writer = vtkdicom.vtkDICOMWriter()
    writer.SetInputConnection(hu.GetOutputPort())
    writer.SetGenerator(vtkdicom.vtkDICOMCTGenerator())
    writer.SetPatientMatrix(reader.GetPatientMatrix())
    writer.SetMemoryRowOrderToFileNative()  # rows as they are: the matrix maps them
    writer.SetFilePrefix(argv[2])
    writer.SetFilePattern("%s/ct_%03d.dcm")
    writer.Write()
    dims = hu.GetOutput().GetDimensions()
    print("wrote %d slices of %d x %d into %s" % (dims[2], dims[0], dims[1], argv[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
