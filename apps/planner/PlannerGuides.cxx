// latticekit-planner: the cutting guides (k): for each saw line, a shell on
// the bone across the saw's plane with a slot for the blade, to print.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"
#include "common/ScanOnPlane.h"

#include "vtkLKCuttingGuideFilter.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace lkplanner
{

std::string Planner::guideFileStem(std::size_t stroke)
{
  return "guide_stroke" + std::to_string(stroke + 1);
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
    g.error = lkapp::updateKeepingErrors(g.filter); // the plan goes on without it; its message says why
    if (g.filter->GetOutput()->GetNumberOfPolys() > 0)
      g.surface = g.filter->GetOutput();
    else if (g.error.empty())
      g.error = "no guide was made";
    made.push_back(g);
  }
  guides = made;
  if (guides.empty())
  {
    addLine(message, "cutting guides (k) are made for saw lines (p): this plan has none");
    return;
  }
  vtkNew<vtkAppendPolyData> all;
  for (const CuttingGuide& g : guides)
  {
    if (g.surface)
      all->AddInputData(g.surface);
    else
      addLine(message, "no cutting guide for the saw line of stroke " + std::to_string(g.stroke + 1) + ": " + g.error);
  }
  if (all->GetNumberOfInputConnections(0) == 0)
    return;
  all->Update();
  vtkPolyDataMapper::SafeDownCast(guideActor->GetMapper())->SetInputData(all->GetOutput());
  guideActor->SetVisibility(true);
}

std::string Planner::guidesText() const
{
  std::string text;
  if (!session.guides)
    return text;
  for (const CuttingGuide& g : guides)
  {
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
      "walls %.1f mm thick, %s, resting on %.0f mm^2 of bone, put on %s(along (%.3f, %.3f, %.3f)); %.0f mm^3 "
      "(%s.stl)\n",
      g.stroke + 1, g.filter->GetSlotLength(), g.filter->GetSlotWidth(), g.filter->GetThickness(), holes,
      g.filter->GetContactArea(), side.c_str(), along[0], along[1], along[2], g.filter->GetVolume(),
      guideFileStem(g.stroke).c_str());
    text += line;
  }
  return text;
}

} // namespace lkplanner
