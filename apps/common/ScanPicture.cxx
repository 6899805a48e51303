#include "common/ScanPicture.h"

#include "common/AppSupport.h"
#include "common/PlaneSection.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkImageActor.h>
#include <vtkImageProperty.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

namespace lkapp
{

bool makeScanPicture(vtkImageData* scan, vtkMatrix4x4* scanToPatient, bool labelMap, bool softTissue, vtkPolyData* bone,
  const std::vector<std::array<double, 3>>& line, const std::array<double, 3>& centre,
  const std::array<double, 3>& normal, ScanPicture& picture, std::string& why)
{
  picture = ScanPicture();
  if (!scan || scan->GetNumberOfPoints() == 0)
  {
    why = "the plan is on a mesh file, not a scan: there is no CT to show";
    return false;
  }
  if (line.size() < 3 || !(std::hypot(normal[0], normal[1], normal[2]) > 0.0))
  {
    why = "the cut line has no plane";
    return false;
  }
  picture.frame = viewFrame(centre, normal);
  // The square: 1.5 times the line's extent in the plane, 40 mm at least
  // (a mandible's section is 10 by 30 mm; its surroundings show), 400 mm
  // at most.
  double reach = 0.0;
  for (const auto& p : line)
  {
    const auto q = inFrame(picture.frame, p);
    reach = std::max({ reach, std::abs(q[0]), std::abs(q[1]) });
  }
  picture.side = std::clamp(3.0 * reach, 40.0, 400.0);
  double spacing[3];
  scan->GetSpacing(spacing);
  const double finest = std::max(std::min({ spacing[0], spacing[1], spacing[2] }), 1e-3);
  const int pixels = static_cast<int>(std::clamp(std::ceil(picture.side / (0.5 * finest)), 64.0, 512.0));
  double range[2] = { 0, 0 };
  scan->GetPointData()->GetScalars()->GetRange(range);
  picture.image = scanOnPlane(scan, scanToPatient, picture.frame, picture.side, pixels, range[0]);
  if (!picture.image)
  {
    why = "the scan cannot be resliced (its matrix to patient coordinates is singular)";
    return false;
  }
  picture.grey = greyWindowOf(scan, labelMap, softTissue);
  picture.line = { line };
  picture.section = planeSectionLoops(bone, centre, normal);
  picture.border = scanBorder(scan, scanToPatient, picture.frame);
  return true;
}

namespace
{

vtkSmartPointer<vtkActor> polylines(const ScanPicture& picture, const std::vector<std::vector<std::array<double, 3>>>& lines,
  double height, const std::array<double, 3>& colour, float width)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (const auto& l : lines)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(l.size()));
    for (const auto& p : l)
    {
      const auto q = inFrame(picture.frame, p);
      cells->InsertCellPoint(points->InsertNextPoint(q[0], q[1], height));
    }
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetLines(cells);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(pd);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(width);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkTextActor> label(const std::string& text, double x, double y, int size,
  const std::array<double, 3>& colour, int horizontal, int vertical)
{
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  actor->GetTextProperty()->SetFontSize(size);
  actor->GetTextProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetTextProperty()->SetJustification(horizontal);
  actor->GetTextProperty()->SetVerticalJustification(vertical);
  actor->GetTextProperty()->BoldOn();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  return actor;
}

} // namespace

