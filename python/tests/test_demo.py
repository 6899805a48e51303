"""The main job end to end under Xvfb: files, report and a PNG that shows the error map."""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

DEMO = os.environ["LATTICEKIT_DEMO"]
SAMPLE_DATA = os.environ["LATTICEKIT_SAMPLE_DATA"]


def read_text(path):
    with open(path) as f:
        return f.read()


class DemoTest(unittest.TestCase):
    @unittest.skipIf(shutil.which("xvfb-run") is None, "xvfb-run is not installed")
    def test_main_job_plans_the_osteotomy_on_the_ct_head(self):
        from vtkmodules.vtkIOImage import vtkPNGReader
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out")
            result = subprocess.run(["xvfb-run", "-a", DEMO, "-o", out, "-q"],
                                    capture_output=True, text=True, check=False, timeout=600)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            names = ["mandible.vtp", "mandible.stl", "stroke.vtp", "cut_line.vtp", "lattice_whole.vtp",
                     "lattice_surface_cut.vtp", "lattice_surface_quads.vtp", "report.md",
                     "plan.png", "pieces.png", "error.png", "cut_line_ct.png", "cut_line_across_ct.png"]
            for p in range(2):
                names += ["piece%d.stl" % p, "piece%d.vtp" % p, "piece%d.obj" % p,
                          "lattice_piece%d.vtp" % p, "lattice_quads_piece%d.vtp" % p]
            for name in names:
                self.assertTrue(os.path.getsize(os.path.join(out, name)) > 0, name)
            # The bundled NIfTI has no orientation: no file claims a coordinate system.
            with open(os.path.join(out, "mandible.stl"), "rb") as f:
                self.assertNotIn(b"SPACE=", f.read(80))
            report = read_text(os.path.join(out, "report.md"))
            self.assertIn("Capped cut: 2 pieces", report)
            # The plan's smoothing, and no Gaussian on a CT.
            self.assertIn("the component at the seed; 10 windowed-sinc iterations on the surface)", report)
            # The bundled NIfTI gives no orientation; the plan states where
            # the head and the face are, so the CT pictures stand head up.
            self.assertIn("head up as the plan's \"patient\" states: the scan gives no orientation", report)
            # The cut line lies in the plan's cut plane (the section it was drawn along, 0.3 mm off).
            m = re.search(r"best-fitting plane is ([0-9.]+) deg from the plan's cut plane, its centre ([0-9.]+) mm", report)
            self.assertIsNotNone(m, report)
            self.assertLess(float(m.group(1)), 1.0)
            self.assertLess(float(m.group(2)), 0.5)
            rows = {}
            for line in report.splitlines():
                cells = [c.strip() for c in line.strip("|").split("|")]
                if len(cells) == 10 and cells[0] in ("no cut", "cut", "cut, quads, refined"):
                    rows[cells[0]] = [float(c) for c in cells[1:]]
            self.assertEqual(set(rows), {"no cut", "cut", "cut, quads, refined"})
            for name, row in rows.items():
                self.assertEqual(row[0], 1500, name)  # control vertices in all
                self.assertTrue(0 < row[6] < row[5], name)  # 0 < mean < max
            self.assertGreater(rows["cut, quads, refined"][2], 0)  # quads were paired
            # The pieces keep the points of the cut line that hold it within
            # the plan's 0.05 mm, not each of its vertices (a split line has
            # one at every mesh edge it crosses): the cut costs the lattice
            # little (each piece kept all 252, a third of the 1,500 between
            # them, and the cut's mean was 1.7 times the uncut one's).
            m = re.search(r"hold the line within 0.05 mm \(the plan's cutLineTolerance\), exactly where they are, as "
                          r"lattice vertices \(([0-9]+) of the ([0-9]+) line vertices of the two pieces\)", report)
            self.assertIsNotNone(m, report)
            self.assertLess(int(m.group(1)), 0.5 * int(m.group(2)))
            self.assertLess(rows["cut"][6], 1.3 * rows["no cut"][6])
            # The rim, where each flat cap meets the bone, is a crease of the
            # lattice surface: every line edge of the pieces' lattices.
            m = re.search(r"its lattice edges are creases of the smooth surface, which keeps the rim's edge: "
                          r"([0-9]+) of the pieces' ([0-9]+) line edges", report)
            self.assertIsNotNone(m, report)
            self.assertGreater(int(m.group(2)), 100)
            self.assertEqual(m.group(1), m.group(2))

            # The pieces are closed, and the cut line lies on both (it is their shared border).
            def read(name):
                r = vtkXMLPolyDataReader()
                r.SetFileName(os.path.join(out, name))
                r.Update()
                return r.GetOutput()
            from mesh_checks import open_edges
            for p in range(2):
                self.assertEqual(open_edges(read("piece%d.vtp" % p)).GetNumberOfCells(), 0, "piece %d is not closed" % p)
            self.assertIsNotNone(read("lattice_surface_quads.vtp").GetPointData().GetArray("Distance"))

            # The cutting guide: closed, on the bone's outer side of the plan's
            # cut plane, its slot in that plane, as the report says.
            guide = read("guide.vtp")
            self.assertEqual(open_edges(guide).GetNumberOfCells(), 0, "the guide is not closed")
            self.assertGreater(os.path.getsize(os.path.join(out, "guide.stl")), 0)
            m = re.search(r"Cutting guide \(`guide.stl`\): a shell 4.0 mm thick on ([0-9]+) mm\^2 of the bone .* with a "
                          r"slot 1.2 mm wide and ([0-9.]+) mm long in the plane for the saw and 2 screw hole\(s\) of 2.1 "
                          r"mm beside it to hold it; ([0-9]+) mm\^3", report)
            self.assertIsNotNone(m, report)
            self.assertGreater(float(m.group(1)), 200)
            self.assertGreater(float(m.group(2)), 10)
            self.assertAlmostEqual(float(m.group(3)), guide.GetFieldData().GetArray("GuideVolume").GetValue(0), delta=1)

            # The saved surface and cut line fit together: the line's MeshPointId
            # name mandible.vtp's points (the surface with the line split in), so
            # the two files cut again into the same pieces.
            import latticekit
            mandible, line = read("mandible.vtp"), read("cut_line.vtp")
            self.assertEqual(mandible.GetNumberOfLines(), 0)
            cut = latticekit.vtkLKClosedLineCutFilter()
            cut.SetInputData(mandible)
            cut.SetLinesData(line)
            cut.CappingOn()
            cut.Update()
            self.assertEqual(cut.GetNumberOfPieces(), 2)
            regions = cut.GetOutput().GetCellData().GetArray("RegionId")
            for p in range(2):
                faces = sum(1 for c in range(regions.GetNumberOfTuples()) if regions.GetValue(c) == p)
                self.assertEqual(faces, read("piece%d.vtp" % p).GetNumberOfPolys(), "piece %d" % p)

            png = vtkPNGReader()
            png.SetFileName(os.path.join(out, "error.png"))
            png.Update()
            image = png.GetOutput()
            width, height, _ = image.GetDimensions()
            scalars = image.GetPointData().GetScalars()
            coloured = blue = warm = magenta = 0
            for i in range(0, width * height, 7):
                r, g, b = (scalars.GetComponent(i, c) for c in range(3))
                if not (r > 240 and g > 240 and b > 240):
                    coloured += 1
                if b > 150 and r < 100:
                    blue += 1
                if i % width < 0.8 * width:  # the bone, left of the colour bar
                    if r > 180 and b < 90:
                        warm += 1
                    if r > 150 and g < 60 and b > 150:
                        magenta += 1
            total = width * height / 7
            self.assertGreater(coloured / total, 0.05, "the picture is almost blank")
            self.assertGreater(blue, 100, "no small-error (blue) surface is visible")
            # The scale ends at the 99th percentile, so the large errors stand
            # out (red), and the few points beyond it are magenta.
            self.assertGreater(warm, 30, "no large-error (yellow to red) surface is visible")
            self.assertGreater(magenta, 10, "the points above the scale are not marked")

            # The CT on the cut line's plane: the bone's cortex white in the
            # bone window, air and marrow dark, the cut line (orange) over it.
            png.SetFileName(os.path.join(out, "cut_line_ct.png"))
            png.Update()
            image = png.GetOutput()
            width, height, _ = image.GetDimensions()
            self.assertEqual((width, height), (600, 600))
            scalars = image.GetPointData().GetScalars()
            white = dark = orange = 0
            for i in range(0, width * height, 3):
                r, g, b = (scalars.GetComponent(i, c) for c in range(3))
                if r > 200 and g > 200 and b > 200:
                    white += 1
                if r < 60 and g < 60 and b < 60:
                    dark += 1
                if r > 200 and 60 < g < 140 and b < 60:
                    orange += 1
            total = width * height / 3
            self.assertGreater(white / total, 0.03, "no bone in the CT's picture")
            self.assertGreater(dark / total, 0.05, "no air or marrow in the CT's picture")
            self.assertGreater(orange, 300, "the cut line is not drawn over the CT")

    def test_label_map_plan_in_patient_coordinates(self):
        """A plan for another volume: the TCIA mandible label map (NRRD, LPS
        origin far from 0). The crop box is in patient coordinates, like the
        seed, the cut plane and the surface (it was read as data coordinates,
        which missed the bone: 'Iso value 0.5 is outside the volume's range
        [0, 0]'). The plan names no smoothing: a label map's surface gets
        latticekit-surface's defaults (it got the CT's 10 iterations and a
        Gaussian of half a voxel before). Too few lattice vertices for the cut
        are refused, with the pieces written and a report that says the run
        did not finish."""
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

        mandible = os.path.join(SAMPLE_DATA, "mandible-tcia", "test_oncologist_0522c0017_Mandible.nrrd")
        # Every vertex of the cut line kept (cutLineTolerance 0), as the
        # refusal's numbers below assume.
        plan_text = ('{"iso": 0.5, "crop": [0, 70, 250, 360, -1000, -900], "seed": [40, 300, -950],'
                     ' "cut": {"origin": [35, 300, -950], "normal": [1, 0, 0]}, "cutLineTolerance": 0,'
                     ' "latticeVertices": %d}')
        with tempfile.TemporaryDirectory() as tmp:
            plan = os.path.join(tmp, "plan.json")
            out = os.path.join(tmp, "out")

            def run(vertices):
                with open(plan, "w") as f:
                    f.write(plan_text % vertices)
                return subprocess.run([DEMO, mandible, "--plan", plan, "-o", out, "--no-render", "-q"],
                                      capture_output=True, text=True, check=False, timeout=300)

            # Each piece keeps the cut line's 232 vertices: 300 in all leaves none free.
            result = run(300)
            self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
            self.assertIn("too few for the cut", result.stderr)
            self.assertIn("give latticeVertices 928 or more", result.stderr)
            self.assertTrue(read_text(os.path.join(out, "report.md")).startswith("# latticekit main job: did not finish"))
            self.assertGreater(os.path.getsize(os.path.join(out, "piece1.stl")), 0)

            result = run(928)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            report = read_text(os.path.join(out, "report.md"))
            self.assertIn("Label map: `test_oncologist_0522c0017_Mandible.nrrd`", report)
            self.assertIn("(label map, level 0.5, the plan's box", report)
            self.assertIn("the component at the seed; a Gaussian of 0.5 voxel on the volume, "
                          "20 windowed-sinc iterations on the surface)", report)
            self.assertIn("Capped cut: 2 pieces", report)
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(out, "mandible.vtp"))
            reader.Update()
            bounds = reader.GetOutput().GetBounds()
            # The crop's x range [0, 70] mm (patient), padded by one voxel (0.98 mm):
            # the mandible reaches x = -59, so the box did cut it.
            self.assertGreater(bounds[0], -1.5)
            self.assertLess(bounds[1], 71.5)
            self.assertGreater(reader.GetOutput().GetNumberOfPoints(), 3000)
            # The NRRD gives its orientation: the files say LPS, as 3D Slicer's do
            # (the bundled NIfTI of the main job gives none, and they say nothing).
            space = reader.GetOutput().GetFieldData().GetAbstractArray("SPACE")
            self.assertIsNotNone(space)
            self.assertEqual(space.GetValue(0), "LPS")
            from vtkmodules.vtkIOGeometry import vtkSTLReader
            stl = vtkSTLReader()
            stl.SetFileName(os.path.join(out, "piece1.stl"))
            stl.Update()
            self.assertIn("SPACE=LPS", stl.GetHeader())
            with open(os.path.join(out, "piece0.obj")) as f:
                self.assertIn("SPACE=LPS", f.readline())

    def test_bad_plan_is_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            plan = os.path.join(tmp, "plan.json")

            def run_plan(text):
                with open(plan, "w") as f:
                    f.write(text)
                return subprocess.run([DEMO, "--plan", plan, "-o", os.path.join(tmp, "out"), "--no-render", "-q"],
                                      capture_output=True, text=True, check=False, timeout=60)

            cut = '"cut": {"origin": [0, 0, 0], "normal": [1, 0, 0]}'
            for text, message in [
                    ('{"cut": {"origin": [0, 0, 0]}}', "needs a cut plane"),
                    # A field of the wrong kind is named (jsoncpp's exception
                    # aborted the demo: a negative return code, from the signal).
                    ('{%s, "latticeVertices": "many"}' % cut, '"latticeVertices" must be a whole number'),
                    # More than the surface filter takes (it clamped them to 1000 without a word).
                    ('{%s, "smoothing": 5000}' % cut, '"smoothing" must be a whole number from 0 to 1000'),
                    ('{%s, "imageSmoothing": 30}' % cut, '"imageSmoothing" must be a standard deviation from 0 to 20'),
                    ('{%s, "cutLineTolerance": -0.1}' % cut, '"cutLineTolerance" must be a distance from 0 to 10 mm'),
                    ('{%s, "crop": [10, 0, 0, 1, 0, 1]}' % cut, "each min below its max"),
                    ('{%s, "patient": {"head": [0, 0, 1], "front": [0, 0, -2]}}' % cut,
                     "the plan's patient needs \"head\" and \"front\" as [x, y, z]: non-zero and not parallel"),
                    # A box far outside the volume (its voxel indices overflow an int).
                    ('{%s, "crop": [1e300, 2e300, 0, 1, 0, 1]}' % cut, "the crop box misses the volume")]:
                result = run_plan(text)
                self.assertEqual(result.returncode, 1, text + ": " + result.stderr)
                self.assertIn(message, result.stderr, text)


