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
#include <vtkMath.h>
#include <vtkPlaneCollection.h> // lkapp::planeCollection
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace lkplanner
{

std::string Planner::guideFileStem(std::size_t stroke)
{
  return "guide_stroke" + std::to_string(stroke + 1);
}

std::string Planner::joinedStrokes(const JoinedGuide& joined, const std::string& separator,
  const std::string& last) const
{
  return lkapp::chainNumbers(
    joined.members, [&](std::size_t i) { return std::to_string(guides[i].stroke + 1); }, separator, last);
}

std::string Planner::joinedGuideFileStem(const JoinedGuide& joined) const
{
  return "guide_strokes" + joinedStrokes(joined, "-", "-");
}

const Planner::JoinedGuide* Planner::joinedGuideOf(std::size_t i) const
{
  for (const JoinedGuide& j : joinedGuides)
    if (j.surface && std::find(j.members.begin(), j.members.end(), i) != j.members.end())
      return &j;
  return nullptr;
}

std::vector<Planner::GuidePart> Planner::guideParts() const
{
  std::vector<GuidePart> parts;
  for (const JoinedGuide& j : joinedGuides)
    if (j.surface)
      parts.push_back({ j.surface, joinedGuideFileStem(j), "resection guide (strokes " + joinedStrokes(j) + ")" });
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
  // The plane through a point of the section a saw line cut along: the
  // guide goes on that part of the bone.
  auto planeOrigin = [](const Stroke& st) { return st.points.empty() ? st.sawOrigin : st.points.front(); };
  for (std::size_t i = 0; i < session.strokes.size(); ++i)
  {
    const Stroke& st = session.strokes[i];
    if (!st.saw)
      continue;
    const std::array<double, 3> origin = planeOrigin(st);
    // The saw lines within 40 mm of this one (a guide reaches 8 mm from its
    // slot, its screws 10 mm into the bone): its label and screw holes keep
    // clear of their guides and saws. Those farther do not remake it.
    std::vector<std::array<double, 6>> others;
    for (std::size_t k = 0; k < session.strokes.size(); ++k)
    {
      const Stroke& other = session.strokes[k];
      if (k == i || !other.saw)
        continue;
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& p : st.points)
        for (const auto& q : other.points)
          nearest = std::min(nearest, vtkMath::Distance2BetweenPoints(p.data(), q.data()));
      if (std::sqrt(nearest) > 40.0)
        continue;
      const std::array<double, 3> at = planeOrigin(other);
      others.push_back({ at[0], at[1], at[2], other.sawNormal[0], other.sawNormal[1], other.sawNormal[2] });
    }
    // The side: the filter's, the other with K (all guides), and each
    // guide's own turn (K on it) on top.
    const bool otherSide = session.guidesOtherSide != st.guideOtherSide;
    bool kept = false;
    for (const CuttingGuide& g : guides)
      if (g.stroke == i && g.origin == origin && g.normal == st.sawNormal && g.otherSide == otherSide &&
        g.others == others)
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
    g.otherSide = otherSide;
    g.others = others;
    g.filter = vtkSmartPointer<vtkLKCuttingGuideFilter>::New();
    g.filter->SetInputData(facesOnly(bone));
    g.filter->SetPlaneOrigin(origin.data());
    g.filter->SetPlaneNormal(st.sawNormal.data());
    g.filter->SetOtherSide(otherSide);
    g.filter->SetLabel(std::to_string(i + 1).c_str()); // the stroke's number, as the plan and the file name give it
    if (!others.empty())
      g.filter->SetOtherCutPlanes(lkapp::planeCollection(others));
    const int warningsBefore = lkapp::warningCount();
    g.error = lkapp::updateKeepingErrors(g.filter); // the plan goes on without it; its message says why
    g.warning = lkapp::warningsSince(warningsBefore); // a label left out
    // A screw hole left out for a saw line nearby is said in the guide's own
    // line (guidesText), in the plan's words.
    {
      std::istringstream lines(g.warning);
      std::string kept, line;
      while (std::getline(lines, line))
        if (line.find("would lie in the path of the saw") == std::string::npos)
          kept += (kept.empty() ? "" : "\n") + line;
      g.warning = kept;
    }
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
    joinAttempts.clear();
    addLine(message, "cutting guides (k) are made for saw lines (p): this plan has none");
    return;
  }
  for (const CuttingGuide& g : guides)
    if (!g.surface)
      addLine(message, "no cutting guide for the saw line of stroke " + std::to_string(g.stroke + 1) + ": " + g.error);
    else if (!g.warning.empty())
      addLines(message, "the cutting guide of stroke " + std::to_string(g.stroke + 1) + ": ", g.warning);
  // Guides on saw lines nearer than their reaches cannot be on the bone
  // together (nor be joined by a bar).
  std::vector<vtkPolyData*> surfaces;
  for (const CuttingGuide& g : guides)
    surfaces.push_back(g.surface);
  const std::vector<lkapp::GuideOverlap> overlaps = lkapp::overlappingGuides(surfaces);
  updateJoinedGuides();
  for (const lkapp::GuideOverlap& o : overlaps)
  {
    // Merged into one block (j): one part with both slots.
    if (const JoinedGuide* part = joinedGuideOf(o.first); part && part == joinedGuideOf(o.second))
      continue;
    char line[400];
    std::snprintf(line, sizeof line,
      "the cutting guides of strokes %zu and %zu overlap over %.1f mm along the bone: they cannot be on it "
      "together; put them on one after the other,%s or move a saw line that much farther",
      guides[o.first].stroke + 1, guides[o.second].stroke + 1, o.along,
      session.guidesJoined ? "" : " join them into one block with both slots (j),");
    addLine(message, line);
  }
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
    joinAttempts.clear();
    return;
  }
  if (guides.size() < 2)
  {
    joinedGuides.clear();
    joinAttempts.clear();
    addLine(message, "cutting guides are joined (j) along the bone, saw line to saw line: this plan has one");
    return;
  }
  // The chains: each saw line joined to the next that bounds one piece of
  // the cut with it (the segment between them), as they lie along the bone,
  // not as they were drawn.
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
  const std::vector<std::vector<std::size_t>> chains = lkapp::chainLinesByPiece(piecesOf);
  // Each chain joined, or as much of it as can be (lkapp::joinChain), each
  // part made anew only when one of its guides was.
  std::vector<JoinedGuide> tried; // this update's parts, made or not: the next one's to keep
  auto strokeOf = [&](std::size_t g) { return std::to_string(guides[g].stroke + 1); };
  auto join = [&](const std::vector<std::size_t>& members) {
    JoinedGuide j;
    j.members = members;
    for (std::size_t i : members)
      j.made.push_back(guides[i].surface);
    const auto kept = std::find_if(joinAttempts.begin(), joinAttempts.end(), [&](const JoinedGuide& old) {
      return old.made.size() == j.made.size() && std::equal(old.made.begin(), old.made.end(), j.made.begin());
    });
    if (kept != joinAttempts.end())
    {
      j = *kept;
      j.members = members;
    }
    else
    {
      j.filter = vtkSmartPointer<vtkLKGuideBarFilter>::New();
      j.filter->SetBoneData(facesOnly(bone));
      for (std::size_t i : members)
        j.filter->AddGuideData(guides[i].surface);
      j.error = lkapp::updateKeepingErrors(j.filter); // the guides stay apart; its message says why
      if (j.filter->GetOutput()->GetNumberOfPolys() > 0)
        j.surface = j.filter->GetOutput();
      else if (j.error.empty())
        j.error = "no bar was made";
    }
    tried.push_back(j);
    return j.surface ? std::string() : lkapp::guidesByLine(j.error, members, "stroke", strokeOf);
  };
  std::vector<JoinedGuide> made;
  for (const auto& chain : chains)
  {
    for (std::size_t i : chain)
      if (!guides[i].surface)
        addLine(message, "the resection guide leaves out stroke " + strokeOf(i) + ": its cutting guide could not be made");
    for (const lkapp::JoinedRun& run :
      lkapp::joinChain(chain, [&](std::size_t i) { return guides[i].surface != nullptr; }, join))
    {
      if (!run.error.empty())
      {
        addLine(message, "the cutting guides of strokes " + lkapp::chainNumbers(run.lines, strokeOf) +
            (run.lines.size() > 2 ? " are not joined in one part: " : " are not joined: ") + run.error);
        continue;
      }
      const auto part = std::find_if(
        tried.rbegin(), tried.rend(), [&](const JoinedGuide& j) { return j.members == run.lines; });
      if (part != tried.rend())
        made.push_back(*part);
    }
  }
  // The guides in no chain, and why.
  for (std::size_t i = 0; i < guides.size(); ++i)
    if (const std::string why = lkapp::whyLineStaysApart(i, piecesOf, chains, "saw line", "stroke", strokeOf);
        !why.empty())
      addLine(message, "the cutting guide of stroke " + strokeOf(i) + " stays apart: " + why);
  joinedGuides = made;
  joinAttempts = tried;
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
    char holes[160] = "no screw hole";
    if (screwHoles > 0)
      std::snprintf(holes, sizeof holes, "%d screw hole%s of %.1f mm%s", screwHoles, screwHoles == 1 ? "" : "s",
        g.filter->GetScrewHoleDiameter(),
        g.filter->GetNumberOfScrewHolesLeftOut() > 0 ? " (the other's screw would lie in a nearby saw line's path)"
                                                      : "");
    else if (g.filter->GetNumberOfScrewHolesLeftOut() > 0)
      std::snprintf(holes, sizeof holes, "no screw hole (their screws would lie in nearby saw lines' paths)");
    char line[700];
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
    // One part, put on along one direction (each guide's contact faces it).
    const double* approach = j.filter->GetApproachUsed();
    const std::string side = lkapp::coordinateSpace(bone) == "LPS"
      ? std::string("from ") + lkapp::directionWord({ approach[0], approach[1], approach[2] }) + " "
      : std::string();
    char line[800];
    std::snprintf(line, sizeof line,
      "resection guide: the cutting guides of strokes %s %s; put on %s(%s); %.0f mm^3 in one part (%s.stl)\n",
      joinedStrokes(j).c_str(),
      lkapp::joinText(j.filter, j.members, "stroke", [&](std::size_t i) { return std::to_string(guides[i].stroke + 1); })
        .c_str(),
      side.c_str(), lkapp::insertionText(j.filter).c_str(),
      j.filter->GetVolume(), joinedGuideFileStem(j).c_str());
    text += line;
  }
  return text;
}

} // namespace lkplanner
