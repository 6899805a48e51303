#include "vtkLKSymmetryPlaneFilter.h"
#include "vtkLKAbort.h"
#include "vtkLKFieldValues.h"
#include "vtkLKPolyDataConversion.h"

#include "latticekit/SymmetryPlane.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkReverseSense.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <array>
#include <cmath>

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
  this->MeanDistance = this->MaximumDistance = this->KeptFraction = 0.0;

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
  if (this->MaximumNumberOfPoints < 3 || this->MaximumNumberOfPoints > 10000000)
  {
    vtkErrorMacro("MaximumNumberOfPoints must be 3 to 10^7, not " << this->MaximumNumberOfPoints << ".");
    return 0;
  }
  if (const std::string why = lkvtk::surfaceProblem(input); !why.empty())
  {
    vtkErrorMacro("Cannot find a plane of symmetry: " << why << ".");
    return 0;
  }
  this->UpdateProgress(0.05);

  // The registration works on triangles: polygons fanned, strips split,
  // lines and vertices left out (the points stay as they are).
  lk::TriangleMesh mesh;
  if (const std::string why = lkvtk::toTriangleMesh(lkvtk::facesAsTriangles(input), mesh);
      !why.empty() || mesh.triangles.empty())
  {
    vtkErrorMacro("Cannot find a plane of symmetry: " << (why.empty() ? "the input has no triangles" : why));
    return 0;
  }
  lk::SymmetryPlaneOptions options;
  options.initialNormal = lk::Vec3(this->InitialNormal[0], this->InitialNormal[1], this->InitialNormal[2]);
  options.trimFraction = this->TrimFraction;
  options.maximumIterations = this->MaximumNumberOfIterations;
  options.maximumPoints = static_cast<std::size_t>(this->MaximumNumberOfPoints);
  options.progress = [this](double done) {
    this->UpdateProgress(0.1 + 0.7 * done);
    return this->GetAbortExecute() == 0;
  };
  const lk::SymmetryPlaneResult plane = this->FitPlane
    ? lk::findSymmetryPlane(mesh, options)
    : lk::measureMirror(mesh, lk::Vec3(this->GivenPlaneOrigin[0], this->GivenPlaneOrigin[1], this->GivenPlaneOrigin[2]),
        lk::Vec3(this->GivenPlaneNormal[0], this->GivenPlaneNormal[1], this->GivenPlaneNormal[2]));
  if (lkvtk::stopRequested(this, { output }))
    return 1;
  if (!plane.ok)
  {
    vtkErrorMacro(<< (this->FitPlane ? "Cannot find a plane of symmetry: " : "Cannot mirror across the given plane: ")
                  << plane.error << ".");
    return 0;
  }
  const double n[3] = { plane.normal.x(), plane.normal.y(), plane.normal.z() };
  const double origin[3] = { plane.origin.x(), plane.origin.y(), plane.origin.z() };

  vtkNew<vtkMatrix4x4> mirror;
  reflectionMatrix(origin, n, mirror);
  vtkSmartPointer<vtkPolyData> image = reflected(input, mirror);
  output->ShallowCopy(image);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  this->UpdateProgress(0.9);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  std::copy(origin, origin + 3, this->PlaneOrigin);
  std::copy(n, n + 3, this->PlaneNormal);
  this->MeanDistance = plane.meanDistance;
  this->MaximumDistance = plane.maximumDistance;
  this->KeptFraction = plane.keptFraction;
  vtkFieldData* fd = output->GetFieldData();
  lkvtk::addFieldValues(fd, "SymmetryPlaneOrigin", this->PlaneOrigin, 3);
  lkvtk::addFieldValues(fd, "SymmetryPlaneNormal", this->PlaneNormal, 3);
  lkvtk::addFieldValue(fd, "SymmetryMeanDistance", this->MeanDistance);
  lkvtk::addFieldValue(fd, "SymmetryMaximumDistance", this->MaximumDistance);
  lkvtk::addFieldValue(fd, "SymmetryKeptFraction", this->KeptFraction);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKSymmetryPlaneFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InitialNormal: " << this->InitialNormal[0] << " " << this->InitialNormal[1] << " "
     << this->InitialNormal[2] << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "MaximumNumberOfPoints: " << this->MaximumNumberOfPoints << "\n";
  os << indent << "TrimFraction: " << this->TrimFraction << "\n";
  os << indent << "FitPlane: " << (this->FitPlane ? "on" : "off") << "\n";
  os << indent << "GivenPlaneOrigin: " << this->GivenPlaneOrigin[0] << " " << this->GivenPlaneOrigin[1] << " "
     << this->GivenPlaneOrigin[2] << "\n";
  os << indent << "GivenPlaneNormal: " << this->GivenPlaneNormal[0] << " " << this->GivenPlaneNormal[1] << " "
     << this->GivenPlaneNormal[2] << "\n";
  os << indent << "PlaneOrigin: " << this->PlaneOrigin[0] << " " << this->PlaneOrigin[1] << " " << this->PlaneOrigin[2]
     << "\n";
  os << indent << "PlaneNormal: " << this->PlaneNormal[0] << " " << this->PlaneNormal[1] << " " << this->PlaneNormal[2]
     << "\n";
  os << indent << "MeanDistance: " << this->MeanDistance << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "KeptFraction: " << this->KeptFraction << "\n";
}
