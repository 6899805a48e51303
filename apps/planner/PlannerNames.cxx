// latticekit-planner: the pieces' names (t): found again on a new cut, shown in
// the view.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
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

void Planner::resolveNames()
{
  std::vector<std::array<double, 3>> points;
  for (const PieceName& n : session.names)
    points.push_back(n.at);
  // The nearest pieces change with the cut or the points only (a name
  // given, taken away, undone), not at every step.
  if (cut.key != namesCutKey || points != namesAt)
  {
    const std::vector<std::vector<double>> distances =
      points.empty() ? std::vector<std::vector<double>>() : pieceDistances(points);
    nameTargets.assign(session.names.size(), -1);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      const auto best = std::min_element(distances[i].begin(), distances[i].end());
      if (best != distances[i].end() && *best < VTK_DOUBLE_MAX)
        nameTargets[i] = static_cast<int>(best - distances[i].begin());
    }
    namesCutKey = cut.key;
    namesAt = points;
  }
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
  {
    const std::string name = pieceName(p);
    for (std::size_t q = p + 1; q < cut.pieces.size() && !name.empty(); ++q)
      if (pieceName(q) == name)
        addLine(message, "piece " + std::to_string(p) + " and piece " + std::to_string(q) + " are both named '" + name +
            "' (the cut numbered them anew): name one again (t)");
  }
}

int Planner::nameIndex(std::size_t p) const
{
  for (std::size_t i = nameTargets.size(); i-- > 0;)
    if (nameTargets[i] == static_cast<int>(p))
      return static_cast<int>(i);
  return -1;
}

std::string Planner::pieceName(std::size_t p) const
{
  const int i = nameIndex(p);
  return i < 0 ? std::string() : session.names[static_cast<std::size_t>(i)].name;
}

void Planner::showNames()
{
  for (const NameCaption& c : nameCaptions)
    renderer->RemoveViewProp(c.actor);
  nameCaptions.clear();
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const int i = nameIndex(p);
    if (i < 0)
      continue;
    const std::string& name = session.names[static_cast<std::size_t>(i)].name;
    auto caption = captionActor(name, { 0.1, 0.1, 0.4 }, 15, NameCaptionOffset); // moved to its point by placeSegment
    renderer->AddViewProp(caption);
    nameCaptions.push_back({ static_cast<int>(p), session.names[static_cast<std::size_t>(i)].at, caption });
  }
}

std::string Planner::pieceLabel(std::size_t p) const
{
  const std::string name = pieceName(p);
  return "piece " + std::to_string(p) + (name.empty() ? "" : " '" + name + "'");
}

bool Planner::namePiece(std::size_t p, const std::array<double, 3>& at, const std::string& name, std::string& why)
{
  why.clear();
  if (!name.empty() && !validPieceName(name, why))
    return false;
  for (std::size_t q = 0; q < cut.pieces.size() && !name.empty(); ++q)
    if (q != p && pieceName(q) == name)
    {
      why = "piece " + std::to_string(q) + " is named '" + name + "' already";
      return false;
    }
    else if (q != p && pieceName(q).empty() && name == "piece " + std::to_string(q))
    {
      why = "'" + name + "' is what piece " + std::to_string(q) + " goes by in the structure set";
      return false;
    }
  remember();
  std::vector<PieceName> kept;
  for (std::size_t i = 0; i < session.names.size(); ++i)
    if (i >= nameTargets.size() || nameTargets[i] != static_cast<int>(p))
      kept.push_back(session.names[i]);
  if (!name.empty())
    kept.push_back({ name, at });
  session.names = kept;
  return true;
}

} // namespace lkplanner
