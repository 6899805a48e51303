// latticekit-metro: Metro-style Hausdorff distance between two triangle meshes.
#include "common/AppSupport.h"

#include "vtkLKMetroFilter.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>

namespace
{
void usage(std::ostream& os)
{
  os << "usage: latticekit-metro A B [options]\n"
        "\n"
        "Measures the distance between the surfaces of two triangle meshes the way Metro\n"
        "(Cignoni, Rocchini, Scopigno 1998) does. A and B: .vtp, .vtk, .stl, .ply or .obj;\n"
        "polygons and strips are split into triangles first (said in the report).\n"
        "\n"
        "  --samples N      face samples per direction (default: 10 per face of the larger mesh)\n"
        "  --density D      face samples per unit area (overrides --samples)\n"
        "  --similar        face sampling by similar-triangle subdivision (deterministic)\n"
        "  --montecarlo     face sampling by Monte Carlo (default)\n"
        "  --seed S         Monte Carlo seed (default 5489)\n"
        "  --no-vertex      no vertex samples\n"
        "  --no-edge        no edge samples\n"
        "  --no-face        no face samples\n"
        "  --one-sided      only A -> B\n"
        "  --all-samples    mean and RMS over every sample counted once, as Metro 4 prints them\n"
        "                   (default: area-weighted over the face samples)\n"
        "  --colored OUT    write A with per-point distance and colours (blue small, red large)\n"
        "  -q, --quiet      no progress bar\n"
        "  -h, --help       this help\n";
}

/// Whether `pd` has faces other than triangles (polygons, strips).
bool hasNonTriangles(vtkPolyData* pd)
{
  if (pd->GetNumberOfStrips() > 0)
    return true;
  vtkCellArray* polys = pd->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
    if (polys->GetCellSize(c) != 3)
      return true;
  return false;
}

/// `pd` with its polygons and strips split into triangles (vtkTriangleFilter;
/// vertex and line cells kept, for the filter to refuse), or `pd` as it is.
vtkSmartPointer<vtkPolyData> triangulated(vtkPolyData* pd, const char* label, std::string& note)
{
  if (!hasNonTriangles(pd))
    return pd;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(pd);
  triangles->Update();
  vtkSmartPointer<vtkPolyData> out = triangles->GetOutput();
  note += std::string(" ") + label + ": " + std::to_string(pd->GetNumberOfPolys() + pd->GetNumberOfStrips()) +
    " faces split into " + std::to_string(out->GetNumberOfPolys()) + " triangles\n";
  return out;
}

void printMeshInfo(const char* label, const std::string& path, vtkPolyData* pd)
{
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(pd);
  mass->Update();
  double b[6];
  pd->GetBounds(b);
  std::printf(" %s: '%s'\n\tvertices  %12lld\n\tfaces     %12lld\n\tarea      %12.6f\n"
              "\tbbox (%.4f %.4f %.4f)-(%.4f %.4f %.4f)\n",
    label, path.c_str(), static_cast<long long>(pd->GetNumberOfPoints()),
    static_cast<long long>(pd->GetNumberOfPolys()), mass->GetSurfaceArea(), b[0], b[2], b[4], b[1],
    b[3], b[5]);
}

void printDirection(vtkPolyData* out, const char* title, const std::string& p)
{
  std::printf("\n%s\n", title);
  std::printf("\tsamples   %12.0f (vertex %.0f, edge %.0f, face %.0f)\n", lkapp::fieldValue(out, p + "_Samples"),
    lkapp::fieldValue(out, p + "_VertexSamples"), lkapp::fieldValue(out, p + "_EdgeSamples"), lkapp::fieldValue(out, p + "_FaceSamples"));
  std::printf("\tmax       %12.6f (%9.6f%% of bbox diagonal)\n", lkapp::fieldValue(out, p + "_Max"),
    lkapp::fieldValue(out, p + "_MaxPercent"));
  std::printf("\tmean      %12.6f (%9.6f%% of bbox diagonal)\n", lkapp::fieldValue(out, p + "_Mean"),
    lkapp::fieldValue(out, p + "_MeanPercent"));
  std::printf("\tRMS       %12.6f (%9.6f%% of bbox diagonal)\n", lkapp::fieldValue(out, p + "_RMS"),
    lkapp::fieldValue(out, p + "_RMSPercent"));
}
} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-metro");
  std::vector<std::string> inputs;
  std::string colored, methodOption;
  long samples = 0, seed = 5489;
  double density = 0.0;
  bool vertex = true, edge = true, face = true, symmetric = true, quiet = false, allSamples = false;
  int method = vtkLKMetroFilter::MONTE_CARLO;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "--samples")
      samples = args.integer(a, 1, std::numeric_limits<long>::max(), "a positive integer");
    else if (a == "--density")
      density = args.number(a, std::numeric_limits<double>::min(), std::numeric_limits<double>::max(), "a positive number");
    else if (a == "--seed")
      seed = args.integer(a, std::numeric_limits<long>::min(), std::numeric_limits<long>::max(), "an integer");
    else if (a == "--similar")
    {
      args.exclusive(a, methodOption);
      method = vtkLKMetroFilter::SIMILAR_TRIANGLES;
    }
    else if (a == "--montecarlo")
    {
      args.exclusive(a, methodOption);
      method = vtkLKMetroFilter::MONTE_CARLO;
    }
    else if (a == "--no-vertex")
      vertex = false;
    else if (a == "--no-edge")
      edge = false;
    else if (a == "--no-face")
      face = false;
    else if (a == "--one-sided")
      symmetric = false;
    else if (a == "--all-samples")
      allSamples = true;
    else if (a == "--colored")
      colored = args.value(a);
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
      inputs.push_back(a);
  }
  if (inputs.size() != 2)
  {
    std::cerr << "error: two meshes A and B are required\n";
    usage(std::cerr);
    return 2;
  }
  if (!vertex && !edge && !face)
  {
    std::cerr << "error: --no-vertex, --no-edge and --no-face together leave nothing to sample\n";
    return 2;
  }
  lkapp::installMessageHandler(quiet);
  std::string error;
  if (!lkapp::checkAllWritable({ colored }, { inputs[0], inputs[1] }))
    return 1;
  vtkSmartPointer<vtkPolyData> meshes[2];
  std::string spaces[2];
  std::string triangulation;
  for (int k = 0; k < 2; ++k)
  {
    meshes[k] = lkapp::readMesh(inputs[static_cast<std::size_t>(k)], error);
    if (!meshes[k])
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    spaces[k] = lkapp::coordinateSpace(meshes[k]);
    meshes[k] = triangulated(meshes[k], k == 0 ? "A" : "B", triangulation);
  }
  // Files that name different coordinate systems (3D Slicer's tag) lie
  // mirrored against each other: their distances measure the mirroring.
  if (!spaces[0].empty() && !spaces[1].empty() && spaces[0] != spaces[1])
    std::cerr << "warning: '" << inputs[0] << "' is in " << spaces[0] << " coordinates and '" << inputs[1] << "' in "
              << spaces[1] << " (their SPACE tags): x and y of one are mirrored against the other, and the distances "
              << "measure that too\n";

  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(meshes[0]);
  metro->SetTargetData(meshes[1]);
  metro->SetNumberOfSamples(samples);
  metro->SetSampleDensity(density);
  metro->SetFaceSamplingMethod(method);
  metro->SetRandomSeed(static_cast<int>(seed));
  metro->SetVertexSampling(vertex);
  metro->SetEdgeSampling(edge);
  metro->SetFaceSampling(face);
  metro->SetSymmetric(symmetric);
  metro->SetMeanOverAllSamples(allSamples);
  const auto start = std::chrono::steady_clock::now();
  {
    lkapp::ProgressBar bar(metro, "metro", !quiet);
    metro->Update();
  }
  if (lkapp::errorCount() > 0)
  {
    return 1;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkPolyData* out = metro->GetOutput();

  std::printf("latticekit-metro: Metro-style surface distance\n\nMesh info:\n");
  std::printf("%s", triangulation.c_str());
  printMeshInfo("A", inputs[0], meshes[0]);
  printMeshInfo("B", inputs[1], meshes[1]);
  std::printf("\tbbox diagonal (A and B together) %.6f\n", lkapp::fieldValue(out, "BoundingBoxDiagonal"));
  std::printf("\tface sampling %s\n",
    method == vtkLKMetroFilter::MONTE_CARLO ? "Monte Carlo" : "similar triangles");
  std::printf("\tmean and RMS %s\n", allSamples ? "over all samples, each counted once (Metro 4)"
                                                 : "area-weighted over the face samples");
  printDirection(out, "Forward distance (A -> B):", "AtoB");
  if (symmetric)
  {
    printDirection(out, "Backward distance (B -> A):", "BtoA");
  }
  std::printf("\nHausdorff distance: %.6f (%.6f%% of bbox diagonal)\n", lkapp::fieldValue(out, "Hausdorff_Max"),
    lkapp::fieldValue(out, "Hausdorff_MaxPercent"));
  std::printf("Worse-direction mean: %.6f (%.6f%%), RMS: %.6f (%.6f%%)\n",
    lkapp::fieldValue(out, "Hausdorff_Mean"), lkapp::fieldValue(out, "Hausdorff_MeanPercent"), lkapp::fieldValue(out, "Hausdorff_RMS"),
    lkapp::fieldValue(out, "Hausdorff_RMSPercent"));
  const double total = lkapp::fieldValue(out, "AtoB_Samples") + (symmetric ? lkapp::fieldValue(out, "BtoA_Samples") : 0.0);
  std::printf("Elapsed %.3f s, %.2f million samples per second\n", seconds,
    seconds > 0 ? total / seconds / 1e6 : 0.0);
  if (!colored.empty())
  {
    if (!lkapp::writeMesh(out, colored, error, spaces[0]))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    std::printf("Coloured mesh written to %s (point data Distance, DistanceColors)\n", colored.c_str());
  }
  return 0;
}
