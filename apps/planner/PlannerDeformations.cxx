// latticekit-planner: the pieces' deformations (bump, box, smoothing brush; seed
// 002): applied in order, found under the mouse and removed.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"

#include "vtkLKPatchDeformationFilter.h"

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

void Planner::addTo(vtkLKPatchDeformationFilter* f, const Deformation& d)
{
  const auto& c = d.centre;
  const double r = d.radius;
  if (d.tool == "bump")
    f->AddFunctionalDeformation(c[0], c[1], c[2], d.amount, d.falloff, r);
  else if (d.tool == "box")
    f->AddRangeDeformation(c[0] - r, c[0] + r, c[1] - r, c[1] + r, c[2] - r, c[2] + r, d.amount * d.normal[0],
      d.amount * d.normal[1], d.amount * d.normal[2]);
  else
    f->AddSmoothingDeformation(c[0], c[1], c[2], r, d.iterations);
}

vtkLKPatchDeformationFilter* Planner::deformer(std::size_t p)
{
  deformers.resize(cut.pieces.size());
  if (!deformers[p])
  {
    deformers[p] = vtkSmartPointer<vtkLKPatchDeformationFilter>::New();
    deformers[p]->SetInputData(cut.pieces[p]);
  }
  return deformers[p];
}

void Planner::applyDeformations()
{
  pieces = cut.pieces;
  std::vector<std::vector<const Deformation*>> perPiece(pieces.size());
  for (std::size_t i = 0; i < session.deformations.size(); ++i)
  {
    const Deformation& d = session.deformations[i];
    if (d.piece < static_cast<int>(pieces.size()))
      perPiece[static_cast<std::size_t>(d.piece)].push_back(&d);
    else
      addLine(message, "deformation " + std::to_string(i) + " is on piece " + std::to_string(d.piece) +
        ", which does not exist: the plan has " + std::to_string(pieces.size()) + " piece(s)");
  }
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    if (perPiece[p].empty())
    {
      if (p < deformers.size() && deformers[p])
        deformers[p]->RemoveAllDeformations(); // undone: the next drag starts from the cut piece
      continue;
    }
    vtkLKPatchDeformationFilter* f = deformer(p);
    f->RemoveAllDeformations();
    for (const Deformation* d : perPiece[p])
      addTo(f, *d);
    f->CheckCrossingsOn(); // a drag turns it off
    const int before = lkapp::errorCount();
    f->Update(); // only what changed is redone (the filter keeps its state)
    if (lkapp::errorCount() > before)
    {
      addLine(message, "cannot deform piece " + std::to_string(p) + ": " + lkapp::errorsSince(before));
      continue;
    }
    if (const vtkIdType crossings = static_cast<vtkIdType>(lkapp::fieldValue(f->GetOutput(), "SelfCrossings")))
    {
      const vtkIdType before = static_cast<vtkIdType>(lkapp::fieldValue(f->GetOutput(), "SelfCrossingsBefore"));
      if (before > 0)
        addLine(message, "piece " + std::to_string(p) + " passes through itself where it is deformed (" +
            std::to_string(crossings) + " pairs of faces cross), as it did there before (" + std::to_string(before) +
            " pairs): it is no valid solid to print");
      else
        addLine(message, "piece " + std::to_string(p) + " passes through itself after its deformations (" +
            std::to_string(crossings) + " pairs of faces cross): it is no valid solid to print; undo (z) or deform less");
    }
    auto deformed = vtkSmartPointer<vtkPolyData>::New();
    deformed->ShallowCopy(f->GetOutput());
    pieces[p] = deformed;
  }
}

int Planner::deformationAt(int piece, const std::array<double, 3>& point) const
{
  for (std::size_t i = session.deformations.size(); i-- > 0;)
  {
    const Deformation& d = session.deformations[i];
    if (d.piece != piece)
      continue;
    // What it moved, moved: its ball or cube swept along its normal by its
    // amount (a dab's amount is 0).
    std::array<double, 3> move;
    for (std::size_t k = 0; k < 3; ++k)
      move[k] = d.tool == "smooth" ? 0.0 : d.amount * d.normal[k];
    if (d.tool == "box")
    {
      // The sweep's steps s in [0, 1] that put the point in the cube.
      double low = 0.0, high = 1.0;
      for (std::size_t k = 0; k < 3 && low <= high; ++k)
      {
        const double off = point[k] - d.centre[k];
        if (move[k] == 0.0)
        {
          if (std::abs(off) > d.radius)
            high = -1.0;
          continue;
        }
        const double a = (off - d.radius) / move[k], b = (off + d.radius) / move[k];
        low = std::max(low, std::min(a, b));
        high = std::min(high, std::max(a, b));
      }
      if (low <= high)
        return static_cast<int>(i);
      continue;
    }
    // A ball swept along a segment: a capsule.
    const double length2 = vtkMath::Dot(move.data(), move.data());
    std::array<double, 3> off{ point[0] - d.centre[0], point[1] - d.centre[1], point[2] - d.centre[2] };
    const double s = length2 > 0.0 ? std::clamp(vtkMath::Dot(off.data(), move.data()) / length2, 0.0, 1.0) : 0.0;
    for (std::size_t k = 0; k < 3; ++k)
      off[k] -= s * move[k];
    if (vtkMath::Dot(off.data(), off.data()) <= d.radius * d.radius)
      return static_cast<int>(i);
  }
  return -1;
}

std::pair<std::size_t, std::size_t> Planner::deformationGroup(std::size_t i) const
{
  const auto& all = session.deformations;
  std::pair<std::size_t, std::size_t> group{ i, i };
  if (i >= all.size() || all[i].tool != "smooth")
    return group;
  // Dabs a and b = a + 1 are of one stroke: by its number, or where a
  // session does not know it, by place.
  const auto joined = [&all](std::size_t a) {
    const Deformation& d = all[a];
    const Deformation& e = all[a + 1];
    if (d.tool != "smooth" || e.tool != "smooth" || d.piece != e.piece)
      return false;
    if (d.stroke > 0 || e.stroke > 0)
      return d.stroke == e.stroke;
    return vtkMath::Distance2BetweenPoints(d.centre.data(), e.centre.data()) <= e.radius * e.radius;
  };
  while (group.first > 0 && joined(group.first - 1))
    --group.first;
  while (group.second + 1 < all.size() && joined(group.second))
    ++group.second;
  return group;
}

void Planner::removeDeformation(std::size_t i)
{
  if (i >= session.deformations.size())
    return;
  const auto group = deformationGroup(i);
  const Deformation& d = session.deformations[i];
  const std::size_t count = group.second - group.first + 1;
  if (count == 1)
    notice = "deformation " + std::to_string(i) + " (" + d.tool + " on piece " + std::to_string(d.piece) + ") removed";
  else
    notice = "deformations " + std::to_string(group.first) + " to " + std::to_string(group.second) +
      " (a smoothing brush stroke on piece " + std::to_string(d.piece) + ", " + std::to_string(count) + " dabs) removed";
  notice += " (z: back)";
  remember();
  session.deformations.erase(session.deformations.begin() + static_cast<std::ptrdiff_t>(group.first),
    session.deformations.begin() + static_cast<std::ptrdiff_t>(group.second + 1));
}

} // namespace lkplanner
