#include "vtkLKGuideBarFilter.h"
#include "vtkLKAbort.h"
#include "vtkLKFieldValues.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKRayCast.h"
#include "vtkLKSawPath.h"

#include "latticekit/SolidBooleans.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkImplicitPolyDataDistance.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkInformationVector.h>
#include <vtkMassProperties.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkStringArray.h>
#include <vtkStaticPointLocator.h>
#include <vtkTriangle.h>
#include <vtkTriangleFilter.h>
#include <vtkTubeFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

vtkStandardNewMacro(vtkLKGuideBarFilter);

namespace
{
using Vec = std::array<double, 3>;

Vec add(const Vec& a, const Vec& b, double s = 1.0)
{
  return { a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2] };
}

double dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double distance(const Vec& a, const Vec& b)
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a.data(), b.data()));
}

/// One guide's place, from its field data.
struct Guide
{
  Vec approach{}, normal{}, slotCentre{};
  double slotWidth = 0.0, slotLength = 0.0, thickness = 0.0, reach = 0.0, clearance = 0.0, hole = 0.0;
  std::vector<Vec> holes; ///< where each screw hole's axis meets the bone
  std::vector<Vec> labelFace; ///< points on its outer face over its label, 0.25 mm apart (none without one)
};

/// Reads `name` (`components` finite values) from the guide's field data;
/// false if it is missing, of another size or not finite.
bool readField(vtkPolyData* guide, const char* name, double* values, int components)
{
  vtkDataArray* a = guide->GetFieldData() ? guide->GetFieldData()->GetArray(name) : nullptr;
  if (!a || a->GetNumberOfComponents() != components || a->GetNumberOfTuples() < 1)
    return false;
  for (int k = 0; k < components; ++k)
  {
    values[k] = a->GetComponent(0, k);
    if (!std::isfinite(values[k]))
      return false;
  }
  return true;
}

/// Points on `guide`'s outer face over its label (its GuideLabelBox,
/// sampled every `step` mm; the first face from outside along the guide's
/// approach): none without a label.
std::vector<Vec> labelFacePoints(vtkPolyData* guide, double step)
{
  vtkDataArray* box = guide->GetFieldData() ? guide->GetFieldData()->GetArray("GuideLabelBox") : nullptr;
  Vec d;
  if (!box || box->GetNumberOfComponents() != 3 || box->GetNumberOfTuples() != 3 ||
    !readField(guide, "GuideApproach", d.data(), 3) || !(vtkMath::Normalize(d.data()) > 0.0))
    return {};
  Vec corner, wide, up;
  box->GetTuple(0, corner.data());
  box->GetTuple(1, wide.data());
  box->GetTuple(2, up.data());
  for (const Vec* v : { &corner, &wide, &up })
    if (!std::isfinite((*v)[0]) || !std::isfinite((*v)[1]) || !std::isfinite((*v)[2]))
      return {};
  vtkNew<vtkStaticCellLocator> onGuide;
  onGuide->SetDataSet(guide);
  onGuide->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  const double far = 2.0 * guide->GetLength() + distance(corner, { guide->GetCenter()[0], guide->GetCenter()[1],
                                                                    guide->GetCenter()[2] });
  const int across = std::clamp(static_cast<int>(std::ceil(std::sqrt(dot(wide, wide)) / step)), 2, 1000);
  const int high = std::clamp(static_cast<int>(std::ceil(std::sqrt(dot(up, up)) / step)), 2, 1000);
  std::vector<Vec> points;
  for (int i = 0; i <= across; ++i)
    for (int j = 0; j <= high; ++j)
    {
      const Vec x = add(add(corner, wide, static_cast<double>(i) / across), up, static_cast<double>(j) / high);
      const Vec from = add(x, d, far), to = add(x, d, -far);
      double hit[3];
      if (lkvtk::firstHit(onGuide, from.data(), to.data(), cell, hit))
        points.push_back({ hit[0], hit[1], hit[2] });
    }
  return points;
}

/// The share of `guide`'s label (its face points every 0.1 mm) where
/// `part`, seen from outside along the guide's approach `d` (unit), is not
/// where the guide was (within 0.02 mm): covered or cut away. 0 without a
/// label.
double labelCovered(vtkPolyData* guide, const Vec& d, vtkPolyData* part)
{
  const std::vector<Vec> face = labelFacePoints(guide, 0.1);
  if (face.empty())
    return 0.0;
  vtkNew<vtkStaticCellLocator> onPart;
  onPart->SetDataSet(part);
  onPart->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  const double far = 2.0 * (guide->GetLength() + part->GetLength());
  int covered = 0;
  for (const Vec& q : face)
  {
    const Vec from = add(q, d, far), to = add(q, d, -far);
    double hit[3];
    if (!lkvtk::firstHit(onPart, from.data(), to.data(), cell, hit) ||
      std::abs(dot(add({ hit[0], hit[1], hit[2] }, q, -1.0), d)) > 0.02)
      ++covered;
  }
  return static_cast<double>(covered) / static_cast<double>(face.size());
}

/// Points along the polyline `line`, its own and between them at most
/// `spacing` apart.
std::vector<Vec> pointsAlong(const std::vector<Vec>& line, double spacing)
{
  if (line.empty())
    return {};
  std::vector<Vec> points{ line.front() };
  for (std::size_t k = 1; k < line.size(); ++k)
  {
    const int parts = std::max(1, static_cast<int>(std::ceil(distance(line[k - 1], line[k]) / spacing)));
    for (int j = 1; j <= parts; ++j)
      points.push_back(add(line[k - 1], add(line[k], line[k - 1], -1.0), static_cast<double>(j) / parts));
  }
  return points;
}

/// The share of a guide's label (`face`: points on its outer face over the
/// label, from labelFacePoints) that a bar of `radius` round `line` stands
/// over, seen from outside along the guide's approach `d` (by more than
/// 0.02 mm; the tube taken as the spheres round points 0.25 mm apart or
/// nearer along the line).
double labelUnderBar(const std::vector<Vec>& face, const Vec& d, const std::vector<Vec>& line, double radius)
{
  if (face.empty() || line.empty())
    return 0.0;
  const std::vector<Vec> centres = pointsAlong(line, 0.25);
  int covered = 0;
  for (const Vec& q : face)
    for (const Vec& p : centres)
    {
      const Vec r = add(p, q, -1.0);
      const double h = dot(r, d), lateral2 = dot(r, r) - h * h;
      if (lateral2 < radius * radius && h + std::sqrt(radius * radius - lateral2) > 0.02)
      {
        ++covered;
        break;
      }
    }
  return static_cast<double>(covered) / static_cast<double>(face.size());
}

/// The share of a label a bar or a wall may stand over before it is
/// reported (half a percent: a stroke's corner).
constexpr double LabelShareCovered = 0.005;

/// The most a joined part's contact may face back from the one direction it
/// goes on along (degrees), and the most of the contact's area that may.
constexpr double MaximumUndercutAngle = 10.0;
constexpr double MaximumUndercutShare = 0.05;

/// The direction a part with these contacts is best put on along (its
/// motion toward the bone): the unit d that makes the least n . d over every
/// contact face's outward normal n the largest, searched over the half
/// sphere round `start` (every 3 degrees, then every 0.25 degrees round the
/// best). `worst` is that least n . d; `guide` the contact it belongs to.
struct Insertion
{
  Vec motion{};
  double worst = -1.0;
  std::size_t guide = 0;
};

