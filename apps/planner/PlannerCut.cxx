// latticekit-planner: strokes, saw lines and the cut: the strokes' feature lines,
// the capped pieces and their lines, where each piece lies, what follows a piece when the cut
// numbers them anew, and each piece's facts.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"
#include "common/CutReport.h"
#include "common/PlaneSection.h"

#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKPolyDataConversion.h"

#include "latticekit/ClosestPointTree.h"
#include "vtkLKStrokeFeatureLineFilter.h"
#include "vtkLKText.h"

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
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>
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
#include <map>
#include <set>
#include <cstdlib>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace lkplanner
{

namespace
{
double distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a.data(), b.data()));
}
} // namespace

std::vector<std::array<double, 3>> Planner::openEnds() const
{
  if (!cut.lastLineOpen || session.strokes.empty() || session.strokes.back().points.size() < 2)
    return {};
  const auto& points = session.strokes.back().points;
  return { points.front(), points.back() };
}

bool Planner::addSawStroke(const std::array<double, 3>& origin, const std::array<double, 3>& normal,
  const std::array<double, 3>& onBone, std::string& why)
{
  // The point under the line lies on the plane and on the bone, so on the
  // section: a loop farther away is another part of the bone.
  double gap = 0.0;
  Stroke saw;
  saw.points = sectionStroke(origin, normal, onBone, gap);
  if (saw.points.empty() || gap > joinTolerance)
  {
    why = "the saw line's plane meets the bone there in no closed loop (at an open border of the surface?)";
    return false;
  }
  saw.mode = vtkLKStrokeFeatureLineFilter::SPLIT;
  saw.saw = true;
  saw.sawOrigin = origin;
  saw.sawNormal = normal;
  session.strokes.push_back(saw);
  return true;
}

std::vector<std::array<double, 3>> Planner::sectionStroke(const std::array<double, 3>& origin,
  const std::array<double, 3>& normal, const std::array<double, 3>& near, double& gap) const
{
  const auto loops = lkapp::planeSectionLoops(bone, origin, normal);
  const int nearest = lkapp::nearestLoop(loops, near, &gap);
  if (nearest < 0)
    return {};
  return lkapp::strokeAlongLoop(loops[static_cast<std::size_t>(nearest)], sawStep(), 0.0);
}

std::vector<std::array<double, 3>> Planner::sawPoints(const Stroke& st, std::string& why) const
{
  double gap = 0.0;
  std::vector<std::array<double, 3>> points =
    sectionStroke(st.sawOrigin, st.sawNormal, st.points.empty() ? st.sawOrigin : st.points.front(), gap);
  if (points.empty())
  {
    why = "its plane meets this bone in no closed loop; the line as it was drawn is used";
    return st.points;
  }
  return points;
}

bool Planner::addStroke(const std::vector<std::array<double, 3>>& points)
{
  const std::vector<std::array<double, 3>> ends = openEnds();
  if (!points.empty() && !ends.empty() && session.strokes.back().mode == mode)
  {
    auto& last = session.strokes.back().points;
    if (distance(points.front(), ends[1]) <= joinTolerance)
    {
      last.insert(last.end(), points.begin(), points.end());
      return true;
    }
    if (distance(points.front(), ends[0]) <= joinTolerance)
    {
      last.insert(last.begin(), points.rbegin(), points.rend());
      return true;
    }
  }
  session.strokes.push_back({ mode, points });
  return false;
}

