#include "common/ScanOnPlane.h"

#include <vtkDataArray.h>
#include <vtkImageReslice.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

bool isValid(const HeadAndFront& patient)
{
  const double head = vtkMath::Norm(patient.head.data()), front = vtkMath::Norm(patient.front.data());
  if (!std::isfinite(head) || !std::isfinite(front) || !(head > 0.0) || !(front > 0.0))
    return false;
  std::array<double, 3> cross;
  vtkMath::Cross(patient.head.data(), patient.front.data(), cross.data());
  return vtkMath::Norm(cross.data()) > std::sin(vtkMath::RadiansFromDegrees(10.0)) * head * front;
}

ViewFrame viewFrame(const std::array<double, 3>& centre, const std::array<double, 3>& normal,
  const HeadAndFront& patient)
{
  if (!isValid(patient))
    return viewFrame(centre, normal);
  // The patient's L, P and S axes in the scan's coordinates.
  std::array<double, 3> s = patient.head, p = patient.front, l;
  vtkMath::Normalize(s.data());
  const double along = vtkMath::Dot(p.data(), s.data());
  for (std::size_t i = 0; i < 3; ++i)
    p[i] = -(p[i] - along * s[i]); // the back: the front made square to the head, turned
  vtkMath::Normalize(p.data());
  vtkMath::Cross(p.data(), s.data(), l.data());
  const auto toPatient = [&](const std::array<double, 3>& v) {
    return std::array<double, 3>{ vtkMath::Dot(v.data(), l.data()), vtkMath::Dot(v.data(), p.data()),
      vtkMath::Dot(v.data(), s.data()) };
  };
  const auto toScan = [&](const std::array<double, 3>& w) {
    std::array<double, 3> v;
    for (std::size_t i = 0; i < 3; ++i)
      v[i] = w[0] * l[i] + w[1] * p[i] + w[2] * s[i];
    return v;
  };
  ViewFrame f = viewFrame(centre, toPatient(normal));
  f.right = toScan(f.right);
  f.up = toScan(f.up);
  f.towardViewer = toScan(f.towardViewer);
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

const char* directionWord(const std::array<double, 3>& v)
{
  const std::string letter = directionLetter(v);
  return letter == "L" ? "the patient's left" : letter == "R" ? "the patient's right" : letter == "A" ? "the front" :
    letter == "P" ? "the back" : letter == "S" ? "the head" : "the feet";
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

std::vector<std::array<double, 3>> scanBorder(vtkImageData* volume, vtkMatrix4x4* dataToPatient, const ViewFrame& frame)
{
  std::vector<std::array<double, 3>> corners;
  if (!volume || volume->GetNumberOfPoints() == 0 || !dataToPatient)
    return corners;
  double bounds[6];
  volume->GetBounds(bounds);
  // The box's corners in the patient's coordinates, and their heights above the plane.
  std::array<double, 3> box[8];
  double height[8];
  for (int c = 0; c < 8; ++c)
  {
    const double data[4] = { bounds[c & 1], bounds[2 + ((c >> 1) & 1)], bounds[4 + ((c >> 2) & 1)], 1.0 };
    double patient[4];
    dataToPatient->MultiplyPoint(data, patient);
    box[c] = { patient[0], patient[1], patient[2] };
    height[c] = inFrame(frame, box[c])[2];
  }
  double size = 0.0;
  for (int c = 1; c < 8; ++c)
    size = std::max(size, std::sqrt(vtkMath::Distance2BetweenPoints(box[0].data(), box[c].data())));
  const auto add = [&](const std::array<double, 3>& p) {
    for (const auto& q : corners)
      if (vtkMath::Distance2BetweenPoints(p.data(), q.data()) <= 1e-18 * size * size)
        return;
    corners.push_back(p);
  };
  for (int a = 0; a < 8; ++a)
  {
    if (height[a] == 0.0)
      add(box[a]);
    for (int bit = 0; bit < 3; ++bit)
    {
      const int b = a | (1 << bit);
      if (b == a || !((height[a] < 0.0 && height[b] > 0.0) || (height[a] > 0.0 && height[b] < 0.0)))
        continue;
      const double t = height[a] / (height[a] - height[b]);
      std::array<double, 3> p;
      for (std::size_t i = 0; i < 3; ++i)
        p[i] = box[a][i] + t * (box[b][i] - box[a][i]);
      add(p);
    }
  }
  if (corners.size() < 3)
    return {};
  // In order around their middle, as the frame shows them.
  std::array<double, 3> middle{ 0, 0, 0 };
  for (const auto& p : corners)
    for (std::size_t i = 0; i < 3; ++i)
      middle[i] += p[i] / static_cast<double>(corners.size());
  const auto angle = [&](const std::array<double, 3>& p) {
    const auto q = inFrame(frame, p), m = inFrame(frame, middle);
    return std::atan2(q[1] - m[1], q[0] - m[0]);
  };
  std::sort(corners.begin(), corners.end(), [&](const auto& p, const auto& q) { return angle(p) < angle(q); });
  corners.push_back(corners.front());
  return corners;
}

GreyWindow greyWindowOf(vtkImageData* volume, bool labelMap, bool softTissue)
{
  GreyWindow w;
  if (!labelMap)
  {
    if (softTissue)
      w = { 400.0, 40.0, "soft-tissue window" };
    return w;
  }
  w.name.clear();
  if (!volume || !volume->GetPointData()->GetScalars())
    return w;
  double range[2];
  volume->GetPointData()->GetScalars()->GetRange(range);
  w.width = std::max(range[1] - range[0], 1.0);
  w.level = 0.5 * (range[0] + range[1]);
  return w;
}

std::string greyWindowLabel(const GreyWindow& window)
{
  if (window.name.empty())
    return "";
  char text[120];
  std::snprintf(text, sizeof text, "%s: W %g, L %g", window.name.c_str(), window.width, window.level);
  return text;
}

std::string greyWindowText(const GreyWindow& window)
{
  const std::string label = greyWindowLabel(window);
  return label.empty() ? "" : " (" + label + ")";
}

} // namespace lkapp
