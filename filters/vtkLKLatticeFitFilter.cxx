#include "vtkLKLatticeFitFilter.h"
#include "vtkLKFieldValues.h"
#include "vtkLKAbort.h"
#include "vtkLKProgressRelay.h"

#include "latticekit/ClosestPointTree.h"
#include "latticekit/ErrorBoundSearch.h"
#include "latticekit/FeatureChains.h"
#include "latticekit/LatticeRefinement.h"
#include "latticekit/LatticeSimplification.h"
#include "latticekit/ManifoldRepair.h"
#include "latticekit/QuadPairing.h"
#include "latticekit/SurfaceSampling.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMetroFilter.h"
#include "vtkLKMeshPointIds.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkMath.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkStaticPointLocator.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

vtkStandardNewMacro(vtkLKLatticeFitFilter);

namespace
{
using lkvtk::addFieldValue;

struct Fit
{
  lk::PolygonMesh lattice;
  std::vector<lk::EdgeKey> features;
  std::vector<char> creases; ///< per feature edge: a crease of the surface (CreaseAngle)
  std::vector<std::int64_t> collapsedInto;
  std::size_t quads = 0;
  lk::RefinementReport refinement;
  int insertions = 0;
  bool insertionsHelped = false; ///< they lowered the largest distance, the mean within the tolerance
  int insertionsRefused = 0;     ///< insertions tried and undone (the fit redone without them)
  std::size_t target = 0;        ///< the vertex count asked for
  std::size_t samples = 0;       ///< the refinement's samples of the input
};

/// The insertions at the largest distances are kept when the largest distance
/// falls and the mean rises by at most this factor (both over the
/// refinement's samples and surface points, against the pass before them).
constexpr double insertionMeanTolerance = 1.02;

/// The refinement's samples: never fewer than the first, whatever the
/// input; thinned only beyond the second (and 150 per lattice vertex).
constexpr std::size_t kMinimumRefinementSamples = 20000;
constexpr std::size_t kRefinementSampleCap = 500000;

/// The rounding weights of the lattice surface's vertices: with
/// `interpolateFeatures`, 0 at the ends of feature edges (the surface passes
/// through them) and 1 elsewhere; otherwise empty (all 1).
std::vector<double> surfaceVertexWeights(const Fit& fit, bool interpolateFeatures)
{
  if (!interpolateFeatures || fit.features.empty())
    return {};
  std::vector<double> w(fit.lattice.points.size(), 1.0);
  for (const auto& e : fit.features)
    w[static_cast<std::size_t>(e.first)] = w[static_cast<std::size_t>(e.second)] = 0.0;
  return w;
}

/// The rounding weights of the lattice surface's edges: 0 on the feature
/// edges that are creases.
std::map<lk::EdgeKey, double> surfaceEdgeWeights(const Fit& fit)
{
  std::map<lk::EdgeKey, double> w;
  for (std::size_t i = 0; i < fit.features.size(); ++i)
    if (fit.creases[i])
      w[fit.features[i]] = 0.0;
  return w;
}
} // namespace

vtkLKLatticeFitFilter::vtkLKLatticeFitFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

void vtkLKLatticeFitFilter::SetFeatureLinesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkLKLatticeFitFilter::SetFeatureLinesData(vtkPolyData* lines)
{
  this->SetInputData(1, lines);
}

vtkPolyData* vtkLKLatticeFitFilter::GetVertexMapOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkLKLatticeFitFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkLKLatticeFitFilter::InsertionsFor(std::size_t target) const
{
  return this->RefinementInsertions >= 0 ? this->RefinementInsertions : static_cast<int>(target / 100);
}

int vtkLKLatticeFitFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* lines = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* vertexMap = vtkPolyData::GetData(outputVector, 1);

  if (std::isnan(this->MaximumError))
  {
    // The clamp in SetMaximumError lets NaN through; 0 (no bound) would be taken silently.
    vtkErrorMacro("Cannot fit a lattice: MaximumError must be a number (0: no error bound), not NaN.");
    return 0;
  }
  if (!(std::isfinite(this->FeatureTolerance) && this->FeatureTolerance >= 0.0))
  {
    vtkErrorMacro("Cannot fit a lattice: FeatureTolerance must be a finite distance >= 0 (0: every feature edge "
                  "kept), not "
      << this->FeatureTolerance << ".");
    return 0;
  }
  if (!(this->CreaseAngle >= 0.0 && this->CreaseAngle <= 180.0))
  {
    vtkErrorMacro("Cannot fit a lattice: CreaseAngle must be an angle from 0 to 180 degrees (180: no crease), not "
      << this->CreaseAngle << ".");
    return 0;
  }
  if (this->FeatureTolerance > 0.0 && !this->LockFeatures)
  {
    vtkErrorMacro("Cannot fit a lattice: FeatureTolerance (" << this->FeatureTolerance
                                                              << ") is for locked lines: turn LockFeatures on, or "
                                                                 "set it to 0.");
    return 0;
  }
  {
    // The refinement's own checks, before the simplification's work.
    lk::RefinementOptions check;
    check.iterations = this->RefinementIterations;
    check.tailWeight = this->RefinementTailWeight;
    check.tailThreshold = this->RefinementTailThreshold;
    const std::string problem = lk::refinementOptionsProblem(check);
    if (!problem.empty())
    {
      vtkErrorMacro("Cannot fit a lattice: " << problem << ".");
      return 0;
    }
  }
  lk::TriangleMesh mesh;
  std::string problem = lkvtk::toTriangleMesh(input, mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot fit a lattice: " << problem << ".");
    return 0;
  }
  std::vector<lk::EdgeKey> features;
  problem = lkvtk::lineEdges(lines, input, features);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot fit a lattice: " << problem << ".");
    return 0;
  }
  if (const std::string off = lkvtk::linesOffTheirMeshPoints(lines, input); !off.empty())
    vtkWarningMacro("The feature lines may belong to another mesh: " << off
                                                                      << ". They are taken by their MeshPointIds.");
  if (features.empty() && lines && lines->GetNumberOfPoints() > 0)
    vtkWarningMacro("The feature lines (" << lines->GetNumberOfPoints() << " points, " << lines->GetNumberOfLines()
                                          << " lines) have no edge between two different mesh points: the "
                                             "lattice is fitted without features.");

  // How sharply the input bends across each feature edge, for the creases.
  const std::vector<double> bends = lk::edgeBends(mesh, features);

  lk::SimplificationOptions so;
  so.featureWeight = this->FeatureWeight;
  so.featureNeighbourWeight = this->FeatureNeighbourWeight;
  so.lockFeatures = this->LockFeatures;
  so.featureTolerance = this->FeatureTolerance;
  so.roundedSurfaceQuadrics = this->RoundedSurfaceQuadrics;
  lk::QuadPairingOptions qo;
  qo.rightAngleTolerance = this->RightAngleTolerance;
  qo.angleSumTolerance = this->AngleSumTolerance;
  qo.maxDihedralDegrees = this->MaximumDihedralAngle;

  const auto inputVertices = static_cast<vtkIdType>(mesh.points.size());
  // Refinement samples: Metro's own sampling of the input (vertices, edges,
  // faces; similar triangles, so deterministic), 4 per input triangle.
  std::vector<lk::Vec3> samples;
  if (this->Refinement)
  {
    lk::SamplingOptions sampling;
    sampling.targetSamples = std::max<std::size_t>(4 * mesh.triangles.size(), kMinimumRefinementSamples);
    sampling.method = lk::FaceSamplingMethod::SimilarTriangles;
    try
    {
      samples = lk::sampleSurface(mesh, sampling).points;
    }
    catch (const std::exception& e)
    {
      // A mesh of zero area (every point one point): uncaught, this ended
      // the program; the mesh check names the cause.
      const std::string cause = lk::cgalSurfaceMeshProblem(mesh);
      vtkErrorMacro("Cannot fit a lattice: " << (cause.empty() ? std::string(e.what()) : cause) << ".");
      return 0;
    }
  }
  const bool searching = this->MaximumError > 0.0;

  // One fit at a vertex count with a given number of insertions; progress
  // runs over [p0, p1].
  auto fitWith = [&](std::size_t target, int insertions, double tailWeight, double p0, double p1, Fit& fit) -> bool {
    const bool refine = this->Refinement;
    const double split = refine ? 0.5 : 0.95;
    so.targetVertices = target - static_cast<std::size_t>(insertions);
    fit.target = target;
    fit.insertionsHelped = false;
    fit.insertionsRefused = 0;
    so.progress = [&](double f) {
      this->UpdateProgress(p0 + (p1 - p0) * split * f);
      return !this->GetAbortExecute();
    };
    const lk::SimplificationResult r = lk::simplifyLattice(mesh, features, so);
    if (r.aborted)
      return false;
    fit.features = r.featureEdges;
    fit.creases =
      lk::creaseFeatureEdges(mesh.points, features, bends, r.featureEdges, r.inputVertex, this->CreaseAngle);
    fit.collapsedInto = r.collapsedInto;
    fit.quads = 0;
    if (this->QuadPairing)
    {
      const std::set<lk::EdgeKey> featureSet(r.featureEdges.begin(), r.featureEdges.end());
      lk::QuadPairingResult q = lk::pairTrianglesIntoQuads(r.mesh, featureSet, qo, &r.edgeCost);
      fit.lattice = std::move(q.lattice);
      fit.quads = q.quads;
    }
    else
    {
      fit.lattice = lk::asPolygonMesh(r.mesh);
    }
    fit.insertions = 0;
    if (refine)
    {
      // A huge input gives far more samples than the lattice needs (the
      // 560,000-triangle skull 4.2 million), which cost time and memory and
      // no accuracy (NOTES, issue 4): beyond 500,000, at most 150 per lattice
      // vertex are kept, every k-th, so vertices, edges and faces keep their
      // shares. Inputs below about 60,000 triangles are never thinned.
      const std::size_t cap = std::max<std::size_t>(kRefinementSampleCap, 150 * target);
      std::vector<lk::Vec3> thinned;
      if (samples.size() > cap)
      {
        thinned.reserve(cap);
        for (std::size_t i = 0; i < cap; ++i)
          thinned.push_back(samples[i * samples.size() / cap]);
      }
      const std::vector<lk::Vec3>& used = thinned.empty() ? samples : thinned;
      fit.samples = used.size();
      lk::RefinementOptions ro;
      ro.iterations = this->RefinementIterations;
      ro.tailWeight = tailWeight;
      ro.tailThreshold = this->RefinementTailThreshold;
      ro.original = &mesh; // both of Metro's directions
      // The refinement's threads follow VTK's (VTK_SMP_MAX_THREADS,
      // vtkSMPTools::Initialize), as the Metro measure's do.
      ro.threads = vtkSMPTools::GetEstimatedNumberOfThreads();
      ro.fixed.assign(fit.lattice.points.size(), 0);
      for (const auto& e : fit.features)
        ro.fixed[static_cast<std::size_t>(e.first)] = ro.fixed[static_cast<std::size_t>(e.second)] = 1;
      ro.weights.vertex = surfaceVertexWeights(fit, this->InterpolateFeatures); // the surface the output describes
      ro.weights.edge = surfaceEdgeWeights(fit);
      // With insertions: a first pass without the tail penalty, the new
      // vertices, then a second pass of half the iterations with it.
      const double firstShare = insertions > 0 ? 2.0 / 3.0 : 1.0;
      if (insertions > 0)
        ro.tailWeight = 0.0;
      ro.progress = [&](double f) {
        this->UpdateProgress(p0 + (p1 - p0) * (split + (0.95 - split) * firstShare * f));
        return !this->GetAbortExecute();
      };
      fit.refinement = lk::refineLatticeFit(fit.lattice, used, ro);
      if (insertions > 0 && !this->GetAbortExecute())
      {
        std::vector<lk::EdgeKey> keep(fit.features.begin(), fit.features.end());
        fit.insertions =
          lk::insertVerticesAtLargestDistances(
          fit.lattice, used, insertions, keep, ro.weights, ro.fixed, ro.locatorResolution, ro.threads);
        ro.iterations = std::max(1, this->RefinementIterations / 2);
        ro.tailWeight = tailWeight;
        ro.progress = [&](double f) {
          this->UpdateProgress(p0 + (p1 - p0) * (split + (0.95 - split) * (firstShare + (1.0 - firstShare) * f)));
          return !this->GetAbortExecute();
        };
        const lk::RefinementReport first = fit.refinement;
        const lk::RefinementReport second = lk::refineLatticeFit(fit.lattice, used, ro);
        fit.refinement.finalRms = second.finalRms;
        fit.refinement.finalMean = second.finalMean;
        fit.refinement.finalMax = second.finalMax;
        fit.refinement.iterations += second.iterations;
        // The insertions are there to lower the largest distance at (nearly)
        // the same mean; where they do not (the new vertices chase an
        // artefact, the second pass bulges), they are refused, and so are
        // fewer than asked (too few edges to split), which would leave the
        // lattice below its target.
        fit.insertionsHelped = fit.insertions == insertions && second.finalMax < first.finalMax &&
          second.finalMean <= insertionMeanTolerance * first.finalMean;
      }
    }
    return !this->GetAbortExecute();
  };
  // One fit at a vertex count: with the insertions when they help, else
  // again without them (the simplification to the whole target, one
  // refinement pass without the tail penalty).
  auto fitAt = [&](std::size_t target, double p0, double p1, Fit& fit) -> bool {
    const int insertions = this->Refinement ? this->InsertionsFor(target) : 0;
    // The tail penalty acts after the insertions; in a single pass only when
    // the insertions are off (RefinementInsertions 0).
    if (insertions == 0)
      return fitWith(target, 0, this->RefinementInsertions == 0 ? this->RefinementTailWeight : 0.0, p0, p1, fit);
    const double pm = p0 + 0.7 * (p1 - p0);
    if (!fitWith(target, insertions, this->RefinementTailWeight, p0, pm, fit))
      return false;
    if (fit.insertionsHelped)
    {
      this->UpdateProgress(p1);
      return true;
    }
    const bool done = fitWith(target, 0, 0.0, pm, p1, fit);
    fit.insertionsRefused = insertions;
    return done;
  };

  // The lattice as polydata: faces, then a line per feature edge.
  const bool interpolate = this->InterpolateFeatures;
  auto toPolyData = [interpolate](const Fit& fit, vtkPolyData* pd) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const auto& p : fit.lattice.points)
      points->InsertNextPoint(p.data());
    vtkNew<vtkCellArray> polys, lineCells;
    for (const auto& f : fit.lattice.faces)
    {
      std::vector<vtkIdType> ids(f.begin(), f.end());
      polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
    for (const auto& e : fit.features)
    {
      const vtkIdType ids[2] = { e.first, e.second };
      lineCells->InsertNextCell(2, ids);
    }
    pd->Initialize();
    pd->SetPoints(points);
    pd->SetPolys(polys);
    pd->SetLines(lineCells);
    // Cell order: lines, then polygons.
    vtkNew<vtkUnsignedCharArray> flag;
    flag->SetName("FeatureEdge");
    vtkNew<vtkDoubleArray> weight;
    weight->SetName("RoundingWeight");
    for (std::size_t i = 0; i < fit.features.size(); ++i)
    {
      flag->InsertNextValue(1);
      weight->InsertNextValue(fit.creases[i] ? 0.0 : 1.0);
    }
    for (std::size_t i = 0; i < fit.lattice.faces.size(); ++i)
    {
      flag->InsertNextValue(0);
      weight->InsertNextValue(1.0);
    }
    pd->GetCellData()->AddArray(flag);
    pd->GetCellData()->AddArray(weight);
    const std::vector<double> weights = surfaceVertexWeights(fit, interpolate);
    if (!weights.empty())
    {
      // Vertex weight 0: the lattice surface passes through the feature vertices.
      vtkNew<vtkDoubleArray> vw;
      vw->SetName("RoundingWeight");
      vw->SetNumberOfTuples(static_cast<vtkIdType>(weights.size()));
      for (std::size_t v = 0; v < weights.size(); ++v)
        vw->SetValue(static_cast<vtkIdType>(v), weights[v]);
      pd->GetPointData()->AddArray(vw);
    }
  };

  // Surface and Metro error of a lattice.
  vtkNew<vtkLKLatticeSurfaceFilter> surface;
  surface->SetResolution(this->ErrorResolution);
  vtkNew<vtkLKMetroFilter> metro;
  lkvtk::ProgressRelay surfaceProgress(this, surface, 0.0, 0.0);
  lkvtk::ProgressRelay metroProgress(this, metro, 0.0, 0.0);
  // The lattice surface, and with `withError` its Metro distance to the
  // input; their progress fills [p0, p1] (on a 600,000-triangle input the
  // two take most of a minute).
  auto measure = [&](vtkPolyData* latticePd, bool withError, double p0, double p1) -> bool {
    const double pm = withError ? p0 + 0.2 * (p1 - p0) : p1;
    surfaceProgress.SetRange(p0, pm);
    metroProgress.SetRange(pm, p1);
    surface->SetInputData(latticePd);
    surface->Update();
    if (surface->GetOutput()->GetNumberOfPolys() == 0)
      return false;
    if (!withError)
      return true;
    metro->SetInputData(surface->GetOutput());
    metro->SetNumberOfSamples(this->ErrorSamples > 0 ? this->ErrorSamples
                                                      : std::max<vtkIdType>(200000, 20 * input->GetNumberOfPolys()));
    metro->SetTargetData(input);
    metro->Update();
    return true;
  };

  Fit fit;
  std::vector<std::pair<std::size_t, double>> errorBoundTrials;
  try
  {
    if (!searching)
    {
      vtkIdType target = this->TargetNumberOfVertices;
      if (target == 0)
        target = static_cast<vtkIdType>(std::llround((1.0 - this->TargetReduction) * inputVertices));
      if (target >= inputVertices)
      {
        vtkErrorMacro("Cannot fit a lattice: the target of "
          << target << " vertices is not below the input's " << inputVertices << " vertices.");
        return 0;
      }
      if (this->Refinement && target - this->InsertionsFor(static_cast<std::size_t>(target)) < 4)
      {
        vtkErrorMacro("Cannot fit a lattice: " << this->InsertionsFor(static_cast<std::size_t>(target))
                                               << " insertions leave fewer than 4 of the " << target
                                               << " vertices to the simplification.");
        return 0;
      }
      if (!fitAt(static_cast<std::size_t>(target), 0.0, 0.9, fit))
      {
        lkvtk::stopRequested(this, { output, vertexMap });
        return 1;
      }
      if (fit.lattice.points.size() > static_cast<std::size_t>(target))
      {
        vtkWarningMacro("The lattice has " << fit.lattice.points.size() << " vertices, more than the target of " << target
                                           << ": every further collapse would break the manifold or its topology,"
                                              " flip or fold a face, make a sliver or remove a locked feature edge.");
      }
    }
    else
    {
      // The fewest vertices within the bound, searched over the count.
      // A set count of insertions raises the floor; the default's (1 per 100)
      // never leaves fewer than 4.
      const int setInsertions = this->Refinement ? std::max(0, this->RefinementInsertions) : 0;
      std::size_t lo = 4 + static_cast<std::size_t>(setInsertions), hi = static_cast<std::size_t>(inputVertices) - 1;
      if (lo > hi)
      {
        if (setInsertions > 0)
          vtkErrorMacro("Cannot fit a lattice: " << setInsertions << " insertions leave fewer than 4 of the " << hi
                                                 << " vertices to the simplification.");
        else
          vtkErrorMacro("Cannot fit a lattice: the input's " << inputVertices
                                                             << " vertices are too few for a lattice below them.");
        return 0;
      }
      // Each trial is a whole fit and a Metro measure; the search estimates
      // the crossing on a log-log line and stops within the count tolerance
      // (lk::fewestWithinErrorBound).
      lk::ErrorBoundSearchOptions searchOptions;
      searchOptions.countTolerance = this->MaximumErrorCountTolerance;
      Fit trial;
      vtkNew<vtkPolyData> pd;
      int step = 0;
      const lk::ErrorBoundSearchResult searched = lk::fewestWithinErrorBound(
        lo, hi, this->MaximumError, [&](std::size_t count, double& error) {
          // Each trial gets a fifth of the progress left before 0.85, so the
          // bar never runs back however many trials the search takes.
          const double p0 = 0.85 * (1.0 - std::pow(0.8, step)), p1 = 0.85 * (1.0 - std::pow(0.8, step + 1));
          ++step;
          const double pm = p0 + 0.8 * (p1 - p0);
          if (!fitAt(count, p0, pm, trial))
            return false;
          toPolyData(trial, pd);
          const bool measured = measure(pd, true, pm, p1);
          if (this->GetAbortExecute())
            return false;
          error = measured ? metro->GetHausdorffDistance() * 100.0 / metro->GetBoundingBoxDiagonal()
                           : std::numeric_limits<double>::infinity();
          // A count within the bound is always below the last one (the
          // bracket only shrinks), so `fit` ends as the search's answer.
          if (error <= this->MaximumError)
            fit = trial;
          return true;
        },
        searchOptions);
      if (searched.aborted)
      {
        lkvtk::stopRequested(this, { output, vertexMap });
        return 1;
      }
      errorBoundTrials = searched.probes;
      // When no count was within the bound, the answer is hi, not measured.
      if (!searched.withinBound)
      {
        vtkWarningMacro("No lattice of fewer than " << hi << " vertices stays within the error bound of "
                                                    << this->MaximumError << " %; the lattice keeps " << hi
                                                    << " vertices.");
        if (!fitAt(hi, 0.85, 0.9, fit))
        {
          lkvtk::stopRequested(this, { output, vertexMap });
          return 1;
        }
      }
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot fit a lattice: " << e.what() << ".");
    return 0;
  }
  if (this->LockFeatures && !fit.features.empty())
  {
    // Locked lines that take most of the vertices leave the rest of the
    // surface a handful: its error is then large (a cut piece at 226
    // vertices, 179 of them on its line: Metro mean 4 % of the diagonal).
    std::set<std::int64_t> onLines;
    for (const auto& e : fit.features)
      onLines.insert({ e.first, e.second });
    const std::size_t all = fit.lattice.points.size();
    if (3 * onLines.size() > 2 * all)
      vtkWarningMacro("The locked feature lines keep " << onLines.size() << " of the lattice's " << all
                                                       << " vertices, so the rest of the surface is fitted with "
                                                       << all - onLines.size()
                                                       << ": ask for more vertices (twice the lines' leaves it as "
                                                          "many), or let each line keep only the points it needs "
                                                          "(a feature tolerance).");
  }

  toPolyData(fit, output);
  vtkFieldData* fd = output->GetFieldData();
  fd->PassData(input->GetFieldData()); // as VTK's filters do: SPACE and the like reach the lattice
  // but not an earlier fit's report (an input fitted before, or its surface):
  // some of these are written only when this fit has them.
  for (const char* name : { "ControlVertices", "Triangles", "Quads", "FeatureEdges", "ErrorBoundTrials",
         "ErrorBoundTrialCountAndError", "RefinementInitialRMS", "RefinementFinalRMS", "RefinementIterations",
         "RefinementSamples", "RefinementInsertions", "RefinementInsertionsRefused", "BoundingBoxDiagonal",
         "Hausdorff_Max", "Hausdorff_Mean", "Hausdorff_RMS", "Hausdorff_MaxPercent", "Hausdorff_MeanPercent",
         "Hausdorff_RMSPercent", "DisplayPolygons", "Patches" })
    fd->RemoveArray(name);
  addFieldValue(fd, "ControlVertices", static_cast<double>(fit.lattice.points.size()));
  addFieldValue(fd, "Triangles", static_cast<double>(fit.lattice.faces.size() - fit.quads));
  addFieldValue(fd, "Quads", static_cast<double>(fit.quads));
  addFieldValue(fd, "FeatureEdges", static_cast<double>(fit.features.size()));
  addFieldValue(fd, "CreaseEdges", static_cast<double>(std::count(fit.creases.begin(), fit.creases.end(), 1)));
  if (searching)
  {
    // The search's trials, in order: count and Hausdorff error (%).
    addFieldValue(fd, "ErrorBoundTrials", static_cast<double>(errorBoundTrials.size()));
    vtkNew<vtkDoubleArray> trials;
    trials->SetName("ErrorBoundTrialCountAndError");
    trials->SetNumberOfComponents(2);
    for (const auto& [count, error] : errorBoundTrials)
      trials->InsertNextTuple2(static_cast<double>(count), error);
    fd->AddArray(trials);
  }
  if (this->Refinement)
  {
    addFieldValue(fd, "RefinementInitialRMS", fit.refinement.initialRms);
    addFieldValue(fd, "RefinementFinalRMS", fit.refinement.finalRms);
    addFieldValue(fd, "RefinementIterations", fit.refinement.iterations);
    addFieldValue(fd, "RefinementSamples", static_cast<double>(fit.samples));
    addFieldValue(fd, "RefinementInsertions", fit.insertions);
    addFieldValue(fd, "RefinementInsertionsRefused", fit.insertionsRefused);
  }

  vertexMap->ShallowCopy(input);
  vtkNew<vtkIdTypeArray> vertexIds;
  vertexIds->SetName("LatticeVertexId");
  for (auto v : fit.collapsedInto)
    vertexIds->InsertNextValue(static_cast<vtkIdType>(v));
  vertexMap->GetPointData()->AddArray(vertexIds);

  {
    // The face map needs the surface; the error comes with it.
    // What is left of the progress: the surface and Metro, then the map.
    const double p0 = this->GetProgress(), pMap = p0 + 0.9 * (1.0 - p0);
    const bool measured = measure(output, this->ComputeError, p0, pMap);
    if (lkvtk::stopRequested(this, { output, vertexMap }))
      return 1;
    if (!measured)
    {
      vtkErrorMacro("Cannot build the lattice surface of the fitted lattice.");
      return 0;
    }
    vtkPolyData* tess = surface->GetOutput();
    if (this->ComputeError)
    {
      vtkFieldData* mfd = metro->GetOutput()->GetFieldData();
      for (const char* name : { "BoundingBoxDiagonal", "Hausdorff_Max", "Hausdorff_Mean", "Hausdorff_RMS",
             "Hausdorff_MaxPercent", "Hausdorff_MeanPercent", "Hausdorff_RMSPercent" })
      {
        if (vtkAbstractArray* a = mfd->GetAbstractArray(name))
          fd->AddArray(a);
      }
    }
    if (vtkAbstractArray* a = tess->GetFieldData()->GetAbstractArray("DisplayPolygons"))
      fd->AddArray(a);
    lk::TriangleMesh tessMesh;
    vtkNew<vtkPolyData> tessPolys;
    tessPolys->ShallowCopy(tess);
    tessPolys->GetPointData()->Initialize();
    if (lkvtk::toTriangleMesh(tessPolys, tessMesh).empty())
    {
      const lk::ClosestPointTree tree(tessMesh);
      vtkDataArray* faceOf = tess->GetCellData()->GetArray("LatticeFaceId");
      vtkNew<vtkIdTypeArray> faceIds;
      faceIds->SetName("LatticeFaceId");
      vtkNew<vtkDoubleArray> distance;
      distance->SetName("Distance");
      lk::ClosestPointTree::Hit hint = tree.closest(mesh.points[0]);
      const std::size_t n = mesh.points.size(), chunk = std::max<std::size_t>(1, n / 20);
      for (std::size_t i = 0; i < n; ++i)
      {
        if (i % chunk == 0)
        {
          this->UpdateProgress(pMap + (1.0 - pMap) * static_cast<double>(i) / static_cast<double>(n));
          if (lkvtk::stopRequested(this, { output, vertexMap }))
            return 1;
        }
        const auto& p = mesh.points[i];
        hint = tree.closest(p, hint);
        faceIds->InsertNextValue(faceOf ? static_cast<vtkIdType>(faceOf->GetComponent(hint.face, 0)) : -1);
        distance->InsertNextValue(hint.distance);
      }
      vertexMap->GetPointData()->AddArray(faceIds);
      vertexMap->GetPointData()->AddArray(distance);
    }
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKLatticeFitFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetNumberOfVertices: " << this->TargetNumberOfVertices << "\n";
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "MaximumErrorCountTolerance: " << this->MaximumErrorCountTolerance << "\n";
  os << indent << "FeatureWeight: " << this->FeatureWeight << "\n";
  os << indent << "FeatureNeighbourWeight: " << this->FeatureNeighbourWeight << "\n";
  os << indent << "FeatureTolerance: " << this->FeatureTolerance << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "LockFeatures: " << this->LockFeatures << "\n";
  os << indent << "InterpolateFeatures: " << this->InterpolateFeatures << "\n";
  os << indent << "RoundedSurfaceQuadrics: " << this->RoundedSurfaceQuadrics << "\n";
  os << indent << "QuadPairing: " << this->QuadPairing << "\n";
  os << indent << "RightAngleTolerance: " << this->RightAngleTolerance << "\n";
  os << indent << "AngleSumTolerance: " << this->AngleSumTolerance << "\n";
  os << indent << "MaximumDihedralAngle: " << this->MaximumDihedralAngle << "\n";
  os << indent << "Refinement: " << this->Refinement << "\n";
  os << indent << "RefinementIterations: " << this->RefinementIterations << "\n";
  os << indent << "RefinementTailWeight: " << this->RefinementTailWeight << "\n";
  os << indent << "RefinementTailThreshold: " << this->RefinementTailThreshold << "\n";
  os << indent << "RefinementInsertions: " << this->RefinementInsertions
     << (this->RefinementInsertions < 0 ? " (1 per 100 target vertices)" : "") << "\n";
  os << indent << "ComputeError: " << this->ComputeError << "\n";
  os << indent << "ErrorResolution: " << this->ErrorResolution << "\n";
  os << indent << "ErrorSamples: " << this->ErrorSamples << (this->ErrorSamples == 0 ? " (20 per input triangle, at least 200,000)" : "")
     << "\n";
}
