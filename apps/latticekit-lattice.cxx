// latticekit-lattice: a lattice (polygonal control mesh) -> its smooth surface.
#include "common/AppSupport.h"

#include "vtkLKLatticeSurfaceFilter.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtksys/SystemTools.hxx>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>

namespace
{
void usage(std::ostream& os)
{
  os << "usage: latticekit-lattice LATTICE -o SURFACE [options]\n"
        "\n"
        "Builds the smooth lattice surface (Doo-Sabin rounding, cubic Bezier edge curves,\n"
        "G1 Gregory patches) of a polygonal lattice: triangles, quads and n-gons, closed or open.\n"
        "LATTICE: .vtp, .vtk, .ply or .obj (line cells on lattice edges mark sharp edges, with\n"
        "cell data RoundingWeight; point data RoundingWeight gives vertex weights).\n"
        "SURFACE: .vtp, .vtk, .stl, .ply, .obj or .gltf.\n"
        "\n"
        "  --resolution N     segments per quad patch side (default 8)\n"
        "  --split-creases    give each side of a sharp edge its own points and normals (crisp\n"
        "                     shading; the surface is then open along the sharp edges)\n"
        "  --control-net OUT  write the edge curves' control polygons and the Gregory interior points\n"
        "  --lattice OUT      write the lattice itself (for example to convert it to .obj)\n"
        "  -q, --quiet        no progress bar\n"
        "  -h, --help         this help\n";
}

} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-lattice");
  std::string input, output, netOut, latticeOut;
  long resolution = 8;
  bool quiet = false, splitCreases = false;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "-o" || a == "--output")
      output = args.value(a);
    else if (a == "--resolution")
      resolution = args.integer(a, 2, 256, "an integer from 2 to 256");
    else if (a == "--split-creases")
      splitCreases = true;
    else if (a == "--control-net")
      netOut = args.value(a);
    else if (a == "--lattice")
      latticeOut = args.value(a);
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
      args.positional(a, input, "lattice");
  }
  if (input.empty() || output.empty())
  {
    std::cerr << "error: a LATTICE and -o SURFACE are required\n";
    usage(std::cerr);
    return 2;
  }
  lkapp::installMessageHandler(quiet);
  std::string error;
  if (!lkapp::checkAllWritable({ output, netOut, latticeOut }, { input }))
    return 1;
  vtkSmartPointer<vtkPolyData> lattice = lkapp::readMesh(input, error);
  if (!lattice)
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkLKLatticeSurfaceFilter> surface;
  surface->SetInputData(lattice);
  surface->SetResolution(static_cast<int>(resolution));
  surface->SetSplitCreases(splitCreases);
  {
    lkapp::ProgressBar bar(surface, "lattice surface", !quiet);
    surface->Update();
  }
  if (lkapp::errorCount() > 0)
  {
    return 1;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string space = lkapp::coordinateSpace(lattice); // the input's, for every file written
  if (!lkapp::writeMesh(surface->GetOutput(), output, error, space) ||
    (!netOut.empty() && !lkapp::writeMesh(surface->GetControlNetOutput(), netOut, error, space)) ||
    (!latticeOut.empty() && !lkapp::writeMesh(lattice, latticeOut, error, space)))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }

  long long kinds[3] = { 0, 0, 0 };
  auto it = vtk::TakeSmartPointer(lattice->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    ++kinds[n == 3 ? 0 : (n == 4 ? 1 : 2)];
  }
  std::printf("lattice          %lld vertices; faces: %lld triangles, %lld quads, %lld other; %lld sharp-edge lines\n",
    static_cast<long long>(lattice->GetNumberOfPoints()), kinds[0], kinds[1], kinds[2],
    static_cast<long long>(lattice->GetNumberOfLines()));
  std::printf("surface          %lld Gregory patches, %lld display polygons on %lld points%s (resolution %ld), %.3f s\n",
    static_cast<long long>(surface->GetNumberOfPatches()),
    static_cast<long long>(surface->GetOutput()->GetFieldData()->GetArray("DisplayPolygons")->GetTuple1(0)),
    static_cast<long long>(surface->GetOutput()->GetNumberOfPoints()), splitCreases ? ", split along the sharp edges" : "",
    resolution, seconds);
  std::printf("bytes on disk    lattice %lld (%s), surface %lld (%s)\n", lkapp::fileBytes(input), input.c_str(),
    lkapp::fileBytes(output), output.c_str());
  return 0;
}
