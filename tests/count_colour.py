"""Counts the pixels of a PNG near a colour and fails when there are fewer
than asked: a picture's overlay (a line of that colour) is drawn, or not.

usage: count_colour.py IMAGE R G B TOLERANCE AT_LEAST [--at-most N]
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader


def main(argv):
    if len(argv) not in (7, 9):
        sys.exit(__doc__)
    path = argv[1]
    colour = [int(v) for v in argv[2:5]]
    tolerance, at_least = int(argv[5]), int(argv[6])
    at_most = int(argv[8]) if len(argv) == 9 and argv[7] == "--at-most" else None
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        sys.exit("error: cannot read the image '%s'" % path)
    scalars = image.GetPointData().GetScalars()
    count = 0
    for i in range(image.GetNumberOfPoints()):
        if all(abs(scalars.GetComponent(i, c) - colour[c]) <= tolerance for c in range(3)):
            count += 1
    print("%s: %d pixels near (%d, %d, %d)" % (path, count, *colour))
    if count < at_least or (at_most is not None and count > at_most):
        sys.exit("error: %d pixels, expected %s" % (count, "at least %d" % at_least if at_most is None
                                                      else "%d to %d" % (at_least, at_most)))


main(sys.argv)
