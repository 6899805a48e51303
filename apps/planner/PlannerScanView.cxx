// latticekit-planner: the CT view (c, C): the scan on a cut line's plane or across
// it, its window, its plane moved off the cut, its square on the bone, and the export's pictures
// of it.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"
#include "common/CutReport.h"
#include "common/PlaneSection.h"

#include "vtkLKMedicalImageReader.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkMath.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkMatrix4x4.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <cstring>
#include <cstdlib>
#include <string>
#include <vector>

namespace lkplanner
{

std::vector<int> Planner::closedCutLines() const
{
  std::vector<int> numbers;
  const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(cut.loops);
  for (std::size_t k = 0; k < facts.size(); ++k)
    if (facts[k].closed)
      numbers.push_back(static_cast<int>(k) + 1);
  return numbers;
}

bool Planner::scanPictureOf(int number, bool across, double offset, lkapp::ScanPicture& picture, std::string& why)
{
  const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(cut.loops);
  if (number < 1 || number > static_cast<int>(facts.size()) || !facts[static_cast<std::size_t>(number - 1)].closed)
  {
    why = "the plan has no closed cut line " + std::to_string(number) +
      (facts.empty() ? " (the plan is not cut: x)" : "");
    return false;
  }
  lkapp::ScanPictureRequest request;
  const lkapp::LineFacts& f = facts[static_cast<std::size_t>(number - 1)];
  request.centre = { f.centre[0], f.centre[1], f.centre[2] };
  request.normal = { f.normal[0], f.normal[1], f.normal[2] };
  request.across = across;
  request.softTissue = session.softTissueWindow;
  request.offset = offset;
  request.patientGiven = patientStated();
  request.patient = session.patient;
  request.windowWidth = session.scanWindowWidth;
  request.windowLevel = session.scanWindowLevel;
  for (std::size_t k = 0; k < facts.size(); ++k)
    if (facts[k].closed && static_cast<int>(k) + 1 != number)
      request.otherPlanes.push_back({ { facts[k].centre[0], facts[k].centre[1], facts[k].centre[2] },
        { facts[k].normal[0], facts[k].normal[1], facts[k].normal[2] } });
  auto it = vtk::TakeSmartPointer(cut.loops->GetLines()->NewIterator());
  int k = 1;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++k)
    if (k == number)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType i = 0; i < n; ++i)
        cut.loops->GetPoint(ids[i], request.line.emplace_back().data());
      break;
    }
  if (!readScanFile(why) || !lkapp::makeScanPicture(scan, scanToPatient, scanIsLabelMap, bone, request, picture, why))
    return false;
  picture.directions = lkapp::coordinateSpace(bone) == "LPS";
  picture.title = scanTitle(picture, number, across, offset);
  return true;
}

std::string Planner::scanTitle(const lkapp::ScanPicture& picture, int number, bool across, double offset) const
{
  return scanText(number, across) + (patientStated() ? ", head up as stated" : "") +
    lkapp::planeOffsetText(picture.frame, offset, picture.directions);
}

bool Planner::patientStated() const
{
  return session.patientGiven && bone && lkapp::coordinateSpace(bone) != "LPS";
}

void Planner::previewScanWindow(double width, double level)
{
  if (!scanRenderer->GetDraw() || !scanPicture.image)
    return;
  scanPicture.grey = lkapp::handWindow(width, level);
  lkapp::showScanPicture(scanRenderer, scanPicture, 12);
}

bool Planner::readScanFile(std::string& why)
{
  if (scanFile.empty())
    return true;
  const std::string file = scanFile;
  scanFile.clear(); // read once, whatever comes of it
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(file.c_str());
  // What the reader says goes into `why`, not the terminal: its warnings
  // (the folder's other series and sets) were said when the plan was read.
  std::string said;
  vtkNew<vtkCallbackCommand> listen;
  listen->SetClientData(&said);
  listen->SetCallback([](vtkObject*, unsigned long event, void* client, void* text) {
    if (event == vtkCommand::ErrorEvent && text)
      *static_cast<std::string*>(client) += (static_cast<std::string*>(client)->empty() ? "" : "; ") +
        lkapp::cleanMessage(static_cast<const char*>(text));
  });
  reader->AddObserver(vtkCommand::ErrorEvent, listen);
  reader->AddObserver(vtkCommand::WarningEvent, listen);
  reader->Update();
  if (!said.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    why = "the CT the segmentation was drawn on ('" + file + "') could not be read" + (said.empty() ? "" : ": " + said);
    return false;
  }
  scan = vtkSmartPointer<vtkImageData>::New();
  scan->ShallowCopy(reader->GetOutput());
  scanToPatient->DeepCopy(reader->GetPatientMatrix());
  scanIsLabelMap = false;
  return true;
}

std::string Planner::scanText(int number, bool across) const
{
  return std::string(scanIsLabelMap ? "label map" : "CT") + (across ? " across cut line " : " on cut line ") +
    std::to_string(number) + (across ? "" : "'s plane");
}

