#!/bin/bash
# Installs the build into a fresh prefix and uses it as someone else's
# project would, with nothing from the build tree: find_package(latticekit)
# from a C++ project (tests/install_consumer), the Python package from the
# prefix's dist-packages, and an installed program without LD_LIBRARY_PATH.
# usage: check_install.sh CMAKE BUILD_DIR SOURCE_DIR PYTHON PYTHON_SITE WORK_DIR
set -euo pipefail
cmake=$1 build=$2 source=$3 python=$4 site=$5 work=$6
rm -rf "$work"
prefix=$work/prefix
"$cmake" --install "$build" --prefix "$prefix" > "$work.install.log" 2>&1 || { cat "$work.install.log"; exit 1; }
unset LD_LIBRARY_PATH PYTHONPATH

# An installed program finds its libraries through its RPATH.
"$prefix/bin/latticekit-surface" --help > /dev/null
if ldd "$prefix/bin/latticekit-fit" | grep 'not found'; then
  echo "error: an installed program misses a library"; exit 1
fi

# A C++ project: find_package(latticekit), LatticeKit::Filters.
"$cmake" -S "$source/tests/install_consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; exit 1; }
"$cmake" --build "$work/consumer" >> "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; exit 1; }
"$work/consumer/consumer"

# Python: the installed package, not the build tree's.
cd "$work"
PYTHONPATH="$prefix/$site" "$python" - "$prefix" <<'PY'
import sys
import latticekit
from vtkmodules.vtkFiltersSources import vtkSphereSource
prefix = sys.argv[1]
assert latticekit.__file__.startswith(prefix), latticekit.__file__
sphere = vtkSphereSource()
surface = latticekit.vtkLKLatticeSurfaceFilter()
surface.SetInputConnection(sphere.GetOutputPort())
surface.Update()
n = surface.GetOutput().GetNumberOfCells()
assert n > 0, n
print("python: latticekit", latticekit.__version__, "from", latticekit.__file__, "-", n, "triangles")
PY
echo "install: ok"