Insertion commonInsertion(const std::vector<std::vector<Vec>>& normals, const Vec& start)
{
  Insertion best;
  // The least n . d, or any value under `floor` as soon as one is found (d
  // cannot be the best then).
  auto leastAlong = [&](const Vec& d, double floor, std::size_t& which) {
    double least = 1.0;
    for (std::size_t g = 0; g < normals.size(); ++g)
      for (const Vec& n : normals[g])
        if (const double v = dot(n, d); v < least)
        {
          least = v;
          which = g;
          if (least <= floor)
            return least;
        }
    return least;
  };
  auto search = [&](const Vec& centre, double radius, double step) {
    Vec u, w;
    vtkMath::Perpendiculars(centre.data(), u.data(), w.data(), 0.0);
    for (double theta = 0.0; theta <= radius + 1e-9; theta += step)
    {
      const int around =
        theta == 0.0 ? 1 : std::max(6, static_cast<int>(std::ceil(2.0 * vtkMath::Pi() * std::sin(theta) / step)));
      for (int k = 0; k < around; ++k)
      {
        const double phi = 2.0 * vtkMath::Pi() * k / around;
        Vec d{ 0.0, 0.0, 0.0 };
        d = add(d, centre, std::cos(theta));
        d = add(d, u, std::sin(theta) * std::cos(phi));
        d = add(d, w, std::sin(theta) * std::sin(phi));
        vtkMath::Normalize(d.data());
        std::size_t which = 0;
        if (const double v = leastAlong(d, best.worst, which); v > best.worst)
          best = { d, v, which };
      }
    }
  };
  search(start, vtkMath::Pi() / 2.0, vtkMath::RadiansFromDegrees(3.0));
  search(best.motion, vtkMath::RadiansFromDegrees(3.0), vtkMath::RadiansFromDegrees(0.25));
  return best;
}

/// The bar: a capped tube of `radius` round `line`, its sides sharing their
/// points, in triangles, merged.
vtkSmartPointer<vtkPolyData> tubeAround(const std::vector<Vec>& line, double radius)
{
  vtkNew<vtkPoints> linePoints;
  linePoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<vtkIdType>(line.size()));
  for (const Vec& x : line)
    lines->InsertCellPoint(linePoints->InsertNextPoint(x.data()));
  vtkNew<vtkPolyData> centre;
  centre->SetPoints(linePoints);
  centre->SetLines(lines);
  vtkNew<vtkTubeFilter> tube;
  tube->SetInputData(centre);
  tube->SetRadius(radius);
  tube->SetNumberOfSides(24);
  tube->CappingOn();
  tube->SidesShareVerticesOn();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(tube->GetOutputPort());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(triangles->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->Update();
  return clean->GetOutput();
}

/// Reads guide `number`'s place from its field data: empty, or why it is
/// not a guide.
std::string readGuide(vtkPolyData* data, std::size_t number, Guide& g)
{
  const char* missing = nullptr;
  if (!data || data->GetNumberOfPolys() == 0)
    missing = "polygons";
  else if (!readField(data, "GuideApproach", g.approach.data(), 3))
    missing = "GuideApproach";
  else if (!readField(data, "GuidePlaneNormal", g.normal.data(), 3))
    missing = "GuidePlaneNormal";
  else if (!readField(data, "GuideSlotCentre", g.slotCentre.data(), 3))
    missing = "GuideSlotCentre";
  else if (!readField(data, "GuideSlotWidth", &g.slotWidth, 1))
    missing = "GuideSlotWidth";
  else if (!readField(data, "GuideSlotLength", &g.slotLength, 1))
    missing = "GuideSlotLength";
  else if (!readField(data, "GuideThickness", &g.thickness, 1))
    missing = "GuideThickness";
  else if (!readField(data, "GuideReach", &g.reach, 1))
    missing = "GuideReach";
  else if (!readField(data, "GuideClearance", &g.clearance, 1))
    missing = "GuideClearance";
  else if (!readField(data, "GuideScrewHoleDiameter", &g.hole, 1))
    missing = "GuideScrewHoleDiameter";
  if (missing)
    return "guide " + std::to_string(number) + " has no " + missing + (missing[0] == 'p' ? "" : " of finite values") +
      " (guides come from vtkLKCuttingGuideFilter)";
  if (!(vtkMath::Normalize(g.approach.data()) > 0.0) || !(vtkMath::Normalize(g.normal.data()) > 0.0) ||
    !(g.thickness > 0.0) || !(g.reach > g.slotWidth / 2.0) || !(g.slotWidth > 0.0) || !(g.slotLength > 0.0) ||
    !(g.clearance >= 0.0) || !(g.hole >= 0.0))
    return "guide " + std::to_string(number) +
      "'s field data do not describe a guide (a zero approach or normal, or sizes out of their ranges)";
  if (vtkDataArray* holes = data->GetFieldData()->GetArray("GuideScrewHoles");
      holes && holes->GetNumberOfComponents() == 3 && g.hole > 0.0)
    for (vtkIdType h = 0; h < holes->GetNumberOfTuples(); ++h)
    {
      Vec x;
      holes->GetTuple(h, x.data());
      if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
        g.holes.push_back(x);
    }
  g.labelFace = labelFacePoints(data, 0.25);
  return {};
}

/// How far apart guides a and b lie along the bone (mm): the farther of
/// each slot centre's distances from the other guide's plane, the way each
/// guide reaches from its slot (guides round a corner of the bone from
/// each other are far apart along one of them). Slots offset along each
/// other (one guide higher on the bone than the other) are no farther apart
/// for that: the guides still overlap where their reaches do.
double apartAlongBone(const Guide& a, const Guide& b)
{
  const Vec between = add(b.slotCentre, a.slotCentre, -1.0);
  return std::max(std::abs(dot(between, a.normal)), std::abs(dot(between, b.normal)));
}

/// The least guide wall between two slots merged into one block (mm).
constexpr double MinimumWallBetweenSlots = 2.0;

/// How much wider (mm) the cutters that open a slot or screw hole through
/// the next solid are than through the one before (guide j's by j steps,
/// bar b's by guides + b). Two solids cut by the same slot otherwise have
/// faces in exactly the same planes where they meet in it, and CGAL's union
/// of them (three guides merged into one block: a horizontal cut along the
/// body crossed by two vertical ones on mandible 1) never ended: its
/// corefinement's search round a vertex for an edge on the intersection
/// went round for ever. 0.002 mm is nothing to a saw.
constexpr double CutterStep = 0.002;

/// How two guides next to each other are joined.
enum class Join
{
  Bar,         ///< a bar arched out over the bone between their edges
  StraightBar, ///< edges nearer than the bar's diameter: a straight bar from wall to wall
  Merged       ///< they overlap: one block, each less the other's slot and screw holes
};

/// Whether guide i and the next can be joined: empty, or why not (after
/// `between`, which names them where there are more than two). `apart` is
/// set to the angle between their approaches (degrees); `join` to how they
/// are joined: as one block where their slots are nearer along the bone
/// than their reaches (the guides overlap), by a straight bar of `radius`
/// where their edges are nearer than its diameter, else by a bar arched
/// over the bone.
std::string neighbourProblem(const std::vector<Guide>& guide, std::size_t i, double radius, double maximumLength,
  const std::string& between, double& apart, Join& join)
{
  std::ostringstream why;
  const Guide& a = guide[i];
  const Guide& b = guide[i + 1];
  apart = vtkMath::DegreesFromRadians(std::acos(std::clamp(dot(a.approach, b.approach), -1.0, 1.0)));
  const double slotsApart = distance(a.slotCentre, b.slotCentre), alongBone = apartAlongBone(a, b);
  join = alongBone < a.reach + b.reach ? Join::Merged
    : alongBone < a.reach + b.reach + 2.0 * radius ? Join::StraightBar
                                                   : Join::Bar;
  if (apart > 120.0)
    why << between << "they are put on from directions " << apart
        << " degrees apart (more than 120): a bar between them would go round the bone";
  else if (slotsApart > maximumLength)
    why << between << "their slots are " << slotsApart << " mm apart, more than MaximumLength (" << maximumLength
        << " mm)";
  // Two slots in one block need a wall between them.
  else if (alongBone < 0.5 * (a.slotWidth + b.slotWidth) + MinimumWallBetweenSlots)
    why << between << "their slots are " << alongBone << " mm apart along the bone, too near for a wall of "
        << MinimumWallBetweenSlots << " mm between them (one saw cut?)";
  // A guide between two others has its bars on either side of its slot
  // (the guides in their order along the bone): two bars on one side
  // would meet there, and one of them would pass over the other guide.
  else if (i > 0 &&
    dot(add(guide[i - 1].slotCentre, a.slotCentre, -1.0), a.normal) * dot(add(b.slotCentre, a.slotCentre, -1.0), a.normal) >=
      0.0)
    why << "guides " << i << " and " << i + 2 << " lie on one side of guide " << i + 1
        << "'s slot, so their bars would leave it on one side (give the guides in their order along the bone)";
  return why.str();
}

