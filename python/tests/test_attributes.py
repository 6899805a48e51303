"""What the filters carry from their input, as VTK's own filters do.

A researcher's arrays (a cortical thickness per point, a region label per
face, Metro's error colours) and the file's coordinate tag (field data
"SPACE") must come through a latticekit filter the way they come through
vtkCleanPolyData, vtkLoopSubdivisionFilter or vtkClipPolyData: point data at
the points it belongs to (interpolated at new points), cell data on the faces
cut from a cell, field data passed on. Normals are left out where the filter
changes the geometry or the orientation, so that a mapper never shades with
stale ones.
"""
import math
import unittest

import latticekit
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkIdList, vtkIntArray, vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkElevationFilter, vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource


def tagged_sphere(theta=24, phi=24):
    """A closed unit-diameter sphere with point normals, point data "Elevation"
    (z + 0.5, linear, so exact at any point of a flat subdivision), cell data
    "Label" (the cell's id times 10) and field data SPACE = RAS."""
    source = vtkSphereSource()
    source.SetThetaResolution(theta)
    source.SetPhiResolution(phi)
    clean = vtkCleanPolyData()
    clean.SetInputConnection(source.GetOutputPort())
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(clean.GetOutputPort())
    elevation.SetLowPoint(0, 0, -0.5)
    elevation.SetHighPoint(0, 0, 0.5)
    elevation.SetScalarRange(0, 1)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(elevation.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    sphere = vtkPolyData()
    sphere.DeepCopy(normals.GetOutput())
    label = vtkIntArray()
    label.SetName("Label")
    for c in range(sphere.GetNumberOfCells()):
        label.InsertNextValue(10 * c)
    sphere.GetCellData().AddArray(label)
    space = vtkStringArray()
    space.SetName("SPACE")
    space.InsertNextValue("RAS")
    sphere.GetFieldData().AddArray(space)
    return sphere


def space_of(mesh):
    tag = mesh.GetFieldData().GetAbstractArray("SPACE")
    return tag.GetValue(0) if tag is not None else None


def point_ids(mesh, cell):
    ids = vtkIdList()
    mesh.GetCellPoints(cell, ids)
    return [ids.GetId(k) for k in range(ids.GetNumberOfIds())]


def inside(a, b, c, x, tolerance=1e-9):
    """Whether x lies in the triangle (a, b, c): in its plane and inside its edges."""
    u, v, w = ([q[k] - a[k] for k in range(3)] for q in (b, c, x))
    dot = lambda p, q: sum(p[k] * q[k] for k in range(3))  # noqa: E731
    d00, d01, d11, d20, d21 = dot(u, u), dot(u, v), dot(v, v), dot(w, u), dot(w, v)
    den = d00 * d11 - d01 * d01
    s = (d11 * d20 - d01 * d21) / den
    r = (d00 * d21 - d01 * d20) / den
    off_plane = [w[k] - s * u[k] - r * v[k] for k in range(3)]
    return s > -tolerance and r > -tolerance and s + r < 1 + tolerance and dot(off_plane, off_plane) < 1e-12


def stroke_on(mesh, points, mode):
    """Output 0 of the stroke filter: `points` (world) drawn on `mesh` in `mode` ("Split", ...)."""
    stroke = vtkPoints()
    for p in points:
        stroke.InsertNextPoint(p)
    stroke_data = vtkPolyData()
    stroke_data.SetPoints(stroke)
    f = latticekit.vtkLKStrokeFeatureLineFilter()
    f.SetInputData(mesh)
    f.SetStrokeData(stroke_data)
    getattr(f, "SetModeTo" + mode)()
    f.Update()
    return f.GetOutput()


class AttributeTest(unittest.TestCase):
    def assertElevationFollowsPoints(self, mesh, base=None):
        """Each point's Elevation is its height z + 0.5 (z of the base
        position where the points were moved)."""
        elevation = mesh.GetPointData().GetArray("Elevation")
        self.assertIsNotNone(elevation)
        for p in range(mesh.GetNumberOfPoints()):
            z = mesh.GetPoint(p)[2] - (base.GetTuple3(p)[2] if base is not None else 0.0)
            self.assertAlmostEqual(elevation.GetValue(p), z + 0.5, delta=1e-6, msg="point %d" % p)

    def test_repair_carries_point_and_cell_data_through_merged_points(self):
        # A triangle soup: each face has its own three copies of the sphere's
        # points, with the point data of the point it copies and its face's label.
        sphere = tagged_sphere()
        points = vtkPoints()
        points.SetDataTypeToDouble()
        faces = vtkCellArray()
        elevation = vtkFloatArray()
        elevation.SetName("Elevation")
        label = vtkIntArray()
        label.SetName("Label")
        source_elevation = sphere.GetPointData().GetArray("Elevation")
        for c in range(sphere.GetNumberOfCells()):
            ids = point_ids(sphere, c)
            faces.InsertNextCell(3)
            for p in ids:
                faces.InsertCellPoint(points.InsertNextPoint(sphere.GetPoint(p)))
                elevation.InsertNextValue(source_elevation.GetValue(p))
            label.InsertNextValue(10 * c)
        soup = vtkPolyData()
        soup.SetPoints(points)
        soup.SetPolys(faces)
        soup.GetPointData().AddArray(elevation)
        soup.GetCellData().AddArray(label)
        soup.GetFieldData().AddArray(sphere.GetFieldData().GetAbstractArray("SPACE"))

        repair = latticekit.vtkLKMeshRepairFilter()
        repair.SetInputData(soup)
        repair.Update()
        out = repair.GetOutput()
        self.assertEqual(out.GetNumberOfPoints(), sphere.GetNumberOfPoints())
        self.assertEqual(out.GetNumberOfCells(), sphere.GetNumberOfCells())
        self.assertEqual(out.GetFieldData().GetArray("MergedPoints").GetValue(0),
                         soup.GetNumberOfPoints() - sphere.GetNumberOfPoints())
        self.assertEqual(space_of(out), "RAS")
        self.assertElevationFollowsPoints(out)
        # Each face keeps the label of the soup face with its three corners.
        corners = {}
        for c in range(sphere.GetNumberOfCells()):
            corners[tuple(sorted(sphere.GetPoint(p) for p in point_ids(sphere, c)))] = 10 * c
        out_label = out.GetCellData().GetArray("Label")
        self.assertIsNotNone(out_label)
        for c in range(out.GetNumberOfCells()):
            key = tuple(sorted(out.GetPoint(p) for p in point_ids(out, c)))
            self.assertEqual(out_label.GetValue(c), corners[key])

    def test_repair_labels_the_faces_it_makes_from_the_input_under_them(self):
        # A zero-area cap: E lies on the edge AB, and the triangle (B, E, A)
        # joins the fan above E to the triangle (A, F, B) below. The repair
        # flips AB into EF, making two faces that are not in the input; they
        # lie in (A, F, B) and take its label.
        points = vtkPoints()
        for p in ((0, 0, 0), (2, 0, 0), (1, 0, 0), (1, -1, 0), (1, 1, 0)):  # A, B, E, F, G
            points.InsertNextPoint(p)
        faces = vtkCellArray()
        for t in ((0, 2, 4), (2, 1, 4), (1, 2, 0), (0, 3, 1)):
            faces.InsertNextCell(3, t)
        mesh = vtkPolyData()
        mesh.SetPoints(points)
        mesh.SetPolys(faces)
        label = vtkIntArray()
        label.SetName("Label")
        for value in (0, 10, 20, 30):
            label.InsertNextValue(value)
        mesh.GetCellData().AddArray(label)
        repair = latticekit.vtkLKMeshRepairFilter()
        repair.SetInputData(mesh)
        repair.Update()
        out = repair.GetOutput()
        self.assertEqual(out.GetNumberOfCells(), 4)
        labels = {}
        for c in range(out.GetNumberOfCells()):
            corners = frozenset(tuple(out.GetPoint(p)[:2]) for p in point_ids(out, c))
            labels[corners] = out.GetCellData().GetArray("Label").GetValue(c)
        self.assertEqual(labels[frozenset({(0, 0), (1, 0), (1, 1)})], 0)  # kept faces keep theirs
        self.assertEqual(labels[frozenset({(1, 0), (2, 0), (1, 1)})], 10)
        self.assertEqual(labels[frozenset({(1, -1), (2, 0), (1, 0)})], 30)  # made by the flip
        self.assertEqual(labels[frozenset({(1, 0), (0, 0), (1, -1)})], 30)

    def test_repair_leaves_out_normals_it_may_turn_over(self):
        # The sphere turned inside out: the repair orients it outward, so the
        # input's normals would point in; they are not carried.
        from vtkmodules.vtkFiltersCore import vtkReverseSense
        sphere = tagged_sphere()
        reverse = vtkReverseSense()
        reverse.SetInputData(sphere)
        reverse.ReverseNormalsOff()
        reverse.Update()
        repair = latticekit.vtkLKMeshRepairFilter()
        repair.SetInputConnection(reverse.GetOutputPort())
        repair.Update()
        out = repair.GetOutput()
        self.assertIsNone(out.GetPointData().GetNormals())
        self.assertIsNone(out.GetPointData().GetArray("Normals"))
        self.assertElevationFollowsPoints(out)
        self.assertEqual(space_of(out), "RAS")

    def test_deformation_interpolates_point_data_at_new_midpoints(self):
        sphere = tagged_sphere()
        deform = latticekit.vtkLKPatchDeformationFilter()
        deform.SetInputData(sphere)
        deform.AddFunctionalDeformation(0, 0, 0.5, 0.1, 20, 0.3)  # a bump at the north pole
        deform.Update()
        out = deform.GetOutput()
        self.assertGreater(out.GetNumberOfPoints(), 2 * sphere.GetNumberOfPoints())  # refined
        self.assertEqual(space_of(out), "RAS")
        self.assertIsNone(out.GetPointData().GetArray("Normals"))
        # Elevation is linear: exact at every base position, input point or midpoint.
        self.assertElevationFollowsPoints(out, base=out.GetPointData().GetArray("Displacement"))
        # Every output triangle lies in the input triangle whose label it carries:
        # its base centre is inside that triangle.
        displacement = out.GetPointData().GetArray("Displacement")
        label = out.GetCellData().GetArray("Label")
        self.assertIsNotNone(label)
        for c in range(out.GetNumberOfCells()):
            centre = [0.0, 0.0, 0.0]
            for p in point_ids(out, c):
                x, d = out.GetPoint(p), displacement.GetTuple3(p)
                centre = [centre[k] + (x[k] - d[k]) / 3 for k in range(3)]
            origin = label.GetValue(c) // 10
            a, b, t = (sphere.GetPoint(p) for p in point_ids(sphere, origin))
            self.assertTrue(inside(a, b, t, centre), "triangle %d, label %d" % (c, origin))

    def test_cut_carries_point_and_cell_data_to_both_pieces(self):
        # The sphere cut at its equator (a ring of its own points), capped.
        sphere = tagged_sphere(theta=24, phi=25)  # an odd count has an equator ring
        ring = [p for p in range(sphere.GetNumberOfPoints()) if abs(sphere.GetPoint(p)[2]) < 1e-9]
        self.assertGreater(len(ring), 20)
        ring.sort(key=lambda p: math.atan2(sphere.GetPoint(p)[1], sphere.GetPoint(p)[0]))
        line_points = vtkPoints()
        line = vtkCellArray()
        line.InsertNextCell(len(ring) + 1)
        for p in ring:
            line.InsertCellPoint(line_points.InsertNextPoint(sphere.GetPoint(p)))
        line.InsertCellPoint(0)
        lines = vtkPolyData()
        lines.SetPoints(line_points)
        lines.SetLines(line)
        name = vtkStringArray()  # not numeric: VTK's NullData leaves it alone
        name.SetName("Name")
        for p in range(sphere.GetNumberOfPoints()):
            name.InsertNextValue("p%d" % p)
        sphere.GetPointData().AddArray(name)
        cut = latticekit.vtkLKClosedLineCutFilter()
        cut.SetInputData(sphere)
        cut.SetLinesData(lines)
        cut.CappingOn()
        cut.Update()
        out = cut.GetOutput()
        self.assertEqual(out.GetFieldData().GetArray("Pieces").GetValue(0), 2)
        self.assertEqual(space_of(out), "RAS")
        self.assertIsNone(out.GetPointData().GetArray("Normals"))
        origin_point = out.GetPointData().GetArray("InputPointId")
        origin_cell = out.GetCellData().GetArray("InputCellId")
        elevation = out.GetPointData().GetArray("Elevation")
        label = out.GetCellData().GetArray("Label")
        source_elevation = sphere.GetPointData().GetArray("Elevation")
        caps = 0
        for p in range(out.GetNumberOfPoints()):
            q = origin_point.GetValue(p)
            self.assertEqual(elevation.GetValue(p), source_elevation.GetValue(q) if q >= 0 else 0.0)
        names = out.GetPointData().GetAbstractArray("Name")
        self.assertEqual(names.GetNumberOfValues(), out.GetNumberOfPoints())  # one per point, caps too
        for p in range(out.GetNumberOfPoints()):
            q = origin_point.GetValue(p)
            self.assertEqual(names.GetValue(p), "p%d" % q if q >= 0 else "")
        for c in range(out.GetNumberOfCells()):
            q = origin_cell.GetValue(c)
            self.assertEqual(label.GetValue(c), 10 * q if q >= 0 else 0)
            caps += q < 0
        self.assertGreater(caps, 0)
        # The equator's points are in both pieces, each copy with its Elevation.
        self.assertEqual(sum(1 for p in range(out.GetNumberOfPoints()) if origin_point.GetValue(p) == ring[0]), 2)

    def test_a_split_stroke_interpolates_point_data_at_its_new_points(self):
        sphere = tagged_sphere()
        r = math.sqrt(0.25 - 0.01)  # along the sphere at z = 0.1, a quarter turn
        out = stroke_on(sphere, [(r * math.cos(1.5 * k / 15), r * math.sin(1.5 * k / 15), 0.1) for k in range(16)],
                        "Split")
        self.assertGreater(out.GetNumberOfPoints(), sphere.GetNumberOfPoints())  # points were added
        self.assertEqual(space_of(out), "RAS")
        self.assertIsNone(out.GetPointData().GetArray("Normals"))  # the split's faces have other normals
        # Elevation is linear, and a new point lies on an input triangle: exact.
        self.assertElevationFollowsPoints(out)
        # Each triangle lies in the input triangle whose label it carries; the
        # line cells (first) have the null label.
        label = out.GetCellData().GetArray("Label")
        lines = out.GetNumberOfLines()
        self.assertGreater(lines, 0)
        for c in range(lines):
            self.assertEqual(label.GetValue(c), 0)
        for c in range(lines, out.GetNumberOfCells()):
            corners = [out.GetPoint(p) for p in point_ids(out, c)]
            centre = [sum(q[k] for q in corners) / 3 for k in range(3)]
            a, b, t = (sphere.GetPoint(p) for p in point_ids(sphere, label.GetValue(c) // 10))
            self.assertTrue(inside(a, b, t, centre), "triangle %d, label %d" % (c, label.GetValue(c)))

    def test_nearest_edges_keep_the_normals_of_a_surface_they_leave_alone(self):
        sphere = tagged_sphere()
        out = stroke_on(sphere, [(0.49 * math.cos(k / 7), 0.49 * math.sin(k / 7), 0.0) for k in range(8)],
                        "NearestEdges")
        self.assertEqual(out.GetNumberOfPoints(), sphere.GetNumberOfPoints())
        normals = out.GetPointData().GetNormals()
        self.assertIsNotNone(normals)
        self.assertEqual(normals.GetTuple3(5), sphere.GetPointData().GetNormals().GetTuple3(5))
        label = out.GetCellData().GetArray("Label")
        lines = out.GetNumberOfLines()
        for c in range(lines, out.GetNumberOfCells()):
            self.assertEqual(label.GetValue(c), 10 * (c - lines))  # the same triangles, in order

    def test_field_data_passes_through_every_mesh_filter(self):
        sphere = tagged_sphere(12, 12)
        loop = latticekit.vtkLKHomogenizedLoopFilter()
        loop.SetInputData(sphere)
        fit = latticekit.vtkLKLatticeFitFilter()
        fit.SetInputData(sphere)
        fit.SetTargetNumberOfVertices(40)
        pairing = latticekit.vtkLKQuadPairingFilter()
        pairing.SetInputData(sphere)
        surface = latticekit.vtkLKLatticeSurfaceFilter()
        surface.SetInputData(sphere)
        for f in (loop, fit, pairing, surface):
            f.Update()
            for port in range(f.GetNumberOfOutputPorts()):
                self.assertEqual(space_of(f.GetOutputDataObject(port)), "RAS", "%s port %d" % (f.GetClassName(), port))
        # The fit's own field data is there beside it.
        self.assertEqual(fit.GetOutput().GetFieldData().GetArray("ControlVertices").GetValue(0), 40)

    def test_the_mirror_image_carries_every_points_and_faces_data(self):
        # Each point of the mirror image is the reflection of its own: it keeps
        # its data, each face its label, the normals are reflected (still
        # outward), and the file's tag stays.
        sphere = tagged_sphere(16, 16)
        mirror = latticekit.vtkLKSymmetryPlaneFilter()
        mirror.SetInputData(sphere)
        mirror.Update()
        out = mirror.GetOutput()
        n = mirror.GetPlaneNormal()
        self.assertAlmostEqual(n[0], 1.0, places=6)  # a sphere: the plane it started from
        self.assertEqual(out.GetNumberOfPoints(), sphere.GetNumberOfPoints())
        self.assertEqual(space_of(out), "RAS")
        elevation_in = sphere.GetPointData().GetArray("Elevation")
        elevation_out = out.GetPointData().GetArray("Elevation")
        label_out = out.GetCellData().GetArray("Label")
        normals_in = sphere.GetPointData().GetNormals()
        normals_out = out.GetPointData().GetNormals()
        for i in range(0, out.GetNumberOfPoints(), 7):
            self.assertEqual(elevation_out.GetValue(i), elevation_in.GetValue(i))
            a, b = normals_in.GetTuple3(i), normals_out.GetTuple3(i)
            along = sum(a[k] * n[k] for k in range(3))
            for k in range(3):
                self.assertAlmostEqual(b[k], a[k] - 2 * along * n[k], places=5)
        for c in range(out.GetNumberOfCells()):
            self.assertEqual(label_out.GetValue(c), 10 * c)
            self.assertEqual(point_ids(out, c), list(reversed(point_ids(sphere, c))))
        self.assertEqual(out.GetFieldData().GetArray("SymmetryPlaneNormal").GetNumberOfComponents(), 3)
        kept = out.GetFieldData().GetArray("SymmetryKeptFraction")
        self.assertEqual(kept.GetValue(0), mirror.GetKeptFraction())
        self.assertGreater(kept.GetValue(0), 0.99)  # a sphere is its own mirror: nothing left out

    def test_a_fit_does_not_pass_on_an_earlier_fits_report(self):
        # A mesh that carries an earlier fit's report (a fitted lattice's
        # surface, fitted again): without an error search or a Metro run of its
        # own, the new lattice must not show the old numbers as its own.
        sphere = tagged_sphere(12, 12)
        for name, value in (("ErrorBoundTrials", 7), ("Hausdorff_Max", 123.0), ("ControlVertices", 999)):
            old = vtkFloatArray()
            old.SetName(name)
            old.InsertNextValue(value)
            sphere.GetFieldData().AddArray(old)
        fit = latticekit.vtkLKLatticeFitFilter()
        fit.SetInputData(sphere)
        fit.SetTargetNumberOfVertices(40)
        fit.SetComputeError(False)
        fit.Update()
        fields = fit.GetOutput().GetFieldData()
        self.assertIsNone(fields.GetArray("ErrorBoundTrials"))
        self.assertIsNone(fields.GetArray("Hausdorff_Max"))
        self.assertEqual(fields.GetArray("ControlVertices").GetValue(0), 40)
        self.assertEqual(space_of(fit.GetOutput()), "RAS")  # what is not the fit's passes

    def test_metro_does_not_pass_on_an_earlier_runs_other_direction(self):
        sphere = tagged_sphere(12, 12)
        coarse = tagged_sphere(8, 8)
        first = latticekit.vtkLKMetroFilter()
        first.SetInputData(0, sphere)
        first.SetInputData(1, coarse)
        first.Update()
        self.assertIsNotNone(first.GetOutput().GetFieldData().GetArray("BtoA_Max"))
        again = latticekit.vtkLKMetroFilter()  # the coloured mesh measured again, one way
        again.SetInputConnection(0, first.GetOutputPort())
        again.SetInputData(1, coarse)
        again.SymmetricOff()
        again.Update()
        fields = again.GetOutput().GetFieldData()
        self.assertIsNone(fields.GetArray("BtoA_Max"))
        self.assertIsNotNone(fields.GetArray("AtoB_Max"))
        self.assertEqual(space_of(again.GetOutput()), "RAS")


if __name__ == "__main__":
    unittest.main()
