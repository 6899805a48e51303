"""Python tests: latticekit through VTK's own wrappers, in pipelines with vtk classes."""
import os
import subprocess
import sys
import tempfile
import unittest

SAMPLE_DATA = os.environ.get("LATTICEKIT_SAMPLE_DATA",
                             os.path.join(os.path.dirname(__file__), "..", "..", "sample_data"))
MANDIBLE = os.path.join(SAMPLE_DATA, "mandible-tcia", "test_oncologist_0522c0017_Mandible.nrrd")
GE = os.path.join(SAMPLE_DATA, "dicom-ct-ge-tilt")
CTHEAD = os.path.join(SAMPLE_DATA, "cthead", "cthead_hu_approx.nii.gz")
TEST_DATA = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data")


class ImportTest(unittest.TestCase):
    def test_every_filter_is_exported(self):
        import latticekit
        for name in ("vtkLKMedicalImageReader", "vtkLKBoneSurfaceFilter",
                     "vtkLKMeshRepairFilter", "vtkLKMetroFilter", "vtkLKLatticeSurfaceFilter",
                     "vtkLKLatticeFitFilter", "vtkLKQuadPairingFilter",
                     "vtkLKHomogenizedLoopFilter", "vtkLKBezierIFSFilter",
                     "vtkLKClosedLineCutFilter", "vtkLKExtractCutPieceFilter",
                     "vtkLKStrokeFeatureLineFilter",
                     "vtkLKWrinklySurfaceFilter", "vtkLKWrinklyNetSource",
                     "vtkLKPatchDeformationFilter", "vtkLKStructureSetWriter",
                     "vtkLKSymmetryPlaneFilter", "vtkLKCuttingGuideFilter",
                     "vtkLKGuideBarFilter"):
            cls = getattr(latticekit, name)
            obj = cls()
            self.assertTrue(obj.IsA("vtkAlgorithm"), name)
            self.assertIn(name, obj.GetClassName())


class DocumentationTest(unittest.TestCase):
    def test_the_package_docstring_runs(self):
        import doctest
        import latticekit
        failures, tried = doctest.testmod(latticekit)
        self.assertGreater(tried, 5)
        self.assertEqual(failures, 0)

    def test_the_readme_example_runs(self):
        # The README's Python block, as a reader would paste it: from the
        # source tree's root, where its sample_data path is.
        root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
        with open(os.path.join(root, "README.md")) as f:
            text = f.read()
        start = text.index("```python\n") + len("```python\n")
        code = text[start:text.index("```", start)]
        self.assertIn("vtkLKMetroFilter", code)
        result = subprocess.run([sys.executable, "-c", code], cwd=root, capture_output=True, text=True,
                                timeout=300, check=False)
        self.assertEqual(result.returncode, 0, result.stderr)
        # It prints the Hausdorff distance (mm) and the mean error (% of the diagonal).
        distance, mean = (float(v) for v in result.stdout.split())
        self.assertGreater(distance, 0.0)
        self.assertGreater(mean, 0.0)
        self.assertLess(mean, 1.0)


    def test_print_names_every_parameter(self):
        # print(filter) is how a Python user sees a filter's settings, as with
        # VTK's own: every parameter the class adds (a Set with a Get) is named.
        import re
        import latticekit
        names = [n for n in dir(latticekit) if n.startswith("vtkLK")]
        self.assertGreaterEqual(len(names), 14)
        for name in names:
            cls = getattr(latticekit, name)
            inherited = set(dir(cls.__bases__[0]))
            params = sorted({m[3:] for m in dir(cls)
                             if m.startswith("Set") and m not in inherited and hasattr(cls, "Get" + m[3:])})
            text = str(cls())
            missing = [p for p in params if not re.search(r"\b" + p + r":", text)]
            self.assertEqual(missing, [], name)