/// Guide `g`'s frame: its plane's normal, the direction along its slot and
/// its approach, unit and square to each other ((n, d, e) is right-handed).
void frameOf(const Guide& g, Vec& n, Vec& e, Vec& d)
{
  n = g.normal;
  vtkMath::Cross(n.data(), g.approach.data(), e.data());
  vtkMath::Normalize(e.data());
  vtkMath::Cross(e.data(), n.data(), d.data());
}

/// A box: corner k is `centre` plus, along each axis j, `low[j]` or
/// `high[j]` (bit j of k) times axis j (a right-handed frame).
lk::TriangleMesh boxSolid(const Vec& centre, const Vec axis[3], const Vec& low, const Vec& high)
{
  lk::TriangleMesh box;
  for (int k = 0; k < 8; ++k)
  {
    Vec x = centre;
    for (int j = 0; j < 3; ++j)
      x = add(x, axis[j], (k >> j) & 1 ? high[j] : low[j]);
    box.points.emplace_back(x[0], x[1], x[2]);
  }
  box.triangles = { { 0, 4, 6 }, { 0, 6, 2 }, { 1, 3, 7 }, { 1, 7, 5 }, { 0, 1, 5 }, { 0, 5, 4 }, { 2, 6, 7 },
    { 2, 7, 3 }, { 0, 2, 3 }, { 0, 3, 1 }, { 4, 5, 7 }, { 4, 7, 6 } };
  return box;
}

/// A closed cylinder of `radius` (48 sides, outside the circle) round the
/// axis through `base` along unit `d`, from `from` to `to` along it.
lk::TriangleMesh cylinderSolid(const Vec& base, const Vec& d, double radius, double from, double to)
{
  constexpr int sides = 48;
  Vec u, w;
  vtkMath::Perpendiculars(d.data(), u.data(), w.data(), 0.0);
  const double r = radius / std::cos(vtkMath::Pi() / sides); // the circle inside the polygon
  lk::TriangleMesh c;
  for (const double at : { from, to })
    for (int k = 0; k < sides; ++k)
    {
      const double phi = 2.0 * vtkMath::Pi() * k / sides;
      const Vec x = add(add(add(base, d, at), u, r * std::cos(phi)), w, r * std::sin(phi));
      c.points.emplace_back(x[0], x[1], x[2]);
    }
  for (const double at : { from, to })
  {
    const Vec x = add(base, d, at);
    c.points.emplace_back(x[0], x[1], x[2]);
  }
  for (std::int64_t k = 0; k < sides; ++k)
  {
    const std::int64_t next = (k + 1) % sides;
    c.triangles.push_back({ k, next, sides + next });
    c.triangles.push_back({ k, sides + next, sides + k });
    c.triangles.push_back({ 2 * sides, next, k });
    c.triangles.push_back({ 2 * sides + 1, sides + k, sides + next });
  }
  return c;
}

/// What guide `k` cuts out of a guide merged with it, so that its slot and
/// screw holes stay open through that guide: its slot (a box a hair wider
/// and longer than the slot, so that the faces left do not meet the slot's
/// own walls) from `lowest` to `highest` along its approach (from its slot
/// centre), and its screw holes (0.05 mm wider) from 2 mm into the bone to
/// `highest`; all `widen` wider still.
std::vector<lk::TriangleMesh> cuttersOf(const Guide& k, double lowest, double highest, double widen)
{
  const double hair = 0.01 + widen;
  Vec n, e, d;
  frameOf(k, n, e, d);
  const Vec box[3] = { n, d, e };
  const double halfWidth = k.slotWidth / 2.0 + hair, halfLength = k.slotLength / 2.0 + hair;
  std::vector<lk::TriangleMesh> cutters{ boxSolid(
    k.slotCentre, box, { -halfWidth, lowest, -halfLength }, { halfWidth, highest, halfLength }) };
  for (const Vec& h : k.holes)
  {
    const double at = dot(add(h, k.slotCentre, -1.0), d);
    cutters.push_back(cylinderSolid(h, d, k.hole / 2.0 + 0.05 + widen, -2.0, highest - at));
  }
  return cutters;
}

/// Whether two guides' bodies overlap: a point of either, or the point
/// 0.25 mm inside it under a vertex (along the vertex normal), more than
/// 0.05 mm inside the other (closed, outward meshes). The points under the
/// vertices find guides stacked on one flat face, whose tops and undersides
/// lie in the same planes: there every vertex of one in the other lies on
/// its faces. Slots far apart along the bone can still have their guides in
/// each other's way where the saw planes cross near it (an L-shaped cut; a
/// long guide on a ramus and one across its top; a V).
bool bodiesOverlap(vtkPolyData* a, vtkPolyData* b)
{
  double boundsA[6], boundsB[6];
  a->GetBounds(boundsA);
  b->GetBounds(boundsB);
  for (int k = 0; k < 3; ++k)
    if (boundsA[2 * k + 1] < boundsB[2 * k] || boundsB[2 * k + 1] < boundsA[2 * k])
      return false;
  for (const auto& [inner, outer, box] : { std::make_tuple(a, b, boundsB), std::make_tuple(b, a, boundsA) })
  {
    vtkNew<vtkImplicitPolyDataDistance> inside;
    inside->SetInput(outer);
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(inner);
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    normals->SplittingOff();
    normals->ConsistencyOff();
    normals->AutoOrientNormalsOff();
    normals->Update();
    vtkDataArray* normal = normals->GetOutput()->GetPointData()->GetNormals();
    for (vtkIdType p = 0; p < inner->GetNumberOfPoints(); ++p)
    {
      double x[3], n[3] = { 0.0, 0.0, 0.0 };
      inner->GetPoint(p, x);
      if (normal)
        normal->GetTuple(p, n);
      if (!(x[0] >= box[0] && x[0] <= box[1] && x[1] >= box[2] && x[1] <= box[3] && x[2] >= box[4] &&
            x[2] <= box[5]))
        continue;
      double under[3] = { x[0] - 0.25 * n[0], x[1] - 0.25 * n[1], x[2] - 0.25 * n[2] };
      if (inside->EvaluateFunction(x) < -0.05 || inside->EvaluateFunction(under) < -0.05)
        return true;
    }
  }
  return false;
}

/// Whether a bar along `line` (a tube of `radius`) reaches more than 0.05
/// mm into `guide` (closed, outward): a point of the line, every 0.25 mm,
/// nearer the guide than that or inside it.
bool barMeets(const std::vector<Vec>& line, double radius, vtkPolyData* guide)
{
  double box[6];
  guide->GetBounds(box);
  vtkNew<vtkImplicitPolyDataDistance> toGuide;
  bool built = false;
  for (Vec x : pointsAlong(line, 0.25))
  {
    bool near = true;
    for (int c = 0; c < 3; ++c)
      near = near && x[c] >= box[2 * c] - radius && x[c] <= box[2 * c + 1] + radius;
    if (!near)
      continue;
    if (!built)
    {
      toGuide->SetInput(guide);
      built = true;
    }
    if (toGuide->EvaluateFunction(x.data()) < radius - 0.05)
      return true;
  }
  return false;
}

