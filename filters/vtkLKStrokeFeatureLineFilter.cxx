#include "vtkLKStrokeFeatureLineFilter.h"
#include "vtkLKAbort.h"

#include "latticekit/StrokeFeatureLine.h"
#include "vtkLKMeshPointIds.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKSurfaceAttributes.h"

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkMatrix4x4.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkOBBTree.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

vtkStandardNewMacro(vtkLKStrokeFeatureLineFilter);

vtkLKStrokeFeatureLineFilter::vtkLKStrokeFeatureLineFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->PickedStroke = vtkPolyData::New();
}

vtkLKStrokeFeatureLineFilter::~vtkLKStrokeFeatureLineFilter()
{
  this->SetCamera(nullptr);
  this->PickedStroke->Delete();
}

vtkCxxSetObjectMacro(vtkLKStrokeFeatureLineFilter, Camera, vtkCamera);

vtkMTimeType vtkLKStrokeFeatureLineFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Camera)
    t = std::max(t, this->Camera->GetMTime());
  return t;
}

vtkPolyData* vtkLKStrokeFeatureLineFilter::GetPickedStroke()
{
  return this->PickedStroke;
}

namespace
{
/// Display points (pixels) to the nearest visible surface points along the
/// rays from the eye; rays that miss are skipped.
std::vector<lk::Vec3> pickOnSurface(
  vtkPolyData* mesh, vtkCamera* camera, const int size[2], const std::vector<lk::Vec3>& display)
{
  const double aspect = static_cast<double>(size[0]) / static_cast<double>(size[1]);
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0));
  toWorld->Invert();
  auto unproject = [&](double x, double y, double z, double out[3]) {
    const double in[4] = { x, y, z, 1.0 };
    double w[4];
    toWorld->MultiplyPoint(in, w);
    for (int i = 0; i < 3; ++i)
      out[i] = w[i] / w[3];
  };
  vtkNew<vtkOBBTree> locator;
  locator->SetDataSet(mesh);
  locator->BuildLocator();
  double bounds[6];
  mesh->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const lk::Vec3 centre(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  std::vector<lk::Vec3> picked;
  vtkNew<vtkIdList> cells;
  vtkNew<vtkPoints> hits;
  for (const lk::Vec3& d : display)
  {
    const double x = 2.0 * d.x() / size[0] - 1.0, y = 2.0 * d.y() / size[1] - 1.0;
    double nearPoint[3], farPoint[3];
    unproject(x, y, -1.0, nearPoint);
    unproject(x, y, 1.0, farPoint);
    // Past the far clipping plane too: the ray runs until it has left the mesh's box.
    const lk::Vec3 a(nearPoint[0], nearPoint[1], nearPoint[2]), f(farPoint[0], farPoint[1], farPoint[2]);
    const lk::Vec3 dir = (f - a).normalized();
    const lk::Vec3 b = a + dir * ((centre - a).norm() + diagonal);
    // The first hit along the ray: all hits of the OBB tree, the nearest
    // kept. (vtkCellLocator's IntersectWithLine and FindCellsAlongLine in
    // VTK 9.1 can miss the front cells and return a hit on the far side.)
    hits->Reset();
    cells->Reset();
    locator->IntersectWithLine(a.data(), b.data(), hits, cells);
    double bestT = VTK_DOUBLE_MAX, best[3] = { 0, 0, 0 };
    for (vtkIdType k = 0; k < hits->GetNumberOfPoints(); ++k)
    {
      double hit[3];
      hits->GetPoint(k, hit);
      const double t = (lk::Vec3(hit[0], hit[1], hit[2]) - a).norm();
      if (t < bestT)
      {
        bestT = t;
        std::copy(hit, hit + 3, best);
      }
    }
    if (bestT < VTK_DOUBLE_MAX)
      picked.emplace_back(best[0], best[1], best[2]);
  }
  return picked;
}
} // namespace

void vtkLKStrokeFeatureLineFilter::SetStrokeConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkLKStrokeFeatureLineFilter::SetStrokeData(vtkPolyData* stroke)
{
  this->SetInputData(1, stroke);
}