class LatticeExampleTest(unittest.TestCase):
    @unittest.skipIf(shutil.which("xvfb-run") is None, "xvfb-run is not installed")
    def test_lattice_example_renders(self):
        from vtkmodules.vtkIOImage import vtkPNGReader

        example = os.path.join(os.path.dirname(__file__), "..", "examples", "lattice_surface.py")
        mandible = os.path.join(SAMPLE_DATA, "mandible-tcia", "test_oncologist_TCGA-CV-7236_Mandible.nrrd")
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "lattice.png")
            result = subprocess.run(["xvfb-run", "-a", sys.executable, example, mandible, png, "300"],
                                    capture_output=True, text=True, check=False, timeout=300)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("display polygons", result.stdout)
            reader = vtkPNGReader()
            reader.SetFileName(png)
            reader.Update()
            image = reader.GetOutput()
            width, height, _ = image.GetDimensions()
            scalars = image.GetPointData().GetScalars()
            shaded = sum(1 for i in range(0, width * height, 11)
                         if scalars.GetComponent(i, 0) < 240 or scalars.GetComponent(i, 2) < 200)
            self.assertGreater(shaded / (width * height / 11), 0.05, "the picture is almost blank")


    @unittest.skipIf(shutil.which("xvfb-run") is None, "xvfb-run is not installed")
    def test_homogenized_loop_example_renders(self):
        from vtkmodules.vtkIOImage import vtkPNGReader

        example = os.path.join(os.path.dirname(__file__), "..", "examples", "homogenized_loop.py")
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "loop.png")
            result = subprocess.run(["xvfb-run", "-a", sys.executable, example, png, "6"],
                                    capture_output=True, text=True, check=False, timeout=300)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("face weight 6.0", result.stdout)
            reader = vtkPNGReader()
            reader.SetFileName(png)
            reader.Update()
            width, height, _ = reader.GetOutput().GetDimensions()
            self.assertEqual((width, height), (1600, 420))


    @unittest.skipIf(shutil.which("xvfb-run") is None, "xvfb-run is not installed")
    def test_bezier_ifs_example_renders(self):
        example = os.path.join(os.path.dirname(__file__), "..", "examples", "bezier_ifs.py")
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "ifs.png")
            result = subprocess.run(["xvfb-run", "-a", sys.executable, example, png],
                                    capture_output=True, text=True, check=False, timeout=300)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("wrote", result.stdout)
            self.assertTrue(os.path.getsize(png) > 10000)


    @unittest.skipIf(shutil.which("xvfb-run") is None, "xvfb-run is not installed")
    def test_osteotomy_cut_example_renders(self):
        example = os.path.join(os.path.dirname(__file__), "..", "examples", "osteotomy_cut.py")
        mandible = os.path.join(SAMPLE_DATA, "mandible-tcia", "test_oncologist_0522c0017_Mandible.nrrd")
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "cut.png")
            result = subprocess.run(["xvfb-run", "-a", sys.executable, example, mandible, png],
                                    capture_output=True, text=True, check=False, timeout=300)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("pieces: 2", result.stdout)
            # Both pieces' cut lines, each the loop's edges.
            edges = int(result.stdout.split("cut line edges, both pieces:")[1].split()[0])
            self.assertGreater(edges, 40)
            self.assertEqual(edges % 2, 0)
            self.assertTrue(os.path.getsize(png) > 10000)


if __name__ == "__main__":
    unittest.main()