/// Why `part` is not one piece, or empty: merged guides (`joins[i]`: guide
/// i and the next) that do not meet, named after `between(i)`; guides
/// merged because their bodies overlap (`overlapping[i]`) that fall apart
/// once cut by each other's slots; or else how many pieces.
std::string apartPieces(vtkPolyData* part, const std::vector<Guide>& guide, const std::vector<Join>& joins,
  const std::vector<char>& overlapping, const std::function<std::string(std::size_t)>& between)
{
  vtkNew<vtkPolyDataConnectivityFilter> regions;
  regions->SetInputData(part);
  regions->SetExtractionModeToAllRegions();
  regions->ColorRegionsOn();
  regions->Update();
  const int count = regions->GetNumberOfExtractedRegions();
  if (count <= 1)
    return {};
  vtkPolyData* coloured = regions->GetOutput();
  vtkDataArray* region = coloured->GetPointData()->GetArray("RegionId");
  vtkNew<vtkStaticPointLocator> points;
  points->SetDataSet(coloured);
  points->BuildLocator();
  // A guide's piece: the one nearest a point inside its wall, beside its
  // slot (no other guide's slot is that near: a wall between them).
  auto regionOf = [&](const Guide& g) {
    Vec n, e, d;
    frameOf(g, n, e, d);
    const Vec x = add(add(g.slotCentre, n, g.slotWidth / 2.0 + 0.5), d, g.clearance + g.thickness / 2.0);
    const vtkIdType nearest = points->FindClosestPoint(x.data());
    return region && nearest >= 0 ? region->GetTuple1(nearest) : -1.0;
  };
  std::ostringstream why;
  for (std::size_t i = 0; i + 1 < guide.size(); ++i)
    if (joins[i] == Join::Merged && !overlapping[i] && regionOf(guide[i]) != regionOf(guide[i + 1]))
    {
      why << between(i) << "their slots are " << apartAlongBone(guide[i], guide[i + 1])
          << " mm apart along the bone, nearer than their reaches, so no bar fits between them, and the guides "
             "do not meet to be one block (one beside the other on the bone, or round an edge of it)";
      return why.str();
    }
  for (std::size_t i = 0; i + 1 < guide.size(); ++i)
    if (overlapping[i])
    {
      why << between(i) << "the guides overlap (their saw planes cross near the bone), and each less the "
          << "other's slot and screw holes falls apart (the part would be " << count << " pieces)";
      return why.str();
    }
  why << "the part would be " << count << " pieces (a guide cut apart by the slot of a guide merged with it or "
      << "crossing it)";
  return why.str();
}

/// The bone as the bars see it: how high it is under a point along a
/// direction, and how far a point is from it.
class BoneQueries
{
public:
  explicit BoneQueries(vtkPolyData* input)
    : bone(lkvtk::facesAsTriangles(input))
  {
    locator->SetDataSet(bone);
    locator->BuildLocator();
    double bounds[6];
    bone->GetBounds(bounds);
    diagonal = std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
    vtkNew<vtkPolyDataNormals> outward; // the distance's sign needs faces facing out
    outward->SetInputData(bone);
    outward->ConsistencyOn();
    outward->AutoOrientNormalsOn();
    outward->SplittingOff();
    outward->ComputeCellNormalsOn();
    outward->ComputePointNormalsOff();
    outward->Update();
    away->SetInput(outward->GetOutput());
  }

  /// How high the bone is along `d` under `x` (the first face a ray down
  /// along -d from far above meets), or -infinity where it meets none.
  double height(const Vec& x, const Vec& d)
  {
    const Vec from = add(x, d, diagonal), to = add(x, d, -diagonal);
    double hit[3];
    if (!lkvtk::firstHit(locator, from.data(), to.data(), cell, hit))
      return -std::numeric_limits<double>::infinity();
    return dot(add({ hit[0], hit[1], hit[2] }, x, -1.0), d);
  }

  /// The distance to the bone, signed (negative inside).
  double distance(const Vec& x) { return away->EvaluateFunction(const_cast<double*>(x.data())); }
  /// The same, and the nearest point of the bone.
  double distance(const Vec& x, Vec& nearest)
  {
    return away->EvaluateFunctionAndGetClosestPoint(const_cast<double*>(x.data()), nearest.data());
  }

private:
  vtkSmartPointer<vtkPolyData> bone;
  vtkNew<vtkStaticCellLocator> locator;
  vtkNew<vtkGenericCell> cell;
  vtkNew<vtkImplicitPolyDataDistance> away;
  double diagonal = 0.0;
};