vtkPolyData* vtkLKStrokeFeatureLineFilter::GetFeatureLineOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkLKStrokeFeatureLineFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkLKStrokeFeatureLineFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* strokePd = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* lineOut = vtkPolyData::GetData(outputVector, 1);
  // NaN passes the setters' clamps (which turn infinity into the largest
  // double), and would be taken as 0, the automatic length.
  if (!std::isfinite(this->BrushRadius) || !std::isfinite(this->CloseTolerance))
  {
    vtkErrorMacro("BrushRadius and CloseTolerance must be finite lengths (0: from the mean edge length), not "
      << this->BrushRadius << " and " << this->CloseTolerance << ".");
    return 0;
  }

  // Line cells on the input are earlier feature lines (output 0 of another
  // stroke): they are carried to output 0, through the edges a split cuts.
  std::vector<std::vector<std::int64_t>> earlierLines;
  vtkSmartPointer<vtkPolyData> faces = input;
  if (input && input->GetNumberOfLines() > 0)
  {
    auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      earlierLines.emplace_back(ids, ids + n);
    }
    faces = vtkSmartPointer<vtkPolyData>::New();
    faces->ShallowCopy(input);
    vtkNew<vtkCellArray> none;
    faces->SetLines(none);
  }
  this->InputPoints = input ? input->GetNumberOfPoints() : 0;
  lk::TriangleMesh mesh;
  std::string problem = lkvtk::toTriangleMesh(faces, mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot make a feature line: " << problem << ".");
    return 0;
  }
  std::vector<lk::Vec3> stroke;
  if (strokePd && strokePd->GetNumberOfLines() > 0)
  {
    auto it = vtk::TakeSmartPointer(strokePd->GetLines()->NewIterator());
    it->GoToFirstCell();
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      double p[3];
      strokePd->GetPoint(ids[k], p);
      stroke.emplace_back(p[0], p[1], p[2]);
    }
  }
  else if (strokePd)
  {
    for (vtkIdType i = 0; i < strokePd->GetNumberOfPoints(); ++i)
    {
      double p[3];
      strokePd->GetPoint(i, p);
      stroke.emplace_back(p[0], p[1], p[2]);
    }
  }
  if (this->Camera)
  {
    if (this->ViewportSize[0] <= 0 || this->ViewportSize[1] <= 0)
    {
      vtkErrorMacro("Cannot make a feature line: a screen stroke needs the viewport size (SetViewportSize).");
      return 0;
    }
    const std::size_t given = stroke.size();
    stroke = pickOnSurface(input, this->Camera, this->ViewportSize, stroke);
    if (stroke.size() < 2 && given >= 2)
    {
      vtkErrorMacro("Cannot make a feature line: the stroke misses the surface (" << stroke.size() << " of " << given
                                                                                   << " screen points hit it).");
      return 0;
    }
    if (stroke.size() < given)
      vtkWarningMacro(<< given - stroke.size() << " of " << given << " screen points missed the surface and were skipped.");
  }
  {
    vtkNew<vtkPoints> picked;
    picked->SetDataTypeToDouble();
    vtkNew<vtkCellArray> line;
    for (const auto& p : stroke)
      picked->InsertNextPoint(p.data());
    if (stroke.size() >= 2) // a line cell needs two points (a shorter stroke is refused below)
    {
      line->InsertNextCell(static_cast<vtkIdType>(stroke.size()));
      for (vtkIdType i = 0; i < static_cast<vtkIdType>(stroke.size()); ++i)
        line->InsertCellPoint(i);
    }
    this->PickedStroke->Initialize();
    this->PickedStroke->SetPoints(picked);
    this->PickedStroke->SetLines(line);
  }
  lk::StrokeOptions o;
  o.mode = this->Mode == PAINT ? lk::StrokeMode::Paint
    : this->Mode == SNAP       ? lk::StrokeMode::Snap
    : this->Mode == SPLIT      ? lk::StrokeMode::Split
                               : lk::StrokeMode::NearestEdges;
  o.brushRadius = this->BrushRadius;
  o.closeTolerance = this->CloseTolerance;
  lk::StrokeResult r;
  try
  {
    r = lk::strokeToFeatureLine(mesh, stroke, o);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot make a feature line: " << e.what() << ".");
    return 0;
  }
  this->UpdateProgress(0.8);
  if (lkvtk::stopRequested(this, { output, lineOut }))
    return 1;

  std::map<std::int64_t, double> gapOf;
  for (std::size_t i = 0; i < r.snapGaps.size(); ++i)
    if (r.snapGaps[i] > 0.0)
      gapOf[r.movedVertices[i]] = r.snapGaps[i];
  if (!gapOf.empty())
  {
    double largest = 0.0;
    for (const auto& vg : gapOf)
      largest = std::max(largest, vg.second);
    char upTo[32];
    std::snprintf(upTo, sizeof upTo, "%.3g", largest);
    vtkWarningMacro(<< gapOf.size() << " of " << r.movedVertices.size()
                    << " line vertices stop short of the stroke, by up to " << upTo
                    << ": snapping them onto it would fold the triangles around them (point data StrokeGap of "
                       "output 1). The split mode puts the line on the stroke exactly.");
  }

  vtkSmartPointer<vtkPolyData> result = lkvtk::fromTriangleMesh(r.mesh);
  output->SetPoints(result->GetPoints());
  vtkNew<vtkCellArray> lines;
  for (const auto& line : lk::carryLines(r.mesh, mesh.points.size(), earlierLines))
  {
    lines->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (const auto v : line)
      lines->InsertCellPoint(static_cast<vtkIdType>(v));
  }
  for (const auto& e : r.featureEdges)
  {
    const vtkIdType ids[2] = { e.first, e.second };
    lines->InsertNextCell(2, ids);
  }
  output->SetLines(lines);
  output->SetPolys(result->GetPolys());
  {
    // The input's attributes: its points keep their ids, a split's new points
    // are interpolated in the triangle they lie in, and each triangle takes
    // the data of the input triangle it is or lies in; the line cells get the
    // null value.
    std::vector<vtkIdType> pointSource(r.mesh.points.size(), -1);
    for (std::size_t p = 0; p < mesh.points.size(); ++p)
      pointSource[p] = static_cast<vtkIdType>(p);
    std::vector<vtkIdType> cellOf(mesh.triangles.size());
    for (std::size_t t = 0; t < cellOf.size(); ++t)
      cellOf[t] = input->GetNumberOfLines() + static_cast<vtkIdType>(t);
    // Paint and nearest edges leave the surface as it was: its normals hold.
    const bool unchanged = r.mesh.points.size() == mesh.points.size() && r.movedVertices.empty();
    lkvtk::carrySurfaceAttributes(input, faces, cellOf, pointSource, {}, output, unchanged);
  }
  vtkNew<vtkUnsignedCharArray> flag;
  flag->SetName("FeatureEdge");
  for (vtkIdType i = 0; i < lines->GetNumberOfCells(); ++i)
    flag->InsertNextValue(1);
  for (std::size_t i = 0; i < r.mesh.triangles.size(); ++i)
    flag->InsertNextValue(0);
  output->GetCellData()->AddArray(flag);

  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> meshIds;
  meshIds->SetName("MeshPointId");
  vtkNew<vtkCellArray> cells;
  auto add = [&](std::int64_t v) {
    meshIds->InsertNextValue(static_cast<vtkIdType>(v));
    return pts->InsertNextPoint(r.mesh.points[static_cast<std::size_t>(v)].data());
  };
  if (!r.line.empty())
  {
    cells->InsertNextCell(static_cast<vtkIdType>(r.line.size()));
    for (auto v : r.line)
      cells->InsertCellPoint(add(v));
  }
  else
  {
    for (const auto& e : r.featureEdges)
    {
      const vtkIdType ids[2] = { add(e.first), add(e.second) };
      cells->InsertNextCell(2, ids);
    }
  }
  lineOut->SetPoints(pts);
  lineOut->SetLines(cells);
  lineOut->GetPointData()->AddArray(meshIds);
  if (this->Mode == SNAP)
  {
    // How far each line vertex is left from the stroke (0: on it).
    vtkNew<vtkDoubleArray> gap;
    gap->SetName("StrokeGap");
    for (vtkIdType i = 0; i < meshIds->GetNumberOfTuples(); ++i)
    {
      const auto it = gapOf.find(meshIds->GetValue(i));
      gap->InsertNextValue(it == gapOf.end() ? 0.0 : it->second);
    }
    lineOut->GetPointData()->AddArray(gap);
  }
  vtkNew<vtkDoubleArray> closed;
  closed->SetName("Closed");
  closed->InsertNextValue(r.closed ? 1.0 : 0.0);
  lineOut->GetFieldData()->AddArray(closed);
  output->GetFieldData()->AddArray(closed);
  this->UpdateProgress(1.0);
  return 1;
}

