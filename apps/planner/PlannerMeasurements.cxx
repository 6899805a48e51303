// latticekit-planner: measuring (u, a): distances and angles on the bone or on
// the CT view, drawn over the bone, and the measurement or stroke under the mouse.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"
#include "common/PlaneSection.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInteractorObserver.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkMath.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkMatrix4x4.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <string>
#include <vector>

namespace lkplanner
{

std::array<double, 3> Planner::shownPoint(const std::array<double, 3>& point, int piece,
  const std::array<double, 16>& matrix) const
{
  return piece < 0 || piece != movedPiece() ? point : lkapp::placedPoint(matrix, point);
}

Measurement Planner::placed(const Measurement& m, const std::array<double, 16>& matrix) const
{
  Measurement shown = m;
  shown.from = shownPoint(m.from, m.pieces[Measurement::FROM], matrix);
  shown.to = shownPoint(m.to, m.pieces[Measurement::TO], matrix);
  shown.at = shownPoint(m.at, m.pieces[Measurement::AT], matrix);
  return shown;
}

std::string Planner::valueText(const Measurement& m)
{
  return m.angle ? degreesText(m.degrees()) : lengthText(m.length());
}

std::string Planner::degreesText(double degrees)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.1f deg", degrees);
  return text;
}

int Planner::pieceOnScan(const std::array<double, 3>& point, double& nearest) const
{
  const std::vector<double> distance = pieceDistances({ point }).front();
  const auto best = std::min_element(distance.begin(), distance.end());
  nearest = best == distance.end() ? VTK_DOUBLE_MAX : *best;
  if (nearest == VTK_DOUBLE_MAX)
    return Measurement::kSoftTissue;
  const int piece = static_cast<int>(best - distance.begin());
  if (nearest <= kBesideTheBone)
    return piece;
  // Inside a piece's outline on the plane (any loop counts, so that the
  // marrow inside the cortex's inner wall is bone too); on a cut's own
  // plane, where a piece's cap lies and its section is not defined, inside
  // the uncut bone's.
  const std::array<double, 3>& normal = scanPicture.frame.towardViewer;
  auto encloses = [&](const std::vector<std::vector<std::array<double, 3>>>& loops) {
    for (const auto& loop : loops)
      if (lkapp::loopEncloses(loop, point, normal))
        return true;
    return false;
  };
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
    if (encloses(lkapp::planeSectionLoops(cut.pieces[p], point, normal, kBesideACap)))
      return static_cast<int>(p);
  return encloses(lkapp::planeSectionLoops(bone, point, normal)) ? piece : Measurement::kSoftTissue;
}

std::string Planner::lengthText(double length)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.2f mm", length);
  return text;
}

