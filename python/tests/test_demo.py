"""The main job end to end under Xvfb: files, report and a PNG that shows the error map."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

DEMO = os.environ["LATTICEKIT_DEMO"]
SAMPLE_DATA = os.environ["LATTICEKIT_SAMPLE_DATA"]


class DemoTest(unittest.TestCase):
    @unittest.skipIf(shutil.which("xvfb-run") is None, "xvfb-run is not installed")
    def test_demo_on_a_mandible(self):
        from vtkmodules.vtkIOImage import vtkPNGReader
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

        mandible = os.path.join(SAMPLE_DATA, "mandible-tcia", "test_oncologist_TCGA-CV-7236_Mandible.nrrd")
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out")
            result = subprocess.run(
                ["xvfb-run", "-a", DEMO, mandible, "-o", out, "--vertices", "2000", "-q",
                 "--view-from", "0,-1,0.3"],
                capture_output=True, text=True, check=False, timeout=300)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            for name in ("bone.vtp", "bone.stl", "simplified.vtp", "bone_error.vtp", "report.md", "error.png"):
                self.assertTrue(os.path.getsize(os.path.join(out, name)) > 0, name)
            report = open(os.path.join(out, "report.md")).read()
            self.assertIn("symmetric", report)

            mesh = vtkXMLPolyDataReader()
            mesh.SetFileName(os.path.join(out, "bone_error.vtp"))
            mesh.Update()
            self.assertIsNotNone(mesh.GetOutput().GetPointData().GetArray("Distance"))

            png = vtkPNGReader()
            png.SetFileName(os.path.join(out, "error.png"))
            png.Update()
            image = png.GetOutput()
            width, height, _ = image.GetDimensions()
            scalars = image.GetPointData().GetScalars()
            coloured = blue = red = 0
            for i in range(0, width * height, 7):
                r, g, b = (scalars.GetComponent(i, c) for c in range(3))
                if not (r > 240 and g > 240 and b > 240):
                    coloured += 1
                if b > 150 and r < 100:
                    blue += 1
                if r > 150 and b < 100 and g < 120:
                    red += 1
            total = width * height / 7
            self.assertGreater(coloured / total, 0.05, "the picture is almost blank")
            self.assertGreater(blue, 100, "no small-error (blue) surface is visible")
            self.assertGreater(red, 5, "no large-error (red) surface is visible")


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
            self.assertTrue(os.path.getsize(png) > 10000)


if __name__ == "__main__":
    unittest.main()
