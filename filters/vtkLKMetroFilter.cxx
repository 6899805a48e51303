#include "vtkLKMetroFilter.h"
#include "vtkLKFieldValues.h"
#include "vtkLKAbort.h"

#include "latticekit/ClosestPointTree.h"
#include "latticekit/DistanceStatistics.h"
#include "latticekit/SurfaceSampling.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLKMetroFilter);

namespace
{
/// The most samples one direction measures: at about a million closest-point
/// queries a second, a quarter of an hour. More is a typo (an extra digit or
/// ten), not a finer measure.
constexpr std::size_t kMaxSamples = 1000000000;

void addValue(vtkFieldData* fd, const std::string& name, double value)
{
  lkvtk::addFieldValue(fd, name.c_str(), value);
}

void addStatistics(
  vtkFieldData* fd, const std::string& prefix, const lk::DistanceStatistics& s, double diagonal)
{
  const double pct = diagonal > 0.0 ? 100.0 / diagonal : 0.0;
  addValue(fd, prefix + "_Max", s.max);
  addValue(fd, prefix + "_Mean", s.mean);
  addValue(fd, prefix + "_RMS", s.rms);
  addValue(fd, prefix + "_MaxPercent", s.max * pct);
  addValue(fd, prefix + "_MeanPercent", s.mean * pct);
  addValue(fd, prefix + "_RMSPercent", s.rms * pct);
  addValue(fd, prefix + "_Samples", static_cast<double>(s.samples()));
}

void addSampleCounts(vtkFieldData* fd, const std::string& prefix, const lk::DistanceStatistics& s)
{
  addValue(fd, prefix + "_VertexSamples", static_cast<double>(s.vertexSamples));
  addValue(fd, prefix + "_EdgeSamples", static_cast<double>(s.edgeSamples));
  addValue(fd, prefix + "_FaceSamples", static_cast<double>(s.faceSamples));
}
} // namespace

vtkLKMetroFilter::vtkLKMetroFilter()
{
  this->SetNumberOfInputPorts(2);
}

void vtkLKMetroFilter::SetTargetConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkLKMetroFilter::SetTargetData(vtkPolyData* pd)
{
  this->SetInputData(1, pd);
}

int vtkLKMetroFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  (void)port;
  return 1;
}

void vtkLKMetroFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "SampleDensity: " << this->SampleDensity << "\n";
  os << indent << "VertexSampling: " << this->VertexSampling << "\n";
  os << indent << "EdgeSampling: " << this->EdgeSampling << "\n";
  os << indent << "FaceSampling: " << this->FaceSampling << "\n";
  os << indent << "FaceSamplingMethod: "
     << (this->FaceSamplingMethod == MONTE_CARLO ? "MonteCarlo" : "SimilarTriangles") << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "Symmetric: " << this->Symmetric << "\n";
  os << indent << "MeanOverAllSamples: " << this->MeanOverAllSamples << "\n";
  os << indent << "ColorMaximum: " << this->ColorMaximum << "\n";
}

int vtkLKMetroFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* inputA = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* inputB = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  std::fill(std::begin(this->Results), std::end(this->Results), 0.0);
  this->SampleCounts[0] = this->SampleCounts[1] = 0;
  if (!inputB)
  {
    vtkErrorMacro("Mesh B (input 1) is missing: call SetTargetConnection or SetTargetData.");
    return 0;
  }
  if (!this->VertexSampling && !this->EdgeSampling && !this->FaceSampling)
  {
    vtkErrorMacro("Every kind of sampling is off: turn on vertex, edge or face sampling.");
    return 0;
  }
  // NaN passes SetColorMaximum's clamp (which turns infinity into the largest double).
  if (!std::isfinite(this->ColorMaximum))
  {
    vtkErrorMacro("ColorMaximum must be a finite distance (0: the 99th percentile), not " << this->ColorMaximum << ".");
    return 0;
  }
  if (!(this->SampleDensity >= 0.0) || !std::isfinite(this->SampleDensity))
  {
    vtkErrorMacro("SampleDensity must be a finite number >= 0, not " << this->SampleDensity << ".");
    return 0;
  }
  lk::TriangleMesh meshA, meshB;
  std::string problem = lkvtk::toTriangleMesh(inputA, meshA);
  if (!problem.empty())
  {
    vtkErrorMacro("Mesh A (input 0): " << problem << ".");
    return 0;
  }
  problem = lkvtk::toTriangleMesh(inputB, meshB);
  if (!problem.empty())
  {
    vtkErrorMacro("Mesh B (input 1): " << problem << ".");
    return 0;
  }
  const double areaA = lk::surfaceArea(meshA);
  const double areaB = lk::surfaceArea(meshB);
  if (!(areaA > 0.0) || !(areaB > 0.0))
  {
    vtkErrorMacro("Mesh " << (areaA > 0.0 ? "B" : "A")
                          << " has zero area: every triangle is degenerate.");
    return 0;
  }
  const lk::Box3 boxA = lk::boundingBox(meshA), boxB = lk::boundingBox(meshB);
  lk::Box3 box = boxA;
  box.extend(boxB);
  const double diagonal = box.diagonal();
  {
    // Two approximations of one surface overlap and are of one size. Meshes
    // far apart, or ten times apart in size, are most often one surface in two
    // coordinate systems (an untagged RAS file beside an LPS one, metres
    // beside millimetres), and the distances would measure that.
    const double dA = boxA.diagonal(), dB = boxB.diagonal();
    // The gap between the boxes along the axis where it is widest (0 where
    // they overlap); half the larger mesh's size is no approximation's.
    const double gap = std::max((boxB.min - boxA.max).maxCoeff(), (boxA.min - boxB.max).maxCoeff());
    const bool apart = gap > 0.5 * std::max(dA, dB);
    const double ratio = std::max(dA, dB) / std::max(std::min(dA, dB), 1e-300);
    if (apart || (this->Symmetric && ratio > 10.0))
    {
      auto range = [](const lk::Box3& b) {
        std::ostringstream os;
        os.precision(4);
        os << "x " << b.min.x() << " to " << b.max.x() << ", y " << b.min.y() << " to " << b.max.y() << ", z "
           << b.min.z() << " to " << b.max.z();
        return os.str();
      };
      const std::string how =
        apart ? "lie far apart" : "differ in size " + std::to_string(static_cast<long long>(ratio)) + "-fold";
      vtkWarningMacro("Mesh A (" << range(boxA) << ") and mesh B (" << range(boxB) << ") " << how
                                 << ": if they are one surface in two coordinate systems (LPS and RAS, millimetres "
                                    "and metres), the distances measure that, not the approximation.");
    }
  }

  lk::SamplingOptions options;
  options.vertexSamples = this->VertexSampling;
  options.edgeSamples = this->EdgeSampling;
  options.faceSamples = this->FaceSampling;
  options.method = this->FaceSamplingMethod == MONTE_CARLO ? lk::FaceSamplingMethod::MonteCarlo
                                                           : lk::FaceSamplingMethod::SimilarTriangles;
  options.seed = static_cast<std::uint64_t>(this->RandomSeed);
  const std::size_t target = this->NumberOfSamples > 0
    ? static_cast<std::size_t>(this->NumberOfSamples)
    : lk::defaultSampleCount(meshA.triangles.size(), meshB.triangles.size());

  const int directions = this->Symmetric ? 2 : 1;
  // Progress: building the trees 10 %, then the sampled directions.
  const double treeShare = 0.1;
  lk::DistanceStatistics stats[2];
  std::vector<double> pointDistance(meshA.points.size(), 0.0);
  for (int dir = 0; dir < directions; ++dir)
  {
    const lk::TriangleMesh& sampled = dir == 0 ? meshA : meshB;
    const lk::TriangleMesh& reference = dir == 0 ? meshB : meshA;
    const double area = dir == 0 ? areaA : areaB;
    options.density = this->SampleDensity > 0.0 ? this->SampleDensity
                                                : static_cast<double>(target) / area;
    const lk::ClosestPointTree tree(reference);
    const double base = treeShare + (1.0 - treeShare) * dir / directions;
    this->UpdateProgress(base);
    const lk::SamplingPlan plan = lk::planSampling(sampled, options);
    // The samples are measured a block at a time (the memory of one block,
    // not of all: a skull's 11 million samples each way took 1.4 GB), so
    // what bounds their number is the time the closest-point queries take.
    if (plan.total > kMaxSamples)
    {
      vtkErrorMacro("Mesh " << (dir == 0 ? "A" : "B") << " would take " << plan.total
                            << " samples, more than the " << kMaxSamples
                            << " one run measures (hours of closest-point queries): ask for fewer "
                               "(NumberOfSamples, SampleDensity).");
      return 0;
    }
    // About 20 blocks a direction, so that progress and a stop stay
    // responsive, of a million samples (about 50 MB with their distances) at most.
    const std::size_t blockSize = std::clamp<std::size_t>(plan.total / 20 + 1, 4096, 1u << 20);
    const std::vector<lk::SampleBlock> blocks = lk::sampleBlocks(plan, blockSize);
    lk::SampleSet samples;
    std::vector<double> distance;
    lk::DistanceAccumulator sums;
    for (const lk::SampleBlock& block : blocks)
    {
      try
      {
        lk::allocateSamples(block, samples);
        distance.resize(block.count);
      }
      catch (const std::bad_alloc&)
      {
        vtkErrorMacro("Out of memory for a block of " << block.count << " samples of mesh " << (dir == 0 ? "A" : "B")
                                                      << ": ask for fewer (NumberOfSamples, SampleDensity).");
        return 0;
      }
      vtkSMPTools::For(static_cast<vtkIdType>(block.begin), static_cast<vtkIdType>(block.end), 4096,
        [&](vtkIdType b, vtkIdType e) {
          lk::fillBlockSamples(
            sampled, plan, options, block, static_cast<std::size_t>(b), static_cast<std::size_t>(e), samples);
        });
      // The SMP grain keeps neighbouring samples together, so that the
      // closest-point hints stay coherent.
      vtkSMPTools::For(0, static_cast<vtkIdType>(block.count), 2048, [&](vtkIdType begin, vtkIdType end) {
        tree.distances(samples, static_cast<std::size_t>(begin), static_cast<std::size_t>(end), distance.data());
      });
      sums.add(samples, distance.data());
      this->UpdateProgress(base +
        (1.0 - treeShare) / directions * static_cast<double>(block.first + block.count) /
          static_cast<double>(plan.total));
      if (lkvtk::stopRequested(this, { output }))
      {
        return 1;
      }
    }
    stats[dir] = sums.result(this->MeanOverAllSamples);
    this->SampleCounts[dir] = static_cast<vtkIdType>(stats[dir].samples());

    if (dir == 0)
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(meshA.points.size()), 2048,
        [&](vtkIdType begin, vtkIdType end) {
          lk::ClosestPointTree::Hit hint;
          for (vtkIdType i = begin; i < end; ++i)
          {
            hint = tree.closest(meshA.points[static_cast<std::size_t>(i)], hint);
            pointDistance[static_cast<std::size_t>(i)] = hint.distance;
          }
        });
    }
  }
  if (directions == 1)
  {
    stats[1] = stats[0];
  }
  const lk::DistanceStatistics sym =
    this->Symmetric ? lk::symmetricStatistics(stats[0], stats[1]) : stats[0];

  output->ShallowCopy(inputA);
  vtkNew<vtkDoubleArray> dist;
  dist->SetName("Distance");
  dist->SetNumberOfValues(static_cast<vtkIdType>(pointDistance.size()));
  double maxPoint = 0.0;
  for (std::size_t i = 0; i < pointDistance.size(); ++i)
  {
    dist->SetValue(static_cast<vtkIdType>(i), pointDistance[i]);
    maxPoint = std::max(maxPoint, pointDistance[i]);
  }
  output->GetPointData()->AddArray(dist);
  output->GetPointData()->SetActiveScalars("Distance");

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0); // blue (small) to red (large)
  double colorMax = this->ColorMaximum;
  if (!(colorMax > 0.0) && !pointDistance.empty())
  {
    // The 99th percentile: a few outliers must not turn the whole map blue.
    std::vector<double> sorted(pointDistance);
    const std::size_t k = std::min(sorted.size() - 1, (sorted.size() * 99) / 100);
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    colorMax = sorted[k] > 0.0 ? sorted[k] : maxPoint;
  }
  this->EffectiveColorMaximum = colorMax;
  lut->SetTableRange(0.0, colorMax > 0.0 ? colorMax : 1.0);
  lut->Build();
  vtkSmartPointer<vtkUnsignedCharArray> colors;
  colors.TakeReference(lut->MapScalars(dist, VTK_COLOR_MODE_MAP_SCALARS, 0, VTK_RGB));
  colors->SetName("DistanceColors");
  output->GetPointData()->AddArray(colors);

  vtkFieldData* fd = output->GetFieldData();
  // Mesh A's field data passes on, but not an earlier Metro report of it (a
  // coloured mesh measured again): without Symmetric, its B-to-A numbers
  // would stand beside this run's as if they were this run's.
  for (int a = fd->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    const char* name = fd->GetAbstractArray(a) ? fd->GetAbstractArray(a)->GetName() : nullptr;
    const std::string n = name ? name : "";
    if (n.rfind("AtoB_", 0) == 0 || n.rfind("BtoA_", 0) == 0)
      fd->RemoveArray(a);
  }
  addValue(fd, "BoundingBoxDiagonal", diagonal);
  addStatistics(fd, "AtoB", stats[0], diagonal);
  addSampleCounts(fd, "AtoB", stats[0]);
  if (this->Symmetric)
  {
    addStatistics(fd, "BtoA", stats[1], diagonal);
    addSampleCounts(fd, "BtoA", stats[1]);
  }
  addStatistics(fd, "Hausdorff", sym, diagonal);

  this->Results[0] = diagonal;
  this->Results[1] = stats[0].max;
  this->Results[2] = stats[0].mean;
  this->Results[3] = stats[0].rms;
  this->Results[4] = stats[1].max;
  this->Results[5] = stats[1].mean;
  this->Results[6] = stats[1].rms;
  this->Results[7] = sym.max;
  this->Results[8] = sym.mean;
  this->Results[9] = sym.rms;
  this->UpdateProgress(1.0);
  return 1;
}