double Planner::pixelsFrom(
  vtkRenderer* view, int x, int y, const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  auto onScreen = [&](const std::array<double, 3>& p) {
    double d[3];
    vtkInteractorObserver::ComputeWorldToDisplay(view, p[0], p[1], p[2], d);
    return std::array<double, 2>{ d[0], d[1] };
  };
  const auto from = onScreen(a), to = onScreen(b);
  const double ux = to[0] - from[0], uy = to[1] - from[1], vx = x - from[0], vy = y - from[1];
  const double length2 = ux * ux + uy * uy;
  const double t = length2 > 0.0 ? std::clamp((ux * vx + uy * vy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(vx - t * ux, vy - t * uy);
}

int Planner::measurementAt(int x, int y, double pixels, double& distance) const
{
  int best = -1;
  distance = pixels;
  // On the CT view: the measurements drawn there, on its plane as picked,
  // in the picture's coordinates (mm along its right and up).
  const bool onScan = onScanView(x, y);
  const lkapp::ViewFrame& frame = scanPicture.frame;
  auto inPicture = [&](const std::array<double, 3>& q) {
    const std::array<double, 3> f = lkapp::inFrame(frame, q);
    return std::array<double, 3>{ f[0], f[1], 0.0 };
  };
  for (std::size_t i = 0; i < session.measurements.size(); ++i)
  {
    const Measurement& m = session.measurements[i];
    if (onScan && (!scanPicture.image || !onScanPlane(m.points(), frame)))
      continue; // not drawn on the view (measuredOnPlane's rule)
    Measurement shown = onScan ? m : placed(m, shownMatrix);
    if (onScan)
    {
      shown.from = inPicture(shown.from);
      shown.to = inPicture(shown.to);
      shown.at = inPicture(shown.at);
    }
    vtkRenderer* view = onScan ? scanRenderer.Get() : renderer.Get();
    const double d = shown.angle
      ? std::min(pixelsFrom(view, x, y, shown.from, shown.at), pixelsFrom(view, x, y, shown.at, shown.to))
      : pixelsFrom(view, x, y, shown.from, shown.to);
    if (d <= distance)
    {
      distance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

int Planner::strokeAt(int x, int y, double pixels, double& distance) const
{
  int best = -1;
  distance = pixels;
  if (onScanView(x, y))
    return best;
  for (std::size_t l = 0; l < cut.lines.size() && l < cut.lineStrokes.size(); ++l)
  {
    vtkPolyData* line = cut.lines[l].first;
    if (!line || !line->GetLines())
      continue;
    auto it = vtk::TakeSmartPointer(line->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        std::array<double, 3> a, b;
        line->GetPoint(ids[k], a.data());
        line->GetPoint(ids[k + 1], b.data());
        const double d = pixelsFrom(renderer, x, y, a, b);
        if (d <= distance)
        {
          distance = d;
          best = static_cast<int>(cut.lineStrokes[l]);
        }
      }
    }
  }
  // A stroke that made no line (its message says why) is found where it
  // was drawn, so that Delete can take it out of the plan.
  for (std::size_t i = 0; i < session.strokes.size(); ++i)
  {
    if (!cut.madeNoLine(i))
      continue;
    const std::vector<std::array<double, 3>>& points = session.strokes[i].points;
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      const double d = pixelsFrom(renderer, x, y, points[k], points[std::min(k + 1, points.size() - 1)]);
      if (d <= distance)
      {
        distance = d;
        best = static_cast<int>(i);
      }
    }
  }
  return best;
}

void Planner::showMeasurements()
{
  for (const auto& c : measureCaptions)
    renderer->RemoveViewProp(c);
  measureCaptions.clear();
  if (measureActor)
    overlay->RemoveActor(measureActor);
  measureActor = nullptr;
  // The points clicked so far, while the next is awaited.
  measureMarker->SetVisibility(measuring && !measurePicked.empty());
  if (measuring && !measurePicked.empty())
  {
    vtkNew<vtkAppendPolyData> balls;
    for (std::size_t k = 0; k < measurePicked.size(); ++k)
      balls->AddInputData(ballAt(shownPoint(measurePicked[k], measurePickedPieces[k], shownMatrix), 0.5 * joinTolerance));
    balls->Update();
    vtkPolyDataMapper::SafeDownCast(measureMarker->GetMapper())->SetInputData(balls->GetOutput());
  }
  showScanMoved(shownMatrix); // and on the CT view, what lies on its plane
  if (session.measurements.empty())
    return;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines, ends;
  for (const Measurement& m : session.measurements)
  {
    const Measurement shown = placed(m, shownMatrix);
    const vtkIdType a = points->InsertNextPoint(shown.from.data());
    const vtkIdType b = points->InsertNextPoint(shown.to.data());
    ends->InsertNextCell(1, &a);
    ends->InsertNextCell(1, &b);
    // A distance's line, with its length below its middle (beside where a
    // name's caption would be); an angle's arms, with its degrees at its
    // vertex.
    std::array<double, 3> label;
    if (m.angle)
    {
      const vtkIdType c = points->InsertNextPoint(shown.at.data());
      const vtkIdType arms[3] = { a, c, b };
      lines->InsertNextCell(3, arms);
      ends->InsertNextCell(1, &c);
      label = shown.at;
    }
    else
    {
      const vtkIdType ids[2] = { a, b };
      lines->InsertNextCell(2, ids);
      for (std::size_t k = 0; k < 3; ++k)
        label[k] = 0.5 * (shown.from[k] + shown.to[k]);
    }
    const std::string text = valueText(shown);
    auto caption = captionActor(text, { 0.45, 0.0, 0.4 }, 14, MeasureCaptionOffset);
    caption->SetAttachmentPoint(label.data());
    renderer->AddViewProp(caption);
    measureCaptions.push_back(caption);
  }
  vtkNew<vtkPolyData> shown;
  shown->SetPoints(points);
  shown->SetLines(lines);
  shown->SetVerts(ends);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(shown);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.55, 0.0, 0.45);
  actor->GetProperty()->SetLineWidth(3);
  actor->GetProperty()->SetPointSize(9);
  actor->GetProperty()->RenderPointsAsSpheresOn();
  actor->PickableOff();
  overlay->AddActor(actor);
  measureActor = actor;
}

} // namespace lkplanner