/// A guide's contact: its faces on the bone (all three corners within its
/// clearance and 0.05 mm; none under 0.001 mm^2), their outward normals and
/// areas.
void contactFaces(vtkPolyData* g, double clearance, BoneQueries& bone, std::vector<Vec>& normals,
  std::vector<double>& areas)
{
  std::vector<char> pointOnBone(static_cast<std::size_t>(g->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p)
  {
    Vec x;
    g->GetPoint(p, x.data());
    pointOnBone[static_cast<std::size_t>(p)] = std::abs(bone.distance(x)) <= clearance + 0.05;
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
  {
    g->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() != 3)
      continue;
    Vec corner[3];
    bool onBone = true;
    for (int k = 0; k < 3; ++k)
    {
      g->GetPoint(ids->GetId(k), corner[k].data());
      onBone = onBone && pointOnBone[static_cast<std::size_t>(ids->GetId(k))];
    }
    const double area = vtkTriangle::TriangleArea(corner[0].data(), corner[1].data(), corner[2].data());
    if (!onBone || area < 1e-3)
      continue;
    Vec normal;
    vtkTriangle::ComputeNormal(corner[0].data(), corner[1].data(), corner[2].data(), normal.data());
    normals.push_back(normal);
    areas.push_back(area);
  }
}

/// One bar: its centre line, length, gap to the bone (where it is farthest
/// from both guides) and solid.
struct Bar
{
  std::vector<Vec> line;
  double length = 0.0, gap = 0.0;
  lk::TriangleMesh solid;
  bool stopped = false; ///< `progress` asked to stop: the rest is not made
};

/// What a bar between two guides needs to know besides them.
struct BarSettings
{
  double radius, standOff, maximumLength;
  double apart;                ///< degrees between the guides' approaches
  std::size_t number[2];       ///< the guides' numbers, for messages
  std::string between;         ///< "guides 2 and 3: ", or empty for two guides
  bool straight = false;       ///< edges nearer than the bar's diameter: straight from wall to wall
};

/// The bar's solid round its line, into `bar.solid`: empty, or why there
/// is none (its tube crosses itself where the line bends tighter than the
/// radius).
std::string tubeSolid(const BarSettings& settings, Bar& bar)
{
  vtkSmartPointer<vtkPolyData> tube = tubeAround(bar.line, settings.radius);
  if (const std::string problem = lkvtk::toTriangleMesh(lkvtk::facesAsTriangles(tube), bar.solid); !problem.empty())
    return settings.between + "the bar: " + problem;
  lk::TriangleMesh alone;
  if (!lk::solidUnion({ bar.solid }, alone).empty())
  {
    std::ostringstream why;
    why << settings.between << "the bar would bend tighter than its radius (" << settings.radius
        << " mm) on its way between them, where it clears the bone (a thinner bar, a smaller StandOff, or guides "
        << "that face more alike: " << settings.apart << " degrees apart)";
    return why.str();
  }
  return {};
}

/// Routes the bar from guide a to guide b: from the edge of each, on the
/// other's side of its slot (`shift[i]` mm from the slot's middle along
/// it, as frameOf's e), a centre line pushed off the bone by its radius
/// and the stand-off and smoothed, then its tube. Empty, or why there is
/// none (after "Cannot join the guides: "). `progress(fraction of this bar)`
/// returns false to stop; `bar.stopped` then says so and the bar is not
/// finished.
std::string routeBar(const Guide& a, const Guide& b, const BarSettings& settings, const double shift[2],
  BoneQueries& bone, const std::function<bool(double)>& progress, Bar& bar)
{
  const Guide* pair[2] = { &a, &b };
  const double radius = settings.radius;
  std::ostringstream why;
  Vec mean = add(a.approach, b.approach);
  vtkMath::Normalize(mean.data());

  // Each end: at the guide's edge on the other's side of its slot, clear
  // of the screw hole, in the wall: its middle above the bone along the
  // approach, or higher where the bar would reach into the bone there (a
  // bar thicker than the wall, a wall on a slope).
  Vec end[2], lead[2];
  double endHeight[2]; // each end's height above the bone, along its guide's approach
  for (int i = 0; i < 2; ++i)
  {
    const Guide& g = *pair[i];
    const Guide& other = *pair[1 - i];
    Vec side = g.normal;
    if (dot(add(other.slotCentre, g.slotCentre, -1.0), side) < 0.0)
      side = { -side[0], -side[1], -side[2] };
    const double half = g.slotWidth / 2.0;
    const double inner = g.hole > 0.0 ? 0.5 * (half + g.reach) + g.hole / 2.0 + 0.5 : half + 0.5;
    const double s = std::max(inner, g.reach - radius);
    if (!(s < g.reach))
    {
      why << "guide " << settings.number[i] << " has no room for the bar beside its screw hole (a larger Reach)";
      return why.str();
    }
    Vec n, e, d;
    frameOf(g, n, e, d);
    const Vec base = add(add(g.slotCentre, side, s), e, shift[i]);
    const double height = bone.height(base, g.approach);
    if (!std::isfinite(height))
    {
      why << "no bone under guide " << settings.number[i]
          << "'s edge (is port 0 the bone the guides were made on?)";
      return why.str();
    }
    const Vec onBone = add(base, g.approach, height - dot(add(base, g.slotCentre, -1.0), g.approach));
    end[i] = add(onBone, g.approach, g.clearance + g.thickness / 2.0);
    for (int step = 0; step < 100 && bone.distance(end[i]) < radius; ++step)
      end[i] = add(end[i], g.approach, 0.1);
    endHeight[i] = dot(add(end[i], onBone, -1.0), g.approach);
    if (!(endHeight[i] < g.clearance + g.thickness + 0.5 * radius))
    {
      why << "the bar would stand " << endHeight[i] << " mm above the bone at guide " << settings.number[i]
          << "'s edge, clear of its wall (a thinner bar, or a thicker wall)";
      return why.str();
    }
    lead[i] = add(end[i], side, g.reach - s + radius);
  }

  std::vector<Vec>& line = bar.line;
  if (settings.straight)
  {
    // Guides whose edges are nearer than the bar's diameter: no room to
    // arch out, so a straight bar from wall to wall, raised (both ends
    // along their approaches, in their walls) until it clears the bone
    // between them by its radius.
    const double length = distance(end[0], end[1]);
    const int parts = std::max(2, static_cast<int>(std::ceil(length / 0.25)));
    double lift = 0.0;
    for (int step = 0; step < 50; ++step)
    {
      const Vec from = add(end[0], a.approach, lift), to = add(end[1], b.approach, lift);
      line.clear();
      for (int k = 0; k <= parts; ++k)
        line.push_back(add(from, add(to, from, -1.0), static_cast<double>(k) / parts));
      bar.gap = std::numeric_limits<double>::infinity();
      for (std::size_t k = 1; k + 1 < line.size(); ++k)
        bar.gap = std::min(bar.gap, bone.distance(line[k]) - radius);
      if (bar.gap > -1e-3)
        break;
      lift += 0.02 - bar.gap;
    }
    bar.length = distance(line.front(), line.back());
    for (int i = 0; i < 2; ++i)
    {
      const Guide& g = *pair[i];
      if (!(bar.gap > -1e-3) || !(endHeight[i] + lift < g.clearance + g.thickness + 0.5 * radius))
      {
        why << settings.between << "their edges are too near for a bar to arch between them, and a straight one "
            << "clear of the bone between them would stand " << endHeight[i] + lift << " mm above it at guide "
            << settings.number[i] << "'s edge, clear of its wall";
        return why.str();
      }
    }
    bar.gap = std::max(bar.gap, 0.0);
    return tubeSolid(settings, bar);
  }

  // The centre line: straight from end to end, then pushed off the bone.
  const double spacing = 0.5;
  line = { end[0] };
  {
    const double length = distance(lead[0], lead[1]);
    const int parts = std::max(2, static_cast<int>(std::ceil(length / spacing)));
    for (int k = 0; k <= parts; ++k)
      line.push_back(add(lead[0], add(lead[1], lead[0], -1.0), static_cast<double>(k) / parts));
    line.push_back(end[1]);
  }
  const std::size_t points = line.size();
  // The distance each point must keep from the bone: the radius at the
  // guides, the radius and the stand-off a little beyond their edges.
  std::vector<double> needed(points), arc(points, 0.0);
  for (std::size_t k = 1; k < points; ++k)
    arc[k] = arc[k - 1] + distance(line[k - 1], line[k]);
  const double leadLength = distance(end[0], lead[0]);
  // Over 5 mm and twice the stand-off, along a smooth step (the bar bends
  // no tighter than it must).
  const double ramp = 5.0 + 2.0 * settings.standOff;
  auto neededAt = [&](double fromEnd) {
    const double t = std::clamp((fromEnd - leadLength) / ramp, 0.0, 1.0);
    return radius + settings.standOff * t * t * (3.0 - 2.0 * t);
  };
  for (std::size_t k = 0; k < points; ++k)
    needed[k] = neededAt(std::min(arc[k], arc.back() - arc[k]));
  // Pushes each point that is too near the bone out to its distance, level
  // with the guides' middles (square to their mean direction along their
  // slots, so that the bar goes in front of the bone and not over its edge:
  // a mandible's teeth): away from the nearest point of the bone, or, inside
  // it or where that is up or down or back, forward (the guides' mean
  // approach, square to the line between the ends); the largest shortfall
  // before the push.
  Vec chord = add(end[1], end[0], -1.0);
  vtkMath::Normalize(chord.data());
  Vec along{ 0, 0, 0 };
  for (const Guide* g : pair)
  {
    Vec axis;
    vtkMath::Cross(g->normal.data(), g->approach.data(), axis.data());
    along = add(along, axis, dot(axis, along) < 0.0 ? -1.0 : 1.0);
  }
  along = add(along, chord, -dot(along, chord));
  Vec forward = add(mean, chord, -dot(mean, chord));
  if (vtkMath::Normalize(along.data()) > 1e-6)
    forward = add(forward, along, -dot(forward, along));
  if (!(vtkMath::Normalize(forward.data()) > 1e-6))
    forward = mean;
  const bool level = vtkMath::Norm(along.data()) > 0.5;
  auto push = [&]() {
    double worst = 0.0;
    for (std::size_t k = 1; k + 1 < points; ++k)
    {
      Vec nearest;
      const double f = bone.distance(line[k], nearest);
      const double shortfall = needed[k] - f;
      worst = std::max(worst, shortfall);
      if (shortfall <= 0.0)
        continue;
      // Outside the bone: away from it, level (round a corner of the bone
      // the guides are on), unless that is up or down, over its edge.
      Vec way = add(line[k], nearest, -1.0);
      vtkMath::Normalize(way.data());
      if (level)
        way = add(way, along, -dot(way, along));
      if (f <= 0.0 || !(vtkMath::Normalize(way.data()) > 0.5) || dot(way, forward) < 0.0)
        way = forward;
      line[k] = add(line[k], way, shortfall);
    }
    return worst;
  };
  // Pushes, then smoothing (each point toward its neighbours' middle, the
  // ends where they are), until a round's smoothing leaves every point
  // where it may be; then pushes alone, for what the last smoothing took.
  const int rounds = 300;
  for (int round = 0; round < rounds; ++round)
  {
    if (push() < 0.01 && round > 0)
      break;
    for (int pass = 0; pass < 2; ++pass)
    {
      std::vector<Vec> smoothed = line;
      for (std::size_t k = 1; k + 1 < points; ++k)
        smoothed[k] = add(add(line[k], line[k], -0.5), add(line[k - 1], line[k + 1]), 0.25);
      line = smoothed;
    }
    if (round % 20 == 0 && !progress(static_cast<double>(round) / rounds))
    {
      bar.stopped = true;
      break;
    }
  }
  double worst = 0.0;
  for (int k = 0; k < 10; ++k)
  {
    worst = push();
    if (worst < 1e-3)
      break;
  }
  if (bar.stopped)
    return {};
  if (!(worst < 0.1))
  {
    why << settings.between << "no bar of " << 2.0 * radius << " mm found a way " << settings.standOff
        << " mm clear of the bone between them (" << worst << " mm short)";
    return why.str();
  }
  bar.length = 0.0;
  bar.gap = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < points; ++k)
    bar.length += distance(line[k - 1], line[k]);
  // The gap where the bar is farthest from both guides (past the ramps; on
  // guides too near for the whole stand-off, at the ramps' top).
  const double top = *std::max_element(needed.begin() + 1, needed.end() - 1);
  for (std::size_t k = 1; k + 1 < points; ++k)
    if (needed[k] >= top - 1e-9)
      bar.gap = std::min(bar.gap, bone.distance(line[k]) - radius);
  if (bar.length > settings.maximumLength)
  {
    why << settings.between << "the bar would be " << bar.length << " mm long, more than MaximumLength ("
        << settings.maximumLength << " mm)";
    return why.str();
  }
  // The tube round it, which crosses itself where its line bends tighter
  // than its radius.
  return tubeSolid(settings, bar);
}
} // namespace