std::string Planner::scanShown() const
{
  const std::string window = scanIsLabelMap ? "" :
    session.scanWindowWidth > 0.0 ? lkapp::greyWindowText(lkapp::handWindow(session.scanWindowWidth, session.scanWindowLevel)) :
    session.softTissueWindow      ? " (soft-tissue window)" : "";
  return scanTitle(scanPicture, session.scanOnLine, session.scanAcross, session.scanOffset) + window;
}

void Planner::showScan()
{
  // The distance colour bar at the right, between the orientation cube and
  // the status lines (its default place reaches down over them); at the
  // window's very edge while the scan is shown.
  scalarBar->SetPosition(0.82, 0.22);
  scalarBar->SetPosition2(0.17, 0.66);
  if (session.scanOnLine <= 0)
  {
    scanRenderer->DrawOff();
    renderer->GetActiveCamera()->SetUserTransform(nullptr);
    return;
  }
  const std::string key = cut.key + "|" + std::to_string(session.scanOnLine) + (session.scanAcross ? "|across" : "") +
    (session.softTissueWindow ? "|soft" : "") + "|" + std::to_string(session.scanOffset) + "|" +
    std::to_string(session.scanWindowWidth) + "|" + std::to_string(session.scanWindowLevel);
  if (key != scanShownKey)
  {
    scanShownKey = key;
    scanMovedKey.clear(); // placeSegment, which rebuild calls next, draws it (showScanMoved)
    scanWhy.clear();
    if (!scanPictureOf(session.scanOnLine, session.scanAcross, session.scanOffset, scanPicture, scanWhy))
      scanPicture = lkapp::ScanPicture();
    // What the mouse does there (the exported pictures have no hint).
    scanPicture.hint = scanIsLabelMap ? "wheel: move the plane" : "drag: window | wheel: move the plane";
  }
  if (!scanWhy.empty())
    addLine(message, "no " + scanText(session.scanOnLine, session.scanAcross) + ": " + scanWhy);
  scanRenderer->SetDraw(scanWhy.empty());
  // The bone's room, right of the scan: [0.38, 0.90] of the width while the
  // distance colour bar stands at the right edge, else [0.375, 0.995].
  const bool colourBar = scalarBar->GetVisibility();
  roomForScan->Identity();
  roomForScan->Translate(colourBar ? 0.28 : 0.37, 0.0, 0.0);
  roomForScan->Scale(colourBar ? 0.52 : 0.62, colourBar ? 0.52 : 0.62, 1.0);
  if (scanWhy.empty())
  {
    scalarBar->SetPosition(0.905, 0.22);
    scalarBar->SetPosition2(0.09, 0.66);
  }
  renderer->GetActiveCamera()->SetUserTransform(scanWhy.empty() ? roomForScan.Get() : nullptr);
  showScanPlane();
}

void Planner::refreshScan()
{
  message = sceneMessage; // what the scene said, not the last key's answer
  showScan();
  showScanMoved(session.segmentMatrix);
  keepChanges();
  updateStatus();
}

void Planner::showScanPlane()
{
  const bool shown = scanRenderer->GetDraw() && scanPicture.image;
  for (vtkActor* actor : { scanPlaneSheet.Get(), scanPlaneOutline.Get() })
    actor->SetVisibility(shown);
  if (!shown)
    return;
  // The picture's square, corner by corner around it.
  const lkapp::ViewFrame& f = scanPicture.frame;
  const double half = 0.5 * scanPicture.side;
  vtkNew<vtkPoints> corners;
  for (const auto& [x, y] : { std::make_pair(-half, -half), { half, -half }, { half, half }, { -half, half } })
    corners->InsertNextPoint(f.centre[0] + x * f.right[0] + y * f.up[0], f.centre[1] + x * f.right[1] + y * f.up[1],
      f.centre[2] + x * f.right[2] + y * f.up[2]);
  showSquare(corners, scanPlaneSheet, scanPlaneOutline);
}

std::vector<std::vector<std::array<double, 3>>> Planner::movedSection(
  const lkapp::ViewFrame& frame, const std::array<double, 16>& matrix) const
{
  if (!hasSegment() || isIdentity(matrix))
    return {};
  vtkNew<vtkTransform> move;
  move->SetMatrix(matrix.data());
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(pieces[static_cast<std::size_t>(movedPiece())]);
  moved->SetTransform(move);
  moved->Update();
  return lkapp::planeSectionLoops(moved->GetOutput(), frame.centre, frame.towardViewer, kBesideACap);
}

void Planner::showScanMoved(const std::array<double, 16>& matrix)
{
  if (!scanRenderer->GetDraw() || !scanPicture.image)
    return;
  std::string key = std::to_string(movedPiece()) +
    (hasSegment() ? " " + std::to_string(pieces[static_cast<std::size_t>(movedPiece())]->GetMTime()) : "");
  if (hasSegment() && !isIdentity(matrix))
    for (double v : matrix)
      key += " " + std::to_string(v);
  lkapp::ScanPicture marks; // the picture's plane and size: a waiting point's cross is sized by it
  marks.frame = scanPicture.frame;
  marks.side = scanPicture.side;
  measuredOnPlane(marks, true);
  std::string measuredKey;
  for (const auto& line : marks.measured)
    for (const auto& q : line)
      measuredKey += std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + ";";
  for (const auto& [at, text] : marks.measuredValues)
    measuredKey += text + ";";
  if (key == scanMovedKey && measuredKey == scanMeasuredKey)
    return;
  if (key != scanMovedKey)
    scanPicture.moved = movedSection(scanPicture.frame, matrix);
  scanMovedKey = key;
  scanMeasuredKey = measuredKey;
  scanPicture.measured = marks.measured;
  scanPicture.measuredValues = marks.measuredValues;
  scanPicture.measuredBeforeMove = marks.measuredBeforeMove;
  lkapp::showScanPicture(scanRenderer, scanPicture, 12);
}