class PipelineTest(unittest.TestCase):
    def test_vtk_sources_and_latticekit_filters_in_one_pipeline(self):
        import latticekit
        from vtkmodules.vtkFiltersCore import vtkQuadricDecimation, vtkTriangleFilter
        from vtkmodules.vtkFiltersSources import vtkSphereSource

        sphere = vtkSphereSource()
        sphere.SetRadius(10.0)
        sphere.SetThetaResolution(64)
        sphere.SetPhiResolution(64)
        repair = latticekit.vtkLKMeshRepairFilter()  # welds the sphere's seam
        repair.SetInputConnection(sphere.GetOutputPort())
        coarse = vtkQuadricDecimation()
        coarse.SetInputConnection(repair.GetOutputPort())
        coarse.SetTargetReduction(0.8)
        triangles = vtkTriangleFilter()
        triangles.SetInputConnection(coarse.GetOutputPort())
        metro = latticekit.vtkLKMetroFilter()
        metro.SetInputConnection(repair.GetOutputPort())
        metro.SetTargetConnection(triangles.GetOutputPort())

        progress = []
        metro.AddObserver("ProgressEvent", lambda caller, event: progress.append(caller.GetProgress()))
        metro.Update()

        out = metro.GetOutput()
        self.assertEqual(out.GetNumberOfPoints(), repair.GetOutput().GetNumberOfPoints())
        hausdorff = out.GetFieldData().GetArray("Hausdorff_Max").GetValue(0)
        self.assertGreater(hausdorff, 0.0)
        self.assertLess(hausdorff, 1.0)  # a coarse copy of a radius-10 sphere
        self.assertAlmostEqual(hausdorff, metro.GetHausdorffDistance(), places=12)
        diag = out.GetFieldData().GetArray("BoundingBoxDiagonal").GetValue(0)
        pct = out.GetFieldData().GetArray("Hausdorff_MaxPercent").GetValue(0)
        self.assertAlmostEqual(pct, 100.0 * hausdorff / diag, places=9)
        self.assertIsNotNone(out.GetPointData().GetArray("Distance"))
        self.assertEqual(progress[-1], 1.0)
        self.assertTrue(all(b >= a for a, b in zip(progress, progress[1:])))

        # Changing a parameter upstream re-executes the pipeline.
        coarse.SetTargetReduction(0.95)
        metro.Update()
        self.assertGreater(metro.GetHausdorffDistance(), hausdorff)

    def test_label_map_to_surface_to_metro(self):
        import latticekit
        from vtkmodules.vtkFiltersCore import vtkQuadricDecimation

        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(MANDIBLE)
        bone = latticekit.vtkLKBoneSurfaceFilter()
        bone.SetInputConnection(reader.GetOutputPort())
        decimate = vtkQuadricDecimation()
        decimate.SetInputConnection(bone.GetOutputPort())
        decimate.SetTargetReduction(0.9)
        metro = latticekit.vtkLKMetroFilter()
        metro.SetInputConnection(bone.GetOutputPort())
        metro.SetTargetConnection(decimate.GetOutputPort())
        metro.Update()
        self.assertTrue(bone.GetTreatedAsLabelMap())
        self.assertEqual(bone.GetEffectiveIsoValue(), 0.5)
        surface = bone.GetOutput()
        self.assertGreater(surface.GetNumberOfPoints(), 9000)
        self.assertEqual(surface.GetFieldData().GetArray("BoundaryEdges").GetValue(0), 0)
        self.assertEqual(surface.GetFieldData().GetArray("Components").GetValue(0), 1)
        mean_pct = metro.GetOutput().GetFieldData().GetArray("Hausdorff_MeanPercent").GetValue(0)
        self.assertGreater(mean_pct, 0.0)
        self.assertLess(mean_pct, 0.1)
        # A label map's smoothing by default: a Gaussian of half a voxel and
        # 20 windowed-sinc iterations, said after the update; the one-voxel
        # surface of before December 2026 on request.
        self.assertEqual(bone.GetImageSmoothing(), -1.0)
        self.assertEqual(bone.GetSmoothingIterations(), -1)
        self.assertEqual(bone.GetEffectiveImageSmoothing(), 0.5)
        self.assertEqual(bone.GetEffectiveSmoothingIterations(), 20)
        self.assertEqual(surface.GetNumberOfPoints(), 12994)
        bone.SetLabelMapImageSmoothing(1.0)
        bone.SetLabelMapSmoothingIterations(0)
        bone.Update()
        self.assertEqual(bone.GetEffectiveImageSmoothing(), 1.0)
        self.assertEqual(bone.GetEffectiveSmoothingIterations(), 0)
        self.assertEqual(bone.GetOutput().GetNumberOfPoints(), 12212)

    def test_a_segment_of_a_segmentation_whose_segments_overlap(self):
        """3D Slicer's layered .seg.nrrd: a component per layer, and a
        segment taken by its name or by a label value only it has."""
        import latticekit

        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(os.path.join(TEST_DATA, "overlapping_segments.seg.nrrd"))
        bone = latticekit.vtkLKBoneSurfaceFilter()
        bone.SetInputConnection(reader.GetOutputPort())
        bone.SetLabelName("tumour")
        bone.Update()
        volume = reader.GetOutput()
        self.assertEqual(volume.GetNumberOfScalarComponents(), 2)
        names = volume.GetFieldData().GetAbstractArray("SegmentNames")
        self.assertEqual([names.GetValue(i) for i in range(names.GetNumberOfValues())],
                         ["mandible", "maxilla", "tumour"])
        layers = volume.GetFieldData().GetArray("SegmentLayers")
        self.assertEqual([layers.GetValue(i) for i in range(3)], [0, 0, 1])
        self.assertEqual(bone.GetEffectiveLabel(), 1)
        self.assertEqual(bone.GetEffectiveSegmentName(), "tumour")
        b = bone.GetOutput().GetBounds()
        self.assertAlmostEqual(0.5 * (b[0] + b[1]), -1.0, delta=1.0)  # the ball at x = -1
        self.assertEqual(bone.GetOutput().GetFieldData().GetArray("BoundaryEdges").GetValue(0), 0)

        bone.SetLabelName(None)
        bone.SetLabel(2)  # only the maxilla has 2
        bone.Update()
        self.assertEqual(bone.GetEffectiveSegmentName(), "maxilla")
        self.assertGreater(bone.GetOutput().GetBounds()[0], 0.0)

    def test_an_organ_of_a_radiotherapy_structure_set(self):
        """A DICOM RT structure set written with vtkDICOM's own Python
        wrappers (a ball contoured on 9 axial slices, and an isocentre
        point) is read as segments; the ball is taken by its ROI name."""
        import math
        import vtkdicom
        import latticekit

        def tag(name):
            value = int(getattr(vtkdicom.DC, name))
            return vtkdicom.vtkDICOMTag(value >> 16, value & 0xFFFF)

        meta = vtkdicom.vtkDICOMMetaData()
        meta.Set(tag("SOPClassUID"), "1.2.840.10008.5.1.4.1.1.481.3")
        meta.Set(tag("Modality"), "RTSTRUCT")
        listed = vtkdicom.vtkDICOMSequence()
        contoured = vtkdicom.vtkDICOMSequence()
        for number, name, kind in ((4, "Mandible", "CLOSED_PLANAR"), (7, "Isocenter", "POINT")):
            roi = vtkdicom.vtkDICOMItem()
            roi.Set(tag("ROINumber"), number)
            roi.Set(tag("ROIName"), name)
            listed.AddItem(roi)
            contours = vtkdicom.vtkDICOMSequence()
            for k in range(-4, 5) if kind == "CLOSED_PLANAR" else (0,):
                z = 2.5 * k
                r = math.sqrt(12.0 ** 2 - z * z)
                count = 48 if kind == "CLOSED_PLANAR" else 1
                points = []
                for i in range(count):
                    a = 2.0 * math.pi * i / count
                    points += [10.0 + r * math.cos(a), -20.0 + r * math.sin(a), 30.0 + z]
                contour = vtkdicom.vtkDICOMItem()
                contour.Set(tag("ContourGeometricType"), kind)
                contour.Set(tag("NumberOfContourPoints"), count)
                contour.Set(tag("ContourData"), "\\".join("%.4f" % v for v in points))
                contours.AddItem(contour)
            item = vtkdicom.vtkDICOMItem()
            item.Set(tag("ReferencedROINumber"), number)
            item.Set(tag("ContourSequence"), contours)
            contoured.AddItem(item)
        meta.Set(tag("StructureSetROISequence"), listed)
        meta.Set(tag("ROIContourSequence"), contoured)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "rtstruct.dcm")
            compiler = vtkdicom.vtkDICOMCompiler()
            compiler.SetFileName(path)
            compiler.SetMetaData(meta)
            compiler.WriteHeader()
            compiler.Close()
            self.assertEqual(compiler.GetErrorCode(), 0)

            reader = latticekit.vtkLKMedicalImageReader()
            reader.SetFileName(path)
            warnings = []
            reader.AddObserver("WarningEvent", lambda caller, event: warnings.append(event))
            bone = latticekit.vtkLKBoneSurfaceFilter()
            bone.SetInputConnection(reader.GetOutputPort())
            bone.SetLabelName("Mandible")
            bone.Update()

            # And back: the surface written as a structure set of its own,
            # read again.
            writer = latticekit.vtkLKStructureSetWriter()
            writer.SetInputConnection(bone.GetOutputPort())
            writer.SetROIName(0, "Kieferh\u00f6hle")  # a Python str: UTF-8 through the wrappers
            writer.AddMarker("Gnathion", 10.0, -20.0, 18.0)  # a landmark: a POINT ROI after the surfaces
            self.assertEqual(writer.GetNumberOfMarkers(), 1)
            writer.SetFileName(os.path.join(tmp, "written.dcm"))
            self.assertEqual(writer.Write(), 1)
            again = latticekit.vtkLKMedicalImageReader()
            again.SetFileName(os.path.join(tmp, "written.dcm"))
            again.AddObserver("WarningEvent", lambda caller, event: None)  # no CT beside it; the marker is a point
            again.Update()
            self.assertEqual([again.GetSegmentName(i) for i in range(again.GetNumberOfSegments())],
                             ["Kieferh\u00f6hle"])
        self.assertGreater(writer.GetNumberOfContours(), 15)
        self.assertEqual(reader.GetFileFormat(), "DICOM RTSTRUCT")
        self.assertEqual(reader.GetReferenceImageFileName(), "")  # no CT to write back onto
        self.assertEqual(len(warnings), 2)  # no CT beside it; the isocentre is a point
        self.assertEqual([(reader.GetSegmentName(i), reader.GetSegmentLabelValue(i), reader.GetSegmentLayer(i))
                          for i in range(reader.GetNumberOfSegments())], [("Mandible", 4, 0)])
        self.assertIsNone(reader.GetSegmentName(1))
        self.assertEqual(bone.GetEffectiveLabel(), 4)
        b = bone.GetOutput().GetBounds()
        for centre, expected in zip((0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])),
                                    (10.0, -20.0, 30.0)):
            self.assertAlmostEqual(centre, expected, delta=0.6)
        self.assertAlmostEqual(b[1] - b[0], 24.0, delta=2.0)
        self.assertEqual(bone.GetOutput().GetFieldData().GetArray("BoundaryEdges").GetValue(0), 0)

    def test_close_at_border_closes_a_scan_that_ends_in_the_bone(self):
        """A scan that ends inside the bone (here the label map's slices cut
        to the lower part of the mandible) gives an open surface there;
        CloseAtBorder closes it, as a crop box is closed."""
        import latticekit
        from vtkmodules.vtkImagingCore import vtkExtractVOI

        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(MANDIBLE)
        reader.Update()
        e = list(reader.GetOutput().GetExtent())
        # The slices that hold the mandible, then the lower half of them.
        scalars = reader.GetOutput().GetPointData().GetScalars()
        nx, ny = e[1] - e[0] + 1, e[3] - e[2] + 1
        slices = [k for k in range(e[4], e[5] + 1)
                  if any(scalars.GetValue((k - e[4]) * nx * ny + i) for i in range(0, nx * ny, 7))]
        voi = vtkExtractVOI()
        voi.SetInputConnection(reader.GetOutputPort())
        voi.SetVOI(e[0], e[1], e[2], e[3], e[4], (slices[0] + slices[-1]) // 2)
        boundary = {}
        for close in (False, True):
            bone = latticekit.vtkLKBoneSurfaceFilter()
            bone.SetInputConnection(voi.GetOutputPort())
            bone.SetCloseAtBorder(close)
            bone.Update()
            self.assertEqual(bone.GetCloseAtBorder(), close)
            fd = bone.GetOutput().GetFieldData()
            self.assertEqual(fd.GetArray("Components").GetValue(0), 1)
            boundary[close] = fd.GetArray("BoundaryEdges").GetValue(0)
        self.assertGreater(boundary[False], 50)
        self.assertEqual(boundary[True], 0)

    def test_lattice_fit_with_features_quads_and_surface(self):
        import latticekit
        from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(MANDIBLE)
        bone = latticekit.vtkLKBoneSurfaceFilter()
        bone.SetInputConnection(reader.GetOutputPort())
        bone.Update()
        mesh = bone.GetOutput()
        # A feature line: three edges of the mesh's first triangle, by point id.
        tri = mesh.GetCell(0)
        ids = [tri.GetPointId(k) for k in range(3)] + [tri.GetPointId(0)]
        points, cell, mesh_ids = vtkPoints(), vtkCellArray(), vtkIdTypeArray()
        mesh_ids.SetName("MeshPointId")
        cell.InsertNextCell(len(ids))
        for i in ids:
            cell.InsertCellPoint(points.InsertNextPoint(mesh.GetPoint(i)))
            mesh_ids.InsertNextValue(i)
        lines = vtkPolyData()
        lines.SetPoints(points)
        lines.SetLines(cell)
        lines.GetPointData().AddArray(mesh_ids)

        fit = latticekit.vtkLKLatticeFitFilter()
        fit.SetInputConnection(bone.GetOutputPort())
        fit.SetFeatureLinesData(lines)
        fit.SetTargetNumberOfVertices(1500)
        fit.LockFeaturesOn()
        fit.QuadPairingOn()
        surface = latticekit.vtkLKLatticeSurfaceFilter()
        surface.SetInputConnection(fit.GetOutputPort())
        surface.SetResolution(4)
        surface.Update()
        lattice = fit.GetOutput()
        fd = lattice.GetFieldData()
        self.assertEqual(lattice.GetNumberOfPoints(), 1500)
        self.assertEqual(fd.GetArray("FeatureEdges").GetValue(0), 3)
        self.assertEqual(lattice.GetNumberOfLines(), 3)
        self.assertGreater(fd.GetArray("Quads").GetValue(0), 0)
        self.assertLess(fd.GetArray("Hausdorff_MeanPercent").GetValue(0), 0.1)
        vmap = fit.GetVertexMapOutput().GetPointData()
        self.assertEqual(vmap.GetArray("LatticeFaceId").GetNumberOfTuples(), mesh.GetNumberOfPoints())
        # The surface of the lattice comes out of the same pipeline.
        self.assertGreater(surface.GetOutput().GetNumberOfPolys(), 10 * lattice.GetNumberOfPolys())

    def test_cut_pieces_fitted_with_their_cut_lines_kept(self):
        """Cut, extract each piece, fit it with its cut line locked: one
        pipeline, the piece's cells in the cut's order every time."""
        import math

        import latticekit
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkPolyData
        from vtkmodules.vtkFiltersSources import vtkSphereSource
        from mesh_checks import open_edges

        sphere = vtkSphereSource()
        sphere.SetThetaResolution(48)
        sphere.SetPhiResolution(48)
        circle = vtkPoints()
        for k in range(41):
            a = 2 * math.pi * k / 40
            circle.InsertNextPoint(0.48 * math.cos(a), 0.48 * math.sin(a), 0.14)
        stroke = vtkPolyData()
        stroke.SetPoints(circle)
        split = latticekit.vtkLKStrokeFeatureLineFilter()
        split.SetInputConnection(sphere.GetOutputPort())
        split.SetStrokeData(stroke)
        split.SetModeToSplit()
        cut = latticekit.vtkLKClosedLineCutFilter()
        cut.SetInputConnection(split.GetOutputPort())
        cut.CappingOn()
        extract = latticekit.vtkLKExtractCutPieceFilter()
        extract.SetInputConnection(cut.GetOutputPort())
        fit = latticekit.vtkLKLatticeFitFilter()
        fit.SetInputConnection(extract.GetOutputPort(0))
        fit.SetFeatureLinesConnection(extract.GetOutputPort(1))
        fit.LockFeaturesOn()
        fit.SetTargetReduction(0.7)
        faces = 0
        for piece in range(2):
            extract.SetPiece(piece)
            fit.Update()
            self.assertEqual(cut.GetNumberOfPieces(), 2)
            lines = extract.GetOutput(1)
            edges = lines.GetFieldData().GetArray("CutLineEdges").GetValue(0)
            self.assertGreater(edges, 20)
            self.assertEqual(lines.GetNumberOfLines(), 1)  # one closed loop
            self.assertEqual(fit.GetOutput().GetFieldData().GetArray("FeatureEdges").GetValue(0), edges)
            # The rim, where the cap meets the sphere (at 74 and 106 degrees),
            # is a crease of the lattice surface, unless a larger angle is asked.
            self.assertEqual(fit.GetOutput().GetFieldData().GetArray("CreaseEdges").GetValue(0), edges)
            # Its surface is one closed mesh, or, with SplitCreases, open
            # along the rim only: each side there has its own points.
            surface = latticekit.vtkLKLatticeSurfaceFilter()
            surface.SetInputConnection(fit.GetOutputPort())
            surface.Update()
            self.assertEqual(open_edges(surface.GetOutput()).GetNumberOfLines(), 0)
            surface.SplitCreasesOn()
            surface.Update()
            self.assertEqual(open_edges(surface.GetOutput()).GetNumberOfLines(), 2 * 8 * edges)
            fit.SetCreaseAngle(120)
            fit.Update()
            self.assertEqual(fit.GetOutput().GetFieldData().GetArray("CreaseEdges").GetValue(0), 0)
            fit.SetCreaseAngle(45)
            # With a tolerance the line keeps only the points its shape needs.
            fit.SetFeatureTolerance(0.005)
            fit.Update()
            fewer = fit.GetOutput().GetFieldData().GetArray("FeatureEdges").GetValue(0)
            self.assertLess(fewer, 0.7 * edges)
            self.assertGreaterEqual(fewer, 4)
            fit.SetFeatureTolerance(0.0)
            fit.Update()
            faces += extract.GetOutput().GetNumberOfPolys()
            # The same piece again, point for point.
            again = latticekit.vtkLKExtractCutPieceFilter()
            again.SetInputConnection(cut.GetOutputPort())
            again.SetPiece(piece)
            again.Update()
            first, second = extract.GetOutput(), again.GetOutput()
            self.assertEqual(first.GetNumberOfPoints(), second.GetNumberOfPoints())
            for i in range(0, first.GetNumberOfPoints(), 37):
                self.assertEqual(first.GetPoint(i), second.GetPoint(i))
        self.assertEqual(faces, cut.GetOutput().GetNumberOfPolys())

    def test_lattice_fit_with_refinement(self):
        import latticekit

        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(MANDIBLE)
        bone = latticekit.vtkLKBoneSurfaceFilter()
        bone.SetInputConnection(reader.GetOutputPort())
        plain = latticekit.vtkLKLatticeFitFilter()
        plain.SetInputConnection(bone.GetOutputPort())
        plain.SetTargetNumberOfVertices(400)
        plain.Update()
        fit = latticekit.vtkLKLatticeFitFilter()
        fit.SetInputConnection(bone.GetOutputPort())
        fit.SetTargetNumberOfVertices(400)
        fit.RefinementOn()
        fit.SetRefinementIterations(4)
        self.assertEqual(fit.GetRefinementInsertions(), -1)  # 1 per 100 vertices
        fit.Update()
        fd, plain_fd = fit.GetOutput().GetFieldData(), plain.GetOutput().GetFieldData()
        self.assertEqual(fit.GetOutput().GetNumberOfPoints(), 400)
        # 4 insertions, kept or (where they do not lower the max) undone.
        tried = fd.GetArray("RefinementInsertions").GetValue(0) + fd.GetArray("RefinementInsertionsRefused").GetValue(0)
        self.assertEqual(tried, 4)
        self.assertLess(fd.GetArray("RefinementFinalRMS").GetValue(0), fd.GetArray("RefinementInitialRMS").GetValue(0))
        self.assertLess(fd.GetArray("Hausdorff_MeanPercent").GetValue(0),
                        0.8 * plain_fd.GetArray("Hausdorff_MeanPercent").GetValue(0))

    def test_lattice_fit_to_an_error_bound(self):
        import latticekit
        from vtkmodules.vtkFiltersSources import vtkSphereSource

        sphere = vtkSphereSource()
        sphere.SetThetaResolution(40)
        sphere.SetPhiResolution(40)
        sphere.SetRadius(10.0)
        fit = latticekit.vtkLKLatticeFitFilter()
        fit.SetInputConnection(sphere.GetOutputPort())
        fit.SetMaximumError(1.0)
        self.assertEqual(fit.GetMaximumErrorCountTolerance(), 0.01)
        fit.SetMaximumErrorCountTolerance(0.05)
        fit.Update()
        lattice = fit.GetOutput()
        fd = lattice.GetFieldData()
        self.assertLessEqual(fd.GetArray("Hausdorff_MaxPercent").GetValue(0), 1.0)
        trials = fd.GetArray("ErrorBoundTrialCountAndError")
        self.assertEqual(trials.GetNumberOfComponents(), 2)
        self.assertEqual(trials.GetNumberOfTuples(), fd.GetArray("ErrorBoundTrials").GetValue(0))
        counts = [trials.GetComponent(i, 0) for i in range(trials.GetNumberOfTuples())]
        errors = [trials.GetComponent(i, 1) for i in range(trials.GetNumberOfTuples())]
        # The lattice's count was measured within the bound; a count at most
        # 5 % below it was measured above it.
        n = lattice.GetNumberOfPoints()
        self.assertIn(n, counts)
        self.assertLessEqual(errors[counts.index(n)], 1.0)
        self.assertTrue(any(e > 1.0 and n - max(1, 0.05 * n) <= c < n for c, e in zip(counts, errors)))

    def test_homogenized_loop_from_python(self):
        import latticekit
        from vtkmodules.vtkCommonCore import vtkDoubleArray
        from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
        from vtkmodules.vtkFiltersSources import vtkPlatonicSolidSource

        solid = vtkPlatonicSolidSource()
        solid.SetSolidTypeToIcosahedron()
        solid.Update()
        plain = latticekit.vtkLKHomogenizedLoopFilter()
        plain.SetInputConnection(solid.GetOutputPort())
        plain.SetNumberOfSubdivisions(2)
        vtk_loop = vtkLoopSubdivisionFilter()
        vtk_loop.SetInputConnection(solid.GetOutputPort())
        vtk_loop.SetNumberOfSubdivisions(2)
        plain.Update()
        vtk_loop.Update()
        self.assertEqual(plain.GetOutput().GetNumberOfPoints(), vtk_loop.GetOutput().GetNumberOfPoints())
        # Vertices keep their ids; VTK's even vertices come first as well.
        for i in range(12):
            a, b = plain.GetOutput().GetPoint(i), vtk_loop.GetOutput().GetPoint(i)
            self.assertAlmostEqual(sum((x - y) ** 2 for x, y in zip(a, b)), 0.0, places=10)
        # A vertex weight pulls the surface towards the vertex.
        mesh = solid.GetOutput()
        w = vtkDoubleArray()
        w.SetName("LoopWeight")
        w.SetNumberOfTuples(mesh.GetNumberOfPoints())
        w.Fill(1.0)
        w.SetValue(0, 4.0)
        mesh.GetPointData().AddArray(w)
        weighted = latticekit.vtkLKHomogenizedLoopFilter()
        weighted.SetInputData(mesh)
        weighted.SetNumberOfSubdivisions(2)
        weighted.Update()
        p0 = mesh.GetPoint(0)
        d = lambda pd: sum((x - y) ** 2 for x, y in zip(pd.GetPoint(0), p0))
        self.assertLess(d(weighted.GetOutput()), d(plain.GetOutput()))

    def test_bezier_ifs_from_python(self):
        import latticekit
        from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkPolyData

        pts = vtkPoints()
        for p in ((0, 0, 0), (1, 2, 0), (3, 2, 1), (4, 0, 0)):
            pts.InsertNextPoint(p)
        control = vtkPolyData()
        control.SetPoints(pts)
        ifs = latticekit.vtkLKBezierIFSFilter()
        ifs.SetInputData(control)
        ifs.SetNumberOfMaps(3)
        ifs.SetDepth(3)
        ifs.Update()
        self.assertEqual(ifs.GetOutput().GetNumberOfPoints(), 28)
        # Every point on the curve: compare with de Casteljau at its parameter.
        t_array = ifs.GetOutput().GetPointData().GetArray("Parameter")
        for i in range(ifs.GetOutput().GetNumberOfPoints()):
            t = t_array.GetValue(i)
            b = [(1 - t) ** 3, 3 * (1 - t) ** 2 * t, 3 * (1 - t) * t ** 2, t ** 3]
            expected = [sum(b[k] * pts.GetPoint(k)[c] for k in range(4)) for c in range(3)]
            for c in range(3):
                self.assertAlmostEqual(ifs.GetOutput().GetPoint(i)[c], expected[c], places=12)
        chaos = latticekit.vtkLKBezierIFSFilter()
        chaos.SetInputData(control)
        chaos.SetAlgorithmToChaosGame()
        chaos.SetNumberOfPoints(5000)
        probabilities = vtkDoubleArray()
        probabilities.InsertNextValue(0.2)
        probabilities.InsertNextValue(0.8)
        chaos.SetProbabilities(probabilities)
        chaos.Update()
        density = chaos.GetOutput().GetPointData().GetArray("HitDensity")
        self.assertEqual(density.GetNumberOfTuples(), 5000)
        low, high = density.GetRange()
        self.assertGreater(high / max(low, 1e-9), 5.0)

    def test_wrinkly_surface_from_python(self):
        import latticekit
        from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints

        net = latticekit.vtkLKWrinklyNetSource()
        net.SetNetTypeToAnnular()
        net.SetSpokes(10)
        net.SetRings(3)
        wrinkly = latticekit.vtkLKWrinklySurfaceFilter()
        wrinkly.SetInputConnection(net.GetOutputPort())
        wrinkly.SetIterations(2)
        wrinkly.Update()
        out = wrinkly.GetOutput()
        shuffled = [out.GetPointData().GetArray("Height").GetValue(i) for i in range(out.GetNumberOfPoints())]
        triangles = out.GetNumberOfPolys()
        self.assertGreater(triangles, 4000)  # 30 patches, 9 x 9 samples each
        low, high = out.GetPointData().GetArray("Height").GetRange()
        self.assertLess(low, 0.0)
        self.assertGreater(high, 0.0)
        # Without the IST (K = 0) the same samples give a different, smooth height field.
        wrinkly.SetIterations(0)
        wrinkly.SetResolution(9)
        wrinkly.Update()
        self.assertEqual(wrinkly.GetOutput().GetNumberOfPolys(), triangles)
        smooth = wrinkly.GetOutput().GetPointData().GetArray("Height")
        moved = sum(1 for i in range(smooth.GetNumberOfTuples()) if abs(smooth.GetValue(i) - shuffled[i]) > 1e-9)
        self.assertGreater(moved, len(shuffled) // 2)
        # A net whose axes fall into one group is refused with the reason.
        messages = []
        odd = latticekit.vtkLKWrinklyNetSource()
        odd.SetNetTypeToPolygon()
        odd.SetSides(3)
        refuse = latticekit.vtkLKWrinklySurfaceFilter()
        refuse.SetInputConnection(odd.GetOutputPort())
        refuse.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: messages.append(event))
        refuse.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda obj, event: None)
        refuse.Update()
        self.assertEqual(refuse.GetOutput().GetNumberOfPoints(), 0)
        self.assertTrue(messages)

    def test_patch_deformation_from_python(self):
        import latticekit
        from vtkmodules.vtkFiltersCore import vtkTriangleFilter
        from vtkmodules.vtkFiltersSources import vtkPlaneSource

        plane = vtkPlaneSource()
        plane.SetResolution(16, 16)
        tri = vtkTriangleFilter()
        tri.SetInputConnection(plane.GetOutputPort())
        deform = latticekit.vtkLKPatchDeformationFilter()
        deform.SetInputConnection(tri.GetOutputPort())
        deform.AddFunctionalDeformation(0.0, 0.0, 0.0, 0.3, 20.0, 0.4)
        deform.Update()
        out = deform.GetOutput()
        self.assertAlmostEqual(out.GetBounds()[5], 0.3, places=12)  # the peak is k
        self.assertGreater(out.GetNumberOfPolys(), 512)  # refined around the bump
        self.assertEqual(deform.GetNumberOfDeformations(), 1)
        # A drag from Python: the last deformation replaced, k now 0.1.
        deform.RemoveLastDeformation()
        deform.AddFunctionalDeformation(0.0, 0.0, 0.0, 0.1, 20.0, 0.4)
        deform.Update()
        self.assertAlmostEqual(deform.GetOutput().GetBounds()[5], 0.1, places=12)
        # Two bumps, the first taken back alone: the second stands.
        deform.AddFunctionalDeformation(0.25, 0.25, 0.0, 0.2, 20.0, 0.1)
        deform.RemoveDeformation(0)
        self.assertEqual(deform.GetNumberOfDeformations(), 1)
        deform.Update()
        self.assertAlmostEqual(deform.GetOutput().GetBounds()[5], 0.2, places=12)
        deform.RemoveAllDeformations()
        deform.Update()
        self.assertEqual(deform.GetOutput().GetNumberOfPolys(), 512)
        # A flat patch dented: nothing crosses, and the field data says so.
        self.assertTrue(deform.GetCheckCrossings())
        deform.AddFunctionalDeformation(0.0, 0.0, 0.0, -0.1, 20.0, 0.4)
        deform.Update()
        self.assertEqual(deform.GetOutput().GetFieldData().GetArray("SelfCrossings").GetValue(0), 0)
        deform.CheckCrossingsOff()
        deform.Update()
        self.assertIsNone(deform.GetOutput().GetFieldData().GetArray("SelfCrossings"))

    def test_screen_stroke_with_a_camera(self):
        # Pixels plus the camera that showed the mesh: picked on the visible side.
        import latticekit
        from vtkmodules.vtkFiltersSources import vtkSphereSource
        from vtkmodules.vtkRenderingCore import vtkCamera
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkPolyData
        ball = vtkSphereSource()
        ball.SetThetaResolution(64)
        ball.SetPhiResolution(48)
        camera = vtkCamera()
        camera.SetPosition(0, 0, 5)
        camera.SetFocalPoint(0, 0, 0)
        pixels = vtkPoints()
        for x in range(150, 251, 10):  # a horizontal drag across the middle of 400 x 400
            pixels.InsertNextPoint(x, 200, 0)
        stroke = vtkPolyData()
        stroke.SetPoints(pixels)
        f = latticekit.vtkLKStrokeFeatureLineFilter()
        f.SetInputConnection(ball.GetOutputPort())
        f.SetStrokeData(stroke)
        f.SetCamera(camera)
        f.SetViewportSize(400, 400)
        f.SetModeToSplit()
        f.Update()
        picked = f.GetPickedStroke()
        self.assertEqual(picked.GetNumberOfPoints(), 11)
        for i in range(picked.GetNumberOfPoints()):
            self.assertGreater(picked.GetPoint(i)[2], 0.0)
        self.assertGreater(f.GetFeatureLineOutput().GetNumberOfPoints(), 11)

    def test_strokes_chain_and_a_split_carries_the_earlier_lines(self):
        # A closed split ring, then an open split stroke across it on the first
        # filter's output (with its line cells): the second cuts edges of the
        # ring, and the ring is carried through them, in output 0 and by
        # CarryLine, so that it still cuts the sphere in two.
        import math
        import latticekit
        from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkPolyData
        from vtkmodules.vtkFiltersSources import vtkSphereSource
        ball = vtkSphereSource()
        ball.SetRadius(1.0)
        ball.SetThetaResolution(48)
        ball.SetPhiResolution(32)

        def stroke(points):
            pts = vtkPoints()
            for p in points:
                pts.InsertNextPoint(p)
            pd = vtkPolyData()
            pd.SetPoints(pts)
            return pd

        ring = [(0.98 * math.cos(a), 0.98 * math.sin(a), 0.2)
                for a in (2 * math.pi * k / 60 for k in range(61))]
        across = [(math.sqrt(1 - z * z) * math.cos(0.31), math.sqrt(1 - z * z) * math.sin(0.31), z)
                  for z in (0.6 - 0.09 * k for k in range(11))]
        first = latticekit.vtkLKStrokeFeatureLineFilter()
        first.SetInputConnection(ball.GetOutputPort())
        first.SetStrokeData(stroke(ring))
        first.SetModeToSplit()
        second = latticekit.vtkLKStrokeFeatureLineFilter()
        second.SetInputConnection(first.GetOutputPort())
        second.SetStrokeData(stroke(across))
        second.SetModeToSplit()
        errors = []
        second.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
        second.Update()
        self.assertEqual(errors, [])
        ring_lines = first.GetOutput().GetNumberOfLines()
        out = second.GetOutput()
        # Output 0: the first filter's line cells, then the new feature edges.
        self.assertEqual(out.GetNumberOfLines(),
                         ring_lines + second.GetFeatureLineOutput().GetNumberOfPoints() - 1)
        self.assertGreater(out.GetNumberOfPoints(), first.GetOutput().GetNumberOfPoints())

        # An id that is not a whole number is refused, as by every other line
        # input (it was read as the point below it).
        from vtkmodules.vtkCommonCore import vtkDoubleArray
        halfway = vtkPolyData()
        halfway.DeepCopy(first.GetFeatureLineOutput())
        ids = vtkDoubleArray()
        ids.DeepCopy(halfway.GetPointData().GetArray("MeshPointId"))
        ids.SetName("MeshPointId")
        ids.SetValue(3, ids.GetValue(3) + 0.5)
        halfway.GetPointData().AddArray(ids)
        carried = vtkPolyData()
        self.assertEqual(second.CarryLine(halfway, carried), 0)
        self.assertEqual(len(errors), 1)
        errors.clear()

        carried = vtkPolyData()
        self.assertEqual(second.CarryLine(first.GetFeatureLineOutput(), carried), 1)
        self.assertGreater(carried.GetNumberOfPoints(), first.GetFeatureLineOutput().GetNumberOfPoints())
        self.assertEqual(carried.GetFieldData().GetArray("Closed").GetValue(0), 1)

        cut = latticekit.vtkLKClosedLineCutFilter()
        cut.SetInputData(out)
        cut.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
        cut.SetLinesData(first.GetFeatureLineOutput())  # stale: its cut edges are gone
        cut.Update()
        self.assertEqual(len(errors), 1)
        self.assertEqual(cut.GetNumberOfPieces(), 0)
        cut.SetLinesData(carried)
        cut.Update()
        self.assertEqual(len(errors), 1)
        self.assertEqual(cut.GetNumberOfPieces(), 2)

    def test_a_saw_cut_through_hollow_bone_goes_through_the_marrow_cavity(self):
        # The main job's mandible (the bundled CT head at 300 HU, the plan's
        # box padded with air, the component at the chin) is hollow half-way
        # along its left body: the marrow cavity gives an inner surface joined
        # to the outside. A closed line drawn around the outside there (the
        # plane's outer section, split into the mesh) does not separate it
        # alone; through the inner walls the cut takes the cavity's section
        # too, and each piece is closed by one annular cap.
        import latticekit
        from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataObject, vtkPlane, vtkPolyData
        from vtkmodules.vtkFiltersCore import vtkCutter, vtkPolyDataConnectivityFilter, vtkStripper, vtkThreshold
        from mesh_checks import open_edges
        from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
        from vtkmodules.vtkImagingCore import vtkExtractVOI, vtkImageConstantPad
        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(CTHEAD)
        voi = vtkExtractVOI()
        voi.SetInputConnection(reader.GetOutputPort())
        voi.SetVOI(0, 255, 0, 255, 83, 112)  # z from 166 mm (2 mm slices) to the last slice
        pad = vtkImageConstantPad()
        pad.SetInputConnection(voi.GetOutputPort())
        pad.SetOutputWholeExtent(-1, 256, -1, 256, 82, 113)
        pad.SetConstant(-1024)
        bone = latticekit.vtkLKBoneSurfaceFilter()
        bone.SetInputConnection(pad.GetOutputPort())
        bone.SetIsoValue(300)
        bone.SetSmoothingIterations(10)
        bone.SetExtractionModeToSeededComponent()
        bone.SetSeedPoint(113, 36, 170)
        bone.Update()
        mandible = bone.GetOutput()
        self.assertGreater(mandible.GetNumberOfPoints(), 10000)

        # The stroke: the plane's section nearest to the plan's point, every
        # third point (about 1 mm apart).
        plane = vtkPlane()
        plane.SetOrigin(83, 72.25, 185)
        plane.SetNormal(-0.55, 0.83, 0)
        section = vtkCutter()
        section.SetInputData(mandible)
        section.SetCutFunction(plane)
        nearest = vtkPolyDataConnectivityFilter()
        nearest.SetInputConnection(section.GetOutputPort())
        nearest.SetExtractionModeToClosestPointRegion()
        nearest.SetClosestPoint(83, 72.25, 195)
        strip = vtkStripper()
        strip.SetInputConnection(nearest.GetOutputPort())
        strip.JoinContiguousSegmentsOn()
        strip.Update()
        loop = strip.GetOutput()
        ids = loop.GetCell(0).GetPointIds()
        stroke_points = vtkPoints()
        for i in range(0, ids.GetNumberOfIds(), 3):
            stroke_points.InsertNextPoint(loop.GetPoint(ids.GetId(i)))
        stroke_points.InsertNextPoint(loop.GetPoint(ids.GetId(0)))
        stroke = vtkPolyData()
        stroke.SetPoints(stroke_points)
        line = latticekit.vtkLKStrokeFeatureLineFilter()
        line.SetInputData(mandible)
        line.SetStrokeData(stroke)
        line.SetModeToSplit()
        line.Update()
        self.assertEqual(line.GetFeatureLineOutput().GetFieldData().GetArray("Closed").GetValue(0), 1)
        faces = vtkPolyData()
        faces.ShallowCopy(line.GetOutput())
        faces.SetLines(vtkCellArray())

        cut = latticekit.vtkLKClosedLineCutFilter()
        cut.SetInputData(faces)
        cut.SetLinesData(line.GetFeatureLineOutput())
        cut.CappingOn()
        errors = []
        cut.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
        cut.AddObserver(vtkCommand.WarningEvent, lambda caller, event: None)
        cut.CutInnerWallsOff()
        cut.Update()
        self.assertEqual(cut.GetNumberOfPieces(), 0)
        self.assertEqual(len(errors), 1)  # refused: the line does not separate the hollow bone

        cut.CutInnerWallsOn()
        cut.Update()
        self.assertEqual(len(errors), 1)
        self.assertEqual(cut.GetNumberOfPieces(), 2)
        self.assertGreaterEqual(cut.GetNumberOfInnerWallLines(), 1)
        out = cut.GetOutput()
        self.assertEqual(out.GetFieldData().GetArray("InnerWallLines").GetValue(0), cut.GetNumberOfInnerWallLines())
        crossings = out.GetFieldData().GetArray("CapCrossings")
        depth = out.GetFieldData().GetArray("CapCrossingDepth")
        # The annulus goes through nothing (two pairs of triangles beside the
        # outer line touch it, 1.5e-6 mm deep: below the millionth of the
        # size that counts as touching).
        self.assertEqual([crossings.GetValue(p) for p in range(2)], [0, 0])
        self.assertEqual([depth.GetValue(p) for p in range(2)], [0, 0])

        def cells(name, value):
            keep = vtkThreshold()
            keep.SetInputData(out)
            keep.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, name)
            keep.SetLowerThreshold(value - 0.5)
            keep.SetUpperThreshold(value + 0.5)
            surface = vtkGeometryFilter()
            surface.SetInputConnection(keep.GetOutputPort())
            surface.Update()
            return surface.GetOutput()

        for p in range(2):
            self.assertEqual(open_edges(cells("RegionId", p)).GetNumberOfCells(), 0, "piece %d is not closed" % p)
        # The caps are annuli, bounded by the outer line and the cavity's.
        loops = vtkPolyDataConnectivityFilter()
        loops.SetInputData(open_edges(cells("Cap", 1), non_manifold=False))
        loops.SetExtractionModeToAllRegions()
        loops.Update()
        # vtkFeatureEdges merges the two caps' coinciding borders: the outer
        # line and the cavity's (a disc cap would have one).
        self.assertEqual(loops.GetNumberOfExtractedRegions(), 2)

    def test_a_cutting_guide_for_a_saw_cut_of_the_mandible(self):
        # The chin cut in the mid-sagittal plane: the guide goes on the front
        # of the jaw (-y in LPS) without being told, closed and outward
        # facing, ready for STL.
        import latticekit
        from vtkmodules.vtkFiltersCore import vtkFeatureEdges, vtkMassProperties
        from vtkmodules.vtkIOGeometry import vtkSTLWriter

        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(MANDIBLE)
        bone = latticekit.vtkLKBoneSurfaceFilter()
        bone.SetInputConnection(reader.GetOutputPort())
        guide = latticekit.vtkLKCuttingGuideFilter()
        guide.SetInputConnection(bone.GetOutputPort())
        guide.SetPlaneOrigin(0.0728, 276.64, -982.1)
        guide.SetPlaneNormal(1, 0, 0)
        guide.SetSlotWidth(1.0)
        guide.SetLabel("1")  # raised on its outer face
        guide.Update()
        out = guide.GetOutput()
        self.assertGreater(out.GetNumberOfCells(), 1000)
        self.assertTrue(guide.GetLabelPlaced())
        self.assertEqual(out.GetFieldData().GetAbstractArray("GuideLabel").GetValue(0), "1")
        edges = vtkFeatureEdges()
        edges.SetInputData(out)
        edges.BoundaryEdgesOn()
        edges.NonManifoldEdgesOn()
        edges.FeatureEdgesOff()
        edges.ManifoldEdgesOff()
        edges.Update()
        self.assertEqual(edges.GetOutput().GetNumberOfCells(), 0)
        mass = vtkMassProperties()
        mass.SetInputData(out)
        mass.Update()
        self.assertAlmostEqual(mass.GetVolume(), guide.GetVolume(), delta=1e-6 * guide.GetVolume())
        self.assertGreater(guide.GetVolume(), 500.0)
        self.assertLess(guide.GetApproachUsed()[1], -0.9)
        fields = out.GetFieldData()
        self.assertAlmostEqual(fields.GetArray("GuideSlotLength").GetValue(0), guide.GetSlotLength(), places=12)
        self.assertGreater(guide.GetSlotLength(), 15.0)
        self.assertEqual(fields.GetAbstractArray("SPACE").GetValue(0), "LPS")  # as the bone says
        with tempfile.TemporaryDirectory() as tmp:
            writer = vtkSTLWriter()
            writer.SetInputData(out)
            writer.SetFileName(os.path.join(tmp, "guide.stl"))
            self.assertEqual(writer.Write(), 1)
        # A plane beside the bone: a VTK error and an empty guide.
        guide.SetPlaneOrigin(500, 276.64, -982.1)
        errors = []
        guide.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
        guide.Update()
        self.assertEqual(guide.GetOutput().GetNumberOfCells(), 0)
        self.assertEqual(len(errors), 1)

    def test_a_resection_guide_joins_the_guides_of_two_cuts(self):
        # A segment of the anterior mandible between cuts through the left
        # and the right body: the two guides joined by a bar in front of the
        # chin, one closed part to print, its screw holes open from above.
        import latticekit
        from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance, vtkPolyDataConnectivityFilter
        from mesh_checks import open_edges

        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(MANDIBLE)
        bone = latticekit.vtkLKBoneSurfaceFilter()
        bone.SetInputConnection(reader.GetOutputPort())
        guides = []
        for x, tilt in ((-30, -0.3), (30, 0.3)):
            guide = latticekit.vtkLKCuttingGuideFilter()
            guide.SetInputConnection(bone.GetOutputPort())
            guide.SetPlaneOrigin(x, 276.64, -982.1)
            guide.SetPlaneNormal(1, tilt, 0)
            guide.SetLabel(str(len(guides) + 1))
            guide.Update()
            self.assertTrue(guide.GetLabelPlaced())
            guides.append(guide)
        bar = latticekit.vtkLKGuideBarFilter()
        bar.SetInputConnection(0, bone.GetOutputPort())
        for guide in guides:
            bar.AddGuideConnection(guide.GetOutputPort())
        bar.Update()
        out = bar.GetOutput()
        self.assertGreater(out.GetNumberOfCells(), 1000)
        self.assertEqual(open_edges(out).GetNumberOfCells(), 0)
        parts = vtkPolyDataConnectivityFilter()
        parts.SetInputData(out)
        parts.SetExtractionModeToAllRegions()
        parts.Update()
        self.assertEqual(parts.GetNumberOfExtractedRegions(), 1)
        self.assertGreater(bar.GetVolume(), sum(g.GetVolume() for g in guides))
        self.assertGreater(bar.GetBarLength(), 40.0)
        self.assertLess(bar.GetBarLength(), 90.0)
        self.assertAlmostEqual(bar.GetBarDiameter(), 4.0)  # the walls' thickness
        self.assertGreater(bar.GetBarGap(), 1.97)
        fields = out.GetFieldData()
        self.assertAlmostEqual(fields.GetArray("GuideBarLength").GetValue(0), bar.GetBarLength(), places=9)
        self.assertEqual(fields.GetAbstractArray("SPACE").GetValue(0), "LPS")
        # In front of the chin (-y in LPS), and nowhere inside the bone.
        bounds = out.GetBounds()
        chin = bone.GetOutput().GetBounds()
        self.assertLess(bounds[2], chin[2] - 2.0)
        inside = vtkImplicitPolyDataDistance()
        inside.SetInput(bone.GetOutput())
        deepest = min(inside.EvaluateFunction(out.GetPoint(i)) for i in range(0, out.GetNumberOfPoints(), 7))
        self.assertGreater(deepest, -1e-3)
        # One guide: a VTK error and an empty output.
        single = latticekit.vtkLKGuideBarFilter()
        single.SetInputConnection(0, bone.GetOutputPort())
        single.AddGuideConnection(guides[0].GetOutputPort())
        errors = []
        single.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
        single.Update()
        self.assertEqual(single.GetOutput().GetNumberOfCells(), 0)
        self.assertEqual(len(errors), 1)
        # A chin cut between the two, given in its place along the bone: one
        # part with two bars, each read back by its number.
        chin = latticekit.vtkLKCuttingGuideFilter()
        chin.SetInputConnection(bone.GetOutputPort())
        chin.SetPlaneOrigin(0, 270.03, -988)
        chin.SetPlaneNormal(1, 0, 0)
        three = latticekit.vtkLKGuideBarFilter()
        three.SetInputConnection(0, bone.GetOutputPort())
        for guide in (guides[0], chin, guides[1]):
            three.AddGuideConnection(guide.GetOutputPort())
        three.Update()
        self.assertEqual(three.GetNumberOfBars(), 2)
        self.assertEqual(open_edges(three.GetOutput()).GetNumberOfCells(), 0)
        lengths = [three.GetBarLength(b) for b in range(2)]
        self.assertTrue(all(10.0 < length < 40.0 for length in lengths), lengths)
        self.assertAlmostEqual(three.GetBarLength(), sum(lengths), places=9)
        self.assertEqual(three.GetOutput().GetFieldData().GetArray("GuideBarGap").GetNumberOfTuples(), 2)
        self.assertGreater(three.GetVolume(), bar.GetVolume())
        # Put on from the front (-y in LPS), every contact facing that way.
        self.assertLess(three.GetApproachUsed()[1], -0.9)
        self.assertGreater(three.GetInsertionMargin(), 0.0)
        self.assertLess(three.GetInsertionMargin(), 45.0)
        self.assertEqual(three.GetNumberOfMerges(), 0)
        # Guides 1 and 3 (the two body cuts) lie far apart: they do not
        # cross, and a pair that did would be listed in GuideCrossings.
        self.assertEqual(three.GetNumberOfCrossings(), 0)
        self.assertFalse(three.GetCrossed(0, 2))
        crossings = three.GetOutput().GetFieldData().GetArray("GuideCrossings")
        self.assertEqual((crossings.GetNumberOfComponents(), crossings.GetNumberOfTuples()), (2, 0))
        # A saw line 9 mm from the right body's: the two guides overlap and
        # are merged into one block, no bar, both slots open through it.
        near = latticekit.vtkLKCuttingGuideFilter()
        near.SetInputConnection(bone.GetOutputPort())
        near.SetPlaneOrigin(-21, 273.5, -984)
        near.SetPlaneNormal(1, -0.25, 0)
        block = latticekit.vtkLKGuideBarFilter()
        block.SetInputConnection(0, bone.GetOutputPort())
        for guide in (guides[0], near):
            block.AddGuideConnection(guide.GetOutputPort())
        block.Update()
        self.assertEqual(block.GetNumberOfMerges(), 1)
        self.assertTrue(block.GetMerged(0))
        self.assertEqual(block.GetNumberOfBars(), 0)
        self.assertEqual(open_edges(block.GetOutput()).GetNumberOfCells(), 0)
        self.assertEqual(block.GetOutput().GetFieldData().GetArray("GuideMerged").GetValue(0), 1.0)
        self.assertLess(block.GetVolume(), guides[0].GetVolume() + near.GetVolume())
        self.assertGreater(block.GetVolume(), max(guides[0].GetVolume(), near.GetVolume()))
        # Made alone, guide 1's label lies partly under the near guide's
        # wall (warned of). Told of each other's plane, each guide keeps its
        # label (and screws) clear of the other's: the pipeline makes both
        # anew.
        self.assertEqual(block.GetNumberOfLabelsCovered(), 1)
        self.assertEqual(block.GetNumberOfScrewHolesInSawPaths(), 0)
        from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPlaneCollection
        for guide, other in ((guides[0], near), (near, guides[0])):
            plane = vtkPlane()
            plane.SetOrigin(other.GetPlaneOrigin())
            plane.SetNormal(other.GetPlaneNormal())
            planes = vtkPlaneCollection()
            planes.AddItem(plane)
            guide.SetOtherCutPlanes(planes)
        near.SetLabel("4")
        block.Update()
        self.assertTrue(block.GetMerged(0))
        self.assertEqual(block.GetNumberOfLabelsCovered(), 0)
        self.assertTrue(guides[0].GetLabelPlaced() and near.GetLabelPlaced())
        self.assertEqual(open_edges(block.GetOutput()).GetNumberOfCells(), 0)

    def test_nrrd_reads_after_import_vtk(self):
        # Importing all of vtk loads vtkIOMPIImage, whose factory override of
        # vtkNrrdReader reads nothing; latticekit's reader must not be fooled.
        import vtk  # noqa: F401
        import latticekit
        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(MANDIBLE)
        reader.Update()
        self.assertEqual(reader.GetOutput().GetDimensions(), (512, 512, 156))

    def test_dicom_geometry_from_python(self):
        import latticekit
        reader = latticekit.vtkLKMedicalImageReader()
        reader.SetFileName(GE)
        reader.Update()
        self.assertEqual(reader.GetFileFormat(), "DICOM")
        self.assertAlmostEqual(reader.GetGantryTilt(), 18.5, delta=0.05)
        matrix = reader.GetPatientMatrix()
        self.assertAlmostEqual(matrix.Determinant(), 1.0, places=9)


