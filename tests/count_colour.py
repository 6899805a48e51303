"""Counts the pixels of a PNG near a colour and fails when there are fewer
than asked: a picture's overlay (a line of that colour) is drawn, or not.

usage: count_colour.py IMAGE R G B TOLERANCE AT_LEAST [--at-most N] [--in X0 Y0 X1 Y1]
       count_colour.py --after IMAGE CHECK [CHECK ...] -- COMMAND [ARGUMENT ...]

--in counts only in that part of the picture, in fractions of its width and
height from the lower left (as a VTK viewport is given).

--after removes IMAGE, runs COMMAND (the program that writes it anew, its
output shown; its failure is the test's), then each CHECK on IMAGE, each one argument:
"R G B TOLERANCE AT_LEAST [--at-most N] [--in X0 Y0 X1 Y1]". All checks are
counted and said; any that fails fails the run.
"""
import os
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader


def check(path, words):
    """One check (the words after IMAGE in the first usage): its line, and
    an error message where it fails (else None)."""
    if len(words) < 5:
        sys.exit(__doc__)
    colour = [int(v) for v in words[0:3]]
    tolerance, at_least = int(words[3]), int(words[4])
    at_most, part = None, (0.0, 0.0, 1.0, 1.0)
    rest = words[5:]
    while rest:
        if rest[0] == "--at-most" and len(rest) >= 2:
            at_most, rest = int(rest[1]), rest[2:]
        elif rest[0] == "--in" and len(rest) >= 5:
            part, rest = tuple(float(v) for v in rest[1:5]), rest[5:]
        else:
            sys.exit(__doc__)
    if not os.path.isfile(path):
        sys.exit("error: no image '%s'" % path)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    if image.GetNumberOfPoints() == 0 or scalars is None or scalars.GetNumberOfComponents() < 3:
        sys.exit("error: cannot read the image '%s' as a colour picture" % path)
    dims = image.GetDimensions()
    columns = range(int(part[0] * dims[0]), int(part[2] * dims[0]))
    rows = range(int(part[1] * dims[1]), int(part[3] * dims[1]))
    count = 0
    for y in rows:
        for x in columns:
            i = y * dims[0] + x
            if all(abs(scalars.GetComponent(i, c) - colour[c]) <= tolerance for c in range(3)):
                count += 1
    print("%s: %d pixels near (%d, %d, %d)" % (path, count, *colour), flush=True)
    if count < at_least or (at_most is not None and count > at_most):
        return "error: %d pixels, expected %s" % (count, "at least %d" % at_least if at_most is None
                                                  else "%d to %d" % (at_least, at_most))
    return None


def main(argv):
    if len(argv) >= 2 and argv[1] == "--after":
        if "--" not in argv[3:] or len(argv) < 6:
            sys.exit(__doc__)
        end = argv.index("--", 3)
        path, checks, command = argv[2], argv[3:end], argv[end + 1:]
        if not checks or not command:
            sys.exit(__doc__)
        if os.path.exists(path):
            os.remove(path)  # a picture of an earlier run is not counted
        sys.stdout.flush()
        ran = subprocess.run(command)
        if ran.returncode != 0:
            sys.exit("error: %s exited with %d" % (command[0], ran.returncode))
        errors = [e for e in (check(path, c.split()) for c in checks) if e]
        if errors:
            sys.exit("\n".join(errors))
        return
    if len(argv) < 7:
        sys.exit(__doc__)
    error = check(argv[1], argv[2:])
    if error:
        sys.exit(error)


if __name__ == "__main__":
    main(sys.argv)
