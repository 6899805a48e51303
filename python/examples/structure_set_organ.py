#!/usr/bin/python3
"""An organ of a radiotherapy structure set -> its surface -> a lattice -> a structure set again.

usage: PYTHONPATH=build/python /usr/bin/python3 python/examples/structure_set_organ.py \\
           INPUT ORGAN [OUT_FOLDER]

INPUT is a DICOM RT structure set (RTSTRUCT) file, or a CT folder exported with the structure
sets drawn on it (a radiotherapy export; or with them in folders beside its own, as a study
exported one series to a folder lies, TCIA's layout). The script lists the organs (ROIs), takes ORGAN by
name, makes its surface, fits a lattice of 1,000 control vertices to it, measures the lattice
surface against the organ's surface (Metro), and writes into OUT_FOLDER (default: the current
folder) the organ's surface (organ.stl, patient LPS mm) and the lattice surface as an RT
structure set (lattice.dcm): on the CT's slices and in its study when the CT lies beside the
structure set (in its folder or in one beside it), else on axial planes 1 mm apart.
"""
import os
import sys

import latticekit


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    source, organ = argv[1], argv[2]
    out = argv[3] if len(argv) > 3 else "."

    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(source)
    reader.Update()
    if reader.GetFileFormat() == "DICOM":
        # A CT folder: the organ lies in a structure set drawn on it.
        sets = [(reader.GetStructureSetFileName(i),
                 [reader.GetStructureSetROIName(i, j) for j in range(reader.GetNumberOfStructureSetROIs(i))])
                for i in range(reader.GetNumberOfStructureSets())]
        holding = [f for f, names in sets if organ.lower() in (n.lower() for n in names)]
        if len(holding) != 1:
            print("error: %d structure sets drawn on this CT have an ROI named '%s': %s"
                  % (len(holding), organ, sets), file=sys.stderr)
            return 1
        reader.SetFileName(holding[0])
        reader.Update()
    if reader.GetNumberOfSegments() == 0:
        print("error: '%s' holds no organs (see the messages above)" % source, file=sys.stderr)
        return 1
    print("organs:", ", ".join("%s (%d)" % (reader.GetSegmentName(i), reader.GetSegmentLabelValue(i))
                               for i in range(reader.GetNumberOfSegments())))

    surface = latticekit.vtkLKBoneSurfaceFilter()
    surface.SetInputConnection(reader.GetOutputPort())
    surface.SetLabelName(organ)

    fit = latticekit.vtkLKLatticeFitFilter()
    fit.SetInputConnection(surface.GetOutputPort())
    fit.SetTargetNumberOfVertices(1000)

    smooth = latticekit.vtkLKLatticeSurfaceFilter()
    smooth.SetInputConnection(fit.GetOutputPort())
    smooth.SetResolution(4)

    metro = latticekit.vtkLKMetroFilter()
    metro.SetInputConnection(surface.GetOutputPort())
    metro.SetTargetConnection(smooth.GetOutputPort())
    metro.Update()
    if metro.GetOutput().GetNumberOfPoints() == 0:
        print("error: the pipeline failed (see the messages above)", file=sys.stderr)
        return 1
    fields = metro.GetOutput().GetFieldData()
    print("organ '%s': %d triangles; lattice: %d control vertices; Metro mean %.4f mm, max %.4f mm"
          % (surface.GetEffectiveSegmentName(), surface.GetOutput().GetNumberOfPolys(),
             fit.GetOutput().GetNumberOfPoints(), fields.GetArray("Hausdorff_Mean").GetValue(0),
             fields.GetArray("Hausdorff_Max").GetValue(0)))

    os.makedirs(out, exist_ok=True)
    from vtkmodules.vtkIOGeometry import vtkSTLWriter
    stl = vtkSTLWriter()
    stl.SetInputConnection(surface.GetOutputPort())
    stl.SetFileName(os.path.join(out, "organ.stl"))
    stl.Write()

    # Back to the hospital: on the CT's slices when the CT lies beside the set.
    writer = latticekit.vtkLKStructureSetWriter()
    writer.AddInputConnection(smooth.GetOutputPort())
    # An ROI name holds 64 characters (a Python str counts them as DICOM does).
    writer.SetROIName(0, surface.GetEffectiveSegmentName()[:54] + " (lattice)")
    if reader.GetReferenceImageFileName():
        writer.SetReferenceFileName(reader.GetReferenceImageFileName())
    writer.SetFileName(os.path.join(out, "lattice.dcm"))
    if writer.Write() != 1:
        print("error: the structure set was not written (see the messages above)", file=sys.stderr)
        return 1
    print("wrote %s and %s: %d contours %s" % (
        stl.GetFileName(), writer.GetFileName(), writer.GetNumberOfContours(),
        "on the CT's slices" if reader.GetReferenceImageFileName() else "on axial planes 1 mm apart"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
