"""Writes the small meshes and lines of latticekit-cut's command-line tests
(tests/data): a sphere with its equator as a line cell, the equator alone, a
10 mm cube whose faces are 2 x 2 grids of quads with the loop around its middle,
and one ring around the tube of torus.obj (which does not separate a torus).
Run from the repository root: /usr/bin/python3 scripts/make_cut_test_data.py"""
import math

from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

DATA = "tests/data/"


def write(pd, name):
    w = vtkXMLPolyDataWriter()
    w.SetFileName(DATA + name)
    w.SetInputData(pd)
    w.SetDataModeToAscii()
    w.Write()


def polyline(points, ids, mesh_point_ids):
    """A closed polyline through points[ids]; with MeshPointId or by coordinates only."""
    pd = vtkPolyData()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    line = vtkCellArray()
    line.InsertNextCell(len(ids) + 1)
    for k, i in enumerate(ids):
        pts.InsertNextPoint(points.GetPoint(i))
        line.InsertCellPoint(k)
    line.InsertCellPoint(0)
    pd.SetPoints(pts)
    pd.SetLines(line)
    if mesh_point_ids:
        a = vtkIdTypeArray()
        a.SetName("MeshPointId")
        for i in ids:
            a.InsertNextValue(i)
        pd.GetPointData().AddArray(a)
    return pd


# The sphere: vtkSphereSource's rings of latitude are mesh edges; phi resolution 9 puts ring 4 of 7 on the equator.
sphere = vtkSphereSource()
sphere.SetThetaResolution(16)
sphere.SetPhiResolution(9)
sphere.SetRadius(10.0)
sphere.Update()
mesh = vtkPolyData()
mesh.DeepCopy(sphere.GetOutput())
mesh.GetPointData().Initialize()
points = mesh.GetPoints()
equator = [i for i in range(points.GetNumberOfPoints()) if abs(points.GetPoint(i)[2]) < 1e-4]
equator.sort(key=lambda i: math.atan2(points.GetPoint(i)[1], points.GetPoint(i)[0]))
assert len(equator) == 16
lines = vtkCellArray()
lines.InsertNextCell(17)
for i in equator + equator[:1]:
    lines.InsertCellPoint(i)
mesh.SetLines(lines)
write(mesh, "sphere_equator.vtp")
write(polyline(points, equator, False), "sphere_equator_line.vtp")

# The cube: 10 mm, each face a 2 x 2 grid of quads (26 vertices, 24 quads), outward.
grid = {}
cube_points = vtkPoints()
cube_points.SetDataTypeToDouble()
for x in range(3):
    for y in range(3):
        for z in range(3):
            if 1 in (x, y, z) and x == 1 and y == 1 and z == 1:
                continue
            grid[(x, y, z)] = cube_points.InsertNextPoint(5.0 * x, 5.0 * y, 5.0 * z)
faces = []
for axis in range(3):
    u, v = [(1, 2), (2, 0), (0, 1)][axis]
    for side in (0, 2):
        for a in range(2):
            for b in range(2):
                corners = []
                for da, db in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    c = [0, 0, 0]
                    c[axis] = side
                    c[u] = a + da
                    c[v] = b + db
                    corners.append(grid[tuple(c)])
                # (u, v, axis) is right-handed: the quad above faces +axis; flip it on the low side.
                faces.append(corners if side == 2 else corners[::-1])
with open(DATA + "cube_grid_lattice.obj", "w") as f:
    f.write("# a 10 mm cube, each face a 2 x 2 grid of quads (scripts/make_cut_test_data.py)\n")
    for i in range(cube_points.GetNumberOfPoints()):
        f.write("v %g %g %g\n" % cube_points.GetPoint(i))
    for face in faces:
        f.write("f %s\n" % " ".join(str(i + 1) for i in face))
middle = [grid[c] for c in ((0, 0, 1), (1, 0, 1), (2, 0, 1), (2, 1, 1), (2, 2, 1), (1, 2, 1), (0, 2, 1), (0, 1, 1))]
write(polyline(cube_points, middle, True), "cube_grid_middle_line.vtp")

# One ring around the tube of torus.obj (its 16 x 8 grid: the 8 vertices of the first tube ring).
torus_points = vtkPoints()
with open(DATA + "torus.obj") as f:
    for line in f:
        if line.startswith("v "):
            torus_points.InsertNextPoint(*map(float, line.split()[1:4]))
ring = [i for i in range(torus_points.GetNumberOfPoints()) if abs(torus_points.GetPoint(i)[1]) < 1e-6
        and torus_points.GetPoint(i)[0] > 0]
assert len(ring) == 8, len(ring)
ring.sort(key=lambda i: math.atan2(torus_points.GetPoint(i)[2], torus_points.GetPoint(i)[0] - 3.0))
write(polyline(torus_points, ring, True), "torus_ring_line.vtp")
