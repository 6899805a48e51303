// latticekit-planner: the cutting guides (k): for each saw line, a shell on
// the bone across the saw's plane with a slot for the blade, to print.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"
#include "common/GuidePairs.h"
#include "common/ScanOnPlane.h"

#include "vtkLKCuttingGuideFilter.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace lkplanner
{

std::string Planner::guideFileStem(std::size_t stroke)
{
  return "guide_stroke" + std::to_string(stroke + 1);
}

std::string Planner::joinedGuideFileStem(const JoinedGuide& joined) const
{
  return "guide_strokes" + std::to_string(guides[joined.first].stroke + 1) + "-" +
    std::to_string(guides[joined.second].stroke + 1);
}

const Planner::JoinedGuide* Planner::joinedGuideOf(std::size_t i) const
{
  for (const JoinedGuide& j : joinedGuides)
    if (j.surface && (j.first == i || j.second == i))
      return &j;
  return nullptr;
}

std::vector<Planner::GuidePart> Planner::guideParts() const
{
  std::vector<GuidePart> parts;
  for (const JoinedGuide& j : joinedGuides)
    if (j.surface)
      parts.push_back({ j.surface, joinedGuideFileStem(j),
        "resection guide (strokes " + std::to_string(guides[j.first].stroke + 1) + " and " +
          std::to_string(guides[j.second].stroke + 1) + ")" });
  for (std::size_t i = 0; i < guides.size(); ++i)
    if (guides[i].surface && !joinedGuideOf(i))
      parts.push_back({ guides[i].surface, guideFileStem(guides[i].stroke),
        "cutting guide (stroke " + std::to_string(guides[i].stroke + 1) + ")" });
  return parts;
}

void Planner::updateGuides()
{
  guideActor->SetVisibility(false);
  if (!session.guides)
    return;
  if (guidesBone != bone.Get() || guidesBoneTime != bone->GetMTime())
    guides.clear(); // another bone: every guide anew
  guidesBone = bone;
  guidesBoneTime = bone->GetMTime();
  std::vector<CuttingGuide> made;
  for (std::size_t i = 0; i < session.strokes.size(); ++i)
  {
    const Stroke& st = session.strokes[i];
    if (!st.saw)
      continue;
    // The plane through a point of the section the saw line cut along: the
    // guide goes on that part of the bone.
    const std::array<double, 3> origin = st.points.empty() ? st.sawOrigin : st.points.front();
    bool kept = false;
    for (const CuttingGuide& g : guides)
      if (g.stroke == i && g.origin == origin && g.normal == st.sawNormal && g.otherSide == session.guidesOtherSide)
      {
        made.push_back(g);
        kept = true;
        break;
      }
    if (kept)
      continue;
    CuttingGuide g;
    g.stroke = i;
    g.origin = origin;
    g.normal = st.sawNormal;
    g.otherSide = session.guidesOtherSide;
    g.filter = vtkSmartPointer<vtkLKCuttingGuideFilter>::New();
    g.filter->SetInputData(facesOnly(bone));
    g.filter->SetPlaneOrigin(origin.data());
    g.filter->SetPlaneNormal(st.sawNormal.data());
    g.filter->SetOtherSide(session.guidesOtherSide);
    g.filter->SetLabel(std::to_string(i + 1).c_str()); // the stroke's number, as the plan and the file name give it
    const int warningsBefore = lkapp::warningCount();
    g.error = lkapp::updateKeepingErrors(g.filter); // the plan goes on without it; its message says why
    g.warning = lkapp::warningsSince(warningsBefore); // a label left out
    if (g.filter->GetOutput()->GetNumberOfPolys() > 0)
      g.surface = g.filter->GetOutput();
    else if (g.error.empty())
      g.error = "no guide was made";
    made.push_back(g);
  }
  guides = made;
  if (guides.empty())
  {
    joinedGuides.clear();
    addLine(message, "cutting guides (k) are made for saw lines (p): this plan has none");
    return;
  }
  for (const CuttingGuide& g : guides)
    if (!g.surface)
      addLine(message, "no cutting guide for the saw line of stroke " + std::to_string(g.stroke + 1) + ": " + g.error);
    else if (!g.warning.empty())
      addLines(message, "the cutting guide of stroke " + std::to_string(g.stroke + 1) + ": ", g.warning);
  updateJoinedGuides();
  vtkNew<vtkAppendPolyData> all;
  for (const GuidePart& part : guideParts())
    all->AddInputData(part.surface);
  if (all->GetNumberOfInputConnections(0) == 0)
    return;
  all->Update();
  vtkPolyDataMapper::SafeDownCast(guideActor->GetMapper())->SetInputData(all->GetOutput());
  guideActor->SetVisibility(true);
}

void Planner::updateJoinedGuides()
{
  if (!session.guidesJoined)
  {
    joinedGuides.clear();
    return;
  }
  if (guides.size() < 2)
  {
    joinedGuides.clear();
    addLine(message, "cutting guides are joined (j) in pairs of saw lines: this plan has one");
    return;
  }
  // The pairs: two saw lines that bound one piece of the cut (the segment
  // between them), as they lie along the bone, not as they were drawn.
  std::vector<std::vector<std::array<double, 3>>> lines(guides.size());
  for (std::size_t i = 0; i < guides.size(); ++i)
    for (std::size_t k = 0; k < cut.lineStrokes.size(); ++k)
      if (cut.lineStrokes[k] == guides[i].stroke)
      {
        vtkPolyData* line = cut.lines[k].first;
        for (vtkIdType p = 0; p < line->GetNumberOfPoints(); ++p)
        {
          double x[3];
          line->GetPoint(p, x);
          lines[i].push_back({ x[0], x[1], x[2] });
        }
      }
  std::vector<vtkPolyData*> pieces;
  double size = 0.0;
  for (const auto& piece : cut.pieces)
  {
    pieces.push_back(piece);
    size = std::max(size, piece->GetLength());
  }
  const std::vector<std::set<std::size_t>> piecesOf = lkapp::piecesAlongLines(pieces, lines, 1e-6 * size);
  const std::vector<std::pair<std::size_t, std::size_t>> pairs = lkapp::pairLinesByPiece(piecesOf);
  std::vector<JoinedGuide> made;
  for (const auto& pair : pairs)
  {
    const std::size_t i = pair.first, i2 = pair.second;
    const CuttingGuide& a = guides[i];
    const CuttingGuide& b = guides[i2];
    const std::string which =
      "strokes " + std::to_string(a.stroke + 1) + " and " + std::to_string(b.stroke + 1);
    if (!a.surface || !b.surface)
    {
      addLine(message, "the cutting guides of " + which + " are not joined: the guide of stroke " +
          std::to_string((a.surface ? b : a).stroke + 1) + " could not be made");
      continue;
    }
    bool kept = false;
    for (const JoinedGuide& j : joinedGuides)
      if (j.firstSurface == a.surface && j.secondSurface == b.surface)
      {
        made.push_back(j);
        made.back().first = i;
        made.back().second = i2;
        kept = true;
        break;
      }
    if (!kept)
    {
      JoinedGuide j;
      j.first = i;
      j.second = i2;
      j.firstSurface = a.surface;
      j.secondSurface = b.surface;
      j.filter = vtkSmartPointer<vtkLKGuideBarFilter>::New();
      j.filter->SetBoneData(facesOnly(bone));
      j.filter->AddGuideData(a.surface);
      j.filter->AddGuideData(b.surface);
      j.error = lkapp::updateKeepingErrors(j.filter); // the guides stay apart; its message says why
      if (j.filter->GetOutput()->GetNumberOfPolys() > 0)
        j.surface = j.filter->GetOutput();
      else if (j.error.empty())
        j.error = "no bar was made";
      made.push_back(j);
    }
    if (!made.back().surface)
      addLine(message, "the cutting guides of " + which + " are not joined: " + made.back().error);
  }
  // The guides in no pair, and why.
  for (std::size_t i = 0; i < guides.size(); ++i)
  {
    if (std::any_of(pairs.begin(), pairs.end(), [&](const auto& p) { return p.first == i || p.second == i; }))
      continue;
    auto strokeOf = [&](std::size_t g) { return std::to_string(guides[g].stroke + 1); };
    const std::string why = lkapp::whyLineStaysApart(i, piecesOf, pairs, "saw line", "stroke", strokeOf);
    addLine(message, "the cutting guide of stroke " + strokeOf(i) + " stays apart: " + why);
  }
  joinedGuides = made;
}

std::string Planner::guidesText() const
{
  std::string text;
  if (!session.guides)
    return text;
  for (std::size_t i = 0; i < guides.size(); ++i)
  {
    const CuttingGuide& g = guides[i];
    if (!g.surface)
      continue; // its message says why
    // The side it goes on, in the patient's words where the bone's
    // coordinates are known (LPS).
    const double* approach = g.filter->GetApproachUsed();
    const std::array<double, 3> along = lkapp::guideDirection(approach);
    const std::string side = lkapp::coordinateSpace(bone) == "LPS"
      ? std::string("from ") + lkapp::directionWord({ approach[0], approach[1], approach[2] }) + " "
      : std::string();
    const int screwHoles = g.filter->GetNumberOfScrewHoles();
    char holes[80] = "no screw hole";
    if (screwHoles > 0)
      std::snprintf(holes, sizeof holes, "%d screw hole%s of %.1f mm", screwHoles, screwHoles == 1 ? "" : "s",
        g.filter->GetScrewHoleDiameter());
    char line[500];
    std::snprintf(line, sizeof line,
      "cutting guide for the saw line of stroke %zu: slot %.1f mm long and %.1f mm wide in the saw's plane, "
      "walls %.1f mm thick, %s%s, resting on %.0f mm^2 of bone, put on %s(along (%.3f, %.3f, %.3f)); %.0f mm^3 "
      "(%s.stl)\n",
      g.stroke + 1, g.filter->GetSlotLength(), g.filter->GetSlotWidth(), g.filter->GetThickness(), holes,
      g.filter->GetLabelPlaced() ? (", labelled \"" + std::string(g.filter->GetLabel()) + "\"").c_str() : "",
      g.filter->GetContactArea(), side.c_str(), along[0], along[1], along[2], g.filter->GetVolume(),
      (joinedGuideOf(i) ? "in " + joinedGuideFileStem(*joinedGuideOf(i)) : guideFileStem(g.stroke)).c_str());
    text += line;
  }
  for (const JoinedGuide& j : joinedGuides)
  {
    if (!j.surface)
      continue; // its message says why
    char line[400];
    std::snprintf(line, sizeof line,
      "resection guide: the cutting guides of strokes %zu and %zu joined by a bar of %.1f mm, %.0f mm long and "
      "%.1f mm clear of the bone between them; %.0f mm^3 in one part (%s.stl)\n",
      guides[j.first].stroke + 1, guides[j.second].stroke + 1, j.filter->GetBarDiameter(), j.filter->GetBarLength(),
      j.filter->GetBarGap(), j.filter->GetVolume(), joinedGuideFileStem(j).c_str());
    text += line;
  }
  return text;
}

} // namespace lkplanner