int vtkLKStrokeFeatureLineFilter::CarryLine(vtkPolyData* line, vtkPolyData* carried)
{
  vtkPolyData* output = this->GetOutput();
  vtkDataArray* ids = line ? line->GetPointData()->GetArray("MeshPointId") : nullptr;
  if (!carried || !ids || !output || output->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("CarryLine needs a line with point data MeshPointId, a polydata to fill, and an updated filter.");
    return 0;
  }
  std::vector<std::vector<std::int64_t>> paths;
  auto it = vtk::TakeSmartPointer(line->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* pts;
    it->GetCurrentCell(n, pts);
    std::vector<std::int64_t> path;
    for (vtkIdType k = 0; k < n; ++k)
    {
      // The rule every line input follows: a whole number naming a point (a
      // cast read 3.5 as 3, and a NaN as anything).
      const vtkIdType v = lkvtk::meshPointIdOf(ids, pts[k], this->InputPoints);
      if (v < 0)
      {
        vtkErrorMacro("CarryLine: MeshPointId " << ids->GetComponent(pts[k], 0)
                                                << " is not a point of the filter's input (" << this->InputPoints
                                                << " points).");
        return 0;
      }
      path.push_back(static_cast<std::int64_t>(v));
    }
    paths.push_back(std::move(path));
  }
  // Only a split adds points, and only then can a line change (a skull's
  // surface is 1.5 million triangles to read for nothing otherwise).
  if (output->GetNumberOfPoints() > this->InputPoints)
  {
    lk::TriangleMesh after;
    after.points.resize(static_cast<std::size_t>(output->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      output->GetPoint(i, p);
      after.points[static_cast<std::size_t>(i)] = lk::Vec3(p[0], p[1], p[2]);
    }
    auto polys = vtk::TakeSmartPointer(output->GetPolys()->NewIterator());
    for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* pts;
      polys->GetCurrentCell(n, pts);
      if (n == 3)
        after.triangles.push_back({ pts[0], pts[1], pts[2] });
    }
    paths = lk::carryLines(after, static_cast<std::size_t>(this->InputPoints), paths);
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdTypeArray> meshIds;
  meshIds->SetName("MeshPointId");
  for (const auto& path : paths)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(path.size()));
    for (const auto v : path)
    {
      meshIds->InsertNextValue(static_cast<vtkIdType>(v));
      double p[3];
      output->GetPoint(static_cast<vtkIdType>(v), p);
      cells->InsertCellPoint(points->InsertNextPoint(p));
    }
  }
  carried->Initialize();
  carried->SetPoints(points);
  carried->SetLines(cells);
  carried->GetPointData()->AddArray(meshIds);
  carried->GetFieldData()->ShallowCopy(line->GetFieldData());
  return 1;
}

double vtkLKStrokeFeatureLineFilter::DefaultCloseTolerance(vtkPolyData* surface)
{
  if (!surface)
    return 0.0;
  vtkNew<vtkPolyData> faces; // without the earlier lines, as RequestData takes it
  faces->ShallowCopy(surface);
  vtkNew<vtkCellArray> none;
  faces->SetLines(none);
  lk::TriangleMesh mesh;
  if (!lkvtk::toTriangleMesh(faces, mesh).empty())
    return 0.0;
  return lk::defaultCloseTolerance(mesh);
}

void vtkLKStrokeFeatureLineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "BrushRadius: " << this->BrushRadius << "\n";
  os << indent << "CloseTolerance: " << this->CloseTolerance << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ViewportSize: " << this->ViewportSize[0] << " x " << this->ViewportSize[1] << "\n";
}
