"""The coordinate system in the files the tools write, as 3D Slicer tags its model files.

Slicer reads "SPACE=LPS" (or RAS) from a .vtk or .stl header, a .ply comment,
a leading .obj comment and a .vtp's field data "SPACE", and mirrors x and y of
a model whose tag says RAS. A bone surface from a CT whose file gives its
orientation is in LPS patient coordinates, so every file made from it says so;
a file made from a mesh keeps the mesh's own tag; a volume without an
orientation gives no tag, since nothing is known.
"""
import os
import shutil
import subprocess
import tempfile
import unittest

BIN = os.environ["LATTICEKIT_BIN"]
SAMPLE_DATA = os.environ["LATTICEKIT_SAMPLE_DATA"]
TEST_DATA = os.environ["LATTICEKIT_TEST_DATA"]
MANDIBLE = os.path.join(SAMPLE_DATA, "mandible-tcia", "test_oncologist_0522c0017_Mandible.nrrd")
CTHEAD = os.path.join(SAMPLE_DATA, "cthead", "cthead_hu_approx.nii.gz")


def tool(name, *args):
    result = subprocess.run([os.path.join(BIN, name), *args, "-q"], capture_output=True, text=True,
                            check=False, timeout=300)
    return result


def space_of(path):
    """The tag a file carries, read as Slicer reads it; None if it has none."""
    ext = os.path.splitext(path)[1]
    text = None
    if ext == ".vtp":
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        r = vtkXMLPolyDataReader()
        r.SetFileName(path)
        r.Update()
        tag = r.GetOutput().GetFieldData().GetAbstractArray("SPACE")
        return tag.GetValue(0) if tag is not None and tag.GetNumberOfValues() > 0 else None
    if ext == ".vtk":
        from vtkmodules.vtkIOLegacy import vtkPolyDataReader
        r = vtkPolyDataReader()
        r.SetFileName(path)
        r.Update()
        text = r.GetHeader()
    elif ext == ".stl":
        from vtkmodules.vtkIOGeometry import vtkSTLReader
        r = vtkSTLReader()
        r.SetFileName(path)
        r.Update()
        text = r.GetHeader()
    elif ext == ".ply":
        from vtkmodules.vtkIOPLY import vtkPLYReader
        r = vtkPLYReader()
        r.SetFileName(path)
        r.Update()
        comments = r.GetComments()
        text = " ".join(comments.GetValue(i) for i in range(comments.GetNumberOfValues()))
    elif ext == ".obj":
        with open(path) as f:
            text = ""
            for line in f:
                if not line.startswith("#"):
                    break
                text += line
    for space in ("LPS", "RAS"):
        if text and "SPACE=" + space in text:
            return space
    return None


def tagged_sphere(folder, space):
    """tests/data/sphere_equator.vtp (its equator as line cells) with a SPACE tag."""
    from vtkmodules.vtkCommonCore import vtkStringArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(TEST_DATA, "sphere_equator.vtp"))
    reader.Update()
    sphere = reader.GetOutput()
    assert sphere.GetFieldData().GetAbstractArray("SPACE") is None
    tag = vtkStringArray()
    tag.SetName("SPACE")
    tag.InsertNextValue(space)
    sphere.GetFieldData().AddArray(tag)
    path = os.path.join(folder, "sphere_%s.vtp" % space)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(sphere)
    writer.SetFileName(path)
    writer.Write()
    return path


