#!/usr/bin/python3
"""A mandible cut along a closed line into two capped pieces, rendered to a PNG.

usage: PYTHONPATH=build/python xvfb-run -a /usr/bin/python3 python/examples/osteotomy_cut.py LABELMAP OUT.png

The bone surface is cut by the closed line where the plane through the middle of
its bounding box (x) meets it: the line's points are picked on the surface and
joined along mesh edges (vtkDijkstraGraphGeodesicPath), the cut filter
duplicates the line's vertices and caps both pieces with one shared smooth
surface. Each piece is taken out with its cut line (vtkLKExtractCutPieceFilter,
whose second output is what a lattice fit keeps). The pieces are drawn apart,
in two colours, the caps darker, each piece's cut line in orange.
"""
import sys

import latticekit
from latticekit.rendering import save_png
from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPlane, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkCutter, vtkPolyDataNormals, vtkStripper, vtkThreshold
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkFiltersModeling import vtkDijkstraGraphGeodesicPath
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def closed_line(surface):
    """Mesh point ids of a closed edge path along the plane x = centre."""
    plane = vtkPlane()
    plane.SetOrigin(surface.GetCenter())
    plane.SetNormal(1, 0, 0)
    cutter = vtkCutter()
    cutter.SetInputData(surface)
    cutter.SetCutFunction(plane)
    stripper = vtkStripper()
    stripper.SetInputConnection(cutter.GetOutputPort())
    stripper.Update()
    contour = stripper.GetOutput()
    cell = contour.GetCell(0)  # the longest piece first is not guaranteed; take the first loop
    locator = vtkStaticPointLocator()
    locator.SetDataSet(surface)
    locator.BuildLocator()
    step = max(1, cell.GetNumberOfPoints() // 30)
    anchors = []
    for k in range(0, cell.GetNumberOfPoints(), step):
        v = locator.FindClosestPoint(contour.GetPoint(cell.GetPointId(k)))
        if not anchors or anchors[-1] != v:
            anchors.append(v)
    anchors.append(anchors[0])
    path = [anchors[0]]
    for a, b in zip(anchors, anchors[1:]):
        dijkstra = vtkDijkstraGraphGeodesicPath()
        dijkstra.SetInputData(surface)
        dijkstra.SetStartVertex(b)  # the path comes out from end to start
        dijkstra.SetEndVertex(a)
        dijkstra.Update()
        ids = dijkstra.GetIdList()
        path += [ids.GetId(i) for i in range(1, ids.GetNumberOfIds())]
    return path


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    reader = latticekit.vtkLKMedicalImageReader()
    reader.SetFileName(argv[1])
    bone = latticekit.vtkLKBoneSurfaceFilter()
    bone.SetInputConnection(reader.GetOutputPort())
    bone.Update()
    surface = bone.GetOutput()
    path = closed_line(surface)
    points, lines, ids = vtkPoints(), vtkCellArray(), vtkIdTypeArray()
    ids.SetName("MeshPointId")
    lines.InsertNextCell(len(path))
    for v in path:
        lines.InsertCellPoint(points.InsertNextPoint(surface.GetPoint(v)))
        ids.InsertNextValue(v)
    line = vtkPolyData()
    line.SetPoints(points)
    line.SetLines(lines)
    line.GetPointData().AddArray(ids)

    cut = latticekit.vtkLKClosedLineCutFilter()
    cut.SetInputConnection(bone.GetOutputPort())
    cut.SetLinesData(line)
    cut.CappingOn()
    cut.Update()
    print("pieces:", cut.GetNumberOfPieces())

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    colours = [(0.9, 0.8, 0.6), (0.6, 0.75, 0.9)]
    cut_lines = 0
    for region in range(cut.GetNumberOfPieces()):
        # One piece, in the cut's order every run (vtkThreshold on RegionId
        # lists the faces in another order from run to run), and its cut line.
        piece = latticekit.vtkLKExtractCutPieceFilter()
        piece.SetInputConnection(cut.GetOutputPort())
        piece.SetPiece(region)
        piece.Update()
        shift = (12.0 * (region - 0.5), 0, 0)  # drawn apart
        for cap in (0, 1):
            caps_only = vtkThreshold()
            caps_only.SetInputConnection(piece.GetOutputPort())
            caps_only.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, "Cap")
            caps_only.SetLowerThreshold(cap - 0.5)
            caps_only.SetUpperThreshold(cap + 0.5)
            geometry = vtkGeometryFilter()
            geometry.SetInputConnection(caps_only.GetOutputPort())
            normals = vtkPolyDataNormals()
            normals.SetInputConnection(geometry.GetOutputPort())
            mapper = vtkPolyDataMapper()
            mapper.SetInputConnection(normals.GetOutputPort())
            mapper.ScalarVisibilityOff()
            actor = vtkActor()
            actor.SetMapper(mapper)
            c = colours[region % 2]
            actor.GetProperty().SetColor(*(x * (0.55 if cap else 1.0) for x in c))
            actor.SetPosition(*shift)
            renderer.AddActor(actor)
        # Where the saw went through this piece: the feature lines a lattice
        # fit keeps (vtkLKLatticeFitFilter's second input, LockFeaturesOn).
        line_mapper = vtkPolyDataMapper()
        line_mapper.SetInputConnection(piece.GetOutputPort(1))
        line_mapper.ScalarVisibilityOff()
        line_actor = vtkActor()
        line_actor.SetMapper(line_mapper)
        line_actor.GetProperty().SetColor(0.95, 0.55, 0.1)
        line_actor.GetProperty().SetLineWidth(3)
        line_actor.SetPosition(*shift)
        renderer.AddActor(line_actor)
        cut_lines += piece.GetOutput(1).GetFieldData().GetArray("CutLineEdges").GetValue(0)
    print("cut line edges, both pieces:", int(cut_lines))
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(900, 600)
    window.AddRenderer(renderer)
    cam = renderer.GetActiveCamera()
    centre = surface.GetCenter()
    cam.SetFocalPoint(centre)
    cam.SetPosition(centre[0] + 60, centre[1] - 250, centre[2] + 160)
    cam.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    save_png(window, argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
