#include "vtkLKSymmetryPlaneFilter.h"
#include "vtkLKAbort.h"

#include <vtkCellLocator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIterativeClosestPointTransform.h>
#include <vtkLandmarkTransform.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkReverseSense.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLKSymmetryPlaneFilter);

namespace
{
/// The reflection across the plane through `o` with unit normal `n`:
/// x - 2 ((x - o) . n) n.
void reflectionMatrix(const double o[3], const double n[3], vtkMatrix4x4* m)
{
  const double d = vtkMath::Dot(o, n);
  m->Identity();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
      m->SetElement(r, c, (r == c ? 1.0 : 0.0) - 2.0 * n[r] * n[c]);
    m->SetElement(r, 3, 2.0 * d * n[r]);
  }
}

/// `input` reflected by `m` (an improper isometry): points, normals and
/// vectors by vtkTransformPolyDataFilter, then each cell's points reversed
/// so its normal points the way the reflected normals do.
vtkSmartPointer<vtkPolyData> reflected(vtkPolyData* input, vtkMatrix4x4* m)
{
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(m);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetInputData(input);
  move->SetTransform(transform);
  move->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  vtkNew<vtkReverseSense> turn;
  turn->SetInputConnection(move->GetOutputPort());
  turn->ReverseCellsOn();
  turn->ReverseNormalsOff();
  turn->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(turn->GetOutput());
  return out;
}
} // namespace

int vtkLKSymmetryPlaneFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  std::fill(this->PlaneOrigin, this->PlaneOrigin + 3, 0.0);
  std::fill(this->PlaneNormal, this->PlaneNormal + 3, 0.0);
  this->MeanDistance = this->MaximumDistance = 0.0;

  const double initialLength = vtkMath::Norm(this->InitialNormal);
  if (!std::isfinite(initialLength) || initialLength == 0.0)
  {
    vtkErrorMacro("InitialNormal must be a finite, non-zero vector.");
    return 0;
  }
  if (this->MaximumNumberOfIterations < 1 || this->MaximumNumberOfIterations > 10000)
  {
    vtkErrorMacro("MaximumNumberOfIterations must be 1 to 10000, not " << this->MaximumNumberOfIterations << ".");
    return 0;
  }
  if (!(this->TrimFraction >= 0.0 && this->TrimFraction <= 0.9))
  {
    vtkErrorMacro("TrimFraction must be 0 to 0.9, not " << this->TrimFraction << ".");
    return 0;
  }
  if (this->MaximumNumberOfLandmarks < 3 || this->MaximumNumberOfLandmarks > 10000000)
  {
    vtkErrorMacro("MaximumNumberOfLandmarks must be 3 to 10^7, not " << this->MaximumNumberOfLandmarks << ".");
    return 0;
  }
  if (!input || input->GetNumberOfPoints() < 3 || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("Cannot find a plane of symmetry: the input has no surface (no polygons or strips).");
    return 0;
  }
  const vtkIdType count = input->GetNumberOfPoints();
  double centre[3] = { 0.0, 0.0, 0.0 };
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      vtkErrorMacro("Cannot find a plane of symmetry: point " << i << " is not finite.");
      return 0;
    }
    for (int k = 0; k < 3; ++k)
      centre[k] += x[k] / static_cast<double>(count);
  }
  double bounds[6];
  input->GetBounds(bounds);
  const double start[3] = { bounds[0], bounds[2], bounds[4] };
  const double diagonalLength = std::sqrt(vtkMath::Distance2BetweenPoints(
    start, std::array<double, 3>{ bounds[1], bounds[3], bounds[5] }.data()));
  if (diagonalLength == 0.0)
  {
    vtkErrorMacro("Cannot find a plane of symmetry: every point is in one place.");
    return 0;
  }
  if (!std::isfinite(diagonalLength))
  {
    vtkErrorMacro("Cannot find a plane of symmetry: the surface is too large to measure (its bounding box's "
                  "diagonal overflows).");
    return 0;
  }
  this->UpdateProgress(0.05);

  // The first mirror: across the plane through the centre normal to
  // InitialNormal.
  double n0[3] = { this->InitialNormal[0], this->InitialNormal[1], this->InitialNormal[2] };
  vtkMath::Normalize(n0);
  vtkNew<vtkMatrix4x4> first;
  reflectionMatrix(centre, n0, first);
  // Registers the points `kept`, placed by `from`, to the surface, rigidly;
  // `result` = the motion x from.
  vtkNew<vtkCellLocator> surfaceLocator; // the kind ICP takes
  surfaceLocator->SetDataSet(input);
  surfaceLocator->BuildLocator();
  auto registered = [&](const std::vector<vtkIdType>& kept, vtkMatrix4x4* from, vtkMatrix4x4* result) {
    vtkNew<vtkPoints> placed;
    placed->SetDataTypeToDouble();
    placed->SetNumberOfPoints(static_cast<vtkIdType>(kept.size()));
    for (std::size_t j = 0; j < kept.size(); ++j)
    {
      double x[4] = { 0, 0, 0, 1 }, y[4];
      input->GetPoint(kept[j], x);
      from->MultiplyPoint(x, y);
      placed->SetPoint(static_cast<vtkIdType>(j), y);
    }
    vtkNew<vtkPolyData> source;
    source->SetPoints(placed);
    vtkNew<vtkIterativeClosestPointTransform> icp;
    icp->SetSource(source);
    icp->SetTarget(input);
    icp->SetLocator(surfaceLocator);
    icp->GetLandmarkTransform()->SetModeToRigidBody();
    icp->SetMaximumNumberOfIterations(this->MaximumNumberOfIterations);
    icp->SetMaximumNumberOfLandmarks(
      static_cast<int>(std::min<vtkIdType>(static_cast<vtkIdType>(kept.size()), this->MaximumNumberOfLandmarks)));
    icp->StartByMatchingCentroidsOff();
    icp->CheckMeanDistanceOn();
    icp->SetMeanDistanceModeToAbsoluteValue();
    icp->SetMaximumMeanDistance(1e-5 * diagonalLength); // how far the points moved in an iteration
    icp->Modified();
    icp->Update();
    vtkMatrix4x4::Multiply4x4(icp->GetMatrix(), from, result);
  };
  // The points registered: every one up to kWorkingPoints, else that many
  // evenly spread (a skull's 280,000 points took 20 s to trim; ICP itself
  // takes at most MaximumNumberOfLandmarks of them).
  constexpr vtkIdType kWorkingPoints = 20000;
  const vtkIdType stride = std::max<vtkIdType>(1, count / kWorkingPoints);
  std::vector<vtkIdType> working;
  for (vtkIdType i = 0; i < count; i += stride)
    working.push_back(i);
  std::vector<vtkIdType> kept = working;
  vtkNew<vtkMatrix4x4> s; // the improper isometry: the mirror, then the motion found
  registered(kept, first, s);
  this->UpdateProgress(0.3);
  // Trimmed ICP (Chetverikov et al. 2002): the points whose mirror lands
  // farthest from the bone (a tumour, a fracture's displaced part, a missing
  // condyle: what mirror-image planning is for) are left out of the next
  // registration, so that they do not pull the plane.
  const int rounds = this->TrimFraction > 0.0 ? 4 : 0;
  for (int round = 0; round < rounds; ++round)
  {
    std::vector<std::pair<double, vtkIdType>> apart(working.size());
    vtkNew<vtkGenericCell> cell;
    for (std::size_t j = 0; j < working.size(); ++j)
    {
      double x[4] = { 0, 0, 0, 1 }, y[4], closest[3], d2;
      vtkIdType cellId;
      int sub;
      input->GetPoint(working[j], x);
      s->MultiplyPoint(x, y);
      surfaceLocator->FindClosestPoint(y, closest, cell, cellId, sub, d2);
      apart[j] = { d2, working[j] };
    }
    const auto keep = std::min(working.size(), static_cast<std::size_t>(std::max<double>(
      3.0, std::ceil((1.0 - this->TrimFraction) * static_cast<double>(working.size())))));
    std::nth_element(apart.begin(), apart.begin() + static_cast<std::ptrdiff_t>(keep - 1), apart.end());
    kept.resize(keep);
    for (std::size_t j = 0; j < keep; ++j)
      kept[j] = apart[j].second;
    std::sort(kept.begin(), kept.end()); // the landmarks ICP takes are evenly spread over the bone
    vtkNew<vtkMatrix4x4> previous;
    previous->DeepCopy(s);
    registered(kept, previous, s);
    this->UpdateProgress(0.3 + 0.4 * (round + 1) / rounds);
    if (lkvtk::stopRequested(this, { output }))
      return 1;
  }
  this->UpdateProgress(0.7);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  // The reflection nearest S.
  double symmetric[3][3], values[3], vectors[3][3];
  double* rows[3] = { symmetric[0], symmetric[1], symmetric[2] };
  double* vectorRows[3] = { vectors[0], vectors[1], vectors[2] };
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      symmetric[r][c] = 0.5 * (s->GetElement(r, c) + s->GetElement(c, r));
  vtkMath::Jacobi(rows, values, vectorRows); // values decreasing, vectors in columns
  double n[3] = { vectors[0][2], vectors[1][2], vectors[2][2] };
  vtkMath::Normalize(n);
  if (vtkMath::Dot(n, n0) < 0.0)
    vtkMath::MultiplyScalar(n, -1.0);
  // Through the midpoints of the points kept and their images.
  double offset = 0.0;
  for (const vtkIdType i : kept)
  {
    double x[4] = { 0, 0, 0, 1 }, y[4];
    input->GetPoint(i, x);
    s->MultiplyPoint(x, y);
    const double middle[3] = { 0.5 * (x[0] + y[0]), 0.5 * (x[1] + y[1]), 0.5 * (x[2] + y[2]) };
    offset += vtkMath::Dot(n, middle) / static_cast<double>(kept.size());
  }
  double origin[3];
  const double along = vtkMath::Dot(n, centre) - offset;
  for (int k = 0; k < 3; ++k)
    origin[k] = centre[k] - along * n[k];
  if (!std::isfinite(vtkMath::Norm(n)) || !std::isfinite(origin[0]) || !std::isfinite(origin[1]) ||
    !std::isfinite(origin[2]))
  {
    vtkErrorMacro("Cannot find a plane of symmetry: the registration gave no finite plane.");
    return 0;
  }

  vtkNew<vtkMatrix4x4> mirror;
  reflectionMatrix(origin, n, mirror);
  vtkSmartPointer<vtkPolyData> image = reflected(input, mirror);
  output->ShallowCopy(image);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  this->UpdateProgress(0.85);

  // How far the bone is from its mirror image: a point's distance to the
  // mirror is its mirrored point's distance to the bone (a reflection keeps
  // distances), so the bone's locator serves.
  double sum = 0.0, most = 0.0;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (i % 4096 == 0 && lkvtk::stopRequested(this, { output }))
      return 1;
    double x[4] = { 0, 0, 0, 1 }, y[4], closest[3], d2;
    vtkIdType cellId;
    int sub;
    input->GetPoint(i, x);
    mirror->MultiplyPoint(x, y);
    surfaceLocator->FindClosestPoint(y, closest, cell, cellId, sub, d2);
    const double d = std::sqrt(d2);
    sum += d;
    most = std::max(most, d);
  }
  std::copy(origin, origin + 3, this->PlaneOrigin);
  std::copy(n, n + 3, this->PlaneNormal);
  this->MeanDistance = sum / static_cast<double>(count);
  this->MaximumDistance = most;
  auto add = [&](const char* name, const double* v, int components) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->InsertNextTuple(v);
    output->GetFieldData()->AddArray(a);
  };
  add("SymmetryPlaneOrigin", this->PlaneOrigin, 3);
  add("SymmetryPlaneNormal", this->PlaneNormal, 3);
  add("SymmetryMeanDistance", &this->MeanDistance, 1);
  add("SymmetryMaximumDistance", &this->MaximumDistance, 1);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKSymmetryPlaneFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InitialNormal: " << this->InitialNormal[0] << " " << this->InitialNormal[1] << " "
     << this->InitialNormal[2] << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "MaximumNumberOfLandmarks: " << this->MaximumNumberOfLandmarks << "\n";
  os << indent << "TrimFraction: " << this->TrimFraction << "\n";
  os << indent << "PlaneOrigin: " << this->PlaneOrigin[0] << " " << this->PlaneOrigin[1] << " " << this->PlaneOrigin[2]
     << "\n";
  os << indent << "PlaneNormal: " << this->PlaneNormal[0] << " " << this->PlaneNormal[1] << " " << this->PlaneNormal[2]
     << "\n";
  os << indent << "MeanDistance: " << this->MeanDistance << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
}
