"""Writes tests/data/rtstruct/head_and_neck.dcm: a DICOM RT structure set as a
radiotherapy planning system exports one, with vtkDICOM's Python wrappers.
Its ROIs, in patient (LPS) mm, contoured on the axial planes z = -20 to 20 mm,
2.5 mm apart:
- 1 "BODY": an ellipse of half-axes 40 and 32 mm around the origin;
- 2 "Mandible": a ball of radius 12 mm at (8, -6, 0), inside the body;
- 3 "SpinalCord": a cylinder of radius 4 mm at (0, 22), contoured on every
  other plane only (as a planner may leave the system to fill in);
- 4 "Isocenter": a point (POINT), which encloses nothing.
The CT it references is not there: the reader fills the ROIs on a grid of
their own. Every UID is fixed, so that the file is the same on every run.
Run with /usr/bin/python3 from the repository's root."""
import math
import os

import vtkdicom


def tag(name):
    value = int(getattr(vtkdicom.DC, name))
    return vtkdicom.vtkDICOMTag(value >> 16, value & 0xFFFF)


ROOT = "2.25.212696138407333008201460284379931325065"  # a UUID-derived root (DICOM PS3.5 B.2), fixed
PLANES = [-20.0 + 2.5 * k for k in range(17)]


def ellipse(cx, cy, rx, ry, z, count=64):
    points = []
    for i in range(count):
        a = 2.0 * math.pi * i / count
        points += [cx + rx * math.cos(a), cy + ry * math.sin(a), z]
    return points


def rois():
    body = [ellipse(0.0, 0.0, 40.0, 32.0, z) for z in PLANES]
    mandible = [ellipse(8.0, -6.0, math.sqrt(144.0 - z * z), math.sqrt(144.0 - z * z), z)
                for z in PLANES if z * z < 144.0]
    cord = [ellipse(0.0, 22.0, 4.0, 4.0, z, 24) for z in PLANES[::2]]
    return [(1, "BODY", "EXTERNAL", "CLOSED_PLANAR", body),
            (2, "Mandible", "ORGAN", "CLOSED_PLANAR", mandible),
            (3, "SpinalCord", "ORGAN", "CLOSED_PLANAR", cord),
            (4, "Isocenter", "ISOCENTER", "POINT", [[8.0, -6.0, 0.0]])]


def main():
    meta = vtkdicom.vtkDICOMMetaData()
    for name, value in (("SOPClassUID", "1.2.840.10008.5.1.4.1.1.481.3"),
                        ("SOPInstanceUID", ROOT + ".4"),
                        ("StudyInstanceUID", ROOT + ".1"),
                        ("SeriesInstanceUID", ROOT + ".3"),
                        ("Modality", "RTSTRUCT"),
                        ("PatientID", "latticekit-test"),
                        ("PatientName", "Test^HeadAndNeck"),
                        ("StudyDate", "20261203"),
                        ("StructureSetLabel", "HN"),
                        ("StructureSetDate", "20261203"),
                        ("Manufacturer", "latticekit tests")):
        meta.Set(tag(name), value)
    series = vtkdicom.vtkDICOMItem()
    series.Set(tag("SeriesInstanceUID"), ROOT + ".2")  # the CT, not included
    study = vtkdicom.vtkDICOMItem()
    study.Set(tag("ReferencedSOPClassUID"), "1.2.840.10008.3.1.2.3.1")
    study.Set(tag("ReferencedSOPInstanceUID"), ROOT + ".1")
    study.Set(tag("RTReferencedSeriesSequence"), vtkdicom.vtkDICOMSequence(series))
    frame = vtkdicom.vtkDICOMItem()
    frame.Set(tag("FrameOfReferenceUID"), ROOT + ".5")
    frame.Set(tag("RTReferencedStudySequence"), vtkdicom.vtkDICOMSequence(study))
    meta.Set(tag("ReferencedFrameOfReferenceSequence"), vtkdicom.vtkDICOMSequence(frame))
    listed, contoured, observed = (vtkdicom.vtkDICOMSequence() for _ in range(3))
    for number, name, kind, geometry, contours in rois():
        roi = vtkdicom.vtkDICOMItem()
        roi.Set(tag("ROINumber"), number)
        roi.Set(tag("ReferencedFrameOfReferenceUID"), ROOT + ".5")
        roi.Set(tag("ROIName"), name)
        roi.Set(tag("ROIGenerationAlgorithm"), "MANUAL")
        listed.AddItem(roi)
        items = vtkdicom.vtkDICOMSequence()
        for points in contours:
            contour = vtkdicom.vtkDICOMItem()
            contour.Set(tag("ContourGeometricType"), geometry)
            contour.Set(tag("NumberOfContourPoints"), len(points) // 3)
            contour.Set(tag("ContourData"), "\\".join("%.3f" % v for v in points))
            items.AddItem(contour)
        item = vtkdicom.vtkDICOMItem()
        item.Set(tag("ReferencedROINumber"), number)
        item.Set(tag("ROIDisplayColor"), "255\\0\\0")
        item.Set(tag("ContourSequence"), items)
        contoured.AddItem(item)
        observation = vtkdicom.vtkDICOMItem()
        observation.Set(tag("ObservationNumber"), number)
        observation.Set(tag("ReferencedROINumber"), number)
        observation.Set(tag("RTROIInterpretedType"), kind)
        observed.AddItem(observation)
    meta.Set(tag("StructureSetROISequence"), listed)
    meta.Set(tag("ROIContourSequence"), contoured)
    meta.Set(tag("RTROIObservationsSequence"), observed)
    folder = os.path.join("tests", "data", "rtstruct")
    os.makedirs(folder, exist_ok=True)
    compiler = vtkdicom.vtkDICOMCompiler()
    compiler.SetFileName(os.path.join(folder, "head_and_neck.dcm"))
    compiler.SetMetaData(meta)
    compiler.SetSOPInstanceUID(ROOT + ".4")
    compiler.SetSeriesInstanceUID(ROOT + ".3")
    compiler.SetStudyInstanceUID(ROOT + ".1")
    compiler.SetImplementationClassUID(ROOT + ".6")
    compiler.WriteHeader()
    compiler.Close()
    if compiler.GetErrorCode() != 0:
        raise SystemExit("vtkDICOMCompiler failed")


if __name__ == "__main__":
    main()
