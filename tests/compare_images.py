"""Compares a rendered screenshot with the expected one (vtkImageDifference,
the image comparison VTK's own regression tests use) and fails when the
thresholded error exceeds the tolerance. With --must-differ IMAGE, that image
must NOT match the expected one (the comparison can fail).

usage: compare_images.py EXPECTED ACTUAL TOLERANCE [--must-differ OTHER]
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkImagingCore import vtkImageDifference


def error(expected, actual):
    readers = []
    for path in (expected, actual):
        r = vtkPNGReader()
        r.SetFileName(path)
        r.Update()
        if r.GetOutput().GetNumberOfPoints() == 0:
            sys.exit("error: cannot read the image '%s'" % path)
        readers.append(r)
    if readers[0].GetOutput().GetDimensions() != readers[1].GetOutput().GetDimensions():
        return float("inf")
    d = vtkImageDifference()
    d.SetInputConnection(readers[1].GetOutputPort())
    d.SetImageConnection(readers[0].GetOutputPort())
    d.Update()
    # Per pixel, as VTK's regression tests normalise it.
    return d.GetThresholdedError()


def main(argv):
    if len(argv) not in (4, 6):
        sys.exit(__doc__)
    expected, actual, tolerance = argv[1], argv[2], float(argv[3])
    e = error(expected, actual)
    print("image difference %s vs %s: %.3f (tolerance %.3f)" % (actual, expected, e, tolerance))
    ok = e <= tolerance
    if len(argv) == 6:
        other = error(expected, argv[5])
        print("image difference %s vs %s: %.3f (must exceed %.3f)" % (argv[5], expected, other, tolerance))
        ok = ok and other > tolerance
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
