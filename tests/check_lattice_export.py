#!/usr/bin/python3
"""Checks the planner's export of the lattices shown: each piece's
lattice_<stem>.vtp keeps the cut line exactly (its feature lines are the cut
line's edges, at the cut line's points, moved with the segment where the plan
moves it), and plan.txt names the files.

usage: check_lattice_export.py FOLDER PIECES
"""
import json
import os
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def edges_of_lines(pd, named_by):
    """The line cells' edges as pairs of the ids of `named_by`'s points at
    their ends (None: a point far from all of them)."""
    from vtkmodules.vtkCommonCore import vtkIdList
    from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator

    locator = vtkStaticPointLocator()
    locator.SetDataSet(named_by)
    locator.BuildLocator()

    def at(i):
        p = pd.GetPoint(i)
        q = locator.FindClosestPoint(p)
        near = named_by.GetPoint(q)
        return q if sum((p[k] - near[k]) ** 2 for k in range(3)) < 1e-8 else None
    out = set()
    lines = pd.GetLines()
    lines.InitTraversal()
    ids = vtkIdList()
    while lines.GetNextCell(ids):
        for k in range(ids.GetNumberOfIds() - 1):
            a, b = at(ids.GetId(k)), at(ids.GetId(k + 1))
            out.add(None if a is None or b is None else (min(a, b), max(a, b)))
    return out


def moved(pd, matrix):
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter

    t = vtkTransform()
    t.SetMatrix(matrix)
    f = vtkTransformPolyDataFilter()
    f.SetInputData(pd)
    f.SetTransform(t)
    f.Update()
    return f.GetOutput()


def main(folder, pieces):
    names = ["lattice_piece%d.vtp" % p for p in range(pieces)]
    with open(os.path.join(folder, "plan.txt")) as f:
        plan = f.read()
    expected = "the lattices shown, their kept lines as line cells: " + " ".join(names) + "\n"
    if expected not in plan:
        print("plan.txt does not name the lattices: " + expected)
        return 1
    with open(os.path.join(folder, "session.json")) as f:
        session = json.load(f)
    segment = session.get("segment")
    cut_lines = read(os.path.join(folder, "cut_lines.vtp"))
    for p, name in enumerate(names):
        lattice = read(os.path.join(folder, name))
        # The segment's lattice moved with it: so does its cut line.
        move = segment["matrix"] if segment and segment["piece"] == p else None
        line = moved(cut_lines, move) if move else cut_lines
        cut_here = edges_of_lines(line, line)
        kept = edges_of_lines(lattice, line)
        flags = lattice.GetCellData().GetArray("FeatureEdge")
        lines = lattice.GetNumberOfLines()
        if not flags or lines == 0:
            print("%s: no feature lines" % name)
            return 1
        if kept != cut_here:
            print("%s: %d feature edges, %d of them on the cut line, which has %d"
                  % (name, len(kept), len(kept & cut_here), len(cut_here)))
            return 1
        print("%s: %d control vertices, the cut line's %d edges kept exactly%s"
              % (name, lattice.GetNumberOfPoints(), len(kept), " (moved with the segment)" if move else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))
