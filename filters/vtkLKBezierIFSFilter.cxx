#include "vtkLKBezierIFSFilter.h"
#include "vtkLKAbort.h"
#include "vtkLKMemory.h"

#include "latticekit/BezierIFS.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <map>
#include <string>

vtkStandardNewMacro(vtkLKBezierIFSFilter);

void vtkLKBezierIFSFilter::SetSplitParameter(double t)
{
  this->RefusedNumberOfMaps = 0;
  this->Breaks = { t };
  this->Modified();
}

void vtkLKBezierIFSFilter::SetNumberOfMaps(int k)
{
  this->Breaks.clear();
  // Not k - 1 breaks for any k: 2^31 - 1 would take 17 GB here already.
  this->RefusedNumberOfMaps = k < 2 || static_cast<std::size_t>(k) > lk::kMaximumIfsMaps ? k : 0;
  for (int i = 1; i < k && this->RefusedNumberOfMaps == 0; ++i)
    this->Breaks.push_back(double(i) / k);
  this->Modified();
}

void vtkLKBezierIFSFilter::SetBreakPoints(vtkDoubleArray* breaks)
{
  this->RefusedNumberOfMaps = 0;
  this->Breaks.clear();
  for (vtkIdType i = 0; breaks && i < breaks->GetNumberOfTuples(); ++i)
    this->Breaks.push_back(breaks->GetValue(i));
  this->Modified();
}

void vtkLKBezierIFSFilter::SetProbabilities(vtkDoubleArray* p)
{
  this->Probabilities.clear();
  for (vtkIdType i = 0; p && i < p->GetNumberOfTuples(); ++i)
    this->Probabilities.push_back(p->GetValue(i));
  this->Modified();
}

int vtkLKBezierIFSFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkLKBezierIFSFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const vtkIdType np = input ? input->GetNumberOfPoints() : 0;
  if (this->RefusedNumberOfMaps != 0)
  {
    vtkErrorMacro("NumberOfMaps must be from 2 to " << lk::kMaximumIfsMaps << ", not " << this->RefusedNumberOfMaps
                                                    << ".");
    return 0;
  }
  std::vector<lk::Vec3> control;
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      vtkErrorMacro("Control point " << i << " is not finite.");
      return 0;
    }
    control.emplace_back(p[0], p[1], p[2]);
  }

  std::vector<lk::IfsMap> maps;
  std::vector<Eigen::VectorXd> base;
  std::vector<std::array<double, 2>> baseParams;
  std::vector<lk::Vec3> plotControl = control;
  const bool surface = this->Shape == SURFACE;
  try
  {
    if (this->Shape == CURVE)
    {
      if (np < 2)
        throw std::invalid_argument("a curve needs at least 2 control points, the input has " + std::to_string(np));
      const int n = static_cast<int>(np) - 1;
      maps = lk::bernsteinCurveMaps(n, this->Breaks);
      base = { lk::bernsteinCurve(n, 0.0), lk::bernsteinCurve(n, 1.0) };
      baseParams = { { 0, 0 }, { 1, 0 } };
    }
    else if (surface)
    {
      const int nu = this->NetDimensions[0], nv = this->NetDimensions[1];
      if (nu < 2 || nv < 2 || static_cast<vtkIdType>(nu) * nv != np)
        throw std::invalid_argument("the control net must hold NetDimensions " + std::to_string(nu) + " x " +
          std::to_string(nv) + " points (at least 2 x 2); the input has " + std::to_string(np));
      maps = lk::bernsteinSurfaceMaps(nu - 1, nv - 1, this->Breaks);
      baseParams = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
      for (const auto& p : baseParams)
        base.push_back(lk::bernsteinSurface(nu - 1, nv - 1, p[0], p[1]));
    }
    else
    {
      if (this->Breaks.size() != 1)
        throw std::invalid_argument("the direct quadratic IFS has two maps: give one split parameter");
      maps = lk::quadraticPlanarMaps(control, this->Breaks[0]);
      Eigen::VectorXd a(3), b(3);
      a << control.front().x(), control.front().y(), control.front().z();
      b << control.back().x(), control.back().y(), control.back().z();
      base = { a, b };
      baseParams = { { 0, 0 }, { 1, 0 } };
      plotControl.clear();
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot build the IFS: " << e.what() << ".");
    return 0;
  }

  if (this->Algorithm == CHAOS_GAME)
  {
    // About 120 bytes a point: the core's position and parameter, then the
    // output's point, parameter and vertex cell.
    std::string tooLarge;
    if (lkvtk::exceedsMemory(120.0 * static_cast<double>(this->NumberOfPoints), tooLarge))
    {
      vtkErrorMacro("Cannot draw the IFS: " << this->NumberOfPoints << " points would take " << tooLarge
                                            << "; ask for fewer (NumberOfPoints).");
      return 0;
    }
  }
  lk::IfsPoints pts;
  try
  {
    if (this->Algorithm == DETERMINISTIC)
      pts = lk::deterministicIfs(maps, base, baseParams, this->Depth, plotControl);
    else
    {
      std::vector<double> p = this->Probabilities;
      if (p.empty())
        p.assign(maps.size(), 1.0 / static_cast<double>(maps.size()));
      pts = lk::chaosGame(maps, p, base[0], baseParams[0], static_cast<std::size_t>(this->NumberOfPoints),
        static_cast<std::uint64_t>(this->RandomSeed), plotControl);
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot draw the IFS: " << e.what() << ".");
    return 0;
  }
  this->UpdateProgress(0.8);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> param;
  param->SetName("Parameter");
  param->SetNumberOfComponents(surface ? 2 : 1);
  vtkNew<vtkCellArray> cells;
  auto addPoint = [&](std::size_t i) {
    const vtkIdType id = points->InsertNextPoint(pts.points[i].data());
    param->InsertNextTuple(pts.parameters[i].data());
    return id;
  };
  if (this->Algorithm == DETERMINISTIC && !surface)
  {
    // Leaves in parameter order: the polyline through every leaf's start and the last end.
    const std::size_t leaves = pts.points.size() / 2;
    cells->InsertNextCell(static_cast<vtkIdType>(leaves + 1));
    for (std::size_t l = 0; l < leaves; ++l)
      cells->InsertCellPoint(addPoint(2 * l));
    cells->InsertCellPoint(addPoint(2 * leaves - 1));
    output->SetLines(cells);
  }
  else if (this->Algorithm == DETERMINISTIC)
  {
    // One quad per leaf; corners shared by parameter (rounded to 1e-9).
    std::map<std::pair<long long, long long>, vtkIdType> ids;
    for (std::size_t l = 0; l < pts.points.size() / 4; ++l)
    {
      vtkIdType quad[4];
      for (int k = 0; k < 4; ++k)
      {
        const std::size_t i = 4 * l + static_cast<std::size_t>(k);
        const auto key = std::make_pair(std::llround(pts.parameters[i][0] * 1e9), std::llround(pts.parameters[i][1] * 1e9));
        auto it = ids.find(key);
        quad[k] = it != ids.end() ? it->second : (ids[key] = addPoint(i));
      }
      cells->InsertNextCell(4, quad);
    }
    output->SetPolys(cells);
  }
  else
  {
    const int bins = this->DensityBins;
    const std::size_t total = surface ? std::size_t(bins) * bins : std::size_t(bins);
    std::vector<double> counts(total, 0.0);
    auto bin = [&](std::size_t i) {
      const auto bu = std::min<std::size_t>(bins - 1, static_cast<std::size_t>(pts.parameters[i][0] * bins));
      const auto bv = std::min<std::size_t>(bins - 1, static_cast<std::size_t>(pts.parameters[i][1] * bins));
      return surface ? bu * bins + bv : bu;
    };
    for (std::size_t i = 0; i < pts.points.size(); ++i)
      counts[bin(i)] += 1.0;
    const double mean = static_cast<double>(pts.points.size()) / static_cast<double>(total);
    vtkNew<vtkDoubleArray> density;
    density->SetName("HitDensity");
    for (std::size_t i = 0; i < pts.points.size(); ++i)
    {
      const vtkIdType id = addPoint(i);
      cells->InsertNextCell(1, &id);
      density->InsertNextValue(counts[bin(i)] / mean);
    }
    output->SetVerts(cells);
    output->GetPointData()->AddArray(density);
  }
  output->SetPoints(points);
  output->GetPointData()->AddArray(param);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKBezierIFSFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shape: " << this->Shape << "\n";
  os << indent << "Algorithm: " << this->Algorithm << "\n";
  os << indent << "NetDimensions: " << this->NetDimensions[0] << " x " << this->NetDimensions[1] << "\n";
  os << indent << "Breaks:";
  for (double b : this->Breaks)
    os << " " << b;
  os << "\n" << indent << "Depth: " << this->Depth << ", NumberOfPoints: " << this->NumberOfPoints
     << ", RandomSeed: " << this->RandomSeed << ", DensityBins: " << this->DensityBins << "\n";
}