class LatticeSurfaceTest(unittest.TestCase):
    def test_octahedron_lattice_from_python(self):
        import latticekit
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
        from mesh_checks import open_edges

        points = vtkPoints()
        for p in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)):
            points.InsertNextPoint(p)
        faces = vtkCellArray()
        for f in ((0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)):
            faces.InsertNextCell(3, f)
        lattice = vtkPolyData()
        lattice.SetPoints(points)
        lattice.SetPolys(faces)

        surface = latticekit.vtkLKLatticeSurfaceFilter()
        surface.SetInputData(lattice)
        surface.SetResolution(6)
        surface.Update()
        self.assertEqual(surface.GetNumberOfPatches(), 24)
        out = surface.GetOutput()
        self.assertEqual(out.GetFieldData().GetArray("DisplayPolygons").GetValue(0), out.GetNumberOfPolys())
        self.assertEqual(open_edges(out).GetNumberOfLines(), 0)

        position, normal = [0.0] * 3, [0.0] * 3
        self.assertTrue(surface.EvaluatePatch(0, 0.5, 0.5, position, normal))
        radius = sum(x * x for x in position) ** 0.5
        self.assertGreater(radius, 0.5)
        self.assertLess(radius, 0.7)
        self.assertGreater(sum(p * n for p, n in zip(position, normal)), 0.0)  # outward


