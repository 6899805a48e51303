"""Writes tests/data/two_labels.mha: a 40 x 30 x 30 label map (1 x 1 x 2 mm
voxels) holding two balls, of labels 1 and 2, as a segmentation with several
segments is stored. Run with /usr/bin/python3 from the repository's root."""
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR
from vtkmodules.vtkIOImage import vtkMetaImageWriter
import sys
img = vtkImageData(); img.SetDimensions(40, 30, 30); img.SetSpacing(1.0, 1.0, 2.0); img.SetOrigin(-20, -15, -30)
img.AllocateScalars(VTK_UNSIGNED_CHAR, 1)
a = img.GetPointData().GetScalars()
for k in range(30):
    for j in range(30):
        for i in range(40):
            x, y, z = -20 + i, -15 + j, -30 + 2 * k
            v = 0
            if (x + 9) ** 2 + y ** 2 + z ** 2 < 64: v = 1
            if (x - 9) ** 2 + y ** 2 + z ** 2 < 49: v = 2
            a.SetValue((k * 30 + j) * 40 + i, v)
w = vtkMetaImageWriter(); w.SetInputData(img); w.SetFileName(sys.argv[1] if len(sys.argv) > 1 else "tests/data/two_labels.mha"); w.SetCompression(True); w.Write()
