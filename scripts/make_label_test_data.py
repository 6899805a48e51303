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


def write_segmentation(path, layers, segments, data):
    """A 3D Slicer .seg.nrrd of the volume's grid: `layers` values per voxel
    (0: a 3D file), `segments` (colour, ID, label value, layer, name; the
    value and layer None where the file leaves them out), gzip `data`."""
    four = layers > 0
    lines = ["NRRD0004",
             "# Complete NRRD file format specification at:",
             "# http://teem.sourceforge.net/nrrd/format.html",
             "type: unsigned char",
             "dimension: %d" % (4 if four else 3),
             "space: left-posterior-superior",
             "sizes: %s%d %d %d" % ("%d " % layers if four else "", NX, NY, NZ),
             "space directions: %s(1,0,0) (0,1,0) (0,0,2)" % ("none " if four else ""),
             "kinds: %sdomain domain domain" % ("list " if four else ""),
             "encoding: gzip",
             "space origin: (-20,-15,-30)"]
    for n, (colour, ident, value, layer, name) in enumerate(segments):
        lines.append("Segment%d_Color:=%s" % (n, colour))
        lines.append("Segment%d_ID:=%s" % (n, ident))
        if value is not None:
            lines.append("Segment%d_LabelValue:=%d" % (n, value))
        if layer is not None:
            lines.append("Segment%d_Layer:=%d" % (n, layer))
        lines.append("Segment%d_Name:=%s" % (n, name))
    lines.append("Segmentation_MasterRepresentation:=Binary labelmap")
    with open(path, "wb") as f:
        f.write(("\n".join(lines) + "\n\n").encode("ascii"))
        f.write(gzip.compress(data, mtime=0))


CONDYLES = [("0.945 0.839 0.568", "Segment_1", 1, 0, "left condyle"),
            ("0.694 0.478 0.396", "Segment_2", 2, 0, "Right Condyle")]
write_segmentation("tests/data/two_segments.seg.nrrd", 0, CONDYLES, values)


def tumour(i, j, k):
    x, y, z = -20 + i, -15 + j, -30 + 2 * k
    return 1 if (x + 1) ** 2 + y ** 2 + z ** 2 < 36 else 0


layered = bytes(v for k in range(NZ) for j in range(NY) for i in range(NX)
                for v in (label(i, j, k), tumour(i, j, k)))
write_segmentation("tests/data/overlapping_segments.seg.nrrd", 2,
                   [("0.945 0.839 0.568", "Segment_1", 1, 0, "mandible"),
                    ("0.694 0.478 0.396", "Segment_2", 2, 0, "maxilla"),
                    ("0.8 0.2 0.2", "Segment_3", 1, 1, "tumour")], layered)

old = bytes(v for k in range(NZ) for j in range(NY) for i in range(NX)
            for v in (int(label(i, j, k) == 1), int(label(i, j, k) == 2)))
write_segmentation("tests/data/slicer4_segments.seg.nrrd", 2,
                   [(c, i, None, None, n) for c, i, _, _, n in CONDYLES], old)
