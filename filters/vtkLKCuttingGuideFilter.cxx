#include "vtkLKCuttingGuideFilter.h"
#include "vtkLKAbort.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCleanPolyData.h>
#include <vtkClipPolyData.h>
#include <vtkCellData.h>
#include <vtkCutter.h>
#include <vtkDoubleArray.h>
#include <vtkFeatureEdges.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkLinearExtrusionFilter.h>
#include <vtkMassProperties.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkStripper.h>
#include <vtkTransform.h>
#include <vtkTriangle.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkLKCuttingGuideFilter);

namespace
{
using Vec = std::array<double, 3>;

Vec add(const Vec& a, const Vec& b, double s = 1.0)
{
  return { a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2] };
}

double dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool finiteVector(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

/// The polylines of `surface`'s section by the plane (o, n), each a list of
/// points (closed loops repeat no point).
std::vector<std::vector<Vec>> sectionLoops(vtkPolyData* surface, const Vec& o, const Vec& n)
{
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(o.data());
  plane->SetNormal(n.data());
  vtkNew<vtkCutter> cutter;
  cutter->SetInputData(surface);
  cutter->SetCutFunction(plane);
  vtkNew<vtkStripper> stripper;
  stripper->SetInputConnection(cutter->GetOutputPort());
  stripper->JoinContiguousSegmentsOn();
  stripper->Update();
  vtkPolyData* lines = stripper->GetOutput();
  std::vector<std::vector<Vec>> loops;
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdList* ids = it->GetCurrentCell();
    std::vector<Vec> loop;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      Vec x;
      lines->GetPoint(ids->GetId(k), x.data());
      loop.push_back(x);
    }
    if (!loop.empty())
      loops.push_back(std::move(loop));
  }
  return loops;
}

/// The surface's polygons alone, as triangles.
vtkSmartPointer<vtkPolyData> trianglesOf(vtkPolyData* input)
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(triangles->GetOutput());
  return out;
}

vtkSmartPointer<vtkPolyData> clipped(vtkPolyData* input, vtkImplicitFunction* function)
{
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputData(input);
  clip->SetClipFunction(function);
  clip->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(clip->GetOutput());
  return out;
}

/// `input` cut along `plane`: every face on both sides, the faces it
/// crosses split, on points the two sides share.
vtkSmartPointer<vtkPolyData> split(vtkPolyData* input, vtkPlane* plane)
{
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputData(input);
  clip->SetClipFunction(plane);
  clip->GenerateClippedOutputOn();
  clip->Update();
  vtkPolyData* one = clip->GetOutput();
  vtkPolyData* other = clip->GetClippedOutput();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(one->GetPolys());
  auto it = vtk::TakeSmartPointer(other->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    polys->InsertNextCell(it->GetCurrentCell());
  if (other->GetPoints() != one->GetPoints() && other->GetNumberOfCells() > 0)
  {
    // Not so in VTK 9.1, where both outputs share one point list; were it
    // so, the points are appended (the guide's closedness check tells).
    vtkNew<vtkPoints> points;
    points->DeepCopy(one->GetPoints());
    const vtkIdType offset = points->GetNumberOfPoints();
    for (vtkIdType i = 0; i < other->GetNumberOfPoints(); ++i)
      points->InsertNextPoint(other->GetPoint(i));
    polys->DeepCopy(one->GetPolys());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdList* ids = it->GetCurrentCell();
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        ids->SetId(k, ids->GetId(k) + offset);
      polys->InsertNextCell(ids);
    }
    out->SetPoints(points);
  }
  else
    out->SetPoints(one->GetPoints());
  out->SetPolys(polys);
  return out;
}

double areaOf(vtkPolyData* triangles)
{
  double area = 0.0;
  auto it = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdList* ids = it->GetCurrentCell();
    if (ids->GetNumberOfIds() != 3)
      continue;
    double a[3], b[3], c[3];
    triangles->GetPoint(ids->GetId(0), a);
    triangles->GetPoint(ids->GetId(1), b);
    triangles->GetPoint(ids->GetId(2), c);
    area += vtkTriangle::TriangleArea(a, b, c);
  }
  return area;
}
} // namespace

int vtkLKCuttingGuideFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  std::fill(this->ApproachUsed, this->ApproachUsed + 3, 0.0);
  this->SlotLength = this->ContactArea = this->Volume = 0.0;

  const double normalLength = vtkMath::Norm(this->PlaneNormal);
  if (!finiteVector(this->PlaneOrigin) || !finiteVector(this->PlaneNormal) || !(normalLength > 0.0) ||
    !std::isfinite(normalLength))
  {
    vtkErrorMacro("Cannot make a cutting guide: PlaneOrigin must be finite and PlaneNormal finite and not zero.");
    return 0;
  }
  if (!finiteVector(this->Approach))
  {
    vtkErrorMacro("Cannot make a cutting guide: Approach must be finite (0, 0, 0: chosen from the section).");
    return 0;
  }
  struct Range
  {
    const char* name;
    double value, low, high;
  };
  for (const Range& r : { Range{ "Thickness", this->Thickness, 0.1, 100.0 },
         Range{ "Reach", this->Reach, 0.0, 200.0 }, Range{ "SlotWidth", this->SlotWidth, 0.05, 20.0 },
         Range{ "Bridge", this->Bridge, 0.0, 100.0 }, Range{ "Clearance", this->Clearance, 0.0, 10.0 },
         Range{ "MaximumContactAngle", this->MaximumContactAngle, 1.0, 89.0 } })
  {
    if (!(r.value >= r.low && r.value <= r.high))
    {
      vtkErrorMacro("Cannot make a cutting guide: " << r.name << " must be " << r.low << " to " << r.high
                                                    << " mm" << (r.name[0] == 'M' ? " (degrees)" : "") << ", not "
                                                    << r.value << ".");
      return 0;
    }
  }
  if (!(this->Reach > this->SlotWidth / 2.0))
  {
    vtkErrorMacro("Cannot make a cutting guide: Reach (" << this->Reach << " mm) must be more than half the "
                                                         << "SlotWidth (" << this->SlotWidth << " mm).");
    return 0;
  }
  if (!input || input->GetNumberOfPoints() < 3 || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("Cannot make a cutting guide: the input has no surface (no polygons).");
    return 0;
  }
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    if (!finiteVector(x))
    {
      vtkErrorMacro("Cannot make a cutting guide: point " << i << " of the input is not finite.");
      return 0;
    }
  }

  vtkSmartPointer<vtkPolyData> bone = trianglesOf(input);
  const Vec o{ this->PlaneOrigin[0], this->PlaneOrigin[1], this->PlaneOrigin[2] };
  Vec n{ this->PlaneNormal[0], this->PlaneNormal[1], this->PlaneNormal[2] };
  vtkMath::Normalize(n.data());
  double bounds[6];
  bone->GetBounds(bounds);
  const double diagonal = std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);

  // The section loop nearest the origin: the bone the guide goes on.
  const std::vector<std::vector<Vec>> loops = sectionLoops(bone, o, n);
  const std::vector<Vec>* loop = nullptr;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& l : loops)
    for (const Vec& x : l)
    {
      const double d2 = vtkMath::Distance2BetweenPoints(x.data(), o.data());
      if (d2 < nearest)
      {
        nearest = d2;
        loop = &l;
      }
    }
  if (!loop)
  {
    vtkErrorMacro("Cannot make a cutting guide: the plane meets no part of the bone.");
    return 0;
  }
  this->UpdateProgress(0.1);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  // The approach, in the plane.
  Vec centre{ 0, 0, 0 };
  for (const Vec& x : *loop)
    centre = add(centre, x, 1.0 / static_cast<double>(loop->size()));
  Vec d{ this->Approach[0], this->Approach[1], this->Approach[2] };
  const double given = vtkMath::Norm(d.data());
  if (given > 0.0)
  {
    d = add(d, n, -dot(d, n));
    if (!(vtkMath::Norm(d.data()) > 1e-6 * given))
    {
      vtkErrorMacro("Cannot make a cutting guide: the Approach lies along the plane's normal (it must have a "
                    "part in the plane).");
      return 0;
    }
  }
  else
  {
    // The section's short axis: the eigenvector of its points' covariance
    // with the smallest eigenvalue among the two in the plane.
    double covariance[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
    for (const Vec& x : *loop)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          covariance[r][c] += (x[r] - centre[r]) * (x[c] - centre[c]);
    double* rows[3] = { covariance[0], covariance[1], covariance[2] };
    double values[3], vectors[3][3];
    double* vectorRows[3] = { vectors[0], vectors[1], vectors[2] };
    vtkMath::Jacobi(rows, values, vectorRows); // decreasing eigenvalues, vectors in columns
    double best = -1.0;
    for (int k = 2; k >= 0 && best < 0.0; --k)
    {
      const Vec v{ vectors[0][k], vectors[1][k], vectors[2][k] };
      if (std::abs(dot(v, n)) < 0.5)
      {
        d = add(v, n, -dot(v, n));
        best = k;
      }
    }
    // Away from the centre of the whole bone.
    Vec boneCentre{ 0, 0, 0 };
    const vtkIdType count = bone->GetNumberOfPoints();
    for (vtkIdType i = 0; i < count; ++i)
    {
      double x[3];
      bone->GetPoint(i, x);
      boneCentre = add(boneCentre, { x[0], x[1], x[2] }, 1.0 / static_cast<double>(count));
    }
    if (dot(add(centre, boneCentre, -1.0), d) < 0.0)
      d = { -d[0], -d[1], -d[2] };
  }
  vtkMath::Normalize(d.data());
  Vec e;
  vtkMath::Cross(n.data(), d.data(), e.data());

  // The contact: faces in the band, facing the approach, seen from it,
  // grown from the face under the section's outermost point.
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(bone);
  locator->BuildLocator();
  bone->BuildLinks();
  const vtkIdType faces = bone->GetNumberOfCells();
  const double facing = std::cos(vtkMath::RadiansFromDegrees(this->MaximumContactAngle));
  const double lift = 1e-4 * diagonal;
  std::vector<signed char> state(static_cast<std::size_t>(faces), -1); // -1 not asked, 0 no, 1 yes
  vtkNew<vtkGenericCell> cell;
  auto takes = [&](vtkIdType f) {
    signed char& s = state[static_cast<std::size_t>(f)];
    if (s >= 0)
      return s == 1;
    s = 0;
    const vtkIdType* ids = nullptr;
    vtkIdType size = 0;
    bone->GetCellPoints(f, size, ids);
    if (size != 3)
      return false;
    Vec p[3];
    bool inBand = false;
    for (int k = 0; k < 3; ++k)
    {
      bone->GetPoint(ids[k], p[k].data());
      inBand = inBand || std::abs(dot(add(p[k], o, -1.0), n)) < this->Reach;
    }
    if (!inBand)
      return false;
    Vec normal;
    vtkTriangle::ComputeNormal(p[0].data(), p[1].data(), p[2].data(), normal.data());
    if (dot(normal, d) < facing)
      return false;
    const Vec middle = add(add(p[0], p[1]), p[2]);
    const Vec from = add({ middle[0] / 3, middle[1] / 3, middle[2] / 3 }, d, lift);
    Vec to = add(from, d, 2.0 * diagonal);
    double t = 0.0, x[3], pcoords[3];
    int subId = 0;
    vtkIdType hit = -1;
    if (locator->IntersectWithLine(from.data(), to.data(), 0.0, t, x, pcoords, subId, hit, cell) && hit != f)
      return false;
    s = 1;
    return true;
  };
  const Vec* outermost = &loop->front();
  for (const Vec& x : *loop)
    if (dot(x, d) > dot(*outermost, d))
      outermost = &x;
  double closest[3], distance2 = 0.0;
  vtkIdType seed = -1;
  int subId = 0;
  locator->FindClosestPoint(outermost->data(), closest, cell, seed, subId, distance2);
  if (seed < 0 || !takes(seed))
  {
    // The outermost point may lie on an edge between a facing face and one
    // that is not: try the faces round it.
    vtkNew<vtkIdList> around;
    if (seed >= 0)
    {
      const vtkIdType* ids = nullptr;
      vtkIdType size = 0;
      bone->GetCellPoints(seed, size, ids);
      for (vtkIdType k = 0; k < size && (seed < 0 || !takes(seed)); ++k)
      {
        bone->GetPointCells(ids[k], around);
        for (vtkIdType j = 0; j < around->GetNumberOfIds(); ++j)
          if (takes(around->GetId(j)))
          {
            seed = around->GetId(j);
            break;
          }
      }
    }
    if (seed < 0 || !takes(seed))
    {
      vtkErrorMacro("Cannot make a cutting guide: no face of the bone at the cut faces the approach ("
                    << d[0] << ", " << d[1] << ", " << d[2] << ") within " << this->MaximumContactAngle
                    << " degrees.");
      return 0;
    }
  }
  std::vector<vtkIdType> contact{ seed };
  std::deque<vtkIdType> queue{ seed };
  std::vector<char> queued(static_cast<std::size_t>(faces), 0);
  queued[static_cast<std::size_t>(seed)] = 1;
  vtkNew<vtkIdList> neighbours;
  while (!queue.empty())
  {
    const vtkIdType f = queue.front();
    queue.pop_front();
    const vtkIdType* ids = nullptr;
    vtkIdType size = 0;
    bone->GetCellPoints(f, size, ids);
    const vtkIdType corners[3] = { ids[0], ids[1], ids[2] };
    for (int k = 0; k < 3; ++k)
    {
      bone->GetCellEdgeNeighbors(f, corners[k], corners[(k + 1) % 3], neighbours);
      for (vtkIdType j = 0; j < neighbours->GetNumberOfIds(); ++j)
      {
        const vtkIdType g = neighbours->GetId(j);
        if (!queued[static_cast<std::size_t>(g)] && takes(g))
        {
          queued[static_cast<std::size_t>(g)] = 1;
          queue.push_back(g);
          contact.push_back(g);
        }
      }
    }
    if (contact.size() % 1024 == 0 && this->GetAbortExecute())
      break;
  }
  this->UpdateProgress(0.5);
  if (lkvtk::stopRequested(this, { output }))
    return 1;
  std::sort(contact.begin(), contact.end());
  vtkNew<vtkCellArray> contactCells;
  for (const vtkIdType f : contact)
  {
    const vtkIdType* ids = nullptr;
    vtkIdType size = 0;
    bone->GetCellPoints(f, size, ids);
    contactCells->InsertNextCell(size, ids);
  }
  vtkNew<vtkPolyData> patch;
  patch->SetPoints(bone->GetPoints());
  patch->SetPolys(contactCells);

  // Clipped at +-Reach from the plane.
  vtkNew<vtkPlane> above, below;
  above->SetOrigin(add(o, n, this->Reach).data());
  above->SetNormal(-n[0], -n[1], -n[2]);
  below->SetOrigin(add(o, n, -this->Reach).data());
  below->SetNormal(n.data());
  vtkSmartPointer<vtkPolyData> band = clipped(clipped(patch, above), below);
  this->ContactArea = areaOf(band);

  // The slot: the contact's extent along the plane, less the bridges.
  vtkNew<vtkPlane> cutPlane;
  cutPlane->SetOrigin(o.data());
  cutPlane->SetNormal(n.data());
  vtkNew<vtkCutter> across;
  across->SetInputData(band);
  across->SetCutFunction(cutPlane);
  across->Update();
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (vtkIdType i = 0; i < across->GetOutput()->GetNumberOfPoints(); ++i)
  {
    Vec x;
    across->GetOutput()->GetPoint(i, x.data());
    const double u = dot(add(x, o, -1.0), e);
    low = std::min(low, u);
    high = std::max(high, u);
  }
  const double slotLength = high - low - 2.0 * this->Bridge;
  if (!(slotLength >= this->SlotWidth))
  {
    vtkErrorMacro("Cannot make a cutting guide: its contact with the bone at the cut is "
      << std::max(0.0, high - low) << " mm long along the plane, too short for a slot between two bridges of "
      << this->Bridge << " mm (a smaller Bridge or a larger MaximumContactAngle?).");
    return 0;
  }
  // The band split along the slot's four sides (each split keeps both
  // sides, on shared points, so the mesh stays conforming), and the faces
  // inside the slot taken out.
  vtkSmartPointer<vtkPolyData> slotted = band;
  const double ends[2] = { low + this->Bridge, high - this->Bridge };
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkPlane> side;
    const Vec& axis = k < 2 ? n : e;
    const double at = k < 2 ? (k == 0 ? -1.0 : 1.0) * this->SlotWidth / 2.0 : ends[k - 2];
    side->SetOrigin(add(o, axis, at).data());
    side->SetNormal(axis.data());
    slotted = split(slotted, side);
  }
  vtkNew<vtkCellArray> kept;
  auto cells = vtk::TakeSmartPointer(slotted->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdList* ids = cells->GetCurrentCell();
    Vec middle{ 0, 0, 0 };
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      Vec x;
      slotted->GetPoint(ids->GetId(k), x.data());
      middle = add(middle, x, 1.0 / static_cast<double>(ids->GetNumberOfIds()));
    }
    const Vec r = add(middle, o, -1.0);
    const double s = dot(r, n), u = dot(r, e);
    if (!(std::abs(s) < this->SlotWidth / 2.0 && u > ends[0] && u < ends[1]))
      kept->InsertNextCell(ids);
  }
  slotted->SetPolys(kept);
  this->UpdateProgress(0.7);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  // The shell: moved by the clearance, swept by the thickness.
  vtkNew<vtkPoints> moved;
  moved->SetDataTypeToDouble();
  moved->SetNumberOfPoints(slotted->GetNumberOfPoints());
  for (vtkIdType i = 0; i < slotted->GetNumberOfPoints(); ++i)
  {
    Vec x;
    slotted->GetPoint(i, x.data());
    moved->SetPoint(i, add(x, d, this->Clearance).data());
  }
  vtkNew<vtkPolyData> inner;
  inner->SetPoints(moved);
  inner->SetPolys(slotted->GetPolys());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(inner);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  vtkNew<vtkLinearExtrusionFilter> sweep;
  sweep->SetInputConnection(clean->GetOutputPort());
  sweep->SetExtrusionTypeToVectorExtrusion();
  sweep->SetVector(d[0] * this->Thickness, d[1] * this->Thickness, d[2] * this->Thickness);
  sweep->CappingOn();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(sweep->GetOutputPort());
  vtkNew<vtkPolyDataNormals> outward;
  outward->SetInputConnection(triangles->GetOutputPort());
  outward->ConsistencyOn();
  outward->AutoOrientNormalsOn();
  outward->SplittingOff();
  outward->ComputeCellNormalsOn(); // with neither, VTK 9.1 leaves the cells as they are
  outward->ComputePointNormalsOff();
  outward->Update();
  this->UpdateProgress(0.9);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  vtkNew<vtkFeatureEdges> open;
  open->SetInputConnection(outward->GetOutputPort());
  open->BoundaryEdgesOn();
  open->NonManifoldEdgesOn();
  open->FeatureEdgesOff();
  open->ManifoldEdgesOff();
  open->Update();
  if (const vtkIdType edges = open->GetOutput()->GetNumberOfCells())
    vtkWarningMacro("The cutting guide is not closed: " << edges << " of its edges are open or shared by more than "
                                                        << "two faces (the bone's surface was not manifold there?).");
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(outward->GetOutputPort());
  mass->Update();
  output->ShallowCopy(outward->GetOutput());
  output->GetPointData()->Initialize();
  output->GetCellData()->Initialize();
  output->GetFieldData()->PassData(input->GetFieldData());

  std::copy(d.begin(), d.end(), this->ApproachUsed);
  this->SlotLength = slotLength;
  this->Volume = mass->GetVolume();
  auto addField = [&](const char* name, const double* v, int components) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->InsertNextTuple(v);
    output->GetFieldData()->AddArray(a);
  };
  addField("GuideApproach", this->ApproachUsed, 3);
  addField("GuideSlotLength", &this->SlotLength, 1);
  addField("GuideContactArea", &this->ContactArea, 1);
  addField("GuideVolume", &this->Volume, 1);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKCuttingGuideFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto triple = [&](const char* name, const double* v) {
    os << indent << name << ": " << v[0] << " " << v[1] << " " << v[2] << "\n";
  };
  triple("PlaneOrigin", this->PlaneOrigin);
  triple("PlaneNormal", this->PlaneNormal);
  triple("Approach", this->Approach);
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "Reach: " << this->Reach << "\n";
  os << indent << "SlotWidth: " << this->SlotWidth << "\n";
  os << indent << "Bridge: " << this->Bridge << "\n";
  os << indent << "Clearance: " << this->Clearance << "\n";
  os << indent << "MaximumContactAngle: " << this->MaximumContactAngle << "\n";
  triple("ApproachUsed", this->ApproachUsed);
  os << indent << "SlotLength: " << this->SlotLength << "\n";
  os << indent << "ContactArea: " << this->ContactArea << "\n";
  os << indent << "Volume: " << this->Volume << "\n";
}
