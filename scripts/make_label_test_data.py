"""Writes the label-map test data of tests/data, a 40 x 30 x 30 volume of
1 x 1 x 2 mm voxels holding two balls, of labels 1 and 2, as a segmentation
with several segments is stored:
- two_labels.mha: the label map alone (MetaImage, written by VTK);
- two_segments.seg.nrrd: the same voxels as 3D Slicer saves a segmentation,
  with its segments' names ("Segment0_Name:=mandible", ...) in the header;
- overlapping_segments.seg.nrrd: a segmentation whose segments overlap, which
  3D Slicer saves in layers (a 4D NRRD, the layer axis first): layer 0 holds
  the two balls ("mandible" 1, "maxilla" 2), layer 1 a third ball ("tumour",
  label 1 of its layer) that overlaps both;
- slicer4_segments.seg.nrrd: the two balls of two_segments.seg.nrrd as 3D
  Slicer 4.10 and older saved segments, each a 0/1 map in a layer of its own,
  without the LabelValue and Layer keys.
Run with /usr/bin/python3 from the repository's root."""
import gzip

from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkMetaImageWriter

NX, NY, NZ = 40, 30, 30


def label(i, j, k):
    x, y, z = -20 + i, -15 + j, -30 + 2 * k
    if (x + 9) ** 2 + y ** 2 + z ** 2 < 64:
        return 1
    if (x - 9) ** 2 + y ** 2 + z ** 2 < 49:
        return 2
    return 0


values = bytes(label(i, j, k) for k in range(NZ) for j in range(NY) for i in range(NX))

img = vtkImageData()
img.SetDimensions(NX, NY, NZ)
img.SetSpacing(1.0, 1.0, 2.0)
img.SetOrigin(-20, -15, -30)
img.AllocateScalars(VTK_UNSIGNED_CHAR, 1)
scalars = img.GetPointData().GetScalars()
for n, v in enumerate(values):
    scalars.SetValue(n, v)
w = vtkMetaImageWriter()
w.SetInputData(img)
w.SetFileName("tests/data/two_labels.mha")
w.SetCompression(True)
w.Write()

header = """NRRD0004
# Complete NRRD file format specification at:
# http://teem.sourceforge.net/nrrd/format.html
type: unsigned char
dimension: 3
space: left-posterior-superior
sizes: {nx} {ny} {nz}
space directions: (1,0,0) (0,1,0) (0,0,2)
kinds: domain domain domain
encoding: gzip
space origin: (-20,-15,-30)
Segment0_Color:=0.945 0.839 0.568
Segment0_ID:=Segment_1
Segment0_LabelValue:=1
Segment0_Layer:=0
Segment0_Name:=left condyle
Segment1_Color:=0.694 0.478 0.396
Segment1_ID:=Segment_2
Segment1_LabelValue:=2
Segment1_Layer:=0
Segment1_Name:=Right Condyle
Segmentation_MasterRepresentation:=Binary labelmap

""".format(nx=NX, ny=NY, nz=NZ)
with open("tests/data/two_segments.seg.nrrd", "wb") as f:
    f.write(header.encode("ascii"))
    f.write(gzip.compress(values, mtime=0))


def tumour(i, j, k):
    x, y, z = -20 + i, -15 + j, -30 + 2 * k
    return 1 if (x + 1) ** 2 + y ** 2 + z ** 2 < 36 else 0


layered = bytes(v for k in range(NZ) for j in range(NY) for i in range(NX)
                for v in (label(i, j, k), tumour(i, j, k)))
header = """NRRD0004
# Complete NRRD file format specification at:
# http://teem.sourceforge.net/nrrd/format.html
type: unsigned char
dimension: 4
space: left-posterior-superior
sizes: 2 {nx} {ny} {nz}
space directions: none (1,0,0) (0,1,0) (0,0,2)
kinds: list domain domain domain
encoding: gzip
space origin: (-20,-15,-30)
Segment0_Color:=0.945 0.839 0.568
Segment0_ID:=Segment_1
Segment0_LabelValue:=1
Segment0_Layer:=0
Segment0_Name:=mandible
Segment1_Color:=0.694 0.478 0.396
Segment1_ID:=Segment_2
Segment1_LabelValue:=2
Segment1_Layer:=0
Segment1_Name:=maxilla
Segment2_Color:=0.8 0.2 0.2
Segment2_ID:=Segment_3
Segment2_LabelValue:=1
Segment2_Layer:=1
Segment2_Name:=tumour
Segmentation_MasterRepresentation:=Binary labelmap

""".format(nx=NX, ny=NY, nz=NZ)
with open("tests/data/overlapping_segments.seg.nrrd", "wb") as f:
    f.write(header.encode("ascii"))
    f.write(gzip.compress(layered, mtime=0))

old = bytes(v for k in range(NZ) for j in range(NY) for i in range(NX)
            for v in (int(label(i, j, k) == 1), int(label(i, j, k) == 2)))
header = """NRRD0004
# Complete NRRD file format specification at:
# http://teem.sourceforge.net/nrrd/format.html
type: unsigned char
dimension: 4
space: left-posterior-superior
sizes: 2 {nx} {ny} {nz}
space directions: none (1,0,0) (0,1,0) (0,0,2)
kinds: list domain domain domain
encoding: gzip
space origin: (-20,-15,-30)
Segment0_Color:=0.945 0.839 0.568
Segment0_ID:=Segment_1
Segment0_Name:=left condyle
Segment1_Color:=0.694 0.478 0.396
Segment1_ID:=Segment_2
Segment1_Name:=Right Condyle
Segmentation_MasterRepresentation:=Binary labelmap

""".format(nx=NX, ny=NY, nz=NZ)
with open("tests/data/slicer4_segments.seg.nrrd", "wb") as f:
    f.write(header.encode("ascii"))
    f.write(gzip.compress(old, mtime=0))
