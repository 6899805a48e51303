// latticekit-fit: a dense triangle mesh -> a lattice whose smooth surface fits it.
#include "common/AppSupport.h"

#include "vtkLKLatticeFitFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMeshRepairFilter.h"
#include "vtkLKMeshPointIds.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtksys/SystemTools.hxx>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

namespace
{
void usage(std::ostream& os)
{
  os << "usage: latticekit-fit MESH -o LATTICE [options]\n"
        "\n"
        "Fits a lattice (coarse control mesh) to a manifold triangle mesh: quadric edge collapse\n"
        "with the error measured on the rounded lattice surface, feature lines kept, optional\n"
        "quad pairing and global refinement (Ceres). Reports the Metro error of the lattice\n"
        "surface against MESH. MESH: .vtp, .vtk, .ply, .obj or .stl; LATTICE: .vtp, .vtk, .ply,\n"
        ".obj (feature edges are line cells in .vtp/.vtk).\n"
        "\n"
        "  --repair               triangulate and repair MESH first (polygons split into\n"
        "                         triangles, duplicate points merged, degenerate faces\n"
        "                         removed, non-manifold vertices split, orientation made\n"
        "                         consistent); the error and --vertex-map are then those\n"
        "                         of the repaired mesh\n"
        "  --vertices N           lattice vertices (default: 10 % of the input's)\n"
        "  --ratio R              keep this fraction of the vertices instead (0 < R < 1)\n"
        "  --max-error E          or the fewest vertices whose surface stays within E % of\n"
        "                         the bounding-box diagonal (Hausdorff), searched over\n"
        "                         fitted and measured counts (one of these three at most)\n"
        "  --count-tolerance T    with --max-error: fewest to within this fraction of the\n"
        "                         count (default 0.01; 0: exact; larger saves fits)\n"
        "  --features LINES       polylines along mesh edges (.vtp/.vtk; point data MeshPointId,\n"
        "                         or points equal to mesh points)\n"
        "  --feature-weight K     k of eq. 3.14 on feature edges (default 1000; this and the\n"
        "                         next two need --features)\n"
        "  --neighbour-weight W   weight of edges next to a feature (default 100)\n"
        "  --lock-features        feature edges are never collapsed and never move\n"
        "  --feature-tolerance D  with --lock-features: each line keeps only the vertices\n"
        "                         that hold it within D (mm), exactly where they were, and\n"
        "                         its lattice edges are chords through them (a line split\n"
        "                         into the surface has a vertex at every edge it crosses;\n"
        "                         default 0: every feature edge kept)\n"
        "  --crease-angle DEG     lines across which the mesh bends by more than DEG degrees\n"
        "                         on average (a cut piece's rim, about 90) become creases of\n"
        "                         the lattice surface (default 45; 180: none)\n"
        "  --flat-quadrics        plain Garland-Heckbert placement (for comparison)\n"
        "  --quads                pair triangles into quads where the pair is near-rectangular\n"
        "  --refine               move the lattice vertices (Ceres) to fit the surface better\n"
        "  --refine-iterations N  outer iterations of the refinement (default 8; implies --refine)\n"
        "  --refine-max K         spend K of the lattice vertices on the largest distances:\n"
        "                         split the edges nearest to the farthest samples, then a\n"
        "                         second refinement pass with the tail penalty (implies\n"
        "                         --refine; default 1 per 100 vertices; 0: none; undone\n"
        "                         when they do not lower the largest distance)\n"
        "  --refine-tail MU       tail penalty of the refinement: a soft bound on the max\n"
        "                         error, paid for in mean; in the pass after the insertions,\n"
        "                         or with --refine-max 0 in the only pass (default 10; 0: off;\n"
        "                         implies --refine)\n"
        "  --surface OUT          also write the lattice surface (.vtp/.vtk/.stl/.ply/.obj/.gltf)\n"
        "  --vertex-map OUT       write MESH with LatticeFaceId, LatticeVertexId, Distance\n"
        "  --resolution N         tessellation of the surface and of the error (default 8)\n"
        "  -q, --quiet            no progress bar\n"
        "  -h, --help             this help\n";
}

/// Whether `b` has the points of `a`, in the same order.
bool samePoints(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
    return false;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
      return false;
  }
  return true;
}

} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-fit");
  std::string input, output, featuresIn, surfaceOut, mapOut;
  long vertices = 0, iterations = 8, resolution = 8, insertions = -1; // -1: 1 per 100 vertices
  double ratio = 0.0, maxError = 0.0, countTolerance = 0.01, k = 1000.0, kn = 100.0, tail = 10.0;
  double featureTolerance = 0.0;
  double creaseAngle = 45.0;
  bool lock = false, flat = false, quads = false, refine = false, quiet = false, repair = false;
  // Options that act only with another: refused without it rather than
  // ignored.
  bool countToleranceGiven = false, featureOptionGiven = false;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "-o" || a == "--output")
      output = args.value(a);
    else if (a == "--vertices")
      vertices = args.integer(a, 4, 2000000000L, "an integer of at least 4");
    else if (a == "--ratio")
      ratio = args.number(a, 1e-9, 1.0 - 1e-9, "a number between 0 and 1");
    else if (a == "--max-error")
      maxError = args.number(a, 1e-9, 100.0, "a percentage above 0");
    else if (a == "--count-tolerance")
    {
      countTolerance = args.number(a, 0.0, 1.0, "a number from 0 to 1");
      countToleranceGiven = true;
    }
    else if (a == "--features")
      featuresIn = args.value(a);
    else if (a == "--feature-weight")
    {
      k = args.number(a, 1e-300, 1e300, "a number above 0");
      featureOptionGiven = true;
    }
    else if (a == "--neighbour-weight")
    {
      kn = args.number(a, 1e-300, 1e300, "a number above 0");
      featureOptionGiven = true;
    }
    else if (a == "--lock-features")
      lock = featureOptionGiven = true;
    else if (a == "--feature-tolerance")
    {
      featureTolerance = args.number(a, 0.0, 1e300, "a distance of 0 or more");
      featureOptionGiven = true;
    }
    else if (a == "--crease-angle")
    {
      creaseAngle = args.number(a, 0.0, 180.0, "an angle from 0 to 180 degrees");
      featureOptionGiven = true;
    }
    else if (a == "--repair")
      repair = true;
    else if (a == "--flat-quadrics")
      flat = true;
    else if (a == "--quads")
      quads = true;
    else if (a == "--refine")
      refine = true;
    else if (a == "--refine-iterations")
    {
      iterations = args.integer(a, 1, 100, "an integer from 1 to 100");
      refine = true;
    }
    else if (a == "--refine-tail")
    {
      tail = args.number(a, 0.0, 1e300, "a number of at least 0");
      refine = true;
    }
    else if (a == "--refine-max")
    {
      insertions = args.integer(a, 0, 1000000, "an integer of at least 0");
      refine = true;
    }
    else if (a == "--surface")
      surfaceOut = args.value(a);
    else if (a == "--vertex-map")
      mapOut = args.value(a);
    else if (a == "--resolution")
      resolution = args.integer(a, 2, 64, "an integer from 2 to 64");
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
      args.positional(a, input, "mesh");
  }
  if (input.empty() || output.empty())
  {
    std::cerr << "error: a MESH and -o LATTICE are required\n";
    usage(std::cerr);
    return 2;
  }
  if ((vertices > 0) + (ratio > 0.0) + (maxError > 0.0) > 1)
  {
    std::cerr << "error: --vertices, --ratio and --max-error exclude each other\n";
    return 2;
  }
  if (countToleranceGiven && maxError == 0.0)
  {
    std::cerr << "error: --count-tolerance needs --max-error\n";
    return 2;
  }
  if (featureOptionGiven && featuresIn.empty())
  {
    std::cerr << "error: --feature-weight, --neighbour-weight, --lock-features, --feature-tolerance and --crease-angle "
                 "need --features\n";
    return 2;
  }
  if (featureTolerance > 0.0 && !lock)
  {
    std::cerr << "error: --feature-tolerance is for locked lines: it needs --lock-features\n";
    return 2;
  }
  lkapp::installMessageHandler(quiet);
  std::string error;
  if (!lkapp::checkAllWritable({ output, surfaceOut, mapOut }, { input, featuresIn }))
    return 1;
  vtkSmartPointer<vtkPolyData> mesh = lkapp::readMesh(input, error);
  if (!mesh)
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  vtkSmartPointer<vtkPolyData> features;
  if (!featuresIn.empty())
  {
    features = lkapp::readMesh(featuresIn, error);
    if (!features)
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
  }
  if (const std::string off = lkvtk::linesOffTheirMeshPoints(features, mesh); !off.empty())
  {
    std::cerr << "error: '" << featuresIn << "' does not fit '" << input << "': " << off
              << ": the lines were made on another mesh\n";
    return 1;
  }
  const std::string space = lkapp::coordinateSpace(mesh); // the input's, for every file written
  const auto start = std::chrono::steady_clock::now();
  const vtkIdType inputPoints = mesh->GetNumberOfPoints(), inputPolygons = mesh->GetNumberOfPolys();
  vtkNew<vtkLKMeshRepairFilter> repairFilter;
  if (repair)
  {
    repairFilter->SetInputData(mesh);
    repairFilter->Update();
    if (lkapp::errorCount() > 0)
      return 1;
    vtkPolyData* repaired = repairFilter->GetOutput();
    // Feature lines name the mesh's points (by id or position); a repair
    // that renumbers or moves them would leave the lines naming others.
    if (features && !samePoints(mesh, repaired))
    {
      std::cerr << "error: --repair changed the points of '" << input << "' (" << inputPoints << " -> "
                << repaired->GetNumberOfPoints()
                << "), so the feature lines no longer name them: draw the features on the repaired mesh "
                   "(--vertex-map writes it) and fit that\n";
      return 1;
    }
    mesh = repaired;
  }
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(mesh);
  if (features)
    fit->SetFeatureLinesData(features);
  if (vertices > 0)
    fit->SetTargetNumberOfVertices(vertices);
  else if (ratio > 0.0)
    fit->SetTargetReduction(1.0 - ratio);
  fit->SetMaximumError(maxError);
  fit->SetMaximumErrorCountTolerance(countTolerance);
  fit->SetFeatureWeight(k);
  fit->SetFeatureNeighbourWeight(kn);
  fit->SetLockFeatures(lock);
  fit->SetFeatureTolerance(featureTolerance);
  fit->SetCreaseAngle(creaseAngle);
  fit->SetRoundedSurfaceQuadrics(!flat);
  fit->SetQuadPairing(quads);
  fit->SetRefinement(refine);
  fit->SetRefinementTailWeight(tail);
  fit->SetRefinementInsertions(static_cast<int>(insertions));
  fit->SetRefinementIterations(static_cast<int>(iterations));
  fit->SetErrorResolution(static_cast<int>(resolution));
  {
    lkapp::ProgressBar bar(fit, "lattice fit", !quiet);
    fit->Update();
  }
  if (lkapp::errorCount() > 0)
  {
    const std::string why = lkapp::errors();
    if (!repair && (why.find("only triangles") != std::string::npos || why.find("manifold") != std::string::npos))
      std::cerr << "hint: --repair triangulates and repairs '" << input << "' first\n";
    return 1;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkPolyData* lattice = fit->GetOutput();
  if (!lkapp::writeMesh(lattice, output, error, space) ||
    (!mapOut.empty() && !lkapp::writeMesh(fit->GetVertexMapOutput(), mapOut, error, space)))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  long long surfaceBytes = -1;
  if (!surfaceOut.empty())
  {
    vtkNew<vtkLKLatticeSurfaceFilter> surface;
    surface->SetInputData(lattice);
    surface->SetResolution(static_cast<int>(resolution));
    surface->Update();
    if (lkapp::errorCount() > 0)
      return 1;
    if (!lkapp::writeMesh(surface->GetOutput(), surfaceOut, error, space))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    surfaceBytes = lkapp::fileBytes(surfaceOut);
  }
  std::printf("input            %lld vertices, %lld %s (%s, %lld bytes)\n", static_cast<long long>(inputPoints),
    static_cast<long long>(inputPolygons), repair ? "polygons" : "triangles", input.c_str(), lkapp::fileBytes(input));
  if (repair)
    std::printf("repaired         %lld vertices, %lld triangles: %.0f points merged, %.0f degenerate faces removed, "
                "%.0f non-manifold vertices split\n",
      static_cast<long long>(mesh->GetNumberOfPoints()), static_cast<long long>(mesh->GetNumberOfPolys()),
      lkapp::fieldValue(repairFilter->GetOutput(), "MergedPoints"),
      lkapp::fieldValue(repairFilter->GetOutput(), "RemovedDegenerateFaces"),
      lkapp::fieldValue(repairFilter->GetOutput(), "SplitNonManifoldVertices"));
  std::printf("lattice          %.0f control vertices; faces: %.0f triangles, %.0f quads; %.0f feature edges",
    lkapp::fieldValue(lattice, "ControlVertices"), lkapp::fieldValue(lattice, "Triangles"), lkapp::fieldValue(lattice, "Quads"),
    lkapp::fieldValue(lattice, "FeatureEdges"));
  if (lkapp::fieldValue(lattice, "FeatureEdges") > 0)
    std::printf(" (%.0f of them creases)", lkapp::fieldValue(lattice, "CreaseEdges"));
  std::printf("\n");
  if (maxError > 0.0)
  {
    std::printf("error bound      %g %% of the bounding-box diagonal: %.0f fits measured (vertices: max %%)",
      maxError, lkapp::fieldValue(lattice, "ErrorBoundTrials"));
    if (vtkDataArray* trials = lattice->GetFieldData()->GetArray("ErrorBoundTrialCountAndError"))
      for (vtkIdType i = 0; i < trials->GetNumberOfTuples(); ++i)
        std::printf("%s %.0f: %.4f", i ? "," : "", trials->GetComponent(i, 0), trials->GetComponent(i, 1));
    std::printf("\n");
  }
  std::printf("display polygons %.0f (resolution %ld)\n", lkapp::fieldValue(lattice, "DisplayPolygons"), resolution);
  std::printf("bytes on disk    lattice %lld (%s)", lkapp::fileBytes(output), output.c_str());
  if (surfaceBytes >= 0)
    std::printf(", surface %lld (%s)", surfaceBytes, surfaceOut.c_str());
  std::printf("\n");
  if (refine)
  {
    std::printf("refinement       RMS distance %.4g -> %.4g in %.0f iterations",
      lkapp::fieldValue(lattice, "RefinementInitialRMS"), lkapp::fieldValue(lattice, "RefinementFinalRMS"),
      lkapp::fieldValue(lattice, "RefinementIterations"));
    const double inserted = lkapp::fieldValue(lattice, "RefinementInsertions");
    const double refused = lkapp::fieldValue(lattice, "RefinementInsertionsRefused");
    if (inserted > 0)
      std::printf("; %.0f vertices inserted at the largest distances", inserted);
    else if (refused > 0)
      std::printf("; %.0f insertions at the largest distances tried and undone (no lower max)", refused);
    std::printf("\n");
  }
  std::printf("Metro error      max %.4f %%, mean %.4f %%, RMS %.4f %% of the bounding-box diagonal (%.4g)\n",
    lkapp::fieldValue(lattice, "Hausdorff_MaxPercent"), lkapp::fieldValue(lattice, "Hausdorff_MeanPercent"),
    lkapp::fieldValue(lattice, "Hausdorff_RMSPercent"), lkapp::fieldValue(lattice, "BoundingBoxDiagonal"));
  std::printf("time             %.2f s\n", seconds);
  return 0;
}