bool Planner::onScanPlane(const std::vector<std::array<double, 3>>& points, const lkapp::ViewFrame& frame)
{
  return std::all_of(points.begin(), points.end(),
    [&](const std::array<double, 3>& q) { return std::abs(lkapp::inFrame(frame, q)[2]) <= kOnScanPlane; });
}

void Planner::measuredOnPlane(lkapp::ScanPicture& picture, bool picking) const
{
  picture.measured.clear();
  picture.measuredValues.clear();
  picture.measuredBeforeMove = false;
  // As picked: the CT is the scan before the segment's move.
  for (const Measurement& m : session.measurements)
  {
    if (!onScanPlane(m.points(), picture.frame))
      continue;
    // The value as picked, on the scan; where the segment's move changes
    // it (the bone's view shows the moved value), the legend says so.
    const std::string text = valueText(m);
    picture.measuredBeforeMove = picture.measuredBeforeMove || text != measuredText(m);
    if (m.angle)
    {
      picture.measured.push_back({ m.from, m.at, m.to });
      picture.measuredValues.emplace_back(m.at, text);
    }
    else
    {
      picture.measured.push_back({ m.from, m.to });
      picture.measuredValues.emplace_back(
        std::array<double, 3>{ 0.5 * (m.from[0] + m.to[0]), 0.5 * (m.from[1] + m.to[1]), 0.5 * (m.from[2] + m.to[2]) },
        text);
    }
  }
  // The points of a measurement under way: small crosses, joined.
  if (!picking || measuring == 0 || settingPlane)
    return;
  std::vector<std::array<double, 3>> waiting;
  for (const auto& q : measurePicked)
    if (onScanPlane({ q }, picture.frame))
    {
      waiting.push_back(q);
      const double arm = 0.015 * picture.side;
      for (const auto& [x, y] : { std::make_pair(1.0, 1.0), std::make_pair(1.0, -1.0) })
      {
        std::array<double, 3> a = q, b = q;
        for (std::size_t i = 0; i < 3; ++i)
        {
          a[i] -= arm * (x * picture.frame.right[i] + y * picture.frame.up[i]);
          b[i] += arm * (x * picture.frame.right[i] + y * picture.frame.up[i]);
        }
        picture.measured.push_back({ a, b });
      }
    }
  if (waiting.size() >= 2)
    picture.measured.push_back(waiting);
}

std::string Planner::scanPictureName(int number, bool across, double offset)
{
  std::string name = "cut_line" + std::to_string(number) + (across ? "_across" : "") + "_ct";
  if (offset != 0.0)
  {
    char mm[32];
    std::snprintf(mm, sizeof mm, "_%+gmm", offset);
    name += mm;
  }
  return name + ".png";
}

bool Planner::writeScanPictures(const std::string& folder, std::vector<std::string>& written, std::string& shown,
  std::string& shownTitle, std::string& error)
{
  written.clear();
  shown.clear();
  shownTitle.clear();
  if (!hasScan())
    return true;
  // Two pictures a closed line, on its plane and across it; and the view as
  // it was shown, where its plane was moved off the cut's (the wheel): the
  // canal beside the cut the surgeon looked at.
  const std::vector<int> lines = closedCutLines();
  std::vector<std::tuple<int, bool, double>> views;
  for (int number : lines)
    for (const bool across : { false, true })
      views.emplace_back(number, across, 0.0);
  if (session.scanOffset != 0.0 && std::find(lines.begin(), lines.end(), session.scanOnLine) != lines.end())
    views.emplace_back(session.scanOnLine, session.scanAcross, session.scanOffset);
  for (const auto& [number, across, offset] : views)
  {
    lkapp::ScanPicture picture;
    std::string why;
    const std::string name = scanPictureName(number, across, offset);
    const bool made = scanPictureOf(number, across, offset, picture, why);
    if (made)
    {
      picture.moved = movedSection(picture.frame, session.segmentMatrix);
      measuredOnPlane(picture, false);
    }
    if (!made ||
      !lkapp::writeScanPicture(picture, 600, folder + "/" + name, why, window->GetGenericDisplayId()))
    {
      // The others are still written.
      error += (error.empty() ? "" : "; ") + ("no " + name + ", the " + scanText(number, across) + ": " + why);
      continue;
    }
    written.push_back(name);
    if (offset != 0.0)
    {
      shown = name;
      shownTitle = picture.title;
    }
  }
  return error.empty();
}

} // namespace lkplanner