vtkLKGuideBarFilter::vtkLKGuideBarFilter()
{
  this->SetNumberOfInputPorts(2);
}

int vtkLKGuideBarFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkLKGuideBarFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->BarLength = this->BarDiameter = this->BarGap = this->Volume = 0.0;
  this->BarLengths.clear();
  this->Merged.clear();
  this->Crossings.clear();
  this->NumberOfLabelsCovered = 0;
  this->NumberOfScrewHolesInSawPaths = 0;
  this->BarGaps.clear();
  this->ApproachUsed[0] = this->ApproachUsed[1] = this->ApproachUsed[2] = 0.0;
  this->InsertionMargin = 0.0;
  this->UndercutArea = 0.0;

  struct Range
  {
    const char* name;
    double value, low, high;
  };
  for (const Range& r : { Range{ "StandOff", this->StandOff, 0.0, 50.0 },
         Range{ "MaximumLength", this->MaximumLength, 1.0, 1000.0 } })
    if (!(r.value >= r.low && r.value <= r.high))
    {
      vtkErrorMacro("Cannot join the guides: " << r.name << " must be " << r.low << " to " << r.high << " mm, not "
                                               << r.value << ".");
      return 0;
    }
  if (!(this->Diameter == 0.0 || (this->Diameter >= 1.0 && this->Diameter <= 20.0)))
  {
    vtkErrorMacro("Cannot join the guides: Diameter must be 1 to 20 mm (0: the guides' wall thickness), not "
      << this->Diameter << ".");
    return 0;
  }
  const int count = inputVector[1]->GetNumberOfInformationObjects();
  if (count < 2)
  {
    vtkErrorMacro("Cannot join the guides: a bar joins two guides, and port 1 has " << count << ".");
    return 0;
  }
  if (const std::string why = lkvtk::surfaceProblem(input); !why.empty())
  {
    vtkErrorMacro("Cannot join the guides: the bone: " << why << ".");
    return 0;
  }
  const std::size_t n = static_cast<std::size_t>(count);
  std::vector<vtkPolyData*> guideData(n);
  std::vector<Guide> guide(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    guideData[i] = vtkPolyData::GetData(inputVector[1], static_cast<int>(i));
    if (const std::string why = readGuide(guideData[i], i + 1, guide[i]); !why.empty())
    {
      vtkErrorMacro("Cannot join the guides: " << why << ".");
      return 0;
    }
  }
  double thinnest = guide[0].thickness;
  for (const Guide& g : guide)
    thinnest = std::min(thinnest, g.thickness);
  const double radius = 0.5 * (this->Diameter > 0.0 ? this->Diameter : thinnest);
  // What the bars' errors say of the guides they join: nothing more for two
  // guides (one bar), which two for more.
  auto between = [&](std::size_t i) {
    return n == 2 ? std::string() : "guides " + std::to_string(i + 1) + " and " + std::to_string(i + 2) + ": ";
  };
  std::vector<double> facingApart(n - 1); // degrees between each guide's approach and the next's
  std::vector<Join> joins(n - 1, Join::Bar); // how guide i and the next are joined
  for (std::size_t i = 0; i + 1 < n; ++i)
  {
    if (const std::string why =
          neighbourProblem(guide, i, radius, this->MaximumLength, between(i), facingApart[i], joins[i]);
        !why.empty())
    {
      vtkErrorMacro("Cannot join the guides: " << why << ".");
      return 0;
    }
  }
  // Guides next to each other whose bodies overlap though their slots are
  // far apart along the bone (saw planes that cross near it): each guide's
  // wall can stand in the other's saw path or over a screw hole. They are
  // one block already: merged, each less the other's slot and screw holes.
  std::vector<char> overlapping(n - 1, 0);
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (joins[i] != Join::Merged && bodiesOverlap(guideData[i], guideData[i + 1]))
    {
      joins[i] = Join::Merged;
      overlapping[i] = 1;
    }
  // Guides farther apart in the order given whose bodies overlap all the
  // same, with a bar between them (saw planes that cross near the bone: a
  // V, an X beside a third): each is cut by the other's slot and screw
  // holes too, as merged neighbours are, and they are one with the bars.
  std::vector<std::vector<char>> crossing(n, std::vector<char>(n, 0));
  for (std::size_t i = 0; i + 2 < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j)
      if (std::any_of(joins.begin() + static_cast<std::ptrdiff_t>(i), joins.begin() + static_cast<std::ptrdiff_t>(j),
            [](Join join) { return join != Join::Merged; }) &&
        bodiesOverlap(guideData[i], guideData[j]))
        crossing[i][j] = crossing[j][i] = 1;

  BoneQueries bone(input);
  // One direction must put every guide on the bone at once (the part is
  // rigid): each guide's contact (its faces on the bone, within its
  // clearance) must face it, as the contact of one guide faces its own
  // approach. Guides far round the bone (a ramus on each side) have none.
  std::vector<std::vector<Vec>> contactNormals(n);
  std::vector<std::vector<double>> contactAreas(n);
  Vec start{ 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    start = add(start, guide[i].approach, -1.0);
    contactFaces(guideData[i], guide[i].clearance, bone, contactNormals[i], contactAreas[i]);
  }
  if (!(vtkMath::Normalize(start.data()) > 1e-6))
    start = { -guide[0].approach[0], -guide[0].approach[1], -guide[0].approach[2] };
  const Insertion insertion = commonInsertion(contactNormals, start);
  // A little undercut (faces a few degrees past square to it, a sliver of
  // the contact: a label map's steps) is what printing's tolerance and the
  // periosteum take up; more is a part that cannot go on.
  double contactArea = 0.0, undercutArea = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t f = 0; f < contactNormals[i].size(); ++f)
    {
      contactArea += contactAreas[i][f];
      if (dot(contactNormals[i][f], insertion.motion) < 0.0)
        undercutArea += contactAreas[i][f];
    }
  const double back =
    vtkMath::DegreesFromRadians(std::acos(std::clamp(insertion.worst, -1.0, 1.0))) - 90.0; // < 0: none
  if (!(back <= MaximumUndercutAngle && undercutArea <= MaximumUndercutShare * contactArea))
  {
    char text[200];
    std::snprintf(text, sizeof text, "%.1f degrees back from it, over %.1f mm^2 of the guides' %.0f mm^2", back,
      undercutArea, contactArea);
    vtkErrorMacro("Cannot join the guides: no one direction puts them all on the bone at once: along the best, "
      << "guide " << insertion.guide + 1 << "'s contact still faces " << text << " (more than "
      << MaximumUndercutAngle << " degrees or " << 100.0 * MaximumUndercutShare
      << " % of the contact: the part would reach round the bone; join fewer guides).");
    return 0;
  }
  this->UpdateProgress(0.05);

  // Each bar's centre line, pushed off the bone; its length and its gap.
  std::vector<lk::TriangleMesh> barSolids;
  std::vector<std::vector<Vec>> barLines;
  std::vector<double> barLengths, barGaps;
  const double share = 0.55 / static_cast<double>(n - 1); // of the progress, for each bar
  for (std::size_t b = 0; b + 1 < n; ++b)
  {
    if (joins[b] == Join::Merged)
      continue;
    const BarSettings settings{ radius, this->StandOff, this->MaximumLength, facingApart[b], { b + 1, b + 2 },
      between(b), joins[b] == Join::StraightBar };
    const Guide* ends[2] = { &guide[b], &guide[b + 1] };
    double shift[2] = { 0.0, 0.0 };
    Bar bar;
    const std::string why = routeBar(guide[b], guide[b + 1], settings, shift, bone,
      [&](double done) {
        this->UpdateProgress(0.05 + share * (static_cast<double>(b) + done));
        return !this->GetAbortExecute();
      },
      bar);
    if (lkvtk::stopRequested(this, { output }))
      return 1;
    if (!why.empty())
    {
      vtkErrorMacro("Cannot join the guides: " << why << ".");
      return 0;
    }
    // A bar that would stand over a guide's label (leaving the guide's edge
    // beside it, or running along the edge toward the other guide): its end
    // moved along the slot away from the label, 2 mm at a time while it stays
    // a radius inside the slot's ends, until it clears the label; the route
    // that covers the least of the labels is kept.
    auto underBar = [&](const Bar& route, int i) {
      return labelUnderBar(ends[i]->labelFace, ends[i]->approach, route.line, radius);
    };
    double cover[2] = { underBar(bar, 0), underBar(bar, 1) };
    double away[2] = { 0.0, 0.0 }; // along frameOf's e, away from each label
    for (int i = 0; i < 2; ++i)
      if (cover[i] > LabelShareCovered)
      {
        Vec middle{ 0.0, 0.0, 0.0 }, nn, e, d;
        for (const Vec& q : ends[i]->labelFace)
          middle = add(middle, q, 1.0 / static_cast<double>(ends[i]->labelFace.size()));
        frameOf(*ends[i], nn, e, d);
        away[i] = dot(add(middle, ends[i]->slotCentre, -1.0), e) > 0.0 ? -1.0 : 1.0;
      }
    for (int step = 1; cover[0] > LabelShareCovered || cover[1] > LabelShareCovered; ++step)
    {
      double tried[2] = { shift[0], shift[1] };
      bool moved = false;
      for (int i = 0; i < 2; ++i)
        if (cover[i] > LabelShareCovered && 2.0 * step <= 0.5 * ends[i]->slotLength - radius)
        {
          tried[i] = away[i] * 2.0 * step;
          moved = true;
        }
      if (!moved)
        break;
      Bar other;
      const std::string problem = routeBar(guide[b], guide[b + 1], settings, tried, bone,
        [&](double) { return !this->GetAbortExecute(); }, other);
      if (lkvtk::stopRequested(this, { output }))
        return 1;
      if (!problem.empty())
        break;
      const double otherCover[2] = { underBar(other, 0), underBar(other, 1) };
      if (otherCover[0] + otherCover[1] < cover[0] + cover[1])
      {
        bar = std::move(other);
        shift[0] = tried[0];
        shift[1] = tried[1];
        cover[0] = otherCover[0];
        cover[1] = otherCover[1];
      }
    }
    barSolids.push_back(std::move(bar.solid));
    barLines.push_back(std::move(bar.line));
    barLengths.push_back(bar.length);
    barGaps.push_back(bar.gap);
  }
  this->UpdateProgress(0.6);

  // Every slot and screw hole open through the whole part: guides merged
  // into one block each less the slots and screw holes of the others in
  // its block (a guide's wall over its neighbour's slot would stop the
  // saw), and each bar less those of the two guides it joins (its end,
  // tilted where it rises off the bone, can reach into a hole beside it).
  std::vector<std::size_t> block(n, 0);
  for (std::size_t i = 0; i + 1 < n; ++i)
    block[i + 1] = joins[i] == Join::Merged ? block[i] : block[i] + 1;
  // Whether guides j and k are cut by each other's slots and screw holes
  // (and their screws checked against each other's saws): one block, or
  // crossing.
  auto together = [&](std::size_t j, std::size_t k) { return block[j] == block[k] || crossing[j][k]; };
  std::vector<lk::TriangleMesh> guideSolids(n);
  for (std::size_t i = 0; i < n; ++i)
    if (const std::string why = lkvtk::toTriangleMesh(lkvtk::facesAsTriangles(guideData[i]), guideSolids[i]);
        !why.empty())
    {
      vtkErrorMacro("Cannot join the guides: guide " << i + 1 << ": " << why << ".");
      return 0;
    }
  // Guide k's cutters, from below its lowest point to above the highest of
  // `over`, along its approach.
  std::vector<double> lowest(n, std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < n; ++k)
    for (const lk::Vec3& p : guideSolids[k].points)
      lowest[k] = std::min(lowest[k], dot(add({ p.x(), p.y(), p.z() }, guide[k].slotCentre, -1.0), guide[k].approach));
  auto cutsOf = [&](std::size_t k, const std::vector<const lk::TriangleMesh*>& over, double widen) {
    double highest = -std::numeric_limits<double>::infinity();
    for (const lk::TriangleMesh* solid : over)
      for (const lk::Vec3& p : solid->points)
        highest = std::max(highest, dot(add({ p.x(), p.y(), p.z() }, guide[k].slotCentre, -1.0), guide[k].approach));
    return cuttersOf(guide[k], lowest[k] - 1.0, highest + 1.0, widen);
  };
  auto cut = [&](lk::TriangleMesh& solid, const std::vector<lk::TriangleMesh>& cutters, const std::string& what) {
    if (cutters.empty())
      return true;
    lk::TriangleMesh rest;
    if (const std::string why = lk::solidDifference(solid, cutters, rest); !why.empty())
    {
      vtkErrorMacro("Cannot join the guides: " << what << " with the slots and screw holes beside it: " << why << ".");
      return false;
    }
    solid = std::move(rest);
    return true;
  };
  // What each guide and bar is cut by, from them as they are; then the cuts.
  std::vector<std::vector<lk::TriangleMesh>> guideCutters(n), barCutters;
  for (std::size_t j = 0; j < n; ++j)
  {
    std::vector<const lk::TriangleMesh*> inBlock;
    for (std::size_t m = 0; m < n; ++m)
      if (together(m, j))
        inBlock.push_back(&guideSolids[m]);
    for (std::size_t k = 0; k < n; ++k)
      if (k != j && together(k, j))
        for (lk::TriangleMesh& c : cutsOf(k, inBlock, CutterStep * static_cast<double>(j)))
          guideCutters[j].push_back(std::move(c));
  }
  for (std::size_t i = 0, b = 0; i + 1 < n; ++i)
    if (joins[i] != Join::Merged)
    {
      // A bar that reaches into a guide other than the two it joins (one
      // merged with either, an X; a third whose saw plane crosses near the
      // bone): cut by that guide's slot and screw holes as well.
      std::vector<std::size_t> by{ i, i + 1 };
      for (std::size_t k = 0; k < n; ++k)
        if (k != i && k != i + 1 && barMeets(barLines[b], radius, guideData[k]))
          by.push_back(k);
      barCutters.emplace_back();
      const double widen = CutterStep * static_cast<double>(n + b);
      for (const std::size_t k : by)
        for (lk::TriangleMesh& c : cutsOf(k, { &guideSolids[k], &barSolids[b] }, widen))
          barCutters.back().push_back(std::move(c));
      ++b;
    }
  for (std::size_t j = 0; j < n; ++j)
  {
    if (!cut(guideSolids[j], guideCutters[j], "guide " + std::to_string(j + 1)))
      return 0;
    this->UpdateProgress(0.6 + 0.1 * static_cast<double>(j + 1) / static_cast<double>(n));
    if (lkvtk::stopRequested(this, { output }))
      return 1;
  }
  for (std::size_t i = 0, b = 0; i + 1 < n; ++i)
    if (joins[i] != Join::Merged)
    {
      if (!cut(barSolids[b], barCutters[b], n == 2 ? std::string("the bar") : "the bar between guides " +
              std::to_string(i + 1) + " and " + std::to_string(i + 2)))
        return 0;
      ++b;
    }

  // The union of the guides and the bars, in their order along the bone.
  std::vector<lk::TriangleMesh> solids;
  std::string names = "guide 1";
  std::size_t nextBar = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!guideSolids[i].triangles.empty())
      solids.push_back(std::move(guideSolids[i]));
    if (i + 1 < n && joins[i] == Join::Merged)
      names += ", guide " + std::to_string(i + 2);
    else if (i + 1 < n)
    {
      solids.push_back(std::move(barSolids[nextBar++]));
      names += (n == 2 ? ", the bar, guide " : ", a bar, guide ") + std::to_string(i + 2);
    }
  }
  lk::TriangleMesh joined;
  if (const std::string why = lk::solidUnion(solids, joined); !why.empty())
  {
    vtkErrorMacro("Cannot join the guides (" << names << "): " << why << ".");
    return 0;
  }
  this->UpdateProgress(0.9);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  vtkSmartPointer<vtkPolyData> result = lkvtk::fromTriangleMesh(joined);
  // One part: merged guides that do not meet (slots offset along each
  // other, the guides on different faces) would be two.
  if (const std::string why = apartPieces(result, guide, joins, overlapping, between); !why.empty())
  {
    vtkErrorMacro("Cannot join the guides: " << why << ".");
    return 0;
  }
  // A screw hole of one guide in a block beside another's slot: the saw
  // would meet its screw (guides made without the plan's other saw planes).
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k < n; ++k)
      if (k != j && together(k, j))
        for (const Vec& x : guide[j].holes)
        {
          // The screw from the wall's top into the bone, against guide k's
          // saw (its kerf half k's slot each side of the plane).
          const Vec top = add(x, guide[j].approach, guide[j].clearance + guide[j].thickness);
          const Vec deep = add(x, guide[j].approach, -lkvtk::ScrewDepth);
          if (lkvtk::screwInSawPath(
                top, deep, 0.5 * guide[j].hole, guide[k].slotCentre, guide[k].normal, 0.5 * guide[k].slotWidth))
          {
            ++this->NumberOfScrewHolesInSawPaths;
            vtkWarningMacro("A screw hole of guide " << j + 1 << " lies in the path of guide " << k + 1
              << "'s saw (its screw within 1 mm of that slot's plane): give vtkLKCuttingGuideFilter the plan's "
              << "other saw planes (OtherCutPlanes), which leaves such holes out.");
          }
        }
  // The labels as the guides showed them: a merged neighbour's wall or a
  // bar over one, or a slot through it, makes it hard to read.
  for (std::size_t i = 0; i < n; ++i)
  {
    const double share = labelCovered(guideData[i], guide[i].approach, result);
    if (!(share > LabelShareCovered))
      continue;
    ++this->NumberOfLabelsCovered;
    vtkStringArray* text =
      vtkStringArray::SafeDownCast(guideData[i]->GetFieldData()->GetAbstractArray("GuideLabel"));
    const std::string name = text && text->GetNumberOfValues() > 0 ? "'" + text->GetValue(0) + "' " : std::string();
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.0f %%", 100.0 * share);
    vtkWarningMacro("The label " << name << "of guide " << i + 1 << " is partly covered or cut in the joined part ("
                                 << percent << " of its place differs: a bar or another guide's wall over it, a "
                                 << "slot or a screw hole through it); vtkLKCuttingGuideFilter keeps labels clear of "
                                 << "merged neighbours when given the plan's other saw planes (OtherCutPlanes).");
  }
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(result);
  mass->Update();
  output->ShallowCopy(result);
  output->GetPointData()->Initialize();
  output->GetCellData()->Initialize();
  output->GetFieldData()->PassData(input->GetFieldData());
  this->BarLengths = barLengths;
  for (int k = 0; k < 3; ++k)
    this->ApproachUsed[k] = -insertion.motion[k];
  this->InsertionMargin = -back;
  this->UndercutArea = undercutArea;
  this->BarGaps = barGaps;
  this->BarLength = std::accumulate(barLengths.begin(), barLengths.end(), 0.0);
  this->BarDiameter = barLengths.empty() ? 0.0 : 2.0 * radius;
  this->BarGap = barGaps.empty() ? 0.0 : *std::min_element(barGaps.begin(), barGaps.end());
  for (const Join j : joins)
    this->Merged.push_back(j == Join::Merged);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (crossing[i][j])
        this->Crossings.push_back({ static_cast<int>(i), static_cast<int>(j) });
  this->Volume = mass->GetVolume();
  vtkFieldData* fd = output->GetFieldData();
  for (const auto& [name, values] :
    { std::make_pair("GuideBarLength", &barLengths), std::make_pair("GuideBarGap", &barGaps) })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    for (double v : *values)
      a->InsertNextValue(v);
    fd->AddArray(a);
  }
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName("GuideMerged");
    for (const char m : this->Merged)
      a->InsertNextValue(m ? 1.0 : 0.0);
    fd->AddArray(a);
  }
  {
    vtkNew<vtkIntArray> a;
    a->SetName("GuideCrossings");
    a->SetNumberOfComponents(2);
    for (const std::array<int, 2>& c : this->Crossings)
      a->InsertNextTuple2(c[0], c[1]);
    fd->AddArray(a);
  }
  lkvtk::addFieldValue(fd, "GuideBarDiameter", this->BarDiameter);
  lkvtk::addFieldValues(fd, "GuideApproach", this->ApproachUsed, 3);
  lkvtk::addFieldValue(fd, "GuideInsertionMargin", this->InsertionMargin);
  lkvtk::addFieldValue(fd, "GuideUndercutArea", this->UndercutArea);
  lkvtk::addFieldValue(fd, "GuideVolume", this->Volume);
  this->UpdateProgress(1.0);
  return 1;
}

