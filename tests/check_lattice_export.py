#!/usr/bin/python3
"""Checks the planner's export of the lattices shown: each piece's
lattice_<stem>.vtp keeps the cut line (its feature lines join points of the
cut line, exactly there, moved with the segment where the plan moves it, and
every point of the line lies within the planner's 0.05 mm of them), and
plan.txt names the files.

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


def distance_to_chords(p, chords):
    """The distance from p to the nearest of the segments."""
    best = float("inf")
    for a, b in chords:
        ab = [b[k] - a[k] for k in range(3)]
        ap = [p[k] - a[k] for k in range(3)]
        length2 = sum(x * x for x in ab)
        t = max(0.0, min(1.0, sum(ab[k] * ap[k] for k in range(3)) / length2)) if length2 > 0 else 0.0
        best = min(best, sum((ap[k] - t * ab[k]) ** 2 for k in range(3)) ** 0.5)
    return best


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
        if None in kept:
            print("%s: a feature edge ends off the cut line's points" % name)
            return 1
        points = {i for e in cut_here for i in e}
        kept_points = {i for e in kept for i in e}
        worst = max(distance_to_chords(line.GetPoint(i), [(line.GetPoint(a), line.GetPoint(b)) for a, b in kept])
                    for i in points)
        if worst > 0.05 + 1e-6:
            print("%s: a point of the cut line lies %.4f mm from the lattice's edges" % (name, worst))
            return 1
        print("%s: %d control vertices, the cut line kept within 0.05 mm through %d of its %d points%s"
              % (name, lattice.GetNumberOfPoints(), len(kept_points), len(points),
                 " (moved with the segment)" if move else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))
