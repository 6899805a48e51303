#include "common/ScanPicture.h"

#include "common/AppSupport.h"
#include "common/PlaneSection.h"
#include "common/WrappedText.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkImageActor.h>
#include <vtkImageProperty.h>
#include <vtkMath.h>
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
#include <cstdio>
#include <utility>

namespace lkapp
{

bool makeScanPicture(vtkImageData* scan, vtkMatrix4x4* scanToPatient, bool labelMap, vtkPolyData* bone,
  const ScanPictureRequest& request, ScanPicture& picture, std::string& why)
{
  picture = ScanPicture();
  if (!scan || scan->GetNumberOfPoints() == 0)
  {
    why = "the plan is on a mesh file, not a scan: there is no CT to show";
    return false;
  }
  const auto& normal = request.normal;
  if (request.line.size() < 3 || !(std::hypot(normal[0], normal[1], normal[2]) > 0.0))
  {
    why = "the cut line has no plane";
    return false;
  }
  const auto frameOf = [&](const std::array<double, 3>& n) {
    return request.patientGiven ? viewFrame(request.centre, n, request.patient) : viewFrame(request.centre, n);
  };
  const ViewFrame on = frameOf(normal);
  // Across: the plane that holds the cut's normal and its up direction.
  picture.frame = request.across ? frameOf(on.right) : on;
  // The square: three times the line's reach from its centre, 40 mm at
  // least (a mandible's section is 10 by 30 mm; its surroundings show).
  double reach = 0.0;
  const auto reachTo = [&](const std::array<double, 3>& p) {
    const auto q = inFrame(picture.frame, p);
    reach = std::max({ reach, std::abs(q[0]), std::abs(q[1]) });
  };
  for (const auto& p : request.line)
    reachTo(p);
  if (request.across)
    for (const auto& [origin, n] : request.otherPlanes)
      if (vtkMath::Distance2BetweenPoints(origin.data(), request.centre.data()) < 100.0 * 100.0)
        reachTo(origin);
  picture.side = std::clamp(3.0 * reach, 40.0, 400.0);
  if (!std::isfinite(request.offset) || !std::isfinite(request.windowWidth) || !std::isfinite(request.windowLevel))
  {
    why = "the plane's offset or the window is not a number";
    return false;
  }
  for (std::size_t i = 0; i < 3; ++i)
    picture.frame.centre[i] += request.offset * picture.frame.towardViewer[i];
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
  picture.grey = greyWindowOf(scan, labelMap, request.softTissue);
  if (!labelMap && request.windowWidth > 0.0)
    picture.grey = handWindow(request.windowWidth, request.windowLevel);
  picture.line = { request.line };
  picture.section = planeSectionLoops(bone, picture.frame.centre, picture.frame.towardViewer);
  picture.border = scanBorder(scan, scanToPatient, picture.frame);
  if (request.across)
  {
    picture.cutTrace = { planeTrace(picture.frame, picture.side, { request.centre, normal }) };
    for (const auto& plane : request.otherPlanes)
      if (auto trace = planeTrace(picture.frame, picture.side, plane); !trace.empty())
        picture.otherTraces.push_back(trace);
  }
  return true;
}

std::string planeOffsetText(const ViewFrame& frame, double offset, bool directions)
{
  if (offset == 0.0)
    return "";
  char mm[40];
  std::snprintf(mm, sizeof mm, ", %g mm ", std::abs(offset));
  if (!directions)
    return mm + std::string(offset > 0.0 ? "toward the viewer" : "away from the viewer");
  const std::array<double, 3> way{ offset * frame.towardViewer[0], offset * frame.towardViewer[1],
    offset * frame.towardViewer[2] };
  return mm + std::string("toward ") + directionWord(way);
}

GreyWindow handWindow(double width, double level)
{
  // Within what any scan's values need (a 16-bit range and more), so that a
  // window dragged far stays one a session can be read back with.
  return { std::clamp(std::round(width), 1.0, kLargestHandWindow),
    std::clamp(std::round(level), -kLargestHandWindow, kLargestHandWindow), "window set by hand" };
}

std::vector<std::array<double, 3>> planeTrace(const ViewFrame& frame, double side, const Plane& plane)
{
  // The plane in the frame's coordinates: a x + b y + d = 0.
  const auto& [origin, normal] = plane;
  const double a = vtkMath::Dot(frame.right.data(), normal.data()), b = vtkMath::Dot(frame.up.data(), normal.data());
  std::array<double, 3> offset;
  vtkMath::Subtract(frame.centre.data(), origin.data(), offset.data());
  const double d = vtkMath::Dot(offset.data(), normal.data());
  const double length = std::hypot(a, b);
  if (!(length > 1e-9 * std::max(1.0, vtkMath::Norm(normal.data()))))
    return {};
  // Its point nearest the centre and its direction, clipped to the square.
  const double x0 = -d * a / (length * length), y0 = -d * b / (length * length);
  const double dx = -b / length, dy = a / length, half = 0.5 * side;
  double lowest = -VTK_DOUBLE_MAX, highest = VTK_DOUBLE_MAX;
  for (const auto& [p, q] : { std::make_pair(x0, dx), std::make_pair(y0, dy) })
  {
    if (std::abs(q) < 1e-12)
    {
      if (std::abs(p) > half)
        return {};
      continue;
    }
    const double t1 = (-half - p) / q, t2 = (half - p) / q;
    lowest = std::max(lowest, std::min(t1, t2));
    highest = std::min(highest, std::max(t1, t2));
  }
  if (!(highest > lowest))
    return {};
  std::vector<std::array<double, 3>> ends;
  for (const double t : { lowest, highest })
  {
    std::array<double, 3>& p = ends.emplace_back();
    for (std::size_t i = 0; i < 3; ++i)
      p[i] = frame.centre[i] + (x0 + t * dx) * frame.right[i] + (y0 + t * dy) * frame.up[i];
  }
  return ends;
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
    if (l.size() < 2)
      continue; // a trace or a border the picture does not have
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
  // Readable over bone and over the lines.
  actor->GetTextProperty()->SetBackgroundColor(0, 0, 0);
  actor->GetTextProperty()->SetBackgroundOpacity(0.55);
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  return actor;
}

/// Breaks `title` after its commas where one line would run out of the
/// picture (0.96 of the renderer's width, the text measured in its window):
/// "..., 3 mm toward the patient's right" runs past a 370-pixel view. Without
/// a window (nothing to measure in) it stays one line.
void fitTitle(vtkRenderer* renderer, vtkTextActor* actor, const std::string& title)
{
  const int* pixels = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
  if (!pixels || pixels[0] <= 0)
    return;
  const auto width = [&](const std::string& text) {
    actor->SetInput(text.c_str());
    return textSize(renderer, actor)[0];
  };
  const double room = 0.96 * pixels[0];
  if (width(title) <= room)
    return;
  std::string fitted, line;
  for (std::size_t start = 0; start < title.size();)
  {
    const std::size_t comma = title.find(", ", start);
    const std::string part = title.substr(start, comma == std::string::npos ? std::string::npos : comma + 1 - start);
    start = comma == std::string::npos ? title.size() : comma + 2;
    if (!line.empty() && width(line + " " + part) > room)
    {
      fitted += line + "\n";
      line = part;
    }
    else
      line += (line.empty() ? "" : " ") + part;
  }
  actor->SetInput((fitted + line).c_str());
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
  renderer->AddViewProp(polylines(picture, picture.otherTraces, 0.75, { 1.0, 0.7, 0.45 }, 1.5f));
  renderer->AddViewProp(polylines(picture, picture.cutTrace, 0.75, { 1.0, 0.4, 0.1 }, 1.5f));
  renderer->AddViewProp(polylines(picture, picture.line, 1.0, { 1.0, 0.4, 0.1 }, 2.5f));
  renderer->AddViewProp(polylines(picture, picture.moved, 1.25, { 0.2, 0.9, 1.0 }, 2.0f));
  renderer->AddViewProp(polylines(picture, picture.measured, 1.5, kMeasuredColour, 2.5f));
  for (const auto& [at, text] : picture.measuredValues)
  {
    // Beside its point, toward the picture's middle: a value near the right
    // edge ends at its point instead of running out of the picture.
    const auto q = inFrame(picture.frame, at);
    const double x = 0.5 + q[0] / picture.side, y = 0.5 + q[1] / picture.side;
    const bool right = x > 0.65;
    auto value = label(text, right ? x - 0.02 : x + 0.02, y + 0.02, fontSize, kMeasuredColour,
      right ? VTK_TEXT_RIGHT : VTK_TEXT_LEFT, VTK_TEXT_BOTTOM);
    renderer->AddViewProp(value);
  }
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
  const bool across = !picture.cutTrace.empty();
  std::string legendText = std::string(across ? "orange: the cut's plane" : "orange: cut line") +
    (picture.otherTraces.empty() ? "" : ", light: other cuts'") + ", yellow: bone surface" +
    (edgeShown ? ", blue: edge of the scan" : "");
  if (!picture.moved.empty())
    legendText += "\ncyan: the segment where the plan moves it";
  if (!picture.measured.empty())
    legendText += picture.measuredBeforeMove ? "\nmagenta: measured on this plane\n  (before the segment's move)"
                                             : "\nmagenta: measured on this plane";
  if (!picture.hint.empty())
    legendText += "\n" + picture.hint;
  // The title at the top, on as many lines as the picture's width needs;
  // the legend under it.
  auto title = label(picture.title, 0.02, 0.98, fontSize, { 1, 1, 1 }, VTK_TEXT_LEFT, VTK_TEXT_TOP);
  const double oneLine = textSize(renderer, title)[1];
  fitTitle(renderer, title, picture.title);
  const int* pixels = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
  const double below = pixels && pixels[1] > 0 ? (textSize(renderer, title)[1] - oneLine) / pixels[1] : 0.0;
  auto legend = label(legendText,
    0.02, 0.935 - below, std::max(9, fontSize - 2), { 0.85, 0.85, 0.85 }, VTK_TEXT_LEFT, VTK_TEXT_TOP);
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
  renderer->AddViewProp(title);
  if (const std::string window = greyWindowLabel(picture.grey); !window.empty())
  {
    auto shown = label(window, 0.98, 0.075, std::max(9, fontSize - 2), { 1, 1, 1 }, VTK_TEXT_RIGHT, VTK_TEXT_BOTTOM);
    shown->GetTextProperty()->BoldOff();
    renderer->AddViewProp(shown);
  }
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
  vtkNew<vtkRenderWindow> window;
  if (display)
    window->SetDisplayId(display);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(pixels, pixels);
  showScanPicture(renderer, picture, std::max(12, pixels / 40)); // in its window: the title is measured
  return writeScreenshot(window, path, error);
}

} // namespace lkapp