double vtkLKGuideBarFilter::GetBarLength(int bar)
{
  return bar >= 0 && static_cast<std::size_t>(bar) < this->BarLengths.size() ? this->BarLengths[bar] : 0.0;
}

bool vtkLKGuideBarFilter::GetMerged(int pair)
{
  return pair >= 0 && static_cast<std::size_t>(pair) < this->Merged.size() && this->Merged[pair];
}

bool vtkLKGuideBarFilter::GetCrossed(int a, int b)
{
  return std::any_of(this->Crossings.begin(), this->Crossings.end(), [&](const std::array<int, 2>& c) {
    return (c[0] == a && c[1] == b) || (c[0] == b && c[1] == a);
  });
}

int vtkLKGuideBarFilter::GetNumberOfCrossings()
{
  return static_cast<int>(this->Crossings.size());
}

int vtkLKGuideBarFilter::GetNumberOfMerges()
{
  return static_cast<int>(std::count(this->Merged.begin(), this->Merged.end(), 1));
}

double vtkLKGuideBarFilter::GetBarGap(int bar)
{
  return bar >= 0 && static_cast<std::size_t>(bar) < this->BarGaps.size() ? this->BarGaps[bar] : 0.0;
}

void vtkLKGuideBarFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Diameter: " << this->Diameter << "\n";
  os << indent << "StandOff: " << this->StandOff << "\n";
  os << indent << "MaximumLength: " << this->MaximumLength << "\n";
  os << indent << "NumberOfBars: " << this->BarLengths.size() << "\n";
  os << indent << "NumberOfMerges: " << this->GetNumberOfMerges() << "\n";
  os << indent << "NumberOfCrossings: " << this->GetNumberOfCrossings() << "\n";
  os << indent << "NumberOfLabelsCovered: " << this->NumberOfLabelsCovered << "\n";
  os << indent << "NumberOfScrewHolesInSawPaths: " << this->NumberOfScrewHolesInSawPaths << "\n";
  os << indent << "BarLength: " << this->BarLength << "\n";
  os << indent << "BarDiameter: " << this->BarDiameter << "\n";
  os << indent << "BarGap: " << this->BarGap << "\n";
  os << indent << "Volume: " << this->Volume << "\n";
  os << indent << "ApproachUsed: " << this->ApproachUsed[0] << " " << this->ApproachUsed[1] << " "
     << this->ApproachUsed[2] << "\n";
  os << indent << "InsertionMargin: " << this->InsertionMargin << "\n";
  os << indent << "UndercutArea: " << this->UndercutArea << "\n";
}