class ErrorTest(unittest.TestCase):
    def test_errors_reach_python_observers(self):
        import latticekit
        from vtkmodules.vtkCommonDataModel import vtkPolyData
        metro = latticekit.vtkLKMetroFilter()
        messages = []
        metro.AddObserver("ErrorEvent", lambda caller, event: messages.append(event))
        metro.SetInputData(vtkPolyData())
        metro.SetTargetData(vtkPolyData())
        metro.Update()
        self.assertEqual(len(messages), 1)
        self.assertEqual(metro.GetOutput().GetNumberOfPoints(), 0)

    def test_missing_file(self):
        import latticekit
        reader = latticekit.vtkLKMedicalImageReader()
        errors = []
        reader.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
        reader.SetFileName("/nonexistent/volume.nii.gz")
        reader.Update()
        self.assertEqual(len(errors), 1)


class AbortTest(unittest.TestCase):
    def test_every_filter_stops_when_asked(self):
        """VTK's way to stop a long run: a progress observer sets AbortExecute.
        Every filter then stops at its next check with empty outputs and the
        warning "Aborted."; after Modified() the next Update runs in full.
        (Loop subdivision, the repair, quad pairing, the cut, the stroke and
        the IFS ran to the end and gave their whole output; the lattice surface
        and the bone surface stopped without a word.)"""
        import math

        import latticekit
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.util.vtkConstants import VTK_STRING
        from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkPolyData
        from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkTriangleFilter
        from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource

        sphere = vtkSphereSource()
        sphere.SetThetaResolution(24)
        sphere.SetPhiResolution(24)
        sphere.Update()
        ball = sphere.GetOutput()
        circle = vtkPoints()
        for k in range(41):
            a = 2 * 3.14159265358979 * k / 40
            circle.InsertNextPoint(0.48 * math.cos(a), 0.48 * math.sin(a), 0.14)
        stroke = vtkPolyData()
        stroke.SetPoints(circle)
        control = vtkPolyData()
        control_points = vtkPoints()
        for p in ((0, 0, 0), (1, 2, 0), (3, 2, 1), (4, 0, 0)):
            control_points.InsertNextPoint(p)
        control.SetPoints(control_points)
        net = latticekit.vtkLKWrinklyNetSource()  # kept alive: a connection does not hold its producer
        plane = vtkPlaneSource()
        plane.SetResolution(8, 8)
        flat = vtkTriangleFilter()
        flat.SetInputConnection(plane.GetOutputPort())

        def bone():
            reader = latticekit.vtkLKMedicalImageReader()
            reader.SetFileName(MANDIBLE)
            f = latticekit.vtkLKBoneSurfaceFilter()
            f.SetInputConnection(reader.GetOutputPort())
            return f

        def split():
            f = latticekit.vtkLKStrokeFeatureLineFilter()
            f.SetInputData(ball)
            f.SetStrokeData(stroke)
            f.SetModeToSplit()
            return f

        def cut():
            line = split()  # its output carries the closed line as line cells
            f = latticekit.vtkLKClosedLineCutFilter()
            f.SetInputConnection(line.GetOutputPort())
            f.CappingOn()
            return f

        def extract():
            pieces = cut()  # held by the connection once made, not before
            f = latticekit.vtkLKExtractCutPieceFilter()
            f.SetInputConnection(pieces.GetOutputPort())
            return f

        def made(cls, **settings):
            def make():
                f = cls()
                for name, value in settings.items():
                    getattr(f, "Set" + name)(value)
                return f
            return make

        box = vtkCubeSource()
        box.SetXLength(100)
        box.SetYLength(20)
        box.SetZLength(30)
        box_faces = vtkTriangleFilter()
        box_faces.SetInputConnection(box.GetOutputPort())
        box_triangles = vtkCleanPolyData()  # the cube's faces share their corners
        box_triangles.SetInputConnection(box_faces.GetOutputPort())
        box_triangles.Update()
        box_guides = []
        for x in (-30, 30):
            g = latticekit.vtkLKCuttingGuideFilter()
            g.SetInputConnection(box_triangles.GetOutputPort())
            g.SetPlaneOrigin(x, 0, 0)
            g.SetApproach(0, -1, 0)
            g.Update()
            box_guides.append(g.GetOutput())

        def guide_bar():
            f = latticekit.vtkLKGuideBarFilter()
            f.SetBoneData(box_triangles.GetOutput())
            for g in box_guides:
                f.AddGuideData(g)
            return f

        cases = {
            "bone surface": bone,
            "mesh repair": made(latticekit.vtkLKMeshRepairFilter, InputData=ball),
            "Metro": made(latticekit.vtkLKMetroFilter, InputData=ball, TargetData=ball),
            "lattice fit": made(latticekit.vtkLKLatticeFitFilter, InputData=ball, TargetNumberOfVertices=100),
            "lattice surface": made(latticekit.vtkLKLatticeSurfaceFilter, InputData=ball),
            "quad pairing": made(latticekit.vtkLKQuadPairingFilter, InputData=ball),
            "homogenized Loop": made(latticekit.vtkLKHomogenizedLoopFilter, InputData=ball, NumberOfSubdivisions=2),
            "stroke (split)": split,
            "closed-line cut": cut,
            "extract a cut piece": extract,
            "Bezier IFS": made(latticekit.vtkLKBezierIFSFilter, InputData=control),
            "wrinkly surface": made(latticekit.vtkLKWrinklySurfaceFilter, InputConnection=net.GetOutputPort()),
            "patch deformation": made(latticekit.vtkLKPatchDeformationFilter, InputConnection=flat.GetOutputPort()),
            "cutting guide": made(latticekit.vtkLKCuttingGuideFilter, InputData=ball, Reach=0.2, SlotWidth=0.1,
                                  Bridge=0.1, Thickness=0.1, ScrewHoleDiameter=0),
            "guide bar": guide_bar,
        }
        for name, make in cases.items():
            f = make()
            warnings = []

            @calldata_type(VTK_STRING)
            def warned(caller, event, text):
                warnings.append(text)

            f.AddObserver(vtkCommand.WarningEvent, warned)
            stop = [True]
            f.AddObserver(vtkCommand.ProgressEvent, lambda caller, event: caller.SetAbortExecute(1) if stop[0] else None)
            f.Update()
            outputs = [f.GetOutputDataObject(port) for port in range(f.GetNumberOfOutputPorts())]
            for port, out in enumerate(outputs):
                self.assertEqual(out.GetNumberOfPoints(), 0, "%s: output %d after the stop" % (name, port))
            self.assertTrue(any("Aborted." in w for w in warnings), "%s: %s" % (name, warnings))
            stop[0] = False
            f.Modified()
            f.Update()
            self.assertGreater(f.GetOutputDataObject(0).GetNumberOfPoints(), 0, name + ": the run after the stop")


class ExampleTest(unittest.TestCase):
    def test_example_script_runs(self):
        example = os.path.join(os.path.dirname(__file__), "..", "examples", "ct_to_metro.py")
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "mandible_error.vtp")
            result = subprocess.run([sys.executable, example, MANDIBLE, out],
                                    capture_output=True, text=True, check=False)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("symmetric", result.stdout)
            self.assertTrue(os.path.getsize(out) > 1000)


if __name__ == "__main__":
    unittest.main()
