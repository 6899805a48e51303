#include "vtkLKCuttingGuideFilter.h"
#include "latticekit/ConvexHull.h"
#include "latticekit/SolidBooleans.h"
#include "vtkLKAbort.h"
#include "vtkLKFieldValues.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKRaisedLabel.h"
#include "vtkLKRayCast.h"
#include "vtkLKSawPath.h"
#include "vtkLKSectionLoops.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCleanPolyData.h>
#include <vtkCellData.h>
#include <vtkClipPolyData.h>
#include <vtkCylinder.h>
#include <vtkDoubleArray.h>
#include <vtkFeatureEdges.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkLinearExtrusionFilter.h>
#include <vtkMassProperties.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPlane.h>
#include <vtkPlaneCollection.h>
#include <vtkCutter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>
#include <vtkStringArray.h>
#include <vtkTriangle.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLKCuttingGuideFilter);

vtkCxxSetObjectMacro(vtkLKCuttingGuideFilter, OtherCutPlanes, vtkPlaneCollection);

vtkLKCuttingGuideFilter::~vtkLKCuttingGuideFilter()
{
  this->SetLabel(nullptr);
  this->SetOtherCutPlanes(nullptr);
}

vtkMTimeType vtkLKCuttingGuideFilter::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->OtherCutPlanes)
  {
    time = std::max(time, this->OtherCutPlanes->GetMTime());
    vtkCollectionSimpleIterator it;
    this->OtherCutPlanes->InitTraversal(it);
    while (vtkPlane* plane = this->OtherCutPlanes->GetNextPlane(it))
      time = std::max(time, plane->GetMTime());
  }
  return time;
}

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

bool finiteVector(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

/// Where another saw line's guide would lie: its plane, and the points
/// where that plane cuts the bone.
struct OtherGuide
{
  Vec origin, normal; // normal: unit
  vtkSmartPointer<vtkPolyData> section;
  vtkSmartPointer<vtkStaticPointLocator> locator;

  /// How far `x` is from where the plane cuts the bone (its nearest section point).
  double fromSection(const Vec& x) const
  {
    double nearest[3];
    this->section->GetPoint(this->locator->FindClosestPoint(x.data()), nearest);
    return std::sqrt(vtkMath::Distance2BetweenPoints(x.data(), nearest));
  }
};

/// The guides of `planes` on `bone`, less the plane (o, n) itself and
/// planes that miss the bone.
std::vector<OtherGuide> otherGuides(vtkPlaneCollection* planes, vtkPolyData* bone, const Vec& o, const Vec& n)
{
  std::vector<OtherGuide> others;
  if (!planes)
    return others;
  const double size = bone->GetLength();
  vtkCollectionSimpleIterator it;
  planes->InitTraversal(it);
  while (vtkPlane* plane = planes->GetNextPlane(it))
  {
    OtherGuide g;
    std::copy(plane->GetOrigin(), plane->GetOrigin() + 3, g.origin.begin());
    std::copy(plane->GetNormal(), plane->GetNormal() + 3, g.normal.begin());
    vtkMath::Normalize(g.normal.data());
    if (std::abs(dot(g.normal, n)) > 1.0 - 1e-9 && std::abs(dot(add(g.origin, o, -1.0), n)) < 1e-6 * size)
      continue; // this guide's own plane
    vtkNew<vtkPlane> cutPlane;
    cutPlane->SetOrigin(g.origin.data());
    cutPlane->SetNormal(g.normal.data());
    vtkNew<vtkCutter> cutter;
    cutter->SetInputData(bone);
    cutter->SetCutFunction(cutPlane);
    cutter->Update();
    if (cutter->GetOutput()->GetNumberOfPoints() == 0)
      continue;
    g.section = cutter->GetOutput();
    g.locator = vtkSmartPointer<vtkStaticPointLocator>::New();
    g.locator->SetDataSet(g.section);
    g.locator->BuildLocator();
    others.push_back(g);
  }
  return others;
}

/// Whether `x` (on this guide's outer face) lies where another guide would:
/// within `reach` of its plane and within `nearSection` of where that plane
/// cuts the bone.
bool underOtherGuide(const std::vector<OtherGuide>& others, const Vec& x, double reach, double nearSection)
{
  for (const OtherGuide& g : others)
  {
    if (std::abs(dot(add(x, g.origin, -1.0), g.normal)) < reach && g.fromSection(x) < nearSection)
      return true;
  }
  return false;
}

/// Whether a screw of `radius` into the bone at `x` along -d (from
/// `above` over the bone to `deep` into it) lies in the path of another
/// saw (vtkLKSawPath.h) that cuts the bone within `nearSection` of `x`.
bool inOtherSawPath(const std::vector<OtherGuide>& others, const Vec& x, const Vec& d, double radius,
  double halfWidth, double above, double deep, double nearSection)
{
  for (const OtherGuide& g : others)
    if (lkvtk::screwInSawPath(add(x, d, above), add(x, d, -deep), radius, g.origin, g.normal, halfWidth) &&
      g.fromSection(x) < nearSection)
      return true;
  return false;
}

} // namespace

int vtkLKCuttingGuideFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  std::fill(this->ApproachUsed, this->ApproachUsed + 3, 0.0);
  this->SlotLength = this->ContactArea = this->Volume = 0.0;
  this->NumberOfScrewHoles = 0;
  this->NumberOfScrewHolesLeftOut = 0;
  this->LabelPlaced = false;
  this->LabelHeightUsed = 0.0;
  std::fill(this->LabelBox, this->LabelBox + 9, 0.0);

  const double normalLength = vtkMath::Norm(this->PlaneNormal);
  if (!finiteVector(this->PlaneOrigin) || !finiteVector(this->PlaneNormal) || !(normalLength > 0.0) ||
    !std::isfinite(normalLength))
  {
    vtkErrorMacro("Cannot make a cutting guide: PlaneOrigin must be finite and PlaneNormal finite and not zero.");
    return 0;
  }
  if (!finiteVector(this->Approach))
  {
    vtkErrorMacro("Cannot make a cutting guide: Approach must be finite (0, 0, 0: chosen from the section).");
    return 0;
  }
  struct Range
  {
    const char* name;
    double value, low, high;
  };
  for (const Range& r : { Range{ "Thickness", this->Thickness, 0.1, 100.0 },
         Range{ "Reach", this->Reach, 0.0, 200.0 }, Range{ "SlotWidth", this->SlotWidth, 0.05, 20.0 },
         Range{ "Bridge", this->Bridge, 0.0, 100.0 }, Range{ "Clearance", this->Clearance, 0.0, 10.0 },
         Range{ "ScrewHoleDiameter", this->ScrewHoleDiameter, 0.0, 10.0 },
         Range{ "LabelHeight", this->LabelHeight, 1.5, 20.0 },
         Range{ "MaximumContactAngle", this->MaximumContactAngle, 1.0, 89.0 } })
  {
    if (!(r.value >= r.low && r.value <= r.high))
    {
      const char* unit = r.name[0] == 'M' ? " degrees" : " mm";
      vtkErrorMacro("Cannot make a cutting guide: " << r.name << " must be " << r.low << " to " << r.high << unit
                                                    << ", not " << r.value << ".");
      return 0;
    }
  }
  if (!(this->Reach > this->SlotWidth / 2.0))
  {
    vtkErrorMacro("Cannot make a cutting guide: Reach (" << this->Reach << " mm) must be more than half the "
                                                         << "SlotWidth (" << this->SlotWidth << " mm).");
    return 0;
  }
  if (this->ScrewHoleDiameter > 0.0 && !(this->ScrewHoleDiameter + 1.0 <= this->Reach - this->SlotWidth / 2.0))
  {
    vtkErrorMacro("Cannot make a cutting guide: a screw hole of " << this->ScrewHoleDiameter << " mm does not fit "
      << "beside the slot with 0.5 mm of wall round it: the guide reaches " << this->Reach - this->SlotWidth / 2.0
      << " mm from the slot (a larger Reach, or ScrewHoleDiameter 0 for none).");
    return 0;
  }
  if (this->OtherCutPlanes)
  {
    vtkCollectionSimpleIterator it;
    this->OtherCutPlanes->InitTraversal(it);
    int k = 0;
    while (vtkPlane* plane = this->OtherCutPlanes->GetNextPlane(it))
    {
      if (!finiteVector(plane->GetOrigin()) || !finiteVector(plane->GetNormal()) ||
        !(vtkMath::Norm(plane->GetNormal()) > 0.0) || !std::isfinite(vtkMath::Norm(plane->GetNormal())))
      {
        vtkErrorMacro("Cannot make a cutting guide: other cut plane " << k << " needs a finite origin and a finite "
                                                                     << "normal that is not zero.");
        return 0;
      }
      ++k;
    }
  }
  if (const std::string why = lkvtk::surfaceProblem(input); !why.empty())
  {
    vtkErrorMacro("Cannot make a cutting guide: " << why << ".");
    return 0;
  }

  vtkSmartPointer<vtkPolyData> bone = lkvtk::facesAsTriangles(input);
  const Vec o{ this->PlaneOrigin[0], this->PlaneOrigin[1], this->PlaneOrigin[2] };
  Vec n{ this->PlaneNormal[0], this->PlaneNormal[1], this->PlaneNormal[2] };
  vtkMath::Normalize(n.data());
  double bounds[6];
  bone->GetBounds(bounds);
  const double diagonal = std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);

  // The section nearest the origin: the bone the guide goes on.
  vtkNew<vtkPlane> cutPlane;
  cutPlane->SetOrigin(o.data());
  cutPlane->SetNormal(n.data());
  const std::vector<std::vector<Vec>> sections = lkvtk::sectionPolylines(bone, cutPlane);
  const int nearest = lkvtk::nearestPolyline(sections, o);
  const std::vector<Vec>* loop = nearest < 0 ? nullptr : &sections[static_cast<std::size_t>(nearest)];
  if (!loop)
  {
    vtkErrorMacro("Cannot make a cutting guide: the plane meets no part of the bone.");
    return 0;
  }
  this->UpdateProgress(0.1);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  // The approach, in the plane.
  Vec centre{ 0, 0, 0 };
  for (const Vec& x : *loop)
    centre = add(centre, x, 1.0 / static_cast<double>(loop->size()));
  Vec d{ this->Approach[0], this->Approach[1], this->Approach[2] };
  const double given = vtkMath::Norm(d.data());
  if (given > 0.0)
  {
    d = add(d, n, -dot(d, n));
    if (!(vtkMath::Norm(d.data()) > 1e-6 * given))
    {
      vtkErrorMacro("Cannot make a cutting guide: the Approach lies along the plane's normal (it must have a "
                    "part in the plane).");
      return 0;
    }
  }
  else
  {
    // The section's short axis: the eigenvector of its points' covariance
    // with the smallest eigenvalue among the two in the plane.
    double covariance[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
    for (const Vec& x : *loop)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          covariance[r][c] += (x[r] - centre[r]) * (x[c] - centre[c]);
    double* rows[3] = { covariance[0], covariance[1], covariance[2] };
    double values[3], vectors[3][3];
    double* vectorRows[3] = { vectors[0], vectors[1], vectors[2] };
    vtkMath::Jacobi(rows, values, vectorRows); // decreasing eigenvalues, vectors in columns
    for (int k = 2; k >= 0; --k)
    {
      const Vec v{ vectors[0][k], vectors[1][k], vectors[2][k] };
      if (std::abs(dot(v, n)) < 0.5)
      {
        d = add(v, n, -dot(v, n));
        break;
      }
    }
    // The bone's outer side: the side of the section that lies on the
    // bone's convex hull, where the other faces the inside of an arch (a
    // mandible's lingual side, its ramus' medial side), on a mandible alone
    // as on a whole skull. It is judged where the cut crosses such an arch:
    // where one of the section's two outermost points along the axis lies 2
    // mm or more inside the hull, the half of the section (either side of
    // its centre along the axis) that lies on average the shallower inside
    // the hull, by 1 mm at least, is the outer side. Otherwise (both ends on
    // the hull: a bone with no inner side, or a cut along the arch, such as
    // a horizontal cut through the chin), away from the centre of the bone
    // round the cut (within twice the section's size of its centre, 30 mm
    // at least): a mandible's arch curves in on both sides of a cut, so
    // that centre lies inside it.
    std::vector<lk::Vec3> bonePoints(static_cast<std::size_t>(bone->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < bone->GetNumberOfPoints(); ++i)
      bone->GetPoint(i, bonePoints[static_cast<std::size_t>(i)].data());
    const lk::ConvexHull hull(bonePoints);
    auto depth = [&](const Vec& x) { return hull.depth({ x[0], x[1], x[2] }); };
    const auto [lowest, highest] =
      std::minmax_element(loop->begin(), loop->end(), [&](const Vec& a, const Vec& b) { return dot(a, d) < dot(b, d); });
    const double deepestEnd = std::max(depth(*lowest), depth(*highest));
    double depthSum[2] = { 0.0, 0.0 }, lengthSum[2] = { 0.0, 0.0 }; // behind, ahead of the centre along d
    for (std::size_t i = 0; i + 1 < loop->size(); ++i)
    {
      const Vec& x = (*loop)[i];
      const Vec& y = (*loop)[i + 1];
      const Vec middle = add(x, add(y, x, -1.0), 0.5);
      const double length = std::sqrt(vtkMath::Distance2BetweenPoints(x.data(), y.data()));
      const int side = dot(add(middle, centre, -1.0), d) > 0.0 ? 1 : 0;
      depthSum[side] += length * depth(middle);
      lengthSum[side] += length;
    }
    const double meanBehind = lengthSum[0] > 0.0 ? depthSum[0] / lengthSum[0] : 0.0;
    const double meanAhead = lengthSum[1] > 0.0 ? depthSum[1] / lengthSum[1] : 0.0;
    if (deepestEnd >= 2.0 && std::abs(meanAhead - meanBehind) >= 1.0)
    {
      if (meanAhead > meanBehind)
        d = { -d[0], -d[1], -d[2] };
    }
    else
    {
      double size = 0.0;
      for (const Vec& x : *loop)
        size = std::max(size, std::sqrt(vtkMath::Distance2BetweenPoints(x.data(), centre.data())));
      const double near2 = std::pow(std::max(30.0, 4.0 * size), 2);
      Vec around{ 0, 0, 0 };
      vtkIdType counted = 0;
      for (vtkIdType i = 0; i < bone->GetNumberOfPoints(); ++i)
      {
        Vec x;
        bone->GetPoint(i, x.data());
        if (vtkMath::Distance2BetweenPoints(x.data(), centre.data()) <= near2)
        {
          around = add(around, x);
          ++counted;
        }
      }
      if (counted > 0)
        around = { around[0] / counted, around[1] / counted, around[2] / counted };
      if (dot(add(centre, around, -1.0), d) < 0.0)
        d = { -d[0], -d[1], -d[2] };
    }
  }
  vtkMath::Normalize(d.data());
  if (this->OtherSide)
    d = { -d[0], -d[1], -d[2] };
  Vec e;
  vtkMath::Cross(n.data(), d.data(), e.data());

  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(bone);
  locator->BuildLocator();
  const double lift = 1e-4 * diagonal;
  vtkNew<vtkGenericCell> cell;
  // Whether nothing of the bone lies beyond `x` along the approach.
  auto seen = [&](const Vec& x, vtkIdType self) {
    const Vec from = add(x, d, lift);
    Vec to = add(from, d, 2.0 * diagonal);
    double hitPoint[3];
    vtkIdType hit = -1;
    return !lkvtk::firstHit(locator, from.data(), to.data(), cell, hitPoint, &hit) || hit == self;
  };

  // The guide's extent along the plane (u, along e): on a section, the run
  // of its segments around its outermost point that face the approach
  // within MaximumContactAngle (the outward normal, in the plane, of the
  // chord over 3 mm about the segment's middle, so that the label map's
  // staircase does not break the run; a longer segment's own) and that
  // nothing hides. Clipped there, the guide's edges across the bone are
  // straight.
  auto uOf = [&](const Vec& x) { return dot(add(x, o, -1.0), e); };
  auto vOf = [&](const Vec& x) { return dot(add(x, o, -1.0), d); };
  const double facing = std::cos(vtkMath::RadiansFromDegrees(this->MaximumContactAngle));
  struct Run
  {
    bool found = false;
    double low = 0.0, high = 0.0, deepest = 0.0;
    Vec outermost{ 0, 0, 0 };
  };
  auto runOf = [&](std::vector<Vec> section) {
    Run run;
    const bool closed = section.size() > 2 && section.front() == section.back();
    if (closed)
      section.pop_back();
    const std::size_t count = section.size();
    if (count < 2)
      return run;
    const std::size_t segments = closed ? count : count - 1;
    double area = 0.0;              // in (u, v): positive counter-clockwise
    std::vector<double> arc{ 0.0 }; // the length along the section to each point
    for (std::size_t i = 0; i < segments; ++i)
    {
      const Vec& p = section[i];
      const Vec& q = section[(i + 1) % count];
      area += uOf(p) * vOf(q) - uOf(q) * vOf(p);
      arc.push_back(arc.back() + std::sqrt(vtkMath::Distance2BetweenPoints(p.data(), q.data())));
    }
    const double total = arc.back();
    // The point at length `at` along the section (round a closed one; an
    // open one's ends where it stops).
    auto pointAt = [&](double at) {
      at = closed ? at - total * std::floor(at / total) : std::clamp(at, 0.0, total);
      const std::size_t i = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(arc.begin(), arc.end(), at) - arc.begin()) - 1, segments - 1);
      const double length = arc[i + 1] - arc[i];
      const double t = length > 0.0 ? (at - arc[i]) / length : 0.0;
      const Vec& p = section[i];
      const Vec& q = section[(i + 1) % count];
      return add(p, add(q, p, -1.0), t);
    };
    auto faces = [&](std::size_t i) {
      const double middle = 0.5 * (arc[i] + arc[i + 1]);
      const Vec a = pointAt(middle - 1.5), b = pointAt(middle + 1.5);
      const double tu = uOf(b) - uOf(a), tv = vOf(b) - vOf(a);
      const double length = std::hypot(tu, tv);
      if (!(length > 0.0))
        return false;
      // Outward: to the right of the way round a counter-clockwise loop.
      // An open section (a surface with a border) has no inside: either
      // side.
      const double mv = (area >= 0.0 ? -tu : tu) / length;
      return (closed ? mv : std::abs(mv)) >= facing && seen(pointAt(middle), -1);
    };
    std::size_t outermost = 0;
    for (std::size_t i = 1; i < count; ++i)
      if (vOf(section[i]) > vOf(section[outermost]))
        outermost = i;
    run.outermost = section[outermost];
    // The segments on either side of the outermost point, and on from them.
    double low = std::numeric_limits<double>::infinity(), high = -low, deepest = low;
    std::vector<char> taken(segments, 0);
    const std::size_t before = outermost > 0 ? outermost - 1 : (closed ? segments - 1 : segments);
    for (const auto& [start, way] : { std::make_pair(before, -1), std::make_pair(outermost, 1) })
    {
      std::size_t k = start;
      for (std::size_t step = 0; step < segments && k < segments && !taken[k] && faces(k); ++step)
      {
        taken[k] = 1;
        for (const Vec& x : { section[k], section[(k + 1) % count] })
        {
          low = std::min(low, uOf(x));
          high = std::max(high, uOf(x));
          deepest = std::min(deepest, vOf(x));
        }
        if (way < 0)
          k = k > 0 ? k - 1 : (closed ? segments - 1 : segments);
        else
          k = k + 1 < segments ? k + 1 : (closed ? 0 : segments);
      }
    }
    if (high >= low)
    {
      run.found = true;
      run.low = low;
      run.high = high;
      run.deepest = deepest;
    }
    return run;
  };
  const Run cutRun = runOf(*loop);
  double low = cutRun.found ? cutRun.low : 0.0, high = cutRun.found ? cutRun.high : 0.0;
  const double deepest = cutRun.deepest;
  if (!(high - low >= this->SlotWidth))
  {
    vtkErrorMacro("Cannot make a cutting guide: the bone's section at the cut faces the approach ("
      << d[0] << ", " << d[1] << ", " << d[2] << ") within " << this->MaximumContactAngle << " degrees over "
      << high - low << " mm only: no face of the bone at the cut faces the approach enough to rest a guide on.");
    return 0;
  }
  this->UpdateProgress(0.3);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  // The slot: between the ends, less the bridges.
  const double slotLength = high - low - 2.0 * this->Bridge;
  if (!(slotLength >= this->SlotWidth))
  {
    vtkErrorMacro("Cannot make a cutting guide: its contact with the bone at the cut is " << high - low
      << " mm long along the plane, too short for a slot between two bridges of " << this->Bridge
      << " mm (a smaller Bridge or a larger MaximumContactAngle?).");
    return 0;
  }

  // The contact: the bone as seen from the approach, over the rectangle
  // within Reach of the plane and between the ends: a grid of rays along
  // -d (every 0.25 mm or finer), each stopped at the first face it meets.
  // A height field along the approach, so the guide comes off along it;
  // its edges are straight, and the slot's sides and ends are grid lines.
  double top = -std::numeric_limits<double>::infinity();
  for (vtkIdType i = 0; i < bone->GetNumberOfPoints(); ++i)
  {
    Vec x;
    bone->GetPoint(i, x.data());
    top = std::max(top, vOf(x));
  }
  // A ray that meets no bone down to a Reach below the run's deepest point
  // passed beside the bone (beyond its edge away from the plane): no
  // contact there.
  const double bottom = deepest - this->Reach;
  // Grid lines through each of `stops` (increasing; those that coincide,
  // as the slot's ends and the extent's with no bridge, once), at most
  // `spacing` apart.
  auto lines = [](const std::vector<double>& stops, double spacing) {
    std::vector<double> at{ stops.front() };
    for (std::size_t k = 1; k < stops.size(); ++k)
    {
      if (stops[k] - at.back() <= 1e-6 * spacing)
        continue;
      const double from = at.back();
      const int parts = std::max(1, static_cast<int>(std::ceil((stops[k] - from) / spacing - 1e-9)));
      for (int j = 1; j <= parts; ++j)
        at.push_back(from + (stops[k] - from) * j / parts);
    }
    return at;
  };
  const double spacing = std::max(0.25, std::max(2.0 * this->Reach, high - low) / 600.0);
  const double half = this->SlotWidth / 2.0;
  const std::vector<double> across = lines({ -this->Reach, -half, half, this->Reach }, spacing);
  // The ends a hair inside, so that rays along a box's edge meet it.
  const double hair = 1e-9 * diagonal;
  const std::vector<double> along =
    lines({ low + hair, low + this->Bridge, high - this->Bridge, high - hair }, spacing);
  const std::size_t rows = across.size(), columns = along.size();
  vtkNew<vtkPoints> gridPoints;
  gridPoints->SetDataTypeToDouble();
  std::vector<vtkIdType> gridId(rows * columns, -1);
  for (std::size_t r = 0; r < rows; ++r)
  {
    for (std::size_t c = 0; c < columns; ++c)
    {
      const Vec base = add(add(o, n, across[r]), e, along[c]);
      Vec from = add(base, d, top + 1.0 - vOf(base)), to = add(base, d, bottom - vOf(base));
      double x[3];
      if (lkvtk::firstHit(locator, from.data(), to.data(), cell, x))
        gridId[r * columns + c] = gridPoints->InsertNextPoint(x);
    }
    this->UpdateProgress(0.3 + 0.3 * static_cast<double>(r + 1) / static_cast<double>(rows));
    if (this->GetAbortExecute())
      break;
  }
  if (lkvtk::stopRequested(this, { output }))
    return 1;
  // The cells whose four corners met the bone, outside the slot; of those,
  // the ones joined across cell sides to the cell nearest the middle of the
  // cut's section (a ray that met a far part of the bone leaves an island).
  const std::size_t cellRows = rows - 1, cellColumns = columns - 1;
  std::vector<char> usable(cellRows * cellColumns, 0);
  for (std::size_t r = 0; r < cellRows; ++r)
    for (std::size_t c = 0; c < cellColumns; ++c)
    {
      const double s = 0.5 * (across[r] + across[r + 1]), u = 0.5 * (along[c] + along[c + 1]);
      const bool inSlot = std::abs(s) < half && u > low + this->Bridge && u < high - this->Bridge;
      usable[r * cellColumns + c] = !inSlot && gridId[r * columns + c] >= 0 && gridId[(r + 1) * columns + c] >= 0 &&
        gridId[(r + 1) * columns + c + 1] >= 0 && gridId[r * columns + c + 1] >= 0;
    }
  // A cell nearly along the approach (a triangle's normal more than 80
  // degrees from it) is a wall where the rays slid off an edge of the bone
  // and met it farther down: at the contact's edge it is left out, with
  // what lies beyond it; inside the contact (a step of the scan's
  // staircase) it stays.
  std::vector<char> steep(usable.size(), 0);
  const double wall = std::cos(vtkMath::RadiansFromDegrees(80.0));
  for (std::size_t r = 0; r < cellRows; ++r)
    for (std::size_t c = 0; c < cellColumns; ++c)
    {
      if (!usable[r * cellColumns + c])
        continue;
      Vec corner[4];
      const vtkIdType ids[4] = { gridId[r * columns + c], gridId[(r + 1) * columns + c],
        gridId[(r + 1) * columns + c + 1], gridId[r * columns + c + 1] };
      for (int k = 0; k < 4; ++k)
        gridPoints->GetPoint(ids[k], corner[k].data());
      Vec first, second;
      vtkTriangle::ComputeNormal(corner[0].data(), corner[2].data(), corner[1].data(), first.data());
      vtkTriangle::ComputeNormal(corner[0].data(), corner[3].data(), corner[2].data(), second.data());
      steep[r * cellColumns + c] = dot(first, d) < wall || dot(second, d) < wall;
    }
  const double middleU = std::clamp(uOf(cutRun.outermost), low, high);
  // The cell nearest the cut's outermost point on each side of the plane
  // (without bridges the two sides are two blocks).
  std::size_t start[2] = { usable.size(), usable.size() };
  double best[2] = { std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity() };
  for (std::size_t r = 0; r < cellRows; ++r)
    for (std::size_t c = 0; c < cellColumns; ++c)
    {
      const double s = 0.5 * (across[r] + across[r + 1]), u = 0.5 * (along[c] + along[c + 1]);
      const double away = s * s + (u - middleU) * (u - middleU);
      const int side = s < 0.0 ? 0 : 1;
      if (usable[r * cellColumns + c] && !steep[r * cellColumns + c] && away < best[side])
      {
        best[side] = away;
        start[side] = r * cellColumns + c;
      }
    }
  // Marks in `mark` the cells reachable across cell sides from those in
  // `queue` (marked already) through cells `passes` lets through.
  auto flood = [&](std::deque<std::size_t> queue, std::vector<char>& mark, const auto& passes) {
    while (!queue.empty())
    {
      const std::size_t k = queue.front();
      queue.pop_front();
      const std::size_t r = k / cellColumns, c = k % cellColumns;
      const std::size_t next[4] = { r > 0 ? k - cellColumns : k, r + 1 < cellRows ? k + cellColumns : k,
        c > 0 ? k - 1 : k, c + 1 < cellColumns ? k + 1 : k };
      for (const std::size_t j : next)
        if (!mark[j] && passes(j))
        {
          mark[j] = 1;
          queue.push_back(j);
        }
    }
  };
  std::vector<char> joined(usable.size(), 0);
  for (const std::size_t first : start)
    if (first < usable.size() && !joined[first])
    {
      joined[first] = 1;
      flood({ first }, joined, [&](std::size_t j) { return usable[j] && !steep[j]; });
    }
  // The cells left out that the joined ones enclose (no way to the grid's
  // border through cells left out) go back in, if their rays met the bone.
  {
    std::vector<char> outside(usable.size(), 0);
    std::deque<std::size_t> border;
    for (std::size_t r = 0; r < cellRows; ++r)
      for (std::size_t c = 0; c < cellColumns; ++c)
        if ((r == 0 || c == 0 || r + 1 == cellRows || c + 1 == cellColumns) && !joined[r * cellColumns + c])
        {
          outside[r * cellColumns + c] = 1;
          border.push_back(r * cellColumns + c);
        }
    flood(border, outside, [&](std::size_t j) { return !joined[j]; });
    for (std::size_t k = 0; k < usable.size(); ++k)
      if (usable[k] && !joined[k] && !outside[k])
        joined[k] = 1;
  }
  // A steep cell in a narrow gap of the contact, between joined cells along
  // its row or its column within `gap` (a step of a smoothed surface, a
  // ledge a few cells high), is inside the contact too, though the gap is
  // open to the grid's edge: left out, it cut a notch into the guide's edge
  // (teeth once swept).
  {
    const std::size_t gap = static_cast<std::size_t>(std::ceil(2.0 / spacing));
    const std::vector<char> before = joined;
    auto joinedWithin = [&](std::size_t r, std::size_t c, long dr, long dc) {
      for (std::size_t k = 1; k <= gap; ++k)
      {
        const long rr = static_cast<long>(r) + dr * static_cast<long>(k),
                   cc = static_cast<long>(c) + dc * static_cast<long>(k);
        if (rr < 0 || cc < 0 || rr >= static_cast<long>(cellRows) || cc >= static_cast<long>(cellColumns))
          return false;
        const std::size_t j = static_cast<std::size_t>(rr) * cellColumns + static_cast<std::size_t>(cc);
        if (before[j])
          return true;
        if (!usable[j] || !steep[j])
          return false;
      }
      return false;
    };
    for (std::size_t r = 0; r < cellRows; ++r)
      for (std::size_t c = 0; c < cellColumns; ++c)
      {
        const std::size_t k = r * cellColumns + c;
        if (usable[k] && steep[k] && !before[k] &&
          ((joinedWithin(r, c, 0, -1) && joinedWithin(r, c, 0, 1)) ||
            (joinedWithin(r, c, -1, 0) && joinedWithin(r, c, 1, 0))))
          joined[k] = 1;
      }
  }
  // Two triangles a cell, facing the approach (n x e = -d, so (s, u)
  // clockwise faces +d).
  vtkNew<vtkCellArray> grid;
  for (std::size_t r = 0; r < cellRows; ++r)
    for (std::size_t c = 0; c < cellColumns; ++c)
    {
      if (!joined[r * cellColumns + c])
        continue;
      const vtkIdType a = gridId[r * columns + c], b = gridId[(r + 1) * columns + c],
                      q = gridId[(r + 1) * columns + c + 1], w = gridId[r * columns + c + 1];
      const vtkIdType first[3] = { a, q, b }, second[3] = { a, w, q };
      grid->InsertNextCell(3, first);
      grid->InsertNextCell(3, second);
    }
  vtkNew<vtkPolyData> contactGrid;
  contactGrid->SetPoints(gridPoints);
  contactGrid->SetPolys(grid);
  // The contact's edges away from the slot follow the grid's cells, and
  // where they run across it obliquely on a steep face, each step stands as
  // a tooth along the approach once the shell is swept (a 0.25 mm step on a
  // face 65 degrees from the approach rises 0.5 mm). So where the face at
  // the edge is steep the contact ends `inset` inside it along a smooth
  // line instead: where its distance to the cells outside it, averaged over
  // `window` each way (those outside counting 0), is `inset` (0.41 mm in
  // from a straight edge). Where the face is within 30 degrees of the
  // approach the edge stays as it is, and between 30 and 45 degrees the
  // line moves from the one to the other. (The lengths shrink with a Reach
  // under 8 mm: a guide for a small model keeps its contact.)
  const double scale = std::min(1.0, this->Reach / 8.0);
  const double inset = 0.5 * scale, window = 1.0 * scale, cap = 3.0 * scale;
  vtkNew<vtkDoubleArray> edgeDistance;
  edgeDistance->SetName("EdgeDistance");
  edgeDistance->SetNumberOfValues(gridPoints->GetNumberOfPoints());
  edgeDistance->Fill(cap);
  {
    std::vector<char> contact(rows * columns, 0);
    for (std::size_t r = 0; r < cellRows; ++r)
      for (std::size_t c = 0; c < cellColumns; ++c)
        if (joined[r * cellColumns + c])
          contact[r * columns + c] = contact[(r + 1) * columns + c] = contact[r * columns + c + 1] =
            contact[(r + 1) * columns + c + 1] = 1;
    auto middleOf = [&](long k, const std::vector<double>& at) {
      const long last = static_cast<long>(at.size()) - 1;
      if (k < 0)
        return at.front() - 0.5 * spacing;
      if (k >= last)
        return at.back() + 0.5 * spacing;
      return 0.5 * (at[static_cast<std::size_t>(k)] + at[static_cast<std::size_t>(k) + 1]);
    };
    // Distance: to the middles of the cells outside the contact that are not
    // the slot's (beyond the grid too); 0 on their corners outside it.
    std::vector<double> distance(rows * columns, cap);
    std::vector<char> counted(rows * columns, 0); // in the averages
    const int capCells = static_cast<int>(std::ceil(cap / spacing)) + 1;
    for (long r = -1; r <= static_cast<long>(cellRows); ++r)
      for (long c = -1; c <= static_cast<long>(cellColumns); ++c)
      {
        const bool onGrid = r >= 0 && c >= 0 && r < static_cast<long>(cellRows) && c < static_cast<long>(cellColumns);
        const double sm = middleOf(r, across), um = middleOf(c, along);
        if (onGrid && joined[static_cast<std::size_t>(r) * cellColumns + static_cast<std::size_t>(c)])
          continue;
        if (std::abs(sm) < half && um > low + this->Bridge && um < high - this->Bridge)
          continue; // the slot
        for (long rr = std::max(0L, r - capCells); rr <= std::min(static_cast<long>(rows) - 1, r + 1 + capCells); ++rr)
          for (long cc = std::max(0L, c - capCells); cc <= std::min(static_cast<long>(columns) - 1, c + 1 + capCells);
               ++cc)
          {
            const std::size_t j = static_cast<std::size_t>(rr) * columns + static_cast<std::size_t>(cc);
            const bool corner = (rr == r || rr == r + 1) && (cc == c || cc == c + 1);
            if (!contact[j])
            {
              if (corner)
              {
                distance[j] = 0.0;
                counted[j] = 1;
              }
              continue;
            }
            distance[j] = std::min(distance[j],
              std::hypot(across[static_cast<std::size_t>(rr)] - sm, along[static_cast<std::size_t>(cc)] - um));
          }
      }
    for (std::size_t j = 0; j < rows * columns; ++j)
      if (contact[j])
        counted[j] = 1;
    // Each contact point's facing: its normal's cosine to the approach,
    // from its neighbours across and along (one side where the other has
    // none).
    auto point = [&](std::size_t r, std::size_t c) {
      Vec x;
      gridPoints->GetPoint(gridId[r * columns + c], x.data());
      return x;
    };
    std::vector<double> facing(rows * columns, -1.0);
    for (std::size_t r = 0; r < rows; ++r)
      for (std::size_t c = 0; c < columns; ++c)
      {
        if (!contact[r * columns + c])
          continue;
        const std::size_t r0 = r > 0 && contact[(r - 1) * columns + c] ? r - 1 : r;
        const std::size_t r1 = r + 1 < rows && contact[(r + 1) * columns + c] ? r + 1 : r;
        const std::size_t c0 = c > 0 && contact[r * columns + c - 1] ? c - 1 : c;
        const std::size_t c1 = c + 1 < columns && contact[r * columns + c + 1] ? c + 1 : c;
        if (r0 == r1 || c0 == c1)
          continue;
        Vec normal;
        const Vec acrossStep = add(point(r1, c), point(r0, c), -1.0), alongStep = add(point(r, c1), point(r, c0), -1.0);
        vtkMath::Cross(acrossStep.data(), alongStep.data(), normal.data());
        if (vtkMath::Normalize(normal.data()) > 0.0)
          facing[r * columns + c] = std::abs(dot(normal, d));
      }
    const double flat = std::cos(vtkMath::RadiansFromDegrees(30.0)), steepFace = std::cos(vtkMath::RadiansFromDegrees(45.0));
    const int windowCells = static_cast<int>(std::ceil(window / spacing));
    for (std::size_t r = 0; r < rows; ++r)
      for (std::size_t c = 0; c < columns; ++c)
      {
        const std::size_t j = r * columns + c;
        if (!contact[j] || distance[j] >= cap - window)
          continue;
        double sum = 0.0, facingSum = 0.0;
        int count = 0, facingCount = 0;
        for (long rr = std::max(0L, static_cast<long>(r) - windowCells);
             rr <= std::min(static_cast<long>(rows) - 1, static_cast<long>(r) + windowCells); ++rr)
          for (long cc = std::max(0L, static_cast<long>(c) - windowCells);
               cc <= std::min(static_cast<long>(columns) - 1, static_cast<long>(c) + windowCells); ++cc)
          {
            const std::size_t k = static_cast<std::size_t>(rr) * columns + static_cast<std::size_t>(cc);
            if (counted[k])
            {
              sum += distance[k];
              ++count;
            }
            if (facing[k] >= 0.0)
            {
              facingSum += facing[k];
              ++facingCount;
            }
          }
        // How steep the face is here: 0 within 30 degrees, 1 beyond 45.
        const double t =
          facingCount > 0 ? std::clamp((flat - facingSum / facingCount) / (flat - steepFace), 0.0, 1.0) : 0.0;
        const double w = t * t * (3.0 - 2.0 * t);
        edgeDistance->SetValue(gridId[j], w * sum / count + (1.0 - w) * cap);
      }
  }
  contactGrid->GetPointData()->SetScalars(edgeDistance);
  vtkNew<vtkCleanPolyData> compact; // the points no cell uses go
  compact->SetInputData(contactGrid);
  compact->PointMergingOff();
  vtkNew<vtkClipPolyData> smoothEdge;
  smoothEdge->SetInputConnection(compact->GetOutputPort());
  smoothEdge->SetValue(inset);
  // A clip point a hair from a grid point would make a sliver that a steep
  // face turns nearly along the approach, and the shell's side crossed it
  // (seen on the TCIA mandible: 25 crossing pairs, one guide in 60). The
  // values within `snap` of the line's are put on it, so that the line
  // passes through those grid points and keeps off the others by a
  // thousandth of a cell or so; the clip's copies of them are the same
  // points, and the triangles left without area go (vtkCleanPolyData,
  // exact). (A snap five times larger put kinks in the line.)
  const double snap = 0.002 * cap;
  for (vtkIdType i = 0; i < edgeDistance->GetNumberOfValues(); ++i)
    if (std::abs(edgeDistance->GetValue(i) - inset) < snap)
      edgeDistance->SetValue(i, inset);
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(smoothEdge->GetOutputPort());
  merged->PointMergingOn();
  merged->SetTolerance(0.0);
  merged->ConvertPolysToLinesOff();
  merged->ConvertLinesToPointsOff();
  // What the line cut off from the rest goes: a part with neither of the
  // cells the contact grew from (nearest the cut's outermost point, either
  // side of the slot) would be loose in the printed guide. Slivers under 1
  // mm^2 (scaled) go in any case.
  vtkNew<vtkPolyDataConnectivityFilter> parts;
  parts->SetInputConnection(merged->GetOutputPort());
  parts->SetExtractionModeToAllRegions();
  parts->ColorRegionsOn();
  parts->Update();
  vtkSmartPointer<vtkPolyData> slotted = vtkSmartPointer<vtkPolyData>::New();
  {
    vtkPolyData* clipped = parts->GetOutput();
    vtkDataArray* region = clipped->GetPointData()->GetArray("RegionId"); // a cell's: its points'
    std::vector<double> area(static_cast<std::size_t>(parts->GetNumberOfExtractedRegions()), 0.0);
    vtkNew<vtkIdList> ids;
    for (vtkIdType i = 0; region && i < clipped->GetNumberOfCells(); ++i)
    {
      clipped->GetCellPoints(i, ids);
      if (ids->GetNumberOfIds() != 3)
        continue;
      double p[3][3];
      for (int k = 0; k < 3; ++k)
        clipped->GetPoint(ids->GetId(k), p[k]);
      area[static_cast<std::size_t>(region->GetComponent(ids->GetId(0), 0))] +=
        vtkTriangle::TriangleArea(p[0], p[1], p[2]);
    }
    // The parts holding the cells the contact grew from: those of the
    // points at their corners (the clip keeps the grid's points inside it).
    std::vector<char> grown(area.size(), 0);
    if (region && clipped->GetNumberOfPoints() > 0)
    {
      vtkNew<vtkStaticPointLocator> points;
      points->SetDataSet(clipped);
      points->BuildLocator();
      for (const std::size_t first : start)
      {
        if (first >= usable.size())
          continue;
        const std::size_t r = first / cellColumns, c = first % cellColumns;
        double x[3];
        gridPoints->GetPoint(gridId[r * columns + c], x);
        const vtkIdType nearest = points->FindClosestPoint(x);
        if (nearest < 0)
          continue;
        double y[3];
        clipped->GetPoint(nearest, y);
        if (vtkMath::Distance2BetweenPoints(x, y) < 1e-12 * diagonal * diagonal)
          grown[static_cast<std::size_t>(region->GetComponent(nearest, 0))] = 1;
      }
    }
    const bool anyGrown = std::find(grown.begin(), grown.end(), 1) != grown.end();
    vtkNew<vtkCellArray> kept;
    for (vtkIdType i = 0; region && i < clipped->GetNumberOfCells(); ++i)
    {
      clipped->GetCellPoints(i, ids);
      if (ids->GetNumberOfIds() != 3)
        continue;
      const std::size_t part = static_cast<std::size_t>(region->GetComponent(ids->GetId(0), 0));
      if (area[part] >= scale * scale && (grown[part] || !anyGrown))
        kept->InsertNextCell(ids);
    }
    vtkNew<vtkPolyData> whole;
    whole->SetPoints(clipped->GetPoints());
    whole->SetPolys(kept);
    vtkNew<vtkCleanPolyData> unused; // the points only the slivers used go
    unused->SetInputData(whole);
    unused->PointMergingOff();
    unused->Update();
    slotted->ShallowCopy(unused->GetOutput());
    slotted->GetPointData()->Initialize();
  }
  if (slotted->GetNumberOfPolys() == 0)
  {
    // All of it lay on steep faces near its edges: the contact as the grid
    // gave it.
    compact->Update();
    slotted->ShallowCopy(compact->GetOutput());
    slotted->GetPointData()->Initialize();
  }
  if (slotted->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("Cannot make a cutting guide: no ray along the approach met the bone at the cut.");
    return 0;
  }
  // The screw holes that fix the guide to the bone while the saw runs: one
  // on each side of the slot, halfway between it and the guide's edge
  // across the plane, at the middle of its extent along the plane, through
  // the guide along the approach (vtkClipPolyData with a vtkCylinder, so
  // their walls are round). A hole whose ray meets no bone is left out.
  std::vector<Vec> holes;
  // The other saw lines' guides, for the holes and the label to keep clear of.
  const std::vector<OtherGuide> others = otherGuides(this->OtherCutPlanes, bone, o, n);
  if (this->ScrewHoleDiameter > 0.0)
  {
    const double radius = this->ScrewHoleDiameter / 2.0, at = 0.5 * (half + this->Reach);
    for (const double side : { -1.0, 1.0 })
    {
      const Vec base = add(add(o, n, side * at), e, 0.5 * (low + high));
      Vec from = add(base, d, top + 1.0 - vOf(base)), to = add(base, d, bottom - vOf(base));
      double x[3];
      if (!lkvtk::firstHit(locator, from.data(), to.data(), cell, x))
        continue;
      // A screw the saw of a line nearby would meet (two cuts a few
      // millimetres apart, their guides merged into one block): left out.
      if (inOtherSawPath(others, { x[0], x[1], x[2] }, d, radius, half, this->Clearance + this->Thickness,
            lkvtk::ScrewDepth, this->Reach + lkvtk::ScrewDepth))
      {
        ++this->NumberOfScrewHolesLeftOut;
        vtkWarningMacro("The cutting guide's screw hole on the slot's "
          << (side > 0.0 ? "side the plane's normal points to" : "side away from the plane's normal")
          << " is left out: its screw (" << 2.0 * radius
          << " mm, " << lkvtk::ScrewDepth << " mm into the bone) would lie in the path of the saw of another cut plane "
          << "(OtherCutPlanes) nearby.");
        continue;
      }
      vtkNew<vtkCylinder> drill;
      drill->SetCenter(x);
      drill->SetAxis(d.data());
      drill->SetRadius(radius);
      vtkNew<vtkClipPolyData> clip;
      clip->SetInputData(slotted);
      clip->SetClipFunction(drill);
      clip->Update();
      slotted = vtkSmartPointer<vtkPolyData>::New();
      slotted->ShallowCopy(clip->GetOutput());
      holes.push_back({ x[0], x[1], x[2] });
    }
  }
  // The clips' new points (the edge's, the holes') lie on the grid's
  // triangles, a hair inside a convex bone: each is put back on the bone
  // along its ray.
  {
    vtkPoints* points = slotted->GetPoints();
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      Vec x;
      points->GetPoint(i, x.data());
      const Vec base = add(x, d, -vOf(x));
      Vec from = add(base, d, top + 1.0), to = add(base, d, bottom);
      double hitPoint[3];
      if (lkvtk::firstHit(locator, from.data(), to.data(), cell, hitPoint))
        points->SetPoint(i, hitPoint);
    }
    points->Modified();
  }
  vtkNew<vtkMassProperties> contactArea;
  contactArea->SetInputData(slotted);
  contactArea->Update();
  this->ContactArea = contactArea->GetSurfaceArea();
  this->UpdateProgress(0.7);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  // The shell: moved by the clearance, swept by the thickness.
  vtkNew<vtkPoints> moved;
  moved->SetDataTypeToDouble();
  moved->SetNumberOfPoints(slotted->GetNumberOfPoints());
  for (vtkIdType i = 0; i < slotted->GetNumberOfPoints(); ++i)
  {
    Vec x;
    slotted->GetPoint(i, x.data());
    moved->SetPoint(i, add(x, d, this->Clearance).data());
  }
  vtkNew<vtkPolyData> inner;
  inner->SetPoints(moved);
  inner->SetPolys(slotted->GetPolys());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(inner);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  vtkNew<vtkLinearExtrusionFilter> sweep;
  sweep->SetInputConnection(clean->GetOutputPort());
  sweep->SetExtrusionTypeToVectorExtrusion();
  sweep->SetVector(d[0] * this->Thickness, d[1] * this->Thickness, d[2] * this->Thickness);
  sweep->CappingOn();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(sweep->GetOutputPort());
  vtkNew<vtkPolyDataNormals> outward;
  outward->SetInputConnection(triangles->GetOutputPort());
  outward->ConsistencyOn();
  outward->AutoOrientNormalsOn();
  outward->SplittingOff();
  outward->ComputeCellNormalsOn(); // with neither, VTK 9.1 leaves the cells as they are
  outward->ComputePointNormalsOff();
  outward->Update();
  this->UpdateProgress(0.9);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  // The label, raised on the outer face and joined to the shell.
  vtkSmartPointer<vtkPolyData> shell = outward->GetOutput();
  if (this->Label && *this->Label)
  {
    const std::string why = this->PutOnLabel(shell, o, n, e, d, low, high,
      others.empty() ? std::function<bool(const Vec&, double)>()
                     : [&](const Vec& x, double margin) {
                         return underOtherGuide(others, x, this->Reach + margin,
                           this->Reach + this->Clearance + this->Thickness + 1.0);
                       });
    if (!why.empty())
      vtkWarningMacro("The cutting guide is made without its label '" << this->Label << "': " << why << ".");
  }

  vtkNew<vtkFeatureEdges> open;
  open->SetInputData(shell);
  open->BoundaryEdgesOn();
  open->NonManifoldEdgesOn();
  open->FeatureEdgesOff();
  open->ManifoldEdgesOff();
  open->Update();
  if (const vtkIdType edges = open->GetOutput()->GetNumberOfCells())
    vtkWarningMacro("The cutting guide is not closed: " << edges << " of its edges are open or shared by more than "
                                                        << "two faces (the bone's surface was not manifold there?).");
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(shell);
  mass->Update();
  output->ShallowCopy(shell);
  output->GetPointData()->Initialize();
  output->GetCellData()->Initialize();
  output->GetFieldData()->PassData(input->GetFieldData());

  // The middle of the slot on the bone (on the plane where no ray meets
  // it): where the saw enters, and the guide's place for others (a bar
  // that joins two guides).
  Vec slotCentre = add(o, e, 0.5 * (low + high) - uOf(o));
  {
    Vec from = add(slotCentre, d, top + 1.0 - vOf(slotCentre)), to = add(slotCentre, d, bottom - vOf(slotCentre));
    double x[3];
    if (lkvtk::firstHit(locator, from.data(), to.data(), cell, x))
      slotCentre = { x[0], x[1], x[2] };
  }

  std::copy(d.begin(), d.end(), this->ApproachUsed);
  this->SlotLength = slotLength;
  this->Volume = mass->GetVolume();
  vtkFieldData* fd = output->GetFieldData();
  lkvtk::addFieldValues(fd, "GuideApproach", this->ApproachUsed, 3);
  lkvtk::addFieldValue(fd, "GuideSlotLength", this->SlotLength);
  lkvtk::addFieldValue(fd, "GuideContactArea", this->ContactArea);
  lkvtk::addFieldValue(fd, "GuideVolume", this->Volume);
  lkvtk::addFieldValues(fd, "GuidePlaneNormal", n.data(), 3);
  lkvtk::addFieldValues(fd, "GuideSlotCentre", slotCentre.data(), 3);
  lkvtk::addFieldValue(fd, "GuideSlotWidth", this->SlotWidth);
  lkvtk::addFieldValue(fd, "GuideThickness", this->Thickness);
  lkvtk::addFieldValue(fd, "GuideReach", this->Reach);
  lkvtk::addFieldValue(fd, "GuideClearance", this->Clearance);
  lkvtk::addFieldValue(fd, "GuideScrewHoleDiameter", holes.empty() ? 0.0 : this->ScrewHoleDiameter);
  vtkNew<vtkDoubleArray> holeCentres; // where each screw hole meets the bone
  holeCentres->SetName("GuideScrewHoles");
  holeCentres->SetNumberOfComponents(3);
  for (const Vec& x : holes)
    holeCentres->InsertNextTuple(x.data());
  fd->AddArray(holeCentres);
  this->NumberOfScrewHoles = static_cast<int>(holes.size());
  if (this->LabelPlaced)
  {
    vtkNew<vtkStringArray> label;
    label->SetName("GuideLabel");
    label->InsertNextValue(this->Label);
    fd->AddArray(label);
    vtkNew<vtkDoubleArray> box; // where it lies: a corner, the text's width and height
    box->SetName("GuideLabelBox");
    box->SetNumberOfComponents(3);
    for (int k = 0; k < 3; ++k)
      box->InsertNextTuple(this->LabelBox + 3 * k);
    fd->AddArray(box);
  }
  this->UpdateProgress(1.0);
  return 1;
}

