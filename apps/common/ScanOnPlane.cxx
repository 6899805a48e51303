#include "common/ScanOnPlane.h"

#include <vtkDataArray.h>
#include <vtkImageReslice.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>

namespace lkapp
{

ViewFrame viewFrame(const std::array<double, 3>& centre, const std::array<double, 3>& normal)
{
  ViewFrame f;
  f.centre = centre;
  std::array<double, 3> w = normal;
  vtkMath::Normalize(w.data());
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(w[static_cast<std::size_t>(i)]) > std::abs(w[static_cast<std::size_t>(axis)]))
      axis = i;
  // LPS: the feet are -z, the front -y, the left +x.
  const double toward = axis == 0 ? w[0] : -w[static_cast<std::size_t>(axis)];
  if (toward < 0.0)
    for (double& c : w)
      c = -c;
  const std::array<double, 3> upward = axis == 2 ? std::array<double, 3>{ 0, -1, 0 } : std::array<double, 3>{ 0, 0, 1 };
  std::array<double, 3> up = upward;
  const double along = vtkMath::Dot(up.data(), w.data());
  for (int i = 0; i < 3; ++i)
    up[static_cast<std::size_t>(i)] -= along * w[static_cast<std::size_t>(i)];
  vtkMath::Normalize(up.data());
  vtkMath::Cross(up.data(), w.data(), f.right.data());
  f.up = up;
  f.towardViewer = w;
  return f;
}

std::array<double, 3> inFrame(const ViewFrame& frame, const std::array<double, 3>& point)
{
  std::array<double, 3> d;
  vtkMath::Subtract(point.data(), frame.centre.data(), d.data());
  return { vtkMath::Dot(d.data(), frame.right.data()), vtkMath::Dot(d.data(), frame.up.data()),
    vtkMath::Dot(d.data(), frame.towardViewer.data()) };
}

const char* directionLetter(const std::array<double, 3>& v)
{
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(v[static_cast<std::size_t>(i)]) > std::abs(v[static_cast<std::size_t>(axis)]))
      axis = i;
  static const char* const letters[3][2] = { { "L", "R" }, { "P", "A" }, { "S", "I" } };
  return letters[axis][v[static_cast<std::size_t>(axis)] >= 0.0 ? 0 : 1];
}

vtkSmartPointer<vtkImageData> scanOnPlane(vtkImageData* volume, vtkMatrix4x4* dataToPatient, const ViewFrame& frame,
  double side, int pixels, double background)
{
  if (!volume || volume->GetNumberOfPoints() == 0 || !volume->GetPointData()->GetScalars() || !dataToPatient ||
    !(side > 0.0) || !std::isfinite(side) || pixels < 2)
    return nullptr;
  const double determinant = dataToPatient->Determinant();
  if (!(std::abs(determinant) > 1e-12) || !std::isfinite(determinant))
    return nullptr;
  vtkNew<vtkMatrix4x4> patientToData;
  vtkMatrix4x4::Invert(dataToPatient, patientToData);
  // The frame's coordinates (right, up, toward the viewer) to the patient's.
  vtkNew<vtkMatrix4x4> frameToPatient;
  for (int row = 0; row < 3; ++row)
  {
    const std::size_t r = static_cast<std::size_t>(row);
    frameToPatient->SetElement(row, 0, frame.right[r]);
    frameToPatient->SetElement(row, 1, frame.up[r]);
    frameToPatient->SetElement(row, 2, frame.towardViewer[r]);
    frameToPatient->SetElement(row, 3, frame.centre[r]);
  }
  vtkNew<vtkMatrix4x4> axes;
  vtkMatrix4x4::Multiply4x4(patientToData, frameToPatient, axes);
  const double pixel = side / pixels;
  const double start = -0.5 * side + 0.5 * pixel;
  vtkNew<vtkImageReslice> reslice;
  reslice->SetInputData(volume);
  reslice->SetResliceAxes(axes);
  reslice->SetOutputDimensionality(2);
  reslice->SetOutputSpacing(pixel, pixel, 1.0);
  reslice->SetOutputOrigin(start, start, 0.0);
  reslice->SetOutputExtent(0, pixels - 1, 0, pixels - 1, 0, 0);
  reslice->SetInterpolationModeToLinear();
  reslice->SetBackgroundLevel(background);
  reslice->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->ShallowCopy(reslice->GetOutput());
  return out;
}

GreyWindow greyWindowOf(vtkImageData* volume, bool labelMap)
{
  GreyWindow w;
  if (!labelMap || !volume || !volume->GetPointData()->GetScalars())
    return w;
  double range[2];
  volume->GetPointData()->GetScalars()->GetRange(range);
  w.width = std::max(range[1] - range[0], 1.0);
  w.level = 0.5 * (range[0] + range[1]);
  return w;
}

} // namespace lkapp