void showScanPicture(vtkRenderer* renderer, const ScanPicture& picture, int fontSize)
{
  renderer->RemoveAllViewProps();
  renderer->SetBackground(0, 0, 0);
  if (!picture.image)
    return;
  vtkNew<vtkImageActor> image;
  image->SetInputData(picture.image);
  image->GetProperty()->SetColorWindow(picture.grey.width);
  image->GetProperty()->SetColorLevel(picture.grey.level);
  image->GetProperty()->SetInterpolationTypeToLinear();
  renderer->AddViewProp(image);
  // The bone surface's section, then the cut line over it (for a saw cut
  // they are the same).
  renderer->AddViewProp(polylines(picture, { picture.border }, 0.25, { 0.35, 0.55, 1.0 }, 1.5f));
  renderer->AddViewProp(polylines(picture, picture.section, 0.5, { 1.0, 0.85, 0.2 }, 1.5f));
  renderer->AddViewProp(polylines(picture, picture.line, 1.0, { 1.0, 0.4, 0.1 }, 2.5f));
  // What the colours are, under the title; the scan's edge only where the
  // picture shows it.
  bool edgeShown = false;
  for (std::size_t k = 0; k + 1 < picture.border.size() && !edgeShown; ++k)
  {
    const auto a = inFrame(picture.frame, picture.border[k]), b = inFrame(picture.frame, picture.border[k + 1]);
    for (int step = 0; step <= 64 && !edgeShown; ++step)
    {
      const double t = step / 64.0, x = a[0] + t * (b[0] - a[0]), y = a[1] + t * (b[1] - a[1]);
      edgeShown = std::abs(x) < 0.5 * picture.side && std::abs(y) < 0.5 * picture.side;
    }
  }
  auto legend = label(std::string("orange: cut line, yellow: bone surface") + (edgeShown ? ", blue: edge of the scan" : ""),
    0.02, 0.935, std::max(9, fontSize - 2), { 0.85, 0.85, 0.85 }, VTK_TEXT_LEFT, VTK_TEXT_TOP);
  legend->GetTextProperty()->BoldOff();
  renderer->AddViewProp(legend);
  // A 10 mm bar at the bottom left.
  const double half = 0.5 * picture.side;
  const double x0 = -half + 0.05 * picture.side, y0 = -half + 0.06 * picture.side;
  ScanPicture flat;
  flat.frame = ViewFrame(); // the bar is in the view's own coordinates already
  renderer->AddViewProp(polylines(flat, { { { x0, y0, 0 }, { x0 + 10.0, y0, 0 } } }, 1.0, { 1, 1, 1 }, 3.0f));
  auto bar = label("10 mm", 0.05 + 5.0 / picture.side, 0.075, fontSize, { 1, 1, 1 }, VTK_TEXT_CENTERED, VTK_TEXT_BOTTOM);
  bar->GetTextProperty()->BoldOff();
  renderer->AddViewProp(bar);
  renderer->AddViewProp(label(picture.title, 0.02, 0.98, fontSize, { 1, 1, 1 }, VTK_TEXT_LEFT, VTK_TEXT_TOP));
  if (picture.directions)
  {
    const auto& f = picture.frame;
    const std::array<double, 3> left{ -f.right[0], -f.right[1], -f.right[2] },
      down{ -f.up[0], -f.up[1], -f.up[2] };
    const std::array<double, 3> letterColour{ 1.0, 0.85, 0.2 };
    renderer->AddViewProp(label(directionLetter(f.right), 0.985, 0.5, fontSize + 2, letterColour, VTK_TEXT_RIGHT,
      VTK_TEXT_CENTERED));
    renderer->AddViewProp(
      label(directionLetter(left), 0.015, 0.5, fontSize + 2, letterColour, VTK_TEXT_LEFT, VTK_TEXT_CENTERED));
    renderer->AddViewProp(
      label(directionLetter(f.up), 0.5, 0.87, fontSize + 2, letterColour, VTK_TEXT_CENTERED, VTK_TEXT_TOP));
    renderer->AddViewProp(
      label(directionLetter(down), 0.5, 0.015, fontSize + 2, letterColour, VTK_TEXT_CENTERED, VTK_TEXT_BOTTOM));
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, picture.side);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(half);
  renderer->ResetCameraClippingRange();
}

bool writeScanPicture(const ScanPicture& picture, int pixels, const std::string& path, std::string& error,
  void* display)
{
  vtkNew<vtkRenderer> renderer;
  showScanPicture(renderer, picture, std::max(12, pixels / 40));
  vtkNew<vtkRenderWindow> window;
  if (display)
    window->SetDisplayId(display);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(pixels, pixels);
  return writeScreenshot(window, path, error);
}

} // namespace lkapp