std::string vtkLKCuttingGuideFilter::PutOnLabel(vtkSmartPointer<vtkPolyData>& shell, const std::array<double, 3>& o,
  const std::array<double, 3>& n, const std::array<double, 3>& e, const std::array<double, 3>& d, double low,
  double high, const std::function<bool(const std::array<double, 3>&, double)>& underOther)
{
  for (const char* c = this->Label; *c; ++c)
    if (static_cast<unsigned char>(*c) < 32 || static_cast<unsigned char>(*c) > 126)
      return "vtkVectorText draws printable ASCII characters only";
  if (std::strlen(this->Label) > 40) // none that long fits beside a slot
    return "it is longer than 40 characters";
  const double margin = 0.5, stroke = 0.6, relief = 0.6, depth = std::min(1.0, 0.5 * this->Thickness);
  const double smallest = 1.5, edge = 0.3;
  vtkSmartPointer<vtkPolyData> outline = lkvtk::textOutline(this->Label, this->LabelHeight, stroke, edge);
  if (!outline)
    return "it has no character to draw";
  double b[6];
  outline->GetBounds(b);
  const double aspect = b[1] / b[3]; // width over height
  // The room: four rectangles (in s across the plane, u along it), beside
  // the slot on either side, between a screw hole and an end.
  const double half = this->SlotWidth / 2.0, holeRadius = this->ScrewHoleDiameter / 2.0, middle = 0.5 * (low + high);
  const double acrossRoom = this->Reach - half - 2.0 * margin, alongRoom = 0.5 * (high - low) - holeRadius - 2.0 * margin;
  if (!(acrossRoom > 0.0) || !(alongRoom > 0.0))
    return "there is no room for it beside the slot (a larger Reach, a longer guide)";
  const double alongMiddle = holeRadius + margin + 0.5 * alongRoom;

  // Each rectangle's room across, from the slot out: the longest run clear
  // of the other saw lines' guides (all of it without them). Off the guide
  // counts as clear first (the text may fit beside a ragged edge, which
  // raisedLabel judges), then as not (a smaller text wholly on it).
  struct Run
  {
    double from, to; // s, from the plane
  };
  using Runs = std::array<std::array<Run, 2>, 2>; // [side][ahead], + first
  // Each rectangle's columns across (0.1 mm apart, its whole along-room
  // sampled every 0.5 mm on the guide's outer face, the first face from
  // outside along the approach): whether one lies under another guide, and
  // whether one is off the guide. Found once, for both rules.
  const double step = 0.1;
  const int count = static_cast<int>(std::floor(acrossRoom / step)) + 1;
  std::array<std::array<std::vector<char>, 2>, 2> covered, offGuide; // [side][ahead][column]
  bool anyOff = false;
  if (underOther)
  {
    vtkNew<vtkStaticCellLocator> top;
    top->SetDataSet(shell);
    top->BuildLocator();
    const double far = 4.0 * shell->GetLength();
    const int alongCount = std::max(3, static_cast<int>(std::ceil(alongRoom / 0.5)) + 1);
    vtkNew<vtkGenericCell> cell;
    for (int si = 0; si < 2; ++si)
      for (int ai = 0; ai < 2; ++ai)
      {
        const double side = si == 0 ? 1.0 : -1.0, ahead = ai == 0 ? 1.0 : -1.0;
        covered[si][ai].assign(count, 0);
        offGuide[si][ai].assign(count, 0);
        for (int k = 0; k < count; ++k)
          for (int j = 0; j < alongCount && !covered[si][ai][k]; ++j)
          {
            const double s = half + margin + k * step;
            const double u = middle + ahead * (holeRadius + margin + alongRoom * j / (alongCount - 1));
            const Vec x = add(add(o, n, side * s), e, u);
            const Vec from = add(x, d, far), to = add(x, d, -far);
            double hit[3];
            if (lkvtk::firstHit(top, from.data(), to.data(), cell, hit))
              covered[si][ai][k] = underOther({ hit[0], hit[1], hit[2] }, margin);
            else
              offGuide[si][ai][k] = 1;
          }
        anyOff = anyOff || std::find(offGuide[si][ai].begin(), offGuide[si][ai].end(), 1) != offGuide[si][ai].end();
      }
  }
  bool crowded = false; // a rectangle lost room to another guide
  auto roomAcross = [&](bool offGuideClear) {
    Runs runs;
    for (auto& r : runs)
      r.fill(Run{ half + margin, this->Reach - margin });
    if (!underOther)
      return runs;
    for (int si = 0; si < 2; ++si)
      for (int ai = 0; ai < 2; ++ai)
      {
        int best = 0, bestStart = 0, start = 0;
        for (int k = 0; k <= count; ++k)
        {
          const bool clear = k < count && !covered[si][ai][k] && (offGuideClear || !offGuide[si][ai][k]);
          if (!clear)
          {
            if (k - start > best)
            {
              best = k - start;
              bestStart = start;
            }
            start = k + 1;
          }
        }
        if (best == count)
          continue; // all of it clear
        crowded = crowded || offGuideClear;
        // best samples clear: a run of (best - 1) steps (none for 0 or 1).
        runs[si][ai] = best > 1 ? Run{ half + margin + bestStart * step, half + margin + (bestStart + best - 1) * step }
                                : Run{ 0.0, 0.0 };
      }
    return runs;
  };

  // The text's up: across the plane (the text reads along the slot) or
  // along it (across the slot), nearest the coordinates' +z first (the
  // patient's head in LPS and RAS alike), so that on a vertical cut a short
  // label stands upright; the full height first, then the largest that fits.
  struct Place
  {
    Vec up;
    double height, upwards;
    bool acrossUp;
    double side, ahead, across; // across: the rectangle's middle, s
  };
  std::vector<Place> places;
  for (const bool offGuideClear : { true, false })
  {
    if (!offGuideClear && !anyOff)
      break; // the same rooms again
    const Runs runs = roomAcross(offGuideClear);
    std::vector<Place> these;
    for (const bool acrossUp : { true, false })
      for (const double sign : { 1.0, -1.0 })
        for (const double side : { 1.0, -1.0 })
          for (const double ahead : { 1.0, -1.0 })
          {
            const Vec up =
              acrossUp ? Vec{ sign * n[0], sign * n[1], sign * n[2] } : Vec{ sign * e[0], sign * e[1], sign * e[2] };
            const Run& run = runs[side > 0.0 ? 0 : 1][ahead > 0.0 ? 0 : 1];
            const double room = run.to - run.from;
            // Its height along up, its width along the other.
            const double upRoom = acrossUp ? room : alongRoom, wideRoom = acrossUp ? alongRoom : room;
            const double height = std::min({ this->LabelHeight, upRoom, wideRoom / aspect });
            if (height >= smallest)
              these.push_back({ up, height, up[2], acrossUp, side, ahead, 0.5 * (run.from + run.to) });
          }
    std::stable_sort(these.begin(), these.end(), [&](const Place& p, const Place& q) {
      const bool pFull = p.height >= this->LabelHeight - 1e-9, qFull = q.height >= this->LabelHeight - 1e-9;
      if (pFull != qFull)
        return pFull;
      if (!pFull && std::abs(p.height - q.height) > 1e-9)
        return p.height > q.height;
      return p.upwards > q.upwards + 1e-9;
    });
    places.insert(places.end(), these.begin(), these.end());
  }
  if (places.empty())
  {
    char room[300];
    if (crowded)
      std::snprintf(room, sizeof room,
        "there is no room for it beside the slot clear of the guides of the saw lines nearby (the other cut "
        "planes; %.1f mm tall at least)",
        smallest);
    else
      std::snprintf(room, sizeof room,
        "it is too long for the room beside the slot between a screw hole and the guide's end (%.1f by %.1f mm, at "
        "%.1f mm tall)",
        alongRoom, acrossRoom, smallest);
    return room;
  }
  std::string why;
  double outlineHeight = this->LabelHeight; // what `outline` was drawn at
  for (const Place& place : places)
  {
    if (std::abs(place.height - outlineHeight) > 1e-9)
    {
      outline = lkvtk::textOutline(this->Label, place.height, stroke, edge);
      if (!outline)
        return "it has no character to draw";
      outlineHeight = place.height;
    }
    outline->GetBounds(b);
    Vec reading;
    vtkMath::Cross(place.up.data(), d.data(), reading.data());
    // The text's middle in the middle of the rectangle.
    const Vec centre = add(add(o, n, place.side * place.across), e, middle + place.ahead * alongMiddle);
    const Vec origin = add(add(centre, reading, -0.5 * b[1]), place.up, -0.5 * b[3]);
    std::string problem;
    vtkSmartPointer<vtkPolyData> raised =
      lkvtk::raisedLabel(shell, outline, origin.data(), reading.data(), place.up.data(), relief, depth, problem);
    if (!raised)
    {
      if (why.empty())
        why = problem;
      continue;
    }
    std::vector<lk::TriangleMesh> solids(2);
    if (!lkvtk::toTriangleMesh(lkvtk::facesAsTriangles(shell), solids[0]).empty() ||
      !lkvtk::toTriangleMesh(raised, solids[1]).empty())
      return "its solid could not be made";
    lk::TriangleMesh joined;
    if (const std::string failed = lk::solidUnion(solids, joined); !failed.empty())
      return "it could not be joined to the guide: " + failed;
    shell = lkvtk::fromTriangleMesh(joined);
    this->LabelPlaced = true;
    this->LabelHeightUsed = place.height;
    for (int k = 0; k < 3; ++k)
    {
      this->LabelBox[k] = origin[k];
      this->LabelBox[3 + k] = b[1] * reading[k];
      this->LabelBox[6 + k] = b[3] * place.up[k];
    }
    return std::string();
  }
  return "no room for it on the outer face beside the slot: " + why;
}

void vtkLKCuttingGuideFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto triple = [&](const char* name, const double* v) {
    os << indent << name << ": " << v[0] << " " << v[1] << " " << v[2] << "\n";
  };
  triple("PlaneOrigin", this->PlaneOrigin);
  triple("PlaneNormal", this->PlaneNormal);
  triple("Approach", this->Approach);
  os << indent << "OtherSide: " << (this->OtherSide ? "on" : "off") << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "Reach: " << this->Reach << "\n";
  os << indent << "SlotWidth: " << this->SlotWidth << "\n";
  os << indent << "Bridge: " << this->Bridge << "\n";
  os << indent << "Clearance: " << this->Clearance << "\n";
  os << indent << "ScrewHoleDiameter: " << this->ScrewHoleDiameter << "\n";
  os << indent << "MaximumContactAngle: " << this->MaximumContactAngle << "\n";
  os << indent << "Label: " << (this->Label ? this->Label : "(none)") << "\n";
  os << indent << "LabelHeight: " << this->LabelHeight << "\n";
  os << indent << "OtherCutPlanes: " << (this->OtherCutPlanes ? this->OtherCutPlanes->GetNumberOfItems() : 0) << "\n";
  os << indent << "LabelPlaced: " << (this->LabelPlaced ? "yes" : "no") << "\n";
  triple("ApproachUsed", this->ApproachUsed);
  os << indent << "SlotLength: " << this->SlotLength << "\n";
  os << indent << "ContactArea: " << this->ContactArea << "\n";
  os << indent << "Volume: " << this->Volume << "\n";
  os << indent << "NumberOfScrewHoles: " << this->NumberOfScrewHoles << "\n";
  os << indent << "NumberOfScrewHolesLeftOut: " << this->NumberOfScrewHolesLeftOut << "\n";
}
