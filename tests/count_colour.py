"""Counts the pixels of a PNG near a colour and fails when there are fewer
than asked: a picture's overlay (a line of that colour) is drawn, or not.

usage: count_colour.py IMAGE R G B TOLERANCE AT_LEAST [--at-most N] [--in X0 Y0 X1 Y1]

--in counts only in that part of the picture, in fractions of its width and
height from the lower left (as a VTK viewport is given).
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader


def main(argv):
    if len(argv) < 7:
        sys.exit(__doc__)
    path = argv[1]
    colour = [int(v) for v in argv[2:5]]
    tolerance, at_least = int(argv[5]), int(argv[6])
    at_most, part = None, (0.0, 0.0, 1.0, 1.0)
    rest = argv[7:]
    while rest:
        if rest[0] == "--at-most" and len(rest) >= 2:
            at_most, rest = int(rest[1]), rest[2:]
        elif rest[0] == "--in" and len(rest) >= 5:
            part, rest = tuple(float(v) for v in rest[1:5]), rest[5:]
        else:
            sys.exit(__doc__)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        sys.exit("error: cannot read the image '%s'" % path)
    scalars = image.GetPointData().GetScalars()
    dims = image.GetDimensions()
    columns = range(int(part[0] * dims[0]), int(part[2] * dims[0]))
    rows = range(int(part[1] * dims[1]), int(part[3] * dims[1]))
    count = 0
    for y in rows:
        for x in columns:
            i = y * dims[0] + x
            if all(abs(scalars.GetComponent(i, c) - colour[c]) <= tolerance for c in range(3)):
                count += 1
    print("%s: %d pixels near (%d, %d, %d)" % (path, count, *colour))
    if count < at_least or (at_most is not None and count > at_most):
        sys.exit("error: %d pixels, expected %s" % (count, "at least %d" % at_least if at_most is None
                                                      else "%d to %d" % (at_least, at_most)))


main(sys.argv)