class CoordinateSpaceTest(unittest.TestCase):
    def test_a_surface_from_an_oriented_ct_says_lps_in_every_format(self):
        with tempfile.TemporaryDirectory() as tmp:
            for ext in (".vtp", ".vtk", ".stl", ".ply", ".obj"):
                path = os.path.join(tmp, "mandible" + ext)
                result = tool("latticekit-surface", MANDIBLE, "-o", path)
                self.assertEqual(result.returncode, 0, result.stderr)
                self.assertEqual(space_of(path), "LPS", ext)
                self.assertIn("space      LPS patient coordinates (tagged SPACE=LPS", result.stdout)
            # The tag costs the mesh nothing: the same points come back.
            from vtkmodules.vtkIOGeometry import vtkOBJReader
            from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
            obj, vtp = vtkOBJReader(), vtkXMLPolyDataReader()
            obj.SetFileName(os.path.join(tmp, "mandible.obj"))
            vtp.SetFileName(os.path.join(tmp, "mandible.vtp"))
            obj.Update()
            vtp.Update()
            self.assertEqual(obj.GetOutput().GetNumberOfPoints(), vtp.GetOutput().GetNumberOfPoints())
            self.assertEqual(obj.GetOutput().GetNumberOfPolys(), vtp.GetOutput().GetNumberOfPolys())

    def test_a_volume_without_orientation_gives_no_tag(self):
        # The bundled NIfTI has neither qform nor sform: its data coordinates
        # are no patient system, and a tag would claim one.
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "skull.stl")
            result = tool("latticekit-surface", CTHEAD, "-o", path, "--iso", "800")
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIsNone(space_of(path))
            self.assertIn("the file gives no orientation; no SPACE tag written", result.stdout)

    def test_tools_keep_the_tag_of_the_mesh_they_read(self):
        with tempfile.TemporaryDirectory() as tmp:
            lps = os.path.join(tmp, "mandible.obj")
            self.assertEqual(tool("latticekit-surface", MANDIBLE, "-o", lps).returncode, 0)
            # The fit: from a tagged .obj to a lattice, its surface and the vertex map.
            lattice, surface, vmap = (os.path.join(tmp, n) for n in ("lattice.vtk", "surface.stl", "map.vtp"))
            result = tool("latticekit-fit", lps, "-o", lattice, "--vertices", "400", "--surface", surface,
                          "--vertex-map", vmap)
            self.assertEqual(result.returncode, 0, result.stderr)
            for path in (lattice, surface, vmap):
                self.assertEqual(space_of(path), "LPS", path)
            # The lattice's surface: the tag of the lattice read.
            smooth = os.path.join(tmp, "smooth.ply")
            result = tool("latticekit-lattice", lattice, "-o", smooth)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertEqual(space_of(smooth), "LPS")

            # A mesh tagged RAS (as older Slicer wrote its models): the cut's
            # files say RAS, not LPS.
            ras = tagged_sphere(tmp, "RAS")
            pieces = os.path.join(tmp, "pieces")
            result = tool("latticekit-cut", ras, "-o", os.path.join(tmp, "cut.vtk"), "--pieces", pieces)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertEqual(space_of(os.path.join(tmp, "cut.vtk")), "RAS")
            for p in range(2):
                for ext in (".stl", ".vtp", ".obj"):
                    self.assertEqual(space_of(os.path.join(pieces, "piece%d%s" % (p, ext))), "RAS", (p, ext))
            # An untagged mesh stays untagged.
            result = tool("latticekit-cut", os.path.join(TEST_DATA, "sphere_equator.vtp"), "-o",
                          os.path.join(tmp, "plain.stl"))
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIsNone(space_of(os.path.join(tmp, "plain.stl")))

    @unittest.skipIf(shutil.which("xvfb-run") is None, "xvfb-run is not installed")
    def test_the_planners_export_names_the_cts_system(self):
        with tempfile.TemporaryDirectory() as tmp:
            folder = os.path.join(tmp, "plan")
            result = subprocess.run(["xvfb-run", "-a", os.path.join(BIN, "latticekit-planner"), MANDIBLE,
                                     "--replay", os.path.join(TEST_DATA, "mandible_session.json"),
                                     "--export", folder], capture_output=True, text=True, check=False, timeout=300)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("space: LPS patient coordinates (the cube at the top right", result.stdout)
            for name in ("piece0.stl", "piece0.vtp", "piece0.obj", "piece1.stl", "surface.vtp", "cut_lines.vtp"):
                self.assertEqual(space_of(os.path.join(folder, name)), "LPS", name)
            # A mesh file's own tag: the cube's letters and the export follow it;
            # an untagged mesh gets no cube and no tag.
            for space, path in (("RAS", tagged_sphere(tmp, "RAS")),
                                (None, os.path.join(TEST_DATA, "sphere_equator.vtp"))):
                folder = os.path.join(tmp, "sphere_%s" % space)
                result = subprocess.run(["xvfb-run", "-a", os.path.join(BIN, "latticekit-planner"), path,
                                         "--export", folder], capture_output=True, text=True, check=False,
                                        timeout=300)
                self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
                if space:
                    self.assertIn("space: RAS patient coordinates", result.stdout)
                else:
                    self.assertIn("space: unknown, the mesh file names none (no orientation cube)", result.stdout)
                self.assertEqual(space_of(os.path.join(folder, "piece0.stl")), space)
                # The plan file names its input and the system its positions are in.
                with open(os.path.join(folder, "plan.txt")) as f:
                    plan = f.read().splitlines()
                self.assertEqual(plan[0], "input: " + os.path.abspath(path))
                self.assertEqual(plan[1], "coordinates: " + ("RAS, mm" if space else
                                                             "the input's own (its patient orientation is unknown)"))

    def test_metro_warns_when_the_two_files_name_different_systems(self):
        with tempfile.TemporaryDirectory() as tmp:
            lps = os.path.join(tmp, "lps.vtk")
            self.assertEqual(tool("latticekit-surface", MANDIBLE, "-o", lps).returncode, 0)
            # The same file, its header saying RAS.
            with open(lps, "rb") as f:
                data = f.read()
            ras = os.path.join(tmp, "ras.vtk")
            with open(ras, "wb") as f:
                f.write(data.replace(b"SPACE=LPS", b"SPACE=RAS", 1))
            self.assertEqual(space_of(ras), "RAS")
            colored = os.path.join(tmp, "colored.vtp")
            result = tool("latticekit-metro", lps, ras, "--samples", "20000", "--colored", colored)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("mirrored against the other", result.stderr)
            self.assertEqual(space_of(colored), "LPS")  # mesh A's
            result = tool("latticekit-metro", lps, lps, "--samples", "20000")
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertNotIn("mirrored", result.stderr)


if __name__ == "__main__":
    unittest.main()