FeatureEdges faceEdgesOf(vtkPolyData* piece, const std::vector<char>* only)
{
  FeatureEdges edges;
  auto flagged = [&](vtkIdType v) {
    return !only || (v >= 0 && static_cast<std::size_t>(v) < only->size() && (*only)[static_cast<std::size_t>(v)]);
  };
  auto it = vtk::TakeSmartPointer(piece->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
      if (flagged(ids[k]) && flagged(ids[(k + 1) % n]))
        edges.push_back({ std::min(ids[k], ids[(k + 1) % n]), std::max(ids[k], ids[(k + 1) % n]) });
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

namespace
{
/// The first two closed lines that share a point of the surface, as a
/// sentence; empty when they are all apart.
std::string closedLinesMeeting(const std::vector<vtkSmartPointer<vtkPolyData>>& lines,
  const std::vector<std::string>& names, vtkPolyData* surface)
{
  std::map<vtkIdType, std::size_t> owner; // mesh point -> the first line through it
  for (std::size_t l = 0; l < lines.size(); ++l)
  {
    vtkDataArray* ids = lines[l]->GetPointData()->GetArray("MeshPointId");
    std::set<vtkIdType> own;
    for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
      own.insert(static_cast<vtkIdType>(ids->GetComponent(i, 0)));
    for (vtkIdType v : own)
    {
      const auto [it, added] = owner.emplace(v, l);
      if (added || v < 0 || v >= surface->GetNumberOfPoints())
        continue;
      double p[3];
      surface->GetPoint(v, p);
      char place[80];
      std::snprintf(place, sizeof(place), "(%.1f, %.1f, %.1f)", p[0], p[1], p[2]);
      return names[it->second] + " and " + names[l] + " meet on the bone at " + place +
        ": each cut needs a closed line apart from the others (two cuts that meet, as a closed wedge's, are "
        "not supported); undo one (z) or draw it apart";
    }
  }
  return {};
}

/// The feature edges of `piece` (its point ids, smaller first): the edges of
/// its cut lines (MeshPointId naming its points; may be null) and of the
/// strokes' `lines` (MeshPointId naming the points of `surface`, the one the
/// cut was made on, which the piece's point data "InputPointId" maps; without
/// it the piece is that surface) that are edges of its faces.
FeatureEdges featureEdgesOf(vtkPolyData* piece, vtkPolyData* cutLines,
  const std::vector<std::pair<vtkSmartPointer<vtkPolyData>, double>>& lines, vtkPolyData* surface)
{
  // The lines' edges in the piece's ids first; then one pass over its faces
  // keeps only the edges between their points (not every edge of a skull's
  // 1.5 million faces, sorted, as before: a second for a bone without lines).
  const vtkIdType points = piece->GetNumberOfPoints();
  FeatureEdges wanted;
  auto add = [&](vtkIdType a, vtkIdType b) {
    if (a >= 0 && b >= 0 && a != b && a < points && b < points)
      wanted.push_back({ std::min(a, b), std::max(a, b) });
  };
  std::vector<lk::EdgeKey> edges;
  if (cutLines)
    lkvtk::lineEdges(cutLines, piece, edges);
  for (const auto& [a, b] : edges)
    add(a, b);
  if (!lines.empty())
  {
    vtkDataArray* input = piece->GetPointData()->GetArray("InputPointId");
    std::vector<vtkIdType> toPiece; // surface point -> the first piece point from it, -1: none
    for (vtkIdType i = 0; input && i < input->GetNumberOfTuples(); ++i)
    {
      const double v = input->GetTuple1(i);
      if (!(v >= 0.0 && v < 1e15))
        continue;
      const auto at = static_cast<std::size_t>(v);
      if (at >= toPiece.size())
        toPiece.resize(std::max(at + 1, 2 * toPiece.size()), -1);
      if (toPiece[at] < 0)
        toPiece[at] = i;
    }
    auto inPiece = [&](vtkIdType v) -> vtkIdType {
      if (!input)
        return v;
      return v >= 0 && static_cast<std::size_t>(v) < toPiece.size() ? toPiece[static_cast<std::size_t>(v)] : -1;
    };
    for (const auto& line : lines)
    {
      edges.clear();
      lkvtk::lineEdges(line.first, surface, edges);
      for (const auto& [a, b] : edges)
        add(inPiece(a), inPiece(b));
    }
  }
  if (wanted.empty())
    return {};
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  std::vector<char> onLine(static_cast<std::size_t>(points), 0);
  for (const auto& e : wanted)
    onLine[static_cast<std::size_t>(e[0])] = onLine[static_cast<std::size_t>(e[1])] = 1;
  const FeatureEdges between = faceEdgesOf(piece, &onLine);
  FeatureEdges kept;
  std::set_intersection(wanted.begin(), wanted.end(), between.begin(), between.end(), std::back_inserter(kept));
  return kept;
}

/// A piece as the planner keeps it: its cells and points, its field data and
/// the cell data "Cap" alone.
vtkSmartPointer<vtkPolyData> withCapOnly(vtkPolyData* piece)
{
  auto kept = vtkSmartPointer<vtkPolyData>::New();
  kept->ShallowCopy(piece);
  kept->GetPointData()->Initialize();
  kept->GetCellData()->Initialize();
  if (vtkDataArray* cap = piece->GetCellData()->GetArray("Cap"))
    kept->GetCellData()->AddArray(cap);
  return kept;
}
} // namespace

void Planner::computeCut()
{
  const std::string key = cutKey(session);
  if (!cut.pieces.empty() && cut.key == key)
    return;
  cut = CutStage();
  cut.key = key;
  deformers.clear();
  // The strokes' results kept from the last rebuild, as far as the strokes
  // are the same and on the same bone, from the last step whose surface is
  // kept.
  if (strokeStepsBone != bone.Get() || strokeStepsBoneTime != bone->GetMTime())
  {
    strokeSteps.clear();
    strokeStepsBone = bone;
    strokeStepsBoneTime = bone->GetMTime();
  }
  std::size_t same = 0;
  while (same < strokeSteps.size() && same < session.strokes.size() &&
    strokeSteps[same].key == strokeKey(session.strokes[same]))
    ++same;
  std::size_t from = same;
  while (from > 0 && !strokeSteps[from - 1].surface)
    --from;
  // Steps past the last stroke (one undone) stay for a redo while every
  // stroke is as it was.
  if (from < session.strokes.size())
    strokeSteps.resize(from);
  strokesReused += from;
  strokesMade += session.strokes.size() - from;
  auto strokeName = [&](std::size_t i) {
    const Stroke& st = session.strokes[i];
    return "stroke " + std::to_string(i + 1) + " (" + (st.saw ? "saw line" : modeName(st.mode)) + ")";
  };
  StrokeStep state;
  if (from > 0)
    state = strokeSteps[from - 1];
  else
    state.surface = bone;
  for (std::size_t i = from; i < session.strokes.size(); ++i)
  {
    state.key = strokeKey(session.strokes[i]);
    const Stroke& st = session.strokes[i];
    const std::string which = strokeName(i);
    // A saw line follows its plane's section of this bone (the same points
    // as when it was drawn on the same bone).
    std::string sawWhy;
    const std::vector<std::array<double, 3>> points = st.saw ? sawPoints(st, sawWhy) : st.points;
    if (!sawWhy.empty())
      addLine(state.message, which + ": " + sawWhy);
    vtkNew<vtkPoints> pts;
    for (const auto& p : points)
      pts->InsertNextPoint(p.data());
    vtkNew<vtkPolyData> stroke;
    stroke->SetPoints(pts);
    vtkNew<vtkLKStrokeFeatureLineFilter> f;
    f->SetInputData(facesOnly(state.surface));
    f->SetStrokeData(stroke);
    f->SetMode(st.mode);
    const int errorsBefore = lkapp::errorCount(), warningsBefore = lkapp::warningCount();
    f->Update();
    const std::string warned = lkapp::warningsSince(warningsBefore);
    if (!warned.empty())
      addLines(state.message, which + ": ", warned);
    if (lkapp::errorCount() > errorsBefore || f->GetOutput()->GetNumberOfPoints() == 0)
    {
      const std::string why = lkapp::errorsSince(errorsBefore);
      // The stroke stays in the session (what the surgeon drew is not
      // thrown away); the message says why it failed and how it goes.
      addLine(state.message, which + " failed: " + (why.empty() ? "no feature line" : why) +
          " (Delete with the mouse where it was drawn removes it)");
      strokeSteps.push_back(state);
      continue;
    }
    auto next = vtkSmartPointer<vtkPolyData>::New();
    next->ShallowCopy(f->GetOutput());
    state.surface = next;
    // The earlier lines onto the new surface: a split stroke that crosses
    // one cuts its edges (the cut needs its loops along the mesh's edges).
    // New objects: the earlier steps keep theirs.
    for (auto& earlier : state.lines)
    {
      auto carried = vtkSmartPointer<vtkPolyData>::New();
      if (f->CarryLine(earlier.first, carried))
        earlier.first = carried;
    }
    auto line = vtkSmartPointer<vtkPolyData>::New();
    line->DeepCopy(f->GetFeatureLineOutput());
    state.lines.emplace_back(line, st.mode == vtkLKStrokeFeatureLineFilter::PAINT ? 0.2 : 0.0);
    state.lineStrokes.push_back(i);
    strokeSteps.push_back(state);
  }
  // The surfaces kept: after the last stroke and the three before it (a
  // stroke drawn on, the last continued, up to three undone in a row), and
  // after the next two past them (redone). Older ones go: a skull's surface
  // is 60 MB.
  const std::size_t n = session.strokes.size();
  for (std::size_t i = 0; i < strokeSteps.size(); ++i)
    if (i + 4 < n || i > n + 1)
      strokeSteps[i].surface = nullptr;
  cut.lines = state.lines;
  cut.lineStrokes = state.lineStrokes;
  cut.message = state.message;
  vtkSmartPointer<vtkPolyData> surface = state.surface;
  // The closed lines the cut takes (a painted line marks faces and cuts
  // nothing; a line keeps its field data "Closed" when carried), and whether
  // the last stroke left an open line that a drag can continue.
  auto closed = [](vtkPolyData* line) { return line->GetFieldData()->GetArray("Closed")->GetComponent(0, 0) > 0.5; };
  auto painted = [&](std::size_t l) {
    return session.strokes[state.lineStrokes[l]].mode == vtkLKStrokeFeatureLineFilter::PAINT;
  };
  std::vector<vtkSmartPointer<vtkPolyData>> closedLines;
  std::vector<std::string> closedNames; // "stroke 3 (saw line)", one per closed line
  for (std::size_t l = 0; l < state.lines.size(); ++l)
    if (!painted(l) && closed(state.lines[l].first))
    {
      closedLines.push_back(state.lines[l].first);
      closedNames.push_back(strokeName(state.lineStrokes[l]));
    }
  const std::size_t last = state.lines.size() - 1;
  cut.lastLineOpen = !state.lines.empty() && state.lineStrokes[last] + 1 == n && !painted(last) &&
    !closed(state.lines[last].first);
  vtkSmartPointer<vtkPolyData> faces = facesOnly(surface);
  cut.surface = faces;
  // Closed lines that meet: the cut needs them apart, and the surgeon needs to
  // know which two strokes and where (the cut filter can name only a mesh
  // point).
  std::string meeting;
  if (session.cut)
    meeting = closedLinesMeeting(closedLines, closedNames, faces);
  if (!meeting.empty())
  {
    addLine(cut.message, "the cut failed: " + meeting);
    cut.failed = true;
  }
  else if (session.cut && !closedLines.empty())
  {
    vtkNew<vtkPolyData> loops;
    vtkNew<vtkPoints> lp;
    vtkNew<vtkCellArray> lc;
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("MeshPointId");
    for (const auto& l : closedLines)
    {
      vtkDataArray* mid = l->GetPointData()->GetArray("MeshPointId");
      lc->InsertNextCell(l->GetNumberOfPoints());
      for (vtkIdType i = 0; i < l->GetNumberOfPoints(); ++i)
      {
        lc->InsertCellPoint(lp->InsertNextPoint(l->GetPoint(i)));
        ids->InsertNextValue(static_cast<vtkIdType>(mid->GetComponent(i, 0)));
      }
    }
    loops->SetPoints(lp);
    loops->SetLines(lc);
    loops->GetPointData()->AddArray(ids);
    vtkNew<vtkLKClosedLineCutFilter> cutter;
    cutter->SetInputData(faces);
    cutter->SetLinesData(loops);
    cutter->SetCapping(session.capping);
    const int before = lkapp::errorCount(), warningsBefore = lkapp::warningCount();
    cutter->Update();
    const std::string warned = lkapp::warningsSince(warningsBefore);
    if (!warned.empty())
      addLines(cut.message, "the cut: ", warned);
    if (lkapp::errorCount() == before)
    {
      cut.loops = loops;
      vtkNew<vtkLKExtractCutPieceFilter> extract;
      extract->SetInputConnection(cutter->GetOutputPort());
      for (int r = 0; r < cutter->GetNumberOfPieces(); ++r)
      {
        extract->SetPiece(r);
        extract->Update();
        cut.featureEdges.push_back(
          featureEdgesOf(extract->GetOutput(), extract->GetCutLinesOutput(), cut.lines, faces));
        cut.pieces.push_back(withCapOnly(extract->GetOutput()));
      }
      cut.innerWallLines = cutter->GetNumberOfInnerWallLines();
    }
    else
    {
      addLine(cut.message, "the cut failed: " + lkapp::errorsSince(before));
      cut.failed = true;
    }
  }
  else if (session.cut)
    addLine(cut.message, "no closed line to cut along: draw a stroke whose ends meet");
  if (cut.pieces.empty())
  {
    auto whole = vtkSmartPointer<vtkPolyData>::New();
    whole->ShallowCopy(faces);
    cut.featureEdges.assign(1, featureEdgesOf(whole, nullptr, cut.lines, faces));
    cut.pieces.push_back(whole);
  }
  followPieces(); // the pieces may be numbered anew
}

std::array<double, 3> Planner::anchorOf(std::size_t p) const
{
  // The point of the piece farthest from every other piece: away from the
  // cut lines and caps (whose points the pieces beside share), so that no
  // other piece of a cut made anew lies as near it.
  vtkNew<vtkPoints> others;
  for (std::size_t q = 0; q < cut.pieces.size(); ++q)
    if (q != p)
      for (vtkIdType i = 0; i < cut.pieces[q]->GetNumberOfPoints(); ++i)
        others->InsertNextPoint(cut.pieces[q]->GetPoint(i));
  vtkPolyData* piece = cut.pieces[p];
  std::array<double, 3> best{ 0, 0, 0 };
  if (piece->GetNumberOfPoints() == 0)
    return best;
  piece->GetPoint(0, best.data());
  if (others->GetNumberOfPoints() == 0)
    return best;
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(others);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  double farthest = -1.0;
  for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
  {
    double x[3], y[3];
    piece->GetPoint(i, x);
    others->GetPoint(locator->FindClosestPoint(x), y);
    const double d = vtkMath::Distance2BetweenPoints(x, y);
    if (d > farthest)
    {
      farthest = d;
      best = { x[0], x[1], x[2] };
    }
  }
  return best;
}

std::vector<std::vector<double>> Planner::pieceDistances(const std::vector<std::array<double, 3>>& points) const
{
  std::vector<std::vector<double>> distances(points.size(), std::vector<double>(cut.pieces.size(), VTK_DOUBLE_MAX));
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
  {
    if (cut.pieces[p]->GetNumberOfCells() == 0)
      continue;
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(cut.pieces[p]);
    locator->BuildLocator();
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      double closest[3], d2 = 0.0;
      vtkIdType cell = -1;
      int sub = 0;
      locator->FindClosestPoint(points[k].data(), closest, cell, sub, d2);
      distances[k][p] = std::sqrt(d2);
    }
  }
  return distances;
}

void Planner::followPieces()
{
  const bool segmentFollows = session.segment >= 0 && session.segmentAnchored && cut.pieces.size() >= 2;
  if (!segmentFollows && session.deformations.empty() && session.measurements.empty())
    return; // without a cut the segment keeps its number for the cut's return
  // One locator per piece serves the segment's point, every centre and
  // every measured end.
  std::vector<std::array<double, 3>> points;
  for (const Deformation& d : session.deformations)
    points.push_back(d.centre);
  std::vector<std::size_t> firstPoint; // each measurement's first point in `points`
  for (const Measurement& m : session.measurements)
  {
    firstPoint.push_back(points.size());
    for (const auto& x : m.points())
      points.push_back(x);
  }
  points.push_back(session.segmentAnchor);
  const std::vector<std::vector<double>> distances = pieceDistances(points);
  double diagonal = 0.0;
  for (const auto& piece : cut.pieces)
    diagonal = std::max(diagonal, piece->GetLength());
  // The nearest piece, or `own` when that is as near (a point on a cut line
  // lies on both pieces).
  auto nearest = [&](const std::vector<double>& distance, int own) {
    const auto best = static_cast<int>(std::min_element(distance.begin(), distance.end()) - distance.begin());
    const bool exists = own >= 0 && own < static_cast<int>(distance.size());
    const double ownDistance = exists ? distance[static_cast<std::size_t>(own)] : VTK_DOUBLE_MAX;
    return best != own && distance[static_cast<std::size_t>(best)] < ownDistance - 1e-9 * diagonal ? best : own;
  };
  if (segmentFollows)
  {
    const int best = nearest(distances.back(), session.segment);
    if (best != session.segment)
    {
      notice = "the cut numbers its pieces anew: the segment is now piece " + std::to_string(best);
      session.segment = best;
    }
  }
  std::string moved;
  std::vector<double> movedBefore(cut.pieces.size(), 0.0); // how far earlier deformations can have moved each piece
  for (std::size_t i = 0; i < session.deformations.size(); ++i)
  {
    Deformation& d = session.deformations[i];
    const std::vector<double>& distance = distances[i];
    const int best = nearest(distance, d.piece);
    if (best != d.piece)
    {
      moved += (moved.empty() ? "" : ", ") + std::to_string(i) + " to piece " + std::to_string(best);
      d.piece = best;
    }
    // Beyond its reach from every piece (a hand-made or stale session), it
    // would move nothing without a word. A box reaches its corners. It acts
    // on the piece as the deformations before it left it (a dab picked on a
    // bump lies off the cut piece), so their largest moves count too.
    if (d.piece < 0 || d.piece >= static_cast<int>(distance.size()) || distance[static_cast<std::size_t>(d.piece)] == VTK_DOUBLE_MAX)
      continue; // no such piece (applyDeformations says so), or an empty one
    const double away = distance[static_cast<std::size_t>(d.piece)];
    double& before = movedBefore[static_cast<std::size_t>(d.piece)];
    const double reach = (d.tool == "box" ? std::sqrt(3.0) * d.radius : d.radius) + before;
    before += d.tool == "smooth" ? d.radius : std::abs(d.amount);
    if (away > reach)
    {
      char line[200];
      std::snprintf(line, sizeof line, "deformation %zu (%s) lies %.1f mm from piece %d, beyond its radius %.1f mm: it moves nothing",
        i, d.tool.c_str(), away, d.piece, d.radius);
      addLine(cut.message, line);
    }
  }
  if (!moved.empty())
    notice += (notice.empty() ? "" : "; ") + std::string("the deformations follow their pieces: ") + moved;
  // Each measured point goes with its piece, as the segment's move shows it;
  // a point of the soft tissue (measured on the CT) with none, as measured.
  for (std::size_t i = 0; i < session.measurements.size(); ++i)
  {
    Measurement& m = session.measurements[i];
    for (std::size_t k = 0; k < m.points().size(); ++k)
      if (m.pieces[k] != Measurement::kSoftTissue)
        m.pieces[k] = nearest(distances[firstPoint[i] + k], m.pieces[k]);
  }
}

std::string Planner::summaryOfCut()
{
  if (!cut.loops)
    return "";
  std::ostringstream s;
  s.setf(std::ios::fixed);
  const std::vector<lkapp::LineFacts> lines = lkapp::lineFacts(cut.loops);
  s.precision(1);
  s << "cut lines:";
  for (std::size_t k = 0; k < lines.size(); ++k)
    s << (k ? "," : "") << " " << k + 1 << ": " << lines[k].length << " mm";
  for (std::size_t j = 0; j < lines.size(); ++j)
    for (std::size_t k = j + 1; k < lines.size(); ++k)
    {
      const lkapp::LinesApart apart = lkapp::linesApart(lines[j], lines[k]);
      s << " | " << j + 1 << "-" << k + 1 << ": " << apart.distance << " mm apart, " << apart.degrees << " deg";
    }
  s.precision(2);
  s << " | pieces:";
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const lkapp::PieceFacts& f = factsOf(p);
    const std::string name = pieceName(p);
    s << (p ? "," : "") << " " << p << (name.empty() ? "" : " '" + name + "'") << ": ";
    if (f.openEdges == 0)
      s << f.volume / 1000.0 << " ml";
    else
      s << "open";
  }
  return s.str();
}

const lkapp::PieceFacts& Planner::factsOf(std::size_t p)
{
  if (pieceFacts.size() != pieces.size())
    pieceFacts.resize(pieces.size());
  KeptFacts& kept = pieceFacts[p];
  // The MTime is global and only grows: a new object never repeats an old
  // one's pointer and time together.
  if (kept.piece != pieces[p].Get() || kept.time != pieces[p]->GetMTime())
  {
    kept.piece = pieces[p];
    kept.time = pieces[p]->GetMTime();
    kept.facts = lkapp::pieceFacts(pieces[p]);
  }
  return kept.facts;
}

} // namespace lkplanner
